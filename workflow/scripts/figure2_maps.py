"""The SOM activations of Figure 2 (plot only)."""

from icub_affordance.figures import figure2_maps
from icub_affordance.files import load_npz, redirect_log

with redirect_log(snakemake.log[0]):
    s = load_npz(snakemake.input.soms)
    figure2_maps(
        s["object_act"],
        s["task_act"],
        s["goal_act"],
        s["objects"].tolist(),
        s["tasks"].tolist(),
        snakemake.output[0],
    )
