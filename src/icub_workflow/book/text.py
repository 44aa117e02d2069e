"""The few phrases a test chooses (its verdict words are ``words``'); the pages hold the
sentences. Each is a ``Claim`` on the entries it rests on, which the tests flip to see the
words follow."""

from __future__ import annotations

import math
from dataclasses import dataclass

from icub_affordance.trials.scores import LABELS

from .words import (
    AFTER_RESULTS,
    CLAIM_WORDS,
    CONFIRMED,
    NOT_ASSESSABLE,
    NOT_SHOWN,
    NOT_TESTABLE,
    PART_DIRECTIONS,
    REVERSED,
    SIZE_PART_WORDS,
    verdict_word,
)


@dataclass(frozen=True)
class Claim:
    """Words that state a finding, and the entries (``"page.key"``) of the statistics it rests
    on: ``findings.json`` keeps them under ``claims``, so each can be traced to its numbers."""

    text: str
    rests_on: tuple[str, ...]

    def __post_init__(self) -> None:
        if not self.rests_on or any("." not in r for r in self.rests_on):
            raise ValueError(f"a claim names the findings it rests on as page.key: {self}")


def fmt_term(term: dict) -> str:
    """Estimate, 95% interval, t, p and, where it has one, its p adjusted within its family."""
    fmt_p = lambda p: "p < 0.001" if p < 0.001 else f"p = {p:.3f}"  # noqa: E731
    family = (f", Holm-adjusted within the family “{term['family']}” ({term['family_size']} "
              f"tests) {fmt_p(term['p_holm'])}") if "family_size" in term else ""  # fmt: skip
    return (f"estimate {term['estimate']:+.4f}, 95% interval [{term['ci_low']:+.4f}, "
            f"{term['ci_high']:+.4f}], t({term['df']:.0f}) = {term['t']:.2f}, "
            f"{fmt_p(term['p'])}{family}")  # fmt: skip


def test_values(page: str, prefix: str, term: dict, verdict=verdict_word, words=None) -> dict:
    """A test's numbers as the analysis wrote them (NaN: untested), family, statistics, and
    ``_verdict``: a ``Claim`` on its estimate and adjusted p, said in ``words`` where given."""
    keys = ("estimate", "ci_low", "ci_high", "p")
    values = {f"{prefix}_{k}": term.get(k, math.nan) for k in keys}
    values[f"{prefix}_p_holm"] = term.get("p_holm", values[f"{prefix}_p"])
    values[f"{prefix}_family"] = term.get("family", "none")
    if "t" in term:
        values[f"{prefix}_stats"] = fmt_term(term)
    word = verdict(term | {k: values[f"{prefix}_{k}"] for k in ("estimate", "p", "p_holm")})
    rests = (f"{page}.{prefix}_estimate", f"{page}.{prefix}_p_holm")
    return values | {f"{prefix}_verdict": Claim((words or {}).get(word, word), rests)}


def listing(items, none: str) -> str:
    """Items joined by commas and "and"; ``none`` where there is none."""
    items = list(items)
    return ", ".join(items[:-1]) + " and " + items[-1] if len(items) > 1 else (items or [none])[0]


CUES = {"first_step": "the cue at the first step only", "all_steps": "the cue at every step"}


# -- which reading reproduces the paper: phrases on the readings' tests (``pages._shown``) -----

MEASURE_LABELS = LABELS  # declared with the measures (icub_affordance.trials.scores)
CUE_LABELS = dict(first_step="first", all_steps="every", cue_timing="cue", goal_response="Goal")


def stat_key(row, stat: str) -> str:
    """The readings page's value of a statistic of one row of the summary or the differences."""
    first = ("comparison", "at") if "comparison" in row else ("cue", "goal_response")
    return "_".join([*(row[c] for c in first), row["measure"], row["effect"], stat])


def _claim(rows, stats, said: str) -> Claim | str:
    """A phrase as a claim on the rows' statistics that exist; with none (nothing could be
    tested), no claim."""
    found = [f"readings.{stat_key(r, s)}" for _, r in rows.iterrows() for s in stats
             if math.isfinite(r[s])]  # fmt: skip
    return Claim(said, tuple(found)) if found else said


def reading_claims(shown) -> dict[str, Claim | str]:
    """Per tested measure, the readings whose congruency, size, or both (``both_<measure>``) go
    the paper's way on Holm's p (``paper_<measure>_<effect>``)."""
    out = {}
    for measure, rows in shown[shown["hypothesis"]].groupby("measure", sort=False):
        paper = rows[rows["verdict"] == CONFIRMED].groupby("named")["effect"].agg(set)
        for effects in (("congruency",), ("size",), ("congruency", "size")):
            chosen = [n for n in rows["named"].unique() if set(effects) <= paper.get(n, set())]
            said = "every reading" if len(chosen) == rows["named"].nunique() else chosen
            key = f"paper_{measure}_{effects[0]}" if len(effects) == 1 else f"both_{measure}"
            out[key] = _claim(rows, ("diff", "p_holm"), listing(said, "no reading")
                              if isinstance(said, list) else said)  # fmt: skip
            if isinstance(out[key], str):  # no reading could be tested
                out[key] = "no test could be made"
    return out


def difference_claims(shown, comparison: str, prefix: str) -> dict[str, Claim | str | int]:
    """The effects a comparison of readings makes larger or smaller (naming the other choice's
    level where only one shows it), and how many of its effects each verdict has."""
    rows = shown[(shown["comparison"] == comparison) & shown["hypothesis"]]
    stats, levels = ("diff", "p_holm", "p_equivalence_holm"), rows["at"].nunique()

    def effects(chosen) -> str:  # e.g. "congruency on RMSE (fixed only) and commitment"
        found: dict[str, list[str]] = {}
        for (effect, label), at in chosen.groupby(["effect", "label"], sort=False)["at"]:
            only = f" ({CUE_LABELS.get(at.iloc[0], at.iloc[0])} only)" * (len(at) < levels)
            found.setdefault(effect, []).append(label + only)
        return "; ".join(f"{e} on {listing(n, '')}" for e, n in found.items()) or "no effect"

    out: dict[str, Claim | str | int] = {f"{prefix}_n": len(rows)}
    changed = rows[rows["verdict"].isin(["larger", "smaller"])]
    out[f"{prefix}_changes"] = _claim(rows, stats, effects(changed))
    for word in ("larger", "smaller", "equivalent", "identical", NOT_ASSESSABLE, NOT_SHOWN,
                 AFTER_RESULTS):  # fmt: skip
        name = {AFTER_RESULTS: "equivalent_after", NOT_ASSESSABLE: "not_estimable"}.get(
            word, word.replace(" ", "_")
        )
        out[f"{prefix}_n_{name}"] = _claim(
            rows, stats, str((rows["verdict"] == word).sum()))  # fmt: skip
    for word in ("larger", "smaller"):
        out[f"{prefix}_{word}"] = _claim(rows, stats, effects(rows[rows["verdict"] == word]))
    return out


# -- what drives the size effect ------------------------------------------------------------

#: The demonstrations' measures (icub_affordance.analysis.size_study.GEOMETRY), in short.
GEOMETRY_SHORT = {"demo_path_length": "path length", "demo_spread": "spread",
                  "demo_grip_distance": "grips' distance"}  # fmt: skip


def trend_phrase(term) -> str:
    """Where a tested change moves the size effect (positive: towards the paper's direction)."""
    word = verdict_word(term)
    if word in (NOT_SHOWN, NOT_TESTABLE):
        return "by no amount its test shows"
    return ("away from" if word == REVERSED else "towards") + " the paper's direction"


def size_part_word(test: str, term: dict) -> str:
    """A declared test of the size study in words (``SIZE_PART_WORDS``)."""
    word = verdict_word(term)
    return SIZE_PART_WORDS[test].get(word, word)


def carrier(size_word: str, grip_word: str) -> str:
    """Which part of the size effect the crossed design shows at one dose and cue timing, from
    the two parts' verdict words (``verdict_word``), each shown part's direction said: a part
    "not shown" is not shown to be absent."""
    size, grips = (PART_DIRECTIONS.get(w) for w in (size_word, grip_word))
    if size and grips:
        return f"both parts are shown (size's own {size}, the grips' distance's {grips})"
    if size:
        return f"only size's own part is shown ({size}; the grips' distance's is not excluded)"
    if grips:
        return f"only the grips' distance's part is shown ({grips}; size's is not excluded)"
    return "the design cannot tell: neither part is shown"


def larger_part(term: dict) -> str:
    """Which part of the size effect is the larger, from the test of |size's part| - |the grips'
    distance's part| over the replications (positive: size's own): said only where that
    difference is shown."""
    word = verdict_word(term)
    if word == CONFIRMED:
        return "size's own part is the larger"
    if word == REVERSED:
        return "the grips' distance's part is the larger"
    return "neither part is shown to be the larger"


def named_measures(measures) -> str:
    """The demonstrations' measures named in short, joined by "and"."""
    return listing((f"the {GEOMETRY_SHORT[m]}" for m in measures), "none of the measures")


# -- the paper's claims over fresh replications ------------------------------------------------

#: The words of a declared test's parts, for its row of the front page.
CLAIM_PARTS = {
    "congruency": "Congruent lower (incongruent − congruent)",
    "size": "Large lower (small − large)",
    "rmse": "all-trial RMSE (the paper's measure)",
    "rmse_correct": "correct-trial RMSE (reaction time)",
    "closed_loop": "closed loop",
    "teacher_forced": "teacher forced",
    "first_step": "cue at the first step",
    "all_steps": "cue at every step",
}
#: The cue timings, as a phrase follows a verdict word ("confirmed with the cue at ...").
CUE_PHRASES = {"first_step": "with the cue at the first step", "all_steps": "with it at every step"}


def by_cue(words: dict[str, str]) -> str:
    """One claim's verdict words in one test mode, by cue timing: said once where they agree."""
    if len(words) > 1 and len(set(words.values())) == 1:
        return f"{next(iter(words.values()))} under both cue timings"
    return " and ".join(f"{word} {CUE_PHRASES[cue]}" for cue, word in words.items())


def condition_count(words: list[str]) -> str:
    """How many of a claim's conditions (cue timing × test mode) give each verdict word, the
    words in ``CLAIM_WORDS``' order: "confirmed in 3 of 4, not shown in 1"."""
    counts = {w: words.count(w) for w in CLAIM_WORDS.values() if w in words}
    said = [f"{word} in {n}" for word, n in counts.items()]
    said[0] += f" of {len(words)}"
    return ", ".join(said)


# -- the robot: an effect one cell carries ------------------------------------------------------

#: The grip a cell requires: congruent, the object's natural grip (large: power, small:
#: precision); incongruent, the other.
CELL_GRIPS = {("congruent", "large"): "power", ("congruent", "small"): "precision",
              ("incongruent", "large"): "precision", ("incongruent", "small"): "power"}  # fmt: skip
#: What a cell that carries an effect does, per robot measure: lower or higher than the others.
CELL_DOES = {"success": ("held less often", "held more often"),
             "contact_time": ("touches sooner", "touches later")}  # fmt: skip


def one_cell(cell: str, measure: str, lower: bool) -> str:
    """An effect one congruency x size cell carries, named as that cell: "one cell: a power grip
    on the small objects, held less often" (never as size or congruency)."""
    congruency, size = cell.split("_")
    does = CELL_DOES[measure][0 if lower else 1]
    return f"one cell: a {CELL_GRIPS[(congruency, size)]} grip on the {size} objects, {does}"
