"""Sentences pinned to the tests they rest on: a Sphinx extension for the book.

A sentence that states a finding is prose a person wrote, with its numbers glued from the
build; what it may not do is outlive the verdict it was written for. So it is written inside a
``finding`` directive that names, for each test it rests on, the verdict it assumes::

    :::{finding} claims/first_step/teacher_forced/rmse/congruency=paper
    Teacher forced, incongruent trials were slower by {glue:text}`...` RMSE.
    :::

The argument is one or more ``test=code`` pairs, separated by spaces (it may run over lines).
A test is named by its row in ``_data/verdicts.csv`` (rule ``verdicts``: every test's family and
verdict code, decided by the science package); a code is one of that table's codes. The
directive renders its content as a paragraph followed by a small mark whose hover text lists the
tests and their verdicts. Where the build's verdict is not the one assumed, or the test does not
exist, Sphinx warns, naming the page, the line and the sentence; the book is built with ``-W``,
so the build fails. That is for the build the sentences were written for (config
``findings_check``: strict, or auto with the tracked results); in any other (a changed config, a
new seed) the sentence's mark turns red and its hover says what moved, and the book builds.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

logger = logging.getLogger(__name__)

#: Where the staged verdicts are, relative to the book's source folder.
VERDICTS = Path("_data") / "verdicts.csv"
#: Whether a moved verdict fails the build (``{"strict": true}``) or is marked on the page,
#: written by the rule ``book`` from config ``findings_check``; strict where it is missing.
CHECK = Path("_data") / "findings_check.json"


def parse_assumptions(argument: str) -> list[tuple[str, str]]:
    """``test=code`` pairs from the directive's argument, in order. A pair without ``=`` or
    with an empty side is refused (ValueError, naming it)."""
    pairs = []
    for item in argument.split():
        test, _, code = item.partition("=")
        if not test or not code:
            raise ValueError(f"{item!r} is not test=code")
        pairs.append((test, code.replace("_", " ")))
    if not pairs:
        raise ValueError("no test=code pair")
    return pairs


def read_verdicts(path: Path) -> dict[str, str]:
    """Each test's verdict code (``test``, ``code`` columns of ``verdicts.csv``)."""
    with open(path, newline="") as handle:
        return {row["test"]: row["code"] for row in csv.DictReader(handle)}


def disagreements(assumed: list[tuple[str, str]], verdicts: dict[str, str]) -> list[str]:
    """What of ``assumed`` the build's ``verdicts`` do not bear out, one phrase each."""
    found = []
    for test, code in assumed:
        if test not in verdicts:
            found.append(f"{test} is no test of this build")
        elif verdicts[test] != code:
            found.append(f"{test} is {verdicts[test]!r}, not {code!r}")
    return found


class Finding(SphinxDirective):
    """A sentence (or a few) resting on named tests with assumed verdicts."""

    required_arguments = 1
    final_argument_whitespace = True
    has_content = True

    def run(self) -> list[nodes.Node]:
        text = " ".join(self.content).strip()
        try:
            assumed = parse_assumptions(self.arguments[0])
        except ValueError as error:
            raise self.error(f"finding: {error}") from None
        verdicts = self.env.app.icub_verdicts
        problems = disagreements(assumed, verdicts)
        say = logger.warning if self.env.app.icub_strict else logger.info
        for problem in problems:
            say(
                "a finding's sentence no longer holds: %s. The sentence: “%s”",
                problem,
                text[:160],
                location=(self.env.docname, self.lineno),
            )
        container = nodes.container(classes=["finding"])
        self.state.nested_parse(self.content, self.content_offset, container)
        listed = "; ".join(f"{test}: {verdicts.get(test, 'missing')}" for test, _ in assumed)
        explanation = f"rests on {listed}"
        if problems:  # marked, in a build whose verdicts are not the ones the sentence was for
            explanation = "written for another build's verdicts; here " + "; ".join(problems)
        mark = nodes.abbreviation(
            "tests", "tests", explanation=explanation, classes=["moved"] if problems else []
        )
        paragraphs = [n for n in container.children if isinstance(n, nodes.paragraph)]
        if paragraphs:
            paragraphs[-1] += [nodes.Text(" "), mark]
        return [container]


def _load(app: Sphinx) -> None:
    path, check = Path(app.srcdir) / VERDICTS, Path(app.srcdir) / CHECK
    app.icub_verdicts = read_verdicts(path) if path.exists() else {}
    app.icub_strict = json.loads(check.read_text())["strict"] if check.exists() else True
    if not path.exists():
        logger.warning("no %s: every finding's test is missing (rule `verdicts` stages it)", path)


def setup(app: Sphinx) -> dict:
    app.add_directive("finding", Finding)
    app.connect("builder-inited", _load)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
