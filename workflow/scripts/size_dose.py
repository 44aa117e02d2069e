"""The size study's tables: data/size_dose/replications.csv (one row per study run and measure),
manipulation.csv (the clusters' sizes), summary.csv and slope.csv (the dose-response), power.csv
(what size effect the design could detect at dose 0), and geometry.csv and motor.csv (do the
demonstrations account for each object's error, per dose and without size?)."""

import json
from pathlib import Path

import pandas as pd

from icub_affordance.io import load_npz, redirect_log, write_tables
from icub_affordance.size_dose import (
    FAMILY_DECLARED,
    declared_family,
    demo_geometry,
    family_size,
    geometry_of_trials,
    grip_distance_share,
    manipulation,
    motor_tests,
    power_table,
    replication_rows,
    slopes,
    summary,
)
from icub_affordance.train import equal_grip_distance

with redirect_log(snakemake.log[0]):
    table = [dict(row) for row in snakemake.params.table]
    measures = list(snakemake.params.measures)
    analyses = [json.loads(Path(path).read_text()) for path in snakemake.input.measures]
    replications = replication_rows(table, analyses, measures)
    checks = manipulation(table, [load_npz(path) for path in snakemake.input.soms])
    geometries, trials = [], []
    for row, trials_path, demos_path in zip(
        table, snakemake.input.trials, snakemake.input.demos, strict=True
    ):
        demos = load_npz(demos_path, required=("angles", "objects", "grips"))
        objects, grips = [str(o) for o in demos["objects"]], [str(g) for g in demos["grips"]]
        angles = demos["angles"]
        if row["dose"] == "equal_grips":  # the demonstrations as that run's networks learn them
            angles = equal_grip_distance(angles)
        geometry = demo_geometry(angles, objects)
        study = {"dose": row["dose"], "cue": row["cue"], "seed": row["seed"]}
        geometries.append(geometry.assign(**study, run=row["run"]))
        df = pd.read_csv(trials_path, keep_default_na=False)
        df = df[(df["task"] == "categorisation") & (df["mode"] == "closed_loop")]
        trials.append(
            df.merge(geometry_of_trials(geometry, grips), on=["object", "target_grip"]).assign(
                **study
            )
        )
    geometry_table = pd.concat(geometries, ignore_index=True)
    motor = motor_tests(pd.concat(trials, ignore_index=True))
    table_summary, table_slopes = declared_family(
        summary(replications, checks), slopes(replications, checks), snakemake.params.declared
    )
    declared = family_size(table_summary, FAMILY_DECLARED) + family_size(
        table_slopes, FAMILY_DECLARED
    )
    power = power_table(replications, declared)
    write_tables(
        [
            (snakemake.output.replications, replications),
            (snakemake.output.manipulation, checks),
            (snakemake.output.summary, table_summary),
            (snakemake.output.slope, table_slopes),
            (snakemake.output.grips, grip_distance_share(replications)),
            (snakemake.output.power, power),
            (snakemake.output.geometry, geometry_table),
            (snakemake.output.motor, motor),
        ]
    )
    print(table_summary.to_string())
    print(table_slopes.to_string())
    print(power.to_string())
    print(motor.to_string())
