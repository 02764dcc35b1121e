"""The record's noise floor: the high-frequency part of a residual, the
scatter of the output during the input's holds, and the checks on both
(holds that oscillate, holds that carried structure, samples clipped at a
converter's full scale)."""

import math

import numpy as np

#: the smallest noise floor, in output spans: the solves' ridge leaves about
#: 1e-6 of the span on a noise-free record the base model draws exactly (y = v:
#: 1.1e-6), which a floor of 1e-6 (until round 28) judged as structure, naming
#: an asymmetry or a rate dependence on it; the floor is ten times that (a
#: 16-bit converter's quantisation over its full scale is 4.4e-6)
RESOLUTION = 1e-5


#: the relative standard error of :func:`_hf_noise` on white Gaussian noise of
#: N samples is HF_STANDARD_ERROR / sqrt(N) (simulated: 1.38-1.40 for N from
#: 5,000 to 40,000, 1,000 records each; a median absolute deviation has 37 %
#: of the efficiency of a standard deviation, and neighbouring second
#: differences are correlated)
HF_STANDARD_ERROR = 1.39


def _hf_noise(x, keep=None):
    """Robust standard deviation of white noise on a smooth signal: the
    median absolute second difference (which removes a smooth signal's
    trend and slope) over 0.6745 sqrt(6); with `keep` (a mask of the
    ``x.size - 2`` second differences), over those kept."""
    if x.size < 5:
        return 0.0
    d2 = x[2:] - 2.0 * x[1:-1] + x[:-2]
    if keep is not None:
        d2 = d2[keep]
        if d2.size < 3:
            return 0.0
    return float(np.median(np.abs(d2 - np.median(d2))) / 0.6745 / math.sqrt(6.0))


def _input_noise(x, m=11):
    """The input's noise: over windows of `m` samples, the scatter about a
    parabola; the 10th percentile of the windows, over 0.72 (that
    percentile of the scatter of white noise with m - 3 degrees of freedom).
    Holds and slow stretches give the noise itself; the fast stretches of a
    clean input are not mistaken for noise, as they are by a difference
    estimate."""
    nb = x.size // m
    if nb < 3:
        return _hf_noise(x)
    X = x[:nb * m].reshape(nb, m)
    tt = np.linspace(-1.0, 1.0, m)
    B = np.column_stack([np.ones(m), tt, tt ** 2 - np.mean(tt ** 2)])
    Q, _ = np.linalg.qr(B)
    R = X - (X @ Q) @ Q.T
    sd = np.sqrt(np.sum(R ** 2, axis=1) / (m - 3))
    return float(np.percentile(sd, 10)) / 0.72


#: a run of at least this many identical samples at the output's largest or
#: smallest value is clipped: a converter at its full scale, a gauge at its
#: stop, which reads the same code whatever the noise
CLIPPED_RUN = 3


def clipped_samples(y):
    """The samples of `y` in runs of at least :data:`CLIPPED_RUN` identical
    values at its largest or its smallest value (a boolean mask).

    Noise rides on no such sample, so the noise floor leaves them out: on a
    record clipped for half its length the median absolute second difference
    of the residual is that of the clipped stretches' smooth residual, and the
    floor falls to a small fraction of the noise (a creep record clipped by its
    gauge's converter, 42-52 % of its samples at full scale: a floor 200 times
    below the true noise, round 53).  Runs of one code inside the range (a
    coarse converter) are not clipping and stay in.

    Examples
    --------
    >>> y = np.array([0.0, 1.0, 2.0, 2.0, 2.0, 1.5, 2.0, 0.5, 0.0])
    >>> clipped_samples(y).astype(int).tolist()
    [0, 0, 1, 1, 1, 0, 0, 0, 0]
    """
    y = np.asarray(y)
    mask = np.zeros(y.size, dtype=bool)
    if y.size < CLIPPED_RUN:
        return mask
    for level in (np.max(y), np.min(y)):
        at = np.concatenate(([False], y == level, [False]))
        edges = np.flatnonzero(np.diff(at.astype(np.int8)))
        for a, b in zip(edges[::2], edges[1::2]):
            if b - a >= CLIPPED_RUN:
                mask[a:b] = True
    return mask


#: pooled autocorrelation of the holds' scatter below which it is an oscillation
#: (a limit cycle swings to about -1 at half its period; sensor noise, white or
#: low-pass filtered, stays near or above 0)
OSCILLATING = -0.5


def hold_oscillation(parts):
    """The most negative autocorrelation of the output's scatter during holds,
    pooled over the holds (each segment's own products, over lags from 1 to
    half the shortest segment, at most 200 samples): ``(lag, value)``.  An
    oscillation sustained while the input is held (a relay servo hunting, a
    vibration) gives about -1 at half its period; white or low-pass filtered
    sensor noise stays near or above 0.

    Examples
    --------
    >>> t = np.arange(400)
    >>> hold_oscillation([np.sin(2 * np.pi * t / 20)])[0]
    10
    >>> hold_oscillation([np.random.default_rng(0).standard_normal(400)])[1] > -0.2
    True
    """
    L = min(200, min(p.size for p in parts) // 2)
    if L < 1:
        return 0, 0.0
    zero = sum(float(p @ p) for p in parts)
    if zero <= 0.0:
        return 0, 0.0
    acf = np.array([sum(float(p[m:] @ p[:-m]) for p in parts) for m in range(1, L + 1)]) / zero
    k = int(np.argmin(acf))
    return k + 1, float(acf[k])


def noise_floor(rec, residual):
    """The record's noise floor [output units] and how it was measured.

    Two estimates, from the record itself: the high-frequency part of the
    base model's residual (median absolute second difference, robust to the
    residual's smooth structure and to isolated kinks at turning points),
    and, when the input holds still, the scatter of the output within each
    hold's second half about a quadratic trend (which takes out creep's
    slow relaxation); the larger of the two (coloured sensor noise is
    underestimated by the second difference alone), unless the holds' scatter
    oscillates (:func:`hold_oscillation`; ``info["holds_oscillate"]``): an
    output that swings while its input is held is structure the model
    misses, not noise. Samples clipped at the output's largest or smallest
    value (:func:`clipped_samples`; ``info["clipped"]`` counts them)
    carry no noise: both estimates leave them out. ``info`` also carries the
    floor's relative standard error (``relative_standard_error``): an
    "explained" verdict asks for the held-out RMS to be within 1.5 floors by
    that margin.

    Parameters
    ----------
    rec : Record
        The record.
    residual : ndarray
        Measured minus base-model output.

    Returns
    -------
    float, dict
    """
    clipped = clipped_samples(rec.y)
    hf, n_used = _residual_high_frequency(residual, clipped)
    info = {"high_frequency": hf}
    if clipped.any():
        info["clipped"] = {"samples": int(clipped.sum()), "share": round(float(clipped.mean()), 4)}
    sd, dof, parts = [], 0, []
    for k, j, _ in rec.holds:
        a = (k + j) // 2
        if j - a < 8 or clipped[a:j].any():
            continue
        seg = rec.y[a:j]
        tt = np.linspace(-1.0, 1.0, seg.size)
        c = np.polyfit(tt, seg, 2)
        r = seg - np.polyval(c, tt)
        sd.append(float(np.sqrt(np.sum(r ** 2) / max(seg.size - 3, 1))))
        dof += max(seg.size - 3, 1)
        parts.append(r)
    if sd:
        info["holds"] = float(np.median(sd))
        info["n_holds"] = len(sd)
        lag, acf = hold_oscillation(parts)
        if acf < OSCILLATING:
            # the output swings to and fro while the input is held (a limit cycle, a
            # vibration): structure, not sensor noise, so the holds do not set the floor
            info["holds_oscillate"] = {"lag_samples": lag, "autocorrelation": round(acf, 4),
                                       "scatter": info.pop("holds")}
    holds = info.get("holds", 0.0)
    if holds > hf and not holds < RESOLUTION * rec.y_span:
        sigma = holds
        info["method"] = "holds"
        # the median of the holds' scatters: each a standard deviation of m - 3
        # degrees of freedom (relative standard error 1 / sqrt(2 (m - 3))), the
        # median 1.2533 times a mean's standard error
        info["relative_standard_error"] = 1.2533 / math.sqrt(2.0 * dof)
    else:
        sigma, info["method"], info["relative_standard_error"] = _high_frequency_floor(hf, n_used, rec.y_span)
    return sigma, info


def _residual_high_frequency(residual, clipped):
    """The high-frequency estimate of `residual`'s noise and the number of
    samples it used: second differences touching a clipped sample (the mask
    `clipped`) carry no noise and are left out."""
    if not clipped.any():
        return _hf_noise(residual), residual.size
    keep = ~(clipped[2:] | clipped[1:-1] | clipped[:-2])
    return _hf_noise(residual, keep), int(keep.sum()) + 2


def final_residual_floor(rec, residual, sigma, info):
    """The noise floor an "explained" verdict is judged against: when the
    floor came from the high-frequency part of the base model's residual,
    that part again on the final model's `residual`, if it is lower.

    The base model's residual carries the missed effects' own fast
    structure (a dead time's misfit at every fast move, the edges of a
    sampled sensor's staircase), and its second differences read a little of
    it as noise; the final model has taken most of it out.  Round 61, on the
    57 committed runs explained at over 1.40 floors (and 39 clean ones): the
    final residual's estimate was 0.2-1.6 % below the base's where the base
    left a dead time or a rate dependence, and within 0.1 % elsewhere; the
    larger gap was HOLDOUT46's laser sensor (a 5.84-sample latency, seed 0),
    whose floor was 1.091 true noise levels from the base residual and 1.074
    from the final one, so that it was explained at 1.61 true noise levels.
    A floor the holds set, or the resolution, stands (the search's noise
    variances keep `sigma`).  `info` (:func:`noise_floor`'s) gains
    ``final_high_frequency`` when the floor is lowered.

    Parameters
    ----------
    rec : Record
        The record.
    residual : ndarray
        Measured minus the final model's output, in the units of
        :func:`noise_floor`'s residual.
    sigma : float
        The search's noise floor.
    info : dict
        :func:`noise_floor`'s ``info``.

    Returns
    -------
    float
        The verdict's floor, at most `sigma`.
    """
    if info.get("method") != "high_frequency":
        return sigma
    hf, n = _residual_high_frequency(residual, clipped_samples(rec.y))
    floor = _high_frequency_floor(hf, n, rec.y_span)[0]
    if not floor < sigma:
        return sigma
    info["final_high_frequency"] = floor
    return floor


def _high_frequency_floor(hf, n, y_span):
    """The floor from the high-frequency estimate `hf` of a residual of `n`
    samples: ``(floor, method, relative standard error)``; never below the
    solves' resolution (a noise-free record shows no noise above it, and the
    floor is it)."""
    if hf < RESOLUTION * y_span:
        return RESOLUTION * y_span, "resolution", 0.0
    return hf, "high_frequency", HF_STANDARD_ERROR / math.sqrt(max(n - 2, 1))


#: a held-out residual below this share of the holds' scatter shows that the
#: holds carried structure (see :func:`holds_carried_structure`)
HOLDS_CARRIED = 0.75


def holds_carried_structure(info, rms_heldout, y_span, n):
    """The noise floor again when a model's held-out residual falls well below
    the scatter of the output during the holds.

    The held-out residual holds the record's whole noise (no weight was fitted
    to it), so its RMS is at least the noise's up to its sampling error (under
    1 % on a record of thousands of held-out samples).  When it is below
    :data:`HOLDS_CARRIED` of the holds' scatter, what the holds showed was not
    noise but structure that the model now reproduces: a stage's mount ringing
    after each move into a hold that is short beside the ring's decay (the
    oscillation test of :func:`hold_oscillation` needs half a period inside
    half a hold).  The floor is then the high-frequency estimate.  On the
    realistic test records the held-out residual was never below 0.82 of a
    floor the holds set (round 32, 975 runs).

    Parameters
    ----------
    info : dict
        :func:`noise_floor`'s ``info``.
    rms_heldout : float
        The current model's held-out RMS.
    y_span : float
        The output's span.
    n : int
        The record's number of samples (the high-frequency estimate's
        standard error).

    Returns
    -------
    (float, dict) or None
        The new floor and its ``info`` (``holds_carried_structure`` records the
        holds' scatter and the held-out RMS), or None when the floor stands.

    Examples
    --------
    >>> info = {"high_frequency": 0.1, "holds": 0.4, "n_holds": 9, "method": "holds",
    ...         "relative_standard_error": 0.01}
    >>> holds_carried_structure(info, 0.3, 100.0, 10_000)[0]
    0.1
    >>> holds_carried_structure(info, 0.35, 100.0, 10_000) is None
    True
    """
    if info.get("method") != "holds" or not rms_heldout < HOLDS_CARRIED * info["holds"]:
        return None
    new = {k: v for k, v in info.items() if k not in ("holds", "n_holds")}
    new["holds_carried_structure"] = {"scatter": info["holds"], "n_holds": info.get("n_holds"),
                                      "rms_heldout": float(rms_heldout)}
    n = int(n) - int(info.get("clipped", {}).get("samples", 0))   # the clipped samples gave the estimate nothing
    sigma, new["method"], new["relative_standard_error"] = _high_frequency_floor(float(info["high_frequency"]),
                                                                                 n, y_span)
    return sigma, new
