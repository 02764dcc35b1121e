"""Model parts of the hysteresis core (:mod:`hystcomp.identify.parts`): the PI
core and the offset that every model has, and the options of the core's plays
(rate-dependent, level-dependent and asymmetric thresholds, saturating
envelopes, eq. 23, and an initial state).
"""


import numpy as np

from ._part_kernels import core_columns
from .part_base import Context, Parameter, Part, creep_time_range, register  # noqa: F401 (Context: the examples)

__all__ = ["PICore", "Offset", "RateThresholds", "ViscousPlays", "ActivatedPlays", "Asymmetry", "LevelThresholds",
           "Saturation", "InitialState", "RingingPreload", "StaircasePreload"]


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
                     float(options.get("level", 0.0)), float(options.get("decay", 0.0)),
                     float(options.get("overstress_scale", 0.0)))
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
class ViscousPlays(Part):
    """Plays whose state moves at a finite rate (viscoplastic plays): outside
    its band a play relaxes towards it with a time constant ``tau``,
    ``dw/dt = -(w - c) / tau`` with ``c`` the rate-independent play's value
    (the overstress law of Perzyna 1966; the Maxwell-slip elements of a
    friction or piezo model with a viscous damper in series).  A faster
    input leaves the states further behind, so the loops widen with the
    drive rate and round off at the reversals, which thresholds growing
    with ``|dv/dt|`` draw only at the rate's level.  ``tau -> 0`` is the
    PI core.

    Examples
    --------
    >>> ctx = Context(np.linspace(0, 1, 11), 0.01, 0.0, 1.0, 0.11)
    >>> opts = {}
    >>> ViscousPlays().core_options({"time_constant": 0.01}, ctx, opts)
    >>> round(opts["decay"], 6)        # exp(-dt / tau)
    0.367879
    """

    effect = "rate_dependence"
    kind = "viscous_plays"
    slot = "core"
    order = 12
    needs_time = True
    description = "viscous plays (state relaxing towards the play with time constant tau)"

    def _bounds(self, ctx):
        lo = 0.2 * ctx.dt
        return lo, max(0.05 * (ctx.duration or ctx.n * ctx.dt), 10.0 * lo)

    def parameters(self, ctx, kinds):
        lo, hi = self._bounds(ctx)
        return [Parameter("time_constant", min(max(5.0 * ctx.dt, lo), hi), lo, hi, True)]

    def initial_values(self, ctx, kinds):
        lo, hi = self._bounds(ctx)
        return [{"time_constant": min(max(m * ctx.dt, lo), hi)} for m in (1.0, 4.0, 16.0, 64.0, 256.0)]

    def core_options(self, values, ctx, options):
        options["decay"] = float(np.exp(-ctx.dt / values["time_constant"]))


@register
class ActivatedPlays(ViscousPlays):
    """Viscous plays whose overstress relaxes by Eyring's law of thermally
    activated flow (Eyring, J. Chem. Phys. 4 (1936) 283; the sinh flow law
    of viscoplasticity):
    ``d|w - c|/dt = -(s / tau) sinh(|w - c| / s)`` with ``c`` the
    rate-independent play's value.  Below the overstress scale ``s`` (in
    scaled input units) it is Perzyna's linear law of
    :class:`ViscousPlays` with time constant ``tau``; above it the states
    catch up exponentially faster, so the loops widen with the drive's rate
    less than in proportion and a fast sweep is not smeared out as by a
    linear viscosity.  ``s -> infinity`` is :class:`ViscousPlays`.  Its
    time constant stays below the creep part's (:func:`creep_time_range`):
    from a large overstress the sinh law relaxes logarithmically in time
    (``E = |w - c|/s >> 1``: ``sinh E ~ e^E / 2``, so ``E(t) = -ln(e^-E0 +
    t / 2 tau)``), and with a time constant of seconds that is log creep.

    Examples
    --------
    >>> ctx = Context(np.linspace(0, 1, 11), 0.01, 0.0, 1.0, 0.11)
    >>> opts = {}
    >>> ActivatedPlays().core_options({"time_constant": 0.01, "overstress_scale": 0.05}, ctx, opts)
    >>> round(opts["decay"], 6), opts["overstress_scale"]
    (0.367879, 0.05)
    """

    kind = "activated_plays"
    order = 13
    description = "thermally activated plays (overstress relaxing as sinh(overstress / s), time constant tau)"

    def _bounds(self, ctx):
        # below the creep part's time constants: the sinh law relaxing for
        # seconds after a step is logarithmic creep (see the class docstring),
        # and a play that did so would name creep "rate dependence"
        lo, hi = super()._bounds(ctx)
        return lo, max(min(hi, creep_time_range(ctx)[0]), 10.0 * lo)

    def parameters(self, ctx, kinds):
        return super().parameters(ctx, kinds) + [Parameter("overstress_scale", 0.05, 1e-3, 1.0, True)]

    def initial_values(self, ctx, kinds):
        # the viscous plays' middle time constants (4, 16 and 64 samples, within the
        # bounds), each with a small and a moderate overstress scale (1 and 5 % of the
        # input scale)
        return [dict(d, overstress_scale=s) for d in super().initial_values(ctx, kinds)[1:4] for s in (0.01, 0.05)]

    def core_options(self, values, ctx, options):
        super().core_options(values, ctx, options)
        options["overstress_scale"] = float(values["overstress_scale"])


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
    ``u2`` (scaled input) before the first sample.  Both are searched
    within a quarter of the input span beyond the record's input range and,
    when the best point ends at that edge, on up to one span beyond it
    (their ``reach``: an actuator parked after a run to the top of its
    stroke and recorded under a smaller drive; a quarter span alone left a
    run to 1.8 times the record's largest input 2-7 noise floors at the
    start, one span from the outset led the piezo record's search to a
    worse optimum).

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
    #: the preload's turning points, in order
    POINTS = ("u1", "u2")

    def parameters(self, ctx, kinds):
        lo, hi = float(ctx.x.min()), float(ctx.x.max())
        w = hi - lo
        reach = (lo - w, hi + w)
        return [Parameter("u1", hi, lo - 0.25 * w, hi + 0.25 * w, False, reach),
                Parameter("u2", lo, lo - 0.25 * w, hi + 0.25 * w, False, reach)]

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
        options["preload"] = [values[name] for name in self.POINTS]

    def describe(self, values):
        return {"part": self.description,
                "preload_scaled": [float(f"{values[name]:.4g}") for name in self.POINTS]}


@register
class RingingPreload(InitialState):
    """Memory left by a ringing move: the preload history of
    :class:`InitialState` (virgin -> ``u1`` -> ``u2``) goes on in a
    decaying alternation about the record's first input ``x0``, each
    reversal ``ringing`` times the last: ``x0 + (u2 - x0) (-q)^j``,
    ``j = 1, 2, ...``, down to 1e-4 of the input span.  An actuator parked
    by an underdamped servo rings about its set point before it settles
    (the overshoot of a second-order step response is
    ``exp(-pi zeta / sqrt(1 - zeta^2))`` a half cycle; Ogata, *Modern
    Control Engineering*, sec. 5-3): the alternation demagnetises the narrow
    plays and leaves the wide ones on the branches of the first
    reversals, where the two-point preload leaves every narrow play on one
    branch.  Under excursions that grow slowly that difference lasts for
    most of a record, and a slow drift drew it better (HOLDOUT15's servo
    memory, round 17).  ``u1`` and ``u2`` are searched as the two-point
    preload's, without its wider reach; the decay from 0.05 to 0.9; the centre
    and the span the alternation settles in are those of the record the part
    is prepared on (:meth:`prepare`; a part not prepared takes its
    context's).

    Examples
    --------
    >>> ctx = Context(np.array([0.0, 1.0, -1.0]), None, 0.0, 1.0, None)
    >>> opts = {}
    >>> RingingPreload().core_options({"u1": 0.5, "u2": -0.4, "ringing": 0.5}, ctx, opts)
    >>> [round(u, 4) for u in opts["preload"][:5]]
    [0.5, -0.4, 0.2, -0.1, 0.05]
    """

    kind = "ringing_preload"
    order = 91
    description = "preload history ending in a decaying alternation (the plays' initial state after ringing)"
    #: the alternation ends where its reversals fall below this share of the input span
    SETTLED = 1e-4

    def parameters(self, ctx, kinds):
        # u1 and u2 within a quarter span of the record's range, without the two-point
        # preload's wider reach: its second search took the part from 40 to 65 inner solves
        # a fit on the 40,000-sample benchmark (the two-point part keeps the reach)
        return [q._replace(reach=None) for q in super().parameters(ctx, kinds)] + [
            Parameter("ringing", 0.4, 0.05, 0.9, False)]

    def initial_values(self, ctx, kinds):
        lo, hi = float(ctx.x.min()), float(ctx.x.max())
        return [{"u1": u1, "u2": hi if u1 == lo else lo, "ringing": q} for u1 in (lo, hi) for q in (0.3, 0.6)]

    def prepare(self, y, ctx):
        # the alternation's centre and where it has settled come from the fitted record,
        # kept for any input the model is run on later (the preload is the record's
        # history, not the new input's), and not recomputed at every solve
        self._anchor = self._anchor_of(ctx)

    def _anchor_of(self, ctx):
        """``(centre, settled)``: the record's first input and SETTLED of its span."""
        return float(ctx.x[0]), self.SETTLED * max(float(np.ptp(ctx.x)), 1e-12)

    def core_options(self, values, ctx, options):
        anchor = getattr(self, "_anchor", None)
        x0, settled = self._anchor_of(ctx) if anchor is None else anchor
        pre = [values["u1"], values["u2"]]
        a, q = values["u2"] - x0, values["ringing"]
        while abs(a) * q > settled:
            a *= -q
            pre.append(x0 + a)
        options["preload"] = pre

    def describe(self, values):
        return dict(super().describe(values), ringing=float(f"{values['ringing']:.4g}"))


@register
class StaircasePreload(InitialState):
    """Memory left by a search that narrows onto a point: the preload
    history virgin -> ``u1`` -> ``u2`` -> ``u3`` -> ``u4`` -> the record's
    first sample, four free turning points.  A stochastic-approximation
    search (Kiefer and Wolfowitz 1952), a converter's self-test staircase or
    a demagnetising sequence cut short leaves its plays on the branches of
    several reversals of shrinking size, not of one reversal pair; the
    two-point preload of :class:`InitialState` draws only the widest of them,
    and on records whose widest excursion comes late the rest of the misfit
    went to a drift (HOLDOUT28's Kiefer-Wolfowitz memory, round 30).  Unlike
    :class:`RingingPreload` the reversals are free, not a geometric
    alternation about the first input.  Each point is searched within a
    quarter of the input span beyond the record's input range, without the
    two-point preload's wider reach.  The search starts from ``u1`` at
    either end of the range and, for ``f`` of 0.3 and 0.7, ``u2 = x0 + f
    (other end - x0)``, ``u3 = x0 + f (u1 - x0) / 2``, ``u4 = x0 + f (other
    end - x0) / 4`` (``x0`` the first input): reversals that shrink about
    the first input.

    Examples
    --------
    >>> ctx = Context(np.zeros(3), None, 0.0, 1.0, None)
    >>> opts = {}
    >>> StaircasePreload().core_options({"u1": 0.9, "u2": -0.5, "u3": 0.3, "u4": -0.1}, ctx, opts)
    >>> opts["preload"]
    [0.9, -0.5, 0.3, -0.1]
    """

    kind = "staircase_preload"
    order = 92
    description = "preload history of four free reversals (the plays' initial state after a search or self-test)"
    POINTS = ("u1", "u2", "u3", "u4")

    def parameters(self, ctx, kinds):
        lo, hi = float(ctx.x.min()), float(ctx.x.max())
        w = hi - lo
        return [Parameter(name, start, lo - 0.25 * w, hi + 0.25 * w, False)
                for name, start in zip(self.POINTS, (hi, lo, hi, lo))]

    def initial_values(self, ctx, kinds):
        lo, hi = float(ctx.x.min()), float(ctx.x.max())
        x0 = float(ctx.x[0])
        out = []
        for u1 in (lo, hi):
            other = hi if u1 == lo else lo
            for f in (0.3, 0.7):
                out.append({"u1": u1, "u2": x0 + f * (other - x0), "u3": x0 + 0.5 * f * (u1 - x0),
                            "u4": x0 + 0.25 * f * (other - x0)})
        return out
