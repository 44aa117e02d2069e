"""A network of a run with names tested in every form (the words study, config ``words``): each
test trial showing its object's image alone, its name alone and both (vocabulary.FORMS), scored
on every measure (``scores.measure_network``), and the hidden state each form reaches at a
declared step, for the question whether a name re-activates its object's representation.
"""

from __future__ import annotations

import numpy as np

from icub_affordance.learning.materials import Materials
from icub_affordance.learning.network import Weights, run_closed_loop
from icub_affordance.trials.in_silico import TrialSet
from icub_affordance.trials.scores import measure_network
from icub_affordance.vocabulary import FORMS


def measure_forms(
    m: Materials, weights: Weights, network: int, mapping: str, cue: str, target: str
) -> list[dict[str, object]]:
    """One row per test trial and form: ``scores.measure_network``'s on what the form shows,
    with its ``form``."""
    return [
        row | {"form": form}
        for form in FORMS
        for row in measure_network(m.shown(form), weights, network, mapping, cue, target)
    ]


def form_states(
    m: Materials, weights: Weights, mapping: str, cue: str, target: str, step: int
) -> tuple[list[tuple[int, int, int]], dict[str, np.ndarray]]:
    """The trials (task, object, sequence) and, for each form, every trial's hidden state at
    predicted step ``step`` (1: the first), (trials, hidden), the demonstrated postures fed
    back. At the first step both test modes feed the demonstration's first posture, the same
    for every trial (every demonstration starts at the initial posture): the state there
    depends on what the trial shows and its task alone."""
    states, trials = {}, None
    for form in FORMS:
        setup = TrialSet.of(m, mapping, cue, target, form)
        context = setup.context[:, :step]
        _, hidden = run_closed_loop(weights, context, setup.teacher[:, 0], setup.teacher)
        states[form], trials = hidden[:, step - 1], setup.trials
    return trials, states
