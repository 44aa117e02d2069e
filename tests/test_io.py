"""Outputs are written atomically: a failure leaves the old file intact and no debris."""

from __future__ import annotations

import pytest

from icub_affordance.io import atomic_path, write_csv, write_text


def test_failed_write_keeps_the_previous_file(tmp_path):
    target = tmp_path / "out.csv"
    write_text(target, "old\n")
    with pytest.raises(RuntimeError), atomic_path(target) as tmp:
        tmp.write_text("half")
        raise RuntimeError("killed")
    assert target.read_text() == "old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["out.csv"]


def test_successful_write_replaces_the_file(tmp_path):
    target = tmp_path / "sub" / "out.txt"
    write_text(target, "a")
    write_text(target, "b")
    assert target.read_text() == "b"


def test_csv_without_pandas_is_what_pandas_writes(tmp_path):
    """The robot and training jobs skip pandas to start faster; their tables must not change."""
    import pandas as pd

    rows = [
        {"network": 0, "task": "grasping", "congruent": "", "held": True, "rmse": 0.1234567,
         "lift_m": float("nan"), "step": 3},
        {"network": 11, "task": "categorisation", "congruent": "False", "held": False,
         "rmse": 1e-7, "lift_m": -0.0001, "step": 9},
    ]  # fmt: skip
    write_csv(tmp_path / "mine.csv", rows)
    pd.DataFrame(rows).to_csv(tmp_path / "pandas.csv", index=False, float_format="%.6f")
    assert (tmp_path / "mine.csv").read_text() == (tmp_path / "pandas.csv").read_text()
