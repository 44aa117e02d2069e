"""The DAG drawn for the book's reproduction page: the rules of ``data/book/rulegraph.dot`` (rule
``rulegraph``) top to bottom, each arrow a direct need, laid out the same on every build."""

from __future__ import annotations

import os
import re

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import networkx as nx  # noqa: E402

from icub_affordance.figures import COLUMN_IN, save  # noqa: E402


def rule_graph(dot: str) -> nx.DiGraph:
    """The rules and their direct needs: the graph of ``dot`` (Snakemake's rule graph) without
    the needs that a longer path implies, nodes and edges in a fixed order."""
    labels = dict(re.findall(r'^\s*(\d+)\[label = "([^"]+)"', dot, flags=re.M))
    graph = nx.DiGraph()
    graph.add_nodes_from(labels.values())
    for a, b in re.findall(r"^\s*(\d+) -> (\d+)", dot, flags=re.M):
        graph.add_edge(labels[a], labels[b])
    reduced = nx.transitive_reduction(graph)  # draw only the direct needs, for legibility
    graph = nx.DiGraph()  # nodes and edges in a fixed order: the same picture on every build
    graph.add_nodes_from(sorted(reduced.nodes))
    graph.add_edges_from(sorted(reduced.edges))
    return graph


def layers(graph: nx.DiGraph, sweeps: int = 3) -> list[list[str]]:
    """The rules in columns (topological generations), each column ordered by where its rules'
    neighbours sit (``sweeps`` sweeps each way): fewer crossings, the same order on every build."""
    columns = [sorted(nodes) for nodes in nx.topological_generations(graph)]
    for _ in range(sweeps):
        for order, neighbours in (
            (range(1, len(columns)), graph.predecessors),
            (range(len(columns) - 2, -1, -1), graph.successors),
        ):
            for i in order:
                rank = {n: k for column in columns for k, n in enumerate(column)}

                def centre(node, rank=rank, neighbours=neighbours):
                    near = [rank[m] for m in neighbours(node)]
                    return (sum(near) / len(near) if near else rank[node], node)

                columns[i] = sorted(columns[i], key=centre)
    return columns


def placed(
    columns: list[list[str]],
    box: dict[str, float],
    width: float,
    row: float = 0.45,
    gap: float = 0.12,
) -> tuple[dict[str, tuple[float, float]], tuple[float, float]]:
    """Each rule's box centre (inches) and the drawing's size: the layers (``columns``) top to
    bottom, each in lines of boxes (``box``: a rule's box width) ``gap`` apart, a line wrapping
    before it would be wider than ``width``, each line centred and ``row`` below the last, so
    that no two boxes overlap and the drawing fits a page's text column."""
    lines: list[list[str]] = []
    for column in columns:
        line: list[str] = []
        for name in column:
            if line and sum(box[n] + gap for n in line) + box[name] > width:
                lines.append(line)
                line = []
            line.append(name)
        lines.append(line)
    size = (width + 0.1, len(lines) * row + 0.1)
    centre = {}
    for k, line in enumerate(lines):
        left = 0.05 + (width - sum(box[n] for n in line) - gap * (len(line) - 1)) / 2
        for name in line:
            centre[name] = (left + box[name] / 2, size[1] - 0.05 - row / 2 - k * row)
            left += box[name] + gap
    return centre, size


def draw_rulegraph(dot: str, path: str | os.PathLike[str]) -> None:
    """The rule graph ``dot``, drawn top to bottom to ``path`` (PNG), as wide as the book's text
    column so that its names read at the page's width: one box per rule, none overlapping
    another (``placed``), and each arrow from the bottom of a rule's box to the top of the box
    of the rule that needs it."""
    graph = rule_graph(dot)
    columns = layers(graph)
    font = 8.5  # points
    fig = plt.figure(figsize=(1, 1))
    renderer = fig.canvas.get_renderer()
    probe = fig.text(0, 0, "", fontsize=font)
    box = {}  # each box's width in inches, its padding included, as the name is drawn
    for name in graph.nodes:
        probe.set_text(name)
        box[name] = probe.get_window_extent(renderer).width / fig.dpi + 0.12
    probe.remove()
    centre, size = placed(columns, box, COLUMN_IN)
    fig.set_size_inches(*size)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, size[0])
    ax.set_ylim(0, size[1])
    ax.axis("off")
    half = 0.11  # half a box's height, inches
    for a, b in graph.edges:
        (xa, ya), (xb, yb) = centre[a], centre[b]
        ax.annotate(
            "", xy=(xb, yb + half), xytext=(xa, ya - half),
            arrowprops=dict(arrowstyle="-|>", color="0.6", lw=0.6, shrinkA=0, shrinkB=0,
                            mutation_scale=7),
        )  # fmt: skip
    for name, (x, y) in centre.items():
        ax.text(
            x, y, name, fontsize=font, ha="center", va="center",
            bbox=dict(boxstyle="round,pad=0.25", fc="#e8f0f8", ec="0.5", lw=0.6),
        )  # fmt: skip
    save(fig, path)
