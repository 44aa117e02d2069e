# The rules that serve a run in one job where the config's own run has a job per object or per
# network (common.smk: PLAN.jobs_per_network): the other runs' demonstrations and networks. A run
# makes its own demonstrations and SOMs only if their settings differ from an earlier run's (a new
# seed, new SOM settings); otherwise it reads that run's (PLAN.stage_run).


# A run that makes its own demonstrations (a sweep point's seed) makes them in one job: the four
# objects' physics take about 1.5 s each and a robot job about 1 s to start. The config's own run
# keeps its job per object (rule demos_object), in parallel at the start of the build.
rule run_demos:
    """A run's 4 x 2 x 5 demonstrations, made and checked in physics, in one file, and the
    summary table: rules demos_object and demos in one job."""
    input:
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("demos_run"),
    output:
        demos="data/{folder}demos/demos.npz",
        summary="data/{folder}demos/summary.csv",
    wildcard_constraints:
        folder=folders_pattern([run for run in PLAN.runs if not PLAN.jobs_per_network(run)]),
    params:
        objects=settings(config["objects"]),
        object_sizes=settings(config["object_sizes_m"]),
        demos=settings(config["demos"]),
        seed=run_section("seed"),
        posture=settings(config["initial_posture_deg"]),
    priority: 2  # a replication's maps and networks wait on it
    resources:
        mem_mb=1000,
        runtime=20,
    log:
        "data/logs/{folder}demos.log",
    benchmark:
        "data/benchmarks/{folder}demos.tsv"
    script:
        "../scripts/demos_run.py"


# Phase 1 of a run's networks, trained once for the robot variants that differ only in what acts
# after it, the cue timing and the rate's schedule (common.smk: PHASE1_RUNS): each continues
# from it in its run_train, to the same bits.
rule run_phase1:
    """Phase 1 (grasping only) of a run's networks, each at its own seed, saved as a training
    state for the runs that share it (runs.py: RunPlan.phase1_run)."""
    input:
        unpack(model_inputs),
        code=script_code("phase1"),
    output:
        [f"data/{{folder}}train/net{net}/phase1.npz" for net in NETWORKS],
    wildcard_constraints:
        folder=folders_pattern(PHASE1_RUNS),
    params:
        network=run_section("network"),
        grip_distance=run_section("grip_distance"),
        seed=run_section("seed"),
    priority: 3  # the build's longest chain: phase 1, three trainings, their robot tests
    resources:
        mem_mb=1000,
        runtime=20,
    log:
        "data/logs/{folder}phase1.log",
    benchmark:
        "data/benchmarks/{folder}phase1.tsv"
    script:
        "../scripts/phase1.py"


# A run's networks in one job (common.smk: GROUPED_RUNS): same arithmetic, same seeds, so the
# same files as one job each; continued from a shared phase 1 where the run has one.
use rule train as run_train with:
    input:
        unpack(model_inputs),
        phase1=phase1_files,
        code=script_code("train"),
    output:
        curve=[f"data/{{folder}}train/net{net}/curve.csv" for net in NETWORKS],
        weights=[f"data/{{folder}}train/net{net}/weights.npz" for net in NETWORKS],
    wildcard_constraints:
        folder=folders_pattern(GROUPED_RUNS),
    priority: 2  # the robot variants' long trainings (the cue ablation's is short)
    log:
        "data/logs/{folder}train.log",
    benchmark:
        "data/benchmarks/{folder}train.tsv"


if FRESH_NETWORKS:

    # A confirmation's fresh networks in one job (common.smk: FRESH_RUNS).
    use rule run_train as confirmation_train with:
        output:
            curve=[f"data/{{folder}}train/net{net}/curve.csv" for net in FRESH_NETWORKS],
            weights=[f"data/{{folder}}train/net{net}/weights.npz" for net in FRESH_NETWORKS],
        wildcard_constraints:
            folder=folders_pattern(FRESH_RUNS),
        priority: 3  # the longest training, and its robot test waits on all of it
