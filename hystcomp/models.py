"""Prandtl-Ishlinskii hysteresis models: PI, stop-type PI, GPI and mGPI.

Notation and equation numbers follow W. Ye, *Inverse Compensation of
Hysteresis using Modified Generalized Prandtl-Ishlinskii Hysteresis Model*
(master's thesis; its typos, corrected here, are listed in the docs' concepts page):

* PI, eq. 18: ``w = p0 v + sum_i p_i F_{r_i}[v]`` with the play F_r of eq. 12-13;
* GPI, eq. 21: ``w = H(v) + sum_i p_i F^gamma_{l r_i}[v]`` with the generalized
  play of eq. 20, ``max{gl(v) - r, min{gr(v) + r, w}}``;
* mGPI, eq. 25/49: ``w = p0 F^gamma_{m0}[v] + sum_i p_i F^gamma_{m r_i}[v]``
  with the modified generalized play of eq. 23,
  ``max{gl(v - r), min{gr(v + r), w}}``.

(The thesis's eqs. 19, 22 and 60 print v(0) where v(t) is meant.)

Every model simulates on an explicit state, like a streaming filter:
``y, state = model.simulate(v, initial_state=state, return_state=True)``;
simulating a record in chunks, passing the state on, gives the one-shot
result bit for bit.  The time loops run compiled (numba) and keep memory
O(samples + operators).
"""

import numpy as np

from . import _kernels as _k
from ._validation import (as_float_array, as_scalar, as_signal, as_state, as_thresholds, as_weights,
                          non_finite_error)
from .envelopes import Envelope, Identity, envelope_from_dict, extended_values as _extended
from .operators import modified_play
from ._model_base import (SCHEMA_VERSION, _BLOCK, _MODELS, HysteresisModel, Invertibility,  # noqa: F401
                          _partial_sum_reasons, model_from_dict)
from ._models_stop_gpi import GPI, StopPI  # noqa: F401

__all__ = ["HysteresisModel", "PI", "StopPI", "GPI", "MGPI", "Invertibility", "model_from_dict"]


class MGPI(HysteresisModel):
    """Modified generalized Prandtl-Ishlinskii model (eq. 25, discrete eq. 49).

    ``w = p0 F^gamma_{m0}[v] + sum_{i=1}^N p_i F^gamma_{m r_i}[v]`` with the
    modified generalized play ``max{gl(v - r), min{gr(v + r), w}}`` (eq. 23).

    Parameters
    ----------
    thresholds : array_like, shape (N,)
        r_1 < ... < r_N, all > 0.
    weights : array_like, shape (N,)
        p_1..p_N (negative values are legal: inverses have them).
    p0 : float
        Weight of the r = 0 operator.
    envelope : Envelope, optional
        Sets both envelopes (gl = gr); default :class:`~hystcomp.envelopes.Identity`,
        with which the model is the classical PI model.
    envelope_left, envelope_right : Envelope, optional
        gl and gr apart (asymmetric hysteresis).

    Notes
    -----
    With one envelope, gamma commutes with max and min, so
    ``F^gamma_{mr}[v] = gamma(F_r[v])``: the state is then the classical play
    positions z_i (input coordinates) and gamma is evaluated only for
    operators that move.  With two envelopes the state is the operator
    outputs w_0..w_N (w_0 of the r = 0 operator, which has memory when
    gl != gr).

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import MGPI
    >>> from hystcomp.envelopes import Tanh
    >>> r = 0.5 * np.arange(1, 21)
    >>> model = MGPI.from_density(lambda r: np.exp(-0.1 * r), r, p0=1.0,
    ...                           envelope=Tanh(10.0, 0.2))
    >>> t = np.linspace(0, 10, 2001)
    >>> y = model.simulate(10 * np.sin(2 * np.pi * t) + t)
    >>> bool(y.max() < model.output_bounds()[1])
    True
    """

    _type = "MGPI"

    def __init__(self, thresholds, weights, p0, envelope=None, envelope_left=None, envelope_right=None):
        self._r = as_thresholds(thresholds)
        self._p = as_weights(weights, self._r.size)
        self.p0 = as_scalar(p0, "p0")
        if envelope is not None and (envelope_left is not None or envelope_right is not None):
            raise ValueError(
                "Parameter envelope sets both sides; pass either envelope or "
                "envelope_left/envelope_right, not both"
            )
        if (envelope_left is None) != (envelope_right is None):
            raise ValueError(
                "Parameters envelope_left and envelope_right go together; pass both "
                "or pass envelope for a symmetric model"
            )
        if envelope is None and envelope_left is None:
            envelope = Identity()
        gl = envelope if envelope is not None else envelope_left
        gr = envelope if envelope is not None else envelope_right
        for name, g in (("envelope_left", gl), ("envelope_right", gr)):
            if not isinstance(g, Envelope):
                raise TypeError(f"Parameter {name} is {g!r} but should be an hystcomp Envelope")
        self.envelope_left = gl
        self.envelope_right = gr
        self.symmetric = gl == gr
        if self.symmetric:
            self.envelope_right = gl
            self.n_states = self._r.size
        else:
            self.n_states = self._r.size + 1

    @property
    def envelope(self):
        """The envelope gamma when gl = gr, else None."""
        return self.envelope_left if self.symmetric else None

    @classmethod
    def from_density(cls, density, thresholds, p0, **envelopes):
        """Discretise a density p(r) as the thesis does (eq. 49, section 5.1):

        p_i = p(r_i) (r_i - r_{i-1}), r_0 = 0.

        Examples
        --------
        >>> import numpy as np
        >>> m = MGPI.from_density(lambda r: np.exp(-0.1 * r), [0.5, 1.0], p0=1.0)
        >>> m.weights.round(6).tolist()
        [0.475615, 0.452419]
        """
        r = as_thresholds(thresholds)
        dens = np.asarray(density(r), dtype=np.float64) if callable(density) else np.asarray(density, dtype=np.float64)
        if dens.shape != r.shape:
            raise ValueError(
                f"Parameter density gives {dens.shape} values but there are {r.size} thresholds"
            )
        return cls(r, dens * np.diff(np.concatenate([[0.0], r])), p0, **envelopes)

    def _envelopes(self):
        return (self.envelope_left,) if self.symmetric else (self.envelope_left, self.envelope_right)

    def default_state(self):
        """Virgin state: every operator output 0 before the first sample.

        For a symmetric model the state holds the play positions z_i with
        operator outputs gamma(z_i): z_i = gamma^-1(0), or the end of gamma's
        domain where gamma is nearest 0 when 0 is an end of gamma's range or
        outside it.

        Returns
        -------
        ndarray, shape (n_states,)
            The virgin state.

        Examples
        --------
        >>> from hystcomp import MGPI
        >>> from hystcomp.envelopes import Polynomial
        >>> g = Polynomial([0.0, 1.0], interval=(0.0, 10.0))   # range [0, 10]
        >>> MGPI([1.0], [0.5], 1.0, envelope=g).default_state().tolist()
        [0.0]
        """
        if self.symmetric:
            g = self.envelope_left
            lo, hi = g.range
            if lo < 0.0 < hi:
                z0 = g._inverse(np.array([0.0]))[0]
            else:
                # 0 at or below gamma's range: the play sits at the bottom
                # of gamma's domain (gamma(z0) = inf gamma, = 0 when the
                # range starts at 0); at or above it, at the top.  A range
                # that excludes 0 has no z with gamma(z) = 0: the operators
                # then start from the nearest output gamma can give.
                dlo, dhi = g.domain
                z0 = dhi if hi <= 0.0 else dlo
            return np.full(self._r.size, z0)
        return np.zeros(self._r.size + 1)

    def _kernel_checks_finite(self):
        return self.symmetric and _k.checks_finite(self.envelope_left.kernel_spec()[0])

    def _check_state(self, state, virgin):
        # a symmetric model's state holds play positions z_i, evaluated by
        # gamma: each must lie in gamma's domain (an open end gives an
        # infinite output), except the virgin state's own infinite ends
        if self.symmetric:
            z = state[np.isfinite(state) | (state != virgin)]
            self.envelope_left.check_domain(z, "initial_state")

    def operator_outputs(self, state):
        """Operator outputs w_i for a state (for symmetric models w_i = gamma(z_i)).

        Parameters
        ----------
        state : array_like, shape (n_states,)
            A state of this model (see :meth:`simulate`).

        Returns
        -------
        ndarray
            The operator outputs: w_1..w_N for a symmetric model, w_0..w_N
            (the state itself) for an asymmetric one.

        Examples
        --------
        >>> from hystcomp import MGPI
        >>> from hystcomp.envelopes import Linear
        >>> m = MGPI([1.0], [0.5], p0=1.0, envelope=Linear(2.0))
        >>> _, s = m.simulate([0.0, 3.0], return_state=True)
        >>> s.tolist(), m.operator_outputs(s).tolist()     # z = 3 - 1, w = 2 z
        ([2.0], [4.0])
        """
        s = as_state(state, self.n_states, "state", virgin=self.default_state())
        if self.symmetric:
            return _extended(self.envelope_left, s)
        return s

    def _simulate(self, x, state):
        y = np.empty(x.size)
        if self.symmetric:
            kind, prm = self.envelope_left.kernel_spec()
            if kind != _k.CUSTOM:
                bad = _k.run_play_sum(x, self._r, self._p, self.p0, state, kind, prm, y)
                if bad >= 0:
                    raise non_finite_error(x, bad, "v")
                return y
            g = self.envelope_left
            block = np.empty((min(_BLOCK, x.size), self._r.size))
            for s in range(0, x.size, _BLOCK):
                xs = x[s:s + _BLOCK]
                zs = block[: xs.size]
                _k.play_states(xs, self._r, state, zs)
                y[s:s + xs.size] = _row_sums(self.p0 * g._value(xs), _extended(g, zs), self._p)
            return y
        r_all = np.concatenate([[0.0], self._r])
        p_all = np.concatenate([[self.p0], self._p])
        kl, pl = self.envelope_left.kernel_spec()
        kr, pr = self.envelope_right.kernel_spec()
        if kl != _k.CUSTOM and kr != _k.CUSTOM:
            _k.mplay_sum_kernel(kl, kr)(x, r_all, p_all, state, kl, pl, kr, pr, y)
            return y
        block = np.empty((min(_BLOCK, x.size), r_all.size))
        for s in range(0, x.size, _BLOCK):
            xs = x[s:s + _BLOCK]
            lower = _extended(self.envelope_left, xs[:, None] - r_all[None, :])
            upper = _extended(self.envelope_right, xs[:, None] + r_all[None, :])
            ws = block[: xs.size]
            _k.bounded_play_states(lower, upper, state, ws)
            y[s:s + xs.size] = _row_sums(0.0, ws, p_all)
        return y

    def _operator_block(self, x, state):
        # (memoryless column weighted by p0, operator outputs (n, N)); state updated
        if self.symmetric:
            z = np.empty((x.size, self._r.size))
            _k.play_states(x, self._r, state, z)
            g = self.envelope_left
            return _extended(g, x), _extended(g, z)
        r_all = np.concatenate([[0.0], self._r])
        w = np.empty((x.size, r_all.size))
        kl, pl = self.envelope_left.kernel_spec()
        kr, pr = self.envelope_right.kernel_spec()
        if kl != _k.CUSTOM and kr != _k.CUSTOM:
            _k.mplay_states(x, r_all, state, kl, pl, kr, pr, w)
        else:
            lower = _extended(self.envelope_left, x[:, None] - r_all[None, :])
            upper = _extended(self.envelope_right, x[:, None] + r_all[None, :])
            _k.bounded_play_states(lower, upper, state, w)
        return w[:, 0].copy(), w[:, 1:]

    def operator_responses(self, v, initial_state=None):
        """Outputs of every operator, shape (n, N+1): column 0 is the r = 0
        operator, column i the operator of threshold r_i (for figures).

        Parameters
        ----------
        v : array_like, shape (n,)
            Input samples.
        initial_state : array_like, optional
            State of the model before the first sample; default the virgin
            state.

        Returns
        -------
        ndarray, shape (n, N+1)
            Operator outputs (unweighted).

        Examples
        --------
        >>> from hystcomp import MGPI
        >>> from hystcomp.envelopes import Linear
        >>> m = MGPI([1.0], [0.5], p0=1.0, envelope=Linear(2.0))
        >>> m.operator_responses([0.0, 3.0, 2.0]).tolist()
        [[0.0, 0.0], [6.0, 4.0], [4.0, 4.0]]
        """
        x = as_signal(v, "v")
        self._check_input_domain(x)
        r_all = np.concatenate([[0.0], self._r])
        state = None
        if initial_state is not None:
            w = self.operator_outputs(initial_state)
            state = np.concatenate([[0.0], w]) if self.symmetric else w
        out, _ = modified_play(x, r_all, self.envelope_left, self.envelope_right, state=state, _allow_zero=True)
        return out

    def loading_curve(self, r):
        """Initial loading curve (eq. 37): phi(r) = p0 gamma(r) + sum_{r_i < r} p_i gamma(r - r_i)
        for gamma(0) = 0, evaluated exactly from the operator definition.

        Parameters
        ----------
        r : float or array_like
            End points of an input rising monotonically from 0 (falling for
            negative `r`).

        Returns
        -------
        float or ndarray
            phi(r), a float for a scalar `r`, else an array of `r`'s shape.

        Examples
        --------
        >>> from hystcomp import MGPI
        >>> from hystcomp.envelopes import Linear
        >>> m = MGPI([1.0], [0.5], p0=1.0, envelope=Linear(2.0))
        >>> m.loading_curve(3.0)        # 1 * 2 * 3 + 0.5 * 2 * (3 - 1)
        8.0
        """
        return super().loading_curve(r)

    def output_bounds(self):
        """(lower, upper) bounds of the output for any input (eq. 29).

        Each modified play stays between the envelopes' infimum and supremum
        (and its initial value 0), so the output stays within
        ``sum_i |p_i| * U`` taken sign by sign; eq. 29's
        ``Q = U (p0 + sum p_i)`` for positive weights.  Infinite for
        unbounded envelopes.
        """
        lo = min(self.envelope_left.range[0], self.envelope_right.range[0], 0.0)
        hi = max(self.envelope_left.range[1], self.envelope_right.range[1], 0.0)
        p_all = np.concatenate([[self.p0], self._p])
        return _weighted_bounds(p_all, lo, hi)

    def is_invertible(self):
        """Whether the thesis's analytic inverse (section 4.3) exists, and why not.

        Needs p0 > 0, all partial sums p0 + p_1 + ... + p_j > 0, gl = gr and
        beta'(0) = 1/gamma'(gamma^-1(0)) finite and non-zero.
        """
        reasons = _partial_sum_reasons(self.p0, self._p)
        reasons += self._recipe_reasons()
        return Invertibility(reasons)

    def _recipe_reasons(self):
        reasons = []
        if not self.symmetric:
            reasons.append(
                "the envelopes differ (gl != gr): the thesis's recipe (eqs. 54-58) needs "
                "one envelope; use model.exact_inverse()"
            )
            return reasons
        g = self.envelope_left
        try:
            dg0 = float(g.derivative(0.0))
            g0 = float(g(0.0))
        except ValueError:
            return ["0 is outside the envelope's domain; use model.exact_inverse()"]
        if g0 != 0.0:
            reasons.append(
                f"gamma(0) = {g0} is not 0 (eq. 40 assumes gamma(0) = 0); use model.exact_inverse()"
            )
        if not np.isfinite(dg0) or dg0 == 0.0:
            reasons.append(
                f"beta'(0) = 1/gamma'(0) is {'0' if not np.isfinite(dg0) else 'infinite'} "
                "(as for gamma = v^3: eq. 58 divides by beta'(0), the thesis's section 6.2 "
                "leaves this open); use model.exact_inverse()"
            )
        if not reasons:
            # eq. 58 evaluates beta'(q_j) at the inverse thresholds q_j = phi(r_j)
            # (eq. 56): they must lie inside beta's domain, gamma's range (a
            # saturating gamma with large weights pushes them beyond it)
            q = np.atleast_1d(self.loading_curve(self._r))
            try:
                g.inverse_envelope().derivative(q)
            except ValueError:
                reasons.append(
                    f"the inverse thresholds q_j = phi(r_j) (eq. 56) reach {float(np.max(q)):.6g}, "
                    f"outside gamma's range {g.range} where eq. 58 needs beta'(q_j); "
                    "use model.exact_inverse()"
                )
        return reasons

    def inverse(self):
        """The analytic inverse by the thesis's recipe (section 4.3, eqs. 54-58).

        Returns the mGPI model with thresholds q_j (eq. 56), weights g(q_j)
        (eq. 58, read with g_j, not q_j, in eq. 57's last term), p0 = g0 = 1/p0
        (eq. 54) and envelope beta = gamma^-1 (eq. 55).  Exact for linear
        envelopes; for nonlinear ones an approximation (see
        :func:`hystcomp.inverses.tracking_error`).

        Raises
        ------
        ValueError
            Where the recipe does not apply (gl != gr, beta'(0) = 0, ...),
            naming the reason and pointing to :meth:`exact_inverse`.
        """
        from .inverses import mgpi_inverse_parameters

        check = self.is_invertible()
        if not check:
            raise ValueError(
                "The analytic inverse of this model does not exist: " + "; ".join(check.reasons)
            )
        q, g, g0 = mgpi_inverse_parameters(self._r, self._p, self.p0, self.envelope_left)
        return MGPI(q, g, g0, envelope=self.envelope_left.inverse_envelope())

    def _key(self):
        return (tuple(self._r), tuple(self._p), self.p0, self.envelope_left, self.envelope_right)

    def to_dict(self):
        """JSON-safe description with a schema version (exact round trip)."""
        d = {
            "schema_version": SCHEMA_VERSION,
            "model": self._type,
            "thresholds": self._r.tolist(),
            "weights": self._p.tolist(),
            "p0": self.p0,
        }
        if self.symmetric:
            d["envelope"] = self.envelope_left.to_dict()
        else:
            d["envelope_left"] = self.envelope_left.to_dict()
            d["envelope_right"] = self.envelope_right.to_dict()
        return d

    @classmethod
    def _from_dict(cls, d):
        if "envelope_left" not in d and "envelope_right" not in d:
            return cls(d["thresholds"], d["weights"], d["p0"], envelope=envelope_from_dict(d["envelope"]))
        if "envelope" in d:
            raise ValueError("Model description of a MGPI model has both 'envelope' and 'envelope_left' / "
                             "'envelope_right'; expected one envelope or the two sides")
        return cls(d["thresholds"], d["weights"], d["p0"],
                   envelope_left=envelope_from_dict(d["envelope_left"]),
                   envelope_right=envelope_from_dict(d["envelope_right"]))

    from_dict = classmethod(lambda cls, d: model_from_dict(d, expected=cls))

    def __repr__(self):
        env = (f"envelope={self.envelope_left!r}" if self.symmetric else
               f"envelope_left={self.envelope_left!r}, envelope_right={self.envelope_right!r}")
        return f"{type(self).__name__}(N={self._r.size}, p0={self.p0!r}, {env})"


class PI(MGPI):
    """Classical play-type Prandtl-Ishlinskii model (eq. 18, discrete form).

    ``w = p0 v + sum_{i=1}^N p_i F_{r_i}[v]`` with the play
    ``f_r(v, w) = max{v - r, min{v + r, w}}`` (eq. 13).  The state is the
    play outputs.  An MGPI model with the identity envelope.

    Parameters
    ----------
    thresholds : array_like, shape (N,)
        r_1 < ... < r_N, all > 0.
    weights : array_like, shape (N,)
        p_1..p_N (negative values are legal: inverses have them).
    p0 : float
        Weight of the linear term p0 v.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> model = PI([1.0, 2.0, 3.0], [0.5, 0.3, 0.2], p0=1.0)
    >>> inv = model.inverse()                      # Krejci-Kuhnen
    >>> u = 4 * np.sin(np.linspace(0, 20, 500))
    >>> bool(np.allclose(model.simulate(inv.simulate(u)), u, atol=1e-12))
    True
    """

    _type = "PI"

    def __init__(self, thresholds, weights, p0):
        super().__init__(thresholds, weights, p0)

    def loading_curve(self, r):
        """phi(r) = p0 r + sum_i p_i max(r - r_i, 0) for r >= 0 (eq. 30).

        Odd in `r`: ``phi(-r) = -phi(r)`` (a falling input from the virgin
        state).

        Parameters
        ----------
        r : float or array_like
            End points of the monotone input.

        Returns
        -------
        float or ndarray
            phi(r), a float for a scalar `r`, else an array of `r`'s shape.

        Examples
        --------
        >>> from hystcomp import PI
        >>> PI([1.0, 2.0], [0.5, 0.25], p0=1.0).loading_curve([1.0, 3.0, -3.0]).tolist()
        [1.0, 4.25, -4.25]
        """
        rr = as_float_array(r, "r")
        as_signal(rr.reshape(-1), "r", min_length=0)   # finite end points
        a = np.abs(rr)[..., None]
        val = self.p0 * np.abs(rr) + (np.maximum(a - self._r, 0.0) * self._p).sum(axis=-1)
        val = np.sign(rr) * val
        return float(val) if rr.ndim == 0 else val

    @classmethod
    def from_loading_curve(cls, phi, thresholds):
        """Recover p0 = phi'(0) and p_i = jump of phi' at r_i (eqs. 31-32).

        `phi` is a callable (the loading curve).  For a PI model the curve is
        piecewise linear with kinks at the thresholds, so the recovery is
        exact; for a smooth curve it discretises p(r) = phi''(r).

        Examples
        --------
        >>> m = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
        >>> rec = PI.from_loading_curve(m.loading_curve, [1.0, 2.0])
        >>> rec.p0, rec.weights.tolist()
        (1.0, [0.5, 0.25])
        """
        r = as_thresholds(thresholds)
        h = r[-1] - r[-2] if r.size > 1 else r[-1]
        pts = np.concatenate([[0.0], r, [r[-1] + h]])
        vals = np.array([float(phi(x)) for x in pts])
        slopes = np.diff(vals) / np.diff(pts)
        p0 = slopes[0]
        p = np.diff(slopes)
        return cls(r, p, p0)

    def inverse(self):
        """Krejci-Kuhnen analytic inverse: again a PI model.

        Thresholds q_j = phi(r_j) (the loading curve, eq. 56 with gamma = v),
        weights g_j = 1/(p0 + p_1 + ... + p_j) - 1/(p0 + ... + p_{j-1}),
        p0' = 1/p0.  Exact: ``inverse.simulate(model.simulate(v)) == v`` up to
        rounding.  Map a non-zero initial state with :meth:`inverse_state`.
        """
        check = Invertibility(_partial_sum_reasons(self.p0, self._p))
        if not check:
            raise ValueError("The PI model is not invertible: " + "; ".join(check.reasons))
        sums = self.p0 + np.concatenate([[0.0], np.cumsum(self._p)])
        q = self.loading_curve(self._r)
        g = 1.0 / sums[1:] - 1.0 / sums[:-1]
        return PI(q, g, 1.0 / self.p0)

    def is_invertible(self):
        """p0 > 0 and all partial sums p0 + p_1 + ... + p_j > 0."""
        return Invertibility(_partial_sum_reasons(self.p0, self._p))

    def inverse_state(self, state):
        """Initial state of :meth:`inverse` matching a state of this model.

        For play outputs z_i of the model, the inverse's plays start at
        ``z'_j = (p0 + p_1 + ... + p_j) z_j + sum_{i > j} p_i z_i``, so that
        ``inverse.simulate(model.simulate(v, s), inverse_state(s)) == v``.

        Parameters
        ----------
        state : array_like, shape (N,)
            Play outputs z_1..z_N of this model.

        Returns
        -------
        ndarray, shape (N,)
            The matching initial state of :meth:`inverse`.

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> m = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
        >>> _, s = m.simulate([0.0, 2.5, -0.5], return_state=True)
        >>> v = np.linspace(-0.5, 3.0, 50)
        >>> inv = m.inverse()
        >>> back = inv.simulate(m.simulate(v, initial_state=s), initial_state=m.inverse_state(s))
        >>> bool(np.allclose(back, v, atol=1e-12))
        True
        """
        z = as_state(state, self.n_states, "state")
        head = (self.p0 + np.cumsum(self._p)) * z
        tail = np.concatenate([np.cumsum((self._p * z)[::-1])[::-1][1:], [0.0]])
        return head + tail

    def to_dict(self):
        d = super().to_dict()
        d.pop("envelope", None)
        return d

    @classmethod
    def _from_dict(cls, d):
        return cls(d["thresholds"], d["weights"], d["p0"])

    def __repr__(self):
        return f"PI(N={self._r.size}, p0={self.p0!r})"


def _row_sums(first, w, p):
    """first + sum_i p_i w[:, i], summed operator by operator in order.

    Unlike ``w @ p`` (BLAS, whose summation order depends on the number of
    rows) each row's result does not depend on the block it is in, so chunked
    simulation equals the one-shot result bit for bit.
    """
    acc = np.zeros(w.shape[0]) + first
    for i in range(w.shape[1]):
        acc += p[i] * w[:, i]
    return acc


def _weighted_bounds(p, lo, hi):
    pos = p > 0
    with np.errstate(invalid="ignore"):
        upper = np.sum(np.where(pos, p * hi, np.where(p < 0, p * lo, 0.0)))
        lower = np.sum(np.where(pos, p * lo, np.where(p < 0, p * hi, 0.0)))
    # widen by the rounding bound of an (N+1)-term sum so that outputs summed
    # in another order (the kernels) never exceed the bounds by an ulp
    mag = float(np.sum(np.abs(p))) * max([abs(b) for b in (lo, hi) if np.isfinite(b)] + [0.0])
    margin = (p.size + 1) * np.finfo(float).eps * mag
    return (float(lower - margin), float(upper + margin))


_MODELS.update({"PI": PI, "MGPI": MGPI})
