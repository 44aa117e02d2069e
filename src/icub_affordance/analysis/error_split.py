"""An effect on the all-trial RMSE taken apart into what its wrong-grip trials carry and what its
correct trials carry (the front page's closed-loop effects; book/results.md).

In a congruency x size cell with wrong-grip rate w, mean correct-trial RMSE c and mean wrong-trial
RMSE e, the all-trial mean is c + w (e - c): the correct trials' level plus the rate of errors
times what an error costs beyond a correct trial. An effect is a contrast of the cells (congruency:
incongruent - congruent, size: small - large, each over the other factor's two levels), so it is
the same contrast of c (the *correct part*) plus the same contrast of w (e - c) (the *wrong-grip
part*), and the two add up to it exactly. A cell without a wrong trial has no e and carries no
wrong-grip part; a cell without a correct trial has no c, and there the effect cannot be split.

The cells pool every trial of every replication, each network x object once per sequence, as the
all-trial RMSE does; with the same trials in every replication and network, the pooled contrast is
the mean of the networks' contrasts. Description, not a test: it says where an effect comes from.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

#: The two effects as contrasts of the cells: (factor, level counted +, level counted -).
EFFECTS = {"congruency": ("congruent", False, True), "size": ("size", "small", "large")}
#: The cells, in the order of the tables.
CELLS = [(c, s) for c in (True, False) for s in ("large", "small")]


def cells(trials: pd.DataFrame) -> pd.DataFrame:
    """Per congruency x size cell of the categorisation trials: trials, wrong-grip rate, the mean
    RMSE of all, correct and wrong trials, what a wrong grip costs beyond a correct one, and the
    mean distance between the object's two grips (the RMS of the two demonstrations'
    difference)."""
    chosen = trials[trials["task"] == "categorisation"]
    rows = []
    for congruent, size in CELLS:
        cell = chosen[(chosen["congruent"].astype(bool) == congruent) & (chosen["size"] == size)]
        wrong = cell["wrong_grip"].astype(bool)
        correct_rmse = cell.loc[~wrong, "rmse"].mean() if (~wrong).any() else np.nan
        wrong_rmse = cell.loc[wrong, "rmse"].mean() if wrong.any() else np.nan
        rows.append(
            {
                "congruent": congruent,
                "size": size,
                "trials": len(cell),
                "wrong_rate": float(wrong.mean()),
                "rmse": float(cell["rmse"].mean()),
                "rmse_correct": float(correct_rmse),
                "rmse_wrong": float(wrong_rmse),
                "wrong_cost": float(wrong_rmse - correct_rmse),
                "grip_distance": float(cell["grip_distance"].mean()),
            }
        )
    return pd.DataFrame(rows)


def _contrast(table: pd.DataFrame, effect: str, values: pd.Series) -> float:
    """An effect's contrast of per-cell values: the + level's mean minus the - level's."""
    factor, plus, minus = EFFECTS[effect]
    level = table["congruent"] if factor == "congruent" else table["size"]
    return float(values[level == plus].mean() - values[level == minus].mean())


def split(table: pd.DataFrame) -> pd.DataFrame:
    """Per effect: the all-trial RMSE effect, its correct part and its wrong-grip part (which add
    up to it), from ``cells``' table. Undefined parts where a cell has no correct trial."""
    wrong_part = table["wrong_rate"] * table["wrong_cost"].where(table["wrong_rate"] > 0, 0.0)
    rows = []
    for effect in EFFECTS:
        rows.append(
            {
                "effect": effect,
                "rmse": _contrast(table, effect, table["rmse"]),
                "correct_part": _contrast(table, effect, table["rmse_correct"]),
                "wrong_part": _contrast(table, effect, wrong_part),
            }
        )
    out = pd.DataFrame(rows)
    unsplit = table["rmse_correct"].isna().any()
    out.loc[:, ["correct_part", "wrong_part"]] = (
        np.nan if unsplit else out[["correct_part", "wrong_part"]]
    )
    return out
