"""The measures of one test trial, declared in the config (``readings.measures``) before any of
their results was read (book/notes.md, "Testing and statistics"). For every measure, higher is
further from the required grip: the paper's reading is that higher is slower.

- ``rmse``: the paper's, the root mean square over the predicted steps and the 16 DoF of the
  output's difference from the required grip's demonstration (as in ``eval/trials.csv``).
- ``wrong_grip``: 1 if the trial's final posture (the output at the last step) is nearer, in
  Euclidean distance over the 16 DoF, the other grip's demonstrated final posture than the
  required grip's (same object and sequence), else 0: the ``final_grip`` column of
  ``eval/trials.csv`` differing from ``target_grip`` (a tie is not wrong). A network's mean over
  an object's sequences is a proportion; the analysis takes each network x object's proportion
  once, as for every measure (``trial_effects.network_contrasts``).
- ``commitment``: how far along the line from the required grip to the other grip the output
  moved. At predicted step t, with r_t and q_t the required and the other grip's demonstrated
  postures and o_t the output, the output's position on the line from r_t (0) to q_t (1) is
  (o_t - r_t).(q_t - r_t) / |q_t - r_t|^2; the component of o_t - r_t off that line is ignored.
  One number per trial: the least-squares position over the predicted steps,
  sum_t (o_t - r_t).(q_t - r_t) / sum_t |q_t - r_t|^2, the single position c for which the
  postures r_t + c (q_t - r_t) come nearest the outputs. It weighs each step by how far apart the
  two grips are there (squared), so the first steps, where both grips are still near the common
  initial posture and a step's own position is unstable, count little. 0 is on the required
  grip throughout, 1 on the other, 0.5 halfway. The per-step positions are kept too
  (``commitment_step{t}``, for a figure; not analysed).
- ``rmse_per_grip_distance``: the trial's RMSE divided by the distance between the object's two
  demonstrated grips (same sequence): the root mean square over the predicted steps and 16 DoF of
  the other grip's demonstration's difference from the required one's. A large object's two
  grips lie further apart than a small one's, so the division alone favours a size effect in the
  paper's direction (small higher). Kept only beside its null control,
  ``rmse_per_grip_distance_null``: the same division applied to a constant error, each
  network's own mean RMSE over its categorisation trials of the test mode divided by each
  trial's grip distance. Whatever effect the null control shows comes from the denominator
  alone.

- ``rmse_correct``: the trial's RMSE where its grip was right (``wrong_grip`` 0), else undefined:
  the reaction-time analogue, as people's reaction times are measured on correct responses with
  errors reported apart. Derived at analysis time from ``rmse`` and ``wrong_grip``
  (``trial_effects.with_outcomes``), not a column of ``measures.csv``. In closed loop a network's
  trials of one object are one trial, so a network that always took the wrong grip on an object has
  no value there: a network can lack a cell by design (``MISSING_BY_DESIGN``).

``time_to_commit`` (the first step from which the output stayed nearer the required grip) was
retired: in closed loop it took almost only the values 1 and ``steps``, the latter exactly for
the trials that ended nearer the wrong grip, so it was a rescaled wrong-grip indicator, not a
latency.
"""

from __future__ import annotations

import numpy as np

from icub_affordance.learning.materials import Materials
from icub_affordance.learning.network import Weights, run_closed_loop
from icub_affordance.trials.in_silico import TrialSet, describe_trial
from icub_affordance.vocabulary import MODES

#: The measures that can be declared, in the order of the tables (config ``readings.measures``).
MEASURES: tuple[str, ...] = (
    "rmse",
    "rmse_correct",
    "wrong_grip",
    "commitment",
    "rmse_per_grip_distance",
)

#: Each measure's name in the book's tables, its null control's and excess's too.
LABELS: dict[str, str] = {
    "rmse": "RMSE",
    "rmse_correct": "correct-trial RMSE",
    "wrong_grip": "wrong-grip rate",
    "commitment": "commitment",
    "rmse_per_grip_distance": "RMSE per grip distance",
    "rmse_per_grip_distance_null": "null control",
    "rmse_per_grip_distance_excess": "excess over null",
}

#: The measures computed at analysis time from other measures' columns
#: (``trial_effects.with_outcomes``), with the columns each needs: not written by
#: ``measure_network``.
DERIVED: dict[str, tuple[str, ...]] = {"rmse_correct": ("rmse", "wrong_grip")}

#: The measures a network can lack in a cell by design (no correct trial of an object): their
#: contrasts come from ``trial_effects.correct_trial_effects``, which keeps such a network, never
#: from the per-network contrasts, which drop it. Declared here, never read off the data.
MISSING_BY_DESIGN: frozenset[str] = frozenset({"rmse_correct"})

#: A measure's null control, analysed beside it whenever it is declared (not a hypothesis).
NULL_CONTROLS: dict[str, str] = {"rmse_per_grip_distance": "rmse_per_grip_distance_null"}


#: A measure with a null control is tested by its excess over it: each trial's value minus its
#: null control's, what the movements add to what the denominator alone makes. The measure and
#: its null control are shown beside the excess; the excess is the hypothesis.
EXCESS: dict[str, str] = {"rmse_per_grip_distance": "rmse_per_grip_distance_excess"}


def analysed(measures) -> list[str]:
    """The declared measures with each one's null control and excess right after it: what is
    analysed."""
    unknown = [m for m in measures if m not in MEASURES]
    if unknown:
        raise ValueError(f"unknown measure(s) {unknown}; the measures are {list(MEASURES)}")
    out = []
    for m in measures:
        out += [m] + ([NULL_CONTROLS[m], EXCESS[m]] if m in NULL_CONTROLS else [])
    return out


def is_null_control(measure: str) -> bool:
    return measure in NULL_CONTROLS.values()


def is_hypothesis(measure: str) -> bool:
    """A measure whose tests are hypotheses: not a null control, and not a measure that is
    tested by its excess over its null control (``EXCESS``: that measure is shown beside it)."""
    return not is_null_control(measure) and measure not in EXCESS


def margin_measure(measure: str) -> str:
    """Whose declared equivalence margin a measure uses: an excess its measure's (same units)."""
    return next((m for m, excess in EXCESS.items() if excess == measure), measure)


def with_excess(trials):
    """``trials`` (a table with the measures' columns) with each ``EXCESS`` column: the measure
    minus its null control, trial by trial."""
    out = trials.copy()
    for measure, excess in EXCESS.items():
        if measure in out and NULL_CONTROLS[measure] in out:
            out[excess] = out[measure] - out[NULL_CONTROLS[measure]]
    return out


def is_derived(measure: str) -> bool:
    return measure in DERIVED


def can_lack_cells(measure: str) -> bool:
    return measure in MISSING_BY_DESIGN


def _check(outputs, required, other) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    outputs, required, other = (np.asarray(a, dtype=float) for a in (outputs, required, other))
    if not (len(outputs) == len(required) - 1 == len(other) - 1):
        raise ValueError("outputs need one step fewer than the demonstrations (step 0 is given)")
    if not (outputs.shape[1:] == required.shape[1:] == other.shape[1:]):
        raise ValueError("outputs and demonstrations need the same DoF")
    return outputs, required[1:], other[1:]


def wrong_grip(outputs: np.ndarray, required: np.ndarray, other: np.ndarray) -> int:
    """1 if the last output is strictly nearer the other grip's final posture than the required
    grip's, else 0. ``outputs`` (steps-1, DoF): steps 1 .. steps-1; ``required`` and ``other``
    (steps, DoF): the two grips' demonstrated trajectories, step 0 included."""
    outputs, required, other = _check(outputs, required, other)
    last = outputs[-1]
    return int(np.linalg.norm(last - other[-1]) < np.linalg.norm(last - required[-1]))


def commitment_steps(outputs: np.ndarray, required: np.ndarray, other: np.ndarray) -> np.ndarray:
    """Each predicted step's position of the output on the line from the required grip's
    posture (0) to the other grip's (1); NaN at a step where the two grips coincide."""
    outputs, required, other = _check(outputs, required, other)
    line = other - required
    length2 = (line**2).sum(axis=1)
    along = ((outputs - required) * line).sum(axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(length2 > 0, along / np.where(length2 > 0, length2, 1), np.nan)


def commitment(outputs: np.ndarray, required: np.ndarray, other: np.ndarray) -> float:
    """The trial's commitment: the least-squares position over the predicted steps,
    sum_t (o_t - r_t).(q_t - r_t) / sum_t |q_t - r_t|^2 (module docstring); NaN if the two grips
    coincide at every step."""
    outputs, required, other = _check(outputs, required, other)
    line = other - required
    total = float((line**2).sum())
    return float(((outputs - required) * line).sum() / total) if total > 0 else float("nan")


def grip_distance(required: np.ndarray, other: np.ndarray) -> float:
    """The distance between two demonstrated grips (steps, DoF): RMS over steps 1 .. and DoF."""
    diff = np.asarray(required, dtype=float)[1:] - np.asarray(other, dtype=float)[1:]
    return float(np.sqrt((diff**2).mean()))


def measure_network(
    m: Materials, weights: Weights, network: int, mapping: str, cue: str, target: str
) -> list[dict[str, object]]:
    """One row per test trial of one network (both tasks and modes, as ``evaluate``), with every
    measure, its null control and the per-step commitment."""
    setup = TrialSet.of(m, mapping, cue, target)
    learned = m.targets(target)
    rows = []
    for mode in MODES:
        forced = setup.teacher if mode == "teacher_forced" else None
        out, _ = run_closed_loop(weights, setup.context, setup.teacher[:, 0], forced)
        mode_rows = []
        for i, (_task, o, s) in enumerate(setup.trials):
            g = setup.grips[i]
            required, other = learned[o, g, s], learned[o, 1 - g, s]
            rmse = float(np.sqrt(((out[i] - required[1:]) ** 2).mean()))
            steps = commitment_steps(out[i], required, other)
            mode_rows.append(
                describe_trial(m, setup, i, network, mapping, mode)
                | {
                    "rmse": rmse,
                    "wrong_grip": wrong_grip(out[i], required, other),
                    "commitment": commitment(out[i], required, other),
                    "rmse_per_grip_distance": rmse / grip_distance(required, other),
                    "grip_distance": grip_distance(required, other),
                }
                | {f"commitment_step{t + 1}": float(v) for t, v in enumerate(steps)}
            )
        categorisation = [r["rmse"] for r in mode_rows if r["task"] == "categorisation"]
        constant = float(np.mean(categorisation))
        for r in mode_rows:
            r["rmse_per_grip_distance_null"] = constant / r["grip_distance"]
        rows += mode_rows
    return rows
