# Sweeps (not part of the default target): replications and hyperparameter grids.
#   snakemake -c2 sweep                                   the points of config `sweep`
#   snakemake --profile workflow/profiles/slurm sweep     the same on a cluster
# A point is one seed and one value of each swept setting; it trains its own networks (the
# demonstrations, visual maps and SOMs are the main run's), tests them and runs the ANOVAs.
import itertools
import re


def _sweep_points():
    sweep = config["sweep"]
    points = {}
    for seed, lr, hidden, cue in itertools.product(
        sweep["seeds"], sweep["learning_rate"], sweep["hidden"], sweep["categorisation_cue"]
    ):
        name = f"seed{seed}_lr{lr}_h{hidden}_{cue}"
        points[name] = {"seed": seed, "learning_rate": lr, "hidden": hidden, "categorisation_cue": cue}
    return points


POINTS = _sweep_points()


def point_network(wildcards):
    """The main run's network settings with this point's values swapped in."""
    point = POINTS[wildcards.point]
    overrides = {k: v for k, v in point.items() if k != "seed"}
    return settings(config["network"] | overrides)


wildcard_constraints:
    point="|".join(map(re.escape, POINTS)) or "none",  # names hold dots (lr0.075)


rule sweep_train:
    """One network of one sweep point."""
    input:
        maps=rules.visual_maps.output.maps,
        soms=rules.soms.output[0],
        demos=rules.demos.output.demos,
        code=package_code("spec", "jordan", "som", "train", "io"),
    output:
        curve="data/sweep/{point}/train/net{net}/curve.csv",
        weights="data/sweep/{point}/train/net{net}/weights.npz",
    params:
        network=point_network,
        seed=lambda w: POINTS[w.point]["seed"],
    wildcard_constraints:
        net=r"\d\d",
    threads: 1
    resources:
        mem_mb=500,
        runtime=10,
    log:
        "data/logs/sweep/{point}/train/net{net}.log",
    benchmark:
        "data/benchmarks/sweep/{point}/train/net{net}.tsv"
    script:
        "../scripts/train.py"


rule sweep_evaluate:
    """Test one point's networks."""
    input:
        maps=rules.visual_maps.output.maps,
        soms=rules.soms.output[0],
        demos=rules.demos.output.demos,
        weights=expand("data/sweep/{{point}}/train/net{net}/weights.npz", net=NETWORKS),
        code=package_code("spec", "jordan", "som", "train", "evaluate", "io"),
    output:
        trials="data/sweep/{point}/eval/trials.csv",
        hidden="data/sweep/{point}/eval/hidden.npz",
    params:
        network=point_network,
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/sweep/{point}/evaluate.log",
    benchmark:
        "data/benchmarks/sweep/{point}/evaluate.tsv"
    script:
        "../scripts/evaluate.py"


rule sweep_stats:
    """One point's ANOVAs."""
    input:
        trials="data/sweep/{point}/eval/trials.csv",
        code=package_code("stats", "io"),
    output:
        json="data/sweep/{point}/eval/anova.json",
        table="data/sweep/{point}/eval/anova_table.md",
    threads: 1
    resources:
        mem_mb=500,
        runtime=5,
    log:
        "data/logs/sweep/{point}/stats.log",
    benchmark:
        "data/benchmarks/sweep/{point}/stats.tsv"
    script:
        "../scripts/stats.py"


rule sweep_summary:
    """Each point's congruency and size effects, with 95% intervals, and how many are significant."""
    input:
        trials=expand("data/sweep/{point}/eval/trials.csv", point=POINTS),
        anova=expand("data/sweep/{point}/eval/anova.json", point=POINTS),
        code=package_code("stats", "io"),
    output:
        points="data/sweep/points.csv",
        summary="data/sweep/summary.csv",
    params:
        points=POINTS,
    threads: 1
    resources:
        mem_mb=1000,
        runtime=5,
    log:
        "data/logs/sweep/summary.log",
    benchmark:
        "data/benchmarks/sweep/summary.tsv"
    script:
        "../scripts/sweep_summary.py"


rule sweep_figure:
    """The sweep's effects per point (plot only)."""
    input:
        points=rules.sweep_summary.output.points,
        code=package_code("figures", "io"),
    output:
        "data/sweep/effects.png",
    threads: 1
    resources:
        mem_mb=500,
        runtime=5,
    log:
        "data/logs/sweep/figure.log",
    benchmark:
        "data/benchmarks/sweep/figure.tsv"
    script:
        "../scripts/sweep_figure.py"


rule sweep:
    """Target: the whole sweep."""
    input:
        rules.sweep_summary.output,
        rules.sweep_figure.output,


rule sweep_cost:
    """Does the sweep's cost grow linearly? Wall time of `snakemake sweep` for each number of
    replications in config `sweep_cost`, in scratch copies (in the book with robustness=True)."""
    input:
        data=[
            *rules.visual_maps.output,
            rules.soms.output[0],
            *rules.demos.output,
            *rules.demos.input.parts,
        ],
        rules="workflow/rules/sweep.smk",
        code=package_code(
            "body", "spec", "jordan", "som", "train", "evaluate", "stats", "figures", "io",
        )
        + ["benchmarks/sweep_cost.py"],  # the measuring (not in the package)
        # For the order only (ancient: remaking these does not rerun the measurement): the sweep
        # and everything else the book shows are made first, so nothing runs or waits beside the
        # timed runs. A job waiting for cores makes Snakemake 9's scheduler poll, at a rate that
        # grows with the jobs done: after the sweep's 300 jobs that took about half a core, and
        # the timed runs came out about a third slower than alone.
        after=ancient(
            sorted(
                {*rules.sweep_summary.output, *rules.sweep_figure.output, *BOOK_DATA.values()}
                - {"data/benchmarks/sweep_cost.csv"}
            )
        ),
    output:
        "data/benchmarks/sweep_cost.csv",
    params:
        # what the timed sweeps depend on: the scratch config is this run's (snakemake.config)
        # with the sweep replaced by seeds 1..n at these network settings
        network=settings(config["network"]),
        replications=config["sweep_cost"],
    # all the run's cores: the timed runs are nested `snakemake -c{threads}`, and nothing else
    # should run beside them and slow them down (a function, so that commands that give no
    # cores, such as --rulegraph, can still read this file)
    threads: lambda wildcards: workflow.cores
    resources:
        mem_mb=2000,
        runtime=120,
    log:
        "data/logs/sweep/cost.log",
    benchmark:
        "data/benchmarks/sweep/cost.tsv"
    script:
        "../scripts/sweep_cost.py"
