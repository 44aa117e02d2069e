"""data/results.sha256: the SHA-256 of each of the build's result files (sha256sum format)."""

from icub_affordance.files import redirect_log, write_text
from icub_workflow.manifest import digests, format_manifest

with redirect_log(snakemake.log[0]):
    text = format_manifest(digests(snakemake.params.results))
    write_text(snakemake.output[0], text)
    print(f"{len(snakemake.params.results)} result files")
