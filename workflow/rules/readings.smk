# Which reading of the paper reproduces it (the book's reproduction notes): every reading (config
# `readings`: cue timing x Goal response) is a run of the model (common.smk: PLAN.readings), one
# replication at each of the confirmation's seeds (config `confirmation`). Each run's
# trials are scored on the declared measures (rule `measures`, for every run), and the rule
# `readings` sets each effect against the paper over the replications, and tests the differences
# between the cue timings and between the Goal responses.


rule measures:
    """Every test trial scored on each declared measure, and each measure's (and null control's)
    per-network contrasts, cell means and per-object means."""
    input:
        unpack(model_inputs),
        weights=run_weights,
        code=script_code("measures"),
    output:
        trials="data/{folder}eval/measures.csv",
        json="data/{folder}eval/measures.json",
    params:
        network=run_section("network"),
        grip_distance=run_section("grip_distance"),
        measures=config["readings"]["measures"],
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/{folder}measures.log",
    benchmark:
        "data/benchmarks/{folder}measures.tsv"
    script:
        "../scripts/measures.py"


# The measured runs of a seed (RunPlan.measured_groups) trained and measured in one job: the
# steps of rules soms (for a run that makes its own maps), train and measures, the same
# files. A group's set of runs varies, so its job makes one folder (RunPlan.group_folder), each
# run's files in it where RunPlan.path puts them; a rule that reads one names the folder
# (measured_inputs). Its runs, as the job's script reads them: common.smk, measured_table.


rule measured:
    """A seed's measured runs (readings, size study): each run's networks trained, then every
    test trial scored on the declared measures, in the group's folder."""
    input:
        models=measured_models,
        code=script_code("measured_runs"),
    output:
        directory("data/measured/{group}"),
    params:
        runs=measured_table,
        objects=settings(config["objects"]),
        measures=config["readings"]["measures"],
    wildcard_constraints:
        group="|".join(MEASURED_GROUPS) or "(?!)",
    priority: 1  # before the figures: the size study's and the readings' tables wait on it
    resources:
        mem_mb=1000,
        runtime=30,
    log:
        "data/logs/measured/{group}.log",
    benchmark:
        "data/benchmarks/measured/{group}.tsv"
    script:
        "../scripts/measured_runs.py"


rule readings:
    """Every reading's effects over its replications: data/readings/summary.csv (contract), with
    each effect's t-test and Holm's p; and the tests of the differences between the cue timings
    and between the Goal responses, paired by network (data/readings/differences.csv)."""
    input:
        measured=measured_inputs(
            PLAN.path(row["run"], f"eval/measures.{kind}")
            for kind in ("json", "csv")
            for row in PLAN.readings
        ),
        code=script_code("readings"),
    output:
        summary="data/readings/summary.csv",
        replications="data/readings/replications.csv",
        differences="data/readings/differences.csv",
    params:
        table=PLAN.readings,
        # the files in the folders named above (measured_inputs)
        analyses=[PLAN.path(row["run"], "eval/measures.json") for row in PLAN.readings],
        trials=[PLAN.path(row["run"], "eval/measures.csv") for row in PLAN.readings],
        measures=config["readings"]["measures"],
        margins=settings(config["readings"]["equivalence_margin"]),
        # the one minimum of every test over replications (analysis/replicated.py)
        least=config["confirmation"]["min_replications"],
    log:
        "data/logs/readings/summary.log",
    benchmark:
        "data/benchmarks/readings/summary.tsv"
    script:
        "../scripts/readings.py"


rule readings_figure:
    """The readings' effects on every measure (plot only)."""
    input:
        summary=rules.readings.output.summary,
        replications=rules.readings.output.replications,
        code=script_code("readings_figure"),
    output:
        "data/readings/effects.png",
    log:
        "data/logs/readings/figure.log",
    benchmark:
        "data/benchmarks/readings/figure.tsv"
    script:
        "../scripts/readings_figure.py"
