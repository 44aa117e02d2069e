"""Where the paper's two effects live: the size x grip-asked cells of every cue timing and test
mode, beside the declared estimates, and how far closed-loop wrong grips travel (plot only)."""

import pandas as pd

from icub_affordance.figures import claim_cells
from icub_affordance.files import redirect_log

with redirect_log(snakemake.log[0]):
    claim_cells(
        pd.read_csv(snakemake.input.cells),
        pd.read_csv(snakemake.input.summary),
        snakemake.params.cues,
        snakemake.output[0],
    )
