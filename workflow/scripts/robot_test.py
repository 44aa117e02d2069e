"""Networks drive the simulated arm through every test trial: a run's part (rule robot_test;
icub_workflow.parts), one network (`net03`) or every network of the run one after another
(`all`)."""

from icub_affordance.body.demonstrations import DemoConfig
from icub_affordance.body.robot import Robot
from icub_affordance.files import redirect_log
from icub_affordance.learning.materials import load_materials
from icub_affordance.learning.training import mapping_of
from icub_affordance.trials.on_robot import embodied_network
from icub_workflow.parts import load_weights, part_networks, write_robot_part


def as_list(paths):
    return [paths] if isinstance(paths, str) else list(paths)


with redirect_log(snakemake.log[0]):
    settings = snakemake.params.network
    trained = dict(load_weights(as_list(snakemake.input.weights)))
    first = settings.get("first_network", 0)  # a confirmation's fresh networks start here
    nets = part_networks(snakemake.wildcards.part) or list(
        range(first, first + settings["networks"])
    )
    if not set(nets) <= set(trained):
        raise ValueError(f"networks {nets}, but weights of {sorted(trained)}")
    materials = load_materials(
        snakemake.input.maps,
        snakemake.input.soms,
        snakemake.input.demos,
        snakemake.params.grip_distance,
    )
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    tested = []
    for net in nets:
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
        tested.append((rows, states))
        rate = sum(row["success"] for row in rows) / len(rows)
        print(f"network {net}: {rate:.0%} of {len(rows)} trials succeed")
    write_robot_part(nets, tested, snakemake.output.trials, snakemake.output.states)
