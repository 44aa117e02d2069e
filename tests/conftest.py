"""Shared fixtures: the robot is cheap to load, so most tests take a fresh one."""

from __future__ import annotations

from pathlib import Path

import pytest

from icub_affordance.body import Robot

REPO = Path(__file__).resolve().parents[1]


@pytest.fixture
def robot() -> Robot:
    r = Robot(REPO / "assets" / "icub_scene.xml")
    yield r
    r.close()


TEST_CONFIG = REPO / ".test" / "config" / "config.yaml"


def scratch_workflow(path: Path) -> Path:
    """A scratch copy of the workflow (symlinks), so tests never touch the repository's data/."""
    import shutil

    path.mkdir(parents=True, exist_ok=True)
    for name in ("Snakefile", "workflow", "config", "assets", "src", "benchmarks", ".test"):
        (path / name).symlink_to(REPO / name)
    # the book's sources are copied: its build writes beside them
    shutil.copytree(REPO / "book", path / "book", ignore=shutil.ignore_patterns("_build", "_data"))
    return path


def run_snakemake(workdir: Path, *args: str, config: Path = TEST_CONFIG):
    import subprocess
    import sys

    return subprocess.run(
        [sys.executable, "-m", "snakemake", *args, "--configfile", str(config)],
        cwd=workdir,
        capture_output=True,
        text=True,
    )


@pytest.fixture(scope="session")
def built(tmp_path_factory) -> Path:
    """The whole pipeline run once on the small test config; tests read its outputs."""
    workdir = scratch_workflow(tmp_path_factory.mktemp("pipeline"))
    result = run_snakemake(workdir, "-c2")
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    return workdir
