"""The sweep's per-point effects and the summary over replications."""

import pandas as pd

from icub_affordance.analysis.sweep import sweep_tables
from icub_affordance.files import atomic_path, redirect_log

with redirect_log(snakemake.log[0]):
    names = list(snakemake.params.points)
    trials = {
        n: pd.read_csv(p, keep_default_na=False)
        for n, p in zip(names, snakemake.input.trials, strict=True)
    }
    per_point, summary = sweep_tables(dict(snakemake.params.points), trials)
    for table, path in ((per_point, snakemake.output.points), (summary, snakemake.output.summary)):
        with atomic_path(path) as tmp:
            table.to_csv(tmp, index=False, float_format="%.6g")
    print(summary.to_string())
