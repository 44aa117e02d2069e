"""The size study taken apart on a second metric of the grips' distance, added after results:
the RMS distance between the two grips' trajectories (the RMSE's own scale) in place of the
distance between their final postures. data/size_dose/trajectory_separated.csv (per replication,
as separated.csv) and trajectory_tests.csv (size's and the grips' distance's parts per dose and
cue timing, and on both metrics which part is the larger, Holm within their own family)."""

import pandas as pd

from icub_affordance.analysis.size_study import (
    FINAL_POSTURE,
    SWAPPED,
    TRAJECTORY,
    crossed_runs,
    metric_tests,
    separated,
    trajectory_geometry,
)
from icub_affordance.files import load_npz, redirect_log, write_tables
from icub_affordance.learning.grip_distance import swapped_grips

with redirect_log(snakemake.log[0]):
    replications = pd.read_csv(snakemake.input.replications)
    checks = pd.read_csv(snakemake.input.manipulation)
    crossed = snakemake.params.crossed
    geometries = []
    for row, demos_path in zip(snakemake.params.table, snakemake.params.demos, strict=True):
        demos = load_npz(demos_path, required=("angles", "objects"))
        objects, angles = [str(o) for o in demos["objects"]], demos["angles"]
        if row["arrangement"] == SWAPPED:  # the demonstrations as that run's networks learn them
            angles = swapped_grips(angles, objects)
        geometries.append(trajectory_geometry(angles, objects).assign(run=row["run"]))
    runs = crossed_runs(replications, checks, pd.concat(geometries), crossed["measure"])
    parts = separated(runs)
    declared_parts = pd.read_csv(snakemake.input.separated)  # the declared metric's lines
    tests = metric_tests(
        {TRAJECTORY: parts, FINAL_POSTURE: declared_parts},
        snakemake.params.doses,
        int(snakemake.params.least),
    )
    write_tables([(snakemake.output.separated, parts), (snakemake.output.tests, tests)])
    print(tests.to_string())
