"""Join every tested variant's robot trials (every test sequence a row, as the robot test wrote
them); the config's own networks' success by condition and congruency effect; each variant's
success and contact time, and their effects (effects.json: congruency, size and their
interaction, with the counts per cell and per object and one Holm family over every variant's
tests): the summaries count each network x object x task once
(``robot_effects.distinct_trials``)."""

import json

import pandas as pd

from icub_affordance.analysis.robot_effects import (
    VARIANT_COLUMNS,
    success_analysis,
    success_table,
    variant_effects,
    variant_table,
)
from icub_affordance.files import atomic_path, redirect_log, write_text
from icub_workflow.parts import load_robot_trials

with redirect_log(snakemake.log[0]):
    variants, by_variant = snakemake.params.variants, snakemake.params.files
    if [f for files in by_variant for f in files] != list(snakemake.input.trials):
        raise ValueError(f"{len(snakemake.input.trials)} trial files, not the variants' parts")
    tables = []
    for variant, files in zip(variants, by_variant, strict=True):
        table = load_robot_trials(files)  # every network's rows, in network order
        for column in reversed(VARIANT_COLUMNS):
            table.insert(0, column, variant[column])
        tables.append(table)
    trials = pd.concat(tables, ignore_index=True)
    with atomic_path(snakemake.output.trials) as tmp:
        trials.to_csv(tmp, index=False, float_format="%.6f")
    trials = pd.read_csv(snakemake.output.trials)  # as readers see it
    own = trials[trials["run"] == snakemake.params.own].drop(columns=list(VARIANT_COLUMNS))
    replay = pd.read_csv(snakemake.input.replay)
    with atomic_path(snakemake.output.success) as tmp:
        success_table(own).to_csv(tmp, index=False, float_format="%.4f")
    analysis = success_analysis(own, replay)
    write_text(snakemake.output.analysis, json.dumps(analysis, indent=2) + "\n")
    table = variant_table(trials)
    with atomic_path(snakemake.output.variants) as tmp:
        table.to_csv(tmp, index=False, float_format="%.4f")
    effects = variant_effects(trials)
    write_text(snakemake.output.effects, json.dumps(effects, indent=2) + "\n")
    print(table.to_string())
