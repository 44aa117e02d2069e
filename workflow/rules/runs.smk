# Every run but the main one: the same rule definitions (workflow/rules/demos.smk, model.smk),
# their outputs under data/runs/{run}/. A run's inputs and parameters come from its own config
# (common.smk: RUN_CONFIG), so these only say where the files go. A run makes its own
# demonstrations and SOMs only if their settings differ from an earlier run's (a new seed, new
# SOM settings); otherwise it reads that run's (common.smk: stage_run).


# A run that makes its own demonstrations (a sweep point's seed) makes them in one job: the four
# objects' physics take about 1.5 s each and a robot job about 1 s to start. The main run keeps
# its job per object (rule demos_object), in parallel at the start of the run.
rule run_demos:
    """A run's 4 x 2 x 5 demonstrations, made and checked in physics, in one file, and the
    summary table: rules demos_object and demos in one job."""
    input:
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("demos_run"),
    output:
        demos="data/runs/{run}/demos/demos.npz",
        summary="data/runs/{run}/demos/summary.csv",
    params:
        objects=settings(config["objects"]),
        object_sizes=settings(config["object_sizes_m"]),
        demos=settings(config["demos"]),
        seed=run_section("seed"),
        posture=settings(config["initial_posture_deg"]),
    threads: 1
    resources:
        mem_mb=1000,
        runtime=20,
    log:
        "data/logs/runs/{run}/demos.log",
    benchmark:
        "data/benchmarks/runs/{run}/demos.tsv"
    script:
        "../scripts/demos_run.py"


use rule soms as run_soms with:
    output:
        "data/runs/{run}/soms/soms.npz",
    log:
        "data/logs/runs/{run}/soms.log",
    benchmark:
        "data/benchmarks/runs/{run}/soms.tsv"


# A run's networks are trained in one job: a network takes about 0.15 s of arithmetic and a job
# about 1 s to start (Python, imports, loading the compiled trainer), so one job per network
# would be mostly start-up. Same arithmetic, same seeds, so the same files as one job each
# (the main run keeps its one job per network, in parallel). A rule's outputs are fixed when
# the rules are read, so this rule serves the runs with the main run's number of networks; any
# run that sets its own `network.networks` gets one job per network (run_train_network).
GROUPED_RUNS = [run for run in RUNS if run_networks(run) == NETWORKS]


def runs_pattern(runs):
    """A wildcard constraint that matches exactly these runs ((?!) matches nothing)."""
    return "|".join(map(re.escape, runs)) or "(?!)"


def run_train_outputs(name, runs, nets):
    return [f"data/runs/{{run,{runs_pattern(runs)}}}/train/net{net}/{name}" for net in nets]


use rule train as run_train with:
    output:
        curve=run_train_outputs("curve.csv", GROUPED_RUNS, NETWORKS),
        weights=run_train_outputs("weights.npz", GROUPED_RUNS, NETWORKS),
    priority: 0  # after the main networks: the robot test waits on those
    log:
        "data/logs/runs/{run}/train.log",
    benchmark:
        "data/benchmarks/runs/{run}/train.tsv"


if len(GROUPED_RUNS) < len(RUNS):
    _other_runs = sorted(set(RUNS) - set(GROUPED_RUNS))

    use rule train as run_train_network with:
        output:
            curve=run_train_outputs("curve.csv", _other_runs, ["{net}"])[0],
            weights=run_train_outputs("weights.npz", _other_runs, ["{net}"])[0],
        priority: 0
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


def robot_files(run):
    """A run's robot test (rule run_embodied), for a run that is a tested robot variant."""
    return embodied_files(run, "trials.csv") + embodied_files(run, "states.npz")


def run_files(run):
    """Every file a run makes: its demonstrations and SOMs (unless it reads an earlier run's,
    common.smk: stage_run), each network's curve and weights, the tests, ANOVAs and Figure 5.
    A robot variant is tested on the robot only: its in-silico closed loop would feed a servo
    target back as the posture reached (icub_affordance.evaluate), and the robot test is what it
    is for.

    All of them are inputs of the run's target, not only its last files: Snakemake does not
    remake a missing file that no job still to run needs, so a deleted (or corrupt, and deleted
    as the error says) intermediate file would otherwise stay missing after a green run.
    """

    def outputs(name, **wildcards):
        """The main run's rule's output files, at this run's place (common.smk: run_dir)."""
        files = expand(list(getattr(rules, name).output), **wildcards)
        return [f"{run_dir(run)}/{f.removeprefix('data/')}" for f in files]

    files = []
    if stage_run(run, "demos") == run:
        # the main run makes each object's part in a job of its own (another run: one job)
        if run == MAIN:
            files += outputs("demos_object", object=config["objects"])
        files += outputs("demos")
    if stage_run(run, "soms") == run:
        files += outputs("soms")
    files += outputs("train", net=run_networks(run))
    # a robot variant or a confirmation: trained, then tested on the robot (robot_files)
    if run in ROBOT_RUNS or run in CONFIRMATION_RUNS:
        return files
    for name in ("evaluate", "stats", "figure5"):
        files += outputs(name)
    return files
