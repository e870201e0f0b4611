r"""The weakest direction of a 3-D body under two horizontal components (issue 20), and
the worst heading of a 3-D body (issue 30).

:func:`heading_sweep` is the 3-D counterpart of the planar sweep: the body itself
(``model="rigid3d"``) under the pair's three components at every heading (the body's x
axis from the first component), in one batch (:class:`HeadingSweep`);
:func:`direction_sweep` with ``model="rigid3d"`` is refused and names it.

:func:`direction_sweep` runs, for every direction ``phi`` of the body's horizontal frame,
the planar analysis of the body's planar block of that direction
(:meth:`rocking.Block.from_shape`: the sides' alpha, R, p and restitutions) under the
ground acceleration projected on ``phi`` (:meth:`rocking.motions.HorizontalPair.along`),
all directions in one :func:`rocking.simulate_many` batch (one block per row), and
returns the table and the worst direction (:class:`DirectionSweep`);
:func:`direction_fragility` fits an overturning fragility curve per direction from pairs
scaled to levels of an intensity measure.

**What this is, and is not.** This planar-per-direction analysis is the standard
engineering answer until a 3-D model exists: in each direction the body is assumed to rock
in the vertical plane of that direction only, about one pivot line at a time, under the
component of the shaking along it. The other component, which acts at the same time, is
ignored in that run; there is no coupling between directions, no twisting about the
vertical axis, no wobbling (rolling on the edge of a round base) and no sliding. A body
shaken obliquely to the edges of its base can uplift earlier than either planar block
says (:func:`rocking.shapes.directional_parameters`' ``uplift_3d_*`` columns).

**Directions.** ``phi`` (rad) is counter-clockwise from the body's x axis (the frame of
:mod:`rocking.shapes`); ``orientation`` is the compass bearing of that axis (None: along
the pair's first component; see :class:`rocking.motions.HorizontalPair`). The direction ``phi + pi``
is the mirror image of ``phi``: the same planar block with its sides swapped under the
negated acceleration, so theta is negated and max ``|theta|``, overturning and the times are
the same. The default directions therefore cover [0, 180) deg every 15 deg for a
:class:`~rocking.shapes.Shape` or a symmetric block, [0, 360) deg otherwise.

**The worst direction.** Ranked by, in turn: overturned first; the earliest overturning
time; the largest ``max_abs_theta_over_alpha``; the largest ``uplift_demand`` (which
ranks the directions when none of them rocks). ``max_abs_theta_over_alpha`` is the peak
rotation over the overturning angle of the side on which it happened: ``max |theta| /
alpha`` for a symmetric block; for an asymmetric one ``max(theta_+ / alpha_plus, theta_- /
alpha_minus)`` with the peaks on each side (``max_theta_plus``, ``max_theta_minus``) read
from the histories sampled every ``dt_out`` (the larger of the two is the run's exact
max ``|theta|``). ``uplift_demand`` is the static measure ``max(max(a) / (g tan alpha_plus),
max(-a) / (g tan alpha_minus))`` of the projected horizontal acceleration ``a`` (> 1: the
block lifts off from rest; a positive ``a`` lifts it on side +; without the vertical
component).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from .._validate import as_float, positive
from ..blocks import Block
from ..errors import ParameterError
from ..models import is_3d, simulate_many
from ..motions import HorizontalPair
from ..motions.pair import angle
from ..plot import PALETTE
from ..shapes.directional import warn_if_degrees
from ..units import G

DEFAULT_STEP = math.radians(15.0)
"""The default spacing of the directions (rad)."""
DEFAULT_DT_OUT = 0.005
"""The sampling (s) of the histories that give an asymmetric block's peaks per side."""

COLUMNS = ("phi", "phi_deg", "alpha_plus", "alpha_minus", "p_plus", "p_minus", "pga",
           "uplift_demand", "max_abs_theta", "max_theta_plus", "max_theta_minus",
           "max_abs_theta_over_alpha", "overturned", "overturn_time", "uplift_time",
           "n_impacts", "settled", "worst")
"""The columns of :attr:`DirectionSweep.table` (SI; angles in rad, ``phi_deg`` in deg)."""


@dataclass(frozen=True, eq=False)
class DirectionSweep:
    """The result of :func:`direction_sweep`: ``table`` (one row per direction,
    :data:`COLUMNS`), ``worst`` (its row of the worst direction, module docstring), the
    ``pair``, ``model``, ``orientation`` (rad, the bearing of the body's x axis) and
    ``scale`` (the load factor of the pair).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import rocking
    >>> from rocking.analysis import direction_sweep
    >>> from rocking.motions import HorizontalPair, Record
    >>> t = np.arange(0.0, 1.0, 0.005)
    >>> pulse = np.sin(2 * np.pi * t)  # a 1 Hz one-sine, m/s^2
    >>> pair = HorizontalPair(Record(3.0 * pulse, 0.005), Record(pulse, 0.005))
    >>> sw = direction_sweep(rocking.specimen(2), pair, 4, duration=5.0)
    >>> len(sw.table), bool(sw.worst["overturned"]), sw.worst_phi == float(sw.worst["phi"])
    (4, True, True)
    >>> type(sw.plot()).__name__
    'Figure'
    """

    table: pd.DataFrame
    worst: pd.Series
    pair: HorizontalPair
    model: str
    orientation: float
    scale: float

    @property
    def worst_phi(self) -> float:
        """The worst direction (rad)."""
        return float(self.worst["phi"])

    def plot(self, ax=None, *, label: str | None = None, mirror: bool = True,
             title: str | None = None, worst: bool = True, color=None):
        """max ``|theta|`` / alpha against ``phi`` on polar axes (overturned directions at
        the rim, marked x); ``mirror`` also draws ``phi + 180`` deg (the same response);
        ``worst`` marks the worst direction (a radial line). The axes are labelled (the
        direction from the body's x axis, the radial quantity) and titled (the pair, its
        load factor, the model; ``title`` replaces it; on a given ``ax`` only when
        ``title`` is given). Returns the figure.

        Examples
        --------
        >>> import rocking
        >>> from rocking.analysis import direction_sweep
        >>> from rocking.motions import HorizontalPair, Record
        >>> pulse = np.sin(2 * np.pi * np.arange(0.0, 1.0, 0.005))  # a 1 Hz one-sine, m/s^2
        >>> pair = HorizontalPair(Record(3.0 * pulse, 0.005), Record(pulse, 0.005))
        >>> sw = direction_sweep(rocking.specimen(2), pair, 4, duration=5.0)
        >>> fig = sw.plot()  # 4 directions and their mirrors phi + 180 deg, closed
        >>> ax = fig.axes[0]
        >>> ax.name, len(ax.lines[0].get_xdata())
        ('polar', 9)
        >>> int(sw.table["overturned"].sum()), len(ax.lines[1].get_xdata())  # x at the rim
        (2, 4)
        >>> bool(ax.get_title()), bool(ax.get_xlabel())
        (True, True)
        """
        own = ax is None
        if own:
            from matplotlib.figure import Figure

            fig = Figure(figsize=(5.6, 6.0), layout="constrained")
            ax = fig.add_subplot(projection="polar")
        fig = ax.figure
        t = self.table.sort_values("phi")
        phi = t.phi.to_numpy(float)
        r = np.minimum(t.max_abs_theta_over_alpha.to_numpy(float), 1.0)
        ovt = t.overturned.to_numpy(bool)
        if mirror:
            phi = np.concatenate([phi, phi + math.pi])
            r = np.concatenate([r, r])
            ovt = np.concatenate([ovt, ovt])
        o = np.argsort(phi % (2 * math.pi))
        phi, r, ovt = phi[o] % (2 * math.pi), r[o], ovt[o]
        line, = ax.plot(np.append(phi, phi[0]), np.append(r, r[0]), marker="o", ms=3,
                        label=label, color=color)
        ax.plot(phi[ovt], r[ovt], "x", color=line.get_color(), ms=8,
                label="overturned" if own and ovt.any() else None)
        if worst:
            w = self.worst_phi
            ax.plot([w, w], [0.0, 1.05], color=line.get_color(), lw=1.0, ls=":",
                    label=f"worst: {math.degrees(w) % 360:.0f} deg" if own else None)
        ax.set_ylim(0.0, 1.05)
        ax.set_theta_zero_location("E")
        ax.set_theta_direction(1)
        ax.set_xlabel("angle: direction of shaking phi (deg)\nfrom the body's x axis, "
                      "counter-clockwise", fontsize=9)
        if own or title is not None:
            scale = f" x {self.scale:g}" if self.scale != 1.0 else ""
            ax.set_title(title if title is not None else
                         f"Peak rocking by direction: {self.pair.name}{scale} "
                         f"({self.model})\nradius: max |θ| / α (1: overturned)",
                         fontsize=10)
        if own and (ovt.any() or worst or label):
            fig.legend(*ax.get_legend_handles_labels(), fontsize=8,
                       loc="outside lower center", frameon=False, ncol=3)
        return fig


def _directions(directions, mirrored: bool) -> np.ndarray:
    if directions is None:
        stop = math.pi if mirrored else 2.0 * math.pi
        return np.arange(0.0, stop - 1e-12, DEFAULT_STEP)
    if isinstance(directions, int | np.integer) and not isinstance(directions, bool):
        if directions < 1:
            raise ParameterError(f"directions must be >= 1 (a count), got {directions}")
        stop = math.pi if mirrored else 2.0 * math.pi
        return np.arange(int(directions)) * (stop / int(directions))
    try:
        d = np.atleast_1d(np.asarray(directions, dtype=float))
    except (TypeError, ValueError):
        raise ParameterError("directions must be angles in rad (a number or a sequence), "
                             f"or a count; got {directions!r}") from None
    if d.ndim != 1 or d.size == 0 or not np.all(np.isfinite(d)):
        raise ParameterError("directions must be a non-empty 1-D sequence of finite angles "
                             "(rad)")
    warn_if_degrees(d)
    return d


def _blocks_of(body, phis: np.ndarray) -> tuple[list, bool]:
    """One planar block per direction, and whether ``phi + pi`` mirrors ``phi``."""
    if isinstance(body, Block):
        return [body] * phis.size, bool(body.symmetric)
    if hasattr(body, "parameters") and hasattr(body, "polygon"):  # a rocking.shapes.Shape
        return [Block.from_shape(body, float(p)) for p in phis], True
    if callable(body):
        blocks = [body(float(p)) for p in phis]
        bad = [type(b).__name__ for b in blocks if not isinstance(b, Block)]
        if bad:
            raise ParameterError(f"body(phi) must return a rocking.Block, got {bad[0]}")
        return blocks, False
    raise ParameterError("body must be a rocking.shapes.Shape, a rocking.Block or a function "
                         f"phi -> Block, got {type(body).__name__}")


def direction_sweep(body, pair: HorizontalPair, directions=None, *, model="housner",
                    orientation=None, scale: float = 1.0, vertical: bool = True,
                    duration: float | None = None, dt_out: float = DEFAULT_DT_OUT,
                    **options) -> DirectionSweep:
    """The planar analysis in every direction under a horizontal pair (module docstring).

    ``body``: a :class:`rocking.shapes.Shape` (the planar block of each direction,
    :meth:`rocking.Block.from_shape`), a :class:`rocking.Block` (the same block in
    every direction: a footprint symmetric about every vertical plane, such as a
    cylinder) or a function ``phi -> Block``. ``pair``: a
    :class:`~rocking.motions.HorizontalPair`. ``directions``: angles (rad), a count, or
    None (every 15 deg; module docstring). ``orientation``: the compass bearing of the
    body's x axis (rad or ``"228deg"``; None: along the first component). ``scale``: a
    load factor on the pair (vertical component too). ``vertical``: use the pair's
    vertical component when it has one. ``model``, ``duration``, ``**options``: as in
    :func:`rocking.simulate_many`; ``dt_out`` (s): the sampling of the histories that
    give an asymmetric block's peak on each side.

    Row ``i`` is bit-identical to ``rocking.simulate(block_i, pair.motion(phi_i))``.

    Examples
    --------
    A block that is the same in every direction (``rocking.Block``) under a pair whose first
    component is three times the second: the acceleration along ``phi`` is
    ``3 cos(phi) + sin(phi)`` times the pulse, and only the directions where its peak exceeds
    ``g tan alpha`` (``uplift_demand > 1``) rock:

    >>> import rocking
    >>> from rocking.analysis import direction_sweep
    >>> from rocking.motions import HorizontalPair, Record
    >>> t = np.arange(0.0, 1.0, 0.005)
    >>> pulse = np.sin(2 * np.pi * t)  # a 1 Hz one-sine, m/s^2
    >>> pair = HorizontalPair(Record(3.0 * pulse, 0.005), Record(pulse, 0.005))
    >>> sw = direction_sweep(rocking.specimen(2), pair, 4, duration=5.0)  # 0, 45, 90, 135 deg
    >>> phi = sw.table["phi"]
    >>> bool(np.allclose(sw.table["pga"], abs(3 * np.cos(phi) + np.sin(phi))))
    True
    >>> sw.table["uplift_demand"].round(2).tolist(), sw.table["overturned"].tolist()
    ([1.8, 1.7, 0.6, 0.85], [True, True, False, False])
    """
    if is_3d(model):
        raise ParameterError(f"direction_sweep is the planar analysis per direction; model "
                             f"{model!r} is 3-D: sweep the pair's heading with "
                             "rocking.analysis.heading_sweep(shape, pair, headings)")
    if not isinstance(pair, HorizontalPair):
        raise ParameterError("pair must be a rocking.motions.HorizontalPair, got "
                             f"{type(pair).__name__}")
    if not isinstance(vertical, bool | np.bool_):
        raise ParameterError(f"vertical must be True or False, got {vertical!r}")
    s = as_float("scale", scale)
    if s <= 0.0:
        raise ParameterError(f"scale must be > 0 (a load factor), got {scale!r}")
    dt_out = positive("dt_out", dt_out, "s")
    _, mirrored = _blocks_of(body, np.zeros(0))  # checks body
    phis = _directions(directions, mirrored)
    blocks, _ = _blocks_of(body, phis)
    o = None if orientation is None else angle("orientation", orientation)
    motions = []
    for p in phis:
        m = pair.motion(float(p), o, vertical=vertical)
        motions.append(m if s == 1.0 else m.scaled(s))
    horiz = [pair.along(float(p), o).values * s for p in phis]
    asym = any(not b.symmetric for b in blocks)
    res = simulate_many(blocks if len(set(map(id, blocks))) > 1 else blocks[0], motions,
                        model=model, duration=duration, return_histories=asym,
                        dt_out=dt_out, **options)
    ap = np.array([b.alpha_plus for b in blocks])
    am = np.array([b.alpha_minus for b in blocks])
    mx = np.asarray(res.max_abs_theta, dtype=float)
    if asym:
        with np.errstate(all="ignore"):
            th = np.asarray(res.theta, dtype=float)
            tp = np.fmax(np.nanmax(np.where(np.isnan(th), -np.inf, th), axis=1), 0.0)
            tm = np.fmax(np.nanmax(np.where(np.isnan(th), -np.inf, -th), axis=1), 0.0)
        plus_side = tp >= tm
        tp = np.where(plus_side, mx, np.minimum(tp, mx))
        tm = np.where(plus_side, np.minimum(tm, mx), mx)
        ratio = np.maximum(tp / ap, tm / am)
    else:
        tp = tm = np.full(mx.size, np.nan)
        ratio = mx / ap
    up_p = np.array([max(float(a.max()), 0.0) for a in horiz]) / (G * np.tan(ap))
    up_m = np.array([max(float(-a.min()), 0.0) for a in horiz]) / (G * np.tan(am))
    table = pd.DataFrame({
        "phi": phis, "phi_deg": np.degrees(phis), "alpha_plus": ap, "alpha_minus": am,
        "p_plus": [b.p_plus for b in blocks], "p_minus": [b.p_minus for b in blocks],
        "pga": [float(np.max(np.abs(a))) for a in horiz],
        "uplift_demand": np.maximum(up_p, up_m), "max_abs_theta": mx,
        "max_theta_plus": tp, "max_theta_minus": tm, "max_abs_theta_over_alpha": ratio,
        "overturned": np.asarray(res.overturned, dtype=bool),
        "overturn_time": np.asarray(res.overturn_time, dtype=float),
        "uplift_time": np.asarray(res.uplift_time, dtype=float),
        "n_impacts": np.asarray(res.n_impacts, dtype=int),
        "settled": np.asarray(res.settled, dtype=bool),
    })
    w = worst_index(table)
    table["worst"] = np.arange(len(table)) == w
    bearing = o if o is not None else (
        pair.azimuths[0] if pair.azimuths is not None else 0.0)
    table.attrs.update({"model": str(model), "pair": pair.name, "scale": s,
                        "orientation": bearing,
                        "vertical": bool(vertical and pair.vertical is not None)})
    return DirectionSweep(table=table, worst=table.iloc[w], pair=pair, model=str(model),
                          orientation=bearing, scale=s)


def worst_index(table: pd.DataFrame) -> int:
    """The position of the worst direction in a sweep's table (module docstring)."""
    if len(table) == 0:
        raise ParameterError("the table has no direction")
    ovt = table.overturned.to_numpy(bool)
    t = np.where(ovt, table.overturn_time.to_numpy(float), np.inf)
    t = np.where(np.isnan(t), np.inf, t)
    r = np.nan_to_num(table.max_abs_theta_over_alpha.to_numpy(float), nan=-np.inf)
    d = np.nan_to_num(table.uplift_demand.to_numpy(float), nan=-np.inf)
    return int(np.lexsort((-d, -r, t, ~ovt))[0])


def plot_sweeps(sweeps, labels=None, *, reference=None, ax=None):
    """Several sweeps' max ``|theta|`` / alpha against ``phi`` (polar); ``reference``: a
    direction (rad) to mark (e.g. the static weakest direction). Returns the figure.

    Examples
    --------
    The same pair at two load factors, compared on one polar plot:

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import rocking
    >>> from rocking.analysis import direction_sweep, plot_sweeps
    >>> from rocking.motions import HorizontalPair, Record
    >>> t = np.arange(0.0, 1.0, 0.005)
    >>> pulse = np.sin(2 * np.pi * t)  # a 1 Hz one-sine, m/s^2
    >>> pair = HorizontalPair(Record(3.0 * pulse, 0.005), Record(pulse, 0.005))
    >>> sweeps = [direction_sweep(rocking.specimen(2), pair, 4, scale=s, duration=5.0)
    ...           for s in (0.5, 1.0)]
    >>> fig = plot_sweeps(sweeps, ["x0.5", "x1"], reference=0.0)
    >>> type(fig).__name__
    'Figure'
    """
    if ax is None:
        from matplotlib.figure import Figure

        fig = Figure(figsize=(5.6, 5.6), layout="constrained")
        ax = fig.add_subplot(projection="polar")
    labels = labels or [f"scale {s.scale:g}" for s in sweeps]
    for i, (sw, lab) in enumerate(zip(sweeps, labels, strict=True)):
        sw.plot(ax, label=lab, worst=False, color=PALETTE[i % len(PALETTE)])
    if reference is not None:
        for k, ph in enumerate((reference, reference + math.pi)):
            ax.plot([ph, ph], [0.0, 1.05], color="k", lw=1.0, ls="--",
                    label=f"reference: {math.degrees(reference) % 360:.0f} deg"
                    if k == 0 else None)
    if not ax.get_title():
        ax.set_title("Peak rocking by direction\nradius: max |θ| / α (1: overturned, x)",
                     fontsize=10)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.05, 1.0), frameon=False)
    return ax.figure


PAIR_IMS = ("larger", "resultant", "geomean")
"""Intensity measures of a pair for :func:`direction_fragility` (m/s^2): the larger of
the two components' PGAs, the peak of the horizontal acceleration vector
(:attr:`~rocking.motions.HorizontalPair.peak_resultant`), the geometric mean of the two
PGAs."""


def pair_im(pair: HorizontalPair, im: str = "larger") -> float:
    """The intensity measure ``im`` (:data:`PAIR_IMS`, m/s^2) of a pair."""
    p1, p2 = pair.pga_components
    if im == "larger":
        return max(p1, p2)
    if im == "resultant":
        return pair.peak_resultant
    if im == "geomean":
        return math.sqrt(p1 * p2)
    raise ParameterError(f"im must be one of {', '.join(PAIR_IMS)}, got {im!r}")


@dataclass(frozen=True, eq=False)
class DirectionFragility:
    """The result of :func:`direction_fragility`: ``table`` (one row per direction:
    ``phi``, ``phi_deg``, ``alpha_plus``, ``alpha_minus``, ``n``, ``n_overturned``,
    ``median``, ``beta``, ``median_se`` (m/s^2), ``median_lower_bound`` /
    ``median_upper_bound`` where no fit exists, ``note``), ``runs`` (one row per run:
    ``pair``, ``level``, ``scale``, ``phi``... and the outcomes), ``fits`` (the
    :class:`~rocking.analysis.FragilityFit` of each direction that has one, by row of
    ``table``) and ``im``.

    Examples
    --------
    >>> import rocking
    >>> from rocking.analysis import direction_fragility
    >>> from rocking.motions import HorizontalPair, Record
    >>> t = np.arange(0.0, 1.0, 0.005)
    >>> pulse = np.sin(2 * np.pi * t)  # a 1 Hz one-sine, m/s^2
    >>> pair = HorizontalPair(Record(3.0 * pulse, 0.005), Record(pulse, 0.005))
    >>> df = direction_fragility(rocking.specimen(2), [pair], [1.0, 2.0, 4.0, 8.0], 2,
    ...                          duration=5.0, n_boot=0)
    >>> df.im, len(df.runs), df.table["n_overturned"].tolist(), df.fits
    ('larger', 8, [3, 1], {})
    """

    table: pd.DataFrame
    runs: pd.DataFrame
    fits: dict
    im: str
    mirrored: bool = False
    """Whether ``phi + 180`` deg is the mirror of ``phi`` (the same outcome: a
    :class:`~rocking.shapes.Shape` or a symmetric block), drawn by :meth:`plot`."""

    def plot(self, *, curves: int = 4, title: str | None = None):
        """The fragility by direction, for a report: left, the median ``im`` of overturning
        (g) against the direction on polar axes (a dot per fitted direction; where no fit
        exists, a radial bar from the bound below to the bound above, an open end where
        the data give none); the weakest direction (the smallest median) marked. Right, the
        fragility curves of up to ``curves`` directions (the weakest, the strongest and
        evenly between, by median; distinct colours and line styles,
        :meth:`~rocking.analysis.FragilityFit.plot`). Returns the figure.

        Examples
        --------
        >>> import rocking
        >>> from rocking.analysis import direction_fragility
        >>> from rocking.motions import HorizontalPair, Record
        >>> pulse = np.sin(2 * np.pi * np.arange(0.0, 1.0, 0.005))  # a 1 Hz one-sine, m/s^2
        >>> pair = HorizontalPair(Record(3.0 * pulse, 0.005), Record(pulse, 0.005))
        >>> df = direction_fragility(rocking.specimen(2), [pair], [1.0, 2.0, 4.0, 8.0], 2,
        ...                          duration=5.0, n_boot=0)
        >>> fig = df.plot()
        >>> [ax.name for ax in fig.axes], bool(fig.axes[0].get_title())
        (['polar', 'rectilinear'], True)
        """
        from matplotlib.figure import Figure

        from ..plot import LINESTYLES, style_axes

        t = self.table
        fig = Figure(figsize=(11.0, 5.0), layout="constrained")
        axp = fig.add_subplot(1, 2, 1, projection="polar")
        axc = fig.add_subplot(1, 2, 2)
        im_name = {"larger": "PGA (larger component)", "resultant": "peak resultant PGA",
                   "geomean": "PGA (geometric mean)"}[self.im]
        phis = t.phi.to_numpy(float)
        med = t["median"].to_numpy(float) / G
        lo = t.median_lower_bound.to_numpy(float) / G
        hi = t.median_upper_bound.to_numpy(float) / G
        top = 1.15 * float(np.nanmax(np.concatenate([med, lo, hi, [1e-3]])))
        shifts = (0.0, math.pi) if self.mirrored else (0.0,)
        fitted = np.isfinite(med)
        if fitted.any():
            x = np.concatenate([(phis[fitted] + sh) % (2 * math.pi) for sh in shifts])
            y = np.concatenate([med[fitted]] * len(shifts))
            o = np.argsort(x)
            x, y = x[o], y[o]
            if fitted.all() and (self.mirrored or np.ptp(phis) > 1.5 * math.pi):
                x, y = np.append(x, x[0]), np.append(y, y[0])
            axp.plot(x, y, "-o", ms=4, color=PALETTE[0], lw=1.2, label="median of the fit")
        for k, sh in enumerate(shifts):
            ph = (phis + sh) % (2 * math.pi)
            for i in np.flatnonzero(~fitted):
                a, b = lo[i], hi[i]
                if np.isnan(a) and np.isnan(b):
                    continue
                a0 = 0.0 if np.isnan(a) else a
                b0 = top if np.isnan(b) else b
                axp.plot([ph[i], ph[i]], [a0, b0], color=PALETTE[1], lw=3, alpha=0.7,
                         solid_capstyle="butt",
                         label=("no fit: bounds of the median" if k == 0 and i ==
                                np.flatnonzero(~fitted)[0] else None))
        est = np.where(fitted, med, np.where(np.isfinite(hi), hi, np.inf))
        if np.isfinite(est).any():
            w = int(np.argmin(est))
            wphi = float(phis[w])
            axp.plot([wphi, wphi], [0.0, top], color="k", ls="--", lw=1.0,
                     label=f"weakest: {math.degrees(wphi):.0f} deg "
                           f"({'median' if fitted[w] else 'median below'} "
                           f"{est[w]:.3g} g)")
        axp.set_ylim(0.0, top)
        axp.set_theta_zero_location("E")
        axp.set_theta_direction(1)
        axp.set_title(f"Median {im_name} of overturning (g)\nby direction phi (deg from "
                      "the body's x axis, ccw)", fontsize=10)
        fig.legend(*axp.get_legend_handles_labels(), fontsize=8, loc="outside lower left",
                   frameon=False, ncol=2)
        keys = sorted(self.fits, key=lambda i: self.fits[i].median)
        if len(keys) > curves:
            pick = np.unique(np.round(np.linspace(0, len(keys) - 1, max(curves, 1))))
            keys = [keys[int(j)] for j in pick]
        same: dict = {}  # directions with the same fit (the same outcomes): one curve
        for i in keys:
            f = self.fits[i]
            same.setdefault((round(f.median, 9), round(f.beta, 9)), []).append(i)
        for n, group in enumerate(same.values()):
            f = self.fits[group[0]]
            where = " and ".join(f"{t.phi_deg.iloc[i]:.0f}" for i in group)
            f.plot(axc, data=False, band=len(same) == 1,
                   color=PALETTE[n % len(PALETTE)], ls=LINESTYLES[n % len(LINESTYLES)],
                   label=f"{where} deg: median {f.median / G:.3g} g, beta {f.beta:.2f}")
        if keys:
            axc.set_title("Fragility curves of the weakest to the strongest directions",
                          fontsize=10)
            style_axes(axc, f"{im_name} (m/s$^2$)", "probability of overturning")
            top = axc.secondary_xaxis("top", functions=(lambda x: x / G, lambda x: x * G))
            top.set_xlabel(f"{im_name} (g)", fontsize=9)
        else:
            axc.set_axis_off()
            axc.text(0.5, 0.5, "no direction has a fragility fit\n(too few runs, or "
                     "outcomes separated by the level:\nthe bounds of the median, left)",
                     ha="center",
                     va="center", transform=axc.transAxes)
        fig.suptitle(title or f"Overturning fragility by direction ({len(t)} directions, "
                     f"{len(self.runs)} runs)", fontsize=11)
        return fig


def direction_fragility(body, pairs, levels, directions=None, *, im: str = "larger",
                        model="housner", orientation=None, vertical: bool = True,
                        duration: float | None = None, n_boot: int = 200, seed: int | None = 0,
                        **options) -> DirectionFragility:
    """An overturning fragility curve per direction: every pair scaled to every level of
    its intensity measure ``im`` (:data:`PAIR_IMS`, m/s^2), run in every direction as in
    :func:`direction_sweep` (one :func:`rocking.simulate_many` batch), and a lognormal
    fit per direction (:func:`rocking.analysis.fragility`; the median bounded by the
    largest level that did not overturn and the smallest that did where no fit exists).

    ``levels``: one sequence of levels (m/s^2) for every pair, or an array ``(pairs,
    levels)``, one row per pair (a design whose pairs cover distinct levels). The
    orientation (as in :class:`rocking.motions.HorizontalPair`) is the same for every
    pair (None: the body's x axis along each pair's first component). The same caveats
    as :func:`direction_sweep`: planar analysis per direction.

    Examples
    --------
    One pair (the second component a third of the first) scaled to four levels of its
    larger PGA (m/s^2), in two directions. The outcomes are separated by the level, so each
    direction gets bounds of its median instead of a fit: along the first component the
    block overturns from level 2, across it (a third of the shaking) only from level 8:

    >>> import rocking
    >>> from rocking.analysis import direction_fragility
    >>> from rocking.motions import HorizontalPair, Record
    >>> t = np.arange(0.0, 1.0, 0.005)
    >>> pulse = np.sin(2 * np.pi * t)  # a 1 Hz one-sine, m/s^2
    >>> pair = HorizontalPair(Record(3.0 * pulse, 0.005), Record(pulse, 0.005))
    >>> df = direction_fragility(rocking.specimen(2), [pair], [1.0, 2.0, 4.0, 8.0], 2,
    ...                          duration=5.0, n_boot=0)
    >>> df.table[["phi_deg", "median_lower_bound", "median_upper_bound"]].values.tolist()
    [[0.0, 1.0, 2.0], [90.0, 4.0, 8.0]]
    """
    from .fragility import fit_or_bounds

    plist = [pairs] if isinstance(pairs, HorizontalPair) else list(pairs)
    if not plist or not all(isinstance(p, HorizontalPair) for p in plist):
        raise ParameterError("pairs must be a rocking.motions.HorizontalPair or a non-empty "
                             "sequence of them")
    if im not in PAIR_IMS:
        raise ParameterError(f"im must be one of {', '.join(PAIR_IMS)}, got {im!r}")
    try:
        lev = np.asarray(levels, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError("levels must be numbers (m/s^2)") from None
    if lev.ndim == 1:
        lev = np.broadcast_to(lev, (len(plist), lev.size))
    if lev.ndim != 2 or lev.shape[0] != len(plist) or lev.size == 0:
        raise ParameterError(f"levels must be a sequence or an array of one row per pair "
                             f"({len(plist)}), got shape {np.shape(levels)}")
    if not (np.all(np.isfinite(lev)) and np.all(lev > 0.0)):
        raise ParameterError("levels must be finite and > 0 (m/s^2)")
    if not isinstance(vertical, bool | np.bool_):
        raise ParameterError(f"vertical must be True or False, got {vertical!r}")
    _, mirrored = _blocks_of(body, np.zeros(0))
    phis = _directions(directions, mirrored)
    dblocks, _ = _blocks_of(body, phis)
    o = None if orientation is None else angle("orientation", orientation)
    blocks, motions, meta = [], [], []
    for k, pair in enumerate(plist):
        base = pair_im(pair, im)
        for lv in lev[k]:
            f = float(lv) / base
            for i, phi in enumerate(phis):
                m = pair.motion(float(phi), o, vertical=vertical)
                motions.append(m.scaled(f))
                blocks.append(dblocks[i])
                meta.append((k, pair.name, float(lv), f, i))
    res = simulate_many(blocks, motions, model=model, duration=duration, **options)
    runs = pd.DataFrame(meta, columns=["pair", "name", "level", "scale", "direction"])
    runs["phi"] = phis[runs.direction.to_numpy()]
    runs["max_abs_theta"] = np.asarray(res.max_abs_theta, dtype=float)
    runs["overturned"] = np.asarray(res.overturned, dtype=bool)
    runs["overturn_time"] = np.asarray(res.overturn_time, dtype=float)
    runs["uplift_time"] = np.asarray(res.uplift_time, dtype=float)
    # a planar block stopped where g + a_v <= 0 (it left the ground, which a planar model
    # cannot represent) neither overturned nor survived: left out of the fits, counted
    runs["lifted_off"] = np.asarray(res.lifted_off, dtype=bool)
    rows, fits = [], {}
    for i, phi in enumerate(phis):
        g_all = runs[runs.direction == i]
        g = g_all[~g_all.lifted_off]
        x, y = g.level.to_numpy(float), g.overturned.to_numpy(bool)
        b = dblocks[i]
        row = {"phi": float(phi), "phi_deg": math.degrees(phi), "alpha_plus": b.alpha_plus,
               "alpha_minus": b.alpha_minus, "n": len(g),
               "n_lifted_off": int(g_all.lifted_off.sum()), "n_overturned": int(y.sum()),
               "median": math.nan, "beta": math.nan, "median_se": math.nan,
               "median_lower_bound": math.nan, "median_upper_bound": math.nan, "note": ""}
        fit, lo, hi, why = fit_or_bounds(x, y, n_boot=n_boot, seed=seed,
                                         im_name=f"pga_{im}", im_unit="m/s^2",
                                         label=f"overturning, {math.degrees(phi):g} deg")
        if fit is not None:
            fits[i] = fit
            row.update(median=fit.median, beta=fit.beta, median_se=fit.median_se)
        else:  # no maximum-likelihood fit: the bounds the outcomes give
            row.update(median_lower_bound=lo, median_upper_bound=hi,
                       note=f"no fragility fit ({why}): bounds of the median")
        rows.append(row)
    return DirectionFragility(table=pd.DataFrame(rows), runs=runs, fits=fits, im=im,
                              mirrored=mirrored)


# ====================================================================== 3-D: headings
HEADING_COLUMNS = ("heading", "heading_deg", "max_tilt", "max_tilt_over_alpha", "overturned",
                   "overturn_time", "overturn_azimuth", "uplift_time", "n_impacts",
                   "max_slide", "residual_slide", "max_twist", "residual_twist",
                   "lifted_off", "settled", "unconverged_steps", "worst")
"""The columns of :attr:`HeadingSweep.table` (SI; angles in rad, ``heading_deg`` and
``overturn_azimuth`` in deg: the outputs of :mod:`rocking.models.rigid3d`)."""
DEFAULT_HEADING_STEP = math.radians(15.0)
"""The default spacing of the headings (rad), over [0, 360) deg."""


@dataclass(frozen=True, eq=False)
class HeadingSweep:
    """The result of :func:`heading_sweep`: ``table`` (one row per heading,
    :data:`HEADING_COLUMNS`), ``worst`` (its row of the worst heading: overturned first,
    then the earliest overturn, the largest ``max_tilt``, the largest ``max_slide``),
    the ``pair``, the body's critical tilt ``alpha`` (rad, of its weakest direction:
    :meth:`rocking.shapes.Shape.weakest`, the scale of ``max_tilt_over_alpha``) and
    ``scale`` (the load factor of the pair).

    Examples
    --------
    >>> import rocking
    >>> from rocking.analysis import heading_sweep
    >>> from rocking.motions import HorizontalPair, Record
    >>> from rocking.shapes import Shape
    >>> pulse = np.sin(2 * np.pi * np.arange(0.0, 1.0, 0.005))  # a 1 Hz one-sine, m/s^2
    >>> pair = HorizontalPair(Record(4.0 * pulse, 0.005), Record(pulse, 0.005))
    >>> sw = heading_sweep(Shape.box(0.3, 0.3, 1.2, density=2000.0), pair, 4,
    ...                    duration=2.0, step=1e-3)
    >>> round(sw.alpha, 6), round(float(np.arctan(0.3 / 1.2)), 6)  # the box's weakest side
    (0.244979, 0.244979)
    >>> bool(sw.table["worst"].sum() == 1), sw.worst_heading == float(sw.worst["heading"])
    (True, True)
    """

    table: pd.DataFrame
    worst: pd.Series
    pair: HorizontalPair
    alpha: float
    scale: float
    model: str = "rigid3d"

    @property
    def worst_heading(self) -> float:
        """The worst heading (rad)."""
        return float(self.worst["heading"])

    def plot(self, ax=None, *, label: str | None = None):
        """``max_tilt / alpha`` against the heading on polar axes (0 deg: the body's x
        axis along the pair's first component, counter-clockwise), the overturned
        headings at the rim, marked x, the worst one ringed; labelled. Returns the
        figure.

        Examples
        --------
        >>> import rocking
        >>> from rocking.analysis import heading_sweep
        >>> from rocking.motions import HorizontalPair, Record
        >>> from rocking.shapes import Shape
        >>> pulse = np.sin(2 * np.pi * np.arange(0.0, 1.0, 0.005))  # a 1 Hz one-sine, m/s^2
        >>> pair = HorizontalPair(Record(4.0 * pulse, 0.005), Record(pulse, 0.005))
        >>> sw = heading_sweep(Shape.box(0.3, 0.3, 1.2, density=2000.0), pair, 4,
        ...                    duration=2.0, step=1e-3)
        >>> ax = sw.plot().axes[0]
        >>> ax.name, len(ax.lines[0].get_xdata())  # 4 headings, closed
        ('polar', 5)
        """
        if ax is None:
            from matplotlib.figure import Figure

            fig = Figure(figsize=(5.4, 5.6), layout="constrained")
            ax = fig.add_subplot(projection="polar")
        t = self.table.sort_values("heading")
        h = t.heading.to_numpy(float) % (2 * math.pi)
        r = t.max_tilt_over_alpha.to_numpy(float)
        ovt = t.overturned.to_numpy(bool)
        rim = max(1.05, float(np.nanmax(np.where(ovt, 0.0, r))) * 1.1 if r.size else 1.05)
        r = np.where(ovt, rim, r)
        line, = ax.plot(np.append(h, h[:1]), np.append(r, r[:1]), marker="o", ms=3,
                        label=label or f"{self.pair.name or 'pair'} x {self.scale:g}")
        ax.plot(h[ovt], r[ovt], "x", color=line.get_color(), ms=8,
                label="overturned" if ovt.any() else None)
        w = self.worst
        ax.plot([float(w["heading"]) % (2 * math.pi)],
                [rim if w["overturned"] else float(w["max_tilt_over_alpha"])], "o",
                mfc="none", mec="#C00000", ms=12, mew=1.5,
                label=f"worst: {float(w['heading_deg']):g} deg")
        ax.set_ylim(0.0, rim * 1.02)
        ax.set_theta_zero_location("E")
        ax.set_theta_direction(1)
        ax.tick_params(labelsize=8)
        ax.set_title("max tilt / alpha (weakest side) against the heading\n(the body's x "
                     "axis from the first component, counter-clockwise)", fontsize=9)
        ax.legend(fontsize=8, loc="lower left", bbox_to_anchor=(-0.12, -0.14),
                  frameon=False)
        return ax.figure


def _headings(headings) -> np.ndarray:
    if headings is None:
        return np.arange(0.0, 2.0 * math.pi - 1e-12, DEFAULT_HEADING_STEP)
    if isinstance(headings, int | np.integer) and not isinstance(headings, bool):
        if headings < 1:
            raise ParameterError(f"headings must be >= 1 (a count), got {headings}")
        return np.arange(int(headings)) * (2.0 * math.pi / int(headings))
    try:
        h = np.atleast_1d(np.asarray(headings, dtype=float))
    except (TypeError, ValueError):
        raise ParameterError("headings must be angles in rad (a number or a sequence), or "
                             f"a count; got {headings!r}") from None
    if h.ndim != 1 or h.size == 0 or not np.all(np.isfinite(h)):
        raise ParameterError("headings must be a non-empty 1-D sequence of finite angles "
                             "(rad)")
    warn_if_degrees(h)
    return h


def heading_sweep(shape, pair: HorizontalPair, headings=None, *, scale: float = 1.0,
                  vertical: bool = True, duration: float | None = None,
                  **options) -> HeadingSweep:
    """The 3-D counterpart of :func:`direction_sweep`: the body ``shape`` (a
    :class:`rocking.shapes.Shape`, or a rectangular :class:`rocking.Block` as its box)
    under the three components of ``pair`` at every heading (``model="rigid3d"``: the
    body's x axis ``heading`` rad counter-clockwise from the first component), all
    headings in one :func:`rocking.simulate_many` batch.

    ``headings``: angles (rad), a count over [0, 2 pi), or None (every 15 deg over
    [0, 360) deg: a heading and its opposite differ unless the body is symmetric under a
    half turn). Heading ``h`` runs the pair turned by ``-h``
    (:meth:`~rocking.motions.HorizontalPair.rotated`: the same ground motion recorded on
    axes along the body's) at heading 0: the same run as ``rocking.simulate(shape, pair,
    model="rigid3d", heading=deg(h))`` up to the rounding of the projection. ``scale``:
    a load factor on the pair (the vertical component too); ``vertical``: use the pair's
    vertical component when it has one; ``duration`` and ``**options`` (``friction``,
    ``step``, ...): as in :func:`rocking.simulate_many` (``heading`` is the sweep's).

    Unlike the planar sweep this couples both components, the vertical one, wobbling,
    twisting and sliding; ``max_tilt_over_alpha`` scales the tilt by the critical tilt of
    the body's weakest side (a box tipping over a corner can tilt beyond it and stand).

    Examples
    --------
    >>> import rocking
    >>> from rocking.analysis import heading_sweep
    >>> from rocking.motions import HorizontalPair, Record
    >>> from rocking.shapes import Shape
    >>> t = np.arange(0.0, 1.0, 0.005)
    >>> pulse = np.sin(2 * np.pi * t)  # a 1 Hz one-sine, m/s^2
    >>> pair = HorizontalPair(Record(4.0 * pulse, 0.005), Record(pulse, 0.005))
    >>> sw = heading_sweep(Shape.box(0.3, 0.3, 1.2, density=2000.0), pair, 4,
    ...                    duration=2.0, step=1e-3)
    >>> sw.table["heading_deg"].tolist(), bool(sw.table["max_tilt"].min() > 0.01)
    ([0.0, 90.0, 180.0, 270.0], True)
    """
    from ..models import get_model

    if not isinstance(pair, HorizontalPair):
        raise ParameterError("pair must be a rocking.motions.HorizontalPair, got "
                             f"{type(pair).__name__}")
    if not isinstance(vertical, bool | np.bool_):
        raise ParameterError(f"vertical must be True or False, got {vertical!r}")
    for k in ("heading", "model"):
        if k in options:
            raise ParameterError(f"{k} is the sweep's (heading_sweep runs model 'rigid3d' "
                                 "at each of its headings)")
    s = as_float("scale", scale)
    if s <= 0.0:
        raise ParameterError(f"scale must be > 0 (a load factor), got {scale!r}")
    body = get_model("rigid3d").check_block(shape)
    hs = _headings(headings)
    base = pair if vertical or pair.vertical is None else HorizontalPair(
        pair.first, pair.second, azimuths=pair.azimuths, name=pair.name)
    if s != 1.0:
        base = base.scaled(s)
    pairs = [base.rotated(-float(h)) for h in hs]
    res = simulate_many(body, pairs, model="rigid3d", duration=duration, heading=0.0,
                        **options)
    alpha = float(body.weakest().alpha)
    out = res.outputs
    table = pd.DataFrame({
        "heading": hs, "heading_deg": np.degrees(hs), "max_tilt": out["max_tilt"],
        "max_tilt_over_alpha": out["max_tilt"] / alpha,
        "overturned": np.asarray(res.overturned, dtype=bool),
        "overturn_time": np.asarray(res.overturn_time, dtype=float),
        "overturn_azimuth": out["overturn_azimuth"],
        "uplift_time": np.asarray(res.uplift_time, dtype=float),
        "n_impacts": np.asarray(res.n_impacts, dtype=int),
        "max_slide": out["max_slide"], "residual_slide": out["residual_slide"],
        "max_twist": out["max_twist"], "residual_twist": out["residual_twist"],
        "lifted_off": np.asarray(out["lifted_off"], dtype=bool),
        "settled": np.asarray(res.settled, dtype=bool),
        "unconverged_steps": out["unconverged_steps"],
    })
    ovt = table.overturned.to_numpy(bool)
    t = np.where(ovt, np.nan_to_num(table.overturn_time.to_numpy(float), nan=np.inf), np.inf)
    w = int(np.lexsort((-np.nan_to_num(table.max_slide.to_numpy(float), nan=-np.inf),
                        -np.nan_to_num(table.max_tilt.to_numpy(float), nan=-np.inf),
                        t, ~ovt))[0])
    table["worst"] = np.arange(len(table)) == w
    table.attrs.update({"model": "rigid3d", "pair": pair.name, "scale": s, "alpha": alpha,
                        "vertical": bool(vertical and pair.vertical is not None)})
    return HeadingSweep(table=table, worst=table.iloc[w], pair=pair, alpha=alpha, scale=s)


__all__ = ["COLUMNS", "HEADING_COLUMNS", "PAIR_IMS", "DirectionFragility", "DirectionSweep",
           "HeadingSweep", "direction_fragility", "direction_sweep", "heading_sweep",
           "pair_im", "plot_sweeps", "worst_index"]
