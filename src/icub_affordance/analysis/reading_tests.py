"""Readings of the paper over replications (book/notes.md, "The maps", "The network and its
training", "Testing and statistics"): per run, every measure's contrasts and per-object means;
across a reading's replications, each effect's mean difference with a 95% interval, its t-test and
its Holm-adjusted p, and how many replications show it significantly in the paper's direction and
how many significantly reversed; and the tests of the differences between readings (the cue timing,
the Goal response), paired by network.

An effect's difference is the contrasts' estimate with the factor coded -0.5 / +0.5
(``trial_effects.CODING``): incongruent minus congruent, small minus large, averaged over the other
factors; for every measure higher is further from the required grip, so a positive difference is
the paper's direction.

Inference (book/notes.md, "Testing and statistics"). An effect's test is a t-test of the
replications' estimates (df = replications - 1), made on at least the declared minimum of them
(config ``confirmation.min_replications``, ``replicated.over_replications``: the one rule of every
test over replications); with fewer it has no p and reads "not assessable". A table of one
replication (the tests' fixtures; a build never has one: its readings run at confirmation.seeds,
refused below the minimum) shows that replication's own test over its networks (df = networks -
2, ``trial_effects.network_contrasts``). The family for Holm's
adjustment is every row of a table that is a hypothesis: every reading x measure x effect of the
summary, every comparison x measure x effect of the differences; a null control's rows
(``scores.NULL_CONTROLS``) are shown beside their measure and are not hypotheses, so they are left
out of the family (their ``p_holm`` is empty). A verdict (``direction``) needs the adjusted p below
``verdicts.ALPHA``; otherwise it is ``NONE``, which is not "no difference": only an equivalence test
(TOST, with a margin declared in config) can say that. Each table names, per row, the family its
``p_holm`` is adjusted within (``family``; ``FAMILY_*``).

A measure that a network can lack in a cell (``scores.MISSING_BY_DESIGN``: the correct-trial RMSE)
is tested with ``trial_effects.correct_trial_effects``, which keeps such a network; its differences
between readings cannot be paired by network (``difference_replications``).
"""

from __future__ import annotations

import functools

import numpy as np
import pandas as pd

from icub_affordance.analysis import replicated
from icub_affordance.analysis.statistics import equivalence, holm, t_term
from icub_affordance.analysis.trial_effects import (
    categorisation_trials,
    cell_means,
    correct_trial_effects,
    network_contrasts,
    network_object_means,
    object_means,
    paired_difference,
    per_network_contrasts,
    with_outcomes,
)
from icub_affordance.analysis.verdicts import ALPHA
from icub_affordance.outcome import Outcome
from icub_affordance.trials.scores import (
    analysed,
    can_lack_cells,
    is_derived,
    is_hypothesis,
    is_null_control,
    margin_measure,
    with_excess,
)
from icub_affordance.vocabulary import MODES

#: The effects the paper reports, the per-network contrasts' test's terms of the same name.
EFFECTS: tuple[str, ...] = ("congruency", "size")

#: The Holm families of the readings' tables (a row's ``family``): every hypothesis of the
#: summary, every difference between readings, every equivalence test (TOST) of a difference.
FAMILY_SUMMARY = "exploration: readings"
FAMILY_DIFFERENCES = "exploration: readings' differences"
FAMILY_EQUIVALENCE = "exploration: readings' equivalence"
#: A null control's rows: shown beside their measure, in no family (empty ``p_holm``).
NULL_CONTROL = "null control (not a hypothesis)"
#: A difference with no spread at all (``identical``): not tested, in no family.
NOT_TESTED = "not tested (identical)"
#: ``difference_verdict``'s code for a difference on fewer replications than the minimum
#: (``replicated``); its word is in ``book.words.DIFFERENCE_WORDS``.
NOT_ASSESSABLE = "not_assessable"
#: A measure tested by its excess over its null control (``scores.EXCESS``): shown, no test.
BY_EXCESS = "shown (tested by its excess over the null control)"

#: The columns that say which effect on which measure, and its mean and interval.
_EFFECT_COLUMNS = ["measure", "effect", "replications", "diff", "ci_low", "ci_high"]

#: The columns of data/readings/summary.csv: the contract's, then df, p and p_holm.
SUMMARY_COLUMNS = [
    "reading",
    "cue",
    "goal_response",
    *_EFFECT_COLUMNS,
    "n_paper",
    "n_reversed",
    "df",
    "p",
    "p_holm",
    "family",
    "not_estimable",
]

#: The columns of data/readings/differences.csv: one row per comparison (the readings ``a`` and
#: ``b`` differing in one choice, the other choice ``at``), measure and effect; ``diff`` is a's
#: effect minus b's. The equivalence columns are filled for the Goal response only. ``identical``:
#: every replication's difference the same with no spread (se 0), so nothing to test.
DIFFERENCE_COLUMNS = [
    "comparison",
    "at",
    "a",
    "b",
    *_EFFECT_COLUMNS,
    "df",
    "identical",
    "p",
    "p_holm",
    "family",
    "margin",
    "p_equivalence",
    "p_equivalence_holm",
    "family_equivalence",
]

#: The comparisons between readings: which choice differs, and its two levels a, b (a - b).
COMPARISONS = {
    "cue_timing": ("cue", "first_step", "all_steps"),
    "goal_response": ("goal_response", "grows", "fixed"),
}


def with_derived(trials: pd.DataFrame, measures) -> pd.DataFrame:
    """``trials`` with the derived measures among ``measures`` (``scores.DERIVED``: the
    correct-trial RMSE, from ``rmse`` and ``wrong_grip``) as columns."""
    if any(is_derived(m) for m in analysed(measures)):
        trials = with_outcomes(trials)
    return with_excess(trials)


def contrasts(df: pd.DataFrame, measure: str, means: pd.DataFrame | None = None) -> dict[str, dict]:
    """A measure's contrasts: ``trial_effects.correct_trial_effects`` for a measure that a network
    can lack in a cell (``scores.MISSING_BY_DESIGN``: the per-network contrasts would drop that
    network), the per-network contrasts otherwise. ``means``: ``network_object_means(df, measure)``,
    when the caller has it already."""
    if can_lack_cells(measure):
        return correct_trial_effects(df, measure)
    return network_contrasts(df, measure, means)


def defined_object_means(
    df: pd.DataFrame, measure: str, means: pd.DataFrame | None = None
) -> dict[str, dict[str, float]]:
    """``trial_effects.object_means`` over the networks with a defined value (means over the defined
    trials): every object kept, its ``n_networks`` the networks defined there. ``means``: as for
    ``contrasts``."""
    means = network_object_means(df, measure) if means is None else means
    out = object_means(df, measure, means)
    per_net = means.dropna(subset=[measure])
    counts = per_net.groupby(["mapping", "object"]).size()
    for key, entry in out.items():
        mapping, obj = key.split("_", 1)
        entry["n_networks"] = int(counts.get((mapping, obj), 0))
    return out


def analyse_measures(trials: pd.DataFrame, measures: list[str]) -> dict[str, dict]:
    """Per test mode and measure (the declared ones, each with its null control:
    ``scores.analysed``; the derived ones computed here, ``with_derived``): the contrasts
    (``contrasts``), the cell means and the per-object means of the categorisation trials
    (``measures.csv``'s rows), each mean over the defined values only."""
    trials = with_derived(trials, measures)
    out: dict[str, dict] = {}
    for mode in MODES:
        df = categorisation_trials(trials, mode)
        out[mode] = {}
        for measure in analysed(measures):
            means = network_object_means(df, measure)  # each network's per object, once
            out[mode][measure] = {
                "contrasts": contrasts(df, measure, means),
                "means": cell_means(df.dropna(subset=[measure]), measure),
                "object_means": defined_object_means(df, measure, means),
            }
    return out


def flat_term(term: dict) -> dict:
    """A term as one table row: ``trial_effects.correct_trial_effects``' networks per cell as
    ``cells_{cell}`` columns, per mapping and cell as ``cells_{mapping}_{cell}``."""
    nested = ("cells", "cells_by_mapping")
    flat = {k: v for k, v in term.items() if k not in nested}
    for key in nested:
        flat |= {f"cells_{cell}": n for cell, n in term.get(key, {}).items()}
    return flat


def replication_rows(
    table: list[dict], analyses: list[dict], measures: list[str], mode: str = "closed_loop"
) -> pd.DataFrame:
    """One row per reading, replication, measure and effect: the contrasts' estimate, its
    interval, df and p. ``table`` holds the readings' rows (reading, cue, goal_response, seed,
    run), ``analyses`` each row's ``analyse_measures`` result. A ``correct_trial_effects``'
    networks per cell are the ``cells_{cell}`` columns."""
    rows = []
    for row, analysis in zip(table, analyses, strict=True):
        for measure in analysed(measures):
            for effect in EFFECTS:
                term = flat_term(analysis[mode][measure]["contrasts"][effect])
                rows.append(dict(row) | {"measure": measure, "effect": effect} | term)
    return pd.DataFrame(rows)


def over_replications(terms: pd.DataFrame, least: int) -> dict[str, float]:
    """An effect over its replications (rows with each one's ``estimate``, ``ci_low``,
    ``ci_high``, ``df``, ``p``): the mean of the defined estimates and a t-test of them (df =
    defined - 1), made only on at least ``least`` of them (``replicated.over_replications``, the
    one rule; below it no p, df 0: not assessable); a replication whose estimate is undefined is
    left out and counted (``not_estimable``), as the confirmation does. One replication alone
    (no test over replications: a fixture, never a build) shows its own test over its networks."""
    if len(terms) == 1:
        row = terms.iloc[0]
        term = {k: float(row[k]) for k in ("estimate", "ci_low", "ci_high", "df", "p")}
        term["se"] = float(row["se"]) if "se" in row else float("nan")
        missing = int(not np.isfinite(term["estimate"]))
    else:
        estimates = terms["estimate"].to_numpy(dtype=float)
        defined = estimates[np.isfinite(estimates)]
        missing = len(estimates) - len(defined)
        term = replicated.over_replications(defined, least)
    return {
        "diff": term["estimate"],
        "ci_low": term["ci_low"],
        "ci_high": term["ci_high"],
        "df": term["df"],
        "p": term["p"],
        "se": term["se"],
        "not_estimable": missing,
    }


def holm_hypotheses(table: pd.DataFrame, column: str = "p") -> np.ndarray:
    """Holm's adjustment of ``column`` over the rows that are hypotheses (``measures.
    is_hypothesis``: a null control's rows and those of a measure tested by its excess are not:
    NaN)."""
    out = np.full(len(table), np.nan)
    hypothesis = table["measure"].map(is_hypothesis).to_numpy(dtype=bool)
    out[hypothesis] = holm(table.loc[hypothesis, column].to_numpy(dtype=float))
    return out


def family_names(table: pd.DataFrame, family: str) -> list[str]:
    """Each row's Holm family as ``holm_hypotheses`` adjusts it: ``family`` for a hypothesis,
    ``NULL_CONTROL`` for a null control's row, ``BY_EXCESS`` for a measure tested by its excess
    over its null control."""
    return [
        family if is_hypothesis(m) else NULL_CONTROL if is_null_control(m) else BY_EXCESS
        for m in table["measure"]
    ]


def summary(replications: pd.DataFrame, least: int) -> pd.DataFrame:
    """One row per reading, measure and effect (``SUMMARY_COLUMNS``). ``diff``, its interval,
    ``df`` and ``p`` from ``over_replications`` (on at least ``least`` estimates, config
    ``confirmation.min_replications``; below it no p, df 0); ``p_holm`` Holm's over the table's
    hypotheses (``holm_hypotheses``), its ``family`` named (``FAMILY_SUMMARY``, or
    ``NULL_CONTROL``).
    ``n_paper`` and ``n_reversed`` count the replications with (raw) p < ALPHA in and against
    the paper's direction."""
    rows = []
    keys = ["reading", "cue", "goal_response", "measure", "effect"]
    for key, group in replications.groupby(keys, sort=False):
        estimates = group["estimate"].to_numpy()
        significant = group["p"].to_numpy() < ALPHA
        test = over_replications(group, least)
        rows.append(
            dict(zip(keys, key, strict=True))
            | {k: test[k] for k in ("diff", "ci_low", "ci_high", "df", "p", "not_estimable")}
            | {
                "replications": len(group),
                "n_paper": int((significant & (estimates > 0)).sum()),
                "n_reversed": int((significant & (estimates < 0)).sum()),
            }
        )
    out = pd.DataFrame(rows, columns=SUMMARY_COLUMNS)
    out["p_holm"] = holm_hypotheses(out) if len(out) else []
    out["family"] = family_names(out, FAMILY_SUMMARY)
    return out


def welch_df(se_a: float, se_b: float, df_a: float, df_b: float) -> float:
    """The Welch-Satterthwaite degrees of freedom of a difference of two independent estimates;
    with both standard errors 0 (no variance to weigh), the two df pooled; NaN where either
    estimate has no test."""
    va, vb = se_a**2, se_b**2
    if not (df_a > 0 and df_b > 0 and np.isfinite(va + vb)):
        return float("nan")
    if va + vb == 0:
        return float(df_a + df_b)
    return float((va + vb) ** 2 / (va**2 / df_a + vb**2 / df_b))


def unpaired_difference(a: pd.DataFrame, b: pd.DataFrame, measure: str) -> dict[str, dict]:
    """A minus B for a measure that a network can lack in a cell (``scores.MISSING_BY_DESIGN``):
    a network's contrast is then undefined, so the runs cannot be paired by network. Each term
    is the difference of the two runs' ``trial_effects.correct_trial_effects`` estimates, with
    se = sqrt(se_a^2 + se_b^2) and Welch-Satterthwaite df. Conservative: the two runs' networks
    are the same networks (same seeds, same mappings), whose estimates correlate positively, and
    the unpaired se ignores that covariance."""
    fa, fb = (correct_trial_effects(run, measure, lono=False) for run in (a, b))
    out = {}
    for effect in EFFECTS:
        ta, tb = fa[effect], fb[effect]
        se = float(np.hypot(ta["se"], tb["se"]))
        df = welch_df(ta["se"], tb["se"], ta["df"], tb["df"])
        out[effect] = t_term(ta["estimate"] - tb["estimate"], se, df) | {
            "networks": min(ta["networks"], tb["networks"]),
            "observations": ta["observations"] + tb["observations"],
        }
    return out


def difference_replications(
    table: list[dict],
    trials: dict[str, pd.DataFrame],
    measures: list[str],
    mode: str = "closed_loop",
) -> pd.DataFrame:
    """One row per comparison (``COMPARISONS``), level of the other choice, replication,
    measure and effect: reading a's effect minus reading b's, paired by network
    (``trial_effects.difference_tests`` on the two runs' trials of the same seed: a run's network k
    has the seed ``training.network_seed(seed, k)`` and the mapping ``training.mapping_of(k)``
    whatever the reading, so network k is the same network under the two settings). ``trials`` maps
    each run to its ``measures.csv``. A measure that a network can lack in a cell
    (``scores.MISSING_BY_DESIGN``) is not paired: ``unpaired_difference``."""
    by = {(r["cue"], r["goal_response"], r["seed"]): r for r in table}
    rows = []

    @functools.cache
    def scored(run: str) -> pd.DataFrame:
        return categorisation_trials(with_derived(trials[run], measures), mode)

    @functools.cache
    def contrasts_of(run: str, measure: str) -> pd.DataFrame:
        return per_network_contrasts(scored(run), measure)

    for comparison, (choice, level_a, level_b) in COMPARISONS.items():
        other = "goal_response" if choice == "cue" else "cue"
        for (cue, goal, seed), ra in by.items():
            if ra[choice] != level_a:
                continue
            rb = by.get((level_b, goal, seed) if choice == "cue" else (cue, level_b, seed))
            if rb is None:  # the config reads only one level of this choice
                continue
            a, b = (scored(r["run"]) for r in (ra, rb))
            for measure in analysed(measures):
                if can_lack_cells(measure):
                    terms = unpaired_difference(a, b, measure)
                else:  # each run's contrasts once, whichever comparisons it is in
                    terms = paired_difference(contrasts_of(ra["run"], measure),
                                              contrasts_of(rb["run"], measure))  # fmt: skip
                for effect in EFFECTS:
                    rows.append(
                        {
                            "comparison": comparison,
                            "at": ra[other],
                            "a": ra["reading"],
                            "b": rb["reading"],
                            "seed": seed,
                            "measure": measure,
                            "effect": effect,
                        }
                        | terms[effect]
                    )
    return pd.DataFrame(rows)


def identical(group: pd.DataFrame, test: dict[str, float]) -> bool:
    """Every replication's difference exactly 0 and no spread within (se 0: e.g. a measure
    constant on every network in both readings): the two readings gave the same values, and
    there is nothing to test. (A difference that is the same non-zero value everywhere, se 0,
    has no variance to test either: its p is undefined, see ``differences``.)"""
    estimates = group["estimate"].to_numpy(dtype=float)
    return bool(np.all(estimates == 0) and test["se"] == 0)


def equivalence_row(row: dict, test: dict[str, float], margins: dict[str, float]) -> dict:
    """A differences row's TOST within its measure's declared margin (config
    ``readings.equivalence_margin``), for the Goal response's hypotheses only."""
    measure = row["measure"]
    if row["comparison"] != "goal_response" or not is_hypothesis(measure):
        return {"margin": np.nan, "p_equivalence": np.nan}
    if margin_measure(measure) not in margins:
        raise ValueError(f"readings.equivalence_margin has no margin for {measure!r}")
    margin = float(margins[margin_measure(measure)])
    tost = equivalence({"estimate": test["diff"], "se": test["se"], "df": test["df"]}, margin)
    return {"margin": margin, "p_equivalence": np.nan if row["identical"] else tost["p"]}


def differences(replications: pd.DataFrame, margins: dict[str, float], least: int) -> pd.DataFrame:
    """One row per comparison, level, measure and effect (``DIFFERENCE_COLUMNS``): the difference
    over replications (``over_replications``, on at least ``least``), Holm's p over the table's
    hypotheses (``FAMILY_DIFFERENCES``), and for the Goal response the equivalence test (TOST)
    within the measure's declared margin (``equivalence_row``), its p Holm-adjusted over the
    equivalence tests (``FAMILY_EQUIVALENCE``; a null control has none). An ``identical`` row is not
    tested: its p and TOST p are NaN, so it is in no family (``NOT_TESTED``)."""
    keys = ["comparison", "at", "a", "b", "measure", "effect"]
    rows = []
    for key, group in replications.groupby(keys, sort=False):
        test = over_replications(group, least)
        row = dict(zip(keys, key, strict=True)) | {"replications": len(group)} | test
        row["identical"] = identical(group, test)
        if row["identical"] or test["se"] == 0:
            row["p"] = np.nan  # no variance: no test, in no family
        rows.append(row | equivalence_row(row, test, margins))
    out = pd.DataFrame(rows, columns=[*DIFFERENCE_COLUMNS])
    if len(out):
        out["p_holm"] = holm_hypotheses(out)
        out["p_equivalence_holm"] = holm_hypotheses(out, "p_equivalence")
        out["family"] = family_names(out, FAMILY_DIFFERENCES)
        null = ~out["measure"].map(is_hypothesis).to_numpy(dtype=bool)
        out.loc[out["identical"].to_numpy(dtype=bool) & ~null, "family"] = NOT_TESTED
        tost = out["margin"].notna() & ~out["identical"]
        out["family_equivalence"] = np.where(tost, FAMILY_EQUIVALENCE, "")
    return out


def verdict_p(row) -> float:
    """The p a row's verdict uses: Holm's for a hypothesis, the raw p for a row shown for
    comparison (a null control, a measure tested by its excess), which is no hypothesis."""
    return float(row["p_holm"] if is_hypothesis(row["measure"]) else row["p"])


def direction(row) -> Outcome:
    """A summary row's effect: ``PAPER`` or ``AGAINST`` when its (Holm-adjusted, ``verdict_p``) p
    is below ALPHA, on the side of its difference; ``NONE`` otherwise; ``CONSTANT`` when the
    measure did not vary at all (a difference of exactly 0 with a zero-width interval);
    ``NOT_ASSESSABLE`` when fewer replications than the minimum had an estimate (df 0:
    ``replicated.was_assessable``)."""
    if row["diff"] == row["ci_low"] == row["ci_high"] == 0:
        return Outcome.CONSTANT
    if not replicated.was_assessable(float(row["df"])):
        return Outcome.NOT_ASSESSABLE
    p = verdict_p(row)
    if not (p < ALPHA):
        return Outcome.NONE
    return Outcome.PAPER if row["diff"] > 0 else Outcome.AGAINST


def difference_verdict(row) -> str:
    """A differences row's verdict: "identical" when there was nothing to test (``identical``:
    no spread at all), "a > b" or "a < b" (its effect larger or smaller in a than in b) when its
    p (Holm's; a null control's raw p) is below ALPHA, "equivalent" when the TOST within the
    margin is (Holm's), ``NOT_ASSESSABLE`` when fewer replications than the minimum had an
    estimate (df 0: ``replicated.was_assessable``), else "none" (neither a difference nor its
    absence)."""
    if str(row.get("identical", False)) == "True":  # a bool, or the CSV's text
        return "identical"
    if not is_hypothesis(row["measure"]):
        return "not a hypothesis"
    if not replicated.was_assessable(float(row["df"])):
        return NOT_ASSESSABLE
    if verdict_p(row) < ALPHA:
        return "a > b" if row["diff"] > 0 else "a < b"
    if row["p_equivalence_holm"] < ALPHA:
        return "equivalent"
    return "none"


def finite(values) -> bool:
    return bool(np.all(np.isfinite(np.asarray(values, dtype=float))))
