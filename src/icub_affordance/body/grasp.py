"""Grasp primitives in physics: where the hand goes, how it moves and closes, what touch reads.

The building blocks that both the demonstrator (``demos``) and the robot test (``robot_trials``) run
on the body: inverse kinematics places the palm, the position servos ramp the arm (``move``), a
grip synergy closes the hand until the fingers stop on the object (``execute_grasp``), the arm
lifts (``lift_arm``), and the touch sensors tell which grip holds (``grip_in_contact``,
``grip_used``). Apart from the demonstration set, so the robot test needs none of its making.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import mujoco
import numpy as np

from icub_affordance.body.ik import solve_palm_pose
from icub_affordance.body.robot import DOF_MAX_DEG, DOF_MIN_DEG, N_ARM_DOF, N_DOF, Robot
from icub_affordance.vocabulary import GRIPS

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
    commands_deg: np.ndarray  # (steps, 16) the servo targets at the same moments
    touch_trace: np.ndarray  # (steps, 6) touch over the same steps, N
    qpos_trace: np.ndarray  # (steps, nq) the whole state, to replay the movement for pictures
    touch: np.ndarray  # (6,) touch at the closed grasp, N
    hand_contacts: set[str] = field(default_factory=set)  # hand geoms touching the object
    lift_height: float = 0.0  # how far the object rose when the arm lifted (m)
    palm_error: float = 0.0  # distance of the palm from its planned grasp pose (m)
    palm_in_object: np.ndarray = field(default_factory=lambda: np.zeros(3))  # final palm - object


def _pads_in_palm(robot: Robot, hand_deg: np.ndarray) -> dict[str, np.ndarray]:
    """Fingertip pad centres in the palm frame for a hand shape (kinematics only)."""
    data = mujoco.MjData(robot.model)
    posture = np.zeros(N_DOF)
    posture[N_ARM_DOF:] = hand_deg
    robot.write_posture(data, np.clip(posture, DOF_MIN_DEG, DOF_MAX_DEG))
    mujoco.mj_kinematics(robot.model, data)
    pos = data.site_xpos[robot.palm_site]
    rot = data.site_xmat[robot.palm_site].reshape(3, 3)
    return {
        finger: rot.T @ (data.site(f"touch_{finger}_site").xpos - pos)
        for finger in ("thumb", "index", "middle", "ring", "little")
    }


def pinch_point(robot: Robot, hand_deg: np.ndarray) -> tuple[np.ndarray, float]:
    """Midpoint of the thumb and index pads (palm frame) for a hand shape, and their distance."""
    pads = _pads_in_palm(robot, hand_deg)
    return (pads["thumb"] + pads["index"]) / 2, float(np.linalg.norm(pads["thumb"] - pads["index"]))


def cage_point(robot: Robot, hand_deg: np.ndarray) -> np.ndarray:
    """Midway between the thumb pad and the mean of the index, middle and ring pads."""
    pads = _pads_in_palm(robot, hand_deg)
    fingers = np.mean([pads["index"], pads["middle"], pads["ring"]], axis=0)
    return (pads["thumb"] + fingers) / 2


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


class _Recorder:
    """Keeps what the demonstration records at chosen physics steps (all, or those of ``keep``).

    Called after every step; a step that is not kept costs one comparison, so a demonstration
    that keeps 10 of its 1,301 moments reads no state at the others.
    """

    def __init__(self, keep: np.ndarray | None = None) -> None:
        self.keep = None if keep is None else [int(k) for k in keep]
        self.calls = 0
        self._next = 0  # the position in ``keep`` of the next moment to record
        self.postures: list[np.ndarray] = []
        self.commands: list[np.ndarray] = []
        self.touch: list[np.ndarray] = []
        self.qpos: list[np.ndarray] = []

    def __call__(self, robot: Robot) -> None:
        moment = self.calls
        self.calls += 1
        times = 1
        if self.keep is not None:  # a moment kept twice (more steps than moments) is two rows
            times = 0
            while self._next < len(self.keep) and self.keep[self._next] == moment:
                self._next += 1
                times += 1
            if not times:
                return
        for _ in range(times):
            self.postures.append(robot.posture_deg())
            self.commands.append(np.degrees(robot.data.ctrl))
            self.touch.append(robot.touch())
            self.qpos.append(robot.data.qpos.copy())


def sample_steps(n_total: int, steps: int) -> np.ndarray:
    """Indices of ``steps`` evenly spaced moments, the first and the last included."""
    return np.round(np.linspace(0, n_total - 1, steps)).astype(int)


def move_steps(robot: Robot, seconds: float) -> int:
    """How many physics steps ``move`` takes for ``seconds``."""
    return int(round(seconds / robot.model.opt.timestep))


#: How long the demonstrator takes to reach above the object, descend and close (s); the
#: recorded steps are spread evenly over their sum. Then it lifts, in LIFT_S.
APPROACH_S, DESCEND_S, CLOSE_S, LIFT_S = 1.0, 0.8, 0.8, 0.8
DEMO_S = APPROACH_S + DESCEND_S + CLOSE_S


def move(robot: Robot, target_deg: np.ndarray, seconds: float, record=None) -> None:
    """Ramp the servo targets linearly over 80% of the time, then hold them.

    The targets of every physics step are computed up front, and an unrecorded hold is stepped
    in one call: the arithmetic is the same as step by step (the same results to the bit), but
    the robot test runs about half a million physics steps, so the loop's own cost counts.
    """
    start = robot.data.ctrl.copy()
    goal = np.radians(target_deg)
    steps = move_steps(robot, seconds)
    ramp = max(1, int(0.8 * steps))
    fractions = np.minimum(1.0, np.arange(1, steps + 1) / ramp)
    targets = start + (goal - start) * fractions[:, None]
    ctrl = robot.data.ctrl
    if record is None:
        for target in targets[:ramp]:
            ctrl[:] = target
            robot.step()
        if steps > ramp:
            ctrl[:] = targets[-1]
            robot.step(steps - ramp)
        return
    for target in targets:
        ctrl[:] = target
        robot.step()
        record(robot)


def execute_grasp(
    robot: Robot,
    obj: str,
    plan: GraspPlan,
    initial_deg: np.ndarray,
    *,
    approach_height: float = 0.06,
    lift: float = 0.05,
    record_steps: int | None = None,
    lift_if=None,
) -> GraspOutcome:
    """Run one grasp in physics from ``initial_deg``: approach, descend, close, then lift.

    The traces hold every physics step from the start to the closed grasp, or, with
    ``record_steps``, only that many evenly spaced moments of them (``sample_steps``: the same
    values as those rows of the full traces, read at the same moments). ``lift_if``, given the
    touch at the closed grasp, can say the lift is not needed (the grasp is judged without it):
    then the arm does not lift and ``lift_height`` is NaN.
    """
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
    n_total = 1 + sum(move_steps(robot, s) for s in (APPROACH_S, DESCEND_S, CLOSE_S))
    keep = None if record_steps is None else sample_steps(n_total, record_steps)
    record = _Recorder(keep)
    record(robot)
    target = np.asarray(initial_deg, dtype=float).copy()
    target[:N_ARM_DOF], target[N_ARM_DOF:] = above_ik.arm_deg, plan.preshape_deg
    move(robot, target, APPROACH_S, record)
    target[:N_ARM_DOF] = grasp_ik.arm_deg
    move(robot, target, DESCEND_S, record)
    palm_error = float(np.linalg.norm(robot.palm_pose()[0] - palm_goal))
    target[N_ARM_DOF:] = plan.closed_deg
    move(robot, target, CLOSE_S, record)
    touch, contacts = robot.touch(), object_contacts(robot, obj)
    height = robot.object_position(obj)[2]
    palm_in_object = robot.palm_pose()[0] - robot.object_position(obj)
    if record.calls != n_total:
        raise RuntimeError(f"recorded {record.calls} moments of a grasp, expected {n_total}")

    lifted = lift_if is None or lift_if(touch)
    if lifted:
        lift_arm(robot, lift)
    return GraspOutcome(
        postures_deg=np.array(record.postures),
        commands_deg=np.array(record.commands),
        touch_trace=np.array(record.touch),
        qpos_trace=np.array(record.qpos),
        touch=touch,
        hand_contacts=contacts,
        lift_height=float(robot.object_position(obj)[2] - height) if lifted else float("nan"),
        palm_error=palm_error,
        palm_in_object=palm_in_object,
    )


def lift_arm(robot: Robot, lift: float) -> None:
    """Raise the palm by ``lift`` (m) without turning it, the hand's servo targets held."""
    palm, rot = robot.palm_pose()
    lift_ik = solve_palm_pose(robot, palm + [0.0, 0.0, lift], rot, robot.posture_deg()[:N_ARM_DOF])
    target = np.degrees(robot.data.ctrl)
    target[:N_ARM_DOF] = lift_ik.arm_deg
    move(robot, target, LIFT_S)


def grip_in_contact(grip: str, touch: np.ndarray, threshold: float) -> bool:
    """book/notes.md, "The demonstrations": the fingers a grip uses touch the object.

    Precision: thumb and index. Power: thumb, and the palm or at least three fingers.
    """
    thumb, index, middle, ring, little, palm = (np.asarray(touch) > threshold).tolist()
    if grip == "precision":
        return bool(thumb and index)
    if grip == "power":
        return bool(thumb and (palm or sum([index, middle, ring, little]) >= 3))
    raise ValueError(f"unknown grip {grip!r}; choose one of {GRIPS}")


def grip_used(touch: np.ndarray, threshold: float) -> str:
    """The grip the touch sensors report: power if it is one, else precision, else none."""
    for grip in GRIPS:
        if grip_in_contact(grip, touch, threshold):
            return grip
    return "none"
