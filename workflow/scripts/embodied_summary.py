"""Join the networks' embodied trials; success by task, congruency and size; its statistics."""

import json

import pandas as pd

from icub_affordance.embodied import success_analysis, success_table
from icub_affordance.io import atomic_path, redirect_log, write_text

with redirect_log(snakemake.log[0]):
    trials = pd.concat([pd.read_csv(p) for p in snakemake.input.trials], ignore_index=True)
    replay = pd.read_csv(snakemake.input.replay)
    with atomic_path(snakemake.output.trials) as tmp:
        trials.to_csv(tmp, index=False, float_format="%.6f")
    with atomic_path(snakemake.output.success) as tmp:
        success_table(trials).to_csv(tmp, index=False, float_format="%.4f")
    analysis = success_analysis(trials, replay)
    write_text(snakemake.output.analysis, json.dumps(analysis, indent=2) + "\n")
    print(json.dumps(analysis, indent=2))
