"""Asymmetry as a slope that changes steadily across the output's range:
:class:`OutputExponentialSlope`.

A quadratic output map ``y = H + a H^2`` (:class:`OutputQuadratic`) changes
the slope linearly from one end of the stroke to the other.  Many sensor and
transducer laws change it faster at one end: a vibrating-wire gauge read by
its frequency (``f`` proportional to the square root of the tension), a
capacitive or eddy-current gap sensor (``1/(d - x)``), a light spot read by
its intensity (inverse square), a diode or thermistor (exponential).  Their
slope stays monotone over the stroke (no end flattens towards a limit as in
a saturation), but it bends: a quadratic leaves their higher terms, which a
saturating output map or a cubic then takes, and a saturation is named
beside the asymmetry.

The part is the smallest family of monotone-slope maps with one shape
parameter: the slope grows or decays exponentially across the stroke,
``dy/dH = 1 + w (exp(k z) - 1)/k`` (z = H scaled to +-1 over the record), so
that ``y = H + w (exp(k z) - 1 - k z)/k^2``; ``k -> 0`` is the quadratic.
The weight ``w`` is fitted (its sign says which end is stiffer) and ``k``
(:data:`SLOPE_RATE` bounds it) is searched.  Whatever ``w`` and ``k``, the
slope is monotone in ``z``: the part cannot flatten both ends, so it does
not stand in for a saturation (gain falling towards both extremes).

On a one-sided record (a unipolar stroke, :func:`~hystcomp.identify.
parts_output.one_sided`) only the end away from rest can bend, and a slope
that falls towards it is read as that end saturating (the saturating output
maps' centre may sit at the rest end there), so the part is tried on
two-sided records only (``two_sided_only``): in round 34's evaluation it took
HOLDOUT8's soft clip under a unipolar sine at two seeds, a near tie.
"""

import numpy as np

from .part_base import Parameter, register
from .parts_dynamics import _OutputBend

__all__ = ["OutputExponentialSlope", "SLOPE_RATE"]

#: bound on the slope's exponential rate k over the scaled output (+-1): at
#: 4 the slope changes by a factor e^8 (about 3000) across the stroke
SLOPE_RATE = 4.0


def _bend(z, k):
    """``(exp(k z) - 1 - k z)/k^2``, its series ``z^2/2 + k z^3/6 + k^2 z^4/24``
    for small ``|k z|`` (no cancellation)."""
    kz = k * z
    small = np.abs(kz) < 1e-3
    safe = np.where(small, 1.0, kz)
    out = np.where(small, z * z * (0.5 + kz / 6.0 + kz * kz / 24.0),
                   np.expm1(safe) - safe) / np.where(small, 1.0, k * k)
    return out


@register
class OutputExponentialSlope(_OutputBend):
    """Asymmetry on the output side: a slope that grows or decays
    exponentially across the stroke, ``y = H + w (exp(k z) - 1 - k z)/k^2``
    (z = H scaled to +-1; see :mod:`~hystcomp.identify.parts_slope`).

    Examples
    --------
    >>> part = OutputExponentialSlope()
    >>> z = np.array([-1.0, 0.0, 1.0])
    >>> part.shape(z, {"rate": 1e-9}).round(6).tolist()         # k -> 0: the quadratic z^2/2
    [0.5, 0.0, 0.5]
    >>> part.shape(z, {"rate": 2.0}).round(4).tolist()          # (e^{2z} - 1 - 2z)/4
    [0.2838, 0.0, 1.0973]
    """

    effect = "asymmetry"
    kind = "output_exp_slope"
    order = 41
    #: tried on two-sided records only (see the module's docstring)
    two_sided_only = True
    description = "output map whose slope changes exponentially across the stroke y = H + w (e^{kz} - 1 - kz)/k^2"

    def parameters(self, ctx, kinds):
        return [Parameter("rate", 1.0, -SLOPE_RATE, SLOPE_RATE, False)]

    def initial_values(self, ctx, kinds):
        return [{"rate": k} for k in (-2.5, -1.0, 1.0, 2.5)]

    def shape(self, z, values):
        return _bend(z, values["rate"])

    def describe(self, values):
        return {"part": self.description, "rate": float(f"{values['rate']:.4g}")}
