"""Object names (config ``names``, learning.names): a name carries no size, each form shows what
it says, training shows each form on its declared share, the compiled trainer still computes
what autograd does, and with names off every bit is what it was before names existed."""

from __future__ import annotations

import hashlib
import itertools

import numpy as np
import pytest
import torch
from conftest import load_config, som_config, train_config

from icub_affordance.learning.maps import active_units, object_inputs, train_soms
from icub_affordance.learning.materials import synthetic_materials
from icub_affordance.learning.names import NamesConfig, form_counts, name_patterns
from icub_affordance.learning.network import N_INPUT, Weights, train_online
from icub_affordance.learning.torch_reference import JordanNet, train_sequence_torch
from icub_affordance.learning.training import context, train_network, train_networks
from icub_affordance.vocabulary import FORMS, OBJECT_NAMES, OBJECTS


def names_on(**changes) -> NamesConfig:
    """The config's names, turned on (with some keys changed)."""
    return NamesConfig.of(load_config()["names"] | {"use": True} | changes)


def test_the_paper_runs_without_names():
    assert NamesConfig.of(load_config()["names"]) is None


def test_a_name_carries_no_size():
    """Every name is as active as every other and as far from every other: no pair of names is
    nearer by size (or shape), so only what the networks learn can link a name to a size."""
    patterns = name_patterns(len(OBJECT_NAMES), 10)
    assert set(np.unique(patterns)) == {0.0, 1.0}
    assert len(set(patterns.sum(axis=1))) == 1
    distances = {
        (a, b): np.linalg.norm(patterns[i] - patterns[j])
        for (i, a), (j, b) in itertools.combinations(enumerate(OBJECT_NAMES), 2)
    }
    same_size = [d for (a, b), d in distances.items() if OBJECTS[a].size == OBJECTS[b].size]
    other_size = [d for (a, b), d in distances.items() if OBJECTS[a].size != OBJECTS[b].size]
    assert same_size and other_size and len(set(same_size + other_size)) == 1


def test_through_the_object_map_every_name_lights_a_cluster_of_one_width():
    """The Object map's cluster grows with its input's activity, the paper's route for size
    (section 2.3): a name alone is equally active for every object, so its cluster is equally
    wide, while the images' are not. (A cluster whose winner lies at the map's edge is cut, a
    name's as an image's; kept whole, soms.keep_whole, every name's has one size.)"""
    m = synthetic_materials()
    inputs = object_inputs(m.visual, names_on())
    assert len(set(inputs["name"].sum(axis=1))) == 1
    assert len(set(inputs["image"].sum(axis=1))) > 1
    maps = train_soms(
        m.visual.reshape(4, 10, 10), som_config(iterations=300, keep_whole=True), 5, names_on()
    )
    name = FORMS.index("name")
    assert len({active_units(act) for act in maps.object_act_forms[name]}) == 1
    assert len({active_units(act) for act in maps.object_act}) > 1  # the images' differ
    # the image form is the map's response to the image alone
    np.testing.assert_array_equal(maps.object_act, maps.object_act_forms[FORMS.index("image")])
    # the Task map knows nothing of names: its patterns and response are the paper's model's
    without = train_soms(
        m.visual.reshape(4, 10, 10), som_config(iterations=300, keep_whole=True), 5
    )
    np.testing.assert_array_equal(maps.task_patterns, without.task_patterns)
    np.testing.assert_array_equal(maps.task_act, without.task_act)
    np.testing.assert_array_equal(maps.name_patterns, name_patterns(4, 10))


def test_each_form_shows_what_it_says():
    m = synthetic_materials(units_per_name=10)
    goal = 100 + 100
    for form in FORMS:
        ctx = context(m.shown(form), 2, 0, "first_step")
        image, name = ctx[:, :100], ctx[:, goal:]
        assert ctx.shape == (9, goal + 40)
        np.testing.assert_array_equal(image[0], m.visual[2] * (form != "name"))
        np.testing.assert_array_equal(name[0], m.names[2] * (form != "image"))
        np.testing.assert_array_equal(ctx[0, 100:goal], m.goal_forms[FORMS.index(form), 2, 0])
    with pytest.raises(ValueError, match="Materials.shown"):
        context(m, 2, 0, "first_step")  # unshown: which form is not said
    with pytest.raises(ValueError, match="names.use"):
        synthetic_materials().shown("name")


def test_names_that_reach_the_maps_alone_give_the_network_no_name_input():
    """A run whose names reach the Object map but not the network (names.routes without
    ``network``) has Goal activations per form and no name input: a form blanks the image or
    not, takes its Goal activations, and adds no input unit."""
    import dataclasses

    m = dataclasses.replace(synthetic_materials(units_per_name=10), names=None)
    for form in FORMS:
        view = m.shown(form)
        assert view.names is None and view.goal_forms is None
        np.testing.assert_array_equal(view.visual, m.visual * (form != "name"))
        np.testing.assert_array_equal(view.goal, m.goal_forms[FORMS.index(form)])
        assert context(view, 2, 0, "first_step").shape == (9, 100 + 100)


def test_training_shows_each_form_on_its_declared_share():
    m = synthetic_materials(units_per_name=10)
    names = names_on(training={"phase1": {"both": 1}, "phase2": {"image": 1, "name": 2}})
    config = train_config(iterations=1200, phase1_iterations=600, curve_rows=0, names=names)
    weights, curve = train_network(m, config, "A", seed=3)
    assert weights.W1.shape == (10, N_INPUT + 40)
    phase1, phase2 = curve["form"][:600], curve["form"][600:]
    assert np.bincount(phase1, minlength=3).tolist() == [0, 0, 600]
    assert np.bincount(phase2, minlength=3).tolist() == [200, 400, 0]
    assert len(set(zip(curve["form"][600:], curve["object"][600:], strict=True))) == 8
    # side by side in lanes, the same bits as alone
    (together, _), _ = train_networks(m, config, ["A", "B"], [3, 4])
    np.testing.assert_array_equal(together.W1, weights.W1)


def test_shares_that_do_not_split_a_phase_are_refused():
    with pytest.raises(ValueError, match="whole shares"):
        form_counts((1, 1, 1), 100)


def test_the_compiled_trainer_with_names_equals_the_torch_loop():
    """With the name's units appended to the input, the compiled trainer still computes what
    autograd computes, to 1e-10."""
    m = synthetic_materials(units_per_name=5)
    rng = np.random.default_rng(2)
    w0 = Weights.init(10, 0.5, rng, N_INPUT + 20)
    views = [m.shown(form) for form in FORMS]
    contexts = np.array([[context(v, o, k, "first_step") for k in range(2)]
                         for v in views for o in range(4)])  # fmt: skip
    demos = np.concatenate([m.demos] * 3)
    grips = rng.integers(0, 2, (12, 2))
    n = 120
    schedule = rng.integers(0, 2, n), rng.integers(0, 12, n), rng.integers(0, 4, n)
    net = JordanNet(w0)
    sgd = torch.optim.SGD(net.parameters(), lr=0.075)
    reference = [
        train_sequence_torch(net, sgd, contexts[p, k], demos[p, grips[p, k], s])
        for k, p, s in zip(*schedule, strict=True)
    ]
    fast, rmse = train_online(w0, 0.075, contexts, demos, grips, schedule)
    np.testing.assert_allclose(rmse, reference, rtol=0, atol=1e-10)
    np.testing.assert_allclose(fast.W1, net.weights().W1, rtol=0, atol=1e-10)


#: The digest of :func:`_paper_digest` computed at be621cd, before names existed, in the build's
#: arithmetic (tests/conftest.py sets it): numpy at the AVX2 level, the same on every x86-64 CPU
#: with AVX2. (At be621cd, AVX-512 kernels gave 1ebab373..., a digest of that CPU alone.)
BEFORE_NAMES = "72846ad273368c564fcd0a2b4fad02b2edd6f47543888041943b764d489f1564"


def _paper_digest(names) -> str:
    """Networks alone and side by side, and the three maps, with ``names`` as given (None, or
    the config's block turned off), digested."""
    m = synthetic_materials()
    off = NamesConfig.of(names) if names else None
    digest = hashlib.sha256()
    trained = [train_network(m, train_config(names=off), "B", seed=7)]
    shorter = train_config(iterations=600, phase1_iterations=300, names=off)
    trained += train_networks(m, shorter, ["A", "B"], [1, 2])
    for weights, curve in trained:
        for key in sorted(curve):
            digest.update(np.ascontiguousarray(curve[key]).tobytes())
        for array in weights.as_dict().values():
            digest.update(array.tobytes())
    maps = train_soms(
        m.visual.reshape(4, 10, 10),
        som_config(iterations=300, goal_response="grows"),
        5,
        off,
    )
    for _, value in sorted(vars(maps).items()):
        if value is not None:
            digest.update(np.ascontiguousarray(value).tobytes())
    return digest.hexdigest()


def test_names_off_leave_every_bit_as_it_was_before_names():
    """Turned off (the paper's model), names change nothing: the networks and the maps are the
    bits the code made before names existed (the build's own check: `snakemake -c2 verify`)."""
    assert _paper_digest(load_config()["names"]) == BEFORE_NAMES


def test_a_network_with_names_is_tested_in_every_form():
    """Each test trial once per form, scored as the paper's trials are on what the form shows;
    and each form's hidden state at the first step, the network's own step on that input."""
    from icub_affordance.learning.network import network_step
    from icub_affordance.trials.forms import form_states, measure_forms
    from icub_affordance.trials.in_silico import TrialSet
    from icub_affordance.trials.scores import measure_network

    m = synthetic_materials(units_per_name=10)
    config = train_config(iterations=600, phase1_iterations=300, names=names_on())
    weights, _ = train_network(m, config, "A", seed=3)
    rows = measure_forms(m, weights, 0, "A", "first_step", "sensed")
    n = len(rows) // len(FORMS)
    assert [row["form"] for row in rows] == [form for form in FORMS for _ in range(n)]
    name_rows = measure_network(m.shown("name"), weights, 0, "A", "first_step", "sensed")
    assert [r | {"form": "name"} for r in name_rows] == rows[n : 2 * n]
    assert [r["rmse"] for r in rows[:n]] != [r["rmse"] for r in rows[n : 2 * n]]
    trials, states = form_states(m, weights, "A", "first_step", "sensed", 1)
    for form in FORMS:
        setup = TrialSet.of(m, "A", "first_step", "sensed", form)
        _, hidden = network_step(weights, setup.context[:, 0], setup.teacher[:, 0])
        np.testing.assert_array_equal(states[form], hidden)
    assert trials == setup.trials and states["name"].shape == (len(trials), 10)
