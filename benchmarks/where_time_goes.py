"""Where the build's time goes (issue 71): a job's fixed cost, each rule's job time and CPU, and
the build's headline figures, on a named CPU, so that a change is measured before and after.

    python benchmarks/where_time_goes.py                       # (a), (b), (c): about 20 s
    python benchmarks/where_time_goes.py --repeats 3           # fewer runs of the empty job
    python benchmarks/where_time_goes.py --paper-after-lr --sweep   # also the two timed builds
    python benchmarks/where_time_goes.py --save before.json    # keep the figures ...
    python benchmarks/where_time_goes.py --compare before.json # ... and set today's beside them
    python benchmarks/where_time_goes.py --compare before.json after.json   # two saved runs

(a) A job's fixed cost: rule ``benchmark_noop`` (workflow/rules/benchmark.smk, in no target),
whose script does nothing, run ``--repeats`` times by ``snakemake -c1 -R benchmark_noop``; the
median of its benchmark record (``s``, ``cpu_time``: Snakemake samples the CPU, so a job of well
under a second may show none) and of the whole command (wall, and CPU from the child's
``getrusage``: Snakemake's start, the job, its bookkeeping). Beside it, the median CPU and wall
of a fresh ``python -c pass``, of Snakemake's script preamble (``from snakemake import script``,
which every ``script:`` job runs) and of the project's own (``import icub_affordance.files``,
which every script imports), each with one thread for the numerical libraries as in a job.
(b) Each rule's summed job time (column ``s``) and CPU (``cpu_time``) over the default build's
jobs (``snakemake -n --forceall``: Snakemake's own list, each job's rule and benchmark file),
from their records in ``data/benchmarks/``; the share of the total, the job counts. Records of
jobs outside the default build (the sweep's, the empty job's) are counted on one line apart.
(c) The default build's summed job time and CPU (the totals of (b); its wall time, the build's
own, is Snakemake's to print, or ``benchmarks/timeline.py``'s after a build from scratch), and,
only when asked since each takes minutes, in a scratch copy of this checkout (code linked,
``data/`` and Snakemake's metadata copied, nothing here touched), each refused before anything
runs unless the build here is up to date (``snakemake -n`` plans nothing), so that only the
change is timed: ``--paper-after-lr``, the wall time of ``snakemake -c2 paper`` after the
copy's ``network.learning_rate`` is changed (``--lr``; by default 0.1, or 0.05 where the
config has 0.1), with its job count; ``--sweep``, ``snakemake -c2 sweep``'s wall time over the
sweep's networks (its points' runs removed from the copy first, so all of it is timed).

Name the CPU beside the figures (printed first: model and x86-64 level): machines differ by more
than the changes measured, and other work on the machine moves them by a tenth or more. The
last line is JSON: {"cpu": ..., "figures": {...}, "rules": {rule: {jobs, s, cpu_s}}};
``--save`` writes it, ``--compare`` prints each figure and each rule's job time before, after,
and after / before.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path

from icub_affordance.files import write_text
from icub_workflow.benchmark_tables import compare_figures, job_usage, rule_sums, x86_level
from icub_workflow.critical_path import parse_dry_run, record_path
from icub_workflow.manifest import cpu_flags
from icub_workflow.sweep_timing import LINKED, planned_jobs

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))
NOOP = "benchmark_noop"
#: What a fresh Python is timed running: the interpreter alone, and each preamble of a job.
STARTS = {
    "python_pass": "pass",
    "snakemake_preamble": "from snakemake import script",
    "project_preamble": "import icub_affordance.files",
}
#: One thread for the numerical libraries, as the Snakefile gives every job.
ONE_THREAD = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}


def cpu_name() -> str:
    """The CPU's model (``/proc/cpuinfo``), its x86-64 level and the machine's cores."""
    info: dict[str, str] = {}
    with contextlib.suppress(OSError):
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            key, _, value = line.partition(":")
            info.setdefault(key.strip(), value.strip())
    model = info.get("model name", "unknown CPU")
    family = f"family {info.get('cpu family', '?')} model {info.get('model', '?')}"
    return f"{model} ({family}), {x86_level(cpu_flags())}, {os.cpu_count()} cores"


def child_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed(
    command: list[str], cwd: Path = ROOT, env: dict | None = None
) -> tuple[float, float, str]:
    """Run ``command``: its wall seconds, CPU seconds (itself and its children) and output. A
    command that fails stops the benchmark, with its output: its time would mean nothing."""
    cpu, start = child_cpu(), time.perf_counter()
    done = subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True)
    wall, used = time.perf_counter() - start, child_cpu() - cpu
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed (exit {done.returncode}) in {cwd}:\n"
                 f"{done.stdout[-2000:]}{done.stderr[-2000:]}")  # fmt: skip
    return wall, used, done.stdout + done.stderr


def fixed_cost(repeats: int) -> dict[str, float]:
    """(a): the empty job's record and command, and a fresh Python's starts, each the median."""
    record = ROOT / "data" / "benchmarks" / f"{NOOP}.tsv"
    jobs, commands = [], []
    for _ in range(repeats):
        wall, cpu, _ = timed([SNAKEMAKE, NOOP, "-c1", "--quiet", "-R", NOOP])
        commands.append((wall, cpu))
        jobs.append(job_usage(record.read_text()))
    env = {**os.environ, **ONE_THREAD}
    figures = {
        "noop_job_s": statistics.median(s for s, _ in jobs),
        "noop_job_cpu_s": statistics.median(c for _, c in jobs),
        "noop_command_s": statistics.median(w for w, _ in commands),
        "noop_command_cpu_s": statistics.median(c for _, c in commands),
    }
    for name, code in STARTS.items():
        runs = [timed([sys.executable, "-c", code], env=env)[:2] for _ in range(repeats)]
        figures[f"{name}_s"] = statistics.median(w for w, _ in runs)
        figures[f"{name}_cpu_s"] = statistics.median(c for _, c in runs)
    return figures


def build_records(directory: Path) -> tuple[list[tuple[str, str]], list[str], list[Path]]:
    """The default build's jobs as (rule, benchmark file text), from Snakemake's dry run of every
    job; the benchmark files of its jobs that have no record; and the records under
    ``directory`` of jobs outside it."""
    jobs = parse_dry_run(timed([SNAKEMAKE, "-n", "--forceall", "-c2"])[2])
    found, missing, seen = [], [], set()
    for job in jobs.values():
        if job.benchmark is None:
            continue  # a target (`all`)
        path = record_path(job.benchmark, directory)
        seen.add(path.resolve())
        if path.exists():
            found.append((job.rule, path.read_text()))
        else:
            missing.append(job.benchmark)
    others = [p for p in sorted(directory.rglob("*.tsv")) if p.resolve() not in seen]
    return found, missing, others


@contextlib.contextmanager
def scratch_copy(learning_rate: float | None = None) -> Iterator[Path]:
    """A copy of this checkout to build in: the code linked, ``data/`` and Snakemake's metadata
    copied with their times (so that only what a change touches reruns), the config copied, with
    ``network.learning_rate`` set if given."""
    import yaml

    with tempfile.TemporaryDirectory(prefix="where-time-goes-") as tmp:
        work = Path(tmp)
        for name in LINKED:
            (work / name).symlink_to(ROOT / name)
        (work / "config").mkdir()
        for other in sorted((ROOT / "config").iterdir()):
            if other.name != "config.yaml":
                (work / "config" / other.name).symlink_to(other)
        config = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())
        if learning_rate is not None:
            config["network"]["learning_rate"] = learning_rate
        (work / "config" / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))
        shutil.copytree(ROOT / "data", work / "data", symlinks=True)
        metadata = ROOT / ".snakemake" / "metadata"
        if metadata.is_dir():
            shutil.copytree(metadata, work / ".snakemake" / "metadata")
        yield work


def timed_build(work: Path, target: str) -> dict[str, float]:
    """``snakemake -c2 {target}`` in ``work``: its wall time, CPU and number of jobs."""
    plan = planned_jobs(timed([SNAKEMAKE, "-n", "-c2", target], cwd=work)[2])
    wall, cpu, _ = timed([SNAKEMAKE, "-c2", target], cwd=work)
    return {"s": wall, "cpu_s": cpu, "jobs": sum(n for rule, n in plan.items() if rule != target)}


def require_built(target: str) -> None:
    """Refuse to time a change on a build that is not up to date here: the jobs it still owes
    (code edited since, say) would be timed with it."""
    plan = planned_jobs(timed([SNAKEMAKE, "-n", "-c2", target])[2])
    owed = {rule: n for rule, n in plan.items() if rule != target}
    if owed:
        sys.exit(f"`snakemake {target}` is not up to date in {ROOT} (it would run {owed}): "
                 "run `snakemake -c2` first, so that only the change is timed")  # fmt: skip


def paper_after_lr(learning_rate: float | None) -> dict[str, float]:
    """(c): ``snakemake -c2 paper`` after a change of the learning rate, in a scratch copy."""
    import yaml

    config = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())
    if learning_rate is None:
        learning_rate = 0.05 if config["network"]["learning_rate"] == 0.1 else 0.1
    with scratch_copy(learning_rate) as work:
        built = timed_build(work, "paper")
    return {f"paper_after_lr_{key}": value for key, value in built.items()}


def sweep_networks(config: dict) -> int:
    """The sweep's networks: a run's networks at each of its points (seed, learning rate,
    hidden units, cue timing)."""
    sweep = config["sweep"]
    points = 1
    for key in ("seeds", "learning_rate", "hidden", "categorisation_cue"):
        points *= len(sweep[key])
    return points * config["network"]["networks"]


def sweep() -> dict[str, float]:
    """(c): ``snakemake -c2 sweep`` in a scratch copy without the sweep's runs, per network."""
    import yaml

    config = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())
    with scratch_copy() as work:
        for folder in (*(work / "data" / "runs").glob("sweep_*"), work / "data" / "sweep"):
            shutil.rmtree(folder, ignore_errors=True)
        built = timed_build(work, "sweep")
    networks = sweep_networks(config)
    return {
        "sweep_s": built["s"],
        "sweep_jobs": built["jobs"],
        "sweep_networks": networks,
        "sweep_s_per_network": built["s"] / networks,
    }


def print_rules(rows: list[dict], missing: list[str], others: list[Path]) -> None:
    print(f"\n(b) each rule's jobs in the default build, from their records ({len(rows)} rules)")
    print(f"{'rule':24s} {'jobs':>5s} {'s':>9s} {'share':>6s} {'cpu_s':>9s} {'s/job':>7s} "
          f"{'cpu/job':>7s}")  # fmt: skip
    for row in rows:
        jobs = row["jobs"]
        na = f"  ({row['cpu_na']} without CPU)" if row["cpu_na"] else ""
        per_job = f"{row['s'] / jobs:7.2f} {row['cpu_s'] / jobs:7.2f}"
        print(f"{row['rule']:24s} {jobs:5d} {row['s']:9.1f} {row['share']:6.1%} "
              f"{row['cpu_s']:9.1f} {per_job}{na}")  # fmt: skip
    if missing:
        print(f"  {len(missing)} jobs of the build have no record (not counted), e.g. "
              f"{', '.join(sorted(missing)[:3])}")  # fmt: skip
    if others:
        print(f"  {len(others)} records under data/benchmarks are of jobs outside the default "
              "build (not counted)")  # fmt: skip


def print_comparison(before: dict, after: dict) -> None:
    """Each figure, then each rule's job time: before, after, after / before."""
    if before.get("cpu") != after.get("cpu"):
        print(f"warning: another CPU: before {before.get('cpu')}, after {after.get('cpu')}")

    def flat(run: dict) -> dict[str, float | None]:
        rules = {f"rule {r} s": v["s"] for r, v in run.get("rules", {}).items()}
        return {**run.get("figures", {}), **rules}

    print(f"\n{'figure':36s} {'before':>10s} {'after':>10s} {'ratio':>7s}")
    for name, old, new, ratio in compare_figures(flat(before), flat(after)):
        show = lambda v: f"{v:10.2f}" if v is not None else f"{'-':>10s}"  # noqa: E731
        print(f"{name:36s} {show(old)} {show(new)} {f'{ratio:7.2f}' if ratio else '      -'}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directory", nargs="?", default="data/benchmarks", type=Path)
    parser.add_argument("--repeats", type=int, default=5, help="runs of each start (median)")
    parser.add_argument("--paper-after-lr", action="store_true", help="time `paper` (minutes)")
    parser.add_argument("--lr", type=float, help="the learning rate set for --paper-after-lr")
    parser.add_argument("--sweep", action="store_true", help="time `sweep` (minutes)")
    parser.add_argument("--save", type=Path, help="write the figures as JSON here")
    parser.add_argument(
        "--compare", type=Path, nargs="+", metavar=("BEFORE", "AFTER"),
        help="a saved run to compare with this one (or with a second saved run: nothing runs)",
    )  # fmt: skip
    args = parser.parse_args()
    if args.compare and len(args.compare) > 2:
        parser.error("--compare takes a saved run, or two")
    if args.compare and len(args.compare) == 2:
        before, after = (json.loads(p.read_text()) for p in args.compare)
        print_comparison(before, after)
        return
    if args.paper_after_lr:
        require_built("paper")
    if args.sweep:
        require_built("all")
    cpu = cpu_name()
    print(f"CPU: {cpu}")
    figures = fixed_cost(args.repeats)
    print(f"\n(a) a job's fixed cost, median of {args.repeats} (s)     wall     cpu")
    for label, key in [
        (f"empty job's record ({NOOP}.tsv)", "noop_job"),
        (f"snakemake -c1 -R {NOOP}", "noop_command"),
        *((f"python -c {code!r}", name) for name, code in STARTS.items()),
    ]:
        print(f"  {label:42s} {figures[key + '_s']:7.2f} {figures[key + '_cpu_s']:7.2f}")
    try:
        found, missing, others = build_records(args.directory)
    except ValueError as error:
        sys.exit(str(error))
    if not found:
        sys.exit(f"no benchmark files under {args.directory}: run `snakemake -c2` first")
    rows = rule_sums(found)
    print_rules(rows, missing, others)
    figures["build_job_s"] = sum(row["s"] for row in rows)
    figures["build_cpu_s"] = sum(row["cpu_s"] for row in rows)
    figures["build_jobs"] = len(found)
    if args.paper_after_lr:
        figures.update(paper_after_lr(args.lr))
    if args.sweep:
        figures.update(sweep())
    print(f"\n(c) the default build: {figures['build_jobs']} jobs on record, summed job time "
          f"{figures['build_job_s']:.1f} s, CPU {figures['build_cpu_s']:.1f} s")  # fmt: skip
    if args.paper_after_lr:
        paper_s, paper_jobs = figures["paper_after_lr_s"], figures["paper_after_lr_jobs"]
        print(f"    snakemake -c2 paper after a learning-rate change: {paper_s:.1f} s, "
              f"{paper_jobs} jobs")  # fmt: skip
    if args.sweep:
        print(f"    snakemake -c2 sweep: {figures['sweep_s']:.1f} s for {figures['sweep_networks']}"
              f" networks, {figures['sweep_s_per_network']:.2f} s per network")  # fmt: skip
    result = {
        "cpu": cpu,
        "figures": {k: round(v, 3) for k, v in figures.items()},
        "rules": {
            row["rule"]: {
                "jobs": row["jobs"],
                "s": round(row["s"], 2),
                "cpu_s": round(row["cpu_s"], 2),
            }  # fmt: skip
            for row in rows
        },
    }
    if args.compare:
        print_comparison(json.loads(args.compare[0].read_text()), result)
    if args.save:
        write_text(args.save, json.dumps(result, indent=1) + "\n")
    print(json.dumps(result))


if __name__ == "__main__":
    main()
