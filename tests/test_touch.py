"""The six touch sensors read contact where the hand touches an object, and nothing in free air."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import initial_posture_deg

from icub_affordance.body.robot import N_ARM_DOF, N_DOF, TOUCH_NAMES

FREE_ARM = initial_posture_deg()[:N_ARM_DOF]  # the initial posture's arm: the hand in free air
PALM_UP_ARM = [-40, 30, 0, 100, -90, -60, 0]  # palm normal within 12 degrees of vertical


def open_hand(robot, arm) -> None:
    posture = np.zeros(N_DOF)
    posture[:7] = arm
    robot.set_posture_deg(posture)


def test_touch_reads_zero_in_free_air(robot):
    open_hand(robot, FREE_ARM)
    robot.command_deg(robot.posture_deg())
    robot.step(250)
    np.testing.assert_array_equal(robot.touch(), np.zeros(len(TOUCH_NAMES)))


@pytest.mark.parametrize("sensor", TOUCH_NAMES)
def test_an_object_pressed_on_one_pad_reads_on_that_sensor_only(robot, sensor):
    """A small ball pushed 1 mm into one pad, on the palmar side, loads that sensor alone."""
    robot.model.opt.gravity[:] = 0
    open_hand(robot, FREE_ARM)
    robot.place_object("small_ball")
    _, palm_rot = robot.palm_pose()
    palmar = palm_rot[:, 2]  # the palm frame's z: out of the palm
    site = robot.model.site(f"{sensor}_site").id
    radius = robot.model.geom("small_ball").size[0]
    # the middle of the pad the site covers, offset along the palmar normal, 1 mm too close
    pad_depth = 0.0 if sensor == "touch_palm" else robot.model.geom("r_index_tip").size[0]
    centre = robot.data.site_xpos[site] + palmar * (radius + pad_depth - 0.001)
    adr = robot.object_qpos["small_ball"]
    robot.data.qpos[adr : adr + 3] = centre
    robot.step(1)
    touch = dict(zip(TOUCH_NAMES, robot.touch(), strict=True))
    assert touch[sensor] > 0.0
    assert all(value == 0.0 for name, value in touch.items() if name != sensor), touch


def test_palm_feels_the_weight_of_a_cube_resting_in_it(robot):
    """Physics, not geometry: a 10 g cube in the upturned palm loads touch_palm with its weight."""
    open_hand(robot, PALM_UP_ARM)
    robot.place_object("small_cube")
    palm, rot = robot.palm_pose()
    centre = palm + rot @ [-0.03, 0, 0] + rot[:, 2] * 0.016
    adr = robot.object_qpos["small_cube"]
    robot.data.qpos[adr : adr + 3] = centre
    robot.step(1000)  # 2 s to settle
    assert np.linalg.norm(robot.object_position("small_cube") - centre) < 0.02  # still in the palm
    weight = robot.model.body("small_cube").mass[0] * 9.81
    palm_force = robot.touch()[TOUCH_NAMES.index("touch_palm")]
    assert palm_force == pytest.approx(weight, rel=0.25)
