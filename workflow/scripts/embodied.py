"""One network (the wildcard `net`) drives the simulated arm through every test trial."""

import pandas as pd

from icub_affordance.body import Robot
from icub_affordance.demos import DemoConfig
from icub_affordance.embodied import embodied_network
from icub_affordance.io import atomic_path, load_npz, redirect_log, save_npz
from icub_affordance.jordan import Weights
from icub_affordance.train import load_materials, mapping_of

with redirect_log(snakemake.log[0]):
    settings = snakemake.params.network
    net = int(snakemake.wildcards.net)
    materials = load_materials(snakemake.input.maps, snakemake.input.soms, snakemake.input.demos)
    stored = load_npz(snakemake.input.weights, required=("W1", "b1", "W2", "b2"))
    weights = Weights(**{k: stored[k] for k in ("W1", "b1", "W2", "b2")})
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    rows, states = embodied_network(
        robot,
        materials,
        weights,
        net,
        mapping_of(net, settings["networks"]),
        settings["categorisation_cue"],
        DemoConfig(**snakemake.params.demos),
    )
    table = pd.DataFrame(rows)
    with atomic_path(snakemake.output.trials) as tmp:
        table.to_csv(tmp, index=False, float_format="%.6f")
    save_npz(snakemake.output.states, qpos=states)
    print(f"network {net}: {table['success'].mean():.0%} of {len(table)} trials succeed")
