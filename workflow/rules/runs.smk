# Every run but the main one: the same rule definitions (workflow/rules/demos.smk, model.smk),
# their outputs under data/runs/{run}/. A run's inputs and parameters come from its own config
# (common.smk: RUN_CONFIG), so these only say where the files go. A run makes its own
# demonstrations and SOMs only if their settings differ from an earlier run's (a new seed, new
# SOM settings); otherwise it reads that run's (common.smk: stage_run).


use rule demos_object as run_demos_object with:
    output:
        "data/runs/{run}/demos/parts/{object}.npz",
    log:
        "data/logs/runs/{run}/demos_object/{object}.log",
    benchmark:
        "data/benchmarks/runs/{run}/demos_object/{object}.tsv"


use rule demos as run_demos with:
    output:
        demos="data/runs/{run}/demos/demos.npz",
        summary="data/runs/{run}/demos/summary.csv",
    log:
        "data/logs/runs/{run}/demos.log",
    benchmark:
        "data/benchmarks/runs/{run}/demos.tsv"


use rule soms as run_soms with:
    output:
        "data/runs/{run}/soms/soms.npz",
    log:
        "data/logs/runs/{run}/soms.log",
    benchmark:
        "data/benchmarks/runs/{run}/soms.tsv"


use rule train as run_train with:
    output:
        curve="data/runs/{run}/train/net{net}/curve.csv",
        weights="data/runs/{run}/train/net{net}/weights.npz",
    priority: 0  # after the main networks: the robot test waits on those
    log:
        "data/logs/runs/{run}/train/net{net}.log",
    benchmark:
        "data/benchmarks/runs/{run}/train/net{net}.tsv"


use rule evaluate as run_evaluate with:
    output:
        trials="data/runs/{run}/eval/trials.csv",
        hidden="data/runs/{run}/eval/hidden.npz",
    log:
        "data/logs/runs/{run}/evaluate.log",
    benchmark:
        "data/benchmarks/runs/{run}/evaluate.tsv"


use rule stats as run_stats with:
    output:
        json="data/runs/{run}/eval/anova.json",
        table="data/runs/{run}/eval/anova_table.md",
    log:
        "data/logs/runs/{run}/stats.log",
    benchmark:
        "data/benchmarks/runs/{run}/stats.tsv"


use rule figure5 as run_figure5 with:
    output:
        figure5="data/runs/{run}/figures/figure5.png",
        timecourse="data/runs/{run}/figures/conflict_timecourse.png",
    log:
        "data/logs/runs/{run}/figure5.log",
    benchmark:
        "data/benchmarks/runs/{run}/figure5.tsv"


def run_files(run):
    """Every file a run makes: its demonstrations and SOMs (unless it reads an earlier run's,
    common.smk: stage_run), each network's curve and weights, the tests, ANOVAs and Figure 5.

    All of them are inputs of the run's target, not only its last files: Snakemake does not
    remake a missing file that no job still to run needs, so a deleted (or corrupt, and deleted
    as the error says) intermediate file would otherwise stay missing after a green run.
    """

    def outputs(name, **wildcards):
        """The rule's output files for this run (the main run's rule, or its `run_` copy)."""
        if run == MAIN:
            return expand(list(getattr(rules, name).output), **wildcards)
        return expand(list(getattr(rules, f"run_{name}").output), run=run, **wildcards)

    files = []
    if stage_run(run, "demos") == run:
        files += outputs("demos_object", object=config["objects"]) + outputs("demos")
    if stage_run(run, "soms") == run:
        files += outputs("soms")
    files += outputs("train", net=run_networks(run))
    for name in ("evaluate", "stats", "figure5"):
        files += outputs(name)
    return files
