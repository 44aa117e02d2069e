"""The robot variants' summary: success and contact per variant, and the congruency and size
effects on success (mixed model, or Fisher's exact test where a rate sits at 0 or 1) and contact
time, recomputed by hand on made-up trials."""

from math import comb

import numpy as np
import pandas as pd
import pytest

from icub_affordance.embodied import (
    VARIANT_COLUMNS,
    tolerance_table,
    variant_effects,
    variant_table,
)
from icub_affordance.findings import (
    best_robot_variant,
    held_interval,
    paired_grasping,
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


def trials(
    run: str, success, contact, networks: int = 4, schedule: str = "constant"
) -> pd.DataFrame:
    """Categorisation and grasping trials of one variant; ``success(net, obj)`` and
    ``contact(net, obj)`` give each network x object's outcome (contact: seconds or NaN)."""
    rows = []
    for net in range(networks):
        mapping = "A" if net < networks // 2 else "B"
        for task in ("grasping", "categorisation"):
            for obj, (size, congruent_a) in OBJECTS.items():
                congruent = congruent_a if mapping == "A" else not congruent_a
                for seq in range(2):
                    rows.append(
                        {
                            "run": run, "categorisation_cue": "first_step",
                            "target": "commands", "hidden": 10, "iterations": 1200,
                            "learning_rate_schedule": schedule, "network": net,
                            "mapping": mapping, "task": task, "object": obj,
                            "size": size, "sequence": seq,
                            "congruent": "" if task == "grasping" else str(congruent),
                            "success": bool(success(net, obj)),
                            "contact_time": contact(net, obj),
                            "palm_error_mm": 2.0 + net + (10.0 if task == "categorisation" else 0),
                        }
                    )  # fmt: skip
    return pd.DataFrame(rows)


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


def test_the_variant_table_counts_success_and_contact_by_task():
    df = trials(
        "v",
        success=lambda net, obj: obj == "big_ball",
        contact=lambda net, obj: 1.5 if obj.startswith("big") else np.nan,
    )
    row = variant_table(df).iloc[0]
    assert row["networks"] == 4 and row["trials"] == 4 * 2 * 4 * 2
    assert row["grasping_success"] == pytest.approx(0.25)
    assert row["categorisation_success"] == pytest.approx(0.25)
    assert row["grasping_contact"] == pytest.approx(0.5)
    assert row["grasping_contact_time"] == pytest.approx(1.5)
    # the median palm error of the grasping trials only: networks at 2, 3, 4, 5 mm
    assert row["grasping_palm_error_mm"] == pytest.approx(3.5)


def test_a_rate_at_zero_gives_the_exact_test_recomputed_by_hand():
    # only congruent big objects are held: the incongruent small cells sit at 0
    df = trials(
        "v",
        success=lambda net, obj: obj == "big_ball" and net < 2 or obj == "big_cube" and net >= 2,
        contact=lambda net, obj: np.nan,
    )
    effect = variant_effects(df)["v"]
    success = effect["success"]
    assert success["method"] == "exact"
    cat = df[df["task"] == "categorisation"]
    for factor, first in (("congruency", "True"), ("size", "large")):
        column = cat["congruent"] if factor == "congruency" else cat["size"]
        a = cat[column == first]["success"]
        b = cat[column != first]["success"]
        table = [[int(a.sum()), int((~a).sum())], [int(b.sum()), int((~b).sum())]]
        assert success["tests"][factor]["table"] == table
        assert success["tests"][factor]["p"] == pytest.approx(fisher_two_sided(table), rel=1e-9)
    assert robot_effect_verdict(success, "success", "congruency").paper_direction
    assert effect["contact_time"]["method"] == "none"  # nothing touched


def test_rates_between_zero_and_one_give_the_mixed_model_and_contact_time_its_own():
    # every congruency x size cell has networks that hold the object and networks that do not
    order = list(OBJECTS)
    held = {(n, o): (n + order.index(o)) % 2 == 0 for n in range(6) for o in OBJECTS}

    def contact(net, obj):  # incongruent 0.2 s slower, small 0.1 s slower, plus jitter
        congruent = OBJECTS[obj][1] if net < 3 else not OBJECTS[obj][1]
        return 1.5 + 0.2 * (not congruent) + 0.1 * (OBJECTS[obj][0] == "small") + 0.01 * net

    df = trials("v", success=lambda n, o: held[(n, o)], contact=contact, networks=6)
    effect = variant_effects(df)["v"]
    assert effect["success"]["method"] == "contrasts"
    times = effect["contact_time"]
    assert times["method"] == "contrasts"
    assert times["contrasts"]["congruency"]["estimate"] == pytest.approx(0.2, abs=1e-6)
    assert times["contrasts"]["size"]["estimate"] == pytest.approx(0.1, abs=1e-6)
    verdict = robot_effect_verdict(times, "contact_time", "congruency")
    assert verdict.paper_direction and verdict.significant


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
