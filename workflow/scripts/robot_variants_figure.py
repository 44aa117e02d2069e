"""The robot variants' success against training (plot only)."""

import pandas as pd

from icub_affordance.figures import robot_variants
from icub_affordance.io import redirect_log

with redirect_log(snakemake.log[0]):
    robot_variants(pd.read_csv(snakemake.input.variants), snakemake.output[0])
