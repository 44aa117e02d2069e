"""Which files of the project a script runs: its imports of the package, followed transitively.

Snakemake does not track what a `script:` imports, so every rule lists that code as inputs,
and editing a module reruns exactly the rules that run it. The lists are derived here from the
sources themselves (with `ast`), never typed by hand, so they cannot drift.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable
from functools import cache
from pathlib import Path

PACKAGE = "icub_affordance"


def _imported_modules(source: str, package: str, current: str | None) -> set[str]:
    """Top-level names of `package` modules that this source imports, anywhere in it.

    `current` is the importing module's own name inside the package (for relative imports),
    None for a file outside it.
    """
    found: set[str] = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            for alias in node.names:
                parts = alias.name.split(".")
                if parts[0] == package:
                    found.add(parts[1] if len(parts) > 1 else "__init__")
        elif isinstance(node, ast.ImportFrom):
            if node.level == 0:
                parts = (node.module or "").split(".")
                if parts[0] != package:
                    continue
                rest = parts[1:]
            elif current is not None and node.level == 1:
                rest = (node.module or "").split(".") if node.module else []
            else:
                continue
            if rest:
                found.add(rest[0])
            else:  # `from icub_affordance import x` / `from . import x`: x may be a module
                found.update(alias.name for alias in node.names)
                found.add("__init__")
    return found


class CodeGraph:
    """The package's modules under `root` (a `src/` folder) and what each imports."""

    def __init__(self, src: str | Path, package: str = PACKAGE) -> None:
        self.package = package
        self.directory = Path(src) / package

    def path(self, module: str) -> Path:
        return self.directory / f"{module}.py"

    @cache  # noqa: B019 (one graph per workflow, alive as long as it)
    def _direct(self, module: str) -> frozenset[str]:
        source = self.path(module).read_text()
        found = _imported_modules(source, self.package, module)
        return frozenset(m for m in found if self.path(m).is_file())

    def closure(self, sources: Iterable[str]) -> list[Path]:
        """The package files that these source texts import, transitively, `__init__` first."""
        todo = {"__init__"}
        for source in sources:
            todo |= {
                m for m in _imported_modules(source, self.package, None) if self.path(m).is_file()
            }
        seen: set[str] = set()
        while todo:
            module = todo.pop()
            if module not in seen:
                seen.add(module)
                todo |= self._direct(module) - seen
        return [self.path(m) for m in sorted(seen, key=lambda m: (m != "__init__", m))]


_CODE_CELL = re.compile(r"^```\{code-cell\}[^\n]*\n(.*?)^```", re.DOTALL | re.MULTILINE)
_CELL_OPTIONS = re.compile(r"\A---\n.*?^---\n", re.DOTALL | re.MULTILINE)


def page_code(page: str | Path) -> str:
    """The Python of a MyST notebook page's code cells (cell options and magics dropped)."""
    cells = [_CELL_OPTIONS.sub("", cell) for cell in _CODE_CELL.findall(Path(page).read_text())]
    lines = [
        line
        for cell in cells
        for line in cell.splitlines()
        if not line.lstrip().startswith((":", "%", "!"))
    ]
    return "\n".join(lines)
