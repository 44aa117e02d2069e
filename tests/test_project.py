"""The project keeps its promises to a newcomer: the README's commands are what CI runs."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]


def readme_quick_start() -> list[str]:
    block = re.search(r"```sh\n(.*?)```", (REPO / "README.md").read_text(), re.S)
    assert block, "README must open with a ```sh quick-start block"
    return [line for line in block.group(1).splitlines() if line.strip()]


def test_readme_quick_start_is_two_lines_setup_then_tests():
    setup, tests = readme_quick_start()
    assert "pip install -r environment.lock" in setup and setup.endswith("snakemake -c2")
    assert tests.endswith("pytest")


def test_ci_runs_exactly_the_readme_commands():
    ci = [line for line in (REPO / ".ci" / "run").read_text().splitlines()]
    for line in readme_quick_start():
        assert line in ci


def test_a_plain_pytest_starts_no_daemon_and_ci_asks_for_the_slurm_test():
    """The Slurm test installs and starts daemons: it runs only when asked, and CI asks."""
    from test_slurm import ASK

    ci = (REPO / ".ci" / "run").read_text()
    asked = ci.index(f"export {ASK}=1")
    assert asked < ci.index(readme_quick_start()[1])  # before the tests run
    assert f"{ASK}=1 pytest tests/test_slurm.py" in (REPO / "README.md").read_text()


def test_lock_pins_every_package_exactly():
    lines = [
        line.split("#")[0].strip()
        for line in (REPO / "environment.lock").read_text().splitlines()
        if line.strip() and not line.lstrip().startswith("#")
    ]
    assert lines and all("==" in line for line in lines), [ln for ln in lines if "==" not in ln]
    assert "torch==2.13.0+cpu" in lines
    assert not any("--hash" in line for line in lines)
    jupyter_book = next(line for line in lines if line.startswith("jupyter-book=="))
    assert jupyter_book.split("==")[1].startswith("1.")


def test_code_is_formatted_and_linted():
    for args in (["check", "."], ["format", "--check", "."]):
        result = subprocess.run(
            [sys.executable, "-m", "ruff", *args], cwd=REPO, capture_output=True, text=True
        )
        assert result.returncode == 0, result.stdout + result.stderr


def tracked_files() -> list[Path]:
    listed = subprocess.run(["git", "ls-files"], cwd=REPO, capture_output=True, text=True)
    return [REPO / name for name in listed.stdout.splitlines() if (REPO / name).is_file()]


def test_readme_is_a_guide_read_in_minutes():
    assert len((REPO / "README.md").read_text().splitlines()) <= 150


def test_no_code_edits_the_import_path():
    """The packages are installed: nothing puts a folder on sys.path by hand."""
    folders = ("Snakefile", "workflow/", "src/", "benchmarks/")
    for path in tracked_files():
        relative = path.relative_to(REPO).as_posix()
        if relative.startswith(folders) and path.suffix in ("", ".py", ".smk"):
            assert "sys.path" not in path.read_text(), relative


def test_the_project_cites_its_own_reasoning_not_an_outside_file():
    for path in tracked_files():
        if (
            path.suffix in (".py", ".smk", ".md", ".yaml", ".yml", ".toml", "")
            and path.stat().st_size
        ):
            text = path.read_text(errors="ignore")
            assert "MODEL" + ".md" not in text and "../" + "shared" not in text, path


def test_the_science_never_imports_the_workflow_and_benchmarks_import_no_tests():
    for path in (REPO / "src" / "icub_affordance").rglob("*.py"):
        assert not re.search(r"^\s*(from|import) icub_workflow", path.read_text(), re.M), path
    for path in (REPO / "benchmarks").glob("*.py"):
        assert not re.search(r"^\s*(from|import) (test_|conftest)", path.read_text(), re.M), path


#: The science package's layers, lowest first (icub_affordance/__init__.py): a module imports
#: only from its own layer or a lower one.
LAYERS = (
    {"vocabulary", "outcome", "files"},
    {"learning", "body"},
    {"trials"},
    {"analysis"},
    {"figures", "animation"},
)


def science_imports() -> list[tuple[str, str]]:
    """Every import between the science package's top-level parts: (importer, imported)."""
    import ast

    root = REPO / "src" / "icub_affordance"
    found = []
    for path in root.rglob("*.py"):
        part = path.relative_to(root).parts[0].removesuffix(".py")
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module]
            elif isinstance(node, ast.Import):
                names = [alias.name for alias in node.names]
            else:
                continue
            found += [(part, n.split(".")[1]) for n in names
                      if n.startswith("icub_affordance.")]  # fmt: skip
    return found


def test_the_science_packages_layers_import_only_downwards():
    """learning and body stand on the vocabulary, the trials on them, the analysis on the
    trials, the figures and films on everything: no import runs back up."""
    layer = {part: level for level, parts in enumerate(LAYERS) for part in parts}
    imports = science_imports()
    assert {part for pair in imports for part in pair} <= set(layer), imports
    upwards = [(a, b) for a, b in imports if layer[b] > layer[a]]
    assert not upwards, upwards
    assert ("analysis", "trials") in imports and ("trials", "learning") in imports


@pytest.mark.dryrun  # runs Snakemake
def test_snakemake_lint_gives_no_advice_but_the_conda_one():
    result = subprocess.run(
        [sys.executable, "-m", "snakemake", "--lint"], cwd=REPO, capture_output=True, text=True
    )
    advice = set(re.findall(r"^\s*\* (.+?):?$", result.stdout + result.stderr, re.M))
    assert advice <= {"Specify a conda environment or container for each rule."}, advice


def test_every_test_that_may_skip_is_listed_with_its_reason_and_ci():
    """docs/pipeline.md lists every test a plain pytest may skip (CI skips none of them): a new
    skip is not a silent gap in CI."""
    import ast

    skipping = set()
    for path in sorted((REPO / "tests").glob("test_*.py")):
        functions = [
            n for n in ast.walk(ast.parse(path.read_text())) if isinstance(n, ast.FunctionDef)
        ]
        for node in functions:
            calls = [c for c in ast.walk(node) if isinstance(c, ast.Call)]
            if not any(ast.unparse(c.func) == "pytest.skip" for c in calls):
                continue
            # a fixture that skips skips the tests that take it
            users = [n.name for n in functions if node.name in [a.arg for a in n.args.args]]
            skipping |= {node.name} if node.name.startswith("test_") else set(users)
    doc = (REPO / "docs" / "pipeline.md").read_text()
    listed = {name for name in re.findall(r"::(test_\w+)`", doc)}
    assert len(skipping) >= 6, skipping
    assert skipping <= listed, sorted(skipping - listed)
