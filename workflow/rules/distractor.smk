# A distractor at test, the paper's closing question (config `distractor`; docs/distractor.md):
# the confirmation's replications (both cue timings, every seed the build makes), no new
# training. Declared before any result: the default target makes it only with `distractor.run`
# (Snakefile: ON_REQUEST); else `snakemake -c1 distractor` asks for it.


# each of the confirmation's replications (RunPlan.claim_rows): its run's seed, model inputs,
# settings and weights
DISTRACTOR_REPLICATIONS = [
    {
        "seed": PLAN.config(row["run"])["seed"],
        **model_inputs({"folder": PLAN.folder(row["run"])}),
        "grip_distance": PLAN.config(row["run"])["grip_distance"],
        "network": settings(PLAN.config(row["run"])["network"]),
        "weights": weights_files(row["run"]),
    }
    for row in PLAN.claim_rows
]


rule distractor:
    """Every categorisation trial of every confirmation replication with each other object as
    distractor at each declared weight (and 0, the reference): the trials, each replication's
    estimates, and the declared tests (Holm within each family) against people's directions."""
    input:
        # the files in a measured group's folder: the folder (measured_inputs)
        models=measured_inputs(
            sorted(
                {rep[key] for rep in DISTRACTOR_REPLICATIONS for key in ("maps", "soms", "demos")}
            )
        ),
        weights=measured_inputs(
            path for rep in DISTRACTOR_REPLICATIONS for path in rep["weights"]
        ),
        code=script_code("distractor"),
    output:
        trials="data/distractor/trials.csv",
        estimates="data/distractor/estimates.csv",
        summary="data/distractor/summary.csv",
    params:
        replications=DISTRACTOR_REPLICATIONS,
        declaration=settings(config["distractor"]),
        # one minimum for every test over replications (icub_affordance.analysis.replicated)
        min_replications=config["confirmation"]["min_replications"],
    log:
        "data/logs/distractor/summary.log",
    benchmark:
        "data/benchmarks/distractor/summary.tsv"
    script:
        "../scripts/distractor.py"
