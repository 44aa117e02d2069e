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

``train_lanes`` trains four networks of one run at once, network l in lane l of 4-wide vectors,
each lane making its network's operations in its network's order, so that each ends with the
bits it has when trained alone (``jordan.train_together``; the section at the end of this file).

Kept apart from ``jordan`` so that only training pays numba's import (about 0.5 s).
"""

from __future__ import annotations

import numba
import numpy as np
from llvmlite import ir
from numba.core import types
from numba.extending import intrinsic, models, register_model


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


# --- Networks side by side: four networks in the four lanes of a vector ----------------------
#
# ``train_lanes`` trains four networks of one run at once (same shapes, same schedule length,
# same contexts; their own weights, schedules, mappings and rates), network l in lane l of every
# 4-wide vector: each array of the state has a last axis of 4, and every vector operation below
# is one IEEE operation per lane, the very operation the per-network kernel makes on that
# network's number. The order of every sum (over the inputs, the hidden units, the outputs, a
# sequence's squared errors) is that of ``train_schedule``; no fused multiply-add, no
# reassociation. So each lane ends with the bits its network has when trained alone (a test
# checks, ``tests/test_jordan.py``).
#
# The vectors are explicit (the intrinsics below emit LLVM's <4 x double> loads, stores and
# arithmetic) rather than left to the compiler, which does not vectorise a loop of 4: numba's
# loop vectoriser wants longer loops, and its SLP vectoriser is off.
#
# What differs from ``train_schedule`` is only where numbers live, never what is computed:
# - W2 is kept once, as (16, hidden, 4): the per-network kernel's second, transposed copy (kept
#   for contiguous sums) holds the same bits, and here every sum runs over lanes anyway.
# - Each network's runs of equal contexts are its own (a categorisation trial with the cue at
#   the first step has two runs, a grasping trial one), so the lanes do not start and end runs
#   together: the current context's part of the hidden input is held per lane in ``cur`` (the
#   per-network kernel's ``u``, a row of ``U``), loaded when the lane's run starts and written
#   back, with the run's update of the other contexts, when it ends (per lane, at the same
#   point of that network's arithmetic as alone). The step's arithmetic itself is the same in
#   every lane whatever its run.

_VEC = ir.VectorType(ir.DoubleType(), 4)


class _Lanes(types.Type):
    """Four float64, one per network: LLVM's <4 x double>."""

    def __init__(self):
        super().__init__(name="Lanes4")


_lanes = _Lanes()


@register_model(_Lanes)
class _LanesModel(models.PrimitiveModel):
    def __init__(self, dmm, fe_type):
        super().__init__(dmm, fe_type, _VEC)


def _element(context, builder, array_type, array, index_type, index):
    """Pointer to element ``index`` of a C-contiguous array (flat index, not checked)."""
    data = context.make_array(array_type)(context, builder, array).data
    index = context.cast(builder, index, index_type, types.intp)
    return builder.gep(data, [index], inbounds=True)


def _vector_at(context, builder, sig, args, k):
    pointer = _element(context, builder, sig.args[k], args[k], sig.args[-1], args[-1])
    return builder.bitcast(pointer, _VEC.as_pointer())


def _float_array(array) -> bool:
    return isinstance(array, types.Array) and array.dtype == types.float64 and array.layout == "C"


@intrinsic
def _load(typingctx, array, index):
    """The four lanes at ``array.flat[index:index + 4]``."""
    if _float_array(array):

        def codegen(context, builder, sig, args):
            return builder.load(_vector_at(context, builder, sig, args, 0), align=8)

        return _lanes(array, index), codegen


@intrinsic
def _store(typingctx, array, value, index):
    """``array.flat[index:index + 4] = value``."""
    if _float_array(array) and value == _lanes:

        def codegen(context, builder, sig, args):
            builder.store(args[1], _vector_at(context, builder, sig, args, 0), align=8)
            return context.get_dummy_value()

        return types.none(array, value, index), codegen


@intrinsic
def _get(typingctx, array, index):
    """``array.flat[index]``, unchecked."""
    if isinstance(array, types.Array) and array.layout == "C":

        def codegen(context, builder, sig, args):
            return builder.load(_element(context, builder, sig.args[0], args[0], sig.args[1],
                                         args[1]))  # fmt: skip

        return array.dtype(array, index), codegen


@intrinsic
def _put(typingctx, array, index, value):
    """``array.flat[index] = value``, unchecked."""
    if isinstance(array, types.Array) and array.layout == "C":

        def codegen(context, builder, sig, args):
            value = context.cast(builder, args[2], sig.args[2], sig.args[0].dtype)
            builder.store(value, _element(context, builder, sig.args[0], args[0], sig.args[1],
                                          args[1]))  # fmt: skip
            return context.get_dummy_value()

        return types.none(array, index, value), codegen


@intrinsic
def _gather(typingctx, array, i0, i1, i2, i3):
    """The lanes ``array.flat[i0]``, ..., ``array.flat[i3]``."""
    if _float_array(array):

        def codegen(context, builder, sig, args):
            value = ir.Constant(_VEC, ir.Undefined)
            for lane in range(4):
                pointer = _element(context, builder, sig.args[0], args[0], sig.args[1 + lane],
                                   args[1 + lane])  # fmt: skip
                value = builder.insert_element(value, builder.load(pointer), ir.IntType(32)(lane))
            return value

        return _lanes(array, i0, i1, i2, i3), codegen


@intrinsic
def _splat(typingctx, x):
    """The same number in the four lanes (a compile-time constant)."""
    if isinstance(x, types.Literal | types.Float):

        def codegen(context, builder, sig, args):
            value = context.cast(builder, args[0], sig.args[0], types.float64)
            vector = ir.Constant(_VEC, ir.Undefined)
            for lane in range(4):
                vector = builder.insert_element(vector, value, ir.IntType(32)(lane))
            return vector

        return _lanes(x), codegen


@intrinsic
def _select(typingctx, mask, a, b):
    """``a`` in the lanes where ``mask`` is not 0.0, ``b`` in the others: bits chosen, not
    computed."""
    if mask == _lanes and a == _lanes and b == _lanes:

        def codegen(context, builder, sig, args):
            zero = ir.Constant(_VEC, [ir.DoubleType()(0.0)] * 4)
            return builder.select(builder.fcmp_ordered("!=", args[0], zero), args[1], args[2])

        return _lanes(mask, a, b), codegen


def _arithmetic(operation):
    @intrinsic
    def apply(typingctx, a, b):
        if a == _lanes and b == _lanes:

            def codegen(context, builder, sig, args):
                return getattr(builder, operation)(args[0], args[1])

            return _lanes(a, b), codegen

    return apply


_add = _arithmetic("fadd")
_sub = _arithmetic("fsub")
_mul = _arithmetic("fmul")

# The sigmoid 1 / (1 + exp(-z)) with ``_neg_exp``'s exponential, lane by lane: the same
# operations in the same order on each number. Sixteen numbers at a time (four vectors whose
# chains of dependent operations interleave, so the processor overlaps them).
_TAYLOR = (
    1.0 / 479001600.0, 1.0 / 39916800.0, 1.0 / 3628800.0, 1.0 / 362880.0, 1.0 / 40320.0,
    1.0 / 5040.0, 1.0 / 720.0, 1.0 / 120.0, 1.0 / 24.0, 1.0 / 6.0, 0.5, 1.0, 1.0,
)  # fmt: skip


def _sigmoid_of(width: int):
    vector = ir.VectorType(ir.DoubleType(), width)
    integers = ir.VectorType(ir.IntType(64), width)

    def constant(x, of=vector):
        return ir.Constant(of, [of.element(x)] * width)

    @intrinsic
    def sigmoid(typingctx, z, index):
        """``z.flat[index:index + width] = 1 / (1 + exp(-z))`` (``_neg_exp``'s exp)."""
        if _float_array(z):

            def codegen(context, builder, sig, args):
                pointer = builder.bitcast(
                    _element(context, builder, sig.args[0], args[0], sig.args[1], args[1]),
                    vector.as_pointer(),
                )
                x = builder.fsub(constant(-0.0), builder.load(pointer, align=8))
                # max(x, -700.0) then min(x, 700.0), as numba computes them
                x = builder.select(builder.fcmp_ordered(">", constant(-700.0), x),
                                   constant(-700.0), x)  # fmt: skip
                x = builder.select(builder.fcmp_ordered("<", constant(700.0), x),
                                   constant(700.0), x)  # fmt: skip
                name = f"llvm.floor.v{width}f64"
                floor = builder.module.globals.get(name) or ir.Function(
                    builder.module, ir.FunctionType(vector, [vector]), name
                )
                k = builder.fadd(builder.fmul(x, constant(1.4426950408889634)), constant(0.5))
                k = builder.call(floor, [k])
                r = builder.fsub(
                    builder.fsub(x, builder.fmul(k, constant(0.6931471803691238))),
                    builder.fmul(k, constant(1.9082149292705877e-10)),
                )
                p = constant(1.0 / 6227020800.0)
                for c in _TAYLOR:
                    p = builder.fadd(builder.fmul(p, r), constant(c))
                # int64(k) for |k| <= 1011: through int32, one instruction instead of four
                k = builder.sext(builder.fptosi(k, ir.VectorType(ir.IntType(32), width)), integers)
                bits = builder.shl(builder.add(k, constant(1023, integers)),
                                   constant(52, integers))  # fmt: skip
                e = builder.fmul(p, builder.bitcast(bits, vector))
                builder.store(builder.fdiv(constant(1.0), builder.fadd(constant(1.0), e)),
                              pointer, align=8)  # fmt: skip
                return context.get_dummy_value()

            return types.none(z, index), codegen

    return sigmoid


_sigmoid_4 = _sigmoid_of(4)
_sigmoid_16 = _sigmoid_of(16)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def train_lanes(
    W1p, b1, W2, b2, U, moved, gram, lr_p, d_hid, lr_h, d_out, rates, context_ids, run_ends,
    demos, targets, grips, tasks, objects, sequences, rmse,
):  # fmt: skip
    """Train four networks side by side over their schedules, in place; each sequence's RMSE
    (before its updates) to ``rmse`` (iterations, 4).

    The state of :func:`train_schedule` with a last axis of 4 (network l in lane l), its weights
    laid out for sums over lanes: ``W1p`` (hidden, 16, 4) from the proprioceptive input (the
    per-network ``W1pT`` transposed), ``b1`` (hidden, 4), ``W2`` (16, hidden, 4), ``b2`` (16, 4),
    ``U`` and ``moved`` (contexts, hidden, 4), ``lr_p`` (16, 4), ``d_hid`` and ``lr_h`` (hidden,
    4), ``d_out`` (16, 4); ``gram`` (contexts, contexts), the contexts' dot products, the same
    for the four. The schedules: ``rates``, ``tasks``, ``objects``, ``sequences`` (iterations,
    4); ``grips`` (objects, tasks, 4) each network's target grips; ``context_ids``,
    ``run_ends``, ``demos``, ``targets`` shared, as in :func:`train_schedule`.
    """
    n_hid = W1p.shape[0]
    n_pro = W1p.shape[1]
    n_out = W2.shape[0]
    n_unique = U.shape[0]
    n_tasks = context_ids.shape[1]
    steps = demos.shape[3] - 1
    n_grips = demos.shape[1]
    n_seq = demos.shape[2]
    seq_size = demos.shape[3] * demos.shape[4]
    one = _splat(1.0)
    zero = _splat(0.0)
    # flat views: every index below is computed, never wrapped or checked
    W1pf = W1p.reshape(W1p.size)
    W2f = W2.reshape(W2.size)
    b1f = b1.reshape(b1.size)
    b2f = b2.reshape(b2.size)
    Uf = U.reshape(U.size)
    movedf = moved.reshape(moved.size)
    gramf = gram.reshape(gram.size)
    lr_pf = lr_p.reshape(lr_p.size)
    d_hidf = d_hid.reshape(d_hid.size)
    lr_hf = lr_h.reshape(lr_h.size)
    d_outf = d_out.reshape(d_out.size)
    idsf = context_ids.reshape(context_ids.size)
    endsf = run_ends.reshape(run_ends.size)
    demosf = demos.reshape(demos.size)
    targetsf = targets.reshape(targets.size)
    # this step's numbers, lane by lane
    p = np.empty(n_pro * 4)
    goal = np.empty(n_out * 4)
    h = np.empty(n_hid * 4)
    y = np.empty(n_out * 4)
    back = np.empty(n_hid * 4)  # the hidden deltas' sums, then the runs' updates
    cur = np.empty(n_hid * 4)  # each lane's current context's part of the hidden input
    run_sum = np.empty(n_hid * 4)  # each lane's run's summed hidden deltas
    sq = np.empty(4)
    lr = np.empty(4)
    lr_cc = np.empty(4)
    run = np.empty(4, dtype=np.int64)  # each lane's current context
    is_end = np.empty(4)  # 1.0 in the lanes whose run ends at this step
    own = np.empty(4)  # 1.0 in the lanes whose run ends with this context
    other = np.empty(4)  # 1.0 in the lanes whose ending run moves this context
    run_end = np.empty(4, dtype=np.int64)
    seq_at = np.empty(4, dtype=np.int64)
    ctx_at = np.empty(4, dtype=np.int64)
    w1 = n_pro * 4  # one hidden unit's row of W1p
    w2 = n_hid * 4  # one output's row of W2
    for it in range(tasks.shape[0]):
        for lane in range(4):
            lr[lane] = rates[it, lane]
            sq[lane] = 0.0
            run_end[lane] = 0
            o = objects[it, lane]
            k = tasks[it, lane]
            grip = grips[o, k, lane]
            seq_at[lane] = ((o * n_grips + grip) * n_seq + sequences[it, lane]) * seq_size
            ctx_at[lane] = (o * n_tasks + k) * steps
        lrv = _load(lr, 0)
        for s in range(steps):
            # the postures fed back and the next ones, gathered lane by lane
            a0 = seq_at[0] + s * n_pro
            a1 = seq_at[1] + s * n_pro
            a2 = seq_at[2] + s * n_pro
            a3 = seq_at[3] + s * n_pro
            for i in range(n_pro):
                _store(p, _gather(demosf, a0 + i, a1 + i, a2 + i, a3 + i), i * 4)
            a0 += n_pro
            a1 += n_pro
            a2 += n_pro
            a3 += n_pro
            for m in range(n_out):
                _store(goal, _gather(targetsf, a0 + m, a1 + m, a2 + m, a3 + m), m * 4)
            for lane in range(4):
                if s == run_end[lane]:  # the lane's run of equal contexts starts
                    at = ctx_at[lane] + s
                    r = _get(idsf, at)
                    run[lane] = r
                    run_end[lane] = _get(endsf, at)
                    lr_cc[lane] = lr[lane] * _get(gramf, r * n_unique + r)
                    for j in range(n_hid):
                        _put(cur, j * 4 + lane, _get(Uf, (r * n_hid + j) * 4 + lane))
                        _put(run_sum, j * 4 + lane, 0.0)
            # forward: the hidden units, four at a time (four sums in flight), W1p updated by
            # the last step first
            j = 0
            while j < n_hid:
                a = j * 4
                if j + 4 <= n_hid:
                    d0 = _load(d_hidf, a)
                    d1 = _load(d_hidf, a + 4)
                    d2 = _load(d_hidf, a + 8)
                    d3 = _load(d_hidf, a + 12)
                    s0 = _add(_load(cur, a), _load(b1f, a))
                    s1 = _add(_load(cur, a + 4), _load(b1f, a + 4))
                    s2 = _add(_load(cur, a + 8), _load(b1f, a + 8))
                    s3 = _add(_load(cur, a + 12), _load(b1f, a + 12))
                    for i in range(n_pro):
                        lp = _load(lr_pf, i * 4)
                        pi = _load(p, i * 4)
                        b = j * w1 + i * 4
                        w = _sub(_load(W1pf, b), _mul(lp, d0))
                        _store(W1pf, w, b)
                        s0 = _add(s0, _mul(w, pi))
                        b += w1
                        w = _sub(_load(W1pf, b), _mul(lp, d1))
                        _store(W1pf, w, b)
                        s1 = _add(s1, _mul(w, pi))
                        b += w1
                        w = _sub(_load(W1pf, b), _mul(lp, d2))
                        _store(W1pf, w, b)
                        s2 = _add(s2, _mul(w, pi))
                        b += w1
                        w = _sub(_load(W1pf, b), _mul(lp, d3))
                        _store(W1pf, w, b)
                        s3 = _add(s3, _mul(w, pi))
                    _store(h, s0, a)
                    _store(h, s1, a + 4)
                    _store(h, s2, a + 8)
                    _store(h, s3, a + 12)
                    _sigmoid_16(h, a)  # overlapping the next block's sums
                    j += 4
                elif j + 2 <= n_hid:  # two at a time
                    d0 = _load(d_hidf, a)
                    d1 = _load(d_hidf, a + 4)
                    s0 = _add(_load(cur, a), _load(b1f, a))
                    s1 = _add(_load(cur, a + 4), _load(b1f, a + 4))
                    for i in range(n_pro):
                        lp = _load(lr_pf, i * 4)
                        pi = _load(p, i * 4)
                        b = j * w1 + i * 4
                        w = _sub(_load(W1pf, b), _mul(lp, d0))
                        _store(W1pf, w, b)
                        s0 = _add(s0, _mul(w, pi))
                        b += w1
                        w = _sub(_load(W1pf, b), _mul(lp, d1))
                        _store(W1pf, w, b)
                        s1 = _add(s1, _mul(w, pi))
                    _store(h, s0, a)
                    _store(h, s1, a + 4)
                    _sigmoid_4(h, a)
                    _sigmoid_4(h, a + 4)
                    j += 2
                else:
                    d0 = _load(d_hidf, a)
                    s0 = _add(_load(cur, a), _load(b1f, a))
                    for i in range(n_pro):
                        b = j * w1 + i * 4
                        w = _sub(_load(W1pf, b), _mul(_load(lr_pf, i * 4), d0))
                        _store(W1pf, w, b)
                        s0 = _add(s0, _mul(w, _load(p, i * 4)))
                    _store(h, s0, a)
                    _sigmoid_4(h, a)
                    j += 1
            # forward: the motor outputs, four at a time, W2 updated by the last step first
            m = 0
            while m < n_out:
                a = m * 4
                if m + 4 <= n_out:
                    d0 = _load(d_outf, a)
                    d1 = _load(d_outf, a + 4)
                    d2 = _load(d_outf, a + 8)
                    d3 = _load(d_outf, a + 12)
                    s0 = _load(b2f, a)
                    s1 = _load(b2f, a + 4)
                    s2 = _load(b2f, a + 8)
                    s3 = _load(b2f, a + 12)
                    for j in range(n_hid):
                        lh = _load(lr_hf, j * 4)
                        hj = _load(h, j * 4)
                        b = m * w2 + j * 4
                        w = _sub(_load(W2f, b), _mul(lh, d0))
                        _store(W2f, w, b)
                        s0 = _add(s0, _mul(w, hj))
                        b += w2
                        w = _sub(_load(W2f, b), _mul(lh, d1))
                        _store(W2f, w, b)
                        s1 = _add(s1, _mul(w, hj))
                        b += w2
                        w = _sub(_load(W2f, b), _mul(lh, d2))
                        _store(W2f, w, b)
                        s2 = _add(s2, _mul(w, hj))
                        b += w2
                        w = _sub(_load(W2f, b), _mul(lh, d3))
                        _store(W2f, w, b)
                        s3 = _add(s3, _mul(w, hj))
                    _store(y, s0, a)
                    _store(y, s1, a + 4)
                    _store(y, s2, a + 8)
                    _store(y, s3, a + 12)
                    _sigmoid_16(y, a)  # overlapping the next block's sums
                    m += 4
                else:
                    d0 = _load(d_outf, a)
                    s0 = _load(b2f, a)
                    for j in range(n_hid):
                        b = m * w2 + j * 4
                        w = _sub(_load(W2f, b), _mul(_load(lr_hf, j * 4), d0))
                        _store(W2f, w, b)
                        s0 = _add(s0, _mul(w, _load(h, j * 4)))
                    _store(y, s0, a)
                    _sigmoid_4(y, a)
                    m += 1
            # backward: deltas of 0.5 * squared error; the output biases' update
            sqv = _load(sq, 0)
            for m in range(n_out):
                a = m * 4
                ym = _load(y, a)
                err = _sub(ym, _load(goal, a))
                dm = _mul(_mul(err, ym), _sub(one, ym))
                _store(d_outf, dm, a)  # the pending update of W2 from here on
                _store(b2f, _sub(_load(b2f, a), _mul(lrv, dm)), a)
                sqv = _add(sqv, _mul(err, err))
            _store(sq, sqv, 0)
            # the hidden deltas (their sums over the outputs with W2 as this step updated it),
            # four at a time, and with each the hidden side of the SGD step: the biases and the
            # context's part now, the weights pending
            lcc = _load(lr_cc, 0)
            j = 0
            while j < n_hid:
                if j + 4 <= n_hid:
                    s0 = zero
                    s1 = zero
                    s2 = zero
                    s3 = zero
                    for m in range(n_out):
                        dm = _load(d_outf, m * 4)
                        b = m * w2 + j * 4
                        s0 = _add(s0, _mul(_load(W2f, b), dm))
                        s1 = _add(s1, _mul(_load(W2f, b + 4), dm))
                        s2 = _add(s2, _mul(_load(W2f, b + 8), dm))
                        s3 = _add(s3, _mul(_load(W2f, b + 12), dm))
                    _store(back, s0, 0)
                    _store(back, s1, 4)
                    _store(back, s2, 8)
                    _store(back, s3, 12)
                    n = 4
                elif j + 2 <= n_hid:
                    s0 = zero
                    s1 = zero
                    for m in range(n_out):
                        dm = _load(d_outf, m * 4)
                        b = m * w2 + j * 4
                        s0 = _add(s0, _mul(_load(W2f, b), dm))
                        s1 = _add(s1, _mul(_load(W2f, b + 4), dm))
                    _store(back, s0, 0)
                    _store(back, s1, 4)
                    n = 2
                else:
                    s0 = zero
                    for m in range(n_out):
                        s0 = _add(s0, _mul(_load(W2f, m * w2 + j * 4), _load(d_outf, m * 4)))
                    _store(back, s0, 0)
                    n = 1
                for k in range(n):
                    a = (j + k) * 4
                    hv = _load(h, a)
                    dh = _mul(_mul(_load(back, k * 4), hv), _sub(one, hv))
                    _store(d_hidf, dh, a)
                    _store(lr_hf, _mul(lrv, hv), a)
                    _store(b1f, _sub(_load(b1f, a), _mul(lrv, dh)), a)
                    _store(cur, _sub(_load(cur, a), _mul(lcc, dh)), a)
                    _store(run_sum, _add(_load(run_sum, a), dh), a)
                j += n
            for i in range(n_pro):
                _store(lr_pf, _mul(lrv, _load(p, i * 4)), i * 4)
            # the runs that end here: their update of W1c, seen by the other contexts (a lane
            # whose run goes on keeps its numbers: chosen, not recomputed)
            ending = False
            for lane in range(4):
                ends = s + 1 == run_end[lane]
                ending = ending or ends
                is_end[lane] = 1.0 if ends else 0.0
            if ending:
                r0 = run[0]
                r1 = run[1]
                r2 = run[2]
                r3 = run[3]
                for j in range(n_hid):
                    a = j * 4
                    _store(back, _mul(_load(run_sum, a), lrv), a)  # the run's lr * summed deltas
                for q in range(n_unique):
                    for lane in range(4):
                        r = run[lane]
                        g = _get(gramf, q * n_unique + r)
                        own[lane] = is_end[lane] if q == r else 0.0
                        other[lane] = is_end[lane] if q != r and g != 0.0 else 0.0
                    g = _gather(gramf, q * n_unique + r0, q * n_unique + r1, q * n_unique + r2,
                                q * n_unique + r3)  # fmt: skip
                    is_own = _load(own, 0)
                    is_other = _load(other, 0)
                    for j in range(n_hid):
                        a = j * 4
                        at = (q * n_hid + j) * 4
                        rs = _load(back, a)
                        u = _load(Uf, at)
                        u = _select(is_other, _sub(u, _mul(g, rs)), u)
                        _store(Uf, _select(is_own, _load(cur, a), u), at)
                        mv = _load(movedf, at)
                        _store(movedf, _select(is_own, _add(mv, rs), mv), at)
        for lane in range(4):
            rmse[it, lane] = np.sqrt(sq[lane] / (steps * n_out))
