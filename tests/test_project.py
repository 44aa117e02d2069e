"""The project keeps its promises to a newcomer: the README's commands are what CI runs."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

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
