"""Envelope functions: strictly increasing functions with inverse and derivative.

An envelope ``gamma`` shapes the boundaries of the generalized play (eq. 20)
and of the modified generalized play (eq. 23) of Ye's thesis.  Every envelope
here is vectorised over NumPy arrays and has

* ``env(v)`` its value, ``env.derivative(v)``, ``env.inverse(y)``;
* ``env.domain`` (inputs where it is defined) and ``env.range`` (its values);
* ``env.inverse_envelope()``, the envelope ``beta = gamma^-1`` (eq. 46/55);
* ``env.to_dict()`` / :func:`envelope_from_dict` for saving.

An input outside the domain, or NaN/inf, raises ``ValueError`` naming the
envelope, the bound and the first offending sample index.

Examples
--------
>>> from hystcomp.envelopes import Tanh
>>> g = Tanh(10.0, 0.2)
>>> float(g(1.0))
1.97375320224904
>>> float(g.inverse(g(1.0)))
1.0
"""

import math

import numpy as np

from . import _kernels as _k
from ._envelope_base import (Envelope, Inverse, _check_finite, _numeric_inverse, _same_shape,
                             _vkernel, extended_values)
from ._doctest_home import method_examples
from ._validation import as_float_array, as_scalar

__all__ = [
    "Envelope",
    "Identity",
    "Linear",
    "Tanh",
    "Atanh",
    "Polynomial",
    "Custom",
    "Inverse",
    "envelope_from_dict",
    "extended_values",
]


class Identity(Envelope):
    """gamma(v) = v.  With it the mGPI model is the classical PI model.

    Examples
    --------
    >>> Identity()(2.5)
    2.5
    """

    _kernel = (_k.IDENTITY, np.zeros(1))

    def _value(self, x):
        return x.copy()

    def _derivative(self, x):
        return np.ones_like(x)

    def _inverse(self, y):
        return y.copy()

    def inverse_envelope(self):
        return Identity()

    def _equal_key(self):
        return ("Identity",)

    def __repr__(self):
        return "Identity()"

    def to_dict(self):
        return {"type": "Identity"}


class Linear(Envelope):
    """gamma(v) = k v with k > 0 (thesis section 5.3 uses k = 3).

    Parameters
    ----------
    k : float
        The slope, > 0.

    Examples
    --------
    >>> Linear(3.0).inverse_envelope()
    Linear(k=0.3333333333333333)
    """

    def __init__(self, k):
        self.k = as_scalar(k, "k", positive=True)
        self._kernel = (_k.LINEAR, np.array([self.k]))

    def _value(self, x):
        return self.k * x

    def _derivative(self, x):
        return np.full_like(x, self.k)

    def _inverse(self, y):
        return y / self.k

    def inverse_envelope(self):
        return Linear(1.0 / self.k)

    def _equal_key(self):
        return ("Linear", self.k)

    def __repr__(self):
        return f"Linear(k={self.k!r})"

    def to_dict(self):
        return {"type": "Linear", "k": self.k}


class Tanh(Envelope):
    """gamma(v) = a tanh(b v + c), a > 0, b > 0: a saturating envelope.

    Its range is (-a, a), so a modified generalized play with it saturates at
    +-a (thesis section 3.5, eq. 29).

    Parameters
    ----------
    a : float
        Saturation level (amplitude), > 0.
    b : float
        Input gain, > 0.
    c : float, optional
        Input offset inside the tanh (default 0).

    Examples
    --------
    >>> g = Tanh(10.0, 0.2)
    >>> g.range
    (-10.0, 10.0)
    >>> g.inverse_envelope()
    Atanh(a=5.0, b=0.1, offset=-0.0)
    """

    def __init__(self, a, b, c=0.0):
        self.a = as_scalar(a, "a", positive=True)
        self.b = as_scalar(b, "b", positive=True)
        self.c = as_scalar(c, "c")
        self.range = (-self.a, self.a)
        self._kernel = (_k.TANH, np.array([self.a, self.b, self.c]))

    def _value(self, x):
        return self.a * np.tanh(self.b * x + self.c)

    def _derivative(self, x):
        t = np.tanh(self.b * x + self.c)
        return self.a * self.b * (1.0 - t * t)

    def _inverse(self, y):
        return (np.arctanh(y / self.a) - self.c) / self.b

    def inverse_envelope(self):
        # y = a tanh(b v + c)  <=>  v = (1/b) atanh(y / a) - c / b
        return Atanh(1.0 / self.b, 1.0 / self.a, offset=-self.c / self.b)

    def _equal_key(self):
        return ("Tanh", self.a, self.b, self.c)

    def __repr__(self):
        c = f", c={self.c!r}" if self.c != 0.0 else ""
        return f"Tanh(a={self.a!r}, b={self.b!r}{c})"

    def to_dict(self):
        return {"type": "Tanh", "a": self.a, "b": self.b, "c": self.c}


class Atanh(Envelope):
    """gamma(v) = a atanh(b v) + offset on the open domain ``|v| < 1/b``.

    Thesis section 5.4 uses gamma = atanh(0.5 v), i.e. ``Atanh(1, 0.5)``,
    whose inverse is beta = 2 tanh(v).

    Parameters
    ----------
    a : float
        Output gain, > 0.
    b : float
        Input gain, > 0; the domain is the open interval (-1/b, 1/b).
    offset : float, optional
        Added to the value (default 0).

    Examples
    --------
    >>> Atanh(1.0, 0.5).domain
    (-2.0, 2.0)
    >>> Atanh(1.0, 0.5).inverse_envelope()
    Tanh(a=2.0, b=1.0)
    """

    def __init__(self, a, b, offset=0.0):
        self.a = as_scalar(a, "a", positive=True)
        self.b = as_scalar(b, "b", positive=True)
        self.offset = as_scalar(offset, "offset")
        self.domain = (-1.0 / self.b, 1.0 / self.b)
        self._kernel = (_k.ATANH, np.array([self.a, self.b, self.offset]))

    def _value(self, x):
        return self.a * np.arctanh(self.b * x) + self.offset

    def _derivative(self, x):
        u = self.b * x
        return self.a * self.b / (1.0 - u * u)

    def _inverse(self, y):
        return np.tanh((y - self.offset) / self.a) / self.b

    def inverse_envelope(self):
        # y = a atanh(b v) + d  <=>  v = (1/b) tanh(y/a - d/a)
        return Tanh(1.0 / self.b, 1.0 / self.a, -self.offset / self.a)

    def _equal_key(self):
        return ("Atanh", self.a, self.b, self.offset)

    def __repr__(self):
        off = f", offset={self.offset!r}" if self.offset != 0.0 or math.copysign(1, self.offset) < 0 else ""
        return f"Atanh(a={self.a!r}, b={self.b!r}{off})"

    def to_dict(self):
        return {"type": "Atanh", "a": self.a, "b": self.b, "offset": self.offset}


class Polynomial(Envelope):
    """gamma(v) = sum_k coeffs[k] v**k on a closed interval where it increases.

    Parameters
    ----------
    coeffs : sequence of float
        Coefficients in increasing powers (``coeffs[k]`` multiplies v**k).
    interval : (float, float)
        The domain [lo, hi]; the polynomial is checked to be strictly
        increasing there (its derivative is >= 0, zero only at isolated
        points, as for v**3 at 0).

    Examples
    --------
    >>> g = Polynomial([0.0, 1.0, 0.0, 0.5], interval=(-3, 3))   # v + v^3/2
    >>> round(float(g.inverse(g(1.2))), 12)
    1.2
    """

    domain_open = False

    def __init__(self, coeffs, interval=(-1.0, 1.0)):
        c = as_float_array(coeffs, "coeffs").reshape(-1)
        if c.size < 2 or not np.all(np.isfinite(c)):
            raise ValueError(
                f"Parameter coeffs is {[float(x) for x in c]} but should hold at least two finite "
                "coefficients (increasing powers)"
            )
        try:
            lo, hi = (float(interval[0]), float(interval[1]))
        except (TypeError, IndexError, ValueError):
            raise ValueError(f"Parameter interval is {interval!r} but should be (lo, hi)") from None
        if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
            raise ValueError(f"Parameter interval is {interval!r} but should be finite with lo < hi")
        self.coeffs = c
        self.domain = (lo, hi)
        dpoly = np.polynomial.Polynomial(c).deriv()
        # roots of the derivative without its negligible leading coefficients
        # (a tiny c_n, e.g. 1e-300, would overflow the companion matrix)
        dc = dpoly.coef
        scale = float(np.max(np.abs(dc))) if dc.size else 0.0
        trimmed = np.polynomial.Polynomial(np.polynomial.polynomial.polytrim(dc, tol=1e-15 * scale))
        crit = [float(z.real) for z in trimmed.roots() if abs(z.imag) < 1e-12 and lo < z.real < hi]
        # the derivative's minimum on [lo, hi] is at an end or where the
        # second derivative vanishes: probe there (real parts of every root,
        # a root pair split by rounding included), not only on a grid
        ddc = trimmed.deriv().coef
        if ddc.size > 1 and np.any(ddc != 0):
            ddc = np.polynomial.polynomial.polytrim(ddc, tol=1e-15 * float(np.max(np.abs(ddc))))
            crit += [float(z.real) for z in np.polynomial.Polynomial(ddc).roots() if lo < z.real < hi]
        probe = np.concatenate([[lo, hi], np.linspace(lo, hi, 257), crit])
        # rounding of the expanded derivative near a double root: a dip below
        # -1e-12 of the derivative's scale on the interval is a real one
        dscale = scale * max(1.0, abs(lo), abs(hi)) ** max(dc.size - 1, 0)
        dmin = float(np.min(dpoly(probe))) if dpoly.degree() >= 0 else 0.0
        if -1e-12 * dscale <= dmin < 0:
            dmin = 0.0
        # a derivative root where the sign does not change (inside, or at an
        # end of the interval) is an isolated flat point: the polynomial is
        # still strictly increasing, so it is allowed as long as the
        # derivative is >= 0 everywhere and not identically 0.
        if dmin < 0 or np.all(dpoly(probe) <= 0):
            k = int(np.argmin(dpoly(probe)))
            raise ValueError(
                f"Polynomial(coeffs={[float(x) for x in c]}) is not increasing on {interval}: its "
                f"derivative is {float(dpoly(probe)[k])} at v = {float(probe[k])}"
            )
        self.range = (float(np.polynomial.Polynomial(c)(lo)), float(np.polynomial.Polynomial(c)(hi)))
        self._kernel = (_k.POLYNOMIAL, np.concatenate([[lo, hi], c]))

    def _value(self, x):
        return np.polynomial.polynomial.polyval(x, self.coeffs)

    def _derivative(self, x):
        return np.polynomial.polynomial.polyval(x, np.polynomial.polynomial.polyder(self.coeffs))

    def _inverse(self, y):
        kind, prm = self.kernel_spec()
        return _vkernel(kind, prm, y, _k.env_inverse)

    def inverse(self, y):
        """Inverse gamma^-1(y) on the closed range [gamma(lo), gamma(hi)].

        Solved per sample by a safeguarded Newton iteration in the compiled
        kernels.

        Parameters
        ----------
        y : float or array_like
            Values inside the closed range (its ends included).

        Returns
        -------
        float or ndarray
            gamma^-1(y), a float for a scalar `y`, else an array of `y`'s shape.

        Raises
        ------
        ValueError
            If a value is not finite or lies outside the range.

        Examples
        --------
        >>> g = Polynomial([0.0, 1.0, 0.0, 1.0], interval=(-1, 1))   # v + v^3
        >>> round(float(g.inverse(2.0)), 12)                        # range end
        1.0
        """
        x = as_float_array(y, "y")
        _check_finite(self, x, "y")
        lo, hi = self.range
        bad = ((x < lo) | (x > hi)).reshape(-1)
        if bad.any():
            k = int(np.argmax(bad))
            raise ValueError(
                f"{self!r}.inverse: parameter y holds {x.reshape(-1)[k]} at sample index {k}, outside "
                f"the envelope's range [{lo}, {hi}]"
            )
        return _same_shape(self._inverse(x), y)

    def _equal_key(self):
        return ("Polynomial", tuple(self.coeffs), self.domain)

    def __repr__(self):
        return f"Polynomial(coeffs={list(map(float, self.coeffs))}, interval={self.domain})"

    def to_dict(self):
        return {"type": "Polynomial", "coeffs": [float(x) for x in self.coeffs],
                "interval": [self.domain[0], self.domain[1]]}


class Custom(Envelope):
    """A user envelope from vectorised functions f (value) and df (derivative).

    Parameters
    ----------
    f, df : callable
        Vectorised functions of a NumPy array: the value and its derivative.
        f must be strictly increasing on `domain`.
    finv : callable, optional
        The inverse; when omitted a safeguarded Newton iteration (bracketed
        by bisection) inverts `f` numerically to 1e-14 relative accuracy.
    domain : (float, float), optional
        Open interval of admissible inputs (default the real line).
    range : (float, float), optional
        (inf, sup) of the values; computed from the domain ends when omitted.
    name : str, optional
        Shown in messages.

    Notes
    -----
    Operators with a Custom envelope run block by block in NumPy around the
    compiled play kernel (memory bounded by the block size), so they are
    slower than the built-in envelopes but exact.

    Examples
    --------
    >>> import numpy as np
    >>> g = Custom(np.sinh, np.cosh, np.arcsinh, name="sinh")
    >>> round(float(g.inverse(g(0.7))), 12)    # arcsinh(sinh(x)) is exact to ~1 ulp
    0.7
    """

    def __init__(self, f, df, finv=None, domain=(-np.inf, np.inf), range=None, name=None):
        if not callable(f) or not callable(df) or (finv is not None and not callable(finv)):
            raise TypeError("Parameters f, df (and finv if given) should be callables")
        self.f, self.df, self.finv = f, df, finv
        self.name = name or getattr(f, "__name__", "f")
        try:
            lo, hi = float(domain[0]), float(domain[1])
        except (TypeError, IndexError, ValueError):
            raise TypeError(f"Parameter domain is {domain!r} but should be a pair (lo, hi) of numbers") from None
        if not lo < hi:
            raise ValueError(f"Parameter domain is {domain!r} but should satisfy lo < hi")
        self.domain = (lo, hi)
        if range is None:
            # values at finite domain ends; an infinite end is taken as unbounded
            # (pass range= for an envelope that saturates at infinity)
            with np.errstate(all="ignore"):
                r_lo = float(f(np.array([lo]))[0]) if np.isfinite(lo) else -np.inf
                r_hi = float(f(np.array([hi]))[0]) if np.isfinite(hi) else np.inf
            range = (r_lo, r_hi)
        self.range = (float(range[0]), float(range[1]))

    def _value(self, x):
        return np.asarray(self.f(x), dtype=np.float64)

    def _derivative(self, x):
        return np.asarray(self.df(x), dtype=np.float64)

    def _inverse(self, y):
        if self.finv is not None:
            return np.asarray(self.finv(y), dtype=np.float64)
        return _numeric_inverse(self, y)

    def _equal_key(self):
        return ("Custom", id(self.f), id(self.df), id(self.finv), self.domain)

    def __repr__(self):
        return f"Custom({self.name})"


_REGISTRY = {
    "Identity": lambda d: Identity(),
    "Linear": lambda d: Linear(d["k"]),
    "Tanh": lambda d: Tanh(d["a"], d["b"], d.get("c", 0.0)),
    "Atanh": lambda d: Atanh(d["a"], d["b"], d.get("offset", 0.0)),
    "Polynomial": lambda d: Polynomial(d["coeffs"], tuple(d["interval"])),
    "Inverse": lambda d: Inverse(envelope_from_dict(d["of"])),
}


def envelope_from_dict(d):
    """Rebuild an envelope written by ``Envelope.to_dict()``.

    Parameters
    ----------
    d : dict or Envelope
        A description with a ``"type"`` key (``"Identity"``, ``"Linear"``,
        ``"Tanh"``, ``"Atanh"``, ``"Polynomial"`` or ``"Inverse"``) and the
        constructor's parameters; an Envelope is returned unchanged.

    Returns
    -------
    Envelope

    Raises
    ------
    ValueError
        If `d` is not such a dict or its type is unknown.

    Examples
    --------
    >>> envelope_from_dict(Tanh(2.0, 0.5).to_dict())
    Tanh(a=2.0, b=0.5)
    """
    if isinstance(d, Envelope):
        return d
    if not isinstance(d, dict) or "type" not in d:
        raise ValueError(f"Envelope description {d!r} should be a dict with a 'type' key")
    try:
        make = _REGISTRY[d["type"]]
    except KeyError:
        raise ValueError(
            f"Envelope type {d['type']!r} is unknown; expected one of {sorted(_REGISTRY)}"
        ) from None
    try:
        return make(d)
    except KeyError as exc:
        raise ValueError(
            f"Envelope description of type {d['type']!r} has no key {exc.args[0]!r}; expected the keys "
            "written by envelope.to_dict()"
        ) from None


# documented, pickled and shown as hystcomp.envelopes.* (their public home)
for _obj in (Envelope, Inverse, extended_values):
    _obj.__module__ = __name__
del _obj
# the base class's methods live in _envelope_base: name their examples here so that doctest runs them
__test__ = method_examples(Envelope, Inverse)
