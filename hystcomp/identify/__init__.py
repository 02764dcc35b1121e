"""Identification of PI and mGPI models (and of other hysteresis models) from measured data.

The output of a PI or symmetric mGPI model (eq. 49) is linear in its weights:

``y(t) = p0 gamma(v(t)) + sum_i p_i gamma(F_{r_i}[v](t)) + offset``

where F_r is the classical play (the state convention of
:mod:`hystcomp.models`: for one envelope the modified play equals
``gamma(F_r[v])``).  For given thresholds and envelope the weights are
therefore a linear least-squares problem with linear constraints.

The package is split by concern:

* :mod:`~hystcomp.identify.parts`: model parts (PI core, envelopes,
  rate-dependent thresholds, linear stages, creep, drift, delay, initial
  state, output clipping), each declaring its nonlinear parameters and
  returning its regressor columns and bounds for given values;
* :mod:`~hystcomp.identify.solver`: the one constrained least-squares solve
  (:func:`~hystcomp.identify.solver.solve_weights`: bounds, linear
  inequality constraints, penalties) that every front end calls;
* :mod:`~hystcomp.identify.search`: variable projection over the nonlinear
  parameters of a set of parts;
* :mod:`~hystcomp.identify.parallel_fits`: several such searches side by
  side (forked processes on Linux, threads elsewhere);
* front ends: :func:`fit_weights` (weights for given thresholds and envelope,
  Gram matrix accumulated block by block), :func:`fit` (envelope parameters by
  variable projection), :class:`HysteresisRegressor` (scikit-learn style),
  :func:`hystcomp.diagnose.diagnose` (which parts a record needs);
* validation: :func:`validate`, :func:`compensation_error`;
* other models: :func:`fit_preisach`, :func:`fit_kp`, :func:`fit_bouc_wen`,
  :func:`fit_backlash_like`, :func:`fit_duhem`, :func:`compare_models`.
"""

from .._doctest_home import method_examples
from .envelope_fit import EnvelopeFitResult, fit
from .estimator import HysteresisRegressor
from .other_models import (ModelComparison, ModelFit, compare_models, fit_backlash_like, fit_bouc_wen,
                           fit_duhem, fit_kp, fit_preisach)
from .weights import FitResult, ValidationResult, compensation_error, fit_weights, validate

__all__ = ["FitResult", "EnvelopeFitResult", "HysteresisRegressor", "fit_weights", "fit", "validate",
           "compensation_error", "ModelFit", "ModelComparison", "fit_preisach", "fit_kp",
           "fit_bouc_wen", "fit_backlash_like", "fit_duhem", "compare_models"]

# the public objects belong to hystcomp.identify (the documented API and the
# docstring checks of the test suite see them there; the submodules are how
# the code is organised, not API)
for _name in __all__:
    globals()[_name].__module__ = __name__
del _name
# their methods live in the submodules: name their examples here so that doctest runs them
__test__ = method_examples(*(globals()[_name] for _name in __all__ if isinstance(globals()[_name], type)))
# FitResult, EnvelopeFitResult and ModelFit are one class (the names are kept)
FitResult.__qualname__ = FitResult.__name__ = "FitResult"
