# Which reading of the paper reproduces it (MODEL.md sections 5, 7, 8): every reading (config
# `readings`: cue timing x Goal response) is a run of the model (common.smk: reading_runs), one
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
        trials="data/eval/measures.csv",
        json="data/eval/measures.json",
    params:
        network=run_section("network"),
        measures=config["readings"]["measures"],
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/measures.log",
    benchmark:
        "data/benchmarks/measures.tsv"
    script:
        "../scripts/measures.py"


use rule measures as run_measures with:
    output:
        trials="data/runs/{run}/eval/measures.csv",
        json="data/runs/{run}/eval/measures.json",
    log:
        "data/logs/runs/{run}/measures.log",
    benchmark:
        "data/benchmarks/runs/{run}/measures.tsv"


rule readings:
    """Every reading's effects over its replications: data/readings/summary.csv (contract), with
    each effect's t-test and Holm's p; and the tests of the differences between the cue timings
    and between the Goal responses, paired by network (data/readings/differences.csv)."""
    input:
        measures=[f"{run_dir(row['run'])}/eval/measures.json" for row in READINGS],
        trials=[f"{run_dir(row['run'])}/eval/measures.csv" for row in READINGS],
        code=script_code("readings"),
    output:
        summary="data/readings/summary.csv",
        replications="data/readings/replications.csv",
        differences="data/readings/differences.csv",
    params:
        table=READINGS,
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


def reading_files(run):
    """Every file a reading's replication makes (common.smk: reading_runs): its demonstrations,
    SOMs and networks (runs.smk: run_files), its measures, and, for the main run and the runs of
    the default target, their tests too; a reading's own run is not tested otherwise (its trials
    are scored by rule `measures`)."""
    files = run_files(run)
    if run != MAIN and run not in CONFIGURED_RUNS:
        tests = {
            f"{run_dir(run)}/{f.removeprefix('data/')}"
            for name in ("evaluate", "stats", "figure5")
            for f in getattr(rules, name).output
        }
        files = [f for f in files if f not in tests]
    return files + [
        f"{run_dir(run)}/{f.removeprefix('data/')}" for f in rules.measures.output
    ]
