"""The size study's manipulation of the networks' input: the shapes' large and small objects, the
removal control's size-free visual maps (``size_free_maps``: each object's map the mean of its
shape's), and the manipulation check (``manipulation``: the units each map's cluster lifts above
one half, large over small, per shape), with the dose column's reading (``dose_value``).

Apart from the study's analysis (``analysis.size_study``) because it acts on, and checks, what
the networks learn from (the visual maps, the Object and Goal maps' clusters), as the rest of
``learning`` does, and reads no result: the rule ``size_free_maps`` and the dose figure no
longer depend on the analysis's code.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from icub_affordance.learning.maps import active_units
from icub_affordance.vocabulary import OBJECTS, TASKS

if TYPE_CHECKING:
    import pandas as pd

#: The study's control, which stands in its ``dose`` column beside the numeric doses: no size in
#: the input (``removed``).
CONTROLS: tuple[str, ...] = ("removed",)


def dose_value(dose: Any) -> Any:
    """A ``dose`` cell as read from a table: a number, or the name of a control."""
    return dose if str(dose) in CONTROLS else float(dose)


#: The shapes, each with its large and its small object.
SHAPES: dict[str, tuple[str, str]] = {
    "ball": ("big_ball", "small_ball"),
    "cube": ("big_cube", "small_cube"),
}


def size_free_maps(maps: Mapping[str, np.ndarray], objects: Sequence[str]) -> dict[str, np.ndarray]:
    """The removal control's visual input: each object's map replaced by the mean of its shape's
    maps (the natural objects', balls; the artefacts', cubes), so the input says which shape, not
    which size; and the maps' clusters, computed from it, are equal for the two sizes."""
    by_category: dict[str, list[str]] = {}
    for obj in objects:
        by_category.setdefault(OBJECTS[obj].category, []).append(obj)
    mean = {c: np.mean([maps[o] for o in members], axis=0) for c, members in by_category.items()}
    return {obj: mean[OBJECTS[obj].category] for obj in objects}


def manipulation_rows(soms: Mapping[str, np.ndarray]) -> list[dict[str, Any]]:
    """Per shape and map, the units the large and the small object's cluster lifts above one
    half (``maps.active_units``), and their ratio: the Object map's response to the object, and
    the Goal map's, averaged over the two tasks."""
    objects = [str(o) for o in soms["objects"]]
    rows = []
    for shape, (large, small) in SHAPES.items():
        li, si = objects.index(large), objects.index(small)
        units = {
            "object": (active_units(soms["object_act"][li]), active_units(soms["object_act"][si])),
            "goal": tuple(
                float(np.mean([active_units(soms["goal_act"][i, t]) for t in range(len(TASKS))]))
                for i in (li, si)
            ),
        }
        for name, (n_large, n_small) in units.items():
            rows.append(
                {
                    "shape": shape,
                    "map": name,
                    "large_units": n_large,
                    "small_units": n_small,
                    "ratio": n_large / n_small,
                }  # fmt: skip
            )
    return rows


def manipulation(table: Sequence[Mapping], soms: Sequence[Mapping]) -> pd.DataFrame:
    """One row per study run (dose, cue, seed, run), shape and map: the manipulation check."""
    import pandas as pd

    rows = [
        dict(row) | check
        for row, maps in zip(table, soms, strict=True)
        for check in manipulation_rows(maps)
    ]
    return pd.DataFrame(rows)
