"""Mechanisms of the HOLDOUT34 set (``cases_holdout34.py``), each written from its law; the signals are in
:mod:`.signals34`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive, or the core's
output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout34.py against an independent
solution (solve_ivp of the underlying equations, quad, brentq, a per-pad loop, a closed form, the transfer function
solved in the frequency domain, or a direct sum).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri


# ---- the rate-independent core: a voice-coil stage on elastomer pads that stick and slip (Gent rubber in shear) ----
#
# The stage is pushed by a voice coil (its force proportional to the drive: a current drive) against a flexure (linear
# stiffness k_f) and rests on a bed of filled-rubber pads bonded to it, whose feet stick to the base plate by Coulomb
# friction. A pad sheared by gamma (its top's travel over its height) carries Gent's shear stress (Gent, Rubber Chem.
# Technol. 69 (1996) 59: W = -(mu J_m / 2) ln(1 - (I_1 - 3) / J_m), I_1 - 3 = gamma^2 in simple shear, so tau = mu
# gamma J_m / (J_m - gamma^2): the chains' finite extensibility stiffens it towards the locking strain sqrt(J_m)); its
# foot slips when that stress reaches its friction, mu_f times its normal load, i.e. at a slip strain gamma_s, which
# spreads from pad to pad with their loads. A pad's strain is therefore a stop operator of the stage's travel bounded
# by +-gamma_s, and the stage's travel x balances k_f x + sum_i w_i gent(e_i) = F. Quasi-static (the stage's mass and
# the rubber's viscosity neglected): rate independent, with return-point memory (each pad's stop wipes out), but NOT a
# Prandtl-Ishlinskii model: the pads stiffen as they shear, so a branch depends on where the pads sat at the reversal,
# not only on the distance travelled from it (the branches are not Masing's).

def gent_shear(gamma, Jm):
    """Gent's simple-shear stress over the small-strain modulus: gamma J_m / (J_m - gamma^2)."""
    g = np.asarray(gamma, float)
    return g * Jm / (Jm - g * g)


def gent_energy(gamma, Jm):
    """Gent's strain energy in simple shear over the small-strain modulus: -(J_m / 2) ln(1 - gamma^2 / J_m)."""
    g = np.asarray(gamma, float)
    return -0.5 * Jm * np.log1p(-g * g / Jm)


def pad_bed(n, g_med, sigma, lock):
    """The pads: n equal-stiffness pads (weights 1 / n, so the bed's small-strain stiffness is 1) whose slip strains are
    log-normal (median g_med, their log's spread sigma; the midpoint quantiles), the locking parameter J_m set so that
    the largest slip strain reaches ``lock`` of J_m in gamma^2 (lock < 1). Returns dict(w, gs, Jm)."""
    gs = g_med * np.exp(sigma * ndtri((np.arange(n) + 0.5) / n))
    return dict(w=np.full(n, 1.0 / n), gs=gs, Jm=float(gs.max() ** 2 / lock))


@njit(cache=True)
def _bed_force(x, x0, e, w, gs, Jm, kf):
    f = kf * x
    for i in range(len(e)):
        s = e[i] + (x - x0)
        if s > gs[i]:
            s = gs[i]
        elif s < -gs[i]:
            s = -gs[i]
        f += w[i] * s * Jm / (Jm - s * s)
    return f


@njit(cache=True)
def _pads_run(F, e, x, w, gs, Jm, kf):
    n = len(F)
    out = np.empty(n)
    for k in range(n):
        g0 = _bed_force(x, x, e, w, gs, Jm, kf)
        r = F[k] - g0
        xn = x
        if r != 0.0:
            if r > 0.0:
                lo, hi = x, x + r / kf                    # the flexure alone would take the stage this far
            else:
                lo, hi = x + r / kf, x
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if _bed_force(mid, x, e, w, gs, Jm, kf) > F[k]:
                    hi = mid
                else:
                    lo = mid
                if hi - lo <= 1e-15 * (1.0 + abs(mid)):
                    break
            xn = 0.5 * (lo + hi)
        for i in range(len(e)):
            s = e[i] + (xn - x)
            if s > gs[i]:
                s = gs[i]
            elif s < -gs[i]:
                s = -gs[i]
            e[i] = s
        x = xn
        out[k] = x
    return out, x


def pad_stage(F, bed, kf, state=None, return_state=False):
    """The stage's travel for the voice coil's force F (in units of the bed's small-strain stiffness times a unit of
    strain): at each sample the travel x where k_f x + sum_i w_i gent(e_i) = F, each pad's strain e_i its value at the
    previous sample moved by the travel's change and clipped to +-gamma_s,i (its foot slipping beyond), solved by
    bisection (the force rises with x: every term is non-decreasing and the flexure's strictly). ``state`` (e, x) as
    returned with ``return_state``; None is the virgin bed (every pad unstrained, the stage at 0)."""
    if state is None:
        e, x = np.zeros(len(bed["w"])), 0.0
    else:
        e, x = np.array(state[0], float), float(state[1])
    out, x = _pads_run(np.asarray(F, float), e, x, bed["w"], bed["gs"], bed["Jm"], float(kf))
    return (out, (e, x)) if return_state else out


def pad_virgin_force(x, bed, kf):
    """The force on the virgin loading curve at travel x >= 0 (every pad strained by x up to its slip strain)."""
    x = np.asarray(x, float)
    s = np.minimum(x[..., None], bed["gs"])
    return kf * x + (bed["w"] * gent_shear(s, bed["Jm"])).sum(axis=-1)


# ---- creep: a lead shim under the sensor's mount, by Andrade's law ----

def andrade(t, beta, kappa):
    """Andrade's creep of a metal at a constant load (Andrade, Proc. R. Soc. A 84 (1910) 1): the transient beta t^(1/3)
    and the viscous flow kappa t (the small-strain form of l = l0 (1 + beta t^(1/3)) e^(kappa t)); 0 for t <= 0."""
    s = np.maximum(np.asarray(t, float), 0.0)
    return beta * np.cbrt(s) + kappa * s


def andrade_creep(f, dt, c, beta, kappa, t_ref=10.0):
    """Creep under the load f (the core's output), superposed after Boltzmann with f linear between the samples: the
    increment df_j spread over its sample gives, m samples later, Andrade's law averaged over that sample, in closed
    form ((3 / 4) beta (t_b^(4/3) - t_a^(4/3)) / dt + kappa (t_a + t_b) / 2); a convolution done by FFT; scaled so that
    a step held t_ref s creeps by c of it; 0 at the start."""
    from scipy.signal import fftconvolve
    f = np.asarray(f, float)
    N = len(f)
    ta = np.arange(N) * dt
    tb = ta + dt
    kern = 0.75 * beta * (tb ** (4 / 3) - ta ** (4 / 3)) / dt + kappa * (ta + tb) / 2
    df = np.r_[0.0, np.diff(f)]
    return c * fftconvolve(df, kern)[:N] / float(andrade(t_ref, beta, kappa))


# ---- rate dependence: a twin-tube damper valved harder in rebound than in compression ----

@njit(cache=True)
def _valved_run(hf, d, tau_ext, tau_cmp):
    out = np.empty(len(hf))
    y = hf[0]
    out[0] = y
    for j in range(1, len(hf)):
        e0 = 0.5 * (hf[j - 1] + hf[j]) - y              # the implicit midpoint: D = d (h_mid - y - D / 2) / tau
        tau = tau_ext if e0 > 0.0 else tau_cmp
        y += d * e0 / (tau + 0.5 * d)
        out[j] = y
    return out


def valved_damper_stage(h, dt, tau_ext, tau_cmp, sub=8):
    """The stage's travel y when the actuator (its free stroke h, the core's output) drives it through its own
    stiffness against a twin-tube damper whose valving is harder in rebound (extension, y' > 0) than in compression
    (a car's shock absorber; e.g. Dixon, *The Shock Absorber Handbook*, 2007): y' = (h - y) / tau, tau = tau_ext for
    y' > 0 and tau_cmp for y' < 0 (each a linear bleed: the damping over the stiffness). Stepped ``sub`` times a sample
    by the implicit midpoint rule (the step's sign is the sign of h_mid - y, so each step is explicit), h linear between
    the samples; at rest at h[0]."""
    h = np.asarray(h, float)
    hf = np.interp(np.arange((len(h) - 1) * sub + 1) / sub, np.arange(len(h)), h)
    return _valved_run(hf, dt / sub, float(tau_ext), float(tau_cmp))[::sub]


# ---- drift: sand-filled legs compacting under a nearby machine's vibration ----

def knight_compaction(t_shake, B, tau):
    """The packing fraction's rise of a granular bed tapped or shaken for a time t_shake, over its final rise:
    1 - 1 / (1 + B ln(1 + t_shake / tau)) (Knight, Fandrich, Lau, Jaeger & Nagel, Phys. Rev. E 51 (1995) 3957: the
    inverse-logarithmic density relaxation); the bed holds still while it is not shaken."""
    s = np.maximum(np.asarray(t_shake, float), 0.0)
    return 1.0 - 1.0 / (1.0 + B * np.log1p(s / tau))


def shaking_time(t, runs):
    """The machine's accumulated running time at the times t: runs (start, duration) in seconds."""
    t = np.asarray(t, float)
    acc = np.zeros(len(t))
    for t0, T in runs:
        acc += np.clip(t - t0, 0.0, T)
    return acc


# ---- asymmetry: a CdS photoresistor behind a shutter on the stage ----

def rose_exponent(T, Tc):
    """The exponent of a photoconductor's current against the light, i ~ E^gamma, for an exponential distribution of
    trap (recombination) states of characteristic temperature Tc (Rose, *Concepts in Photoconductivity*, 1963):
    gamma = Tc / (T + Tc)."""
    return Tc / (T + Tc)


def ldr_reading(u, a, gamma):
    """The photocurrent of a CdS cell read at a fixed bias by a transimpedance amplifier, the light on it E0 (1 + a u)
    (a straight shutter edge on the stage uncovering a uniformly lit rectangular window: the open area linear in the
    travel u, -1 ... 1), scaled to slope 1 at u = 0: ((1 + a u)^gamma - 1) / (gamma a); concave for gamma < 1."""
    return ((1.0 + a * np.asarray(u, float)) ** gamma - 1.0) / (gamma * a)


def ldr_asym(a, gamma):
    """The ends' secants' difference, reading(1) + reading(-1) (negative: the dim end steeper)."""
    return float(ldr_reading(1.0, a, gamma) + ldr_reading(-1.0, a, gamma))


# ---- saturation: a pre-tensioned membrane bulged by the oil the stage's plunger displaces ----

def cap_volume(h, a):
    """The volume of a spherical cap of height h on a circle of radius a: (pi h / 6)(3 a^2 + h^2) (signed: a bulge
    either way)."""
    h = np.asarray(h, float)
    return math.pi * h / 6.0 * (3 * a * a + h * h)


def membrane_apex(V, a):
    """The apex height of a pre-tensioned membrane clamped on a circle of radius a bulged by the oil volume V: under a
    uniform pressure and a uniform tension much larger than its stretching adds, the membrane is a spherical cap
    (Laplace, p = 2 T / R), so V = cap_volume(h, a); inverted in closed form: with v = V / (pi a^3 / 2), v = q + q^3 / 3
    (q = h / a), q = 2 sinh(asinh(3 v / 2) / 3)."""
    v = np.asarray(V, float) / (math.pi * a ** 3 / 2)
    return 2.0 * a * np.sinh(np.arcsinh(1.5 * v) / 3.0)


def membrane_reading(u, b):
    """The apex read for the plunger's travel u (-1 ... 1 of its stroke; the stroke displaces b (pi a^3 / 2) of oil),
    scaled to slope 1 at u = 0: q(b u) / b (q = h / a, a = 1), the ends compressed by 1 - reading(1)."""
    return membrane_apex(b * np.asarray(u, float) * (math.pi / 2), 1.0) / b


# ---- delay: a smart sensor's oversampled exponential moving average ----

def ema_sensor(xf, R, k, latency=1):
    """A smart sensor that samples R times a record's sample, smooths by the firmware's exponential moving average
    (a bit-shift filter: s += (x - s) >> k, i.e. alpha = 2^-k, from its first sample) and reports, at each record
    sample, its state ``latency`` record samples old (the report's transmission). xf is the input on the fine grid
    (every R-th sample a record's); returns the record's readings (the first held at xf[0])."""
    xf = np.asarray(xf, float)
    alpha = 2.0 ** -k
    s = np.empty(len(xf))
    acc = xf[0]
    for j in range(len(xf)):
        acc += alpha * (xf[j] - acc)
        s[j] = acc
    rec = s[::R]
    return np.r_[np.full(latency, xf[0]), rec[:len(rec) - latency]]


def ema_transfer(z, k):
    """The EMA's transfer function alpha / (1 - (1 - alpha) z^-1), alpha = 2^-k."""
    alpha = 2.0 ** -k
    return alpha / (1.0 - (1.0 - alpha) / np.asarray(z, complex))


# ---- the initial state: an emergency stop during a swept-sine test ----

def estop_path(A, f0, f1, T_sweep, t_cut, tau_L, per_cycle=200):
    """The coil's force during a swept-sine (a linear chirp f0 -> f1 over T_sweep at the amplitude A) cut by an
    emergency stop at t_cut: the amplifier disabled, the coil's current decaying through its freewheel diode as
    exp(-(t - t_cut) / tau_L) from its value at the cut (the coil's L / R). Sampled per_cycle times a cycle of the
    sweep and 400 times over 8 tau_L of the decay, then 0. Returns (times, path)."""
    n = int(per_cycle * (f0 + f1) / 2 * T_sweep) + 1
    t = np.linspace(0.0, t_cut, max(int(n * t_cut / T_sweep), 2))
    ph = 2 * math.pi * (f0 * t + (f1 - f0) * t * t / (2 * T_sweep))
    p = A * np.sin(ph)
    td = np.linspace(0.0, 8 * tau_L, 401)[1:]
    return np.r_[t, t_cut + td, t_cut + 8 * tau_L + 1e-3], np.r_[p, p[-1] * np.exp(-td / tau_L), 0.0]


# ---- the pair: a helium-neon laser sweeping its modes as it warms, read by an antiparallel-diode transimpedance ----

def hene_power(phase, fsr, fwhm, thresh):
    """A helium-neon laser's output while its cavity's modes sweep through the neon line's Doppler-broadened gain
    (e.g. Siegman, *Lasers*, 1986; the "mode sweeping" of an unstabilised tube): the modes sit at (j - phase) fsr from
    the line's centre (phase the fractional number of half-wavelengths the tube has grown by), each lasing with the
    gain above the loss, exp(-4 ln 2 (nu / fwhm)^2) - thresh, clipped at 0; the power the sum over the modes."""
    ph = np.asarray(phase, float)[..., None]
    j = np.arange(-8, 9)
    nu = (j - ph) * fsr
    g = np.exp(-4 * math.log(2) * (nu / fwhm) ** 2) - thresh
    return np.maximum(g, 0.0).sum(axis=-1)


def tube_phase(t, n_sweeps, tau_w, t_on):
    """The fractional half-wavelengths the tube has grown by since the record's start, t_on s after switch-on, the tube
    warming as 1 - exp(-t / tau_w): n_sweeps mode spacings over the whole warm-up from t_on."""
    t = np.asarray(t, float)
    return n_sweeps * (math.exp(-t_on / tau_w) - np.exp(-(t + t_on) / tau_w)) / math.exp(-t_on / tau_w)


def diode_tia(i, i_s):
    """A transimpedance amplifier with antiparallel diodes (a matched pair) in its feedback: the feedback current
    2 I_s sinh(V / (n V_T)) carries the input, so V / (n V_T) = asinh(i / (2 I_s)) (the Shockley law, e.g. Horowitz &
    Hill, *The Art of Electronics*, on log amplifiers)."""
    return np.arcsinh(np.asarray(i, float) / (2.0 * i_s))


def tia_reading(u, b):
    """The TIA's reading for the bicell's difference current b u (-1 ... 1 of the stroke; b in units of 2 I_s),
    scaled to slope 1 at u = 0: asinh(b u) / b, the ends compressed by 1 - reading(1)."""
    return diode_tia(b * np.asarray(u, float), 0.5) / b


# ---- out of vocabulary: a sensor follower dragged over a magnetic detent rack (Prandtl-Tomlinson) ----

@njit(cache=True)
def _tomlinson_run(h, y, eta, p):
    """Quasi-static: the follower at y relaxes downhill to the nearest stable equilibrium of K (h - y) = F0 sin(2 pi
    y / p) (units: F0 / K = eta p / (2 pi))."""
    n = len(h)
    out = np.empty(n)
    c = eta * p / (2 * math.pi)                          # F0 / K
    step = p / 400.0
    for k in range(n):
        hk = h[k]
        g = (hk - y) - c * math.sin(2 * math.pi * y / p)
        if g != 0.0:
            sgn = 1.0 if g > 0.0 else -1.0
            a = y
            b = y + sgn * step
            gb = (hk - b) - c * math.sin(2 * math.pi * b / p)
            while gb * sgn > 0.0:                        # scan downhill to the first sign change: the basin's bottom
                a = b
                b = b + sgn * step
                gb = (hk - b) - c * math.sin(2 * math.pi * b / p)
            lo, hi = (a, b) if a < b else (b, a)
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                gm = (hk - mid) - c * math.sin(2 * math.pi * mid / p)
                if gm > 0.0:
                    lo = mid
                else:
                    hi = mid
                if hi - lo <= 1e-15 * (1.0 + abs(mid)):
                    break
            y = 0.5 * (lo + hi)
        out[k] = y
    return out


def tomlinson_follower(h, eta, p, y0=None):
    """A sensor's follower carriage dragged by the stage through a soft spring K over a toothed steel rack, its magnet
    cogging with the force F0 sin(2 pi y / p) (pitch p): the Prandtl-Tomlinson model of stick-slip (Prandtl, ZAMM 8
    (1928) 85; Tomlinson, Phil. Mag. 7 (1929) 905). With eta = 2 pi F0 / (K p) > 1 the follower sticks in a detent and
    slips to the next when its basin vanishes; quasi-static (overdamped and slow): it rests at the stable equilibrium
    it relaxes to downhill from where it was. Starts at rest in the detent nearest h[0] (y0 if given)."""
    h = np.asarray(h, float)
    y = float(p * round(h[0] / p)) if y0 is None else float(y0)
    return _tomlinson_run(h, y, float(eta), float(p))
