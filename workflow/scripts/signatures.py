"""The human signatures' conditions on the replications' networks: trials, tests and errors."""

from icub_affordance.files import redirect_log
from icub_workflow.book.words import signature_words
from icub_workflow.steps import signature_tables

with redirect_log(snakemake.log[0]):
    signature_tables(
        snakemake.params.replications,
        snakemake.params.signatures,
        snakemake.params.min_replications,
        {name: snakemake.output[name] for name in ("trials", "summary", "errors")},
        signature_words,
    )
