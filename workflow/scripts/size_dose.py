"""The size study's tables: data/size_dose/replications.csv (one row per study run and measure),
manipulation.csv (the clusters' sizes), summary.csv and slope.csv (the dose-response), and, on
the removal control, geometry.csv and motor.csv (do the demonstrations account for the error?)."""

import json
from pathlib import Path

import pandas as pd

from icub_affordance.io import atomic_path, load_npz, redirect_log
from icub_affordance.size_dose import (
    demo_geometry,
    geometry_of_trials,
    manipulation,
    motor_tests,
    replication_rows,
    slopes,
    summary,
)

with redirect_log(snakemake.log[0]):
    table = [dict(row) for row in snakemake.params.table]
    measures = list(snakemake.params.measures)
    analyses = [json.loads(Path(path).read_text()) for path in snakemake.input.measures]
    replications = replication_rows(table, analyses, measures)
    checks = manipulation(table, [load_npz(path) for path in snakemake.input.soms])
    removed = [row for row in table if row["dose"] == "removed"]
    geometries, trials = [], []
    for row, trials_path, demos_path in zip(
        removed, snakemake.input.removal_trials, snakemake.input.removal_demos, strict=True
    ):
        demos = load_npz(demos_path, required=("angles", "objects", "grips"))
        objects, grips = [str(o) for o in demos["objects"]], [str(g) for g in demos["grips"]]
        geometry = demo_geometry(demos["angles"], objects)
        geometries.append(geometry.assign(cue=row["cue"], seed=row["seed"], run=row["run"]))
        df = pd.read_csv(trials_path, keep_default_na=False)
        df = df[(df["task"] == "categorisation") & (df["mode"] == "closed_loop")]
        keyed = geometry_of_trials(geometry, grips)
        trials.append(
            df.merge(keyed, on=["object", "target_grip"]).assign(cue=row["cue"], seed=row["seed"])
        )
    geometry_table = pd.concat(geometries, ignore_index=True) if geometries else pd.DataFrame()
    motor = motor_tests(pd.concat(trials, ignore_index=True)) if trials else pd.DataFrame()
    for path, frame in (
        (snakemake.output.replications, replications),
        (snakemake.output.manipulation, checks),
        (snakemake.output.summary, summary(replications, checks)),
        (snakemake.output.slope, slopes(replications)),
        (snakemake.output.geometry, geometry_table),
        (snakemake.output.motor, motor),
    ):
        with atomic_path(path) as tmp:
            frame.to_csv(tmp, index=False)
    print(summary(replications, checks).to_string())
    print(slopes(replications).to_string())
    print(motor.to_string())
