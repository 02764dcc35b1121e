"""The outcome of a diagnosis: verdict, steps, JSON and figures."""

import json
import math
import os
import textwrap

import numpy as np

from .noise import HOLDS_CARRIED
from .record import caution, quiet_caution, start_caution
from .preisach_core import describe as describe_preisach_core
from .signatures import SHIFT_OR_LAG

SCHEMA_VERSION = 30


def _jsonable(x):
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    if isinstance(x, (np.floating, float)):
        return float(x) if math.isfinite(x) else None
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, np.ndarray):
        return _jsonable(x.tolist())
    return x


#: a reversal of the input counts when it moves back from its last extreme by
#: this share of the span (or five noise widths): the half-cycles of the loops
#: figure, not the noise's sign changes during a hold
REVERSAL = 0.02


def reversals(v, tol):
    """Indices of the input's reversals: the extremes from which it moved
    back by more than `tol` (a noisy hold is no reversal).

    Parameters
    ----------
    v : ndarray
        Input samples.
    tol : float
        How far the input must move back from an extreme [input units].

    Returns
    -------
    ndarray of int

    Examples
    --------
    >>> v = np.array([0.0, 1.0, 1.01, 0.99, 1.0, 2.0, 1.0, 0.0, 0.5])
    >>> reversals(v, 0.1).tolist()
    [5, 7]
    """
    out, direction, ext = [], 0, 0
    for k in range(1, v.size):
        if direction == 0:
            # the first move by more than tol sets the direction
            if abs(v[k] - v[0]) > tol:
                direction, ext = (1 if v[k] > v[0] else -1), k
        elif direction > 0:
            if v[k] >= v[ext]:
                ext = k
            elif v[ext] - v[k] > tol:
                out.append(ext)
                direction, ext = -1, k
        else:
            if v[k] <= v[ext]:
                ext = k
            elif v[k] - v[ext] > tol:
                out.append(ext)
                direction, ext = 1, k
    return np.asarray(out, dtype=int)


def _rate_limits(rate, keep=0.998):
    """Limits of the rate axis that hold the middle `keep` of the samples
    (padded by a tenth of that range), and how many samples fall beyond
    them; (None, None, 0) when the whole range is no wider than twice that.

    Examples
    --------
    >>> rate = np.r_[np.sin(np.linspace(0, 20, 10000)), -400.0]
    >>> lo, hi, beyond = _rate_limits(rate)
    >>> round(lo, 2), round(hi, 2), beyond
    (-1.2, 1.2, 1)
    >>> _rate_limits(np.sin(np.linspace(0, 20, 1000)))
    (None, None, 0)
    """
    rate = np.asarray(rate, dtype=np.float64)
    a, b = np.quantile(rate, [(1 - keep) / 2, (1 + keep) / 2])
    pad = 0.1 * (b - a) if b > a else 1.0
    lo, hi = float(a - pad), float(b + pad)
    if rate.min() >= lo - (hi - lo) and rate.max() <= hi + (hi - lo):
        return None, None, 0
    return lo, hi, int(np.count_nonzero((rate < lo) | (rate > hi)))


def _mark_held_out(ax, xax, rec):
    """Dashed lines at each held-out block's start (and end, inside the
    record), the blocks shaded in light orange."""
    for a, b in rec.blocks:
        ax.axvline(xax[a], color="k", ls="--", lw=0.8)
        if b < rec.n:
            ax.axvline(xax[b - 1], color="k", ls="--", lw=0.8)
        ax.axvspan(xax[a], xax[b - 1], color="tab:orange", alpha=0.12, lw=0)


def _ordinal(n):
    """2 -> "2nd", 3 -> "3rd", 11 -> "11th", 21 -> "21st"."""
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"


class Diagnosis:
    """The outcome of :func:`hystcomp.diagnose.diagnose`.

    Attributes
    ----------
    verdict : str
        ``"explained"`` (held-out RMS within :attr:`explained_limit` noise
        floors and no signature left in the residual) or ``"unexplained"``.
    noise_floor : float
        Noise floor estimated from the record [output units] (how:
        ``noise_info``; its relative standard error:
        ``noise_info["relative_standard_error"]``; samples clipped at the
        output's largest or smallest value, left out of it:
        ``noise_info["clipped"]``).
    explained_limit : float
        The bound on an "explained" held-out RMS, in noise floors: 1.5 less
        the floor's relative standard error (1.5 (1 - se)), so that a floor
        estimated a little high does not pass a residual a little above
        1.5 true noise levels.
    effects : list of str
        The effects named, in order.
    tentative : list of str
        Extensions the search added but does not name, because the model
        with them still leaves more than 3 noise floors and they removed less
        than 90 % of the base model's misfit above the noise, or leaves the
        record unexplained and they removed less than 40 %, or it leaves
        more than 6 noise floors whatever they removed on a record whose
        floor is confirmed (by its holds, or measured on a time axis; the
        misfit is mostly of a kind no part describes; ``remaining`` says so
        under ``out_of_vocabulary``).  Also, on a record left unexplained,
        an effect added after the first step whose step lowered the held-out
        mean square by less than 3 noise variances (a saturation or an
        asymmetry: 60), and on a record explained a saturation at any step
        or an asymmetry so added under 2.5, and a saturation so added under
        10; the final model's loss without the step counts too, the larger
        of the two is judged (its step's evidence says so under
        ``small_later_step``; the effects before it stay named).
        Empty otherwise.
    ambiguous : dict
        Named effects the record does not tell apart from others: named
        effect -> the effects whose part came within 10 % of the named part's
        held-out gain at its step and passed every acceptance rule (e.g. a
        dead time and a first-order lag under a drive too slow to separate
        them).  The named one is the better fit or the one with fewer
        parameters; read it as "this or one of these".  Each step lists its
        near ties under ``alternatives``.
    misfit_share_explained : float
        Share of the base model's held-out mean square above the noise that
        the final model removes (1: all of it).
    steps : list of dict
        One per added effect: ``effect``, ``rms_before``, ``rms_after``,
        ``rms_before_pct``, ``rms_after_pct`` (held-out RMS, and in % of the
        output span), ``evidence`` (the signature test, the extension and its
        parameters, gain and BIC change, the held-out RMS of every
        candidate fitted at the step, ``candidates``, and those not fitted
        because their signature was absent, ``signature_absent``) and
        ``dropped`` (True when a later effect made it redundant) and
        ``alternatives`` (its near ties, see :attr:`ambiguous`).
    revisions : list of dict
        Changes of the final pass over the chosen effects: a near-tie part
        replaced by another effect's (``replaced``, ``by``), or a redundant
        one dropped (``by`` None), with the held-out RMS before and after.
    untested : dict
        Effects the data cannot show, with the reason.
    stopped : str
        Why the search ended.
    remaining : dict
        What structure remains when unexplained (key -> where and how much).
    validation : (float, float)
        The held-out part's first and last sample, in seconds (sample
        indices without a time axis).
    held_out_blocks : list of (float, float)
        Each held-out block's first and last sample (one block unless
        ``held_out="blocks"`` or ``"auto"`` took the blocks' diagnosis).
    other_split : dict or None
        With ``held_out="auto"``, when the end left the record unexplained
        with no drift or gain drift named and the record was re-judged on
        blocks spread over it: the verdict of the split not reported
        (``held_out``, ``validation``, ``verdict``, ``effects``,
        ``tentative``, ``rms_heldout``, ``noise_floor``,
        ``noise_floors_left``) and ``why`` the reported one was taken.
    rest : dict
        Where the base model's plays start at rest (``origin``, input
        units): 0 on a record that reaches 0 V.  On a record that never
        does, the search fits the base model with the plays at rest at 0 and
        at the first sample and takes the better (by a BIC lower by more
        than 10; else 0, or the first sample on a record far from 0):
        ``other`` is the point not taken, ``bic`` and ``bic_other`` the two
        base models' BIC on the fitted part, ``why`` the report's line.
        Neither is an unknown memory, so no effect is named for it (an
        ``initial_state`` is one beyond both).
    finer_core : dict or None
        When the base model (checked before the search; reported only when
        taken) or the final model left the held-out part above the explained
        bound: the same model refitted with twice as many plays
        (:mod:`hystcomp.diagnose.resolution`): ``plays``, ``rms_heldout``,
        ``noise_floors``, ``signatures_present`` and ``taken`` (within the
        bound with no signature present: the model and the verdict are the
        finer core's; what remained was the base model's grid of
        thresholds, not an effect).  None when the final model was within
        the bound or the thresholds were given.
    preisach_core : dict or None
        On a record left unexplained: a rate-independent core of the
        Preisach type (a KP model, :func:`hystcomp.identify.fit_kp`) fitted
        to the same part and judged on the held-out part
        (:mod:`hystcomp.diagnose.preisach_core`): ``model``, ``cells``,
        ``weights``, ``rms_heldout``, ``noise_floors``,
        ``signatures_present``, ``lag1_autocorrelation``, ``explains``
        (within the explained bound with no signature present and a residual
        not correlated from sample to sample, as the final model is judged:
        what the vocabulary misses may be a core that is not PI, or a static
        map that such a core draws too), ``taken`` and ``seconds``.  It
        changes no name.  ``taken`` when it explains the record and no
        effect was named (:attr:`tentative` is then emptied, and what the PI
        model left moves from :attr:`remaining` to its ``pi_remaining``):
        the verdict is ``explained`` and :attr:`model` is the KP core
        (:class:`~hystcomp.diagnose.preisach_core.PreisachCoreModel`; the PI
        model of the search stays as :attr:`pi_model`).
        None on a record the PI model and its effects explained.
    held_out_beyond_fitted_range : float
        How far the held-out input leaves the fitted part's input range, in
        fractions of the input span (0: inside it).  Above 0.05 the report
        cautions that the held-out residual is partly extrapolation: on the
        realistic test records such runs were named right in 20 of 30 runs
        against 178 of 195 below (round 6, the end held out); since round 7
        ``held_out="auto"`` holds out a block inside the record instead
        when it can (see :attr:`held_out_moved`).
    held_out_moved : float
        0 when the held-out part is the record's end; else how far the end
        would have driven the input beyond the rest's range (a share of the
        span, above 0.05), which is why a block inside the record was held
        out instead (``held_out="auto"``; :attr:`validation` gives where).
    held_out_input_share : float
        The share of the input's span that the held-out input moves over.
        Below 0.05 (a quiet tail: the input held, or dying away) the report
        cautions that the held-out part tests nothing the input drives: any
        model of the input passes it.
    start_in_input_range : float
        Where the record's first input sits in its input range (0: the
        minimum, 1: the maximum).  When an ``initial_state`` is named on a
        record that starts within 0.05 of an end (a unipolar stroke from 0 V),
        the report cautions that it may be the memory of the actuator's use
        before the record rather than a disturbance
        (:func:`hystcomp.diagnose.record.start_caution`, with the figures
        measured on the realistic test records).
    asymmetry_antisymmetric_share : float or None
        When the final model holds asymmetric envelopes: the share of their
        departure from a PI core that reflection through the rest point
        (``v -> -v``) reverses (:func:`hystcomp.diagnose.symmetry.antisymmetric_share`);
        None otherwise.  Below 0.35 on a record driven to both sides
        (:attr:`input_balance` at least 0.5) the envelopes draw loops that
        change their width with the level alike on both sides: the core's
        shape, not named an asymmetry (:attr:`core_shape`).
    input_balance : float
        How evenly the input is driven to both sides of the core's rest
        point: the weaker side's reach over the stronger's (0 for a record
        on one side, such as a unipolar stroke from 0 V).
    core_shape : dict or None
        When an asymmetry was named only by asymmetric envelopes that are
        mostly point symmetric (:attr:`asymmetry_antisymmetric_share` below
        0.35) on a record driven to both sides: the envelopes are read as
        the core's shape (a generalized PI core whose loops widen or narrow
        towards both ends alike), kept in the model and not named
        (:func:`hystcomp.diagnose.symmetry.core_shape`): ``part``,
        ``antisymmetric_share``, ``input_balance``, ``step`` (1-based, the
        step marked ``core_shape``) and ``why``.  None otherwise.
    held_out_moved_faster : float
        0 when the held-out part is the record's end; else how many times
        as fast the end's input moved as the rest's (the 99th percentiles of
        the rate; above 2 the end was moved for its rate, the analogue of
        the input range for rate effects).
    model : PartsModel or PreisachCoreModel
        The final model, built from the same parts as the fit (or the KP
        core, when :attr:`preisach_core` was taken);
        ``model.simulate(v)`` reproduces :attr:`rms_heldout`.
    pi_model : PartsModel or None
        When :attr:`preisach_core` was taken: the search's final PI model
        (with any extensions it kept tentative), which :attr:`model`
        replaced; None otherwise.
    rms_heldout : float
        Held-out RMS of :attr:`model` (= :attr:`rms_after`).
    rms_before : float
        Held-out RMS of the base PI model (:attr:`base_model`).

    Examples
    --------
    >>> from hystcomp.diagnose import diagnose
    >>> from hystcomp.datasets import hidden_effect_data
    >>> d = hidden_effect_data("drift", seed=3, dt=0.01)
    >>> rep = diagnose(d.t, d.v, d.y, effects=["drift"], progress=False)
    >>> rep.effects, rep.verdict
    (['drift'], 'explained')
    """

    held_out_beyond_fitted_range = 0.0
    explained_limit = 1.5
    held_out_moved = 0.0
    held_out_moved_faster = 0.0
    held_out_input_share = 1.0
    start_in_input_range = 0.5
    asymmetry_antisymmetric_share = None
    input_balance = 1.0
    core_shape = None
    other_split = None
    finer_core = None
    preisach_core = None
    pi_model = None
    held_out_blocks = ()
    rest = None

    def __init__(self, **kw):
        self.__dict__.update(kw)

    def _with_ties(self, effect):
        """`effect` with its near ties, e.g. "delay (or rate_dependence)"."""
        alts = self.ambiguous.get(effect)
        return effect + (f" (or {' or '.join(alts)})" if alts else "")

    def _core_name(self):
        """The core's name: "PI", or "PI (point-symmetric envelopes)" when
        asymmetric envelopes were read as its shape (:attr:`core_shape`), or
        the KP core's when the Preisach-type core was taken
        (:attr:`preisach_core`)."""
        if (self.preisach_core or {}).get("taken"):
            return f"KP core ({self.preisach_core['cells']} x {self.preisach_core['cells']} cells, Preisach type)"
        return "PI" + (" (point-symmetric envelopes)" if self.core_shape else "")

    def _final_name(self):
        """The final model's parts, e.g. "PI + creep + drift" (tentative ones said so)."""
        if not self.effects or not self.tentative:
            names = " + ".join([self._core_name()] + [self._with_ties(e) for e in (self.tentative or self.effects)])
            return names + (" (tentative, not named)" if self.tentative else "")
        # some named, some tentative (small later steps): in the order of the steps
        order = [st["effect"] for st in self.steps if not st.get("dropped")]
        parts = [e for e in dict.fromkeys(order) if e in self.effects or e in self.tentative]
        parts += [e for e in self.effects if e not in parts]
        return " + ".join([self._core_name()]
                          + [self._with_ties(e) if e in self.effects else f"{e} (tentative)" for e in parts])

    def _pct(self, x):
        return 100.0 * x / self.output_span

    def _cautions(self, short=False):
        """The cautions on the held-out part, for the report's lines or (`short`)
        the gap figure's title: it leaves the fitted range
        (:data:`~hystcomp.diagnose.record.BEYOND`), it barely moves the input
        (:data:`~hystcomp.diagnose.record.QUIET`), or an initial state is named
        on a record that starts at an end of its input range
        (:data:`~hystcomp.diagnose.record.START_END`).  Each caution function
        holds its own bound and says "" within it."""
        out = [caution(self.held_out_beyond_fitted_range, short=short),
               quiet_caution(self.held_out_input_share, short=short)]
        if "initial_state" in self.effects:
            out.append(start_caution(self.start_in_input_range, short=short))
        return [c for c in out if c]

    def to_dict(self):
        """The JSON object of ``hystcomp diagnose --json`` (schema version 30; 5
        added ``held_out_beyond_fitted_range``, 6 ``held_out_moved``, 7
        ``held_out_blocks`` and ``other_split``, 8 ``rest``, 9
        ``held_out_moved_faster``, 10 ``explained_limit`` and the noise
        floor's ``relative_standard_error`` in ``noise_floor_method``, 11 the
        steps' ``held_out_loss_without_it_noise_variances`` in ``evidence``:
        when two or more effects were named, what the held-out mean square
        loses without each once the others are in; 12 ``holds_oscillate``
        in ``noise_floor_method``, 13 ``rms_heldout_pct``, 14 ``off_centre_of``
        in the ``evidence`` of an asymmetry step named from an off-centre
        saturating output map, whose ``rms_before`` is the held-out RMS with
        the map's centre held at the offset, 15 ``start_or_trend`` in the
        ``evidence`` of a step where a drift and an initial state gained
        alike held out and the training fit chose between them, 16
        ``finer_core``, 17 ``holds_carried_structure`` in
        ``noise_floor_method``, 18 ``gain_at_extremes`` ("falls" or "rises")
        in a present saturation signature's evidence and in
        ``final_signatures``, and ``instead_of_one_map`` in the ``evidence``
        of an asymmetry step that replaced a saturation and an asymmetry
        drawn by one off-centre saturating map, 19 ``pair_lead`` beside
        ``paired`` and ``small_later_step`` in a step's ``evidence``, 20
        ``held_out_input_share``, 21 ``start_in_input_range``, 22
        ``asymmetry_antisymmetric_share`` and ``input_balance``, 23
        ``core_shape`` and the steps' ``core_shape``, 24 ``creep_or_trend``
        in the ``evidence`` of a step where creep was taken over a drift on a
        near tie held out, 25 ``preisach_core``, 26 its ``taken``,
        ``lag1_autocorrelation`` and ``pi_remaining``; when taken, ``model``
        describes the KP core; 27 ``clipped`` and 30 ``final_high_frequency``
        in ``noise_floor_method``, 28 ``named_beyond_vocabulary`` and 29
        ``relaxation_per_step`` in a step's ``evidence``).

        Returns
        -------
        dict
        """
        steps = [{"effect": s["effect"], "rms_before": s["rms_before"], "rms_after": s["rms_after"],
                  "rms_before_pct": self._pct(s["rms_before"]), "rms_after_pct": self._pct(s["rms_after"]),
                  "evidence": s["evidence"], "dropped": bool(s.get("dropped", False)),
                  "tentative": bool(s.get("tentative", False)), "core_shape": bool(s.get("core_shape", False)),
                  "alternatives": list(s.get("alternatives", []))} for s in self.steps]
        return _jsonable({
            "schema_version": SCHEMA_VERSION, "verdict": self.verdict, "noise_floor": self.noise_floor,
            "noise_floor_pct": self._pct(self.noise_floor), "noise_floor_method": self.noise_info,
            "explained_limit": self.explained_limit,
            "effects": list(self.effects), "tentative_effects": list(self.tentative),
            "ambiguous": dict(self.ambiguous),
            "misfit_share_explained": self.misfit_share_explained, "rms_before": self.rms_before, "rms_after": self.rms_after,
            "rms_before_pct": self._pct(self.rms_before), "rms_after_pct": self._pct(self.rms_after),
            "rms_heldout": self.rms_heldout, "rms_heldout_pct": self._pct(self.rms_heldout),
            "output_span": self.output_span,
            "validation": list(self.validation), "held_out_blocks": [list(b) for b in self.held_out_blocks],
            "other_split": self.other_split, "rest": self.rest, "finer_core": self.finer_core,
            "preisach_core": self.preisach_core,
            "held_out_beyond_fitted_range": self.held_out_beyond_fitted_range,
            "held_out_moved": self.held_out_moved, "held_out_moved_faster": self.held_out_moved_faster,
            "held_out_input_share": self.held_out_input_share,
            "start_in_input_range": self.start_in_input_range,
            "asymmetry_antisymmetric_share": self.asymmetry_antisymmetric_share,
            "input_balance": self.input_balance, "core_shape": self.core_shape,
            "steps": steps, "untested": dict(self.untested),
            "stopped": self.stopped, "remaining": dict(self.remaining),
            "revisions": list(getattr(self, "revisions", [])),
            "model": self.model.describe(),
            "final_signatures": {k: {kk: v[kk] for kk in ("statistic", "threshold", "present", "testable",
                                                          "gain_at_extremes") if kk in v}
                                 for k, v in self.final_evidence.items()}})

    def to_json(self):
        """:meth:`to_dict` as a JSON string.

        Returns
        -------
        str
        """
        return json.dumps(self.to_dict())

    def report(self):
        """A readable report (str).

        Returns
        -------
        str
        """
        s = self.noise_floor
        plays = self.base_model._ctx.thresholds.size
        lines = [f"base model: PI with {plays} plays; held-out RMS {self.rms_before:.4g} "
                 f"({self._pct(self.rms_before):.3g} % of the output span), noise floor {s:.4g} "
                 + (f"({self._pct(s):.3g} %: the diagnosis's resolution, the record shows no noise above it)"
                    if self.noise_info["method"] == "resolution" else
                    f"({self._pct(s):.3g} %, from the {self.noise_info['method'].replace('_', '-')} part)")]
        hc = self.noise_info.get("holds_carried_structure")
        if hc is not None:
            lines.append(f"  noise floor: the output's scatter during the holds ({hc['scatter']:.4g}) was structure, "
                         f"not noise: a model left {hc['rms_heldout']:.4g} held out, below {HOLDS_CARRIED} of it")
        nc = self.noise_info.get("clipped")
        if nc:
            lines.append(f"  noise floor: {nc['samples']} samples ({100 * nc['share']:.3g} %) sit in runs of one "
                         "value at the output's largest or smallest, clipped (a converter at full scale, a stop): "
                         "they carry no noise and were left out of it; the held-out RMS still counts those in the "
                         "held-out part, where a model that clips leaves about 0, so it may read below the floor")
        if self.rest is not None and self.rest.get("other") is not None:
            lines.append("  rest: " + self.rest["why"])
        for name, why in self.untested.items():
            lines.append(f"  {name}: {why}")
        for i, st in enumerate(self.steps, 1):
            ext = st["evidence"]["extension"]
            sig = st["evidence"]["signature"]
            shape = ", read as the core's shape" if st.get("core_shape") else ""
            rv = st["evidence"].get("revised") or {}
            if rv.get("by") and rv["effect_after"] != rv["effect_before"]:
                # the line reads the step as it was taken; the revision's line below says what replaced it
                shape += f" (taken as {rv['effect_before']}, replaced in the revision)"
            lines.append(f"step {i}: {st['effect']}{shape} -- {ext['part']}; held-out RMS {st['rms_before']:.4g} -> "
                         f"{st['rms_after']:.4g} ({st['rms_after'] / s:.2f} x noise floor)")
            way = sig.get("relaxation_per_step")
            # creep's hold test is signed: which way the residual relaxed, on with the steps or back against them
            way = "" if way is None else (
                "; it relaxes on, with the step" if way > 0 else "; it relaxes back, against the step")
            lines.append(f"  signature: {sig['signature']}: {sig['statistic']:.3g} > {sig['threshold']:.3g}{way}")
            if st["evidence"].get("instead_of_one_map"):
                lines.append("  instead of " + st["evidence"]["instead_of_one_map"])
            if st["evidence"].get("paired"):
                # a pair's lead can raise the held-out RMS on its own: say so where the number is read
                lines.append("  " + st["evidence"]["paired"])
            if st["evidence"].get("small_later_step"):
                lines.append("  " + st["evidence"]["small_later_step"])
            if st.get("core_shape") and self.core_shape:
                lines.append("  the core's shape, not named: " + self.core_shape["why"])
            loss = st["evidence"].get("held_out_loss_without_it_noise_variances")
            if loss is not None:
                lines.append(f"  without it (the other effects refitted): the held-out mean square rises by "
                             f"{loss + 0.0:.3g} noise variances" + (" -- dropped at the revision" if st.get("dropped")
                                                               else ""))
            told = st["evidence"].get("start_or_trend") or {}
            for a in st.get("alternatives", []):
                head = (f"  near tie: {a['effect']} ({a['kind']}) lowers the held-out mean square by "
                        f"{a['held_out_gain_noise_variances']:.3g} noise variances against "
                        f"{a['named_gain_noise_variances']:.3g}")
                if a["kind"] == told.get("held_out_chose"):
                    bic = told["training_bic_change"]
                    lines.append(head + f"; the training part, which holds the record's start, takes {st['effect']} "
                                 f"(its BIC lower by {bic[a['kind']] - bic[told['taken']]:.0f})")
                elif a["kind"] == (st["evidence"].get("creep_or_trend") or {}).get("held_out_chose"):
                    lines.append(head + "; creep, which the input's steps draw (a drift draws from time alone), "
                                 "is taken on the near tie")
                else:
                    lines.append(head + ": the record does not tell them apart")
        for rv in getattr(self, "revisions", []):
            what = f"replaced by {rv['by']} ({rv['effect_after']})" if rv["by"] else "dropped"
            lines.append(f"revision: step {rv['step']}'s {rv['replaced']} {what}: held-out RMS {rv['rms_before']:.4g} "
                         f"-> {rv['rms_after']:.4g} ({rv['reason']})")
        fc = self.finer_core
        if fc is not None:
            lines.append(f"finer core ({fc['plays']} plays): held-out RMS {fc['rms_heldout']:.4g} "
                         f"({fc['noise_floors']:.3g} x noise floor)"
                         + ("; taken: what remained was the base model's grid of thresholds, not an effect"
                            if fc["taken"] else "; not taken" + (
                                f" (signatures present: {', '.join(fc['signatures_present'])})"
                                if fc["signatures_present"] else "")))
        for k, why in self.remaining.items():
            lines.append(f"  remains: {why}")
        pc = describe_preisach_core(self.preisach_core)
        if pc:
            lines.append("  " + pc)
            for k, why in (self.preisach_core.get("pi_remaining") or {}).items():
                lines.append(f"  with the PI core, remained: {why}")
        if self.held_out_moved > 0 or self.held_out_moved_faster > 0 or len(self.held_out_blocks) > 1:
            lines.append("  " + self._rec.held_out_line())
        if self.other_split is not None:
            o = self.other_split
            lines.append(f"  other split ({o['held_out']} held out): {o['verdict']}, effects "
                         f"{', '.join(o['effects']) or 'none'}, {o['noise_floors_left']:.2f} noise floors left; "
                         + ("this diagnosis is taken: " + o["why"] if o["held_out"] != "blocks" else o["why"]))
        lines += ["  caution: " + c for c in self._cautions()]
        tent = self.tentative
        named = [self._with_ties(e) for e in self.effects]
        lines.append(f"verdict: {self.verdict}; effects: {', '.join(named) or 'none'}"
                     + (f" (tentative, not named: {', '.join(tent)})" if tent else "")
                     + ("; core: PI with point-symmetric envelopes" if self.core_shape else "") + "; held-out RMS "
                     f"{self.rms_before:.4g} -> {self.rms_after:.4g}; stopped: {self.stopped}")
        return "\n".join(lines)

    summary = report

    def __repr__(self):
        return (f"Diagnosis(verdict={self.verdict!r}, effects={self.effects}, noise_floor={self.noise_floor:.4g}, "
                f"rms_before={self.rms_before:.4g}, rms_after={self.rms_after:.4g})")

    # -- figures
    def plots(self, input_unit=None, output_unit=None, *, input_name="input v",
              output_name="output y"):
        """Figures: ``signatures`` (the base residual in time, against the
        input and against the rate, the noise floor drawn; the rate axis
        holds the middle 99.8 % of the samples when a step in the input
        would squeeze the rest, and its label counts those beyond), ``loops``
        (held-out loops of the base and final model, every n-th cycle on long
        records), ``gap`` (the residual before and after each step with the
        noise floor; on a record left unexplained, a last panel with the
        residual of the Preisach-type core alone, :attr:`preisach_core`).

        Parameters
        ----------
        input_unit, output_unit : str or None
            Units of the input and output written on the axes in brackets
            (e.g. ``"V"``, ``"um"``); the record itself carries none. None
            (the default) writes no unit.
        input_name, output_name : str
            What the input and output are called on the axes (e.g. the CSV's
            column names ``"drive_V"``, ``"deflection_um"``).

        Returns
        -------
        dict of str -> matplotlib.figure.Figure
        """
        from ..plotting import new_figure

        for name, unit in (("input_unit", input_unit), ("output_unit", output_unit)):
            if unit is not None and not isinstance(unit, str):
                raise TypeError(f"Parameter {name} is {unit!r} but should be a string such as 'V' or None")
        for name, label in (("input_name", input_name), ("output_name", output_name)):
            if not isinstance(label, str) or not label.strip():
                raise TypeError(f"Parameter {name} is {label!r} but should be a non-empty string such as 'drive_V'")
        x_in, y_out = _axis(input_name, input_unit), _axis(output_name, output_unit)
        y_res = _axis("residual", output_unit)
        x_rate = _axis("input rate dv/dt" if input_name == "input v" else f"rate of {input_name}",
                       f"{input_unit}/s" if input_unit else "per s")
        rec = self._rec
        s = self.noise_floor
        xax = rec.t if rec.t is not None else np.arange(rec.n)
        xlabel = "time [s]" if rec.t is not None else "sample index"
        # measured minus model in the output's own sign (the parts fit the output times its sign)
        sgn = rec.output_sign
        e0 = sgn * (rec.y - self._base_pred)
        idx = np.linspace(0, rec.n - 1, min(rec.n, 5000)).astype(int)
        fig, ax = new_figure(2, 2, size=(12, 7.5))
        ax = ax.ravel()
        ax[0].plot(xax[idx], e0[idx], ".", ms=1.5, label="residual")
        for a in (ax[0], ax[1], ax[2]):
            a.axhspan(-s, s, color="C2", alpha=0.2, label="noise floor +-1 sigma")
        for k, j, _ in rec.holds:
            ax[0].axvspan(xax[k], xax[j - 1], color="0.85", zorder=0)
        _mark_held_out(ax[0], xax, rec)
        ax[0].set(xlabel=xlabel + " (grey: holds; dashed, orange: held-out part)", ylabel=y_res,
                  title="in time (drift, creep, initial state)")
        ax[0].legend(fontsize=7, loc="best", framealpha=0.6)
        up = rec.direction[idx] >= 0
        ax[1].plot(rec.v[idx][up], e0[idx][up], ".", ms=1.5, label="rising")
        ax[1].plot(rec.v[idx][~up], e0[idx][~up], ".", ms=1.5, label="falling")
        ax[1].set(xlabel=x_in, ylabel=y_res,
                  title="against input (asymmetry, saturation)")
        ax[1].legend(fontsize=7, loc="best", framealpha=0.6)
        if rec.dt is not None:
            ax[2].plot(rec.rate[idx], e0[idx], ".", ms=1.5)
            lo, hi, beyond = _rate_limits(rec.rate)
            note = ""
            if beyond:
                # a step in the input (one sample at thousands of V/s) would squeeze the
                # other samples into one column: the axis keeps 99.8 % of them
                ax[2].set_xlim(lo, hi)
                note = f"; {beyond} samples beyond the axis"
            ax[2].set(xlabel=x_rate + note, ylabel=y_res,
                      title="against rate (rate dependence, delay)")
        else:
            ax[2].text(0.5, 0.5, "no time axis: rate untested", ha="center", transform=ax[2].transAxes)
            ax[2].set(xlabel="-", ylabel=y_res, title="against rate")
        ax[3].axis("off")
        txt = "\n".join(f"{k}: {v['statistic']:.2f} (threshold {v['threshold']:.2f})" + _mark(k, v)
                        for k, v in self.first_evidence.items())
        ax[3].text(0, 1, "Signatures of the base residual (in noise floors)\n\n" + txt, va="top", fontsize=8,
                   family="monospace")
        fig.suptitle("Residual of the base PI model")
        out = {"signatures": fig}

        # loops on the held-out part, thinned to at most ~8 cycles on long records
        fig, ax = new_figure(1, 2, size=(13, 5))
        val = np.flatnonzero(~rec.train)
        turns = val[reversals(rec.v[val], max(REVERSAL * rec.span, 5.0 * rec.input_noise))]
        if turns.size > 16:
            step = int(math.ceil(turns.size / 16))
            sel = np.concatenate([np.arange(turns[j], turns[j + 1]) for j in range(0, turns.size - 1, step)])
            note = f" (every {_ordinal(step)} half-cycle)"
        else:
            sel, note = val, ""
        final = self._final_pred
        for a, pred, name in ((ax[0], self._base_pred, "base PI"), (ax[1], final, "final model")):
            # in the output's units, sign and level as measured
            a.plot(rec.v[sel], rec.measured[sel], ".", color="0.5", ms=1.5, label="measured")
            a.plot(rec.v[sel], rec.output_sign * (pred[sel] + rec.y_offset), ".", ms=1.5, label=name)
            rms = float(np.sqrt(np.mean((rec.y - pred)[val] ** 2)))
            a.set(xlabel=x_in, ylabel=y_out,
                  title=f"held-out loops{note}, {name}: RMS {rms:.3g}")
            a.legend(fontsize=8, loc="upper left", markerscale=4)
        fig.suptitle("Loops on the held-out part: " + self._final_name())
        out["loops"] = fig

        # residual before and after each step, noise floor drawn
        preds = list(self._step_preds)
        labels = ["base PI"]
        off = getattr(self, "_off_centre", None)
        for i, st in enumerate(self.steps):
            if st["evidence"].get("off_centre_of") and off is not None and off.get("held") is not None:
                # the panel before it: the same model with the map's centre held at the offset
                preds.insert(len(labels), off["held"].prediction)
                labels.append("the same model with the saturating output map's centre held at the offset")
            rv = st["evidence"].get("revised")
            if rv is not None and rv["by"] is not None:
                if rv["effect_after"] == rv["effect_before"]:
                    # another part of the same effect (an algebraic saturation map by a tanh map)
                    lab = f"+ {rv['effect_before']} ({rv['replaced']}, replaced by {rv['by']} in the revision)"
                else:
                    lab = f"+ {rv['effect_before']} (replaced by {rv['effect_after']} in the revision)"
            elif st["evidence"].get("off_centre_of"):
                # the model is unchanged: this panel is the final residual, the
                # saturating map's centre fitted instead of held at the offset
                lab = "+ asymmetry (the saturating output map's centre fitted off the offset)"
            else:
                lab = f"+ {st['effect']}" + (" (dropped in the revision)" if st.get("dropped") else "")
                if st.get("core_shape"):
                    lab = "+ point-symmetric envelopes (asymmetry fitted, read as the core's shape: not named)"
                if st["evidence"].get("paired") and st["evidence"]["pair_lead"]:
                    # the pair's lead alone may raise the held-out RMS; the next panel shows the pair
                    lab += f" (alone; {self.steps[i + 1]['effect']} is fitted jointly with it in the next panel)"
                elif st["evidence"].get("paired"):
                    lab += f" ({st['evidence']['paired']})"
                if st.get("alternatives"):
                    lab += f" (or {' or '.join(a['effect'] for a in st['alternatives'])}: near tie)"
            labels.append(lab + (" [tentative]" if st.get("tentative") else ""))
        finer = getattr(self, "finer_core", None)
        finer = finer if finer and finer["taken"] else None
        if len(preds) > len(labels) + (finer is not None):
            labels.append(f"final: {self._final_name()} (after revision)")
        if finer is not None:
            labels.append(f"final: {self._final_name()} with {finer['plays']} plays (the finer core)")
        last = len(preds) - 1     # the search's final model (a KP core's panel may follow)
        fh = self.noise_info.get("final_high_frequency")   # the verdict's floor, when lower (round 61)
        pc, kp = self.preisach_core, getattr(self, "_kp_pred", None)
        if pc is not None and kp is not None:
            # the rate-independent core of the Preisach type alone: evidence, or the model when taken
            preds.append(kp)
            if pc.get("taken"):
                labels.append(f"final: a Preisach-type core alone (KP, {pc['cells']} x {pc['cells']} cells), taken "
                              "as the model: it explains the record with no effect")
            else:
                labels.append(f"a Preisach-type core alone (KP, {pc['cells']} x {pc['cells']} cells; evidence, not "
                              "the model): " + ("explains the record" if pc["explains"] else "does not explain it"))
        fig, ax = new_figure(len(preds), 1, size=(11, 1.9 * len(preds) + 1.2))
        ax = np.atleast_1d(ax)
        # robust limits (isolated spikes, e.g. at a voltage step, do not squash the rest)
        ylim = max(4.0 * s, 1.3 * float(np.percentile(np.abs(rec.y - preds[0]), 99.5))) or 1.0
        for i, (a, p, lab) in enumerate(zip(ax, preds, labels)):
            e = rec.output_sign * (rec.y - p)
            rms = float(np.sqrt(np.mean(e[~rec.train] ** 2)))
            a.plot(xax[idx], e[idx], lw=0.6)
            a.axhspan(-s, s, color="C2", alpha=0.25)
            a.axhline(1.5 * s, color="C2", ls=":", lw=0.8)
            a.axhline(-1.5 * s, color="C2", ls=":", lw=0.8)
            _mark_held_out(a, xax, rec)
            a.set_ylim(-ylim, ylim)
            a.set_ylabel(y_res)
            on_final = (f"; {rms / fh:.2f} of the verdict's floor, {fh:.3g}, from its own residual"
                        if fh and i == last else "")
            head = f"{lab}: held-out RMS {rms:.3g} = {rms / s:.2f} noise floors"
            a.set_title(textwrap.fill(head + on_final, 150) if on_final else head, fontsize=9)
        ax[-1].set_xlabel(xlabel + " (green: noise floor +-sigma, dotted: 1.5 sigma; dashed, orange: held-out part)")
        title = f"verdict: {self.verdict}; stopped: {self.stopped}"
        title += "".join(". Caution: " + c for c in self._cautions(short=True))
        fig.suptitle(textwrap.fill(title, 110), fontsize=9)
        out["gap"] = fig
        return out

    def save_plots(self, folder, input_unit=None, output_unit=None, *, input_name="input v",
                   output_name="output y"):
        """Write the figures of :meth:`plots` as PNG files; returns their paths.

        Parameters
        ----------
        folder : str or path-like
            Directory for ``diagnose_signatures.png``, ``diagnose_loops.png``
            and ``diagnose_gap.png`` (created if missing).
        input_unit, output_unit : str or None
            Units written on the axes (see :meth:`plots`).
        input_name, output_name : str
            Names of the input and output on the axes (see :meth:`plots`).

        Returns
        -------
        list of str
            The paths written.
        """
        import matplotlib.pyplot as plt

        os.makedirs(folder, exist_ok=True)
        paths = []
        for name, fig in self.plots(input_unit, output_unit, input_name=input_name,
                                          output_name=output_name).items():
            p = os.path.join(folder, f"diagnose_{name}.png")
            fig.savefig(p, dpi=90)
            plt.close(fig)
            paths.append(p)
        return paths


def _axis(name, unit):
    """An axis label: the quantity's name and its unit in brackets (none when `unit` is None)."""
    return f"{name} [{unit}]" if unit else name


def _mark(name, ev):
    """What the signatures panel writes after a test's statistic: PRESENT, and why when the
    statistic alone does not say it (present through its pair's test; over its threshold but
    not counted, see the evidence's reading), or untested."""
    if not ev["testable"]:
        return "  untested"
    over = ev["statistic"] > ev["threshold"]
    if ev["present"]:
        return "  PRESENT" if over or name not in SHIFT_OR_LAG else f"  PRESENT (by {SHIFT_OR_LAG[name]}'s test)"
    return "  (not counted: see its reading)" if over else ""
