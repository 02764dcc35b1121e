"""Mechanisms of the HOLDOUT40 set (``cases_holdout40.py``), each written from its law; the signals are in
:mod:`.signals40`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive's field, or the
core's output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout40.py against an independent
solution (the grains switched one at a time by their definition, a closed form of the major branch, solve_ivp of the
same lines, quad and brentq, scipy's own Bessel design).
"""

import math

import numpy as np
from numba import njit
from scipy.linalg import expm
from scipy.optimize import brentq
from scipy.signal import bessel, tf2ss
from scipy.special import exp1
from scipy.stats import norm


# ---- the rate-independent core: a soft PZT disc's grains switching by 180 deg, read by a charge amplifier ----
#
# A disc of polycrystalline lead zirconate titanate (PZT, a tetragonal ferroelectric ceramic) between two silvered
# electrodes, in silicone oil, driven by a high-voltage amplifier (its field E proportional to the drive); its charge is
# read by a charge amplifier, times a drawn gain. Each grain carries a spontaneous polarisation P_s along its polar
# axis, at an angle theta to the field (the axes random in space: c = cos(theta) uniform on 0 ... 1 for the axis
# pointing to the field's side), and switches it by 180 deg when the work the field does on the switch exceeds a
# critical energy: 2 P_s E_loc c >= 2 P_s E_c (Hwang, Lynch & McMeeking, Acta Metall. Mater. 43 (1995) 2073; the 1 /
# cos(theta) law of coercivity is Kondorsky's for magnets, J. Phys. USSR 2 (1940) 161). Every grain's coercive field E_c
# is log-normal (median 1: fields in units of the median coercive field, about 1 kV/mm for soft PZT; the log's spread
# 0.25 ... 0.35) and it sits in an internal bias field b along its axis (defect dipoles and space charge, normal, spread
# 0.45 ... 0.6): the grain switches up (to +c P_s along the field) when E_loc >= (E_c + b) / c and down when E_loc <= (b
# - E_c) / c, a relay of the local field. The switched grains' polarisation depolarises the rest: in the mean-field
# (Lorentz-type) approximation E_loc = E - lambda P with P the mean of c s over the grains (s = +-1), lambda 1.2 ... 1.8
# (negative feedback: it shears the loop, as the demagnetising field does a magnet's). The grains switch one at a time
# in the order of their thresholds until none is left beyond its threshold (the feedback makes the local field fall as
# grains switch up, so the order is the physical one). The lattice's reversible polarisation adds eps E (eps 0.15 ...
# 0.3 of P_s per coercive field). The grains: 40 x 24 x 24 = 23,040, stratified over the quantiles of c, E_c and b (each
# grain's jump 1 / 23,040 of P_s: far below the noise).
#
# Rate independent, with return-point memory (a Preisach model of the local field, and the local field's path has the
# drive's turning points: the feedback is negative), but not a Prandtl-Ishlinskii model: each grain's thresholds are
# absolute fields, not distances from the last reversal, and the feedback breaks the minor loops' congruence. Before
# every record the disc was depoled by a slowly decaying alternating field (the rig's AC-depoling routine): in its limit
# every grain whose relay's centre b / c lies above 0 ends down, every other up (the Preisach plane's diagonal
# staircase; the grains' set is symmetric in b, so the net polarisation is 0).

def grains(ec_spread, bias, nc=40, ne=24, nb=24):
    """The grains' c = cos(theta), up thresholds alpha = (E_c + b) / c and down thresholds beta = (b - E_c) / c, on
    the midpoint quantiles of c (uniform on 0 ... 1), E_c (log-normal, median 1, the log's spread ec_spread) and b
    (normal, spread bias)."""
    def q(n):
        return (np.arange(n) + 0.5) / n
    c = q(nc)
    ec = np.exp(ec_spread * norm.ppf(q(ne)))
    b = bias * norm.ppf(q(nb)) if nb > 1 else np.zeros(1)
    C, E, B = (a.ravel() for a in np.meshgrid(c, ec, b, indexing="ij"))
    return C, (E + B) / C, (B - E) / C


def depoled(alpha, beta):
    """The AC-depoled state: every grain whose relay's centre (alpha + beta) / 2 lies at or above 0 down (-1), the
    others up (+1)."""
    return np.where(alpha + beta < 0.0, 1, -1).astype(np.int64)


@njit(cache=True)
def _switch_run(e, c, alpha, beta, oa, ob, s, lam):
    n = c.shape[0]
    w = 1.0 / n
    P = 0.0
    for i in range(n):
        P += w * c[i] * s[i]
    out = np.empty(e.shape[0])
    for k in range(e.shape[0]):
        x = e[k]
        changed = True
        while changed:
            changed = False
            for j in range(n):                                     # up, in the order of alpha
                i = oa[j]
                if alpha[i] > x - lam * P:
                    break
                if s[i] < 0:
                    s[i] = 1
                    P += 2.0 * w * c[i]
                    changed = True
            for j in range(n):                                     # down, in the order of beta (falling)
                i = ob[j]
                if beta[i] < x - lam * P:
                    break
                if s[i] > 0:
                    s[i] = -1
                    P -= 2.0 * w * c[i]
                    changed = True
        out[k] = P
    return out


def core_grains(core):
    """The core's grains (c, alpha, beta), cached on the core's dict."""
    key = (core["ecs"], core["bias"], core.get("nc", 40), core.get("ne", 24), core.get("nb", 24))
    cache = core.setdefault("_grains", {})
    if key not in cache:
        c, a, b = grains(*key)
        cache.clear()
        cache[key] = (c, a, b, np.argsort(a, kind="stable"), np.argsort(-b, kind="stable"))
    return cache[key]


def polarisation(core, e, s0=None, return_state=False):
    """The switched polarisation P (mean of c s, in units of P_s) along the fields e (units of the median coercive
    field), from the grains' states s0 (default the AC-depoled disc); with return_state also the states at the end."""
    c, a, b, oa, ob = core_grains(core)
    s = depoled(a, b) if s0 is None else np.array(s0, dtype=np.int64)
    P = _switch_run(np.asarray(e, float), c, a, b, oa, ob, s, float(core["lam"]))
    return (P, s) if return_state else P


def reading(core, e, p):
    """The charge amplifier's reading (before the offset): gain (P + eps E)."""
    return core["gain"] * (np.asarray(p, float) + core["eps"] * np.asarray(e, float))


def poled_state(core, e_pole, n_steps=60):
    """The grains after a DC field e_pole applied to the AC-depoled disc and removed (ramped up and down in n_steps
    steps each)."""
    ramp = np.r_[np.linspace(0.0, e_pole, n_steps + 1), np.linspace(e_pole, 0.0, n_steps + 1)[1:]]
    return polarisation(core, ramp, return_state=True)[1]


# ---- first-order lags, exact for an input linear between samples ----

def lag(u, dt, tau, x0=None):
    """x of tau x' = u - x for u linear between the samples (the exact first-order-hold recursion), from x0 (default
    u[0]: at rest)."""
    u = np.asarray(u, float)
    a = math.exp(-dt / tau)
    g = 1.0 - tau / dt * (1.0 - a)
    return _lag_run(u, a, g, float(u[0] if x0 is None else x0))


@njit(cache=True)
def _lag_run(u, a, g, x0):
    out = np.empty(u.shape[0])
    x = x0
    out[0] = x
    for k in range(1, u.shape[0]):
        x = a * x + (1.0 - a) * u[k - 1] + g * (u[k] - u[k - 1])
        out[k] = x
    return out


# ---- creep: the domain walls' thermally activated after-effect ----
#
# After every change of the polarisation (a grain's switch, or the walls' reversible bowing with the field) the walls
# keep advancing over the pinning barriers by thermal activation; with barriers spread evenly over a wide range the
# relaxation times tau = tau0 exp(U / kT) are spread evenly in ln(tau), and the polarisation approaches kappa times each
# increment more with the step response phi(t) = 1 - (E1(t / tau2) - E1(t / tau1)) / ln(tau2 / tau1) (a box spectrum of
# ln(tau)): linear in ln(t) between tau1 and tau2 (the after-effect of Street & Woolley, Proc. Phys. Soc. A 62 (1949)
# 562, for magnets; the log-time relaxation of switched PZT's polarisation, e.g. Lohkamper et al., J. Appl. Phys. 68
# (1990) 4220). Here tau1 0.05 s, tau2 500 s, kappa 0.25 ... 0.35, the spectrum taken as 24 Kelvin elements (6 a decade,
# the midpoint rule in ln tau).

def creep_times(tau1=0.05, tau2=500.0, per_decade=6):
    n = int(round(per_decade * math.log10(tau2 / tau1)))
    return np.exp(math.log(tau1) + (np.arange(n) + 0.5) * math.log(tau2 / tau1) / n)


def creep_step(t, tau1=0.05, tau2=500.0):
    """The box spectrum's step response phi(t) (0 at t = 0, 1 at infinity)."""
    t = np.maximum(np.asarray(t, float), 1e-300)
    return 1.0 - (exp1(t / tau2) - exp1(t / tau1)) / math.log(tau2 / tau1)


def aftereffect(p, dt, kappa, taus=None):
    """kappa times the mean of the Kelvin elements' responses to the polarisation's increments (each element at rest
    at p[0] at the start)."""
    taus = creep_times() if taus is None else taus
    p = np.asarray(p, float)
    acc = np.zeros(len(p))
    for tau in taus:
        acc += lag(p, dt, tau)
    return kappa * (acc / len(taus) - p[0])


# ---- rate dependence: the domain walls' viscosity ----
#
# The walls move at a finite speed: near the quasi-static state the switched polarisation relaxes to it as tau dP/dt =
# P_qs - P (Landau-Khalatnikov kinetics linearised; e.g. Lines & Glass, *Principles and Applications of Ferroelectrics*,
# 1977), tau 3 ... 15 ms; the lattice's reversible part follows the field at once.


# ---- drift: the electrometer's JFET gate current as it warms ----
#
# The charge amplifier's input JFET leaks a gate current that doubles every 10 K (a reverse-biased junction's
# generation current; e.g. Horowitz & Hill, *The Art of Electronics*, the JFET chapter); the amplifier warms after the
# range switch by dT (1 - exp(-t / tau)), dT 8 ... 20 K, tau 0.15 ... 0.5 of the record, so the current I0 2^(dT (1 -
# exp(-t / tau)) / 10 K), integrated on the feedback capacitor, gives an offset of the shape tau e^k (E1(k exp(-t /
# tau)) - E1(k)), k = ln(2) dT / 10 K, normalised to 1 at the record's end.

def gate_drift(t, tau, dT):
    """The integrated gate current tau e^k (E1(k e^(-t / tau)) - E1(k)) (0 at t = 0, slope 1 there)."""
    k = math.log(2.0) * dT / 10.0
    t = np.asarray(t, float)
    return tau * math.exp(k) * (exp1(k * np.exp(-t / tau)) - exp1(k))


# ---- asymmetry: a graded-junction varactor as the Sawyer-Tower sense capacitor ----
#
# The disc's charge is read as the voltage on a sense capacitor in series with it (Sawyer & Tower, Phys. Rev. 35 (1930)
# 269); here that capacitor is a reverse-biased, linearly graded silicon junction (C = C0 (1 + V / phi)^(-1/3); Sze,
# *Physics of Semiconductor Devices*), so its charge is q = (3 / 2) C0 phi ((1 + V / phi)^(2/3) - 1) and its voltage V
# = phi ((1 + (2 / 3) q / (C0 phi))^(3/2) - 1): convex in the charge. Over the reading's stroke s (-1 ... 1, slope 1 at
# 0): f(s) = ((1 + 2 k s / 3)^(3/2) - 1) / k, the ends' secants f(1) + f(-1) apart.

def varactor_reading(s, k):
    """The sense capacitor's voltage over its slope at 0: ((1 + 2 k s / 3)^(3/2) - 1) / k."""
    s = np.asarray(s, float)
    return ((1.0 + 2.0 * k * s / 3.0) ** 1.5 - 1.0) / k


def varactor_for(asym):
    """The k giving the ends' secants asym apart."""
    return brentq(lambda k: float(varactor_reading(1.0, k) + varactor_reading(-1.0, k)) - asym, 1e-6, 1.49,
                  xtol=1e-15)


# ---- saturation: the logger's input protection, anti-parallel diodes behind a series resistor ----
#
# The logger's input is guarded by a series resistor R and two anti-parallel silicon diodes to ground (Shockley's law,
# I = I_s (exp(V / n V_T) - 1) each): the source's voltage splits as V_src = V_in + 2 R I_s sinh(V_in / n V_T). Over
# the stroke X: s = u + rho sinh(beta u) (u = V_in / X, rho = 2 R I_s / X, beta = X / n V_T), read over its slope at 0,
# (1 + rho beta) u: soft, symmetric compression of the ends (10 ... 17 % here).

def diode_reading(s, rho, beta):
    """(1 + rho beta) u with s = u + rho sinh(beta u), u by Newton's method from inside the bracket."""
    s = np.asarray(s, float)
    u = s / (1.0 + rho * beta)                       # the linear guess: |u| too large, never too small
    for _ in range(200):
        f = u + rho * np.sinh(beta * u) - s
        step = f / (1.0 + rho * beta * np.cosh(beta * u))
        u = u - step
        if np.all(np.abs(step) <= 1e-15 * (1.0 + np.abs(u))):
            break
    return (1.0 + rho * beta) * u


def diodes_for(comp, rho_beta):
    """The (rho, beta) with rho beta = rho_beta whose reading at s = 1 is 1 - comp."""
    beta = brentq(lambda b: float(diode_reading(1.0, rho_beta / b, b)) - (1.0 - comp), 1e-3, 200.0, xtol=1e-14)
    return rho_beta / beta, beta


# ---- delay: the logger's fourth-order Bessel anti-aliasing filter ----
#
# The logger's analogue anti-aliasing filter is a fourth-order Bessel low-pass (Thomson, Proc. IEE 96 (1949) 487: a
# maximally flat group delay), normalised to a group delay tau_g at DC (2.5 ... 5.5 samples here): in the signals' band
# a pure delay. Its lines are solved exactly for an input linear between the steps of a grid four times finer than the
# record's (the core computed there), and the logger takes the filter's output at its samples.

R_FINE = 4


def bessel_ss(tau_g):
    """The state-space (A, B, C, D) of the fourth-order Bessel low-pass with a group delay tau_g at DC."""
    b, a = bessel(4, 1.0 / tau_g, btype="low", analog=True, norm="delay")
    return tf2ss(b, a)


def bessel_filter(u, h, tau_g):
    """The filter's output for u (linear between its samples, step h), from rest at u[0]; exact (the first-order hold
    through the matrix exponential of an augmented system)."""
    A, B, C, D = bessel_ss(tau_g)
    n = A.shape[0]
    M = np.zeros((n + 2, n + 2))
    M[:n, :n] = A * h
    M[:n, n] = B[:, 0] * h
    M[n, n + 1] = 1.0
    E = expm(M)
    Phi, G0, G1 = E[:n, :n], E[:n, n], E[:n, n + 1]
    u = np.asarray(u, float)
    x = -np.linalg.solve(A, B[:, 0]) * u[0]                     # at rest at the first input
    out = np.empty(len(u))
    out[0] = (C @ x)[0] + D[0, 0] * u[0]
    for k in range(1, len(u)):
        du = u[k] - u[k - 1]
        x = Phi @ x + G0 * u[k - 1] + G1 * du                   # the ramp's part: int (s / h) e^{A (h - s)} B ds
        out[k] = (C @ x)[0] + D[0, 0] * u[k]
    return out


# ---- out of vocabulary: the high-voltage amplifier's switching ripple, aliased ----
#
# The high-voltage amplifier is a switch-mode (half-bridge) stage at some 40 kHz whose output filter leaves a ripple on
# the disc's field; the disc's charge carries it, and the logger (no anti-aliasing filter on the charge channel) samples
# it: aliased to |f_sw - m f_s|, here 24 ... 40 Hz, drifting by 0.6 ... 1.5 Hz as the switcher's oscillator warms (tau_w
# 20 ... 40 s). A half-bridge's inductor ripple goes as D (1 - D), D = (1 + v / V_rail) / 2: the largest at 0 V, 1 - (v
# / V_rail)^2. The amplifier's monitor output is filtered and carries none of it. Its amplitude at its largest: 3.5 ...
# 6 % of the span. A tone the input does not carry, made by no map of the core, no time-invariant filter of the input
# and no labelled drift.

def aliased_ripple(t, v, f0, df, tau_w, v_rail, phase):
    """The ripple on times t: (1 - (v / v_rail)^2) sin(phase + 2 pi int f dt), f = f0 + df (1 - exp(-t / tau_w))."""
    t = np.asarray(t, float)
    ph = phase + 2 * math.pi * (f0 * t + df * (t - tau_w * (1.0 - np.exp(-t / tau_w))))
    return (1.0 - (np.asarray(v, float) / v_rail) ** 2) * np.sin(ph)
