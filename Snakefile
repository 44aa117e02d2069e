# icub-affordance: one DAG from the simulated iCub to the book.
#   snakemake -c2                                   reproduce everything with config/config.yaml
#   snakemake -c2 --configfile .test/config/config.yaml   the small test configuration
from snakemake.utils import min_version, validate

min_version("9.0")


configfile: "config/config.yaml"


validate(config, "workflow/schemas/config.schema.yaml")


include: "workflow/rules/common.smk"
include: "workflow/rules/body.smk"
include: "workflow/rules/vision.smk"
include: "workflow/rules/demos.smk"
include: "workflow/rules/model.smk"
include: "workflow/rules/book.smk"


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
