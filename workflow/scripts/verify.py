"""Compare the result files in data/ with the tracked manifest; exit 1 naming each that differs."""

import sys

from icub_affordance.files import write_text
from icub_workflow.manifest import compare, read_manifest

manifest = snakemake.input[0]
try:
    comparison = compare(read_manifest(manifest), snakemake.params.results)
except (OSError, ValueError) as err:
    sys.exit(f"verify: {err}")
report = comparison.report(manifest)
write_text(snakemake.log[0], report + "\n")
print(report, file=sys.stdout if comparison.same else sys.stderr)
sys.exit(0 if comparison.same else 1)
