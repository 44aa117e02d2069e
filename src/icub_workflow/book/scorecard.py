"""The front page's scorecard: each claim of the paper and each question this project adds, with
the paper's result, this build's, a verdict word (a ``text.Claim`` on the numbers beside it) and
the scale it was measured at."""

from __future__ import annotations

import pandas as pd

from icub_affordance import findings as science

from . import text

#: The paper's training RMSE after about 2,000 iterations and at the end (its Figure 4).
PAPER_FINAL_RMSE = 0.05
#: The robot rows: the bar (``findings.GRASPS``) against the 95% interval of the share held.
BAR_WORDS = {"above": "shown", "includes": "not known", "below": "falls short"}
PAPER_SAYS = {"congruency": "congruent lower, significant", "size": "large lower, significant"}


def _tested(prefix: str, term) -> tuple[dict, str]:
    """A test's values and verdict (``text.test_values``), and the result cell."""
    values = text.test_values("index", prefix, dict(term))
    est, low, high, p = (
        values[f"{prefix}_{k}"] for k in ("estimate", "ci_low", "ci_high", "p_holm")
    )
    return values, f"{est:+.4f} [{low:+.4f}, {high:+.4f}]; Holm p {p:.2g} ({term['family']})"


def _held(prefix: str, share: float, low: float, high: float, how: str) -> tuple[dict, str]:
    """A share of grasping trials held, its interval and its verdict against the bar."""
    values = {f"{prefix}_share": float(share), f"{prefix}_ci_low": float(low),
              f"{prefix}_ci_high": float(high)}  # fmt: skip
    side = "above" if low > science.GRASPS else "below" if high < science.GRASPS else "includes"
    rests = (f"index.{prefix}_ci_low", f"index.{prefix}_ci_high")
    values[f"{prefix}_verdict"] = text.Claim(BAR_WORDS[side], rests)
    pct = "{:.1%}".format
    return values, f"{pct(share)} of grasping trials [{pct(low)}, {pct(high)}] ({how} interval); " \
        f"bar {science.GRASPS:.0%}"  # fmt: skip


def scorecard(anova: dict, curve: dict, readings: pd.DataFrame, size: pd.DataFrame,
              variants: pd.DataFrame, confirmation: pd.DataFrame, signatures: pd.DataFrame
              ) -> tuple[dict, pd.DataFrame]:  # fmt: skip
    """The scorecard's values (for ``findings.json``'s ``index``) and its table."""
    values: dict[str, object] = {}
    rows: list[dict[str, object]] = []
    networks = anova["closed_loop"]["n_networks"]
    own_scale = f"{networks} networks, one set of demonstrations"

    def add(prefix, said, claim, paper, scale, chapter) -> None:
        values.update(said[0])
        rows.append({"claim or question": claim, "paper": paper, "this build": said[1],
                     "verdict": values[f"{prefix}_verdict"].text, "measured at": scale,
                     "chapter": chapter})  # fmt: skip

    learnt = "reproduced" if curve["end"] <= PAPER_FINAL_RMSE else "not shown"
    learn = {"score_learn_start": curve["start"], "score_learn_end": curve["end"],
             "score_learn_paper": PAPER_FINAL_RMSE,
             "score_learn_verdict": text.Claim(learnt, ("index.score_learn_end",))}  # fmt: skip
    add("score_learn", (learn, f"{curve['start']:.3f} → {curve['end']:.3f}"),
        "The arm learns to grasp (training RMSE)", f"≈0.3 → ≈{PAPER_FINAL_RMSE}", own_scale,
        "results")  # fmt: skip
    for effect, lower in (("congruency", "Congruent"), ("size", "Large")):
        for trials, measure, term in (
            ("all", "lower: all-trial RMSE (the paper's measure)",
             anova["contrasts"]["closed_loop"][effect]),
            ("correct", "faster: correct-trial RMSE (reaction time)",
             anova["closed_loop"]["correct_rt"][effect]),
        ):  # fmt: skip
            cells = term.get("cells", {})
            scale = own_scale if not cells else (f"{networks} networks; {min(cells.values())}-"
                                                 f"{max(cells.values())} with a correct trial "
                                                 "per cell")  # fmt: skip
            prefix = f"score_{effect}_{trials}"
            add(prefix, _tested(prefix, term), f"{lower} {measure}", PAPER_SAYS[effect], scale,
                "results")  # fmt: skip
    # this project's questions
    key = (readings["measure"] == "rmse") & (readings["effect"] == "congruency")
    other = readings[key & (readings["cue"] != readings["cue"].iloc[0])]
    for _, row in other.head(1).iterrows():
        add("score_reading", _tested("score_reading", {**row, "estimate": row["diff"]}),
            f"Congruency under the other cue reading ({row['reading']})", "not asked",
            f"{int(row['replications'])} replication(s) of 12 networks", "readings")  # fmt: skip
    for dose, name, question in (
        ("0.0", "maps", "Size effect with the maps' size difference removed"),
        ("equal_grips", "grips", "Size effect with each object's grips moved towards one distance"),
    ):  # fmt: skip
        chosen = size[(size["dose"].astype(str) == dose) & (size["measure"] == "rmse")
                      & size["family"].str.contains("declared")
                      & (size["cue"] == size["cue"].iloc[0])]  # fmt: skip
        for _, row in chosen.head(1).iterrows():
            said = _tested(f"score_size_{name}", {**row, "estimate": row["diff"]})
            add(f"score_size_{name}", said,
                f"{question} (cue {row['cue'].replace('_', ' ')})", "not asked",
                f"{int(row['replications'])} replications of 12 networks", "size")  # fmt: skip
    own = variants[variants["run"] == variants["run"].iloc[0]].iloc[0]
    trials = int(own["grasping_trials"])
    low, high = science.held_interval(round(own["grasping_success"] * trials), trials)
    add("score_robot_own", _held("score_robot_own", own["grasping_success"], low, high, "exact"),
        "The paper's networks, driving the arm, hold the object", "not asked",
        f"{int(own['networks'])} networks × {trials // int(own['networks'])} grasping trials",
        "robot_test")  # fmt: skip
    for _, row in confirmation[confirmation["seed_set"] == "confirmation"].head(1).iterrows():
        add("score_robot_best",
            _held("score_robot_best", row["share"], row["ci_low"], row["ci_high"], "clustered"),
            "A larger network, chosen then confirmed on fresh seeds, holds the object",
            "not asked", f"{int(row['networks'])} fresh networks × "
            f"{int(row['trials'] // row['networks'])} grasping trials", "robot_test")  # fmt: skip
    for _, row in signatures[signatures["family"] == "signatures"].iterrows():
        prefix, name = f"score_signature_{row['signature']}", row["signature"]
        said = {f"{prefix}_estimate": float(row["estimate"]),
                f"{prefix}_p_holm": float(row["p_adjusted"]),
                f"{prefix}_verdict": text.Claim(row["verdict"], (
                    f"index.{prefix}_estimate", f"index.{prefix}_p_holm"))}  # fmt: skip
        result = signature_result(row)
        add(prefix, (said, result), SIGNATURE_CLAIMS[name], SIGNATURE_PEOPLE[name],
            signature_scale(row), "signatures")  # fmt: skip
    return values, pd.DataFrame(rows)


#: The scorecard's rows for the human signatures: the claim, and what people showed.
SIGNATURE_CLAIMS = {
    "grows_with_rt": "The congruency effect grows with reaction time (delta-plot slope)",
    "extinction": "The effect fades when the object is blanked early",
    "brief_exposure": "A one-step masked glimpse gives the in-view effect (equivalence)",
    "advance_cueing": "No effect when the response is cued before the object",
}
SIGNATURE_PEOPLE = {
    "grows_with_rt": "people: grows (Tucker & Ellis 2001)",
    "extinction": "people: fades (Tucker & Ellis 2001)",
    "brief_exposure": "people: the same (Tucker & Ellis 2004)",
    "advance_cueing": "people: absent (Tucker & Ellis 2001)",
}


def signature_result(row) -> str:
    """A signature test's result cell: estimate, interval and Holm p (for an equivalence, the
    TOST's), or why there is none."""
    if pd.isna(row["estimate"]):
        return str(row["reason"]) or "–"
    test = "equivalence (TOST) " if "equivalence" in str(row["condition"]) else ""
    return (f"{row['estimate']:+.4f} [{row['ci_low']:+.4f}, {row['ci_high']:+.4f}]; {test}Holm p "
            f"{row['p_adjusted']:.2g} (signatures)")  # fmt: skip


def signature_scale(row) -> str:
    """Where a signature's verdict was made: networks of one replication, or replications."""
    if not row["units"]:
        return "not posed" if isinstance(row["reason"], str) and row["reason"] else "no data"
    if int(row["replications"]) > 1:
        return f"{int(row['units'])} of {int(row['of'])} replications (full scale)"
    return f"{int(row['units'])} of {int(row['of'])} networks, one replication"
