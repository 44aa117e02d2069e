"""The longest chain of jobs in a configuration's DAG, and the wall time it allows on N cores,
from the jobs' own benchmark records (`python benchmarks/critical_path.py`).

The DAG comes from Snakemake's dry run (`snakemake -n --forceall`, not `--quiet`): each job's
block names its rule, jobid, inputs, outputs, benchmark file, priority and threads, so one text
gives both the edges (a job waits for the job whose outputs hold one of its inputs) and each
job's record. `--d3dag` gives the edges but not the benchmark files.
"""

from __future__ import annotations

import heapq
import re
from dataclasses import dataclass, field
from pathlib import Path

#: A job block's first line, at any indentation (a group job's members are indented).
HEAD = re.compile(r"^\s*(?:rule|localrule|checkpoint) (\S+):\s*$")
FIELD = re.compile(r"^\s+(input|output|jobid|benchmark|priority|threads): (.*)$")


@dataclass
class Job:
    """One job of the dry run: what it reads and writes, its record, and its scheduling."""

    jobid: int
    rule: str
    inputs: list[str] = field(default_factory=list)
    outputs: list[str] = field(default_factory=list)
    benchmark: str | None = None
    priority: int = 0
    threads: int = 1


def parse_dry_run(text: str) -> dict[int, Job]:
    """Snakemake 9's dry-run text as {jobid: Job}. Line by line rather than by block, so that a
    group job's indented members are read like the others (run locally, a group's jobs are
    scheduled one by one)."""
    jobs: dict[int, Job] = {}
    current: dict[str, str] | None = None

    def close() -> None:
        if current is not None and "jobid" in current:
            split = lambda key: [p for p in current.get(key, "").split(", ") if p]  # noqa: E731
            job = Job(
                jobid=int(current["jobid"]),
                rule=current["rule"],
                inputs=split("input"),
                outputs=split("output"),
                benchmark=current.get("benchmark"),
                priority=int(current.get("priority", 0)),
                threads=int(current.get("threads", 1)),
            )
            jobs[job.jobid] = job

    for line in text.splitlines():
        head = HEAD.match(line)
        if head:
            close()
            current = {"rule": head.group(1)}
            continue
        found = FIELD.match(line)
        if found and current is not None:
            current[found.group(1)] = found.group(2).strip()
        elif current is not None and not line.startswith((" ", "\t")):
            close()
            current = None
    close()
    if not jobs:
        raise ValueError("no job blocks in the dry run: was it run with --quiet?")
    return jobs


def dependencies(jobs: dict[int, Job]) -> dict[int, set[int]]:
    """{jobid: the jobs it waits for}: those whose outputs include one of its inputs."""
    writer = {path: job.jobid for job in jobs.values() for path in job.outputs}
    return {
        job.jobid: {writer[p] for p in job.inputs if p in writer and writer[p] != job.jobid}
        for job in jobs.values()
    }


def topological(depends: dict[int, set[int]]) -> list[int]:
    """The jobs in an order where each comes after all it waits for; a cycle is an error."""
    waiting = {job: len(before) for job, before in depends.items()}
    after: dict[int, list[int]] = {job: [] for job in depends}
    for job, before in depends.items():
        for b in before:
            after[b].append(job)
    ready = sorted(job for job, n in waiting.items() if n == 0)
    order = []
    while ready:
        job = ready.pop()
        order.append(job)
        for a in after[job]:
            waiting[a] -= 1
            if waiting[a] == 0:
                ready.append(a)
    if len(order) != len(depends):
        raise ValueError("the jobs' dependencies form a cycle")
    return order


def critical_path(depends: dict[int, set[int]], seconds: dict[int, float]) -> list[int]:
    """The chain of jobs, each waiting for the one before, with the most seconds in all: no
    number of cores builds the DAG faster than its sum."""
    best: dict[int, float] = {}
    previous: dict[int, int | None] = {}
    for job in topological(depends):
        before = max(depends[job], key=lambda b: (best[b], -b), default=None)
        best[job] = seconds[job] + (best[before] if before is not None else 0.0)
        previous[job] = before
    job: int | None = max(best, key=lambda j: (best[j], -j))
    chain = []
    while job is not None:
        chain.append(job)
        job = previous[job]
    return chain[::-1]


def remaining_chain(depends: dict[int, set[int]], seconds: dict[int, float]) -> dict[int, float]:
    """Each job's longest chain to the end of the build, itself included: the jobs that hold up
    most of the build are the ones to start first."""
    after: dict[int, list[int]] = {job: [] for job in depends}
    for job, before in depends.items():
        for b in before:
            after[b].append(job)
    rest: dict[int, float] = {}
    for job in reversed(topological(depends)):
        rest[job] = seconds[job] + max((rest[a] for a in after[job]), default=0.0)
    return rest


def simulate(
    depends: dict[int, set[int]],
    seconds: dict[int, float],
    cores: int,
    priority: dict[int, int] | None = None,
    threads: dict[int, int] | None = None,
) -> float:
    """The wall time of a greedy list schedule on ``cores``: whenever cores are free, start the
    ready jobs (all inputs done) that fit, highest Snakemake ``priority`` first, then longest
    remaining chain, each on min(threads, cores) cores. A prediction, not a bound: Snakemake
    breaks ties between priorities by input size, not by the chain."""
    priority = priority or {}
    threads = threads or {}
    rest = remaining_chain(depends, seconds)
    need = {job: min(max(threads.get(job, 1), 1), cores) for job in depends}
    waiting = {job: len(before) for job, before in depends.items()}
    after: dict[int, list[int]] = {job: [] for job in depends}
    for job, before in depends.items():
        for b in before:
            after[b].append(job)
    rank = lambda j: (-priority.get(j, 0), -rest[j], j)  # noqa: E731
    ready = sorted((job for job, n in waiting.items() if n == 0), key=rank)
    running: list[tuple[float, int]] = []  # (end, job)
    now, free = 0.0, cores
    while ready or running:
        for job in list(ready):
            if need[job] <= free:
                ready.remove(job)
                free -= need[job]
                heapq.heappush(running, (now + seconds[job], job))
        now, job = heapq.heappop(running)
        done = [job]
        while running and running[0][0] <= now:
            done.append(heapq.heappop(running)[1])
        for job in done:
            free += need[job]
            for a in after[job]:
                waiting[a] -= 1
                if waiting[a] == 0:
                    ready.append(a)
        ready.sort(key=rank)
    return now


def record_path(benchmark: str, directory: Path, default: str = "data/benchmarks") -> Path:
    """Where a job's benchmark file is read: its path under Snakemake's folder ``default``, moved
    to ``directory`` (a copy of another build's records, say)."""
    path = Path(benchmark)
    try:
        return Path(directory) / path.relative_to(default)
    except ValueError:
        return path


# ---- the record the book quotes (benchmarks/full_scale_critical_path.json) ---------------------

#: What a record must hold, each key's type: the reproduce page states these.
RECORD_KEYS = {
    "jobs": int, "missing": int, "critical_path_s": float, "critical_path_jobs": int,
    "sum_of_job_seconds": float, "on_cores": list, "chain": list, "commit": str, "date": str,
    "cpu": str, "snakemake_args": list, "span_s": float,
}  # fmt: skip


def wall_times(
    depends: dict[int, set[int]],
    seconds: dict[int, float],
    cores: list[int],
    priority: dict[int, int] | None = None,
    threads: dict[int, int] | None = None,
) -> list[dict[str, float]]:
    """Per number of cores: the wall time at least (the critical path, or the cores' share of
    the job time, each job on min(threads, cores) of them, whichever is longer) and the greedy
    schedule's (``simulate``)."""
    threads = threads or {}
    path_s = sum(seconds[j] for j in critical_path(depends, seconds))
    rows = []
    for n in cores:
        core_s = sum(seconds[j] * min(max(threads.get(j, 1), 1), n) for j in depends)
        rows.append(
            {
                "cores": n,
                "lower_bound_s": round(max(path_s, core_s / n), 1),
                "predicted_s": round(simulate(depends, seconds, n, priority, threads), 1),
            }
        )
    return rows


def load_record(path: str | Path) -> dict:
    """A critical-path record written by ``benchmarks/critical_path.py --record``, checked: a
    missing or incomplete one is refused, naming the file and how to make it again."""
    import json

    fix = (
        "Fix: after a full-scale build (snakemake -c2 --config robustness=True), run "
        "python benchmarks/critical_path.py --cores 2 8 32 --record "
        f"{path} -- --config robustness=True"
    )
    try:
        record = json.loads(Path(path).read_text())
    except (OSError, ValueError) as error:
        raise ValueError(f"{path}: not a readable critical-path record ({error}). {fix}") from None
    wrong = [
        key
        for key, kind in RECORD_KEYS.items()
        if not isinstance(record.get(key), kind if kind is not float else (int, float))
    ]
    if wrong or not record["on_cores"] or record["missing"]:
        problem = f"keys missing or of the wrong type: {wrong}" if wrong else (
            "no wall time on any number of cores" if not record["on_cores"]
            else f"{record['missing']} jobs had no record"
        )  # fmt: skip
        raise ValueError(f"{path}: {problem}. {fix}")
    return record
