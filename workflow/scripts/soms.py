"""Train the three SOMs on the visual maps and save their activations (and weights)."""

import numpy as np

from icub_affordance.io import load_npz, redirect_log, save_npz
from icub_affordance.som import SOMConfig, active_units, train_soms
from icub_affordance.spec import TASKS

with redirect_log(snakemake.log[0]):
    objects = list(snakemake.params.objects)
    maps = load_npz(snakemake.input.maps, required=tuple(objects))
    visual = np.array([maps[o] for o in objects])
    soms = train_soms(visual, SOMConfig(**snakemake.params.soms), snakemake.params.seed)
    save_npz(
        snakemake.output[0],
        objects=np.array(objects),
        tasks=np.array(TASKS),
        **{k: v for k, v in vars(soms).items()},
    )
    for obj, act in zip(objects, soms.object_act, strict=True):
        print(f"{obj}: {active_units(act)} Object-map units above 0.5")
