"""Compiled sample loops (numba, ``cache=True``).

One kernel per operator family; every driver (simulate, inverses,
identification regressors, fast loops) calls these and nothing else runs the
play recursion.

Envelopes inside kernels are a kind code and a parameter array (see
:mod:`hystcomp.envelopes`): the value of a built-in envelope is computed
inline.  Outside its domain an envelope counts as -inf (below) or +inf
(above), so an operator boundary that leaves the domain never binds.

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


# ----------------------------------------------------------------------------
# envelopes
# ----------------------------------------------------------------------------
@njit(cache=True, inline="always")
def _tanh(x):
    # tanh through expm1 of a non-positive argument: accurate to a few ulp
    # and about twice as fast as libm's tanh here.
    if x >= 0.0:
        e = math.expm1(-2.0 * x)
        return -e / (e + 2.0)
    e = math.expm1(2.0 * x)
    return e / (e + 2.0)


@njit(cache=True)
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


@njit(cache=True)
def _poly_derivative(prm, x):
    if x < prm[0] or x > prm[1]:
        return _INF
    n = prm.size
    s = (n - 3) * prm[n - 1]
    for k in range(n - 2, 2, -1):
        s = s * x + (k - 2) * prm[k]
    return s


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True, inline="always")
def env_value(kind, prm, x):
    """Value of a compiled envelope; kind INVERSE_OF wraps a base kind:
    prm = [inner kind, inner params...]."""
    if kind == INVERSE_OF:
        return _base_inverse(int(prm[0]), prm[1:], x)
    return _base_value(kind, prm, x)


@njit(cache=True, inline="always")
def env_derivative(kind, prm, x):
    if kind == INVERSE_OF:
        ik = int(prm[0])
        return 1.0 / _base_derivative(ik, prm[1:], _base_inverse(ik, prm[1:], x))
    return _base_derivative(kind, prm, x)


@njit(cache=True)
def env_inverse(kind, prm, y):
    """Inverse of a compiled envelope; +-inf outside its range."""
    if kind == INVERSE_OF:
        return _base_value(int(prm[0]), prm[1:], y)
    return _base_inverse(kind, prm, y)


# ----------------------------------------------------------------------------
# forward kernels
# ----------------------------------------------------------------------------
@njit(cache=True)
def play_sum(v, r, p, p0, z, kind, prm, out):
    """Sum of weighted enveloped plays: ``out = p0*g(v) + sum_i p_i g(F_ri[v])``.

    `z` (the play positions, input coordinates) is updated in place.  With
    ``kind == IDENTITY`` this is the PI model of eq. 18 (branch-free clamp);
    otherwise the symmetric mGPI of eq. 25/49 with ``g = gamma``.
    """
    n = v.size
    N = r.size
    if kind == IDENTITY or kind == LINEAR:
        scale = 1.0 if kind == IDENTITY else prm[0]
        for k in range(n):
            x = v[k]
            s = 0.0
            for i in range(N):
                zi = z[i]
                lo = x - r[i]
                hi = x + r[i]
                zi = lo if zi < lo else (hi if zi > hi else zi)
                z[i] = zi
                s += p[i] * zi
            out[k] = scale * (p0 * x + s)
        return
    g = np.empty(N)
    for i in range(N):
        g[i] = env_value(kind, prm, z[i])
    for k in range(n):
        x = v[k]
        s = 0.0
        for i in range(N):
            zi = z[i]
            lo = x - r[i]
            hi = x + r[i]
            if zi < lo:
                z[i] = lo
                g[i] = env_value(kind, prm, lo)
            elif zi > hi:
                z[i] = hi
                g[i] = env_value(kind, prm, hi)
            s += p[i] * g[i]
        out[k] = p0 * env_value(kind, prm, x) + s


@njit(cache=True)
def play_states(v, r, z, out):
    """Play positions for every sample: ``out[k, i] = F_ri[v](t_k)``.

    Used in blocks (bounded memory) for envelopes that have no compiled form
    and to build identification regressors.  `z` is updated in place.
    """
    n = v.size
    N = r.size
    for k in range(n):
        x = v[k]
        for i in range(N):
            zi = z[i]
            lo = x - r[i]
            hi = x + r[i]
            zi = lo if zi < lo else (hi if zi > hi else zi)
            z[i] = zi
            out[k, i] = zi


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True, inline="always")
def _mplay(x, ri, wi, kl, pl, kr, pr):
    hi = env_value(kr, pr, x + ri)
    if wi > hi:
        wi = hi
    lo = env_value(kl, pl, x - ri)
    if wi < lo:
        wi = lo
    return wi


@njit(cache=True)
def mplay_sum(v, r, p, w, kl, pl, kr, pr, out):
    """Modified generalized plays with two envelopes (eq. 23).

    ``w_i <- max(gl(v - r_i), min(gr(v + r_i), w_i))``; `r` includes the
    r = 0 operator of p0 (eq. 25).  ``out = sum_i p_i w_i``.
    """
    n = v.size
    N = r.size
    for k in range(n):
        x = v[k]
        s = 0.0
        for i in range(N):
            wi = _mplay(x, r[i], w[i], kl, pl, kr, pr)
            w[i] = wi
            s += p[i] * wi
        out[k] = s


@njit(cache=True)
def mplay_states(v, r, w, kl, pl, kr, pr, out):
    n = v.size
    N = r.size
    for k in range(n):
        x = v[k]
        for i in range(N):
            wi = _mplay(x, r[i], w[i], kl, pl, kr, pr)
            w[i] = wi
            out[k, i] = wi


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True, inline="always")
def _val_der(kind, prm, x):
    if kind == TANH:
        t = _tanh(prm[1] * x + prm[2])
        return prm[0] * t, prm[0] * prm[1] * (1.0 - t * t)
    return env_value(kind, prm, x), env_derivative(kind, prm, x)


@njit(cache=True)
def _output_and_slopes(fam, x, xprev, r, p, p0, state, cache,
                       kl, pl, kr, pr, kh, ph, hscale):
    """Model output for a new input x from the current state, with the
    right and left derivatives (the state is not changed)."""
    N = r.size
    y = 0.0
    sr = 0.0
    sl = 0.0
    if fam == FAM_PLAY:
        g, dg = _val_der(kl, pl, x)
        y = p0 * g
        sr = p0 * dg
        sl = sr
        for i in range(N):
            zi = state[i]
            lo = x - r[i]
            hi = x + r[i]
            if zi <= lo:
                gi, di = _val_der(kl, pl, lo)
                y += p[i] * gi
                sr += p[i] * di
                if zi < lo:
                    sl += p[i] * di
            elif zi >= hi:
                gi, di = _val_der(kl, pl, hi)
                y += p[i] * gi
                sl += p[i] * di
                if zi > hi:
                    sr += p[i] * di
            else:
                y += p[i] * cache[i]
    elif fam == FAM_MPLAY:
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


@njit(cache=True)
def _advance(fam, x, xprev, r, state, cache, kl, pl, kr, pr):
    """Update the state for the new input x (the forward step)."""
    N = r.size
    if fam == FAM_PLAY:
        for i in range(N):
            zi = state[i]
            lo = x - r[i]
            hi = x + r[i]
            if zi < lo:
                state[i] = lo
                cache[i] = env_value(kl, pl, lo)
            elif zi > hi:
                state[i] = hi
                cache[i] = env_value(kl, pl, hi)
    elif fam == FAM_MPLAY:
        for i in range(N):
            state[i] = _mplay(x, r[i], state[i], kl, pl, kr, pr)
    elif fam == FAM_GPI:
        a = env_value(kl, pl, x)
        b = env_value(kr, pr, x)
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


@njit(cache=True)
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
    N = r.size
    cache = np.empty(N)
    if fam == FAM_PLAY:
        for i in range(N):
            cache[i] = env_value(kl, pl, state[i])
    n_clip = 0
    first = -1
    max_it = 0
    for k in range(u.size):
        target = u[k]
        tol = rtol * (1.0 + abs(target))
        x = xprev
        y, sr, sl = _output_and_slopes(fam, x, xprev, r, p, p0, state, cache,
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
            y, sr, sl = _output_and_slopes(fam, xn, xprev, r, p, p0, state, cache,
                                           kl, pl, kr, pr, kh, ph, hscale)
            f = y - target
            x = xn
            if f < 0.0:
                lo = x
                if x >= xmax:
                    break  # above the largest reachable output: clip
            elif f > 0.0:
                hi = x
                if x <= xmin:
                    break
            if hi - lo <= 1e-15 * (1.0 + abs(x)):
                break
        if abs(f) > tol and (x >= xmax or x <= xmin):
            n_clip += 1
            if first < 0:
                first = k
        if it > max_it:
            max_it = it
        _advance(fam, x, xprev, r, state, cache, kl, pl, kr, pr)
        xprev = x
        out[k] = x
    info[0] = n_clip
    info[1] = first
    info[2] = max_it
    return xprev
