"""The Jordan network in torch: the reference implementation, trained the plain way.

The pipeline trains with :func:`icub_affordance.learning.network.train_online`, the same
arithmetic in a compiled loop without autograd's per-step overhead; the tests hold the two equal
within 1e-10 and ``benchmarks/train_speed.py`` measures the difference. Kept apart so that the
training jobs need not import torch.
"""

from __future__ import annotations

import numpy as np
import torch

from icub_affordance.learning.network import N_OUTPUT, N_VISUAL, Weights


class JordanNet(torch.nn.Module):
    """The reference implementation in torch (float64)."""

    def __init__(self, weights: Weights) -> None:
        super().__init__()
        hidden = weights.W1.shape[0]
        self.hidden = torch.nn.Linear(
            weights.W1.shape[1], hidden
        ).double()  # 216, or more with names
        self.motor = torch.nn.Linear(hidden, N_OUTPUT).double()
        with torch.no_grad():
            self.hidden.weight.copy_(torch.from_numpy(weights.W1))
            self.hidden.bias.copy_(torch.from_numpy(weights.b1))
            self.motor.weight.copy_(torch.from_numpy(weights.W2))
            self.motor.bias.copy_(torch.from_numpy(weights.b2))

    def forward(self, x: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        h = torch.sigmoid(self.hidden(x))
        return torch.sigmoid(self.motor(h)), h

    def weights(self) -> Weights:
        return Weights(
            self.hidden.weight.detach().numpy().copy(),
            self.hidden.bias.detach().numpy().copy(),
            self.motor.weight.detach().numpy().copy(),
            self.motor.bias.detach().numpy().copy(),
        )


def train_sequence_torch(
    net: JordanNet, optimiser: torch.optim.Optimizer, context: np.ndarray, postures: np.ndarray
) -> float:
    """One training sequence, the plain way: autograd and an SGD step at every time step.

    ``context`` is (steps-1, 200): visual and goal input at each step; ``postures`` (steps, 16)
    is the demonstrated sequence (teacher forcing). Returns the sequence's RMSE before updates.
    """
    errors = []
    for t in range(len(postures) - 1):
        x = np.concatenate([context[t, :N_VISUAL], postures[t], context[t, N_VISUAL:]])
        y, _ = net(torch.from_numpy(x))
        target = torch.from_numpy(postures[t + 1])
        loss = 0.5 * ((y - target) ** 2).sum()
        optimiser.zero_grad()
        loss.backward()
        optimiser.step()
        errors.append((y.detach().numpy() - postures[t + 1]) ** 2)
    return float(np.sqrt(np.mean(errors)))
