"""The Jordan network's training loop, compiled: a network's whole schedule in one call.

Online back-propagation of the squared error with hand-derived gradients, one weight update per
time step, no momentum: the arithmetic of the torch reference (``jordan_torch``), which
autograd computes step by step. Compiled by numba to machine code, it trains a network of the
paper's size (216-10-16, 12,000 sequences of 9 steps) in about 0.1-0.2 s, a few hundred times
faster than the plain torch loop (``benchmarks/train_speed.py``).

Made fast by doing less, not by approximating. The visual and goal inputs stay the same from
step to step within a sequence (the goal map changes only when the task cue does), so they
enter incrementally: for a run of steps with the same context ``c``, ``u = W1c c`` is computed
once; after each step's update ``W1c -= lr dh c^T``, ``u`` changes by ``-lr (c . c) dh``, and
``W1c`` itself is updated once at the end of the run with the summed ``dh``. Mathematically the
same updates; in floating point the sums are taken in another order, so the weights agree with
the torch loop's to about 1e-14 (a test holds them within 1e-10).

Reproducible bits: no fast-math (IEEE operations in the order written, no fused multiply-add,
no reassociated sums), no threads, nothing random. numba's cache (``cache=True``: the
``__pycache__`` beside this file, or ``NUMBA_CACHE_DIR``) is keyed on this file's content, the
function's bytecode, the CPU and the numba version, so a cached kernel is the kernel compiled
from this code, and a cold compile, a cache load and an uncached compile give the same bits (a
test checks). The kernel calls no other compiled function and reads no global of another module
(whose change the cache would not see): every size comes from the arrays.

Kept apart from ``jordan`` so that only training pays numba's import (about 0.5 s).
"""

from __future__ import annotations

import numba
import numpy as np


@numba.njit(cache=True, nogil=True, error_model="numpy")
def train_schedule(
    W1cT, W1pT, b1, W2T, b2, rates, contexts, run_ends, demos, targets, grips, tasks, objects,
    sequences, rmse,
):  # fmt: skip
    """Train in place over the schedule; each sequence's RMSE (before its updates) to ``rmse``.

    Weights, transposed so that the inner loops run over contiguous rows: ``W1cT`` (200, hidden)
    from the context inputs (visual, goal), ``W1pT`` (16, hidden) from the proprioceptive input,
    ``b1`` (hidden,), ``W2T`` (hidden, 16), ``b2`` (16,). ``rates`` (iterations,) the learning
    rate of each iteration's updates. ``contexts`` (objects, tasks, steps-1,
    200) the context at each transition; ``run_ends`` (objects, tasks, steps-1) the end of the
    run of equal contexts that starts at each step; ``demos`` (objects, grips, sequences, steps,
    16) the postures fed back as proprioception; ``targets`` (the same shape) what the motor
    output learns at each next step (``demos`` itself in the paper's reading); ``grips``
    (objects, tasks) the target grip; ``tasks``, ``objects``, ``sequences`` (iterations,) the
    schedule.
    """
    n_ctx, n_hid = W1cT.shape
    n_pro = W1pT.shape[0]
    n_out = W2T.shape[1]
    u = np.empty(n_hid)  # W1c @ c for the current run, kept up to date
    acc = np.empty(n_hid)  # the run's summed hidden deltas, for W1c's deferred update
    h = np.empty(n_hid)
    y = np.empty(n_out)
    d_out = np.empty(n_out)
    d_hid = np.empty(n_hid)
    for it in range(tasks.shape[0]):
        lr = rates[it]
        o = objects[it]
        k = tasks[it]
        ctx = contexts[o, k]
        ends = run_ends[o, k]
        post = demos[o, grips[o, k], sequences[it]]
        goal = targets[o, grips[o, k], sequences[it]]
        steps = post.shape[0] - 1
        sq = 0.0
        t = 0
        while t < steps:
            end = ends[t]
            c = ctx[t]
            cc = 0.0
            for j in range(n_hid):
                u[j] = 0.0
                acc[j] = 0.0
            for i in range(n_ctx):
                ci = c[i]
                cc += ci * ci
                for j in range(n_hid):
                    u[j] += W1cT[i, j] * ci
            lr_cc = lr * cc
            for s in range(t, end):
                p = post[s]
                # forward: hidden, then motor output
                for j in range(n_hid):
                    h[j] = u[j] + b1[j]
                for i in range(n_pro):
                    pi = p[i]
                    for j in range(n_hid):
                        h[j] += W1pT[i, j] * pi
                for j in range(n_hid):
                    h[j] = 1.0 / (1.0 + np.exp(-h[j]))
                for m in range(n_out):
                    y[m] = b2[m]
                for j in range(n_hid):
                    hj = h[j]
                    for m in range(n_out):
                        y[m] += W2T[j, m] * hj
                # backward: deltas of 0.5 * squared error, with the weights before the update
                for m in range(n_out):
                    ym = 1.0 / (1.0 + np.exp(-y[m]))
                    err = ym - goal[s + 1, m]
                    sq += err * err
                    d_out[m] = err * ym * (1.0 - ym)
                for j in range(n_hid):
                    back = 0.0
                    for m in range(n_out):
                        back += W2T[j, m] * d_out[m]
                    d_hid[j] = back * h[j] * (1.0 - h[j])
                # one SGD step
                for j in range(n_hid):
                    lr_h = lr * h[j]
                    for m in range(n_out):
                        W2T[j, m] -= lr_h * d_out[m]
                for m in range(n_out):
                    b2[m] -= lr * d_out[m]
                for i in range(n_pro):
                    lr_p = lr * p[i]
                    for j in range(n_hid):
                        W1pT[i, j] -= lr_p * d_hid[j]
                for j in range(n_hid):
                    b1[j] -= lr * d_hid[j]
                    u[j] -= lr_cc * d_hid[j]
                    acc[j] += d_hid[j]
            for i in range(n_ctx):
                lr_c = lr * c[i]
                for j in range(n_hid):
                    W1cT[i, j] -= lr_c * acc[j]
            t = end
        rmse[it] = np.sqrt(sq / (steps * n_out))
