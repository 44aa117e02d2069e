"""What each page of the book shows, from the pipeline's outputs: the values a page glues
(``findings.json``, one entry per page) and the tables it shows. Statistics and verdicts are the
package's (``icub_affordance``); the words are ``text``'s; the pages hold the prose."""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path

import numpy as np
import pandas as pd

from icub_affordance.analysis import confirmation as confirmation_science
from icub_affordance.analysis import reading_tests as readings_science
from icub_affordance.analysis import verdicts as science
from icub_affordance.analysis.decide import significant
from icub_affordance.analysis.robot_effects import FACTOR_LEVELS, INTERACTION, record_table
from icub_affordance.analysis.size_study import (
    FAMILY_MOTOR_ADDED,
    FAMILY_MOTOR_PLANNED,
    FAMILY_TRAJECTORY,
    FINAL_POSTURE,
    SIZE_LARGER,
    TRAJECTORY,
    ranked_like_size,
)
from icub_affordance.analysis.trial_effects import WITHIN
from icub_affordance.files import load_npz
from icub_affordance.learning.maps import active_units
from icub_affordance.learning.variants import NetworkVariant
from icub_affordance.outcome import Outcome
from icub_affordance.trials.scores import margin_measure
from icub_affordance.vocabulary import MODES
from icub_workflow.runs import MAIN

from . import text, words
from .names_page import score_rows, words_page
from .scorecard import claims_values, scorecard, signature_result, signature_scale


def _json(path) -> dict:
    return json.loads(Path(path).read_text())


def main_tests(anova: dict, curve: dict, demos: dict, cue: str) -> dict:
    """The config's own run, named once for every page that states it: the learning curve, the
    cell means, and each test as ``<mode>_[errors_|rt_]<effect>`` (the paper's measure, the
    wrong-grip rate, the correct-trial RMSE) or ``<mode>_<simple effect>``, with its verdict."""
    gap = science.grip_distance(demos["angles"], demos["objects"].tolist())
    out = {"rmse_start": curve["start"], "rmse_2000": curve["around_at"], "at_2000": curve["at"],
           "rmse_phase1_end": curve["phase1_end"], "rmse_end": curve["end"],
           "n_networks": curve["n_networks"], "cue": text.CUES[cue],
           "grip_distance_large": gap["large"], "grip_distance_small": gap["small"],
           "df": anova["contrasts"]["closed_loop"]["congruency"]["df"]}  # fmt: skip
    for mode in MODES:
        m = anova[mode]
        wrong = m["wrong_grip_rate"] | science.wrong_grip_by_congruency(m["wrong_grip_rate"])
        out |= {f"{mode}_{key}": value for key, value in m["means"].items()}
        out |= {f"{mode}_wrong_{key}": value for key, value in wrong.items()}
        out |= {f"{mode}_correct_{key}": value for key, value in m["means_correct"].items()}
        sources = (("", "contrasts", anova["contrasts"][mode]), ("errors_", "errors", m["errors"]),
                   ("rt_", "correct_rt", m["correct_rt"]))  # fmt: skip
        for prefix, outcome, tests in sources:
            for effect in WITHIN:
                name = f"{mode}_{prefix}{effect.replace('congruency:size', 'grip')}"
                said = lambda t, o=outcome, e=effect: words.claim_verdict(t, o, e)  # noqa: E731
                out |= text.test_values("tests", name, tests[effect], said)
        for name, term in anova["simple"][mode].items():
            out |= text.test_values("tests", f"{mode}_{name}", term)  # the paper's direction
    return out


# -- which reading reproduces the paper ---------------------------------------------------------


def _holm(row, column: str = "p_holm") -> str:
    """A Holm p (2 significant digits), or why the row has none."""
    if np.isfinite(row[column]):
        return f"{row[column]:.2g}"
    if not np.isfinite(row["diff"]):
        return words.NOT_ASSESSABLE
    if readings_science.is_hypothesis(row["measure"]):
        return "identical" if str(row.get("identical")) == "True" else "constant"
    return "not a hypothesis" if readings_science.is_null_control(row["measure"]) else "by excess"


def _family(table: pd.DataFrame, column: str = "family", p: str = "p_holm") -> str:
    """The one family a table's adjusted p are Holm-adjusted within (``readings.FAMILY_*``)."""
    tested = table[p].map(np.isfinite) & table["measure"].map(readings_science.is_hypothesis)
    (family,) = set(table.loc[tested, column])
    return family


def _shown(table: pd.DataFrame, test, said: Mapping) -> pd.DataFrame:
    """The readings' tests with what the page shows beside their numbers: the reading's name, the
    verdict word (``test``'s code in ``said``'s words; "not assessable": too few
    replications answered, never tested), why no Holm p."""
    compared = "comparison" in table
    verdicts = table.apply(test, axis=1).map(lambda code: said.get(code, code))
    verdicts = verdicts.where(table["measure"].map(readings_science.is_hypothesis), "")
    named = table[["comparison", "at"] if compared else ["cue", "goal_response"]]
    return table.assign(
        named=named.replace(text.CUE_LABELS).agg(" · ".join, axis=1),
        label=table["measure"].map(text.MEASURE_LABELS), holm=table.apply(_holm, axis=1),
        hypothesis=table["measure"].map(readings_science.is_hypothesis),
        verdict=verdicts.where(table["diff"].notna(), words.NOT_ASSESSABLE))  # fmt: skip


def readings(inputs: Mapping[str, str], config: dict) -> tuple[dict, dict[str, pd.DataFrame]]:
    """The readings chapter: the Goal map's clusters under each response, the statistics of the
    readings and of their differences, the verdict phrases on them, and the tables."""
    summary = pd.read_csv(inputs["readings_summary.csv"])
    diffs = pd.read_csv(inputs["readings_differences.csv"], keep_default_na=False, na_values=[""])
    values = {}
    for response, name in (("fixed", "soms.npz"), ("grows", "readings_grows_soms.npz")):
        soms = load_npz(inputs[name]) if name in inputs else None
        for o, obj in enumerate([] if soms is None else soms["objects"].tolist()):
            for t, task in enumerate(soms["tasks"].tolist()):
                values[f"goal_{response}_{obj}_{task}"] = active_units(soms["goal_act"][o, t])
    for table in (summary, diffs):  # the statistics the claims rest on (None: there is none)
        for _, row in table.iterrows():
            for stat in (s for s in ("diff", "p_holm", "p_equivalence_holm") if s in row):
                values[text.stat_key(row, stat)] = row[stat] if np.isfinite(row[stat]) else None
    values |= {
        "n_readings": int(summary["reading"].nunique()),
        "replications": " to ".join(map(str, sorted(set(summary["replications"])))),
        "n_hypotheses": int(np.isfinite(summary["p_holm"]).sum()),
        "n_differences": int(np.isfinite(diffs["p_holm"]).sum()),
        "n_equivalence": int(np.isfinite(diffs["p_equivalence_holm"]).sum()),
        "family": _family(summary), "family_differences": _family(diffs),
        "family_equivalence": _family(diffs, "family_equivalence", "p_equivalence_holm"),
    }  # fmt: skip
    shown = _shown(summary, readings_science.direction, words.READING_WORDS)
    compared = _shown(diffs, readings_science.difference_verdict, words.DIFFERENCE_WORDS)
    after = {m for m, d in config["readings"]["margin_declared"].items() if d["results_before"]}
    late = (compared["verdict"] == "equivalent") & compared["measure"].map(
        lambda m: margin_measure(m) in after)  # fmt: skip
    compared.loc[late, "verdict"] = words.AFTER_RESULTS
    values |= text.reading_claims(shown) | text.difference_claims(compared, "cue_timing", "cue")
    values |= text.difference_claims(compared, "goal_response", "goal")
    tost = diffs.apply(_holm, axis=1, column="p_equivalence_holm").where(
        diffs["margin"].notna(), "–")  # fmt: skip
    tost += diffs["margin"].map(" (±{:g})".format).where(diffs["p_equivalence_holm"].notna(), "")
    also = _also_confirmatory(summary, pd.read_csv(inputs["claims_summary.csv"]), config)
    return values, {"readings_summary": shown.assign(also_in=also),
                    "readings_differences": compared.assign(tost=tost)}  # fmt: skip


def _also_confirmatory(summary: pd.DataFrame, claims: pd.DataFrame, config: dict) -> pd.Series:
    """Each reading's test that is also one of the confirmatory family (the same replications:
    the config's Goal response, closed loop, a declared measure and effect): that family's
    verdict and Holm p, which the book reads; empty for the others."""
    keyed = claims[claims["mode"] == "closed_loop"].set_index(["cue", "measure", "effect"])
    goal = config["soms"]["goal_response"]

    def said(row) -> str:
        key = (row["cue"], row["measure"], row["effect"])
        if row["goal_response"] != goal or key not in keyed.index:
            return ""
        test = keyed.loc[key]
        return (f"confirmatory family: {words.CLAIM_WORDS[test['direction']]}, Holm p "
                f"{test['p_holm']:.2g} (the verdict the book reads)")  # fmt: skip

    return summary.apply(said, axis=1)


# -- the robot: the chapters beyond (robot test, cue, hidden layer) and grasping ---------------

#: A variant's settings in the robot tables' short words (the robot test chapter's legend).
SHORT = {"categorisation_cue": {"first_step": "first", "all_steps": "all"},
         "target": {"sensed": "sens", "commands": "cmd"},
         "learning_rate_schedule": {"constant": "const", "anneal": "anneal"}}  # fmt: skip
ROBOT_MEASURES = (("success", "held", "held"), ("contact_time", "touched", "contact, s"))
EFFECT_NAMES = {"congruency": "congruency", "size": "size", INTERACTION: "cong. × size"}
#: The family of the cue difference at one seed, when the readings replicate it over seeds.
FAMILY_NONE = "none: one test at one seed, unadjusted; the readings replicate it"


def short_label(row: Mapping, leave_out: tuple[str, ...] = ()) -> str:
    """A variant in short words, e.g. ``all · cmd · h40 · 768k · anneal``."""
    v = NetworkVariant.from_row(row).row()
    short = {k: SHORT[k].get(v[k], v[k]) for k in SHORT}
    short |= {"hidden": f"h{int(v['hidden'])}", "iterations": f"{int(v['iterations']) / 1000:g}k"}
    return " · ".join(short[k] for k in NetworkVariant.keys() if k not in leave_out)


def _misses(counts: Mapping[str, tuple[int, int]]) -> str:
    """The trials not held, per object: ``counts`` is {object: (held, trials)}."""
    missed = [f"{k.replace('_', ' ')} {t - h} of {t}" for k, (h, t) in counts.items() if h < t]
    return "; ".join(missed) or "none"


def robot_verdict(effect: dict, measure: str, factor: str) -> str:
    """One robot effect against the paper (Holm within the robot's family); the congruency x
    size term, with no paper direction, is "confirmed" or not where a contrast tests it. A shown
    effect that one cell carries (``carrying_cell``) is named as that cell, not as an effect."""
    test = effect["tests"][factor]
    if factor == INTERACTION:
        word = words.shown_word(test) if test["method"] == "contrasts" else words.NOT_ASSESSABLE
    else:
        verdict = science.robot_effect_verdict(effect, measure, factor)
        if verdict is None or not verdict.significant:
            return words.robot_word(None if verdict is None else verdict.paper_direction, False)
        word = words.robot_word(verdict.paper_direction, True)
    cell = carrying_cell(effect)
    if cell is None or word not in (words.CONFIRMED, words.REVERSED):
        return word
    others = [c["mean"] for name, c in effect["cells"].items() if name != cell]
    return text.one_cell(cell, measure, effect["cells"][cell]["mean"] < np.nanmean(others))


def carrying_cell(effect: dict) -> str | None:
    """The congruency x size cell that carries a measure's effects, if one does: size's effect
    is shown (Holm within the four simple effects) within one congruency level only and
    congruency's within one size only, so the two meet in one cell ("incongruent_small"); None
    otherwise, or without simple effects (``robot_effects.variant_effects``)."""
    simple = effect.get("simple") or {}
    shown = [k for k, t in simple.items() if significant(t["p_holm"])]
    size_in = [k.removeprefix("size_in_") for k in shown if k.startswith("size_in_")]
    congruency_in = [k.removeprefix("congruency_in_") for k in shown if k.startswith("congr")]
    if len(size_in) == 1 and len(congruency_in) == 1:
        return f"{size_in[0]}_{congruency_in[0]}"
    return None


def divergence_verdict(first: int | None) -> text.Claim:
    """The hidden layer's lasting conflict (per-step paired tests, Holm over the steps)."""
    lasting = "not at every step to the last (no lasting conflict shown)"
    lasting = lasting if first is None else f"at every step from step {first} to the last"
    return text.Claim(lasting, ("beyond.div_first_step",))


def _robot_values(emb: dict, own: dict) -> dict:
    """The robot test's numbers (``embodied/analysis.json``; ``own`` the config's own networks'
    ``effects.json`` entry), every count over distinct trials, and its verdicts."""
    out = {f"emb_{k}": v for k, v in emb.items() if not isinstance(v, dict)}
    suc, err = emb["measures"]["success"], emb["measures"]["final_error"]
    records = {k: emb[k] for k in ("replay_success", "replay_trials", "replay_wrong_grip_holds")}
    records |= {
        "suc": suc["means"],
        "err": err["means"],
        "suc_diff": suc["incongruent_minus_congruent"],
    }
    out |= {f"{name}_{k}": v for name, record in records.items() for k, v in record.items()}
    stats = science.robot_effect_statistics(own["success"], "congruency")
    out |= {f"emb_success_{k}": v for k, v in stats.items()}
    out["emb_success_family"] = own["success"]["tests"]["congruency"].get("family", "none")
    out["emb_success_verdict"] = text.Claim(
        robot_verdict(own["success"], "success", "congruency"),
        ("beyond.emb_success_estimate", "beyond.emb_success_p"),
    )
    floor = science.robot_verdicts(emb)["at_floor"]  # fmt: skip
    out["emb_floor"] = text.Claim(
        "near the floor, so it can say little about congruency" if floor else "clear of the floor",
        ("beyond.emb_categorisation_success",),
    )
    for effect, where in (("congruency", "when incongruent"), ("size", "for small objects")):
        phrases = {words.CONFIRMED: f"larger {where}", words.REVERSED: f"smaller {where}",
                   words.NOT_SHOWN: "not shown to differ"}  # fmt: skip
        term = (err["contrasts"] or {}).get(effect) or {}
        out |= text.test_values("beyond", f"emb_final_error_{effect}", term, words=phrases)
    return out


def beyond(inputs: Mapping[str, str], config: dict, ablation_cue: str) -> tuple[dict, dict]:
    """The robot test, the cue ablation and the hidden layer."""
    cues = {"main": config["network"]["categorisation_cue"], "ablation": ablation_cue}
    first = _json(inputs["divergence.json"])["first_divergent_step"]
    out = {f"{name}_cue_phrase": text.CUES[cue] for name, cue in cues.items()} | {
        "n_predicted": config["demos"]["steps"] - 1, "n_hidden": config["network"]["hidden"],
        "pca_explained": science.explained_by_two_axes(pd.read_csv(inputs["hidden_explained.csv"])),
        "div_first_step": np.nan if first is None else first,
        "div_verdict": divergence_verdict(first),
    }  # fmt: skip
    out |= _robot_values(_json(inputs["robot_analysis.json"]),
                         _json(inputs["robot_effects.json"])[MAIN])  # fmt: skip
    for name in cues:
        result = _json(inputs["anova.json" if name == "main" else "ablation_anova.json"])
        means = {f"cue_{name}_{k}": v for k, v in result["closed_loop"]["means"].items()}
        out |= text.test_values("beyond", f"cue_{name}", result["contrasts"]["closed_loop"][
            "congruency"]) | means  # fmt: skip
    # the test of the difference, first step only minus every step, paired by network; its
    # adjusted p is the readings' table's where that row is this very test (one replication)
    difference = _json(inputs["cue_difference.json"])["congruency"]
    row = pd.read_csv(inputs["readings_differences.csv"]).query(
        "comparison == 'cue_timing' & measure == 'rmse' & effect == 'congruency' & at == "
        "@goal_response & replications == 1", local_dict=config["soms"])  # fmt: skip
    difference |= (row[["p_holm", "family"]].to_dict("records") or [{"family": FAMILY_NONE}])[0]
    out |= {f"cue_difference_{k}": difference[k] for k in ("df", "t")}
    phrases = {words.CONFIRMED: "larger with the cue at the first step only",
               words.REVERSED: "larger with the cue at every step",
               words.NOT_SHOWN: "not shown to differ between the timings"}  # fmt: skip
    out |= text.test_values("beyond", "cue_difference", difference, words=phrases)
    p, family = out["cue_difference_p_holm"], out["cue_difference_family"]
    out["cue_difference_p_words"] = (
        f"Holm p {p:.2g} within “{family}”" if family != FAMILY_NONE
        else f"p {p:.2g}, one test at one seed in no family (the readings' chapter tests the "
        "difference over the replications)")  # fmt: skip
    return out, {}


def _effect_rows(effects: dict, label: str = "") -> tuple[list[dict], list[dict]]:
    """A variant's robot effects (``effects.json``): per measure and term the test, the difference
    and the p its verdict reads (``verdicts.robot_effect_statistics``); its counts per cell."""
    rows, cells = [], []
    for measure, counted, shown in ROBOT_MEASURES:
        named = {k.replace("ongruent_", "ong. "): c for k, c in effects[measure]["cells"].items()}
        cells.append({"variant": label, "measure": counted}
                     | {k: f"{c[counted]}/{c['trials']}" for k, c in named.items()})  # fmt: skip
        for factor in (*FACTOR_LEVELS, INTERACTION):
            test = dict.fromkeys(("estimate", "ci_low", "ci_high", "p", "p_holm"), np.nan)
            test |= effects[measure]["tests"][factor]
            reads = {"estimate": test["estimate"], "p": test["p_holm"]}  # the interaction's
            if factor != INTERACTION:
                reads = science.robot_effect_statistics(effects[measure], factor)
            method = {"contrasts": f"t, {test.get('networks')} nets", "exact": "Fisher"}
            rows.append(test | {
                "estimate": reads["estimate"], "p_reads": reads["p"], "variant": label,
                "measure": shown, "effect": EFFECT_NAMES[factor],
                "key": f"{measure}_{factor.replace(INTERACTION, 'interaction')}",
                "test": method.get(test["method"], "none"),
                "verdict": robot_verdict(effects[measure], measure, factor)})  # fmt: skip
    return rows, cells


def _best_effects(effects: dict) -> dict:
    """The best variant's effects: each verdict a claim resting on its difference and p; misses."""
    out: dict[str, object] = {}
    for r in _effect_rows(effects)[0]:
        name = f"best_{r['key']}"
        out |= {f"{name}_estimate": r["estimate"], f"{name}_p": r["p_reads"]}
        rests = (f"robot_test.{name}_estimate", f"robot_test.{name}_p")
        out[name] = text.Claim(r["verdict"], rests)
    objects = effects["success"]["objects"]
    out["best_misses"] = _misses({k: (c["held"], c["trials"]) for k, c in objects.items()})
    tests = [t for m in effects.values() for t in m["tests"].values() if "family" in t]
    family = tests[0] if tests else {"family": "none", "family_size": 0}
    return out | {"robot_family": family["family"], "robot_family_size": family["family_size"]}


def _robot_scope(config: dict, variants: pd.DataFrame, records: Mapping[str, dict]) -> dict:
    """What this build tests on the robot on networks 0.., in the chapter's words. A build that
    tests variants besides the config's own networks (the grid at full scale, or entries of
    robot.default) compares them (``compared``), and its effects are the best variant's; the
    default build tests the config's own networks alone beside the confirmation, so the
    comparison is left to the full scale (``scope`` says so) and the effects are theirs."""
    robot, network = config["robot"], config["network"]
    grid = len(dict.fromkeys([NetworkVariant.of(network, network), *NetworkVariant.grid(robot)]))
    n, explored = len(variants), f"0-{network['networks'] - 1}"
    own, best = (records[k]["grasping_palm_error_mm"] for k in ("own", "best"))
    values = {"compared": n > 1, "grid_variants": grid, "explored_networks": explored,
              "seed": config["seed"]}  # fmt: skip
    if config["robustness"]:
        tested = f"every variant of the grid, {n} with the config's own networks"
    else:
        tested = f"{n} variants: the config's own networks and the {n - 1} of robot.default"
    if n > 1:
        return values | {
            "tested_variants": tested,
            "palm_compared": f"the best variant's palm ends a median {best:.1f} mm from the "
            f"demonstrator's and the config's own networks' {own:.1f} mm",
            "effects_subject": "the best variant", "effects_whose": "the best variant's",
            "effects_note": "The best variant was chosen on these networks, so its effects "
            "are exploration",
            "every_variant_effects": "Every variant's effects and counts per cell:",
            "scope": "",
        }  # fmt: skip
    return values | {
        "tested_variants": "the config's own networks alone (robot.default lists no other "
        "variant)",
        "palm_compared": f"the config's own networks' palm ends a median {own:.1f} mm from the "
        "demonstrator's",
        "effects_subject": "the config's own networks",
        "effects_whose": "the config's own networks'",
        "effects_note": "This build tests them on the config's own networks, the only variant "
        f"it tests on networks {explored}; like every robot test they are exploration",
        "every_variant_effects": "This build tests no variant beside the config's own networks: "
        "their effects and counts per cell are the tables above.",
        "scope": "This build therefore compares no variants: the grid's "
        f"{grid} variants on networks {explored}, their cue timings and learning-rate schedules "
        "side by side, the best of them and their success against training appear at full "
        "scale only (`snakemake -c2 --config robustness=True`).",
    }  # fmt: skip


def _exploration(confirmation: pd.DataFrame) -> dict:
    """The sentence on the confirmed variant's share on the networks it was chosen on: its
    counts where this build tests it there (full scale), else where that share is found."""
    rows = confirmation[confirmation["seed_set"] == "exploration"] if len(confirmation) else []
    if not len(rows):
        return {"explored": False, "exploration_words": "This build does not test it on those "
                "networks again; a build at full scale does, and shows that share beside the "
                "fresh networks' one."}  # fmt: skip
    row = rows.iloc[0]
    return {"explored": True, "exploration_words": "This build tests it on those networks as "
            f"well: there it held the object in {row['held']} of {row['trials']} grasping "
            "trials."}  # fmt: skip


def _animated(config: dict, confirmation: pd.DataFrame) -> dict:
    """Which networks the films show (``runs.RunPlan.animated``): the animated variant's first
    network of each mapping, on networks 0.. where the default build tests it there (the
    config's own networks, an entry of robot.default), else on its confirmation's fresh
    networks (their first index and count from the confirmation's row)."""
    robot, network = config["robot"], config["network"]
    variant = NetworkVariant.of(robot["animation"]["variant"], network)
    listed = [NetworkVariant.of(entry, network) for entry in [network, *robot["default"]]]
    first, count, where = 0, network["networks"], "its first"
    if variant not in listed:
        fresh = confirmation[confirmation["seed_set"] == "confirmation"]
        row = fresh[[NetworkVariant.from_row(r) == variant for _, r in fresh.iterrows()]].iloc[0]
        first, count = int(row["first_network"]), int(row["networks"])
        where = "the first of its confirmation's fresh networks"
    return {"animated_film": f"network {first}, {where}",
            "animated_pair": f"networks {first} and {first + count // 2}"}  # fmt: skip


def _confirmation(confirmation: pd.DataFrame) -> tuple[dict, pd.DataFrame]:
    """The first confirmed variant's counts, chosen on some networks, the bar set on fresh ones."""
    rows = confirmation.to_dict("records")
    for r in rows:
        bar = confirmation_science.bar_verdict(r["ci_low"], r["ci_high"], science.GRASPS)
        r |= {"variant": short_label(r), "vs_bar": bar if r["seed_set"] == "confirmation" else ""}
    out = {"bar": science.GRASPS, "confirmed_label": "none"}
    if not rows:
        return out | {"confirmation_bar": "is not tested: no variant confirmed"}, pd.DataFrame()
    first = {r["seed_set"]: r for r in reversed(rows)}  # the first confirmed variant's two rows
    keys = ("networks", "trials", "held", "share", "ci_low", "ci_high")
    out |= {f"{seeds}_{k}": r[k] for seeds, r in first.items() for k in keys}
    fresh = first["confirmation"]
    out |= {"confirmed_label": fresh["variant"], "confirmation_verdict": fresh["vs_bar"]}
    bar = "includes it" if fresh["vs_bar"] == "includes" else f"lies {fresh['vs_bar']} it"
    out["confirmation_bar"] = text.Claim(bar, ("robot_test.bar", "robot_test.confirmation_ci_low",
                                               "robot_test.confirmation_ci_high"))  # fmt: skip
    held = {k.removesuffix("_held"): v for k, v in fresh.items() if k.endswith("_held")}
    out["confirmation_misses"] = _misses({k: (v, fresh[f"{k}_trials"]) for k, v in held.items()})
    return out, pd.DataFrame(rows)


def _contact_time(tests: pd.DataFrame) -> dict:
    """The declared contact-time test on the first confirmed variant's fresh networks: its
    numbers and verdict (``words.CLAIM_WORDS``), a claim on its estimate and Holm p."""
    if not len(tests):
        return {"contact_verdict": "not tested: no variant confirmed", "contact_said": ""}
    row = tests.iloc[0]
    out = {f"contact_{k}": float(row[k]) for k in ("estimate", "ci_low", "ci_high", "p_holm")}
    out |= {"contact_networks": int(row["networks"]),
            "contact_networks_tested": int(row["networks_tested"])}  # fmt: skip
    word = words.CLAIM_WORDS[row["direction"]]
    out["contact_verdict"] = text.Claim(word, ("robot_test.contact_estimate",
                                               "robot_test.contact_p_holm"))  # fmt: skip
    out["contact_said"] = (
        f" ({row['estimate']:+.3f} s, Holm p {row['p_holm']:.2g}; "
        f"{int(row['networks_tested'])} of {int(row['networks'])} networks)"
        if np.isfinite(row["p_holm"]) else ""
    )  # fmt: skip
    return out


def robot_test(inputs: Mapping[str, str], config: dict) -> tuple[dict, dict[str, pd.DataFrame]]:
    """The robot grasps: the variants, the best confirmed, the arm's precision, the effects."""
    variants = pd.read_csv(inputs["robot_variants.csv"])
    variants["variant"] = [short_label(r) for _, r in variants.iterrows()]
    effects, stats = _json(inputs["robot_effects.json"]), _json(inputs["robot_statistics.json"])
    tolerated = science.tolerated_noise(tolerance := record_table(stats["tolerance"]))
    best, smallest = science.best_robot_variant(variants), science.smallest_that_grasps(variants)
    animated = {k: config["network"][k] for k in ("categorisation_cue", "learning_rate_schedule")}
    out = {
        "n_variants": len(variants),
        "animated_label": short_label(animated | config["robot"]["animation"]["variant"]),
        "smallest_label": "none" if smallest is None else smallest["variant"],
        "tolerated_noise": "none tested" if tolerated is None else f"{tolerated['noise']:g}",
        "tolerated_palm_mm": np.nan if tolerated is None else tolerated["palm_error_mm"],
    }  # fmt: skip
    records = {"own": variants[variants["run"] == MAIN].to_dict("records")[0], "best": best,
               "replay": stats["replay"],  # the config lists noise 0 for the exact postures
               "exact": tolerance[tolerance["noise"] == 0].to_dict("records")[0]}  # fmt: skip
    out |= {f"{name}_{k}": v for name, record in records.items() for k, v in record.items()}
    for key in ("grasping_wrong_grip_hold", "categorisation_wrong_grip_hold", "trials"):
        out[f"wrong_grip_{key.split('_')[0]}"] = int(variants[key].sum())
    confirmed, confirmation = _confirmation(pd.read_csv(inputs["robot_confirmation.csv"]))
    for p in (pairs := stats["schedule_pairs"]):  # paired by network and object: McNemar
        p["same"] = short_label(p | {"learning_rate_schedule": p["a"]}, ("learning_rate_schedule",))
        below = "p < 0.05, unadjusted" if len(pairs) > 1 else "differ"  # several: no family
        p["verdict"] = words.below_alpha(p["p"], below)
    out |= _robot_scope(config, variants, records) | _exploration(confirmation)
    out |= _animated(config, confirmation)
    rows = [_effect_rows(effects[v["run"]], v["variant"]) for _, v in variants.iterrows()]
    out |= _contact_time(pd.read_csv(inputs["robot_contact_time.csv"]))
    return out | confirmed | _best_effects(effects[best["run"]]), {
        "robot_variants": variants, "robot_pairs": pd.DataFrame(pairs),
        "robot_confirmation": confirmation,
        "robot_effects": pd.DataFrame([r for effect, _ in rows for r in effect]),
        "robot_cells": pd.DataFrame([c for _, cells in rows for c in cells]),
    }  # fmt: skip


# -- the sweep, the method pages, the size study --------------------------------------------------


def robustness(inputs: Mapping[str, str], config: dict,
               sweep_jobs: Mapping[str, object] | None = None
               ) -> tuple[dict, pd.DataFrame | None]:  # fmt: skip
    """The sweep's values, its summary with each effect's direction, and its cost from its jobs'
    own records (``sweep_jobs``: {benchmark file: seed}, ``benchmark_tables.replication_cost``);
    or, not run, what it would train."""
    sweep = config["sweep"]
    points = len(sweep["categorisation_cue"]) * int(
        np.prod([len(sweep[k]) for k in ("seeds", "learning_rate", "hidden")]))  # fmt: skip
    values: dict = {"ran": bool(config["robustness"]), "points": points,
                    "networks": points * config["network"]["networks"]}  # fmt: skip
    values |= full_scale_cost(inputs["full_scale_critical_path.json"])
    if not config["robustness"]:
        return values | {"sweep_ran": "did not run it (robustness is false, the default)"}, None
    from icub_workflow.benchmark_tables import replication_cost

    summary = pd.read_csv(inputs["sweep_summary.csv"])
    values |= {"sweep_ran": f"ran it: seeds {', '.join(map(str, sweep['seeds']))}, "
               f"{len(summary)} setting(s)"}  # fmt: skip
    values |= {f"cost_{k}": v for k, v in replication_cost(sweep_jobs or {}).items()}
    directions = {  # each effect's mean over the replications, by its 95% interval
        f"{e}_direction": [words.SWEEP_DIRECTIONS[science.interval_direction(
            r["replications"], *(r[f"{e}_{k}"] for k in ("effect", "ci_low", "ci_high")))]
            for _, r in summary.iterrows()] for e in ("congruency", "size")}  # fmt: skip
    return values, summary.assign(**directions)


def full_scale_cost(path: str) -> dict:
    """The full scale's critical path and its wall time on each number of cores, from the record
    ``benchmarks/critical_path.py --record`` wrote after a full-scale build (its job records):
    minutes and hours for the reproduce page, the chain's rules with their seconds, and where
    the records come from."""
    from icub_workflow.critical_path import load_record

    record = load_record(path)
    chain = " → ".join(f"{job['rule']} {job['s']:.0f} s" for job in record["chain"]
                       if job["benchmark"] is not None)  # not the target `all`  # fmt: skip
    return {
        "full_jobs": record["jobs"], "full_job_h": record["sum_of_job_seconds"] / 3600,
        "full_path_min": record["critical_path_s"] / 60,
        "full_path_jobs": sum(job["benchmark"] is not None for job in record["chain"]),
        "full_chain": chain, "full_span_min": record["span_s"] / 60,
        "full_on_cores": [{"cores": row["cores"], "at_least_min": row["lower_bound_s"] / 60,
                           "predicted_min": row["predicted_s"] / 60}
                          for row in record["on_cores"]],
        "full_commit": record["commit"], "full_cpu": record["cpu"], "full_date": record["date"],
    }  # fmt: skip


#: The config sections the pages quote, each setting by its path (a reader changes it by that name).
QUOTED = ("seed", "object_sizes_m", "vision", "demos", "soms", "network")


def methods(inputs: Mapping[str, str]) -> dict[str, dict]:
    """The method pages' numbers: the demonstrations, the visual maps, the body and the maps."""
    soms = load_npz(inputs["soms.npz"])
    units = zip(soms["objects"].tolist(), soms["object_act"], strict=True)
    demos = science.demo_counts(pd.read_csv(inputs["demo_summary.csv"]))
    return {
        "training": {k: demos[k] for k in ("n_demos", "n_attempts", "n_retried", "lift_min_cm")},
        "vision": {f"cells_{name}": n for name, n in
                   science.edge_cells(load_npz(inputs["visual_maps.npz"])).items()},
        "body": science.joint_counts(pd.read_csv(inputs["joint_table.csv"])),
        "architecture": {f"units_{obj}": active_units(act) for obj, act in units},
    }  # fmt: skip


#: The size study's cue timings, in short.
SIZE_CUES = {"first_step": "first step", "all_steps": "every step"}


def _declared_key(row) -> str:
    """A declared test's name in the size page's values: ``<test>_<dose>_<cue>`` (the dose
    contrast ``dose_contrast_<cue>``)."""
    at = "contrast" if row["test"] == "dose" else str(row["dose"]).replace(".", "")
    return f"{row['test']}_{at}_{row['cue']}"


def _declared_values(values: dict, declared: pd.DataFrame) -> pd.Series:
    """Each declared test's numbers and its verdict word (``words.SIZE_PART_WORDS``), and, per
    dose and cue timing, which of the two parts its tests show (``text.carrier``). Returns the
    verdict word of each row."""
    said_words = []
    for _, row in declared.iterrows():
        key = _declared_key(row)
        term = {k: float(row[k]) for k in ("estimate", "ci_low", "ci_high", "p", "p_holm")}
        values |= {f"{key}_{k}".replace("_estimate", ""): v for k, v in term.items()}
        values[f"{key}_replications"] = int(row["replications"])
        word = text.size_part_word(row["test"], term)
        values[f"{key}_verdict"] = text.Claim(word, (f"size.{key}", f"size.{key}_p_holm"))
        said_words.append(word)
    for (dose, cue), rows in declared[declared["test"] != "dose"].groupby(["dose", "cue"],
                                                                          sort=False):  # fmt: skip
        by = {row["test"]: row for _, row in rows.iterrows()}
        if {"size", "grip_distance"} <= set(by):
            keys = [_declared_key(by[t]) for t in ("size", "grip_distance")]
            said = text.carrier(
                *(words.verdict_word(dict(by[t])) for t in ("size", "grip_distance"))
            )
            values[f"carrier_{str(dose).replace('.', '')}_{cue}"] = text.Claim(
                said, tuple(f"size.{k}{s}" for k in keys for s in ("", "_p_holm"))
            )
    # one phrase per dose, and one for the dose contrast, over the cue timings this build ran
    phrases = {f"carrier_{str(d).replace('.', '')}": "" for d in dict.fromkeys(declared["dose"])}
    for name, suffix in (phrases | {"dose_contrast": "_verdict"}).items():
        claims = {
            c: values[f"{name}_{c}{suffix}"] for c in SIZE_CUES if f"{name}_{c}{suffix}" in values
        }
        if claims:
            values[f"{name}_by_cue"] = text.Claim(
                "; ".join(f"{SIZE_CUES[c]}: {v.text}" for c, v in claims.items()),
                tuple(r for v in claims.values() for r in v.rests_on),
            )
    return pd.Series(said_words, index=declared.index, dtype=object)


def _metric_values(values: dict, metrics: pd.DataFrame) -> pd.DataFrame:
    """The size study on the two metrics of the grips' distance (``size_study.metric_tests``,
    added after results): each test's numbers as ``<metric>_<declared key>``, and per metric,
    dose and cue timing which part is shown (``text.carrier``; the declared metric's is
    ``carrier_<dose>_<cue>``) and which is the larger (``text.larger_part``). Returns the
    chapter's table: one row per metric, cue timing and dose, with the declared metric's parts
    read from ``values`` (``_declared_values``)."""
    for _, row in metrics.iterrows():
        key = f"{row['metric']}_{_declared_key(row)}"
        values |= {f"{key}{s}": float(row[k]) for s, k in (("", "estimate"), ("_ci_low", "ci_low"),
                   ("_ci_high", "ci_high"), ("_p_holm", "p_holm"))}  # fmt: skip
    rows = []
    for (metric, dose, cue), by in metrics.groupby(["metric", "dose", "cue"], sort=False):
        at = f"{str(dose).replace('.', '')}_{cue}"
        pre = f"{metric}_" if metric == TRAJECTORY else ""
        parts = {t: (values[f"{pre}{t}_{at}"], values[f"{pre}{t}_{at}_p_holm"])
                 for t in ("size", "grip_distance")}  # fmt: skip
        if metric == TRAJECTORY:
            values[f"{metric}_carrier_{at}"] = text.Claim(
                text.carrier(
                    *(
                        words.verdict_word({"estimate": e, "p": p, "p_holm": p})
                        for e, p in parts.values()
                    )
                ),
                tuple(f"size.{metric}_{t}_{at}{s}" for t in parts for s in ("", "_p_holm")),
            )
        larger = by[by["test"] == SIZE_LARGER].iloc[0]
        key = f"{metric}_{SIZE_LARGER}_{at}"
        values[f"{metric}_larger_{at}"] = text.Claim(
            text.larger_part(dict(larger)), (f"size.{key}", f"size.{key}_p_holm")
        )
        rows.append({"metric": metric, "cue": cue, "dose": dose}
                    | {f"{t}{s}": v for t, (e, p) in parts.items()
                       for s, v in (("", e), ("_p_holm", p))}
                    | {"size_larger": float(larger["estimate"]),
                       "size_larger_p_holm": float(larger["p_holm"]),
                       "larger": values[f"{metric}_larger_{at}"].text,
                       "family": larger["family"]})  # fmt: skip
    places = zip(metrics["dose"], metrics["cue"], strict=True)
    for at in dict.fromkeys(f"{str(d).replace('.', '')}_{c}" for d, c in places):
        said = [values[f"{m}_larger_{at}"] for m in (FINAL_POSTURE, TRAJECTORY)]
        values[f"metrics_differ_{at}"] = text.Claim(
            "Which part is the larger thus depends on how the grips' distance is measured"
            if said[0].text != said[1].text
            else "Both metrics name the same part the larger",
            tuple(r for claim in said for r in claim.rests_on),
        )
    return pd.DataFrame(rows)


def size_study(inputs: Mapping[str, str], config: dict) -> tuple[dict, dict[str, pd.DataFrame]]:
    """The chapter "What drives the size effect": values, verdict words (Claims), tables."""
    summary, checks, crossed = (
        pd.read_csv(inputs[f"size_{name}.csv"], dtype={"dose": str}).rename(
            columns={"diff": "estimate"})
        for name in ("summary", "manipulation", "crossed"))  # fmt: skip
    declared = pd.read_csv(inputs["size_declared.csv"], dtype={"dose": str})
    power = pd.read_csv(inputs["size_power.csv"], dtype={"dose": str})
    try:
        motor = pd.read_csv(inputs["size_motor.csv"], dtype={"dose": str})
    except pd.errors.EmptyDataError:  # no runs in this build
        motor = pd.DataFrame(columns=["dose", "arrangement", "cue", "geometry", "estimate",
                                      "p_holm", "family"])  # fmt: skip
    doses = config["size_dose"]["doses"]
    crossing = config["size_dose"]["crossed"]
    top = str(float(max(doses)))
    rmse = summary[summary["measure"] == "rmse"]
    natural = rmse[rmse["arrangement"] == "natural"]
    values: dict = {"doses": ", ".join(f"{d:g}" for d in doses), "top_dose": f"{float(top):g}",
                    "replications": int(
                        (declared["replications"] + declared["left_out"]).max()),
                    "declared_tests": len(declared),
                    "effect_of_interest": float(crossing["effect_of_interest"]),
                    "alpha": float(crossing["alpha"]),
                    "alpha_at_least": float(power["alpha_at_least"].iloc[0]),
                    "delivered_top": float(
                        natural.loc[natural["dose"] == top, "delivered_dose"].mean())}  # fmt: skip
    for (shape, name), ratios in checks[checks["dose"] == top].groupby(["shape", "map"])["ratio"]:
        values[f"ratio_{name}_{shape}"] = float(ratios.min())
    arrived = min(values["ratio_goal_ball"], values["ratio_goal_cube"]) >= 2
    values["check"] = text.Claim("arrived" if arrived else "did not fully arrive",
                                 ("size.ratio_goal_ball", "size.ratio_goal_cube"))  # fmt: skip
    for arrangement, runs in crossed.groupby("arrangement"):
        values[f"gap_{arrangement}_low"] = float(runs["gap"].min())
        values[f"gap_{arrangement}_high"] = float(runs["gap"].max())
    verdicts = _declared_values(values, declared)
    for name, dose in (("none", min(doses)), ("top", max(doses))):  # the book's two doses
        values[f"carrier_{name}_by_cue"] = values[f"carrier_{f'{dose:g}'.replace('.', '')}_by_cue"]
    for name, column in (("size", "power_at_least"), ("size_low", "power_at_least_low"),
                         ("size_high", "power_at_most_high")):  # fmt: skip
        chosen = power.loc[power["test"] != "dose", column]
        values[f"power_{name}"] = float(chosen.min() if name != "size_high" else chosen.max())
    for name, column in (("dose_low", "power_at_least_low"), ("dose_high", "power_at_most_high")):
        chosen = power.loc[power["test"] == "dose", column]
        values[f"power_{name}"] = float(chosen.min() if name == "dose_low" else chosen.max())
    removed = rmse[rmse["dose"] == "removed"]
    for _, row in removed.iterrows():
        rests = (f"size.removed_{row['cue']}", f"size.removed_p_holm_{row['cue']}")
        values |= {f"removed_{row['cue']}": float(row["estimate"]),
                   f"removed_p_holm_{row['cue']}": float(row["p_holm"]),
                   f"removed_verdict_{row['cue']}": text.Claim(words.verdict_word(dict(row)),
                                                               rests)}  # fmt: skip
    ran = [cue for cue in SIZE_CUES if f"removed_{cue}" in values]
    values["removed_by_cue"] = text.Claim(
        " and ".join(f"{values[f'removed_verdict_{c}'].text} ({SIZE_CUES[c]})" for c in ran),
        tuple(f"size.removed{s}_{c}" for c in ran for s in ("", "_p_holm")),
    ) if ran else "not run in this build"  # fmt: skip
    keys = ("motor_p_holm_" + motor["dose"] + "_" + motor["arrangement"] + "_" + motor["cue"]
            + "_" + motor["geometry"])  # fmt: skip
    values |= dict(zip(keys, motor["p_holm"].astype(float), strict=True))
    for family, name in ((FAMILY_MOTOR_PLANNED, "planned"), (FAMILY_MOTOR_ADDED, "added")):
        chosen = (motor["family"] == family).to_numpy()
        found = motor.loc[chosen & significant(motor["p_holm"]).to_numpy(), "geometry"]
        values[f"motor_found_{name}"] = text.Claim(
            text.named_measures(found.unique()), tuple("size." + keys[chosen])
        ) if chosen.any() else "not run in this build"  # fmt: skip
    values["like_size"] = text.named_measures(
        ranked_like_size(pd.read_csv(inputs["size_geometry.csv"])))  # fmt: skip
    shown = _metric_values(values, pd.read_csv(inputs["size_trajectory_tests.csv"],
                                               dtype={"dose": str}))  # fmt: skip
    lines = pd.read_csv(inputs["size_trajectory_separated.csv"])
    values |= {"trajectory_gap_natural": float(lines["gap_natural"].mean()),
               "trajectory_gap_swapped": float(lines["gap_swapped"].mean()),
               "trajectory_family": FAMILY_TRAJECTORY}  # fmt: skip
    return values, {"size_tests": declared.assign(verdict=verdicts), "size_metrics": shown}


#: A signature's name in the book's words.
SIGNATURE_NAMES = {"grows_with_rt": "The effect grows with reaction time",
                   "extinction": "The effect fades after the object disappears",
                   "brief_exposure": "A brief masked glimpse gives the same effect",
                   "advance_cueing": "No effect when the response is cued in advance"}  # fmt: skip

#: The extinction levels' test, added after the results (``extinction_levels``), in words for
#: each ``Outcome`` against people's direction: a blanked effect smaller than in view, as the
#: effect fades in people (here: the scripts that write results import ``words``, and a
#: word added there would rerun them).
EXTINCTION_LEVEL_WORDS = {Outcome.PAPER: "smaller than in view, as in people",
                          Outcome.AGAINST: "larger than in view, unlike people",
                          Outcome.NONE: "not shown to differ from in view",
                          Outcome.NOT_ASSESSABLE: words.NOT_ASSESSABLE}  # fmt: skip


def extinction_level_values(levels: pd.DataFrame) -> dict:
    """The extinction levels against in view, a test added after the results: each level's
    difference, interval, Holm p within its family and replications (``blank_k{k}_...``), and
    ``blank_levels``, the levels by which way they go against people (a ``Claim`` on their
    Holm p)."""
    from icub_affordance.analysis.extinction_levels import ADDED_FAMILY

    values: dict = {"blank_family": ADDED_FAMILY}
    said: dict[str, list[str]] = {}
    for _, row in levels.iterrows():
        k = int(row["k"])
        stats = ("in_view", "blanked", "estimate", "ci_low", "ci_high", "p_holm")
        values |= {f"blank_k{k}_{stat}": float(row[stat]) for stat in stats}
        values |= {f"blank_k{k}_{n}": int(row[n]) for n in ("replications", "of")}
        word = EXTINCTION_LEVEL_WORDS[Outcome(int(row["direction"]))]
        said.setdefault(word, []).append(str(k))
    rests = tuple(f"signatures.blank_k{int(k)}_p_holm" for k in levels["k"])
    values["blank_levels"] = (
        text.Claim("; ".join(f"at k = {text.listing(ks, '')} {word}" for word, ks in said.items()),
                   rests)
        if said else "no level has an estimate"
    )  # fmt: skip
    tested = levels[np.isfinite(levels["p_holm"].astype(float))]
    values["blank_tested"] = text.listing(
        [f"{r.estimate:+.4f} [{r.ci_low:+.4f}, {r.ci_high:+.4f}] at k = {r.k} (Holm p "
         f"{r.p_holm:.2g}, {r.replications} of {r.of} replications)"
         for r in tested.itertuples()], "none tested")  # fmt: skip
    return values


def signatures(inputs: Mapping[str, str], config: dict) -> tuple[dict, dict[str, pd.DataFrame]]:
    """The chapter "The model against what people do": each signature's verdict (a Claim on its
    estimate and Holm p), the errors apart, and the table of one row per signature."""
    summary = pd.read_csv(inputs["signatures_summary.csv"])
    summary = summary.fillna({"reason": "", "verdict": "", "level": ""})
    errors = pd.read_csv(inputs["signatures_errors.csv"])
    declared = {e["signature"]: e for e in config["signatures"]["list"]}
    verdicts = summary[summary["family"] == "signatures"]
    values: dict = {key: config["signatures"][key] for key in ("trials", "visual_noise",
                                                                "quantiles", "margin")}  # fmt: skip
    rows = []
    for _, row in verdicts.iterrows():
        name = row["signature"]
        for stat in ("estimate", "ci_low", "ci_high", "p", "p_adjusted"):
            values[f"{name}_{stat}"] = float(row[stat])
        rests = (f"signatures.{name}_estimate", f"signatures.{name}_p_adjusted")
        values[f"{name}_verdict"] = text.Claim(row["verdict"], rests)
        values[f"{name}_scale"] = signature_scale(row)
        est = signature_result(row)
        rows.append({"signature": SIGNATURE_NAMES[name],
                     "people": f"{declared[name]['finding']} ({declared[name]['citation']})",
                     "model condition": row["condition"], "model result": est,
                     "verdict": row["verdict"], "measured at": signature_scale(row)})  # fmt: skip
    overall = summary[(summary["signature"] == "grows_with_rt") & (summary["level"] == "all")]
    for _, row in overall.iterrows():  # the in-view effect whose shape the signatures test
        for stat in ("estimate", "ci_low", "ci_high", "p_adjusted"):
            values[f"in_view_{stat}"] = float(row[stat])
        found = significant(row["p_adjusted"])
        word = ("is confirmed (incongruent slower)" if row["estimate"] > 0 else "is reversed") if (
            found) else "is not shown"  # fmt: skip
        values["in_view_verdict"] = text.Claim(
            word,
            ("signatures.in_view_estimate", "signatures.in_view_p_adjusted"),
        )
        values["in_view_scale"] = signature_scale(row)
    view = errors[errors["condition"] == "in_view"].iloc[0]
    values |= {"wrong_congruent": float(view["wrong_congruent"]),
               "wrong_incongruent": float(view["wrong_incongruent"]),
               "wrong_p_adjusted": float(view["p_adjusted"])}  # fmt: skip
    depends = significant(view["p_adjusted"])
    values["errors_verdict"] = text.Claim(
        "depend on congruency" if depends else "are not shown to depend on congruency",
        ("signatures.wrong_p_adjusted",),
    )
    values |= extinction_level_values(pd.read_csv(inputs["signatures_extinction_levels.csv"]))
    counts = verdicts["verdict"].value_counts()
    values["shown"] = text.Claim(
        text.listing([SIGNATURE_NAMES[n].lower() for n in verdicts.loc[
            verdicts["verdict"] == words.SHOWN, "signature"]], "none"),
        tuple(f"signatures.{n}_p_adjusted" for n in verdicts["signature"]))  # fmt: skip
    values["counts"] = ", ".join(f"{counts[w]} {w}" for w in words.SIGNATURE_WORDS.values()
                                 if w in counts)  # fmt: skip
    return values, {"signatures": pd.DataFrame(rows)}


#: The distractor's cells in short, for its tables (signatures.md, "Two objects at once").
DISTRACTOR_CUES = {"first_step": "first step", "all_steps": "every step"}
DISTRACTOR_MODES = {"teacher_forced": "forced", "closed_loop": "closed loop"}
DISTRACTOR_MEASURES = {"rmse": "all trials", "rmse_correct": "correct trials"}
#: Each distractor test's sign, in words: positive is the grip compatible with the object faster.
DISTRACTOR_SIGNS = {
    Outcome.PAPER: "positive",
    Outcome.AGAINST: "negative",
    Outcome.NONE: words.NOT_SHOWN,
    Outcome.NOT_ASSESSABLE: words.NOT_ASSESSABLE,
}


def distractor_name(row: Mapping) -> str:
    """A distractor test's findings key: ``distractor_{lam}_{cue}_{mode}_{measure}_{effect}``,
    the weight without its point and its minus an ``m`` (-0.25: ``m025``)."""
    lam = f"{float(row['lam']):g}".replace("-", "m").replace(".", "")
    return "_".join(["distractor", lam, *(str(row[k]) for k in ("cue", "mode", "measure",
                                                                  "effect"))])  # fmt: skip


def distractor_values(summary: pd.DataFrame) -> tuple[dict, dict[str, pd.DataFrame]]:
    """A distractor at test (config ``distractor``): each test's estimate, interval and Holm p
    (``distractor_name``), each effect's signs counted per family (a ``Claim`` on the Holm p's:
    ``distractor_{effect}_declared``, ``..._inhibition``), and the cells' table: an estimate
    and its interval, in parentheses where Holm p is not below alpha."""
    tests = summary.assign(
        name=[distractor_name(r) for r in summary.to_dict("records")],
        sign=[DISTRACTOR_SIGNS[Outcome(int(d))] for d in summary["direction"]],
    )
    values: dict = {}
    rows: dict[tuple, dict] = {}
    for r in tests.to_dict("records"):
        values |= {f"{r['name']}_{stat}": float(r[stat])
                   for stat in ("estimate", "ci_low", "ci_high", "p_holm")}  # fmt: skip
        shown = f"{r['estimate']:+.4f} [{r['ci_low']:+.4f}, {r['ci_high']:+.4f}]"
        cell = rows.setdefault((r["lam"], r["cue"], r["mode"], r["measure"]), {
            "λ": f"{float(r['lam']):g}", "cue": DISTRACTOR_CUES[r["cue"]],
            "mode": DISTRACTOR_MODES[r["mode"]], "measure": DISTRACTOR_MEASURES[r["measure"]],
        })  # fmt: skip
        cell[r["effect"]] = shown if r["sign"] in ("positive", "negative") else f"({shown})"
    for part, chosen in (("declared", tests["lam"] > 0), ("inhibition", tests["lam"] < 0)):
        family = tests[chosen]
        values[f"distractor_{part}_family"] = str(family["family"].iloc[0])
        values[f"distractor_{part}_size"] = int(family["family_size"].iloc[0])
        for effect, group in family.groupby("effect"):
            counts = group["sign"].value_counts()
            values[f"distractor_{effect}_{part}"] = text.Claim(
                ", ".join(f"{word} in {counts[word]}" for word in DISTRACTOR_SIGNS.values()
                          if word in counts) + f" of {len(group)} cells",
                tuple(f"signatures.{n}_p_holm" for n in group["name"]))  # fmt: skip
    values["distractor_replications"] = int(tests["replications"].min())
    order = sorted(rows, key=lambda k: (k[0] < 0, abs(k[0]), list(DISTRACTOR_CUES).index(k[1]),
                                        list(DISTRACTOR_MODES).index(k[2]), k[3]))  # fmt: skip
    table = pd.DataFrame([rows[k] for k in order]).rename(
        columns={"congruency": "target congruency", "compatibility": "distractor compatibility"}
    )
    cells = table[table["λ"].astype(float) > 0]
    short = {}  # the declared family's cells, estimates only: one row per cue x mode x measure
    for _, r in cells.iterrows():
        row = short.setdefault(
            (r["cue"], r["mode"], r["measure"]),
            {"cue": r["cue"], "mode": r["mode"], "measure": r["measure"]},
        )
        for effect, label in (("target congruency", "target"),
                              ("distractor compatibility", "distractor")):  # fmt: skip
            est = r[effect].split(" [")[0]
            row[f"{label}, λ {r['λ']}"] = est + (")" if est.startswith("(") else "")
    short_table = pd.DataFrame(list(short.values()))
    effects = sorted(short_table.columns[3:], key=lambda c: (not c.startswith("target"), c))
    return values, {
        "distractor": table,
        "distractor_cells": short_table[[*short_table.columns[:3], *effects]],
    }


def page_findings(inputs: Mapping[str, str], config: dict, ablation_cue: str,
                  scale: dict[str, dict[str, int]], sweep_jobs: Mapping[str, object] | None = None
                  ) -> tuple[dict, dict[str, pd.DataFrame]]:  # fmt: skip
    """Every page's values ({page: {name: value}}) and tables ({name: table}), from ``inputs``:
    the book's names of the outputs (``BOOK_DATA``'s keys) and their files; ``sweep_jobs``, with
    robustness, the benchmark file of each job of the sweep's points and its seed."""
    anova, cue = _json(inputs["anova.json"]), config["network"]["categorisation_cue"]
    quoted = {key: config[key] for key in QUOTED}
    curves = [pd.read_csv(inputs[n]) for n in sorted(n for n in inputs if n.startswith("curves/"))]
    curve = science.curve_summary(np.array([c["rmse"] for c in curves]), config["network"][
        "phase1_iterations"], curves[0]["iteration"].to_numpy())  # fmt: skip
    read = {name: pd.read_csv(inputs[f"{name}.csv"]) for name in (
        "claims_summary", "claims_learning", "size_declared", "robot_variants",
        "robot_confirmation", "signatures_summary")}  # fmt: skip
    sensitivity = pd.read_csv(inputs["claims_correct_sensitivity.csv"])
    score_values, score_table = scorecard(
        *read.values(), sensitivity=sensitivity,
        contact=pd.read_csv(inputs["robot_contact_time.csv"]),
        contact_cells=pd.read_csv(inputs["robot_contact_time_cells.csv"]))  # fmt: skip
    claim_values, claim_table = claims_values(
        read["claims_summary"], pd.read_csv(inputs["claims_power.csv"]), sensitivity,
        pd.read_csv(inputs["claims_correct_cells.csv"]),
        pd.read_csv(inputs["claims_replications.csv"]))  # fmt: skip
    score_values |= claim_values
    pages, tables = {}, {}
    for page, (values, shown) in {
        "beyond": beyond(inputs, config, ablation_cue), "readings": readings(inputs, config),
        "robot_test": robot_test(inputs, config), "size": size_study(inputs, config),
        "signatures": signatures(inputs, config), "words": words_page(inputs, config),
    }.items():  # fmt: skip
        pages[page], tables = values, tables | shown
    if "distractor_summary.csv" in inputs:  # config distractor.run: signatures.md's last section
        values, shown = distractor_values(pd.read_csv(inputs["distractor_summary.csv"]))
        pages["signatures"], tables = pages["signatures"] | values, tables | shown
    said, rows = score_rows(pages["words"])
    score_values |= said
    score_table = pd.concat([score_table, pd.DataFrame(rows)], ignore_index=True)
    pages["robustness"], sweep = robustness(inputs, config, sweep_jobs)
    pages |= {
        "tests": main_tests(anova, curve, load_npz(inputs["demos.npz"]), cue),
        "index": score_values,
        "reproduce": {"scale": scale | {"full": bool(config["robustness"])}},
        "settings": pd.json_normalize(quoted, sep=".").to_dict("records")[0],
    } | methods(inputs)  # fmt: skip
    tables |= {"scorecard": score_table, "claims": claim_table}
    tables |= {} if sweep is None else {"sweep": sweep}
    return traced(pages), tables


def traced(pages: dict[str, dict]) -> dict[str, dict]:
    """The pages' values, each ``text.Claim`` as its words and under ``claims`` the entries it
    rests on; an entry that names no value is refused: a claim rests on numbers the book has."""
    out = {page: {k: v.text if isinstance(v, text.Claim) else v for k, v in values.items()}
           for page, values in pages.items()}  # fmt: skip
    claims = {page: {k: list(v.rests_on) for k, v in values.items() if isinstance(v, text.Claim)}
              for page, values in pages.items()}  # fmt: skip
    claims = {page: found for page, found in claims.items() if found}
    for page, keys in claims.items():
        for key, entries in keys.items():
            missing = [e for e in entries if e.split(".", 1)[1] not in out.get(e.split(".")[0], {})]
            if missing:
                raise KeyError(f"{page}.{key} rests on {missing}, which findings.json lacks")
    return out | {"claims": claims}
