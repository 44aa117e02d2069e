"""Trust: identical reruns (also -c1 vs -c2 and after a kill), rerun scope, errors on bad input."""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import yaml
from conftest import REPO, TEST_CONFIG, load_test_config, run_snakemake, scratch_workflow

from icub_affordance.body.robot import Robot
from icub_affordance.files import load_npz
from icub_workflow.sweep_timing import planned_jobs

COMPARED = [
    "data/vision/visual_maps.npz",
    "data/demos/demos.npz",
    "data/soms/soms.npz",
    "data/eval/trials.csv",
    "data/eval/anova.json",
]


@pytest.mark.reruns
def test_killed_and_resumed_single_core_run_equals_the_two_core_run(built, tmp_path):
    """A run with -c1, killed hard part-way and resumed, gives byte-identical outputs."""
    workdir = scratch_workflow(tmp_path)
    cmd = [sys.executable, "-m", "snakemake", "data/eval/anova.json", "-c1"]
    cmd += ["--configfile", str(TEST_CONFIG)]  # last: --configfile takes several values
    proc = subprocess.Popen(
        cmd,
        cwd=workdir,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        start_new_session=True,
    )
    deadline = time.time() + 240
    while not (workdir / "data/train/net00/curve.csv").exists() and time.time() < deadline:
        time.sleep(0.2)
    assert proc.poll() is None, "the run ended before it could be killed"
    os.killpg(proc.pid, signal.SIGKILL)  # a hard kill, as by a power cut
    proc.wait()
    assert not (workdir / "data/eval/anova.json").exists(), "killed too late to test a resume"
    for npz in (workdir / "data").rglob("*.npz"):
        load_npz(npz)  # whatever exists is whole: outputs are written atomically
    # what a user does after a hard kill: release Snakemake's lock, then resume
    assert run_snakemake(workdir, "--unlock").returncode == 0
    resumed = run_snakemake(workdir, "-c1", "--rerun-incomplete", "data/eval/anova.json")
    assert resumed.returncode == 0, resumed.stderr[-3000:]
    nets = sorted(p.name for p in (built / "data/train").iterdir())
    for name in COMPARED + [
        f"data/train/{n}/{f}" for n in nets for f in ("curve.csv", "weights.npz")
    ]:
        assert (workdir / name).read_bytes() == (built / name).read_bytes(), name


def changed_config(tmp_path: Path, change) -> Path:
    config = load_test_config()
    change(config)
    path = tmp_path / "changed.yaml"
    path.write_text(yaml.safe_dump(config))
    return path


@pytest.mark.dryrun
def test_a_training_hyperparameter_reruns_training_and_after_but_not_the_data(built, tmp_path):
    path = changed_config(tmp_path, lambda c: c["network"].update(learning_rate=0.05))
    plan = run_snakemake(built, "-n", config=path)
    jobs = planned_jobs(plan.stdout)
    config = load_test_config()
    confirmation = config["robot"]["confirmation"]
    # a job per network of the main run; the cue ablation's, each confirmation's and each words
    # replication's in one
    words = len(config["words"]["seeds"]) * len(config["words"]["cues"])
    assert jobs.get("train") == (
        config["network"]["networks"] + 1 + len(confirmation["variants"]) + words
    )
    for rule in ("evaluate", "stats", "figure5"):  # the main run and the cue ablation
        assert jobs.get(rule) == 2, (rule, jobs)
    for rule in ("figure4", "book"):
        assert jobs.get(rule) == 1, (rule, jobs)
    for rule in ("visual_maps", "soms", "body_figure", "demos"):
        assert rule not in jobs, (rule, jobs)


@pytest.mark.dryrun
def test_the_cue_timing_reruns_training_too(built, tmp_path):
    def change(c):
        c["network"].update(categorisation_cue="all_steps")
        # the robot grid and the animated variant follow (the test config names its cue timing)
        c["robot"].update(categorisation_cue=["all_steps"])
        c["robot"]["animation"]["variant"].update(categorisation_cue="all_steps")
        for variant in c["robot"]["confirmation"]["variants"]:  # so does the confirmation's
            variant.update(categorisation_cue="all_steps")

    path = changed_config(tmp_path, change)
    jobs = planned_jobs(run_snakemake(built, "-n", config=path).stdout)
    assert "train" in jobs and "demos" not in jobs and "soms" not in jobs


@pytest.mark.dryrun
def test_an_object_size_reruns_from_the_scene_on(built, tmp_path):
    path = changed_config(tmp_path, lambda c: c["object_sizes_m"].update(big_ball=0.065))
    jobs = planned_jobs(run_snakemake(built, "-n", config=path).stdout)
    for rule in ("body_figure", "visual_maps", "demos", "soms", "train", "book"):
        assert rule in jobs, (rule, jobs)


@pytest.mark.dryrun
def test_a_plot_setting_reruns_only_the_plot(built, tmp_path):
    path = changed_config(
        tmp_path, lambda c: c["figures"].update(filmstrip=[["small_ball", "power", 1]])
    )
    jobs = planned_jobs(run_snakemake(built, "-n", config=path).stdout)
    assert set(jobs) <= {"demo_filmstrip", "book", "all", "rulegraph", "rulegraph_figure"}, jobs


@pytest.mark.dryrun
@pytest.mark.parametrize(
    ("change", "words"),
    [
        (lambda c: c["network"].update(learning_rate=-0.1), ["learning_rate", "minimum"]),
        (lambda c: c["figures"].update(filmstrip=[["big_ball", "pinch", 0]]), ["pinch", "power"]),
        (lambda c: c.update(objects=["big_ball", "pear"]), ["pear", "small_cube"]),
        (lambda c: c["network"].pop("hidden"), ["hidden", "required"]),
        (lambda c: c["network"].update(iterations="many"), ["many", "integer"]),
        (lambda c: c["network"].update(categorisation_cue="sometimes"), ["sometimes", "all_steps"]),
        # rules between keys (src/icub_workflow/config_checks.py), checked when the config is read
        (lambda c: c["network"].update(phase1_iterations=1300), ["phase1_iterations", "1300"]),
        (lambda c: c["vision"].update(window=300), ["vision.window", "300", "320x240"]),
        (
            lambda c: c["initial_posture_deg"].__setitem__(3, 150),
            ["initial_posture_deg[3]", "150", "elbow", "6..106", "Fix"],
        ),
        (
            lambda c: c["figures"].update(filmstrip=[["big_ball", "power", 7]]),
            ["figures.filmstrip[0]", "7", "0..4"],
        ),
        (lambda c: c["runs"].update(x={"network": {"phase1_iterations": 5000}}), ["runs.x."]),
        (lambda c: c.update(scene="assets/icub_right_arm.xml"), ["config key scene", "Fix"]),
        # a declared test no run backs (issue 57)
        (
            lambda c: c["readings"].update(categorisation_cue=["first_step"]),
            ["confirmation.cues", "all_steps", "Fix"],
        ),
    ],
)
def test_bad_config_stops_before_any_job_naming_key_and_allowed_values(tmp_path, change, words):
    workdir = scratch_workflow(tmp_path / "w")
    # the bad file replaces the default config itself, so that a missing key is really missing
    (workdir / "config").unlink()
    (workdir / "config").mkdir()
    shutil.copy(changed_config(tmp_path, change), workdir / "config" / "config.yaml")
    shutil.copy(REPO / "config" / "confirmation_pilot.csv", workdir / "config")
    result = run_snakemake(workdir, "-c1", config=workdir / "config" / "config.yaml")
    assert result.returncode != 0
    message = result.stdout + result.stderr
    for word in words:
        assert word in message, (word, message[-2000:])
    assert not (workdir / "data").exists()


@pytest.mark.dryrun
def test_a_missing_scene_is_named_before_any_job(tmp_path):
    workdir = scratch_workflow(tmp_path / "w")
    path = changed_config(tmp_path, lambda c: c.update(scene="assets/missing.xml"))
    result = run_snakemake(workdir, "-c1", config=path)
    assert result.returncode != 0
    assert "assets/missing.xml" in result.stdout + result.stderr


def test_a_missing_or_broken_scene_file_gives_a_clear_error(tmp_path):
    with pytest.raises(FileNotFoundError, match="git checkout"):
        Robot(tmp_path / "nothing.xml")
    broken = tmp_path / "broken.xml"
    broken.write_text("<mujoco><worldbody><body></mujoco>")
    with pytest.raises(ValueError, match="broken.xml"):
        Robot(broken)


@pytest.mark.parametrize("name", ["data/demos/demos.npz", "data/train/net00/weights.npz"])
def test_a_truncated_file_is_named_with_what_to_do(built, tmp_path, name):
    bad = tmp_path / Path(name).name
    data = (built / name).read_bytes()
    bad.write_bytes(data[: len(data) // 2])
    with pytest.raises(ValueError, match=re.escape(str(bad)) + ".*rerun"):
        load_npz(bad)
    with pytest.raises(FileNotFoundError, match="rerun"):
        load_npz(tmp_path / "gone.npz")


@pytest.mark.reruns
def test_a_corrupt_weights_file_fails_the_evaluation_and_keeps_the_old_trials(built, tmp_path):
    copy = tmp_path / "copy"
    shutil.copytree(built, copy, symlinks=True)
    (copy / "data/eval/trials.csv").read_bytes()
    weights = copy / "data/train/net00/weights.npz"
    weights.write_bytes(weights.read_bytes()[:100])
    result = run_snakemake(copy, "-c1", "data/eval/trials.csv", "--forcerun", "evaluate")
    assert result.returncode != 0
    log = (copy / "data/logs/evaluate.log").read_text()
    assert "weights.npz" in log and "rerun" in log
    assert not list((copy / "data/eval").glob(".*"))  # no half-written temporary files


def test_loading_never_unpickles():
    sources = [p.read_text() for p in (REPO / "src").rglob("*.py")]
    sources += [p.read_text() for p in (REPO / "workflow/scripts").glob("*.py")]
    for text in sources:
        assert "allow_pickle=True" not in text
        assert "import pickle" not in text
        assert "torch.load(" not in text


def test_object_sizes_change_the_scene():
    robot = Robot(object_sizes={"big_ball": 0.06})
    assert robot.model.geom("big_ball").size[0] == pytest.approx(0.03)
    default = Robot()
    ratio = robot.model.body("big_ball").mass[0] / default.model.body("big_ball").mass[0]
    assert ratio == pytest.approx((0.06 / 0.07) ** 3)
    with pytest.raises(ValueError, match="pear"):
        Robot(object_sizes={"pear": 0.05})
    np.testing.assert_allclose(default.model.geom("big_ball").size[0], 0.035)


def data_files(workdir: Path) -> dict[str, bytes]:
    """Every file of a run under data/, logs and benchmarks aside, by path."""
    return {
        str(p.relative_to(workdir)): p.read_bytes()
        for p in sorted((workdir / "data").rglob("*"))
        if p.is_file() and p.relative_to(workdir / "data").parts[0] not in ("logs", "benchmarks")
    }


def default_targets(workdir: Path) -> set[str]:
    """The files the default target `all` names in `workdir`, from a forced dry run's plan."""
    plan = run_snakemake(workdir, "-n", "--force", "all", "-c1")
    assert plan.returncode == 0, plan.stderr[-2000:]
    block = plan.stdout.split("rule all:", 1)[1]
    return set(re.search(r"input: (.*)", block)[1].split(", "))


@pytest.mark.dryrun
def test_the_default_target_names_the_book_and_every_missing_file(built, tmp_path):
    """Snakemake remakes a missing file only if a job still to run needs it. On a finished
    build the default target names the book and the manifest (which reach every job), not every
    intermediate file; once files are deleted, it names each of them, so each is remade."""
    summary = run_snakemake(built, "--summary", "-c1")
    assert summary.returncode == 0, summary.stderr[-2000:]
    made = {line.split("\t")[0] for line in summary.stdout.splitlines()[1:] if line.strip()}
    made = {f for f in made if not f.startswith(("data/logs/", "data/benchmarks/"))}
    finished = default_targets(built)
    assert {"book/_build/html/index.html", "data/results.sha256"} <= finished <= made
    assert "data/train/net01/weights.npz" not in finished and len(finished) < len(made) / 4
    copy = tmp_path / "copy"
    shutil.copytree(built, copy, symlinks=True)
    for name in made:  # a measured group's folder is one output (rule measured)
        shutil.rmtree(copy / name) if (copy / name).is_dir() else (copy / name).unlink()
    named = default_targets(copy)
    assert made - named == set()
    # every file of the finished run, or the folder output it lies in
    unnamed = {f for f in data_files(built) if not any(f == n or f.startswith(f"{n}/")
                                                       for n in named)}  # fmt: skip
    assert unnamed == set()


@pytest.mark.reruns
def test_deleted_intermediate_files_are_remade_byte_identically(built, tmp_path):
    copy = tmp_path / "copy"
    shutil.copytree(built, copy, symlinks=True)
    for name in ("data/soms/soms.npz", "data/eval/trials.csv", "data/train/net01/weights.npz"):
        (copy / name).unlink()
    result = run_snakemake(copy, "-c2")
    assert result.returncode == 0, result.stderr[-3000:]
    assert data_files(copy) == data_files(built)


@pytest.mark.reruns
def test_following_the_advice_for_a_corrupt_file_restores_the_run(built, tmp_path):
    """A corrupt file: the job that reads it fails saying "delete it and rerun `snakemake -c2`";
    doing exactly that gives back every file, byte for byte."""
    copy = tmp_path / "copy"
    shutil.copytree(built, copy, symlinks=True)
    weights = copy / "data/train/net01/weights.npz"
    weights.write_bytes(weights.read_bytes()[:100])
    failed = run_snakemake(copy, "-c1", "--forcerun", "evaluate")
    assert failed.returncode != 0
    # the first job to read it fails (the evaluation, or the robot test of that network)
    logs = "".join(p.read_text() for p in sorted((copy / "data/logs").rglob("*.log")))
    advice = re.search(
        r"(\S+) is corrupt or truncated .*; delete it and rerun `(snakemake -c2)`", logs
    )
    assert advice, failed.stdout[-3000:]
    (copy / advice[1]).unlink()  # delete it ...
    rerun = run_snakemake(copy, *advice[2].split()[1:])  # ... and rerun `snakemake -c2`
    assert rerun.returncode == 0, rerun.stderr[-3000:]
    assert data_files(copy) == data_files(built)


@pytest.mark.dryrun
def test_a_broken_benchmark_file_advice_rewrites_every_benchmark_the_timeline_reads(
    built, tmp_path
):
    """The timeline refuses a broken benchmark file and advises a complete run from scratch.
    The advised command, as a dry run, reruns every job whose benchmark the build holds (the
    broken one included); and a complete run's benchmark files, the build's own, make a working
    timeline. (Running the advice itself would rebuild the whole test pipeline a second time.)"""
    copy = tmp_path / "copy"
    shutil.copytree(built, copy, symlinks=True)
    (copy / "data/benchmarks/figure4.tsv").write_text("not a benchmark\n")
    timeline = [sys.executable, str(REPO / "benchmarks/timeline.py"), "data/benchmarks"]
    failed = subprocess.run(timeline, cwd=copy, capture_output=True, text=True)
    advice = re.search(r"`(snakemake -c2 --forceall)`", failed.stderr)
    assert failed.returncode != 0 and advice, failed.stderr
    plan = run_snakemake(copy, *advice[1].split()[1:], "-n")
    assert plan.returncode == 0, plan.stderr[-3000:]
    rewritten = set(re.findall(r"benchmark: (\S+)", plan.stdout))
    held = {str(p.relative_to(copy)) for p in (copy / "data/benchmarks").rglob("*.tsv")}
    assert "data/benchmarks/figure4.tsv" in rewritten and held <= rewritten, held - rewritten
    assert subprocess.run(timeline, cwd=built, capture_output=True).returncode == 0


@pytest.mark.dryrun
def test_the_sweep_is_a_target_with_robustness_and_no_job_starts_snakemake(built):
    plan = run_snakemake(built, "-n", "--force", "all", "-c1", "--config", "robustness=True")
    targets = set(re.search(r"input: (.*)", plan.stdout.split("rule all:", 1)[1])[1].split(", "))
    assert not [t for t in targets if t.startswith("data/benchmarks/")]  # no cost measured apart
    assert "rule sweep_cost" not in plan.stdout
    assert "data/sweep/points.csv" in targets
    assert any(t.startswith("data/runs/sweep_seed1_") and "weights.npz" in t for t in targets)


@pytest.mark.dryrun
def test_another_scene_path_reruns_everything_that_loads_the_scene(built, tmp_path):
    scene = built / "moved_scene"
    scene.mkdir(exist_ok=True)
    for name in ("icub_scene.xml", "icub_right_arm.xml"):
        shutil.copy(REPO / "assets" / name, scene / name)
    plan = run_snakemake(built, "-n", "-c1", "--config", "scene=moved_scene/icub_scene.xml")
    shutil.rmtree(scene)
    assert plan.returncode == 0, plan.stderr[-2000:]
    jobs = planned_jobs(plan.stdout)
    for rule in ("body_figure", "visual_maps", "demos", "demo_filmstrip", "robot_test"):
        assert rule in jobs, (rule, jobs)


@pytest.mark.dryrun
def test_a_nested_command_line_override_means_what_the_config_file_would(tmp_path):
    workdir = scratch_workflow(tmp_path / "w")
    for entry in ("network={networks: 6}", "runs={x: {network: {learning_rate: 0.0375}}}"):
        result = run_snakemake(workdir, "-n", "-c1", "--config", entry)
        assert result.returncode == 0, (entry, result.stderr[-2000:])
    assert "data/runs/x/train/all/weights.npz" in result.stdout  # its networks in one job
    result = run_snakemake(workdir, "-n", "-c1", "--config", "network={phase1_iterations: 1300}")
    message = result.stdout + result.stderr
    assert result.returncode != 0 and "network.phase1_iterations: 1300" in message, message
