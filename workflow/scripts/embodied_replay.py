"""Replay every demonstration through the embodied controller: its servo targets and its sensed
postures (the controller's ceiling, and what a perfect network would send)."""

import pandas as pd

from icub_affordance.body import Robot
from icub_affordance.demos import DemoConfig
from icub_affordance.embodied import replay_demos
from icub_affordance.io import atomic_path, load_npz, redirect_log

with redirect_log(snakemake.log[0]):
    demos = load_npz(snakemake.input.demos, required=("angles", "commands_deg", "objects", "grips"))
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    table = pd.DataFrame(replay_demos(robot, demos, DemoConfig(**snakemake.params.demos)))
    with atomic_path(snakemake.output[0]) as tmp:
        table.to_csv(tmp, index=False, float_format="%.6f")
    print(table.groupby("plan")["success"].mean())
