"""Mechanisms of the HOLDOUT51 set (``cases_holdout51.py``), each written from its law; the signals are in
:mod:`.signals51`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the voltage the amplifier sets on
the stack (from the clean drive), or the stack's field, polarisation or reading, and returns the response; all are
causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the constants quoted (typical values as remembered, not a datasheet's). The laws do not rest on them:
each is checked in tests/test_realistic_holdout51.py against an independent solution (the clusters' roots by Cardano's
formulas and their wells by the last threshold each crossed, the barrier by numpy's roots of the free energy's
derivative, the switching table by brentq, an explicit decaying dither for the rest state, the Mittag-Leffler series and
asymptotics for the Cole-Cole response, direct sums for the hereditary integrals, solve_ivp for the charging, the
stack's warming and the chiller, brentq for the stops' balance, quad for the gauge's filter, and finer grids).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri

from .mechanisms50 import relax  # y relaxing toward x with a time constant, exact per step

# ---- the rate-independent core: a PMN-PT relaxor stack's polar nanoregions, read through a lever stage ----
#
# The actuator is a multilayer stack of the relaxor 0.9 PMN - 0.1 PT (lead magnesium niobate - lead titanate), 200
# layers of 100 um between interdigitated electrodes (20 mm active, 5 x 5 mm^2), driving a flexure-hinged lever of ratio
# 5 whose tip a capacitive gauge reads (um; the gauge zeroed at the start of every record). Below its dielectric maximum
# (near 40 C) such a relaxor is electrostrictive: no remanent polarisation to speak of, its strain S = Q P^2 (Q = Q_11
# 0.025 m^4 / C^2 as remembered for PMN; Cross, Jang, Newnham, Nomura & Uchino, Ferroelectrics 23 (1980) 187, and
# Uchino's books, as remembered) and a slim loop from its polar nanoregions.
#
# The polarisation (a model written here from the laws of its parts, not quoted):
#
# * Smolenskii's picture of a diffuse transition (as remembered): the composition fluctuates from region to region, so
#   each polar cluster k has its own Curie temperature T_c,k, normal about the mean T_c (spread dT_c 9 ... 11 K). Each
#   cluster is a Landau-Devonshire body along the field (its polar axis taken along the field: a choice; the grains'
#   orientations would only rescale the distributions): free energy per volume g(p) = a_k p^2 / 2 + b p^4 / 4 - E_k p,
#   a_k = (T - T_c,k) / (eps_0 C) (the Curie-Weiss constant C = 1.2e5 K, as remembered for PMN), b = 5.2e8 J m^5 / C^4
#   (a choice: a cluster 50 K below its T_c holds 0.3 C / m^2), E_k = E + E_I,k its local field: the applied field E =
#   U / 100 um plus a random field E_I,k (normal, spread sigma_I 0.68 ... 0.74 MV / m: the quenched charge disorder of
#   the B site, Westphal, Kleemann & Glinchuk, Phys. Rev. Lett. 68 (1992) 847, as remembered). The cluster's p sits in a
#   minimum of g: the outer roots of a p + b p^3 = E_k.
# * Above its T_c (a_k >= 0) a cluster has one minimum and follows it (paraelectric). Below (a_k < 0) it has two wells
#   while |E_k| is below the spinodal field; it crosses the barrier between them by thermal activation, at the rate nu_0
#   exp(-v_k Delta g / k T) (Neel-Arrhenius; v_k the cluster's volume, nu_0 ~ 1e12 / s): over the records' time scales
#   (0.1 ... 10 s) it has crossed once the barrier has fallen to LN_RATE = ln(nu_0 t) = 25 k T and not before (the
#   rate-independent limit: the logarithm's change over the records' two decades of time scales, 4.6 of 25, is left out:
#   a choice). So a cluster whose barrier at zero local field is already under 25 k T is ergodic: it sits in the deeper
#   well (it switches at E_k = 0; the thermal smearing of that step, k T / 2 v_k p_0, under 0.01 MV / m but for the
#   clusters nearest their T_c, whose p_0 is small, is left out); the others are blocked, each a relay of its local
#   field that switches at +-E_sw,k where its barrier falls to 25 k T: in the reduced units x = p / p_0 (p_0 = sqrt(-a /
#   b)) and e = E_k / (-a p_0), the barrier is (a^2 / b) D(e), D(0) = 1/4, D of the spinodal 2 / 3^(3/2) = 0, and E_sw =
#   e_sw (-a p_0) with D(e_sw) = theta = 25 k T b / (v a^2) (a table of e_sw against (4 theta)^(2/3), checked against
#   brentq in the test).
#   The clusters' sizes are log-normal (median 28 ... 32 nm across, log spread 0.3: a choice).
# * 4096 clusters from a scrambled Sobol sequence over the three distributions' quantiles (T_c, the size, E_I; the
#   core's seed scrambles it), filling 0.8 of the ceramic (a choice); the sizes drawn from the volume-weighted
#   distribution (the log-normal with its log median moved up by 3 s^2), so that each cluster carries the same share of
#   the polar volume, w_k = 0.8 / 4096 (no one large cluster's step stands out); the rest of the ceramic adds eps_0
#   (eps_bg - 1) E (eps_bg 1400 ... 1600). P = sum_k w_k p_k + eps_0 (eps_bg - 1) E.
#
# The reading: the lever's tip, 1e6 * 5 * 0.02 Q (P^2 - P(0)^2) um (the lever's ratio with its hinges' compliance taken
# as 5: a choice). Rate independent (every cluster's state is its well, which changes only at its thresholds, and its p
# is a function of its local field in that well), with return-point memory of its turning points (the blocked clusters
# are relays); close to a Prandtl-Ishlinskii model but not one (measured in the test and stated there): the loop is slim
# (the relaxor's), the branch functions are roots of cubics, the strain is the square of the polarisation.
#
# The amplifier (0 ... 200 V) sets U = bias + gain v: the bipolar records' bias 120 V, the unipolar records' 70 V (gain
# 1 V / V), so that the strain, convex in P, and P, concave in E above the bias, make the stroke near linear about the
# bipolar records' bias (measured: a straight line misses the clean core by 13 ... 16 sigma, a PI model by 1.2 ...
# 1.6 RMS).
#
# The rest state: the controller's start-up routine raises the stack to its bias under a decaying dither (a de-ageing
# routine), whose limit leaves every bistable cluster in its deeper well at the bias field (the sign of its local
# field there): the state is set so, not run (checked in the test against an explicit dither of 4000 cycles). Every
# record but the initial-state case's starts there, at 0 V of drive.

KB = 1.380649e-23
EPS0 = 8.8541878128e-12
CURIE = 1.2e5
A0 = 1.0 / (EPS0 * CURIE)
B4 = 5.2e8
LN_RATE = 25.0
T_ROOM = 298.15
N_CLUSTERS = 4096
LAYER = 100e-6
N_LAYERS = 200
AREA = 25e-6
LENGTH = N_LAYERS * LAYER
Q11 = 0.025
LEVER = 5.0
POLAR = 0.8
SIZE_SPREAD = 0.3
E_SPINODAL = 2.0 / 3.0 ** 1.5


def roots_reduced(e):
    """The three real roots (ascending) of x^3 - x - e = 0 for |e| < 2 / 3^(3/2) (trigonometric form): arrays."""
    e = np.asarray(e, float)
    ph = np.arccos(np.clip(e * 1.5 * math.sqrt(3.0), -1.0, 1.0))
    r = 2.0 / math.sqrt(3.0)
    x0 = r * np.cos(ph / 3.0)
    x1 = r * np.cos((ph - 2.0 * math.pi) / 3.0)
    x2 = r * np.cos((ph - 4.0 * math.pi) / 3.0)
    return np.sort(np.stack([x0, x1, x2]), axis=0)


def barrier(e):
    """The reduced barrier D(e) (in a^2 / b) that a cluster in its '-' well must cross at the reduced field e in [0,
    2 / 3^(3/2)]: G(saddle) - G(well), G(x) = x^4 / 4 - x^2 / 2 - e x."""
    e = np.asarray(e, float)
    x = roots_reduced(e)

    def G(u):
        return u ** 4 / 4.0 - u * u / 2.0 - e * u
    return G(x[1]) - G(x[0])


def _switch_table(n=4001):
    """e_sw on a grid of z = (4 theta)^(2/3) in [0, 1]: D(e_sw) = theta, by bisection (80 halvings, to below 1e-16)."""
    z = np.linspace(0.0, 1.0, n)
    theta = 0.25 * z ** 1.5
    lo, hi = np.zeros(n), np.full(n, E_SPINODAL)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        big = barrier(mid) > theta
        lo = np.where(big, mid, lo)
        hi = np.where(big, hi, mid)
    e = 0.5 * (lo + hi)
    e[0], e[-1] = E_SPINODAL, 0.0
    return z, e


SW_Z, SW_E = _switch_table()


def e_switch(theta):
    """The reduced switching field e_sw at which the barrier falls to theta (in a^2 / b): linear interpolation of the
    table in z = (4 theta)^(2/3); 0 for theta >= 1/4 (an ergodic cluster)."""
    z = np.clip(4.0 * np.asarray(theta, float), 0.0, 1.0) ** (2.0 / 3.0)
    return np.interp(z, SW_Z, SW_E)


_CLUSTERS = {}


def clusters(core):
    """The core's clusters: (a at T_ROOM (J m / C^2), b, volume (m^3), random field (V / m), weight, switching field
    (V / m; 0 for the ergodic and the paraelectric ones)), from a scrambled Sobol sequence seeded by core['rseed']."""
    key = (core["rseed"], core["Tc"], core["dTc"], core["d50"], core["sI"])
    if key not in _CLUSTERS:
        from scipy.stats import qmc
        u = qmc.Sobol(d=3, scramble=True, seed=core["rseed"]).random(N_CLUSTERS)
        u = np.clip(u, 1e-12, 1.0 - 1e-12)
        tc = core["Tc"] + core["dTc"] * ndtri(u[:, 0])
        # sizes drawn from the volume-weighted distribution (log-normal, its log median moved up by 3 s^2), every
        # cluster then carrying an equal share of the polar volume
        vol = (core["d50"] * 1e-9 * np.exp(SIZE_SPREAD * ndtri(u[:, 1]) + 3.0 * SIZE_SPREAD ** 2)) ** 3
        ei = core["sI"] * 1e6 * ndtri(u[:, 2])
        a = A0 * (T_ROOM - tc)
        w = np.full(N_CLUSTERS, POLAR / N_CLUSTERS)
        esw = switching_fields(a, vol, T_ROOM)
        _CLUSTERS[key] = (a, B4, vol, ei, w, esw)
    return _CLUSTERS[key]


def switching_fields(a, vol, T):
    """Every cluster's switching field (V / m) at the temperature T: e_sw(theta) (-a p_0), theta = 25 k T b / (v a^2);
    0 where a >= 0 (paraelectric) or theta >= 1/4 (ergodic)."""
    a = np.asarray(a, float)
    neg = a < 0.0
    theta = np.full(a.shape, np.inf)
    theta[neg] = LN_RATE * KB * T * B4 / (vol[neg] * a[neg] ** 2)
    out = np.zeros(a.shape)
    out[neg] = e_switch(theta[neg]) * (-a[neg]) * np.sqrt(-a[neg] / B4)
    return out


def branch_root(a, b, el, s):
    """The cluster's p on its well s (+1 or -1; ignored where a >= 0) at the local field el: the outer root of a p + b
    p^3 = el on that side (Newton's method from beyond the root, to 1e-15): arrays."""
    a, el, s = np.broadcast_arrays(np.asarray(a, float), np.asarray(el, float), np.asarray(s, float))
    x = np.where(a < 0.0, s, np.sign(el)) * (2.0 * np.sqrt(np.abs(a) / b) + np.cbrt(np.abs(el) / b) + 1e-3)
    for _ in range(200):
        dx = ((b * x * x + a) * x - el) / (3.0 * b * x * x + a)
        x = x - dx
        if np.all(np.abs(dx) < 1e-16):
            break
    return x


class Stack:
    """The stack's clusters and their state (each bistable cluster's well s and every cluster's p); `run(E)` steps them
    along the field E (V / m) and returns the polarisation P (C / m^2)."""

    def __init__(self, core, E0=0.0, s=None):
        self.core = core
        self.a, self.b, self.vol, self.ei, self.w, self.esw = clusters(core)
        el = E0 + self.ei
        self.s = np.where(el >= 0.0, 1.0, -1.0) if s is None else np.asarray(s, float).copy()
        self.p = branch_root(self.a, self.b, el, self.s)

    def run(self, E):
        E = np.asarray(E, float)
        Pc = _ensemble(E, self.a, self.b, self.esw, self.ei, self.w, self.s, self.p)
        return Pc + EPS0 * (self.core["eps_bg"] - 1.0) * E

    def run_warming(self, E, dT):
        """As run, the stack's temperature T_ROOM + dT (K, per sample) changing every cluster's a and switching
        field."""
        E, dT = np.asarray(E, float), np.asarray(dT, float)
        Pc = _ensemble_warming(E, dT, self.a, self.b, self.vol, self.ei, self.w, self.s, self.p, SW_Z, SW_E)
        return Pc + EPS0 * (self.core["eps_bg"] - 1.0) * E


@njit(cache=True)
def _newton(x, a, b, el):
    """The root of a x + b x^3 = el reached from x by Newton's method (stopping when a step is under 1e-9: the next
    would be under 1e-16 here)."""
    for _ in range(200):
        bx2 = b * x * x
        dx = ((bx2 + a) * x - el) / (3.0 * bx2 + a)
        x -= dx
        if abs(dx) < 1e-9:
            break
    return x


@njit(cache=True)
def _ensemble(E, a, b, esw, ei, w, s, p):
    """sum_k w_k p_k along the fields E, every bistable cluster switching its well where its local field passes its
    threshold (s and p carried in and out)."""
    n = E.shape[0]
    m = a.shape[0]
    out = np.empty(n)
    for i in range(n):
        tot = 0.0
        Ei = E[i]
        for k in range(m):
            el = Ei + ei[k]
            ak = a[k]
            x = p[k]
            if ak < 0.0:
                if s[k] > 0.0:
                    if el < -esw[k]:
                        s[k] = -1.0
                        x = -2.0 * math.sqrt(-ak / b) - (abs(el) / b) ** (1.0 / 3.0) - 1e-3
                elif el > esw[k]:
                    s[k] = 1.0
                    x = 2.0 * math.sqrt(-ak / b) + (abs(el) / b) ** (1.0 / 3.0) + 1e-3
            x = _newton(x, ak, b, el)
            p[k] = x
            tot += w[k] * x
        out[i] = tot
    return out


@njit(cache=True)
def _ensemble_warming(E, dT, a, b, vol, ei, w, s, p, sw_z, sw_e):
    """As _ensemble with the temperature T_ROOM + dT[i]: a_k + A0 dT, the switching fields from the table at theta = 25
    k T b / (v a^2); a cluster warmed past its T_c loses its well, one cooled below it takes the well its p is in."""
    n = E.shape[0]
    m = a.shape[0]
    out = np.empty(n)
    nz = sw_z.shape[0]
    for i in range(n):
        tot = 0.0
        Ei = E[i]
        T = T_ROOM + dT[i]
        da = A0 * dT[i]
        for k in range(m):
            el = Ei + ei[k]
            ak = a[k] + da
            x = p[k]
            if ak < 0.0:
                if s[k] == 0.0:
                    s[k] = 1.0 if x >= 0.0 else -1.0
                theta = LN_RATE * KB * T * b / (vol[k] * ak * ak)
                if theta >= 0.25:
                    e_sw = 0.0
                else:
                    z = (4.0 * theta) ** (2.0 / 3.0)
                    j = min(int(z * (nz - 1)), nz - 2)
                    f = (z - sw_z[j]) / (sw_z[j + 1] - sw_z[j])
                    e_sw = sw_e[j] + f * (sw_e[j + 1] - sw_e[j])
                esw = e_sw * (-ak) * math.sqrt(-ak / b)
                if s[k] > 0.0:
                    if el < -esw:
                        s[k] = -1.0
                        x = -2.0 * math.sqrt(-ak / b) - (abs(el) / b) ** (1.0 / 3.0) - 1e-3
                    elif x <= math.sqrt(-ak / (3.0 * b)):
                        x = 2.0 * math.sqrt(-ak / b) + (abs(el) / b) ** (1.0 / 3.0) + 1e-3
                elif el > esw:
                    s[k] = 1.0
                    x = 2.0 * math.sqrt(-ak / b) + (abs(el) / b) ** (1.0 / 3.0) + 1e-3
                elif x >= -math.sqrt(-ak / (3.0 * b)):
                    x = -2.0 * math.sqrt(-ak / b) - (abs(el) / b) ** (1.0 / 3.0) - 1e-3
            else:
                s[k] = 0.0
            x = _newton(x, ak, b, el)
            p[k] = x
            tot += w[k] * x
        out[i] = tot
    return out


def field(U):
    """The applied field (V / m) of the stack's voltage U (V): U over a layer's thickness."""
    return np.asarray(U, float) / LAYER


def amp_voltage(core, v):
    """The voltage the amplifier sets on the stack for the drive v: bias + gain v."""
    return core["bias"] + core["gain"] * np.asarray(v, float)


def reading(P):
    """The gauge's reading at the lever's tip (um) for the polarisation P, zeroed at the first sample: 1e6 LEVER LENGTH
    Q (P^2 - P(0)^2)."""
    P = np.asarray(P, float)
    return 1e6 * LEVER * LENGTH * Q11 * (P * P - P[0] * P[0])


def core_polarisation(core, U, stack=None):
    """The core's polarisation along the voltages U, from `stack` (default: the rest state at U[0]'s field)."""
    E = field(U)
    st = Stack(core, E[0]) if stack is None else stack
    return st.run(E)


def core_reading(core, U, stack=None):
    """The rate-independent stack's reading (um at the lever's tip) along the voltages U, from `stack` (default the rest
    state at U[0]), zeroed at the start."""
    return reading(core_polarisation(core, U, stack))


# ---- creep: the relaxor's slow dielectric relaxation (Cole-Cole) ----
#
# The creep record's stack relaxes: a relaxor's permittivity disperses over many decades of frequency, and its slow end
# (a Cole-Cole relaxation, as the relaxors' dielectric spectra are fitted: Cole & Cole, J. Chem. Phys. 9 (1941) 341, as
# remembered; the relaxation times spread by the clusters' Vogel-Fulcher barriers, Viehland, Jang, Cross & Wuttig,
# J. Appl. Phys. 68 (1990) 2916, as remembered) adds a polarisation that follows the field late: P_s(t) = chi_s int
# phi(t - u) dE(u), phi the Cole-Cole step response 1 - E_alpha(-(t / tau)^alpha) (E_alpha Mittag-Leffler's function:
# the time-domain form of the Cole-Cole law; alpha 0.45 ... 0.6, tau 1.5 ... 3 s), chi_s 0.16 ... 0.21 of the core's
# chord susceptibility over the record (a choice: a stack kept near its dielectric maximum, where the dispersion is
# largest). The strain is Q (P + P_s)^2: after a move up the stroke goes on growing, after a move down it goes on
# falling. phi is written as the Cole-Cole distribution of relaxation times, G(s) = sin(alpha pi) / (2 pi (cosh(alpha
# s) + cos(alpha pi))) over s = ln(tau' / tau), whose distribution function is F(s) = 1/2 + arctan(tanh(alpha s / 2)
# tan(alpha pi / 2)) / (pi alpha): cells of 0.02 in s over +-30 carry their exact masses at their middles (the mass
# below -30 relaxed at once, the mass above +30, under 1e-6, left out). The field is linear between samples, so P_s[i] =
# chi_s sum_j (E_j - E_(j-1)) k_(i-j), k_m the step response's mean over the lag's sample interval (exact through its
# antiderivative for m < 2000, beyond by Simpson's rule on a cubic interpolation in log t of phi, within 1e-10 of it).

CC_H, CC_S, CC_EXACT = 0.02, 30.0, 2000


def cole_cole_cells(alpha):
    """(s_mid, masses, fast): the Cole-Cole distribution's cells in s = ln(tau' / tau) and the mass relaxed at once."""
    edges = np.arange(-CC_S, CC_S + CC_H / 2, CC_H)
    F = 0.5 + np.arctan(np.tanh(alpha * edges / 2.0) * math.tan(alpha * math.pi / 2.0)) / (math.pi * alpha)
    return 0.5 * (edges[:-1] + edges[1:]), np.diff(F), float(F[0])


def cole_cole_step(t, tau, alpha):
    """phi(t) = 1 - E_alpha(-(t / tau)^alpha) (t > 0; 0 at t = 0) from the cells."""
    t = np.asarray(t, float)
    s, W, fast = cole_cole_cells(alpha)
    taus = tau * np.exp(s)
    out = np.empty(t.shape)
    flat = t.ravel()
    res = out.ravel()
    for i0 in range(0, flat.size, 256):
        tt = flat[i0:i0 + 256]
        res[i0:i0 + 256] = fast * (tt > 0) - np.expm1(-tt[:, None] / taus[None, :]) @ W
    return out


def cole_cole_kernel(n, dt, tau, alpha):
    """k_m (m = 0 ... n-1): phi's mean over [m dt, (m + 1) dt]."""
    s, W, fast = cole_cole_cells(alpha)
    taus = tau * np.exp(s)
    m = min(n, CC_EXACT)
    tt = np.arange(m + 1) * dt
    # the antiderivative of 1 - exp(-t / tau'): tau' (x + expm1(-x)), x = t / tau'
    Phi = np.empty(m + 1)
    for i0 in range(0, m + 1, 256):
        x = tt[i0:i0 + 256, None] / taus[None, :]
        Phi[i0:i0 + 256] = fast * tt[i0:i0 + 256] + (taus[None, :] * (x + np.expm1(-x))) @ W
    k = np.empty(n)
    k[:m] = np.diff(Phi) / dt
    if n > m:
        from scipy.interpolate import CubicSpline
        lg = np.linspace(math.log(m * dt), math.log(n * dt), 1200)
        spl = CubicSpline(lg, cole_cole_step(np.exp(lg), tau, alpha))
        t0 = np.arange(m, n) * dt
        k[m:] = (spl(np.log(t0)) + 4.0 * spl(np.log(t0 + 0.5 * dt)) + spl(np.log(t0 + dt))) / 6.0
    return k


def hereditary(x, kernel):
    """sum_j (x_j - x_(j-1)) kernel_(i-j) over j <= i (x before the record its first value): the hereditary integral of
    x linear between samples, kernel the step response's means over the samples' intervals (FFT convolution)."""
    from scipy.signal import fftconvolve
    dx = np.diff(np.asarray(x, float), prepend=x[0])
    return fftconvolve(dx, kernel)[:len(dx)]


# ---- rate dependence: the amplifier's series resistor charging the stack ----
#
# The rate record's stack hangs on a small 200 V amplifier whose output reaches it through a series resistor (R 1.5 ...
# 2.2 kOhm: its short-circuit protection; a choice of amplifier): the stack's charge Q (its 200 layers in parallel, each
# of 5 x 5 mm^2: Q = 200 A D, D = eps_0 E + P) follows R dQ / dt = U_a(t) - U, U_a the amplifier's output (bias + gain
# v). A relaxor's permittivity falls under a bias (the clusters align), so the time constant R dQ / dU is 7 ... 10 ms at
# 70 V, 4.5 ... 6.6 ms at the bias (120 V) and 3 ... 5 ms at 170 V: a lag whose length follows the voltage. The charge's
# law is the stack's polarisation with every cluster in its deeper well (its anhysteretic curve, tabulated on 0.05 V
# steps; the loop's share of the charge, the slim loop's, left out: a choice), the stack then stepped by its core along
# the voltage that results. The model's 4096 clusters draw that curve as a staircase of small steps (a real stack's far
# more clusters draw it smooth): the charge's law is the staircase averaged over SMEAR_V = 2 V (a Gaussian: a choice).
# The ODE is stepped by RK4 on SUB_RC sub-steps a sample (the amplifier's output linear between them); the drive's
# samples are the programme's, evaluated on the sub-steps. Checked in the test against solve_ivp.

SUB_RC = 8
SMEAR_V = 2.0


def anhysteretic(core, U):
    """The stack's polarisation with every cluster in its deeper well at the voltages U (increasing)."""
    E = field(U)
    a, b, vol, ei, w, esw = clusters(core)
    st = Stack(core, E[0])
    return _ensemble(E, a, b, np.zeros_like(esw), ei, w, st.s, st.p) + EPS0 * (core["eps_bg"] - 1.0) * E


def charge_table(core, u_max=215.0, du=0.05):
    """(U, Q): the stack's charge (C) on a grid of its voltage: N A (eps_0 E + P), P the anhysteretic polarisation
    averaged over SMEAR_V (a Gaussian, its tails beyond the grid's ends taken at the ends' values)."""
    from scipy.ndimage import gaussian_filter1d
    U = np.arange(-5.0 * SMEAR_V, u_max + 5.0 * SMEAR_V + du / 2, du)
    D = EPS0 * field(U) + anhysteretic(core, U)
    D = gaussian_filter1d(D, SMEAR_V / du, mode="nearest", truncate=5.0)
    keep = (U >= -du / 2) & (U <= u_max + du / 2)
    return U[keep], N_LAYERS * AREA * D[keep]


@njit(cache=True)
def _u_of_q(q, qt, ut):
    """The voltage at charge q, linear between the table's points (q increasing)."""
    n = qt.shape[0]
    if q <= qt[0]:
        return ut[0] + (q - qt[0]) * (ut[1] - ut[0]) / (qt[1] - qt[0])
    if q >= qt[n - 1]:
        return ut[n - 1] + (q - qt[n - 1]) * (ut[n - 1] - ut[n - 2]) / (qt[n - 1] - qt[n - 2])
    lo, hi = 0, n - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if qt[mid] <= q:
            lo = mid
        else:
            hi = mid
    return ut[lo] + (q - qt[lo]) * (ut[hi] - ut[lo]) / (qt[hi] - qt[lo])


@njit(cache=True)
def _charging(ua, h, R, qt, ut, q0):
    """The stack's voltage on the sub-steps along the amplifier's output ua (linear between them): RK4 of R dq/dt = ua -
    U(q)."""
    n = ua.shape[0]
    out = np.empty(n)
    q = q0
    out[0] = _u_of_q(q, qt, ut)
    for i in range(1, n):
        a0, a1 = ua[i - 1], ua[i]
        am = 0.5 * (a0 + a1)
        k1 = (a0 - _u_of_q(q, qt, ut)) / R
        k2 = (am - _u_of_q(q + 0.5 * h * k1, qt, ut)) / R
        k3 = (am - _u_of_q(q + 0.5 * h * k2, qt, ut)) / R
        k4 = (a1 - _u_of_q(q + h * k3, qt, ut)) / R
        q += h * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0
        out[i] = _u_of_q(q, qt, ut)
    return out


def charging(core, ua_fine, h, R, table=None):
    """The stack's voltage along the amplifier's output on a fine grid (step h), from rest at ua_fine[0]."""
    U, Q = charge_table(core) if table is None else table
    q0 = float(np.interp(ua_fine[0], U, Q))
    return _charging(np.asarray(ua_fine, float), h, R, Q, U, q0)


# ---- drift: the stack's temperature under a chiller's dead band ----
#
# The drift record's stack sits in a water-cooled housing on a small recirculating chiller with an on-off compressor
# and a dead band (a cheap one, as remembered; a choice): the coolant cools toward T_cold (6 ... 8 K below the set
# point) while the compressor runs and warms toward T_load (3 ... 5 K above it, the heat the room and the pump put in)
# while it rests, the compressor switched on at the set point + band and off at - band (band 1.0 ... 1.4 K), each arc
# an exponential approach with the coolant loop's time constant tau_w (60 ... 100 s: its reservoir's). The stack follows
# the coolant through its housing, tau_s T_s' = T_c - T_s (tau_s 8 ... 14 s; exact for T_c linear between samples).
# The chiller ran for 8 ... 9 cycles before the record from the set point with the compressor off; the set point is the
# room's 25 C, so the stack's temperature wanders about it by 1.6 ... 2.0 K from peak to peak over the record, a
# lopsided wave of 4 switchings, never a ramp. The relaxor feels it: every cluster's a_k moves with the temperature, and
# its switching field with it (the core at T_ROOM + dT, stepped by Stack.run_warming): at rest the stroke moves by -15
# sigma per K and its gain by -2.2 ... -2.6 % per K (measured on the records; labelled "drift").

def chiller(t, t_lead, band, d_cold, d_load, tau_w):
    """The coolant's temperature (K from the set point) at the times t (from 0), the chiller started t_lead before at
    the set point, compressor off: exponential arcs toward d_load (off) and -d_cold (on), switched at +-band. Returns
    (temperature, [(switch time, on), ...])."""
    t = np.asarray(t, float)
    T, on, now = 0.0, False, -t_lead
    switches = []
    out = np.empty(len(t))
    i = 0
    while i < len(t):
        target = -d_cold if on else d_load
        stop = -band if on else band
        t_sw = now + tau_w * math.log((T - target) / (stop - target))
        j = int(np.searchsorted(t, t_sw, side="right"))
        seg = t[i:j]
        out[i:j] = target + (T - target) * np.exp(-(seg - now) / tau_w)
        i = j
        T, now, on = stop, t_sw, not on
        switches.append((t_sw, on))
    return out, switches


def stack_temperature(t, t_lead, band, d_cold, d_load, tau_w, tau_s, dt_lead):
    """The stack's temperature (K from the set point) at the times t: the chiller from t_lead before the record (steps
    dt_lead), the stack starting at the set point with it. Returns (T_s on t, T_c on t)."""
    tt = np.r_[np.arange(-t_lead, 0.0, dt_lead), np.asarray(t, float)]
    Tc, _ = chiller(tt, t_lead, band, d_cold, d_load, tau_w)
    Ts = relax(tt, Tc, tau_s, 0.0)
    return Ts[-len(t):], Tc[-len(t):]


# ---- asymmetry: the bias switch left low ----
#
# The asymmetry record's amplifier has its bias switch left at its low position (60 ... 66 V, for another stack): the
# drive swings the stack about a point where the relaxor's polarisation is still steep and the strain, its square,
# strongly convex: a volt up moves it farther than a volt down (labelled "asymmetry"; the core's bipolar records' bias,
# 120 V, sits where the two curvatures cancel).


# ---- saturation: the lever stage's overtravel stops, set too tight ----
#
# The saturation record's lever stage had its overtravel stops (a hardened steel ball on a screw each side of the
# lever's tip: Hertz's contact of a sphere on a flat, F = K_H delta^(3/2), K_H = (4/3) E* R^(1/2), E* 115 GPa for
# steel on steel and R 10 ... 20 mm: 15 ... 22 N / um^(3/2); Hertz 1882, as remembered) set too tight after a service,
# at +-g from the tip's rest (g 0.55 ... 0.65 of the free stroke's half range on that side). The stack drives the tip
# through its own and the lever's compliance (the tip's stiffness k_e 10 ... 14 N / um: the stack's 300 N / um over the
# ratio squared, with the hinges'): the tip's travel x solves k_e (x_f - x) = K_H ((x - g)_+^(3/2) - (-g - x)_+^(3/2)),
# x_f the free tip's travel (the core's reading), by bisection (80 halvings); the stops bend the stroke's ends over
# (labelled "output_saturation").

def stopped(xf, k_e, K_H, g_hi, g_lo):
    """The tip's travel x (um) against the stops at +g_hi and -g_lo for the free travels xf: k_e (xf - x) = K_H ((x -
    g_hi)_+^1.5 - (-g_lo - x)_+^1.5), by bisection (monotone in x)."""
    xf = np.asarray(xf, float)
    lo = np.minimum(xf, -g_lo)
    hi = np.maximum(xf, g_hi)

    def resid(x):
        return k_e * (xf - x) - K_H * (np.maximum(x - g_hi, 0.0) ** 1.5 - np.maximum(-g_lo - x, 0.0) ** 1.5)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        pos = resid(mid) > 0.0
        lo = np.where(pos, mid, lo)
        hi = np.where(pos, hi, mid)
    return 0.5 * (lo + hi)


# ---- delay: the gauge's sigma-delta filter ----
#
# The delay record's capacitive gauge digitises its demodulated signal with a sigma-delta converter whose sinc^3
# decimation filter averages the position over three of its output words (its impulse response the quadratic B-spline
# over [0, 3 T], T the word period, here the logger's sample period: a group delay of 1.5 samples), and its interface
# hands the logger the word finished one period before the logger's sample: the reading at t_n is int B(s) x(t_n - T -
# s) ds, delay 2.5 samples in all (the sinc^3's smoothing, its variance T^2 / 4, is the rest). The position x is the
# core's on SUB_GAUGE sub-steps a sample, linear between them; the weights are B's exact integrals against those hats.

SUB_GAUGE = 4


def bspline2(s):
    """The quadratic B-spline over [0, 3] (unit area): the sinc^3 filter's impulse response in word periods."""
    s = np.asarray(s, float)
    return np.where((s >= 0) & (s < 1), s * s / 2, np.where((s >= 1) & (s < 2), -s * s + 3 * s - 1.5,
                                                           np.where((s >= 2) & (s <= 3), (3 - s) ** 2 / 2, 0.0)))


def gauge_weights(sub):
    """c_j = int B(s) hat_j(s) ds for the hats of the sub-steps (s in word periods, j = 0 ... 3 sub): Simpson's rule on
    each sub-step's halves (exact: B times a hat is a cubic there)."""
    h = 1.0 / sub
    c = np.zeros(3 * sub + 1)
    for j in range(3 * sub):
        for k in range(2):
            a = (j + 0.5 * k) * h
            b = a + 0.5 * h
            m = 0.5 * (a + b)
            for node, wt in ((a, 1.0), (m, 4.0), (b, 1.0)):
                f = float(bspline2(node)) * (b - a) / 6.0 * wt
                u = (node - j * h) / h
                c[j] += f * (1.0 - u)
                c[j + 1] += f * u
    return c


def gauge_filtered(x_fine, sub):
    """The gauge's reading on the samples from the position on the sub-steps (x before the record its first value): the
    sinc^3 filter over the three word periods ending one period before each sample."""
    c = gauge_weights(sub)
    pad = np.r_[np.full(4 * sub, x_fine[0]), np.asarray(x_fine, float)]
    # the sample n's position in pad: 4 sub + n sub; its filter reads pad[4 sub + n sub - sub - j], j = 0 ... 3 sub
    full = np.convolve(pad, c)[:len(pad)]
    idx = 4 * sub + np.arange(0, len(x_fine), sub) - sub
    return full[idx]


# ---- initial state: the stack short-circuited overnight, the dither skipped ----
#
# The initial-state record's stack stood the night short-circuited (the amplifier off, its output shorted by its safety
# relay): a long rest at zero field leaves every bistable cluster in its deeper well at E = 0 (the sign of its random
# field); the controller was started in its service mode, which skips the de-ageing dither, and ramped the stack
# straight to its bias: the clusters whose up-threshold lies above the bias field, and whose centre lies between 0 and
# it, are left in their '-' wells, where the dither's limit has them '+'. Until the drive sweeps them the stroke runs
# below the core's, and the stroke's zero with it.

def overnight_stack(core, n=2000):
    """The stack left by a night at 0 V and a straight ramp to the bias: the deeper wells at E = 0, then the field run
    up to the bias's."""
    st = Stack(core, 0.0)
    st.run(np.linspace(0.0, field(core["bias"]), n + 1)[1:])
    return st


# ---- two effects: an epoxy bond line's creep and the gauge's range ----
#
# The pair's stack was re-bonded to its base with a flexible epoxy (a repair: a bond line of some tenths of a mm): the
# preload spring and the lever's hinges press the stack down by F = F_0 + k_L e, e the stack's extension (k_L 1.5 ...
# 2.5 N / um), and the bond line creeps under it with the logarithmic creep compliance of a glassy polymer, J_c(t) = J_1
# log10(1 + t / t_0) (J_1 0.022 ... 0.03 um / N a decade, t_0 0.05 ... 0.1 s; the instantaneous part a constant gain,
# in the lever's ratio; a choice of law as remembered for polymers well below their glass transition, e.g. Struik's
# physical ageing, 1978), d(t) = int J_c(t - u) dF(u): the stack's base sinks by d, the tip by LEVER d: after a move up
# the stroke sags back, after a move down it recovers (labelled "creep"). The gauge was left on a range too small for
# the lever's stroke: its converter clips the reading at its full-scale codes, c_lo and c_hi about the gauge's zero
# (0.55 ... 0.7 of the free reading's extremes each way; labelled "output_saturation"); the converter's clip comes after
# the gauge's noise (the clipped samples read the full-scale codes exactly).

def log_creep_kernel(n, dt, J1, t0):
    """k_m: J_1 log10(1 + t / t_0)'s mean over [m dt, (m + 1) dt] (its antiderivative (t_0 + t) ln(1 + t / t_0) - t,
    over ln 10)."""
    tt = np.arange(n + 1) * dt
    A = ((t0 + tt) * np.log1p(tt / t0) - tt) / math.log(10.0)
    return J1 * np.diff(A) / dt


# ---- out of vocabulary: the bias supply's fuse ----
#
# The out-of-vocabulary record's amplifier lost its bias (the bias supply's fuse blown): the stack sees the drive alone,
# U = gain v, which swings the field through zero both ways; the electrostrictive strain, Q P^2, rises whichever way the
# field points: the stroke is a butterfly, twice the drive's frequency, that no monotone map of the biased core and no
# effect of the vocabulary draws. The controller's start-up dither ran about 0 V (where the stack then rested).
