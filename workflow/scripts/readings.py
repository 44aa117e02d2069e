"""Every reading's effects over its replications: data/readings/replications.csv (one row per
reading, replication, measure and effect), data/readings/summary.csv (the contract) and
data/readings/differences.csv (the cue timings' and Goal responses' differences, paired by
network)."""

import json
from pathlib import Path

import pandas as pd

from icub_affordance.analysis.reading_tests import (
    difference_replications,
    differences,
    replication_rows,
    summary,
)
from icub_affordance.files import redirect_log, write_tables

with redirect_log(snakemake.log[0]):
    table = list(snakemake.params.table)
    measures = list(snakemake.params.measures)
    least = int(snakemake.params.least)
    analyses = [json.loads(Path(path).read_text()) for path in snakemake.params.analyses]
    replications = replication_rows(table, analyses, measures)
    trials = {
        row["run"]: pd.read_csv(path, keep_default_na=False)
        for row, path in zip(table, snakemake.params.trials, strict=True)
    }
    diffs = differences(
        difference_replications(table, trials, measures), dict(snakemake.params.margins), least
    )
    table_summary = summary(replications, least)
    write_tables(
        [
            (snakemake.output.replications, replications),
            (snakemake.output.summary, table_summary),
            (snakemake.output.differences, diffs),
        ]
    )
    print(table_summary.to_string())
    print(diffs.to_string())
