"""The effects by what a trial shows, image, name or both (plot only)."""

import pandas as pd

from icub_affordance.figures import words_effects
from icub_affordance.files import redirect_log

with redirect_log(snakemake.log[0]):
    words_effects(
        pd.read_csv(snakemake.input.by_form),
        pd.read_csv(snakemake.input.replications),
        snakemake.output[0],
    )
