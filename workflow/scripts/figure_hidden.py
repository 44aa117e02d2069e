"""The hidden-representation figure from the saved trajectories and distances (plot only)."""

import pandas as pd

from icub_affordance.figures import hidden_representations
from icub_affordance.files import redirect_log

with redirect_log(snakemake.log[0]):
    hidden_representations(
        pd.read_csv(snakemake.input.trajectories),
        pd.read_csv(snakemake.input.explained),
        pd.read_csv(snakemake.input.divergence),
        int(snakemake.params.network),
        snakemake.output[0],
    )
