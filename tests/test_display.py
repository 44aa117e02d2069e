"""The pages' one display helper (``icub_workflow.book.display``): every page lays out its tables
and writes its p values with it, and none defines its own."""

from __future__ import annotations

import ast

import numpy as np
import pandas as pd
import pytest
from conftest import REPO

from icub_workflow.book import display
from icub_workflow.code_deps import page_code

PAGES = sorted((REPO / "book").glob("*.md"))


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.stem)
def test_no_page_defines_its_own_table_or_p_value(page):
    code = page_code(page)
    defined = {n.name for n in ast.walk(ast.parse(code)) if isinstance(n, ast.FunctionDef)}
    assert not defined & {"table", "p", "p_values", "estimates", "counts"}
    assert ".style" not in code and "set_uuid" not in code, "lay it out with display.table"


def test_a_table_formats_each_column_and_blanks_what_reads_nan():
    frame = pd.DataFrame({"a": [0.12345, np.nan], "b": ["x", "y"]})
    shown = display.formatted(frame, {"A": "{a:.2f}", "B": "b", "both": "{b} {a:.1f}"})
    assert shown.to_dict("list") == {"A": ["0.12", ""], "B": ["x", "y"], "both": ["x 0.1", ""]}
    html = display.table(
        frame, "t1", {"A": "{a:.2f}"}, cells="padding: 1px", size="0.8em"
    ).to_html()
    assert 'id="T_t1"' in html and "padding: 1px" in html and "font-size: 0.8em" in html
    assert "<th" in html and "0.12" in html


def test_a_tables_options_reach_its_cells():
    frame = pd.DataFrame({"test": ["size"], "p": ["0.01"], "cell": ["+0.1 reproduced"]})
    html = display.table(frame, "t2", nowrap_but=("test",), breaks=slice(2, None)).to_html()
    assert "+0.1<br>reproduced" in html and "white-space: nowrap" in html
    assert display.table(frame.iloc[:0], "t3", empty="*None.*").data == "*None.*"
    styled = display.table(pd.DataFrame({"x": [np.nan]}), "t4", formats={}, na_rep="–")
    assert "–" in styled.to_html()


def test_p_values_estimates_and_counts_read_as_the_tables_show_them():
    assert display.p_values(pd.Series([0.01234, np.nan])).tolist() == ["0.012", "–"]
    assert display.counts(pd.Series([9.0, np.nan])).tolist() == ["9", "–"]
    frame = pd.DataFrame({"estimate": [0.5, np.nan], "ci_low": [0.25, np.nan],
                          "ci_high": [0.75, np.nan]})  # fmt: skip
    estimate, ci = display.estimates(frame)
    assert estimate.tolist() == ["+0.5000", "–"]
    assert ci.tolist() == ["[+0.2500, +0.7500]", "–"]
