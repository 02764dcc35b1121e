"""The base of the model parts (:mod:`hystcomp.identify.parts`): the fitting
context (:class:`Context`), a part's nonlinear parameter (:class:`Parameter`),
the base class :class:`Part` and the registry (:func:`register`, ``PARTS``).
"""

from collections import OrderedDict, namedtuple

import numpy as np

__all__ = ["Parameter", "Context", "Part", "register", "PARTS", "SLOTS", "creep_time_range"]


Parameter = namedtuple("Parameter", ["name", "initial", "lower", "upper", "log", "reach"], defaults=(None,))
Parameter.__doc__ = """A nonlinear parameter of a part: name, initial value, bounds,
whether it is searched on a logarithmic scale, and optionally ``reach``:
wider bounds ``(lower, upper)`` that the search moves on to when its best
point ends at an edge of the first bounds (the first bounds are a prior
guess the data may push against; :meth:`VariableProjection.optimise`).

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
    fit_end : float or None
        Time [s] at which the samples the weights are fitted on end (the
        diagnosis holds out the rest); default `duration`.  Parts whose
        time functions must be extrapolated beyond it (:class:`SlowDrift`)
        place their knots before it.
    held_out : (float, float), sequence of them, or None
        Start and end time [s] of a held-out block inside the record, or of
        several (the diagnosis holds out a block in the middle when the
        record's end leaves the input range of the rest, or blocks spread
        over the record): the samples ``start <= t < end`` are not fitted,
        and parts with knots in time place none inside a block.

    Examples
    --------
    >>> ctx = Context(np.linspace(0, 2, 5), dt=0.1, origin=0.0, scale=2.0, duration=0.5)
    >>> ctx.x.tolist(), ctx.time.tolist()[:2]
    ([0.0, 0.25, 0.5, 0.75, 1.0], [0.0, 0.1])
    """

    def __init__(self, v, dt, origin, scale, duration, n_thresholds=20, noise=0.0, fit_end=None, held_out=None):
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
        self.fit_end = self.duration if fit_end is None else float(fit_end)
        self.held_out = _blocks(held_out)
        #: memo of the core's play columns (see :class:`~hystcomp.identify.search.VariableProjection`)
        self.core_cache = OrderedDict()
        #: memo of the additive parts' columns (see :func:`~hystcomp.identify.search._additive_columns`)
        self.additive_cache = OrderedDict()

    @property
    def fitted_until(self):
        """The time up to which the weights are fitted [s]: `fit_end`, or the
        duration when `fit_end` is unset or 0."""
        return self.fit_end if self.fit_end else self.duration

    def fitted_times(self):
        """Boolean mask of the samples in time the weights are fitted on: up
        to `fit_end`, outside the held-out block (None without time).

        Examples
        --------
        >>> ctx = Context(np.zeros(6), 1.0, 0.0, 1.0, 6.0, held_out=(2.0, 4.0))
        >>> ctx.fitted_times().tolist()
        [True, True, False, False, True, True]
        >>> Context(np.zeros(6), 1.0, 0.0, 1.0, 6.0, held_out=[(1.0, 2.0), (4.0, 5.0)]).fitted_times().tolist()
        [True, False, True, True, False, True]
        """
        if self.time is None:
            return None
        fit = self.time <= self.fitted_until
        for a, b in self.held_out or ():
            fit &= ~((self.time >= a - 1e-9 * self.dt) & (self.time < b - 1e-9 * self.dt))
        return fit

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
        ctx = Context(v, self.dt, self.origin, self.scale, self.duration, self.n_thresholds, self.noise,
                      self.fit_end, self.held_out)
        ctx.thresholds = self.thresholds.copy()      # set thresholds carry over (diagnose sets its own)
        return ctx


def _blocks(held_out):
    """Held-out blocks as a tuple of (start, end) pairs in time order, or
    None: `held_out` is None, one (start, end) pair or a sequence of them."""
    if held_out is None or len(held_out) == 0:
        return None
    if np.ndim(held_out) == 1:
        held_out = [held_out]
    return tuple(sorted((float(a), float(b)) for a, b in held_out))


class Part:
    """Base class of a model part (see the module docstring).

    Subclasses set ``effect`` (the effect they model, or None for a part
    every model has), ``kind`` (a unique name), ``slot``, ``needs_time`` and
    ``description``, declare :meth:`parameters`, and implement the hook of
    their slot.

    Examples
    --------
    >>> from hystcomp.identify.parts import Drift
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
    #: the diagnosis' tie-break between parts that fit equally well with as
    #: many nonlinear parameters: the lower rank is named (see
    #: :data:`hystcomp.diagnose.revise.PARSIMONY`)
    occam_rank = 1

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
        hit = getattr(self, "_driven", None)
        if hit is None or hit[0] != key:
            # key and output in one attribute: a part shared by candidates fitted on
            # threads never pairs one context's key with another's output
            hit = self._driven = (key, self.driver.simulate(ctx.v))
        return hit[1]

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
    ['activated_plays', 'input_lag', 'input_slew', 'mount_recoil', 'output_lag', 'output_resonance', 'rate_term', 'rate_thresholds', 'viscous_plays']
    """
    if not (isinstance(cls, type) and issubclass(cls, Part)):
        raise TypeError(f"Parameter cls is {cls!r} but should be a subclass of Part")
    if cls.slot not in SLOTS:
        raise ValueError(f"Part {cls.__name__} has slot {cls.slot!r} but should have one of {SLOTS}")
    if not cls.kind:
        raise ValueError(f"Part {cls.__name__} has no kind (a unique name)")
    PARTS[cls.kind] = cls
    return cls


def creep_time_range(ctx):
    """The time constants [s] the creep part spans, ``(shortest, longest)``:
    from ``max(20 dt, T/2000)`` (at most a tenth of the longest) to the
    record's length ``T`` (at least 10 dt).  A part of another effect whose
    own relaxation would reach into this range (a viscous play relaxing for
    seconds after a step) would draw creep; such parts keep their time
    constants below it.

    Examples
    --------
    >>> ctx = Context(np.zeros(20_000), 1e-3, 0.0, 1.0, 20.0)
    >>> creep_time_range(ctx)
    (0.02, 20.0)
    """
    hi = max(ctx.duration, 10 * ctx.dt)
    lo = min(max(20 * ctx.dt, ctx.duration / 2000), hi / 10)
    return lo, hi
