"""The statistics, recomputed here by hand from trials.csv, and the evaluation's bookkeeping."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest
from conftest import REPO, load_config, load_test_config
from scipy import stats as sps

from icub_workflow.runs import plan_runs
from icub_workflow.sweep_timing import planned_jobs


@pytest.fixture(scope="module")
def outputs(built):
    trials = pd.read_csv(built / "data" / "eval" / "trials.csv", keep_default_na=False)
    anova = json.loads((built / "data" / "eval" / "anova.json").read_text())
    return trials, anova


def cat_trials(trials: pd.DataFrame, mode: str) -> pd.DataFrame:
    df = trials[(trials["task"] == "categorisation") & (trials["mode"] == mode)]
    return df.assign(
        c=(df["congruent"] == "True").astype(int), s=(df["size"] == "large").astype(int)
    )


def two_way_by_hand(df: pd.DataFrame) -> dict[str, tuple[float, float]]:
    """Balanced 2x2 between-trials ANOVA from sums of squares: effect -> (F, p)."""
    y, grand = df["rmse"].to_numpy(), df["rmse"].mean()
    cells = df.groupby(["c", "s"])["rmse"]
    n = cells.size().iloc[0]
    assert (cells.size() == n).all()  # balanced, so type I = type II
    ss_c = 2 * n * ((df.groupby("c")["rmse"].mean() - grand) ** 2).sum()
    ss_s = 2 * n * ((df.groupby("s")["rmse"].mean() - grand) ** 2).sum()
    ss_cells = n * ((cells.mean() - grand) ** 2).sum()
    ss_int = ss_cells - ss_c - ss_s
    ss_err = ((y - df.groupby(["c", "s"])["rmse"].transform("mean").to_numpy()) ** 2).sum()
    df_err = len(y) - 4
    out = {}
    for name, ss in (("congruency", ss_c), ("size", ss_s), ("interaction", ss_int)):
        f = ss / (ss_err / df_err)
        out[name] = (f, sps.f.sf(f, 1, df_err))
    return out


def repeated_by_hand(df: pd.DataFrame) -> dict[str, tuple[float, float]]:
    """2x2 within-subject ANOVA (subject = network) from the per-network cell means."""
    m = df.groupby(["network", "c", "s"])["rmse"].mean().unstack(["c", "s"])
    k = len(m)
    a = m[(1, 1)] + m[(1, 0)] - m[(0, 1)] - m[(0, 0)]  # congruency contrast per network
    b = m[(1, 1)] + m[(0, 1)] - m[(1, 0)] - m[(0, 0)]  # size contrast
    ab = m[(1, 1)] - m[(1, 0)] - m[(0, 1)] + m[(0, 0)]  # interaction contrast
    out = {}
    for name, contrast in (("congruency", a), ("size", b), ("interaction", ab)):
        t = contrast.mean() / (contrast.std(ddof=1) / np.sqrt(k))  # F(1, k-1) = t^2
        out[name] = (t**2, sps.f.sf(t**2, 1, k - 1))
    return out


@pytest.mark.parametrize("mode", ["closed_loop", "teacher_forced"])
def test_anova_json_equals_an_independent_recomputation(outputs, mode):
    trials, anova = outputs
    df = cat_trials(trials, mode)
    for analysis, by_hand in (
        ("two_way", two_way_by_hand),
        ("repeated_measures", repeated_by_hand),
    ):
        expected = by_hand(df)
        for effect, (f, p) in expected.items():
            got = anova[mode][analysis][effect]
            assert got["F"] == pytest.approx(f, rel=1e-6), (analysis, effect)
            assert got["p"] == pytest.approx(p, rel=1e-6, abs=1e-300), (analysis, effect)
            assert got["eta_p2"] == pytest.approx(
                f * got["df1"] / (f * got["df1"] + got["df2"]), rel=1e-9
            )


def test_trials_cover_every_network_task_object_sequence_and_mode(outputs):
    trials, _ = outputs
    n_net = trials["network"].nunique()
    assert len(trials) == n_net * 2 * 2 * 4 * 5  # modes x tasks x objects x sequences
    cat = trials[trials["task"] == "categorisation"]
    # congruent exactly when the required grip is the object's natural grip
    assert ((cat["congruent"] == "True") == (cat["target_grip"] == cat["natural_grip"])).all()
    assert set(trials[trials["held_out"]]["sequence"]) == {4}
    assert ((trials["rmse"] > 0) & (trials["rmse"] < 1)).all()
    steps = [c for c in trials.columns if c.startswith("rmse_step")]
    assert len(steps) == 9
    # the trial RMSE is the root of the mean of the per-step mean squares
    recomputed = np.sqrt((trials[steps] ** 2).mean(axis=1))
    np.testing.assert_allclose(trials["rmse"], recomputed, rtol=1e-4)


def test_mapping_a_is_the_first_half_of_the_networks(outputs):
    trials, _ = outputs
    n = trials["network"].nunique()
    mapping = trials.groupby("network")["mapping"].first()
    assert (mapping[: n // 2] == "A").all() and (mapping[n // 2 :] == "B").all()


@pytest.mark.parametrize(
    "config, args",
    [
        (None, ("--quiet", "rules")),  # the default config
        ({"robustness": False}, ()),  # the test config
        ({"robustness": True}, ("--config", "robustness=True")),
    ],
    ids=["default", "test", "test-robustness"],
)
def test_the_dag_makes_the_jobs_the_run_plan_predicts(dry_run, config, args):
    """Snakemake's DAG of the default target has, for each rule that serves runs, the jobs the
    run plan counts (RunPlan.job_counts, whose numbers tests/test_run_plan.py checks without
    Snakemake), and one job of every other rule: the plan is what the rules build."""
    if config is None:
        result = dry_run(*args, config=REPO / "config" / "config.yaml")
        settings = load_config()
    else:
        result = dry_run(*args)
        settings = load_test_config() | config
    assert result.returncode == 0, result.stderr[-3000:]
    dag = planned_jobs(result.stdout)
    predicted = plan_runs(settings).job_counts()
    assert set(predicted) <= set(dag), set(predicted) - set(dag)
    assert {rule: dag[rule] for rule in predicted} == predicted
    assert {rule: n for rule, n in dag.items() if rule not in predicted} == {
        rule: 1 for rule in dag if rule not in predicted
    }
