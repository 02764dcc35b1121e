"""Mechanisms and signals of the HOLDOUT15 set (``cases_holdout15.py``), each written from its law.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the
response; all are causal. The sources of the laws are beside each function and in ``cases_holdout15``'s docstring.
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.signal import bilinear, butter, lfilter, sosfilt

from . import mechanisms13 as _m13

#: the play sum with a linear part (the play operator's definition), shared with HOLDOUT13 and HOLDOUT14
plays = _m13.plays


# ---- the rate-independent core ----

def beta_plays(n, r_max, a, b, w0):
    """n thresholds evenly spaced in (0, r_max) with weights of a beta density (r / r_max)^(a - 1) (1 - r /
    r_max)^(b - 1) (Pearson's type I; a hump for a, b > 1, its mode at (a - 1) / (a + b - 2) of r_max), summing to
    1 - w0."""
    r = (np.arange(n) + 0.5) * r_max / n
    x = r / r_max
    dens = x ** (a - 1) * (1 - x) ** (b - 1)
    return r, (1 - w0) * dens / dens.sum()


# ---- signals ----

def raised_cosine(x):
    """0 for x <= 0, (1 - cos(pi x)) / 2 between, 1 for x >= 1."""
    x = np.clip(np.asarray(x, float), 0.0, 1.0)
    return (1 - np.cos(np.pi * x)) / 2


def lorenz_rhs(_, s, sigma=10.0, rho=28.0, beta=8.0 / 3.0):
    """The Lorenz system dx/dt = sigma (y - x), dy/dt = x (rho - z) - y, dz/dt = x y - beta z (Lorenz,
    "Deterministic nonperiodic flow", J. Atmos. Sci. 20 (1963) 130), at its classical chaotic parameters."""
    x, y, z = s
    return [sigma * (y - x), x * (rho - z) - y, x * y - beta * z]


def lorenz_path(dt, n, time_scale, start, settle=30.0):
    """The Lorenz state at n instants k dt of a clock running time_scale Lorenz time units per second, from `start`
    after `settle` units on the attractor (RK45, rtol 1e-10). Returns an (n, 3) array."""
    s0 = solve_ivp(lorenz_rhs, (0, settle), start, rtol=1e-10, atol=1e-10).y[:, -1]
    tl = np.arange(n) * dt * time_scale
    return solve_ivp(lorenz_rhs, (0, tl[-1]), s0, t_eval=tl, rtol=1e-10, atol=1e-10).y.T


def stress_dip_blocks(dt, levels, dips, load_s, dip_s, rest_s, edge_s, lead_s=0.5):
    """Stress-dip creep tests (Ahlquist & Nix, "The measurement of internal stresses during creep of Al and Al-Mg
    alloys", Acta Metall. 19 (1971) 373): block i steps to levels[i], holds load_s[i], dips to dips[i] levels[i]
    and holds dip_s[i], returns to 0 V and rests rest_s[i]; every change a raised-cosine step of edge_s, starting
    at the hold's end. Starts with lead_s at 0 V. Returns the path and each block's first sample."""
    me_ = max(int(round(edge_s / dt)), 1)
    parts, starts, pos, cur = [np.zeros(int(round(lead_s / dt)))], [], int(round(lead_s / dt)), 0.0
    for lv, q, a, b, c in zip(levels, dips, load_s, dip_s, rest_s):
        starts.append(pos)
        for target, hold in ((lv, a), (q * lv, b), (0.0, c)):
            m = int(round(hold / dt))
            seg = np.r_[cur + (target - cur) * raised_cosine(np.arange(1, me_ + 1) / me_), np.full(m - me_, target)]
            parts.append(seg)
            pos += len(seg)
            cur = target
    return np.concatenate(parts), np.array(starts)


def velocity_step_ramps(dt, ends, speeds_per_ramp, splits_per_ramp, hold_s):
    """Ramps from 0 V to ends[0], then ends[0] to ends[1], ...; ramp i runs at speeds_per_ramp[i][j] (V/s) between
    its split fractions splits_per_ramp[i] (a velocity-step test: Dieterich, "Modeling of rock friction 1.
    Experimental results and constitutive equations", J. Geophys. Res. 84 (1979) 2161), with a hold of hold_s at
    each end. Piecewise linear. Returns the path and the knots (times, values)."""
    kt, kv = [0.0], [0.0]
    for end, speeds, splits in zip(ends, speeds_per_ramp, splits_per_ramp):
        a = kv[-1]
        fr = np.r_[0.0, np.sort(splits), 1.0]
        for f0, f1, s in zip(fr[:-1], fr[1:], speeds):
            kt.append(kt[-1] + abs(end - a) * (f1 - f0) / s)
            kv.append(a + (end - a) * f1)
        kt.append(kt[-1] + hold_s)
        kv.append(end)
    kt, kv = np.array(kt), np.array(kv)
    t = np.arange(int(kt[-1] / dt) + 1) * dt
    return np.interp(t, kt, kv), kt, kv


def kanai_tajimi_filter(wg, zg, dt):
    """The Kanai-Tajimi ground filter H(s) = (wg^2 + 2 zg wg s) / (s^2 + 2 zg wg s + wg^2) (Kanai, Bull. Earthq.
    Res. Inst. 35 (1957) 309; Tajimi, Proc. 2nd World Conf. Earthq. Eng., 1960), discretised by the bilinear
    transform at the sampling rate 1 / dt. Returns (b, a) for lfilter."""
    return bilinear([2 * zg * wg, wg * wg], [1.0, 2 * zg * wg, wg * wg], fs=1 / dt)


def jennings_envelope(t, t1, t2, c):
    """The Jennings-Housner-Tsai envelope of strong ground motion: (t / t1)^2 up to t1, 1 to t2, exp(-c (t - t2))
    after (Jennings, Housner & Tsai, "Simulated earthquake motions", Caltech EERL report, 1968); 0 before 0."""
    t = np.asarray(t, float)
    return np.where(t < 0, 0.0, np.where(t < t1, (t / t1) ** 2, np.where(t < t2, 1.0, np.exp(-c * (t - t2)))))


def synthetic_quakes(dt, events, rng, f_cmd):
    """Displacement commands of a shake table: events (start, duration, peak, wg, zg, t1, t2, c) of white noise
    through the Kanai-Tajimi filter under a Jennings envelope, each scaled to its peak, then the table controller's
    2nd-order Butterworth command filter at f_cmd (causal, from rest). Returns the command and the unfiltered sum."""
    n = int(round(max(e[0] + e[1] for e in events) / dt)) + 1
    raw = np.zeros(n)
    for start, dur, peak, wg, zg, t1, t2, c in events:
        k0, m = int(round(start / dt)), int(round(dur / dt))
        b, a = kanai_tajimi_filter(wg, zg, dt)
        g = lfilter(b, a, rng.standard_normal(m)) * jennings_envelope(np.arange(m) * dt, t1, t2, c)
        raw[k0:k0 + m] += peak * g / np.abs(g).max()
    sos = butter(2, f_cmd, fs=1 / dt, output="sos")
    return sosfilt(sos, raw), raw


def iec_swept_sine(t, f0, f1, T, f_x, amp):
    """A logarithmic sine sweep from f0 to f1 over T (phase 2 pi f0 T (r^(t / T) - 1) / ln r, r = f1 / f0) at
    constant displacement amp below the crossover f_x and constant velocity (amp f_x / f) above it, the profile of
    the sinusoidal vibration test IEC 60068-2-6 (Test Fc). Starts at 0 V."""
    t = np.asarray(t, float)
    r = f1 / f0
    f = f0 * r ** (t / T)
    phase = 2 * np.pi * f0 * T * (r ** (t / T) - 1) / math.log(r)
    return amp * np.minimum(1.0, f_x / f) * np.sin(phase), f


def van_der_pol_path(dt, n, omega, mu0, mu1, start=(0.0, 2.0)):
    """x of the van der Pol oscillator x'' - mu (1 - x^2) x' + x = 0 (van der Pol, "On relaxation-oscillations",
    Phil. Mag. 2 (1926) 978) in a time running omega units per second, its damping mu swept linearly from mu0 to
    mu1 over the record: a near-sine that turns into a relaxation oscillation (RK45, rtol 1e-10)."""
    T = (n - 1) * dt

    def rhs(tt, s):
        mu = mu0 + (mu1 - mu0) * tt / T
        return [omega * s[1], omega * (mu * (1 - s[0] ** 2) * s[1] - s[0])]
    t = np.arange(n) * dt
    return solve_ivp(rhs, (0, T), list(start), t_eval=t, rtol=1e-10, atol=1e-10, max_step=0.02).y[0]


def weierstrass_mandelbrot(t, f0, gamma, D, phases):
    """The Weierstrass-Mandelbrot profile sum_n gamma^(-(2 - D) n) cos(2 pi f0 gamma^n t + phi_n) (Berry & Lewis,
    "On the Weierstrass-Mandelbrot fractal function", Proc. R. Soc. Lond. A 370 (1980) 459; a rough surface of
    fractal dimension D, Majumdar & Bhushan, J. Tribol. 112 (1990) 205), as the z command of a probe tracking it
    along a line at constant speed."""
    t = np.asarray(t, float)[:, None]
    k = np.arange(len(phases))
    return (gamma ** (-(2 - D) * k) * np.cos(2 * np.pi * f0 * gamma ** k * t + np.asarray(phases))).sum(axis=1)


def second_order_step(t, delta, zeta, wn):
    """The step response of an underdamped 2nd-order loop to a step of delta: delta (1 - exp(-zeta wn t) (cos
    wd t + zeta / sqrt(1 - zeta^2) sin wd t)), wd = wn sqrt(1 - zeta^2) (Ogata, *Modern Control Engineering*, 2010,
    sec. 5-3); 0 before 0. Its extrema are delta (1 - (-OS)^k) at t = k pi / wd, OS = exp(-zeta pi / sqrt(1 -
    zeta^2))."""
    t = np.asarray(t, float)
    wd = wn * math.sqrt(1 - zeta * zeta)
    tp = np.clip(t, 0.0, None)
    s = delta * (1 - np.exp(-zeta * wn * tp) * (np.cos(wd * tp) + zeta / math.sqrt(1 - zeta * zeta) * np.sin(wd * tp)))
    return np.where(t < 0, 0.0, s)


def servo_history(dt, set_points, zeta, wn, settle_s):
    """A closed-loop servo's path through set points from rest at 0 V: each step an underdamped 2nd-order
    response (:func:`second_order_step`) held settle_s, long enough for the ringing to die out."""
    m = int(round(settle_s / dt))
    t = np.arange(m) * dt
    out, cur = [np.zeros(1)], 0.0
    for sp in set_points:
        out.append(cur + second_order_step(t + dt, sp - cur, zeta, wn))
        cur = sp
    return np.concatenate(out)


def zvd_shaped_steps(t, step_times, levels, period, tau):
    """Point-to-point steps through `levels` (from 0 V) at step_times, each convolved with the zero-vibration-
    derivative input shaper (impulses 1/4, 1/2, 1/4 at 0, period / 2 and period: Singer & Seering, "Preshaping
    command inputs to reduce system vibration", J. Dyn. Syst. Meas. Control 112 (1990) 76) and passed through the
    amplifier's first-order lag tau (exact: each sub-step rises as 1 - exp(-t / tau))."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    prev = 0.0
    for ts, lv in zip(step_times, levels):
        for a, d in ((0.25, 0.0), (0.5, period / 2), (0.25, period)):
            u = t - ts - d
            out += a * (lv - prev) * np.where(u > 0, 1 - np.exp(-np.clip(u, 0, None) / tau), 0.0)
        prev = lv
    return out


def apsk_sine(dt, f_c, cycles, amps, signs):
    """An amplitude-and-phase-shift-keyed sine: symbol i is `cycles` whole carrier periods of amps[i] signs[i]
    sin(2 pi f_c t) (a phase of 0 or pi), so every symbol starts and ends at 0 V (Proakis, *Digital
    Communications*, 2001, ch. 4: APSK). Returns the path and each symbol's first sample."""
    m = int(round(cycles / (f_c * dt)))
    base = np.sin(2 * np.pi * np.arange(m) / m * cycles)
    parts = [a * s * base for a, s in zip(amps, signs)]
    return np.concatenate(parts + [np.zeros(1)]), np.arange(len(amps)) * m


def hilbert_points(order):
    """The cells of the Hilbert curve of the given order in visiting order (Hilbert, "Ueber die stetige Abbildung
    einer Linie auf ein Flaechenstueck", Math. Ann. 38 (1891) 459): the index d -> (x, y) by the quadrant recursion,
    from (0, 0) to (2^order - 1, 0), neighbouring cells one step apart."""
    n = 2 ** order
    pts = []
    for d in range(n * n):
        x = y = 0
        t = d
        s = 1
        while s < n:
            rx = 1 & (t // 2)
            ry = 1 & (t ^ rx)
            if ry == 0:
                if rx == 1:
                    x, y = s - 1 - x, s - 1 - y
                x, y = y, x
            x += s * rx
            y += s * ry
            t //= 4
            s *= 2
        pts.append((x, y))
    return np.array(pts)


def hilbert_scan_axis(dt, order, axis, top, unit_s):
    """One axis of a scan along the Hilbert curve at constant speed (one cell per unit_s), scaled to 0 ... top:
    piecewise-linear moves of equal length and holds while the other axis moves (space-filling non-raster scans of
    probe microscopes). Returns the path and the cells' coordinates on that axis."""
    c = hilbert_points(order)[:, axis].astype(float) * top / (2 ** order - 1)
    kt = np.arange(len(c)) * unit_s
    t = np.arange(int(kt[-1] / dt) + 1) * dt
    return np.interp(t, kt, c), c


# ---- mechanisms ----

def burgers_creep(u, dt, c_k, tau_k, c_m, tau_m):
    """Creep of a Burgers body (a Maxwell element in series with a Kelvin element: Burgers, in *First Report on
    Viscosity and Plasticity*, Amsterdam, 1935; Findley, Lai & Onaran, *Creep and Relaxation of Nonlinear
    Viscoelastic Materials*, 1976, ch. 5): the Kelvin strain relaxes toward c_k u with tau_k, the Maxwell dashpot
    flows at c_m u / tau_m for as long as the load lasts (no bound: under a held load the output creeps on
    linearly). Exact per sample with u held; the output at sample k is the state before the k-th update. Returns the
    Kelvin and the Maxwell parts."""
    u = np.asarray(u, float)
    a = math.exp(-dt / tau_k)
    ek, em = c_k * u[0], 0.0
    out_k, out_m = np.empty_like(u), np.empty_like(u)
    for k, uk in enumerate(u.tolist()):
        out_k[k], out_m[k] = ek, em
        ek = c_k * uk + (ek - c_k * uk) * a
        em += c_m * uk * dt / tau_m
    return out_k, out_m


def squeeze_tau(y, tau0, gap):
    """The stage's time constant between two squeeze films: a plate between two fixed plates, each gap gap -+ y; the
    Reynolds-equation damping of a plate of radius R at the gap g, 3 pi mu R^4 / (2 g^3) (Langlois, Q. Appl. Math. 20
    (1962) 131; Bao & Yang, "Squeeze film air damping in MEMS", Sens. Actuators A 136 (2007) 3), summed over both
    films and divided by the flexure's stiffness: tau0 ((gap / (gap - y))^3 + (gap / (gap + y))^3) / 2."""
    return tau0 * ((gap / (gap - y)) ** 3 + (gap / (gap + y)) ** 3) / 2


def squeeze_film_stage(h, dt, tau0, gap, sub=4):
    """A stage pulled by the core's output h through a flexure and damped by squeeze films: dy/dt = (h - y) /
    tau(y) (:func:`squeeze_tau`), h linear between samples, classical Runge-Kutta on `sub` steps per sample; at rest
    at h[0]. The lag grows toward either end of the stroke, where a film thins."""
    h = np.asarray(h, float).tolist()
    hs = dt / sub
    y = h[0]
    out = np.empty(len(h))
    out[0] = y

    def f(yy, hh):
        return (hh - yy) / squeeze_tau(yy, tau0, gap)
    for k in range(1, len(h)):
        h0, dh = h[k - 1], (h[k] - h[k - 1]) / sub
        for j in range(sub):
            ha, hm, hb = h0 + dh * j, h0 + dh * (j + 0.5), h0 + dh * (j + 1)
            k1 = f(y, ha)
            k2 = f(y + 0.5 * hs * k1, hm)
            k3 = f(y + 0.5 * hs * k2, hm)
            k4 = f(y + hs * k3, hb)
            y += hs * (k1 + 2 * k2 + 2 * k3 + k4) / 6
        out[k] = y
    return out


def tremblay_voltage(x, e0, k, a, b):
    """The cell voltage after a fraction x of its capacity has been drawn at constant current, Shepherd's discharge
    law in Tremblay's form: e0 - k x / (1 - x) + a exp(-b x) (the polarisation term K Q it / (Q - it) and the
    exponential zone; the ohmic drop folded into e0; Shepherd, J. Electrochem. Soc. 112 (1965) 657; Tremblay,
    Dessaint & Dekkiche, IEEE Vehicle Power and Propulsion Conf., 2007): flat, then falling faster and faster toward
    the end of the discharge."""
    x = np.asarray(x, float)
    return e0 - k * x / (1 - x) + a * np.exp(-b * x)


def quarter_bridge(x, w_per_unit, q):
    """A semiconductor strain gauge in a quarter Wheatstone bridge read in the core's units: the gauge's relative
    change u = w + q w^2, w = w_per_unit x (Mason, Forst & Tornillo, "Recent developments in semiconductor strain
    transducers", ISA Proc. 1962: p-type silicon, about 120 eps + 4000 eps^2, q = 0.28), the bridge's output u / (4
    + 2 u) of its excitation (Hoffmann, *An Introduction to Measurements using Strain Gages*, 1989, ch. 7), scaled
    to slope 1 at rest: 4 u / ((4 + 2 u) w_per_unit)."""
    w = w_per_unit * np.asarray(x, float)
    u = w + q * w * w
    return 4 * u / ((4 + 2 * u) * w_per_unit)


def hertz_stops(x, gap, kappa, iters=80):
    """A stage between two compliant end stops: free travel within +-gap, beyond it the stop's Hertzian force
    K delta^(3/2) (Hertz 1882; Johnson, *Contact Mechanics*, 1985, sec. 4.2) balances the flexure's k (x - y), so y +
    kappa sign(y) (|y| - gap)_+^(3/2) = x (kappa = K / k), solved by bisection (the left side is increasing in y, and
    |y| <= |x|)."""
    x = np.asarray(x, float)
    lo, hi = np.minimum(x, 0.0), np.maximum(x, 0.0)
    for _ in range(iters):
        mid = (lo + hi) / 2
        g = mid + kappa * np.sign(mid) * np.clip(np.abs(mid) - gap, 0, None) ** 1.5 - x
        lo, hi = np.where(g < 0, mid, lo), np.where(g < 0, hi, mid)
    return (lo + hi) / 2


def camera_samples(t_fine, h_fine, t_frames, latency, row, exposure, dt):
    """The frames of a rolling-shutter camera tracking the stage: frame k, delivered at t_k, is the mean of the
    position over its exposure [t_k - (latency + row) dt - exposure dt, t_k - (latency + row) dt] (the row is read
    `row` of a frame after the first; the frame arrives `latency` frames after its readout; Liang, Chang & Chen,
    IEEE Trans. Image Process. 17 (2008) 1323 for the rolling shutter), integrated exactly for h linear between the
    fine instants (its integral from the first instant is piecewise quadratic: a cumulative trapezoid to the last
    instant before, and the part of the interval beyond it). Returns the frames."""
    t_fine, h_fine = np.asarray(t_fine, float), np.asarray(h_fine, float)
    c = np.r_[0.0, np.cumsum((h_fine[1:] + h_fine[:-1]) / 2 * np.diff(t_fine))]

    def integral(tt):
        i = np.clip(np.searchsorted(t_fine, tt, side="right") - 1, 0, len(t_fine) - 2)
        step = t_fine[i + 1] - t_fine[i]
        u = tt - t_fine[i]
        return c[i] + h_fine[i] * u + (h_fine[i + 1] - h_fine[i]) * u * u / (2 * step)
    b = np.asarray(t_frames, float) - (latency + row) * dt
    a = b - exposure * dt
    return (integral(b) - integral(a)) / (b - a)


def hybrid_charge_drive(h, v, dt, f_c, k_q):
    """A DC-stabilised charge drive (Fleming, "Charge drive with active DC stabilization for linearization of
    piezoelectric hysteresis", IEEE Trans. Ultrason. Ferroelectr. Freq. Control 60 (2013) 1630) in its
    complementary-filter form: below the crossover f_c the stack is voltage driven (the displacement is the core's
    output h of the command), above it charge driven (the displacement proportional to the command, k_q v): y =
    LP[h] + k_q (v - LP[v]), LP the first-order low-pass at f_c (exact for inputs linear between samples). The
    hysteresis fades out of the fast parts of the record."""
    a = math.exp(-2 * math.pi * f_c * dt)

    def lp(x):
        x = np.asarray(x, float)
        out = np.empty_like(x)
        s = x[0]
        g = (1 - a) / (2 * math.pi * f_c * dt)           # the ramp-invariant weights of a first-order lag
        c0, c1 = 1 - g, g - a
        out[0] = s
        xs = x.tolist()
        for k in range(1, len(xs)):
            s = a * s + c1 * xs[k - 1] + c0 * xs[k]
            out[k] = s
        return out
    return lp(h) + k_q * (np.asarray(v, float) - lp(v))


def magnet_axial_field(z, radius, length):
    """The axial field of a cylindrical permanent magnet at a distance z from its face, in units of its remanence:
    ((length + z) / sqrt(radius^2 + (length + z)^2) - z / sqrt(radius^2 + z^2)) / 2 (the field of its equivalent
    surface current; e.g. Camacho & Sosa, Rev. Mex. Fis. E 59 (2013) 8)."""
    z = np.asarray(z, float)
    return ((length + z) / np.sqrt(radius ** 2 + (length + z) ** 2) - z / np.sqrt(radius ** 2 + z ** 2)) / 2


def hall_sensor(x, d0, radius, length):
    """A Hall element on the axis of a magnet carried by the stage, d0 from its face at rest, the magnet approaching
    by x: the field change, scaled to slope 1 at rest (steeper as the gap closes: convex, asymmetric)."""
    eps = 1e-6 * d0
    slope = (magnet_axial_field(d0 - eps, radius, length) - magnet_axial_field(d0 + eps, radius, length)) / (2 * eps)
    return (magnet_axial_field(d0 - np.asarray(x, float), radius, length) - magnet_axial_field(d0, radius, length)) \
        / slope


def stick_slip(x, s, f_k, y0=0.0):
    """A carriage on a friction guide pulled through a stiff flexure by the core's travel x, with static friction
    above the kinetic (Rabinowicz, *Friction and Wear of Materials*, 1965, ch. 4; Bowden & Tabor, 1950), in units of
    travel: s = F_s / k, f_k = F_k / k (s / 2 < f_k < s). The carriage sticks while |x - y| < s; once x - y reaches
    sigma s it slips and, the flexure's natural frequency far above the sampling rate, comes to rest half a
    period later at x - sigma (2 f_k - s): a jump of 2 sigma (s - f_k) (repeated within a sample if x has run on).
    Returns y."""
    out = np.empty(len(x))
    y = float(y0)
    jump = 2 * (s - f_k)
    for k, xk in enumerate(np.asarray(x, float).tolist()):
        while xk - y >= s:
            y += jump
        while y - xk >= s:
            y -= jump
        out[k] = y
    return out
