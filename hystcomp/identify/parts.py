"""Model parts: the feature libraries of hystcomp's identification.

A part declares its nonlinear parameters (:class:`Parameter`: initial value,
bounds, log or linear scale) and, for given values of them, contributes to
the regressor columns of a linear-in-the-weights model

``y = sum_j theta_j a_j(v; values) (+ an output map)``

in one of five places (its ``slot``), applied in this order:

``input``
    transforms the input before the hysteresis (:class:`Delay`,
    :class:`InputLag`);
``core``
    sets options of the hysteresis core's plays (:class:`Asymmetry` and
    :class:`Saturation`: envelopes, eq. 23; :class:`RateThresholds`:
    ``r_i + beta |dv/dt|``; :class:`InitialState`: a preload history);
``filter``
    maps the core's columns (:class:`OutputLag`, :class:`OutputResonance`:
    a linear stage after the hysteresis; :class:`GainDrift`);
``additive``
    adds columns of its own (:class:`Creep`, :class:`Drift`, and the
    offset);
``output``
    maps the linear prediction (:class:`OutputClip`: clipping of the output
    side), and says which samples the linear solve may use.

:class:`PICore` (thresholds spread up to the full input span, eq. 18) is
always there.  :mod:`hystcomp.identify.search` builds the columns of a set
of parts, solves for the weights with
:func:`hystcomp.identify.solver.solve_weights` and varies the nonlinear
parameters (variable projection); :class:`~hystcomp.identify.search.PartsModel`
is the fitted model built from the same parts.

Adding an effect is one class here (or in your own module) and one call of
:func:`register` (see docs/diagnose.md, "Write your own effect").
"""

import math
from collections import namedtuple

import numpy as np

from ..effects import LinearStage, lag_bank
from ._part_kernels import core_columns, fractional_delay

__all__ = ["Parameter", "Context", "Part", "PICore", "Offset", "Delay", "InputLag", "RateThresholds", "LevelThresholds",
           "Asymmetry", "Saturation", "InitialState", "OutputLag", "OutputResonance", "GainDrift", "Creep",
           "Drift", "SensorDrift", "OutputQuadratic", "OutputCubic", "OutputClip", "OutputTanh", "register", "PARTS"]

Parameter = namedtuple("Parameter", ["name", "initial", "lower", "upper", "log"])
Parameter.__doc__ = """A nonlinear parameter of a part: name, initial value, bounds and
whether it is searched on a logarithmic scale.

Examples
--------
>>> Parameter("time_constant", 0.01, 1e-3, 1.0, True).log
True
"""

SLOTS = ("input", "core", "filter", "additive", "output", "after_output")


class Context:
    """What the parts know about a record: the input, its scaling, the
    sampling step and the clock.

    Parameters
    ----------
    v : array_like, shape (n,)
        Input samples.
    dt : float or None
        Sampling step [s]; None for a record without a time axis (then the
        parts that need time are not available).
    origin, scale : float
        The core works on ``x = (v - origin) / scale``.
    duration : float or None
        Duration [s] of the record the model was fitted on (the clock of the
        drift parts; None without time).
    n_thresholds : int
        Number of play operators of the core (the first has threshold 0).
    noise : float
        Noise floor of the output [output units] (parts that mask samples use
        it).

    Examples
    --------
    >>> ctx = Context(np.linspace(0, 2, 5), dt=0.1, origin=0.0, scale=2.0, duration=0.5)
    >>> ctx.x.tolist(), ctx.time.tolist()[:2]
    ([0.0, 0.25, 0.5, 0.75, 1.0], [0.0, 0.1])
    """

    def __init__(self, v, dt, origin, scale, duration, n_thresholds=20, noise=0.0):
        self.v = np.ascontiguousarray(v, dtype=np.float64)
        self.n = self.v.size
        self.dt = None if dt is None else float(dt)
        self.origin = float(origin)
        self.scale = float(scale)
        self.x = (self.v - self.origin) / self.scale
        self.duration = None if duration is None else float(duration)
        self.n_thresholds = int(n_thresholds)
        self.thresholds = np.arange(self.n_thresholds) / self.n_thresholds
        self.noise = float(noise)
        self.time = None if self.dt is None else np.arange(self.n) * self.dt

    def like(self, v):
        """The same context for another input `v` (same scaling and clock).

        Parameters
        ----------
        v : array_like, shape (m,)
            The other input.

        Returns
        -------
        Context
        """
        return Context(v, self.dt, self.origin, self.scale, self.duration, self.n_thresholds, self.noise)


class Part:
    """Base class of a model part (see the module docstring).

    Subclasses set ``effect`` (the effect they model, or None for a part
    every model has), ``kind`` (a unique name), ``slot``, ``needs_time`` and
    ``description``, declare :meth:`parameters`, and implement the hook of
    their slot.

    Examples
    --------
    >>> Drift().slot, Drift().effect, Drift().needs_time
    ('additive', 'drift', True)
    """

    effect = None
    kind = None
    slot = None
    needs_time = False
    description = ""
    #: order inside the slot (smaller first)
    order = 50

    def parameters(self, ctx, kinds):
        """The nonlinear parameters (list of :class:`Parameter`) for a record
        and the other parts' kinds (a part may need more parameters when
        another part is there)."""
        return []

    def initial_values(self, ctx, kinds):
        """Starting points of the search (list of dicts); default the
        parameters' initial values."""
        return [{p.name: p.initial for p in self.parameters(ctx, kinds)}]

    def prepare(self, y, ctx):
        """Called once with the measured output before fitting (default:
        nothing; :class:`OutputClip` reads the output's extremes)."""

    def attach(self, model):
        """Called with the current model (a
        :class:`~hystcomp.identify.search.PartsModel`) before this part is
        tried on top of it (default: nothing; parts driven by the model's
        output keep it, frozen, as their driver)."""

    def _driver_output(self, ctx):
        """The frozen driver's output for the context's input (cached)."""
        key = (id(ctx.v), ctx.n)
        if getattr(self, "_cache_key", None) != key:
            self._cache_key = key
            self._cache = self.driver.simulate(ctx.v)
        return self._cache

    def signature(self, residual, prediction, record, noise_floor):
        """The signature test of a new effect on a residual: a dict with
        ``signature`` (what is measured), ``statistic`` and ``threshold`` (in
        noise floors).  The canonical effects' tests live in
        :mod:`hystcomp.diagnose.signatures`; a part of a new effect overrides
        this (default None: no test, and a part without one is never named).
        `record` has ``v``, ``y``, ``t`` (or None), ``dt``, ``n``, ``train``,
        ``holds`` and ``rate``."""
        return None

    # slot hooks ---------------------------------------------------------
    def transform(self, x, values, ctx):
        """``input`` slot: the transformed (scaled) input."""
        raise NotImplementedError

    def core_options(self, values, ctx, options):
        """``core`` slot: set keys of the core's `options` dict."""
        raise NotImplementedError

    def filter(self, columns, values, ctx):
        """``filter`` slot: the mapped core columns."""
        raise NotImplementedError

    def columns(self, values, ctx):
        """``additive`` slot: (columns (n, k), lower (k,), upper (k,), names)."""
        raise NotImplementedError

    def fit_rows(self, y, values, ctx):
        """``output`` slot: boolean mask of the samples the linear solve uses."""
        return np.ones(y.size, bool)

    def target(self, y, values, ctx):
        """``output`` slot: what the linear part must predict, and the weight
        of each sample (default y itself, unweighted: None)."""
        return y, None

    def output(self, u, values, ctx):
        """``output`` slot: the output for the linear prediction `u`."""
        return u

    def after_output(self, values, ctx):
        """``after_output`` slot: a term added after the output map (from
        nonlinear parameters only), shape (n,)."""
        raise NotImplementedError

    def describe(self, values):
        """Readable parameters (dict)."""
        return {"part": self.description, **{k: float(f"{v:.6g}") for k, v in values.items()}}


PARTS = {}


def register(cls):
    """Register a part class under its ``kind`` (usable as a decorator);
    :func:`hystcomp.diagnose.diagnose` tries every registered part whose
    ``effect`` is among its candidates.

    Parameters
    ----------
    cls : type
        A subclass of :class:`Part` with ``kind``, ``slot`` and ``effect`` set.

    Returns
    -------
    type
        `cls` itself.

    Examples
    --------
    >>> sorted(k for k, c in PARTS.items() if c.effect == "rate_dependence")
    ['input_lag', 'output_lag', 'output_resonance', 'rate_thresholds']
    """
    if not (isinstance(cls, type) and issubclass(cls, Part)):
        raise TypeError(f"Parameter cls is {cls!r} but should be a subclass of Part")
    if cls.slot not in SLOTS:
        raise ValueError(f"Part {cls.__name__} has slot {cls.slot!r} but should have one of {SLOTS}")
    if not cls.kind:
        raise ValueError(f"Part {cls.__name__} has no kind (a unique name)")
    PARTS[cls.kind] = cls
    return cls


# ----------------------------------------------------------------------------
# parts every model has
# ----------------------------------------------------------------------------
class PICore(Part):
    """The PI core (eq. 18): ``p0 x + sum_i p_i F_{r_i}[x]`` with
    thresholds ``r_i = i/N`` of the scaled input (up to the full input span,
    so a unipolar record's first loading curve is covered), weights >= 0.
    Core-slot parts turn the plays into modified plays (eq. 23).

    Examples
    --------
    >>> ctx = Context(np.sin(np.linspace(0, 6, 50)), None, 0.0, 1.0, None, n_thresholds=4)
    >>> PICore().core(ctx.x, {}, ctx).shape
    (50, 4)
    """

    kind = "core"
    slot = "core"
    description = "PI core (plays up to the full input span)"

    def core(self, x, options, ctx):
        """Columns of the (modified) plays for the scaled input `x` and the
        options set by the core-slot parts."""
        out = np.empty((x.size, ctx.thresholds.size))
        beta = float(options.get("beta", 0.0))
        inv_dt = 1.0 / ctx.dt if ctx.dt else 0.0
        pre = np.asarray(options.get("preload", ()), dtype=np.float64)
        if pre.size:
            pre = np.append(pre, x[0] if x.size else 0.0)
        core_columns(np.ascontiguousarray(x), ctx.thresholds, beta, inv_dt, float(options.get("rho", 1.0)),
                     float(options.get("ql", 0.0)), float(options.get("qr", 0.0)), float(options.get("bl", 0.0)),
                     float(options.get("br", 0.0)), pre, out, float(options.get("shift", 0.0)),
                     float(options.get("level", 0.0)))
        return out


class Offset(Part):
    """A constant output offset (free sign).

    Examples
    --------
    >>> Offset().columns({}, Context(np.zeros(3), None, 0.0, 1.0, None))[0].ravel().tolist()
    [1.0, 1.0, 1.0]
    """

    kind = "offset"
    slot = "additive"
    order = 99
    description = "output offset"

    def columns(self, values, ctx):
        return np.ones((ctx.n, 1)), np.array([-np.inf]), np.array([np.inf]), ["offset"]


# ----------------------------------------------------------------------------
# input side
# ----------------------------------------------------------------------------
@register
class Delay(Part):
    """Dead time before the hysteresis, in fractional samples (linear
    interpolation): ``x(t - delay)``.

    Examples
    --------
    >>> ctx = Context(np.arange(5.0), 1.0, 0.0, 1.0, 5.0)
    >>> Delay().transform(ctx.x, {"delay": 1.5}, ctx).tolist()
    [0.0, 0.0, 0.5, 1.5, 2.5]
    """

    effect = "delay"
    kind = "delay"
    slot = "input"
    order = 10
    needs_time = True
    description = "dead time before the hysteresis"

    def _max(self, ctx):
        return float(min(max(20.0, 0.002 * ctx.n), 0.05 * ctx.n))

    def parameters(self, ctx, kinds):
        return [Parameter("delay", 1.0, 0.0, self._max(ctx), False)]

    def initial_values(self, ctx, kinds):
        return [{"delay": d} for d in np.geomspace(0.5, self._max(ctx), 5)]

    def transform(self, x, values, ctx):
        out = np.empty_like(x)
        fractional_delay(np.ascontiguousarray(x), float(values["delay"]), out)
        return out

    def describe(self, values):
        return {"part": self.description, "delay_samples": float(f"{values['delay']:.4g}")}


def _lag_bounds(ctx):
    lo = 0.3 * ctx.dt
    hi = max(50 * ctx.dt, min(0.5, ctx.duration / 20))
    return lo, hi


@register
class InputLag(Part):
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

    def parameters(self, ctx, kinds):
        lo, hi = _lag_bounds(ctx)
        return [Parameter("time_constant", 3 * ctx.dt, lo, hi, True)]

    def initial_values(self, ctx, kinds):
        lo, hi = _lag_bounds(ctx)
        return [{"time_constant": t} for t in np.geomspace(lo * 2, hi, 5)]

    def transform(self, x, values, ctx):
        # at rest at the first sample (the record starts in a steady state)
        return lag_bank(x, [values["time_constant"]], ctx.dt, state=[x[0]])[0][:, 0].copy()


# ----------------------------------------------------------------------------
# the core's plays
# ----------------------------------------------------------------------------
@register
class RateThresholds(Part):
    """Rate-dependent thresholds ``r_i + beta |dv/dt|`` (Al Janaideh et al.
    2009); the parameter is ``beta`` times the record's largest input rate
    over the input scale (dimensionless).

    Examples
    --------
    >>> ctx = Context(np.linspace(0, 1, 11), 0.1, 0.0, 1.0, 1.1)
    >>> opts = {}
    >>> RateThresholds().core_options({"relative_rate_coefficient": 0.1}, ctx, opts)   # rate 1 / s
    >>> round(opts["beta"], 6)
    0.1
    """

    effect = "rate_dependence"
    kind = "rate_thresholds"
    slot = "core"
    order = 10
    needs_time = True
    description = "rate-dependent thresholds r_i + beta |dv/dt|"

    def _rate_max(self, ctx):
        return float(np.max(np.abs(np.diff(ctx.x)))) / ctx.dt or 1.0

    def parameters(self, ctx, kinds):
        return [Parameter("relative_rate_coefficient", 0.05, 1e-4, 3.0, True)]

    def initial_values(self, ctx, kinds):
        return [{"relative_rate_coefficient": c} for c in (0.003, 0.01, 0.03, 0.1, 0.3, 1.0)]

    def core_options(self, values, ctx, options):
        options["beta"] = values["relative_rate_coefficient"] / self._rate_max(ctx)

    def describe(self, values):
        return {"part": self.description, "relative_rate_coefficient":
                float(f"{values['relative_rate_coefficient']:.4g}")}


@register
class Asymmetry(Part):
    """Asymmetric envelopes (eq. 23 with gl != gr): ``gl(s) = rho (s + q_l s^2)``,
    ``gr(s) = s + q_r s^2`` (scaled input); with :class:`Saturation` in the
    model the two envelopes saturate differently (``b_l = b (1 + skew)``,
    ``b_r = b (1 - skew)``): asymmetry together with saturation.

    Examples
    --------
    >>> ctx = Context(np.zeros(3), None, 0.0, 1.0, None)
    >>> [p.name for p in Asymmetry().parameters(ctx, {"saturation_envelope"})]
    ['rho', 'q_left', 'q_right', 'skew']
    """

    effect = "asymmetry"
    kind = "asymmetric_envelopes"
    slot = "core"
    order = 30
    description = "asymmetric mGPI envelopes"

    def parameters(self, ctx, kinds):
        ps = [Parameter("rho", 1.0, 0.4, 2.5, True), Parameter("q_left", 0.0, -0.25, 0.25, False),
              Parameter("q_right", 0.0, -0.25, 0.25, False)]
        if "saturation_envelope" in kinds:
            ps.append(Parameter("skew", 0.0, -0.7, 0.7, False))
        return ps

    def initial_values(self, ctx, kinds):
        base = {p.name: p.initial for p in self.parameters(ctx, kinds)}
        out = []
        for rho in (0.7, 1.0, 1.4):
            for q in (-0.1, 0.1):
                out.append({**base, "rho": rho, "q_left": q, "q_right": -q})
        return out

    def core_options(self, values, ctx, options):
        options["rho"] = values["rho"]
        options["ql"] = values["q_left"]
        options["qr"] = values["q_right"]
        options["skew"] = values.get("skew", 0.0)


@register
class LevelThresholds(Part):
    """Thresholds that grow (or shrink) with the input level,
    ``r_i max(1 + k x, 0.05)`` with ``x`` the scaled input (``|x| <= 1``):
    the loop is wider at one end of the stroke than at the other, an
    asymmetry that envelopes shared by all plays do not draw.  It is the
    static counterpart of the rate-dependent thresholds ``r_i + beta
    |dv/dt|`` of Al Janaideh et al. (2009), and a generalized play (eq. 23)
    whose envelope slopes ``1 -/+ k r_i`` depend on the threshold.

    Examples
    --------
    >>> opts = {}
    >>> LevelThresholds().core_options({"level_coefficient": 0.3}, None, opts)
    >>> opts["level"]
    0.3
    """

    effect = "asymmetry"
    kind = "level_thresholds"
    slot = "core"
    order = 35
    description = "thresholds growing with the input level r_i (1 + k x)"

    def parameters(self, ctx, kinds):
        return [Parameter("level_coefficient", 0.0, -0.9, 0.9, False)]

    def initial_values(self, ctx, kinds):
        return [{"level_coefficient": k} for k in (-0.4, -0.15, 0.15, 0.4)]

    def core_options(self, values, ctx, options):
        options["level"] = values["level_coefficient"]


@register
class Saturation(Part):
    """Saturating envelope ``gamma(s) = tanh(b s)/b`` (eq. 25) on both sides
    of the plays (scaled input).

    Examples
    --------
    >>> opts = {}
    >>> Saturation().core_options({"b": 1.0}, None, opts)
    >>> opts["bl"], opts["br"]
    (1.0, 1.0)
    """

    effect = "saturation"
    kind = "saturation_envelope"
    slot = "core"
    order = 40
    description = "saturating mGPI envelope tanh(b v)/b"

    def parameters(self, ctx, kinds):
        return [Parameter("b", 0.8, 0.02, 4.0, True)]

    def initial_values(self, ctx, kinds):
        return [{"b": b} for b in (0.2, 0.6, 1.2, 2.5)]

    def core_options(self, values, ctx, options):
        skew = options.get("skew", 0.0)
        options["bl"] = values["b"] * (1.0 + skew)
        options["br"] = values["b"] * (1.0 - skew)


@register
class InitialState(Part):
    """Unknown memory at the record's start: the plays start from the
    state a preload history leaves, the virgin state driven to ``u1`` and
    ``u2`` (scaled input) before the first sample.

    Examples
    --------
    >>> ctx = Context(np.zeros(3), None, 0.0, 1.0, None)
    >>> opts = {}
    >>> InitialState().core_options({"u1": 0.5, "u2": -0.2}, ctx, opts)
    >>> opts["preload"]
    [0.5, -0.2]
    """

    effect = "initial_state"
    kind = "initial_state"
    slot = "core"
    order = 90
    description = "preload history before the record (the plays' initial state)"

    def parameters(self, ctx, kinds):
        lo, hi = float(ctx.x.min()), float(ctx.x.max())
        w = hi - lo
        return [Parameter("u1", hi, lo - 0.25 * w, hi + 0.25 * w, False),
                Parameter("u2", lo, lo - 0.25 * w, hi + 0.25 * w, False)]

    def initial_values(self, ctx, kinds):
        lo, hi = float(ctx.x.min()), float(ctx.x.max())
        x0 = float(ctx.x[0])
        out = []
        for u1 in (lo, hi):
            for f in (0.0, 0.5, 1.0):
                u2 = x0 + f * ((hi if u1 == lo else lo) - x0)
                out.append({"u1": u1, "u2": u2})
        return out

    def core_options(self, values, ctx, options):
        options["preload"] = [values["u1"], values["u2"]]

    def describe(self, values):
        return {"part": self.description, "preload_scaled": [float(f"{values['u1']:.4g}"),
                                                            float(f"{values['u2']:.4g}")]}


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
class OutputLag(Part):
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

    def parameters(self, ctx, kinds):
        lo, hi = _lag_bounds(ctx)
        return [Parameter("time_constant", 3 * ctx.dt, lo, hi, True)]

    def initial_values(self, ctx, kinds):
        lo, hi = _lag_bounds(ctx)
        return [{"time_constant": t} for t in np.geomspace(lo * 2, hi, 5)]

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


# ----------------------------------------------------------------------------
# additive parts
# ----------------------------------------------------------------------------
@register
class Creep(Part):
    """Creep: first-order lags on a logarithmic grid of time constants from
    ``max(20 dt, T/2000)`` to ``T/4`` (Kuhnen's creep operator,
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

    def time_constants(self, ctx):
        hi = max(ctx.duration / 4, 10 * ctx.dt)
        lo = min(max(20 * ctx.dt, ctx.duration / 2000), hi / 10)
        m = max(3, int(round(np.log10(hi / lo) * 2)) + 1)
        return np.geomspace(lo, hi, m)

    def columns(self, values, ctx):
        tau = self.time_constants(ctx)
        X = lag_bank(ctx.x, tau, ctx.dt, state=np.full(tau.size, ctx.x[0]))[0]
        names = [f"creep_input_{t:.3g}s" for t in tau]
        if self.driver is not None:
            h = self._driver_output(ctx)
            # lags minus the driver itself: only the creeping part, no copy of the driver
            Y = lag_bank(h, tau, ctx.dt, state=np.full(tau.size, h[0]))[0] - h[:, None]
            X = np.column_stack([X, -Y])
            names += [f"creep_output_{t:.3g}s" for t in tau]
        k = X.shape[1]
        return X, np.zeros(k), np.full(k, np.inf), names

    def describe(self, values):
        return {"part": self.description}


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
            self._center = 0.5 * (float(h.max()) + float(h.min()))
            self._scale = 0.5 * float(np.ptp(h)) or 1.0
        z = (h - self._center) / self._scale
        return (z ** self.power)[:, None], np.array([-np.inf]), np.array([np.inf]), [self.kind]


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


@register
class OutputCubic(_OutputBend):
    """Saturation on the output side: ``y = H + c H^3`` (c < 0: the gain falls
    at the extremes; H the model's output scaled to +-1 over the record).

    Examples
    --------
    >>> OutputCubic().power, OutputCubic().effect
    (3, 'saturation')
    """

    effect = "saturation"
    kind = "output_cubic"
    power = 3
    description = "cubic output map y = H + c H^3"


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


# ----------------------------------------------------------------------------
# output side
# ----------------------------------------------------------------------------
@register
class OutputClip(Part):
    """Clipping on the output side (a sensor or amplifier range):
    ``y = clip(u, low, high)``.  The linear solve uses only the samples
    more than two noise widths inside the limits (a clipped sample says only
    that the unclipped output was beyond the limit).  Parameters: the limits
    as fractions of the output span inside its extremes.

    Examples
    --------
    >>> ctx = Context(np.zeros(3), None, 0.0, 1.0, None)
    >>> part = OutputClip()
    >>> part.set_output_range(0.0, 1.0)
    >>> part.output(np.array([-1.0, 0.5, 2.0]), {"low": 0.0, "high": 0.0}, ctx).tolist()
    [0.0, 0.5, 1.0]
    """

    effect = "output_saturation"
    kind = "output_clip"
    slot = "output"
    description = "clipping of the output"

    def __init__(self):
        self.y_min, self.y_max = 0.0, 1.0

    def set_output_range(self, y_min, y_max):
        """The measured output's extremes (the limits are placed from them).

        Parameters
        ----------
        y_min, y_max : float
            Smallest and largest measured output.
        """
        self.y_min, self.y_max = float(y_min), float(y_max)

    def prepare(self, y, ctx):
        self.set_output_range(float(np.min(y)), float(np.max(y)))

    def limits(self, values):
        """(low, high) in output units."""
        span = self.y_max - self.y_min
        return self.y_min + values["low"] * span, self.y_max - values["high"] * span

    def parameters(self, ctx, kinds):
        return [Parameter("low", 0.0, -0.2, 0.2, False), Parameter("high", 0.0, -0.2, 0.2, False)]

    def initial_values(self, ctx, kinds):
        return [{"low": a, "high": b} for a in (-0.1, 0.0) for b in (-0.1, 0.0)]

    def fit_rows(self, y, values, ctx):
        lo, hi = self.limits(values)
        m = 2.0 * ctx.noise
        return (y > lo + m) & (y < hi - m)

    def output(self, u, values, ctx):
        lo, hi = self.limits(values)
        return np.clip(u, lo, hi)

    def describe(self, values):
        lo, hi = self.limits(values)
        return {"part": self.description, "low": float(f"{lo:.6g}"), "high": float(f"{hi:.6g}")}


@register
class OutputTanh(Part):
    """Smooth saturation on the output side (a magnetisation-like output,
    an amplifier running into its rails):
    ``y = c + S tanh((u - c)/S)`` for the linear prediction u.  The linear
    solve fits ``u`` to ``c + S atanh((y - c)/S)`` on the samples inside
    98 % of the limits, weighted by ``(1 - ((y - c)/S)^2)^2`` (the slope of
    the map squared, so that the weighted residual is the output's residual
    to first order).  Parameters: the half-range ``S`` relative to the
    output's half-span (> 1) and the centre ``c`` relative to the output's
    mid-range, in half-spans.

    Examples
    --------
    >>> part = OutputTanh()
    >>> part.set_output_range(-1.0, 1.0)
    >>> ctx = Context(np.zeros(3), None, 0.0, 1.0, None)
    >>> part.output(np.array([0.0, 10.0]), {"limit": 1.5, "centre": 0.0}, ctx).round(4).tolist()
    [0.0, 1.5]
    """

    effect = "saturation"
    kind = "output_tanh"
    slot = "output"
    description = "saturating output map y = c + S tanh((u - c)/S)"

    def __init__(self):
        self.y_min, self.y_max = -1.0, 1.0

    def prepare(self, y, ctx):
        self.set_output_range(float(np.min(y)), float(np.max(y)))

    def set_output_range(self, y_min, y_max):
        """The measured output's extremes.

        Parameters
        ----------
        y_min, y_max : float
            Smallest and largest measured output.
        """
        self.y_min, self.y_max = float(y_min), float(y_max)

    def _map(self, values):
        half = 0.5 * (self.y_max - self.y_min) or 1.0
        c = 0.5 * (self.y_max + self.y_min) + values["centre"] * half
        S = values["limit"] * half
        return c, S

    def parameters(self, ctx, kinds):
        # the limit may sit just inside the measured half-span: the measured
        # extremes carry the noise's extremes (about 3 noise floors)
        return [Parameter("limit", 1.5, 0.97, 20.0, True), Parameter("centre", 0.0, -0.3, 0.3, False)]

    def initial_values(self, ctx, kinds):
        return [{"limit": L, "centre": 0.0} for L in (1.0, 1.05, 1.15, 1.4, 2.0, 4.0)]

    def fit_rows(self, y, values, ctx):
        c, S = self._map(values)
        return np.abs(y - c) < 0.98 * S

    def target(self, y, values, ctx):
        c, S = self._map(values)
        r = np.clip((y - c) / S, -0.98, 0.98)
        return c + S * np.arctanh(r), (1.0 - r ** 2) ** 2

    def output(self, u, values, ctx):
        c, S = self._map(values)
        return c + S * np.tanh((u - c) / S)

    def output_slope(self, u, values, ctx):
        """d output / d u (for the Gauss-Newton refinement of the weights)."""
        c, S = self._map(values)
        return 1.0 - np.tanh((u - c) / S) ** 2

    def describe(self, values):
        c, S = self._map(values)
        return {"part": self.description, "centre": float(f"{c:.6g}"), "limit": float(f"{S:.6g}")}
