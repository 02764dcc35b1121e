"""Envelopes inside the compiled kernels (numba, ``cache=True``), and the
helper that makes specialised copies of a kernel (`_specialise`).

Envelopes inside kernels are a kind code and a parameter array (see
:mod:`hystcomp.envelopes`).  Outside its domain an envelope counts as -inf
(below) or +inf (above), so an operator boundary that leaves the domain never
binds.  The kernels themselves live in :mod:`hystcomp._kernels` (forward) and
:mod:`hystcomp._kernels_inverse` (exact inverse); :mod:`hystcomp._kernels`
re-exports every name of this module.
"""

import math
import types

import numpy as np
from llvmlite import ir
from numba import njit
from numba.core import cgutils
from numba.core import types as numba_types
from numba.extending import intrinsic

IDENTITY = 0
LINEAR = 1
TANH = 2
ATANH = 3
POLYNOMIAL = 4
INVERSE_OF = 5
CUSTOM = -1

_INF = np.inf


def _specialise(template, name, doc=None, callable_from_python=True, **bindings):
    """A compiled copy of the plain Python function `template` in which the
    global names in `bindings` refer to the given objects (other compiled
    functions).

    One source serves several copies that differ in the functions they call
    (e.g. the envelope evaluator of a solver), without numba-level inlining
    (which re-types a kernel at each call site and dominated the first-call
    compilation time) and without passing functions as arguments (a compiled
    caller that passes one cannot be cached).  Each copy is its own numba
    function named `name` (its own on-disk cache entry), compiled on its first
    call only; it sees the module's globals as they are when it is made.
    `callable_from_python` False: no CPython wrapper (a helper that only
    compiled code calls; less to compile).
    """
    glb = dict(template.__globals__)
    glb.update(bindings)
    func = types.FunctionType(template.__code__, glb, name, template.__defaults__, template.__closure__)
    func.__qualname__ = name
    func.__module__ = template.__module__
    func.__doc__ = doc if doc is not None else template.__doc__
    return njit(cache=True, nogil=True, no_cfunc_wrapper=True, no_cpython_wrapper=not callable_from_python)(func)


# ----------------------------------------------------------------------------
# envelopes
# ----------------------------------------------------------------------------
_ROUND_SHIFT = 6755399441055744.0   # 1.5 * 2**52


@intrinsic
def _pow2_of_shifted(typingctx, t):
    """``2**n`` for ``t = n + 1.5 * 2**52`` (n an integer in [-1022, 1023]):
    n sits in the low bits of t's mantissa and becomes the exponent field.
    No libm call, no branch (SIMD lanes)."""
    sig = numba_types.float64(numba_types.float64)

    def codegen(context, builder, signature, args):
        (t,) = args
        i64 = ir.IntType(64)
        n = builder.sub(builder.bitcast(t, i64), ir.Constant(i64, 0x4338000000000000))
        e = builder.shl(builder.add(n, ir.Constant(i64, 1023)), ir.Constant(i64, 52))
        return builder.bitcast(e, ir.DoubleType())
    return sig, codegen


@intrinsic
def _is_finite(typingctx, x):
    """True when the float64 `x` is neither NaN nor +-inf, from its exponent
    bits (all ones for NaN and inf), so that no fastmath flag can fold the
    test away (a float comparison such as ``x - x == 0`` may be, under
    ``nnan``/``ninf``).  One integer AND and compare, no branch."""
    sig = numba_types.boolean(numba_types.float64)

    def codegen(context, builder, signature, args):
        (v,) = args
        i64 = ir.IntType(64)
        expo = ir.Constant(i64, 0x7FF0000000000000)
        bits = builder.and_(builder.bitcast(v, i64), expo)
        return builder.icmp_unsigned("!=", bits, expo)
    return sig, codegen


@intrinsic
def _fma(typingctx, x, y, z):
    """``x * y + z`` with one rounding (llvm.fma: the FMA instruction of the
    CPU, in SIMD lanes too).  Written out rather than left to the compiler's
    contraction so that every kernel performs the same operations (bit-identical
    results between the SIMD forward, the inverse and the compiled loops)."""
    f64 = numba_types.float64
    sig = f64(f64, f64, f64)

    def codegen(context, builder, signature, args):
        dbl = ir.DoubleType()
        fn = cgutils.get_or_insert_function(builder.module, ir.FunctionType(dbl, [dbl, dbl, dbl]), "llvm.fma.f64")
        return builder.call(fn, args)
    return sig, codegen


# exp(f) = P(f) / P(-f) with P the [6/6] Pade numerator of exp, written
# P(f) = E(f^2) + f O(f^2); on |f| <= ln(2)/2 its relative error is below
# 2e-19 (the rounding of the arithmetic dominates).
def _pade_exp_coefficients():
    f = math.factorial
    c = [f(12 - j) * f(6) / (f(12) * f(j) * f(6 - j)) for j in range(7)]
    return c[2], c[4], c[6], c[1], c[3], c[5]


_E2, _E4, _E6, _O1, _O3, _O5 = _pade_exp_coefficients()
_LN2 = 0.6931471805599453
_INV_LN2 = 1.4426950408889634


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _tanh(x):
    """tanh(x) without a libm call or a branch, so that a loop over operators
    runs in SIMD lanes (the tanh mGPI forward, `play_sum_tanh`).

    x is clamped to [-20, 20] (tanh is +-1 in double precision beyond 19.1).
    With y = -2x = n ln2 + f (n integer, |f| <= ln2/2), s = 2**n and
    exp(f) = (E + fO)/(E - fO) (Pade [6/6], E and O even polynomials),
    ``tanh x = (1 - e^y)/(1 + e^y) = (E(1 - s) - fO(1 + s)) / (E(1 + s) - fO(1 - s))``:
    one division, and no cancellation (for n = 0 the numerator is -2 fO, so
    tanh keeps its relative accuracy near 0; for n != 0 the two terms of the
    numerator have the same sign or differ by a factor of 2 or more).
    Within 2.2 ulp of NumPy's tanh (relative; tests/test_tanh_kernel.py);
    tanh(+-inf) = +-1, tanh(-0) = +0, NaN stays NaN.  Every kernel evaluates
    a Tanh envelope with this function.
    """
    w = 20.0 if x > 20.0 else x
    w = -20.0 if w < -20.0 else w
    y = -2.0 * w
    # n = round(y / ln2): the shift by 1.5 * 2**52 rounds to an integer
    t = _fma(y, _INV_LN2, _ROUND_SHIFT)
    nf = t - _ROUND_SHIFT
    f = _fma(-nf, _LN2, y)
    f2 = f * f
    E = _fma(_fma(_fma(_E6, f2, _E4), f2, _E2), f2, 1.0)
    fO = f * _fma(_fma(_O5, f2, _O3), f2, _O1)
    s = _pow2_of_shifted(t)
    sm = 1.0 - s
    sp = 1.0 + s
    return _fma(E, sm, -fO * sp) / _fma(E, sp, -fO * sm)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _poly_value(prm, x):
    # prm = [lo, hi, c0, c1, ..., cn]  (c_k multiplies x**k)
    if x < prm[0]:
        return -_INF
    if x > prm[1]:
        return _INF
    n = prm.size
    s = prm[n - 1]
    for k in range(n - 2, 1, -1):
        s = s * x + prm[k]
    return s


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _poly_derivative(prm, x):
    if x < prm[0] or x > prm[1]:
        return _INF
    n = prm.size
    s = (n - 3) * prm[n - 1]
    for k in range(n - 2, 2, -1):
        s = s * x + (k - 2) * prm[k]
    return s


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _poly_inverse(prm, y):
    # safeguarded Newton on [lo, hi]
    lo = prm[0]
    hi = prm[1]
    flo = _poly_value(prm, lo)
    fhi = _poly_value(prm, hi)
    if y <= flo:
        return lo if y == flo else -_INF
    if y >= fhi:
        return hi if y == fhi else _INF
    x = lo + (hi - lo) * (y - flo) / (fhi - flo)
    for _ in range(200):
        f = _poly_value(prm, x) - y
        if f == 0.0:
            return x
        if f > 0.0:
            hi = x
        else:
            lo = x
        d = _poly_derivative(prm, x)
        xn = x - f / d if d > 0.0 else 0.5 * (lo + hi)
        if not (lo < xn < hi):
            xn = 0.5 * (lo + hi)
        if abs(xn - x) <= 4e-16 * (1.0 + abs(x)) or hi - lo <= 4e-16 * (1.0 + abs(x)):
            return xn
        x = xn
    return x


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _base_value(kind, prm, x):
    if kind == IDENTITY:
        return x
    if kind == LINEAR:
        return prm[0] * x
    if kind == TANH:
        return prm[0] * _tanh(_fma(prm[1], x, prm[2]))
    if kind == ATANH:
        u = prm[1] * x
        if u >= 1.0:
            return _INF
        if u <= -1.0:
            return -_INF
        return prm[0] * math.atanh(u) + prm[2]
    return _poly_value(prm, x)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _base_derivative(kind, prm, x):
    if kind == IDENTITY:
        return 1.0
    if kind == LINEAR:
        return prm[0]
    if kind == TANH:
        t = _tanh(_fma(prm[1], x, prm[2]))
        return prm[0] * prm[1] * (1.0 - t * t)
    if kind == ATANH:
        u = prm[1] * x
        if u >= 1.0 or u <= -1.0:
            return _INF
        return prm[0] * prm[1] / (1.0 - u * u)
    return _poly_derivative(prm, x)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _base_inverse(kind, prm, y):
    if kind == IDENTITY:
        return y
    if kind == LINEAR:
        return y / prm[0]
    if kind == TANH:
        u = (y / prm[0])
        if u >= 1.0:
            return _INF
        if u <= -1.0:
            return -_INF
        return (math.atanh(u) - prm[2]) / prm[1]
    if kind == ATANH:
        return _tanh((y - prm[2]) / prm[0]) / prm[1]
    return _poly_inverse(prm, y)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def env_value(kind, prm, x):
    """Value of a compiled envelope; kind INVERSE_OF wraps a base kind:
    prm = [inner kind, inner params...]."""
    if kind == INVERSE_OF:
        return _base_inverse(int(prm[0]), prm[1:], x)
    return _base_value(kind, prm, x)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def env_derivative(kind, prm, x):
    if kind == INVERSE_OF:
        ik = int(prm[0])
        return 1.0 / _base_derivative(ik, prm[1:], _base_inverse(ik, prm[1:], x))
    return _base_derivative(kind, prm, x)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def env_inverse(kind, prm, y):
    """Inverse of a compiled envelope; +-inf outside its range."""
    if kind == INVERSE_OF:
        return _base_value(int(prm[0]), prm[1:], y)
    return _base_inverse(kind, prm, y)


# Fast paths.  Dispatching through env_value (a call that takes the
# parameter array) costs ~20 ns per evaluation here, more than the envelope
# itself, and an opaque call in a loop blocks the compiler's optimisations;
# so the kernels' inner loops use these versions, which take the first three
# parameters as scalars (see `_prm3`) and compute the built-in closed forms
# with exactly the same floating-point operations as `_base_value` /
# `_val_der` (so results are bit-identical); only Polynomial and Inverse
# reach the general code, and only in loops compiled with gen=True.
# (numba-level inlining: LLVM alone leaves the tanh paths ~30 % slower; it
# costs first-use compilation time, so the number of call sites is kept small.)
@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _prm3(prm):
    a = prm[0] if prm.size > 0 else 0.0
    b = prm[1] if prm.size > 1 else 0.0
    c = prm[2] if prm.size > 2 else 0.0
    return a, b, c


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _fval(kind, prm, a, b, c, x, gen):
    """env_value(kind, prm, x) with (a, b, c) = _prm3(prm).  `gen` False
    promises a built-in closed-form kind (Identity, Linear, Tanh, Atanh): the
    general fallback is then compiled out of the caller's loop."""
    if kind == TANH:
        return a * _tanh(_fma(b, x, c))
    if kind == IDENTITY:
        return x
    if kind == LINEAR:
        return a * x
    if kind == ATANH:
        u = b * x
        if u >= 1.0:
            return _INF
        if u <= -1.0:
            return -_INF
        return a * math.atanh(u) + c
    if gen:
        return _slow_value(kind, prm, x)
    return np.nan


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _fval_der(kind, prm, a, b, c, x, gen):
    """_val_der(kind, prm, x) with (a, b, c) = _prm3(prm); `gen` as in `_fval`."""
    if kind == TANH:
        t = _tanh(_fma(b, x, c))
        return a * t, a * b * (1.0 - t * t)
    if kind == IDENTITY:
        return x, 1.0
    if kind == LINEAR:
        return a * x, a
    if kind == ATANH:
        u = b * x
        if u >= 1.0:
            return _INF, _INF
        if u <= -1.0:
            return -_INF, _INF
        return a * math.atanh(u) + c, a * b / (1.0 - u * u)
    if gen:
        return _slow_val_der(kind, prm, x)
    return np.nan, np.nan


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _slow_value(kind, prm, x):
    return env_value(kind, prm, x)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _slow_val_der(kind, prm, x):
    return env_value(kind, prm, x), env_derivative(kind, prm, x)


# Envelope evaluators bound into the specialised copies of the kernels (see
# `_specialise`): (g(x), g'(x)) with the same operations as `_fval_der`
# (bit-identical results).  Each copy compiles only the envelope code of its
# class, and the big kernel bodies are no longer inlined into one another by
# numba (re-typing them at every call site dominated the first-call
# compilation time).  `_vd_*` are inlined by numba where a solver runs them
# per operator (as calls, the tanh inverse ran 1.5x slower); `_vd_*_call`
# (the same, compiled as functions) serve everywhere else: the forward sums
# (LLVM inlines them and drops the unused derivative: same speed, half the
# compilation time) and the solvers' once-per-iteration evaluations.
@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _vd_identity(kind, prm, a, b, c, x):
    """(g(x), g'(x)) of the identity envelope (PI)."""
    return x, 1.0


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _vd_closed(kind, prm, a, b, c, x):
    """(g(x), g'(x)) of a built-in closed-form envelope (Identity, Linear,
    Tanh, Atanh); NaN for the others."""
    return _fval_der(kind, prm, a, b, c, x, False)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _vd_general(kind, prm, a, b, c, x):
    """(g(x), g'(x)) of any compiled envelope."""
    return _fval_der(kind, prm, a, b, c, x, True)


_vd_closed_call = _specialise(_vd_closed.py_func, "_vd_closed_call", callable_from_python=False)
_vd_general_call = _specialise(_vd_general.py_func, "_vd_general_call", callable_from_python=False)


# ----------------------------------------------------------------------------
# SIMD lanes of the branch-free kernels (play_sum_tanh, play_solve_pi/_tanh)
# ----------------------------------------------------------------------------
@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True, inline="always")
def _fill_lanes(r, p, p0, z, z0, rr, pp, zz):
    """Fill the lanes (rr, pp, zz) of a branch-free kernel, of size M = the
    next multiple of 4 above N: lane 0 the p0 term (threshold 0, position
    z0), lanes 1..N the operators, then operators that never move (infinite
    threshold) and weigh 0."""
    N = r.size
    rr[0] = 0.0
    pp[0] = p0
    zz[0] = z0
    for i in range(N):
        rr[i + 1] = r[i]
        pp[i + 1] = p[i]
        zz[i + 1] = z[i]
    for i in range(N + 1, rr.size):
        rr[i] = _INF
        pp[i] = 0.0
        zz[i] = 0.0


# ----------------------------------------------------------------------------
# operator step shared by the forward and inverse kernels
# ----------------------------------------------------------------------------
@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _fmplay(x, ri, wi, kl, pl, al, bl, cl, kr, pr, ar, br, cr, gen):
    hi = _fval(kr, pr, ar, br, cr, x + ri, gen)
    if wi > hi:
        wi = hi
    lo = _fval(kl, pl, al, bl, cl, x - ri, gen)
    if wi < lo:
        wi = lo
    return wi
