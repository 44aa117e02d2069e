"""Figure 4 from the learning curves (plot only)."""

import pandas as pd

from icub_affordance.figures import figure4
from icub_affordance.io import redirect_log

with redirect_log(snakemake.log[0]):
    curves = [pd.read_csv(path)["rmse"].to_numpy() for path in snakemake.input.curves]
    figure4(curves, snakemake.params.phase1, snakemake.output[0])
