"""The declared contact-time test on the robot's fresh networks (config
``robot.confirmation.contact_time``, declared in bec68e0 before any result of it): per confirmed
variant, the congruency effect on the seconds until the required grip's fingers touch the object,
incongruent minus congruent (positive: congruent faster, the paper's direction).

Why a test of its own: the exploration's contact-time tests ran on the networks a variant was
chosen on, so they cannot confirm anything about it; the fresh networks were tested on the robot
in every build, but only for the share held. The estimator is the exploration's
(``robot_effects.variant_effects``): each network x object once (its closed-loop sequences are one
movement), the trials that touched, each network's contrast over its four congruency x size
cells from the networks that touched in all four, t over them with the mapping as a covariate.
Beside each test, per cell, the trials and how many touched: a cell that no network touches is
an effect of its own, which no contrast shows.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import pandas as pd

from icub_affordance.analysis.paper_claims import direction
from icub_affordance.analysis.robot_effects import distinct_trials
from icub_affordance.analysis.statistics import holm
from icub_affordance.analysis.trial_effects import contrast_tests, per_network_contrasts

#: The family the declared tests are Holm-adjusted in, over themselves alone.
FAMILY = "declared: contact-time congruency on fresh networks"


def _categorisation(trials: pd.DataFrame) -> pd.DataFrame:
    """The distinct categorisation trials, with congruency and size named."""
    df = distinct_trials(trials)
    df = df[df["task"] == "categorisation"].copy()
    df["congruency"] = np.where(df["congruent"].astype(str) == "True", "congruent", "incongruent")
    return df


def cell_counts(trials: pd.DataFrame) -> pd.DataFrame:
    """Per run and congruency x size cell: the distinct trials, how many touched (a contact
    time), and the networks that touched there."""
    rows = []
    df = _categorisation(trials) if len(trials) else trials.assign(congruency=[])
    for (run, congruency, size), cell in df.groupby(["run", "congruency", "size"], sort=False):
        touched = cell["contact_time"].notna()
        rows.append({"run": run, "congruency": congruency, "size": size,
                     "trials": int(len(cell)), "touched": int(touched.sum()),
                     "networks_touched": int(cell.loc[touched, "network"].nunique())})  # fmt: skip
    return pd.DataFrame(rows, columns=["run", "congruency", "size", "trials", "touched",
                                       "networks_touched"])  # fmt: skip


def contact_time_tests(trials: pd.DataFrame, declaration: Mapping[str, Any]) -> pd.DataFrame:
    """Per run (a confirmed variant's fresh networks) the declared test: the networks in all,
    those that touched in all four cells (the test's units), estimate, interval, t, df, p, Holm's
    p over the runs (``FAMILY``) and the direction (``paper_claims.direction``, the confirmation's
    reading: an ``Outcome``); no test with fewer than
    ``min_networks`` networks, networks of one mapping only, or no spread."""
    effect, alpha = declaration["effect"], float(declaration["alpha"])
    least = max(int(declaration["min_networks"]), 3)
    rows = []
    for run, df in (_categorisation(trials) if len(trials) else trials).groupby("run", sort=False):
        per_net = per_network_contrasts(df[df["contact_time"].notna()], "contact_time")
        term = {k: np.nan for k in ("estimate", "se", "ci_low", "ci_high", "t", "df", "p")}
        if len(per_net) >= least and per_net["mapping"].nunique() == 2:
            with np.errstate(divide="ignore", invalid="ignore"):
                found = contrast_tests(per_net)[effect]
            if np.isfinite(found["se"]) and found["se"] > 0:
                term = {k: float(found[k]) for k in term}
        rows.append({"run": run, "effect": effect, "networks": int(df["network"].nunique()),
                     "networks_tested": int(len(per_net))} | term)  # fmt: skip
    table = pd.DataFrame(rows, columns=["run", "effect", "networks", "networks_tested", "estimate",
                                        "se", "ci_low", "ci_high", "t", "df", "p"])  # fmt: skip
    table["family"] = FAMILY
    table["p_holm"] = holm(table["p"].to_numpy(dtype=float)) if len(table) else []
    pairs = zip(table["estimate"], table["p_holm"], strict=True)
    table["direction"] = [direction(e, p, alpha) for e, p in pairs]
    return table


#: The family of the split below: chosen after the declared test's result was read (issue 70:
#: a referee found it carried by one mapping), so exploration, Holm-adjusted within itself alone.
ADDED_FAMILY = "exploration, added after results: contact-time congruency by mapping and object"

#: The columns of data/embodied/contact_time_split.csv.
SPLIT_COLUMNS = ["run", "split", "mapping", "natural_grip", "size", "object", "versus",
                 "networks", "estimate", "se", "ci_low", "ci_high", "t", "df", "p", "family",
                 "p_holm", "direction"]  # fmt: skip


def congruency_split(trials: pd.DataFrame, declaration: Mapping[str, Any]) -> pd.DataFrame:
    """Where the declared congruency effect on contact time comes from, on the declared test's
    own networks (those that touched in all four cells), per run: per mapping (``split``
    ``mapping``; ``natural_grip``, the grip that answers "natural" there), each network's
    incongruent minus congruent contact time averaged over the two sizes; per mapping x size
    (``object``), the incongruent object's time less that of the congruent object of its size
    (``versus``) in the same network, so each of the four objects is once the incongruent one;
    and ``congruency x mapping``, B's effect less A's, the declared fit's own term (a difference
    between the mappings is stated from its own test).
    The declared estimate is the mean of the two mappings' rows, and each mapping's the mean of
    its two objects' rows. Each a t over networks with at least the declared minimum, Holm
    within ``ADDED_FAMILY``; ``direction``, the declared test's rule (an ``Outcome``)."""
    from icub_affordance.analysis.replicated import over_replications

    alpha, least = float(declaration["alpha"]), max(int(declaration["min_networks"]), 3)
    rows = []
    for run, df in (_categorisation(trials) if len(trials) else trials).groupby("run", sort=False):
        touched = df[df["contact_time"].notna()]
        units = per_network_contrasts(touched, "contact_time").index
        used = touched[touched["network"].isin(units)]
        cells4 = pd.MultiIndex.from_product([("congruent", "incongruent"), ("large", "small")])
        time = used.pivot_table(index="network", columns=["congruency", "size"],
                                values="contact_time").reindex(columns=cells4)  # fmt: skip
        # (no network touched in all four cells: no mapping row, the difference not assessable)
        mapping = used.groupby("network")["mapping"].first().reindex(time.index)
        by_size = {s: time[("incongruent", s)] - time[("congruent", s)] for s in ("large", "small")}
        effect = (by_size["large"] + by_size["small"]) / 2
        base = {"run": run, "family": ADDED_FAMILY}
        for m, nets in mapping.groupby(mapping).groups.items():
            cells = df[df["mapping"] == m]
            natural = cells.loc[cells["category"] == "natural", "target_grip"].iloc[0]
            term = over_replications(effect[nets].to_numpy(), least)
            rows.append(base | {"split": "mapping", "mapping": m, "natural_grip": natural,
                                "size": "", "object": "", "versus": "",
                                "networks": len(nets)} | term)  # fmt: skip
            for s, values in by_size.items():
                names = cells[cells["size"] == s].groupby("congruency")["object"].first()
                term = over_replications(values[nets].to_numpy(), least)
                rows.append(base | {"split": "mapping x size", "mapping": m,
                                    "natural_grip": natural, "size": s,
                                    "object": names["incongruent"], "versus": names["congruent"],
                                    "networks": len(nets)} | term)  # fmt: skip
        per_net = per_network_contrasts(used, "contact_time")
        term = {k: np.nan for k in ("estimate", "se", "ci_low", "ci_high", "t", "df", "p")}
        if min(mapping.value_counts().reindex(["A", "B"], fill_value=0)) >= least:
            found = contrast_tests(per_net)["congruency:mapping"]  # the declared fit's own term
            term = {k: float(found[k]) for k in term}
        rows.append(base | {"split": "congruency x mapping", "mapping": "B - A", "natural_grip": "",
                            "size": "", "object": "", "versus": "",
                            "networks": len(per_net)} | term)  # fmt: skip
    table = pd.DataFrame(rows, columns=SPLIT_COLUMNS[:-2])
    table["p_holm"] = holm(table["p"].to_numpy(dtype=float)) if len(table) else []
    pairs = zip(table["estimate"], table["p_holm"], strict=True)
    table["direction"] = [direction(e, p, alpha) for e, p in pairs]
    return table[SPLIT_COLUMNS]
