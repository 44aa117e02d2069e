"""The chapter "Words" (config ``words``): the declared family's values and verdicts, the
reactivation's, what qualifies them (an equivalence where the image's own effect is inside the
margin; two effects that read the same errors), the table of the tests, and the front page's
scorecard rows."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from icub_affordance.analysis.decide import significant

from . import text, words
from .scorecard import interval

#: What each declared test asks, in the tables.
QUESTIONS = {
    "congruency": "The name alone: congruent lower (incongruent − congruent)",
    "equivalence": "The name's congruency effect minus the image's, within the margin",
    "size": "The name alone: large lower (small − large)",
}
#: The order the verdict words are counted in, per kind of test.
ORDER = {"congruency": words.CLAIM_WORDS, "size": words.CLAIM_WORDS,
         "equivalence": words.EQUIVALENCE_WORDS}  # fmt: skip


def word_key(row) -> str:
    """A declared test's name in findings.json's ``words``."""
    return "w_" + "_".join(str(row[k]) for k in ("cue", "mode", "measure", "test"))


def _count(said: list[str], order: Mapping[str, str]) -> str:
    """How many conditions give each verdict word: "confirmed in 3 of 8, not shown in 5"."""
    counts = [(w, said.count(w)) for w in dict.fromkeys(order.values()) if w in said]
    parts = [f"{w} in {n}" for w, n in counts]
    parts[0] += f" of {len(said)}"
    return ", ".join(parts)


def _measure(name: str) -> str:
    return text.CLAIM_PARTS.get(name, name.replace("_", " "))


def _equivalence_notes(summary: pd.DataFrame, alpha: float) -> dict:
    """Of the conditions whose name-image difference is shown within the margin: in how many
    the image's own congruency effect lies inside the margin too, and in how many the
    difference itself has p below alpha, unadjusted (the family's columns
    ``image_inside_margin`` and ``difference_below_alpha``, name_effects.qualifiers)."""
    shown = summary[(summary["test"] == "equivalence") & (summary["direction"] == "paper")]
    inside = int(shown["image_inside_margin"].sum())
    differing = int(shown["difference_below_alpha"].sum())
    rests = tuple(f"words.{word_key(r)}_p_holm" for _, r in shown.iterrows())
    note = f" (in {inside} the image's own effect is inside the margin too)" if inside else ""
    differs = ""
    if differing:
        differs = (f"; of the conditions shown equivalent, in {differing} the difference "
                   f"itself has p below {alpha:g} before adjustment (exploration)")  # fmt: skip
    return {
        "equivalence_note": text.Claim(note, rests or ("words.alpha",)),
        "differing_note": text.Claim(differs, rests or ("words.alpha",)),
        "equivalent_inside_margin": inside,
        "equivalent_differing": differing,
    }


def _same_errors(summary: pd.DataFrame) -> dict:
    """On the wrong-grip rate, the conditions where the name's size and congruency effects
    are one number, and whether their wrong grips all fall in the incongruent small cell (the
    family's columns ``same_as_congruency`` and ``only_incongruent_small``)."""
    sizes = summary[(summary["measure"] == "wrong_grip") & (summary["test"] == "size")]
    same = sizes[sizes["same_as_congruency"].astype(bool)]
    rests = tuple(f"words.{word_key({**r.to_dict(), 'test': t})}_estimate"
                  for _, r in same.iterrows() for t in ("congruency", "size"))  # fmt: skip
    if same.empty:
        return {"size_note": text.Claim("", ("words.size_count",)), "same_errors": ""}
    where = ("every wrong grip fell on a small object asked for the grip it does not afford "
             "(incongruent and small), the one cell both contrasts read"
             if same["only_incongruent_small"].astype(bool).all()
             else "their wrong grips fall in cells both contrasts read alike")  # fmt: skip
    said = (f"on the wrong-grip rate the name's size effect is its congruency effect's number "
            f"in {len(same)} of {len(sizes)} conditions: {where}, so these are one finding "
            "read twice")  # fmt: skip
    short = (f" (on the wrong-grip rate, in {len(same)} of {len(sizes)} conditions the "
             "same errors as the congruency effect's)")  # fmt: skip
    return {
        "size_note": text.Claim(short, rests),
        "same_errors": text.Claim(said[0].upper() + said[1:] + ".", rests),
    }


def row_note(row, alpha: float) -> str:
    """What qualifies a test's verdict, in its own row: an equivalence whose difference is itself
    shown (its t Holm-adjusted in ``name_effects.FAMILY_DIFFERENCE``, added after results), or
    whose image effect lies inside the margin, so that a name with no effect would pass too; a
    size effect that is the congruency effect's number, the same wrong grips read by size."""
    said = ""
    if row["test"] == "equivalence" and row["direction"] == "paper":
        p = float(row.get("p_difference_holm", np.nan))
        if significant(p, alpha):
            said += f", and a difference shown (p {p:.2g}, added after results)"
        if str(row["image_inside_margin"]) == "True":
            said += "; tells little: the image's effect is inside the margin"
    elif row["test"] == "size" and str(row["same_as_congruency"]) == "True":
        where = " in one cell" if str(row["only_incongruent_small"]) == "True" else ""
        said += f": the congruency effect's errors{where}, read by size"
    return said


def words_page(inputs: Mapping[str, str], config: dict) -> tuple[dict, dict[str, pd.DataFrame]]:
    """The chapter's values (each test's numbers and ``text.Claim`` verdict, per kind of test
    the count of verdicts over its conditions and what qualifies them, the reactivation per cue
    timing) and its table, a row per declared test."""
    summary = pd.read_csv(inputs["words_summary.csv"], keep_default_na=False, na_values=[""])
    reactivation = pd.read_csv(inputs["words_reactivation.csv"])
    declaration = config["words"]
    alpha = float(declaration["alpha"])
    values: dict = {
        "replications": int(summary["replications"].max()),
        "fewest_estimable": int(summary["estimable"].min()),
        "networks": int(config["network"]["networks"]),
        "family_declared": len(summary),
        "family_size": int(summary["family_size"].iloc[0]),
        "alpha": alpha,
        "seeds": f"{min(declaration['seeds'])}-{max(declaration['seeds'])}",
        "units_per_name": int(config["names"]["units_per_name"]),
        "step": int(declaration["reactivation"]["step"]),
    } | {f"margin_{m}": float(v) for m, v in declaration["margin"].items()}
    rows = []
    for _, row in summary.iterrows():
        key = word_key(row)
        word = ORDER[row["test"]][row["direction"]]
        values |= {f"{key}_{k}": float(row[k]) for k in ("estimate", "ci_low", "ci_high", "p",
                                                         "p_holm")}  # fmt: skip
        rests = (f"words.{key}_estimate", f"words.{key}_p_holm")
        values[f"{key}_verdict"] = text.Claim(word, rests)
        rows.append({
            "test": QUESTIONS[row["test"]], "measure": _measure(row["measure"]),
            "cue": text.CLAIM_PARTS[row["cue"]], "test mode": text.CLAIM_PARTS[row["mode"]],
            "estimate [95% interval]": interval(row),
            "margin": "–" if not np.isfinite(row["margin"]) else f"±{row['margin']:g}",
            "replications with an estimate": f"{int(row['estimable'])} of "
                                             f"{int(row['replications'])}",
            "Holm p": row["p_holm"], "verdict": word + row_note(row, alpha),
        })  # fmt: skip
    for test, group in summary.groupby("test", sort=False):
        said = [ORDER[test][d] for d in group["direction"]]
        rests = tuple(f"words.{word_key(r)}_p_holm" for _, r in group.iterrows())
        values[f"{test}_count"] = text.Claim(_count(said, ORDER[test]), rests)
    values |= _equivalence_notes(summary, alpha) | _same_errors(summary)
    for _, row in reactivation.iterrows():
        key = f"react_{row['cue']}"
        values |= {f"{key}_{k}": float(row[k]) for k in ("estimate", "ci_low", "ci_high", "p",
                                                         "p_holm")}  # fmt: skip
        word = words.REACTIVATION_WORDS[row["direction"]]
        values[f"{key}_verdict"] = text.Claim(word, (f"words.{key}_estimate",
                                                     f"words.{key}_p_holm"))  # fmt: skip
        # the scorecard's word for it, one of the five (the row names what is tested)
        values[f"{key}_word"] = text.Claim(words.CLAIM_WORDS[row["direction"]],
                                           values[f"{key}_verdict"].rests_on)  # fmt: skip
    verdicts = {k.removeprefix("react_").removesuffix("_verdict"): v for k, v in values.items()
                if k.startswith("react_") and k.endswith("_verdict")}  # fmt: skip
    values["react_verdict"] = text.Claim(
        text.by_cue({cue: v.text for cue, v in verdicts.items()}),
        tuple(r for v in verdicts.values() for r in v.rests_on),
    )
    return values, {"words": pd.DataFrame(rows)}


def _ranges(values: Mapping, test: str, what: str) -> str:
    """A test's estimates over its conditions, measure by measure (their units differ)."""
    said = []
    for measure in ("rmse_correct", "wrong_grip"):
        keys = [k for k in values if k.startswith("w_") and k.endswith(f"_{test}_estimate")
                and f"_{measure}_" in k]  # fmt: skip
        found = [float(values[k]) for k in keys if np.isfinite(values[k])]
        if found:
            said.append(f"{_measure(measure)} {min(found):+.4f} to {max(found):+.4f}")
    return f"{what}: " + "; ".join(said) if said else "no estimate"


def score_rows(values: Mapping) -> tuple[dict, list[dict]]:
    """The front page's rows for the words study: the name's congruency effect, its
    equivalence with the image's and the reactivation, each a count of verdicts (``index``'s
    ``score_words_*``) resting on the chapter's tests."""
    scale = (f"{values['replications']} replications × {values['networks']} networks per "
             f"condition ({values['fewest_estimable']} or more with an estimate)")  # fmt: skip
    said, rows = {}, []
    asked = {"congruency": ("A name alone gives the congruency effect", "name alone"),
             "equivalence": ("A name's effect is within a margin of the image's",
                             "name − image")}  # fmt: skip
    for test, (claim, what) in asked.items():
        count = values[f"{test}_count"]
        note = values["equivalence_note"].text if test == "equivalence" else ""
        said[f"score_words_{test}_verdict"] = text.Claim(count.text + note, count.rests_on)
        rows.append({"claim or question": claim,
                     "paper": "proposed as its next step, not run",
                     "this build": _ranges(values, test, what),
                     "verdict": count.text + note, "measured at": scale,
                     "chapter": "words"})  # fmt: skip
    cues = [k.removeprefix("react_").removesuffix("_estimate") for k in values
            if k.startswith("react_") and k.endswith("_estimate")]  # fmt: skip
    word = text.Claim(
        text.by_cue({cue: values[f"react_{cue}_word"].text for cue in cues}),
        tuple(r for cue in cues for r in values[f"react_{cue}_word"].rests_on),
    )
    said["score_words_reactivation_verdict"] = word
    rows.append({"claim or question": "A name's hidden state is nearer its own object's image "
                                      "state than the others'",
                 "paper": "not asked",
                 "this build": "; ".join(
                     f"{text.CLAIM_PARTS[cue]}: {values[f'react_{cue}_estimate']:+.3f}, "
                     f"Holm p {values[f'react_{cue}_p_holm']:.2g}" for cue in cues),
                 "verdict": word.text, "measured at": scale, "chapter": "words"})  # fmt: skip
    return said, rows
