"""The robot's effect sentences (issue 24): each is a ``text.Claim`` resting on the statistics
stored beside it, and changing a statistic (its sign, its p across 0.05, its counts) changes the
sentence accordingly. Made-up effects, in the shape ``embodied_stats.variant_effects`` writes."""

import copy

import pytest
from scipy.stats import fisher_exact

from icub_workflow.book import pages, text


def counts(first_held: int, second_held: int, n: int = 24, factor: str = "congruency") -> dict:
    first, second = {"congruency": ("congruent", "incongruent"), "size": ("large", "small")}[factor]
    return {
        first: {"trials": n, "n": n, "mean": first_held / n},
        second: {"trials": n, "n": n, "mean": second_held / n},
    }


def contrast(estimate: float, p: float) -> dict:
    return {"method": "contrasts", "estimate": estimate, "se": 0.1, "t": estimate / 0.1,
            "df": 10.0, "ci_low": estimate - 0.2, "ci_high": estimate + 0.2, "p": p,
            "networks": 12}  # fmt: skip


def exact(table, p=None) -> dict:
    p = fisher_exact(table)[1] if p is None else p
    return {"method": "exact", "table": table, "odds_ratio": None, "p": float(p)}


def effects() -> dict:
    """One variant: success by contrast (congruency) and by the exact test (size, the issue's
    19/24 vs 15/24); contact time by contrast (congruency) and not estimable (size)."""
    success = {
        "distinct_trials": 48,
        "congruency": counts(18, 12),
        "size": counts(19, 15, factor="size"),
        "tests": {"congruency": contrast(-0.25, 0.03), "size": exact([[19, 5], [15, 9]])},
    }
    contact = {
        "distinct_trials": 48,
        "congruency": counts(20, 20),
        "size": counts(22, 18, factor="size"),
        "tests": {
            "congruency": contrast(0.08, 0.01),
            "size": {"method": "none", "reason": "2 network(s) touched in all four cells"},
        },
    }
    return {"v": {"success": success, "contact_time": contact}}


def sentence(effs: dict, name: str) -> str:
    values = pages._robot_effect_values(effs, "v", "best")
    claim = values[name]
    assert isinstance(claim, text.Claim)
    for entry in claim.rests_on:  # every entry names a value stored beside the sentence
        page, key = entry.split(".", 1)
        assert page == "grasping" and key in values, entry
    return claim.text


def test_the_issues_size_effect_counted_once_is_not_significant():
    # the constant-rate all_steps variant's size effect, counted once per network and object
    assert fisher_exact([[19, 5], [15, 9]])[1] == pytest.approx(0.34, abs=0.005)
    words = sentence(effects(), "best_success_size")
    assert words.startswith("not shown (")
    assert "held in 19 of 24 distinct large trials and 15 of 24 small" in words
    assert "Fisher's exact test, p = 0.341" in words
    # the same shares counted five times over: what the old summary tested
    assert fisher_exact([[95, 25], [75, 45]])[1] < 0.01


def test_a_contrast_claim_follows_its_sign_and_its_p():
    base = sentence(effects(), "best_success_congruency")
    assert base.startswith("as in the paper (") and "p = 0.030" in base  # congruent held more
    flipped = effects()
    flipped["v"]["success"]["tests"]["congruency"] = contrast(+0.25, 0.03)
    assert sentence(flipped, "best_success_congruency").startswith(
        "the opposite of what the paper reports ("
    )
    weak = effects()
    weak["v"]["success"]["tests"]["congruency"] = contrast(-0.25, 0.07)
    # a direction is not claimed from a test that does not show it
    assert sentence(weak, "best_success_congruency").startswith("not shown (")
    # contact time: longer when incongruent is the paper's direction
    assert sentence(effects(), "best_contact_time_congruency").startswith("as in the paper (")
    faster = effects()
    faster["v"]["contact_time"]["tests"]["congruency"] = contrast(-0.08, 0.01)
    assert sentence(faster, "best_contact_time_congruency").startswith("the opposite")


def test_an_exact_claim_follows_its_counts_and_its_p():
    swapped = effects()
    swapped["v"]["success"]["tests"]["size"] = exact([[15, 9], [19, 5]], p=0.01)
    swapped["v"]["success"]["size"] = counts(15, 19, factor="size")
    assert sentence(swapped, "best_success_size").startswith("the opposite of what the paper")
    swapped["v"]["success"]["tests"]["size"] = exact([[15, 9], [19, 5]])  # p = 0.341
    assert sentence(swapped, "best_success_size").startswith("not shown (")
    strong = effects()
    strong["v"]["success"]["tests"]["size"] = exact([[19, 5], [15, 9]], p=0.01)
    assert sentence(strong, "best_success_size").startswith("as in the paper (")
    same = effects()
    same["v"]["success"]["tests"]["size"] = exact([[19, 5], [19, 5]])
    same["v"]["success"]["size"] = counts(19, 19, factor="size")
    assert sentence(same, "best_success_size").startswith("no difference")
    values = pages._robot_effect_values(effects(), "v", "best")
    assert values["best_success_size_estimate"] == pytest.approx(15 / 24 - 19 / 24)


def test_an_effect_that_cannot_be_estimated_says_so():
    words = sentence(effects(), "best_contact_time_size")
    assert words.startswith("not estimable (") and "2 network(s)" in words
    values = pages._robot_effect_values(effects(), "v", "best")
    assert values["best_contact_time_size_p"] != values["best_contact_time_size_p"]  # NaN


def test_traced_keeps_what_each_robot_claim_rests_on():
    found = pages.traced({"grasping": pages._robot_effect_values(effects(), "v", "best")})
    claims = found["claims"]["grasping"]
    assert claims["best_success_size"] == ["grasping.best_success_size_estimate",
                                           "grasping.best_success_size_p"]  # fmt: skip
    assert isinstance(found["grasping"]["best_success_size"], str)


def test_the_wrong_grip_sentence_counts_the_failures_it_names():
    import pandas as pd

    variants = pd.DataFrame({"trials": [96, 96], "grasping_wrong_grip_hold": [0, 1],
                             "categorisation_wrong_grip_hold": [2, 0]})  # fmt: skip
    values = pages._wrong_grip_values(variants)
    assert values["wrong_grip_sentence"].text.startswith(
        "Of the 192 distinct trials of all variants, 3 held the object with a grip other"
    )
    assert "(1 grasping, 2 categorisation)" in values["wrong_grip_sentence"].text
    none = pages._wrong_grip_values(variants.assign(grasping_wrong_grip_hold=0,
                                                    categorisation_wrong_grip_hold=0))  # fmt: skip
    assert none["wrong_grip_sentence"].text.startswith("No distinct trial of any variant")


def analysis(err_estimate: float, err_p: float, categorisation: float = 0.4) -> dict:
    term = contrast(err_estimate, err_p) | {"networks": 12}
    means = {"congruent": 0.05, "incongruent": 0.06, "large": 0.05, "small": 0.06}
    return {
        "n_trials": 96, "n_networks": 12, "success_rate": 0.5, "grasping_success": 0.6,
        "categorisation_success": categorisation, "touching_rate": 0.9, "wrong_grip_holds": 1,
        "replay_success": {"commands": 0.975, "sensed_postures": 0.4},
        "replay_trials": {"commands": 40, "sensed_postures": 40},
        "replay_wrong_grip_holds": {"commands": 1, "sensed_postures": 0},
        "measures": {
            "final_error": {"means": means, "contrasts": {"congruency": term, "size": term},
                            "incongruent_minus_congruent": {}},
            "success": {"means": means, "contrasts": None,
                        "incongruent_minus_congruent": {"mean": -0.1, "ci_low": -0.2,
                                                        "ci_high": 0.0}},
        },
    }  # fmt: skip


def test_the_chapter_beyond_states_the_robots_effects_from_their_tests():
    own = effects()["v"]
    values = pages._robot_values(analysis(+0.01, 0.02), own)
    found = pages.traced({"beyond": values})
    words = found["beyond"]
    assert words["emb_n_trials"] == 96
    assert words["emb_err_sentence"] == (
        "the arm ended further from the demonstrated grasp in incongruent trials, significantly"
    )
    assert found["claims"]["beyond"]["emb_err_sentence"] == [
        "beyond.emb_final_error_congruency_estimate",
        "beyond.emb_final_error_congruency_p",
    ]
    flipped = pages.traced({"beyond": pages._robot_values(analysis(-0.01, 0.02), own)})
    assert flipped["beyond"]["emb_err_sentence"].startswith("the arm ended nearer")
    weak = pages.traced({"beyond": pages._robot_values(analysis(+0.01, 0.2), own)})
    assert weak["beyond"]["emb_err_sentence"].endswith(
        "did not differ significantly between congruent and incongruent trials"
    )  # noqa: E501
    assert words["emb_success_congruency"] == sentence(effects(), "best_success_congruency")
    other = copy.deepcopy(own)
    other["success"]["tests"]["congruency"] = contrast(+0.25, 0.02)
    changed = pages.traced({"beyond": pages._robot_values(analysis(+0.01, 0.02), other)})
    assert changed["beyond"]["emb_success_congruency"].startswith("the opposite")
    assert changed["beyond"]["emb_success_congruency"] != words["emb_success_congruency"]
    # the floor and the ceiling follow their rates
    assert words["floor_sentence"] == "" and words["emb_ceiling_sentence"] == "at or above"
    low = pages.traced({"beyond": pages._robot_values(analysis(0.01, 0.02, 0.05), own)})
    assert low["beyond"]["floor_sentence"].startswith("Success is near the floor")


def test_the_replays_held_with_the_other_grip_are_counted():
    own = effects()["v"]
    words = pages.traced({"beyond": pages._robot_values(analysis(0.01, 0.02), own)})["beyond"]
    assert words["replay_wrong_sentence"].startswith("1 of these 40 replays held the object")
    clean = analysis(0.01, 0.02)
    clean["replay_wrong_grip_holds"]["commands"] = 0
    words = pages.traced({"beyond": pages._robot_values(clean, own)})["beyond"]
    assert words["replay_wrong_sentence"] == ""
