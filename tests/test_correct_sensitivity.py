"""The correct-trial RMSE's sensitivity estimate over every replication
(icub_affordance.analysis.correct_sensitivity), checked on made-up trials: a replication lacking a
cell still counts, a known effect is recovered, the networks per cell are counted right."""

from __future__ import annotations

import numpy as np
import pandas as pd

from icub_affordance.analysis.correct_sensitivity import FAMILY, cells, observations, sensitivity
from icub_affordance.analysis.trial_effects import (
    categorisation_trials,
    correct_trial_effects,
    with_outcomes,
)

#: Each mapping's objects: (object, size, congruent); mapping B swaps which are congruent.
OBJECTS = {
    "A": [("big_ball", "large", True), ("big_cube", "large", False),
          ("small_ball", "small", False), ("small_cube", "small", True)],
    "B": [("big_ball", "large", False), ("big_cube", "large", True),
          ("small_ball", "small", True), ("small_cube", "small", False)],
}  # fmt: skip


def made_up(
    replications: int = 4,
    networks: int = 8,
    sequences: int = 2,
    congruency: float = 0.02,
    size: float = 0.01,
    noise: float = 0.004,
    wrong=lambda seed, network, mapping, congruent, size, sequence: False,
    seed: int = 0,
) -> pd.DataFrame:
    """Categorisation trials (closed loop) of ``replications`` x ``networks`` (half mapping A,
    half B): RMSE 0.05 plus a replication's and a network's intercept, ``congruency`` times the
    incongruent code (+0.5, congruent -0.5), ``size`` times the small code, and noise; ``wrong``
    says which trials take the wrong grip. One grasping trial per network, which is no
    categorisation trial, always correct."""
    rng = np.random.default_rng(seed)
    rows = []
    for rep in range(replications):
        rep_shift = rng.normal(0, 0.01)
        for net in range(networks):
            mapping = "A" if net < networks // 2 else "B"
            net_shift = rng.normal(0, 0.005)
            for obj, sz, congruent in OBJECTS[mapping]:
                c, s = (-0.5 if congruent else 0.5), (0.5 if sz == "small" else -0.5)
                for q in range(sequences):
                    rmse = 0.05 + rep_shift + net_shift + congruency * c + size * s
                    rmse += rng.normal(0, noise)
                    bad = wrong(rep, net, mapping, congruent, sz, q)
                    rows.append({"cue": "first_step", "seed": rep, "network": net,
                                 "mapping": mapping, "mode": "closed_loop",
                                 "task": "categorisation", "object": obj, "size": sz,
                                 "congruent": congruent, "sequence": q, "rmse": rmse,
                                 "wrong_grip": int(bad)})  # fmt: skip
            rows.append({"cue": "first_step", "seed": rep, "network": net, "mapping": mapping,
                         "mode": "closed_loop", "task": "grasping", "object": "big_ball",
                         "size": "large", "congruent": np.nan, "sequence": 0, "rmse": 9.0,
                         "wrong_grip": 0})  # fmt: skip
    return pd.DataFrame(rows)


def by_hand(trials: pd.DataFrame) -> dict[str, float]:
    """With every cell of every network correct: the mean over networks of each network's
    contrasts (incongruent - congruent, small - large, each averaged over the other factor)."""
    cat = trials[(trials["task"] == "categorisation") & (trials["wrong_grip"] == 0)]
    cell = cat.groupby(["seed", "network", "congruent", "size"])["rmse"].mean().unstack(
        ["congruent", "size"])  # fmt: skip
    congruency = (cell[(False, "large")] + cell[(False, "small")]
                  - cell[(True, "large")] - cell[(True, "small")]) / 2  # fmt: skip
    size = (cell[(True, "small")] + cell[(False, "small")]
            - cell[(True, "large")] - cell[(False, "large")]) / 2  # fmt: skip
    return {"congruency": float(congruency.mean()), "size": float(size.mean())}


def test_a_replication_lacking_a_cell_still_counts():
    """Replication 2: every network took the wrong grip on every incongruent small trial. The
    per-replication estimator has no estimate there; the mixed model keeps its other cells."""

    def wrong(rep, net, mapping, congruent, size, q):
        return rep == 2 and not congruent and size == "small"

    trials = made_up(replications=4, networks=8, wrong=wrong)
    lacking = categorisation_trials(with_outcomes(trials[trials["seed"] == 2]), "closed_loop")
    assert np.isnan(correct_trial_effects(lacking, lono=False)["congruency"]["estimate"])

    table = sensitivity(trials).set_index("effect")
    assert (table["replications"] == 4).all()
    assert (table["replications_used"] == 4).all()
    assert (table["networks_used"] == 4 * 8).all()
    # every network x object but replication 2's incongruent small ones (one per network)
    assert (table["observations"] == 4 * 8 * 4 - 8).all()
    assert (table["fewest_networks_per_cell"] == 0).all()
    assert np.isfinite(table["estimate"]).all() and np.isfinite(table["p"]).all()
    data = observations(trials, "closed_loop")
    assert data.groupby("seed").size().to_dict() == {0: 32, 1: 32, 2: 24, 3: 32}


def test_a_known_effect_is_recovered_on_the_project_scale():
    """True congruency 0.02 and size 0.01: each within its 95% interval; with every cell
    present the estimate is the networks' mean contrast and the mean of the replications'
    ``trial_effects.correct_trial_effects`` estimates (the confirmation's), both computed apart."""
    trials = made_up(replications=6, networks=8, congruency=0.02, size=0.01, seed=3)
    table = sensitivity(trials).set_index("effect")
    hand = by_hand(trials)
    per_replication = [
        correct_trial_effects(categorisation_trials(with_outcomes(g), "closed_loop"), lono=False)
        for _, g in trials.groupby("seed")
    ]
    for effect, true in (("congruency", 0.02), ("size", 0.01)):
        row = table.loc[effect]
        assert row["ci_low"] < true < row["ci_high"]
        # t on the replications less one degrees of freedom: 2.570582 at 5 df
        assert np.isclose(row["ci_high"] - row["estimate"], 2.570582 * row["se"], rtol=1e-5)
        assert np.isclose(row["estimate"], hand[effect], rtol=1e-8, atol=1e-10)
        confirm = np.mean([r[effect]["estimate"] for r in per_replication])
        assert np.isclose(row["estimate"], confirm, rtol=1e-8, atol=1e-10)
        assert row["converged"] == 1.0 and row["p"] < 1e-4
    assert (table["family"] == FAMILY).all() and (table["family_size"] == 2).all()
    # Holm over two tests: the smaller p doubled, the larger kept (both at least the smaller's)
    p = table["p"].sort_values()
    holm = np.maximum.accumulate(np.minimum(1, p.to_numpy() * np.array([2, 1])))
    assert np.allclose(table.loc[p.index, "p_holm"], holm)


def test_networks_per_cell_are_counted():
    """Two replications, two networks per mapping, one trial each per object. Replication 0:
    network 0 (A) always wrong on the incongruent large object, network 1 (A) wrong on one of
    its two trials there, network 2 (B) always wrong on the congruent small object;
    replication 1 all correct."""

    def wrong(rep, net, mapping, congruent, size, q):
        if rep != 0:
            return False
        return (
            (net == 0 and not congruent and size == "large")
            or (net == 1 and not congruent and size == "large" and q == 0)
            or (net == 2 and congruent and size == "small")
        )

    trials = made_up(replications=2, networks=4, sequences=2, wrong=wrong)
    counts = cells(trials).set_index(["seed", "mapping", "congruency", "size"])
    expected = {(m, c, s): 2 for m in "AB" for c in ("congruent", "incongruent")
                for s in ("large", "small")}  # fmt: skip
    assert counts.loc[1, "networks"].to_dict() == expected
    assert counts.loc[0, "networks"].to_dict() == expected | {
        ("A", "incongruent", "large"): 1,
        ("B", "congruent", "small"): 1,
    }
    assert counts.loc[0, "fewest_in_mapping"].groupby("mapping").first().to_dict() == {
        "A": 1,
        "B": 1,
    }
    assert (counts.loc[1, "fewest_in_mapping"] == 2).all()
    assert (counts["networks_in_mapping"] == 2).all()
    assert len(counts) == 2 * 2 * 4
