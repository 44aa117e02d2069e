"""The statistics of the robot test: its trials counted, tabled and tested, for every variant,
the body's tolerance and the replays.

Kept apart from the trials' physics (``robot_trials``) so that the robot jobs start without pandas
and the statistics, and the summary and the book read the tables without the simulator's code.

In closed loop a network's test sequences of one object and task are one and the same movement
(``on_robot.embodied_network``): every count, rate and test here is over distinct trials, one
per network x object x task (``distinct_trials``), never over the duplicated sequences. The
variants' congruency and size effects are tested per network (``trial_effects.contrast_tests``),
with Fisher's exact test where the contrast has no variance; their congruency x size interaction by
the per-network contrast only; and Holm's adjustment over them all, one family
(``ROBOT_FAMILY``). Each effect keeps its counts per cell and per object, so that a reader sees
which trials were missed.

Beside the variants' table and effects (rule ``robot_summary``), the rule ``robot_statistics``
reads the joined robot trials (``data/embodied/trials.csv``), the body's tolerance trials
(``data/embodied/tolerance.csv``) and the demonstrations' replays (``data/embodied/replay.csv``)
for the share held and the median palm error per arm noise, the share held per bin of palm error
(the tolerance trials, the replayed demonstrations and each variant's grasping trials), the
replayed demonstrations' palm error, and the exact McNemar tests of the variants that differ in
the learning-rate schedule alone (``data/embodied/statistics.json``; the book only formats them).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from icub_affordance.analysis.statistics import holm, mcnemar_exact, mean_ci
from icub_affordance.analysis.trial_effects import (
    adjust_families,
    categorisation_trials,
    cell_means,
    contrast_tests,
    network_contrasts,
    per_network_contrasts,
    repeated_measures_anova,
    simple_effects,
    trial_conditions,
)
from icub_affordance.learning.variants import NetworkVariant
from icub_affordance.vocabulary import TOUCH_NAMES

#: The family of the config's own networks' robot tests in ``success_analysis``.
OWN_ROBOT_FAMILY = "exploration: the config's own networks on the robot"

#: The columns a robot trial's physics decides: the same in every test sequence of one network x
#: object x task, which are one movement on the robot (``embodied_network``).
PHYSICAL_COLUMNS = (
    "success",
    "wrong_grip_hold",
    "grip_used",
    "lift_m",
    "contact_time",
    "palm_error_mm",
    *TOUCH_NAMES,
)

#: The columns that compare a trial with one test sequence's demonstration: a distinct trial
#: keeps their mean over its sequences.
PER_SEQUENCE_COLUMNS = ("final_error", "rmse")


def trial_keys(trials: pd.DataFrame) -> list[str]:
    """What tells one physical robot trial from another: the run (where the table has it), the
    network, the task and the object."""
    return [c for c in ("run",) if c in trials.columns] + ["network", "task", "object"]


def distinct_trials(trials: pd.DataFrame) -> pd.DataFrame:
    """One row per physical trial (``trial_keys``: run, network, task, object), in the order of
    their first rows: a network's test sequences of one object and task are one movement on the
    robot and count once in every count, rate and test of the summary.

    The physical outcome (``PHYSICAL_COLUMNS``) is the first sequence's, and a ValueError is
    raised where the sequences disagree on it (they were then not one trial); the distances from
    the sequences' demonstrations (``PER_SEQUENCE_COLUMNS`` and every ``rmse_step*``) are their
    mean; ``sequence`` and ``held_out``, which name one sequence, are dropped.
    """
    keys = trial_keys(trials)
    groups = trials.groupby(keys, sort=False)
    physical = [c for c in PHYSICAL_COLUMNS if c in trials.columns]
    varying = groups[physical].nunique(dropna=False) if physical else None
    if varying is not None and (varying > 1).any().any():
        bad = varying.columns[(varying > 1).any()].tolist()
        raise ValueError(f"the test sequences of one robot trial differ in {bad}")
    means = [c for c in trials.columns if c in PER_SEQUENCE_COLUMNS or c.startswith("rmse_step")]
    out = trials.drop_duplicates(keys).drop(columns=["sequence", "held_out"], errors="ignore")
    if means:
        averaged = groups[means].mean()
        out = out.drop(columns=means).merge(averaged, left_on=keys, right_index=True, how="left")
        out = out[[c for c in trials.columns if c in out.columns]]
    return out.reset_index(drop=True)


def success_table(trials: pd.DataFrame) -> pd.DataFrame:
    """Success, grip read and final error by task, congruency and size, over distinct trials
    (``distinct_trials``): ``trials`` counts them, ``wrong_grip_hold`` how many held the object
    with the other grip than the required one (failures)."""
    df = distinct_trials(trials)
    df = df.assign(condition=trial_conditions(df))
    groups = df.groupby(["condition", "size"], sort=True)
    table = groups.agg(
        trials=("success", "size"),
        success=("success", "mean"),
        final_error=("final_error", "mean"),
    )
    for grip in ("power", "precision", "none"):
        table[f"grip_{grip}"] = groups["grip_used"].apply(lambda g, grip=grip: (g == grip).mean())
    table["grip_target"] = groups.apply(
        lambda g: (g["grip_used"] == g["target_grip"]).mean(), include_groups=False
    )
    table["wrong_grip_hold"] = groups["wrong_grip_hold"].apply(lambda g: int(g.astype(bool).sum()))
    return table.reset_index()


def success_analysis(trials: pd.DataFrame, replay: pd.DataFrame) -> dict[str, object]:
    """Does congruency (or size) change the robot's categorisation grasps? Over distinct trials
    (``distinct_trials``: one per network x object x task).

    For success (0/1) and for the final posture error: each network's mean per congruency x size
    cell, the per-network incongruent - congruent difference with its 95% t-interval, the
    per-network contrasts used for inference (``trial_effects.network_contrasts``: t over networks),
    and, descriptive only, the repeated-measures ANOVA (network as subject; it averages each
    network's cell, so the duplicated sequences never changed it). Where every network scores the
    same in every cell the ANOVA is undefined and reported as None.
    """
    trials = distinct_trials(trials)
    df = categorisation_trials(trials, "embodied")
    df["success"] = df["success"].astype(float)
    measures = {}
    for measure in ("success", "final_error"):
        per_net = df.groupby(["network", "congruency"])[measure].mean().unstack()
        mean, lo, hi = mean_ci((per_net["incongruent"] - per_net["congruent"]).to_numpy())
        with np.errstate(divide="ignore", invalid="ignore"):
            try:
                anova = repeated_measures_anova(df, measure)
            except (ValueError, ZeroDivisionError, np.linalg.LinAlgError):
                anova = None
            try:
                contrasts = network_contrasts(df, measure)
            except (ValueError, np.linalg.LinAlgError):
                contrasts = None
        if anova and not all(np.isfinite(r["F"]) for r in anova.values()):
            anova = None
        measures[measure] = {
            "means": cell_means(df, measure),
            "incongruent_minus_congruent": {"mean": mean, "ci_low": lo, "ci_high": hi},
            "contrasts": contrasts,
            "repeated_measures": anova,
        }
    # the config's own networks' final-error tests on the robot, one family (their success is
    # tested with every variant's, variant_effects)
    own = [
        measures["final_error"]["contrasts"][e]
        for e in ("congruency", "size")
        if measures["final_error"]["contrasts"]
    ]
    adjust_families([(OWN_ROBOT_FAMILY, term) for term in own])
    grasping = trials[trials["task"] == "grasping"]
    return {
        "n_networks": int(df["network"].nunique()),
        "n_trials": int(len(trials)),
        "n_grasping_trials": int(len(grasping)),
        "n_categorisation_trials": int(len(df)),
        "success_rate": float(trials["success"].astype(float).mean()),
        "grasping_success": float(grasping["success"].astype(float).mean()),
        "categorisation_success": float(df["success"].mean()),
        "touching_rate": float((trials["grip_used"] != "none").mean()),
        "wrong_grip_holds": int(trials["wrong_grip_hold"].astype(bool).sum()),
        "measures": measures,
        "replay_success": {
            plan: float(group["success"].astype(float).mean())
            for plan, group in replay.groupby("plan")
        },
        "replay_trials": {plan: int(len(group)) for plan, group in replay.groupby("plan")},
        # replays that held the object with the other grip than the one demonstrated (failures)
        "replay_wrong_grip_holds": {
            plan: int(group["wrong_grip_hold"].astype(bool).sum())
            for plan, group in replay.groupby("plan")
        },
    }


# -- the variants (target x hidden units x iterations) ------------------------------------------

#: What tells the robot test's variants apart, the first columns of data/embodied/trials.csv.
VARIANT_COLUMNS = ("run", *NetworkVariant.keys())


def variant_table(trials: pd.DataFrame) -> pd.DataFrame:
    """One row per variant, over its distinct trials (``distinct_trials``; ``trials`` counts
    them): its success on each task, how often the required grip's fingers touched, how soon
    (contact time over the trials that touched), and how many trials held the object with the
    other grip (``{task}_wrong_grip_hold``, failures by the grip criterion)."""
    rows = []
    for key, df in distinct_trials(trials).groupby(list(VARIANT_COLUMNS), sort=False):
        row = dict(zip(VARIANT_COLUMNS, key, strict=True))
        row |= {"networks": int(df["network"].nunique()), "trials": len(df)}
        for task in ("grasping", "categorisation"):
            mine = df[df["task"] == task]
            touched = mine["contact_time"].notna()
            row |= {
                f"{task}_trials": len(mine),
                f"{task}_success": float(mine["success"].astype(float).mean()),
                f"{task}_contact": float(touched.mean()),
                f"{task}_contact_time": float(mine.loc[touched, "contact_time"].mean())
                if touched.any()
                else float("nan"),
                f"{task}_wrong_grip_hold": int(mine["wrong_grip_hold"].astype(bool).sum()),
            }
        row["success"] = float(df["success"].astype(float).mean())
        grasping = df[df["task"] == "grasping"]
        row["grasping_palm_error_mm"] = float(grasping["palm_error_mm"].median())
        rows.append(row)
    return pd.DataFrame(rows)


#: Bins of the palm's distance from the demonstrator's (mm) in which success is compared.
PALM_BINS_MM = (0.0, 3.0, 6.0, 10.0, 20.0, float("inf"))


def held_by_palm_error(trials: pd.DataFrame, edges=PALM_BINS_MM) -> pd.DataFrame:
    """Per bin of the palm's distance from the demonstrator's (column ``palm_error_mm``): the
    trials in it and the share that held the object; a bin is [low, high)."""
    errors = trials["palm_error_mm"].to_numpy(dtype=float)
    held = trials["success"].astype(bool).to_numpy()
    rows = []
    for low, high in zip(edges[:-1], edges[1:], strict=True):
        inside = (errors >= low) & (errors < high)
        n = int(inside.sum())
        rows.append({"low_mm": low, "high_mm": high, "trials": n,
                     "held": float(held[inside].mean()) if n else float("nan")})  # fmt: skip
    return pd.DataFrame(rows)


def tolerance_table(tolerance: pd.DataFrame) -> pd.DataFrame:
    """Per noise level of the body's tolerance test: how often the mean plan still grasps, and
    how far the palm ended from the demonstrator's (median, mm); success per object too."""
    rows = []
    for noise, df in tolerance.groupby("noise", sort=True):
        row = {"noise": float(noise), "trials": len(df)}
        row["success"] = float(df["success"].astype(float).mean())
        row["palm_error_mm"] = float(df["palm_error_mm"].median())
        for obj, mine in df.groupby("object", sort=False):
            row[f"{obj}_success"] = float(mine["success"].astype(float).mean())
        rows.append(row)
    return pd.DataFrame(rows)


def _counts(df: pd.DataFrame, factor: str, measure: str) -> dict[str, dict[str, float]]:
    """Per level of ``factor``: the distinct trials, how many have ``measure`` (contact time:
    those that touched), and its mean over them."""
    return {
        str(level): {
            "trials": len(g),
            "n": int(g[measure].notna().sum()),
            "mean": float(g[measure].mean()),
        }
        for level, g in df.groupby(factor, sort=True)
    }


#: The two levels of each factor the robot effects compare, the paper's faster one first.
FACTOR_LEVELS = {"congruency": ("congruent", "incongruent"), "size": ("large", "small")}

#: The interaction's key in a measure's ``tests``. With four objects it is twice the difference
#: between the trials that require a power grip (congruent large, incongruent small, under
#: either mapping) and those that require a precision grip: a grip effect, not a size one.
INTERACTION = "congruency:size"

#: The family of every robot test (``p_holm``): the variants were explored, none confirmed.
ROBOT_FAMILY = "exploration: robot"

#: What a cell or object counts for each measure: the trials held (success), or touched
#: (contact time, defined only where the required fingers touched).
COUNTED = {"success": "held", "contact_time": "touched"}


def _tally(g: pd.DataFrame, measure: str) -> dict[str, float]:
    """The distinct trials of ``g``, how many were held or touched (``COUNTED``) and the
    measure's mean over them (NaN where none)."""
    count = g[measure].sum() if measure == "success" else g[measure].notna().sum()
    mean = float(g[measure].mean()) if len(g) else float("nan")
    return {"trials": int(len(g)), COUNTED[measure]: int(count), "mean": mean}


def _cells(df: pd.DataFrame, measure: str) -> dict[str, dict[str, float]]:
    """Per congruency x size cell ("congruent_large", ...), the counts of ``_tally``: a main
    effect resting on one cell shows here."""
    return {
        f"{c}_{s}": _tally(df[(df["congruency"] == c) & (df["size"] == s)], measure)
        for c in FACTOR_LEVELS["congruency"]
        for s in FACTOR_LEVELS["size"]
    }


def _objects(df: pd.DataFrame, measure: str) -> dict[str, dict[str, object]]:
    """Per mapping and object ("A_big_ball", ...), its congruency, size and required grip, and
    the counts of ``_tally``: which objects the misses are."""
    out = {}
    for (mapping, obj), g in df.groupby(["mapping", "object"], sort=True):
        first = g.iloc[0]
        out[f"{mapping}_{obj}"] = {
            "congruency": str(first["congruency"]),
            "size": str(first["size"]),
            "target_grip": str(first["target_grip"]),
        } | _tally(g, measure)
    return out


def _exact_test(df: pd.DataFrame, factor: str) -> dict[str, object]:
    """Fisher's exact test of success against ``factor``, over the distinct trials of ``df``
    (which takes a network's two objects of a level as independent: the fallback where the
    per-network contrast has no variance to test)."""
    from scipy.stats import fisher_exact

    first, second = FACTOR_LEVELS[factor]
    table = [
        [int(g["success"].sum()), int((~g["success"]).sum())]
        for g in (df[df[factor] == first], df[df[factor] == second])
    ]
    odds, p = fisher_exact(table)
    # an odds ratio of 0 or infinity (a rate of 0 or 1) has no JSON number: None
    odds = float(odds) if np.isfinite(odds) and odds > 0 else None
    return {"method": "exact", "table": table, "odds_ratio": odds, "p": float(p)}


def _contrasts_or_none(df: pd.DataFrame, measure: str) -> tuple[dict | None, int]:
    """The per-network contrasts of ``measure`` over the networks that have all four
    congruency x size cells, and how many do; None where fewer than three do (no degrees of
    freedom) or the design is singular."""
    per_net = per_network_contrasts(df, measure)
    if len(per_net) < 3:
        return None, len(per_net)
    try:
        with np.errstate(divide="ignore", invalid="ignore"):
            return contrast_tests(per_net), len(per_net)
    except (np.linalg.LinAlgError, ValueError):
        return None, len(per_net)


def _defined(term: dict) -> bool:
    """A contrast's test is defined: its standard error is finite and not zero (networks differ)."""
    return bool(np.isfinite(term["se"]) and term["se"] > 0 and np.isfinite(term["p"]))


def _no_test(measure: str, contrasts: dict | None, networks: int, exact: bool) -> dict:
    """A term with no test, and why: too few networks with all four cells, or no variance in
    the per-network contrast; ``exact`` (the interaction of success, whose factors fall back on
    Fisher's test): says that it has no such fallback."""
    some, every = (
        ("network(s) touched in", "every network that touched in")
        if measure == "contact_time"
        else ("network(s) with trials in", "every network with trials in")
    )
    reason = (
        f"{networks} {some} all four congruency x size cells, "
        "fewer than the three a test over networks needs"
        if contrasts is None
        else f"{every} all four cells shows the same contrast"
    )
    if exact:
        reason += "; an interaction has no exact test to fall back on"
    return {"method": "none", "reason": reason}


def _measure_effects(
    tested: pd.DataFrame, counted: pd.DataFrame, measure: str, exact: pd.DataFrame | None
) -> dict[str, object]:
    """One measure's effects in one variant: the per-network contrasts over ``tested``; per
    factor the contrast's test where it is defined, else Fisher's exact test over ``exact``
    (success, as booleans) or, without it (contact time), no test and why; the interaction
    (``INTERACTION``) by the contrast only; and the counts over ``counted``, the variant's
    distinct trials, per level, per cell and per mapping and object."""
    contrasts, networks = _contrasts_or_none(tested, measure)
    tests: dict[str, object] = {}
    for factor in FACTOR_LEVELS:
        if contrasts is not None and _defined(contrasts[factor]):
            tests[factor] = {"method": "contrasts"} | contrasts[factor]
        elif exact is not None:
            tests[factor] = _exact_test(exact, factor)
        else:
            tests[factor] = _no_test(measure, contrasts, networks, exact=False)
    if contrasts is not None and _defined(contrasts[INTERACTION]):
        tests[INTERACTION] = {"method": "contrasts"} | contrasts[INTERACTION]
    else:
        tests[INTERACTION] = _no_test(measure, contrasts, networks, exact=exact is not None)
    return {
        "distinct_trials": int(len(counted)),
        "congruency": _counts(counted, "congruency", measure),
        "size": _counts(counted, "size", measure),
        "cells": _cells(counted, measure),
        "objects": _objects(counted, measure),
        "networks": networks,
        "contrasts": contrasts,
        "tests": tests,
    }


def variant_effects(trials: pd.DataFrame) -> dict[str, object]:
    """Congruency and size effects on the robot's categorisation, per variant, over distinct
    trials (``distinct_trials``: each network x object counted once, whatever the number of test
    sequences).

    Success: per factor, the per-network contrast (``trial_effects.network_contrasts`` on success as
    0/1 per network x object, a difference of proportions tested over the networks with t), where
    its test is defined; where it is not (every network shows the same contrast: no variance),
    Fisher's exact test over the distinct trials. Contact time: the per-network contrasts over the
    trials that touched, from the networks that touched in all four congruency x size cells; where
    that test is undefined (fewer than three such networks, or no variance) the effect is not
    estimable and says why. The congruency x size interaction (``INTERACTION``): the per-network
    contrast where defined, else no test (an interaction has no exact fallback).

    Each measure keeps its counts per level, per cell (``cells``: "congruent_large", ...) and per
    mapping and object (``objects``: "A_big_ball", ...), each with its distinct trials, how many
    were held or touched (``COUNTED``) and the mean; and its ``tests`` per factor and for the
    interaction ({"method": "contrasts" | "exact" | "none", ...}). Every test with a method is
    in one family over all the variants (``family``, ``ROBOT_FAMILY``; ``family_size``) with its
    p Holm-adjusted over it (``p_holm``).
    """
    out = {}
    for run, df in distinct_trials(trials).groupby("run", sort=False):
        df = df[(df["task"] == "categorisation")].copy()
        df["congruency"] = np.where(
            df["congruent"].astype(str) == "True", "congruent", "incongruent"
        )
        df["success"] = df["success"].astype(bool)
        held = df.assign(success=df["success"].astype(float))
        success = _measure_effects(held, held, "success", exact=df)
        touched = df[df["contact_time"].notna()]
        contact = _measure_effects(touched, df, "contact_time", exact=None)
        success["simple"] = _simple_or_none(held, "success")
        contact["simple"] = _simple_or_none(touched, "contact_time")
        out[str(run)] = {"success": success, "contact_time": contact}
    _holm_over_family(out)
    return out


def _simple_or_none(df: pd.DataFrame, measure: str) -> dict[str, dict] | None:
    """Each factor's effect within each level of the other (``trial_effects.simple_effects``: small
    - large among the congruent trials, ...) over the networks with all four cells, Holm over
    those of the four that have a test (``p_holm``): where a main effect comes from one cell,
    these say which. None with fewer
    than three such networks or a singular design."""
    try:
        with np.errstate(divide="ignore", invalid="ignore"):
            found = simple_effects(df, measure)
    except (np.linalg.LinAlgError, ValueError, KeyError):  # KeyError: a cell no network has
        return None
    if not found or next(iter(found.values()))["networks"] < 3:
        return None
    adjusted = holm(np.array([t["p"] for t in found.values()], dtype=float))
    return {k: t | {"p_holm": float(q)} for (k, t), q in zip(found.items(), adjusted, strict=True)}


def _holm_over_family(effects: dict[str, dict]) -> None:
    """Every test of every variant, measure and term (the robot chapter reads them together) is
    one family, ``ROBOT_FAMILY``: each gains ``family``, ``family_size`` and ``p_holm``, Holm's
    adjustment over the family, which the verdicts read. A term with no test (method "none")
    is not in the family and has no ``p_holm``."""
    tests = [
        test
        for measures in effects.values()
        for measure in measures.values()
        for test in measure["tests"].values()
        if test["method"] != "none"
    ]
    p = [t["p"] for t in tests]
    size = int(np.isfinite(p).sum())
    for test, adjusted in zip(tests, holm(p), strict=True):
        test |= {"family": ROBOT_FAMILY, "family_size": size, "p_holm": float(adjusted)}


def _plain(value):
    """``value`` with numpy scalars as Python's (for JSON)."""
    if isinstance(value, dict):
        return {key: _plain(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [_plain(item) for item in value]
    if isinstance(value, np.generic):
        return value.item()
    return value


def table_record(table: pd.DataFrame) -> dict[str, list]:
    """A table as {column: values}, in its column order, with Python's numbers (for JSON)."""
    return {column: _plain(table[column].tolist()) for column in table.columns}


def record_table(record: dict[str, list]) -> pd.DataFrame:
    """The table of ``table_record``."""
    return pd.DataFrame(record)


def grasping_trials(trials: pd.DataFrame, keys=("run",)) -> pd.DataFrame:
    """The distinct grasping trials of ``trials``: one per variant (``keys``), network and
    object (a network's test sequences of one object are one physical trial)."""
    return trials[trials["task"] == "grasping"].drop_duplicates([*keys, "network", "object"])


def paired_grasping(trials: pd.DataFrame, column: str, keys: tuple[str, ...]) -> list[dict]:
    """Robot variants that differ in ``column`` alone, compared on the same networks.

    ``trials``: ``data/embodied/trials.csv``; ``keys``: the columns that tell variants apart
    (``variants.NetworkVariant.keys()``). Variants of one group share everything but
    ``column``, so network k of each starts from the same initial weights and sees the same
    presentations: its grasping trial of an object (one physical trial, however many test
    sequences share it) pairs with the other variant's. Per pair of values: the distinct trials,
    how many each holds, the discordant pairs, and the exact McNemar test
    (``statistics.mcnemar_exact``).
    """
    grasping = grasping_trials(trials, keys)
    others = [k for k in keys if k != column]
    out = []
    for group, mine in grasping.groupby(others, sort=True):
        values = sorted(mine[column].unique())
        held = mine.pivot_table(
            index=["network", "object"], columns=column, values="success", aggfunc="first"
        ).dropna()
        for i, a in enumerate(values):
            for b in values[i + 1 :]:
                ya, yb = held[a].astype(bool), held[b].astype(bool)
                only_a, only_b = int((ya & ~yb).sum()), int((yb & ~ya).sum())
                out.append(
                    dict(zip(others, group, strict=True))
                    | {
                        "a": a, "b": b, "trials": len(held),
                        "held_a": int(ya.sum()), "held_b": int(yb.sum()),
                        "only_a": only_a, "only_b": only_b,
                        "p": mcnemar_exact(only_a, only_b),
                    }
                )  # fmt: skip
    return out


def replay_palm(replay: pd.DataFrame) -> dict[str, float | int]:
    """The demonstrations replayed through the controller (``plan`` commands): how far their
    palm ends from the demonstrator's mean (median and largest, mm), the share that held the
    object, and the replays."""
    demos = replay[replay["plan"] == "commands"]
    return {
        "palm_error_mm_median": float(demos["palm_error_mm"].median()),
        "palm_error_mm_max": float(demos["palm_error_mm"].max()),
        "held": float(demos["success"].astype(bool).mean()),
        "trials": len(demos),
    }


def robot_statistics(
    trials: pd.DataFrame, tolerance: pd.DataFrame, replay: pd.DataFrame
) -> dict[str, object]:
    """Every statistic of this module, for JSON (``data/embodied/statistics.json``):

    - ``tolerance``: ``robot_effects.tolerance_table`` of the tolerance trials (``table_record``);
    - ``held_by_palm_error``: ``robot_effects.held_by_palm_error`` of the tolerance trials
      (``tolerance``), the replayed demonstrations (``replay``) and each variant's distinct
      grasping trials (``runs``, by run);
    - ``replay``: ``replay_palm``;
    - ``schedule_pairs``: ``paired_grasping`` over the learning-rate schedule.
    """
    grasping = grasping_trials(trials)
    return {
        "tolerance": table_record(tolerance_table(tolerance)),
        "held_by_palm_error": {
            "tolerance": table_record(held_by_palm_error(tolerance)),
            "replay": table_record(held_by_palm_error(replay[replay["plan"] == "commands"])),
            "runs": {
                run: table_record(held_by_palm_error(grasping[grasping["run"] == run]))
                for run in sorted(grasping["run"].unique())
            },
        },
        "replay": replay_palm(replay),
        "schedule_pairs": _plain(
            paired_grasping(trials, "learning_rate_schedule", NetworkVariant.keys())
        ),
    }
