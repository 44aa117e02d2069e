"""The book's words: numbers formatted for reading, and the sentences generated from the run.

The verdicts behind the sentences (is an effect in the paper's direction, is it significant)
are the package's (``icub_affordance.findings``); this module only says them. The rule
``findings`` (``workflow/scripts/findings.py``) calls it, and the pages show what it wrote.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from icub_affordance.findings import ALPHA
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


def shown_word(term: dict, alpha: float = ALPHA) -> str:
    """A difference the paper does not predict (a simple effect, the wrong-grip rate, the
    required grip): "shown" where its p adjusted within its family is below ``alpha``, else "not
    shown"; its sign is in the estimate beside it."""
    word = verdict_word(term, alpha)
    return "shown" if word in ("reproduced", "reversed") else word


def test_values(page: str, prefix: str, term: dict, verdict=verdict_word) -> dict:
    """A test as page values: its numbers as the analysis wrote them, ``_stats`` (all of them for
    reading), and ``_verdict``, a ``Claim`` resting on its estimate and adjusted p."""
    values = {f"{prefix}_{key}": term[key] for key in ("estimate", "ci_low", "ci_high", "p")}
    values[f"{prefix}_p_holm"] = term.get("p_holm", term["p"])
    values[f"{prefix}_stats"] = fmt_term(term)
    rests = (f"{page}.{prefix}_estimate", f"{page}.{prefix}_p_holm")
    return values | {f"{prefix}_verdict": Claim(verdict(term), rests)}


def pct(x: float) -> str:
    return f"{100 * x:.0f}%"


# The main effects: the front page, the results, the discussion and the chapter beyond the paper.


def anova_or_undefined(anova: dict | None, effect: str) -> str:
    return (
        fmt_f(anova[effect]) if anova else "undefined: every network scored the same in every cell"
    )


# The robustness page (book/robustness.md): the sweep and its cost, or a plain note that this
# build did not run them.

ROBUSTNESS_COMMAND = "snakemake -c2 --config robustness=True"
CUES = {"first_step": "the cue at the first step only", "all_steps": "the cue at every step"}
#: An effect over the sweep's replications by its 95% interval (findings.interval_direction).
SWEEP_DIRECTIONS = {"paper": "paper's direction", "against": "reversed", "unclear": "not shown"}
SWEEP_DIRECTIONS["single"] = "one replication"


def growth_phrase(growth: dict) -> str:
    """How the sweep's wall time grows (growth.cost_growth's ``change``, the last added
    replication's cost over the first's less one): within 10%, "linearly"."""
    if len(growth["marginal"]) < 2:
        return "in a way two timings cannot show: it takes three to tell"
    if abs(growth["change"]) <= 0.1:
        return "linearly"
    return "faster than linearly" if growth["change"] > 0 else "no faster than linearly"


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


# The readings chapter (book/readings.md): the readings x measures matrix in words, and the tests
# of the differences between readings. Every sentence that states a finding is a Claim resting on
# the page's values named by ``summary_key`` and ``difference_key``.

MEASURE_NAMES = {
    "rmse": "the paper's RMSE",
    "rmse_correct": "the correct-trial RMSE (the reaction-time analogue)",
    "wrong_grip": "the wrong-grip rate",
    "commitment": "commitment",
    "rmse_per_grip_distance": "RMSE per grip distance",
    "rmse_per_grip_distance_null": "the null control of RMSE per grip distance",
    "rmse_per_grip_distance_excess": "RMSE per grip distance beyond its null control",
}
GOAL_RESPONSES = {
    "fixed": "a Goal bump of fixed width",
    "grows": "a Goal bump that widens with its input",
}
DIRECTIONS = {
    "paper": "in the paper's direction",
    "reversed": "reversed",
    "none": "not shown (p ≥ 0.05 after Holm within “exploration: readings”)",
    "constant": "absent, the measure the same for every network and object,",
}
COMPARISON_NAMES = {
    "cue_timing": ("the cue timing", "the cue at the first step only minus the cue at every step"),
    "goal_response": (
        "the Goal response",
        "a Goal bump that widens minus one of fixed width",
    ),
}


def summary_key(row, stat: str) -> str:
    """The readings page's value of one summary row's statistic (diff, p, p_holm)."""
    return f"{row['cue']}_{row['goal_response']}_{row['measure']}_{row['effect']}_{stat}"


def difference_key(row, stat: str) -> str:
    """The readings page's value of one differences row's statistic."""
    return f"{row['comparison']}_{row['at']}_{row['measure']}_{row['effect']}_{stat}"


def _on(keys) -> tuple[str, ...]:
    return tuple(f"readings.{k}" for k in keys)


def _stats(row, stats, key) -> list[str]:
    """The keys of a row's statistics that exist (a constant cell has no p, a null control no
    Holm p): what a claim can rest on."""
    return [key(row, stat) for stat in stats if math.isfinite(float(row[stat]))]


def reading_label(cue: str, goal: str) -> str:
    return f"{CUES[cue]}, {GOAL_RESPONSES[goal]}"


def fmt_holm(p: float, family: str | None = None) -> str:
    """A Holm-adjusted p, with the family it is adjusted within where given."""
    within = f" within “{family}”" if family else ""
    return f"Holm-adjusted{within} p < 0.001" if p < 0.001 else f"Holm-adjusted{within} p = {p:.3f}"


def readings_method(summary) -> str:
    """How the matrix's tests were made (MyST): not a finding."""
    n = sorted(set(summary["replications"]))
    hypotheses = summary[summary["measure"].map(is_hypothesis)]
    tested = int(hypotheses["p"].map(math.isfinite).sum())
    untested = len(hypotheses) - tested
    family = (
        f"Holm's adjustment runs over the family “exploration: readings”, the matrix's {tested} "
        "tests (every reading, measure and effect; the null control's rows, and those of RMSE "
        "per grip distance, whose hypothesis is its excess over the null control, are shown "
        "and left out"
        + (
            f", and so are {untested} cells where every network scored the same on every object, "
            "which leave nothing to test"
            if untested
            else ""
        )
        + "), and a verdict needs the adjusted p below 0.05."
    )
    if n == [1]:
        return (
            "Each reading ran once here (one replication at the config's seed), so a test below "
            "is that replication's t-test over its networks (t with networks − 2 degrees of "
            "freedom, the mapping between networks): it says how sure the effect is for these "
            "demonstrations, maps and networks, not whether another replication would show it. "
            f"`{ROBUSTNESS_COMMAND}` replicates every reading. " + family
        )
    return (
        f"Each reading ran {' to '.join(map(str, n))} whole replications (each reseeding the "
        "demonstrations, the SOMs and the networks); a test is a t-test of the replications' "
        "estimates (replications − 1 degrees of freedom) and an interval a 95% t-interval. "
        + family
    )


def readings_conclusion(summary) -> dict[str, Claim]:
    """What the readings matrix says (MyST), generated from ``data/readings/summary.csv``: per
    measure and effect, which readings give it in the paper's direction, reversed or not at all
    (``readings.direction``, on Holm's p), and which readings give both effects."""
    from icub_affordance.readings import direction

    readings = list(dict.fromkeys(summary["reading"]))
    measures = [m for m in dict.fromkeys(summary["measure"]) if is_hypothesis(m)]
    rows = {(r["reading"], r["measure"], r["effect"]): r for _, r in summary.iterrows()}
    info = summary.drop_duplicates("reading").set_index("reading")

    def label(reading: str) -> str:
        row = info.loc[reading]
        return f"*{reading_label(row['cue'], row['goal_response'])}*"

    def listing(names: list[str]) -> str:
        labels = [label(r) for r in names]
        if not labels:
            return "no reading"
        return labels[0] if len(labels) == 1 else ", ".join(labels[:-1]) + " and " + labels[-1]

    def on(measure, effects=("congruency", "size")) -> tuple[str, ...]:
        keys = []
        for reading in readings:
            for effect in effects:
                row = rows[(reading, measure, effect)]
                keys += _stats(row, ("diff", "p_holm"), summary_key)
        return _on(keys)

    lines, rests = [], []
    for measure in measures:
        for effect in ("congruency", "size"):
            by = {d: [] for d in DIRECTIONS}
            for reading in readings:
                by[direction(rows[(reading, measure, effect)])].append(reading)
            parts = [f"{DIRECTIONS[d]} with {listing(names)}" for d, names in by.items() if names]
            lines.append(
                f"- **{effect.capitalize()}, {MEASURE_NAMES[measure]}:** " + "; ".join(parts) + "."
            )
        rests += on(measure)
    both = {
        measure: [
            r
            for r in readings
            if direction(rows[(r, measure, "congruency")])
            == direction(rows[(r, measure, "size")])
            == "paper"
        ]
        for measure in measures
    }
    first = measures[0]
    if both[first]:
        paper = (
            f"On {MEASURE_NAMES[first]}, the paper's own measure, both effects go the paper's way "
            f"with {listing(both[first])}."
        )
    else:
        paper = (
            f"On {MEASURE_NAMES[first]}, the paper's own measure, no reading gives both effects "
            "in the paper's direction."
        )
    others = [m for m in measures[1:] if both[m]]
    other = (
        " ".join(
            f"On {MEASURE_NAMES[m]}, both go the paper's way with {listing(both[m])}."
            for m in others
        )
        or "No other measure gives both effects in the paper's direction under any reading."
    )
    return {
        "conclusion_effects": Claim("\n".join(lines), tuple(rests)),
        "conclusion_paper_measure": Claim(paper, on(first)),
        "conclusion_other_measures": Claim(other, tuple(k for m in measures[1:] for k in on(m))),
    }


def null_control_sentence(summary) -> Claim | None:
    """How much of RMSE per grip distance's size effect the denominator alone makes, per
    reading: the measure's size effect beside its null control's (numbers, no test)."""
    from icub_affordance.measures import NULL_CONTROLS

    parts, keys = [], []
    for measure, null in NULL_CONTROLS.items():
        for _, row in summary[
            (summary["measure"] == measure) & (summary["effect"] == "size")
        ].iterrows():
            control = summary[
                (summary["measure"] == null)
                & (summary["effect"] == "size")
                & (summary["reading"] == row["reading"])
            ].iloc[0]
            parts.append(
                f"*{reading_label(row['cue'], row['goal_response'])}* {row['diff']:+.3g} "
                f"beside {control['diff']:+.3g} from the null control"
            )
            keys += [summary_key(row, "diff"), summary_key(control, "diff")]
    if not parts:
        return None
    return Claim(
        "The size effect on RMSE per grip distance, and the same effect made by dividing one "
        "constant error per network by each trial's grip distance (the null control): "
        + "; ".join(parts)
        + ". What the null control shows, the denominator makes by itself, whatever the network "
        "did: of a size effect on RMSE per grip distance, only what exceeds its null control "
        "can come from the movements.",
        _on(keys),
    )


def _cells(rows, with_ci: bool = True) -> str:
    out = []
    for _, row in rows.iterrows():
        text = f"the {row['effect']} effect on {MEASURE_NAMES[row['measure']]}"
        ci = f" [{row['ci_low']:+.3g}, {row['ci_high']:+.3g}]" if with_ci else ""
        out.append(f"{text} ({row['diff']:+.3g}{ci}, {fmt_holm(row['p_holm'], row.get('family'))})")
    return "; ".join(out)


def cue_timing_conclusion(differences) -> Claim | None:
    """What the paired tests of first_step minus all_steps show (``differences.csv``): the
    cue timing is said to change an effect only where that difference is significant after
    Holm's adjustment."""
    rows = differences[
        (differences["comparison"] == "cue_timing") & differences["measure"].map(is_hypothesis)
    ]
    if rows.empty:
        return None
    keys = _on(k for _, r in rows.iterrows() for k in _stats(r, ("diff", "p_holm"), difference_key))
    sig = rows[rows["p_holm"] < ALPHA]
    if sig.empty:
        return Claim(
            f"No difference between the two cue timings survives Holm's adjustment over the "
            f"{int((differences['measure'].map(is_hypothesis)).sum())} tests of differences "
            "(each effect of one reading minus the same effect of the other, paired by network): "
            "this build does not show that the cue timing decides any effect on any measure.",
            keys,
        )
    parts = []
    for goal, group in sig.groupby("at", sort=False):
        parts.append(f"with {GOAL_RESPONSES[goal]}, " + _cells(group))
    rest = (
        " No other difference between the cue timings survives the adjustment."
        if len(sig) < len(rows)
        else ""
    )
    return Claim(
        "The cue timing changes these effects (the cue at the first step only minus the cue at "
        "every step, paired by network, significant after Holm's adjustment): "
        + "; ".join(parts)
        + "."
        + rest,
        keys,
    )


def goal_response_conclusion(differences) -> Claim | None:
    """What the paired tests of grows minus fixed and their equivalence tests show: a difference
    only where it is significant after Holm's adjustment, no difference only where the TOST
    within the declared margin is (Holm-adjusted over the equivalence tests), and "the Goal
    response barely matters" only if every effect on every measure is equivalent."""
    rows = differences[
        (differences["comparison"] == "goal_response") & differences["measure"].map(is_hypothesis)
    ]
    if rows.empty:
        return None
    keys = _on(
        k
        for _, r in rows.iterrows()
        for k in _stats(r, ("diff", "p_holm", "p_equivalence_holm"), difference_key)
    )
    sig = rows[rows["p_holm"] < ALPHA]
    same = rows[rows["p_equivalence_holm"] < ALPHA]
    identical = rows[rows["identical"].astype(str) == "True"] if "identical" in rows else rows[:0]
    neither = len(rows) - len(sig) - len(same) - len(identical)
    sentences = []
    if sig.empty:
        sentences.append(
            "No effect differs between the two Goal responses after Holm's adjustment (a "
            "widening bump minus a fixed one, paired by network)."
        )
    else:
        parts = [
            f"with {CUES[cue]}, " + _cells(group) for cue, group in sig.groupby("at", sort=False)
        ]
        sentences.append(
            "The Goal response changes these effects (a widening bump minus a fixed one, paired "
            "by network, significant after Holm's adjustment): " + "; ".join(parts) + "."
        )
    tested = same
    if not tested.empty:
        parts = []
        for cue, group in tested.groupby("at", sort=False):
            items = [
                f"the {r['effect']} effect on {MEASURE_NAMES[r['measure']]} (within "
                f"±{r['margin']:g}, TOST "
                f"{fmt_holm(r['p_equivalence_holm'], r.get('family_equivalence'))})"
                for _, r in group.iterrows()
            ]
            parts.append(f"with {CUES[cue]}, " + "; ".join(items))
        sentences.append(
            "Within the margins declared in the config, the Goal response is shown to make no "
            "difference (equivalence tests) to these effects: " + "; ".join(parts) + "."
        )
    if not identical.empty:
        parts = [
            f"with {CUES[cue]}, "
            + "; ".join(
                f"the {r['effect']} effect on {MEASURE_NAMES[r['measure']]}"
                for _, r in group.iterrows()
            )
            for cue, group in identical.groupby("at", sort=False)
        ]
        sentences.append(
            "These effects are identical on every network under both responses (nothing "
            "varies, so no test is needed or possible): " + "; ".join(parts) + "."
        )
    if len(same) + len(identical) == len(rows):
        sentences.append(
            "So the Goal response barely matters: every effect on every measure is the same "
            "within its margin under both responses."
        )
    elif neither:
        sentences.append(
            f"For the other {neither} of the {len(rows)} effects, the data neither show a "
            "difference between the Goal responses nor rule one out within the margin: whether "
            "the Goal response matters there is not known from this build."
        )
    return Claim(" ".join(sentences), keys)


# ---- What drives the size effect -----------------------------------------------------------

#: The demonstrations' measures (icub_affordance.size_dose.GEOMETRY), in short.
GEOMETRY_SHORT = {"demo_path_length": "path length", "demo_spread": "spread"}
GEOMETRY_SHORT["demo_grip_distance"] = "grips' distance"


def size_verdict(term) -> str:
    """A size-study test (positive: large objects lower) by its Holm p: "in the paper's
    direction", "reversed", "not shown" (not "none": that needs an equivalence test)."""
    word = verdict_word({"estimate": term["estimate"], "p": term["p"], "p_holm": term["p_holm"]})
    return {"reproduced": "in the paper's direction"}.get(word, word)


def trend_phrase(term) -> str:
    """Where a tested change moves the size effect (positive: towards the paper's direction)."""
    word = size_verdict(term)
    if word in ("not shown", "not testable"):
        return "by no amount its test shows"
    return ("away from" if word == "reversed" else "towards") + " the paper's direction"


def account_phrase(slopes) -> str:
    """What more size delivered to the maps (the paper's mechanism) does, from every cue
    timing's declared slope."""
    words = {trend_phrase(s) for s in slopes}
    if len(words) > 1:
        return "moves the size effect differently under the two cue timings"
    return {"away from the paper's direction": "pushes the size effect against the paper",
            "towards the paper's direction": "pushes the size effect the paper's way"}.get(
        words.pop(), "is not shown to move the size effect")  # fmt: skip


def removal_phrase(removed) -> str:
    """What the removal control (no size in the input) says of the motor side, from its rows."""
    words = {size_verdict(r) for _, r in removed.iterrows()}
    can = "reverse the" if "reversed" in words else "give the paper's"
    if words & {"reversed", "in the paper's direction"}:
        return f"the movements the networks learn can {can} size effect without size in the input"
    return "this build cannot say whether the movements alone produce a size effect"


def named_measures(measures) -> str:
    """The demonstrations' measures named in short, joined by "and"."""
    words = [f"the {GEOMETRY_SHORT[m]}" for m in measures] or ["none of the measures"]
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]
