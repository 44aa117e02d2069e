"""What a reader of the built book reads: the words of each page's article, and its "In brief".

The count is declared here, before the pages were cut to it (issue: the book a scientist reads
in twenty minutes): the text of the page's ``<article>``, outside tables (data, not prose),
outside code cells' input (hidden from a reader) and outside folded sections (an admonition of
class ``dropdown``, or a cell output hidden behind a toggle: method details a reader opens only
to check the work). Folded words are
counted apart, so a page cannot hide its prose by folding it without the count saying so.

``python -m icub_workflow.book_build.reading book/_build/html`` prints the table.
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass, field
from html.parser import HTMLParser
from pathlib import Path

#: Elements whose text is not prose a reader reads through.
SKIPPED_TAGS = ("script", "style", "table")
#: Classes of ``div`` whose text is skipped: code cells' input, and folded sections.
SKIPPED_CLASSES = ("cell_input",)
FOLDED_CLASS = "dropdown"
IN_BRIEF_CLASS = "in-brief"
#: Pages of a Sphinx build that are not chapters.
NOT_CHAPTERS = ("genindex", "search")


@dataclass
class PageText:
    """One built page: the prose a reader reads, the folded words, and its In brief box."""

    words: int = 0
    folded_words: int = 0
    in_brief: str = ""
    first_block: str = ""  # the class of the first block after the title: "in-brief" or other


@dataclass
class _Parser(HTMLParser):
    page: PageText = field(default_factory=PageText)
    stack: list[tuple[str, str]] = field(default_factory=list)  # (tag, role) per open element
    seen_title: bool = False

    def __post_init__(self) -> None:
        super().__init__(convert_charrefs=True)

    def _roles(self) -> set[str]:
        return {role for _, role in self.stack}

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag in ("br", "img", "hr", "meta", "link", "input", "col", "source", "wbr"):
            return
        classes = (dict(attrs).get("class") or "").split()
        role = ""
        if tag == "article":
            role = "article"
        elif tag in SKIPPED_TAGS or any(c in classes for c in SKIPPED_CLASSES):
            role = "skip"
        elif FOLDED_CLASS in classes or tag == "details":
            role = "folded"
        elif IN_BRIEF_CLASS in classes:
            role = "brief"
        if (
            "article" in self._roles()
            and self.seen_title
            and not self.page.first_block
            and tag in ("div", "p", "section", "table", "figure", "ul", "ol", "aside")
            and "section" not in classes
            and tag != "section"
        ):
            self.page.first_block = IN_BRIEF_CLASS if IN_BRIEF_CLASS in classes else tag
        self.stack.append((tag, role))

    def handle_endtag(self, tag: str) -> None:
        for index in range(len(self.stack) - 1, -1, -1):
            if self.stack[index][0] == tag:
                if tag == "h1":
                    self.seen_title = True
                del self.stack[index:]
                return

    def handle_data(self, data: str) -> None:
        roles = self._roles()
        if "article" not in roles or "skip" in roles:
            return
        words = len(data.split())
        if "folded" in roles:
            self.page.folded_words += words
            return
        self.page.words += words
        if "brief" in roles:
            self.page.in_brief += data


def page_text(html: str) -> PageText:
    """Read one built page."""
    parser = _Parser()
    parser.feed(html)
    brief = re.sub(r"\s+", " ", parser.page.in_brief).strip()
    parser.page.in_brief = brief.removeprefix("In brief").strip()
    return parser.page


def sentences(text: str) -> list[str]:
    """A paragraph's sentences: split after a full stop, question or exclamation mark that ends
    a word and is followed by a capital (so "p = 0.013" and "e.g." stay whole)."""
    parts = re.split(r"(?<=[a-z0-9)\]%][.!?])\s+(?=[A-Z“\"(])", text.strip())
    return [part for part in parts if part]


def chapters(html_dir: Path) -> dict[str, PageText]:
    """Every chapter page of a built book, by name."""
    return {
        path.stem: page_text(path.read_text("utf8"))
        for path in sorted(Path(html_dir).glob("*.html"))
        if path.stem not in NOT_CHAPTERS
    }


def main(html_dir: str) -> None:
    pages = chapters(Path(html_dir))
    print(f"{'chapter':<14}{'words':>7}{'folded':>8}  in brief (sentences)")
    for name, page in pages.items():
        brief = len(sentences(page.in_brief)) if page.in_brief else "-"
        print(f"{name:<14}{page.words:>7}{page.folded_words:>8}  {brief}")
    total = sum(p.words for p in pages.values())
    folded = sum(p.folded_words for p in pages.values())
    print(f"{'total':<14}{total:>7}{folded:>8}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "book/_build/html")
