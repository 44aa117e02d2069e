"""Readings of the paper over replications (MODEL.md sections 5, 7, 8): per run, every measure's
contrasts and per-object means; across a reading's replications, each effect's mean difference
with a 95% interval, and how many replications show it significantly in the paper's direction and
how many significantly reversed.

An effect's difference is the contrasts' estimate with the factor coded -0.5 / +0.5
(``stats.CODING``): incongruent minus congruent, small minus large, averaged over the other
factors; for every measure higher is slower, so a positive difference is the paper's direction.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .findings import ALPHA
from .spec import MODES
from .stats import categorisation_trials, cell_means, mean_ci, network_contrasts, object_means

#: The effects the paper reports, the per-network contrasts' test's terms of the same name.
EFFECTS: tuple[str, ...] = ("congruency", "size")

#: The columns of data/readings/summary.csv (a contract).
SUMMARY_COLUMNS = [
    "reading",
    "cue",
    "goal_response",
    "measure",
    "effect",
    "replications",
    "diff",
    "ci_low",
    "ci_high",
    "n_paper",
    "n_reversed",
]


def analyse_measures(trials: pd.DataFrame, measures: list[str]) -> dict[str, dict]:
    """Per test mode and measure: the contrasts, the cell means and the per-object means of the
    categorisation trials (``measures.csv``'s rows)."""
    out: dict[str, dict] = {}
    for mode in MODES:
        df = categorisation_trials(trials, mode)
        out[mode] = {
            measure: {
                "contrasts": network_contrasts(df, measure),
                "means": cell_means(df, measure),
                "object_means": object_means(df, measure),
            }
            for measure in measures
        }
    return out


def replication_rows(
    table: list[dict], analyses: list[dict], measures: list[str], mode: str = "closed_loop"
) -> pd.DataFrame:
    """One row per reading, replication, measure and effect: the contrasts' estimate, its
    interval and p. ``table`` holds the readings' rows (reading, cue, goal_response, seed, run),
    ``analyses`` each row's ``analyse_measures`` result."""
    rows = []
    for row, analysis in zip(table, analyses, strict=True):
        for measure in measures:
            for effect in EFFECTS:
                term = analysis[mode][measure]["contrasts"][effect]
                rows.append(dict(row) | {"measure": measure, "effect": effect} | term)
    return pd.DataFrame(rows)


def summary(replications: pd.DataFrame) -> pd.DataFrame:
    """One row per reading, measure and effect (``SUMMARY_COLUMNS``). ``diff`` is the mean over
    replications of the contrasts' estimate; its interval a t-interval over replications, or,
    with a single replication, that replication's own 95% interval. ``n_paper`` and
    ``n_reversed`` count the replications with p < ALPHA in and against the paper's direction."""
    rows = []
    keys = ["reading", "cue", "goal_response", "measure", "effect"]
    for key, group in replications.groupby(keys, sort=False):
        estimates = group["estimate"].to_numpy()
        significant = group["p"].to_numpy() < ALPHA
        if len(group) > 1:
            diff, low, high = mean_ci(estimates)
        else:
            diff, low, high = (float(group[c].iloc[0]) for c in ("estimate", "ci_low", "ci_high"))
        rows.append(
            dict(zip(keys, key, strict=True))
            | {
                "replications": len(group),
                "diff": diff,
                "ci_low": low,
                "ci_high": high,
                "n_paper": int((significant & (estimates > 0)).sum()),
                "n_reversed": int((significant & (estimates < 0)).sum()),
            }
        )
    return pd.DataFrame(rows, columns=SUMMARY_COLUMNS)


def direction(row) -> str:
    """A summary row's effect: "paper" or "reversed" when its interval excludes 0 on that side,
    "none" when it includes 0, "constant" when the measure did not vary at all (a difference of
    exactly 0 with a zero-width interval)."""
    if row["diff"] == row["ci_low"] == row["ci_high"] == 0:
        return "constant"
    if row["ci_low"] > 0:
        return "paper"
    if row["ci_high"] < 0:
        return "reversed"
    return "none"


def matrix(summary_table: pd.DataFrame) -> pd.DataFrame:
    """Readings x measures, both effects in every cell: the difference, its interval and the
    replications significant each way, as text (the book's matrix)."""

    def cell(row) -> str:
        if direction(row) == "constant":
            return "0 (every network scored the same on every object)"
        counts = f"; {row['n_paper']}/{row['replications']} paper, {row['n_reversed']} reversed"
        return (
            f"{row['diff']:+.3g} [{row['ci_low']:+.3g}, {row['ci_high']:+.3g}]"
            f"{counts if row['replications'] > 1 else ''} ({direction(row)})"
        )

    out = summary_table.assign(text=summary_table.apply(cell, axis=1))
    wide = out.pivot_table(
        index=["reading", "effect"], columns="measure", values="text", aggfunc="first", sort=False
    )
    return wide.reset_index()


def finite(values) -> bool:
    return bool(np.all(np.isfinite(np.asarray(values, dtype=float))))
