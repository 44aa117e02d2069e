"""The four cells of object size x grip asked over the confirmation's replications, per cue
timing and test mode (data/claims/cells.csv), each replication's (cell_replications.csv), and
each declared RMSE estimate as a share of its condition's mean RMSE (effect_shares.csv), and
size among congruent trials alone, a test added after the results (congruent_size.csv)."""

import pandas as pd

from icub_affordance.analysis.cells import (
    cell_summary,
    congruent_size_tests,
    effect_shares,
    replication_cells,
)
from icub_affordance.files import redirect_log, write_tables

with redirect_log(snakemake.log[0]):
    trials = pd.concat(
        pd.read_csv(path).assign(cue=cue, replication=seed)
        for path, cue, seed in zip(
            snakemake.params.trials, snakemake.params.cues, snakemake.params.seeds, strict=True
        )
    )
    per_replication = replication_cells(trials)
    summary = cell_summary(per_replication)
    shares = effect_shares(summary, pd.read_csv(snakemake.input.declared))
    added = congruent_size_tests(per_replication, snakemake.params.least, snakemake.params.alpha)
    write_tables(
        [
            (snakemake.output.replications, per_replication),
            (snakemake.output.cells, summary),
            (snakemake.output.shares, shares),
            (snakemake.output.added, added),
        ]
    )
    print(summary.to_string())
