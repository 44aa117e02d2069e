# icub-affordance: one DAG from the simulated iCub to the book.
#   snakemake -c2                                   reproduce everything with config/config.yaml
#   snakemake -c2 --configfile .test/config/config.yaml   the small test configuration
import os

from snakemake.utils import min_version, validate

min_version("9.0")

# One thread per job for the numerical libraries: results must not depend on how many cores a
# library happens to use (floating-point sums in another order), and jobs run side by side.
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_var] = "1"


configfile: "config/config.yaml"


# `--config robustness=true` reaches Snakemake as the text "true" (only True and False are read
# as booleans there): say so plainly instead of the schema's bare type error.
if isinstance(config.get("robustness"), str):
    raise ValueError(
        f"config robustness: {config['robustness']!r} is text, not a boolean. On the command line "
        "write it capitalised, as Snakemake reads booleans: --config robustness=True (or False)."
    )
validate(config, "workflow/schemas/config.schema.yaml")



include: "workflow/rules/common.smk"
include: "workflow/rules/body.smk"
include: "workflow/rules/vision.smk"
include: "workflow/rules/demos.smk"
include: "workflow/rules/model.smk"
include: "workflow/rules/runs.smk"
include: "workflow/rules/readings.smk"
include: "workflow/rules/embodied.smk"
include: "workflow/rules/book.smk"
include: "workflow/rules/sweep.smk"


rule all:
    """Everything: the book and every output it shows."""
    default_target: True
    input:
        rules.book.output,
        rules.body_figure.output,
        rules.visual_maps.output,
        rules.figure3.output,
        rules.demos.output,
        rules.demo_filmstrip.output,
        rules.figure2_maps.output,
        rules.stats.output,
        rules.figure4.output,
        rules.figure5.output,
        rules.figure_hidden.output,
        run_outputs(CONFIGURED_RUNS),
        rules.readings.output,
        rules.readings_figure.output,
        rules.embodied_summary.output,
        rules.embodied_filmstrip.output,
