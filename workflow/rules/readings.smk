# Which reading of the paper reproduces it (the book's reproduction notes): every reading (config
# `readings`: cue timing x Goal response) is a run of the model (common.smk: PLAN.readings), one
# replication at the config's seed and, with robustness, one per `readings.seeds`. Each run's
# trials are scored on the declared measures (rule `measures`, for every run), and the rule
# `readings` sets each effect against the paper over the replications, and tests the differences
# between the cue timings and between the Goal responses.


rule measures:
    """Every test trial scored on each declared measure, and each measure's (and null control's)
    per-network contrasts, cell means and per-object means."""
    input:
        unpack(model_inputs),
        weights=run_network_files("train/net{net}/weights.npz"),
        code=script_code("measures"),
    output:
        trials="data/{folder}eval/measures.csv",
        json="data/{folder}eval/measures.json",
    params:
        network=run_section("network"),
        measures=config["readings"]["measures"],
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/{folder}measures.log",
    benchmark:
        "data/benchmarks/{folder}measures.tsv"
    script:
        "../scripts/measures.py"


rule readings:
    """Every reading's effects over its replications: data/readings/summary.csv (contract), with
    each effect's t-test and Holm's p; and the tests of the differences between the cue timings
    and between the Goal responses, paired by network (data/readings/differences.csv)."""
    input:
        measures=[PLAN.path(row["run"], "eval/measures.json") for row in PLAN.readings],
        trials=[PLAN.path(row["run"], "eval/measures.csv") for row in PLAN.readings],
        code=script_code("readings"),
    output:
        summary="data/readings/summary.csv",
        replications="data/readings/replications.csv",
        differences="data/readings/differences.csv",
    params:
        table=PLAN.readings,
        measures=config["readings"]["measures"],
        margins=settings(config["readings"]["equivalence_margin"]),
    threads: 1
    resources:
        mem_mb=500,
        runtime=5,
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
    threads: 1
    resources:
        mem_mb=500,
        runtime=5,
    log:
        "data/logs/readings/figure.log",
    benchmark:
        "data/benchmarks/readings/figure.tsv"
    script:
        "../scripts/readings_figure.py"
