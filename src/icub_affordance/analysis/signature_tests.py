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

from icub_affordance.analysis.replicated import assessable, over_replications
from icub_affordance.analysis.statistics import equivalence, holm
from icub_affordance.analysis.trial_effects import correct_trial_effects
from icub_affordance.analysis.verdicts import ALPHA
from icub_affordance.learning.materials import Materials
from icub_affordance.learning.network import Weights, run_closed_loop
from icub_affordance.learning.training import N_VISUAL, context, target_grip
from icub_affordance.outcome import Outcome
from icub_affordance.vocabulary import CATEGORISATION, OBJECTS

#: Where the object is in view at every step: a trial's 9 steps.
IN_VIEW = 9
#: The family of the signatures' verdict tests (one per chapter), and of the tests beside them.
FAMILY, LEVELS_FAMILY, ERRORS_FAMILY = "signatures", "signatures: levels", "signatures: errors"
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
    #: the fewest replications with an estimate a test needs (config
    #: ``confirmation.min_replications``: one minimum for every replicated test)
    min_replications: int

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
    the evaluation's trial of that sequence does (``in_silico.trial_row``).
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


# ---- per replication: the one estimator -----------------------------------------------------


def estimator_rows(trials: pd.DataFrame) -> pd.DataFrame:
    """``trials`` as the correct-trial estimator reads them
    (``trial_effects.correct_trial_effects``): congruency and size as cell names,
    ``rmse_correct`` the RMSE where the grip was right."""
    out = trials.copy()
    out["congruency"] = np.where(out["congruent"].astype(bool), "congruent", "incongruent")
    out["rmse_correct"] = out["rmse"].where(out["correct"].astype(bool))
    return out


def _congruency(rows: pd.DataFrame, left_out: bool = True) -> list[dict[str, float]]:
    """One replication's congruency effect on correct-trial RMSE by the one estimator: a row
    with every network (``dropped`` -1) and a row without each network in turn (``dropped``
    its index), for leave-one-network-out ranges of every statistic built on it; with the
    fewest networks carrying a cell."""
    term = correct_trial_effects(rows, left_out=left_out, lono=left_out)["congruency"]
    fewest = min(term["cells"].values()) if term["cells"] else 0
    full = {"dropped": -1, "effect": term["estimate"], "fewest_networks_per_cell": fewest}
    return [full] + [
        {"dropped": int(n), "effect": v, "fewest_networks_per_cell": fewest}
        for n, v in term.get("left_out", {}).items()
    ]


def replication_effects(trials: pd.DataFrame, left_out: bool = True) -> pd.DataFrame:
    """Per replication, condition and k: the congruency effect on correct-trial RMSE (incongruent
    minus congruent) by ``trial_effects.correct_trial_effects``, the estimator every chapter uses:
    each network x object's mean over its correct trials is an observation, the fit has an intercept
    per network and the cell terms, so networks keep their other cells when one has no correct
    trial and objects are not pooled (a pooled mean would compare different mixtures of
    objects: correct incongruent trials are mostly of some objects, and correct-trial RMSE
    differs by object). Rows with ``dropped`` >= 0 are the estimate without that network (none
    with ``left_out`` False: a figure of the estimates needs no refits)."""
    rows = estimator_rows(trials)
    out = []
    for (rep, kind, k), g in rows.groupby(["replication", "condition", "k"], sort=True):
        out += [{"replication": rep, "condition": kind, "k": k} | r
                for r in _congruency(g, left_out)]  # fmt: skip
    return pd.DataFrame(out)


def network_errors(trials: pd.DataFrame) -> pd.DataFrame:
    """Per replication, network and condition: the wrong-grip rates of congruent and
    incongruent trials (errors, reported apart from reaction time)."""
    keys = ["replication", "network", "condition", "k"]
    wrong = 1.0 - trials.groupby([*keys, "congruent"])["correct"].mean()
    table = wrong.unstack("congruent").rename(
        columns={True: "wrong_congruent", False: "wrong_incongruent"}
    )
    return table.reindex(columns=["wrong_congruent", "wrong_incongruent"]).reset_index()


def bin_rows(trials: pd.DataFrame, quantiles: int) -> pd.DataFrame:
    """In view: each network x object's correct trials sorted by RMSE and cut into
    ``quantiles`` bins of equal count (a delta plot within each cell, so that a bin compares
    like objects); a row per network, object and bin with the bin's mean RMSE as
    ``rmse_correct``. A network x object with fewer correct trials than bins has no bins."""
    view = estimator_rows(trials)
    view = view[(view["condition"] == "in_view") & view["correct"].astype(bool)]
    keys = ["replication", "network", "mapping", "object", "congruency", "size"]
    rows = []
    for key, g in view.groupby(keys, sort=True):
        values = np.sort(g["rmse"].to_numpy(dtype=float))
        if len(values) < quantiles:
            continue
        for q, part in enumerate(np.array_split(values, quantiles), start=1):
            rows.append(dict(zip(keys, key, strict=True)) | {"bin": q, "rmse_correct": part.mean()})
    return pd.DataFrame(rows, columns=[*keys, "bin", "rmse_correct"])


def bin_effects(trials: pd.DataFrame, quantiles: int, left_out: bool = True) -> pd.DataFrame:
    """Per replication and reaction-time bin (``bin_rows``): the congruency effect by the one
    estimator (rows with ``dropped`` >= 0: without that network, as ``replication_effects``)."""
    rows = bin_rows(trials, quantiles)
    out = [
        {"replication": rep, "bin": q} | r
        for (rep, q), g in rows.groupby(["replication", "bin"], sort=True)
        for r in _congruency(g, left_out)
    ]
    columns = ["replication", "bin", "dropped", "effect", "fewest_networks_per_cell"]
    return pd.DataFrame(out, columns=columns)


def slope(x: np.ndarray, y: np.ndarray) -> float:
    """The least-squares slope of y on x."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    return float(np.sum((x - x.mean()) * (y - y.mean())) / np.sum((x - x.mean()) ** 2))


# ---- over networks or replications ---------------------------------------------------------


def over_units(values: pd.DataFrame, column: str, least: int) -> dict[str, float]:
    """The mean of ``column`` over the replications (one value each: networks within a
    replication share its maps and demonstrations, so the replication is the unit) with its
    t-test (df = replications - 1), made only on at least ``least`` replications with an
    estimate (``replicated.over_replications``: the declared minimum; ``assessable`` says
    whether it was). NaN values (a replication whose estimate is undefined) are
    left out and counted in ``not_estimable``. With a ``dropped`` column (``replication_effects``)
    the test reads the rows with every network (``dropped`` -1); the others give the
    leave-one-network-out range of the mean (``lono_low``, ``lono_high``): the mean with one
    replication's value replaced by its value without one of its networks, over every network."""
    full = values[values["dropped"] == -1] if "dropped" in values else values
    # one value per replication (per-network values, as the error rates, by their mean)
    defined = full.dropna(subset=[column]).groupby("replication")[column].mean()
    n = len(defined)
    test = over_replications(defined.to_numpy(), least)
    reps = int(full["replication"].nunique())
    test |= {"units": n, "replications": reps, "not_estimable": reps - n,
             "assessable": assessable(n, least)}  # fmt: skip
    if "dropped" in values and n:
        others = values[(values["dropped"] != -1) & values["replication"].isin(defined.index)]
        shifted = (
            defined.mean()
            + (others[column].to_numpy(dtype=float) - defined.loc[others["replication"]].to_numpy())
            / n
        )
        shifted = shifted[np.isfinite(shifted)]
        if len(shifted):
            test |= {"lono_low": float(shifted.min()), "lono_high": float(shifted.max())}
    if "fewest_networks_per_cell" in values and len(full):
        test["fewest_networks_per_cell"] = float(full["fewest_networks_per_cell"].min())
    return test


def verdict(test: str, expected: str, row: Mapping[str, float], alpha: float = ALPHA) -> Outcome:
    """The ``Outcome`` of a signature's test. A slope: ``PAPER`` (the signature shown) if
    significant (Holm) in the expected direction, ``AGAINST`` if significant against it.
    Equivalence: ``PAPER`` if TOST is significant (Holm), ``AGAINST`` if the difference itself is
    (``p_difference_adjusted``), else ``NONE``. No test, or no data for one: ``NOT_TESTED``. A
    signature describes the shape of the congruency effect, so while the in-view effect is not
    established (``in_view_established`` False) it is ``NOT_ASSESSABLE``; so is a test on fewer
    replications with an estimate than the declared minimum (``assessable`` False:
    ``replicated``)."""
    if test == "none" or not np.isfinite(row.get("estimate", np.nan)):
        return Outcome.NOT_TESTED
    if not row.get("assessable", True) or not row.get("in_view_established", True):
        return Outcome.NOT_ASSESSABLE
    p = row.get("p_adjusted", np.nan)
    if test == "slope":
        if not (np.isfinite(p) and p < alpha):
            return Outcome.NONE
        want = 1.0 if expected == "positive" else -1.0
        return Outcome.PAPER if np.sign(row["estimate"]) == want else Outcome.AGAINST
    if test == "equivalence":
        if np.isfinite(p) and p < alpha:
            return Outcome.PAPER
        p_diff = row.get("p_difference_adjusted", np.nan)
        return Outcome.AGAINST if np.isfinite(p_diff) and p_diff < alpha else Outcome.NONE
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
    "not_estimable",
    "lono_low",
    "lono_high",
    "fewest_networks_per_cell",
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
        "not_estimable": test.get("not_estimable", 0),
        **{key: test.get(key, np.nan) for key in ("lono_low", "lono_high")},
        "fewest_networks_per_cell": test.get("fewest_networks_per_cell", np.nan),
        "assessable": test.get("assessable", True),
        "reason": "",
    }


def _slopes(curves: pd.DataFrame, x: str, points: int) -> pd.DataFrame:
    """Per replication (and ``dropped`` network, as ``replication_effects``), the slope of its
    effect over ``x``; NaN where one of the ``points`` is missing."""
    keys = ["replication", "dropped"]
    rows = []
    for (rep, dropped), g in curves.groupby(keys, sort=True):
        g = g.dropna(subset=["effect"])
        rows.append({
            "replication": rep, "dropped": dropped,
            "slope": slope(g[x], g["effect"]) if len(g) == points else np.nan,
            "fewest_networks_per_cell": g["fewest_networks_per_cell"].min() if len(g) else 0,
        })  # fmt: skip
    return pd.DataFrame(rows, columns=[*keys, "slope", "fewest_networks_per_cell"])


def _rt_rows(trials: pd.DataFrame, effects: pd.DataFrame, config: SignatureConfig) -> list[dict]:
    """The effect growing with reaction time: the in-view effect (the effect whose shape the
    bins show), the effect per RT bin, and its slope over bins."""
    bins = bin_effects(trials, config.quantiles)
    view = effects[effects["condition"] == "in_view"]
    rows = [_row("grows_with_rt", "in view, all correct trials", "all",
                 over_units(view, "effect", config.min_replications), LEVELS_FAMILY)]  # fmt: skip
    for q in range(1, config.quantiles + 1):
        one = bins[bins["bin"] == q]
        tested = over_units(one, "effect", config.min_replications)
        rows.append(_row("grows_with_rt", "in view, RT bin", f"q{q}", tested, LEVELS_FAMILY))
    slopes = over_units(_slopes(bins, "bin", config.quantiles), "slope", config.min_replications)
    return rows + [_row("grows_with_rt", "in view, effect over RT bins", "slope",
                        slopes, FAMILY)]  # fmt: skip


def _hidden_rows(
    effects: pd.DataFrame, entry: Mapping[str, Any], config: SignatureConfig
) -> list[dict]:
    """The object hidden after k steps (blanked or masked): at each k the contrast blanked (or
    masked) minus in view, per replication; then the signature's test, the slope over k (in view
    as k = 9) or the equivalence at the briefest k."""
    name, test = entry["signature"], entry["test"]
    what = "blanked" if name == "extinction" else "masked"
    keys = ["replication", "dropped"]
    view = effects[effects["condition"] == "in_view"]
    hidden = effects[effects["condition"] == name]
    rows = []
    for k, g in hidden.groupby("k"):
        paired = g.merge(view, on=keys, suffixes=("", "_view"))
        diff = paired[keys].assign(
            d=paired["effect"] - paired["effect_view"],
            fewest_networks_per_cell=np.minimum(
                paired["fewest_networks_per_cell"], paired["fewest_networks_per_cell_view"]
            ),
        )
        tested = over_units(diff, "d", config.min_replications)
        rows.append(_row(name, f"{what} after k steps minus in view", f"k={k}", tested,
                         LEVELS_FAMILY))  # fmt: skip
        if test == "equivalence" and k == min(entry["levels"]):
            row = _row(name, f"{what} after k steps minus in view: equivalence", f"k={k}",
                       tested, FAMILY)  # fmt: skip
            rows.append(row | {"p": equivalence(tested, config.margin)["p"]})
    if test == "slope":
        curves = pd.concat([hidden, view])
        slopes = over_units(
            _slopes(curves, "k", len(entry["levels"]) + 1), "slope", config.min_replications
        )
        rows.append(_row(name, f"effect over k, {what} after k steps (k = 9: in view)", "slope",
                         slopes, FAMILY))  # fmt: skip
    return rows


def in_view_established(table: pd.DataFrame, alpha: float = ALPHA) -> bool:
    """Is the in-view congruency effect (the row ``level == "all"``) shown, incongruent
    slower, at Holm's p within its family below ``alpha``? The signatures describe its shape."""
    row = table[(table["signature"] == "grows_with_rt") & (table["level"] == "all")]
    if row.empty:
        return False
    p, estimate = float(row["p_adjusted"].iloc[0]), float(row["estimate"].iloc[0])
    return bool(np.isfinite(p) and p < alpha and estimate > 0)


def _with_verdicts(table: pd.DataFrame, config: SignatureConfig) -> pd.DataFrame:
    """Holm's p within each family, and each verdict test's ``Outcome`` ("" in the other rows)."""
    table = table.copy()
    table["p_adjusted"] = np.nan
    for _family, idx in table.groupby("family").groups.items():
        table.loc[idx, "p_adjusted"] = holm(table.loc[idx, "p"])
    established = in_view_established(table)
    table["verdict"] = pd.Series("", index=table.index, dtype=object)  # "" or an Outcome
    for i, row in table[table["family"] == FAMILY].iterrows():
        entry = config.entry(row["signature"])
        extra = {"in_view_established": established}
        if entry["test"] == "equivalence":  # its difference test, the same level, beside it
            twin = table[
                (table["signature"] == row["signature"])
                & (table["family"] == LEVELS_FAMILY)
                & (table["level"] == row["level"])
            ]
            extra["p_difference_adjusted"] = float(twin["p_adjusted"].iloc[0])
        code = verdict(entry["test"], entry["expected"], row.to_dict() | extra)
        table.loc[i, "verdict"] = code
        if code == Outcome.NOT_TESTED and not row["reason"]:
            table.loc[i, "reason"] = "too few replications with an estimate"
        if code == Outcome.NOT_ASSESSABLE:
            table.loc[i, "reason"] = (
                "the in-view congruency effect it describes is not established"
                if row.get("assessable", True)
                else f"fewer than {config.min_replications} replications with an estimate"
            )
    return table


def summary(trials: pd.DataFrame, config: SignatureConfig) -> pd.DataFrame:
    """One row per signature and condition level (``SUMMARY_COLUMNS``): each signature's verdict
    test in the family ``signatures``, the tests of its levels beside it (exploration); every
    estimate over the replications' estimates by the one correct-trial estimator."""
    effects = replication_effects(trials)
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
    table["of"] = np.where(table["units"] > 0, trials["replication"].nunique(), 0)
    return table[SUMMARY_COLUMNS]


def errors(trials: pd.DataFrame, least: int) -> pd.DataFrame:
    """Errors apart: per condition, the wrong-grip rates of congruent and incongruent trials and
    the test of their difference (incongruent minus congruent) over the replications' means (on
    at least ``least`` of them, ``over_units``), Holm over the table."""
    rates = network_errors(trials)
    rates["wrong_difference"] = rates["wrong_incongruent"] - rates["wrong_congruent"]
    rows = []
    for (kind, k), g in rates.groupby(["condition", "k"], sort=False):
        test = over_units(g, "wrong_difference", least)
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
