"""Figure 2's diagram of the architecture (plot only)."""

from icub_affordance.figures import figure2_architecture
from icub_affordance.files import redirect_log

with redirect_log(snakemake.log[0]):
    figure2_architecture(snakemake.params.hidden, snakemake.output[0])
