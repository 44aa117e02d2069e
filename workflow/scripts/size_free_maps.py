"""A run's visual maps without size: each object's map its shape's mean (the removal control)."""

from icub_affordance.files import load_npz, redirect_log, save_npz
from icub_affordance.learning.size_manipulation import size_free_maps

with redirect_log(snakemake.log[0]):
    objects = list(snakemake.params.objects)
    maps = load_npz(snakemake.input.maps, required=tuple(objects))
    free = size_free_maps(maps, objects)
    for obj in objects:
        print(f"{obj}: {free[obj].sum():.1f} edge cells (was {maps[obj].sum():.0f})")
    save_npz(snakemake.output[0], **free)
