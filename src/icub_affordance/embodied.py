"""Beyond the paper: the trained network drives the simulated arm, and physics judges the grasp.

The paper scored its networks by how far their outputs were from the demonstrated postures and
never let them move the robot. Here each test trial is run on the MuJoCo iCub, closed loop: at
every step the network reads the arm's *actual* posture from the simulator (proprioception) and
its output becomes the 16 position-servo targets, ramped over one demonstration step's time. The
arm then lifts, and the grasp counts as a success when the grip the touch sensors read is the
required one and the object rises with the hand (MODEL.md section 4's criteria: precision, thumb
and index; power, thumb and the palm or at least three fingers; a hand that meets power's
criterion reads power, whatever else touches). A precision trial held with the whole hand is a
failure, counted as such (``wrong_grip_hold``).

In closed loop a network's test sequences of one object and task are one and the same movement
(``embodied_network``): every count, rate and test of the summary is over distinct trials, one
per network x object x task (``distinct_trials``), never over the duplicated sequences.

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
from typing import TYPE_CHECKING

import numpy as np

from .body import (
    DOF_MAX_DEG,
    DOF_MIN_DEG,
    N_ARM_DOF,
    OBJECTS,
    TOUCH_NAMES,
    Robot,
    to_degrees,
    to_normalised,
)
from .demos import DemoConfig
from .evaluate import TrialSet, trial_row
from .grasp import DEMO_S, grip_in_contact, grip_used, lift_arm, move
from .jordan import Weights, network_step
from .train import Materials

if TYPE_CHECKING:  # pandas only for the summary: the robot jobs start faster without it
    import pandas as pd

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


# -- the summary -------------------------------------------------------------------------------

#: The columns a robot trial's physics decides: the same in every test sequence of one network x
#: object x task, which are one movement on the robot (``embodied_network``).
PHYSICAL_COLUMNS = (
    "success",
    "wrong_grip_hold",
    "grip_used",
    "lift_m",
    "contact_time",
    "palm_error_mm",
    *TOUCH_NAMES,
)

#: The columns that compare a trial with one test sequence's demonstration: a distinct trial
#: keeps their mean over its sequences.
PER_SEQUENCE_COLUMNS = ("final_error", "rmse")


def trial_keys(trials: pd.DataFrame) -> list[str]:
    """What tells one physical robot trial from another: the run (where the table has it), the
    network, the task and the object."""
    return [c for c in ("run",) if c in trials.columns] + ["network", "task", "object"]


def distinct_trials(trials: pd.DataFrame) -> pd.DataFrame:
    """One row per physical trial (``trial_keys``: run, network, task, object), in the order of
    their first rows: a network's test sequences of one object and task are one movement on the
    robot and count once in every count, rate and test of the summary.

    The physical outcome (``PHYSICAL_COLUMNS``) is the first sequence's, and a ValueError is
    raised where the sequences disagree on it (they were then not one trial); the distances from
    the sequences' demonstrations (``PER_SEQUENCE_COLUMNS`` and every ``rmse_step*``) are their
    mean; ``sequence`` and ``held_out``, which name one sequence, are dropped.
    """
    keys = trial_keys(trials)
    groups = trials.groupby(keys, sort=False)
    physical = [c for c in PHYSICAL_COLUMNS if c in trials.columns]
    varying = groups[physical].nunique(dropna=False) if physical else None
    if varying is not None and (varying > 1).any().any():
        bad = varying.columns[(varying > 1).any()].tolist()
        raise ValueError(f"the test sequences of one robot trial differ in {bad}")
    means = [c for c in trials.columns if c in PER_SEQUENCE_COLUMNS or c.startswith("rmse_step")]
    out = trials.drop_duplicates(keys).drop(columns=["sequence", "held_out"], errors="ignore")
    if means:
        averaged = groups[means].mean()
        out = out.drop(columns=means).merge(averaged, left_on=keys, right_index=True, how="left")
        out = out[[c for c in trials.columns if c in out.columns]]
    return out.reset_index(drop=True)


def success_table(trials: pd.DataFrame) -> pd.DataFrame:
    """Success, grip read and final error by task, congruency and size, over distinct trials
    (``distinct_trials``): ``trials`` counts them, ``wrong_grip_hold`` how many held the object
    with the other grip than the required one (failures)."""
    from .stats import trial_conditions

    df = distinct_trials(trials)
    df = df.assign(condition=trial_conditions(df))
    groups = df.groupby(["condition", "size"], sort=True)
    table = groups.agg(
        trials=("success", "size"),
        success=("success", "mean"),
        final_error=("final_error", "mean"),
    )
    for grip in ("power", "precision", "none"):
        table[f"grip_{grip}"] = groups["grip_used"].apply(lambda g, grip=grip: (g == grip).mean())
    table["grip_target"] = groups.apply(
        lambda g: (g["grip_used"] == g["target_grip"]).mean(), include_groups=False
    )
    table["wrong_grip_hold"] = groups["wrong_grip_hold"].apply(lambda g: int(g.astype(bool).sum()))
    return table.reset_index()


def success_analysis(trials: pd.DataFrame, replay: pd.DataFrame) -> dict[str, object]:
    """Does congruency (or size) change the robot's categorisation grasps? Over distinct trials
    (``distinct_trials``: one per network x object x task).

    For success (0/1) and for the final posture error: each network's mean per congruency x size
    cell, the per-network incongruent - congruent difference with its 95% t-interval, the
    per-network contrasts used for inference (``stats.network_contrasts``: t over networks), and,
    descriptive only, the repeated-measures ANOVA (network as subject; it averages each network's
    cell, so the duplicated sequences never changed it). Where every network scores the same in
    every cell the ANOVA is undefined and reported as None.
    """
    from .stats import (
        categorisation_trials,
        cell_means,
        mean_ci,
        network_contrasts,
        repeated_measures_anova,
    )

    trials = distinct_trials(trials)
    df = categorisation_trials(trials, "embodied")
    df["success"] = df["success"].astype(float)
    measures = {}
    for measure in ("success", "final_error"):
        per_net = df.groupby(["network", "congruency"])[measure].mean().unstack()
        mean, lo, hi = mean_ci((per_net["incongruent"] - per_net["congruent"]).to_numpy())
        with np.errstate(divide="ignore", invalid="ignore"):
            try:
                anova = repeated_measures_anova(df, measure)
            except (ValueError, ZeroDivisionError, np.linalg.LinAlgError):
                anova = None
            try:
                contrasts = network_contrasts(df, measure)
            except (ValueError, np.linalg.LinAlgError):
                contrasts = None
        if anova and not all(np.isfinite(r["F"]) for r in anova.values()):
            anova = None
        measures[measure] = {
            "means": cell_means(df, measure),
            "incongruent_minus_congruent": {"mean": mean, "ci_low": lo, "ci_high": hi},
            "contrasts": contrasts,
            "repeated_measures": anova,
        }
    grasping = trials[trials["task"] == "grasping"]
    return {
        "n_networks": int(df["network"].nunique()),
        "n_trials": int(len(trials)),
        "n_grasping_trials": int(len(grasping)),
        "n_categorisation_trials": int(len(df)),
        "success_rate": float(trials["success"].astype(float).mean()),
        "grasping_success": float(grasping["success"].astype(float).mean()),
        "categorisation_success": float(df["success"].mean()),
        "touching_rate": float((trials["grip_used"] != "none").mean()),
        "wrong_grip_holds": int(trials["wrong_grip_hold"].astype(bool).sum()),
        "measures": measures,
        "replay_success": {
            plan: float(group["success"].astype(float).mean())
            for plan, group in replay.groupby("plan")
        },
        "replay_trials": {plan: int(len(group)) for plan, group in replay.groupby("plan")},
        # replays that held the object with the other grip than the one demonstrated (failures)
        "replay_wrong_grip_holds": {
            plan: int(group["wrong_grip_hold"].astype(bool).sum())
            for plan, group in replay.groupby("plan")
        },
    }


# -- the variants (target x hidden units x iterations) ------------------------------------------

#: What tells the robot test's variants apart, the first columns of data/embodied/trials.csv.
VARIANT_COLUMNS = (
    "run",
    "categorisation_cue",
    "target",
    "hidden",
    "iterations",
    "learning_rate_schedule",
)


def variant_table(trials: pd.DataFrame) -> pd.DataFrame:
    """One row per variant, over its distinct trials (``distinct_trials``; ``trials`` counts
    them): its success on each task, how often the required grip's fingers touched, how soon
    (contact time over the trials that touched), and how many trials held the object with the
    other grip (``{task}_wrong_grip_hold``, failures by the grip criterion)."""
    import pandas as pd

    rows = []
    for key, df in distinct_trials(trials).groupby(list(VARIANT_COLUMNS), sort=False):
        row = dict(zip(VARIANT_COLUMNS, key, strict=True))
        row |= {"networks": int(df["network"].nunique()), "trials": len(df)}
        for task in ("grasping", "categorisation"):
            mine = df[df["task"] == task]
            touched = mine["contact_time"].notna()
            row |= {
                f"{task}_trials": len(mine),
                f"{task}_success": float(mine["success"].astype(float).mean()),
                f"{task}_contact": float(touched.mean()),
                f"{task}_contact_time": float(mine.loc[touched, "contact_time"].mean())
                if touched.any()
                else float("nan"),
                f"{task}_wrong_grip_hold": int(mine["wrong_grip_hold"].astype(bool).sum()),
            }
        row["success"] = float(df["success"].astype(float).mean())
        grasping = df[df["task"] == "grasping"]
        row["grasping_palm_error_mm"] = float(grasping["palm_error_mm"].median())
        rows.append(row)
    return pd.DataFrame(rows)


#: Bins of the palm's distance from the demonstrator's (mm) in which success is compared.
PALM_BINS_MM = (0.0, 3.0, 6.0, 10.0, 20.0, float("inf"))


def held_by_palm_error(trials: pd.DataFrame, edges=PALM_BINS_MM) -> pd.DataFrame:
    """Per bin of the palm's distance from the demonstrator's (column ``palm_error_mm``): the
    trials in it and the share that held the object; a bin is [low, high)."""
    import pandas as pd

    errors = trials["palm_error_mm"].to_numpy(dtype=float)
    held = trials["success"].astype(bool).to_numpy()
    rows = []
    for low, high in zip(edges[:-1], edges[1:], strict=True):
        inside = (errors >= low) & (errors < high)
        n = int(inside.sum())
        rows.append({"low_mm": low, "high_mm": high, "trials": n,
                     "held": float(held[inside].mean()) if n else float("nan")})  # fmt: skip
    return pd.DataFrame(rows)


def tolerance_table(tolerance: pd.DataFrame) -> pd.DataFrame:
    """Per noise level of the body's tolerance test: how often the mean plan still grasps, and
    how far the palm ended from the demonstrator's (median, mm); success per object too."""
    import pandas as pd

    rows = []
    for noise, df in tolerance.groupby("noise", sort=True):
        row = {"noise": float(noise), "trials": len(df)}
        row["success"] = float(df["success"].astype(float).mean())
        row["palm_error_mm"] = float(df["palm_error_mm"].median())
        for obj, mine in df.groupby("object", sort=False):
            row[f"{obj}_success"] = float(mine["success"].astype(float).mean())
        rows.append(row)
    return pd.DataFrame(rows)


def _counts(df: pd.DataFrame, factor: str, measure: str) -> dict[str, dict[str, float]]:
    """Per level of ``factor``: the distinct trials, how many have ``measure`` (contact time:
    those that touched), and its mean over them."""
    return {
        str(level): {
            "trials": len(g),
            "n": int(g[measure].notna().sum()),
            "mean": float(g[measure].mean()),
        }
        for level, g in df.groupby(factor, sort=True)
    }


#: The two levels of each factor the robot effects compare, the paper's faster one first.
FACTOR_LEVELS = {"congruency": ("congruent", "incongruent"), "size": ("large", "small")}


def _exact_test(df: pd.DataFrame, factor: str) -> dict[str, object]:
    """Fisher's exact test of success against ``factor``, over the distinct trials of ``df``
    (which takes a network's two objects of a level as independent: the fallback where the
    per-network contrast has no variance to test)."""
    from scipy.stats import fisher_exact

    first, second = FACTOR_LEVELS[factor]
    table = [
        [int(g["success"].sum()), int((~g["success"]).sum())]
        for g in (df[df[factor] == first], df[df[factor] == second])
    ]
    odds, p = fisher_exact(table)
    # an odds ratio of 0 or infinity (a rate of 0 or 1) has no JSON number: None
    odds = float(odds) if np.isfinite(odds) and odds > 0 else None
    return {"method": "exact", "table": table, "odds_ratio": odds, "p": float(p)}


def _contrasts_or_none(df: pd.DataFrame, measure: str) -> tuple[dict | None, int]:
    """The per-network contrasts of ``measure`` over the networks that have all four
    congruency x size cells, and how many do; None where fewer than three do (no degrees of
    freedom) or the design is singular."""
    from .stats import contrast_tests, per_network_contrasts

    per_net = per_network_contrasts(df, measure)
    if len(per_net) < 3:
        return None, len(per_net)
    try:
        with np.errstate(divide="ignore", invalid="ignore"):
            return contrast_tests(per_net), len(per_net)
    except (np.linalg.LinAlgError, ValueError):
        return None, len(per_net)


def _defined(term: dict) -> bool:
    """A contrast's test is defined: its standard error is finite and not zero (networks differ)."""
    return bool(np.isfinite(term["se"]) and term["se"] > 0 and np.isfinite(term["p"]))


def variant_effects(trials: pd.DataFrame) -> dict[str, object]:
    """Congruency and size effects on the robot's categorisation, per variant, over distinct
    trials (``distinct_trials``: each network x object counted once, whatever the number of test
    sequences).

    Success: per factor, the per-network contrast (``stats.network_contrasts`` on success as 0/1
    per network x object, a difference of proportions tested over the networks with t), where
    its test is defined; where it is not (every network shows the same contrast: no variance),
    Fisher's exact test over the distinct trials. Contact time: the per-network contrasts over
    the trials that touched, from the networks that touched in all four congruency x size cells;
    where that test is undefined (fewer than three such networks, or no variance) the effect is
    not estimable and says why. Each measure keeps its counts per level and the per-factor
    ``tests`` ({"method": "contrasts" | "exact" | "none", ...}); every defined test's p is also
    given Holm-adjusted over all the variants' tests together (``p_holm``).
    """
    out = {}
    for run, df in distinct_trials(trials).groupby("run", sort=False):
        df = df[(df["task"] == "categorisation")].copy()
        df["congruency"] = np.where(
            df["congruent"].astype(str) == "True", "congruent", "incongruent"
        )
        df["success"] = df["success"].astype(bool)
        held = df.assign(success=df["success"].astype(float))
        contrasts, networks = _contrasts_or_none(held, "success")
        tests: dict[str, object] = {}
        for factor in FACTOR_LEVELS:
            if contrasts is not None and _defined(contrasts[factor]):
                tests[factor] = {"method": "contrasts"} | contrasts[factor]
            else:
                tests[factor] = _exact_test(df, factor)
        success = {
            "distinct_trials": int(len(df)),
            "congruency": _counts(held, "congruency", "success"),
            "size": _counts(held, "size", "success"),
            "networks": networks,
            "contrasts": contrasts,
            "tests": tests,
        }
        touched = df[df["contact_time"].notna()]
        contrasts, networks = _contrasts_or_none(touched, "contact_time")
        tests = {}
        for factor in FACTOR_LEVELS:
            if contrasts is not None and _defined(contrasts[factor]):
                tests[factor] = {"method": "contrasts"} | contrasts[factor]
            else:
                reason = (
                    f"{networks} network(s) touched in all four congruency x size cells, "
                    "fewer than the three a test over networks needs"
                    if contrasts is None
                    else "every network that touched in all four cells shows the same contrast"
                )
                tests[factor] = {"method": "none", "reason": reason}
        contact = {
            "distinct_trials": int(len(df)),
            "congruency": _counts(df, "congruency", "contact_time"),
            "size": _counts(df, "size", "contact_time"),
            "networks": networks,
            "contrasts": contrasts,
            "tests": tests,
        }
        out[str(run)] = {"success": success, "contact_time": contact}
    _holm_over_family(out)
    return out


def _holm_over_family(effects: dict[str, dict]) -> None:
    """Every defined test of every variant, measure and factor is one family (the robot
    chapter reads them together): each gains ``p_holm``, Holm's adjustment over the family,
    which the verdicts read."""
    from .stats import holm

    tests = [
        test
        for measures in effects.values()
        for measure in measures.values()
        for test in measure["tests"].values()
        if test["method"] != "none"
    ]
    for test, p in zip(tests, holm([t["p"] for t in tests]), strict=True):
        test["p_holm"] = float(p)
