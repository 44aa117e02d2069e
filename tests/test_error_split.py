"""The closed-loop effects taken apart into their wrong-grip and correct-trial parts
(icub_affordance.analysis.error_split), checked on made-up trials against sums done by hand."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from icub_affordance.analysis.error_split import cells, split


def made_up(wrong_large: int = 3, trials: int = 10) -> pd.DataFrame:
    """Categorisation trials of four cells: correct trials cost 0.05 (large) or 0.04 (small), a
    wrong grip 0.20 on a large object and 0.10 on a small one; ``wrong_large`` of the
    incongruent large cell's trials and 2 of the incongruent small cell's end on the wrong grip.
    Grasping trials, which the split leaves out, cost 9."""
    rows = []
    for congruent, size, wrong in ((True, "large", 0), (True, "small", 0),
                                   (False, "large", wrong_large), (False, "small", 2)):  # fmt: skip
        for i in range(trials):
            is_wrong = i < wrong
            cost = {"large": (0.05, 0.20), "small": (0.04, 0.10)}[size][is_wrong]
            rows.append({"task": "categorisation", "congruent": congruent, "size": size,
                         "wrong_grip": int(is_wrong), "rmse": cost,
                         "grip_distance": 0.18 if size == "large" else 0.15})  # fmt: skip
    rows.append({"task": "grasping", "congruent": np.nan, "size": "large", "wrong_grip": 1,
                 "rmse": 9.0, "grip_distance": 0.18})  # fmt: skip
    return pd.DataFrame(rows)


def effect_by_hand(trials: pd.DataFrame, effect: str) -> float:
    """The all-trial effect straight from the trials' cell means."""
    cat = trials[trials["task"] == "categorisation"]
    mean = cat.groupby(["congruent", "size"])["rmse"].mean()
    if effect == "congruency":
        return mean[False].mean() - mean[True].mean()
    return mean.xs("small", level="size").mean() - mean.xs("large", level="size").mean()


@pytest.mark.parametrize("wrong_large", [0, 3, 7])
def test_the_parts_follow_the_wrong_grip_rate_and_add_up_to_the_effect(wrong_large):
    trials = made_up(wrong_large)
    table = cells(trials)
    parts = split(table).set_index("effect")
    for effect in ("congruency", "size"):
        row = parts.loc[effect]
        assert row["rmse"] == pytest.approx(effect_by_hand(trials, effect))
        assert row["correct_part"] + row["wrong_part"] == pytest.approx(row["rmse"])
    # by hand: the wrong part is the contrast of rate x (wrong - correct RMSE); correct trials
    # cost the same in both congruency levels, so congruency's correct part is 0
    wrong = {"large": wrong_large / 10 * (0.20 - 0.05), "small": 2 / 10 * (0.10 - 0.04)}
    assert parts.loc["congruency", "wrong_part"] == pytest.approx(sum(wrong.values()) / 2)
    assert parts.loc["congruency", "correct_part"] == pytest.approx(0.0, abs=1e-12)
    assert parts.loc["size", "wrong_part"] == pytest.approx((wrong["small"] - wrong["large"]) / 2)
    assert parts.loc["size", "correct_part"] == pytest.approx(0.04 - 0.05)
    incongruent_large = table[~table["congruent"] & (table["size"] == "large")].iloc[0]
    assert incongruent_large["wrong_rate"] == pytest.approx(wrong_large / 10)
    assert incongruent_large["grip_distance"] == pytest.approx(0.18)


def test_more_wrong_grips_on_large_objects_turn_the_size_effect_round():
    few, many = (split(cells(made_up(n))).set_index("effect").loc["size"] for n in (0, 7))
    assert few["rmse"] < 0 and many["rmse"] < few["rmse"]  # small - large falls
    assert many["correct_part"] == pytest.approx(few["correct_part"])  # only errors moved
    assert many["wrong_part"] - few["wrong_part"] == pytest.approx(many["rmse"] - few["rmse"])


def test_a_cell_without_a_correct_trial_cannot_be_split():
    parts = split(cells(made_up(10)))
    assert parts["rmse"].notna().all()
    assert parts[["correct_part", "wrong_part"]].isna().all().all()
