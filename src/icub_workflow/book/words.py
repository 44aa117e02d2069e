"""Every verdict word the book uses, and the threshold the words read: the one place that says
what "confirmed", "reversed", "not shown", "equivalent" and "not assessable" mean (the book's
five verdict words, ``VERDICTS``; the front page defines them once). The science package
returns numbers, flags and ``Outcome`` codes (``icub_affordance.outcome``); this module
puts the words on them, for the pages and for the result tables that hold words (the claims'
and the signatures' summaries)."""

from __future__ import annotations

from collections.abc import Mapping

from icub_affordance.analysis.decide import decide, significant
from icub_affordance.analysis.verdicts import ALPHA
from icub_affordance.outcome import Outcome

#: The verdict words themselves, each spelled once: the rest of the book layer names them here.
#: Confirmed: a test finds its difference (adjusted p below ``ALPHA``) in the direction it names
#: (the paper's, people's, or for a difference nobody predicts, the sign shown beside it);
#: reversed: found, the other way; not shown: not found, which is not "no difference"; equivalent:
#: a difference shown within a margin declared before its result; not assessable: no test could
#: be made (too few replications, no variation, a question the model cannot pose).
CONFIRMED, REVERSED, NOT_SHOWN = "confirmed", "reversed", "not shown"
EQUIVALENT, NOT_ASSESSABLE = "equivalent", "not assessable"
VERDICTS = (CONFIRMED, REVERSED, NOT_SHOWN, EQUIVALENT, NOT_ASSESSABLE)
#: The words the book once used for these, each now one of ``VERDICTS`` (a test keeps them out).
RETIRED = ("reproduced", "shown, opposite", "opposite", "not known", "falls short",
           "not testable", "not estimable", "no variation", "carries part of it", "moves it",
           "not shown equivalent")  # fmt: skip
#: Older names of the same words, kept for the code that reads them.
REPRODUCED = SHOWN = CONFIRMED
NOT_TESTABLE = NOT_ASSESSABLE
#: The robot rows of the scorecard: the bar (``verdicts.GRASPS``) against the 95% interval of
#: the share held: above it, confirmed; wholly below it, found the other way.
BAR_WORDS = {"above": CONFIRMED, "includes": NOT_SHOWN, "below": REVERSED}

# -- a test's p against ALPHA, on the side of its estimate -------------------------------------


def verdict_word(term: Mapping, alpha: float = ALPHA) -> str:
    """A test in the paper's direction (a positive estimate) is "confirmed", against it
    "reversed", where its p adjusted within its family is below ``alpha``; else "not shown"
    (which is not "no difference") or, with no p, "not assessable"."""
    return CLAIM_OUTCOME_WORDS[decide(term["estimate"], term.get("p_holm", term["p"]), alpha)]


def shown_word(term: Mapping, alpha: float = ALPHA) -> str:
    """A difference the paper does not predict: "confirmed" or "not shown"; its sign is beside
    it."""
    word = verdict_word(term, alpha)
    return CONFIRMED if word in (CONFIRMED, REVERSED) else word


def claim_verdict(term: Mapping, outcome: str, effect: str) -> str:
    """The paper's two effects, on its measure and on correct trials, are "confirmed" or not;
    errors are read in the effect's direction (more errors where slower), the required grip,
    which has none, by its sign."""
    if effect == "congruency:size":
        return shown_word(term)
    return verdict_word(term)


def robot_word(paper_direction: bool | None, significant: bool) -> str:
    """A robot effect's verdict (``verdicts.robot_effect_verdict``'s flags; None: no test)."""
    if paper_direction is None:
        return NOT_ASSESSABLE
    if not significant:
        return NOT_SHOWN
    return CONFIRMED if paper_direction else REVERSED


def below_alpha(p: float, said: str, otherwise: str = "not shown") -> str:
    """``said`` where ``p`` is below ALPHA, else ``otherwise``."""
    return said if significant(p) else otherwise


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
EQUIVALENCE_WORDS = {"paper": EQUIVALENT, "none": NOT_SHOWN,
                     "not assessable": NOT_ASSESSABLE}  # fmt: skip
#: The words study's reactivation test (``name_effects.reactivation_tests``), for each code.
REACTIVATION_WORDS = {
    "paper": "nearer its own object's image state than the others'",
    "reversed": "farther from its own object's image state than from the others'",
    "none": "not shown nearer its own object's image state than the others'",
    "not assessable": NOT_ASSESSABLE,
}
#: The same words by ``Outcome`` (the forest plot's legend).
CLAIM_OUTCOME_WORDS = {o: CLAIM_WORDS[code] for o, code in DIRECTION_CODES.items()}
#: A confirmatory test's direction and the exploration's verdict word that says the same.
SAME_WORD = {"paper": CONFIRMED, "reversed": REVERSED, "none": NOT_SHOWN}


def direction_codes(outcomes) -> list[str]:
    """A table's ``direction`` column (``Outcome`` codes) as its file writes it."""
    return [DIRECTION_CODES[Outcome(o)] for o in outcomes]


# -- the readings (icub_affordance.analysis.reading_tests.direction and difference_verdict) --------

#: The words of ``reading_tests.direction``'s ``Outcome``.
READING_WORDS = {Outcome.PAPER: CONFIRMED, Outcome.AGAINST: REVERSED,
                 Outcome.NONE: NOT_SHOWN, Outcome.CONSTANT: NOT_ASSESSABLE,
                 Outcome.NOT_ASSESSABLE: NOT_ASSESSABLE}  # fmt: skip
#: The words of ``reading_tests.difference_verdict``, where they differ from its code: a
#: confirmed difference between two readings, which nobody predicts, is said by its sign.
DIFFERENCE_WORDS = {"none": NOT_SHOWN, "a > b": "larger", "a < b": "smaller",
                    "not_assessable": NOT_ASSESSABLE}  # fmt: skip
#: An equivalence whose margin was set after its measure's results were read
#: (config ``readings.margin_declared``): said so wherever it appears, never counted with the
#: equivalences whose margin came first.
AFTER_RESULTS = "equivalent, margin set after results"

# -- the human signatures (icub_affordance.analysis.signature_tests.verdict) -----------------------

#: A signature's verdict word for each ``Outcome``, in the order the page counts them.
SIGNATURE_WORDS = {Outcome.PAPER: CONFIRMED, Outcome.NONE: NOT_SHOWN, Outcome.AGAINST: REVERSED,
                   Outcome.NOT_ASSESSABLE: NOT_ASSESSABLE,
                   Outcome.NOT_TESTED: NOT_ASSESSABLE}  # fmt: skip


def signature_words(codes) -> list:
    """A signatures table's ``verdict`` column (``Outcome`` codes, "" for a row with no verdict)
    as its file writes it."""
    return [SIGNATURE_WORDS[Outcome(c)] if c != "" else "" for c in codes]


# -- the size study and the sweep ------------------------------------------------------------

#: The size study's declared tests' verdict words, by test, for a verdict_word: every part and
#: the dose contrast say "confirmed" where they move the size effect the paper's way.
SIZE_PART_WORDS: dict[str, dict[str, str]] = {"size": {}, "grip_distance": {}, "dose": {}}
#: A shown part's direction, from its verdict word.
PART_DIRECTIONS = {CONFIRMED: "the paper's way", REVERSED: "against the paper"}
#: An effect over the sweep's replications by its 95% interval (verdicts.interval_direction).
SWEEP_DIRECTIONS = {"paper": "paper's way", "against": "against", "unclear": "includes 0",
                    "single": "one replication"}  # fmt: skip
