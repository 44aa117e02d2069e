"""Figure 5 and the conflict time-course from the trials (plot only)."""

import pandas as pd

from icub_affordance.analysis.trial_effects import categorisation_trials
from icub_affordance.figures import conflict_timecourse, figure5
from icub_affordance.files import redirect_log
from icub_affordance.vocabulary import MODES

with redirect_log(snakemake.log[0]):
    trials = pd.read_csv(snakemake.input.trials, keep_default_na=False)
    cells, steps = {}, {}
    for mode in MODES:
        df = categorisation_trials(trials, mode)
        means = df.groupby(["congruency", "size", "network"])["rmse"].mean()
        cells[mode] = {
            (c, s): means.loc[c, s].to_numpy()
            for c in ("congruent", "incongruent")
            for s in ("large", "small")
        }
    df = categorisation_trials(trials, "closed_loop")
    step_cols = [c for c in df.columns if c.startswith("rmse_step")]
    for c in ("congruent", "incongruent"):
        steps[f"{c} (closed loop)"] = (
            df[df["congruency"] == c].groupby("network")[step_cols].mean().to_numpy()
        )
    figure5(cells, snakemake.output.figure5)
    conflict_timecourse(steps, snakemake.output.timecourse)
