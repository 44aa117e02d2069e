"""A code change reruns exactly the rules that run that code (issue 14, item 2).

Each rule's code inputs are derived from its script's imports (src/icub_workflow/code_deps.py, with
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
import time
from pathlib import Path

import pytest
from conftest import REPO, run_snakemake

from icub_workflow.code_deps import CodeGraph, page_code

SCRIPTS = REPO / "workflow" / "scripts"
ROOTS = [REPO / "src"]  # the project's code


def write_package(root: Path, modules: dict[str, str]) -> Path:
    pkg = root / "icub_affordance"
    pkg.mkdir(parents=True)
    for name, text in {"__init__": "", **modules}.items():
        (pkg / f"{name}.py").write_text(text)
    return root


def test_closure_follows_relative_absolute_and_nested_imports(tmp_path):
    src = write_package(
        tmp_path / "src",
        {
            "a": "from .b import x\n",
            "b": "def f():\n    from icub_affordance import c\n",
            "c": "import numpy\n",
            "d": "from . import a\n",
            "lonely": "",
        },
    )
    lib = tmp_path / "lib"
    (lib / "tools").mkdir(parents=True)
    (lib / "tools" / "__init__.py").write_text("from .words import w\n")
    (lib / "tools" / "words.py").write_text("from icub_affordance.c import z\n")
    graph = CodeGraph([src, lib])

    def names(source: str) -> list[str]:
        return sorted(str(p.relative_to(tmp_path)) for p in graph.closure([source]))

    package = "src/icub_affordance/"
    assert names("from icub_affordance.a import y") == [
        f"{package}{m}.py" for m in ("__init__", "a", "b", "c")
    ]
    assert names("import icub_affordance.d as d") == [
        f"{package}{m}.py" for m in ("__init__", "a", "b", "c", "d")
    ]
    assert names("from tools import w") == [
        "lib/tools/__init__.py", "lib/tools/words.py", f"{package}__init__.py", f"{package}c.py",
    ]  # fmt: skip
    assert names("import os\nimport numpy") == []


def test_the_import_cache_follows_edits_new_modules_and_survives_a_broken_file(tmp_path):
    """What a graph parsed is kept in its cache file; a later graph reading that file gives the
    closure a fresh parse gives, after a module's edit and after a module is added (the cache
    keeps what a source names, not which names are project modules); an edited source's old
    entry is dropped; and a broken cache file is parsed afresh."""
    src = write_package(tmp_path / "src", {"a": "from . import b\n", "b": ""})
    cache = tmp_path / "cache" / "code_deps.json"

    def closure(graph: CodeGraph) -> list[str]:
        return [p.name for p in graph.closure(["from icub_affordance import a"])]

    first = CodeGraph([src], cache=cache)
    assert closure(first) == ["__init__.py", "a.py", "b.py"]
    first.save()
    assert json.loads(cache.read_text())  # kept
    (src / "icub_affordance" / "a.py").write_text("from . import b\nfrom . import c\n")
    assert closure(CodeGraph([src], cache=cache)) == ["__init__.py", "a.py", "b.py"]  # no c yet
    (src / "icub_affordance" / "c.py").write_text("")
    assert closure(CodeGraph([src], cache=cache)) == ["__init__.py", "a.py", "b.py", "c.py"]
    (src / "icub_affordance" / "a.py").write_text("")
    edited = CodeGraph([src], cache=cache)
    assert closure(edited) == ["__init__.py", "a.py"]
    edited.save()  # the file keeps the sources as they are now: the source asked for, a, __init__
    assert len(json.loads(cache.read_text())) == 3
    cache.write_text("{not json")
    assert closure(CodeGraph([src], cache=cache)) == ["__init__.py", "a.py"]


def test_page_code_reads_code_cells_without_their_options(tmp_path):
    page = tmp_path / "p.md"
    page.write_text(
        "# Title\n\n```{code-cell} ipython3\n---\ntags: [remove-input]\n---\n"
        "from icub_affordance.analysis.statistics import x\n%matplotlib inline\n```\n\n"
        "```python\nfrom icub_affordance.body.robot import y\n```\n"
        "```{code-cell} ipython3\n:tags: [hide-input]\nimport icub_affordance.learning.maps\n```\n"
    )
    code = page_code(page)
    ast.parse(code)
    # a plain block is no cell
    assert "statistics" in code and "maps" in code and "body" not in code


#: Run in one fresh interpreter: for each source, the project's modules are dropped from
#: ``sys.modules`` and its module-level imports executed, so each source loads the project's
#: files it needs from scratch, while the libraries they load (numpy, pandas, MuJoCo...) stay
#: loaded from the first source that needed them: one start-up instead of one per script.
_PROBE = """
import json, sys
from pathlib import Path
roots = [Path(r).resolve() for r in json.loads(sys.argv[1])]
sources = json.loads(sys.stdin.read())
def project_files():
    files = {}
    for name, module in list(sys.modules.items()):
        f = getattr(module, "__file__", None)
        if f and any(Path(f).resolve().is_relative_to(root) for root in roots):
            files[name] = str(Path(f).resolve())
    return files
loaded = {}
for key, imports in sources.items():
    for name in project_files():
        del sys.modules[name]
    exec(imports, {"__name__": "probe"})
    loaded[key] = sorted(set(project_files().values()))
print(json.dumps(loaded))
"""


def imported_by_python(sources: dict[str, str]) -> dict[str, set[str]]:
    """For each source (by key), the project files that running its module-level imports
    actually loads (in a fresh Python: ``_PROBE``)."""
    imports = {
        key: "\n".join(
            ast.unparse(node)
            for node in ast.parse(source).body
            if isinstance(node, ast.Import | ast.ImportFrom)
        )
        for key, source in sources.items()
    }
    env = os.environ | {
        "MUJOCO_GL": "egl",
        "PYTHONPATH": os.pathsep.join(str(root) for root in ROOTS),
    }
    out = subprocess.run(
        [sys.executable, "-c", _PROBE, json.dumps([str(root) for root in ROOTS])],
        input=json.dumps(imports), capture_output=True, text=True, env=env, cwd=REPO,
    )  # fmt: skip
    assert out.returncode == 0, out.stderr[-2000:]
    loaded = json.loads(out.stdout.splitlines()[-1])
    return {key: {str(Path(f).relative_to(REPO)) for f in files} for key, files in loaded.items()}


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


@pytest.mark.heavy
def test_derived_code_covers_what_python_imports():
    graph = CodeGraph(ROOTS)
    sources = {script: script_sources(script) for script in sorted({*rule_scripts().values()})}
    for script, loaded in imported_by_python(sources).items():
        derived = {str(p.relative_to(REPO)) for p in graph.closure([sources[script]])}
        missing = loaded - derived
        assert not missing, f"{script}: imports {missing} but its rule does not list them"


@pytest.mark.dryrun
def test_editing_a_module_reruns_every_rule_that_imports_it(built, tmp_path):
    """Every job of the finished test run has among its inputs every module of the project that
    its script imports, so that editing the module reruns it (Snakemake reruns a job whose
    input is newer than its outputs); and, end to end, touching a module in a copy of the run
    schedules every rule that imports it: for the trainer and for the book's words."""
    work = tmp_path / "work"
    work.mkdir()
    # copies with their times kept (a new link would count as a newer input)
    for name in ("Snakefile", "workflow", "config", "assets", ".test", "book", "src", "data"):
        if (built / name).is_dir():
            shutil.copytree(built / name, work / name)
        else:
            shutil.copy2(built / name, work / name)
    shutil.copytree(REPO / "benchmarks", work / "benchmarks")
    done = dry_run_rules(work, "--rerun-triggers", "mtime")
    assert done == set(), f"the finished run is not up to date: {done}"
    scripts = sorted({*rule_scripts().values()})
    imports = imported_by_python({s: script_sources(s) for s in scripts})
    inputs = job_inputs(work)
    in_target = set(inputs)
    modules = sorted({m for files in imports.values() for m in files})
    assert (
        "src/icub_affordance/learning/training.py" in modules
        and "src/icub_workflow/book/text.py" in modules
    )
    for rule, script in rule_scripts().items():
        if rule in in_target:
            assert imports[script] <= inputs[rule], f"{rule}: {imports[script] - inputs[rule]}"
    for module in ("src/icub_affordance/learning/training.py", "src/icub_workflow/book/text.py"):
        path = work / module
        before = path.stat()
        later = time.time() + 3600  # after every output of the run
        os.utime(path, (later, later))
        scheduled = dry_run_rules(work, "--rerun-triggers", "mtime")
        os.utime(path, (before.st_atime, before.st_mtime))
        expected = {
            rule
            for rule, script in rule_scripts().items()
            if rule in in_target and module in imports[script]
        }
        assert expected <= scheduled, f"{module} edited: {expected - scheduled} not rerun"


def dry_run_rules(work: Path, *args: str) -> set[str]:
    result = run_snakemake(work, "-n", "-c1", *args)
    assert result.returncode == 0, result.stderr[-3000:]
    return set(re.findall(r"^rule (\w+):", result.stdout + result.stderr, re.M)) - {"all"}


def job_inputs(work: Path) -> dict[str, set[str]]:
    """Each rule of the default target (planned from scratch), and the inputs its jobs list,
    every job's in one set."""
    result = run_snakemake(work, "-n", "-c1", "--forceall")
    assert result.returncode == 0, result.stderr[-3000:]
    inputs: dict[str, set[str]] = {}
    jobs = re.split(r"^(?=(?:local)?rule \w+:$)", result.stdout + result.stderr, flags=re.M)
    for job in jobs:
        rule = re.match(r"(?:local)?rule (\w+):", job)
        if rule:
            listed = re.search(r"^\s*input: (.*)$", job, flags=re.M)
            files = set(listed[1].split(", ")) if listed else set()
            inputs.setdefault(rule[1], set()).update(files)
    return inputs
