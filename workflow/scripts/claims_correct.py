"""The correct-trial RMSE's effects over every confirmation replication, none dropped for lacking a
cell (icub_affordance.analysis.correct_sensitivity): the networks that carry each replication's
cells (data/claims/correct_cells.csv) and the mixed model's estimates (correct_sensitivity.csv), an
exploration beside the confirmatory family."""

import pandas as pd

from icub_affordance.analysis.correct_sensitivity import cells, sensitivity
from icub_affordance.files import redirect_log, write_tables

with redirect_log(snakemake.log[0]):
    trials = pd.concat(
        pd.read_csv(path).assign(cue=cue, seed=seed)
        for path, cue, seed in zip(
            snakemake.params.trials, snakemake.params.cues, snakemake.params.seeds, strict=True
        )
    )
    counts = cells(trials)
    table = sensitivity(trials, counts, least=snakemake.params.least)
    write_tables([(snakemake.output.cells, counts), (snakemake.output.sensitivity, table)])
    print(table.to_string())
