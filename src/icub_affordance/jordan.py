"""The Jordan network of the paper (section 2.2, Figure 2), and how it learns.

Inputs: the 10x10 visual map (100), the 16 proprioceptive units (the arm's current normalised
posture) and the 10x10 Goal map (100); 10 sigmoid hidden units; 16 sigmoid motor outputs, the
posture at the next time step. The recurrence is Jordan's: the motor output comes back as the
next proprioceptive input (in closed loop; training feeds the demonstrated posture back).

Learning is online back-propagation of the squared error, one weight update per time step, no
momentum. Two implementations of the same arithmetic: ``jordan_torch.JordanNet`` (torch, the
reference, trained the plain way by autograd) and ``OnlineTrainer`` here (NumPy, hand-derived
gradients, fast enough to train 12 networks in seconds). A test holds them equal.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.special import expit

N_VISUAL = 100
N_PROPRIO = 16
N_GOAL = 100
N_INPUT = N_VISUAL + N_PROPRIO + N_GOAL
N_OUTPUT = 16
# Input layout: [visual (100), proprioception (16), goal (100)], as in Figure 2.
PROPRIO = slice(N_VISUAL, N_VISUAL + N_PROPRIO)


@dataclass
class Weights:
    """The network's parameters (float64), stored without pickle as a .npz."""

    W1: np.ndarray  # (hidden, 216)
    b1: np.ndarray  # (hidden,)
    W2: np.ndarray  # (16, hidden)
    b2: np.ndarray  # (16,)

    @classmethod
    def init(cls, hidden: int, scale: float, rng: np.random.Generator) -> Weights:
        return cls(
            W1=rng.uniform(-scale, scale, (hidden, N_INPUT)),
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
    return expit(z)


class OnlineTrainer:
    """Online back-propagation with hand-derived gradients; the same arithmetic as the torch loop.

    Made fast by doing less, not by approximating: the biases ride along as weights on a constant
    input of 1, the updates are in-place BLAS rank-1 updates, and the visual and goal inputs,
    which stay the same from step to step within a sequence (the goal map changes only when the
    task cue does), enter incrementally: after a step's update W1c -= lr * dh c^T the product
    W1c @ c changes by -lr * dh * (c . c), and W1c itself is updated once per run of equal inputs.
    """

    def __init__(self, weights: Weights, learning_rate: float) -> None:
        hidden = weights.W1.shape[0]
        ctx_cols = np.r_[0:N_VISUAL, N_VISUAL + N_PROPRIO : N_INPUT]
        self.lr = learning_rate
        self.W1c = np.asfortranarray(weights.W1[:, ctx_cols])  # (hidden, 200)
        self.W1pb = np.asfortranarray(np.column_stack([weights.W1[:, PROPRIO], weights.b1]))
        self.W2b = np.asfortranarray(np.column_stack([weights.W2, weights.b2]))
        self._h1 = np.ones(hidden + 1)  # hidden activity and a constant 1 for the bias

    @property
    def w(self) -> Weights:
        hidden = self.W1c.shape[0]
        W1 = np.empty((hidden, N_INPUT))
        W1[:, :N_VISUAL] = self.W1c[:, :N_VISUAL]
        W1[:, PROPRIO] = self.W1pb[:, :N_PROPRIO]
        W1[:, N_VISUAL + N_PROPRIO :] = self.W1c[:, N_VISUAL:]
        return Weights(W1, self.W1pb[:, -1].copy(), self.W2b[:, :-1].copy(), self.W2b[:, -1].copy())

    def train_sequence(
        self, context: np.ndarray, postures: np.ndarray, runs: list[tuple[int, int]] | None = None
    ) -> float:
        """One sequence, one update per step; ``runs`` (from :func:`equal_runs`) may be cached."""
        from scipy.linalg.blas import dger  # here, not at the top: only training needs it

        lr, h1 = self.lr, self._h1
        n_hidden = len(h1) - 1
        W1c, W1pb, W2b = self.W1c, self.W1pb, self.W2b  # updated in place by dger below
        W2h_T = W2b[:, :n_hidden].T  # a view: it follows W2b's updates
        proprio = np.column_stack([postures, np.ones(len(postures))])  # [p, 1] per step
        sq_error = 0.0
        steps = len(postures) - 1
        for t, end in runs if runs is not None else equal_runs(context):
            c = context[t]
            u = W1c @ c
            lr_cc = lr * (c @ c)
            acc = np.zeros(n_hidden)
            for k in range(t, end):
                p1 = proprio[k]
                h = expit(u + W1pb @ p1)
                h1[:n_hidden] = h
                y = expit(W2b @ h1)
                err = y - postures[k + 1]
                sq_error += err @ err
                d_out = err * y * (1.0 - y)
                d_hid = (W2h_T @ d_out) * h * (1.0 - h)
                dger(-lr, d_out, h1, a=W2b, overwrite_a=1)
                dger(-lr, d_hid, p1, a=W1pb, overwrite_a=1)
                u -= lr_cc * d_hid
                acc += d_hid
            dger(-lr, acc, c, a=W1c, overwrite_a=1)
        return float(np.sqrt(sq_error / (steps * N_OUTPUT)))


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
