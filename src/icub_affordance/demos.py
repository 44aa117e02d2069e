"""The scripted demonstrator: reach, pre-shape, close and lift, in physics.

This is the controller that makes the paper's training sequences (section 2.3): inverse kinematics
places the palm, the position servos move the arm, a grip synergy closes the hand until the
fingers stop on the object, and touch and a lift test tell a real grasp from a near miss.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import mujoco
import numpy as np

from .body import DOF_MAX_DEG, DOF_MIN_DEG, N_ARM_DOF, N_DOF, Robot
from .ik import solve_palm_pose

#: Palm frame axes (columns, in world coordinates) for a palm-down hand with the fingers forward.
PALM_DOWN = np.array([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]])


def rot_z(deg: float) -> np.ndarray:
    c, s = np.cos(np.radians(deg)), np.sin(np.radians(deg))
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rot_y(deg: float) -> np.ndarray:
    c, s = np.cos(np.radians(deg)), np.sin(np.radians(deg))
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def palm_down_rotation(yaw_deg: float, tilt_deg: float) -> np.ndarray:
    """Palm down, turned ``yaw`` about the vertical, fingertips pitched ``tilt`` down."""
    return rot_z(yaw_deg) @ rot_y(tilt_deg) @ PALM_DOWN


@dataclass(frozen=True)
class GraspPlan:
    """Where the object sits in the hand at the grasp, and how the hand gets there."""

    object_in_palm: np.ndarray  # object centre in the palm frame at the grasp (m)
    preshape_deg: np.ndarray  # the 9 hand angles while approaching
    closed_deg: np.ndarray  # the 9 hand angles commanded to close (past contact: servos stop)
    yaw_deg: float = 30.0
    tilt_deg: float = 0.0


@dataclass
class GraspOutcome:
    postures_deg: np.ndarray  # (steps, 16) the controlled angles from start to closed grasp
    touch: np.ndarray  # (6,) touch at the closed grasp, N
    hand_contacts: set[str] = field(default_factory=set)  # hand geoms touching the object
    lift_height: float = 0.0  # how far the object rose when the arm lifted (m)
    palm_error: float = 0.0  # distance of the palm from its planned grasp pose (m)


def pinch_point(robot: Robot, hand_deg: np.ndarray) -> tuple[np.ndarray, float]:
    """Midpoint of the thumb and index pads (palm frame) for a hand shape, and their distance."""
    data = mujoco.MjData(robot.model)
    posture = np.zeros(N_DOF)
    posture[N_ARM_DOF:] = hand_deg
    robot.write_posture(data, np.clip(posture, DOF_MIN_DEG, DOF_MAX_DEG))
    mujoco.mj_kinematics(robot.model, data)
    pos = data.site_xpos[robot.palm_site]
    rot = data.site_xmat[robot.palm_site].reshape(3, 3)
    thumb = rot.T @ (data.site("touch_thumb_site").xpos - pos)
    index = rot.T @ (data.site("touch_index_site").xpos - pos)
    return (thumb + index) / 2, float(np.linalg.norm(thumb - index))


def object_contacts(robot: Robot, obj: str) -> set[str]:
    """Names of the hand's geoms in contact with ``obj``."""
    model, data = robot.model, robot.data
    target = model.geom(obj).id
    hand_root = model.body("r_hand").id
    names = set()
    for contact in data.contact[: data.ncon]:
        if target not in (contact.geom1, contact.geom2):
            continue
        other = contact.geom2 if contact.geom1 == target else contact.geom1
        body = model.geom_bodyid[other]
        while body not in (0, hand_root):
            body = model.body_parentid[body]
        if body == hand_root:
            names.add(model.geom(other).name)
    return names


def _move(robot: Robot, target_deg: np.ndarray, seconds: float, log: list) -> None:
    """Ramp the servo targets linearly over 80% of the time, hold for the rest; log postures."""
    start = robot.data.ctrl.copy()
    goal = np.radians(target_deg)
    steps = int(round(seconds / robot.model.opt.timestep))
    ramp = max(1, int(0.8 * steps))
    for i in range(steps):
        robot.data.ctrl[:] = start + (goal - start) * min(1.0, (i + 1) / ramp)
        robot.step()
        log.append(robot.posture_deg())


def execute_grasp(
    robot: Robot,
    obj: str,
    plan: GraspPlan,
    initial_deg: np.ndarray,
    *,
    approach_height: float = 0.06,
    lift: float = 0.05,
) -> GraspOutcome:
    """Run one grasp in physics from ``initial_deg``: approach, descend, close, then lift."""
    robot.reset()
    robot.place_object(obj)
    robot.set_posture_deg(initial_deg)
    centre = robot.object_position(obj)
    rotation = palm_down_rotation(plan.yaw_deg, plan.tilt_deg)
    palm_goal = centre - rotation @ plan.object_in_palm
    grasp_ik = solve_palm_pose(robot, palm_goal, rotation, initial_deg[:N_ARM_DOF])
    above_ik = solve_palm_pose(
        robot, palm_goal + [0.0, 0.0, approach_height], rotation, grasp_ik.arm_deg
    )
    log: list[np.ndarray] = [robot.posture_deg()]
    target = np.asarray(initial_deg, dtype=float).copy()
    target[:N_ARM_DOF], target[N_ARM_DOF:] = above_ik.arm_deg, plan.preshape_deg
    _move(robot, target, 1.0, log)
    target[:N_ARM_DOF] = grasp_ik.arm_deg
    _move(robot, target, 0.8, log)
    palm_error = float(np.linalg.norm(robot.palm_pose()[0] - palm_goal))
    target[N_ARM_DOF:] = plan.closed_deg
    _move(robot, target, 0.8, log)
    touch, contacts = robot.touch(), object_contacts(robot, obj)
    height = robot.object_position(obj)[2]

    palm, rot = robot.palm_pose()
    lift_ik = solve_palm_pose(robot, palm + [0.0, 0.0, lift], rot, robot.posture_deg()[:N_ARM_DOF])
    target[:N_ARM_DOF] = lift_ik.arm_deg
    _move(robot, target, 0.8, [])
    return GraspOutcome(
        postures_deg=np.array(log),
        touch=touch,
        hand_contacts=contacts,
        lift_height=float(robot.object_position(obj)[2] - height),
        palm_error=palm_error,
    )
