"""A run's trained and robot-tested networks as files, in parts: the writers and the loaders.

The config's own run trains and tests each network in a job of its own, in parallel at the
start, so its parts are its networks (``train/net03/weights.npz``, ``curve.csv``;
``embodied/net03/trials.csv``, ``states.npz``). Every other run trains its networks in one job,
and tests them on the robot in one job, whose part is ``all``: one ``weights.npz`` stacking the
networks' arrays beside their indices (``networks``), one ``curve.csv`` with a ``network``
column; one ``trials.csv`` holding every network's rows in network order (each row names its
``network``), one ``states.npz`` stacking each network's ``qpos`` beside the indices. The arrays
and rows are the ones a network's own file holds, bit for bit; only the files' layout differs.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from icub_affordance.files import load_npz, save_npz, write_columns, write_csv
from icub_affordance.learning.network import Weights
from icub_affordance.learning.training import Phase1

if TYPE_CHECKING:  # pandas is imported where a table is read: a training job is short
    import pandas as pd

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


def write_phase1_part(nets: Sequence[int], phase1s: Sequence[Phase1], path: str) -> None:
    """Write one part of a shared phase 1 (rule phase1): a network's state as it is
    (``Phase1.save``), or (several networks) each one's arrays under its index
    (``net03_W1cT``...) beside the indices (``networks``)."""
    if len(nets) != len(phase1s):
        raise ValueError(f"{len(nets)} networks, but {len(phase1s)} phase 1s")
    if len(nets) == 1:
        phase1s[0].save(path)
        return
    arrays = {
        f"net{net:02d}_{name}": value
        for net, phase1 in zip(nets, phase1s, strict=True)
        for name, value in phase1.arrays().items()
    }
    save_npz(path, networks=np.asarray(nets, dtype=np.int64), **arrays)


def load_phase1s(paths: Sequence[str]) -> dict[int, Phase1]:
    """Every network's phase 1 the parts ``paths`` hold, by network index: a one-network part's
    index from its folder (``net03``), a part ``all``'s from its file."""
    phase1s = {}
    for path in paths:
        folder = Path(path).parent.name
        if folder == ALL:
            stored = load_npz(path, required=("networks",))
            nets = stored["networks"].tolist()
            names = [f"net{net:02d}_{key}" for net in nets for key in Phase1.KEYS]
            missing = [name for name in names if name not in stored]
            if missing:
                raise ValueError(f"{path} lacks {missing}; delete it and rerun `snakemake -c2`.")
            for net in nets:
                prefix = f"net{net:02d}_"
                phase1s[net] = Phase1.of_arrays({k: stored[prefix + k] for k in Phase1.KEYS})
        else:
            (net,) = part_networks(folder)
            phase1s[net] = Phase1.load(path)
    return phase1s


def load_curves(paths: Sequence[str]) -> list[tuple[int, pd.DataFrame]]:
    """Every network's learning curve the parts ``paths`` hold, with its index, in the parts'
    order: a one-network part's as its file reads, a part ``all``'s rows of that network."""
    import pandas as pd

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


def write_robot_part(
    nets: Sequence[int],
    tested: Sequence[tuple[Sequence[Mapping[str, object]], np.ndarray]],
    trials_path: str,
    states_path: str,
) -> None:
    """Write one part of a robot test: a network's trial rows and sensed postures (``qpos``,
    one per trial) as they are, or (several networks) every network's rows in one table in
    network order and their postures stacked beside their indices. Each row names its network
    (column ``network``), so the table needs no column more."""
    if len(nets) != len(tested):
        raise ValueError(f"{len(nets)} networks, but {len(tested)} robot tests")
    for net, (rows, _) in zip(nets, tested, strict=True):
        if any(int(row["network"]) != net for row in rows):
            raise ValueError(f"network {net}'s robot test has rows of another network")
    write_csv(trials_path, [row for rows, _ in tested for row in rows])
    if len(nets) == 1:
        save_npz(states_path, qpos=tested[0][1])
        return
    qpos = np.stack([states for _, states in tested])
    save_npz(states_path, networks=np.asarray(nets, dtype=np.int64), qpos=qpos)


def load_robot_trials(paths: Sequence[str], **read_csv) -> pd.DataFrame:
    """Every robot trial the parts ``paths`` hold (trials.csv), one table in the parts' order:
    each network's rows as its robot test wrote them, column ``network`` naming it.
    ``read_csv``: pandas.read_csv's options (``dtype=str, keep_default_na=False``: as written)."""
    import pandas as pd

    if not paths:
        raise ValueError("no robot-test files to read")
    tables = [pd.read_csv(path, **read_csv) for path in paths]
    return pd.concat(tables, ignore_index=True) if len(tables) > 1 else tables[0]


def network_trials(trials: pd.DataFrame, net: int) -> pd.DataFrame:
    """One network's rows of a robot-test table (``load_robot_trials``), in the test's order,
    numbered from 0 as its postures are (``load_robot_states``)."""
    mine = trials[trials["network"].astype(int) == int(net)]
    if mine.empty:
        raise ValueError(f"no robot trial of network {net}")
    return mine.reset_index(drop=True)


def load_robot_states(paths: Sequence[str]) -> dict[int, np.ndarray]:
    """Every network's sensed postures in a robot test (``qpos``: trial x step x joint) that the
    parts ``paths`` hold (states.npz), by network index: a one-network part's index from its
    folder (``net03``), a part ``all``'s from its file."""
    states = {}
    for path in paths:
        folder = Path(path).parent.name
        if folder == ALL:
            stored = load_npz(path, required=("networks", "qpos"))
            for k, net in enumerate(stored["networks"].tolist()):
                states[net] = stored["qpos"][k]
        else:
            (net,) = part_networks(folder)
            states[net] = load_npz(path, required=("qpos",))["qpos"]
    return states
