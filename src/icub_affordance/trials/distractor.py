"""A distractor at test (config ``distractor``; the paper's future work, issue 73): the trained
networks see the target and a second object together, no new training.

The reading is a sum of inputs at the network (docs/distractor.md says why): every input the
image reaches, the visual map and the Goal map's response, is the target's plus ``lam`` times the
distractor's, each object's maps' response computed as in training; the Task map is the trial's,
the required grip the target's category's under the network's mapping. ``lam`` 0 is the paper's
test, to the bit (tests/test_distractor.py); ``lam`` > 0 a distractor that leaks into
perception; ``lam`` < 0 its features pushed down, a stand-in for top-down inhibition.

Every categorisation trial (target x sequence) is run with every other object as distractor, in
both test modes, and scored on the trial's RMSE and wrong grip as ``scores.measure_network``.
A distractor is set by a shift of the object axis (distractor = (target + shift) mod objects), so
that each run of the network is one batch of the evaluation's own shape: the no-distractor
trials' arithmetic exactly.
"""

from __future__ import annotations

import numpy as np

from icub_affordance.learning.materials import Materials
from icub_affordance.learning.network import N_GOAL, N_VISUAL, Weights, run_closed_loop
from icub_affordance.learning.training import context
from icub_affordance.trials.in_silico import TrialSet, describe_trial
from icub_affordance.trials.scores import wrong_grip
from icub_affordance.vocabulary import CATEGORISATION, MODES, OBJECTS

#: The inputs the image reaches (the visual map and the Goal map's response): the distractor's
#: weighted share is added to these; the names' units, if any, are the target's alone.
IMAGE_INPUTS = slice(0, N_VISUAL + N_GOAL)


def with_distractor(m: Materials, setup: TrialSet, cue: str, shift: int, lam: float) -> np.ndarray:
    """``setup``'s input with each trial's distractor, the object ``shift`` places on along the
    object axis, added at weight ``lam`` to the inputs the image reaches (same task, same cue
    timing): (trials, steps-1, inputs)."""
    ctx = setup.context.copy()
    n = len(m.objects)
    for i, (task, o, _s) in enumerate(setup.trials):
        other = context(m, (o + shift) % n, task, cue)
        ctx[i, :, IMAGE_INPUTS] += lam * other[:, IMAGE_INPUTS]
    return ctx


def distractor_trials(
    m: Materials,
    weights: Weights,
    network: int,
    mapping: str,
    cue: str,
    target: str,
    lambdas,
) -> list[dict[str, object]]:
    """One row per categorisation trial, distractor, weight ``lam`` (of ``lambdas``) and test
    mode: what the trial was (``in_silico.describe_trial``), its distractor and whether the grip
    asked is the distractor's natural grip (``compatible``), and the trial's ``rmse`` and
    ``wrong_grip`` against the required grip (``scores``)."""
    setup = TrialSet.of(m, mapping, cue, target)
    learned = m.targets(target)
    shown = [i for i, (task, _o, _s) in enumerate(setup.trials) if task == CATEGORISATION]
    rows = []
    for lam in lambdas:
        for shift in range(1, len(m.objects)):
            ctx = with_distractor(m, setup, cue, shift, float(lam))
            for mode in MODES:
                forced = setup.teacher if mode == "teacher_forced" else None
                out, _ = run_closed_loop(weights, ctx, setup.teacher[:, 0], forced)
                for i in shown:
                    _task, o, s = setup.trials[i]
                    g = setup.grips[i]
                    required, other = learned[o, g, s], learned[o, 1 - g, s]
                    distractor = m.objects[(o + shift) % len(m.objects)]
                    natural = OBJECTS[distractor].natural_grip
                    rows.append(
                        describe_trial(m, setup, i, network, mapping, mode)
                        | {
                            "lam": float(lam),
                            "distractor": distractor,
                            "distractor_grip": natural,
                            "compatible": m.grips[g] == natural,
                            "rmse": float(np.sqrt(((out[i] - required[1:]) ** 2).mean())),
                            "wrong_grip": wrong_grip(out[i], required, other),
                        }
                    )
    return rows
