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
from .spec import GRIPS

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
    """Keeps what the demonstration records at every physics step."""

    def __init__(self) -> None:
        self.postures: list[np.ndarray] = []
        self.commands: list[np.ndarray] = []
        self.touch: list[np.ndarray] = []
        self.qpos: list[np.ndarray] = []

    def __call__(self, robot: Robot) -> None:
        self.postures.append(robot.posture_deg())
        self.commands.append(np.degrees(robot.data.ctrl))
        self.touch.append(robot.touch())
        self.qpos.append(robot.data.qpos.copy())


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
    steps = int(round(seconds / robot.model.opt.timestep))
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
    record = _Recorder()
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

    lift_arm(robot, lift)
    return GraspOutcome(
        postures_deg=np.array(record.postures),
        commands_deg=np.array(record.commands),
        touch_trace=np.array(record.touch),
        qpos_trace=np.array(record.qpos),
        touch=touch,
        hand_contacts=contacts,
        lift_height=float(robot.object_position(obj)[2] - height),
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


# -- the demonstration set (paper sections 2.3 and 3) --------------------------------------------


@dataclass(frozen=True)
class DemoConfig:
    """How the demonstrator varies and checks its grasps (config key ``demos``, where their
    values are given)."""

    sequences: int  # per object and grip; they differ in the hand's final pose
    steps: int  # recorded time steps, pre-grasp (0) to final grasp (steps - 1)
    max_attempts: int  # fresh variations tried before a demo is declared impossible
    yaw_deg: float  # variation of the hand's final rotation about the vertical, +-
    tilt_deg: float  # variation of its pitch, +-
    shift_m: float  # variation of its final position relative to the object, +- per axis
    lift_m: float  # the check: lift the arm this far...
    min_lift_m: float  # ...and the object must rise at least this much with the hand
    touch_threshold: float  # N; a touch sensor reads contact above this

    def __post_init__(self) -> None:
        if self.min_lift_m > self.lift_m:
            raise ValueError(
                f"demos.min_lift_m ({self.min_lift_m}) cannot exceed demos.lift_m ({self.lift_m}):"
                " the object cannot rise further than the hand"
            )


def grasp_template(robot: Robot, grip: str, size: str) -> GraspPlan:
    """The demonstrator's hand shape and hand pose for a grip on a large or a small object.

    Hand shapes were chosen for this hand model by a grid search in physics (see
    ``tools/search_grasps.py``): each one wraps or pinches both shapes of its size and lifts them.
    """
    if grip == "power" and size == "large":
        return GraspPlan(
            object_in_palm=np.array([0.035, -0.01, 0.037]),
            preshape_deg=np.array([20, 75, 0, 0, 0, 0, 0, 0, 0], dtype=float),
            closed_deg=np.array([20, 75, 0, 90, 70, 70, 70, 70, 100], dtype=float),
            yaw_deg=35.0,
            tilt_deg=15.0,
        )
    if grip == "precision":
        contact, yaw, tilt = {
            "small": (np.array([0, 75, 10, 10, 45, 20, 0, 0, 0], dtype=float), 30.0, 30.0),
            "large": (np.array([0, 45, 10, 10, 10, 0, 0, 0, 0], dtype=float), 30.0, 15.0),
        }[size]
        centre, _ = pinch_point(robot, contact)
        opening = np.array([0, 0, 10, 10, 20, 0, 0, 0, 0], dtype=float)
        return GraspPlan(
            object_in_palm=centre,
            preshape_deg=np.maximum(contact - opening, 0.0),
            closed_deg=contact + [0, 0, 15, 15, 15, 15, 0, 0, 0],
            yaw_deg=yaw,
            tilt_deg=tilt,
        )
    if grip == "power" and size == "small":
        # the four fingers pulled together (adduction -20) close on the object with the thumb
        contact = np.array([-20, 105, 10, 10, 30, 10, 30, 10, 40], dtype=float)
        centre = cage_point(robot, contact)
        opening = np.array([0, 0, 10, 10, 20, 20, 20, 20, 20], dtype=float)
        return GraspPlan(
            object_in_palm=centre,
            preshape_deg=np.maximum(contact - opening, [-20, -15, 0, 0, 0, 0, 0, 0, 0]),
            closed_deg=contact + [0, 0, 15, 15, 15, 15, 15, 15, 15],
            yaw_deg=30.0,
            tilt_deg=30.0,
        )
    raise ValueError(f"unknown grip {grip!r} or size {size!r}")


def varied(plan: GraspPlan, rng: np.random.Generator, config: DemoConfig) -> GraspPlan:
    """The same grasp with the hand's final position and rotation moved a little."""
    shift = rng.uniform(-config.shift_m, config.shift_m, size=3)
    shift[2] = 0.0  # keep the palm's height over the object: the variation is in the plane
    return GraspPlan(
        object_in_palm=plan.object_in_palm + shift,
        preshape_deg=plan.preshape_deg,
        closed_deg=plan.closed_deg,
        yaw_deg=plan.yaw_deg + rng.uniform(-config.yaw_deg, config.yaw_deg),
        tilt_deg=plan.tilt_deg + rng.uniform(-config.tilt_deg, config.tilt_deg),
    )


def grip_in_contact(grip: str, touch: np.ndarray, threshold: float) -> bool:
    """MODEL.md section 4: the fingers a grip uses touch the object.

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


def is_grasp(grip: str, touch: np.ndarray, lift: float, config: DemoConfig) -> bool:
    """A grasp holds: the grip's fingers touch the object, and it rises with the lifted hand."""
    return grip_in_contact(grip, touch, config.touch_threshold) and bool(lift >= config.min_lift_m)


@dataclass
class Demo:
    object: str
    grip: str
    sequence: int
    attempts: int
    plan: GraspPlan
    postures_deg: np.ndarray  # (steps, 16) as proprioception read them
    commands_deg: np.ndarray  # (steps, 16) the servo targets at the same moments
    touch: np.ndarray  # (steps, 6)
    qpos: np.ndarray  # (steps, nq)
    lift_m: float
    palm_in_object: np.ndarray  # final palm position relative to the object centre (m)


def sample_steps(n_total: int, steps: int) -> np.ndarray:
    """Indices of ``steps`` evenly spaced moments, the first and the last included."""
    return np.round(np.linspace(0, n_total - 1, steps)).astype(int)


def demo_rng(seed: int, obj_index: int, grip_index: int, sequence: int, attempt: int):
    """One independent random stream per demo and attempt, all derived from the config seed."""
    return np.random.default_rng([seed, obj_index, grip_index, sequence, attempt])


def make_demo(
    robot: Robot,
    obj: str,
    grip: str,
    sequence: int,
    initial_deg: np.ndarray,
    seed: int,
    config: DemoConfig,
    size: str,
) -> Demo:
    """One validated demonstration, or a RuntimeError naming it if no variation grasps."""
    from .body import OBJECT_NAMES

    template = grasp_template(robot, grip, size)
    for attempt in range(config.max_attempts):
        rng = demo_rng(seed, OBJECT_NAMES.index(obj), GRIPS.index(grip), sequence, attempt)
        plan = varied(template, rng, config)
        outcome = execute_grasp(robot, obj, plan, initial_deg, lift=config.lift_m)
        if is_grasp(grip, outcome.touch, outcome.lift_height, config):
            idx = sample_steps(len(outcome.postures_deg), config.steps)
            return Demo(
                object=obj,
                grip=grip,
                sequence=sequence,
                attempts=attempt + 1,
                plan=plan,
                # MuJoCo's joint limits are soft: a finger pushed onto its stop by a contact can
                # pass it by a few degrees. Proprioception reads within Figure 1's ranges.
                postures_deg=np.clip(outcome.postures_deg[idx], DOF_MIN_DEG, DOF_MAX_DEG),
                commands_deg=outcome.commands_deg[idx],
                touch=outcome.touch_trace[idx],
                qpos=outcome.qpos_trace[idx],
                lift_m=outcome.lift_height,
                palm_in_object=outcome.palm_in_object,
            )
    raise RuntimeError(
        f"demo {obj}/{grip}/sequence {sequence}: no grasp in {config.max_attempts} attempts "
        f"(touch or lift check failed). Widen demos.max_attempts or check the scene's objects."
    )


def object_demos(
    robot: Robot, obj: str, initial_deg: np.ndarray, seed: int, config: DemoConfig
) -> dict[str, np.ndarray]:
    """All grips and sequences of one object, as arrays with (grip, sequence, ...) leading axes."""
    from .body import OBJECTS

    demos = [
        [
            make_demo(robot, obj, grip, seq, initial_deg, seed, config, OBJECTS[obj].size)
            for seq in range(config.sequences)
        ]
        for grip in GRIPS
    ]

    def stack(get) -> np.ndarray:
        return np.array([[get(d) for d in row] for row in demos])

    return {
        "angles_deg": stack(lambda d: d.postures_deg),
        "commands_deg": stack(lambda d: d.commands_deg),
        "touch": stack(lambda d: d.touch),
        "qpos": stack(lambda d: d.qpos),
        "lift_m": stack(lambda d: d.lift_m),
        "attempts": stack(lambda d: d.attempts),
        "palm_in_object": stack(lambda d: d.palm_in_object),
        "yaw_deg": stack(lambda d: d.plan.yaw_deg),
        "tilt_deg": stack(lambda d: d.plan.tilt_deg),
        "object_in_palm": stack(lambda d: d.plan.object_in_palm),
    }


def merge_demos(parts: dict[str, dict[str, np.ndarray]]) -> dict[str, np.ndarray]:
    """The per-object parts joined into the contract file's layout (object, grip, seq, ...)."""
    from .body import DOF_NAMES, to_normalised

    objects = list(parts)
    merged = {key: np.stack([parts[o][key] for o in objects]) for key in parts[objects[0]]}
    merged["angles"] = to_normalised(merged["angles_deg"])
    merged["objects"] = np.array(objects)
    merged["grips"] = np.array(GRIPS)
    merged["dofs"] = np.array(DOF_NAMES)
    return merged


def summary_rows(merged: dict[str, np.ndarray], config: DemoConfig) -> list[dict[str, object]]:
    """One readable row per demonstration: how it ended, and where the hand was."""
    from .body import TOUCH_NAMES

    rows = []
    for o, obj in enumerate(merged["objects"]):
        for g, grip in enumerate(merged["grips"]):
            for s in range(merged["angles"].shape[2]):
                final_touch = merged["touch"][o, g, s, -1]
                palm = merged["palm_in_object"][o, g, s]
                row = {"object": str(obj), "grip": str(grip), "sequence": s}
                row["attempts"] = int(merged["attempts"][o, g, s])
                row["yaw_deg"] = round(float(merged["yaw_deg"][o, g, s]), 2)
                row["tilt_deg"] = round(float(merged["tilt_deg"][o, g, s]), 2)
                touch = zip(TOUCH_NAMES, final_touch, strict=True)
                row |= {n: round(float(v), 3) for n, v in touch}
                row["lift_m"] = round(float(merged["lift_m"][o, g, s]), 4)
                row["held"] = bool(merged["lift_m"][o, g, s] >= config.min_lift_m)
                row |= {f"palm_{a}_m": round(float(v), 4) for a, v in zip("xyz", palm, strict=True)}
                rows.append(row)
    return rows


def summary_csv(merged: dict[str, np.ndarray], config: DemoConfig) -> str:
    """The summary rows as CSV text (the file ``demos/summary.csv``)."""
    import csv
    import io

    rows = summary_rows(merged, config)
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(rows[0]), lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    return buffer.getvalue()
