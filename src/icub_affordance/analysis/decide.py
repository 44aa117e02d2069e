"""The one place a p value meets alpha: every verdict of every study is decided here.

A study hands over its estimate, its (adjusted) p and, where it declares one, the minimum number
of replications a test needs; ``decide`` returns the ``Outcome`` code and the book puts the word
on it (``icub_workflow.book.words``). Deciding in one place keeps "significant" meaning the same
thing everywhere (a finite p strictly below alpha), and a test (tests/test_decide.py) keeps any
other module from comparing a p with alpha itself.
"""

from __future__ import annotations

from typing import TypeVar

import numpy as np

from icub_affordance.analysis.verdicts import ALPHA
from icub_affordance.outcome import Outcome

P = TypeVar("P")


def significant(p: P, alpha: float = ALPHA) -> P:
    """Whether ``p`` is below ``alpha``: a number, an array or a column alike (NaN: never).

    Returns what ``p < alpha`` returns for that type, so a column gives a boolean column."""
    return p < alpha


def decide(
    estimate: float,
    p: float,
    alpha: float = ALPHA,
    *,
    expected: int = 1,
    replications: int | None = None,
    minimum: int | None = None,
) -> Outcome:
    """A test's ``Outcome`` against the direction it expects (``expected``: +1 a positive
    estimate, -1 a negative one): ``PAPER`` or ``AGAINST`` where ``p`` is below ``alpha``, on the
    side of ``estimate`` (an estimate of exactly 0 counts as against); ``NONE`` where it is not
    (neither shown nor excluded); ``NOT_ASSESSABLE`` with no p, or with fewer ``replications``
    than the declared ``minimum``."""
    if minimum is not None and (replications is None or replications < minimum):
        return Outcome.NOT_ASSESSABLE
    if not np.isfinite(p):
        return Outcome.NOT_ASSESSABLE
    if not significant(p, alpha):
        return Outcome.NONE
    return Outcome.PAPER if np.sign(estimate) == np.sign(expected) else Outcome.AGAINST


def decide_equivalence(p: float, alpha: float = ALPHA) -> Outcome:
    """An equivalence test's (TOST's) ``Outcome``: ``PAPER`` (the difference shown inside its
    declared margin) where ``p`` is below ``alpha``, else ``NONE``; ``NOT_ASSESSABLE`` with no
    p."""
    if not np.isfinite(p):
        return Outcome.NOT_ASSESSABLE
    return Outcome.PAPER if significant(p, alpha) else Outcome.NONE
