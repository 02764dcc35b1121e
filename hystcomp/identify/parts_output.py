"""Model parts of the output side (:mod:`hystcomp.identify.parts`): clipping
and smooth saturation of the output.
"""

import copy

import numpy as np

from .part_base import Context, Parameter, Part, register  # noqa: F401 (Context: the examples)

__all__ = ["OutputClip", "OutputTanh", "OutputAlgebraic"]

#: largest shift of the output tanh's centre from the output's mid-range, in half-spans
CENTRE = 0.3


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

    #: the centre held at this value (relative to the output's mid-range, in
    #: half-spans) instead of fitted, when not None (:meth:`held_at`)
    fixed_centre = None

    def __init__(self):
        self.y_min, self.y_max = -1.0, 1.0

    def prepare(self, y, ctx):
        self.set_output_range(float(np.min(y)), float(np.max(y)))

    def held_at(self, level):
        """A copy of this map (the same output range) whose centre is held at
        the output level `level` (output units) instead of fitted: the
        symmetric map of the diagnosis's off-centre test.

        Examples
        --------
        >>> part = OutputTanh()
        >>> part.set_output_range(-1.0, 3.0)
        >>> held = part.held_at(0.0)
        >>> held.fixed_centre, [q.name for q in held.parameters(None, set())]
        (-0.5, ['limit'])
        >>> held.describe({"limit": 1.5})
        {'part': 'saturating output map y = c + S tanh((u - c)/S)', 'centre': 0.0, 'limit': 3.0}
        """
        other = copy.copy(self)
        mid, half = self.mid_half()
        other.fixed_centre = (float(level) - mid) / half
        return other

    def mid_half(self):
        """The output's mid-range and half-span (1 for a flat output): the
        units of the centre and the limit."""
        return 0.5 * (self.y_max + self.y_min), 0.5 * (self.y_max - self.y_min) or 1.0

    def _centred(self, params):
        """`params` without the centre when it is held (:meth:`held_at`)."""
        return [q for q in params if not (self.fixed_centre is not None and q.name == "centre")]

    def set_output_range(self, y_min, y_max):
        """The measured output's extremes.

        Parameters
        ----------
        y_min, y_max : float
            Smallest and largest measured output.
        """
        self.y_min, self.y_max = float(y_min), float(y_max)

    def _map(self, values):
        mid, half = self.mid_half()
        centre = values["centre"] if self.fixed_centre is None else self.fixed_centre
        c = mid + centre * half
        S = values["limit"] * half
        return c, S

    def parameters(self, ctx, kinds):
        # the limit may sit just inside the measured half-span: the measured
        # extremes carry the noise's extremes (about 3 noise floors)
        return self._centred([Parameter("limit", 1.5, 0.97, 20.0, True),
                              Parameter("centre", 0.0, -CENTRE, CENTRE, False)])

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


#: input span over its scale below which a record counts as one-sided (a unipolar
#: stroke 0 ... V has 1, a bipolar one 2); the diagnosis's play thresholds use it too
ONE_SIDED_SPAN = 1.5


def one_sided(ctx):
    """Whether the record of `ctx` is one-sided (a unipolar stroke: the
    scaled input's span is less than :data:`ONE_SIDED_SPAN`; False for an
    empty record)."""
    return np.ptp(ctx.x) < ONE_SIDED_SPAN if ctx.n else False


@register
class OutputAlgebraic(OutputTanh):
    """Saturation on the output side with a knee of any sharpness, the
    algebraic sigmoid ``y = c + S z / (1 + |z|^p)^(1/p)``, ``z = (u - c)/S``,
    for the linear prediction u.  ``p = 1`` is the Frohlich-Kennelly law of
    magnetic saturation, ``M = H / (a + b |H|)`` (Jiles, *Introduction to
    Magnetism and Magnetic Materials*, 3rd ed., 2015, sec. 5.4), whose
    distance to the limit falls as ``1/u``; larger ``p`` sharpen the knee
    (``p`` about 2.5 is close to :class:`OutputTanh`, ``p -> inf`` a clip).
    On a one-sided record (a unipolar stroke: the input's span is less than
    1.5 times its scale) the centre ``c`` may sit anywhere in the output's
    range, so that only the end away from rest saturates; on a two-sided
    record it stays within ``CENTRE`` half-spans of the mid-range as the
    tanh's does.  The linear solve fits ``u`` to the inverse map
    ``c + S r/(1 - |r|^p)^(1/p)``, ``r = (y - c)/S``, weighted by the map's
    slope squared.  Parameters: the limit ``S`` (in output half-spans), the
    centre and the exponent ``p`` (0.7 ... 8).

    Examples
    --------
    >>> part = OutputAlgebraic()
    >>> part.set_output_range(-1.0, 1.0)
    >>> ctx = Context(np.zeros(3), None, 0.0, 1.0, None)
    >>> part.output(np.array([0.0, 1.5, 1e6]), {"limit": 1.5, "centre": 0.0, "exponent": 1.0}, ctx).round(4).tolist()
    [0.0, 0.75, 1.5]
    """

    kind = "output_algebraic"
    description = "algebraic saturating output map y = c + S z/(1 + |z|^p)^(1/p), z = (u - c)/S"

    def parameters(self, ctx, kinds):
        c = 1.0 if one_sided(ctx) else CENTRE
        return self._centred([Parameter("limit", 2.0, 0.97, 40.0, True), Parameter("centre", 0.0, -c, c, False),
                              Parameter("exponent", 1.5, 0.7, 8.0, True)])

    def initial_values(self, ctx, kinds):
        out = [{"limit": L, "centre": 0.0, "exponent": p} for L in (1.05, 1.4, 2.5, 6.0) for p in (1.0, 2.0)]
        if one_sided(ctx):
            # the rest end of a unipolar stroke: the start of the record
            x = ctx.x
            side = -1.0 if abs(x[0] - x.min()) <= abs(x[0] - x.max()) else 1.0
            out += [{"limit": L, "centre": side, "exponent": p} for L in (2.5, 4.0, 8.0) for p in (1.0, 2.0)]
        return out

    def target(self, y, values, ctx):
        c, S = self._map(values)
        p = values["exponent"]
        r = np.clip((y - c) / S, -0.98, 0.98)
        a = np.abs(r) ** p
        return c + S * r / (1.0 - a) ** (1.0 / p), (1.0 - a) ** (2.0 + 2.0 / p)

    def output(self, u, values, ctx):
        c, S = self._map(values)
        p = values["exponent"]
        z = (u - c) / S
        return c + S * z / (1.0 + np.abs(z) ** p) ** (1.0 / p)

    def output_slope(self, u, values, ctx):
        """d output / d u (for the Gauss-Newton refinement of the weights)."""
        c, S = self._map(values)
        p = values["exponent"]
        return (1.0 + np.abs((u - c) / S) ** p) ** (-1.0 - 1.0 / p)
