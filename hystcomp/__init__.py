"""hystcomp: model and cancel actuator hysteresis in control loops.

The Prandtl-Ishlinskii family (PI, GPI and the modified generalized PI of
W. Ye's thesis), their loading curves and inverses (analytic and exact),
built on compiled operator kernels.

Layout, one way down: :mod:`~hystcomp.envelopes` ->
:mod:`~hystcomp.operators` -> :mod:`~hystcomp.models` ->
:mod:`~hystcomp.inverses`; :mod:`~hystcomp.thesis` holds the thesis's cases.
"""

from . import envelopes
from .envelopes import Atanh, Custom, Identity, Linear, Polynomial, Tanh
from .inverses import ExactInverse, GPIInverse, UnreachableWarning, tracking_error
from .models import GPI, MGPI, PI, HysteresisModel, StopPI, model_from_dict
from .operators import generalized_play, modified_play, play, stop

__version__ = "0.1.0"

__all__ = [
    "envelopes",
    "Identity", "Linear", "Tanh", "Atanh", "Polynomial", "Custom",
    "play", "stop", "generalized_play", "modified_play",
    "HysteresisModel", "PI", "StopPI", "GPI", "MGPI", "model_from_dict",
    "ExactInverse", "GPIInverse", "UnreachableWarning", "tracking_error",
]
