"""Physical mechanisms for realistic test records, written independently of hystcomp.

Nothing here imports hystcomp: each mechanism is written from its physics so that a
detector tuned on hystcomp's own model parts cannot pass these records by construction.
Every function takes the drive signal and returns the response; all are causal.

Sources
-------
- Continuous-density play core: M. Brokate, J. Sprekels, *Hysteresis and Phase
  Transitions*, Springer 1996, ch. 2 (the play as a rate-independent operator); here a
  200-element Riemann sum of a smooth density, not the library's 20-element model.
- Preisach relay plane: I. D. Mayergoyz, *Mathematical Models of Hysteresis*, 1991, ch. 1.
- Viscoplastic (overstress) play: P. Perzyna, "Fundamental problems in viscoplasticity",
  Adv. Appl. Mech. 9 (1966): the yield excess drives the internal variable at a finite rate.
- Bouc-Wen with a mechanical stage: M. Goldfarb, N. Celanovic, "Modeling piezoelectric stack
  actuators for control of micromanipulation", IEEE Control Syst. Mag. 17 (1997), and
  T. S. Low, W. Guo, J. Microelectromech. Syst. 4 (1995): m x'' + c x' + k x = k (d v - h).
- Kelvin-Voigt creep chain: a generalized Kelvin-Voigt body (springs and dashpots in parallel,
  elements in series), e.g. W. N. Findley et al., *Creep and Relaxation of Nonlinear
  Viscoelastic Materials*, 1976, ch. 5.
- Logarithmic creep: H. Jung, D.-G. Gweon, Rev. Sci. Instrum. 71 (2000) 3436:
  y(t) = y(t0) (1 + gamma log10(t / t0)) after a step.
"""

import numpy as np

__all__ = [
    "play_core", "preisach_core", "viscoplastic_core", "bouc_wen_stage",
    "kelvin_voigt_creep", "log_creep", "thermal_offset", "thermal_gain", "clip",
    "fractional_delay", "butterfly", "flag_core", "asymmetric_play_core",
]


def _density_thresholds(span, n=200, decay=0.6, r_max_fraction=0.9):
    """Thresholds and weights of a smooth decreasing density p(r) = exp(-decay r / R)."""
    R = r_max_fraction * span / 2.0
    r = (np.arange(n) + 0.5) * (R / n)
    w = np.exp(-decay * r / R * 3.0) * (R / n)
    return r, w


def play_core(v, span, gain=1.0, n=200, decay=0.6, state=None, return_state=False):
    """Rate-independent hysteresis: a linear term plus a continuous density of plays.

    ``y = gain * (0.35 v + sum_k w_k F_{r_k}[v])`` with 200 thresholds up to 0.45 span.
    ``state`` (play positions) defaults to the virgin state (all plays at v[0] clipped
    to 0, i.e. demagnetised). Returns y (and the final state).
    """
    v = np.asarray(v, float)
    r, w = _density_thresholds(span, n, decay)
    w = w / w.sum()
    z = np.zeros_like(r) if state is None else np.array(state, float)
    y = np.empty_like(v)
    for k, vk in enumerate(v):
        z = np.minimum(np.maximum(z, vk - r), vk + r)
        y[k] = 0.35 * vk + 0.65 * (w @ z)
    y *= gain
    return (y, z) if return_state else y


def preisach_core(v, lo, hi, n=48, interaction=0.0, width=0.25, state=None):
    """Preisach model on an n x n relay half-plane (alpha >= beta) over [lo, hi].

    Density: Gaussian in the loop half-width (alpha - beta)/2 with scale ``width`` x
    range, times a Gaussian in the interaction field (alpha + beta)/2 centred at
    ``interaction`` x range from the middle. A non-zero ``interaction`` makes the loops
    asymmetric (not representable by any PI model). Starts demagnetised (relays with
    alpha + beta > 2 * middle down, others up) unless ``state`` is given.
    """
    v = np.asarray(v, float)
    edges = np.linspace(lo, hi, n + 1)
    c = 0.5 * (edges[1:] + edges[:-1])
    A, B = np.meshgrid(c, c, indexing="ij")
    keep = A >= B
    a, b = A[keep], B[keep]
    rng = hi - lo
    mid = 0.5 * (lo + hi)
    half = (a - b) / 2 / rng
    field = ((a + b) / 2 - mid) / rng
    mu = np.exp(-(half / width) ** 2) * np.exp(-((field - interaction) / 0.25) ** 2)
    mu /= mu.sum()
    s = np.where(a + b > 2 * mid, -1.0, 1.0) if state is None else np.array(state, float)
    y = np.empty_like(v)
    for k, vk in enumerate(v):
        s[a <= vk] = 1.0
        s[b >= vk] = -1.0
        y[k] = mu @ s
    return y * rng / 2 + mid


def viscoplastic_core(v, dt, span, eta, n=60):
    """Plays whose internal variable moves at a finite rate (Perzyna overstress).

    dz/dt = sign(v - z) max(|v - z| - r, 0) / eta, integrated exactly per sample for a
    piecewise-constant input. eta -> 0 gives the rate-independent play. Fast inputs see
    wider loops (the internal variable lags further behind).
    """
    v = np.asarray(v, float)
    r, w = _density_thresholds(span, n)
    w = w / w.sum()
    z = np.zeros_like(r)
    y = np.empty_like(v)
    decay = np.exp(-dt / eta)
    for k, vk in enumerate(v):
        # the overstress e = v - z - r*sign decays exponentially while outside the band
        up = vk - r
        dn = vk + r
        zu = up + (z - up) * decay
        zd = dn + (z - dn) * decay
        z = np.where(z < up, zu, np.where(z > dn, zd, z))
        y[k] = 0.35 * vk + 0.65 * (w @ z)
    return y


def bouc_wen_stage(v, dt, d=1.0, alpha=0.4, beta=0.9, gamma=0.1, n_exp=1.0, fn=60.0,
                   zeta=0.3, substeps=4):
    """Bouc-Wen hysteresis h driving a second-order stage (Goldfarb-Celanovic form).

    dh/dt = alpha d dv/dt - beta |dv/dt| |h|^(n-1) h - gamma dv/dt |h|^n (h in input units),
    x'' + 2 zeta wn x' + wn^2 x = wn^2 (d v - h); RK4 on a linearly interpolated input.
    The stage makes the loop rate dependent (phase lag growing with frequency).
    A sample whose input rate would make the stiff term ``beta |dv/dt| h`` unstable for RK4
    with `substeps` (``beta |dv/dt| dt / substeps > 1``) is integrated with as many substeps
    as keep that product at 0.5 (a fast input step; without it the state diverged).
    """
    v = np.asarray(v, float)
    wn = 2 * np.pi * fn
    h = 0.0
    x = d * v[0]
    xd = 0.0
    out = np.empty_like(v)

    def f(state, vk, dvk):
        h_, x_, xd_ = state
        dh = alpha * d * dvk - beta * abs(dvk) * abs(h_) ** (n_exp - 1) * h_ - gamma * dvk * abs(h_) ** n_exp
        xdd = wn ** 2 * (d * vk - h_ - x_) - 2 * zeta * wn * xd_
        return np.array([dh, xd_, xdd])

    st = np.array([h, x, xd])
    out[0] = x
    for k in range(1, len(v)):
        v0, v1 = v[k - 1], v[k]
        slope = (v1 - v0) / dt
        m = substeps
        if beta * abs(slope) * dt / substeps > 1.0:
            m = int(np.ceil(beta * abs(slope) * dt / 0.5))
        hs = dt / m
        for j in range(m):
            s0 = v0 + slope * j * hs
            sm = s0 + slope * hs / 2
            s1 = s0 + slope * hs
            k1 = f(st, s0, slope)
            k2 = f(st + hs / 2 * k1, sm, slope)
            k3 = f(st + hs / 2 * k2, sm, slope)
            k4 = f(st + hs * k3, s1, slope)
            st = st + hs / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        out[k] = st[1]
    return out


def kelvin_voigt_creep(u, dt, compliances, time_constants):
    """Creep strain of Kelvin-Voigt elements in series driven by the load u.

    Element k: tau_k de_k/dt = c_k u - e_k (exact discretisation for a zero-order-hold
    load). Returns sum_k e_k, starting relaxed (e_k = 0).
    """
    u = np.asarray(u, float)
    c = np.asarray(compliances, float)
    tau = np.asarray(time_constants, float)
    a = np.exp(-dt / tau)
    e = np.zeros_like(c)
    out = np.empty_like(u)
    for k, uk in enumerate(u):
        out[k] = e.sum()
        e = a * e + (1 - a) * c * uk
    return out


def log_creep(u, dt, gamma, t0=0.05):
    """Logarithmic creep after each step of a staircase load (Jung & Gweon 2000).

    Each change of the load by du adds du * gamma * log10(1 + (t - t_step) / t0): a
    superposition of logarithmic relaxations, causal and unbounded (slowly) in time.
    """
    u = np.asarray(u, float)
    t = np.arange(len(u)) * dt
    du = np.diff(u, prepend=u[0])
    steps = np.flatnonzero(np.abs(du) > 1e-9 * (np.ptp(u) + 1e-300))
    out = np.zeros_like(u)
    for s in steps:
        out[s:] += du[s] * gamma * np.log10(1 + (t[s:] - t[s]) / t0)
    return out


def thermal_offset(t, amplitude, tau):
    """Offset of a warming stage: amplitude (1 - exp(-t/tau)) plus a slow 0.3x ripple."""
    t = np.asarray(t, float)
    T = t[-1] if t[-1] > 0 else 1.0
    return amplitude * (1 - np.exp(-t / tau)) + 0.3 * amplitude * np.sin(2 * np.pi * t / (1.7 * T))


def thermal_gain(t, relative_change, tau):
    """Gain factor of a warming actuator: 1 + relative_change (1 - exp(-t / tau))."""
    t = np.asarray(t, float)
    return 1 + relative_change * (1 - np.exp(-t / tau))


def clip(y, lo, hi):
    """A sensor or amplifier that saturates hard at [lo, hi]."""
    return np.clip(y, lo, hi)


def fractional_delay(v, delay_samples):
    """v delayed by a fractional number of samples (linear interpolation, held at start)."""
    v = np.asarray(v, float)
    k = np.arange(len(v)) - delay_samples
    return np.interp(k, np.arange(len(v)), v, left=v[0])


def low_passed_rate(v, dt, tau):
    """dv/dt (central differences) through a first-order low-pass of time constant tau:
    an eddy-current field of a laminated core is proportional to it (Bertotti 1998, ch. 12)."""
    dv = np.gradient(np.asarray(v, float), dt)
    a = np.exp(-dt / tau)
    out = np.empty_like(dv)
    acc = 0.0
    for k, x in enumerate(dv):
        acc = a * acc + (1 - a) * x
        out[k] = acc
    return out


def butterfly(p, scale):
    """Strain of a ferroelectric: proportional to the square of the polarisation p.

    Non-monotone in the drive: no Prandtl-Ishlinskii-type model represents it.
    """
    return scale * np.asarray(p, float) ** 2


def flag_core(v, span, bias_fraction=0.35, r_fraction=0.08):
    """Flag-shaped (double) hysteresis, as of superelastic shape-memory alloys.

    Two narrow play families centred at +-bias: loops open only away from the origin,
    pinched to a line through it. Not representable by a PI model (whose loops open
    from any reversal point).
    """
    v = np.asarray(v, float)
    b = bias_fraction * span / 2
    r = r_fraction * span / 2
    zp = 0.0
    zm = 0.0
    y = np.empty_like(v)
    for k, vk in enumerate(v):
        xp = max(vk - b, 0.0)
        xm = min(vk + b, 0.0)
        zp = min(max(zp, xp - r), xp + r)
        zm = min(max(zm, xm - r), xm + r)
        y[k] = 0.2 * vk + 1.5 * (max(zp, 0.0) + min(zm, 0.0))
    return y


def asymmetric_play_core(v, span, skew, n=200, state=None, return_state=False):
    """Plays whose threshold grows with the input level: r(v) = r (1 + skew v / (span/2)).

    The loop's width differs between the top and the bottom of the stroke (asymmetric hysteresis,
    as the GPI of Al Janaideh et al. describes with different rising and falling envelopes).
    Note that a constant difference between rising and falling thresholds would NOT do: a
    play is shift-equivariant, F_r[v - c] = F_r[v] - c, so that is only an offset.
    ``skew = 0`` is :func:`play_core`; thresholds are kept >= 0.1 r.
    """
    v = np.asarray(v, float)
    r, w = _density_thresholds(span, n)
    w = w / w.sum()
    z = np.zeros_like(r) if state is None else np.array(state, float)
    y = np.empty_like(v)
    for k, vk in enumerate(v):
        rk = r * max(1 + skew * vk / (span / 2), 0.1)
        z = np.minimum(np.maximum(z, vk - rk), vk + rk)
        y[k] = 0.35 * vk + 0.65 * (w @ z)
    return (y, z) if return_state else y


def langevin(x):
    """L(x) = coth x - 1/x: paramagnetic saturation, approaching 1 as 1 - 1/x (x/3 near 0)."""
    x = np.asarray(x, float)
    out = x / 3.0
    big = np.abs(x) >= 1e-4
    out[big] = 1.0 / np.tanh(x[big]) - 1.0 / x[big]
    return out
