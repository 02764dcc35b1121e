"""Mechanisms of the HOLDOUT48 set (``cases_holdout48.py``), each written from its law; the signals are in
:mod:`.signals48`.

Nothing here imports hystcomp (the one relaxation exact per interval, :func:`relax_linear`, is imported from
:mod:`.mechanisms47`, not copied). Every mechanism takes the coils' fields that the current amplifier sets from the
clean drive, or the element's state or travel, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the material constants quoted (they are typical values as remembered, not a datasheet's). The laws
do not rest on them: each is checked in tests/test_realistic_holdout48.py against an independent solution (the
element's equilibrium and the regions' switching rules written out there, with brentq for the springs; Radau
(solve_ivp) of the twin boundaries' kinetics, of the elastomer's relaxation and of the warm-up; closed forms; direct
sums and convolutions).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri

from .mechanisms47 import relax_linear

# ---- the rate-independent core: a magnetic shape-memory (Ni-Mn-Ga) actuator ----
#
# A magnetic shape-memory (MSM) alloy (Ullakko, O'Handley et al., Appl. Phys. Lett. 69 (1996) 1966, as remembered): a
# single crystal of Ni-Mn-Ga in its five-layered (10M) martensite, tetragonal with c/a about 0.94, trained so that it
# holds two twin variants only, one with its short c axis along the element's length (x) and one across it (y). Its
# length along x is L_0 (1 + eps_0 xi) to first order, L_0 the length all in the first variant, eps_0 = 1 - c/a (0.056
# ... 0.062) and xi the share of the second (the element's strain up to about 6 %: Murray et al., Appl. Phys. Lett. 77
# (2000) 886, as remembered). The variants' easy axis of magnetisation is their c axis, the anisotropy uniaxial, K_u
# (1.6 ... 1.9e5 J/m^3) and the saturation mu0 M_s = J_s (0.58 ... 0.64 T); the anisotropy field H_a = 2 K_u / J_s.
#
# A field H along y magnetises the second variant along its easy axis (its energy -J_s H) and rotates the first's
# magnetisation toward it (-J_s H^2 / (2 H_a) while H < H_a, K_u - J_s H above); the difference per volume, J_s H (1 - H
# / (2 H_a)) rising to K_u at H_a, drives the twin boundaries: per unit strain the magnetic stress
#     sigma_m(H) = J_s h (1 - h / (2 H_a)) / eps_0,   h = min(|H|, H_a)
# (O'Handley, J. Appl. Phys. 83 (1998) 3263; Likhachev & Ullakko, Phys. Lett. A 275 (2000) 142; as remembered), even
# in H: a field along x drives them back the same way, toward the first variant. The element's demagnetising field is
# left out (the yokes close the flux; the element fills their gaps: a choice).
#
# The actuator (a design chosen, not quoted): the element (its section 2 x 3 mm, L_0 15 ... 20 mm) is bonded at one end
# to the frame and at the other to a push rod held at the element's mid-stroke by a pair of centring springs (their
# stiffness k; per unit of xi a stress kappa = k L_0 eps_0 / A on the element, 1.3 ... 1.6 MPa), so that the springs'
# stress on it is kappa (xi - 1/2), pushing back from either side of the middle (compressive above it, tensile below).
# Two coils, each in its own yoke, set the fields: coil Y's across the element (lengthening it) and coil X's along it
# (shortening it); a current amplifier feeds them through a pair of steering diodes, coil Y for a positive drive and
# coil X for a negative one, H = q H_a v / amp (q 0.08 ... 0.10 at the full drive: the low field at which the type II
# twins of such crystals move, tens of mT), on the unipolar records coil Y alone (H = q H_a v / top). So the drive sets
# the stress u(v) = sign(v) sigma_m(q H_a |v| / amp), odd and nearly linear in v at the rated field.
#
# The twin boundaries move against a friction of their own (the twinning stress) and their pinning by the crystal's
# defects: the element is N_REG = 1000 regions in series along its length, region i swept from the first variant into
# the second by its boundary when the stress on it, s = u - kappa (xi - 1/2) - (the local internal stress b_i), exceeds
# its twinning stress tau_i, and back when it falls below -tau_i: a rectangular hysteron in the common stress s with
# the thresholds alpha_i = b_i + tau_i (up) and beta_i = b_i - tau_i (down), tau_i log-normal about tau_m (0.08 ...
# 0.12 MPa: the type II twins' low twinning stress, e.g. Straka et al. on 10M crystals, as remembered; spread 0.15 ...
# 0.3), b_i normal (spread 0.06 ... 0.10 MPa), drawn on a Latin hypercube (each variable's n quantile strata taken once,
# paired at random). Preisach models have been fitted to MSM actuators' loops before (e.g. by Riccardi, Holz, Janocha
# and co-workers, as remembered); this one is written from the regions' mechanics. The springs shear the ensemble: a
# region switching lengthens the element, the springs push back harder, and the stress s is held at the region's
# threshold while it switches part by part (the region's boundary stopping inside it: xi_i in [0, 1]). The equilibrium
# at every drive: every region with xi_i < 1 has alpha_i >= s, every region with xi_i > 0 has beta_i <= s, and s = u -
# F(xi), F(xi) = kappa (xi - 1/2) (plus what the effects add: two rates, stops), xi the regions' mean. Rate
# independent, with return-point memory (a Preisach model behind a monotone feedback).
#
# The reading: a laser Doppler vibrometer on the push rod's end with its displacement decoder (um), zeroed at the
# record's first sample: y = 1000 L_0 eps_0 (xi - xi(0)) (L_0 in mm).
#
# The rest state: the controller runs a centring routine at power-down (a decaying alternating current through the two
# coils in turn), which leaves the element in the Preisach demagnetised state about the springs' middle: every region
# in the second variant whose internal stress b_i lies below the stress s it then feels, and in the first above it, s =
# -F(xi) self-consistent (one region part-switched at s = b_i); the state is set so, not run, and tested in the test
# against a slow decaying alternating drive. Every record but the initial-state case's starts there, at 0 V and 0 A.

N_REG = 1000


def regions(seed, n, tau_m, s_tau, s_b):
    """The regions' up and down thresholds alpha = b + tau, beta = b - tau (MPa) and weights (1 / n each): tau
    log-normal about tau_m (spread s_tau), b normal (spread s_b), on a Latin hypercube (each variable's n quantile
    strata taken once, at a uniform point inside, the two paired by random permutations drawn from the seed)."""
    rng = np.random.default_rng(seed)
    u1 = (rng.permutation(n) + rng.uniform(size=n)) / n
    u2 = (rng.permutation(n) + rng.uniform(size=n)) / n
    tau = tau_m * np.exp(s_tau * ndtri(u1))
    b = s_b * ndtri(u2)
    return b + tau, b - tau, np.full(n, 1.0 / n)


_R_CACHE = {}


def element_regions(core):
    """The element's regions: (alpha, beta, w, ia, ib), ia by rising alpha, ib by falling beta (cached)."""
    key = (core["rseed"], core.get("n", N_REG), core["tau_m"], core["s_tau"], core["s_b"])
    if key not in _R_CACHE:
        al, be, w = regions(*key)
        _R_CACHE[key] = (al, be, w, np.argsort(al, kind="stable"), np.argsort(-be, kind="stable"))
    return _R_CACHE[key]


def magnetic_stress(H, Js, K, eps0):
    """The magnetic stress on the twin boundaries (MPa) at the field H (A/m): J_s h (1 - h / (2 H_a)) / eps_0, h =
    min(|H|, H_a), H_a = 2 K / J_s (J_s in T, K in J/m^3)."""
    Ha = 2.0 * K / Js
    h = np.minimum(np.abs(np.asarray(H, float)), Ha)
    return Js * h * (1.0 - h / (2.0 * Ha)) / eps0 / 1e6


def anisotropy_field(core):
    """H_a = 2 K_u / J_s (A/m)."""
    return 2.0 * core["K"] / core["Js"]


def coil_field(core, v, gain=1.0):
    """The active coil's field (A/m) for the drive v: q H_a v / amp (bipolar; the sign says which coil) or q H_a v /
    top (unipolar, coil Y alone), times `gain`."""
    return gain * core["q"] * anisotropy_field(core) * np.asarray(v, float) / core["top" if core["unipolar"] else "amp"]


def drive_stress(core, v, gain=1.0, Js=None, K=None):
    """The stress the coils set, u = sign(H) sigma_m(H) (MPa), H the coil field for the drive v (default the core's J_s
    and K; the warm-up gives them per sample)."""
    H = coil_field(core, v, gain)
    Js = core["Js"] if Js is None else Js
    K = core["K"] if K is None else K
    return np.sign(H) * magnetic_stress(H, Js, K, core["eps0"])


# the springs: F(x) = c + k x + sum_j a_j max(x - p_j, 0), increasing in x (the element's mean strain share xi)

def springs(core, ratio=1.0, stops=None):
    """The centring springs' stress on the element as (c, k, p, a): kappa (xi - 1/2); with `ratio` != 1 the spring on
    the lengthening side `ratio` times as stiff (kappa (ratio - 1) more above the middle); with stops = (lo, hi, K_s)
    end stops of stiffness K_s (MPa per unit xi) met at xi = lo and xi = hi."""
    kap = core["kappa"]
    c, k, p, a = -kap / 2, kap, [], []
    if ratio != 1.0:
        p.append(0.5)
        a.append(kap * (ratio - 1.0))
    if stops is not None:
        lo, hi, Ks = stops
        # below lo: K_s (xi - lo), as K_s xi - K_s lo and a hinge of -K_s at lo; above hi: a hinge of +K_s
        c -= Ks * lo
        k += Ks
        p += [lo, hi]
        a += [-Ks, Ks]
    o = np.argsort(p, kind="stable")
    return float(c), float(k), np.asarray(p, float)[o], np.asarray(a, float)[o]


@njit(cache=True)
def _fval(x, c, k, p, a):
    """F(x) = c + k x + sum_j a_j max(x - p_j, 0)."""
    v = c + k * x
    for j in range(p.shape[0]):
        if x > p[j]:
            v += a[j] * (x - p[j])
    return v


@njit(cache=True)
def _fslope(x, k, p, a):
    """F's slope at x (from the right)."""
    v = k
    for j in range(p.shape[0]):
        if x >= p[j]:
            v += a[j]
    return v


@njit(cache=True)
def _finv(T, c, k, p, a):
    """The x with F(x) = T (F increasing, piecewise linear; p sorted)."""
    slope = k
    off = c
    for j in range(p.shape[0]):
        if T <= off + slope * p[j]:
            return (T - off) / slope
        slope += a[j]
        off -= a[j] * p[j]
    return (T - off) / slope


@njit(cache=True)
def _step(u, c, k, p, a, xi, st, al, be, w, ia, ib, als, nbes):
    """One step of the element to the stress u with the springs F(x) = c + k x + hinges, from the state st = [xi mean,
    s] and the regions' shares xi (changed in place): the regions whose thresholds s passes switch, the one whose
    switching holds s at its threshold switches in part. als are the alphas in the order ia (rising), nbes minus the
    betas in the order ib (-beta rising)."""
    xb, s0 = st[0], st[1]
    s = u - _fval(xb, c, k, p, a)
    n = al.shape[0]
    if s > s0:
        j = np.searchsorted(als, s0 - 1e-12)
        while j < n:
            r = ia[j]
            j += 1
            if xi[r] >= 1.0:
                continue
            if s <= al[r]:
                break
            xn = _finv(u - al[r], c, k, p, a)
            cap = xb + w[r] * (1.0 - xi[r])
            if xn <= cap:
                xi[r] = min(xi[r] + (xn - xb) / w[r], 1.0)
                xb = xn
                s = al[r]
                break
            xi[r] = 1.0
            xb = cap
            s = u - _fval(xb, c, k, p, a)
    elif s < s0:
        j = np.searchsorted(nbes, -(s0 + 1e-12))
        while j < n:
            r = ib[j]
            j += 1
            if xi[r] <= 0.0:
                continue
            if s >= be[r]:
                break
            xn = _finv(u - be[r], c, k, p, a)
            cap = xb - w[r] * xi[r]
            if xn >= cap:
                xi[r] = max(xi[r] - (xb - xn) / w[r], 0.0)
                xb = xn
                s = be[r]
                break
            xi[r] = 0.0
            xb = cap
            s = u - _fval(xb, c, k, p, a)
    st[0] = xb
    st[1] = s


@njit(cache=True)
def _run(u, c, k, p, a, eta, kj, tj, q, dt, xi, st, al, be, w, ia, ib, als, nbes):
    """The element's mean share xi along the stresses u (one step each). The springs F(x) = c + k x + hinges; with dt >
    0 a dashpot eta (MPa s per unit xi: the stress eta dxi/dt, implicit Euler over the steps dt) and relaxing spring
    parts kj (MPa per unit xi) at the times tj, their stress kj (xi - q_j) with q_j relaxing toward xi, exact per step
    for xi linear over it (q changed in place)."""
    N = u.shape[0]
    out = np.empty(N)
    m = kj.shape[0]
    A = np.empty(m)
    B = np.empty(m)
    for i in range(N):
        cc = c
        kk = k
        if eta > 0.0:
            cc -= eta * st[0] / dt
            kk += eta / dt
        for j in range(m):
            r = tj[j] / dt
            E = math.exp(-dt / tj[j])
            A[j] = 1.0 - r * (1.0 - E)
            B[j] = st[0] * (r * (1.0 - E) - E) + E * q[j]
            kk += kj[j] * (1.0 - A[j])
            cc -= kj[j] * B[j]
        _step(u[i], cc, kk, p, a, xi, st, al, be, w, ia, ib, als, nbes)
        for j in range(m):
            q[j] = A[j] * st[0] + B[j]
        out[i] = st[0]
    return out


def rest_state(al, be, w, F, u0=0.0):
    """The Preisach demagnetised state at the stress u0 with the springs F: every region with b = (alpha + beta) / 2
    below s switched, the rest not, s = u0 - F(xi) self-consistent (the region at s = b part-switched). Returns (xi,
    [xi mean, s])."""
    c, k, p, a = F
    b = 0.5 * (al + be)
    o = np.argsort(b, kind="stable")
    xi = np.zeros(len(b))
    x = 0.0
    s = u0 - _fval(x, c, k, p, a)
    for r in o:
        if s <= b[r]:
            break
        xn = _finv(u0 - b[r], c, k, p, a)
        if xn <= x + w[r]:
            xi[r] = (xn - x) / w[r]
            x, s = xn, b[r]
            break
        xi[r] = 1.0
        x += w[r]
        s = u0 - _fval(x, c, k, p, a)
    return xi, np.array([x, s])


class Element:
    """The element's regions and their state (xi; st = [xi mean, s]); by default in the demagnetised state with the
    springs F (default the core's centring springs)."""

    def __init__(self, core, F=None, state="demagnetised"):
        self.al, self.be, self.w, self.ia, self.ib = element_regions(core)
        self.als = np.ascontiguousarray(self.al[self.ia])
        self.nbes = np.ascontiguousarray(-self.be[self.ib])
        self.F = springs(core) if F is None else F
        if state == "demagnetised":
            self.xi, self.st = rest_state(self.al, self.be, self.w, self.F)
        elif state == "short":
            # every region in the first variant (the supplier's reset), s below every threshold
            self.xi = np.zeros(len(self.al))
            self.st = np.array([0.0, float(self.be.min()) - 1.0])
        else:
            raise ValueError(state)

    def copy(self):
        c = object.__new__(Element)
        c.__dict__.update({k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in self.__dict__.items()})
        return c

    def run(self, u, F=None, eta=0.0, kj=(), tj=(), q=None, dt=0.0):
        """The mean share xi along the stresses u (MPa), the state carried on; F the springs (default the element's),
        eta a dashpot and kj, tj relaxing spring parts over steps dt (see :func:`_run`; q their states, default xi's
        now, changed in place)."""
        c, k, p, a = self.F if F is None else F
        kj = np.ascontiguousarray(kj, dtype=float)
        tj = np.ascontiguousarray(tj, dtype=float)
        if (eta > 0.0 or len(kj)) and not dt > 0.0:
            raise ValueError("a dashpot or a relaxing spring needs the step dt")
        if q is None:
            q = np.full(len(kj), self.st[0])
        return _run(np.ascontiguousarray(u, dtype=float), float(c), float(k), np.ascontiguousarray(p, dtype=float),
                    np.ascontiguousarray(a, dtype=float), float(eta), kj, tj, q, float(dt) if dt > 0 else 1.0,
                    self.xi, self.st, self.al, self.be, self.w, self.ia, self.ib, self.als, self.nbes)


def travel(core, x, x0):
    """The vibrometer's reading (um) of the mean share x, zeroed at x0: 1000 L_0 eps_0 (x - x0)."""
    return 1e3 * core["L0"] * core["eps0"] * (np.asarray(x, float) - x0)


def core_share(core, v, element=None, gain=1.0):
    """The element's mean share xi along the drive v (rate independent) from `element` (default demagnetised; a copy
    is run)."""
    el = Element(core) if element is None else element.copy()
    return el.run(drive_stress(core, v, gain))


def core_reading(core, v, element=None, gain=1.0):
    """The vibrometer's reading (um) of the rate-independent actuator along the drive v, zeroed at its start."""
    el = Element(core) if element is None else element
    x = core_share(core, v, el, gain)
    return travel(core, x, el.st[0])


# ---- creep: elastomer centring springs relaxing ----
#
# The creep record's actuator has its centring springs made as polyurethane bushes (an elastomer in compression, a
# design chosen). The elastomer's stress relaxes: its modulus a Prony series E(t) = E_inf + sum_j E_j e^(-t / tau_j)
# (tau_j 0.5, 5 and 50 s; the relaxing share sum E_j / E(0) 0.2 ... 0.3: a soft polyurethane's over those decades, as
# remembered; Boltzmann's superposition, Ferry's Viscoelastic Properties of Polymers), so the springs' stress on the
# element is kappa_inf (xi - 1/2) + sum_j kappa_j (xi - q_j), dq_j/dt = (xi - q_j) / tau_j (the springs' short-time
# stiffness kappa = kappa_inf + sum_j kappa_j). After a move the springs' push relaxes and the region at its threshold
# goes on switching: the element goes on the way it went, fast at first, slowly later. Each q_j is exact per interval
# for xi linear over it, which makes the springs' stress at the step's end linear in xi (solved with the element at
# once: :func:`_run`); checked in the test against Radau and against halving the step.

CREEP_TAUS = np.array([0.5, 5.0, 50.0])


# ---- rate dependence: the twin boundaries' mobility ----
#
# A twin boundary does not sweep its region at once: above its threshold it moves at a speed that rises with the excess
# stress (the kinetic relation Faran & Shilo measured on Ni-Mn-Ga, a threshold then a rise, as remembered; here linear
# above the threshold): dxi_i/dt = (s - alpha_i) / eta_m where s > alpha_i (xi_i < 1), (s - beta_i) / eta_m where s <
# beta_i (xi_i > 0), 0 between, s = u - F(xi) at every instant (the springs' stress). eta_m (MPa s) is chosen so that a
# region is swept in 10 ... 30 ms at 0.1 MPa above its threshold (eta_m 1e-3 ... 3e-3 MPa s: a slow crystal; chosen,
# not quoted). Solved by implicit Euler on SUB_MOB steps a sample (each step's s found by a safeguarded Newton on the
# monotone, piecewise-linear balance); first order: checked in the test against Radau and its error halving with the
# step. With eta_m -> 0 it is the rate-independent element (checked).

SUB_MOB = 6


@njit(cache=True)
def _mobile(u, h, eta, c, k, p, a, xi, st, al, be, w):
    """The mean share along the stresses u (one implicit Euler step of h each) with the regions' mobility 1 / eta;
    xi and st = [xi mean, s] changed in place."""
    n = al.shape[0]
    out = np.empty(u.shape[0])
    g = h / eta
    for i in range(u.shape[0]):
        ui = u[i]
        lo = ui - _fval(1.0, c, k, p, a) - 1e-9
        hi = ui - _fval(0.0, c, k, p, a) + 1e-9
        s = ui - _fval(st[0], c, k, p, a)
        X = st[0]
        for _ in range(200):
            X = 0.0
            dX = 0.0
            for r in range(n):
                d = 0.0
                if s > al[r]:
                    d = g * (s - al[r])
                elif s < be[r]:
                    d = g * (s - be[r])
                xn = xi[r] + d
                if xn >= 1.0:
                    xn = 1.0
                elif xn <= 0.0:
                    xn = 0.0
                elif d != 0.0:
                    dX += w[r] * g
                X += w[r] * xn
            G = s - ui + _fval(X, c, k, p, a)
            if G > 0.0:
                hi = s
            elif G < 0.0:
                lo = s
            if abs(G) <= 1e-14 or hi - lo <= 1e-15:
                break
            sn = s - G / (1.0 + _fslope(X, k, p, a) * dX)
            if not (lo < sn < hi):
                sn = 0.5 * (lo + hi)
            s = sn
        X = 0.0
        for r in range(n):
            d = 0.0
            if s > al[r]:
                d = g * (s - al[r])
            elif s < be[r]:
                d = g * (s - be[r])
            xn = min(max(xi[r] + d, 0.0), 1.0)
            xi[r] = xn
            X += w[r] * xn
        st[0] = X
        st[1] = s
        out[i] = X
    return out


def mobile_share(el, u, h, eta_m):
    """The element `el` (changed) along the stresses u on steps h with the mobility 1 / eta_m (implicit Euler)."""
    c, k, p, a = el.F
    return _mobile(np.ascontiguousarray(u, dtype=float), float(h), float(eta_m), float(c), float(k),
                   np.ascontiguousarray(p, dtype=float), np.ascontiguousarray(a, dtype=float), el.xi, el.st, el.al,
                   el.be, el.w)


# ---- drift: the element warmed by its coil ----
#
# The drift record's actuator is started cold. Coil Y's Joule heat, P = P_full (i / i_full)^2, warms the element, its
# yoke and its housing through a lumped heat capacity with a loss to the room (Newton's cooling, time constant tau_th 60
# ... 120 s; at the full current held the rise would settle at dT_full 45 ... 60 K):
#     tau_th dT/dt = dT_full (i / i_full)^2 - T,
# T the rise over the room (at 22 C, 295 K; the alloy's martensite holds to its A_s about 45 C in these records: the
# rise stays under 20 K, checked). The alloy's saturation falls toward its Curie point T_c (365 ... 375 K) as J_s(T) =
# J_s0 ((T_c - T) / (T_c - T_0))^0.36 (the critical law's exponent, used away from T_c as a fit, as remembered), and
# its anisotropy with it as K(T) = K_0 (J_s(T) / J_s0)^3 (Callen & Callen's l(l+1)/2 law for a uniaxial anisotropy, as
# remembered): the magnetic stress at a given current falls as the element warms (a gain drifting down: 5 ... 7 % by
# the end). And the reading's zero moves: the element and its push rod expand toward the vibrometer (alpha_e 12 ...
# 16e-6 / K over L_0 + 10 mm) while the aluminium housing, clamped to the bench at its front flange, carries the
# element's base back (23e-6 / K over the L_h 80 ... 110 mm from the flange to the base): the reading falls by about
# 1.4 ... 2.2 um per kelvin. The twinning stress's own change with temperature is left out (a choice). T is exact per
# interval for the power linear between samples (:func:`warm_up`; checked against Radau in the test).

CURIE_EXP = 0.36
T_ROOM = 295.0
ALPHA_AL = 23e-6          # the aluminium housing's expansion coefficient (1/K), as remembered


def warm_up(t, heat, tau_th):
    """The rise T (K) over the times t, from 0, relaxing toward `heat` (dT_full (i / i_full)^2, linear between the
    samples) at tau_th: exact per interval (:func:`.mechanisms47.relax_linear`)."""
    return relax_linear(t, heat, tau_th, 0.0)[:, 0]


def expansion(T, alpha_e, L0, L_h):
    """The reading's zero moving (um) as the element and its push rod (alpha_e over L0 + 10 mm: the rod's end toward
    the vibrometer's positive) and the housing (aluminium over the L_h mm from its front flange, clamped to the bench,
    back to the element's base: the base carried away) expand by the rise T (K)."""
    return 1e3 * (alpha_e * (L0 + 10.0) - ALPHA_AL * L_h) * np.asarray(T, float)


def warm_constants(core, T):
    """J_s and K at the rise T over the room (K)."""
    r = ((core["Tc"] - T_ROOM - np.asarray(T, float)) / (core["Tc"] - T_ROOM)) ** CURIE_EXP
    return core["Js"] * r, core["K"] * r ** 3


# ---- asymmetry: the centring springs' halves mismatched ----
#
# The asymmetry record's actuator had the spring on its lengthening side replaced by a stiffer one (ratio 1.8 ... 2.5
# times the other's: a wrong wire gauge): above the middle the springs push back at kappa ratio per unit xi, below it
# at kappa (:func:`springs` with `ratio`). The element lengthens less far than it shortens: a kink at the middle.


# ---- saturation: end stops inside the stroke ----
#
# The saturation record's actuator has its push rod's end stops (hardened steel, K_s 150 ... 250 times the springs'
# kappa) set inside the element's travel (at 0.6 ... 0.75 of the rated drive's excursion from the middle on each side:
# a spacer of the wrong thickness). At a stop the element is blocked: the stop's reaction holds the stress on the
# twin boundaries below the next thresholds, the regions stop switching (they do not go on switching underneath, as a
# clipped reading would say) and the reading flattens at both ends.


# ---- delay: the vibrometer's decoder ----
#
# The delay record's vibrometer decodes the displacement digitally: its samples at the decoder's rate f_d (10.24 kHz)
# through a linear-phase lowpass FIR (N_d taps, 81 ... 121, a Blackman-windowed sinc cut off at f_c 0.8 ... 1.2 kHz, its
# gain 1 at DC), and its analogue output updates to each filtered sample a latency T_lat (1 ... 2 ms: the output's DAC
# and the processor's frame, an order of magnitude as remembered) after it and holds it. The filter's group delay is
# (N_d - 1) / (2 f_d): the reading is the travel (N_d - 1) / (2 f_d) + T_lat late, plus the hold (half a decoder
# period on average), the FIR's passband ripple on the drive's slow content under 1e-3 (checked in the test).

F_DEC = 10240.0


def decoder_fir(n_taps, f_c, f_d=F_DEC):
    """A Blackman-windowed sinc lowpass of n_taps (odd) taps cut off at f_c on the rate f_d, its gain 1 at DC."""
    m = np.arange(n_taps) - (n_taps - 1) / 2
    h = np.sinc(2 * f_c / f_d * m) * np.blackman(n_taps)
    return h / h.sum()


def decoder_output(x_fine, h):
    """The FIR's output at every decoder sample: sum_j h_j x[k - j] (the first samples' history the first value's)."""
    xp = np.r_[np.full(len(h) - 1, x_fine[0]), x_fine]
    return np.convolve(xp, h, mode="valid")


def held_reading(t, t_out, y_out, T_lat, rest):
    """The logged reading at t: the last output whose instant plus T_lat is at or before t (the rest value before)."""
    m = np.searchsorted(t_out + T_lat, np.asarray(t, float) + 1e-12, side="right") - 1
    return np.where(m >= 0, y_out[np.maximum(m, 0)], rest)


# ---- initial state: the element as the supplier reset it ----
#
# The initial-state record's element is a replacement fitted as supplied: the supplier resets MSM elements by
# compressing them to the first variant (every region at xi = 0: the short element), and it was bonded in without the
# centring routine. Released, the centring springs pull the short element toward the middle (a stress kappa / 2 on
# it), its regions switching in order of their up thresholds until the springs' pull balances the next one: it rests
# below the middle (by the twinning stress over kappa), on the rising branch from the short end; the record starts
# there, at 0 V. The first swing of the drive to both ends wipes the history out.

def supplier_element(core):
    """The element reset short by the supplier and released in the actuator at 0 A."""
    el = Element(core, state="short")
    el.run([0.0])
    return el


# ---- two effects: an oil dashpot and the overdriven coils ----
#
# The pair record's actuator has an oil dashpot on its push rod (a damper fitted to calm the mount it carries; a design
# chosen), its stress on the element eta_d dxi/dt (eta_d / kappa 45 ... 70 ms; labelled "rate_dependence": a viscous
# loss that widens the loop with the drive's rate; the push rod's and the mount's inertia left out), solved by implicit
# Euler with the element (:func:`_run`), SUB_DASH steps a sample on the drive's own finer grid; first order: checked in
# the test against its own closed form and the exponential for one region, and on twice as many steps. And its
# amplifier's gain set 1.8 ... 2.2 times its rating (labelled "saturation"): the field reaches 0.14 ... 0.22 H_a, the
# rotation's quadratic term bends the magnetic stress (its slope at the top down by 14 ... 22 %) and, above all, the
# element runs out of regions to switch at the swing's ends (its share within a few hundredths of 0 and 1: the strain's
# limit, 0 ... eps_0).

SUB_DASH = 8


# ---- out of vocabulary: the vibrometer's velocity decoder ----
#
# The out-of-vocabulary record's vibrometer was left on its velocity decoder: the reading is the push rod's speed
# (mm/s), the decoder's averaging over T_a (1 ... 2 ms) the mean speed over it, (y(t) - y(t - T_a)) / T_a. Zero
# whenever the element stands (in every hold, and while the drive moves within the twins' friction band), signed with
# the travel's direction: no map of the core, monotone or not, draws it. The record carries only the drive.

def velocity_reading(core, t, T_a, drive_at, element=None):
    """The velocity decoder's reading (mm/s) at the times t: the travel's mean speed over the last T_a, the core run
    along the drive at the merged times t and t - T_a (rate independent; the drive at rest before 0)."""
    t = np.asarray(t, float)
    tt = np.r_[t - T_a, t]
    o = np.argsort(tt, kind="stable")
    x = np.empty(len(tt))
    x[o] = core_reading(core, drive_at(np.maximum(tt[o], 0.0)), element)
    return (x[len(t):] - x[:len(t)]) / T_a * 1e-3
