"""Phase 1 of a run's networks, saved for the runs that continue from it (rule phase1)."""

from icub_affordance.files import redirect_log
from icub_affordance.learning.materials import load_materials
from icub_workflow.steps import train_phase1s

with redirect_log(snakemake.log[0]):
    train_phase1s(
        load_materials(
            snakemake.input.maps,
            snakemake.input.soms,
            snakemake.input.demos,
            snakemake.params.grip_distance,
        ),
        snakemake.params.network,
        snakemake.params.seed,
        snakemake.wildcards.part,
        snakemake.output[0],
        snakemake.params.names,
    )
