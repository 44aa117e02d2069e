# The results manifest (src/icub_workflow/manifest.py): the SHA-256 of every result file of this
# configuration's build, in `sha256sum` format. Included after DEFAULT_OUTPUTS (Snakefile).
from icub_workflow.manifest import result_files

# this configuration's result files: the tables, arrays and summaries of the default target,
# but those of a run of config `runs` that plays no other part (the user's own experiments, which
# the book does not show: adding one reruns nothing of the main run's, the manifest and the book
# included). A user's run that is also, say, a reading (the same settings) keeps its files here.
_USER_ONLY = set(PLAN.built()) - set(PLAN.built(users=False))
_USER_RUN_FILES = {f for run in _USER_ONLY for f in run_outputs(run)}
RESULT_FILES = result_files(f for f in DEFAULT_OUTPUTS if f not in _USER_RUN_FILES)


rule manifest:
    """The build's results manifest: one `<sha256>  <path>` line per result file."""
    input:
        results=measured_inputs(RESULT_FILES),
        code=script_code("manifest"),
    output:
        "data/results.sha256",
    params:
        results=RESULT_FILES,  # the files, those in the folders named above too
    log:
        "data/logs/manifest.log",
    benchmark:
        "data/benchmarks/manifest.tsv"
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
