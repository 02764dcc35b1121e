"""Model parts with time (:mod:`hystcomp.identify.parts`): dead time and lags
before the hysteresis, lags, resonance and gain drift after it, creep and
output bends (the offset drifts are in :mod:`~hystcomp.identify.parts_drift`).
"""

import math

import numpy as np

from ..effects import LinearStage, lag_bank
from ._part_kernels import drifting_delay, fractional_delay, slew_limit
from .part_base import Context, Parameter, Part, creep_time_range, register  # noqa: F401 (Context: the examples)

__all__ = ["Delay", "DriftingDelay", "InputLag", "SlewLimit", "OutputLag", "OutputResonance", "GainDrift", "SlowGainDrift", "Creep", "BackCreep", "RateTerm",
           "OutputQuadratic", "OutputCubic", "OutputHinge"]


# ----------------------------------------------------------------------------
# input side
# ----------------------------------------------------------------------------
@register
class Delay(Part):
    """Dead time before the hysteresis, in fractional samples (cubic Lagrange
    interpolation between samples, which keeps the input's shape: linear
    interpolation would also low-pass it, by up to 1.2 % at 0.05 cycles a
    sample): ``x(t - delay)``.

    Examples
    --------
    >>> ctx = Context(np.arange(5.0), 1.0, 0.0, 1.0, 5.0)
    >>> Delay().transform(ctx.x, {"delay": 1.5}, ctx).tolist()
    [0.0, 0.0, 0.4375, 1.5, 2.5]
    """

    effect = "delay"
    kind = "delay"
    slot = "input"
    order = 10
    needs_time = True
    description = "dead time before the hysteresis"
    #: a dead time shifts the input without changing its shape: named before a
    #: lag that fits as well with as many parameters (at low frequency
    #: e^(-s T) and 1 / (1 + s T) agree to first order, and a lag that stands
    #: in for a dead time fits no better; a real lag fits clearly better than
    #: a dead time on the realistic sets: 0.15 ... 450 noise variances)
    occam_rank = 0

    def _max(self, ctx):
        return float(min(max(20.0, 0.002 * ctx.n), 0.05 * ctx.n))

    def _reach(self, ctx):
        """Wider bounds ``(0, samples)`` the search moves on to when the best
        dead time ends at the first bound (:class:`Parameter`'s ``reach``):
        up to the longest lag tried (``max(50 dt, min(0.5 s, T/20))``, the
        upper bound of :class:`OutputLag`'s time constant) and at most 5 % of
        the record.  A drive's output buffer, a camera's frame pipeline or a
        water line's transport delay can hold 0.1-0.2 s; 0.2 % of a record of
        30,000 samples at 577 Hz is 0.1 s.  None when no wider."""
        if ctx.dt is None:
            return None
        hi = float(min(_lag_bounds(ctx)[1] / ctx.dt, 0.05 * ctx.n))
        return (0.0, hi) if hi > self._max(ctx) else None

    def parameters(self, ctx, kinds):
        return [Parameter("delay", 1.0, 0.0, self._max(ctx), False, self._reach(ctx))]

    def initial_values(self, ctx, kinds):
        return [{"delay": d} for d in np.geomspace(0.5, self._max(ctx), 5)]

    def transform(self, x, values, ctx):
        out = np.empty_like(x)
        fractional_delay(np.ascontiguousarray(x), float(values["delay"]), out)
        return out

    def describe(self, values):
        return {"part": self.description, "delay_samples": float(f"{values['delay']:.4g}")}


@register
class DriftingDelay(Delay):
    """A dead time that changes linearly along the record, from ``delay`` samples
    at the first sample to ``delay_end`` at the last (fractional samples, cubic
    Lagrange interpolation): a sensor recorded on its own clock, which runs fast or slow
    against the drive's by a frequency offset ``eps`` (crystal tolerances are
    1e-5 ... 1e-3), so the two drift apart by ``eps`` samples a sample (the
    reason for IEEE 1588 time synchronisation).  Parameters: ``delay``,
    ``delay_end`` [samples].

    Examples
    --------
    >>> ctx = Context(np.arange(5.0), 1.0, 0.0, 1.0, 5.0)
    >>> DriftingDelay().transform(ctx.x, {"delay": 0.0, "delay_end": 2.0}, ctx).tolist()
    [0.0, 0.4375, 1.0, 1.5, 2.0]
    """

    kind = "delay_drift"
    description = "dead time drifting linearly along the record (unsynchronised clocks)"
    occam_rank = 1

    def parameters(self, ctx, kinds):
        return [Parameter("delay", 1.0, 0.0, self._max(ctx), False, self._reach(ctx)),
                Parameter("delay_end", 1.0, 0.0, self._max(ctx), False, self._reach(ctx))]

    def initial_values(self, ctx, kinds):
        hi = self._max(ctx)
        return [{"delay": a, "delay_end": min(f * a, hi)} for a in np.geomspace(0.5, hi, 4) for f in (0.5, 1.0, 2.0)]

    def transform(self, x, values, ctx):
        out = np.empty_like(x)
        drifting_delay(np.ascontiguousarray(x), float(values["delay"]), float(values["delay_end"]), out)
        return out

    def describe(self, values):
        return {"part": self.description, "delay_samples": float(f"{values['delay']:.4g}"),
                "delay_end_samples": float(f"{values['delay_end']:.4g}")}


def _lag_bounds(ctx):
    lo = 0.3 * ctx.dt
    hi = max(50 * ctx.dt, min(0.5, ctx.duration / 20))
    return lo, hi


class _Lag(Part):
    """A first-order lag's time constant [s] (the one nonlinear parameter of
    :class:`InputLag` and :class:`OutputLag`), from 0.3 dt to
    ``max(50 dt, min(0.5 s, T/20))``."""

    def parameters(self, ctx, kinds):
        lo, hi = _lag_bounds(ctx)
        return [Parameter("time_constant", 3 * ctx.dt, lo, hi, True)]

    def initial_values(self, ctx, kinds):
        lo, hi = _lag_bounds(ctx)
        return [{"time_constant": t} for t in np.geomspace(lo * 2, hi, 5)]


@register
class InputLag(_Lag):
    """A first-order lag before the hysteresis (time constant [s]).

    Examples
    --------
    >>> ctx = Context(np.ones(3), 1.0, 0.0, 1.0, 3.0)
    >>> np.round(InputLag().transform(ctx.x, {"time_constant": 1.0}, ctx), 3).tolist()
    [1.0, 1.0, 1.0]
    """

    effect = "rate_dependence"
    kind = "input_lag"
    slot = "input"
    order = 20
    needs_time = True
    description = "first-order lag before the hysteresis"

    def transform(self, x, values, ctx):
        # at rest at the first sample (the record starts in a steady state)
        return lag_bank(x, [values["time_constant"]], ctx.dt, state=[x[0]])[0][:, 0].copy()


@register
class SlewLimit(Part):
    """A slew-rate limit before the hysteresis: the actuator's input follows
    the recorded command at most ``S`` per second, ``u[k] = u[k-1] +
    clip(v[k] - u[k-1], -S dt, S dt)`` from ``u[0] = v[0]``.  A piezo
    amplifier whose output current is limited charges the stack's
    capacitance ``C`` at most at ``S = I_max / C`` (Fleming & Leang, *Design,
    Modeling and Control of Nanopositioning Systems*, 2014, ch. 13): fast or
    large commands fall behind and are cut to triangles, slow ones pass
    unchanged, so the loop widens with rate and amplitude together, unlike
    a linear lag's.  Parameter: ``relative_slew_rate``, ``S`` over the
    record's largest input rate (0.02 ... 1; at 1 nothing is limited).

    Examples
    --------
    >>> ctx = Context(np.array([0.0, 1.0, 1.0, 1.0, 0.0]), 1.0, 0.0, 1.0, 5.0)
    >>> SlewLimit().transform(ctx.x, {"relative_slew_rate": 0.4}, ctx).round(6).tolist()
    [0.0, 0.4, 0.8, 1.0, 0.6]
    """

    effect = "rate_dependence"
    kind = "input_slew"
    slot = "input"
    order = 30
    needs_time = True
    description = "slew-rate limit before the hysteresis (a current-limited amplifier)"

    def _rate_max(self, ctx):
        return float(np.max(np.abs(np.diff(ctx.x)))) / ctx.dt if ctx.n > 1 else 1.0

    def parameters(self, ctx, kinds):
        return [Parameter("relative_slew_rate", 0.5, 0.02, 1.0, True)]

    def initial_values(self, ctx, kinds):
        return [{"relative_slew_rate": r} for r in (0.05, 0.15, 0.4, 0.8)]

    def transform(self, x, values, ctx):
        out = np.empty_like(x)
        step = float(values["relative_slew_rate"]) * self._rate_max(ctx) * ctx.dt
        slew_limit(np.ascontiguousarray(x, dtype=np.float64), step, out)
        return out

    def describe(self, values):
        return {"part": self.description, "relative_slew_rate": float(f"{values['relative_slew_rate']:.4g}")}


# ----------------------------------------------------------------------------
# after the core
# ----------------------------------------------------------------------------
def _steady_filter(stage, cols):
    """Filter every column through `stage`, starting at the steady state of
    the first sample (the record starts at rest)."""
    I = np.eye(stage.n_states)
    x_ss = np.linalg.solve(I - stage.A, stage.B).ravel()
    states = cols[0][:, None] * x_ss[None, :]
    return stage.filter_columns(cols, states)[0]


@register
class OutputLag(_Lag):
    """A first-order lag after the hysteresis (time constant [s]).

    Examples
    --------
    >>> ctx = Context(np.ones(4), 0.1, 0.0, 1.0, 0.4)
    >>> OutputLag().filter(np.ones((4, 2)), {"time_constant": 0.2}, ctx)[:, 0].round(6).tolist()
    [1.0, 1.0, 1.0, 1.0]
    """

    effect = "rate_dependence"
    kind = "output_lag"
    slot = "filter"
    order = 10
    needs_time = True
    description = "first-order lag after the hysteresis"

    def filter(self, columns, values, ctx):
        return _steady_filter(LinearStage.lag(values["time_constant"], ctx.dt), columns)


@register
class OutputResonance(Part):
    """A lightly damped mode after the hysteresis (frequency [Hz], damping).

    Examples
    --------
    >>> ctx = Context(np.ones(4), 0.01, 0.0, 1.0, 0.04)
    >>> [p.name for p in OutputResonance().parameters(ctx, set())]
    ['frequency', 'damping']
    """

    effect = "rate_dependence"
    kind = "output_resonance"
    slot = "filter"
    order = 20
    needs_time = True
    description = "resonance after the hysteresis"

    def _band(self, ctx):
        hi = 0.3 / ctx.dt
        lo = min(max(5.0 / ctx.duration, 1e-3 / ctx.dt), hi / 4)
        return lo, hi

    def parameters(self, ctx, kinds):
        lo, hi = self._band(ctx)
        return [Parameter("frequency", math.sqrt(lo * hi), lo, hi, True),
                Parameter("damping", 0.15, 0.01, 1.5, True)]

    def initial_values(self, ctx, kinds):
        lo, hi = self._band(ctx)
        return [{"frequency": f, "damping": z} for f in np.geomspace(lo, hi, 16) for z in (0.05, 0.15, 0.4)]

    def filter(self, columns, values, ctx):
        return _steady_filter(LinearStage.resonance(values["frequency"], values["damping"], ctx.dt), columns)


@register
class GainDrift(Part):
    """A gain that changes over the record, ``(1 + g (s(t) - 1/2))`` times
    the hysteresis, with ``s(t) = (1 - exp(-t/tau)) / (1 - exp(-T/tau))``
    rising from 0 to 1 over the record: an exponential approach (an
    actuator warming up with time constant tau [s]), linear in time for
    tau >> T.

    Examples
    --------
    >>> ctx = Context(np.zeros(3), 1.0, 0.0, 1.0, 2.0)
    >>> GainDrift().filter(np.ones((3, 1)), {"g": 0.2, "time_constant": 1e6}, ctx).ravel().round(6).tolist()
    [0.9, 1.0, 1.1]
    """

    effect = "gain_drift"
    kind = "gain_drift"
    slot = "filter"
    order = 90
    needs_time = True
    description = "gain changing in time 1 + g (s(t) - 1/2), s rising 0 -> 1 with time constant tau"

    def parameters(self, ctx, kinds):
        T = ctx.duration
        return [Parameter("g", 0.0, -0.6, 0.6, False),
                Parameter("time_constant", 3.0 * T, 0.02 * T, 20.0 * T, True)]

    def initial_values(self, ctx, kinds):
        T = ctx.duration
        return [{"g": g, "time_constant": f * T} for g in (-0.1, 0.1) for f in (0.1, 0.3, 20.0)]

    def filter(self, columns, values, ctx):
        tau = values.get("time_constant", 1e6 * ctx.duration)
        s = np.expm1(-ctx.time / tau) / np.expm1(-ctx.duration / tau)
        return columns * (1.0 + values["g"] * (s - 0.5))[:, None]


def _knot_times(ctx, k):
    """The `k` + 1 knots (from ``t = 0``) of a broken line in time over the
    fitted part of the record when blocks inside it are held out
    (``ctx.held_out``): in equal shares of the fitted time, none inside a
    block (the line crosses each block straight).

    Examples
    --------
    >>> ctx = Context(np.zeros(10), 1.0, 0.0, 1.0, 10.0, held_out=(4.0, 6.0))
    >>> _knot_times(ctx, 4).tolist()
    [0.0, 2.0, 6.0, 8.0, 10.0]

    Two blocks, 2 s and 1 s: 9 s fitted, a knot every 3 s of fitted time

    >>> ctx = Context(np.zeros(12), 1.0, 0.0, 1.0, 12.0, held_out=[(2.0, 4.0), (7.0, 8.0)])
    >>> _knot_times(ctx, 3).tolist()
    [0.0, 5.0, 9.0, 12.0]
    """
    T = ctx.fitted_until
    blocks = ctx.held_out
    F = np.linspace(0.0, T - sum(b - a for a, b in blocks), k + 1)     # knots in fitted time
    out, skipped = F.copy(), 0.0
    for a, b in blocks:
        out[F >= a - skipped] += b - a            # knots at or after the block's start (fitted time)
        skipped += b - a
    return out


def _time_hats(ctx, k):
    """Hat functions of a broken line in time with `k` equal segments over
    ``0 ... fit_end`` (held at the last knot after it; with a held-out block
    inside the record, equal shares of the fitted time, see
    :func:`_knot_times`): the columns of the knots after ``t = 0``, shape
    (n, k)."""
    if ctx.held_out is None:
        T = ctx.fitted_until
        s = np.minimum(ctx.time / T, 1.0) * k          # time in segments, held at k after T
    else:
        s = np.interp(ctx.time, _knot_times(ctx, k), np.arange(k + 1.0))
    return np.clip(1.0 - np.abs(s[:, None] - np.arange(1, k + 1)[None, :]), 0.0, None)


#: segments of the slow gain's broken line over the fitted part of the record
SLOW_GAIN_SEGMENTS = 4


@register
class SlowGainDrift(Part):
    """A gain of no set shape (a thermal cycle, a warming that stops): the
    hysteresis times ``1 + g(t)``, ``g`` a broken line in time with
    ``SLOW_GAIN_SEGMENTS`` equal segments over the fitted part of the record
    (``g(0) = 0``), held at its last level after it, as
    :class:`SlowDrift` is for the offset.  Parameters: the gain changes at
    the knots (``g1 ... g4``, within +-0.3); the search starts from a
    linear fit of the current residual on the knots' hat functions times
    the current model's output.

    Examples
    --------
    >>> ctx = Context(np.zeros(5), 1.0, 0.0, 1.0, 5.0, fit_end=4.0)
    >>> g = {"g1": 0.1, "g2": 0.2, "g3": 0.2, "g4": 0.1}
    >>> SlowGainDrift().filter(np.ones((5, 1)), g, ctx).ravel().round(6).tolist()
    [1.0, 1.1, 1.2, 1.2, 1.1]
    """

    effect = "gain_drift"
    kind = "slow_gain_drift"
    slot = "filter"
    order = 91
    needs_time = True
    description = "gain of no set shape: 1 + a broken line in time, held at its last level"

    def __init__(self):
        self.driver = None
        self._y = None

    def prepare(self, y, ctx):
        self._y = np.asarray(y, dtype=np.float64)

    def attach(self, model):
        self.driver = model

    def parameters(self, ctx, kinds):
        return [Parameter(f"g{i}", 0.0, -0.3, 0.3, False) for i in range(1, SLOW_GAIN_SEGMENTS + 1)]

    def initial_values(self, ctx, kinds):
        zero = {f"g{i}": 0.0 for i in range(1, SLOW_GAIN_SEGMENTS + 1)}
        if self.driver is None or self._y is None or self._y.size != ctx.n:
            return [zero]
        h = self._driver_output(ctx)
        fit = ctx.fitted_times()
        G = _time_hats(ctx, SLOW_GAIN_SEGMENTS) * (h - h[fit].mean())[:, None]
        g = np.linalg.lstsq(G[fit], (self._y - h)[fit], rcond=None)[0]
        return [{f"g{i + 1}": float(np.clip(x, -0.3, 0.3)) for i, x in enumerate(g)}, zero]

    def filter(self, columns, values, ctx):
        g = np.array([values[f"g{i}"] for i in range(1, SLOW_GAIN_SEGMENTS + 1)])
        return columns * (1.0 + _time_hats(ctx, SLOW_GAIN_SEGMENTS) @ g)[:, None]

    def describe(self, values):
        return {"part": self.description,
                "gain_changes": [float(f"{values[f'g{i}']:.4g}") for i in range(1, SLOW_GAIN_SEGMENTS + 1)]}


# ----------------------------------------------------------------------------
# additive parts
# ----------------------------------------------------------------------------
@register
class Creep(Part):
    """Creep: first-order lags on a logarithmic grid of time constants from
    ``max(20 dt, T/2000)`` to the record's length ``T`` (Kuhnen's creep operator,
    :class:`hystcomp.effects.CreepOperator`) of the input and of the current
    model's output (frozen when the part is tried: creep driven by the
    hysteresis output), coefficients >= 0 (the output keeps moving in the
    direction of the last step).  No nonlinear parameter.

    Examples
    --------
    >>> ctx = Context(np.ones(100), 0.1, 0.0, 1.0, 10.0)
    >>> cols, lower, upper, names = Creep().columns({}, ctx)
    >>> cols.shape[0], bool(np.all(lower == 0))
    (100, True)
    """

    effect = "creep"
    kind = "creep_lags"
    slot = "additive"
    order = 10
    needs_time = True
    description = "creep operators (lags of the input and of the hysteresis output)"

    def __init__(self):
        self.driver = None

    def attach(self, model):
        self.driver = model

    #: creep back (:class:`BackCreep`): the lags' complements, ``x - L_i[x]`` and ``h - L_i[h]``
    back = False

    def _shortest(self, ctx, lo, hi):
        """The shortest time constant of the grid, given the creep range's ``(lo, hi)``."""
        return lo

    def time_constants(self, ctx):
        # up to the record's length: logarithmic and power-law creep relax on every time
        # scale the record covers (Jung & Gweon 2000), and a bank that stops at T/4 leaves
        # their slow part as a trend (measured: 1.5-2.0 noise floors left on log creep)
        lo, hi = creep_time_range(ctx)
        lo = self._shortest(ctx, lo, hi)
        m = max(3, int(round(np.log10(hi / lo) * 2)) + 1)
        return np.geomspace(lo, hi, m)

    def columns(self, values, ctx):
        tau = self.time_constants(ctx)
        X = lag_bank(ctx.x, tau, ctx.dt, state=np.full(tau.size, ctx.x[0]))[0]
        if self.back:
            X = ctx.x[:, None] - X
        names = [f"{self.kind.replace('_lags', '')}_input_{t:.3g}s" for t in tau]
        if self.driver is not None:
            h = self._driver_output(ctx)
            # lags minus the driver itself: only the creeping part, no copy of the driver.  After a
            # step of the driver a lag minus the driver rises back to 0 from minus the step, so a
            # coefficient >= 0 keeps the output moving in the step's direction (Kelvin-Voigt
            # creep: y = h + sum c_i L_i[h] = (1 + sum c_i) h + sum c_i (L_i[h] - h)); creep
            # back takes the driver minus the lags, and the output sags back after the step
            Y = lag_bank(h, tau, ctx.dt, state=np.full(tau.size, h[0]))[0] - h[:, None]
            X = np.column_stack([X, -Y if self.back else Y])
            names += [f"{self.kind.replace('_lags', '')}_output_{t:.3g}s" for t in tau]
        k = X.shape[1]
        return X, np.zeros(k), np.full(k, np.inf), names

    def describe(self, values):
        return {"part": self.description}


@register
class BackCreep(Creep):
    """Creep back: after each step the output relaxes *against* it, on time
    constants of seconds, ``y = h + sum c_i (h - L_i[h]) + sum d_i (x - L_i[x])``
    with ``c_i, d_i >= 0`` (the lags ``L_i`` as in :class:`Creep`: the output
    overshoots at the step and sags back towards a lower relaxed gain).  A
    viscoelastic coupling in series with a spring does this (a generalised
    Maxwell solid under an imposed travel relaxes its force: Ferry 1980,
    *Viscoelastic Properties of Polymers*, ch. 3), as does the back relaxation
    of ionic polymer actuators (Nemat-Nasser & Wu 2003, J. Appl. Phys. 93,
    5255).  Its time constants start at four times the rate term's longest
    (:class:`RateTerm`): a fast lag of this form, ``x - L[x] = tau L[dx/dt]``,
    is a rate term.  No nonlinear parameter.  The diagnosis tries it only
    where the residual relaxes against the steps into the holds
    (``relaxation_per_step < 0`` in the creep signature).

    Examples
    --------
    >>> ctx = Context(np.r_[np.zeros(10), np.ones(990)], 0.1, 0.0, 1.0, 100.0)
    >>> cols, lower, upper, names = BackCreep().columns({}, ctx)
    >>> bool(cols[10, 0] > 0.9 and cols[-1, 0] < cols[10, 0]), names[0]
    (True, 'creep_back_input_10s')
    """

    kind = "creep_back"
    order = 11
    back = True
    description = "creep back (the output relaxes against each step: lags of the input and hysteresis output)"

    def _shortest(self, ctx, lo, hi):
        return min(max(lo, 4.0 * _lag_bounds(ctx)[1]), hi / 10.0)


@register
class RateTerm(Part):
    """A rate term beside the hysteresis: ``c L_tau[dv/dt]``, the input's
    rate (backward difference) through a first-order low-pass of time
    constant ``tau``, coefficient ``c >= 0`` (it widens the loop as the rate
    grows).  The classical eddy-current field of a laminated core
    (Bertotti 1998, *Hysteresis in Magnetism*, ch. 12: ``H_eddy`` is
    proportional to ``dB/dt``) and viscous damping of a stage are of this
    kind; unlike a lag or resonance after the hysteresis it makes the output
    lead, not lag.  Parameter: ``tau`` [s].

    Examples
    --------
    >>> ctx = Context(np.array([0.0, 1.0, 2.0, 2.0]), 1.0, 0.0, 1.0, 4.0)
    >>> RateTerm().columns({"time_constant": 1e-9}, ctx)[0].ravel().round(6).tolist()
    [0.0, 1.0, 1.0, 0.0]
    """

    effect = "rate_dependence"
    kind = "rate_term"
    slot = "additive"
    order = 15
    needs_time = True
    description = "rate term c L[dv/dt] beside the hysteresis (eddy currents, viscous damping)"

    def parameters(self, ctx, kinds):
        lo, hi = _lag_bounds(ctx)
        return [Parameter("time_constant", math.sqrt(lo * hi), lo, hi, True)]

    def initial_values(self, ctx, kinds):
        lo, hi = _lag_bounds(ctx)
        return [{"time_constant": t} for t in np.geomspace(lo, hi, 4)]

    def columns(self, values, ctx):
        rate = np.diff(ctx.x, prepend=ctx.x[0]) / ctx.dt
        scale = float(np.max(np.abs(rate))) or 1.0
        col = lag_bank(rate / scale, np.array([values["time_constant"]]), ctx.dt, state=np.zeros(1))[0]
        return col, np.zeros(1), np.full(1, np.inf), ["rate_term"]

    def describe(self, values):
        return {"part": self.description, "time_constant": float(f"{values['time_constant']:.4g}")}


class _OutputBend(Part):
    """A power of the current model's output (frozen when the part is tried),
    added on the output side."""

    slot = "additive"
    order = 40
    power = 2

    def __init__(self):
        self.driver = None

    def attach(self, model):
        self.driver = model
        self._center = self._scale = None

    def columns(self, values, ctx):
        h = self._driver_output(ctx)
        if self._center is None:        # fixed on the fitted record
            centre, scale = 0.5 * (float(h.max()) + float(h.min())), 0.5 * float(np.ptp(h)) or 1.0
            # the scale first: a thread that sees the centre set sees the scale too
            self._scale = scale
            self._center = centre
        z = (h - self._center) / self._scale
        return self.shape(z, values)[:, None], np.array([-np.inf]), np.array([np.inf]), [self.kind]

    def shape(self, z, values):
        """The bend of the scaled output `z` (its weight is fitted)."""
        return z ** self.power


@register
class OutputQuadratic(_OutputBend):
    """Asymmetry on the output side: ``y = H + a H^2`` (H the model's output,
    scaled to +-1 over the record).

    Examples
    --------
    >>> OutputQuadratic().power, OutputQuadratic().effect
    (2, 'asymmetry')
    """

    effect = "asymmetry"
    kind = "output_quadratic"
    power = 2
    description = "quadratic output map y = H + a H^2"


#: width of the hinge's rounded corner (scaled output, +-1 over the record)
HINGE_WIDTH = 0.05
#: the hinge's slope ratio (above the corner over below) is kept within
#: ``[1/HINGE_RATIO, HINGE_RATIO]``: a stiffness that changes, not a clip (a
#: slope falling to 0 is the output clip's, :class:`OutputClip`)
HINGE_RATIO = 2.0


@register
class OutputHinge(_OutputBend):
    """Asymmetry on the output side: a stiffness that differs on either side
    of one output level (a stack stiffer in compression than in tension, a
    contact that closes), ``y = H + k w ln(1 + exp((z - c)/w))``: slope 1
    below the corner ``c``, ``1 + k`` above it (``k`` of either sign, fitted
    as a weight, ``1 + k`` within a factor :data:`HINGE_RATIO` of 1), the
    corner rounded over ``w`` = :data:`HINGE_WIDTH` (z = H scaled to +-1
    over the record; bimodular elasticity, Ambartsumyan 1982).

    Examples
    --------
    >>> h = OutputHinge()
    >>> z = np.array([-1.0, 0.0, 1.0])
    >>> h.shape(z, {"corner": 0.0}).round(4).tolist()      # 0 below the corner, z - c above
    [0.0, 0.0347, 1.0]
    """

    effect = "asymmetry"
    kind = "output_hinge"
    description = "bimodular output map y = H + k max(z - c, 0) (rounded corner)"

    def parameters(self, ctx, kinds):
        return [Parameter("corner", 0.0, -0.8, 0.8, False)]

    def initial_values(self, ctx, kinds):
        return [{"corner": c} for c in (-0.5, 0.0, 0.5)]

    def shape(self, z, values):
        return HINGE_WIDTH * np.logaddexp(0.0, (z - values["corner"]) / HINGE_WIDTH)

    def columns(self, values, ctx):
        col, _, _, names = super().columns(values, ctx)
        # the weight k scale is the slope's change relative to the driving output's:
        # 1 + k within [1/HINGE_RATIO, HINGE_RATIO]
        return (col, np.array([(1.0 / HINGE_RATIO - 1.0) * self._scale]),
                np.array([(HINGE_RATIO - 1.0) * self._scale]), names)

    def describe(self, values):
        return {"part": self.description, "corner_scaled": float(f"{values['corner']:.4g}")}


@register
class OutputCubic(_OutputBend):
    """Saturation on the output side: ``y = H + c H^3`` with ``c <= 0``, the
    gain falling at the extremes (H the model's output scaled to +-1 over the
    record).  A positive ``c``, a gain that rises towards both extremes, is
    not a saturation, so the weight is bounded above by 0: an expanding
    output map (the odd tail of a smooth sensor law such as a tilted plate's
    refraction, Snell's law) is left in the residual rather than named.

    Examples
    --------
    >>> OutputCubic().power, OutputCubic().effect
    (3, 'saturation')
    >>> from hystcomp.identify.parts import Context
    >>> ctx = Context(np.linspace(-1, 1, 5), None, 0.0, 1.0, None)
    >>> part = OutputCubic()
    >>> part.attach(type("Identity", (), {"simulate": staticmethod(lambda v: v)})())  # driver: H = v
    >>> col, lower, upper, names = part.columns({}, ctx)
    >>> col[:, 0].tolist(), lower.tolist(), upper.tolist()
    ([-1.0, -0.125, 0.0, 0.125, 1.0], [-inf], [0.0])
    """

    effect = "saturation"
    kind = "output_cubic"
    power = 3
    description = "cubic output map y = H + c H^3 (c <= 0)"

    def columns(self, values, ctx):
        col, lower, _, names = super().columns(values, ctx)
        return col, lower, np.array([0.0]), names
