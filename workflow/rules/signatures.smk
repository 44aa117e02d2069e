# The model against what people do (config `signatures`; the book's chapter of that name): the
# compatibility effect's human signatures, each with the model condition declared for it, tested
# at test time on the networks of the config's own reading, one replication per confirmation
# seed that the build makes (config `confirmation`).


SIGNATURE_REPLICATIONS = signature_replications()


rule signatures:
    """Every signature's condition on every replication's networks: the noisy trials, each
    signature's tests and verdict (data/signatures/summary.csv, contract), the errors apart."""
    input:
        # the files in a measured group's folder: the folder (measured_inputs)
        models=measured_inputs(
            sorted(
                {rep[key] for rep in SIGNATURE_REPLICATIONS for key in ("maps", "soms", "demos")}
            )
        ),
        weights=measured_inputs(
            path for rep in SIGNATURE_REPLICATIONS for path in rep["weights"]
        ),
        code=script_code("signatures"),
    output:
        trials="data/signatures/trials.csv",
        summary="data/signatures/summary.csv",
        errors="data/signatures/errors.csv",
    params:
        replications=SIGNATURE_REPLICATIONS,
        signatures=settings(config["signatures"]),
        # one minimum for every test over replications (icub_affordance.analysis.replicated)
        min_replications=config["confirmation"]["min_replications"],
    log:
        "data/logs/signatures/summary.log",
    benchmark:
        "data/benchmarks/signatures/summary.tsv"
    script:
        "../scripts/signatures.py"


rule signatures_extinction:
    """A test added after the results (family "signatures: extinction levels (exploration, added
    after results)"): each blanking level's congruency effect less the in-view one, over the
    replications with both, at least the one minimum, Holm within the family; its direction
    against people's (the effect fades once the object is gone)."""
    input:
        trials=rules.signatures.output.trials,
        code=script_code("signatures_extinction"),
    output:
        "data/signatures/extinction_levels.csv",
    params:
        # one minimum for every test over replications (icub_affordance.analysis.replicated)
        least=config["confirmation"]["min_replications"],
        alpha=config["confirmation"]["alpha"],
    log:
        "data/logs/signatures/extinction_levels.log",
    benchmark:
        "data/benchmarks/signatures/extinction_levels.tsv"
    script:
        "../scripts/signatures_extinction.py"


rule signatures_figure:
    """The delta plot (the effect per reaction-time bin) and the effect against the steps the
    object was seen (plot only)."""
    input:
        trials=rules.signatures.output.trials,
        code=script_code("signatures_figure"),
    output:
        "data/signatures/signatures.png",
    params:
        quantiles=config["signatures"]["quantiles"],
    log:
        "data/logs/signatures/figure.log",
    benchmark:
        "data/benchmarks/signatures/figure.tsv"
    script:
        "../scripts/signatures_figure.py"
