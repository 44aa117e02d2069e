"""The demonstration grasps: 40 real, touch-checked grasps that differ where they should."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import demo_config, initial_posture_deg

from icub_affordance.body.demonstrations import is_grasp, make_demo, object_demos
from icub_affordance.body.robot import (
    DOF_NAMES,
    OBJECT_NAMES,
    OBJECTS,
    TOUCH_NAMES,
    Robot,
    to_normalised,
)
from icub_affordance.files import load_npz
from icub_affordance.vocabulary import GRIPS

INITIAL = initial_posture_deg()  # config/config.yaml
T = {name: i for i, name in enumerate(TOUCH_NAMES)}


@pytest.fixture(scope="module")
def demos(built):
    return load_npz(built / "data" / "demos" / "demos.npz")


def test_forty_sequences_of_ten_steps_normalised(demos):
    assert demos["angles"].shape == (4, 2, 5, 10, 16)
    assert demos["angles_deg"].shape == (4, 2, 5, 10, 16)
    assert demos["touch"].shape == (4, 2, 5, 10, 6)
    assert demos["objects"].tolist() == list(OBJECT_NAMES)
    assert demos["grips"].tolist() == ["power", "precision"]
    assert demos["dofs"].tolist() == list(DOF_NAMES)
    assert demos["angles"].min() >= 0.0 and demos["angles"].max() <= 1.0
    np.testing.assert_allclose(demos["angles"], to_normalised(demos["angles_deg"]))


def test_every_final_posture_really_grasps(demos):
    final = demos["touch"][:, :, :, -1]
    config = demo_config()
    for o, obj in enumerate(OBJECT_NAMES):
        for s in range(5):
            power, precision = final[o, 0, s], final[o, 1, s]
            assert power[T["touch_thumb"]] > 0.01, (obj, s)
            fingers = (
                power[[T["touch_index"], T["touch_middle"], T["touch_ring"], T["touch_little"]]]
                > 0.01
            ).sum()
            assert power[T["touch_palm"]] > 0.01 or fingers >= 3, (obj, s)
            assert precision[T["touch_thumb"]] > 0.01 and precision[T["touch_index"]] > 0.01
    assert (demos["lift_m"] >= config.min_lift_m).all()  # each object rose with the hand


def test_all_sequences_start_from_one_common_posture(demos):
    """book/notes.md, "The demonstrations": the grip must not show at step 0."""
    first = demos["angles"][:, :, :, 0].reshape(-1, 16)
    np.testing.assert_allclose(first - first[0], 0.0, atol=1e-9)


def test_sequences_of_one_object_and_grip_differ_in_the_final_hand_pose(demos):
    for o in range(4):
        for g in range(2):
            poses = np.column_stack(
                [demos["yaw_deg"][o, g], demos["tilt_deg"][o, g], demos["palm_in_object"][o, g]]
            )
            for a in range(5):
                for b in range(a + 1, 5):
                    assert not np.allclose(poses[a], poses[b])
            finals = demos["angles"][o, g, :, -1, :7]
            assert np.ptp(finals, axis=0).max() > 0.01  # the arm ends in different postures


def test_power_and_precision_differ_in_the_fingers(demos):
    hand = slice(7, 16)
    for o in range(4):
        power = demos["angles_deg"][o, 0, :, -1, hand].mean(axis=0)
        precision = demos["angles_deg"][o, 1, :, -1, hand].mean(axis=0)
        others = [
            DOF_NAMES.index(n) - 7 for n in ("middle_proximal", "middle_distal", "ring_little")
        ]
        # precision leaves the middle, ring and little fingers open; power closes them
        assert power[others].sum() > precision[others].sum() + 60, DOF_NAMES


@pytest.mark.heavy
def test_demos_are_the_same_on_every_run():
    robot = Robot()
    config = demo_config(sequences=2)
    a = object_demos(robot, "small_cube", INITIAL, 7, config)
    b = object_demos(robot, "small_cube", INITIAL, 7, config)
    for key in a:
        np.testing.assert_array_equal(a[key], b[key], err_msg=key)
    c = object_demos(robot, "small_cube", INITIAL, 8, config)  # another seed, other variations
    assert not np.array_equal(a["yaw_deg"], c["yaw_deg"])


def test_grasp_check():
    config = demo_config()
    touch = np.zeros(6)
    assert not is_grasp("precision", touch, 0.05, config)
    touch[[T["touch_thumb"], T["touch_index"]]] = 1.0
    assert is_grasp("precision", touch, 0.05, config)
    assert not is_grasp("precision", touch, 0.0, config)  # it did not come up with the hand
    assert not is_grasp("power", touch, 0.05, config)  # thumb + one finger is no power grip
    touch[T["touch_middle"]] = touch[T["touch_ring"]] = 1.0
    assert is_grasp("power", touch, 0.05, config)
    only_palm = np.zeros(6)
    only_palm[[T["touch_thumb"], T["touch_palm"]]] = 1.0
    assert is_grasp("power", only_palm, 0.05, config)


def test_a_demo_that_cannot_grasp_fails_with_its_name():
    config = demo_config(max_attempts=1, lift_m=0.05, min_lift_m=0.05, touch_threshold=1e6)
    with pytest.raises(RuntimeError, match="small_ball/precision/sequence 3"):
        make_demo(Robot(), "small_ball", "precision", 3, INITIAL, 1, config, "small")


def test_inconsistent_lift_settings_are_refused():
    with pytest.raises(ValueError, match="min_lift_m"):
        demo_config(lift_m=0.02, min_lift_m=0.03)


@pytest.mark.parametrize("obj", OBJECT_NAMES)
def test_object_table_follows_the_paper(obj):
    info = OBJECTS[obj]
    assert info.category == ("natural" if "ball" in obj else "artefact")
    assert info.size == ("large" if obj.startswith("big") else "small")
    assert info.natural_grip == ("power" if info.size == "large" else "precision")
    assert GRIPS == ("power", "precision")
