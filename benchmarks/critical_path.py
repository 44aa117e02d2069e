"""The longest chain of jobs of a configuration, and the wall time its job records allow on N cores.

    python benchmarks/critical_path.py [data/benchmarks] [--cores 2 [8 ...]] [--record FILE]
        [-- SNAKEMAKE ARGS]
    python benchmarks/critical_path.py --cores 2 8 32 \\
        --record benchmarks/full_scale_critical_path.json -- --config robustness=True

The second, after a full-scale build, writes the record the book's robustness page states
(icub_workflow.critical_path.load_record reads it).

The DAG is Snakemake's own, from a dry run of every job (`snakemake -n --forceall --cores N`,
plus the arguments after `--`); nothing runs. Each job is weighed by its wall time on record
(column `s` of its benchmark file, under the given folder). The critical path (the chain of
jobs, each waiting for the one before, with the most seconds) bounds the build from below
whatever the cores, and the summed job time over N cores bounds it too; a greedy schedule
(ready jobs by Snakemake's priority, then longest remaining chain) predicts it.

A job with no record (the configuration has jobs the last build never ran) counts 0 s, with
a warning naming how many and a few of them, so that the figures over the jobs on record are
still given, labelled as such in the JSON (`missing`); `--strict` refuses instead. A job whose
rule keeps no benchmark (the target `all`) counts 0 s too. Snakemake's own time (its start,
the dry run's wall time, and its work between jobs, `--overhead` s a job) is not in the
records: the first is printed apart, the second added to each job if given.

Prints the critical path (each job, its rule and seconds), then the figures per number of
cores; the last line is JSON: jobs, missing, critical_path_s, sum_of_job_seconds, and for the
first number of cores, cores, lower_bound_s, predicted_s, and the records' span (``span_s``:
the build's wall time, for a build from scratch). ``--record`` writes these, the wall
times on every number of cores, the chain, the commit, the date and the CPU (refused if a job
has no record).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

from icub_affordance.files import write_text
from icub_workflow.benchmark_tables import job_seconds
from icub_workflow.critical_path import (
    critical_path,
    dependencies,
    load_record,
    parse_dry_run,
    record_path,
    wall_times,
)

ROOT = Path(__file__).resolve().parents[1]


def dry_run(cores: int, extra: list[str]) -> tuple[str, float]:
    """Snakemake's dry run of every job at the checkout's root, and its wall time. ``--cores``
    is passed so that each job's threads are shown as a build on that many cores gives them."""
    snakemake = str(Path(sys.executable).with_name("snakemake"))
    command = [snakemake, "-n", "--forceall", "--cores", str(cores), *extra]
    start = time.perf_counter()
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed (exit {done.returncode}):\n{done.stderr[-2000:]}")
    return done.stdout + done.stderr, time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        epilog="more Snakemake arguments after --, e.g. -- --config robustness=True",
    )
    parser.add_argument("directory", nargs="?", default="data/benchmarks", type=Path)
    parser.add_argument("--cores", type=int, nargs="+", default=[2], help="one or more")
    parser.add_argument(
        "--record", type=Path, help="also write the figures, the chain and their provenance here"
    )
    parser.add_argument("--overhead", type=float, default=0.0, help="seconds added to each job")
    parser.add_argument("--strict", action="store_true", help="refuse jobs with no record")
    argv = sys.argv[1:]
    ours, extra = (
        (argv[: argv.index("--")], argv[argv.index("--") + 1 :]) if "--" in argv else (argv, [])
    )
    args = parser.parse_args(ours)
    text, dry_s = dry_run(max(args.cores), extra)
    jobs = parse_dry_run(text)
    seconds, missing, ran = {}, [], []  # ran: each recorded job's (start, end)
    for job in jobs.values():
        seconds[job.jobid] = args.overhead
        if job.benchmark is None:
            continue
        path = record_path(job.benchmark, args.directory)
        if not path.exists():
            missing.append(job.benchmark)
            continue
        try:
            wall = job_seconds(path)
        except ValueError as error:
            sys.exit(str(error))
        seconds[job.jobid] += wall
        end = path.stat().st_mtime  # Snakemake writes the record as the job ends
        ran.append((end - wall, end))
    if missing:
        message = (f"{len(missing)} of {len(jobs)} jobs have no record under {args.directory} "
                   f"(counted 0 s), e.g. {', '.join(sorted(missing)[:3])}")  # fmt: skip
        if args.strict or len(missing) == sum(job.benchmark is not None for job in jobs.values()):
            sys.exit(message + ": run the build first, or name the folder")
        print("warning: " + message, file=sys.stderr)
    depends = dependencies(jobs)
    chain = critical_path(depends, seconds)
    threads = {j: job.threads for j, job in jobs.items()}
    priority = {j: jobs[j].priority for j in jobs}
    on_cores = wall_times(depends, seconds, args.cores, priority, threads)
    path_s = sum(seconds[j] for j in chain)
    work = sum(seconds.values())
    total = 0.0
    print(f"{'s':>8} {'total':>8}  rule: benchmark file")
    for j in chain:
        total += seconds[j]
        name = jobs[j].benchmark or "(no benchmark)"
        print(f"{seconds[j]:8.1f} {total:8.1f}  {jobs[j].rule}: {name}")
    kept = sum(job.benchmark is not None for job in jobs.values())
    label = f" ({kept - len(missing)} on record, {len(missing)} counted 0 s)" if missing else ""
    print(
        f"\n{len(jobs)} jobs{label}; critical path {path_s:.1f} s over {len(chain)} jobs; "
        f"summed job time {work:.1f} s; Snakemake's start (the dry run) {dry_s:.1f} s, "
        "not included"
    )
    for row in on_cores:
        print(
            f"on {row['cores']} cores: at least {row['lower_bound_s']:.1f} s, "
            f"greedy schedule {row['predicted_s']:.1f} s"
        )
    first = on_cores[0]
    figures = {
        "jobs": len(jobs),
        "missing": len(missing),
        "critical_path_s": round(path_s, 1),
        "critical_path_jobs": len(chain),
        "sum_of_job_seconds": round(work, 1),
        "cores": first["cores"],
        "lower_bound_s": first["lower_bound_s"],
        "predicted_s": first["predicted_s"],
        "dry_run_s": round(dry_s, 1),
        # from the first recorded job's start to the last one's end: the build's own wall time
        # if it ran whole, from scratch (else it reaches back to older records)
        "span_s": round(max(e for _, e in ran) - min(b for b, _ in ran), 1) if ran else 0.0,
    }
    if args.record is not None:
        if missing:
            sys.exit(f"not recorded: {len(missing)} jobs have no record (the book states none)")
        record = figures | {
            "on_cores": on_cores,
            "chain": [
                {"rule": jobs[j].rule, "s": round(seconds[j], 1), "benchmark": jobs[j].benchmark}
                for j in chain
            ],
            **provenance(),
            "snakemake_args": extra,
        }
        write_text(args.record, json.dumps(record, indent=2) + "\n")
        load_record(args.record)  # as the book reads it
        print(f"recorded in {args.record}")
    print(json.dumps(figures))


def provenance() -> dict[str, object]:
    """Which code and which machine the records come from: the checkout's commit, the tracked
    files that differ from it (``changed``: the records' build ran on this code only if these
    are files that do not run in a build, such as this script), the date and the CPU."""

    def git(*args: str) -> str:
        return subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True).stdout

    changed = [line[3:] for line in git("status", "--porcelain", "-uno").splitlines()]
    commit = git("rev-parse", "--short", "HEAD").strip()
    cpu = "unknown"
    info = Path("/proc/cpuinfo")
    if info.exists():
        fields = dict(line.split(":", 1) for line in info.read_text().splitlines() if ":" in line)
        strip = {k.strip(): v.strip() for k, v in fields.items()}
        cpu = (f"{strip.get('model name', 'unknown')} (family {strip.get('cpu family', '?')}, "
               f"model {strip.get('model', '?')}, {os.cpu_count()} cores)")  # fmt: skip
    date = time.strftime("%Y-%m-%d", time.gmtime())
    return {"commit": commit, "changed": changed, "date": date, "cpu": cpu}


if __name__ == "__main__":
    main()
