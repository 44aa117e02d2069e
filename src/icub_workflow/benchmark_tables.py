"""The pipeline's benchmark files as one table (rule, jobs, wall time, memory), as a time
line (when each job ran, how long the build took), and as the sweep's cost (its jobs' seconds
per replication).

Printed by `python benchmarks/collect.py` and `python benchmarks/timeline.py`, and shown on the
book's reproduce page (rule `book`) and reproduce page (rule `findings`).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path


def benchmark_files(directory: Path, files: list[str] | None = None) -> list[Path]:
    """The benchmark files to read: ``files`` (a rule's declared inputs, under ``directory``), or
    every one under ``directory`` (the command-line tools, on a finished build)."""
    if files is not None:
        return sorted(Path(f) for f in files)
    return sorted(Path(directory).rglob("*.tsv"))


def read_benchmarks(directory: Path, files: list[str] | None = None) -> dict[str, str]:
    """Each benchmark file (``benchmark_files``): {job name (its path under ``directory``, no
    suffix): file text}."""
    return {
        str(path.relative_to(directory).with_suffix("")): path.read_text()
        for path in benchmark_files(directory, files)
    }


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


def job_times(directory: Path, files: list[str] | None = None) -> list[tuple[float, float, str]]:
    """Each job's (start, end, name), sorted, from its benchmark file (``benchmark_files``):
    Snakemake writes it when the job ends (its modification time) and records the job's wall
    time, so the job ran from end - wall to end."""
    rows = []
    for path in benchmark_files(directory, files):
        name = str(path.relative_to(directory).with_suffix(""))
        lines = path.read_text().splitlines()
        try:
            wall = float(lines[-1].split("\t")[0])
        except (IndexError, ValueError):
            raise ValueError(
                f"{path} is not a Snakemake benchmark file. Time a complete run from scratch, "
                "which rewrites every benchmark file: `snakemake -c2 --forceall`"
            ) from None
        end = path.stat().st_mtime
        rows.append((end - wall, end, name))
    return sorted(rows)


def timeline(rows: list[tuple[float, float, str]], cores: int = 2) -> dict[str, float | int]:
    """How the jobs filled the build: their count, the span from the first start to the last
    end, the sum of their wall times, and the core-seconds left idle (each job counted as one
    core, sampled every 0.05 s)."""
    import numpy as np

    t0 = rows[0][0]
    span = max(end for _, end, _ in rows) - t0
    grid = np.arange(0.0, span, 0.05)
    running = np.zeros_like(grid)
    for start, end, _ in rows:
        running += (grid >= start - t0) & (grid < end - t0)
    return {
        "jobs": len(rows),
        "span_s": round(span, 1),
        "job_s": round(sum(end - start for start, end, _ in rows), 1),
        "idle_core_s": round(float(np.clip(cores - running, 0, None).sum() * 0.05), 1),
    }


def executor(environment: dict[str, str]) -> dict[str, str]:
    """Where the job asking ran: on a Slurm cluster (Slurm sets SLURM_JOB_ID in a job's
    environment) or on this machine. Asked by the book's own job, the last of a build: with
    workflow/profiles/slurm every job but the manifest runs on the cluster, the book included."""
    if "SLURM_JOB_ID" not in environment:
        return {"executor": "local"}
    return {
        "executor": "slurm",
        "cluster": environment.get("SLURM_CLUSTER_NAME", "unnamed"),
        "partition": environment.get("SLURM_JOB_PARTITION", "default"),
    }


def job_seconds(path: str | Path) -> float:
    """A job's wall time (s): column ``s`` of its Snakemake benchmark file (the last row)."""
    lines = Path(path).read_text().splitlines()
    try:
        if lines[0].split("\t")[0] != "s":
            raise ValueError
        return float(lines[-1].split("\t")[0])
    except (IndexError, ValueError):
        raise ValueError(
            f"{path} is not a Snakemake benchmark file: delete it and rerun the job that "
            "writes it (`snakemake -c2 --config robustness=True`)"
        ) from None


def replication_cost(records: Mapping[str, object]) -> dict[str, float | int]:
    """The sweep's cost from its jobs' own records, ``{benchmark file: the replication (seed)
    whose point the job served}``: per replication, the job seconds summed over its points'
    jobs; their mean, least and most (s), the total (s), and the counts of replications and
    jobs. Job seconds, not the build's wall time: jobs run side by side."""
    if not records:
        raise ValueError("no job records of the sweep: did the sweep run?")
    per = {}
    for path, replication in records.items():
        per[replication] = per.get(replication, 0.0) + job_seconds(path)
    seconds = list(per.values())
    return {  # to the records' own precision, 0.01 s
        "replications": len(seconds),
        "jobs": len(records),
        "mean_s": round(sum(seconds) / len(seconds), 2),
        "min_s": round(min(seconds), 2),
        "max_s": round(max(seconds), 2),
        "total_s": round(sum(seconds), 2),
    }


# ---- where the build's time goes (benchmarks/where_time_goes.py, issue 71) --------------------

#: The flags each x86-64 level adds to the one below (the psABI's levels; Linux's names).
X86_LEVELS = {
    "x86-64-v2": {"cx16", "lahf_lm", "popcnt", "sse4_1", "sse4_2", "ssse3"},
    "x86-64-v3": {"avx", "avx2", "bmi1", "bmi2", "f16c", "fma", "abm", "movbe", "xsave"},
    "x86-64-v4": {"avx512f", "avx512bw", "avx512cd", "avx512dq", "avx512vl"},
}


def x86_level(flags: set[str]) -> str:
    """The highest x86-64 level whose flags (and those of the levels below) the CPU has: the
    numerical libraries pick their code paths by it, so timings are compared within a level."""
    level = "x86-64"
    for name, needed in X86_LEVELS.items():
        if not needed <= flags:
            break
        level = name
    return level


def job_usage(text: str) -> tuple[float, float]:
    """A job's wall time and CPU seconds (columns ``s`` and ``cpu_time``, the last row) from the
    text of its Snakemake benchmark file; the CPU is NaN where Snakemake wrote none (``NA``:
    a job too short for its sampler)."""
    lines = text.strip().splitlines()
    if len(lines) < 2 or lines[0].split("\t")[0] != "s":
        raise ValueError("not a Snakemake benchmark file (no header starting with `s`)")
    header, row = lines[0].split("\t"), lines[-1].split("\t")
    wall = float(row[0])
    try:
        cpu = float(row[header.index("cpu_time")])
    except (ValueError, IndexError):
        cpu = float("nan")
    return wall, cpu


def rule_sums(jobs: list[tuple[str, str]]) -> list[dict[str, float | int | str]]:
    """Per rule, from ``[(rule, benchmark file text), ...]`` (one per job): its jobs, summed wall
    time (``s``) and CPU (``cpu_s``, the jobs with no CPU on record left out and counted in
    ``cpu_na``), and its share of all jobs' wall time; the rule with the most wall time first.
    Summed job time, not the build's wall time: jobs run side by side."""
    import math

    sums: dict[str, dict[str, float | int | str]] = {}
    for rule, text in jobs:
        wall, cpu = job_usage(text)
        row = sums.setdefault(rule, {"rule": rule, "jobs": 0, "s": 0.0, "cpu_s": 0.0, "cpu_na": 0})
        row["jobs"] += 1
        row["s"] += wall
        if math.isnan(cpu):
            row["cpu_na"] += 1
        else:
            row["cpu_s"] += cpu
    total = sum(float(row["s"]) for row in sums.values())
    for row in sums.values():
        row["share"] = float(row["s"]) / total if total else 0.0
    return sorted(sums.values(), key=lambda row: (-float(row["s"]), str(row["rule"])))


def compare_figures(
    before: Mapping[str, float | None], after: Mapping[str, float | None]
) -> list[tuple[str, float | None, float | None, float | None]]:
    """Each figure of either run as (name, before, after, after / before); None where a run
    lacks it or the ratio has no meaning (a figure of 0 before). Names in ``before``'s order,
    then those only ``after`` has."""
    rows = []
    for name in [*before, *(n for n in after if n not in before)]:
        old, new = before.get(name), after.get(name)
        ratio = new / old if old and new is not None else None
        rows.append((name, old, new, ratio))
    return rows
