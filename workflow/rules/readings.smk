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
    wildcard_constraints:
        folder=served_by("measures", "measures"),
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
# files. A rule's outputs are fixed when the rules are read, so each group has its rule.
for _group, _runs in MEASURED_GROUPS.items():
    # each run as the job's script reads it: its settings and its files
    _table = [
        {
            "run": run,
            "network": settings(PLAN.config(run)["network"]),
            "grip_distance": PLAN.config(run)["grip_distance"],
            "seed": PLAN.config(run)["seed"],
            **model_inputs({"folder": PLAN.folder(run)}),
            "makes_soms": PLAN.makes(run, "soms"),  # else it reads an earlier run's (same seed)
            "som_settings": settings(PLAN.config(run)["soms"]),
            "names": settings(PLAN.config(run)["names"]),
            "curves": curve_files(run),  # its part `all`: one file each
            "weights": weights_files(run),
            "trials": PLAN.path(run, "eval/measures.csv"),
            "json": PLAN.path(run, "eval/measures.json"),
        }
        for run in _runs
    ]

    rule:
        """A seed's measured runs (readings, size study): each run's networks trained, then
        every test trial scored on the declared measures."""
        name:
            f"measured_{_group}"
        input:
            models=sorted(
                {row[key] for row in _table for key in ("maps", "soms", "demos")}
                - {row["soms"] for row in _table if row["makes_soms"]}
            ),
            code=script_code("measured_runs"),
        output:
            soms=[row["soms"] for row in _table if row["makes_soms"]],
            curves=[path for row in _table for path in row["curves"]],
            weights=[path for row in _table for path in row["weights"]],
            trials=[row["trials"] for row in _table],
            json=[row["json"] for row in _table],
        params:
            runs=_table,
            objects=settings(config["objects"]),
            measures=config["readings"]["measures"],
        priority: 1  # before the figures: the size study's and the readings' tables wait on it
        resources:
            mem_mb=1000,
            runtime=30,
        log:
            f"data/logs/measured/{_group}.log",
        benchmark:
            f"data/benchmarks/measured/{_group}.tsv"
        script:
            "../scripts/measured_runs.py"


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
