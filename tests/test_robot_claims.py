"""The robot's effect sentences (issue 24): each is a ``text.Claim`` resting on the statistics
stored beside it, and changing a statistic (its sign, its p across 0.05, its counts) changes the
sentence accordingly. Made-up effects, in the shape ``embodied_stats.variant_effects`` writes."""

import copy

import numpy as np
import pytest
from scipy.stats import fisher_exact

from icub_workflow.book import pages, text

#: Per mapping and object (``variant_effects``' ``objects`` keys), its congruency x size cell
#: and the grip it requires: under mapping A natural objects take the power grip and artefacts
#: the precision grip, under B the reverse; a large object's natural grip is the power grip.
OBJECTS = {
    "A_big_ball": ("congruent", "large", "power"),
    "A_big_cube": ("incongruent", "large", "precision"),
    "A_small_ball": ("incongruent", "small", "power"),
    "A_small_cube": ("congruent", "small", "precision"),
    "B_big_ball": ("incongruent", "large", "precision"),
    "B_big_cube": ("congruent", "large", "power"),
    "B_small_ball": ("congruent", "small", "precision"),
    "B_small_cube": ("incongruent", "small", "power"),
}
CELLS = [f"{c}_{s}" for c in ("congruent", "incongruent") for s in ("large", "small")]
LEVELS = {"congruency": ("congruent", "incongruent"), "size": ("large", "small")}


def split(cells: dict[str, int]) -> dict[str, int]:
    """Each cell's count over its two objects (one per mapping), mapping A's the larger half."""
    out = {}
    for name, (c, s, _grip) in OBJECTS.items():
        count = cells[f"{c}_{s}"]
        out[name] = (count + 1) // 2 if name.startswith("A") else count // 2
    return out


def measure(cells: dict[str, int], seconds: dict[str, float] | None = None, per_object=6):
    """One measure's counts as ``variant_effects`` writes them, from its count per congruency x
    size cell (held, or with ``seconds`` touched: contact time, each object's mean ``seconds``
    of its congruency): per object (``per_object`` networks of each mapping), per cell and per
    level, each the sum of what it holds. No tests: ``effects`` adds them."""
    counted = "held" if seconds is None else "touched"
    objects = {}
    for name, count in split(cells).items():
        c, s, grip = OBJECTS[name]
        mean = count / per_object if seconds is None else (seconds[c] if count else np.nan)
        objects[name] = {"congruency": c, "size": s, "target_grip": grip,
                         "trials": per_object, counted: count, "mean": mean}  # fmt: skip

    def pooled(members: list[dict]) -> dict:
        trials, count = sum(o["trials"] for o in members), sum(o[counted] for o in members)
        if seconds is None:
            return {"trials": trials, counted: count, "mean": count / trials}
        mean = sum(o["mean"] * o[counted] for o in members if o[counted]) / count
        return {"trials": trials, counted: count, "mean": mean}

    out: dict = {"distinct_trials": per_object * len(OBJECTS)}
    for factor, levels in LEVELS.items():
        k = 0 if factor == "congruency" else 1
        out[factor] = {}
        for level in levels:
            mine = pooled([o for name, o in objects.items() if OBJECTS[name][k] == level])
            # every trial has a success, held or not; a contact time only where touched
            n = mine["trials"] if seconds is None else mine[counted]
            out[factor][level] = {"trials": mine["trials"], "n": n, "mean": mine["mean"]}
    out["cells"] = {
        cell: pooled([o for name, o in objects.items() if "_".join(OBJECTS[name][:2]) == cell])
        for cell in CELLS
    }
    out["objects"] = objects
    return out


def contrast(estimate: float, p: float, networks: int = 12) -> dict:
    return {"method": "contrasts", "estimate": estimate, "se": 0.1, "t": estimate / 0.1,
            "df": networks - 2.0, "ci_low": estimate - 0.2, "ci_high": estimate + 0.2, "p": p,
            "networks": networks}  # fmt: skip


def exact(table, p=None) -> dict:
    p = fisher_exact(table)[1] if p is None else p
    return {"method": "exact", "table": table, "odds_ratio": None, "p": float(p)}


def in_family(effs: dict) -> dict:
    """``effs`` with every test that has a method in the robot's one family, as
    ``variant_effects`` leaves them: its name, its size and Holm's p over it (statsmodels)."""
    from statsmodels.stats.multitest import multipletests

    tests = [
        t for v in effs.values() for m in v.values() for t in m["tests"].values()
        if t["method"] != "none"
    ]  # fmt: skip
    for t in tests:
        for key in ("family", "family_size", "p_holm"):
            t.pop(key, None)
    adjusted = multipletests([t["p"] for t in tests], method="holm")[1]
    for t, p in zip(tests, adjusted, strict=True):
        t |= {"family": "exploration: robot", "family_size": len(tests), "p_holm": float(p)}
    return effs


#: The made-up variant's cells: success held 12, 8, 7 and 7 of 12 (congruent 20 of 24 held,
#: incongruent 14; large 19, small 15: the issue's counts); contact time touched in 11, 9, 11
#: and 9 of 12, 0.08 s longer when incongruent.
HELD = {"congruent_large": 12, "congruent_small": 8, "incongruent_large": 7, "incongruent_small": 7}
TOUCHED = {"congruent_large": 11, "congruent_small": 9, "incongruent_large": 11,
           "incongruent_small": 9}  # fmt: skip
SECONDS = {"congruent": 1.2, "incongruent": 1.28}


def effects(held: dict[str, int] = HELD) -> dict:
    """One variant, its counts from ``held`` (and ``TOUCHED``) and its tests in one family
    (``in_family``): success by contrast (congruency: incongruent minus congruent share held)
    and by the exact test (size, the issue's 19/24 vs 15/24); contact time by contrast
    (congruency, over the 8 networks that touched in all four cells) and not estimable (size);
    the interaction (twice the power-required share held minus the precision-required one, over
    the networks) by contrast for success and not estimable for contact time, which no factor's
    sentence reads."""
    success = measure(held)
    levels = {f: [success[f][level] for level in LEVELS[f]] for f in LEVELS}
    shares = {f: [x["mean"] for x in levels[f]] for f in LEVELS}
    power = held["congruent_large"] + held["incongruent_small"]
    precision = held["congruent_small"] + held["incongruent_large"]
    large, small = (round(x["mean"] * x["trials"]) for x in levels["size"])
    success["tests"] = {
        "congruency": contrast(shares["congruency"][1] - shares["congruency"][0], 0.02),
        "size": exact([[large, 24 - large], [small, 24 - small]]),
        "congruency:size": contrast((power - precision) / 12, 0.001),
    }
    contact = measure(TOUCHED, SECONDS)
    same = "every network that touched in all four cells shows the same contrast"
    contact["tests"] = {
        "congruency": contrast(SECONDS["incongruent"] - SECONDS["congruent"], 0.01, networks=8),
        "size": {"method": "none", "reason": same},
        "congruency:size": {"method": "none", "reason": same},
    }
    return in_family({"v": {"success": success, "contact_time": contact}})


def robot_trials(held: dict[str, int], touched: dict[str, int], seconds: dict[str, float]):
    """Robot trials that give ``measure``'s counts: 12 networks (0-5 mapping A, 6-11 B), two
    test sequences each; of each mapping's six, the first ``split(held)[object]`` hold the object
    and the first ``split(touched)[object]`` touch it, for ``seconds`` of its congruency."""
    import pandas as pd

    holds, touches = split(held), split(touched)
    rows = []
    for net in range(12):
        mapping, k = "AB"[net // 6], net % 6
        for name, (c, size, grip) in OBJECTS.items():
            if not name.startswith(mapping):
                continue
            for task in ("grasping", "categorisation"):
                cat = task == "categorisation"
                rows += [
                    {"run": "v", "network": net, "mapping": mapping, "task": task,
                     "object": name[2:], "size": size,
                     "congruent": str(c == "congruent") if cat else "", "target_grip": grip,
                     "sequence": seq, "success": k < holds[name] if cat else True,
                     "contact_time": seconds[c] if k < touches[name] or not cat else np.nan}
                    for seq in range(2)
                ]  # fmt: skip
    return pd.DataFrame(rows)


def test_the_made_up_counts_are_the_ones_variant_effects_writes():
    """The made-up variant's counts, per level, cell and object, are what
    ``embodied_stats.variant_effects`` counts in trials made to give them."""
    from icub_affordance.embodied_stats import variant_effects

    real = variant_effects(robot_trials(HELD, TOUCHED, SECONDS))["v"]
    made = {"success": measure(HELD), "contact_time": measure(TOUCHED, SECONDS)}
    for name, m in made.items():
        assert set(real[name]) == set(m) | {"networks", "contrasts", "tests"}
        assert real[name]["distinct_trials"] == m["distinct_trials"]
        for key in ("congruency", "size", "cells", "objects"):
            assert set(real[name][key]) == set(m[key]), (name, key)
            for part, counts in m[key].items():
                got = real[name][key][part]
                assert set(got) == set(counts), (name, key, part)
                assert {k: v for k, v in got.items() if k != "mean"} == {
                    k: v for k, v in counts.items() if k != "mean"
                }, (name, key, part)
                assert got["mean"] == pytest.approx(counts["mean"], nan_ok=True), (name, part)
        assert set(real[name]["tests"]) == set(effects()["v"][name]["tests"])
    # the made-up contrasts of success are the ones these counts give, one object per network
    # and cell (the size effect's is tested by Fisher's exact test in the made-up variant)
    for term in ("congruency", "congruency:size"):
        made_up = effects()["v"]["success"]["tests"][term]
        assert real["success"]["tests"][term]["estimate"] == pytest.approx(made_up["estimate"])


def test_the_made_up_counts_are_consistent():
    """Each level's counts are its two cells', each cell's its two objects' (one per mapping),
    and the tests' numbers are the counts'."""
    for name, m in effects()["v"].items():
        counted = "held" if name == "success" else "touched"
        assert m["distinct_trials"] == sum(o["trials"] for o in m["objects"].values()) == 48
        for cell, c in m["cells"].items():
            mine = [o for o in m["objects"].values() if f"{o['congruency']}_{o['size']}" == cell]
            assert len(mine) == 2 and c["trials"] == 12
            assert c[counted] == sum(o[counted] for o in mine)
        for factor, levels in LEVELS.items():
            for level in levels:
                cells = [c for k, c in m["cells"].items() if level in k.split("_")]
                assert m[factor][level]["trials"] == sum(c["trials"] for c in cells) == 24
                if name == "success":
                    held = sum(c["held"] for c in cells)
                    assert m[factor][level]["mean"] == pytest.approx(held / 24)
                else:
                    assert m[factor][level]["n"] == sum(c["touched"] for c in cells)
    success = effects()["v"]["success"]
    assert [success["size"][s]["mean"] * 24 for s in ("large", "small")] == [19, 15]
    assert success["tests"]["congruency"]["estimate"] == pytest.approx(14 / 24 - 20 / 24)
    assert success["tests"]["size"]["table"] == [[19, 5], [15, 9]]
    grips = {g: [o["held"] for o in success["objects"].values() if o["target_grip"] == g]
             for g in ("power", "precision")}  # fmt: skip
    assert [len(held) for held in grips.values()] == [4, 4]
    assert success["tests"]["congruency:size"]["estimate"] == pytest.approx(
        2 * (sum(grips["power"]) - sum(grips["precision"])) / 24
    )
    # every test with a method in the one family, Holm over its four
    tests = [t for m in effects()["v"].values() for t in m["tests"].values()]
    assert sorted(t["p_holm"] for t in tests if t["method"] != "none") == pytest.approx(
        [0.004, 0.03, 0.04, fisher_exact([[19, 5], [15, 9]])[1]]
    )


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
    assert (
        "per cell, congruent large 12/12, congruent small 8/12, incongruent large 7/12, "
        "incongruent small 7/12" in words
    )
    assert "Fisher's exact test, p = 0.341" in words
    assert "Holm-adjusted within the family" in words and "exploration: robot" in words
    assert "(4 tests) p = 0.341" in words
    # the same shares counted five times over: what the old summary tested
    assert fisher_exact([[95, 25], [75, 45]])[1] < 0.01


def test_a_contrast_claim_follows_its_sign_and_its_p():
    base = sentence(effects(), "best_success_congruency")
    assert base.startswith("as in the paper (") and "p = 0.020" in base  # congruent held more
    assert "held in 20 of 24 distinct congruent trials and 14 of 24 incongruent" in base
    assert "(4 tests) p = 0.040" in base  # significant after Holm over the robot's family
    flipped = effects()
    flipped["v"]["success"]["tests"]["congruency"] = contrast(+0.25, 0.02)
    assert sentence(in_family(flipped), "best_success_congruency").startswith(
        "the opposite of what the paper reports ("
    )
    weak = effects()
    weak["v"]["success"]["tests"]["congruency"] = contrast(-0.25, 0.07)
    # a direction is not claimed from a test that does not show it
    assert sentence(in_family(weak), "best_success_congruency").startswith("not shown (")
    # nor from a raw p below 0.05 that Holm over the family lifts above it
    lifted = effects()
    lifted["v"]["success"]["tests"]["congruency"] = contrast(-0.25, 0.03)
    words = sentence(in_family(lifted), "best_success_congruency")
    assert words.startswith("not shown (") and "p = 0.030" in words and "p = 0.060" in words
    # contact time: longer when incongruent is the paper's direction
    assert sentence(effects(), "best_contact_time_congruency").startswith("as in the paper (")
    faster = effects()
    faster["v"]["contact_time"]["tests"]["congruency"] = contrast(-0.08, 0.01, networks=8)
    assert sentence(in_family(faster), "best_contact_time_congruency").startswith("the opposite")


#: The same congruency counts (20 and 14 of 24 held), the sizes' swapped (15 large, 19 small)
#: or equal (19 and 19).
SWAPPED = {"congruent_large": 8, "congruent_small": 12, "incongruent_large": 7,
           "incongruent_small": 7}  # fmt: skip
SAME = {"congruent_large": 10, "congruent_small": 10, "incongruent_large": 9,
        "incongruent_small": 9}  # fmt: skip


def test_an_exact_claim_follows_its_counts_and_its_p():
    swapped = effects(SWAPPED)
    assert swapped["v"]["success"]["tests"]["size"]["table"] == [[15, 9], [19, 5]]
    swapped["v"]["success"]["tests"]["size"] = exact([[15, 9], [19, 5]], p=0.01)
    words = sentence(in_family(swapped), "best_success_size")
    assert words.startswith("the opposite of what the paper")
    assert "held in 15 of 24 distinct large trials and 19 of 24 small" in words
    swapped["v"]["success"]["tests"]["size"] = exact([[15, 9], [19, 5]])  # p = 0.341
    assert sentence(in_family(swapped), "best_success_size").startswith("not shown (")
    strong = effects()
    strong["v"]["success"]["tests"]["size"] = exact([[19, 5], [15, 9]], p=0.01)
    assert sentence(in_family(strong), "best_success_size").startswith("as in the paper (")
    same = effects(SAME)
    assert same["v"]["success"]["tests"]["size"]["table"] == [[19, 5], [19, 5]]
    words = sentence(same, "best_success_size")
    assert words.startswith("no difference") and "19 of 24 distinct large trials" in words
    values = pages._robot_effect_values(effects(), "v", "best")
    assert values["best_success_size_estimate"] == pytest.approx(15 / 24 - 19 / 24)


def test_an_effect_that_cannot_be_estimated_says_so():
    words = sentence(effects(), "best_contact_time_size")
    assert words.startswith("not estimable (")
    assert "every network that touched in all four cells shows the same contrast" in words
    assert "touched in 22 of 24 distinct large trials and 18 of 24 small" in words
    few = effects()
    few["v"]["contact_time"]["tests"]["size"] = {
        "method": "none",
        "reason": "2 network(s) touched in all four congruency x size cells, fewer than the "
        "three a test over networks needs",
    }
    assert "2 network(s)" in sentence(few, "best_contact_time_size")
    values = pages._robot_effect_values(effects(), "v", "best")
    assert values["best_contact_time_size_p"] != values["best_contact_time_size_p"]  # NaN
    assert values["best_contact_time_size_estimate"] != values["best_contact_time_size_estimate"]


def test_the_required_grip_term_and_the_misses_rest_on_the_cells_and_objects():
    """The congruency x size term (twice the required grip's difference) is stated within its
    family beside every cell's count, or not tested with its reason; the misses are named per
    object and mapping."""
    found = pages.traced({"grasping": pages._robot_effect_values(effects(), "v", "best")})
    page, claims = found["grasping"], found["claims"]["grasping"]
    assert claims["best_success_interaction"] == [
        "grasping.best_success_interaction_estimate",
        "grasping.best_success_interaction_p_holm",
    ]
    assert page["best_success_interaction_estimate"] == pytest.approx(1 / 3)
    assert page["best_success_interaction_p_holm"] == pytest.approx(0.004)
    words = page["best_success_interaction"]
    assert words.startswith("shown: +0.333") and "p = 0.001" in words and "p = 0.004" in words
    assert words.endswith(
        "(per cell, congruent large 12/12, congruent small 8/12, incongruent large 7/12, "
        "incongruent small 7/12)"
    )
    untested = page["best_contact_time_interaction"]
    assert untested.startswith(
        "not tested (per cell, congruent large 11/12, congruent small 9/12, "
        "incongruent large 11/12, incongruent small 9/12; every network"
    )
    assert np.isnan(page["best_contact_time_interaction_p_holm"])
    # within its family: a raw p that Holm lifts above 0.05 is not shown
    weak = effects()
    weak["v"]["success"]["tests"]["congruency:size"] = contrast(1 / 3, 0.045)
    words = pages._robot_effect_values(in_family(weak), "v", "best")["best_success_interaction"]
    assert words.text.startswith("not shown: +0.333")
    # the misses: held 12, 8, 7, 7 of 12 per cell, mapping A's the larger half of each cell
    assert page["best_misses"] == (
        "A big cube 2 of 6; A small ball 2 of 6; A small cube 2 of 6; B big ball 3 of 6; "
        "B small ball 2 of 6; B small cube 3 of 6"
    )
    every = effects({cell: 12 for cell in CELLS})
    assert pages._robot_effect_values(every, "v", "best")["best_misses"] == "none"


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
    from icub_affordance.embodied_stats import OWN_ROBOT_FAMILY

    # the own networks' robot tests as success_analysis writes them: a family of their own (the
    # same term twice here: congruency and size)
    term = contrast(err_estimate, err_p) | {
        "networks": 12,
        "family": OWN_ROBOT_FAMILY,
        "family_size": 2,
        "p_holm": min(1.0, 2 * err_p),
    }
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
        "beyond.emb_final_error_congruency_p_holm",
    ]
    # the verdict reads the p adjusted within the family, which is named
    assert "the config's own networks on the robot" in words["emb_final_error_congruency"]
    lifted = pages.traced({"beyond": pages._robot_values(analysis(+0.01, 0.04), own)})
    assert "did not differ significantly" in lifted["beyond"]["emb_err_sentence"]
    flipped = pages.traced({"beyond": pages._robot_values(analysis(-0.01, 0.02), own)})
    assert flipped["beyond"]["emb_err_sentence"].startswith("the arm ended nearer")
    weak = pages.traced({"beyond": pages._robot_values(analysis(+0.01, 0.2), own)})
    assert weak["beyond"]["emb_err_sentence"].endswith(
        "did not differ significantly between congruent and incongruent trials"
    )  # noqa: E501
    assert words["emb_success_congruency"] == sentence(effects(), "best_success_congruency")
    other = copy.deepcopy(own)
    other["success"]["tests"]["congruency"] = contrast(+0.25, 0.02)
    other = in_family({"v": other})["v"]
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
