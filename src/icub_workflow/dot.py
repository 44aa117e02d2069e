"""The DAG drawing's text made canonical: the same rules and needs give the same bytes.

`snakemake --rulegraph` numbers the rules and lists the edges in an order that follows Python's
hash seed, so two runs of the same workflow wrote different files. Here the rules are numbered in
the order of their names and the edges sorted; the drawing itself (labels, colours) is kept.
"""

from __future__ import annotations

import re

_NODE = re.compile(r'^\s*(\d+)\[label = "([^"]+)"(.*)$')
_EDGE = re.compile(r"^\s*(\d+) -> (\d+)\s*$")


def canonical_dot(text: str) -> str:
    """`text` (Snakemake's rule graph in dot) with nodes numbered by name and edges sorted."""
    header, nodes, edges = [], {}, []
    for line in text.splitlines():
        if node := _NODE.match(line):
            nodes[node.group(1)] = (node.group(2), node.group(3))
        elif edge := _EDGE.match(line):
            edges.append((edge.group(1), edge.group(2)))
        elif line.strip() == "}":
            continue
        elif not nodes:
            header.append(line)
        else:
            raise ValueError(f"unexpected line in the rule graph: {line!r}")
    if not nodes:
        raise ValueError("the rule graph has no rules: was it `snakemake --rulegraph` output?")
    names = sorted(label for label, _ in nodes.values())
    number = {old: names.index(label) for old, (label, _) in nodes.items()}
    rest = {label: tail for label, tail in nodes.values()}
    lines = [*header]
    lines += [f'\t{i}[label = "{label}"{rest[label]}' for i, label in enumerate(names)]
    lines += [f"\t{a} -> {b}" for a, b in sorted({(number[a], number[b]) for a, b in edges})]
    return "\n".join([*lines, "}"]) + "\n"
