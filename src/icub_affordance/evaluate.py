"""Testing the trained networks (paper section 3): every task, object and sequence, two ways.

Closed loop: the network's own output is its next proprioceptive input, as the robot would move;
teacher forced: the demonstrated posture is. One trial's RMSE is over its steps and the 16 DoF,
and stands for the reaction time (paper section 3).
"""

from __future__ import annotations

import numpy as np

from .body import OBJECTS
from .jordan import Weights, run_closed_loop
from .som import TASKS
from .train import GRASPING, Materials, context, target_grip

MODES = ("closed_loop", "teacher_forced")


def evaluate_network(
    m: Materials, weights: Weights, network: int, mapping: str, cue: str
) -> tuple[list[dict[str, object]], dict[str, np.ndarray]]:
    """One row per trial, and the hidden activity of every trial for later analysis."""
    n_seq = m.demos.shape[2]
    trials = [
        (task, o, s)
        for task in range(len(TASKS))
        for o in range(len(m.objects))
        for s in range(n_seq)
    ]
    grips = [m.grips.index(target_grip(m.objects[o], task, mapping)) for task, o, _ in trials]
    ctx = np.array([context(m, o, task, cue) for task, o, _ in trials])
    teacher = np.array([m.demos[o, g, s] for (_, o, s), g in zip(trials, grips, strict=True)])
    rows, hidden = [], {}
    for mode in MODES:
        forced = teacher if mode == "teacher_forced" else None
        out, hid = run_closed_loop(weights, ctx, teacher[:, 0], forced)
        hidden[mode] = hid
        sq = (out - teacher[:, 1:]) ** 2  # (trials, steps-1, 16)
        per_step = np.sqrt(sq.mean(axis=2))
        overall = np.sqrt(sq.mean(axis=(1, 2)))
        # which grip the final output is nearer to (the same object and sequence's two demos)
        finals = m.demos[:, :, :, -1]  # (objects, grips, seq, 16)
        for i, ((task, o, s), g) in enumerate(zip(trials, grips, strict=True)):
            obj = m.objects[o]
            info = OBJECTS[obj]
            grip = m.grips[g]
            nearest = int(np.argmin(np.linalg.norm(finals[o, :, s] - out[i, -1], axis=1)))
            congruent = "" if task == GRASPING else str(grip == info.natural_grip)
            row = {
                "network": network,
                "mapping": mapping,
                "mode": mode,
                "task": TASKS[task],
                "object": obj,
                "size": info.size,
                "category": info.category,
                "natural_grip": info.natural_grip,
                "target_grip": grip,
                "congruent": congruent,
                "sequence": s,
                "held_out": s == n_seq - 1,
                "rmse": float(overall[i]),
                "final_grip": m.grips[nearest],
            }
            row |= {f"rmse_step{t + 1}": float(v) for t, v in enumerate(per_step[i])}
            rows.append(row)
    return rows, hidden
