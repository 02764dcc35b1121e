"""The HOLDOUT8 set: written after HOLDOUT7 was measured (2026-11-25, eighth round), to be run once
for the eighth round's final measurement (docs/diagnose.md); kept out of ALL until then.

Mechanisms and signals that the other sets do not have, or not in these combinations:

- a clean core under a sawtooth that ramps up slowly (80 ... 90 % of each period) and falls fast,
  between extremes drawn per cycle, sampled at 400 Hz;
- creep with a power-law compliance J(t) ~ t^alpha (alpha 0.15 ... 0.25), approximated by a
  Prony series of 14 Kelvin-Voigt elements spread log-uniformly from 10 ms to 200 s (compliances
  fitted to the law from 20 ms to 100 s), under holds at random levels, sampled at 250 Hz;
- plays whose weights grow with the recent input rate (a first-order lag of |dv/dt|; the
  rate-dependent weights of Ang et al. 2007), the reversible linear part unchanged, under a
  logarithmic sine sweep DOWN from 20 ... 30 Hz to 0.3 ... 0.5 Hz at constant amplitude, sampled
  at 2 kHz;
- a thermal offset linear in time plus a sinusoid (a period of 12 ... 20 s) under repeated
  triangles of three amplitudes, sampled at 600 Hz;
- a soft clip of the output, y = h / (1 + |h / ymax|^p)^(1/p) with p 2.5 ... 4 (HOLDOUT3 had
  p = 4 on bipolar sines), under a unipolar sine 0 ... 100 V with a slowly varying amplitude,
  1.2 kHz;
- a Preisach plane of 15,000 randomly placed relays whose interaction-field density is linear
  (skewed) instead of flat, plus a reversible part, under Hann-windowed tone bursts around
  offsets drawn per burst, sampled at 800 Hz (asymmetric loops without a Gaussian's saturation);
- a dead time of 1.5 ... 4 samples under a random-phase multisine (8 tones, 0.3 ... 6 Hz),
  sampled at 750 Hz;
- a core preloaded by three large one-sided cycles (to -+48 ... 58 V and back to -+10 ... 20 V,
  then to 0 V) before a staircase of random levels within +-40 V, sampled at 1.5 kHz;
- two effects: two Kelvin-Voigt elements and a sensor range that clips the top, under a staircase
  with a few holds near the top of the stroke, sampled at 500 Hz;
- out of vocabulary: accommodation, a core whose play thresholds (all below half the stroke)
  grow by 50 ... 80 % with the number of cycles it has been driven through, so that its loops
  widen and settle while their tips come in, under 28 cycles of a constant-amplitude sine and a
  decaying tail, sampled at 300 Hz; no PI core with the named effects draws that (a gain drift
  scales width and span alike, and the rate stays the same).
"""

import numpy as np

from . import excitations as ex
from . import mechanisms as me
from .record import case_set, finish

HOLDOUT8, case, _rng = case_set("holdout8_", 8000)


# ---- signals not in excitations.py ----

def _sawtooth(dt, n, rng, amp, period=(1.6, 2.6), rise_fraction=(0.8, 0.9), low_fraction=0.45):
    """A sawtooth starting at 0 V: slow linear ramps up to highs and fast ramps down to lows,
    each extreme drawn in [low_fraction, 1] x amp (highs positive, lows negative), each cycle's
    period and rise fraction drawn from the given ranges. Cut to ``n`` samples."""
    pts, durs = [0.0], []
    total = 0
    while total < n:
        T = rng.uniform(*period)
        rise = rng.uniform(*rise_fraction)
        hi = amp * rng.uniform(low_fraction, 1.0)
        lo = -amp * rng.uniform(low_fraction, 1.0)
        pts += [hi, lo]
        durs += [max(int(round(rise * T / dt)), 2), max(int(round((1 - rise) * T / dt)), 2)]
        total += durs[-1] + durs[-2]
    segs = [np.linspace(a, b, m, endpoint=False) for a, b, m in zip(pts[:-1], pts[1:], durs)]
    return np.concatenate(segs)[:n]


def _log_sweep(dt, n, f0, f1, amp):
    """A sine whose frequency moves exponentially from f0 to f1 Hz over n samples (f1 < f0 sweeps
    down), constant amplitude, starting at 0 V."""
    t = np.arange(n) * dt
    T = n * dt
    k = np.log(f1 / f0) / T
    phase = 2 * np.pi * f0 * (np.exp(k * t) - 1) / k
    return amp * np.sin(phase)


def _triangle_points(extremes, dt, rate):
    """Straight ramps at |dv/dt| = rate through the given extremes (starting at the first)."""
    parts = []
    for a, b in zip(extremes[:-1], extremes[1:]):
        m = max(int(round(abs(b - a) / rate / dt)), 2)
        parts.append(np.linspace(a, b, m, endpoint=False))
    return np.concatenate(parts + [[extremes[-1]]])


def _unipolar_varying_sine(dt, n, freq, top, env_period, env_depth=0.5):
    """0 ... top x env(t) V: (1 - cos) / 2 at `freq`, the envelope swinging between 1 and
    1 - env_depth with period `env_period` (starts at full amplitude, at 0 V)."""
    t = np.arange(n) * dt
    env = 1 - env_depth * 0.5 * (1 - np.cos(2 * np.pi * t / env_period))
    return top * env * 0.5 * (1 - np.cos(2 * np.pi * freq * t))


def _hann_bursts(dt, rng, n_bursts, carrier=(2.5, 5.0), cycles=(6, 11), peak=50.0, rest_s=0.25):
    """Tone bursts, each a sine of a whole number of cycles under a Hann window around an offset,
    both drawn per burst (|offset| + amplitude <= peak), 0 V between bursts. Returns the signal and
    the list of (offset, amplitude) per burst."""
    rest = np.zeros(int(round(rest_s / dt)))
    parts, drawn = [rest], []
    for _ in range(n_bursts):
        f = rng.uniform(*carrier)
        c = int(rng.integers(*cycles))
        m = int(round(c / f / dt))
        s = np.arange(m) / m
        w = 0.5 * (1 - np.cos(2 * np.pi * s))
        off = rng.uniform(-16.0, 16.0)
        a = rng.uniform(0.55, 1.0) * (peak - abs(off))
        parts += [w * (off + a * np.sin(2 * np.pi * c * s)), rest]
        drawn.append((off, a))
    return np.concatenate(parts), drawn


def _multisine(dt, n, freqs, rng, peak):
    """A sum of sines at `freqs` with random phases and amplitudes 1/sqrt(f), scaled to `peak`;
    faded in over the first second so that it starts at 0 V."""
    t = np.arange(n) * dt
    ph = rng.uniform(0, 2 * np.pi, len(freqs))
    x = sum(np.sin(2 * np.pi * f * t + p) / np.sqrt(f) for f, p in zip(freqs, ph))
    x = x * np.minimum(t / 1.0, 1.0)
    return peak * x / np.abs(x).max()


def _one_sided_cycles(sign, far, near, cycles, ramp=400):
    """A preload: 0 -> sign far -> sign near -> sign far ... (`cycles` times) -> 0."""
    pts = [0.0] + [sign * far, sign * near] * (cycles - 1) + [sign * far, 0.0]
    return np.concatenate([np.linspace(a, b, ramp, endpoint=False) for a, b in zip(pts[:-1], pts[1:])]
                          + [[0.0]])


def _hold_spans(v):
    """(start, end) index pairs of the flat runs of v longer than 20 samples."""
    edges = np.flatnonzero(np.diff(v) != 0) + 1
    starts = np.concatenate([[0], edges])
    ends = np.concatenate([edges, [len(v)]])
    return [(int(a), int(b)) for a, b in zip(starts, ends) if b - a > 20]


# ---- mechanisms not in mechanisms.py ----

def _prony_power_law(alpha, compliance_1s, tau_min=0.01, tau_max=200.0, n=14):
    """A Prony series (Kelvin-Voigt compliances c_k >= 0, time constants tau_k) fitted to the
    power-law creep compliance J(t) = J(1 s) t^alpha for 2 tau_min <= t <= tau_max / 2.

    The fractional (power-law) law has a continuous spectrum of retardation times; a Prony series
    with log-uniform tau_k samples it (Park & Schapery, Int. J. Solids Struct. 36 (1999) 1653:
    a collocation fit of the Prony coefficients). Here the c_k are the non-negative least-squares
    fit of sum c_k (1 - exp(-t / tau_k)) to the law in relative error on 60 log-spaced times.
    (Simply taking c_k proportional to tau_k^alpha converges to t^alpha only many decades above
    tau_min when alpha is small.)
    """
    from scipy.optimize import nnls

    tau = np.geomspace(tau_min, tau_max, n)
    t = np.geomspace(2 * tau_min, tau_max / 2, 60)
    target = compliance_1s * t ** alpha
    A = (1 - np.exp(-t[:, None] / tau[None, :])) / target[:, None]
    c, _ = nnls(A, np.ones(len(t)))
    return c, tau


def _rate_weighted_play(v, dt, span, kappa, tau, rate_ref, n=200):
    """Plays whose weights grow with the recent input rate: the hysteretic part of
    :func:`play_core` times 1 + kappa g(t), g = (first-order lag, time constant tau, of |dv/dt|)
    / rate_ref (causal backward difference); the reversible linear part stays.

    The rate-dependent weights of Ang, Khosla, Riviere, IEEE/ASME Trans. Mechatronics 12 (2007)
    (the loading slopes of a piezo stack grow with the drive rate): faster drive, wider loops.
    The lag keeps the output continuous where the rate jumps. ``kappa = 0`` is :func:`play_core`.
    """
    v = np.asarray(v, float)
    r, w = me._density_thresholds(span, n)
    w = w / w.sum()
    a = np.exp(-dt / tau)
    g = 0.0
    z = np.zeros_like(r)
    y = np.empty_like(v)
    prev = v[0]
    for k, vk in enumerate(v):
        g = a * g + (1 - a) * abs(vk - prev) / dt
        prev = vk
        z = np.minimum(np.maximum(z, vk - r), vk + r)
        y[k] = 0.35 * vk + 0.65 * (1 + kappa * g / rate_ref) * (w @ z)
    return y


def _soft_clip(h, ymax, p):
    """A smooth limiter y = h / (1 + |h / ymax|^p)^(1/p): slope 1 at 0, odd, tends to +-ymax."""
    h = np.asarray(h, float)
    return h / (1 + np.abs(h / ymax) ** p) ** (1 / p)


def _skewed_relays(rng, n, field_half_width, half_scale, skew):
    """Relay thresholds (alpha, beta) drawn from a Preisach density that is exponential in the
    half-width (alpha - beta) / 2 (scale `half_scale`) and LINEAR in the interaction field
    (alpha + beta) / 2 on [-W, W]: proportional to 1 + skew field / W (|skew| < 1).

    A density flat in the field on an unbounded plane is a Prandtl-Ishlinskii model; the linear
    field density makes the loops' top and bottom differ (rejection sampling)."""
    field = np.empty(0)
    while len(field) < n:
        f = rng.uniform(-field_half_width, field_half_width, 2 * n)
        keep = rng.uniform(0, 1 + abs(skew), 2 * n) < 1 + skew * f / field_half_width
        field = np.concatenate([field, f[keep]])
    field = field[:n]
    half = rng.exponential(half_scale, n)
    return field + half, field - half


def _relay_plane(v, alpha, beta, state=None):
    """The mean of relays with up-thresholds alpha and down-thresholds beta (alpha >= beta).

    A relay is +1 once the input has reached alpha and -1 once it has fallen to beta. After every
    sample all relays with alpha <= v are up and all with beta >= v down, so only the relays whose
    thresholds the input passed since the last sample change (sorted thresholds, exact).
    Demagnetised start (relays with alpha + beta > 0 down, the others up) unless ``state``.
    """
    v = np.asarray(v, float)
    s = np.where(alpha + beta > 0, -1.0, 1.0) if state is None else np.array(state, float)
    ia = np.argsort(alpha)
    ib = np.argsort(beta)
    a_sorted = alpha[ia]
    b_sorted = beta[ib]
    y = np.empty_like(v)
    total = s.sum()
    prev = None
    for k, vk in enumerate(v):
        if prev is None:
            up = ia[:np.searchsorted(a_sorted, vk, "right")]
            dn = ib[np.searchsorted(b_sorted, vk, "left"):]
        elif vk > prev:
            up = ia[np.searchsorted(a_sorted, prev, "right"):np.searchsorted(a_sorted, vk, "right")]
            dn = ib[:0]
        else:
            up = ia[:0]
            dn = ib[np.searchsorted(b_sorted, vk, "left"):np.searchsorted(b_sorted, prev, "left")]
        total += np.sum(1.0 - s[up]) - np.sum(1.0 + s[dn])
        s[up] = 1.0
        s[dn] = -1.0
        y[k] = total / len(s)
        prev = vk
    return y


def _accommodating_play(v, span, growth, cycles_scale, r_max_fraction=0.45, n=120):
    """Accommodation: plays whose thresholds grow with the number of cycles driven,
    r_k (1 + growth (1 - exp(-N / cycles_scale))), N = (total variation of v so far) / (2 span)
    (one cycle between -span/2 and +span/2 counts one).

    A narrow density (thresholds up to ``r_max_fraction`` x span / 2, below half the stroke) so
    that wider thresholds widen the loops (each play's loop is 2 r wide at the middle while
    r < amplitude / 2) while their tips come in (each play's output reaches amplitude - r): loops
    that widen and settle under repeated cycling, as magnetic materials and ferroelectrics show.
    A gain drift would scale the width and the span alike. ``growth = 0`` is a PI core.
    """
    v = np.asarray(v, float)
    r, w = me._density_thresholds(span, n, r_max_fraction=r_max_fraction)
    w = w / w.sum()
    z = np.zeros_like(r)
    y = np.empty_like(v)
    tv = 0.0
    prev = v[0]
    for k, vk in enumerate(v):
        tv += abs(vk - prev)
        prev = vk
        rk = r * (1 + growth * (1 - np.exp(-tv / (2 * span) / cycles_scale)))
        z = np.minimum(np.maximum(z, vk - rk), vk + rk)
        y[k] = 0.35 * vk + 0.65 * (w @ z)
    return y


# ---- clean ----

@case
def clean_slow_up_fast_down_sawtooth_400hz(seed):
    rng = _rng(seed, 1)
    dt, n = 1 / 400, 14_000
    v = _sawtooth(dt, n, rng, rng.uniform(44, 50))
    y = me.play_core(v, 100.0, gain=rng.uniform(0.6, 1.6)) + rng.uniform(-4, 4)
    return finish("holdout8_clean_slow_up_fast_down_sawtooth_400hz", seed, np.arange(n) * dt, v, y, set(),
                  "explained", "a clean core under a sawtooth (slow ramps up, fast ramps down, extremes "
                  "drawn per cycle) sampled at 400 Hz", rng, monitor_noise=3e-4)


# ---- one effect ----

@case
def creep_prony_power_law_holds_250hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 250
    levels = np.concatenate([[0.0], rng.uniform(-46, 46, 14)])
    v = ex.staircase_holds(dt, levels, rng.uniform(2.5, 3.5), 0.1)
    h = me.play_core(v, 100.0)
    alpha = rng.uniform(0.15, 0.25)
    c, tau = _prony_power_law(alpha, rng.uniform(0.05, 0.07))
    y = h + me.kelvin_voigt_creep(h, dt, c, tau)
    rec = finish("holdout8_creep_prony_power_law_holds_250hz", seed, np.arange(len(v)) * dt, v, y, {"creep"},
                 "either", f"power-law creep t^{alpha:.2f} (a Prony series of 14 Kelvin-Voigt elements, "
                 "10 ms ... 200 s) under holds at random levels, 250 Hz", rng, monitor_noise=4e-4)
    rec.extra.update(alpha=alpha, compliances=c, time_constants=tau, holds=_hold_spans(v))
    return rec


@case
def rate_weighted_plays_sweep_down(seed):
    rng = _rng(seed, 3)
    dt, n = 5e-4, 36_000
    f0, f1 = rng.uniform(20.0, 30.0), rng.uniform(0.3, 0.5)
    amp = rng.uniform(42, 48)
    v = _log_sweep(dt, n, f0, f1, amp)
    kappa = rng.uniform(0.12, 0.2)
    y = _rate_weighted_play(v, dt, 100.0, kappa, tau=rng.uniform(0.05, 0.15), rate_ref=4 * 50.0 * 10.0)
    rec = finish("holdout8_rate_weighted_plays_sweep_down", seed, np.arange(n) * dt, v, y,
                 {"rate_dependence"}, "either",
                 f"play weights growing with the lagged input rate (kappa {kappa:.2f}) under a "
                 f"logarithmic sweep down {f0:.1f} ... {f1:.2f} Hz, 2 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(f0=f0, f1=f1, kappa=kappa)
    return rec


@case
def drift_linear_plus_sine_repeated_triangles(seed):
    rng = _rng(seed, 4)
    dt = 1 / 600
    amp = rng.uniform(42, 48)
    pattern = np.array([1.0, rng.uniform(0.6, 0.75), rng.uniform(0.3, 0.45)])
    ext = [0.0] + [s * a * amp for a in np.tile(pattern, 7) for s in (1.0, -1.0)] + [0.0]
    v = _triangle_points(ext, dt, rate=4 * amp * rng.uniform(0.5, 0.7))
    t = np.arange(len(v)) * dt
    h = me.play_core(v, 100.0)
    T = t[-1]
    lin = rng.choice([-1.0, 1.0]) * rng.uniform(0.025, 0.045)
    off = np.ptp(h) * (lin * t / T + rng.uniform(0.015, 0.03)
                       * np.sin(2 * np.pi * t / rng.uniform(12.0, 20.0) + rng.uniform(0, 2 * np.pi)))
    off -= off[0]
    y = h + off
    rec = finish("holdout8_drift_linear_plus_sine_repeated_triangles", seed, t, v, y, {"drift"}, "either",
                 "a thermal offset linear in time plus a 12 ... 20 s sinusoid, triangles of three "
                 "amplitudes repeated seven times, 600 Hz", rng, monitor_noise=3e-4)
    rec.extra["offset"] = off
    return rec


@case
def saturation_soft_clip_unipolar_sine(seed):
    rng = _rng(seed, 5)
    dt, n = 1 / 1200, 24_000
    v = _unipolar_varying_sine(dt, n, rng.uniform(1.5, 2.5), 100.0, rng.uniform(6.0, 9.0))
    h = me.play_core(v, 100.0)
    ymax = rng.uniform(1.05, 1.4) * h.max()
    p = rng.uniform(2.5, 4.0)
    y = _soft_clip(h, ymax, p)
    rec = finish("holdout8_saturation_soft_clip_unipolar_sine", seed, np.arange(n) * dt, v, y,
                 {"output_saturation"}, "either",
                 f"a soft clip h / (1 + |h/ymax|^{p:.1f})^(1/{p:.1f}) of a unipolar sine 0 ... 100 V "
                 "with a slowly varying amplitude, 1.2 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(ymax=ymax, p=p)
    return rec


@case
def asymmetry_skewed_preisach_bursts(seed):
    rng = _rng(seed, 6)
    dt = 1 / 800
    v, drawn = _hann_bursts(dt, rng, 10)
    skew = rng.choice([-1.0, 1.0]) * rng.uniform(0.55, 0.8)
    W = 57.0
    alpha, beta = _skewed_relays(rng, 15_000, W, rng.uniform(11.0, 15.0), skew)
    y = 0.3 * v + 0.7 * W * _relay_plane(v, alpha, beta)
    rec = finish("holdout8_asymmetry_skewed_preisach_bursts", seed, np.arange(len(v)) * dt, v, y,
                 {"asymmetry"}, "either",
                 f"a Preisach plane with a linear (skew {skew:+.2f}) interaction-field density under "
                 "Hann-windowed tone bursts around drawn offsets, 800 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(skew=skew, alpha=alpha, beta=beta, bursts=drawn)
    return rec


@case
def delay_multisine_750hz(seed):
    rng = _rng(seed, 7)
    dt, n = 1 / 750, 30_000
    freqs = np.geomspace(0.3, 6.0, 8) * rng.uniform(0.93, 1.07, 8)
    v = _multisine(dt, n, freqs, rng, rng.uniform(44, 49))
    d = rng.uniform(1.5, 4.0)
    y = me.play_core(me.fractional_delay(v, d), 100.0)
    rec = finish("holdout8_delay_multisine_750hz", seed, np.arange(n) * dt, v, y, {"delay"}, "explained",
                 f"dead time {d:.2f} samples under a random-phase multisine (8 tones, 0.3 ... 6 Hz), "
                 "750 Hz", rng, monitor_noise=3e-4)
    rec.extra["delay_samples"] = d
    return rec


@case
def initial_state_one_sided_cycles_staircase(seed):
    rng = _rng(seed, 8)
    sign = rng.choice([-1.0, 1.0])
    pre = _one_sided_cycles(sign, rng.uniform(48, 58), rng.uniform(10, 20), 3)
    _, z = me.play_core(pre, 100.0, return_state=True)
    dt = 1 / 1500
    levels = np.concatenate([[0.0], rng.uniform(-40, 40, 24)])
    v = ex.staircase_holds(dt, levels, rng.uniform(0.5, 0.75), 0.04)
    y = me.play_core(v, 100.0, state=z)
    rec = finish("holdout8_initial_state_one_sided_cycles_staircase", seed, np.arange(len(v)) * dt, v, y,
                 {"initial_state"}, "explained",
                 "a core preloaded by three large one-sided cycles before a staircase of random levels, "
                 "1.5 kHz", rng, monitor_noise=3e-4)
    rec.extra["preload"] = pre
    return rec


# ---- two effects ----

@case
def pair_creep_clip_staircase_500hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 500
    signs = rng.choice([-1.0, 1.0]) * (-1.0) ** np.arange(14)            # alternating sides
    levels = signs * rng.uniform(8, 42, 14)
    levels[rng.choice(np.flatnonzero(signs > 0), 2, replace=False)] = rng.uniform(45, 48, 2)   # near the top
    levels = np.concatenate([[0.0], levels])
    v = ex.staircase_holds(dt, levels, rng.uniform(1.5, 2.2), 0.06)
    h = me.play_core(v, 100.0)
    c = rng.uniform(0.05, 0.08) * rng.dirichlet([3.0, 3.0])
    tau = [rng.uniform(0.2, 0.4), rng.uniform(2.0, 4.0)]
    x = h + me.kelvin_voigt_creep(h, dt, c, tau)
    level = x.max() - rng.uniform(0.05, 0.08) * np.ptp(x)
    y = me.clip(x, -np.inf, level)
    rec = finish("holdout8_pair_creep_clip_staircase_500hz", seed, np.arange(len(v)) * dt, v, y,
                 {"creep", "output_saturation"}, "either",
                 "two Kelvin-Voigt elements and a sensor range clipping the top, a staircase with holds "
                 "near the top, 500 Hz", rng, monitor_noise=4e-4)
    rec.extra.update(clip_level=level, compliances=c, time_constants=tau, holds=_hold_spans(v))
    return rec


# ---- out of vocabulary ----

@case
def oov_accommodation_constant_cycles(seed):
    rng = _rng(seed, 10)
    dt = 1 / 300
    f = rng.uniform(0.8, 1.2)
    amp = rng.uniform(44, 48)
    m = int(round(40 / f / dt))
    t = np.arange(m) * dt
    s = np.clip((f * t - 28.0) / 12.0, 0.0, 1.0)        # 28 constant cycles, then a decaying tail
    v = amp * (1 - 0.7 * s) * np.sin(2 * np.pi * f * t)
    growth = rng.uniform(0.5, 0.8)
    y = _accommodating_play(v, 100.0, growth, rng.uniform(3.0, 6.0), r_max_fraction=0.36)
    rec = finish("holdout8_oov_accommodation_constant_cycles", seed, t, v, y, set(), "unexplained",
                 f"accommodation: play thresholds growing by {growth:.0%} with the cycles driven, a "
                 "constant-amplitude sine then a decaying tail, 300 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(growth=growth, freq=f)
    return rec
