"""The cases of W. Ye's thesis as data: models, input signals, time vectors.

Each function returns a :class:`ThesisCase` holding what a section of the
thesis simulates, so that examples, tests and the ``hystcomp thesis``
command reproduce the same things:

* :func:`figure_2_1` -- Fig. 2.1, a typical hysteresis loop;
* :func:`section_3_4_3` -- table 3.1 / Figs. 3.13-3.16, the mGPI model with
  four envelope sets;
* :func:`section_3_5` -- Figs. 3.17-3.19 and eq. 29, PI vs GPI vs mGPI;
* :func:`section_4_1` -- Figs. 4.1-4.2 and eq. 35, the initial loading curve;
* :func:`section_5_2`, :func:`section_5_3`, :func:`section_5_4` -- the
  inverse compensation of chapter 5, with the printed inverse parameters in
  :data:`THESIS_TABLES`.

Sampling.  The thesis integrates with ode45 (maximum step 0.01 s); the
models here are rate independent, so the sampling only resolves the curves:
every case uses ``dt = 0.001`` s by default.

Discretisation.  Densities are discretised as the thesis does (eq. 49,
section 5.1): ``p_i = p(r_i) (r_i - r_{i-1})`` with ``r_0 = 0``
(:meth:`hystcomp.MGPI.from_density`).  Where the thesis gives no thresholds
(sections 3.4.3 and 3.5, Fig. 2.1) the cases use ``r_i = 0.5 i``,
``N = 20`` (R = 10, the R of section 3.5).
"""

from dataclasses import dataclass, field

import numpy as np

from .envelopes import Atanh, Identity, Linear, Tanh
from .models import GPI, MGPI, PI
from ._validation import as_count, as_float_array, as_scalar

__all__ = [
    "ThesisCase", "THESIS_TABLES", "DT", "time_vector", "density",
    "figure_2_1", "section_3_4_3", "section_3_5", "section_4_1",
    "section_5_2", "section_5_3", "section_5_4", "section_5",
    "loading_curve_deviation", "loading_curve_error_bound", "mgpi_bound",
    "mgpi_bound_limit", "compensation_errors", "SECTION_5",
]

#: Sampling step of every case (s).
DT = 0.001

#: The inverse parameters printed in the thesis: thresholds q_i (eq. 56)
#: and weights g(q_i) (eq. 58) for sections 5.2, 5.3 and 5.4, copied from the
#: thesis text.  Section 5.4 prints only the first 9 of the 20 weights.
THESIS_TABLES = {
    "5.2": {
        "q": (0.2500, 0.5610, 0.9314, 1.3598, 1.8447, 2.3848, 2.9787, 3.6251, 4.3226, 5.0700,
              5.8661, 6.7097, 7.5996, 8.5347, 9.5138, 10.5358, 11.5997, 12.7045, 13.8492, 15.0327),
        "g": (-0.1960, -0.1290, -0.0914, -0.0681, -0.0526, -0.0419, -0.0342, -0.0284, -0.0239,
              -0.0205, -0.0177, -0.0154, -0.0136, -0.0120, -0.0107, -0.0096, -0.0087, -0.0079,
              -0.0072, -0.0066),
    },
    "5.3": {
        "q": (0.7500, 1.6829, 2.7941, 4.0793, 5.5341, 7.1544, 8.9361, 10.8752, 12.9678, 15.2101,
              17.5984, 20.1292, 22.7989, 25.6040, 28.5413, 31.6074, 34.7992, 38.1136, 41.5476,
              45.0982),
        "g": (-0.1960, -0.1290, -0.0914, -0.0681, -0.0526, -0.0419, -0.0342, -0.0284, -0.0239,
              -0.0205, -0.0177, -0.0154, -0.0136, -0.0120, -0.0107, -0.0096, -0.0087, -0.0079,
              -0.0072, -0.0066),
    },
    "5.4": {
        "q": (0.0125, 0.0253, 0.0385, 0.0519, 0.0657, 0.0798, 0.0943, 0.1090, 0.1242, 0.1396,
              0.1554, 0.1716, 0.1881, 0.2050, 0.2223, 0.2399, 0.2580, 0.2764, 0.2952, 0.3144),
        "g": (-0.0243, -0.0231, -0.0218, -0.0207, -0.0195, -0.0184, -0.0173, -0.0162, -0.0152),
    },
}


@dataclass
class ThesisCase:
    """One simulated case of the thesis.

    Made by the section functions of this module; every parameter is kept
    as the attribute of the same name, and ``case.model`` is the single
    model of a one-model case.

    Parameters
    ----------
    section : str
        Section of the thesis ("3.5", "5.4", ...).
    caption : str
        The thesis's caption of the matching figure(s).
    t : ndarray
        Time vector (s).
    signal : ndarray
        The input of the case: the model input v(t) for chapters 2-4, the
        reference u(t) to compensate for chapter 5.
    models : dict of str to model
        The model(s) of the case, by name.
    notes : str
        Choices the thesis leaves open and how the case fills them.
    extra : dict
        Other data of the case (e.g. the analytic loading curve).

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> t = time_vector(1.0, 0.5)
    >>> case = ThesisCase("2.1", "a loop", t, np.sin(t), {"PI": PI([1.0], [0.5], p0=1.0)})
    >>> case.model
    PI(N=1, p0=1.0)
    >>> section_3_5(dt=0.01).model
    Traceback (most recent call last):
    ...
    ValueError: Case 3.5 has 3 models (PI, GPI, mGPI); pick one from .models
    """

    section: str
    caption: str
    t: np.ndarray
    signal: np.ndarray
    models: dict
    notes: str = ""
    extra: dict = field(default_factory=dict)

    @property
    def model(self):
        """The single model of the case (error if it has several)."""
        if len(self.models) != 1:
            raise ValueError(
                f"Case {self.section} has {len(self.models)} models ({', '.join(self.models)}); "
                "pick one from .models"
            )
        return next(iter(self.models.values()))


def time_vector(t_end=10.0, dt=DT):
    """Sample times 0, dt, ..., t_end (the thesis's t in [0, 10]).

    Parameters
    ----------
    t_end : float, optional
        Last time in seconds (default 10), rounded to a multiple of `dt`.
    dt : float, optional
        Step in seconds, > 0 (default :data:`DT`).

    Returns
    -------
    ndarray

    Examples
    --------
    >>> t = time_vector(1.0, 0.25)
    >>> t.tolist()
    [0.0, 0.25, 0.5, 0.75, 1.0]
    """
    dt = as_scalar(dt, "dt", positive=True)
    t_end = as_scalar(t_end, "t_end", nonnegative=True)
    n = int(round(t_end / dt))
    return np.linspace(0.0, n * dt, n + 1)


def density(r):
    """The density of every case of the thesis, p(r) = e^{-0.1 r}.

    Parameters
    ----------
    r : float or array_like
        Thresholds.

    Returns
    -------
    ndarray
        p(r), of `r`'s shape (0-d for a scalar).

    Examples
    --------
    >>> round(float(density(10.0)), 6)
    0.367879
    """
    r = as_float_array(r, "r")
    if not np.all(np.isfinite(r)):
        raise ValueError("Parameter r holds NaN or inf; expected finite thresholds")
    return np.exp(-0.1 * r)


def _thresholds(spacing, n):
    return spacing * np.arange(1, n + 1)


def _grid(spacing, R):
    """spacing > 0, R >= spacing: the number of thresholds ``round(R / spacing)``."""
    spacing = as_scalar(spacing, "spacing", positive=True)
    R = as_scalar(R, "R", positive=True)
    if R < spacing:
        raise ValueError(f"Parameter R is {R} but should be >= spacing = {spacing} (at least one threshold)")
    return spacing, R, int(round(R / spacing))


def figure_2_1(dt=DT):
    """Fig. 2.1: a typical hysteresis loop, input ``10 sin(2 pi t)/(1 + 0.1 t)``.

    The thesis does not say which model drew Fig. 2.1; the case uses the PI
    model of eq. 34 (p0 = 1, p(r) = e^{-0.1 r}) with r_i = 0.5 i, N = 20.
    The loop shows the multivalued output, the wiping-out property and
    congruent minor loops.

    Parameters
    ----------
    dt : float, optional
        Sampling step in seconds (default :data:`DT`).

    Examples
    --------
    >>> case = figure_2_1(dt=0.01)
    >>> case.t.size, round(float(case.signal.max()), 3)
    (1001, 9.756)
    """
    t = time_vector(10.0, dt)
    v = 10.0 * np.sin(2 * np.pi * t) / (1.0 + 0.1 * t)
    model = PI.from_density(density, _thresholds(0.5, 20), p0=1.0)
    return ThesisCase(
        "2.1",
        "Figure 2.1: A typical hysteresis behavior under input v(t) = 10sin(2 pi t)/(1 + 0.1t), "
        "t in [0, 10], with properties of multivalued, wiping out, and congruent minor loop",
        t, v, {"PI": model},
        notes="Model not given by the thesis: PI of eq. 34 with r_i = 0.5 i, N = 20.",
    )


#: Envelope sets of table 3.1 (section 3.4.3): (figure, label, gl, gr).
_TABLE_3_1 = {
    1: ("3.13", "gl = gr = v", Identity(), Identity()),
    2: ("3.14", "gl = gr = 3v", Linear(3.0), Linear(3.0)),
    3: ("3.15", "gl = gr = tanh(0.5v)", Tanh(1.0, 0.5), Tanh(1.0, 0.5)),
    4: ("3.16", "gl = 20tanh(0.1v + 0.2), gr = 20tanh(0.2v + 0.1)",
        Tanh(20.0, 0.1, 0.2), Tanh(20.0, 0.2, 0.1)),
}


def section_3_4_3(envelope_set, dt=DT):
    """Section 3.4.3, table 3.1: the mGPI model (eq. 25) with four envelope sets.

    Input ``v(t) = 6 sin(pi t) + 4 cos(3.3 pi t)``, t in [0, 10], p0 = 1,
    p(r) = e^{-0.1 r}; the thesis gives no thresholds: r_i = 0.5 i, N = 20.

    Parameters
    ----------
    envelope_set : {1, 2, 3, 4}
        Row of table 3.1: 1 gl = gr = v (Fig. 3.13), 2 gl = gr = 3v
        (Fig. 3.14), 3 gl = gr = tanh(0.5 v) (Fig. 3.15), 4 gl = 20 tanh(0.1 v
        + 0.2) and gr = 20 tanh(0.2 v + 0.1) (Fig. 3.16, asymmetric).
    dt : float, optional
        Sampling step (s).

    Notes
    -----
    Set 4 has gl(0) != 0 and gr(0) != 0: the r = 0 operator then has memory
    and the virgin output is not 0 at v = 0.  The thesis's summary (section
    3.6) calls the set-3 envelope "bounded between +-5", which fits
    5 tanh(0.5 v); table 3.1 prints tanh(0.5 v), which is used here.

    Examples
    --------
    >>> case = section_3_4_3(4, dt=0.01)
    >>> case.model.symmetric
    False
    """
    if envelope_set not in _TABLE_3_1:
        raise ValueError(
            f"Parameter envelope_set is {envelope_set!r} but should be one of 1, 2, 3, 4 "
            "(the rows of table 3.1)"
        )
    fig, label, gl, gr = _TABLE_3_1[envelope_set]
    t = time_vector(10.0, dt)
    v = 6.0 * np.sin(np.pi * t) + 4.0 * np.cos(3.3 * np.pi * t)
    env = {"envelope": gl} if gl == gr else {"envelope_left": gl, "envelope_right": gr}
    model = MGPI.from_density(density, _thresholds(0.5, 20), p0=1.0, **env)
    return ThesisCase(
        "3.4.3",
        f"Figure {fig}: Examples with {label}",
        t, v, {"mGPI": model},
        notes="Thresholds not given by the thesis: r_i = 0.5 i, N = 20.",
        extra={"figure": fig, "label": label},
    )


def section_3_5(dt=DT):
    """Section 3.5, Figs. 3.17-3.19: PI (eq. 26), GPI (eq. 27) and mGPI (eq. 28).

    R = 10, p0 = 1, p(r) = e^{-0.1 r}, r_i = 0.5 i, N = 20, input
    ``v(t) = 10 sin(2 pi t) + t``, t in [0, 10].  GPI and mGPI use
    gl(v) = 10 tanh(0.2 v) and gr(v) = 10 tanh(0.1 v) (the thesis writes them
    as functions of r; they are functions of the input v).

    The thesis does not give the GPI's memoryless term H: the case uses
    H(v) = p0 v (the PI model's term), so the three models differ only in
    their operators.

    Parameters
    ----------
    dt : float, optional
        Sampling step in seconds (default :data:`DT`).

    Examples
    --------
    >>> case = section_3_5(dt=0.01)
    >>> sorted(case.models)
    ['GPI', 'PI', 'mGPI']
    """
    t = time_vector(10.0, dt)
    v = 10.0 * np.sin(2 * np.pi * t) + t
    r = _thresholds(0.5, 20)
    p0 = 1.0
    gl, gr = Tanh(10.0, 0.2), Tanh(10.0, 0.1)
    pi = PI.from_density(density, r, p0=p0)
    gpi = GPI(r, pi.weights, gl, gr, H=p0)
    mgpi = MGPI.from_density(density, r, p0=p0, envelope_left=gl, envelope_right=gr)
    return ThesisCase(
        "3.5",
        "Figures 3.17-3.19: PI, GPI and mGPI models, v(t) = 10sin(2 pi t) + t",
        t, v, {"PI": pi, "GPI": gpi, "mGPI": mgpi},
        notes="GPI memoryless term chosen as H(v) = p0 v (not given by the thesis).",
        extra={"shown_thresholds": (2.0, 4.0, 6.0, 8.0, 10.0), "U": 10.0, "R": 10.0},
    )


def section_4_1(spacing=0.05, R=10.0, dt=DT):
    """Section 4.1, eqs. 34-35, Figs. 4.1-4.2: the initial loading curve of a PI model.

    ``w = v + int_0^R e^{-0.1 r} F_r[v] dr`` (eq. 34) under
    ``v(t) = 10 sin(2 pi t)/(1 + 0.1 t)``; its loading curve is
    ``phi(r) = 11 r - 100 + 100 e^{-0.1 r}`` (eq. 35) for r <= R.

    The integral is discretised on the fine grid ``r_i = spacing * i`` up to
    R (R = 10 covers the input's range, so no operator beyond R would move
    on the loading curve); the discrete curve lies below eq. 35 by at most
    ``spacing * r`` (:func:`loading_curve_error_bound`).

    Parameters
    ----------
    spacing : float, optional
        Threshold step h of the discretised density (default 0.05).
    R : float, optional
        Largest threshold (default 10).
    dt : float, optional
        Sampling step in seconds (default :data:`DT`).

    Examples
    --------
    >>> case = section_4_1(dt=0.01)
    >>> case.model.n_operators
    200
    >>> round(float(case.extra["phi"](10.0)), 4)
    46.7879
    """
    spacing, R, n = _grid(spacing, R)
    t = time_vector(10.0, dt)
    v = 10.0 * np.sin(2 * np.pi * t) / (1.0 + 0.1 * t)
    model = PI.from_density(density, _thresholds(spacing, n), p0=1.0)
    return ThesisCase(
        "4.1",
        "Figure 4.1: input-output relation of (34) with v(t) = 10sin(2 pi t)/(1+0.1t); "
        "Figure 4.2: The simulated and the derived loading curve",
        t, v, {"PI": model},
        notes=f"Density discretised with r_i = {spacing} i, i = 1..{n} (R = {R}).",
        extra={"phi": lambda r: 11.0 * np.asarray(r) - 100.0 + 100.0 * np.exp(-0.1 * np.asarray(r)),
               "spacing": spacing, "R": R},
    )


def loading_curve_deviation(case, n_points=2001):
    """Max ``|phi_N(r) - phi(r)|`` over r in [0, R] for a :func:`section_4_1` case.

    phi_N is the discretised model's loading curve, phi eq. 35.

    Parameters
    ----------
    case : ThesisCase
        A case made by :func:`section_4_1`.
    n_points : int, optional
        Number of points r on [0, R] (default 2001).

    Returns
    -------
    float

    Examples
    --------
    >>> dev = loading_curve_deviation(section_4_1(dt=0.01))
    >>> bool(0.0 < dev <= loading_curve_error_bound(0.05, 10.0))
    True
    """
    if not isinstance(case, ThesisCase) or "phi" not in case.extra:
        raise TypeError(f"Parameter case is {case!r} but should be a ThesisCase made by section_4_1")
    r = np.linspace(0.0, case.extra["R"], as_count(n_points, "n_points", 2))
    return float(np.max(np.abs(case.model.loading_curve(r) - case.extra["phi"](r))))


def loading_curve_error_bound(spacing, r):
    """Bound of eq. 35 minus the discretised loading curve: ``spacing * r``.

    With f(theta) = e^{-0.1 theta}(r - theta), decreasing on [0, r], the
    discrete curve is ``r + sum_{r_i < r} h f(r_i)`` (a right Riemann sum with
    step h), and ``0 <= int_0^r f - sum h f(r_i) <= h f(0) = h r``.

    Parameters
    ----------
    spacing : float
        Threshold step h.
    r : float
        End of the loading curve.

    Returns
    -------
    float

    Examples
    --------
    >>> loading_curve_error_bound(0.05, 10.0)
    0.5
    """
    return float(as_scalar(spacing, "spacing", positive=True) * as_scalar(r, "r", nonnegative=True))


def mgpi_bound(spacing=0.5, R=10.0, U=10.0, p0=1.0):
    """Eq. 29 for the discretised mGPI of section 3.5: ``U (p0 + sum_i p_i)``.

    Parameters
    ----------
    spacing : float, optional
        Threshold step (default 0.5, r_i = 0.5 i).
    R : float, optional
        Largest threshold (default 10).
    U : float, optional
        Supremum of the envelopes (default 10, from 10 tanh(.)).
    p0 : float, optional
        Weight of the r = 0 operator (default 1).

    Returns
    -------
    float

    Examples
    --------
    >>> round(mgpi_bound(), 4)
    71.6449
    """
    spacing, R, n = _grid(spacing, R)
    U, p0 = as_scalar(U, "U"), as_scalar(p0, "p0")
    return float(U * (p0 + np.sum(density(_thresholds(spacing, n)) * spacing)))


def mgpi_bound_limit(R=10.0, U=10.0, p0=1.0):
    """Eq. 29 with the integral: ``U (p0 + 10 - 10 e^{-R/10})`` (73.21 for R = 10).

    The limit of :func:`mgpi_bound` as the threshold step goes to 0.

    Parameters
    ----------
    R : float, optional
        Upper limit of the density's integral (default 10).
    U : float, optional
        Supremum of the envelopes (default 10).
    p0 : float, optional
        Weight of the r = 0 operator (default 1).

    Returns
    -------
    float

    Examples
    --------
    >>> round(mgpi_bound_limit(), 4)
    73.2121
    """
    R = as_scalar(R, "R", nonnegative=True)
    U, p0 = as_scalar(U, "U"), as_scalar(p0, "p0")
    return float(U * (p0 + 10.0 - 10.0 * np.exp(-0.1 * R)))


_SECTION_5 = {
    "5.2": (0.25, Identity(), 5.0, "5.3", "gamma[v] = v"),
    "5.3": (0.25, Linear(3.0), 5.0, "5.4", "gamma[v] = 3v"),
    "5.4": (0.025, Atanh(1.0, 0.5), 0.5, "5.6", "gamma[v] = tanh^-1[0.5v]"),
}

#: The sections of chapter 5 reproduced by :func:`section_5`.
SECTION_5 = tuple(_SECTION_5)


def section_5(name, dt=DT):
    """Chapter 5: the mGPI model to compensate and the reference u(t).

    p0 = 1, p(r) = e^{-0.1 r}, N = 20, ``u(t) = A sin(2 pi t)/(1 + 0.1 t)``,
    t in [0, 10]:

    * "5.2": r_i = 0.25 i, gamma = v, A = 5 (Fig. 5.3);
    * "5.3": r_i = 0.25 i, gamma = 3 v, A = 5 (Fig. 5.4);
    * "5.4": r_i = 0.025 i, gamma = atanh(0.5 v), A = 0.5 (Fig. 5.6).

    The printed inverse parameters are in ``THESIS_TABLES[name]``.

    Parameters
    ----------
    name : {"5.2", "5.3", "5.4"}
        The section (see :data:`SECTION_5`).
    dt : float, optional
        Sampling step in seconds (default :data:`DT`).

    Examples
    --------
    >>> case = section_5("5.4", dt=0.01)
    >>> case.model.envelope
    Atanh(a=1.0, b=0.5)
    """
    if name not in _SECTION_5:
        raise ValueError(f"Parameter name is {name!r} but should be one of {', '.join(_SECTION_5)}")
    spacing, env, amp, fig, label = _SECTION_5[name]
    t = time_vector(10.0, dt)
    u = amp * np.sin(2 * np.pi * t) / (1.0 + 0.1 * t)
    model = MGPI.from_density(density, _thresholds(spacing, 20), p0=1.0, envelope=env)
    amp_txt = f"{amp:g}"
    return ThesisCase(
        name,
        f"Figure {fig}: Simulation Results with {label}, and u(t) = {amp_txt}sin(2 pi t)/(1+0.1t)",
        t, u, {"mGPI": model},
        extra={"table": THESIS_TABLES[name], "figure": fig},
    )


def section_5_2(dt=DT):
    """Section 5.2 (Fig. 5.3): identity envelope, r_i = 0.25 i; see :func:`section_5`.

    Parameters
    ----------
    dt : float, optional
        Sampling step in seconds (default :data:`DT`).

    Examples
    --------
    >>> section_5_2(dt=0.01).section
    '5.2'
    """
    return section_5("5.2", dt)


def section_5_3(dt=DT):
    """Section 5.3 (Fig. 5.4): gamma = 3v, r_i = 0.25 i; see :func:`section_5`.

    Parameters
    ----------
    dt : float, optional
        Sampling step in seconds (default :data:`DT`).

    Examples
    --------
    >>> section_5_3(dt=0.01).model.envelope
    Linear(k=3.0)
    """
    return section_5("5.3", dt)


def section_5_4(dt=DT):
    """Section 5.4 (Fig. 5.6): gamma = atanh(0.5 v), r_i = 0.025 i; see :func:`section_5`.

    Parameters
    ----------
    dt : float, optional
        Sampling step in seconds (default :data:`DT`).

    Examples
    --------
    >>> float(section_5_4(dt=0.01).model.thresholds[-1])
    0.5
    """
    return section_5("5.4", dt)


def compensation_errors(dt=DT, progress=False):
    """Tracking errors of the analytic inverse (eqs. 54-58) and of the exact
    inverse for sections 5.2-5.4: ``model(inverse(u)) - u``.

    Parameters
    ----------
    dt : float, optional
        Sampling step in seconds (default :data:`DT`).
    progress : bool, optional
        A progress bar (tqdm) on stderr, shown only on a terminal
        (default False).

    Returns
    -------
    list of dict
        One row per (section, inverse) with keys ``section``, ``inverse``
        ("analytic" or "exact"), ``rms``, ``max``, ``rms_percent``,
        ``max_percent`` (of the reference span) and ``span``.

    Examples
    --------
    >>> rows = compensation_errors(dt=0.05)
    >>> [(r["section"], r["inverse"]) for r in rows][:2]
    [('5.2', 'analytic'), ('5.2', 'exact')]
    """
    from ._progress import progress_bar
    from .inverses import tracking_error

    rows = []
    for name in progress_bar(SECTION_5, desc="section 5 errors", enabled=progress, unit="case"):
        case = section_5(name, dt)
        model = case.model
        for kind, comp in (("analytic", model.inverse()), ("exact", model.exact_inverse())):
            err = tracking_error(model, comp, case.signal)
            rows.append({"section": name, "inverse": kind,
                         **{k: float(err[k]) for k in ("rms", "max", "rms_percent", "max_percent", "span")}})
    return rows
