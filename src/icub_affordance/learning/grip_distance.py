"""The size study's manipulation of the grips' distance (config ``grip_distance``): each object's
two grips moved to its same-shape partner's distance, so that object size and the distance between
the grips no longer go together (the size study's crossed design).

Applied to the demonstrations when the materials are loaded (``materials.load_materials``) and
read by the size study's measure of the gap; apart from the loading and from the training regime,
which it does not change.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from icub_affordance.vocabulary import OBJECTS

#: What the networks learn of the two grips' distance (config ``grip_distance``): the
#: demonstrations as made, or each object's grips moved to its same-shape partner's distance.
GRIP_DISTANCES = ("natural", "swapped")


def mean_final_grip_distances(postures: np.ndarray) -> np.ndarray:
    """Per object, the distance between its two grips' mean final postures (over sequences):
    the grips' distance the size study measures and the swap matches."""
    final = np.asarray(postures, dtype=float)[:, :, :, -1].mean(axis=2)
    return np.linalg.norm(final[:, 0] - final[:, 1], axis=-1)


def trajectory_grip_distances(postures: np.ndarray) -> np.ndarray:
    """Per object, the RMS distance between its two grips' trajectories, over steps 1 .. and
    DoF (the RMSE's own scale, ``trials.scores.grip_distance``), the mean over sequences: the
    size study's second metric of the grips' distance (added after results), beside the
    declared ``mean_final_grip_distances``, which sees the final posture only."""
    postures = np.asarray(postures, dtype=float)
    diff = postures[:, 0, :, 1:] - postures[:, 1, :, 1:]  # (object, sequence, step, DoF)
    return np.sqrt((diff**2).mean(axis=(2, 3))).mean(axis=1)


def shape_partners(objects: Sequence[str]) -> list[int]:
    """Per object, the index of the other object of its shape (its category: the balls are
    the natural objects, the cubes the artefacts). Refused unless each shape has two."""
    partners = []
    for obj in objects:
        same = [k for k, o in enumerate(objects) if o != obj
                and OBJECTS[o].category == OBJECTS[obj].category]  # fmt: skip
        if len(same) != 1:
            raise ValueError(
                f"grip_distance 'swapped' needs each object's one same-shape partner; {obj!r} "
                f"has {len(same)} among {list(objects)}: use grip_distance 'natural'"
            )
        partners.append(same[0])
    return partners


def swap_scale(postures: np.ndarray, objects: Sequence[str]) -> np.ndarray:
    """Per object, the factor that moves its two grips' mean final postures to its partner's
    distance (``mean_final_grip_distances``): partner's distance over its own."""
    distances = mean_final_grip_distances(postures)
    return distances[shape_partners(objects)] / distances


def scaled_grips(postures: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """The demonstrations with each object's two grips moved apart (factor above 1) or together
    about their midpoint, at every step, by the object's factor, then held within the joints'
    ranges (0-1), which may clip the move: its effect is measured, not assumed. Step 0, common
    to both grips, does not move."""
    postures = np.asarray(postures, dtype=float)
    mid = postures.mean(axis=1, keepdims=True)
    factor = np.asarray(scale, dtype=float)[:, None, None, None, None]
    return np.clip(mid + factor * (postures - mid), 0.0, 1.0)


def swapped_grips(postures: np.ndarray, objects: Sequence[str]) -> np.ndarray:
    """The demonstrations with each object's grips at its same-shape partner's distance: the
    small objects' grips then lie the further apart, so size and the grips' distance no longer
    go together (the size study's crossed design)."""
    return scaled_grips(postures, swap_scale(postures, objects))
