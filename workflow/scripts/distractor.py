"""A distractor at test on the confirmation's networks: trials, estimates and tests."""

from icub_affordance.files import redirect_log
from icub_workflow.distractor import distractor_tables

with redirect_log(snakemake.log[0]):
    distractor_tables(
        snakemake.params.replications,
        snakemake.params.declaration,
        snakemake.params.min_replications,
        {name: snakemake.output[name] for name in ("trials", "estimates", "summary")},
    )
