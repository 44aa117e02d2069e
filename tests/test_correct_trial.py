"""One estimator for the correct-trial RMSE (issue 47): every chapter that shows the measure (the
results, the readings, the size study, the claims' confirmation, the signatures) takes its number
from ``statistics.correct_trial_effects``. Changing the estimator's input moves each chapter's
number to the estimator's new value, and the estimator itself is recomputed by hand."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from test_contrasts import synthetic, with_errors

from icub_affordance.analysis import paper_claims as claims
from icub_affordance.analysis import reading_tests as readings
from icub_affordance.analysis import signature_tests as signatures
from icub_affordance.analysis import size_study as size_dose
from icub_affordance.analysis import trial_effects as stats

MEASURES = ["rmse", "rmse_correct", "wrong_grip"]
DECLARATION = {"cues": ["first_step"], "modes": ["closed_loop", "teacher_forced"],
               "measures": ["rmse", "rmse_correct"], "effects": ["congruency", "size"],
               "alpha": 0.05, "min_replications": 2}  # fmt: skip


def trial_table(df: pd.DataFrame) -> pd.DataFrame:
    """A run's trial table as the pipeline writes it: categorisation trials in both modes."""
    trials = df.assign(task="categorisation",
                       congruent=df["congruency"].eq("congruent").astype(str))  # fmt: skip
    return pd.concat([trials.assign(mode="closed_loop"), trials.assign(mode="teacher_forced")])


def signature_table(df: pd.DataFrame) -> pd.DataFrame:
    """The same trials as the signatures' in-view trials of one replication."""
    correct = df["final_grip"].eq(df["target_grip"])
    out = df.assign(replication=1, condition="in_view", k=signatures.IN_VIEW,
                    congruent=df["congruency"].eq("congruent"), correct=correct,
                    trial=df["sequence"])  # fmt: skip
    return out.drop(columns=["congruency"])


def every_chapter(df: pd.DataFrame) -> dict[str, float]:
    """The correct-trial congruency estimate (closed loop) as each chapter computes it."""
    trials = trial_table(df)
    measured = readings.analyse_measures(trials, MEASURES)  # a run's measures.json
    table = [{"reading": "r", "cue": "first_step", "goal_response": "fixed", "seed": 1,
              "run": "x", "dose": 0.0}]  # fmt: skip
    reading_rows = readings.replication_rows(table, [measured], MEASURES)
    claim_rows = claims.replication_estimates(table, [measured], DECLARATION)
    effects = signatures.replication_effects(signature_table(df))
    pick = lambda t: float(t[(t["measure"] == "rmse_correct") & (t["effect"] == "congruency")]  # noqa: E731
                           ["estimate"].iloc[0])  # fmt: skip
    return {
        "results": stats.analyse(trials)["closed_loop"]["correct_rt"]["congruency"]["estimate"],
        "readings": pick(reading_rows),
        "claims": float(
            claim_rows[
                (claim_rows["mode"] == "closed_loop")
                & (claim_rows["measure"] == "rmse_correct")
                & (claim_rows["effect"] == "congruency")
            ]["estimate"].iloc[0]
        ),
        "signatures": float(effects[effects["dropped"] == -1]["effect"].iloc[0]),
    }


def estimator(df: pd.DataFrame) -> float:
    correct = stats.with_outcomes(df)
    return stats.correct_trial_effects(correct)["congruency"]["estimate"]


@pytest.mark.heavy
def test_every_chapter_shows_the_one_estimators_number_and_follows_a_change_of_its_input():
    df = with_errors(synthetic(seed=11))
    before = every_chapter(df)
    assert before == pytest.approx(dict.fromkeys(before, estimator(df)), rel=1e-9)
    # one network's correct trials of one incongruent object slower by 0.04
    ok = df["final_grip"].eq(df["target_grip"])
    target = df.index[ok & df["congruency"].eq("incongruent") & df["network"].eq(
        df.loc[ok & df["congruency"].eq("incongruent"), "network"].iloc[0])]  # fmt: skip
    changed = df.copy()
    changed.loc[target, "rmse"] += 0.04
    after = every_chapter(changed)
    assert after == pytest.approx(dict.fromkeys(after, estimator(changed)), rel=1e-9)
    assert all(after[k] > before[k] + 1e-4 for k in after)


def test_the_size_chapter_reads_the_same_estimate_for_its_effect():
    """The size study's size term on correct trials is the estimator's size term."""
    df = with_errors(synthetic(seed=12))
    measured = readings.analyse_measures(trial_table(df), MEASURES)
    table = [{"dose": 0.0, "cue": "first_step", "seed": 1, "run": "x"}]
    rows = size_dose.replication_rows(table, [measured], MEASURES)
    size = float(rows[rows["measure"] == "rmse_correct"]["estimate"].iloc[0])
    expected = stats.correct_trial_effects(stats.with_outcomes(df))["size"]["estimate"]
    assert size == pytest.approx(expected, rel=1e-9)


def test_the_estimator_by_hand_networks_per_cell_and_the_leave_one_network_out_range():
    df = stats.with_outcomes(with_errors(synthetic(seed=13)))
    effects = stats.correct_trial_effects(df, left_out=True)
    term = effects["congruency"]
    # by hand, least squares with a dummy per network and the coded cell terms
    data = stats.coded(stats.network_object_means(df.dropna(subset=["rmse_correct"]),
                                                  "rmse_correct"))  # fmt: skip
    c, s, m = (data[k].to_numpy() for k in ("congruency", "size", "mapping"))
    dummies = pd.get_dummies(data["network"]).to_numpy(dtype=float)
    X = np.column_stack([dummies, c, s, c * s, c * m, s * m, c * s * m])
    beta = np.linalg.lstsq(X, data["rmse_correct"].to_numpy(), rcond=None)[0]
    assert term["estimate"] == pytest.approx(beta[dummies.shape[1]], rel=1e-9)
    # networks per mapping and cell, counted by hand
    defined = df.dropna(subset=["rmse_correct"])
    for key, n in term["cells_by_mapping"].items():
        mapping, congruency, size = key.split("_")
        cell = defined[(defined["mapping"] == mapping) & (defined["congruency"] == congruency)
                       & (defined["size"] == size)]  # fmt: skip
        assert n == cell["network"].nunique()
    # each network left out in turn: the range is over those refits
    refits = [stats.correct_trial_effects(df[df["network"] != n])["congruency"]["estimate"]
              for n in sorted(defined["network"].unique())]  # fmt: skip
    assert term["lono_low"] == pytest.approx(min(refits))
    assert term["lono_high"] == pytest.approx(max(refits))
    assert list(term["left_out"].values()) == pytest.approx(refits)


def test_without_the_refits_the_estimate_is_the_same():
    """A difference of two runs' estimates reads the estimates alone: the same numbers, no
    leave-one-network-out range."""
    df = stats.with_outcomes(with_errors(synthetic(seed=14)))
    full = stats.correct_trial_effects(df)
    quick = stats.correct_trial_effects(df, lono=False)
    for term in stats.WITHIN:
        assert quick[term]["estimate"] == full[term]["estimate"]
        assert quick[term]["se"] == full[term]["se"]
        assert np.isnan(quick[term]["lono_low"]) and np.isfinite(full[term]["lono_low"])
