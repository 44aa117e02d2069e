"""The robot test as films: the first network grasping each object, and one object's congruent
and incongruent categorisation side by side (a network of each mapping).

Each trial is run again in physics and filmed as it runs; its outcome must be the one the robot
test recorded (the run's trials.csv), or the film would show another trial than the tables
(``animation.film_trial``).
"""

from icub_affordance.animation import (
    categorise_panels,
    filmed_networks,
    grasp_panels,
    write_gif,
)
from icub_affordance.body.demonstrations import DemoConfig
from icub_affordance.body.robot import Robot
from icub_affordance.files import redirect_log
from icub_affordance.learning.materials import load_materials
from icub_workflow.parts import load_robot_trials, load_weights, network_trials


def as_list(paths):
    return [paths] if isinstance(paths, str) else list(paths)


with redirect_log(snakemake.log[0]):
    m = load_materials(
        snakemake.input.maps,
        snakemake.input.soms,
        snakemake.input.demos,
        snakemake.params.grip_distance,
    )
    nets = [int(n) for n in snakemake.params.networks]
    trained = dict(load_weights(as_list(snakemake.input.weights)))
    # the recorded trials as written (every value text), each network's in the test's order
    recorded = load_robot_trials(as_list(snakemake.input.trials), dtype=str, keep_default_na=False)
    films = filmed_networks(
        m,
        snakemake.params.network,
        nets,
        [trained[net] for net in nets],
        [network_trials(recorded, net).to_dict("records") for net in nets],
    )
    config = DemoConfig(**snakemake.params.demos)
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    fps = float(snakemake.params.fps)

    panels = grasp_panels(robot, m, films[0], config)
    for title, frames in panels.items():
        print(f"filmed {title} ({len(frames)} frames)")
    write_gif(panels, snakemake.output.grasps, fps=fps)

    panels = categorise_panels(robot, m, films, snakemake.params.object, config)
    robot.close()
    for title, frames in panels.items():
        print(f"filmed {title} ({len(frames)} frames)")
    write_gif(panels, snakemake.output.categorise, fps=fps)
