"""The MJCF files: the scene includes the robot file, and both loaders read the same model."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import REPO, initial_posture_deg

from icub_affordance.body.robot import OBJECT_NAMES, Robot
from icub_workflow.scene_files import scene_files

SCENE = REPO / "assets" / "icub_scene.xml"
ROBOT = REPO / "assets" / "icub_right_arm.xml"


def body_names(model: mujoco.MjModel) -> list[str]:
    return [model.body(i).name for i in range(model.nbody)]


def test_both_loaders_resolve_the_include_to_the_same_model():
    from_xml = mujoco.MjModel.from_xml_path(str(SCENE))
    from_spec = mujoco.MjSpec.from_file(str(SCENE)).compile()
    for model in (from_xml, from_spec):
        assert model.nu == 16 and model.nsensor == 6 and model.neq == 10
        assert model.camera("left_eye").id >= 0 and model.body("big_ball").id >= 0
    assert from_xml.names == from_spec.names
    for name in ("body_pos", "jnt_range", "geom_size", "actuator_gainprm", "eq_solref", "qpos0"):
        np.testing.assert_array_equal(getattr(from_xml, name), getattr(from_spec, name))


def test_the_robot_keeps_its_place_between_the_table_and_the_objects():
    names = body_names(mujoco.MjModel.from_xml_path(str(SCENE)))
    assert names[:3] == ["world", "table", "root"]
    assert names[-5:] == ["gaze_target", *OBJECT_NAMES]


def test_the_robot_file_compiles_alone():
    robot = mujoco.MjModel.from_xml_path(str(ROBOT))
    scene = mujoco.MjModel.from_xml_path(str(SCENE))
    assert body_names(robot) == [n for n in body_names(scene) if n not in ("table", *OBJECT_NAMES)]
    assert robot.nu == scene.nu and robot.nq == scene.nq - 7 * len(OBJECT_NAMES)


def test_the_initial_keyframe_is_the_configured_initial_posture(robot):
    posture = initial_posture_deg()  # config/config.yaml
    key = robot.model.key("initial")
    np.testing.assert_allclose(robot.keyframe_deg("initial"), posture, rtol=0, atol=1e-9)
    np.testing.assert_allclose(np.degrees(key.ctrl), posture, rtol=0, atol=1e-9)
    # the whole state: followers equal to their leads, the objects where the scene puts them
    data = mujoco.MjData(robot.model)
    robot.write_posture(data, posture)
    np.testing.assert_allclose(key.qpos, data.qpos, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(key.qvel, 0.0)


def test_the_keyframe_leaves_resized_objects_where_the_scene_puts_them():
    robot = Robot(object_sizes={"big_ball": 0.09})
    key = robot.model.key("initial")
    n_robot = robot.model.nq - 7 * len(OBJECT_NAMES)
    np.testing.assert_array_equal(key.qpos[n_robot:], robot.model.qpos0[n_robot:])
    assert key.qpos[robot.object_qpos["big_ball"] + 2] == 0.045  # resting on the floor
    robot.close()


def test_an_unknown_keyframe_is_named(robot):
    with pytest.raises(ValueError, match="no keyframe 'home'.*initial"):
        robot.keyframe_deg("home")


def test_scene_files_lists_the_scene_and_the_robot_file(monkeypatch):
    assert scene_files(SCENE) == [SCENE, ROBOT]
    monkeypatch.chdir(REPO)
    assert scene_files("assets/icub_scene.xml") == [  # relative paths stay relative
        Path("assets/icub_scene.xml"),
        Path("assets/icub_right_arm.xml"),
    ]


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def body_file(name: str) -> str:
    return f'<mujoco><worldbody><body name="{name}"/></worldbody></mujoco>'


def test_scene_files_finds_nested_includes_where_mujoco_does(tmp_path):
    scene = write(
        tmp_path / "scene.xml",
        '<mujoco><include file="parts/a.xml"/>'
        '<worldbody><include file="parts/c.xml"/></worldbody></mujoco>',
    )
    a = write(tmp_path / "parts" / "a.xml", '<mujoco><include file="b.xml"/></mujoco>')
    b = write(tmp_path / "parts" / "b.xml", body_file("b"))
    c = write(tmp_path / "parts" / "c.xml", '<mujoco><body name="c"/></mujoco>')
    assert scene_files(scene) == [scene, a, b, c]
    assert body_names(mujoco.MjModel.from_xml_path(str(scene))) == ["world", "b", "c"]
    # MuJoCo looks in the scene's directory first, then in the including file's
    top_b = write(tmp_path / "b.xml", body_file("top_b"))
    assert scene_files(scene) == [scene, a, top_b, c]
    assert body_names(mujoco.MjModel.from_xml_path(str(scene))) == ["world", "top_b", "c"]


def test_scene_files_names_a_missing_include(tmp_path):
    scene = write(tmp_path / "scene.xml", '<mujoco><include file="robot.xml"/></mujoco>')
    with pytest.raises(FileNotFoundError, match=r"robot\.xml, included by .*scene\.xml"):
        scene_files(scene)
    with pytest.raises(FileNotFoundError, match="missing.xml"):
        scene_files(tmp_path / "missing.xml")
