"""Preisach (eq. 7) and Krasnoselskii-Pokrovskii (eq. 8) models on a
discretised Preisach plane.

Both models live on the same grid: the input interval ``[v_min, v_max]`` is
cut into n cells of width ``h = (v_max - v_min) / n`` with centres
``c_j = v_min + (j + 1/2) h``; cell (i, j), i >= j, of the triangular
Preisach plane has ``alpha = c_i``, ``beta = c_j`` and a weight ``mu[i, j]``
(n (n + 1) / 2 cells: 1,275 for n = 50).

* :class:`Preisach`: ``w = offset + sum_{i>=j} mu_ij gamma_ij[v]`` with the
  relay ``gamma_ij`` of thesis Fig. 2.4 (output +1 after ``v >= alpha``, -1
  after ``v < beta``), the discrete form of eq. 7.  Its state is the
  staircase memory curve (one integer per alpha row, stored as floats),
  which gives wiping-out and congruent minor loops exactly.  The output is
  piecewise constant in v (steps at the level values c_j).
* :class:`KP`: the same sum with the Krasnoselskii-Pokrovskii operator
  (a relay whose switching edges are ramps of width h centred on alpha and
  beta; Krasnosel'skii and Pokrovskii 1989, Banks, Kurdila and Webb 1997),
  the discrete form of eq. 8.  Its output is continuous and piecewise linear
  in v; its state is one play position per diagonal ``i - j``.

Both outputs are linear in the weights, so :func:`hystcomp.identify.fit_preisach`
and :func:`hystcomp.identify.fit_kp` identify them by non-negative least
squares.  Neither has an analytic inverse (thesis section 2.3);
``exact_inverse()`` returns a numerical one
(:class:`hystcomp.numerical_inverse.NumericalInverse`).
"""

import numpy as np

from . import _kernels_other as _ko
from ._validation import as_float_array, as_scalar, as_signal, as_state
from .models import SCHEMA_VERSION, HysteresisModel, Invertibility, _MODELS, model_from_dict

__all__ = ["Preisach", "KP", "preisach_grid"]


def preisach_grid(input_range, n):
    """Cell centres c_j and edges of the grid on ``input_range`` with n cells.

    Parameters
    ----------
    input_range : (float, float)
        ``(v_min, v_max)``, finite with ``v_min < v_max``.
    n : int
        Number of cells; their width is ``h = (v_max - v_min) / n``.

    Returns
    -------
    centres : ndarray, shape (n,)
        ``c_j = v_min + (j + 1/2) h``.
    edges : ndarray, shape (n + 1,)
        ``v_min + j h``.

    Examples
    --------
    >>> c, e = preisach_grid((-1.0, 1.0), 4)
    >>> c.tolist(), e.tolist()
    ([-0.75, -0.25, 0.25, 0.75], [-1.0, -0.5, 0.0, 0.5, 1.0])
    """
    lo, hi = _as_range(input_range)
    if isinstance(n, (bool, np.bool_)) or not isinstance(n, (int, np.integer)):
        raise TypeError(f"Parameter n is {n!r} but should be an integer number of cells")
    if n < 1:
        raise ValueError(f"Parameter n is {n} but should be >= 1")
    h = (hi - lo) / n
    return lo + (np.arange(n) + 0.5) * h, lo + np.arange(n + 1) * h


def _as_range(input_range):
    try:
        lo, hi = float(input_range[0]), float(input_range[1])
    except (TypeError, IndexError, ValueError):
        raise ValueError(f"Parameter input_range is {input_range!r} but should be (v_min, v_max)") from None
    if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
        raise ValueError(f"Parameter input_range is {input_range!r} but should be finite with v_min < v_max")
    return lo, hi


def _require_keys(d, keys):
    missing = [k for k in keys if k not in d]
    if missing:
        raise ValueError(f"Model description of a {d.get('model')} model lacks the key(s) {missing}; "
                         f"expected {list(keys)} (as written by to_dict())")


def _as_plane_weights(weights):
    mu = np.array(as_float_array(weights, "weights"), dtype=np.float64)
    if mu.ndim != 2 or mu.shape[0] != mu.shape[1] or mu.shape[0] < 1:
        raise ValueError(
            f"Parameter weights has shape {mu.shape} but should be a square (n, n) array "
            "(row i = alpha cell, column j = beta cell, only j <= i used)"
        )
    if not np.all(np.isfinite(mu)):
        i, j = np.argwhere(~np.isfinite(mu))[0]
        raise ValueError(f"Parameter weights holds a non-finite value ({mu[i, j]}) at [{i}, {j}]")
    upper = np.triu(mu, 1)
    if np.any(upper != 0):
        i, j = np.argwhere(upper != 0)[0]
        raise ValueError(
            f"Parameter weights has weights[{i}, {j}] = {mu[i, j]} above the diagonal; the Preisach "
            "plane is the triangle alpha >= beta (j <= i), so entries with j > i must be 0"
        )
    return np.ascontiguousarray(np.tril(mu))


class _PlaneModel(HysteresisModel):
    """Common parts of the Preisach and KP models (grid, weights, offset)."""

    def __init__(self, input_range, weights, offset=0.0):
        self.v_min, self.v_max = _as_range(input_range)
        self._mu = _as_plane_weights(weights)
        self.n = self._mu.shape[0]
        self.offset = as_scalar(offset, "offset")
        self.h = (self.v_max - self.v_min) / self.n
        self.levels, self.edges = preisach_grid((self.v_min, self.v_max), self.n)
        self.n_states = self.n

    @property
    def weights(self):
        """The (n, n) lower-triangular weight array mu[i, j] (copy)."""
        return self._mu.copy()

    @property
    def input_range(self):
        return (self.v_min, self.v_max)

    @property
    def n_cells(self):
        """Number of cells of the triangular plane, n (n + 1) / 2."""
        return self.n * (self.n + 1) // 2

    @property
    def n_parameters(self):
        """Cell weights plus the offset."""
        return self.n_cells + 1

    def output_bounds(self):
        """Every operator lies in [-1, 1]: ``offset -+ sum |mu|`` (tight for
        non-negative weights: the saturated outputs)."""
        s = float(np.abs(self._mu).sum())
        margin = (self.n_cells + 1) * np.finfo(float).eps * (s + abs(self.offset))
        return (self.offset - s - margin, self.offset + s + margin)

    def is_invertible(self):
        """No analytic inverse exists (thesis section 2.3); the numerical one
        of :meth:`exact_inverse` needs non-negative weights."""
        reasons = [f"the {type(self).__name__} model has no analytic inverse (thesis section 2.3); "
                   "model.exact_inverse() gives a numerical one"]
        if np.any(self._mu < 0):
            reasons.append("negative weights: the output is not monotone in the input")
        return Invertibility(reasons)

    def exact_inverse(self, on_unreachable="clip", input_limits=None):
        """Numerical inverse compensator (closest match / monotone solve per
        sample), :class:`hystcomp.numerical_inverse.NumericalInverse`.

        Parameters
        ----------
        on_unreachable : {"clip", "raise"}
            What to do with a desired output outside the reachable range,
            as in :class:`~hystcomp.numerical_inverse.NumericalInverse`.
        input_limits : (float, float), optional
            Bounds of the compensator output; default ``input_range``.

        Returns
        -------
        NumericalInverse

        Examples
        --------
        >>> m = Preisach.from_density(lambda a, b: np.ones_like(a), (-1, 1), 4)
        >>> m.exact_inverse().input_limits
        (-1.0, 1.0)
        """
        from .numerical_inverse import NumericalInverse

        return NumericalInverse(self, on_unreachable=on_unreachable, input_limits=input_limits)

    def _key(self):
        return (self.v_min, self.v_max, (self._mu + 0.0).tobytes(), self.offset)   # + 0.0: -0.0 -> 0.0

    def to_dict(self):
        """JSON-safe description (exact round trip through :func:`model_from_dict`)."""
        return {"schema_version": SCHEMA_VERSION, "model": self._type,
                "input_range": [self.v_min, self.v_max], "weights": self._mu.tolist(),
                "offset": self.offset}

    @classmethod
    def _from_dict(cls, d):
        _require_keys(d, ("input_range", "weights"))
        return cls(d["input_range"], d["weights"], d.get("offset", 0.0))

    from_dict = classmethod(lambda cls, d: model_from_dict(d, expected=cls))

    @classmethod
    def from_density(cls, density, input_range, n, offset=0.0):
        """Discretise a density mu(alpha, beta): ``mu_ij = density(c_i, c_j) h^2``
        (half that on the diagonal, whose cells are half inside the triangle).

        Parameters
        ----------
        density : callable
            ``density(alpha, beta)``, vectorised over arrays of cell centres.
        input_range : (float, float)
            ``(v_min, v_max)`` of the grid.
        n : int
            Cells per axis.
        offset : float, optional
            Added to the output.

        Returns
        -------
        Preisach or KP
            A model of the class it is called on.

        Examples
        --------
        >>> m = Preisach.from_density(lambda a, b: np.ones_like(a), (-1, 1), 4)
        >>> float(m.weights.sum())   # area of the triangle alpha >= beta in [-1, 1]^2
        2.0
        """
        lo, hi = _as_range(input_range)
        c, _ = preisach_grid((lo, hi), int(n))
        h = (hi - lo) / n
        A, B = np.meshgrid(c, c, indexing="ij")
        vals = np.asarray(density(A, B), dtype=np.float64) * h * h
        vals = np.tril(vals)
        vals[np.diag_indices(int(n))] *= 0.5
        return cls((lo, hi), vals, offset)

    def __repr__(self):
        return (f"{type(self).__name__}(n={self.n}, input_range=({self.v_min!r}, {self.v_max!r}), "
                f"offset={self.offset!r})")


class Preisach(_PlaneModel):
    """Discrete Preisach model (thesis eq. 7) on an n x n triangular grid.

    ``w = offset + sum_{i >= j} mu_ij gamma_ij[v]`` with relays
    ``gamma_ij`` at ``alpha = c_i``, ``beta = c_j`` (+1 after ``v >= alpha``,
    -1 after ``v < beta``).

    Parameters
    ----------
    input_range : (float, float)
        ``(v_min, v_max)``: the grid covers it with n cells.
    weights : array_like, shape (n, n)
        ``mu[i, j]`` for alpha cell i and beta cell j (lower triangle,
        diagonal included; entries above the diagonal must be 0).
    offset : float, optional
        Added to the output.

    Notes
    -----
    The state is the staircase memory curve: ``k_i`` = number of +1 relays
    in alpha row i (relays ``j < k_i`` are up).  It is a fixed-length float
    array of n integers.  The default state is the demagnetised one (the
    staircase along ``alpha = -beta``, reached by an oscillation decaying to
    v = 0).  A sample costs the number of rows whose staircase moves, not
    the 1,275 relays of a 50 x 50 grid (see :mod:`hystcomp._kernels_other`).

    Examples
    --------
    >>> import numpy as np
    >>> m = Preisach.from_density(lambda a, b: np.exp(-(a - b)), (-1, 1), 10)
    >>> v = np.array([0.0, 1.0, -0.2, 0.6, -0.2, 1.0])
    >>> y = m.simulate(v)
    >>> bool(y[1] == y[5]), bool(y[2] == y[4])   # wiping out: the minor loop closes
    (True, True)
    """

    _type = "Preisach"

    def __init__(self, input_range, weights, offset=0.0):
        super().__init__(input_range, weights, offset)
        # table[i, k] = contribution of row i when its first k relays are up:
        # 2 * sum_{j<k} mu_ij - sum_{j<=i} mu_ij
        n = self.n
        cums = np.zeros((n, n + 1))
        cums[:, 1:] = np.cumsum(self._mu, axis=1)
        self._table = 2.0 * cums - cums[:, -1][:, None]

    def level(self, v):
        """Input level ``L(v) = #{j : c_j <= v}`` (0..n), what the relays see.

        Parameters
        ----------
        v : float or array_like
            Input value(s).

        Returns
        -------
        int or ndarray of int
            The level(s), rounded to the nearest cell edge.

        Examples
        --------
        >>> m = Preisach.from_density(lambda a, b: np.ones_like(a), (-1, 1), 4)
        >>> m.level([-1.0, -0.3, 0.0, 0.9]).tolist(), m.level(0.6)
        ([0, 1, 2, 4], 3)
        """
        x = as_float_array(v, "v")
        if np.isnan(x).any():
            raise ValueError("Parameter v holds NaN; expected input values (+-inf give the end levels)")
        centres = self.v_min + (np.arange(self.n) + 0.5) * self.h   # as preisach_grid
        L = np.searchsorted(centres, x, side="right").astype(np.int64)
        return int(L) if L.ndim == 0 else L

    def default_state(self):
        """Demagnetised staircase: relay (i, j) up iff ``c_i + c_j <= 0``.

        Returns
        -------
        ndarray, shape (n,)
            ``k_i``, the number of up relays of alpha row i.

        Examples
        --------
        >>> Preisach.from_density(lambda a, b: np.ones_like(a), (-1, 1), 4).default_state().tolist()
        [1.0, 2.0, 2.0, 1.0]
        """
        c = self.levels
        k = np.array([np.count_nonzero(c[: i + 1] + c[i] <= 0.0) for i in range(self.n)], dtype=np.float64)
        return k

    def saturated_state(self, positive=False):
        """All relays down (negative saturation) or all up.

        Parameters
        ----------
        positive : bool
            True: every relay up (positive saturation, after ``v >= v_max``);
            False: every relay down (after ``v < v_min``).

        Returns
        -------
        ndarray, shape (n,)
            The state ``k_i`` (0 or i + 1 for every row).

        Examples
        --------
        >>> m = Preisach.from_density(lambda a, b: np.ones_like(a), (-1, 1), 4)
        >>> m.saturated_state(positive=True).tolist()
        [1.0, 2.0, 3.0, 4.0]
        >>> m.simulate([-1.0], initial_state=m.saturated_state()).tolist()   # -(sum of weights)
        [-2.0]
        """
        return (np.arange(1, self.n + 1, dtype=np.float64) if positive else np.zeros(self.n))

    def relay_states(self, state):
        """The (n, n) array of relay outputs +1/-1 for a state (0 above the diagonal).

        Parameters
        ----------
        state : array_like, shape (n,)
            A Preisach state (staircase counts ``k_i``), e.g. the final state
            returned by ``simulate(..., return_state=True)``.

        Returns
        -------
        ndarray, shape (n, n)
            Relay (i, j) output at row i (alpha), column j (beta).

        Examples
        --------
        >>> m = Preisach.from_density(lambda a, b: np.ones_like(a), (-1, 1), 3)
        >>> m.relay_states(m.default_state())   # demagnetised: up iff alpha + beta <= 0
        array([[ 1.,  0.,  0.],
               [ 1.,  1.,  0.],
               [ 1., -1., -1.]])
        """
        k = self._check_state(as_state(state, self.n, "state"))
        j = np.arange(self.n)
        out = np.where(j[None, :] < k[:, None], 1.0, -1.0)
        return np.tril(out)

    def _check_state(self, s):
        k = np.rint(s).astype(np.int64)
        n = self.n
        if np.any(k != s) or np.any(k < 0) or np.any(k > np.arange(1, n + 1)):
            bad = int(np.argmax((k != s) | (k < 0) | (k > np.arange(1, n + 1))))
            raise ValueError(
                f"Parameter initial_state has entry {bad} = {s[bad]} but a Preisach state holds "
                f"integers k_i with 0 <= k_i <= i + 1 (the number of up relays of row i)"
            )
        L = 0
        while L < n and k[L] == L + 1:
            L += 1
        if np.any(np.diff(k[L:]) > 0):
            raise ValueError(
                "Parameter initial_state is not a staircase: after the full rows (the current input "
                "level) the counts k_i must be non-increasing"
            )
        return k

    def _check_input_domain(self, x, finite=False):
        pass

    def simulate(self, v, initial_state=None, return_state=False):
        """Output of the model for the input samples `v` (see
        :meth:`hystcomp.models.HysteresisModel.simulate`).  Inputs outside
        ``input_range`` saturate every relay they pass.

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (n,), optional
            Staircase counts ``k_i`` at the start; default the demagnetised
            :meth:`default_state`.
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        y : ndarray, shape (n_samples,)
            Model output.
        state : ndarray, shape (n,)
            Final state; only with ``return_state=True``.

        Examples
        --------
        >>> m = Preisach.from_density(lambda a, b: np.ones_like(a), (-1, 1), 4)
        >>> y, s = m.simulate([0.0, 1.0, -0.2], return_state=True)
        >>> y.tolist(), m.simulate([0.5], initial_state=s).tolist()
        ([0.5, 2.0, 1.0], [1.25])
        """
        x = as_signal(v, "v")
        s = self.default_state() if initial_state is None else as_state(initial_state, self.n)
        k = self._check_state(s)
        y = np.empty(x.size)
        _ko.preisach_sum(x, self.v_min, self.h, self._table, self.offset, k, y)
        state = k.astype(np.float64)
        return (y, state) if return_state else y


class KP(_PlaneModel):
    """Discrete Krasnoselskii-Pokrovskii model (thesis eq. 8) on an n x n grid.

    ``w = offset + sum_{i >= j} mu_ij k_ij[v]`` with the KP operator of cell
    (i, j): it rises along the ramp ``clip(2 (v - alpha) / h, -1, 1)`` while
    the input increases and falls along ``clip(2 (v - beta) / h, -1, 1)``
    while it decreases (``alpha = c_i``, ``beta = c_j``, ramp width h = the
    cell width): a relay with ramps of width h instead of jumps.

    Parameters
    ----------
    input_range, weights, offset
        As for :class:`Preisach`.

    Notes
    -----
    The operator equals ``rho(F_r[v] - m)`` with the play F_r of radius
    ``r = (alpha - beta) / 2``, ``m = (alpha + beta) / 2`` and
    ``rho(x) = clip(2 x / h, -1, 1)``; cells on one diagonal share the play,
    so the state is n play positions (the default: 0, the virgin state at
    v = 0).  Per sample cost O(n).

    Examples
    --------
    >>> import numpy as np
    >>> m = KP.from_density(lambda a, b: np.exp(-(a - b)), (-1, 1), 10)
    >>> v = np.linspace(0, 1, 5)
    >>> y = m.simulate(np.concatenate([v, v[::-1], -v, -v[::-1]]))
    >>> bool(np.all(np.diff(y[:5]) > 0))
    True
    """

    _type = "KP"

    def __init__(self, input_range, weights, offset=0.0):
        super().__init__(input_range, weights, offset)
        n = self.n
        # prefix sums of the weights along each diagonal d = i - j, ordered by j
        self._prefix = np.zeros((n, n + 1))
        for d in range(n):
            diag = np.diagonal(self._mu, -d)
            self._prefix[d, 1:diag.size + 1] = np.cumsum(diag)
            self._prefix[d, diag.size + 1:] = self._prefix[d, diag.size]

    def default_state(self):
        """Play positions 0 (the virgin state at v = 0).

        Returns
        -------
        ndarray, shape (n,)

        Examples
        --------
        >>> KP.from_density(lambda a, b: np.ones_like(a), (-1, 1), 3).default_state().tolist()
        [0.0, 0.0, 0.0]
        """
        return np.zeros(self.n)

    def _check_input_domain(self, x, finite=False):
        pass

    def operator_outputs(self, state):
        """The (n, n) array of KP operator outputs for a state (0 above the diagonal).

        Parameters
        ----------
        state : array_like, shape (n,)
            Play positions, one per diagonal ``i - j`` (as returned by
            ``simulate(..., return_state=True)``).

        Returns
        -------
        ndarray, shape (n, n)
            Operator (i, j) output in [-1, 1] at row i (alpha), column j (beta).

        Examples
        --------
        >>> m = KP.from_density(lambda a, b: np.ones_like(a), (-1, 1), 4)
        >>> _, s = m.simulate([0.0, 1.0, -0.2], return_state=True)
        >>> np.round(m.operator_outputs(s)[1], 6).tolist()
        [1.0, 0.2, 0.0, 0.0]
        """
        z = as_state(state, self.n, "state")
        i, j = np.tril_indices(self.n)
        out = np.zeros((self.n, self.n))
        m = 0.5 * (self.levels[i] + self.levels[j])
        out[i, j] = np.clip(2.0 * (z[i - j] - m) / self.h, -1.0, 1.0)
        return out

    def simulate(self, v, initial_state=None, return_state=False):
        """Output of the model for the input samples `v` (see
        :meth:`hystcomp.models.HysteresisModel.simulate`).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (n,), optional
            Play positions at the start; default :meth:`default_state`.
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        y : ndarray, shape (n_samples,)
            Model output.
        state : ndarray, shape (n,)
            Final play positions; only with ``return_state=True``.

        Examples
        --------
        >>> m = KP.from_density(lambda a, b: np.ones_like(a), (-1, 1), 4)
        >>> y, s = m.simulate([0.0, 1.0, -0.2], return_state=True)
        >>> np.round(y, 6).tolist(), np.round(s, 6).tolist()
        ([0.0, 2.0, 0.5], [-0.2, 0.05, 0.3, 0.25])
        """
        x = as_signal(v, "v")
        z = self.default_state() if initial_state is None else as_state(initial_state, self.n)
        if not np.all(np.isfinite(z)):
            raise ValueError("Parameter initial_state holds a non-finite play position")
        y = np.empty(x.size)
        _ko.kp_sum(x, self.v_min, self.h, self._prefix, self.offset, z, y)
        return (y, z) if return_state else y


_MODELS.setdefault("Preisach", Preisach)
_MODELS.setdefault("KP", KP)
