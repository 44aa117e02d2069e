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


def draw_rulegraph(dot: str, path: str | os.PathLike[str]) -> None:
    """The rule graph ``dot``, drawn left to right to ``path`` (PNG)."""
    graph = rule_graph(dot)
    pos = nx.multipartite_layout(
        graph, subset_key=dict(enumerate(layers(graph))), align="vertical", scale=2.0
    )
    fig, ax = plt.subplots(figsize=(10, 4.2))
    nx.draw_networkx_edges(
        graph, pos, ax=ax, arrows=True, arrowsize=12, edge_color="0.55", node_size=3000,
        connectionstyle="arc3,rad=0.05",
    )  # fmt: skip
    nx.draw_networkx_labels(
        graph, pos, ax=ax, font_size=8,
        bbox=dict(boxstyle="round,pad=0.3", fc="#e8f0f8", ec="0.5"),
    )  # fmt: skip
    ax.axis("off")
    fig.tight_layout()
    save(fig, path)
