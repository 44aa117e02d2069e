"""Names against images over fresh replications (config ``words``, declared before any result):
the declared family of tests, and whether a name re-activates its object's hidden state.

Each replication (the whole model at one seed, names on, one cue timing) gives one estimate per
test mode, measure, form and effect: its networks' contrast on the trials showing that form
(``reading_tests.analyse_measures``, the estimator every chapter uses; for the correct-trial RMSE
the within-network fit). A declared test is over the replications, as the confirmation's
(``paper_claims``): a one-sample t (df = replications - 1) for the name-alone congruency and size
effects; for the name's equivalence with the image, each replication's difference (the name's
congruency effect minus the image's, on its own networks) held within the declared margin by two
one-sided t's. Holm over the whole family. A replication whose estimate is undefined is left out
of that test and counted; a test on fewer than ``min_replications`` has no p.

The reactivation (config ``words.reactivation``), a family of its own: at a declared step every
trial starts from the same posture, so a hidden state there reflects what the trial shows. For
each network the mean over tasks and objects of (the distance of the name's state to the other
objects' image states, averaged) minus (its distance to its own object's image state).
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from icub_affordance.analysis.decide import decide_equivalence, significant
from icub_affordance.analysis.paper_claims import direction
from icub_affordance.analysis.replicated import over_replications
from icub_affordance.analysis.statistics import equivalence, holm
from icub_affordance.outcome import Outcome
from icub_affordance.vocabulary import FORMS

#: The families' names wherever their tests appear.
FAMILY = "confirmatory: names against images over fresh replications"
FAMILY_REACTIVATION = "declared: a name's hidden state against its object's image's"

#: What a declared test is made of, in the order of its table's columns.
TEST_KEYS: tuple[str, ...] = ("cue", "mode", "measure", "test")

#: The effects each form is estimated on; positive is the paper's direction.
EFFECTS: tuple[str, ...] = ("congruency", "size")

#: Each declared test: the form and effect it reads, and whether it compares it with the image's.
TESTS: dict[str, tuple[str, str]] = {
    "congruency": ("name", "congruency"),
    "size": ("name", "size"),
    "equivalence": ("name", "congruency"),  # minus the image's, within the margin
}

#: The columns of a test's row after ``TEST_KEYS``.
SUMMARY_COLUMNS: tuple[str, ...] = (
    "replications", "estimable", "not_estimable", "estimate", "se", "ci_low", "ci_high", "t",
    "df", "p", "margin", "p_difference", "family", "p_holm", "family_size", "direction",
)  # fmt: skip


def declared_tests(declaration: Mapping[str, Any]) -> list[dict[str, str]]:
    """Every test of the family: each cue timing x test mode x measure x test the declaration
    lists (config ``words``), in that order."""
    lists = [declaration[key] for key in ("cues", "modes", "measures", "tests")]
    return [dict(zip(TEST_KEYS, combo, strict=True)) for combo in itertools.product(*lists)]


def replication_estimates(
    rows: Sequence[Mapping[str, Any]],
    analyses: Sequence[Mapping[str, Any]],
    declaration: Mapping[str, Any],
) -> pd.DataFrame:
    """One row per replication, test mode, measure, form and effect: its estimate (NaN where
    undefined), from each replication's analyses by form (``analyses``, in the order of
    ``rows``: cue, seed, run; each ``{form: reading_tests.analyse_measures(...)}``)."""
    out = []
    for row, by_form in zip(rows, analyses, strict=True):
        for mode, measure, form, effect in itertools.product(
            declaration["modes"], declaration["measures"], FORMS, EFFECTS
        ):
            term = by_form[form][mode][measure]["contrasts"][effect]
            out.append(
                {"cue": row["cue"], "seed": row["seed"], "run": row["run"], "mode": mode}
                | {"measure": measure, "form": form, "effect": effect}
                | {"estimate": float(term.get("estimate", np.nan))}
            )
    return pd.DataFrame(out)


def _per_seed(estimates: pd.DataFrame, cue: str, mode: str, measure: str, form: str,
              effect: str) -> pd.Series:  # fmt: skip
    """The replications' estimates of one form and effect, by seed."""
    keys = {"cue": cue, "mode": mode, "measure": measure, "form": form, "effect": effect}
    mask = np.logical_and.reduce([estimates[k] == v for k, v in keys.items()])
    return estimates[mask].set_index("seed")["estimate"].astype(float)


def word_tests(estimates: pd.DataFrame, declaration: Mapping[str, Any]) -> pd.DataFrame:
    """Each declared test over the replications (``SUMMARY_COLUMNS``), Holm over the family.
    ``direction``: for the name-alone effects, the paper's direction, against it, or neither
    (``paper_claims.direction``); for equivalence, ``PAPER`` when the difference is shown
    within the margin, else ``NONE`` (the difference's own t, ``p_difference``, is beside it,
    unadjusted: exploration)."""
    alpha, least = float(declaration["alpha"]), int(declaration["min_replications"])
    rows = []
    for test in declared_tests(declaration):
        form, effect = TESTS[test["test"]]
        cell = (test["cue"], test["mode"], test["measure"])
        values = _per_seed(estimates, *cell, form, effect)
        margin, p_difference = np.nan, np.nan
        if test["test"] == "equivalence":
            values = values - _per_seed(estimates, *cell, "image", effect)
        defined = values.to_numpy()[np.isfinite(values.to_numpy())]
        term = over_replications(defined, least)
        p = term["p"]
        if test["test"] == "equivalence":
            margin = float(declaration["margin"][test["measure"]])
            p_difference, p = p, equivalence(term, margin)["p"]
        rows.append(
            test
            | {"replications": len(values), "estimable": len(defined)}
            | {"not_estimable": len(values) - len(defined)}
            | {k: term[k] for k in ("estimate", "se", "ci_low", "ci_high", "t", "df")}
            | {"p": p, "margin": margin, "p_difference": p_difference}
        )
    table = pd.DataFrame(rows)
    table["family"] = FAMILY
    table["p_holm"] = holm(table["p"].to_numpy(dtype=float))
    table["family_size"] = int(np.isfinite(table["p"].to_numpy(dtype=float)).sum())
    table["direction"] = [
        _equivalent(p, alpha) if kind == "equivalence" else direction(e, p, alpha)
        for kind, e, p in zip(table["test"], table["estimate"], table["p_holm"], strict=True)
    ]
    return table[[*TEST_KEYS, *SUMMARY_COLUMNS]]


def _equivalent(p_holm: float, alpha: float) -> Outcome:
    """An equivalence test's ``Outcome``: ``PAPER`` (within the margin: the names' effect as
    the images', Tucker & Ellis 2004) when its adjusted p is below alpha, else ``NONE``."""
    return decide_equivalence(p_holm, alpha)


def reactivation(
    trials: Sequence[tuple[int, int, int]], name: np.ndarray, image: np.ndarray
) -> float:
    """One network's contrast (module docstring): ``trials`` (task, object, sequence) and the
    hidden states (trials, hidden) with the name alone and with the image alone. States of one
    task and object are averaged over sequences first."""
    trials = np.asarray(trials)
    contrasts = []
    for task in np.unique(trials[:, 0]):
        objects = np.unique(trials[:, 1])
        means = [
            [states[(trials[:, 0] == task) & (trials[:, 1] == o)].mean(axis=0) for o in objects]
            for states in (name, image)
        ]
        distances = np.linalg.norm(
            np.asarray(means[0])[:, None] - np.asarray(means[1])[None], axis=-1
        )  # (name's object, image's object)
        own = np.diag(distances)
        others = (distances.sum(axis=1) - own) / (len(objects) - 1)
        contrasts.append(float(np.mean(others - own)))
    return float(np.mean(contrasts))


def reactivation_tests(contrasts: pd.DataFrame, declaration: Mapping[str, Any]) -> pd.DataFrame:
    """Per cue timing: each replication's estimate the mean of its networks' contrasts
    (``contrasts``: cue, seed, network, contrast), a one-sample t over the replications, Holm
    over the cue timings at ``reactivation.alpha``; direction positive (the name nearer its
    own object's image)."""
    alpha = float(declaration["reactivation"]["alpha"])
    least = int(declaration["min_replications"])
    rows = []
    for cue in declaration["cues"]:
        per_seed = contrasts[contrasts["cue"] == cue].groupby("seed")["contrast"].mean()
        defined = per_seed.to_numpy()[np.isfinite(per_seed.to_numpy())]
        term = over_replications(defined, least)
        rows.append(
            {"cue": cue, "replications": len(per_seed), "estimable": len(defined)}
            | {k: term[k] for k in ("estimate", "se", "ci_low", "ci_high", "t", "df", "p")}
        )
    table = pd.DataFrame(rows)
    table["family"] = FAMILY_REACTIVATION
    table["p_holm"] = holm(table["p"].to_numpy(dtype=float))
    table["direction"] = [
        direction(e, p, alpha) for e, p in zip(table["estimate"], table["p_holm"], strict=True)
    ]
    return table


#: Two estimates this close are one number (the same cells read by two contrasts).
SAME = 1e-12

#: The columns ``qualifiers`` adds to the family's rows.
QUALIFIER_COLUMNS: tuple[str, ...] = (
    "image_effect", "image_inside_margin", "difference_below_alpha", "same_as_congruency",
    "only_incongruent_small", "p_difference_holm", "difference_family",
)  # fmt: skip
#: The family of the name-minus-image differences' own t's, Holm within it: the equivalence rows
#: say where a difference is shown too, which was asked after the results were seen.
FAMILY_DIFFERENCE = "exploration: name − image difference (added after results)"


def qualifiers(
    tests: pd.DataFrame, forms: pd.DataFrame, cells: pd.DataFrame, alpha: float
) -> pd.DataFrame:
    """What qualifies each declared test's verdict, as columns beside it (none is a test; each
    is a plain comparison, exploration):

    - an equivalence row: the image's own congruency effect over the replications
      (``image_effect``, from ``form_summary``), whether it lies inside the margin too
      (``image_inside_margin``: a name with no effect would then pass as well), and whether
      the difference's own unadjusted p is below ``alpha`` (``difference_below_alpha``), and
      that p Holm-adjusted over the equivalence rows (``p_difference_holm``, in
      ``FAMILY_DIFFERENCE``, added after results);
    - a size row: whether its estimate is the congruency test's number (``same_as_congruency``:
      the same cells read by both contrasts) and whether the name alone, in its cue timing and
      mode, made wrong grips, all of them in the incongruent small cell
      (``only_incongruent_small``, from ``error_cells``, the mean over replications).

    Empty where a column does not apply."""
    out = tests.copy()
    for column in QUALIFIER_COLUMNS:
        out[column] = pd.Series([pd.NA] * len(out), dtype="object")
    image = forms[(forms["form"] == "image") & (forms["effect"] == "congruency")]
    image = image.set_index(["cue", "mode", "measure"])["estimate"]
    by_test = tests.set_index([*TEST_KEYS])["estimate"]
    named = cells[cells["form"] == "name"]
    for i, row in out.iterrows():
        cell = (row["cue"], row["mode"], row["measure"])
        if row["test"] == "equivalence":
            effect = float(image[cell])
            out.at[i, "image_effect"] = effect
            out.at[i, "image_inside_margin"] = bool(abs(effect) < row["margin"])
            out.at[i, "difference_below_alpha"] = bool(significant(row["p_difference"], alpha))
        elif row["test"] == "size":
            congruency = by_test.get((*cell, "congruency"), np.nan)
            out.at[i, "same_as_congruency"] = bool(abs(row["estimate"] - congruency) < SAME)
            mine = named[(named["cue"] == row["cue"]) & (named["mode"] == row["mode"])]
            rates = mine.groupby(["congruent", "size"])["wrong_grip"].mean()
            carrying = {(str(c), str(z)) for (c, z), rate in rates.items() if rate > 0}
            out.at[i, "only_incongruent_small"] = carrying == {("False", "small")}
    tested = out.index[(out["test"] == "equivalence") & np.isfinite(out["p_difference"])]
    for i, p in zip(tested, holm(out.loc[tested, "p_difference"].to_numpy(float)), strict=True):
        out.at[i, "p_difference_holm"] = float(p)
        out.at[i, "difference_family"] = FAMILY_DIFFERENCE
    return out


def form_summary(estimates: pd.DataFrame, declaration: Mapping[str, Any]) -> pd.DataFrame:
    """Every form's congruency and size effects over the replications (a figure's points, each
    a one-sample t, unadjusted: beside the family, not in it), per cue timing, mode and
    measure."""
    least = int(declaration["min_replications"])
    rows = []
    keys = ("cue", "mode", "measure", "form", "effect")
    for values, group in estimates.groupby(list(keys), sort=False):
        defined = group["estimate"].to_numpy(dtype=float)
        defined = defined[np.isfinite(defined)]
        term = over_replications(defined, least)
        rows.append(
            dict(zip(keys, values, strict=True))
            | {"replications": len(group), "estimable": len(defined)}
            | {k: term[k] for k in ("estimate", "ci_low", "ci_high", "p")}
        )
    return pd.DataFrame(rows)


def error_cells(trials: pd.DataFrame) -> pd.DataFrame:
    """Each congruency x size cell's wrong-grip rate in one replication's categorisation trials
    (``trials``: its words.csv), per test mode and form: each network x object's rate once,
    then the mean over networks. Where the two effects coincide, these say which cell carries
    them (with four objects each cell is one object)."""
    cat = trials[trials["task"] == "categorisation"]
    per_object = cat.groupby(["mode", "form", "congruent", "size", "network", "object"])[
        "wrong_grip"
    ].mean()
    cells = per_object.groupby(["mode", "form", "congruent", "size"]).mean()
    return cells.rename("wrong_grip").reset_index()
