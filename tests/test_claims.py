"""The confirmation's declaration: its family, and the design's power, checked against
statsmodels' own power calculation and a chi-square interval computed by hand."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy import stats as sps
from statsmodels.stats.power import TTestPower

from icub_affordance.analysis import paper_claims as claims
from icub_affordance.outcome import Outcome

DECLARATION = {
    "seeds": [101, 102, 103],
    "robustness_seeds": [111],
    "cues": ["first_step", "all_steps"],
    "modes": ["closed_loop", "teacher_forced"],
    "measures": ["rmse", "rmse_correct"],
    "effects": ["congruency", "size"],
    "alpha": 0.05,
    "min_replications": 2,
}


def test_the_family_is_every_combination_once():
    tests = claims.declared_tests(DECLARATION)
    assert len(tests) == 16
    assert len({tuple(t.values()) for t in tests}) == 16
    assert tests[0] == {"cue": "first_step", "mode": "closed_loop", "measure": "rmse",
                        "effect": "congruency"}  # fmt: skip


def test_the_full_scale_adds_its_seeds():
    assert claims.seeds(DECLARATION, robustness=False) == [101, 102, 103]
    assert claims.seeds(DECLARATION, robustness=True) == [101, 102, 103, 111]


@pytest.mark.parametrize(("effect", "sd", "n", "alpha"), [
    (0.01, 0.01, 10, 0.05), (0.004, 0.003, 10, 0.05 / 16), (-0.02, 0.008, 6, 0.01),
    (0.001, 0.01, 20, 0.05)])  # fmt: skip
def test_power_is_statsmodels_power(effect, sd, n, alpha):
    expected = TTestPower().power(effect_size=abs(effect) / sd, nobs=n, alpha=alpha,
                                  alternative="two-sided")  # fmt: skip
    assert claims.power(effect, sd, n, alpha) == pytest.approx(expected, rel=1e-6)


def test_power_is_undefined_without_a_spread_or_a_second_replication():
    assert np.isnan(claims.power(0.01, 0.0, 10, 0.05))
    assert np.isnan(claims.power(0.01, 0.01, 1, 0.05))
    assert np.isnan(claims.power(np.nan, 0.01, 10, 0.05))


def test_the_sd_interval_is_the_chi_square_interval():
    low, high = claims.sd_interval(2.0, 10)
    assert low == pytest.approx(2.0 * np.sqrt(9 / sps.chi2.ppf(0.975, 9)))
    assert high == pytest.approx(2.0 * np.sqrt(9 / sps.chi2.ppf(0.025, 9)))
    assert low < 2.0 < high


def test_pilot_power_reads_each_test_and_counts_what_was_not_estimable():
    rng = np.random.default_rng(0)
    rows = []
    for test in claims.declared_tests(DECLARATION):
        for seed in range(1, 11):
            rows.append(test | {"seed": seed, "estimate": rng.normal(0.006, 0.01)})
    pilot = pd.DataFrame(rows)
    gone = (pilot["measure"] == "rmse_correct") & (pilot["seed"] <= 3)
    pilot.loc[gone, "estimate"] = np.nan
    table = claims.pilot_power(pilot, DECLARATION, replications=10)
    assert list(table.columns) == [*claims.TEST_KEYS, *claims.POWER_COLUMNS]
    assert len(table) == 16 and (table["family_size"] == 16).all()
    correct = table[table["measure"] == "rmse_correct"]
    assert (correct["pilot_replications"] == 7).all()
    assert (correct["pilot_not_estimable"] == 3).all()
    assert (correct["expected_estimable"] == 7).all()  # 10 replications, 7 in 10 estimable
    assert (table.loc[table["measure"] == "rmse", "expected_estimable"] == 10).all()
    row = table.iloc[0]
    values = pilot[(pilot[list(claims.TEST_KEYS)] == row[list(claims.TEST_KEYS)]).all(axis=1)]
    mean, sd = values["estimate"].mean(), values["estimate"].std(ddof=1)
    assert row["pilot_estimate"] == pytest.approx(mean)
    assert row["power_at_least"] == pytest.approx(
        TTestPower().power(
            effect_size=abs(mean) / sd, nobs=10, alpha=0.05 / 16, alternative="two-sided"
        )
    )
    # the bounds are ordered: more alpha, more power; a larger SD, less
    assert (table["power_at_least"] <= table["power_at_most"]).all()
    assert (table["power_at_least_sd_high"] <= table["power_at_least"]).all()
    assert (table["power_at_least"] <= table["power_at_least_sd_low"]).all()


def test_power_far_from_zero_agrees_with_a_simulation():
    """Where scipy's lower tail of the noncentral t is NaN (a large shift), the power still
    matches simulated t-tests."""
    rng = np.random.default_rng(1)
    effect, sd, n, alpha = 0.01, 0.004, 10, 0.05 / 16
    samples = rng.normal(effect, sd, size=(20000, n))
    p = sps.ttest_1samp(samples, 0.0, axis=1).pvalue
    assert claims.power(effect, sd, n, alpha) == pytest.approx((p < alpha).mean(), abs=0.01)


def test_a_claim_on_fewer_replications_than_the_minimum_is_not_assessable():
    """The one rule of every replicated test (icub_affordance.analysis.replicated, which the
    signatures read too): a test over fewer estimates than ``min_replications`` has no p and
    reads "not assessable"; at the minimum it is the t-test over the estimates, recomputed
    here."""
    rng = np.random.default_rng(5)
    rows = [
        test | {"seed": seed, "estimate": 0.01 + rng.normal(0, 0.0002), "lono_low": np.nan,
                "lono_high": np.nan, "fewest_networks_per_cell": np.nan}
        for test in claims.declared_tests(DECLARATION) for seed in (101, 102, 103)
    ]  # fmt: skip
    estimates = pd.DataFrame(rows)
    for least, code in ((3, Outcome.PAPER), (4, Outcome.NOT_ASSESSABLE)):
        table = claims.confirm(estimates, DECLARATION | {"min_replications": least})
        assert (table["direction"] == code).all()
    first = estimates.iloc[:3]["estimate"]
    made = claims.confirm(estimates, DECLARATION | {"min_replications": 3}).iloc[0]
    assert made["p"] == pytest.approx(sps.ttest_1samp(first, 0.0).pvalue)
    assert np.isnan(table["p"]).all() and (table["estimable"] == 3).all()
