# The model against what people do (config `signatures`; the book's chapter of that name): the
# compatibility effect's human signatures, each with the model condition declared for it, tested
# at test time on the networks of the config's own reading, one replication per readings seed
# that the build makes (with robustness, every readings.seeds replication as well).


def signature_replications():
    """Each replication of the config's own reading (its cue timing and Goal response) that
    this build makes: its run's seed, model inputs, settings and weights."""
    cue = config["network"]["categorisation_cue"]
    goal = config["soms"]["goal_response"]
    rows = [r for r in PLAN.readings if r["cue"] == cue and r["goal_response"] == goal]
    return [
        {
            "seed": PLAN.config(row["run"])["seed"],
            **model_inputs({"folder": PLAN.folder(row["run"])}),
            "grip_distance": PLAN.config(row["run"])["grip_distance"],
            "network": settings(PLAN.config(row["run"])["network"]),
            "weights": [
                PLAN.path(row["run"], f"train/net{net}/weights.npz")
                for net in PLAN.networks(row["run"])
            ],
        }
        for row in rows
    ]


SIGNATURE_REPLICATIONS = signature_replications()


rule signatures:
    """Every signature's condition on every replication's networks: the noisy trials, each
    signature's tests and verdict (data/signatures/summary.csv, contract), the errors apart."""
    input:
        models=sorted(
            {rep[key] for rep in SIGNATURE_REPLICATIONS for key in ("maps", "soms", "demos")}
        ),
        weights=[path for rep in SIGNATURE_REPLICATIONS for path in rep["weights"]],
        code=script_code("signatures"),
    output:
        trials="data/signatures/trials.csv",
        summary="data/signatures/summary.csv",
        errors="data/signatures/errors.csv",
    params:
        replications=SIGNATURE_REPLICATIONS,
        signatures=settings(config["signatures"]),
    log:
        "data/logs/signatures/summary.log",
    benchmark:
        "data/benchmarks/signatures/summary.tsv"
    script:
        "../scripts/signatures.py"


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
