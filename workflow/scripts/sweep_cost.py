"""The sweep's cost: wall time of `snakemake sweep` for each number of replications in config
`sweep_cost`, each in a scratch copy of the workflow, at this job's cores."""

import sys
from pathlib import Path

# The measuring is benchmarks/sweep_cost.py, not in the package: put benchmarks/ first on the
# path (Snakemake appends only this script's own folder, whose sweep_cost.py is this script).
sys.path.insert(0, str(Path(snakemake.scriptdir).resolve().parents[1] / "benchmarks"))

from sweep_cost import measure, write_cost_table  # noqa: E402

from icub_affordance.io import redirect_log  # noqa: E402

with redirect_log(snakemake.log[0]):
    table = measure(
        Path.cwd(),
        dict(snakemake.config),
        snakemake.params.replications,
        snakemake.threads,
        inputs=list(snakemake.input.data),
    )
    write_cost_table(table, snakemake.output[0])
    print(table.to_string(index=False))
