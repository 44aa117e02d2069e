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

from icub_affordance.analysis.statistics import equivalence, holm
from icub_affordance.analysis.trial_effects import (
    TERMS,
    coded,
    difference_tests,
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


def test_holm_is_statsmodels_holm_to_the_bit(monkeypatch):
    """The project's Holm adjustment gives statsmodels' numbers exactly (ties, ones, p above
    1/m), over families of every size the project tests. (statsmodels' own garbage collection
    at every call, which changes no number, is skipped: it would make this test take 40 s.)"""
    import gc

    from statsmodels.stats.multitest import multipletests

    monkeypatch.setattr(gc, "collect", lambda *args: 0)
    rng = np.random.default_rng(7)
    for m in (1, 2, 3, 5, 16, 40):
        for _ in range(25):
            p = rng.choice([rng.uniform(0, 1), 1e-6, 0.01, 0.5, 1.0], size=m)
            p = np.where(rng.uniform(size=m) < 0.5, rng.uniform(0, 0.2, m), p)
            assert holm(p).tobytes() == multipletests(p, method="holm")[1].tobytes(), p


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


# -- errors apart from reaction time, and the families --------------------------------------


def with_errors(df: pd.DataFrame, seed: int = 5, rate: float = 0.6) -> pd.DataFrame:
    """``df`` with trial-table grip columns: each incongruent network x object ends on the wrong
    grip with probability ``rate`` (all its sequences alike, as in closed loop), and its RMSE
    then grows by 0.05; congruent trials are always right."""
    rng = np.random.default_rng(seed)
    out = df.copy()
    wrong = {
        key: (not group["congruency"].eq("congruent").all()) and rng.random() < rate
        for key, group in out.groupby(["network", "object"])
    }
    flag = np.array([wrong[(n, o)] for n, o in zip(out["network"], out["object"], strict=True)])
    out["target_grip"] = "power"
    out["final_grip"] = np.where(flag, "precision", "power")
    out["rmse"] = out["rmse"] + 0.05 * flag
    return out


def test_the_within_network_fit_equals_a_model_with_a_dummy_per_network():
    from icub_affordance.analysis.trial_effects import with_outcomes, within_network_fit

    df = with_outcomes(with_errors(synthetic(seed=11)))
    fit = within_network_fit(df, "rmse_correct")
    # the reference: statsmodels OLS on each network x object with a correct trial, an
    # intercept per network and the coded within terms with their mapping interactions
    data = coded(network_object_means(df.dropna(subset=["rmse_correct"]), "rmse_correct"))
    data = data.dropna(subset=["rmse_correct"])
    ref = smf.ols(
        "rmse_correct ~ 0 + C(network) + (congruency + size + congruency:size) * mapping - mapping",
        data=data,
    ).fit()
    ci = ref.conf_int()
    for term, name in (("congruency", "congruency"), ("size", "size"),
                       ("congruency:size", "congruency:size")):  # fmt: skip
        assert fit[term]["estimate"] == pytest.approx(ref.params[name], abs=1e-12)
        assert fit[term]["se"] == pytest.approx(ref.bse[name], rel=1e-9)
        assert fit[term]["df"] == ref.df_resid
        assert fit[term]["p"] == pytest.approx(ref.pvalues[name], rel=1e-9)
        assert fit[term]["ci_low"] == pytest.approx(ci.loc[name, 0], rel=1e-9)
    # every network kept, even one with no correct trial in a cell
    assert fit["congruency"]["networks"] == 12
    assert fit["congruency"]["observations"] == len(data) < 48
    counts = data.groupby(["congruency", "size"])["network"].nunique()
    assert fit["congruency"]["cells"]["incongruent_small"] == counts[(0.5, 0.5)]
    # the correct trials carry no error effect: the truth, 0.03, is inside the interval
    assert fit["congruency"]["ci_low"] < TRUTH["congruency"] < fit["congruency"]["ci_high"]


def test_with_every_cell_the_within_fit_estimates_the_networks_contrasts():
    from icub_affordance.analysis.trial_effects import within_network_fit

    df = synthetic(seed=4)
    fit, contrasts = within_network_fit(df, "rmse"), network_contrasts(df)
    for term in ("congruency", "size", "congruency:size"):
        assert fit[term]["estimate"] == pytest.approx(contrasts[term]["estimate"], abs=1e-12)


def test_a_cell_no_network_reaches_leaves_the_terms_untestable():
    from icub_affordance.analysis.trial_effects import with_outcomes, within_network_fit

    df = with_outcomes(with_errors(synthetic(seed=2), rate=1.0))  # no correct incongruent trial
    fit = within_network_fit(df, "rmse_correct")
    assert all(np.isnan(fit[t]["p"]) for t in ("congruency", "size", "congruency:size"))
    assert fit["congruency"]["cells"]["incongruent_large"] == 0


def test_the_errors_are_the_wrong_grip_rates_contrasts():
    from icub_affordance.analysis.trial_effects import outcome_tests, with_outcomes

    df = with_outcomes(with_errors(synthetic(seed=7)))
    errors = outcome_tests(df, "errors")
    per_object = df.groupby(["network", "object", "congruency"])["wrong_grip"].mean()
    by_net = per_object.groupby(["network", "congruency"]).mean().unstack()
    expected = (by_net["incongruent"] - by_net["congruent"]).mean()
    assert errors["congruency"]["estimate"] == pytest.approx(expected, abs=1e-12)


def test_the_interaction_is_twice_the_required_grip_and_the_three_way_four_times_the_shapes():
    df = synthetic(seed=9)
    grips = {("A", "big_ball"): "power", ("A", "small_ball"): "power",
             ("A", "big_cube"): "precision", ("A", "small_cube"): "precision",
             ("B", "big_ball"): "precision", ("B", "small_ball"): "precision",
             ("B", "big_cube"): "power", ("B", "small_cube"): "power"}  # fmt: skip
    means = network_object_means(df).assign(
        grip=lambda d: [grips[(m, o)] for m, o in zip(d["mapping"], d["object"], strict=True)],
        shape=lambda d: d["object"].str.split("_").str[1],
    )
    per_net = means.pivot_table(index=["network", "mapping"], columns="grip", values="rmse")
    required = (per_net["power"] - per_net["precision"]).groupby("mapping").mean().mean()
    shapes = means.pivot_table(index=["network", "mapping"], columns="shape", values="rmse")
    cubes = (shapes["cube"] - shapes["ball"]).groupby("mapping").mean().mean()
    tests = network_contrasts(df)
    assert tests["congruency:size"]["estimate"] == pytest.approx(2 * required, abs=1e-12)
    assert tests["congruency:size:mapping"]["estimate"] == pytest.approx(4 * cubes, abs=1e-12)


def analysed(df: pd.DataFrame) -> dict:
    from icub_affordance.analysis.trial_effects import analyse

    trials = with_errors(df).assign(task="categorisation", congruent=lambda d: d["congruency"].eq(
        "congruent").astype(str))  # fmt: skip
    trials = pd.concat([trials.assign(mode="closed_loop"), trials.assign(mode="teacher_forced")])
    return analyse(trials)


def every_test(result: dict):
    for mode in ("closed_loop", "teacher_forced"):
        yield from result["contrasts"][mode].values()
        for outcome in ("errors", "correct_rt"):
            yield from result[mode][outcome].values()
        yield from result["simple"][mode].values()


def test_every_test_is_holm_adjusted_within_its_named_family():
    result = analysed(synthetic(seed=6))
    families: dict[str, list[dict]] = {}
    for test in every_test(result):
        families.setdefault(test["family"], []).append(test)
    # one run's tests are its exploration: the paper's claims are confirmed over replications
    assert set(families) == {"exploration: closed loop", "exploration: teacher forced"}
    for tests in families.values():
        p = np.array([t["p"] for t in tests])
        ok = np.isfinite(p)
        m = int(ok.sum())  # Holm by hand: (m - j) p_(j), made monotone, capped at 1
        expected = np.minimum(np.maximum.accumulate(np.sort(p[ok]) * (m - np.arange(m))), 1)
        got = np.array([t["p_holm"] for t in tests])[ok][np.argsort(p[ok])]
        assert got == pytest.approx(expected, rel=1e-12)
        assert all(t["family_size"] == ok.sum() for t in tests)
