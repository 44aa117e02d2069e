"""The eyes see the object on the spot, near the centre of the image (they foveate it)."""

from __future__ import annotations

import numpy as np
import pytest

from icub_affordance.body.robot import OBJECT_NAMES

W, H = 160, 120


@pytest.fixture(scope="module")
def eye_images():
    import mujoco

    from icub_affordance.body.robot import Robot

    robot = Robot()
    images = {}
    for eye in ("left_eye", "right_eye"):
        for name in OBJECT_NAMES:
            robot.place_object(name)
            images[eye, name] = robot.render(eye, W, H)
            # the same view (same gaze) with the object taken away: the empty table
            adr = robot.object_qpos[name]
            robot.data.qpos[adr : adr + 3] = robot.model.body(name).pos
            mujoco.mj_forward(robot.model, robot.data)
            images[eye, name, "empty"] = robot.render(eye, W, H)
    robot.close()
    return images


def object_mask(images, eye, name) -> np.ndarray:
    with_object = images[eye, name].astype(int)
    empty = images[eye, name, "empty"].astype(int)
    return np.abs(with_object - empty).sum(axis=2) > 60


@pytest.mark.parametrize("eye", ["left_eye", "right_eye"])
@pytest.mark.parametrize("name", OBJECT_NAMES)
def test_object_is_near_the_image_centre(eye_images, eye, name):
    image = eye_images[eye, name]
    assert image.shape == (H, W, 3) and image.dtype == np.uint8
    mask = object_mask(eye_images, eye, name)
    assert mask.sum() > 10, "object not visible"
    rows, cols = np.nonzero(mask)
    # the object itself, not its shadow: its own colour dominates the changed pixels
    assert abs(cols.mean() - W / 2) < 0.12 * W
    assert abs(rows.mean() - H / 2) < 0.15 * H


def test_big_objects_look_bigger(eye_images):
    area = {n: object_mask(eye_images, "left_eye", n).sum() for n in OBJECT_NAMES}
    assert area["big_ball"] > 3 * area["small_ball"]
    assert area["big_cube"] > 3 * area["small_cube"]
