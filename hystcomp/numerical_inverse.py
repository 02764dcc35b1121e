"""Numerical inverse compensators of the Preisach, KP, Bouc-Wen,
backlash-like and Duhem models (none has an analytic inverse, thesis
section 2.3).

:class:`NumericalInverse` follows the compensator protocol of
:class:`hystcomp.inverses.ExactInverse`: ``simulate(u, initial_state=None,
return_state=False)``, ``n_states``, ``default_state()``, state
``[v_prev, *model_state]``.  Per sample it picks the input whose model
output, from the current state, is nearest the target:

* Preisach: *closest match* (Iyer, Tan and Krishnaprasad 2005, thesis
  ref. [25]): the output is piecewise constant in the input level, so the
  compensator chooses among the n + 1 levels by binary search (the output
  is non-decreasing in the level for non-negative weights) and outputs the
  cell edge of that level.  The error left is at most half an output step.
* KP, Bouc-Wen, backlash-like, Duhem: *monotone solve*: the output after a
  monotone step to v is non-decreasing in v, so bisection on v (from a
  bracket grown around the previous input) finds ``model(v) = u`` to
  `tol` in the input.

Unreachable targets (beyond the saturated outputs or the input limits)
are clipped to the nearest reachable output and reported with
:class:`hystcomp.inverses.UnreachableWarning`, or raise.
"""

import warnings

import numpy as np

from . import _kernels_other as _ko
from ._validation import as_scalar, as_signal, as_state, check_choice
from .differential import BacklashLike, BoucWen, Duhem
from .inverses import UnreachableWarning
from .preisach import KP, Preisach

__all__ = ["NumericalInverse"]


class NumericalInverse:
    """Numerical inverse compensator (closest match / monotone solve).

    Parameters
    ----------
    model : Preisach, KP, BoucWen, BacklashLike or Duhem
        The model to invert; Preisach and KP need non-negative weights.
    on_unreachable : {"clip", "raise"}
        For a desired output the model cannot reach with inputs in
        `input_limits`: "clip" outputs the input of the nearest reachable
        output and warns (:class:`~hystcomp.inverses.UnreachableWarning`);
        "raise" raises ValueError.  ``last_unreachable`` holds
        ``(count, first index)`` of the last call.
    input_limits : (float, float), optional
        Bounds of the compensator output.  Default: the grid's input range
        (Preisach, KP), else unbounded.
    tol : float, optional
        Bisection tolerance in the input (relative to ``1 + |v|`` for the
        differential models); default 1e-12.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp.differential import BoucWen
    >>> m = BoucWen(A=1.0, alpha=0.6, beta=0.2, n=1.0, gain=0.5)
    >>> comp = m.exact_inverse()
    >>> u = 2 * np.sin(np.linspace(0, 12, 1200))
    >>> bool(np.abs(m.simulate(comp.simulate(u)) - u).max() < 1e-9)
    True
    """

    def __init__(self, model, on_unreachable="clip", input_limits=None, tol=1e-12):
        if not isinstance(model, (Preisach, KP, BoucWen, BacklashLike, Duhem)):
            raise TypeError(f"Parameter model is {type(model).__name__}; expected Preisach, KP, BoucWen, "
                            "BacklashLike or Duhem (PI-family models have model.exact_inverse())")
        check_choice(on_unreachable, "on_unreachable", ("clip", "raise"))
        self.model = model
        self.on_unreachable = on_unreachable
        self.tol = as_scalar(tol, "tol", positive=True)
        if isinstance(model, (Preisach, KP)) and np.any(model._mu < 0):
            raise ValueError(
                f"The numerical inverse of a {type(model).__name__} model needs non-negative weights "
                f"(an output that increases with the input); min weight is {model._mu.min():.6g}"
            )
        if isinstance(model, BoucWen) and model.sign < 0 and not model.gain > model.max_slope():
            raise ValueError(
                f"The numerical inverse needs an output that increases with the input: y = gain v - w "
                f"does when gain > max dw/dv = {model.max_slope():.6g}, but gain = {model.gain:.6g}"
            )
        if input_limits is None:
            if isinstance(model, (Preisach, KP)):
                input_limits = (model.v_min, model.v_max)
            else:
                input_limits = (-np.inf, np.inf)
        try:
            lo, hi = float(input_limits[0]), float(input_limits[1])
        except (TypeError, IndexError, ValueError):
            raise ValueError(f"Parameter input_limits is {input_limits!r} but should be (lo, hi)") from None
        if not lo < hi:
            raise ValueError(f"Parameter input_limits is {input_limits!r} but should satisfy lo < hi")
        self.input_limits = (lo, hi)
        self.n_states = 1 + model.n_states
        self.last_unreachable = (0, -1)

    def default_state(self):
        """``[last input 0, the model's default state]``.

        Returns
        -------
        ndarray, shape (n_states,)

        Examples
        --------
        >>> from hystcomp.differential import BacklashLike
        >>> BacklashLike(alpha=1.0, c=3.0, B1=1.0).exact_inverse().default_state().tolist()
        [0.0, 0.0, 0.0]
        """
        return np.concatenate([[0.0], self.model.default_state()])

    def simulate(self, u, initial_state=None, return_state=False):
        """Compensator output v with ``model.simulate(v)`` nearest u.

        Parameters
        ----------
        u : array_like, shape (n,)
            Desired model outputs.
        initial_state : array_like, optional
            ``[v_prev, *model_state]``; default :meth:`default_state`.
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        v : ndarray, shape (n,)
            Compensator output (the model's input).
        state : ndarray, shape (n_states,)
            Final ``[v_prev, *model_state]``; only with ``return_state=True``.

        Warns
        -----
        UnreachableWarning
            With ``on_unreachable="clip"``, when some targets are out of reach.

        Raises
        ------
        ValueError
            With ``on_unreachable="raise"``, when some targets are out of reach.

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp.differential import BacklashLike
        >>> m = BacklashLike(alpha=1.0, c=3.0, B1=1.0)
        >>> comp = m.exact_inverse(input_limits=(-1.0, 1.0))
        >>> v = comp.simulate([0.0, 1.5])
        >>> np.round(m.simulate(v), 9).tolist()
        [0.0, 1.5]
        >>> import warnings
        >>> with warnings.catch_warnings():
        ...     warnings.simplefilter("ignore")
        ...     v = comp.simulate([0.0, 10.0])   # 10 needs v > 1: clipped
        >>> v.tolist(), comp.last_unreachable
        ([0.0, 1.0], (1, 1))
        """
        target = as_signal(u, "u")
        st = self.default_state() if initial_state is None else as_state(initial_state, self.n_states)
        m = self.model
        out = np.empty(target.size)
        info = np.array([0, -1], dtype=np.int64)
        lo, hi = self.input_limits
        if isinstance(m, Preisach):
            k = m._check_state(st[1:])
            if (lo, hi) != (m.v_min, m.v_max):
                raise ValueError("Parameter input_limits of a Preisach compensator must be the grid's "
                                 f"input_range {m.input_range} (it outputs cell edges)")
            _ko.preisach_inverse(target, m.v_min, m.h, m._table, m.offset, k, m.edges, out, info)
            mstate = k.astype(np.float64)
            vlast = out[-1]
        elif isinstance(m, KP):
            z = st[1:].copy()
            vprev = min(max(st[0], max(lo, m.v_min)), min(hi, m.v_max))
            vlast = _ko.kp_inverse(target, max(lo, m.v_min), min(hi, m.v_max), m.h, m._prefix, m.offset, z,
                                   vprev, self.tol * max(1.0, abs(m.v_max) + abs(m.v_min)), out, info)
            mstate = z
        elif isinstance(m, (BoucWen, BacklashLike)):
            ms = st[1:].copy()
            kind = _ko.BOUC_WEN if isinstance(m, BoucWen) else _ko.BACKLASH
            gain = m.gain if isinstance(m, BoucWen) else 0.0
            _ko.diff_inverse(kind, m._prm, gain, m.offset, target, ms, lo, hi, self.tol, out, info)
            mstate = ms
            vlast = ms[0]
        else:
            mstate, vlast = self._duhem(target, st[1:].copy(), out, info)
        count, first = int(info[0]), int(info[1])
        self.last_unreachable = (count, first)
        if count:
            msg = (f"{count} of {target.size} targets are outside the outputs the model can reach with "
                   f"inputs in {self.input_limits} (first at sample index {first}, u = {target[first]:.6g})")
            if self.on_unreachable == "raise":
                raise ValueError(msg)
            warnings.warn(msg + "; clipped to the nearest reachable output", UnreachableWarning, stacklevel=2)
        final = np.concatenate([[vlast], mstate])
        return (out, final) if return_state else out

    def _duhem(self, target, ms, out, info):
        """Python bisection for the Duhem model (its step runs through simulate)."""
        m = self.model
        lo, hi = self.input_limits

        def step(v):
            y, s = m.simulate(np.array([v]), initial_state=ms, return_state=True)
            return y[0], s

        for t, u in enumerate(target):
            v0 = ms[0]
            y0 = m.gain * v0 + ms[1] + m.offset
            if u == y0:
                out[t] = v0
                continue
            s = 1.0 if u > y0 else -1.0
            lim = hi if s > 0 else lo
            stepsize = 1e-3 * (abs(v0) + 1.0)
            a = b = v0
            ya = y0
            found = False
            for _ in range(200):
                b = v0 + s * stepsize
                if (s > 0 and b >= lim) or (s < 0 and b <= lim):
                    b = lim
                yb, _s = step(b)
                if (s > 0 and yb >= u) or (s < 0 and yb <= u):
                    found = True
                    break
                if b == lim:
                    break
                # saturated (as in _kernels_other.diff_inverse): settle on
                # the first input that reaches that output
                if not (s * (yb - ya) > self.tol * (1.0 + abs(yb))) and stepsize > 1.0 + abs(v0):
                    near, far = v0, a
                    for _k in range(200):
                        mid = 0.5 * (near + far)
                        if mid in (near, far):
                            break
                        if s * (ya - step(mid)[0]) > self.tol * (1.0 + abs(ya)):
                            near = mid
                        else:
                            far = mid
                    b = far
                    break
                a = b
                ya = yb
                stepsize *= 2.0
            if found:
                x0, x1 = min(a, b), max(a, b)
                while x1 - x0 > self.tol * (1.0 + abs(x0)):
                    mid = 0.5 * (x0 + x1)
                    if mid <= x0 or mid >= x1:
                        break
                    if step(mid)[0] < u:
                        x0 = mid
                    else:
                        x1 = mid
                b = x1 if s > 0 else x0
            else:
                info[0] += 1
                if info[1] < 0:
                    info[1] = t
            _, ms = step(b)
            out[t] = b
        return ms, ms[0]

    def __repr__(self):
        return f"NumericalInverse({self.model!r}, input_limits={self.input_limits})"
