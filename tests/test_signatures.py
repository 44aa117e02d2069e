"""The human signatures' conditions and tests (icub_affordance.signatures): the conditions show
what they declare, each statistic is recomputed independently, and each verdict word follows its
statistic across the threshold."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import yaml
from conftest import REPO
from scipy import stats as sps

from icub_affordance.jordan import Weights
from icub_affordance.signatures import (
    FAMILY,
    IN_VIEW,
    LEVELS_FAMILY,
    SUMMARY_COLUMNS,
    SignatureConfig,
    delta_bins,
    network_trials,
    over_units,
    summary,
    verdict,
    visual_inputs,
)
from icub_affordance.train import synthetic_materials


def declared() -> SignatureConfig:
    return SignatureConfig(
        **yaml.safe_load((REPO / "config/config.yaml").read_text())["signatures"]
    )


def binary_map(seed: int = 0) -> np.ndarray:
    return (np.random.default_rng(seed).random(100) < 0.3).astype(float)


def test_extinction_blanks_the_map_after_k_steps_and_noise_flips_pixels_at_its_rate():
    visual = binary_map()
    still = visual_inputs(visual, "extinction", 3, 50, 1e-12, np.random.default_rng(1))
    assert (still[:, :3] == visual).all() and (still[:, 3:] == 0).all()
    noisy = visual_inputs(visual, "in_view", IN_VIEW, 400, 0.05, np.random.default_rng(2))
    flipped = (noisy != visual).mean()
    assert abs(flipped - 0.05) < 0.005  # 360,000 pixels: a binomial sd of 0.00036
    assert np.isin(noisy, (0.0, 1.0)).all()


def test_the_mask_scrambles_the_objects_own_pixels_afresh_each_step():
    visual = binary_map(3)
    masked = visual_inputs(visual, "brief_exposure", 1, 20, 1e-12, np.random.default_rng(4))
    assert (masked[:, 0] == visual).all()
    assert (masked[:, 1:].sum(axis=2) == visual.sum()).all()  # the same amount of edge
    assert not (masked[:, 1:] == visual).all(axis=2).any()  # never the object itself
    assert len({m.tobytes() for m in masked[:, 1:].reshape(-1, 100)}) > 100


def test_a_non_binary_map_is_refused():
    with pytest.raises(ValueError, match="binary"):
        visual_inputs(np.full(100, 0.5), "in_view", IN_VIEW, 2, 0.05, np.random.default_rng(0))


def test_trials_are_seeded_and_cover_every_condition_object_and_trial():
    m = synthetic_materials(0)
    m = type(m)(**{**vars(m), "visual": (m.visual > np.median(m.visual)).astype(float)})
    rng = np.random.default_rng(5)
    weights = Weights(W1=rng.normal(0, 0.5, (10, 216)), b1=np.zeros(10),
                      W2=rng.normal(0, 0.5, (16, 10)), b2=np.zeros(16))  # fmt: skip
    config = declared()
    one = network_trials(m, weights, 0, "A", "first_step", "sensed", config, 7)
    again = network_trials(m, weights, 0, "A", "first_step", "sensed", config, 7)
    other = network_trials(m, weights, 0, "A", "first_step", "sensed", config, 8)
    assert one == again and one != other
    assert len(one) == len(config.conditions()) * len(m.objects) * config.trials


def synthetic_trials(slope_per_bin: float, networks: int = 12, seed: int = 0) -> pd.DataFrame:
    """Correct in-view trials whose incongruent RMSEs exceed the congruent ones by an amount that
    grows with the trial's rank (a delta plot of known slope), plus one all-wrong network."""
    rng = np.random.default_rng(seed)
    rows = []
    for net in range(networks):
        base = np.sort(rng.normal(0.1, 0.01, 20))
        for i, value in enumerate(base):
            q = i * 4 // 20  # its bin, 0-3
            for congruent, extra in ((True, 0.0), (False, 0.005 + slope_per_bin * q)):
                rows.append({"replication": 1, "network": net, "condition": "in_view",
                             "k": IN_VIEW, "congruent": congruent, "correct": True,
                             "rmse": value + extra + rng.normal(0, 1e-4)})  # fmt: skip
    return pd.DataFrame(rows)


def test_the_delta_plot_slope_is_recomputed_independently():
    trials = synthetic_trials(0.002)
    bins = delta_bins(trials, 4)
    net0 = trials[trials["network"] == 0]
    inc = np.sort(net0[~net0["congruent"]]["rmse"])
    con = np.sort(net0[net0["congruent"]]["rmse"])
    by_hand = [inc[i * 5 : (i + 1) * 5].mean() - con[i * 5 : (i + 1) * 5].mean() for i in range(4)]
    assert np.allclose(bins[bins["network"] == 0]["effect"], by_hand)
    slopes = [sps.linregress(range(1, 5), g["effect"]).slope for _, g in bins.groupby("network")]
    test = over_units(pd.DataFrame({"replication": 1, "s": slopes}), "s")
    reference = sps.ttest_1samp(slopes, 0.0)
    assert test["estimate"] == pytest.approx(np.mean(slopes))
    assert test["p"] == pytest.approx(reference.pvalue) and test["df"] == len(slopes) - 1


def test_over_units_takes_the_replications_means_when_there_are_several():
    values = pd.DataFrame({"replication": np.repeat([1, 2, 3], 4), "v": np.arange(12.0)})
    test = over_units(values, "v")
    means = [1.5, 5.5, 9.5]
    assert test["df"] == 2 and test["replications"] == 3
    assert test["p"] == pytest.approx(sps.ttest_1samp(means, 0.0).pvalue)


def test_the_summary_holds_the_contract_and_holm_within_each_family():
    config = declared()
    trials = synthetic_trials(0.002)
    table = summary(trials, SignatureConfig(**{**vars(config), "list": [config.list[0]]}))
    assert list(table.columns) == SUMMARY_COLUMNS
    levels = table[table["family"] == LEVELS_FAMILY]
    from statsmodels.stats.multitest import multipletests

    assert np.allclose(levels["p_adjusted"], multipletests(levels["p"], method="holm")[1])
    slope = table[table["family"] == FAMILY].iloc[0]
    assert slope["verdict"] == "shown" and slope["estimate"] > 0


@pytest.mark.parametrize(
    ("test", "expected", "row", "word"),
    [
        ("slope", "positive", {"estimate": 0.01, "p_adjusted": 0.049}, "shown"),
        ("slope", "positive", {"estimate": 0.01, "p_adjusted": 0.051}, "not shown"),
        ("slope", "positive", {"estimate": -0.01, "p_adjusted": 0.049}, "opposite"),
        ("slope", "negative", {"estimate": -0.01, "p_adjusted": 0.049}, "shown"),
        ("equivalence", "same", {"estimate": 0.001, "p_adjusted": 0.049}, "shown"),
        ("equivalence", "same",
         {"estimate": 0.03, "p_adjusted": 0.6, "p_difference_adjusted": 0.049}, "opposite"),
        ("equivalence", "same",
         {"estimate": 0.03, "p_adjusted": 0.6, "p_difference_adjusted": 0.051}, "not shown"),
        ("none", "absent", {"estimate": np.nan}, "not testable here"),
        ("slope", "positive", {"estimate": np.nan, "p_adjusted": np.nan}, "not testable here"),
    ],
)  # fmt: skip
def test_each_verdict_word_follows_its_statistic_across_the_threshold(test, expected, row, word):
    assert verdict(test, expected, row) == word
