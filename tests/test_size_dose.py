"""What drives the size effect (icub_affordance.size_dose), on made-up inputs: the size-free
input, the manipulation check, the dose-response's slope recomputed with scipy, the
demonstrations' geometry by hand, and the plan's dose runs."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from conftest import REPO, load_config, load_test_config, som_config
from scipy import stats as sps

from icub_affordance.readings import BY_EXCESS, NULL_CONTROL
from icub_affordance.size_dose import (
    AXES,
    CONTROLS,
    FAMILY_DECLARED,
    FAMILY_MOTOR,
    FAMILY_SLOPES,
    FAMILY_SUMMARY,
    MOST_REPLICATIONS,
    POWER_COLUMNS,
    POWER_EFFECTS,
    SLOPE_COLUMNS,
    SUMMARY_COLUMNS,
    declared_family,
    delivered_doses,
    demo_geometry,
    family_size,
    manipulation_rows,
    motor_tests,
    power,
    power_table,
    replications_for,
    size_free_maps,
    slopes,
    summary,
    variance_components,
)
from icub_affordance.som import active_units, bump, kept_whole, train_soms
from icub_workflow.runs import plan_runs

OBJECTS = ["big_ball", "small_ball", "big_cube", "small_cube"]


def test_the_size_free_input_keeps_the_shape_and_drops_the_size():
    rng = np.random.default_rng(0)
    maps = {o: rng.integers(0, 2, (10, 10)).astype(float) for o in OBJECTS}
    free = size_free_maps(maps, OBJECTS)
    np.testing.assert_array_equal(free["big_ball"], free["small_ball"])
    np.testing.assert_array_equal(free["big_cube"], free["small_cube"])
    np.testing.assert_allclose(free["big_ball"], (maps["big_ball"] + maps["small_ball"]) / 2)
    assert not np.array_equal(free["big_ball"], free["big_cube"])


def test_a_width_of_zero_sends_the_winner_alone_and_a_kept_cluster_is_whole():
    one = bump(10, (0, 9), 0.0)
    assert one.sum() == 1 and one[0, 9] == 1
    for sigma in (0.5, 1.0, 2.0, 3.0):
        centre = kept_whole(10, (0, 9), sigma)
        inside = active_units(bump(10, centre, sigma))
        unclipped = active_units(bump(41, (20, 20), sigma))
        assert inside == unclipped, (sigma, centre)
    assert kept_whole(10, (0, 9), 20.0) == (4, 4)  # wider than the map: the middle
    assert kept_whole(10, (5, 5), 2.0) == (5, 5)  # inside already: unmoved


def test_keeping_clusters_whole_delivers_the_dose_the_edge_cut():
    rng = np.random.default_rng(3)
    big = np.zeros((10, 10))
    big[1:9, 1:9] = 1
    big[2:8, 2:8] = 0  # an outline of 28 edge cells
    small = np.zeros((10, 10))
    small[4:6, 4:6] = 1  # 4
    maps = np.array([big, small, np.roll(big, 1, 0), np.roll(small, 2, 1)])
    maps += rng.uniform(0, 1e-3, maps.shape)
    ratios = {}
    for whole in (False, True):
        config = som_config(object_width_per_edge=0.45, goal_response="grows", keep_whole=whole)
        soms = train_soms(maps, config, seed=1)
        soms_arrays = {"objects": np.array(OBJECTS)} | {
            k: getattr(soms, k) for k in ("object_act", "goal_act")
        }
        rows = manipulation_rows(soms_arrays)
        ratios[whole] = {(r["shape"], r["map"]): r["ratio"] for r in rows}
        for r in rows:
            assert r["ratio"] == pytest.approx(r["large_units"] / r["small_units"])
    assert all(ratios[True][key] >= 2 for key in ratios[True] if key[1] == "object")


def replications_table(
    slope: float, seeds=(1, 2, 3), noise=0.0, equal_grips: bool = False
) -> pd.DataFrame:
    """Per replication (seed) the size effect at the doses 0, 0.3 and 0.6, rising by ``slope``
    per unit of dose, and the removal control; with ``equal_grips``, the equal-grips control too
    (dose 0's maps)."""
    rng = np.random.default_rng(0)
    rows = []
    for seed in seeds:
        tilt = slope + rng.normal(0, noise)
        for dose in (0.0, 0.3, 0.6):
            rows.append(
                {"dose": dose, "cue": "first_step", "seed": seed, "run": f"r{seed}_{dose}",
                 "measure": "rmse", "estimate": 0.01 + tilt * dose + rng.normal(0, 0.001),
                 "cell_mean": 0.1, "ci_low": 0.0, "ci_high": 0.0, "df": 10.0, "p": 0.5,
                 "se": 0.01, "networks": 12}
            )  # fmt: skip
        rows.append(
            {"dose": "removed", "cue": "first_step", "seed": seed, "run": f"r{seed}_x",
             "measure": "rmse", "estimate": -0.02, "cell_mean": 0.1, "ci_low": 0.0,
             "ci_high": 0.0, "df": 10.0, "p": 0.5, "se": 0.01, "networks": 12}
        )  # fmt: skip
        if equal_grips:
            rows.append(
                {"dose": "equal_grips", "cue": "first_step", "seed": seed, "run": f"r{seed}_eq",
                 "measure": "rmse", "estimate": 0.005 + rng.normal(0, 0.002), "cell_mean": 0.1,
                 "ci_low": 0.0, "ci_high": 0.0, "df": 10.0, "p": 0.5, "se": 0.01,
                 "networks": 12}
            )  # fmt: skip
    return pd.DataFrame(rows)


def manipulation_table(replications: pd.DataFrame) -> pd.DataFrame:
    """The manipulation check of every run of ``replications``: the small clusters 4 units, the
    large ones growing with the nominal dose, each run and shape a little apart (so a run's
    delivered dose is not a function of its nominal dose); the controls at dose 0's maps."""
    rng = np.random.default_rng(5)
    rows = []
    for run in replications.drop_duplicates("run").to_dict("records"):
        for shape in ("ball", "cube"):
            for name in ("object", "goal"):
                dose = 0.0 if run["dose"] in CONTROLS else float(run["dose"])
                large = 4.0 if dose == 0 else 4.0 * (1 + 4 * dose) + rng.uniform(-1, 1)
                rows.append(
                    {k: run[k] for k in ("dose", "cue", "seed", "run")}
                    | {"shape": shape, "map": name, "large_units": large, "small_units": 4.0,
                       "ratio": large / 4.0}
                )  # fmt: skip
    return pd.DataFrame(rows)


def test_the_slope_is_each_replications_own_fit_tested_over_replications():
    table = replications_table(0.05, noise=0.01)
    out = slopes(table, manipulation_table(table))
    assert list(out.columns) == SLOPE_COLUMNS and list(out["axis"]) == ["nominal", "delivered"]
    out = out.iloc[0]
    per_seed = [
        sps.linregress(g["dose"].astype(float), g["estimate"]).slope
        for _, g in table[table["dose"] != "removed"].groupby("seed")
    ]
    test = sps.ttest_1samp(per_seed, 0.0)
    assert out["slope"] == pytest.approx(np.mean(per_seed))
    assert out["p"] == pytest.approx(test.pvalue)
    assert out["replications"] == 3 and out["df"] == 2
    low, high = sps.t.interval(0.95, 2, loc=np.mean(per_seed), scale=sps.sem(per_seed))
    assert (out["ci_low"], out["ci_high"]) == pytest.approx((low, high))


def test_the_summary_tests_each_dose_over_replications_and_carries_the_check():
    table = replications_table(0.05)
    checks = pd.DataFrame(
        [
            {"dose": d, "cue": "first_step", "seed": s,
             "run": f"r{s}_{'x' if d == 'removed' else d}", "shape": sh, "map": m,
             "large_units": 4.0 * r, "small_units": 4.0, "ratio": r}
            for d, r in ((0.0, 1.0), (0.3, 2.0), (0.6, 3.0), ("removed", 1.0))
            for s in (1, 2, 3)
            for sh in ("ball", "cube")
            for m in ("object", "goal")
        ]
    )  # fmt: skip
    out = summary(table, checks)
    assert list(out.columns) == SUMMARY_COLUMNS
    assert list(out["dose"]) == [0.0, 0.3, 0.6, "removed"]
    row = out[out["dose"] == 0.3].iloc[0]
    estimates = table[table["dose"] == 0.3]["estimate"]
    assert row["diff"] == pytest.approx(estimates.mean())
    assert row["p"] == pytest.approx(sps.ttest_1samp(estimates, 0.0).pvalue)
    assert row["large_small_ratio_goal"] == 2.0 and row["replications"] == 3
    assert row["relative_to_mean"] == pytest.approx(estimates.mean() / 0.1)
    from statsmodels.stats.multitest import multipletests

    # the removal rows' replications agree exactly: no spread, no p (and no place in Holm's)
    assert np.isnan(out[out["dose"] == "removed"]["p"]).all()
    tested = np.isfinite(out["p"].to_numpy(dtype=float))
    holm = multipletests(out["p"].to_numpy(dtype=float)[tested], method="holm")[1]
    np.testing.assert_allclose(out["p_holm"].to_numpy(dtype=float)[tested], holm)


def test_the_delivered_dose_is_the_goal_maps_log_ratio():
    checks = pd.DataFrame(
        [
            {"run": "a", "shape": "ball", "map": "goal", "large_units": 8.0, "small_units": 2.0},
            {"run": "a", "shape": "cube", "map": "goal", "large_units": 6.0, "small_units": 3.0},
            {"run": "a", "shape": "ball", "map": "object", "large_units": 50.0, "small_units": 1.0},
            {"run": "b", "shape": "ball", "map": "goal", "large_units": 1.0, "small_units": 1.0},
            {"run": "b", "shape": "cube", "map": "goal", "large_units": 1.0, "small_units": 1.0},
        ]
    )  # fmt: skip
    delivered = delivered_doses(checks)
    assert delivered["a"] == pytest.approx((np.log(4) + np.log(2)) / 2)  # the Object map's not
    assert delivered["b"] == 0


def test_the_summary_carries_the_delivered_dose():
    table = replications_table(0.05)
    checks = manipulation_table(table)
    out = summary(table, checks).set_index("dose")
    goal = checks[checks["map"] == "goal"]
    for dose in (0.0, 0.3, 0.6, "removed"):
        rows = goal[goal["dose"] == dose]
        expected = np.log(rows["large_units"] / rows["small_units"]).mean()
        assert out.loc[dose, "delivered_dose"] == pytest.approx(expected)
    assert out.loc[0.0, "delivered_dose"] == 0 == out.loc["removed", "delivered_dose"]
    assert out.loc[0.6, "delivered_dose"] > out.loc[0.3, "delivered_dose"] > 0


def test_the_slope_on_the_delivered_dose_uses_each_runs_own_dose():
    table = replications_table(0.05, noise=0.01)
    checks = manipulation_table(table)
    out = slopes(table, checks).set_index("axis").loc["delivered"]
    delivered = delivered_doses(checks)
    dosed = table[table["dose"] != "removed"]
    per_seed = [
        sps.linregress(delivered.loc[g["run"]].to_numpy(), g["estimate"]).slope
        for _, g in dosed.groupby("seed")
    ]
    assert out["slope"] == pytest.approx(np.mean(per_seed))
    assert out["p"] == pytest.approx(sps.ttest_1samp(per_seed, 0.0).pvalue)
    assert out["replications"] == 3 and out["df"] == 2
    # the removal control is in neither slope
    moved = table.assign(estimate=np.where(table["dose"] == "removed", 5.0, table["estimate"]))
    pd.testing.assert_frame_equal(slopes(moved, checks), slopes(table, checks))


# ---- the Holm families the tables name --------------------------------------------------------


def holm_within_families(table: pd.DataFrame, across: tuple[str, ...] = ()) -> set:
    """Holm recomputed (statsmodels) over the rows of each named family of a table as its CSV
    reads back, against the table's ``p_holm``; the families seen. A null control's rows and
    those of a measure tested by its excess are in no family (empty ``p_holm``); the families
    ``across`` span more than this table and are checked by the caller."""
    import io

    from statsmodels.stats.multitest import multipletests

    back = pd.read_csv(io.StringIO(table.to_csv(index=False)))
    for name, rows in back.groupby("family"):
        if name in (NULL_CONTROL, BY_EXCESS):
            assert rows["p_holm"].isna().all(), name
            continue
        if name in across:
            continue
        tested = rows["p"].notna()
        expected = multipletests(rows.loc[tested, "p"].to_numpy(dtype=float), method="holm")[1]
        assert rows.loc[tested, "p_holm"].to_numpy() == pytest.approx(expected), name
        assert rows.loc[~tested, "p_holm"].isna().all(), name
    return set(back["family"])


EXCESS_STUDY = ("rmse_per_grip_distance", "rmse_per_grip_distance_null")


def study_with_a_null_control(equal_grips: bool = False) -> pd.DataFrame:
    """The study's replications on the RMSE and on RMSE per grip distance with its null control
    and its excess over it (``measures.analysed``): a run's excess estimate is its measure's
    minus its null control's, as the per-network contrasts are linear in the trials."""
    rng = np.random.default_rng(2)
    measures = []
    for measure in ("rmse", *EXCESS_STUDY):
        table = replications_table(0.05, noise=0.01, equal_grips=equal_grips)
        table = table.assign(measure=measure)
        table["estimate"] += rng.normal(0, 0.01, len(table))
        measures.append(table)
    excess = measures[1].assign(
        measure="rmse_per_grip_distance_excess",
        estimate=measures[1]["estimate"] - measures[2]["estimate"],
    )
    both = pd.concat([*measures, excess], ignore_index=True)
    return pd.concat([both, both.assign(cue="all_steps")], ignore_index=True)


def study_checks(table: pd.DataFrame) -> pd.DataFrame:
    return pd.concat(
        [manipulation_table(table[table["cue"] == c]).assign(cue=c) for c in table["cue"].unique()]
    )


def test_the_summary_and_slopes_name_their_holm_families():
    """The null control and the raw measure tested by its excess are shown, in no family; the
    excess is a hypothesis beside the RMSE."""
    table = study_with_a_null_control()
    checks = study_checks(table)
    out = summary(table, checks)
    assert holm_within_families(out) == {FAMILY_SUMMARY, NULL_CONTROL, BY_EXCESS}
    families = out.groupby("measure")["family"].unique().map(list).to_dict()
    assert families == {
        "rmse": [FAMILY_SUMMARY],
        "rmse_per_grip_distance": [BY_EXCESS],
        "rmse_per_grip_distance_null": [NULL_CONTROL],
        "rmse_per_grip_distance_excess": [FAMILY_SUMMARY],
    }
    assert out.loc[out["measure"].isin(EXCESS_STUDY), "p_holm"].isna().all()
    assert out.loc[out["measure"].isin(EXCESS_STUDY), "p"].notna().any()  # shown, with its p
    assert family_size(out, FAMILY_SUMMARY) == int(
        out.loc[out["family"] == FAMILY_SUMMARY, "p"].notna().sum()
    )
    fits = slopes(table, checks)
    assert holm_within_families(fits) == {FAMILY_SLOPES, NULL_CONTROL, BY_EXCESS}
    assert (fits.loc[fits["measure"] == "rmse_per_grip_distance", "family"] == BY_EXCESS).all()
    assert fits.loc[fits["measure"].isin(EXCESS_STUDY), "p_holm"].isna().all()
    assert len(fits) == 2 * 2 * 4  # cue timing x axis x measure, both axes one family


def test_the_declared_tests_are_one_family_across_the_summary_and_slopes():
    """The config's declared tests (the RMSE's size effect at dose 0 and under equal grips, and
    its slope on the delivered dose, under each cue timing): Holm over those six rows of the
    two tables alone; every other hypothesis re-adjusted within its exploration family without
    them; the rows in no family, and every statistic but p_holm and family, as they were."""
    from statsmodels.stats.multitest import multipletests

    table = study_with_a_null_control(equal_grips=True)
    checks = study_checks(table)
    summ, fits = summary(table, checks), slopes(table, checks)
    declared = {"doses": [0.0, "equal_grips"], "slopes": ["delivered"], "measure": "rmse"}
    out_summary, out_slopes = declared_family(summ, fits, declared)
    chosen_summary = out_summary["family"] == FAMILY_DECLARED
    chosen_slopes = out_slopes["family"] == FAMILY_DECLARED
    assert set(out_summary.loc[chosen_summary, "measure"]) == {"rmse"}
    assert sorted(out_summary.loc[chosen_summary, "dose"].astype(str)) == sorted(
        ["0.0", "equal_grips"] * 2
    )
    assert set(out_slopes.loc[chosen_slopes, "measure"]) == {"rmse"}
    assert list(out_slopes.loc[chosen_slopes, "axis"]) == ["delivered"] * 2
    assert sorted(out_slopes.loc[chosen_slopes, "cue"]) == ["all_steps", "first_step"]
    p = np.concatenate([out_summary.loc[chosen_summary, "p"], out_slopes.loc[chosen_slopes, "p"]])
    assert len(p) == 6 and np.isfinite(p).all()
    adjusted = np.concatenate(
        [out_summary.loc[chosen_summary, "p_holm"], out_slopes.loc[chosen_slopes, "p_holm"]]
    )
    assert adjusted == pytest.approx(multipletests(p, method="holm")[1])
    # the rest: each exploration family over its own rows, the declared ones no longer in it
    assert holm_within_families(out_summary, across=(FAMILY_DECLARED,)) == {
        FAMILY_DECLARED, FAMILY_SUMMARY, NULL_CONTROL, BY_EXCESS}  # fmt: skip
    assert holm_within_families(out_slopes, across=(FAMILY_DECLARED,)) == {
        FAMILY_DECLARED, FAMILY_SLOPES, NULL_CONTROL, BY_EXCESS}  # fmt: skip
    assert family_size(out_summary, FAMILY_SUMMARY) == family_size(summ, FAMILY_SUMMARY) - 4
    assert family_size(out_slopes, FAMILY_SLOPES) == family_size(fits, FAMILY_SLOPES) - 2
    for before, after in ((summ, out_summary), (fits, out_slopes)):
        same = after.columns.drop(["p_holm", "family"])
        pd.testing.assert_frame_equal(after[same], before[same])
        untested = before["family"].isin([NULL_CONTROL, BY_EXCESS])
        assert (after.loc[untested, "family"] == before.loc[untested, "family"]).all()
        assert after.loc[untested, "p_holm"].isna().all()
    # the tables given are left as they were
    assert not (summ["family"] == FAMILY_DECLARED).any()
    assert not (fits["family"] == FAMILY_DECLARED).any()


def test_a_declared_test_the_tables_do_not_hold_is_refused():
    table = study_with_a_null_control()  # no equal-grips control
    checks = study_checks(table)
    declared = {"doses": [0.0, "equal_grips"], "slopes": ["delivered"], "measure": "rmse"}
    with pytest.raises(ValueError, match="size_dose.declared names 6 tests"):
        declared_family(summary(table, checks), slopes(table, checks), declared)


def test_the_motor_table_names_its_holm_family():
    rng = np.random.default_rng(4)
    rows = [
        {"dose": dose, "cue": "first_step", "seed": seed, "network": net, "object": obj,
         "rmse": rng.normal(0.1, 0.01), "demo_path_length": rng.uniform(0, 1),
         "demo_spread": rng.uniform(0, 1), "demo_grip_distance": rng.uniform(0, 1)}
        for dose in ("removed", 0.6)
        for seed in (1, 2, 3)
        for net in range(4)
        for obj in OBJECTS
    ]  # fmt: skip
    out = motor_tests(pd.DataFrame(rows))
    assert holm_within_families(out) == {FAMILY_MOTOR}
    assert list(out.columns[-2:]) == ["p_holm", "family"]


# ---- the design's power -----------------------------------------------------------------------


def test_power_is_the_z_tests_in_the_limit():
    """Without replication variance and with very many replications the t-test is the z-test:
    power Phi(ncp - z) + Phi(-ncp - z) with ncp = effect sqrt(R) / (sigma_net / sqrt(networks))."""
    networks, sigma_net, many = 12, 0.02, 10**6
    tau = sigma_net / np.sqrt(networks)
    z = sps.norm.ppf(0.975)
    for ncp in (1.0, 2.5, 3.5):
        effect = ncp * tau / np.sqrt(many)
        expected = sps.norm.cdf(ncp - z) + sps.norm.cdf(-ncp - z)
        assert power(effect, many, networks, 0.0, sigma_net) == pytest.approx(expected, abs=1e-4)


def test_power_at_no_effect_is_alpha_and_grows_with_replications_and_effect():
    args = {"networks": 12, "sigma_rep": 0.004, "sigma_net": 0.02}
    for alpha in (0.05, 0.01):
        assert power(0.0, 3, **args, alpha=alpha) == pytest.approx(alpha)
    by_replications = [power(0.01, r, **args) for r in (2, 3, 5, 10, 30)]
    assert np.all(np.diff(by_replications) > 0)
    by_effect = [power(e, 3, **args) for e in (0.005, 0.01, 0.02, 0.04)]
    assert np.all(np.diff(by_effect) > 0)
    # far into the noncentral t's tails (scipy's lower tail gives NaN there): still defined
    sharp = [power(e, r, 12, 0.0015, 0.0097) for r in (2, 3, 10) for e in (0.01, 0.02, 0.04)]
    assert np.all(np.isfinite(sharp)) and sharp[-1] == pytest.approx(1.0)
    assert power(0.01, 3, **args, alpha=0.001) < power(0.01, 3, **args)
    assert power(-0.02, 3, **args) == pytest.approx(power(0.02, 3, **args))  # two-sided
    assert np.isnan(power(0.01, 1, **args))  # one replication: no test over replications
    assert np.isnan(power(0.01, 3, 12, 0.0, 0.0))  # no variance: no test
    fewest = replications_for(0.02, **args)
    assert power(0.02, fewest, **args) >= 0.8 > power(0.02, fewest - 1, **args)
    assert replications_for(1e-6, **args) is None  # not within MOST_REPLICATIONS
    assert power(1e-6, MOST_REPLICATIONS, **args) < 0.8


def test_variance_components_by_the_method_of_moments():
    rows = pd.DataFrame(
        {"estimate": [0.01, 0.03, 0.05], "se": [0.004, 0.006, 0.005], "networks": [12, 12, 12]}
    )
    parts = variance_components(rows)
    se2 = np.array([0.004, 0.006, 0.005]) ** 2
    assert parts["sigma_net"] == pytest.approx(np.sqrt(12 * se2.mean()))
    between = np.var([0.01, 0.03, 0.05], ddof=1) - se2.mean()
    assert parts["sigma_rep"] == pytest.approx(np.sqrt(between))
    assert parts["networks"] == 12
    # estimates closer together than their own se's say: no variance between replications
    tight = variance_components(rows.assign(estimate=[0.030, 0.031, 0.029]))
    assert tight["sigma_rep"] == 0 and tight["sigma_net"] == parts["sigma_net"]


def test_the_power_table_of_the_default_design():
    table = study_with_a_null_control()
    table["networks"] = 12
    out = power_table(table, tests=20)
    assert list(out.columns) == POWER_COLUMNS
    assert len(out) == 2 * len(POWER_EFFECTS) and set(out["measure"]) == {"rmse"}
    for cue, rows in out.groupby("cue"):
        zero = table[(table["cue"] == cue) & (table["measure"] == "rmse") & (table["dose"] == 0.0)]
        parts = variance_components(zero)
        assert (rows["sigma_rep"] == parts["sigma_rep"]).all()
        assert (rows["replications"] == 3).all() and (rows["networks"] == 12).all()
        for row in rows.to_dict("records"):
            design = (row["replications"], 12, row["sigma_rep"], row["sigma_net"])
            assert row["power"] == pytest.approx(power(row["effect"], *design))
            assert row["alpha_holm_bound"] == pytest.approx(0.05 / 20)
            assert row["power_holm_bound"] == pytest.approx(
                power(row["effect"], *design, alpha=0.05 / 20)
            )
            assert row["power_holm_bound"] <= row["power"]
            needed = replications_for(row["effect"], *design[1:])
            if needed is None:
                assert pd.isna(row["replications_for_80"])
            else:
                assert row["replications_for_80"] == needed
        assert np.all(np.diff(rows["power"].to_numpy()) > 0)  # the effects in increasing order
    # only the dose-0 rows count
    moved = table.assign(estimate=np.where(table["dose"] == 0.6, 9.0, table["estimate"]))
    pd.testing.assert_frame_equal(power_table(moved, tests=20), out)


def test_the_demonstrations_geometry_by_hand():
    angles = np.zeros((4, 2, 2, 3, 16))
    angles[0, 0, :, 1, 0] = 0.3  # object 0, power: out 0.3 and back 0.3
    angles[0, 1, 0, :, 1] = 0.1  # object 0, precision: one sequence off by 0.1 throughout
    angles[0, 1, :, 2, 2] = 0.4  # both precision sequences end 0.4 along DoF 2
    geometry = demo_geometry(angles, OBJECTS).set_index(["object", "grip"])
    assert geometry.loc[("big_ball", 0), "demo_path_length"] == pytest.approx(0.6)
    assert geometry.loc[("big_ball", 1), "demo_spread"] == pytest.approx(0.05)
    assert geometry.loc[("big_ball", 0), "demo_grip_distance"] == pytest.approx(np.hypot(0.4, 0.05))
    assert geometry.loc[("small_cube", 0), "demo_path_length"] == 0


def test_an_error_that_follows_the_path_length_is_found():
    rng = np.random.default_rng(1)
    rows = []
    for seed in (1, 2, 3, 4):  # the runs of four replications
        for net in range(6):
            for k, obj in enumerate(OBJECTS):
                length = [1.0, 0.4, 1.3, 0.7][k]
                rows.append(
                    {"dose": "removed", "cue": "first_step", "seed": seed, "network": net,
                     "object": obj, "rmse": 0.05 + 0.04 * length + rng.normal(0, 0.002),
                     "demo_path_length": length, "demo_spread": rng.uniform(0, 1),
                     "demo_grip_distance": [0.2, 0.2, 0.5, 0.5][k]}
                )  # fmt: skip
    out = motor_tests(pd.DataFrame(rows)).set_index("geometry")
    # the unit is the replication (its networks share its demonstrations)
    assert out.loc["demo_path_length", "replications"] == 4
    assert out.loc["demo_path_length", "networks"] == 24
    assert out.loc["demo_path_length", "df"] == 3
    assert out.loc["demo_path_length", "p_holm"] < 0.01
    assert out.loc["demo_path_length", "estimate"] > 0


def test_the_plan_makes_a_run_per_dose_cue_and_replication():
    config = load_config() | {"robustness": False}
    plan = plan_runs(config)
    study = config["size_dose"]
    assert study["removal"] and study["equal_grips"]  # the default runs both controls
    assert CONTROLS == ("removed", "equal_grips")
    doses = len(study["doses"]) + bool(study["removal"]) + bool(study["equal_grips"])
    assert len(plan.size_dose) == doses * len(study["categorisation_cue"]) * study["replications"]
    per_dose = pd.Series([str(row["dose"]) for row in plan.size_dose]).value_counts()
    expected = len(study["categorisation_cue"]) * study["replications"]
    assert per_dose.to_dict() == {
        str(d): expected for d in [*study["doses"], "removed", "equal_grips"]
    }
    for row in plan.size_dose:
        run = plan.config(row["run"])
        assert run["network"]["categorisation_cue"] == row["cue"] and run["seed"] == row["seed"]
        if row["dose"] == "removed":
            assert run["size_free_input"] and plan.stage_run(row["run"], "demos") != row["run"]
            assert run["grip_distance"] == "natural"
        elif row["dose"] == "equal_grips":  # dose 0's maps, every object's grips at one distance
            assert run["grip_distance"] == "equal" and not run["size_free_input"]
            soms = run["soms"]
            assert soms["object_width_per_edge"] == 0
            assert soms["goal_response"] == "grows" and soms["keep_whole"]
        else:
            soms = run["soms"]
            assert soms["object_width_per_edge"] == row["dose"]
            assert soms["goal_response"] == "grows" and soms["keep_whole"]
            assert run["grip_distance"] == "natural" and not run["size_free_input"]
    assert len({row["run"] for row in plan.size_dose}) == len(plan.size_dose)
    # without the control, no equal-grips run
    fewer = plan_runs(config | {"size_dose": study | {"equal_grips": False}}).size_dose
    assert len(fewer) == (doses - 1) * len(study["categorisation_cue"]) * study["replications"]
    assert not any(row["dose"] == "equal_grips" for row in fewer)
    seeds = {row["seed"] for row in plan.size_dose}
    # the study's own seeds, in order: none of them the config's (whose runs others read)
    assert seeds == set(study["seeds"][: study["replications"]]) and config["seed"] not in seeds
    robust = plan_runs(config | {"robustness": True})
    assert len({row["seed"] for row in robust.size_dose}) == study["robustness_replications"]


# ---- the study in the built test pipeline -----------------------------------------------------


def test_the_study_writes_its_contract_and_the_dose_arrives(built):
    """data/size_dose/: one summary row per cue timing, measure and dose (and each control
    the config runs: removal, equal grips), a slope per cue timing and measure, the figure; at
    the largest dose the Goal map's large cluster has at least twice the small one's units, for
    each shape and replication."""
    folder = built / "data" / "size_dose"
    summary = pd.read_csv(folder / "summary.csv", keep_default_na=False)
    contract = ["dose", "cue", "measure", "replications", "large_small_ratio_object",
                "large_small_ratio_goal", "diff", "ci_low", "ci_high"]  # fmt: skip
    assert summary.columns[: len(contract)].tolist() == contract
    config = load_test_config()["size_dose"]
    controls = [c for c in CONTROLS if config["removal" if c == "removed" else c]]
    doses = {str(float(d)) for d in config["doses"]} | set(controls)
    assert set(summary["dose"].astype(str)) == doses
    assert (summary["replications"] == config["replications"]).all()
    slope = pd.read_csv(folder / "slope.csv")
    assert {"cue", "measure", "axis", "slope", "ci_low", "ci_high", "p"} <= set(slope.columns)
    pairs = set(zip(summary["cue"], summary["measure"], strict=True))
    assert len(slope) == len(AXES) * len(pairs) and set(slope["axis"]) == set(AXES)
    powers = pd.read_csv(folder / "power.csv")
    assert list(powers.columns) == POWER_COLUMNS
    assert len(powers) == len(config["categorisation_cue"]) * len(POWER_EFFECTS)
    assert (powers["replications"] == config["replications"]).all()
    checks = pd.read_csv(folder / "manipulation.csv", keep_default_na=False)
    top = checks[checks["dose"].astype(str) == str(float(max(config["doses"])))]
    goal = top[top["map"] == "goal"]
    assert set(goal["shape"]) == {"ball", "cube"} and (goal["ratio"] >= 2).all(), goal
    removed = checks[checks["dose"] == "removed"]
    assert (removed["ratio"] == 1).all()  # no size: equal clusters
    assert (folder / "dose_response.png").stat().st_size > 10_000


# ---- the chapter's sentences follow their tests ---------------------------------------------


def test_the_size_verdict_words_follow_their_holm_tests():
    from icub_workflow.book import text

    row = {"estimate": -0.03, "p": 0.001, "p_holm": 0.01}
    assert text.verdict_word(row) == "reversed"
    assert text.verdict_word(row | {"estimate": 0.03}) == "reproduced"
    # a raw p under 0.05 that Holm lifts above it: not shown, whatever the raw interval
    assert text.verdict_word(row | {"p": 0.01, "p_holm": 0.2}) == "not shown"
    assert text.verdict_word(row | {"p": float("nan"), "p_holm": float("nan")}) == "not testable"
    assert text.trend_phrase(row) == "away from the paper's direction"
    assert text.trend_phrase(row | {"estimate": 0.03}) == "towards the paper's direction"
    assert text.trend_phrase(row | {"p_holm": 0.3}) == "by no amount its test shows"
    assert text.named_measures(["demo_path_length", "demo_grip_distance"]) == (
        "the path length and the grips' distance"
    )
    assert text.named_measures([]) == "none of the measures"


def test_the_size_chapters_verdicts_flip_with_their_statistics(tmp_path):
    """The chapter's values from this build's study tables; a flipped slope, effect or p flips
    the words, and every verdict names the numbers it rests on."""
    from icub_workflow.book import pages

    folder = REPO / "data" / "size_dose"
    if not (folder / "summary.csv").exists():
        pytest.skip("needs the size study's outputs (data/size_dose)")
    names = {"size_summary.csv": "summary.csv", "size_slope.csv": "slope.csv",
             "size_power.csv": "power.csv", "size_grips.csv": "grip_distance.csv",
             "size_manipulation.csv": "manipulation.csv", "size_motor.csv": "motor.csv",
             "size_geometry.csv": "geometry.csv"}  # fmt: skip
    inputs = {name: folder / file for name, file in names.items()}
    config = load_config()

    def chapter(**changed):
        for name, change in changed.items():
            frame = change(pd.read_csv(inputs[f"size_{name}.csv"]))
            frame.to_csv(tmp_path / f"{name}.csv", index=False)
        paths = inputs | {f"size_{n}.csv": tmp_path / f"{n}.csv" for n in changed}
        values, tables = pages.size_study(paths, config)
        return pages.traced({"size": values}), tables

    found, tables = chapter()
    size = found["size"]
    assert found["claims"]["size"]["slope_verdict_all_steps"] == [
        "size.slope_all_steps", "size.slope_p_holm_all_steps"]  # fmt: skip
    declared = tables["size_tests"]
    assert set(declared["verdict"]) <= {"reproduced", "reversed", "not shown"}
    # the slope's interval as the analysis wrote it
    low, high = size["slope_ci_low_all_steps"], size["slope_ci_high_all_steps"]
    assert low <= size["slope_all_steps"] <= high

    def negate(frame, measure="rmse"):
        rows = frame["measure"] == measure
        frame.loc[rows, ["diff" if "diff" in frame else "slope", "ci_low", "ci_high"]] = -frame.loc[
            rows, ["diff" if "diff" in frame else "slope", "ci_high", "ci_low"]
        ].values
        return frame

    flipped, _ = chapter(slope=negate, summary=negate, grips=negate)
    turned = {"away from the paper's direction": "towards the paper's direction",
              "towards the paper's direction": "away from the paper's direction"}  # fmt: skip
    turned |= {"reversed": "reproduced", "reproduced": "reversed"}
    for key, word in size.items():
        if key in found["claims"]["size"] and word in turned:
            assert flipped["size"][key] == turned[word], key
    lifted, _ = chapter(
        **dict.fromkeys(("slope", "summary", "grips"), lambda f: f.assign(p_holm=0.5))
    )
    assert lifted["size"]["slope_verdict_first_step"] == "by no amount its test shows"
    assert lifted["size"]["grips_verdict_all_steps"] == "by no amount its test shows"
    for key in ("none", "removed", "equal"):
        assert lifted["size"][f"{key}_verdict_first_step"] == "not shown", key
    unmoved, _ = chapter(motor=lambda f: f.assign(p_holm=0.5))
    assert unmoved["size"]["motor_found"] == "none of the measures"


# ---- size apart from the grips' distance ----------------------------------------------------


def test_equal_grips_put_every_objects_grips_at_one_distance_and_keep_the_start():
    from icub_affordance.train import equal_grip_distance, final_grip_distances

    rng = np.random.default_rng(3)
    start = rng.uniform(0.3, 0.7, 16)
    ends = rng.uniform(0.3, 0.7, (4, 2, 16))
    ends[:, 1] = ends[:, 0] + np.array([0.2, 0.05, 0.15, 0.04])[:, None]  # large, small, ...
    t = np.linspace(0, 1, 10)[None, None, None, :, None]
    demos = (
        start + t * (ends[:, :, None, None, :] - start) + rng.normal(0, 0.002, (4, 2, 5, 10, 16))
    )
    demos[:, :, :, 0] = start  # one common initial posture
    before = final_grip_distances(demos)
    after = final_grip_distances(equal_grip_distance(demos))
    assert np.ptp(before) > 0.5 and after == pytest.approx(np.full(4, before.mean()), rel=1e-9)
    moved = equal_grip_distance(demos)
    assert np.array_equal(moved[:, :, :, 0], demos[:, :, :, 0])  # the start does not move
    # each object's grips move about their own midpoint
    assert moved.mean(axis=1) == pytest.approx(demos.mean(axis=1), abs=1e-12)
    # and stay within the joints' ranges
    wide = equal_grip_distance(demos, scale=np.array([5.0, 5.0, 5.0, 5.0]))
    assert wide.min() >= 0 and wide.max() <= 1


def test_a_declared_test_the_study_does_not_run_is_refused():
    from icub_workflow.config_checks import ConfigError, check_config

    config = load_config()
    check_config(config)  # the default's declared tests are all run
    study = config["size_dose"] | {"equal_grips": False}
    with pytest.raises(ConfigError, match=r"size_dose\.declared\.doses.*equal_grips"):
        check_config(config | {"size_dose": study})


def test_the_grips_share_is_the_paired_difference_over_replications():
    from scipy import stats as sps

    from icub_affordance.size_dose import FAMILY_GRIPS, grip_distance_share

    rng = np.random.default_rng(8)
    rows = []
    for cue in ("first_step", "all_steps"):
        for seed in (11, 12, 13, 14):
            for dose in ("0.0", "0.6", "equal_grips"):
                effect = rng.normal(-0.02 if dose == "0.0" else 0.0, 0.005)
                rows.append(
                    {"dose": dose, "cue": cue, "seed": seed, "measure": "rmse", "estimate": effect}
                )
    table = pd.DataFrame(rows)
    share = grip_distance_share(table).set_index("cue")
    for cue in ("first_step", "all_steps"):
        mine = table[table["cue"] == cue].pivot(index="seed", columns="dose", values="estimate")
        diff = mine["0.0"] - mine["equal_grips"]
        test = sps.ttest_1samp(diff, 0)
        assert share.loc[cue, "diff"] == pytest.approx(diff.mean(), abs=1e-12)
        assert share.loc[cue, "p"] == pytest.approx(test.pvalue, rel=1e-9)
        assert share.loc[cue, "df"] == 3
    assert (share["family"] == FAMILY_GRIPS).all()
    assert share["p_holm"].to_numpy() == pytest.approx(
        np.minimum(np.maximum.accumulate(np.sort(share["p"].to_numpy()) * [2, 1]), 1)[
            np.argsort(np.argsort(share["p"].to_numpy()))
        ]
    )
