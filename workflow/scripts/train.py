"""Train a run's part (icub_workflow.parts): the network of the wildcard `part` (`net03`: the
config's own run, a job per network) or every network of the run (`all`), continued from a
shared phase 1 where the run has one (input `phase1`); save its learning curve and weights."""

from icub_affordance.files import redirect_log
from icub_affordance.learning.materials import load_materials
from icub_workflow.steps import train_part

with redirect_log(snakemake.log[0]):
    train_part(
        load_materials(
            snakemake.input.maps,
            snakemake.input.soms,
            snakemake.input.demos,
            snakemake.params.grip_distance,
        ),
        snakemake.params.network,
        snakemake.params.seed,
        snakemake.wildcards.part,
        snakemake.output.curve,
        snakemake.output.weights,
        list(snakemake.input.phase1),
        snakemake.params.names,
    )
