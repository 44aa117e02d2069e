"""What drives the size effect (icub_affordance.size_dose), on made-up inputs: the size-free
input, the manipulation check, the dose-response's slope recomputed with scipy, the
demonstrations' geometry by hand, and the plan's dose runs."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from conftest import load_config, load_test_config, som_config
from scipy import stats as sps

from icub_affordance.size_dose import (
    demo_geometry,
    manipulation_rows,
    motor_tests,
    ranked_like_size,
    size_free_maps,
    slopes,
    summary,
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


def replications_table(slope: float, seeds=(1, 2, 3), noise=0.0) -> pd.DataFrame:
    rng = np.random.default_rng(0)
    rows = []
    for seed in seeds:
        tilt = slope + rng.normal(0, noise)
        for dose in (0.0, 0.3, 0.6):
            rows.append(
                {"dose": dose, "cue": "first_step", "seed": seed, "run": f"r{seed}_{dose}",
                 "measure": "rmse", "estimate": 0.01 + tilt * dose + rng.normal(0, 0.001),
                 "cell_mean": 0.1, "ci_low": 0.0, "ci_high": 0.0, "df": 10.0, "p": 0.5,
                 "se": 0.01}
            )  # fmt: skip
        rows.append(
            {"dose": "removed", "cue": "first_step", "seed": seed, "run": f"r{seed}_x",
             "measure": "rmse", "estimate": -0.02, "cell_mean": 0.1, "ci_low": 0.0,
             "ci_high": 0.0, "df": 10.0, "p": 0.5, "se": 0.01}
        )  # fmt: skip
    return pd.DataFrame(rows)


def test_the_slope_is_each_replications_own_fit_tested_over_replications():
    table = replications_table(0.05, noise=0.01)
    out = slopes(table).iloc[0]
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
            {"dose": d, "cue": "first_step", "seed": s, "shape": sh, "map": m, "ratio": r}
            for d, r in ((0.0, 1.0), (0.3, 2.0), (0.6, 3.0), ("removed", 1.0))
            for s in (1, 2, 3)
            for sh in ("ball", "cube")
            for m in ("object", "goal")
        ]
    )
    out = summary(table, checks)
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
    doses = len(study["doses"]) + bool(study["removal"])
    assert len(plan.size_dose) == doses * len(study["categorisation_cue"]) * study["replications"]
    for row in plan.size_dose:
        run = plan.config(row["run"])
        assert run["network"]["categorisation_cue"] == row["cue"] and run["seed"] == row["seed"]
        if row["dose"] == "removed":
            assert run["size_free_input"] and plan.stage_run(row["run"], "demos") != row["run"]
        else:
            soms = run["soms"]
            assert soms["object_width_per_edge"] == row["dose"]
            assert soms["goal_response"] == "grows" and soms["keep_whole"]
    seeds = {row["seed"] for row in plan.size_dose}
    assert config["seed"] in seeds and len(seeds) == study["replications"]
    robust = plan_runs(config | {"robustness": True})
    assert len({row["seed"] for row in robust.size_dose}) == study["robustness_replications"]


# ---- the study in the built test pipeline -----------------------------------------------------


def test_the_study_writes_its_contract_and_the_dose_arrives(built):
    """data/size_dose/: one summary row per cue timing, measure and dose (and the removal
    control), a slope per cue timing and measure, the figure; at the largest dose the Goal map's
    large cluster has at least twice the small one's units, for each shape and replication."""
    folder = built / "data" / "size_dose"
    summary = pd.read_csv(folder / "summary.csv", keep_default_na=False)
    contract = ["dose", "cue", "measure", "replications", "large_small_ratio_object",
                "large_small_ratio_goal", "diff", "ci_low", "ci_high"]  # fmt: skip
    assert summary.columns[: len(contract)].tolist() == contract
    config = load_test_config()["size_dose"]
    doses = {str(float(d)) for d in config["doses"]} | {"removed"}
    assert set(summary["dose"].astype(str)) == doses
    assert (summary["replications"] == config["replications"]).all()
    slope = pd.read_csv(folder / "slope.csv")
    assert {"cue", "measure", "slope", "ci_low", "ci_high", "p"} <= set(slope.columns)
    assert len(slope) == len(set(zip(summary["cue"], summary["measure"], strict=True)))
    checks = pd.read_csv(folder / "manipulation.csv", keep_default_na=False)
    top = checks[checks["dose"].astype(str) == str(float(max(config["doses"])))]
    goal = top[top["map"] == "goal"]
    assert set(goal["shape"]) == {"ball", "cube"} and (goal["ratio"] >= 2).all(), goal
    removed = checks[checks["dose"] == "removed"]
    assert (removed["ratio"] == 1).all()  # no size: equal clusters
    assert (folder / "dose_response.png").stat().st_size > 10_000


# ---- the chapter's sentences follow their tests ---------------------------------------------


def test_the_size_sentences_follow_their_holm_verdicts():
    from icub_workflow.book import text

    row = {"diff": -0.03, "ci_low": -0.05, "ci_high": -0.01, "p": 0.001, "p_holm": 0.01,
           "replications": 3}  # fmt: skip
    assert "reversed" in text.size_dose_claim(row, "first_step", "top", "At 0.6").text
    assert (
        "paper's direction"
        in text.size_dose_claim(
            row | {"diff": 0.03, "ci_low": 0.01, "ci_high": 0.05}, "first_step", "top", "At 0.6"
        ).text
    )
    # a raw p under 0.05 that Holm lifts above it: not detected, whatever the raw interval
    said = text.size_dose_claim(row | {"p": 0.01, "p_holm": 0.2}, "all_steps", "top", "At 0.6")
    assert "not detected after Holm" in said.text and "reversed" not in said.text
    assert said.rests_on == ("size.top_diff_all_steps", "size.top_p_holm_all_steps")
    source = text.size_removal_claim(row, "first_step").text
    assert "motor side" in source
    assert "cannot say" in text.size_removal_claim(row | {"p_holm": 0.3}, "first_step").text
    slope = {"slope": -0.05, "ci_low": -0.09, "ci_high": -0.01, "df": 2, "p": 0.03,
             "p_holm": 0.01, "replications": 3}  # fmt: skip
    assert "away from the paper's" in text.size_slope_claim(slope, "all_steps").text
    assert "towards the paper's" in text.size_slope_claim(slope | {"slope": 0.05}, "all_steps").text
    assert "no trend" in text.size_slope_claim(slope | {"p_holm": 0.3}, "all_steps").text


def test_the_motor_sentence_names_only_what_survives_holm():
    from icub_workflow.book import text

    motor = pd.DataFrame(
        [
            {"dose": "removed", "cue": "all_steps", "geometry": "demo_path_length",
             "estimate": 0.01, "replications": 3, "networks": 36, "p_holm": 0.001},
            {"dose": "removed", "cue": "all_steps", "geometry": "demo_spread", "estimate": 0.02,
             "replications": 3, "networks": 36, "p_holm": 0.4},
        ]
    )  # fmt: skip
    said = text.size_motor_claim(motor, "Without size")
    assert "path" in said.text and "spread" not in said.text
    assert said.rests_on[0] == "size.motor_p_holm_removed_all_steps_demo_path_length"
    none = text.size_motor_claim(motor.assign(p_holm=0.5), "Without size").text
    assert "none of the demonstrations' measures" in none


def test_the_caveat_names_the_measures_that_rank_as_size_does():
    from icub_workflow.book import text

    rows = []
    for seed in (1, 2):
        for obj, length, spread in (("big_ball", 2.0, 0.1), ("small_ball", 1.0, 0.3),
                                    ("big_cube", 3.0, 0.2), ("small_cube", 1.5, 0.1)):  # fmt: skip
            for grip in (0, 1):
                rows.append({"seed": seed, "object": obj, "grip": grip,
                             "demo_path_length": length, "demo_spread": spread,
                             "demo_grip_distance": 1.0})  # fmt: skip
    assert ranked_like_size(pd.DataFrame(rows)) == ["demo_path_length"]
    said = text.geometry_like_size(["demo_path_length", "demo_grip_distance"])
    assert " and " in said and " are larger" in said
    assert "None" in text.geometry_like_size([])
