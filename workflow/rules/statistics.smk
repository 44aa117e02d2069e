# The statistics the book reports that no earlier rule computes: computed here, once per build,
# so that the rule `findings` (and the book's machinery, src/icub_workflow/book) only formats them.


rule robot_statistics:
    """The robot chapter's statistics beyond the variants' table and effects: the share held and
    the median palm error per arm noise, the share held per bin of palm error (the tolerance
    trials, the replayed demonstrations, each variant's grasping trials), the replays' palm
    error, and the exact McNemar tests of the variants that differ in the schedule alone."""
    input:
        trials=rules.robot_summary.output.trials,
        tolerance=rules.robot_tolerance.output[0],
        replay=rules.robot_replay.output[0],
        code=script_code("robot_statistics"),
    output:
        "data/embodied/statistics.json",
    log:
        "data/logs/robot/statistics.log",
    benchmark:
        "data/benchmarks/robot_statistics.tsv"
    script:
        "../scripts/robot_statistics.py"


rule cue_difference:
    """The test of the difference between the cue timings: the main run's and the cue
    ablation's per-network contrasts (the same networks under the two timings), the cue at the
    first step only minus at every step, paired by network (closed loop)."""
    input:
        trials=PLAN.path(MAIN, "eval/trials.csv"),
        ablation_trials=PLAN.path(PLAN.ablation, "eval/trials.csv"),
        code=script_code("cue_difference"),
    output:
        "data/eval/cue_difference.json",
    params:
        # which run is which timing (common.smk: PLAN.ablation)
        cue=config["network"]["categorisation_cue"],
        ablation_cue=PLAN.config(PLAN.ablation)["network"]["categorisation_cue"],
    log:
        "data/logs/cue_difference.log",
    benchmark:
        "data/benchmarks/cue_difference.tsv"
    script:
        "../scripts/cue_difference.py"
