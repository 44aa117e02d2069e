"""Every test the book's sentences may rest on, by name, with its verdict code: the table the
``finding`` directive (``pinned``) checks each sentence's assumptions against.

A test's name is its family's short name and its keys, joined by ``/``; its code is the one its
own table holds (``claims/summary.csv``'s ``direction``), or for a table without one, the
declared tests' rule applied to its estimate and Holm p (``paper_claims.direction``), so one
function decides both. Codes: ``paper``, ``reversed``, ``none``, ``not assessable``
(``book.words.DIRECTION_CODES``).
"""

from __future__ import annotations

from collections.abc import Mapping

import pandas as pd

from icub_affordance.analysis import confirmation as confirmation_science
from icub_affordance.analysis import reading_tests
from icub_affordance.analysis.paper_claims import direction
from icub_affordance.analysis.verdicts import ALPHA, GRASPS
from icub_affordance.outcome import Outcome
from icub_workflow.book.words import DIRECTION_CODES, SIGNATURE_WORDS

COLUMNS = ["test", "family", "code"]
#: A signature's code from the word its table holds (``words.SIGNATURE_WORDS``).
SIGNATURE_CODES = {word: DIRECTION_CODES[o] for o, word in SIGNATURE_WORDS.items()
                   if o in DIRECTION_CODES}  # fmt: skip
#: The robot's share held against the bar (``confirmation.bar_verdict``), as a code.
BAR_CODES = {"above": "paper", "includes": "none", "below": "reversed"}


def _code(estimate: float, p_holm: float) -> str:
    """The declared tests' rule, for a table that holds numbers only."""
    return DIRECTION_CODES[direction(estimate, p_holm, ALPHA)]


def _dose(dose: object) -> str:
    """A dose as a test's name holds it: ``0``, ``0.6``, ``0.6-0`` (a contrast)."""
    return f"{dose:g}" if isinstance(dose, float | int) else str(dose).replace(" ", "")


def verdict_rows(
    claims: pd.DataFrame,
    correct_sensitivity: pd.DataFrame,
    congruent_size: pd.DataFrame,
    studies: Mapping[str, object] | None = None,
) -> pd.DataFrame:
    """The declared tests of the paper's claims (``claims/{cue}/{mode}/{measure}/{effect}``),
    the correct-trial RMSE over every replication (``correct_all/{cue}/{mode}/{effect}``) and
    size among congruent trials, added after the results
    (``congruent_size/{cue}/{mode}``, its ``Outcome`` codes); with ``studies``, the other
    chapters' tests too (``study_rows``)."""
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
            "code": _code(r["estimate"], r["p_holm"]),
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
    rows += study_rows(studies or {})
    table = pd.DataFrame(rows, columns=COLUMNS)
    doubled = table["test"][table["test"].duplicated()].tolist()
    if doubled:
        raise ValueError(f"tests named twice: {doubled}")
    return table


def study_rows(studies: Mapping[str, object]) -> list[dict]:
    """The chapters' own tests, each where ``studies`` has its table: ``runs`` (cue timing ->
    that run's ``eval/anova.json``), ``readings``, ``size``,
    ``size_metrics`` (the second metric's, added after results), ``signatures``,
    ``signature_errors``, ``words``, ``contact_time``, ``confirmation``, ``distractor`` (its
    summary.csv: a code from its ``direction``, positive the grip compatible with the object
    faster, whatever people's direction for the effect)."""
    rows: list[dict] = []
    for cue, anova in (studies.get("runs") or {}).items():
        rows += run_rows(cue, anova)
    by_p = {  # a table read by its p (Holm within its family), on the estimate's side
        "size": lambda r: f"size/{r['test']}/{_dose(r['dose'])}/{r['cue']}",
        "size_metrics": lambda r: (
            f"size_metric/{r['metric']}/{r['test']}/{_dose(r['dose'])}/{r['cue']}"
        ),
    }
    if "readings" in studies:
        readings = studies["readings"]
        rows += _named(
            readings[readings["measure"].map(reading_tests.is_hypothesis)],
            lambda r: f"readings/{r['cue']}/{r['goal_response']}/{r['measure']}/{r['effect']}",
            lambda r: DIRECTION_CODES.get(reading_tests.direction(r), "not assessable"),
        )
    for study, test in by_p.items():
        if study in studies:
            rows += _named(studies[study], test, lambda r: _code(r["estimate"], r["p_holm"]))
    if "signatures" in studies:
        table = studies["signatures"]
        verdicts = table[table["verdict"].notna() & (table["verdict"] != "")]
        rows += _named(verdicts, lambda r: f"signatures/{r['signature']}",
                       lambda r: SIGNATURE_CODES[r["verdict"]])  # fmt: skip
        rows += _named(table[table["condition"].str.startswith("in view, all")],
                       lambda r: "signatures/in_view",
                       lambda r: _code(r["estimate"], r["p_adjusted"]))  # fmt: skip
    if "signature_errors" in studies:
        rows += _named(studies["signature_errors"],
                       lambda r: f"signature_errors/{r['condition']}/{r['k']}",
                       lambda r: _code(r["estimate"], r["p_adjusted"]))  # fmt: skip
    if "words" in studies:
        rows += _named(studies["words"],
                       lambda r: f"words/{r['cue']}/{r['mode']}/{r['measure']}/{r['test']}",
                       lambda r: r["direction"])  # fmt: skip
    if "contact_time" in studies:
        rows += _named(studies["contact_time"], lambda r: f"robot/contact_time/{r['effect']}",
                       lambda r: r["direction"])  # fmt: skip
    if "confirmation" in studies:
        table = studies["confirmation"]
        rows += [
            {
                "test": "robot/held_vs_bar",
                "family": "declared: the robot grasps",
                "code": BAR_CODES[
                    confirmation_science.bar_verdict(r["ci_low"], r["ci_high"], GRASPS)
                ],
            }
            for r in table[table["seed_set"] == "confirmation"].head(1).to_dict("records")
        ]
    if "distractor" in studies:
        rows += _named(studies["distractor"],
                       lambda r: f"distractor/{float(r['lam'])}/{r['cue']}/{r['mode']}/"
                       f"{r['measure']}/{r['effect']}",
                       lambda r: DIRECTION_CODES[Outcome(int(r["direction"]))])  # fmt: skip
    return rows


def _named(table: pd.DataFrame, test, code) -> list[dict]:
    """A table's rows as tests: named by ``test(row)``, in their family, coded ``code(row)``."""
    return [{"test": test(r), "family": r["family"], "code": code(r)}
            for r in table.to_dict("records")]  # fmt: skip


def run_rows(cue: str, anova: Mapping) -> list[dict]:
    """One run's congruency and size tests (its ``eval/anova.json``), each test mode on the RMSE
    of all trials, the wrong-grip rate and the correct trials' RMSE
    (``run/{cue}/{mode}/{measure}/{effect}``)."""
    sources = {"rmse": lambda mode: anova["contrasts"][mode],
               "errors": lambda mode: anova[mode]["errors"],
               "rmse_correct": lambda mode: anova[mode]["correct_rt"]}  # fmt: skip
    return [
        {
            "test": f"run/{cue}/{mode}/{measure}/{effect}",
            "family": t["family"],
            "code": _code(t["estimate"], t["p_holm"]),
        }
        for mode in ("closed_loop", "teacher_forced")
        for measure, tests in ((m, source(mode)) for m, source in sources.items())
        for effect, t in tests.items()
        if effect in ("congruency", "size")
    ]
