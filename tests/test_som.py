"""The three SOMs: one cluster per object, larger for large objects (from the input), 8 goals."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from conftest import som_config

from icub_affordance.files import load_npz
from icub_affordance.learning.maps import (
    active_units,
    object_activation,
    train_som,
    train_soms,
)


@pytest.fixture(scope="module")
def soms(built):
    return load_npz(built / "data" / "soms" / "soms.npz")


def test_maps_are_ten_by_ten(soms):
    assert soms["object_act"].shape == (4, 10, 10)
    assert soms["task_act"].shape == (2, 10, 10)
    assert soms["goal_act"].shape == (4, 2, 10, 10)
    for key in ("object_act", "task_act", "goal_act"):
        assert soms[key].min() >= 0.0 and soms[key].max() <= 1.0


def test_each_object_has_its_own_cluster(soms):
    winners = [tuple(w) for w in soms["object_winners"]]
    assert len(set(winners)) == 4


def test_large_objects_activate_more_units_than_small_ones(soms):
    objects = soms["objects"].tolist()
    units = {o: active_units(a) for o, a in zip(objects, soms["object_act"], strict=True)}
    for big, small in itertools.product(["big_ball", "big_cube"], ["small_ball", "small_cube"]):
        assert units[big] > units[small], units


def test_cluster_size_comes_from_the_input_not_the_name():
    """The same SOM, two synthetic inputs: the one with more edge cells lights up more units."""
    few = np.zeros((10, 10))
    few[4:6, 4:6] = 1
    many = np.zeros((10, 10))
    many[2:8, 2] = many[2:8, 7] = many[2, 2:8] = many[7, 2:8] = 1
    config = som_config(iterations=200)
    som = train_som(np.array([few.ravel(), many.ravel()]), config, seed=1)
    small = object_activation(som, few, config)
    large = object_activation(som, many, config)
    assert active_units(large) > active_units(small)


def test_goal_map_has_eight_distinct_patterns(soms):
    goals = soms["goal_act"].reshape(8, -1)
    winners = [tuple(w) for w in soms["goal_winners"].reshape(8, 2)]
    assert len(set(winners)) == 8
    for a, b in itertools.combinations(range(8), 2):
        assert np.abs(goals[a] - goals[b]).max() > 0.5


def test_the_two_task_patterns_differ(soms):
    assert not np.array_equal(soms["task_patterns"][0], soms["task_patterns"][1])
    assert np.abs(soms["task_act"][0] - soms["task_act"][1]).max() > 0.5


def test_soms_are_deterministic():
    maps = np.random.default_rng(3).integers(0, 2, (4, 10, 10))
    a = train_soms(maps, som_config(iterations=100), 5)
    b = train_soms(maps, som_config(iterations=100), 5)
    np.testing.assert_array_equal(a.goal_act, b.goal_act)


def outline_maps() -> np.ndarray:
    """Two large outlines (many edge cells) and two small ones, as the four objects' maps."""
    maps = np.zeros((4, 10, 10))
    maps[0, 1:9, 1] = maps[0, 1:9, 8] = maps[0, 1, 1:9] = maps[0, 8, 1:9] = 1  # big square
    maps[1, 4:6, 4:6] = 1  # small square
    maps[2, 2:8, 2] = maps[2, 2:8, 7] = maps[2, 2, 3:7] = maps[2, 7, 3:7] = 1  # big, rounder
    maps[3, 4, 4:7] = maps[3, 5, 4] = 1  # small, another shape
    return maps


def test_goal_response_changes_the_goal_activations_and_nothing_upstream():
    """Two readings that differ only in soms.goal_response: the same Object and Task maps (and
    the same Goal map weights, trained on their outputs); only what the Goal map sends on
    differs, and with `grows` a large object's Goal cluster is the larger."""
    maps = outline_maps()
    fixed = train_soms(maps, som_config(iterations=300, goal_response="fixed"), 7)
    grows = train_soms(maps, som_config(iterations=300, goal_response="grows"), 7)
    for field in vars(fixed):
        if field != "goal_act":
            np.testing.assert_array_equal(getattr(fixed, field), getattr(grows, field), field)
    assert not np.allclose(fixed.goal_act, grows.goal_act)
    # a bump of one width whatever the object (3-5 units, fewer at the map's edge)
    assert max(active_units(a) for a in fixed.goal_act.reshape(8, 10, 10)) <= 5

    def width(act, winner):
        """The bump's width, from its value one unit from the winner: exp(-1 / (2 width^2))."""
        row = winner[0] + 1 if winner[0] + 1 < act.shape[0] else winner[0] - 1
        return np.sqrt(-1 / (2 * np.log(act[row, winner[1]])))

    for task in range(2):
        widths = [width(grows.goal_act[o, task], grows.goal_winners[o, task]) for o in range(4)]
        assert min(widths[0], widths[2]) > max(widths[1], widths[3]), widths
        assert widths[0] > som_config().bump_sigma


def test_goal_response_is_checked():
    with pytest.raises(ValueError, match="goal_response"):
        som_config(goal_response="wide")
