"""Stop-type PI (eq. 15-16) and GPI (eq. 21) models, re-exported by
:mod:`hystcomp.models`.
"""

import numpy as np

from . import _kernels as _k
from ._model_base import (SCHEMA_VERSION, _MODELS, HysteresisModel, Invertibility, _partial_sum_reasons,
                          model_from_dict)
from ._validation import as_scalar, as_thresholds, as_weights
from .envelopes import Envelope, Linear, envelope_from_dict

__all__ = ["StopPI", "GPI"]

class StopPI(HysteresisModel):
    """Stop-type Prandtl-Ishlinskii model: ``w = p0 v + sum_i p_i E_{r_i}[v]``.

    The stop E_r of eq. 15-16 (elastic-plastic element): state is the stop
    outputs and the last input, ``[e_1, ..., e_N, v_prev]``.

    Parameters
    ----------
    thresholds : array_like, shape (N,)
        r_1 < ... < r_N, all > 0 (the stops saturate at +-r_i).
    weights : array_like, shape (N,)
        p_1..p_N.
    p0 : float, optional
        Weight of the linear term p0 v (default 0).

    Examples
    --------
    >>> import numpy as np
    >>> m = StopPI([1.0, 2.0], [1.0, 0.5])
    >>> m.simulate([0.0, 1.5, 3.0, 0.0]).tolist()
    [0.0, 1.75, 2.0, -1.5]
    """

    _type = "StopPI"

    def __init__(self, thresholds, weights, p0=0.0):
        self._r = as_thresholds(thresholds)
        self._p = as_weights(weights, self._r.size)
        self.p0 = as_scalar(p0, "p0")
        self.n_states = self._r.size + 1

    def default_state(self):
        return np.zeros(self.n_states)

    def _simulate(self, x, state):
        y = np.empty(x.size)
        w = state[:-1].copy()
        state[-1] = _k.stop_sum(x, self._r, self._p, self.p0, w, state[-1], y)
        state[:-1] = w
        return y

    def _operator_block(self, x, state):
        w = state[:-1].copy()
        out = np.empty((x.size, self._r.size))
        state[-1] = _k.stop_states(x, self._r, w, state[-1], out)
        state[:-1] = w
        return x, out

    def output_bounds(self):
        """Bounded only if p0 = 0: then ``|w| <= sum_i |p_i| r_i``."""
        if self.p0 != 0.0:
            return (-np.inf, np.inf)
        b = float(np.sum(np.abs(self._p) * self._r))
        return (-b, b)

    def is_invertible(self):
        reasons = []
        if not self.p0 > 0:
            reasons.append(f"p0 = {self.p0} is not positive (a stop-type model saturates)")
        if np.any(self._p < 0):
            reasons.append("negative weights")
        return Invertibility(reasons)

    def _key(self):
        return (tuple(self._r), tuple(self._p), self.p0)

    def to_dict(self):
        return {"schema_version": SCHEMA_VERSION, "model": self._type,
                "thresholds": self._r.tolist(), "weights": self._p.tolist(), "p0": self.p0}

    @classmethod
    def _from_dict(cls, d):
        return cls(d["thresholds"], d["weights"], d["p0"])

    from_dict = classmethod(lambda cls, d: model_from_dict(d, expected=cls))

    def __repr__(self):
        return f"StopPI(N={self._r.size}, p0={self.p0!r})"


class GPI(HysteresisModel):
    """Generalized Prandtl-Ishlinskii model (eq. 21, Al Janaideh et al.).

    ``w = H(v) + sum_i p_i F^gamma_{l r_i}[v]`` with the generalized play
    ``max{gl(v) - r, min{gr(v) + r, w}}`` (eq. 20).

    Parameters
    ----------
    thresholds, weights : array_like, shape (N,)
        r_1 < ... < r_N (> 0) and p_1..p_N.
    envelope_left, envelope_right : Envelope
        gl and gr.
    H : None, float or Envelope, optional
        The memoryless term: None for H = 0, a number k for H(v) = k v, or an
        increasing :class:`~hystcomp.envelopes.Envelope` (e.g. ``p0 * gamma``
        as ``Tanh(p0 * a, b)``).

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import GPI
    >>> from hystcomp.envelopes import Tanh
    >>> gpi = GPI([10.0], [1.0], Tanh(10, 0.2), Tanh(10, 0.1))
    >>> t = np.linspace(0, 10, 1001)
    >>> float(np.abs(gpi.simulate(10 * np.sin(2 * np.pi * t) + t)).max())  # never moves
    0.0
    """

    _type = "GPI"

    def __init__(self, thresholds, weights, envelope_left, envelope_right, H=None):
        self._r = as_thresholds(thresholds)
        self._p = as_weights(weights, self._r.size)
        for name, g in (("envelope_left", envelope_left), ("envelope_right", envelope_right)):
            if not isinstance(g, Envelope):
                raise TypeError(f"Parameter {name} is {g!r} but should be an hystcomp Envelope")
        self.envelope_left = envelope_left
        self.envelope_right = envelope_right
        if H is None or isinstance(H, Envelope):
            self.H = H
        else:
            k = as_scalar(H, "H", nonnegative=True)
            self.H = Linear(k) if k > 0 else None
        self.n_states = self._r.size

    def _envelopes(self):
        envs = [self.envelope_left, self.envelope_right]
        if self.H is not None:
            envs.append(self.H)
        return tuple(envs)

    def default_state(self):
        return np.zeros(self._r.size)

    def _simulate(self, x, state):
        a = self.envelope_left._value(x)
        b = self.envelope_right._value(x)
        y = np.empty(x.size)
        _k.two_input_play_sum(a, b, self._r, self._p, state, y)
        if self.H is not None:
            y += self.H._value(x)
        return y

    def _operator_block(self, x, state):
        a = self.envelope_left._value(x)
        b = self.envelope_right._value(x)
        out = np.empty((x.size, self._r.size))
        _k.two_input_play_states(a, b, self._r, state, out)
        return (self.H._value(x) if self.H is not None else None), out

    def output_bounds(self):
        """(lower, upper) bounds of the output for any input from the virgin state.

        Each generalized play ``max{gl(v) - r, min{gr(v) + r, w}}`` (eq. 20)
        stays between ``min(inf gl - r, inf gr + r, 0)`` and
        ``max(sup gl - r, sup gr + r, 0)`` (the play can reach sup gl - r
        when gl rises above gr + 2r); the bounds are the weighted sums of
        those, sign by sign, plus H's range.

        Returns
        -------
        (float, float)
            Lower and upper bound (infinite for unbounded envelopes).

        Examples
        --------
        >>> from hystcomp import GPI
        >>> from hystcomp.envelopes import Tanh
        >>> GPI([0.1], [1.0], Tanh(10, 1.0), Tanh(5, 1.0)).output_bounds()
        (-10.1, 9.9)
        """
        gl, gr = self.envelope_left.range, self.envelope_right.range
        lo = np.minimum(np.minimum(gl[0] - self._r, gr[0] + self._r), 0.0)
        hi = np.maximum(np.maximum(gl[1] - self._r, gr[1] + self._r), 0.0)
        pos = self._p > 0
        upper = np.sum(np.where(pos, self._p * hi, self._p * lo))
        lower = np.sum(np.where(pos, self._p * lo, self._p * hi))
        if self.H is not None:
            lower += self.H.range[0]
            upper += self.H.range[1]
        return (float(lower), float(upper))

    def _cascade_gain(self):
        """k if gl = gr = gamma and H = k gamma (numerically checked), else None."""
        if self.envelope_left != self.envelope_right or self.H is None:
            return None
        g = self.envelope_left
        lo, hi = g.domain
        lo = max(lo, -10.0) if np.isfinite(lo) else -10.0
        hi = min(hi, 10.0) if np.isfinite(hi) else 10.0
        x = np.linspace(lo, hi, 41)[1:-1]
        gx, hx = g._value(x), self.H._value(x)
        nz = np.abs(gx) > 1e-12
        if not nz.any() or np.any(np.abs(hx[~nz]) > 1e-12):
            return None
        ratios = hx[nz] / gx[nz]
        k = float(np.median(ratios))
        if k > 0 and np.allclose(ratios, k, rtol=1e-10, atol=0):
            return k
        return None

    def is_invertible(self):
        """The analytic inverse needs gl = gr = gamma and H = k gamma with
        k > 0 (the GPI is then the PI model applied to gamma(v)) and positive
        partial sums."""
        reasons = []
        k = self._cascade_gain()
        if k is None:
            reasons.append(
                "the analytic inverse needs gl = gr = gamma and H = k*gamma (the GPI is then "
                "a PI model of gamma(v)); use model.exact_inverse()"
            )
            return Invertibility(reasons)
        return Invertibility(_partial_sum_reasons(k, self._p))

    def inverse(self):
        """Analytic inverse (Al Janaideh et al.): ``gamma^-1 o PI^-1``.

        With gl = gr = gamma and H = k gamma, ``GPI[v] = PI[gamma(v)]`` for the
        PI model with p0 = k and the same thresholds and weights, so the
        inverse is the Krejci-Kuhnen inverse followed by gamma^-1.
        """
        from .inverses import GPIInverse

        check = self.is_invertible()
        if not check:
            raise ValueError("The analytic inverse of this GPI model does not exist: " + "; ".join(check.reasons))
        return GPIInverse(self)

    def as_pi(self):
        """The PI model P with ``GPI[v] = P[gamma(v)]`` (needs gl = gr, H = k gamma)."""
        k = self._cascade_gain()
        if k is None:
            raise ValueError("This GPI model is not a PI model of gamma(v): " + self.is_invertible().reasons[0])
        return _MODELS["PI"](self._r, self._p, k)     # hystcomp.models.PI, registered there

    def _key(self):
        return (tuple(self._r), tuple(self._p), self.envelope_left, self.envelope_right, self.H)

    def to_dict(self):
        return {"schema_version": SCHEMA_VERSION, "model": self._type,
                "thresholds": self._r.tolist(), "weights": self._p.tolist(),
                "envelope_left": self.envelope_left.to_dict(),
                "envelope_right": self.envelope_right.to_dict(),
                "H": None if self.H is None else self.H.to_dict()}

    @classmethod
    def _from_dict(cls, d):
        H = d.get("H")
        return cls(d["thresholds"], d["weights"], envelope_from_dict(d["envelope_left"]),
                   envelope_from_dict(d["envelope_right"]), H=None if H is None else envelope_from_dict(H))

    from_dict = classmethod(lambda cls, d: model_from_dict(d, expected=cls))

    def __repr__(self):
        return (f"GPI(N={self._r.size}, envelope_left={self.envelope_left!r}, "
                f"envelope_right={self.envelope_right!r}, H={self.H!r})")


_MODELS.update({"StopPI": StopPI, "GPI": GPI})
