"""Beyond the paper: the trained network drives the simulated arm, and physics judges the grasp.

The paper scored its networks by how far their outputs were from the demonstrated postures and
never let them move the robot. Here each test trial is run on the MuJoCo iCub, closed loop: at
every step the network reads the arm's *actual* posture from the simulator (proprioception) and
its output becomes the 16 position-servo targets, ramped over one demonstration step's time. The
arm then lifts, and the grasp counts as a success when the grip the touch sensors read is the
required one and the object rises with the hand (the criteria of book/notes.md, "The
demonstrations": precision, thumb and index; power, thumb and the palm or at least three fingers; a
hand that meets power's criterion reads power, whatever else touches). A precision trial held with
the whole hand is a failure, counted as such (``wrong_grip_hold``).

In closed loop a network's test sequences of one object and task are one and the same movement
(``embodied_network``), run once. The trials' statistics are in ``robot_stats``, over distinct
trials (one per network x object x task); this module runs the trials only, and imports neither
pandas nor the statistics, so the robot jobs start faster.

Two replays bound what a network could achieve with this controller: the demonstrator's own
servo targets at the ten recorded moments (a correct plan), and the postures proprioception
recorded at those moments (what the networks were taught).

The reaction time on the body is the contact time: from the trial's start until the touch
sensors of every finger the required grip uses first read contact, at the physics step's
resolution (2 ms).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from icub_affordance.body.demonstrations import DemoConfig
from icub_affordance.body.grasp import DEMO_S, grip_in_contact, grip_used, lift_arm, move
from icub_affordance.body.robot import (
    DOF_MAX_DEG,
    DOF_MIN_DEG,
    N_ARM_DOF,
    OBJECTS,
    TOUCH_NAMES,
    Robot,
    to_degrees,
    to_normalised,
)
from icub_affordance.learning.materials import Materials
from icub_affordance.learning.network import Weights, network_step
from icub_affordance.trials.in_silico import TrialSet, trial_row

#: A controller: (step index, the posture proprioception reads, 0-1) -> the servo targets, 0-1.
Policy = Callable[[int, np.ndarray], np.ndarray]


@dataclass(frozen=True)
class Outcome:
    commands: np.ndarray  # (steps-1, 16) the servo targets sent, 0-1
    sensed: np.ndarray  # (steps, 16) the posture read before each command and at the end, 0-1
    touch: np.ndarray  # (6,) N, at the end of the last step
    lift_m: float  # how far the object rose with the lifted hand; NaN when not lifted
    qpos: np.ndarray  # (steps + 1, nq) the state at every step and after the lift, for pictures
    contact_time: float  # s from the start until the required grip's fingers all touch; NaN: never
    palm: np.ndarray  # (3,) m, the palm at the end of the movement, from the object's start


class _ContactClock:
    """Watches the touch sensors at every physics step for the first moment the required grip's
    fingers all read contact."""

    def __init__(self, robot: Robot, grip: str, threshold: float) -> None:
        self.start, self.grip, self.threshold = robot.data.time, grip, threshold
        self.time = float("nan")

    def __call__(self, robot: Robot) -> None:
        if np.isnan(self.time) and grip_in_contact(self.grip, robot.touch(), self.threshold):
            self.time = float(robot.data.time - self.start)


def sensed_posture(robot: Robot) -> np.ndarray:
    """Proprioception, 0-1 within Figure 1's ranges (as the demonstrations were recorded)."""
    return to_normalised(np.clip(robot.posture_deg(), DOF_MIN_DEG, DOF_MAX_DEG))


def run_trial(
    robot: Robot,
    obj: str,
    policy: Policy,
    start: np.ndarray,
    steps: int,
    grip: str,
    config: DemoConfig,
    watch: Callable[[Robot], None] | None = None,
) -> Outcome:
    """One trial in physics from the posture ``start`` (0-1), ``steps`` postures long;
    ``watch``, if given, sees the robot after every physics step of the movement (pictures).

    The arm is lifted only if the required grip's fingers touch the object (``grip_in_contact``:
    for a precision trial thumb and index, with or without the rest of the hand): without that
    the trial has failed whatever the lift would show, and the lift is the costliest part. A
    precision trial whose touch reads power is lifted, so that a hold with the wrong grip is
    seen and named (``outcome_columns``).
    """
    robot.reset()
    robot.place_object(obj)
    robot.set_posture_deg(to_degrees(start))
    origin = robot.object_position(obj).copy()
    height = origin[2]
    step_s = DEMO_S / (steps - 1)  # the demonstrations' time between recorded steps
    sensed, commands, states = [sensed_posture(robot)], [], [robot.data.qpos.copy()]
    clock = _ContactClock(robot, grip, config.touch_threshold)
    record = clock if watch is None else lambda r: (clock(r), watch(r))
    for t in range(steps - 1):
        command = np.asarray(policy(t, sensed[-1]), dtype=float)
        move(robot, to_degrees(command), step_s, record=record)
        commands.append(command)
        sensed.append(sensed_posture(robot))
        states.append(robot.data.qpos.copy())
    touch = robot.touch()
    palm = robot.palm_pose()[0] - origin
    lift = float("nan")
    if grip_in_contact(grip, touch, config.touch_threshold):
        lift_arm(robot, config.lift_m)
        lift = float(robot.object_position(obj)[2] - height)
    states.append(robot.data.qpos.copy())
    return Outcome(
        np.array(commands), np.array(sensed), touch, lift, np.array(states), clock.time, palm
    )


def network_policy(weights: Weights, context: np.ndarray) -> Policy:
    """The Jordan network as a controller; ``context`` (steps-1, 200) is the trial's map input."""

    def policy(t: int, proprio: np.ndarray) -> np.ndarray:
        return network_step(weights, context[t], proprio)[0]

    return policy


def replay_policy(plan: np.ndarray) -> Policy:
    """Send the postures of a recorded plan (steps, 16; 0-1) one after another, ignoring the
    senses: the controller's part of the job, with no network in the way."""
    return lambda t, _proprio: plan[t + 1]


def demo_palms(robot: Robot, demos: np.ndarray, objects: tuple[str, ...]) -> np.ndarray:
    """Where each demonstration put the palm, from the object's start (objects, grips,
    sequences, 3; m): its final sensed posture through the forward kinematics.

    Measured in the task's space, not in joint angles: the arm has 7 joints for a 6-dof palm pose,
    and the demonstrations of one grasp differ by several degrees per joint while their palms lie
    within millimetres of each other.
    """
    palms = np.empty(demos.shape[:3] + (3,))
    for o, obj in enumerate(objects):
        robot.reset()
        robot.place_object(obj)
        origin = robot.object_position(obj).copy()
        for key in np.ndindex(*demos.shape[1:3]):
            robot.set_posture_deg(to_degrees(demos[(o, *key, -1)]))
            palms[(o, *key)] = robot.palm_pose()[0] - origin
    return palms


def reference_palms(palms: np.ndarray) -> np.ndarray:
    """Per object and grip the demonstrator's palm position: the mean over the training
    sequences (the last is held out)."""
    return palms[:, :, :-1].mean(axis=2)


def outcome_columns(
    out: Outcome,
    grip: str,
    target_final: np.ndarray,
    palm_ref: np.ndarray | None,
    config: DemoConfig,
):
    """What a roboticist measures of one trial; ``palm_ref`` (3,) is where the demonstrator put
    the palm for this object and grip (``reference_palms``), None where nobody asks.

    ``grip_used`` is the grip the touch sensors read at the end of the movement
    (``grasp.grip_used``: power where power's criterion holds, thumb and the palm or at least
    three fingers, else precision where thumb and index touch, else none). ``success``: that grip
    is the required one and the object rose with the lifted hand. ``wrong_grip_hold``: the
    object rose but the touch read the other grip; only a precision trial can be one, since a
    power trial is lifted only when power's criterion holds.
    """
    held = bool(out.lift_m >= config.min_lift_m)  # NaN (not lifted) compares False
    read = grip_used(out.touch, config.touch_threshold)
    return {
        "success": bool(read == grip and held),
        "wrong_grip_hold": bool(held and read not in (grip, "none")),
        "grip_used": read,
        "final_error": float(np.sqrt(np.mean((out.sensed[-1] - target_final) ** 2))),
        "palm_error_mm": float("nan")
        if palm_ref is None
        else float(1000 * np.linalg.norm(out.palm - palm_ref)),
        "lift_m": out.lift_m,
        "contact_time": out.contact_time,
    } | {name: float(v) for name, v in zip(TOUCH_NAMES, out.touch, strict=True)}


def embodied_network(
    robot: Robot,
    m: Materials,
    weights: Weights,
    network: int,
    mapping: str,
    cue: str,
    target: str,
    config: DemoConfig,
) -> tuple[list[dict[str, object]], np.ndarray]:
    """Every test trial of one network on the robot: rows with the columns of the evaluation's
    trials (mode ``embodied``) plus the physical outcome, and the states for pictures.

    A trial is decided by its object, grip, maps' input and start posture: the test sequences of
    one object and task differ only in the demonstration their result is compared with, so the
    network drives the same movement in each. Physics runs once per distinct trial (MuJoCo is
    deterministic from a reset), and the others reuse it.
    """
    setup = TrialSet.of(m, mapping, cue, target)
    palms = reference_palms(demo_palms(robot, m.demos, m.objects))
    rows, states, done = [], [], {}
    for i, (_task, o, _s) in enumerate(setup.trials):
        grip = m.grips[setup.grips[i]]
        start = setup.teacher[i, 0]
        key = (o, grip, setup.context[i].tobytes(), start.tobytes())
        if key not in done:
            done[key] = run_trial(
                robot,
                m.objects[o],
                network_policy(weights, setup.context[i]),
                start,
                len(setup.teacher[i]),
                grip,
                config,
            )
        out = done[key]
        row = trial_row(m, setup, i, out.commands, out.sensed[-1], network, mapping, "embodied")
        ref = palms[o, setup.grips[i]]
        rows.append(row | outcome_columns(out, grip, setup.teacher[i, -1], ref, config))
        states.append(out.qpos)
    return rows, np.array(states)


def replay_demos(
    robot: Robot, demos: dict[str, np.ndarray], config: DemoConfig
) -> list[dict[str, object]]:
    """Each demonstration replayed through the controller twice: its servo targets (a correct
    plan) and its sensed postures (what the networks learn to output)."""
    rows = []
    plans = {
        "commands": to_normalised(demos["commands_deg"]),
        "sensed_postures": demos["angles"],
    }
    objects, grips = demos["objects"].tolist(), demos["grips"].tolist()
    palms = reference_palms(demo_palms(robot, demos["angles"], tuple(objects)))
    for o, obj in enumerate(objects):
        for g, grip in enumerate(grips):
            for s in range(demos["angles"].shape[2]):
                for plan_name, plan in plans.items():
                    p = plan[o, g, s]
                    out = run_trial(
                        robot, obj, replay_policy(p), demos["angles"][o, g, s, 0], len(p),
                        grip, config,
                    )  # fmt: skip
                    row = {"object": obj, "grip": grip, "sequence": s, "plan": plan_name}
                    final = demos["angles"][o, g, s, -1]
                    rows.append(row | outcome_columns(out, grip, final, palms[o, g], config))
    return rows


def body_tolerance(
    robot: Robot,
    demos: dict[str, np.ndarray],
    noise: list[float],
    repeats: int,
    seed: int,
    config: DemoConfig,
) -> list[dict[str, object]]:
    """How precise must a learned arm be? Each object's natural grasp replayed as the mean plan
    of its training demonstrations (the servo targets a network fits, clipped to 0-1 as its
    sigmoid outputs are), with the 7 arm joints' targets shifted by a constant Gaussian offset of
    standard deviation ``noise`` (0-1 units) over the whole trial: success against arm error.

    The offset stays the same at every step, like a network's error that persists through a
    trial. Noise 0 is run once (physics is deterministic). A repeat's offset is one standard
    normal draw per joint, from the seed derived from ``seed``, the object and the repeat, scaled
    by each noise level: the levels share their directions and differ in size only, so adding
    or removing a level changes no other level's trials. ``offset`` is the RMS of the offset sent
    (after clipping to 0-1).
    """
    rows = []
    objects, grips = demos["objects"].tolist(), demos["grips"].tolist()
    commands = np.clip(to_normalised(demos["commands_deg"]), 0.0, 1.0)
    train = slice(0, demos["angles"].shape[2] - 1)  # the last sequence is held out
    palms = reference_palms(demo_palms(robot, demos["angles"], tuple(objects)))
    for o, obj in enumerate(objects):
        grip = OBJECTS[obj].natural_grip
        g = grips.index(grip)
        start = demos["angles"][o, g, 0, 0]
        final = demos["angles"][o, g, train, -1].mean(axis=0)  # the plan's own final posture
        plan = np.vstack([start, commands[o, g, train, 1:].mean(axis=0)])
        directions = [
            np.random.default_rng([seed, o, repeat]).standard_normal(N_ARM_DOF)
            for repeat in range(repeats)
        ]
        for sigma in noise:
            for repeat in range(repeats if sigma > 0 else 1):
                arm = plan[1:, :N_ARM_DOF]
                shifted = plan.copy()
                shifted[1:, :N_ARM_DOF] = np.clip(arm + sigma * directions[repeat], 0.0, 1.0)
                sent = shifted[1:, :N_ARM_DOF] - arm
                out = run_trial(robot, obj, replay_policy(shifted), start, len(plan), grip, config)
                row = {"object": obj, "grip": grip, "noise": float(sigma), "repeat": repeat,
                       "offset": float(np.sqrt(np.mean(sent**2)))}  # fmt: skip
                rows.append(row | outcome_columns(out, grip, final, palms[o, g], config))
    return rows
