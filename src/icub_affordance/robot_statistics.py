"""The robot chapter's statistics that the variants' table and effects do not hold.

From the joined robot trials (``data/embodied/trials.csv``), the body's tolerance trials
(``data/embodied/tolerance.csv``) and the demonstrations' replays (``data/embodied/replay.csv``):
the share held and the median palm error per arm noise, the share held per bin of palm error
(the tolerance trials, the replayed demonstrations and each variant's grasping trials), the
replayed demonstrations' palm error, and the exact McNemar tests of the variants that differ in
the learning-rate schedule alone. The rule ``robot_statistics`` writes them once per build to
``data/embodied/statistics.json``; the book only formats them.

Every count is over distinct trials: a network's grasping trial of an object is one physical
trial, however many test sequences share it.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .embodied_stats import held_by_palm_error, tolerance_table
from .stats import mcnemar_exact
from .variants import NetworkVariant


def _plain(value):
    """``value`` with numpy scalars as Python's (for JSON)."""
    if isinstance(value, dict):
        return {key: _plain(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [_plain(item) for item in value]
    if isinstance(value, np.generic):
        return value.item()
    return value


def table_record(table: pd.DataFrame) -> dict[str, list]:
    """A table as {column: values}, in its column order, with Python's numbers (for JSON)."""
    return {column: _plain(table[column].tolist()) for column in table.columns}


def record_table(record: dict[str, list]) -> pd.DataFrame:
    """The table of ``table_record``."""
    return pd.DataFrame(record)


def grasping_trials(trials: pd.DataFrame, keys=("run",)) -> pd.DataFrame:
    """The distinct grasping trials of ``trials``: one per variant (``keys``), network and
    object (a network's test sequences of one object are one physical trial)."""
    return trials[trials["task"] == "grasping"].drop_duplicates([*keys, "network", "object"])


def paired_grasping(trials: pd.DataFrame, column: str, keys: tuple[str, ...]) -> list[dict]:
    """Robot variants that differ in ``column`` alone, compared on the same networks.

    ``trials``: ``data/embodied/trials.csv``; ``keys``: the columns that tell variants apart
    (``variants.NetworkVariant.keys()``). Variants of one group share everything but
    ``column``, so network k of each starts from the same initial weights and sees the same
    presentations: its grasping trial of an object (one physical trial, however many test
    sequences share it) pairs with the other variant's. Per pair of values: the distinct trials,
    how many each holds, the discordant pairs, and the exact McNemar test
    (``stats.mcnemar_exact``).
    """
    grasping = grasping_trials(trials, keys)
    others = [k for k in keys if k != column]
    out = []
    for group, mine in grasping.groupby(others, sort=True):
        values = sorted(mine[column].unique())
        held = mine.pivot_table(
            index=["network", "object"], columns=column, values="success", aggfunc="first"
        ).dropna()
        for i, a in enumerate(values):
            for b in values[i + 1 :]:
                ya, yb = held[a].astype(bool), held[b].astype(bool)
                only_a, only_b = int((ya & ~yb).sum()), int((yb & ~ya).sum())
                out.append(
                    dict(zip(others, group, strict=True))
                    | {
                        "a": a, "b": b, "trials": len(held),
                        "held_a": int(ya.sum()), "held_b": int(yb.sum()),
                        "only_a": only_a, "only_b": only_b,
                        "p": mcnemar_exact(only_a, only_b),
                    }
                )  # fmt: skip
    return out


def replay_palm(replay: pd.DataFrame) -> dict[str, float | int]:
    """The demonstrations replayed through the controller (``plan`` commands): how far their
    palm ends from the demonstrator's mean (median and largest, mm), the share that held the
    object, and the replays."""
    demos = replay[replay["plan"] == "commands"]
    return {
        "palm_error_mm_median": float(demos["palm_error_mm"].median()),
        "palm_error_mm_max": float(demos["palm_error_mm"].max()),
        "held": float(demos["success"].astype(bool).mean()),
        "trials": len(demos),
    }


def robot_statistics(
    trials: pd.DataFrame, tolerance: pd.DataFrame, replay: pd.DataFrame
) -> dict[str, object]:
    """Every statistic of this module, for JSON (``data/embodied/statistics.json``):

    - ``tolerance``: ``embodied_stats.tolerance_table`` of the tolerance trials (``table_record``);
    - ``held_by_palm_error``: ``embodied_stats.held_by_palm_error`` of the tolerance trials
      (``tolerance``), the replayed demonstrations (``replay``) and each variant's distinct
      grasping trials (``runs``, by run);
    - ``replay``: ``replay_palm``;
    - ``schedule_pairs``: ``paired_grasping`` over the learning-rate schedule.
    """
    grasping = grasping_trials(trials)
    return {
        "tolerance": table_record(tolerance_table(tolerance)),
        "held_by_palm_error": {
            "tolerance": table_record(held_by_palm_error(tolerance)),
            "replay": table_record(held_by_palm_error(replay[replay["plan"] == "commands"])),
            "runs": {
                run: table_record(held_by_palm_error(grasping[grasping["run"] == run]))
                for run in sorted(grasping["run"].unique())
            },
        },
        "replay": replay_palm(replay),
        "schedule_pairs": _plain(
            paired_grasping(trials, "learning_rate_schedule", NetworkVariant.keys())
        ),
    }
