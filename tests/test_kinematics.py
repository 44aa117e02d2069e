"""The MuJoCo arm is the iCub's: the palm frame agrees with an independent iKin DH chain."""

from __future__ import annotations

import numpy as np
import pytest

from icub_affordance.body.robot import N_DOF

# iKin right arm, version 1 (the iCub's public iKin tables; docs/pipeline.md, "The simulated
# iCub"), typed here independently of the MJCF: (a, d, alpha, offset) per link, angles in
# degrees. Links 0-2 are the torso, held at 0.
DH = [
    (0.032, 0.0, 90, 0),
    (0.0, -0.0055, 90, -90),
    (-0.0233647, -0.1433, 90, -105),
    (0.0, -0.10774, 90, -90),
    (0.0, 0.0, -90, -90),
    (-0.015, -0.15228, -90, -105),
    (0.015, 0.0, 90, 0),
    (0.0, -0.1373, 90, -90),
    (0.0, 0.0, 90, 90),
    (0.0625, 0.016, 0, 180),
]
H0 = np.array([[0, -1, 0, 0], [0, 0, -1, 0], [1, 0, 0, 0], [0, 0, 0, 1]], dtype=float)
ARM_RANGES = [(-95, 90), (0, 161), (-37, 100), (6, 106), (-90, 90), (-90, 10), (-20, 40)]


def dh_link(theta: float, a: float, d: float, alpha: float) -> np.ndarray:
    ct, st, ca, sa = np.cos(theta), np.sin(theta), np.cos(alpha), np.sin(alpha)
    return np.array(
        [
            [ct, -st * ca, st * sa, a * ct],
            [st, ct * ca, -ct * sa, a * st],
            [0, sa, ca, d],
            [0, 0, 0, 1],
        ]
    )


def ikin_palm(arm_deg: np.ndarray) -> np.ndarray:
    """Palm frame in the iCub root frame for the 7 arm angles (torso at zero)."""
    thetas = np.radians(np.concatenate([[0, 0, 0], arm_deg]))
    T = H0.copy()
    for theta, (a, d, alpha, offset) in zip(thetas, DH, strict=True):
        T = T @ dh_link(theta + np.radians(offset), a, d, np.radians(alpha))
    return T


def mujoco_palm_in_root(robot, arm_deg: np.ndarray) -> np.ndarray:
    posture = np.zeros(N_DOF)
    posture[3] = 6.0
    posture[:7] = arm_deg
    robot.set_posture_deg(posture)
    pos, rot = robot.palm_pose()
    root = robot.data.body("root")
    T_root = np.eye(4)
    T_root[:3, :3] = root.xmat.reshape(3, 3)
    T_root[:3, 3] = root.xpos
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = rot, pos
    return np.linalg.inv(T_root) @ T


def rotation_angle_deg(R1: np.ndarray, R2: np.ndarray) -> float:
    cos = (np.trace(R1.T @ R2) - 1) / 2
    return float(np.degrees(np.arccos(np.clip(cos, -1, 1))))


def test_palm_frame_matches_ikin_over_random_configurations(robot):
    rng = np.random.default_rng(0)
    lo, hi = np.array(ARM_RANGES, dtype=float).T
    for _ in range(200):
        arm = rng.uniform(lo, hi)
        expected = ikin_palm(arm)
        actual = mujoco_palm_in_root(robot, arm)
        assert np.linalg.norm(actual[:3, 3] - expected[:3, 3]) <= 0.002, arm
        assert rotation_angle_deg(actual[:3, :3], expected[:3, :3]) <= 1.0, arm


def test_segment_lengths_are_the_icubs(robot):
    mujoco_palm_in_root(robot, np.array([0, 0, 0, 6, 0, 0, 0.0]))
    shoulder = robot.data.body("r_upper_arm").xpos
    elbow = robot.data.body("r_elbow").xpos
    wrist = robot.data.body("r_wrist_1").xpos
    palm, _ = robot.palm_pose()
    assert np.linalg.norm(elbow - shoulder) == pytest.approx(0.1525, abs=0.001)
    assert np.linalg.norm(wrist - elbow) == pytest.approx(0.1375, abs=0.001)
    assert np.linalg.norm(palm - wrist) == pytest.approx(0.0645, abs=0.001)


def test_joint_signs_mean_what_they_mean_on_the_robot(robot):
    """Zero hangs the arm; pitch<0 raises it forward, roll>0 takes it out, elbow>0 bends it."""
    world = {}
    for name, arm in {
        "zero": [0, 0, 0, 6, 0, 0, 0],
        "pitch": [-60, 0, 0, 6, 0, 0, 0],
        "roll": [0, 60, 0, 6, 0, 0, 0],
        "elbow": [0, 0, 0, 90, 0, 0, 0],
    }.items():
        T = mujoco_palm_in_root(robot, np.array(arm, dtype=float))
        world[name] = T[:3, 3]  # root frame: x backward, y right, z up
    shoulder_height = 0.175
    assert world["zero"][2] < shoulder_height - 0.3  # the arm hangs down
    assert world["pitch"][0] < world["zero"][0] - 0.2  # forward is -x in the root frame
    assert world["pitch"][2] > world["zero"][2] + 0.1
    assert world["roll"][1] > world["zero"][1] + 0.2  # out to the right side
    assert world["elbow"][0] < world["zero"][0] - 0.15  # forearm bent forward


def test_robot_faces_the_table(robot):
    """The palm reaches the spot's neighbourhood with the arm raised forward."""
    arm = np.array([-40, 20, 10, 60, 0, 0, 0.0])
    mujoco_palm_in_root(robot, arm)
    palm, _ = robot.palm_pose()
    assert palm[0] > 0.2  # in front of the robot (world +x), over the table
    assert np.linalg.norm(palm[:2] - robot.spot[:2]) < 0.15
