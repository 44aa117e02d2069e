# The robot's visual input (paper section 2.2, Figure 3).


rule visual_maps:
    """Render each object on the spot, edge-filter, foveate and reduce to the 10x10 maps."""
    input:
        scene=config["scene"],
        scene_files=SCENE_FILES,  # the scene and the files it includes (the robot)
        code=script_code("visual_maps"),
    output:
        maps="data/vision/visual_maps.npz",
        stages="data/vision/vision_stages.npz",
    params:
        object_sizes=settings(config["object_sizes_m"]),
        vision=settings(config["vision"]),
        objects=settings(config["objects"]),
        posture=settings(config["initial_posture_deg"]),
    priority: 3  # every training waits on it: first
    resources:
        mem_mb=1000,
    log:
        "data/logs/visual_maps.log",
    benchmark:
        "data/benchmarks/visual_maps.tsv"
    script:
        "../scripts/visual_maps.py"


rule figure3:
    """Figure 3: eye image, Sobel edges and visual input for every object (plot only)."""
    input:
        stages=rules.visual_maps.output.stages,
        code=script_code("figure3"),
    output:
        "data/vision/figure3.png",
    params:
        window=config["vision"]["window"],
    log:
        "data/logs/figure3.log",
    benchmark:
        "data/benchmarks/figure3.tsv"
    script:
        "../scripts/figure3.py"
