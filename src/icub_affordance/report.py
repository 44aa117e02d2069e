"""What the book's pages need: the run's provenance and numbers formatted for reading.

The book rule copies every pipeline output it shows into ``book/_data`` and writes
``book/_data/run.json``; the pages read only those, so each number and figure in the book is
the pipeline's own output on that run.
"""

from __future__ import annotations

import json
import shutil
import subprocess
from datetime import UTC, datetime
from importlib import metadata
from pathlib import Path

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


def stage(files: dict[str, str], data_dir: Path) -> None:
    """Copy the pipeline outputs the book shows into its data folder, under stable names."""
    if data_dir.exists():
        shutil.rmtree(data_dir)
    data_dir.mkdir(parents=True)
    for name, source in files.items():
        target = data_dir / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(source, target)


def load_run(data_dir: Path) -> dict:
    return json.loads((data_dir / "run.json").read_text())


def fmt_p(p: float) -> str:
    return "p < 0.001" if p < 0.001 else f"p = {p:.3f}"


def fmt_f(effect: dict) -> str:
    """F(df1, df2) = x.xx, p ..., partial eta squared."""
    return (
        f"F({effect['df1']:.0f}, {effect['df2']:.0f}) = {effect['F']:.2f}, {fmt_p(effect['p'])}, "
        f"partial η² = {effect['eta_p2']:.2f}"
    )


def benchmark_table(tables: dict[str, str]):
    """Per rule: jobs, total and longest wall time (s), largest memory (MB), from Snakemake's
    benchmark files (``{job name: file text}``, the job name's first part being the rule)."""
    import io

    import pandas as pd

    rows = []
    for job, text in tables.items():
        table = pd.read_csv(io.StringIO(text), sep="\t")
        memory = pd.to_numeric(table["max_rss"], errors="coerce").iloc[-1]
        rows.append(
            {
                "rule": job.split("/")[0],
                "seconds": float(table["s"].iloc[-1]),
                "memory": float(memory),
            }
        )
    frame = pd.DataFrame(rows)
    return (
        frame.groupby("rule")
        .agg(
            jobs=("seconds", "size"),
            total_s=("seconds", "sum"),
            longest_s=("seconds", "max"),
            max_memory_mb=("memory", "max"),
        )
        .sort_values("total_s", ascending=False)
    )


def read_benchmarks(directory: Path) -> dict[str, str]:
    return {
        str(path.relative_to(directory).with_suffix("")): path.read_text()
        for path in sorted(Path(directory).rglob("*.tsv"))
    }
