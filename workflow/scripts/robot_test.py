"""Networks drive the simulated arm through every test trial: the network of the wildcard `net`
(rule robot_test: one job per network), or every network of a run, one after another (rules
run_robot_test, confirmation_robot_test: the outputs list them in order)."""

from icub_affordance.body import Robot
from icub_affordance.demos import DemoConfig
from icub_affordance.io import redirect_log, save_npz, write_csv
from icub_affordance.robot_test import embodied_network
from icub_affordance.train import load_materials, mapping_of
from icub_workflow.parts import load_weights


def as_list(paths):
    return [paths] if isinstance(paths, str) else list(paths)


with redirect_log(snakemake.log[0]):
    settings = snakemake.params.network
    trained = dict(load_weights(as_list(snakemake.input.weights)))
    trials_files, states_files = as_list(snakemake.output.trials), as_list(snakemake.output.states)
    first = settings.get("first_network", 0)  # a confirmation's fresh networks start here
    if "net" in snakemake.wildcards.keys():
        nets = [int(snakemake.wildcards.net)]
    else:
        nets = list(range(first, first + settings["networks"]))
    if not set(nets) <= set(trained) or not len(nets) == len(trials_files) == len(states_files):
        raise ValueError(f"networks {nets}, but weights of {sorted(trained)}")
    materials = load_materials(
        snakemake.input.maps,
        snakemake.input.soms,
        snakemake.input.demos,
        snakemake.params.grip_distance,
    )
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    for net, trials_path, states_path in zip(nets, trials_files, states_files, strict=True):
        rows, states = embodied_network(
            robot,
            materials,
            trained[net],
            net,
            mapping_of(net - first, settings["networks"]),  # by its place in the run
            settings["categorisation_cue"],
            settings["target"],
            DemoConfig(**snakemake.params.demos),
        )
        write_csv(trials_path, rows)
        save_npz(states_path, qpos=states)
        rate = sum(row["success"] for row in rows) / len(rows)
        print(f"network {net}: {rate:.0%} of {len(rows)} trials succeed")
