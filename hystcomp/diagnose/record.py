"""A measured record as diagnosis reads it: checks, the input's holds and the
noise floor."""

import math

import numpy as np

from .._validation import as_scalar, as_signal
from ..identify._records import _seconds
from ._hold_runs import hold_runs
from .noise import _input_noise


#: share of the input span by which the held-out part may leave the fitted
#: part's input range before the report cautions that its residual is partly
#: extrapolation (over the realistic sets' 225 runs: 91 % named right at or
#: below 5 %, 67 % above)
BEYOND = 0.05

#: with ``held_out="auto"`` on a timed record, the held-out part's input may move at
#: most this many times as fast as the fitted part's (the 99th percentiles of the
#: smoothed input's rate): beyond, a rate effect is judged by extrapolation in rate,
#: as a chirp's fastest end or stepped sines' last steps would be
FASTER = 2.0

#: with ``held_out="auto"``, an inner held-out block starts at a multiple of
#: this share of the record, not before BLOCK_FIRST of it (the fit needs the
#: record's first part: the core's virgin loading, the initial state)
BLOCK_STEP = 0.05
BLOCK_FIRST = 0.3

#: ``held_out="blocks"``: the held-out share in this many blocks spread over
#: the record after :data:`BLOCK_FIRST` of it (see :func:`spread_blocks`)
N_BLOCKS = 5

HELD_OUT = ("auto", "last", "blocks")


def spread_blocks(n, length, m=N_BLOCKS):
    """`m` held-out blocks, `length` samples in all, spread over a record of
    `n` samples after :data:`BLOCK_FIRST` of it, with fitted stretches of
    equal length between them and after the last: a time function of no set
    shape (a thermal drift) is then judged by interpolation, not by
    extrapolation into the record's end.

    Returns
    -------
    list of (int, int)
        Each block's first sample and the sample after its last.

    Examples
    --------
    >>> spread_blocks(1000, 300, 3)
    [(300, 400), (533, 633), (767, 867)]
    """
    first = int(round(BLOCK_FIRST * n))
    L = length // m
    g = (n - first - m * L) / m
    return [(int(round(first + i * (L + g))), int(round(first + i * (L + g))) + L) for i in range(m)]


def caution(beyond, short=False):
    """The caution on a held-out part that leaves the fitted part's input
    range by `beyond` (a share of the input span), or "" at or below
    :data:`BEYOND`; `short` for a figure's title."""
    if beyond <= BEYOND:
        return ""
    s = f"the held-out part drives the input {100 * beyond:.0f} % of its span beyond the fitted part's range"
    if short:
        return s + " (partly extrapolation)"
    return (s + "; its residual there is partly the extrapolation of plays the fit never moved, not only "
            "missing effects (a record whose held-out part stays within the rest's range is judged more surely)")


#: a held-out part over which the input moves less than this share of its span
#: (a quiet tail: the input held, or dying away) tests nothing the input
#: drives: any model of the input passes it, and the report says so
#: (:func:`quiet_caution`).  Over the thirty-six realistic sets (seeds 0 ... 2,
#: 1,125 records) four held-out ends were this quiet (0.2 ... 3.9 %); the next
#: moved the input over 6.7 % of its span.
QUIET = 0.05


def quiet_caution(share, short=False):
    """The caution on a held-out part over which the input moves only
    `share` of its span, or "" at or above :data:`QUIET`; `short` for a
    figure's title.

    Examples
    --------
    >>> quiet_caution(0.5)
    ''
    >>> quiet_caution(0.0022, short=True)
    'the held-out part moves the input over only 0.22 % of its span (it tests little)'
    """
    if share >= QUIET:
        return ""
    s = f"the held-out part moves the input over only {100 * share:.2g} % of its span"
    if short:
        return s + " (it tests little)"
    return (s + "; it tests nothing the input drives (any model of the input passes it), so the verdict rests "
            "on the signatures and on effects in time; hold out a part where the input moves (validation, "
            "held_out='blocks') to judge the effects of the input")


#: a record whose first input lies within this share of its span of either
#: end of its input range starts at an end (a unipolar stroke from 0 V, an
#: actuator parked at a stop): an ``initial_state`` named on it is cautioned
#: (:func:`start_caution`)
START_END = 0.05

#: how often an ``initial_state`` named on the realistic test records (the
#: committed sets, seeds 0 ... 2) was the labelled effect: (right, named) on
#: records that start at an end (within :data:`START_END` of it) and inside
#: the range, the number of runs and the round measured; the caution of
#: :func:`start_caution` quotes it
START_RECORD = {"end": (19, 56), "inside": (164, 178), "runs": 1845, "round": 61}


def start_caution(position, short=False):
    """The caution on an ``initial_state`` named on a record whose first input
    sits at `position` of its input range (0: the minimum, 1: the maximum), or
    "" when it starts more than :data:`START_END` of the span from both ends;
    `short` for a figure's title.

    An actuator brought to the end of its range before the record (a unipolar
    stroke from 0 V after earlier use, cells filled and run in at one end)
    keeps a memory that a stroke from that end never wipes out: the plays that
    came down from the top stay raised.  The initial state the diagnosis fits
    is then that memory, which a user who drove the actuator before the record
    should expect, rather than a disturbance.  On the realistic test records
    (:data:`START_RECORD`: the committed sets, seeds 0 ... 2, 1,845 runs as of
    round 61) an initial state named on a record starting at an end was the
    labelled effect in 19 of 56 runs, and in 164 of 178 on records starting
    inside the range; the sets' labels count such prior-use memory as no
    effect.

    Examples
    --------
    >>> start_caution(0.5)
    ''
    >>> start_caution(0.0, short=True)
    'the record starts at the low end of its input range (the initial state may be prior use)'
    """
    if START_END <= position <= 1.0 - START_END:
        return ""
    end = "low" if position < 0.5 else "high"
    s = f"the record starts at the {end} end of its input range"
    if short:
        return s + " (the initial state may be prior use)"
    return (s + f" ({100 * min(position, 1.0 - position):.2g} % of its span from it): the initial state named may "
            "be the memory of the actuator's use before the record (one driven to the other end and back, or "
            "prepared at this end, keeps a memory that a stroke from this end never wipes out) rather than a "
            "disturbance; on the realistic test records an initial state named on a record starting at an end was "
            f"the labelled effect in {_of(START_RECORD['end'])} runs, against {_of(START_RECORD['inside'])} "
            "elsewhere; a record that starts inside the range, or from a known state (demagnetised, or after a "
            "decaying alternating drive), tells them apart")


def _of(counts):
    """'17 of 45' for ``(17, 45)``."""
    return f"{counts[0]} of {counts[1]}"


def _range_excess(vh, rest, span):
    """How far the samples `vh` leave the range of the samples `rest`, in
    shares of `span`."""
    out = max(float(vh.max() - rest.max()), 0.0) + max(float(rest.min() - vh.min()), 0.0)
    return out / span


def _beyond_range(v, a, b, span):
    """How far v[a:b] leaves the range of the rest of v, in shares of `span`."""
    return _range_excess(v[a:b], np.concatenate([v[:a], v[b:]]), span)


def _fast(r):
    """The input's fast rate: the 99th percentile of ``|r|``."""
    return float(np.percentile(np.abs(r), 99)) if r.size else 0.0


def _rate_excess(r, a, b):
    """How many times as fast the input moves in r[a:b] as in the rest (the
    99th percentiles of ``|r|``; 0 when the rest does not move)."""
    rest = _fast(np.concatenate([r[:a], r[b:]]))
    return _fast(r[a:b]) / rest if rest > 0 else 0.0


def _excess(v, a, b, span, rate=None):
    """How far the block v[a:b] leaves the rest's input range and (with
    `rate`) rate, in units of the allowed :data:`BEYOND` and :data:`FASTER`:
    at most 1 when it leaves neither."""
    x = _beyond_range(v, a, b, span) / BEYOND
    if rate is not None:
        x = max(x, _rate_excess(rate, a, b) / FASTER)
    return x


def inner_block(v, length, span, rate=None):
    """Start of a held-out block of `length` samples inside the record whose
    input stays within the rest's range (to :data:`BEYOND` of the span) and,
    given the input's `rate`, moves at most :data:`FASTER` times as fast as
    the rest: the latest such start at a multiple of :data:`BLOCK_STEP` of
    the record from :data:`BLOCK_FIRST` of it on; when none does, the start
    whose block leaves them least, or None when there is no start.

    Parameters
    ----------
    v : ndarray
        Input samples.
    length : int
        Samples held out.
    span : float
        The input's span.
    rate : ndarray, optional
        The input's rate (a timed record).

    Returns
    -------
    int or None

    Examples
    --------
    A sine whose amplitude grows to the end: the last 300 samples leave the
    rest's range, the block 600 ... 899 does not (the samples after it reach
    further):

    >>> v = np.linspace(0.5, 1.0, 1000) * np.sin(np.linspace(0, 60, 1000))
    >>> inner_block(v, 300, float(np.ptp(v)))
    600

    Stepped sines, 1 Hz and then 4 Hz over the last 30 %: held out, the end
    moves four times as fast as the rest; the block 650 ... 949 leaves fast
    samples in the fitted part:

    >>> t = np.linspace(0.0, 10.0, 1000, endpoint=False)
    >>> v = np.where(t < 7.0, np.sin(2 * np.pi * t), np.sin(2 * np.pi * 4 * t))
    >>> rate = np.gradient(v, t)
    >>> round(_rate_excess(rate, 700, 1000), 1)
    4.0
    >>> inner_block(v, 300, float(np.ptp(v)), rate=rate)
    650
    """
    n = v.size
    step = max(int(round(BLOCK_STEP * n)), 1)
    starts = list(range(int(round(BLOCK_FIRST * n)), n - length, step))   # each block ends before n
    if not starts:
        return None
    out = [(_excess(v, a, a + length, span, rate), a) for a in starts]
    inside = [a for x, a in out if x <= 1.0]
    if inside:
        return max(inside)
    x, a = min(out)
    return a


class Record:
    """Checked (t, v, y) with the held-out split, the input's holds, rate and
    the figures of the excitation.

    ``t = None``: no time axis (a quasi-static point sequence, e.g. a B-H
    loop); the sample index is the only axis.  A datetime or timedelta `t`
    (numpy or pandas) is read as seconds from its first sample.

    The held-out part is ``validation`` of the record: its end
    (``held_out="last"``), or, with ``held_out="auto"``, its end unless the
    end drives the input more than :data:`BEYOND` of the span beyond the
    rest's range (a record whose amplitude grows) or, on a timed record,
    moves it more than :data:`FASTER` times as fast as the rest (a chirp's
    fast end); then the block of the same length inside the record chosen
    by :func:`inner_block` (when it leaves the range and rate less than half
    as far as the end does, in units of the two limits).  With
    ``held_out="blocks"``, :data:`N_BLOCKS` blocks spread over the record
    (:func:`spread_blocks`).  The held-out samples are those of
    :attr:`blocks`, all within ``held_start ... held_end - 1``.
    """

    def __init__(self, t, v, y, validation, held_out="auto"):
        self.v = as_signal(v, "v", min_length=2)
        self.y = as_signal(y, "y", min_length=2)
        #: the output as measured (:attr:`y` is the output the parts fit: times
        #: :attr:`output_sign`, less :attr:`y_offset`)
        self.measured = self.y
        n = self.v.size
        if self.y.size != n:
            raise ValueError(f"Parameter y has {self.y.size} samples but v has {n}; expected equal lengths")
        if t is None:
            self.t = None
            self.dt = None
        else:
            # a datetime or timedelta axis: seconds from the first sample
            self.t = as_signal(_seconds(t, "t"), "t", min_length=2)
            if self.t.size != n:
                raise ValueError(f"Parameter v has {n} samples but t has {self.t.size}; expected equal lengths")
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
                             "(that share of the record is held out)")
        if held_out not in HELD_OUT:
            raise ValueError(f"Parameter held_out is {held_out!r} but should be one of {HELD_OUT}")
        self.n = n
        self.k_val = int(round(n * (1.0 - frac)))
        if self.k_val < 50 or n - self.k_val < 20:
            raise ValueError(f"Parameters v and y have {n} samples; at least 50 training and 20 held-out "
                             f"samples are needed (validation = {frac})")
        self.vmin, self.vmax = float(self.v.min()), float(self.v.max())
        self.span = self.vmax - self.vmin
        if self.span <= 0:
            raise ValueError(f"Parameter v is constant ({self.v[0]}); diagnosis needs an input that moves")
        _check_scale(self.v, self.span, "v")
        # a smoothed input and its rate (per second, or per sample without a time axis)
        self.vs = _smooth(self.v, 5)
        self.rate = np.gradient(self.vs) if self.dt is None else np.gradient(self.vs, self.dt)
        # the held-out part: the end, or (auto) a block inside the record when
        # the end leaves the rest's input range, or (blocks) blocks spread over it
        #: how far the end block would have left the range when the block was moved (else 0)
        self.held_moved_from_end = 0.0
        #: how many times as fast the end's input moved as the rest's when the block was moved (else 0)
        self.held_moved_faster = 0.0
        #: the held-out blocks, (first sample, sample after the last) each
        self.blocks = [(self.k_val, n)]
        if held_out == "blocks":
            self.blocks = spread_blocks(n, n - self.k_val)
        elif held_out == "auto":
            rate = None if self.t is None else self.rate
            end = _excess(self.v, self.k_val, n, self.span, rate)
            if end > 1.0:
                a = inner_block(self.v, n - self.k_val, self.span, rate)
                if a is not None and _excess(self.v, a, a + n - self.k_val, self.span, rate) < 0.5 * end:
                    self.held_moved_from_end = _beyond_range(self.v, self.k_val, n, self.span)
                    self.held_moved_faster = 0.0 if rate is None else _rate_excess(rate, self.k_val, n)
                    self.blocks = [(a, a + n - self.k_val)]
        self.train = np.ones(n, bool)
        for a, b in self.blocks:
            self.train[a:b] = False
        self.y_span = float(np.ptp(self.y))
        if self.y_span <= 0:
            raise ValueError(f"Parameter y is constant ({self.y[0]}); there is no response to diagnose")
        _check_scale(self.y, self.y_span, "y")
        # an output that falls as the input rises: the parts (weights >= 0) model -y
        slope = float(np.polyfit(self.v, self.y, 1)[0])
        self.output_sign = -1.0 if slope < 0 else 1.0
        if self.output_sign < 0:
            self.y = -self.y
        # an output far from 0 is fitted about its median: the solves' Gram
        # matrices square the output, and a level 50,000 spans from 0 left 1.5
        # noise floors where the same record about 0 left 1.0 (round 28)
        self.y_offset = 0.0
        med = float(np.median(self.y))
        if abs(med) > FAR_OUTPUT * self.y_span:
            self.y_offset = med
            self.y = self.y - med
        # the plays' rest point (the core's origin): physical zero when the record
        # contains or comes near 0 (a unipolar record 0..100 V: plays up to the
        # full span); else the first sample (a record far from 0 starts with
        # plays at rest).  A record that never reaches 0 may have started
        # either way (switched on at 0 V and driven to its first sample, or
        # settled at it): the search tries both (:attr:`other_origin`)
        contains = self.vmin <= 0.0 <= self.vmax
        near = contains or min(abs(self.vmin), abs(self.vmax)) <= self.span
        self.set_origin(0.0 if near else float(self.v[0]))
        #: the other rest point the search tries (None on a record that reaches 0)
        self.other_origin = None if contains else (float(self.v[0]) if near else 0.0)
        self.duration = None if self.dt is None else n * self.dt
        # input noise (the input's high-frequency part)
        self.input_noise = _input_noise(self.v)
        if self.dt is not None:
            self.holds = find_holds(self.v, self.dt, self.span)
            P = np.abs(np.fft.rfft(self.v - self.v.mean())) ** 2
            f = np.fft.rfftfreq(n, self.dt)
            P, f = P[1:], f[1:]
            self.f_peak = float(f[np.argmax(P)]) if P.size else 0.0
            band = (f >= self.f_peak / 1.5) & (f <= self.f_peak * 1.5)
            self.peak_share = float(P[band].sum() / P.sum()) if P.sum() > 0 else 1.0
        else:
            self.holds = []
            self.f_peak, self.peak_share = 0.0, 1.0
        self.direction = np.sign(self.rate)
        #: the signature tests' columns that depend on the record alone, with their Gram
        #: matrices, built at their first use (:mod:`hystcomp.diagnose.signatures`)
        self.signature_memo = {}

    def set_origin(self, origin):
        """Start the plays at rest at `origin` (input units): the core works
        on ``(v - origin) / scale`` with ``scale`` the largest ``|v - origin|``.
        (A play at rest at ``origin`` is the play from 0 of ``v - origin``,
        shifted by ``origin``: the rest point is the core's origin.)"""
        self.origin = float(origin)
        self.scale = float(np.max(np.abs(self.v - self.origin))) or 1.0

    @property
    def beyond_fitted_range(self):
        """How far the held-out input leaves the fitted part's input range, in
        fractions of the input span (0 when it stays inside): there the plays
        whose thresholds the fitted part never reached are extrapolated."""
        return _range_excess(self.v[~self.train], self.v[self.train], self.span)

    @property
    def held_input_share(self):
        """The share of the input's span that the held-out input moves over
        (below :data:`QUIET` the held-out part tests nothing the input
        drives)."""
        return float(np.ptp(self.v[~self.train])) / self.span

    @property
    def start_in_input_range(self):
        """Where the record's first input sits in its input range: 0 at the
        minimum, 1 at the maximum (the smoothed input, so that a monitor's
        noise does not move it)."""
        return float(np.clip((self.vs[0] - self.vmin) / self.span, 0.0, 1.0))

    @property
    def held_start(self):
        """The first held-out sample (of the first block)."""
        return self.blocks[0][0]

    @property
    def held_end(self):
        """The sample after the last held-out one (of the last block)."""
        return self.blocks[-1][1]

    @property
    def held_out_in_middle(self):
        """Whether the held-out block lies inside the record (not at its end)."""
        return self.held_end < self.n

    def _at(self, k):
        return float(self.t[k]) if self.t is not None else k

    def held_interval(self):
        """The held-out part's first and last sample, in seconds (or sample
        indices without a time axis); with several blocks, the first block's
        first and the last block's last sample (see :meth:`held_blocks`)."""
        return self._at(self.held_start), self._at(self.held_end - 1)

    def held_blocks(self):
        """Each held-out block's first and last sample, in seconds (or sample
        indices without a time axis)."""
        return [(self._at(a), self._at(b - 1)) for a, b in self.blocks]

    def held_out_line(self):
        """The report's line on a part held out inside the record ("" when
        the end is held out)."""
        if not self.held_out_in_middle:
            return ""
        unit = " s" if self.t is not None else " (sample index)"
        if len(self.blocks) > 1:
            where = ", ".join(f"{a:.4g} ... {b:.4g}" for a, b in self.held_blocks())
            return (f"held out: {len(self.blocks)} blocks spread over the record, {where}{unit} (a time "
                    "effect of no set shape is judged by interpolation between fitted stretches)")
        a, b = self.held_interval()
        why = []
        if self.held_moved_from_end > BEYOND:
            why.append(f"drives the input {100 * self.held_moved_from_end:.0f} % of its span beyond the rest's range")
        if self.held_moved_faster > FASTER:
            why.append(f"moves the input {self.held_moved_faster:.3g} times as fast as the rest")
        return (f"held out: {a:g} ... {b:g}{unit} inside the record, not its end (the end "
                + " and ".join(why) + ")")


def _smooth(x, m):
    if x.size < 2 * m + 1:
        return x.copy()
    k = np.ones(2 * m + 1) / (2 * m + 1)
    xp = np.pad(x, m, mode="edge")
    return np.convolve(xp, k, mode="valid")


#: an output whose median is more than this many spans from 0 is fitted about
#: its median (the model adds it back: ``PartsModel.offset``)
FAR_OUTPUT = 100.0

#: the largest and the smallest span and magnitude of a record's columns: the
#: diagnosis squares and sums the samples
LARGEST, SMALLEST = 1e100, 1e-100


def _check_scale(x, span, name):
    """Reject a column whose squares and sums would overflow or underflow."""
    big = float(np.max(np.abs(x)))
    if big > LARGEST or span < SMALLEST:
        raise ValueError(f"Parameter {name} spans {span:.3g} with values up to {big:.3g} in magnitude; diagnosis "
                         f"needs a span of at least {SMALLEST:g} and values within {LARGEST:g} (it squares and "
                         f"sums the samples): rescale {name} (e.g. to other units)")


#: the input has turned back (a reversal ends the walk into a hold) when it returns
#: by this share of its span; holds within it of one level are one hold for creep
TURN_BACK = 0.01


def find_holds(v, dt, span, noise=None, min_duration=0.1, min_samples=10):
    """Segments where the input stays put: (start, end, step) of each run of
    at least ``max(min_samples, min_duration/dt)`` samples in which the
    input, smoothed over 11 samples, stays within five noise widths (of
    the smoothed input's difference; the input's own noise, from its
    quietest stretches, at least 1e-4 of its span) of its value at the run's
    run so far.  `step` is the load change into the hold since the input
    last turned back: the hold's level minus the farthest the smoothed input
    was on the way in, walking back to where it had turned back by 1 % of
    its span (or the noise tolerance, if larger), over any holds on the way.
    A hold reached by a slow ramp thus counts its whole ramp, and a stair of
    a staircase every stair since the staircase turned (until round 27: the
    hold's level minus the mean input over the 2 s before it, which counted
    only the last seconds of a slow approach).

    Parameters
    ----------
    v : ndarray
        Input samples.
    dt : float
        Sampling step [s].
    span : float
        The input's span.
    noise : float, optional
        Input noise standard deviation (default estimated from `v`).
    min_duration : float
        Shortest hold [s].
    min_samples : int
        Shortest hold [samples].

    Returns
    -------
    list of (int, int, float)

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> v = np.concatenate([np.linspace(0, 1, 50), np.ones(100), np.linspace(1, 0, 50), np.zeros(100)])
    >>> holds = find_holds(v + 1e-3 * rng.standard_normal(300), 0.01, 1.0)
    >>> [(k // 10, j // 10, bool(s > 0)) for k, j, s in holds]
    [(5, 14, True), (20, 29, False)]
    """
    if noise is None:
        noise = _input_noise(v)
    vs = _smooth(v, 5)
    # two 11-sample means differ by noise sqrt(2/11) (std); five such widths,
    # and never less than 1e-4 of the span (a noise-free input)
    tol = max(5.0 * noise * math.sqrt(2.0 / 11.0), 1e-4 * span)
    min_len = max(int(min_samples), int(round(min_duration / dt)))
    # the approach turns back when the smoothed input returns by this much
    turn = max(tol, TURN_BACK * span)
    out = []
    # runs whose samples stay within tol of the mean of the run's smoothed samples so far
    starts, ends = hold_runs(np.ascontiguousarray(vs, dtype=np.float64), float(tol), int(min_len))
    for k, j in zip(starts.tolist(), ends.tolist()):
        # a hold is judged by its own level: shrink by the smoothing half-width
        a, b = min(k + 5, j - 1), max(j - 5, k + 1)
        if b - a >= min_len // 2:
            level = float(np.mean(v[a:b]))
            out.append((a, b, _approach_step(vs, a, level, turn)))
    return out


def _approach_step(vs, a, level, turn, chunk=4096):
    """The load change into a hold starting at `a`: `level` minus the extreme
    of the smoothed input `vs` walking back from `a`, up to where it first
    turned back by more than `turn` (a reversal; else the record's start).
    Of the walk from below and the walk from above, the larger change is the
    approach.  The walk reads back in blocks of `chunk` samples and stops at
    the reversal, so its cost is the approach's length, not the record's."""
    best = 0.0
    for sign in (1.0, -1.0):            # from below (a running minimum), from above
        ext, j = math.inf, a
        while j > 0:
            back = sign * vs[max(0, j - chunk):j][::-1]
            run = np.minimum(np.minimum.accumulate(back), ext)
            turned = back - run > turn
            if turned.any():
                k = int(np.argmax(turned))
                # the extreme before the input turned back (the sample before the turn)
                ext = float(run[k - 1]) if k > 0 else ext
                break
            ext = float(run[-1])
            j -= back.size
        if math.isfinite(ext):
            step = level - sign * ext
            if abs(step) > abs(best):
                best = step
    return best
