"""Train one Jordan network (the wildcard `net`) and save its learning curve and weights."""

import numpy as np

from icub_affordance.io import redirect_log, save_npz, write_csv
from icub_affordance.spec import TASKS
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
    weights.check_finite(f"network {net:02d}")
    if not np.all(np.isfinite(curve["rmse"])):
        raise FloatingPointError(
            f"network {net:02d}: its training error became NaN (the outputs diverged). Lower "
            "config network.learning_rate or network.init_scale."
        )
    columns = ("iteration", "phase", "task", "object", "sequence", "rmse")
    rows = [
        dict(zip(columns, (i, phase, TASKS[task], materials.objects[obj], seq, rmse), strict=True))
        for i, phase, task, obj, seq, rmse in zip(
            curve["iteration"], curve["phase"], curve["task"], curve["object"],
            curve["sequence"], curve["rmse"].tolist(), strict=True,
        )
    ]  # fmt: skip
    write_csv(snakemake.output.curve, rows)  # not pandas: a training job is short
    save_npz(snakemake.output.weights, **weights.as_dict())
    final = curve["rmse"][-500:].mean()
    print(f"network {net} (mapping {mapping}): final RMSE {final:.4f}")
