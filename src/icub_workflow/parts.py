"""A run's trained networks as files, in parts: the writer and the one loader.

The config's own run trains each network in a job of its own, in parallel at the start, so its
parts are its networks (``train/net03/weights.npz``, ``curve.csv``). Every other run trains its
networks in one job, whose part is ``all``: one ``weights.npz`` stacking the networks' arrays
beside their indices (``networks``), one ``curve.csv`` with a ``network`` column. The arrays are
the ones a network's own file holds, bit for bit; only the files' layout differs.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import pandas as pd

from icub_affordance.io import load_npz, save_npz, write_columns
from icub_affordance.jordan import Weights

#: The part that holds every network of a run.
ALL = "all"
#: The name of a part that holds one network (its index, two digits).
NETWORK_PART = re.compile(r"net(\d\d)")
WEIGHT_ARRAYS = ("W1", "b1", "W2", "b2")


def part_names(nets: Sequence[str], per_network: bool) -> list[str]:
    """A run's parts: one per network (``net03``...), or the one part ``all``."""
    return [f"net{net}" for net in nets] if per_network else [ALL]


def part_networks(part: str) -> list[int] | None:
    """The network a one-network part holds, as a list; None for ``all`` (every network)."""
    if part == ALL:
        return None
    found = NETWORK_PART.fullmatch(part)
    if found is None:
        raise ValueError(f"{part!r} is not a part: `all` or a network's `netNN`")
    return [int(found[1])]


def write_part(
    nets: Sequence[int],
    trained: Sequence[tuple[Weights, Mapping[str, list]]],
    curve_path: str,
    weights_path: str,
) -> None:
    """Write one part: a network's curve and weights as they are, or (several networks) their
    curves under a ``network`` column and their weights stacked beside their indices."""
    if len(nets) == 1:
        weights, curve = trained[0]
        write_columns(curve_path, dict(curve))
        save_npz(weights_path, **weights.as_dict())
        return
    columns: dict[str, list] = {"network": []}
    for net, (_, curve) in zip(nets, trained, strict=True):
        rows = len(next(iter(curve.values())))
        columns["network"] += [net] * rows
        for name, values in curve.items():
            columns.setdefault(name, []).extend(values)
    write_columns(curve_path, columns)
    stacked = {
        name: np.stack([getattr(weights, name) for weights, _ in trained]) for name in WEIGHT_ARRAYS
    }
    save_npz(weights_path, networks=np.asarray(nets, dtype=np.int64), **stacked)


def load_weights(paths: Sequence[str]) -> list[tuple[int, Weights]]:
    """Every network the parts ``paths`` hold, with its index, in the parts' order: a
    one-network part's index from its folder (``net03``), a part ``all``'s from its file."""
    networks = []
    for path in paths:
        folder = Path(path).parent.name
        if folder == ALL:
            stored = load_npz(path, required=("networks", *WEIGHT_ARRAYS))
            for k, net in enumerate(stored["networks"].tolist()):
                networks.append((net, Weights(**{a: stored[a][k] for a in WEIGHT_ARRAYS})))
        else:
            (net,) = part_networks(folder)
            stored = load_npz(path, required=WEIGHT_ARRAYS)
            networks.append((net, Weights(**{a: stored[a] for a in WEIGHT_ARRAYS})))
    return networks


def load_curves(paths: Sequence[str]) -> list[tuple[int, pd.DataFrame]]:
    """Every network's learning curve the parts ``paths`` hold, with its index, in the parts'
    order: a one-network part's as its file reads, a part ``all``'s rows of that network."""
    curves = []
    for path in paths:
        folder = Path(path).parent.name
        table = pd.read_csv(path)
        if folder == ALL:
            for net, rows in table.groupby("network", sort=False):
                curves.append((int(net), rows.drop(columns="network").reset_index(drop=True)))
        else:
            (net,) = part_networks(folder)
            curves.append((net, table))
    return curves
