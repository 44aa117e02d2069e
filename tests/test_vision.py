"""The visual input of Figure 3: binary 10x10 edge maps that carry each object's size and shape."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from conftest import initial_posture_deg

from icub_affordance.body.robot import OBJECT_NAMES, Robot
from icub_affordance.body.vision import VisionConfig, foveate, sobel_rgb, to_map, visual_maps

INITIAL = initial_posture_deg()  # config/config.yaml


def compute_maps() -> dict[str, np.ndarray]:
    robot = Robot()
    robot.set_posture_deg(INITIAL)
    stages = visual_maps(robot, OBJECT_NAMES, VisionConfig())
    robot.close()
    return {obj: s.visual_map for obj, s in stages.items()}


@pytest.fixture(scope="module")
def maps():
    return compute_maps()


def test_maps_are_binary_ten_by_ten(maps):
    for vmap in maps.values():
        assert vmap.shape == (10, 10)
        assert set(np.unique(vmap)) <= {0, 1}


def test_big_objects_have_more_edge_cells_spread_wider(maps):
    def spread(vmap):
        rows, cols = np.nonzero(vmap)
        return max(np.ptp(rows), np.ptp(cols))

    for shape in ("ball", "cube"):
        big, small = maps[f"big_{shape}"], maps[f"small_{shape}"]
        assert big.sum() > small.sum()
        assert spread(big) > spread(small)


def test_the_four_maps_are_pairwise_different(maps):
    for a, b in itertools.combinations(OBJECT_NAMES, 2):
        assert not np.array_equal(maps[a], maps[b]), (a, b)


def test_maps_are_the_same_on_every_run(maps):
    again = compute_maps()
    for obj in OBJECT_NAMES:
        np.testing.assert_array_equal(maps[obj], again[obj])


def test_sobel_finds_the_outline_of_a_coloured_square():
    image = np.full((60, 60, 3), 200, dtype=np.uint8)
    image[20:40, 20:40] = (200, 30, 30)  # differs from the background in G and B only
    magnitude = sobel_rgb(image)
    assert magnitude[30, 20] > 60 and magnitude[20, 30] > 60  # on the border
    assert magnitude[30, 30] == 0 and magnitude[5, 5] == 0  # inside and outside
    edges = (foveate(magnitude, 50) >= 60).astype(np.uint8)
    vmap = to_map(edges, 10)
    assert vmap.sum() > 0 and vmap[5, 5] == 0  # a ring of cells, empty in the middle


def test_bad_vision_settings_are_refused():
    with pytest.raises(ValueError, match="multiple of grid"):
        VisionConfig(window=95, grid=10)
    with pytest.raises(ValueError, match="fit"):
        VisionConfig(width=64, height=64, window=100)
