"""Asymmetry carried by a saturating output map: the off-centre test of a
diagnosis (:func:`hystcomp.diagnose.search.run_search` calls it once the
search and its revision are done).

A symmetric actuator's characteristic is odd about its zero-input output,
``y(-v) - y0 = -(y(v) - y0)``: its saturation compresses both ends alike.  A
saturating output map ``y = c + S f((u - c)/S)`` (:class:`OutputTanh`,
:class:`OutputAlgebraic`) is odd about its centre ``c``, so it keeps the
record symmetric only when ``c`` sits at the core's zero-input output.  For a
PI core that is the offset weight: the plays are odd, and on a loop the two
branches at ``v = 0`` sit symmetrically about it (eq. 18).  A centre fitted
away from it saturates one end of the stroke sooner than the other: the
characteristic is asymmetric, and one map has drawn both effects, so that
no asymmetry part is left anything to add (neo-Hookean pads read through a
saturating gauge, a Preisach core with a skewed density).

The test names asymmetry beside the saturation when

- the record is two-sided (the input's span is at least
  :data:`~hystcomp.identify.parts_output.ONE_SIDED_SPAN` times its scale: on
  a unipolar stroke the map's centre may sit anywhere, as only the end away
  from rest saturates);
- the map's centre sits at least :data:`OFF_CENTRE` output half-spans from
  the offset; and
- it pays as an effect does: holding the centre at the offset, every other
  parameter refitted jointly (warm-started), raises the held-out mean square
  by at least ``MIN_GAIN`` noise variances and the training BIC by at least
  :data:`~hystcomp.diagnose.base.REST_BIC` (one parameter, "very strong"
  evidence).

Measured before the rule was set, on the 69 runs of the nineteen realistic
sets whose model ends with such a map: on two-sided records with a
symmetric saturation the centre sat 0.000-0.051 output half-spans from the
offset (0.05-0.06 on out-of-vocabulary cores whose parts stay tentative),
0.17-0.23 on the HOLDOUT18 pads + gauge pair and 0.74-1.17 on the held-out
set's strongly skewed Preisach core.
"""

from ..identify.parts_output import one_sided
from ..identify.search import Structure
from .base import REST_BIC

__all__ = ["OFF_CENTRE", "off_centre_test"]

#: the map's centre at least this many output half-spans from the core's
#: zero-input output (the offset) before the asymmetry is tested
OFF_CENTRE = 0.1


def off_centre_test(vp, ctx, struct, cur, sigma, rms_val, min_gain):
    """The off-centre test of a fitted model (see the module's docstring).

    Parameters
    ----------
    vp : VariableProjection
        The diagnosis's engine.
    ctx : Context
        The parts' context of the record.
    struct : Structure
        The final model's parts.
    cur : FitPoint
        Its fit.
    sigma : float
        The noise floor.
    rms_val : callable
        ``rms_val(fit_point)``: the held-out RMS.
    min_gain : float
        The held-out gain (noise variances) an effect must bring.

    Returns
    -------
    dict or None
        ``None`` when the model has no saturating map with a centre or the
        record is one-sided; else the test's figures: ``kind``,
        ``centre_off`` (half-spans), ``threshold``, ``gain`` (held-out,
        noise variances), ``bic_change`` (training BIC of the fitted centre
        less the held one's), ``rms_held`` (held-out RMS with the centre
        held), ``present`` (every condition met) and ``held`` (the fit with
        the centre held, or None when not refitted).
    """
    out = struct.output_part()
    if out is None or not hasattr(out, "held_at") or out.fixed_centre is not None:
        return None
    if ctx.n == 0 or one_sided(ctx) or "offset" not in cur.names:
        return None
    offset = float(cur.theta[cur.names.index("offset")])
    c, _ = out._map(cur.values[out.kind])
    off = (c - offset) / out.mid_half()[1]
    res = {"kind": out.kind, "centre": c, "offset": offset, "centre_off": off, "threshold": OFF_CENTRE,
           "gain": None, "bic_change": None, "rms_held": None, "present": False, "held": None}
    if abs(off) < OFF_CENTRE:
        return res
    held_part = out.held_at(offset)
    st = Structure([held_part if p is out else p for p in struct.parts])
    start = {k: {q: x for q, x in v.items() if not (k == out.kind and q == "centre")}
             for k, v in cur.values.items()}
    n_par = len(st.parameters(ctx))
    held = vp.optimise(st, start, free=None, max_evaluations=10 * n_par)
    gain = (rms_val(held) ** 2 - rms_val(cur) ** 2) / sigma ** 2
    dbic = cur.bic - held.bic
    res.update(gain=float(gain), bic_change=float(dbic), rms_held=float(rms_val(held)), held=held,
               present=bool(gain >= min_gain and dbic <= -REST_BIC))
    return res
