"""Mechanisms of the HOLDOUT23 set (``cases_holdout23.py``), each written from its law; the signals are in
:mod:`.signals23`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal. The play, its threshold grid, a path's turning points and the raised cosine are the earlier sets' (the
same laws, imported as mechanisms22 does).

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout23.py against an independent
solution (a closed form, quadrature, brentq, solve_ivp, scipy's distributions or a finer simulation).
"""

import math

import numpy as np
from scipy.signal import lfilter

from .mechanisms13 import turning_points  # noqa: F401
from .mechanisms18 import exp_plays, grid, plays  # noqa: F401
from .mechanisms19 import raised_cosine  # noqa: F401


# ---- the rate-independent core ----

def nakagami_plays(n, r_max, m, spread, w0):
    """Thresholds on :func:`grid` weighted by the Nakagami-m density 2 m^m / (Gamma(m) W^m) r^(2m - 1) exp(-m r^2 /
    W), W = spread^2 (Nakagami 1960, the envelope of a faded radio signal: here the magnitude of a random local field
    summed from m 'clusters' of components): a hump at spread sqrt((2m - 1) / 2m); summing to 1 - w0."""
    r = grid(n, r_max)
    W = spread * spread
    logd = (2 * m - 1) * np.log(r) - m * r * r / W
    dens = np.exp(logd - logd.max())
    return r, (1 - w0) * dens / dens.sum()


# ---- creep: the Fuoss-Kirkwood distribution of retardation times ----

def fuoss_kirkwood_density(s, beta):
    """The density in s = ln(tau / tau0) of Fuoss & Kirkwood (J. Am. Chem. Soc. 63 (1941) 385, for the dielectric
    loss of plasticised polyvinyl chloride): (beta / pi) cos(beta pi / 2) cosh(beta s) / (cos^2(beta pi / 2) +
    sinh^2(beta s)), 0 < beta <= 1; its loss is (beta / 2) sech(beta ln(omega tau0)) (a Debye peak broadened by 1 /
    beta), with tails exp(-beta |s|)."""
    s = np.asarray(s, float)
    c = math.cos(beta * math.pi / 2)
    return beta / math.pi * c * np.cosh(beta * s) / (c * c + np.sinh(beta * s) ** 2)


def fuoss_kirkwood_cdf(s, beta):
    """The cumulative of :func:`fuoss_kirkwood_density`, 1/2 + (1 / pi) atan(sinh(beta s) / cos(beta pi / 2)) (its
    derivative is the density)."""
    return 0.5 + np.arctan(np.sinh(beta * np.asarray(s, float)) / math.cos(beta * math.pi / 2)) / math.pi


def fuoss_kirkwood_chain(tau0, beta, tau_lo=1e-4, tau_hi=1e4, per_decade=24):
    """A Kelvin chain on the density: cells of equal width in ln tau between tau_lo and tau_hi (s), each weighted by
    the density's mass over it (by :func:`fuoss_kirkwood_cdf`) and placed at its geometric centre; the mass faster
    than tau_lo acts at once (a gain on the core, returned as `instant`), the slower than tau_hi stays frozen over a
    record. Returns (taus, weights, instant)."""
    n = int(round(per_decade * math.log10(tau_hi / tau_lo)))
    edges = np.linspace(math.log(tau_lo), math.log(tau_hi), n + 1)
    cdf = fuoss_kirkwood_cdf(edges - math.log(tau0), beta)
    return np.exp(0.5 * (edges[1:] + edges[:-1])), np.diff(cdf), float(cdf[0])


def kelvin_chain_response(h, dt, taus, weights):
    """sum_i w_i e_i, each Kelvin element e_i' = (h - e_i) / tau_i, exact for h linear between samples (e_{k+1} = a
    e_k + (1 - c) h_{k+1} + (c - a) h_k, a = exp(-dt / tau), c = tau (1 - a) / dt), at rest at h[0] before the
    record."""
    h = np.asarray(h, float)
    x = h - h[0]
    out = np.zeros_like(h)
    for tau, w in zip(np.asarray(taus, float), np.asarray(weights, float)):
        a = math.exp(-dt / tau)
        c = tau * -math.expm1(-dt / tau) / dt
        out += w * lfilter([1 - c, c - a], [1.0, -a], x)
    return out + h[0] * float(np.sum(weights))


def fk_step_creep(t, tau0, beta):
    """The chain's retarded step response J_r(t) = sum w_i (1 - exp(-t / tau_i)) (0 at t = 0+)."""
    taus, w, _ = fuoss_kirkwood_chain(tau0, beta)
    t = np.clip(np.asarray(t, float), 0, None)[..., None]
    return np.sum(w * -np.expm1(-t / taus), axis=-1)


def fk_creep(h, dt, c, tau0, beta, t_ref=10.0):
    """Creep of a polymer mount with the Fuoss-Kirkwood spectrum, by Boltzmann superposition over the core's output h
    (the retarded chain's response R(h), exact for h linear between samples), normalised so that a step held t_ref s
    creeps by c of it: c R(h) / J_r(t_ref)."""
    taus, w, _ = fuoss_kirkwood_chain(tau0, beta)
    return c * kelvin_chain_response(h, dt, taus, w) / float(fk_step_creep(t_ref, tau0, beta))


# ---- rate dependence: a damper filled with a shear-thinning fluid ----

def shear_thinning_stage(h, dt, v_f, e_f, n, sub=4):
    """The stage behind the core's flexure (h its free stroke) held back by a damper filled with a shear-thinning
    polymer solution, the Ostwald-de Waele power law (stress K rate^n, n < 1; e.g. Bird, Armstrong & Hassager,
    *Dynamics of Polymeric Liquids*, 1987, vol. 1, ch. 4): k (h - y) = c |y'|^n sign(y'), i.e. with e = h - y, y' =
    v_f sign(e) |e / e_f|^(1 / n), e_f the lag at the speed v_f. A step relaxes algebraically (e0 (1 + (m - 1) v_f
    e0^(m - 1) t / e_f^m)^(-1 / (m - 1)), m = 1 / n) and a steady ramp of speed s lags by e_f (s / v_f)^n: a slow
    motion lags relatively more than a linear damper's. Classical Runge-Kutta on e' = h' - y' (h linear between
    samples, `sub` steps a sample); from rest at h[0]."""
    h = np.asarray(h, float).tolist()
    m = 1.0 / n
    d = dt / sub

    def f(e, s):
        return s - math.copysign(v_f * (abs(e) / e_f) ** m, e)
    e = 0.0
    out = [h[0]]
    for k in range(1, len(h)):
        s = (h[k] - h[k - 1]) / dt
        for _ in range(sub):
            k1 = f(e, s)
            k2 = f(e + 0.5 * d * k1, s)
            k3 = f(e + 0.5 * d * k2, s)
            k4 = f(e + d * k3, s)
            e += d * (k1 + 2 * k2 + 2 * k3 + k4) / 6
        out.append(h[k] - e)
    return np.array(out)


# ---- offset drift: a ground loop carrying a DC pump motor's current ----

def motor_ground_offset(t, runs, tau_m, ratio, tau_f):
    """The offset put on the sensor's reading by a DC pump motor whose current returns through a conductor shared with
    the sensor's ground (a ground loop: the offset R_g I; e.g. Ott, *Noise Reduction Techniques in Electronic
    Systems*, 1988, ch. 3), seen through the sensor's input filter (first order, tau_f). The motor, started across the
    line for each (t_on, t_off) in `runs`: its speed u (over the no-load speed) obeys tau_m u' = u_ss - u while on
    (armature inductance neglected; u_ss = 1 - 1 / ratio) and coasts, tau_m ratio u' = -u, while off (friction alone:
    the coast is `ratio` times slower); its current, in units of the locked-rotor current, is 1 - u while on (the back
    EMF) and 0 while off: an inrush `ratio` times the running current, decaying as the motor spins up. Closed form,
    piece by piece (the filter of an exponential is a difference of two). Returns the filtered current i_f (its
    largest, the inrush's peak, below 1)."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    u_ss = 1.0 - 1.0 / ratio
    tau_c = tau_m * ratio
    edges = sorted([(a, 1) for a, _ in runs] + [(b, 0) for _, b in runs])
    u, fv = 0.0, 0.0                                   # the speed and the filtered current at a piece's start
    bounds = [e[0] for e in edges] + [np.inf]
    for (ts, on), tn in zip(edges, bounds[1:]):      # nothing before the first start
        m = (t >= ts) & (t < tn)
        s = t[m] - ts
        if on:
            A, B = 1.0 - u_ss, u - u_ss              # i = A - B exp(-s / tau_m)
            out[m] = A * -np.expm1(-s / tau_f) + fv * np.exp(-s / tau_f) - B * tau_m / (tau_m - tau_f) * (
                np.exp(-s / tau_m) - np.exp(-s / tau_f))
            if np.isfinite(tn):
                S = tn - ts
                fv = A * -math.expm1(-S / tau_f) + fv * math.exp(-S / tau_f) - B * tau_m / (tau_m - tau_f) * (
                    math.exp(-S / tau_m) - math.exp(-S / tau_f))
                u = u_ss + B * math.exp(-S / tau_m)
        else:
            out[m] = fv * np.exp(-s / tau_f)
            if np.isfinite(tn):
                S = tn - ts
                fv *= math.exp(-S / tau_f)
                u *= math.exp(-S / tau_c)
    return out


# ---- asymmetry: a hot-wire anemometer by King's law ----

def king_voltage(x, a, lam, n):
    """The bridge voltage of a constant-temperature hot-wire anemometer, E^2 = A + B U^n (King, Phil. Trans. R. Soc.
    A 214 (1914) 373; Collis & Williams, J. Fluid Mech. 6 (1959) 357 found n about 0.45), in units of sqrt(B U0^n):
    sqrt(lam + (1 + a x)^n), the flow U = U0 (1 + a x) set by a throttle the stage moves (x its travel over its
    largest, a < 1), lam = A / (B U0^n)."""
    return np.sqrt(lam + (1 + a * np.asarray(x, float)) ** n)


def king_reading(x, a, lam, n):
    """:func:`king_voltage` from its value at rest, over its slope there (slope 1 at x = 0): concave, monotone."""
    e0 = math.sqrt(lam + 1.0)
    slope = n * a / (2 * e0)
    return (king_voltage(x, a, lam, n) - e0) / slope


# ---- saturation: a MOS differential pair ----

def mos_pair(u):
    """The differential output current of a source-coupled pair of MOS transistors in saturation (the square law I =
    (k / 2) (V_GS - V_t)^2, the tail current I_ss; e.g. Gray & Meyer, *Analysis and Design of Analog Integrated
    Circuits*, ch. 3): (I1 - I2) / I_ss = u sqrt(2 - u^2) for |u| <= 1, u = V_id / sqrt(2 I_ss / k), and sign(u)
    beyond (one transistor takes the whole tail current); slope sqrt(2) at 0, odd."""
    u = np.asarray(u, float)
    uc = np.clip(u, -1.0, 1.0)
    return np.where(np.abs(u) < 1.0, uc * np.sqrt(np.clip(2 - uc * uc, 0, None)), np.sign(u))


def mos_reading(h, centre, F):
    """The sensor's preamplifier on its pair: centre + F / sqrt(2) mos_pair((h - centre) / F) (slope 1 at the
    centre)."""
    return centre + F / math.sqrt(2) * mos_pair((np.asarray(h, float) - centre) / F)


# ---- delay: a voltage-to-frequency converter read by a gated counter ----

def gate_average(t_fine, h_fine, t_end, T_g):
    """The mean of the piecewise-linear h_fine (on the uniform t_fine) over [t_end - T_g, t_end] for each t_end, exact
    (the cumulative trapezoid, quadratic within a step); h_fine[0] before t_fine[0]."""
    t_fine = np.asarray(t_fine, float)
    h = np.asarray(h_fine, float)
    d = t_fine[1] - t_fine[0]
    C = np.r_[0.0, np.cumsum((h[1:] + h[:-1]) / 2) * d]

    def cum(x):
        x = np.asarray(x, float)
        before = x < t_fine[0]
        xc = np.clip(x, t_fine[0], t_fine[-1])
        k = np.minimum(((xc - t_fine[0]) / d).astype(int), len(h) - 2)
        tau = xc - t_fine[k]
        val = C[k] + h[k] * tau + (h[k + 1] - h[k]) * tau * tau / (2 * d)
        return np.where(before, (x - t_fine[0]) * h[0], val)
    t_end = np.asarray(t_end, float)
    return (cum(t_end) - cum(t_end - T_g)) / T_g


def vfc_counter(t, t_fine, h_fine, lag, dt):
    """A sensor whose output drives a voltage-to-frequency converter (charge balancing: its pulse count over a gate
    is the integral of the input over it; e.g. the synchronous VFCs of Analog Devices' application notes) counted by a
    gated counter over gates of one sample, which end `lag` samples before the logger reads them (the gate's phase
    against the logger's clock and the words queued in the interface): the reading at t_i is the mean of h over [t_i
    - lag dt - dt, t_i - lag dt]: a delay of lag + 1/2 samples and a one-sample moving average."""
    return gate_average(t_fine, h_fine, np.asarray(t, float) - lag * dt, dt)


# ---- two effects: an LED's inverse-square irradiance and its junction's self-heating ----

def inverse_square_reading(x, xi):
    """A photodiode facing an LED carried by the stage, d0 away at rest: the irradiance (d0 / (d0 - x))^2 (a point
    source's inverse-square law; e.g. Ryer, *Light Measurement Handbook*, 1997), x the travel toward the diode over
    its largest, xi the largest travel over d0; from its value at rest over its slope there: ((1 - xi x)^-2 - 1) / (2
    xi), convex, monotone for xi |x| < 1."""
    x = np.asarray(x, float)
    return ((1 - xi * x) ** -2 - 1) / (2 * xi)


def junction_droop(t, t_on, R1, tau1, R2, tau2, T_k):
    """The light of an LED switched on at t_on, over its cold value: exp(-dT / T_k) (the output falls with the
    junction's temperature; e.g. Schubert, *Light-Emitting Diodes*, 2006, ch. 6), dT = R1 (1 - exp(-s / tau1)) + R2
    (1 - exp(-s / tau2)) (the dissipated power through a two-stage Foster network: the die and the package), 1 before
    t_on."""
    s = np.clip(np.asarray(t, float) - t_on, 0, None)
    dT = R1 * -np.expm1(-s / tau1) + R2 * -np.expm1(-s / tau2)
    return np.exp(-dT / T_k)


# ---- out of vocabulary: a column under a pulsating axial load (parametric resonance) ----

def column_rhs(q, qd, p, w0, zeta, gamma, delta0):
    """The lateral mode of a slender push rod between the stage and its load, the axial load p (over the Euler load)
    taken from the core (Bolotin, *The Dynamic Stability of Elastic Systems*, 1964; a Mathieu-Duffing equation): q'' =
    -2 zeta w0 q' - w0^2 (1 - p) q - w0^2 gamma q^3 + w0^2 p delta0 (delta0 the rod's initial crookedness, amplified
    by the load; gamma the hardening of large deflections, which bounds the parametric growth)."""
    return -2 * zeta * w0 * qd - w0 * w0 * ((1 - p) * q + gamma * q ** 3 - p * delta0)


def column_lateral(p_fine, dt, w0, zeta, gamma, delta0):
    """q on the fine grid of the load p_fine (linear between its samples), classical Runge-Kutta at the grid's step,
    from the static deflection at p_fine[0] at rest."""
    p = np.asarray(p_fine, float).tolist()
    q = p[0] * delta0 / (1 - p[0])
    for _ in range(50):                                # the static state with the cubic: (1 - p) q + g q^3 = p delta0
        q -= ((1 - p[0]) * q + gamma * q ** 3 - p[0] * delta0) / ((1 - p[0]) + 3 * gamma * q * q)
    qd = 0.0
    out = [q]
    for k in range(1, len(p)):
        p0, p1 = p[k - 1], p[k]
        pm = 0.5 * (p0 + p1)
        a1 = column_rhs(q, qd, p0, w0, zeta, gamma, delta0)
        q2, v2 = q + 0.5 * dt * qd, qd + 0.5 * dt * a1
        a2 = column_rhs(q2, v2, pm, w0, zeta, gamma, delta0)
        q3, v3 = q + 0.5 * dt * v2, qd + 0.5 * dt * a2
        a3 = column_rhs(q3, v3, pm, w0, zeta, gamma, delta0)
        q4, v4 = q + dt * v3, qd + dt * a3
        a4 = column_rhs(q4, v4, p1, w0, zeta, gamma, delta0)
        q += dt * (qd + 2 * v2 + 2 * v3 + v4) / 6
        qd += dt * (a1 + 2 * a2 + 2 * a3 + a4) / 6
        out.append(q)
    return np.array(out)


__all__ = ["turning_points", "exp_plays", "grid", "plays", "raised_cosine", "nakagami_plays",
           "fuoss_kirkwood_density", "fuoss_kirkwood_cdf", "fuoss_kirkwood_chain", "kelvin_chain_response",
           "fk_step_creep", "fk_creep", "shear_thinning_stage", "motor_ground_offset", "king_voltage", "king_reading",
           "mos_pair", "mos_reading", "gate_average", "vfc_counter", "inverse_square_reading", "junction_droop",
           "column_rhs", "column_lateral"]
