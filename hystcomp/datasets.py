"""Simulated measurements with one hidden effect, for testing diagnosis blind.

:func:`hidden_effect_data` drives a random Prandtl-Ishlinskii actuator with
the identification experiment (:func:`hystcomp.signals.identification_experiment`),
adds exactly one of the effects :func:`hystcomp.diagnose.diagnose` knows (or
none) with a mechanism and a size drawn at random from several per effect,
and adds white sensor noise.  The mechanisms are deliberately not all the
model parts diagnosis fits, so that a test passing is not a formula matched
to itself:

===============  ===========================================================
effect           mechanisms (drawn with equal probability)
===============  ===========================================================
rate_dependence  ``lag``: first-order lag after the hysteresis, tau 1.5-6 ms;
                 ``resonance``: lightly damped mode after it, 15-35 Hz
                 (at most 0.2/dt),
                 damping 0.05-0.3; ``rate_thresholds``: thresholds
                 ``r_i + beta |dv/dt|`` (Al Janaideh et al. 2009), beta 4-10 ms
creep            ``multi_time_constant``: three lags of the input, tau
                 0.1-5 s, 5-12 % of the static gain; ``logarithmic``:
                 gamma log10(1 + t/t0) after every input change (Jung and
                 Gweon 2000), gamma 2.5-5 % of the static gain per decade,
                 t0 0.01-0.1 s; ``output_driven``: two lags of the
                 hysteresis output, 8-15 %
drift            ``ramp``: linear in time; ``thermal``: 1 - exp(-t/tau), tau
                 0.2-0.6 of the record; ``ramp_and_settle``: both; total
                 2-6 % of the output span
asymmetry        ``branch_gain``: asymmetric mGPI with linear envelopes of
                 slopes 1 and 1.25-1.6 (or the inverse); ``envelopes``:
                 one quadratic envelope v + c v^2/A, ``|c|`` 0.14-0.22,
                 the other v (since round 42); ``output_quadratic``: y = H + a H^2 / max|H|,
                 ``|a|`` 0.06-0.15
saturation       ``tanh_envelope``: mGPI with gamma = tanh(b v)/b, b A
                 0.8-1.4; ``output_tanh``: y = S tanh(H/S), S 0.7-1.2 of
                 max|H|; ``cubic``: y = H - k H^3 / max|H|^2, k 0.12-0.25
===============  ===========================================================
"""

from collections import namedtuple

import numpy as np
from scipy.signal import fftconvolve

from ._validation import as_count, as_scalar, as_signal, as_vector, check_choice
from .effects import LinearStage, RateDependentPI, lag_bank
from .envelopes import Identity, Linear, Polynomial, Tanh
from .models import MGPI, PI
from .signals import identification_experiment

__all__ = ["HiddenEffectData", "hidden_effect_data", "EFFECTS", "MECHANISMS"]

EFFECTS = ("rate_dependence", "creep", "drift", "asymmetry", "saturation")
MECHANISMS = {
    "rate_dependence": ("lag", "resonance", "rate_thresholds"),
    "creep": ("multi_time_constant", "logarithmic", "output_driven"),
    "drift": ("ramp", "thermal", "ramp_and_settle"),
    "asymmetry": ("branch_gain", "envelopes", "output_quadratic"),
    "saturation": ("tanh_envelope", "output_tanh", "cubic"),
}

HiddenEffectData = namedtuple("HiddenEffectData", ["t", "v", "y", "effect", "mechanism", "parameters",
                                                   "clean", "noise"])
HiddenEffectData.__doc__ = """Simulated measurement: t, v, y (noisy output), the hidden effect
and mechanism (None for none), their parameters (dict), the noise-free output
and the noise standard deviation (a named tuple, returned by
:func:`hidden_effect_data`).

Examples
--------
>>> d = hidden_effect_data(None, seed=0, dt=0.01)
>>> d.effect, d.mechanism, d.t.size == d.y.size == d.clean.size
(None, None, True)
>>> bool(abs(float(np.std(d.y - d.clean)) - d.noise) < 0.1 * d.noise)   # white noise of std d.noise
True
"""


def _actuator(rng, A):
    r = A * np.linspace(0.025, 0.975, 40)
    decay = rng.uniform(0.5, 3.0) / A
    p = np.exp(-decay * r) * (r[1] - r[0])
    p *= rng.uniform(0.6, 1.2) / p.sum()
    return r, p, float(rng.uniform(0.3, 1.0))


def hidden_effect_data(effect=None, seed=0, dt=4e-3, duration=40.0, noise=0.002, amplitude=1.0,
                       mechanism=None, experiment=None):
    """Measured-like data with exactly one hidden effect (or none).

    Parameters
    ----------
    effect : str or None
        One of ``rate_dependence``, ``creep``, ``drift``, ``asymmetry``,
        ``saturation``, or None / ``"none"`` for a plain hysteresis.
    seed : int
        Seeds the actuator, the mechanism, its size and the noise.
    dt, duration, amplitude
        Of the identification experiment (ignored when `experiment` is given).
    noise : float
        Sensor noise standard deviation as a fraction of the output span.
    mechanism : str, optional
        Force one mechanism of the effect (default drawn at random).
    experiment : Experiment or (t, v), optional
        Another excitation.

    Returns
    -------
    HiddenEffectData

    Examples
    --------
    >>> d = hidden_effect_data("creep", seed=1, dt=0.01)
    >>> d.effect, d.mechanism in ("multi_time_constant", "logarithmic", "output_driven"), d.t.size
    ('creep', True, 4000)
    """
    if effect == "none":
        effect = None
    if effect is not None:
        check_choice(effect, "effect", EFFECTS)
    rng = np.random.default_rng(as_count(seed, "seed", 0))
    if experiment is None:
        t, v, _ = identification_experiment(dt=dt, duration=duration, amplitude=amplitude)
    else:
        if isinstance(experiment, (str, bytes)) or not hasattr(experiment, "__len__") or len(experiment) < 2:
            raise TypeError(f"Parameter experiment is {experiment!r} but should be an Experiment or a pair "
                            "(t, v) of sample arrays")
        t = as_vector(experiment[0], "experiment[0] (t)", min_length=2, increasing=True)
        v = as_signal(experiment[1], "experiment[1] (v)")
        if v.size != t.size:
            raise ValueError(f"Parameter experiment has {t.size} times but {v.size} input samples; "
                             "expected one input sample per time")
        dt = float(np.median(np.diff(t)))
    A = float(np.max(np.abs(v)))
    noise = as_scalar(noise, "noise", nonnegative=True)
    r, p, p0 = _actuator(rng, A)
    gain = p0 + p.sum()
    pi = PI(r, p, p0)
    if effect is not None:
        mechs = MECHANISMS[effect]
        mech = mechanism if mechanism is not None else mechs[int(rng.integers(len(mechs)))]
        check_choice(mech, "mechanism", mechs)
    else:
        mech = None
    prm = {}
    T = float(t[-1] - t[0]) + dt
    tt = t - t[0]
    if effect is None:
        y = pi.simulate(v)
    elif effect == "rate_dependence":
        if mech == "lag":
            prm["time_constant"] = tau = float(rng.uniform(1.5e-3, 6e-3))
            y = LinearStage.lag(tau, dt).simulate(pi.simulate(v))
        elif mech == "resonance":
            prm["frequency"] = f = float(rng.uniform(15.0, min(35.0, 0.2 / dt)))
            prm["damping"] = z = float(rng.uniform(0.05, 0.3))
            y = LinearStage.resonance(f, z, dt).simulate(pi.simulate(v))
        else:
            prm["rate_coefficient"] = beta = float(rng.uniform(4e-3, 1e-2))
            y = RateDependentPI(r, p, p0, beta, dt).simulate(v)
    elif effect == "creep":
        H = pi.simulate(v)
        if mech == "multi_time_constant":
            tau = np.sort(np.exp(rng.uniform(np.log(0.1), np.log(5.0), 3)))
            c = rng.dirichlet(np.ones(3)) * rng.uniform(0.05, 0.12) * gain
            prm.update(time_constants=tau.tolist(), coefficients=c.tolist())
            X, _ = lag_bank(v, tau, dt)
            y = H + X @ c
        elif mech == "logarithmic":
            t0 = float(np.exp(rng.uniform(np.log(0.01), np.log(0.1))))
            gamma = float(rng.uniform(0.025, 0.05)) * gain
            prm.update(t0=t0, gamma_per_decade=gamma)
            dv = np.diff(v, prepend=v[0])
            kern = np.log10(1.0 + tt / t0)
            y = H + gamma * fftconvolve(dv, kern)[:v.size]
        else:
            tau = np.sort(np.exp(rng.uniform(np.log(0.1), np.log(5.0), 2)))
            c = rng.dirichlet(np.ones(2)) * rng.uniform(0.08, 0.15)
            prm.update(time_constants=tau.tolist(), coefficients=c.tolist())
            X, _ = lag_bank(H, tau, dt)
            y = H + X @ c
    elif effect == "drift":
        H = pi.simulate(v)
        total = float(rng.uniform(0.02, 0.06)) * float(np.ptp(H)) * rng.choice([-1.0, 1.0])
        if mech == "ramp":
            d = total * tt / T
        elif mech == "thermal":
            tau = float(rng.uniform(0.2, 0.6)) * T
            prm["time_constant"] = tau
            d = total * -np.expm1(-tt / tau) / -np.expm1(-1.0 * T / tau)
        else:
            tau = float(rng.uniform(0.2, 0.6)) * T
            prm["time_constant"] = tau
            d = 0.5 * total * (tt / T - np.expm1(-tt / tau) / -np.expm1(-T / tau))
        prm["total"] = total
        y = H + d
    elif effect == "asymmetry":
        lo, hi = -2 * A, 2 * A
        if mech == "branch_gain":
            k = float(rng.uniform(1.25, 1.6))
            k = k if rng.random() < 0.5 else 1.0 / k
            prm["slope_ratio"] = k
            y = MGPI(r, p, p0, envelope_left=Linear(k), envelope_right=Identity()).simulate(v)
        elif mech == "envelopes":
            # one envelope bent, the other straight: a difference between the
            # input's two sides (until round 42 the two were bent by nearly
            # opposite curvatures, mid +- half: gl(v) = -gr(-v) within |mid|,
            # a point-symmetric core whose loops narrow or widen towards both
            # ends alike, not an asymmetry; the same draws, so the other
            # mechanisms' records stay as they were)
            side, half = float(rng.uniform(-0.05, 0.05)), float(rng.uniform(0.07, 0.11))
            sgn = float(rng.choice([-1.0, 1.0]))
            cl, cr = (2.0 * sgn * half, 0.0) if side >= 0.0 else (0.0, 2.0 * sgn * half)
            prm.update(c_left=cl, c_right=cr)
            gl = Polynomial([0.0, 1.0, cl / A], interval=(lo, hi))
            gr = Polynomial([0.0, 1.0, cr / A], interval=(lo, hi))
            y = MGPI(r, p, p0, envelope_left=gl, envelope_right=gr).simulate(v)
        else:
            H = pi.simulate(v)
            a = float(rng.uniform(0.06, 0.15)) * rng.choice([-1.0, 1.0])
            prm["a"] = a
            y = H + a * H ** 2 / np.abs(H).max()
    else:  # saturation
        if mech == "tanh_envelope":
            b = float(rng.uniform(0.8, 1.4)) / A
            prm["b"] = b
            y = MGPI(r, p, p0, envelope=Tanh(1.0 / b, b)).simulate(v)
        else:
            H = pi.simulate(v)
            Hm = float(np.abs(H).max())
            if mech == "output_tanh":
                S = float(rng.uniform(0.7, 1.2)) * Hm
                prm["S"] = S
                y = S * np.tanh(H / S)
            else:
                k = float(rng.uniform(0.12, 0.25))
                prm["k"] = k
                y = H - k * H ** 3 / Hm ** 2
    sigma = noise * float(np.ptp(y))
    y_noisy = y + sigma * rng.standard_normal(y.size)
    return HiddenEffectData(t, v, y_noisy, effect, mech, prm, y, sigma)
