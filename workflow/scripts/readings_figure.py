"""The readings' effects on every measure (plot only)."""

import pandas as pd

from icub_affordance.figures import readings_effects
from icub_affordance.files import redirect_log

with redirect_log(snakemake.log[0]):
    readings_effects(
        pd.read_csv(snakemake.input.summary),
        pd.read_csv(snakemake.input.replications),
        snakemake.output[0],
    )
