"""Compiled sample loops (numba, ``cache=True``).

One kernel per operator family; every driver (simulate, inverses,
identification regressors, fast loops) calls these and nothing else runs the
play recursion.

Envelopes inside kernels are a kind code and a parameter array (see
:mod:`hystcomp.envelopes`): the value of a built-in envelope is computed
inline.  Outside its domain an envelope counts as -inf (below) or +inf
(above), so an operator boundary that leaves the domain never binds.

Speed (see benchmarks/bench_models.py): inner loops evaluate built-in
envelopes inline (`_fval`, `_fval_der`) and the hot kernels are compiled in
a few copies (built-in closed forms without the general fallback in the
loop, the rest with it; the PI inverse with a constant kind).  Each copy is
a separate compiled function, so that a call compiles only the copy it needs
(Python callers choose it with `play_sum_kernel` / `inverse_kernel`; compiled
callers go through the dispatching `play_sum` / `inverse_solve`).
Every kernel releases the GIL (``nogil=True``).  The PI forward sum
(`pi_sum`) may reassociate the sum over operators (fastmath reassoc and
contract only: NaN and inf keep their meaning), so it runs in SIMD lanes;
its results are within a few ulp of the plain formula.  Every other fast path
performs the same floating-point operations in the same order as the plain
formulas.  Either way the operations do not depend on how a record is cut,
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

import math
import types

import numpy as np
from numba import njit

IDENTITY = 0
LINEAR = 1
TANH = 2
ATANH = 3
POLYNOMIAL = 4
INVERSE_OF = 5
CUSTOM = -1

_INF = np.inf


def _specialise(template, name, doc=None, **bindings):
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
    """
    glb = dict(template.__globals__)
    glb.update(bindings)
    func = types.FunctionType(template.__code__, glb, name, template.__defaults__, template.__closure__)
    func.__qualname__ = name
    func.__module__ = template.__module__
    func.__doc__ = doc if doc is not None else template.__doc__
    return njit(cache=True, nogil=True)(func)


# ----------------------------------------------------------------------------
# envelopes
# ----------------------------------------------------------------------------
@njit(cache=True, nogil=True, inline="always")
def _tanh(x):
    # tanh within 2 ulp of libm's, cheaper: for |x| >= 0.55 the form
    # 1 - 2/(exp(2|x|) + 1) has no cancellation and exp costs less than expm1
    # (or tanh) in glibc; near 0 expm1 keeps full relative accuracy.
    a = abs(x)
    if a < 0.55:
        e = math.expm1(2.0 * a)
        t = e / (e + 2.0)
    else:
        t = 1.0 - 2.0 / (math.exp(2.0 * a) + 1.0)
    return t if x >= 0.0 else -t


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True)
def _poly_derivative(prm, x):
    if x < prm[0] or x > prm[1]:
        return _INF
    n = prm.size
    s = (n - 3) * prm[n - 1]
    for k in range(n - 2, 2, -1):
        s = s * x + (k - 2) * prm[k]
    return s


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True)
def _base_value(kind, prm, x):
    if kind == IDENTITY:
        return x
    if kind == LINEAR:
        return prm[0] * x
    if kind == TANH:
        return prm[0] * _tanh(prm[1] * x + prm[2])
    if kind == ATANH:
        u = prm[1] * x
        if u >= 1.0:
            return _INF
        if u <= -1.0:
            return -_INF
        return prm[0] * math.atanh(u) + prm[2]
    return _poly_value(prm, x)


@njit(cache=True, nogil=True)
def _base_derivative(kind, prm, x):
    if kind == IDENTITY:
        return 1.0
    if kind == LINEAR:
        return prm[0]
    if kind == TANH:
        t = _tanh(prm[1] * x + prm[2])
        return prm[0] * prm[1] * (1.0 - t * t)
    if kind == ATANH:
        u = prm[1] * x
        if u >= 1.0 or u <= -1.0:
            return _INF
        return prm[0] * prm[1] / (1.0 - u * u)
    return _poly_derivative(prm, x)


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True, inline="always")
def env_value(kind, prm, x):
    """Value of a compiled envelope; kind INVERSE_OF wraps a base kind:
    prm = [inner kind, inner params...]."""
    if kind == INVERSE_OF:
        return _base_inverse(int(prm[0]), prm[1:], x)
    return _base_value(kind, prm, x)


@njit(cache=True, nogil=True, inline="always")
def env_derivative(kind, prm, x):
    if kind == INVERSE_OF:
        ik = int(prm[0])
        return 1.0 / _base_derivative(ik, prm[1:], _base_inverse(ik, prm[1:], x))
    return _base_derivative(kind, prm, x)


@njit(cache=True, nogil=True)
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
@njit(cache=True, nogil=True, inline="always")
def _prm3(prm):
    a = prm[0] if prm.size > 0 else 0.0
    b = prm[1] if prm.size > 1 else 0.0
    c = prm[2] if prm.size > 2 else 0.0
    return a, b, c


@njit(cache=True, nogil=True, inline="always")
def _fval(kind, prm, a, b, c, x, gen):
    """env_value(kind, prm, x) with (a, b, c) = _prm3(prm).  `gen` False
    promises a built-in closed-form kind (Identity, Linear, Tanh, Atanh): the
    general fallback is then compiled out of the caller's loop."""
    if kind == TANH:
        return a * _tanh(b * x + c)
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


@njit(cache=True, nogil=True, inline="always")
def _fval_der(kind, prm, a, b, c, x, gen):
    """_val_der(kind, prm, x) with (a, b, c) = _prm3(prm); `gen` as in `_fval`."""
    if kind == TANH:
        t = _tanh(b * x + c)
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


@njit(cache=True, nogil=True)
def _slow_value(kind, prm, x):
    return env_value(kind, prm, x)


@njit(cache=True, nogil=True)
def _slow_val_der(kind, prm, x):
    return env_value(kind, prm, x), env_derivative(kind, prm, x)


@njit(cache=True, nogil=True)
def _v_closed(kind, prm, a, b, c, x):
    """g(x) of a built-in closed-form envelope; NaN for the others."""
    return _fval(kind, prm, a, b, c, x, False)


@njit(cache=True, nogil=True)
def _v_general(kind, prm, a, b, c, x):
    """g(x) of any compiled envelope."""
    return _fval(kind, prm, a, b, c, x, True)


# Envelope evaluators bound into the specialised copies of the kernels (see
# `_specialise` and the end of this module): `_v_*` give g(x), `_vd_*`
# (g(x), g'(x)), with the same operations as `_fval` / `_fval_der`
# (bit-identical results).  Each copy compiles only the envelope code of its
# class, and the big kernel bodies are no longer inlined into one another by
# numba (re-typing them at every call site dominated the first-call
# compilation time).  The forward sums call `_v_*` (LLVM inlines them: same
# speed, half the compilation time of numba-level inlining); the solvers
# inline `_vd_*` in numba where they run per operator (as calls, the tanh
# inverse ran 1.5x slower).
@njit(cache=True, nogil=True, inline="always")
def _vd_identity(kind, prm, a, b, c, x):
    """(g(x), g'(x)) of the identity envelope (PI)."""
    return x, 1.0


@njit(cache=True, nogil=True, inline="always")
def _vd_closed(kind, prm, a, b, c, x):
    """(g(x), g'(x)) of a built-in closed-form envelope (Identity, Linear,
    Tanh, Atanh); NaN for the others."""
    return _fval_der(kind, prm, a, b, c, x, False)


@njit(cache=True, nogil=True, inline="always")
def _vd_general(kind, prm, a, b, c, x):
    """(g(x), g'(x)) of any compiled envelope."""
    return _fval_der(kind, prm, a, b, c, x, True)


# ----------------------------------------------------------------------------
# forward kernels
# ----------------------------------------------------------------------------
# fastmath only for reassociation and contraction (FMA) of the operator sum,
# so that it runs in SIMD lanes; never nnan/ninf/nsz (NaN and inf keep their
# IEEE meaning).  The flags are fixed per compiled function, so a chunked run
# performs the same operations as a one-shot run (bit for bit).
_SUM_FLAGS = {"reassoc", "contract"}


@njit(cache=True, nogil=True, fastmath=_SUM_FLAGS)
def pi_sum(v, r, p, p0, z, scale, out):
    """PI model (eq. 18), scaled by `scale` (a Linear envelope):
    ``out = scale * (p0 v + sum_i p_i F_ri[v])``; `z` updated in place.

    Branch-free play update ``z_i = min(max(z_i, v - r_i), v + r_i)`` with a
    reassociated sum over operators (vectorised).
    """
    n = v.size
    N = r.size
    for k in range(n):
        x = v[k]
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


def play_sum_kernel(kind):
    """The compiled kernel `play_sum` would use for envelope `kind`, chosen in
    Python so that a call compiles only that kernel (cold start).  Returns
    ``(kernel, takes_scale)``: PI-like kinds take ``scale`` instead of
    ``(kind, prm)``."""
    if kind == IDENTITY or kind == LINEAR:
        return pi_sum, True
    if kind == TANH or kind == ATANH:
        return play_sum_closed, False
    return play_sum_general, False


def run_play_sum(v, r, p, p0, z, kind, prm, out):
    """Python-side `play_sum`: same results, compiles only the kernel the
    envelope kind needs."""
    kernel, scaled = play_sum_kernel(kind)
    if scaled:
        kernel(v, r, p, p0, z, 1.0 if kind == IDENTITY else float(prm[0]), out)
    else:
        kernel(v, r, p, p0, z, kind, prm, out)


@njit(cache=True, nogil=True)
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
    elif kind == TANH or kind == ATANH:
        play_sum_closed(v, r, p, p0, z, kind, prm, out)
    else:
        play_sum_general(v, r, p, p0, z, kind, prm, out)


def _play_sum_template(v, r, p, p0, z, kind, prm, out):
    """`play_sum` with an envelope: g = gamma(z) is kept per operator and
    re-evaluated only for the operators that move.  `_v` evaluates the
    envelope (see the copies at the end of the module)."""
    n = v.size
    N = r.size
    a, b, c = _prm3(prm)
    g = np.empty(N)
    for i in range(N):
        g[i] = _v(kind, prm, a, b, c, z[i])
    for k in range(n):
        x = v[k]
        s = 0.0
        for i in range(N):
            zi = z[i]
            lo = x - r[i]
            hi = x + r[i]
            if zi < lo:
                z[i] = lo
                g[i] = _v(kind, prm, a, b, c, lo)
            elif zi > hi:
                z[i] = hi
                g[i] = _v(kind, prm, a, b, c, hi)
            s += p[i] * g[i]
        out[k] = p0 * _v(kind, prm, a, b, c, x) + s


@njit(cache=True, nogil=True, inline="always")
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


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True, inline="always")
def _fmplay(x, ri, wi, kl, pl, al, bl, cl, kr, pr, ar, br, cr, gen):
    hi = _fval(kr, pr, ar, br, cr, x + ri, gen)
    if wi > hi:
        wi = hi
    lo = _fval(kl, pl, al, bl, cl, x - ri, gen)
    if wi < lo:
        wi = lo
    return wi


@njit(cache=True, nogil=True)
def mplay_sum_closed(v, r, p, w, kl, pl, kr, pr, out):
    """`mplay_sum` for the built-in closed-form envelopes (Identity, Linear,
    Tanh, Atanh on both sides)."""
    _mplay_sum_body(v, r, p, w, kl, pl, kr, pr, out, False)


@njit(cache=True, nogil=True)
def mplay_sum_general(v, r, p, w, kl, pl, kr, pr, out):
    """`mplay_sum` for any compiled envelopes."""
    _mplay_sum_body(v, r, p, w, kl, pl, kr, pr, out, True)


def mplay_sum_kernel(kl, kr):
    """The compiled kernel `mplay_sum` uses for envelope kinds (kl, kr),
    chosen in Python so that a call compiles only that one."""
    if IDENTITY <= kl <= ATANH and IDENTITY <= kr <= ATANH:
        return mplay_sum_closed
    return mplay_sum_general


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True, inline="always")
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


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True)
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
# exact inverse: per-sample monotone solve
# ----------------------------------------------------------------------------
FAM_PLAY = 0    # symmetric plays with envelope g (PI, mGPI gl = gr); state z
FAM_MPLAY = 1   # modified plays with gl != gr; state w (r includes 0)
FAM_GPI = 2     # generalized plays; state w; memoryless H(x) = hk(x)
FAM_STOP = 3    # stops; state w, memoryless p0 x


@njit(cache=True, nogil=True)
def _val_der(kind, prm, x):
    a, b, c = _prm3(prm)
    return _fval_der(kind, prm, a, b, c, x, True)


@njit(cache=True, nogil=True)
def _output_and_slopes(fam, x, xprev, r, p, p0, state,
                       kl, pl, kr, pr, kh, ph, hscale):
    """Model output for a new input x from the current state, with the
    right and left derivatives (the state is not changed).  Families
    FAM_MPLAY, FAM_GPI and FAM_STOP (FAM_PLAY: `_play_eval_template`)."""
    N = r.size
    y = 0.0
    sr = 0.0
    sl = 0.0
    if fam == FAM_MPLAY:
        for i in range(N):
            wi = state[i]
            lo, dlo = _val_der(kl, pl, x - r[i])
            hi, dhi = _val_der(kr, pr, x + r[i])
            v = wi if wi < hi else hi
            v = lo if lo > v else v
            y += p[i] * v
            # right derivative
            if lo >= wi or lo >= hi:
                sr += p[i] * dlo
            elif hi < wi:
                sr += p[i] * dhi
            # left derivative
            if hi <= wi and hi >= lo:
                sl += p[i] * dhi
            elif lo > wi or lo > hi:
                sl += p[i] * dlo
    elif fam == FAM_GPI:
        a, da = _val_der(kl, pl, x)
        b, db = _val_der(kr, pr, x)
        if hscale != 0.0:
            h, dh = _val_der(kh, ph, x)
            y = hscale * h
            sr = hscale * dh
            sl = sr
        for i in range(N):
            wi = state[i]
            lo = a - r[i]
            hi = b + r[i]
            v = wi if wi < hi else hi
            v = lo if lo > v else v
            y += p[i] * v
            if lo >= wi or lo >= hi:
                sr += p[i] * da
            elif hi < wi:
                sr += p[i] * db
            if hi <= wi and hi >= lo:
                sl += p[i] * db
            elif lo > wi or lo > hi:
                sl += p[i] * da
    else:  # FAM_STOP
        y = p0 * x
        sr = p0
        sl = p0
        dx = x - xprev
        for i in range(N):
            e = state[i] + dx
            v = r[i] if e > r[i] else e
            v = -r[i] if v < -r[i] else v
            y += p[i] * v
            if -r[i] <= e < r[i]:
                sr += p[i]
            if -r[i] < e <= r[i]:
                sl += p[i]
    return y, sr, sl


@njit(cache=True, nogil=True)
def _advance(fam, x, xprev, r, state, kl, pl, kr, pr):
    """Update the state for the new input x (the forward step); families
    FAM_MPLAY, FAM_GPI and FAM_STOP (FAM_PLAY: in `_play_solve_template`)."""
    N = r.size
    if fam == FAM_MPLAY:
        al, bl, cl = _prm3(pl)
        ar, br, cr = _prm3(pr)
        for i in range(N):
            state[i] = _fmplay(x, r[i], state[i], kl, pl, al, bl, cl, kr, pr, ar, br, cr, True)
    elif fam == FAM_GPI:
        al, bl, cl = _prm3(pl)
        ar, br, cr = _prm3(pr)
        a = _fval(kl, pl, al, bl, cl, x, True)
        b = _fval(kr, pr, ar, br, cr, x, True)
        for i in range(N):
            wi = state[i]
            hi = b + r[i]
            lo = a - r[i]
            wi = hi if wi > hi else wi
            wi = lo if wi < lo else wi
            state[i] = wi
    else:
        dx = x - xprev
        for i in range(N):
            e = state[i] + dx
            e = r[i] if e > r[i] else e
            e = -r[i] if e < -r[i] else e
            state[i] = e


@njit(cache=True, nogil=True, inline="always")
def _newton_point(f, x, xprev, lo, hi, sr, sl, checked_limit):
    """Next trial input: Newton with the one-sided slope on the side of the
    root, kept inside the bracket (lo, hi); returns (x_new, checked_limit)."""
    s = sr if f < 0.0 else sl
    xn = x - f / s if s > 0.0 else np.nan
    if not (xn > lo and xn < hi):
        lim = hi if f < 0.0 else lo
        if not checked_limit and math.isfinite(lim):
            # try the input limit itself once: detects unreachable targets
            checked_limit = True
            xn = lim
        elif math.isfinite(lo) and math.isfinite(hi):
            xn = 0.5 * (lo + hi)
        else:
            step = max(1.0, 2.0 * abs(x - xprev))
            xn = x + step if f < 0.0 else x - step
    return xn, checked_limit


@njit(cache=True, nogil=True, inline="always")
def _shrink(f, x, lo, hi, xmin, xmax):
    """Bracket update after evaluating f at x; returns (lo, hi, stop)."""
    if f < 0.0:
        lo = x
        if x >= xmax:
            return lo, hi, True  # above the largest reachable output: clip
    elif f > 0.0:
        hi = x
        if x <= xmin:
            return lo, hi, True
    return lo, hi, hi - lo <= 1e-15 * (1.0 + abs(x))


def _play_eval_template(x, r, p, p0, g0, dg0, state, cache, dcache, sv, sd, kind, prm, a, b, c):
    """Output and one-sided slopes of a PI / symmetric mGPI for a new input x.

    ``y = p0 g(x) + sum_i p_i g(clamp(z_i, x - r_i, x + r_i))``; the right
    slope sr counts the operators that move when x increases (z_i <= x - r_i
    or z_i > x + r_i), the left slope sl those that move when it decreases
    (z_i < x - r_i or z_i >= x + r_i).  g0, dg0 = g(x), g'(x) are given.  The
    envelope (`_vd`, one of the `_vd_*` evaluators) is evaluated only for
    operators that move strictly; one sitting
    on a boundary (z_i == x -+ r_i, e.g. all of them at the previous input)
    reuses its cached value and slope (cache = g(z), dcache = g'(z)).  The
    values of the moving operators are left in sv, sd for the state update.
    """
    y = p0 * g0
    sr = p0 * dg0
    sl = sr
    for i in range(r.size):
        zi = state[i]
        lo = x - r[i]
        hi = x + r[i]
        if zi < lo or zi > hi:
            gi, di = _vd(kind, prm, a, b, c, lo if zi < lo else hi)
            sv[i] = gi
            sd[i] = di
            y += p[i] * gi
            sr += p[i] * di
            sl += p[i] * di
        else:
            y += p[i] * cache[i]
            if zi == lo:
                sr += p[i] * dcache[i]
            elif zi == hi:
                sl += p[i] * dcache[i]
    return y, sr, sl


@njit(cache=True, nogil=True)
def _play_solve(u, r, p, p0, state, xprev, kind, prm, xmin, xmax, rtol, out, info):
    """`inverse_solve` for FAM_PLAY: three compiled copies, one per kind class
    (each is compiled on first use only; Python callers pick one through
    `inverse_kernel`)."""
    if kind == IDENTITY:
        return play_solve_pi(u, r, p, p0, state, xprev, kind, prm, xmin, xmax, rtol, out, info)
    if kind == LINEAR or kind == TANH or kind == ATANH:
        return play_solve_closed(u, r, p, p0, state, xprev, kind, prm, xmin, xmax, rtol, out, info)
    return play_solve_general(u, r, p, p0, state, xprev, kind, prm, xmin, xmax, rtol, out, info)


def _play_solve_template(u, r, p, p0, state, xprev, kind, prm, xmin, xmax, rtol, out, info):
    """`inverse_solve` for FAM_PLAY (PI and symmetric mGPI).

    The same iteration as the general solver, with less work per sample:
    the output at the previous input (the starting point) needs no envelope
    evaluation (every operator sits inside or on its boundaries there, with
    cached values and slopes, and the p0 term is the one of the previous
    sample's last iterate), and the state update reuses the envelope values
    of the last iterate, which is the accepted input.
    """
    N = r.size
    a, b, c = _prm3(prm)
    cache = np.empty(N)
    dcache = np.empty(N)
    sv = np.empty(N)
    sd = np.empty(N)
    for i in range(N):
        cache[i], dcache[i] = _vd(kind, prm, a, b, c, state[i])
    gx, dgx = _vd(kind, prm, a, b, c, xprev)
    # output and one-sided slopes at the starting point (the previous input),
    # carried over from the state update of the previous sample
    y0 = 0.0
    sr0 = 0.0
    sl0 = 0.0
    n_clip = 0
    first = -1
    max_it = 0
    for k in range(u.size):
        target = u[k]
        tol = rtol * (1.0 + abs(target))
        x = xprev
        if k > 0:
            y, sr, sl = y0, sr0, sl0
        else:
            # the initial state need not sit inside the boundaries at xprev
            y, sr, sl = _play_eval(x, r, p, p0, gx, dgx, state, cache, dcache, sv, sd, kind, prm, a, b, c)
        f = y - target
        if f < 0.0:
            lo = x
            hi = xmax
        else:
            hi = x
            lo = xmin
        checked_limit = False
        it = 0
        while abs(f) > tol and it < 200:
            it += 1
            x, checked_limit = _newton_point(f, x, xprev, lo, hi, sr, sl, checked_limit)
            gx, dgx = _vd(kind, prm, a, b, c, x)
            y, sr, sl = _play_eval(x, r, p, p0, gx, dgx, state, cache, dcache, sv, sd, kind, prm, a, b, c)
            f = y - target
            lo, hi, stop = _shrink(f, x, lo, hi, xmin, xmax)
            if stop:
                break
        if abs(f) > tol and (x >= xmax or x <= xmin):
            n_clip += 1
            if first < 0:
                first = k
        if it > max_it:
            max_it = it
        # advance the state to x, the last point evaluated (sv, sd hold the
        # envelope at the new positions of the operators that move), and
        # compute in the same pass the output and slopes at x for the next
        # sample: every operator is then inside or on its boundaries, so this
        # is `_play_eval(x)` term by term (same sums, same order).
        y0 = p0 * gx
        sr0 = p0 * dgx
        sl0 = sr0
        for i in range(N):
            zi = state[i]
            lo_i = x - r[i]
            hi_i = x + r[i]
            if zi < lo_i:
                zi = lo_i
                state[i] = zi
                cache[i] = sv[i]
                dcache[i] = sd[i]
            elif zi > hi_i:
                zi = hi_i
                state[i] = zi
                cache[i] = sv[i]
                dcache[i] = sd[i]
            y0 += p[i] * cache[i]
            if zi == lo_i:
                sr0 += p[i] * dcache[i]
            elif zi == hi_i:
                sl0 += p[i] * dcache[i]
        xprev = x
        out[k] = x
    info[0] = n_clip
    info[1] = first
    info[2] = max_it
    return xprev


@njit(cache=True, nogil=True)
def inverse_solve(fam, u, r, p, p0, state, xprev, kl, pl, kr, pr, kh, ph, hscale,
                  xmin, xmax, rtol, out, info):
    """Exact inverse: for each target u[k] find x with Y(x; state) = u[k].

    Y is the model's output for a new input x given the state; it is
    monotone in x and smooth between the points where an operator starts
    or stops moving.  A Newton step with the one-sided slope on the side of
    the root (the active set of moving operators) is kept inside a bracket
    and replaced by bisection when it leaves it, so piecewise-linear models
    (PI) are solved exactly in as many steps as kinks are crossed and smooth
    envelopes converge quadratically.  Targets beyond Y(xmin) or Y(xmax) are
    clipped there.  info[0] = number of clipped samples, info[1] = first one,
    info[2] = largest iteration count.  Returns the last input.
    """
    if fam == FAM_PLAY:
        return _play_solve(u, r, p, p0, state, xprev, kl, pl, xmin, xmax, rtol, out, info)
    return inverse_solve_other(fam, u, r, p, p0, state, xprev, kl, pl, kr, pr, kh, ph, hscale,
                               xmin, xmax, rtol, out, info)


def inverse_kernel(fam, kind):
    """The compiled kernel `inverse_solve` uses for family `fam` and (for
    FAM_PLAY) envelope `kind`, chosen in Python so that a call compiles only
    that one.  Every kernel returned takes `inverse_solve`'s arguments."""
    if fam != FAM_PLAY:
        return inverse_solve_other
    if kind == IDENTITY:
        play = play_solve_pi
    elif kind == LINEAR or kind == TANH or kind == ATANH:
        play = play_solve_closed
    else:
        play = play_solve_general

    def solve(fam, u, r, p, p0, state, xprev, kl, pl, kr, pr, kh, ph, hscale, xmin, xmax, rtol, out, info):
        return play(u, r, p, p0, state, xprev, kl, pl, xmin, xmax, rtol, out, info)
    return solve


@njit(cache=True, nogil=True)
def inverse_solve_other(fam, u, r, p, p0, state, xprev, kl, pl, kr, pr, kh, ph, hscale,
                        xmin, xmax, rtol, out, info):
    """`inverse_solve` for the families FAM_MPLAY, FAM_GPI and FAM_STOP."""
    n_clip = 0
    first = -1
    max_it = 0
    for k in range(u.size):
        target = u[k]
        tol = rtol * (1.0 + abs(target))
        x = xprev
        y, sr, sl = _output_and_slopes(fam, x, xprev, r, p, p0, state,
                                       kl, pl, kr, pr, kh, ph, hscale)
        f = y - target
        if f < 0.0:
            lo = x
            hi = xmax
        else:
            hi = x
            lo = xmin
        checked_limit = False
        it = 0
        while abs(f) > tol and it < 200:
            it += 1
            x, checked_limit = _newton_point(f, x, xprev, lo, hi, sr, sl, checked_limit)
            y, sr, sl = _output_and_slopes(fam, x, xprev, r, p, p0, state,
                                           kl, pl, kr, pr, kh, ph, hscale)
            f = y - target
            lo, hi, stop = _shrink(f, x, lo, hi, xmin, xmax)
            if stop:
                break
        if abs(f) > tol and (x >= xmax or x <= xmin):
            n_clip += 1
            if first < 0:
                first = k
        if it > max_it:
            max_it = it
        _advance(fam, x, xprev, r, state, kl, pl, kr, pr)
        xprev = x
        out[k] = x
    info[0] = n_clip
    info[1] = first
    info[2] = max_it
    return xprev


# ----------------------------------------------------------------------------
# specialised copies (made last: a copy sees the module's globals when it is made)
# ----------------------------------------------------------------------------
# The copies of the FAM_PLAY solver, one per envelope class: the same code
# with `_vd` bound to the class's evaluator: inlined by numba in the loop over
# operators (`_play_eval_*`), a call in the solver itself (once per Newton
# iteration: inlining it there doubled the compilation time for no speed).
_vd_closed_call = _specialise(_vd_closed.py_func, "_vd_closed_call")
_vd_general_call = _specialise(_vd_general.py_func, "_vd_general_call")
_play_eval_pi = _specialise(_play_eval_template, "_play_eval_pi", _vd=_vd_identity)
_play_eval_closed = _specialise(_play_eval_template, "_play_eval_closed", _vd=_vd_closed)
_play_eval_general = _specialise(_play_eval_template, "_play_eval_general", _vd=_vd_general)
play_solve_pi = _specialise(
    _play_solve_template, "play_solve_pi", _vd=_vd_identity, _play_eval=_play_eval_pi,
    doc="`inverse_solve` for FAM_PLAY with the PI (identity envelope: no envelope code in the loops).")
play_solve_closed = _specialise(
    _play_solve_template, "play_solve_closed", _vd=_vd_closed_call, _play_eval=_play_eval_closed,
    doc="`inverse_solve` for FAM_PLAY with Identity, Linear, Tanh or Atanh (no general envelope code "
        "in the loops; ~3x faster than the general copy).")
play_solve_general = _specialise(
    _play_solve_template, "play_solve_general", _vd=_vd_general_call, _play_eval=_play_eval_general,
    doc="`inverse_solve` for FAM_PLAY with any compiled envelope.")

# The copies of the enveloped forward sum (same scheme).
play_sum_closed = _specialise(
    _play_sum_template, "play_sum_closed", _v=_v_closed,
    doc="`play_sum` for the built-in closed-form envelopes (Tanh, Atanh).")
play_sum_general = _specialise(
    _play_sum_template, "play_sum_general", _v=_v_general,
    doc="`play_sum` for any compiled envelope (Polynomial, Inverse, ...).")
