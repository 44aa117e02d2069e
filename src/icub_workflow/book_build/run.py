"""The run's provenance, and the staging of the outputs the book shows into ``book/_data``.

The rule ``book`` copies every pipeline output the pages show into ``book/_data`` and writes
``book/_data/run.json``; the pages read only those, so each number and figure in the book is
the pipeline's own output on that run.
"""

from __future__ import annotations

import shutil
import subprocess
from datetime import UTC, datetime
from importlib import metadata
from pathlib import Path

from icub_workflow.manifest import read_manifest, sha256

PACKAGES = (
    "mujoco",
    "numpy",
    "torch",
    "opencv-python-headless",
    "minisom",
    "statsmodels",
    "pandas",
    "matplotlib",
    "snakemake",
    "jupyter-book",
)


def provenance(config: dict, repo: Path) -> dict:
    """The config used, the git commit, key package versions and the date of this run."""
    try:
        commit = subprocess.run(
            ["git", "rev-parse", "HEAD"], cwd=repo, capture_output=True, text=True, check=True
        ).stdout.strip()
        dirty = bool(
            subprocess.run(
                ["git", "status", "--porcelain", "--untracked-files=no"],
                cwd=repo,
                capture_output=True,
                text=True,
                check=True,
            ).stdout.strip()
        )
    except (OSError, subprocess.CalledProcessError):
        commit, dirty = "unknown (not a git checkout)", False
    return {
        "config": config,
        "commit": commit,
        "uncommitted_changes": dirty,
        "versions": {name: metadata.version(name) for name in PACKAGES},
        "date": datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC"),
    }


def results_provenance(manifest: str, tracked: str) -> dict:
    """The build's results manifest, summed up: its digest and how it stands against the tracked
    manifest of the default configuration (the same digest when every result is the same bytes)."""
    built, expected = read_manifest(manifest), read_manifest(tracked)
    return {
        "digest": sha256(manifest),
        "files": len(built),
        "tracked_digest": sha256(tracked),
        "same_as_tracked": sum(built[path] == expected.get(path) for path in built),
        "tracked_files": len(expected),
    }


def stage(files: dict[str, str], data_dir: Path) -> None:
    """Copy the pipeline outputs the book shows into its data folder, under stable names."""
    if data_dir.exists():
        shutil.rmtree(data_dir)
    data_dir.mkdir(parents=True)
    for name, source in files.items():
        target = data_dir / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(source, target)
