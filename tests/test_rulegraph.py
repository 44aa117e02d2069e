"""The DAG drawing: the same bytes on every run, and the run's own config."""

from __future__ import annotations

import os
import random
import re
import subprocess
import sys

import pytest
from conftest import TEST_CONFIG, scratch_workflow

from icub_workflow.dot import canonical_dot

DOT = """digraph snakemake_dag {
    graph[bgcolor=white, margin=0];
\t0[label = "all", color = "0.00 0.6 0.85", style="rounded"];
\t1[label = "train", color = "0.63 0.6 0.85", style="rounded"];
\t2[label = "book", color = "0.04 0.6 0.85", style="rounded"];
\t1 -> 0
\t2 -> 0
\t1 -> 2
}            
"""  # noqa: W291 (Snakemake's own trailing blanks)


def test_the_same_graph_in_another_order_gives_the_same_bytes():
    lines = DOT.splitlines()
    number = {"0": "7", "1": "3", "2": "5"}  # the same rules under other numbers
    renumbered = [re.sub(r"^\t(\d+)\[", lambda m: f"\t{number[m[1]]}[", n) for n in lines[2:5]]
    moved = [re.sub(r"\d+", lambda m: number[m[0]], e) for e in lines[5:8]]
    random.Random(1).shuffle(renumbered)
    random.Random(2).shuffle(moved)
    other = "\n".join([*lines[:2], *renumbered, *moved, "}"])
    assert canonical_dot(other) == canonical_dot(DOT)
    assert canonical_dot(canonical_dot(DOT)) == canonical_dot(DOT)
    assert '\t0[label = "all"' in canonical_dot(DOT) and "\t2 -> 1" in canonical_dot(DOT)


def test_the_drawing_shows_the_direct_needs_in_columns(tmp_path):
    """The DAG drawn by rule ``rulegraph_figure``: the needs a longer path implies are left out,
    the rules sit in columns by their needs, and the same graph gives the same PNG."""
    from icub_workflow.rulegraph_figure import draw_rulegraph, layers, rule_graph

    graph = rule_graph(canonical_dot(DOT))
    assert sorted(graph.edges) == [("book", "all"), ("train", "book")]  # not train -> all
    assert layers(graph) == [["train"], ["book"], ["all"]]
    paths = [tmp_path / "a.png", tmp_path / "b.png"]
    for path in paths:
        draw_rulegraph(DOT, path)
    assert paths[0].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert paths[0].read_bytes() == paths[1].read_bytes()


def test_no_two_boxes_of_the_drawing_overlap():
    """Layers of boxes of different widths, top to bottom: a layer wider than the drawing wraps,
    boxes of a line ``gap`` apart, lines a row apart, every box inside the drawing."""
    from icub_workflow.rulegraph_figure import placed

    columns = [["a", "bb"], ["ccc", "d", "e"], ["f"]]
    box = {"a": 0.5, "bb": 1.2, "ccc": 2.0, "d": 0.4, "e": 0.9, "f": 0.7}
    centre, (width, height) = placed(columns, box, width=3.0, row=0.3, gap=0.2)
    names = list(box)
    for i, m in enumerate(names):
        for n in names[i + 1 :]:
            (xm, ym), (xn, yn) = centre[m], centre[n]
            apart_x = abs(xm - xn) >= (box[m] + box[n]) / 2 + 0.2 - 1e-9
            apart_y = abs(ym - yn) >= 0.3 - 1e-9
            assert apart_x or apart_y, (m, n)
    for name, (x, y) in centre.items():
        assert 0 < x - box[name] / 2 and x + box[name] / 2 < width, name
        assert 0 < y - 0.15 and y + 0.15 < height, name
    # "ccc", "d" fill a line of 3.0 in, "e" wraps below them; "f" is the last layer's line
    assert centre["ccc"][1] == centre["d"][1] > centre["e"][1] > centre["f"][1]
    assert centre["a"][1] > centre["ccc"][1] and width == 3.1


def test_a_text_that_is_no_rule_graph_is_refused():
    with pytest.raises(ValueError, match="no rules"):
        canonical_dot("Building DAG of jobs...\n")


@pytest.mark.reruns
def test_the_drawing_is_byte_identical_across_runs_and_follows_the_config(tmp_path):
    workdir = scratch_workflow(tmp_path / "w")
    out = workdir / "data/book/rulegraph.dot"

    def draw(*args, seed):
        env = os.environ | {"PYTHONHASHSEED": str(seed)}
        cmd = [sys.executable, "-m", "snakemake", "-c1", str(out.relative_to(workdir))]
        cmd += ["--forcerun", "rulegraph", *args, "--configfile", str(TEST_CONFIG)]
        result = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, env=env)
        assert result.returncode == 0, result.stderr[-3000:]
        return out.read_bytes()

    first, second = draw(seed=1), draw(seed=2)
    assert first == second
    assert b"sweep_summary" not in first
    assert b"sweep_summary" in draw("--config", "robustness=True", seed=3)
