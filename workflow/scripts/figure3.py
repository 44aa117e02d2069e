"""Figure 3 from the saved vision stages (plot only)."""

from icub_affordance.figures import figure3
from icub_affordance.files import load_npz, redirect_log

with redirect_log(snakemake.log[0]):
    arrays = load_npz(snakemake.input.stages)
    stages: dict = {}
    for key, value in arrays.items():
        obj, part = key.split("__")
        stages.setdefault(obj, {})[part] = value
    figure3(stages, snakemake.params.window, snakemake.output[0])
