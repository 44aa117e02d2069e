"""Every test trial's measures (data/eval/measures.csv), and their per-network contrasts and
per-object means (data/eval/measures.json)."""

import json

import pandas as pd

from icub_affordance.io import atomic_path, load_npz, redirect_log, write_text
from icub_affordance.jordan import Weights
from icub_affordance.measures import measure_network
from icub_affordance.readings import analyse_measures
from icub_affordance.train import load_materials, mapping_of

with redirect_log(snakemake.log[0]):
    materials = load_materials(snakemake.input.maps, snakemake.input.soms, snakemake.input.demos)
    n_networks = snakemake.params.network["networks"]
    cue = snakemake.params.network["categorisation_cue"]
    target = snakemake.params.network["target"]
    rows = []
    for net, path in enumerate(snakemake.input.weights):
        weights = Weights(**load_npz(path, required=("W1", "b1", "W2", "b2")))
        mapping = mapping_of(net, n_networks)
        rows += measure_network(materials, weights, net, mapping, cue, target)
    trials = pd.DataFrame(rows)
    with atomic_path(snakemake.output.trials) as tmp:
        trials.to_csv(tmp, index=False, float_format="%.6f")
    trials = pd.read_csv(snakemake.output.trials, keep_default_na=False)  # as readers see it
    result = analyse_measures(trials, list(snakemake.params.measures))
    write_text(snakemake.output.json, json.dumps(result, indent=2, sort_keys=True) + "\n")
