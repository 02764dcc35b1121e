"""Figures for hysteresis models (matplotlib, no pyplot state).

Helpers build :class:`matplotlib.figure.Figure` objects directly, so they
work under any backend (no window opens) and the caller saves them with
``fig.savefig(path)``:

* :func:`plot_loop` -- input-output loop(s) w against v;
* :func:`plot_operators` -- operator outputs against the input;
* :func:`plot_compensation` -- u, v = inverse(u) and w = model(v) in time;
* :func:`plot_loading_curve` -- simulated vs analytic loading curve;
* :func:`thesis_figures` -- every figure of the thesis reproduction.

The thesis's cases carry no physical units, so the default axis labels say
"[a.u.]" (arbitrary units, the same for input and output); pass your own
labels (``xlabel="voltage [V]"``) for measured data.
"""

import textwrap

import numpy as np
from matplotlib.figure import Figure

from ._validation import as_count, as_float_array, as_pair, as_signal

__all__ = [
    "new_figure", "plot_loop", "plot_operators", "plot_compensation",
    "plot_loading_curve", "thesis_figures",
]


def _wrap(text, width=80):
    """Wrap a (long thesis) caption over several lines, keeping its breaks."""
    return "\n".join(textwrap.fill(line, width) for line in str(text).split("\n"))


def _curve(x, name, n=None, other=None):
    """A 1-D float array to plot (NaN allowed: matplotlib leaves a gap), of
    length `n` when given (that of `other`)."""
    a = as_float_array(x, name)
    if a.ndim == 0:
        a = a.reshape(1)
    if a.ndim != 1:
        raise ValueError(f"Parameter {name} has shape {a.shape} but should be a 1-D array of samples")
    if n is not None and a.size != n:
        raise ValueError(f"Parameter {name} has {a.size} samples but {other} has {n}; expected the same length")
    return a


def _axes(ax):
    if ax is not None and not callable(getattr(ax, "plot", None)):
        raise TypeError(f"Parameter ax is {ax!r} but should be a matplotlib Axes or None")


def new_figure(nrows=1, ncols=1, size=(6.4, 4.8)):
    """A figure with a grid of axes, detached from pyplot.

    Parameters
    ----------
    nrows, ncols : int, optional
        Rows and columns of the grid (default 1 by 1).
    size : (float, float), optional
        Figure width and height in inches (default (6.4, 4.8)).

    Returns
    -------
    fig : Figure
    axes : ndarray of Axes, shape (nrows, ncols), squeezed

    Examples
    --------
    >>> fig, axes = new_figure(1, 2)
    >>> len(fig.axes)
    2
    """
    nrows, ncols = as_count(nrows, "nrows", 1), as_count(ncols, "ncols", 1)
    w, h = as_pair(size, "size", increasing=False)
    if w <= 0 or h <= 0:
        raise ValueError(f"Parameter size is {size!r} but should be (width, height) in inches, both > 0")
    fig = Figure(figsize=(w, h), layout="constrained")
    axes = fig.subplots(nrows, ncols, squeeze=True)
    return fig, axes


def plot_loop(v, w, ax=None, label=None, title=None, xlabel="input v [a.u.]", ylabel="output w [a.u.]", **kw):
    """Plot the input-output loop w(v).

    Parameters
    ----------
    v, w : array_like, shape (n,)
        Input and output samples.
    ax : Axes, optional
        Where to draw; default a new figure.
    label, title, xlabel, ylabel : str, optional
        Legend label, axes title and axis labels.
    **kw
        Passed to ``ax.plot``.

    Returns
    -------
    Axes

    Examples
    --------
    >>> import numpy as np
    >>> ax = plot_loop(np.sin(np.linspace(0, 6, 50)), np.cos(np.linspace(0, 6, 50)), title="loop")
    >>> ax.get_title()
    'loop'
    """
    v = _curve(v, "v")
    w = _curve(w, "w", v.size, "v")
    _axes(ax)
    if ax is None:
        _, ax = new_figure()
    ax.plot(v, w, label=label, lw=kw.pop("lw", 0.9), **kw)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(_wrap(title), fontsize=9)
    ax.grid(True, alpha=0.3)
    if label:
        ax.legend(fontsize=8)
    return ax


def plot_operators(v, W, thresholds, ax=None, select=None, title=None, name="r"):
    """Plot operator outputs against the input, one curve per threshold.

    Parameters
    ----------
    v : array_like, shape (n,)
        Input samples.
    W : array_like, shape (n, M)
        Operator outputs, column j for ``thresholds[j]``.
    thresholds : array_like, shape (M,)
        Threshold of each column.
    ax : Axes, optional
        Where to draw; default a new figure.
    select : sequence of float, optional
        Thresholds to show (nearest columns); default all.
    title : str, optional
        Axes title (long ones are wrapped).
    name : str, optional
        Symbol of the threshold in the legend.

    Returns
    -------
    Axes

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp.operators import play
    >>> v = 5 * np.sin(np.linspace(0, 12, 300))
    >>> W, _ = play(v, [1.0, 2.0, 3.0])
    >>> ax = plot_operators(v, W, [1.0, 2.0, 3.0], select=[1.0, 3.0])
    >>> [text.get_text() for text in ax.get_legend().get_texts()]
    ['r = 1', 'r = 3']
    """
    v = _curve(v, "v")
    W = as_float_array(W, "W")
    r = as_signal(thresholds, "thresholds")
    _axes(ax)
    if select is not None:
        select = as_signal(select, "select")
        if np.any((select < r.min() - 1e-12) | (select > r.max() + 1e-12)):
            raise ValueError(f"Parameter select is {select.tolist()} but should hold thresholds within "
                             f"[{r.min()}, {r.max()}] (the nearest column is drawn)")
    if W.ndim != 2 or W.shape != (v.size, r.size):
        raise ValueError(
            f"Parameter W has shape {W.shape} but should be (len(v), len(thresholds)) = ({v.size}, {r.size}) "
            "(samples x thresholds)"
        )
    if ax is None:
        _, ax = new_figure()
    cols = range(r.size) if select is None else [int(np.argmin(np.abs(r - s))) for s in select]
    for j in cols:
        ax.plot(v, W[:, j], lw=0.9, label=f"{name} = {r[j]:g}")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("input v [a.u.]")
    ax.set_ylabel("operator output [a.u.]")
    if title:
        ax.set_title(_wrap(title), fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))  # beside the curves
    return ax


def plot_compensation(t, u, v, w, title=None, error_label=None):
    """Inverse compensation in time: reference u, compensator output v and
    model output w (top), and the tracking error w - u (bottom).

    Parameters
    ----------
    t : array_like, shape (n,)
        Times.
    u : array_like, shape (n,)
        Reference (desired output).
    v : array_like, shape (n,)
        Compensator output, the model's input.
    w : array_like, shape (n,)
        Model output.
    title : str, optional
        Title of the top panel (long ones are wrapped).
    error_label : str, optional
        Title of the error panel; default "tracking error".

    Returns
    -------
    Figure

    Examples
    --------
    >>> import numpy as np
    >>> t = np.linspace(0, 1, 20)
    >>> fig = plot_compensation(t, t, 0.5 * t, t, title="demo")
    >>> fig.axes[0].get_title()
    'demo'
    """
    t = _curve(t, "t")
    u, v, w = (_curve(a, name, t.size, "t") for a, name in ((u, "u"), (v, "v"), (w, "w")))
    fig, (a1, a2) = new_figure(2, 1, size=(8.5, 6.0))
    a1.plot(t, u, lw=1.6, label="u(t) reference")
    a1.plot(t, v, lw=0.9, label="v(t) = inverse[u](t)")
    a1.plot(t, w, "--", lw=0.9, label="w(t) = model[v](t)")
    a1.set_xlabel("time t [s]")
    a1.set_ylabel("u, v, w [a.u.]")
    a1.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    a1.grid(True, alpha=0.3)
    if title:
        a1.set_title(_wrap(title, 100), fontsize=9)
    a2.plot(t, w - u, lw=0.8, color="C3")
    a2.set_xlabel("time t [s]")
    a2.set_ylabel("error w - u [a.u.]")
    a2.set_title(error_label or "tracking error", fontsize=9)
    a2.grid(True, alpha=0.3)
    return fig


def plot_loading_curve(r, simulated, analytic, ax=None, title=None):
    """Simulated loading curve (markers) over the analytic one (line).

    Parameters
    ----------
    r : array_like, shape (n,)
        Inputs at which both curves are given.
    simulated : array_like, shape (n,)
        Loading curve from a simulation (markers).
    analytic : array_like, shape (n,)
        Loading curve from its formula (line, e.g. eq. 35).
    ax : Axes, optional
        Where to draw; default a new figure.
    title : str, optional
        Axes title (long ones are wrapped).

    Returns
    -------
    Axes

    Examples
    --------
    >>> import numpy as np
    >>> r = np.linspace(0, 1, 5)
    >>> ax = plot_loading_curve(r, r, r, title="phi")
    >>> ax.get_title()
    'phi'
    """
    r = _curve(r, "r")
    simulated = _curve(simulated, "simulated", r.size, "r")
    analytic = _curve(analytic, "analytic", r.size, "r")
    _axes(ax)
    if ax is None:
        _, ax = new_figure()
    ax.plot(r, analytic, lw=1.5, label="derived, eq. 35")
    ax.plot(r, simulated, "o", ms=3, mfc="none", label="simulated")
    ax.set_xlabel("input r [a.u.]")
    ax.set_ylabel("loading curve phi(r) [a.u.]")
    if title:
        ax.set_title(_wrap(title), fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return ax


# --- the thesis's figures ---------------------------------------------------

def figure_2_1(case):
    """Fig. 2.1 from :func:`hystcomp.thesis.figure_2_1`: one Figure."""
    fig, ax = new_figure(size=(6.0, 4.8))
    plot_loop(case.signal, case.model.simulate(case.signal), ax=ax, title=case.caption)
    return fig


def figure_3_4_3(case):
    """Table 3.1 row from :func:`hystcomp.thesis.section_3_4_3`: (a) the
    mGPI loop, (b) the modified generalized play operators r = 2, 4, 6, 8, 10."""
    model = case.model
    v = case.signal
    fig, (a1, a2) = new_figure(1, 2, size=(10.0, 4.4))
    plot_loop(v, model.simulate(v), ax=a1, title="(a) input-output relationship of the mGPI model")
    W = model.operator_responses(v)
    r_all = np.concatenate([[0.0], model.thresholds])
    plot_operators(v, W, r_all, ax=a2, select=(2.0, 4.0, 6.0, 8.0, 10.0),
                   title="(b) modified generalized play operator")
    fig.suptitle(_wrap(case.caption, 110), fontsize=10)
    return fig


def figure_3_5(case):
    """Figs. 3.17-3.19 from :func:`hystcomp.thesis.section_3_5`: one figure,
    a row per model, (a) loop and (b) operators r = 2, 4, 6, 8, 10."""
    from .operators import generalized_play, play

    v = case.signal
    shown = np.asarray(case.extra["shown_thresholds"])
    pi, gpi, mgpi = (case.models[k] for k in ("PI", "GPI", "mGPI"))
    fig, axes = new_figure(3, 2, size=(10.0, 11.0))
    rows = (
        ("Figure 3.17: PI Model", pi, play(v, shown)[0]),
        ("Figure 3.18: GPI Model", gpi,
         generalized_play(v, shown, gpi.envelope_left, gpi.envelope_right)[0]),
        ("Figure 3.19: mGPI Model", mgpi, None),
    )
    for (cap, model, W), (a1, a2) in zip(rows, axes):
        w = model.simulate(v)
        plot_loop(v, w, ax=a1, title=f"{cap} (a) Input-output relationship")
        if W is None:
            W_all = model.operator_responses(v)
            cols = [int(np.argmin(np.abs(model.thresholds - s))) + 1 for s in shown]
            W = W_all[:, cols]
        plot_operators(v, W, shown, ax=a2, title=f"{cap} (b) Operators behaviors")
    bound = mgpi.output_bounds()[1]
    axes[2, 0].axhline(bound, color="C3", ls=":", lw=1.0, label=f"output_bounds() = {bound:.2f}")
    axes[2, 0].legend(fontsize=8)
    return fig


def figure_4_1(case, n_points=41):
    """Figs. 4.1 (loop of eq. 34) and 4.2 (simulated vs derived loading curve)
    from :func:`hystcomp.thesis.section_4_1`: one Figure with two axes."""
    model = case.model
    v = case.signal
    fig, (a1, a2) = new_figure(1, 2, size=(10.0, 4.4))
    plot_loop(v, model.simulate(v), ax=a1,
              title="Figure 4.1: input-output relation of (34)\nwith v(t) = 10sin(2 pi t)/(1+0.1t), t in [0, 10]")
    r = np.linspace(0.0, case.extra["R"], n_points)
    ramp = np.linspace(0.0, case.extra["R"], 2001)
    sim = np.interp(r, ramp, model.simulate(ramp))
    from .thesis import loading_curve_deviation

    dev = loading_curve_deviation(case)
    plot_loading_curve(r, sim, case.extra["phi"](r), ax=a2,
                       title=("Figure 4.2: The simulated and the derived loading curve\n"
                              f"(N = {model.n_operators} operators: max |deviation| = {dev:.3f})"))
    return fig


def figure_5(case, analytic=True):
    """Figs. 5.3/5.4/5.6 from :func:`hystcomp.thesis.section_5`: u, v =
    inverse(u), w = model(v) and the error, for the analytic inverse
    (default) or the exact one."""
    from .inverses import tracking_error

    model = case.model
    comp = model.inverse() if analytic else model.exact_inverse()
    u = case.signal
    v = comp.simulate(u)
    err = tracking_error(model, comp, u)
    kind = "analytic inverse (eqs. 54-58)" if analytic else "exact inverse"
    return plot_compensation(
        case.t, u, v, model.simulate(v), title=case.caption,
        error_label=(f"tracking error w - u, {kind}:\nRMS {err['rms_percent']:.3g} %, "
                     f"max {err['max_percent']:.3g} % of the reference span"),
    )


def thesis_figures(dt=None, progress=False):
    """Every figure of the thesis reproduction, as ``{file stem: Figure}``.

    Parameters
    ----------
    dt : float, optional
        Sampling time of the thesis's input signals in seconds; default
        each case's own (see :mod:`hystcomp.thesis`).  A coarser one makes
        quick previews.
    progress : bool, optional
        A progress bar (tqdm) on stderr, shown only on a terminal
        (default False).

    Returns
    -------
    dict
        File stem (``"fig2_1"``, ``"fig3_13"``, ..., ``"fig5_6"``) ->
        :class:`matplotlib.figure.Figure`.

    Examples
    --------
    >>> figs = thesis_figures(dt=0.05)
    >>> sorted(figs)[:3]
    ['fig2_1', 'fig3_13', 'fig3_14']
    """
    from . import thesis
    from ._progress import progress_bar

    kw = {} if dt is None else {"dt": dt}

    def stem(case):
        return "fig" + case.extra["figure"].replace(".", "_")

    jobs = [lambda: ("fig2_1", figure_2_1(thesis.figure_2_1(**kw)))]
    jobs += [lambda k=k: (lambda c: (stem(c), figure_3_4_3(c)))(thesis.section_3_4_3(k, **kw)) for k in (1, 2, 3, 4)]
    jobs += [lambda: ("fig3_17-3_19", figure_3_5(thesis.section_3_5(**kw))),
             lambda: ("fig4_1-4_2", figure_4_1(thesis.section_4_1(**kw)))]
    jobs += [lambda n=n: (lambda c: (stem(c), figure_5(c)))(thesis.section_5(n, **kw)) for n in thesis.SECTION_5]
    return dict(job() for job in progress_bar(jobs, desc="thesis figures", enabled=progress, unit="fig"))
