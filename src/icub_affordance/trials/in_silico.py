"""Testing the trained networks (paper section 3): every task, object and sequence, two ways.

Closed loop: the network's own output is its next proprioceptive input, as the robot would move;
teacher forced: the demonstrated posture is. One trial's RMSE is over its steps and the 16 DoF,
and stands for the reaction time (paper section 3).

A network that learned the servo targets (config ``network.target: commands``) is compared with
the servo targets it learned. Its in-silico closed loop feeds each command back as if the arm had
reached it: true in free space, not where the fingers meet the object and a command lies beyond
the posture reached. That loop is therefore the plan the network would send unopposed; its own
closed loop runs through the body, in the robot test (``robot_trials``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from icub_affordance.learning.materials import Materials
from icub_affordance.learning.network import Weights, run_closed_loop
from icub_affordance.learning.training import context, target_grip
from icub_affordance.vocabulary import GRASPING, MODES, OBJECTS, TASKS


def evaluate_network(
    m: Materials, weights: Weights, network: int, mapping: str, cue: str, target: str
) -> tuple[list[dict[str, object]], dict[str, np.ndarray]]:
    """One row per trial, and the hidden activity of every trial for later analysis."""
    setup = TrialSet.of(m, mapping, cue, target)
    rows, hidden = [], {}
    for mode in MODES:
        forced = setup.teacher if mode == "teacher_forced" else None
        out, hid = run_closed_loop(weights, setup.context, setup.teacher[:, 0], forced)
        if not np.all(np.isfinite(out)):
            raise FloatingPointError(
                f"network {network:02d} outputs NaN or infinity ({mode}): its results would be "
                "meaningless. Retrain it with a lower config network.learning_rate or init_scale."
            )
        hidden[mode] = hid
        rows += [
            trial_row(m, setup, i, out[i], out[i, -1], network, mapping, mode)
            for i in range(len(setup.trials))
        ]
    return rows, hidden


@dataclass(frozen=True)
class TrialSet:
    """Every test trial of one network: task, object, sequence, and what it is shown and taught."""

    trials: list[tuple[int, int, int]]  # (task, object, sequence)
    grips: list[int]  # the grip each trial requires, as an index into Materials.grips
    context: np.ndarray  # (trials, steps-1, 200) the maps' input at every step
    teacher: np.ndarray  # (trials, steps, 16) the demonstration of the required grip (sensed)
    targets: np.ndarray  # (trials, steps, 16) what the outputs are compared with (network.target)

    @classmethod
    def of(cls, m: Materials, mapping: str, cue: str, target: str, form: str = "image") -> TrialSet:
        """Every trial, showing ``form`` of its object (vocabulary.FORMS): the image, as the
        paper's tests do, unless asked; a run without names shows nothing else."""
        m = m.shown(form)
        n_seq = m.demos.shape[2]
        trials = [
            (task, o, s)
            for task in range(len(TASKS))
            for o in range(len(m.objects))
            for s in range(n_seq)
        ]
        grips = [m.grips.index(target_grip(m.objects[o], task, mapping)) for task, o, _ in trials]
        ctx = np.array([context(m, o, task, cue) for task, o, _ in trials])
        pairs = list(zip(trials, grips, strict=True))
        teacher = np.array([m.demos[o, g, s] for (_, o, s), g in pairs])
        learned = m.targets(target)
        targets = (
            teacher
            if learned is m.demos
            else np.array([learned[o, g, s] for (_, o, s), g in pairs])
        )
        return cls(trials, grips, ctx, teacher, targets)


def describe_trial(
    m: Materials, setup: TrialSet, i: int, network: int, mapping: str, mode: str
) -> dict[str, object]:
    """What a trial was: the network, the test mode, the task, the object and the grip asked for.
    The first columns of every table of trials (evaluation, measures, robot test)."""
    task, o, s = setup.trials[i]
    obj, grip = m.objects[o], m.grips[setup.grips[i]]
    info = OBJECTS[obj]
    return {
        "network": network,
        "mapping": mapping,
        "mode": mode,
        "task": TASKS[task],
        "object": obj,
        "size": info.size,
        "category": info.category,
        "natural_grip": info.natural_grip,
        "target_grip": grip,
        "congruent": "" if task == GRASPING else str(grip == info.natural_grip),
        "sequence": s,
    }


def trial_row(
    m: Materials,
    setup: TrialSet,
    i: int,
    outputs: np.ndarray,
    final_posture: np.ndarray,
    network: int,
    mapping: str,
    mode: str,
) -> dict[str, object]:
    """One trial's row: what it was, its RMSE against what it learned, and per step.

    ``final_grip`` is the grip whose demonstrated final posture (same object and sequence) is
    nearer to ``final_posture``.
    """
    _task, o, s = setup.trials[i]
    sq = (outputs - setup.targets[i, 1:]) ** 2  # (steps-1, 16)
    nearest = int(np.argmin(np.linalg.norm(m.demos[o, :, s, -1] - final_posture, axis=1)))
    row = describe_trial(m, setup, i, network, mapping, mode) | {
        "held_out": s == m.demos.shape[2] - 1,
        "rmse": float(np.sqrt(sq.mean())),
        "final_grip": m.grips[nearest],
    }
    row |= {f"rmse_step{t + 1}": float(v) for t, v in enumerate(np.sqrt(sq.mean(axis=1)))}
    return row
