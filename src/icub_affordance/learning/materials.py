"""What a network learns from (``Materials``): the visual maps, the Goal map's activations, the
demonstrations and the servo targets, with the object axis in the same order everywhere; read from
the pipeline's vision, SOM and demonstration outputs (``load_materials``), or small stand-ins of
the same shapes for the tests and the benchmarks (``synthetic_materials``).

Apart from the training regime (``training``), which trains on any ``Materials``: the trials,
the robot and the figures read materials without the regime's code.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from icub_affordance.learning.grip_distance import GRIP_DISTANCES, scaled_grips, swap_scale
from icub_affordance.learning.names import name_patterns, shown
from icub_affordance.vocabulary import FORMS, TARGETS, TASKS, to_normalised


@dataclass(frozen=True)
class Materials:
    """Everything a network learns from, with the object axis in the same order everywhere."""

    objects: tuple[str, ...]
    grips: tuple[str, ...]
    visual: np.ndarray  # (objects, 100) the visual maps
    goal: np.ndarray  # (objects, tasks, 100) the Goal map's activations
    demos: np.ndarray  # (objects, grips, sequences, steps, 16) normalised postures
    commands: np.ndarray  # the same shape: the servo targets the demonstrator sent, 0-1
    #: a run with names (learning.names): each object's name as the network receives it
    #: (objects, units), None where no name reaches the network
    names: np.ndarray | None = None
    #: a run with names: the Goal map's activations when each form is shown
    #: (forms, objects, tasks, 100; vocabulary.FORMS); None: a run without names, image only
    goal_forms: np.ndarray | None = None

    def shown(self, form: str) -> Materials:
        """What the network receives when a trial shows ``form`` (vocabulary.FORMS) of its
        object: the visual map blanked unless the image is shown, the name's units 0 unless the
        name is, and the Goal map's activations for that form. Materials without names show
        the image alone."""
        if self.goal_forms is None:
            if form != "image":
                raise ValueError(
                    f"a run without names shows its objects' images alone, not {form!r}: "
                    "set config names.use to true for a run with names"
                )
            return self
        # a run whose names reach the maps but not the network has no name input: none shown
        names = np.zeros((len(self.visual), 0)) if self.names is None else self.names
        visual, names = shown(self.visual, names, form)
        return dataclasses.replace(
            self,
            visual=visual,
            goal=self.goal_forms[FORMS.index(form)],
            names=None if self.names is None else names,
            goal_forms=None,
        )

    def targets(self, target: str) -> np.ndarray:
        """What the motor outputs learn and are compared with (config ``network.target``): the
        sensed postures (the paper) or the servo targets."""
        if target not in TARGETS:
            raise ValueError(f"network.target must be one of {TARGETS}, not {target!r}")
        return self.demos if target == "sensed" else self.commands

    @property
    def n_train_sequences(self) -> int:
        return self.demos.shape[2] - 1  # the last sequence is held out


def synthetic_materials(seed: int = 0, units_per_name: int = 0) -> Materials:
    """Small stand-ins for the pipeline's outputs with the real shapes: what the tests and the
    training benchmark train on without running the pipeline; with ``units_per_name``, a run's
    names too (their Goal activations drawn after everything else)."""
    rng = np.random.default_rng(seed)
    start = rng.uniform(0.2, 0.8, 16)
    ends = rng.uniform(0, 1, (4, 2, 16))
    steps = np.linspace(0, 1, 10)[:, None]
    demos = np.empty((4, 2, 5, 10, 16))
    for o, g, s in np.ndindex(4, 2, 5):
        end = np.clip(ends[o, g] + rng.normal(0, 0.02, 16), 0, 1)
        demos[o, g, s] = start + steps * (end - start)
    m = Materials(
        objects=("big_ball", "small_ball", "big_cube", "small_cube"),
        grips=("power", "precision"),
        visual=rng.integers(0, 2, (4, 100)).astype(float),
        goal=rng.uniform(0, 1, (4, 2, 100)),
        demos=demos,
        commands=np.clip(demos + 0.05, 0, 1),
    )
    if not units_per_name:
        return m
    goal_forms = np.concatenate([m.goal[None], rng.uniform(0, 1, (len(FORMS) - 1, 4, 2, 100))])
    return dataclasses.replace(m, names=name_patterns(4, units_per_name), goal_forms=goal_forms)


def load_materials(visual_maps_path, soms_path, demos_path, grip_distance="natural") -> Materials:
    """Read the pipeline's vision, SOM and demonstration outputs into one consistent bundle;
    with ``grip_distance`` "swapped", the demonstrations (and the servo targets, by the same
    factors) with each object's grips at its partner's distance (``swapped_grips``)."""
    if grip_distance not in GRIP_DISTANCES:
        raise ValueError(f"grip_distance must be one of {GRIP_DISTANCES}, not {grip_distance!r}")
    from icub_affordance.files import load_npz

    demos = load_npz(demos_path, required=("angles", "commands_deg", "objects", "grips"))
    objects = tuple(demos["objects"].tolist())
    maps = load_npz(visual_maps_path, required=objects)
    soms = load_npz(soms_path, required=("goal_act", "objects"))
    if tuple(soms["objects"].tolist()) != objects:
        raise ValueError(
            f"{soms_path} and {demos_path} list different objects: delete both and rerun "
            "`snakemake -c2`."
        )
    angles = demos["angles"]
    # a servo target may lie beyond a joint's range (pressing against the stop); the sigmoid
    # outputs cannot, so they learn the range's end
    commands = np.clip(to_normalised(demos["commands_deg"]), 0.0, 1.0)
    if grip_distance == "swapped":
        scale = swap_scale(angles, objects)
        angles, commands = (scaled_grips(a, scale) for a in (angles, commands))
    with_names = "goal_act_forms" in soms  # a run with names (learning.maps.train_soms)
    return Materials(
        objects=objects,
        grips=tuple(demos["grips"].tolist()),
        visual=np.array([maps[o].ravel() for o in objects], dtype=float),
        goal=soms["goal_act"].reshape(len(objects), len(TASKS), -1),
        demos=angles,
        commands=commands,
        names=soms["name_input"] if with_names and soms["name_input"].size else None,
        goal_forms=(
            soms["goal_act_forms"].reshape(len(FORMS), len(objects), len(TASKS), -1)
            if with_names
            else None
        ),
    )
