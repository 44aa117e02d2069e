"""The readings of the paper (book/notes.md, "The maps", "The network and its training", "Testing
and statistics"): runs derived from the config, the summary over replications
(data/readings/summary.csv) with its tests and Holm's adjustment, the tests of the differences
between readings (data/readings/differences.csv), and the sentences generated from them, each
changed when the statistic it rests on is."""

from __future__ import annotations

import functools
import io

import numpy as np
import pandas as pd
import pytest
from conftest import REPO, load_config, run_snakemake, scratch_workflow
from scipy import stats as sps

from icub_affordance.analysis.reading_tests import (
    BY_EXCESS,
    DIFFERENCE_COLUMNS,
    FAMILY_DIFFERENCES,
    FAMILY_EQUIVALENCE,
    FAMILY_SUMMARY,
    NOT_TESTED,
    NULL_CONTROL,
    SUMMARY_COLUMNS,
    analyse_measures,
    difference_replications,
    difference_verdict,
    differences,
    direction,
    replication_rows,
    summary,
)
from icub_affordance.analysis.statistics import equivalence, holm
from icub_affordance.analysis.trial_effects import (
    categorisation_trials,
    difference_tests,
    network_contrasts,
    with_outcomes,
    within_network_fit,
)
from icub_affordance.outcome import Outcome
from icub_workflow.book import text
from icub_workflow.book.pages import readings as readings_page
from icub_workflow.book.pages import traced
from icub_workflow.runs import plan_runs

READINGS = ("first_step+fixed", "first_step+grows", "all_steps+fixed", "all_steps+grows")


def replications(estimates: dict, measure: str = "rmse", effect: str = "congruency"):
    """Rows as the rule `readings` writes them: (estimate, p) per replication of each reading."""
    rows = []
    for reading, values in estimates.items():
        cue, goal = reading.split("+")
        for seed, (estimate, p) in enumerate(values):
            rows.append(
                {
                    "reading": reading,
                    "cue": cue,
                    "goal_response": goal,
                    "seed": seed,
                    "run": f"{reading}_{seed}",
                    "measure": measure,
                    "effect": effect,
                    "estimate": estimate,
                    "se": 0.005,
                    "df": 10.0,
                    "ci_low": estimate - 0.01,
                    "ci_high": estimate + 0.01,
                    "p": p,
                }
            )
    return pd.DataFrame(rows)


def test_summary_tests_each_reading_and_adjusts_over_the_family():
    reps = [(0.04, 0.001), (0.03, 0.01), (0.01, 0.2), (-0.02, 0.04)]
    table = summary(
        pd.concat(
            [
                replications({"first_step+fixed": reps, "all_steps+fixed": [(0.02, 0.03)]}),
                replications(
                    {"all_steps+fixed": [(0.5, 0.01)]}, measure="rmse_per_grip_distance_null"
                ),
            ]
        ),
        least=2,
    )
    assert list(table.columns) == SUMMARY_COLUMNS
    many, one, null = table.iloc[0], table.iloc[1], table.iloc[2]
    assert many["replications"] == 4 and many["n_paper"] == 2 and many["n_reversed"] == 1
    assert many["diff"] == pytest.approx(0.015)
    # several replications: a t-test of their estimates, df = replications - 1
    ref = sps.ttest_1samp([e for e, _ in reps], 0.0)
    assert (many["p"], many["df"]) == pytest.approx((ref.pvalue, 3))
    assert many["ci_low"] < 0.015 < many["ci_high"]
    # one replication: its own test
    assert (one["diff"], one["ci_low"], one["ci_high"]) == pytest.approx((0.02, 0.01, 0.03))
    assert (one["p"], one["df"]) == (0.03, 10)
    # Holm over the two hypotheses; the null control is not one
    assert [many["p_holm"], one["p_holm"]] == pytest.approx(holm([many["p"], 0.03]))
    assert np.isnan(null["p_holm"])
    # verdicts on the adjusted p: 0.03 alone would pass, 0.06 after Holm does not
    assert one["p_holm"] == pytest.approx(0.06) and direction(one) == Outcome.NONE
    assert direction(null) == Outcome.PAPER  # a control's verdict is on its raw p
    assert direction(pd.Series({**one, "p_holm": 0.049})) == Outcome.PAPER
    assert direction(pd.Series({**one, "p_holm": 0.049, "diff": -0.02})) == Outcome.AGAINST


# -- synthetic runs: networks whose per-network effects are known -----------------------------

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


def run_trials(
    congruency, size, networks: int = 8, seed: int = 0, sd: float = 0.002, wrong=frozenset()
):
    """A run's categorisation trials (closed loop, 2 identical sequences): each network's value
    0.1 + its congruency effect if incongruent (coded +-0.5) + its size effect if small, with
    network noise; ``congruency``/``size`` per network or a constant. Every measure the same.
    ``wrong_grip`` is 1 for the (network, object) pairs in ``wrong`` (their RMSE 0.05 higher),
    else 0."""
    rng = np.random.default_rng(seed)
    cong = np.broadcast_to(np.asarray(congruency, dtype=float), (networks,))
    sz = np.broadcast_to(np.asarray(size, dtype=float), (networks,))
    rows = []
    for net in range(networks):
        mapping = "A" if net < networks // 2 else "B"
        for obj, (osize, category) in OBJECTS.items():
            congruent = MAPPING[mapping][category] == NATURAL[osize]
            value = (
                0.1
                + cong[net] * (-0.5 if congruent else 0.5)
                + sz[net] * (0.5 if osize == "small" else -0.5)
                + rng.normal(0, sd)
            )
            is_wrong = (net, obj) in wrong
            value += 0.05 * is_wrong
            for seq in range(2):
                rows.append(
                    {
                        "network": net,
                        "mapping": mapping,
                        "mode": "closed_loop",
                        "task": "categorisation",
                        "object": obj,
                        "size": osize,
                        "congruent": str(congruent),
                        "sequence": seq,
                        "wrong_grip": int(is_wrong),
                    }
                    | {m: value for m in ("rmse", "rmse_per_grip_distance")}
                    | {"rmse_per_grip_distance_null": 0.5 + rng.normal(0, sd)}
                )
    closed = pd.DataFrame(rows)
    return pd.concat([closed, closed.assign(mode="teacher_forced")], ignore_index=True)


def readings_table(seeds=(2009,)):
    return [
        {
            "reading": r,
            "cue": r.split("+")[0],
            "goal_response": r.split("+")[1],
            "seed": s,
            "run": f"{r}_{s}",
        }  # fmt: skip
        for r in READINGS
        for s in seeds
    ]


def test_differences_are_paired_by_network():
    rng = np.random.default_rng(1)
    base = rng.normal(0.03, 0.01, 8)  # each network's own congruency effect
    effects = {  # reading: (congruency per network, size)
        "first_step+fixed": (base + 0.02, 0.0),
        "first_step+grows": (base + 0.02, 0.0),
        "all_steps+fixed": (base, 0.0),
        "all_steps+grows": (base, 0.01),
    }
    table = readings_table()
    trials = {
        row["run"]: run_trials(*effects[row["reading"]], seed=i) for i, row in enumerate(table)
    }
    reps = difference_replications(table, trials, ["rmse"])
    assert set(reps["comparison"]) == {"cue_timing", "goal_response"}
    cue = reps[(reps["comparison"] == "cue_timing") & (reps["at"] == "fixed")]
    cong = cue[cue["effect"] == "congruency"].iloc[0]
    assert (cong["a"], cong["b"]) == ("first_step+fixed", "all_steps+fixed")
    expected = difference_tests(
        trials["first_step+fixed_2009"][lambda d: d["task"] == "categorisation"].assign(
            congruency=lambda d: np.where(d["congruent"] == "True", "congruent", "incongruent")
        ),
        trials["all_steps+fixed_2009"][lambda d: d["task"] == "categorisation"].assign(
            congruency=lambda d: np.where(d["congruent"] == "True", "congruent", "incongruent")
        ),
        "rmse",
    )["congruency"]
    assert cong["estimate"] == pytest.approx(expected["estimate"])
    assert cong["estimate"] == pytest.approx(0.02, abs=0.003)
    # paired: the networks' own effects (sd 0.01) cancel, so the test is sharp
    assert cong["p"] < 1e-4 and cong["df"] == 6
    out = differences(reps, {"rmse": 0.01}, least=2)
    assert list(out.columns) == DIFFERENCE_COLUMNS
    assert out["p_holm"].to_numpy() == pytest.approx(holm(out["p"]))
    goal = out[out["comparison"] == "goal_response"].set_index(["at", "effect"])
    # the Goal response: no difference under first_step (equivalent within 0.01), a size
    # difference of 0.01 under all_steps (not equivalent)
    assert goal.loc[("first_step", "congruency"), "p_equivalence_holm"] < 0.05
    assert difference_verdict(goal.loc[("first_step", "congruency")]) == "equivalent"
    assert goal.loc[("all_steps", "size"), "diff"] == pytest.approx(0.01, abs=0.003)
    assert difference_verdict(goal.loc[("all_steps", "size")]) == "a > b"
    assert out[out["comparison"] == "cue_timing"]["p_equivalence"].isna().all()


def test_differences_over_replications_test_the_replications_differences():
    table = readings_table(seeds=(1, 2, 3))
    diffs = {1: 0.01, 2: 0.02, 3: 0.04}
    trials = {}
    for i, row in enumerate(table):
        shift = diffs[row["seed"]] if row["cue"] == "first_step" else 0.0
        trials[row["run"]] = run_trials(0.03 + shift, 0.0, seed=i)
    out = differences(difference_replications(table, trials, ["rmse"]), {"rmse": 0.01}, least=2)
    row = out[(out["comparison"] == "cue_timing") & (out["at"] == "fixed")]
    row = row[row["effect"] == "congruency"].iloc[0]
    assert row["replications"] == 3 and row["df"] == 2
    assert row["diff"] == pytest.approx(np.mean(list(diffs.values())), abs=0.003)


def test_a_missing_margin_is_a_clear_error():
    table = readings_table()
    trials = {row["run"]: run_trials(0.03, 0.0, seed=i) for i, row in enumerate(table)}
    with pytest.raises(ValueError, match="equivalence_margin has no margin for 'rmse'"):
        differences(difference_replications(table, trials, ["rmse"]), {}, least=2)


# -- the correct-trial RMSE: a measure a network can lack in a cell ---------------------------

#: Network 0 (mapping A) always takes the wrong grip on the small ball, network 5 (B) on the big
#: cube: each has no correct trial there.
WRONG = frozenset({(0, "small_ball"), (5, "big_cube")})


def closed_loop(trials: pd.DataFrame) -> pd.DataFrame:
    return categorisation_trials(with_outcomes(trials), "closed_loop")


def test_the_correct_trial_rmse_keeps_a_network_that_lacks_a_cell():
    trials = run_trials(0.03, 0.01, wrong=WRONG)
    out = analyse_measures(trials, ["rmse", "rmse_correct"])["closed_loop"]["rmse_correct"]
    df = closed_loop(trials)
    fit = within_network_fit(df, "rmse_correct")
    for effect in ("congruency", "size"):
        for stat in ("estimate", "se", "df", "p"):
            assert out["contrasts"][effect][stat] == pytest.approx(fit[effect][stat])
    # every network informs the test; the per-network contrasts would have dropped two
    assert out["contrasts"]["size"]["networks"] == 8
    assert network_contrasts(df, "rmse_correct")["size"]["networks"] == 6
    assert out["contrasts"]["size"]["cells"] == fit["size"]["cells"]
    assert sorted(out["contrasts"]["size"]["cells"].values()) == [7, 7, 8, 8]
    # the wrong trials are out of the means: a mean over the defined networks, counted as such
    small_ball = df[(df["mapping"] == "A") & (df["object"] == "small_ball")]
    defined = small_ball.dropna(subset=["rmse_correct"]).groupby("network")["rmse_correct"].mean()
    entry = out["object_means"]["A_small_ball"]
    assert entry["n_networks"] == 3 == len(defined)
    assert entry["mean"] == pytest.approx(defined.mean())
    assert entry["mean"] < small_ball["rmse"].max()  # network 0's wrong trials (+0.05) not in it
    cell = f"{small_ball['congruency'].iloc[0]}_small"
    per_net = df[(df["congruency"] == small_ball["congruency"].iloc[0]) & (df["size"] == "small")]
    expected = per_net.groupby("network")["rmse_correct"].mean().dropna().mean()
    assert out["means"][cell] == pytest.approx(expected)


def test_the_route_follows_the_declaration_not_the_data():
    """Without a single wrong trial the correct-trial RMSE still goes through the fit that keeps
    every network (its estimates then those of the per-network contrasts), and the RMSE through
    the per-network contrasts."""
    trials = run_trials(0.03, 0.01)
    out = analyse_measures(trials, ["rmse", "rmse_correct"])["closed_loop"]
    assert "cells" in out["rmse_correct"]["contrasts"]["size"]
    assert "mapping" not in out["rmse_correct"]["contrasts"]  # the network intercepts absorb it
    assert "mapping" in out["rmse"]["contrasts"] and "cells" not in out["rmse"]["contrasts"]["size"]
    for effect in ("congruency", "size"):
        assert out["rmse_correct"]["contrasts"][effect]["estimate"] == pytest.approx(
            out["rmse"]["contrasts"][effect]["estimate"]
        )


def test_the_correct_trial_rmses_differences_are_unpaired_with_welch_df():
    table = readings_table()
    wrong = {"first_step+fixed": WRONG, "all_steps+fixed": frozenset({(2, "big_ball")})}
    trials = {
        row["run"]: run_trials(0.03 + 0.02 * (row["cue"] == "first_step"), 0.0, seed=i,
                               wrong=wrong.get(row["reading"], frozenset()))
        for i, row in enumerate(table)
    }  # fmt: skip
    reps = difference_replications(table, trials, ["rmse_correct"])
    row = reps[(reps["comparison"] == "cue_timing") & (reps["at"] == "fixed")]
    row = row[row["effect"] == "congruency"].iloc[0]
    a = within_network_fit(closed_loop(trials["first_step+fixed_2009"]), "rmse_correct")
    b = within_network_fit(closed_loop(trials["all_steps+fixed_2009"]), "rmse_correct")
    a, b = a["congruency"], b["congruency"]
    se = np.sqrt(a["se"] ** 2 + b["se"] ** 2)
    welch = se**4 / (a["se"] ** 4 / a["df"] + b["se"] ** 4 / b["df"])
    assert row["estimate"] == pytest.approx(a["estimate"] - b["estimate"])
    assert row["estimate"] == pytest.approx(0.02, abs=0.003)
    assert (row["se"], row["df"]) == pytest.approx((se, welch))
    t = row["estimate"] / se
    assert row["p"] == pytest.approx(2 * sps.t.sf(abs(t), welch))
    assert row["networks"] == 8


def test_a_difference_of_a_term_one_run_does_not_identify_is_undefined():
    """Every network wrong on every incongruent object in one reading: its correct-trial RMSE
    identifies neither effect (congruency needs the incongruent cells, size averaged over the
    congruencies too), so the differences are undefined, not made up."""
    table = readings_table()
    incongruent = {
        (net, obj) for net in range(8) for obj in OBJECTS
        if (obj in ("small_ball", "big_cube")) == (net < 4)
    }  # fmt: skip
    trials = {
        row["run"]: run_trials(0.03, 0.01, seed=i,
                               wrong=incongruent if row["reading"] == "first_step+fixed" else ())
        for i, row in enumerate(table)
    }  # fmt: skip
    first = closed_loop(trials["first_step+fixed_2009"])
    assert first.loc[first["congruency"] == "incongruent", "rmse_correct"].isna().all()
    reps = difference_replications(table, trials, ["rmse_correct"])
    row = reps[(reps["comparison"] == "cue_timing") & (reps["at"] == "fixed")].set_index("effect")
    for effect in ("congruency", "size"):
        assert row.loc[effect, ["estimate", "se", "df", "p"]].isna().all(), effect
    other = reps[(reps["comparison"] == "cue_timing") & (reps["at"] == "grows")]
    assert other["p"].notna().all()  # the readings that identify them are tested


@pytest.mark.heavy
def test_identical_cells_are_not_tested():
    """A measure constant on every network in both readings (no wrong grip anywhere): its
    differences have no spread, so no test, no TOST and no place in any Holm family."""
    table = readings_table()
    trials = {row["run"]: run_trials(0.03, 0.0, seed=i) for i, row in enumerate(table)}
    margins = {"rmse": 0.01, "wrong_grip": 0.10}
    out = differences(
        difference_replications(table, trials, ["rmse", "wrong_grip"]), margins, least=2
    )
    assert list(out.columns) == DIFFERENCE_COLUMNS
    same = out[out["measure"] == "wrong_grip"]
    assert same["identical"].all() and not out[out["measure"] == "rmse"]["identical"].any()
    assert (same["diff"] == 0).all()
    for column in ("p", "p_holm", "p_equivalence", "p_equivalence_holm"):
        assert same[column].isna().all(), column
    assert (same["family"] == NOT_TESTED).all() and (same["family_equivalence"] == "").all()
    assert same.apply(difference_verdict, axis=1).eq("identical").all()
    # the other rows are adjusted among themselves alone
    tested = out[~out["identical"]]
    assert tested["p_holm"].to_numpy() == pytest.approx(holm(tested["p"]))
    goal = tested[tested["comparison"] == "goal_response"]
    assert goal["p_equivalence_holm"].to_numpy() == pytest.approx(holm(goal["p_equivalence"]))
    # as the book reads it back
    back = pd.read_csv(io.StringIO(out.to_csv(index=False)))
    verdicts = back.apply(difference_verdict, axis=1)
    assert (verdicts[back["measure"] == "wrong_grip"] == "identical").all()
    assert not (verdicts[back["measure"] == "rmse"] == "identical").any()


@pytest.mark.parametrize("estimate", [0.0, 0.05, 0.5])
def test_an_equivalence_test_without_spread_has_no_p(estimate):
    tost = equivalence({"estimate": estimate, "se": 0.0, "df": 6.0}, 0.1)
    assert np.isnan(tost["p"]) and np.isnan(tost["p_lower"]) and np.isnan(tost["p_upper"])
    assert equivalence({"estimate": estimate, "se": 0.01, "df": 6.0}, 0.1)["p"] >= 0


# -- the Holm families the tables name ----------------------------------------------------------


def holm_within_families(table: pd.DataFrame, family="family", p="p", p_holm="p_holm") -> set:
    """Holm recomputed (statsmodels) over the rows of each named family of a table as its CSV
    reads back, against the table's own adjusted p; the families seen. The rows in no family (a
    null control's, a measure's tested by its excess, an untested difference's) have no
    adjusted p."""
    from statsmodels.stats.multitest import multipletests

    back = pd.read_csv(io.StringIO(table.to_csv(index=False)))
    back[family] = back[family].fillna("")
    for name, rows in back.groupby(family):
        tested = rows[p].notna()
        if name in (NULL_CONTROL, BY_EXCESS, NOT_TESTED, ""):
            assert rows[p_holm].isna().all(), name
            continue
        expected = multipletests(rows.loc[tested, p].to_numpy(dtype=float), method="holm")[1]
        assert rows.loc[tested, p_holm].to_numpy() == pytest.approx(expected), name
        assert rows.loc[~tested, p_holm].isna().all(), name
    return set(back[family])


def family_tables():
    """The summary and differences of three replications of every reading, on the RMSE, the
    correct-trial RMSE, the wrong-grip rate and RMSE per grip distance with its null control and
    its excess over it (fresh copies each call; the tables are computed once)."""
    summ, diffs = _family_tables()
    return summ.copy(), diffs.copy()


@functools.cache
def _family_tables():
    table = readings_table(seeds=(1, 2, 3))
    trials = {
        row["run"]: run_trials(0.02 + 0.01 * row["seed"], 0.005 * (row["cue"] == "all_steps"),
                               seed=i, wrong=WRONG if row["goal_response"] == "grows" else ())
        for i, row in enumerate(table)
    }  # fmt: skip
    measures = ["rmse", "rmse_correct", "wrong_grip", "rmse_per_grip_distance"]
    analyses = [analyse_measures(trials[row["run"]], measures) for row in table]
    summ = summary(replication_rows(table, analyses, measures), least=2)
    margins = load_config()["readings"]["equivalence_margin"]
    diffs = differences(difference_replications(table, trials, measures), margins, least=2)
    return summ, diffs


@pytest.mark.heavy
def test_the_summary_names_its_holm_family():
    """The null control and the measure tested by its excess are shown (with their raw p), in
    no family; the excess is the hypothesis, in the family with the other measures."""
    summ, _ = family_tables()
    assert holm_within_families(summ) == {FAMILY_SUMMARY, NULL_CONTROL, BY_EXCESS}
    null = summ["measure"] == "rmse_per_grip_distance_null"
    raw = summ["measure"] == "rmse_per_grip_distance"
    assert (summ.loc[null, "family"] == NULL_CONTROL).all()
    assert (summ.loc[raw, "family"] == BY_EXCESS).all()
    assert summ.loc[null | raw, "p_holm"].isna().all()
    assert summ.loc[null | raw, "p"].notna().all()  # shown, with their raw p
    assert (summ.loc[~null & ~raw, "family"] == FAMILY_SUMMARY).all()
    assert set(summ["measure"]) >= {"rmse_correct", "rmse_per_grip_distance_excess"}
    excess = summ[summ["measure"] == "rmse_per_grip_distance_excess"]
    assert len(excess) == len(summ[raw]) and excess["p_holm"].notna().all()


@pytest.mark.heavy
def test_the_differences_name_their_holm_families():
    _, diffs = family_tables()
    families = holm_within_families(diffs)
    assert families >= {FAMILY_DIFFERENCES, NULL_CONTROL, BY_EXCESS}
    assert families <= {FAMILY_DIFFERENCES, NULL_CONTROL, BY_EXCESS, NOT_TESTED}
    raw = diffs["measure"] == "rmse_per_grip_distance"
    assert (diffs.loc[raw, "family"] == BY_EXCESS).all() and diffs.loc[raw, "p_holm"].isna().all()
    excess = diffs["measure"] == "rmse_per_grip_distance_excess"
    assert excess.sum() == raw.sum()
    assert diffs.loc[excess, "family"].isin([FAMILY_DIFFERENCES, NOT_TESTED]).all()
    equivalence_families = holm_within_families(
        diffs, "family_equivalence", "p_equivalence", "p_equivalence_holm"
    )
    assert equivalence_families == {FAMILY_EQUIVALENCE, ""}
    tost = diffs[diffs["family_equivalence"] == FAMILY_EQUIVALENCE]
    assert (tost["comparison"] == "goal_response").all() and tost["p_equivalence"].notna().all()
    assert not tost["measure"].str.endswith("_null").any()
    # the excess is tested for equivalence within its measure's margin, the raw measure is not
    assert "rmse_per_grip_distance" not in set(tost["measure"])
    margins = load_config()["readings"]["equivalence_margin"]
    excess = tost[tost["measure"] == "rmse_per_grip_distance_excess"]
    assert len(excess) and (excess["margin"] == margins["rmse_per_grip_distance"]).all()


def test_the_config_declares_the_correct_trial_rmse_with_its_margin():
    readings = load_config()["readings"]
    measures = readings["measures"]
    assert measures[measures.index("rmse") + 1] == "rmse_correct"
    assert readings["equivalence_margin"]["rmse_correct"] == 0.01


# -- the sentences: each changes when the statistic it rests on does --------------------------


def built_tables(cong_shift=0.02, grows_size=0.01, margin=0.01, seed=0):
    """The readings' summary and differences of made-up trials (fresh copies each call: the
    tests change them; the tables themselves are computed once per setting)."""
    summ, diffs = _built_tables(cong_shift, grows_size, margin, seed)
    return summ.copy(), diffs.copy()


@functools.cache
def _built_tables(cong_shift, grows_size, margin, seed):
    rng = np.random.default_rng(seed)
    base = rng.normal(0.03, 0.01, 8)
    effects = {
        "first_step+fixed": (base + cong_shift, 0.0),
        "first_step+grows": (base + cong_shift, 0.0),
        "all_steps+fixed": (base, 0.0),
        "all_steps+grows": (base, grows_size),
    }
    table = readings_table()
    trials = {
        row["run"]: run_trials(*effects[row["reading"]], seed=i) for i, row in enumerate(table)
    }
    measures = ["rmse", "rmse_per_grip_distance"]
    analyses = [analyse_measures(trials[row["run"]], measures) for row in table]
    summ = summary(replication_rows(table, analyses, measures), least=2)
    margins = {"rmse": margin, "rmse_per_grip_distance": margin}
    diffs = differences(difference_replications(table, trials, measures), margins, least=2)
    return summ, diffs


def page(tmp_path, summ, diffs, with_tables=False):
    summ.to_csv(tmp_path / "summary.csv", index=False)
    diffs.to_csv(tmp_path / "differences.csv", index=False)
    # the confirmatory family's test of the same replications (data/claims/summary.csv)
    pd.DataFrame([{"cue": "first_step", "mode": "closed_loop", "measure": "rmse",
                   "effect": "congruency", "direction": "paper", "p_holm": 0.045},
                  {"cue": "first_step", "mode": "teacher_forced", "measure": "rmse",
                   "effect": "size", "direction": "none", "p_holm": 0.3}]).to_csv(
        tmp_path / "claims.csv", index=False)  # fmt: skip
    inputs = {
        "readings_summary.csv": str(tmp_path / "summary.csv"),
        "readings_differences.csv": str(tmp_path / "differences.csv"),
        "claims_summary.csv": str(tmp_path / "claims.csv"),
    }
    config = {
        "soms": {"goal_response": "fixed"},
        "readings": {
            "measures": ["rmse", "rmse_per_grip_distance"],
            "equivalence_margin": {"rmse": 0.01, "rmse_per_grip_distance": 0.01},
            "margin_declared": {
                "rmse": {"commit": "3e997e7", "results_before": True},
                "rmse_per_grip_distance": {"commit": "3e997e7", "results_before": False},
            },
        },
    }
    values, tables = readings_page(inputs, config)
    pages = traced({"readings": values})
    return (pages, tables) if with_tables else pages


@pytest.mark.heavy
def test_every_readings_claim_rests_on_values_the_page_stores(tmp_path):
    summ, diffs = built_tables()
    # a cell where every network scored the same has no test: its claim rests on its difference
    summ.loc[0, ["diff", "ci_low", "ci_high", "p", "p_holm"]] = [0.0, 0.0, 0.0, np.nan, np.nan]
    diffs.loc[0, ["p", "p_holm"]] = np.nan
    pages = page(tmp_path, summ, diffs)
    claims = pages["claims"]["readings"]
    assert set(claims) >= {
        "both_rmse",
        "paper_rmse_congruency",
        "paper_rmse_size",
        "both_rmse_per_grip_distance_excess",
        "cue_changes",
        "cue_larger",
        "goal_changes",
        "goal_n_equivalent",
        "goal_n_identical",
    }
    for entries in claims.values():
        for entry in entries:
            assert isinstance(pages["readings"][entry.split(".", 1)[1]], float), entry
    assert pages["readings"][text.stat_key(summ.iloc[0], "p_holm")] is None


def verdicts(table: pd.DataFrame) -> pd.Series:
    """A readings table's verdict words by measure, effect and reading (or comparison), as the
    page's matrices show them beside each estimate."""
    return table.set_index(["label", "effect", "named"])["verdict"]


def matrix_page(tmp_path, summ):
    _, diffs = built_tables()
    pages, tables = page(tmp_path, summ, diffs, with_tables=True)
    return pages["readings"], verdicts(tables["readings_summary"])


@pytest.mark.heavy
def test_the_matrix_verdicts_and_phrases_follow_holm_p(tmp_path):
    summ, _ = built_tables()
    key = (
        (summ["reading"] == "all_steps+fixed")
        & (summ["measure"] == "rmse")
        & (summ["effect"] == "congruency")
    )
    others = (summ["measure"] == "rmse") & ~key  # not shown: the phrase lists this one alone
    holm_p = np.where(key, 0.01, np.where(others, 0.5, summ["p_holm"]))
    shown = summ.assign(p_holm=holm_p, diff=summ["diff"].abs())
    cell = ("RMSE", "congruency", "every · fixed")
    for table, word, listed in (
        (shown, "confirmed", True),
        (shown.assign(p_holm=np.where(key, 0.2, shown["p_holm"])), "not shown", False),
        (shown.assign(diff=np.where(key, -shown["diff"], shown["diff"])), "reversed", False),
    ):
        values, matrix = matrix_page(tmp_path, table)
        assert matrix.loc[cell] == word
        assert ("every · fixed" in values["paper_rmse_congruency"]) is listed
    # the raw p is not the verdict's: a raw p below 0.05 with Holm's above is "not shown"
    raw = shown.assign(
        p=np.where(key, 0.01, shown["p"]), p_holm=np.where(key, 0.2, shown["p_holm"])
    )
    assert matrix_page(tmp_path, raw)[1].loc[cell] == "not shown"


def test_both_effects_need_both_verdicts_after_holm(tmp_path):
    summ, _ = built_tables()
    rmse, first = summ["measure"] == "rmse", summ["reading"] == "first_step+fixed"
    both = summ.assign(p_holm=np.where(rmse & first, 0.001, 0.5), diff=summ["diff"].abs() + 0.01)
    assert matrix_page(tmp_path, both)[0]["both_rmse"] == "first · fixed"
    size = rmse & first & (summ["effect"] == "size")
    one = both.assign(p_holm=np.where(size, 0.06, both["p_holm"]))
    assert matrix_page(tmp_path, one)[0]["both_rmse"] == "no reading"
    every = both.assign(p_holm=np.where(rmse, 0.001, 0.5))
    assert matrix_page(tmp_path, every)[0]["both_rmse"] == "every reading"


def test_grip_distance_verdicts_read_its_excess_over_the_null_control(tmp_path):
    summ, diffs = built_tables()
    # the raw measure and its null control significant on their raw p: still no verdict
    shown = summ["measure"].isin(["rmse_per_grip_distance", "rmse_per_grip_distance_null"])
    summ = summ.assign(p=np.where(shown, 1e-6, summ["p"]))
    pages, tables = page(tmp_path, summ, diffs, with_tables=True)
    matrix = verdicts(tables["readings_summary"])
    for measure in ("RMSE per grip distance", "null control"):
        assert set(matrix.loc[measure]) == {""}  # a number alone
    assert "" not in set(matrix.loc["excess over null"])
    assert "paper_rmse_per_grip_distance_congruency" not in pages["readings"]
    assert "paper_rmse_per_grip_distance_excess_congruency" in pages["readings"]
    numbers = tables["readings_summary"].set_index("label")
    assert pages["readings"]["family"] == FAMILY_SUMMARY
    assert set(numbers.loc["null control", "holm"]) == {"not a hypothesis"}
    assert set(numbers.loc["RMSE per grip distance", "holm"]) == {"by excess"}


def test_cue_phrases_only_from_the_test_of_the_difference(tmp_path):
    summ, diffs = built_tables(cong_shift=0.02)
    pages, tables = page(tmp_path, summ, diffs, with_tables=True)
    values = pages["readings"]
    assert values["cue_larger"].startswith("congruency on RMSE")
    assert values["cue_changes"].startswith(values["cue_larger"])
    assert (
        "readings.cue_timing_fixed_rmse_congruency_p_holm"
        in pages["claims"]["readings"]["cue_larger"]
    )
    assert verdicts(tables["readings_differences"]).loc[("RMSE", "congruency", "cue · fixed")] == (
        "larger"
    )
    cue = diffs["comparison"] == "cue_timing"
    faint = diffs.assign(p_holm=np.where(cue, np.maximum(diffs["p_holm"], 0.06), diffs["p_holm"]))
    values = page(tmp_path, summ, faint)["readings"]
    assert values["cue_changes"] == values["cue_larger"] == "no effect"
    # one Goal response only: the phrase says where
    fixed = cue & (diffs["at"] == "fixed")
    one = faint.assign(p_holm=np.where(fixed, 0.001, faint["p_holm"]))
    assert "(fixed only)" in page(tmp_path, summ, one)["readings"]["cue_changes"]


def test_goal_phrases_say_no_difference_only_from_equivalence(tmp_path):
    summ, diffs = built_tables(grows_size=0.01)
    values = page(tmp_path, summ, diffs)["readings"]
    assert "size on RMSE" in values["goal_changes"]
    goal = diffs["comparison"] == "goal_response"
    everything = diffs.assign(
        p_holm=np.where(goal, 0.5, diffs["p_holm"]),
        p_equivalence_holm=np.where(goal, 0.001, diffs["p_equivalence_holm"]),
    )
    values = page(tmp_path, summ, everything)["readings"]
    assert values["goal_changes"] == "no effect"
    # the RMSE's margin was set after its results were read (page's margin_declared): its four
    # equivalences are said so and never counted with the others
    assert int(values["goal_n_equivalent_after"]) == 4
    assert int(values["goal_n_equivalent"]) + 4 == values["goal_n"]
    nothing = everything.assign(p_equivalence_holm=np.where(goal, 0.2, np.nan))
    values = page(tmp_path, summ, nothing)["readings"]
    assert values["goal_n_equivalent"] == "0"
    assert int(values["goal_n_not_shown"]) == values["goal_n"]


def test_identical_differences_are_listed_as_identical_without_a_test(tmp_path):
    summ, diffs = built_tables()
    row = (diffs["comparison"] == "goal_response") & (diffs["measure"] == "rmse")
    row &= (diffs["effect"] == "size") & (diffs["at"] == "all_steps")
    diffs.loc[
        row, ["diff", "ci_low", "ci_high", "p", "p_holm", "p_equivalence", "p_equivalence_holm"]
    ] = [0.0, 0.0, 0.0, np.nan, np.nan, np.nan, np.nan]
    diffs.loc[row, ["identical", "family", "family_equivalence"]] = [True, NOT_TESTED, ""]
    pages, tables = page(tmp_path, summ, diffs, with_tables=True)
    assert pages["readings"]["goal_n_identical"] == "1"
    numbers = tables["readings_differences"].set_index(["label", "effect", "named"])
    shown = numbers.loc[("RMSE", "size", "Goal · every")]
    assert shown["verdict"] == "identical" and shown["diff"] == 0 and np.isnan(shown["p"])
    assert shown["holm"] == shown["tost"] == "identical"  # no TOST, no margin, no family
    found = pages["readings"]
    assert (found["family_differences"], found["family_equivalence"]) == (
        FAMILY_DIFFERENCES, FAMILY_EQUIVALENCE)  # fmt: skip


def job_counts(stdout: str) -> dict[str, int]:
    counts = {}
    for line in stdout.split("Job stats:")[-1].splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[1].isdigit():
            counts[parts[0]] = int(parts[1])
    return counts


def planned_outputs(stdout: str) -> dict[str, list[str]]:
    """A dry run's jobs: each job's heading line (rule and number) and its outputs."""
    import re

    jobs = re.split(r"^(?=(?:local)?rule \w+:$)", stdout, flags=re.M)
    made = {}
    for k, job in enumerate(jobs):
        found = re.search(r"^\s*output: (.*)$", job, flags=re.M)
        if found:
            made[f"{k}: {job.splitlines()[0]}"] = found[1].split(", ")
    return made


@pytest.mark.dryrun
@pytest.mark.parametrize("robustness", [False, True])
def test_readings_reuse_runs_whose_settings_coincide(tmp_path, robustness):
    """Every reading is replicated at the confirmation's seeds (each a job of its seed's
    measured runs), the Goal response changes only the maps, and a seed's readings share its
    demonstrations."""
    workdir = scratch_workflow(tmp_path)
    result = run_snakemake(
        workdir,
        "-n",
        "--forceall",
        "data/readings/summary.csv",
        "--config",
        f"robustness={robustness}",
        config=REPO / "config" / "config.yaml",
    )
    assert result.returncode == 0, result.stderr[-3000:]
    counts = job_counts(result.stdout)
    made = planned_outputs(result.stdout)
    readings = load_config()["readings"]
    n_readings = len(readings["categorisation_cue"]) * len(readings["goal_response"])
    declared = load_config()["confirmation"]
    n_reps = len(declared["seeds"]) + (len(declared["robustness_seeds"]) if robustness else 0)
    plan = plan_runs(load_config() | {"robustness": robustness})
    runs = {row["run"] for row in plan.readings}
    assert len(plan.readings) == n_readings * n_reps
    # every replication measured by exactly one job: its seed's job of rule measured (with its
    # training and maps, all in its group's folder: RunPlan.container), or rule measures for a
    # run the book also tests in full
    outputs = [path for paths in made.values() for path in paths]
    assert sorted(outputs) == sorted(set(outputs))
    assert {plan.container(plan.path(run, "eval/measures.json")) for run in runs} <= set(outputs)
    assert counts.get("measures", 0) + sum(
        run in runs for group in plan.measured_groups.values() for run in group
    ) == len(runs)
    # the Goal response changes the SOMs only: one set per seed and response, demos per seed
    # (whichever job makes them: rule soms, or a seed's measured job)
    readings_soms = {plan.path(plan.stage_run(run, "soms"), "soms/soms.npz") for run in runs}
    assert {plan.container(path) for path in readings_soms} <= set(outputs)
    assert len(readings_soms) == n_reps * len(readings["goal_response"])
    assert counts["demos"] == n_reps  # a job per replication (its seed)


def test_closed_loop_trials_do_not_depend_on_the_sequence(built):
    """What the book says plainly: in closed loop a network's trials of one object and task are
    one movement whatever the sequence (same start, same inputs); teacher forced, they differ."""
    import numpy as np

    from icub_affordance.files import load_npz

    hidden = load_npz(built / "data" / "eval" / "hidden.npz")
    sequences = load_config()["demos"]["sequences"]
    for key, h in hidden.items():
        per = h.reshape(-1, sequences, *h.shape[1:])  # (task x object, sequence, step, unit)
        same = np.allclose(per, per[:, :1], atol=0, rtol=0)
        assert same == key.endswith("closed_loop"), key


def test_readings_summary_has_every_cell(built):
    from icub_affordance.trials.scores import analysed, can_lack_cells

    table = pd.read_csv(built / "data" / "readings" / "summary.csv")
    readings = load_config()["readings"]
    assert list(table.columns) == SUMMARY_COLUMNS
    n_readings = len(readings["categorisation_cue"]) * len(readings["goal_response"])
    assert len(table) == n_readings * len(analysed(readings["measures"])) * 2
    assert set(table["measure"]) == set(analysed(readings["measures"]))
    import yaml
    from conftest import TEST_CONFIG

    replications = len(yaml.safe_load(TEST_CONFIG.read_text())["confirmation"]["seeds"])
    assert (table["replications"] == replications).all()
    # a t over the replications' defined estimates; a replication that could not estimate a
    # term (the correct-trial RMSE without a correct trial in a cell) is left out and counted
    tested = table["p"].notna()
    assert (table.loc[tested, "df"] == replications - table.loc[tested, "not_estimable"] - 1).all()
    assert not table.loc[~table["measure"].map(can_lack_cells), "not_estimable"].any()
    from icub_affordance.trials.scores import is_hypothesis

    # the null control and the measure tested by its excess over it are in no family
    hypothesis = table["measure"].map(is_hypothesis)
    hypotheses = table[hypothesis]
    assert hypotheses["p_holm"].to_numpy() == pytest.approx(holm(hypotheses["p"]), nan_ok=True)
    assert table.loc[~hypothesis, "p_holm"].isna().all()
    diffs = pd.read_csv(built / "data" / "readings" / "differences.csv")
    assert list(diffs.columns) == DIFFERENCE_COLUMNS
    # each comparison at each level of the other choice, every measure, both effects
    assert len(diffs) == 2 * 2 * len(analysed(readings["measures"])) * 2


def test_anova_json_has_the_contrasts_per_mode(built):
    import json

    from icub_affordance.analysis.trial_effects import TERMS
    from icub_affordance.vocabulary import MODES

    anova = json.loads((built / "data" / "eval" / "anova.json").read_text())
    assert set(anova["contrasts"]) == set(MODES)
    for mode in MODES:
        assert set(anova["contrasts"][mode]) == set(TERMS)
        for term in anova["contrasts"][mode].values():
            assert {"estimate", "ci_low", "ci_high", "p", "df"} <= set(term)
            assert term["ci_low"] <= term["estimate"] <= term["ci_high"]
    # the paper's analysis is still there, beside it
    assert "two_way" in anova["closed_loop"]


def test_paired_readings_share_each_networks_seed(built):
    """The pairing of the differences: network k of every reading at one seed draws the same
    initial weights and the same training schedule (one generator, seeded by
    training.network_seed(seed, k), draws both in that order), so the schedules in the learning
    curves coincide between readings and differ between networks."""
    import yaml
    from conftest import TEST_CONFIG

    cue = yaml.safe_load((REPO / "config" / "config.yaml").read_text())["network"][
        "categorisation_cue"
    ]
    other = {"first_step": "all_steps", "all_steps": "first_step"}[cue]
    groups = [[built / "data", built / "data" / "runs" / f"cue_{other}"]]
    for seed in yaml.safe_load(TEST_CONFIG.read_text())["confirmation"]["seeds"]:
        # a seed's readings: trained in its group's folder (rule measured, RunPlan.path)
        group = built / "data" / "measured" / f"seed{seed}"
        groups.append(sorted(group.glob(f"reading_*_seed{seed}")))
    assert all(len(runs) >= 2 for runs in groups) and len(groups) >= 3
    networks = yaml.safe_load(TEST_CONFIG.read_text())["network"]["networks"]
    columns = ["iteration", "task", "object", "sequence"]

    def schedule(run, net):  # the config's own run a part per network, any other one part
        from icub_workflow.parts import load_curves

        part = run / "train" / "all" / "curve.csv"
        paths = [part] if part.exists() else [run / "train" / f"net{net:02d}" / "curve.csv"]
        return dict(load_curves([str(p) for p in paths]))[net][columns]

    for runs in groups:  # the runs of one seed: the same schedule for each network
        for net in range(networks):
            mine = schedule(runs[0], net)
            for run in runs[1:]:
                pd.testing.assert_frame_equal(schedule(run, net), mine)
        assert not schedule(runs[0], 0).equals(schedule(runs[0], 1))
    # another seed, another schedule
    assert not schedule(groups[1][0], 0).equals(schedule(groups[2][0], 0))


def test_every_margin_names_the_commit_that_declared_it():
    """Each equivalence margin says when it was declared and whether its measure's results had
    been read by then; the config check refuses a margin without that record."""
    import subprocess

    from icub_workflow.config_checks import ConfigError, check_config

    readings = load_config()["readings"]
    declared = readings["margin_declared"]
    assert set(declared) == set(readings["equivalence_margin"])
    # the RMSE's margin came after its results were in the book; rmse_correct's before any
    assert declared["rmse"]["results_before"] and not declared["rmse_correct"]["results_before"]
    # every named commit exists in this history
    for measure, entry in declared.items():
        known = subprocess.run(
            ["git", "cat-file", "-t", entry["commit"]], cwd=REPO, capture_output=True, text=True
        )
        if known.returncode and not (REPO / ".git").exists():
            pytest.skip("no git history to check the commits against")
        assert known.stdout.strip() == "commit", (measure, entry)
    config = load_config()
    undated = config["readings"] | {"margin_declared": {"rmse": declared["rmse"]}}
    with pytest.raises(ConfigError, match=r"readings\.margin_declared.*no entry"):
        check_config(config | {"readings": undated})


def test_a_test_also_in_the_confirmatory_family_names_the_verdict_the_book_reads(tmp_path):
    summ, diffs = built_tables()
    _, tables = page(tmp_path, summ, diffs, with_tables=True)
    shown = tables["readings_summary"]
    marked = shown[shown["also_in"] != ""]
    # only the first-step, fixed reading's closed-loop RMSE congruency: the confirmation's own
    # replications (the teacher-forced test is another test, the grows reading other runs)
    assert marked[["cue", "goal_response", "measure", "effect"]].values.tolist() == [
        ["first_step", "fixed", "rmse", "congruency"]
    ]
    assert marked["also_in"].iloc[0].startswith("confirmatory family: confirmed, Holm p 0.045")
