"""What a words replication's job does (rule word_trials): its networks tested in every form.

Apart from ``steps`` (training and measuring), so that editing the words study's analysis reruns
its own jobs, not the trainings of every run (each rule's code is what its script imports).
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence

import pandas as pd

from icub_affordance.files import atomic_path, write_text
from icub_affordance.learning.materials import Materials
from icub_affordance.learning.training import mapping_of
from icub_affordance.vocabulary import FORMS
from icub_workflow.parts import load_weights


def word_trials(
    materials: Materials,
    network: Mapping,
    weights_files: Sequence[str],
    measures: Sequence[str],
    step: int,
    trials_path: str,
    json_path: str,
) -> None:
    """A words replication (config ``words``): every test trial of its networks in every form,
    scored on each declared measure (``trials_path``); each form's contrasts over its networks
    and each network's reactivation contrast at ``step`` (``json_path``)."""
    from icub_affordance.analysis.name_effects import reactivation
    from icub_affordance.analysis.reading_tests import analyse_measures
    from icub_affordance.trials.forms import form_states, measure_forms

    n_networks = network["networks"]
    cue, target = network["categorisation_cue"], network["target"]
    rows, contrasts = [], []
    for net, weights in load_weights(weights_files):
        mapping = mapping_of(net, n_networks)
        rows += measure_forms(materials, weights, net, mapping, cue, target)
        trials, states = form_states(materials, weights, mapping, cue, target, step)
        contrast = reactivation(trials, states["name"], states["image"])
        contrasts.append({"network": net, "contrast": contrast})
    with atomic_path(trials_path) as tmp:
        pd.DataFrame(rows).to_csv(tmp, index=False, float_format="%.6f")
    table = pd.read_csv(trials_path, keep_default_na=False)  # as readers see it
    forms = {form: analyse_measures(table[table["form"] == form], list(measures)) for form in FORMS}
    result = {"forms": forms, "reactivation": contrasts}
    write_text(json_path, json.dumps(result, indent=2, sort_keys=True) + "\n")
