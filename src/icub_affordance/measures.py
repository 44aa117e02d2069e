"""Three measures of one test trial, declared before any result was read (config
``readings.measures``; MODEL.md section 8). Each stands for the reaction time; higher is slower.

- ``rmse``: the paper's, the root mean square over the predicted steps and the 16 DoF of the
  output's difference from the required grip's demonstration (as in ``eval/trials.csv``).
- ``time_to_commit``: the first step from which on the output stays nearer the required grip's
  demonstrated trajectory than the other grip's (the same object and sequence, compared step by
  step). Steps are numbered 1 .. steps-1 (step 0, the common initial posture, is not predicted);
  a trial whose output is not nearer the required grip at the last step never commits and
  scores ``steps`` (one past the last).
- ``rmse_per_grip_distance``: the trial's RMSE divided by the distance between the object's two
  demonstrated grips (same sequence): the root mean square over the predicted steps and 16 DoF of
  the power demonstration's difference from the precision one. It asks how far off the trial is
  in units of how far apart its two possible answers lie, which differs between objects: a large
  object's two grips are further apart than a small one's.
"""

from __future__ import annotations

import numpy as np

from .evaluate import TrialSet, describe_trial
from .jordan import Weights, run_closed_loop
from .spec import MODES
from .train import Materials

#: The measures, in the order of the tables; config ``readings.measures`` declares which are used.
MEASURES: tuple[str, ...] = ("rmse", "time_to_commit", "rmse_per_grip_distance")


def time_to_commit(outputs: np.ndarray, required: np.ndarray, other: np.ndarray) -> int:
    """The step from which on ``outputs`` stays nearer ``required`` than ``other``.

    ``outputs`` (steps-1, DoF): the postures the network output for steps 1 .. steps-1;
    ``required`` and ``other`` (steps, DoF): the two grips' demonstrated trajectories, step 0
    included. Nearer is a smaller Euclidean distance at the same step (a tie is not nearer).
    Returns a step in 1 .. steps-1, or ``steps`` if the last output is not nearer ``required``.
    """
    outputs, required, other = (np.asarray(a, dtype=float) for a in (outputs, required, other))
    if not (len(outputs) == len(required) - 1 == len(other) - 1):
        raise ValueError("outputs need one step fewer than the demonstrations (step 0 is given)")
    nearer = np.linalg.norm(outputs - required[1:], axis=1) < np.linalg.norm(
        outputs - other[1:], axis=1
    )
    not_nearer = np.flatnonzero(~nearer)
    return 1 if len(not_nearer) == 0 else int(not_nearer[-1]) + 2


def grip_distance(required: np.ndarray, other: np.ndarray) -> float:
    """The distance between two demonstrated grips (steps, DoF): RMS over steps 1 .. and DoF."""
    diff = np.asarray(required, dtype=float)[1:] - np.asarray(other, dtype=float)[1:]
    return float(np.sqrt((diff**2).mean()))


def measure_network(
    m: Materials, weights: Weights, network: int, mapping: str, cue: str, target: str
) -> list[dict[str, object]]:
    """One row per test trial of one network (both tasks and modes, as ``evaluate``), with every
    measure."""
    setup = TrialSet.of(m, mapping, cue, target)
    learned = m.targets(target)
    rows = []
    for mode in MODES:
        forced = setup.teacher if mode == "teacher_forced" else None
        out, _ = run_closed_loop(weights, setup.context, setup.teacher[:, 0], forced)
        for i, (_task, o, s) in enumerate(setup.trials):
            g = setup.grips[i]
            required, other = learned[o, g, s], learned[o, 1 - g, s]
            rmse = float(np.sqrt(((out[i] - required[1:]) ** 2).mean()))
            rows.append(
                describe_trial(m, setup, i, network, mapping, mode)
                | {
                    "rmse": rmse,
                    "time_to_commit": time_to_commit(out[i], required, other),
                    "rmse_per_grip_distance": rmse / grip_distance(required, other),
                }
            )
    return rows
