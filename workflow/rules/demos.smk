# Demonstration grasps (paper sections 2.3 and 3): the sequences the network learns from.


rule demos_object:
    """Every grip and sequence of one object, made and checked in physics (one job per object)."""
    input:
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("demos_object"),
    output:
        "data/demos/parts/{object}.npz",
    params:
        object_sizes=settings(config["object_sizes_m"]),
        demos=settings(config["demos"]),
        seed=run_section("seed"),
        posture=settings(config["initial_posture_deg"]),
    wildcard_constraints:
        object="|".join(config["objects"]),
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    log:
        "data/logs/demos_object/{object}.log",
    benchmark:
        "data/benchmarks/demos_object/{object}.tsv"
    script:
        "../scripts/demos_object.py"


rule demos:
    """The 4 x 2 x 5 demonstrations in one file, and a readable summary."""
    input:
        parts=lambda w: [
            f"{run_dir(run_of(w))}/demos/parts/{obj}.npz" for obj in config["objects"]
        ],
        code=script_code("demos_merge"),
    output:
        demos="data/demos/demos.npz",
        summary="data/demos/summary.csv",
    params:
        objects=settings(config["objects"]),
        demos=settings(config["demos"]),
    threads: 1
    resources:
        mem_mb=500,
        runtime=5,
    log:
        "data/logs/demos.log",
    benchmark:
        "data/benchmarks/demos.tsv"
    script:
        "../scripts/demos_merge.py"


rule demo_filmstrip:
    """Filmstrips of chosen demonstrations, replayed from their recorded states (render only)."""
    input:
        demos=rules.demos.output.demos,
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("demo_filmstrip"),
    output:
        "data/demos/filmstrip.png",
    params:
        object_sizes=settings(config["object_sizes_m"]),
        picks=config["figures"]["filmstrip"],
    threads: 1
    resources:
        mem_mb=1000,
        runtime=5,
    log:
        "data/logs/demo_filmstrip.log",
    benchmark:
        "data/benchmarks/demo_filmstrip.tsv"
    script:
        "../scripts/demo_filmstrip.py"
