"""The hand can really grasp: 2.5 cm objects pinched, 7 cm objects wrapped, all lifted 5 cm.

These are physics runs of the scripted demonstrator with hand shapes chosen by hand for this
hand model; they show that the collision geometry, friction and servos hold real objects.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import initial_posture_deg

from icub_affordance.body.grasp import GraspPlan, execute_grasp, pinch_point
from icub_affordance.body.robot import TOUCH_NAMES, Robot

INITIAL = initial_posture_deg()  # config/config.yaml


@pytest.fixture(scope="module")
def robot():
    r = Robot()
    yield r
    r.close()


def touched(outcome, *sensors: str) -> bool:
    return all(outcome.touch[TOUCH_NAMES.index(f"touch_{s}")] > 0 for s in sensors)


@pytest.mark.parametrize("obj", ["small_cube", "small_ball"])
def test_pinch_lifts_a_small_object_between_thumb_and_index(robot, obj):
    contact = np.array([0, 75, 10, 10, 45, 20, 0, 0, 0], dtype=float)
    centre, gap = pinch_point(robot, contact)
    assert 0.03 < gap < 0.045  # the pads are one cube (+ pads) apart at contact
    plan = GraspPlan(
        object_in_palm=centre,
        preshape_deg=contact - [0, 0, 10, 10, 20, 0, 0, 0, 0],
        closed_deg=contact + [0, 0, 15, 15, 15, 15, 0, 0, 0],
        yaw_deg=30,
        tilt_deg=30,
    )
    outcome = execute_grasp(robot, obj, plan, INITIAL)
    assert outcome.palm_error < 0.01
    assert touched(outcome, "thumb", "index")
    assert any(g.startswith("r_thumb") for g in outcome.hand_contacts)
    assert any(g.startswith("r_index") for g in outcome.hand_contacts)
    assert outcome.lift_height > 0.04  # it rose with the hand: friction holds it


#: A power grasp of a big object: the wrap the tests below lift with and record.
POWER_PLAN = GraspPlan(
    object_in_palm=np.array([0.035, -0.01, 0.037]),
    preshape_deg=np.array([20, 75, 0, 0, 0, 0, 0, 0, 0], dtype=float),
    closed_deg=np.array([20, 75, 0, 90, 70, 70, 70, 70, 100], dtype=float),
    yaw_deg=35,
    tilt_deg=15,
)


@pytest.mark.parametrize("obj", ["big_ball", "big_cube"])
def test_power_grasp_wraps_and_lifts_a_big_object(robot, obj):
    plan = POWER_PLAN
    outcome = execute_grasp(robot, obj, plan, INITIAL)
    assert touched(outcome, "thumb")
    fingers = sum(touched(outcome, f) for f in ("index", "middle", "ring", "little"))
    assert fingers >= 3
    assert outcome.lift_height > 0.04


def test_a_grasp_in_free_air_lifts_nothing(robot):
    """The same power closure far above the object: no contact, so the lift test fails."""
    plan = GraspPlan(
        object_in_palm=np.array([0.01, 0.0, 0.12]),
        preshape_deg=np.array([0, 45, 0, 0, 0, 0, 0, 0, 0], dtype=float),
        closed_deg=np.array([0, 45, 50, 50, 80, 80, 80, 80, 100], dtype=float),
    )
    outcome = execute_grasp(robot, "big_cube", plan, INITIAL)
    assert not outcome.hand_contacts
    assert abs(outcome.lift_height) < 0.005


def test_recording_chosen_moments_keeps_the_full_traces_rows(robot):
    """The demonstrator records 10 moments, not every step (issue 71): the same rows to the bit;
    and a grasp not lifted, because its touch already failed it, says so with a NaN lift."""
    from icub_affordance.body.grasp import sample_steps

    plan = POWER_PLAN
    full = execute_grasp(robot, "big_ball", plan, INITIAL)
    kept = execute_grasp(robot, "big_ball", plan, INITIAL, record_steps=10)
    idx = sample_steps(len(full.postures_deg), 10)
    for name in ("postures_deg", "commands_deg", "touch_trace", "qpos_trace"):
        assert np.array_equal(getattr(kept, name), getattr(full, name)[idx]), name
    assert kept.lift_height == full.lift_height
    unlifted = execute_grasp(robot, "big_ball", plan, INITIAL, lift_if=lambda touch: False)
    assert np.array_equal(unlifted.touch, full.touch) and np.isnan(unlifted.lift_height)
