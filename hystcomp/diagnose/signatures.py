"""Signature tests: where each effect leaves its mark in a model's residual.

Every test returns its statistic in units of the noise floor ``sigma`` and
the threshold it is compared with.  Most are a *partial RMS*: the residual
is regressed on nuisance columns (static functions of the input on each
branch, so that an ordinary misfit of the hysteresis does not count) and
then on nuisance plus the signature's columns; the statistic is
``sqrt((RSS_nuisance - RSS_both) / n) / sigma``, the RMS of the structure the
signature's columns explain beyond the nuisance.  Thresholds are fractions
of the noise floor (a structure of 0.5 sigma RMS is what a human still
sees in a residual plot of a few thousand samples).
"""

import math

import numpy as np

from .record import TURN_BACK

#: partial-RMS threshold (fraction of the noise floor) of the regression signatures
PARTIAL = 0.5
#: the delay's test reads the samples where the model's output moves faster than this
#: share of its fastest rate
MOVING = 0.02
#: excess RMS at the record's start (fraction of the noise floor) for initial_state
START = 0.5
#: samples running into a flat extreme that the output-saturation test needs
CLIP_SAMPLES = 20
#: ... where the residual exceeds the noise by more than this many noise floors
#: (RMS in quadrature): a smooth saturation fitted with a dead time leaves
#: 1.4-1.7 there (two realistic pairs), a clip the model lacks 5 or more
CLIP_EXCESS = 2.0
#: a drift's trend that changes with the input level may be at most this
#: multiple of the trend common to every level (partial RMS of each)
LEVEL_TREND = 1.0
#: lag-1 autocorrelation above which a final residual is not taken for white noise
WHITE = 0.6

WHERE = {"rate_dependence": "against rate", "delay": "against rate", "creep": "in time (during holds)",
         "drift": "in time", "gain_drift": "in time", "asymmetry": "against input",
         "saturation": "against input", "output_saturation": "against output",
         "initial_state": "at the record's start"}


#: one-sided level of 2.5 standard errors of a normal distribution
_LEVEL_25 = 0.5 * (1.0 + math.erf(2.5 / math.sqrt(2.0)))


def _t_quantile(dof):
    """Student-t quantile at the level of 2.5 normal standard errors (2.5 as
    dof -> inf; 3.8 for 5 degrees of freedom, 51 for one)."""
    from scipy.stats import t

    return float(t.ppf(_LEVEL_25, dof))


def _rss_gram(G, b, ee, rcond=1e-13):
    """Residual sum of squares of the least-squares fit whose Gram matrix is
    `G`, right-hand side `b` and ``e @ e`` `ee` (columns equilibrated;
    eigenvalues below ``rcond * m * max`` dropped, so a rank-deficient set
    of columns counts once)."""
    if G.size == 0:                      # no columns: nothing is explained
        return max(ee, 0.0)
    d = np.sqrt(np.maximum(np.diag(G), 0.0))
    d[d == 0] = 1.0
    lam, U = np.linalg.eigh(G / np.outer(d, d))
    keep = lam > max(float(lam.max()), 0.0) * lam.size * rcond
    z = U[:, keep].T @ (b / d)
    return max(ee - float(z @ (z / lam[keep])), 0.0)


def _gram(N, F):
    """The Gram matrix of ``[N, F]``, by blocks (without stacking the columns)."""
    k = N.shape[1]
    m = k + F.shape[1]
    G = np.empty((m, m))
    G[:k, :k] = N.T @ N
    G[:k, k:] = N.T @ F
    G[k:, :k] = G[:k, k:].T
    G[k:, k:] = F.T @ F
    return G


def _partial(e, N, F, G=None):
    """RMS of what the columns F explain of e beyond the columns N.

    One Gram matrix of ``[N, F]`` (`G` when known: :func:`_fixed`) serves
    both fits: 40,000 rows cost a few ms, where an SVD per fit
    (``numpy.linalg.lstsq``) cost 12 ms each."""
    n = e.size
    F = F.reshape(n, -1)
    k = N.shape[1]
    G = _gram(N, F) if G is None else G
    b = np.concatenate([N.T @ e, F.T @ e])
    ee = float(e @ e)
    return math.sqrt(max(_rss_gram(G[:k, :k], b[:k], ee) - _rss_gram(G, b, ee), 0.0) / n)


def _fixed(rec, key, build):
    """Columns ``(N, F)`` that depend on the record alone, with their Gram
    matrix: built by ``build()`` at the first call for `key` and kept in
    ``rec.signature_memo`` (every step's evidence tests new residuals
    against the same columns; the same floats as building them afresh)."""
    hit = rec.signature_memo.get(key)
    if hit is None:
        N, F = build()
        F = F.reshape(N.shape[0], -1)
        hit = rec.signature_memo[key] = (N, F, _gram(N, F))
    return hit


def _partial_fixed(e, rec, key, build):
    """:func:`_partial` of the record's columns ``build() -> (N, F)`` (kept: :func:`_fixed`)."""
    N, F, G = _fixed(rec, key, build)
    return _partial(e, N, F, G)


def _level_split(e, N, F, by_level):
    """Partial RMS of the trend columns F beyond N (common to every input
    level), and of the level-dependent columns `by_level` beyond N and F."""
    NF = np.column_stack([N, F])
    return _partial(e, N, F), _partial(e, NF, np.column_stack(by_level))


def _level_split_fixed(e, rec, key, N, trend, by_level):
    """:func:`_level_split` of columns of the record alone, built by the
    callables ``trend()`` and ``by_level()`` (a list) at their first use and
    kept with their Gram matrices (:func:`_fixed`, under `key`)."""
    common = _partial_fixed(e, rec, key + ("common",), lambda: (N, trend()))
    Nc, Fc, _ = rec.signature_memo[key + ("common",)]
    return common, _partial_fixed(e, rec, key + ("by_level",),
                                  lambda: (np.column_stack([Nc, Fc]), np.column_stack(by_level())))


def _level_verdict(common, by_level, sigma, what, how, effect):
    """The keywords of a trend signature's :func:`evidence` entry: present
    only when the level-dependent part is at most LEVEL_TREND times the
    common one, and a reading that says why when it is not."""
    ok = by_level <= LEVEL_TREND * common
    reading = "" if ok or common <= PARTIAL * sigma else (
        f"absent: {what} ({common / sigma:.2f} noise floors) is mostly one that changes with the input "
        f"level{how} ({by_level / sigma:.2f}): a misfit of the loop under an excitation that changes in "
        f"time, not {effect}")
    return {"also": ok, "level_dependent_trend": round(by_level / sigma, 4), "reading": reading}


#: full cycles of the smooth trend in time (cosines) beyond which the drift's
#: level test reads a trend that changes with the input level (0: beyond t and
#: t^2 alone, as before round 58)
SLOW_CYCLES = 4
#: ... and the most the level's trends may explain beyond those cosines, as a
#: multiple of the trend common to every level (round 58: the drifts that rise
#: and fall on HOLDOUT50-52 left 0.11-0.39; asymmetries and a clean Dahl core
#: that a drift would have been named on, 0.77-0.98)
SLOW_LEVEL_TREND = 0.5


def _slow_time(n):
    """Cosines of 1 ... 2 :data:`SLOW_CYCLES` half cycles over the record's
    samples (a smooth trend in time of up to that many cycles).

    Examples
    --------
    >>> _slow_time(5).shape, _slow_time(5)[[0, -1], 0].tolist()
    ((5, 8), [1.0, -1.0])
    """
    tn = np.arange(n) / max(n - 1, 1)
    return np.column_stack([np.cos(np.pi * k * tn) for k in range(1, 2 * SLOW_CYCLES + 1)])


def _static_nuisance(rec, bins=12):
    """Piecewise-linear functions of the input (hat functions on `bins`
    knots), separately on rising and falling branches, and a constant."""
    u = (rec.v - rec.vmin) / rec.span
    knots = np.linspace(0.0, 1.0, bins)
    h = knots[1] - knots[0]
    H = np.maximum(0.0, 1.0 - np.abs(u[:, None] - knots[None, :]) / h)
    up = (rec.direction >= 0)[:, None]
    return np.column_stack([H * up, H * ~up])


#: a drive whose power lies this much within a factor 1.5 of one frequency
#: excites one rate only: rate dependence is untested there (a lag shifts the
#: phase as a dead time does), and a delay named on it is a near tie of a
#: rate dependence (:func:`one_rate_tie`)
ONE_RATE = 0.9


def one_rate_tie(rec, named, untested, ambiguous):
    """`ambiguous` with a rate dependence added as a near tie of a named
    delay when the record's drive excites one rate only (:data:`ONE_RATE`)
    and rate dependence, a candidate, was `untested` for it: no part of it
    was fitted to tie with the delay, and the report's untested line already
    says that a delay named here may be a lag.  Round 37: HOLDOUT35's voltage-driven coil,
    whose back-EMF lags the travel (4-8 ms), was named a delay at all three
    seeds of a drive with 95-98 % of its power at one frequency.

    Examples
    --------
    >>> class R: dt, peak_share = 1e-3, 0.95
    >>> why = {"rate_dependence": "untested: at one rate of excitation ..."}
    >>> one_rate_tie(R, ["delay"], why, {})
    {'delay': ['rate_dependence']}
    >>> one_rate_tie(R, ["delay"], {}, {})          # rate dependence was not a candidate
    {}
    >>> R.peak_share = 0.5
    >>> one_rate_tie(R, ["delay"], why, {})
    {}
    """
    if (rec.dt is None or rec.peak_share < ONE_RATE or "delay" not in named or "rate_dependence" not in untested
            or "rate_dependence" in named or "rate_dependence" in ambiguous.get("delay", [])):
        return ambiguous
    out = {k: list(v) for k, v in ambiguous.items()}
    out.setdefault("delay", []).append("rate_dependence")
    return out


#: windows over the record of the local frequency (:func:`_local_frequency`)
FREQUENCY_WINDOWS = 10


def _moving_mean(x, m):
    """Mean over a centred window of `m` samples (edges: the window shrinks)."""
    c = np.concatenate([[0.0], np.cumsum(x)])
    k = np.arange(x.size)
    lo, hi = np.maximum(k - m // 2, 0), np.minimum(k + m // 2 + 1, x.size)
    return (c[hi] - c[lo]) / (hi - lo)


def _local_frequency(rec):
    """The excitation's local angular frequency, standardised (mean 0,
    standard deviation 1; zeros when it does not change): over windows of
    1/:data:`FREQUENCY_WINDOWS` of the record, the input rate's RMS over the
    RMS of the input's excursion about its window mean (2 pi f for a sine of
    frequency f), clipped to its 2nd and 98th percentiles.  A loop whose
    gain changes with frequency (a lag, a rate-dependent stage) under a
    chirp changes its gain in time along it, not with the clock."""
    m = max(rec.n // FREQUENCY_WINDOWS, 3)
    dv = rec.v - _moving_mean(rec.v, m)
    f = np.sqrt(_moving_mean(rec.rate ** 2, m) / np.maximum(_moving_mean(dv ** 2, m), 1e-300))
    f = np.clip(f, *np.percentile(f, [2.0, 98.0]))
    sd = float(np.std(f))
    return (f - f.mean()) / sd if sd > 1e-12 * max(float(np.abs(f).max()), 1e-300) else np.zeros(rec.n)


def lag1_autocorrelation(e):
    """Lag-1 autocorrelation of a residual about its mean (0 for a constant
    one): above :data:`WHITE` it is not taken for white noise.

    Examples
    --------
    >>> round(lag1_autocorrelation(np.sin(np.linspace(0, 6, 200))), 2)
    1.0
    >>> lag1_autocorrelation(np.ones(5))
    0.0
    """
    e = np.asarray(e, dtype=np.float64)
    e = e - e.mean()
    ee = float(e @ e)
    return float(e[1:] @ e[:-1] / ee) if ee > 0 else 0.0


def evidence(rec, e, pred, sigma, only=None):
    """Every effect's signature test on the residual `e` (all samples).

    Parameters
    ----------
    rec : Record
        The record.
    e : ndarray
        Measured minus model output.
    pred : ndarray
        The model's prediction.
    sigma : float
        Noise floor.
    only : str, optional
        Compute this effect's test only (the others are skipped).

    Returns
    -------
    dict
        effect -> {signature, statistic, threshold, present, testable,
        where, reading}.
    """
    ev = {}
    n = rec.n
    one = np.ones((n, 1))
    N = rec.signature_memo.get("nuisance")
    if N is None:
        N = rec.signature_memo["nuisance"] = _static_nuisance(rec)
    timed = rec.dt is not None
    c = 0.5 * (rec.vmin + rec.vmax)
    xc = (rec.v - c) / (0.5 * rec.span)

    def put(name, signature, stat, thr, testable=True, reading="", also=True, **extra):
        stat = float(stat)
        present = bool(testable and stat > thr and also)
        ev[name] = {"signature": signature, "statistic": round(stat, 4), "threshold": thr,
                    "present": present, "testable": bool(testable), "where": WHERE[name],
                    "reading": reading or (("present: " if present else "absent: ") + signature), **extra}

    # a dead time and a lag leave the same residual to first order (-T dH/dv dv/dt):
    # each of the two tests is computed with the other, and reads it (below)
    pair = only is None or only in ("rate_dependence", "delay")
    if pair:
        # -- rate dependence: residual against the input rate beyond static branch functions
        sig = "residual against the input rate |dv/dt| beyond static functions of the input on each branch"
        if not timed:
            put("rate_dependence", sig, 0.0, PARTIAL, False, "untested: the record has no time axis")
        elif rec.peak_share >= ONE_RATE:
            put("rate_dependence", sig, 0.0, PARTIAL, False,
                f"untested: {100 * rec.peak_share:.0f} % of the input's power lies within a factor 1.5 of "
                f"{rec.f_peak:.3g} Hz; at one rate of excitation rate dependence cannot be told from the loop's "
                "shape, and a lag shifts the phase as a dead time does, so a delay named here may be a lag "
                "(add sines at other frequencies)")
        else:
            def rate_columns():
                r = rec.rate / (np.max(np.abs(rec.rate)) or 1.0)
                return N, np.column_stack([r, r * np.abs(r), np.gradient(r)])

            put("rate_dependence", sig, _partial_fixed(e, rec, ("rate",), rate_columns) / sigma, PARTIAL)

    if pair:
        # -- delay: residual along the derivative of the prediction
        sig = "residual along the model output's time derivative (a shift in time), where the output moves"
        if not timed:
            put("delay", sig, 0.0, PARTIAL, False, "untested: the record has no time axis")
        else:
            dp = np.gradient(pred)
            dp = dp / (np.max(np.abs(dp)) or 1.0)
            lag = _xcorr_lag(e, dp, max_lag=max(3, min(200, n // 50)))
            # a dead time moves the output only while it moves: the partial RMS over those
            # samples (|d pred| above MOVING of its peak), not diluted by the holds of a
            # record of moves and holds (min-jerk moves 8 % of the time: measured 0.16-0.35
            # noise floors over the record, 1.0-1.7 over the moves)
            mv = np.abs(dp) > MOVING
            if mv.sum() < 10:
                mv = np.ones(n, dtype=bool)
            put("delay", sig, _partial(e[mv], N[mv], dp[mv, None]) / sigma, PARTIAL, lag_samples=lag,
                moving_share=round(float(mv.mean()), 4))

    if only is None or only in ('creep',):
        # -- creep: relaxation during holds in the direction of the step into them
        sig = "residual change during each hold against the step into it (either direction)"
        moved = [(k, j, s) for k, j, s in _merged_holds(rec) if abs(s) > 0.02 * rec.span]
        n_up = sum(1 for _, _, s in moved if s > 0)
        n_dn = sum(1 for _, _, s in moved if s < 0)
        if not timed:
            put("creep", sig, 0.0, 0.3, False, "untested: the record has no time axis")
        elif n_up < 1 or n_dn < 1 or len(moved) < 3:
            put("creep", sig, 0.0, 0.3, False,
                "untested: the input is held still after steps in both directions too rarely "
                "(need at least 3 holds, after up and down steps)", holds=len(moved))
        else:
            rows = []
            for k, j, s in moved:
                m = max(2, (j - k) // 5)
                rows.append((math.copysign(1.0, s), float(e[j - m:j].mean() - e[k:k + m].mean()), (j - k) * rec.dt))
            R = np.array(rows)
            # linear creep (Kelvin-Voigt chains, logarithmic creep superposed step by
            # step) relaxes in proportion to the step into the hold: the regressor is
            # the signed step in units of the mean step (coefficient: the relaxation
            # after a mean-sized step), and the hold's length
            steps = np.array([s for _, _, s in moved])
            X = np.column_stack([steps / np.abs(steps).mean(), R[:, 2] / R[:, 2].mean()])
            coef, *_ = np.linalg.lstsq(X, R[:, 1], rcond=None)
            res = R[:, 1] - X @ coef
            dof = max(R.shape[0] - 2, 1)
            se = math.sqrt(float(res @ res) / dof / R.shape[0]) if R.shape[0] > 2 else abs(coef[0])
            # the relaxation (in either direction: creep on, or relaxing back) must
            # exceed 0.3 noise floors and the Student-t quantile of 2.5 standard
            # errors for the holds' degrees of freedom (2.5 for many holds; 3 holds
            # give one degree of freedom, and their standard error says little)
            stat = abs(float(coef[0])) / sigma
            thr = max(0.3, _t_quantile(dof) * se / sigma)
            # signed, in noise floors: > 0 on with the step (creep), < 0 back against it
            put("creep", sig, stat, round(thr, 4), holds=len(moved),
                relaxation_per_step=round(float(coef[0]) / sigma, 4))

    if only is None or only in ('drift', 'gain_drift'):
        # -- drift / gain drift: slow trend in time beyond static functions of the input
        sig = ("residual's slow trend in time (t, t^2) beyond static functions of the input, common to every "
               "input level")
        sig_g = ("residual along t times the model output (a gain changing in time) beyond the output times the "
                 "excitation's local frequency, not mostly a trend of other input functions")
        if not timed:
            put("drift", sig, 0.0, PARTIAL, False, "untested: the record has no time axis")
            put("gain_drift", sig_g, 0.0, PARTIAL, False, "untested: the record has no time axis")
        else:
            tn = np.arange(n) / (n - 1) - 0.5
            T = np.column_stack([tn, tn ** 2 - 1.0 / 12.0])
            # a drift is the same at every input level: the trend must not be
            # mostly one that changes with the input (t and t^2 times v, v^2, the
            # branch and branch x v), as a misfit of the loop does under an
            # excitation whose amplitude changes in time
            d = rec.direction

            def level_trends():
                return [T * xc[:, None], T * (xc ** 2)[:, None], T * d[:, None], T * (d * xc)[:, None]]

            common, by_level = _level_split_fixed(e, rec, ("drift",), N, lambda: T, level_trends)
            if SLOW_CYCLES and by_level > LEVEL_TREND * common:
                # ... judged beyond a smooth trend in time as well (cosines of up to
                # SLOW_CYCLES cycles): a drift that rises and falls (a chiller's
                # dead band, a valve's stiction cycles) leaves, beyond t and t^2,
                # a wave that the level's trends pick up where the input's level
                # changes slowly (rests and sets), and would read as one that
                # changes with the level (round 58: tests/test_diagnose_level_trend.py).
                # The cosines take some of any slow misfit, so the level's share
                # left beyond them must be at most SLOW_LEVEL_TREND of the trend
                slow = _partial_fixed(e, rec, ("drift", "slow"), lambda: (
                    np.column_stack([N, T, _slow_time(n)]), np.column_stack(level_trends())))
                if slow <= SLOW_LEVEL_TREND * common:
                    by_level = slow
            put("drift", sig, common / sigma, PARTIAL, **_level_verdict(
                common, by_level, sigma, "the slow trend", "", "a drift"))
            pc = (pred - pred.mean()) / (np.std(pred) or 1.0)
            # likewise a gain drift scales the whole output: beyond t times the
            # output, the trend must not be mostly one of the other input levels'
            # functions (t and t^2 times v^2, the branch and branch x v); and a
            # gain that changes with the excitation's frequency (the output times
            # the local frequency and its square) is a nuisance: under a chirp it
            # changes along the record as a gain drift would
            fq = _local_frequency(rec)
            NG = np.column_stack([N, T, pc * fq, pc * (fq ** 2 - 1.0)])
            along, by_level_g = _level_split(e, NG, (tn * pc)[:, None],
                                             [T * (xc ** 2)[:, None], T * d[:, None], T * (d * xc)[:, None]])
            put("gain_drift", sig_g, along / sigma, PARTIAL, **_level_verdict(
                along, by_level_g, sigma, "the gain's trend", " in other ways", "a gain drift"))

    if only is None or only in ('asymmetry', 'saturation'):
        # -- asymmetry and saturation: even and odd bends against the input
        s = rec.direction
        N1 = np.column_stack([one, xc])
        # a point-symmetric loop (what a PI model draws) leaves residuals odd under
        # (v, dv/dt) -> (-v, -dv/dt); asymmetry leaves an even part
        put("asymmetry", "residual against functions of the input even under (v, dv/dt) -> (-v, -dv/dt) "
            "(v^2, sign(dv/dt) v^2, |v|, sign(dv/dt) v)",
            _partial_fixed(e, rec, ("asymmetry",), lambda: (
                N1, np.column_stack([xc ** 2, s * xc ** 2, np.abs(xc), s * xc]))) / sigma, PARTIAL)
        sig = "residual against odd bends of the input (v^3, v^5): a gain change at the extremes"
        stat = _partial_fixed(e, rec, ("saturation",), lambda: (N1, np.column_stack([xc ** 3, xc ** 5]))) / sigma
        bend = {}
        if stat > PARTIAL:
            # which way the gain changes: a saturation's falls towards the extremes
            # (the residual follows -v^3 beyond a line); a gain that rises there is
            # not one, and no saturating part can fit it
            c3 = np.linalg.lstsq(np.column_stack([N1, xc ** 3]), e, rcond=None)[0][-1]
            bend = {"gain_at_extremes": "falls" if c3 < 0 else "rises"}
            if c3 >= 0:
                bend["reading"] = ("present: " + sig + ", but the gain rises towards the extremes (the residual "
                                   "follows +v^3): an expanding map, not a saturation")
        put("saturation", sig, stat, PARTIAL, **bend)

    if only is None or only in ('output_saturation',):
        # -- output saturation: the output stays flat at an extreme while the input keeps moving
        sig = ("input range over which the output sits at its extreme (within 3 noise floors) while the "
               "input still runs towards it, in fractions of the input span, where the residual exceeds the "
               "noise by more than two noise floors")
        stat = 0.0
        for top in (True, False):
            # the extreme without its noise: a high percentile of the output
            lim = float(np.percentile(rec.y, 99.5 if top else 0.5))
            near = np.abs(rec.y - lim) <= 3 * sigma
            # on the branch that runs into the extreme (rising into the top): a
            # hysteresis loop reaches its extreme only at the input's extreme, a
            # clipped output long before (a loop's flat start after a reversal
            # does not count)
            at = near & ((rec.direction > 0) if top else (rec.direction < 0))
            # the output sits at the extreme for 0.5 % of the record or more, in
            # either direction (a brief clip under random drive is about as often
            # left running in as running out; counting one direction alone
            # halved it below the bar); and a few samples run into it
            if near.mean() < 0.005 or at.sum() < CLIP_SAMPLES or at.all():
                continue
            # from where the output first sits there to the input's extreme (holds at the
            # extreme put many samples at one input value: a percentile range would hide it)
            if top:
                reach = rec.vmax - float(np.percentile(rec.v[at], 5))
            else:
                reach = float(np.percentile(rec.v[at], 95)) - rec.vmin
            # ... and only where the model misses it: the residual there exceeds the
            # noise by more than CLIP_EXCESS noise floors (RMS, in quadrature)
            excess = math.sqrt(max(float(np.mean(e[at] ** 2)) - sigma ** 2, 0.0)) / sigma
            if excess > CLIP_EXCESS:
                stat = max(stat, reach / rec.span)
        put("output_saturation", sig, stat, 0.03)

    if only is None or only in ('initial_state',):
        # -- initial state: a misfit of its own at the record's start (before the input's
        # first full excursion, and over the first 5, 10 and 20 % of the record: the
        # memory of a preload is wiped out once the input passes the preload's extremes)
        sig = ("residual with a level and gain of its own at the record's start (before the first full "
               "excursion; first 5, 10, 20 %), beyond static functions of the input and a smooth trend")
        lo = np.flatnonzero(rec.v <= rec.vmin + 0.05 * rec.span)
        hi = np.flatnonzero(rec.v >= rec.vmax - 0.05 * rec.span)
        k1 = int(max(lo[0], hi[0])) + 1 if lo.size and hi.size else n
        ends = sorted({int(f * n) for f in (0.05, 0.1, 0.2)} | ({k1} if 10 <= k1 <= 0.6 * n else set()))
        k_idx = np.arange(n)
        # windows by the input's reach: a play of threshold r keeps its memory until the input
        # has run over 2 r (the running range max - min); under excursions that grow slowly
        # the memory fades in steps as the reach grows, not within a set share of the time
        reach = (np.maximum.accumulate(rec.v) - np.minimum.accumulate(rec.v)) / rec.span
        for q in (0.4, 0.6, 0.8):
            k = int(np.searchsorted(reach, q))
            if 0.2 * n < k <= 0.9 * n and all(abs(k - k0) > 0.05 * n for k0 in ends):
                ends.append(k)
        def start_columns():
            tn = k_idx / (n - 1) - 0.5
            return (np.column_stack([N, tn, tn ** 2]),
                    np.column_stack([col for k in ends for col in ((k_idx < k).astype(float), (k_idx < k) * xc)]))

        put("initial_state", sig, _partial_fixed(e, rec, ("initial_state",), start_columns) / sigma, START,
            first_excursion=k1)
    if pair:
        _shift_or_lag(ev)
    return ev


#: the two tests that read one misfit, each by the other's name (:func:`_shift_or_lag`)
SHIFT_OR_LAG = {"delay": "rate_dependence", "rate_dependence": "delay"}


def _shift_or_lag(ev):
    """A dead time T and a lag tau leave the same residual to first order in
    the frequency (e^(-sT) and 1 / (1 + s tau) both start 1 - s T), so the
    delay's test (along the model output's derivative) and the rate
    dependence's (against the input rate) see one misfit through different
    columns: when both are testable, either present makes both present, and
    the fits tell them apart (the dead time, with fewer parameters, on a
    near tie).  A record driven at one frequency leaves rate dependence
    untested, and the delay on its own test."""
    if not all(ev[name]["testable"] for name in SHIFT_OR_LAG):
        return
    for own, paired in SHIFT_OR_LAG.items():
        mine, other, name = ev[own], ev[paired], paired.replace("_", " ")
        if other["present"] and not mine["present"]:
            mine["present"] = True
            mine["reading"] = (f"present through the {name}'s test ({other['statistic']:.2f} > "
                               f"{other['threshold']:.2f}): a dead time and a lag leave the same residual to first "
                               f"order; its own, {mine['signature']}, is {mine['statistic']:.2f}")


def _merged_holds(rec):
    """The record's holds, those at one level merged: a slow approach to a
    plateau splits it into short holds (the input still creeping by more
    than the hold's tolerance) that are one hold for creep.  Consecutive
    holds merge while the input between them stays within 1 % of the span
    of the first one's level; the merged hold keeps the first one's step."""
    out = []
    turn = TURN_BACK * rec.span
    for k, j, s in rec.holds:
        if out:
            k0, j0, s0, lv = out[-1]
            if abs(float(np.mean(rec.v[k:j])) - lv) <= turn and np.all(np.abs(rec.v[j0:k] - lv) <= turn):
                out[-1] = (k0, j, s0, lv)
                continue
        out.append((k, j, s, float(np.mean(rec.v[k:j]))))
    return [(k, j, s) for k, j, s, _ in out]


def _xcorr_lag(e, d, max_lag):
    """Lag (samples, positive: the residual lags) of the largest |cross-correlation|."""
    best, lag = -1.0, 0
    n = e.size
    for k in range(-max_lag, max_lag + 1):
        a = e[max(0, k):n + min(0, k)]
        b = d[max(0, -k):n - max(0, k)]
        if a.size < 10:
            continue
        c = abs(float(a @ b))
        if c > best:
            best, lag = c, k
    return int(lag)
