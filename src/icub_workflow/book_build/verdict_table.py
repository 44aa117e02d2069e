"""Every test the book's sentences may rest on, by name, with its verdict code: the table the
``finding`` directive (``pinned``) checks each sentence's assumptions against.

A test's name is its family's short name and its keys, joined by ``/``; its code is the one its
own table holds (``claims/summary.csv``'s ``direction``), or for a table without one, the
declared tests' rule applied to its estimate and Holm p (``paper_claims.direction``), so one
function decides both. Codes: ``paper``, ``reversed``, ``none``, ``not assessable``
(``book.words.DIRECTION_CODES``).
"""

from __future__ import annotations

import pandas as pd

from icub_affordance.analysis.paper_claims import direction
from icub_affordance.analysis.verdicts import ALPHA
from icub_affordance.outcome import Outcome
from icub_workflow.book.words import DIRECTION_CODES

COLUMNS = ["test", "family", "code"]


def verdict_rows(
    claims: pd.DataFrame, correct_sensitivity: pd.DataFrame, congruent_size: pd.DataFrame
) -> pd.DataFrame:
    """The declared tests of the paper's claims (``claims/{cue}/{mode}/{measure}/{effect}``),
    the correct-trial RMSE over every replication (``correct_all/{cue}/{mode}/{effect}``) and
    size among congruent trials, added after the results
    (``congruent_size/{cue}/{mode}``, its ``Outcome`` codes)."""
    rows = [
        {
            "test": f"claims/{r['cue']}/{r['mode']}/{r['measure']}/{r['effect']}",
            "family": r["family"],
            "code": r["direction"],
        }
        for r in claims.to_dict("records")
    ]
    rows += [
        {
            "test": f"correct_all/{r['cue']}/{r['mode']}/{r['effect']}",
            "family": r["family"],
            "code": DIRECTION_CODES[direction(r["estimate"], r["p_holm"], ALPHA)],
        }
        for r in correct_sensitivity.to_dict("records")
    ]
    rows += [
        {
            "test": f"congruent_size/{r['cue']}/{r['mode']}",
            "family": r["family"],
            "code": DIRECTION_CODES[Outcome(int(r["direction"]))],
        }
        for r in congruent_size.to_dict("records")
    ]
    table = pd.DataFrame(rows, columns=COLUMNS)
    doubled = table["test"][table["test"].duplicated()].tolist()
    if doubled:
        raise ValueError(f"tests named twice: {doubled}")
    return table
