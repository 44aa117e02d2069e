"""The book pages' one display helper: how a table is laid out and how its p values, estimates,
intervals and counts read, so that every page shows them the same way. The pages import it; the
words in the cells come from the build (``findings.json`` and ``data/book/tables``)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

#: A cell with nothing to show (no test, no estimate).
DASH = "–"


def p_values(values: pd.Series) -> pd.Series:
    """p values as the tables show them: two significant digits; a dash where there is none."""
    return values.map(lambda v: f"{v:.2g}" if np.isfinite(v) else DASH)


def counts(values: pd.Series) -> pd.Series:
    """Whole numbers (degrees of freedom, networks) as text; a dash where there is none."""
    return values.map(lambda v: f"{v:.0f}" if np.isfinite(v) else DASH)


def estimates(frame: pd.DataFrame) -> tuple[pd.Series, pd.Series]:
    """A test's estimate and its 95% interval (``estimate``, ``ci_low``, ``ci_high``) as text,
    signed to four decimals; a dash where none could be made."""
    n = frame[["estimate", "ci_low", "ci_high"]].astype(float)
    n = n.map("{:+.4f}".format).where(np.isfinite(n), DASH)
    ci = ("[" + n["ci_low"] + ", " + n["ci_high"] + "]").where(n["ci_low"] != DASH, DASH)
    return n["estimate"], ci


def formatted(frame: pd.DataFrame, columns: Mapping[str, str]) -> pd.DataFrame:
    """``frame`` for reading: each column a format string over a row's fields, or a column's
    name; a cell that reads NaN is blank."""
    rows = [{k: f.format_map(r) if "{" in f else str(r[f]) for k, f in columns.items()}
            for r in frame.to_dict("records")]  # fmt: skip
    return pd.DataFrame(rows, columns=list(columns)).replace(r"^.*\bnan\b.*$", "", regex=True)


def table(
    frame: pd.DataFrame,
    uuid: str,
    columns: Mapping[str, str] | None = None,
    *,
    cells: str | None = None,
    size: str | None = None,
    caption_left: bool = False,
    nowrap_but: Sequence[str] | None = None,
    wrap: Sequence[str] = (),
    breaks: slice | None = None,
    formats: Mapping | None = None,
    na_rep: str | None = None,
    precision: int | None = None,
    index: bool = False,
    empty: str | None = None,
):
    """A page's table: ``frame`` (``formatted`` by ``columns`` where given) under the id
    ``uuid``, its index shown only with ``index``; ``cells``: the cells' CSS (padding); ``size``:
    the table's font size; ``caption_left``: its caption to the left; ``nowrap_but``: every
    column but these kept on one line; ``wrap``: columns let wrap; ``breaks``: the columns (a
    slice) whose first space breaks the line (a verdict under its estimate); ``formats``,
    ``na_rep`` and ``precision``: the cells' formats. An empty frame reads ``empty`` where given
    (Markdown)."""
    if empty is not None and frame.empty:
        from IPython.display import Markdown

        return Markdown(empty)
    shown = frame if columns is None else formatted(frame, columns)
    style = shown.style.set_uuid(uuid)
    style = style if index else style.hide(axis="index")
    styles = [{"selector": "td, th", "props": cells}] if cells else []
    styles += [{"selector": "caption", "props": "text-align: left"}] if caption_left else []
    styles += [{"selector": "", "props": f"font-size: {size}"}] if size else []
    if styles:
        style = style.set_table_styles(styles)
    if nowrap_but is not None:
        whole = [c for c in shown.columns if c not in nowrap_but]
        style = style.set_properties(subset=whole, **{"white-space": "nowrap"})
    if wrap:
        style = style.set_properties(subset=list(wrap), **{"white-space": "normal"})
    if breaks is not None:
        style = style.format(lambda v: v.replace(" ", "<br>", 1), subset=shown.columns[breaks])
    if formats is not None or na_rep is not None or precision is not None:
        style = style.format(formats or {}, na_rep=na_rep, precision=precision)
    return style
