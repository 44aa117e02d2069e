"""The analysis used for inference (book/notes.md, "Testing and statistics"), recomputed
independently: per-network contrasts tested with t over networks (statsmodels OLS and scipy's
t-tests as the references), each network x object counted once, Holm's adjustment and the
equivalence test by hand."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import statsmodels.formula.api as smf
from scipy import stats as sps

from icub_affordance.stats import (
    TERMS,
    coded,
    difference_tests,
    equivalence,
    holm,
    network_contrasts,
    network_object_means,
    simple_effects,
)

OBJECTS = {  # object: (size, category)
    "big_ball": ("large", "natural"),
    "small_ball": ("small", "natural"),
    "big_cube": ("large", "artefact"),
    "small_cube": ("small", "artefact"),
}
NATURAL = {"large": "power", "small": "precision"}
MAPPING = {
    "A": {"natural": "power", "artefact": "precision"},
    "B": {"natural": "precision", "artefact": "power"},
}
TRUTH = {"congruency": 0.03, "size": 0.0}


def synthetic(seed: int = 3, networks: int = 12, sequences: int = 5, shift: float = 0.0):
    """Categorisation trials: RMSE = 0.1 + network intercept + 0.03 (+ shift) if incongruent +
    network x object deviation + trial noise (no size effect)."""
    rng = np.random.default_rng(seed)
    rows = []
    for net in range(networks):
        mapping = "A" if net < networks // 2 else "B"
        intercept = rng.normal(0, 0.02)
        for obj, (size, category) in OBJECTS.items():
            congruent = MAPPING[mapping][category] == NATURAL[size]
            cell = rng.normal(0, 0.01)
            for seq in range(sequences):
                rmse = 0.1 + intercept + (0 if congruent else TRUTH["congruency"] + shift) + cell
                rows.append(
                    {
                        "network": net,
                        "mapping": mapping,
                        "object": obj,
                        "size": size,
                        "congruency": "congruent" if congruent else "incongruent",
                        "sequence": seq,
                        "rmse": rmse + rng.normal(0, 0.002),
                    }
                )
    return pd.DataFrame(rows)


def reference(df: pd.DataFrame) -> dict[str, tuple[float, float, float, float]]:
    """Every term by statsmodels OLS: each network's contrast (built from the coded cells by
    regression, not by the differences the package takes) regressed on the mapping."""
    data = coded(network_object_means(df))
    rows = []
    for _net, cells in data.groupby("network"):
        fit = smf.ols("rmse ~ congruency * size", cells).fit()  # 4 cells, saturated: exact
        contrast = {k: float(fit.params[k]) for k in ("congruency", "size", "congruency:size")}
        rows.append(
            {"mapping": cells["mapping"].iloc[0], "mean": cells["rmse"].mean()}
            | {k.replace(":", "_"): v for k, v in contrast.items()}
        )
    nets = pd.DataFrame(rows)

    def term(fit, name):
        ci = fit.conf_int(0.05)
        return fit.params[name], ci.loc[name, 0], ci.loc[name, 1], fit.pvalues[name]

    out = {}
    for column in ("congruency", "size", "congruency_size"):
        fit = smf.ols(f"{column} ~ mapping", nets).fit()
        name = column.replace("_", ":")
        out[name], out[f"{name}:mapping"] = term(fit, "Intercept"), term(fit, "mapping")
    out["mapping"] = term(smf.ols("mean ~ mapping", nets).fit(), "mapping")
    return out


def test_contrasts_match_statsmodels_ols_over_networks():
    df = synthetic()
    fit, ref = network_contrasts(df), reference(df)
    assert set(fit) == set(TERMS)
    for term in TERMS:
        estimate, low, high, p = ref[term]
        assert fit[term]["estimate"] == pytest.approx(estimate, abs=1e-12)
        assert fit[term]["ci_low"] == pytest.approx(low, abs=1e-12)
        assert fit[term]["ci_high"] == pytest.approx(high, abs=1e-12)
        assert fit[term]["p"] == pytest.approx(p, rel=1e-9)
        assert fit[term]["df"] == 10 and fit[term]["networks"] == 12


def test_the_congruency_test_is_a_t_test_of_the_networks_contrasts():
    """With the mapping balanced, the congruency term's t equals Welch-free pooled reasoning:
    a one-sample t-test of the per-network contrasts after removing each mapping's mean differs
    only in its df; with one mapping only it is exactly scipy's one-sample t-test."""
    df = synthetic()
    only_a = df[df["mapping"] == "A"]
    cells = network_object_means(only_a).pivot_table(
        index="network", columns="congruency", values="rmse"
    )
    contrast = cells["incongruent"] - cells["congruent"]
    ref = sps.ttest_1samp(contrast, 0.0)
    fit = network_contrasts(only_a)["congruency"]
    assert fit["estimate"] == pytest.approx(contrast.mean(), abs=1e-12)
    assert fit["p"] == pytest.approx(ref.pvalue, rel=1e-9)
    assert fit["df"] == len(contrast) - 1


def test_contrasts_find_the_known_effect():
    fit = network_contrasts(synthetic())
    cong, size = fit["congruency"], fit["size"]
    assert cong["ci_low"] < TRUTH["congruency"] < cong["ci_high"] and cong["p"] < 0.001
    assert size["ci_low"] < TRUTH["size"] < size["ci_high"]


def test_identical_sequences_count_once():
    """Five identical copies of every trial (closed loop) give the same tests as one."""
    df = synthetic(sequences=1)
    copies = pd.concat([df.assign(sequence=k) for k in range(5)])
    a, b = network_contrasts(df), network_contrasts(copies)
    for term in TERMS:
        for key in ("estimate", "ci_low", "ci_high", "p", "df"):
            assert a[term][key] == pytest.approx(b[term][key], rel=1e-12)


def test_a_constant_measure_has_zero_estimates_and_no_p():
    fit = network_contrasts(synthetic().assign(rmse=1.0))
    for term in TERMS:
        assert fit[term]["estimate"] == pytest.approx(0.0, abs=1e-15)
        assert np.isnan(fit[term]["p"])


def test_the_difference_of_two_runs_is_paired_by_network():
    """Run A has 0.01 more congruency effect than run B in every network: the difference is
    found, with the same networks' noise cancelling; and it equals a paired t-test by scipy."""
    a = synthetic(seed=3, shift=0.01)
    b = synthetic(seed=3)
    b["rmse"] += np.random.default_rng(9).normal(0, 0.002, len(b))  # the other run's own noise
    diff = difference_tests(a, b)["congruency"]
    assert diff["estimate"] == pytest.approx(0.01, abs=2e-3) and diff["p"] < 0.001
    one_a, one_b = (x[x["mapping"] == "A"] for x in (a, b))

    def contrast(x):
        c = network_object_means(x).pivot_table(
            index="network", columns="congruency", values="rmse"
        )
        return c["incongruent"] - c["congruent"]

    ref = sps.ttest_rel(contrast(one_a), contrast(one_b))
    assert difference_tests(one_a, one_b)["congruency"]["p"] == pytest.approx(ref.pvalue, rel=1e-9)


def test_holm_by_hand():
    p = [0.01, 0.04, 0.03, float("nan"), 0.005]
    # sorted 0.005, 0.01, 0.03, 0.04 (m = 4): 0.02, 0.03, 0.06, 0.06 (monotone)
    expected = [0.03, 0.06, 0.06, float("nan"), 0.02]
    np.testing.assert_allclose(holm(p), expected, rtol=1e-12)


def test_equivalence_is_two_one_sided_t_tests():
    rng = np.random.default_rng(0)
    x = rng.normal(0.001, 0.01, 12)
    se = x.std(ddof=1) / np.sqrt(len(x))
    term = {"estimate": x.mean(), "se": se, "df": len(x) - 1}
    mine = equivalence(term, 0.02)
    lower = sps.ttest_1samp(x, -0.02, alternative="greater").pvalue
    upper = sps.ttest_1samp(x, 0.02, alternative="less").pvalue
    assert mine["p"] == pytest.approx(max(lower, upper), rel=1e-9)
    assert mine["p"] < 0.05  # well inside a 0.02 margin
    assert equivalence(term, 0.001)["p"] > 0.05  # not inside a margin smaller than the noise
    with pytest.raises(ValueError, match="margin"):
        equivalence(term, 0.0)


def test_simple_effects_are_the_cells_differences_tested_over_networks():
    """Size within congruent trials is congruent small - congruent large per network; with one
    mapping its test is scipy's one-sample t-test of those differences."""
    df = synthetic()
    df.loc[(df["congruency"] == "congruent") & (df["size"] == "small"), "rmse"] += 0.04
    only_a = df[df["mapping"] == "A"]
    cells = network_object_means(only_a).pivot_table(
        index="network", columns=["congruency", "size"], values="rmse"
    )
    within = cells[("congruent", "small")] - cells[("congruent", "large")]
    fit = simple_effects(only_a)["size_in_congruent"]
    assert fit["estimate"] == pytest.approx(within.mean(), abs=1e-12)
    assert fit["p"] == pytest.approx(sps.ttest_1samp(within, 0.0).pvalue, rel=1e-9)
    both = simple_effects(df)
    assert both["size_in_congruent"]["estimate"] == pytest.approx(0.04, abs=0.015)
    assert both["size_in_congruent"]["p"] < 0.01
    assert both["size_in_incongruent"]["ci_low"] < 0 < both["size_in_incongruent"]["ci_high"]
