"""Explore, then confirm: each confirmed variant's share of grasping trials held on its fresh
networks (the confirmation run's robot trials, joined here) and, where this build tests it there
(its exploration run named, not None: full scale, or an entry of robot.default), on the networks it
was chosen on (its rows of data/embodied/trials.csv), with the interval of
icub_affordance.analysis.confirmation, its design effect before the floor at 1, and the trials and
held per mapping and object.
"""

import pandas as pd

from icub_affordance.analysis.confirmation import confirmation_table
from icub_affordance.files import atomic_path, redirect_log
from icub_workflow.parts import load_robot_trials

with redirect_log(snakemake.log[0]):
    variants, by_run = snakemake.params.confirmation, snakemake.params.files
    if [f for files in by_run for f in files] != list(snakemake.input.confirmation):
        raise ValueError(f"{len(snakemake.input.confirmation)} trial files, not the runs' parts")
    tables, first = [], ["run", *snakemake.params.variant_keys]
    for variant, files in zip(variants, by_run, strict=True):
        labels = {"run": variant["confirmation"]} | {c: variant[c] for c in first[1:]}
        tables.append(load_robot_trials(files).assign(**labels))  # in network order
    fresh = pd.concat(tables, ignore_index=True) if tables else pd.DataFrame(columns=first)
    fresh = fresh[[*first, *(c for c in fresh.columns if c not in first)]]
    with atomic_path(snakemake.output.trials) as tmp:
        fresh.to_csv(tmp, index=False, float_format="%.6f")
    fresh = pd.read_csv(snakemake.output.trials)  # as readers see it
    explored = pd.read_csv(snakemake.input.trials)
    table = confirmation_table(pd.concat([explored, fresh], ignore_index=True), variants)
    with atomic_path(snakemake.output.table) as tmp:
        table.to_csv(tmp, index=False, float_format="%.6f")
    print(table.to_string())
