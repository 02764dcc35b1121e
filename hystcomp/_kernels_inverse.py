"""Exact inverse kernels (numba, ``cache=True``): per-sample monotone solve.

For each target the input with ``Y(x; state) = target`` is found by Newton
steps on the one-sided slopes inside a bracket (see `inverse_solve`).  Python
callers choose the compiled copy with `inverse_kernel`; the FAM_PLAY solver
has one copy per envelope class (PI, closed forms, general), made from one
template with `_specialise`.  :mod:`hystcomp._kernels` re-exports every name
of this module.
"""

import math

import numpy as np
from numba import njit

from ._kernels_envelopes import (ATANH, IDENTITY, LINEAR, TANH, _fma, _fmplay, _fval, _fval_der, _prm3, _specialise,
                                 _fill_lanes, _tanh, _vd_closed, _vd_closed_call, _vd_general, _vd_general_call)

# ----------------------------------------------------------------------------
# exact inverse: per-sample monotone solve
# ----------------------------------------------------------------------------
# Names a template calls and each of its compiled copies binds to a compiled
# function (see `_specialise` and the end of this module); None here.
_vd = None
_play_eval = None
_lanes_eval = None

FAM_PLAY = 0    # symmetric plays with envelope g (PI, mGPI gl = gr); state z
FAM_MPLAY = 1   # modified plays with gl != gr; state w (r includes 0)
FAM_GPI = 2     # generalized plays; state w; memoryless H(x) = hk(x)
FAM_STOP = 3    # stops; state w, memoryless p0 x


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True)
def _val_der(kind, prm, x):
    a, b, c = _prm3(prm)
    return _fval_der(kind, prm, a, b, c, x, True)


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True)
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


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True)
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


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
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


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True, inline="always")
def _other_side(f, xp, fp, x_other, f_other):
    """The last trial input whose output missed the target on the other side
    of the newest trial's (f: the newest trial's miss; xp, fp: the trial
    before it): the far end of the bracket, where the output jumps across the
    target when the bracket closes without meeting it."""
    if (f < 0.0) != (fp < 0.0) and fp != 0.0:
        return xp, fp
    return x_other, f_other


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True, inline="always")
def _jump(f, x, sr, sl, x_other, f_other):
    """Whether the output jumps across the target between the newest trial x
    (miss f, one-sided slopes sr, sl) and the far end of the closed bracket
    (x_other, f_other): the two misses differ by more than a thousand times
    what the slope at x carries over the bracket's width.  A jump comes from a
    boundary that leaves an envelope's domain (-inf or +inf there, eq. 23) while
    the other envelope lies below it (crossing envelopes: a band that is
    inverted there); a steep but continuous output (an Atanh envelope near
    its domain's end) is not one."""
    if f_other == 0.0 or (f_other < 0.0) == (f < 0.0):
        return False
    return abs(f - f_other) > 1e3 * max(sr, sl, 0.0) * abs(x - x_other)


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True)
def _input_scale(r):
    """The model's input scale: its largest threshold (1 without a positive one)."""
    xs = 0.0
    for i in range(r.size):
        if r[i] > xs:
            xs = r[i]
    return xs if xs > 0.0 else 1.0


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _shrink(f, x, lo, hi, xmin, xmax, xs):
    """Bracket update after evaluating f at x; returns (lo, hi, stop).  The
    bracket is narrow enough at ``1e-15 (xs + |x|)``, xs the model's input
    scale (its largest threshold), so the stop is the same in any units."""
    if f < 0.0:
        lo = x
        if x >= xmax:
            return lo, hi, True  # above the largest reachable output: clip
    elif f > 0.0:
        hi = x
        if x <= xmin:
            return lo, hi, True
    return lo, hi, hi - lo <= 1e-15 * (xs + abs(x))


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


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _play_solve(u, r, p, p0, state, xprev, kind, prm, xmin, xmax, rtol, out, info):
    """`inverse_solve` for FAM_PLAY: three compiled copies, one per kind class
    (each is compiled on first use only; Python callers pick one through
    `inverse_kernel`)."""
    if kind == IDENTITY:
        return play_solve_pi(u, r, p, p0, state, xprev, kind, prm, xmin, xmax, rtol, out, info)
    if kind == TANH:
        return play_solve_tanh(u, r, p, p0, state, xprev, kind, prm, xmin, xmax, rtol, out, info)
    if kind == LINEAR or kind == ATANH:
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
    xs = _input_scale(r)
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
        x_other, f_other = x, f
        while abs(f) > tol and it < 200:
            it += 1
            xp, fp = x, f
            x, checked_limit = _newton_point(f, x, xprev, lo, hi, sr, sl, checked_limit)
            gx, dgx = _vd(kind, prm, a, b, c, x)
            y, sr, sl = _play_eval(x, r, p, p0, gx, dgx, state, cache, dcache, sv, sd, kind, prm, a, b, c)
            f = y - target
            x_other, f_other = _other_side(f, xp, fp, x_other, f_other)
            lo, hi, stop = _shrink(f, x, lo, hi, xmin, xmax, xs)
            if stop:
                break
        at_limit = x >= xmax or x <= xmin
        if abs(f) > tol and (at_limit or _jump(f, x, sr, sl, x_other, f_other)):
            # not met: beyond the outputs at the input limits, or inside a jump of
            # the output (the bracket closed on it): clipped to the nearer side
            if not at_limit and abs(f_other) < abs(f):
                x = x_other
                gx, dgx = _vd(kind, prm, a, b, c, x)
                y, sr, sl = _play_eval(x, r, p, p0, gx, dgx, state, cache, dcache, sv, sd, kind, prm, a, b, c)
                f = y - target
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


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True, fastmath={"reassoc", "contract"},
      error_model="numpy")
def _tanh_eval(x, rr, pp, zz, a, b, c):
    """Output and one-sided slopes of a tanh mGPI for a new input x, branch-free
    over every operator (SIMD lanes, as `_kernels.play_sum_tanh`): the lanes
    of `play_solve_tanh` (lane 0 the p0 term with threshold 0, padding lanes
    with an infinite threshold and weight 0).  An operator moving when x
    increases (z_i <= x - r_i, or z_i > x + r_i) counts in the right slope,
    one moving when x decreases (z_i < x - r_i, or z_i >= x + r_i) in the
    left one, as in `_play_eval_template`.  Also returns the slopes once the
    state is advanced to x (every operator then on or inside its boundaries:
    right slope those at z_i = x - r_i, left slope those at x + r_i), which
    are what an evaluation at x from the advanced state gives, bit for bit.
    Every value is a function of (x, z_i) alone.  (``error_model="numpy"``:
    see `play_sum_tanh`.)"""
    y = 0.0
    sr = 0.0
    sl = 0.0
    sra = 0.0
    sla = 0.0
    for i in range(rr.size):
        zi = zz[i]
        lo = x - rr[i]
        hi = x + rr[i]
        zc = lo if zi < lo else zi
        zc = hi if zc > hi else zc
        t = _tanh(_fma(b, zc, c))
        d = pp[i] * (1.0 - t * t)
        y += pp[i] * t
        sr += d if (zi <= lo) | (zi > hi) else 0.0
        sl += d if (zi < lo) | (zi >= hi) else 0.0
        sra += d if (zc <= lo) | (zc > hi) else 0.0
        sla += d if (zc < lo) | (zc >= hi) else 0.0
    ab = a * b
    return a * y, ab * sr, ab * sl, ab * sra, ab * sla


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True, fastmath={"reassoc", "contract"})
def _pi_eval(x, rr, pp, zz, a, b, c):
    """`_tanh_eval` for the PI (identity envelope; a, b, c unused): output
    and one-sided slopes, before and after advancing the state to x."""
    y = 0.0
    sr = 0.0
    sl = 0.0
    sra = 0.0
    sla = 0.0
    for i in range(rr.size):
        zi = zz[i]
        lo = x - rr[i]
        hi = x + rr[i]
        zc = lo if zi < lo else zi
        zc = hi if zc > hi else zc
        d = pp[i]
        y += d * zc
        sr += d if (zi <= lo) | (zi > hi) else 0.0
        sl += d if (zi < lo) | (zi >= hi) else 0.0
        sra += d if (zc <= lo) | (zc > hi) else 0.0
        sla += d if (zc < lo) | (zc >= hi) else 0.0
    return y, sr, sl, sra, sla


def _play_solve_lanes_template(u, r, p, p0, state, xprev, kind, prm, xmin, xmax, rtol, out, info):
    """`inverse_solve` for FAM_PLAY in SIMD lanes: the PI (`play_solve_pi`,
    `_lanes_eval` = `_pi_eval`) and the symmetric tanh mGPI
    (`play_solve_tanh`, `_tanh_eval`).

    The iteration of `_play_solve_template` (Newton on the one-sided slopes
    inside a bracket), with the output and slopes at each trial input
    evaluated by `_lanes_eval` over every operator in SIMD lanes instead of
    the moving operators one at a time with cached values.  The output and
    slopes at the accepted input (the next sample's starting point) are
    those `_lanes_eval` gives at that input from the advanced state, so a
    chunked run, which starts with that evaluation, equals a one-shot run
    bit for bit.
    """
    N = r.size
    a, b, c = _prm3(prm)
    M = (N + 4) // 4 * 4
    rr, pp, zz = np.empty(M), np.empty(M), np.empty(M)
    _fill_lanes(r, p, p0, state, xprev, rr, pp, zz)
    n_clip = 0
    first = -1
    max_it = 0
    xs = _input_scale(r)
    # output and slopes at the starting point (before and after advancing
    # the state to it: the initial state need not sit inside its boundaries)
    y, sr, sl, sra, sla = _lanes_eval(xprev, rr, pp, zz, a, b, c)
    for k in range(u.size):
        target = u[k]
        tol = rtol * (1.0 + abs(target))
        x = xprev
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
            y, sr, sl, sra, sla = _lanes_eval(x, rr, pp, zz, a, b, c)
            f = y - target
            lo, hi, stop = _shrink(f, x, lo, hi, xmin, xmax, xs)
            if stop:
                break
        if abs(f) > tol and (x >= xmax or x <= xmin):
            n_clip += 1
            if first < 0:
                first = k
        if it > max_it:
            max_it = it
        for i in range(M):
            lo_i = x - rr[i]
            hi_i = x + rr[i]
            zi = zz[i]
            zi = lo_i if zi < lo_i else zi
            zi = hi_i if zi > hi_i else zi
            zz[i] = zi
        # the next starting point is x, the last point evaluated, from the
        # advanced state: same output, slopes of the advanced state
        sr = sra
        sl = sla
        xprev = x
        out[k] = x
    for i in range(N):
        state[i] = zz[i + 1]
    info[0] = n_clip
    info[1] = first
    info[2] = max_it
    return xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
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
    clipped there; a target inside a jump of Y (a boundary that leaves an
    envelope's domain while the other envelope lies below it: see `_jump`)
    is clipped to the nearer side of the jump.  info[0] = number of clipped
    samples, info[1] = first one,
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
    elif kind == TANH:
        play = play_solve_tanh
    elif kind == LINEAR or kind == ATANH:
        play = play_solve_closed
    else:
        play = play_solve_general

    def solve(fam, u, r, p, p0, state, xprev, kl, pl, kr, pr, kh, ph, hscale, xmin, xmax, rtol, out, info):
        return play(u, r, p, p0, state, xprev, kl, pl, xmin, xmax, rtol, out, info)
    return solve


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def inverse_solve_other(fam, u, r, p, p0, state, xprev, kl, pl, kr, pr, kh, ph, hscale,
                        xmin, xmax, rtol, out, info):
    """`inverse_solve` for the families FAM_MPLAY, FAM_GPI and FAM_STOP."""
    n_clip = 0
    first = -1
    max_it = 0
    xs = _input_scale(r)
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
        x_other, f_other = x, f
        while abs(f) > tol and it < 200:
            it += 1
            xp, fp = x, f
            x, checked_limit = _newton_point(f, x, xprev, lo, hi, sr, sl, checked_limit)
            y, sr, sl = _output_and_slopes(fam, x, xprev, r, p, p0, state,
                                           kl, pl, kr, pr, kh, ph, hscale)
            f = y - target
            x_other, f_other = _other_side(f, xp, fp, x_other, f_other)
            lo, hi, stop = _shrink(f, x, lo, hi, xmin, xmax, xs)
            if stop:
                break
        at_limit = x >= xmax or x <= xmin
        if abs(f) > tol and (at_limit or _jump(f, x, sr, sl, x_other, f_other)):
            # not met: beyond the outputs at the input limits, or inside a jump of
            # the output (the bracket closed on it): clipped to the nearer side
            if not at_limit and abs(f_other) < abs(f):
                x = x_other
                y, sr, sl = _output_and_slopes(fam, x, xprev, r, p, p0, state,
                                               kl, pl, kr, pr, kh, ph, hscale)
                f = y - target
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
_play_eval_closed = _specialise(_play_eval_template, "_play_eval_closed", _vd=_vd_closed)
_play_eval_general = _specialise(_play_eval_template, "_play_eval_general", _vd=_vd_general)
play_solve_pi = _specialise(
    _play_solve_lanes_template, "play_solve_pi", _lanes_eval=_pi_eval,
    doc="`inverse_solve` for FAM_PLAY with the PI (identity envelope), in SIMD lanes.")
play_solve_tanh = _specialise(
    _play_solve_lanes_template, "play_solve_tanh", _lanes_eval=_tanh_eval,
    doc="`inverse_solve` for FAM_PLAY with a Tanh envelope, in SIMD lanes.")
play_solve_closed = _specialise(
    _play_solve_template, "play_solve_closed", _vd=_vd_closed_call, _play_eval=_play_eval_closed,
    doc="`inverse_solve` for FAM_PLAY with Identity, Linear, Tanh or Atanh (no general envelope code "
        "in the loops; ~3x faster than the general copy).")
play_solve_general = _specialise(
    _play_solve_template, "play_solve_general", _vd=_vd_general_call, _play_eval=_play_eval_general,
    doc="`inverse_solve` for FAM_PLAY with any compiled envelope.")
