"""Explore, then confirm (issue 24): the share held on the networks a variant was chosen on and on
fresh ones, each grasping trial counted once, with an interval that takes a network's objects as
one cluster (icub_affordance.analysis.confirmation)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from icub_affordance.analysis.confirmation import (
    COLUMNS,
    DETAIL_COLUMNS,
    bar_verdict,
    clustered_interval,
    confirmation_table,
)
from icub_affordance.learning.variants import NetworkVariant

OBJECTS = ("big_ball", "small_ball", "big_cube", "small_cube")


def robot_trials(run: str, held: dict[int, list[bool]], sequences: int = 5) -> pd.DataFrame:
    """A run's robot trials: each network's grasping trial of each object repeated over the
    test sequences (one movement), plus categorisation trials that must not count; even
    networks learn mapping A, odd ones B."""
    rows = []
    for net, outcomes in held.items():
        mine = {"run": run, "network": net, "mapping": "AB"[net % 2]}
        for obj, ok in zip(OBJECTS, outcomes, strict=True):
            for seq in range(sequences):
                rows.append(mine | dict(task="grasping", object=obj, success=ok))
                rows.append(
                    mine | dict(task="categorisation", object=obj, success=True, sequence=seq)
                )
    return pd.DataFrame(rows)


def by_hand(held: list[int], trials: list[int], level: float = 0.95) -> tuple[float, float]:
    """Korn and Graubard's interval, computed independently: the share's variance from an OLS
    fit of each trial's outcome on a constant with standard errors clustered by network
    (statsmodels, which scales by G / (G - 1)), then Clopper-Pearson's beta quantiles."""
    import statsmodels.api as sm

    y = np.concatenate([[1.0] * h + [0.0] * (n - h) for h, n in zip(held, trials, strict=True)])
    groups = np.repeat(np.arange(len(held)), trials)
    fit = sm.OLS(y, np.ones_like(y)).fit(cov_type="cluster", cov_kwds={"groups": groups})
    p, var, n, m = float(fit.params[0]), float(fit.cov_params()[0, 0]), len(y), len(held)
    n_eff = min(n, p * (1 - p) / var) if var > 0 else n
    n_eff *= (stats.t.ppf(0.975, n - 1) / stats.t.ppf(0.975, m - 1)) ** 2
    low = stats.beta.ppf(0.025, p * n_eff, n_eff * (1 - p) + 1) if p > 0 else 0.0
    high = stats.beta.ppf(0.975, p * n_eff + 1, n_eff * (1 - p)) if p < 1 else 1.0
    return low, high


@pytest.mark.parametrize(
    "held",
    [
        [4, 4, 4, 3, 4, 4, 3, 4, 4, 4, 3, 4],  # 45 of 48, the exploration's count
        [4, 4, 0, 4, 4, 0, 4, 4, 4, 4, 0, 4],  # all or nothing: strongly clustered
        [2, 3, 1, 4, 2, 3, 0, 4, 3, 2, 1, 3],
    ],
)
def test_the_interval_matches_an_independent_computation(held):
    got = clustered_interval(held, [4] * len(held))
    low, high = by_hand(held, [4] * len(held))
    assert got["share"] == pytest.approx(sum(held) / 48)
    assert got["ci_low"] == pytest.approx(low, abs=1e-9)
    assert got["ci_high"] == pytest.approx(high, abs=1e-9)
    # the design effect before its floor: the clustered variance over the binomial one
    raw = raw_design_effect(held, [4] * len(held))
    assert got["design_effect_raw"] == pytest.approx(raw, rel=1e-9)
    assert got["design_effect"] == pytest.approx(max(1.0, raw), rel=1e-9)


def raw_design_effect(held: list[int], trials: list[int]) -> float:
    """The share's variance clustered by network (statsmodels' OLS on a constant) over the
    binomial variance of as many independent trials."""
    import statsmodels.api as sm

    y = np.concatenate([[1.0] * h + [0.0] * (n - h) for h, n in zip(held, trials, strict=True)])
    groups = np.repeat(np.arange(len(held)), trials)
    fit = sm.OLS(y, np.ones_like(y)).fit(cov_type="cluster", cov_kwds={"groups": groups})
    p = float(fit.params[0])
    return float(fit.cov_params()[0, 0]) / (p * (1 - p) / len(y))


def test_clusters_of_one_trial_give_clopper_pearson_at_one_trial_fewer():
    """With one trial per network the design effect is m / (m - 1) and the t-correction 1: the
    interval is the exact binomial one at m - 1 trials."""
    held = [1] * 30 + [0] * 11  # 41 networks, one trial each; 30 of 41 held
    got = clustered_interval(held, [1] * len(held))
    x = 30 / 41 * 40  # the share, at m - 1 = 40 trials
    low = stats.beta.ppf(0.025, x, 40 - x + 1)
    high = stats.beta.ppf(0.975, x + 1, 40 - x)
    assert got["effective_trials"] == pytest.approx(40)
    assert (got["ci_low"], got["ci_high"]) == pytest.approx((low, high))


def test_every_trial_held_gives_the_closed_form_lower_end():
    """At a share of 1 the variance is 0 (design effect 1) and Clopper-Pearson's lower end is
    (alpha / 2) ** (1 / n) at the df-corrected n."""
    got = clustered_interval([4] * 12, [4] * 12)
    n = 48 * (stats.t.ppf(0.975, 47) / stats.t.ppf(0.975, 11)) ** 2
    assert got["design_effect"] == 1 and got["effective_trials"] == pytest.approx(n)
    assert np.isnan(got["design_effect_raw"])  # no binomial variance to divide by
    assert got["ci_low"] == pytest.approx(0.025 ** (1 / n)) and got["ci_high"] == 1
    # 48 of 48 held with 12 networks does not reach what 48 independent trials would show
    assert got["ci_low"] < stats.binomtest(48, 48).proportion_ci(method="exact").low


def test_clustering_widens_the_interval():
    """The same 36 of 48 held: spread evenly (3 per network) or all-or-nothing by network."""
    even = clustered_interval([3] * 12, [4] * 12)
    clustered = clustered_interval([4] * 9 + [0] * 3, [4] * 12)
    assert even["share"] == clustered["share"] == 0.75
    assert clustered["design_effect"] > 3 and even["design_effect"] == 1
    # evenly spread, every network's count is the share's: no variance between networks, a raw
    # design effect of 0, which the interval does not take below 1
    assert even["design_effect_raw"] == 0 and clustered["design_effect_raw"] > 3
    assert clustered["ci_high"] - clustered["ci_low"] > 1.5 * (even["ci_high"] - even["ci_low"])


def test_too_few_networks_are_refused():
    with pytest.raises(ValueError, match="2 or more networks"):
        clustered_interval([4], [4])


def confirmed(**runs) -> list[dict]:
    return [{"target": "commands", "hidden": 40} | runs]


def test_the_table_counts_each_network_and_object_once():
    """Five identical test sequences give the table of one; categorisation trials never count."""
    explored = {n: [True, True, n % 3 > 0, True] for n in range(12)}
    fresh = {n: [True, n % 2 == 0, True, True] for n in range(12, 24)}
    variants = confirmed(exploration="explore", confirmation="confirm")
    five = pd.concat([robot_trials("explore", explored), robot_trials("confirm", fresh)])
    one = pd.concat([robot_trials("explore", explored, 1), robot_trials("confirm", fresh, 1)])
    table = confirmation_table(five, variants)
    pd.testing.assert_frame_equal(table, confirmation_table(one, variants))
    assert list(table.columns) == ["target", "hidden", *COLUMNS, *DETAIL_COLUMNS]
    assert list(table["seed_set"]) == ["exploration", "confirmation"]
    assert list(table["networks"]) == [12, 12] and list(table["trials"]) == [48, 48]
    assert list(table["held"]) == [44, 42]  # 4 networks miss a cube; 6 miss the small ball
    assert list(table["first_network"]) == [0, 12] and list(table["last_network"]) == [11, 23]
    row = table.iloc[1]
    expected = clustered_interval([4 if n % 2 == 0 else 3 for n in range(12)], [4] * 12)
    assert (row["ci_low"], row["ci_high"]) == pytest.approx(
        (expected["ci_low"], expected["ci_high"])
    )
    assert row["design_effect_raw"] == pytest.approx(expected["design_effect_raw"])


def test_without_the_exploration_the_table_has_the_confirmations_row_alone():
    """The default build does not test the variant on the networks it was chosen on (its
    exploration None): the table is the full table's confirmation row, the same numbers; a
    variant without a confirmation run is refused."""
    explored = {n: [True, True, n % 3 > 0, True] for n in range(12)}
    fresh = {n: [True, n % 2 == 0, True, True] for n in range(12, 24)}
    both = pd.concat([robot_trials("explore", explored), robot_trials("confirm", fresh)])
    full = confirmation_table(both, confirmed(exploration="explore", confirmation="confirm"))
    alone = confirmation_table(
        robot_trials("confirm", fresh), confirmed(exploration=None, confirmation="confirm")
    )
    assert list(alone["seed_set"]) == ["confirmation"] and list(alone["run"]) == ["confirm"]
    pd.testing.assert_frame_equal(alone, full.iloc[[1]].reset_index(drop=True))
    with pytest.raises(ValueError, match="no confirmation run"):
        confirmation_table(both, confirmed(exploration="explore", confirmation=None))


def test_the_table_shows_the_misses_per_mapping_and_object():
    """By hand: in the exploration networks 0, 3, 6 and 9 miss the big cube (two of mapping A,
    0 and 6; two of B); in the confirmation the odd networks (all of mapping B) miss the small
    ball. Six networks per mapping, each object once per network."""
    explored = {n: [True, True, n % 3 > 0, True] for n in range(12)}
    fresh = {n: [True, n % 2 == 0, True, True] for n in range(12, 24)}
    trials = pd.concat([robot_trials("explore", explored), robot_trials("confirm", fresh)])
    table = confirmation_table(trials, confirmed(exploration="explore", confirmation="confirm"))
    detail = [c for c in DETAIL_COLUMNS if c != "design_effect_raw"]
    assert detail == [f"{m}_{o}_{c}" for m in "AB" for o in OBJECTS for c in ("trials", "held")]
    assert (table[[c for c in detail if c.endswith("_trials")]] == 6).all().all()
    for _, row in table.iterrows():  # the per-object counts add up to the row's
        assert sum(row[c] for c in detail if c.endswith("_held")) == row["held"]
        assert sum(row[c] for c in detail if c.endswith("_trials")) == row["trials"]
    explore, confirm = (table.iloc[k] for k in (0, 1))
    missed = {c.removesuffix("_held"): 6 - explore[c] for c in detail if c.endswith("_held")}
    assert {k: v for k, v in missed.items() if v} == {"A_big_cube": 2, "B_big_cube": 2}
    missed = {c.removesuffix("_held"): 6 - confirm[c] for c in detail if c.endswith("_held")}
    assert {k: v for k, v in missed.items() if v} == {"B_small_ball": 6}


def test_no_confirmed_variant_gives_the_columns_without_rows():
    table = confirmation_table(robot_trials("explore", {0: [True] * 4}), [])
    assert table.empty and list(table.columns) == [*COLUMNS, *DETAIL_COLUMNS]


def test_sequences_that_disagree_are_refused():
    trials = robot_trials("explore", {0: [True] * 4, 1: [True] * 4})
    first = trials.index[(trials["task"] == "grasping")][0]
    trials.loc[first, "success"] = False
    variants = confirmed(exploration="explore", confirmation="explore")
    with pytest.raises(ValueError, match="network 0 .*big_ball.*must agree"):
        confirmation_table(trials, variants)


def test_a_run_without_trials_is_refused():
    trials = robot_trials("explore", {0: [True] * 4, 1: [True] * 4})
    with pytest.raises(ValueError, match="'confirm'"):
        confirmation_table(trials, confirmed(exploration="explore", confirmation="confirm"))


@pytest.mark.parametrize(
    ("low", "high", "verdict"),
    [(0.91, 0.99, "above"), (0.85, 0.97, "includes"), (0.7, 0.89, "below"), (0.9, 1, "includes")],
)
def test_the_bar_verdict(low, high, verdict):
    assert bar_verdict(low, high, 0.9) == verdict


# -- the book's values: the rows' numbers, and the bar phrase resting on them and moving with them


#: The per-object cells of a row (``DETAIL_COLUMNS`` after the raw design effect).
CELLS = [f"{m}_{o}" for m in "AB" for o in OBJECTS]


def object_detail(held: int, networks: int = 12) -> dict[str, int]:
    """A row's per-mapping and per-object counts: each cell the trials of its mapping's
    networks (half of them), the misses (trials - held) dealt over the cells in turn."""
    per_cell = networks // 2
    missed = dict.fromkeys(CELLS, 0)
    for k in range(networks * len(OBJECTS) - held):
        missed[CELLS[k % len(CELLS)]] += 1
    assert all(n <= per_cell for n in missed.values())
    return {f"{c}_trials": per_cell for c in CELLS} | {
        f"{c}_held": per_cell - missed[c] for c in CELLS
    }


def confirmation_csv(
    explore=(45, 0.83, 0.98), confirm=(44, 0.80, 0.97), raw=(0.85, 0.85)
) -> pd.DataFrame:
    """data/embodied/confirmation.csv for one variant: (held of 48, ci_low, ci_high) per set,
    its raw design effect (``raw``, below 1: the design effect floors it at 1) and its counts
    per mapping and object, consistent with the row's (``object_detail``)."""
    variant = {
        "categorisation_cue": "all_steps",
        "target": "commands",
        "hidden": 40,
        "iterations": 768000,
        "learning_rate_schedule": "anneal",
    }
    rows = []
    for name, (held, low, high), first, deff in (
        ("exploration", explore, 0, raw[0]),
        ("confirmation", confirm, 12, raw[1]),
    ):
        rows.append(
            variant
            | {"seed_set": name, "run": name, "first_network": first, "last_network": first + 11}
            | {"networks": 12, "trials": 48, "held": held, "share": held / 48}
            | {"design_effect": max(1.0, deff), "effective_trials": 40.0}
            | {"ci_low": low, "ci_high": high, "design_effect_raw": deff}
            | object_detail(held)
        )
    return pd.DataFrame(rows)[[*variant, *COLUMNS, *DETAIL_COLUMNS]]  # as the table writes it


def page(table: pd.DataFrame) -> tuple[dict, pd.DataFrame]:
    from icub_workflow.book import pages

    values, shown = pages._confirmation(table)
    return pages.traced({"robot_test": values}), shown


def test_the_values_are_the_rows_and_the_bar_phrase_rests_on_them():
    out, shown = page(confirmation_csv())
    values, claims = out["robot_test"], out["claims"]["robot_test"]
    assert set(claims) == {"confirmation_bar"}
    assert claims["confirmation_bar"] == [
        "robot_test.bar", "robot_test.confirmation_ci_low", "robot_test.confirmation_ci_high"
    ]  # fmt: skip
    for entry in claims["confirmation_bar"]:
        assert isinstance(values[entry.split(".", 1)[1]], int | float)
    assert (values["exploration_held"], values["exploration_trials"]) == (45, 48)
    assert values["confirmation_held"] == 44 and values["confirmation_networks"] == 12
    assert values["confirmed_label"] == "all · cmd · h40 · 768k · anneal"
    # the fresh networks' misses, one each on mapping A's objects as the fixture deals them
    assert values["confirmation_misses"] == (
        "A big ball 1 of 6; A small ball 1 of 6; A big cube 1 of 6; A small cube 1 of 6"
    )
    # the table: every row as written, beside its label and where it stands against the bar
    assert shown["seed_set"].tolist() == ["exploration", "confirmation"]
    assert shown[["first_network", "last_network"]].values.tolist() == [[0, 11], [12, 23]]
    assert shown["held"].tolist() == [45, 44] and shown["design_effect_raw"].tolist()[1] == 0.85
    moved, _ = page(confirmation_csv(confirm=(41, 0.70, 0.92), raw=(0.85, 0.6)))
    assert "B big ball 1 of 6" in moved["robot_test"]["confirmation_misses"]
    held, _ = page(confirmation_csv(confirm=(48, 0.93, 1.0), raw=(0.85, float("nan"))))
    assert held["robot_test"]["confirmation_misses"] == "none"


@pytest.mark.parametrize(
    ("low", "high", "words"),
    [
        (0.92, 0.99, "lies above it"),
        (0.80, 0.97, "includes it"),
        (0.70, 0.88, "lies below it"),
    ],
)
def test_the_bar_is_set_against_the_confirmations_interval(low, high, words):
    out, shown = page(confirmation_csv(confirm=(44, low, high)))
    assert out["robot_test"]["confirmation_verdict"] == bar_verdict(low, high, 0.9)
    assert out["robot_test"]["confirmation_bar"].startswith(words)
    assert shown["vs_bar"].tolist() == ["", bar_verdict(low, high, 0.9)]


def test_the_exploration_alone_never_meets_the_bar():
    """An exploration interval far above the bar changes its numbers, not the verdict, which is
    the confirmation's."""
    high, _ = page(confirmation_csv(explore=(48, 0.95, 1.0)))
    low, _ = page(confirmation_csv(explore=(30, 0.45, 0.78)))
    assert high["robot_test"]["exploration_held"] == 48
    assert low["robot_test"]["exploration_held"] == 30
    assert high["robot_test"]["confirmation_bar"] == low["robot_test"]["confirmation_bar"]


def test_every_confirmed_variant_is_in_the_table():
    one = confirmation_csv(confirm=(44, 0.92, 0.99))
    two = confirmation_csv(explore=(40, 0.7, 0.9), confirm=(30, 0.5, 0.8)).assign(hidden=20)
    table = pd.concat([one, two], ignore_index=True)
    out, shown = page(table)
    assert out["robot_test"]["confirmation_verdict"] == "above"  # the first's
    assert (
        shown["variant"].tolist()
        == ["all · cmd · h40 · 768k · anneal"] * 2 + ["all · cmd · h20 · 768k · anneal"] * 2
    )
    assert shown["vs_bar"].tolist() == ["", "above", "", "below"]


def test_no_confirmed_variant_says_so():
    out, shown = page(confirmation_csv().iloc[0:0])
    assert shown.empty and out["robot_test"]["confirmation_bar"].startswith("is not tested")


# -- the chapter at either scale: the exploration's row, the comparison of variants, the films


def test_without_the_exploration_row_the_page_says_where_that_share_is():
    """The default build's table (the fresh networks' row alone): the bar's verdict and the
    counts are the confirmation's, as with both rows; the exploration's sentence says the full
    scale shows that share, and gives no count; with the row, it gives the row's counts."""
    from icub_workflow.book import pages

    both = confirmation_csv(explore=(30, 0.45, 0.78))
    alone = both[both["seed_set"] == "confirmation"].reset_index(drop=True)
    full, fresh = page(both)[0]["robot_test"], page(alone)[0]["robot_test"]
    assert "exploration_held" not in fresh and full["exploration_held"] == 30
    for key in ("confirmation_bar", "confirmation_held", "confirmation_ci_low", "bar"):
        assert fresh[key] == full[key], key
    assert page(alone)[1]["seed_set"].tolist() == ["confirmation"]
    said = pages._exploration(page(alone)[1])
    assert said["explored"] is False and "full scale" in said["exploration_words"]
    assert not any(ch.isdigit() for ch in said["exploration_words"])
    said = pages._exploration(page(both)[1])
    assert said["explored"] is True and "30 of 48" in said["exploration_words"]


def robot_config(default: list[dict], robustness: bool = False) -> dict:
    """The config's sections the robot chapter reads, with ``default`` as robot.default."""
    from conftest import load_config

    config = load_config() | {"robustness": robustness}
    return config | {"robot": config["robot"] | {"default": default}}


def variants_csv(runs: list[str], palm: list[float], held: list[float]) -> pd.DataFrame:
    """data/embodied/variants.csv's columns the scope reads: a run's grasping share, palm."""
    return pd.DataFrame({"run": runs, "grasping_palm_error_mm": palm, "grasping_success": held})


def test_the_default_build_compares_no_variants_and_says_the_full_scale_does():
    """With the own networks alone (the default build), the comparison is left to the full
    scale in one sentence whose counts are the config's (its grid, networks 0..11), and the
    effects and palm are the own networks'; with more variants (robot.default's entries, or
    the grid at full scale) they are compared and the effects are the best variant's."""
    from icub_workflow.book import pages

    own = variants_csv(["main"], [41.0], [0.2])
    records = {"own": own.iloc[0].to_dict(), "best": own.iloc[0].to_dict()}
    config = robot_config([])
    grid = int(np.prod([len(config["robot"][k]) for k in NetworkVariant.keys()]))
    alone = pages._robot_scope(config, own, records)
    assert alone["compared"] is False and alone["grid_variants"] == grid  # the own among them
    assert alone["explored_networks"] == "0-11" and alone["seed"] == 2009
    assert f"{grid} variants on networks 0-11" in alone["scope"] and "full scale" in alone["scope"]
    assert alone["effects_subject"] == "the config's own networks"
    assert alone["palm_compared"].startswith("the config's own networks' palm ends a median 41.0")
    assert "best variant" not in " ".join(str(v) for v in alone.values())
    two = variants_csv(["main", "robot_x"], [41.0, 12.5], [0.2, 0.9])
    records["best"] = two.iloc[1].to_dict()
    listed = pages._robot_scope(robot_config([{"target": "commands"}]), two, records)
    assert listed["compared"] is True and listed["scope"] == ""
    assert listed["tested_variants"].startswith("2 variants") and "robot.default" in listed[
        "tested_variants"]  # fmt: skip
    assert listed["effects_subject"] == "the best variant" and "12.5" in listed["palm_compared"]
    full = pages._robot_scope(robot_config([], robustness=True), two, records)
    assert full["tested_variants"].startswith("every variant of the grid")


def test_a_confirmed_animation_names_the_fresh_networks_it_films():
    """The films of a confirmed variant the default build tests only on fresh networks show
    the confirmation's first network of each mapping (12 and 18 of 12-23); listed in
    robot.default, its networks 0 and 6."""
    from icub_workflow.book import pages

    _, shown = page(confirmation_csv())
    fresh = pages._animated(robot_config([]), shown)
    assert fresh == {
        "animated_film": "network 12, the first of its confirmation's fresh networks",
        "animated_pair": "networks 12 and 18",
    }
    entry = load_config_animation()
    listed = pages._animated(robot_config([entry]), shown)
    assert listed == {"animated_film": "network 0, its first",
                      "animated_pair": "networks 0 and 6"}  # fmt: skip


def load_config_animation() -> dict:
    from conftest import load_config

    return dict(load_config()["robot"]["animation"]["variant"])
