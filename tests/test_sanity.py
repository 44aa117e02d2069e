"""Physical sanity checks where a result could be silently meaningless: objects the eye does not
see or cannot tell apart, networks whose outputs are NaN."""

from __future__ import annotations

import numpy as np
import pytest

from icub_affordance.body.vision import check_seen
from icub_affordance.learning.network import Weights
from icub_affordance.trials.in_silico import evaluate_network


def maps(**cells) -> dict[str, np.ndarray]:
    out = {}
    for name, ones in cells.items():
        m = np.zeros((10, 10), dtype=np.uint8)
        m.flat[list(ones)] = 1
        out[name] = m
    return out


def test_four_seen_and_different_maps_pass():
    check_seen(maps(big_ball=[1, 2], small_ball=[3], big_cube=[1, 2, 3], small_cube=[4]), 60)


def test_an_object_without_edge_cells_is_refused_naming_it_and_the_threshold():
    with pytest.raises(ValueError, match=r"no edge of \['small_ball'\].*edge_threshold = 1000"):
        check_seen(maps(big_ball=[1], small_ball=[], big_cube=[2], small_cube=[3]), 1000)


def test_two_equal_maps_are_refused_naming_the_pair():
    with pytest.raises(ValueError, match=r"\('big_ball', 'big_cube'\).*identical"):
        check_seen(maps(big_ball=[1], small_ball=[2], big_cube=[1], small_cube=[3]), 60)


def test_weights_with_nan_are_refused_naming_the_network():
    w = Weights.init(3, 0.5, np.random.default_rng(0))
    w.check_finite("network 03")
    w.W2[0, 0] = np.nan
    with pytest.raises(FloatingPointError, match=r"network 03: weights \['W2'\].*learning_rate"):
        w.check_finite("network 03")


def test_a_network_that_outputs_nan_fails_its_evaluation_naming_it(monkeypatch):
    import icub_affordance.trials.in_silico as evaluate

    class Setup:
        context = np.zeros((1, 2, 200))
        teacher = np.zeros((1, 3, 16))

    monkeypatch.setattr(evaluate.TrialSet, "of", classmethod(lambda cls, *a: Setup()))
    monkeypatch.setattr(
        evaluate, "run_closed_loop", lambda *a: (np.full((1, 3, 16), np.nan), np.zeros((1, 3, 2)))
    )
    with pytest.raises(FloatingPointError, match="network 07 outputs NaN"):
        evaluate_network(None, None, 7, "B", "first_step", "sensed")
