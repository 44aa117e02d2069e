"""Train Jordan networks and save each one's learning curve and weights: the network of the
wildcard `net` (rule train: one job per network), or every network of the run, one after
another (rule run_train: the outputs list them in order), continued from a shared phase 1 where
the run has one (input `phase1`)."""

from icub_affordance.io import redirect_log
from icub_affordance.train import load_materials
from icub_workflow.steps import train_networks


def as_list(paths):
    return [paths] if isinstance(paths, str) else list(paths)


with redirect_log(snakemake.log[0]):
    nets = [int(snakemake.wildcards.net)] if "net" in snakemake.wildcards.keys() else None
    train_networks(
        load_materials(
            snakemake.input.maps,
            snakemake.input.soms,
            snakemake.input.demos,
            snakemake.params.grip_distance,
        ),
        snakemake.params.network,
        snakemake.params.seed,
        nets,
        as_list(snakemake.output.curve),
        as_list(snakemake.output.weights),
        as_list(getattr(snakemake.input, "phase1", [])),
    )
