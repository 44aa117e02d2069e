"""The sweep's effects per point (plot only)."""

import pandas as pd

from icub_affordance.figures import sweep_effects
from icub_affordance.files import redirect_log

with redirect_log(snakemake.log[0]):
    sweep_effects(pd.read_csv(snakemake.input.points), snakemake.output[0])
