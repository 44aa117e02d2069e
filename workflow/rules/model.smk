# The learning model (paper sections 2.2, 2.3 and 3): SOMs, 12 Jordan networks, tests, ANOVA.
# The rules with the wildcard `folder` serve every run (common.smk: PLAN): their inputs and
# parameters are the run's own. The plot rules without it draw the config's own run.


rule soms:
    """Train the Object, Task and Goal maps offline and save what they send to the network."""
    input:
        maps=lambda wildcards: maps_file(run_of(wildcards)),
        code=script_code("soms"),
    output:
        "data/{folder}soms/soms.npz",
    params:
        soms=run_section("soms"),
        names=run_section("names"),
        seed=run_section("seed"),
        objects=settings(config["objects"]),
    priority: 3  # every training waits on it: first
    log:
        "data/logs/{folder}soms.log",
    benchmark:
        "data/benchmarks/{folder}soms.tsv"
    script:
        "../scripts/soms.py"


rule figure2_maps:
    """The three maps' activations for every object and task (plot only)."""
    input:
        soms=PLAN.path(MAIN, "soms/soms.npz"),
        code=script_code("figure2_maps"),
    output:
        "data/soms/figure2_maps.png",
    log:
        "data/logs/figure2_maps.log",
    benchmark:
        "data/benchmarks/figure2_maps.tsv"
    script:
        "../scripts/figure2_maps.py"



rule figure2_architecture:
    """Figure 2's diagram: the maps and the Jordan network, and what feeds what (plot only)."""
    input:
        code=script_code("figure2_architecture"),
    output:
        "data/figures/figure2_architecture.png",
    params:
        hidden=config["network"]["hidden"],
    log:
        "data/logs/figure2_architecture.log",
    benchmark:
        "data/benchmarks/figure2_architecture.tsv"
    script:
        "../scripts/figure2_architecture.py"

rule train:
    """A run's Jordan networks, each from its own seed; networks 0-5 learn mapping A, 6-11
    mapping B. A job per part (icub_workflow.parts): one network of the config's own run
    (`net03`: its twelve in parallel at the start), or every network of another run (`all`),
    continued from a shared phase 1 where the run has one (runs.smk: phase1)."""
    input:
        unpack(model_inputs),
        phase1=phase1_files,
        code=script_code("train"),
    output:
        curve="data/{folder}train/{part}/curve.csv",
        weights="data/{folder}train/{part}/weights.npz",
    params:
        network=run_section("network"),
        names=run_section("names"),
        grip_distance=run_section("grip_distance"),
        seed=run_section("seed"),
    wildcard_constraints:
        part=r"net\d\d|all",
    # before the other rules' jobs when both are ready: the robot tests wait on these networks,
    # and theirs are the longest jobs that follow (see workflow/rules/robot.smk)
    priority: 2
    # on a cluster, another run's networks go as one job with its tests and measures (group
    # `replication`, workflow/profiles/slurm); the config's own, a job each, go apart (and a
    # local run, a dry run too, shows no group)
    group:
        lambda wildcards: (
            "replication" if wildcards.part == "all" and workflow.non_local_exec else None
        )
    resources:
        # a run's networks side by side: the 768,000-iteration robot trainings take about 600 MB
        mem_mb=lambda wildcards: 1000 if wildcards.part == "all" else 500,
        runtime=10,
    log:
        "data/logs/{folder}train/{part}.log",
    benchmark:
        "data/benchmarks/{folder}train/{part}.tsv"
    script:
        "../scripts/train.py"


rule evaluate:
    """Test every network on both tasks, all objects and sequences, closed loop and forced."""
    input:
        unpack(model_inputs),
        weights=run_weights,
        code=script_code("evaluate"),
    output:
        trials="data/{folder}eval/trials.csv",
        hidden="data/{folder}eval/hidden.npz",
    params:
        network=run_section("network"),
        grip_distance=run_section("grip_distance"),
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/{folder}evaluate.log",
    benchmark:
        "data/benchmarks/{folder}evaluate.tsv"
    script:
        "../scripts/evaluate.py"


rule stats:
    """The two-way and repeated-measures ANOVAs of the categorisation trials."""
    input:
        trials=run_file("eval/trials.csv"),
        code=script_code("stats"),
    output:
        json="data/{folder}eval/anova.json",
        table="data/{folder}eval/anova_table.md",
    params:
        # another run's exploration families carry its name (the own run's none)
        run=lambda w: None if run_of(w) == MAIN else run_of(w),
    log:
        "data/logs/{folder}stats.log",
    benchmark:
        "data/benchmarks/{folder}stats.tsv"
    script:
        "../scripts/stats.py"


rule figure4:
    """Figure 4: training RMSE over iterations, mean and range over the networks (plot only)."""
    input:
        curves=[PLAN.path(MAIN, f"train/net{net}/curve.csv") for net in NETWORKS],
        code=script_code("figure4"),
    output:
        "data/figures/figure4.png",
    params:
        phase1=config["network"]["phase1_iterations"],
    log:
        "data/logs/figure4.log",
    benchmark:
        "data/benchmarks/figure4.tsv"
    script:
        "../scripts/figure4.py"


rule figure5:
    """Figure 5 and the per-step conflict time-course, from the trials (plot only)."""
    input:
        trials=run_file("eval/trials.csv"),
        code=script_code("figure5"),
    output:
        figure5="data/{folder}figures/figure5.png",
        timecourse="data/{folder}figures/conflict_timecourse.png",
    log:
        "data/logs/{folder}figure5.log",
    benchmark:
        "data/benchmarks/{folder}figure5.tsv"
    script:
        "../scripts/figure5.py"


rule representations:
    """The hidden units over the steps: how far categorisation trials are from grasping, and
    each network's trajectories on its first two principal axes."""
    input:
        trials=PLAN.path(MAIN, "eval/trials.csv"),
        hidden=PLAN.path(MAIN, "eval/hidden.npz"),
        code=script_code("representations"),
    output:
        divergence="data/eval/divergence.csv",
        trajectories="data/eval/hidden_trajectories.csv",
        explained="data/eval/hidden_explained.csv",
        summary="data/eval/divergence.json",
    log:
        "data/logs/representations.log",
    benchmark:
        "data/benchmarks/representations.tsv"
    script:
        "../scripts/representations.py"


rule figure_hidden:
    """The hidden-representation figure (plot only)."""
    input:
        trajectories=rules.representations.output.trajectories,
        explained=rules.representations.output.explained,
        divergence=rules.representations.output.divergence,
        code=script_code("figure_hidden"),
    output:
        "data/figures/hidden_representations.png",
    params:
        network=0,
    log:
        "data/logs/figure_hidden.log",
    benchmark:
        "data/benchmarks/figure_hidden.tsv"
    script:
        "../scripts/figure_hidden.py"
