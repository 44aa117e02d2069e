"""The book's words: numbers formatted for reading, and the sentences generated from the run.

The verdicts behind the sentences (is an effect in the paper's direction, is it significant)
are the package's (``icub_affordance.findings``); this module only says them. The rule
``findings`` (``workflow/scripts/findings.py``) calls it, and the pages show what it wrote.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from icub_affordance.findings import ALPHA, Verdict, interval_direction
from icub_affordance.measures import is_hypothesis


@dataclass(frozen=True)
class Claim:
    """A generated sentence that states a finding, and the entries of ``findings.json`` it rests
    on (``"page.key"``: the statistic, not its words). The page shows ``text``; ``findings.json``
    keeps ``rests_on`` under ``claims``, so a reader (and a test) can trace every finding the
    book states to the numbers behind it."""

    text: str
    rests_on: tuple[str, ...]

    def __post_init__(self) -> None:
        if not self.rests_on or any("." not in r for r in self.rests_on):
            raise ValueError(f"a claim names the findings it rests on as page.key: {self}")


def fmt_p(p: float) -> str:
    return "p < 0.001" if p < 0.001 else f"p = {p:.3f}"


def fmt_f(effect: dict) -> str:
    """F(df1, df2) = x.xx, p ..., partial eta squared."""
    return (
        f"F({effect['df1']:.0f}, {effect['df2']:.0f}) = {effect['F']:.2f}, {fmt_p(effect['p'])}, "
        f"partial η² = {effect['eta_p2']:.2f}"
    )


def fmt_ci(term: dict) -> str:
    return f"[{term['ci_low']:+.4f}, {term['ci_high']:+.4f}]"


def fmt_family(term: dict) -> str:
    """An adjusted p with the family it is adjusted within (``stats.adjust_families``)."""
    return (
        f"Holm-adjusted within the family “{term['family']}” ({term['family_size']} tests) "
        f"{fmt_p(term['p_holm'])}"
    )


def fmt_term(term: dict) -> str:
    """A tested term: estimate, 95% t-interval, t with its degrees of freedom, p, and where it
    has one, its p adjusted within its named family."""
    return (
        f"estimate {term['estimate']:+.4f}, 95% interval {fmt_ci(term)}, "
        f"t({term['df']:.0f}) = {term['t']:.2f}, {fmt_p(term['p'])}"
        + (f", {fmt_family(term)}" if "family" in term else "")
    )


#: The terms' names: what each estimate is, in the cells it compares. With four objects the
#: congruency x size term is twice the required grip's difference (power - precision), and the
#: three-way term four times the cubes' mean minus the balls' (stats.CODING).
TERM_NAMES = {
    "congruency": "congruency (incongruent − congruent)",
    "size": "size (small − large)",
    "mapping": "mapping (B − A)",
    "congruency:size": "congruency × size = 2 × required grip (power − precision)",
    "congruency:mapping": "congruency × mapping",
    "size:mapping": "size × mapping",
    "congruency:size:mapping": "three-way = 4 × (cubes − balls)",
}

#: The simple effects (``stats.SIMPLE``) by the object and grip cells they compare: the cell
#: counted positive, the cell counted negative, and which congruency or size level both share.
SIMPLE_NAMES = {
    "size_in_congruent": ("the small object with a precision grip required",
                          "the large object with a power grip required", "congruent cells"),
    "size_in_incongruent": ("the small object with a power grip required",
                            "the large object with a precision grip required", "incongruent cells"),
    "congruency_in_large": ("the large object with a precision grip required",
                            "the large object with a power grip required", "large objects"),
    "congruency_in_small": ("the small object with a power grip required",
                            "the small object with a precision grip required", "small objects"),
}  # fmt: skip


def simple_name(name: str) -> str:
    """A simple effect's row name: its two cells."""
    first, second, _ = SIMPLE_NAMES[name]
    return f"{first.removeprefix('the ')} − {second.removeprefix('the ')}"


def required_grip_phrase(term: dict) -> str:
    """The congruency x size term as what it is with four objects: twice the difference between
    the trials that require a power grip and those that require a precision grip."""
    numbers = f"congruency × size, twice power − precision: {fmt_term(term)}"
    if verdict_word(term) not in ("reproduced", "reversed"):
        return f"the required grip was not shown to matter ({numbers})"
    word = "higher" if term["estimate"] > 0 else "lower"
    return f"trials that require a power grip gave a {word} RMSE than precision ones ({numbers})"


def direction_word(term: dict) -> str:
    """A test's direction against the paper without claiming a reproduction (a control's or a
    slope's): "paper's direction", "against the paper", "not shown" or "not testable"."""
    return {"reproduced": "paper's direction", "reversed": "against the paper"}.get(
        verdict_word(term), verdict_word(term)
    )


def claim_verdict(term: dict, outcome: str, effect: str) -> str:
    """The front page's verdict on one test: "reproduced" or "reversed" for the two effects the
    paper claims, on its measure or the correct trials' (its reaction-time reading); the paper
    claims nothing of errors, nor of the required grip (the congruency x size term), so those
    are "shown", "shown, opposite" (against the paper's direction) or "not shown"."""
    word = verdict_word(term)
    if outcome != "errors" and effect != "congruency:size":
        return word
    if effect == "congruency:size":
        return "shown" if word in ("reproduced", "reversed") else word
    return {"reproduced": "shown", "reversed": "shown, opposite"}.get(word, word)


def term_name(term: str) -> str:
    return TERM_NAMES.get(term, term.replace(":", " × "))


def verdict_word(term: dict, alpha: float = ALPHA) -> str:
    """A test against the paper's direction (positive estimate): "reproduced" or "reversed"
    where its p adjusted within its family is below ``alpha``, else "not shown" (which is not
    "no difference": only an equivalence test says that); "not testable" where it has no p."""
    p = term.get("p_holm", term["p"])
    if not math.isfinite(p):
        return "not testable"
    if p >= alpha:
        return "not shown"
    return "reproduced" if term["estimate"] > 0 else "reversed"


def pct(x: float) -> str:
    return f"{100 * x:.0f}%"


# The main effects: the front page, the results, the discussion and the chapter beyond the paper.


def lower_or_higher(verdict: Verdict) -> str:
    """The RMSE of the condition the paper reports as faster, against the other's: a direction
    only where the test shows one."""
    if not verdict.significant:
        return "not significantly different"
    return "lower" if verdict.paper_direction else "higher"


def paper_agreement(verdict: Verdict) -> str:
    """How an effect stands to the paper, after "congruent trials were lower" (front page)."""
    if not verdict.significant:
        return "unlike the paper, which reports a significant difference"
    return (
        "as in the paper" if verdict.paper_direction else "the opposite of what the paper reports"
    )


def significance(verdict: Verdict) -> str:
    return ", significantly" if verdict.significant else ", but not significantly"


def results_sentence(effect: str, verdict: Verdict, interacts: bool = False) -> str:
    """One effect of one test mode on the all-trials RMSE (results page), said in RMSE, not
    speed (errors and correct trials are set apart below it): a difference is stated only where
    its test, adjusted within its family, is significant. ``interacts``: the required grip's
    term is significant, so a main effect is only an average over the grips."""
    if effect == "congruency":
        first, second, pair = "congruent trials", "incongruent ones", "congruent and incongruent"
    else:
        first, second, pair = "large objects", "small ones", "large and small objects"
    average = " on average over the required grips, which differ" if interacts else ""
    if verdict.significant:
        word = "a lower" if verdict.paper_direction else "a higher"
        return f"{first} gave {word} RMSE than {second}{average}, significantly"
    return f"the difference between {pair} was not significant"


def p_word(p: float, alpha: float = 0.05) -> str:
    return "significant" if p < alpha else "not significant"


def simple_phrase(term: dict, name: str, alpha: float = ALPHA) -> str:
    """A simple effect (``stats.SIMPLE``) named by the object and grip cells it compares, with
    its p adjusted within its family. Said in RMSE, not speed: the cells differ in object and
    grip at once."""
    first, second, where = SIMPLE_NAMES[name]
    numbers = (
        f"{where}, {term['estimate']:+.4f}, t({term['df']:.0f}) = {term['t']:.2f}, "
        f"{fmt_family(term)}"
    )
    if not term["p_holm"] < alpha:
        return f"{first} and {second} were not shown to differ in RMSE ({numbers})"
    word = "higher" if term["estimate"] > 0 else "lower"
    return f"{first} gives a {word} RMSE than {second} ({numbers})"


def rt_phrase(effect: str, term: dict) -> str:
    """The correct-trial RMSE (the reaction-time analogue): "faster" and "slower" are said of
    this measure only, and only where its test, adjusted within its family, shows a direction."""
    faster, slower = ("congruent", "incongruent") if effect == "congruency" else ("large", "small")
    n = term.get("cells", {})
    counts = ", ".join(f"{k.replace('_', ' ')} {v}" for k, v in n.items())
    numbers = f"{fmt_term(term)}; networks with a correct trial per cell: {counts}"
    word = verdict_word(term)
    if word == "reproduced":
        return f"{faster} trials were faster (lower RMSE) than {slower} ones ({numbers})"
    if word == "reversed":
        return f"{faster} trials were slower (higher RMSE) than {slower} ones ({numbers})"
    if word == "not testable":
        return f"the correct trials cannot test this difference ({counts})"
    return f"{faster} and {slower} trials were not shown to differ in speed ({numbers})"


def error_phrase(effect: str, term: dict, rates: tuple[float, float]) -> str:
    """The wrong-grip rate's difference: (the paper's faster condition's rate, the other's)."""
    first, second = ("congruent", "incongruent") if effect == "congruency" else ("large", "small")
    numbers = f"{pct(rates[1])} of {second} against {pct(rates[0])} of {first} trials"
    word = verdict_word(term)
    if word in ("reproduced", "reversed"):
        more = second if term["estimate"] > 0 else first
        return f"{more} trials ended on the wrong grip more often ({numbers}; {fmt_term(term)})"
    return f"the wrong-grip rate was not shown to differ ({numbers}; {fmt_term(term)})"


def measure_verdict(word: str) -> str:
    """A verdict word as the front page's table says it."""
    return {"reproduced": "reproduced", "reversed": "reversed", "not shown": "not shown",
            "not testable": "not testable"}[word]  # fmt: skip


def discussion_congruency(
    rmse: dict, errors: dict, rt: dict, wrong: dict[str, float], cue: str
) -> Claim:
    """The discussion's congruency paragraph: the paper's measure's verdict in the confirmatory
    family, then its two parts, errors and the correct-trial RMSE (the reaction-time analogue);
    "faster" only of the latter."""
    word = verdict_word(rmse)
    head = {
        "reproduced": "**On the paper's measure the congruency effect is reproduced**",
        "reversed": "**On the paper's measure the congruency effect is reversed**",
    }.get(word, "**On the paper's measure the congruency effect is not shown**")
    text = (
        f"{head} (all-trials RMSE, incongruent − congruent, closed loop: {fmt_term(rmse)}). "
        "People's reaction-time effects are measured on correct responses, with errors counted "
        "apart, and the all-trials RMSE mixes the two. Errors: "
        + error_phrase("congruency", errors, (wrong["congruent"], wrong["incongruent"]))
        + ". Correct trials alone: "
        + rt_phrase("congruency", rt)
        + "."
    )
    if cue == "first_step":
        text += (
            " With the cue at the first step only, errors are what the design leads one to "
            "expect: from the second step on the Task map shows the grasping pattern, exactly as "
            "in a grasping trial of the same object."
        )
    rests = (
        "discussion.congruency_estimate",
        "discussion.congruency_p_holm",
        "discussion.errors_congruency_estimate",
        "discussion.errors_congruency_p_holm",
        "discussion.rt_congruency_estimate",
        "discussion.rt_congruency_p_holm",
        "discussion.wrong_incongruent",
        "discussion.wrong_congruent",
    )
    return Claim(text, rests)


def discussion_size(
    rmse: dict,
    errors: dict,
    rt: dict,
    simple: dict[str, dict],
    wrong: dict[str, float],
    rt_grip: dict,
) -> Claim:
    """The discussion's size paragraph (closed loop): the paper's measure's verdict in the
    confirmatory family, its two parts, and why a size term cannot be read apart from the grips
    (the congruent cells compare a small object's precision grasp with a large one's power
    grasp)."""
    word = verdict_word(rmse)
    head = {
        "reproduced": "**On the paper's measure the size effect is reproduced**",
        "reversed": "**On the paper's measure the size effect is reversed**",
    }.get(word, "**On the paper's measure the size effect is not shown**")
    tail = {
        "reproduced": ", as the paper reports",
        "reversed": ": large objects give a *higher* RMSE, where the paper reports a lower one",
    }.get(word, ": the paper reports a lower RMSE for large objects; this test shows no "
              "difference, which is not evidence of its absence")  # fmt: skip
    text = (
        f"{head} (all-trials RMSE, small − large, closed loop: {fmt_term(rmse)}){tail}. Errors: "
        + error_phrase("size", errors, (wrong["large"], wrong["small"]))
        + ". Correct trials alone: "
        + rt_phrase("size", rt)
        + "; and on them "
        + required_grip_phrase(rt_grip)
        + ". With four objects a size term is not object size alone: "
        + simple_phrase(simple["size_in_congruent"], "size_in_congruent")
        + ", and the congruency × size term is twice the difference between the trials that "
        "require a power grip and those that require a precision grip. The chapter on what "
        "drives the size effect asks what lies behind it."
    )
    rests = (
        "discussion.size_estimate",
        "discussion.size_p_holm",
        "discussion.errors_size_estimate",
        "discussion.errors_size_p_holm",
        "discussion.rt_size_estimate",
        "discussion.rt_size_p_holm",
        "discussion.rt_grip_estimate",
        "discussion.rt_grip_p_holm",
        "discussion.size_in_congruent_estimate",
        "discussion.size_in_congruent_p_holm",
        "discussion.wrong_large",
        "discussion.wrong_small",
    )
    return Claim(text, rests)


def discussion_forced(forced: dict[str, dict], simple: dict[str, dict]) -> Claim:
    """The teacher-forced size result, stated with the required-grip term it comes with: where
    that term is shown, the size term alone does not say which cells differ; the simple effects,
    named by their cells, do. Every p is adjusted within its family (the mode's exploration)."""
    size, inter = forced["size"], forced["congruency:size"]
    text = (
        "In teacher-forced testing, where each step starts from the demonstrated posture and no "
        f"drift can build up, the size term is {size['estimate']:+.4f} "
        f"(t({size['df']:.0f}) = {size['t']:.2f}, {fmt_family(size)}) and the congruency × size "
        f"term, twice the required grip's difference (power − precision), {inter['estimate']:+.4f} "
        f"(t({inter['df']:.0f}) = {inter['t']:.2f}, {fmt_family(inter)})"
    )
    if inter["p_holm"] < ALPHA:
        text += (
            ": the required grip matters, so the size term alone does not say which cells "
            "differ. "
            + simple_phrase(simple["size_in_congruent"], "size_in_congruent")[0].upper()
            + simple_phrase(simple["size_in_congruent"], "size_in_congruent")[1:]
            + "; "
            + simple_phrase(simple["size_in_incongruent"], "size_in_incongruent")
            + "."
        )
    else:
        text += "."
    rests = (
        "discussion.forced_size_estimate",
        "discussion.forced_size_p_holm",
        "discussion.forced_interaction_estimate",
        "discussion.forced_interaction_p_holm",
        "discussion.forced_size_in_congruent_p_holm",
        "discussion.forced_size_in_incongruent_p_holm",
    )
    return Claim(text, rests)


def discussion_readings(cue: str) -> str:
    return (
        "The reproduction notes list the choices behind these numbers. The most consequential are "
        f"readings of the paper's text: when the categorisation cue reaches the network (this "
        f"run: `{cue}`) and what the Goal map sends on. The next chapters set the other readings "
        "beside this one, with equal standing, run by the same pipeline and scored on the same "
        "trials with several measures."
    )


def robot_error_sentence(verdict: Verdict) -> str:
    """The congruency effect on the robot's final posture error; no direction without its test."""
    if not verdict.significant:
        return (
            "the final error did not differ significantly between congruent and incongruent trials"
        )
    return (
        "the arm ended further from the demonstrated grasp in incongruent trials, significantly"
        if verdict.paper_direction
        else "the arm ended nearer the demonstrated grasp in incongruent trials, significantly"
    )


def anova_or_undefined(anova: dict | None, effect: str) -> str:
    return (
        fmt_f(anova[effect]) if anova else "undefined: every network scored the same in every cell"
    )


def points_difference(difference: dict) -> str:
    """A difference of rates in percentage points, with its 95% interval when there is one."""
    if math.isnan(difference["ci_low"]):
        return f"{100 * difference['mean']:+.0f} points"
    return (
        f"{100 * difference['mean']:+.0f} points (95% interval {100 * difference['ci_low']:+.0f} "
        f"to {100 * difference['ci_high']:+.0f})"
    )


def cue_verdict(verdict: Verdict) -> str:
    if verdict.reproduced:
        return "shows the congruency effect"
    if verdict.reversed:
        return "shows the congruency effect reversed"
    return "shows no significant congruency effect"


def cue_difference(difference: dict, alpha: float = 0.05) -> Claim:
    """The test of the difference between the cue timings: the congruency effect with the cue at
    the first step only minus with the cue at every step, paired by network (the same networks,
    seeds and trials, retrained under the other timing; ``stats.difference_tests``)."""
    numbers = (
        f"first step only − every step {difference['estimate']:+.4f}, 95% interval "
        f"{fmt_ci(difference)}, t({difference['df']:.0f}) = {difference['t']:.2f}, "
        f"{fmt_p(difference['p'])}, paired over networks"
        + (
            f"; Holm-adjusted over the readings' differences {fmt_p(difference['p_holm'])}"
            if "p_holm" in difference
            else ""
        )
    )
    p = difference.get("p_holm", difference["p"])
    rests = ("beyond.cue_difference_estimate", "beyond.cue_difference_p_holm")
    if p >= alpha:
        return Claim(
            "The two timings' congruency effects do not differ significantly "
            f"({numbers}), so this run does not show that the cue's timing decides the effect.",
            rests,
        )
    larger = "at the first step only" if difference["estimate"] > 0 else "at every step"
    text = f"The congruency effect is significantly larger with the cue {larger} ({numbers})."
    if difference["estimate"] > 0:
        text += (
            " One reading of this: a cue that stays on tells the network at every step which "
            "grip is wanted, while a cue that is gone leaves the network to hold its choice in "
            "its own posture feedback, where the grasp the object affords can win."
        )
    return Claim(text, rests)


def divergence_sentence(first_step: int | None) -> Claim:
    """The hidden layer's conflict, from the per-step paired tests (Holm over the steps)."""
    rests = ("beyond.div_first_step",)
    if first_step is not None:
        return Claim(
            f"From step {first_step} on, incongruent trials are significantly further from "
            "grasping at every step (paired t-tests over networks, Holm-adjusted over the steps, "
            "p < 0.05): the hidden state of a categorisation trial that asks for the grip the "
            "object does not invite stays apart from the one the same object drives in a "
            "grasping trial, whichever grip the output ends on.",
            rests,
        )
    return Claim(
        "Incongruent trials are not significantly further from grasping at every step to the end "
        "(paired t-tests over networks, Holm-adjusted over the steps): this run shows no lasting "
        "conflict in the hidden layer.",
        rests,
    )


def floor_sentence(at_floor: bool) -> str:
    return "Success is near the floor, so it can say little about congruency." if at_floor else ""


# The robustness page (book/robustness.md): the sweep and its cost, or a plain note that this
# build did not run them.

ROBUSTNESS_COMMAND = "snakemake -c2 --config robustness=True"
CUES = {"first_step": "the cue at the first step only", "all_steps": "the cue at every step"}
EFFECTS = {
    "congruency": ("congruent", "incongruent"),
    "size": ("large objects", "small objects"),
}


def sweep_size(config: dict) -> tuple[int, int]:
    """Points of the config's sweep and networks trained in all."""
    sweep = config["sweep"]
    points = 1
    for key in ("seeds", "learning_rate", "hidden", "categorisation_cue"):
        points *= len(sweep[key])
    return points, points * config["network"]["networks"]


def build_scale(scale: dict[str, dict[str, int]], config: dict) -> str:
    """What this build trained and tested (``scale["now"]``, runs.RunPlan.scale), and what the
    other scale does (``scale["other"]``), in MyST: the default build answers each of the
    book's questions at the smallest scale that supports its claims, ``robustness: true`` at
    full scale."""
    network = config["network"]

    def words(s: dict[str, int]) -> str:
        return (
            f"each of the {s['readings']} readings of the paper at "
            f"{_count(s['reading_seeds'], 'seed')}; the size study's {s['size_runs']} runs "
            f"({_count(s['size_replications'], 'replication')}); "
            f"{_count(s['variants'], 'robot variant')} besides the config's own networks; "
            f"{s['fresh']} fresh networks for the confirmation; "
            + (f"the sweep's {s['sweep']} points" if s["sweep"] else "no sweep")
        )

    made = "`robustness: true`" if config["robustness"] else "`robustness: false` (the default)"
    other = (
        f"The full scale, `{ROBUSTNESS_COMMAND}`, builds {words(scale['other'])}."
        if not config["robustness"]
        else f"The default build makes {words(scale['other'])}."
    )
    return (
        f"This book was built with {made}: the paper's model once ({network['networks']} "
        f"networks at seed {config['seed']}) and its cue ablation; {words(scale['now'])}. " + other
    )


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}" + ("" if n == 1 else "s")


def robustness_not_run(config: dict) -> str:
    """What the page says when this build did not run the sweep (MyST)."""
    points, networks = sweep_size(config)
    return (
        "```{important}\n"
        "**This build did not run the sweep.** It was made with `robustness: false` (the "
        "default), which keeps the run to the paper's single replication, so this page has no "
        "results and no cost table. To add them, run the pipeline with\n\n"
        f"    {ROBUSTNESS_COMMAND}\n\n"
        f"which trains the {points} points of the config's `sweep` section ({networks} networks "
        "in all), times the sweep for the numbers of replications in `sweep_cost`, and rebuilds "
        "this book with both.\n"
        "```"
    )


def fmt_interval(mean: float, low: float, high: float, digits: int = 4) -> str:
    """A mean with its interval, or the mean alone when there is none (one replication)."""
    if math.isnan(low) or math.isnan(high):
        return f"{mean:.{digits}f}"
    return f"{mean:.{digits}f} [{low:.{digits}f}, {high:.{digits}f}]"


def setting_label(row) -> str:
    return (
        f"{CUES.get(row['categorisation_cue'], row['categorisation_cue'])}, learning rate "
        f"{row['learning_rate']:g}, {row['hidden']:.0f} hidden units"
    )


def sweep_summary_display(summary):
    """The per-setting summary as the book shows it: one row per setting and effect, with the
    mean difference and its 95% interval over replications, the mean partial eta squared, and
    how many replications were significant in the paper's direction and how many reversed."""
    import pandas as pd

    rows = []
    for _, r in summary.iterrows():
        n = int(r["replications"])
        for effect in EFFECTS:
            rows.append(
                {
                    "cue": r["categorisation_cue"],
                    "learning rate": f"{r['learning_rate']:g}",
                    "hidden": f"{r['hidden']:.0f}",
                    "effect": effect,
                    "mean difference [95% CI]": fmt_interval(
                        r[f"{effect}_effect"], r[f"{effect}_ci_low"], r[f"{effect}_ci_high"]
                    ),
                    "partial η² (mean)": f"{r[f'{effect}_eta_p2']:.2f}",
                    "significant": f"{r[f'{effect}_n_significant']:.0f} of {n}",
                    "reversed": f"{r[f'{effect}_n_reversed']:.0f} of {n}",
                }
            )
    return pd.DataFrame(rows)


def effect_sentence(row, effect: str) -> str:
    """One effect of one setting over its replications, in words, from the summary row."""
    first, second = EFFECTS[effect]
    n = int(row["replications"])
    mean, low, high = row[f"{effect}_effect"], row[f"{effect}_ci_low"], row[f"{effect}_ci_high"]
    interval = fmt_interval(mean, low, high)
    direction = {
        "single": f"{first} {'lower' if mean > 0 else 'higher'} in RMSE than {second} "
        "(one replication)",
        "paper": f"{first} lower in RMSE than {second}, the paper's direction",
        "against": f"{first} higher in RMSE than {second}, against the paper",
        "unclear": f"no consistent difference between {first} and {second}",
    }[interval_direction(n, mean, low, high)]
    sig, rev = int(row[f"{effect}_n_significant"]), int(row[f"{effect}_n_reversed"])
    return (
        f"**{effect.capitalize()}:** {direction} (mean difference {interval}); significant "
        f"(p < .05) in the paper's direction in {sig} of {n} replication{'s' if n != 1 else ''}, "
        f"significantly reversed in {rev}; mean partial η² {row[f'{effect}_eta_p2']:.2f}."
    )


def sweep_findings(summary) -> str:
    """What the sweep shows, per setting, in words generated from the summary (MyST)."""
    paragraphs = []
    for _, row in summary.iterrows():
        paragraphs.append(
            f"*With {setting_label(row)}* ({row['replications']:.0f} replications):\n\n"
            + "\n".join(f"- {effect_sentence(row, effect)}" for effect in EFFECTS)
        )
    return "\n\n".join(paragraphs)


def cost_findings(cost, growth: dict) -> str:
    """How the sweep's wall time grows with the number of replications, in words (MyST):
    ``cost`` is the cost table, ``growth`` its wall time against its replications
    (``icub_affordance.growth.cost_growth``)."""
    import numpy as np

    cost = cost.sort_values("replications")
    n, s = growth["sizes"], growth["seconds"]
    cores = int(cost["cores"].iloc[0])
    machine = int(cost["machine_cores"].iloc[0])
    text = (
        f"Each run is `snakemake -c{cores} sweep` in a scratch copy of the workflow on this "
        f"run's machine ({machine} cores), timed from start to end with nothing else of the "
        "pipeline running, for replications of the main run's network settings (seeds 1 to n)."
    )
    other = cost["other_load"].to_numpy(dtype=float)
    if not np.isnan(other).all():
        worst = int(np.nanargmax(other))
        if other[worst] > 0.25:
            text += (
                f" The machine was shared: while {n[worst]:.0f} replications were timed, other "
                f"work kept {other[worst]:.1f} of its cores busy on average (column *other "
                "load*), which lengthens that time; the growth below must be read with that in "
                "mind."
            )
        else:
            text += (
                f" Nothing else loaded the machine meanwhile (other load at most "
                f"{np.nanmax(other):.2f} cores)."
            )
    if len(n) < 2:
        return text + " With a single measurement there is no growth to describe."
    marginal = growth["marginal"]
    steps = ", ".join(
        f"{m:.1f} s between {a:.0f} and {b:.0f}"
        for m, a, b in zip(marginal, n[:-1], n[1:], strict=True)
    )
    text += (
        f" From {n[0]:.0f} to {n[-1]:.0f} replications the wall time grew "
        f"{s[-1] / s[0]:.1f}-fold for {n[-1] / n[0]:g} times the work; the time per replication "
        f"went from {s[0] / n[0]:.1f} s to {s[-1] / n[-1]:.1f} s, and each added replication "
        f"cost {steps} replications."
    )
    if (line := growth["line"]) is not None:
        far = line["furthest_size"]
        text += (
            f" A straight line through the {len(n)} measurements has {line['slope']:.1f} s per "
            f"replication and an intercept of {line['intercept']:.1f} s; the measurement "
            f"furthest from it is {100 * line['furthest_offset']:.0f}% off (at {far:.0f} "
            f"replication{'s' if far != 1 else ''})."
        )
    change = growth["change"]
    if len(marginal) < 2:
        text += (
            " Two measurements always lie on a line: it takes three to tell whether the cost "
            "grows linearly."
        )
    elif abs(change) <= 0.1:
        text += " So the cost grew linearly: every added replication cost about the same."
    elif change < 0:
        text += (
            f" So the cost grew no faster than linearly: an added replication cost "
            f"{100 * -change:.0f}% less in the larger sweeps."
        )
    else:
        text += (
            f" So the cost grew faster than linearly: an added replication cost "
            f"{100 * change:.0f}% more in the larger sweeps."
        )
    if len(marginal) >= 2:
        text += (
            " Each number is a single timing, and timings of the same sweep vary from run to "
            "run, so modest differences between the marginal costs mean little."
        )
    return text


# ---- Which reading reproduces the paper (book/readings.md) --------------------------------------
# Short verdict phrases on the readings' tests, each a Claim resting on the page's statistics
# (``stat_key``); the sentences around them are the page's own.

#: The chapter's names of the measures and cue timings (its tables' legend), and of the verdicts
#: (``readings.direction``, ``readings.difference_verdict``) where they differ from the verdict.
MEASURE_LABELS = {
    "rmse": "RMSE",
    "rmse_correct": "correct-trial RMSE",
    "wrong_grip": "wrong-grip rate",
    "commitment": "commitment",
    "rmse_per_grip_distance": "RMSE per grip distance",
    "rmse_per_grip_distance_null": "null control",
    "rmse_per_grip_distance_excess": "excess over null",
}
CUE_LABELS = {"first_step": "first", "all_steps": "every"}
WORDS = {"none": "not shown", "constant": "no variation", "a > b": "larger", "a < b": "smaller"}


def stat_key(row, stat: str) -> str:
    """The readings page's value of a statistic of one row of the summary or the differences."""
    first = (
        [row["comparison"], row["at"]]
        if "comparison" in row
        else [row["cue"], row["goal_response"]]
    )
    return "_".join([*first, row["measure"], row["effect"], stat])


def _rests_on(rows, stats) -> tuple[str, ...]:
    """The rows' statistics that exist (a constant cell has no p, an identical difference no
    test), as what a claim rests on."""
    return tuple(
        f"readings.{stat_key(r, s)}"
        for _, r in rows.iterrows()
        for s in stats
        if math.isfinite(r[s])
    )


def _listing(items: list[str], none: str) -> str:
    if not items:
        return none
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def reading_claims(summary) -> dict[str, Claim]:
    """Per tested measure, the readings whose congruency or size effect goes the paper's way on
    Holm's p (``paper_<measure>_<effect>``), and those where both do (``both_<measure>``)."""
    from icub_affordance.readings import direction

    out = {}
    for measure, rows in summary[summary["measure"].map(is_hypothesis)].groupby(
        "measure", sort=False
    ):
        found: dict[str, set[str]] = {}
        for _, r in rows.iterrows():
            found.setdefault(f"{CUE_LABELS[r['cue']]} · {r['goal_response']}", set())
            if direction(r) == "paper":
                found[f"{CUE_LABELS[r['cue']]} · {r['goal_response']}"].add(r["effect"])
        for name, effects in (
            ("congruency", {"congruency"}),
            ("size", {"size"}),
            ("both", {"congruency", "size"}),
        ):
            chosen = [reading for reading, shown in found.items() if effects <= shown]
            words = "every reading" if len(chosen) == len(found) else _listing(chosen, "no reading")
            key = f"both_{measure}" if name == "both" else f"paper_{measure}_{name}"
            out[key] = Claim(words, _rests_on(rows, ("diff", "p_holm")))
    return out


def difference_claims(differences, comparison: str, prefix: str) -> dict[str, Claim | int]:
    """The effects a comparison of readings changes, from its tests
    (``readings.difference_verdict``): ``<prefix>_changes`` (larger or smaller, Holm),
    ``_larger``, ``_smaller``, naming the level of the other choice where only one shows it; and
    how many of the ``<prefix>_n`` effects are larger, smaller, equivalent (TOST within the
    margin, Holm), identical or not shown (``<prefix>_n_equivalent``, ...)."""
    from icub_affordance.readings import difference_verdict

    rows = differences[
        (differences["comparison"] == comparison) & differences["measure"].map(is_hypothesis)
    ]
    words = rows.apply(difference_verdict, axis=1).map(lambda v: WORDS.get(v, v))
    rests = _rests_on(rows, ("diff", "p_holm", "p_equivalence_holm"))

    def effects(chosen) -> str:
        parts = []
        for effect, group in chosen.groupby("effect", sort=False):
            measures = [
                MEASURE_LABELS[m]
                + (
                    ""
                    if len(at) == rows["at"].nunique()
                    else f" ({CUE_LABELS.get(at.iloc[0], at.iloc[0])} only)"
                )
                for m, at in group.groupby("measure", sort=False)["at"]
            ]
            parts.append(f"{effect} on {_listing(measures, '')}")
        return "; ".join(parts) or "no effect"

    out: dict[str, Claim | int] = {f"{prefix}_n": len(rows)}
    for word in ("larger", "smaller", "equivalent", "identical", "not shown"):
        out[f"{prefix}_n_{word.replace(' ', '_')}"] = Claim(str((words == word).sum()), rests)
    out[f"{prefix}_larger"] = Claim(effects(rows[words == "larger"]), rests)
    out[f"{prefix}_smaller"] = Claim(effects(rows[words == "smaller"]), rests)
    out[f"{prefix}_changes"] = Claim(effects(rows[words.isin(["larger", "smaller"])]), rests)
    return out


# ---- What drives the size effect ----------------------------------------------------------------

#: A cue timing in words, for the size study's sentences.
SIZE_CUE_WORDS = {
    "first_step": "the cue at the first step only",
    "all_steps": "the cue at every step",
}

#: The demonstrations' geometry in words (icub_affordance.size_dose.GEOMETRY).
GEOMETRY_WORDS = {
    "demo_path_length": "the length of the path the demonstrations travel",
    "demo_spread": "the spread of the demonstrations around their mean",
    "demo_grip_distance": "the distance between the two grips' final postures",
}


def _interval(row) -> str:
    return f"{row['diff']:+.4f} (95% interval [{row['ci_low']:+.4f}, {row['ci_high']:+.4f}])"


def size_effect_words(row) -> str:
    """A size effect's verdict from its Holm-adjusted test: the paper's direction (large lower),
    reversed, or not detected (which is not a claim that there is none)."""
    if row["p_holm"] < ALPHA:
        return "in the paper's direction" if row["diff"] > 0 else "reversed (large higher)"
    return "not detected within its family (which is not evidence of none)"


def _adjusted(row) -> str:
    """A table row's adjusted p with its family named."""
    return f"Holm-adjusted within “{row['family']}” {fmt_p(row['p_holm'])}"


def size_slope_claim(slope, cue: str) -> Claim:
    """The size effect's slope on the delivered dose (the Goal map's large/small log ratio),
    tested over replications, Holm-adjusted within its family."""
    p = slope["p_holm"]
    if p < ALPHA:
        trend = (
            "more size delivered to the maps moves the effect towards the paper's direction"
            if slope["slope"] > 0
            else "more size delivered to the maps moves the effect away from the paper's direction"
        )
    else:
        trend = "no change with the delivered size is detected, which is not evidence of none"
    return Claim(
        f"With {SIZE_CUE_WORDS[cue]}, the size effect on the paper's RMSE changes by "
        f"{slope['slope']:+.4f} per unit of the delivered dose (95% interval "
        f"[{slope['ci_low']:+.4f}, {slope['ci_high']:+.4f}], t({slope['df']:.0f}), "
        f"{fmt_p(slope['p'])}, {_adjusted(slope)}, over {int(slope['replications'])} "
        f"replications): {trend}.",
        (f"size.slope_{cue}", f"size.slope_p_holm_{cue}"),
    )


def size_dose_claim(row, cue: str, key: str, what: str) -> Claim:
    """The size effect at one dose (or without size), over its replications."""
    return Claim(
        f"{what}, with {SIZE_CUE_WORDS[cue]}, the size effect on the paper's RMSE is "
        f"{_interval(row)}, {fmt_p(row['p'])}, {_adjusted(row)}, over "
        f"{int(row['replications'])} replications: {size_effect_words(row)}.",
        (f"size.{key}_diff_{cue}", f"size.{key}_p_holm_{cue}"),
    )


def size_grips_claim(row, cue: str) -> Claim:
    """How much of the dose-0 size effect the grips' distance carries: the effect with the grips
    as demonstrated minus with them at one distance, paired by replication (exploration)."""
    if row["p_holm"] < ALPHA:
        verdict = (
            "the grips' distance changes the size effect: reducing it moves the effect "
            + ("towards" if row["diff"] < 0 else "away from")
            + " the paper's direction"
        )
    else:
        verdict = "whether the grips' distance changes the size effect is not shown"
    return Claim(
        f"With {SIZE_CUE_WORDS[cue]}, the dose-0 size effect with the grips as demonstrated minus "
        f"with them moved towards one distance is {_interval(row)}, t({row['df']:.0f}), "
        f"{fmt_p(row['p'])}, "
        f"{_adjusted(row)} (a comparison made after the control's results were read): {verdict}.",
        (f"size.grips_diff_{cue}", f"size.grips_p_holm_{cue}"),
    )


def size_removal_claim(row, cue: str) -> Claim:
    """Where the reversed size effect comes from, by the removal control: if it is still there
    (Holm) without any size in the input, it cannot come from vision."""
    if row["p_holm"] < ALPHA and row["diff"] < 0:
        verdict = (
            "without size in the input the size effect is reversed (large higher), so the motor "
            "side (the grips and their demonstrations) can produce a reversed effect without vision"
        )
    elif row["p_holm"] < ALPHA:
        verdict = "without size in the input the effect takes the paper's direction"
    else:
        verdict = (
            "without size in the input no size effect is detected within its family, so this "
            "build cannot say"
        )
    return Claim(
        f"With {SIZE_CUE_WORDS[cue]}: {verdict}.",
        (f"size.removed_diff_{cue}", f"size.removed_p_holm_{cue}"),
    )


def size_motor_key(row) -> str:
    """The size page's value of one motor test's Holm p."""
    dose = row["dose"] if isinstance(row["dose"], str) else f"{float(row['dose']):g}"
    return f"motor_p_holm_{dose}_{row['cue']}_{row['geometry']}"


def size_motor_claim(motor, where: str) -> Claim:
    """Do the demonstrations' differences account for each object's error (``motor``: the
    tests of one dose, or of the removal runs; ``where`` says which)?"""
    found = motor[motor["p_holm"] < ALPHA]
    rests = tuple(f"size.{size_motor_key(r)}" for _, r in motor.iterrows())
    if found.empty:
        return Claim(
            f"{where}, none of the demonstrations' measures lines up with the objects' errors "
            f"detectably (every p Holm-adjusted within “{motor['family'].iloc[0]}” at least "
            "0.05).",
            rests,
        )
    said = "; ".join(
        f"{GEOMETRY_WORDS[r['geometry']]}, with {SIZE_CUE_WORDS[r['cue']]} (an object's error "
        f"{'rises' if r['estimate'] > 0 else 'falls'} by {abs(r['estimate']):.4f} per standard "
        f"deviation of it, {_adjusted(r)}, over {int(r['replications'])} "
        f"replications of {int(r['networks'])} networks)"
        for _, r in found.iterrows()
    )
    return Claim(f"{where}, an object's error lines up with " + said + ".", rests)


def geometry_like_size(measures: list[str]) -> str:
    """Which of the demonstrations' measures rank the objects as size does (a description of the
    demonstrations, the caveat on the motor tests)."""
    if not measures:
        return "None of the demonstrations' measures ranks the objects as their size does."
    words = [GEOMETRY_WORDS[m] for m in measures]
    named = words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]
    verb = "is" if len(words) == 1 else "are"
    return (
        f"In every replication's demonstrations, {named} {verb} larger for both large objects "
        "than for the small one of the same shape: with four objects per network, a slope on "
        "such a measure cannot be told apart from the size effect itself."
    )
