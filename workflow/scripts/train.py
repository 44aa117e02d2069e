"""Train Jordan networks and save each one's learning curve and weights: the network of the
wildcard `net` (rule train: one job per network), or every network of the run, one after
another (rule run_train: the outputs list them in order)."""

import numpy as np

from icub_affordance.io import redirect_log, save_npz, write_columns
from icub_affordance.spec import TASKS
from icub_affordance.train import (
    TrainConfig,
    load_materials,
    mapping_of,
    network_seed,
    train_network,
)


def as_list(paths):
    return [paths] if isinstance(paths, str) else list(paths)


def curve_columns(curve, objects):
    """The learning curve's table, column by column: one row per iteration."""
    return {
        "iteration": curve["iteration"].tolist(),
        "phase": curve["phase"].tolist(),
        "task": [TASKS[task] for task in curve["task"].tolist()],
        "object": [objects[obj] for obj in curve["object"].tolist()],
        "sequence": curve["sequence"].tolist(),
        "rmse": curve["rmse"].tolist(),
    }


with redirect_log(snakemake.log[0]):
    settings = dict(snakemake.params.network)
    n_networks = settings.pop("networks")
    # a confirmation's fresh networks start at this index (robot.confirmation); others at 0
    first = settings.pop("first_network", 0)
    if "net" in snakemake.wildcards.keys():
        nets = [int(snakemake.wildcards.net)]
    else:
        nets = list(range(first, first + n_networks))
    curves, weights_files = as_list(snakemake.output.curve), as_list(snakemake.output.weights)
    if len(curves) != len(nets) or not first <= min(nets) <= max(nets) < first + n_networks:
        raise ValueError(
            f"networks {nets} asked for, but the run's are {first}..{first + n_networks - 1}"
        )
    config = TrainConfig(**settings)
    materials = load_materials(snakemake.input.maps, snakemake.input.soms, snakemake.input.demos)
    for net, curve_path, weights_path in zip(nets, curves, weights_files, strict=True):
        mapping = mapping_of(net - first, n_networks)  # by its place in the run
        weights, curve = train_network(
            materials, config, mapping, network_seed(snakemake.params.seed, net)
        )
        weights.check_finite(f"network {net:02d}")
        if not np.all(np.isfinite(curve["rmse"])):
            raise FloatingPointError(
                f"network {net:02d}: its training error became NaN (the outputs diverged). "
                "Lower config network.learning_rate or network.init_scale."
            )
        # not pandas: a training job is short
        write_columns(curve_path, curve_columns(curve, materials.objects))
        save_npz(weights_path, **weights.as_dict())
        final = curve["rmse"][-500:].mean()
        print(f"network {net} (mapping {mapping}): final RMSE {final:.4f}")
