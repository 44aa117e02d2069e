"""Runs as data (issue 14): a run is a config entry; bad entries are refused naming run and key."""

from __future__ import annotations

import re

import pytest
import yaml
from conftest import REPO, load_test_config, run_snakemake, scratch_workflow

from icub_workflow.config_checks import check_runs
from icub_workflow.configs import merged

SCHEMA = yaml.safe_load((REPO / "workflow" / "schemas" / "config.schema.yaml").read_text())


def test_overrides_are_laid_over_the_config_key_by_key():
    base = {"seed": 1, "network": {"hidden": 10, "learning_rate": 0.075}, "soms": {"grid": 10}}
    run = merged(base, {"network": {"learning_rate": 0.0375}, "seed": 7})
    assert run == {
        "seed": 7,
        "network": {"hidden": 10, "learning_rate": 0.0375},
        "soms": {"grid": 10},
    }
    assert base["network"]["learning_rate"] == 0.075  # the config itself is not changed


@pytest.mark.parametrize(
    ("run", "words"),
    [
        ({"objects": ["big_ball"]}, ["runs.bad", "objects"]),  # not a section a run may change
        ({"network": {"learnin_rate": 0.1}}, ["runs.bad", "network", "learnin_rate"]),
        ({"network": {"learning_rate": -1}}, ["runs.bad", "network.learning_rate", "-1"]),
        ({"soms": {"iterations": "many"}}, ["runs.bad", "soms.iterations", "many"]),
        ({"seed": -3}, ["runs.bad", "seed", "-3"]),
        ({}, ["runs.bad"]),  # a run that changes nothing
    ],
)
def test_a_bad_run_is_refused_naming_the_run_and_the_key(run, words):
    config = load_test_config() | {"runs": {"fine": {"seed": 3}, "bad": run}}
    with pytest.raises(ValueError) as refused:
        check_runs(config, SCHEMA)
    for word in words:
        assert word in str(refused.value), (word, str(refused.value))


def test_a_run_may_not_take_a_derived_runs_name():
    config = load_test_config() | {"runs": {"cue_all_steps": {"seed": 3}}}
    with pytest.raises(ValueError, match="cue_all_steps.*taken"):
        check_runs(config, SCHEMA, taken=["main", "cue_all_steps"])


def test_good_runs_pass():
    config = load_test_config() | {
        "runs": {"half_lr": {"network": {"learning_rate": 0.0375}}, "s7": {"seed": 7}}
    }
    check_runs(config, SCHEMA, taken=["main", "cue_all_steps"])


def planned(result) -> dict[str, int]:
    assert result.returncode == 0, result.stderr[-3000:]
    table = result.stdout.split("Job stats:")[-1]
    return {m[0]: int(m[1]) for m in re.findall(r"^(\w+)\s+(\d+)$", table, re.M) if m[0] != "total"}


@pytest.mark.dryrun
def test_a_run_in_config_runs_alone_and_reruns_nothing_of_the_main_run(built, tmp_path):
    path = tmp_path / "runs.yaml"
    path.write_text(
        yaml.safe_dump(
            load_test_config() | {"runs": {"half_lr": {"network": {"learning_rate": 0.0375}}}}
        )
    )
    result = run_snakemake(built, "-n", config=path)
    jobs = planned(result)
    assert jobs == {
        "train": 1,  # the run's networks in one job (its part `all`)
        "evaluate": 1,  # the rules of every run
        "stats": 1,
        "figure5": 1,
        "all": 1,
    }
    assert "data/runs/half_lr/eval/anova.json" in result.stdout


@pytest.mark.dryrun
def test_a_robot_variant_is_a_run_trained_and_tested_on_the_robot_alone(built, tmp_path):
    """A variant added to robot.default trains its networks and drives the robot (a job each,
    its part `all`),
    then only the summaries and pages that show the variants rerun: nothing of the main run."""
    config = load_test_config()
    config["robot"]["hidden"] = [10, 20]
    config["robot"]["default"].append({"target": "sensed", "hidden": 20, "iterations": 1200})
    path = tmp_path / "robot.yaml"
    path.write_text(yaml.safe_dump(config))
    result = run_snakemake(built, "-n", config=path)
    jobs = planned(result)
    assert jobs.pop("train") == jobs.pop("robot_test") == 1  # each its part `all`
    shown = {"robot_summary", "robot_variants_figure", "findings", "rulegraph", "book", "all"}
    shown.add("manifest")  # the results' digests, which the book shows
    shown.add("robot_statistics")  # the robot statistics beyond the variants' table
    shown.add("rulegraph_figure")  # the DAG, drawn again after rulegraph
    shown.add("other_scale")  # the other scale's plan, which reads the robot's settings
    shown.add("robot_contact_time")  # reads the joined fresh trials robot_confirmation rewrites
    shown.add("robot_confirmation")  # reads the joined trials (the exploration's share)
    shown.add("robot_contact_time_split")  # the contact split reads them too (issue 70)
    shown.add("verdicts")  # names the robot's declared tests for the book's sentences
    assert set(jobs) <= shown, jobs
    assert "data/runs/robot_sensed_h20_it1200/embodied/all/trials.csv" in result.stdout


@pytest.mark.dryrun
def test_a_robot_variant_of_the_other_cue_timing_reuses_the_cue_ablation(built, tmp_path):
    """The cue timing is a dimension of the robot grid: the variant with the config's network
    settings under the other cue is the cue ablation's run (tested on the robot, not retrained);
    any other is a new run named by its cue timing. The servo-target variant under both cue
    timings shares one phase 1."""
    config = load_test_config()
    config["robot"]["categorisation_cue"] = ["first_step", "all_steps"]
    own = {k: config["network"][k] for k in ("target", "hidden", "iterations")}
    commands = {"target": "commands", "hidden": 10, "iterations": 1200}
    config["robot"]["default"] += [
        {"categorisation_cue": "all_steps"} | own,
        commands,
        {"categorisation_cue": "all_steps"} | commands,
    ]
    path = tmp_path / "robot.yaml"
    path.write_text(yaml.safe_dump(config))
    result = run_snakemake(built, "-n", config=path)
    jobs = planned(result)
    # the two servo-target variants, which share a phase 1 (the cue acts only after it:
    # runs.RunPlan.phase1_run) and continue from it; the animated variant, listed now, is
    # filmed on its networks 0.. instead of the confirmation's fresh ones, so the film runs too
    assert jobs.pop("phase1") == 1
    assert jobs.pop("train") == 2 and jobs.pop("robot_test") == 3
    assert "data/runs/cue_all_steps/embodied/all/trials.csv" in result.stdout
    assert "data/runs/robot_commands_h10_it1200_all_steps/train/all/weights.npz" in result.stdout
    shown = {"robot_summary", "robot_variants_figure", "findings", "rulegraph", "book", "all"}
    shown.add("manifest")  # the results' digests, which the book shows
    shown.add("robot_statistics")  # the robot statistics beyond the variants' table
    shown.add("rulegraph_figure")  # the DAG, drawn again after rulegraph
    shown.add("other_scale")  # the other scale's plan, which reads the robot's settings
    shown.add("robot_contact_time")  # reads the joined fresh trials robot_confirmation rewrites
    shown.add("robot_confirmation")  # reads the joined trials (the exploration's share)
    shown.add("robot_contact_time_split")  # the contact split reads them too (issue 70)
    shown.add("verdicts")  # names the robot's declared tests for the book's sentences
    shown.add("robot_animation")  # films the variant's networks 0.. (listed in robot.default)
    assert set(jobs) <= shown, jobs


@pytest.mark.dryrun
def test_a_robot_variant_with_the_annealed_rate_is_a_run_of_its_own(built, tmp_path):
    """The learning-rate schedule is a dimension of the robot grid: the config's network with
    the annealed rate trains its own networks, in a run named by what differs (_anneal)."""
    config = load_test_config()
    config["robot"]["learning_rate_schedule"] = ["constant", "anneal"]
    own = {k: config["network"][k] for k in ("target", "hidden", "iterations")}
    config["robot"]["default"] += [{"learning_rate_schedule": "anneal"} | own]
    path = tmp_path / "robot.yaml"
    path.write_text(yaml.safe_dump(config))
    result = run_snakemake(built, "-n", config=path)
    jobs = planned(result)
    assert jobs.pop("train") == 1 and jobs.pop("robot_test") == 1
    run = f"robot_{own['target']}_h{own['hidden']}_it{own['iterations']}_anneal"
    assert f"data/runs/{run}/train/all/weights.npz" in result.stdout
    shown = {"robot_summary", "robot_variants_figure", "findings", "rulegraph", "book", "all"}
    shown.add("manifest")  # the results' digests, which the book shows
    shown.add("robot_statistics")  # the robot statistics beyond the variants' table
    shown.add("rulegraph_figure")  # the DAG, drawn again after rulegraph
    shown.add("other_scale")  # the other scale's plan, which reads the robot's settings
    shown.add("robot_contact_time")  # reads the joined fresh trials robot_confirmation rewrites
    shown.add("robot_confirmation")  # reads the joined trials (the exploration's share)
    shown.add("robot_contact_time_split")  # the contact split reads them too (issue 70)
    shown.add("verdicts")  # names the robot's declared tests for the book's sentences
    assert set(jobs) <= shown, jobs


@pytest.mark.dryrun
def test_a_run_with_its_own_seed_makes_its_own_demonstrations_and_maps(built, tmp_path):
    path = tmp_path / "runs.yaml"
    path.write_text(yaml.safe_dump(load_test_config() | {"runs": {"s7": {"seed": 7}}}))
    jobs = planned(run_snakemake(built, "-n", config=path))
    # its four objects' demonstrations in one job
    assert jobs["soms"] == jobs["demos"] == 1
    assert "visual_maps" not in jobs  # the scene and the eye do not depend on the seed


@pytest.mark.dryrun
def test_a_bad_run_stops_snakemake_before_any_job(tmp_path):
    workdir = scratch_workflow(tmp_path / "w")
    path = tmp_path / "bad.yaml"
    bad = {"half_lr": {"network": {"learnin_rate": 0.1}}}
    path.write_text(yaml.safe_dump(load_test_config() | {"runs": bad}))
    result = run_snakemake(workdir, "-n", config=path)
    assert result.returncode != 0
    message = result.stdout + result.stderr
    assert "runs.half_lr" in message and "learnin_rate" in message
    assert not (workdir / "data").exists()


def test_the_confirmation_trains_fresh_networks_on_the_main_runs_demonstrations_and_maps(
    built, tmp_path
):
    """Config robot.confirmation (issue 24): the confirmed variant is a run of its own whose
    networks are the fresh indices first_network.., trained from the main run's demonstrations
    and maps (none of its own), mapping by place in the run (first half A), tested on the
    robot; its networks start from other weights than the exploration's, so they end elsewhere
    (the exploration's, which this build does not train, trained here from the same files).
    Planned from scratch, the run's jobs are one training job and one robot job; the table has
    the fresh networks' row alone (issue 47: robot.default is empty, so the build tests the
    variant on no other networks)."""
    import numpy as np
    import pandas as pd

    from icub_affordance.learning.materials import load_materials
    from icub_workflow.parts import load_weights
    from icub_workflow.runs import plan_runs
    from icub_workflow.steps import train_part

    config = load_test_config()
    confirmation = config["robot"]["confirmation"]
    first, count = confirmation["first_network"], confirmation["networks"]
    explored, run = "robot_commands_h10_it1200", "robot_commands_h10_it1200_confirm"
    nets = [f"{i:02d}" for i in range(first, first + count)]
    # the plan: the run's networks, from the main run's demonstrations and maps
    plan = run_snakemake(scratch_workflow(tmp_path / "w"), "-n").stdout
    jobs = [job for job in re.split(r"^(?=rule \w+:$)", plan, flags=re.M) if f"runs/{run}/" in job]
    trainings = [job for job in jobs if "rule train:" in job]  # one job, its part `all`
    assert len(trainings) == 1
    for job in trainings:
        inputs = re.search(r"input: (.*)", job)[1].split(", ")
        assert "data/demos/demos.npz" in inputs and "data/soms/soms.npz" in inputs, job
    assert f"data/runs/{run}/demos" not in plan and f"data/runs/{run}/soms" not in plan
    assert f"data/runs/{run}/train/all/weights.npz" in plan
    assert sum("rule robot_test:" in job for job in jobs) == 1  # its part `all`
    assert f"data/runs/{run}/embodied/all/trials.csv" in plan
    assert f"data/runs/{explored}/" not in plan  # the exploration is not part of this build
    # the built run: fresh networks, unlike the exploration's at 0.., their trials, the table
    data = built / "data"
    materials = load_materials(*(data / f for f in (
        "vision/visual_maps.npz", "soms/soms.npz", "demos/demos.npz")))  # fmt: skip
    network = plan_runs(config | {"robustness": False}).config(explored)["network"]
    (tmp_path / "all").mkdir()
    explored_files = [str(tmp_path / "all" / name) for name in ("curve.csv", "weights.npz")]
    train_part(materials, network, config["seed"], "all", *explored_files)
    old = load_weights(explored_files[1:])
    fresh = dict(load_weights([str(data / f"runs/{run}/train/all/weights.npz")]))
    assert sorted(fresh) == [int(net) for net in nets] and len(old) == count
    for net, (_, weights) in zip(nets, old, strict=True):
        assert fresh[int(net)].W1.shape == weights.W1.shape
        assert not np.allclose(fresh[int(net)].W1, weights.W1)
    trials = pd.read_csv(built / "data/embodied/confirmation_trials.csv")
    assert sorted(trials["network"].unique()) == list(range(first, first + count))
    mapping = trials.drop_duplicates("network").set_index("network")["mapping"]
    assert list(mapping) == ["A"] * (count // 2) + ["B"] * (count // 2)
    table = pd.read_csv(built / "data/embodied/confirmation.csv")
    assert list(table["seed_set"]) == ["confirmation"] and list(table["run"]) == [run]
    assert list(table["networks"]) == [count] and list(table["trials"]) == [4 * count]
    span = table["first_network"].item(), table["last_network"].item()
    assert span == (first, first + count - 1)


@pytest.mark.dryrun  # runs Snakemake
def test_the_paper_target_makes_the_papers_model_alone(tmp_path):
    """`snakemake paper`: the config's own run (demonstrations, maps, 12 networks, tests, ANOVA,
    Figures 1-5), nothing of the other runs, the robot, the readings, the size study or the
    book."""
    workdir = scratch_workflow(tmp_path / "w")
    config = REPO / "config" / "config.yaml"
    jobs = planned(run_snakemake(workdir, "-n", "paper", config=config))
    assert jobs.pop("train") == 12
    expected = {"visual_maps", "body_figure", "figure3", "demos", "demo_filmstrip", "soms",
                "figure2_maps", "figure2_architecture", "evaluate", "stats", "figure4",
                "figure5", "measures", "paper"}  # fmt: skip
    assert set(jobs) == expected and all(count == 1 for count in jobs.values()), jobs
