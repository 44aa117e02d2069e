# The results manifest (src/icub_workflow/manifest.py): the SHA-256 of every result file of this
# configuration's build, in `sha256sum` format. Included after DEFAULT_OUTPUTS (Snakefile).
from icub_workflow.manifest import result_files

# this configuration's result files: tables, arrays and summaries of the default target
RESULT_FILES = result_files(DEFAULT_OUTPUTS)


rule manifest:
    """The build's results manifest: one `<sha256>  <path>` line per result file."""
    localrule: True
    input:
        results=RESULT_FILES,
        code=script_code("manifest"),
    output:
        "data/results.sha256",
    log:
        "data/logs/manifest.log",
    script:
        "../scripts/manifest.py"


rule verify:
    """Compare data/ with the tracked manifest of the default configuration (results.sha256):
    name every result file that differs, exit non-zero if any does. Builds nothing."""
    localrule: True
    input:
        "results.sha256",
    params:
        results=RESULT_FILES,
    log:
        # the report, also printed
        "data/logs/verify.log",
    script:
        "../scripts/verify.py"
