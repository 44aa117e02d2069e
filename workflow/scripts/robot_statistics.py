"""The robot chapter's statistics beyond the variants' table and effects, to
data/embodied/statistics.json (``icub_affordance.analysis.robot_effects``)."""

import json

import pandas as pd

from icub_affordance.analysis.robot_effects import robot_statistics
from icub_affordance.files import redirect_log, write_text

with redirect_log(snakemake.log[0]):
    statistics = robot_statistics(
        pd.read_csv(snakemake.input.trials),
        pd.read_csv(snakemake.input.tolerance),
        pd.read_csv(snakemake.input.replay),
    )
    write_text(snakemake.output[0], json.dumps(statistics, indent=1) + "\n")
    print(json.dumps(statistics, indent=1))
