"""The distractor's declared tests (config ``distractor``; docs/distractor.md): per replication
one estimate of each effect, then a t over the replications, Holm within the declared family.

Per replication, cue timing, test mode, weight and measure: each network x target x distractor's
mean over its defined trials is an observation, fitted by least squares with an intercept per
network and the coded terms of target congruency, distractor compatibility and their product
(each +1/2 where incongruent, incompatible), so each main effect weighs the four cells equally
(the pairs are not balanced: a target has one distractor of its own grip class and two of the
other). ``congruency`` is incongruent - congruent, ``compatibility`` incompatible - compatible:
positive is the grip compatible with the object faster, people's direction for the target. A
network that lacks a cell (no correct trial there) keeps its other cells, as the confirmation's
correct-trial estimator does; a term the observations do not identify is NaN, and the
replication is left out of that test and counted.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import pandas as pd

from icub_affordance.analysis.decide import decide
from icub_affordance.analysis.replicated import over_replications
from icub_affordance.analysis.statistics import holm
from icub_affordance.outcome import Outcome

#: The two declared effects, in the tables' order.
EFFECTS: tuple[str, ...] = ("congruency", "compatibility")
#: What a test is made of, in the order of its table's columns.
TEST_KEYS: tuple[str, ...] = ("cue", "mode", "lam", "measure", "effect")


def effect_fit(trials: pd.DataFrame, depvar: str) -> dict[str, float]:
    """One replication's effects on ``depvar`` (module docstring); NaN for a term the
    observations do not identify."""
    data = trials.dropna(subset=[depvar])
    data = data.groupby(["network", "object", "distractor"], as_index=False).agg(
        y=(depvar, "mean"), congruent=("congruent", "first"), compatible=("compatible", "first")
    )
    if data.empty:
        return dict.fromkeys(EFFECTS, float("nan"))
    c = np.where(data["congruent"].astype(str) == "True", -0.5, 0.5)
    d = np.where(data["compatible"].astype(bool), -0.5, 0.5)
    networks = sorted(data["network"].unique())
    dummies = [(data["network"].to_numpy() == n).astype(float) for n in networks]
    X = np.column_stack([*dummies, c, d, c * d])
    y = data["y"].to_numpy(dtype=float)
    beta = np.linalg.lstsq(X, y, rcond=None)[0]
    rank = np.linalg.matrix_rank(X)
    out = {}
    for name, j in zip(EFFECTS, (len(networks), len(networks) + 1), strict=True):
        identified = np.linalg.matrix_rank(np.delete(X, j, axis=1)) < rank
        out[name] = float(beta[j]) if identified else float("nan")
    return out


def replication_estimates(trials: pd.DataFrame, measures) -> pd.DataFrame:
    """One row per replication, cue timing, mode, weight, measure and effect: its estimate.
    ``trials``: the distractor trials with ``replication`` and ``cue`` columns; the measure
    ``rmse_correct`` is the RMSE where the grip was right (``wrong_grip`` 0)."""
    data = trials.copy()
    data["rmse_correct"] = data["rmse"].where(data["wrong_grip"].astype(float) == 0)
    rows = []
    keys = ["replication", "cue", "mode", "lam"]
    for (rep, cue, mode, lam), group in data.groupby(keys, sort=True):
        for measure in measures:
            fit = effect_fit(group, measure)
            rows += [
                {"replication": rep, "cue": cue, "mode": mode, "lam": lam, "measure": measure,
                 "effect": effect, "estimate": fit[effect]}
                for effect in EFFECTS
            ]  # fmt: skip
    return pd.DataFrame(rows)


def family_of(lam: float, declaration: Mapping[str, Any]) -> str:
    """The family a weight's tests belong to: the declared one above zero, the inhibition's
    exploration below; none at zero (the paper's test, a reference)."""
    if lam > 0:
        return declaration["family"]
    return declaration["inhibition_family"] if lam < 0 else ""


def direction(estimate: float, p_holm: float, alpha: float) -> Outcome:
    """A test's outcome against people's direction for the target (positive: compatible
    faster); the distractor's expectation per selection is set beside it (``summary``)."""
    return decide(estimate, p_holm, alpha)


def summary(estimates: pd.DataFrame, declaration: Mapping[str, Any], least: int) -> pd.DataFrame:
    """Each test over the replications (``over_replications``: none below ``least``), Holm within
    each family, its sign's outcome (``direction``) and people's expected direction under each
    selection (config ``distractor.human``), per weight other than 0."""
    alpha = float(declaration["alpha"])
    rows = []
    for key, group in estimates.groupby(list(TEST_KEYS), sort=False):
        test = dict(zip(TEST_KEYS, key, strict=True))
        family = family_of(float(test["lam"]), declaration)
        if not family:
            continue
        values = group["estimate"].to_numpy(dtype=float)
        defined = values[np.isfinite(values)]
        term = over_replications(defined, least)
        rows.append(
            test
            | {"replications": len(values), "estimable": len(defined), "family": family}
            | {k: term[k] for k in ("estimate", "se", "ci_low", "ci_high", "t", "df", "p")}
            | {
                f"human_{sel}": declaration["human"][test["effect"]][sel]
                for sel in ("colour", "location")
            }  # fmt: skip
        )
    table = pd.DataFrame(rows)
    if table.empty:
        return table
    for _family, index in table.groupby("family").groups.items():
        p = table.loc[index, "p"].to_numpy(dtype=float)
        table.loc[index, "p_holm"] = holm(p)
        table.loc[index, "family_size"] = int(np.isfinite(p).sum())
    table["family_size"] = table["family_size"].astype(int)
    pairs = zip(table["estimate"], table["p_holm"], strict=True)
    table["direction"] = [int(direction(e, p, alpha)) for e, p in pairs]
    return table
