"""The Jordan network and its training: shapes, the fast trainer's exactness, learning, schedule."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest
import torch
from conftest import REPO, train_config

from icub_affordance.learning.materials import synthetic_materials
from icub_affordance.learning.network import N_INPUT, Weights, run_closed_loop, train_online
from icub_affordance.learning.torch_reference import JordanNet, train_sequence_torch
from icub_affordance.learning.training import (
    context,
    learning_rates,
    mapping_of,
    schedule,
    target_grip,
    train_network,
)
from icub_affordance.vocabulary import CATEGORISATION, GRASPING


def test_network_shapes_and_outputs():
    w = Weights.init(10, 0.5, np.random.default_rng(0))
    assert w.W1.shape == (10, N_INPUT) == (10, 216) and w.W2.shape == (16, 10)
    net = JordanNet(w)
    y, h = net(torch.zeros(216, dtype=torch.float64))
    assert y.shape == (16,) and h.shape == (10,)
    assert ((y > 0) & (y < 1)).all()


@pytest.mark.heavy
@pytest.mark.parametrize("hidden", [10, 40])
@pytest.mark.parametrize("rate", ["constant", "anneal"])
def test_fast_trainer_equals_the_plain_torch_loop(hidden, rate):
    """The compiled trainer computes what autograd computes, step by step, to 1e-10: both cue
    timings, a constant rate and a falling one (as the annealed schedule's phase 2), the
    paper's 10 hidden units and the robot variants' 40."""
    m = synthetic_materials()
    rng = np.random.default_rng(1)
    w0 = Weights.init(hidden, 0.5, rng)
    n = 150  # per variant
    schedule = rng.integers(0, 2, n), rng.integers(0, 4, n), rng.integers(0, 4, n)
    rates = np.full(n, 0.075) if rate == "constant" else 0.075 * np.arange(n, 0, -1) / n
    for mapping, cue in (("A", "first_step"), ("B", "all_steps")):
        contexts = np.array([[context(m, o, k, cue) for k in range(2)] for o in range(4)])
        grips = np.array(
            [
                [m.grips.index(target_grip(m.objects[o], k, mapping)) for k in range(2)]
                for o in range(4)
            ]
        )
        net = JordanNet(w0)
        sgd = torch.optim.SGD(net.parameters(), lr=0.075)
        reference = []
        for lr, (k, o, s) in zip(rates, zip(*schedule, strict=True), strict=True):
            sgd.param_groups[0]["lr"] = float(lr)
            reference.append(
                train_sequence_torch(net, sgd, contexts[o, k], m.demos[o, grips[o, k], s])
            )
        fast, rmse = train_online(w0, rates, contexts, m.demos, grips, schedule)
        np.testing.assert_allclose(rmse, reference, rtol=0, atol=1e-10)
        for name in ("W1", "b1", "W2", "b2"):
            np.testing.assert_allclose(
                getattr(fast, name), getattr(net.weights(), name), rtol=0, atol=1e-10
            )
    # the initial weights are left as they were
    np.testing.assert_array_equal(w0.W1, Weights.init(hidden, 0.5, np.random.default_rng(1)).W1)


# Trains one network of the paper's size on the synthetic materials, and twelve together, and
# prints a digest of the weights and the learning curves; with "uncached", from kernels compiled
# afresh without a cache.
KERNEL_RUN = """
import hashlib, sys
import numba
from icub_affordance.learning.materials import synthetic_materials
from conftest import train_config
import icub_affordance.learning.kernel as kernel
from icub_affordance.learning.training import train_network, train_networks
if sys.argv[1] == "uncached":  # the same options, less the cache (the kernel the wrappers
    # call first: they find it among the module's globals when they compile)
    for name in ("_train_lanes", "train_lanes4", "train_lanes8"):
        compiled = getattr(kernel, name)
        options = {k: v for k, v in compiled.targetoptions.items() if k != "nopython"}
        setattr(kernel, name, numba.njit(**options)(compiled.py_func))
m = synthetic_materials()
trained = [train_network(m, train_config(), "B", seed=7)]
# twelve: eight in eight lanes, four in four
trained += train_networks(m, train_config(iterations=600, phase1_iterations=300), ["A"] * 12,
                          list(range(1, 13)))
digest = hashlib.sha256()
for weights, curve in trained:
    digest.update(curve["rmse"].tobytes())
    for array in weights.as_dict().values():
        digest.update(array.tobytes())
print("digest", digest.hexdigest())
"""


@pytest.mark.heavy  # three compilations of the kernel in fresh processes
def test_the_kernel_cache_cannot_change_the_bits(tmp_path):
    """A cold compile that fills an empty cache, a load from that cache and a compile without any
    cache train to the same bits, one network alone and networks together: what ran before
    cannot change a result."""

    def run(mode: str) -> tuple[str, str]:
        env = os.environ | {"NUMBA_CACHE_DIR": str(tmp_path / "cache"), "NUMBA_DEBUG_CACHE": "1"}
        env["PYTHONPATH"] = os.pathsep.join([str(REPO / "tests"), str(REPO / "src")])
        result = subprocess.run(
            [sys.executable, "-c", KERNEL_RUN, mode], env=env, capture_output=True, text=True
        )
        assert result.returncode == 0, result.stderr
        return result.stdout.rsplit("digest ", 1)[1].strip(), result.stdout

    cold, cold_log = run("cached")
    assert "data saved" in cold_log and "data loaded" not in cold_log
    warm, warm_log = run("cached")
    assert "data loaded" in warm_log and "data saved" not in warm_log
    uncached, _ = run("uncached")
    assert cold == warm == uncached


def test_the_kernels_exponential_is_within_one_ulp_of_the_c_librarys():
    """The trainer's own exp (vectorisable, the same on every CPU) over the range a sigmoid of
    a trained network meets, and its ends: 0 and a huge value, never NaN."""
    from icub_affordance.learning.kernel import neg_exp

    z = np.concatenate([np.linspace(-60, 60, 400_001), [-1e-300, 0.0, 1e-300, 0.5 * np.log(2)]])
    reference = np.exp(-z)
    ulps = np.abs(neg_exp(z) - reference) / np.spacing(reference)
    assert ulps.max() <= 1.0
    ends = neg_exp(np.array([-1e6, 1e6, -710.0, 710.0]))
    assert np.all(np.isfinite(ends)) and ends[1] < 1e-300 < 1e300 < ends[0]


def test_a_long_trainings_curve_keeps_every_kth_iteration_of_the_full_curve():
    """curve_rows caps the learning curve: every k-th iteration's own record (k the smallest
    that fits), the same network and weights as with the full curve."""
    m = synthetic_materials()
    full_w, full = train_network(m, train_config(iterations=1000, phase1_iterations=500), "A", 3)
    capped = train_config(iterations=1000, phase1_iterations=500, curve_rows=300)
    thin_w, thin = train_network(m, capped, "A", 3)
    assert list(thin["iteration"]) == list(range(4, 1001, 4))  # k = 4: 250 rows
    for key in full:
        np.testing.assert_array_equal(thin[key], full[key][3::4])
    np.testing.assert_array_equal(thin_w.W1, full_w.W1)
    assert train_config(curve_rows=0).curve_rows == 0
    with pytest.raises(ValueError, match="curve_rows"):
        train_config(curve_rows=-1)


def test_a_network_continued_from_a_shared_phase_1_is_the_network_trained_whole(tmp_path):
    """Phase 1 trained at the constant rate with the cue at the first step, saved and loaded,
    then continued with the annealed rate and the cue at every step: the same bits as that
    network trained in one go (so robot variants that differ only in what acts after phase 1
    share it). A phase 1 of other settings is refused."""
    from icub_affordance.learning.network import TrainingState
    from icub_affordance.learning.training import Phase1, train_phase1

    m = synthetic_materials()
    common = {"iterations": 600, "phase1_iterations": 300, "hidden": 12}
    constant = train_config(
        **common, learning_rate_schedule="constant", categorisation_cue="first_step"
    )
    anneal = train_config(**common, learning_rate_schedule="anneal", categorisation_cue="all_steps")
    train_phase1(m, constant, "B", 4).save(tmp_path / "phase1.npz")
    shared = Phase1.load(tmp_path / "phase1.npz")
    continued, curve = train_network(m, anneal, "B", 4, after=shared)
    whole, whole_curve = train_network(m, anneal, "B", 4)
    for key in ("W1", "b1", "W2", "b2"):
        np.testing.assert_array_equal(getattr(continued, key), getattr(whole, key))
    np.testing.assert_array_equal(curve["rmse"], whole_curve["rmse"])
    assert not np.array_equal(whole.W1, train_network(m, constant, "B", 4)[0].W1)
    for other in (train_config(**common | {"hidden": 11}), anneal):
        with pytest.raises(ValueError, match="other settings, mapping, seed or materials"):
            train_network(m, other, "A" if other is anneal else "B", 4, after=shared)
    # a saved state holds every array the kernel carries; one without them all is refused
    assert set(shared.state.arrays) == set(TrainingState.KEYS)
    arrays = dict(np.load(tmp_path / "phase1.npz"))
    del arrays["U"]
    np.savez(tmp_path / "partial.npz", **arrays)
    with pytest.raises(ValueError, match=r"lacks \['U'\]; delete it and rerun"):
        Phase1.load(tmp_path / "partial.npz")


def test_training_lowers_the_error():
    m = synthetic_materials()
    config = train_config(iterations=2000, phase1_iterations=1000)
    _, curve = train_network(m, config, "A", seed=4)
    assert curve["rmse"][:100].mean() > 2 * curve["rmse"][900:1000].mean()


def test_closed_loop_feeds_the_output_back():
    m = synthetic_materials()
    w = Weights.init(10, 0.5, np.random.default_rng(2))
    ctx = np.array([context(m, 0, GRASPING, "first_step")])
    teacher = m.demos[0, 0, :1]
    out, hidden = run_closed_loop(w, ctx, teacher[:, 0])
    assert out.shape == (1, 9, 16) and hidden.shape == (1, 9, 10)
    # step 2's input is step 1's output: recompute it by hand
    x = np.concatenate([ctx[0, 1, :100], out[0, 0], ctx[0, 1, 100:]])
    h = 1 / (1 + np.exp(-(w.W1 @ x + w.b1)))
    np.testing.assert_allclose(out[0, 1], 1 / (1 + np.exp(-(w.W2 @ h + w.b2))))
    forced, _ = run_closed_loop(w, ctx, teacher[:, 0], teacher)
    assert not np.allclose(forced, out)


def test_categorisation_cue_is_on_at_the_first_step_only_or_throughout():
    m = synthetic_materials()
    first = context(m, 2, CATEGORISATION, "first_step")
    always = context(m, 2, CATEGORISATION, "all_steps")
    np.testing.assert_array_equal(first[0, 100:], m.goal[2, CATEGORISATION])
    np.testing.assert_array_equal(first[1:, 100:], np.broadcast_to(m.goal[2, GRASPING], (8, 100)))
    np.testing.assert_array_equal(
        always[:, 100:], np.broadcast_to(m.goal[2, CATEGORISATION], (9, 100))
    )
    np.testing.assert_array_equal(
        context(m, 2, GRASPING, "first_step")[:, 100:], first[1:2, 100:].repeat(9, 0)
    )


def test_schedule_has_two_phases_half_and_half():
    config = train_config(iterations=12000, phase1_iterations=6000)
    tasks, objects, sequences = schedule(config, 4, 4, np.random.default_rng(0))
    assert (tasks[:6000] == GRASPING).all()
    assert (tasks[6000:] == CATEGORISATION).sum() == 3000
    assert set(objects) == {0, 1, 2, 3} and set(sequences) == {0, 1, 2, 3}  # never the 5th


def test_mappings_and_targets():
    assert [mapping_of(i, 12) for i in range(12)] == ["A"] * 6 + ["B"] * 6
    assert target_grip("big_ball", CATEGORISATION, "A") == "power"
    assert target_grip("small_ball", CATEGORISATION, "A") == "power"
    assert target_grip("big_cube", CATEGORISATION, "A") == "precision"
    assert target_grip("big_ball", CATEGORISATION, "B") == "precision"
    assert target_grip("small_cube", GRASPING, "B") == "precision"


def test_bad_training_settings_are_refused():
    with pytest.raises(ValueError, match="categorisation_cue"):
        train_config(categorisation_cue="sometimes")
    with pytest.raises(ValueError, match="learning_rate_schedule.*'anneal'"):
        train_config(learning_rate_schedule="cosine")
    with pytest.raises(ValueError, match="even"):
        train_config(iterations=101, phase1_iterations=50)


def test_the_annealed_rate_is_full_in_phase_1_then_falls_linearly_over_phase_2():
    constant = learning_rates(train_config(iterations=1000, phase1_iterations=600))
    np.testing.assert_array_equal(constant, np.full(1000, 0.075))
    config = train_config(iterations=1000, phase1_iterations=600, learning_rate_schedule="anneal")
    rates = learning_rates(config)
    np.testing.assert_array_equal(rates[:600], 0.075)
    assert rates[600] == 0.075 and rates[-1] == pytest.approx(0.075 / 400)
    np.testing.assert_allclose(np.diff(rates[600:]), -0.075 / 400)  # one step down per iteration


@pytest.mark.heavy
def test_a_rate_per_iteration_is_what_the_torch_loop_does_with_that_rate():
    """The kernel's per-iteration rates: the same bits as one rate when they are all equal, and
    the torch reference's updates, its optimiser's rate set before each sequence, when not."""
    m = synthetic_materials()
    rng = np.random.default_rng(3)
    w0 = Weights.init(10, 0.5, rng)
    n = 120
    schedule = rng.integers(0, 2, n), rng.integers(0, 4, n), rng.integers(0, 4, n)
    contexts = np.array([[context(m, o, k, "all_steps") for k in range(2)] for o in range(4)])
    grips = np.array([[m.grips.index(target_grip(m.objects[o], k, "A")) for k in range(2)]
                      for o in range(4)])  # fmt: skip
    one, rmse_one = train_online(w0, 0.075, contexts, m.demos, grips, schedule)
    same, rmse_same = train_online(w0, np.full(n, 0.075), contexts, m.demos, grips, schedule)
    np.testing.assert_array_equal(rmse_one, rmse_same)
    for name in ("W1", "b1", "W2", "b2"):
        np.testing.assert_array_equal(getattr(one, name), getattr(same, name))
    rates = np.linspace(0.2, 0.001, n)
    fast, rmse = train_online(w0, rates, contexts, m.demos, grips, schedule)
    net = JordanNet(w0)
    sgd = torch.optim.SGD(net.parameters(), lr=0.075)
    reference = []
    for rate, (k, o, s) in zip(rates, zip(*schedule, strict=True), strict=True):
        sgd.param_groups[0]["lr"] = float(rate)
        reference.append(train_sequence_torch(net, sgd, contexts[o, k], m.demos[o, grips[o, k], s]))
    np.testing.assert_allclose(rmse, reference, rtol=0, atol=1e-10)
    for name in ("W1", "b1", "W2", "b2"):
        np.testing.assert_allclose(
            getattr(fast, name), getattr(net.weights(), name), rtol=0, atol=1e-10
        )
    assert not np.allclose(fast.W2, one.W2)  # the rates made a difference
    with pytest.raises(ValueError, match="3 learning rates|\\(3,\\) learning rates"):
        train_online(w0, np.full(3, 0.075), contexts, m.demos, grips, schedule)


@pytest.mark.parametrize("hidden", [9, 10, 40])
@pytest.mark.parametrize("rate", ["constant", "anneal"])
def test_networks_trained_together_are_the_networks_trained_alone(hidden, rate):
    """train_networks (a run's networks eight or four at a time in a vector's lanes) gives every
    network the bytes train_network gives it alone, weights and learning curve: both cue
    timings, the paper's 10 hidden units and the robot variants' 40 (and 9: the kernels' path
    for a last single hidden unit), a constant and a falling rate; six networks (eight lanes,
    two of them copies) and eleven (eight lanes, then four with one copy)."""
    from icub_affordance.learning.training import train_networks

    m = synthetic_materials()
    for cue, n in [(cue, n) for cue in ("first_step", "all_steps") for n in (6, 11)]:
        mappings, seeds = ["A"] * (n // 2) + ["B"] * (n - n // 2), list(range(11, 11 + n))
        config = train_config(
            hidden=hidden, iterations=240, phase1_iterations=120, categorisation_cue=cue,
            learning_rate_schedule=rate, curve_rows=0,
        )  # fmt: skip
        together = train_networks(m, config, mappings, seeds)
        assert len(together) == len(seeds)
        for (weights, curve), mapping, seed in zip(together, mappings, seeds, strict=True):
            alone, alone_curve = train_network(m, config, mapping, seed)
            for name in ("W1", "b1", "W2", "b2"):
                assert getattr(weights, name).tobytes() == getattr(alone, name).tobytes()
            assert curve.keys() == alone_curve.keys()
            for key in curve:
                assert curve[key].tobytes() == alone_curve[key].tobytes(), key


def test_networks_go_eight_then_four_to_a_kernel_and_a_last_one_to_four_lanes():
    from icub_affordance.learning.network import lane_groups

    def widths(n):
        return [(len(group), lanes) for group, lanes in lane_groups(n)]

    assert widths(12) == [(8, 8), (4, 4)] and widths(13) == [(8, 8), (5, 8)]
    assert widths(6) == [(6, 8)] and widths(5) == [(5, 8)] and widths(4) == [(4, 4)]
    assert widths(3) == [(3, 4)] and widths(9) == [(8, 8), (1, 4)]
    assert widths(1) == [(1, 4)] and widths(0) == []  # one learning rule: no kernel for one
    assert [i for group, _ in lane_groups(21) for i in group] == list(range(21))


@pytest.mark.heavy
def test_a_shared_phase_1_trained_together_continues_to_the_networks_trained_alone():
    """Phase 1 of several networks trained together (train_phase1s), each the bytes of
    train_phase1, continued together with other settings after phase 1 (the annealed rate, the
    cue at every step, the servo targets) to the bytes of each network trained whole, alone."""
    from icub_affordance.learning.training import train_networks, train_phase1, train_phase1s

    m = synthetic_materials()
    common = {"iterations": 200, "phase1_iterations": 100, "hidden": 12, "target": "commands"}
    constant = train_config(**common, categorisation_cue="first_step")
    anneal = train_config(
        **common, learning_rate_schedule="anneal", categorisation_cue="all_steps", curve_rows=50
    )
    mappings, seeds = ["A", "B", "B", "A", "B"], [4, 5, 6, 7, 8]  # four together, one alone
    shared = train_phase1s(m, constant, mappings, seeds)
    for phase1, mapping, seed in zip(shared, mappings, seeds, strict=True):
        alone = train_phase1(m, constant, mapping, seed)
        assert phase1.key == alone.key and phase1.state.done == alone.state.done
        assert phase1.rmse.tobytes() == alone.rmse.tobytes()
        for key, value in alone.state.arrays.items():
            assert phase1.state.arrays[key].tobytes() == value.tobytes(), key
    kept = {k: v.copy() for k, v in shared[0].state.arrays.items()}
    continued = train_networks(m, anneal, mappings, seeds, after=shared)
    for key, value in kept.items():  # the saved phase 1 is left as it was
        assert shared[0].state.arrays[key].tobytes() == value.tobytes()
    for (weights, curve), mapping, seed in zip(continued, mappings, seeds, strict=True):
        whole, whole_curve = train_network(m, anneal, mapping, seed)
        for name in ("W1", "b1", "W2", "b2"):
            assert getattr(weights, name).tobytes() == getattr(whole, name).tobytes()
        for key in curve:
            assert curve[key].tobytes() == whole_curve[key].tobytes(), key
    with pytest.raises(ValueError, match="other settings, mapping, seed or materials"):
        train_networks(m, anneal, ["B"] * 5, seeds, after=shared)
    with pytest.raises(ValueError, match="one of each a network"):
        train_networks(m, anneal, ["A"], seeds)
