"""Mechanisms of the HOLDOUT38 set (``cases_holdout38.py``), each written from its law; the signals are in
:mod:`.signals38`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive, or the core's
output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout38.py against an independent
solution (an event-driven stick-slip solution written from the friction law alone, a coordinate-wise minimisation,
solve_ivp, quad, a closed form, a geometry written as vectors, a direct loop).
"""

import math

import numpy as np
from numba import njit


# ---- the rate-independent core: a push rod through a row of floating friction bushes ----
#
# A voice coil (its force proportional to the drive) on a centring flexure k_g pushes a slender glass-epoxy rod through
# a row of n spring-loaded PTFE guide bushes to a remote stage, whose flexure holds the rod's far end. Each bush grips
# the rod with a Coulomb friction force f_i (Amontons-Coulomb: the rod sticks in the bush until the axial force the bush
# must take reaches f_i, then slides with f_i against the motion), and each bush floats axially in its housing with a
# clearance of +-g_i (a self-aligning bush fitted between two shoulders), so that the rod carries it along freely until
# it meets a shoulder and only then slips in it. The rod between two bushes is a linear spring k_i = E A / l_i. Lumping
# the rod at the bushes gives a chain of spring-coupled nodes, each on a frictional support with a free play, pulled at
# one end: the quasi-static limit of the Burridge-Knopoff chain (Bull. Seismol. Soc. Am. 57 (1967) 341) or the discrete
# form of a fibre sliding against a matrix (Marshall & Oliver, J. Am. Ceram. Soc. 70 (1987) 542), with a backlash at
# every contact: a discrete elasto-plastic chain in series, not Iwan's parallel array. Without the play it would obey
# Masing's rules (a linear-elastic Coulomb system under one load: a Prandtl-Ishlinskii operator in disguise); the play
# breaks them (a bush that has just reversed offers no friction until it re-seats).
#
# Quasi-statically (the rod's axial resonance is kHz), with x the nodes' displacements (node 0 the coil, nodes 1 ... n
# the rod at the bushes), b_i the bushes' positions in their housings (|b_i| <= g_i) and R = g - K x the axial forces
# the supports must take (K the chain's tridiagonal stiffness, g = k_0 u e_0, u the coil's force over k_0 = k_g): a
# floating bush takes no force (R_i = 0 while |b_i| < g_i and it moves with the rod), a seated one sticks while |R_i| <
# f_i and slips in the direction of R_i with |R_i| = f_i. The evolution is rate independent, and because K is an
# M-matrix a rise of u moves every node forward or not at all ("no passing"): the state after a monotone change of u is
# the minimiser of the incremental energy 1/2 x'Kx - g'x + sum f_i dist(x_i - a_i, [lo_i, hi_i]) (a the state before,
# [lo_i, hi_i] the travel left to bush i before its shoulders; Han & Reddy's incremental plasticity), exact for an input
# linear between the samples. The same step takes a viscous slip term E_i / 2 dist(.)^2 (a drag in the bush, E = c / h)
# and a diagonal term on the coil (its inertia, by Newmark's average acceleration); each step is solved exactly by
# following its piecewise-linear solution path from a trivial problem, an active-set homotopy (as Osborne, Presnell &
# Turlach's for the lasso, IMA J. Numer. Anal. 20 (2000) 389), each piece one tridiagonal solve on the free nodes.

BIG = 1e300


@njit(cache=True)
def _solve_free(Ad, off, rhs, free, d):
    """A_FF d_F = rhs_F - A_FZ d_Z (A tridiagonal: diagonal Ad, off-diagonal off; d_Z, off the free set, given in d)."""
    N = Ad.shape[0]
    cp = np.zeros(N)
    dp = np.zeros(N)
    for i in range(N):
        if not free[i]:
            continue
        q = rhs[i]
        if i > 0 and not free[i - 1]:
            q -= off[i - 1] * d[i - 1]
        if i < N - 1 and not free[i + 1]:
            q -= off[i] * d[i + 1]
        if i > 0 and free[i - 1]:
            m = Ad[i] - off[i - 1] * cp[i - 1]
            dp[i] = (q - off[i - 1] * dp[i - 1]) / m
        else:
            m = Ad[i]
            dp[i] = q / m
        cp[i] = off[i] / m if i < N - 1 else 0.0
    for i in range(N - 1, -1, -1):
        if not free[i]:
            continue
        if i < N - 1 and free[i + 1]:
            d[i] = dp[i] - cp[i] * d[i + 1]
        else:
            d[i] = dp[i]


@njit(cache=True)
def _tri_mul(Ad, off, x, out):
    N = Ad.shape[0]
    for i in range(N):
        s = Ad[i] * x[i]
        if i > 0:
            s += off[i - 1] * x[i - 1]
        if i < N - 1:
            s += off[i] * x[i + 1]
        out[i] = s


@njit(cache=True)
def _solve2(Ad, off, rp, rq, free, fixval, p, q):
    """A_FF p_F = rp_F - A_FZ fixval_Z and A_FF q_F = rq_F (q_Z = 0); p_Z = fixval_Z (Thomas on the free runs)."""
    N = Ad.shape[0]
    cp = np.zeros(N)
    dp = np.zeros(N)
    dq = np.zeros(N)
    for i in range(N):
        if not free[i]:
            p[i] = fixval[i]
            q[i] = 0.0
    for i in range(N):
        if not free[i]:
            continue
        a1 = rp[i]
        if i > 0 and not free[i - 1]:
            a1 -= off[i - 1] * fixval[i - 1]
        if i < N - 1 and not free[i + 1]:
            a1 -= off[i] * fixval[i + 1]
        if i > 0 and free[i - 1]:
            m = Ad[i] - off[i - 1] * cp[i - 1]
            dp[i] = (a1 - off[i - 1] * dp[i - 1]) / m
            dq[i] = (rq[i] - off[i - 1] * dq[i - 1]) / m
        else:
            m = Ad[i]
            dp[i] = a1 / m
            dq[i] = rq[i] / m
        cp[i] = off[i] / m if i < N - 1 else 0.0
    for i in range(N - 1, -1, -1):
        if not free[i]:
            continue
        if i < N - 1 and free[i + 1]:
            p[i] = dp[i] - cp[i] * p[i + 1]
            q[i] = dq[i] - cp[i] * q[i + 1]
        else:
            p[i] = dp[i]
            q[i] = dq[i]


@njit(cache=True)
def _step(Ad, off, f, E, lo, hi, r, d):
    """The minimiser d of 1/2 d'A d - r'd + sum_i [f_i dist(d_i, [lo_i, hi_i]) + E_i / 2 dist(d_i, [lo_i, hi_i])^2]
    (A tridiagonal, an M-matrix; lo_i <= 0 <= hi_i), followed exactly along the homotopy r -> lam r from lam = 0 (where
    d = 0) to 1, r0 = r clipped node by node to the reactions d = 0 allows (0 for a floating bush, up to f for one
    against a shoulder): between events d is affine in lam and every node keeps its state (floating inside its bush's
    travel, held at an edge with its reaction inside its friction, or slipping beyond it); an event switches one node's
    state. Returns the events taken (-1: the path stalled, d then from exact coordinate descent)."""
    N = Ad.shape[0]
    st = np.zeros(N, np.int64)       # 0 floating, +-1 held at hi / lo, +-2 slipping beyond hi / lo
    full = np.zeros(N, np.bool_)     # held with no clearance: the reaction free over [-f, f]
    for i in range(N):
        if lo[i] <= -BIG:
            st[i] = 0
        elif lo[i] == hi[i]:
            st[i] = 1
            full[i] = True
        elif hi[i] == 0.0:
            st[i] = 1
        elif lo[i] == 0.0:
            st[i] = -1
    r0 = np.zeros(N)
    for i in range(N):
        if st[i] == 1 or st[i] == -1:
            top = f[i] if (st[i] == 1 or full[i]) else 0.0
            bot = -f[i] if (st[i] == -1 or full[i]) else 0.0
            r0[i] = min(max(r[i], bot), top)
            if r[i] > top and (st[i] == 1 or full[i]):
                st[i] = 2                # at d = 0 with the reaction f: as valid as held, and likelier to last
            elif r[i] < bot and (st[i] == -1 or full[i]):
                st[i] = -2
    free = np.empty(N, np.bool_)
    Dg = np.empty(N)
    rp = np.empty(N)
    rq = np.empty(N)
    fixv = np.zeros(N)
    p = np.empty(N)
    q = np.empty(N)
    Ap = np.empty(N)
    Aq = np.empty(N)
    lam = 0.0
    stalls = 0
    for ev in range(50 * N + 200):
        for i in range(N):
            s = st[i]
            Dg[i] = Ad[i]
            rp[i] = r0[i]
            rq[i] = r[i] - r0[i]
            free[i] = s == 0 or s == 2 or s == -2
            if s == 1:
                fixv[i] = hi[i]
            elif s == -1:
                fixv[i] = lo[i]
            elif s == 2:
                Dg[i] += E[i]
                rp[i] += -f[i] + E[i] * hi[i]
            elif s == -2:
                Dg[i] += E[i]
                rp[i] += f[i] + E[i] * lo[i]
        _solve2(Dg, off, rp, rq, free, fixv, p, q)
        _tri_mul(Ad, off, p, Ap)
        _tri_mul(Ad, off, q, Aq)
        best = 2.0
        who = -1
        to = 0
        for i in range(N):
            s = st[i]
            le = 2.0
            nxt = s
            if s == 0:
                if lo[i] > -BIG:
                    if q[i] > 0.0:
                        le, nxt = (hi[i] - p[i]) / q[i], 1
                    elif q[i] < 0.0:
                        le, nxt = (lo[i] - p[i]) / q[i], -1
            elif s == 1 or s == -1:
                al = r0[i] - Ap[i]
                be = r[i] - r0[i] - Aq[i]
                top = f[i] if (s == 1 or full[i]) else 0.0
                bot = -f[i] if (s == -1 or full[i]) else 0.0
                if be > 0.0:
                    le, nxt = (top - al) / be, 2 if (s == 1 or full[i]) else 0
                elif be < 0.0:
                    le, nxt = (bot - al) / be, -2 if (s == -1 or full[i]) else 0
            elif s == 2:
                if q[i] < 0.0:
                    le, nxt = (hi[i] - p[i]) / q[i], 1
            else:
                if q[i] > 0.0:
                    le, nxt = (lo[i] - p[i]) / q[i], -1
            if le < lam:
                le = lam
            if le < best:
                best, who, to = le, i, nxt
        if best >= 1.0 or who < 0:
            for i in range(N):
                d[i] = p[i] + q[i]
            return ev
        if best <= lam:
            stalls += 1
            if stalls > 4 * N + 20:
                break
        else:
            stalls = 0
        lam = best
        if full[who] and (to == 1 or to == -1):
            to = 1
        st[who] = to
    # a safeguard (never met in the records' checks): exact coordinate descent to convergence
    for i in range(N):
        d[i] = 0.0
    for sweep in range(200000):
        big = 0.0
        for i in range(N):
            qq = r[i]
            if i > 0:
                qq -= off[i - 1] * d[i - 1]
            if i < N - 1:
                qq -= off[i] * d[i + 1]
            c = Ad[i]
            z = qq / c
            if z > hi[i] + f[i] / c:
                new = (c * z - f[i] + E[i] * hi[i]) / (c + E[i])
            elif z >= hi[i]:
                new = hi[i]
            elif z > lo[i]:
                new = z
            elif z > lo[i] - f[i] / c:
                new = lo[i]
            else:
                new = (c * z + f[i] + E[i] * lo[i]) / (c + E[i])
            big = max(big, abs(new - d[i]))
            d[i] = new
        if big < 1e-16:
            break
    return -1


@njit(cache=True)
def _tri(k, kt, n1):
    Ad = np.empty(n1)
    off = np.empty(n1)
    for i in range(n1):
        Ad[i] = k[i] + (k[i + 1] if i < n1 - 1 else kt)
        off[i] = -k[i + 1] if i < n1 - 1 else 0.0
    return Ad, off


@njit(cache=True)
def _window(g, b, lo, hi):
    """The travel left to each bush before its housing's shoulders."""
    for i in range(g.shape[0]):
        if g[i] >= BIG:
            lo[i] = -BIG
            hi[i] = BIG
        else:
            lo[i] = -g[i] - b[i]
            hi[i] = g[i] - b[i]


@njit(cache=True)
def _carry(g, b, e, lo, hi):
    """The bushes carried by the step e (relative to their housings), up to their shoulders."""
    for i in range(g.shape[0]):
        if g[i] < BIG:
            b[i] += min(max(e[i], lo[i]), hi[i])


@njit(cache=True)
def _chain_run(k, kt, f, g, U, S, x0, b0):
    """The rate-independent chain along the drive points U (one a sample) from the nodes x0 and the bushes b0, the
    housings displaced by S (T x n1: their positions; the first row where they were at x0, b0): every node after each
    sample, and the bushes at the end. A step with the housings moved by dS is solved for e = d - dS (the nodes'
    motion relative to them)."""
    n1 = f.shape[0]
    Ad, off = _tri(k, kt, n1)
    E = np.zeros(n1)
    x = x0.copy()
    b = b0.copy()
    out = np.empty((U.shape[0], n1))
    e = np.zeros(n1)
    r = np.empty(n1)
    Kx = np.empty(n1)
    KdS = np.zeros(n1)
    lo = np.empty(n1)
    hi = np.empty(n1)
    dS = np.zeros(n1)
    moved = S.shape[0] > 1
    for t in range(U.shape[0]):
        for i in range(n1):
            dS[i] = S[t, i] - S[t - 1, i] if moved and t > 0 else 0.0
        _window(g, b, lo, hi)
        _tri_mul(Ad, off, x, Kx)
        _tri_mul(Ad, off, dS, KdS)
        for i in range(n1):
            r[i] = -Kx[i] - KdS[i]
        r[0] += k[0] * U[t]
        _step(Ad, off, f, E, lo, hi, r, e)
        _carry(g, b, e, lo, hi)
        for i in range(n1):
            x[i] += e[i] + dS[i]
            out[t, i] = x[i]
    return out, b


@njit(cache=True)
def _viscous_run(k, kt, f, g, c, U, sub, x0, b0, dt):
    """The chain whose bushes add a viscous drag c_i times the slip speed (Bingham contacts): backward Euler in ``sub``
    steps a sample, the drive linear between the samples (U[0] the drive at x0, b0)."""
    n1 = f.shape[0]
    Ad, off = _tri(k, kt, n1)
    h = dt / sub
    E = c / h
    x = x0.copy()
    b = b0.copy()
    out = np.empty((U.shape[0], n1))
    out[0] = x
    d = np.zeros(n1)
    r = np.empty(n1)
    Kx = np.empty(n1)
    lo = np.empty(n1)
    hi = np.empty(n1)
    for t in range(1, U.shape[0]):
        for s in range(sub):
            u = U[t - 1] + (U[t] - U[t - 1]) * (s + 1) / sub
            _window(g, b, lo, hi)
            _tri_mul(Ad, off, x, Kx)
            for i in range(n1):
                r[i] = -Kx[i]
            r[0] += k[0] * u
            _step(Ad, off, f, E, lo, hi, r, d)
            _carry(g, b, d, lo, hi)
            for i in range(n1):
                x[i] += d[i]
        for i in range(n1):
            out[t, i] = x[i]
    return out, b


@njit(cache=True)
def _inertial_run(k, kt, f, g, M, c0, U, sub, x0, b0, dt):
    """The chain whose driven node 0 (friction-free) carries a mass M and a viscous damping c0: Newmark's average
    acceleration for node 0, the bushes quasi-static, in ``sub`` steps a sample (the drive linear between the samples);
    starting at rest at x0, b0 in equilibrium with U[0]. Returns every node's displacement and node 0's velocity."""
    n1 = f.shape[0]
    Kd, off = _tri(k, kt, n1)
    h = dt / sub
    D0 = 4.0 * M / (h * h) + 2.0 * c0 / h
    Ad = Kd.copy()
    Ad[0] += D0
    E = np.zeros(n1)
    x = x0.copy()
    b = b0.copy()
    v0 = 0.0
    a0 = 0.0
    out = np.empty((U.shape[0], n1))
    vel = np.empty(U.shape[0])
    out[0] = x
    vel[0] = 0.0
    d = np.zeros(n1)
    r = np.empty(n1)
    Kx = np.empty(n1)
    lo = np.empty(n1)
    hi = np.empty(n1)
    for t in range(1, U.shape[0]):
        for s in range(sub):
            u = U[t - 1] + (U[t] - U[t - 1]) * (s + 1) / sub
            _window(g, b, lo, hi)
            _tri_mul(Kd, off, x, Kx)
            for i in range(n1):
                r[i] = -Kx[i]
            r[0] += k[0] * u + 4.0 * M / h * v0 + M * a0 + c0 * v0
            _step(Ad, off, f, E, lo, hi, r, d)
            _carry(g, b, d, lo, hi)
            for i in range(n1):
                x[i] += d[i]
            a1 = 4.0 / (h * h) * (d[0] - h * v0) - a0
            v0 = 2.0 / h * d[0] - v0
            a0 = a1
        for i in range(n1):
            out[t, i] = x[i]
        vel[t] = v0
    return out, vel


@njit(cache=True)
def _psi(v, s, w):
    """The dissipation potential of the activated slip law v = w sinh(R / s): s (v asinh(v / w) - sqrt(v^2 + w^2) +
    w)."""
    return s * (v * math.asinh(v / w) - math.sqrt(v * v + w * w) + w)


@njit(cache=True)
def _act_energy(k0, u, Kd, off, x, a, sg, w, lo, hi, h, Kx):
    _tri_mul(Kd, off, x, Kx)
    E = -k0 * u * x[0]
    for i in range(x.shape[0]):
        E += 0.5 * x[i] * Kx[i]
        if sg[i] > 0.0:
            dd = x[i] - a[i]
            sl = dd - min(max(dd, lo[i]), hi[i])
            E += h * _psi(sl / h, sg[i], w[i])
    return E


@njit(cache=True)
def _activated_run(k, kt, sg, w, g, U, sub, x0, b0, dt):
    """The chain whose seated bushes slip at the thermally activated rate v_i = w_i sinh(R_i / s_i) (no sticking; a
    floating bush takes no force): backward Euler in ``sub`` steps a sample (the drive linear between the samples), each
    step the minimiser of the convex, once differentiable 1/2 x'Kx - g'x + h sum psi_i(slip_i / h) (slip_i the part of
    x_i - a_i beyond bush i's travel) by Newton's method with a backtracking line search."""
    n1 = sg.shape[0]
    Kd, off = _tri(k, kt, n1)
    h = dt / sub
    x = x0.copy()
    b = b0.copy()
    vprev = np.zeros(n1)
    out = np.empty((U.shape[0], n1))
    out[0] = x
    a = np.empty(n1)
    Kx = np.empty(n1)
    grad = np.empty(n1)
    Hd = np.empty(n1)
    dx = np.empty(n1)
    xt = np.empty(n1)
    lo = np.empty(n1)
    hi = np.empty(n1)
    dd = np.empty(n1)
    allfree = np.ones(n1, np.bool_)
    for t in range(1, U.shape[0]):
        for s in range(sub):
            u = U[t - 1] + (U[t] - U[t - 1]) * (s + 1) / sub
            _window(g, b, lo, hi)
            for i in range(n1):
                a[i] = x[i]
                x[i] = a[i] + h * vprev[i]
            for it in range(100):
                E = _act_energy(k[0], u, Kd, off, x, a, sg, w, lo, hi, h, Kx)
                for i in range(n1):
                    grad[i] = Kx[i]
                    Hd[i] = Kd[i]
                grad[0] -= k[0] * u
                for i in range(n1):
                    if sg[i] > 0.0:
                        di = x[i] - a[i]
                        v = (di - min(max(di, lo[i]), hi[i])) / h
                        if v != 0.0:
                            grad[i] += sg[i] * math.asinh(v / w[i])
                            Hd[i] += sg[i] / (h * math.sqrt(v * v + w[i] * w[i]))
                for i in range(n1):
                    grad[i] = -grad[i]
                _solve_free(Hd, off, grad, allfree, dx)
                big = 0.0
                slope = 0.0
                for i in range(n1):
                    big = max(big, abs(dx[i]))
                    slope -= grad[i] * dx[i]
                if big < 1e-14:
                    break
                step = 1.0
                while -slope > 1e-13 * (1.0 + abs(E)):
                    for i in range(n1):
                        xt[i] = x[i] + step * dx[i]
                    Et = _act_energy(k[0], u, Kd, off, xt, a, sg, w, lo, hi, h, Kx)
                    if Et <= E + 1e-4 * step * slope or step < 1e-12:
                        break
                    step *= 0.5
                for i in range(n1):
                    x[i] += step * dx[i]
                if big * step < 1e-14:
                    break
            for i in range(n1):
                dd[i] = x[i] - a[i]
                vprev[i] = dd[i] / h
            _carry(g, b, dd, lo, hi)
        for i in range(n1):
            out[t, i] = x[i]
    return out, b


def chain_stiffness(k, kt):
    """The chain's stiffness matrix (dense; for checks)."""
    n1 = len(k)
    K = np.zeros((n1, n1))
    for i in range(n1):
        K[i, i] = k[i] + (k[i + 1] if i < n1 - 1 else kt)
        if i < n1 - 1:
            K[i, i + 1] = K[i + 1, i] = -k[i + 1]
    return K


def _gaps(core):
    g = np.asarray(core["g"], float).copy()
    g[np.asarray(core["f"]) == 0] = BIG
    return g


def _start(core, x0, b0):
    n1 = len(core["f"])
    return (np.zeros(n1) if x0 is None else np.asarray(x0, float).copy(),
            np.zeros(n1) if b0 is None else np.asarray(b0, float).copy())


def chain(core, U, x0=None, b0=None, S=None, return_bushes=False):
    """The rate-independent chain of ``core`` (k, kt, f, g) along the drive points U from the nodes x0 and bushes b0
    (default as assembled: unstressed, every bush centred in its housing), the housings displaced by S (rows: their
    positions; default fixed): every node after each sample (and the bushes at the end)."""
    n1 = len(core["f"])
    x0, b0 = _start(core, x0, b0)
    S = np.zeros((1, n1)) if S is None else np.asarray(S, float)
    out, b = _chain_run(np.asarray(core["k"], float), float(core["kt"]), np.asarray(core["f"], float), _gaps(core),
                        np.asarray(U, float), S, x0, b0)
    return (out, b) if return_bushes else out


# ---- creep: thermally activated slip of the PTFE bushes ----
#
# A polymer-on-metal contact does not stick outright: its junctions creep by thermally activated shear (the "creep"
# regime of a multicontact interface: Heslot, Baumberger, Perrin, Caroli & Caroli, Phys. Rev. E 49 (1994) 4973;
# Baumberger & Caroli, Adv. Phys. 55 (2006) 279; the direct, velocity-strengthening term of Dieterich and Ruina's
# rate-and-state friction, mu = mu0 + a ln(V / V0), without its ageing term): the slip rate is V0 exp((|R| - f) / (a'
# f)) in the direction of R, a' = a / mu0 (0.03 ... 0.045 for PTFE on steel), f the friction at V0; both directions
# together, v = w sinh(R / s), s = a' f, w = 2 V0 exp(-1 / a'). Held, a loaded bush keeps slipping at an
# exponentially falling rate (its force relaxes by s per e-fold of the time: logarithmic creep); moved, it takes a' f
# more per e-fold of the speed. Nothing sticks, so the chain is no longer rate independent (a bush floating in its
# clearance still takes no force).


def activated_params(f, a_rel, V0):
    """(s, w) of the activated slip law for frictions f (0 for a friction-free node: no law) at the relative rate
    sensitivity a_rel and the reference speed V0."""
    f = np.asarray(f, float)
    s = a_rel * f
    w = np.where(f > 0, 2.0 * V0 * math.exp(-1.0 / a_rel), 1.0)
    return s, w


def activated_chain(core, U, dt, a_rel, V0, sub=8, x0=None, b0=None):
    s, w = activated_params(core["f"], a_rel, V0)
    x0, b0 = _start(core, x0, b0)
    return _activated_run(np.asarray(core["k"], float), float(core["kt"]), s, w, _gaps(core), np.asarray(U, float),
                          int(sub), x0, b0, float(dt))[0]


# ---- rate dependence: Petroff's viscous drag in oil-lubricated bushes ----
#
# The bushes run on an oil film: beside the lip's Coulomb friction f_i each bush drags the rod with the film's viscous
# shear, c_i = mu pi D L / h (Petroff's law for a concentric journal, here sliding axially: N. P. Petroff, 1883; the
# film's viscosity mu, the rod's diameter D, the bush's length L, the clearance h). A seated bush then slides when the
# force on it exceeds f_i, at the speed (|R_i| - f_i) / c_i (a Bingham contact; a floating one is carried along): the
# chain's time constants c / k of a few ms make the loops widen with the rate.


def viscous_chain(core, U, dt, c, sub=8, x0=None, b0=None):
    x0, b0 = _start(core, x0, b0)
    return _viscous_run(np.asarray(core["k"], float), float(core["kt"]), np.asarray(core["f"], float), _gaps(core),
                        np.asarray(c, float), np.asarray(U, float), int(sub), x0, b0, float(dt))[0]


# ---- rate dependence (the pair): the coil's moving mass ----
#
# The coil carries a mirror cell: the driven node has a mass M on its centring flexure (its resonance f0 = sqrt(k_g /
# M) / 2 pi of 6 ... 10 Hz, its own damping ratio 0.03 ... 0.06), the rod and bushes stay quasi-static. The stroke
# overshoots where the drive turns quickly and rings where a bush lets go: a rate dependence beside the core.


def inertial_chain(core, U, dt, f0, zeta, sub=4, x0=None, b0=None):
    M = 1.0 / (2 * math.pi * f0) ** 2 * core["k"][0]
    c0 = 2.0 * zeta * math.sqrt(M * core["k"][0])
    x0, b0 = _start(core, x0, b0)
    return _inertial_run(np.asarray(core["k"], float), float(core["kt"]), np.asarray(core["f"], float), _gaps(core), M,
                         c0, np.asarray(U, float), int(sub), x0, b0, float(dt))[0]


# ---- initial state: the bushes' rail through a thermal cycle ----
#
# The bushes sit on an aluminium rail fixed at the coil's end; the rod is glass-epoxy. A warm spell (the room's air
# conditioning failing over a weekend) and its recovery stretch the rail against the rod and back, (alpha_Al -
# alpha_rod) dT times the distance from the fixed end (about 12e-6 / K: 10 K over a metre is 0.12 mm): each bush's
# housing is carried along the rod by that much and back, the bush dragging the rod where its friction holds, and the
# rod is left stressed and the bushes off centre.


def rail_cycle(pos, eps, n=60):
    """The supports' positions through the thermal cycle: every bush carried out to eps times its fractional distance
    from the fixed end (pos, 0 ... 1) and back in n steps each way (the coil, node 0, is not on the rail)."""
    th = np.r_[np.linspace(0.0, 1.0, n + 1), np.linspace(1.0, 0.0, n + 1)[1:]]
    S = eps * th[:, None] * np.asarray(pos, float)[None, :]
    S[:, 0] = 0.0
    return S


# ---- drift: the optical table re-levelling itself ----
#
# The actuator stands on a pneumatically isolated optical table, the reading's reference on the floor. A load put on the
# table (a box of optics, an elbow) sinks it on its air springs (by its weight over their stiffness, with the
# isolators' bounce: 1.2 ... 2 Hz, damping ratio 0.15 ... 0.3 from their laminar orifices); the levelling valves (a
# height-sensing valve per leg with a dead band) then feed air until the table is back within the dead band, at a rate
# limited by the valve's orifice (proportional over a band as wide as the dead band, then saturated), and vent it when
# the load is taken off. With z the table's height, m the air springs' equilibrium height and L the loads' sinking:
# z'' = w^2 (m - L - z) - 2 zeta w z', m' = q clip(e / e_s, -1, 1), e the height's error beyond the dead band (+-delta).
# Integrated by the classical Runge-Kutta method in 8 steps a sample.


def table_loads(t, loads):
    """The loads' sinking L(t): each load (t0, L, ramp) put on (L > 0) or taken off (L < 0) over a half-cosine ramp."""
    t = np.asarray(t, float)
    out = np.zeros(len(t))
    for t0, L, ramp in loads:
        s = np.clip((t - t0) / ramp, 0.0, 1.0)
        out += L * 0.5 * (1.0 - np.cos(math.pi * s))
    return out


@njit(cache=True)
def _table_rhs(t, z, zd, m, t0s, Ls, ramps, w, zeta, q, delta, e_s):
    L = 0.0
    for j in range(t0s.shape[0]):
        s = min(max((t - t0s[j]) / ramps[j], 0.0), 1.0)
        L += Ls[j] * 0.5 * (1.0 - math.cos(math.pi * s))
    e = -delta - z if z < -delta else (delta - z if z > delta else 0.0)
    return zd, w * w * (m - L - z) - 2.0 * zeta * w * zd, q * min(max(e / e_s, -1.0), 1.0)


@njit(cache=True)
def _table_run(t, t0s, Ls, ramps, w, zeta, q, delta, e_s, sub):
    h = (t[1] - t[0]) / sub
    z, zd, m = 0.0, 0.0, 0.0
    out = np.empty(t.shape[0])
    out[0] = 0.0
    for k in range(1, t.shape[0]):
        for s in range(sub):
            tk = t[k - 1] + s * h
            a1, b1, c1 = _table_rhs(tk, z, zd, m, t0s, Ls, ramps, w, zeta, q, delta, e_s)
            a2, b2, c2 = _table_rhs(tk + h / 2, z + h / 2 * a1, zd + h / 2 * b1, m + h / 2 * c1, t0s, Ls, ramps, w,
                                    zeta, q, delta, e_s)
            a3, b3, c3 = _table_rhs(tk + h / 2, z + h / 2 * a2, zd + h / 2 * b2, m + h / 2 * c2, t0s, Ls, ramps, w,
                                    zeta, q, delta, e_s)
            a4, b4, c4 = _table_rhs(tk + h, z + h * a3, zd + h * b3, m + h * c3, t0s, Ls, ramps, w, zeta, q, delta,
                                    e_s)
            z += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4)
            zd += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4)
            m += h / 6 * (c1 + 2 * c2 + 2 * c3 + c4)
        out[k] = z
    return out


def levelling_table(t, loads, f_iso, zeta, q, delta, e_s, sub=8):
    """The table's height on the uniform times t (from rest, level, at t[0] = 0); loads a list of (t0, L, ramp)."""
    L = np.asarray(loads, float).reshape(-1, 3)
    return _table_run(np.asarray(t, float), L[:, 0].copy(), L[:, 1].copy(), L[:, 2].copy(), 2 * math.pi * f_iso,
                      float(zeta), float(q), float(delta), float(e_s), int(sub))


# ---- asymmetry: a capacitive probe mounted tilted to the coil's target ----
#
# The coil's carriage is read by a capacitive probe facing its flat end. Mounted with its face tilted to the target, the
# gap runs linearly across the electrode, g(s) = g + theta s: the capacitance is eps w int ds / (g + theta s) = (eps w /
# theta) ln((g + a) / (g - a)), a = theta l / 2 the gap's excess at the electrode's edge, and the probe's electronics,
# calibrated for a parallel gap, read g_r = eps A / C = a / artanh(a / g): below the true gap, the more so the closer
# the target (g_r ~ g - a^2 / (3 g)): a reading steeper on the near side. (The tilt sensitivity of capacitive gauges:
# e.g. Smith, Chetwynd, Harb, "Foundations of ultraprecision mechanism design".)


def tilted_gap_reading(g, a):
    """The gap read by a probe tilted so that its electrode's edges see g +- a."""
    g = np.asarray(g, float)
    return a / np.arctanh(a / g) if a > 0 else g


def tilted_probe_reading(u, tau, stroke):
    """The reading over its slope at rest (slope 1 at u = 0), the gap 1 + stroke u (over the gap at rest), the tilt's
    edge excess tau (over the gap at rest)."""
    g = 1.0 + stroke * np.asarray(u, float)
    at = math.atanh(tau)
    slope = tau * tau / ((1.0 - tau * tau) * at * at)
    return (tilted_gap_reading(g, tau) - tau / at) / (stroke * slope)


# ---- saturation: a tangent arm read at its far end ----
#
# The carriage's ball tip pushes a flat lever (a tangent arm) at l from its pivot, square to it at rest: the lever turns
# by theta = atan(x / l) (the contact slides along its face; the tangent-bar drive of goniometers), held against the tip
# by a light spring. A capacitive probe reads the lever's far end, L from the pivot, along the lever's rest normal: L
# sin theta = L x / sqrt(l^2 + x^2), flattening toward the stroke's ends on both sides.


def tangent_arm_reading(u, z0):
    """The reading over its slope at rest, the tip at u times z0 l: u / sqrt(1 + (z0 u)^2)."""
    u = np.asarray(u, float)
    return u / np.sqrt(1.0 + (z0 * u) ** 2)


# ---- asymmetry (the pair): a swing-arm follower ----
#
# A swing arm (a feeler of radius R on a rotary encoder, its ball resting on the carriage's face) reads the carriage by
# its angle; mounted with the arm at theta0 off square to the face, the ball's travel along the face's normal is R
# (sin(theta0 + theta) - sin theta0): the encoder reads theta = asin(sin theta0 + x / R) - theta0, steeper toward the
# side where the arm turns past square.


def swing_arm_reading(u, th0, s):
    """The reading over its slope at rest (R cos theta0 theta over the stroke s R), the carriage at u s R."""
    u = np.asarray(u, float)
    return (np.arcsin(math.sin(th0) + s * u) - th0) * math.cos(th0) / s


# ---- delay: a laser scan micrometer ----
#
# The carriage's edge is read by a laser scan micrometer (a rotating polygon sweeps a collimated beam across the
# measuring field; the edge's position is timed from the shadow's onset at every scan; e.g. the instruments after
# Mitutoyo's LSM or Keyence's LS series): f_scan scans a second, the output the mean of the last M scans (its averaging
# setting, a power of 2), issued p scans after the last of them (its processing). A logger sampling at f_s reads the
# newest output: the mean of the M scans ending at the newest scan at least p scans before the sample, a moving average
# and a dead time together, (M - 1) / 2 + p scans and the scans' phase behind the sample.


def scan_times(t_end, f_scan, phase, M, p):
    """The scans' times from before the first average's window (M + p + 1 scans before 0) to t_end."""
    j0 = -(M + p + 1)
    j1 = int(math.floor(t_end * f_scan - phase)) + 1
    return (np.arange(j0, j1 + 1) + phase) / f_scan


def scan_micrometer(t, taus, scans, M, p, f_scan):
    """The logger's readings at times t: the mean of the M scans (values ``scans`` at times ``taus``) ending at the
    newest scan no later than t - p / f_scan."""
    t = np.asarray(t, float)
    last = np.searchsorted(taus, t - p / f_scan + 1e-12, side="right") - 1
    cs = np.r_[0.0, np.cumsum(scans)]
    return (cs[last + 1] - cs[last + 1 - M]) / M


# ---- out of vocabulary: Abbe's error from the stage's unrecorded second axis ----
#
# The carriage is the X axis of an XY stage whose Y axis runs its own programme (not recorded). The Y axis's drive yaws
# the carriage (its guide's parasitic rotation, proportional to the Y force on its flexure, so to the Y position), and
# the X probe, reading off the X axis's line by Abbe's offset, adds offset x yaw (Abbe, 1890): an unrecorded input
# added to the reading.


def abbe_reading(x, y_axis, kappa):
    return np.asarray(x, float) + kappa * np.asarray(y_axis, float)
