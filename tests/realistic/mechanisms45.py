"""Mechanisms of the HOLDOUT45 set (``cases_holdout45.py``), each written from its law; the signals are in
:mod:`.signals45`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the field the coil sets in the rod
(from the clean drive), or the core's output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the material constants quoted (they are typical values, not a datasheet's). The laws do not rest on
them: each is checked in tests/test_realistic_holdout45.py against an independent solution (the plays written from
their definition, brentq of every sample's eddy-current balance, Radau (solve_ivp) of the walls' thermally activated
motion, LSODA of the coil's heating and of the dashpot, closed forms).
"""

import math

import numpy as np
from numba import njit

from .excitations import on_off_intervals


# ---- the rate-independent core: a prestressed Terfenol-D rod with pinned domain walls ----
#
# A Terfenol-D (Tb0.3Dy0.7Fe1.9) rod, 50 ... 65 mm across and 60 ... 100 mm long, is held in compression by a
# disc-spring
# stack (the prestress that turns its moments across the rod at rest: Clark's giant magnetostriction, Clark in
# *Ferromagnetic Materials* vol. 1, 1980; the Etrema actuators' layout, Dapino, Smith & Flatau, IEEE Trans. Magn. 36
# (2000) 545), inside a copper coil fed by a current amplifier (the coil's field proportional to the drive) and, on the
# bipolar records, a permanent bias magnet sleeve whose field H_b sets the rod's working point. An eddy-current probe
# reads the push rod's travel (um). Fields are in units of the anhysteretic's field scale a.
#
# The magnetisation (Bergqvist's dry-friction pinning of the domain walls, as remembered: Bergqvist, Physica B 233
# (1997)
# 342; the same structure as the "lag" or play models of Della Torre): the walls of the rod's regions are pinned like
# dry friction, region i's wall held until the field moves r_i past its equilibrium, so its effective field z_i is a
# play
# of H of threshold r_i (the pinning strengths r_i log-normal); each region's magnetisation is the anhysteretic of its
# effective field, and a reversible share c (the walls' bowing between pins) follows H itself:
#     M / Ms = c tanh(H) + (1 - c) sum_i w_i tanh(z_i),   z_i = min(max(z_i, H - r_i), H + r_i).
# The anhysteretic tanh(H / a) is the two-level limit of Armstrong's Boltzmann average over the easy axes (Armstrong, J.
# Appl. Phys. 81 (1997) 3548, as remembered): under the prestress the moments sit across the rod and the field lifts
# them to the axis, the two states' Boltzmann average a tanh (a choice over the full eight-axis average). The strain is
# the 90 deg rotation's quadratic law (the moments turned from across the rod to along it): lambda = (3 / 2) lambda_s
# (M / Ms)^2 (the "quadratic model" the actuator literature uses at moderate fields, e.g. Calkins, Smith & Flatau 2000),
# so the travel is y = Y (M / Ms)^2, Y = (3 / 2) lambda_s L the rod's full stroke.
#
# Rate independent, with return-point memory (every play has it, and the maps after the plays are fixed). Not a
# Prandtl-Ishlinskii model of the drive: the plays pass through tanh and the square (the loops narrow toward
# saturation, and the square folds the output at M = 0: a butterfly, which the bias keeps off the records).
#
# The virgin state: the rod AC-demagnetised at the factory (every z_i = 0, H = 0). On the bipolar records the actuator
# is assembled as its maker does: the bias sleeve slid on first (the field rising from 0 to H_b: every z_i = max(H_b -
# r_i, 0), the rising branch), then the prestress bolt tightened with the sleeve in place. Stress applied at a fixed
# field carries the magnetisation toward the anhysteretic (the magnetomechanical effect; Jiles's "law of approach",
# J. Phys. D 28 (1995) 1537, as remembered: dM / dsigma proportional to (M_an - M)); in this model the anhysteretic
# state at H is every z_i = H, and the prestress's ramp leaves z_i = H_b + (z_i - H_b) e^(-kappa), kappa 6 ... 9 (the
# prestress over the law's stress scale: chosen, not quoted). That is the state at 0 V, where the rod has sat since; no
# settling routine is run before a record. The unipolar records run without the sleeve: the prestress at zero field
# leaves the demagnetised rod as it was (every z_i = 0).

N_REG = 48


def regions(seed, n=N_REG, r_med=0.15, r_spread=0.5):
    """The regions' pinning thresholds r_i (log-normal about r_med, the log's spread r_spread, sorted) and weights w_i
    (log-normal, the log's spread 0.3, summing to 1)."""
    rng = np.random.default_rng(seed)
    r = np.sort(r_med * np.exp(r_spread * rng.standard_normal(n)))
    w = np.exp(0.3 * rng.standard_normal(n))
    return r, w / w.sum()


_R_CACHE = {}


def core_regions(core):
    """The core's regions (cached by their parameters)."""
    key = (core["rseed"], core.get("n", N_REG), core["r_med"], core["r_spread"])
    if key not in _R_CACHE:
        _R_CACHE[key] = regions(core["rseed"], core.get("n", N_REG), core["r_med"], core["r_spread"])
    return _R_CACHE[key]


def assembled(core, order="sleeve_first"):
    """The regions' effective fields at 0 V after assembly: the demagnetised rod (0) without the sleeve; with it, the
    sleeve slid on (max(H_b - r, 0)) and then the prestress applied (toward H_b by e^-kappa), or (order
    "prestress_first") the prestress applied at zero field and the sleeve slid on after (max(H_b - r, 0))."""
    r, _ = core_regions(core)
    Hb = core.get("Hb", 0.0)
    if Hb == 0.0:
        return np.zeros(len(r))
    z = np.maximum(Hb - r, 0.0)
    if order == "prestress_first":
        return z
    return Hb + (z - Hb) * math.exp(-core["kappa"])


def virgin(core):
    """The state at 0 V of a rod assembled the maker's way (:func:`assembled`)."""
    return assembled(core)


@njit(cache=True)
def _mag(H, z, w, c):
    """M / Ms at field H with the regions' effective fields z."""
    s = 0.0
    for i in range(z.shape[0]):
        s += w[i] * math.tanh(z[i])
    return c * math.tanh(H) + (1.0 - c) * s


@njit(cache=True)
def _plays(H, z, r):
    for i in range(z.shape[0]):
        z[i] = min(max(z[i], H - r[i]), H + r[i])


@njit(cache=True)
def _run_qs(Hs, z, r, w, c):
    out = np.empty(Hs.shape[0])
    for k in range(Hs.shape[0]):
        _plays(Hs[k], z, r)
        out[k] = _mag(Hs[k], z, w, c)
    return out


def field_path(core, H, z0=None, return_state=False):
    """M / Ms along the field H (rate independent) from the regions' fields z0 (default the virgin state)."""
    r, w = core_regions(core)
    z = virgin(core) if z0 is None else np.array(z0, float)
    m = _run_qs(np.ascontiguousarray(H, dtype=float), z, r, w, float(core["c"]))
    return (m, z) if return_state else m


def travel(core, m):
    """The probe's reading (um): Y (M / Ms)^2."""
    return core["Y"] * np.square(np.asarray(m, float))


def field(core, v):
    """The field (units of a) the coil and the sleeve set for the drive v: H_b + h v / amp (bipolar), H_top v / top
    (unipolar: no sleeve)."""
    v = np.asarray(v, float)
    if core["unipolar"]:
        return core["Htop"] * v / core["top"]
    return core["Hb"] + core["h"] * v / core["amp"]


# ---- creep: thermally activated wall motion (magnetic viscosity) ----
#
# The walls are not held for ever: thermal activation lets them hop past their pins (Neel 1950; Street & Woolley, Proc.
# Phys. Soc. A 62 (1949) 562: the magnetic viscosity, a change of magnetisation linear in ln t after a field change).
# A wall of region i hops forward and back over barriers lowered and raised by the field's pull d = H - z_i, the
# barrier's height r_i - d and r_i + d in units of the fluctuation field H_f = kT / (mu0 Ms V_act):
#     dz_i / dt = (H_f / tau0) [exp(-(r_i - d) / H_f) - exp(-(r_i + d) / H_f)]
#               = (2 H_f / tau0) e^(-r_i / H_f) sinh(d / H_f),
# tau0 the attempt time (1e-9 s). Driven fast (d beyond r_i) a wall follows the field at a lag r_i less a few H_f (its
# apparent pinning at the drive's speed); held, the lag shrinks as H_f ln t. With the field held over a sample (the
# amplifier's DAC holds it), the law has a closed form: tanh(d / (2 H_f)) decays as exp(-2 e^(-r_i / H_f) t / tau0).

TAU0 = 1e-9


@njit(cache=True)
def _creep_step(H, z, r, Hf, dt, tau0):
    for i in range(z.shape[0]):
        d0 = H - z[i]
        ad = abs(d0)
        ex = math.exp(-ad / Hf)
        one_m_q = 2.0 * ex / (1.0 + ex)
        kdt = 2.0 * math.exp(-r[i] / Hf) * dt / tau0
        E = math.exp(-kdt)
        y = (1.0 - one_m_q) * E
        one_m_y = -math.expm1(-kdt) + E * one_m_q
        d = Hf * math.log((1.0 + y) / one_m_y)
        z[i] = H - (d if d0 >= 0 else -d)


@njit(cache=True)
def _run_creep(Hs, z, r, w, c, Hf, dt):
    out = np.empty(Hs.shape[0])
    for k in range(Hs.shape[0]):
        _creep_step(Hs[k], z, r, Hf, dt, TAU0)
        out[k] = _mag(Hs[k], z, w, c)
    return out


def creep_path(core, H, dt, Hf, z0=None, return_state=False):
    """M / Ms along the field H (held over every sample of dt) with thermally activated walls (fluctuation field Hf)."""
    r, w = core_regions(core)
    z = virgin(core) if z0 is None else np.array(z0, float)
    m = _run_creep(np.ascontiguousarray(H, dtype=float), z, r, w, float(core["c"]), float(Hf), float(dt))
    return (m, z) if return_state else m


# ---- rate dependence: eddy currents in the solid rod ----
#
# The rod is solid (not laminated): a change of its flux drives currents round it that oppose the change. In a long
# cylinder of radius R and conductivity sigma, Faraday's and Ampere's laws give the field at radius rho as H(R) - (sigma
# / 4)(R^2 - rho^2) dB/dt at low frequency; over the cross-section the mean field lags the applied one by (sigma R^2 /
# 8)
# dB/dt (the classical eddy-current term, as in Jiles's dynamic model, J. Appl. Phys. 76 (1994) 5849, from memory):
#     H_in = H_a - tau_e d(H_in + (Ms / a) M / Ms) / dt,    tau_e = mu0 sigma R^2 / 8,
# the material following H_in (the rod's field taken uniform at its mean: the lumped, low-frequency limit). Terfenol-D's
# resistivity 0.6 uOhm m and a 50 ... 65 mm rod give tau_e 0.16 ... 0.28 ms, times the rod's relative permeability (10
# ... 40 on its steep branch). Solved by backward Euler in substeps (the applied field linear between samples): every
# substep's H_in lies between the last H_in and the applied field, and the balance is monotone in it (bisection with
# Newton's steps, to 1e-14).

RATE_SUB = 4


@njit(cache=True)
def _eddy_solve(Ha, Hp, Bp, z, r, w, c, ms, g):
    """The H_in with H_in + g (H_in + ms m(H_in) - Bp) = Ha, m from the regions z moved to H_in (z not changed)."""
    lo, hi = min(Ha, Hp), max(Ha, Hp)
    if hi - lo < 1e-300:
        return Ha
    zt = z.copy()
    x = Ha
    for _ in range(200):
        for i in range(z.shape[0]):
            zt[i] = min(max(z[i], x - r[i]), x + r[i])
        m = _mag(x, zt, w, c)
        f = x + g * (x + ms * m - Bp) - Ha
        if f > 0:
            hi = x
        else:
            lo = x
        # the slope: 1 + g (1 + ms dm/dH), the sliding regions' and the reversible share's
        dm = c / math.cosh(x) ** 2
        for i in range(z.shape[0]):
            if zt[i] != z[i]:
                dm += (1.0 - c) * w[i] / math.cosh(zt[i]) ** 2
        xn = x - f / (1.0 + g * (1.0 + ms * dm))
        if not (lo < xn < hi):
            xn = 0.5 * (lo + hi)
        if abs(xn - x) <= 1e-14 or hi - lo <= 1e-14:
            x = xn
            break
        x = xn
    return x


@njit(cache=True)
def _run_eddy(Ha, z, Hin, r, w, c, ms, tau, dt, nsub):
    out = np.empty(Ha.shape[0])
    hin = np.empty(Ha.shape[0])
    Hprev_a = Ha[0]
    g = tau / (dt / nsub)
    for k in range(Ha.shape[0]):
        for j in range(1, nsub + 1):
            ha = Hprev_a + (Ha[k] - Hprev_a) * j / nsub
            Bp = Hin + ms * _mag(Hin, z, w, c)
            Hin = _eddy_solve(ha, Hin, Bp, z, r, w, c, ms, g)
            _plays(Hin, z, r)
        Hprev_a = Ha[k]
        out[k] = _mag(Hin, z, w, c)
        hin[k] = Hin
    return out, hin


def eddy_path(core, Ha, dt, tau, nsub=RATE_SUB, z0=None, H0=None):
    """M / Ms and the rod's mean field along the applied field Ha with the eddy-current lag tau (s); from the virgin
    state at rest (the rod's field equal to the applied one at the start)."""
    r, w = core_regions(core)
    z = virgin(core) if z0 is None else np.array(z0, float)
    Ha = np.ascontiguousarray(Ha, dtype=float)
    Hin = float(Ha[0] if H0 is None else H0)
    return _run_eddy(Ha, z, Hin, r, w, float(core["c"]), float(core["ms"]), float(tau), float(dt), int(nsub))


# ---- drift: the coil's Joule heat warming the rod ----
#
# The coil's copper loss, R i^2 (i proportional to the drive on a unipolar record), warms the coil and, through the
# bobbin, the rod; the rod's temperature rise follows a first-order thermal network, C dT/dt = P - T / R_th (the time
# constant R_th C of minutes: 240 ... 480 s, far beyond the record), so the rise is nearly the heat's running integral.
# The warm rod lengthens against the (cooler) housing, alpha L T (Terfenol-D's expansion 12 ppm/K, as remembered), and
# its magnetostriction falls, (1 - beta T) (beta 0.3 ... 0.5 %/K: chosen, not quoted): the reading drifts.

def heating(t, p, T_end, tau_th):
    """The temperature rise (K) for the heating power p (any unit, linear between samples) through a first-order
    network of time constant tau_th, scaled so that it reaches T_end at the last sample (exact for p linear between
    samples)."""
    t = np.asarray(t, float)
    p = np.asarray(p, float)
    T = np.zeros(len(t))
    for k in range(1, len(t)):
        h = t[k] - t[k - 1]
        e = math.exp(-h / tau_th)
        # exact for p linear over the step: tau_th T' = p - T
        T[k] = p[k] + (T[k - 1] - p[k - 1]) * e - (p[k] - p[k - 1]) * tau_th / h * (1 - e)
    return T_end * T / T[-1]


# ---- saturation: the rod overdriven, the amplifier's reverse limit ----
#
# Driven well past its rating (the coil's field swing 2.2 ... 2.8 times the rated one), the rod's moments are all along
# its axis at the top (tanh near 1: the stroke flattens), and on the way down the current amplifier's reverse current
# limit, set to the bias sleeve's equivalent so the rod never sees a reversed field, holds the field at 0 (the stroke
# flat at the butterfly's bottom).

def limited_field(core, v, over):
    """The field with the coil's swing multiplied by over and the reverse limit at H = 0."""
    return np.maximum(core["Hb"] + over * core["h"] * np.asarray(v, float) / core["amp"], 0.0)


# ---- delay: the eddy-current probe's conditioner ----
#
# The probe's conditioner demodulates its carrier and filters the result with a linear-phase FIR filter before its
# analogue output (a digital conditioner: the filter's group delay, half its length, plus the converter's latency, 3.5
# ... 7 ms in all; a datasheet's order of magnitude as remembered). A linear-phase filter well above the record's band
# is a pure delay: y(t) = core(v(t - T_d)).


# ---- rate dependence (in the pair): an oil dashpot on the load ----
#
# The load is quietened by an oil dashpot on the push rod; the rod's and the disc springs' stiffness k in series with
# the dashpot's c: the push rod's travel follows the rod's free stroke as a first-order lag, tau_d dy/dt + y = y_free,
# tau_d = c / k (8 ... 15 ms). Exact for y_free linear between samples.

def dashpot(y_free, dt, tau):
    """The first-order lag of y_free (linear between samples), from rest at y_free[0]."""
    x = np.asarray(y_free, float)
    e = math.exp(-dt / tau)
    b = tau / dt * (1.0 - e)
    y = np.empty(len(x))
    y[0] = x[0]
    for k in range(1, len(x)):
        y[k] = x[k] + (y[k - 1] - x[k - 1]) * e - (x[k] - x[k - 1]) * b
    return y


# ---- out of vocabulary: a magnetic chuck on the next machine ----
#
# A surface grinder's electromagnetic chuck on the next bench is switched on and off as its operator changes parts; its
# stray field adds to the rod's (a fixed field H_s while it is on, 0.12 ... 0.2 of a: the leakage of a chuck a metre
# off, as an order of magnitude), and the rod's walls answer it like any field. The chuck's schedule is not recorded.

def chuck(t, on_range, off_range, rng):
    """The chuck's on intervals [(start, duration)] over t (the first after an off time), and a 0/1 mask."""
    return on_off_intervals(t, on_range, off_range, rng)
