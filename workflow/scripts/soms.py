"""Train the three SOMs on the visual maps and save their activations (and weights)."""

from icub_affordance.files import redirect_log
from icub_workflow.steps import make_soms

with redirect_log(snakemake.log[0]):
    make_soms(
        snakemake.input.maps,
        list(snakemake.params.objects),
        snakemake.params.soms,
        snakemake.params.seed,
        snakemake.output[0],
        snakemake.params.names,
    )
