"""The demonstration set (paper sections 2.3 and 3): the scripted demonstrator's grasps, varied,
checked and recorded.

Each object is grasped with each grip several times, the hand's final pose varied a little; a
variation counts only if it holds the object (``is_grasp``), and its recorded steps become the
networks' training sequences. The physics of a grasp is in ``grasp``; here is what is grasped,
how it varies, what is kept, and the files it is kept in.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from icub_affordance.body.grasp import (
    GraspPlan,
    cage_point,
    execute_grasp,
    grip_in_contact,
    pinch_point,
)
from icub_affordance.body.robot import DOF_MAX_DEG, DOF_MIN_DEG, Robot
from icub_affordance.vocabulary import GRIPS


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
    from icub_affordance.body.robot import OBJECT_NAMES

    template = grasp_template(robot, grip, size)
    for attempt in range(config.max_attempts):
        rng = demo_rng(seed, OBJECT_NAMES.index(obj), GRIPS.index(grip), sequence, attempt)
        plan = varied(template, rng, config)
        # only the recorded moments are kept, and a grasp whose fingers do not touch is judged
        # without lifting it: the same demonstrations, to the bit, in less time
        outcome = execute_grasp(
            robot,
            obj,
            plan,
            initial_deg,
            lift=config.lift_m,
            record_steps=config.steps,
            lift_if=lambda touch: grip_in_contact(grip, touch, config.touch_threshold),
        )
        if is_grasp(grip, outcome.touch, outcome.lift_height, config):
            return Demo(
                object=obj,
                grip=grip,
                sequence=sequence,
                attempts=attempt + 1,
                plan=plan,
                # MuJoCo's joint limits are soft: a finger pushed onto its stop by a contact can
                # pass it by a few degrees. Proprioception reads within Figure 1's ranges.
                postures_deg=np.clip(outcome.postures_deg, DOF_MIN_DEG, DOF_MAX_DEG),
                commands_deg=outcome.commands_deg,
                touch=outcome.touch_trace,
                qpos=outcome.qpos_trace,
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
    from icub_affordance.body.robot import OBJECTS

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
    from icub_affordance.body.robot import DOF_NAMES, to_normalised

    objects = list(parts)
    merged = {key: np.stack([parts[o][key] for o in objects]) for key in parts[objects[0]]}
    merged["angles"] = to_normalised(merged["angles_deg"])
    merged["objects"] = np.array(objects)
    merged["grips"] = np.array(GRIPS)
    merged["dofs"] = np.array(DOF_NAMES)
    return merged


def summary_rows(merged: dict[str, np.ndarray], config: DemoConfig) -> list[dict[str, object]]:
    """One readable row per demonstration: how it ended, and where the hand was."""
    from icub_affordance.body.robot import TOUCH_NAMES

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
