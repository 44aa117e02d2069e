"""Outputs are written atomically: a failure leaves the old file intact and no debris."""

from __future__ import annotations

import pytest

from icub_affordance.files import atomic_path, write_csv, write_text


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


def test_columns_are_written_as_rows_would_be(tmp_path):
    """write_columns (the learning curves' fast path) gives write_csv's bytes: floats to 6
    places, NaN empty, text quoted by the csv module where it must be."""
    import math

    import numpy as np

    from icub_affordance.files import write_columns

    rng = np.random.default_rng(0)
    columns = {
        "iteration": list(range(1, 301)),
        "task": ["grasping", "categorisation", "a,b"] * 100,
        "rmse": rng.random(300).tolist(),
    }
    columns["rmse"][3] = math.nan
    columns["rmse"][4] = 2.5e-7
    columns["iteration"][5] = None
    plain = {  # each column of one plain type: written a column at once
        "iteration": list(range(1, 301)),
        "task": ["grasping", "categorisation"] * 150,
        "rmse": rng.random(300).tolist(),
        "held": [True, False, True] * 100,
    }
    for table in (columns, {k: v for k, v in columns.items() if k != "task"}, plain):
        rows = [dict(zip(table, row, strict=True)) for row in zip(*table.values(), strict=True)]
        write_csv(tmp_path / "rows.csv", rows)
        write_columns(tmp_path / "columns.csv", table)
        assert (tmp_path / "columns.csv").read_bytes() == (tmp_path / "rows.csv").read_bytes()


def test_tables_are_written_whole_without_their_index(tmp_path):
    import pandas as pd

    from icub_affordance.files import write_tables

    frame = pd.DataFrame({"a": [1, 2], "b": [0.5, float("nan")]})
    write_tables([(tmp_path / "t.csv", frame)])
    assert (tmp_path / "t.csv").read_text() == frame.to_csv(index=False)
    assert [p.name for p in tmp_path.iterdir()] == ["t.csv"]  # no temporary left behind
