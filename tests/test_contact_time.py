"""The declared contact-time test on the robot's fresh networks (icub_affordance.analysis.contact):
the per-network contrast over the networks that touched in all four cells, recomputed by hand
(an ordinary least-squares fit of the contrasts on the mapping), and its cells."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy import stats as sps

from icub_affordance.analysis.contact import (
    ADDED_FAMILY,
    FAMILY,
    cell_counts,
    congruency_split,
    contact_time_tests,
)
from icub_affordance.analysis.statistics import holm
from icub_affordance.outcome import Outcome

DECLARATION = {"effect": "congruency", "alpha": 0.05, "min_networks": 3}
#: Under mapping A the big ball and the small cube are congruent, under B the other two.
CONGRUENT = {"A": {"big_ball", "small_cube"}, "B": {"small_ball", "big_cube"}}


def made_up(
    shift: float = 0.1,
    untouched: int = 1,
    networks: int = 8,
    seed: int = 0,
    shift_b: float | None = None,
):
    """Two sequences per network x object (one movement: the same physics), incongruent trials
    ``shift`` seconds slower (``shift_b`` under mapping B, where given), a network's own offset;
    the first ``untouched`` networks never
    touch the incongruent small object (no contact time there)."""
    rng = np.random.default_rng(seed)
    rows = []
    for net in range(networks):
        mapping = "A" if net < networks // 2 else "B"
        offset = rng.normal(0, 0.05)
        for obj in ("big_ball", "small_ball", "big_cube", "small_cube"):
            congruent = obj in CONGRUENT[mapping]
            size = "large" if obj.startswith("big") else "small"
            slower = shift if shift_b is None or mapping == "A" else shift_b
            time = 1.5 + offset + (0 if congruent else slower) + rng.normal(0, 0.02)
            if net < untouched and not congruent and size == "small":
                time = np.nan
            for sequence in (0, 1):
                rows.append({"run": "fresh", "network": net, "mapping": mapping,
                             "task": "categorisation", "object": obj, "size": size,
                             "congruent": congruent, "sequence": sequence,
                             "category": "natural" if "ball" in obj else "artefact",
                             "target_grip": "power" if (mapping == "A") == ("ball" in obj)
                             else "precision",
                             "contact_time": time, "success": True})  # fmt: skip
    return pd.DataFrame(rows)


def by_hand(trials: pd.DataFrame) -> tuple[float, float, int]:
    """Each network's incongruent minus congruent mean contact time (the mean of its two
    objects in each), over the networks with all four; regressed on the mapping coded -0.5 /
    +0.5: the intercept, its p (t, networks - 2 df), and the networks."""
    one = trials[trials["sequence"] == 0]
    wide = one.pivot_table("contact_time", "network", "object", dropna=False)
    wide = wide.dropna()
    mapping = one.groupby("network")["mapping"].first().loc[wide.index]
    diffs = []
    for net, row in wide.iterrows():
        cong = [row[o] for o in CONGRUENT[mapping[net]]]
        diffs.append(np.mean([row[o] for o in row.index if o not in CONGRUENT[mapping[net]]])
                     - np.mean(cong))  # fmt: skip
    x = np.where(mapping == "A", -0.5, 0.5)
    fit = sps.linregress(x, diffs)
    t = fit.intercept / fit.intercept_stderr
    return fit.intercept, 2 * sps.t.sf(abs(t), len(diffs) - 2), len(diffs)


def test_the_declared_test_is_the_networks_contrast_with_the_mapping_as_a_covariate():
    trials = made_up()
    row = contact_time_tests(trials, DECLARATION).iloc[0]
    estimate, p, networks = by_hand(trials)
    assert row["networks"] == 8 and row["networks_tested"] == networks == 7
    assert row["estimate"] == pytest.approx(estimate) and row["p"] == pytest.approx(p)
    assert row["df"] == networks - 2 and row["family"] == FAMILY
    assert row["direction"] == Outcome.PAPER and row["p_holm"] == pytest.approx(p)
    slower = contact_time_tests(made_up(shift=-0.1), DECLARATION).iloc[0]
    assert slower["direction"] == Outcome.AGAINST


def test_too_few_networks_touching_every_cell_is_not_assessable():
    row = contact_time_tests(made_up(untouched=6), DECLARATION).iloc[0]
    assert row["networks_tested"] == 2 and np.isnan(row["p"])
    assert row["direction"] == Outcome.NOT_ASSESSABLE


def test_the_cells_count_distinct_trials_and_those_that_touched():
    cells = cell_counts(made_up(untouched=3)).set_index(["congruency", "size"])
    assert (cells["trials"] == 8).all()  # one per network, not one per sequence
    assert cells.loc[("incongruent", "small"), "touched"] == 5
    assert cells.loc[("congruent", "small"), "networks_touched"] == 8


def test_the_split_by_mapping_and_object_adds_up_to_the_declared_estimate():
    """Added after results (issue 70): the declared estimate is the mean of the two mappings'
    rows, each mapping's the mean of its two objects' rows, each object incongruent once."""
    trials = made_up(shift=0.0, shift_b=0.2, networks=10)
    declared = contact_time_tests(trials, DECLARATION).iloc[0]
    split = congruency_split(trials, DECLARATION)
    assert (split["family"] == ADDED_FAMILY).all() and "added after results" in ADDED_FAMILY
    assert split["p_holm"].to_numpy() == pytest.approx(holm(split["p"]))
    mapping = split[split["split"] == "mapping"].set_index("mapping")
    assert mapping["estimate"].mean() == pytest.approx(declared["estimate"])
    assert mapping["networks"].sum() == declared["networks_tested"] == 9
    assert dict(mapping["natural_grip"]) == {"A": "power", "B": "precision"}
    objects = split[split["split"] == "mapping x size"]
    assert sorted(objects["object"]) == ["big_ball", "big_cube", "small_ball", "small_cube"]
    for m, rows in objects.groupby("mapping"):
        assert rows["estimate"].mean() == pytest.approx(mapping.loc[m, "estimate"])
        assert not set(rows["object"]) & CONGRUENT[m] and set(rows["versus"]) == CONGRUENT[m]
    # only mapping B is slower when incongruent: its row shows it, A's does not
    assert mapping.loc["B", "direction"] == Outcome.PAPER
    assert mapping.loc["A", "direction"] == Outcome.NONE
    between = split[split["split"] == "congruency x mapping"].iloc[0]
    assert between["estimate"] == pytest.approx(mapping.loc["B", "estimate"]
                                                - mapping.loc["A", "estimate"])  # fmt: skip
    assert between["df"] == declared["df"]  # the declared fit's own term


def test_the_split_with_no_network_touching_every_cell_is_not_assessable():
    """A small configuration (the test build's four networks) may leave no network with a
    contact in all four cells: the split then has its difference row only, not assessable,
    rather than failing the build."""
    split = congruency_split(made_up(untouched=8), DECLARATION)
    assert list(split["split"]) == ["congruency x mapping"]
    assert np.isnan(split["p"]).all() and (split["direction"] == Outcome.NOT_ASSESSABLE).all()
