"""The words study's declared tests (analysis.name_effects), recomputed independently: the t's
over replications, the two one-sided t's of the name's equivalence with the image, Holm over the
family, and the reactivation contrast from hidden states."""

from __future__ import annotations

import itertools

import numpy as np
import pandas as pd
import pytest
from conftest import load_config
from scipy import stats

from icub_affordance.analysis.name_effects import (
    FAMILY_DIFFERENCE,
    declared_tests,
    error_cells,
    form_summary,
    qualifiers,
    reactivation,
    reactivation_tests,
    word_tests,
)
from icub_affordance.analysis.statistics import holm
from icub_affordance.outcome import Outcome
from icub_affordance.vocabulary import FORMS

SEEDS = list(range(141, 151))


def estimates_of(effects) -> pd.DataFrame:
    """A table of replication estimates: ``effects(form, effect, rng)`` draws each seed's."""
    declaration = load_config()["words"]
    rng = np.random.default_rng(0)
    rows = []
    for cue, mode, measure, form, effect in itertools.product(
        declaration["cues"], declaration["modes"], declaration["measures"], FORMS,
        ("congruency", "size"),
    ):  # fmt: skip
        values = effects(form, effect, rng)
        for seed, value in zip(SEEDS, values, strict=True):
            rows.append({"cue": cue, "seed": seed, "run": f"r{seed}", "mode": mode,
                         "measure": measure, "form": form, "effect": effect,
                         "estimate": value})  # fmt: skip
    return pd.DataFrame(rows)


def test_the_family_is_every_declared_combination():
    declaration = load_config()["words"]
    tests = declared_tests(declaration)
    assert len(tests) == 2 * 2 * 2 * 3 == len({tuple(t.values()) for t in tests})


def test_names_tests_recomputed():
    """Names' congruency effect clearly positive and as large as the image's; size none."""
    declaration = load_config()["words"]

    def effects(form, effect, rng):
        if effect == "size":
            return rng.normal(0, 0.01, len(SEEDS))
        return 0.03 + rng.normal(0, 0.002, len(SEEDS))

    estimates = estimates_of(effects)
    table = word_tests(estimates, declaration)
    assert len(table) == 24 and (table["family_size"] == 24).all()
    # every p recomputed by scipy, then Holm by hand
    ps = []
    for row in table.itertuples():

        def values(form, effect, row=row):
            keys = {"cue": row.cue, "mode": row.mode, "measure": row.measure, "form": form,
                    "effect": effect}  # fmt: skip
            mask = np.logical_and.reduce([estimates[k] == v for k, v in keys.items()])
            return estimates[mask].sort_values("seed")["estimate"].to_numpy()

        if row.test == "equivalence":
            diff = values("name", "congruency") - values("image", "congruency")
            margin = declaration["margin"][row.measure]
            lower = stats.ttest_1samp(diff, -margin, alternative="greater").pvalue
            upper = stats.ttest_1samp(diff, margin, alternative="less").pvalue
            p = max(lower, upper)
            assert row.p_difference == pytest.approx(stats.ttest_1samp(diff, 0).pvalue)
        else:
            p = stats.ttest_1samp(values("name", row.test), 0).pvalue
        assert row.p == pytest.approx(p, rel=1e-9)
        ps.append(p)
    order = np.argsort(ps)
    holm = np.maximum.accumulate([ps[i] * (24 - k) for k, i in enumerate(order)])
    expected = np.empty(24)
    expected[order] = np.minimum(holm, 1)
    np.testing.assert_allclose(table["p_holm"], expected, rtol=1e-12)
    verdicts = table.groupby("test")["direction"].agg(set)
    assert verdicts["congruency"] == {Outcome.PAPER}
    assert verdicts["equivalence"] == {Outcome.PAPER}
    assert Outcome.PAPER not in verdicts["size"]


def test_a_names_effect_far_from_the_images_is_not_equivalent():
    declaration = load_config()["words"]

    def effects(form, effect, rng):
        base = 0.05 if form == "image" else 0.0
        return base + rng.normal(0, 0.002, len(SEEDS))

    table = word_tests(estimates_of(effects), declaration)
    rmse = table[(table["test"] == "equivalence") & (table["measure"] == "rmse_correct")]
    assert (rmse["direction"] == Outcome.NONE).all()
    assert (rmse["p_difference"] < 1e-6).all()


def test_an_undefined_replication_is_left_out_and_counted():
    declaration = load_config()["words"]
    estimates = estimates_of(lambda form, effect, rng: 0.02 + rng.normal(0, 0.01, len(SEEDS)))
    estimates.loc[estimates["seed"] == 141, "estimate"] = np.nan
    table = word_tests(estimates, declaration)
    assert (table["estimable"] == 9).all() and (table["not_estimable"] == 1).all()


def test_the_reactivation_contrast():
    """A name whose state is its object's image's: the mean distance to the other images; a name
    whose state is the same for every object: exactly 0; recomputed by loops."""
    rng = np.random.default_rng(3)
    trials = [(task, o, s) for task in range(2) for o in range(4) for s in range(5)]
    image = rng.uniform(0, 1, (len(trials), 10))
    assert reactivation(trials, image, image) > 0
    same = np.tile(rng.uniform(0, 1, 10), (len(trials), 1))
    assert reactivation(trials, same, image) == pytest.approx(0, abs=1e-12)
    name = rng.uniform(0, 1, (len(trials), 10))
    expected = []
    for task in range(2):

        def mean(states, o, task=task):
            return np.mean([states[i] for i, t in enumerate(trials) if t[:2] == (task, o)],
                           axis=0)  # fmt: skip

        for o in range(4):
            own = np.linalg.norm(mean(name, o) - mean(image, o))
            others = [np.linalg.norm(mean(name, o) - mean(image, q)) for q in range(4) if q != o]
            expected.append(np.mean(others) - own)
    assert reactivation(trials, name, image) == pytest.approx(np.mean(expected), rel=1e-12)


def test_the_reactivation_tests_are_per_cue_over_replications():
    declaration = load_config()["words"]
    rng = np.random.default_rng(4)
    rows = [
        {"cue": cue, "seed": seed, "network": net, "contrast": rng.normal(0.1, 0.05)}
        for cue in declaration["cues"] for seed in SEEDS for net in range(12)
    ]  # fmt: skip
    contrasts = pd.DataFrame(rows)
    table = reactivation_tests(contrasts, declaration)
    for row in table.itertuples():
        per_seed = contrasts[contrasts["cue"] == row.cue].groupby("seed")["contrast"].mean()
        assert row.p == pytest.approx(stats.ttest_1samp(per_seed, 0).pvalue, rel=1e-9)
    assert (table["direction"] == Outcome.PAPER).all()


def test_the_chapter_says_each_tests_verdict_in_its_own_words(tmp_path):
    """The book's words page: the name-alone tests in the confirmation's words, the equivalence
    in its own (equivalent / not shown equivalent), each count over the conditions, and every
    verdict resting on the numbers it came from."""
    from icub_workflow.book.names_page import score_rows, words_page
    from icub_workflow.book.pages import traced
    from icub_workflow.book.words import direction_codes

    config = load_config()

    def effects(form, effect, rng):
        return (0.03 if effect == "congruency" else 0.0) + rng.normal(0, 0.002, len(SEEDS))

    estimates = estimates_of(effects)
    table = word_tests(estimates, config["words"])
    forms = form_summary(estimates, config["words"])
    cells = pd.DataFrame([{"mode": "closed_loop", "form": "name", "congruent": "False",
                           "size": "small", "wrong_grip": 0.5, "cue": "first_step",
                           "seed": 141}])  # fmt: skip
    table["direction"] = direction_codes(table["direction"])
    table = qualifiers(table, forms, cells, float(config["words"]["alpha"]))
    contrasts = pd.DataFrame([{"cue": cue, "seed": s, "network": 0, "contrast": 0.1 + s / 1e4}
                              for cue in config["words"]["cues"] for s in SEEDS])  # fmt: skip
    react = reactivation_tests(contrasts, config["words"])
    react["direction"] = direction_codes(react["direction"])
    table.to_csv(tmp_path / "s.csv", index=False)
    react.to_csv(tmp_path / "r.csv", index=False)
    saved = {"summary": "s", "reactivation": "r"}
    inputs = {f"words_{name}.csv": tmp_path / f"{short}.csv" for name, short in saved.items()}
    values, tables = words_page(inputs, config)
    assert values["congruency_count"].text == "confirmed in 8 of 8"
    assert values["equivalence_count"].text == "equivalent in 8 of 8"
    assert values["react_first_step_verdict"].text == (
        "nearer its own object's image state than the others'"
    )
    assert values["react_verdict"].text == (
        "nearer its own object's image state than the others' under both cue timings"
    )
    assert len(tables["words"]) == 24
    said, rows = score_rows(values)
    assert [r["chapter"] for r in rows] == ["words"] * 3
    traced({"words": values, "index": said})  # every claim rests on values the page has


def test_the_error_cells_count_each_network_and_object_once():
    """A cell's wrong-grip rate: each network x object's mean over its trials, then the mean
    over networks; grasping trials left out."""
    rows = []
    for network, obj, size, congruent, wrong in [
        (0, "small_ball", "small", "False", [1, 1, 0, 0]),
        (1, "small_ball", "small", "False", [1, 1, 1, 1]),
        (0, "big_ball", "large", "True", [0, 0, 0, 0]),
    ]:
        rows += [{"task": "categorisation", "mode": "closed_loop", "form": "name",
                  "network": network, "object": obj, "size": size, "congruent": congruent,
                  "wrong_grip": w} for w in wrong]  # fmt: skip
    rows.append({"task": "grasping", "mode": "closed_loop", "form": "name", "network": 0,
                 "object": "small_ball", "size": "small", "congruent": "",
                 "wrong_grip": 1})  # fmt: skip
    cells = error_cells(pd.DataFrame(rows)).set_index(["congruent", "size"])["wrong_grip"]
    assert cells[("False", "small")] == pytest.approx((0.5 + 1.0) / 2)
    assert cells[("True", "large")] == 0
    assert len(cells) == 2


def test_what_qualifies_a_verdict_is_recomputed_beside_each_test():
    """name_effects.qualifiers, recomputed: an equivalence row carries the image's own
    congruency effect (the mean over replications) and whether it lies inside the margin, and
    whether the difference's unadjusted p is below alpha; a size row whether its estimate is the
    congruency test's number and whether the name's wrong grips all fall in the incongruent
    small cell (and made some). Here the image's effect is 0.002 (inside every margin), the
    name's size and congruency estimates are one number (both 0.03 + the same draws), and one
    cue timing's closed loop has a wrong grip in a congruent cell beside the incongruent small
    one's."""
    declaration = load_config()["words"]
    alpha = float(declaration["alpha"])
    draws = np.random.default_rng(7).normal(0, 0.002, len(SEEDS))

    def effects(form, effect, rng):
        return (0.002 if form == "image" else 0.03) + draws

    estimates = estimates_of(effects)
    forms = form_summary(estimates, declaration)
    cells = pd.DataFrame([
        {"mode": "closed_loop", "form": "name", "congruent": "False", "size": "small",
         "wrong_grip": 0.4, "cue": "first_step", "seed": 141},
        {"mode": "closed_loop", "form": "name", "congruent": "True", "size": "large",
         "wrong_grip": 0.1, "cue": "first_step", "seed": 141},
        {"mode": "closed_loop", "form": "image", "congruent": "True", "size": "small",
         "wrong_grip": 0.3, "cue": "all_steps", "seed": 141},
    ])  # fmt: skip
    tests = word_tests(estimates, declaration)
    table = qualifiers(tests, forms, cells, alpha)
    assert list(table.columns[: len(tests.columns)]) == list(tests.columns)
    # the congruent cell's wrong grip removed: first_step's closed loop errs only where it should
    alone = qualifiers(tests, forms, cells.drop(index=1), alpha)
    alone = alone[alone["test"] == "size"].set_index(["cue", "mode", "measure"])
    assert alone["only_incongruent_small"].tolist() == [
        cue == "first_step" and mode == "closed_loop" for cue, mode, _ in alone.index
    ]
    image_mean = float(np.mean(0.002 + draws))
    for _, row in table.iterrows():
        if row["test"] == "equivalence":
            assert row["image_effect"] == pytest.approx(image_mean, abs=1e-12)
            assert row["image_inside_margin"] == (abs(image_mean) < row["margin"])
            assert row["difference_below_alpha"] == (row["p_difference"] < alpha)
            assert pd.isna(row["same_as_congruency"])
        elif row["test"] == "size":
            assert row["same_as_congruency"] is True
            # wrong grips, all incongruent and small: nowhere (first_step's closed loop has one
            # in a congruent cell too; the other conditions none at all)
            assert row["only_incongruent_small"] is False
            assert pd.isna(row["image_effect"])
        else:
            assert table.loc[[_], list(table.columns[len(tests.columns) :])].isna().all(axis=None)
    # the differences' own t's, Holm over the equivalence rows, in a family added after results
    shown = table[table["test"] == "equivalence"]
    assert shown["p_difference_holm"].astype(float).tolist() == pytest.approx(
        holm(shown["p_difference"].to_numpy(float)).tolist(), nan_ok=True
    )
    assert set(shown["difference_family"].dropna()) <= {FAMILY_DIFFERENCE}
    assert "added after results" in FAMILY_DIFFERENCE
