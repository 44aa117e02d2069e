"""The front page's scorecard: each claim of the paper and each question this project adds, with
the paper's result, this build's, a verdict word (a ``text.Claim`` on the numbers beside it) and
the scale it was measured at."""

from __future__ import annotations

import itertools

import numpy as np
import pandas as pd

from icub_affordance.analysis import verdicts as science

from . import text, words

#: The paper's training RMSE after about 2,000 iterations and at the end (its Figure 4).
PAPER_FINAL_RMSE = 0.05
PAPER_SAYS = {"congruency": "congruent lower, significant", "size": "large lower, significant"}
#: What the paper says of a declared test's measure: it reports the all-trial RMSE only (its test
#: mode unnamed); the correct-trial RMSE is this project's reading of its reaction-time claim.
PAPER_MEASURE = {"rmse": "", "rmse_correct": " (on all trials; correct trials not measured)"}


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
    values[f"{prefix}_verdict"] = text.Claim(words.BAR_WORDS[side], rests)
    pct = "{:.1%}".format
    return values, f"{pct(share)} of grasping trials [{pct(low)}, {pct(high)}] ({how} interval); " \
        f"bar {science.GRASPS:.0%}"  # fmt: skip


def claim_key(row) -> str:
    """A declared test's name in findings.json's ``index``."""
    return "claim_" + "_".join(str(row[k]) for k in ("cue", "mode", "measure", "effect"))


def claims_values(
    summary: pd.DataFrame,
    power: pd.DataFrame,
    sensitivity: pd.DataFrame,
    cells: pd.DataFrame,
    replications: pd.DataFrame | None = None,
) -> tuple[dict, pd.DataFrame]:
    """The confirmatory family's values (``claim_<cue>_<mode>_<measure>_<effect>_*``: estimate,
    interval, Holm p, verdict, power) and its table, a row per declared test. Each correct-trial
    test leads with its estimate over every replication (``sensitivity``: correct_sensitivity.csv,
    exploration; ``sens_<cue>_<mode>_<effect>_*``), since the declared test leaves out the
    replications with a cell without a correct trial; beside it, the fewest networks carrying a
    cell per mapping (``cells``: data/claims/correct_cells.csv) in the replications the test used
    (``replications``: data/claims/replications.csv, those with an estimate; every replication
    where it is not given)."""
    values: dict[str, object] = sensitivity_values(sensitivity)
    rows = []
    keyed = power.set_index(["cue", "mode", "measure", "effect"])
    for _, row in summary.iterrows():
        key = claim_key(row)
        word = words.CLAIM_WORDS[row["direction"]]
        values |= {f"{key}_{k}": float(row[k]) for k in ("estimate", "ci_low", "ci_high", "p",
                                                         "p_holm")}  # fmt: skip
        values[f"{key}_estimable"] = int(row["estimable"])
        values[f"{key}_verdict"] = text.Claim(word, (f"index.{key}_estimate",
                                                     f"index.{key}_p_holm"))  # fmt: skip
        planned = keyed.loc[(row["cue"], row["mode"], row["measure"], row["effect"])]
        rows.append({
            "claim": text.CLAIM_PARTS[row["effect"]], "measure": text.CLAIM_PARTS[row["measure"]],
            "cue": text.CLAIM_PARTS[row["cue"]], "test": text.CLAIM_PARTS[row["mode"]],
            "over every replication (exploration)": _sensitivity_cell(values, row),
            "estimate [95% interval]": interval(row),
            "replications with an estimate": f"{int(row['estimable'])} of "
                                             f"{int(row['replications'])}",
            "Holm p": row["p_holm"], "verdict": word,
            "power planned (at least)": float(planned["power_at_least"]),
            "fewest networks per cell (A / B)": fewest_per_mapping(
                cells, row, used_seeds(replications, row))
            if row["measure"] == "rmse_correct" else "–",
        })  # fmt: skip
    for (mode, measure), group in summary.groupby(["mode", "measure"], sort=False):
        both = [
            cue
            for cue, g in group.groupby("cue", sort=False)
            if set(g.loc[g["direction"] == "paper", "effect"]) >= {"congruency", "size"}
        ]
        rests = tuple(f"index.{claim_key(r)}_p_holm" for _, r in group.iterrows())
        said = text.listing((text.CLAIM_PARTS[c] for c in both), "none")
        values[f"claims_both_{mode}_{measure}"] = text.Claim(said, rests)  # fmt: skip
    values |= by_condition(summary)
    values["claims_replications"] = int(summary["replications"].max())
    return values, pd.DataFrame(rows)


def sens_key(row) -> str:
    """A correct-trial test's name in the sensitivity's values."""
    return "sens_" + "_".join(str(row[k]) for k in ("cue", "mode", "effect"))


def sensitivity_values(sensitivity: pd.DataFrame) -> dict[str, object]:
    """The correct-trial effects over every replication (exploration): estimate, interval, Holm
    p within its own family, and the verdict word (``words.verdict_word``)."""
    values: dict[str, object] = {}
    for _, row in sensitivity.iterrows():
        key = sens_key(row)
        values |= {f"{key}_{k}": float(row[k]) for k in ("estimate", "ci_low", "ci_high",
                                                         "p_holm")}  # fmt: skip
        values[f"{key}_replications"] = int(row["replications_used"])
        values[f"{key}_verdict"] = text.Claim(
            words.verdict_word(dict(row)), (f"index.{key}_estimate", f"index.{key}_p_holm")
        )
    return values


def used_seeds(replications: pd.DataFrame | None, row) -> set | None:
    """The seeds of the replications a declared test rests on: those with an estimate of it
    (None: every replication)."""
    if replications is None:
        return None
    keys = ("cue", "mode", "measure", "effect")
    mine = replications[(replications[list(keys)] == [row[k] for k in keys]).all(axis=1)]
    return set(mine.loc[mine["estimate"].notna(), "seed"])


def fewest_per_mapping(cells: pd.DataFrame, row, seeds: set | None = None) -> str:
    """The fewest networks carrying a congruency x size cell in any of the replications
    ``seeds`` (None: every replication), per mapping; a dash where none is left."""
    chosen = cells[(cells["cue"] == row["cue"]) & (cells["mode"] == row["mode"])]
    if seeds is not None:
        chosen = chosen[chosen["seed"].isin(seeds)]
    if chosen.empty:
        return "–"
    fewest = chosen.groupby("mapping")["networks"].min()
    return " / ".join(str(int(n)) for n in fewest)


def _sensitivity_cell(values: dict, row) -> str:
    """A correct-trial test's estimate over every replication, with its verdict; a dash for the
    paper's measure, where no replication lacks an estimate."""
    key = sens_key(row)
    if row["measure"] != "rmse_correct" or f"{key}_estimate" not in values:
        return "–"
    est, low, high, p = (values[f"{key}_{k}"] for k in ("estimate", "ci_low", "ci_high", "p_holm"))
    return (
        f"{est:+.4f} [{low:+.4f}, {high:+.4f}], {values[f'{key}_replications']} "
        f"replications; Holm p {p:.2g}: {values[f'{key}_verdict'].text}"
    )


def _every_replication(group: pd.DataFrame, sens: dict) -> tuple[dict, str, text.Claim] | None:
    """A correct-trial claim's verdicts over every replication, none left out (exploration), by
    test mode as the declared ones are read (``by_condition``): the values they rest on, the
    words by mode, and their count. None for the paper's measure or without the estimates: the
    scorecard leads with these because the declared test leaves out a replication with a cell
    without a correct trial, which is the effect under test."""
    keys = [sens_key(r) for _, r in group.iterrows()]
    if (group["measure"] != "rmse_correct").any() or any(f"{k}_verdict" not in sens
                                                         for k in keys):  # fmt: skip
        return None
    said = {f"{k}_{s}": sens[f"{k}_{s}"] for k in keys for s in ("estimate", "p_holm")}
    rests = tuple(f"index.{k}_p_holm" for k in keys)
    modes, every = [], []
    for mode in _ordered(group, "mode", MODE_ORDER):
        rows = group[group["mode"] == mode]
        by = {cue: sens[f"{sens_key(r)}_verdict"].text
              for cue in _ordered(rows, "cue", CUE_ORDER)
              for _, r in rows[rows["cue"] == cue].iterrows()}  # fmt: skip
        modes.append(f"{text.CLAIM_PARTS[mode]}: {text.by_cue(by)}")
        every += by.values()
    return said, "; ".join(modes), text.Claim(text.condition_count(every), rests)


#: The test modes, the one the paper's text describes first (book/notes.md, "Which test mode is
#: the paper's"), and the cue timings.
MODE_ORDER = ("teacher_forced", "closed_loop")
CUE_ORDER = ("first_step", "all_steps")


def _ordered(frame: pd.DataFrame, column: str, order: tuple[str, ...]) -> list[str]:
    return [v for v in order if v in set(frame[column])] + sorted(set(frame[column]) - set(order))


def by_condition(summary: pd.DataFrame) -> dict[str, text.Claim]:
    """Each claim's verdicts by condition (cue timing × test mode), per measure: per test mode,
    the words by cue timing (``claims_<mode>_<measure>_<effect>``), and over the conditions, how
    many give each word (``claims_count_<measure>_<effect>``). The tests are those of the
    declared family, each read once; both modes test the same networks, so the conditions are
    counted, not the tests pooled."""
    values: dict[str, text.Claim] = {}
    for (measure, effect), group in summary.groupby(["measure", "effect"], sort=False):
        said_words = []
        for mode in _ordered(group, "mode", MODE_ORDER):
            rows = group[group["mode"] == mode].set_index("cue")
            said = {cue: words.CLAIM_WORDS[rows.loc[cue, "direction"]]
                    for cue in _ordered(rows.reset_index(), "cue", CUE_ORDER)}  # fmt: skip
            rests = tuple(f"index.{claim_key(r)}_p_holm" for _, r in rows.reset_index().iterrows())
            values[f"claims_{mode}_{measure}_{effect}"] = text.Claim(text.by_cue(said), rests)
            said_words += said.values()
        rests = tuple(f"index.{claim_key(r)}_p_holm" for _, r in group.iterrows())
        values[f"claims_count_{measure}_{effect}"] = text.Claim(
            text.condition_count(said_words), rests
        )
    return values


def interval(row) -> str:
    """A test's estimate and 95% interval as the tables show them ("no test" without one)."""
    if not np.isfinite(row["estimate"]):
        return "–"
    if not np.isfinite(row["ci_low"]):
        return f"{row['estimate']:+.4f} (no test)"
    return f"{row['estimate']:+.4f} [{row['ci_low']:+.4f}, {row['ci_high']:+.4f}]"


def scorecard(claims: pd.DataFrame, learning: pd.DataFrame, size: pd.DataFrame,
              variants: pd.DataFrame, confirmation: pd.DataFrame, signatures: pd.DataFrame,
              sensitivity: pd.DataFrame | None = None, contact: pd.DataFrame | None = None,
              contact_cells: pd.DataFrame | None = None) -> tuple[dict, pd.DataFrame]:  # fmt: skip
    """The scorecard's values (for ``findings.json``'s ``index``) and its table: the paper's
    claims from the confirmation's replications (``claims``: data/claims/summary.csv), the
    learning curve over the same replications, then this project's questions."""
    values: dict[str, object] = {}
    rows: list[dict[str, object]] = []
    replications = int(len(learning))
    networks = int(learning["networks"].iloc[0])
    scale = f"{replications} replications × {networks} networks"

    def add(prefix, said, claim, paper, measured_at, chapter) -> None:
        values.update(said[0])
        rows.append({"claim or question": claim, "paper": paper, "this build": said[1],
                     "verdict": values[f"{prefix}_verdict"].text, "measured at": measured_at,
                     "chapter": chapter})  # fmt: skip

    end = float(learning["end"].mean())
    learnt = words.CONFIRMED if end <= PAPER_FINAL_RMSE else words.NOT_SHOWN
    learn = {"score_learn_start": float(learning["start"].mean()), "score_learn_end": end,
             "score_learn_end_low": float(learning["end"].min()),
             "score_learn_end_high": float(learning["end"].max()),
             "score_learn_paper": PAPER_FINAL_RMSE,
             "score_learn_verdict": text.Claim(learnt, ("index.score_learn_end",))}  # fmt: skip
    add("score_learn", (learn, f"{learn['score_learn_start']:.3f} → {end:.3f} (replications "
                               f"{learn['score_learn_end_low']:.3f}–"
                               f"{learn['score_learn_end_high']:.3f})"),
        "The arm learns to grasp (training RMSE)", f"≈0.3 → ≈{PAPER_FINAL_RMSE}", scale,
        "results")  # fmt: skip
    for (measure, effect), group in claims.groupby(["measure", "effect"], sort=False):
        said = {f"{claim_key(r)}_{k}": float(r[k]) for _, r in group.iterrows()
                for k in ("estimate", "p_holm")}  # fmt: skip
        found = by_condition(group)
        prefix = f"score_claim_{measure}_{effect}"
        said[f"{prefix}_verdict"] = found[f"claims_count_{measure}_{effect}"]
        modes = "; ".join(
            f"{text.CLAIM_PARTS[mode]}: {found[f'claims_{mode}_{measure}_{effect}'].text}"
            for mode in _ordered(group, "mode", MODE_ORDER)
        )
        fewer = group[group["estimable"] < group["replications"]]
        sens = {} if sensitivity is None else sensitivity_values(sensitivity)
        led = _every_replication(group, sens)
        selected = ""
        if led is None:
            modes += " (confirmatory)"
        else:  # led by every replication; the declared verdicts beside, with their selection
            said |= led[0]
            said[f"{prefix}_verdict"] = text.Claim(
                f"every replication: {led[2].text}; declared: {said[f'{prefix}_verdict'].text}",
                led[2].rests_on + said[f"{prefix}_verdict"].rests_on,
            )
            if not fewer.empty:
                selected = "; on the replications with a correct trial in every cell: " + ", ".join(
                    f"{int(r['estimable'])} of {int(r['replications'])} "
                    f"({text.CLAIM_PARTS[r['mode']]}, {text.CLAIM_PARTS[r['cue']]})"
                    for _, r in fewer.iterrows())  # fmt: skip
            modes = (f"over every replication (exploration), {led[1]}. Declared (confirmatory), "
                     f"{modes}{selected}")  # fmt: skip
        add(prefix, (said, modes),
            f"{text.CLAIM_PARTS[effect]}: {text.CLAIM_PARTS[measure]}",
            PAPER_SAYS[effect] + PAPER_MEASURE[measure],
            f"{int(group['replications'].max())} replications × {networks} networks per condition"
            + ("" if selected else "".join(
                f"; {int(r['estimable'])} with an estimate ({text.CLAIM_PARTS[r['mode']]}, "
                f"{text.CLAIM_PARTS[r['cue']]})" for _, r in fewer.iterrows())),
            "index")  # fmt: skip
    # this project's questions: the size study's declared tests, under each cue timing, at dose
    # 0 (no size difference in the maps; its keys carry no dose), beside them at every other
    # dose, then the dose contrast
    doses = [d for d in dict.fromkeys(size["dose"].astype(str)) if " - " not in d]
    for (test, name, question), cue, dose in itertools.product((
        ("size", "size", "Size's own part of the size effect, at no gap between the grips' "
                         "distances"),
        ("grip_distance", "grips", "The part of the size effect that the grips' distance "
                                   "carries"),
        ("dose", "dose", "More size in the maps changes the size effect (dose contrast)"),
    ), dict.fromkeys(size["cue"]), doses):  # fmt: skip
        at = pd.to_numeric(size["dose"], errors="coerce")
        first = float(dose) == 0
        if test == "dose":
            if not first:
                continue
            chosen = size[(size["test"] == test) & (size["cue"] == cue)]
        else:
            chosen = size[(size["test"] == test) & (at == float(dose)) & (size["cue"] == cue)]
        for _, row in chosen.head(1).iterrows():
            where = "" if first or test == "dose" else f"{dose.replace('.', '')}_"
            prefix = f"score_size_{name}_{where}{cue}"
            values_, cell = _tested(prefix, row)
            word = text.size_part_word(test, dict(row))
            values_[f"{prefix}_verdict"] = text.Claim(word, (f"index.{prefix}_estimate",
                                                             f"index.{prefix}_p_holm"))  # fmt: skip
            maps = (
                "natural runs, dose " + str(row["dose"])
                if test == "dose"
                else "maps without size (dose 0)"
                if first
                else f"size in the maps (dose {dose})"
            )
            claim = f"{question}; {maps}, {text.CLAIM_PARTS[cue]}, closed loop"
            scale = f"{int(row['replications'])} replications × {networks} networks"
            add(prefix, (values_, cell), claim, "not asked", scale, "size")
    own = variants[variants["run"] == variants["run"].iloc[0]].iloc[0]
    trials = int(own["grasping_trials"])
    low, high = science.held_interval(round(own["grasping_success"] * trials), trials)
    add("score_robot_own", _held("score_robot_own", own["grasping_success"], low, high, "exact"),
        "The paper's networks, driving the arm, hold the object", "not asked",
        f"the robot test: this run's {int(own['networks'])} networks × "
        f"{trials // int(own['networks'])} grasping trials", "robot_test")  # fmt: skip
    for _, row in confirmation[confirmation["seed_set"] == "confirmation"].head(1).iterrows():
        add("score_robot_best",
            _held("score_robot_best", row["share"], row["ci_low"], row["ci_high"], "clustered"),
            "A larger network, chosen then tested again on fresh seeds, holds the object",
            "not asked", f"the robot test: {int(row['networks'])} fresh networks × "
            f"{int(row['trials'] // row['networks'])} grasping trials", "robot_test")  # fmt: skip
    for k, (_, row) in enumerate(() if contact is None else contact.iterrows()):
        prefix = f"score_robot_contact{k or ''}"
        add(prefix, _contact(prefix, row, contact_cells),
            "Congruent faster on the robot: the time until the required grip's fingers touch, "
            "fresh networks", "not asked",
            f"the robot test: {int(row['networks'])} fresh networks × 4 categorisation trials",
            "robot_test")  # fmt: skip
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


def _contact(prefix: str, row, cells: pd.DataFrame | None) -> tuple[dict, str]:
    """The declared contact-time test's values and result cell, with the cells whose trials did
    not all touch named by their cell (the test leaves those networks out)."""
    word = words.CLAIM_WORDS[row["direction"]]
    values = {f"{prefix}_estimate": float(row["estimate"]),
              f"{prefix}_p_holm": float(row["p_holm"]),
              f"{prefix}_verdict": text.Claim(word, (f"index.{prefix}_estimate",
                                                     f"index.{prefix}_p_holm"))}  # fmt: skip
    short = [] if cells is None else [
        f"{c['congruency']} {c['size']} {int(c['touched'])} of {int(c['trials'])}"
        for _, c in cells[(cells["run"] == row["run"]) & (cells["touched"] < cells["trials"])]
        .iterrows()]  # fmt: skip
    touched = "; trials that touched: " + ", ".join(short) if short else ""
    units = (f"{int(row['networks_tested'])} of {int(row['networks'])} networks touched in all "
             "four cells")  # fmt: skip
    if not np.isfinite(row["p_holm"]):
        return values, f"no test: {units}{touched}"
    return values, (f"{row['estimate']:+.3f} s [{row['ci_low']:+.3f}, {row['ci_high']:+.3f}]; "
                    f"Holm p {row['p_holm']:.2g} (declared); {units}{touched}")  # fmt: skip


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
    if pd.isna(row["p_adjusted"]):  # an estimate but no test: the reason says why
        return f"{row['estimate']:+.4f}; no test: {row['reason']}"
    test = "equivalence (TOST) " if "equivalence" in str(row["condition"]) else ""
    return (f"{row['estimate']:+.4f} [{row['ci_low']:+.4f}, {row['ci_high']:+.4f}]; {test}Holm p "
            f"{row['p_adjusted']:.2g} (signatures)")  # fmt: skip


def signature_scale(row) -> str:
    """Where a signature's verdict was made: the replications with an estimate, out of all."""
    if not row["units"]:
        return "not posed" if isinstance(row["reason"], str) and row["reason"] else "no data"
    return f"{int(row['units'])} of {int(row['of'])} replications"
