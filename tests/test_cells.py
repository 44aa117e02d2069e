"""The four cells of object size x grip asked (analysis.cells): each replication's cell values
recomputed by hand, their intervals by scipy, and the declared estimates as contrasts of them."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from icub_affordance.analysis.cells import cell_summary, effect_shares, replication_cells


def _trials() -> pd.DataFrame:
    """Two replications, one cue and mode; each cell two trials per replication."""
    rows = []
    for replication, shift in ((1, 0.0), (2, 0.01)):
        for size, grip, congruent in (
            ("large", "power", True),
            ("large", "precision", False),
            ("small", "power", False),
            ("small", "precision", True),
        ):
            for k in range(2):
                wrong = int(not congruent and size == "small" and k == 0)
                rows.append(
                    {
                        "replication": replication,
                        "cue": "first_step",
                        "mode": "closed_loop",
                        "task": "categorisation",
                        "size": size,
                        "target_grip": grip,
                        "congruent": congruent,
                        "rmse": 0.05 + shift + 0.1 * wrong + 0.01 * k,
                        "wrong_grip": wrong,
                        "commitment": 0.8 if wrong else 0.1,
                    }
                )
    grasping = dict(rows[0], task="grasping", rmse=9.0)
    return pd.DataFrame([*rows, grasping])


def test_a_replications_cell_is_the_mean_of_its_categorisation_trials():
    cells = replication_cells(_trials()).set_index(["replication", "size", "grip_asked"])
    small_power = cells.loc[(1, "small", "power")]
    assert small_power["trials"] == 2
    assert small_power["rmse"] == pytest.approx(((0.05 + 0.1) + (0.05 + 0.01)) / 2)
    assert small_power["wrong_rate"] == 0.5
    assert small_power["wrong_commitment"] == 0.8
    assert small_power["wrong_cost"] == pytest.approx(0.15 - 0.06)
    large_power = cells.loc[(2, "large", "power")]
    assert large_power["rmse"] == pytest.approx(0.06 + 0.005)
    assert large_power["wrong_rate"] == 0 and np.isnan(large_power["wrong_commitment"])
    assert np.isnan(large_power["wrong_cost"]) and bool(large_power["congruent"])


def test_a_cells_interval_is_t_over_the_replications():
    per = replication_cells(_trials())
    summary = cell_summary(per).set_index(["size", "grip_asked", "value"])
    values = per[(per["size"] == "small") & (per["grip_asked"] == "power")]["rmse"].to_numpy()
    low, high = stats.t.interval(0.95, len(values) - 1, values.mean(), stats.sem(values))
    row = summary.loc[("small", "power", "rmse")]
    assert (row["mean"], row["ci_low"], row["ci_high"]) == pytest.approx((values.mean(), low, high))
    assert row["replications"] == 2 and not row["congruent"]
    none = summary.loc[("large", "power", "wrong_commitment")]
    assert none["replications"] == 0 and np.isnan(none["mean"])


def test_the_declared_rmse_estimates_are_contrasts_of_the_cells(built):
    """The figure's numbers above each condition are the declared tests'; its cells carry them:
    congruency is the incongruent cells' mean less the congruent cells', size small less large."""
    data = built / "data" / "claims"
    cells = pd.read_csv(data / "cells.csv")
    declared = pd.read_csv(data / "summary.csv")
    declared = declared[declared["measure"] == "rmse"].set_index(["cue", "mode", "effect"])
    rmse = cells[cells["value"] == "rmse"]
    assert len(rmse) == 4 * len(declared) // 2
    for (cue, mode), four in rmse.groupby(["cue", "mode"]):
        mean = four.set_index(["size", "grip_asked"])["mean"]
        congruent = four.set_index(["size", "grip_asked"])["congruent"]
        congruency = mean[~congruent].mean() - mean[congruent].mean()
        size = mean.xs("small").mean() - mean.xs("large").mean()
        assert congruency == pytest.approx(declared.loc[(cue, mode, "congruency"), "estimate"])
        assert size == pytest.approx(declared.loc[(cue, mode, "size"), "estimate"])


def test_an_effects_share_is_its_estimate_over_its_conditions_mean_rmse():
    summary = cell_summary(replication_cells(_trials()))
    declared = pd.DataFrame(
        [
            {
                "cue": "first_step",
                "mode": "closed_loop",
                "measure": m,
                "effect": "size",
                "estimate": 0.02,
            }
            for m in ("rmse", "rmse_correct")
        ]
    )
    shares = effect_shares(summary, declared)
    cells = summary[summary["value"] == "rmse"]["mean"]
    assert len(shares) == 1 and len(cells) == 4
    assert shares["condition_rmse"].iloc[0] == pytest.approx(cells.mean())
    assert shares["share"].iloc[0] == pytest.approx(0.02 / cells.mean())


def test_size_among_congruent_trials_is_tested_over_replications_with_holm():
    """The added test (exploration, after results): per replication the small congruent cell's
    RMSE less the large one's, a one-sample t over the replications, Holm over the conditions."""
    from statsmodels.stats.multitest import multipletests

    from icub_affordance.analysis.cells import ADDED_FAMILY, congruent_size_tests

    rows = []
    rng = np.random.default_rng(0)
    for cue in ("first_step", "all_steps"):
        for replication in range(6):
            for size, grip, congruent, rmse in (
                ("large", "power", True, 0.05 + rng.normal(0, 0.002)),
                ("small", "precision", True, 0.04 + rng.normal(0, 0.002)),
                ("large", "precision", False, 0.06),
                ("small", "power", False, 0.07),
            ):
                rows.append(
                    {
                        "replication": replication,
                        "cue": cue,
                        "mode": "teacher_forced",
                        "size": size,
                        "grip_asked": grip,
                        "congruent": congruent,
                        "rmse": rmse,
                    }
                )
    per = pd.DataFrame(rows)
    tests = congruent_size_tests(per, least=5, alpha=0.05).set_index("cue")
    p = []
    for cue in ("first_step", "all_steps"):
        mine = per[(per["cue"] == cue) & per["congruent"]].pivot(
            index="replication", columns="size", values="rmse"
        )
        d = (mine["small"] - mine["large"]).to_numpy()
        t = stats.ttest_1samp(d, 0.0)
        assert tests.loc[cue, "estimate"] == pytest.approx(d.mean())
        assert tests.loc[cue, "p"] == pytest.approx(t.pvalue)
        p.append(t.pvalue)
    holm = multipletests(p, method="holm")[1]
    assert tests.loc[["first_step", "all_steps"], "p_holm"].to_numpy() == pytest.approx(holm)
    assert set(tests["direction"]) == {-1} and set(tests["family"]) == {ADDED_FAMILY}
    few = congruent_size_tests(per[per["replication"] < 3], least=5, alpha=0.05)
    assert few["p"].isna().all() and set(few["direction"]) == {2}
