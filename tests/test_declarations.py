"""A declared test came before its data (icub_workflow.declarations): the tracked manifest as of
each declaring commit lists none of the declared test's input files, but where the project
records why they already existed (a named exception, reported, not passed silently)."""

from __future__ import annotations

import subprocess
import warnings
from pathlib import Path

import pytest

from icub_workflow.declarations import DECLARED, Declaration

REPO = Path(__file__).resolve().parents[1]


def git(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(["git", *args], cwd=REPO, capture_output=True, text=True)


def manifest_at(commit: str) -> str:
    """``results.sha256`` as of ``commit``; skipped where the history lacks it (a copy without
    ``.git``, or a shallow clone cut after it), failed where a full history does."""
    shown = git("show", f"{commit}:results.sha256")
    if shown.returncode:
        shallow = git("rev-parse", "--is-shallow-repository").stdout.strip() == "true"
        if not (REPO / ".git").exists() or shallow:
            pytest.skip(f"no git history back to {commit} (a copy, or a shallow clone)")
        pytest.fail(f"{commit}: {shown.stderr.strip()}")
    return shown.stdout


@pytest.mark.parametrize("declared", DECLARED, ids=lambda d: d.test)
def test_a_declaration_was_committed_before_the_data_it_tests(declared: Declaration):
    present = declared.inputs_in(manifest_at(declared.commit))
    if declared.exception:
        # a named exception must still be one: its inputs did exist then
        assert present, f"{declared.test}: recorded as an exception, but no input existed"
        said = f"{len(present)} input files existed at its declaration: {declared.exception}"
        warnings.warn(f"{declared.test} ({declared.commit}): {said}", stacklevel=1)
        return
    assert not present, f"{declared.test} declared in {declared.commit} after {present}"


def test_the_check_reads_a_manifests_paths():
    declared = Declaration("t", "0000000", ("data/x/*.csv",))
    text = "ab  data/x/a.csv\ncd  data/y/b.csv\n"
    assert declared.inputs_in(text) == ["data/x/a.csv"]


def test_the_robot_contact_time_is_the_named_exception():
    """The one declaration made when its trials existed says why; every other must pass."""
    named = {d.test: d for d in DECLARED if d.exception}
    assert set(named) == {"robot.confirmation.contact_time"}
    assert "before the data it tests exist" in named["robot.confirmation.contact_time"].exception
