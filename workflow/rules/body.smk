# The simulated iCub (paper section 2.1, Figure 1).


rule body_figure:
    """Figure 1: the robot at the table in its initial posture, the eye's view, the joint table."""
    input:
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("body_figure"),
    output:
        scene="data/body/figure1_scene.png",
        eye="data/body/figure1_eye.png",
        table="data/body/joint_table.csv",
    params:
        object_sizes=settings(config["object_sizes_m"]),
        posture=settings(config["initial_posture_deg"]),
        figure=settings(config["body_figure"]),
    resources:
        mem_mb=1000,
    log:
        "data/logs/body_figure.log",
    benchmark:
        "data/benchmarks/body_figure.tsv"
    script:
        "../scripts/body_figure.py"
