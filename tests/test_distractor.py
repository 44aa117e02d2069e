"""A distractor at test (icub_affordance.trials.distractor): at weight 0 the trials are the
paper's own, to the bit, and the design holds every target x other object x grip asked."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from icub_affordance.learning.materials import synthetic_materials
from icub_affordance.learning.network import Weights
from icub_affordance.trials.distractor import IMAGE_INPUTS, distractor_trials, with_distractor
from icub_affordance.trials.in_silico import TrialSet
from icub_affordance.trials.scores import measure_network
from icub_affordance.vocabulary import CATEGORISATION


@pytest.mark.parametrize(("mapping", "cue"), [("A", "first_step"), ("B", "all_steps")])
def test_no_weight_reproduces_the_trials_without_a_distractor(mapping, cue):
    """lam = 0 with every distractor: each categorisation trial's RMSE and wrong grip are the
    no-distractor trial's (scores.measure_network), bit for bit, in both test modes."""
    m = synthetic_materials()
    weights = Weights.init(10, 0.5, np.random.default_rng(3))
    plain = pd.DataFrame(measure_network(m, weights, 0, mapping, cue, "sensed"))
    plain = plain[plain["task"] == "categorisation"]
    rows = pd.DataFrame(distractor_trials(m, weights, 0, mapping, cue, "sensed", [0.0]))
    assert len(rows) == 3 * len(plain)  # every other object as distractor
    keys = ["mode", "object", "sequence"]
    joined = rows.merge(plain, on=keys, suffixes=("", "_plain"), validate="many_to_one")
    assert len(joined) == len(rows)
    assert (joined["rmse"].to_numpy() == joined["rmse_plain"].to_numpy()).all()
    assert (joined["wrong_grip"].to_numpy() == joined["wrong_grip_plain"].to_numpy()).all()
    assert (joined["target_grip"] == joined["target_grip_plain"]).all()


def test_the_distractor_adds_to_the_image_inputs_alone():
    """The distractor's share reaches the visual map and the Goal map's response, at its
    weight, and nothing else; a weight changes the trials."""
    m = synthetic_materials()
    setup = TrialSet.of(m, "A", "first_step", "sensed")
    ctx = with_distractor(m, setup, "first_step", 1, -0.5)
    i = next(i for i, (task, o, _) in enumerate(setup.trials) if task == CATEGORISATION and o == 0)
    other = TrialSet.of(m, "A", "first_step", "sensed").context
    j = next(j for j, (task, o, s) in enumerate(setup.trials)
             if task == CATEGORISATION and o == 1 and s == setup.trials[i][2])  # fmt: skip
    expected = setup.context[i, :, IMAGE_INPUTS] - 0.5 * other[j, :, IMAGE_INPUTS]
    np.testing.assert_array_equal(ctx[i, :, IMAGE_INPUTS], expected)
    np.testing.assert_array_equal(ctx[i, :, IMAGE_INPUTS.stop :], setup.context[i, :, 200:])
    weights = Weights.init(10, 0.5, np.random.default_rng(3))
    rows = pd.DataFrame(distractor_trials(m, weights, 0, "A", "first_step", "sensed", [0.0, 0.5]))
    by = rows.set_index(["lam", "mode", "object", "distractor", "sequence"])["rmse"]
    assert not np.array_equal(by.loc[0.0].to_numpy(), by.loc[0.5].to_numpy())


def test_every_pair_grip_and_compatibility():
    """Each target meets each other object once per sequence, mode and weight; both grips are
    asked over the two mappings; a distractor is compatible exactly when the grip asked is its
    natural grip, so all four cells of congruency x compatibility occur under each mapping."""
    m = synthetic_materials()
    weights = Weights.init(10, 0.5, np.random.default_rng(3))
    for mapping in ("A", "B"):
        rows = pd.DataFrame(
            distractor_trials(m, weights, 0, mapping, "first_step", "sensed", [0.25])
        )
        pairs = rows.groupby(["object", "distractor"]).size()
        assert len(pairs) == 12 and (pairs == 2 * 5).all()  # 2 modes x 5 sequences
        assert (rows["object"] != rows["distractor"]).all()
        assert (rows["compatible"] == (rows["target_grip"] == rows["distractor_grip"])).all()
        cells = rows.groupby(["congruent", "compatible"]).size()
        assert len(cells) == 4


def _trials_with(congruency: float, compatibility: float, seed: int) -> pd.DataFrame:
    """Stand-in distractor trials whose RMSE carries known effects, plus noise and a network
    offset (the real design: every target x other object under each mapping)."""
    m = synthetic_materials()
    weights = Weights.init(10, 0.5, np.random.default_rng(3))
    rows = []
    for net, mapping in enumerate(("A", "A", "B", "B")):
        rows += distractor_trials(m, weights, net, mapping, "first_step", "sensed", [0.0, 0.5])
    df = pd.DataFrame(rows)
    rng = np.random.default_rng(seed)
    incongruent = df["congruent"].astype(str) != "True"
    df["rmse"] = (
        0.1 + 0.01 * df["network"] + congruency * incongruent
        + compatibility * ~df["compatible"] + rng.normal(0, 1e-4, len(df))
    )  # fmt: skip
    df["wrong_grip"] = 0
    return df.assign(cue="first_step")


def test_the_fit_recovers_both_effects_and_the_families_hold():
    """Per replication the fit returns the effects put in (the cells weighed equally, the
    network's offset absorbed); the summary tests weights above 0 in the declared family alone
    (Holm over its tests), none at 0."""
    from icub_affordance.analysis.distractor_tests import replication_estimates, summary

    trials = pd.concat(
        [_trials_with(0.02, -0.01, seed).assign(replication=seed) for seed in range(3)]
    )
    estimates = replication_estimates(trials, ["rmse", "rmse_correct"])
    got = estimates.groupby("effect")["estimate"].mean()
    assert got["congruency"] == pytest.approx(0.02, abs=1e-3)
    assert got["compatibility"] == pytest.approx(-0.01, abs=1e-3)
    declaration = {
        "alpha": 0.05, "family": "declared", "inhibition_family": "explored",
        "human": {"congruency": {"colour": "positive", "location": "positive"},
                  "compatibility": {"colour": "negative", "location": "none"}},
    }  # fmt: skip
    table = summary(estimates, declaration, 2)
    assert set(table["lam"]) == {0.5} and set(table["family"]) == {"declared"}
    assert (table["family_size"] == 8).all()  # 2 modes x 1 weight x 2 measures x 2 effects
    assert (table["direction"] == np.where(table["effect"] == "congruency", 1, -1)).all()


def test_the_declaration_is_checked():
    """The distractor's measures must be the confirmation's."""
    from conftest import load_config

    from icub_workflow.config_checks import ConfigError, check_config

    config = load_config()
    check_config(config)
    config["distractor"]["measures"] = ["rmse"]
    with pytest.raises(ConfigError, match="distractor.measures"):
        check_config(config)
