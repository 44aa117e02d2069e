"""Learning the servo targets (config ``network.target: commands``) and grasping with them.

The training side on synthetic materials (fast): the choice changes what the motor outputs learn
and nothing upstream of them. The robot side on the real demonstrations (slow, a few seconds of
physics): a network that output the demonstrator's servo targets would grasp, the contact time
is the first physics step at which the required grip's sensors all read contact, and the robot
test's memo of identical trials changes no result.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd
import pytest
from conftest import demo_config, initial_posture_deg, load_config, train_config

from icub_affordance.body.demonstrations import merge_demos, object_demos
from icub_affordance.body.grasp import DEMO_S, move
from icub_affordance.body.robot import (
    OBJECT_NAMES,
    OBJECTS,
    TOUCH_NAMES,
    Robot,
    to_degrees,
    to_normalised,
)
from icub_affordance.files import save_npz
from icub_affordance.learning.materials import Materials, load_materials, synthetic_materials
from icub_affordance.learning.network import Weights, run_closed_loop, train_online
from icub_affordance.learning.training import context, target_grip, train_network
from icub_affordance.trials.in_silico import TrialSet, evaluate_network, trial_row
from icub_affordance.trials.on_robot import (
    body_tolerance,
    demo_palms,
    embodied_network,
    network_policy,
    outcome_columns,
    reference_palms,
    replay_policy,
    run_trial,
)
from icub_affordance.vocabulary import GRASPING, TASKS

CUE = "first_step"


def contexts_and_grips(m: Materials, mapping: str) -> tuple[np.ndarray, np.ndarray]:
    """Per object and task: the maps' input and the target grip, as train_network makes them."""
    n_objects, n_tasks = len(m.objects), len(TASKS)
    contexts = np.array([[context(m, o, k, CUE) for k in range(n_tasks)] for o in range(n_objects)])
    grips = np.array(
        [
            [m.grips.index(target_grip(m.objects[o], k, mapping)) for k in range(n_tasks)]
            for o in range(n_objects)
        ]
    )
    return contexts, grips


def teacher_forced_rmse(m: Materials, weights: Weights, against: str) -> float:
    """The network's teacher-forced outputs (sensed postures in) against the demos' sensed
    postures or servo targets at the next step, over every test trial."""
    setup = TrialSet.of(m, "A", CUE, "commands")
    out, _ = run_closed_loop(weights, setup.context, setup.teacher[:, 0], setup.teacher)
    wanted = setup.targets if against == "commands" else setup.teacher
    return float(np.sqrt(np.mean((out - wanted[:, 1:]) ** 2)))


# -- training: what the motor outputs learn -----------------------------------------------------


def test_target_commands_changes_what_is_learned_and_nothing_upstream():
    m = synthetic_materials()
    assert not np.allclose(m.demos, m.commands)  # the two targets differ
    config = {"iterations": 400, "phase1_iterations": 200}
    sensed_w, sensed = train_network(m, train_config(target="sensed", **config), "B", seed=11)
    commands_w, commands = train_network(m, train_config(target="commands", **config), "B", 11)
    # the same initial weights and schedule: the same trials in the same order
    for column in ("iteration", "phase", "task", "object", "sequence"):
        np.testing.assert_array_equal(sensed[column], commands[column], err_msg=column)
    # the first sequence's error is measured before any update: the same outputs, other targets
    assert sensed["rmse"][0] != commands["rmse"][0]
    for name, value in sensed_w.as_dict().items():
        assert not np.allclose(value, commands_w.as_dict()[name]), name
    # and target: sensed is the paper's network, taught the sensed postures (targets None)
    contexts, grips = contexts_and_grips(m, "B")
    rng = np.random.default_rng(11)
    w0 = Weights.init(train_config().hidden, train_config().init_scale, rng)
    schedule = (sensed["task"], sensed["object"], sensed["sequence"])
    lr = train_config().learning_rate
    paper, rmse = train_online(w0, lr, contexts, m.demos, grips, schedule)
    for name, value in paper.as_dict().items():
        np.testing.assert_array_equal(value, sensed_w.as_dict()[name], err_msg=name)
    np.testing.assert_array_equal(rmse, sensed["rmse"])
    taught, rmse = train_online(w0, lr, contexts, m.demos, grips, schedule, m.commands)
    for name, value in taught.as_dict().items():
        np.testing.assert_array_equal(value, commands_w.as_dict()[name], err_msg=name)
    np.testing.assert_array_equal(rmse, commands["rmse"])


def test_explicit_sensed_targets_are_the_default_to_the_bit():
    m = synthetic_materials(seed=2)
    contexts, grips = contexts_and_grips(m, "A")
    rng = np.random.default_rng(5)
    w0 = Weights.init(10, 0.5, rng)
    n = 300
    schedule = rng.integers(0, 2, n), rng.integers(0, 4, n), rng.integers(0, 4, n)
    default, rmse_default = train_online(w0, 0.075, contexts, m.demos, grips, schedule)
    explicit, rmse_explicit = train_online(
        w0, 0.075, contexts, m.demos, grips, schedule, targets=m.demos.copy()
    )
    for name, value in default.as_dict().items():
        np.testing.assert_array_equal(value, explicit.as_dict()[name], err_msg=name)
    np.testing.assert_array_equal(rmse_default, rmse_explicit)
    # and other targets do change the result
    other, _ = train_online(w0, 0.075, contexts, m.demos, grips, schedule, targets=m.commands)
    assert not np.allclose(other.W2, default.W2)


def test_each_network_outputs_what_it_was_taught():
    """Teacher forced, a commands network is nearer the servo targets than the sensed postures,
    and a sensed network the other way round."""
    m = synthetic_materials()
    config = {"iterations": 2000, "phase1_iterations": 1000}
    for seed in (3, 4):
        sensed, _ = train_network(m, train_config(target="sensed", **config), "A", seed)
        commands, _ = train_network(m, train_config(target="commands", **config), "A", seed)
        assert teacher_forced_rmse(m, commands, "commands") < teacher_forced_rmse(
            m, commands, "sensed"
        )
        assert teacher_forced_rmse(m, sensed, "sensed") < teacher_forced_rmse(m, sensed, "commands")
        # each is nearer its own target than the other network is
        assert teacher_forced_rmse(m, commands, "commands") < teacher_forced_rmse(
            m, sensed, "commands"
        )
        assert teacher_forced_rmse(m, sensed, "sensed") < teacher_forced_rmse(m, commands, "sensed")


def test_targets_must_have_the_demos_shape():
    m = synthetic_materials()
    contexts, grips = contexts_and_grips(m, "A")
    w0 = Weights.init(10, 0.5, np.random.default_rng(0))
    schedule = np.zeros(3, int), np.zeros(3, int), np.zeros(3, int)
    for bad in (m.commands[:, :, :-1], m.commands[..., :-1], m.commands[0]):
        with pytest.raises(ValueError, match="shape"):
            train_online(w0, 0.075, contexts, m.demos, grips, schedule, targets=bad)


def test_an_unknown_target_is_refused_naming_the_config_key():
    with pytest.raises(ValueError, match="network.target"):
        train_config(target="bogus")
    with pytest.raises(ValueError, match="network.target"):
        synthetic_materials().targets("bogus")
    m = synthetic_materials()
    assert m.targets("sensed") is m.demos and m.targets("commands") is m.commands


def test_a_commands_network_is_scored_against_the_commands_with_the_sensed_postures_fed_in():
    m = synthetic_materials()
    weights, _ = train_network(
        m, train_config(target="commands", iterations=400, phase1_iterations=200), "A", 1
    )
    sensed_setup = TrialSet.of(m, "A", CUE, "sensed")
    setup = TrialSet.of(m, "A", CUE, "commands")
    # what it is shown is the same; only what it is compared with changes
    assert setup.trials == sensed_setup.trials and setup.grips == sensed_setup.grips
    np.testing.assert_array_equal(setup.context, sensed_setup.context)
    np.testing.assert_array_equal(setup.teacher, sensed_setup.teacher)
    np.testing.assert_array_equal(sensed_setup.targets, sensed_setup.teacher)
    for i, ((_task, o, s), g) in enumerate(zip(setup.trials, setup.grips, strict=True)):
        np.testing.assert_array_equal(setup.teacher[i], m.demos[o, g, s])
        np.testing.assert_array_equal(setup.targets[i], m.commands[o, g, s])
    assert not np.allclose(setup.targets, setup.teacher)

    rows, _ = evaluate_network(m, weights, 0, "A", CUE, "commands")
    table = pd.DataFrame(rows)
    for mode, forced in (("teacher_forced", setup.teacher), ("closed_loop", None)):
        got = table[table["mode"] == mode]["rmse"].to_numpy()
        # the sensed postures in (teacher forced), the sensed start (closed loop)
        out, _ = run_closed_loop(weights, setup.context, setup.teacher[:, 0], forced)
        expected = np.sqrt(((out - setup.targets[:, 1:]) ** 2).mean(axis=(1, 2)))
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12, err_msg=mode)
        # not the sensed postures as targets
        assert not np.allclose(got, np.sqrt(((out - setup.teacher[:, 1:]) ** 2).mean(axis=(1, 2))))
    # nor the commands fed in as proprioception
    wrong, _ = run_closed_loop(weights, setup.context, setup.targets[:, 0], setup.targets)
    got = table[table["mode"] == "teacher_forced"]["rmse"].to_numpy()
    assert not np.allclose(got, np.sqrt(((wrong - setup.targets[:, 1:]) ** 2).mean(axis=(1, 2))))


# -- the robot ---------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def scene() -> Robot:
    """The robot with the config's object sizes, as the pipeline's robot jobs load it."""
    robot = Robot(object_sizes=load_config()["object_sizes_m"])
    yield robot
    robot.close()


@pytest.fixture(scope="module")
def demos(scene) -> dict[str, np.ndarray]:
    """The pipeline's demonstrations (the config's seed and demo settings; the small test config
    changes neither), made here in a few seconds."""
    config = load_config()
    parts = {
        obj: object_demos(
            scene, obj, initial_posture_deg(), config["seed"], demo_config()
        )  # fmt: skip
        for obj in OBJECT_NAMES
    }
    return merge_demos(parts)


@pytest.fixture(scope="module")
def materials(demos, tmp_path_factory) -> Materials:
    """The demonstrations read by ``load_materials`` beside stand-in visual and Goal maps (the
    robot tests never look at those)."""
    folder = tmp_path_factory.mktemp("materials")
    save_npz(folder / "demos.npz", **demos)
    rng = np.random.default_rng(0)
    save_npz(folder / "maps.npz", **{o: rng.integers(0, 2, (10, 10)) for o in OBJECT_NAMES})
    save_npz(
        folder / "soms.npz",
        goal_act=rng.uniform(0, 1, (len(OBJECT_NAMES) * len(TASKS), 100)),
        objects=np.array(OBJECT_NAMES),
    )
    return load_materials(folder / "maps.npz", folder / "soms.npz", folder / "demos.npz")


def every_demo(m: Materials):
    for o, obj in enumerate(m.objects):
        for g, grip in enumerate(m.grips):
            for s in range(m.demos.shape[2]):
                yield o, obj, g, grip, s


@pytest.mark.heavy
def test_a_network_that_outputs_the_servo_targets_grasps(scene, materials):
    """What a perfect ``target: commands`` network sends (at step t the demonstration's servo
    targets of step t+1, clipped to 0-1 as the sigmoid outputs are) grasps and lifts on the
    robot; the sensed postures it would send under ``target: sensed`` do no better."""
    m, config = materials, demo_config()
    assert m.demos.shape == (4, 2, 5, 10, 16)
    success = {"commands": {}, "sensed": {}}
    for o, obj, g, grip, s in every_demo(m):
        for kind in success:
            plan = m.targets(kind)[o, g, s]

            def perfect(t, _proprio, plan=plan):
                return plan[t + 1]

            out = run_trial(scene, obj, perfect, m.demos[o, g, s, 0], len(plan), grip, config)
            columns = outcome_columns(out, grip, m.demos[o, g, s, -1], None, config)
            success[kind][obj, grip, s] = columns["success"]
            if kind == "commands":
                np.testing.assert_array_equal(out.commands, plan[1:])  # what it sent
    natural = {k: v for k, v in success["commands"].items() if k[1] == OBJECTS[k[0]].natural_grip}
    assert len(natural) == 20 and all(natural.values()), [k for k, v in natural.items() if not v]
    rate = {kind: np.mean(list(result.values())) for kind, result in success.items()}
    assert rate["commands"] >= 0.9, rate
    assert rate["sensed"] <= rate["commands"], rate
    print(f"success: {rate}")


def first_contact_time(robot: Robot, obj: str, plan: np.ndarray, start: np.ndarray, grip: str):
    """The demonstration replayed step by step here: the time from the start to the first
    physics step at which every sensor the grip needs reads above the threshold."""
    threshold = demo_config().touch_threshold
    robot.reset()
    robot.place_object(obj)
    robot.set_posture_deg(to_degrees(start))
    t0, log = robot.data.time, []
    for t in range(1, len(plan)):
        move(
            robot,
            to_degrees(plan[t]),
            DEMO_S / (len(plan) - 1),
            record=lambda r: log.append((r.data.time, r.touch().copy())),
        )
    sensor = {name.removeprefix("touch_"): i for i, name in enumerate(TOUCH_NAMES)}
    for time, touch in log:
        on = {name: touch[i] > threshold for name, i in sensor.items()}
        fingers = sum(on[f] for f in ("index", "middle", "ring", "little"))
        if grip == "precision":
            ready = on["thumb"] and on["index"]
        else:
            ready = on["thumb"] and (on["palm"] or fingers >= 3)
        if ready:
            return time - t0, len(log)
    return float("nan"), len(log)


@pytest.mark.heavy
def test_contact_time_is_the_first_physics_step_the_grip_touches(scene, materials):
    m, config = materials, demo_config()
    for obj, grip in (("big_ball", "power"), ("small_cube", "precision"), ("big_cube", "power")):
        o, g = m.objects.index(obj), m.grips.index(grip)
        plan, start = m.commands[o, g, 0], m.demos[o, g, 0, 0]
        out = run_trial(
            scene, obj, lambda t, _p, plan=plan: plan[t + 1], start, len(plan), grip, config
        )
        expected, n_steps = first_contact_time(scene, obj, plan, start, grip)
        assert np.isfinite(expected) and 0 < expected < DEMO_S, (obj, grip, expected)
        assert abs(out.contact_time - expected) <= 1e-12, (obj, grip, out.contact_time, expected)
        # it is a physics step's time: a whole number of 2 ms steps (every one of them watched)
        dt = scene.model.opt.timestep
        assert n_steps == (len(plan) - 1) * round(DEMO_S / (len(plan) - 1) / dt)
        assert abs(out.contact_time / dt - round(out.contact_time / dt)) < 1e-6


def test_a_trial_that_never_touches_has_no_contact_time(robot):
    """The arm holds the initial posture, well above the object."""
    start = to_normalised(initial_posture_deg())
    out = run_trial(robot, "big_ball", lambda t, _p: start, start, 10, "power", demo_config())
    assert np.isnan(out.contact_time)
    assert np.isnan(outcome_columns(out, "power", start, None, demo_config())["contact_time"])


@pytest.mark.heavy
def test_the_memo_of_identical_trials_changes_no_result(scene, materials):
    """embodied_network runs each distinct trial once; running every trial afresh gives the same
    rows and states, to the bit."""
    m, config = materials, demo_config()
    weights, _ = train_network(m, train_config(target="commands"), "A", seed=5)
    mapping, target = "A", "commands"
    # two objects (a large and a small one) keep it short: the memo works per trial anyway
    keep = [m.objects.index("big_ball"), m.objects.index("small_cube")]
    small = replace(
        m,
        objects=tuple(m.objects[o] for o in keep),
        visual=m.visual[keep],
        goal=m.goal[keep],
        demos=m.demos[keep],
        commands=m.commands[keep],
    )
    rows, states = embodied_network(scene, small, weights, 3, mapping, CUE, target, config)
    setup = TrialSet.of(small, mapping, CUE, target)
    assert len(rows) == len(setup.trials) == len(TASKS) * 2 * 5
    palms = reference_palms(demo_palms(scene, small.demos, small.objects))
    expected_rows, expected_states = [], []
    for i, (_task, o, _s) in enumerate(setup.trials):
        grip = small.grips[setup.grips[i]]
        out = run_trial(
            scene,
            small.objects[o],
            network_policy(weights, setup.context[i]),
            setup.teacher[i, 0],
            len(setup.teacher[i]),
            grip,
            config,
        )
        row = trial_row(small, setup, i, out.commands, out.sensed[-1], 3, mapping, "embodied")
        ref = palms[o, setup.grips[i]]
        expected_rows.append(row | outcome_columns(out, grip, setup.teacher[i, -1], ref, config))
        expected_states.append(out.qpos)
    pd.testing.assert_frame_equal(pd.DataFrame(rows), pd.DataFrame(expected_rows), check_exact=True)
    np.testing.assert_array_equal(states, np.array(expected_states))
    # the network did reach the objects in some trials: the comparison covers contacts too
    table = pd.DataFrame(rows)
    assert table["contact_time"].notna().any()
    assert (table["task"] == TASKS[GRASPING]).sum() == 10


# -- how precisely the arm must move -----------------------------------------------------------


@pytest.mark.heavy
def test_the_palm_measure_is_where_the_replayed_demo_put_the_palm(scene, materials):
    """``demo_palms`` (forward kinematics of a demonstration's final sensed posture) agrees with
    the palm the physics reached when the demonstration's servo targets are replayed, within a
    millimetre; and the reference is the mean over the training sequences only."""
    m, config = materials, demo_config()
    palms = demo_palms(scene, m.demos, m.objects)
    assert palms.shape == (4, 2, 5, 3)
    for o, obj in enumerate(m.objects):
        g = m.grips.index(OBJECTS[obj].natural_grip)
        for s in (0, 4):
            plan = m.commands[o, g, s]
            out = run_trial(scene, obj, replay_policy(plan), m.demos[o, g, s, 0], 10, m.grips[g],
                            config)  # fmt: skip
            assert np.linalg.norm(out.palm - palms[o, g, s]) < 1e-3, (obj, s)
    np.testing.assert_allclose(reference_palms(palms), palms[:, :, :4].mean(axis=2))
    # the demonstrations of one grasp differ in their palms by millimetres, not centimetres
    spread = np.linalg.norm(palms - palms.mean(axis=2, keepdims=True), axis=-1)
    assert spread.max() < 0.01


@pytest.mark.heavy
def test_the_mean_plan_grasps_and_offsets_are_seeded(scene, demos):
    """The body's tolerance test: unshifted, the demonstrations' mean plan of each object's
    natural grasp holds the object, its palm within millimetres of the demonstrator's; every
    offset comes from the seed (the same call gives the same rows) and moves the palm."""
    config = demo_config()
    rows = pd.DataFrame(body_tolerance(scene, demos, [0.0, 0.02], 2, 7, config))
    assert len(rows) == 4 * (1 + 2)
    exact = rows[rows["noise"] == 0.0]
    assert exact["success"].all() and (exact["offset"] == 0).all()
    assert (exact["grip"] == [OBJECTS[o].natural_grip for o in exact["object"]]).all()
    assert exact["palm_error_mm"].max() < 5.0
    shifted = rows[rows["noise"] == 0.02]
    assert (shifted["offset"] > 0).all() and shifted["offset"].nunique() == len(shifted)
    assert (shifted["palm_error_mm"].to_numpy() != np.repeat(exact["palm_error_mm"], 2)).all()
    again = pd.DataFrame(body_tolerance(scene, demos, [0.0, 0.02], 2, 7, config))
    pd.testing.assert_frame_equal(rows, again, check_exact=True)
    other = pd.DataFrame(body_tolerance(scene, demos, [0.0, 0.02], 2, 8, config))
    assert not np.isin(other["offset"], shifted["offset"]).any()  # another seed, other offsets
    # a level's offsets do not depend on the other levels listed: a repeat keeps its direction
    alone = pd.DataFrame(body_tolerance(scene, demos, [0.02], 2, 7, config))
    np.testing.assert_array_equal(alone["offset"], shifted["offset"])
