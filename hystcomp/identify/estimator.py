"""A scikit-learn estimator around :func:`fit_weights` (scikit-learn optional)."""


import numpy as np

from .._validation import as_signal
from ._records import _index_of, _is_frame, _is_record_list, _is_series, _with_index
from .envelope_fit import fit
from .weights import fit_weights

try:       # scikit-learn is optional (pip install hystcomp[sklearn])
    from sklearn.base import BaseEstimator as _BaseEstimator
    from sklearn.base import RegressorMixin as _RegressorMixin
    from sklearn.exceptions import NotFittedError as _SklearnNotFitted
except ImportError:          # pragma: no cover - exercised without scikit-learn
    _BASES = ()
    _NOT_FITTED_BASES = (RuntimeError,)
else:
    _BASES = (_RegressorMixin, _BaseEstimator)
    _NOT_FITTED_BASES = (_SklearnNotFitted, RuntimeError)


class NotFittedError(*_NOT_FITTED_BASES):
    """Raised by :meth:`HysteresisRegressor.predict` before ``fit``: scikit-learn's
    ``NotFittedError`` (when installed) and a ``RuntimeError``.

    Examples
    --------
    >>> try:
    ...     HysteresisRegressor().predict([0.0, 1.0])
    ... except NotFittedError as exc:
    ...     print(exc)
    This HysteresisRegressor is not fitted yet; call fit(v, y) first
    """


_SEVERAL_FEATURES = ("the check fits random data with several feature columns; a hysteresis model has "
                     "one input signal, so X must be (n_samples, 1) and more columns are rejected")
#: scikit-learn's common checks that a model with memory cannot pass (the
#: prediction at a sample depends on the samples before it, and there is
#: one input signal, not a feature matrix), with the reason; pass to
#: ``check_estimator(est, expected_failed_checks=EXPECTED_FAILED_CHECKS)``
EXPECTED_FAILED_CHECKS = {
    **{name: _SEVERAL_FEATURES for name in (
        "check_dict_unchanged", "check_dont_overwrite_parameters", "check_dtype_object",
        "check_estimators_dtypes", "check_estimators_fit_returns_self", "check_estimators_overwrite_params",
        "check_estimators_pickle", "check_f_contiguous_array_estimator", "check_fit2d_predict1d",
        "check_fit_check_is_fitted", "check_fit_idempotent", "check_fit_score_takes_y",
        "check_n_features_in", "check_n_features_in_after_fitting", "check_pipeline_consistency",
        "check_positive_only_tag_during_fit", "check_readonly_memmap_input",
        "check_regressor_data_not_an_array", "check_regressors_int", "check_regressors_no_decision_function",
        "check_regressors_train", "check_sample_weights_list", "check_sample_weights_not_an_array",
        "check_sample_weights_not_overwritten", "check_sample_weights_pandas_series",
        "check_sample_weights_shape", "check_supervised_y_2d", "check_all_zero_sample_weights_error",
        "check_estimators_nan_inf")},
    "check_methods_sample_order_invariance": "the samples are a time record: the output at a sample "
                                             "depends on the samples before it (memory), so reordering "
                                             "them changes the predictions",
    "check_methods_subset_invariance": "memory: a prediction on a subset of the samples starts the "
                                       "model from its virgin state at the subset's first sample",
    "check_sample_weight_equivalence_on_dense_data": "memory: a sample of weight 0 still drives the "
                                                     "operators, so it is not the same as removing it",
    "check_fit1d": "a 1-D X is the input signal itself (accepted), not a malformed feature matrix",
}


def _signal(X, name="X"):
    """The input signal of an estimator argument: a 1-D array, an (n, 1)
    array or DataFrame, or a list of such records (returned as a list)."""
    if _is_frame(X):
        if X.shape[1] != 1:
            raise ValueError(f"Parameter {name} has {X.shape[1]} columns but should have 1: the input "
                             "signal (a model with memory has one input, not a feature matrix)")
        return X.iloc[:, 0]
    if _is_series(X):
        return X
    if _is_records(X):
        return [_signal(e, f"{name}[{j}]") for j, e in enumerate(X)]
    if hasattr(X, "toarray"):
        raise TypeError(f"Parameter {name} is a sparse matrix but should be a dense input signal")
    arr = np.asarray(X)
    if np.iscomplexobj(arr):
        raise ValueError(f"Parameter {name}: Complex data not supported; expected a real input signal")
    if arr.ndim == 2 and arr.shape[1] == 0:
        raise ValueError(f"Parameter {name}: Found array with 0 feature(s) (shape={arr.shape}) while a "
                         "minimum of 1 is required (the input signal)")
    if arr.ndim >= 1 and arr.shape[0] == 1:
        raise ValueError(f"Parameter {name} has 1 sample; a record needs an input that moves "
                         "(n_samples = 1 is not a record)")
    if arr.dtype.kind in "fc" and not np.all(np.isfinite(arr)):
        raise ValueError(f"Parameter {name} contains NaN or infinity; expected a finite input signal")
    if arr.ndim == 2:
        if arr.shape[1] != 1:
            raise ValueError(f"Parameter {name} has shape {arr.shape} but should be (n_samples, 1): the "
                             "input signal (a model with memory has one input, not a feature matrix)")
        return arr[:, 0]
    return arr


def _is_records(X):
    """A list of records: each element an array of more than one sample (a
    list of one-sample rows is an (n, 1) matrix)."""
    return (isinstance(X, (list, tuple)) and len(X) > 0
            and all(_is_frame(e) or (np.ndim(e) in (1, 2) and np.shape(e)[0] > 1) for e in X))


def _target(y, name="y"):
    if _is_frame(y):
        return _signal(y, name)
    if _is_records(y):
        return [_target(e, f"{name}[{j}]") for j, e in enumerate(y)]
    arr = y if _is_series(y) else np.asarray(y)
    if np.ndim(arr) == 2 and arr.shape[1] == 1:
        arr = arr[:, 0]
    return arr


# scikit-learn estimator
# ----------------------------------------------------------------------------
class HysteresisRegressor(*_BASES):
    """A scikit-learn style wrapper of :func:`fit_weights` and :func:`fit`.

    Hyper-parameters are set in ``__init__`` and stored unchanged;
    ``fit(X, y)`` returns ``self`` and sets the fitted attributes (names
    ending in ``_``); ``predict(X)`` runs the fitted model from its virgin
    state and adds the offset.  When scikit-learn is installed it is a
    scikit-learn estimator (``BaseEstimator``, ``RegressorMixin``:
    ``clone``, ``GridSearchCV``, ``cross_val_score``).

    X is the input signal: an array of shape (n_samples, 1) as
    scikit-learn passes it, a 1-D array, a one-column DataFrame or a
    Series; or a **list of records** (one per measurement, each from the
    virgin state).  Cross-validate over records, never over samples (the
    model has memory): ``cross_val_score(est, [v1, v2, v3], [y1, y2, y3],
    cv=3)``.  The common checks of scikit-learn that a model with memory
    cannot pass are listed, with the reason, in
    :data:`EXPECTED_FAILED_CHECKS` (``expected_failed_checks``).

    Parameters
    ----------
    model : {"pi", "mgpi", "gpi"}
    thresholds : array_like, optional
        Default: `n_thresholds` equally spaced over the data (as :func:`fit_weights`).
    envelope : None, Envelope or family name
        An :class:`~hystcomp.envelopes.Envelope` is used as given (for
        model="gpi" it sets gl = gr); a family name ("tanh", "atanh",
        "polynomial", "linear") is fitted by :func:`fit` (model="mgpi" only).
    envelope_left, envelope_right : Envelope, optional
        Given asymmetric envelopes (model "mgpi" or "gpi").
    asymmetric : bool
        With a family name: fit gl and gr apart.
    H : None, float or Envelope
        Memoryless term of model="gpi" (its coefficient is fitted).
    constraints, regularization, offset, n_thresholds, solver
        As in :func:`fit_weights`.

    Attributes
    ----------
    result_ : FitResult
    model_ : PI, MGPI or GPI
    weights_, p0_, offset_, thresholds_, rmse_ : the fitted values

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
    >>> true = PI([0.5, 1.0, 1.5], [0.3, 0.2, 0.1], p0=1.0)
    >>> est = HysteresisRegressor(model="pi", thresholds=[0.5, 1.0, 1.5]).fit(v, true.simulate(v))
    >>> np.round(est.weights_, 4).tolist()
    [0.3, 0.2, 0.1]
    >>> float(np.max(np.abs(est.predict(v) - true.simulate(v)))) < 1e-5
    True

    Cross-validation over three records (each fold fits two, scores one):

    >>> from sklearn.model_selection import cross_val_score
    >>> records = [a * np.sin(np.linspace(0, 12, 1500)) for a in (2.0, 2.5, 3.0)]
    >>> scores = cross_val_score(HysteresisRegressor(model="pi", thresholds=[0.5, 1.0, 1.5]),
    ...                          records, [true.simulate(r) for r in records], cv=3)
    >>> bool(np.all(scores > 0.999))
    True
    """

    #: scikit-learn's common checks a model with memory cannot pass (see the module)
    expected_failed_checks = EXPECTED_FAILED_CHECKS

    if _BASES:
        # no metadata routing of sample_weight / validation (scikit-learn would
        # add set_fit_request and set_score_request, whose docstrings do not
        # build in hystcomp's docs); pass them to fit() and score() directly
        from sklearn.utils import metadata_routing as _routing

        # (v is the input signal, scikit-learn's X, not metadata)
        __metadata_request__fit = {"v": _routing.UNUSED, "sample_weight": _routing.UNUSED,
                                   "validation": _routing.UNUSED}
        __metadata_request__predict = {"v": _routing.UNUSED}
        __metadata_request__score = {"v": _routing.UNUSED, "sample_weight": _routing.UNUSED}
        del _routing

    def __init__(self, model="mgpi", thresholds=None, envelope=None, envelope_left=None,
                 envelope_right=None, asymmetric=False, H=None, constraints="nonnegative",
                 regularization=None, offset=True, n_thresholds=20, solver=None):
        self.model = model
        self.thresholds = thresholds
        self.envelope = envelope
        self.envelope_left = envelope_left
        self.envelope_right = envelope_right
        self.asymmetric = asymmetric
        self.H = H
        self.constraints = constraints
        self.regularization = regularization
        self.offset = offset
        self.n_thresholds = n_thresholds
        self.solver = solver

    _PARAMS = ("model", "thresholds", "envelope", "envelope_left", "envelope_right", "asymmetric",
               "H", "constraints", "regularization", "offset", "n_thresholds", "solver")

    def get_params(self, deep=True):
        """The hyper-parameters (dict), as scikit-learn's ``get_params``.

        Parameters
        ----------
        deep : bool
            Accepted for scikit-learn compatibility; the hyper-parameters
            hold no sub-estimators, so it changes nothing.

        Returns
        -------
        dict
            Hyper-parameter name -> value.

        Examples
        --------
        >>> HysteresisRegressor(model="pi", n_thresholds=5).get_params()["n_thresholds"]
        5
        """
        return {k: getattr(self, k) for k in self._PARAMS}

    def set_params(self, **params):
        """Set hyper-parameters; returns self.

        Parameters
        ----------
        **params
            Hyper-parameter name -> new value (names of ``__init__``).

        Returns
        -------
        HysteresisRegressor
            self.

        Raises
        ------
        ValueError
            For a name that is not a hyper-parameter.

        Examples
        --------
        >>> HysteresisRegressor().set_params(model="pi").model
        'pi'
        """
        for k, val in params.items():
            if k not in self._PARAMS:
                raise ValueError(f"Parameter {k!r} is not a hyper-parameter of HysteresisRegressor; "
                                 f"expected one of {list(self._PARAMS)}")
            setattr(self, k, val)
        return self

    def fit(self, v, y, sample_weight=None, validation=None):
        """Identify the model from input `v` and output `y` (arrays or lists
        of records); returns self.

        Parameters
        ----------
        v : array_like, shape (n_samples,) or (n_samples, 1), or list of them
            The input signal (scikit-learn's X: one column), or a list of
            records.
        y : array_like, shape (n_samples,), or list of them
            Measured output, as in :func:`fit_weights`.
        sample_weight : array_like or list, optional
            Non-negative weight per sample, as in :func:`fit_weights`.
        validation : None, float, boolean mask(s) or (v_val, y_val)
            Held-out data, as in :func:`fit_weights`.

        Returns
        -------
        HysteresisRegressor
            self, with the fitted attributes set.

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> est = HysteresisRegressor(model="pi", thresholds=[1.0, 2.0])
        >>> est.fit(v, PI([1.0, 2.0], [0.5, 0.2], p0=1.0).simulate(v)) is est
        True
        """
        if y is None:
            raise ValueError("HysteresisRegressor requires y to be passed, but the target y is None")
        v, y = _signal(v, "X"), _target(y)
        if _is_series(sample_weight):
            sample_weight = sample_weight.to_numpy()
        kw = dict(thresholds=self.thresholds, constraints=self.constraints,
                  regularization=self.regularization, offset=self.offset,
                  n_thresholds=self.n_thresholds, solver=self.solver,
                  sample_weight=sample_weight, validation=validation)
        if isinstance(self.envelope, (str, tuple)):
            if self.model != "mgpi":
                raise ValueError(f"Parameter envelope is {self.envelope!r} (a family to fit) but "
                                 f"model is {self.model!r}; envelope families are fitted for 'mgpi'")
            res = fit(v, y, envelope=self.envelope, asymmetric=self.asymmetric, **kw)
        else:
            res = fit_weights(v, y, model=self.model, envelope=self.envelope,
                              envelope_left=self.envelope_left, envelope_right=self.envelope_right,
                              H=self.H, **kw)
        self.result_ = res
        self.model_ = res.model
        self.weights_ = res.weights
        self.p0_ = res.p0
        self.offset_ = res.offset
        self.thresholds_ = res.thresholds
        self.rmse_ = res.rmse
        self.n_features_in_ = 1
        return self

    def predict(self, v):
        """Model output plus offset for an input record (from the virgin state).

        Parameters
        ----------
        v : array_like, shape (n_samples,) or (n_samples, 1), or list of them
            Input record (scikit-learn's X), or a list of records.

        Returns
        -------
        ndarray or pandas.Series, shape (n_samples,), or list of them
            A Series on the input's index when the input had one.

        Raises
        ------
        NotFittedError
            Before :meth:`fit`.

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> true = PI([1.0, 2.0], [0.5, 0.2], p0=1.0)
        >>> est = HysteresisRegressor(model="pi", thresholds=[1.0, 2.0]).fit(v, true.simulate(v))
        >>> bool(np.allclose(est.predict(v), true.simulate(v), atol=1e-6))
        True
        """
        if not hasattr(self, "result_"):
            raise NotFittedError("This HysteresisRegressor is not fitted yet; call fit(v, y) first")
        x = _signal(v, "X")
        if isinstance(x, list):
            return [self.result_.predict(e) for e in x]
        return self.result_.predict(x)

    def score(self, v, y, sample_weight=None):
        """Coefficient of determination R^2 of ``predict(v)`` against y.

        Parameters
        ----------
        v : array_like, shape (n_samples,) or (n_samples, 1), or list of them
            Input record (scikit-learn's X), or a list of records (R^2 over
            all their samples).
        y : array_like, shape (n_samples,), or list of them
            Measured output.
        sample_weight : array_like, optional
            Weight per sample of the R^2 (as scikit-learn's ``score``).

        Returns
        -------
        float
            ``1 - sum(e^2) / sum((y - mean y)^2)``; 1 is a perfect fit.

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> y = PI([1.0, 2.0], [0.5, 0.2], p0=1.0).simulate(v)
        >>> est = HysteresisRegressor(model="pi", thresholds=[1.0, 2.0]).fit(v, y)
        >>> round(est.score(v, y), 6)
        1.0
        """
        pred = self.predict(v)
        y = _target(y)
        if isinstance(pred, list):
            if not isinstance(y, list) or len(y) != len(pred):
                raise ValueError(f"Parameter y should be a list of {len(pred)} records, one per input record")
            pred = np.concatenate([np.asarray(p) for p in pred])
            y = np.concatenate([as_signal(e, f"y[{j}]") for j, e in enumerate(y)])
        y = as_signal(y, "y")
        pred = np.asarray(pred, dtype=np.float64)
        if y.size != pred.size:
            raise ValueError(f"Parameter y has {y.size} samples but the input has {pred.size}")
        w = np.ones(y.size) if sample_weight is None else as_signal(sample_weight, "sample_weight")
        e = y - pred
        ybar = float(np.sum(w * y) / np.sum(w))
        return 1.0 - float(np.sum(w * e * e)) / float(np.sum(w * (y - ybar) ** 2))

    def __repr__(self):
        args = ", ".join(f"{k}={getattr(self, k)!r}" for k in self._PARAMS)
        return f"HysteresisRegressor({args})"


# ----------------------------------------------------------------------------
# the other models of the thesis's survey (issue 7): Preisach, KP, Bouc-Wen,
# backlash-like, Duhem, and a side-by-side comparison
