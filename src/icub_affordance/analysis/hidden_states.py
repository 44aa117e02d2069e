"""The networks' internal representations (the paper's stated future work, section 4).

Why is an incongruent categorisation slower? In this model the object's visual map keeps pushing
the hidden layer toward the object's natural grip, the one grasping taught, while the task cue
pushes toward the other grip. So the question is asked of the hidden units: over the steps of a
trial, how far is a categorisation trial's hidden state from the grasping trial of the same object
and sequence, for congruent and for incongruent trials, and from which step on do they differ?
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from icub_affordance.analysis.decide import significant
from icub_affordance.analysis.statistics import group_regression, holm
from icub_affordance.analysis.trial_effects import CODING, trial_conditions
from icub_affordance.analysis.verdicts import ALPHA


def pca(states: np.ndarray, components: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """Principal axes of ``states`` (samples, units) by SVD of the centred data: the projection
    (samples, components) and the fraction of variance each component explains."""
    centred = states - states.mean(axis=0)
    _, singular, axes = np.linalg.svd(centred, full_matrices=False)
    # fix each axis's sign (largest loading positive) so that reruns draw the same picture
    signs = np.sign(axes[np.arange(len(axes)), np.abs(axes).argmax(axis=1)])
    axes = axes * signs[:, None]
    explained = singular**2 / np.sum(singular**2)
    return centred @ axes[:components].T, explained[:components]


def distances_to_grasping(hidden: np.ndarray, trials: pd.DataFrame) -> pd.DataFrame:
    """For each categorisation trial of one network, the Euclidean distance at every step between
    its hidden state and that of the grasping trial of the same object and sequence.

    ``hidden`` (trials, steps, units) is in the order of ``trials`` (one network, one mode).
    """
    conditions = trial_conditions(trials)
    key = list(zip(trials["object"], trials["sequence"], strict=True))
    grasp_index = {
        k: i for i, (k, c) in enumerate(zip(key, conditions, strict=True)) if c == "grasping"
    }
    rows = []
    for i, (k, condition) in enumerate(zip(key, conditions, strict=True)):
        if condition == "grasping":
            continue
        d = np.linalg.norm(hidden[i] - hidden[grasp_index[k]], axis=1)
        for step, value in enumerate(d, start=1):
            rows.append(
                {"object": k[0], "sequence": k[1], "congruency": condition, "step": step,
                 "distance": float(value)}
            )  # fmt: skip
    return pd.DataFrame(rows)


def divergence(hidden: dict[str, np.ndarray], trials: pd.DataFrame, mode: str = "closed_loop"):
    """Every network's distances to grasping (long table), and per step the incongruent minus
    congruent difference over networks: its estimate with the mapping as a covariate (coded
    -0.5 / +0.5, the average of the two mappings' means, as every other per-network test),
    95% interval, t-test p on the residual degrees of freedom, and that p Holm-adjusted over the
    steps (one family: "from step k on" reads every step's test)."""
    levels = CODING["mapping"]
    unknown = sorted(set(trials["mapping"].astype(str)) - set(levels))
    if unknown:
        raise ValueError(f"mapping: levels {unknown}, expected {levels[0]} or {levels[1]}")
    mapping = trials.groupby("network")["mapping"].first().astype(str)
    coded = pd.Series(np.where(mapping == levels[1], 0.5, -0.5), index=mapping.index)
    tables = []
    for net in sorted(trials["network"].unique()):
        mine = trials[(trials["network"] == net) & (trials["mode"] == mode)]
        table = distances_to_grasping(hidden[f"net{int(net):02d}__{mode}"], mine)
        tables.append(table.assign(network=int(net)))
    long = pd.concat(tables, ignore_index=True)
    per_net = long.groupby(["network", "step", "congruency"])["distance"].mean().unstack()
    rows = []
    for step, group in per_net.groupby(level="step"):
        networks = group.index.get_level_values("network")
        diff = (group["incongruent"] - group["congruent"]).to_numpy()
        term = group_regression(diff, coded.loc[networks].to_numpy())["mean"]
        rows.append(
            {"step": int(step), "congruent": float(group["congruent"].mean()),
             "incongruent": float(group["incongruent"].mean()),
             "difference": term["estimate"], "ci_low": term["ci_low"],
             "ci_high": term["ci_high"], "df": term["df"], "p": term["p"]}
        )  # fmt: skip
    summary = pd.DataFrame(rows)
    summary["p_holm"] = holm(summary["p"].to_numpy())
    return long, summary


def first_divergent_step(summary: pd.DataFrame, alpha: float = ALPHA) -> int | None:
    """The first step from which incongruent trials stay significantly further from grasping,
    by the steps' Holm-adjusted p."""
    shown = significant(summary["p_holm"], alpha) & (summary["difference"] > 0)
    for i in range(len(summary)):
        if shown.iloc[i:].all():
            return int(summary["step"].iloc[i])
    return None


def trajectories(hidden: np.ndarray, trials: pd.DataFrame) -> dict[str, object]:
    """One network's hidden states over the steps projected on its first two principal axes,
    averaged over sequences per object and condition: {(object, condition): (steps, 2)}."""
    trials = trials.reset_index(drop=True)
    n, steps, units = hidden.shape
    projected, explained = pca(hidden.reshape(n * steps, units))
    projected = projected.reshape(n, steps, 2)
    conditions = trial_conditions(trials)
    paths = {}
    for (obj, condition), group in trials.groupby([trials["object"], conditions], sort=False):
        paths[(obj, condition)] = projected[group.index].mean(axis=0)
    return {"paths": paths, "explained": explained}


def trajectory_table(
    hidden: dict[str, np.ndarray], trials: pd.DataFrame, mode: str = "closed_loop"
):
    """Every network's mean trajectories on its own first two principal axes (long table), and
    the variance those axes explain."""
    rows, explained = [], []
    for net in sorted(trials["network"].unique()):
        mine = trials[(trials["network"] == net) & (trials["mode"] == mode)]
        result = trajectories(hidden[f"net{int(net):02d}__{mode}"], mine)
        explained.append(
            {"network": int(net), "pc1": result["explained"][0], "pc2": result["explained"][1]}
        )
        for (obj, condition), path in result["paths"].items():
            for step, (x, y) in enumerate(path, start=1):
                rows.append(
                    {"network": int(net), "object": obj, "condition": condition, "step": step,
                     "pc1": float(x), "pc2": float(y)}
                )  # fmt: skip
    return pd.DataFrame(rows), pd.DataFrame(explained)
