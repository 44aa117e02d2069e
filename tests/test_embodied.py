"""Beyond the paper (issue 9): the network drives the robot; the cue ablation; the hidden units."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest
from conftest import demo_config, load_test_config

from icub_affordance.body import OBJECT_NAMES, Robot, to_normalised
from icub_affordance.embodied import (
    Outcome,
    network_policy,
    outcome_columns,
    replay_policy,
    run_trial,
)
from icub_affordance.embodied_stats import success_table
from icub_affordance.grasp import grip_in_contact, grip_used
from icub_affordance.jordan import Weights, network_step, run_closed_loop
from icub_affordance.representations import (
    distances_to_grasping,
    first_divergent_step,
    pca,
)

# -- the controller ----------------------------------------------------------------------------


def test_parked_objects_take_no_part_in_the_physics(robot):
    robot.place_object("big_ball")
    parked = {name: robot.object_position(name) for name in OBJECT_NAMES if name != "big_ball"}
    robot.step(500)
    bodies = {robot.model.geom_bodyid[g] for c in robot.data.contact for g in (c.geom1, c.geom2)}
    names = {robot.model.body(b).name for b in bodies}
    assert names.isdisjoint(parked), f"parked objects in contact: {names & set(parked)}"
    for name, pos in parked.items():
        np.testing.assert_allclose(robot.object_position(name), pos, atol=1e-9)
    # and the live object rests on the table, as before
    robot.place_object("small_cube")
    z = robot.object_position()[2]
    robot.step(500)
    assert abs(robot.object_position()[2] - z) < 2e-3


def test_grip_used_reads_the_touch_sensors():
    threshold = 0.01
    #        thumb index middle ring little palm
    assert grip_used(np.array([1, 1, 0, 0, 0, 0.0]), threshold) == "precision"
    assert grip_used(np.array([1, 1, 1, 1, 0, 0.0]), threshold) == "power"
    assert grip_used(np.array([1, 0, 0, 0, 0, 1.0]), threshold) == "power"
    assert grip_used(np.array([0, 1, 1, 1, 1, 1.0]), threshold) == "none"  # no thumb
    assert grip_used(np.zeros(6), threshold) == "none"


@pytest.mark.parametrize(
    ("required", "touch", "lift", "success", "wrong"),
    [
        #            thumb index middle ring little palm
        ("precision", [1, 1, 0, 0, 0, 0], 0.05, True, False),  # a pinch that holds
        ("precision", [1, 1, 0, 0, 0, 1], 0.05, False, True),  # the palm too: power, held
        ("precision", [1, 1, 1, 1, 0, 0], 0.05, False, True),  # three fingers: power, held
        ("precision", [1, 1, 1, 1, 0, 0], float("nan"), False, False),  # not lifted
        ("precision", [1, 1, 0, 0, 0, 0], 0.0, False, False),  # pinched, did not rise
        ("power", [1, 1, 1, 1, 1, 1], 0.05, True, False),
        ("power", [1, 0, 0, 0, 0, 1], 0.05, True, False),  # thumb and palm: power
        ("power", [1, 1, 0, 0, 0, 0], float("nan"), False, False),  # a pinch, not lifted
    ],
)
def test_success_is_the_required_grip_read_by_touch_and_the_object_rising(
    required, touch, lift, success, wrong
):
    """Issue 24: a precision trial held with the whole hand (touch reads power) is a failure,
    named as such; success is the grip the sensors read being the required one, and the lift."""
    config = demo_config()
    out = Outcome(
        commands=np.zeros((9, 16)), sensed=np.zeros((10, 16)), touch=np.array(touch, float),
        lift_m=lift, qpos=np.zeros((11, 3)), contact_time=1.0, palm=np.zeros(3),
    )  # fmt: skip
    row = outcome_columns(out, required, np.zeros(16), None, config)
    assert (row["success"], row["wrong_grip_hold"]) == (success, wrong)
    assert row["grip_used"] == grip_used(out.touch, config.touch_threshold)


def test_the_network_as_controller_is_the_network_of_the_evaluation():
    rng = np.random.default_rng(0)
    weights = Weights.init(hidden=7, scale=0.5, rng=rng)
    context = rng.uniform(size=(3, 9, 200))
    start = rng.uniform(size=(3, 16))
    outputs, _ = run_closed_loop(weights, context, start)
    # in a world where the arm goes exactly where it is told, the controller's loop is the same
    for trial in range(3):
        policy, proprio = network_policy(weights, context[trial]), start[trial]
        for t in range(9):
            proprio = policy(t, proprio)
            np.testing.assert_allclose(proprio, outputs[trial, t], rtol=0, atol=1e-12)
    y, h = network_step(weights, context[0, 0], start[0])
    assert y.shape == (16,) and h.shape == (7,)


@pytest.fixture(scope="module")
def demos(built):
    """The demonstrations of the small pipeline run (the demos do not depend on the config's
    test-size settings)."""
    data = np.load(built / "data" / "demos" / "demos.npz")
    return {key: data[key] for key in data.files}


def test_the_controller_follows_a_correct_plan(demos):
    """Replaying a demonstration's own servo targets through the embodied controller grasps and
    lifts the object: a network that output them would succeed."""
    robot = Robot()
    config = demo_config()
    objects, grips = demos["objects"].tolist(), demos["grips"].tolist()
    for o, g in ((0, 0), (1, 1), (2, 0), (3, 1)):  # each object, power and precision
        plan = to_normalised(demos["commands_deg"][o, g, 0])
        out = run_trial(
            robot, objects[o], replay_policy(plan), demos["angles"][o, g, 0, 0], len(plan),
            grips[g], config,
        )  # fmt: skip
        assert grip_used(out.touch, config.touch_threshold) == grips[g], (objects[o], out.touch)
        assert out.lift_m >= config.min_lift_m, (objects[o], grips[g], out.lift_m)
        np.testing.assert_allclose(out.sensed[0], demos["angles"][o, g, 0, 0], atol=1e-9)
    robot.close()


def test_a_plan_that_never_reaches_the_object_fails(demos):
    robot = Robot()
    start = demos["angles"][0, 0, 0, 0]
    out = run_trial(robot, "big_ball", lambda t, p: start, start, 10, "power", demo_config())
    assert grip_used(out.touch, 0.01) == "none"
    assert np.isnan(out.lift_m)  # not lifted: the grip's fingers never touched
    assert out.qpos.shape[0] == 11  # a state per step and after the lift test
    robot.close()


# -- the pipeline's outputs on the small config -------------------------------------------------


def test_embodied_trials_have_the_evaluation_columns_and_the_physical_outcome(built):
    data = built / "data"
    evaluation = pd.read_csv(data / "eval" / "trials.csv")
    embodied = pd.read_csv(data / "embodied" / "trials.csv")
    missing = set(evaluation.columns) - set(embodied.columns)
    assert not missing, missing
    assert {"success", "grip_used", "final_error"} <= set(embodied.columns)
    # the contract: which variant each row is, and its contact time
    assert {"run", "target", "hidden", "iterations", "contact_time"} <= set(embodied.columns)
    variants = pd.read_csv(data / "embodied" / "variants.csv")
    assert list(embodied["run"].unique()) == list(variants["run"]) and "main" in set(
        variants["run"]
    )
    # for every tested variant, one robot trial per closed-loop trial of the evaluation
    closed = evaluation[evaluation["mode"] == "closed_loop"]
    assert (embodied.groupby("run").size() == len(closed)).all()
    main = embodied[embodied["run"] == "main"]
    own = load_test_config()["network"]
    assert set(main["target"]) == {own["target"]} and set(main["hidden"]) == {own["hidden"]}
    assert set(main["iterations"]) == {own["iterations"]}
    # contact before the end of the trial, and none where the required fingers never all touched
    assert embodied["contact_time"].dropna().between(0, 2.6).all()
    assert set(embodied["mode"]) == {"embodied"}
    assert set(embodied["grip_used"]) <= {"power", "precision", "none"}
    assert embodied["final_error"].between(0, 1).all()
    # the palm's distance from the demonstrator's, in every trial, in millimetres (a hand some
    # millimetres to a few centimetres off; in metres the median would be below 0.1)
    assert embodied["palm_error_mm"].between(0, 500).all()
    assert 0.5 < embodied["palm_error_mm"].median() < 200
    # the body's tolerance: every object's unshifted mean plan holds it, each level's trials
    tolerance = pd.read_csv(data / "embodied" / "tolerance.csv")
    settings = load_test_config()["robot"]["tolerance"]
    assert tolerance.groupby("noise").size().to_dict() == {
        noise: 4 * (settings["repeats"] if noise else 1) for noise in settings["noise"]
    }
    assert tolerance.loc[tolerance["noise"] == 0, "success"].all()
    # success is exactly: the touch sensors read the required grip, and the object rose with the
    # hand; a hold with the other grip is a failure of its own (lifted: the required fingers
    # touched, with more of the hand)
    config = demo_config()
    touch = embodied[[f"touch_{n}" for n in ("thumb", "index", "middle", "ring", "little", "palm")]]
    read = np.array([grip_used(t, config.touch_threshold) for t in touch.to_numpy()])
    in_contact = np.array([
        grip_in_contact(g, t, config.touch_threshold)
        for g, t in zip(embodied["target_grip"], touch.to_numpy(), strict=True)
    ])  # fmt: skip
    assert (read == embodied["grip_used"]).all()
    held = embodied["lift_m"].fillna(0) >= config.min_lift_m
    assert (embodied["lift_m"].notna() == in_contact).all()
    assert (embodied["success"] == ((read == embodied["target_grip"]) & held)).all()
    wrong = held & (read != embodied["target_grip"])
    assert (embodied["wrong_grip_hold"] == wrong).all()
    assert not (wrong & (embodied["target_grip"] == "power")).any()


def test_the_success_table_covers_every_condition(built):
    data = built / "data" / "embodied"
    table = pd.read_csv(data / "success.csv")
    assert set(zip(table["condition"], table["size"], strict=True)) == {
        (c, s) for c in ("grasping", "congruent", "incongruent") for s in ("large", "small")
    }
    assert table["success"].between(0, 1).all()
    grips = table[["grip_power", "grip_precision", "grip_none"]].sum(axis=1)
    np.testing.assert_allclose(grips, 1.0)
    # recomputed from the trials
    trials = pd.read_csv(data / "trials.csv")
    np.testing.assert_allclose(
        success_table(trials)["success"].to_numpy(), table["success"].to_numpy(), atol=1e-4
    )
    analysis = json.loads((data / "analysis.json").read_text())
    assert analysis["replay_success"]["commands"] >= 0.9
    assert set(analysis["measures"]) == {"success", "final_error"}


def test_the_cue_ablation_runs_beside_the_main_run(built):
    data = built / "data"
    main = json.loads((data / "eval" / "anova.json").read_text())
    run = data / "runs" / "cue_all_steps"  # the test config's cue is first_step
    ablation = json.loads((run / "eval" / "anova.json").read_text())
    assert set(ablation) == set(main)
    assert ablation["closed_loop"]["n_trials"] == main["closed_loop"]["n_trials"]
    # same seeds, other cue: different networks, tested on the same trials
    a = pd.read_csv(run / "eval" / "trials.csv")
    m = pd.read_csv(data / "eval" / "trials.csv")
    assert len(a) == len(m)
    assert not np.allclose(a["rmse"], m["rmse"])
    assert (run / "figures" / "figure5.png").stat().st_size > 10_000
    # the run reads the main run's demonstrations and maps: it makes none of its own
    assert not (run / "demos").exists() and not (run / "soms").exists()


def test_hidden_representation_outputs_have_the_expected_shapes(built):
    data = built / "data" / "eval"
    trials = pd.read_csv(data / "trials.csv")
    n_networks, steps = trials["network"].nunique(), 9
    divergence = pd.read_csv(data / "divergence.csv")
    assert divergence["step"].tolist() == list(range(1, steps + 1))
    paths = pd.read_csv(data / "hidden_trajectories.csv")
    # per network: 4 objects x (grasping + its one categorisation condition) x 9 steps
    assert len(paths) == n_networks * 4 * 2 * steps
    explained = pd.read_csv(data / "hidden_explained.csv")
    assert len(explained) == n_networks
    assert (
        (explained["pc1"] >= explained["pc2"]) & (explained["pc1"] + explained["pc2"] <= 1)
    ).all()


# -- the analysis of the hidden units ----------------------------------------------------------


def test_pca_finds_the_direction_of_most_variance():
    rng = np.random.default_rng(1)
    latent = rng.normal(size=(500, 1)) * 5.0
    direction = np.array([[3.0, 4.0, 0.0]]) / 5.0
    states = latent @ direction + rng.normal(scale=0.1, size=(500, 3))
    projected, explained = pca(states)
    assert projected.shape == (500, 2)
    assert explained[0] > 0.99
    assert abs(np.corrcoef(projected[:, 0], latent[:, 0])[0, 1]) > 0.999


def test_distances_to_grasping_pair_each_trial_with_its_own_grasp():
    trials = pd.DataFrame(
        {
            "task": ["grasping", "grasping", "categorisation", "categorisation"],
            "congruent": ["", "", "True", "False"],
            "object": ["a", "b", "a", "b"],
            "sequence": [0, 0, 0, 0],
        }
    )
    hidden = np.zeros((4, 3, 2))
    hidden[1] = 1.0  # b's grasp
    hidden[3] = 1.0  # b's categorisation starts at its grasp...
    hidden[3, 2] = [4.0, 5.0]  # ...and moves 5 away at step 3
    table = distances_to_grasping(hidden, trials)
    congruent = table[table["congruency"] == "congruent"]["distance"].tolist()
    incongruent = table[table["congruency"] == "incongruent"]["distance"].tolist()
    assert congruent == [0.0, 0.0, 0.0]
    assert incongruent == [0.0, 0.0, 5.0]


def test_first_divergent_step_needs_every_later_step_significant():
    summary = pd.DataFrame(
        {"step": [1, 2, 3, 4], "difference": [0.1, 0.2, 0.3, 0.3], "p": [0.01, 0.2, 0.01, 0.001]}
    )
    summary["p_holm"] = summary["p"]
    assert first_divergent_step(summary) == 3
    summary["p_holm"] = 0.5
    assert first_divergent_step(summary) is None
    # the adjusted p decides, not the raw one
    summary = summary.assign(p=0.001, p_holm=[0.01, 0.01, 0.06, 0.01])
    assert first_divergent_step(summary) == 4
