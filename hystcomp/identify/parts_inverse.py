"""The causal inverse of a model built from parts (what :func:`hystcomp.diagnose.diagnose`
returns): a compensator for a diagnosed actuator.

At every sample the compensator finds the input for which the model's output equals the
reference, given everything the model remembers (play states, creep lags, the clock), by
bracketing on a grid and refining it (the output is nondecreasing in the current input: the
weights are >= 0, creep coefficients >= 0, the gain and the output maps increasing), then
advances the states with that input.  This is the exact inverse of eq. 40's kind for any
part the model contains that can be inverted causally:

- the PI core with every core option (modified plays with envelopes, eq. 23; rate-dependent,
  level-dependent and asymmetric thresholds; a preload history);
- the offset, drift and sensor drift (known functions of time), gain drift;
- creep (lags of the input and of the driving model's output, inverted with their states);
- the output bends ``a H^2``, ``c H^3`` and the hinge of the driving model's output H;
- the output maps (smooth saturation, clipping: references beyond the clip are clipped).

- first-order lags before and after the hysteresis (rate dependence): both discretisations
  have a direct feedthrough, so the current input still moves the current output and the
  lag is inverted with its state (the inverse is a lead: it amplifies fast reference changes,
  up to ``1/(1 - a)`` for the lag before and ``1/b0`` for the lag after, ``b0`` the
  first-order-hold coefficient of :meth:`hystcomp.effects.LinearStage.lag`).

A dead time cannot be inverted causally, and the resonance's Tustin discretisation has its
zeros at z = -1 (an unstable inverse); :class:`PartsInverse` names the part in its error
(compensate a dead time with preview: the reference shifted that many samples earlier).
"""

import math

import numpy as np

from ._part_kernels import activated_overstress
from .parts_dynamics import Creep, _OutputBend

__all__ = ["PartsInverse", "NOT_CAUSAL"]

#: parts without a causal inverse, and what to do instead
NOT_CAUSAL = {
    "delay": "a dead time cannot be inverted causally; shift the reference earlier by the delay (preview)",
    "output_resonance": ("the resonance's bilinear (Tustin) discretisation puts both zeros at z = -1, so its "
                         "inverse is unstable; compensate the mode with a notch in the loop instead"),
    "delay_drift": "a dead time cannot be inverted causally; shift the reference earlier by the delay (preview)",
    "input_slew": ("a slew-rate limit cannot be inverted: a reference that asks for a faster input than the "
                   "limit is out of reach; keep the reference's rate below the limit and invert the model "
                   "without it"),
    "rate_term": ("the inverse does not solve for a rate term beside the hysteresis yet; invert the model "
                  "without it (drop the part) and let the loop's feedback take the rate term"),
}


def _env(s, q, b):
    u = s + q * s * s
    if b == 0.0:
        return u
    return np.tanh(b * u) / b


class _Stepper:
    """One model's output for trial inputs at one sample, and its states."""

    def __init__(self, model, n):
        self.model = model
        ctx = model._ctx
        self.ctx_n = ctx.like(np.zeros(n))
        st = model.structure
        for p in st.parts:
            if p.kind in NOT_CAUSAL:
                raise ValueError(f"The model contains the part {p.kind!r} ({p.description}): {NOT_CAUSAL[p.kind]}")
        vals = model.values
        self.origin, self.scale = ctx.origin, ctx.scale
        self.dt = ctx.dt
        options = {}
        for p in st.parts:
            if p.slot == "core" and p.kind != "core":
                p.core_options(vals.get(p.kind, {}), ctx, options)
        self.r = np.asarray(ctx.thresholds, dtype=np.float64)
        self.beta = float(options.get("beta", 0.0))
        self.rho = float(options.get("rho", 1.0))
        self.ql, self.qr = float(options.get("ql", 0.0)), float(options.get("qr", 0.0))
        self.bl, self.br = float(options.get("bl", 0.0)), float(options.get("br", 0.0))
        self.shift = float(options.get("shift", 0.0))
        self.level = float(options.get("level", 0.0))
        self.decay = float(options.get("decay", 0.0))
        self.overstress_scale = float(options.get("overstress_scale", 0.0))
        self.preload = [float(u) for u in options.get("preload", ())]
        theta = model.theta
        k = self.r.size
        self.w_core = theta[:k]
        # input slot: lags of the core's input, a_j L + (1 - a_j) x (lag_bank, at rest at the
        # first sample); the core and its rate see the lagged input, the additive parts the input
        self.input_lags = []
        for p in st.parts:
            if p.slot == "input":
                self.input_lags.append(math.exp(-ctx.dt / vals[p.kind]["time_constant"]))
        # filter slot, in the parts' order: a known multiplier per sample (gain drift) or a
        # linear stage with feedthrough (the output lag: x' = A x + B h, y = C x + D h, D > 0),
        # started at the steady state of its first input as the fit's columns are
        self.filters = []
        for p in st.parts:
            if p.slot != "filter":
                continue
            if p.kind == "output_lag":
                from ..effects import LinearStage

                stage = LinearStage.lag(vals[p.kind]["time_constant"], ctx.dt)
                x_ss = np.linalg.solve(np.eye(stage.n_states) - stage.A, stage.B).ravel()
                self.filters.append(("stage", (np.asarray(stage.A, dtype=np.float64),
                                               np.asarray(stage.B, dtype=np.float64).ravel(),
                                               np.asarray(stage.C, dtype=np.float64).ravel(),
                                               float(np.asarray(stage.D).ravel()[0]), x_ss)))
            else:
                g = p.filter(np.ones((n, 1)), vals.get(p.kind, {}), self.ctx_n)[:, 0]
                self.filters.append(("gain", g))
        # additive parts: known in time, or creep (lags with states)
        self.known = np.zeros(n)
        self.creep = []
        self.bends = []
        j = k
        for p in st.parts:
            if p.slot != "additive":
                continue
            if isinstance(p, Creep):
                tau = p.time_constants(ctx)
                m = tau.size
                a = np.exp(-ctx.dt / tau)
                w_in = theta[j:j + m]
                j += m
                driver, w_out = None, None
                if p.driver is not None:
                    w_out = theta[j:j + m]
                    j += m
                    driver = _Stepper(p.driver, n)
                # creep back: the same lags, their complements (x - L, h - L) as columns
                sign = -1.0 if p.back else 1.0
                self.creep.append((a, sign * w_in, sign * w_out, driver, float(w_in.sum()) if sign < 0 else 0.0))
            elif isinstance(p, _OutputBend):      # a bend of the driving output: its own shape
                self.bends.append((p, vals.get(p.kind, {}), float(theta[j]), _Stepper(p.driver, n)))
                j += 1
            else:
                cols = p.columns(vals.get(p.kind, {}), self.ctx_n)[0]
                c = cols.shape[1]
                self.known += cols @ theta[j:j + c]
                j += c
        self.out = st.output_part()
        self.out_values = vals.get(self.out.kind, {}) if self.out is not None else {}
        D = st.after_output(vals, self.ctx_n) if hasattr(st, "after_output") else 0.0
        self.after = np.broadcast_to(np.asarray(D, dtype=np.float64), (n,)).copy()
        self.sign = model.sign
        self.offset = getattr(model, "offset", 0.0)
        self.reset()

    def reset(self):
        self.w = np.zeros(self.r.size)
        for u in self.preload:
            self.w = self._plays(np.array([u]), self.w, rate=0.0, at_rest=True)[0]
        self.prev = None
        self.k = 0
        self.input_state = [None] * len(self.input_lags)
        self.filter_state = [None] * len(self.filters)
        self.lag_in = [None] * len(self.creep)
        self.lag_out = [None] * len(self.creep)
        for c in self.creep:
            if c[3] is not None:
                c[3].reset()
        for b in self.bends:
            b[3].reset()

    def _plays(self, x, w, rate, at_rest=False):
        """Play states after trial scaled inputs x (shape (m,)) from states w: (m, N)."""
        r = self.r
        extra = (self.beta * np.broadcast_to(np.asarray(rate, dtype=np.float64), x.shape))[:, None]
        grow = np.maximum(1.0 + self.level * x, 0.05)[:, None]
        pos = (r > 0.0)[None, :]
        ri = np.where(pos, r[None, :] * grow + extra, 0.0)
        xi = np.where(pos, x[:, None] - self.shift, x[:, None])
        lo = self.rho * _env(xi - ri, self.ql, self.bl)
        hi = _env(xi + ri, self.qr, self.br)
        wb = np.broadcast_to(w, lo.shape)
        c = np.maximum(np.minimum(wb, hi), lo)
        if self.decay > 0.0 and not at_rest:
            # viscous plays relax towards the band (the preload, at rest, is fully relaxed)
            if self.overstress_scale > 0.0:
                # Eyring's sinh law (see identify._part_kernels): tanh(|w - c| / 2s) falls by decay
                e = wb - c
                a = activated_overstress(np.abs(e), self.decay, self.overstress_scale)
                c = np.where(pos, c + np.copysign(a, e), c)
            else:
                c = np.where(pos, c + (wb - c) * self.decay, c)
        return c

    def output(self, x, commit=False):
        """Model output (in the model's sign) for trial scaled inputs x (m,) at the current
        sample; with commit, advance the states with x (one value)."""
        k = self.k
        xc, new_input = x, []
        for i, a in enumerate(self.input_lags):
            L = self.input_state[i]
            xc = xc if L is None else a * L + (1.0 - a) * xc
            new_input.append(xc)
        if self.prev is None or self.dt is None:
            rate = np.zeros_like(x)
        else:
            rate = np.abs(xc - self.prev) / self.dt
        W = self._plays(xc, self.w, rate)
        h = W @ self.w_core
        new_filter = []
        for i, (kind, f) in enumerate(self.filters):
            if kind == "gain":
                h = h * f[k]
                new_filter.append(None)
                continue
            A, B, C, D, x_ss = f
            X = self.filter_state[i]
            X = h[:, None] * x_ss[None, :] if X is None else np.broadcast_to(X, (h.size, X.size))
            new_filter.append(X @ A.T + h[:, None] * B[None, :])
            h = X @ C + D * h
        u = h + self.known[k]
        new_in, new_out, drv_out = [], [], []
        for i, (a, w_in, w_out, driver, direct) in enumerate(self.creep):
            L = self.lag_in[i]
            L = np.broadcast_to(x[:, None], (x.size, a.size)) if L is None else L[None, :]
            Lin = a * L + (1.0 - a) * x[:, None]
            u = u + Lin @ w_in + direct * x
            new_in.append(Lin)
            if driver is not None:
                h = driver.output(x)
                Lo = self.lag_out[i]
                Lo = np.broadcast_to(h[:, None], (x.size, a.size)) if Lo is None else Lo[None, :]
                Lout = a * Lo + (1.0 - a) * h[:, None]
                u = u + (Lout - h[:, None]) @ w_out
                new_out.append(Lout)
                drv_out.append(h)
            else:
                new_out.append(None)
        for part, bend_values, coef, driver in self.bends:
            u = u + coef * part.shape((driver.output(x) - part._center) / part._scale, bend_values)
        y = u if self.out is None else self.out.output(u, self.out_values, self.model._ctx)
        y = y + self.after[k]
        if commit:
            self.w = W[0].copy()
            self.prev = float(xc[0])
            for i in range(len(self.input_lags)):
                self.input_state[i] = float(new_input[i][0])
            for i, X in enumerate(new_filter):
                if X is not None:
                    self.filter_state[i] = X[0].copy()
            for i, (a, w_in, w_out, driver, _) in enumerate(self.creep):
                self.lag_in[i] = new_in[i][0].copy()
                if driver is not None:
                    driver.output(x, commit=True)
                    self.lag_out[i] = new_out[i][0].copy()
            for b in self.bends:
                b[3].output(x, commit=True)
            self.k += 1
        return y


class PartsInverse:
    """Causal compensator of a :class:`~hystcomp.identify.search.PartsModel`
    (see the module docstring): ``model.simulate(inverse.simulate(r))``
    equals ``r`` wherever the model can reach ``r`` within the input limits.

    Parameters
    ----------
    model : PartsModel
        The model to invert.
    input_limits : (float, float), optional
        Smallest and largest input the compensator may command; default the
        fitted record's input range widened by 10 % of its span on each side.
    tolerance : float, optional
        Input resolution of the per-sample solve (default 1e-9 of the input
        span).

    Examples
    --------
    >>> from hystcomp.identify.parts import Context
    >>> from hystcomp.identify.search import PartsModel, Structure, VariableProjection
    >>> v = 3 * np.sin(np.linspace(0, 20, 600))
    >>> ctx = Context(v, None, 0.0, 3.0, None, n_thresholds=8)
    >>> from hystcomp.models import PI
    >>> y = PI(3 * np.arange(1, 8) / 8, np.full(7, 0.3), 1.0).simulate(v)
    >>> vp = VariableProjection(ctx, y, np.arange(600) < 450)
    >>> pt = vp.evaluate(Structure(), {})
    >>> model = PartsModel(Structure(), pt.values, pt.theta, ctx, pt.names)
    >>> r = 0.8 * y
    >>> bool(np.max(np.abs(model.simulate(model.exact_inverse().simulate(r)) - r)) < 1e-6)
    True
    """

    def __init__(self, model, input_limits=None, tolerance=None):
        self.model = model
        ctx = model._ctx
        lo, hi = float(ctx.v.min()), float(ctx.v.max())
        if input_limits is None:
            span = (hi - lo) or 1.0
            input_limits = (lo - 0.1 * span, hi + 0.1 * span)
        try:
            a, b = (float(x) for x in input_limits)
        except (TypeError, ValueError):
            raise TypeError(f"Parameter input_limits is {input_limits!r}; expected (low, high)") from None
        if not (math.isfinite(a) and math.isfinite(b) and a < b):
            raise ValueError(f"Parameter input_limits is {input_limits!r} but should be finite with low < high")
        self.input_limits = (a, b)
        self.tolerance = (b - a) * 1e-9 if tolerance is None else float(tolerance)
        _Stepper(model, 2)          # the parts' errors now, not at the first simulate

    def simulate(self, reference):
        """The input that makes the model follow `reference`, from the model's
        start conditions (its preload and clock).

        Parameters
        ----------
        reference : array_like, shape (n,)
            Desired output, sampled as the fitted record.

        Returns
        -------
        ndarray, shape (n,)
            Input; where the reference is out of reach the nearest input limit.
        """
        from .._validation import as_signal

        ref = as_signal(reference, "reference")
        n = ref.size
        st = _Stepper(self.model, n)
        target = ref * st.sign - st.offset
        a, b = ((x - st.origin) / st.scale for x in self.input_limits)
        tol = self.tolerance / st.scale
        out = np.empty(n)
        grid = 33
        for k in range(n):
            lo, hi = a, b
            yk = target[k]
            while hi - lo > tol:
                xs = np.linspace(lo, hi, grid)
                ys = st.output(xs)
                above = np.flatnonzero(ys >= yk)
                if above.size == 0:
                    lo = hi = xs[-1]
                    break
                j = int(above[0])
                if j == 0:
                    lo = hi = xs[0]
                    break
                lo, hi = xs[j - 1], xs[j]
            x = 0.5 * (lo + hi)
            st.output(np.array([x]), commit=True)
            out[k] = st.origin + st.scale * x
        return out
