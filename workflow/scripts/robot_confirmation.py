"""Explore, then confirm: each confirmed variant's share of grasping trials held on its fresh
networks (the confirmation run's robot trials, joined here) and, where this build tests it there
(its exploration run named, not None: full scale, or an entry of robot.default), on the networks
it was chosen on (its rows of data/embodied/trials.csv), with the interval of
icub_affordance.confirmation, its design effect before the floor at 1, and the trials and held
per mapping and object.
"""

import pandas as pd

from icub_affordance.confirmation import confirmation_table
from icub_affordance.io import atomic_path, redirect_log

with redirect_log(snakemake.log[0]):
    variants = snakemake.params.confirmation
    files = list(snakemake.input.confirmation)
    per_run = len(files) // max(1, len(variants))
    if len(files) != per_run * len(variants):
        raise ValueError(f"{len(files)} trial files for {len(variants)} confirmation runs")
    tables, first = [], ["run", *snakemake.params.variant_keys]
    for k, variant in enumerate(variants):
        labels = {"run": variant["confirmation"]} | {c: variant[c] for c in first[1:]}
        for path in files[k * per_run : (k + 1) * per_run]:
            tables.append(pd.read_csv(path).assign(**labels))
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
