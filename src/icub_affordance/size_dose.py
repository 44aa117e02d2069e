"""What drives the size effect: the dose of size coding, its manipulation check, the removal
control and the demonstrations' geometry.

The paper explains why large objects are categorised faster by the Object map's larger cluster
for a larger object. Here the width of the Object and Goal maps' clusters per unit of input is
a dose (config ``size_dose``), each dose a run of the model replicated with fresh seeds, and a
control run sends no size at all (``size_free_input``). The manipulation check counts the units
each map's cluster lifts above one half, large over small, per shape; the dose-response is the
size effect per dose, over whole replications, and its slope on the dose, one slope per
replication, tested over replications. Each replication is one observation.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from .measures import analysed, is_null_control
from .readings import holm_hypotheses, over_replications
from .som import active_units
from .spec import OBJECTS, TASKS
from .stats import holm, t_term

#: The effect the study is about (the per-network contrast of the same name).
EFFECT = "size"

#: The shapes, each with its large and its small object.
SHAPES: dict[str, tuple[str, str]] = {
    "ball": ("big_ball", "small_ball"),
    "cube": ("big_cube", "small_cube"),
}

#: The columns of data/size_dose/summary.csv (the contract first).
SUMMARY_COLUMNS = [
    "dose",
    "cue",
    "measure",
    "replications",
    "large_small_ratio_object",
    "large_small_ratio_goal",
    "diff",
    "ci_low",
    "ci_high",
    "df",
    "p",
    "p_holm",
    "relative_to_mean",
]

#: The columns of data/size_dose/slope.csv.
SLOPE_COLUMNS = [
    "cue",
    "measure",
    "replications",
    "slope",
    "ci_low",
    "ci_high",
    "df",
    "p",
    "p_holm",
]


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
    half (``som.active_units``), and their ratio: the Object map's response to the object, and
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
    rows = [
        dict(row) | check
        for row, maps in zip(table, soms, strict=True)
        for check in manipulation_rows(maps)
    ]
    return pd.DataFrame(rows)


def replication_rows(
    table: Sequence[Mapping], analyses: Sequence[Mapping], measures: Sequence[str]
) -> pd.DataFrame:
    """One row per study run and measure (closed loop): the size contrast over its networks
    (positive: the paper's direction, large lower) and the measure's mean over the four cells."""
    rows = []
    for row, analysis in zip(table, analyses, strict=True):
        for measure in analysed(measures):
            result = analysis["closed_loop"][measure]
            mean = float(np.mean([result["means"][k] for k in ("large", "small")]))
            rows.append(
                dict(row) | {"measure": measure, "cell_mean": mean} | result["contrasts"][EFFECT]
            )
    return pd.DataFrame(rows)


def summary(replications: pd.DataFrame, checks: pd.DataFrame) -> pd.DataFrame:
    """One row per cue timing, measure and dose (SUMMARY_COLUMNS): the size effect over the
    replications (``readings.over_replications``: their mean, a t-interval over them), Holm's p
    over the table's hypotheses (a null control's rows are not), the effect relative to the
    measure's mean, and the manipulation check's mean ratios. Replications that all give the
    same estimate (a discrete measure) have no spread to test against: their p is undefined
    (NaN), not 0."""
    ratios = checks.groupby(["dose", "cue", "map"], sort=False)["ratio"].mean()
    rows = []
    for (cue, measure, dose), group in replications.groupby(["cue", "measure", "dose"], sort=False):
        test = over_replications(group)
        if len(group) > 1 and np.ptp(group["estimate"].to_numpy(dtype=float)) == 0:
            test["p"] = float("nan")
        rows.append(
            {"dose": dose, "cue": cue, "measure": measure, "replications": len(group),
             "large_small_ratio_object": float(ratios[(dose, cue, "object")]),
             "large_small_ratio_goal": float(ratios[(dose, cue, "goal")]),
             "relative_to_mean": test["diff"] / float(group["cell_mean"].mean())}
            | {k: test[k] for k in ("diff", "ci_low", "ci_high", "df", "p")}
        )  # fmt: skip
    out = pd.DataFrame(rows, columns=SUMMARY_COLUMNS)
    out["p_holm"] = holm_hypotheses(out) if len(out) else []
    return out


def slopes(replications: pd.DataFrame) -> pd.DataFrame:
    """Per cue timing and measure, the size effect's slope on the dose (the removal control
    left out): each replication's own least-squares slope over the doses, their mean and a
    t-test over the replications (df = replications - 1), Holm's p over the table's hypotheses
    (a null control's rows are not)."""
    dosed = replications[replications["dose"] != "removed"]
    rows = []
    for (cue, measure), group in dosed.groupby(["cue", "measure"], sort=False):
        per_seed = []
        for _seed, rep in group.groupby("seed", sort=False):
            dose = rep["dose"].to_numpy(dtype=float)
            effect = rep["estimate"].to_numpy(dtype=float)
            per_seed.append(
                np.sum((dose - dose.mean()) * (effect - effect.mean()))
                / np.sum((dose - dose.mean()) ** 2)
            )
        slope = np.array(per_seed)
        n = len(slope)
        sd = slope.std(ddof=1) if n > 1 else float("nan")
        term = t_term(slope.mean(), sd / np.sqrt(n), n - 1)
        rows.append(
            {"cue": cue, "measure": measure, "replications": n, "slope": term["estimate"]}
            | {k: term[k] for k in ("ci_low", "ci_high", "df", "p")}
        )
    out = pd.DataFrame(rows, columns=SLOPE_COLUMNS)
    hypothesis = ~out["measure"].map(is_null_control).to_numpy(dtype=bool)
    out.loc[hypothesis, "p_holm"] = holm(out.loc[hypothesis, "p"].to_numpy(dtype=float))
    return out


# ---- the motor side: the demonstrations' geometry ---------------------------------------------


#: The demonstrations' geometry, per object and grip (columns of data/size_dose/geometry.csv).
GEOMETRY = ("demo_path_length", "demo_spread", "demo_grip_distance")


def demo_geometry(angles: np.ndarray, objects: Sequence[str]) -> pd.DataFrame:
    """How an object's demonstrations move, from their postures (object, grip, sequence, step,
    DoF; 0-1): ``demo_path_length``, the mean distance travelled in posture space from the first
    step to the last; ``demo_spread``, the mean distance of a sequence's posture from the mean
    of its object and grip at the same step; ``demo_grip_distance``, the distance between the
    mean final postures of the two grips (the same for both grips of an object)."""
    steps = np.linalg.norm(np.diff(angles, axis=3), axis=-1).sum(axis=3)  # (o, g, s)
    mean = angles.mean(axis=2, keepdims=True)
    spread = np.linalg.norm(angles - mean, axis=-1).mean(axis=(2, 3))  # (o, g)
    final = angles[:, :, :, -1].mean(axis=2)  # (o, g, dof)
    grip_distance = np.linalg.norm(final[:, 0] - final[:, 1], axis=-1)  # (o,)
    rows = []
    for o, obj in enumerate(objects):
        for g in range(angles.shape[1]):
            rows.append(
                {"object": obj, "grip": g, "demo_path_length": float(steps[o, g].mean()),
                 "demo_spread": float(spread[o, g]),
                 "demo_grip_distance": float(grip_distance[o])}
            )  # fmt: skip
    return pd.DataFrame(rows)


def geometry_of_trials(geometry: pd.DataFrame, grips: Sequence[str]) -> pd.DataFrame:
    """Each object's geometry for the grip a categorisation trial requires: the rows of
    ``demo_geometry`` keyed by object and target grip name."""
    out = geometry.copy()
    out["target_grip"] = [grips[g] for g in out["grip"]]
    return out.drop(columns="grip")


def motor_tests(trials: pd.DataFrame, measure: str = "rmse") -> pd.DataFrame:
    """Do the demonstrations' differences line up with each object's error? ``trials``: the
    categorisation trials (closed loop) of the study's runs, with their ``dose`` (or "removed"),
    cue timing, replication (``seed``), network, object and target grip, the measure, and the
    geometry of the required grip's demonstrations (``GEOMETRY`` columns, from that run's own
    demonstrations). Per network, the least-squares slope of its four objects' mean error on
    each geometry measure (standardised over the four). The networks of one replication share
    its demonstrations, so the unit is the replication: its networks' mean slope, tested over
    the replications (df = replications - 1), per dose and cue timing; Holm's p over the table.
    With four objects a measure that ranks the objects as size does cannot be told from size."""
    keys = ["dose", "cue", "seed", "network", "object"]
    per_object = (
        trials.groupby(keys, sort=False)
        .agg({measure: "mean", **{g: "mean" for g in GEOMETRY}})
        .reset_index()
    )
    rows = []
    for (dose, cue), by_cue in per_object.groupby(["dose", "cue"], sort=False):
        for geometry in GEOMETRY:
            per_replication = []
            networks = 0
            for _seed, replication in by_cue.groupby("seed", sort=True):
                slope = []
                for _net, net in replication.groupby("network", sort=True):
                    x = net[geometry].to_numpy(dtype=float)
                    if np.ptp(x) == 0:
                        continue
                    x = (x - x.mean()) / x.std(ddof=0)
                    y = net[measure].to_numpy(dtype=float)
                    slope.append(float(np.sum(x * (y - y.mean())) / np.sum(x * x)))
                if slope:
                    per_replication.append(float(np.mean(slope)))
                    networks += len(slope)
            values = np.array(per_replication)
            n = len(values)
            sd = values.std(ddof=1) if n > 1 else float("nan")
            term = t_term(values.mean() if n else float("nan"), sd / np.sqrt(max(n, 1)), n - 1)
            rows.append(
                {
                    "dose": dose,
                    "cue": cue,
                    "geometry": geometry,
                    "measure": measure,
                    "replications": n,
                    "networks": networks,
                }  # fmt: skip
                | {k: term[k] for k in ("estimate", "ci_low", "ci_high", "df", "p")}
            )
    out = pd.DataFrame(rows)
    if len(out):
        out["p_holm"] = holm(out["p"].to_numpy(dtype=float))
    return out


def ranked_like_size(geometry: pd.DataFrame) -> list[str]:
    """The demonstrations' measures (``GEOMETRY``) that rank the objects as their size does in
    every replication of ``geometry`` (``demo_geometry`` rows with a ``seed``): larger for the
    big ball than the small one and for the big cube than the small one (mean over the grips).
    With four objects per network, a slope on such a measure cannot be told from size."""
    per_seed = geometry.groupby(["seed", "object"])[list(GEOMETRY)].mean()
    return [
        g
        for g in GEOMETRY
        if all(
            per_seed.loc[(seed, large), g] > per_seed.loc[(seed, small), g]
            for seed in geometry["seed"].unique()
            for large, small in SHAPES.values()
        )
    ]
