"""The statistics the book reports that the rules `robot_statistics` and `cue_difference` compute
(and the few the findings compute from the outputs), recomputed independently: the exact McNemar
test against scipy's binomial test and by hand, the cue timings' difference against the paired
test of the per-network contrasts and the robot's tables by hand on made-up trials. The book's
machinery only formats them."""

from __future__ import annotations

import json
from math import comb

import numpy as np
import pandas as pd
import pytest
from scipy import stats as sps
from test_contrasts import synthetic
from test_robot_variants import trials as robot_trials

from icub_affordance.analysis.robot_effects import (
    PALM_BINS_MM,
    grasping_trials,
    record_table,
    replay_palm,
    robot_statistics,
    table_record,
)
from icub_affordance.analysis.statistics import mcnemar_exact
from icub_affordance.analysis.trial_effects import cue_timing_difference, difference_tests
from icub_affordance.analysis.verdicts import robot_effect_statistics, wrong_grip_by_congruency


@pytest.mark.parametrize(("only_a", "only_b"), [(4, 1), (1, 4), (0, 7), (10, 10), (3, 12)])
def test_the_exact_mcnemar_test_is_the_binomial_test_of_the_discordant_pairs(only_a, only_b):
    n = only_a + only_b
    assert mcnemar_exact(only_a, only_b) == pytest.approx(sps.binomtest(only_a, n, 0.5).pvalue)
    # by hand: both tails of Binomial(n, 1/2) at least as far from n/2 as the smaller count
    k = min(only_a, only_b)
    by_hand = min(1.0, sum(comb(n, x) for x in range(n + 1) if min(x, n - x) <= k) / 2**n)
    assert mcnemar_exact(only_a, only_b) == pytest.approx(by_hand)
    assert mcnemar_exact(only_a, only_b) == mcnemar_exact(only_b, only_a)


def test_without_discordant_pairs_the_mcnemar_test_shows_nothing():
    assert mcnemar_exact(0, 0) == 1.0


def categorisation(seed: int, shift: float = 0.0) -> pd.DataFrame:
    """``test_contrasts.synthetic``'s trials as a run's trial table (task, mode, congruent)."""
    df = synthetic(seed=seed, shift=shift)
    return df.drop(columns="congruency").assign(
        task="categorisation",
        mode="closed_loop",
        congruent=(df["congruency"] == "congruent").astype(str),
    )


def test_the_cue_timings_difference_is_first_step_minus_every_step_paired_by_network():
    first, every = categorisation(3, shift=0.01), categorisation(3)
    every["rmse"] += np.random.default_rng(9).normal(0, 0.002, len(every))
    # the other mode's trials are not read
    noise = every.assign(mode="teacher_forced", rmse=every["rmse"] + 1.0)
    result = cue_timing_difference({"all_steps": pd.concat([every, noise]), "first_step": first})
    assert result["congruency"]["estimate"] == pytest.approx(0.01, abs=2e-3)
    assert result == difference_tests(
        synthetic(3, shift=0.01), synthetic(3).assign(rmse=every["rmse"])
    )
    # independently: the paired t-test of the per-network congruency contrasts, one mapping
    one = {
        cue: df[df["mapping"] == "A"] for cue, df in (("first_step", first), ("all_steps", every))
    }

    def contrast(df):
        cells = df.groupby(["network", "congruent"])["rmse"].mean().unstack()
        return cells["False"] - cells["True"]

    ref = sps.ttest_rel(contrast(one["first_step"]), contrast(one["all_steps"]))
    p = cue_timing_difference(one)["congruency"]["p"]
    assert p == pytest.approx(ref.pvalue, rel=1e-9)
    json.dumps(result)  # as the rule writes it


def made_up_robot():
    """Two variants (constant and annealed rate) on 4 networks, a tolerance test at two noise
    levels, and replays of the demonstrations (commands) and of the sensed postures."""
    constant = robot_trials("c", success=lambda net, obj: net > 0, contact=lambda net, obj: 1.0)
    anneal = robot_trials(
        "main",
        success=lambda net, obj: not (net == 3 and obj == "small_ball"),
        contact=lambda net, obj: 1.0,
        schedule="anneal",
    )
    tolerance = pd.DataFrame(
        [
            {"object": obj, "noise": noise, "success": k % 4 != 3 or noise == 0.0,
             "palm_error_mm": 1000 * noise + k}
            for noise in (0.0, 0.01)
            for k, obj in enumerate(["big_ball", "small_ball"] * 4)
        ]
    )  # fmt: skip
    replay = pd.DataFrame(
        {
            "plan": ["commands"] * 5 + ["sensed_postures"] * 2,
            "success": [True, True, False, True, True, True, False],
            "palm_error_mm": [1.0, 2.5, 30.0, 4.0, 7.5, 100.0, 200.0],
        }
    )
    return pd.concat([constant, anneal], ignore_index=True), tolerance, replay


def test_the_robot_statistics_by_hand_and_as_json():
    trials, tolerance, replay = made_up_robot()
    found = json.loads(json.dumps(robot_statistics(trials, tolerance, replay)))
    # the tolerance per noise: share held and median palm error, by hand
    table = record_table(found["tolerance"])
    assert table["noise"].tolist() == [0.0, 0.01]
    assert table["trials"].tolist() == [8, 8]
    assert table["success"].tolist() == [1.0, 0.75]
    assert table["palm_error_mm"].tolist() == [3.5, 13.5]
    assert table["small_ball_success"].tolist() == [1.0, 0.5]
    # the replayed demonstrations (commands only)
    assert found["replay"] == {
        "palm_error_mm_median": 4.0,
        "palm_error_mm_max": 30.0,
        "held": 0.8,
        "trials": 5,
    }
    bins = record_table(found["held_by_palm_error"]["replay"])
    assert bins["low_mm"].tolist() == list(PALM_BINS_MM[:-1])
    assert bins["high_mm"].tolist()[-1] == float("inf")
    assert bins["trials"].tolist() == [2, 1, 1, 0, 1]  # 1, 2.5 | 4 | 7.5 | - | 30 mm
    assert bins["held"].iloc[[0, 1, 2, 4]].tolist() == [1.0, 1.0, 1.0, 0.0]
    assert np.isnan(bins["held"].iloc[3])
    # each variant's distinct grasping trials (network x object, the sequences once); the
    # made-up palm error of a grasping trial is 2 + network mm
    runs = found["held_by_palm_error"]["runs"]
    assert sorted(runs) == ["c", "main"]
    main = record_table(runs["main"])
    assert main["trials"].tolist() == [4, 12, 0, 0, 0]  # network 0 at 2 mm, 1-3 at 3-5 mm
    assert main["held"].tolist()[:2] == [1.0, pytest.approx(11 / 12)]  # net 3's small ball
    assert record_table(runs["c"])["held"].tolist()[:2] == [0.0, 1.0]  # network 0 misses
    # the schedules' pair, with its exact McNemar test
    (pair,) = found["schedule_pairs"]
    assert (pair["a"], pair["b"], pair["trials"]) == ("anneal", "constant", 16)
    assert (pair["only_a"], pair["only_b"]) == (4, 1)
    assert pair["p"] == pytest.approx(sps.binomtest(4, 5, 0.5).pvalue)
    assert isinstance(pair["hidden"], int)  # Python's numbers, for JSON


def test_a_table_survives_its_record_exactly():
    table = pd.DataFrame({"noise": [0.0, 0.005], "trials": [4, 10], "success": [1 / 3, 0.1 + 0.2]})
    back = record_table(json.loads(json.dumps(table_record(table))))
    pd.testing.assert_frame_equal(back, table)


def test_distinct_grasping_trials_count_a_network_and_object_once():
    trials, _, replay = made_up_robot()
    grasping = grasping_trials(trials)
    assert len(grasping) == 2 * 4 * 4 and set(grasping["task"]) == {"grasping"}
    assert replay_palm(replay)["trials"] == 5


def test_a_robot_effects_statistics():
    contrast = {"tests": {"size": {"method": "contrasts", "estimate": -0.25, "p": 0.01,
                                   "p_holm": 0.04}}}  # fmt: skip
    assert robot_effect_statistics(contrast, "size") == {"estimate": -0.25, "p": 0.04}
    # the exact test: the share held at the slower level minus at the faster one
    exact = {"tests": {"congruency": {"method": "exact", "table": [[9, 3], [6, 6]], "p": 0.4}}}
    assert robot_effect_statistics(exact, "congruency") == {
        "estimate": pytest.approx(6 / 12 - 9 / 12),
        "p": 0.4,
    }
    none = robot_effect_statistics({"tests": {"size": {"method": "none"}}}, "size")
    assert np.isnan(none["estimate"]) and np.isnan(none["p"])


def test_the_wrong_grip_rate_per_level_averages_the_other_factors_levels():
    rates = {"congruent_large": 0.1, "congruent_small": 0.3, "incongruent_large": 0.5,
             "incongruent_small": 0.0}  # fmt: skip
    assert wrong_grip_by_congruency(rates) == pytest.approx(
        {"congruent": 0.2, "incongruent": 0.25, "large": 0.3, "small": 0.15}
    )
