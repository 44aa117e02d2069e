"""How the demonstrator's grasp templates were chosen: a grid search in physics (not in the DAG).

For a grip and an object size, each candidate hand shape is tried on both objects of that size at
the corners and centre of the demonstrator's yaw and pitch variation, and scored by how many of
those grasps pass the demonstration check (touch and lift). Run, for example:

    python tools/search_grasps.py power small

The winners are written into ``icub_affordance.body.demonstrations.grasp_template``; this
script documents the search so that a different hand model can be given its own templates.
"""

from __future__ import annotations

import argparse
import itertools
from pathlib import Path

import numpy as np
import yaml

from icub_affordance.body.demonstrations import DemoConfig, is_grasp
from icub_affordance.body.grasp import GraspPlan, cage_point, execute_grasp, pinch_point
from icub_affordance.body.robot import OBJECTS, Robot


def candidates(robot: Robot, grip: str, size: str):
    """(label, plan) pairs: the hand-shape families explored for each grip and size."""
    if grip == "power" and size == "large":
        for x, y, opp, thumb_p, thumb_d in itertools.product(
            [0.03, 0.035, 0.04], [-0.01, 0.0], [60, 75, 90], [0, 20, 40], [30, 60, 90]
        ):
            closed = np.array([20, opp, thumb_p, thumb_d, 70, 70, 70, 70, 100], dtype=float)
            pre = np.array([20, opp, 0, 0, 0, 0, 0, 0, 0], dtype=float)
            yield (
                (x, y, opp, thumb_p, thumb_d),
                GraspPlan(np.array([x, y, 0.037]), pre, closed, 35, 15),
            )
    elif grip == "precision":
        tilt = 30 if size == "small" else 15
        for opp, tf, ip, idist in itertools.product(
            range(45, 106, 15), range(0, 41, 10), range(0, 61, 15), range(0, 61, 10)
        ):
            contact = np.array([0, opp, tf, tf, ip, idist, 0, 0, 0], dtype=float)
            centre, gap = pinch_point(robot, contact)
            wanted = 0.038 if size == "small" else 0.083  # object width + two pads
            if abs(gap - wanted) > 0.005:
                continue
            opening = np.array([0, 0, 10, 10, 20, 0, 0, 0, 0], dtype=float)
            closed = contact + [0, 0, 15, 15, 15, 15, 0, 0, 0]
            yield (
                (opp, tf, ip, idist),
                GraspPlan(centre, np.maximum(contact - opening, 0), closed, 30, tilt),
            )
    else:  # power on a small object: the four fingers pulled together close with the thumb
        for opp, p, d, rl, tf in itertools.product(
            [90, 105], [30, 40, 50], [10, 20, 30], [20, 30, 40], [10, 20]
        ):
            contact = np.array([-20, opp, tf, tf, p, d, p, d, rl], dtype=float)
            opening = np.array([0, 0, 10, 10, 20, 20, 20, 20, 20], dtype=float)
            pre = np.maximum(contact - opening, [-20, -15, 0, 0, 0, 0, 0, 0, 0])
            closed = contact + [0, 0, 15, 15, 15, 15, 15, 15, 15]
            yield (opp, p, d, rl, tf), GraspPlan(cage_point(robot, contact), pre, closed, 30, 30)


def score(robot: Robot, grip: str, size: str, plan: GraspPlan, config: DemoConfig) -> int:
    objects = [name for name, info in OBJECTS.items() if info.size == size]
    initial = robot.keyframe_deg("initial")  # the demos' initial posture (config's, checked)
    passed = 0
    for obj, dyaw, dtilt in itertools.product(objects, [-5, 0, 5], [-5, 0, 5]):
        trial = GraspPlan(
            plan.object_in_palm,
            plan.preshape_deg,
            plan.closed_deg,
            plan.yaw_deg + dyaw,
            plan.tilt_deg + dtilt,
        )
        outcome = execute_grasp(robot, obj, trial, initial, lift=config.lift_m)
        passed += is_grasp(grip, outcome.touch, outcome.lift_height, config)
    return passed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("grip", choices=["power", "precision"])
    parser.add_argument("size", choices=["large", "small"])
    args = parser.parse_args()
    settings = yaml.safe_load((Path(__file__).parents[1] / "config" / "config.yaml").read_text())
    robot, config = Robot(), DemoConfig(**settings["demos"])
    results = []
    for label, plan in candidates(robot, args.grip, args.size):
        results.append((score(robot, args.grip, args.size, plan, config), label))
        print(f"{label}: {results[-1][0]}/18", flush=True)
    best = max(results)
    print(f"best: {best[1]} passes {best[0]}/18")


if __name__ == "__main__":
    main()
