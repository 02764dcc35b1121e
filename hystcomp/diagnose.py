"""Find where a hysteresis model and a measurement disagree, and name the missing effect.

:func:`diagnose` fits a plain PI model (eq. 18, :func:`hystcomp.identify.fit_weights`)
on the first part of a record, reads the residual where each effect leaves
its signature, then tries each effect's extension -- a real model part of
:mod:`hystcomp.effects` or an mGPI envelope -- and keeps the one that most
reduces the error on the held-out tail, as long as it pays:

* ``rate_dependence``: a linear stage after the hysteresis (first-order lag
  or lightly damped resonance, :class:`~hystcomp.effects.LinearStage`), a lag
  before it, or rate-dependent thresholds
  (:class:`~hystcomp.effects.RateDependentPI`); the best of the four;
* ``creep``: Kuhnen's creep operator (:class:`~hystcomp.effects.CreepOperator`),
  lags of the input on a logarithmic grid of time constants;
* ``drift``: ``a t + b (1 - exp(-t/tau))`` (:class:`~hystcomp.effects.DriftTerm`);
* ``asymmetry``: an asymmetric mGPI, ``gl = rho (v + c_l v^2/V)``,
  ``gr = v + c_r v^2/V`` (eq. 23 with gl != gr);
* ``saturation``: a symmetric mGPI with ``gamma = tanh(b v)/b`` (eq. 25).

The linear parameters (weights, creep and drift coefficients, offset) are
solved by bounded least squares on the training samples; the few nonlinear
ones (time constants, frequency and damping, rate coefficient, envelope
parameters) by variable projection (scipy.optimize on the training error).
An effect is added when its extension lowers the Bayesian information
criterion ``n ln(RSS/n) + k ln n`` on the training part *and* shrinks the
held-out RMS by at least `min_gain` (relative); then the remaining effects
are tried on top of it, up to `max_effects`.  Nonlinear parameters of
effects already added stay fixed; every linear parameter is refitted.
"""

import argparse
import json
import math
import os
import sys
import time
import warnings

import numpy as np
from numba import njit
from scipy.linalg import cholesky, solve_triangular
from scipy.optimize import lsq_linear, minimize, minimize_scalar

from . import _kernels as _k
from ._validation import as_scalar, as_signal, check_choice
from .effects import CreepOperator, DriftTerm, LinearStage, Parallel, RateDependentPI, Series, \
    _rate_play_states, lag_bank
from .envelopes import Polynomial, Tanh
from .models import MGPI, PI

__all__ = ["EFFECTS", "ALL", "Diagnosis", "diagnose", "evidence", "add_arguments", "run", "load_csv"]

EFFECTS = ("rate_dependence", "creep", "drift", "asymmetry", "saturation")
#: every effect (the default of :func:`diagnose`)
ALL = EFFECTS


# ----------------------------------------------------------------------------
# data and signatures
# ----------------------------------------------------------------------------
class _Data:
    def __init__(self, t, v, y, validation):
        self.t = as_signal(t, "t", min_length=2)
        self.v = as_signal(v, "v", min_length=2)
        self.y = as_signal(y, "y", min_length=2)
        n = self.t.size
        for name, a in (("v", self.v), ("y", self.y)):
            if a.size != n:
                raise ValueError(f"Parameter {name} has {a.size} samples but t has {n}; "
                                 "expected equal lengths")
        d = np.diff(self.t)
        if np.any(d <= 0):
            k = int(np.argmax(d <= 0)) + 1
            raise ValueError(f"Parameter t is not increasing: t[{k}] = {self.t[k]} follows t[{k - 1}] = "
                             f"{self.t[k - 1]}")
        self.dt = float(np.median(d))
        if np.max(np.abs(d - self.dt)) > 0.05 * self.dt:
            k = int(np.argmax(np.abs(d - self.dt)))
            raise ValueError(f"Parameter t is not uniformly sampled: step {d[k]} at sample {k} against the "
                             f"median {self.dt}; diagnose needs a uniform sampling time (resample first)")
        frac = as_scalar(validation, "validation")
        if not 0.0 < frac < 0.9:
            raise ValueError(f"Parameter validation is {frac} but should be a fraction in (0, 0.9) "
                             "(the last part of the record is held out)")
        self.n = n
        self.k_val = int(round(n * (1.0 - frac)))
        if self.k_val < 50 or n - self.k_val < 20:
            raise ValueError(f"Parameters t, v, y have {n} samples; at least 50 training and 20 held-out "
                             "samples are needed")
        self.train = np.zeros(n, bool)
        self.train[:self.k_val] = True
        self.tk = np.arange(n, dtype=np.float64) * self.dt        # t = k dt (DriftTerm's clock)
        self.T = n * self.dt
        self.V = float(np.max(np.abs(self.v)))
        self.span = float(np.ptp(self.v))
        if self.span <= 0:
            raise ValueError(f"Parameter v is constant ({self.v[0]}); diagnosis needs an input that moves")
        # smoothed rate (a 5-sample centred difference keeps measured noise down)
        m = 2
        vp = np.pad(self.v, m, mode="edge")
        self.rate = (vp[2 * m:] - vp[:-2 * m]) / (2 * m * self.dt)
        self.holds = _holds(self.v, self.dt, self.span)
        # how much of the input's power sits near one frequency (rate dependence needs several)
        P = np.abs(np.fft.rfft(self.v - self.v.mean())) ** 2
        f = np.fft.rfftfreq(n, self.dt)
        P, f = P[1:], f[1:]
        self.f_peak = float(f[np.argmax(P)]) if P.size else 0.0
        band = (f >= self.f_peak / 1.5) & (f <= self.f_peak * 1.5)
        self.peak_share = float(P[band].sum() / P.sum()) if P.sum() > 0 else 1.0


def _holds(v, dt, span):
    """(start, end, step) of each stretch where the input stays put for at least
    max(10 samples, 0.1 s); step is the input's change against its mean over
    the 2 s before the hold (creep follows the recent input history)."""
    tol = 1e-4 * span
    still = np.abs(np.diff(v, prepend=v[0])) <= tol
    min_len = max(10, int(round(0.1 / dt)))
    W = max(min_len, int(round(2.0 / dt)))
    out, k, n = [], 0, v.size
    while k < n:
        if still[k]:
            j = k
            while j < n and still[j]:
                j += 1
            if j - k >= min_len and k > 0:
                out.append((k, j, float(v[k] - v[max(0, k - W):k].mean())))
            elif j - k >= min_len:
                out.append((k, j, 0.0))
            k = j
        else:
            k += 1
    return out


def _r2(e, F):
    """Coefficient of determination of e regressed on the columns of F (with an intercept)."""
    X = np.column_stack([np.ones(e.size), F])
    coef, *_ = np.linalg.lstsq(X, e, rcond=None)
    res = e - X @ coef
    tot = float(np.sum((e - e.mean()) ** 2))
    return (1.0 - float(np.sum(res ** 2)) / tot if tot > 0 else 0.0), coef[1:]


def _hold_changes(d, e):
    rows = []
    for k, j, step in d.holds:
        m = max(2, (j - k) // 5)
        rows.append((step, float(e[j - m:j].mean() - e[k:k + m].mean()), (j - k) * d.dt))
    return np.array(rows).reshape(-1, 3)


def _evidence(d, e):
    """Signatures of every effect in the residual e (all samples)."""
    ev = {}
    u = d.v / d.V
    rate = d.rate / (np.max(np.abs(d.rate)) or 1.0)
    acc = np.gradient(rate)
    acc = acc / (np.max(np.abs(acc)) or 1.0)
    r2, _ = _r2(e, np.column_stack([rate, acc]))
    corr = float(np.corrcoef(e, rate)[0, 1]) if np.std(e) > 0 else 0.0
    ev["rate_dependence"] = {
        "signature": "residual against the input rate dv/dt and its change",
        "r2_rate": round(r2, 4), "corr_rate": round(corr, 4), "testable": True,
        "input_power_near_peak": round(d.peak_share, 4),
        "reading": ("the residual follows the input rate: the output depends on how fast the "
                    "input moves" if r2 > 0.2 else "the residual barely follows the input rate"),
    }
    if d.peak_share >= 0.9:
        ev["rate_dependence"]["testable"] = False
        ev["rate_dependence"]["reading"] = (
            f"untested: {100 * d.peak_share:.0f} % of the input's power lies within a factor 1.5 of "
            f"{d.f_peak:.3g} Hz; at one rate of excitation rate dependence cannot be told from the "
            "loop's shape (add sines at other frequencies)")
    hc = _hold_changes(d, e)
    moved = hc[np.abs(hc[:, 0]) > 1e-3 * d.span] if hc.size else hc
    n_up = int(np.sum(moved[:, 0] > 0)) if moved.size else 0
    n_down = int(np.sum(moved[:, 0] < 0)) if moved.size else 0
    if n_up >= 1 and n_down >= 1 and moved.shape[0] >= 3:
        X = np.column_stack([moved[:, 0], moved[:, 2]])
        coef, *_ = np.linalg.lstsq(X, moved[:, 1], rcond=None)
        c_corr = float(np.corrcoef(moved[:, 0], moved[:, 1])[0, 1]) if np.std(moved[:, 1]) > 0 else 0.0
        ev["creep"] = {
            "signature": "residual change during each hold against the input step into it "
                         "(hold level minus the mean input of the 2 s before)",
            "holds": int(moved.shape[0]), "corr_step": round(c_corr, 4),
            "change_per_unit_step": float(f"{coef[0]:.4g}"), "testable": True,
            "reading": ("the output keeps moving during holds in the sign of the last step"
                        if c_corr > 0.5 else "no consistent movement after steps"),
        }
    else:
        ev["creep"] = {"signature": "residual change during holds against the preceding step",
                       "holds": int(moved.shape[0]) if moved.size else 0, "testable": False,
                       "reading": "untested: the data hold the input still after steps in both "
                                  "directions too rarely (need holds after up and down steps)"}
    if hc.size:
        rate_all = hc[:, 1] / hc[:, 2]
        X = np.column_stack([hc[:, 0] / hc[:, 2], np.ones(hc.shape[0])]) if hc.shape[0] >= 3 else \
            np.ones((hc.shape[0], 1))
        coef, *_ = np.linalg.lstsq(X, rate_all, rcond=None)
        common = float(coef[-1])
        seg = max(1, d.n // 40)
        nb = d.n // seg
        eb = e[:nb * seg].reshape(nb, seg).mean(axis=1)
        tb = d.tk[:nb * seg].reshape(nb, seg).mean(axis=1) / d.T
        r2t, _ = _r2(eb, np.column_stack([tb, tb ** 2]))
        ev["drift"] = {
            "signature": "common residual trend during holds, and the residual's slow trend in time",
            "hold_drift_rate": float(f"{common:.4g}"), "r2_time": round(r2t, 4), "testable": True,
            "reading": ("the residual moves with time whatever the input does" if r2t > 0.5
                        else "no clear trend in time"),
        }
    else:
        ev["drift"] = {"signature": "residual trend during holds", "testable": False,
                       "reading": "untested: the input is never held still, so a slow trend cannot be "
                                  "told from the hysteresis"}
    s = np.sign(d.rate)
    r2a, _ = _r2(e, np.column_stack([u ** 2, np.abs(u), s * u ** 2, s]))
    ev["asymmetry"] = {
        "signature": "residual against even and direction-dependent functions of the input "
                     "(v^2, |v|, sign(dv/dt) v^2)",
        "r2_even_or_direction": round(r2a, 4), "testable": True,
        "reading": ("positive and negative inputs or rising and falling branches differ"
                    if r2a > 0.2 else "branches look symmetric"),
    }
    r2s, cs = _r2(e, np.column_stack([u, u ** 3]))
    ev["saturation"] = {
        "signature": "residual against the odd cubic v^3 (gain change at large |v|)",
        "r2_cubic": round(r2s, 4), "cubic_coefficient": float(f"{cs[1]:.4g}"), "testable": True,
        "reading": ("the incremental gain falls at large |v|" if r2s > 0.2 and cs[1] < 0
                    else "no gain loss at large |v|"),
    }
    return ev


def evidence(t, v, y, model=None, validation=0.3):
    """The residual signatures of every effect for a model's residual (default
    a plain PI model fitted on the training part), as a dict of dicts.

    Parameters
    ----------
    t, v, y : array_like, shape (n,)
        Time [s] (increasing, uniformly sampled), input and measured output.
    model : model, optional
        A model whose ``simulate(v)`` predicts y (offset included, e.g.
        :attr:`Diagnosis.model`); default a plain PI model fitted on the
        training part.
    validation : float
        Fraction of the record held out at its end (not used to fit the
        default model).

    Returns
    -------
    dict
        Effect name -> dict with ``signature`` (what is measured),
        the effect's statistics, ``testable`` (whether the data can show the
        effect) and ``reading`` (a sentence).

    Examples
    --------
    >>> from hystcomp.datasets import hidden_effect_data
    >>> d = hidden_effect_data("saturation", seed=0, dt=0.01, mechanism="cubic")
    >>> ev = evidence(d.t, d.v, d.y)
    >>> sorted(ev), ev["saturation"]["cubic_coefficient"] < 0
    (['asymmetry', 'creep', 'drift', 'rate_dependence', 'saturation'], True)
    """
    d = _Data(t, v, y, validation)
    if model is None:
        st = _Structure(d, _base_thresholds(d))
        pred = st.fit().pred
    else:
        pred = model.simulate(d.v)
    return _evidence(d, d.y - pred)


# ----------------------------------------------------------------------------
# extended model structure: columns, bounded least squares, model
# ----------------------------------------------------------------------------
def _base_thresholds(d, n=20):
    return 0.5 * d.span * np.arange(1, n + 1) / (n + 1)


class _Fit:
    def __init__(self, **kw):
        self.__dict__.update(kw)


@njit(cache=True)
def _asym_play_states(x, r, rho, ql, qr, w, out):
    """Modified plays (eq. 23) with gl(s) = rho (s + ql s^2), gr(s) = s + qr s^2:
    the same outputs as :func:`hystcomp.operators.modified_play` with those
    Polynomial envelopes, without the generic envelope dispatch."""
    for k in range(x.size):
        xk = x[k]
        for i in range(r.size):
            a = xk - r[i]
            b = xk + r[i]
            lo = rho * (a + ql * a * a)
            hi = b + qr * b * b
            wi = w[i]
            wi = hi if wi > hi else wi
            wi = lo if wi < lo else wi
            w[i] = wi
            out[k, i] = wi


class _Structure:
    """An extended model structure: which parts, with their nonlinear parameters."""

    def __init__(self, d, r, **parts):
        self.d = d
        self.r = r
        self.input_lag = parts.get("input_lag")            # tau
        self.rate_beta = parts.get("rate_beta")            # beta
        self.envelope = parts.get("envelope")              # ("tanh", b) | ("asym", rho, cl, cr)
        self.output_stage = parts.get("output_stage")      # ("lag", tau) | ("resonance", f, z)
        self.creep = parts.get("creep")                    # tuple of taus
        self.creep_driver = parts.get("creep_driver")      # frozen hysteresis estimate (a model)
        self.drift = parts.get("drift")                    # tau of the exponential
        self.effects = tuple(parts.get("effects", ()))

    def replace(self, **kw):
        parts = dict(input_lag=self.input_lag, rate_beta=self.rate_beta, envelope=self.envelope,
                     output_stage=self.output_stage, creep=self.creep, drift=self.drift,
                     creep_driver=self.creep_driver,
                     effects=self.effects)
        parts.update(kw)
        return _Structure(self.d, self.r, **parts)

    @property
    def n_nonlinear(self):
        k = int(self.input_lag is not None) + int(self.rate_beta is not None) + int(self.drift is not None)
        if self.envelope is not None:
            k += 1 if self.envelope[0] == "tanh" else 3
        if self.output_stage is not None:
            k += 1 if self.output_stage[0] == "lag" else 2
        return k

    # -- pieces
    def _x(self):
        d = self.d
        if self.input_lag is None:
            return d.v
        return lag_bank(d.v, [self.input_lag], d.dt)[0][:, 0].copy()

    def _envelopes(self):
        env = self.envelope
        V = self.d.V
        if env is None:
            return None
        if env[0] == "tanh":
            b = env[1] / V
            return Tanh(1.0 / b, b)
        rho, cl, cr = env[1:]
        lo, hi = -2.0 * V, 2.0 * V      # v - r and v + r stay inside (r <= span/2 <= V)
        return (Polynomial([0.0, rho, rho * cl / V], interval=(lo, hi)),
                Polynomial([0.0, 1.0, cr / V], interval=(lo, hi)))

    def _core(self, x):
        r = self.r
        env = self._envelopes()
        if env is not None and not isinstance(env, Tanh):
            rho, cl, cr = self.envelope[1:]
            out = np.empty((x.size, r.size + 1))
            _asym_play_states(x, np.concatenate([[0.0], r]), rho, cl / self.d.V, cr / self.d.V,
                              np.zeros(r.size + 1), out)
            return out
        Z = np.empty((x.size, r.size))
        if self.rate_beta is not None:
            _rate_play_states(x, r, float(self.rate_beta), self.d.dt, np.zeros(r.size), np.zeros(2), Z)
        else:
            _k.play_states(x, r, np.zeros(r.size), Z)
        cols = np.column_stack([x, Z])
        if env is not None:
            cols = env._value(cols)
        return cols

    def _stage(self):
        st = self.output_stage
        if st is None:
            return None
        if st[0] == "lag":
            return LinearStage.lag(st[1], self.d.dt)
        return LinearStage.resonance(st[1], st[2], self.d.dt)

    def columns(self):
        """(A, lower bounds, column groups)."""
        d = self.d
        core = self._core(self._x())
        stage = self._stage()
        if stage is not None:
            core, _ = stage.filter_columns(core)
        blocks = [core]
        lower = [np.zeros(core.shape[1])]
        groups = {"core": core.shape[1]}
        if self.creep is not None:
            X, _ = lag_bank(d.v, self.creep, d.dt)
            blocks.append(X)
            lower.append(np.zeros(X.shape[1]))
            groups["creep"] = X.shape[1]
            if self.creep_driver is not None:
                if getattr(self, "_driver_cols", None) is None:
                    self._driver_cols = lag_bank(self.creep_driver.simulate(d.v), self.creep, d.dt)[0]
                blocks.append(self._driver_cols)
                lower.append(np.zeros(len(self.creep)))
                groups["creep_output"] = len(self.creep)
        if self.drift is not None:
            D = np.column_stack([d.tk / d.T, -np.expm1(-d.tk / self.drift)])
            blocks.append(D)
            lower.append(np.full(2, -np.inf))
            groups["drift"] = 2
        blocks.append(np.ones((d.n, 1)))
        lower.append(np.array([-np.inf]))
        groups["offset"] = 1
        return np.column_stack(blocks), np.concatenate(lower), groups

    def fit(self):
        d = self.d
        A, lower, groups = self.columns()
        k = d.k_val                      # the training part is the first k samples
        At, yt = A[:k], d.y[:k]
        scale = np.sqrt(np.einsum("ij,ij->j", At, At) / k)
        scale[scale == 0] = 1.0
        As = At / scale
        # normal equations on equilibrated columns (cheaper than a QR of the
        # tall matrix; the bounded solve then runs on the m x m Cholesky factor)
        G = As.T @ As
        b = As.T @ yt
        m = G.shape[0]
        G[np.diag_indices(m)] += 1e-12 * np.trace(G)
        L = cholesky(G, lower=True)
        qy = solve_triangular(L, b, lower=True)
        res = lsq_linear(L.T, qy, bounds=(lower, np.full(m, np.inf)), method="bvls", tol=1e-12)
        theta = res.x / scale
        pred = A @ theta
        e = d.y - pred
        rss = float(np.sum(e[:k] ** 2))
        k_eff = int(np.sum(np.abs(res.x) > 0)) + self.n_nonlinear
        bic = k * math.log(max(rss / k, 1e-300)) + k_eff * math.log(k)
        rms_val = float(np.sqrt(np.mean(e[k:] ** 2)))
        return _Fit(theta=theta, pred=pred, rss=rss, bic=bic, rms_val=rms_val,
                    rms_train=math.sqrt(rss / k), groups=groups, structure=self, n_params=k_eff)

    def model(self, theta, groups):
        """The fitted model as protocol blocks (hystcomp.effects)."""
        d = self.d
        i = 0
        nc = groups["core"]
        w = theta[i:i + nc]
        i += nc
        env = self._envelopes()
        if env is not None and not isinstance(env, Tanh):
            core = MGPI(self.r, w[1:], w[0], envelope_left=env[0], envelope_right=env[1])
        elif env is not None:
            core = MGPI(self.r, w[1:], w[0], envelope=env)
        elif self.rate_beta is not None:
            core = RateDependentPI(self.r, w[1:], w[0], self.rate_beta, d.dt)
        else:
            core = PI(self.r, w[1:], w[0])
        chain = []
        if self.input_lag is not None:
            chain.append(LinearStage.lag(self.input_lag, d.dt))
        chain.append(core)
        if self.output_stage is not None:
            chain.append(self._stage())
        hyst = chain[0] if len(chain) == 1 else Series(*chain)
        blocks = [hyst]
        if "creep" in groups:
            c = theta[i:i + groups["creep"]]
            i += groups["creep"]
            blocks.append(CreepOperator(self.creep, c, d.dt))
        if "creep_output" in groups:
            c = theta[i:i + groups["creep_output"]]
            i += groups["creep_output"]
            blocks.append(Series(self.creep_driver, CreepOperator(self.creep, c, d.dt)))
        if "drift" in groups:
            a, b = theta[i:i + 2]
            i += 2
            blocks.append(DriftTerm(d.dt, polynomial=[a / d.T], amplitudes=[b], time_constants=[self.drift]))
        offset = float(theta[i])
        return Parallel(*blocks, offset=offset)


# ----------------------------------------------------------------------------
# candidates
# ----------------------------------------------------------------------------
def _best(fits):
    fits = [f for f in fits if f is not None]
    return min(fits, key=lambda f: f.bic) if fits else None


def _search_1d(make, lo, hi, n_grid=7):
    """Minimise the training RSS over one parameter: a log grid, then Brent's bounded search."""
    grid = np.linspace(lo, hi, n_grid)
    fits = {}

    def f(x):
        key = float(x)
        if key not in fits:
            try:
                fits[key] = make(x).fit()
            except ValueError:
                return np.inf
        return fits[key].rss
    vals = [f(x) for x in grid]
    j = int(np.argmin(vals))
    a, b = grid[max(0, j - 1)], grid[min(n_grid - 1, j + 1)]
    if b > a:
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)     # Brent's step on an infeasible point
            minimize_scalar(f, bounds=(a, b), method="bounded",
                            options={"xatol": 0.02 * (hi - lo), "maxiter": 12})
    return min(fits.values(), key=lambda ft: ft.rss)


def _candidate(effect, cur):
    """The best fit of the current fit's structure extended by `effect`, or (None, reason)."""
    st = cur.structure
    d = st.d
    if effect == "rate_dependence":
        fits = []
        if st.output_stage is None:
            fits.append(_search_1d(lambda x: st.replace(output_stage=("lag", math.exp(x))),
                                   math.log(d.dt * 0.5), math.log(max(0.5, 50 * d.dt))))
            # resonance: grid over frequency and damping, then Nelder-Mead
            f_hi = 0.3 / d.dt
            f_lo = max(0.5, 5.0 / d.T)
            best = None
            for fr in np.geomspace(f_lo, f_hi, 10):
                for z in (0.05, 0.15, 0.4):
                    ft = st.replace(output_stage=("resonance", fr, z)).fit()
                    if best is None or ft.rss < best.rss:
                        best = ft
            x0 = [math.log(best.structure.output_stage[1]), math.log(best.structure.output_stage[2])]
            cache = {"best": best}

            def cost(x):
                fr, z = math.exp(x[0]), math.exp(x[1])
                if not (f_lo * 0.5 <= fr <= 0.45 / d.dt and 0.005 <= z <= 2.0):
                    return np.inf
                ft = st.replace(output_stage=("resonance", fr, z)).fit()
                if ft.rss < cache["best"].rss:
                    cache["best"] = ft
                return ft.rss
            minimize(cost, x0, method="Nelder-Mead", options={"maxfev": 40, "xatol": 0.01, "fatol": 0.0})
            fits.append(cache["best"])
        if st.input_lag is None and st.output_stage is None:
            fits.append(_search_1d(lambda x: st.replace(input_lag=math.exp(x)),
                                   math.log(d.dt * 0.5), math.log(max(0.5, 50 * d.dt))))
        if st.rate_beta is None and (st.envelope is None or st.envelope[0] == "tanh"):
            rmax = float(np.max(np.abs(np.diff(d.v)))) / d.dt or 1.0
            scale = d.span / rmax
            fits.append(_search_1d(lambda x: st.replace(rate_beta=scale * math.exp(x)),
                                   math.log(1e-3), math.log(1.0)))
        if not fits:
            return None, "rate dependence is already in the model"
        return _best(fits), None
    if effect == "creep":
        if st.creep is not None:
            return None, "creep is already in the model"
        hi = max(0.2, d.T / 4)
        lo = min(max(0.05, 20 * d.dt), hi / 10)
        taus = tuple(np.geomspace(lo, hi, max(3, int(round(np.log10(hi / lo) * 1.5)) + 1)).tolist())
        # creep driven by the input, and by the hysteresis output: the current model's
        # hysteresis part, frozen, drives a second bank (Kuhnen's creep on the output)
        driver = st.model(cur.theta, cur.groups).blocks[0]
        return st.replace(creep=taus, creep_driver=driver).fit(), None
    if effect == "drift":
        if st.drift is not None:
            return None, "drift is already in the model"
        fits = [st.replace(drift=tau * d.T).fit() for tau in (0.05, 0.1, 0.2, 0.4, 0.8, 1.6)]
        return min(fits, key=lambda f: f.rss), None
    if effect == "asymmetry":
        if st.envelope is not None:
            return None, "the envelope is already taken by " + ("saturation" if st.envelope[0] == "tanh"
                                                               else "asymmetry")
        if st.rate_beta is not None:
            return None, "asymmetric envelopes do not combine with rate-dependent thresholds here"
        cache = {}

        def cost(x):
            key = tuple(np.round(x, 12))
            if key not in cache:
                try:
                    cache[key] = st.replace(envelope=("asym", math.exp(x[0]), x[1], x[2])).fit()
                except ValueError:
                    return np.inf
            return cache[key].rss
        minimize(cost, [0.0, 0.0, 0.0], method="Powell",
                 bounds=[(math.log(0.25), math.log(4.0)), (-0.2, 0.2), (-0.2, 0.2)],
                 options={"maxfev": 120, "xtol": 1e-3, "ftol": 1e-6})
        return min(cache.values(), key=lambda f: f.rss), None
    if effect == "saturation":
        if st.envelope is not None:
            return None, "the envelope is already taken by asymmetry"
        return _search_1d(lambda x: st.replace(envelope=("tanh", math.exp(x))),
                          math.log(0.05), math.log(4.0)), None
    raise ValueError(effect)


def _describe(effect, st):
    """Readable parameters of an effect's extension in a structure."""
    if effect == "rate_dependence":
        if st.output_stage is not None and st.output_stage[0] == "lag":
            return {"extension": "first-order lag after the hysteresis", "time_constant": st.output_stage[1]}
        if st.output_stage is not None:
            return {"extension": "resonance after the hysteresis", "frequency": st.output_stage[1],
                    "damping": st.output_stage[2]}
        if st.input_lag is not None:
            return {"extension": "first-order lag before the hysteresis", "time_constant": st.input_lag}
        return {"extension": "rate-dependent thresholds r_i + beta |dv/dt|", "rate_coefficient": st.rate_beta}
    if effect == "creep":
        return {"extension": "creep operators (lags of the input and of the hysteresis output)",
                "time_constants": list(st.creep)}
    if effect == "drift":
        return {"extension": "drift a t + b (1 - exp(-t/tau))", "time_constant": st.drift}
    if effect == "asymmetry":
        return {"extension": "asymmetric mGPI envelopes", "rho": st.envelope[1], "c_left": st.envelope[2],
                "c_right": st.envelope[3]}
    return {"extension": "tanh envelope (mGPI)", "b_times_max_input": st.envelope[1]}


# ----------------------------------------------------------------------------
# report
# ----------------------------------------------------------------------------
class Diagnosis:
    """The outcome of :func:`diagnose`.

    Attributes
    ----------
    effects : list of str
        The effects added, in order (empty: the base model explains the data).
    steps : list of dict
        One per added effect: ``effect``, ``rms_before``, ``rms_after`` (held-out
        RMS), ``evidence`` (the residual signature, the extension and its
        parameters, the held-out RMS of every candidate tried at that step).
    rms_before, rms_after : float
        Held-out RMS of the base and of the final model.
    validation : (float, float)
        Start and end time of the held-out part.
    model : Parallel
        The final model (hystcomp.effects blocks; ``model.simulate(v)`` predicts y).
    base_model : Parallel
        The base PI model with its offset.
    untested : dict
        Effects the data cannot show, with the reason.
    stopped : str
        Why the search stopped.

    Examples
    --------
    >>> from hystcomp.datasets import hidden_effect_data
    >>> d = hidden_effect_data("drift", seed=3, dt=0.01)
    >>> rep = diagnose(d.t, d.v, d.y, effects=["drift"], progress=False)
    >>> rep.effects, rep.steps[0]["effect"], rep.rms_after < rep.rms_before
    (['drift'], 'drift', True)
    >>> print(rep.summary().splitlines()[-1])
    effects: drift; held-out RMS 0.02371 -> 0.005759; stopped: every candidate effect was added
    """

    def __init__(self, **kw):
        self.__dict__.update(kw)

    def to_dict(self):
        """The JSON object of ``hystcomp diagnose --json``."""
        return {"effects": list(self.effects), "rms_before": self.rms_before, "rms_after": self.rms_after,
                "validation": [float(self.validation[0]), float(self.validation[1])],
                "steps": [{"effect": s["effect"], "rms_before": s["rms_before"], "rms_after": s["rms_after"],
                           "evidence": s["evidence"]} for s in self.steps]}

    def to_json(self):
        """:meth:`to_dict` as a JSON string (numpy values converted)."""
        return json.dumps(_jsonable(self.to_dict()))

    def summary(self):
        """A readable report (str)."""
        lines = [f"base model: PI with {self._r.size} thresholds; held-out RMS {self.rms_before:.4g} "
                 f"(t = {self.validation[0]:.4g} .. {self.validation[1]:.4g} s)"]
        for name, why in self.untested.items():
            lines.append(f"  {name}: {why}")
        for i, s in enumerate(self.steps, 1):
            ext = s["evidence"]["extension"]
            lines.append(f"step {i}: {s['effect']} -- {ext['extension']}; held-out RMS "
                         f"{s['rms_before']:.4g} -> {s['rms_after']:.4g} "
                         f"({100 * (1 - s['rms_after'] / s['rms_before']):.1f} % smaller)")
            lines.append(f"  evidence: {s['evidence']['signature']['reading']}")
        if not self.effects:
            lines.append("effects: none -- " + self.stopped)
        else:
            lines.append(f"effects: {', '.join(self.effects)}; held-out RMS {self.rms_before:.4g} -> "
                         f"{self.rms_after:.4g}; stopped: {self.stopped}")
        return "\n".join(lines)

    def __repr__(self):
        return (f"Diagnosis(effects={self.effects}, rms_before={self.rms_before:.4g}, "
                f"rms_after={self.rms_after:.4g})")

    # -- figures
    def plots(self):
        """Figures: ``signatures`` (base residual against each effect's
        signature), ``loops`` (held-out loops before and after), ``gap``
        (held-out RMS per step).  Returns {name: Figure}."""
        from .plotting import new_figure

        d = self._data
        e = d.y - self._base_pred
        idx = np.linspace(0, d.n - 1, min(d.n, 6000)).astype(int)
        fig, ax = new_figure(2, 3, size=(13, 7.5))
        ax = ax.ravel()
        ax[0].plot(d.rate[idx], e[idx], ".", ms=2)
        ax[0].set(xlabel="input rate dv/dt", ylabel="residual", title="rate_dependence")
        hc = _hold_changes(d, e)
        if hc.size:
            ax[1].plot(hc[:, 0], hc[:, 1], "o")
        else:
            ax[1].text(0.5, 0.5, "no holds: untested", ha="center", transform=ax[1].transAxes)
        ax[1].set(xlabel="hold level - mean input of the 2 s before", ylabel="residual change during hold",
                  title="creep")
        ax[2].plot(d.t[idx], e[idx], ".", ms=2, label="residual")
        seg = max(1, d.n // 50)
        nb = d.n // seg
        ax[2].plot(d.t[:nb * seg].reshape(nb, seg).mean(1), e[:nb * seg].reshape(nb, seg).mean(1), "r-",
                   label="block mean")
        for k, j, _ in d.holds:
            ax[2].axvspan(d.t[k], d.t[j - 1], color="0.85", zorder=0)
        ax[2].axvline(self.validation[0], color="k", ls="--")
        ax[2].set(xlabel="time [s] (grey: holds, dashed: held-out from)", ylabel="residual", title="drift")
        ax[2].legend(fontsize=8)
        up = d.rate[idx] > 0
        ax[3].plot(d.v[idx][up], e[idx][up], ".", ms=2, label="rising")
        ax[3].plot(d.v[idx][~up], e[idx][~up], ".", ms=2, label="falling")
        ax[3].set(xlabel="input v", ylabel="residual", title="asymmetry")
        ax[3].legend(fontsize=8)
        bins = np.linspace(-d.V, d.V, 25)
        cen = 0.5 * (bins[1:] + bins[:-1])
        which = np.clip(np.digitize(d.v, bins) - 1, 0, 23)
        cnt = np.bincount(which, minlength=24)
        mean = np.bincount(which, e, minlength=24) / np.maximum(cnt, 1)
        ax[4].plot(cen[cnt > 0], mean[cnt > 0], "o-")
        ax[4].axhline(0, color="k", lw=0.5)
        ax[4].set(xlabel="input v", ylabel="mean residual", title="saturation (odd bend = gain change)")
        ev = self.first_evidence
        txt = "\n".join(f"{k}: {v['reading']}" for k, v in ev.items())
        ax[5].axis("off")
        ax[5].text(0, 1, "\n".join(_wrap(line, 48) for line in txt.split("\n")), va="top", fontsize=8)
        fig.suptitle("Residual of the base PI model against each effect's signature")
        out = {"signatures": fig}

        fig, ax = new_figure(1, 3, size=(16, 5))
        val = ~d.train
        final = self.model.simulate(d.v)
        for a, pred, name in ((ax[0], self._base_pred, "base PI"), (ax[1], final, "final model")):
            a.plot(d.v[val], d.y[val], "-", color="0.6", lw=1, label="measured")
            a.plot(d.v[val], pred[val], "-", lw=1, label=name)
            rms = float(np.sqrt(np.mean((d.y - pred)[val] ** 2)))
            a.set(xlabel="input v", ylabel="output y", title=f"held-out loops, {name}: RMS {rms:.3g}")
            a.legend(fontsize=8)
            ax[2].plot(d.t[val], (d.y - pred)[val], lw=0.8, label=f"{name}: RMS {rms:.3g}")
        ax[2].set(xlabel="time [s]", ylabel="measured - model", title="held-out residual in time")
        ax[2].legend(fontsize=8)
        fig.suptitle("Loops on the held-out part: " + (" + ".join(["PI"] + list(self.effects))))
        out["loops"] = fig

        fig, ax = new_figure(1, 1, size=(7, 4.5))
        labels = ["base PI"] + [f"+ {s['effect']}" for s in self.steps]
        vals = [self.rms_before] + [s["rms_after"] for s in self.steps]
        ax.bar(range(len(vals)), vals, color=["0.6"] + ["C0"] * len(self.steps))
        ax.set_xticks(range(len(vals)), labels, rotation=15)
        for i, val in enumerate(vals):
            ax.text(i, val, f"{val:.3g}", ha="center", va="bottom")
        ax.set(ylabel="held-out RMS", title="Gap per step\n" + _wrap("stopped: " + self.stopped, 80))
        ax.title.set_fontsize(9)
        out["gap"] = fig
        return out

    def save_plots(self, folder):
        """Write the figures of :meth:`plots` as PNG files; returns their paths.

        Parameters
        ----------
        folder : str or path-like
            Directory for ``diagnose_signatures.png``, ``diagnose_loops.png``
            and ``diagnose_gap.png`` (created if missing).

        Returns
        -------
        list of str
            The paths written.
        """
        os.makedirs(folder, exist_ok=True)
        paths = []
        for name, fig in self.plots().items():
            p = os.path.join(folder, f"diagnose_{name}.png")
            fig.savefig(p, dpi=90)
            paths.append(p)
        return paths


def _wrap(s, n):
    import textwrap
    return textwrap.fill(s, n)


def _jsonable(x):
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, (np.floating, float)):
        return float(x) if math.isfinite(x) else None
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, np.ndarray):
        return _jsonable(x.tolist())
    return x


# ----------------------------------------------------------------------------
# the workflow
# ----------------------------------------------------------------------------
def diagnose(t, v, y, base="pi", effects=ALL, validation=0.3, max_effects=3, min_gain=0.1,
             progress=True, n_thresholds=20):
    """Name the effects a hysteresis model lacks, add them, and show the gap shrink.

    Parameters
    ----------
    t, v, y : array_like, shape (n,)
        Time [s] (increasing, uniformly sampled), input and measured output.
    base : "pi" or PI
        The base model: a plain PI model (eq. 18) with `n_thresholds`
        thresholds equally spaced in (0, span/2), or a :class:`~hystcomp.models.PI`
        whose thresholds are used (its weights are refitted).
    effects : sequence of str
        Candidates among ``rate_dependence``, ``creep``, ``drift``, ``asymmetry``,
        ``saturation`` (default all).
    validation : float
        Fraction of the record held out at its end.
    max_effects : int
        At most this many effects are added.
    min_gain : float
        An effect is added only when it shrinks the held-out RMS by at least
        this fraction (and lowers the training BIC).
    progress : bool
        Progress lines on stderr.
    n_thresholds : int
        Number of thresholds of the default base model (``base="pi"``).

    Returns
    -------
    Diagnosis

    Examples
    --------
    >>> from hystcomp.datasets import hidden_effect_data
    >>> d = hidden_effect_data("drift", seed=3, dt=0.01)
    >>> rep = diagnose(d.t, d.v, d.y, progress=False)
    >>> rep.effects[0], rep.rms_after < 0.5 * rep.rms_before
    ('drift', True)
    """
    data = _Data(t, v, y, validation)
    effects = list(effects)
    for e in effects:
        check_choice(e, "effects", EFFECTS)
    max_effects = int(max_effects)
    if max_effects < 0:
        raise ValueError(f"Parameter max_effects is {max_effects} but should be >= 0")
    min_gain = as_scalar(min_gain, "min_gain", nonnegative=True)
    if isinstance(base, PI):
        r = base.thresholds
    elif base == "pi":
        r = _base_thresholds(data, int(n_thresholds))
    else:
        raise ValueError(f"Parameter base is {base!r} but should be 'pi' or a PI model")
    say = (lambda s: print("diagnose: " + s, file=sys.stderr, flush=True)) if progress else (lambda s: None)
    t0 = time.perf_counter()
    # base: the plain PI of hystcomp.identify (constrained least squares, held-out tail)
    from .identify import fit_weights

    mask = ~data.train
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        base_fit = fit_weights(data.v, data.y, thresholds=r, model="pi", validation=mask)
    base_pred = base_fit.predict(data.v)
    st = _Structure(data, r)
    cur = st.fit()
    cur_pred = base_pred
    rms0 = float(base_fit.validation["rms"])
    # the structure's own fit is the same convex problem; keep the better of the two
    if cur.rms_train > base_fit.rmse * (1 + 1e-6):
        warnings.warn("the bounded least-squares base fit is worse than fit_weights's", RuntimeWarning)
    cur.rms_val = rms0
    say(f"base PI ({r.size} thresholds) held-out RMS {rms0:.4g}  [{time.perf_counter() - t0:.1f} s]")
    first_ev = _evidence(data, data.y - base_pred)
    untested = {k: v["reading"] for k, v in first_ev.items() if not v["testable"] and k in effects}
    for k, why in untested.items():
        say(f"{k}: {why}")
    remaining = [e for e in effects if e not in untested]
    steps, chosen = [], []
    stopped = "no candidate effects to try"
    while remaining and len(chosen) < max_effects:
        ev = _evidence(data, data.y - cur_pred)
        trials = {}
        for j, eff in enumerate(remaining):
            ft, why = _candidate(eff, cur)
            if ft is not None:
                trials[eff] = ft
            say(f"step {len(chosen) + 1}: {eff:16s} ({j + 1}/{len(remaining)}) held-out RMS "
                + (f"{ft.rms_val:.4g}" if ft is not None else f"-- {why}")
                + f"  [{time.perf_counter() - t0:.1f} s]")
        if not trials:
            stopped = "no extension left to try"
            break
        eff = min(trials, key=lambda k: trials[k].rms_val)
        ft = trials[eff]
        gain = 1.0 - ft.rms_val / cur.rms_val
        if ft.bic >= cur.bic or gain < min_gain:
            stopped = (f"none of the remaining effects pays: the best, {eff}, shrinks the held-out RMS "
                       f"by {100 * gain:.1f} % (needs {100 * min_gain:.0f} %) and changes the BIC by "
                       f"{ft.bic - cur.bic:+.1f}")
            say(stopped)
            break
        struct = ft.structure.replace(effects=cur.structure.effects + (eff,))
        step_ev = {"signature": ev[eff], "extension": _describe(eff, struct),
                   "held_out_gain": round(gain, 4), "bic_change": round(ft.bic - cur.bic, 1),
                   "candidates": {k: f.rms_val for k, f in trials.items()}}
        steps.append({"effect": eff, "rms_before": cur.rms_val, "rms_after": ft.rms_val, "evidence": step_ev})
        chosen.append(eff)
        say(f"added {eff}: held-out RMS {cur.rms_val:.4g} -> {ft.rms_val:.4g}")
        ft.structure = struct
        cur = ft
        cur_pred = ft.pred
        remaining.remove(eff)
    else:
        if len(chosen) >= max_effects and remaining:
            stopped = f"max_effects = {max_effects} reached"
        elif not remaining and chosen:
            stopped = "every candidate effect was added"
    if steps:
        final = cur.structure.model(cur.theta, cur.groups)
    else:
        final = Parallel(base_fit.model, offset=base_fit.offset)
    rep = Diagnosis(effects=chosen, steps=steps, rms_before=rms0,
                    rms_after=steps[-1]["rms_after"] if steps else rms0,
                    validation=(float(data.t[data.k_val]), float(data.t[-1])), model=final,
                    base_model=Parallel(base_fit.model, offset=base_fit.offset), untested=untested,
                    stopped=stopped, first_evidence=first_ev, elapsed=time.perf_counter() - t0,
                    _data=data, _base_pred=base_pred, _r=r)
    say(f"done in {rep.elapsed:.1f} s: effects {chosen or 'none'}")
    return rep


# ----------------------------------------------------------------------------
# command line: ``hystcomp diagnose DATA.csv``
# ----------------------------------------------------------------------------
def load_csv(path, time="t", input="v", output="y"):
    """(t, v, y) from a CSV file with a header row; ValueError with a one-line
    reason for missing columns, non-numeric cells, NaN, unsorted time or too
    few samples.

    Parameters
    ----------
    path : str or path-like
        The CSV file (comma separated, a header row, at least 100 samples).
    time, input, output : str
        Header names of the time [s], input and output columns.

    Returns
    -------
    t, v, y : ndarray
        The three columns, time strictly increasing.

    Raises
    ------
    ValueError
        With a one-line reason naming the file (and line) at fault.

    Examples
    --------
    >>> import os, tempfile
    >>> folder = tempfile.mkdtemp()
    >>> path = os.path.join(folder, "record.csv")
    >>> k = np.arange(100)
    >>> np.savetxt(path, np.column_stack([0.01 * k, k % 7, k % 5]), delimiter=",",
    ...            header="time,volt,um", comments="")
    >>> t, v, y = load_csv(path, time="time", input="volt", output="um")
    >>> t.size, float(v[8]), float(y[8])
    (100, 1.0, 3.0)
    >>> load_csv(path)
    Traceback (most recent call last):
    ...
    ValueError: ... has no column 't' (header: time, volt, um)
    >>> import shutil
    >>> shutil.rmtree(folder)
    """
    import csv

    try:
        with open(path, newline="") as fh:
            rows = list(csv.reader(fh))
    except OSError as exc:
        raise ValueError(f"cannot read {path}: {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise ValueError(f"{path} is not a text CSV file") from None
    if not rows:
        raise ValueError(f"{path} is empty; expected a header row with columns {time}, {input}, {output}")
    header = [h.strip() for h in rows[0]]
    cols = {}
    for name in (time, input, output):
        if name not in header:
            raise ValueError(f"{path} has no column {name!r} (header: {', '.join(header)})")
        cols[name] = header.index(name)
    body = [r for r in rows[1:] if any(c.strip() for c in r)]
    out = {name: np.empty(len(body)) for name in cols}
    for i, row in enumerate(body, start=2):
        for name, j in cols.items():
            try:
                val = float(row[j])
            except (IndexError, ValueError):
                cell = row[j] if j < len(row) else ""
                raise ValueError(f"{path} line {i}: column {name!r} holds {cell!r}, not a number") from None
            if not math.isfinite(val):
                raise ValueError(f"{path} line {i}: column {name!r} holds {val}; expected a finite number")
            out[name][i - 2] = val
    if len(body) < 100:
        raise ValueError(f"{path} has {len(body)} samples; diagnose needs at least 100")
    t = out[time]
    d = np.diff(t)
    if np.any(d <= 0):
        k = int(np.argmax(d <= 0))
        raise ValueError(f"{path} line {k + 3}: time {t[k + 1]} does not increase (previous {t[k]})")
    return t, out[input], out[output]


def add_arguments(parser):
    """Add the ``diagnose`` arguments to an argparse parser (sub-parser).

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The parser (or sub-parser) to extend.

    Returns
    -------
    argparse.ArgumentParser
        The same parser.

    Examples
    --------
    >>> import argparse
    >>> args = add_arguments(argparse.ArgumentParser()).parse_args(["data.csv", "--max-effects", "1"])
    >>> args.data, args.max_effects, args.validation
    ('data.csv', 1, 0.3)
    """
    parser.add_argument("data", metavar="DATA.csv", help="CSV file with a header row")
    parser.add_argument("--time", default="t", help="time column [s] (default t)")
    parser.add_argument("--input", default="v", help="input column (default v)")
    parser.add_argument("--output", default="y", help="measured output column (default y)")
    parser.add_argument("--json", action="store_true", help="print one JSON object to stdout")
    parser.add_argument("--plots", metavar="DIR", help="write the diagnosis figures (PNG) into DIR")
    parser.add_argument("--validation", type=float, default=0.3, help="held-out fraction (default 0.3)")
    parser.add_argument("--max-effects", type=int, default=3, help="at most this many effects (default 3)")
    parser.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    return parser


def run(args):
    """Run ``hystcomp diagnose`` for parsed `args`; returns the exit status
    (0 success, 2 bad data file).

    Parameters
    ----------
    args : argparse.Namespace
        Arguments parsed by a parser built with :func:`add_arguments`.

    Returns
    -------
    int
        Exit status: 0 on success (the report or JSON printed to stdout), 2
        when the data file cannot be used (a one-line error on stderr).

    Examples
    --------
    >>> import argparse
    >>> args = add_arguments(argparse.ArgumentParser()).parse_args(["no-such-file.csv", "--quiet"])
    >>> run(args)   # prints "hystcomp diagnose: error: cannot read no-such-file.csv: ..." on stderr
    2
    """
    try:
        t, v, y = load_csv(args.data, args.time, args.input, args.output)
        rep = diagnose(t, v, y, validation=args.validation, max_effects=args.max_effects,
                       progress=not args.quiet)
    except ValueError as exc:
        msg = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        print(f"hystcomp diagnose: error: {msg}", file=sys.stderr)
        return 2
    if args.plots:
        import matplotlib

        matplotlib.use("Agg")
        for p in rep.save_plots(args.plots):
            print(f"wrote {p}", file=sys.stderr)
    if args.json:
        print(rep.to_json())
    else:
        print(rep.summary())
    return 0


def main(argv=None):
    """``python -m hystcomp.diagnose DATA.csv ...`` (the same as ``hystcomp diagnose``)."""
    parser = add_arguments(argparse.ArgumentParser(prog="hystcomp diagnose",
                                                   description="name the effects a PI model lacks"))
    return run(parser.parse_args(argv))


if __name__ == "__main__":
    sys.exit(main())
