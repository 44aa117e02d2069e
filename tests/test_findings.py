"""The findings: the verdicts and statistics the book reports, on hand-made inputs."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pandas as pd
import pytest

from icub_affordance import findings
from icub_affordance.findings import Verdict, verdict


def analysis(congruent, incongruent, large, small, p_congruency, p_size):
    """One test mode as anova.json holds it (only what the verdicts read)."""
    means = {"congruent": congruent, "incongruent": incongruent, "large": large, "small": small}
    rm = {"congruency": {"p": p_congruency}, "size": {"p": p_size}}
    return {"means": means, "repeated_measures": rm}


# -- the verdict: direction and p < 0.05, defined once ------------------------------------------


@pytest.mark.parametrize(
    ("congruent", "incongruent", "p", "direction", "significant"),
    [
        (0.10, 0.12, 0.01, True, True),  # the paper's result
        (0.10, 0.12, 0.20, True, False),  # its direction, not significant
        (0.12, 0.10, 0.01, False, True),  # significantly reversed
        (0.12, 0.10, 0.20, False, False),
        (0.10, 0.10, 0.01, False, True),  # equal means are not the paper's direction
        (0.10, 0.12, 0.05, True, False),  # p must be below 0.05, not at it
        (0.10, 0.12, 0.0499, True, True),
        (0.10, 0.12, float("nan"), True, False),  # an undefined p is not significant
    ],
)
def test_the_congruency_verdict(congruent, incongruent, p, direction, significant):
    v = verdict(analysis(congruent, incongruent, 0.1, 0.1, p, 0.5), "congruency")
    assert v == Verdict(paper_direction=direction, significant=significant)
    assert v.reproduced == (direction and significant)
    assert v.reversed == (significant and not direction)


def test_the_size_verdict_reads_the_size_means_and_p():
    # congruency says one thing, size another: each verdict reads its own effect
    m = analysis(0.10, 0.12, 0.15, 0.11, 0.001, 0.03)
    assert verdict(m, "size") == Verdict(paper_direction=False, significant=True)
    assert verdict(m, "size").reversed and verdict(m, "congruency").reproduced
    m = analysis(0.10, 0.12, 0.11, 0.15, 0.9, 0.03)
    assert verdict(m, "size").reproduced and not verdict(m, "congruency").significant


def test_without_an_anova_nothing_is_significant():
    """The robot measures' ANOVA is None where every network scored the same in every cell."""
    m = {"means": {"congruent": 0.2, "incongruent": 0.3}, "repeated_measures": None}
    assert verdict(m, "congruency") == Verdict(paper_direction=True, significant=False)


@pytest.mark.parametrize(
    ("main", "ablation", "decides"),
    [
        (("first_step", True), ("all_steps", False), True),
        (("all_steps", False), ("first_step", True), True),  # the same, with the roles swapped
        (("first_step", True), ("all_steps", True), False),
        (("first_step", False), ("all_steps", False), False),
        (("all_steps", True), ("first_step", False), False),  # the other way round
    ],
)
def test_the_cue_timing_decides_only_when_first_step_alone_shows_the_effect(
    main, ablation, decides
):
    assert findings.cue_timing_decides(dict([main, ablation])) is decides


@pytest.mark.parametrize(
    ("n", "mean", "low", "high", "direction"),
    [
        (10, 0.03, 0.02, 0.04, "paper"),
        (10, -0.03, -0.04, -0.02, "against"),
        (10, 0.01, -0.01, 0.03, "unclear"),
        (10, 0.01, 0.0, 0.03, "unclear"),  # an interval touching 0 does not exclude it
        (1, -0.02, float("nan"), float("nan"), "single"),
    ],
)
def test_an_effect_over_replications_by_its_interval(n, mean, low, high, direction):
    assert findings.interval_direction(n, mean, low, high) == direction


def test_the_robot_verdicts():
    emb = {
        "success_rate": 0.3,
        "categorisation_success": 0.05,
        "replay_success": {"commands": 1.0, "sensed_postures": 0.5},
    }
    assert findings.robot_verdicts(emb) == {"below_ceiling": True, "at_floor": True}
    emb |= {"success_rate": 0.5, "categorisation_success": 0.1}
    assert findings.robot_verdicts(emb) == {"below_ceiling": False, "at_floor": False}


# -- the statistics ------------------------------------------------------------------------------

OBJECTS = ["big_ball", "small_ball", "big_cube", "small_cube"]


def test_the_grip_distance_of_a_made_up_demonstration_set():
    """Two grips a known distance apart at every step after the first; the first step (the
    common starting posture) is made far apart on purpose and must not count."""
    angles = np.zeros((4, 2, 5, 10, 16))
    angles[:, 1, :, 0] = 0.9  # step 0: excluded
    angles[[0, 2], 1, :, 1:] = 0.3  # large objects: precision 0.3 from power on every DoF
    angles[[1, 3], 1, :, 1:] = 0.1
    gap = findings.grip_distance(angles, OBJECTS)
    assert gap["large"] == pytest.approx(0.3) and gap["small"] == pytest.approx(0.1)


def grip_distance_by_hand(angles, objects, size):
    """The root mean square difference between the grips, summed term by term."""
    total, count = 0.0, 0
    for o, name in enumerate(objects):
        if name.startswith("big") != (size == "large"):
            continue
        for seq, step, dof in itertools.product(
            range(angles.shape[2]), range(1, angles.shape[3]), range(angles.shape[4])
        ):
            total += (angles[o, 0, seq, step, dof] - angles[o, 1, seq, step, dof]) ** 2
            count += 1
    return math.sqrt(total / count)


def test_the_grip_distance_of_random_demonstrations_equals_a_hand_count():
    angles = np.random.default_rng(3).random((4, 2, 3, 6, 5))
    objects = ["small_cube", "big_ball", "big_cube", "small_ball"]  # any order
    gap = findings.grip_distance(angles, objects)
    for size in ("large", "small"):
        assert gap[size] == pytest.approx(grip_distance_by_hand(angles, objects, size), rel=1e-12)


def test_the_learning_curve_summary():
    iterations = np.arange(3000, dtype=float)
    curves = np.stack([iterations, iterations + 2])  # two networks, mean = iteration + 1
    s = findings.curve_summary(curves, phase1_iterations=1500)
    assert s["n_networks"] == 2 and s["at"] == 2000
    assert s["start"] == pytest.approx(np.mean(np.arange(10)) + 1)
    assert s["around_at"] == pytest.approx(np.mean(np.arange(1900, 2100)) + 1)
    assert s["phase1_end"] == pytest.approx(np.mean(np.arange(1000, 1500)) + 1)
    assert s["end"] == pytest.approx(np.mean(np.arange(2500, 3000)) + 1)
    # a short run: the moment "around 2000" moves to 100 before the end
    assert findings.curve_summary(curves[:, :1200], 600)["at"] == 1100


def test_the_demonstration_counts():
    summary = pd.DataFrame({"attempts": [1, 3, 1, 2], "lift_m": [0.05, 0.049, 0.051, 0.05]})
    assert findings.demo_counts(summary) == {
        "n_demos": 4,
        "n_attempts": 7,
        "n_retried": 2,
        "lift_min_cm": pytest.approx(4.9),
    }


def test_the_joint_counts():
    joints = pd.DataFrame({"driven_joints": ["a"] * 7 + ["b c", "d", "e f g"]})
    assert findings.joint_counts(joints) == {"n_dof": 10, "n_driven": 13, "n_hand_driven": 6}
