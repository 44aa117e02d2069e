"""One network (the wildcard `net`) drives the simulated arm through every test trial."""

from icub_affordance.body import Robot
from icub_affordance.demos import DemoConfig
from icub_affordance.embodied import embodied_network
from icub_affordance.io import load_npz, redirect_log, save_npz, write_csv
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
    write_csv(snakemake.output.trials, rows)
    save_npz(snakemake.output.states, qpos=states)
    rate = sum(row["success"] for row in rows) / len(rows)
    print(f"network {net}: {rate:.0%} of {len(rows)} trials succeed")
