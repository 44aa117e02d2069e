"""The confirmation's pilot: each earlier replication's estimate of every test the config's
confirmation declares, from runs already built (the sweep's points at seeds 1-10: the same model
as the readings' replications of those seeds), for the design's power.

    snakemake -c2 <each point's eval/anova.json>      # the sweep's runs, at least their analyses
    python tools/confirmation_pilot.py [config/config.yaml] > config/confirmation_pilot.csv

A point's estimate of a test is the one its run's analysis made (data/runs/{point}/eval/
anova.json: the all-trial RMSE's per-network contrasts, the correct-trial RMSE's within-network
fit), the estimators the confirmation uses. Run once, before the confirmation's declaration;
the table is tracked, and every build recomputes the power from it (data/claims/power.csv).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pandas as pd
import yaml

from icub_affordance.analysis.paper_claims import declared_tests
from icub_workflow.runs import plan_runs

#: Where each measure's term lives in a run's anova.json.
SOURCES = {"rmse": ("contrasts", None), "rmse_correct": (None, "correct_rt")}


def estimate(anova: dict, mode: str, measure: str, effect: str) -> float:
    top, inner = SOURCES[measure]
    term = anova[top][mode][effect] if top else anova[mode][inner][effect]
    return float(term["estimate"]) if term["estimate"] is not None else float("nan")


def main() -> None:
    path = Path(sys.argv[1] if len(sys.argv) > 1 else "config/config.yaml")
    config = yaml.safe_load(path.read_text())
    plan = plan_runs(config)
    rows = []
    for point, settings in plan.sweep.items():
        anova_path = Path(plan.path(point, "eval/anova.json"))
        if not anova_path.exists():
            sys.exit(f"{anova_path} is missing: build the sweep's analyses first (docstring)")
        anova = json.loads(anova_path.read_text())
        for test in declared_tests(config["confirmation"]):
            if test["cue"] != settings["categorisation_cue"]:
                continue
            value = estimate(anova, test["mode"], test["measure"], test["effect"])
            rows.append(test | {"seed": settings["seed"], "estimate": value})
    table = pd.DataFrame(rows).sort_values(["cue", "mode", "measure", "effect", "seed"])
    print(table.to_csv(index=False, float_format="%.6g"), end="")


if __name__ == "__main__":
    main()
