"""Explore, then confirm: the robot's share of grasping trials held, on the networks a variant was
chosen on and on fresh ones (config ``robot.confirmation``).

A robot variant is picked after the grid of variants was tried on one set of networks (the
exploration: the config's seed, network indices 0..network.networks-1), so its share there is
the data it was chosen on and is biased upwards by the choice. The confirmation trains the same
variant again on network indices the exploration never used (``training.network_seed(seed, i)``,
same demonstrations and maps) and tests it on the robot by the same rules; only its share is set
against a bar.

Unit. A grasping trial is one network grasping one object: a network's test sequences of one
object are the same movement on the robot (``on_robot.embodied_network``), so they count once.

Interval. The four objects of a network are not independent trials: a network that learned
well grasps most of them. The interval is Clopper-Pearson's exact binomial interval at an
effective number of trials that accounts for that clustering, the method of Korn and Graubard
(1998, Survey Methodology 24, 193-201; R's ``survey::svyciprop(method = "beta")``):

- the share's variance is estimated over networks (the networks are the sampled units):
  ``var = m / (m - 1) * sum_i (held_i - share * trials_i)**2 / trials**2`` for m networks;
- the design effect ``deff = var / (share * (1 - share) / trials)``, taken as at least 1, so the
  interval is never narrower than if every trial were independent (with 12 networks a smaller
  estimate is mostly noise; at a share of 0 or 1 the variance is 0 and deff is 1); the estimate
  before that floor is reported too (``design_effect_raw``; undefined, NaN, at a share of 0 or
  1), so a reader sees how far below 1 it was;
- the effective trials ``trials / deff``, times ``(t(trials - 1) / t(m - 1))**2`` (the 97.5%
  points of Student's t), which widens the interval for a variance estimated from m networks
  only;
- the exact interval at that number of trials, with ``share * effective`` held (the beta
  quantiles of Clopper-Pearson, which take a non-integer count).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from icub_affordance.vocabulary import OBJECT_NAMES

#: The seed sets of a confirmation, in the order of data/embodied/confirmation.csv.
SEED_SETS = ("exploration", "confirmation")
#: The columns of data/embodied/confirmation.csv after the variant's keys.
COLUMNS = (
    "seed_set",
    "run",
    "first_network",
    "last_network",
    "networks",
    "trials",
    "held",
    "share",
    "design_effect",
    "effective_trials",
    "ci_low",
    "ci_high",
)
#: The networks' mappings, whose objects differ in congruency (not in the grasping task's grip).
MAPPINGS = ("A", "B")
#: The columns after ``COLUMNS``: the design effect before its floor at 1, and per mapping and
#: object (``{mapping}_{object}``) its distinct grasping trials and how many held, so that the
#: misses per object show beside the share.
DETAIL_COLUMNS = (
    "design_effect_raw",
    *(f"{m}_{o}_{c}" for m in MAPPINGS for o in OBJECT_NAMES for c in ("trials", "held")),
)


def distinct_grasping_trials(trials: pd.DataFrame) -> pd.DataFrame:
    """One row per network and object of the grasping task: its test sequences are the same
    movement on the robot, so they must agree on ``success`` (refused if they do not)."""
    grasping = trials[trials["task"] == "grasping"].copy()
    grasping["success"] = grasping["success"].map(lambda v: str(v).lower() in ("true", "1", "1.0"))
    outcomes = grasping.groupby(["network", "object"])["success"].nunique()
    if (outcomes > 1).any():
        bad = outcomes[outcomes > 1].index[0]
        raise ValueError(
            f"network {bad[0]} grasps {bad[1]!r} with different outcomes in its test sequences; "
            "they are one movement on the robot and must agree"
        )
    return grasping.drop_duplicates(["network", "object"])


def clustered_interval(
    held: Sequence[int], trials: Sequence[int], level: float = 0.95
) -> dict[str, float]:
    """The share held over clusters (networks) with ``held[i]`` of ``trials[i]`` each, and its
    Korn-Graubard interval (module docstring): share, design_effect, effective_trials, ci_low,
    ci_high; and design_effect_raw, the estimate before its floor at 1 (NaN at a share of 0 or
    1)."""
    from scipy import stats

    held, trials = np.asarray(held, dtype=float), np.asarray(trials, dtype=float)
    m, n = len(held), float(trials.sum())
    if m < 2 or n < 2 or (trials <= 0).any() or (held < 0).any() or (held > trials).any():
        raise ValueError(f"a clustered interval needs 2 or more networks with trials: {m}, {n}")
    share = float(held.sum() / n)
    var = m / (m - 1) * float(np.sum((held - share * trials) ** 2)) / n**2
    binomial = share * (1 - share) / n
    raw = var / binomial if binomial > 0 else float("nan")
    deff = max(1.0, raw) if binomial > 0 else 1.0
    alpha = 1 - level
    widen = (stats.t.ppf(1 - alpha / 2, n - 1) / stats.t.ppf(1 - alpha / 2, m - 1)) ** 2
    effective = n / deff * widen
    x = share * effective
    low = 0.0 if share == 0 else float(stats.beta.ppf(alpha / 2, x, effective - x + 1))
    high = 1.0 if share == 1 else float(stats.beta.ppf(1 - alpha / 2, x + 1, effective - x))
    return {
        "share": share,
        "design_effect": float(deff),
        "effective_trials": float(effective),
        "ci_low": low,
        "ci_high": high,
        "design_effect_raw": float(raw),
    }


def object_counts(grasping: pd.DataFrame) -> dict[str, int]:
    """Per mapping and object (``DETAIL_COLUMNS``' ``{mapping}_{object}_trials`` and
    ``_held``), the distinct grasping trials and how many held: 0 and 0 where none."""
    out = {}
    for mapping in MAPPINGS:
        for obj in OBJECT_NAMES:
            mine = grasping[(grasping["mapping"] == mapping) & (grasping["object"] == obj)]
            out[f"{mapping}_{obj}_trials"] = int(len(mine))
            out[f"{mapping}_{obj}_held"] = int(mine["success"].sum())
    return out


def confirmation_table(
    trials: pd.DataFrame, confirmation: Sequence[Mapping[str, object]], level: float = 0.95
) -> pd.DataFrame:
    """One row per confirmed variant and seed set (``SEED_SETS``) tested: the variant's keys,
    then ``COLUMNS``, then ``DETAIL_COLUMNS``, from its grasping trials counted once per network
    and object.

    ``trials``: robot trials with columns run, network, mapping, task, object, success (e.g.
    data/embodied/trials.csv with the confirmation's joined); ``confirmation``: one mapping per
    variant, its keys (``variants.NetworkVariant.keys()``) and the runs ``exploration`` and
    ``confirmation``. An ``exploration`` of None (a build that does not test the variant on the
    networks it was chosen on: the default build) has no row; the confirmation always has one.
    """
    rows = []
    for variant in confirmation:
        keys = {k: v for k, v in variant.items() if k not in SEED_SETS}
        if variant["confirmation"] is None:
            raise ValueError(f"the confirmed variant {keys} names no confirmation run")
        for seed_set in SEED_SETS:
            run = variant[seed_set]
            if run is None:  # the exploration, not tested in this build
                continue
            mine = distinct_grasping_trials(trials[trials["run"] == run])
            if mine.empty:
                raise ValueError(f"no grasping trials of run {run!r} ({seed_set})")
            per_net = mine.groupby("network")["success"].agg(["sum", "count"])
            interval = clustered_interval(per_net["sum"], per_net["count"], level)
            rows.append(
                keys
                | {
                    "seed_set": seed_set,
                    "run": run,
                    "first_network": int(per_net.index.min()),
                    "last_network": int(per_net.index.max()),
                    "networks": len(per_net),
                    "trials": int(per_net["count"].sum()),
                    "held": int(per_net["sum"].sum()),
                }
                | interval
                | object_counts(mine)
            )
    if not rows:
        return pd.DataFrame(columns=[*COLUMNS, *DETAIL_COLUMNS])
    keys = [k for k in rows[0] if k not in COLUMNS and k not in DETAIL_COLUMNS]
    return pd.DataFrame(rows)[[*keys, *COLUMNS, *DETAIL_COLUMNS]]


def bar_verdict(ci_low: float, ci_high: float, bar: float) -> str:
    """Where a confirmation's interval lies against ``bar``: above, includes or below."""
    if ci_low > bar:
        return "above"
    if ci_high < bar:
        return "below"
    return "includes"
