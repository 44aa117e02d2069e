# Demonstration grasps (paper sections 2.3 and 3): the sequences the network learns from. A run
# makes its own demonstrations only if their settings differ from an earlier run's (a new seed);
# otherwise it reads that run's (PLAN.stage_run).


rule demos:
    """A run's 4 x 2 x 5 demonstrations, each object's made and checked in physics on a freshly
    loaded robot, in one file, and a readable summary (one job per run)."""
    input:
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("demos"),
    output:
        demos="data/{folder}demos/demos.npz",
        summary="data/{folder}demos/summary.csv",
    params:
        objects=settings(config["objects"]),
        object_sizes=settings(config["object_sizes_m"]),
        demos=settings(config["demos"]),
        seed=run_section("seed"),
        posture=settings(config["initial_posture_deg"]),
    # every map and training waits on it: first, the config's own run's before all (the robot
    # test's long chain starts from it)
    priority: lambda wildcards: 3 if run_of(wildcards) == MAIN else 2
    resources:
        mem_mb=1000,
        runtime=20,
    log:
        "data/logs/{folder}demos.log",
    benchmark:
        "data/benchmarks/{folder}demos.tsv"
    script:
        "../scripts/demos.py"


rule demo_filmstrip:
    """Filmstrips of chosen demonstrations, replayed from their recorded states (render only)."""
    input:
        demos=PLAN.path(MAIN, "demos/demos.npz"),
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("demo_filmstrip"),
    output:
        "data/demos/filmstrip.png",
    params:
        object_sizes=settings(config["object_sizes_m"]),
        picks=config["figures"]["filmstrip"],
    resources:
        mem_mb=1000,
    log:
        "data/logs/demo_filmstrip.log",
    benchmark:
        "data/benchmarks/demo_filmstrip.tsv"
    script:
        "../scripts/demo_filmstrip.py"
