"""What the distractor's job does (rule ``distractor``; config ``distractor``), for its script: a
module of its own, so that adding it reruns no other job (a job's code is every module its script
imports, ``common.smk: script_code``)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from icub_affordance.files import atomic_path
from icub_affordance.learning.training import mapping_of
from icub_workflow.parts import load_weights


def distractor_tables(
    replications: Sequence[Mapping],
    declaration: Mapping,
    min_replications: int,
    outputs: Mapping[str, str],
) -> None:
    """A distractor at test on each of the confirmation's replications
    (``icub_affordance.trials.distractor``): every categorisation trial at weight 0 (the paper's
    test, the reference), each declared weight and each inhibition weight (``outputs["trials"]``);
    each replication's estimates (``estimates``) and the tests over them (``summary``;
    ``icub_affordance.analysis.distractor_tests``), a test only with ``min_replications``
    estimates. A replication: its seed, model inputs (maps, soms, demos), grip_distance, network
    settings and weights files."""
    import pandas as pd

    from icub_affordance.analysis.distractor_tests import replication_estimates, summary
    from icub_affordance.learning.materials import load_materials
    from icub_affordance.trials.distractor import distractor_trials

    lambdas = [0.0, *declaration["lambdas"], *declaration["inhibition"]]
    rows = []
    for rep in replications:
        materials = load_materials(rep["maps"], rep["soms"], rep["demos"], rep["grip_distance"])
        network = rep["network"]
        cue, target = network["categorisation_cue"], network["target"]
        for net, weights in load_weights(rep["weights"]):
            mapping = mapping_of(net, network["networks"])
            trials = distractor_trials(materials, weights, net, mapping, cue, target, lambdas)
            rows += [{"replication": rep["seed"], "cue": cue, **row} for row in trials]
        print(f"replication at seed {rep['seed']} ({cue}): tested")
    with atomic_path(outputs["trials"]) as tmp:
        pd.DataFrame(rows).to_csv(tmp, index=False, float_format="%.6g")
    trials = pd.read_csv(outputs["trials"])  # as readers see it: a recomputation from it agrees
    estimates = replication_estimates(trials, declaration["measures"])
    tables = {"estimates": estimates, "summary": summary(estimates, declaration, min_replications)}
    for name, table in tables.items():
        with atomic_path(outputs[name]) as tmp:
            table.to_csv(tmp, index=False, float_format="%.6g")
