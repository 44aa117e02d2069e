"""The science package returns numbers, flags and ``Outcome`` codes; the book's words, and the
threshold they read, are one module's (``icub_workflow.book.words``). Both read from the source,
so that a verdict word put back into ``icub_affordance`` (returned, or held in a constant) or an
import of the book layer fails here."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from conftest import REPO

from icub_affordance.outcome import Outcome
from icub_workflow.book import words

SCIENCE = REPO / "src" / "icub_affordance"
#: Every verdict word the book uses (issue 58), and the phrases it builds from them.
#: ("equivalent" is also the readings' difference code, which the science package writes.)
VERDICT_WORDS = (set(words.VERDICTS) - {words.EQUIVALENT}) | set(words.RETIRED)
VERDICT_WORDS |= {"shown", "not testable here", "same direction"}


def test_the_book_has_five_verdict_words():
    """Issue 69: every verdict the book and the result tables hold is one of the five words the
    front page defines; a confirmed difference between two readings, which nobody predicts, is
    said by its sign."""
    assert len(words.VERDICTS) == 5
    for table in (
        words.CLAIM_WORDS,
        words.EQUIVALENCE_WORDS,
        words.SAME_WORD,
        words.BAR_WORDS,
        words.READING_WORDS,
        words.SIGNATURE_WORDS,
        words.CLAIM_OUTCOME_WORDS,
    ):
        assert set(table.values()) <= set(words.VERDICTS), table
    assert set(words.DIFFERENCE_WORDS.values()) <= set(words.VERDICTS) | {"larger", "smaller"}
    assert not set(words.RETIRED) & set(words.VERDICTS)


def science_modules() -> list:
    return sorted(SCIENCE.rglob("*.py"))


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


def verdict_strings(source: str, keys: bool = True) -> list[tuple[int, str]]:
    """Each string constant in ``source`` outside its docstrings that is a verdict word: returned,
    compared with, or held in a constant alike, with its line; with ``keys`` False, not one that
    only names an entry (``values["confirmed"]``)."""
    tree = ast.parse(source)
    skip = docstrings(tree)
    if not keys:
        skip |= {id(n.slice) for n in ast.walk(tree) if isinstance(n, ast.Subscript)}
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


@pytest.mark.parametrize("path", science_modules(), ids=lambda p: str(p.relative_to(SCIENCE)))
def test_no_science_module_imports_the_book_layer(path):
    assert book_imports(path.read_text()) == []


@pytest.mark.parametrize("path", science_modules(), ids=lambda p: str(p.relative_to(SCIENCE)))
def test_no_science_module_returns_or_holds_a_verdict_word(path):
    assert verdict_strings(path.read_text()) == [], "say it in icub_workflow.book.words"


#: The book layer's modules besides ``words``, and the rule that writes its findings.
BOOK = [
    *sorted((REPO / "src" / "icub_workflow" / "book").glob("*.py")),
    REPO / "workflow" / "scripts" / "findings.py",
]


@pytest.mark.parametrize("path", [p for p in BOOK if p.name != "words.py"], ids=lambda p: p.name)
def test_the_rest_of_the_book_layer_names_its_verdict_words_from_the_words_module(path):
    """One module spells every verdict word: changing what "confirmed" reads is one edit."""
    assert verdict_strings(path.read_text(), keys=False) == [], "name it from book.words"


def test_a_words_change_reruns_only_the_rules_that_write_words():
    """The words module is code only of the scripts whose outputs hold words (the claims', the
    contact-time tests', the signatures' and the words study's tables, the forest plot's
    legend, the findings, and the book's table of verdict codes): a word changed reruns none of
    the model's rules."""
    from icub_workflow.code_deps import CodeGraph

    graph = CodeGraph([REPO / "src"])
    words_file = REPO / "src" / "icub_workflow" / "book" / "words.py"
    users = {
        script.stem
        for script in (REPO / "workflow" / "scripts").glob("*.py")
        if words_file in {Path(p).resolve() for p in graph.closure([script.read_text()])}
    }
    assert users == {
        "claims", "claims_figure", "findings", "robot_contact_time", "robot_contact_time_split",
        "signatures", "verdicts", "words"
    }  # fmt: skip


def test_the_scans_catch_what_they_look_for():
    """Each scan finds a regression of the kind it guards against, and passes over a docstring."""
    returned = 'def f(p):\n    """Is "reversed" or "not shown"."""\n    return "Not shown"\n'
    assert verdict_strings(returned) == [(3, "Not shown")]
    held = 'WORDS = {"paper": "confirmed"}\nif x == "reversed":\n    pass\n'
    assert [w for _, w in verdict_strings(held)] == ["confirmed", "reversed"]
    assert verdict_strings('CODES = ("paper", "against", "none")\n') == []
    assert verdict_strings('values["confirmed"] = 1\n', keys=False) == []
    assert verdict_strings('values["confirmed"] = "confirmed"\n', keys=False) == [(1, "confirmed")]
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
                                        Outcome.CONSTANT, Outcome.NOT_ASSESSABLE}  # fmt: skip
    from icub_affordance.analysis.reading_tests import NOT_ASSESSABLE

    assert words.DIFFERENCE_WORDS[NOT_ASSESSABLE] == words.NOT_ASSESSABLE
    assert words.direction_codes([1, -1, 0, 2]) == ["paper", "reversed", "none", "not assessable"]
    assert words.signature_words(["", Outcome.AGAINST]) == ["", "reversed"]
    # the words read the science package's one significance level
    from icub_affordance.analysis.verdicts import ALPHA

    assert words.ALPHA == ALPHA
    assert words.verdict_word({"estimate": 1.0, "p": ALPHA * 0.99}) == "confirmed"
    assert words.verdict_word({"estimate": 1.0, "p": ALPHA}) == "not shown"
