"""Several measured runs (readings, size study) of one seed in one process: each run's maps
trained where the run makes its own, its networks trained, then scored on the declared measures
(the steps of rules soms, train and measures)."""

from pathlib import Path

from icub_affordance.files import redirect_log
from icub_affordance.learning.materials import load_materials
from icub_workflow.steps import make_soms, measure_networks, train_part

with redirect_log(snakemake.log[0]):
    for run in snakemake.params.runs:
        print(f"run {run['run']}")
        # its files' folders in the group's (rule measured makes the group's folder whole)
        made = [*run["curves"], *run["weights"], run["trials"], run["json"]]
        for path in made + ([run["soms"]] if run["makes_soms"] else []):
            Path(path).parent.mkdir(parents=True, exist_ok=True)
        if run["makes_soms"]:
            make_soms(
                run["maps"],
                snakemake.params.objects,
                run["som_settings"],
                run["seed"],
                run["soms"],
                run["names"],
            )
        materials = load_materials(run["maps"], run["soms"], run["demos"], run["grip_distance"])
        (curve,), (weights,) = run["curves"], run["weights"]  # its part `all`
        train_part(
            materials, run["network"], run["seed"], "all", curve, weights, names=run["names"]
        )
        measure_networks(
            materials,
            run["network"],
            run["weights"],
            snakemake.params.measures,
            run["trials"],
            run["json"],
        )
