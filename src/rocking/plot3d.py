"""Plots of a 3-D body's response (``model="rigid3d"``): tilt, slide and twist against
time, the path of the centre of mass seen from above, and the lean of the body's up axis
on a compass with the overturning azimuth.

Conventions (:mod:`rocking.models.rigid3d`): the ground's frame, its ``x`` axis the body's
``x`` axis at rest, angles counter-clockwise looking down; the tilt is the angle of the
body's initial up axis from the vertical (:attr:`rocking.Response.tilt`), the slide the
horizontal displacement of its base point (:attr:`rocking.Response.slide`), the twist its
rotation about the vertical (:attr:`rocking.Response.twist`). Angles are drawn in degrees,
lengths in mm. Each function draws on the axes it is given (a new figure without pyplot
otherwise, :func:`rocking.plot.figure`) and returns them.
"""

from __future__ import annotations

import math

import numpy as np

from .errors import ParameterError
from .plot import PALETTE, style_axes

OVERTURN_COLOR = "#C00000"


def _check(resp):
    if getattr(resp, "tilt", None) is None:
        raise ParameterError("resp must be the Response of a 3-D body (model 'rigid3d', whose "
                             "state has an orientation); for a planar model plot theta with "
                             "rocking.plot.plot_response")
    return resp


def _figure(nrows=1, figsize=(7.0, 3.6), polar=False):
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize, layout="constrained")
    if polar:
        return fig, fig.add_subplot(projection="polar")
    return fig, fig.subplots(nrows, 1, sharex=True, squeeze=False)[:, 0]


def lean_azimuth(resp) -> np.ndarray:
    """The bearing (deg, counter-clockwise from ``x``) towards which the body's up axis
    leans, from its quaternion history: ``atan2(R_yz, R_xz)`` (the overturning azimuth
    when it falls)."""
    names = tuple(resp.state_names)
    q0, q1, q2, q3 = (resp.states[:, names.index(n)] for n in ("q0", "q1", "q2", "q3"))
    return np.degrees(np.arctan2(2 * (q2 * q3 - q0 * q1), 2 * (q1 * q3 + q0 * q2)))


def plot_histories3d(resp, axes=None, *, title: str | None = None):
    """Tilt (deg), slide (mm) and twist (deg) of a 3-D body against time, on three axes
    sharing the time axis (``axes``: three matplotlib Axes; new ones by default). The
    tilt's peak (``max_tilt``) is marked, and an overturn with a red cross at its time.
    Returns the three Axes.

    Examples
    --------
    >>> import rocking
    >>> from rocking.plot3d import plot_histories3d
    >>> from rocking.shapes import Shape
    >>> box = Shape.box(0.4, 0.4, 1.2, density=2000.0)
    >>> r = rocking.simulate(box, model="rigid3d", duration=0.5, tilt0=0.1, step=1e-3)
    >>> axes = plot_histories3d(r)
    >>> [ax.get_ylabel() for ax in axes]
    ['tilt (deg)', 'slide (mm)', 'twist (deg)']
    """
    _check(resp)
    if axes is None:
        _, axes = _figure(3, figsize=(7.0, 6.0))
    t = np.asarray(resp.t, dtype=float)
    curves = ((np.degrees(resp.tilt), "tilt (deg)"), (1e3 * resp.slide, "slide (mm)"),
              (np.degrees(resp.twist), "twist (deg)"))
    for k, (ax, (y, label)) in enumerate(zip(axes, curves, strict=True)):
        ax.plot(t, y, color=PALETTE[k], linewidth=1.1)
        ax.axhline(0.0, color="0.3", linewidth=0.6)
        style_axes(ax, "time t (s)" if k == len(curves) - 1 else None, label)
        if t.size > 1:
            ax.set_xlim(0.0, float(t[-1]))
    peak = float(np.degrees(resp.max_tilt))
    if resp.overturned:
        axes[0].plot([resp.overturn_time], [np.degrees(resp.tilt[-1])], marker="X",
                     markersize=9, color=OVERTURN_COLOR, linestyle="none", zorder=5)
        axes[0].annotate(f"overturned, t = {resp.overturn_time:.2f} s, towards "
                         f"{resp.overturn_azimuth:.0f} deg", xy=(0.01, 0.97),
                         xycoords="axes fraction", va="top", fontsize=8,
                         color=OVERTURN_COLOR)
    else:
        axes[0].annotate(f"max tilt {peak:.3g} deg", xy=(0.01, 0.97),
                         xycoords="axes fraction", va="top", fontsize=8, color="0.3")
    axes[1].annotate(f"max {1e3 * resp.max_slide:.3g} mm, residual "
                     f"{1e3 * resp.residual_slide:.3g} mm (base point)", xy=(0.01, 0.97),
                     xycoords="axes fraction", va="top", fontsize=8, color="0.3")
    axes[2].annotate(f"max |twist| {np.degrees(resp.max_twist):.3g} deg, residual "
                     f"{np.degrees(resp.residual_twist):.3g} deg", xy=(0.01, 0.97),
                     xycoords="axes fraction", va="top", fontsize=8, color="0.3")
    if title:
        axes[0].set_title(title, fontsize=10)
    return axes


def plot_com_path(resp, ax=None, *, title: str | None = None):
    """The path of the centre of mass seen from above (mm, relative to the ground; equal
    scales), with the base point's (dashed), the start (circle), the end (square) or the
    overturn (red cross), and the body's support at rest (grey outline). Returns the Axes.

    Examples
    --------
    >>> import rocking
    >>> from rocking.plot3d import plot_com_path
    >>> from rocking.shapes import Shape
    >>> box = Shape.box(0.4, 0.4, 1.2, density=2000.0)
    >>> r = rocking.simulate(box, model="rigid3d", duration=0.5, tilt0=0.1, step=1e-3)
    >>> plot_com_path(r).get_xlabel()
    'x (mm, ground frame)'
    """
    _check(resp)
    if ax is None:
        _, axes = _figure(1, figsize=(5.2, 5.0))
        ax = axes[0]
    com = 1e3 * resp.com_path()
    base = 1e3 * resp.base_path()
    bp0 = None
    try:
        from .models import get_model
        from .results import support_base_point

        shape = get_model(resp.model).check_block(resp.block)
        sup = np.vstack([shape.support, shape.support[:1]]) * 1e3
        ax.fill(sup[:, 0] + com[0, 0], sup[:, 1] + com[0, 1], color="0.92", zorder=0,
                label="support at rest")
        bp0 = 1e3 * support_base_point(shape)[:2] + com[0]
    except Exception:  # noqa: BLE001 - the outline is a courtesy
        pass
    ax.plot(com[:, 0], com[:, 1], color=PALETTE[0], linewidth=1.2,
            label="centre of mass")
    if bp0 is not None:
        ax.plot(base[:, 0] + bp0[0], base[:, 1] + bp0[1], color=PALETTE[1],
                linewidth=0.9, linestyle="--", label="base point")
    ax.plot(*com[0], marker="o", color=PALETTE[0], linestyle="none", label="start")
    if resp.overturned:
        ax.plot(*com[-1], marker="X", markersize=10, color=OVERTURN_COLOR,
                linestyle="none", label=f"overturn ({resp.overturn_azimuth:.0f} deg)")
    else:
        ax.plot(*com[-1], marker="s", color=PALETTE[0], linestyle="none", label="end")
    ax.set_aspect("equal", adjustable="datalim")
    style_axes(ax, "x (mm, ground frame)", "y (mm, ground frame)")
    ax.legend(frameon=False, fontsize=8, loc="best")
    ax.set_title(title or "centre of mass seen from above", fontsize=10)
    return ax


def plot_overturn_azimuth(resp, ax=None, *, title: str | None = None):
    """A compass (polar axes, 0 deg along the ground's ``x``, counter-clockwise): the lean
    of the body's up axis over the run (bearing :func:`lean_azimuth`, radius the tilt in
    deg) and, if it overturned, an arrow along ``overturn_azimuth``. Returns the Axes.

    Examples
    --------
    >>> import rocking
    >>> from rocking.plot3d import plot_overturn_azimuth
    >>> from rocking.shapes import Shape
    >>> box = Shape.box(0.4, 0.4, 1.2, density=2000.0)
    >>> r = rocking.simulate(box, model="rigid3d", duration=0.5, tilt0=0.1, step=1e-3)
    >>> plot_overturn_azimuth(r).name
    'polar'
    """
    _check(resp)
    if ax is None:
        _, ax = _figure(figsize=(5.0, 5.0), polar=True)
    if ax.name != "polar":
        raise ParameterError("ax must be polar axes (projection='polar')")
    tilt = np.degrees(resp.tilt)
    az = np.radians(lean_azimuth(resp))
    ax.plot(az, tilt, color=PALETTE[0], linewidth=0.9, label="lean of the up axis")
    top = 90.0 if resp.overturned else max(float(np.max(tilt)) * 1.15, 1e-3)
    if resp.overturned:
        a = math.radians(resp.overturn_azimuth)
        ax.annotate("", xy=(a, top), xytext=(a, 0.0),
                    arrowprops={"arrowstyle": "-|>", "color": OVERTURN_COLOR, "lw": 2.0})
        ax.plot([a], [top], marker="X", markersize=10, color=OVERTURN_COLOR,
                linestyle="none", label=f"overturned towards {resp.overturn_azimuth:.1f} deg")
    else:
        ax.plot([], [], linestyle="none", label="did not overturn")
    ax.set_ylim(0.0, top)
    ax.set_theta_zero_location("E")
    ax.set_theta_direction(1)
    ax.set_rlabel_position(112.5)
    ax.tick_params(labelsize=8)
    ax.legend(frameon=False, fontsize=8, loc="lower left", bbox_to_anchor=(-0.12, -0.14))
    ax.set_title(title or "lean (tilt, deg) and overturning azimuth\n(0 deg: ground x, "
                          "counter-clockwise)", fontsize=10)
    return ax
