"""Train one Jordan network (the wildcard `net`) and save its learning curve and weights."""

import pandas as pd

from icub_affordance.io import atomic_path, redirect_log, save_npz
from icub_affordance.som import TASKS
from icub_affordance.train import (
    TrainConfig,
    load_materials,
    mapping_of,
    network_seed,
    train_network,
)

with redirect_log(snakemake.log[0]):
    settings = dict(snakemake.params.network)
    n_networks = settings.pop("networks")
    net = int(snakemake.wildcards.net)
    if net >= n_networks:
        raise ValueError(f"network {net} asked for, but config network.networks is {n_networks}")
    config = TrainConfig(**settings)
    materials = load_materials(snakemake.input.maps, snakemake.input.soms, snakemake.input.demos)
    mapping = mapping_of(net, n_networks)
    weights, curve = train_network(
        materials, config, mapping, network_seed(snakemake.params.seed, net)
    )
    table = pd.DataFrame(curve)
    table["task"] = [TASKS[k] for k in table["task"]]
    table["object"] = [materials.objects[o] for o in table["object"]]
    with atomic_path(snakemake.output.curve) as tmp:
        table.to_csv(tmp, index=False, float_format="%.6f")
    save_npz(snakemake.output.weights, **weights.as_dict())
    print(f"network {net} (mapping {mapping}): final RMSE {table['rmse'].tail(500).mean():.4f}")
