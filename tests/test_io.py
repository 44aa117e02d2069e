"""Outputs are written atomically: a failure leaves the old file intact and no debris."""

from __future__ import annotations

import pytest

from icub_affordance.io import atomic_path, write_text


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
