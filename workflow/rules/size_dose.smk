# What drives the size effect (config `size_dose`; the book's chapter of that name): a dose of
# size coding crossed with the grips' distance, each condition a run replicated with fresh seeds
# (common.smk: PLAN.size_dose), the removal control without size in the input.


rule size_free_maps:
    """A run's visual input without size (config size_free_input): each object's map replaced
    by its shape's mean map."""
    input:
        maps=rules.visual_maps.output.maps,
        code=script_code("size_free_maps"),
    output:
        "data/{folder}vision/size_free_maps.npz",
    params:
        objects=settings(config["objects"]),
    log:
        "data/logs/{folder}size_free_maps.log",
    benchmark:
        "data/benchmarks/{folder}size_free_maps.tsv"
    script:
        "../scripts/size_free_maps.py"


SIZE_MEASURES = [PLAN.path(row["run"], "eval/measures.json") for row in PLAN.size_dose]
SIZE_SOMS = [
    PLAN.path(PLAN.stage_run(row["run"], "soms"), "soms/soms.npz") for row in PLAN.size_dose
]
SIZE_TRIALS = [PLAN.path(row["run"], "eval/measures.csv") for row in PLAN.size_dose]
SIZE_DEMOS = [
    PLAN.path(PLAN.stage_run(row["run"], "demos"), "demos/demos.npz") for row in PLAN.size_dose
]


rule size_dose:
    """The size study: per dose, grip arrangement, cue timing and measure, the size effect over
    whole replications with the manipulation check's ratios and the delivered dose; size and
    the grips' distance separated per replication, the declared tests and their power; and,
    per condition, whether the demonstrations' geometry accounts for each object's error."""
    input:
        measured=measured_inputs(
            [*SIZE_MEASURES, *SIZE_SOMS, *SIZE_TRIALS, *SIZE_DEMOS]
        ),
        code=script_code("size_dose"),
    output:
        summary="data/size_dose/summary.csv",
        crossed="data/size_dose/crossed.csv",
        separated="data/size_dose/separated.csv",
        declared="data/size_dose/declared.csv",
        power="data/size_dose/power.csv",
        replications="data/size_dose/replications.csv",
        manipulation="data/size_dose/manipulation.csv",
        geometry="data/size_dose/geometry.csv",
        motor="data/size_dose/motor.csv",
    params:
        # the files in the folders named above (measured_inputs)
        analyses=SIZE_MEASURES,
        soms=SIZE_SOMS,
        trials=SIZE_TRIALS,
        demos=SIZE_DEMOS,
        table=PLAN.size_dose,
        measures=config["readings"]["measures"],
        crossed=settings(config["size_dose"]["crossed"]),
        doses=settings(config["size_dose"]["doses"]),
        # the one minimum of every test over replications (analysis/replicated.py)
        least=config["confirmation"]["min_replications"],
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/size_dose/summary.log",
    benchmark:
        "data/benchmarks/size_dose/summary.tsv"
    script:
        "../scripts/size_dose.py"


rule size_dose_figure:
    """The size effect against the gap between the grips' distances, per dose and cue timing,
    the size effect per condition and measure, and the manipulation check (plot only)."""
    input:
        summary=rules.size_dose.output.summary,
        replications=rules.size_dose.output.replications,
        manipulation=rules.size_dose.output.manipulation,
        crossed=rules.size_dose.output.crossed,
        code=script_code("size_dose_figure"),
    output:
        "data/size_dose/dose_response.png",
    log:
        "data/logs/size_dose/figure.log",
    benchmark:
        "data/benchmarks/size_dose/figure.tsv"
    script:
        "../scripts/size_dose_figure.py"


rule size_trajectory:
    """The size study taken apart on the RMS distance between the grips' trajectories (the
    RMSE's own scale) instead of their final postures, and on both metrics which part is the
    larger: added after results, its own Holm family, beside the declared tests (a referee's
    question, issue 70)."""
    input:
        replications=rules.size_dose.output.replications,
        manipulation=rules.size_dose.output.manipulation,
        separated=rules.size_dose.output.separated,
        demos=measured_inputs(SIZE_DEMOS),
        code=script_code("size_trajectory"),
    output:
        separated="data/size_dose/trajectory_separated.csv",
        tests="data/size_dose/trajectory_tests.csv",
    params:
        demos=SIZE_DEMOS,
        table=PLAN.size_dose,
        crossed=settings(config["size_dose"]["crossed"]),
        doses=settings(config["size_dose"]["doses"]),
        # the one minimum of every test over replications (analysis/replicated.py)
        least=config["confirmation"]["min_replications"],
    log:
        "data/logs/size_dose/trajectory.log",
    benchmark:
        "data/benchmarks/size_dose/trajectory.tsv"
    script:
        "../scripts/size_trajectory.py"
