"""Several measured runs (readings, size study) of one seed in one process: each run's networks
trained, then scored on the declared measures (the steps of rules run_train and measures)."""

from icub_affordance.io import redirect_log
from icub_affordance.train import load_materials
from icub_workflow.steps import measure_networks, train_networks

with redirect_log(snakemake.log[0]):
    for run in snakemake.params.runs:
        print(f"run {run['run']}")
        materials = load_materials(run["maps"], run["soms"], run["demos"])
        train_networks(materials, run["network"], run["seed"], None, run["curves"], run["weights"])
        measure_networks(
            materials,
            run["network"],
            run["weights"],
            snakemake.params.measures,
            run["trials"],
            run["json"],
        )
