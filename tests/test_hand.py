"""Figure 1's 16 actuators, their ranges, and the under-actuated hand's couplings."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from conftest import initial_posture_deg

from icub_affordance.body.robot import DOF_NAMES, N_ARM_DOF, N_DOF, to_degrees, to_normalised

# The paper's Figure 1, typed from the paper: (actuator, min deg, max deg).
FIGURE1_TABLE = [
    ("shoulder_pitch", -95, 90),
    ("shoulder_roll", 0, 161),
    ("shoulder_yaw", -37, 100),
    ("elbow", 6, 106),
    ("wrist_prosup", -90, 90),
    ("wrist_pitch", -90, 10),
    ("wrist_yaw", -20, 40),
    ("hand_finger", -20, 30),
    ("thumb_oppose", -15, 105),
    ("thumb_proximal", 0, 90),
    ("thumb_distal", 0, 90),
    ("index_proximal", 0, 90),
    ("index_distal", 0, 90),
    ("middle_proximal", 0, 90),
    ("middle_distal", 0, 90),
    ("ring_little", 0, 115),
]

# Which joints each hand motor drives on the iCub (its public hand documentation; docs/pipeline.md,
# "The simulated iCub").
HAND_COUPLING = {
    "hand_finger": {"r_index_abduction", "r_ring_abduction", "r_little_abduction"},
    "thumb_oppose": {"r_thumb_oppose"},
    "thumb_proximal": {"r_thumb_proximal"},
    "thumb_distal": {"r_thumb_middle", "r_thumb_distal"},
    "index_proximal": {"r_index_proximal"},
    "index_distal": {"r_index_middle", "r_index_distal"},
    "middle_proximal": {"r_middle_proximal"},
    "middle_distal": {"r_middle_middle", "r_middle_distal"},
    "ring_little": {
        "r_ring_proximal",
        "r_ring_middle",
        "r_ring_distal",
        "r_little_proximal",
        "r_little_middle",
        "r_little_distal",
    },
}
# An arm posture with the hand in free air, well above the table: the initial posture's arm.
FREE_ARM = initial_posture_deg()[:N_ARM_DOF]


def hand_joints(model) -> list[str]:
    names = [model.joint(j).name for j in range(model.njnt)]
    return [
        n
        for n in names
        if n.startswith("r_") and n.split("_")[1] in {"thumb", "index", "middle", "ring", "little"}
    ]


def test_sixteen_position_actuators_in_figure1_order_with_its_ranges(robot):
    m = robot.model
    assert m.nu == 16
    assert [m.actuator(i).name for i in range(m.nu)] == [row[0] for row in FIGURE1_TABLE]
    assert DOF_NAMES == tuple(row[0] for row in FIGURE1_TABLE)
    for i, (_, lo, hi) in enumerate(FIGURE1_TABLE):
        assert m.actuator_dyntype[i] == mujoco.mjtDyn.mjDYN_NONE
        assert m.actuator_gainprm[i, 0] > 0 and m.actuator_biasprm[i, 1] < 0  # a position servo
        np.testing.assert_allclose(np.degrees(m.actuator_ctrlrange[i]), [lo, hi], atol=1e-9)
        joint = m.actuator_trnid[i, 0]
        np.testing.assert_allclose(np.degrees(m.jnt_range[joint]), [lo, hi], atol=1e-9)


def test_the_hand_has_nineteen_joints(robot):
    assert len(hand_joints(robot.model)) == 19


def test_normalisation_round_trip():
    lo = np.array([row[1] for row in FIGURE1_TABLE], dtype=float)
    hi = np.array([row[2] for row in FIGURE1_TABLE], dtype=float)
    np.testing.assert_allclose(to_normalised(lo), 0.0)
    np.testing.assert_allclose(to_normalised(hi), 1.0)
    x = np.random.default_rng(1).uniform(0, 1, N_DOF)
    np.testing.assert_allclose(to_normalised(to_degrees(x)), x)


def settle_with_motor(robot, motor: str, value_deg: float) -> dict[str, float]:
    """Start from an open hand in free air, drive one motor in physics, return hand joint angles."""
    start = np.zeros(N_DOF)
    start[:7] = FREE_ARM
    robot.set_posture_deg(start)
    target = start.copy()
    target[DOF_NAMES.index(motor)] = value_deg
    robot.command_deg(target)
    robot.step(1500)  # 3 s
    m = robot.model
    return {
        n: float(np.degrees(robot.data.qpos[m.jnt_qposadr[m.joint(n).id]])) for n in hand_joints(m)
    }


@pytest.mark.parametrize("motor", sorted(HAND_COUPLING))
def test_each_hand_motor_moves_exactly_its_joints_over_its_whole_range(robot, motor):
    lo, hi = next((row[1], row[2]) for row in FIGURE1_TABLE if row[0] == motor)
    for value in (lo, hi):
        angles = settle_with_motor(robot, motor, value)
        for joint, angle in angles.items():
            expected = value if joint in HAND_COUPLING[motor] else 0.0
            assert angle == pytest.approx(expected, abs=2.0), (motor, value, joint)


def test_arm_servos_track_a_commanded_posture(robot):
    start = np.zeros(N_DOF)
    start[:7] = FREE_ARM
    robot.set_posture_deg(start)
    target = start.copy()
    target[:7] = [-30, 40, 20, 50, 30, -20, 10]
    robot.command_deg(target)
    robot.step(1500)
    np.testing.assert_allclose(robot.posture_deg(), target, atol=1.0)
