"""The size study's tables: data/size_dose/replications.csv (one row per study run and measure),
manipulation.csv (the clusters' sizes), summary.csv (the size effect per dose, grip arrangement
and cue timing: exploration), crossed.csv and separated.csv (size crossed with the grips'
distance: per run, per replication), declared.csv and power.csv (the declared tests and their
power), and geometry.csv and motor.csv (do the demonstrations account for each object's error?)."""

import json
from pathlib import Path

import pandas as pd

from icub_affordance.analysis.size_study import (
    SWAPPED,
    crossed_runs,
    declared_tests,
    demo_geometry,
    geometry_of_trials,
    motor_tests,
    power_table,
    replication_rows,
    separated,
    summary,
)
from icub_affordance.files import load_npz, redirect_log, write_tables
from icub_affordance.learning.grip_distance import swapped_grips
from icub_affordance.learning.size_manipulation import manipulation

with redirect_log(snakemake.log[0]):
    table = [dict(row) for row in snakemake.params.table]
    crossed = snakemake.params.crossed
    measures = list(snakemake.params.measures)
    least = int(snakemake.params.least)
    analyses = [json.loads(Path(path).read_text()) for path in snakemake.params.analyses]
    replications = replication_rows(table, analyses, measures)
    checks = manipulation(table, [load_npz(path) for path in snakemake.params.soms])
    geometries, trials = [], []
    for row, trials_path, demos_path in zip(
        table, snakemake.params.trials, snakemake.params.demos, strict=True
    ):
        demos = load_npz(demos_path, required=("angles", "objects", "grips"))
        objects, grips = [str(o) for o in demos["objects"]], [str(g) for g in demos["grips"]]
        angles = demos["angles"]
        if row["arrangement"] == SWAPPED:  # the demonstrations as that run's networks learn them
            angles = swapped_grips(angles, objects)
        geometry = demo_geometry(angles, objects)
        study = {k: row[k] for k in ("dose", "arrangement", "cue", "seed")}
        geometries.append(geometry.assign(**study, run=row["run"]))
        df = pd.read_csv(trials_path, keep_default_na=False)
        df = df[(df["task"] == "categorisation") & (df["mode"] == "closed_loop")]
        trials.append(
            df.merge(geometry_of_trials(geometry, grips), on=["object", "target_grip"]).assign(
                **study
            )
        )
    geometry_table = pd.concat(geometries, ignore_index=True)
    motor = motor_tests(pd.concat(trials, ignore_index=True), least)
    runs = crossed_runs(replications, checks, geometry_table, crossed["measure"])
    parts = separated(runs)
    declared = declared_tests(parts, crossed["tests"], snakemake.params.doses, least)
    power = power_table(declared, crossed["effect_of_interest"], crossed["alpha"])
    table_summary = summary(replications, checks, least)
    write_tables(
        [
            (snakemake.output.replications, replications),
            (snakemake.output.manipulation, checks),
            (snakemake.output.summary, table_summary),
            (snakemake.output.crossed, runs),
            (snakemake.output.separated, parts),
            (snakemake.output.declared, declared),
            (snakemake.output.power, power),
            (snakemake.output.geometry, geometry_table),
            (snakemake.output.motor, motor),
        ]
    )
    print(declared.to_string())
    print(power.to_string())
    print(table_summary.to_string())
    print(motor.to_string())
