"""A model part of the stage's mounting (:mod:`hystcomp.identify.parts`): the
base recoiling on a compliant mount while the stroke is read from the ground.
"""

import numpy as np

from ..effects import LinearStage
from .part_base import Context, Parameter, register  # noqa: F401 (Context: the examples)
from .parts_dynamics import OutputResonance, _steady_filter

__all__ = ["MountRecoil"]


@register
class MountRecoil(OutputResonance):
    """The base recoiling on its mount under the stage's reaction force, the
    stroke read from the ground (:meth:`hystcomp.effects.LinearStage.recoil`):
    ``y = u - share s^2 / (s^2 + 2 zeta w s + w^2) u`` after the
    hysteresis (frequency [Hz], damping, share of the moving mass).

    Below the mount's mode the reading is the stroke with no first-order
    phase, so the part does not stand in for a lag or a dead time; above it
    the base takes a share of the stroke, and near it the base rings after
    every fast move.  The frequency spans :class:`OutputResonance`'s band.

    Examples
    --------
    >>> ctx = Context(np.ones(4), 0.01, 0.0, 1.0, 0.04)
    >>> [p.name for p in MountRecoil().parameters(ctx, set())]
    ['frequency', 'damping', 'share']
    >>> cols = np.ones((4, 1))
    >>> MountRecoil().filter(cols, {"frequency": 2.0, "damping": 0.2, "share": 0.1}, ctx).ravel().round(6).tolist()
    [1.0, 1.0, 1.0, 1.0]
    """

    effect = "rate_dependence"
    kind = "mount_recoil"
    slot = "filter"
    order = 25
    needs_time = True
    description = "the base recoiling on its mount, the stroke read from the ground"

    def parameters(self, ctx, kinds):
        # the resonance's frequency and damping, and the stage's share of the moving mass
        return super().parameters(ctx, kinds) + [Parameter("share", 0.1, 0.005, 0.6, True)]

    def initial_values(self, ctx, kinds):
        lo, hi = self._band(ctx)
        return [{"frequency": f, "damping": z, "share": a}
                for f in np.geomspace(lo, hi, 12) for z in (0.05, 0.25) for a in (0.05, 0.2)]

    def filter(self, columns, values, ctx):
        return _steady_filter(LinearStage.recoil(values["frequency"], values["damping"], values["share"], ctx.dt),
                              columns)
