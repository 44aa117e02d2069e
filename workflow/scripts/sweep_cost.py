"""The sweep's cost: wall time of `snakemake sweep` for each number of replications in config
`sweep_cost`, each in a scratch copy of the workflow, at this job's cores."""

from pathlib import Path

from icub_affordance.io import redirect_log
from icub_workflow.sweep_timing import measure, write_cost_table

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
