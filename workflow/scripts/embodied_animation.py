"""The robot test as films: the first network grasping each object, and one object's congruent
and incongruent categorisation side by side (a network of each mapping).

Each trial is run again in physics and filmed as it runs; its outcome must be the one the robot
test recorded (the network's trials.csv), or the film would show another trial than the tables.
"""

import csv

from icub_affordance.animation import trial_frames, write_gif
from icub_affordance.body import Robot
from icub_affordance.demos import DemoConfig
from icub_affordance.embodied import network_policy, outcome_columns
from icub_affordance.evaluate import TrialSet, describe_trial
from icub_affordance.io import load_npz, redirect_log
from icub_affordance.jordan import Weights
from icub_affordance.spec import TASKS
from icub_affordance.train import load_materials, mapping_of

CAMERA, WIDTH, HEIGHT = "closeup", 240, 180
EVERY = 20  # physics steps (2 ms) between frames: 40 ms of the trial a frame
SEQUENCE = 0  # the test sequence filmed (the sequences of one task and object move alike)


def as_list(paths):
    return [paths] if isinstance(paths, str) else list(paths)


def film(robot, m, setup, i, weights, net, mapping, recorded, config):
    """Trial ``i`` of one network re-run and filmed; its panel title. Raises if its outcome is
    not the recorded one."""
    _task, o, _s = setup.trials[i]
    grip = m.grips[setup.grips[i]]
    frames, out = trial_frames(
        robot,
        m.objects[o],
        network_policy(weights, setup.context[i]),
        setup.teacher[i, 0],
        len(setup.teacher[i]),
        grip,
        config,
        CAMERA,
        WIDTH,
        HEIGHT,
        EVERY,
    )
    trial = describe_trial(m, setup, i, net, mapping, "embodied")
    row = recorded[i]
    for key in ("task", "object", "target_grip", "sequence"):
        if str(row[key]) != str(trial[key]):
            raise ValueError(
                f"network {net}: recorded trial {i} is {row['task']} {row['object']} "
                f"sequence {row['sequence']}, not {trial['task']} {trial['object']} sequence "
                f"{trial['sequence']}: the trials file is not in the test's order, or stale"
            )
    outcome = outcome_columns(out, grip, setup.teacher[i, -1], None, config)
    seen = {"success": str(outcome["success"]), "grip_used": outcome["grip_used"]}
    was = {"success": row["success"], "grip_used": row["grip_used"]}
    if seen != was:
        raise RuntimeError(
            f"network {net}, {trial['task']} {trial['object']} sequence {trial['sequence']}: "
            f"the re-run trial gives {seen}, the robot test recorded {was}. The film would not "
            "show the recorded trial: rerun the robot test (rule embodied) with this code."
        )
    held = "held" if outcome["success"] else "not held"
    return (
        frames,
        (
            f"network {net} ({mapping}), {trial['task']}: {trial['object'].replace('_', ' ')}, "
            f"{grip} grip. Touch reads {outcome['grip_used']}: {held}"
        ),
        trial,
    )


def index_of(setup, task, obj):
    return setup.trials.index((TASKS.index(task), obj, SEQUENCE))


with redirect_log(snakemake.log[0]):
    settings = snakemake.params.network
    nets = [int(n) for n in snakemake.params.networks]
    weights_files = as_list(snakemake.input.weights)
    trials_files = as_list(snakemake.input.trials)
    if not len(nets) == len(weights_files) == len(trials_files) == 2:
        raise ValueError(
            f"two networks (one of each mapping) with their weights and trials, not {nets}, "
            f"{len(weights_files)} weights and {len(trials_files)} trials files"
        )
    mappings = [mapping_of(net, settings["networks"]) for net in nets]
    if sorted(mappings) != ["A", "B"]:
        raise ValueError(f"networks {nets} learned mappings {mappings}: one of each is needed")
    m = load_materials(snakemake.input.maps, snakemake.input.soms, snakemake.input.demos)
    config = DemoConfig(**snakemake.params.demos)
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    fps = float(snakemake.params.fps)
    obj = m.objects.index(snakemake.params.object)

    films = []
    for net, mapping, weights_path, trials_path in zip(
        nets, mappings, weights_files, trials_files, strict=True
    ):
        stored = load_npz(weights_path, required=("W1", "b1", "W2", "b2"))
        weights = Weights(**{k: stored[k] for k in ("W1", "b1", "W2", "b2")})
        setup = TrialSet.of(m, mapping, settings["categorisation_cue"], settings["target"])
        with open(trials_path, newline="") as f:
            recorded = list(csv.DictReader(f))
        if len(recorded) != len(setup.trials):
            raise ValueError(
                f"{trials_path} has {len(recorded)} trials, the test {len(setup.trials)}: "
                "stale; rerun the robot test (rule embodied)"
            )
        films.append((net, mapping, weights, setup, recorded))

    net, mapping, weights, setup, recorded = films[0]
    panels = {}
    for o in range(len(m.objects)):
        frames, title, _ = film(
            robot, m, setup, index_of(setup, "grasping", o), weights, net, mapping, recorded, config
        )
        panels[title] = frames
        print(f"filmed {title} ({len(frames)} frames)")
    write_gif(panels, snakemake.output.grasps, fps=fps)

    panels = {}
    for net, mapping, weights, setup, recorded in films:
        i = index_of(setup, "categorisation", obj)
        frames, title, trial = film(robot, m, setup, i, weights, net, mapping, recorded, config)
        kind = "congruent" if trial["congruent"] == "True" else "incongruent"
        panels[kind] = (f"{kind}, {title}", frames)
        print(f"filmed {kind}: {title} ({len(frames)} frames)")
    robot.close()
    if set(panels) != {"congruent", "incongruent"}:
        raise ValueError(f"the two networks' trials of {snakemake.params.object} are {set(panels)}")
    write_gif(
        dict(panels[kind] for kind in ("congruent", "incongruent")),
        snakemake.output.categorise,
        fps=fps,
    )
