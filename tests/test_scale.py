"""Scale-out: the profiles parse, and a generic cluster executor gives the local run's outputs."""

from __future__ import annotations

import json
import re

import pytest
import yaml
from conftest import REPO, load_config, load_test_config, run_snakemake, scratch_workflow

from icub_workflow.sweep_timing import planned_jobs

COMPARED = [
    "data/demos/demos.npz",
    "data/soms/soms.npz",
    "data/eval/trials.csv",
    "data/eval/anova.json",
    "data/train/net00/weights.npz",
    "data/train/net03/curve.csv",
]


@pytest.mark.dryrun
@pytest.mark.parametrize("profile", ["default", "slurm", "local-cluster"])
def test_profiles_parse(tmp_path, profile):
    workdir = scratch_workflow(tmp_path)
    result = run_snakemake(
        workdir,
        "-n",
        "--profile",
        f"workflow/profiles/{profile}",
        config=REPO / "config" / "config.yaml",
    )
    assert result.returncode == 0, result.stderr[-3000:]


@pytest.mark.dryrun
def test_every_job_of_the_run_left_a_benchmark(built):
    """Each job's wall time and memory are on record (benchmarks/collect.py reads them)."""
    result = run_snakemake(built, "-n", "--forceall")
    assert result.returncode == 0, result.stderr[-3000:]
    jobs = sum(n for rule, n in planned_jobs(result.stdout).items() if rule != "all")
    assert len(list((built / "data" / "benchmarks").rglob("*.tsv"))) == jobs


@pytest.mark.reruns
def test_cluster_generic_executor_gives_the_local_outputs(built, tmp_path):
    workdir = scratch_workflow(tmp_path)
    result = run_snakemake(
        workdir, "--profile", "workflow/profiles/local-cluster", "data/eval/anova.json"
    )
    assert result.returncode == 0, result.stderr[-3000:]
    assert "with external jobid" in result.stderr  # each job went through the submit script
    for name in COMPARED:
        assert (workdir / name).read_bytes() == (built / name).read_bytes(), name


@pytest.mark.dryrun
def test_the_sweep_dag_trains_each_points_networks_in_one_job(tmp_path):

    workdir = scratch_workflow(tmp_path)
    config = load_config()
    sweep = config["sweep"]
    points = (
        len(sweep["seeds"])
        * len(sweep["learning_rate"])
        * len(sweep["hidden"])
        * len(sweep["categorisation_cue"])
    )
    result = run_snakemake(workdir, "-n", "sweep", config=REPO / "config" / "config.yaml")
    assert result.returncode == 0, result.stderr[-3000:]
    counts = {}
    for line in result.stdout.split("Job stats:")[-1].splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[1].isdigit():
            counts[parts[0]] = int(parts[1])
    assert counts["train"] == points  # a point's 12 networks in one job (its part `all`)
    assert counts["evaluate"] == points and counts["sweep_summary"] == 1
    # whole replications: each seed makes its own demonstrations and SOMs, once
    assert counts["demos"] == counts["soms"] == len(sweep["seeds"])


def test_sweep_tables_count_significant_replications():
    import pandas as pd

    from icub_affordance.analysis.sweep import sweep_tables

    def trials(effect, spread):
        """Four networks whose congruency effects are ``effect`` +- ``spread`` (mean ``effect``),
        with a small size effect of alternating sign."""
        rows = []
        for net in range(4):
            sign = (-1) ** net
            for cong, size, base in (
                ("True", "large", 0.05),
                ("True", "small", 0.05 + 0.0005 * sign),
                ("False", "large", 0.05 + effect + spread * sign),
                ("False", "small", 0.05 + effect + spread * sign + 0.0005 * sign),
            ):
                rows.append(
                    {
                        "network": net,
                        "mode": "closed_loop",
                        "task": "categorisation",
                        "congruent": cong,
                        "size": size,
                        "rmse": base + 0.001 * net,
                    }
                )
        return pd.DataFrame(rows)

    points = {
        f"s{i}": {
            "seed": i,
            "learning_rate": 0.075,
            "hidden": 10,
            "categorisation_cue": "first_step",
        }
        for i in range(3)
    }
    # s0 consistent (significant), s1 noisy (not), s2 consistent the other way (reversed)
    per_point, summary = sweep_tables(
        points, {"s0": trials(0.02, 0.001), "s1": trials(0.03, 0.1), "s2": trials(-0.02, 0.001)}
    )
    assert per_point["congruency_effect"].round(6).tolist() == [0.02, 0.03, -0.02]
    assert per_point["congruency_significant"].tolist() == [True, False, False]
    assert per_point["congruency_reversed"].tolist() == [False, False, True]
    assert per_point["congruency_p"].tolist()[1] > 0.05
    assert summary.loc[0, "replications"] == 3
    assert summary.loc[0, "congruency_n_significant"] == 1
    assert summary.loc[0, "congruency_n_reversed"] == 1
    assert summary.loc[0, "congruency_eta_p2"] == pytest.approx(
        per_point["congruency_eta_p2"].mean()
    )


def counts_and_inputs(result, rule="book"):
    """Planned job counts and the inputs of one rule's job, from a dry run's output."""
    assert result.returncode == 0, result.stderr[-3000:]
    counts = {}
    for line in result.stdout.split("Job stats:")[-1].splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[1].isdigit() and parts[0] != "total":
            counts[parts[0]] = int(parts[1])
    block = result.stdout.split(f"rule {rule}:")[1]
    inputs = block.split("input:")[1].split("\n")[0].split(", ")
    return counts, [name.strip() for name in inputs]


@pytest.mark.dryrun
def test_robustness_puts_the_sweep_and_its_cost_into_the_books_dag(dry_run):
    from icub_workflow.book.pages import robustness

    config = load_test_config()
    tracked = {
        "full_scale_critical_path.json": REPO / "benchmarks" / "full_scale_critical_path.json"
    }
    values, _ = robustness(tracked, config | {"robustness": False})
    points, networks = values["points"], values["networks"]
    plan = dry_run("--config", "robustness=True")
    counts, book_inputs = counts_and_inputs(plan)
    n = config["network"]["networks"]
    assert networks == points * n
    # the jobs that serve runs are the plan's (tests/test_stats.py, tests/test_run_plan.py)
    assert counts["sweep_summary"] == counts["sweep_figure"] == 1
    assert "sweep_cost" not in counts  # no job starts Snakemake
    assert counts["book"] == 1
    for output in ("data/sweep/points.csv", "data/sweep/summary.csv", "data/sweep/effects.png"):
        assert output in book_inputs, output
    # the book's sentences about the sweep and its cost are the findings rule's; the cost from
    # the engine's own records: the benchmark file of every job that makes a sweep point's
    # files (not rule measures', which scores a point that is also a reading's replication)
    jobs = planned(plan.stdout)
    findings_inputs = next(job for job in jobs if job["rule"] == "findings")["input"].split(", ")
    assert "data/sweep/summary.csv" in findings_inputs
    records = {name for name in findings_inputs if name.startswith("data/benchmarks/")}
    made = {
        job["benchmark"]
        for job in jobs
        if job["rule"] != "measures" and "data/runs/sweep_" in job.get("output", "")
    }
    assert records == made and len(made) >= 2 * len(config["sweep"]["seeds"]), (records, made)


def planned(dry_run_output: str) -> list[dict[str, str]]:
    """Each job of a dry run: its rule and its printed fields (input, output, benchmark...)."""
    jobs = []
    for block in re.split(r"^rule ", dry_run_output, flags=re.M)[1:]:
        name, _, body = block.partition(":\n")
        fields = dict(re.findall(r"^\s+(\w+): (.*)$", body, flags=re.M))
        jobs.append({"rule": name.strip()} | fields)
    return jobs


@pytest.mark.dryrun
def test_without_robustness_the_book_does_not_wait_for_the_sweep(dry_run):
    counts, book_inputs = counts_and_inputs(dry_run())
    assert counts["book"] == 1  # nor for the robot grid: tests/test_run_plan.py
    assert not [rule for rule in counts if rule.startswith("sweep")], counts
    assert not [n for n in book_inputs if n.startswith("data/") and "sweep" in n], book_inputs


@pytest.mark.dryrun
def test_robustness_in_lower_case_is_refused_with_the_command_that_works(tmp_path):
    result = run_snakemake(scratch_workflow(tmp_path), "-n", "--config", "robustness=true")
    assert result.returncode != 0
    assert "--config robustness=True" in result.stdout + result.stderr
    assert not (tmp_path / "data").exists()


def test_the_cost_of_one_replication_is_timed_in_a_scratch_copy(built):
    from icub_workflow.sweep_timing import SWEEP_INPUTS, measure

    config = load_test_config()
    table = measure(built, config, [1], cores=2, log=lambda _: None)
    assert table["replications"].tolist() == [1] and table["cores"].tolist() == [2]
    assert 0 < table["seconds"].iloc[0] < 300
    assert table["seconds_per_replication"].iloc[0] == table["seconds"].iloc[0]
    assert 0 <= table["other_load"].iloc[0] <= table["machine_cores"].iloc[0]
    # the copy ran it, not the checkout
    assert not (built / "data" / "sweep").exists()
    assert not list((built / "data" / "runs").glob("sweep_*"))
    with pytest.raises(RuntimeError, match="visual_maps"):  # a missing input would be timed too
        measure(built, config, [1], cores=2, inputs=SWEEP_INPUTS[:0])


def test_the_cost_table_is_written_whole(tmp_path):
    """benchmarks/sweep_cost.py --output: the table, atomically."""
    import pandas as pd

    from icub_workflow.sweep_timing import cost_table, write_cost_table

    table = cost_table([1, 4, 10], [20.0, 50.0, 110.0], cores=2, other_load=[0.0, 0.01, 0.5])
    assert table["seconds_per_replication"].tolist() == [20.0, 12.5, 11.0]
    path = tmp_path / "benchmarks" / "sweep_cost.csv"
    write_cost_table(table, path)
    back = pd.read_csv(path)
    assert back.columns.tolist() == table.columns.tolist()
    assert back["seconds"].tolist() == [20.0, 50.0, 110.0]
    assert back["other_load"].tolist() == [0.0, 0.01, 0.5]
    assert [p.name for p in path.parent.iterdir()] == ["sweep_cost.csv"]  # no temporary left
    with pytest.raises(ValueError, match="seconds_per_replication"):
        write_cost_table(table.drop(columns="seconds_per_replication"), path)


@pytest.mark.parametrize("counts", [[], [0, 4], [1, 1], [1.5], ["4"]])
def test_bad_replication_counts_are_refused(counts):
    from icub_workflow.sweep_timing import check_counts

    with pytest.raises(ValueError, match="sweep_cost"):
        check_counts(counts)


def test_the_cost_config_times_replications_of_the_main_runs_networks():
    from icub_workflow.sweep_timing import cost_config

    config = load_test_config() | {"robustness": True}
    scratch = cost_config(config, 3)
    assert scratch["sweep"] == {
        "seeds": [1, 2, 3],
        "learning_rate": [config["network"]["learning_rate"]],
        "hidden": [config["network"]["hidden"]],
        "categorisation_cue": [config["network"]["categorisation_cue"]],
    }
    assert scratch["robustness"] is False and config["robustness"] is True


def test_the_robustness_page_without_the_sweep_gives_the_command_and_no_numbers():
    from icub_workflow.book.pages import robustness

    config = load_config()
    tracked = REPO / "benchmarks" / "full_scale_critical_path.json"  # the full scale's record
    values, table = robustness({"full_scale_critical_path.json": tracked}, config)
    assert values["ran"] is False and table is None
    assert "did not run" in values["sweep_ran"]
    assert (
        "`snakemake -c2 --config robustness=True`" in (REPO / "book" / "reproduce.md").read_text()
    )
    sweep = config["sweep"]
    points = len(sweep["seeds"]) * len(sweep["learning_rate"]) * len(sweep["hidden"])
    points *= len(sweep["categorisation_cue"])
    assert values["points"] == points
    assert values["networks"] == points * config["network"]["networks"]


@pytest.mark.dryrun
def test_the_reproduction_notes_say_which_scale_this_build_is(built):
    found = json.loads((built / "data" / "book" / "findings.json").read_text())["reproduce"]
    config = yaml.safe_load((built / "config" / "config.yaml").read_text())
    assert found["scale"]["full"] is bool(config["robustness"]) is False
    assert set(found["scale"]) == {"now", "other", "full"}
