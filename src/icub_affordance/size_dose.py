"""What drives the size effect: the dose of size coding, its manipulation check, the removal
control and the demonstrations' geometry.

The paper explains why large objects are categorised faster by the Object map's larger cluster
for a larger object. Here the width of the Object and Goal maps' clusters per unit of input is
a dose (config ``size_dose``), each dose a run of the model replicated with fresh seeds, and a
control run sends no size at all (``size_free_input``). The manipulation check counts the units
each map's cluster lifts above one half, large over small, per shape; the dose-response is the
size effect per dose, over whole replications, and its slope on the dose, one slope per
replication, tested over replications. Each replication is one observation.

The nominal dose is a cluster width; what reaches the network is the Goal map's response (the
Object map does not feed the network, the Goal map does). The delivered dose is therefore
ln(large_units / small_units) on the Goal map (``delivered_doses``): 0 when the two sizes light
as many units, and the slopes are fitted on it as well as on the nominal dose. ``power`` says
what size effect the design could detect at all.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from .measures import analysed
from .readings import family_names, flat_term, holm_hypotheses, over_replications
from .som import active_units
from .spec import OBJECTS, TASKS
from .stats import holm, t_term

#: The effect the study is about (the per-network contrast of the same name).
EFFECT = "size"

#: The Holm families of the study's tables (a row's ``family``).
FAMILY_SUMMARY = "exploration: size study"
#: The study's declared family (config ``size_dose.declared``), across the summary and slopes.
FAMILY_DECLARED = "size study: declared"
FAMILY_SLOPES = "exploration: size study slopes"
FAMILY_MOTOR = "exploration: size study motor"

#: The study's controls, which stand in its ``dose`` column beside the numeric doses: no size in
#: the input (``removed``), and dose 0 with every object's grips at one distance
#: (``equal_grips``).
CONTROLS: tuple[str, ...] = ("removed", "equal_grips")


def dose_value(dose: Any) -> Any:
    """A ``dose`` cell as read from a table: a number, or the name of a control."""
    return dose if str(dose) in CONTROLS else float(dose)


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
    "delivered_dose",
    "df",
    "p",
    "p_holm",
    "family",
    "relative_to_mean",
]

#: The columns of data/size_dose/slope.csv.
#: ``axis``: the dose the slope is on, "nominal" (the cluster width) or "delivered"
#: (``delivered_doses``).
SLOPE_COLUMNS = [
    "cue",
    "measure",
    "axis",
    "replications",
    "slope",
    "ci_low",
    "ci_high",
    "df",
    "p",
    "p_holm",
    "family",
]

#: The dose axes of the slopes, in the table's order.
AXES = ("nominal", "delivered")


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
            term = flat_term(result["contrasts"][EFFECT])
            rows.append(dict(row) | {"measure": measure, "cell_mean": mean} | term)
    return pd.DataFrame(rows)


def delivered_doses(checks: pd.DataFrame) -> pd.Series:
    """Per study run (index ``run``), the dose the network receives: the mean over the shapes of
    ln(large_units / small_units) on the Goal map (the manipulation check, ``map == "goal"``),
    the map that feeds the network (the Object map does not)."""
    goal = checks[checks["map"] == "goal"]
    log_ratio = np.log(goal["large_units"].to_numpy(dtype=float)) - np.log(
        goal["small_units"].to_numpy(dtype=float)
    )
    return pd.Series(log_ratio, index=goal["run"].to_numpy()).groupby(level=0, sort=False).mean()


def summary(replications: pd.DataFrame, checks: pd.DataFrame) -> pd.DataFrame:
    """One row per cue timing, measure and dose (SUMMARY_COLUMNS): the size effect over the
    replications (``readings.over_replications``: their mean, a t-interval over them), Holm's p
    over the table's hypotheses (``FAMILY_SUMMARY``; a null control's rows are not), the effect
    relative to the measure's mean, the manipulation check's mean ratios and the delivered dose
    (``delivered_doses``, its mean over the replications). Replications that all give the
    same estimate (a discrete measure) have no spread to test against: their p is undefined
    (NaN), not 0."""
    ratios = checks.groupby(["dose", "cue", "map"], sort=False)["ratio"].mean()
    delivered = delivered_doses(checks)
    rows = []
    for (cue, measure, dose), group in replications.groupby(["cue", "measure", "dose"], sort=False):
        test = over_replications(group)
        if len(group) > 1 and np.ptp(group["estimate"].to_numpy(dtype=float)) == 0:
            test["p"] = float("nan")
        rows.append(
            {"dose": dose, "cue": cue, "measure": measure, "replications": len(group),
             "large_small_ratio_object": float(ratios[(dose, cue, "object")]),
             "large_small_ratio_goal": float(ratios[(dose, cue, "goal")]),
             "delivered_dose": float(delivered.reindex(group["run"].unique()).mean()),
             "relative_to_mean": test["diff"] / float(group["cell_mean"].mean())}
            | {k: test[k] for k in ("diff", "ci_low", "ci_high", "df", "p")}
        )  # fmt: skip
    out = pd.DataFrame(rows, columns=SUMMARY_COLUMNS)
    out["p_holm"] = holm_hypotheses(out) if len(out) else []
    out["family"] = family_names(out, FAMILY_SUMMARY)
    return out


def least_squares_slope(x: np.ndarray, y: np.ndarray) -> float:
    """The least-squares slope of y on x; NaN if x does not vary."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    sxx = np.sum((x - x.mean()) ** 2)
    return float(np.sum((x - x.mean()) * (y - y.mean())) / sxx) if sxx > 0 else float("nan")


def slopes(replications: pd.DataFrame, checks: pd.DataFrame) -> pd.DataFrame:
    """Per cue timing, measure and dose axis (``AXES``), the size effect's slope on the dose
    (the removal control left out): each replication's own least-squares slope over its runs,
    on the nominal dose or on each run's own delivered dose (``delivered_doses`` of the
    manipulation check ``checks``), their mean and a t-test over the replications
    (df = replications - 1), Holm's p over the table's hypotheses, both axes one family
    (``FAMILY_SLOPES``; a null control's rows are not in it)."""
    dosed = replications[~replications["dose"].astype(str).isin(CONTROLS)]
    delivered = delivered_doses(checks)
    rows = []
    for (cue, measure), group in dosed.groupby(["cue", "measure"], sort=False):
        for axis in AXES:
            per_seed = [
                least_squares_slope(
                    rep["dose"] if axis == "nominal" else delivered.loc[rep["run"]],
                    rep["estimate"],
                )
                for _seed, rep in group.groupby("seed", sort=False)
            ]
            slope = np.array(per_seed)
            n = len(slope)
            sd = slope.std(ddof=1) if n > 1 else float("nan")
            term = t_term(slope.mean(), sd / np.sqrt(n), n - 1)
            rows.append(
                {"cue": cue, "measure": measure, "axis": axis, "replications": n,
                 "slope": term["estimate"]}
                | {k: term[k] for k in ("ci_low", "ci_high", "df", "p")}
            )  # fmt: skip
    out = pd.DataFrame(rows, columns=SLOPE_COLUMNS)
    out["p_holm"] = holm_hypotheses(out) if len(out) else []
    out["family"] = family_names(out, FAMILY_SLOPES)
    return out


def declared_family(
    summary_table: pd.DataFrame, slope_table: pd.DataFrame, declared: Mapping[str, Any]
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """The two tables with the study's declared tests (config ``size_dose.declared``: the size
    effect at each of its ``doses`` and the slope on each of its ``slopes`` axes, on its
    ``measure``, under every cue timing) made one family, ``FAMILY_DECLARED``, Holm-adjusted
    over themselves alone; every other hypothesis of each table re-adjusted within its own
    exploration family without them. A declared test that the tables do not hold is refused."""
    summary_table, slope_table = summary_table.copy(), slope_table.copy()
    doses = {str(dose_value(d)) for d in declared["doses"]}
    in_summary = (summary_table["measure"] == declared["measure"]) & summary_table["dose"].map(
        lambda d: str(dose_value(d)) in doses
    )
    in_slopes = (slope_table["measure"] == declared["measure"]) & slope_table["axis"].isin(
        declared["slopes"]
    )
    expected = len(summary_table["cue"].unique()) * (len(doses) + len(set(declared["slopes"])))
    if int(in_summary.sum() + in_slopes.sum()) != expected:
        raise ValueError(
            f"size_dose.declared names {expected} tests, the study's tables hold "
            f"{int(in_summary.sum() + in_slopes.sum())}: every declared dose must be in "
            "size_dose.doses and every slope axis one of " + ", ".join(AXES)
        )
    adjusted = holm(
        np.concatenate([summary_table.loc[in_summary, "p"], slope_table.loc[in_slopes, "p"]])
    )
    n = int(in_summary.sum())
    for table, chosen, exploration, values in (
        (summary_table, in_summary, FAMILY_SUMMARY, adjusted[:n]),
        (slope_table, in_slopes, FAMILY_SLOPES, adjusted[n:]),
    ):
        table.loc[chosen, "p_holm"] = values
        table.loc[chosen, "family"] = FAMILY_DECLARED
        rest = (table["family"] == exploration).to_numpy()
        table.loc[rest, "p_holm"] = holm(table.loc[rest, "p"].to_numpy(dtype=float))
    return summary_table, slope_table


#: The family of the grips' distance's share (``grip_distance_share``): chosen after the
#: equal-grips control's results were read, so exploration.
FAMILY_GRIPS = "exploration: the grips' distance"

#: The columns of data/size_dose/grip_distance.csv.
GRIP_COLUMNS = ["cue", "measure", "replications", "diff", "ci_low", "ci_high", "df", "p",
                "family", "p_holm"]  # fmt: skip


def grip_distance_share(replications: pd.DataFrame, measure: str = "rmse") -> pd.DataFrame:
    """Per cue timing, how much of the dose-0 size effect the grips' distance carries: each
    replication's size effect at dose 0 minus its size effect at dose 0 with every object's
    grips at one distance (``equal_grips``: the same seed, so the same demonstrations before
    the move, maps and initial networks), tested over the replications (t, replications - 1
    df); Holm within ``FAMILY_GRIPS``. Empty without the control."""
    rows = []
    dose = replications["dose"].astype(str)
    for cue, group in replications[replications["measure"] == measure].groupby("cue", sort=False):
        by = {
            level: group[dose.loc[group.index] == level].set_index("seed")["estimate"]
            for level in ("0.0", "equal_grips")
        }
        seeds = by["0.0"].index.intersection(by["equal_grips"].index)
        if len(seeds) == 0:
            continue
        diff = (by["0.0"].loc[seeds] - by["equal_grips"].loc[seeds]).to_numpy(dtype=float)
        n = len(diff)
        sd = diff.std(ddof=1) if n > 1 else float("nan")
        term = t_term(diff.mean(), sd / np.sqrt(n), n - 1)
        rows.append(
            {"cue": cue, "measure": measure, "replications": n, "diff": term["estimate"]}
            | {k: term[k] for k in ("ci_low", "ci_high", "df", "p")}
        )
    out = pd.DataFrame(rows, columns=GRIP_COLUMNS)
    out["family"] = FAMILY_GRIPS
    out["p_holm"] = holm(out["p"].to_numpy(dtype=float)) if len(out) else []
    return out


# ---- the design's power --------------------------------------------------------------------

#: The size effects (RMSE, small - large) the power table asks about, at dose 0, and the test's
#: two-sided alpha; the power wanted, and the most replications looked at to reach it.
POWER_EFFECTS: tuple[float, ...] = (0.01, 0.02, 0.04)
POWER_ALPHA = 0.05
POWER_TARGET = 0.8
MOST_REPLICATIONS = 100

#: The columns of data/size_dose/power.csv.
POWER_COLUMNS = [
    "cue",
    "measure",
    "effect",
    "replications",
    "networks",
    "sigma_rep",
    "sigma_net",
    "alpha",
    "power",
    "alpha_holm_bound",
    "power_holm_bound",
    "replications_for_80",
    "replications_for_80_holm_bound",
]


def variance_components(rows: pd.DataFrame) -> dict[str, float]:
    """How a replication's size estimate varies, by the method of moments, from replications
    of one design (rows with ``estimate``, its ``se`` and ``networks``). A replication's se is
    sigma_net / sqrt(networks), so sigma_net^2 is the pooled se^2 * networks (the between-network
    variance of the per-network contrast); sigma_rep^2, the between-replication variance beyond
    it, is the variance of the estimates minus its expected within part, mean(se^2), floored at
    0 (NaN with one replication)."""
    se2 = rows["se"].to_numpy(dtype=float) ** 2
    networks = rows["networks"].to_numpy(dtype=float)
    estimates = rows["estimate"].to_numpy(dtype=float)
    between = estimates.var(ddof=1) - se2.mean() if len(rows) > 1 else float("nan")
    return {
        "sigma_rep": float(np.sqrt(max(between, 0.0))) if np.isfinite(between) else float("nan"),
        "sigma_net": float(np.sqrt((se2 * networks).mean())),
        "networks": int(round(networks.mean())),
    }


def power(
    effect: float,
    replications: int,
    networks: int,
    sigma_rep: float,
    sigma_net: float,
    alpha: float = POWER_ALPHA,
) -> float:
    """The power of the study's test of a size effect (``readings.over_replications``: a t-test
    of the replications' estimates, df = R - 1, two-sided): each estimate has variance
    tau^2 = sigma_rep^2 + sigma_net^2 / networks, so t is noncentral t with df R - 1 and
    noncentrality effect * sqrt(R) / tau, and the power is P(t > c) + P(t < -c), c the central
    t's 1 - alpha/2 quantile; P(t < -c) as P(t' > c) with the noncentrality negated (scipy's
    lower tail of a far noncentral t can be NaN, its upper tails are not). NaN with fewer than
    two replications or no variance (no test)."""
    from scipy import stats as sps

    tau = float(np.sqrt(sigma_rep**2 + sigma_net**2 / networks))
    if replications < 2 or not (np.isfinite(tau) and tau > 0):
        return float("nan")
    df = replications - 1
    ncp = effect * np.sqrt(replications) / tau
    c = float(sps.t.ppf(1 - alpha / 2, df))
    return float(sps.nct.sf(c, df, ncp) + sps.nct.sf(c, df, -ncp))


def replications_for(
    effect: float, networks: int, sigma_rep: float, sigma_net: float, alpha: float = POWER_ALPHA
) -> int | None:
    """The fewest replications (2 .. ``MOST_REPLICATIONS``) whose test has at least
    ``POWER_TARGET`` power (``power``); None if even the most have less."""
    for replications in range(2, MOST_REPLICATIONS + 1):
        if power(effect, replications, networks, sigma_rep, sigma_net, alpha) >= POWER_TARGET:
            return replications
    return None


def family_size(table: pd.DataFrame, family: str) -> int:
    """The tests of ``family`` in a table with a defined p (those Holm adjusts over)."""
    return int(np.isfinite(table.loc[table["family"] == family, "p"].to_numpy(dtype=float)).sum())


def power_table(replications: pd.DataFrame, tests: int, measure: str = "rmse") -> pd.DataFrame:
    """Per cue timing, the default design's power (``power``) to detect each size effect of
    ``POWER_EFFECTS`` at dose 0, with the variance components of that design's dose-0 rows
    (``variance_components``): at alpha, and at alpha / ``tests`` (``tests``: the size study's
    family, ``FAMILY_SUMMARY``), Holm's first step, Bonferroni's: a lower bound on the power
    after Holm, whose threshold for any test is at least that. ``replications_for_80``: the
    fewest replications with 80% power at alpha, and at the Holm bound (empty if more than
    ``MOST_REPLICATIONS``)."""
    dose = replications["dose"].astype(str)
    zero = ~dose.isin(CONTROLS) & (pd.to_numeric(dose, errors="coerce") == 0)
    rows = []
    for cue, group in replications[zero & (replications["measure"] == measure)].groupby(
        "cue", sort=False
    ):
        parts = variance_components(group)
        design = {"replications": int(group["seed"].nunique()), "networks": parts["networks"]}
        spread = {k: parts[k] for k in ("sigma_rep", "sigma_net")}
        bound = POWER_ALPHA / max(tests, 1)
        for effect in POWER_EFFECTS:
            rows.append(
                {"cue": cue, "measure": measure, "effect": effect} | design | spread
                | {"alpha": POWER_ALPHA, "power": power(effect, **design, **spread),
                   "alpha_holm_bound": bound,
                   "power_holm_bound": power(effect, **design, **spread, alpha=bound),
                   "replications_for_80": replications_for(
                       effect, design["networks"], **spread),
                   "replications_for_80_holm_bound": replications_for(
                       effect, design["networks"], **spread, alpha=bound)}
            )  # fmt: skip
    out = pd.DataFrame(rows, columns=POWER_COLUMNS)
    for column in ("replications_for_80", "replications_for_80_holm_bound"):
        out[column] = out[column].astype("Int64")
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
    the replications (df = replications - 1), per dose and cue timing; Holm's p over the table
    (``FAMILY_MOTOR``).
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
        out["family"] = FAMILY_MOTOR
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
