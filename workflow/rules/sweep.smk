# Sweeps (not part of the default target): replications and hyperparameter grids.
#   snakemake -c2 sweep                                   the points of config `sweep`
#   snakemake --profile workflow/profiles/slurm sweep     the same on a cluster
# A point is a run (common.smk: PLAN.sweep) of one seed and one value of each swept setting: a
# whole replication, whose seed reseeds the demonstrations, the SOMs and the networks. Its
# networks are trained and tested by the rules of every run, in its folder (PLAN.folder); its
# ANOVA is the summary's, as no page reads a point's own stats or Figure 5 (RunPlan.steps).
# Its cost is read from those jobs' own records, their benchmark files (book.smk:
# sweep_job_records); the wall time against the number of replications is measured from outside
# the DAG, `python benchmarks/sweep_cost.py` (no job starts Snakemake).


rule sweep_summary:
    """Each point's congruency and size effects, with 95% intervals, and how many are significant."""
    input:
        trials=[PLAN.path(run, "eval/trials.csv") for run in PLAN.sweep],
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

