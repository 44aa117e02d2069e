"""data/book/other_scale.json: how much the build at the other scale (robustness flipped) would
train and test (RunPlan.scale), for the book's reproduce page; planned here, not at every parse."""

import json

from icub_affordance.files import redirect_log, write_text
from icub_workflow.runs import plan_runs

with redirect_log(snakemake.log[0]):
    config = dict(snakemake.config)
    scale = plan_runs(config | {"robustness": not config["robustness"]}).scale()
    write_text(snakemake.output[0], json.dumps(scale, indent=1) + "\n")
    print(json.dumps(scale, indent=1))
