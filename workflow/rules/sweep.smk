# Sweeps (not part of the default target): replications and hyperparameter grids.
#   snakemake -c2 sweep                                   the points of config `sweep`
#   snakemake --profile workflow/profiles/slurm sweep     the same on a cluster
# A point is a run (common.smk: PLAN.sweep) of one seed and one value of each swept setting: a
# whole replication, whose seed reseeds the demonstrations, the SOMs and the networks. Its
# networks are trained, tested and analysed by the rules of every run, in its folder (PLAN.folder).


rule sweep_summary:
    """Each point's congruency and size effects, with 95% intervals, and how many are significant."""
    input:
        trials=[PLAN.path(run, "eval/trials.csv") for run in PLAN.sweep],
        anova=[PLAN.path(run, "eval/anova.json") for run in PLAN.sweep],
        code=script_code("sweep_summary"),
    output:
        points="data/sweep/points.csv",
        summary="data/sweep/summary.csv",
    params:
        points=PLAN.sweep,
    resources:
        mem_mb=1000,
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
        code=script_code("sweep_figure"),
    output:
        "data/sweep/effects.png",
    log:
        "data/logs/sweep/figure.log",
    benchmark:
        "data/benchmarks/sweep/figure.tsv"
    script:
        "../scripts/sweep_figure.py"


# every file of the sweep, each point's too (see run_files)
SWEEP_OUTPUTS = [
    *(f for run in PLAN.sweep for f in run_files(run)),
    *rules.sweep_summary.output,
    *rules.sweep_figure.output,
]


rule sweep:
    """Target: the whole sweep."""
    input:
        SWEEP_OUTPUTS,


rule sweep_cost:
    """Does the sweep's cost grow linearly? Wall time of `snakemake sweep` for each number of
    replications in config `sweep_cost`, in scratch copies (in the book with robustness=True)."""
    input:
        # the sweep's only input from the main run (icub_workflow.sweep_timing: SWEEP_INPUTS)
        data=rules.visual_maps.output,
        rules=sorted(glob.glob("workflow/rules/*.smk")),
        # the measuring, and the code of the rules it times
        code=script_code(
            "sweep_cost", "demos_run", "soms", "train", "evaluate", "stats",
            "sweep_summary", "sweep_figure",
        ),
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
