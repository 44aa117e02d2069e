"""The MJCF files: the scene includes the robot file, and both loaders read the same model."""

from __future__ import annotations

import mujoco
import numpy as np
from conftest import REPO

from icub_affordance.body import OBJECT_NAMES

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
