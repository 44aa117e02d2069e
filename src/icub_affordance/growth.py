"""How a cost grows with the size of the work: the cost of each added unit between measured
sizes, and the least-squares line through the measurements (the sweep's wall time against its
replications, ``data/benchmarks/sweep_cost.csv``)."""

from __future__ import annotations

import numpy as np


def line_fit(x, y) -> dict[str, object]:
    """The least-squares line ``y = intercept + slope * x`` (``np.polyfit``, degree 1), and how
    far each point lies from it relative to its own ``y`` (``relative_offsets``)."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    slope, intercept = np.polyfit(x, y, 1)
    return {
        "slope": slope,
        "intercept": intercept,
        "relative_offsets": np.abs(y - (intercept + slope * x)) / y,
    }


def cost_growth(sizes, seconds) -> dict[str, object]:
    """``seconds`` measured at each of ``sizes``, sorted by size: the ``sizes`` and ``seconds``
    in that order, the ``marginal`` cost of a unit between consecutive sizes, its relative
    ``change`` from the first to the last (NaN with fewer than two), and the ``line`` through
    the measurements (``line_fit``; None with fewer than three: two always lie on a line), with
    the point furthest from it (``furthest_offset``, ``furthest_size``)."""
    order = np.argsort(np.asarray(sizes, dtype=float), kind="stable")
    n = np.asarray(sizes, dtype=float)[order]
    s = np.asarray(seconds, dtype=float)[order]
    marginal = np.diff(s) / np.diff(n)
    out: dict[str, object] = {
        "sizes": n,
        "seconds": s,
        "marginal": marginal,
        "change": marginal[-1] / marginal[0] - 1 if len(marginal) else float("nan"),
        "line": None,
    }
    if len(n) >= 3:
        line = line_fit(n, s)
        off = line["relative_offsets"]
        out["line"] = line | {"furthest_offset": off.max(), "furthest_size": n[off.argmax()]}
    return out
