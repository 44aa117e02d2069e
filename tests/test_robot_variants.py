"""The robot variants' summary: success and contact per variant, and the congruency and size
effects on success (per-network contrasts, or Fisher's exact test over distinct trials where the
contrast has no variance) and contact time, recomputed by hand on made-up trials; every count and
test over distinct trials (one per network x object x task), whatever the number of sequences."""

import json
from math import comb

import numpy as np
import pandas as pd
import pytest
from scipy import stats as sps

from icub_affordance.analysis.robot_effects import (
    VARIANT_COLUMNS,
    distinct_trials,
    paired_grasping,
    success_analysis,
    success_table,
    tolerance_table,
    variant_effects,
    variant_table,
)
from icub_affordance.analysis.verdicts import (
    best_robot_variant,
    held_interval,
    robot_effect_verdict,
    smallest_that_grasps,
    tolerated_noise,
)

OBJECTS = {  # object: (size, congruent under mapping A)
    "big_ball": ("large", True),
    "small_ball": ("small", False),
    "big_cube": ("large", False),
    "small_cube": ("small", True),
}
NATURAL = {"large": "power", "small": "precision"}


def trials(
    run: str,
    success,
    contact,
    networks: int = 4,
    schedule: str = "constant",
    sequences: int = 2,
    wrong=lambda net, obj, task: False,
) -> pd.DataFrame:
    """Categorisation and grasping trials of one variant; ``success(net, obj)`` and
    ``contact(net, obj)`` give each network x object's outcome (contact: seconds or NaN), the
    same in all its ``sequences`` (one physical trial); ``wrong(net, obj, task)`` marks a trial
    that held the object with the other grip (a failure). The final error differs between
    sequences (each is compared with its own demonstration)."""
    rows = []
    for net in range(networks):
        mapping = "A" if net < networks // 2 else "B"
        for task in ("grasping", "categorisation"):
            for obj, (size, congruent_a) in OBJECTS.items():
                congruent = congruent_a if mapping == "A" else not congruent_a
                natural = NATURAL[size]
                other = "precision" if natural == "power" else "power"
                required = natural if task == "grasping" or congruent else other
                ok, bad = bool(success(net, obj)), bool(wrong(net, obj, task))
                read = required if ok else (other if bad else "none")
                for seq in range(sequences):
                    rows.append(
                        {
                            "run": run, "categorisation_cue": "first_step",
                            "target": "commands", "hidden": 10, "iterations": 1200,
                            "learning_rate_schedule": schedule, "network": net,
                            "mapping": mapping, "mode": "embodied", "task": task,
                            "object": obj, "size": size, "target_grip": required,
                            "congruent": "" if task == "grasping" else str(congruent),
                            "sequence": seq, "held_out": seq == sequences - 1,
                            "success": ok and not bad, "wrong_grip_hold": bad,
                            "grip_used": read,
                            # sixty-fourths: their means over sequences are exact
                            "final_error": (1 + net + 3 * len(obj) % 5 + seq) / 64,
                            "contact_time": contact(net, obj),
                            "palm_error_mm": 2.0 + net + (10.0 if task == "categorisation" else 0),
                        }
                    )  # fmt: skip
    return pd.DataFrame(rows)


def one_sequence(df: pd.DataFrame) -> pd.DataFrame:
    """The table with only its first test sequence, final error the mean over the sequences (as
    a distinct trial keeps it)."""
    mean = df.groupby(["run", "network", "task", "object"])["final_error"].transform("mean")
    first = df.assign(final_error=mean)
    return first[first["sequence"] == 0].reset_index(drop=True)


def fisher_two_sided(table) -> float:
    """Fisher's exact test by the hypergeometric sum: every table with the same margins that is
    no more likely than the one observed."""
    (a, b), (c, d) = table
    row1, col1, n = a + b, a + c, a + b + c + d

    def prob(x):
        return comb(col1, x) * comb(n - col1, row1 - x) / comb(n, row1)

    observed = prob(a)
    lo, hi = max(0, row1 - (n - col1)), min(row1, col1)
    return sum(prob(x) for x in range(lo, hi + 1) if prob(x) <= observed * (1 + 1e-7))


def test_the_variant_table_counts_success_and_contact_by_task_over_distinct_trials():
    df = trials(
        "v",
        success=lambda net, obj: obj == "big_ball",
        contact=lambda net, obj: 1.5 if obj.startswith("big") else np.nan,
        wrong=lambda net, obj, task: obj == "small_cube" and task == "grasping" and net == 1,
    )
    row = variant_table(df).iloc[0]
    # 4 networks x 2 tasks x 4 objects, each counted once (its two sequences are one trial)
    assert row["networks"] == 4 and row["trials"] == 4 * 2 * 4
    assert row["grasping_trials"] == row["categorisation_trials"] == 16
    assert row["grasping_success"] == pytest.approx(0.25)
    assert row["categorisation_success"] == pytest.approx(0.25)
    assert row["grasping_contact"] == pytest.approx(0.5)
    assert row["grasping_contact_time"] == pytest.approx(1.5)
    assert (row["grasping_wrong_grip_hold"], row["categorisation_wrong_grip_hold"]) == (1, 0)
    # the median palm error of the grasping trials only: networks at 2, 3, 4, 5 mm
    assert row["grasping_palm_error_mm"] == pytest.approx(3.5)


def test_a_contrast_without_variance_falls_back_to_the_exact_test_over_distinct_trials():
    # every network holds both large objects and neither small one: the size contrast is -1 and
    # the congruency contrast 0 in every network, so neither has a variance to test
    df = trials("v", success=lambda net, obj: obj.startswith("big"), contact=lambda n, o: np.nan)
    effect = variant_effects(df)["v"]
    success = effect["success"]
    assert {success["tests"][f]["method"] for f in ("congruency", "size")} == {"exact"}
    # an interaction has no exact fallback: with no variance it is not tested
    assert success["tests"]["congruency:size"]["method"] == "none"
    assert success["distinct_trials"] == 16
    cat = distinct_trials(df)
    cat = cat[cat["task"] == "categorisation"]
    for factor, first in (("congruency", "True"), ("size", "large")):
        column = cat["congruent"] if factor == "congruency" else cat["size"]
        a = cat[column == first]["success"]
        b = cat[column != first]["success"]
        table = [[int(a.sum()), int((~a).sum())], [int(b.sum()), int((~b).sum())]]
        assert sum(map(sum, table)) == 16  # 4 networks x 4 objects, not x 2 sequences
        assert success["tests"][factor]["table"] == table
        assert success["tests"][factor]["p"] == pytest.approx(fisher_two_sided(table), rel=1e-9)
    assert success["tests"]["size"]["table"] == [[8, 0], [0, 8]]
    assert robot_effect_verdict(success, "success", "size").paper_direction
    assert not robot_effect_verdict(success, "success", "congruency").significant
    times = effect["contact_time"]
    assert {t["method"] for t in times["tests"].values()} == {"none"}  # nothing touched
    assert robot_effect_verdict(times, "contact_time", "size") is None


@pytest.mark.heavy
def test_success_is_tested_by_per_network_contrasts_and_contact_time_by_its_own():
    # every congruency x size cell has networks that hold the object and networks that do not
    order = list(OBJECTS)
    held = {(n, o): (n + order.index(o)) % 2 == 0 or (n == 5 and o == "big_ball")
            for n in range(6) for o in OBJECTS}  # fmt: skip

    def contact(net, obj):  # incongruent 0.2 s slower, small 0.1 s slower, plus jitter
        congruent = OBJECTS[obj][1] if net < 3 else not OBJECTS[obj][1]
        small = OBJECTS[obj][0] == "small"
        slower = 0.2 + 0.004 * net  # networks differ in the effect, so it has a variance
        return 1.5 + slower * (not congruent) + 0.1 * small + 0.01 * net + 0.003 * (net * small)

    df = trials("v", success=lambda n, o: held[(n, o)], contact=contact, networks=6)
    effect = variant_effects(df)["v"]
    success = effect["success"]
    assert {t["method"] for t in success["tests"].values()} == {"contrasts"}
    # the size contrast by hand: per network the small objects' share held minus the large ones',
    # a t-test over the 6 networks with the mapping as covariate (df = 6 - 2)
    cat = df[(df["task"] == "categorisation") & (df["sequence"] == 0)]
    rate = cat.groupby(["network", "size"])["success"].mean().unstack()
    diff = (rate["small"] - rate["large"]).to_numpy()
    mapping = np.where(np.arange(6) < 3, -0.5, 0.5)
    fit = sps.linregress(mapping, diff)
    intercept_se = fit.intercept_stderr
    term = success["tests"]["size"]
    assert term["estimate"] == pytest.approx(fit.intercept, abs=1e-12)
    assert term["p"] == pytest.approx(2 * sps.t.sf(abs(fit.intercept / intercept_se), 4))
    assert term["df"] == 4 and term["networks"] == 6
    times = effect["contact_time"]
    assert {times["tests"][f]["method"] for f in ("congruency", "size")} == {"contrasts"}
    assert times["tests"]["congruency:size"]["method"] == "none"  # 0 in every network
    assert times["tests"]["congruency"]["estimate"] == pytest.approx(0.2 + 0.01, abs=1e-6)
    assert times["tests"]["size"]["estimate"] == pytest.approx(0.1 + 0.0075, abs=1e-6)
    verdict = robot_effect_verdict(times, "contact_time", "congruency")
    assert verdict.paper_direction and verdict.significant


def test_contact_time_needs_three_networks_that_touched_in_every_cell():
    # only networks 0 and 1 touch at all: the contrast over networks has no degrees of freedom
    df = trials(
        "v",
        success=lambda net, obj: net < 2,
        contact=lambda net, obj: 1.0 + 0.1 * net + 0.05 * len(obj) if net < 2 else np.nan,
    )
    tests = variant_effects(df)["v"]["contact_time"]["tests"]
    assert {t["method"] for t in tests.values()} == {"none"}
    assert "2 network(s)" in tests["congruency"]["reason"]


@pytest.mark.heavy
@pytest.mark.parametrize("case", ["exact", "contrasts"])
def test_five_identical_sequences_give_the_counts_and_p_values_of_one(case):
    """The issue's check: every robot table and test over five identical test sequences of each
    network x object x task equals the same over one sequence (final error, which each sequence
    measures against its own demonstration, averaged)."""
    order = list(OBJECTS)

    def success(net, obj):  # exact: every network holds the large objects only (no variance)
        return obj.startswith("big") if case == "exact" else (net + order.index(obj)) % 3 != 0

    def contact(net, obj):
        return 1.2 + 0.1 * net + 0.02 * len(obj) * net if success(net, obj) else np.nan

    def wrong(net, obj, task):
        return net == 2 and obj == "small_cube"

    five = trials("v", success, contact, networks=6, sequences=5, wrong=wrong)
    one = one_sequence(five)
    assert len(five) == 5 * len(one)
    e5, e1 = variant_effects(five), variant_effects(one)
    assert json.dumps(e5, sort_keys=True) == json.dumps(e1, sort_keys=True)
    assert e5["v"]["success"]["tests"]["size"]["method"] == case
    pd.testing.assert_frame_equal(variant_table(five), variant_table(one))
    pd.testing.assert_frame_equal(success_table(five), success_table(one))
    replay = pd.DataFrame(
        {"plan": ["commands", "sensed_postures"], "success": [True, False],
         "wrong_grip_hold": [False, True]}
    )  # fmt: skip
    a5 = success_analysis(five.drop(columns=list(VARIANT_COLUMNS)), replay)
    a1 = success_analysis(one.drop(columns=list(VARIANT_COLUMNS)), replay)
    assert json.dumps(a5, sort_keys=True) == json.dumps(a1, sort_keys=True)
    assert a5["n_trials"] == 6 * 2 * 4 and a5["wrong_grip_holds"] == 2
    # the counts the old summary gave (every sequence a trial) are five times these
    assert (
        e5["v"]["success"]["distinct_trials"] == 24 == len(five[five.task == "categorisation"]) / 5
    )


def test_sequences_that_disagree_on_the_physics_are_not_one_trial():
    df = trials("v", success=lambda net, obj: True, contact=lambda net, obj: 1.0)
    df.loc[1, "success"] = False  # network 0's grasping big ball, second sequence
    with pytest.raises(ValueError, match="success"):
        distinct_trials(df)


def test_the_best_and_the_smallest_variant_that_grasps():
    variants = pd.DataFrame(
        {
            "run": ["a", "b", "c", "d"],
            "hidden": [10, 40, 20, 40],
            "iterations": [12000, 12000, 48000, 48000],
            "grasping_success": [0.1, 0.95, 0.95, 0.5],
        }
    )
    assert best_robot_variant(variants)["run"] == "c"  # ties: fewer hidden units
    assert smallest_that_grasps(variants)["run"] == "c"
    assert smallest_that_grasps(variants, bar=0.99) is None


def test_the_tolerance_table_and_the_largest_noise_the_body_forgives():
    """Made-up tolerance trials: per noise level the share held, the median palm error and each
    object's share; the tolerated noise is the largest level held in at least 90%."""
    held = {0.0: [1, 1, 1, 1], 0.005: [1, 1, 1, 1, 1, 1, 1, 1, 1, 0], 0.01: [1, 0, 0, 0]}
    rows = []
    for noise, outcomes in held.items():
        for k, ok in enumerate(outcomes):
            rows.append({"object": ["big_ball", "small_ball"][k % 2], "noise": noise,
                         "success": bool(ok), "palm_error_mm": 1000 * noise + k})  # fmt: skip
    table = tolerance_table(pd.DataFrame(rows))
    assert table["noise"].tolist() == [0.0, 0.005, 0.01]
    assert table["trials"].tolist() == [4, 10, 4]
    assert table["success"].tolist() == pytest.approx([1.0, 0.9, 0.25])
    assert table["palm_error_mm"].tolist() == pytest.approx([1.5, 9.5, 11.5])
    assert table["small_ball_success"].tolist() == pytest.approx([1.0, 0.8, 0.0])
    assert tolerated_noise(table)["noise"] == 0.005
    assert tolerated_noise(table, bar=0.95)["noise"] == 0.0
    assert tolerated_noise(table, bar=1.01) is None


def test_schedules_are_compared_on_the_same_networks_and_objects():
    """Two variants that differ in the learning-rate schedule alone: each network x object's
    grasping trial pairs with the other variant's; the exact McNemar test is the two-sided
    binomial test of the discordant pairs, recomputed by hand."""
    # constant: network 0 misses everything; anneal: networks 0-3 hold everything but the
    # small ball of network 3, which constant holds
    constant = trials("c", success=lambda net, obj: net > 0, contact=lambda net, obj: 1.0)
    anneal = trials(
        "a",
        success=lambda net, obj: not (net == 3 and obj == "small_ball"),
        contact=lambda net, obj: 1.0,
        schedule="anneal",
    )
    keys = tuple(k for k in VARIANT_COLUMNS if k != "run")
    (pair,) = paired_grasping(pd.concat([constant, anneal]), "learning_rate_schedule", keys)
    assert (pair["a"], pair["b"]) == ("anneal", "constant")
    assert pair["trials"] == 16  # 4 networks x 4 objects, the two sequences counted once
    assert (pair["held_a"], pair["held_b"]) == (15, 12)
    assert (pair["only_a"], pair["only_b"]) == (4, 1)
    n, k = 5, 1  # two-sided: P(X <= 1) + P(X >= 4) for X ~ Binomial(5, 1/2)
    by_hand = sum(comb(n, x) for x in range(n + 1) if min(x, n - x) <= k) / 2**n
    assert pair["p"] == pytest.approx(by_hand)
    # variants that differ in more than the schedule are not paired
    other = anneal.assign(hidden=20)
    assert paired_grasping(pd.concat([constant, other]), "learning_rate_schedule", keys) == []


def test_the_interval_of_a_share_held_is_clopper_pearson():
    """Recomputed from the beta quantiles that define it; at 0 and at all held, one end is 0 or
    1."""
    from scipy.stats import beta

    low, high = held_interval(45, 48)
    assert low == pytest.approx(beta.ppf(0.025, 45, 4)) and low < 0.9 < 45 / 48
    assert high == pytest.approx(beta.ppf(0.975, 46, 3))
    assert held_interval(0, 10)[0] == 0.0 and held_interval(10, 10)[1] == 1.0


@pytest.mark.heavy
def test_the_robots_tests_are_one_family_adjusted_by_holm():
    """Two variants' defined tests, Holm-adjusted together (by hand: sorted p times the tests
    left, made monotone), and the verdict reads the adjusted p."""
    order = list(OBJECTS)
    held = {(n, o): (n + order.index(o)) % 2 == 0 or (n == 5 and o == "big_ball")
            for n in range(6) for o in OBJECTS}  # fmt: skip
    df = pd.concat(
        [
            trials("a", success=lambda n, o: held[(n, o)], contact=lambda n, o: np.nan, networks=6),
            trials(
                "b", success=lambda n, o: not held[(n, o)], contact=lambda n, o: np.nan, networks=6
            ),
        ]
    )
    effects = variant_effects(df)
    tests = [
        t for run in ("a", "b") for m in ("success", "contact_time")
        for t in effects[run][m]["tests"].values() if t["method"] != "none"
    ]  # fmt: skip
    raw = np.array([t["p"] for t in tests])
    order_ = np.argsort(raw)
    m = len(raw)
    expected = np.empty(m)
    running = 0.0
    for rank, i in enumerate(order_):
        running = max(running, min(1.0, (m - rank) * raw[i]))
        expected[i] = running
    np.testing.assert_allclose([t["p_holm"] for t in tests], expected, rtol=1e-12)
    for run in ("a", "b"):
        for factor in ("congruency", "size"):
            test = effects[run]["success"]["tests"][factor]
            verdict = robot_effect_verdict(effects[run]["success"], "success", factor)
            assert verdict.significant == (test["p_holm"] < 0.05)
