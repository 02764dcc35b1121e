"""Differential-equation hysteresis models: Duhem (eqs. 1-2), Bouc-Wen
(eq. 3) and backlash-like (eqs. 4-6), integrated along the input path.

Each model is a Duhem model ``dw/dt = f1(w, v) v'_+ - f2(w, v) v'_-``
(eq. 1, with ``v'_+ = max(v', 0)`` and ``v'_- = max(-v', 0)``, eq. 2):
divided by dv it reads ``dw/dv = f1(w, v)`` while the input rises and
``dw/dv = f2(w, v)`` while it falls, with no time left in it.  Between two
samples the input is taken as monotone (as for the PI family), so each
sample step is integrated *in the input* from ``v_prev`` to ``v``: the
outputs depend on the samples only, not on the sampling times (rate
independence).

* :class:`BacklashLike` (eq. 5, Su, Stepanenko, Svoboda and Leung 2000):
  ``dw/dt = alpha |v'| (c v - w) + B1 v'``.  Linear in w on a monotone step,
  solved in closed form (eq. 6: ``w = c v + d(v)`` with
  ``d`` relaxing exponentially in v): exact to rounding.
* :class:`BoucWen` (eq. 3, Bouc 1971, Wen 1976; the thesis's naming):
  ``dw/dt = A v' - beta v' |w|^n - alpha |v'| |w|^(n-1) w``, output
  ``gain * v + w + offset`` (``gain = offset = 0`` is eq. 3 alone).  RK4
  sub-steps in v, their number chosen so that ``|dv| * stiffness <= 0.1``
  (``stiffness = n (|alpha| + |beta|) max(|w|, w_bound)^(n-1)``): the
  explicit scheme stays far inside its stability region however large the
  sample step.  Measured accuracy: see ``docs/other_models.md``.
* :class:`Duhem` with user shape functions ``f1(w, v, p)``, ``f2(w, v, p)``
  (``p`` a parameter array): RK4 with sub-steps of at most ``max_step`` in v.

State of every model: ``[v_prev, w]`` (default ``[0, 0]``: input 0, output
``gain * 0 + 0``).  None has an analytic inverse (thesis section 2.3):
``exact_inverse()`` returns a monotone solve per sample
(:class:`hystcomp.numerical_inverse.NumericalInverse`).
"""

import math

import numpy as np

from . import _kernels_other as _ko
from ._validation import as_scalar, as_signal, as_state
from .models import SCHEMA_VERSION, HysteresisModel, Invertibility, _MODELS, model_from_dict
from .preisach import _require_keys

__all__ = ["Duhem", "BoucWen", "BacklashLike"]


class _DifferentialModel(HysteresisModel):
    n_states = 2

    def default_state(self):
        """``[v_prev, w] = [0, 0]``."""
        return np.zeros(2)

    def _check_input_domain(self, x, finite=False):
        pass

    def _state(self, initial_state):
        if initial_state is None:
            return self.default_state()
        s = as_state(initial_state, 2)
        if not np.all(np.isfinite(s)):
            raise ValueError(f"Parameter initial_state is {s.tolist()} but [v_prev, w] must be finite")
        return s

    def exact_inverse(self, on_unreachable="clip", input_limits=None):
        """Numerical inverse compensator (monotone solve per sample),
        :class:`hystcomp.numerical_inverse.NumericalInverse`.

        Parameters
        ----------
        on_unreachable : {"clip", "raise"}
            What to do with a desired output the model cannot reach, as in
            :class:`~hystcomp.numerical_inverse.NumericalInverse`.
        input_limits : (float, float), optional
            Bounds of the compensator output (see
            :class:`~hystcomp.numerical_inverse.NumericalInverse` for the default).

        Returns
        -------
        NumericalInverse
        """
        from .numerical_inverse import NumericalInverse

        return NumericalInverse(self, on_unreachable=on_unreachable, input_limits=input_limits)

    from_dict = classmethod(lambda cls, d: model_from_dict(d, expected=cls))


class BoucWen(_DifferentialModel):
    """Bouc-Wen model (thesis eq. 3), integrated in the input.

    ``dw/dt = A v' - beta v' |w|^n - alpha |v'| |w|^(n-1) w``, output
    ``y = gain * v + sign * w + offset``.

    Parameters
    ----------
    A : float
        Slope of the loop at w = 0 (> 0).
    alpha, beta : float
        Shape parameters in the thesis's naming (``alpha`` multiplies
        ``|v'| |w|^(n-1) w``, ``beta`` multiplies ``v' |w|^n``; many papers
        call them beta and gamma the other way round).  The valid range is
        the bounded (BIBO-stable) class of Ikhouane and Rodellar (2007):
        ``alpha + beta > 0`` and ``alpha >= beta``.
    n : float
        Smoothness exponent, ``n >= 1``.
    gain : float, optional
        Linear term ``gain * v`` added to the output (>= 0; 0 is eq. 3
        alone, which saturates at :meth:`w_bound`).
    offset : float, optional
        Constant added to the output.
    sign : {1, -1}, optional
        Sign of w in the output.  w alone traces a clockwise,
        stop-like loop; piezo actuators are modelled as ``y = d v - w``
        (Low and Guo 1995), sign = -1, a counter-clockwise loop.

    Notes
    -----
    For a rising input and w > 0, ``dw/dv = A - (alpha + beta) w^n``, so w
    approaches ``w_bound = (A / (alpha + beta))^(1/n)``; with
    ``alpha >= beta`` the other branches move w towards the same band, and
    ``|w| <= max(|w_0|, w_bound)`` for every input (Ikhouane, Manosa and
    Rodellar 2007).  :meth:`output_bounds` is that bound (finite when
    ``gain = 0``).

    Examples
    --------
    >>> import numpy as np
    >>> m = BoucWen(A=1.0, alpha=0.5, beta=0.5, n=1.0)
    >>> y = m.simulate(3 * np.sin(np.linspace(0, 20, 2001)))
    >>> bool(np.abs(y).max() <= m.w_bound()), round(m.w_bound(), 6)
    (True, 1.0)
    >>> BoucWen(A=1.0, alpha=0.5, beta=0.5, n=0.5)
    Traceback (most recent call last):
    ...
    ValueError: Parameter n is 0.5 but should be >= 1 (the Bouc-Wen exponent)
    """

    _type = "BoucWen"

    def __init__(self, A, alpha, beta, n=1.0, gain=0.0, offset=0.0, sign=1):
        self.A = as_scalar(A, "A", positive=True)
        self.alpha = as_scalar(alpha, "alpha")
        self.beta = as_scalar(beta, "beta")
        self.n = as_scalar(n, "n")
        if self.n < 1.0:
            raise ValueError(f"Parameter n is {self.n} but should be >= 1 (the Bouc-Wen exponent)")
        if not self.alpha + self.beta > 0:
            raise ValueError(
                f"Parameters alpha = {self.alpha} and beta = {self.beta} have alpha + beta = "
                f"{self.alpha + self.beta} but should have alpha + beta > 0 (else w grows without bound)"
            )
        if not self.alpha >= self.beta:
            raise ValueError(
                f"Parameters alpha = {self.alpha} and beta = {self.beta} should satisfy alpha >= beta "
                "(the bounded class of Ikhouane and Rodellar; else w diverges on reversals)"
            )
        self.gain = as_scalar(gain, "gain", nonnegative=True)
        self.offset = as_scalar(offset, "offset")
        if sign not in (1, -1):
            raise ValueError(f"Parameter sign is {sign!r} but should be 1 or -1")
        self.sign = int(sign)
        self._prm = np.array([self.A, self.alpha, self.beta, self.n, self.w_bound(), float(self.sign)])

    def w_bound(self):
        """``(A / (alpha + beta))^(1/n)``: the loop's saturation level of w."""
        return (self.A / (self.alpha + self.beta)) ** (1.0 / self.n)

    @property
    def n_parameters(self):
        return 6

    def simulate(self, v, initial_state=None, return_state=False):
        """Output for the input samples `v`; state ``[v_prev, w]`` (see
        :meth:`hystcomp.models.HysteresisModel.simulate`).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (2,), optional
            ``[v_prev, w]`` at the start: the previous input and the
            internal variable w; default ``[0, 0]`` (the virgin state at v = 0).
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        y : ndarray, shape (n_samples,)
            Model output.
        state : ndarray, shape (2,)
            Final ``[v_prev, w]``; only with ``return_state=True``.

        Examples
        --------
        >>> import numpy as np
        >>> m = BoucWen(A=1.0, alpha=0.5, beta=0.5, n=1.0)
        >>> np.round(m.simulate([0.0, 1.0, 2.0]), 6).tolist()   # 1 - exp(-v) towards w_bound = 1
        [0.0, 0.632121, 0.864665]
        >>> v = 3 * np.sin(np.linspace(0, 20, 2001))
        >>> y1, s = m.simulate(v[:1000], return_state=True)
        >>> bool(np.array_equal(np.concatenate([y1, m.simulate(v[1000:], initial_state=s)]), m.simulate(v)))
        True
        """
        x = as_signal(v, "v")
        s = self._state(initial_state)
        y = np.empty(x.size)
        _ko.diff_sum(_ko.BOUC_WEN, self._prm, self.gain, self.offset, x, s, y)
        return (y, s) if return_state else y

    def max_slope(self):
        """Largest dw/dv over the band ``|w| <= w_bound``:
        ``A + (alpha - beta) w_bound^n`` (reached right after a reversal)."""
        return self.A + (self.alpha - self.beta) * self.w_bound() ** self.n

    def output_bounds(self):
        """``offset -+ w_bound`` from the virgin state when ``gain = 0``
        (with a slack of 1e-9 relative for the integration); unbounded
        otherwise."""
        if self.gain != 0.0:
            return (-np.inf, np.inf)
        b = self.w_bound() * (1 + 1e-9)
        return (self.offset - b, self.offset + b)

    def is_invertible(self):
        """No analytic inverse; the numerical one needs an output that
        increases with the input (true in the valid range)."""
        return Invertibility(["the Bouc-Wen model has no analytic inverse (thesis section 2.3); "
                              "model.exact_inverse() gives a numerical one"])

    def _key(self):
        return (self.A, self.alpha, self.beta, self.n, self.gain, self.offset, self.sign)

    def to_dict(self):
        return {"schema_version": SCHEMA_VERSION, "model": self._type, "A": self.A, "alpha": self.alpha,
                "beta": self.beta, "n": self.n, "gain": self.gain, "offset": self.offset, "sign": self.sign}

    @classmethod
    def _from_dict(cls, d):
        _require_keys(d, ("A", "alpha", "beta", "n"))
        return cls(d["A"], d["alpha"], d["beta"], d["n"], d.get("gain", 0.0), d.get("offset", 0.0),
                   d.get("sign", 1))

    def __repr__(self):
        return (f"BoucWen(A={self.A!r}, alpha={self.alpha!r}, beta={self.beta!r}, n={self.n!r}, "
                f"gain={self.gain!r}, offset={self.offset!r}, sign={self.sign})")


class BacklashLike(_DifferentialModel):
    """Backlash-like model (thesis eqs. 5-6, Su et al. 2000).

    ``dw/dt = alpha |v'| (c v - w) + B1 v'``, output ``w + offset``.

    Parameters
    ----------
    alpha : float
        Rate at which w relaxes towards the branch (> 0).
    c : float
        Slope of the centre line ``c v`` (> 0).
    B1 : float
        Slope right after a reversal, ``0 < B1 <= c`` (Su et al.'s ``c > B1``;
        ``B1 = c`` is the line ``w = c v + const``).
    offset : float, optional
        Constant added to the output.

    Notes
    -----
    Writing ``w = c v + d`` (eq. 6), ``dd/dv = -s alpha d + (B1 - c)`` on a
    step of direction s = +-1: ``d`` relaxes exponentially in v towards
    ``s (B1 - c) / alpha``, which the simulation applies exactly per sample.
    So ``|w - c v| <= max(|d_0|, (c - B1) / alpha)`` for every input.

    Examples
    --------
    >>> import numpy as np
    >>> m = BacklashLike(alpha=1.0, c=3.0, B1=1.0)
    >>> v = 5 * np.sin(np.linspace(0, 30, 3001))
    >>> bool(np.abs(m.simulate(v) - 3 * v).max() <= 2.0)
    True
    """

    _type = "BacklashLike"

    def __init__(self, alpha, c, B1, offset=0.0):
        self.alpha = as_scalar(alpha, "alpha", positive=True)
        self.c = as_scalar(c, "c", positive=True)
        self.B1 = as_scalar(B1, "B1", positive=True)
        if self.B1 > self.c:
            raise ValueError(
                f"Parameter B1 is {self.B1} but should be <= c = {self.c} (Su et al.'s condition "
                "c > B1; B1 > c turns the loop clockwise)"
            )
        self.offset = as_scalar(offset, "offset")
        self._prm = np.array([self.alpha, self.c, self.B1])

    @property
    def n_parameters(self):
        return 4

    def simulate(self, v, initial_state=None, return_state=False):
        """Output for the input samples `v`; state ``[v_prev, w]``.

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (2,), optional
            ``[v_prev, w]`` at the start: the previous input and the
            internal variable w; default ``[0, 0]`` (the virgin state at v = 0).
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        y : ndarray, shape (n_samples,)
            Model output.
        state : ndarray, shape (2,)
            Final ``[v_prev, w]``; only with ``return_state=True``.

        Examples
        --------
        >>> m = BacklashLike(alpha=1.0, c=3.0, B1=1.0)
        >>> y, s = m.simulate([0.0, 1.0, 2.0], return_state=True)
        >>> [round(float(x), 6) for x in y], [round(float(x), 6) for x in s]
        ([0.0, 1.735759, 4.270671], [2.0, 4.270671])
        """
        x = as_signal(v, "v")
        s = self._state(initial_state)
        y = np.empty(x.size)
        _ko.diff_sum(_ko.BACKLASH, self._prm, 0.0, self.offset, x, s, y)
        return (y, s) if return_state else y

    def output_bounds(self):
        """Unbounded: w follows ``c v``."""
        return (-np.inf, np.inf)

    def is_invertible(self):
        return Invertibility(["the backlash-like model has no analytic inverse in hystcomp; "
                              "model.exact_inverse() gives a numerical one"])

    def _key(self):
        return (self.alpha, self.c, self.B1, self.offset)

    def to_dict(self):
        return {"schema_version": SCHEMA_VERSION, "model": self._type, "alpha": self.alpha, "c": self.c,
                "B1": self.B1, "offset": self.offset}

    @classmethod
    def _from_dict(cls, d):
        _require_keys(d, ("alpha", "c", "B1"))
        return cls(d["alpha"], d["c"], d["B1"], d.get("offset", 0.0))

    def __repr__(self):
        return f"BacklashLike(alpha={self.alpha!r}, c={self.c!r}, B1={self.B1!r}, offset={self.offset!r})"


def _compile_shape(f, params):
    """A numba-compiled version of a shape function, or None."""
    try:
        from numba import njit

        g = njit(f) if not hasattr(f, "py_func") else f
        float(g(0.0, 0.0, params))
        return g
    except Exception:  # not compilable: fall back to Python
        return None


_DUHEM_KERNELS = {}


def _duhem_kernel(f1, f2):
    """A compiled RK4 loop specialised to the shape functions (not cached on
    disk: user functions change from run to run)."""
    key = (f1, f2)
    if key in _DUHEM_KERNELS:
        return _DUHEM_KERNELS[key]
    from numba import njit

    @njit
    def run(x, p, max_step, gain, offset, state, y):
        v0 = state[0]
        w = state[1]
        for t in range(x.size):
            v1 = x[t]
            dv = v1 - v0
            if dv != 0.0:
                m = int(math.ceil(abs(dv) / max_step))
                if m < 1:
                    m = 1
                hs = dv / m
                for q in range(m):
                    va = v0 + q * hs
                    if dv > 0:
                        k1 = f1(w, va, p)
                        k2 = f1(w + 0.5 * hs * k1, va + 0.5 * hs, p)
                        k3 = f1(w + 0.5 * hs * k2, va + 0.5 * hs, p)
                        k4 = f1(w + hs * k3, va + hs, p)
                    else:
                        k1 = f2(w, va, p)
                        k2 = f2(w + 0.5 * hs * k1, va + 0.5 * hs, p)
                        k3 = f2(w + 0.5 * hs * k2, va + 0.5 * hs, p)
                        k4 = f2(w + hs * k3, va + hs, p)
                    w = w + hs * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0
            v0 = v1
            y[t] = gain * v1 + w + offset
        state[0] = v0
        state[1] = w

    _DUHEM_KERNELS[key] = run
    return run


def _duhem_python(f1, f2, x, p, max_step, gain, offset, state, y):
    v0, w = float(state[0]), float(state[1])
    for t in range(x.size):
        v1 = float(x[t])
        dv = v1 - v0
        if dv != 0.0:
            m = max(1, int(math.ceil(abs(dv) / max_step)))
            hs = dv / m
            f = f1 if dv > 0 else f2
            for q in range(m):
                va = v0 + q * hs
                k1 = f(w, va, p)
                k2 = f(w + 0.5 * hs * k1, va + 0.5 * hs, p)
                k3 = f(w + 0.5 * hs * k2, va + 0.5 * hs, p)
                k4 = f(w + hs * k3, va + hs, p)
                w = w + hs * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0
        v0 = v1
        y[t] = gain * v1 + w + offset
    state[0], state[1] = v0, w


class Duhem(_DifferentialModel):
    """Duhem model (thesis eqs. 1-2) with user shape functions.

    ``dw/dt = f1(w, v) v'_+ - f2(w, v) v'_-``: ``dw/dv = f1(w, v, p)`` while
    the input rises, ``f2(w, v, p)`` while it falls (eq. 1 divided by
    ``|v'|``; with eq. 2's ``v'_-`` >= 0, eq. 1's ``-f2 v'_-`` equals
    ``f2 v'`` then).  Output ``gain * v + w + offset``.

    Parameters
    ----------
    f1, f2 : callable ``(w, v, p) -> float``
        Slopes dw/dv on rising and falling inputs; ``p`` is `params` as a
        float array.  Functions numba can compile (plain arithmetic and
        ``math``) run compiled; others run in Python (slower, same result
        up to rounding).
    params : array_like, optional
        Parameters passed to the shape functions (what :func:`hystcomp.identify.fit_duhem` fits).
    max_step : float
        Largest RK4 sub-step in the input (> 0): the accuracy knob.  The
        global error of RK4 falls as ``max_step^4``; choose it small
        against the input scale over which the slopes change.
    gain, offset : float, optional
        Linear term ``gain * v`` and constant added to the output.

    Notes
    -----
    A Duhem model is rate independent (its right-hand side is homogeneous
    of degree 1 in v'), which the integration in v keeps by construction.
    User functions cannot be written to JSON: :meth:`to_dict` raises.

    Examples
    --------
    The backlash-like model as a Duhem model:

    >>> import numpy as np
    >>> f1 = lambda w, v, p: p[0] * (p[1] * v - w) + p[2]
    >>> f2 = lambda w, v, p: -p[0] * (p[1] * v - w) + p[2]
    >>> duhem = Duhem(f1, f2, params=[1.0, 3.0, 1.0], max_step=0.01)
    >>> v = 5 * np.sin(np.linspace(0, 10, 501))
    >>> exact = BacklashLike(1.0, 3.0, 1.0).simulate(v)
    >>> bool(np.abs(duhem.simulate(v) - exact).max() < 1e-9)
    True
    """

    _type = "Duhem"

    def __init__(self, f1, f2, params=(), max_step=0.01, gain=0.0, offset=0.0):
        for name, f in (("f1", f1), ("f2", f2)):
            if not callable(f):
                raise TypeError(f"Parameter {name} is {f!r} but should be a callable f(w, v, p)")
        self.f1, self.f2 = f1, f2
        self.params = np.atleast_1d(np.asarray(params, dtype=np.float64)).copy()
        if self.params.size == 0:
            self.params = np.zeros(1)
        if not np.all(np.isfinite(self.params)):
            raise ValueError(f"Parameter params is {self.params.tolist()} but should be finite")
        self.max_step = as_scalar(max_step, "max_step", positive=True)
        self.gain = as_scalar(gain, "gain")
        self.offset = as_scalar(offset, "offset")
        c1, c2 = _compile_shape(f1, self.params), _compile_shape(f2, self.params)
        self._kernel = _duhem_kernel(c1, c2) if (c1 is not None and c2 is not None) else None

    @property
    def compiled(self):
        """True when the shape functions run compiled (numba)."""
        return self._kernel is not None

    @property
    def n_parameters(self):
        return self.params.size + 2

    def with_params(self, params, gain=None, offset=None):
        """A copy with new parameters (shares the compiled kernel).

        Parameters
        ----------
        params : array_like
            New parameters of the shape functions.
        gain, offset : float, optional
            New gain and offset; default the current ones.

        Returns
        -------
        Duhem

        Examples
        --------
        >>> f1 = lambda w, v, p: p[0] * (p[1] * v - w) + p[2]
        >>> f2 = lambda w, v, p: -p[0] * (p[1] * v - w) + p[2]
        >>> m = Duhem(f1, f2, params=[1.0, 3.0, 1.0]).with_params([2.0, 3.0, 1.0], offset=1.0)
        >>> m.params.tolist(), m.gain, m.offset
        ([2.0, 3.0, 1.0], 0.0, 1.0)
        """
        new = Duhem.__new__(Duhem)
        new.__dict__.update(self.__dict__)
        new.params = np.atleast_1d(np.asarray(params, dtype=np.float64)).copy()
        if gain is not None:
            new.gain = float(gain)
        if offset is not None:
            new.offset = float(offset)
        return new

    def simulate(self, v, initial_state=None, return_state=False):
        """Output for the input samples `v`; state ``[v_prev, w]``.

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (2,), optional
            ``[v_prev, w]`` at the start: the previous input and the
            internal variable w; default ``[0, 0]`` (the virgin state at v = 0).
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        y : ndarray, shape (n_samples,)
            Model output.
        state : ndarray, shape (2,)
            Final ``[v_prev, w]``; only with ``return_state=True``.

        Raises
        ------
        FloatingPointError
            If the output diverges (unbounded shape functions).

        Examples
        --------
        >>> f1 = lambda w, v, p: p[0] * (p[1] * v - w) + p[2]
        >>> f2 = lambda w, v, p: -p[0] * (p[1] * v - w) + p[2]
        >>> m = Duhem(f1, f2, params=[1.0, 3.0, 1.0], max_step=0.01)
        >>> [round(float(x), 6) for x in m.simulate([0.0, 1.0, 2.0])]   # = BacklashLike(1, 3, 1)
        [0.0, 1.735759, 4.270671]
        """
        x = as_signal(v, "v")
        s = self._state(initial_state)
        y = np.empty(x.size)
        if self._kernel is not None:
            self._kernel(x, self.params, self.max_step, self.gain, self.offset, s, y)
        else:
            _duhem_python(self.f1, self.f2, x, self.params, self.max_step, self.gain, self.offset, s, y)
        if not np.all(np.isfinite(y)):
            k = int(np.argmax(~np.isfinite(y)))
            raise FloatingPointError(
                f"The Duhem model's output diverged at sample index {k} (v = {x[k]:.6g}); check the "
                "shape functions and params (the loop must be bounded) or lower max_step"
            )
        return (y, s) if return_state else y

    def output_bounds(self):
        """Unknown in general: (-inf, inf)."""
        return (-np.inf, np.inf)

    def is_invertible(self):
        return Invertibility(["a Duhem model has no analytic inverse (thesis section 2.3); "
                              "model.exact_inverse() gives a numerical one"])

    def _key(self):
        return (self.f1, self.f2, tuple(self.params), self.max_step, self.gain, self.offset)

    def to_dict(self):
        raise TypeError("A Duhem model with user shape functions cannot be written to a dict/JSON "
                        "(functions are not data); use BoucWen or BacklashLike, or store params yourself")

    def __repr__(self):
        return (f"Duhem(f1={getattr(self.f1, '__name__', self.f1)!s}, f2={getattr(self.f2, '__name__', self.f2)!s}, "
                f"params={self.params.tolist()}, max_step={self.max_step!r})")


_MODELS.setdefault("BoucWen", BoucWen)
_MODELS.setdefault("BacklashLike", BacklashLike)
