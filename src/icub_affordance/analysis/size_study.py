"""What drives the size effect: the dose of size coding, its manipulation check, the removal
control, object size crossed with the distance between an object's two grips, and the
demonstrations' geometry.

The paper explains why large objects are categorised faster by the Object map's larger cluster
for a larger object. Here the width of the Object and Goal maps' clusters per unit of input is
a dose (config ``size_dose``), each dose a run of the model replicated with fresh seeds, and a
control run sends no size at all (``size_free_input``). The manipulation check counts the units
each map's cluster lifts above one half, large over small, per shape.

With four objects a large object's two grips end further apart than its small partner's, so
size and the grips' distance go together. The crossed design (config ``size_dose.crossed``)
runs every replication twice, with the grips as demonstrated and with each object's grips moved
to its same-shape partner's distance (``grip_distance.swapped_grips``), and measures each run's gap
(``grip_gaps``). Each replication's two size effects against its two gaps give a line, whose
value at no gap is size's part and whose rise over the natural gap is the grips' distance's part
(``separated``); the declared tests (``declared_tests``) are one-sample t-tests of those parts
over the replications, each replication one observation. The manipulation itself (the shapes,
the removal control's size-free maps, the manipulation check) is ``learning.size_manipulation``.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from icub_affordance.analysis import replicated
from icub_affordance.analysis.paper_claims import power, sd_interval
from icub_affordance.analysis.reading_tests import (
    family_names,
    flat_term,
    holm_hypotheses,
    over_replications,
)
from icub_affordance.analysis.statistics import holm
from icub_affordance.learning.grip_distance import trajectory_grip_distances
from icub_affordance.learning.size_manipulation import CONTROLS, SHAPES
from icub_affordance.trials.scores import analysed

#: The effect the study is about (the per-network contrast of the same name).
EFFECT = "size"

#: The Holm families of the study's tables (a row's ``family``).
FAMILY_SUMMARY = "exploration: size study"
#: The crossed design's declared tests (config ``size_dose.crossed``), Holm over themselves.
FAMILY_DECLARED = "size study: declared"
#: The motor tests: on the removal runs planned with the study; at every dose added after the
#: chapter's first results had been read; each its own family, never pooled.
FAMILY_MOTOR_PLANNED = "exploration: size study motor (planned)"
FAMILY_MOTOR_ADDED = "exploration: size study motor (added after results)"
#: The same attribution on a second metric of the grips' distance, the trajectories' RMS distance
#: (``grip_distance.trajectory_grip_distances``), asked by a referee once the declared results
#: were read: Holm over itself alone, never pooled with the declared family.
FAMILY_TRAJECTORY = "exploration: size study, grips' trajectory distance (added after results)"
#: The two metrics of the grips' distance: the declared one (between the final postures) and
#: the one added after results (the trajectories' RMS distance).
FINAL_POSTURE, TRAJECTORY = "final_posture", "trajectory_rms"
#: The added test of which part is the larger: per replication |size's part| - |the grips'
#: distance's part| (positive: size's own part the larger).
SIZE_LARGER = "size_larger"


#: The grips as the networks learn them: as demonstrated, or each object's at its same-shape
#: partner's distance (config ``size_dose.crossed.grip_arrangements``).
NATURAL, SWAPPED = "natural", "swapped"


#: The columns of data/size_dose/summary.csv (the contract first).
SUMMARY_COLUMNS = [
    "dose",
    "arrangement",
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


def summary(replications: pd.DataFrame, checks: pd.DataFrame, least: int) -> pd.DataFrame:
    """One row per cue timing, measure, dose and grip arrangement (SUMMARY_COLUMNS): the size effect
    over the replications (``reading_tests.over_replications``: their mean, a t-interval over them,
    on at least ``least`` defined estimates, config ``confirmation.min_replications``; below it no
    p, df 0: not assessable), Holm's p over the table's hypotheses (``FAMILY_SUMMARY``, exploration;
    a null control's rows are not), the effect relative to the measure's mean, the manipulation
    check's mean ratios and the delivered dose (``delivered_doses``, its mean over the
    replications). Replications that all give the same estimate (a discrete measure) have no spread
    to test against: their p is undefined (NaN), not 0."""
    keys = ["dose", "arrangement", "cue"]
    ratios = checks.groupby([*keys, "map"], sort=False)["ratio"].mean()
    delivered = delivered_doses(checks)
    rows = []
    for (cue, measure, dose, arrangement), group in replications.groupby(
        ["cue", "measure", "dose", "arrangement"], sort=False
    ):
        test = over_replications(group, least)
        if len(group) > 1 and np.ptp(group["estimate"].to_numpy(dtype=float)) == 0:
            test["p"] = float("nan")
        at = (dose, arrangement, cue)
        rows.append(
            {"dose": dose, "arrangement": arrangement, "cue": cue, "measure": measure,
             "replications": len(group),
             "large_small_ratio_object": float(ratios[(*at, "object")]),
             "large_small_ratio_goal": float(ratios[(*at, "goal")]),
             "delivered_dose": float(delivered.reindex(group["run"].unique()).mean()),
             "relative_to_mean": test["diff"] / float(group["cell_mean"].mean())}
            | {k: test[k] for k in ("diff", "ci_low", "ci_high", "df", "p")}
        )  # fmt: skip
    out = pd.DataFrame(rows, columns=SUMMARY_COLUMNS)
    out["p_holm"] = holm_hypotheses(out) if len(out) else []
    out["family"] = family_names(out, FAMILY_SUMMARY)
    return out


def grip_gaps(geometry: pd.DataFrame) -> pd.Series:
    """Per run (index ``run``), the gap: the large minus the small object's grip distance
    (``demo_grip_distance`` of the demonstrations that run's networks learn), the mean over the
    shapes. Positive where the large objects' grips lie the further apart (as demonstrated)."""
    per_object = geometry.groupby(["run", "object"], sort=False)["demo_grip_distance"].first()
    gaps = {}
    for run in dict.fromkeys(geometry["run"]):
        distance = per_object.loc[run]
        gaps[run] = float(np.mean([distance[large] - distance[small]
                                   for large, small in SHAPES.values()]))  # fmt: skip
    return pd.Series(gaps, name="gap")


#: The columns of data/size_dose/crossed.csv: per run of the crossed design, both factors as
#: measured (the Goal map's delivered size, each object's grips' distance and the gap) and the
#: run's size effect on the declared measure.
CROSSED_COLUMNS = ["cue", "dose", "arrangement", "seed", "run", "measure", "delivered_dose",
                   *(f"grip_distance_{o}" for pair in SHAPES.values() for o in pair), "gap",
                   "estimate"]  # fmt: skip


def crossed_runs(
    replications: pd.DataFrame, checks: pd.DataFrame, geometry: pd.DataFrame, measure: str
) -> pd.DataFrame:
    """One row per run of the crossed design (the removal control left out): its size effect on
    ``measure`` and the two factors it was run at, as measured (``CROSSED_COLUMNS``)."""
    runs = replications[
        (replications["measure"] == measure) & ~replications["dose"].astype(str).isin(CONTROLS)
    ]
    delivered, gaps = delivered_doses(checks), grip_gaps(geometry)
    distance = geometry.groupby(["run", "object"], sort=False)["demo_grip_distance"].first()
    rows = []
    for _, row in runs.iterrows():
        run = row["run"]
        rows.append(
            {k: row[k] for k in ("cue", "dose", "arrangement", "seed", "run", "measure")}
            | {"delivered_dose": float(delivered[run]), "gap": float(gaps[run]),
               "estimate": float(row["estimate"])}
            | {f"grip_distance_{o}": float(distance[(run, o)])
               for pair in SHAPES.values() for o in pair}
        )  # fmt: skip
    return pd.DataFrame(rows, columns=CROSSED_COLUMNS)


#: The columns of data/size_dose/separated.csv: per replication, cue timing and dose, the two
#: runs' effects and gaps and the line through them.
SEPARATED_COLUMNS = ["cue", "dose", "seed", "measure", "effect_natural", "effect_swapped",
                     "gap_natural", "gap_swapped", "slope", "size", "grip_distance"]  # fmt: skip


def separate(
    effect_natural: float, effect_swapped: float, gap_natural: float, gap_swapped: float
) -> dict[str, float]:
    """The line c = size + slope * gap through a replication's two runs (effect c, gap g):
    ``size``, its value at no gap (size's part), and ``grip_distance``, slope * the natural gap
    (the part of the natural run's effect the gap carries; the two add up to the natural run's
    effect). Undefined (NaN) where the two gaps are equal: no line."""
    run = gap_natural - gap_swapped
    if not (np.isfinite(run) and run != 0):
        nan = float("nan")
        return {"slope": nan, "size": nan, "grip_distance": nan}
    slope = (effect_natural - effect_swapped) / run
    return {"slope": float(slope), "size": float(effect_natural - slope * gap_natural),
            "grip_distance": float(slope * gap_natural)}  # fmt: skip


def separated(crossed: pd.DataFrame) -> pd.DataFrame:
    """Per cue timing, dose and replication, size's and the grips' distance's parts of the size
    effect (``separate``) from the replication's natural and swapped runs (``crossed_runs``)."""
    rows = []
    for (cue, dose, seed), runs in crossed.groupby(["cue", "dose", "seed"], sort=False):
        by = runs.set_index("arrangement")
        if not {NATURAL, SWAPPED} <= set(by.index):
            continue
        values = {
            "effect_natural": float(by.loc[NATURAL, "estimate"]),
            "effect_swapped": float(by.loc[SWAPPED, "estimate"]),
            "gap_natural": float(by.loc[NATURAL, "gap"]),
            "gap_swapped": float(by.loc[SWAPPED, "gap"]),
        }
        rows.append(
            {"cue": cue, "dose": dose, "seed": seed, "measure": runs["measure"].iloc[0]}
            | values | separate(*values.values())
        )  # fmt: skip
    return pd.DataFrame(rows, columns=SEPARATED_COLUMNS)


#: The columns of data/size_dose/declared.csv.
DECLARED_COLUMNS = ["test", "cue", "dose", "measure", "replications", "left_out", "estimate",
                    "sd", "ci_low", "ci_high", "df", "p", "p_holm", "family"]  # fmt: skip


def one_sample(values: np.ndarray, least: int) -> dict[str, float]:
    """The one-sample t-test of mean 0 over the defined ``values`` (one per replication; an
    undefined one left out and counted): the mean, SD, t-interval, df and p; made on at least
    ``least`` defined values (``replicated.over_replications``; below it no p, df 0)."""
    values = np.asarray(values, dtype=float)
    defined = values[np.isfinite(values)]
    n = len(defined)
    sd = float(defined.std(ddof=1)) if n > 1 else float("nan")
    term = replicated.over_replications(defined, least)
    return {"replications": n, "left_out": len(values) - n, "sd": sd} | {
        k: term[k] for k in ("estimate", "ci_low", "ci_high", "df", "p")
    }


def declared_tests(
    parts: pd.DataFrame,
    tests: Sequence[str],
    doses: Sequence[float],
    least: int,
    family: str = FAMILY_DECLARED,
) -> pd.DataFrame:
    """The crossed design's declared family (config ``size_dose.crossed.tests``), Holm over
    itself alone (``FAMILY_DECLARED``): per cue timing, ``size`` and ``grip_distance`` at every
    dose (``separated``), and ``dose``, the natural runs' size effect at the largest dose minus at
    the smallest, per replication; each a one-sample t over the replications (``one_sample``, on
    at least ``least``). ``dose`` for the
    contrast reads "<largest> - <smallest>". ``family``: another family's name, for the same
    tests on another metric (``trajectory_geometry``), Holm within it alone."""
    low, high = float(min(doses)), float(max(doses))
    rows = []
    for cue, by_cue in parts.groupby("cue", sort=False):
        dose = by_cue["dose"].astype(float)
        for test in tests:
            if test == "dose":
                natural = by_cue.assign(dose=dose).pivot(index="seed", columns="dose",
                                                         values="effect_natural")  # fmt: skip
                values = {f"{high:g} - {low:g}": (natural[high] - natural[low]).to_numpy()}
            else:
                values = {f"{d:g}": by_cue.loc[dose == d, test].to_numpy() for d in doses}
            for at, column in values.items():
                rows.append(
                    {"test": test, "cue": cue, "dose": at, "measure": by_cue["measure"].iloc[0]}
                    | one_sample(column, least)
                )
    out = pd.DataFrame(rows, columns=DECLARED_COLUMNS)
    out["p_holm"] = holm(out["p"].to_numpy(dtype=float)) if len(out) else []
    out["family"] = family
    return out


def metric_tests(
    parts: Mapping[str, pd.DataFrame], doses: Sequence[float], least: int
) -> pd.DataFrame:
    """The family added after results (``FAMILY_TRAJECTORY``): on the trajectory metric
    (``parts[TRAJECTORY]``, ``separated`` on ``trajectory_geometry``), size's and the grips'
    distance's parts at every dose and cue timing, as the declared family tests them on the
    final postures; and on both metrics, which part is the larger (``SIZE_LARGER``, per
    replication |size| - |grip_distance|), since "carries most" is a difference and is said only
    from its own test. One-sample t over the replications (``declared_tests``), Holm over the
    whole family; ``metric`` names the grips' distance each row is on. The declared parts on the
    final postures are not tested again here."""
    frames = []
    for metric, tests in ((TRAJECTORY, ["size", "grip_distance", SIZE_LARGER]),
                          (FINAL_POSTURE, [SIZE_LARGER])):  # fmt: skip
        frame = parts[metric]
        frame = frame.assign(**{SIZE_LARGER: frame["size"].abs() - frame["grip_distance"].abs()})
        found = declared_tests(frame, tests, doses, least, family=FAMILY_TRAJECTORY)
        frames.append(found.assign(metric=metric))
    out = pd.concat(frames, ignore_index=True)
    out = out[["metric", *DECLARED_COLUMNS]]
    out["p_holm"] = holm(out["p"].to_numpy(dtype=float))
    return out


#: The columns of data/size_dose/power.csv.
POWER_COLUMNS = ["test", "cue", "dose", "replications", "effect_of_interest", "sd", "sd_low",
                 "sd_high", "alpha_at_least", "power_at_least", "power_at_least_low",
                 "power_at_least_high", "alpha_at_most", "power_at_most", "power_at_most_low",
                 "power_at_most_high"]  # fmt: skip


def power_table(declared: pd.DataFrame, effect: float, alpha: float) -> pd.DataFrame:
    """Per declared test, its power to detect ``effect`` (``paper_claims.power``: a two-sided
    one-sample t over its replications), from the build's own SD of the replications' values
    and at the two ends of that SD's 95% chi-square interval (``paper_claims.sd_interval``): the
    range the variance estimate allows (a larger SD, less power). At alpha / the family's size
    (*at least*: Holm's threshold for any test of the family is at least that, so its power is
    at least this) and at alpha (*at most*: no test of the family is tried at a larger level)."""
    tested = int(np.isfinite(declared["p"].to_numpy(dtype=float)).sum())
    at_least = alpha / max(tested, 1)
    rows = []
    for _, row in declared.iterrows():
        n, sd = int(row["replications"]), float(row["sd"])
        low, high = sd_interval(sd, n)
        out = {k: row[k] for k in ("test", "cue", "dose", "replications")} | {
            "effect_of_interest": effect,
            "sd": sd,
            "sd_low": low,
            "sd_high": high,
        }
        for name, level in (("at_least", at_least), ("at_most", alpha)):
            out |= {f"alpha_{name}": level, f"power_{name}": power(effect, sd, n, level),
                    f"power_{name}_low": power(effect, high, n, level),
                    f"power_{name}_high": power(effect, low, n, level)}  # fmt: skip
        rows.append(out)
    return pd.DataFrame(rows, columns=POWER_COLUMNS)


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


def trajectory_geometry(angles: np.ndarray, objects: Sequence[str]) -> pd.DataFrame:
    """Per object, the grips' distance on the second metric (``demo_grip_distance``: the RMS
    distance between the two grips' trajectories, ``grip_distance.trajectory_grip_distances``),
    in ``demo_geometry``'s column, so that ``crossed_runs`` and ``separated`` take the study apart
    on it as they do on the declared final-posture distance."""
    distance = trajectory_grip_distances(angles)
    return pd.DataFrame({"object": list(objects), "demo_grip_distance": distance.astype(float)})


def geometry_of_trials(geometry: pd.DataFrame, grips: Sequence[str]) -> pd.DataFrame:
    """Each object's geometry for the grip a categorisation trial requires: the rows of
    ``demo_geometry`` keyed by object and target grip name."""
    out = geometry.copy()
    out["target_grip"] = [grips[g] for g in out["grip"]]
    return out.drop(columns="grip")


def motor_tests(trials: pd.DataFrame, least: int, measure: str = "rmse") -> pd.DataFrame:
    """Do the demonstrations' differences line up with each object's error? ``trials``: the
    categorisation trials (closed loop) of the study's runs, with their ``dose`` (or "removed"),
    grip ``arrangement``, cue timing, replication (``seed``), network, object and target grip,
    the measure, and the geometry of the required grip's demonstrations (``GEOMETRY`` columns,
    from that run's own demonstrations). Per network, the least-squares slope of its four
    objects' mean error on each geometry measure (standardised over the four). The networks
    of one replication share its demonstrations, so the unit is the replication: its networks'
    mean slope, tested over the replications (df = replications - 1; on at least ``least``,
    ``replicated.over_replications``), per dose, arrangement
    and cue timing; Holm's p within each family: the removal runs' (``FAMILY_MOTOR_PLANNED``,
    planned with the study) and every other run's (``FAMILY_MOTOR_ADDED``, added after
    results), never pooled.
    With four objects a measure that ranks the objects as size does cannot be told from size."""
    keys = ["dose", "arrangement", "cue", "seed", "network", "object"]
    per_object = (
        trials.groupby(keys, sort=False)
        .agg({measure: "mean", **{g: "mean" for g in GEOMETRY}})
        .reset_index()
    )
    rows = []
    for (dose, arrangement, cue), by_cue in per_object.groupby(
        ["dose", "arrangement", "cue"], sort=False
    ):
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
            term = replicated.over_replications(values, least)
            rows.append(
                {
                    "dose": dose,
                    "arrangement": arrangement,
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
        planned = out["dose"].astype(str).isin(CONTROLS).to_numpy()
        out["family"] = np.where(planned, FAMILY_MOTOR_PLANNED, FAMILY_MOTOR_ADDED)
        out["p_holm"] = np.nan
        for chosen in (planned, ~planned):
            out.loc[chosen, "p_holm"] = holm(out.loc[chosen, "p"].to_numpy(dtype=float))
    return out


def ranked_like_size(geometry: pd.DataFrame) -> list[str]:
    """The demonstrations' measures (``GEOMETRY``) that rank the objects as their size does in
    every replication of ``geometry``'s natural runs (``demo_geometry`` rows with a ``seed`` and
    an ``arrangement``): larger for the big ball than the small one and for the big cube than
    the small one (mean over the grips). With four objects per network, a slope on such a
    measure cannot be told from size; the swapped runs reverse the grips' distance on purpose."""
    geometry = geometry[geometry["arrangement"] == NATURAL]
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
