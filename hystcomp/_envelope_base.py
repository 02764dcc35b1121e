"""The envelope base class (:class:`Envelope`), the inverse of an envelope as
an envelope (:class:`Inverse`) and the helpers every envelope shares.

The public names live in :mod:`hystcomp.envelopes`, which imports this
module; the built-in envelopes (Identity, Linear, Tanh, Atanh, Polynomial,
Custom) are there.
"""

import numpy as np

from . import _kernels as _k
from ._validation import as_float_array

__all__ = ["Envelope", "Inverse", "extended_values"]


class Envelope:
    """Base class of strictly increasing envelope functions.

    Subclasses implement ``_value``, ``_derivative`` and ``_inverse`` on
    checked arrays and set ``domain`` and ``range``.  Built-in families also
    provide ``_kernel`` = (kind, params) so the compiled operator kernels
    evaluate them inline.  Calling an envelope, ``env(v)``, returns its
    value gamma(v): a float for a scalar `v`, an array of the same shape
    otherwise.

    See Also
    --------
    Identity, Linear, Tanh, Atanh, Polynomial, Custom, Inverse

    Examples
    --------
    >>> from hystcomp.envelopes import Envelope, Tanh
    >>> g = Tanh(2.0, 1.0)
    >>> isinstance(g, Envelope), g.is_bounded
    (True, True)
    >>> g([0.0, 0.5]).round(4).tolist()
    [0.0, 0.9242]
    """

    #: (lower, upper) bounds of the inputs; open bounds are excluded.
    domain = (-np.inf, np.inf)
    #: whether the domain bounds themselves are excluded
    domain_open = True
    #: (inf, sup) of the values
    range = (-np.inf, np.inf)

    # -- public, checked ------------------------------------------------------
    def __call__(self, v):
        x = self._check(v, "v")
        return _same_shape(self._value(x), v)

    def derivative(self, v):
        """Derivative gamma'(v).

        Parameters
        ----------
        v : float or array_like
            Inputs inside the envelope's domain (finite).

        Returns
        -------
        float or ndarray
            gamma'(v), a float for a scalar `v`, else an array of `v`'s shape.

        Raises
        ------
        ValueError
            If a sample of `v` is not finite or lies outside the domain.

        Examples
        --------
        >>> from hystcomp.envelopes import Linear
        >>> Linear(3.0).derivative(1.5)
        3.0
        """
        x = self._check(v, "v")
        return _same_shape(self._derivative(x), v)

    def inverse(self, y):
        """Inverse gamma^-1(y).

        Parameters
        ----------
        y : float or array_like
            Values inside the envelope's range (finite; the range's ends are
            excluded when the domain is open).

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
        >>> from hystcomp.envelopes import Linear
        >>> Linear(4.0).inverse(2.0)
        0.5
        """
        x = as_float_array(y, "y")
        _check_finite(self, x, "y")
        lo, hi = self.range
        bad = (x <= lo) | (x >= hi) if _open_range(self) else (x < lo) | (x > hi)
        if np.any(bad):
            k = int(np.argmax(bad.reshape(-1)))
            val = x.reshape(-1)[k]
            raise ValueError(
                f"{self!r}.inverse: parameter y holds {val} at sample index {k}, outside the "
                f"envelope's range ({lo}, {hi})"
            )
        return _same_shape(self._inverse(x), y)

    def inverse_envelope(self):
        """The envelope beta = gamma^-1 (eq. 46, 55), as an :class:`Envelope`."""
        return Inverse(self)

    @property
    def is_bounded(self):
        """True when both ends of the range are finite (a saturating envelope)."""
        return bool(np.isfinite(self.range[0]) and np.isfinite(self.range[1]))

    def check_domain(self, v, name="v"):
        """Raise ValueError if any sample of `v` lies outside the domain.

        Parameters
        ----------
        v : float or array_like
            Inputs to check.
        name : str, optional
            Name of the input shown in the error message (default ``"v"``).

        Raises
        ------
        ValueError
            Naming the first offending sample index, its value and the bound
            it crosses, or the first sample that is not finite.

        Examples
        --------
        >>> from hystcomp.envelopes import Atanh
        >>> Atanh(1.0, 0.5).check_domain([0.0, 1.9])      # inside (-2, 2): no error
        >>> Atanh(1.0, 0.5).check_domain([0.0, 2.0], name="u")
        Traceback (most recent call last):
        ...
        ValueError: Atanh(a=1.0, b=0.5): input u[1] = 2.0 is outside the domain (-2.0, 2.0): it is >= the upper bound 2.0
        """
        self._check(v, name)

    # -- plumbing -------------------------------------------------------------
    _kernel = None  # (kind, params) for compiled kernels, None for Python-only

    def kernel_spec(self):
        """(kind code, float64 parameter array) for the compiled kernels."""
        if self._kernel is None:
            return _k.CUSTOM, np.zeros(1)
        kind, prm = self._kernel
        return kind, np.ascontiguousarray(prm, dtype=np.float64)

    def _check(self, v, name):
        x = as_float_array(v, name)
        _check_finite(self, x, name)
        lo, hi = self.domain
        if np.isfinite(lo) or np.isfinite(hi):
            flat = x.reshape(-1)
            if self.domain_open:
                bad = (flat <= lo) | (flat >= hi)
            else:
                bad = (flat < lo) | (flat > hi)
            if bad.any():
                k = int(np.argmax(bad))
                val = flat[k]
                which = "lower" if val <= lo else "upper"
                bound = lo if which == "lower" else hi
                rel = ("<=" if which == "lower" else ">=") if self.domain_open else (
                    "<" if which == "lower" else ">")
                raise ValueError(
                    f"{self!r}: input {name}[{k}] = {val} is outside the domain "
                    f"({lo}, {hi}): it is {rel} the {which} bound {bound}"
                )
        return x

    def _equal_key(self):
        return ("id", id(self))

    def __eq__(self, other):
        return isinstance(other, Envelope) and self._equal_key() == other._equal_key()

    def __hash__(self):
        return hash(self._equal_key())

    def to_dict(self):
        """JSON-safe description (see :func:`envelope_from_dict`)."""
        raise TypeError(
            f"{self!r} holds Python functions and cannot be written to a dict; "
            "use a built-in envelope (Identity, Linear, Tanh, Atanh, Polynomial) to save a model"
        )


def _open_range(env):
    # the range of a closed-domain envelope (Polynomial) includes its ends
    return env.domain_open


def _check_finite(env, x, name):
    flat = x.reshape(-1)
    bad = ~np.isfinite(flat)
    if bad.any():
        k = int(np.argmax(bad))
        raise ValueError(
            f"{env!r}: input {name}[{k}] = {flat[k]} is not finite; expected finite numbers"
        )


def _same_shape(result, like):
    if np.ndim(like) == 0:
        return float(np.asarray(result).reshape(-1)[0])
    return result


def _vkernel(kind, prm, x, func):
    out = np.empty(x.shape)
    flat_in = x.reshape(-1)
    flat_out = out.reshape(-1)
    for j in range(flat_in.size):
        flat_out[j] = func(kind, prm, flat_in[j])
    return out


class Inverse(Envelope):
    """The inverse beta = gamma^-1 of an envelope, as an envelope.

    Its domain is gamma's range and its range gamma's domain.  Built-in
    envelopes return closed forms from ``inverse_envelope()``; this class
    serves the others (Polynomial, Custom).

    Parameters
    ----------
    envelope : Envelope
        The envelope gamma to invert.

    Examples
    --------
    >>> from hystcomp.envelopes import Polynomial
    >>> b = Inverse(Polynomial([0, 1, 0, 1], interval=(-2, 2)))
    >>> round(float(b(2.0)), 12)   # v + v^3 = 2 at v = 1
    1.0
    """

    def __init__(self, envelope):
        if not isinstance(envelope, Envelope):
            raise TypeError(f"Parameter envelope is {envelope!r} but should be an Envelope")
        self.of = envelope
        if envelope._kernel is not None and envelope._kernel[0] != _k.INVERSE_OF:
            ik, iprm = envelope.kernel_spec()
            self._kernel = (_k.INVERSE_OF, np.concatenate([[float(ik)], iprm]))
        self.domain = envelope.range
        self.domain_open = _open_range(envelope)  # closed where gamma's domain is (Polynomial)
        self.range = envelope.domain

    def _value(self, x):
        return self.of._inverse(x)

    def _derivative(self, x):
        return 1.0 / self.of._derivative(self.of._inverse(x))

    def _inverse(self, y):
        return self.of._value(y)

    def inverse_envelope(self):
        return self.of

    def _equal_key(self):
        return ("Inverse", self.of._equal_key())

    def __repr__(self):
        return f"Inverse({self.of!r})"

    def to_dict(self):
        return {"type": "Inverse", "of": self.of.to_dict()}


def extended_values(env, x):
    """Envelope values with -inf below and +inf above its domain (no error).

    Inside operators an envelope boundary that leaves the domain never binds
    (for Atanh the value tends to +-inf there anyway).

    Parameters
    ----------
    env : Envelope
        The envelope gamma.
    x : array_like
        Inputs, anywhere on the real line.

    Returns
    -------
    ndarray
        gamma(x) inside the domain, -inf below it and +inf above it, with the
        shape of `x`.

    Examples
    --------
    >>> from hystcomp.envelopes import Atanh
    >>> extended_values(Atanh(1.0, 0.5), [-3.0, 0.0, 2.0]).tolist()
    [-inf, 0.0, inf]
    """
    if not isinstance(env, Envelope):
        raise TypeError(f"Parameter env is {env!r} but should be an hystcomp Envelope")
    x = as_float_array(x, "x")
    if np.isnan(x).any():
        raise ValueError(f"Parameter x holds NaN at flat index {int(np.argmax(np.isnan(x.reshape(-1))))}")
    lo, hi = env.domain
    if lo == -np.inf and hi == np.inf:
        # the whole real line (Identity, Linear, Tanh, ...): no masks to build
        out = np.asarray(env._value(x), dtype=np.float64)
        return out.copy() if np.may_share_memory(out, x) else out   # never the caller's own array
    out = np.empty(x.shape)
    if env.domain_open:
        below, above = x <= lo, x >= hi
    else:
        below, above = x < lo, x > hi
    inside = ~(below | above)
    out[below] = -np.inf
    out[above] = np.inf
    if inside.any():
        out[inside] = env._value(x[inside])
    return out


def _numeric_inverse(env, y):
    """Vectorised safeguarded Newton for gamma(x) = y inside env.domain."""
    y = np.asarray(y, dtype=np.float64)
    lo_d, hi_d = env.domain
    flat = y.reshape(-1)
    lo = np.full(flat.shape, lo_d if np.isfinite(lo_d) else -1.0)
    hi = np.full(flat.shape, hi_d if np.isfinite(hi_d) else 1.0)
    # expand infinite brackets
    if not np.isfinite(lo_d):
        for _ in range(1100):
            need = env._value(lo) > flat
            if not need.any():
                break
            lo[need] *= 2.0
    if not np.isfinite(hi_d):
        for _ in range(1100):
            need = env._value(hi) < flat
            if not need.any():
                break
            hi[need] *= 2.0
    x = 0.5 * (lo + hi)
    for _ in range(300):
        with np.errstate(all="ignore"):
            f = env._value(x) - flat
            d = env._derivative(x)
            above = f > 0
            hi = np.where(above, x, hi)
            lo = np.where(above, lo, x)
            xn = x - f / d
        bad = ~np.isfinite(xn) | (xn <= lo) | (xn >= hi)
        xn = np.where(bad, 0.5 * (lo + hi), xn)
        done = np.abs(xn - x) <= 1e-15 * (1.0 + np.abs(x))
        x = xn
        if done.all() or np.all(hi - lo <= 1e-15 * (1 + np.abs(x))):
            break
    return x.reshape(y.shape)
