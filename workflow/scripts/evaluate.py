"""Test all networks; one row per trial in data/eval/trials.csv."""

import numpy as np
import pandas as pd

from icub_affordance.files import atomic_path, redirect_log, save_npz
from icub_affordance.learning.materials import load_materials
from icub_affordance.learning.training import mapping_of
from icub_affordance.trials.in_silico import evaluate_network
from icub_workflow.parts import load_weights

with redirect_log(snakemake.log[0]):
    materials = load_materials(
        snakemake.input.maps,
        snakemake.input.soms,
        snakemake.input.demos,
        snakemake.params.grip_distance,
    )
    n_networks = snakemake.params.network["networks"]
    cue = snakemake.params.network["categorisation_cue"]
    target = snakemake.params.network["target"]
    rows, hidden = [], {}
    for net, weights in load_weights(list(snakemake.input.weights)):
        weights.check_finite(f"network {net:02d}")
        net_rows, net_hidden = evaluate_network(
            materials, weights, net, mapping_of(net, n_networks), cue, target
        )
        rows += net_rows
        for mode, h in net_hidden.items():
            hidden[f"net{net:02d}__{mode}"] = h
    with atomic_path(snakemake.output.trials) as tmp:
        pd.DataFrame(rows).to_csv(tmp, index=False, float_format="%.6f")
    save_npz(snakemake.output.hidden, **{k: np.asarray(v) for k, v in hidden.items()})
