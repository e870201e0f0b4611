"""Matplotlib helpers for responses and base motions.

matplotlib is imported lazily, inside the functions, so that ``import rocking`` stays
light. When no display is available (and no backend was chosen by the user, e.g. through
``MPLBACKEND``), the non-interactive ``Agg`` backend is selected. Library code never calls
``plt.show()``; call it yourself, or save with :func:`save_figure`.

Conventions: time in s, rocking angle in degrees by default (``deg=False`` for rad),
ground acceleration in m/s^2.
"""

from __future__ import annotations

import math
import os
import sys
from pathlib import Path

import numpy as np

from ._atomic import atomic_path
from ._validate import positive
from .errors import ParameterError
from .motions import Motion, Record

#: Colours of the overlaid curves (colour-blind safe, Okabe-Ito).
PALETTE = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000")

#: Line styles of the overlaid curves, cycled with :data:`PALETTE` (a curve stays
#: distinguishable in grey print and for colour-blind readers).
LINESTYLES = ("-", "--", "-.", ":", (0, (5, 1, 1, 1, 1, 1)), (0, (8, 2)), (0, (1, 3)))

#: The ``gid`` of a fragility curve drawn by :meth:`rocking.analysis.FragilityFit.plot`
#: (the next curve on the same axes takes the next colour and line style).
CURVE_GID = "rocking.fragility_curve"


def _has_display() -> bool:
    if sys.platform in ("darwin", "win32"):
        return True
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def _pyplot():
    """``matplotlib.pyplot``, on the Agg backend when there is no display."""
    import matplotlib

    if ("matplotlib.pyplot" not in sys.modules and not os.environ.get("MPLBACKEND")
            and not _has_display()):
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def new_axes(figsize=(7.0, 3.6)):
    """A new ``(fig, ax)`` with constrained (tight) layout, through pyplot."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=figsize, layout="constrained")
    return fig, ax


def figure(figsize=(7.0, 3.6)):
    """A new ``(fig, ax)`` *without* pyplot (no global state; for scripts and the CLI)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize, layout="constrained")
    return fig, fig.add_subplot()


def style_axes(ax, xlabel: str | None = None, ylabel: str | None = None):
    """Publication-style axes: light grid, no top/right spines, labels with units."""
    ax.grid(True, which="major", color="0.85", linewidth=0.7)
    ax.set_axisbelow(True)
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    ax.tick_params(direction="out", length=3)
    if xlabel:
        ax.set_xlabel(xlabel)
    if ylabel:
        ax.set_ylabel(ylabel)
    return ax


def plain_log_ticks(ax, axis: str = "x"):
    """Label a log ``axis`` with plain numbers (``0.5``, ``1``, ``2``, ``5``) instead of
    ``3 x 10^0``: majors at the decades, the minors 2 and 5 of each decade labelled when
    the axis spans at most three decades (beyond, the decades alone). Call after the
    scale and limits are set.

    Examples
    --------
    >>> from rocking.plot import figure, plain_log_ticks
    >>> fig, ax = figure()
    >>> _ = ax.plot([0.5, 8.0], [0, 1]); ax.set_xscale("log")
    >>> plain_log_ticks(ax)
    >>> fig.canvas.draw()
    >>> lo, hi = ax.get_xlim()
    >>> def shown(minor):
    ...     return [t.get_text() for t in ax.get_xticklabels(minor=minor)
    ...             if t.get_text() and lo <= t.get_position()[0] <= hi]
    >>> shown(False), shown(True)
    (['1'], ['0.5', '2', '5'])
    """
    from matplotlib.ticker import FuncFormatter, LogLocator

    a = ax.xaxis if axis == "x" else ax.yaxis
    lo, hi = sorted(ax.get_xlim() if axis == "x" else ax.get_ylim())
    few = lo > 0 and hi / lo <= 1e3

    def major(v, _):
        return f"{v:g}"

    def minor(v, _):
        if not few or v <= 0:
            return ""
        m = v / 10 ** np.floor(np.log10(v) + 1e-9)
        return f"{v:g}" if np.isclose(m, 2) or np.isclose(m, 5) else ""

    a.set_major_locator(LogLocator(base=10))
    a.set_minor_locator(LogLocator(base=10, subs=np.arange(2, 10)))
    a.set_major_formatter(FuncFormatter(major))
    a.set_minor_formatter(FuncFormatter(minor))


_IM_NAMES = {"pga": "PGA", "pgv": "PGV", "pgd": "PGD", "arias": "Arias intensity",
             "pga_ratio": r"PGA / ($g\,\tan\alpha$)",
             "pgv_ratio": r"PGV $p$ / ($g\,\tan\alpha$)",
             "im": "intensity measure"}
_UNIT_TEX = {"m/s^2": r"m/s$^2$", "m/s2": r"m/s$^2$", "mps2": r"m/s$^2$",
             "cm/s^2": r"cm/s$^2$", "cm/s2": r"cm/s$^2$", "mm/s^2": r"mm/s$^2$",
             "mps": "m/s", "1/s": r"s$^{-1}$"}


def unit_label(unit: str | None) -> str:
    """A unit for an axis label, exponents in mathtext (``m/s^2`` -> ``m/s$^2$``); ``""``
    for a dimensionless or unknown unit (``None``, ``""``, ``"-"``)."""
    if unit is None:
        return ""
    u = str(unit).strip()
    if u in ("", "-", "unitless", "1"):
        return ""
    return _UNIT_TEX.get(u, u.replace("^2", "$^2$") if "$" not in u else u)


def im_label(name: str | None, unit: str | None = None) -> str:
    """An axis label for an intensity measure: its name (``pga`` -> ``PGA``, the keys of
    :data:`rocking.analysis.ida.IMS`) and its unit in parentheses, e.g. ``PGA (m/s$^2$)``;
    ``"intensity measure"`` when the name is not known."""
    key = "im" if not name else str(name)
    text = _IM_NAMES.get(key.lower(), key)
    u = unit_label(unit)
    return f"{text} ({u})" if u else text


def _angle_label(deg: bool) -> str:
    return r"rocking angle $\theta$ (deg)" if deg else r"rocking angle $\theta$ (rad)"


def _draw_response(ax, resp, deg: bool, label, color, annotate: bool, **kw):
    t = np.asarray(resp.t, dtype=float)
    th = np.asarray(resp.theta, dtype=float)
    if deg:
        th = np.degrees(th)
    kw.setdefault("linewidth", 1.1)
    (line,) = ax.plot(t, th, label=label, color=color, **kw)
    if getattr(resp, "overturned", False):
        t_over = resp.overturn_time if not math.isnan(resp.overturn_time) else (
            t[-1] if t.size else 0.0)
        sign = math.copysign(1.0, th[-1]) if th.size else 1.0
        y = sign * (90.0 if deg else math.pi / 2)
        ax.plot([t_over], [y], marker="X", markersize=9, color="#C00000", zorder=5,
                linestyle="none", clip_on=False)
        if annotate:
            ax.annotate(f"overturned\nt = {t_over:.2f} s", xy=(t_over, y),
                        xytext=(-12, -14 * sign), textcoords="offset points",
                        ha="right", va="top" if sign > 0 else "bottom", fontsize=8,
                        color="#C00000")
    return line


def plot_response(resp, ax=None, deg: bool = True, label: str | None = None, *,
                  show_alpha: bool = False, title: str | None = None, **kw):
    """Plot the rocking angle ``theta(t)`` of one :class:`~rocking.Response`.

    Parameters
    ----------
    resp : Response
    ax : matplotlib Axes, optional
        Drawn on a new figure (through pyplot) when omitted.
    deg : bool
        Angle in degrees (default) or radians.
    label : str, optional
        Legend entry; a legend is drawn when given.
    show_alpha : bool
        Draw the critical angles as dashed lines: ``+-alpha`` for a symmetric block,
        ``alpha_plus`` and ``-alpha_minus`` (each side's own) for an asymmetric one.
    title : str, optional
    **kw
        Passed to ``Axes.plot`` (``color``, ``linewidth``, ...).

    Overturning is marked with a red cross at ``|theta| = 90 deg`` and annotated with its
    time. A 3-D body (``rigid3d``) draws its tilt (:attr:`rocking.Response.tilt`; its
    slide, twist and path: :mod:`rocking.plot3d`); another model without a planar angle
    (``Response.theta`` None) draws each of its states against time. Returns the Axes.
    """
    if ax is None:
        _, ax = new_axes()
    if resp.theta is None and getattr(resp, "tilt", None) is not None:  # a 3-D body
        tilt = np.degrees(resp.tilt) if deg else resp.tilt
        ax.plot(resp.t, tilt, color=kw.pop("color", PALETTE[0]), label=label, **kw)
        if resp.overturned:
            ax.plot([resp.overturn_time], [tilt[-1]], marker="X", markersize=9,
                    color="#C00000", linestyle="none", zorder=5)
        style_axes(ax, "time t (s)", "tilt (deg)" if deg else "tilt (rad)")
        if label is not None:
            ax.legend(frameon=False, fontsize=9)
        if title:
            ax.set_title(title, fontsize=10)
        return ax
    if resp.theta is None:  # no planar angle: the states (Response.state_names)
        for j, name in enumerate(resp.state_names):
            ax.plot(resp.t, resp.states[:, j], color=PALETTE[j % len(PALETTE)], label=name,
                    **kw)
        style_axes(ax, "time t (s)", "state (SI units)")
        ax.legend(frameon=False, fontsize=9)
        if title:
            ax.set_title(title)
        return ax
    color = kw.pop("color", PALETTE[0])
    _draw_response(ax, resp, deg, label, color, True, **kw)
    block = getattr(resp, "block", None)
    if show_alpha and block is not None and getattr(block, "alpha", None):
        ap = getattr(block, "alpha_plus", block.alpha)
        am = getattr(block, "alpha_minus", block.alpha)
        ap, am = (math.degrees(ap), math.degrees(am)) if deg else (ap, am)
        if ap == am:  # symmetric: one +-alpha
            marks = ((ap, r"$\pm\alpha$"), (-am, None))
        else:  # each side's own overturning angle
            u = "°" if deg else " rad"
            marks = ((ap, rf"$\alpha_+$ = {ap:.3g}{u}"), (-am, rf"$-\alpha_-$ = {-am:.3g}{u}"))
        for y, text in marks:
            ax.axhline(y, color="0.45", linestyle="--", linewidth=0.8)
            if text:
                ax.annotate(text, xy=(1.0, y), xycoords=("axes fraction", "data"),
                            xytext=(2, 0), textcoords="offset points", va="center",
                            fontsize=8, color="0.35")
    ax.axhline(0.0, color="0.3", linewidth=0.6)
    style_axes(ax, "time t (s)", _angle_label(deg))
    t = np.asarray(resp.t, dtype=float)
    if t.size > 1:
        ax.set_xlim(0.0, float(t[-1]))
    if label is not None:
        ax.legend(frameon=False, fontsize=9)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def plot_responses(responses, labels=None, ax=None, deg: bool = True, *,
                   title: str | None = None, colors=None, **kw):
    """Overlay the ``theta(t)`` of several responses, one legend entry per ``labels`` item.

    ``labels`` (optional) must have one entry per response. Returns the Axes.
    """
    responses = list(responses)
    if labels is None:
        labels = [getattr(r, "model", f"response {i + 1}") for i, r in enumerate(responses)]
    labels = list(labels)
    if len(labels) != len(responses):
        raise ParameterError(f"labels must have one entry per response "
                             f"({len(responses)}), got {len(labels)}")
    if ax is None:
        _, ax = new_axes()
    colors = list(colors) if colors is not None else list(PALETTE)
    t_end = 0.0
    for i, (r, lab) in enumerate(zip(responses, labels, strict=True)):
        _draw_response(ax, r, deg, lab, colors[i % len(colors)], len(responses) == 1, **kw)
        if len(r.t):
            t_end = max(t_end, float(r.t[-1]))
    ax.axhline(0.0, color="0.3", linewidth=0.6)
    style_axes(ax, "time t (s)", _angle_label(deg))
    if t_end > 0:
        ax.set_xlim(0.0, t_end)
    if responses:
        ax.legend(frameon=False, fontsize=9)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def plot_motion(motion, ax=None, duration: float | None = None, *, title: str | None = None,
                **kw):
    """Plot the ground acceleration ``a(t)`` (m/s^2) of a base motion.

    A :class:`~rocking.motions.Record` is drawn through its samples; any other motion is
    sampled finely enough to resolve it. ``duration`` (s) defaults to the motion's.
    Returns the Axes.
    """
    if not isinstance(motion, Motion):
        raise ParameterError(f"motion must be a rocking.motions.Motion, "
                             f"got {type(motion).__name__}")
    dur = motion.duration if duration is None else positive("duration", duration, "s")
    horizontal = getattr(motion, "horizontal", None)  # a GroundMotion: its horizontal part
    if horizontal is not None:
        motion = horizontal.scaled(motion.scale)
    if isinstance(motion, Record):
        n = min(motion.acc.size, int(math.floor(dur / motion.dt + 1e-9)) + 1)
        t = motion.t[:n]
        a = motion.values[:n]
    else:
        dt = min(motion.scan_step / 4.0, dur / 2000.0)
        t = np.arange(int(math.ceil(dur / dt)) + 1) * dt
        t = t[t <= dur + 1e-12]
        a = motion.acceleration(t)
    if ax is None:
        _, ax = new_axes()
    kw.setdefault("linewidth", 0.9)
    kw.setdefault("color", "0.2")
    ax.plot(t, a, **kw)
    ax.axhline(0.0, color="0.3", linewidth=0.6)
    style_axes(ax, "time t (s)", r"ground acceleration $a$ (m/s$^2$)")
    ax.set_xlim(0.0, float(dur))
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def save_figure(fig, path, dpi: int = 120) -> Path:
    """Save ``fig`` (a Figure, or an Axes of one) to ``path``, creating parent folders.

    Returns the path. The figure is not closed (close pyplot figures with ``plt.close``).
    """
    fig = getattr(fig, "figure", fig)  # accept an Axes
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(path) as tmp:  # never a half-written PNG under its name
        fig.savefig(tmp, dpi=dpi, bbox_inches="tight", facecolor="white")
    return path
