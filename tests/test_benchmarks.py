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
