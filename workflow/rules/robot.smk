# Beyond the paper: the trained networks drive the simulated arm (a job per part), the
# demonstrations are replayed through the same controller, and the robot's success is summarised.


rule robot_test:
    """A run's networks drive the MuJoCo arm through every test trial, closed loop on its senses.
    A job per part (icub_workflow.parts): one network of the config's own run (`net03`: its
    twelve in parallel), or every network of another run, one after another (`all`)."""
    input:
        unpack(model_inputs),
        weights=robot_test_weights,
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("robot_test"),
    output:
        trials="data/{folder}embodied/{part}/trials.csv",
        states="data/{folder}embodied/{part}/states.npz",
    params:
        network=run_section("network"),
        grip_distance=run_section("grip_distance"),
        demos=settings(config["demos"]),
        object_sizes=settings(config["object_sizes_m"]),
    wildcard_constraints:
        folder=served_by("robot_test", "robot_test"),
        part=r"net\d\d|all",
    priority: 1  # the longest jobs: started early, the short plot jobs fill the end of the run
    resources:
        runtime=10,
    log:
        "data/logs/{folder}robot_test/{part}.log",
    benchmark:
        "data/benchmarks/{folder}robot_test/{part}.tsv"
    script:
        "../scripts/robot_test.py"


rule robot_replay:
    """Every demonstration replayed through the embodied controller: its servo targets and its
    sensed postures."""
    input:
        demos=PLAN.path(MAIN, "demos/demos.npz"),
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("robot_replay"),
    output:
        "data/embodied/replay.csv",
    params:
        demos=settings(config["demos"]),
        object_sizes=settings(config["object_sizes_m"]),
    priority: 1  # the longest jobs: started early, the short plot jobs fill the end of the run
    resources:
        runtime=10,
    log:
        "data/logs/robot/replay.log",
    benchmark:
        "data/benchmarks/robot_replay.tsv"
    script:
        "../scripts/robot_replay.py"


rule robot_tolerance:
    """How precisely must a learned arm move? Each object's natural grasp, the mean plan of its
    demonstrations, replayed with its arm targets offset by Gaussian noise: success against the
    palm's distance from where the demonstrator put it (config robot.tolerance)."""
    input:
        demos=PLAN.path(MAIN, "demos/demos.npz"),
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("robot_tolerance"),
    output:
        "data/embodied/tolerance.csv",
    params:
        demos=settings(config["demos"]),
        object_sizes=settings(config["object_sizes_m"]),
        tolerance=settings(config["robot"]["tolerance"]),
        seed=config["seed"],
    priority: 1
    resources:
        runtime=10,
    log:
        "data/logs/robot/tolerance.log",
    benchmark:
        "data/benchmarks/robot_tolerance.tsv"
    script:
        "../scripts/robot_tolerance.py"


rule robot_summary:
    """Every tested variant's robot trials in one table; the config's own networks' success by
    condition and the effect of congruency; each variant's success, contact time and holds with
    the wrong grip, and their congruency and size effects. Every count and test is over distinct
    trials, one per network x object x task (the test sequences are one movement)."""
    input:
        trials=[f for run in PLAN.robot_runs for f in robot_test_files(run, "trials.csv")],
        replay=rules.robot_replay.output[0],
        code=script_code("robot_summary"),
    output:
        trials="data/embodied/trials.csv",
        success="data/embodied/success.csv",
        analysis="data/embodied/analysis.json",
        variants="data/embodied/variants.csv",
        effects="data/embodied/effects.json",
    params:
        variants=PLAN.robot_tested,
        # each variant's files, in the variants' order (the inputs' `trials`, by variant)
        files=[robot_test_files(run, "trials.csv") for run in PLAN.robot_runs],
        own=MAIN,
    log:
        "data/logs/robot/summary.log",
    benchmark:
        "data/benchmarks/robot_summary.tsv"
    script:
        "../scripts/robot_summary.py"


rule robot_confirmation:
    """Explore, then confirm: each confirmed variant's share of grasping trials held (each
    network and object once) on fresh networks and, where this build tests it there (full
    scale, or an entry of robot.default), on the networks it was chosen on, with an interval
    that takes a network's four objects as one cluster; and the fresh networks' robot trials
    joined."""
    input:
        trials=rules.robot_summary.output.trials,
        confirmation=[
            f for run in PLAN.confirmation_runs for f in robot_test_files(run, "trials.csv")
        ],
        code=script_code("robot_confirmation"),
    output:
        table="data/embodied/confirmation.csv",
        trials="data/embodied/confirmation_trials.csv",
    params:
        confirmation=PLAN.confirmation_tested,  # exploration None: not tested in this build
        # each confirmation's files, in its order (the inputs' `confirmation`, by run)
        files=[robot_test_files(run, "trials.csv") for run in PLAN.confirmation_runs],
        variant_keys=list(NetworkVariant.keys()),
    log:
        "data/logs/robot/confirmation.log",
    benchmark:
        "data/benchmarks/robot_confirmation.tsv"
    script:
        "../scripts/robot_confirmation.py"


rule robot_contact_time:
    """The declared contact-time test on the fresh networks (config
    robot.confirmation.contact_time): per confirmed variant, the congruency effect on the time
    until the required grip's fingers touch, over the networks that touched in all four cells,
    Holm over the variants; and per cell the trials and how many touched
    (icub_affordance.analysis.contact)."""
    input:
        trials=rules.robot_confirmation.output.trials,
        code=script_code("robot_contact_time"),
    output:
        tests="data/embodied/contact_time.csv",
        cells="data/embodied/contact_time_cells.csv",
    params:
        declaration=settings(config["robot"]["confirmation"]["contact_time"]),
    log:
        "data/logs/robot/contact_time.log",
    benchmark:
        "data/benchmarks/robot_contact_time.tsv"
    script:
        "../scripts/robot_contact_time.py"


rule robot_contact_time_split:
    """Where the declared contact-time congruency comes from (issue 70; exploration, added after
    results, Holm within its own family): per mapping, per mapping x size (the incongruent
    object against the congruent one of its size) and the mappings' difference, on the declared
    test's networks (icub_affordance.analysis.contact.congruency_split)."""
    input:
        trials=rules.robot_confirmation.output.trials,
        code=script_code("robot_contact_time_split"),
    output:
        "data/embodied/contact_time_split.csv",
    params:
        declaration=settings(config["robot"]["confirmation"]["contact_time"]),
    log:
        "data/logs/robot/contact_time_split.log",
    benchmark:
        "data/benchmarks/robot_contact_time_split.tsv"
    script:
        "../scripts/robot_contact_time_split.py"


rule robot_filmstrip:
    """A congruent and an incongruent categorisation trial of the same object, on the robot
    (render only)."""
    input:
        states=robot_test_files(MAIN, "states.npz", FILM_NETWORKS),
        # each film network's own trials, not the joined table: the picture need not wait
        # for the other networks
        trials=robot_test_files(MAIN, "trials.csv", FILM_NETWORKS),
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("robot_filmstrip"),
    output:
        "data/figures/robot_filmstrip.png",
    params:
        networks=FILM_NETWORKS,
        pick=settings(config["figures"]["embodied"]),
        object_sizes=settings(config["object_sizes_m"]),
    resources:
        mem_mb=1000,
    log:
        "data/logs/robot/filmstrip.log",
    benchmark:
        "data/benchmarks/robot_filmstrip.tsv"
    script:
        "../scripts/robot_filmstrip.py"


rule robot_variants_figure:
    """The robot variants' success against training iterations, and against the palm's error
    beside the body's tolerance (plot only)."""
    input:
        variants=rules.robot_summary.output.variants,
        tolerance=rules.robot_tolerance.output[0],
        code=script_code("robot_variants_figure"),
    output:
        variants="data/figures/robot_variants.png",
        tolerance="data/figures/robot_tolerance.png",
    log:
        "data/logs/robot/variants_figure.log",
    benchmark:
        "data/benchmarks/robot_variants_figure.tsv"
    script:
        "../scripts/robot_variants_figure.py"


# The variant the book animates (config robot.animation.variant) and its first network of each
# mapping: the config's own networks or an entry of robot.default on networks 0.., or a
# confirmed variant on its fresh networks (RunPlan.animated), each tested in every build.
ANIMATED_RUN, ANIMATED_NETWORKS = PLAN.animated(config["robot"]["animation"]["variant"])


rule robot_animation:
    """Films of the animated variant's first network of each mapping on the robot: grasping each
    object, and one object's congruent and incongruent categorisation (render only; each
    re-run trial is checked against the recorded one)."""
    input:
        unpack(lambda w: model_inputs({"folder": PLAN.folder(ANIMATED_RUN)})),
        weights=weights_files(ANIMATED_RUN, ANIMATED_NETWORKS),
        trials=robot_test_files(ANIMATED_RUN, "trials.csv", ANIMATED_NETWORKS),
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("robot_animation"),
    output:
        grasps="data/figures/robot_grasps.gif",
        categorise="data/figures/robot_categorise.gif",
    params:
        network=settings(PLAN.config(ANIMATED_RUN)["network"]),
        grip_distance=PLAN.config(ANIMATED_RUN)["grip_distance"],
        networks=[int(net) for net in ANIMATED_NETWORKS],
        demos=settings(config["demos"]),
        object_sizes=settings(config["object_sizes_m"]),
        object=config["robot"]["animation"]["object"],
        fps=config["robot"]["animation"]["fps"],
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/robot/animation.log",
    benchmark:
        "data/benchmarks/robot_animation.tsv"
    script:
        "../scripts/robot_animation.py"
