"""The paper's statistics (section 3): ANOVAs of trial RMSE by congruency and object size.

Three analyses of the categorisation trials: the paper's two-way ANOVA over all trials (every
trial an observation: the paper's analysis, shown, not used for inference), a repeated-measures
ANOVA with the network as the subject, and the analysis used for inference: per-network contrasts
of congruency x size, with the mapping between networks (``network_contrasts``; book/notes.md,
"Testing and statistics"). The network is the unit: in closed loop a network's trials of one object
and task are identical, whatever the sequence, so each network x object is counted once, and every
test is a t-test over networks with the design's degrees of freedom. The ANOVAs report F, degrees of
freedom, p and partial eta squared; the contrasts an estimate, its standard error, df, 95%
t-interval and p per term.

One job: the analysis of the trial tables (their columns: task, mode, congruent, network, mapping,
object, size, rmse...). The tests it uses are the toolkit's (``statistics``), which knows no
column; the sweep's tables over many runs are ``sweep``'s.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from icub_affordance.analysis.statistics import effect_row, group_regression, holm, t_term
from icub_affordance.vocabulary import MODES

EFFECTS = {"congruency": "congruency", "size": "size", "interaction": "congruency:size"}


def trial_conditions(trials: pd.DataFrame) -> np.ndarray:
    """Each trial's condition, grasping, congruent or incongruent, from its ``task`` and
    ``congruent`` columns (as the trial tables are written)."""
    congruent = trials["congruent"].astype(str)
    return np.where(
        trials["task"] == "grasping",
        "grasping",
        np.where(congruent == "True", "congruent", "incongruent"),
    )


def categorisation_trials(trials: pd.DataFrame, mode: str) -> pd.DataFrame:
    df = trials[(trials["task"] == "categorisation") & (trials["mode"] == mode)].copy()
    df["congruency"] = trial_conditions(df)
    return df


def two_way_anova(df: pd.DataFrame) -> dict[str, dict[str, float]]:
    import statsmodels.formula.api as smf  # here, not above: plot jobs import this module
    from statsmodels.stats.anova import anova_lm

    model = smf.ols("rmse ~ C(congruency) * C(size)", data=df).fit()
    table = anova_lm(model, typ=2)
    names = {
        "congruency": "C(congruency)",
        "size": "C(size)",
        "interaction": "C(congruency):C(size)",
    }
    df2 = float(table.loc["Residual", "df"])
    return {
        effect: effect_row(table.loc[row, "F"], table.loc[row, "df"], df2, table.loc[row, "PR(>F)"])
        for effect, row in names.items()
    }


def repeated_measures_anova(df: pd.DataFrame, depvar: str = "rmse") -> dict[str, dict[str, float]]:
    from statsmodels.stats.anova import AnovaRM

    fit = AnovaRM(
        df, depvar=depvar, subject="network", within=["congruency", "size"], aggregate_func="mean"
    ).fit()
    table = fit.anova_table
    return {
        effect: effect_row(*(table.loc[row, c] for c in ("F Value", "Num DF", "Den DF", "Pr > F")))
        for effect, row in EFFECTS.items()
    }


def cell_means(df: pd.DataFrame, depvar: str = "rmse") -> dict[str, float]:
    """Mean per congruency x size cell (over networks' means), and the marginal means."""
    per_net = df.groupby(["network", "congruency", "size"])[depvar].mean().reset_index()
    out = {
        f"{c}_{s}": float(v)
        for (c, s), v in per_net.groupby(["congruency", "size"])[depvar].mean().items()
    }
    out |= {c: float(v) for c, v in per_net.groupby("congruency")[depvar].mean().items()}
    out |= {s: float(v) for s, v in per_net.groupby("size")[depvar].mean().items()}
    return out


#: The factors of the analysis used for inference, each coded -0.5 / +0.5, the second level
#: +0.5: so a main effect's estimate is the difference second - first averaged over the other
#: factors (for congruency and size, positive is the paper's direction), and an interaction's the
#: difference of differences.
CODING = {
    "congruency": ("congruent", "incongruent"),
    "size": ("large", "small"),
    "mapping": ("A", "B"),
}
TERMS = (
    "congruency",
    "size",
    "mapping",
    "congruency:size",
    "congruency:mapping",
    "size:mapping",
    "congruency:size:mapping",
)
#: The effects the paper tested (its two-way ANOVA's main effects): the family of hypotheses
#: whose verdicts the book states, Holm-adjusted together; the other terms model the design.
PAPER_EFFECTS = ("congruency", "size")
#: The within-network contrasts, each a difference of a network's four congruency x size cells.
WITHIN = ("congruency", "size", "congruency:size")


def network_object_means(df: pd.DataFrame, depvar: str = "rmse") -> pd.DataFrame:
    """Each network's mean ``depvar`` per object (over its sequences), with the object's
    congruency, size and the network's mapping: each network x object counted once (in closed
    loop a network's sequences of one object and task are one and the same trial)."""
    keys = ["network", "mapping", "object", "congruency", "size"]
    return df.groupby(keys, as_index=False)[depvar].mean()


def coded(means: pd.DataFrame) -> pd.DataFrame:
    """The factors of ``CODING`` as -0.5 / +0.5 columns."""
    out = means.copy()
    for factor, (first, second) in CODING.items():
        values = out[factor].astype(str)
        if not set(values) <= {first, second}:
            raise ValueError(f"{factor}: levels {sorted(set(values))}, expected {first}, {second}")
        out[factor] = np.where(values == second, 0.5, -0.5)
    return out


def network_cells(data: pd.DataFrame, depvar: str) -> pd.DataFrame:
    """Each network's mean of ``depvar`` per coded congruency x size cell (a row per network, a
    column per cell), from a coded table of per-object means (``coded``): ``pivot_table``'s
    result. Where each network has one object per cell (the design), without its grouping's
    cost: the mean of one value is that value, and the undefined values, all-undefined cells
    and the order are handled as ``pivot_table`` handles them."""
    keys = ["network", "congruency", "size"]
    if data.duplicated(keys).any():
        return data.pivot_table(index="network", columns=keys[1:], values=depvar, aggfunc="mean")
    cells = data.dropna(subset=[depvar]).set_index(keys)[depvar].unstack(keys[1:])
    return cells.dropna(axis=1, how="all").sort_index(axis=1)


def per_network_contrasts(
    df: pd.DataFrame, depvar: str = "rmse", means: pd.DataFrame | None = None
) -> pd.DataFrame:
    """One row per network (index ``network``): its mapping (-0.5 A, +0.5 B), its mean over the
    four congruency x size cells, and each within-network contrast (``WITHIN``: incongruent -
    congruent, small - large, and the difference of the congruency differences small - large).
    A network missing a cell (say, a robot measure undefined where nothing touched) is left out.
    ``means``: ``network_object_means(df, depvar)``, when the caller has it already."""
    data = coded(network_object_means(df, depvar) if means is None else means)
    cells = network_cells(data, depvar)
    full = [(c, s) for c in (-0.5, 0.5) for s in (-0.5, 0.5)]
    cells = cells.reindex(columns=pd.MultiIndex.from_tuples(full)).dropna()
    ci, cc = 0.5, -0.5  # incongruent, congruent
    sm, lg = 0.5, -0.5  # small, large
    out = pd.DataFrame(index=cells.index)
    out["mapping"] = data.groupby("network")["mapping"].first().reindex(cells.index)
    out["mean"] = cells.mean(axis=1)
    out["congruency"] = (cells[(ci, sm)] + cells[(ci, lg)] - cells[(cc, sm)] - cells[(cc, lg)]) / 2
    out["size"] = (cells[(ci, sm)] + cells[(cc, sm)] - cells[(ci, lg)] - cells[(cc, lg)]) / 2
    out["congruency:size"] = (cells[(ci, sm)] - cells[(cc, sm)]) - (
        cells[(ci, lg)] - cells[(cc, lg)]
    )
    return out


def contrast_tests(contrasts: pd.DataFrame) -> dict[str, dict[str, float]]:
    """Every term of ``TERMS`` from a table of per-network contrasts (``per_network_contrasts``,
    or a difference of two such tables): each within contrast's mean over networks (the average
    of the two mappings' means) and its difference between mappings, and the mapping's effect on
    the network mean; t-tests with networks - 2 degrees of freedom (networks are the unit)."""
    mapping = contrasts["mapping"].to_numpy()
    out = {"mapping": group_regression(contrasts["mean"].to_numpy(), mapping)["mapping"]}
    for term in WITHIN:
        fit = group_regression(contrasts[term].to_numpy(), mapping)
        out[term] = fit["mean"]
        out[f"{term}:mapping"] = fit["mapping"]
    n = int(len(contrasts))
    return {term: out[term] | {"networks": n} for term in TERMS}


#: The simple effects: one factor's difference within one level of the other, as the cells'
#: (congruency, size) codes: (incongruent, small) etc. Name -> (cell +0.5 minus cell -0.5).
SIMPLE = {
    "size_in_congruent": ((-0.5, 0.5), (-0.5, -0.5)),
    "size_in_incongruent": ((0.5, 0.5), (0.5, -0.5)),
    "congruency_in_large": ((0.5, -0.5), (-0.5, -0.5)),
    "congruency_in_small": ((0.5, 0.5), (-0.5, 0.5)),
}


def simple_effects(df: pd.DataFrame, depvar: str = "rmse") -> dict[str, dict[str, float]]:
    """Each factor's effect within each level of the other (``SIMPLE``: small - large among the
    congruent trials, ...), per network and tested over networks as ``contrast_tests`` does (the
    mean of the two mappings' means, t with networks - 2 df; ``p_holm`` adjusted over the four).
    Where congruency and size interact, these, not the main effects, say where a difference
    lies."""
    data = coded(network_object_means(df, depvar))
    cells = network_cells(data, depvar).dropna()
    mapping = data.groupby("network")["mapping"].first().reindex(cells.index).to_numpy()
    out = {}
    for name, (plus, minus) in SIMPLE.items():
        values = (cells[plus] - cells[minus]).to_numpy()
        out[name] = group_regression(values, mapping)["mean"] | {"networks": int(len(cells))}
    return out


def network_contrasts(
    df: pd.DataFrame, depvar: str = "rmse", means: pd.DataFrame | None = None
) -> dict[str, dict[str, float]]:
    """The analysis used for inference (book/notes.md, "Testing and statistics"): per term of
    ``TERMS``, the estimate (coded as ``CODING``), its standard error, t, degrees of freedom, 95%
    t-interval and p, from per-network contrasts. The network is the unit: each network's four
    objects are the four congruency x size cells, so a within effect is a contrast of one network's
    cells, tested over the networks with the mapping (between networks) as a covariate. For a
    balanced design the estimates equal a mixed model's; the tests, unlike a random-intercept
    model's Wald z, assume no common error across the three within contrasts and use t with
    networks - 2 df. ``means``: as for ``per_network_contrasts``."""
    return contrast_tests(per_network_contrasts(df, depvar, means))


def difference_tests(
    a: pd.DataFrame, b: pd.DataFrame, depvar: str = "rmse"
) -> dict[str, dict[str, float]]:
    """A minus B, term by term, paired by network: for two runs whose network k is the same
    network under two settings (same seed, same mapping), the per-network contrasts' differences
    tested as ``contrast_tests`` (the test of a difference between readings or cue timings)."""
    return paired_difference(per_network_contrasts(a, depvar), per_network_contrasts(b, depvar))


def paired_difference(ca: pd.DataFrame, cb: pd.DataFrame) -> dict[str, dict[str, float]]:
    """``difference_tests`` from the two runs' per-network contrasts (``per_network_contrasts``),
    for a caller that reuses a run's contrasts in several comparisons."""
    common = ca.index.intersection(cb.index)
    ca, cb = ca.loc[common], cb.loc[common]
    if not (ca["mapping"] == cb["mapping"]).all():
        raise ValueError("paired runs differ in which networks learn which mapping")
    diff = ca.drop(columns="mapping") - cb.drop(columns="mapping")
    return contrast_tests(diff.assign(mapping=ca["mapping"]))


def cue_timing_difference(
    trials: dict[str, pd.DataFrame], mode: str = "closed_loop", depvar: str = "rmse"
) -> dict[str, dict[str, float]]:
    """The categorisation trials' per-network contrasts with the cue at the first step only
    minus with the cue at every step, paired by network (``difference_tests``): ``trials`` maps
    each cue timing (``first_step``, ``all_steps``) to its run's trial table, the two runs the
    same networks (same seed and mapping) trained under the two timings."""
    first, every = (categorisation_trials(trials[cue], mode) for cue in ("first_step", "all_steps"))
    return difference_tests(first, every, depvar)


def object_means(
    df: pd.DataFrame, depvar: str = "rmse", means: pd.DataFrame | None = None
) -> dict[str, dict[str, float]]:
    """Per object and mapping, the mean over networks of each network's mean (and its n).
    ``means``: ``network_object_means(df, depvar)``, when the caller has it already."""
    per_net = network_object_means(df, depvar) if means is None else means
    out = {}
    for (mapping, obj), group in per_net.groupby(["mapping", "object"]):
        out[f"{mapping}_{obj}"] = {
            "mean": float(group[depvar].mean()),
            "sd": float(group[depvar].std(ddof=1)) if len(group) > 1 else float("nan"),
            "n_networks": int(len(group)),
            "congruency": str(group["congruency"].iloc[0]),
            "size": str(group["size"].iloc[0]),
        }
    return out


#: The three readings of the paper's measure, as the keys of ``anova.json`` and the columns of
#: the trial tables they test: the all-trials RMSE the paper reports (``contrasts``), the
#: wrong-grip rate (``errors``: the trial ended nearer the other grip), and the correct-trial
#: RMSE (``correct_rt``: the reaction-time analogue, as people's reaction times are measured on
#: correct responses with errors reported apart).
OUTCOMES = {"contrasts": "rmse", "errors": "wrong_grip", "correct_rt": "rmse_correct"}

#: The family of every test of a run, per mode (the confirmatory family is ``paper_claims.FAMILY``).
EXPLORATION = "exploration: {mode}"


def with_outcomes(trials: pd.DataFrame) -> pd.DataFrame:
    """``trials`` with ``wrong_grip`` (1.0 where the final posture is nearer the other grip: the
    measures' table has it, the trial table's ``final_grip`` and ``target_grip`` give it) and
    ``rmse_correct`` (the trial's RMSE where its grip was right, else NaN: no reaction time)."""
    out = trials.copy()
    if "wrong_grip" not in out:
        out["wrong_grip"] = (out["final_grip"] != out["target_grip"]).astype(float)
    out["rmse_correct"] = out["rmse"].where(out["wrong_grip"].astype(float) == 0)
    return out


def cell_counts(df: pd.DataFrame, depvar: str) -> dict[str, int]:
    """Per congruency x size cell, the networks with at least one defined ``depvar`` there."""
    defined = df.dropna(subset=[depvar])
    counts = defined.groupby(["congruency", "size"])["network"].nunique()
    return {
        f"{c}_{s}": int(counts.get((c, s), 0))
        for c in ("congruent", "incongruent")
        for s in ("large", "small")
    }


def _coded_means(df: pd.DataFrame, depvar: str) -> pd.DataFrame:
    """Each network x object's mean over its defined ``depvar``, the factors coded: the
    observations of ``within_network_fit``."""
    data = network_object_means(df.dropna(subset=[depvar]), depvar).dropna(subset=[depvar])
    return coded(data)


def _within_terms(data: pd.DataFrame, depvar: str) -> dict[str, dict[str, float]]:
    """``within_network_fit``'s least squares on its observations (``_coded_means``)."""
    names = ["congruency", "size", "congruency:size"]
    both = data["mapping"].nunique() == 2
    c, s, m = (data[k].to_numpy(dtype=float) for k in ("congruency", "size", "mapping"))
    columns = [c, s, c * s] + ([c * m, s * m, c * s * m] if both else [])
    names += [f"{n}:mapping" for n in names] if both else []
    networks = sorted(data["network"].unique())
    dummies = [(data["network"].to_numpy() == n).astype(float) for n in networks]
    X = np.column_stack(dummies + columns) if len(data) else np.zeros((0, len(networks) + 3))
    y = data[depvar].to_numpy(dtype=float)
    rank = int(np.linalg.matrix_rank(X)) if len(data) else 0
    dof = len(y) - rank
    beta = np.linalg.lstsq(X, y, rcond=None)[0] if len(data) else np.zeros(X.shape[1])
    resid = y - X @ beta
    s2 = float(resid @ resid / dof) if dof > 0 else float("nan")
    cov = s2 * np.linalg.pinv(X.T @ X)
    tol = 1e-12 * max(1.0, float(np.abs(y).max()) if len(y) else 1.0)
    if dof > 0 and np.allclose(resid, 0, atol=tol):
        cov = np.zeros_like(cov)  # every network's contrasts the same: no variance
    out = {}
    nan = float("nan")
    for j, name in enumerate(names, start=len(networks)):
        without = np.delete(X, j, axis=1)
        identified = len(data) > 0 and int(np.linalg.matrix_rank(without)) < rank
        if identified:
            term = t_term(beta[j], np.sqrt(max(cov[j, j], 0.0)), dof)
        else:
            term = {k: nan for k in ("estimate", "se", "t", "ci_low", "ci_high", "p")}
            term["df"] = float(dof)
        out[name] = term | {"networks": len(networks), "observations": int(len(y))}
    return out


def within_network_fit(df: pd.DataFrame, depvar: str) -> dict[str, dict[str, float]]:
    """The within-network effects (``WITHIN`` and each one's difference between mappings) of a
    measure that a network may lack in some cells: the correct-trial RMSE, where a network that
    always took the wrong grip on an object has no correct trial of it. Each network x object
    with a defined value is one observation (its mean over its defined trials); a least-squares
    model with an intercept per network (which absorbs the network's speed and its mapping) and
    the coded within terms; t with the residual degrees of freedom (observations - rank). No
    network is dropped: one with a missing cell still informs the terms its other cells reach.
    With every cell present the estimates equal ``network_contrasts``' (the tests pool the
    three contrasts' error, as a repeated-measures ANOVA does). A term the observations do not
    identify has NaN statistics. ``cells`` counts the networks per cell."""
    out = _within_terms(_coded_means(df, depvar), depvar)
    cells = cell_counts(df, depvar)
    return {name: term | {"cells": cells} for name, term in out.items()}


def cells_by_mapping(df: pd.DataFrame, depvar: str) -> dict[str, int]:
    """Per mapping and congruency x size cell (``{mapping}_{congruency}_{size}``), the networks
    with at least one defined ``depvar`` there: under each mapping a cell is one object, so
    these say which objects' networks carry an estimate."""
    defined = df.dropna(subset=[depvar])
    counts = defined.groupby(["mapping", "congruency", "size"])["network"].nunique()
    return {
        f"{m}_{c}_{s}": int(counts.get((m, c, s), 0))
        for m in ("A", "B")
        for c in ("congruent", "incongruent")
        for s in ("large", "small")
    }


def correct_trial_effects(
    df: pd.DataFrame, depvar: str = "rmse_correct", left_out: bool = False, lono: bool = True
) -> dict[str, dict]:
    """THE estimator of the correct-trial RMSE's effects (every chapter that reports the measure
    calls this one function): ``within_network_fit``'s within terms (network intercepts and cell
    terms, so a network's other cells count when one has no correct trial), each with the
    networks per cell (``cells``), per mapping and cell (``cells_by_mapping``) and the
    leave-one-network-out range of its estimate (``lono_low``, ``lono_high``: the fit refitted
    without each network in turn, over the refits that still estimate the term; NaN if none
    does), so a reader sees how far an estimate rests on single networks. ``left_out``: each
    term also holds ``left_out``, {network: the estimate without it}, for statistics built on
    the estimates (their own leave-one-network-out range). ``lono`` False skips the refits
    (NaN range), for a caller that uses the estimates alone (a difference of two runs')."""
    fit = within_network_fit(df, depvar)
    by_mapping = cells_by_mapping(df, depvar)
    data = _coded_means(df, depvar)
    networks = sorted(data["network"].unique())
    # the same observations less one network's: the fit of the trials without that network
    refits = [_within_terms(data[data["network"] != n], depvar) for n in networks] if (
        lono or left_out) else []  # fmt: skip
    out = {}
    for term in WITHIN:
        without = np.array([r[term]["estimate"] for r in refits], dtype=float)
        without = without[np.isfinite(without)]
        low, high = (float(without.min()), float(without.max())) if len(without) else (
            float("nan"), float("nan"))  # fmt: skip
        out[term] = fit[term] | {"cells_by_mapping": by_mapping, "lono_low": low,
                                 "lono_high": high}  # fmt: skip
        if left_out:
            out[term]["left_out"] = {
                n: float(r[term]["estimate"]) for n, r in zip(networks, refits, strict=True)
            }
    return out


def outcome_tests(df: pd.DataFrame, outcome: str) -> dict[str, dict[str, float]]:
    """One mode's tests of one of ``OUTCOMES``: the per-network contrasts (every term of
    ``TERMS``) for the all-trials RMSE; the within terms for the wrong-grip rate (every network
    has every cell: per-network contrasts) and for the correct-trial RMSE (a network may lack a
    cell: ``within_network_fit``)."""
    depvar = OUTCOMES[outcome]
    if outcome == "contrasts":
        return network_contrasts(df, depvar)
    if outcome == "errors":
        tests = network_contrasts(df, depvar)
        return {t: tests[t] | {"cells": cell_counts(df, depvar)} for t in WITHIN}
    return correct_trial_effects(df, depvar)


def adjust_families(tests: list[tuple[str, dict]]) -> None:
    """Holm's adjustment within each family: every test ``(family, term)`` gets ``family``,
    ``family_size`` (its tests with a defined p) and ``p_holm`` (adjusted within it)."""
    families: dict[str, list[dict]] = {}
    for family, term in tests:
        families.setdefault(family, []).append(term)
    for family, terms in families.items():
        adjusted = holm([t["p"] for t in terms])
        size = int(np.isfinite([t["p"] for t in terms]).sum())
        for term, p in zip(terms, adjusted, strict=True):
            term |= {"family": family, "family_size": size, "p_holm": float(p)}


def analyse(trials: pd.DataFrame, run: str | None = None) -> dict[str, object]:
    """Everything anova.json holds, for both test modes: the ANOVAs and cell means per mode;
    the tests of the paper's measure and its two parts (``OUTCOMES``): the all-trials RMSE's
    per-network contrasts under ``contrasts`` (the analysis used for inference), and per mode
    ``errors`` (wrong-grip rate) and ``correct_rt`` (correct-trial RMSE); the simple effects
    (``simple_effects``) under ``simple``. Every test names its ``family`` and its ``p_holm``
    within it: every test of a mode is that mode's exploration of this run (``EXPLORATION``,
    named with ``run`` where it is given: another run's families are its own). The paper's
    claims are confirmed over fresh replications (``claims``), not on one run."""
    result: dict[str, object] = {}
    contrasts, simple = {}, {}
    trials = with_outcomes(trials)
    family: list[tuple[str, dict]] = []
    for mode in MODES:
        df = categorisation_trials(trials, mode)
        result[mode] = {
            "n_trials": int(len(df)),
            "n_networks": int(df["network"].nunique()),
            "two_way": two_way_anova(df),
            "repeated_measures": repeated_measures_anova(df),
            "means": cell_means(df),
            "wrong_grip_rate": wrong_grip_rates(df),
            # NaN where no network has a correct trial in the cell
            "means_correct": dict.fromkeys(cell_means(df), float("nan"))
            | cell_means(df.dropna(subset=["rmse_correct"]), "rmse_correct"),
        }
        contrasts[mode] = outcome_tests(df, "contrasts")
        for outcome in ("errors", "correct_rt"):
            result[mode][outcome] = outcome_tests(df, outcome)
        simple[mode] = simple_effects(df)
        explore = EXPLORATION.format(mode=mode.replace("_", " "))
        if run is not None:
            explore = explore.replace("exploration: ", f"exploration: run {run}, ")
        for outcome in OUTCOMES:
            tests = contrasts[mode] if outcome == "contrasts" else result[mode][outcome]
            family += [(explore, test) for test in tests.values()]
        family += [(explore, test) for test in simple[mode].values()]
    adjust_families(family)
    result["contrasts"] = contrasts
    result["simple"] = simple
    return result


def wrong_grip_rates(df: pd.DataFrame) -> dict[str, float]:
    """How often the final posture is nearer the other grip than the required one, per cell."""
    wrong = df["final_grip"] != df["target_grip"]
    return {
        f"{c}_{s}": float(v)
        for (c, s), v in wrong.groupby([df["congruency"], df["size"]]).mean().items()
    }


def anova_table_markdown(result: dict[str, object]) -> str:
    lines = [
        "| mode | analysis | effect | F | df | p | partial eta^2 |",
        "|---|---|---|---|---|---|---|",
    ]
    for mode in MODES:
        for analysis in ("two_way", "repeated_measures"):
            for effect, r in result[mode][analysis].items():
                lines.append(
                    f"| {mode.replace('_', ' ')} | {analysis.replace('_', ' ')} | {effect} | "
                    f"{r['F']:.2f} | {r['df1']:.0f}, {r['df2']:.0f} | {r['p']:.3g} | "
                    f"{r['eta_p2']:.3f} |"
                )
    return "\n".join(lines) + "\n"
