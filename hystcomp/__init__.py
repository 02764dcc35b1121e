"""hystcomp: model and cancel actuator hysteresis in control loops.

The Prandtl-Ishlinskii family (PI, GPI and the modified generalized PI of
W. Ye's thesis), their loading curves and inverses (analytic and exact),
built on compiled operator kernels.

Layout, one way down: :mod:`~hystcomp.envelopes` ->
:mod:`~hystcomp.operators` -> :mod:`~hystcomp.models` (and the other
models of the thesis's survey: :mod:`~hystcomp.preisach`,
:mod:`~hystcomp.differential`; model parts in :mod:`~hystcomp.effects`) ->
:mod:`~hystcomp.inverses`, :mod:`~hystcomp.numerical_inverse`;
:mod:`~hystcomp.iosys` and :mod:`~hystcomp.loops` on top (python-control);
:mod:`~hystcomp.identify` and :mod:`~hystcomp.diagnose` beside them;
:mod:`~hystcomp.signals`, :mod:`~hystcomp.datasets` and :mod:`~hystcomp.data`
as inputs; :mod:`~hystcomp.plotting` at the edge; :mod:`~hystcomp.cli` last.
"""

from . import envelopes
from .envelopes import Atanh, Custom, Identity, Linear, Polynomial, Tanh
from .inverses import ExactInverse, GPIInverse, UnreachableWarning, tracking_error
from .models import GPI, MGPI, PI, HysteresisModel, StopPI, model_from_dict
from .operators import generalized_play, modified_play, play, stop

# models and model parts that register themselves with model_from_dict
from . import effects  # noqa: E402,F401
from .differential import BacklashLike, BoucWen, Duhem  # noqa: E402
from .numerical_inverse import NumericalInverse  # noqa: E402
from .preisach import KP, Preisach  # noqa: E402

__version__ = "0.1.0"

__all__ = [
    "envelopes",
    "Identity", "Linear", "Tanh", "Atanh", "Polynomial", "Custom",
    "play", "stop", "generalized_play", "modified_play",
    "HysteresisModel", "PI", "StopPI", "GPI", "MGPI", "model_from_dict",
    "ExactInverse", "GPIInverse", "UnreachableWarning", "tracking_error",
    "Preisach", "KP", "BoucWen", "BacklashLike", "Duhem", "NumericalInverse",
]
