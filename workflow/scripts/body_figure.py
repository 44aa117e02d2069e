"""Figure 1: render the robot at the table and the eye view; the joint table from the model."""

import csv
import io

from icub_affordance.body.robot import Robot, check_posture_deg
from icub_affordance.files import redirect_log, write_png, write_text

with redirect_log(snakemake.log[0]):
    posture = check_posture_deg(snakemake.params.posture, "config key initial_posture_deg")
    figure = snakemake.params.figure
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    robot.place_object(figure["object"])
    robot.set_posture_deg(posture)
    size = dict(width=figure["width"], height=figure["height"])
    write_png(snakemake.output.scene, robot.render("overview", **size))
    write_png(snakemake.output.eye, robot.render("left_eye", **size))

    rows = robot.joint_table()
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(rows[0]), lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    write_text(snakemake.output.table, buffer.getvalue())
    robot.close()
