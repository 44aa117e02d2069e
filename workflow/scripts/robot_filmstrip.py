"""A congruent and an incongruent categorisation trial of one object, as the robot moved."""

from icub_affordance.body.robot import Robot
from icub_affordance.figures import filmstrip
from icub_affordance.files import redirect_log
from icub_workflow.parts import load_robot_states, load_robot_trials, network_trials

with redirect_log(snakemake.log[0]):
    obj, seq = snakemake.params.pick["object"], int(snakemake.params.pick["sequence"])
    robot = Robot(snakemake.input.scene, snakemake.params.object_sizes)
    strips = {}
    trials = load_robot_trials(snakemake.input.trials, keep_default_na=False)
    postures = load_robot_states(snakemake.input.states)
    for net in snakemake.params.networks:
        mine = network_trials(trials, int(net))  # this network's, in its postures' order
        hit = mine[
            (mine["task"] == "categorisation") & (mine["object"] == obj) & (mine["sequence"] == seq)
        ]
        if len(hit) != 1:
            raise ValueError(
                f"no single categorisation trial of {obj}, sequence {seq}, network {net}"
            )
        row = hit.iloc[0]
        # pandas reads a column of True and False as booleans, one with blanks as text
        kind = "congruent" if str(row["congruent"]) == "True" else "incongruent"
        outcome = "held" if str(row["success"]) == "True" else "not held"
        title = (
            f"{kind}, network {int(net)}: categorise {obj.replace('_', ' ')} with a "
            f"{row['target_grip']} grip; touch reads {row['grip_used']}, {outcome}"
        )
        states = postures[int(net)][hit.index[0]]
        # every other step, the last step, and the state after the lift test
        frames = [*range(0, len(states) - 2, 2), len(states) - 2, len(states) - 1]
        strips[title] = [robot.render_state(states[k], "closeup", 320, 240) for k in frames]
    robot.close()
    labels = [f"step {k}" for k in frames[:-1]] + ["lift test"]
    filmstrip(strips, snakemake.output[0], labels=labels)
