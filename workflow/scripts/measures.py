"""Every test trial's measures (data/eval/measures.csv), and their per-network contrasts and
per-object means (data/eval/measures.json)."""

from icub_affordance.files import redirect_log
from icub_affordance.learning.materials import load_materials
from icub_workflow.steps import measure_networks

with redirect_log(snakemake.log[0]):
    measure_networks(
        load_materials(
            snakemake.input.maps,
            snakemake.input.soms,
            snakemake.input.demos,
            snakemake.params.grip_distance,
        ),
        snakemake.params.network,
        list(snakemake.input.weights),
        snakemake.params.measures,
        snakemake.output.trials,
        snakemake.output.json,
    )
