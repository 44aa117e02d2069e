"""One minimum for every test over replications (icub_affordance.analysis.replicated, issue 70):
every module that tests over replications calls the one function, and below the declared minimum
each family's test has no p and reads "not assessable"."""

from __future__ import annotations

import ast

import numpy as np
import pandas as pd
import pytest
from conftest import REPO, load_config

from icub_affordance.analysis import reading_tests, replicated, size_study
from icub_affordance.outcome import Outcome

ANALYSIS = REPO / "src" / "icub_affordance" / "analysis"

#: Every module that makes a test over replications: each on the one function.
FAMILIES = (
    "paper_claims",
    "signature_tests",
    "extinction_levels",
    "name_effects",
    "reading_tests",
    "size_study",
    "distractor_tests",
)
#: The one function's own module, the statistics it is made of, and one run's tests over its
#: networks (a replication's own estimate, which the families then test over replications).
PARTS = ("replicated", "statistics", "trial_effects")
#: Tests over replications that are no mean of the replications' estimates, and so keep the
#: one minimum through ``replicated.assessable`` rather than ``over_replications``.
MINIMUM_ONLY = {
    "correct_sensitivity": "the correct-trial RMSE's mixed model, df = replications - 1"
}
#: What is left (issue 70 item 2): a test over replications not yet on the one minimum.
LEFT: dict[str, str] = {}
#: A family's use of the t distribution that is no test over replications: the unpaired
#: difference of two runs' tests over their networks (Welch df); a design's power.
NOT_OVER_REPLICATIONS = {("reading_tests", "unpaired_difference"), ("paper_claims", "power")}


def _tree(name: str) -> ast.Module:
    return ast.parse((ANALYSIS / f"{name}.py").read_text(), filename=f"{name}.py")


def _replicated_calls(tree: ast.Module) -> set[str]:
    """The functions of ``replicated`` a module calls: imported from it by name, or as
    ``replicated.<name>`` after importing the module."""
    names: dict[str, str] = {}  # local name -> replicated's
    module_alias = set()
    for node in ast.walk(tree):
        if (
            isinstance(node, ast.ImportFrom)
            and node.module == "icub_affordance.analysis.replicated"
        ):
            names |= {a.asname or a.name: a.name for a in node.names}
        if isinstance(node, ast.ImportFrom) and node.module == "icub_affordance.analysis":
            module_alias |= {a.asname or a.name for a in node.names if a.name == "replicated"}
    called = set()
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        f = node.func
        if isinstance(f, ast.Name) and f.id in names:
            called.add(names[f.id])
        if isinstance(f, ast.Attribute) and isinstance(f.value, ast.Name):
            if f.value.id in module_alias:
                called.add(f.attr)
    return called


def _t_tests(tree: ast.Module) -> set[str]:
    """The functions of a module that make a t-test themselves: call ``t_term`` or scipy's t."""
    found = set()
    for function in (n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)):
        for node in ast.walk(function):
            if not isinstance(node, ast.Call):
                continue
            f = node.func
            name = (
                f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""
            )
            if name in ("t_term", "ttest_1samp", "ttest_rel") or (
                isinstance(f, ast.Attribute) and isinstance(f.value, ast.Attribute)
                and f.value.attr == "t"  # sps.t.sf, sps.t.ppf
            ):  # fmt: skip
                found.add(function.name)
    return found


@pytest.mark.parametrize("name", FAMILIES)
def test_every_replicated_family_calls_the_one_function(name):
    """A family testing over replications makes its test with ``replicated.over_replications``
    (the minimum, the mean, the t), never a t of its own over the replications."""
    tree = _tree(name)
    assert "over_replications" in _replicated_calls(tree), name
    own = {(name, f) for f in _t_tests(tree)} - NOT_OVER_REPLICATIONS
    assert not own, f"{name} makes t-tests outside replicated.over_replications: {own}"


def test_no_other_module_makes_a_t_test_over_replications():
    """A module of analysis/ that makes a t-test and speaks of replications is a family above
    (on the one function), a part of it, or listed as left: a new one must join the rule."""
    for path in sorted(ANALYSIS.glob("*.py")):
        name = path.stem
        if name in FAMILIES or name in PARTS or name in LEFT or name in MINIMUM_ONLY:
            continue
        text = path.read_text().lower()
        made = _t_tests(_tree(name))
        assert not (made and "replication" in text), (name, made)


@pytest.mark.parametrize("name", MINIMUM_ONLY)
def test_a_test_that_is_no_mean_of_replications_keeps_the_one_minimum(name):
    assert "assessable" in _replicated_calls(_tree(name)), name


def test_assessable_needs_the_minimum_and_a_spread():
    assert [replicated.assessable(n, 5) for n in (4, 5, 6)] == [False, True, True]
    assert not replicated.assessable(1, 1)  # a t-test needs two, whatever is declared
    below = replicated.over_replications(np.array([0.1, 0.2, 0.3]), 4)
    assert np.isnan(below["p"]) and below["df"] == 0 and below["estimate"] == pytest.approx(0.2)
    assert not replicated.was_assessable(below["df"])
    at = replicated.over_replications(np.array([0.1, 0.2, 0.3]), 3)
    assert np.isfinite(at["p"]) and at["df"] == 2 and replicated.was_assessable(at["df"])


def _reading_rows(estimates, **keys) -> pd.DataFrame:
    return pd.DataFrame(
        [keys | {"seed": s, "run": f"r{s}", "estimate": e, "se": 0.01, "df": 6.0,
                 "ci_low": e - 0.02, "ci_high": e + 0.02, "p": 0.01}
         for s, e in enumerate(estimates)]
    )  # fmt: skip


@pytest.mark.parametrize(("least", "tested"), [(3, True), (4, False)])
def test_a_reading_below_the_minimum_is_not_assessable(least, tested):
    """Three replications (one undefined left out: four rows) against a minimum of 3 and 4."""
    rows = _reading_rows([0.03, 0.04, 0.05, np.nan], reading="first_step+fixed",
                         cue="first_step", goal_response="fixed", measure="rmse",
                         effect="congruency")  # fmt: skip
    row = reading_tests.summary(rows, least=least).iloc[0]
    assert row["not_estimable"] == 1 and row["diff"] == pytest.approx(0.04)
    assert np.isfinite(row["p"]) == tested
    outcome = reading_tests.direction(row)
    assert (outcome == Outcome.NOT_ASSESSABLE) != tested


@pytest.mark.parametrize(("least", "tested"), [(3, True), (4, False)])
def test_a_readings_difference_below_the_minimum_is_not_assessable(least, tested):
    rows = _reading_rows([0.03, 0.04, 0.05], comparison="goal_response", at="first_step",
                         a="first_step+grows", b="first_step+fixed", measure="rmse",
                         effect="congruency")  # fmt: skip
    row = reading_tests.differences(rows, {"rmse": 0.5}, least=least).iloc[0]
    assert np.isfinite(row["p"]) == tested and np.isfinite(row["p_equivalence"]) == tested
    assert (reading_tests.difference_verdict(row) == reading_tests.NOT_ASSESSABLE) != tested


@pytest.mark.parametrize(("least", "tested"), [(3, True), (4, False)])
def test_the_size_study_below_the_minimum_is_not_assessable(least, tested):
    """The summary, the declared tests and the motor tests, each on three replications."""
    from test_size_dose import manipulation_table, motor_trials, replications_table

    table = replications_table(0.05, noise=0.01)
    summary = size_study.summary(table, manipulation_table(table), least=least)
    varied = summary[summary["dose"] != "removed"]
    assert np.isfinite(varied["p"].to_numpy(dtype=float)).all() == tested
    assert (varied["df"] == (2 if tested else 0)).all()
    if not tested:
        assert {reading_tests.direction(r) for _, r in varied.iterrows()} == {
            Outcome.NOT_ASSESSABLE
        }
    one = size_study.one_sample(np.array([0.01, 0.02, 0.04, np.nan]), least)
    assert one["left_out"] == 1 and np.isfinite(one["p"]) == tested
    motor = size_study.motor_tests(motor_trials([0.0]), least=least + 1)  # four replications
    assert np.isfinite(motor["p"].to_numpy(dtype=float)).all() == tested


def test_the_words_below_their_minimum_are_not_assessable():
    """The words study's declared tests on ten replications against a minimum of eleven."""
    from test_name_effects import estimates_of

    declaration = load_config()["words"]
    estimates = estimates_of(lambda form, effect, rng: 0.03 + rng.normal(0, 0.002, 10))
    from icub_affordance.analysis.name_effects import word_tests

    table = word_tests(estimates, declaration | {"min_replications": 11})
    assert table["p"].isna().all()
    assert set(table["direction"]) == {Outcome.NOT_ASSESSABLE}
    assert set(word_tests(estimates, declaration)["direction"]) != {Outcome.NOT_ASSESSABLE}
