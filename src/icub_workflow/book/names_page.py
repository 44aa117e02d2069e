"""The chapter "Words" (config ``words``): the declared family's values and verdicts, the
reactivation's, the table of the tests, and the front page's scorecard rows."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from . import text, words

#: What each declared test asks, in the tables.
QUESTIONS = {
    "congruency": "The name alone: congruent lower (incongruent − congruent)",
    "equivalence": "The name's congruency effect as the image's (within the margin)",
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


def words_page(inputs: Mapping[str, str], config: dict) -> tuple[dict, dict[str, pd.DataFrame]]:
    """The chapter's values (each test's numbers and ``text.Claim`` verdict, per kind of test
    the count of verdicts over its conditions, the reactivation per cue timing) and its table,
    a row per declared test."""
    summary = pd.read_csv(inputs["words_summary.csv"], keep_default_na=False, na_values=[""])
    reactivation = pd.read_csv(inputs["words_reactivation.csv"])
    declaration = config["words"]
    values: dict = {
        "replications": int(summary["replications"].max()),
        "networks": int(config["network"]["networks"]),
        "family_size": int(summary["family_size"].iloc[0]),
        "alpha": float(declaration["alpha"]),
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
        values[f"{key}_verdict"] = text.Claim(
            word, (f"words.{key}_estimate", f"words.{key}_p_holm")
        )
        interval = "–"
        if np.isfinite(row["estimate"]):
            interval = f"{row['estimate']:+.4f}" + (
                f" [{row['ci_low']:+.4f}, {row['ci_high']:+.4f}]"
                if np.isfinite(row["ci_low"])
                else " (no test)"
            )
        rows.append({
            "question": QUESTIONS[row["test"]], "measure": text.CLAIM_PARTS[row["measure"]]
            if row["measure"] in text.CLAIM_PARTS else row["measure"].replace("_", " "),
            "cue": text.CLAIM_PARTS[row["cue"]], "test": text.CLAIM_PARTS[row["mode"]],
            "estimate [95% interval]": interval,
            "margin": "–" if not np.isfinite(row["margin"]) else f"±{row['margin']:g}",
            "replications with an estimate": f"{int(row['estimable'])} of "
                                             f"{int(row['replications'])}",
            "Holm p": row["p_holm"], "verdict": word,
        })  # fmt: skip
    for test, group in summary.groupby("test", sort=False):
        said = [ORDER[test][d] for d in group["direction"]]
        rests = tuple(f"words.{word_key(r)}_p_holm" for _, r in group.iterrows())
        values[f"{test}_count"] = text.Claim(_count(said, ORDER[test]), rests)
    for _, row in reactivation.iterrows():
        key = f"react_{row['cue']}"
        values |= {f"{key}_{k}": float(row[k]) for k in ("estimate", "ci_low", "ci_high", "p",
                                                         "p_holm")}  # fmt: skip
        word = words.REACTIVATION_WORDS[row["direction"]]
        values[f"{key}_verdict"] = text.Claim(word, (f"words.{key}_estimate",
                                                     f"words.{key}_p_holm"))  # fmt: skip
    verdicts = {k.removeprefix("react_").removesuffix("_verdict"): v for k, v in values.items()
                if k.startswith("react_") and k.endswith("_verdict")}  # fmt: skip
    values["react_verdict"] = text.Claim(
        text.by_cue({cue: v.text for cue, v in verdicts.items()}),
        tuple(r for v in verdicts.values() for r in v.rests_on),
    )
    return values, {"words": pd.DataFrame(rows)}


def score_rows(values: Mapping) -> tuple[dict, list[dict]]:
    """The front page's rows for the words study: the name's congruency effect, its
    equivalence with the image's and the reactivation, each a count of verdicts (``index``'s
    ``score_words_*``) resting on the chapter's tests."""
    scale = f"{values['replications']} replications × {values['networks']} networks per condition"
    said, rows = {}, []
    asked = {"congruency": "A name alone gives the congruency effect",
             "equivalence": "A name's effect equals the image's (within the margin)"}  # fmt: skip
    for test, claim in asked.items():
        count = values[f"{test}_count"]
        said[f"score_words_{test}_verdict"] = text.Claim(count.text, count.rests_on)
        keys = [k for k in values if k.startswith("w_") and k.endswith(f"_{test}_estimate")]
        found = [float(values[k]) for k in keys if np.isfinite(values[k])]
        what = "name − image" if test == "equivalence" else "name alone"
        numbers = (f"{what}: {min(found):+.4f} to {max(found):+.4f} over the {len(found)} "
                   "conditions with an estimate" if found else "no estimate")  # fmt: skip
        rows.append({"claim or question": claim,
                     "paper": "proposed as its next step, not run",
                     "this build": numbers,
                     "verdict": count.text, "measured at": scale, "chapter": "words"})  # fmt: skip
    cues = [k.removeprefix("react_").removesuffix("_estimate") for k in values
            if k.startswith("react_") and k.endswith("_estimate")]  # fmt: skip
    word = values["react_verdict"]
    said["score_words_reactivation_verdict"] = text.Claim(word.text, word.rests_on)
    rows.append({"claim or question": "A name's hidden state is nearest its own object's image's",
                 "paper": "not asked",
                 "this build": "; ".join(
                     f"{text.CLAIM_PARTS[cue]}: {values[f'react_{cue}_estimate']:+.3f}, "
                     f"Holm p {values[f'react_{cue}_p_holm']:.2g}" for cue in cues),
                 "verdict": word.text, "measured at": scale, "chapter": "words"})  # fmt: skip
    return said, rows
