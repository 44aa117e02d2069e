"""The hidden units over the steps: distances to grasping, and principal-axis trajectories."""

import json

import pandas as pd

from icub_affordance.analysis.hidden_states import (
    divergence,
    first_divergent_step,
    trajectory_table,
)
from icub_affordance.files import atomic_path, load_npz, redirect_log, write_text

with redirect_log(snakemake.log[0]):
    trials = pd.read_csv(snakemake.input.trials, keep_default_na=False)
    hidden = load_npz(snakemake.input.hidden)
    _, summary = divergence(hidden, trials)
    paths, explained = trajectory_table(hidden, trials)
    for table, path in (
        (summary, snakemake.output.divergence),
        (paths, snakemake.output.trajectories),
        (explained, snakemake.output.explained),
    ):
        with atomic_path(path) as tmp:
            table.to_csv(tmp, index=False, float_format="%.6f")
    first = first_divergent_step(summary)
    write_text(snakemake.output.summary, json.dumps({"first_divergent_step": first}) + "\n")
    print(summary.to_string())
    print("first step from which incongruent trials stay further from grasping:", first)
