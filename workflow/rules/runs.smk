# Phase 1 of a run's networks, trained once for the robot variants that differ only in what acts
# after it, the cue timing and the rate's schedule (RunPlan.phase1_owners): each continues
# from it in its training (rule train, part `all`), to the same bits.
rule phase1:
    """Phase 1 (grasping only) of a run's networks, each at its own seed, saved as a training
    state for the runs that share it (runs.py: RunPlan.phase1_run), by part
    (icub_workflow.parts: the run's part `all`, every network in one file)."""
    input:
        unpack(model_inputs),
        code=script_code("phase1"),
    output:
        "data/{folder}train/{part}/phase1.npz",
    wildcard_constraints:
        folder=folders_pattern(PLAN.phase1_owners),
        part=r"net\d\d|all",
    params:
        network=run_section("network"),
        names=run_section("names"),
        grip_distance=run_section("grip_distance"),
        seed=run_section("seed"),
    priority: 3  # the build's longest chain: phase 1, three trainings, their robot tests
    resources:
        mem_mb=1000,
        runtime=20,
    log:
        "data/logs/{folder}train/{part}/phase1.log",
    benchmark:
        "data/benchmarks/{folder}train/{part}/phase1.tsv"
    script:
        "../scripts/phase1.py"
