"""Mechanisms of the HOLDOUT36 set (``cases_holdout36.py``), each written from its law; the signals are in
:mod:`.signals36`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive, or the core's
output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout36.py against an independent
solution (an exact solution on the Bethe lattice, a brute-force relaxation of the whole lattice, solve_ivp, brentq, a
closed form, a reflection written as vectors or a direct sum).
"""

import math
from functools import lru_cache

import numpy as np
from numba import njit


# ---- the rate-independent core: a servo valve's torque motor whose iron is a random-field Ising model ----
#
# The first stage of an electrohydraulic servo valve: a torque motor whose armature carries the flapper. A permanent
# magnet polarises the four air gaps; the control coils (driven by a current amplifier: their MMF proportional to the
# drive) add a control flux through the armature, and the torque, 4 Phi_p Phi_c in the bridge, is linear in the control
# flux, so the flapper's deflection on its flexure tube is proportional to the control flux B. The hysteresis is the
# armature's and pole pieces' soft iron: its magnetisation is the zero-temperature random-field Ising model (Sethna,
# Dahmen, Kartha, Krumhansl, Roberts & Shore, Phys. Rev. Lett. 70 (1993) 3347): a periodic simple-cubic lattice of
# Ising grains s_i = +-1, each with a quenched random field h_i (Gaussian, of spread R in units of the coupling J = 1)
# and coupled ferromagnetically to its six neighbours. A grain is stable while s_i f_i >= 0, f_i = q + h_i + J sum_j s_j
# (q the field in the iron); when q moves, every grain that turns unstable flips, which may destabilise its neighbours:
# an avalanche (Barkhausen's jumps). The order of the flips within one field does not matter and the state after a
# monotone change of q depends only on its end (the "abelian" and "no-passing" properties, Sethna et al. 1993): rate
# independent, with return-point memory, but NOT a Preisach model (the grains interact, so the minor loops are not
# congruent: on the open iron by about 8 % of their rise) and not a Prandtl-Ishlinskii one. The magnetic circuit has
# air gaps (which bring the loops much closer to congruent, and keep the return-point memory): Ampere's law around it,
# with the flux continuous through iron and gaps, is H_d = q + k B (H_d the coils' MMF over the iron's length, k the
# gaps' shearing), B = m + chi q the flux (m = sum s_i / N, chi the grains' reversible rotation). The gaps feed the flux
# back on the iron's field: for a given H_d the iron sits where q + k B(q) = H_d; an avalanche that would carry the flux
# past it is not fired (the drive has not reached it yet: its trigger is where the field stops).

#: how far the scans reach back past the field they start from: a grain whose trigger is that field (where an avalanche
#: was held back) has -(-h - J n) - J n within a few ulps of h, so the sorted fields are searched that much wider (a
#: grain taken in needlessly is only tested and left)
EPS = 1e-9


@lru_cache(maxsize=4)
def cubic_neighbours(L):
    """The six neighbours of every site of a periodic L x L x L simple-cubic lattice (site x + L (y + L z))."""
    idx = np.arange(L ** 3).reshape(L, L, L)
    nb = np.stack([np.roll(idx, s, axis=a).ravel() for a in range(3) for s in (1, -1)], axis=1)
    nb = nb.astype(np.int32)
    nb.setflags(write=False)
    return nb


def chain_neighbours(n):
    """The two neighbours of every site of a periodic chain of n sites (the Bethe lattice of coordination 2)."""
    i = np.arange(n)
    return np.stack([(i - 1) % n, (i + 1) % n], axis=1).astype(np.int32)


def make_iron(nb, h, J=1.0):
    """The iron's quenched disorder: the neighbour table, the random fields and the fields sorted (with the sort's
    order), as a dict the solvers take."""
    h = np.asarray(h, float)
    order = np.argsort(h, kind="stable").astype(np.int32)
    return dict(nb=nb, h=h, order=order, hs=h[order], J=float(J))


def saturated(iron, sign):
    """Every grain at ``sign``: the state (s, nsum, q, M), q a field beyond the last grain's flip."""
    N, z = iron["nb"].shape
    s = np.full(N, sign, np.int8)
    nsum = np.full(N, sign * z, np.int8)
    q = sign * (np.abs(iron["h"]).max() + z * iron["J"] + 1.0)
    return (s, nsum, float(q), int(sign * N))


def copy_state(state):
    s, nsum, q, M = state
    return (s.copy(), nsum.copy(), float(q), int(M))


@njit(cache=True)
def _flip_spread(i0, new, H, h, J, s, nsum, nb, stack):
    """Flip grain i0 to ``new`` and spread the avalanche at the field H; returns the change of sum s."""
    z = nb.shape[1]
    s[i0] = new
    dM = 2 * new
    top = 0
    stack[top] = i0
    top += 1
    while top > 0:
        top -= 1
        i = stack[top]
        for a in range(z):
            j = nb[i, a]
            nsum[j] += 2 * new
            if s[j] == -new:
                if (H + h[j] + J * nsum[j]) * new > 0.0:
                    s[j] = new
                    dM += 2 * new
                    stack[top] = j
                    top += 1
    return dM


@njit(cache=True)
def _sweep(H0, H1, h, hs, order, J, s, nsum, nb, stack):
    """The open iron's field moved from H0 (the state stable there) to H1: every grain that the move destabilises,
    found among those whose threshold -h_i - J sum_j s_j lies between H0 and H1 (by their class sum_j s_j and the
    sorted fields), flipped with its avalanche; neighbours destabilised later are caught in the avalanches. Returns the
    change of sum s."""
    z = nb.shape[1]
    dM = 0
    if H1 == H0:
        return dM
    new = 1 if H1 > H0 else -1
    for c in range(z + 1):
        n = 2 * c - z
        if new == 1:
            lo = np.searchsorted(hs, -H1 - J * n, 'right')
            hi = np.searchsorted(hs, -H0 - J * n + EPS, 'right')
        else:
            lo = np.searchsorted(hs, -H0 - J * n - EPS, 'left')
            hi = np.searchsorted(hs, -H1 - J * n, 'left')
        for k in range(lo, hi):
            i = order[k]
            if s[i] == -new and nsum[i] == n:
                if (H1 + h[i] + J * nsum[i]) * new > 0.0:
                    dM += _flip_spread(i, new, H1, h, J, s, nsum, nb, stack)
    return dM


@njit(cache=True)
def _open_run(path, q, M, h, hs, order, J, s, nsum, nb):
    n = len(path)
    out = np.empty(n)
    N = len(h)
    stack = np.empty(N, np.int32)
    for k in range(n):
        M += _sweep(q, path[k], h, hs, order, J, s, nsum, nb, stack)
        q = path[k]
        out[k] = M / N
    return out, q, M


def open_iron(iron, state, path):
    """The open iron (no gap) driven along the field ``path``: m = sum s / N at each point, and the final state (the
    given state is not changed)."""
    s, nsum, q, M = copy_state(state)
    out, q, M = _open_run(np.asarray(path, float), q, M, iron["h"], iron["hs"], iron["order"], iron["J"], s, nsum,
                          iron["nb"])
    return out, (s, nsum, float(q), int(M))


@njit(cache=True)
def _hpush(hk, hv, n, key, val):
    i = n
    hk[i] = key
    hv[i] = val
    while i > 0:
        p = (i - 1) >> 1
        if hk[p] <= hk[i]:
            break
        hk[p], hk[i] = hk[i], hk[p]
        hv[p], hv[i] = hv[i], hv[p]
        i = p
    return n + 1


@njit(cache=True)
def _hpop(hk, hv, n):
    key = hk[0]
    val = hv[0]
    n -= 1
    if n > 0:
        hk[0] = hk[n]
        hv[0] = hv[n]
        i = 0
        while True:
            a = 2 * i + 1
            if a >= n:
                break
            c = a
            if a + 1 < n and hk[a + 1] < hk[a]:
                c = a + 1
            if hk[i] <= hk[c]:
                break
            hk[c], hk[i] = hk[i], hk[c]
            hv[c], hv[i] = hv[i], hv[c]
            i = c
    return key, val, n


@njit(cache=True)
def _advance(T, a, b, q, M, h, hs, order, J, s, nsum, nb, hk, hv, stack, log):
    """Move the iron's field q (the state stable there) until (1 + a) q + b M / N reaches T (b >= 0): the grains'
    triggers between q and the furthest reachable field kept in a heap, the avalanches fired in the order of their
    triggers (each at its trigger's field); one that would carry the left side past T is undone and q stops at its
    trigger; else q ends where the left side equals T. Returns (q, M)."""
    N = len(h)
    z = nb.shape[1]
    phi = (1.0 + a) * q + b * M / N
    if phi == T:
        return q, M
    sg = 1 if T > phi else -1
    qmax = (T - b * M / N) / (1.0 + a)
    nh = 0
    for c in range(z + 1):
        n = 2 * c - z
        if sg == 1:
            lo = np.searchsorted(hs, -qmax - J * n, 'right')
            hi = np.searchsorted(hs, -q - J * n + EPS, 'right')
        else:
            lo = np.searchsorted(hs, -q - J * n - EPS, 'left')
            hi = np.searchsorted(hs, -qmax - J * n, 'left')
        for k in range(lo, hi):
            i = order[k]
            if s[i] == -sg and nsum[i] == n:
                nh = _hpush(hk, hv, nh, sg * (-h[i] - J * n), i)
    while True:
        if nh == 0:
            q = (T - b * M / N) / (1.0 + a)
            break
        tu, i, nh = _hpop(hk, hv, nh)
        if s[i] != -sg or sg * (-h[i] - J * nsum[i]) != tu:
            continue                                   # a stale entry (the grain flipped or its class changed)
        t = sg * tu
        if sg * ((1.0 + a) * t + b * M / N - T) >= 0.0:
            q = (T - b * M / N) / (1.0 + a)
            break
        s[i] = sg
        dM = 2 * sg
        top = 0
        stack[top] = i
        top += 1
        nl = 0
        log[nl] = i
        nl += 1
        while top > 0:
            top -= 1
            u = stack[top]
            for e in range(z):
                j = nb[u, e]
                nsum[j] += 2 * sg
                if s[j] == -sg:
                    if sg * (t + h[j] + J * nsum[j]) > 0.0:
                        s[j] = sg
                        dM += 2 * sg
                        stack[top] = j
                        top += 1
                        log[nl] = j
                        nl += 1
                    else:
                        tj = sg * (-h[j] - J * nsum[j])
                        if tj < sg * qmax:
                            nh = _hpush(hk, hv, nh, tj, j)
        if sg * ((1.0 + a) * t + b * (M + dM) / N - T) > 0.0:
            for r in range(nl - 1, -1, -1):             # it would overshoot: undone, the field stops at its trigger
                u = log[r]
                s[u] = -sg
                for e in range(z):
                    nsum[nb[u, e]] -= 2 * sg
            q = t
            break
        M += dM
        q = t
    return q, M


def _buffers(N):
    return np.empty(8 * N + 64), np.empty(8 * N + 64, np.int32), np.empty(N, np.int32), np.empty(N, np.int32)


@njit(cache=True)
def _gap_run(Hd, k, chi, q, M, h, hs, order, J, s, nsum, nb, hk, hv, stack, log):
    N = len(h)
    n = len(Hd)
    B = np.empty(n)
    Q = np.empty(n)
    for t in range(n):
        q, M = _advance(Hd[t], k * chi, k, q, M, h, hs, order, J, s, nsum, nb, hk, hv, stack, log)
        B[t] = M / N + chi * q
        Q[t] = q
    return B, Q, q, M


def gapped_iron(iron, state, Hd, k, chi, return_field=False):
    """The torque motor's control flux B = m + chi q for the coils' MMF path ``Hd`` (in the coupling's units over the
    iron's length), the iron's field solving q + k B = Hd at every sample, from ``state`` (not changed). Returns (B,
    final state), and the iron's field too with ``return_field``."""
    s, nsum, q, M = copy_state(state)
    hk, hv, stack, log = _buffers(len(iron["h"]))
    B, Q, q, M = _gap_run(np.asarray(Hd, float), float(k), float(chi), q, M, iron["h"], iron["hs"], iron["order"],
                          iron["J"], s, nsum, iron["nb"], hk, hv, stack, log)
    st = (s, nsum, float(q), int(M))
    return (B, st, Q) if return_field else (B, st)


def demagnetise(iron, n_rev=200, amp=None):
    """The iron demagnetised before assembly (no gap): from positive saturation an alternating field whose amplitude
    falls linearly from ``amp`` (beyond saturation) to 0 over n_rev reversals, ending at 0. Returns the state."""
    z = iron["nb"].shape[1]
    if amp is None:
        amp = np.abs(iron["h"]).max() + z * iron["J"] + 1.0
    amps = amp * (1.0 - np.arange(n_rev) / n_rev)
    pts = np.r_[[a * (-1.0) ** (j + 1) for j, a in enumerate(amps)], 0.0]
    _, st = open_iron(iron, saturated(iron, 1), pts)
    return st


@lru_cache(maxsize=12)
def _iron_cached(L, R, seed):
    h = R * np.random.default_rng(seed).standard_normal(L ** 3)
    iron = make_iron(cubic_neighbours(L), h)
    st = demagnetise(iron)
    for arr in (iron["h"], iron["hs"], iron["order"], st[0], st[1]):
        arr.setflags(write=False)
    return iron, st


def torque_motor_iron(L, R, seed):
    """The iron of side L, disorder R, its random fields drawn from ``seed`` (numpy's default generator, standard
    normals times R), and its demagnetised state (both cached; the state is copied by every solver)."""
    return _iron_cached(int(L), float(R), int(seed))


def virgin_field(iron, state, m_target, q_top, n=4001):
    """The open iron's field where its magnetisation, rising from ``state`` along a ramp of n points to q_top, first
    reaches m_target (linear between the ramp's points)."""
    qs = np.linspace(state[2], q_top, n)
    m, _ = open_iron(iron, state, qs)
    j = int(np.argmax(m >= m_target))
    if m[j] < m_target:
        raise ValueError("the ramp does not reach m_target")
    return float(np.interp(m_target, m[j - 1:j + 1], qs[j - 1:j + 1]))


# ---- rate dependence: the coils' aluminium bobbins, a shorted turn on the armature's flux ----
#
# The control coils are wound on aluminium bobbins that encircle the armature: each is a shorted turn. Its current i_s
# (as an MMF over the iron's length) obeys tau i_s' + i_s = -kappa B' (Lenz; tau its L / R, kappa its coupling over its
# resistance), and adds to the coils' MMF: H_d + i_s = q + k B. Per step of length h the trapezoidal rule (the
# integral of i_s over the step as h (i_old + i_new) / 2; second order, A-stable) gives i_new = ((tau - h / 2) i_old -
# kappa (B_new - B_old)) / (tau + h / 2), so the iron's field solves q + (k + g) B(q) = H_d + ((tau - h / 2) i_old +
# kappa B_old) / (tau + h / 2), g = kappa / (tau + h / 2): the same avalanche solver with the gap's k raised by g.

@njit(cache=True)
def _eddy_run(Hf, hstep, k, chi, kappa, tau, q, M, h, hs, order, J, s, nsum, nb, hk, hv, stack, log):
    N = len(h)
    n = len(Hf)
    B = np.empty(n)
    I = np.empty(n)
    Bo = M / N + chi * q
    io = 0.0
    tp, tm = tau + 0.5 * hstep, tau - 0.5 * hstep
    g = kappa / tp
    for t in range(n):
        T = Hf[t] + (tm * io + kappa * Bo) / tp
        q, M = _advance(T, (k + g) * chi, k + g, q, M, h, hs, order, J, s, nsum, nb, hk, hv, stack, log)
        Bn = M / N + chi * q
        io = (tm * io - kappa * (Bn - Bo)) / tp
        Bo = Bn
        B[t] = Bn
        I[t] = io
    return B, I, q, M


def bobbin_eddy_iron(iron, state, Hd, dt, k, chi, kappa, tau, sub=16, return_current=False):
    """The control flux with the bobbins' shorted turn: ``sub`` trapezoidal steps a sample (H_d linear between the
    samples), from ``state`` with no current in the bobbin. Returns B at the samples (and the bobbin's MMF)."""
    Hd = np.asarray(Hd, float)
    Hf = np.interp(np.arange((len(Hd) - 1) * sub + 1) / sub, np.arange(len(Hd)), Hd)
    s, nsum, q, M = copy_state(state)
    hk, hv, stack, log = _buffers(len(iron["h"]))
    B, I, q, M = _eddy_run(Hf, dt / sub, float(k), float(chi), float(kappa), float(tau), q, M, iron["h"],
                           iron["hs"], iron["order"], iron["J"], s, nsum, iron["nb"], hk, hv, stack, log)
    return (B[::sub], I[::sub]) if return_current else B[::sub]


# ---- creep: the diffusion after-effect of carbon and nitrogen in the armature's iron (Richter, Snoek) ----
#
# Interstitial carbon and nitrogen in iron re-order in the strain and magnetisation of the domain walls (Snoek's
# relaxation; Richter, Ann. Phys. 1937, for its magnetic after-effect), stabilising a wall where it stands: after the
# flux changes, a share of the change is at first held back and follows as the interstitials re-order, each species a
# Debye relaxation of its own time tau = tau_ref exp(Q / k_B (1 / T - 1 / T_ref)) (its Snoek peak at 1 Hz: carbon near
# 40 C with Q ~ 0.87 eV, nitrogen near 25 C with Q ~ 0.79 eV; Nowick & Berry, *Anelastic Relaxation in Crystalline
# Solids*, 1972). A servo valve on a cold hydraulic unit (-5 ... 5 C) sees seconds to tens of seconds.

K_B_EV = 8.617333e-5


def snoek_tau(T_c, peak_c, Q_ev):
    """The relaxation time at T_c (deg C) of a species whose Snoek peak at 1 Hz (omega tau = 1) sits at peak_c."""
    return 1.0 / (2 * math.pi) * math.exp(Q_ev / K_B_EV * (1.0 / (T_c + 273.15) - 1.0 / (peak_c + 273.15)))


def debye_lag(x, dt, tau):
    """w with tau w' = x - w, w(0) = x(0), x linear between the samples: the exact first-order-hold step."""
    x = np.asarray(x, float)
    return _debye_run(x, math.exp(-dt / tau), (1.0 - math.exp(-dt / tau)) * tau / dt)


@njit(cache=True)
def _debye_run(x, e, c):
    n = len(x)
    w = np.empty(n)
    w[0] = x[0]
    for k in range(1, n):
        w[k] = x[k] + e * (w[k - 1] - x[k - 1]) - (x[k] - x[k - 1]) * c
    return w


def after_effect(B, dt, shares, taus):
    """The flux seen: B less the shares still held back, B - sum c_j (B - w_j), each w_j B's Debye lag of tau_j."""
    B = np.asarray(B, float)
    out = B.copy()
    for c, tau in zip(shares, taus):
        out -= c * (B - debye_lag(B, dt, tau))
    return out


# ---- drift: the stray current of a DC tramway lifting the laboratory's ground ----
#
# A tram leaving the stop by the laboratory draws its starting current (the controller notching at a constant current
# I_s, then the series motors' current falling as their back EMF grows: exponentially to the cruising current); its
# return current runs in the rails, whose potential to the earth at the laboratory (and so the offset of the
# single-ended reading, its ground bonded to the building's steel) is that current times the share of the rail's
# resistance behind it, falling as the tram runs off towards the substation (e.g. the stray-current chapters of any
# traction-supply handbook; the rail-to-earth potential is a classic cause of offsets in measurements near tramways).

def tram_current(t, t0, ramp, I_s, t_notch, I_c, tau_m, run):
    """A tram's line current from its start at t0: eased up to I_s over ``ramp`` s, held while notching (t_notch), then
    falling as I_c + (I_s - I_c) exp(-(t - t_n) / tau_m); off after ``run`` s (coasting), 0 before t0."""
    t = np.asarray(t, float)
    s = t - t0
    out = np.zeros(len(t))
    m = (s > 0) & (s < run)
    ss = s[m]
    up = 0.5 * (1 - np.cos(math.pi * np.clip(ss / ramp, 0.0, 1.0)))
    fall = np.where(ss > t_notch, I_c + (I_s - I_c) * np.exp(-(ss - t_notch) / tau_m), I_s)
    off = 0.5 * (1 + np.cos(math.pi * np.clip((ss - (run - ramp)) / ramp, 0.0, 1.0)))
    out[m] = up * fall * off
    return out


def tram_offset(t, trams, lam):
    """The rails' potential at the laboratory: each tram's current times its share exp(-x / lam) of the rail behind it,
    x its distance run (x = the integral of a speed rising in proportion to the time since it started, v = a s: x = a
    s^2 / 2, the tram's constant acceleration), signed by the side of the stop it leaves to. ``trams`` are (t0, ramp,
    I_s, t_notch, I_c, tau_m, run, a, side)."""
    t = np.asarray(t, float)
    out = np.zeros(len(t))
    for t0, ramp, I_s, t_notch, I_c, tau_m, run, acc, side in trams:
        s = np.maximum(t - t0, 0.0)
        out += side * tram_current(t, t0, ramp, I_s, t_notch, I_c, tau_m, run) * np.exp(-0.5 * acc * s * s / lam)
    return out


# ---- asymmetry: a variable-reluctance proximity sensor in an LC oscillator, read by its frequency ----

def reluctance_frequency(g):
    """A coil on a ferrite pot core facing the flapper across the gap g: its reluctance is the gap's (the ferrite's
    negligible), L = N^2 mu0 A / (2 g), tuned by a fixed capacitor: f = 1 / (2 pi sqrt(L C)), in units of the rest
    gap's frequency: sqrt(g) (g in units of the rest gap)."""
    return np.sqrt(np.asarray(g, float))


def reluctance_reading(u, r):
    """The frequency's change for the flapper's travel u (-1 ... 1) closing the gap by r u (r of the rest gap), scaled
    to slope 1 at u = 0 and rising with u: 2 (1 - sqrt(1 - r u)) / r; the ends' secants 2 (1 - sqrt(1 - r)) / r and 2
    (sqrt(1 + r) - 1) / r."""
    return 2.0 * (1.0 - reluctance_frequency(1.0 - r * np.asarray(u, float))) / r


# ---- saturation: the pilot stage's differential pressure (a double nozzle-flapper) ----

def nozzle_back_pressure(g, g_c):
    """A nozzle fed from the supply through a fixed orifice and discharging past the flapper at the gap g: one flow
    through the orifice (area a_o) and the nozzle's curtain (pi d_n g), both sharp-edged with one discharge
    coefficient, so (p_s - p) a_o^2 = p (pi d_n g)^2 and p / p_s = 1 / (1 + (g / g_c)^2), g_c = a_o / (pi d_n) (e.g.
    Merritt, *Hydraulic Control Systems*, 1967, ch. 7)."""
    return 1.0 / (1.0 + (np.asarray(g, float) / g_c) ** 2)


def pilot_pressure(x, beta):
    """The spool-end pressures' difference (over p_s) of two nozzles x0 either side of the flapper at x (in units of
    x0; beta = x0 / g_c): P(1 - x) - P(1 + x), odd in x."""
    x = np.asarray(x, float)
    return nozzle_back_pressure(1.0 - x, 1.0 / beta) - nozzle_back_pressure(1.0 + x, 1.0 / beta)


def pilot_slope(beta):
    """d/dx of :func:`pilot_pressure` at 0: 4 beta^2 / (1 + beta^2)^2."""
    return 4.0 * beta * beta / (1.0 + beta * beta) ** 2


def pilot_reading(u, stroke, beta):
    """The differential pressure for the flapper's travel u (-1 ... 1) reaching ``stroke`` of the nozzles' gap x0,
    scaled to slope 1 at u = 0."""
    return pilot_pressure(stroke * np.asarray(u, float), beta) / (stroke * pilot_slope(beta))


# ---- delay: a strobed camera whose frames pass a fixed processing pipeline ----

def camera_pipeline(hf, R, M):
    """A machine-vision camera watching a mark on the flapper's extension: a strobe (microseconds) freezes each frame,
    R frames a record sample (the core on the frames' grid), and each frame's position leaves the fixed pipeline
    (transfer, buffering, centroid) M frames after its exposure; the logger reads the newest at each record sample.
    Before the first frame arrives the reading is hf[0]."""
    hf = np.asarray(hf, float)
    k = np.arange(0, len(hf), R) - M
    return hf[np.maximum(k, 0)]


# ---- the initial state: a servo amplifier's spool-unsticking routine ----

def unsticking_routine(step, n_pulses, hold, gap, n_per=30):
    """A servo amplifier's 'chip-shear' routine for a silted spool, run before the valve was taken for the test: current
    pulses of alternating sign and growing size, +step, -2 step, +3 step, ... (n_pulses of them), each reached over
    n_per points, held (``hold`` points) and released to 0 (``gap`` points at 0 between). Returns the drive's path (a
    point sequence: the core is rate independent)."""
    path = [np.zeros(1)]
    for j in range(1, n_pulses + 1):
        lv = (1 if j % 2 else -1) * j * step
        path += [np.linspace(0.0, lv, n_per + 1)[1:], np.full(hold, lv), np.linspace(lv, 0.0, n_per + 1)[1:],
                 np.zeros(gap)]
    return np.concatenate(path)


# ---- the pair: the hydraulic oil warming (a null shift) and an optical lever read at an oblique angle ----

def oil_network(tau_x, tau_a, ratio):
    """The state matrix of the hydraulic unit's oil (heat capacity 1) exchanging heat with its reservoir's steel
    (capacity ``ratio``) through a conductance 1 / tau_x, the steel losing heat to the room through ratio / tau_a:
    d/dt [T_o, T_r] = A [T_o, T_r] + [p, 0] under the pump's loss power p (a lumped two-node network; e.g. the heat
    balance of hydraulic power units in Merritt, *Hydraulic Control Systems*, 1967)."""
    g = 1.0 / tau_x
    return np.array([[-g, g], [g / ratio, -(g + ratio / tau_a) / ratio]])


def oil_warmup(t, t_on, A):
    """The oil's temperature over the room's under a unit loss power since the pump started, t_on s before t = 0 (the
    record's start), from A's eigen-decomposition: T(s) = V diag((exp(lam s) - 1) / lam) V^-1 [1, 0]."""
    lam, V = np.linalg.eig(A)
    c = np.linalg.solve(V, np.array([1.0, 0.0]))
    s = np.asarray(t, float) + t_on
    return np.real(sum(V[0, j] * c[j] * np.expm1(lam[j] * s) / lam[j] for j in range(2)))


def optical_lever(u, phi0, dphi):
    """A mirror on the flapper turns the laser beam by dphi u (twice its tilt; u -1 ... 1) about phi0 from the normal of
    a scale at the distance D: the spot at D tan(phi0 + dphi u) (Poggendorff's mirror and scale), less its rest, scaled
    to slope 1 at u = 0: (tan(phi0 + dphi u) - tan phi0) / (dphi sec^2 phi0)."""
    u = np.asarray(u, float)
    return (np.tan(phi0 + dphi * u) - math.tan(phi0)) * math.cos(phi0) ** 2 / dphi


# ---- out of vocabulary: a JFET op-amp follower driven below its common-mode range (phase reversal) ----

def phase_reversal(x, x_c, width, rail):
    """A follower whose input falls below its input common-mode limit x_c: there the input stage's JFETs saturate and
    the output swings to the positive rail (the phase reversal of early JFET op-amps, e.g. the LF356 and TL07x data
    sheets' warnings). Above x_c the output follows; below it, it goes to ``rail`` through a transition of ``width``
    (a half-cosine blend)."""
    x = np.asarray(x, float)
    s = np.clip((x_c - x) / width, 0.0, 1.0)
    w = 0.5 * (1.0 - np.cos(math.pi * s))
    return (1.0 - w) * x + w * rail
