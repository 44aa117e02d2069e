"""The four 10x10 visual maps, and every stage of Figure 3, from the eye camera."""

from icub_affordance.body.robot import Robot, check_posture_deg
from icub_affordance.body.vision import VisionConfig, check_seen, visual_maps
from icub_affordance.files import redirect_log, save_npz

with redirect_log(snakemake.log[0]):
    config = VisionConfig(**snakemake.params.vision)
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    robot.set_posture_deg(
        check_posture_deg(snakemake.params.posture, "config key initial_posture_deg")
    )
    stages = visual_maps(robot, tuple(snakemake.params.objects), config)
    robot.close()
    for obj, s in stages.items():
        print(f"{obj}: {int(s.visual_map.sum())} edge cells")
    check_seen({obj: s.visual_map for obj, s in stages.items()}, config.edge_threshold)
    save_npz(snakemake.output.maps, **{obj: s.visual_map for obj, s in stages.items()})
    save_npz(
        snakemake.output.stages,
        **{
            f"{obj}__{part}": getattr(s, part)
            for obj, s in stages.items()
            for part in ("eye", "sobel", "edges", "visual_map")
        },
    )
