"""The DAG drawn for the book's reproduction page: the rules of ``data/book/rulegraph.dot`` (rule
``rulegraph``) left to right, each arrow a direct need, laid out the same on every build."""

from __future__ import annotations

import os
import re

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import networkx as nx  # noqa: E402

from icub_affordance.figures import save  # noqa: E402


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
    columns: list[list[str]], box: dict[str, float], row: float = 0.27, gap: float = 0.32
) -> tuple[dict[str, tuple[float, float]], tuple[float, float]]:
    """Each rule's box centre (inches) and the drawing's size: the columns left to right, each
    as wide as its widest box (``box``: a rule's box width) and ``gap`` apart, each column's
    rules ``row`` apart and centred on the middle, so that no two boxes overlap."""
    widths = [max(box[name] for name in column) for column in columns]
    size = (sum(widths) + gap * (len(columns) - 1) + 0.1, max(map(len, columns)) * row + 0.1)
    centre, left = {}, 0.05
    for column, width in zip(columns, widths, strict=True):
        top = size[1] / 2 + (len(column) - 1) * row / 2
        for k, name in enumerate(column):
            centre[name] = (left + width / 2, top - k * row)
        left += width + gap
    return centre, size


def draw_rulegraph(dot: str, path: str | os.PathLike[str]) -> None:
    """The rule graph ``dot``, drawn left to right to ``path`` (PNG): one box per rule, none
    overlapping another (``placed``), and each arrow from the right edge of a rule's box to the
    left edge of the box of the rule that needs it."""
    graph = rule_graph(dot)
    columns = layers(graph)
    font = 7.5  # points
    fig = plt.figure(figsize=(1, 1))
    renderer = fig.canvas.get_renderer()
    probe = fig.text(0, 0, "", fontsize=font)
    box = {}  # each box's width in inches, its padding included, as the name is drawn
    for name in graph.nodes:
        probe.set_text(name)
        box[name] = probe.get_window_extent(renderer).width / fig.dpi + 0.12
    probe.remove()
    centre, size = placed(columns, box)
    fig.set_size_inches(*size)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, size[0])
    ax.set_ylim(0, size[1])
    ax.axis("off")
    for a, b in graph.edges:
        (xa, ya), (xb, yb) = centre[a], centre[b]
        ax.annotate(
            "", xy=(xb - box[b] / 2, yb), xytext=(xa + box[a] / 2, ya),
            arrowprops=dict(arrowstyle="-|>", color="0.6", lw=0.6, shrinkA=0, shrinkB=0,
                            mutation_scale=7),
        )  # fmt: skip
    for name, (x, y) in centre.items():
        ax.text(
            x, y, name, fontsize=font, ha="center", va="center",
            bbox=dict(boxstyle="round,pad=0.25", fc="#e8f0f8", ec="0.5", lw=0.6),
        )  # fmt: skip
    save(fig, path)
