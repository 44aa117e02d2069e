"""The compatibility effect's human signatures, tested on the model (the book's chapter "The model
against what people do").

The human studies behind the paper report more than "congruent is faster": the effect grows with
reaction time while the object is in view, fades after the object disappears, and survives a
brief masked glimpse (Tucker & Ellis 2001, 2004). Each signature is a config entry (config
``signatures``) with the model condition that stands for it, declared before its result. A
condition acts at test time only, on the visual input of closed-loop categorisation trials, so
every network is tested in every condition and conditions are compared within networks.

A closed loop is deterministic per network and object; the trial-to-trial variability that
reaction-time distributions need comes from sensor noise: each pixel of the binary visual map
flips with a small chance at every step, whatever the map shows. Reaction time is the
correct-trial RMSE; errors (the wrong-grip rate) are reported apart.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd

from .findings import ALPHA
from .jordan import Weights, run_closed_loop
from .spec import CATEGORISATION, OBJECTS
from .stats import equivalence, holm, t_term
from .train import N_VISUAL, Materials, context, target_grip

#: Where the object is in view at every step: a trial's 9 steps.
IN_VIEW = 9
#: The family of the signatures' verdict tests (one per chapter), and of the tests beside them.
FAMILY, LEVELS_FAMILY, ERRORS_FAMILY = "signatures", "signatures: levels", "signatures: errors"
VERDICTS = ("shown", "not shown", "opposite", "not testable here")
#: Each signature this module has a condition for (config ``signatures.list``): the test its
#: verdict comes from, the directions that test can expect, and whether it has levels (the
#: steps the object is seen). The config's schema and checks read it from here.
TESTS: dict[str, tuple[str, tuple[str, ...], bool]] = {
    "grows_with_rt": ("slope", ("positive", "negative"), False),
    "extinction": ("slope", ("positive", "negative"), True),
    "brief_exposure": ("equivalence", ("same",), True),
    "advance_cueing": ("none", ("absent",), False),
}


@dataclass(frozen=True)
class SignatureConfig:
    """Config ``signatures``: how many noisy trials, how much noise, and the declared list."""

    trials: int
    visual_noise: float
    quantiles: int
    margin: float
    list: Sequence[Mapping[str, Any]]

    def entry(self, signature: str) -> Mapping[str, Any] | None:
        return next((e for e in self.list if e["signature"] == signature), None)

    def conditions(self) -> list[tuple[str, int]]:
        """Every (condition, k) the trials are run in: in view, and each declared level of the
        conditions that hide the object after k steps."""
        out = [("in_view", IN_VIEW)]
        for kind in ("extinction", "brief_exposure"):
            entry = self.entry(kind)
            out += [(kind, int(k)) for k in (entry or {}).get("levels", [])]
        return out


def visual_inputs(
    visual: np.ndarray, kind: str, k: int, trials: int, noise: float, rng: np.random.Generator
) -> np.ndarray:
    """A condition's visual input for ``trials`` trials: (trials, 9, 100).

    ``extinction``: the map for the first k steps, then blank (an empty retina, every pixel 0);
    ``brief_exposure``: the map for the first k steps, then the object's own pixels scrambled, a
    fresh permutation per trial and step (a mask with the object's amount of edge). Then each
    pixel flips with chance ``noise``.
    """
    visual = np.asarray(visual, dtype=float)
    if not np.isin(visual, (0.0, 1.0)).all():
        raise ValueError("the visual map must be binary (0/1) for its pixels to flip")
    out = np.broadcast_to(visual, (trials, IN_VIEW, visual.size)).copy()
    if kind == "extinction":
        out[:, k:] = 0.0
    elif kind == "brief_exposure":
        for i in range(trials):
            for t in range(k, IN_VIEW):
                out[i, t] = visual[rng.permutation(visual.size)]
    elif kind != "in_view":
        raise ValueError(f"unknown condition {kind!r}")
    flips = rng.random(out.shape) < noise
    return np.where(flips, 1.0 - out, out)


def network_trials(
    m: Materials,
    weights: Weights,
    network: int,
    mapping: str,
    cue: str,
    target: str,
    config: SignatureConfig,
    seed: int,
) -> list[dict[str, object]]:
    """Every noisy categorisation trial of one network in every condition, one row each.

    Trial i uses sequence i mod 5 for its start, its target and the grips it is judged by, as
    the evaluation's trial of that sequence does (``evaluate.trial_row``).
    """
    n_seq = m.demos.shape[2]
    learned = m.targets(target)
    rows = []
    for c, (kind, k) in enumerate(config.conditions()):
        for o, obj in enumerate(m.objects):
            rng = np.random.default_rng([seed, network, c, o])
            ctx = np.repeat(context(m, o, CATEGORISATION, cue)[None], config.trials, axis=0)
            ctx[:, :, :N_VISUAL] = visual_inputs(
                m.visual[o], kind, k, config.trials, config.visual_noise, rng
            )
            grip = target_grip(obj, CATEGORISATION, mapping)
            g = m.grips.index(grip)
            seqs = np.arange(config.trials) % n_seq
            out, _ = run_closed_loop(weights, ctx, m.demos[o, g, seqs, 0])
            err = out - learned[o, g, seqs, 1:]
            rmse = np.sqrt((err**2).mean(axis=(1, 2)))
            finals = m.demos[o][:, seqs, -1]  # (grips, trials, 16)
            nearest = np.argmin(np.linalg.norm(finals - out[None, :, -1], axis=2), axis=0)
            for i in range(config.trials):
                rows.append(
                    {
                        "network": network,
                        "mapping": mapping,
                        "condition": kind,
                        "k": k,
                        "object": obj,
                        "size": OBJECTS[obj].size,
                        "congruent": grip == OBJECTS[obj].natural_grip,
                        "trial": i,
                        "sequence": int(seqs[i]),
                        "rmse": float(rmse[i]),
                        "correct": bool(nearest[i] == g),
                    }
                )
    return rows


# ---- per network ---------------------------------------------------------------------------


def network_effects(trials: pd.DataFrame) -> pd.DataFrame:
    """Per replication, network and condition: the congruency effect on correct-trial RMSE
    (incongruent minus congruent; NaN where a network has no correct trial of one kind) and the
    wrong-grip rates."""

    def one(g: pd.DataFrame) -> pd.Series:
        ok = g[g["correct"]]
        inc, con = ok[~ok["congruent"]]["rmse"], ok[ok["congruent"]]["rmse"]
        wrong = 1.0 - g.groupby("congruent")["correct"].mean()
        return pd.Series(
            {
                "effect": inc.mean() - con.mean() if len(inc) and len(con) else np.nan,
                "wrong_congruent": wrong.get(True, np.nan),
                "wrong_incongruent": wrong.get(False, np.nan),
            }
        )

    keys = ["replication", "network", "condition", "k"]
    return (
        trials.groupby(keys, sort=True)[["correct", "congruent", "rmse"]].apply(one).reset_index()
    )


def delta_bins(trials: pd.DataFrame, quantiles: int) -> pd.DataFrame:
    """Per replication and network, in view: the congruency effect in each reaction-time bin
    (each congruency's correct trials sorted by RMSE and cut into ``quantiles`` bins of equal
    count, as in a delta plot); a network with fewer correct trials of a kind than bins has none."""
    rows = []
    in_view = trials[(trials["condition"] == "in_view") & trials["correct"]]
    for (rep, net), g in in_view.groupby(["replication", "network"], sort=True):
        inc = np.sort(g[~g["congruent"]]["rmse"].to_numpy())
        con = np.sort(g[g["congruent"]]["rmse"].to_numpy())
        if min(len(inc), len(con)) < quantiles:
            continue
        bins = zip(np.array_split(inc, quantiles), np.array_split(con, quantiles), strict=True)
        for q, (a, b) in enumerate(bins, start=1):
            rows.append(
                {"replication": rep, "network": net, "bin": q, "effect": a.mean() - b.mean()}
            )
    return pd.DataFrame(rows, columns=["replication", "network", "bin", "effect"])


def slope(x: np.ndarray, y: np.ndarray) -> float:
    """The least-squares slope of y on x."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    return float(np.sum((x - x.mean()) * (y - y.mean())) / np.sum((x - x.mean()) ** 2))


# ---- over networks or replications ---------------------------------------------------------


def over_units(values: pd.DataFrame, column: str) -> dict[str, float]:
    """The mean of ``column`` with its t-test: over networks with one replication, over the
    replications' means with several (networks within a replication share its maps and
    demonstrations). NaN values (a network without the trials a value needs) are left out."""
    values = values.dropna(subset=[column])
    reps = values["replication"].nunique()
    units = values.groupby("replication")[column].mean() if reps > 1 else values[column]
    units = units.to_numpy(dtype=float)
    n = len(units)
    if n < 2:
        test = t_term(units.mean() if n else np.nan, np.nan, 0.0)
    else:
        test = t_term(units.mean(), units.std(ddof=1) / np.sqrt(n), n - 1)
    return test | {"units": n, "replications": reps}


def verdict(test: str, expected: str, row: Mapping[str, float], alpha: float = ALPHA) -> str:
    """The verdict word of a signature's test (``VERDICTS``). A slope: shown if significant
    (Holm) in the expected direction, opposite if significant against it. Equivalence: shown if
    TOST is significant (Holm), opposite if the difference itself is (``p_difference_adjusted``),
    else not shown. No test, or no data for one: not testable here."""
    if test == "none" or not np.isfinite(row.get("estimate", np.nan)):
        return "not testable here"
    p = row.get("p_adjusted", np.nan)
    if test == "slope":
        if not (np.isfinite(p) and p < alpha):
            return "not shown"
        want = 1.0 if expected == "positive" else -1.0
        return "shown" if np.sign(row["estimate"]) == want else "opposite"
    if test == "equivalence":
        if np.isfinite(p) and p < alpha:
            return "shown"
        p_diff = row.get("p_difference_adjusted", np.nan)
        return "opposite" if np.isfinite(p_diff) and p_diff < alpha else "not shown"
    raise ValueError(f"unknown signature test {test!r}")


# ---- the tables ------------------------------------------------------------------------------

SUMMARY_COLUMNS = [
    "signature",
    "condition",
    "level",
    "estimate",
    "ci_low",
    "ci_high",
    "df",
    "p",
    "family",
    "p_adjusted",
    "verdict",
    "replications",
    "units",
    "of",
    "reason",
]


def _row(signature: str, condition: str, level: str, test: dict, family: str) -> dict:
    return {
        "signature": signature,
        "condition": condition,
        "level": level,
        **{key: test.get(key, np.nan) for key in ("estimate", "ci_low", "ci_high", "df", "p")},
        "family": family,
        "replications": test.get("replications", 0),
        "units": test.get("units", 0),
        "reason": "",
    }


def _slopes(curves: pd.DataFrame, x: str, points: int) -> pd.DataFrame:
    """Per replication and network, the slope of the effect over ``x``; NaN for a network that
    lacks one of the ``points``."""

    def one(g: pd.DataFrame) -> float:
        return slope(g[x], g["effect"]) if len(g) == points else np.nan

    groups = curves.dropna(subset=["effect"]).groupby(["replication", "network"])
    return groups[[x, "effect"]].apply(one).rename("slope").reset_index()


def _rt_rows(trials: pd.DataFrame, effects: pd.DataFrame, config: SignatureConfig) -> list[dict]:
    """The effect growing with reaction time: the in-view effect over all correct trials (the
    effect whose shape the bins show), the effect per RT bin, and its slope over bins."""
    bins = delta_bins(trials, config.quantiles)
    view = effects[effects["condition"] == "in_view"]
    rows = [_row("grows_with_rt", "in view, all correct trials", "all",
                 over_units(view, "effect"), LEVELS_FAMILY)]  # fmt: skip
    rows += [
        _row("grows_with_rt", "in view, RT bin", f"q{q}",
             over_units(bins[bins["bin"] == q], "effect"), LEVELS_FAMILY)
        for q in range(1, config.quantiles + 1)
    ]  # fmt: skip
    slopes = over_units(_slopes(bins, "bin", config.quantiles), "slope")
    return rows + [_row("grows_with_rt", "in view, effect over RT bins", "slope", slopes, FAMILY)]


def _hidden_rows(
    effects: pd.DataFrame, entry: Mapping[str, Any], config: SignatureConfig
) -> list[dict]:
    """The object hidden after k steps (blanked or masked): the effect at each k minus in view;
    then the signature's test, the slope over k (in view as k = 9) or the equivalence at the
    briefest k."""
    name, test = entry["signature"], entry["test"]
    what = "blanked" if name == "extinction" else "masked"
    index = ["replication", "network"]
    view = effects[effects["condition"] == "in_view"].set_index(index)
    hidden = effects[effects["condition"] == name].set_index(index)
    rows = []
    for k, g in hidden.groupby("k"):
        diff = over_units((g["effect"] - view["effect"]).rename("d").reset_index(), "d")
        rows.append(_row(name, f"{what} after k steps, minus in view", f"k={k}", diff,
                         LEVELS_FAMILY))  # fmt: skip
        if test == "equivalence" and k == min(entry["levels"]):
            row = _row(name, f"{what} after k steps, minus in view: equivalence", f"k={k}",
                       diff, FAMILY)  # fmt: skip
            rows.append(row | {"p": equivalence(diff, config.margin)["p"]})
    if test == "slope":
        curves = pd.concat([hidden.reset_index(), view.reset_index()])
        slopes = over_units(_slopes(curves, "k", len(entry["levels"]) + 1), "slope")
        rows.append(_row(name, f"effect over k, {what} after k steps (k = 9: in view)", "slope",
                         slopes, FAMILY))  # fmt: skip
    return rows


def _with_verdicts(table: pd.DataFrame, config: SignatureConfig) -> pd.DataFrame:
    """Holm's p within each family, and each verdict test's word."""
    table = table.copy()
    table["p_adjusted"] = np.nan
    for _family, idx in table.groupby("family").groups.items():
        table.loc[idx, "p_adjusted"] = holm(table.loc[idx, "p"])
    table["verdict"] = ""
    for i, row in table[table["family"] == FAMILY].iterrows():
        entry = config.entry(row["signature"])
        extra = {}
        if entry["test"] == "equivalence":  # its difference test, the same level, beside it
            twin = table[
                (table["signature"] == row["signature"])
                & (table["family"] == LEVELS_FAMILY)
                & (table["level"] == row["level"])
            ]
            extra["p_difference_adjusted"] = float(twin["p_adjusted"].iloc[0])
        word = verdict(entry["test"], entry["expected"], row.to_dict() | extra)
        table.loc[i, "verdict"] = word
        if word == "not testable here" and not row["reason"]:
            table.loc[i, "reason"] = "too few networks with correct trials of both kinds"
    return table


def summary(trials: pd.DataFrame, config: SignatureConfig) -> pd.DataFrame:
    """One row per signature and condition level (``SUMMARY_COLUMNS``): each signature's verdict
    test in the family ``signatures``, the tests of its levels beside it (exploration)."""
    effects = network_effects(trials)
    rows: list[dict] = []
    for entry in config.list:
        name = entry["signature"]
        if name == "grows_with_rt":
            rows += _rt_rows(trials, effects, config)
        elif name in ("extinction", "brief_exposure"):
            rows += _hidden_rows(effects, entry, config)
        else:  # advance_cueing: no condition the model can express
            row = _row(name, "required response before the object", "", {}, FAMILY)
            rows.append(row | {"reason": "no input names a grip apart from an object"})
    table = _with_verdicts(pd.DataFrame(rows), config)
    # what a test's units are out of: the replications with several, else the networks
    reps = trials["replication"].nunique()
    table["of"] = np.where(table["units"] > 0, reps if reps > 1 else trials["network"].nunique(), 0)
    return table[SUMMARY_COLUMNS]


def errors(trials: pd.DataFrame) -> pd.DataFrame:
    """Errors apart: per condition, the wrong-grip rates of congruent and incongruent trials and
    the test of their difference (incongruent minus congruent), Holm over the table."""
    effects = network_effects(trials)
    effects["wrong_difference"] = effects["wrong_incongruent"] - effects["wrong_congruent"]
    rows = []
    for (kind, k), g in effects.groupby(["condition", "k"], sort=False):
        test = over_units(g, "wrong_difference")
        rows.append(
            {
                "condition": kind,
                "k": k,
                "wrong_congruent": g["wrong_congruent"].mean(),
                "wrong_incongruent": g["wrong_incongruent"].mean(),
                **{key: test[key] for key in ("estimate", "ci_low", "ci_high", "df", "p")},
                "family": ERRORS_FAMILY,
                "replications": test["replications"],
            }
        )
    table = pd.DataFrame(rows)
    table["p_adjusted"] = holm(table["p"])
    return table
