"""The findings: the verdicts and statistics the book reports, on hand-made inputs, and the rule
that writes them for every page (data/book/findings.json and data/book/tables/)."""

from __future__ import annotations

import itertools
import json
import math
import re
from html import escape
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from conftest import REPO, load_test_config
from scipy import stats as sps

from icub_affordance.analysis import verdicts
from icub_affordance.analysis.verdicts import Verdict, verdict


def analysis(congruent, incongruent, large, small, p_congruency, p_size):
    """One test mode as anova.json holds it (only what the verdicts read)."""
    means = {"congruent": congruent, "incongruent": incongruent, "large": large, "small": small}
    rm = {"congruency": {"p": p_congruency}, "size": {"p": p_size}}
    return {"means": means, "repeated_measures": rm}


# -- the verdict: direction and p < 0.05, defined once ------------------------------------------


@pytest.mark.parametrize(
    ("congruent", "incongruent", "p", "direction", "significant"),
    [
        (0.10, 0.12, 0.01, True, True),  # the paper's result
        (0.10, 0.12, 0.20, True, False),  # its direction, not significant
        (0.12, 0.10, 0.01, False, True),  # significantly reversed
        (0.12, 0.10, 0.20, False, False),
        (0.10, 0.10, 0.01, False, True),  # equal means are not the paper's direction
        (0.10, 0.12, 0.05, True, False),  # p must be below 0.05, not at it
        (0.10, 0.12, 0.0499, True, True),
        (0.10, 0.12, float("nan"), True, False),  # an undefined p is not significant
    ],
)
def test_the_congruency_verdict(congruent, incongruent, p, direction, significant):
    v = verdict(analysis(congruent, incongruent, 0.1, 0.1, p, 0.5), "congruency")
    assert v == Verdict(paper_direction=direction, significant=significant)
    assert v.reproduced == (direction and significant)
    assert v.reversed == (significant and not direction)


def test_the_size_verdict_reads_the_size_means_and_p():
    # congruency says one thing, size another: each verdict reads its own effect
    m = analysis(0.10, 0.12, 0.15, 0.11, 0.001, 0.03)
    assert verdict(m, "size") == Verdict(paper_direction=False, significant=True)
    assert verdict(m, "size").reversed and verdict(m, "congruency").reproduced
    m = analysis(0.10, 0.12, 0.11, 0.15, 0.9, 0.03)
    assert verdict(m, "size").reproduced and not verdict(m, "congruency").significant


def test_without_an_anova_nothing_is_significant():
    """The robot measures' ANOVA is None where every network scored the same in every cell."""
    m = {"means": {"congruent": 0.2, "incongruent": 0.3}, "repeated_measures": None}
    assert verdict(m, "congruency") == Verdict(paper_direction=True, significant=False)


@pytest.mark.parametrize(
    ("n", "mean", "low", "high", "direction"),
    [
        (10, 0.03, 0.02, 0.04, "paper"),
        (10, -0.03, -0.04, -0.02, "against"),
        (10, 0.01, -0.01, 0.03, "unclear"),
        (10, 0.01, 0.0, 0.03, "unclear"),  # an interval touching 0 does not exclude it
        (1, -0.02, float("nan"), float("nan"), "single"),
    ],
)
def test_an_effect_over_replications_by_its_interval(n, mean, low, high, direction):
    assert verdicts.interval_direction(n, mean, low, high) == direction


def test_the_robot_verdicts():
    emb = {
        "success_rate": 0.3,
        "categorisation_success": 0.05,
        "replay_success": {"commands": 1.0, "sensed_postures": 0.5},
    }
    assert verdicts.robot_verdicts(emb) == {"below_ceiling": True, "at_floor": True}
    emb |= {"success_rate": 0.5, "categorisation_success": 0.1}
    assert verdicts.robot_verdicts(emb) == {"below_ceiling": False, "at_floor": False}


# -- the statistics ------------------------------------------------------------------------------

OBJECTS = ["big_ball", "small_ball", "big_cube", "small_cube"]


def test_the_grip_distance_of_a_made_up_demonstration_set():
    """Two grips a known distance apart at every step after the first; the first step (the
    common starting posture) is made far apart on purpose and must not count."""
    angles = np.zeros((4, 2, 5, 10, 16))
    angles[:, 1, :, 0] = 0.9  # step 0: excluded
    angles[[0, 2], 1, :, 1:] = 0.3  # large objects: precision 0.3 from power on every DoF
    angles[[1, 3], 1, :, 1:] = 0.1
    gap = verdicts.grip_distance(angles, OBJECTS)
    assert gap["large"] == pytest.approx(0.3) and gap["small"] == pytest.approx(0.1)


def grip_distance_by_hand(angles, objects, size):
    """The root mean square difference between the grips, summed term by term."""
    total, count = 0.0, 0
    for o, name in enumerate(objects):
        if name.startswith("big") != (size == "large"):
            continue
        for seq, step, dof in itertools.product(
            range(angles.shape[2]), range(1, angles.shape[3]), range(angles.shape[4])
        ):
            total += (angles[o, 0, seq, step, dof] - angles[o, 1, seq, step, dof]) ** 2
            count += 1
    return math.sqrt(total / count)


def test_the_grip_distance_of_random_demonstrations_equals_a_hand_count():
    angles = np.random.default_rng(3).random((4, 2, 3, 6, 5))
    objects = ["small_cube", "big_ball", "big_cube", "small_ball"]  # any order
    gap = verdicts.grip_distance(angles, objects)
    for size in ("large", "small"):
        assert gap[size] == pytest.approx(grip_distance_by_hand(angles, objects, size), rel=1e-12)


def test_the_learning_curve_summary():
    iterations = np.arange(3000, dtype=float)
    curves = np.stack([iterations, iterations + 2])  # two networks, mean = iteration + 1
    s = verdicts.curve_summary(curves, phase1_iterations=1500)
    assert s["n_networks"] == 2 and s["at"] == 2000
    assert s["start"] == pytest.approx(np.mean(np.arange(10)) + 1)
    assert s["around_at"] == pytest.approx(np.mean(np.arange(1900, 2100)) + 1)
    assert s["phase1_end"] == pytest.approx(np.mean(np.arange(1000, 1500)) + 1)
    assert s["end"] == pytest.approx(np.mean(np.arange(2500, 3000)) + 1)
    # a short run: the moment "around 2000" moves to 100 before the end
    assert verdicts.curve_summary(curves[:, :1200], 600)["at"] == 1100


def test_a_thinned_learning_curve_is_summarised_over_the_iterations_it_kept():
    """A long training's curve keeps every k-th iteration (training.curve_every): each window is
    the kept rows whose iteration falls in it, not the first rows."""
    kept = np.arange(4, 3001, 4)  # iterations 4, 8, ..., 3000
    curves = np.stack([kept, kept + 2.0])
    s = verdicts.curve_summary(curves, 1500, iterations=kept)
    assert s["at"] == 2000 and s["start"] == pytest.approx(np.mean([4, 8]) + 1)
    assert s["around_at"] == pytest.approx(np.mean(np.arange(1904, 2101, 4)) + 1)
    assert s["phase1_end"] == pytest.approx(np.mean(np.arange(1004, 1501, 4)) + 1)
    assert s["end"] == pytest.approx(np.mean(np.arange(2504, 3001, 4)) + 1)


def test_the_demonstration_counts():
    summary = pd.DataFrame({"attempts": [1, 3, 1, 2], "lift_m": [0.05, 0.049, 0.051, 0.05]})
    assert verdicts.demo_counts(summary) == {
        "n_demos": 4,
        "n_attempts": 7,
        "n_retried": 2,
        "lift_min_cm": pytest.approx(4.9),
    }


def test_the_joint_counts():
    joints = pd.DataFrame({"driven_joints": ["a"] * 7 + ["b c", "d", "e f g"]})
    assert verdicts.joint_counts(joints) == {"n_dof": 10, "n_driven": 13, "n_hand_driven": 6}


# -- the words ---------------------------------------------------------------------------------


def term(estimate: float, p: float, df: float = 10.0, se: float = 0.01, **extra) -> dict:
    """A tested term as ``stats`` writes it (t from the estimate and se)."""
    return {"estimate": estimate, "se": se, "t": estimate / se, "df": df, "p": p,
            "ci_low": estimate - 0.02, "ci_high": estimate + 0.02, "p_holm": p,
            "family": "a family", "family_size": 4} | extra  # fmt: skip


def test_a_verdict_word_reads_the_p_adjusted_within_its_family():
    from icub_workflow.book import text, words

    assert words.verdict_word(term(0.03, 0.01)) == "confirmed"
    assert words.verdict_word(term(-0.03, 0.01)) == "reversed"
    # the raw p is significant, the adjusted one is not: not shown
    assert words.verdict_word(term(-0.03, 0.01, p_holm=0.2)) == "not shown"
    assert words.verdict_word(term(0.03, float("nan"))) == "not assessable"
    # the adjusted p crosses alpha and the word follows
    assert words.verdict_word(term(0.03, 0.049)) == "confirmed"
    assert words.verdict_word(term(0.03, 0.051)) == "not shown"
    assert "within the family “a family” (4 tests) p = 0.010" in text.fmt_term(term(0.03, 0.01))


def test_a_tests_page_values_carry_its_verdict_and_what_it_rests_on():
    from icub_workflow.book import text

    values = text.test_values("discussion", "size", term(-0.026, 0.01))
    assert values["size_verdict"] == text.Claim(
        "reversed", ("discussion.size_estimate", "discussion.size_p_holm")
    )
    assert values["size_estimate"] == -0.026 and values["size_p_holm"] == 0.01
    assert "within the family “a family” (4 tests) p = 0.010" in values["size_stats"]
    # the verdict follows the adjusted p, not the raw one, and the estimate's sign
    assert text.test_values("d", "s", term(-0.026, 0.01, p_holm=0.17))["s_verdict"].text == (
        "not shown"
    )
    assert text.test_values("d", "s", term(0.026, 0.01))["s_verdict"].text == "confirmed"


def test_a_difference_the_paper_does_not_predict_is_shown_or_not_without_a_direction():
    from icub_workflow.book import text, words

    assert (
        words.shown_word(term(-0.03, 0.001)) == words.shown_word(term(0.03, 0.001)) == "confirmed"
    )
    assert words.shown_word(term(0.03, 0.001, p_holm=0.2)) == "not shown"
    assert words.shown_word(term(0.03, float("nan"))) == "not assessable"
    values = text.test_values("d", "grip", term(0.06, 0.3), words.shown_word)
    assert values["grip_verdict"].text == "not shown"


def test_the_main_runs_verdicts_keep_errors_apart():
    from icub_workflow.book import pages

    wrong = {"congruent_large": 0.0, "congruent_small": 0.0, "incongruent_large": 0.5,
             "incongruent_small": 0.7}  # fmt: skip
    loop = {
        "means": {"congruent": 0.07, "incongruent": 0.11, "large": 0.1, "small": 0.08},
        "means_correct": {}, "wrong_grip_rate": wrong,
        "errors": {"congruency": term(0.6, 0.001), "size": term(-0.1, 0.5),
                   "congruency:size": term(0.1, 0.5)},
        "correct_rt": {"congruency": term(-0.01, 0.001), "size": term(0.0, 1.0),
                       "congruency:size": term(0.01, 0.001)},
    }  # fmt: skip
    rmse = {"congruency": term(0.04, 0.001), "size": term(-0.026, 0.01),
            "congruency:size": term(0.02, 0.001)}  # fmt: skip
    anova = {mode: loop for mode in ("closed_loop", "teacher_forced")}
    anova |= {"contrasts": dict.fromkeys(("closed_loop", "teacher_forced"), rmse),
              "simple": dict.fromkeys(("closed_loop", "teacher_forced"),
                                      {"size_in_congruent": term(-0.02, 0.001)})}  # fmt: skip
    curve = dict.fromkeys(("start", "around_at", "at", "phase1_end", "end", "n_networks"), 1)
    demos = {"angles": np.zeros((4, 2, 5, 3, 2)),
             "objects": np.array(["big_ball", "small_ball", "big_cube", "small_cube"])}  # fmt: skip
    values = pages.main_tests(anova, curve, demos, "first_step")
    said = {k: v.text for k, v in values.items() if k.endswith("_verdict")}
    assert said["closed_loop_congruency_verdict"] == "confirmed"
    assert said["closed_loop_size_verdict"] == "reversed"
    # the paper claims nothing of errors: a difference there is "confirmed", not "confirmed"
    assert said["closed_loop_errors_congruency_verdict"] == "confirmed"
    assert said["closed_loop_rt_congruency_verdict"] == "reversed"
    assert (
        said["closed_loop_errors_size_verdict"]
        == said["closed_loop_rt_size_verdict"]
        == ("not shown")
    )
    # nor of the required grip: shown or not, in either direction; a simple size effect has the
    # paper's direction (small - large), so it is reproduced or reversed
    assert said["closed_loop_grip_verdict"] == said["closed_loop_rt_grip_verdict"] == "confirmed"
    assert said["closed_loop_size_in_congruent_verdict"] == "reversed"
    assert values["closed_loop_wrong_incongruent"] == pytest.approx(0.6)


def test_the_cue_timings_are_compared_by_the_test_of_their_difference():
    from icub_workflow.book import pages, text, words

    def said(t):
        words = {"confirmed": "larger first", "reversed": "larger every"}
        found = pages.traced({"beyond": text.test_values("beyond", "d", t, words=words)})
        assert found["claims"]["beyond"]["d_verdict"] == ["beyond.d_estimate", "beyond.d_p_holm"]
        return found["beyond"]["d_verdict"]

    assert words.verdict_word(term(0.03, 0.001)) == "confirmed"
    assert said(term(0.03, 0.001)) == "larger first"
    # the verdict reads the readings' table's Holm p where given
    assert said(term(0.03, 0.001, p_holm=0.2)) == "not shown"
    assert said(term(-0.03, 0.001)) == "larger every"
    assert said(term(0.03, 0.2)) == "not shown"


def test_a_claim_must_rest_on_findings_the_book_has():
    from icub_workflow.book import pages, text

    ok = pages.traced({"p": {"x": 1.0, "s": text.Claim("x is one", ("p.x",))}})
    assert ok["p"]["s"] == "x is one" and ok["claims"] == {"p": {"s": ["p.x"]}}
    with pytest.raises(KeyError, match="p.y"):
        pages.traced({"p": {"x": 1.0, "s": text.Claim("y is", ("p.y",))}})
    with pytest.raises(ValueError, match="page.key"):
        text.Claim("unfounded", ())


# -- the rule, on the test configuration's run ---------------------------------------------------

PAGES = sorted(p.stem for p in (REPO / "book").glob("*.md") if "kernelspec:" in p.read_text())


@pytest.fixture(scope="module")
def found(built):
    return json.loads((built / "data" / "book" / "findings.json").read_text())


def test_the_rule_writes_a_section_for_every_page_that_glues(found):
    """Every section of findings.json is read by a page (by its name, as a page reads it:
    ``["robot_test"]``, or in a tuple of sections, as the model chapter reads its four), and
    every page that reads findings.json names a section it has; "claims" traces the sentences."""
    texts = {p: (REPO / "book" / f"{p}.md").read_text() for p in PAGES}
    read = {s for s in found for text in texts.values() if f'"{s}"' in text}
    assert set(found) - {"claims"} <= read, set(found) - read
    for page, text in texts.items():
        if "findings.json" in text:
            assert any(f'"{s}"' in text for s in found), page


def test_every_claim_rests_on_numbers_the_book_has(found):
    claims = found["claims"]
    for page in ("index", "tests", "beyond"):
        assert claims.get(page), page
    for page, keys in claims.items():
        for key, entries in keys.items():
            assert key in found[page] and isinstance(found[page][key], str), (page, key)
            for entry in entries:
                where, name = entry.split(".", 1)
                assert isinstance(found[where][name], (int, float)), entry


def test_the_rule_computes_the_grip_distance_of_the_runs_demonstrations(built, found):
    with np.load(built / "data" / "demos" / "demos.npz", allow_pickle=False) as demos:
        angles, objects = demos["angles"], demos["objects"].tolist()
    for size in ("large", "small"):
        expected = grip_distance_by_hand(angles, objects, size)
        assert found["tests"][f"grip_distance_{size}"] == pytest.approx(expected, rel=1e-9)


def test_the_rules_verdicts_are_the_ones_the_book_shows(built, found):
    from icub_affordance.analysis.statistics import holm

    # the front page reads the confirmatory family over the replications, recomputed here
    summary = pd.read_csv(built / "data" / "claims" / "summary.csv")
    estimates = pd.read_csv(built / "data" / "claims" / "replications.csv")
    least = load_test_config()["confirmation"]["min_replications"]
    keys = ["cue", "mode", "measure", "effect"]
    expected_p = []
    for _, row in summary.iterrows():
        values = estimates[(estimates[keys] == row[keys]).all(axis=1)]["estimate"].dropna()
        assert row["estimable"] == len(values)
        if len(values) >= least:
            assert row["estimate"] == pytest.approx(values.mean(), rel=1e-9)
            expected_p.append(sps.ttest_1samp(values.to_numpy(), 0.0).pvalue)
        else:
            expected_p.append(np.nan)
    assert summary["p_holm"].to_numpy() == pytest.approx(holm(expected_p), rel=1e-9, nan_ok=True)
    words = {"paper": "confirmed", "reversed": "reversed", "none": "not shown",
             "not assessable": "not assessable"}  # fmt: skip
    for _, row in summary.iterrows():
        key = "claim_" + "_".join(row[k] for k in keys)
        assert found["index"][f"{key}_verdict"] == words[row["direction"]]
        if np.isfinite(row["p_holm"]):
            want = "none" if row["p_holm"] >= 0.05 else "paper" if row["estimate"] > 0 else (
                "reversed")  # fmt: skip
            assert row["direction"] == want
    # this run's own tests are exploration, and its page reads them
    anova = json.loads((built / "data" / "eval" / "anova.json").read_text())
    closed = anova["contrasts"]["closed_loop"]
    assert closed["congruency"]["family"] == "exploration: closed loop"
    p_holm = closed["congruency"]["p_holm"]
    assert found["tests"]["closed_loop_congruency_p_holm"] == p_holm
    estimate = closed["congruency"]["estimate"]
    verdict = found["tests"]["closed_loop_congruency_verdict"]
    assert verdict == (
        "not shown" if p_holm >= 0.05 else "confirmed" if estimate > 0 else "reversed"
    )


def test_the_comparison_page_shows_the_main_runs_numbers(built, found):
    html = (built / "book" / "_build" / "html" / "results.html").read_text()
    tests = found["tests"]  # the results page sets the paper beside the main run's tests
    for key in ("closed_loop_congruency_stats", "closed_loop_size_stats"):
        assert escape(tests[key]) in html or tests[key] in html, key
    assert f"{tests['rmse_end']:.3f}" in html and f"{tests['closed_loop_congruent']:.4f}" in html


def holm_by_family(table: pd.DataFrame, p: str, adjusted: str, family: str) -> None:
    """Every adjusted p of ``table`` equals Holm's over its named family, recomputed here (by
    hand: the step-down products, made monotone, capped at 1); a row without a p has none."""
    for name, rows in table.groupby(family):
        values = rows[p].to_numpy(dtype=float)
        ok = np.isfinite(values)
        m = int(ok.sum())
        order = np.argsort(values[ok])
        expected = np.empty(m)
        expected[order] = np.minimum(
            np.maximum.accumulate(values[ok][order] * (m - np.arange(m))), 1
        )
        got = rows[adjusted].to_numpy(dtype=float)
        assert np.isnan(got[~ok]).all(), name
        assert got[ok] == pytest.approx(expected, rel=1e-9), name


def test_the_books_test_tables_name_their_families_and_adjust_within_them(built):
    anova = json.loads((built / "data" / "eval" / "anova.json").read_text())
    both = pd.DataFrame(  # every test of both modes, as the results page shows them
        {"p": t["p"], "family": t["family"], "p (Holm, within its family)": t["p_holm"]}
        for mode in ("closed_loop", "teacher_forced")
        for tests in (anova["contrasts"][mode], anova[mode]["errors"], anova[mode]["correct_rt"],
                      anova["simple"][mode])
        for t in tests.values()
    )  # fmt: skip
    # this run's tests are its exploration (the confirmatory family is the replications')
    assert set(both["family"]) == {"exploration: closed loop", "exploration: teacher forced"}
    holm_by_family(both, "p", "p (Holm, within its family)", "family")
    # the front page's rows are tests of these tables: the same p, family and adjusted p
    found = json.loads((built / "data" / "book" / "findings.json").read_text())["tests"]
    for prefix in ("", "errors_", "rt_"):
        for effect in ("congruency", "size", "grip"):
            key = f"closed_loop_{prefix}{effect}"
            if np.isnan(found[f"{key}_p"]):
                assert np.isnan(found[f"{key}_p_holm"])
                continue
            match = both[(both["family"] == found[f"{key}_family"]) & np.isclose(
                both["p"], found[f"{key}_p"])]  # fmt: skip
            assert len(match) >= 1, key
            assert match["p (Holm, within its family)"].iloc[0] == pytest.approx(
                found[f"{key}_p_holm"])  # fmt: skip


@pytest.mark.dryrun
def test_the_findings_rule_reads_no_figure(tmp_path):
    from conftest import run_snakemake, scratch_workflow

    result = run_snakemake(
        scratch_workflow(tmp_path), "-n", "--forceall", "data/book/findings.json"
    )
    assert result.returncode == 0, result.stderr[-3000:]
    block = result.stdout.split("rule findings:")[1].split("\n\n")[0]
    inputs = block.split("input:")[1].split("\n")[0].split(", ")
    assert "data/eval/anova.json" in [name.strip() for name in inputs]
    assert not [name for name in inputs if name.strip().endswith(".png")], inputs
    # nor on a plot rule: nothing drawn is made for it
    assert not re.search(r"rule (figure\w*|\w*filmstrip):", result.stdout)


FORBIDDEN = [
    "icub_affordance",  # the science: the findings rule runs it
    "icub_book",  # the words: the findings rule writes them
    ".mean(",
    ".sum(",
    ".groupby(",
    "< 0.05",
    "ttest",
]


@pytest.mark.parametrize("page", PAGES)
def test_a_page_only_displays(page):
    """No statistic, test or verdict in a page's code: it reads and shows what the rules wrote."""
    source = (REPO / "book" / f"{page}.md").read_text()
    code = "\n".join(re.findall(r"```\{code-cell\}[^\n]*\n(.*?)```", source, flags=re.S))
    for word in FORBIDDEN:
        assert word not in code, (page, word)


@pytest.mark.heavy
def test_with_the_sweep_the_robustness_page_shows_the_findings(tmp_path):
    """The sweep is too long for the tests' run: its findings from a made-up summary and job
    records (benchmark files), and the page executed on them."""
    import shutil

    from conftest import load_test_config
    from jupyter_cache import get_cache
    from myst_nb.core.read import read_myst_markdown_notebook

    from icub_workflow.book import pages
    from icub_workflow.book_build.notebooks import execute_pages

    config = load_test_config() | {"robustness": True}
    config["sweep"] |= {"seeds": [1, 2, 3], "categorisation_cue": ["first_step"]}
    row = {"learning_rate": 0.075, "hidden": 10, "categorisation_cue": "first_step"}
    row |= {"replications": 3}
    for effect, sign in (("congruency", 1), ("size", -1)):
        row |= {
            f"{effect}_effect": 0.03 * sign,
            f"{effect}_ci_low": 0.02 * sign,
            f"{effect}_ci_high": 0.04 * sign,
            f"{effect}_eta_p2": 0.5,
            f"{effect}_n_significant": 3 if sign > 0 else 0,
            f"{effect}_n_reversed": 0 if sign > 0 else 2,
        }
    inputs = {"sweep_summary.csv": tmp_path / "summary.csv"}
    pd.DataFrame([row]).to_csv(inputs["sweep_summary.csv"], index=False)
    # the full scale's critical path, as benchmarks/critical_path.py --record writes it
    inputs["full_scale_critical_path.json"] = tmp_path / "critical_path.json"
    inputs["full_scale_critical_path.json"].write_text(json.dumps({
        "jobs": 500, "missing": 0, "critical_path_s": 1800.0, "critical_path_jobs": 3,
        "sum_of_job_seconds": 7200.0, "commit": "abc1234", "date": "2026-12-07",
        "cpu": "a test CPU", "snakemake_args": ["--config", "robustness=True"], "span_s": 3810.0,
        "chain": [{"rule": "demos", "s": 600.0, "benchmark": "a"},
                  {"rule": "train", "s": 1200.0, "benchmark": "b"},
                  {"rule": "all", "s": 0.0, "benchmark": None}],  # the target: not shown
        "on_cores": [{"cores": 2, "lower_bound_s": 3600.0, "predicted_s": 3720.0},
                     {"cores": 8, "lower_bound_s": 1800.0, "predicted_s": 1860.0}],
    }))  # fmt: skip
    jobs = {}  # each seed's jobs, as the engine records them (column s: wall time)
    for seed, walls in {1: [60.0, 30.0], 2: [50.0], 3: [100.0, 20.0, 10.0]}.items():
        for k, wall in enumerate(walls):
            record = tmp_path / "benchmarks" / f"seed{seed}" / f"job{k}.tsv"
            record.parent.mkdir(parents=True, exist_ok=True)
            record.write_text(f"s\th:m:s\tmax_rss\n{wall}\t0:01:00\t100\n")
            jobs[str(record)] = seed
    values, table = pages.robustness(inputs, config, jobs)
    assert values["ran"] and values["sweep_ran"] == "ran it: seeds 1, 2, 3, 1 setting(s)"
    assert [table["congruency_direction"][0], table["size_direction"][0]] == [
        "paper's way", "against"]  # fmt: skip
    # a flipped interval flips the word: the size interval made to include 0
    summary = pd.read_csv(inputs["sweep_summary.csv"]).assign(size_ci_high=0.01)
    summary.to_csv(tmp_path / "flipped.csv", index=False)
    _, flipped = pages.robustness(
        inputs | {"sweep_summary.csv": tmp_path / "flipped.csv"}, config, jobs
    )
    assert [flipped["congruency_direction"][0], flipped["size_direction"][0]] == [
        "paper's way", "includes 0"]  # fmt: skip
    # per replication: 90, 50 and 130 s of job time
    assert {k: values[f"cost_{k}"] for k in ("replications", "jobs", "min_s", "max_s")} == {
        "replications": 3, "jobs": 6, "min_s": 50.0, "max_s": 130.0}  # fmt: skip
    assert values["cost_mean_s"] == 90.0 and values["cost_total_s"] == 270.0
    values = pages.traced({"robustness": values})["robustness"]

    book = tmp_path / "book"
    (book / "_data" / "tables").mkdir(parents=True)
    page = shutil.copy(REPO / "book" / "reproduce.md", book / "reproduce.md")
    # the page's other sections: the two scales, each rule's time, the packages and config
    scale = {row: 1 for row in ("readings", "reading_seeds", "size_runs", "size_replications",
                                "variants", "fresh", "sweep")}  # fmt: skip
    reproduce = {"scale": {"now": scale, "other": scale, "full": True}}
    (book / "_data" / "findings.json").write_text(
        json.dumps({"robustness": values, "reproduce": reproduce})
    )
    pd.DataFrame({"rule": ["demos"], "total_s": [1.0], "longest_s": [1.0]}).to_csv(
        book / "_data" / "benchmarks.csv", index=False
    )
    (book / "_data" / "run.json").write_text(json.dumps({"versions": {}, "config": {}}))
    table.to_csv(book / "_data" / "tables" / "sweep.csv", index=False)
    line = {"jobs": 412, "span_s": 1509.0, "job_s": 2753.0, "idle_core_s": 265.0}
    line |= {"executor": "slurm", "cluster": "hpc", "partition": "short"}
    (book / "_data" / "timeline.json").write_text(json.dumps(line))
    execute_pages(book, [Path(page)], workers=1)
    notebook = read_myst_markdown_notebook(Path(page).read_text(), path=str(page))
    _, merged = get_cache(str(book / "_build" / ".jupyter_cache")).merge_match_into_notebook(
        notebook
    )
    shown = json.dumps([cell.get("outputs", []) for cell in merged.cells])
    # the page's prose is its own; what it glues and shows comes from these numbers
    said = ("ran it: seeds 1, 2, 3, 1 setting(s)", "paper's way", "3 / 0 of 3", "0 / 2 of 3",
            "the sweep's 6 jobs took 90 s per replication on average, from 50 s to 130 s over "
            "its 3 replications, and 4.5 minutes in all", "the Slurm cluster hpc (partition short)",
            "412", "At full scale the build has 500 jobs and 2.0 hours of job time; its "
            "critical path is 30.0 minutes over 2 jobs. A schedule of these jobs predicts 62.0 "
            "minutes on 2 cores and 31.0 minutes on 8 cores; the build they come from ran 63.5 "
            "minutes from its first job's start to its last one's end.",
            "demos 600 s → train 1200 s",
            "a test CPU", "60.0 minutes on 2 cores, 30.0 minutes on 8 cores")  # fmt: skip
    for words in said:
        assert json.dumps(words)[1:-1] in shown, words
    assert "did not run it" not in shown
    assert "all 0 s" not in shown  # the target is no step of the chain


def test_the_package_is_the_science():
    """The book's machinery and the benchmarks live outside the package, which never imports
    Snakemake or the book's tools."""
    import ast

    machinery = {"snakemake", "myst_nb", "jupyter_cache", "nbclient", "nbformat", "sphinx"}
    machinery |= {"IPython", "icub_book", "sweep_cost", "collect", "subprocess"}
    for path in (REPO / "src" / "icub_affordance").rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Import):
                names = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0:
                names = [node.module]
            else:
                continue
            assert not {name.split(".")[0] for name in names} & machinery, (path.name, names)
    for moved in ("notebooks", "report", "sweep_cost"):
        assert not (REPO / "src" / "icub_affordance" / f"{moved}.py").exists(), moved


def test_the_hidden_layer_sentence_follows_the_adjusted_tests():
    from icub_workflow.book.pages import divergence_verdict

    assert divergence_verdict(3).text == "at every step from step 3 to the last"
    assert divergence_verdict(None).text.startswith("not at every step")
    assert divergence_verdict(3).rests_on == ("beyond.div_first_step",)


@pytest.mark.dryrun
def test_the_headline_reads_the_declared_family_and_nothing_else(built, tmp_path):
    """Changing the declared family reruns the claims' tests and nothing trained or measured
    before them; this run's statistics do not depend on it."""
    from conftest import run_snakemake

    def dry_run(target: str, **changes) -> str:
        path = tmp_path / "config.yaml"
        path.write_text(yaml.safe_dump(load_test_config() | changes))
        result = run_snakemake(built, "-n", "--nolock", target, config=path)
        assert result.returncode == 0, result.stderr[-3000:]
        return result.stdout

    fewer = load_test_config()["confirmation"] | {"measures": ["rmse"]}
    # the distractor's declared measures are the confirmation's (config_checks refuses others)
    distractor = load_test_config()["distractor"] | {"measures": ["rmse"]}
    out = dry_run("data/claims/summary.csv", confirmation=fewer, distractor=distractor)
    assert re.search(r"rule claims:\n(?:    .*\n)*?    output: data/claims/replications\.csv", out)
    assert "rule measured:" not in out and "rule train" not in out
    assert "Nothing to be done" in dry_run(
        "data/eval/anova.json", confirmation=fewer, distractor=distractor
    )
