"""The Jordan network's training loop, compiled: a network's whole schedule in one call.

Online back-propagation of the squared error with hand-derived gradients, one weight update per
time step, no momentum: the arithmetic of the torch reference (``jordan_torch``), which
autograd computes step by step. Compiled by numba to machine code, it trains a network of the
paper's size (216-10-16, 12,000 sequences of 9 steps) in a few hundredths of a second, and a
robot variant's (40 hidden units, 768,000 sequences) in about 4 s, several hundred times
faster than the plain torch loop (``benchmarks/train_speed.py``).

Made fast by doing less, not by approximating:

- The visual and goal inputs (the context) take only a few distinct values: one per object and
  task cue (8 here). Their part of the hidden input, ``U[k] = W1c c_k``, is kept for each
  distinct context ``c_k`` instead of recomputed from the 200 x hidden weights ``W1c``. A step
  whose context is ``c_r`` updates ``W1c -= lr dh c_r^T``, which moves every ``U[k]`` by
  ``-lr (c_k . c_r) dh``: the current context's at each step (the next step needs it), the
  others once at the end of the run of equal contexts, with the run's summed ``dh``. ``W1c``
  itself is rebuilt at the end from the sum of each context's updates.
- The hidden deltas ``W2^T d`` are summed with a copy of ``W2`` laid out so the sums run over
  contiguous memory (the same additions in the same order as over ``W2T``).
- A step's weight updates are made by the next step's loops over the same weights (each
  weight updated just before it is read: the same operations in the same order), so the
  weights are read and written once per step instead of twice.
- The sigmoid's exponential is computed here (``_neg_exp``: range reduction by powers of 2 and
  a degree-13 polynomial, within 1 ulp of the C library's exp) in plain arithmetic that the
  compiler runs in vector lanes, where a call to the C library's exp runs one value at a time.

Mathematically the torch loop's updates; in floating point the sums are taken in another order
and the exponential rounds differently, so the weights agree with the torch loop's to about
1e-14 (a test holds them within 1e-10).

Reproducible bits: no fast-math (IEEE operations in the order written, no fused multiply-add,
no reassociated sums), no threads, nothing random, no call into a library whose implementation
the CPU selects (the exponential is this file's own). numba's cache (``cache=True``: the
``__pycache__`` beside this file, or ``NUMBA_CACHE_DIR``) is keyed on this file, the function's
bytecode, the CPU and the numba version, so a cached kernel is the kernel compiled from this
code, and a cold compile, a cache load and an uncached compile give the same bits (a test
checks). The kernel calls only this file's compiled functions and reads no global of another
module (whose change the cache would not see): every size comes from the arrays.

Kept apart from ``jordan`` so that only training pays numba's import (about 0.5 s).
"""

from __future__ import annotations

import numba
import numpy as np


@numba.njit(cache=True, nogil=True, inline="always")
def _neg_exp(z, n, out, bits, scale):
    """``out[j] = exp(-z[j])`` for ``j < n``; ``bits`` an int64 buffer, ``scale`` its float view.

    exp(x) = 2^k exp(r), k = round(x / ln 2), r = x - k ln 2 (ln 2 in two parts, so that k ln 2
    is exact), exp(r) by its Taylor polynomial to degree 13 (|r| <= 0.35: truncation below
    1e-17), 2^k made from its exponent bits. Written as plain operations over an array so that
    the compiler vectorises it; arguments beyond +-700 are clamped (exp is then 0 or inf for the
    sigmoid's purpose either way).
    """
    for j in range(n):
        x = min(max(-z[j], -700.0), 700.0)
        k = np.floor(x * 1.4426950408889634 + 0.5)
        r = (x - k * 0.6931471803691238) - k * 1.9082149292705877e-10
        p = 1.0 / 6227020800.0
        p = p * r + 1.0 / 479001600.0
        p = p * r + 1.0 / 39916800.0
        p = p * r + 1.0 / 3628800.0
        p = p * r + 1.0 / 362880.0
        p = p * r + 1.0 / 40320.0
        p = p * r + 1.0 / 5040.0
        p = p * r + 1.0 / 720.0
        p = p * r + 1.0 / 120.0
        p = p * r + 1.0 / 24.0
        p = p * r + 1.0 / 6.0
        p = p * r + 0.5
        p = p * r + 1.0
        p = p * r + 1.0
        bits[j] = (np.int64(k) + 1023) << 52
        out[j] = p * scale[j]


@numba.njit(cache=True, nogil=True)
def neg_exp(z):
    """exp(-z) by the kernel's own exponential (for tests)."""
    out = np.empty(z.size)
    bits = np.empty(z.size, dtype=np.int64)
    _neg_exp(z, z.size, out, bits, bits.view(np.float64))
    return out


@numba.njit(cache=True, nogil=True)
def project_contexts(W1cT, unique, U, gram):
    """The state's context part at the start: ``U[k] = W1c @ unique[k]`` and the contexts' dot
    products ``gram[k, q] = unique[k] . unique[q]`` (both zero on entry)."""
    n_ctx, n_hid = W1cT.shape
    n_unique = unique.shape[0]
    for k in range(n_unique):
        for i in range(n_ctx):
            ci = unique[k, i]
            for j in range(n_hid):
                U[k, j] += W1cT[i, j] * ci
    for k in range(n_unique):
        for q in range(n_unique):
            s = 0.0
            for i in range(n_ctx):
                s += unique[k, i] * unique[q, i]
            gram[k, q] = s


@numba.njit(cache=True, nogil=True, error_model="numpy")
def train_schedule(
    W1pT, b1, W2T, b2, U, moved, gram, lr_p, d_hid, lr_h, d_out, rates, context_ids, run_ends,
    demos, targets, grips, tasks, objects, sequences, rmse,
):  # fmt: skip
    """Train in place over the schedule; each sequence's RMSE (before its updates) to ``rmse``.

    The training state (``jordan.TrainingState``), carried from one call to the next so that a
    schedule trained in parts is trained to the same bits as in one call: the weights, transposed
    so that the inner loops run over contiguous rows, ``W1pT`` (16, hidden) from the
    proprioceptive input, ``b1`` (hidden,), ``W2T`` (hidden, 16), ``b2`` (16,); the context
    part ``U`` (contexts, hidden) and ``moved`` (contexts, hidden), the sum of lr * dh over each
    context's steps, with ``gram`` (contexts, contexts) from :func:`project_contexts`; the last
    step's pending weight update ``lr_p`` (16,), ``d_hid`` (hidden,), ``lr_h`` (hidden,),
    ``d_out`` (16,) (zero before the first step).

    The schedule: ``rates`` (iterations,) the learning rate of each iteration's updates;
    ``context_ids`` (objects, tasks, steps-1) which distinct context is the input at each
    transition; ``run_ends`` (objects, tasks, steps-1) the end of the run of equal contexts that
    starts at each step; ``demos`` (objects, grips, sequences, steps, 16) the postures fed back
    as proprioception; ``targets`` (the same shape) what the motor output learns at each next
    step (``demos`` itself in the paper's reading); ``grips`` (objects, tasks) the target grip;
    ``tasks``, ``objects``, ``sequences`` (iterations,) the schedule.
    """
    n_hid = W1pT.shape[1]
    n_unique = U.shape[0]
    n_pro = W1pT.shape[0]
    n_out = W2T.shape[1]
    W2 = np.empty((n_out, n_hid))  # W2T's transpose, updated alongside it
    for j in range(n_hid):
        for m in range(n_out):
            W2[m, j] = W2T[j, m]
    n_max = max(n_hid, n_out)
    e = np.empty(n_max)
    bits = np.empty(n_max, dtype=np.int64)
    scale = bits.view(np.float64)
    run_sum = np.empty(n_hid)  # the run's summed hidden deltas
    h = np.empty(n_hid)
    y = np.empty(n_out)
    back = np.empty(n_hid)
    # A step's updates of W1p, W2T and W2 are made by the next step's loops over those weights,
    # each weight updated just before that loop reads it (one pass over the weights, not two);
    # lr_p, d_hid, lr_h and d_out hold the update: W1p -= lr_p d_hid^T, W2T -= lr_h d_out^T, W2
    # -= its transpose (:func:`finish` makes the last one).
    d_new = np.empty(n_out)
    err = np.empty(n_out)
    for it in range(tasks.shape[0]):
        lr = rates[it]
        o = objects[it]
        k = tasks[it]
        ids = context_ids[o, k]
        ends = run_ends[o, k]
        post = demos[o, grips[o, k], sequences[it]]
        goal = targets[o, grips[o, k], sequences[it]]
        steps = post.shape[0] - 1
        sq = 0.0
        t = 0
        while t < steps:
            end = ends[t]
            r = ids[t]
            u = U[r]
            for j in range(n_hid):
                run_sum[j] = 0.0
            lr_cc = lr * gram[r, r]
            for s in range(t, end):
                p = post[s]
                # forward: hidden (W1p updated by the last step first), then motor output (W2T
                # updated by the last step first)
                for j in range(n_hid):
                    h[j] = u[j] + b1[j]
                for i in range(n_pro):
                    lp = lr_p[i]
                    pi = p[i]
                    for j in range(n_hid):
                        w = W1pT[i, j] - lp * d_hid[j]
                        W1pT[i, j] = w
                        h[j] += w * pi
                _neg_exp(h, n_hid, e, bits, scale)
                for j in range(n_hid):
                    h[j] = 1.0 / (1.0 + e[j])
                for m in range(n_out):
                    y[m] = b2[m]
                for j in range(n_hid):
                    lh = lr_h[j]
                    hj = h[j]
                    for m in range(n_out):
                        w = W2T[j, m] - lh * d_out[m]
                        W2T[j, m] = w
                        y[m] += w * hj
                # backward: deltas of 0.5 * squared error, with the weights before this step's
                # update (W2 updated by the last step first)
                _neg_exp(y, n_out, e, bits, scale)
                target = goal[s + 1]
                for m in range(n_out):  # in vector lanes: the sum of squares apart
                    ym = 1.0 / (1.0 + e[m])
                    err[m] = ym - target[m]
                    d_new[m] = err[m] * ym * (1.0 - ym)
                for m in range(n_out):
                    sq += err[m] * err[m]
                for j in range(n_hid):
                    back[j] = 0.0
                for m in range(n_out):
                    dm = d_new[m]
                    dp = d_out[m]
                    for j in range(n_hid):
                        w = W2[m, j] - lr_h[j] * dp
                        W2[m, j] = w
                        back[j] += w * dm
                # one SGD step: the biases and the context's part now, the weights pending
                for m in range(n_out):
                    d_out[m] = d_new[m]
                    b2[m] -= lr * d_out[m]
                for j in range(n_hid):
                    d_hid[j] = back[j] * h[j] * (1.0 - h[j])
                    lr_h[j] = lr * h[j]
                for i in range(n_pro):
                    lr_p[i] = lr * p[i]
                for j in range(n_hid):
                    b1[j] -= lr * d_hid[j]
                    u[j] -= lr_cc * d_hid[j]
                    run_sum[j] += d_hid[j]
            # the run's update of W1c, seen by the other contexts and kept for the end
            for j in range(n_hid):
                run_sum[j] *= lr
                moved[r, j] += run_sum[j]
            for q in range(n_unique):
                g = gram[q, r]
                if q != r and g != 0.0:
                    for j in range(n_hid):
                        U[q, j] -= g * run_sum[j]
            t = end
        rmse[it] = np.sqrt(sq / (steps * n_out))


@numba.njit(cache=True, nogil=True)
def finish(W1cT, unique, moved, W1pT, W2T, lr_p, d_hid, lr_h, d_out):
    """The weights at the end, in place: the last step's pending update made, and ``W1cT`` (the
    context weights as they started) moved by each context's summed updates."""
    n_ctx, n_hid = W1cT.shape
    for i in range(W1pT.shape[0]):
        for j in range(n_hid):
            W1pT[i, j] -= lr_p[i] * d_hid[j]
    for j in range(n_hid):
        for m in range(W2T.shape[1]):
            W2T[j, m] -= lr_h[j] * d_out[m]
    for q in range(unique.shape[0]):
        for i in range(n_ctx):
            ci = unique[q, i]
            if ci != 0.0:
                for j in range(n_hid):
                    W1cT[i, j] -= ci * moved[q, j]
