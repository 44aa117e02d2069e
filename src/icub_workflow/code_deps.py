"""Which files of the project a script runs: its imports, followed transitively.

Snakemake does not track what a `script:` imports, so every rule lists that code as inputs, and
editing a module reruns exactly the rules that run it. The lists are derived here from the
sources themselves (with `ast`), never typed by hand, so they cannot drift. Only the project's
own code counts: modules found under the given roots (`src/`: the science package and the
workflow's); everything else (NumPy, MuJoCo, ...) is pinned by the lock.
"""

from __future__ import annotations

import ast
import hashlib
import json
import os
import re
import tempfile
from collections.abc import Iterable, Iterator, Sequence
from functools import cache
from pathlib import Path


class CodeGraph:
    """The project's modules under `roots` and what each imports."""

    def __init__(self, roots: Sequence[str | Path], cache: str | Path | None = None) -> None:
        self.roots = tuple(Path(root) for root in roots)
        # what each source text names in its imports, by the text's digest: read from `cache`
        # (a JSON file; a missing or unreadable one is started afresh), kept there by `save`
        self._cache = Path(cache) if cache is not None else None
        self._named: dict[str, list[str]] = _read_json(self._cache)
        self._stored = set(self._named)  # the digests the cache file holds
        self._used: set[str] = set()  # the digests asked for since the graph was made

    @cache  # noqa: B019 (one graph per workflow, alive as long as it)
    def find(self, module: str) -> Path | None:
        """The file of a dotted module name under the roots (a package: its `__init__.py`)."""
        parts = module.split(".")
        for root in self.roots:
            for path in (
                root.joinpath(*parts).with_suffix(".py"),
                root.joinpath(*parts, "__init__.py"),
            ):
                if path.is_file():
                    return path
        return None

    def _with_parents(self, module: str) -> set[str]:
        """A module and the packages it sits in: importing it runs their `__init__` too."""
        parts = module.split(".")
        return {".".join(parts[:i]) for i in range(1, len(parts) + 1)}

    def imports(self, source: str, module: str | None = None, is_package: bool = False) -> set[str]:
        """The project modules a source imports, anywhere in it (functions included).

        `module` is the source's own dotted name, for its relative imports (None: a script).
        """
        key = hashlib.sha256(f"{module}\0{is_package}\0{source}".encode()).hexdigest()
        if key not in self._named:
            self._named[key] = _imported_names(source, module, is_package)
        self._used.add(key)
        found: set[str] = set()
        for name in self._named[key]:
            found |= {m for m in self._with_parents(name) if self.find(m) is not None}
        return found

    def save(self) -> None:
        """Keep what this graph parsed in its cache file (written whole), so that the next
        Snakemake start parses only the sources that changed: parsing every module took a
        tenth of each start. Only the sources asked for since the graph was made are kept, so
        the file holds the code as it is, not every version it has been; an unchanged cache is
        not written."""
        if self._cache is None or self._used == self._stored:
            return
        self._cache.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=self._cache.parent, prefix=self._cache.name)
        with os.fdopen(fd, "w") as out:
            json.dump({key: self._named[key] for key in sorted(self._used)}, out)
        os.replace(tmp, self._cache)
        self._stored = set(self._used)

    @cache  # noqa: B019 (one graph per workflow, alive as long as it)
    def _direct(self, module: str) -> frozenset[str]:
        path = self.find(module)
        return frozenset(self.imports(path.read_text(), module, path.name == "__init__.py"))

    def closure(self, sources: Iterable[str]) -> list[Path]:
        """The project files that these source texts import, transitively, sorted."""
        todo: set[str] = set()
        for source in sources:
            todo |= self.imports(source)
        seen: set[str] = set()
        while todo:
            module = todo.pop()
            if module not in seen:
                seen.add(module)
                todo |= self._direct(module) - seen
        return sorted({self.find(m) for m in seen})


def _imported_names(source: str, module: str | None, is_package: bool) -> list[str]:
    """Every dotted name a source's import statements name, anywhere in it (functions
    included), whether or not it is one of the project's modules: ``import a.b`` names
    ``a.b``; ``from a import b`` names ``a`` and ``a.b`` (b may be a module of package a).
    `module` is the source's own dotted name, for its relative imports (None: a script)."""
    names: list[str] = []
    for node in _statements(ast.parse(source).body):
        if isinstance(node, ast.Import):
            names += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                if module is None:
                    continue
                package = module.split(".")
                package = package[: len(package) - node.level + (1 if is_package else 0)]
                base = ".".join([*package, *([node.module] if node.module else [])])
            else:
                base = node.module or ""
            names += [base, *(f"{base}.{alias.name}" for alias in node.names)]
    return names


def _read_json(path: Path | None) -> dict[str, list[str]]:
    """A cache file's contents; empty if there is none or it cannot be read (it is only a
    cache: whatever it lacks is parsed again)."""
    if path is None:
        return {}
    try:
        stored = json.loads(path.read_text())
    except (OSError, ValueError):
        return {}
    return stored if isinstance(stored, dict) else {}


def _statements(nodes: Iterable[ast.AST]) -> Iterator[ast.AST]:
    """Every statement in ``nodes`` and in the blocks nested in them (functions, classes, ``if``,
    ``try``, ``with``, loops, ``match``): where an import can stand, without visiting the
    expressions, which hold none and are most of a module's nodes (every Snakemake start reads
    the project's modules)."""
    for node in nodes:
        yield node
        for block in ("body", "orelse", "finalbody", "handlers", "cases"):
            yield from _statements(getattr(node, block, ()))


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
