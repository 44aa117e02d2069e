"""The robot's effect sentences (issue 24): each is a ``text.Claim`` resting on the statistics
stored beside it, and changing a statistic (its sign, its p across 0.05, its counts) changes the
sentence accordingly. Made-up effects, in the shape ``robot_effects.variant_effects`` writes."""

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


@pytest.mark.heavy
def test_the_made_up_counts_are_the_ones_variant_effects_writes():
    """The made-up variant's counts, per level, cell and object, are what
    ``robot_effects.variant_effects`` counts in trials made to give them."""
    from icub_affordance.analysis.robot_effects import variant_effects

    real = variant_effects(robot_trials(HELD, TOUCHED, SECONDS))["v"]
    made = {"success": measure(HELD), "contact_time": measure(TOUCHED, SECONDS)}
    for name, m in made.items():
        assert set(real[name]) == set(m) | {"networks", "contrasts", "tests", "simple"}
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


def verdict(effs: dict, name: str) -> str:
    """The best variant's verdict ``name`` (``pages._best_effects``), a claim resting on the
    values stored beside it."""
    values = pages._best_effects(effs["v"])
    claim = values[name]
    assert isinstance(claim, text.Claim)
    for entry in claim.rests_on:  # every entry names a value stored beside the verdict
        page, key = entry.split(".", 1)
        assert page == "robot_test" and key in values, entry
    return claim.text


def rows(effs: dict) -> dict[tuple[str, str], dict]:
    """The effects table's rows of the made-up variant, by (measure, effect)."""
    shown, _cells = pages._effect_rows(effs["v"])
    return {(r["measure"], r["effect"]): r for r in shown}


def approx(row: dict, **expected) -> bool:
    """The row's numbers as the analysis wrote them (NaN: none)."""
    return all(
        np.isnan(row[k]) if v is None else row[k] == pytest.approx(v, abs=0.005)
        for k, v in expected.items()
    )


@pytest.mark.heavy
def test_the_issues_size_effect_counted_once_is_not_significant():
    # the constant-rate all_steps variant's size effect, counted once per network and object
    assert fisher_exact([[19, 5], [15, 9]])[1] == pytest.approx(0.34, abs=0.005)
    assert verdict(effects(), "best_success_size") == "not shown"
    row = rows(effects())["held", "size"]
    assert row["test"] == "Fisher" and approx(row, p=0.34, p_holm=0.34)
    assert approx(row, estimate=-0.167)  # 15/24 - 19/24, the shares' difference
    # the same shares counted five times over: what the old summary tested
    assert fisher_exact([[95, 25], [75, 45]])[1] < 0.01


@pytest.mark.heavy
def test_a_contrast_verdict_follows_its_sign_and_its_adjusted_p():
    assert verdict(effects(), "best_success_congruency") == "confirmed"  # congruent held more
    row = rows(effects())["held", "congruency"]
    assert row["test"] == "t, 12 nets" and approx(row, p=0.02, p_holm=0.04)
    flipped = effects()
    flipped["v"]["success"]["tests"]["congruency"] = contrast(+0.25, 0.02)
    assert verdict(in_family(flipped), "best_success_congruency") == "reversed"
    weak = effects()
    weak["v"]["success"]["tests"]["congruency"] = contrast(-0.25, 0.07)
    # a direction is not claimed from a test that does not show it
    assert verdict(in_family(weak), "best_success_congruency") == "not shown"
    # nor from a raw p below 0.05 that Holm over the family lifts above it
    lifted = effects()
    lifted["v"]["success"]["tests"]["congruency"] = contrast(-0.25, 0.03)
    assert verdict(in_family(lifted), "best_success_congruency") == "not shown"
    assert approx(rows(in_family(lifted))["held", "congruency"], p_holm=0.06)
    # contact time: longer when incongruent is the paper's direction
    assert verdict(effects(), "best_contact_time_congruency") == "confirmed"
    faster = effects()
    faster["v"]["contact_time"]["tests"]["congruency"] = contrast(-0.08, 0.01, networks=8)
    assert verdict(in_family(faster), "best_contact_time_congruency") == "reversed"
    values = pages._best_effects(effects()["v"])
    assert values["best_success_congruency_estimate"] == pytest.approx(14 / 24 - 20 / 24)
    assert values["best_success_congruency_p"] == pytest.approx(0.04)  # the p the verdict reads


#: The same congruency counts (20 and 14 of 24 held), the sizes' swapped (15 large, 19 small)
#: or equal (19 and 19).
SWAPPED = {"congruent_large": 8, "congruent_small": 12, "incongruent_large": 7,
           "incongruent_small": 7}  # fmt: skip
SAME = {"congruent_large": 10, "congruent_small": 10, "incongruent_large": 9,
        "incongruent_small": 9}  # fmt: skip


@pytest.mark.heavy
def test_an_exact_verdict_follows_its_counts_and_its_p():
    swapped = effects(SWAPPED)
    assert swapped["v"]["success"]["tests"]["size"]["table"] == [[15, 9], [19, 5]]
    swapped["v"]["success"]["tests"]["size"] = exact([[15, 9], [19, 5]], p=0.01)
    assert verdict(in_family(swapped), "best_success_size") == "reversed"
    swapped["v"]["success"]["tests"]["size"] = exact([[15, 9], [19, 5]])  # p = 0.341
    assert verdict(in_family(swapped), "best_success_size") == "not shown"
    strong = effects()
    strong["v"]["success"]["tests"]["size"] = exact([[19, 5], [15, 9]], p=0.01)
    assert verdict(in_family(strong), "best_success_size") == "confirmed"
    # equal shares are not shown to differ: only an equivalence test says "no difference"
    same = effects(SAME)
    assert same["v"]["success"]["tests"]["size"]["table"] == [[19, 5], [19, 5]]
    assert verdict(same, "best_success_size") == "not shown"
    values = pages._best_effects(effects()["v"])
    assert values["best_success_size_estimate"] == pytest.approx(15 / 24 - 19 / 24)


@pytest.mark.heavy
def test_an_effect_that_cannot_be_estimated_says_so():
    assert verdict(effects(), "best_contact_time_size") == "not assessable"
    row = rows(effects())["contact, s", "size"]
    assert row["test"] == "none" and approx(row, estimate=None, p=None, p_holm=None)
    values = pages._best_effects(effects()["v"])
    assert np.isnan(values["best_contact_time_size_p"])
    assert np.isnan(values["best_contact_time_size_estimate"])


@pytest.mark.heavy
def test_the_required_grip_term_and_the_misses_rest_on_the_cells_and_objects():
    """The congruency x size term (twice the required grip's difference) is shown or not within
    its family, or not tested; the counts per cell and the misses per object stand beside it."""
    found = pages.traced({"robot_test": pages._best_effects(effects()["v"])})
    page, claims = found["robot_test"], found["claims"]["robot_test"]
    assert claims["best_success_interaction"] == [
        "robot_test.best_success_interaction_estimate",
        "robot_test.best_success_interaction_p",
    ]
    assert page["best_success_interaction_estimate"] == pytest.approx(1 / 3)
    assert page["best_success_interaction_p"] == pytest.approx(0.004)
    assert page["best_success_interaction"] == "confirmed"
    assert page["best_contact_time_interaction"] == "not assessable"
    assert np.isnan(page["best_contact_time_interaction_p"])
    weak = effects()
    weak["v"]["success"]["tests"]["congruency:size"] = contrast(1 / 3, 0.045)
    assert verdict(in_family(weak), "best_success_interaction") == "not shown"
    _rows, cells = pages._effect_rows(effects()["v"])
    assert cells[0] == {"variant": "", "measure": "held", "cong. large": "12/12",
                        "cong. small": "8/12",
                        "incong. large": "7/12", "incong. small": "7/12"}  # fmt: skip
    assert cells[1]["measure"] == "touched" and cells[1]["incong. small"] == "9/12"
    # the misses: held 12, 8, 7, 7 of 12 per cell, mapping A's the larger half of each cell
    assert page["best_misses"] == (
        "A big cube 2 of 6; A small ball 2 of 6; A small cube 2 of 6; B big ball 3 of 6; "
        "B small ball 2 of 6; B small cube 3 of 6"
    )
    every = effects({cell: 12 for cell in CELLS})
    assert pages._best_effects(every["v"])["best_misses"] == "none"
    assert page["robot_family"] == "exploration: robot" and page["robot_family_size"] == 4


def test_a_variant_is_named_in_short_words():
    row = {"categorisation_cue": "all_steps", "target": "commands", "hidden": 40,
           "iterations": 768000, "learning_rate_schedule": "anneal"}  # fmt: skip
    assert pages.short_label(row) == "all · cmd · h40 · 768k · anneal"
    own = row | {"categorisation_cue": "first_step", "target": "sensed", "hidden": 10,
                 "iterations": 12000, "learning_rate_schedule": "constant"}  # fmt: skip
    assert pages.short_label(own) == "first · sens · h10 · 12k · const"
    assert pages.short_label(row, ("categorisation_cue",)) == "cmd · h40 · 768k · anneal"


def analysis(err_estimate: float, err_p: float, categorisation: float = 0.4) -> dict:
    from icub_affordance.analysis.robot_effects import OWN_ROBOT_FAMILY

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


@pytest.mark.heavy
def test_the_chapter_beyond_states_the_robots_effects_from_their_tests():
    own = effects()["v"]
    found = pages.traced({"beyond": pages._robot_values(analysis(+0.01, 0.02), own)})
    words = found["beyond"]
    assert words["emb_n_trials"] == 96
    assert words["emb_final_error_congruency_verdict"] == "larger when incongruent"
    assert found["claims"]["beyond"]["emb_final_error_congruency_verdict"] == [
        "beyond.emb_final_error_congruency_estimate",
        "beyond.emb_final_error_congruency_p_holm",
    ]
    # the verdict reads the p adjusted within the family, which is named
    assert (
        words["emb_final_error_congruency_family"]
        == "exploration: the config's own networks on the robot"
    )
    lifted = pages.traced({"beyond": pages._robot_values(analysis(+0.01, 0.04), own)})
    assert lifted["beyond"]["emb_final_error_congruency_verdict"] == "not shown to differ"
    flipped = pages.traced({"beyond": pages._robot_values(analysis(-0.01, 0.02), own)})
    assert flipped["beyond"]["emb_final_error_congruency_verdict"] == "smaller when incongruent"
    assert flipped["beyond"]["emb_final_error_size_verdict"] == "smaller for small objects"
    assert words["emb_success_verdict"] == verdict(effects(), "best_success_congruency")
    other = copy.deepcopy(own)
    other["success"]["tests"]["congruency"] = contrast(+0.25, 0.02)
    other = in_family({"v": other})["v"]
    changed = pages.traced({"beyond": pages._robot_values(analysis(+0.01, 0.02), other)})
    assert changed["beyond"]["emb_success_verdict"] == "reversed"
    assert found["claims"]["beyond"]["emb_success_verdict"] == [
        "beyond.emb_success_estimate",
        "beyond.emb_success_p",
    ]
    # the floor follows its rate
    assert words["emb_floor"] == "clear of the floor"
    low = pages.traced({"beyond": pages._robot_values(analysis(0.01, 0.02, 0.05), own)})
    assert low["beyond"]["emb_floor"].startswith("near the floor")
    assert words["suc_diff_mean"] == pytest.approx(-0.1)
    assert words["replay_wrong_grip_holds_commands"] == 1 and words["replay_trials_commands"] == 40


@pytest.mark.heavy
def test_an_effect_one_cell_carries_is_named_as_that_cell_and_follows_a_swap():
    """Holding fails in one cell only (1 of 12 held, every other cell 11 of 12): size's and
    congruency's effects are that cell's, so the chapter names the cell, not an effect; swap
    that cell's count with another's and the words follow the cell (issue 60)."""
    from icub_affordance.analysis.robot_effects import variant_effects

    def words(held: dict[str, int]) -> dict[str, str]:
        effs = variant_effects(robot_trials(held, TOUCHED, SECONDS))
        values = pages._best_effects(effs["v"])
        return {k: values[f"best_success_{k}"].text for k in ("size", "congruency")}

    held = dict.fromkeys(CELLS, 11) | {"incongruent_small": 1}
    said = words(held)
    assert (
        said["size"]
        == said["congruency"]
        == ("one cell: a power grip on the small objects, held less often")
    )
    swapped = held | {"incongruent_small": 11, "congruent_small": 1}
    said = words(swapped)
    assert (
        said["size"]
        == said["congruency"]
        == ("one cell: a precision grip on the small objects, held less often")
    )
    # no single cell (two cells fail): the effect keeps its word
    two = dict.fromkeys(CELLS, 11) | {"incongruent_small": 1, "congruent_small": 1}
    assert not words(two)["size"].startswith("one cell")
