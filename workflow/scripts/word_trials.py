"""A words replication's networks tested in every form (image, name, both): its trials
(eval/words.csv), and each form's contrasts and each network's reactivation contrast
(eval/words.json)."""

from icub_affordance.files import redirect_log
from icub_affordance.learning.materials import load_materials
from icub_workflow.name_trials import word_trials

with redirect_log(snakemake.log[0]):
    word_trials(
        load_materials(
            snakemake.input.maps,
            snakemake.input.soms,
            snakemake.input.demos,
            snakemake.params.grip_distance,
        ),
        snakemake.params.network,
        list(snakemake.input.weights),
        snakemake.params.measures,
        snakemake.params.step,
        snakemake.output.trials,
        snakemake.output.json,
    )
