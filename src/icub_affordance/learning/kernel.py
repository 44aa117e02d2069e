"""The Jordan network's training loop, compiled: a network's whole schedule in one call.

Online back-propagation of the squared error with hand-derived gradients, one weight update per
time step, no momentum: the arithmetic of the torch reference (``torch_reference``), which
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

``train_lanes4`` and ``train_lanes8`` train four or eight networks of one run at once, network l
in lane l of 4- or 8-wide vectors, each lane making its network's operations in its network's
order, so that each ends with the same bits whatever the group it trains in
(``network.train_together``; the section at the end of this file). They are the one learning
rule: a network alone trains in four lanes beside three copies of itself.

Kept apart from ``network`` so that only training pays numba's import (about 0.5 s).
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


# --- Networks side by side: one network in each lane of a vector ----------------------------
#
# ``train_lanes4`` and ``train_lanes8`` train four or eight networks of one run at once (same
# shapes, same schedule length, same contexts; their own weights, schedules, mappings and rates),
# network l in lane l of every vector: each array of the state has a last axis of 4 or 8, and
# every vector operation below is one IEEE operation per lane, the very operation the
# per-network kernel makes on that network's number. The order of every sum (over the inputs,
# the hidden units, the outputs, a sequence's squared errors) is a lone network's own; no
# fused multiply-add, no reassociation. So each lane ends with the bits its network has when
# trained alone, whatever the width (a test checks, ``tests/test_jordan.py``).
#
# The vectors are explicit (the intrinsics below emit LLVM's <4 x double> or <8 x double>
# loads, stores and arithmetic) rather than left to the compiler, which does not vectorise a
# loop of 4: numba's loop vectoriser wants longer loops, and its SLP vectoriser is off. The
# width is a compile-time constant of ``_train_lanes`` (a literal argument, one compiled kernel
# per width). A step is mostly chains of dependent operations (the sigmoid's polynomial, the
# sums), so eight lanes, two vectors' work in flight where the CPU has 256-bit registers, train
# eight networks in about 1.3 times the time of four (``benchmarks/train_speed.py``).
#
# What differs from a loop over one network is only where numbers live, never what is computed:
# - W2 is kept once, as (16, hidden, lanes): the per-network kernel's second, transposed copy
#   (kept for contiguous sums) holds the same bits, and here every sum runs over lanes anyway.
# - Each network's runs of equal contexts are its own (a categorisation trial with the cue at
#   the first step has two runs, a grasping trial one), so the lanes do not start and end runs
#   together: the current context's part of the hidden input is held per lane in ``cur`` (the
#   per-network kernel's ``u``, a row of ``U``), loaded when the lane's run starts and written
#   back, with the run's update of the other contexts, when it ends (per lane, at the same
#   point of that network's arithmetic as alone). The step's arithmetic itself is the same in
#   every lane whatever its run.


class _Lanes(types.Type):
    """``width`` float64, one per network: LLVM's <width x double>."""

    def __init__(self, width: int):
        self.width = width
        super().__init__(name=f"Lanes{width}")


def _vec(width: int) -> ir.VectorType:
    """LLVM's <width x double>: a :class:`_Lanes` value as the machine code holds it."""
    return ir.VectorType(ir.DoubleType(), width)


def _width(value: types.IntegerLiteral) -> int:
    """A literal integer argument's value (the lanes' count the kernel was compiled for)."""
    return value.literal_value


@register_model(_Lanes)
class _LanesModel(models.PrimitiveModel):
    def __init__(self, dmm, fe_type):
        super().__init__(dmm, fe_type, _vec(fe_type.width))


def _element(context, builder, array_type, array, index_type, index):
    """Pointer to element ``index`` of a C-contiguous array (flat index, not checked)."""
    data = context.make_array(array_type)(context, builder, array).data
    index = context.cast(builder, index, index_type, types.intp)
    return builder.gep(data, [index], inbounds=True)


def _vector_at(context, builder, sig, args, k, index, width):
    """``width`` lanes from element ``args[index]`` of the array ``args[k]``."""
    pointer = _element(context, builder, sig.args[k], args[k], sig.args[index], args[index])
    return builder.bitcast(pointer, _vec(width).as_pointer())


def _float_array(array) -> bool:
    return isinstance(array, types.Array) and array.dtype == types.float64 and array.layout == "C"


@intrinsic
def _load(typingctx, array, index, width):
    """The lanes at ``array.flat[index:index + width]``."""
    if _float_array(array) and isinstance(width, types.IntegerLiteral):
        n = _width(width)

        def codegen(context, builder, sig, args):
            return builder.load(_vector_at(context, builder, sig, args, 0, 1, n), align=8)

        return _Lanes(n)(array, index, width), codegen


@intrinsic
def _store(typingctx, array, value, index):
    """``array.flat[index:index + width] = value``, ``width`` the value's lanes."""
    if _float_array(array) and isinstance(value, _Lanes):
        n = value.width

        def codegen(context, builder, sig, args):
            builder.store(args[1], _vector_at(context, builder, sig, args, 0, 2, n), align=8)
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
def _gather_at(typingctx, array, idx, off, width):
    """The lanes ``array.flat[idx[l] + off]``, l < width (``idx`` a C-contiguous int64 array)."""
    indices = isinstance(idx, types.Array) and idx.dtype == types.int64 and idx.layout == "C"
    if _float_array(array) and indices and isinstance(width, types.IntegerLiteral):
        n = _width(width)

        def codegen(context, builder, sig, args):
            value = ir.Constant(_vec(n), ir.Undefined)
            idx_data = context.make_array(sig.args[1])(context, builder, args[1]).data
            off = context.cast(builder, args[2], sig.args[2], types.intp)
            for lane in range(n):
                k = builder.load(builder.gep(idx_data, [ir.IntType(64)(lane)], inbounds=True))
                at = builder.add(k, off)
                pointer = _element(context, builder, sig.args[0], args[0], types.intp, at)
                value = builder.insert_element(value, builder.load(pointer), ir.IntType(32)(lane))
            return value

        return _Lanes(n)(array, idx, off, width), codegen


@intrinsic
def _splat(typingctx, x, width):
    """The same number in every lane (a compile-time constant)."""
    if isinstance(x, types.Literal | types.Float) and isinstance(width, types.IntegerLiteral):
        n = _width(width)

        def codegen(context, builder, sig, args):
            value = context.cast(builder, args[0], sig.args[0], types.float64)
            vector = ir.Constant(_vec(n), ir.Undefined)
            for lane in range(n):
                vector = builder.insert_element(vector, value, ir.IntType(32)(lane))
            return vector

        return _Lanes(n)(x, width), codegen


@intrinsic
def _select(typingctx, mask, a, b):
    """``a`` in the lanes where ``mask`` is not 0.0, ``b`` in the others: bits chosen, not
    computed."""
    if isinstance(mask, _Lanes) and mask == a == b:
        n = mask.width

        def codegen(context, builder, sig, args):
            zero = ir.Constant(_vec(n), [ir.DoubleType()(0.0)] * n)
            return builder.select(builder.fcmp_ordered("!=", args[0], zero), args[1], args[2])

        return mask(mask, a, b), codegen


def _arithmetic(operation):
    @intrinsic
    def apply(typingctx, a, b):
        if isinstance(a, _Lanes) and a == b:

            def codegen(context, builder, sig, args):
                return getattr(builder, operation)(args[0], args[1])

            return a(a, b), codegen

    return apply


_add = _arithmetic("fadd")
_sub = _arithmetic("fsub")
_mul = _arithmetic("fmul")

# The sigmoid 1 / (1 + exp(-z)) with ``_neg_exp``'s exponential, lane by lane: the same
# operations in the same order on each number. Several vectors' numbers at a time (four, after a
# block of four hidden units or outputs: their chains of dependent operations interleave, so the
# processor overlaps them).
_TAYLOR = (
    1.0 / 479001600.0, 1.0 / 39916800.0, 1.0 / 3628800.0, 1.0 / 362880.0, 1.0 / 40320.0,
    1.0 / 5040.0, 1.0 / 720.0, 1.0 / 120.0, 1.0 / 24.0, 1.0 / 6.0, 0.5, 1.0, 1.0,
)  # fmt: skip


@intrinsic
def _sigmoid(typingctx, z, index, lanes, blocks):
    """``z.flat[index:index + lanes * blocks] = 1 / (1 + exp(-z))`` (``_neg_exp``'s exp): the
    numbers of ``blocks`` vectors of ``lanes`` at once (both literal integers)."""
    literal = isinstance(lanes, types.IntegerLiteral) and isinstance(blocks, types.IntegerLiteral)
    if _float_array(z) and literal:
        width = _width(lanes) * _width(blocks)
        vector = ir.VectorType(ir.DoubleType(), width)
        integers = ir.VectorType(ir.IntType(64), width)

        def constant(x, of=vector):
            return ir.Constant(of, [of.element(x)] * width)

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

        return types.none(z, index, lanes, blocks), codegen


@numba.njit(cache=True, nogil=True, error_model="numpy")
def _train_lanes(
    W1p, b1, W2, b2, U, moved, gram, lr_p, d_hid, lr_h, d_out, rates, context_ids, run_ends,
    demos, targets, grips, tasks, objects, sequences, rmse, lanes,
):  # fmt: skip
    """Train ``lanes`` networks side by side over their schedules, in place; each sequence's
    RMSE (before its updates) to ``rmse`` (iterations, lanes). ``lanes`` (4 or 8) must be a
    literal: called through :func:`train_lanes4` or :func:`train_lanes8`.

    A network's training state (``network.TrainingState``) with a last axis of ``lanes`` (network
    l in lane l), its
    weights laid out for sums over lanes: ``W1p`` (hidden, 16, lanes) from the proprioceptive
    input (the per-network ``W1pT`` transposed), ``b1`` (hidden, lanes), ``W2`` (16, hidden,
    lanes), ``b2`` (16, lanes), ``U`` and ``moved`` (contexts, hidden, lanes), ``lr_p`` (16,
    lanes), ``d_hid`` and ``lr_h`` (hidden, lanes), ``d_out`` (16, lanes); ``gram`` (contexts,
    contexts), the contexts' dot products, the same for all. The schedules: ``rates``,
    ``tasks``, ``objects``, ``sequences`` (iterations, lanes); ``grips`` (objects, tasks, lanes)
    each network's target grips; ``context_ids``, ``run_ends``, ``demos``, ``targets`` shared,
    as ``network.train_together`` passes them.
    """
    numba.literally(lanes)
    L = lanes  # the lanes, a constant of each compiled kernel
    n_hid = W1p.shape[0]
    n_pro = W1p.shape[1]
    n_out = W2.shape[0]
    n_unique = U.shape[0]
    n_tasks = context_ids.shape[1]
    steps = demos.shape[3] - 1
    n_grips = demos.shape[1]
    n_seq = demos.shape[2]
    seq_size = demos.shape[3] * demos.shape[4]
    one = _splat(1.0, L)
    zero = _splat(0.0, L)
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
    p = np.empty(n_pro * L)
    goal = np.empty(n_out * L)
    h = np.empty(n_hid * L)
    y = np.empty(n_out * L)
    back = np.empty(n_hid * L)  # the hidden deltas' sums, then the runs' updates
    cur = np.empty(n_hid * L)  # each lane's current context's part of the hidden input
    run_sum = np.empty(n_hid * L)  # each lane's run's summed hidden deltas
    sq = np.empty(L)
    lr = np.empty(L)
    lr_cc = np.empty(L)
    run = np.empty(L, dtype=np.int64)  # each lane's current context
    is_end = np.empty(L)  # 1.0 in the lanes whose run ends at this step
    own = np.empty(L)  # 1.0 in the lanes whose run ends with this context
    other = np.empty(L)  # 1.0 in the lanes whose ending run moves this context
    run_end = np.empty(L, dtype=np.int64)
    seq_at = np.empty(L, dtype=np.int64)
    ctx_at = np.empty(L, dtype=np.int64)
    pos = np.empty(L, dtype=np.int64)
    w1 = n_pro * L  # one hidden unit's row of W1p
    w2 = n_hid * L  # one output's row of W2
    for it in range(tasks.shape[0]):
        for lane in range(L):
            lr[lane] = rates[it, lane]
            sq[lane] = 0.0
            run_end[lane] = 0
            o = objects[it, lane]
            k = tasks[it, lane]
            grip = grips[o, k, lane]
            seq_at[lane] = ((o * n_grips + grip) * n_seq + sequences[it, lane]) * seq_size
            ctx_at[lane] = (o * n_tasks + k) * steps
        lrv = _load(lr, 0, L)
        for s in range(steps):
            # the postures fed back and the next ones, gathered lane by lane
            for lane in range(L):
                pos[lane] = seq_at[lane] + s * n_pro
            for i in range(n_pro):
                _store(p, _gather_at(demosf, pos, i, L), i * L)
            for m in range(n_out):
                _store(goal, _gather_at(targetsf, pos, n_pro + m, L), m * L)
            for lane in range(L):
                if s == run_end[lane]:  # the lane's run of equal contexts starts
                    at = ctx_at[lane] + s
                    r = _get(idsf, at)
                    run[lane] = r
                    run_end[lane] = _get(endsf, at)
                    lr_cc[lane] = lr[lane] * _get(gramf, r * n_unique + r)
                    for j in range(n_hid):
                        _put(cur, j * L + lane, _get(Uf, (r * n_hid + j) * L + lane))
                        _put(run_sum, j * L + lane, 0.0)
            # forward: the hidden units, four at a time (four sums in flight), W1p updated by
            # the last step first
            j = 0
            while j < n_hid:
                a = j * L
                if j + 4 <= n_hid:
                    d0 = _load(d_hidf, a, L)
                    d1 = _load(d_hidf, a + L, L)
                    d2 = _load(d_hidf, a + 2 * L, L)
                    d3 = _load(d_hidf, a + 3 * L, L)
                    s0 = _add(_load(cur, a, L), _load(b1f, a, L))
                    s1 = _add(_load(cur, a + L, L), _load(b1f, a + L, L))
                    s2 = _add(_load(cur, a + 2 * L, L), _load(b1f, a + 2 * L, L))
                    s3 = _add(_load(cur, a + 3 * L, L), _load(b1f, a + 3 * L, L))
                    for i in range(n_pro):
                        lp = _load(lr_pf, i * L, L)
                        pi = _load(p, i * L, L)
                        b = j * w1 + i * L
                        w = _sub(_load(W1pf, b, L), _mul(lp, d0))
                        _store(W1pf, w, b)
                        s0 = _add(s0, _mul(w, pi))
                        b += w1
                        w = _sub(_load(W1pf, b, L), _mul(lp, d1))
                        _store(W1pf, w, b)
                        s1 = _add(s1, _mul(w, pi))
                        b += w1
                        w = _sub(_load(W1pf, b, L), _mul(lp, d2))
                        _store(W1pf, w, b)
                        s2 = _add(s2, _mul(w, pi))
                        b += w1
                        w = _sub(_load(W1pf, b, L), _mul(lp, d3))
                        _store(W1pf, w, b)
                        s3 = _add(s3, _mul(w, pi))
                    _store(h, s0, a)
                    _store(h, s1, a + L)
                    _store(h, s2, a + 2 * L)
                    _store(h, s3, a + 3 * L)
                    _sigmoid(h, a, L, 4)  # overlapping the next block's sums
                    j += 4
                elif j + 2 <= n_hid:  # two at a time
                    d0 = _load(d_hidf, a, L)
                    d1 = _load(d_hidf, a + L, L)
                    s0 = _add(_load(cur, a, L), _load(b1f, a, L))
                    s1 = _add(_load(cur, a + L, L), _load(b1f, a + L, L))
                    for i in range(n_pro):
                        lp = _load(lr_pf, i * L, L)
                        pi = _load(p, i * L, L)
                        b = j * w1 + i * L
                        w = _sub(_load(W1pf, b, L), _mul(lp, d0))
                        _store(W1pf, w, b)
                        s0 = _add(s0, _mul(w, pi))
                        b += w1
                        w = _sub(_load(W1pf, b, L), _mul(lp, d1))
                        _store(W1pf, w, b)
                        s1 = _add(s1, _mul(w, pi))
                    _store(h, s0, a)
                    _store(h, s1, a + L)
                    _sigmoid(h, a, L, 1)
                    _sigmoid(h, a + L, L, 1)
                    j += 2
                else:
                    d0 = _load(d_hidf, a, L)
                    s0 = _add(_load(cur, a, L), _load(b1f, a, L))
                    for i in range(n_pro):
                        b = j * w1 + i * L
                        w = _sub(_load(W1pf, b, L), _mul(_load(lr_pf, i * L, L), d0))
                        _store(W1pf, w, b)
                        s0 = _add(s0, _mul(w, _load(p, i * L, L)))
                    _store(h, s0, a)
                    _sigmoid(h, a, L, 1)
                    j += 1
            # forward: the motor outputs, four at a time, W2 updated by the last step first
            m = 0
            while m < n_out:
                a = m * L
                if m + 4 <= n_out:
                    d0 = _load(d_outf, a, L)
                    d1 = _load(d_outf, a + L, L)
                    d2 = _load(d_outf, a + 2 * L, L)
                    d3 = _load(d_outf, a + 3 * L, L)
                    s0 = _load(b2f, a, L)
                    s1 = _load(b2f, a + L, L)
                    s2 = _load(b2f, a + 2 * L, L)
                    s3 = _load(b2f, a + 3 * L, L)
                    for j in range(n_hid):
                        lh = _load(lr_hf, j * L, L)
                        hj = _load(h, j * L, L)
                        b = m * w2 + j * L
                        w = _sub(_load(W2f, b, L), _mul(lh, d0))
                        _store(W2f, w, b)
                        s0 = _add(s0, _mul(w, hj))
                        b += w2
                        w = _sub(_load(W2f, b, L), _mul(lh, d1))
                        _store(W2f, w, b)
                        s1 = _add(s1, _mul(w, hj))
                        b += w2
                        w = _sub(_load(W2f, b, L), _mul(lh, d2))
                        _store(W2f, w, b)
                        s2 = _add(s2, _mul(w, hj))
                        b += w2
                        w = _sub(_load(W2f, b, L), _mul(lh, d3))
                        _store(W2f, w, b)
                        s3 = _add(s3, _mul(w, hj))
                    _store(y, s0, a)
                    _store(y, s1, a + L)
                    _store(y, s2, a + 2 * L)
                    _store(y, s3, a + 3 * L)
                    _sigmoid(y, a, L, 4)  # overlapping the next block's sums
                    m += 4
                else:
                    d0 = _load(d_outf, a, L)
                    s0 = _load(b2f, a, L)
                    for j in range(n_hid):
                        b = m * w2 + j * L
                        w = _sub(_load(W2f, b, L), _mul(_load(lr_hf, j * L, L), d0))
                        _store(W2f, w, b)
                        s0 = _add(s0, _mul(w, _load(h, j * L, L)))
                    _store(y, s0, a)
                    _sigmoid(y, a, L, 1)
                    m += 1
            # backward: deltas of 0.5 * squared error; the output biases' update
            sqv = _load(sq, 0, L)
            for m in range(n_out):
                a = m * L
                ym = _load(y, a, L)
                err = _sub(ym, _load(goal, a, L))
                dm = _mul(_mul(err, ym), _sub(one, ym))
                _store(d_outf, dm, a)  # the pending update of W2 from here on
                _store(b2f, _sub(_load(b2f, a, L), _mul(lrv, dm)), a)
                sqv = _add(sqv, _mul(err, err))
            _store(sq, sqv, 0)
            # the hidden deltas (their sums over the outputs with W2 as this step updated it),
            # four at a time, and with each the hidden side of the SGD step: the biases and the
            # context's part now, the weights pending
            lcc = _load(lr_cc, 0, L)
            j = 0
            while j < n_hid:
                if j + 4 <= n_hid:
                    s0 = zero
                    s1 = zero
                    s2 = zero
                    s3 = zero
                    for m in range(n_out):
                        dm = _load(d_outf, m * L, L)
                        b = m * w2 + j * L
                        s0 = _add(s0, _mul(_load(W2f, b, L), dm))
                        s1 = _add(s1, _mul(_load(W2f, b + L, L), dm))
                        s2 = _add(s2, _mul(_load(W2f, b + 2 * L, L), dm))
                        s3 = _add(s3, _mul(_load(W2f, b + 3 * L, L), dm))
                    _store(back, s0, 0)
                    _store(back, s1, L)
                    _store(back, s2, 2 * L)
                    _store(back, s3, 3 * L)
                    n = 4
                elif j + 2 <= n_hid:
                    s0 = zero
                    s1 = zero
                    for m in range(n_out):
                        dm = _load(d_outf, m * L, L)
                        b = m * w2 + j * L
                        s0 = _add(s0, _mul(_load(W2f, b, L), dm))
                        s1 = _add(s1, _mul(_load(W2f, b + L, L), dm))
                    _store(back, s0, 0)
                    _store(back, s1, L)
                    n = 2
                else:
                    s0 = zero
                    for m in range(n_out):
                        s0 = _add(s0, _mul(_load(W2f, m * w2 + j * L, L), _load(d_outf, m * L, L)))
                    _store(back, s0, 0)
                    n = 1
                for k in range(n):
                    a = (j + k) * L
                    hv = _load(h, a, L)
                    dh = _mul(_mul(_load(back, k * L, L), hv), _sub(one, hv))
                    _store(d_hidf, dh, a)
                    _store(lr_hf, _mul(lrv, hv), a)
                    _store(b1f, _sub(_load(b1f, a, L), _mul(lrv, dh)), a)
                    _store(cur, _sub(_load(cur, a, L), _mul(lcc, dh)), a)
                    _store(run_sum, _add(_load(run_sum, a, L), dh), a)
                j += n
            for i in range(n_pro):
                _store(lr_pf, _mul(lrv, _load(p, i * L, L)), i * L)
            # the runs that end here: their update of W1c, seen by the other contexts (a lane
            # whose run goes on keeps its numbers: chosen, not recomputed)
            ending = False
            for lane in range(L):
                ends = s + 1 == run_end[lane]
                ending = ending or ends
                is_end[lane] = 1.0 if ends else 0.0
            if ending:
                for j in range(n_hid):
                    a = j * L
                    _store(back, _mul(_load(run_sum, a, L), lrv), a)  # the run's lr * summed deltas
                for q in range(n_unique):
                    for lane in range(L):
                        r = run[lane]
                        g = _get(gramf, q * n_unique + r)
                        own[lane] = is_end[lane] if q == r else 0.0
                        other[lane] = is_end[lane] if q != r and g != 0.0 else 0.0
                    g = _gather_at(gramf, run, q * n_unique, L)
                    is_own = _load(own, 0, L)
                    is_other = _load(other, 0, L)
                    for j in range(n_hid):
                        a = j * L
                        at = (q * n_hid + j) * L
                        rs = _load(back, a, L)
                        u = _load(Uf, at, L)
                        u = _select(is_other, _sub(u, _mul(g, rs)), u)
                        _store(Uf, _select(is_own, _load(cur, a, L), u), at)
                        mv = _load(movedf, at, L)
                        _store(movedf, _select(is_own, _add(mv, rs), mv), at)
        for lane in range(L):
            rmse[it, lane] = np.sqrt(sq[lane] / (steps * n_out))


# One compiled kernel per width, each passing its width as a literal: a constant of the
# compiled code, so the vectors' types are known when it compiles. Called from Python instead,
# ``_train_lanes`` would have to ask numba for a literal on every call (``numba.literally``
# retypes the call each time: about 0.25 s a call, measured, against 0.05 s of training).
@numba.njit(cache=True, nogil=True, error_model="numpy")
def train_lanes4(
    W1p, b1, W2, b2, U, moved, gram, lr_p, d_hid, lr_h, d_out, rates, context_ids, run_ends,
    demos, targets, grips, tasks, objects, sequences, rmse,
):  # fmt: skip
    """:func:`_train_lanes` for four networks (every array's last axis 4)."""
    _train_lanes(
        W1p, b1, W2, b2, U, moved, gram, lr_p, d_hid, lr_h, d_out, rates, context_ids, run_ends,
        demos, targets, grips, tasks, objects, sequences, rmse, 4,
    )  # fmt: skip


@numba.njit(cache=True, nogil=True, error_model="numpy")
def train_lanes8(
    W1p, b1, W2, b2, U, moved, gram, lr_p, d_hid, lr_h, d_out, rates, context_ids, run_ends,
    demos, targets, grips, tasks, objects, sequences, rmse,
):  # fmt: skip
    """:func:`_train_lanes` for eight networks (every array's last axis 8)."""
    _train_lanes(
        W1p, b1, W2, b2, U, moved, gram, lr_p, d_hid, lr_h, d_out, rates, context_ids, run_ends,
        demos, targets, grips, tasks, objects, sequences, rmse, 8,
    )  # fmt: skip
