"""What a test shows, as a code: the science package says it with these, never in words.

The words the book puts on each code, and the threshold they read, are the book's
(``icub_workflow.book.words``); a result table that holds words gets them there, as it is written.
"""

from __future__ import annotations

from enum import IntEnum


class Outcome(IntEnum):
    """A test's outcome against the direction it expects (the paper's, or a signature's)."""

    PAPER = 1  #: significant in the expected direction
    AGAINST = -1  #: significant against it
    NONE = 0  #: not significant: neither shown nor excluded
    NOT_ASSESSABLE = 2  #: a test whose premise or replications are lacking
    NOT_TESTED = 3  #: no test could be made (no estimate, no data)
    CONSTANT = 4  #: the measure did not vary at all
