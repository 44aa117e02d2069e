"""The Snakemake pipeline: its config is checked, and the small test config runs end to end."""

from __future__ import annotations

import copy
import csv
import shutil
import subprocess
from pathlib import Path

import cv2
import numpy as np
import pytest
import yaml
from conftest import load_config, load_test_config, run_snakemake, scratch_workflow
from snakemake.utils import validate

REPO = Path(__file__).resolve().parents[1]
SCHEMA = REPO / "workflow" / "schemas" / "config.schema.yaml"


@pytest.fixture
def workdir(tmp_path: Path) -> Path:
    return scratch_workflow(tmp_path)


def snakemake(workdir: Path, *args: str) -> subprocess.CompletedProcess:
    return run_snakemake(workdir, *args)


@pytest.mark.parametrize("config", [load_config, load_test_config])
def test_shipped_configs_are_valid(config):
    validate(config(), str(SCHEMA))


@pytest.mark.parametrize(
    ("key", "value", "words"),
    [
        ("seed", -1, "minimum"),
        ("seed", "abc", "integer"),
        ("initial_posture_deg", [0] * 15, "short"),
        ("body_figure", {"object": "pear", "width": 320, "height": 240}, "pear"),
        ("unexpected_key", 1, "unexpected_key"),
    ],
)
def test_bad_config_values_are_refused_with_the_key_named(key, value, words):
    config = copy.deepcopy(load_config())
    config[key] = value
    with pytest.raises(Exception, match=words):
        validate(config, str(SCHEMA))


def test_missing_key_is_refused():
    config = load_config()
    del config["seed"]
    with pytest.raises(Exception, match="seed"):
        validate(config, str(SCHEMA))


@pytest.mark.dryrun
def test_bad_config_stops_the_run_before_any_job(workdir, tmp_path):
    bad = load_test_config()
    bad["seed"] = -5
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(bad))
    result = run_snakemake(workdir, "-n", config=path)
    assert result.returncode != 0
    assert "seed" in result.stderr + result.stdout
    assert not (workdir / "data").exists()


@pytest.mark.dryrun
def test_test_config_runs_end_to_end(built):
    workdir = built
    body = workdir / "data" / "body"
    config = load_test_config()["body_figure"]
    for name in ("figure1_scene.png", "figure1_eye.png"):
        image = cv2.imread(str(body / name))
        assert image.shape == (config["height"], config["width"], 3)
        assert image.std() > 10  # a picture, not a blank frame
    with open(body / "joint_table.csv") as f:
        rows = list(csv.DictReader(f))
    assert [r["actuator"] for r in rows][:4] == [
        "shoulder_pitch",
        "shoulder_roll",
        "shoulder_yaw",
        "elbow",
    ]
    assert len(rows) == 16
    assert rows[15]["max_deg"] == "115.0"
    assert len(rows[15]["driven_joints"].split()) == 6
    # the visual maps, keyed by object, binary 10x10, and Figure 3
    with np.load(workdir / "data" / "vision" / "visual_maps.npz", allow_pickle=False) as maps:
        assert sorted(maps.files) == sorted(load_test_config()["objects"])
        assert all(maps[k].shape == (10, 10) and maps[k].max() == 1 for k in maps.files)
    assert cv2.imread(str(workdir / "data" / "vision" / "figure3.png")).std() > 10
    # nothing left half-written beside the outputs
    for name in (
        "eval/anova.json",
        "eval/anova_table.md",
        "figures/figure4.png",
        "figures/figure5.png",
        "figures/conflict_timecourse.png",
        "soms/figure2_maps.png",
    ):
        assert (workdir / "data" / name).stat().st_size > 0, name
    for folder in ("body", "vision", "demos", "soms", "eval", "figures"):
        assert not list((workdir / "data" / folder).glob(".*")), folder
    assert cv2.imread(str(workdir / "data" / "demos" / "filmstrip.png")).std() > 10
    # a second run has nothing to do
    again = snakemake(workdir, "-c2", "-n")
    assert "Nothing to be done" in again.stdout + again.stderr


def replace_with_edited_copy(workdir: Path, relative: str) -> None:
    """Turn a symlinked file of the scratch workflow into a real copy with a new comment line."""
    parts = Path(relative).parts
    (workdir / parts[0]).unlink()
    shutil.copytree(REPO / parts[0], workdir / parts[0])
    target = workdir / relative
    comment = "<!-- edited -->\n" if target.suffix == ".xml" else "# edited\n"
    target.write_text(target.read_text() + comment)


BODY = "data/body/joint_table.csv"


@pytest.fixture(scope="module")
def body_made(tmp_path_factory) -> Path:
    """A scratch workflow in which the body rule has run (once for the three edits below)."""
    workdir = scratch_workflow(tmp_path_factory.mktemp("body"))
    result = snakemake(workdir, "-c1", BODY)
    assert result.returncode == 0, result.stderr[-3000:]
    return workdir


@pytest.mark.reruns
@pytest.mark.parametrize(
    "edited",
    ["assets/icub_scene.xml", "assets/icub_right_arm.xml", "src/icub_affordance/body/robot.py"],
)
def test_an_edit_of_the_scene_or_its_code_reruns_the_body_rule(body_made, tmp_path, edited):
    workdir = tmp_path / "w"
    shutil.copytree(body_made, workdir, symlinks=True)  # the times kept: the outputs stay new
    assert "Nothing to be done" in snakemake(workdir, "-n", BODY).stdout
    replace_with_edited_copy(workdir, edited)
    plan = snakemake(workdir, "-n", BODY)
    assert "body_figure" in plan.stdout, plan.stdout
