"""The benchmark scripts: per-rule table and the run's time line, from Snakemake's files."""

from __future__ import annotations

import os
import subprocess
import sys

from conftest import REPO

HEADER = "s\th:m:s\tmax_rss\tmax_vms\tmax_uss\tmax_pss\tio_in\tio_out\tmean_load\tcpu_time\n"


def bench(path, wall: float, end: float) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(HEADER + f"{wall}\t0:00:0{wall:.0f}\t100\t0\t0\t0\t0\t0\t0\t{wall}\n")
    os.utime(path, (end, end))


def run(script: str, *args: str):
    return subprocess.run(
        [sys.executable, str(REPO / "benchmarks" / script), *args], capture_output=True, text=True
    )


def test_timeline_places_jobs_and_counts_idle_cores(tmp_path):
    # two cores: a (0-4 s) and b (0-2 s) together, then c (4-6 s) alone
    bench(tmp_path / "a.tsv", 4.0, 1000.0 + 4)
    bench(tmp_path / "train" / "b.tsv", 2.0, 1000.0 + 2)
    bench(tmp_path / "c.tsv", 2.0, 1000.0 + 6)
    result = run("timeline.py", str(tmp_path), "--cores", "2")
    assert result.returncode == 0, result.stderr
    assert "3 jobs; span 6.0 s; sum of job wall times 8.0 s; 67% of 2 cores" in result.stdout
    idle = float(result.stdout.rsplit("idle core-seconds", 1)[1])
    assert abs(idle - 4.0) < 0.2  # b's core from 2 to 4 s, and one core from 4 to 6 s


def test_benchmark_scripts_say_what_is_missing(tmp_path):
    for script in ("timeline.py", "collect.py"):
        result = run(script, str(tmp_path / "nothing"))
        assert result.returncode != 0
        assert "no benchmark files" in result.stderr and "snakemake -c2" in result.stderr


def test_job_imports_times_only_a_scripts_top_level_imports(tmp_path):
    """benchmarks/job_imports.py: a script's imports run, its work does not."""
    import json

    script = tmp_path / "job.py"
    script.write_text(
        "import json\nfrom pathlib import Path\n\n"
        "Path(__file__).with_name('ran').write_text('')\n"
        "def f():\n    import csv\n"
    )
    result = run("job_imports.py", str(script), "--repeats", "1")
    assert result.returncode == 0, result.stderr
    assert not (tmp_path / "ran").exists()
    figures = json.loads(result.stdout.splitlines()[-1])
    assert set(figures["scripts"]) == {"job"}
    assert abs(figures["total_s"] - figures["scripts"]["job"]) <= 0.01 and figures["total_s"] > 0


def test_the_book_says_whether_its_build_ran_on_slurm_from_the_jobs_environment():
    from icub_workflow.benchmark_tables import executor

    assert executor({"HOME": "/root"}) == {"executor": "local"}
    slurm = {
        "SLURM_JOB_ID": "53",
        "SLURM_CLUSTER_NAME": "icub-local",
        "SLURM_JOB_PARTITION": "local",
    }
    assert executor(slurm) == {"executor": "slurm", "cluster": "icub-local", "partition": "local"}


def test_the_sweeps_cost_sums_its_jobs_seconds_per_replication(tmp_path):
    """The robustness page's cost: each job's column `s`, summed over a replication's jobs."""
    import pytest

    from icub_workflow.benchmark_tables import replication_cost

    jobs = {"a/demos": (1, 20.0), "a/train": (1, 10.0), "b/train": (1, 5.0), "c/train": (2, 15.0)}
    records = {}
    for name, (seed, wall) in jobs.items():
        bench(tmp_path / f"{name}.tsv", wall, 1000.0)
        records[str(tmp_path / f"{name}.tsv")] = seed
    cost = replication_cost(records)
    assert cost == {"replications": 2, "jobs": 4, "mean_s": 25.0, "min_s": 15.0, "max_s": 35.0,
                    "total_s": 50.0}  # fmt: skip
    (tmp_path / "a" / "train.tsv").write_text("not a benchmark\n")
    with pytest.raises(ValueError, match="train.tsv is not a Snakemake benchmark file"):
        replication_cost(records)
    with pytest.raises(ValueError, match="did the sweep run"):
        replication_cost({})


#: An excerpt of `snakemake -n --forceall --cores 2` (Snakemake 9.27, the test config; the
#: book's block from the default config, for its threads), the input lists shortened: plain
#: jobs, a group job's indented member, the book's threads, and the target `all`.
DRY_RUN = """\
Building DAG of jobs...
[Sun Dec  6 18:40:12 2026]
rule visual_maps:
    input: assets/icub_scene.xml, assets/icub_scene.xml, src/icub_affordance/body/vision.py
    output: data/vision/visual_maps.npz, data/vision/vision_stages.npz
    log: data/logs/visual_maps.log
    jobid: 5
    benchmark: data/benchmarks/visual_maps.tsv
    reason: Forced execution
    priority: 3
    resources: tmpdir=/tmp, mem_mb=1000, mem=1 GB, mem_mib=954
[Sun Dec  6 18:40:12 2026]
rule figure3:
    input: data/vision/vision_stages.npz, src/icub_affordance/__init__.py
    output: data/vision/figure3.png
    log: data/logs/figure3.log
    jobid: 7
    benchmark: data/benchmarks/figure3.tsv
    reason: Forced execution
    resources: tmpdir=/tmp
[Sun Dec  6 18:40:12 2026] Group job replication (jobs in lexicogr. order):

    [Sun Dec  6 18:40:12 2026]
    rule train:
        input: data/vision/visual_maps.npz, data/soms/soms.npz, data/demos/demos.npz
        output: data/runs/cue_all_steps/train/all/curve.csv, data/runs/cue_all_steps/train/all/weights.npz
        log: data/logs/runs/cue_all_steps/train/all.log
        jobid: 20
        benchmark: data/benchmarks/runs/cue_all_steps/train/all.tsv
        reason: Forced execution
        wildcards: folder=runs/cue_all_steps/, part=all
        priority: 2
        resources: tmpdir=/tmp, runtime=10, mem_mb=1000, mem=1 GB, mem_mib=954
[Sun Dec  6 18:40:12 2026]
rule book:
    input: data/vision/figure3.png, data/vision/visual_maps.npz, src/icub_workflow/manifest.py
    output: book/_build/html/index.html
    log: data/logs/book.log
    jobid: 1
    benchmark: data/benchmarks/book.tsv
    reason: Forced execution
    threads: 2
    resources: tmpdir=/tmp, runtime=15, mem_mb=2000, mem=2 GB, mem_mib=1908
[Sun Dec  6 18:41:15 2026]
rule all:
    input: book/_build/html/index.html, data/runs/cue_all_steps/train/all/curve.csv
    jobid: 0
    reason: Forced execution
    resources: tmpdir=/tmp
Job stats:
job            count
-----------  -------
all                1
"""  # noqa: E501 (the real lines)


def test_the_dry_run_gives_each_job_its_record_and_the_jobs_it_waits_for(tmp_path):
    """benchmarks/critical_path.py: the DAG and the records from Snakemake's dry-run text."""
    from icub_workflow.critical_path import dependencies, parse_dry_run, record_path

    jobs = parse_dry_run(DRY_RUN)
    assert {j: job.rule for j, job in jobs.items()} == {
        5: "visual_maps", 7: "figure3", 20: "train", 1: "book", 0: "all"}  # fmt: skip
    assert jobs[20].benchmark == "data/benchmarks/runs/cue_all_steps/train/all.tsv"
    assert jobs[20].outputs[1] == "data/runs/cue_all_steps/train/all/weights.npz"
    assert (jobs[5].priority, jobs[7].priority, jobs[1].threads, jobs[7].threads) == (3, 0, 2, 1)
    assert jobs[0].benchmark is None
    assert dependencies(jobs) == {5: set(), 7: {5}, 20: {5}, 1: {5, 7}, 0: {1, 20}}
    assert (
        record_path(jobs[20].benchmark, tmp_path) == tmp_path / "runs/cue_all_steps/train/all.tsv"
    )
    import pytest

    with pytest.raises(ValueError, match="--quiet"):
        parse_dry_run("Building DAG of jobs...\nJob stats:\n")


def test_the_critical_path_and_the_wall_time_on_n_cores_of_a_small_dag():
    """Worked by hand: a(3) and b(2) start; c(4) waits for a and b, d(6) for b, e(1) for c and
    d. Chains a-c-e 8 s, b-c-e 7 s, b-d-e 9 s: the critical path is b, d, e (9 s). On two
    cores: a and b at 0; b ends at 2, d runs 2-8; a ends at 3, c runs 3-7; e runs 8-9: 9 s,
    the critical path itself. On one core, the sum: 16 s."""
    from icub_workflow.critical_path import critical_path, remaining_chain, simulate

    a, b, c, d, e = range(5)
    depends = {a: set(), b: set(), c: {a, b}, d: {b}, e: {c, d}}
    seconds = {a: 3.0, b: 2.0, c: 4.0, d: 6.0, e: 1.0}
    assert critical_path(depends, seconds) == [b, d, e]
    assert remaining_chain(depends, seconds) == {a: 8.0, b: 9.0, c: 5.0, d: 7.0, e: 1.0}
    assert simulate(depends, seconds, cores=2) == 9.0
    assert simulate(depends, seconds, cores=1) == 16.0
    assert simulate(depends, seconds, cores=4) == 9.0


def test_the_schedule_follows_snakemakes_priority_and_a_jobs_threads():
    """x(5), y(1), z(1), and w(5) waiting for y, on two cores. By longest remaining chain, y
    (6 s to the end) and x start; w runs 1-6, z 5-6: 6 s. With x and z given priority, x and z
    start, y runs 1-2 and w 2-7: 7 s. A two-thread job holds both cores: p(2, 2 threads) and
    q(2) take 4 s, not 2."""
    from icub_workflow.critical_path import simulate

    x, y, z, w = range(4)
    depends = {x: set(), y: set(), z: set(), w: {y}}
    seconds = {x: 5.0, y: 1.0, z: 1.0, w: 5.0}
    assert simulate(depends, seconds, cores=2) == 6.0
    assert simulate(depends, seconds, cores=2, priority={x: 1, z: 1}) == 7.0
    p, q = 0, 1
    pair = {p: set(), q: set()}
    assert simulate(pair, {p: 2.0, q: 2.0}, cores=2) == 2.0
    assert simulate(pair, {p: 2.0, q: 2.0}, cores=2, threads={p: 2}) == 4.0
    assert simulate(pair, {p: 2.0, q: 2.0}, cores=1, threads={p: 2}) == 4.0


def test_the_wall_time_per_number_of_cores_is_bounded_by_the_chain_and_the_cores_share():
    """The small DAG above (chain b-d-e 9 s, 16 s of jobs): on one core at least 16 s and 16 s
    scheduled; on two at least 9 s (the chain beats 16/2) and 9 s scheduled; a job of two
    threads holds both cores, so the cores' share on two is (16 + 2) / 2 = 9 s."""
    from icub_workflow.critical_path import wall_times

    a, b, c, d, e = range(5)
    depends = {a: set(), b: set(), c: {a, b}, d: {b}, e: {c, d}}
    seconds = {a: 3.0, b: 2.0, c: 4.0, d: 6.0, e: 1.0}
    assert wall_times(depends, seconds, [1, 2]) == [
        {"cores": 1, "lower_bound_s": 16.0, "predicted_s": 16.0},
        {"cores": 2, "lower_bound_s": 9.0, "predicted_s": 9.0},
    ]
    heavy = wall_times(depends, seconds, [2], threads={b: 2})[0]
    assert heavy["lower_bound_s"] == 9.0 and heavy["predicted_s"] >= 9.0


def test_a_critical_path_record_that_is_missing_or_incomplete_is_refused(tmp_path):
    """The book states the full scale's record: a missing, unreadable or incomplete one is
    refused naming the file and the command that writes it again; a whole one is read."""
    import json

    import pytest

    from icub_workflow.critical_path import load_record

    path = tmp_path / "record.json"
    with pytest.raises(ValueError, match="record.json.*--record"):
        load_record(path)
    path.write_text("{not json")
    with pytest.raises(ValueError, match="not a readable"):
        load_record(path)
    whole = {
        "jobs": 3, "missing": 0, "critical_path_s": 9.0, "critical_path_jobs": 3,
        "sum_of_job_seconds": 16.0, "chain": [{"rule": "train", "s": 9.0, "benchmark": "x"}],
        "on_cores": [{"cores": 2, "lower_bound_s": 9.0, "predicted_s": 9.0}],
        "commit": "abc1234", "date": "2026-12-07", "cpu": "a CPU", "snakemake_args": [],
        "span_s": 12.0,
    }  # fmt: skip
    path.write_text(json.dumps(whole))
    assert load_record(path) == whole
    for broken, words in (
        ({"critical_path_s": None}, "critical_path_s"),
        ({"on_cores": []}, "no wall time"),
        ({"missing": 2}, "2 jobs had no record"),
    ):
        path.write_text(json.dumps(whole | broken))
        with pytest.raises(ValueError, match=words):
            load_record(path)


def test_where_time_goes_sums_each_rules_wall_time_and_cpu_from_its_records():
    """benchmarks/where_time_goes.py (b): per rule, the jobs' `s` and `cpu_time` summed, the
    rule with the most wall time first, a record with no CPU (`NA`) counted apart."""
    import pytest

    from icub_workflow.benchmark_tables import job_usage, rule_sums

    def record(wall: float, cpu: str) -> str:
        return HEADER + f"{wall}\t0:00:01\t100\t0\t0\t0\t0\t0\t0\t{cpu}\n"

    assert job_usage(record(1.5, "0.75")) == (1.5, 0.75)
    rows = rule_sums(
        [
            ("figure3", record(1.0, "0.5")),
            ("demos", record(6.0, "5.0")),
            ("demos", record(2.0, "NA")),
            ("figure3", record(1.0, "0.25")),
        ]
    )
    assert [row["rule"] for row in rows] == ["demos", "figure3"]
    demos, figure3 = rows
    assert (demos["jobs"], demos["s"], demos["cpu_s"], demos["cpu_na"]) == (2, 8.0, 5.0, 1)
    assert (figure3["jobs"], figure3["s"], figure3["cpu_s"], figure3["cpu_na"]) == (2, 2.0, 0.75, 0)
    assert demos["share"] == pytest.approx(0.8) and figure3["share"] == pytest.approx(0.2)
    with pytest.raises(ValueError, match="not a Snakemake benchmark file"):
        job_usage("wall\n1.0\n")


def test_where_time_goes_names_the_cpus_level_and_compares_two_runs(tmp_path):
    """The CPU's x86-64 level from its flags; two saved runs set side by side, nothing run."""
    import json

    from icub_workflow.benchmark_tables import X86_LEVELS, compare_figures, x86_level

    v2, v3 = X86_LEVELS["x86-64-v2"], X86_LEVELS["x86-64-v3"]
    assert x86_level(set()) == "x86-64" and x86_level(v2 | {"sse2"}) == "x86-64-v2"
    assert x86_level(v2 | v3) == "x86-64-v3" and x86_level(v3) == "x86-64"
    assert compare_figures({"a": 2.0, "b": 0.0}, {"a": 1.0, "c": 3.0}) == [
        ("a", 2.0, 1.0, 0.5),
        ("b", 0.0, None, None),
        ("c", None, 3.0, None),
    ]
    runs = []
    for name, seconds in (("before", 10.0), ("after", 4.0)):
        path = tmp_path / f"{name}.json"
        figures = {"build_job_s": seconds}
        rules = {"demos": {"jobs": 1, "s": seconds, "cpu_s": 1.0}}
        path.write_text(json.dumps({"cpu": "x", "figures": figures, "rules": rules}))
        runs.append(str(path))
    result = run("where_time_goes.py", "--compare", *runs)
    assert result.returncode == 0, result.stderr
    lines = {line.split()[0]: line.split()[1:] for line in result.stdout.splitlines() if line}
    assert lines["build_job_s"] == ["10.00", "4.00", "0.40"]
    assert "rule demos s" in result.stdout
