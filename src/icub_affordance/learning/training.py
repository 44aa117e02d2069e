"""The paper's training regime (sections 2.3 and 3; book/notes.md, "The network and its training").

Phase 1: every iteration a grasping trial, target the object's natural grip. Phase 2: half the
iterations grasping trials, half categorisation trials whose target grip follows the network's
mapping of the object's category. Each iteration: one object and one of its training sequences
drawn at random, presented step by step with the demonstrated posture fed back.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from icub_affordance.learning.materials import Materials
from icub_affordance.learning.names import NamesConfig, form_schedule
from icub_affordance.learning.network import (
    N_GOAL,
    N_INPUT,
    N_VISUAL,
    TrainingState,
    Weights,
    distinct_contexts,
    train_together,
)
from icub_affordance.vocabulary import (
    AFTER_PHASE1,
    CATEGORISATION,
    CUES,
    FORMS,
    GRASPING,
    MAPPINGS,
    OBJECTS,
    SCHEDULES,
    TARGETS,
    TASKS,
)


@dataclass(frozen=True)
class TrainConfig:
    """A network's training settings (config key ``network``, where their values are given)."""

    hidden: int
    learning_rate: float
    iterations: int
    phase1_iterations: int
    init_scale: float  # initial weights uniform in +- this
    categorisation_cue: str  # one of CUES
    target: str  # one of TARGETS: what the motor outputs learn
    learning_rate_schedule: str = "constant"  # one of SCHEDULES
    curve_rows: int = 0  # the learning curve's rows at most (every k-th iteration); 0: all
    names: NamesConfig | None = None  # config ``names``: None, the paper's model without names

    def __post_init__(self) -> None:
        if self.target not in TARGETS:
            raise ValueError(f"network.target must be one of {TARGETS}, not {self.target!r}")
        if self.categorisation_cue not in CUES:
            raise ValueError(
                f"categorisation_cue must be one of {CUES}, not {self.categorisation_cue!r}"
            )
        if self.learning_rate_schedule not in SCHEDULES:
            raise ValueError(
                f"network.learning_rate_schedule must be one of {SCHEDULES}, "
                f"not {self.learning_rate_schedule!r}"
            )
        if not 0 <= self.phase1_iterations <= self.iterations:
            raise ValueError("phase1_iterations must lie between 0 and iterations")
        if self.curve_rows < 0:
            raise ValueError("network.curve_rows must be 0 (every iteration) or more")
        if (self.iterations - self.phase1_iterations) % 2:
            raise ValueError("phase 2 must have an even number of iterations (half of each task)")


def mapping_of(network: int, n_networks: int) -> str:
    """The first half of the networks learn mapping A, the second half mapping B (paper, sec. 3)."""
    return "A" if network < n_networks // 2 else "B"


def target_grip(obj: str, task: int, mapping: str) -> str:
    info = OBJECTS[obj]
    return info.natural_grip if task == GRASPING else MAPPINGS[mapping][info.category]


def context(m: Materials, obj: int, task: int, cue: str) -> np.ndarray:
    """Visual and goal input at each of the steps-1 transitions of a trial: (steps-1, 200), and
    the name's units after them where names reach the network (``Materials.names``).

    In a categorisation trial the Task map shows the categorisation pattern at the first step
    only (cue "first_step"), then the grasping pattern again; with cue "all_steps" it stays on. Both
    are readings of the paper (book/notes.md, "The network and its training"), run side by side.
    """
    if m.goal_forms is not None:
        raise ValueError(
            "a run with names shows its objects in forms: choose what a trial shows "
            "(Materials.shown) before building its input"
        )
    steps = m.demos.shape[3] - 1
    goal = slice(N_VISUAL, N_VISUAL + N_GOAL)
    ctx = np.empty((steps, goal.stop + (0 if m.names is None else m.names.shape[1])))
    ctx[:, :N_VISUAL] = m.visual[obj]
    ctx[:, goal] = m.goal[obj, GRASPING]
    if task == CATEGORISATION:
        cued = slice(0, 1) if cue == "first_step" else slice(0, steps)
        ctx[cued, goal] = m.goal[obj, CATEGORISATION]
    if m.names is not None:
        ctx[:, goal.stop :] = m.names[obj]
    return ctx


def schedule(config: TrainConfig, n_objects: int, n_sequences: int, rng: np.random.Generator):
    """(task, object, sequence) for every iteration: phase 1 grasping, phase 2 half and half."""
    phase2 = config.iterations - config.phase1_iterations
    tasks = np.concatenate(
        [
            np.full(config.phase1_iterations, GRASPING),
            rng.permutation(np.repeat([GRASPING, CATEGORISATION], phase2 // 2)),
        ]
    )
    objects = rng.integers(0, n_objects, config.iterations)
    sequences = rng.integers(0, n_sequences, config.iterations)
    return tasks, objects, sequences


def learning_rates(config: TrainConfig) -> np.ndarray:
    """Each iteration's learning rate (config ``network.learning_rate_schedule``,
    vocabulary.SCHEDULES).

    ``anneal``: the full rate through phase 1; over phase 2's n iterations the k-th (from 0)
    learns at rate * (n - k) / n, the full rate falling linearly to rate / n at the last.
    """
    rates = np.full(config.iterations, config.learning_rate)
    if config.learning_rate_schedule == "anneal":
        n = config.iterations - config.phase1_iterations
        rates[config.phase1_iterations :] *= np.arange(n, 0, -1) / n
    return rates


@dataclass(frozen=True)
class Phase1:
    """A network at the end of phase 1: its training state and phase 1's RMSE per iteration.
    Phase 1 is the same for settings that differ only after it (vocabulary.AFTER_PHASE1: the cue
    timing, the learning-rate schedule), so one training of it serves them all
    (:func:`train_phase1`, the rule ``phase1``). ``key`` names what phase 1 depends on
    (:func:`phase1_key`)."""

    key: str
    state: TrainingState
    rmse: np.ndarray

    #: the arrays a saved phase 1 holds (``arrays``)
    KEYS: ClassVar[tuple[str, ...]] = ("key", "done", "rmse", *TrainingState.KEYS)

    def arrays(self) -> dict[str, np.ndarray]:
        """Everything it holds, as named arrays (a file's contents: ``save``, and a part
        ``all`` of several networks, icub_workflow.parts)."""
        return {"key": np.array(self.key), "done": np.array(self.state.done), "rmse": self.rmse,
                **self.state.arrays}  # fmt: skip

    @classmethod
    def of_arrays(cls, arrays: dict[str, np.ndarray]) -> Phase1:
        """The phase 1 that ``arrays`` (all of ``KEYS``) hold."""
        arrays = dict(arrays)
        key, done, rmse = str(arrays.pop("key")), int(arrays.pop("done")), arrays.pop("rmse")
        return cls(key, TrainingState(arrays, done), rmse)

    def save(self, path) -> None:
        from icub_affordance.files import save_npz

        save_npz(path, **self.arrays())

    @classmethod
    def load(cls, path) -> Phase1:
        from icub_affordance.files import load_npz

        return cls.of_arrays(load_npz(path, required=cls.KEYS))


def phase1_key(m: Materials, config: TrainConfig, mapping: str, seed: int) -> str:
    """What phase 1 of a network depends on: its settings but those that act only after it
    (vocabulary.AFTER_PHASE1), its mapping, its seed and a digest of what it learns from."""
    settings = dataclasses.asdict(config)
    for after in AFTER_PHASE1:
        settings.pop(after)
    if config.names is None:
        settings.pop("names")  # the paper's model: the key it always had
    digest = hashlib.sha256()
    arrays = [m.visual, m.goal, m.demos, m.targets(config.target)]
    arrays += [a for a in (m.names, m.goal_forms) if a is not None]
    for array in arrays:
        digest.update(np.ascontiguousarray(array, dtype=np.float64).tobytes())
    what = settings | {"mapping": mapping, "seed": seed, "materials": digest.hexdigest()}
    return json.dumps(what, sort_keys=True)


@dataclass(frozen=True)
class _Training:
    """A network's training, laid out: initial weights, schedule, inputs and rates.

    The learning rule sees presentations, an object shown in a form (vocabulary.FORMS): form f
    of object o is presentation f * objects + o, and ``schedule`` names presentations; without
    names there is one form, the image, and a presentation is its object. ``objects`` and
    ``forms`` (None without names): what each iteration shows, for the learning curve."""

    weights: Weights
    schedule: tuple[np.ndarray, np.ndarray, np.ndarray]
    contexts: np.ndarray  # (presentations, tasks, steps-1, context)
    grips: np.ndarray  # (presentations, tasks)
    demos: np.ndarray  # (presentations, grips, sequences, steps, 16)
    targets: np.ndarray | None
    rates: np.ndarray
    objects: np.ndarray
    forms: np.ndarray | None


def _training(m: Materials, config: TrainConfig, mapping: str, seed: int) -> _Training:
    rng = np.random.default_rng(seed)
    n_input = N_INPUT + (0 if m.names is None else m.names.shape[1])
    weights = Weights.init(config.hidden, config.init_scale, rng, n_input)
    tasks, objects, sequences = schedule(config, len(m.objects), m.n_train_sequences, rng)
    forms, shown = None, [m]
    if config.names is not None:
        forms = form_schedule(config.names, config.phase1_iterations, config.iterations, rng)
        shown = [m.shown(form) for form in FORMS]
    n_objects, n_tasks = len(m.objects), len(TASKS)
    contexts = np.array(
        [
            [context(view, o, k, config.categorisation_cue) for k in range(n_tasks)]
            for view in shown
            for o in range(n_objects)
        ]
    )
    grips = np.array(
        [
            [m.grips.index(target_grip(m.objects[o], k, mapping)) for k in range(n_tasks)]
            for _ in shown
            for o in range(n_objects)
        ]
    )
    targets = None if config.target == "sensed" else m.targets(config.target)
    demos = m.demos
    if forms is not None:  # every form of an object shows its demonstrations
        demos = np.concatenate([m.demos] * len(shown))
        targets = None if targets is None else np.concatenate([targets] * len(shown))
    presentations = objects if forms is None else forms * n_objects + objects
    return _Training(
        weights, (tasks, presentations, sequences), contexts, grips, demos, targets,
        learning_rates(config), objects, forms,
    )  # fmt: skip


def _train_part(m: Materials, state: TrainingState, training: _Training, begin: int, end: int):
    """Train ``state`` on, over iterations begin..end-1; their RMSE."""
    part = tuple(a[begin:end] for a in training.schedule)
    return state.train(
        training.rates[begin:end], training.contexts, training.demos, training.grips, part,
        training.targets,
    )  # fmt: skip


def _first_phase(m: Materials, config: TrainConfig, training: _Training):
    """The state at the end of phase 1, from the initial weights, and phase 1's RMSE."""
    state = TrainingState.start(training.weights, training.contexts)
    return state, _train_part(m, state, training, 0, config.phase1_iterations)


def train_phase1(m: Materials, config: TrainConfig, mapping: str, seed: int) -> Phase1:
    """Phase 1 of one network, kept to be continued by :func:`train_network`."""
    state, rmse = _first_phase(m, config, _training(m, config, mapping, seed))
    return Phase1(phase1_key(m, config, mapping, seed), state, rmse)


def train_network(
    m: Materials, config: TrainConfig, mapping: str, seed: int, after: Phase1 | None = None
) -> tuple[Weights, dict[str, np.ndarray]]:
    """Train one network; return its weights and its learning curve (:func:`curve_every`).

    ``after``: its phase 1, trained already (:func:`train_phase1`, with settings that differ
    at most after phase 1): the network continues from it, to the same bits as when trained
    whole.
    """
    training = _training(m, config, mapping, seed)
    if after is None:
        state, first = _first_phase(m, config, training)
    elif after.key != phase1_key(m, config, mapping, seed):
        raise ValueError(
            "the saved phase 1 was trained with other settings, mapping, seed or materials than "
            "this network's: delete it and rerun `snakemake -c2` to train it again"
        )
    else:
        state, first = after.state.copy(), after.rmse  # the saved state stays as it was
    rest = _train_part(m, state, training, config.phase1_iterations, config.iterations)
    return state.weights(), _curve(config, training, np.concatenate([first, rest]))


def _curve(config: TrainConfig, training: _Training, rmse: np.ndarray) -> dict[str, np.ndarray]:
    """The learning curve's rows (:func:`curve_every`) from every iteration's RMSE."""
    tasks, _, sequences = training.schedule
    kept = np.arange(curve_every(config) - 1, config.iterations, curve_every(config))
    curve = {
        "iteration": kept + 1,
        "phase": np.where(kept < config.phase1_iterations, 1, 2),
        "task": tasks[kept],
        "object": training.objects[kept],
        "sequence": sequences[kept],
        "rmse": rmse[kept],
    }
    if training.forms is not None:
        curve["form"] = training.forms[kept]
    return curve


def _train_parts_together(
    m: Materials, states: list[TrainingState], trainings: list[_Training], begin: int, end: int
) -> list[np.ndarray]:
    """:func:`_train_part` for several networks of one run at once (``network.train_together``);
    the same bits, network by network."""
    return train_together(
        states,
        [t.rates[begin:end] for t in trainings],
        trainings[0].contexts,
        trainings[0].demos,
        [t.grips for t in trainings],
        [tuple(a[begin:end] for a in t.schedule) for t in trainings],
        trainings[0].targets,
    )


def _starts(trainings: list[_Training]) -> list[TrainingState]:
    """Each network's state before its first iteration (the run's distinct contexts found once:
    its networks share them)."""
    if not trainings:
        return []
    unique = distinct_contexts(trainings[0].contexts)
    return [TrainingState.start(t.weights, t.contexts, unique) for t in trainings]


def _check_together(mappings, seeds) -> None:
    if len(mappings) != len(seeds):
        raise ValueError(f"{len(mappings)} mappings for {len(seeds)} seeds: one of each a network")


def train_phase1s(
    m: Materials, config: TrainConfig, mappings: list[str], seeds: list[int]
) -> list[Phase1]:
    """:func:`train_phase1` of several networks of one run (network i: ``mappings[i]``,
    ``seeds[i]``), trained side by side: each the same bits as trained alone."""
    _check_together(mappings, seeds)
    trainings = [_training(m, config, a, seed) for a, seed in zip(mappings, seeds, strict=True)]
    states = _starts(trainings)
    rmse = _train_parts_together(m, states, trainings, 0, config.phase1_iterations)
    return [
        Phase1(phase1_key(m, config, a, seed), state, r)
        for a, seed, state, r in zip(mappings, seeds, states, rmse, strict=True)
    ]


def train_networks(
    m: Materials,
    config: TrainConfig,
    mappings: list[str],
    seeds: list[int],
    after: list[Phase1] | None = None,
) -> list[tuple[Weights, dict[str, np.ndarray]]]:
    """:func:`train_network` of several networks of one run (network i: ``mappings[i]``,
    ``seeds[i]``, and ``after[i]`` its phase 1 when given), trained side by side, eight or
    four at a time in a vector's lanes (``network.train_together``): each network's weights and
    learning curve are the bits :func:`train_network` gives it alone, in the order given."""
    _check_together(mappings, seeds)
    trainings = [_training(m, config, a, seed) for a, seed in zip(mappings, seeds, strict=True)]
    if after is None:
        states = _starts(trainings)
        firsts = _train_parts_together(m, states, trainings, 0, config.phase1_iterations)
    else:
        if len(after) != len(seeds):
            raise ValueError(f"{len(after)} phases 1 for {len(seeds)} networks")
        for phase1, a, seed in zip(after, mappings, seeds, strict=True):
            if phase1.key != phase1_key(m, config, a, seed):
                raise ValueError(
                    "the saved phase 1 was trained with other settings, mapping, seed or "
                    "materials than this network's: delete it and rerun `snakemake -c2` to "
                    "train it again"
                )
        states = [phase1.state.copy() for phase1 in after]  # the saved states stay as they were
        firsts = [phase1.rmse for phase1 in after]
    rests = _train_parts_together(m, states, trainings, config.phase1_iterations, config.iterations)
    return [
        (state.weights(), _curve(config, t, np.concatenate([first, rest])))
        for state, t, first, rest in zip(states, trainings, firsts, rests, strict=True)
    ]


def curve_every(config: TrainConfig) -> int:
    """The learning curve keeps every k-th iteration, k the smallest that leaves at most
    ``curve_rows`` rows (1, every iteration, when that is 0 or the training is short enough):
    a long training's curve at the resolution a figure can show, each row an iteration's own
    record. The full curve is ``curve_rows: 0``."""
    if config.curve_rows == 0:
        return 1
    return -(-config.iterations // config.curve_rows)


def network_seed(seed: int, network: int) -> int:
    """Each network's own seed, derived from the config's seed and its index."""
    return int(np.random.SeedSequence([seed, 1000 + network]).generate_state(1)[0])
