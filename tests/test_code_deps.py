"""A code change reruns exactly the rules that run that code (issue 14, item 2).

Each rule's code inputs are derived from its script's imports (workflow/lib/code_deps.py, with
`ast`). Here they are checked against Python's own import machinery, and against Snakemake:
edit a module, dry-run, and every rule whose code imports it is scheduled.
"""

from __future__ import annotations

import ast
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import REPO, run_snakemake

sys.path.insert(0, str(REPO / "workflow" / "lib"))
from code_deps import CodeGraph, page_code  # noqa: E402

SCRIPTS = REPO / "workflow" / "scripts"
PACKAGE = REPO / "src" / "icub_affordance"


def write_package(root: Path, modules: dict[str, str]) -> Path:
    pkg = root / "icub_affordance"
    pkg.mkdir(parents=True)
    for name, text in {"__init__": "", **modules}.items():
        (pkg / f"{name}.py").write_text(text)
    return root


def test_closure_follows_relative_absolute_and_nested_imports(tmp_path):
    src = write_package(
        tmp_path,
        {
            "a": "from .b import x\n",
            "b": "def f():\n    from icub_affordance import c\n",
            "c": "import numpy\n",
            "d": "from . import a\n",
            "lonely": "",
        },
    )
    graph = CodeGraph(src)
    names = lambda paths: [p.stem for p in paths]  # noqa: E731
    assert names(graph.closure(["from icub_affordance.a import y"])) == ["__init__", "a", "b", "c"]
    assert names(graph.closure(["import icub_affordance.d as d"])) == [
        "__init__", "a", "b", "c", "d",
    ]  # fmt: skip
    assert names(graph.closure(["import os"])) == ["__init__"]


def test_page_code_reads_code_cells_without_their_options(tmp_path):
    page = tmp_path / "p.md"
    page.write_text(
        "# Title\n\n```{code-cell} ipython3\n---\ntags: [remove-input]\n---\n"
        "from icub_affordance.stats import x\n%matplotlib inline\n```\n\n"
        "```python\nfrom icub_affordance.body import y\n```\n"
        "```{code-cell} ipython3\n:tags: [hide-input]\nimport icub_affordance.som\n```\n"
    )
    code = page_code(page)
    ast.parse(code)
    assert "stats" in code and "som" in code and "body" not in code  # a plain block is no cell


def imported_by_python(source: str) -> set[str]:
    """The package modules that running a source's module-level imports actually loads."""
    imports = [
        ast.unparse(node)
        for node in ast.parse(source).body
        if isinstance(node, ast.Import | ast.ImportFrom)
    ]
    probe = "\n".join(
        [
            *imports,
            "import sys, json",
            "print(json.dumps(sorted(m.split('.', 1)[1] for m in sys.modules "
            "if m.startswith('icub_affordance.'))))",
        ]
    )
    env = os.environ | {"MUJOCO_GL": "egl", "PYTHONPATH": str(REPO / "src")}
    out = subprocess.run(
        [sys.executable, "-c", probe], capture_output=True, text=True, env=env, cwd=REPO
    )
    assert out.returncode == 0, out.stderr[-2000:]
    return set(json.loads(out.stdout.splitlines()[-1])) | {"__init__"}


def rule_scripts() -> dict[str, str]:
    """Rule name -> script name, read from the rule files (`use rule` inherits the script)."""
    scripts: dict[str, str] = {}
    inherited: dict[str, str] = {}
    for path in sorted((REPO / "workflow" / "rules").glob("*.smk")):
        text = path.read_text()
        for block in re.split(r"\n(?=rule |use rule )", text):
            if m := re.match(r"rule (\w+):", block):
                if s := re.search(r'script:\s*"\.\./scripts/(\w+)\.py"', block):
                    scripts[m.group(1)] = s.group(1)
            elif m := re.match(r"use rule (\w+) as (\w+)", block):
                inherited[m.group(2)] = m.group(1)
    return scripts | {new: scripts[old] for new, old in inherited.items() if old in scripts}


def script_sources(script: str) -> str:
    source = (SCRIPTS / f"{script}.py").read_text()
    if script == "book":  # the book rule also runs its pages' code
        source += "\n" + "\n".join(page_code(p) for p in sorted((REPO / "book").glob("*.md")))
    return source


@pytest.mark.slow
def test_derived_code_covers_what_python_imports():
    graph = CodeGraph(REPO / "src")
    for script in sorted({*rule_scripts().values()}):
        source = script_sources(script)
        derived = {p.stem for p in graph.closure([source])}
        missing = imported_by_python(source) - derived
        assert not missing, f"{script}: imports {missing} but its rule does not list them"


@pytest.mark.slow
def test_editing_a_module_reruns_every_rule_that_imports_it(built, tmp_path):
    """For every module: touch it in a copy of the finished test run, dry-run, and every rule
    of that run whose code imports the module is scheduled."""
    work = tmp_path / "work"
    work.mkdir()
    # copies with their times kept (a new link would count as a newer input)
    for name in ("Snakefile", "workflow", "config", "assets", ".test", "book", "src", "data"):
        if (built / name).is_dir():
            shutil.copytree(built / name, work / name)
        else:
            shutil.copy2(built / name, work / name)
    done = dry_run_rules(work, "--rerun-triggers", "mtime")
    assert done == set(), f"the finished run is not up to date: {done}"
    imports = {s: imported_by_python(script_sources(s)) for s in {*rule_scripts().values()}}
    in_target = rules_in_target(work)
    later = os.stat(work / "src" / "icub_affordance" / "io.py").st_mtime + 3600
    for module in sorted(p.stem for p in (work / "src" / "icub_affordance").glob("*.py")):
        path = work / "src" / "icub_affordance" / f"{module}.py"
        before = path.stat()
        os.utime(path, (later, later))
        scheduled = dry_run_rules(work, "--rerun-triggers", "mtime")
        os.utime(path, (before.st_atime, before.st_mtime))
        expected = {
            rule
            for rule, script in rule_scripts().items()
            if rule in in_target and module in imports[script]
        }
        assert expected <= scheduled, f"{module}.py edited: {expected - scheduled} not rerun"


def dry_run_rules(work: Path, *args: str) -> set[str]:
    result = run_snakemake(work, "-n", "-c1", *args)
    assert result.returncode == 0, result.stderr[-3000:]
    return set(re.findall(r"^rule (\w+):", result.stdout + result.stderr, re.M)) - {"all"}


def rules_in_target(work: Path) -> set[str]:
    result = run_snakemake(work, "-n", "-c1", "--forceall")
    assert result.returncode == 0, result.stderr[-3000:]
    return set(re.findall(r"^rule (\w+):", result.stdout + result.stderr, re.M))
