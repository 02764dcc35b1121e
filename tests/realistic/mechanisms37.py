"""Mechanisms of the HOLDOUT37 set (``cases_holdout37.py``), each written from its law; the signals are in
:mod:`.signals37`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive, or the core's
output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout37.py against an independent
solution (a brute-force relaxation of the whole pore network, a brute-force fixed-volume solve, a brute-force
integration of every cavity's hazard, the closed-form logarithmic law of independent cavities, solve_ivp, quad, a
method-of-characteristics solution of the line, a geometry written as vectors or integer arithmetic).
"""

import math
from functools import lru_cache

import numpy as np
from numba import njit
from scipy.special import kei


# ---- the rate-independent core: a push-pull pair of liquid-nanofoam cells ----
#
# A "heterogeneous lyophobic system" (Eroshenko, Regis, Soulard & Patarin, J. Am. Chem. Soc. 123 (2001) 8129; as
# dampers and actuators, "liquid nanofoams", e.g. Qiao's group): a sealed bellows cell holding a hydrophobised
# mesoporous silica powder under water. Water does not wet the pores: it is pushed into a pore only when the pressure
# exceeds the Laplace-Washburn pressure of the pore's entrance, p = 2 gamma |cos theta_a| / r (gamma the water's surface
# tension, theta_a the advancing contact angle, r the entrance's radius), and it leaves a filled cavity when the
# pressure falls below the pressure at which its liquid recedes (the receding angle theta_r: 2 gamma |cos theta_r| /
# r_s, r_s the cavity's radius). The silica's pores are a network of cavities joined by narrower necks (Mason, Proc. R.
# Soc. Lond. A 390 (1983) 47 and 415 (1988) 453, for capillary condensation in Vycor; the "ink-bottle" picture): water
# enters a cavity only through a neck from a filled neighbour or from the bulk water at the grain's surface, so a
# cavity whose necks all lead to empty cavities is not reached however high the pressure (pore blocking), while a
# filled cavity empties by itself (the vapour nucleates in it). The necks are no wider than the cavities they join
# (Mayagoitia's construction principle of the dual site-bond model: Mayagoitia, Rojas & Kornhauser, J. Chem. Soc.,
# Faraday Trans. 1 81 (1985) 2931): a neck's radius is the smaller cavity's times a uniform factor 0.5 ... 0.8.
#
# Filling is monotone in the neighbours' filling and emptying is local, so the dynamics keep the order of two states
# under the order of two pressure histories ("no passing", the property behind the random-field Ising model's memory:
# Sethna et al., Phys. Rev. Lett. 70 (1993) 3347): rate independent, with return-point memory, the state after a
# monotone change of pressure independent of the order in which the events are processed; NOT a Preisach model (the
# necks couple the cavities: a minor loop's rise depends on which cavities were emptied before) and not a
# Prandtl-Ishlinskii one (intrusion and extrusion are different laws).
#
# Units: pressures over P0 = 2 gamma |cos theta_a| / r0 (r0 the cavities' median radius; for water at 120 deg in 4 nm
# cavities about 18 MPa); a neck of radius r_n enters at a = r0 / r_n, a cavity of radius r_s empties at b = lam r0 /
# r_s (lam = |cos theta_r| / |cos theta_a|); a cavity's volume is r_s^3 (integers: r_s^3 in units of r0^3 / 2^20,
# rounded, so that the filled volume is summed exactly in any order).
#
# A servo valve sets the two cells' pressures in push-pull about a preload, p_A,B = p_c +- dp u (u the drive over its
# peak; for a unipolar stroke u = 2 v / top - 1: the valve biased so that 0 V is one end); each cell's bellows travel is
# (kappa p + S) in units of its pore volume over the bellows' area (kappa the water's and the bellows' compliance
# over the pore volume, S the filled share of the pore volume), and the cells push the two ends of a rocker, whose tip
# is the output: gain (x_A - x_B).

N_SIDES = 6
VOL_SCALE = 2 ** 20


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
def _frontier(filled, nb, a, hk, hv):
    """The heap of every open neck into an empty cavity (from a filled neighbour or from the bulk water), keyed by its
    entry pressure; its value j * 6 + k (cavity j, its side k)."""
    n = 0
    for j in range(filled.shape[0]):
        if not filled[j]:
            for k in range(N_SIDES):
                i = nb[j, k]
                if i == -1 or (i >= 0 and filled[i]):
                    n = _hpush(hk, hv, n, a[j, k], j * N_SIDES + k)
    return n


@njit(cache=True)
def _top_in(hk, hv, n, filled, nb):
    """Drop the heap's stale tops (the cavity filled meanwhile, or the neighbour the neck leads from emptied)."""
    while n > 0:
        val = hv[0]
        j = val // N_SIDES
        i = nb[j, val % N_SIDES]
        if filled[j] or (i >= 0 and not filled[i]):
            _, _, n = _hpop(hk, hv, n)
        else:
            break
    return n


@njit(cache=True)
def _push_in(hk, hv, n, key, val, filled, nb, a):
    if n >= hk.shape[0]:
        n = _frontier(filled, nb, a, hk, hv)           # the heap full of stale entries: rebuilt from the state
        return n
    return _hpush(hk, hv, n, key, val)


@njit(cache=True)
def _fill(j, filled, nb, a, hk, hv, n):
    """Cavity j fills: the necks from it into its empty neighbours open."""
    filled[j] = True
    for k in range(N_SIDES):
        i = nb[j, k]
        if i >= 0 and not filled[i]:
            n = _push_in(hk, hv, n, a[j, k], i * N_SIDES + (k ^ 1), filled, nb, a)
    return n


@njit(cache=True)
def _empty(j, filled, nb, a, hk, hv, n):
    """Cavity j empties: its necks from filled neighbours (or from the bulk water) open into it."""
    filled[j] = False
    for k in range(N_SIDES):
        i = nb[j, k]
        if i == -1 or (i >= 0 and filled[i]):
            n = _push_in(hk, hv, n, a[j, k], j * N_SIDES + k, filled, nb, a)
    return n


@njit(cache=True)
def _soft_run(path, p, S, filled, nb, a, b, vol, hk, hv, ek, ev):
    """The cell at the pressures ``path`` (its state p, S, filled): the filled volume after each."""
    nin = _frontier(filled, nb, a, hk, hv)
    nex = 0
    for j in range(filled.shape[0]):
        if filled[j]:
            nex = _hpush(ek, ev, nex, -b[j], j)
    out = np.empty(path.shape[0], np.int64)
    for t in range(path.shape[0]):
        pn = path[t]
        if pn > p:
            while True:
                nin = _top_in(hk, hv, nin, filled, nb)
                if nin == 0 or hk[0] > pn:
                    break
                _, val, nin = _hpop(hk, hv, nin)
                j = val // N_SIDES
                nin = _fill(j, filled, nb, a, hk, hv, nin)
                S += vol[j]
                nex = _hpush(ek, ev, nex, -b[j], j)
        elif pn < p:
            while nex > 0 and -ek[0] >= pn:
                _, j, nex = _hpop(ek, ev, nex)
                if filled[j]:
                    nin = _empty(j, filled, nb, a, hk, hv, nin)
                    S -= vol[j]
        p = pn
        out[t] = S
    return out, p, S


def cubic_grains(n_grains, L):
    """The neighbour table of n_grains separate L^3 cubes of cavities: nb[j, k] the neighbour on side k (sides 2m and
    2m + 1 opposite), -1 where side k is on the grain's surface (the bulk water)."""
    n = L ** 3
    idx = np.arange(n).reshape(L, L, L)
    one = -np.ones((L, L, L, N_SIDES), np.int64)
    one[:-1, :, :, 0] = idx[1:]
    one[1:, :, :, 1] = idx[:-1]
    one[:, :-1, :, 2] = idx[:, 1:]
    one[:, 1:, :, 3] = idx[:, :-1]
    one[:, :, :-1, 4] = idx[:, :, 1:]
    one[:, :, 1:, 5] = idx[:, :, :-1]
    one = one.reshape(n, N_SIDES)
    nb = np.tile(one, (n_grains, 1))
    off = np.repeat(np.arange(n_grains, dtype=np.int64) * n, n)[:, None]
    return np.where(nb >= 0, nb + off, -1)


def make_foam(nb, r_site, neck_factor, lam):
    """A pore network from its neighbour table, the cavities' radii (over r0) and one factor per side (0.5 ... 0.8; a
    neck between two cavities takes the factor of its lower-numbered cavity's side): the necks' entry pressures a (the
    same from both sides), the cavities' emptying pressures b and integer volumes."""
    nb = np.asarray(nb, np.int64)
    r_site = np.asarray(r_site, float)
    N = len(r_site)
    j = np.arange(N)[:, None]
    other = np.where(nb >= 0, nb, j)
    a = 1.0 / (np.minimum(r_site[:, None], r_site[other]) * neck_factor)
    k = np.broadcast_to(np.arange(N_SIDES)[None, :], nb.shape)
    upper = (nb >= 0) & (nb < j)
    a[upper] = a[nb[upper], k[upper] ^ 1]
    b = lam / r_site
    vol = np.maximum(np.rint(r_site ** 3 * VOL_SCALE), 1).astype(np.int64)
    return dict(nb=nb, a=a, b=b, vol=vol, V=int(vol.sum()))


@lru_cache(maxsize=24)
def _foam_cached(n_grains, L, sig, lam, seed):
    rng = np.random.default_rng(seed)
    nb = cubic_grains(n_grains, L)
    r = np.exp(sig * rng.standard_normal(len(nb)))
    foam = make_foam(nb, r, rng.uniform(0.5, 0.8, nb.shape), lam)
    for key in ("nb", "a", "b", "vol"):
        foam[key].setflags(write=False)
    return foam


def nanofoam(n_grains, L, sig, lam, seed):
    """The silica of one cell: n_grains grains of L^3 cavities, the cavities' radii lognormal (spread sig about r0),
    the neck factors uniform on 0.5 ... 0.8, all from numpy's default generator seeded with ``seed`` (cached)."""
    return _foam_cached(int(n_grains), int(L), float(sig), float(lam), int(seed))


def dry_state(foam):
    """Every cavity empty, at zero pressure (the dry powder under water at atmospheric pressure)."""
    return (np.zeros(len(foam["b"]), np.bool_), 0.0, 0)


def _buffers(N):
    return np.empty(8 * N), np.empty(8 * N, np.int64), np.empty(N + 1), np.empty(N + 1, np.int64)


def foam_cell(foam, state, path):
    """The cell driven along the pressures ``path`` from ``state`` = (filled, p, S): the filled share of its pore
    volume after each, and the final state (the given state is not changed)."""
    filled = state[0].copy()
    hk, hv, ek, ev = _buffers(len(filled))
    out, p, S = _soft_run(np.asarray(path, float), float(state[1]), int(state[2]), filled, foam["nb"], foam["a"],
                          foam["b"], foam["vol"], hk, hv, ek, ev)
    return out / foam["V"], (filled, float(p), int(S))


def run_in_path(p0, amp, n_rev=40):
    """The run-in of a cell before use: from atmospheric pressure to p0, then cycled about p0 with an amplitude falling
    linearly from amp to 0 over n_rev reversals, ending at p0."""
    amps = amp * (1.0 - np.arange(n_rev) / n_rev)
    pts = np.r_[p0 + amps * (-1.0) ** np.arange(n_rev), p0]
    return np.r_[0.0, np.maximum(pts, 0.0)]


@lru_cache(maxsize=24)
def _run_in_cached(n_grains, L, sig, lam, seed, p0, amp):
    foam = nanofoam(n_grains, L, sig, lam, seed)
    _, st = foam_cell(foam, dry_state(foam), run_in_path(p0, amp))
    st[0].setflags(write=False)
    return st


def run_in(n_grains, L, sig, lam, seed, p0, amp):
    """The state of a cell run in about p0 from amplitude amp (cached)."""
    return _run_in_cached(int(n_grains), int(L), float(sig), float(lam), int(seed), float(p0), float(amp))


# ---- rate dependence: the cells fed through sintered snubbers (Darcy flow) ----
#
# Each cell is fed from its valve port through a sintered-bronze pressure snubber: a porous plug whose flow is Darcy's
# law, Q = k A / (mu L) (p_port - p_cell), its permeability k the Kozeny-Carman one, k = d^2 eps^3 / (180 (1 - eps)^2)
# (Carman, Trans. Inst. Chem. Eng. 15 (1937) 150; d the sintered grains' size, eps the porosity): a laminar resistance
# R. The flow fills the cell's volume, kappa p + S (in its pore volume), so that the cell's pressure lags the port's
# with the time constant tau = R kappa on the water's and bellows' compliance alone and far more where the silica
# takes or gives water (its intrusion and extrusion act as a large, hysteretic compliance): a rate dependence inside
# the core. Stepped by the trapezoidal rule in the cell's volume, each sub-step an implicit solve p + k S = T of the
# network at fixed "volume" (the hard device: a cavity fills when the pressure reaches its neck's entry pressure, the
# pressure then drops by k times its volume).


@njit(cache=True)
def _hard_solve(T, k, p, S, filled, nb, a, b, vol, hk, hv, nin, ek, ev, nex):
    """The network where p + k S = T (k per unit of integer volume): events fired one at a time, each at the pressure
    the line p = T - k S gives before it; returns p, S and the heaps' sizes."""
    while True:
        p = T - k * S
        nin = _top_in(hk, hv, nin, filled, nb)
        if nin > 0 and hk[0] <= p:
            _, val, nin = _hpop(hk, hv, nin)
            j = val // N_SIDES
            nin = _fill(j, filled, nb, a, hk, hv, nin)
            S += vol[j]
            nex = _hpush(ek, ev, nex, -b[j], j)
            continue
        while nex > 0 and not filled[ev[0]]:
            _, _, nex = _hpop(ek, ev, nex)
        if nex > 0 and -ek[0] >= p:
            _, j, nex = _hpop(ek, ev, nex)
            nin = _empty(j, filled, nb, a, hk, hv, nin)
            S -= vol[j]
            continue
        return p, S, nin, nex


@njit(cache=True)
def _snubber_run(port, sub, h, tau, kappa, V, p, S, filled, nb, a, b, vol, hk, hv, ek, ev):
    nin = _frontier(filled, nb, a, hk, hv)
    nex = 0
    for j in range(filled.shape[0]):
        if filled[j]:
            nex = _hpush(ek, ev, nex, -b[j], j)
    c = h / (2.0 * tau)
    k = 1.0 / (kappa * (1.0 + c) * V)
    n = port.shape[0]
    out_p = np.empty(n)
    out_S = np.empty(n, np.int64)
    out_p[0] = p
    out_S[0] = S
    for t in range(1, n):
        for s in range(sub):
            q_o = port[t - 1] + (port[t] - port[t - 1]) * s / sub
            q_n = port[t - 1] + (port[t] - port[t - 1]) * (s + 1) / sub
            T = (p * (1.0 - c) + S / (kappa * V) + c * (q_n + q_o)) / (1.0 + c)
            p, S, nin, nex = _hard_solve(T, k, p, S, filled, nb, a, b, vol, hk, hv, nin, ek, ev, nex)
        out_p[t] = p
        out_S[t] = S
    return out_p, out_S, p, S


def snubbed_cell(foam, state, port, dt, tau, kappa, sub=16):
    """The cell fed through its snubber from the port pressures ``port`` (one a record sample, the first the cell's own
    pressure at rest: the state's p), ``sub`` trapezoidal sub-steps a sample, the port linear between the samples:
    the cell's pressure and filled share after each sample, and the final state."""
    filled = state[0].copy()
    hk, hv, ek, ev = _buffers(len(filled))
    port = np.asarray(port, float)
    pc, Sc, p, S = _snubber_run(port, int(sub), dt / sub, float(tau), float(kappa), float(foam["V"]),
                                float(state[1]), int(state[2]), filled, foam["nb"], foam["a"], foam["b"], foam["vol"],
                                hk, hv, ek, ev)
    return pc, Sc / foam["V"], (filled, float(p), int(S))


def hard_cell(foam, state, T, k):
    """The network at fixed volume: for each target T, the state where p + k S = T (S the filled share). Returns the
    pressures, the filled shares and the final state."""
    filled = state[0].copy()
    hk, hv, ek, ev = _buffers(len(filled))
    nb, a, b, vol = foam["nb"], foam["a"], foam["b"], foam["vol"]
    nin = _frontier(filled, nb, a, hk, hv)
    nex = 0
    for j in np.nonzero(filled)[0]:
        nex = _hpush(ek, ev, nex, -b[j], j)
    p, S = float(state[1]), int(state[2])
    ps, Ss = [], []
    for x in np.asarray(T, float):
        p, S, nin, nex = _hard_solve(x, k / foam["V"], p, S, filled, nb, a, b, vol, hk, hv, nin, ek, ev, nex)
        ps.append(p)
        Ss.append(S)
    return np.array(ps), np.array(Ss) / foam["V"], (filled, float(p), int(S))


# ---- creep: thermally activated drying of the filled cavities ----
#
# A filled hydrophobic cavity empties by the nucleation of a vapour bubble, a thermally activated event (Guillemot,
# Biben, Galarneau, Vigier & Charlaix, Proc. Natl. Acad. Sci. USA 109 (2012) 19557, "activated drying in hydrophobic
# nanopores"; Lefevre, Saugey, Barrat, Bocquet, Charlaix, Gobin & Vigier, J. Chem. Phys. 120 (2004) 4927): the barrier
# grows with the pressure's excess over the cavity's emptying pressure b, E = v* (p - b) to first order (v* the
# activation volume), so the cavity empties at the rate nu exp(-(p - b) / D), D = k_B T / v*. Taken deterministically
# (the cavity empties when its hazard, the rate's integral since it filled, reaches 1): held at a pressure, the
# emptying front moves by D per e-fold of time (logarithmic creep), and the loops widen with the rate. Filling stays
# the athermal Laplace-Washburn entry. The hazards share one clock: with G(t) = int nu exp(-(p - P) / D) dt (P a
# reference pressure), a cavity filled at t_j empties when G(t) >= G(t_j) + exp((P - b_j) / D); the reference is
# moved (the keys rescaled, which keeps their order) whenever the pressure strays 6 D from it.


@njit(cache=True)
def _g_step(p0, p1, dt, P, D, nu):
    """nu int exp(-(p - P) / D) over one sample, p linear from p0 to p1."""
    x = (p1 - p0) / D
    e0 = math.exp(-(p0 - P) / D)
    if abs(x) < 1e-8:
        return nu * dt * e0 * (1.0 - 0.5 * x)
    return nu * dt * e0 * (1.0 - math.exp(-x)) / x


@njit(cache=True)
def _activated_run(path, dt, D, nu, age, p, S, filled, nb, a, b, vol, hk, hv, ek, ev):
    nin = _frontier(filled, nb, a, hk, hv)
    P = p
    G = 0.0
    nex = 0
    for j in range(filled.shape[0]):
        if filled[j]:
            nex = _hpush(ek, ev, nex, math.exp((P - b[j]) / D) - nu * age, j)
    out = np.empty(path.shape[0], np.int64)
    for t in range(path.shape[0]):
        pn = path[t]
        if t > 0:
            G += _g_step(p, pn, dt, P, D, nu)
        while nex > 0 and ek[0] <= G:
            _, j, nex = _hpop(ek, ev, nex)
            if filled[j]:
                nin = _empty(j, filled, nb, a, hk, hv, nin)
                S -= vol[j]
        while True:
            nin = _top_in(hk, hv, nin, filled, nb)
            if nin == 0 or hk[0] > pn:
                break
            _, val, nin = _hpop(hk, hv, nin)
            j = val // N_SIDES
            nin = _fill(j, filled, nb, a, hk, hv, nin)
            S += vol[j]
            nex = _hpush(ek, ev, nex, G + math.exp((P - b[j]) / D), j)
        p = pn
        if abs(p - P) > 6.0 * D:
            scale = math.exp((p - P) / D)
            for i in range(nex):
                ek[i] = (ek[i] - G) * scale
            G = 0.0
            P = p
        out[t] = S
    return out, p, S


def activated_cell(foam, state, path, dt, D, nu, age):
    """The cell along the pressures ``path`` (one a sample of dt s; the first the state's own pressure) with thermally
    activated emptying (D the pressure per e-fold of the rate, nu the attempt rate in 1/s), the cell having rested at
    the state for ``age`` s before: the filled share after each sample and the final filled state."""
    filled = state[0].copy()
    hk, hv, ek, ev = _buffers(len(filled))
    out, p, S = _activated_run(np.asarray(path, float), float(dt), float(D), float(nu), float(age), float(state[1]),
                               int(state[2]), filled, foam["nb"], foam["a"], foam["b"], foam["vol"], hk, hv, ek, ev)
    return out / foam["V"], (filled, float(p), int(S))


# ---- drift: a pallet truck on the floor slab ----
#
# The cell's base and the reading's stand sit on the laboratory's floor slab at two points a little apart. A loaded
# pallet truck rolled across the floor bends the slab: a plate on a Winkler foundation (Hertz, Wied. Ann. 22 (1884)
# 449, "ueber das Gleichgewicht schwimmender elastischer Platten"; Westergaard's interior load on a pavement), its
# deflection under a point load P at the distance r w(r) = -P l^2 / (2 pi D) kei(r / l), l = (D / k)^(1/4) the
# radius of relative stiffness (kei the Kelvin function; w(0) = P / (8 sqrt(k D))). The reading shifts by the
# difference of the deflections under the base and the stand (the stand's arm reads the cell against the floor).


def slab_deflection(r, ell):
    """The slab's deflection at the distance r from a point load, over its value under the load (Hertz's floating
    plate: -kei(r / l) / (pi / 4))."""
    return -kei(np.asarray(r, float) / ell) / (math.pi / 4.0)


def truck_position(t, t0, x0, x1, speed, x_stop, dwell):
    """The truck's position along its path (x from x0 to x1 at a constant speed, with a stop of ``dwell`` s at x_stop
    on the way), and whether it is on the floor near the rig (t0 ... the time it reaches x1)."""
    t = np.asarray(t, float)
    d = np.sign(x1 - x0)
    t_stop = t0 + abs(x_stop - x0) / speed
    t_go = t_stop + dwell
    t_end = t_go + abs(x1 - x_stop) / speed
    x = np.where(t < t_stop, x0 + d * speed * (t - t0), np.where(t < t_go, x_stop, x_stop + d * speed * (t - t_go)))
    return x, (t >= t0) & (t <= t_end)


def truck_offset(t, passes, sep, ell):
    """The reading's shift as pallet trucks pass: for each pass (t0, x0, x1, speed, x_stop, dwell, y, axles) the
    difference of the slab's deflections under the base (at the origin) and the stand (at (sep, 0)) summed over the
    truck's axles (axles: (distance behind the front along the path, the share of the weight)); the truck on the path
    y from x0 to x1 (in units of l, far enough out that it arrives and leaves unfelt)."""
    t = np.asarray(t, float)
    out = np.zeros(len(t))
    for t0, x0, x1, speed, x_stop, dwell, y, axles in passes:
        x, on = truck_position(t, t0, x0, x1, speed, x_stop, dwell)
        d = np.sign(x1 - x0)
        for back, share in axles:
            xa = x - d * back
            wb = slab_deflection(np.hypot(xa, y), ell)
            ws = slab_deflection(np.hypot(xa - sep, y), ell)
            out += np.where(on, share * (wb - ws), 0.0)
    return out


# ---- asymmetry: a draw-wire sensor mounted off the rocker tip's line ----
#
# The rocker's tip is read by a draw-wire (string-potentiometer) sensor whose wire leaves its housing off the tip's
# line of travel: the wire's angle to the line is phi0 at rest, so its length is the straight distance from the exit
# to the tip, L = sqrt((L0 cos phi0 + s)^2 + (L0 sin phi0)^2) (s the travel): a hyperbola, steeper on the side where
# the tip moves away along the wire.


def draw_wire_length(u, phi0, stroke):
    """The wire's length over its length at rest, the tip at u times the stroke (over the rest length) along its
    line."""
    u = np.asarray(u, float)
    return np.sqrt((math.cos(phi0) + stroke * u) ** 2 + math.sin(phi0) ** 2)


def draw_wire_reading(u, phi0, stroke):
    """The reading over its slope at rest (slope 1 at u = 0): (L / L0 - 1) / (stroke cos phi0)."""
    return (draw_wire_length(u, phi0, stroke) - 1.0) / (stroke * math.cos(phi0))


# ---- saturation: an astigmatic focus-error sensor watching the rocker tip ----
#
# The tip carries a mirror watched by an optical pickup's focus sensor (an astigmatic lens before a quadrant
# photodiode turned 45 degrees to the astigmatism's axes: Bricot, Lehureau, Puech & Le Carvennec, IEEE Trans. Consum.
# Electron. CE-22 (1976) 304). The returning Gaussian beam has its two line foci a distance 2 s apart; at a defocus z
# its spot's squared widths are w0^2 (1 + ((z + s) / z_R)^2) and w0^2 (1 + ((z - s) / z_R)^2). The focus error
# (A + C - B - D) / (A + B + C + D) of an elliptical Gaussian spot on a quadrant detector at 45 degrees is (2 / pi)
# asin(rho), rho = (wx^2 - wy^2) / (wx^2 + wy^2) (Sheppard's formula for the quadrant probabilities of a correlated
# normal pair), here rho = 2 z s / (z_R^2 + z^2 + s^2): the S-curve, linear about focus, saturating toward its peaks at
# z = +-sqrt(z_R^2 + s^2).


def focus_error(z, s):
    """The focus-error signal at the defocus z (over z_R) for line foci 2 s apart (over z_R)."""
    z = np.asarray(z, float)
    return (2.0 / math.pi) * np.arcsin(2.0 * z * s / (1.0 + z * z + s * s))


def focus_reading(u, z0, s):
    """The reading over its slope at focus (slope 1 at u = 0), the tip at u times z0 (the defocus at the stroke's
    end, over z_R)."""
    slope = (2.0 / math.pi) * 2.0 * s / (1.0 + s * s)
    return focus_error(z0 * np.asarray(u, float), s) / (slope * z0)


# ---- delay: the valve's ports reach the cells through long water lines (Korteweg's wave speed) ----
#
# The servo valve sits on the power unit, L away, and its port pressures reach the cells as waves in the water-filled
# steel lines, at Korteweg's speed c = sqrt((K / rho) / (1 + K D / (E e))) (Korteweg, Ann. Phys. Chem. 5 (1878) 525;
# K, rho the water's bulk modulus and density, D, e, E the tube's bore, wall and modulus). The valve's outlets match the
# lines' impedance and the cells' compliance is negligible against the lines' (their ends are closed): the wave
# reflected at a cell doubles the arriving one and is absorbed at the valve, so each cell's pressure is the port's
# pressure L / c earlier (a pure dead time).

WATER_K = 2.2e9
WATER_RHO = 998.0
STEEL_E = 200e9


def korteweg_speed(D_over_e, K=WATER_K, rho=WATER_RHO, E=STEEL_E):
    return math.sqrt((K / rho) / (1.0 + K * D_over_e / E))


# ---- out of vocabulary: an ADC with a data bit stuck high ----


def stuck_bit_reading(y, lo, hi, bits, k):
    """The reading through an ADC of ``bits`` bits spanning lo ... hi whose data bit k is stuck at 1 (a cracked trace
    on its parallel bus held high): the code rounded and clipped, bit k forced, scaled back."""
    n = 2 ** bits - 1
    code = np.clip(np.rint((np.asarray(y, float) - lo) / (hi - lo) * n), 0, n).astype(np.int64)
    return lo + (code | (1 << k)) * (hi - lo) / n


# ---- histories before a record (initial state) ----


def leak_test(p_c, p_test, n_ramp=40, n_hold=20):
    """A cell's pressure through the leak test: both ports raised together from the preload p_c to p_test, held while
    the pressure's decay is watched, and lowered back to p_c."""
    up = np.linspace(p_c, p_test, n_ramp + 1)
    return np.r_[up, np.full(n_hold, p_test), up[::-1]]


def bleeding_routine(u_bleed, n_pulses, n_per=20, n_hold=10):
    """The installer's bleeding of the lines: the valve pulsed to +u_bleed and -u_bleed in turn (n_pulses, starting
    positive), each pulse ramped, held and released to 0."""
    pts = [0.0]
    for i in range(n_pulses):
        s = u_bleed if i % 2 == 0 else -u_bleed
        ramp = np.linspace(0.0, s, n_per + 1)[1:]
        pts += list(ramp) + [s] * n_hold + list(ramp[::-1][1:]) + [0.0]
    return np.array(pts)
