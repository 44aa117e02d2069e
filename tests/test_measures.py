"""The three measures of a trial (MODEL.md section 8), on hand-made trajectories."""

from __future__ import annotations

import numpy as np
import pytest

from icub_affordance.measures import grip_distance, time_to_commit

STEPS = 5  # step 0 (given) and 4 predicted steps, one DoF


def demo(values) -> np.ndarray:
    return np.array(values, dtype=float)[:, None]


REQUIRED = demo([0.5, 0.6, 0.7, 0.8, 0.9])  # rises
OTHER = demo([0.5, 0.4, 0.3, 0.2, 0.1])  # falls


@pytest.mark.parametrize(
    ("outputs", "expected"),
    [
        ([0.6, 0.7, 0.8, 0.9], 1),  # on the required grip from the first step
        ([0.4, 0.3, 0.6, 0.9], 3),  # starts toward the other grip, turns at step 3
        ([0.6, 0.4, 0.7, 0.8], 3),  # nearer, then not (step 2), then nearer for good
        ([0.6, 0.7, 0.8, 0.2], STEPS),  # ends at the other grip: never commits
        ([0.4, 0.3, 0.2, 0.1], STEPS),  # the other grip throughout
        ([0.5, 0.5, 0.5, 0.9], 4),  # a tie (equally far) is not nearer
    ],
)
def test_time_to_commit(outputs, expected):
    assert time_to_commit(demo(outputs), REQUIRED, OTHER) == expected


def test_time_to_commit_uses_every_dof():
    required = np.array([[0, 0], [1, 0], [1, 0]], dtype=float)
    other = np.array([[0, 0], [0, 1], [0, 1]], dtype=float)
    # step 1 nearer the other grip in the second DoF only, step 2 nearer the required one
    outputs = np.array([[0.6, 0.9], [0.9, 0.1]])
    assert time_to_commit(outputs, required, other) == 2


def test_time_to_commit_needs_matching_lengths():
    with pytest.raises(ValueError, match="one step fewer"):
        time_to_commit(demo([0.6, 0.7]), REQUIRED, OTHER)


def test_grip_distance_ignores_the_common_first_step():
    required = demo([0.5, 0.7, 0.9])
    other = demo([0.5, 0.3, 0.1])
    assert grip_distance(required, other) == pytest.approx(np.sqrt((0.4**2 + 0.8**2) / 2))
