"""Every reading's effects over its replications: data/readings/replications.csv (one row per
reading, replication, measure and effect) and data/readings/summary.csv (the contract)."""

import json
from pathlib import Path

from icub_affordance.io import atomic_path, redirect_log
from icub_affordance.readings import replication_rows, summary

with redirect_log(snakemake.log[0]):
    table = list(snakemake.params.table)
    analyses = [json.loads(Path(path).read_text()) for path in snakemake.input.measures]
    replications = replication_rows(table, analyses, list(snakemake.params.measures))
    for path, frame in (
        (snakemake.output.replications, replications),
        (snakemake.output.summary, summary(replications)),
    ):
        with atomic_path(path) as tmp:
            frame.to_csv(tmp, index=False)
    print(summary(replications).to_string())
