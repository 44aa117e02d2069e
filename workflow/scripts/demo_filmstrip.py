"""Filmstrips of chosen demonstrations, rendered from the recorded states."""

from icub_affordance.body.robot import Robot
from icub_affordance.figures import filmstrip
from icub_affordance.files import load_npz, redirect_log

with redirect_log(snakemake.log[0]):
    demos = load_npz(snakemake.input.demos, required=("qpos", "objects", "grips"))
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    objects, grips = demos["objects"].tolist(), demos["grips"].tolist()
    strips = {}
    for obj, grip, seq in snakemake.params.picks:
        states = demos["qpos"][objects.index(obj), grips.index(grip), int(seq)]
        strips[f"{obj.replace('_', ' ')}, {grip} grip (sequence {seq})"] = [
            robot.render_state(state, "closeup", 320, 240) for state in states
        ]
    robot.close()
    filmstrip(strips, snakemake.output[0])
