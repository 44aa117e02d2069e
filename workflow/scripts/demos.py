"""A run's demonstrations in one job: every object made and checked in physics, one after
another, each on a freshly loaded robot, then joined with their summary."""

from icub_affordance.body.demonstrations import DemoConfig, merge_demos, object_demos, summary_csv
from icub_affordance.body.robot import Robot, check_posture_deg
from icub_affordance.files import redirect_log, save_npz, write_text

with redirect_log(snakemake.log[0]):
    initial = check_posture_deg(snakemake.params.posture, "config key initial_posture_deg")
    config = DemoConfig(**snakemake.params.demos)
    parts = {}
    for obj in snakemake.params.objects:
        robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
        parts[obj] = object_demos(robot, obj, initial, snakemake.params.seed, config)
        print(f"{obj}: attempts per demo {parts[obj]['attempts'].tolist()}")
    merged = merge_demos(parts)
    save_npz(snakemake.output.demos, **merged)
    write_text(snakemake.output.summary, summary_csv(merged, config))
