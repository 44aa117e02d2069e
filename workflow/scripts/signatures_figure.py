"""The signatures' figure: the delta plot and the effect against the steps the object was seen."""

import pandas as pd

from icub_affordance.figures import signatures_figure
from icub_affordance.files import redirect_log

with redirect_log(snakemake.log[0]):
    trials = pd.read_csv(snakemake.input.trials)
    signatures_figure(trials, snakemake.params.quantiles, snakemake.output[0])
