"""Offset drift parts (:mod:`hystcomp.identify.parts`): a trend, a slow drift
on time hats, a drift made of events, and a drifting sensor.

They register after the parts of :mod:`~hystcomp.identify.parts_dynamics`
(``parts.py`` imports this module right after that one), so the registry's
order, which the diagnosis's search follows, is the same as when they lived
there.
"""

import numpy as np

from .part_base import Context, Parameter, Part, register  # noqa: F401 (Context: the examples)
from .parts_dynamics import _time_hats

__all__ = ["Drift", "SlowDrift", "EventDrift", "SensorDrift"]


@register
class Drift(Part):
    """Offset drift ``a t/T + b (1 - exp(-t/tau))`` (free a, b; tau [s]).

    Examples
    --------
    >>> ctx = Context(np.zeros(3), 1.0, 0.0, 1.0, 3.0)
    >>> Drift().columns({"time_constant": 1.0}, ctx)[0].round(4).tolist()
    [[0.0, 0.0], [0.3333, 0.6321], [0.6667, 0.8647]]
    """

    effect = "drift"
    kind = "offset_drift"
    slot = "additive"
    order = 20
    needs_time = True
    description = "offset drift a t + b (1 - exp(-t/tau))"

    def parameters(self, ctx, kinds):
        return [Parameter("time_constant", 0.3 * ctx.duration, 0.02 * ctx.duration, 3 * ctx.duration, True)]

    def initial_values(self, ctx, kinds):
        return [{"time_constant": f * ctx.duration} for f in (0.05, 0.2, 0.8)]

    def columns(self, values, ctx):
        t = ctx.time
        D = np.column_stack([t / ctx.duration, -np.expm1(-t / values["time_constant"])])
        return D, np.full(2, -np.inf), np.full(2, np.inf), ["drift_linear", "drift_exponential"]


#: segments of the slow drift's broken line over the fitted part of the record
SLOW_DRIFT_SEGMENTS = 6


@register
class SlowDrift(Part):
    """An offset drift of no set shape (a random walk, a thermal cycle, a
    fixture settling): a broken line in time with ``SLOW_DRIFT_SEGMENTS``
    equal segments over the fitted part of the record (``0 ... fit_end``),
    held at its last level after it.  Held level is the forecast of a
    drift whose next step is as likely up as down (a random walk); the
    parametric :class:`Drift` extrapolates its trend instead.  Columns: the
    hat functions of the knots after ``t = 0`` (the level at ``t = 0`` is
    the core's offset); no nonlinear parameter.

    Examples
    --------
    >>> ctx = Context(np.zeros(8), 1.0, 0.0, 1.0, 8.0, fit_end=6.0)
    >>> D = SlowDrift().columns({}, ctx)[0]
    >>> D.shape, D[:, -1].round(2).tolist()
    ((8, 6), [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0])
    >>> bool(np.allclose(D[:7].sum(axis=1)[1:], 1.0))   # the hats add up to 1 after t = 0
    True
    """

    effect = "drift"
    kind = "slow_drift"
    slot = "additive"
    order = 21
    needs_time = True
    description = "offset drift of no set shape: a broken line in time, held at its last level"

    #: segments of the broken line
    SEGMENTS = SLOW_DRIFT_SEGMENTS

    def columns(self, values, ctx):
        k = self.SEGMENTS
        D = _time_hats(ctx, k)
        names = [f"{self.kind}_{i}" for i in range(1, k + 1)]
        return D, np.full(k, -np.inf), np.full(k, np.inf), names

    def describe(self, values):
        return {"part": self.description, "segments": self.SEGMENTS}


#: segments of the event drift's broken line over the fitted part of the record
EVENT_DRIFT_SEGMENTS = 24


@register
class EventDrift(SlowDrift):
    """An offset drift made of events: a door opened, a lamp switched on and
    off, another axis of the machine moved, a part flash-heated; the offset
    moves within seconds at a few moments of a long record and stays put in
    between.  The six segments of :class:`SlowDrift` cannot follow such a
    move, and the core's weights bend to what they leave.  The same broken
    line in time with ``EVENT_DRIFT_SEGMENTS`` equal segments over the
    fitted part (1.17 s each on a 40 s record with its last 30 % held out),
    held at its last level after it: the forecast is that the last event is
    over.  No nonlinear parameter; the BIC charges its 24 columns.

    On the thirty realistic sets (round 32, 945 runs) it turned 9 runs whose
    drift :class:`SlowDrift` had named from ``unexplained`` to ``explained``,
    and 9 runs right, against 7 that went wrong (3 of them out-of-vocabulary
    cores whose mean walks in time: a ratchet, an inertia drive); see
    docs/diagnose_history.md, round 32.

    Examples
    --------
    >>> ctx = Context(np.zeros(50), 1.0, 0.0, 1.0, 50.0, fit_end=48.0)
    >>> D, lo, hi, names = EventDrift().columns({}, ctx)
    >>> D.shape, names[0], names[-1]
    ((50, 24), 'event_drift_1', 'event_drift_24')
    >>> D[2].round(2).tolist()[:2], float(D[-1, -1])     # 2 s a segment; held at the last knot
    ([1.0, 0.0], 1.0)
    """

    kind = "event_drift"
    order = 22
    SEGMENTS = EVENT_DRIFT_SEGMENTS
    description = (f"offset drift made of events in time: a broken line of {EVENT_DRIFT_SEGMENTS} segments, "
                   "held at its last level")


@register
class SensorDrift(Part):
    """Offset drift added after a saturating output map (a displacement
    sensor or a fixture warming up, outside the actuator):
    ``y = map(u) + a t/T + b (1 - exp(-t/tau))``.  Tried only when the model
    has an output map (without one it is :class:`Drift`); its amplitudes are
    nonlinear parameters (in output spans) because the map is.

    Examples
    --------
    >>> ctx = Context(np.zeros(3), 1.0, 0.0, 1.0, 3.0)
    >>> part = SensorDrift(); part.y_span = 2.0
    >>> part.after_output({"linear": 0.5, "exponential": 0.0, "time_constant": 1.0}, ctx).tolist()
    [0.0, 0.3333333333333333, 0.6666666666666666]
    """

    effect = "drift"
    kind = "sensor_drift"
    slot = "after_output"
    needs_time = True
    needs_output_map = True
    description = "offset drift after the output map a t + b (1 - exp(-t/tau))"

    def __init__(self):
        self.y_span = 1.0
        self.driver = None

    def prepare(self, y, ctx):
        self.y_span = float(np.ptp(y)) or 1.0
        self._y = np.asarray(y, dtype=np.float64)

    def attach(self, model):
        self.driver = model

    def parameters(self, ctx, kinds):
        return [Parameter("linear", 0.0, -0.5, 0.5, False), Parameter("exponential", 0.0, -0.5, 0.5, False),
                Parameter("time_constant", 0.3 * ctx.duration, 0.02 * ctx.duration, 3 * ctx.duration, True)]

    def initial_values(self, ctx, kinds):
        # amplitudes from a least-squares fit of the current residual's trend
        out = []
        e = None
        if self.driver is not None and getattr(self, "_y", None) is not None and self._y.size == ctx.n:
            e = self._y - self.driver.simulate(ctx.v)
        for f in (0.05, 0.2, 0.8):
            tau = f * ctx.duration
            a = b = 0.0
            if e is not None:
                t = ctx.time
                D = np.column_stack([t / ctx.duration, -np.expm1(-t / tau), np.ones(ctx.n)])
                coef = np.linalg.lstsq(D, e, rcond=None)[0]
                a, b = (float(np.clip(c / self.y_span, -0.5, 0.5)) for c in coef[:2])
            out.append({"linear": a, "exponential": b, "time_constant": tau})
        return out

    def after_output(self, values, ctx):
        t = ctx.time
        return self.y_span * (values["linear"] * t / ctx.duration
                              - values["exponential"] * np.expm1(-t / values["time_constant"]))
