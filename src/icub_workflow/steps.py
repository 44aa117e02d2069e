"""What a training or measuring job does, for the scripts that run it: one run's part or run
per job (rules train, measures) or several runs in one process (the measured runs of a seed, rule
``measured``, a job per seed's group: one start-up, one load of the compiled trainer, for a
dozen runs).

Plain functions of paths and settings, without Snakemake, so that every rule that runs a step
runs the same code, and a run's files are the same bytes whichever rule made them.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from icub_affordance.files import atomic_path, load_npz, save_npz, write_text
from icub_affordance.learning.materials import Materials
from icub_affordance.learning.names import NamesConfig
from icub_affordance.learning.network import Weights
from icub_affordance.learning.training import TrainConfig, mapping_of, network_seed
from icub_affordance.learning.training import train_networks as train_side_by_side
from icub_affordance.learning.training import train_phase1s as train_phase1s_side_by_side
from icub_affordance.vocabulary import FORMS, TASKS
from icub_workflow.parts import (
    load_phase1s,
    load_weights,
    part_networks,
    write_part,
    write_phase1_part,
)

if TYPE_CHECKING:
    import pandas as pd


def make_soms(
    maps_path: str,
    objects: Sequence[str],
    soms: Mapping,
    seed: int,
    path: str,
    names: Mapping | None = None,
) -> None:
    """Train the three SOMs on the objects' visual maps (and their names, config ``names``, when
    used); save their activations and weights."""
    from icub_affordance.learning.maps import SOMConfig, active_units, train_soms

    maps = load_npz(maps_path, required=tuple(objects))
    visual = np.array([maps[o] for o in objects])
    trained = train_soms(visual, SOMConfig(**soms), seed, names and NamesConfig.of(names))
    arrays = {key: value for key, value in vars(trained).items() if value is not None}
    save_npz(path, objects=np.array(objects), tasks=np.array(TASKS), **arrays)
    for obj, act in zip(objects, trained.object_act, strict=True):
        print(f"{obj}: {active_units(act)} Object-map units above 0.5")


def curve_columns(curve: Mapping[str, np.ndarray], objects: Sequence[str]) -> dict[str, list]:
    """The learning curve's table, column by column: one row per kept iteration."""
    return {
        "iteration": curve["iteration"].tolist(),
        "phase": curve["phase"].tolist(),
        "task": [TASKS[task] for task in curve["task"].tolist()],
        "object": [objects[obj] for obj in curve["object"].tolist()],
        "sequence": curve["sequence"].tolist(),
        "rmse": curve["rmse"].tolist(),
    } | ({"form": [FORMS[form] for form in curve["form"].tolist()]} if "form" in curve else {})


def _networks(network: Mapping, nets: Sequence[int] | None, names: Mapping | None = None):
    """A run's training settings (with its ``names``, config ``names``), and each network asked
    for with its mapping: (net, mapping)."""
    settings = dict(network)
    n_networks = settings.pop("networks")
    # a confirmation's fresh networks start at this index (robot.confirmation); others at 0
    first = settings.pop("first_network", 0)
    nets = list(range(first, first + n_networks)) if nets is None else list(nets)
    if not first <= min(nets) <= max(nets) < first + n_networks:
        raise ValueError(
            f"networks {nets} asked for, but the run's are {first}..{first + n_networks - 1}"
        )
    # each network's mapping by its place in the run
    config = TrainConfig(**settings, names=names and NamesConfig.of(names))
    return config, [(net, mapping_of(net - first, n_networks)) for net in nets]


def _check_files(nets: Sequence, files: Sequence[str]) -> None:
    if len(files) != len(nets):
        raise ValueError(f"{len(nets)} networks, but {len(files)} files to write them to")


def train_phase1s(
    materials: Materials,
    network: Mapping,
    seed: int,
    part: str,
    phase1_path: str,
    names: Mapping | None = None,
) -> None:
    """Phase 1 of a run's part (icub_workflow.parts: every network, ``all``, or one), saved
    for the runs that continue from it: trained side by side, each the bits it has trained
    alone (``training.train_phase1s``)."""
    config, nets = _networks(network, part_networks(part), names)
    phase1s = train_phase1s_side_by_side(
        materials,
        config,
        [mapping for _, mapping in nets],
        [network_seed(seed, net) for net, _ in nets],
    )
    write_phase1_part([net for net, _ in nets], phase1s, phase1_path)


def _trained(
    materials: Materials,
    network: Mapping,
    seed: int,
    nets: Sequence[int] | None,
    phase1_files: Sequence[str],
    names: Mapping | None = None,
) -> tuple[list[int], list[tuple[Weights, dict[str, list]]]]:
    """Train a run's networks ``nets`` (all of them when None), each from its own seed or
    continued from its saved phase 1: each one's index, and its weights and curve's columns,
    checked finite."""
    config, nets = _networks(network, nets, names)
    starts = None
    if phase1_files:
        saved = load_phase1s(phase1_files)
        lacking = [net for net, _ in nets if net not in saved]
        if lacking:
            raise ValueError(f"no saved phase 1 of networks {lacking} in {list(phase1_files)}")
        starts = [saved[net] for net, _ in nets]
    # side by side in a vector's lanes, each network the bits it has trained alone
    trained = train_side_by_side(
        materials,
        config,
        [mapping for _, mapping in nets],
        [network_seed(seed, net) for net, _ in nets],
        starts,
    )
    done = []
    for (net, mapping), (weights, curve) in zip(nets, trained, strict=True):
        weights.check_finite(f"network {net:02d}")
        if not np.all(np.isfinite(curve["rmse"])):
            raise FloatingPointError(
                f"network {net:02d}: its training error became NaN (the outputs diverged). "
                "Lower config network.learning_rate or network.init_scale."
            )
        final = curve["rmse"][-500:].mean()
        print(f"network {net} (mapping {mapping}): final RMSE {final:.4f}")
        done.append((weights, curve_columns(curve, materials.objects)))
    return [net for net, _ in nets], done


def train_part(
    materials: Materials,
    network: Mapping,
    seed: int,
    part: str,
    curve_path: str,
    weights_path: str,
    phase1_files: Sequence[str] = (),
    names: Mapping | None = None,
) -> None:
    """Train a run's part (icub_workflow.parts: one network, ``net03``, or ``all``) and write
    its curve and weights."""
    nets, trained = _trained(materials, network, seed, part_networks(part), phase1_files, names)
    write_part(nets, trained, curve_path, weights_path)


def measure_networks(
    materials: Materials,
    network: Mapping,
    weights_files: Sequence[str],
    measures: Sequence[str],
    trials_path: str,
    json_path: str,
) -> None:
    """Score every test trial of a run's networks on each declared measure (``trials_path``),
    and each measure's per-network contrasts and per-object means (``json_path``)."""
    import pandas as pd

    from icub_affordance.analysis.reading_tests import analyse_measures
    from icub_affordance.trials.scores import measure_network

    n_networks = network["networks"]
    rows = []
    for net, weights in load_weights(weights_files):
        mapping = mapping_of(net, n_networks)
        rows += measure_network(
            materials, weights, net, mapping, network["categorisation_cue"], network["target"]
        )
    trials = pd.DataFrame(rows)
    with atomic_path(trials_path) as tmp:
        trials.to_csv(tmp, index=False, float_format="%.6f")
    trials = pd.read_csv(trials_path, keep_default_na=False)  # as readers see it
    result = analyse_measures(trials, list(measures))
    write_text(json_path, json.dumps(result, indent=2, sort_keys=True) + "\n")


def signature_tables(
    replications: Sequence[Mapping],
    signatures: Mapping,
    min_replications: int,
    outputs: Mapping[str, str],
    verdict_words: Callable[[pd.Series], list],
) -> None:
    """The human signatures' conditions on each replication's networks (``icub_affordance.
    signatures``): every noisy trial (``outputs["trials"]``), each signature's tests and verdict
    word (``summary``; ``verdict_words`` says its codes, as ``icub_workflow.book.words``, which the
    rule's script passes, so that a word's change reruns no model), and the errors apart
    (``errors``). A replication: its seed, its model inputs (maps, soms, demos), grip_distance,
    network settings and weights files. A test needs
    ``min_replications`` replications with an estimate (config ``confirmation``)."""
    import pandas as pd

    from icub_affordance.analysis.signature_tests import (
        SignatureConfig,
        errors,
        network_trials,
        summary,
    )
    from icub_affordance.learning.materials import load_materials

    config = SignatureConfig(**signatures, min_replications=min_replications)
    rows = []
    for rep in replications:
        materials = load_materials(rep["maps"], rep["soms"], rep["demos"], rep["grip_distance"])
        network = rep["network"]
        for net, weights in load_weights(rep["weights"]):
            mapping = mapping_of(net, network["networks"])
            cue, target = network["categorisation_cue"], network["target"]
            trials = network_trials(
                materials, weights, net, mapping, cue, target, config, rep["seed"]
            )
            rows += [{"replication": rep["seed"], **row} for row in trials]
        print(f"replication at seed {rep['seed']}: {len(rep['weights'])} networks tested")
    with atomic_path(outputs["trials"]) as tmp:
        pd.DataFrame(rows).to_csv(tmp, index=False, float_format="%.6g")
    trials = pd.read_csv(outputs["trials"])  # as readers see it: a recomputation from it agrees
    for name, table in {
        "summary": (found := summary(trials, config)).assign(
            verdict=verdict_words(found["verdict"])
        ),
        "errors": errors(trials, min_replications),
    }.items():
        with atomic_path(outputs[name]) as tmp:
            table.to_csv(tmp, index=False, float_format="%.6g")
