"""What each page of the book shows: every number, verdict, sentence and table, from the outputs.

``page_findings`` reads the pipeline's outputs (by their names in the book rule's ``BOOK_DATA``)
and returns, per page, the values the page glues (``findings.json``), and the tables it shows.
The verdicts and statistics are the package's (``icub_affordance.findings``, ``.som``), the
words this package's (``text``); the pages only display the result.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path

import numpy as np
import pandas as pd

from icub_affordance import confirmation as confirmation_science
from icub_affordance import findings as science
from icub_affordance import readings as readings_science
from icub_affordance.embodied_stats import FACTOR_LEVELS, INTERACTION
from icub_affordance.growth import cost_growth
from icub_affordance.io import load_npz
from icub_affordance.robot_statistics import record_table
from icub_affordance.size_dose import FAMILY_DECLARED, dose_value, ranked_like_size
from icub_affordance.som import active_units
from icub_affordance.spec import MODES
from icub_affordance.stats import TERMS, WITHIN
from icub_affordance.variants import SCHEDULE_WORDS, NetworkVariant
from icub_workflow.runs import OWN

from . import text

#: The three readings of the paper's measure (``stats.OUTCOMES``), as the tables name them.
OUTCOME_LABELS = {
    "contrasts": "RMSE, all trials",
    "errors": "wrong-grip rate",
    "correct_rt": "RMSE, correct trials",
}

ANALYSES = (("two_way", "two-way (trials)"), ("repeated_measures", "repeated measures (networks)"))

#: What the paper reports, beside which the comparison page sets this run's numbers.
PAPER = {
    "start": "about 0.3",
    "around_2000": "about 0.05",
    "end": "stable around 0.05",
    "congruency": "congruent lower; significant",
    "size": "large lower; significant",
    "networks": "12 (6 per mapping)",
    "learning_rate": "0.075",
    "iterations": "12,000 (6000 + 6000)",
    "hidden": "10",
    "sequences": "5 (4 + 1)",
}


def _json(path) -> dict:
    return json.loads(Path(path).read_text())


def _curves(inputs: Mapping[str, str]) -> tuple[np.ndarray, np.ndarray]:
    """The learning curves' RMSE (networks, rows) and the iteration of each row."""
    names = sorted(name for name in inputs if name.startswith("curves/"))
    tables = [pd.read_csv(inputs[name]) for name in names]
    return np.array([t["rmse"].to_numpy() for t in tables]), tables[0]["iteration"].to_numpy()


def anova_rows(anova: dict, mode: str) -> pd.DataFrame:
    """Both ANOVAs of one test mode, one row per effect (results page)."""
    rows = []
    for analysis, label in ANALYSES:
        for effect, r in anova[mode][analysis].items():
            rows.append(
                {
                    "analysis": label,
                    "effect": effect,
                    "F": r["F"],
                    "df": f"({r['df1']:.0f}, {r['df2']:.0f})",
                    "p": r["p"],
                    "partial η²": r["eta_p2"],
                }
            )
    return pd.DataFrame(rows)


def contrast_rows(anova: dict, mode: str) -> pd.DataFrame:
    """Every test of one test mode, one row per measure and term (results page): the all-trials
    RMSE's per-network contrasts and simple effects, the wrong-grip rate's and the correct-trial
    RMSE's within terms; each with its family and its p adjusted within it (the families are
    whole across the two modes' tables)."""
    rmse = OUTCOME_LABELS["contrasts"]
    sources = (
        [(rmse, anova["contrasts"][mode][t], text.term_name(t)) for t in TERMS]
        + [
            (OUTCOME_LABELS[o], anova[mode][o][t], text.term_name(t))
            for o in ("errors", "correct_rt")
            for t in WITHIN
        ]
        + [(rmse, term, text.simple_name(name)) for name, term in anova["simple"][mode].items()]
    )
    return pd.DataFrame(
        [
            {
                "measure": label,
                "term": name,
                "estimate": test["estimate"],
                "95% interval": text.fmt_ci(test),
                "t": test["t"],
                "df": test["df"],
                "p": test["p"],
                "family": test["family"],
                "p (Holm, within its family)": test["p_holm"],
            }
            for label, test, name in sources
        ]
    )


def object_means(measures: dict) -> pd.DataFrame:
    """Per mapping and object: the mean RMSE over networks of categorisation trials, in both test
    modes (``eval/measures.json``; results page)."""
    closed, forced = (measures[mode]["rmse"]["object_means"] for mode in MODES)
    return pd.DataFrame(
        [
            {
                "mapping": key.split("_", 1)[0],
                "object": key.split("_", 1)[1].replace("_", " "),
                "congruency": row["congruency"],
                "size": row["size"],
                "networks": row["n_networks"],
                "closed loop": f"{row['mean']:.4f} (sd {row['sd']:.4f})",
                "teacher forced": f"{forced[key]['mean']:.4f} (sd {forced[key]['sd']:.4f})",
            }
            for key, row in closed.items()
        ]
    )


def _p(p: float) -> str:
    return f"{p:.2g}" if np.isfinite(p) else "–"


def _estimate(d: float) -> str:
    return np.format_float_positional(d, 3, fractional=False, sign=True) if d else "0"


def _holm(row, column: str = "p_holm") -> str:
    """A Holm p (2 significant digits), or why the row has none: it is in no family."""
    if np.isfinite(row[column]):
        return f"{row[column]:.2g}"
    if not readings_science.is_hypothesis(row["measure"]):
        return (
            "not a hypothesis" if readings_science.is_null_control(row["measure"]) else "by excess"
        )
    return "identical" if str(row.get("identical")) == "True" else "no variation"


def _family(table: pd.DataFrame, column: str = "family", p: str = "p_holm") -> str:
    """The one family a table's adjusted p are Holm-adjusted within (``readings.FAMILY_*``)."""
    tested = table[p].map(np.isfinite) & table["measure"].map(readings_science.is_hypothesis)
    (family,) = set(table.loc[tested, column])
    return family


def _label(row) -> str:
    """A reading (``first · fixed``), or a comparison at a level of the other choice."""
    if "comparison" in row:
        name = "cue" if row["comparison"] == "cue_timing" else "Goal"
        return f"{name} · {text.CUE_LABELS.get(row['at'], row['at'])}"
    return f"{text.CUE_LABELS[row['cue']]} · {row['goal_response']}"


def _verdicts(table: pd.DataFrame) -> pd.DataFrame:
    """Measure and effect (rows) by reading or comparison (columns): the estimate and, for a
    hypothesis, its verdict (``readings.direction``, ``readings.difference_verdict``)."""
    rows: dict = {}
    for _, r in table.iterrows():
        cell = _estimate(r["diff"])
        if readings_science.is_hypothesis(r["measure"]):
            test = (
                readings_science.difference_verdict
                if "comparison" in r
                else readings_science.direction
            )
            cell += " " + text.WORDS.get(test(r), test(r))
        label = {"measure": text.MEASURE_LABELS[r["measure"]], "effect": r["effect"]}
        rows.setdefault((r["measure"], r["effect"]), label)[_label(r)] = cell
    return pd.DataFrame(list(rows.values()))


def _numbers(table: pd.DataFrame, name: str) -> pd.DataFrame:
    """Every row's estimate, interval, raw p and Holm p, its family in the column's name."""
    return pd.DataFrame(
        {
            name: table.apply(_label, axis=1),
            "measure": table["measure"].map(text.MEASURE_LABELS),
            "effect": table["effect"],
            "estimate [95% interval]": [
                f"{_estimate(d)} [{_estimate(a)}, {_estimate(b)}]"
                for d, a, b in table[["diff", "ci_low", "ci_high"]].to_numpy()
            ],
            "p": table["p"].map(lambda p: f"{p:.2g}" if np.isfinite(p) else "–"),
            f"Holm p, “{_family(table)}”": table.apply(_holm, axis=1),
        }
    )


def readings(inputs: Mapping[str, str], config: dict) -> tuple[dict, dict[str, pd.DataFrame]]:
    """The readings chapter: the Goal map's clusters under each response, the statistics of the
    readings x measures matrix and of the differences between readings, the verdict phrases on
    them (``text.reading_claims``, ``text.difference_claims``), and the tables: the matrix and
    the differences with their verdicts, every number of both (folded), the margins."""
    summary = pd.read_csv(inputs["readings_summary.csv"])
    diffs = pd.read_csv(inputs["readings_differences.csv"], keep_default_na=False, na_values=[""])
    values = {}
    for response, name in (("fixed", "soms.npz"), ("grows", "readings_grows_soms.npz")):
        if name in inputs:
            soms = load_npz(inputs[name])
            for o, obj in enumerate(soms["objects"].tolist()):
                for t, task in enumerate(soms["tasks"].tolist()):
                    values[f"goal_{response}_{obj}_{task}"] = active_units(soms["goal_act"][o, t])
    for table, stats in (
        (summary, ("diff", "p", "p_holm")),
        (diffs, ("diff", "p", "p_holm", "margin", "p_equivalence_holm")),
    ):  # a statistic, or None where there is none (a null control's Holm p, ...)
        for _, row in table.iterrows():
            values |= {
                text.stat_key(row, s): row[s] if np.isfinite(row[s]) else None for s in stats
            }
    values |= {
        "n_readings": int(summary["reading"].nunique()),
        "replications": " to ".join(map(str, sorted(set(summary["replications"])))),
        "n_hypotheses": int(np.isfinite(summary["p_holm"]).sum()),
        "n_differences": int(np.isfinite(diffs["p_holm"]).sum()),
        "n_equivalence": int(np.isfinite(diffs["p_equivalence_holm"]).sum()),
        "family": _family(summary),
        "family_differences": _family(diffs),
        "family_equivalence": _family(diffs, "family_equivalence", "p_equivalence_holm"),
    }
    values |= text.reading_claims(summary) | text.difference_claims(diffs, "cue_timing", "cue")
    values |= text.difference_claims(diffs, "goal_response", "goal")
    numbers = _numbers(summary, "reading")
    if (summary["replications"] > 1).any():
        counts = summary[["n_paper", "n_reversed", "replications"]].to_numpy()
        numbers["paper / reversed"] = [f"{a} / {b} of {n}" for a, b, n in counts]
    tost = [  # a TOST's Holm p with its margin; an identical difference had no TOST
        "–"
        if not np.isfinite(r["margin"])
        else _holm(r, "p_equivalence_holm")
        + (f" (±{r['margin']:g})" if np.isfinite(r["p_equivalence_holm"]) else "")
        for _, r in diffs.iterrows()
    ]
    declared, margins = (config["readings"][k] for k in ("margin_declared", "equivalence_margin"))
    shown = [m for m in margins if m in config["readings"]["measures"]]
    return values, {
        "readings_matrix": _verdicts(summary),
        "readings_summary": numbers,
        "readings_verdicts": _verdicts(diffs[diffs["measure"].map(readings_science.is_hypothesis)]),
        "readings_differences": _numbers(diffs, "comparison").assign(
            **{f"TOST Holm p (margin), “{values['family_equivalence']}”": tost}
        ),
        "readings_margins": pd.DataFrame(
            {
                "measure": [text.MEASURE_LABELS[m] for m in shown],
                "margin": [f"±{margins[m]:g}" for m in shown],
                "declared in": [declared[m]["commit"] for m in shown],
                "its results read before": [
                    "yes" if declared[m]["results_before"] else "no" for m in shown
                ],
            }
        ),
    }


def _term_values(prefix: str, term: dict) -> dict:
    """A tested term's numbers as page values (what a claim rests on)."""
    return {f"{prefix}_estimate": term["estimate"], f"{prefix}_p": term["p"]}


def _measure_terms(anova: dict):
    """The closed-loop tests of the paper's two effects on its measure and its two parts, as
    (key prefix, effect, test): "" the all-trials RMSE, "errors_", "rt_" the correct trials."""
    loop = anova["closed_loop"]
    for effect in ("congruency", "size"):
        yield "", effect, anova["contrasts"]["closed_loop"][effect]
        yield "errors_", effect, loop["errors"][effect]
        yield "rt_", effect, loop["correct_rt"][effect]


def headline(anova: dict) -> pd.DataFrame:
    """The front page's table: the paper's two effects (closed loop) on the paper's measure and
    its two parts, each with its test, its family, its p adjusted within it and a verdict word
    (``text.verdict_word``)."""
    closed = anova["closed_loop"]
    sources = {"contrasts": anova["contrasts"]["closed_loop"]} | {
        o: closed[o] for o in ("errors", "correct_rt")
    }
    rows = []
    for outcome, tests in sources.items():
        for effect in ("congruency", "size", "congruency:size"):
            term = tests[effect]
            rows.append(
                {
                    "measure": OUTCOME_LABELS[outcome],
                    "effect": text.term_name(effect),
                    "estimate [95% interval]": f"{term['estimate']:+.4f} {text.fmt_ci(term)}",
                    "df": term["df"],
                    "p": term["p"],
                    "family": term["family"],
                    "Holm p": term["p_holm"],
                    "verdict": text.claim_verdict(term, outcome, effect),
                }
            )
    return pd.DataFrame(rows)


def intro(anova: dict) -> dict:
    closed = anova["closed_loop"]
    means, contrasts = closed["means"], anova["contrasts"]["closed_loop"]
    wrong = science.wrong_grip_by_congruency(closed["wrong_grip_rate"])
    out = {
        "n_networks": closed["n_networks"],
        "cong": means["congruent"],
        "incong": means["incongruent"],
        "large": means["large"],
        "small": means["small"],
        "family_size": contrasts["congruency"]["family_size"],
        "wrong_congruent": wrong["congruent"],
        "wrong_incongruent": wrong["incongruent"],
    }
    for prefix, effect, term in _measure_terms(anova):
        out |= _term_values(f"{prefix}{effect}", term)
        out[f"{prefix}{effect}_p_holm"] = term["p_holm"]
        keys = (f"intro.{prefix}{effect}_estimate", f"intro.{prefix}{effect}_p_holm")
        out[f"{prefix}{effect}_verdict"] = text.Claim(text.verdict_word(term), keys)
        out[f"{prefix}{effect}_stats"] = text.fmt_term(term)
    out["rt_sentence"] = text.Claim(
        text.rt_phrase("congruency", closed["correct_rt"]["congruency"]),
        ("intro.rt_congruency_estimate", "intro.rt_congruency_p_holm"),
    )
    grip = closed["correct_rt"]["congruency:size"]
    out |= {"rt_grip_estimate": grip["estimate"], "rt_grip_p_holm": grip["p_holm"]}
    out["rt_grip_sentence"] = text.Claim(
        text.required_grip_phrase(grip), ("intro.rt_grip_estimate", "intro.rt_grip_p_holm")
    )
    out["errors_sentence"] = text.Claim(
        text.error_phrase(
            "congruency", closed["errors"]["congruency"], (wrong["congruent"], wrong["incongruent"])
        ),
        ("intro.errors_congruency_estimate", "intro.errors_congruency_p_holm"),
    )
    return out


def results(anova: dict, curve: dict, cue: str) -> dict:
    out = {
        "rmse_start": curve["start"],
        "rmse_2000": curve["around_at"],
        "at_2000": curve["at"],
        "rmse_phase1_end": curve["phase1_end"],
        "rmse_end": curve["end"],
        "n_networks": curve["n_networks"],
    }
    for mode in MODES:
        m = anova[mode]
        for key, value in m["means"].items():
            out[f"{mode}_{key}"] = value
        for analysis, _ in ANALYSES:
            for effect, r in m[analysis].items():
                out[f"{mode}_{analysis}_{effect}"] = text.fmt_f(r)
        for key, value in m["wrong_grip_rate"].items():
            out[f"{mode}_wrong_{key}"] = 100 * value
        contrasts = anova["contrasts"][mode]
        for term, r in contrasts.items():
            out[f"{mode}_contrast_{term.replace(':', '_x_')}"] = text.fmt_term(r)
        interaction = contrasts["congruency:size"]
        out[f"{mode}_interaction_p"] = interaction["p_holm"]
        for key, value in m["means_correct"].items():
            out[f"{mode}_correct_{key}"] = value
        for effect, short in (("congruency", "cong"), ("size", "size")):
            out |= _term_values(f"{mode}_{effect}", contrasts[effect])
            out[f"{mode}_{effect}_p_holm"] = contrasts[effect]["p_holm"]
            out[f"{mode}_{short}_sentence"] = text.Claim(
                text.results_sentence(
                    effect,
                    science.contrast_verdict(contrasts, effect),
                    interaction["p_holm"] < science.ALPHA,
                ),
                (
                    f"results.{mode}_{effect}_estimate",
                    f"results.{mode}_{effect}_p_holm",
                    f"results.{mode}_interaction_p",
                ),
            )
    out["n_trials"] = anova["closed_loop"]["n_trials"]
    out["n_networks_tested"] = anova["contrasts"]["closed_loop"]["congruency"]["networks"]
    out["df"] = anova["contrasts"]["closed_loop"]["congruency"]["df"]
    out["cue"] = text.CUES[cue]
    return out


def discussion(anova: dict, demos: dict, cue: str) -> dict:
    """The discussion's paragraphs, each a claim on this page's numbers, in ``order``."""
    gap = science.grip_distance(demos["angles"], demos["objects"].tolist())
    closed, forced = anova["contrasts"]["closed_loop"], anova["contrasts"]["teacher_forced"]
    simple, forced_simple = anova["simple"]["closed_loop"], anova["simple"]["teacher_forced"]
    loop = anova["closed_loop"]
    wrong = science.wrong_grip_by_congruency(loop["wrong_grip_rate"])
    out = (
        {"grip_distance_large": gap["large"], "grip_distance_small": gap["small"]}
        | {"forced_size_estimate": forced["size"]["estimate"]}
        | {"forced_size_p_holm": forced["size"]["p_holm"]}
        | {"forced_interaction_estimate": forced["congruency:size"]["estimate"]}
        | {"forced_interaction_p_holm": forced["congruency:size"]["p_holm"]}
        | {f"wrong_{k}": v for k, v in wrong.items()}
    )
    for prefix, effect, term in _measure_terms(anova):
        out |= _term_values(f"{prefix}{effect}", term)
        out[f"{prefix}{effect}_p_holm"] = term["p_holm"]
    grip = loop["correct_rt"]["congruency:size"]
    out |= {"rt_grip_estimate": grip["estimate"], "rt_grip_p_holm": grip["p_holm"]}
    for name, term in simple.items():
        out |= {f"{name}_estimate": term["estimate"], f"{name}_p_holm": term["p_holm"]}
    for name, term in forced_simple.items():
        out |= {
            f"forced_{name}_estimate": term["estimate"],
            f"forced_{name}_p_holm": term["p_holm"],
        }
    paragraphs = {
        "congruency_text": text.discussion_congruency(
            closed["congruency"],
            loop["errors"]["congruency"],
            loop["correct_rt"]["congruency"],
            wrong,
            cue,
        ),
        "size_text": text.discussion_size(
            closed["size"],
            loop["errors"]["size"],
            loop["correct_rt"]["size"],
            simple,
            wrong,
            loop["correct_rt"]["congruency:size"],
        ),
        "forced_text": text.discussion_forced(forced, forced_simple),
        "readings_text": text.discussion_readings(cue),
    }
    return out | paragraphs | {"order": list(paragraphs)}


def comparison(anova: dict, curve: dict, config: dict) -> pd.DataFrame:
    """The paper's numbers beside this run's (closed loop, repeated-measures ANOVA)."""
    net, closed = config["network"], anova["closed_loop"]
    m = closed["means"]

    def effect(name: str) -> str:
        first, second = science.PAPER_ORDER[name]
        lower = first if m[first] < m[second] else second
        return (
            f"closed loop, {lower} lower: {first} {m[first]:.4f}, {second} {m[second]:.4f}; "
            "per-network contrast "
            f"{text.fmt_term(anova['contrasts']['closed_loop'][name])}"
        )

    at, n = curve["at"], closed["n_networks"]
    sequences = config["demos"]["sequences"]
    rows = [
        ("RMSE at the start of training", "start", f"{curve['start']:.3f} (first 10 iterations)"),
        (
            "RMSE after about 2000 iterations",
            "around_2000",
            f"{curve['around_at']:.3f} (iterations {at - 100}-{at + 100})",
        ),
        ("RMSE afterwards", "end", f"{curve['end']:.3f} (last 500 iterations)"),
        ("congruent vs incongruent", "congruency", effect("congruency")),
        ("large vs small objects", "size", effect("size")),
        ("networks", "networks", f"{n} ({n // 2} per mapping)"),
        ("learning rate", "learning_rate", f"{net['learning_rate']}"),
        (
            "iterations",
            "iterations",
            f"{net['iterations']:,} ({net['phase1_iterations']} + "
            f"{net['iterations'] - net['phase1_iterations']})",
        ),
        ("hidden units", "hidden", f"{net['hidden']}"),
        ("sequences per object (train + test)", "sequences", f"{sequences} ({sequences - 1} + 1)"),
    ]
    return pd.DataFrame(
        [(quantity, PAPER[key], run) for quantity, key, run in rows],
        columns=["quantity", "paper", "this run"],
    )


def _robot_values(emb: dict, own_effects: dict) -> dict:
    """The chapter beyond the paper's robot numbers and sentences: ``emb`` is
    ``embodied/analysis.json``, ``own_effects`` the config's own networks' entry of
    ``embodied/effects.json``; every count over distinct trials, and every sentence that states
    an effect a ``text.Claim`` resting on the statistics stored beside it."""
    robot = science.robot_verdicts(emb)
    err, suc = emb["measures"]["final_error"], emb["measures"]["success"]
    out = {
        "emb_n_trials": emb["n_trials"],
        "emb_n_networks": emb["n_networks"],
        "emb_success": text.pct(emb["success_rate"]),
        "emb_grasping_success": text.pct(emb["grasping_success"]),
        "emb_categorisation_success": text.pct(emb["categorisation_success"]),
        "emb_categorisation_rate": float(emb["categorisation_success"]),
        "emb_success_rate": float(emb["success_rate"]),
        "emb_touching": text.pct(emb["touching_rate"]),
        "emb_wrong_grip_holds": int(emb["wrong_grip_holds"]),
        "replay_commands": text.pct(emb["replay_success"]["commands"]),
        "replay_sensed": text.pct(emb["replay_success"]["sensed_postures"]),
        "replay_sensed_rate": float(emb["replay_success"]["sensed_postures"]),
        "replay_commands_wrong_grip": int(emb["replay_wrong_grip_holds"]["commands"]),
        "replay_commands_trials": int(emb["replay_trials"]["commands"]),
        "err_congruent": err["means"]["congruent"],
        "err_incongruent": err["means"]["incongruent"],
        "err_large": err["means"]["large"],
        "err_small": err["means"]["small"],
    }
    # the final posture error: per-network contrasts (t over networks) are the test
    for effect in ("congruency", "size"):
        term = (err["contrasts"] or {}).get(effect)
        out[f"emb_final_error_{effect}_estimate"] = term["estimate"] if term else float("nan")
        out[f"emb_final_error_{effect}_p"] = term["p"] if term else float("nan")
        out[f"emb_final_error_{effect}_p_holm"] = term["p_holm"] if term else float("nan")
        out[f"emb_final_error_{effect}"] = text.Claim(
            text.fmt_term(term) if term else "not estimable",
            (
                f"beyond.emb_final_error_{effect}_estimate",
                f"beyond.emb_final_error_{effect}_p_holm",
            ),
        )
    # success: the per-network contrast, or the exact test over distinct trials without variance
    stats = science.robot_effect_statistics(own_effects["success"], "congruency")
    out["emb_success_congruency_estimate"] = stats["estimate"]
    out["emb_success_congruency_p"] = stats["p"]
    out["emb_success_congruency"] = text.Claim(
        _robot_effect_text(own_effects["success"], "success", "congruency"),
        ("beyond.emb_success_congruency_estimate", "beyond.emb_success_congruency_p"),
    )
    err_verdict = (
        science.contrast_verdict(err["contrasts"], "congruency")
        if err["contrasts"]
        else science.Verdict(paper_direction=False, significant=False)
    )
    out |= {
        "suc_congruent": text.pct(suc["means"]["congruent"]),
        "suc_incongruent": text.pct(suc["means"]["incongruent"]),
        "suc_diff": text.points_difference(suc["incongruent_minus_congruent"]),
        "emb_err_sentence": text.Claim(
            text.robot_error_sentence(err_verdict),
            (
                "beyond.emb_final_error_congruency_estimate",
                "beyond.emb_final_error_congruency_p_holm",
            ),
        ),
        "emb_ceiling_sentence": text.Claim(
            "below" if robot["below_ceiling"] else "at or above",
            ("beyond.emb_success_rate", "beyond.replay_sensed_rate"),
        ),
        "replay_wrong_sentence": text.Claim(
            (
                f"{out['replay_commands_wrong_grip']} of these {out['replay_commands_trials']} "
                "replays held the object with a grip other than the one demonstrated (the "
                "touch sensors read power in a precision grasp) and count as failures."
            )
            if out["replay_commands_wrong_grip"]
            else "",
            ("beyond.replay_commands_wrong_grip", "beyond.replay_commands_trials"),
        ),
        "floor_sentence": text.Claim(
            text.floor_sentence(robot["at_floor"]), ("beyond.emb_categorisation_rate",)
        ),
    }
    return out


def beyond(inputs: Mapping[str, str], config: dict, ablation_cue: str) -> tuple[dict, pd.DataFrame]:
    """The robot test, the cue ablation and the hidden layer; and the cue ablation's ANOVAs."""
    emb = _json(inputs["embodied_analysis.json"])
    # each run's tests in its own families (anova.json: the main run's confirmatory, the
    # ablation's exploration)
    main, ablation = _json(inputs["anova.json"]), _json(inputs["ablation_anova.json"])
    divergence = pd.read_csv(inputs["divergence.csv"])
    first_step = _json(inputs["divergence.json"])["first_divergent_step"]
    explained = pd.read_csv(inputs["hidden_explained.csv"])
    out = {
        "n_steps": config["demos"]["steps"],
        "n_predicted": config["demos"]["steps"] - 1,
        "n_hidden": config["network"]["hidden"],
    }
    # the config's own networks' robot effects, over distinct trials (effects.json's main run)
    out |= _robot_values(emb, _json(inputs["robot_effects.json"])[OWN])

    # the cue ablation: which reading of the paper's cue gives the effect
    main_cue = config["network"]["categorisation_cue"]
    rows = []
    for cue, result in ((main_cue, main), (ablation_cue, ablation)):
        for mode in MODES:
            for effect in ("congruency", "size", "interaction"):
                e = result[mode]["repeated_measures"][effect]
                rows.append(
                    {
                        "cue": cue.replace("_", " "),
                        "test": mode.replace("_", " "),
                        "effect": effect,
                        "F": e["F"],
                        "df": f"({e['df1']:.0f}, {e['df2']:.0f})",
                        "p": e["p"],
                        "partial η²": e["eta_p2"],
                    }
                )
    for name, result in (("main", main), ("ablation", ablation)):
        m, contrasts = result["closed_loop"], result["contrasts"]["closed_loop"]
        out |= {
            f"cue_{name}_congruent": m["means"]["congruent"],
            f"cue_{name}_incongruent": m["means"]["incongruent"],
            f"cue_{name}_congruency": text.fmt_term(contrasts["congruency"]),
            f"cue_{name}_size": text.fmt_term(contrasts["size"]),
        }
        out |= _term_values(f"cue_{name}_congruency", contrasts["congruency"])
        out[f"cue_{name}_verdict"] = text.Claim(
            text.cue_verdict(science.contrast_verdict(contrasts, "congruency")),
            (f"beyond.cue_{name}_congruency_estimate", f"beyond.cue_{name}_congruency_p"),
        )
    # the test of the difference: first step only minus every step, paired by network
    difference = _json(inputs["cue_difference.json"])["congruency"]
    # its verdict is the readings' table's, Holm-adjusted over that table's family of tests
    differences = pd.read_csv(inputs["readings_differences.csv"])
    row = differences[
        (differences["comparison"] == "cue_timing")
        & (differences["at"] == config["soms"]["goal_response"])
        & (differences["measure"] == "rmse")
        & (differences["effect"] == "congruency")
    ]
    if len(row) == 1:
        difference["p_holm"] = float(row["p_holm"].iloc[0])
        difference["family"] = str(row["family"].iloc[0]) if "family" in row else "readings"
    out |= _term_values("cue_difference", difference)
    out["cue_difference_p_holm"] = difference.get("p_holm", difference["p"])
    out |= {
        "main_cue_phrase": text.CUES[main_cue],
        "ablation_cue_phrase": text.CUES[ablation_cue],
        "cue_explanation": text.cue_difference(difference),
    }

    # the hidden layer
    out |= {
        "div_last_cong": float(divergence["congruent"].iloc[-1]),
        "div_last_incong": float(divergence["incongruent"].iloc[-1]),
        "div_step1_cong": float(divergence["congruent"].iloc[0]),
        "div_step1_incong": float(divergence["incongruent"].iloc[0]),
        "div_first_step": float("nan") if first_step is None else first_step,
        "div_sentence": text.divergence_sentence(first_step),
        "pca_explained": text.pct(science.explained_by_two_axes(explained)),
    }
    return out, pd.DataFrame(rows)


def _variant_label(row: Mapping) -> str:
    return NetworkVariant.from_row(row).label()


def _schedule_sentence(pairs: list[dict]) -> str:
    """The robot variants of this build that differ in the learning-rate schedule alone,
    compared on the same networks' grasping trials (``robot_statistics.paired_grasping``)."""
    if not pairs:
        return "No two variants of this build differ in the learning-rate schedule alone."
    said = []
    for p in pairs:
        a, b = SCHEDULE_WORDS[p["a"]], SCHEDULE_WORDS[p["b"]]
        said.append(
            f"with the cue {CUE_WORDS.get(p['categorisation_cue'], p['categorisation_cue'])}, "
            f"{p['target']}, {int(p['hidden'])} hidden and {int(p['iterations']):,} iterations, "
            f"the {a} holds the object in {p['held_a']} and the {b} in {p['held_b']} of the "
            f"same {p['trials']} grasping trials (network and object); {p['only_a']} are held "
            f"only with the {a} and {p['only_b']} only with the {b} (exact McNemar test "
            f"{text.fmt_p(p['p'])})"
        )
    return "Variants that differ in the learning-rate schedule alone: " + "; ".join(said) + "."


#: The cue timings in words.
CUE_WORDS = {"first_step": "at the first step only", "all_steps": "at every step"}


def _cue_sentence(variants: pd.DataFrame) -> str:
    """The robot variants of this build that differ in the cue timing only, side by side."""
    same = [k for k in NetworkVariant.keys() if k != "categorisation_cue"]
    pairs = []
    for _, mine in variants.groupby(same, sort=True):
        if mine["categorisation_cue"].nunique() < 2:
            continue
        held = ", ".join(
            f"{text.pct(row['grasping_success'])} with the cue "
            f"{CUE_WORDS.get(row['categorisation_cue'], row['categorisation_cue'])}"
            for _, row in mine.sort_values("categorisation_cue", ascending=False).iterrows()
        )
        variant = NetworkVariant.from_row(mine.iloc[0])
        pairs.append(f"{variant.label(leave_out=('categorisation_cue',))}: {held}")
    if not pairs:
        return "No two variants of this build differ in the cue timing alone."
    return (
        "Variants that differ in the cue timing alone hold the object in their grasping trials: "
        + "; ".join(pairs)
        + "."
    )


def _confirmation(confirmation: pd.DataFrame, seed: int) -> dict:
    """Explore, then confirm (config robot.confirmation; data/embodied/confirmation.csv): each
    confirmed variant's share on the networks it was chosen on and on fresh ones, each with its
    clustered interval, and the bar set against the confirmation's interval only. The statistics
    are numbers named ``{seed set}_{statistic}`` (``_{k}`` appended for the k-th variant from the
    second on); the two sentences are ``text.Claim`` s resting on them."""
    if confirmation.empty:
        none = (
            "This build confirms no variant (config robot.confirmation.variants is empty), so no "
            "share is set against the bar."
        )
        return {"exploration_sentence": "", "confirmation_sentence": none}
    bar = text.pct(science.GRASPS)
    out: dict[str, object] = {"bar_share": float(science.GRASPS)}
    said_bar = {
        "above": f"the confirmation's interval lies above {bar}, so the variant's rate of "
        f"holding the object is above {bar} (at 95% confidence)",
        "includes": f"the confirmation's interval includes {bar}, so these networks cannot tell "
        f"whether the variant's rate is above or below {bar}",
        "below": f"the confirmation's interval lies below {bar}, so the variant's rate of "
        f"holding the object is below {bar} (at 95% confidence)",
    }
    counts = ("networks", "first_network", "last_network", "trials", "held")
    entries = {"exploration": [], "confirmation": ["grasping.bar_share"]}
    said: dict[str, list[str]] = {"exploration": [], "confirmation": []}
    explored = confirmation[confirmation["seed_set"] == "exploration"]
    for k, (_, row) in enumerate(explored.iterrows()):
        suffix = "" if k == 0 else f"_{k + 1}"
        mine = confirmation[(confirmation["seed_set"] == "confirmation")].iloc[k]
        v = {}
        for name, source in (("exploration", row), ("confirmation", mine)):
            for column in (*counts, "share", "ci_low", "ci_high"):
                value = source[column]
                v[name, column] = int(value) if column in counts else float(value)
                out[f"{name}_{column}{suffix}"] = v[name, column]
                entries[name].append(f"grasping.{name}_{column}{suffix}")

        def share(name: str, v=v) -> str:
            low, high = text.pct(v[name, "ci_low"]), text.pct(v[name, "ci_high"])
            return (
                f"{v[name, 'held']} of its {v[name, 'trials']} distinct grasping trials "
                f"({text.pct(v[name, 'share'])}; 95% interval {low} to {high})"
            )

        def networks(name: str, v=v) -> str:
            return f"seed {seed}'s networks {v[name, 'first_network']}-{v[name, 'last_network']}"

        label = f"the variant ({_variant_label(row)})"
        verdict = confirmation_science.bar_verdict(
            v["confirmation", "ci_low"], v["confirmation", "ci_high"], science.GRASPS
        )
        out[f"confirmation_verdict{suffix}"] = verdict
        said["exploration"].append(
            f"on the networks it was chosen on ({networks('exploration')}, on which the grid and "
            f"the schedule were tried: the exploration), {label} holds the object in "
            f"{share('exploration')}"
        )
        out[f"confirmation_design_effect_raw{suffix}"] = float(mine["design_effect_raw"])
        entries["confirmation"].append(f"grasping.confirmation_design_effect_raw{suffix}")
        misses = [
            f"{o.replace('_', ' ')} ({m}) {int(mine[f'{m}_{o}_trials'] - mine[f'{m}_{o}_held'])} "
            f"of {int(mine[f'{m}_{o}_trials'])}"
            for m in confirmation_science.MAPPINGS
            for o in confirmation_science.OBJECT_NAMES
            if mine[f"{m}_{o}_held"] < mine[f"{m}_{o}_trials"]
        ]
        raw = float(mine["design_effect_raw"])
        raw_design = (
            f"the raw design effect, before the interval floors it at 1, {raw:.3f}"
            if np.isfinite(raw)
            else "no design effect: every trial or none was held, so there is no spread"
        )
        said["confirmation"].append(
            f"on {v['confirmation', 'networks']} fresh networks ({networks('confirmation')}, "
            "never used to choose it; the same demonstrations and maps), "
            f"{'it' if len(explored) == 1 else label} holds the object in "
            f"{share('confirmation')}: {said_bar[verdict]} ({raw_design}; the trials it missed, "
            f"per object and mapping: {'; '.join(misses) or 'none'})"
        )
    out["exploration_sentence"] = text.Claim(
        "Counted once per network and object, and with an interval that takes each network's "
        "four objects as one cluster (Korn and Graubard's: Clopper-Pearson's exact interval at "
        "the effective number of trials): "
        + "; ".join(said["exploration"])
        + f". That share is the data the variant was chosen on, so the choice biases it upwards, "
        f"and the bar of {bar} is not set against it.",
        tuple(entries["exploration"]),
    )
    out["confirmation_sentence"] = text.Claim(
        "Trained again and tested by the same rules, " + "; ".join(said["confirmation"]) + ".",
        tuple(entries["confirmation"]),
    )
    return out


def _palm_sentence(best: Mapping, own: Mapping, replay: Mapping) -> str:
    """Where the learned networks' palms end, beside where the demonstrations' own ends
    (``replay``: ``robot_statistics.replay_palm``)."""
    return (
        f"In their grasping trials the best variant's palm ends a median "
        f"{best['grasping_palm_error_mm']:.1f} mm from the demonstrator's, the config's own "
        f"networks' {own['grasping_palm_error_mm']:.1f} mm. The demonstrations themselves, "
        f"replayed through the same controller, end a median "
        f"{replay['palm_error_mm_median']:.1f} mm from that mean (at most "
        f"{replay['palm_error_mm_max']:.1f} mm) and hold the object in "
        f"{text.pct(replay['held'])} of their {replay['trials']} replays."
    )


def _palm_table(sources: dict[str, pd.DataFrame]) -> pd.DataFrame:
    """Share held per bin of palm error, one column per source of trials (each its
    ``embodied_stats.held_by_palm_error`` table)."""
    columns = {}
    for name, bins in sources.items():
        columns[name] = [
            f"{text.pct(row['held'])} of {int(row['trials'])}" if row["trials"] else ""
            for _, row in bins.iterrows()
        ]
    labels = [
        f"{low:g}-{high:g} mm" if np.isfinite(high) else f"{low:g} mm or more"
        for low, high in zip(bins["low_mm"], bins["high_mm"], strict=True)
    ]
    return pd.DataFrame({"palm error": labels} | columns)


def _level_counts(effect: dict, measure: str, factor: str) -> str:
    """The two levels' distinct trials of one robot effect, the paper's faster level first, and
    every congruency x size cell's beside them: an effect can come from one cell alone."""
    first, second = FACTOR_LEVELS[factor]
    a, b = effect[factor][first], effect[factor][second]
    if measure == "success":
        verb, x, y = "held", round(a["mean"] * a["trials"]), round(b["mean"] * b["trials"])
    else:
        verb, x, y = "touched", a["n"], b["n"]
    return (
        f"{verb} in {x} of {a['trials']} distinct {first} trials and {y} of {b['trials']} "
        f"{second}; per cell, {_cell_counts(effect, measure)}"
    )


def _cell_counts(effect: dict, measure: str) -> str:
    """Each congruency x size cell's count of the measure over its distinct trials."""
    counted = "held" if measure == "success" else "touched"
    return ", ".join(
        f"{name.replace('_', ' ')} {cell[counted]}/{cell['trials']}"
        for name, cell in effect["cells"].items()
    )


def _robot_effect_text(effect: dict, measure: str, factor: str) -> str:
    """One variant's effect of ``factor`` on a robot ``measure``, in words and numbers, over its
    distinct trials (``effects.json``: one per network x object)."""
    verdict = science.robot_effect_verdict(effect, measure, factor)
    test = effect["tests"][factor]
    first, second = FACTOR_LEVELS[factor]
    counts = _level_counts(effect, measure, factor)
    if verdict is None:
        return f"not estimable ({counts}; {test['reason']})"
    if test["method"] == "contrasts":
        unit = " s" if measure == "contact_time" else ""
        what = "share held" if measure == "success" else "contact time"
        numbers = (
            f"{counts}; per-network contrast of the {what}, {second} minus {first}, "
            f"{test['estimate']:+.3f}{unit}, 95% interval {text.fmt_ci(test)}, "
            f"t({test['df']:.0f}) = {test['t']:.2f}, {text.fmt_p(test['p'])}{_holm_words(test)}, "
            f"{test['networks']} networks"
        )
    else:
        (x, x_no), (y, y_no) = test["table"]
        if x * (y + y_no) == y * (x + x_no):  # the same rate in both conditions
            return f"no difference ({counts})"
        numbers = f"{counts}; Fisher's exact test, {text.fmt_p(test['p'])}{_holm_words(test)}"
    if not verdict.significant:  # a direction is not claimed from a test that does not show it
        return f"not shown ({numbers})"
    grip = effect["tests"][INTERACTION]
    if grip["method"] == "contrasts" and grip["p_holm"] < science.ALPHA:
        numbers += (
            "; the congruency × size term is shown too, so this difference is an average over "
            "cells that differ with the required grip, not an effect of every cell"
        )
    return f"{text.paper_agreement(verdict)} ({numbers})"


def _robot_interaction_text(effect: dict, measure: str) -> str:
    """The congruency x size term of a robot measure: twice the required grip's difference
    (power - precision), which has no paper direction; shown or not within its family."""
    test = effect["tests"][INTERACTION]
    cells = _cell_counts(effect, measure)
    if test["method"] != "contrasts":
        return f"not tested (per cell, {cells}; {test['reason']})"
    shown = "shown" if test["p_holm"] < science.ALPHA else "not shown"
    return (
        f"{shown}: {test['estimate']:+.3f}, 95% interval {text.fmt_ci(test)}, "
        f"t({test['df']:.0f}) = {test['t']:.2f}, {text.fmt_p(test['p'])}{_holm_words(test)} "
        f"(per cell, {cells})"
    )


def _object_misses(effect: dict) -> str:
    """The objects a variant did not hold in every categorisation trial, per mapping."""
    misses = [
        f"{name.replace('_', ' ')} {cell['trials'] - cell['held']} of {cell['trials']}"
        for name, cell in effect["objects"].items()
        if cell["held"] < cell["trials"]
    ]
    return "; ".join(misses) if misses else "none"


def _holm_words(test: dict) -> str:
    if "p_holm" not in test:
        return ""
    return f", {text.fmt_family(test)}"


def _robot_effect_values(effects: dict, run: str, key: str, page: str = "grasping") -> dict:
    """For one variant (``key``: own or best) each robot effect's sentence, a ``text.Claim``
    resting on its difference and p, which are stored beside it; the required-grip term and the
    misses per object beside them."""
    out: dict[str, object] = {}
    for measure in ("success", "contact_time"):
        effect = effects[run][measure]
        for factor in FACTOR_LEVELS:
            name = f"{key}_{measure}_{factor}"
            stats = science.robot_effect_statistics(effect, factor)
            out[f"{name}_estimate"], out[f"{name}_p"] = stats["estimate"], stats["p"]
            out[name] = text.Claim(
                _robot_effect_text(effect, measure, factor),
                (f"{page}.{name}_estimate", f"{page}.{name}_p"),
            )
        name = f"{key}_{measure}_interaction"
        test = effect["tests"][INTERACTION]
        out[f"{name}_estimate"] = test.get("estimate", float("nan"))
        out[f"{name}_p_holm"] = test.get("p_holm", float("nan"))
        out[name] = text.Claim(
            _robot_interaction_text(effect, measure),
            (f"{page}.{name}_estimate", f"{page}.{name}_p_holm"),
        )
    out[f"{key}_misses"] = _object_misses(effects[run]["success"])
    return out


def _wrong_grip_values(variants: pd.DataFrame) -> dict:
    """How many distinct trials the grip criterion fails (held, but with the other grip), in
    all variants together and per task; and the sentence that says so."""
    grasp = int(variants["grasping_wrong_grip_hold"].sum())
    cat = int(variants["categorisation_wrong_grip_hold"].sum())
    trials = int(variants["trials"].sum())
    if grasp + cat == 0:
        words = (
            f"No distinct trial of any variant ({trials} in all) held the object with a grip "
            "other than the required one."
        )
    else:
        words = (
            f"Of the {trials} distinct trials of all variants, {grasp + cat} held the object "
            f"with a grip other than the required one ({grasp} grasping, {cat} "
            "categorisation) and count as failures; the table's last column gives them per "
            "variant."
        )
    return {
        "wrong_grip_grasping": grasp,
        "wrong_grip_categorisation": cat,
        "wrong_grip_trials": trials,
        "wrong_grip_sentence": text.Claim(
            words,
            (
                "grasping.wrong_grip_grasping",
                "grasping.wrong_grip_categorisation",
                "grasping.wrong_grip_trials",
            ),
        ),
    }


def grasping(inputs: Mapping[str, str], config: dict) -> tuple[dict, dict[str, pd.DataFrame]]:
    """The robot grasps with what it learned: the variants' success, the best and the smallest
    that grasps, and the congruency and size effects on success and contact time."""
    variants = pd.read_csv(inputs["robot_variants.csv"])
    effects = _json(inputs["robot_effects.json"])
    anova = _json(inputs["anova.json"])
    robot_stats = _json(inputs["robot_statistics.json"])
    tolerance = record_table(robot_stats["tolerance"])
    tolerated = science.tolerated_noise(tolerance)
    exact = tolerance[tolerance["noise"] == 0].iloc[0]  # config checks: noise 0 is listed
    own = variants[variants["run"] == OWN].iloc[0]
    best = science.best_robot_variant(variants)
    smallest = science.smallest_that_grasps(variants)
    animated = config["robot"]["animation"]["variant"]
    network = config["network"]
    animated = {
        "categorisation_cue": network["categorisation_cue"],
        "learning_rate_schedule": network["learning_rate_schedule"],
    } | animated
    out = {
        "bar": text.pct(science.GRASPS),
        "n_variants": len(variants),
        "n_networks": int(own["networks"]),
        "own_label": _variant_label(own),
        "own_grasping": text.pct(own["grasping_success"]),
        "own_categorisation": text.pct(own["categorisation_success"]),
        "best_label": _variant_label(best),
        "best_grasping": text.pct(best["grasping_success"]),
        "best_categorisation": text.pct(best["categorisation_success"]),
        "best_contact": text.pct(best["grasping_contact"]),
        "smallest_sentence": (
            f"The smallest variant that holds the object in at least {text.pct(science.GRASPS)} "
            f"of its grasping trials on these networks is {_variant_label(smallest)} "
            f"({text.pct(smallest['grasping_success'])}), a share on the networks the variants "
            "were compared on, not a test against the bar."
            if smallest is not None
            else f"No variant tested in this build holds the object in "
            f"{text.pct(science.GRASPS)} of its grasping trials: the issue's bar is not met."
        ),
        "grid_sentence": (
            "This build tested the whole grid (robustness)."
            if config["robustness"]
            else "This build tested only the config's own networks and the variants that config "
            "robot.default lists; a build with robustness=True tests the whole grid."
        ),
        "animated_label": _variant_label(animated),
        "best_palm_error": f"{best['grasping_palm_error_mm']:.0f} mm",
        "own_palm_error": f"{own['grasping_palm_error_mm']:.0f} mm",
        "tolerance_exact": (
            f"the plan holds the object in {text.pct(exact['success'])} of its "
            f"{int(exact['trials'])} trials, its palm {exact['palm_error_mm']:.1f} mm (median) "
            "from the demonstrator's"
        ),
        "tolerance_sentence": (
            f"The largest arm noise at which the plan holds the object in at least "
            f"{text.pct(science.GRASPS)} of the trials is {tolerated['noise']:g} (0-1 units), "
            f"where the palm ends {tolerated['palm_error_mm']:.1f} mm (median) from the "
            f"demonstrator's ({text.pct(tolerated['success'])} held)."
            if tolerated is not None
            else f"At no arm noise tested does the plan hold the object in "
            f"{text.pct(science.GRASPS)} of the trials."
        ),
        "palm_sentence": _palm_sentence(best, own, robot_stats["replay"]),
        **_confirmation(pd.read_csv(inputs["robot_confirmation.csv"]), config["seed"]),
        "cue_sentence": _cue_sentence(variants),
        "schedule_sentence": _schedule_sentence(robot_stats["schedule_pairs"]),
        "rmse_congruency": text.fmt_term(anova["contrasts"]["closed_loop"]["congruency"]),
        "rmse_size": text.fmt_term(anova["contrasts"]["closed_loop"]["size"]),
    }
    rows = []
    for _, row in variants.iterrows():
        effect = effects[row["run"]]
        for measure in ("success", "contact_time"):
            for factor in FACTOR_LEVELS:
                rows.append(
                    {
                        "variant": _variant_label(row),
                        "measure": measure.replace("_", " "),
                        "factor": factor,
                        "distinct trials": effect[measure]["distinct_trials"],
                        "method": effect[measure]["tests"][factor]["method"],
                        "result": _robot_effect_text(effect[measure], measure, factor),
                    }
                )
            rows.append(
                {
                    "variant": _variant_label(row),
                    "measure": measure.replace("_", " "),
                    "factor": "congruency × size (2 × required grip, power − precision)",
                    "distinct trials": effect[measure]["distinct_trials"],
                    "method": effect[measure]["tests"][INTERACTION]["method"],
                    "result": _robot_interaction_text(effect[measure], measure),
                }
            )
    for key, row in (("own", own), ("best", best)):
        out |= _robot_effect_values(effects, row["run"], key)
    out |= _wrong_grip_values(variants)
    table = variants.assign(
        variant=[_variant_label(r) for _, r in variants.iterrows()],
        grasping=[text.pct(v) for v in variants["grasping_success"]],
        categorisation=[text.pct(v) for v in variants["categorisation_success"]],
        touched=[text.pct(v) for v in variants["grasping_contact"]],
        contact_time=[
            f"{v:.2f} s" if np.isfinite(v) else "" for v in variants["grasping_contact_time"]
        ],
        palm_error=[f"{v:.0f} mm" for v in variants["grasping_palm_error_mm"]],
        wrong_grip=[
            f"{int(g)} + {int(c)}"
            for g, c in zip(
                variants["grasping_wrong_grip_hold"],
                variants["categorisation_wrong_grip_hold"],
                strict=True,
            )
        ],
    )
    table = table.rename(columns={"grasping_trials": "distinct trials per task"})
    shown = ["variant", "networks", "distinct trials per task", "grasping", "categorisation"]
    shown += ["touched", "contact_time", "palm_error"]
    table = table[[*shown, "wrong_grip"]].rename(
        columns={"wrong_grip": "held with the other grip (grasping + categorisation)"}
    )
    objects = [c.removesuffix("_success") for c in tolerance.columns if c.endswith("_success")]
    tolerance_shown = pd.DataFrame(
        {
            "arm noise (0-1 units)": [f"σ = {v:g}" for v in tolerance["noise"]],
            "trials": tolerance["trials"].astype(int),
            "held": [text.pct(v) for v in tolerance["success"]],
            "palm error (median)": [f"{v:.1f} mm" for v in tolerance["palm_error_mm"]],
        }
        | {
            obj.replace("_", " "): [text.pct(v) for v in tolerance[f"{obj}_success"]]
            for obj in objects
        }
    )
    bins = robot_stats["held_by_palm_error"]
    palm = _palm_table(
        {
            "mean plan, arm offset": record_table(bins["tolerance"]),
            "demonstrations replayed": record_table(bins["replay"]),
            f"best variant ({_variant_label(best)})": record_table(bins["runs"][best["run"]]),
            "config's own networks": record_table(bins["runs"][OWN]),
        }
    )
    return out, {
        "robot_palm": palm,
        "robot_variants": table,
        "robot_effects": pd.DataFrame(rows),
        "robot_tolerance": tolerance_shown,
    }


def robustness(inputs: Mapping[str, str], config: dict) -> tuple[dict, pd.DataFrame | None]:
    """The sweep's sentences and table, or what the page says when this build did not run it."""
    if not config["robustness"]:
        return {"ran": False, "not_run": text.robustness_not_run(config)}, None
    from icub_workflow.sweep_timing import read_cost_table  # the cost table's columns, checked

    summary = pd.read_csv(inputs["sweep_summary.csv"])
    cost = read_cost_table(inputs["sweep_cost.csv"])
    n_points, n_networks = text.sweep_size(config)
    seeds = config["sweep"]["seeds"]
    settings = f"each of {len(summary)} settings" if len(summary) > 1 else "one setting"
    return {
        "ran": True,
        "sweep_run": (
            f"This build ran the sweep: {len(seeds)} replications (seeds "
            f"{', '.join(map(str, seeds))}) of {settings}, {n_points} points of "
            f"{config['network']['networks']} networks, {n_networks} networks in all."
        ),
        "sweep_findings": text.sweep_findings(summary),
        "cost_findings": text.cost_findings(
            cost, cost_growth(cost["replications"], cost["seconds"])
        ),
    }, text.sweep_summary_display(summary)


def training(inputs: Mapping[str, str], config: dict) -> dict:
    net, dem = config["network"], config["demos"]
    demos = science.demo_counts(pd.read_csv(inputs["demo_summary.csv"]))
    return {
        "n_demos": demos["n_demos"],
        "n_attempts": demos["n_attempts"],
        "n_retried": demos["n_retried"],
        "lift_min": demos["lift_min_cm"],
        "lift_check": dem["lift_m"] * 100,
        "yaw": dem["yaw_deg"],
        "tilt": dem["tilt_deg"],
        "shift": dem["shift_m"] * 1000,
        "lr": net["learning_rate"],
        "iterations": net["iterations"],
        "phase1": net["phase1_iterations"],
        "phase2_start": net["phase1_iterations"] + 1,
        "phase2_half": (net["iterations"] - net["phase1_iterations"]) // 2,
        "networks": net["networks"],
        "half_networks": net["networks"] // 2,
        "cue": net["categorisation_cue"].replace("_", " "),
        "n_sequences": dem["sequences"],
        "n_train_sequences": dem["sequences"] - 1,
        "n_steps": dem["steps"],
        "last_step": dem["steps"] - 1,
    }


def vision(inputs: Mapping[str, str], config: dict) -> dict:
    cells = science.edge_cells(load_npz(inputs["visual_maps.npz"]))
    return {f"cells_{name}": n for name, n in cells.items()} | {
        "window": config["vision"]["window"],
        "threshold": config["vision"]["edge_threshold"],
    }


def robot(inputs: Mapping[str, str]) -> dict:
    return science.joint_counts(pd.read_csv(inputs["joint_table.csv"]))


def architecture(inputs: Mapping[str, str], config: dict) -> dict:
    soms = load_npz(inputs["soms.npz"])
    units = {
        f"units_{obj}": active_units(act)
        for obj, act in zip(soms["objects"].tolist(), soms["object_act"], strict=True)
    }
    return units | {
        "width_per_edge": config["soms"]["object_width_per_edge"],
        "bump_sigma": config["soms"]["bump_sigma"],
        "hidden": config["network"]["hidden"],
    }


def notes(config: dict) -> dict:
    sizes = config["object_sizes_m"]
    return {
        "seed": config["seed"],
        "init_scale": config["network"]["init_scale"],
        "som_iterations": config["soms"]["iterations"],
        "big_cm": 100 * sizes["big_ball"],
        "small_cm": 100 * sizes["small_ball"],
        "big_cube_cm": 100 * sizes["big_cube"],
        "small_cube_cm": 100 * sizes["small_cube"],
    }


def _study_table(path: str) -> pd.DataFrame:
    """A size-study table with its doses as numbers (the controls' names stay)."""
    frame = pd.read_csv(path)
    if "dose" in frame:
        frame["dose"] = [dose_value(d) for d in frame["dose"].astype(str)]
    return frame


def size_study(inputs: Mapping[str, str], config: dict) -> tuple[dict, dict[str, pd.DataFrame]]:
    """The chapter "What drives the size effect": the doses, the manipulation check at the
    largest dose, per cue timing the effect at the largest dose, without size, and the slope on
    the dose (the paper's RMSE), the demonstrations' account of the errors, and the tables."""
    summary = _study_table(inputs["size_summary.csv"])
    slope = pd.read_csv(inputs["size_slope.csv"])
    checks = _study_table(inputs["size_manipulation.csv"])
    try:
        motor = pd.read_csv(inputs["size_motor.csv"])
    except pd.errors.EmptyDataError:  # no removal control in this build
        motor = pd.DataFrame()
    study = config["size_dose"]
    top = max(study["doses"])
    at_top = checks[checks["dose"] == top]
    values: dict = {
        "doses": ", ".join(f"{d:g}" for d in study["doses"]),
        "top_dose": f"{top:g}",
        "replications": int(summary["replications"].max()),
        "n_runs": int(len(checks) // 4),
    }
    for shape in ("ball", "cube"):
        for name in ("object", "goal"):
            rows = at_top[(at_top["shape"] == shape) & (at_top["map"] == name)]
            values[f"ratio_{name}_{shape}"] = float(rows["ratio"].min())
    ratios = [values[f"ratio_goal_{shape}"] for shape in ("ball", "cube")]
    claims: dict = {
        "claim_check": text.Claim(
            "The dose arrived: at the largest dose the Goal map's large cluster has at least "
            "twice the small one's units for both shapes."
            if min(ratios) >= 2
            else "The dose did not fully arrive: at the largest dose the Goal map's large "
            "cluster has less than twice the small one's units for at least one shape.",
            ("size.ratio_goal_ball", "size.ratio_goal_cube"),
        )
    }
    for cue in study["categorisation_cue"]:
        rmse = summary[(summary["cue"] == cue) & (summary["measure"] == "rmse")]
        for key, dose in (
            ("top", top),
            ("removed", "removed"),
            ("none", min(study["doses"])),
            ("equal_grips", "equal_grips"),
        ):
            rows = rmse[rmse["dose"] == dose]
            if rows.empty:
                continue
            row = rows.iloc[0]
            values[f"{key}_diff_{cue}"] = float(row["diff"])
            values[f"{key}_p_holm_{cue}"] = float(row["p_holm"])
            what = {
                "top": f"At the largest dose ({top:g})",
                "removed": "Without any size in the input (the removal control)",
                "none": "With no size on the maps (dose 0, the visual input unchanged)",
                "equal_grips": "With no size on the maps and every object's grips moved towards "
                "one distance (the grips' distance much reduced, the size left; the motor side "
                "below gives the distances)",
            }[key]
            claims[f"claim_{key}_{cue}"] = text.size_dose_claim(row, cue, key, what)
            if key == "removed":
                claims[f"claim_source_{cue}"] = text.size_removal_claim(row, cue)
        delivered = slope[(slope["cue"] == cue) & (slope["measure"] == "rmse")]
        fit = delivered[delivered["axis"] == "delivered"].iloc[0]
        values[f"slope_{cue}"] = float(fit["slope"])
        values[f"slope_p_holm_{cue}"] = float(fit["p_holm"])
        claims[f"claim_slope_{cue}"] = text.size_slope_claim(fit, cue)
    geometry = pd.read_csv(inputs["size_geometry.csv"])
    values["geometry_like_size"] = text.geometry_like_size(ranked_like_size(geometry))
    if len(motor):
        motor["dose"] = [dose_value(d) for d in motor["dose"].astype(str)]
        for _, row in motor.iterrows():
            values[text.size_motor_key(row)] = float(row["p_holm"])
        for key, dose, where in (
            ("claim_motor_none", min(study["doses"]), "At dose 0, no size on the maps"),
            ("claim_motor_top", top, f"At the largest dose ({top:g}), with size in the input"),
            ("claim_motor_removed", "removed", "Without size in the input"),
            (
                "claim_motor_equal_grips",
                "equal_grips",
                "At dose 0 with the grips moved towards one distance",
            ),
        ):
            subset = motor[motor["dose"].astype(str) == str(dose)]
            if len(subset):
                claims[key] = text.size_motor_claim(subset, where)
    shown = summary.copy()
    shown["dose"] = [d if isinstance(d, str) else f"{d:g}" for d in shown["dose"]]
    for column in ("diff", "ci_low", "ci_high", "relative_to_mean"):
        shown[column] = shown[column].map(lambda v: f"{v:+.4f}" if np.isfinite(v) else "–")
    # relative to the measure's mean is a proportion of an error only for the RMSE measures
    shown.loc[~shown["measure"].isin(["rmse", "rmse_correct"]), "relative_to_mean"] = "–"
    shown["p"] = shown["p"].map(lambda v: text.fmt_p(v) if np.isfinite(v) else "–")
    shown["p_holm"] = shown["p_holm"].map(lambda v: "–" if not np.isfinite(v) else text.fmt_p(v))
    for column in ("large_small_ratio_object", "large_small_ratio_goal"):
        shown[column] = shown[column].map(lambda v: f"{v:.2f}")
    fits = slope.copy()
    for column in ("slope", "ci_low", "ci_high"):
        fits[column] = fits[column].map(lambda v: f"{v:+.4f}" if np.isfinite(v) else "–")
    for column in ("p", "p_holm"):
        fits[column] = fits[column].map(lambda v: "–" if not np.isfinite(v) else text.fmt_p(v))
    grips = pd.read_csv(inputs["size_grips.csv"])
    for _, row in grips.iterrows():
        values[f"grips_diff_{row['cue']}"] = float(row["diff"])
        values[f"grips_p_holm_{row['cue']}"] = float(row["p_holm"])
        claims[f"claim_grips_{row['cue']}"] = text.size_grips_claim(row, row["cue"])
    power = pd.read_csv(inputs["size_power.csv"])
    values["power_replications"] = int(power["replications"].max()) if len(power) else 0
    at = power[np.isclose(power["effect"], 0.02)]
    for _, row in at.iterrows():
        values[f"power_{row['cue']}"] = float(row["power_holm_bound"])
    values["power_sentence"] = text.Claim(
        " and ".join(
            f"{row['power_holm_bound']:.2f} ({text.SIZE_CUE_WORDS[row['cue']]})"
            for _, row in at.iterrows()
        ),
        tuple(f"size.power_{cue}" for cue in at["cue"]),
    )
    declared = pd.concat(
        [
            summary[summary["family"] == FAMILY_DECLARED].assign(
                test=lambda d: [
                    f"size effect at dose {x:g}"
                    if not isinstance(x, str)
                    else "size effect at dose 0, grips moved towards one distance"
                    for x in d["dose"]
                ],
                estimate=lambda d: d["diff"],
            ),
            slope[slope["family"] == FAMILY_DECLARED].assign(
                test=lambda d: [f"slope on the {a} dose" for a in d["axis"]],
                estimate=lambda d: d["slope"],
            ),
        ]
    )
    tables = {
        "size_summary": shown.drop(columns=["df"]),
        "size_slope": fits,
        "size_power": pd.DataFrame(
            {
                "cue": power["cue"].str.replace("_", " "),
                "effect": power["effect"],
                "replications": power["replications"],
                "σ_rep": power["sigma_rep"],
                "σ_net": power["sigma_net"],
                "power (α)": power["power"],
                "power (Holm bound)": power["power_holm_bound"],
                "replications for 80% (α)": power["replications_for_80"],
                "(Holm bound)": power["replications_for_80_holm_bound"],
            }
        ),
        "size_declared": pd.DataFrame(
            {
                "cue": declared["cue"].map(text.SIZE_CUE_WORDS),
                "test": declared["test"],
                "estimate [95% interval]": [
                    f"{r['estimate']:+.4f} [{r['ci_low']:+.4f}, {r['ci_high']:+.4f}]"
                    for _, r in declared.iterrows()
                ],
                "df": declared["df"],
                "p": declared["p"],
                "family": declared["family"],
                "Holm p": declared["p_holm"],
                "verdict": [
                    text.direction_word({"estimate": e, "p": p, "p_holm": h})
                    for e, p, h in zip(
                        declared["estimate"], declared["p"], declared["p_holm"], strict=True
                    )
                ],
            }
        ),
    }
    shown_motor = motor.copy()
    if len(motor):
        for column in ("estimate", "ci_low", "ci_high"):
            shown_motor[column] = shown_motor[column].map(lambda v: f"{v:+.4f}")
        for column in ("p", "p_holm"):
            shown_motor[column] = shown_motor[column].map(text.fmt_p)
    tables["size_motor"] = shown_motor
    return values | claims, tables


def page_findings(
    inputs: Mapping[str, str], config: dict, ablation_cue: str, scale: dict[str, dict[str, int]]
) -> tuple[dict[str, dict], dict[str, pd.DataFrame]]:
    """Every page's values ({page: {name: value}}) and tables ({name: table}).

    ``inputs`` maps the book's names of the outputs (``BOOK_DATA``'s keys, the learning curves
    as ``curves/netNN.csv``) to their files; ``config`` is the run's, ``ablation_cue`` the cue
    timing the ablation trained with, ``scale`` this build's and the other scale's counts
    (``{"now": ..., "other": ...}``, runs.RunPlan.scale).
    """
    anova = _json(inputs["anova.json"])
    rmse, iterations = _curves(inputs)
    curve = science.curve_summary(rmse, config["network"]["phase1_iterations"], iterations)
    demos = load_npz(inputs["demos.npz"])
    beyond_values, cue_table = beyond(inputs, config, ablation_cue)
    robustness_values, sweep_table = robustness(inputs, config)
    readings_values, readings_tables = readings(inputs, config)
    grasping_values, grasping_tables = grasping(inputs, config)
    size_values, size_tables = size_study(inputs, config)
    pages = {
        "intro": intro(anova),
        "results": results(anova, curve, config["network"]["categorisation_cue"]),
        "discussion": discussion(anova, demos, config["network"]["categorisation_cue"]),
        "beyond": beyond_values,
        "grasping": grasping_values,
        "robustness": robustness_values,
        "readings": readings_values,
        "training": training(inputs, config),
        "vision": vision(inputs, config),
        "robot": robot(inputs),
        "architecture": architecture(inputs, config),
        "notes": notes(config),
        "size": size_values,
        "reproduce": {"scale": text.build_scale(scale, config)},
    }
    tables = (
        {f"anova_{mode}": anova_rows(anova, mode) for mode in MODES}
        | {f"contrasts_{mode}": contrast_rows(anova, mode) for mode in MODES}
        | {
            "object_means": object_means(_json(inputs["measures.json"])),
            "headline": headline(anova),
            "comparison": comparison(anova, curve, config),
            "cue_anova": cue_table,
        }
        | readings_tables
        | grasping_tables
        | size_tables
    )
    if sweep_table is not None:
        tables["sweep"] = sweep_table
    return traced(pages), tables


def traced(pages: dict[str, dict]) -> dict[str, dict]:
    """The pages' values with every ``text.Claim`` replaced by its sentence, and under ``claims``
    ({page: {key: [entries]}}) the findings each rests on. An entry that names no value of
    ``pages`` is refused: a claim must rest on numbers the book has."""
    out: dict[str, dict] = {}
    claims: dict[str, dict[str, list[str]]] = {}
    for page, values in pages.items():
        out[page] = {}
        for key, value in values.items():
            if isinstance(value, text.Claim):
                claims.setdefault(page, {})[key] = list(value.rests_on)
                value = value.text
            out[page][key] = value
    for page, keys in claims.items():
        for key, entries in keys.items():
            missing = [e for e in entries if e.split(".", 1)[1] not in out.get(e.split(".")[0], {})]
            if missing:
                raise KeyError(f"{page}.{key} rests on {missing}, which findings.json lacks")
    return out | {"claims": claims}
