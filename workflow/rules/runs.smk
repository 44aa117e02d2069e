# The rules that serve a run in one job where the config's own run has a job per network
# (common.smk: PLAN.jobs_per_network): the other runs' networks.


# Phase 1 of a run's networks, trained once for the robot variants that differ only in what acts
# after it, the cue timing and the rate's schedule (RunPlan.phase1_owners): each continues
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
        folder=folders_pattern(PLAN.phase1_owners),
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


# A run's networks in one job (RunPlan.rule_for): same arithmetic, same seeds, so the
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
        folder=served_by("run_train", "train"),
    priority: 2  # the robot variants' long trainings (the cue ablation's is short)
    resources:
        # a run's networks side by side: the 768,000-iteration robot trainings take about 600 MB
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/{folder}train.log",
    benchmark:
        "data/benchmarks/{folder}train.tsv"


if FRESH_NETWORKS:

    # A confirmation's fresh networks in one job (RunPlan.rule_for).
    use rule run_train as confirmation_train with:
        output:
            curve=[f"data/{{folder}}train/net{net}/curve.csv" for net in FRESH_NETWORKS],
            weights=[f"data/{{folder}}train/net{net}/weights.npz" for net in FRESH_NETWORKS],
        wildcard_constraints:
            folder=served_by("confirmation_train", "train"),
        priority: 3  # the longest training, and its robot test waits on all of it
