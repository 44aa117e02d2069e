# Demonstration grasps (paper sections 2.3 and 3): the sequences the network learns from. For the
# config's own run a job per object (the other runs: runs.smk, run_demos).


rule demos_object:
    """Every grip and sequence of one object, made and checked in physics (one job per object)."""
    input:
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("demos_object"),
    output:
        "data/{folder}demos/parts/{object}.npz",
    params:
        object_sizes=settings(config["object_sizes_m"]),
        demos=settings(config["demos"]),
        seed=run_section("seed"),
        posture=settings(config["initial_posture_deg"]),
    wildcard_constraints:
        object="|".join(config["objects"]),
        folder=folders_pattern([run for run in PLAN.runs if PLAN.jobs_per_network(run)]),
    priority: 3  # every training waits on it: first
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/{folder}demos_object/{object}.log",
    benchmark:
        "data/benchmarks/{folder}demos_object/{object}.tsv"
    script:
        "../scripts/demos_object.py"


rule demos:
    """The 4 x 2 x 5 demonstrations in one file, and a readable summary."""
    input:
        parts=lambda w: [
            PLAN.path(run_of(w), f"demos/parts/{obj}.npz") for obj in config["objects"]
        ],
        code=script_code("demos_merge"),
    output:
        demos="data/{folder}demos/demos.npz",
        summary="data/{folder}demos/summary.csv",
    wildcard_constraints:
        folder=folders_pattern([run for run in PLAN.runs if PLAN.jobs_per_network(run)]),
    params:
        objects=settings(config["objects"]),
        demos=settings(config["demos"]),
    priority: 3  # every training waits on it: first
    log:
        "data/logs/{folder}demos.log",
    benchmark:
        "data/benchmarks/{folder}demos.tsv"
    script:
        "../scripts/demos_merge.py"


rule demo_filmstrip:
    """Filmstrips of chosen demonstrations, replayed from their recorded states (render only)."""
    input:
        demos=PLAN.path(OWN, "demos/demos.npz"),
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
