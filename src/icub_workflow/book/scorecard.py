"""The front page's scorecard: each claim of the paper, and each question this project adds, with
the paper's result, this build's, a verdict word and the scale it was measured at.

Every verdict is a ``text.Claim`` resting on the numbers beside it (``intro.score_*``), chosen by
the test's direction, interval and p adjusted within its named family (``text.verdict_word``);
the table the page shows is these same values, row by row.
"""

from __future__ import annotations

from collections.abc import Mapping

import pandas as pd

from icub_affordance import findings as science

from . import text

#: The paper's level of the training RMSE after about 2,000 iterations and at the end (its
#: Figure 4: "about 0.05"): the learning row reads the build's end RMSE against it.
PAPER_FINAL_RMSE = 0.05

#: Verdict words of the rows that ask this project's questions of the robot: the bar
#: (``findings.GRASPS``) against the 95% interval of the share held.
BAR_WORDS = {"above": "shown", "includes": "not known", "below": "falls short"}


def _term(prefix: str, term: Mapping) -> dict:
    """A test's numbers as scorecard values."""
    return {
        f"{prefix}_estimate": float(term["estimate"] if "estimate" in term else term["diff"]),
        f"{prefix}_ci_low": float(term["ci_low"]),
        f"{prefix}_ci_high": float(term["ci_high"]),
        f"{prefix}_p_holm": float(term["p_holm"]),
        f"{prefix}_family": str(term["family"]),
    }


def _result(values: Mapping, prefix: str) -> str:
    return (
        f"{values[f'{prefix}_estimate']:+.4f} [{values[f'{prefix}_ci_low']:+.4f}, "
        f"{values[f'{prefix}_ci_high']:+.4f}]; Holm p {values[f'{prefix}_p_holm']:.2g} "
        f"({values[f'{prefix}_family']})"
    )


def _test_verdict(values: Mapping, prefix: str) -> text.Claim:
    word = text.verdict_word(
        {"estimate": values[f"{prefix}_estimate"], "p": values[f"{prefix}_p_holm"],
         "p_holm": values[f"{prefix}_p_holm"]}
    )  # fmt: skip
    return text.Claim(word, (f"intro.{prefix}_estimate", f"intro.{prefix}_p_holm"))


def _pct(share: float) -> str:
    return f"{100 * share:.1f}%"


def _bar_position(low: float, high: float, bar: float) -> str:
    return "above" if low > bar else "below" if high < bar else "includes"


def scorecard(
    anova: dict,
    curve: dict,
    readings: pd.DataFrame,
    size: pd.DataFrame,
    variants: pd.DataFrame,
    confirmation: pd.DataFrame,
) -> tuple[dict, pd.DataFrame]:
    """The scorecard's values (for ``findings.json``'s ``intro``) and its table."""
    values: dict[str, object] = {}
    rows: list[dict[str, object]] = []
    networks = anova["closed_loop"]["n_networks"]
    own_scale = f"{networks} networks, one set of demonstrations"

    def add(claim: str, paper: str, result: str, prefix: str, scale: str, chapter: str) -> None:
        rows.append(
            {"claim or question": claim, "paper": paper, "this build": result,
             "verdict": values[f"{prefix}_verdict"].text, "measured at": scale,
             "chapter": chapter}
        )  # fmt: skip

    # the paper's claims
    values |= {"score_learn_start": curve["start"], "score_learn_end": curve["end"],
               "score_learn_paper": PAPER_FINAL_RMSE}  # fmt: skip
    values["score_learn_verdict"] = text.Claim(
        "reproduced" if curve["end"] <= PAPER_FINAL_RMSE else "not shown",
        ("intro.score_learn_end",),
    )
    add(
        "The arm learns to grasp (training RMSE)",
        f"≈0.3 → ≈{PAPER_FINAL_RMSE}",
        f"{curve['start']:.3f} → {curve['end']:.3f}",
        "score_learn",
        own_scale,
        "results",
    )
    claims = (
        ("congruency", "contrasts", "Congruent lower: all-trial RMSE (the paper's measure)"),
        ("congruency", "correct_rt", "Congruent faster: correct-trial RMSE (reaction time)"),
        ("size", "contrasts", "Large lower: all-trial RMSE (the paper's measure)"),
        ("size", "correct_rt", "Large faster: correct-trial RMSE (reaction time)"),
    )
    paper = {"congruency": "congruent lower, significant", "size": "large lower, significant"}
    for effect, outcome, claim in claims:
        term = (
            anova["contrasts"]["closed_loop"][effect]
            if outcome == "contrasts"
            else anova["closed_loop"][outcome][effect]
        )
        prefix = f"score_{effect}_{'all' if outcome == 'contrasts' else 'correct'}"
        values |= _term(prefix, term)
        values[f"{prefix}_verdict"] = _test_verdict(values, prefix)
        cells = term.get("cells", {})
        scale = own_scale if not cells else (
            f"{networks} networks; {min(cells.values())}-{max(cells.values())} with a correct "
            "trial per cell")  # fmt: skip
        add(claim, paper[effect], _result(values, prefix), prefix, scale, "results")

    # this project's questions
    other = readings[
        (readings["measure"] == "rmse")
        & (readings["effect"] == "congruency")
        & (readings["cue"] != readings["cue"].iloc[0])
    ]
    if not other.empty:
        row = other.iloc[0]
        values |= _term("score_reading", row)
        values["score_reading_verdict"] = _test_verdict(values, "score_reading")
        add(
            f"Congruency under the other cue reading ({row['reading']})",
            "not asked",
            _result(values, "score_reading"),
            "score_reading",
            f"{int(row['replications'])} replication(s) of 12 networks",
            "readings",
        )
    for dose, question in (
        ("0.0", "Size effect with the maps' size difference removed"),
        ("equal_grips", "Size effect with each object's grips moved towards one distance"),
    ):
        chosen = size[
            (size["dose"].astype(str) == dose)
            & (size["measure"] == "rmse")
            & (size["family"].str.contains("declared"))
            & (size["cue"] == size["cue"].iloc[0])
        ]
        if chosen.empty:
            continue
        row = chosen.iloc[0]
        prefix = "score_size_" + ("maps" if dose == "0.0" else "grips")
        values |= _term(prefix, row)
        values[f"{prefix}_verdict"] = _test_verdict(values, prefix)
        add(
            f"{question} (cue {row['cue'].replace('_', ' ')})",
            "not asked",
            _result(values, prefix),
            prefix,
            f"{int(row['replications'])} replications of 12 networks",
            "size",
        )
    bar = science.GRASPS
    own = variants[variants["run"] == variants["run"].iloc[0]].iloc[0]
    held = round(own["grasping_success"] * own["grasping_trials"])
    low, high = science.held_interval(held, int(own["grasping_trials"]))
    values |= {"score_robot_own_share": float(own["grasping_success"]),
               "score_robot_own_ci_low": low, "score_robot_own_ci_high": high}  # fmt: skip
    values["score_robot_own_verdict"] = text.Claim(
        BAR_WORDS[_bar_position(low, high, bar)],
        ("intro.score_robot_own_ci_low", "intro.score_robot_own_ci_high"),
    )
    add(
        "The paper's networks, driving the arm, hold the object",
        "not asked",
        f"{_pct(own['grasping_success'])} of grasping trials "
        f"[{_pct(low)}, {_pct(high)}] (exact interval); bar {text.pct(bar)}",
        "score_robot_own",
        f"{int(own['networks'])} networks × {int(own['grasping_trials'] // own['networks'])}"
        " grasping trials",
        "grasping",
    )
    confirmed = confirmation[confirmation["seed_set"] == "confirmation"]
    if not confirmed.empty:
        row = confirmed.iloc[0]
        values |= {"score_robot_best_share": float(row["share"]),
                   "score_robot_best_ci_low": float(row["ci_low"]),
                   "score_robot_best_ci_high": float(row["ci_high"])}  # fmt: skip
        values["score_robot_best_verdict"] = text.Claim(
            BAR_WORDS[_bar_position(row["ci_low"], row["ci_high"], bar)],
            ("intro.score_robot_best_ci_low", "intro.score_robot_best_ci_high"),
        )
        add(
            "A larger network, chosen then confirmed on fresh seeds, holds the object",
            "not asked",
            f"{_pct(row['share'])} of grasping trials [{_pct(row['ci_low'])}, "
            f"{_pct(row['ci_high'])}] (clustered interval); bar {text.pct(bar)}",
            "score_robot_best",
            f"{int(row['networks'])} fresh networks × {int(row['trials'] // row['networks'])}"
            " grasping trials",
            "grasping",
        )
    return values, pd.DataFrame(rows)
