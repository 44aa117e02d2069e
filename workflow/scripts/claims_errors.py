"""Each cue timing and test mode's all-trial RMSE effects split into their wrong-grip and
correct-trial parts over the confirmation's replications (data/claims/error_split.csv), with the
cells they come from (error_cells.csv)."""

import pandas as pd

from icub_affordance.analysis.error_split import cells, split
from icub_affordance.files import redirect_log, write_tables

with redirect_log(snakemake.log[0]):
    trials = pd.concat(
        pd.read_csv(path).assign(cue=cue)
        for path, cue in zip(snakemake.params.trials, snakemake.params.cues, strict=True)
    )
    cell_tables, split_tables = [], []
    for (cue, mode), chosen in trials.groupby(["cue", "mode"], sort=False):
        table = cells(chosen)
        cell_tables.append(table.assign(cue=cue, mode=mode))
        split_tables.append(split(table).assign(cue=cue, mode=mode))
    first = ["cue", "mode"]
    cell_table, split_table = (
        pd.concat(tables, ignore_index=True) for tables in (cell_tables, split_tables)
    )
    cell_table = cell_table[first + [c for c in cell_table if c not in first]]
    split_table = split_table[first + [c for c in split_table if c not in first]]
    write_tables([(snakemake.output.cells, cell_table), (snakemake.output.split, split_table)])
    print(split_table.to_string())
