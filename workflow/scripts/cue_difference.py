"""The test of the difference between the cue timings (first step only minus every step), to
data/eval/cue_difference.json (``icub_affordance.analysis.trial_effects.cue_timing_difference``)."""

import json

import pandas as pd

from icub_affordance.analysis.trial_effects import cue_timing_difference
from icub_affordance.files import redirect_log, write_text

with redirect_log(snakemake.log[0]):
    runs = {
        snakemake.params.cue: snakemake.input.trials,
        snakemake.params.ablation_cue: snakemake.input.ablation_trials,
    }
    difference = cue_timing_difference({cue: pd.read_csv(path) for cue, path in runs.items()})
    write_text(snakemake.output[0], json.dumps(difference, indent=1) + "\n")
    print(json.dumps(difference, indent=1))
