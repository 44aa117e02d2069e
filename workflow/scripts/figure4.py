"""Figure 4 from the learning curves (plot only)."""

import pandas as pd

from icub_affordance.figures import figure4
from icub_affordance.files import redirect_log

with redirect_log(snakemake.log[0]):
    tables = [pd.read_csv(path) for path in snakemake.input.curves]
    curves = [table["rmse"].to_numpy() for table in tables]
    figure4(curves, snakemake.params.phase1, snakemake.output[0], iterations=tables[0]["iteration"])
