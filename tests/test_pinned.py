"""Sentences pinned to the tests they rest on (book_build.pinned, verdict_table): the assumed
verdicts read from a directive's argument, every test of the claims named once with the code its
table holds or the declared tests' rule gives, and a sentence whose verdict moved is found."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from icub_workflow.book_build.pinned import disagreements, parse_assumptions, read_verdicts
from icub_workflow.book_build.verdict_table import verdict_rows


def test_a_findings_argument_is_pairs_of_test_and_code():
    assert parse_assumptions("a/b=paper\n  c/d=not_assessable") == [
        ("a/b", "paper"),
        ("c/d", "not assessable"),
    ]
    for bad in ("a/b", "=paper", "a/b=", ""):
        with pytest.raises(ValueError):
            parse_assumptions(bad)


def test_a_sentence_disagrees_where_a_verdict_moved_or_its_test_is_gone():
    verdicts = {"claims/x": "paper", "claims/y": "none"}
    assert disagreements([("claims/x", "paper"), ("claims/y", "none")], verdicts) == []
    found = disagreements([("claims/x", "none"), ("claims/z", "paper")], verdicts)
    assert found == ["claims/x is 'paper', not 'none'", "claims/z is no test of this build"]


def test_every_claim_and_sensitivity_test_is_named_once_with_its_code(tmp_path):
    claims = pd.DataFrame(
        [
            {
                "cue": "first_step",
                "mode": m,
                "measure": "rmse",
                "effect": e,
                "family": "confirmatory",
                "direction": code,
            }
            for (m, e), code in zip(
                [("closed_loop", "congruency"), ("closed_loop", "size")],
                ["paper", "reversed"],
                strict=True,
            )
        ]
    )
    sensitivity = pd.DataFrame(
        [
            {
                "cue": "first_step",
                "mode": "closed_loop",
                "effect": e,
                "family": "exploration",
                "estimate": est,
                "p_holm": p,
            }
            for e, est, p in (("congruency", 0.01, 0.01), ("size", -0.01, 0.5))
        ]
        + [
            {
                "cue": "all_steps",
                "mode": "closed_loop",
                "effect": "size",
                "family": "exploration",
                "estimate": -0.02,
                "p_holm": 0.001,
            },
            {
                "cue": "all_steps",
                "mode": "closed_loop",
                "effect": "congruency",
                "family": "exploration",
                "estimate": 0.02,
                "p_holm": np.nan,
            },
        ]
    )
    added = pd.DataFrame(
        [{"cue": "first_step", "mode": "teacher_forced", "family": "added", "direction": -1}]
    )
    table = verdict_rows(claims, sensitivity, added)
    codes = dict(zip(table["test"], table["code"], strict=True))
    assert codes == {
        "claims/first_step/closed_loop/rmse/congruency": "paper",
        "claims/first_step/closed_loop/rmse/size": "reversed",
        "correct_all/first_step/closed_loop/congruency": "paper",
        "correct_all/first_step/closed_loop/size": "none",
        "correct_all/all_steps/closed_loop/size": "reversed",
        "correct_all/all_steps/closed_loop/congruency": "not assessable",
        "congruent_size/first_step/teacher_forced": "reversed",
    }
    table.to_csv(tmp_path / "verdicts.csv", index=False)
    assert read_verdicts(tmp_path / "verdicts.csv") == codes
    with pytest.raises(ValueError, match="named twice"):
        verdict_rows(pd.concat([claims, claims]), sensitivity, added)


def assumed_in(page: str) -> list[tuple[str, str]]:
    """Every test=code pair the page's {finding} directives assume, in order."""
    found = re.findall(r"^:::+\{finding\}(.*(?:\n(?!:::).*)*)", page, re.M)
    return [pair for block in found for pair in parse_assumptions(block.split("\n")[0])]


def test_every_pages_findings_rest_on_tests_of_the_build():
    """Every test the book's sentences name is one the rule `verdicts` makes."""
    from conftest import REPO

    assumed = [
        pair
        for page in sorted((REPO / "book").glob("*.md"))
        for pair in assumed_in(page.read_text())
    ]
    assert len(assumed) >= 16
    cue, mode = "(first_step|all_steps)", "(teacher_forced|closed_loop)"
    effect = "(congruency|size)"
    named = [  # the tests verdict_table.verdict_rows names, family by family
        rf"claims/{cue}/{mode}/(rmse|rmse_correct)/{effect}",
        rf"congruent_size/{cue}/{mode}",
        rf"run/{cue}/{mode}/(rmse|errors|rmse_correct)/{effect}",
        rf"readings/{cue}/(fixed|grows)/(rmse|rmse_correct|wrong_grip|commitment)/{effect}",
        rf"size/(size|grip_distance|dose)/[0-9.\-]+/{cue}",
        rf"size_metric/(final_posture|trajectory_rms)/(size|grip_distance|size_larger)/[0-9.]+/{cue}",
        r"signatures/(in_view|grows_with_rt|extinction|brief_exposure|advance_cueing)",
        r"signature_errors/(in_view|extinction|brief_exposure)/[0-9]+",
        rf"words/{cue}/{mode}/(rmse_correct|wrong_grip)/(congruency|size|equivalence)",
        r"robot/(contact_time/congruency|held_vs_bar)",
        rf"distractor/-?[0-9.]+/{cue}/{mode}/(rmse|rmse_correct)/(congruency|compatibility)",
    ]
    unknown = [t for t, _ in assumed if not any(re.fullmatch(n, t) for n in named)]
    assert unknown == []


@pytest.mark.reruns
def test_a_flipped_verdict_fails_the_book_naming_its_sentence(built, tmp_path):
    """A copy of the test build whose verdicts are the ones the front page assumes but one,
    built strictly (config findings_check: strict): the book's build fails, and its log names
    the page, the test that moved and the sentence."""
    import shutil

    from conftest import run_snakemake

    copy = tmp_path / "copy"
    shutil.copytree(built, copy, symlinks=True)
    assumed = assumed_in((copy / "book" / "index.md").read_text())
    flipped = assumed[0][0]
    # every page's sentences hold in the copy but those resting on the flipped test
    codes = {test: code for page in sorted((copy / "book").glob("*.md"))
             for test, code in assumed_in(page.read_text())}  # fmt: skip
    codes[flipped] = "none"
    path = copy / "data" / "book" / "verdicts.csv"
    table = pd.read_csv(path)
    table["code"] = [codes.get(t, c) for t, c in zip(table["test"], table["code"], strict=True)]
    missing = sorted(set(codes) - set(table["test"]))  # tests the small configuration lacks
    table = pd.concat([table, pd.DataFrame({"test": missing, "family": "a test of the default",
                                            "code": [codes[t] for t in missing]})])  # fmt: skip
    table.to_csv(path, index=False)
    result = run_snakemake(
        copy, "-c2", "book/_build/html/index.html", "--config", "findings_check=strict"
    )
    assert result.returncode != 0
    log = (copy / "data" / "logs" / "book.log").read_text()
    moved = re.findall(r"(\w+)\.md:\d+: WARNING: a finding's sentence no longer holds: (.*)", log)
    assert moved and all(said.startswith(f"{flipped} is 'none'") for _, said in moved), log[-3000:]
    front = [said for page, said in moved if page == "index"]
    assert len(front) == 1
    assert front[0].startswith(f"{flipped} is 'none', not '{assumed[0][1]}'. The sentence: “Over ")


def test_each_chapters_tests_are_named_with_the_code_their_numbers_give():
    """The chapters' tests join the claims' (verdict_table.study_rows): a run's test reads its
    Holm p on the side of its estimate, a signature its word's code, the robot's share held its
    interval against the bar."""
    from icub_workflow.book_build.verdict_table import study_rows

    test = {"estimate": -0.02, "p_holm": 0.01, "family": "exploration: closed loop"}
    none = test | {"estimate": 0.02, "p_holm": 0.2}
    anova = {
        "contrasts": {
            m: {"congruency": test, "size": none} for m in ("closed_loop", "teacher_forced")
        }
    }
    anova |= {m: {"errors": {"congruency": none}, "correct_rt": {"size": test}}
              for m in ("closed_loop", "teacher_forced")}  # fmt: skip
    signatures = pd.DataFrame(
        {"signature": ["grows_with_rt", "grows_with_rt", "brief_exposure"],
         "condition": ["in view, all correct trials", "in view, slope", "masked"],
         "verdict": [np.nan, "not shown", "reversed"], "family": "signatures",
         "estimate": [0.02, -0.001, 0.01], "p_adjusted": [0.001, 0.3, 0.9]})  # fmt: skip
    confirmation = pd.DataFrame({"seed_set": ["exploration", "confirmation"],
                                 "ci_low": [0.95, 0.84], "ci_high": [0.99, 0.99]})  # fmt: skip
    rows = {
        r["test"]: r["code"]
        for r in study_rows(
            {"runs": {"first_step": anova}, "signatures": signatures, "confirmation": confirmation}
        )
    }
    assert rows["run/first_step/closed_loop/rmse/congruency"] == "reversed"
    assert rows["run/first_step/teacher_forced/rmse/size"] == "none"
    assert rows["run/first_step/closed_loop/rmse_correct/size"] == "reversed"
    assert rows["signatures/grows_with_rt"] == "none"
    assert rows["signatures/brief_exposure"] == "reversed"
    assert rows["signatures/in_view"] == "paper"
    assert rows["robot/held_vs_bar"] == "none"  # the fresh networks' interval includes 0.9


def test_the_distractors_tests_are_named_with_their_tables_direction():
    """The distractor's tests (issue 73) join the verdict table as
    ``distractor/{lam}/{cue}/{mode}/{measure}/{effect}``, their code the sign their table
    holds (positive: the grip compatible with the object faster), each in its family."""
    from icub_workflow.book_build.verdict_table import study_rows

    keys = {"cue": "first_step", "mode": "teacher_forced", "measure": "rmse"}
    summary = pd.DataFrame(
        [keys | {"lam": 0.25, "effect": "congruency", "direction": 1, "family": "declared"},
         keys | {"lam": 0.5, "effect": "compatibility", "direction": -1, "family": "declared"},
         keys | {"lam": -0.25, "effect": "compatibility", "direction": 0, "family": "inhibition"}]
    )  # fmt: skip
    rows = {r["test"]: (r["code"], r["family"]) for r in study_rows({"distractor": summary})}
    assert rows == {
        "distractor/0.25/first_step/teacher_forced/rmse/congruency": ("paper", "declared"),
        "distractor/0.5/first_step/teacher_forced/rmse/compatibility": ("reversed", "declared"),
        "distractor/-0.25/first_step/teacher_forced/rmse/compatibility": ("none", "inhibition"),
    }
