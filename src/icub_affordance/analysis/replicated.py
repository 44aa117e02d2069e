"""One rule for every test over replications (the paper's claims, the human signatures, the
words, the readings and their differences, the size study): a test is made only on at least the
declared minimum of replications with an estimate (config ``confirmation.min_replications``; the
words study's own ``words.min_replications``); with fewer it has no p, df 0, and its verdict code
is "not assessable" (``Outcome.NOT_ASSESSABLE``). Every module of this package that tests over
replications calls ``over_replications`` (tests/test_replicated.py checks it).

Why one rule: a replication whose estimate is undefined is left out and counted, and with only a
few left a t-test over them (df 1 on two replications) says next to nothing, whichever family it
sits in; a minimum declared once keeps every family's "not shown" from resting on such a test."""

from __future__ import annotations

import numpy as np

from icub_affordance.analysis.statistics import t_term


def assessable(estimates: int, least: int) -> bool:
    """Whether ``estimates`` replications with an estimate are enough for a test: at least the
    declared minimum ``least``, and never fewer than two (a t-test needs a spread)."""
    return estimates >= max(int(least), 2)


def over_replications(defined: np.ndarray, least: int) -> dict[str, float]:
    """The mean of the replications' defined estimates with its t-test (df = n - 1): the test
    only where ``assessable``, else the mean alone (NaN se, t, p; df 0)."""
    defined = np.asarray(defined, dtype=float)
    n = len(defined)
    if assessable(n, least):
        return t_term(defined.mean(), defined.std(ddof=1) / np.sqrt(n), n - 1)
    return t_term(defined.mean() if n else np.nan, np.nan, 0.0)


def was_assessable(df: float) -> bool:
    """Whether a test ``over_replications`` made had its minimum, from its df: n - 1 >= 1 where
    it had, 0 where it had not (NaN, a term with no test at all, reads not assessable too)."""
    return bool(df > 0)
