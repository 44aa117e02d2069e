# Beyond the paper: the trained networks drive the simulated arm (one job per network), the
# demonstrations are replayed through the same controller, and the robot's success is summarised.

# The filmstrip shows the first network of each mapping: for any object one of them categorises
# it with its natural grip (congruent) and the other with the other grip (incongruent).
EMBODIED_FILM_NETWORKS = [NETWORKS[0], NETWORKS[len(NETWORKS) // 2]]


def embodied_weights(wildcards):
    """The weights the robot test of a run drives with: the wildcard `net`'s (rule embodied, the
    main run), or every network's of the run (rule run_embodied, one job)."""
    run = run_of(wildcards)
    nets = [wildcards.net] if "net" in wildcards.keys() else run_networks(run)
    return [f"{run_dir(run)}/train/net{net}/weights.npz" for net in nets]


def embodied_files(run, name):
    """A tested variant's per-network robot-test files (`name`: trials.csv or states.npz)."""
    folder = "data/embodied" if run == MAIN else f"data/runs/{run}/embodied"
    return [f"{folder}/net{net}/{name}" for net in run_networks(run)]


rule embodied:
    """One network drives the MuJoCo arm through every test trial, closed loop on its senses."""
    input:
        unpack(model_inputs),
        weights=embodied_weights,
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("embodied"),
    output:
        trials="data/embodied/net{net}/trials.csv",
        states="data/embodied/net{net}/states.npz",
    params:
        network=run_section("network"),
        demos=settings(config["demos"]),
        object_sizes=settings(config["object_sizes_m"]),
    wildcard_constraints:
        net=r"\d\d",
    threads: 1
    priority: 1  # the longest jobs: started early, the short plot jobs fill the end of the run
    resources:
        mem_mb=500,
        runtime=10,
    log:
        "data/logs/embodied/net{net}.log",
    benchmark:
        "data/benchmarks/embodied/net{net}.tsv"
    script:
        "../scripts/embodied.py"


# A robot variant's networks drive the robot in one job, one network after another (the main
# run keeps a job per network, in parallel).
ROBOT_RUN_NAMES = [row["run"] for row in ROBOT_VARIANTS if row["run"] != MAIN]


use rule embodied as run_embodied with:
    output:
        trials=[
            f"data/runs/{{run,{runs_pattern(ROBOT_RUN_NAMES)}}}/embodied/net{net}/trials.csv"
            for net in NETWORKS
        ],
        states=[
            f"data/runs/{{run,{runs_pattern(ROBOT_RUN_NAMES)}}}/embodied/net{net}/states.npz"
            for net in NETWORKS
        ],
    log:
        "data/logs/runs/{run}/embodied.log",
    benchmark:
        "data/benchmarks/runs/{run}/embodied.tsv"


# The confirmation (config robot.confirmation): each confirmed variant's fresh networks drive the
# robot in one job, as a variant's do (rule run_embodied); the networks' indices are the fresh
# ones (common.smk: run_networks), the same for every confirmation run.
CONFIRMATION_NETWORKS = run_networks(next(iter(CONFIRMATION_RUNS))) if CONFIRMATION_RUNS else []


if CONFIRMATION_RUNS:

    use rule embodied as confirmation_embodied with:
        output:
            trials=[
                f"data/runs/{{run,{runs_pattern(CONFIRMATION_RUNS)}}}/embodied/net{net}/trials.csv"
                for net in CONFIRMATION_NETWORKS
            ],
            states=[
                f"data/runs/{{run,{runs_pattern(CONFIRMATION_RUNS)}}}/embodied/net{net}/states.npz"
                for net in CONFIRMATION_NETWORKS
            ],
        log:
            "data/logs/runs/{run}/embodied.log",
        benchmark:
            "data/benchmarks/runs/{run}/embodied.tsv"


rule embodied_replay:
    """Every demonstration replayed through the embodied controller: its servo targets and its
    sensed postures."""
    input:
        demos=rules.demos.output.demos,
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("embodied_replay"),
    output:
        "data/embodied/replay.csv",
    params:
        demos=settings(config["demos"]),
        object_sizes=settings(config["object_sizes_m"]),
    threads: 1
    priority: 1  # the longest jobs: started early, the short plot jobs fill the end of the run
    resources:
        mem_mb=500,
        runtime=10,
    log:
        "data/logs/embodied/replay.log",
    benchmark:
        "data/benchmarks/embodied_replay.tsv"
    script:
        "../scripts/embodied_replay.py"


rule embodied_tolerance:
    """How precisely must a learned arm move? Each object's natural grasp, the mean plan of its
    demonstrations, replayed with its arm targets offset by Gaussian noise: success against the
    palm's distance from where the demonstrator put it (config robot.tolerance)."""
    input:
        demos=rules.demos.output.demos,
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("embodied_tolerance"),
    output:
        "data/embodied/tolerance.csv",
    params:
        demos=settings(config["demos"]),
        object_sizes=settings(config["object_sizes_m"]),
        tolerance=settings(config["robot"]["tolerance"]),
        seed=config["seed"],
    threads: 1
    priority: 1
    resources:
        mem_mb=500,
        runtime=10,
    log:
        "data/logs/embodied/tolerance.log",
    benchmark:
        "data/benchmarks/embodied_tolerance.tsv"
    script:
        "../scripts/embodied_tolerance.py"


rule embodied_summary:
    """Every tested variant's robot trials in one table; the config's own networks' success by
    condition and the effect of congruency; each variant's success, contact time and holds with
    the wrong grip, and their congruency and size effects. Every count and test is over distinct
    trials, one per network x object x task (the test sequences are one movement)."""
    input:
        trials=[f for row in ROBOT_TESTED for f in embodied_files(row["run"], "trials.csv")],
        replay=rules.embodied_replay.output[0],
        code=script_code("embodied_summary"),
    output:
        trials="data/embodied/trials.csv",
        success="data/embodied/success.csv",
        analysis="data/embodied/analysis.json",
        variants="data/embodied/variants.csv",
        effects="data/embodied/effects.json",
    params:
        variants=ROBOT_TESTED,
        networks=len(NETWORKS),
        main=MAIN,
    threads: 1
    resources:
        mem_mb=500,
        runtime=5,
    log:
        "data/logs/embodied/summary.log",
    benchmark:
        "data/benchmarks/embodied_summary.tsv"
    script:
        "../scripts/embodied_summary.py"


rule embodied_confirmation:
    """Explore, then confirm: each confirmed variant's share of grasping trials held (each
    network and object once) on the networks it was chosen on and on fresh ones, with an
    interval that takes a network's four objects as one cluster; and the fresh networks' robot
    trials joined."""
    input:
        trials=rules.embodied_summary.output.trials,
        confirmation=[
            f for row in CONFIRMATION for f in embodied_files(row["confirmation"], "trials.csv")
        ],
        code=script_code("embodied_confirmation"),
    output:
        table="data/embodied/confirmation.csv",
        trials="data/embodied/confirmation_trials.csv",
    params:
        confirmation=CONFIRMATION,
        variant_keys=list(ROBOT_KEYS),
    threads: 1
    resources:
        mem_mb=500,
        runtime=5,
    log:
        "data/logs/embodied/confirmation.log",
    benchmark:
        "data/benchmarks/embodied_confirmation.tsv"
    script:
        "../scripts/embodied_confirmation.py"


rule embodied_filmstrip:
    """A congruent and an incongruent categorisation trial of the same object, on the robot
    (render only)."""
    input:
        states=lambda w: [
            f"data/embodied/net{net}/states.npz" for net in EMBODIED_FILM_NETWORKS
        ],
        # each film network's own trials, not the joined table: the picture need not wait
        # for the other networks
        trials=lambda w: [
            f"data/embodied/net{net}/trials.csv" for net in EMBODIED_FILM_NETWORKS
        ],
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("embodied_filmstrip"),
    output:
        "data/figures/embodied_filmstrip.png",
    params:
        networks=EMBODIED_FILM_NETWORKS,
        pick=settings(config["figures"]["embodied"]),
        object_sizes=settings(config["object_sizes_m"]),
    threads: 1
    resources:
        mem_mb=1000,
        runtime=5,
    log:
        "data/logs/embodied/filmstrip.log",
    benchmark:
        "data/benchmarks/embodied_filmstrip.tsv"
    script:
        "../scripts/embodied_filmstrip.py"


rule robot_variants_figure:
    """The robot variants' success against training iterations, and against the palm's error
    beside the body's tolerance (plot only)."""
    input:
        variants=rules.embodied_summary.output.variants,
        tolerance=rules.embodied_tolerance.output[0],
        code=script_code("robot_variants_figure"),
    output:
        variants="data/figures/robot_variants.png",
        tolerance="data/figures/robot_tolerance.png",
    threads: 1
    resources:
        mem_mb=500,
        runtime=5,
    log:
        "data/logs/embodied/variants_figure.log",
    benchmark:
        "data/benchmarks/robot_variants_figure.tsv"
    script:
        "../scripts/robot_variants_figure.py"


# The variant the book animates (config robot.animation.variant): the config's own networks or
# one of robot.default, so its robot test is part of the default run.
_animated = robot_key(config["robot"]["animation"]["variant"], config["network"])
ANIMATED_RUN = next(
    row["run"] for row in ROBOT_VARIANTS if tuple(row[k] for k in ROBOT_KEYS) == _animated
)


rule robot_animation:
    """Films of the animated variant's first network of each mapping on the robot: grasping each
    object, and one object's congruent and incongruent categorisation (render only; each
    re-run trial is checked against the recorded one)."""
    input:
        unpack(lambda w: model_inputs({"run": ANIMATED_RUN})),
        weights=[
            f"{run_dir(ANIMATED_RUN)}/train/net{net}/weights.npz" for net in EMBODIED_FILM_NETWORKS
        ],
        trials=[embodied_files(ANIMATED_RUN, "trials.csv")[int(net)] for net in EMBODIED_FILM_NETWORKS],
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("embodied_animation"),
    output:
        grasps="data/figures/robot_grasps.gif",
        categorise="data/figures/robot_categorise.gif",
    params:
        network=settings(RUN_CONFIG[ANIMATED_RUN]["network"]),
        networks=[int(net) for net in EMBODIED_FILM_NETWORKS],
        demos=settings(config["demos"]),
        object_sizes=settings(config["object_sizes_m"]),
        object=config["robot"]["animation"]["object"],
        fps=config["robot"]["animation"]["fps"],
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/embodied/animation.log",
    benchmark:
        "data/benchmarks/robot_animation.tsv"
    script:
        "../scripts/embodied_animation.py"
