"""A scikit-learn style estimator around :func:`fit_weights`."""


import numpy as np

from .._validation import as_signal
from .envelope_fit import fit
from .weights import fit_weights

# scikit-learn style estimator
# ----------------------------------------------------------------------------
class HysteresisRegressor:
    """A scikit-learn style wrapper of :func:`fit_weights` and :func:`fit`.

    Hyper-parameters are set in ``__init__`` and stored unchanged;
    ``fit(v, y)`` returns ``self`` and sets the fitted attributes (names
    ending in ``_``); ``predict(v)`` runs the fitted model from its virgin
    state and adds the offset.  (It follows the estimator conventions without
    depending on scikit-learn: v is a 1-D signal, not a feature matrix,
    because the model has memory.)

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
    """

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
        v, y : array_like or list of array_like
            Input and measured output, as in :func:`fit_weights`.
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
        return self

    def predict(self, v):
        """Model output plus offset for an input record (from the virgin state).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input record.

        Returns
        -------
        ndarray, shape (n_samples,)

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
            raise RuntimeError("This HysteresisRegressor is not fitted yet; call fit(v, y) first")
        return self.result_.predict(v)

    def score(self, v, y):
        """Coefficient of determination R^2 of ``predict(v)`` against y.

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input record.
        y : array_like, shape (n_samples,)
            Measured output.

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
        y = as_signal(y, "y")
        e = y - self.predict(v)
        return 1.0 - float(e @ e) / float(np.sum((y - y.mean()) ** 2))

    def __repr__(self):
        args = ", ".join(f"{k}={getattr(self, k)!r}" for k in self._PARAMS)
        return f"HysteresisRegressor({args})"


# ----------------------------------------------------------------------------
# the other models of the thesis's survey (issue 7): Preisach, KP, Bouc-Wen,
# backlash-like, Duhem, and a side-by-side comparison
