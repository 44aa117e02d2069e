"""Replay every demonstration through the embodied controller: its servo targets and its sensed
postures (the controller's ceiling, and what a perfect network would send)."""

from icub_affordance.body.demonstrations import DemoConfig
from icub_affordance.body.robot import Robot
from icub_affordance.files import load_npz, redirect_log, write_csv
from icub_affordance.trials.on_robot import replay_demos

with redirect_log(snakemake.log[0]):
    demos = load_npz(snakemake.input.demos, required=("angles", "commands_deg", "objects", "grips"))
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    rows = replay_demos(robot, demos, DemoConfig(**snakemake.params.demos))
    write_csv(snakemake.output[0], rows)
    for plan in ("commands", "sensed_postures"):
        mine = [row["success"] for row in rows if row["plan"] == plan]
        print(f"replaying the demos' {plan}: {sum(mine)} of {len(mine)} grasp and lift")
