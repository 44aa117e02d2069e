"""One decision, one place (issue 72): every verdict comes from ``analysis.decide``, and no other
module compares a p value with alpha. The comparisons not yet routed are listed in ``LEFT``, which
can only shrink: a new comparison fails, and so does an entry that no longer has one."""

from __future__ import annotations

import ast
import re
from collections import Counter
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from icub_affordance.analysis.decide import decide, decide_equivalence, significant
from icub_affordance.analysis.verdicts import ALPHA
from icub_affordance.outcome import Outcome

SRC = Path(__file__).resolve().parents[1] / "src"
DECIDE = "icub_affordance/analysis/decide.py"
#: A name that holds a p value: p, p_holm, p_adjusted, row["p_difference"], verdict_p(row), ...
P_NAME = re.compile(r"(^|_)p(_|$)")

#: Comparisons of a p with alpha not yet routed through ``decide``, by file and function, with
#: how many each holds. Why each is left: changing these modules reruns every job that imports
#: them, training included (verdicts, reading_tests and signature_tests are imported by `train`
#: and the other model jobs), so routing them waits for a build that reruns those anyway.
LEFT = {
    # Verdict flags (paper_direction, significant): to become Outcome codes from decide.
    ("icub_affordance/analysis/verdicts.py", "verdict"): 1,
    ("icub_affordance/analysis/verdicts.py", "robot_effect_verdict"): 2,
    # The readings: Holm's or the raw p by row (verdict_p); "a > b" / "equivalent" strings.
    ("icub_affordance/analysis/reading_tests.py", "summary"): 1,
    ("icub_affordance/analysis/reading_tests.py", "direction"): 1,
    ("icub_affordance/analysis/reading_tests.py", "difference_verdict"): 2,
    # The signatures: a slope with an expected sign, an equivalence that a shown difference
    # reverses (a NaN p is NONE there, not NOT_ASSESSABLE as decide_equivalence says).
    ("icub_affordance/analysis/signature_tests.py", "verdict"): 3,
    ("icub_affordance/analysis/signature_tests.py", "in_view_established"): 1,
}


def _names(node: ast.AST):
    """Every identifier, attribute and string constant in ``node`` (a subscript's key too)."""
    for n in ast.walk(node):
        if isinstance(n, ast.Name):
            yield n.id
        elif isinstance(n, ast.Attribute):
            yield n.attr
        elif isinstance(n, ast.Constant) and isinstance(n.value, str):
            yield n.value


def _is_p(node: ast.AST) -> bool:
    return any(P_NAME.search(name) for name in _names(node))


def _is_alpha(node: ast.AST) -> bool:
    """A name with "alpha" in it (ALPHA, alpha, science.ALPHA), or alpha's value written out."""
    literal = isinstance(node, ast.Constant) and node.value == ALPHA
    return literal or any("alpha" in name.lower() for name in _names(node))


def p_alpha_comparisons(root: Path = SRC) -> Counter:
    """How many comparisons of a p with alpha each (file, function) of ``root`` holds."""
    found: Counter = Counter()

    def visit(node: ast.AST, path: str, where: str) -> None:
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
            where = f"{where}.{node.name}" if where else node.name
        if isinstance(node, ast.Compare):
            sides = [node.left, *node.comparators]
            for a, b in zip(sides, sides[1:], strict=False):
                if (_is_p(a) and _is_alpha(b)) or (_is_alpha(a) and _is_p(b)):
                    found[(path, where or "<module>")] += 1
        for child in ast.iter_child_nodes(node):
            visit(child, path, where)

    for file in sorted(root.rglob("*.py")):
        path = file.relative_to(root).as_posix()
        if path != DECIDE:
            visit(ast.parse(file.read_text()), path, "")
    return found


def test_no_module_but_decide_compares_p_with_alpha():
    found = p_alpha_comparisons()
    new = {k: n for k, n in found.items() if n > LEFT.get(k, 0)}
    assert not new, f"compare p with alpha through analysis.decide, not here: {new}"
    routed = {k: n for k, n in LEFT.items() if found.get(k, 0) < n}
    assert not routed, f"routed through decide: take these out of LEFT (or lower them): {routed}"


def test_the_scan_finds_a_comparison(tmp_path):
    (tmp_path / "m.py").write_text(
        "def f(row, alpha):\n    return row['p_holm'] < alpha\n"
        "def g(p):\n    return p >= science.ALPHA\n"
        "def h(p, power):\n    return power > 0.8 and p < 0.05\n"
        "def ok(alpha):\n    return 0 < alpha < 1\n"
    )
    assert p_alpha_comparisons(tmp_path) == {("m.py", "f"): 1, ("m.py", "g"): 1, ("m.py", "h"): 1}


# ---- decide's outcomes -----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("estimate", "p", "outcome"),
    [
        (0.3, 0.01, Outcome.PAPER),
        (-0.3, 0.01, Outcome.AGAINST),
        (0.0, 0.01, Outcome.AGAINST),  # significant with no sign: not the paper's direction
        (0.3, ALPHA, Outcome.NONE),  # alpha itself is not below alpha
        (-0.3, 0.5, Outcome.NONE),
        (0.3, np.nan, Outcome.NOT_ASSESSABLE),
        (0.3, np.inf, Outcome.NOT_ASSESSABLE),
    ],
)
def test_decide(estimate, p, outcome):
    assert decide(estimate, p) is outcome


def test_decide_expected_negative_and_its_own_alpha():
    assert decide(-0.3, 0.01, expected=-1) is Outcome.PAPER
    assert decide(0.3, 0.01, expected=-1) is Outcome.AGAINST
    assert decide(0.3, 0.03, 0.01) is Outcome.NONE


def test_decide_below_the_minimum_is_not_assessable():
    assert decide(0.3, 0.01, replications=2, minimum=3) is Outcome.NOT_ASSESSABLE
    assert decide(0.3, 0.01, minimum=3) is Outcome.NOT_ASSESSABLE  # no count: not shown enough
    assert decide(0.3, 0.01, replications=3, minimum=3) is Outcome.PAPER


def test_decide_equivalence():
    assert decide_equivalence(0.01) is Outcome.PAPER
    assert decide_equivalence(0.2) is Outcome.NONE
    assert decide_equivalence(np.nan) is Outcome.NOT_ASSESSABLE


def test_significant_takes_numbers_and_columns():
    assert significant(0.01) and not significant(ALPHA) and not significant(np.nan)
    column = significant(pd.Series([0.01, 0.2, np.nan]))
    assert column.tolist() == [True, False, False]
