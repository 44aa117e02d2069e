"""Make and check every demonstration of one object in physics."""

from icub_affordance.body import Robot, check_posture_deg
from icub_affordance.demos import DemoConfig, object_demos
from icub_affordance.io import redirect_log, save_npz

with redirect_log(snakemake.log[0]):
    obj = snakemake.wildcards.object
    initial = check_posture_deg(snakemake.params.posture, "config key initial_posture_deg")
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    arrays = object_demos(
        robot, obj, initial, snakemake.params.seed, DemoConfig(**snakemake.params.demos)
    )
    save_npz(snakemake.output[0], **arrays)
    print(f"{obj}: attempts per demo {arrays['attempts'].tolist()}")
