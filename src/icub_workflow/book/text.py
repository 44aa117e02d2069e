"""The book's words: numbers formatted for reading, and the sentences generated from the run.

The verdicts behind the sentences (is an effect in the paper's direction, is it significant)
are the package's (``icub_affordance.findings``); this module only says them. The rule
``findings`` (``workflow/scripts/findings.py``) calls it, and the pages show what it wrote.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from icub_affordance.findings import ALPHA
from icub_affordance.measures import is_hypothesis


@dataclass(frozen=True)
class Claim:
    """A generated sentence that states a finding, and the entries of ``findings.json`` it rests
    on (``"page.key"``: the statistic, not its words). The page shows ``text``; ``findings.json``
    keeps ``rests_on`` under ``claims``, so a reader (and a test) can trace every finding the
    book states to the numbers behind it."""

    text: str
    rests_on: tuple[str, ...]

    def __post_init__(self) -> None:
        if not self.rests_on or any("." not in r for r in self.rests_on):
            raise ValueError(f"a claim names the findings it rests on as page.key: {self}")


def fmt_p(p: float) -> str:
    return "p < 0.001" if p < 0.001 else f"p = {p:.3f}"


def fmt_ci(term: dict) -> str:
    return f"[{term['ci_low']:+.4f}, {term['ci_high']:+.4f}]"


def fmt_family(term: dict) -> str:
    """An adjusted p with the family it is adjusted within (``stats.adjust_families``)."""
    return (
        f"Holm-adjusted within the family “{term['family']}” ({term['family_size']} tests) "
        f"{fmt_p(term['p_holm'])}"
    )


def fmt_term(term: dict) -> str:
    """A tested term: estimate, 95% t-interval, t with its degrees of freedom, p, and where it
    has one, its p adjusted within its named family."""
    return (
        f"estimate {term['estimate']:+.4f}, 95% interval {fmt_ci(term)}, "
        f"t({term['df']:.0f}) = {term['t']:.2f}, {fmt_p(term['p'])}"
        + (f", {fmt_family(term)}" if "family_size" in term else "")
    )


def claim_verdict(term: dict, outcome: str, effect: str) -> str:
    """The front page's verdict on one test: "reproduced" or "reversed" for the two effects the
    paper claims, on its measure or the correct trials' (its reaction-time reading); the paper
    claims nothing of errors, nor of the required grip (the congruency x size term), so those
    are "shown", "shown, opposite" (against the paper's direction) or "not shown"."""
    word = verdict_word(term)
    if outcome != "errors" and effect != "congruency:size":
        return word
    if effect == "congruency:size":
        return "shown" if word in ("reproduced", "reversed") else word
    return {"reproduced": "shown", "reversed": "shown, opposite"}.get(word, word)


def verdict_word(term: dict, alpha: float = ALPHA) -> str:
    """A test against the paper's direction (positive estimate): "reproduced" or "reversed"
    where its p adjusted within its family is below ``alpha``, else "not shown" (which is not
    "no difference": only an equivalence test says that); "not testable" where it has no p."""
    p = term.get("p_holm", term["p"])
    if not math.isfinite(p):
        return "not testable"
    if p >= alpha:
        return "not shown"
    return "reproduced" if term["estimate"] > 0 else "reversed"


def shown_word(term: dict, alpha: float = ALPHA) -> str:
    """A difference the paper does not predict (a simple effect, the wrong-grip rate, the
    required grip): "shown" where its p adjusted within its family is below ``alpha``, else "not
    shown"; its sign is in the estimate beside it."""
    word = verdict_word(term, alpha)
    return "shown" if word in ("reproduced", "reversed") else word


def test_values(page: str, prefix: str, term: dict, verdict=verdict_word, words=None) -> dict:
    """A test as page values: its numbers as the analysis wrote them (NaN where untested), its
    family, its statistics in a line where it has them, and ``_verdict``: a ``Claim`` resting on
    its estimate and adjusted p, said in ``words`` (verdict word: phrase) where given."""
    values = {
        f"{prefix}_{k}": term.get(k, math.nan) for k in ("estimate", "ci_low", "ci_high", "p")
    }
    values[f"{prefix}_p_holm"] = term.get("p_holm", values[f"{prefix}_p"])
    values[f"{prefix}_family"] = term.get("family", "none")
    if "t" in term:
        values[f"{prefix}_stats"] = fmt_term(term)
    word = verdict(term | {k: values[f"{prefix}_{k}"] for k in ("estimate", "p", "p_holm")})
    rests = (f"{page}.{prefix}_estimate", f"{page}.{prefix}_p_holm")
    return values | {f"{prefix}_verdict": Claim((words or {}).get(word, word), rests)}


def pct(x: float) -> str:
    return f"{100 * x:.0f}%"


# The main effects: the front page, the results, the discussion and the chapter beyond the paper.


# The robustness page (book/robustness.md) and the reproduction notes' scale.

CUES = {"first_step": "the cue at the first step only", "all_steps": "the cue at every step"}
#: An effect over the sweep's replications by its 95% interval (findings.interval_direction).
SWEEP_DIRECTIONS = {"paper": "reproduced", "against": "reversed", "unclear": "not shown"}
SWEEP_DIRECTIONS["single"] = "one replication"


def growth_phrase(growth: dict) -> str:
    """How the sweep's wall time grows (growth.cost_growth's ``change``, the last added
    replication's cost over the first's less one): within 10%, "linearly"."""
    if len(growth["marginal"]) < 2:
        return "in a way two timings cannot show: it takes three to tell"
    if abs(growth["change"]) <= 0.1:
        return "linearly"
    return "faster than linearly" if growth["change"] > 0 else "no faster than linearly"


# ---- Which reading reproduces the paper (book/readings.md) --------------------------------------
# Short verdict phrases on the readings' tests, each a Claim resting on the page's statistics
# (``stat_key``); the sentences around them are the page's own.

#: The chapter's names of the measures, of the readings' choices (its tables' legend) and of the
#: verdicts (``readings.direction``, ``readings.difference_verdict``) where they differ.
MEASURE_LABELS = {
    "rmse": "RMSE",
    "rmse_correct": "correct-trial RMSE",
    "wrong_grip": "wrong-grip rate",
    "commitment": "commitment",
    "rmse_per_grip_distance": "RMSE per grip distance",
    "rmse_per_grip_distance_null": "null control",
    "rmse_per_grip_distance_excess": "excess over null",
}
CUE_LABELS = dict(first_step="first", all_steps="every", cue_timing="cue", goal_response="Goal")
WORDS = {
    "none": "not shown",
    "constant": "no variation",
    "a > b": "larger",
    "a < b": "smaller",
    "paper": "reproduced",
}


def stat_key(row, stat: str) -> str:
    """The readings page's value of a statistic of one row of the summary or the differences."""
    first = ("comparison", "at") if "comparison" in row else ("cue", "goal_response")
    return "_".join([*(row[c] for c in first), row["measure"], row["effect"], stat])


def _rests_on(rows, stats) -> tuple[str, ...]:
    """The rows' statistics that exist (a constant cell has no p, an identical difference no
    test), as what a claim rests on."""
    found = ((r, s) for _, r in rows.iterrows() for s in stats if math.isfinite(r[s]))
    return tuple(f"readings.{stat_key(r, s)}" for r, s in found)


def _listing(items, none: str) -> str:
    items = list(items)
    return ", ".join(items[:-1]) + " and " + items[-1] if len(items) > 1 else (items or [none])[0]


def reading_claims(summary) -> dict[str, Claim]:
    """Per tested measure, the readings whose congruency or size effect goes the paper's way on
    Holm's p (``paper_<measure>_<effect>``), and those where both do (``both_<measure>``)."""
    from icub_affordance.readings import direction

    out = {}
    tested = summary[summary["measure"].map(is_hypothesis)]
    for measure, rows in tested.groupby("measure", sort=False):
        names = rows["cue"].map(CUE_LABELS) + " · " + rows["goal_response"]
        paper = rows.apply(direction, axis=1) == "paper"
        shown = rows["effect"][paper].groupby(names[paper]).agg(set)
        for effects in (("congruency",), ("size",), ("congruency", "size")):
            chosen = [n for n in names.unique() if set(effects) <= shown.get(n, set())]
            every = len(chosen) == names.nunique()
            words = "every reading" if every else _listing(chosen, "no reading")
            key = f"paper_{measure}_{effects[0]}" if len(effects) == 1 else f"both_{measure}"
            rests = _rests_on(rows, ("diff", "p_holm"))
            # a measure none of whose readings could be tested (too few correct trials at a
            # small scale) states no finding: it says so, and is no claim
            out[key] = Claim(words, rests) if rests else "no test could be made"
    return out


def difference_claims(differences, comparison: str, prefix: str) -> dict[str, Claim | str | int]:
    """The effects a comparison of readings changes, from its tests
    (``readings.difference_verdict``): ``<prefix>_larger``, ``_smaller`` and ``_changes``
    (either), naming the level of the other choice where only one shows it; and how many of its
    ``<prefix>_n`` effects are larger, smaller, equivalent (TOST within the margin, Holm),
    identical or not shown (``<prefix>_n_equivalent``, ...)."""
    from icub_affordance.readings import difference_verdict

    rows = differences[differences["comparison"] == comparison]
    rows = rows[rows["measure"].map(is_hypothesis)]
    words = rows.apply(difference_verdict, axis=1).map(lambda v: WORDS.get(v, v))
    rests, levels = _rests_on(rows, ("diff", "p_holm", "p_equivalence_holm")), rows["at"].nunique()

    def effects(chosen) -> str:
        """E.g. "congruency on RMSE (fixed only) and commitment; size on ..."."""
        found: dict[str, list[str]] = {}
        for (effect, m), at in chosen.groupby(["effect", "measure"], sort=False)["at"]:
            only = f" ({CUE_LABELS.get(at.iloc[0], at.iloc[0])} only)" * (len(at) < levels)
            found.setdefault(effect, []).append(MEASURE_LABELS[m] + only)
        parts = (f"{effect} on {_listing(named, '')}" for effect, named in found.items())
        return "; ".join(parts) or "no effect"

    def claim(said: str) -> Claim | str:  # with no test behind it (all identical) no claim
        return Claim(said, rests) if rests else said

    out: dict[str, Claim | str | int] = {f"{prefix}_n": len(rows)}
    out[f"{prefix}_changes"] = claim(effects(rows[words.isin(["larger", "smaller"])]))
    for word in ("larger", "smaller", "equivalent", "identical", "not shown"):
        out[f"{prefix}_n_{word.replace(' ', '_')}"] = claim(str((words == word).sum()))
        if word in ("larger", "smaller"):
            out[f"{prefix}_{word}"] = claim(effects(rows[words == word]))
    return out


# ---- What drives the size effect -----------------------------------------------------------

#: The demonstrations' measures (icub_affordance.size_dose.GEOMETRY), in short.
GEOMETRY_SHORT = {"demo_path_length": "path length", "demo_spread": "spread"}
GEOMETRY_SHORT["demo_grip_distance"] = "grips' distance"


def trend_phrase(term) -> str:
    """Where a tested change moves the size effect (positive: towards the paper's direction)."""
    word = verdict_word(term)
    if word in ("not shown", "not testable"):
        return "by no amount its test shows"
    return ("away from" if word == "reversed" else "towards") + " the paper's direction"


def named_measures(measures) -> str:
    """The demonstrations' measures named in short, joined by "and"."""
    return _listing((f"the {GEOMETRY_SHORT[m]}" for m in measures), "none of the measures")
