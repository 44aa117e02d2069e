"""The Jordan network of the paper (section 2.2, Figure 2), and how it learns.

Inputs: the 10x10 visual map (100), the 16 proprioceptive units (the arm's current normalised
posture) and the 10x10 Goal map (100); 10 sigmoid hidden units; 16 sigmoid motor outputs, the
posture at the next time step. The recurrence is Jordan's: the motor output comes back as the
next proprioceptive input (in closed loop; training feeds the demonstrated posture back).

Learning is online back-propagation of the squared error, one weight update per time step, no
momentum. Two implementations of the same arithmetic: ``torch_reference.JordanNet`` (torch, the
reference, trained the plain way by autograd) and :func:`train_online` here (hand-derived
gradients in a compiled loop, ``kernel``: a network in a fraction of a second). A test
holds them equal within 1e-10.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

N_VISUAL = 100
N_PROPRIO = 16
N_GOAL = 100
N_INPUT = N_VISUAL + N_PROPRIO + N_GOAL
N_OUTPUT = 16
# Input layout: [visual (100), proprioception (16), goal (100)], as in Figure 2; a run with
# names (learning.names) appends the name's units after the goal.
PROPRIO = slice(N_VISUAL, N_VISUAL + N_PROPRIO)


def context_columns(n_input: int) -> np.ndarray:
    """The input columns a trial's context fills (every input but proprioception), for a network
    of ``n_input`` inputs: the visual and goal inputs for the paper's 216."""
    return np.r_[0:N_VISUAL, N_VISUAL + N_PROPRIO : n_input]


@dataclass
class Weights:
    """The network's parameters (float64), stored without pickle as a .npz."""

    W1: np.ndarray  # (hidden, 216)
    b1: np.ndarray  # (hidden,)
    W2: np.ndarray  # (16, hidden)
    b2: np.ndarray  # (16,)

    @classmethod
    def init(
        cls, hidden: int, scale: float, rng: np.random.Generator, n_input: int = N_INPUT
    ) -> Weights:
        """Uniform in +- ``scale``; ``n_input`` inputs (more than the paper's 216 with names)."""
        return cls(
            W1=rng.uniform(-scale, scale, (hidden, n_input)),
            b1=rng.uniform(-scale, scale, hidden),
            W2=rng.uniform(-scale, scale, (N_OUTPUT, hidden)),
            b2=rng.uniform(-scale, scale, N_OUTPUT),
        )

    def copy(self) -> Weights:
        return Weights(self.W1.copy(), self.b1.copy(), self.W2.copy(), self.b2.copy())

    def check_finite(self, name: str) -> None:
        """Refuse weights holding NaN or infinity (diverged training), naming the network: its
        outputs would be NaN, and every statistic after them meaningless."""
        bad = [key for key, value in self.as_dict().items() if not np.all(np.isfinite(value))]
        if bad:
            raise FloatingPointError(
                f"{name}: weights {bad} are not finite (NaN or infinite), so its outputs are NaN: "
                "the training diverged. Lower config network.learning_rate or network.init_scale."
            )

    def as_dict(self) -> dict[str, np.ndarray]:
        return {"W1": self.W1, "b1": self.b1, "W2": self.W2, "b2": self.b2}


def sigmoid(z: np.ndarray) -> np.ndarray:
    # SciPy's special functions are imported where used: every Snakemake start reads this
    # module (the config's measures are named in the package), and they take a quarter second
    from scipy.special import expit

    return expit(z)


@dataclass
class TrainingState:
    """A network part-way through its online training: what the compiled loop carries from one
    iteration to the next (``kernel.train_lanes4``). Training a schedule in parts, from
    a saved state, gives the same bits as in one call: so two settings that differ only after
    phase 1 (the learning-rate schedule) can share phase 1's training.

    ``arrays``: ``W1cT`` the context weights as they started (200, hidden), ``W1pT``, ``b1``,
    ``W2T``, ``b2`` the other weights now, ``unique`` the distinct contexts, ``U``, ``moved``,
    ``gram`` the context part, ``lr_p``, ``d_hid``, ``lr_h``, ``d_out`` the last step's update
    not yet made. ``done``: the iterations trained.
    """

    arrays: dict[str, np.ndarray]
    done: int = 0

    #: the arrays a state holds
    KEYS: ClassVar[tuple[str, ...]] = (
        "W1cT", "W1pT", "b1", "W2T", "b2", "unique", "U", "moved", "gram", "lr_p", "d_hid",
        "lr_h", "d_out",
    )  # fmt: skip

    @classmethod
    def start(
        cls, weights: Weights, contexts: np.ndarray, unique: np.ndarray | None = None
    ) -> TrainingState:
        """The state before the first iteration, for these initial weights and the contexts
        (objects, tasks, steps-1, 200) the training will show; ``unique``: their distinct
        contexts, when known already (networks of one run share them)."""
        from icub_affordance.learning.kernel import project_contexts

        if unique is None:
            unique = _distinct_contexts(contexts)[0]
        unique = np.ascontiguousarray(unique)
        hidden = weights.W1.shape[0]
        arrays = {
            "W1cT": np.ascontiguousarray(weights.W1[:, context_columns(weights.W1.shape[1])].T),
            "W1pT": np.ascontiguousarray(weights.W1[:, PROPRIO].T),
            "b1": weights.b1.copy(),
            "W2T": np.ascontiguousarray(weights.W2.T),
            "b2": weights.b2.copy(),
            "unique": unique,
            "U": np.zeros((len(unique), hidden)),
            "moved": np.zeros((len(unique), hidden)),
            "gram": np.zeros((len(unique), len(unique))),
            "lr_p": np.zeros(N_PROPRIO),
            "d_hid": np.zeros(hidden),
            "lr_h": np.zeros(hidden),
            "d_out": np.zeros(N_OUTPUT),
        }
        project_contexts(arrays["W1cT"], unique, arrays["U"], arrays["gram"])
        return cls(arrays)

    def copy(self) -> TrainingState:
        return TrainingState({k: v.copy() for k, v in self.arrays.items()}, self.done)

    def train(
        self,
        learning_rate: float | np.ndarray,
        contexts: np.ndarray,
        demos: np.ndarray,
        grips: np.ndarray,
        schedule: tuple[np.ndarray, np.ndarray, np.ndarray],
        targets: np.ndarray | None = None,
    ) -> np.ndarray:
        """Train on, in place, over ``schedule`` (see :func:`train_online` for the arguments);
        return each of its iterations' RMSE, measured before that sequence's updates. The one
        learning rule, the lanes kernel's (:func:`train_together`, this network in a group of
        its own)."""
        return train_together([self], [learning_rate], contexts, demos, [grips], [schedule],
                              targets)[0]  # fmt: skip

    def weights(self) -> Weights:
        """The weights the training has reached (the state itself can train on)."""
        from icub_affordance.learning.kernel import finish

        a = {k: v.copy() for k, v in self.arrays.items()}
        finish(
            a["W1cT"], a["unique"], a["moved"], a["W1pT"], a["W2T"], a["lr_p"], a["d_hid"],
            a["lr_h"], a["d_out"],
        )  # fmt: skip
        hidden = a["b1"].shape[0]
        n_input = N_PROPRIO + a["W1cT"].shape[0]
        W1 = np.empty((hidden, n_input))
        W1[:, context_columns(n_input)] = a["W1cT"].T
        W1[:, PROPRIO] = a["W1pT"].T
        return Weights(W1, a["b1"], np.ascontiguousarray(a["W2T"].T), a["b2"])


def _demos_and_targets(demos, targets) -> tuple[np.ndarray, np.ndarray]:
    """The demonstrations and the targets the output learns (the demonstrations where none are
    given), as the kernels read them."""
    demos = np.ascontiguousarray(demos, dtype=np.float64)
    if targets is None:
        return demos, demos
    if targets.shape != demos.shape:
        raise ValueError(f"targets {targets.shape} and demos {demos.shape} differ in shape")
    return demos, np.ascontiguousarray(targets, dtype=np.float64)


def _run_ends(contexts: np.ndarray) -> np.ndarray:
    """At each transition (objects, tasks, steps-1), the end of the run of equal contexts it is
    in (:func:`equal_runs`)."""
    run_ends = np.empty(contexts.shape[:3], dtype=np.int64)
    for key in np.ndindex(*contexts.shape[:2]):
        for start, end in equal_runs(contexts[key]):
            run_ends[key][start:end] = end
    return run_ends


def lane_groups(n: int) -> list[tuple[list[int], int]]:
    """How :func:`train_together` trains networks 0..n-1: groups and the kernel's lanes for each.
    Eight at a time while five or more are left, then four (a group of one to three filled with
    copies). Eight lanes train in about 1.3 times four lanes' time, so five networks go to eight
    lanes rather than to four and one. A network alone goes to four lanes too: about 2.3 times
    the time of a kernel for one network (0.08 CPU s for the paper's 12,000 iterations; 3.4
    times for a wide robot network), the price of one learning rule written once instead of
    twice (docs/speed.md)."""
    groups, start = [], 0
    while start < n:
        left = n - start
        lanes = 8 if left >= 5 else 4
        groups.append((list(range(start, start + min(lanes, left))), lanes))
        start += min(lanes, left)
    return groups


# A lane's arrays in the lanes kernels (``kernel.train_lanes4``...) from a state's:
# (key, transposed)
_LANE_ARRAYS = (
    ("W1pT", True), ("b1", False), ("W2T", True), ("b2", False), ("U", False), ("moved", False),
    ("lr_p", False), ("d_hid", False), ("lr_h", False), ("d_out", False),
)  # fmt: skip


def train_together(
    states: list[TrainingState],
    learning_rates: list[float | np.ndarray],
    contexts: np.ndarray,
    demos: np.ndarray,
    grips: list[np.ndarray],
    schedules: list[tuple[np.ndarray, np.ndarray, np.ndarray]],
    targets: np.ndarray | None = None,
) -> list[np.ndarray]:
    """Train several networks on, in place, side by side: each state over its own schedule
    (all of one length) with its own learning rates and target grips, the contexts, demos and
    targets shared (see :func:`train_online` for the arguments). Returns each state's RMSE per
    iteration, as :meth:`TrainingState.train` would.

    Every state ends with the bits :meth:`TrainingState.train` gives it alone: the networks are
    trained eight or four at a time (:func:`lane_groups`), network l of a group in lane l of 8-
    or 4-wide vectors, each lane doing its network's operations in its network's order
    (``kernel.train_lanes8``, ``train_lanes4``). A short group is filled with copies of
    its first network, trained and dropped.
    """
    from icub_affordance.learning import kernel

    n = len(states)
    if not (len(learning_rates) == len(grips) == len(schedules) == n):
        raise ValueError("one learning rate (or schedule of rates), grips and schedule per state")
    if n == 0:
        return []
    contexts = np.ascontiguousarray(contexts, dtype=np.float64)
    unique, context_ids = _distinct_contexts(contexts)
    first = states[0].arrays
    for state in states:
        if not np.array_equal(unique, state.arrays["unique"]):
            raise ValueError(
                "these contexts are not the ones the training started with: a state continues "
                "only the training it was made by (same maps, same cue timing)"
            )
        if state.arrays["b1"].shape != first["b1"].shape or not np.array_equal(
            state.arrays["gram"], first["gram"]
        ):
            raise ValueError("networks trained together need the same hidden size and contexts")
    run_ends = _run_ends(contexts)
    demos, targets = _demos_and_targets(demos, targets)
    schedules = [tuple(np.asarray(a, dtype=np.int64) for a in sch) for sch in schedules]
    length = len(schedules[0][0])
    if any(len(a) != length for sch in schedules for a in sch):
        raise ValueError("networks trained together need schedules of one length")
    rates = []
    for rate in learning_rates:
        rate = np.asarray(rate, dtype=np.float64)
        if rate.ndim and rate.shape != (length,):
            raise ValueError(f"{rate.shape} learning rates for a schedule of {length} iterations")
        rates.append(np.broadcast_to(rate, (length,)))
    rmse = []  # in the networks' order, as the groups come
    for group, width in lane_groups(n):
        lanes = group + [group[0]] * (width - len(group))  # a short group: copies of its first

        def stacked(arrays, lanes=lanes):
            return np.ascontiguousarray(np.stack([arrays[i] for i in lanes], axis=-1))

        a = {
            key: stacked([s.arrays[key].T if transposed else s.arrays[key] for s in states])
            for key, transposed in _LANE_ARRAYS
        }
        out = np.empty((length, width))
        getattr(kernel, f"train_lanes{width}")(
            a["W1pT"], a["b1"], a["W2T"], a["b2"], a["U"], a["moved"], first["gram"],
            a["lr_p"], a["d_hid"], a["lr_h"], a["d_out"], stacked(rates), context_ids, run_ends,
            demos, targets, stacked([np.asarray(g, dtype=np.int64) for g in grips]),
            stacked([sch[0] for sch in schedules]), stacked([sch[1] for sch in schedules]),
            stacked([sch[2] for sch in schedules]), out,
        )  # fmt: skip
        for lane, i in enumerate(group):
            arrays = states[i].arrays
            for key, transposed in _LANE_ARRAYS:
                value = a[key][..., lane]
                arrays[key][...] = value.T if transposed else value
            states[i].done += length
            rmse.append(out[:, lane].copy())
    return rmse


def distinct_contexts(contexts: np.ndarray) -> np.ndarray:
    """The distinct contexts (in sorted order) of contexts (objects, tasks, steps-1, 200)."""
    return _distinct_contexts(np.ascontiguousarray(contexts, dtype=np.float64))[0]


def _distinct_contexts(contexts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The distinct contexts (in sorted order) and which one each transition shows."""
    unique, ids = np.unique(contexts.reshape(-1, contexts.shape[-1]), axis=0, return_inverse=True)
    return unique, ids.reshape(contexts.shape[:3]).astype(np.int64)


def train_online(
    weights: Weights,
    learning_rate: float | np.ndarray,
    contexts: np.ndarray,
    demos: np.ndarray,
    grips: np.ndarray,
    schedule: tuple[np.ndarray, np.ndarray, np.ndarray],
    targets: np.ndarray | None = None,
) -> tuple[Weights, np.ndarray]:
    """Online back-propagation over a whole schedule, one update per time step (teacher forced).

    ``contexts`` (objects, tasks, steps-1, 200): the visual and goal input at each transition;
    ``demos`` (objects, grips, sequences, steps, 16): the demonstrated postures, fed back as
    proprioception; ``targets`` (the same shape): what the motor outputs learn, ``demos``
    itself when None (the paper: the network outputs the next posture); ``grips``
    (objects, tasks): the target grip of each trial kind; ``schedule``: the (tasks, objects,
    sequences) of every iteration; ``learning_rate`` one rate for all of it, or one per
    iteration (a schedule, :func:`icub_affordance.learning.training.learning_rates`). Returns
    the trained weights (``weights`` is left as it was) and each iteration's RMSE, measured
    before that sequence's updates.

    The loop runs compiled (:mod:`icub_affordance.learning.kernel`, imported only here and in
    :class:`TrainingState` so that only training pays for numba); the torch loop of
    :mod:`icub_affordance.learning.torch_reference` is the reference it is tested against.
    """
    state = TrainingState.start(weights, contexts)
    rmse = state.train(learning_rate, contexts, demos, grips, schedule, targets)
    return state.weights(), rmse


def equal_runs(context: np.ndarray) -> list[tuple[int, int]]:
    """Maximal runs [start, end) of consecutive steps with the same visual and goal input."""
    runs, start = [], 0
    for t in range(1, len(context) + 1):
        if t == len(context) or not np.array_equal(context[t], context[start]):
            runs.append((start, t))
            start = t
    return runs


def network_step(
    weights: Weights, context: np.ndarray, proprio: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """One forward step: the maps' input ``context`` (..., 200) and the posture (..., 16) in,
    the next posture (..., 16) and the hidden activity out."""
    x = np.concatenate([context[..., :N_VISUAL], proprio, context[..., N_VISUAL:]], axis=-1)
    h = sigmoid(x @ weights.W1.T + weights.b1)
    return sigmoid(h @ weights.W2.T + weights.b2), h


def run_closed_loop(
    weights: Weights, context: np.ndarray, start: np.ndarray, teacher: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Run many trials at once. ``context`` (trials, steps-1, 200); ``start`` (trials, 16).

    Closed loop (``teacher`` None): each output is the next proprioceptive input, as the robot
    would move. Teacher forced: the proprioceptive input is ``teacher`` (trials, steps, 16).
    Returns the outputs (trials, steps-1, 16) and hidden activity (trials, steps-1, hidden).
    """
    trials, steps, _ = context.shape
    proprio = start
    outputs, hiddens = [], []
    for t in range(steps):
        if teacher is not None:
            proprio = teacher[:, t]
        y, h = network_step(weights, context[:, t], proprio)
        outputs.append(y)
        hiddens.append(h)
        proprio = y
    return np.stack(outputs, axis=1), np.stack(hiddens, axis=1)
