"""Every verdict word the book uses, and the threshold the words read: the one place that says
what "reproduced", "confirmed", "reversed", "shown", "opposite", "not shown" and "not assessable"
mean. The science package returns numbers, flags and ``Outcome`` codes
(``icub_affordance.outcome``); this module puts the words on them, for the pages and for the
result tables that hold words (the claims' and the signatures' summaries)."""

from __future__ import annotations

import math
from collections.abc import Mapping

from icub_affordance.analysis.verdicts import ALPHA
from icub_affordance.outcome import Outcome

#: The verdict words themselves, each spelled once: the rest of the book layer names them here.
REPRODUCED, CONFIRMED, REVERSED = "reproduced", "confirmed", "reversed"
SHOWN, NOT_SHOWN, OPPOSITE = "shown", "not shown", "opposite"
NOT_ASSESSABLE, NOT_TESTABLE = "not assessable", "not testable"
#: The robot rows of the scorecard: the bar (``verdicts.GRASPS``) against the 95% interval of
#: the share held.
BAR_WORDS = {"above": SHOWN, "includes": "not known", "below": "falls short"}

# -- a test's p against ALPHA, on the side of its estimate -------------------------------------


def verdict_word(term: Mapping, alpha: float = ALPHA) -> str:
    """A test in the paper's direction (a positive estimate) is "reproduced", against it
    "reversed", where its p adjusted within its family is below ``alpha``; else "not shown"
    (which is not "no difference") or, with no p, "not testable"."""
    p = term.get("p_holm", term["p"])
    if not math.isfinite(p):
        return "not testable"
    if p >= alpha:
        return "not shown"
    return "reproduced" if term["estimate"] > 0 else "reversed"


def shown_word(term: Mapping, alpha: float = ALPHA) -> str:
    """A difference the paper does not predict: "shown" or "not shown"; its sign is beside it."""
    word = verdict_word(term, alpha)
    return "shown" if word in ("reproduced", "reversed") else word


def claim_verdict(term: Mapping, outcome: str, effect: str) -> str:
    """The paper's two effects, on its measure and on correct trials, are "reproduced" or not; it
    claims nothing of errors ("shown", "shown, opposite") or the required grip ("shown")."""
    word = verdict_word(term)
    if effect == "congruency:size":
        return shown_word(term)
    if outcome == "errors":
        return {"reproduced": "shown", "reversed": "shown, opposite"}.get(word, word)
    return word


def robot_word(paper_direction: bool | None, significant: bool) -> str:
    """A robot effect's verdict (``verdicts.robot_effect_verdict``'s flags; None: no test)."""
    if paper_direction is None:
        return "not estimable"
    if not significant:
        return "not shown"
    return "reproduced" if paper_direction else "reversed"


def below_alpha(p: float, said: str, otherwise: str = "not shown") -> str:
    """``said`` where ``p`` is below ALPHA, else ``otherwise``."""
    return said if p < ALPHA else otherwise


# -- the declared tests' directions (icub_affordance.analysis.paper_claims.direction) --------------

#: The code a result table (``claims/summary.csv``, ``embodied/contact_time.csv``) writes for
#: each ``Outcome`` of a declared test.
DIRECTION_CODES = {Outcome.PAPER: "paper", Outcome.AGAINST: "reversed", Outcome.NONE: "none",
                   Outcome.NOT_ASSESSABLE: "not assessable"}  # fmt: skip
#: A declared test's ``Outcome`` from the code its table holds.
DIRECTION_OUTCOMES = {code: outcome for outcome, code in DIRECTION_CODES.items()}
#: A declared test's verdict word for each code of its table (``DIRECTION_CODES``).
CLAIM_WORDS = {"paper": "confirmed", "reversed": "reversed", "none": "not shown",
               "not assessable": "not assessable"}  # fmt: skip
#: The words study's equivalence test (``name_effects.word_tests``), for each code of its table:
#: ``paper`` is the name's effect shown within the margin of the image's.
EQUIVALENCE_WORDS = {"paper": "equivalent", "none": "not shown equivalent",
                     "not assessable": "not assessable"}  # fmt: skip
#: The words study's reactivation test (``name_effects.reactivation_tests``), for each code.
REACTIVATION_WORDS = {
    "paper": "nearer its own object's image state than the others'",
    "reversed": "farther from its own object's image state than from the others'",
    "none": "not shown nearer its own object's image state than the others'",
    "not assessable": "not assessable",
}
#: The same words by ``Outcome`` (the forest plot's legend).
CLAIM_OUTCOME_WORDS = {o: CLAIM_WORDS[code] for o, code in DIRECTION_CODES.items()}
#: A confirmatory test's direction and the exploration's verdict word that says the same.
SAME_WORD = {"paper": "reproduced", "reversed": "reversed", "none": "not shown"}


def direction_codes(outcomes) -> list[str]:
    """A table's ``direction`` column (``Outcome`` codes) as its file writes it."""
    return [DIRECTION_CODES[Outcome(o)] for o in outcomes]


# -- the readings (icub_affordance.analysis.reading_tests.direction and difference_verdict) --------

#: The words of ``reading_tests.direction``'s ``Outcome``.
READING_WORDS = {Outcome.PAPER: "reproduced", Outcome.AGAINST: "reversed",
                 Outcome.NONE: "not shown", Outcome.CONSTANT: "no variation",
                 Outcome.NOT_ASSESSABLE: "not assessable"}  # fmt: skip
#: The words of ``reading_tests.difference_verdict``, where they differ from its code.
DIFFERENCE_WORDS = {"none": "not shown", "a > b": "larger", "a < b": "smaller",
                    "not_assessable": NOT_ASSESSABLE}  # fmt: skip
#: An equivalence whose margin was set after its measure's results were read
#: (config ``readings.margin_declared``): said so wherever it appears, never counted with the
#: equivalences whose margin came first.
AFTER_RESULTS = "equivalent, margin set after results"

# -- the human signatures (icub_affordance.analysis.signature_tests.verdict) -----------------------

#: A signature's verdict word for each ``Outcome``, in the order the page counts them.
SIGNATURE_WORDS = {Outcome.PAPER: "shown", Outcome.NONE: "not shown", Outcome.AGAINST: "opposite",
                   Outcome.NOT_ASSESSABLE: "not assessable",
                   Outcome.NOT_TESTED: "not testable here"}  # fmt: skip


def signature_words(codes) -> list:
    """A signatures table's ``verdict`` column (``Outcome`` codes, "" for a row with no verdict)
    as its file writes it."""
    return [SIGNATURE_WORDS[Outcome(c)] if c != "" else "" for c in codes]


# -- the size study and the sweep ------------------------------------------------------------

#: The size study's declared tests' verdict words, by test, for a verdict_word: the size part
#: against the paper's direction; the grips' distance's part and the dose contrast as what they
#: move the natural run's size effect by.
SIZE_PART_WORDS = {
    "size": {},
    "grip_distance": {"reproduced": "carries part of it, the paper's way",
                      "reversed": "carries part of it, against the paper"},
    "dose": {"reproduced": "moves it the paper's way", "reversed": "moves it against the paper"},
}  # fmt: skip
#: A shown part's direction, from its verdict word.
PART_DIRECTIONS = {"reproduced": "the paper's way", "reversed": "against the paper"}
#: An effect over the sweep's replications by its 95% interval (verdicts.interval_direction).
SWEEP_DIRECTIONS = {"paper": "paper's way", "against": "against", "unclear": "includes 0",
                    "single": "one replication"}  # fmt: skip
