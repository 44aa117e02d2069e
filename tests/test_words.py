"""The science package returns numbers, flags and ``Outcome`` codes; the book's words, and the
threshold they read, are one module's (``icub_workflow.book.words``). Both read from the source,
so that a verdict word put back into ``icub_affordance`` (returned, or held in a constant) or an
import of the book layer fails here."""

from __future__ import annotations

import ast

import pytest
from conftest import REPO

from icub_affordance.outcome import Outcome
from icub_workflow.book import words

SCIENCE = REPO / "src" / "icub_affordance"
#: Every verdict word the book uses (issue 58), and the phrases it builds from them.
VERDICT_WORDS = {
    "reproduced", "confirmed", "reversed", "shown", "not shown", "opposite", "not assessable",
    "not testable", "not testable here", "shown, opposite", "same direction",
}  # fmt: skip


def science_modules() -> list:
    return sorted(SCIENCE.glob("*.py"))


def docstrings(tree: ast.AST) -> set[int]:
    """The ids of the docstring nodes of a module and of its classes and functions."""
    out = set()
    for node in ast.walk(tree):
        kinds = (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)
        if isinstance(node, kinds) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                out.add(id(first.value))
    return out


def verdict_strings(source: str) -> list[tuple[int, str]]:
    """Each string constant in ``source`` outside its docstrings that is a verdict word: returned,
    compared with, or held in a constant alike, with its line."""
    tree = ast.parse(source)
    skip = docstrings(tree)
    return [
        (node.lineno, node.value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant) and isinstance(node.value, str)
        and id(node) not in skip and node.value.strip().lower() in VERDICT_WORDS
    ]  # fmt: skip


def book_imports(source: str) -> list[str]:
    """The modules of the workflow's package (``icub_workflow``, the book layer's) that
    ``source`` imports, at its top or inside a function."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            found += [a.name for a in node.names if a.name.split(".")[0] == "icub_workflow"]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            if node.module.split(".")[0] == "icub_workflow":
                found.append(node.module)
    return found


@pytest.mark.parametrize("path", science_modules(), ids=lambda p: p.name)
def test_no_science_module_imports_the_book_layer(path):
    assert book_imports(path.read_text()) == []


@pytest.mark.parametrize("path", science_modules(), ids=lambda p: p.name)
def test_no_science_module_returns_or_holds_a_verdict_word(path):
    assert verdict_strings(path.read_text()) == [], "say it in icub_workflow.book.words"


def test_the_scans_catch_what_they_look_for():
    """Each scan finds a regression of the kind it guards against, and passes over a docstring."""
    returned = 'def f(p):\n    """Is "reversed" or "not shown"."""\n    return "Not shown"\n'
    assert verdict_strings(returned) == [(3, "Not shown")]
    held = 'WORDS = {"paper": "confirmed"}\nif x == "opposite":\n    pass\n'
    assert [w for _, w in verdict_strings(held)] == ["confirmed", "opposite"]
    assert verdict_strings('CODES = ("paper", "against", "none")\n') == []
    assert book_imports("from icub_workflow.book import words\n") == ["icub_workflow.book"]
    assert book_imports("def f():\n    import icub_workflow.book.text\n") == [
        "icub_workflow.book.text"
    ]
    assert book_imports("from .outcome import Outcome\nimport numpy\n") == []


def test_every_outcome_a_table_or_a_page_reads_has_its_words():
    """The words module names every code the science package gives where it is read: a
    declared test's table code and word, a signature's word, a reading's word."""
    tested = set(Outcome) - {Outcome.NOT_TESTED, Outcome.CONSTANT}
    assert set(words.DIRECTION_CODES) == set(words.CLAIM_OUTCOME_WORDS) == tested
    assert set(words.SIGNATURE_WORDS) == set(Outcome) - {Outcome.CONSTANT}
    assert set(words.READING_WORDS) == {Outcome.PAPER, Outcome.AGAINST, Outcome.NONE,
                                        Outcome.CONSTANT}  # fmt: skip
    assert words.direction_codes([1, -1, 0, 2]) == ["paper", "reversed", "none", "not assessable"]
    assert words.signature_words(["", Outcome.AGAINST]) == ["", "opposite"]
    # the words read the science package's one significance level
    from icub_affordance.findings import ALPHA

    assert words.ALPHA == ALPHA
    assert words.verdict_word({"estimate": 1.0, "p": ALPHA * 0.99}) == "reproduced"
    assert words.verdict_word({"estimate": 1.0, "p": ALPHA}) == "not shown"
