"""Compiled sample loops (numba, ``cache=True``) of the models outside the
Prandtl-Ishlinskii family: Preisach, Krasnoselskii-Pokrovskii (KP), Bouc-Wen
and the backlash-like model (:mod:`hystcomp.preisach`,
:mod:`hystcomp.differential`), and their per-sample inverse solves
(:mod:`hystcomp.numerical_inverse`).

Grids (Preisach and KP): the input interval ``[v_min, v_max]`` is cut into n
cells of width ``h``; level values ``c_j = v_min + (j + 1/2) h``.  A Preisach
relay (i, j), i >= j, switches up when ``v >= c_i`` and down when
``v < c_j``, so every relay depends on the input only through its level
``L(v) = #{j : c_j <= v}`` (0..n).

Preisach state: the staircase ``k_i`` (row i = alpha index): relay (i, j) is
+1 iff ``j < k_i``.  Rows ``i < L`` (L the current level) are full
(``k_i = i + 1``) and the other rows are non-increasing in i, so a move up
fills rows ``L_old .. L_new - 1`` and a move down sets ``k_i = L_new`` on the
rows above ``L_new`` until the first row already at or below it: the cost of
a sample is the number of rows that change (amortised O(1 + |dL|)), never the
number of relays.  The output is a fixed-order sum of per-row table entries,
so it is a function of the state alone (chunked == one-shot, bit for bit).

KP state: one play position per diagonal ``d = i - j`` (play radius
``d h / 2``); the KP operator of cell (i, j) is ``rho(z_d - m_ij)`` with
``m_ij = (c_i + c_j) / 2`` and the ramp ``rho(x) = clip(2 x / h, -1, 1)``.
Along a diagonal at most one cell is on its ramp, so a prefix sum per
diagonal gives the diagonal's output in O(1).

Differential models (state ``[v_prev, w]``): each sample step is integrated
in the input (dw/dv), not in time, so the result depends only on the
samples (rate independence).  The backlash-like model (eq. 5) is linear in
w on a monotone step and is solved in closed form; Bouc-Wen (eq. 3) uses
classical RK4 sub-steps whose number keeps ``|dv| * stiffness`` below a
fixed bound.
"""

import math

import numpy as np
from numba import njit

from ._kernels import play_step

BOUC_WEN = 0
BACKLASH = 1

#: RK4 sub-step bound on |dv| * |d(dw/dv)/dw| (see the module notes)
RK_SCALE = 0.05
#: sub-steps per stiff chunk (then the equilibrium test)
RK_MAX = 256


# ----------------------------------------------------------------------------
# Preisach
# ----------------------------------------------------------------------------
@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _level(x, vmin, h, n):
    """#{j : c_j <= x} with the centres c_j = vmin + (j + 1/2) h computed as
    `preisach_grid` does (exact at a centre; no int overflow for huge x)."""
    u = (x - vmin) / h + 0.5
    if not u >= 0.0:
        return 0
    if u >= n + 1.0:
        return n
    t = int(math.floor(u))
    if t > n:
        t = n
    # the division rounds: settle the count on the centres themselves
    while t < n and vmin + (t + 0.5) * h <= x:
        t += 1
    while t > 0 and vmin + (t - 0.5) * h > x:
        t -= 1
    return t


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _preisach_value(table, k, offset):
    s = offset
    for i in range(k.size):
        s += table[i, k[i]]
    return s


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _full_rows(k):
    L = 0
    while L < k.size and k[L] == L + 1:
        L += 1
    return L


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _preisach_move(k, Lc, L):
    """Apply a move of the input level from Lc to L; True if a relay switched."""
    changed = False
    if L > Lc:
        for i in range(Lc, L):
            k[i] = i + 1
        changed = True
    elif L < Lc:
        for i in range(L, k.size):
            if k[i] > L:
                k[i] = L
                changed = True
            else:
                break
    return changed


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def preisach_sum(x, vmin, h, table, offset, k, y):
    """Preisach output for every sample; `k` (int64 staircase) updated in place."""
    n = k.size
    Lc = _full_rows(k)
    cur = _preisach_value(table, k, offset)
    for t in range(x.size):
        L = _level(x[t], vmin, h, n)
        if L != Lc:
            if _preisach_move(k, Lc, L):
                cur = _preisach_value(table, k, offset)
            Lc = L
        y[t] = cur


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def preisach_segments(x, vmin, h, k, starts, states):
    """Segments of constant state: their start indices and staircases.

    Returns the number of segments S (``starts[:S]``, ``states[:S]``); the
    first segment starts at 0 with the state after the first sample.
    """
    n = k.size
    Lc = _full_rows(k)
    S = 0
    for t in range(x.size):
        L = _level(x[t], vmin, h, n)
        changed = False
        if L != Lc:
            changed = _preisach_move(k, Lc, L)
            Lc = L
        if changed or t == 0:
            starts[S] = t
            for i in range(n):
                states[S, i] = k[i]
            S += 1
    return S


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def preisach_inverse(u, vmin, h, table, offset, k, edges, out, info):
    """Closest match per sample: the level whose output is nearest the target.

    The output after a move to level L is non-decreasing in L (non-negative
    weights), so a binary search over L = 0..n finds the first level whose
    output reaches the target; the nearer of it and the level below wins
    (the current level on ties).  The compensator output is the cell edge
    ``edges[L]``, an input of level L.  ``info = [unreachable count, first]``.
    """
    n = k.size
    trial = np.empty(n, np.int64)
    Lc = _full_rows(k)
    cur = _preisach_value(table, k, offset)
    ymin = 0.0
    ymax = 0.0
    for t in range(u.size):
        target = u[t]
        lo = 0
        hi = n
        # y(L) for the candidate levels
        for i in range(n):
            trial[i] = k[i]
        _preisach_move(trial, Lc, 0)
        ymin = _preisach_value(table, trial, offset)
        for i in range(n):
            trial[i] = k[i]
        _preisach_move(trial, Lc, n)
        ymax = _preisach_value(table, trial, offset)
        if target <= ymin:
            best = 0
            if target < ymin - 1e-12 * (abs(ymin) + abs(ymax) + 1.0):
                info[0] += 1
                if info[1] < 0:
                    info[1] = t
        elif target >= ymax:
            best = n
            if target > ymax + 1e-12 * (abs(ymin) + abs(ymax) + 1.0):
                info[0] += 1
                if info[1] < 0:
                    info[1] = t
        else:
            # smallest L with y(L) >= target, in (0, n]
            ylo = ymin
            yhi = ymax
            while hi - lo > 1:
                mid = (lo + hi) // 2
                for i in range(n):
                    trial[i] = k[i]
                _preisach_move(trial, Lc, mid)
                ym = _preisach_value(table, trial, offset)
                if ym >= target:
                    hi = mid
                    yhi = ym
                else:
                    lo = mid
                    ylo = ym
            best = hi if (yhi - target) <= (target - ylo) else lo
            # stay where the output is already the best one
            if Lc >= lo and Lc <= hi:
                for i in range(n):
                    trial[i] = k[i]
                _preisach_move(trial, Lc, Lc)
                yb = yhi if best == hi else ylo
                if _preisach_value(table, trial, offset) == yb:
                    best = Lc
        if best != Lc:
            _preisach_move(k, Lc, best)
            cur = _preisach_value(table, k, offset)
            Lc = best
        out[t] = edges[best]
    return cur


# ----------------------------------------------------------------------------
# Krasnoselskii-Pokrovskii
# ----------------------------------------------------------------------------
@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _kp_diag(z, d, vmin, h, n, prefix):
    """Sum over the cells of diagonal d of mu * rho(z - m)."""
    M = n - d                                  # cells on the diagonal
    t = (z - (vmin + (0.5 + 0.5 * d) * h)) / h  # position in cell units
    total = prefix[d, M]
    # compare before rounding to an integer: no int64 overflow for huge z
    if not t + 0.5 >= 0.0:
        return -total
    if t + 0.5 >= M:
        return total
    jr = math.floor(t + 0.5)
    j = int(jr)
    below = prefix[d, j]
    mu = prefix[d, j + 1] - below
    above = total - prefix[d, j + 1]
    return below - above + mu * (2.0 * (t - jr))


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _kp_value(z, vmin, h, prefix, offset):
    n = z.size
    s = offset
    for d in range(n):
        s += _kp_diag(z[d], d, vmin, h, n, prefix)
    return s


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _kp_thresholds(n, h):
    """Thresholds of the KP diagonals: r_d = d h / 2 (the plays of the ridge operators)."""
    r = np.empty(n)
    for d in range(n):
        r[d] = 0.5 * d * h
    return r


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def kp_sum(x, vmin, h, prefix, offset, z, y):
    """KP output for every sample; play positions `z` (one per diagonal) updated."""
    r = _kp_thresholds(z.size, h)
    for t in range(x.size):
        play_step(x[t], r, 0.0, z)
        y[t] = _kp_value(z, vmin, h, prefix, offset)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def kp_regressors(x, vmin, h, z, cell_d, cell_j, A):
    """KP operator outputs rho(z_d - m) for every sample and cell (columns
    ordered by `cell_d`, `cell_j`); `z` updated."""
    r = _kp_thresholds(z.size, h)
    for t in range(x.size):
        v = x[t]
        play_step(v, r, 0.0, z)
        for c in range(cell_d.size):
            d = cell_d[c]
            q = 2.0 * (z[d] - (vmin + (cell_j[c] + 0.5 + 0.5 * d) * h)) / h
            if q > 1.0:
                q = 1.0
            elif q < -1.0:
                q = -1.0
            A[t, c] = q


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _kp_trial(z, v, r, vmin, h, prefix, offset, work):
    work[:] = z
    play_step(v, r, 0.0, work)
    return _kp_value(work, vmin, h, prefix, offset)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def kp_inverse(u, vmin, vmax, h, prefix, offset, z, vprev, tol, out, info):
    """Monotone solve per sample (bisection on the input in [vmin, vmax]):
    the KP output after a monotone step to v is non-decreasing in v for
    non-negative weights."""
    n = z.size
    work = np.empty(n)
    r_diag = _kp_thresholds(n, h)
    for t in range(u.size):
        target = u[t]
        ylo = _kp_trial(z, vmin, r_diag, vmin, h, prefix, offset, work)
        yhi = _kp_trial(z, vmax, r_diag, vmin, h, prefix, offset, work)
        scale = 1e-12 * (abs(ylo) + abs(yhi) + 1.0)
        if target <= ylo:
            v = vmin
            if target < ylo - scale:
                info[0] += 1
                if info[1] < 0:
                    info[1] = t
        elif target >= yhi:
            v = vmax
            if target > yhi + scale:
                info[0] += 1
                if info[1] < 0:
                    info[1] = t
        else:
            a = vmin
            b = vmax
            # start from a bracket around the previous input when possible
            yp = _kp_trial(z, vprev, r_diag, vmin, h, prefix, offset, work)
            if yp == target:
                a = vprev
                b = vprev
            elif yp < target:
                a = vprev
            else:
                b = vprev
            # regula falsi with the Illinois modification (bisection if the
            # secant point leaves the bracket): the output is piecewise linear
            # in v, so the secant is exact once the bracket holds one linear
            # piece; stop at 1e-13 of the output scale or `tol` in v
            ya = _kp_trial(z, a, r_diag, vmin, h, prefix, offset, work) if a != vprev else yp
            yb = _kp_trial(z, b, r_diag, vmin, h, prefix, offset, work) if b != vprev else yp
            side = 0
            v = b
            while b - a > tol:
                if yb > ya:
                    mid = a + (target - ya) * (b - a) / (yb - ya)
                else:
                    mid = 0.5 * (a + b)
                if not (a < mid < b):
                    mid = 0.5 * (a + b)
                if mid <= a or mid >= b:
                    break
                ym = _kp_trial(z, mid, r_diag, vmin, h, prefix, offset, work)
                if abs(ym - target) <= 0.1 * scale:
                    a = mid
                    b = mid
                    break
                if ym < target:
                    a = mid
                    ya = ym
                    if side == -1:
                        yb = target + 0.5 * (yb - target)
                    side = -1
                else:
                    b = mid
                    yb = ym
                    if side == 1:
                        ya = target + 0.5 * (ya - target)
                    side = 1
            v = b
        play_step(v, r_diag, 0.0, z)
        out[t] = v
        vprev = v
    return vprev


# ----------------------------------------------------------------------------
# differential models: Bouc-Wen (eq. 3) and backlash-like (eq. 5)
# ----------------------------------------------------------------------------
@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _bw_rate(w, s, A, alpha, beta, n):
    """dw/dv of eq. 3 for an input moving in direction s = +-1."""
    aw = abs(w)
    if n == 1.0:
        return A - beta * aw - alpha * s * w
    if n == 2.0:
        p = aw
    elif n == 3.0:
        p = aw * aw
    else:
        p = aw ** (n - 1.0)
    return A - beta * p * aw - alpha * s * p * w


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _diff_step(kind, prm, w, v0, v1):
    """State w after a monotone input step v0 -> v1."""
    dv = v1 - v0
    if dv == 0.0:
        return w
    s = 1.0 if dv > 0.0 else -1.0
    if kind == BACKLASH:
        alpha, c, B1 = prm[0], prm[1], prm[2]
        # e = w - c v obeys de/dv = -s alpha e + (B1 - c): exact exponential
        e = w - c * v0
        es = s * (B1 - c) / alpha
        e = es + (e - es) * math.exp(-alpha * abs(dv))
        return c * v1 + e
    A, alpha, beta, n = prm[0], prm[1], prm[2], prm[3]
    if n == 1.0:
        return _bw_exact_n1(w, dv, s, A, alpha, beta)
    # stiffness |d(dw/dv)/dw| <= n (|alpha| + |beta|) |w|^(n-1), bounded over
    # the step by the larger of |w| and the loop bound wb = prm[4] (|w| moves
    # towards the band |w| <= wb in the valid range)
    rest = dv
    while True:
        wm = max(abs(w), prm[4])
        lam = n * (abs(alpha) + abs(beta)) * wm ** (n - 1.0)
        need = math.ceil(abs(rest) * lam / RK_SCALE)
        if need < 1.0:
            need = 1.0
        stiff = need > RK_MAX
        m = RK_MAX if stiff else int(need)
        hstep = rest / need
        for _ in range(m):
            wn = _rk4(w, hstep, s, A, alpha, beta, n)
            if (w > 0.0 and wn < 0.0) or (w < 0.0 and wn > 0.0):
                # w crosses 0, where |w|^n is not smooth: split the sub-step
                # at the crossing (first-order estimate), so that RK4
                # integrates each side of the kink
                k1 = _bw_rate(w, s, A, alpha, beta, n)
                d1 = -w / k1 if k1 != 0.0 else 0.5 * hstep
                if d1 * hstep <= 0.0 or abs(d1) >= abs(hstep):
                    d1 = 0.5 * hstep
                wn = _rk4(_rk4(w, d1, s, A, alpha, beta, n), hstep - d1, s, A, alpha, beta, n)
            w = wn
        if not stiff:
            return w
        # a stiff step: after RK_MAX sub-steps of RK_SCALE / lam, stop once w
        # sits at the branch's equilibrium (dw/dv = 0 to rounding: it stays)
        if abs(_bw_rate(w, s, A, alpha, beta, n)) <= 1e-13 * A:
            return w
        rest = rest - m * hstep


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _rk4(w, hs, s, A, alpha, beta, n):
    k1 = _bw_rate(w, s, A, alpha, beta, n)
    k2 = _bw_rate(w + 0.5 * hs * k1, s, A, alpha, beta, n)
    k3 = _bw_rate(w + 0.5 * hs * k2, s, A, alpha, beta, n)
    k4 = _bw_rate(w + hs * k3, s, A, alpha, beta, n)
    return w + hs * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def _lin_relax(w, d, A, kappa):
    """w after d along dw/dv = A - kappa w (exact)."""
    if kappa == 0.0:
        return w + A * d
    ws = A / kappa
    return ws + (w - ws) * math.exp(-kappa * d)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _bw_exact_n1(w, dv, s, A, alpha, beta):
    """Eq. 3 with n = 1 on a monotone step, exactly: dw/dv = A - kappa w with
    kappa = beta sign(w) + alpha s, piecewise constant between zero crossings
    of w (at most one per step: dw/dv = A > 0 at w = 0)."""
    sg = 1.0 if w > 0.0 else (-1.0 if w < 0.0 else s)
    kappa = beta * sg + alpha * s
    wn = _lin_relax(w, dv, A, kappa)
    if w != 0.0 and (wn > 0.0) != (w > 0.0) and wn != 0.0:
        # distance in v to w = 0 on this side, then the rest on the other
        if kappa == 0.0:
            d0 = -w / A
        else:
            ws = A / kappa
            d0 = -math.log(ws / (ws - w)) / kappa
        if d0 * dv < 0.0:
            d0 = 0.0
        if abs(d0) > abs(dv):
            d0 = dv
        kappa2 = beta * (-sg) + alpha * s
        wn = _lin_relax(0.0, dv - d0, A, kappa2)
    return wn


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def diff_sum(kind, prm, gain, offset, x, state, y):
    """Output ``gain * v + sign * w + offset`` per sample (sign = prm[5] for
    Bouc-Wen, else 1); state [v_prev, w] updated."""
    v0 = state[0]
    w = state[1]
    sg = prm[5] if kind == BOUC_WEN else 1.0
    for t in range(x.size):
        v1 = x[t]
        w = _diff_step(kind, prm, w, v0, v1)
        v0 = v1
        y[t] = gain * v1 + sg * w + offset
    state[0] = v0
    state[1] = w


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def diff_inverse(kind, prm, gain, offset, u, state, vlo, vhi, tol, out, info):
    """Monotone solve per sample: the output after a monotone step from
    v_prev is non-decreasing in the new input (the models' valid ranges
    ensure it); the bracket grows from v_prev by doubling up to the input
    limits, then bisection.  ``state = [v_prev, w]``."""
    v0 = state[0]
    w = state[1]
    sg = prm[5] if kind == BOUC_WEN else 1.0
    for t in range(u.size):
        target = u[t]
        y0 = gain * v0 + sg * w + offset
        if target == y0:
            out[t] = v0
            continue
        s = 1.0 if target > y0 else -1.0
        lim = vhi if s > 0 else vlo
        step = max(1e-3 * (abs(v0) + 1.0), tol)
        a = v0
        b = v0
        ya = y0
        found = False
        for _ in range(200):
            b = v0 + s * step
            if (s > 0 and b >= lim) or (s < 0 and b <= lim):
                b = lim
            yb = gain * b + sg * _diff_step(kind, prm, w, v0, b) + offset
            if (s > 0 and yb >= target) or (s < 0 and yb <= target):
                found = True
                break
            if b == lim:
                break
            # saturated: a step longer than the input scale no longer moves
            # the output: settle on the first input that reaches that output
            # (to tol) rather than running off towards an overflow
            if not (s * (yb - ya) > tol * (1.0 + abs(yb))) and step > 1.0 + abs(v0):
                near = v0
                far = a
                for _k in range(200):
                    mid = 0.5 * (near + far)
                    if mid == near or mid == far:
                        break
                    ym = gain * mid + sg * _diff_step(kind, prm, w, v0, mid) + offset
                    if s * (ya - ym) > tol * (1.0 + abs(ya)):
                        near = mid
                    else:
                        far = mid
                b = far
                break
            a = b
            ya = yb
            step *= 2.0
        if not found:
            info[0] += 1
            if info[1] < 0:
                info[1] = t
            v = b
        else:
            lo = min(a, b)
            hi = max(a, b)
            while hi - lo > tol * (1.0 + abs(lo)):
                mid = 0.5 * (lo + hi)
                if mid <= lo or mid >= hi:
                    break
                ym = gain * mid + sg * _diff_step(kind, prm, w, v0, mid) + offset
                if ym < target:
                    lo = mid
                else:
                    hi = mid
            v = hi if s > 0 else lo
        w = _diff_step(kind, prm, w, v0, v)
        v0 = v
        out[t] = v
    state[0] = v0
    state[1] = w
