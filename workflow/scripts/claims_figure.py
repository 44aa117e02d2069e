"""The forest plot of the paper's claims over fresh replications (plot only)."""

import pandas as pd

from icub_affordance.figures import claims_forest
from icub_affordance.io import redirect_log

with redirect_log(snakemake.log[0]):
    claims_forest(pd.read_csv(snakemake.input.summary), snakemake.output[0])
