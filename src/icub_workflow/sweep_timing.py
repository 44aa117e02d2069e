"""Does the cost of a sweep grow linearly? The wall time of `snakemake sweep` for n replications.

Each measurement runs in a fresh scratch copy of the workflow: the code is linked, the config is
config/config.yaml with the sweep replaced by n replications (seeds 1..n) at its network
settings (whole replications: each makes its own demonstrations and SOMs), and the sweep's
input (this checkout's visual maps) is copied in and marked up to date first, so that only the
sweep itself is timed. Prints a table
and, last, JSON: replications, seconds and seconds per replication.

Measured from the command line only, outside the DAG (`python benchmarks/sweep_cost.py`): no job
starts Snakemake. The book's reproduce page reads the sweep's cost from its jobs' own benchmark
files instead (benchmark_tables.replication_cost).
"""

from __future__ import annotations

import copy
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterable, Sequence
from pathlib import Path

import pandas as pd

from icub_affordance.files import atomic_path

LINKED = ("Snakefile", "workflow", "assets", "src", "benchmarks")
SWEEP_INPUTS = ("data/vision",)  # a replication makes its own demonstrations and SOMs
COLUMNS = [
    "replications",
    "seconds",
    "seconds_per_replication",
    "cores",
    "machine_cores",
    "other_load",
]


def busy_cpu_seconds() -> float:
    """CPU seconds the whole machine has been busy since boot (Linux /proc/stat), or NaN."""
    try:
        ticks = [int(x) for x in Path("/proc/stat").read_text().split("\n", 1)[0].split()[1:9]]
    except (OSError, ValueError):
        return float("nan")
    idle = ticks[3] + ticks[4]  # idle and waiting for I/O
    return (sum(ticks) - idle) / os.sysconf("SC_CLK_TCK")


def children_cpu_seconds() -> float:
    """CPU seconds used by this process's finished children and their descendants."""
    import resource

    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def check_counts(counts: Iterable[object]) -> list[int]:
    """Numbers of replications: whole numbers from 1, each once."""
    counts = list(counts)
    bad = [c for c in counts if isinstance(c, bool) or not isinstance(c, int) or c < 1]
    if not counts or bad or len(set(counts)) != len(counts):
        raise ValueError(
            "benchmarks/sweep_cost.py: the numbers of replications must be distinct whole "
            f"numbers from 1 (e.g. 1 4 10), got {counts}"
        )
    return counts


def cost_config(config: dict, replications: int) -> dict:
    """The config of one measurement: n replications (seeds 1..n) at the network's settings,
    without the reproduce pages (the scratch run makes only the sweep)."""
    config = copy.deepcopy(config)
    network = config["network"]
    config["sweep"] = {
        "seeds": list(range(1, replications + 1)),
        "learning_rate": [network["learning_rate"]],
        "hidden": [network["hidden"]],
        "categorisation_cue": [network["categorisation_cue"]],
    }
    config["robustness"] = False
    return config


def _snakemake(args: list[str], work: Path, what: str) -> str:
    result = subprocess.run(args, cwd=work, capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(
            f"{what}: `{' '.join(args)}` failed in the scratch copy {work}:\n"
            f"{result.stdout[-3000:]}\n{result.stderr[-3000:]}"
        )
    return result.stdout


def planned_jobs(dry_run: str) -> dict[str, int]:
    """The job counts of a dry run's summary table (rule: jobs)."""
    counts = {}
    for line in dry_run.split("Job stats:")[-1].splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[1].isdigit() and parts[0] != "total":
            counts[parts[0]] = int(parts[1])
    return counts


def time_sweep(
    repo: Path,
    config: dict,
    replications: int,
    cores: int,
    inputs: Sequence[str | os.PathLike[str]] = SWEEP_INPUTS,
) -> tuple[float, float]:
    """Wall time (s) of `snakemake -c{cores} sweep` for n replications in a scratch copy, and
    the other load meanwhile: how many cores, on average, were busy with anything else (the
    machine's busy CPU time less the timed run's own, per second). On a shared machine that
    tells a clean measurement from a disturbed one.

    ``inputs`` are the files or folders, relative to ``repo``, of the sweep's inputs.
    """
    import yaml

    repo = Path(repo).resolve()
    with tempfile.TemporaryDirectory(prefix="sweep-cost-") as tmp:
        work = Path(tmp)
        for name in LINKED:
            (work / name).symlink_to(repo / name)
        (work / "config").mkdir()
        # the config's other files (the confirmation's pilot, which the config checks refuse
        # to do without) linked, its config.yaml the measurement's own
        for other in sorted((repo / "config").iterdir()):
            if other.name != "config.yaml":
                (work / "config" / other.name).symlink_to(other)
        (work / "config" / "config.yaml").write_text(
            yaml.safe_dump(cost_config(config, replications), sort_keys=False)
        )
        for path in inputs:
            source, target = repo / path, work / path
            if not source.exists():
                raise FileNotFoundError(
                    f"{source} is missing: the sweep's cost is measured on the main run's "
                    "visual maps; run `snakemake -c2` first."
                )
            target.parent.mkdir(parents=True, exist_ok=True)
            if source.is_dir():
                shutil.copytree(source, target, dirs_exist_ok=True)
            else:
                shutil.copy2(source, target)
        what = f"timing the sweep with {replications} replication(s)"
        cmd = [sys.executable, "-m", "snakemake", "sweep", f"-c{cores}", "--quiet"]
        # the copied inputs are older than the linked code: mark them up to date, then clear
        # the sweep's own outputs (its runs' and its summary), which --touch marked too
        _snakemake(cmd + ["--touch"], work, what)
        for made in ("runs", "sweep"):
            shutil.rmtree(work / "data" / made, ignore_errors=True)
        # what is timed must be the sweep and nothing else
        dry_run = _snakemake(cmd[:-1] + ["-n"], work, what)
        plan = planned_jobs(dry_run)
        others = sorted(
            path
            for line in re.findall(r"^\s+output: (.*)$", dry_run, re.M)
            for path in line.split(", ")
            if not path.startswith(("data/runs/", "data/sweep/"))
        )
        if others or not plan.get("train"):
            raise RuntimeError(
                f"{what}: the scratch run would run {plan}, not only the sweep's rules "
                f"(also {others}); the sweep's inputs in {repo} may be incomplete."
            )
        busy, own = busy_cpu_seconds(), children_cpu_seconds()
        start = time.perf_counter()
        _snakemake(cmd, work, what)
        seconds = time.perf_counter() - start
        other = (busy_cpu_seconds() - busy) - (children_cpu_seconds() - own)
        return seconds, max(other, 0.0) / seconds


def cost_table(
    counts: Sequence[int],
    seconds: Sequence[float],
    cores: int,
    other_load: Sequence[float] | None = None,
) -> pd.DataFrame:
    """One row per measurement: replications, wall time, wall time per replication, the cores
    given and the machine's, and the other load meanwhile (cores busy with other work)."""
    counts = check_counts(counts)
    if len(seconds) != len(counts):
        raise ValueError(f"{len(counts)} replication counts but {len(seconds)} wall times")
    return pd.DataFrame(
        {
            "replications": counts,
            "seconds": [float(s) for s in seconds],
            "seconds_per_replication": [float(s) / n for s, n in zip(seconds, counts, strict=True)],
            "cores": int(cores),
            "machine_cores": os.cpu_count() or 0,
            "other_load": [float("nan")] * len(counts) if other_load is None else other_load,
        },
        columns=COLUMNS,
    )


def measure(
    repo: Path,
    config: dict,
    counts: Sequence[int],
    cores: int,
    inputs: Sequence[str | os.PathLike[str]] = SWEEP_INPUTS,
    log=print,
) -> pd.DataFrame:
    """Time the sweep for each number of replications; the cost table."""
    counts = check_counts(counts)
    seconds, other = [], []
    for n in counts:
        s, o = time_sweep(repo, config, n, cores, inputs)
        seconds.append(s)
        other.append(o)
        log(f"{n} replication(s): {s:.1f} s at -c{cores}; other load meanwhile {o:.2f} cores")
    return cost_table(counts, seconds, cores, other)


def write_cost_table(table: pd.DataFrame, path: str | os.PathLike[str]) -> None:
    """Atomically write the cost table as CSV."""
    missing = [c for c in COLUMNS if c not in table]
    if missing:
        raise ValueError(f"the cost table lacks the columns {missing}")
    with atomic_path(path) as tmp:
        table[COLUMNS].to_csv(tmp, index=False, float_format="%.2f")
