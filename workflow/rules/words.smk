# Names against images (config `words`, declared before any result; book chapter "Words"): the
# whole model made again with names on (config `names`) at each of the study's seeds and cue
# timings (RunPlan.words), each replication's networks tested showing each object's image, its
# name and both, and the declared tests over the replications.


rule word_trials:
    """A words replication's networks tested in every form: each test trial scored on the
    declared measures (eval/words.csv), each form's contrasts and each network's reactivation
    contrast at the declared step (eval/words.json)."""
    input:
        unpack(model_inputs),
        weights=run_weights,
        code=script_code("word_trials"),
    output:
        trials="data/{folder}eval/words.csv",
        json="data/{folder}eval/words.json",
    wildcard_constraints:
        folder=folders_pattern([row["run"] for row in PLAN.words]),
    params:
        network=run_section("network"),
        grip_distance=run_section("grip_distance"),
        measures=config["words"]["measures"],
        step=config["words"]["reactivation"]["step"],
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/{folder}word_trials.log",
    benchmark:
        "data/benchmarks/{folder}word_trials.tsv"
    script:
        "../scripts/word_trials.py"


rule words:
    """The declared family over the replications (data/words/summary.csv), their estimates,
    every form's effects, the reactivation tests over each network's contrast, and each
    replication's wrong-grip rate per congruency x size cell."""
    input:
        json=[PLAN.path(row["run"], "eval/words.json") for row in PLAN.words],
        trials=[PLAN.path(row["run"], "eval/words.csv") for row in PLAN.words],
        code=script_code("words"),
    output:
        summary="data/words/summary.csv",
        replications="data/words/replications.csv",
        by_form="data/words/by_form.csv",
        reactivation="data/words/reactivation.csv",
        contrasts="data/words/contrasts.csv",
        error_cells="data/words/error_cells.csv",
    params:
        table=PLAN.words,
        declaration=settings(config["words"]),
    log:
        "data/logs/words/summary.log",
    benchmark:
        "data/benchmarks/words/summary.tsv"
    script:
        "../scripts/words.py"


rule words_figure:
    """The effects by what a trial shows, image, name or both (plot only)."""
    input:
        by_form=rules.words.output.by_form,
        replications=rules.words.output.replications,
        code=script_code("words_figure"),
    output:
        "data/words/effects.png",
    log:
        "data/logs/words/figure.log",
    benchmark:
        "data/benchmarks/words/figure.tsv"
    script:
        "../scripts/words_figure.py"
