# icub-affordance: one DAG from the simulated iCub to the book.
#   snakemake -c2                                   reproduce everything with config/config.yaml
#   snakemake -c2 --configfile .test/config/config.yaml   the small test configuration
import os
from pathlib import Path

from snakemake.utils import min_version, update_config

min_version("9.0")

# The same bytes on any x86-64 machine with AVX2 (src/icub_workflow/manifest.py): one thread per
# job for the numerical libraries (a sum split over cores is a sum in another order), and the
# same SIMD code paths of numpy and OpenBLAS whatever the CPU offers beyond AVX2. Every job's
# process inherits these; they act when it imports numpy.
from icub_workflow.manifest import arithmetic_environment, cpu_flags

os.environ.update(arithmetic_environment(cpu_flags()))


configfile: "config/config.yaml"


# The config is checked here, before any job (src/icub_workflow/config_checks.py): the schema (each key
# alone, workflow/schemas/config.schema.yaml), the rules between keys, and the scene itself.
# Nested `--config` values reach here as text (Snakemake reads them with YAML's BaseLoader): they
# are read again as a config file's would be.
from icub_workflow.config_checks import (
    check_command_line,
    check_config,
    check_scene,
    check_schema,
    load_schema,
    typed_overrides,
)

CONFIG_SCHEMA = load_schema(Path(workflow.basedir) / "workflow" / "schemas" / "config.schema.yaml")
update_config(config, typed_overrides(workflow.config_settings.config))
check_command_line(config)
check_schema(config, CONFIG_SCHEMA)
check_config(config)
check_scene(config)



include: "workflow/rules/common.smk"


# A run's folder (RunPlan.folder: the config's own at the top of data/, any other in runs/{run}/;
# names may hold dots, lr0.075), by its shape: a pattern listing every run's folder would be
# compiled into every output's pattern, a second of every start (a job asked for a folder that
# no run has is refused by its input functions, RunPlan.run_in); and a network's index.
wildcard_constraints:
    folder=FOLDER_PATTERN,
    net=r"\d\d",


include: "workflow/rules/body.smk"
include: "workflow/rules/vision.smk"
include: "workflow/rules/demos.smk"
include: "workflow/rules/model.smk"
include: "workflow/rules/runs.smk"
include: "workflow/rules/readings.smk"
include: "workflow/rules/claims.smk"
include: "workflow/rules/size_dose.smk"
include: "workflow/rules/robot.smk"
include: "workflow/rules/statistics.smk"
include: "workflow/rules/signatures.smk"
include: "workflow/rules/words.smk"
include: "workflow/rules/distractor.smk"
include: "workflow/rules/book.smk"
include: "workflow/rules/sweep.smk"
include: "workflow/rules/benchmark.smk"


# Every file the default target makes, the intermediate ones too (DEFAULT_TARGET below names
# those that are missing). Derived, never listed: every file of each run the build makes
# (RunPlan.built, common.smk: run_outputs) and every output of a rule without wildcards, but the
# sweep's summary, which only `robustness=True` (or the target `sweep`) asks for.
ON_REQUEST = () if config["robustness"] else ("sweep_summary", "sweep_figure")
# the distractor's tests, declared before any result: made only when config distractor.run is
ON_REQUEST += () if config["distractor"]["run"] else ("distractor",)
DEFAULT_OUTPUTS = list(
    dict.fromkeys(
        [
            *(f for run in PLAN.built() for f in run_outputs(run)),
            *(
                f
                for rule in workflow.rules
                if not rule.has_wildcards() and rule.name not in ON_REQUEST
                for f in rule.output
            ),
            "data/results.sha256",
        ]
    )
)


include: "workflow/rules/manifest.smk"


# What the default target names. The results manifest reads every result file and the book every
# job's record, so the two reach every job of the build; the target names them, the build's files
# that neither reads, and any file of the build that is missing: Snakemake remakes a missing file
# only if a job still to run needs it, so a file deleted after a run (as the project's errors
# advise for a corrupt one) must be named to be remade. Naming every file every time would make
# every start match each of them to its rule (issue 56).
_READ = {*RESULT_FILES, *BOOK_DATA.values(), *BOOK_FINDINGS.values(), *rules.book.output}
DEFAULT_TARGET = list(
    dict.fromkeys(
        [
            *rules.book.output,
            *rules.manifest.output,
            # a file in a measured group's folder: that folder (common.smk: measured_inputs)
            *measured_inputs(
                f for f in DEFAULT_OUTPUTS if f not in _READ or not os.path.exists(f)
            ),
        ]
    )
)


rule all:
    """Everything: the book and every file it is made from."""
    default_target: True
    input:
        DEFAULT_TARGET,


# The paper's own model alone: its figures, its ANOVA and the config's own run's files, without
# the work beyond the paper (the readings, the robot, the size study, the book). A fast loop:
# a change to a paper hyperparameter reruns only the config's own run.
PAPER_OUTPUTS = [
    *run_files(MAIN),
    *outputs("measures", MAIN),
    *rules.body_figure.output,
    *rules.visual_maps.output,
    *rules.figure3.output,
    *rules.demo_filmstrip.output,
    *rules.figure2_maps.output,
    *rules.figure2_architecture.output,
    *rules.figure4.output,
]


rule paper:
    """Target: the paper's own model, its figures and its ANOVA (snakemake -c2 paper)."""
    input:
        PAPER_OUTPUTS,


# what the rules' code imports, parsed this time, kept for the next start (common.smk: _CODE)
_CODE.save()
