"""What drives the size effect (icub_affordance.analysis.size_study), on made-up inputs: the
size-free input, the manipulation check and the delivered dose, the summary per dose and grip
arrangement, the grips swapped to their same-shape partner's distance, size and the grips' distance
separated per replication and their declared tests and power (each recomputed with scipy and numpy),
the demonstrations' geometry by hand, the motor tests' families, and the plan's runs."""

from __future__ import annotations

import io

import numpy as np
import pandas as pd
import pytest
from conftest import REPO, load_config, load_test_config, som_config
from scipy import stats as sps
from statsmodels.stats.multitest import multipletests

from icub_affordance.analysis.reading_tests import BY_EXCESS, NULL_CONTROL
from icub_affordance.analysis.size_study import (
    CROSSED_COLUMNS,
    DECLARED_COLUMNS,
    FAMILY_DECLARED,
    FAMILY_MOTOR_ADDED,
    FAMILY_MOTOR_PLANNED,
    FAMILY_SUMMARY,
    FAMILY_TRAJECTORY,
    NATURAL,
    POWER_COLUMNS,
    SEPARATED_COLUMNS,
    SUMMARY_COLUMNS,
    SWAPPED,
    crossed_runs,
    declared_tests,
    delivered_doses,
    demo_geometry,
    grip_gaps,
    motor_tests,
    power_table,
    ranked_like_size,
    separate,
    separated,
    summary,
    trajectory_geometry,
)
from icub_affordance.learning.grip_distance import (
    mean_final_grip_distances,
    shape_partners,
    swap_scale,
    swapped_grips,
    trajectory_grip_distances,
)
from icub_affordance.learning.maps import active_units, bump, kept_whole, train_soms
from icub_affordance.learning.size_manipulation import CONTROLS, manipulation_rows, size_free_maps
from icub_workflow.runs import plan_runs

OBJECTS = ["big_ball", "small_ball", "big_cube", "small_cube"]
#: Each object's same-shape partner, written out (not read from the code under test).
PARTNER = {"big_ball": "small_ball", "small_ball": "big_ball",
           "big_cube": "small_cube", "small_cube": "big_cube"}  # fmt: skip
CUES = ("first_step", "all_steps")


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


@pytest.mark.heavy
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


# ---- the summary: per dose, grip arrangement and cue timing ----------------------------------


DOSES = (0.0, 0.3, 0.6)


def replications_table(slope: float, seeds=(1, 2, 3), noise=0.0) -> pd.DataFrame:
    """Per replication (seed) the size effect at the doses 0, 0.3 and 0.6 with the grips as
    demonstrated (rising by ``slope`` per unit of dose) and swapped (0.02 lower), and the
    removal control (natural grips)."""
    rng = np.random.default_rng(0)
    common = {"cue": "first_step", "measure": "rmse", "cell_mean": 0.1, "ci_low": 0.0,
              "ci_high": 0.0, "df": 10.0, "p": 0.5, "se": 0.01, "networks": 12}  # fmt: skip
    rows = []
    for seed in seeds:
        tilt = slope + rng.normal(0, noise)
        for dose in DOSES:
            for arrangement in (NATURAL, SWAPPED):
                shift = 0.0 if arrangement == NATURAL else -0.02
                rows.append(
                    common
                    | {"dose": dose, "arrangement": arrangement, "seed": seed,
                       "run": f"r{seed}_{dose}_{arrangement}",
                       "estimate": 0.01 + tilt * dose + shift + rng.normal(0, 0.001)}
                )  # fmt: skip
        rows.append(
            common
            | {"dose": "removed", "arrangement": NATURAL, "seed": seed, "run": f"r{seed}_x",
               "estimate": -0.02}
        )  # fmt: skip
    return pd.DataFrame(rows)


def manipulation_table(replications: pd.DataFrame) -> pd.DataFrame:
    """The manipulation check of every run of ``replications``: the small clusters 4 units, the
    large ones growing with the nominal dose, each run and shape a little apart (so a run's
    delivered dose is not a function of its nominal dose); the control at dose 0's maps."""
    rng = np.random.default_rng(5)
    rows = []
    for run in replications.drop_duplicates("run").to_dict("records"):
        for shape in ("ball", "cube"):
            for name in ("object", "goal"):
                dose = 0.0 if run["dose"] in CONTROLS else float(run["dose"])
                large = 4.0 if dose == 0 else 4.0 * (1 + 4 * dose) + rng.uniform(-1, 1)
                rows.append(
                    {k: run[k] for k in ("dose", "arrangement", "cue", "seed", "run")}
                    | {"shape": shape, "map": name, "large_units": large, "small_units": 4.0,
                       "ratio": large / 4.0}
                )  # fmt: skip
    return pd.DataFrame(rows)


def test_the_summary_tests_each_dose_and_arrangement_over_replications_and_carries_the_check():
    table = replications_table(0.05)
    ratio = {0.0: 1.0, 0.3: 2.0, 0.6: 3.0, "removed": 1.0}
    checks = pd.DataFrame(
        [
            {k: run[k] for k in ("dose", "arrangement", "cue", "seed", "run")}
            | {"shape": sh, "map": m, "large_units": 4.0 * ratio[run["dose"]],
               "small_units": 4.0, "ratio": ratio[run["dose"]]
               * (1.5 if run["arrangement"] == SWAPPED and m == "object" else 1.0)}
            for run in table.drop_duplicates("run").to_dict("records")
            for sh in ("ball", "cube")
            for m in ("object", "goal")
        ]
    )  # fmt: skip
    out = summary(table, checks, least=2)
    assert list(out.columns) == SUMMARY_COLUMNS
    conditions = [(d, a) for d in DOSES for a in (NATURAL, SWAPPED)] + [("removed", NATURAL)]
    assert list(zip(out["dose"], out["arrangement"], strict=True)) == conditions
    for arrangement in (NATURAL, SWAPPED):
        row = out[(out["dose"] == 0.3) & (out["arrangement"] == arrangement)].iloc[0]
        chosen = (table["dose"] == 0.3) & (table["arrangement"] == arrangement)
        estimates = table.loc[chosen, "estimate"]
        test = sps.ttest_1samp(estimates, 0.0)
        assert row["diff"] == pytest.approx(estimates.mean())
        assert row["p"] == pytest.approx(test.pvalue) and row["df"] == 2
        low, high = sps.t.interval(0.95, 2, loc=estimates.mean(), scale=sps.sem(estimates))
        assert (row["ci_low"], row["ci_high"]) == pytest.approx((low, high))
        assert row["large_small_ratio_goal"] == 2.0 and row["replications"] == 3
        # each arrangement's own runs' check
        assert row["large_small_ratio_object"] == (3.0 if arrangement == SWAPPED else 2.0)
        assert row["relative_to_mean"] == pytest.approx(estimates.mean() / 0.1)
    # the removal rows' replications agree exactly: no spread, no p (and no place in Holm's)
    assert np.isnan(out[out["dose"] == "removed"]["p"]).all()
    tested = np.isfinite(out["p"].to_numpy(dtype=float))
    holm = multipletests(out["p"].to_numpy(dtype=float)[tested], method="holm")[1]
    np.testing.assert_allclose(out["p_holm"].to_numpy(dtype=float)[tested], holm)
    assert (out["family"] == FAMILY_SUMMARY).all()


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
    out = summary(table, checks, least=2).set_index(["dose", "arrangement"])
    goal = checks[checks["map"] == "goal"]
    for dose, arrangement in out.index:
        rows = goal[(goal["dose"] == dose) & (goal["arrangement"] == arrangement)]
        assert len(rows) == 3 * 2  # the replications' runs, two shapes each
        expected = np.log(rows["large_units"] / rows["small_units"]).mean()
        assert out.loc[(dose, arrangement), "delivered_dose"] == pytest.approx(expected)
    for arrangement in (NATURAL, SWAPPED):
        at = {d: out.loc[(d, arrangement), "delivered_dose"] for d in DOSES}
        assert at[0.0] == 0 and at[0.6] > at[0.3] > 0
    assert out.loc[("removed", NATURAL), "delivered_dose"] == 0


# ---- the Holm families the tables name --------------------------------------------------------


def holm_within_families(table: pd.DataFrame) -> set:
    """Holm recomputed (statsmodels) over the rows of each named family of a table as its CSV
    reads back, against the table's ``p_holm``; the families seen. A null control's rows and
    those of a measure tested by its excess are in no family (empty ``p_holm``)."""
    back = pd.read_csv(io.StringIO(table.to_csv(index=False)))
    for name, rows in back.groupby("family"):
        if name in (NULL_CONTROL, BY_EXCESS):
            assert rows["p_holm"].isna().all(), name
            continue
        tested = rows["p"].notna()
        expected = multipletests(rows.loc[tested, "p"].to_numpy(dtype=float), method="holm")[1]
        assert rows.loc[tested, "p_holm"].to_numpy() == pytest.approx(expected), name
        assert rows.loc[~tested, "p_holm"].isna().all(), name
    return set(back["family"])


EXCESS_STUDY = ("rmse_per_grip_distance", "rmse_per_grip_distance_null")


def study_with_a_null_control() -> pd.DataFrame:
    """The study's replications on the RMSE and on RMSE per grip distance with its null control
    and its excess over it (``scores.analysed``): a run's excess estimate is its measure's
    minus its null control's, as the per-network contrasts are linear in the trials."""
    rng = np.random.default_rng(2)
    measures = []
    for measure in ("rmse", *EXCESS_STUDY):
        table = replications_table(0.05, noise=0.01).assign(measure=measure)
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


def test_the_summary_names_its_holm_families():
    """The null control and the raw measure tested by its excess are shown, in no family; the
    excess is a hypothesis beside the RMSE; both arrangements are one family."""
    table = study_with_a_null_control()
    out = summary(table, study_checks(table), least=2)
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
    # 2 cue timings x 4 measures x (3 doses x 2 arrangements + the removal control)
    assert len(out) == 2 * 4 * 7
    assert set(out.loc[out["family"] == FAMILY_SUMMARY, "arrangement"]) == {NATURAL, SWAPPED}


# ---- the grips swapped to their same-shape partner's distance ---------------------------------


def postures(offsets, centre=0.5, seed=3) -> np.ndarray:
    """Made-up demonstrations (object, grip, sequence, step, DoF; 0-1): every sequence starts
    at one common posture and moves in a straight line to its grip's end, the two grips of
    object ``o`` ending ``offsets[o]`` apart along one direction about ``centre``; a little
    noise on every step but the first."""
    rng = np.random.default_rng(seed)
    start = rng.uniform(0.45, 0.55, 16)
    direction = rng.normal(0, 1, 16)
    direction /= np.linalg.norm(direction)
    centres = np.broadcast_to(np.asarray(centre, dtype=float), (4,))
    ends = np.empty((4, 2, 16))
    for o, (offset, mid) in enumerate(zip(offsets, centres, strict=True)):
        ends[o, 0] = mid - offset / 2 * direction
        ends[o, 1] = mid + offset / 2 * direction
    t = np.linspace(0, 1, 10)[None, None, None, :, None]
    demos = start + t * (ends[:, :, None, None, :] - start)
    demos = demos + rng.normal(0, 0.002, (4, 2, 5, 10, 16))
    demos[:, :, :, 0] = start  # one common initial posture, shared by both grips
    return np.clip(demos, 0.0, 1.0)


def distances_by_hand(demos: np.ndarray) -> np.ndarray:
    """Per object, the distance between its two grips' mean final postures."""
    final = demos[:, :, :, -1].mean(axis=2)
    return np.sqrt(((final[:, 0] - final[:, 1]) ** 2).sum(axis=-1))


def test_the_swap_gives_each_object_its_partners_grip_distance():
    demos = postures([0.2, 0.05, 0.15, 0.04])  # large, small, large, small
    before = distances_by_hand(demos)
    # the swap's moves stay inside the joints' ranges here: no clipping
    mid = demos.mean(axis=1, keepdims=True)
    factor = np.array(
        [before[OBJECTS.index(PARTNER[o])] / before[k] for k, o in enumerate(OBJECTS)]
    )
    unclipped = mid + factor[:, None, None, None, None] * (demos - mid)
    assert unclipped.min() > 0 and unclipped.max() < 1
    swapped = swapped_grips(demos, OBJECTS)
    after = distances_by_hand(swapped)
    for k, obj in enumerate(OBJECTS):
        assert after[k] == pytest.approx(before[OBJECTS.index(PARTNER[obj])], rel=1e-9), obj
    np.testing.assert_allclose(swapped, unclipped, atol=1e-12)
    # the start, which both grips share, does not move
    np.testing.assert_array_equal(swapped[:, :, :, 0], demos[:, :, :, 0])
    # the order by size reverses: the small objects' grips now lie the further apart
    gap = {s: (before[2 * i] - before[2 * i + 1], after[2 * i] - after[2 * i + 1])
           for i, s in enumerate(("ball", "cube"))}  # fmt: skip
    for shape, (natural, swap) in gap.items():
        assert natural > 0 > swap and swap == pytest.approx(-natural, rel=1e-9), shape
    # the code's own measure and the geometry's are this distance
    np.testing.assert_allclose(mean_final_grip_distances(demos), before, rtol=1e-12)
    geometry = demo_geometry(swapped, OBJECTS).groupby("object")["demo_grip_distance"].first()
    np.testing.assert_allclose(geometry[OBJECTS].to_numpy(), after, rtol=1e-12)
    np.testing.assert_allclose(swap_scale(demos, OBJECTS), factor, rtol=1e-12)


def test_a_clipped_swap_falls_short_only_where_it_moves_the_grips_apart():
    """Near a joint's end the small cube's grips, moved apart to the big cube's distance, are
    held within the range and end nearer than their partner's; a move together (factor below 1)
    stays between the two grips and is never clipped."""
    demos = postures([0.2, 0.05, 0.15, 0.04], centre=[0.5, 0.5, 0.5, 0.99])
    before = distances_by_hand(demos)
    swapped = swapped_grips(demos, OBJECTS)
    after = distances_by_hand(swapped)
    assert swapped.min() >= 0 and swapped.max() <= 1
    big, small = OBJECTS.index("big_cube"), OBJECTS.index("small_cube")
    assert after[small] < before[big] - 0.02  # clipped: short of its partner's distance
    assert after[big] == pytest.approx(before[small], rel=1e-9)  # together: exact
    # the cube's order still reversed, by less than the natural gap
    assert -(before[big] - before[small]) < after[big] - after[small] < 0


def test_a_swap_needs_each_objects_one_same_shape_partner():
    assert shape_partners(OBJECTS) == [1, 0, 3, 2]
    shuffled = ["small_cube", "big_ball", "big_cube", "small_ball"]
    assert [shuffled[k] for k in shape_partners(shuffled)] == [PARTNER[o] for o in shuffled]
    with pytest.raises(ValueError, match=r"big_cube.*grip_distance 'natural'"):
        shape_partners(["big_ball", "small_ball", "big_cube"])


# ---- size crossed with the grips' distance ----------------------------------------------------


def test_each_runs_gap_and_factors_are_what_its_geometry_and_check_say():
    distances = {  # per run: big ball, small ball, big cube, small cube
        "nat": [0.30, 0.10, 0.25, 0.05],
        "swp": [0.10, 0.28, 0.05, 0.25],
        "rem": [0.30, 0.10, 0.25, 0.05],
    }
    geometry = pd.DataFrame(
        [
            {"run": run, "object": obj, "grip": g, "demo_grip_distance": d[k],
             "demo_path_length": 1.0, "demo_spread": 0.1}
            for run, d in distances.items()
            for k, obj in enumerate(OBJECTS)
            for g in (0, 1)
        ]
    )  # fmt: skip
    gaps = grip_gaps(geometry)
    assert gaps["nat"] == pytest.approx(((0.30 - 0.10) + (0.25 - 0.05)) / 2)
    assert gaps["swp"] == pytest.approx(((0.10 - 0.28) + (0.05 - 0.25)) / 2)
    runs = [("nat", 0.6, NATURAL), ("swp", 0.6, SWAPPED), ("rem", "removed", NATURAL)]
    replications = pd.DataFrame(
        [
            {"cue": "first_step", "dose": dose, "arrangement": arrangement, "seed": 7,
             "run": run, "measure": measure, "estimate": e}
            for (run, dose, arrangement), e in zip(runs, (0.03, -0.01, 0.02), strict=True)
            for measure in ("rmse", "wrong_grip")
        ]
    )  # fmt: skip
    checks = pd.DataFrame(
        [
            {"run": run, "shape": shape, "map": "goal", "large_units": large, "small_units": 4.0}
            for run, _, _ in runs
            for shape, large in (("ball", 12.0), ("cube", 8.0))
        ]
    )  # fmt: skip
    out = crossed_runs(replications, checks, geometry, "rmse")
    assert list(out.columns) == CROSSED_COLUMNS
    assert list(out["run"]) == ["nat", "swp"]  # the removal control is not crossed
    assert set(out["measure"]) == {"rmse"}
    by = out.set_index("run")
    assert by.loc["nat", "estimate"] == 0.03 and by.loc["swp", "estimate"] == -0.01
    assert by.loc["swp", "gap"] == pytest.approx(gaps["swp"])
    for k, obj in enumerate(OBJECTS):
        assert by.loc["swp", f"grip_distance_{obj}"] == distances["swp"][k]
    np.testing.assert_allclose(out["delivered_dose"], (np.log(3) + np.log(2)) / 2, rtol=1e-12)


def test_a_replications_line_splits_its_effect_into_sizes_and_the_grips_part():
    size, slope = 0.02, 0.05
    for natural, swap in ((0.3, -0.1), (0.12, -0.12), (-0.05, 0.2)):
        effects = [size + slope * g for g in (natural, swap)]
        out = separate(*effects, natural, swap)
        # the line through the two points, by numpy
        rise, at_zero = np.polyfit([natural, swap], effects, 1)
        assert out["slope"] == pytest.approx(rise) == pytest.approx(slope)
        assert out["size"] == pytest.approx(at_zero) == pytest.approx(size)
        assert out["grip_distance"] == pytest.approx(slope * natural)
        assert out["size"] + out["grip_distance"] == pytest.approx(effects[0])
    # an exact swap (the gap reversed): size is the mean of the two effects, the grips' part
    # half their difference
    rng = np.random.default_rng(1)
    for _ in range(5):
        gap, natural_effect, swapped_effect = rng.normal(0, 0.1, 3)
        out = separate(natural_effect, swapped_effect, gap, -gap)
        assert out["size"] == pytest.approx((natural_effect + swapped_effect) / 2)
        assert out["grip_distance"] == pytest.approx((natural_effect - swapped_effect) / 2)
    # equal gaps (or an undefined one): no line, nothing to split
    for gaps in ((0.1, 0.1), (0.0, 0.0), (np.nan, 0.1)):
        out = separate(0.03, 0.01, *gaps)
        assert all(np.isnan(v) for v in out.values()), gaps


#: The crossed design's made-up truth: size's part per cue timing and dose, the grips' slope.
SIZE_PART = {("first_step", 0.0): 0.015, ("first_step", 0.6): 0.02,
             ("all_steps", 0.0): -0.005, ("all_steps", 0.6): 0.0}  # fmt: skip
GRIP_SLOPE = 0.05
SEEDS = (1, 2, 3, 4, 5, 6)
#: The replication whose two gaps are equal (no line): cue, dose, seed.
NO_LINE = ("all_steps", 0.6, 4)


def crossed_table() -> tuple[pd.DataFrame, dict]:
    """Per cue timing, dose (0 and 0.6) and replication, a natural and a swapped run whose size
    effects lie on the replication's own line c = a + b g (a, b about ``SIZE_PART`` and
    ``GRIP_SLOPE``), the swapped gap most of the natural one reversed; and, per cue timing,
    dose and seed, the replication's true a, b g_n and natural effect."""
    rng = np.random.default_rng(11)
    rows, truth = [], {}
    for cue in CUES:
        for dose in (0.0, 0.6):
            for seed in SEEDS:
                a = SIZE_PART[(cue, dose)] + rng.normal(0, 0.004)
                b = GRIP_SLOPE + rng.normal(0, 0.02)
                natural = rng.uniform(0.05, 0.15)
                swap = natural if (cue, dose, seed) == NO_LINE else -natural * rng.uniform(0.7, 1)
                truth[(cue, dose, seed)] = {"size": a, "grip_distance": b * natural,
                                            "effect_natural": a + b * natural}  # fmt: skip
                for arrangement, gap in ((NATURAL, natural), (SWAPPED, swap)):
                    rows.append(
                        {"cue": cue, "dose": dose, "arrangement": arrangement, "seed": seed,
                         "run": f"{cue}_{dose}_{arrangement}_{seed}", "measure": "rmse",
                         "delivered_dose": dose * 1.7, "gap": gap, "estimate": a + b * gap}
                        | {f"grip_distance_{o}": 0.1 for o in OBJECTS}
                    )  # fmt: skip
    return pd.DataFrame(rows, columns=CROSSED_COLUMNS), truth


def test_each_replication_is_separated_from_its_own_two_runs():
    table, truth = crossed_table()
    parts = separated(table)
    assert list(parts.columns) == SEPARATED_COLUMNS
    assert len(parts) == len(truth)
    for row in parts.to_dict("records"):
        key = (row["cue"], row["dose"], row["seed"])
        if key == NO_LINE:
            assert np.isnan(row["size"]) and np.isnan(row["grip_distance"])
            continue
        for name in ("size", "grip_distance", "effect_natural"):
            assert row[name] == pytest.approx(truth[key][name], abs=1e-12), (key, name)
    # a replication with one of its two runs only has no line: it is not in the table
    alone = table.drop(index=table.index[(table["seed"] == 2) & (table["arrangement"] == SWAPPED)])
    assert 2 not in set(separated(alone)["seed"])


def test_the_declared_tests_are_one_sample_ts_over_the_replications_holm_over_themselves():
    table, truth = crossed_table()
    out = declared_tests(separated(table), ["size", "grip_distance", "dose"], [0.0, 0.6], least=2)
    assert list(out.columns) == DECLARED_COLUMNS
    expected_rows = [
        (test, cue, dose)
        for cue in CUES
        for test, dose in (("size", "0"), ("size", "0.6"), ("grip_distance", "0"),
                           ("grip_distance", "0.6"), ("dose", "0.6 - 0"))
    ]  # fmt: skip
    assert list(zip(out["test"], out["cue"], out["dose"], strict=True)) == expected_rows
    assert len(out) == 10 and (out["family"] == FAMILY_DECLARED).all()
    assert (out["measure"] == "rmse").all()
    for row in out.to_dict("records"):
        cue = row["cue"]
        if row["test"] == "dose":
            effect = {d: np.array([truth[(cue, d, s)]["effect_natural"] for s in SEEDS])
                      for d in (0.0, 0.6)}  # fmt: skip
            values = effect[0.6] - effect[0.0]
            left_out = 0  # the replication without a line still has its natural runs
        else:
            dose = float(row["dose"])
            kept = [s for s in SEEDS if (cue, dose, s) != NO_LINE]
            values = [truth[(cue, dose, s)][row["test"]] for s in kept]
            left_out = len(SEEDS) - len(kept)
        values = np.array(values)
        n = len(values)
        test = sps.ttest_1samp(values, 0.0)
        low, high = sps.t.interval(0.95, n - 1, loc=values.mean(), scale=sps.sem(values))
        where = (row["test"], cue, row["dose"])
        assert row["replications"] == n and row["left_out"] == left_out, where
        assert row["df"] == n - 1, where
        assert row["estimate"] == pytest.approx(values.mean(), abs=1e-12), where
        assert row["sd"] == pytest.approx(values.std(ddof=1), rel=1e-9), where
        assert row["p"] == pytest.approx(test.pvalue, rel=1e-9), where
        assert (row["ci_low"], row["ci_high"]) == pytest.approx((low, high), rel=1e-9), where
    assert out.loc[(out["cue"] == "all_steps") & (out["dose"] == "0.6"), "left_out"].tolist() == [
        1,
        1,
    ]
    holm = multipletests(out["p"].to_numpy(dtype=float), method="holm")[1]
    np.testing.assert_allclose(out["p_holm"].to_numpy(dtype=float), holm, rtol=1e-12)
    # the made-up size part is found where it is large against its spread
    first = out.set_index(["test", "cue", "dose"]).loc[("size", "first_step", "0")]
    assert first["p_holm"] < 0.05 and first["ci_low"] > 0


def power_by_hand(effect: float, sd: float, n: int, alpha: float) -> float:
    """A two-sided one-sample t-test's power by the noncentral t: P(T > c) + P(T < -c), the
    far tail as its mirror image P(T > c) at the negated shift (scipy's cdf gives NaN far out
    in the lower tail, where it is below 1e-10)."""
    if not (n >= 2 and np.isfinite(sd)):
        return float("nan")
    df = n - 1
    critical = sps.t.ppf(1 - alpha / 2, df)
    shift = effect / (sd / np.sqrt(n))
    lower = sps.nct.cdf(-critical, df, shift)
    if not np.isfinite(lower):
        lower = sps.nct.sf(critical, df, -shift)
        assert lower < 1e-9
    return float(sps.nct.sf(critical, df, shift) + lower)


def test_the_power_of_each_declared_test_and_its_range():
    declared = pd.DataFrame(
        {"test": ["size", "grip_distance", "size", "dose", "size"],
         "cue": ["first_step"] * 5, "dose": ["0", "0", "0.6", "0.6 - 0", "0.6"],
         "replications": [10, 10, 8, 10, 1], "sd": [0.004, 0.01, 0.02, 0.013, np.nan],
         "p": [0.001, 0.2, np.nan, 0.6, np.nan]}
    )  # fmt: skip
    effect, alpha = 0.01, 0.05
    out = power_table(declared, effect, alpha)
    assert list(out.columns) == POWER_COLUMNS and len(out) == len(declared)
    at_least = alpha / 3  # the rows with a p: the family Holm adjusts over
    np.testing.assert_allclose(out["alpha_at_least"], at_least, rtol=1e-12)
    assert (out["alpha_at_most"] == alpha).all()
    for row, given in zip(out.to_dict("records"), declared.to_dict("records"), strict=True):
        n, sd = given["replications"], given["sd"]
        assert (row["test"], row["dose"], row["replications"]) == (
            given["test"], given["dose"], n)  # fmt: skip
        if n < 2:
            assert all(np.isnan(row[k]) for k in ("sd_low", "sd_high", "power_at_least",
                                                  "power_at_most_low"))  # fmt: skip
            continue
        df = n - 1
        low = sd * np.sqrt(df / sps.chi2.ppf(0.975, df))
        high = sd * np.sqrt(df / sps.chi2.ppf(0.025, df))
        assert (row["sd_low"], row["sd_high"]) == pytest.approx((low, high), rel=1e-9)
        for name, level in (("at_least", at_least), ("at_most", alpha)):
            expected = {"": power_by_hand(effect, sd, n, level),
                        "_low": power_by_hand(effect, high, n, level),  # a larger SD, less power
                        "_high": power_by_hand(effect, low, n, level)}  # fmt: skip
            for suffix, value in expected.items():
                assert row[f"power_{name}{suffix}"] == pytest.approx(value, rel=1e-7), (
                    row["test"], row["dose"], name, suffix)  # fmt: skip
            assert row[f"power_{name}_low"] <= row[f"power_{name}"] <= row[f"power_{name}_high"]
        assert row["power_at_least"] < row["power_at_most"]


# ---- the motor side: the demonstrations' geometry ---------------------------------------------


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


def test_only_the_natural_runs_say_which_measures_rank_the_objects_like_size():
    """The swapped runs reverse the grips' distance on purpose; the natural runs' geometry alone
    says which measures go with size."""
    rng = np.random.default_rng(6)
    rows = []
    for seed in (1, 2, 3):
        for arrangement in (NATURAL, SWAPPED):
            for k, obj in enumerate(OBJECTS):
                distance = [0.3, 0.1, 0.25, 0.05][k]
                if arrangement == SWAPPED:
                    distance = [0.1, 0.3, 0.05, 0.25][k]
                for grip in (0, 1):
                    rows.append(
                        {"seed": seed, "arrangement": arrangement, "object": obj, "grip": grip,
                         "demo_path_length": [1.2, 0.8, 1.1, 0.7][k] + rng.normal(0, 0.01),
                         "demo_spread": rng.uniform(0, 1), "demo_grip_distance": distance}
                    )  # fmt: skip
    geometry = pd.DataFrame(rows)
    assert ranked_like_size(geometry) == ["demo_path_length", "demo_grip_distance"]
    # read over both arrangements the grips' distance would not rank like size
    assert "demo_grip_distance" not in ranked_like_size(geometry.assign(arrangement=NATURAL))


def motor_trials(doses, effect=0.04, seed=1) -> pd.DataFrame:
    """Made-up categorisation trials (one per network and object) of four replications at each
    dose and arrangement (the removal control with natural grips only), the error rising with
    each object's path length by ``effect``."""
    rng = np.random.default_rng(seed)
    rows = []
    for dose in doses:
        for arrangement in (NATURAL,) if dose in CONTROLS else (NATURAL, SWAPPED):
            for replication in (1, 2, 3, 4):
                for net in range(6):
                    for k, obj in enumerate(OBJECTS):
                        length = [1.0, 0.4, 1.3, 0.7][k]
                        rows.append(
                            {"dose": dose, "arrangement": arrangement, "cue": "first_step",
                             "seed": replication, "network": net, "object": obj,
                             "rmse": 0.05 + effect * length + rng.normal(0, 0.002),
                             "demo_path_length": length, "demo_spread": rng.uniform(0, 1),
                             "demo_grip_distance": [0.2, 0.2, 0.5, 0.5][k]}
                        )  # fmt: skip
    return pd.DataFrame(rows)


def test_an_error_that_follows_the_path_length_is_found():
    trials = motor_trials(["removed"])
    out = motor_tests(trials, least=2).set_index("geometry")
    row = out.loc["demo_path_length"]
    # the unit is the replication (its networks share its demonstrations)
    assert row["replications"] == 4 and row["networks"] == 24 and row["df"] == 3
    assert row["arrangement"] == NATURAL
    # by hand: per network the least-squares slope on the standardised length, their mean per
    # replication, a one-sample t over the replications
    per_replication = []
    for _, replication in trials.groupby("seed"):
        slopes = []
        for _, net in replication.groupby("network"):
            x = net["demo_path_length"].to_numpy()
            slopes.append(np.polyfit((x - x.mean()) / x.std(), net["rmse"].to_numpy(), 1)[0])
        per_replication.append(np.mean(slopes))
    test = sps.ttest_1samp(per_replication, 0.0)
    assert row["estimate"] == pytest.approx(np.mean(per_replication), rel=1e-9)
    assert row["p"] == pytest.approx(test.pvalue, rel=1e-9)
    assert row["p_holm"] < 0.01 and row["estimate"] > 0


@pytest.mark.heavy
def test_the_motor_tests_planned_and_added_are_two_holm_families():
    out = motor_tests(motor_trials(["removed", 0.0, 0.6], effect=0.002), least=2)
    planned = out["dose"].astype(str) == "removed"
    assert set(out.loc[planned, "family"]) == {FAMILY_MOTOR_PLANNED}
    assert set(out.loc[~planned, "family"]) == {FAMILY_MOTOR_ADDED}
    assert planned.sum() == 3 and (~planned).sum() == 2 * 2 * 3  # geometry x conditions
    assert set(zip(out["dose"].astype(str), out["arrangement"], strict=True)) == {
        ("removed", NATURAL), ("0.0", NATURAL), ("0.0", SWAPPED), ("0.6", NATURAL),
        ("0.6", SWAPPED)}  # fmt: skip
    for family in (FAMILY_MOTOR_PLANNED, FAMILY_MOTOR_ADDED):
        rows = out[out["family"] == family]
        tested = rows["p"].notna()
        expected = multipletests(rows.loc[tested, "p"].to_numpy(dtype=float), method="holm")[1]
        np.testing.assert_allclose(rows.loc[tested, "p_holm"], expected, rtol=1e-12)
    # never pooled: Holm over every row would say otherwise here
    pooled = multipletests(out["p"].to_numpy(dtype=float), method="holm")[1]
    assert not np.allclose(pooled, out["p_holm"].to_numpy(dtype=float))
    assert holm_within_families(out) == {FAMILY_MOTOR_PLANNED, FAMILY_MOTOR_ADDED}
    assert list(out.columns[-2:]) == ["family", "p_holm"]


# ---- the plan ----------------------------------------------------------------------------------


@pytest.mark.parametrize("robustness", [False, True])
def test_the_plan_crosses_every_dose_with_both_arrangements_at_the_studys_seeds(robustness):
    config = load_config() | {"robustness": robustness}
    plan = plan_runs(config)
    study, crossed = config["size_dose"], config["size_dose"]["crossed"]
    assert study["removal"] and crossed["grip_arrangements"] == [NATURAL, SWAPPED]
    assert CONTROLS == ("removed",)
    count = crossed["robustness_replications" if robustness else "replications"]
    seeds = list(crossed["seeds"][:count])
    cues = study["categorisation_cue"]
    expected = [
        (dose, arrangement, cue, seed)
        for cue in cues
        for dose, arrangement in [
            *((d, a) for d in study["doses"] for a in crossed["grip_arrangements"]),
            ("removed", NATURAL),
        ]
        for seed in seeds
    ]
    got = [(r["dose"], r["arrangement"], r["cue"], r["seed"]) for r in plan.size_dose]
    assert sorted(got, key=str) == sorted(expected, key=str) and len(got) == len(expected)
    assert len(plan.size_dose) == len(cues) * (len(study["doses"]) * 2 + 1) * count
    for row in plan.size_dose:
        run, overrides = plan.config(row["run"]), plan.runs[row["run"]].overrides
        assert run["network"]["categorisation_cue"] == row["cue"] and run["seed"] == row["seed"]
        if row["dose"] == "removed":
            assert row["run"] == f"size_removed_{row['cue']}_seed{row['seed']}"
            assert run["size_free_input"] and plan.stage_run(row["run"], "demos") != row["run"]
            assert "grip_distance" not in overrides and run["grip_distance"] == NATURAL
            continue
        soms = run["soms"]
        assert soms["object_width_per_edge"] == row["dose"]
        assert soms["goal_response"] == "grows" and soms["keep_whole"]
        assert not run["size_free_input"]
        if row["arrangement"] == SWAPPED:
            assert row["run"] == f"size_dose{row['dose']}_swapped_{row['cue']}_seed{row['seed']}"
            assert overrides["grip_distance"] == SWAPPED == run["grip_distance"]
            # the natural run's demonstrations, moved as the networks learn them
            natural = f"size_dose{row['dose']}_{row['cue']}_seed{row['seed']}"
            assert plan.stage_run(row["run"], "demos") == plan.stage_run(natural, "demos")
        else:
            assert row["run"] == f"size_dose{row['dose']}_{row['cue']}_seed{row['seed']}"
            assert "grip_distance" not in overrides and run["grip_distance"] == NATURAL
    assert len({row["run"] for row in plan.size_dose}) == len(plan.size_dose)
    # the crossed seeds, in order, none of them another part's (whose runs others read)
    used = {row["seed"] for row in plan.size_dose}
    assert used == set(seeds) and config["seed"] not in used
    confirmation = config["confirmation"]
    assert not used & {*confirmation["seeds"], *confirmation["robustness_seeds"]}
    # without the removal control, the crossed runs alone
    fewer = plan_runs(config | {"size_dose": study | {"removal": False}}).size_dose
    assert len(fewer) == len(cues) * len(study["doses"]) * 2 * count
    assert not any(row["dose"] == "removed" for row in fewer)


# ---- one test under two names ----------------------------------------------------------------


def same_tests(tables: dict[str, pd.DataFrame], rtol: float = 1e-9) -> list[tuple[str, str]]:
    """Pairs of rows, across and within ``tables`` (name -> a table with ``p`` and ``df``), that
    carry the same test: the same finite p (to ``rtol``) at the same df. Each row named
    ``<table>:<row index>``."""
    rows = pd.concat(
        [
            pd.DataFrame({"row": [f"{name}:{i}" for i in t.index],
                          "p": pd.to_numeric(t["p"], errors="coerce").to_numpy(dtype=float),
                          "df": pd.to_numeric(t["df"], errors="coerce").to_numpy(dtype=float)})
            for name, t in tables.items()
        ],
        ignore_index=True,
    )  # fmt: skip
    rows = rows[np.isfinite(rows["p"])].sort_values(["df", "p"], ignore_index=True)
    pairs = []
    for _, by_df in rows.groupby("df"):
        p, names = by_df["p"].to_numpy(), by_df["row"].to_numpy()
        for i in range(len(p)):
            for j in range(i + 1, len(p)):
                if not np.isclose(p[i], p[j], rtol=rtol, atol=0):
                    break  # sorted: no later p is closer
                pairs.append((names[i], names[j]))
    return pairs


def test_a_test_under_two_names_is_flagged():
    table, _ = crossed_table()
    declared = declared_tests(
        separated(table), ["size", "grip_distance", "dose"], [0.0, 0.6], least=2
    )
    replications = replications_table(0.05, noise=0.01)
    summ = summary(replications, manipulation_table(replications), least=2)
    assert same_tests({"declared": declared, "summary": summ}) == []
    # one declared test again in the summary, under another dose and arrangement
    copied = declared.iloc[[3]].rename(columns={"estimate": "diff"})
    again = pd.concat([summ, copied.assign(dose=0.3, arrangement=SWAPPED)], ignore_index=True)
    assert same_tests({"declared": declared, "summary": again}) == [
        ("declared:3", f"summary:{len(summ)}")
    ]
    # the same p at another df is another test; an undefined p is no test
    assert same_tests({"a": declared.iloc[[3]], "b": declared.iloc[[3]].assign(df=9)}) == []
    nan = declared.iloc[[0]].assign(p=np.nan)
    assert same_tests({"a": nan, "b": nan}) == []
    # within one table too
    assert same_tests({"declared": pd.concat([declared, declared.iloc[[0]]])}) == [
        ("declared:0", "declared:0")
    ]


# ---- the study in the built test pipeline -----------------------------------------------------


def study_contract(folder, config: dict) -> None:
    """The size study's tables in ``folder`` (data/size_dose/ of a build of ``config``)."""
    study, crossed = config["size_dose"], config["size_dose"]["crossed"]
    cues, doses = study["categorisation_cue"], [float(d) for d in study["doses"]]
    arrangements = crossed["grip_arrangements"]
    replications = crossed["replications"]
    summary = pd.read_csv(folder / "summary.csv", keep_default_na=False)
    assert summary.columns.tolist() == SUMMARY_COLUMNS
    conditions = {(str(d), a) for d in doses for a in arrangements}
    conditions |= {("removed", NATURAL)} if study["removal"] else set()
    assert set(zip(summary["dose"].astype(str), summary["arrangement"], strict=True)) == conditions
    assert (summary["replications"] == replications).all()
    # the declared tests: per cue timing, size and the grips' part at each dose, the contrast
    declared = pd.read_csv(folder / "declared.csv", dtype={"dose": str})
    assert declared.columns.tolist() == DECLARED_COLUMNS
    assert len(declared) == len(cues) * (len(doses) * 2 + 1)
    assert (declared["family"] == FAMILY_DECLARED).all()
    assert (declared["measure"] == crossed["measure"]).all()
    assert (declared["replications"] + declared["left_out"] == replications).all()
    assert set(declared["dose"]) == {f"{d:g}" for d in doses} | {f"{max(doses):g} - {min(doses):g}"}
    tested = declared["p"].notna()
    holm = multipletests(declared.loc[tested, "p"], method="holm")[1]
    np.testing.assert_allclose(declared.loc[tested, "p_holm"], holm, rtol=1e-9)
    # per run: the gap, every object's grips' distance and the delivered dose
    runs = pd.read_csv(folder / "crossed.csv")
    assert runs.columns.tolist() == CROSSED_COLUMNS
    assert {"gap", "delivered_dose", *(f"grip_distance_{o}" for o in OBJECTS)} <= set(runs)
    assert len(runs) == len(cues) * len(doses) * len(arrangements) * replications
    assert runs[["gap", "delivered_dose", "estimate"]].notna().all().all()
    for (_cue, _dose, seed), pair in runs.groupby(["cue", "dose", "seed"]):
        by = pair.set_index("arrangement")
        natural, swapped = by.loc[NATURAL], by.loc[SWAPPED]
        # the design's guarantee: an object moved together (its grips the further apart) lands
        # on its partner's distance exactly; moved apart it may be clipped, and falls short
        for obj in OBJECTS:
            mine, partners = (
                natural[f"grip_distance_{obj}"],
                natural[f"grip_distance_{PARTNER[obj]}"],
            )
            moved = swapped[f"grip_distance_{obj}"]
            if mine >= partners:
                assert moved == pytest.approx(partners, rel=1e-6), (seed, obj)
            else:
                assert mine < moved <= partners * (1 + 1e-6), (seed, obj)
        assert natural["gap"] > 0 > swapped["gap"], (seed, natural["gap"], swapped["gap"])
    # the separated parts add up to the natural runs' effect
    parts = pd.read_csv(folder / "separated.csv")
    assert parts.columns.tolist() == SEPARATED_COLUMNS
    lined = parts["size"].notna()
    np.testing.assert_allclose(
        parts.loc[lined, "size"] + parts.loc[lined, "grip_distance"],
        parts.loc[lined, "effect_natural"],
        atol=1e-12,
    )
    # the power of each declared row, with its range
    power = pd.read_csv(folder / "power.csv", dtype={"dose": str})
    assert power.columns.tolist() == POWER_COLUMNS
    assert power[["test", "cue", "dose"]].equals(declared[["test", "cue", "dose"]])
    assert (power["effect_of_interest"] == crossed["effect_of_interest"]).all()
    defined = power["power_at_least"].notna()
    assert defined.any()
    for name in ("at_least", "at_most"):
        chosen = power.loc[defined]
        assert (chosen[f"power_{name}_low"] <= chosen[f"power_{name}"] + 1e-12).all()
        assert (chosen[f"power_{name}"] <= chosen[f"power_{name}_high"] + 1e-12).all()
    assert (power["alpha_at_most"] == crossed["alpha"]).all()
    np.testing.assert_allclose(power["alpha_at_least"], crossed["alpha"] / tested.sum())
    # the manipulation check: at the largest dose the Goal map's large cluster has at least
    # twice the small one's units, for each shape, arrangement and replication
    checks = pd.read_csv(folder / "manipulation.csv", keep_default_na=False)
    top = checks[checks["dose"].astype(str) == str(max(doses))]
    goal = top[top["map"] == "goal"]
    assert set(goal["shape"]) == {"ball", "cube"} and (goal["ratio"] >= 2).all(), goal
    assert set(goal["arrangement"]) == set(arrangements)
    removed = checks[checks["dose"] == "removed"]
    assert (removed["ratio"] == 1).all()  # no size: equal clusters
    motor = pd.read_csv(folder / "motor.csv", keep_default_na=False)
    assert set(motor["family"]) == {FAMILY_MOTOR_PLANNED, FAMILY_MOTOR_ADDED}
    assert (folder / "dose_response.png").stat().st_size > 10_000


def test_the_study_writes_its_contract_and_the_dose_arrives(built):
    """data/size_dose/ of the test pipeline: the summary per dose and arrangement, the declared
    tests per cue timing, each run's gap and factors, the power of each declared test, the
    manipulation check and the figure; the swapped runs' gap reversed."""
    study_contract(built / "data" / "size_dose", load_test_config())


def test_the_default_builds_study_writes_its_contract():
    """The same of this repository's default build (data/size_dose/: 2 cue timings, so 10
    declared tests), once it has the crossed design's tables."""
    folder = REPO / "data" / "size_dose"
    if not (folder / "declared.csv").exists():
        pytest.skip("needs the default build's crossed size study (data/size_dose/declared.csv)")
    config = load_config()
    assert len(pd.read_csv(folder / "declared.csv")) == 10
    study_contract(folder, config)


def built_tests(folder) -> dict[str, pd.DataFrame]:
    return {name: pd.read_csv(folder / f"{name}.csv") for name in ("summary", "declared", "motor")}


def test_no_test_of_the_built_study_is_reported_under_two_names(built):
    assert same_tests(built_tests(built / "data" / "size_dose")) == []


def test_no_test_of_the_default_builds_study_is_reported_under_two_names():
    folder = REPO / "data" / "size_dose"
    if not (folder / "declared.csv").exists():
        pytest.skip("needs the default build's crossed size study (data/size_dose/declared.csv)")
    assert same_tests(built_tests(folder)) == []


# ---- the chapter's sentences follow their tests ---------------------------------------------


def test_the_size_verdict_words_follow_their_holm_tests():
    from icub_workflow.book import text, words

    row = {"estimate": -0.03, "p": 0.001, "p_holm": 0.01}
    assert words.verdict_word(row) == "reversed"
    assert words.verdict_word(row | {"estimate": 0.03}) == "confirmed"
    # a raw p under 0.05 that Holm lifts above it: not shown, whatever the raw interval
    assert words.verdict_word(row | {"p": 0.01, "p_holm": 0.2}) == "not shown"
    assert words.verdict_word(row | {"p": float("nan"), "p_holm": float("nan")}) == "not assessable"
    assert text.size_part_word("size", row) == "reversed"
    assert text.size_part_word("grip_distance", row | {"estimate": 0.03}) == "confirmed"
    assert text.size_part_word("dose", row) == "reversed"
    assert text.size_part_word("dose", row | {"p_holm": 0.2}) == "not shown"
    assert text.carrier("confirmed", "reversed").startswith("both parts are shown")
    assert text.carrier("reversed", "not shown").startswith("only size's own part")
    assert text.carrier("not shown", "confirmed").startswith("only the grips' distance's part")
    assert text.carrier("not assessable", "not shown").startswith("the design cannot tell")
    assert text.named_measures(["demo_path_length", "demo_grip_distance"]) == (
        "the path length and the grips' distance"
    )
    assert text.named_measures([]) == "none of the measures"


def test_the_size_chapters_verdicts_flip_with_their_statistics(tmp_path):
    """The chapter's values from this build's study tables; a flipped estimate or a lifted p
    changes the words (the verdicts, and which part carries the size effect), and every verdict
    names the numbers it rests on."""
    from icub_workflow.book import pages, text

    folder = REPO / "data" / "size_dose"
    if not (folder / "declared.csv").exists():
        pytest.skip("needs the size study's crossed outputs (data/size_dose/declared.csv)")
    names = ("declared", "crossed", "summary", "manipulation", "power", "motor", "geometry",
             "trajectory_tests", "trajectory_separated")  # fmt: skip
    inputs = {f"size_{name}.csv": folder / f"{name}.csv" for name in names}
    config = load_config()
    cues = config["size_dose"]["categorisation_cue"]

    def chapter(**changed):
        for name, change in changed.items():
            frame = change(pd.read_csv(inputs[f"size_{name}.csv"], dtype={"dose": str}))
            frame.to_csv(tmp_path / f"{name}.csv", index=False)
        paths = inputs | {f"size_{n}.csv": tmp_path / f"{n}.csv" for n in changed}
        values, tables = pages.size_study(paths, config)
        return pages.traced({"size": values}), tables

    found, tables = chapter()
    size, claims = found["size"], found["claims"]["size"]
    declared = pd.read_csv(inputs["size_declared.csv"], dtype={"dose": str})
    assert len(tables["size_tests"]) == len(declared)
    assert claims["size_0_first_step_verdict"] == ["size.size_0_first_step",
                                                   "size.size_0_first_step_p_holm"]  # fmt: skip
    for row in declared.to_dict("records"):
        at = "contrast" if row["test"] == "dose" else row["dose"].replace(".", "")
        key = f"{row['test']}_{at}_{row['cue']}"
        assert size[key] == pytest.approx(row["estimate"])
        assert size[f"{key}_ci_low"] <= size[key] <= size[f"{key}_ci_high"]
        assert size[f"{key}_verdict"] == text.size_part_word(row["test"], row)

    def negate(frame):
        frame[["estimate", "ci_low", "ci_high"]] = -frame[["estimate", "ci_high", "ci_low"]].values
        return frame

    flipped, _ = chapter(declared=negate)
    turned = {"reversed": "confirmed", "confirmed": "reversed"}
    changed = 0
    for row in declared.to_dict("records"):
        at = "contrast" if row["test"] == "dose" else row["dose"].replace(".", "")
        key = f"{row['test']}_{at}_{row['cue']}_verdict"
        word = size[key]
        assert flipped["size"][key] == turned.get(word, word), key
        changed += word in turned
    assert changed == (declared["p_holm"] < 0.05).sum()  # every shown test turns
    # which part carries it follows the two parts' adjusted p
    for size_p, grip_p, said in (
        (0.001, 0.001, "both parts are shown"),
        (0.001, 0.5, "only size's own part"),
        (0.5, 0.001, "only the grips' distance's part"),
        (0.5, 0.5, "the design cannot tell"),
    ):
        carried, _ = chapter(declared=lambda f, s=size_p, g=grip_p: f.assign(
            p_holm=np.where(f["test"] == "size", s, np.where(f["test"] == "grip_distance", g,
                                                             f["p_holm"]))))  # fmt: skip
        for cue in cues:
            for dose in ("0", "06"):
                assert carried["size"][f"carrier_{dose}_{cue}"].startswith(said), (said, cue)
        assert carried["size"]["carrier_none_by_cue"] == carried["size"]["carrier_0_by_cue"]
        assert said in carried["size"]["carrier_top_by_cue"]
    lifted, _ = chapter(
        declared=lambda f: f.assign(p_holm=0.5), summary=lambda f: f.assign(p_holm=0.5)
    )
    for cue in cues:
        assert lifted["size"][f"dose_contrast_{cue}_verdict"] == "not shown"
        assert lifted["size"][f"removed_verdict_{cue}"] == "not shown"
    unmoved, _ = chapter(motor=lambda f: f.assign(p_holm=0.5))
    assert unmoved["size"]["motor_found_planned"] == "none of the measures"
    assert unmoved["size"]["motor_found_added"] == "none of the measures"
    # the two metrics (added after results): which part is the larger follows its own test
    metrics = pd.read_csv(inputs["size_trajectory_tests.csv"], dtype={"dose": str})
    assert len(tables["size_metrics"]) == len(metrics.groupby(["metric", "dose", "cue"]))
    for larger, said in ((0.01, "size's own part is the larger"),
                         (-0.01, "the grips' distance's part is the larger")):  # fmt: skip
        sized, _ = chapter(
            trajectory_tests=lambda f, x=larger: f.assign(
                estimate=np.where(f["test"] == "size_larger", x, f["estimate"]), p_holm=0.001
            )
        )
        for cue in cues:
            for dose in ("0", "06"):
                for metric in ("final_posture", "trajectory_rms"):
                    assert sized["size"][f"{metric}_larger_{dose}_{cue}"] == said
                assert sized["size"][f"metrics_differ_{dose}_{cue}"].startswith("Both metrics")
    unshown, _ = chapter(trajectory_tests=lambda f: f.assign(p_holm=0.5))
    assert unshown["size"]["trajectory_rms_larger_0_first_step"] == (
        "neither part is shown to be the larger"
    )
    assert (
        unshown["size"]["trajectory_rms_carrier_0_first_step"] == "the design cannot tell: "
        "neither part is shown"
    )


def test_the_trajectory_grip_distance_is_the_rms_over_steps_after_the_first_by_hand():
    rng = np.random.default_rng(7)
    demos = rng.uniform(0, 1, (4, 2, 3, 5, 16))
    by_hand = [
        np.mean([np.sqrt(np.mean([(demos[o, 0, s, t, d] - demos[o, 1, s, t, d]) ** 2
                                  for t in range(1, 5) for d in range(16)]))
                 for s in range(3)])
        for o in range(4)
    ]  # fmt: skip
    np.testing.assert_allclose(trajectory_grip_distances(demos), by_hand, rtol=1e-12)
    # the common first step does not count; the final posture alone is the declared metric
    moved = demos.copy()
    moved[:, 0, :, 0] += 0.3
    np.testing.assert_allclose(trajectory_grip_distances(moved), by_hand, rtol=1e-12)
    frame = trajectory_geometry(demos, OBJECTS)
    assert list(frame["object"]) == list(OBJECTS)
    np.testing.assert_allclose(frame["demo_grip_distance"], by_hand, rtol=1e-12)


def test_the_trajectory_attribution_is_its_own_family_added_after_results():
    assert "added after results" in FAMILY_TRAJECTORY and FAMILY_TRAJECTORY != FAMILY_DECLARED
    rng = np.random.default_rng(3)
    parts = pd.DataFrame(
        [{"cue": "first_step", "dose": d, "seed": s, "measure": "rmse",
          "size": rng.normal(0.01, 0.01), "grip_distance": rng.normal(0, 0.01),
          "effect_natural": 0.0}
         for d in (0.0, 0.6) for s in range(6)]
    )  # fmt: skip
    found = declared_tests(parts, ["size", "grip_distance"], [0.0, 0.6], 2, FAMILY_TRAJECTORY)
    assert set(found["family"]) == {FAMILY_TRAJECTORY} and len(found) == 4
    # Holm within these four tests alone
    expected = multipletests(found["p"], method="holm")[1]
    np.testing.assert_allclose(found["p_holm"], expected, rtol=1e-12)
