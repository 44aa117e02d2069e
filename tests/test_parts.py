"""A run's networks in parts (icub_workflow.parts): a part `all` holds each network's arrays and
curve (trained) or rows and postures (robot test), bit for bit, as that network's own part
would; the loaders read either."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from icub_affordance.learning.network import Weights
from icub_workflow.parts import (
    load_curves,
    load_robot_states,
    load_robot_trials,
    load_weights,
    network_trials,
    part_names,
    part_networks,
    write_part,
    write_robot_part,
)


def made_up(net: int) -> tuple[Weights, dict[str, list]]:
    rng = np.random.default_rng(net)
    weights = Weights(
        W1=rng.normal(size=(5, 7)), b1=rng.normal(size=5), W2=rng.normal(size=(3, 5)),
        b2=rng.normal(size=3),
    )  # fmt: skip
    curve = {"iteration": [0, 10], "phase": [1, 2], "rmse": [rng.random(), rng.random() / 3]}
    return weights, curve


def test_a_part_all_holds_each_networks_own_bits(tmp_path):
    nets = [12, 13, 14]
    trained = [made_up(net) for net in nets]
    (tmp_path / "all").mkdir()
    write_part(nets, trained, str(tmp_path / "all/curve.csv"), str(tmp_path / "all/weights.npz"))
    for net, result in zip(nets, trained, strict=True):
        (tmp_path / f"net{net}").mkdir()
        write_part([net], [result], *(str(tmp_path / f"net{net}/{f}") for f in
                                      ("curve.csv", "weights.npz")))  # fmt: skip
    packed = load_weights([str(tmp_path / "all/weights.npz")])
    alone = load_weights([str(tmp_path / f"net{net}/weights.npz") for net in nets])
    assert [net for net, _ in packed] == [net for net, _ in alone] == nets
    for (_, a), (_, b) in zip(packed, alone, strict=True):
        for name in ("W1", "b1", "W2", "b2"):
            assert getattr(a, name).tobytes() == getattr(b, name).tobytes()
    curves = pd.read_csv(tmp_path / "all/curve.csv")
    assert list(curves.columns) == ["network", "iteration", "phase", "rmse"]
    loaded = load_curves([str(tmp_path / "all/curve.csv")])
    alone_curves = load_curves([str(tmp_path / f"net{net}/curve.csv") for net in nets])
    assert [net for net, _ in loaded] == [net for net, _ in alone_curves] == nets
    for (_, a), (_, b) in zip(loaded, alone_curves, strict=True):
        assert a.equals(b)
    for net in nets:
        own = pd.read_csv(tmp_path / f"net{net}/curve.csv")
        assert own.equals(curves[curves["network"] == net].drop(columns="network").reset_index(
            drop=True))  # fmt: skip


def test_parts_are_the_networks_or_all():
    assert part_names(["00", "01"], per_network=True) == ["net00", "net01"]
    assert part_names(["00", "01"], per_network=False) == ["all"]
    assert part_networks("net07") == [7] and part_networks("all") is None
    with pytest.raises(ValueError, match="not a part"):
        part_networks("net7")


def robot_tested(net: int) -> tuple[list[dict], np.ndarray]:
    rng = np.random.default_rng(net)
    rows = [
        {"network": net, "task": task, "success": bool(rng.random() < 0.5), "contact_time":
         float("nan") if k == 0 else rng.random(), "congruent": "" if k == 0 else True}
        for k, task in enumerate(["grasping", "categorisation", "categorisation"])
    ]  # fmt: skip
    return rows, rng.normal(size=(3, 4, 5))


def test_a_robot_part_all_holds_each_networks_rows_and_postures(tmp_path):
    nets = [12, 13, 14]
    tested = [robot_tested(net) for net in nets]
    (tmp_path / "all").mkdir()
    packed = [str(tmp_path / "all/trials.csv"), str(tmp_path / "all/states.npz")]
    write_robot_part(nets, tested, *packed)
    own = []
    for net, result in zip(nets, tested, strict=True):
        (tmp_path / f"net{net}").mkdir()
        own.append([str(tmp_path / f"net{net}/{f}") for f in ("trials.csv", "states.npz")])
        write_robot_part([net], [result], *own[-1])
    # the table is each network's file, one after another, under one header
    lines = [Path(t).read_text().splitlines() for t, _ in own]
    assert Path(packed[0]).read_text().splitlines() == lines[0] + [
        line for more in lines[1:] for line in more[1:]
    ]
    trials = load_robot_trials([packed[0]])
    alone = load_robot_trials([t for t, _ in own])
    assert trials.equals(alone) and list(trials["network"]) == [n for n in nets for _ in range(3)]
    for net in nets:
        mine = network_trials(trials, net)
        assert list(mine.index) == [0, 1, 2] and (mine["network"] == net).all()
    states, apart = load_robot_states([packed[1]]), load_robot_states([s for _, s in own])
    assert list(states) == list(apart) == nets
    for net, (_, qpos) in zip(nets, tested, strict=True):
        assert states[net].tobytes() == apart[net].tobytes() == qpos.tobytes()
    with pytest.raises(ValueError, match="rows of another network"):
        write_robot_part([12, 14], tested[:2], *packed)


def test_a_shared_phase_1_in_a_part_all_continues_each_network_to_its_bits_trained_whole(tmp_path):
    """Rule phase1's part `all` holds every network's phase 1 in one file; a run that continues
    from it (another cue timing and rate schedule, part `all`) gets the bits of that run trained
    whole: the steps rules phase1 and train run, through their files. A file lacking a
    network's array is refused with the advice that works."""
    from conftest import load_config

    from icub_affordance.learning.materials import synthetic_materials
    from icub_workflow.parts import load_phase1s
    from icub_workflow.steps import train_part, train_phase1s

    m = synthetic_materials()
    network = load_config()["network"] | {"networks": 4, "iterations": 600,
                                          "phase1_iterations": 300, "hidden": 12}  # fmt: skip
    owner = network | {"learning_rate_schedule": "constant", "categorisation_cue": "first_step"}
    other = network | {"learning_rate_schedule": "anneal", "categorisation_cue": "all_steps"}
    shared = tmp_path / "owner" / "all" / "phase1.npz"
    shared.parent.mkdir(parents=True)
    train_phase1s(m, owner, 7, "all", str(shared))
    assert sorted(load_phase1s([str(shared)])) == [0, 1, 2, 3]
    made = {}
    for name, phase1 in (("continued", [str(shared)]), ("whole", [])):
        part = tmp_path / name / "all"
        part.mkdir(parents=True)
        train_part(m, other, 7, "all", str(part / "curve.csv"), str(part / "weights.npz"), phase1)
        made[name] = part
    continued, whole = (load_weights([str(made[n] / "weights.npz")]) for n in made)
    assert [net for net, _ in continued] == [net for net, _ in whole] == [0, 1, 2, 3]
    for (_, a), (_, b) in zip(continued, whole, strict=True):
        for name in ("W1", "b1", "W2", "b2"):
            assert getattr(a, name).tobytes() == getattr(b, name).tobytes()
    curves = [(made[n] / "curve.csv").read_bytes() for n in made]
    assert curves[0] == curves[1]
    arrays = dict(np.load(shared))
    del arrays["net02_U"]
    np.savez(tmp_path / "partial.npz", **arrays)
    (tmp_path / "p" / "all").mkdir(parents=True)
    (tmp_path / "partial.npz").rename(tmp_path / "p" / "all" / "phase1.npz")
    with pytest.raises(ValueError, match=r"lacks \['net02_U'\]; delete it and rerun"):
        load_phase1s([str(tmp_path / "p" / "all" / "phase1.npz")])
