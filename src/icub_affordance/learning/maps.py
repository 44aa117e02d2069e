"""The three Kohonen maps of the paper (section 2.2): Object, Task and Goal.

The maps themselves are MiniSom's. What the network receives from a map is this project's
choice, stated here and in the book: a Gaussian bump on the map centred on the winning unit.
For the Object map its width grows with the square root of the input's activity (its sum: the
number of edge cells of the binary visual map), so a large object (more edge cells, a longer
outline) lights up a larger cluster than a small one (paper section 2.3, after Caligiore et al.
2008). The width is computed from the input alone; nothing is keyed by the object's name. The Task
map's bump has a fixed width. The Goal map's is a reading (book/notes.md, "The maps"; config
``soms.goal_response``): ``fixed``, the Task map's fixed width, or ``grows``, the Object map's rule
applied to the Goal map's input (the Object and Task maps' activations), so a large object's Goal
cluster is larger too.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from minisom import MiniSom

from icub_affordance.learning.names import NamesConfig, name_patterns, shown
from icub_affordance.vocabulary import FORMS, GOAL_RESPONSES, TASKS


@dataclass(frozen=True)
class SOMConfig:
    """The maps' settings (config key ``soms``, where their values and meaning are given)."""

    grid: int  # each map is grid x grid units
    iterations: int  # training presentations per map
    sigma: float  # initial neighbourhood width (units), decays during training
    learning_rate: float
    object_width_per_edge: float  # object bump width = this * sqrt(edge cells), units
    bump_sigma: float  # width of the Task bump, and of the Goal bump when it is fixed, units
    task_pattern_size: int  # length of the random binary task patterns
    goal_response: str  # one of GOAL_RESPONSES: the Goal bump's width fixed or growing
    #: a growing bump's centre moved off the map's edge so that its cluster stays whole
    keep_whole: bool = False

    def __post_init__(self) -> None:
        if self.goal_response not in GOAL_RESPONSES:
            raise ValueError(
                f"goal_response must be one of {GOAL_RESPONSES}, not {self.goal_response!r}"
            )


def train_som(data: np.ndarray, config: SOMConfig, seed: int) -> MiniSom:
    som = MiniSom(
        config.grid,
        config.grid,
        data.shape[1],
        sigma=config.sigma,
        learning_rate=config.learning_rate,
        random_seed=seed,
    )
    som.random_weights_init(data)
    som.train(data, config.iterations, random_order=True)
    return som


def bump(grid: int, centre: tuple[int, int], sigma: float) -> np.ndarray:
    """A Gaussian of the map distance to ``centre``: the activation pattern a map sends on. A
    width of 0 is the winner alone (no size reaches the map's output)."""
    if sigma <= 0:
        out = np.zeros((grid, grid))
        out[tuple(centre)] = 1.0
        return out
    rows, cols = np.mgrid[0:grid, 0:grid]
    d2 = (rows - centre[0]) ** 2 + (cols - centre[1]) ** 2
    return np.exp(-d2 / (2.0 * sigma**2))


def kept_whole(grid: int, centre: tuple[int, int], sigma: float) -> tuple[int, int]:
    """``centre`` moved towards the middle of the map just far enough that every unit a bump of
    ``sigma`` lifts above one half lies on the map (a winner at the edge would cut its cluster
    to a half or a quarter); the middle if the cluster is wider than the map."""
    radius = sigma * np.sqrt(2.0 * np.log(2.0))  # units above one half: distance < radius
    reach = max(int(np.ceil(radius)) - 1, 0)
    low, high = reach, grid - 1 - reach
    if low > high:
        return ((grid - 1) // 2, (grid - 1) // 2)
    return (int(min(max(centre[0], low), high)), int(min(max(centre[1], low), high)))


def growing_activation(som: MiniSom, x: np.ndarray, config: SOMConfig) -> np.ndarray:
    """The Object map's rule: a bump at the winner whose width is ``object_width_per_edge`` times
    the square root of the input's activity (its sum; at least 1); with ``keep_whole``, centred
    off the map's edge (``kept_whole``)."""
    x = np.asarray(x, dtype=float).ravel()
    width = config.object_width_per_edge * np.sqrt(max(x.sum(), 1.0))
    centre = som.winner(x)
    if config.keep_whole:
        centre = kept_whole(config.grid, centre, width)
    return bump(config.grid, centre, width)


def object_activation(som: MiniSom, visual_map: np.ndarray, config: SOMConfig) -> np.ndarray:
    """The Object map's response: a bump at the winner, as wide as the input is active (for the
    binary visual map, its activity is its number of edge cells)."""
    return growing_activation(som, visual_map, config)


def fixed_activation(som: MiniSom, x: np.ndarray, config: SOMConfig) -> np.ndarray:
    return bump(config.grid, som.winner(np.asarray(x, dtype=float)), config.bump_sigma)


def goal_activation(som: MiniSom, x: np.ndarray, config: SOMConfig) -> np.ndarray:
    """The Goal map's response to its input (the Object and Task maps' activations, joined), by
    the reading ``config.goal_response``: a fixed-width bump, or the Object map's growing one."""
    if config.goal_response == "grows":
        return growing_activation(som, x, config)
    return fixed_activation(som, x, config)


@dataclass
class SOMs:
    """The three trained maps' outputs, everything the network and the figures need."""

    object_act: np.ndarray  # (objects, grid, grid)
    task_act: np.ndarray  # (tasks, grid, grid)
    goal_act: np.ndarray  # (objects, tasks, grid, grid)
    task_patterns: np.ndarray  # (tasks, task_pattern_size) the random task inputs
    object_weights: np.ndarray  # MiniSom weights (grid, grid, 100)
    task_weights: np.ndarray
    goal_weights: np.ndarray
    object_winners: np.ndarray  # (objects, 2)
    goal_winners: np.ndarray  # (objects, tasks, 2)
    # a run with names (learning.names); the fields above are then the image's
    name_patterns: np.ndarray | None = None  # (objects, units) each object's name
    name_input: np.ndarray | None = None  # the names the network receives: (objects, 0) if none
    object_act_forms: np.ndarray | None = None  # (forms, objects, grid, grid), vocabulary.FORMS
    goal_act_forms: np.ndarray | None = None  # (forms, objects, tasks, grid, grid)


def object_inputs(flat: np.ndarray, names: NamesConfig | None) -> dict[str, np.ndarray]:
    """The Object map's input for each form a trial may show (vocabulary.FORMS): the visual map,
    blanked unless the image is shown, and with the ``object_map`` route the name beside it,
    0 unless the name is shown. Without names: the image alone, the visual map (the paper)."""
    if names is None:
        return {"image": flat}
    patterns = name_patterns(len(flat), names.units_per_name)
    inputs = {}
    for form in FORMS:
        visual, name = shown(flat, patterns, form)
        inputs[form] = np.hstack([visual, name]) if "object_map" in names.routes else visual
    return inputs


def train_soms(
    visual_maps: np.ndarray, config: SOMConfig, seed: int, names: NamesConfig | None = None
) -> SOMs:
    """Train Object, Task and Goal maps in that order (the Goal map learns from the other two);
    with ``names``, the Object and Goal maps learn from the forms training shows (image, name,
    both) and respond to each."""
    rng = np.random.default_rng([seed, 1])
    flat = visual_maps.reshape(len(visual_maps), -1).astype(float)
    inputs = object_inputs(flat, names)
    trained = names.trained_forms if names else ("image",)
    object_som = train_som(np.concatenate([inputs[f] for f in trained]), config, seed + 11)
    object_forms = {
        form: np.array([object_activation(object_som, x, config) for x in shown_inputs])
        for form, shown_inputs in inputs.items()
    }
    object_act = object_forms["image"]

    # the paper's task inputs: a pattern for grasping and a "new (random)" one for categorising
    patterns = rng.integers(0, 2, size=(len(TASKS), config.task_pattern_size)).astype(float)
    while np.array_equal(patterns[0], patterns[1]):
        patterns[1] = rng.integers(0, 2, size=config.task_pattern_size)
    task_som = train_som(patterns, config, seed + 12)
    task_act = np.array([fixed_activation(task_som, p, config) for p in patterns])

    goal_forms = {
        form: np.array([np.concatenate([o.ravel(), t.ravel()]) for o in act for t in task_act])
        for form, act in object_forms.items()
    }
    goal_inputs = goal_forms["image"]
    goal_som = train_som(np.concatenate([goal_forms[f] for f in trained]), config, seed + 13)
    goal_act = np.array([goal_activation(goal_som, g, config) for g in goal_inputs])
    n_obj, n_task = len(object_act), len(task_act)
    extra = {}
    if names is not None:
        spoken = name_patterns(n_obj, names.units_per_name)
        extra = {
            "name_patterns": spoken,
            "name_input": spoken if "network" in names.routes else spoken[:, :0],
            "object_act_forms": np.array([object_forms[f] for f in FORMS]),
            "goal_act_forms": np.array(
                [[goal_activation(goal_som, g, config) for g in goal_forms[f]] for f in FORMS]
            ).reshape(len(FORMS), n_obj, n_task, config.grid, config.grid),
        }
    return SOMs(
        **extra,
        object_act=object_act,
        task_act=task_act,
        goal_act=goal_act.reshape(n_obj, n_task, config.grid, config.grid),
        task_patterns=patterns,
        object_weights=object_som.get_weights(),
        task_weights=task_som.get_weights(),
        goal_weights=goal_som.get_weights(),
        object_winners=np.array([object_som.winner(x) for x in inputs["image"]]),
        goal_winners=np.array([goal_som.winner(g) for g in goal_inputs]).reshape(n_obj, n_task, 2),
    )


def active_units(activation: np.ndarray, threshold: float = 0.5) -> int:
    """How many units of a map respond above ``threshold`` (the size of its cluster)."""
    return int((activation > threshold).sum())
