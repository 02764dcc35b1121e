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
    ``r_i + beta |dv/dt|``; :class:`ViscousPlays`: plays relaxing at a
    finite rate; :class:`ActivatedPlays`: relaxing by Eyring's sinh law;
    :class:`InitialState`: a preload history; :class:`RingingPreload`: one ending in a decaying alternation;
    :class:`StaircasePreload`: one of four free reversals);
``filter``
    maps the core's columns (:class:`OutputLag`, :class:`OutputResonance`:
    a linear stage after the hysteresis; :class:`MountRecoil`: the base
    recoiling on its mount; :class:`GainDrift`,
    :class:`SlowGainDrift`);
``additive``
    adds columns of its own (:class:`Creep`, :class:`Drift`,
    :class:`SlowDrift`, :class:`EventDrift`, and the offset);
``output``
    maps the linear prediction (:class:`OutputClip`: clipping of the output
    side; :class:`OutputTanh`, :class:`OutputAlgebraic`: smooth saturation),
    and says which samples the linear solve may use.

:class:`PICore` (thresholds spread up to the full input span, eq. 18) is
always there.  :mod:`hystcomp.identify.search` builds the columns of a set
of parts, solves for the weights with
:func:`hystcomp.identify.solver.solve_weights` and varies the nonlinear
parameters (variable projection); :class:`~hystcomp.identify.search.PartsModel`
is the fitted model built from the same parts.

Adding an effect is one class here (or in your own module) and one call of
:func:`register` (see docs/diagnose.md, "Write your own effect").

The parts live in :mod:`~hystcomp.identify.part_base` (the base class and
the registry), :mod:`~hystcomp.identify.parts_core`,
:mod:`~hystcomp.identify.parts_dynamics`, :mod:`~hystcomp.identify.parts_drift`,
:mod:`~hystcomp.identify.parts_mount`,
:mod:`~hystcomp.identify.parts_slope` and
:mod:`~hystcomp.identify.parts_output`;
importing this module registers every built-in part, in one place.
"""

from .part_base import PARTS, SLOTS, Context, Parameter, Part, register  # noqa: F401
from .parts_core import (ActivatedPlays, Asymmetry, InitialState, LevelThresholds, Offset, PICore,  # noqa: F401
                         RateThresholds, RingingPreload, Saturation, StaircasePreload, ViscousPlays)
from .parts_dynamics import (BackCreep, Creep, Delay, DriftingDelay, GainDrift, InputLag, OutputCubic, OutputHinge,  # noqa: F401
                             OutputLag, OutputQuadratic, OutputResonance, RateTerm, SlewLimit, SlowGainDrift)
from .parts_drift import Drift, EventDrift, SensorDrift, SlowDrift  # noqa: F401 (registers right after parts_dynamics)
from .parts_mount import MountRecoil  # noqa: F401
from .parts_slope import OutputExponentialSlope  # noqa: F401
from .parts_output import OutputClip, OutputAlgebraic, OutputTanh  # noqa: F401

__all__ = ["Parameter", "Context", "Part", "PICore", "Offset", "Delay", "DriftingDelay", "InputLag", "SlewLimit", "RateThresholds", "ViscousPlays", "ActivatedPlays",
           "LevelThresholds",
           "Asymmetry", "Saturation", "InitialState", "RingingPreload", "StaircasePreload", "OutputLag", "OutputResonance", "MountRecoil", "GainDrift", "SlowGainDrift", "Creep", "BackCreep", "RateTerm",
           "Drift", "SlowDrift", "EventDrift", "SensorDrift", "OutputQuadratic", "OutputExponentialSlope", "OutputCubic", "OutputHinge", "OutputClip", "OutputTanh",
           "OutputAlgebraic", "register", "PARTS"]
