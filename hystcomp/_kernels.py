"""Compiled sample loops (numba, ``cache=True``).

One kernel per operator family; every driver (simulate, inverses,
identification regressors, fast loops) calls these and nothing else runs the
play recursion.

Envelopes inside kernels are a kind code and a parameter array (see
:mod:`hystcomp.envelopes`): the value of a built-in envelope is computed
inline.  Outside its domain an envelope counts as -inf (below) or +inf
(above), so an operator boundary that leaves the domain never binds.

This module holds the forward kernels; the envelope code lives in
:mod:`hystcomp._kernels_envelopes` and the exact inverse in
:mod:`hystcomp._kernels_inverse`, and every name of both is importable from
here (``_kernels.inverse_solve``, ``_kernels.TANH``, ...).

Speed (see benchmarks/bench_models.py): inner loops evaluate built-in
envelopes without dispatching through the parameter array (`_fval`,
`_fval_der`) and the hot kernels are compiled in a few copies (built-in
closed forms without the general fallback in the loop, the rest with it; the
PI with no envelope code).  Each copy is a separate compiled function, most
of them made from one template by `_specialise`, so that a call compiles
only the copy it needs (cold start, benchmarks/bench_coldstart.py): Python
callers choose it with `play_sum_kernel`, `mplay_sum_kernel` and
`inverse_kernel`, the compiled loops with `_loop_kernels.step_kernel`; the
dispatching `play_sum`, `mplay_sum` and `inverse_solve` remain for compiled
callers that take any block (they compile every copy on first use).
Every kernel releases the GIL (``nogil=True``).  The PI forward sum
(`pi_sum`), the tanh mGPI forward (`play_sum_tanh`) and the exact inverses of
both (`play_solve_pi`, `play_solve_tanh`) evaluate every operator at every
sample (or Newton step) branch-free and may reassociate the sums over
operators (fastmath reassoc and contract only: NaN and inf keep their
meaning), so they run in SIMD lanes; their results are within a few ulp of
the plain formula (Tanh envelopes use the libm-free `_tanh`, within 2.2 ulp
of NumPy's).  Every other fast path performs the same floating-point
operations in the same order as the plain formulas.  Either way each value
is a function of the input and the state only, not of how a record is cut,
so chunked runs equal one-shot runs bit for bit.

Operator families, all of the form ``w <- max(L(v), min(U(v), w))``:

* play (eq. 13): ``L = v - r``, ``U = v + r``;
* modified generalized play with one envelope gamma (eq. 23, gl = gr):
  because gamma is increasing it commutes with max and min, so
  ``F^gamma_mr[v] = gamma(F_r[v])``: the state is the play position ``z`` in
  input coordinates and gamma is evaluated only when an operator moves;
* modified generalized play with two envelopes (eq. 23): state ``w``;
* generalized play (eq. 20): ``L = gl(v) - r``, ``U = gr(v) + r``: with
  ``a = gl(v)``, ``b = gr(v)`` precomputed once per sample this is a play
  with two inputs;
* stop (eq. 15-16): state ``(w, v_prev)``.
"""

import numpy as np
from numba import njit

# re-exported: every kernel name is importable from this module
from ._kernels_envelopes import (  # noqa: F401
    IDENTITY, LINEAR, TANH, ATANH, POLYNOMIAL, INVERSE_OF, CUSTOM, _INF, _specialise,
    _tanh, _fma, _is_finite, _fill_lanes, _poly_value, _poly_derivative, _poly_inverse, _base_value, _base_derivative,
    _base_inverse, env_value, env_derivative, env_inverse, _prm3, _fval, _fval_der,
    _slow_value, _slow_val_der, _vd_identity, _vd_closed, _vd_general, _vd_closed_call,
    _vd_general_call, _fmplay)
from ._kernels_inverse import (  # noqa: F401
    FAM_PLAY, FAM_MPLAY, FAM_GPI, FAM_STOP, _val_der, _output_and_slopes, _advance,
    _newton_point, _shrink, _play_eval_template, _play_solve, _play_solve_template,
    inverse_solve, inverse_kernel, inverse_solve_other,
    _play_eval_closed, _play_eval_general, play_solve_pi,
    play_solve_closed, play_solve_general, play_solve_tanh, _tanh_eval)

# ----------------------------------------------------------------------------
# forward kernels
# ----------------------------------------------------------------------------
# fastmath only for reassociation and contraction (FMA) of the operator sum,
# so that it runs in SIMD lanes; never nnan/ninf/nsz (NaN and inf keep their
# IEEE meaning).  The flags are fixed per compiled function, so a chunked run
# performs the same operations as a one-shot run (bit for bit).
_SUM_FLAGS = {"reassoc", "contract"}

# The name `_play_sum_template` calls and each of its compiled copies binds to
# an envelope evaluator (see `_specialise` and the end of this module).
_vd = None


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, fastmath=_SUM_FLAGS)
def pi_sum(v, r, p, p0, z, scale, out):
    """PI model (eq. 18), scaled by `scale` (a Linear envelope):
    ``out = scale * (p0 v + sum_i p_i F_ri[v])``; `z` updated in place.

    Branch-free play update ``z_i = min(max(z_i, v - r_i), v + r_i)`` with a
    reassociated sum over operators (vectorised).  `z` is loaded and stored
    at every sample in SIMD vectors of 32 bytes: Python callers pass
    32-byte aligned arrays (`run_play_sum`), since a vector that straddles a
    4 KiB page made a call 1.9-3.5x slower (benchmarks/README.md).

    Returns the index of the first sample of `v` that is NaN or +-inf, or -1
    when every sample is finite (tested on the exponent bits, `_is_finite`,
    in the same pass; the samples after it are still processed).
    `MGPI.simulate` raises the ValueError of `as_signal` from it instead of
    a separate pass over the record: a pass over the input and a temporary
    array less, which do not scale over threads
    (benchmarks/bench_models.py).
    """
    n = v.size
    N = r.size
    bad = -1
    for k in range(n):
        x = v[k]
        if bad < 0 and not _is_finite(x):
            bad = k
        s = 0.0
        for i in range(N):
            lo = x - r[i]
            hi = x + r[i]
            zi = z[i]
            zi = lo if zi < lo else zi
            zi = hi if zi > hi else zi
            z[i] = zi
            s += p[i] * zi
        out[k] = scale * (p0 * x + s)
    return bad


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, fastmath=_SUM_FLAGS, error_model="numpy")
def play_sum_tanh(v, r, p, p0, z, kind, prm, out):
    """Symmetric mGPI with a Tanh envelope (eq. 25/49, gamma(x) = a tanh(b x + c)):
    ``out = a (p0 tanh(b v + c) + sum_i p_i tanh(b z_i + c))``; `z` updated
    in place.

    Branch-free, in SIMD lanes: every operator's play position is clamped
    and its envelope evaluated at every sample (`_tanh` has no libm call and
    no branch), which costs less than evaluating only the moving operators
    one at a time (benchmarks/bench_models.py).  The p0 term is one more
    lane (threshold 0: its position is the input), and the lanes are padded
    to a multiple of 4 with operators that never move and weigh 0.  Each
    term depends on the operator's own position alone, so chunked runs equal
    one-shot runs bit for bit; the sum is reassociated and contracted
    (`_SUM_FLAGS`), so results are within a few ulp of the plain formula
    (`play_sum_closed`; tests/test_tanh_kernel.py).  ``error_model="numpy"``
    drops the Python division check, whose exit would stop the
    vectorisation (the denominator in `_tanh` is at least 1).
    """
    n = v.size
    N = r.size
    a, b, c = _prm3(prm)
    M = (N + 4) // 4 * 4
    rr, pp, zz = np.empty(M), np.empty(M), np.empty(M)
    _fill_lanes(r, p, p0, z, 0.0, rr, pp, zz)
    for k in range(n):
        x = v[k]
        s = 0.0
        for i in range(M):
            lo = x - rr[i]
            hi = x + rr[i]
            zi = zz[i]
            zi = lo if zi < lo else zi
            zi = hi if zi > hi else zi
            zz[i] = zi
            s += pp[i] * _tanh(_fma(b, zi, c))
        out[k] = a * s
    for i in range(N):
        z[i] = zz[i + 1]


def play_sum_kernel(kind):
    """The compiled kernel `play_sum` would use for envelope `kind`, chosen in
    Python so that a call compiles only that kernel (cold start).  Returns
    ``(kernel, takes_scale)``: PI-like kinds take ``scale`` instead of
    ``(kind, prm)``."""
    if kind == IDENTITY or kind == LINEAR:
        return pi_sum, True
    if kind == TANH:
        return play_sum_tanh, False
    if kind == ATANH:
        return play_sum_closed, False
    return play_sum_general, False


def run_play_sum(v, r, p, p0, z, kind, prm, out):
    """Python-side `play_sum`: same results, compiles only the kernel the
    envelope kind needs.  Returns the index of the first non-finite sample
    of `v` for the kinds whose kernel tests it (`checks_finite`), else -1."""
    kernel, scaled = play_sum_kernel(kind)
    if scaled:
        scale = 1.0 if kind == IDENTITY else float(prm[0])
        if v.size < _ALIGN_MIN:
            return kernel(v, r, p, p0, z, scale, out)
        za = _aligned_copy(z)
        bad = kernel(v, _aligned_copy(r), _aligned_copy(p), p0, za, scale, out)
        z[:] = za
        return bad
    kernel(v, r, p, p0, z, kind, prm, out)
    return -1


# `run_play_sum` runs `pi_sum` on records of at least this many samples with
# 32-byte aligned copies of the operator arrays (a few microseconds; shorter
# calls, such as the python-control blocks' one sample per step, skip it).
_ALIGN_MIN = 64


def _aligned_copy(a, align=32):
    """A copy of the 1-D float64 array `a` whose data starts on an
    `align`-byte boundary: the caller's arrays may sit anywhere (NumPy
    aligns to 16 bytes), so that the SIMD vectors of a kernel's
    operator loop never straddle a cache line or a page."""
    buf = np.empty(a.size + align // 8)
    k = (-buf.__array_interface__["data"][0] % align) // 8
    out = buf[k:k + a.size]
    out[:] = a
    return out


def checks_finite(kind):
    """True when the `play_sum` kernel of envelope `kind` reports the first
    non-finite input sample (`pi_sum`: the PI and Linear envelopes)."""
    return kind == IDENTITY or kind == LINEAR


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def play_sum(v, r, p, p0, z, kind, prm, out):
    """Sum of weighted enveloped plays: ``out = p0*g(v) + sum_i p_i g(F_ri[v])``.

    `z` (the play positions, input coordinates) is updated in place.  With
    ``kind == IDENTITY`` this is the PI model of eq. 18 (branch-free clamp);
    otherwise the symmetric mGPI of eq. 25/49 with ``g = gamma``.  Compiled
    code calls this; Python callers use `run_play_sum`, which compiles only
    the kernel a model needs.
    """
    if kind == IDENTITY or kind == LINEAR:
        pi_sum(v, r, p, p0, z, 1.0 if kind == IDENTITY else prm[0], out)
    elif kind == TANH:
        play_sum_tanh(v, r, p, p0, z, kind, prm, out)
    elif kind == ATANH:
        play_sum_closed(v, r, p, p0, z, kind, prm, out)
    else:
        play_sum_general(v, r, p, p0, z, kind, prm, out)


def _play_sum_template(v, r, p, p0, z, kind, prm, out):
    """`play_sum` with an envelope: g = gamma(z) is kept per operator and
    re-evaluated only for the operators that move.  `_vd` evaluates the
    envelope (see the copies at the end of the module)."""
    n = v.size
    N = r.size
    a, b, c = _prm3(prm)
    g = np.empty(N)
    for i in range(N):
        g[i] = _vd(kind, prm, a, b, c, z[i])[0]
    for k in range(n):
        x = v[k]
        s = 0.0
        for i in range(N):
            zi = z[i]
            lo = x - r[i]
            hi = x + r[i]
            if zi < lo:
                z[i] = lo
                g[i] = _vd(kind, prm, a, b, c, lo)[0]
            elif zi > hi:
                z[i] = hi
                g[i] = _vd(kind, prm, a, b, c, hi)[0]
            s += p[i] * g[i]
        out[k] = p0 * _vd(kind, prm, a, b, c, x)[0] + s


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def play_step(x, r, widen, z):
    """One sample of the plays (eq. 13): ``z_i <- max(x - r_i', min(x + r_i', z_i))``
    with ``r_i' = r_i + widen``; `z` updated in place.

    The play recursion for every kernel outside the fused sums of this module
    (play regressors, the KP model's diagonals, rate-dependent thresholds).
    """
    for i in range(r.size):
        ri = r[i] + widen
        lo = x - ri
        hi = x + ri
        zi = z[i]
        zi = lo if zi < lo else (hi if zi > hi else zi)
        z[i] = zi


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def play_states(v, r, z, out):
    """Play positions for every sample: ``out[k, i] = F_ri[v](t_k)``.

    Used in blocks (bounded memory) for envelopes that have no compiled form
    and to build identification regressors.  `z` is updated in place.
    """
    N = r.size
    for k in range(v.size):
        play_step(v[k], r, 0.0, z)
        for i in range(N):
            out[k, i] = z[i]


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def two_input_play_sum(a, b, r, p, w, out):
    """Generalized plays (eq. 20) given ``a = gl(v)``, ``b = gr(v)``:

    ``w_i <- max(a - r_i, min(b + r_i, w_i))``, ``out = sum_i p_i w_i``.
    """
    n = a.size
    N = r.size
    for k in range(n):
        ak = a[k]
        bk = b[k]
        s = 0.0
        for i in range(N):
            wi = w[i]
            hi = bk + r[i]
            lo = ak - r[i]
            wi = hi if wi > hi else wi
            wi = lo if wi < lo else wi
            w[i] = wi
            s += p[i] * wi
        out[k] = s


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def two_input_play_states(a, b, r, w, out):
    """Generalized play outputs for every sample (see `two_input_play_sum`)."""
    n = a.size
    N = r.size
    for k in range(n):
        for i in range(N):
            wi = w[i]
            hi = b[k] + r[i]
            lo = a[k] - r[i]
            wi = hi if wi > hi else wi
            wi = lo if wi < lo else wi
            w[i] = wi
            out[k, i] = wi


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def mplay_sum_closed(v, r, p, w, kl, pl, kr, pr, out):
    """`mplay_sum` for the built-in closed-form envelopes (Identity, Linear,
    Tanh, Atanh on both sides)."""
    _mplay_sum_body(v, r, p, w, kl, pl, kr, pr, out, False)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def mplay_sum_general(v, r, p, w, kl, pl, kr, pr, out):
    """`mplay_sum` for any compiled envelopes."""
    _mplay_sum_body(v, r, p, w, kl, pl, kr, pr, out, True)


def mplay_sum_kernel(kl, kr):
    """The compiled kernel `mplay_sum` uses for envelope kinds (kl, kr),
    chosen in Python so that a call compiles only that one."""
    if IDENTITY <= kl <= ATANH and IDENTITY <= kr <= ATANH:
        return mplay_sum_closed
    return mplay_sum_general


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def mplay_sum(v, r, p, w, kl, pl, kr, pr, out):
    """Modified generalized plays with two envelopes (eq. 23).

    ``w_i <- max(gl(v - r_i), min(gr(v + r_i), w_i))``; `r` includes the
    r = 0 operator of p0 (eq. 25).  ``out = sum_i p_i w_i``.  Compiled code
    calls this (both copies compiled on first use); Python callers use
    `mplay_sum_kernel`, which compiles only the copy the envelopes need.
    """
    if IDENTITY <= kl <= ATANH and IDENTITY <= kr <= ATANH:
        mplay_sum_closed(v, r, p, w, kl, pl, kr, pr, out)
    else:
        mplay_sum_general(v, r, p, w, kl, pl, kr, pr, out)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _mplay_sum_body(v, r, p, w, kl, pl, kr, pr, out, gen):
    n = v.size
    N = r.size
    al, bl, cl = _prm3(pl)
    ar, br, cr = _prm3(pr)
    for k in range(n):
        x = v[k]
        s = 0.0
        for i in range(N):
            wi = _fmplay(x, r[i], w[i], kl, pl, al, bl, cl, kr, pr, ar, br, cr, gen)
            w[i] = wi
            s += p[i] * wi
        out[k] = s


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def mplay_states(v, r, w, kl, pl, kr, pr, out):
    n = v.size
    N = r.size
    al, bl, cl = _prm3(pl)
    ar, br, cr = _prm3(pr)
    for k in range(n):
        x = v[k]
        for i in range(N):
            wi = _fmplay(x, r[i], w[i], kl, pl, al, bl, cl, kr, pr, ar, br, cr, True)
            w[i] = wi
            out[k, i] = wi


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def bounded_play_states(lower, upper, w, out):
    """``w_i <- max(lower[k, i], min(upper[k, i], w_i))`` for given boundaries.

    The fallback for envelopes without a compiled form (boundaries evaluated
    in NumPy block by block).
    """
    n = lower.shape[0]
    N = lower.shape[1]
    for k in range(n):
        for i in range(N):
            wi = w[i]
            hi = upper[k, i]
            lo = lower[k, i]
            wi = hi if wi > hi else wi
            wi = lo if wi < lo else wi
            w[i] = wi
            out[k, i] = wi


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def stop_states(v, r, w, vprev, out):
    """Stop operators (eq. 15-16): ``w_i <- clamp(w_i + v - v_prev, -r_i, r_i)``.

    `w` is updated in place; returns the last input (the new `vprev`).
    """
    n = v.size
    N = r.size
    for k in range(n):
        dv = v[k] - vprev
        vprev = v[k]
        for i in range(N):
            e = w[i] + dv
            e = r[i] if e > r[i] else e
            e = -r[i] if e < -r[i] else e
            w[i] = e
            out[k, i] = e
    return vprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def stop_sum(v, r, p, p0, w, vprev, out):
    n = v.size
    N = r.size
    for k in range(n):
        x = v[k]
        dv = x - vprev
        vprev = x
        s = 0.0
        for i in range(N):
            e = w[i] + dv
            e = r[i] if e > r[i] else e
            e = -r[i] if e < -r[i] else e
            w[i] = e
            s += p[i] * e
        out[k] = p0 * x + s
    return vprev


# ----------------------------------------------------------------------------
# specialised copies (made last: a copy sees the module's globals when it is made)
# ----------------------------------------------------------------------------
# The copies of the enveloped forward sum, one per envelope class: `_vd` bound
# to the class's evaluator, a call (LLVM inlines it; see `_kernels_envelopes`).
play_sum_closed = _specialise(
    _play_sum_template, "play_sum_closed", _vd=_vd_closed_call,
    doc="`play_sum` for the built-in closed-form envelopes (Tanh, Atanh).")
play_sum_general = _specialise(
    _play_sum_template, "play_sum_general", _vd=_vd_general_call,
    doc="`play_sum` for any compiled envelope (Polynomial, Inverse, ...).")
