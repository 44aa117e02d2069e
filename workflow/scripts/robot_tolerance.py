"""The body's tolerance: each object's natural grasp replayed as the demonstrations' mean plan
with its arm targets offset, success against the palm's error."""

import pandas as pd

from icub_affordance.analysis.robot_effects import tolerance_table
from icub_affordance.body.demonstrations import DemoConfig
from icub_affordance.body.robot import Robot
from icub_affordance.files import load_npz, redirect_log, write_csv
from icub_affordance.trials.on_robot import body_tolerance

with redirect_log(snakemake.log[0]):
    demos = load_npz(snakemake.input.demos, required=("angles", "commands_deg", "objects", "grips"))
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    tolerance = snakemake.params.tolerance
    rows = body_tolerance(
        robot, demos, list(tolerance["noise"]), int(tolerance["repeats"]), snakemake.params.seed,
        DemoConfig(**snakemake.params.demos),
    )  # fmt: skip
    write_csv(snakemake.output[0], rows)
    print(tolerance_table(pd.DataFrame(rows)).to_string())
