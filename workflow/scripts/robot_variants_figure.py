"""The robot variants' success against training, and against the palm's error beside the
body's tolerance (plot only)."""

import pandas as pd

from icub_affordance.figures import robot_tolerance, robot_variants
from icub_affordance.files import redirect_log

with redirect_log(snakemake.log[0]):
    variants = pd.read_csv(snakemake.input.variants)
    robot_variants(variants, snakemake.output.variants)
    robot_tolerance(pd.read_csv(snakemake.input.tolerance), variants, snakemake.output.tolerance)
