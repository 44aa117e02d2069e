"""The human signatures' conditions and tests (icub_affordance.analysis.signature_tests): the
conditions show what they declare, each statistic is recomputed independently, and each verdict word
follows its statistic across the threshold."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import yaml
from conftest import REPO
from scipy import stats as sps

from icub_affordance.analysis.signature_tests import (
    FAMILY,
    IN_VIEW,
    LEVELS_FAMILY,
    SUMMARY_COLUMNS,
    SignatureConfig,
    bin_effects,
    network_trials,
    over_units,
    replication_effects,
    summary,
    verdict,
    visual_inputs,
)
from icub_affordance.learning.materials import synthetic_materials
from icub_affordance.learning.network import Weights
from icub_affordance.outcome import Outcome
from icub_workflow.book.words import SIGNATURE_WORDS


def declared() -> SignatureConfig:
    config = yaml.safe_load((REPO / "config/config.yaml").read_text())
    return SignatureConfig(
        **config["signatures"], min_replications=config["confirmation"]["min_replications"]
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


#: Under mapping A the big ball and the small cube are categorised with their natural grip.
CONGRUENT_A = {"big_ball": True, "small_ball": False, "big_cube": False, "small_cube": True}
SIZES = {"big_ball": "large", "small_ball": "small", "big_cube": "large", "small_cube": "small"}


def synthetic_trials(slope_per_bin: float, replications: int = 5, networks: int = 12,
                     seed: int = 0, object_offset: float = 0.0) -> pd.DataFrame:  # fmt: skip
    """Correct in-view trials whose incongruent RMSEs exceed the congruent ones of a network by
    an amount that grows with the trial's rank (a delta plot of known slope); small objects'
    RMSE higher by ``object_offset``."""
    rng = np.random.default_rng(seed)
    rows = []
    for rep in range(1, replications + 1):
        for net in range(networks):
            mapping = "A" if net < networks // 2 else "B"
            speed = rng.normal(0.1, 0.01)
            for obj, congruent_a in CONGRUENT_A.items():
                congruent = congruent_a if mapping == "A" else not congruent_a
                base = np.sort(rng.normal(speed, 0.01, 20))
                for i, value in enumerate(base):
                    q = i * 4 // 20  # its bin, 0-3
                    extra = 0.0 if congruent else 0.005 + slope_per_bin * q
                    extra += object_offset if SIZES[obj] == "small" else 0.0
                    rows.append({"replication": rep, "network": net, "mapping": mapping,
                                 "condition": "in_view", "k": IN_VIEW, "object": obj,
                                 "size": SIZES[obj], "congruent": congruent, "trial": i,
                                 "correct": True,
                                 "rmse": value + extra + rng.normal(0, 1e-4)})  # fmt: skip
    return pd.DataFrame(rows)


def by_hand_bin_effects(trials: pd.DataFrame) -> pd.DataFrame:
    """Each replication's per-bin effect recomputed without the estimator: per network x
    object, the correct trials' RMSEs in 4 bins of equal count; per network the mean of its two
    incongruent objects minus its two congruent ones; the mean of the two mappings' means."""
    rows = []
    for (rep, net, _obj), g in trials.groupby(["replication", "network", "object"]):
        values = np.sort(g["rmse"].to_numpy())
        for q in range(4):
            rows.append({"replication": rep, "network": net, "mapping": g["mapping"].iloc[0],
                         "congruent": g["congruent"].iloc[0], "bin": q + 1,
                         "v": values[q * 5 : (q + 1) * 5].mean()})  # fmt: skip
    cells = pd.DataFrame(rows)
    sign = np.where(cells["congruent"], -0.5, 0.5)
    per_net = cells.assign(v=cells["v"] * sign).groupby(
        ["replication", "bin", "mapping", "network"])["v"].sum()  # fmt: skip
    return per_net.groupby(["replication", "bin", "mapping"]).mean().groupby(
        ["replication", "bin"]).mean().rename("effect").reset_index()  # fmt: skip


@pytest.mark.heavy
def test_the_delta_plot_slope_is_recomputed_independently():
    trials = synthetic_trials(0.002)
    bins = bin_effects(trials, 4)
    full = bins[bins["dropped"] == -1].sort_values(["replication", "bin"])
    by_hand = by_hand_bin_effects(trials).sort_values(["replication", "bin"])
    assert np.allclose(full["effect"], by_hand["effect"])
    slopes = [sps.linregress(range(1, 5), g["effect"]).slope
              for _, g in by_hand.groupby("replication")]  # fmt: skip
    config = declared()
    table = summary(trials, SignatureConfig(**{**vars(config), "list": [config.list[0]]}))
    row = table[table["level"] == "slope"].iloc[0]
    reference = sps.ttest_1samp(slopes, 0.0)
    assert row["estimate"] == pytest.approx(np.mean(slopes))
    assert row["p"] == pytest.approx(reference.pvalue) and row["df"] == len(slopes) - 1
    assert row["units"] == row["replications"] == 5


def test_objects_are_not_pooled_a_mixture_of_objects_makes_no_effect():
    """Small objects slower, no congruency effect within any cell, and the incongruent correct
    trials mostly small objects (most incongruent large-object trials wrong): the estimator
    finds no effect where the pooled difference of means finds one."""
    trials = synthetic_trials(0.0, object_offset=0.02)
    trials.loc[~trials["congruent"], "rmse"] -= 0.005  # take the built-in effect away
    # every trial of a network x object alike, so which of them are correct selects nothing
    cell = ["replication", "network", "object"]
    trials["rmse"] = trials.groupby(cell)["rmse"].transform("mean")
    drop = (~trials["congruent"]) & (trials["size"] == "large") & (trials["trial"] >= 4)
    trials.loc[drop, "correct"] = False
    effects = replication_effects(trials)
    full = effects[effects["dropped"] == -1]
    assert np.abs(full["effect"]).max() < 1e-3
    ok = trials[trials["correct"]]
    pooled = ok[~ok["congruent"]]["rmse"].mean() - ok[ok["congruent"]]["rmse"].mean()
    assert pooled > 0.005


def test_over_units_takes_one_value_per_replication_and_counts_the_undefined():
    values = pd.DataFrame({"replication": [1, 2, 3, 4], "v": [1.0, 2.0, np.nan, 4.0]})
    test = over_units(values, "v", 2)
    assert test["df"] == 2 and test["replications"] == 4 and test["not_estimable"] == 1
    assert test["p"] == pytest.approx(sps.ttest_1samp([1.0, 2.0, 4.0], 0.0).pvalue)
    # per-network values (the error rates) count once per replication, by their mean
    networks = pd.DataFrame({"replication": np.repeat([1, 2, 3], 4), "v": np.arange(12.0)})
    test = over_units(networks, "v", 2)
    assert test["df"] == 2 and test["units"] == 3
    assert test["p"] == pytest.approx(sps.ttest_1samp([1.5, 5.5, 9.5], 0.0).pvalue)


@pytest.mark.heavy
def test_a_signature_on_fewer_replications_than_the_minimum_is_not_assessable():
    """One minimum for every replicated test (icub_affordance.analysis.replicated): five
    replications against a declared minimum of six give no p and no verdict but "not
    assessable"; the confirmation's claims read the same rule (tests/test_claims.py)."""
    config = declared()
    trials = synthetic_trials(0.002)
    assert trials["replication"].nunique() == 5
    for least, word in ((5, "confirmed"), (6, "not assessable")):
        chosen = SignatureConfig(**{**vars(config), "list": [config.list[0]],
                                    "min_replications": least})  # fmt: skip
        slope = summary(trials, chosen).query("family == @FAMILY").iloc[0]
        assert SIGNATURE_WORDS[slope["verdict"]] == word
        assert np.isfinite(slope["p"]) == (least == 5)
    assert "fewer than 6 replications" in slope["reason"]


@pytest.mark.heavy
def test_the_leave_one_network_out_range_brackets_the_estimate():
    trials = synthetic_trials(0.002, replications=3)
    config = declared()
    table = summary(trials, SignatureConfig(**{**vars(config), "list": [config.list[0]]}))
    view = table[table["level"] == "all"].iloc[0]
    assert view["lono_low"] <= view["estimate"] <= view["lono_high"]
    assert view["lono_low"] < view["lono_high"]
    # by hand: replication 1 without network 0
    effects = replication_effects(trials)
    one = effects[(effects["replication"] == 1) & (effects["dropped"] == 0)]["effect"].iloc[0]
    full = effects[effects["dropped"] == -1].set_index("replication")["effect"]
    shifted = full.mean() + (one - full.loc[1]) / 3
    assert view["lono_low"] <= shifted <= view["lono_high"]
    assert view["fewest_networks_per_cell"] == 12


@pytest.mark.heavy
def test_the_summary_holds_the_contract_and_holm_within_each_family():
    config = declared()
    trials = synthetic_trials(0.002)
    table = summary(trials, SignatureConfig(**{**vars(config), "list": [config.list[0]]}))
    assert list(table.columns) == SUMMARY_COLUMNS
    levels = table[table["family"] == LEVELS_FAMILY]
    from statsmodels.stats.multitest import multipletests

    assert np.allclose(levels["p_adjusted"], multipletests(levels["p"], method="holm")[1])
    slope = table[table["family"] == FAMILY].iloc[0]
    assert slope["verdict"] == Outcome.PAPER and slope["estimate"] > 0


@pytest.mark.heavy
def test_no_signature_is_judged_while_the_in_view_effect_is_not_established():
    config = declared()
    trials = synthetic_trials(0.002)
    trials.loc[~trials["congruent"], "rmse"] -= 0.0125  # the in-view effect now reversed
    table = summary(trials, SignatureConfig(**{**vars(config), "list": [config.list[0]]}))
    slope = table[table["family"] == FAMILY].iloc[0]
    assert slope["verdict"] == Outcome.NOT_ASSESSABLE and "in-view" in slope["reason"]


@pytest.mark.parametrize(
    ("test", "expected", "row", "word"),
    [
        ("slope", "positive", {"estimate": 0.01, "p_adjusted": 0.049}, "confirmed"),
        ("slope", "positive", {"estimate": 0.01, "p_adjusted": 0.051}, "not shown"),
        ("slope", "positive", {"estimate": -0.01, "p_adjusted": 0.049}, "reversed"),
        ("slope", "negative", {"estimate": -0.01, "p_adjusted": 0.049}, "confirmed"),
        ("equivalence", "same", {"estimate": 0.001, "p_adjusted": 0.049}, "confirmed"),
        ("equivalence", "same",
         {"estimate": 0.03, "p_adjusted": 0.6, "p_difference_adjusted": 0.049}, "reversed"),
        ("equivalence", "same",
         {"estimate": 0.03, "p_adjusted": 0.6, "p_difference_adjusted": 0.051}, "not shown"),
        ("none", "absent", {"estimate": np.nan}, "not assessable"),
        ("slope", "positive", {"estimate": np.nan, "p_adjusted": np.nan}, "not assessable"),
        ("slope", "positive", {"estimate": 0.01, "p_adjusted": 0.001,
                               "in_view_established": False}, "not assessable"),
    ],
)  # fmt: skip
def test_each_verdict_word_follows_its_statistic_across_the_threshold(test, expected, row, word):
    assert SIGNATURE_WORDS[verdict(test, expected, row)] == word  # the book's word for it
