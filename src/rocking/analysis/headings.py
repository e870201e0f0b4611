"""Fragility by heading of a 3-D body's runs (issue 30): a campaign with a ``heading``
axis (``model = "rigid3d"``, ``[options.rigid3d] heading = [...]``) runs every record
at every heading and level. :func:`heading_fragility` fits, from those rows,

* an overturning fragility curve per heading (as :func:`rocking.analysis.direction_fragility`
  gives one per direction of the planar analysis; where the outcomes of a heading give
  no maximum-likelihood fit, the bounds of its median), and the worst heading (the
  smallest median);
* the pooled curve of all headings (the outcome at a heading drawn uniformly), whose
  interval comes from a bootstrap that resamples RECORDS (:func:`rocking.analysis.fragility`
  with ``bootstrap="cluster"``): each drawn record brings all its runs, at every heading
  and level. The runs of one record at several headings are not independent (the same
  shaking, turned), so a bootstrap of runs, or the GLM's asymptotic normal, gives an
  interval too narrow by up to ``sqrt(number of headings)``.

The per-heading fits resample records too (at one heading a record's levels are one
record scaled). Everything here reads rows; nothing is simulated.

Example: :func:`heading_fragility` on a campaign's table (``rocking.campaign.load``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..errors import ParameterError
from ..plot import LINESTYLES, PALETTE
from .fragility import (
    MIN_CLUSTERS,
    FragilityFit,
    bootstrap_reliable,
    fit_or_bounds,
    fragility,
    unreliable_note,
)

HEADING_FIT_COLUMNS = ("heading_deg", "n", "n_records", "n_overturned", "median", "beta",
                       "median_se", "median_ci_lower", "median_ci_upper",
                       "median_lower_bound", "median_upper_bound", "note", "worst")
"""The columns of :attr:`HeadingFragility.table` (the median and its bounds in the IM's
unit; ``median_ci_*`` the 95 % interval of the by-record bootstrap)."""
CI_LEVEL = 0.95
"""The level of the intervals."""


@dataclass(frozen=True, eq=False)
class HeadingFragility:
    """The result of :func:`heading_fragility`: ``table`` (one row per heading,
    :data:`HEADING_FIT_COLUMNS`), ``fits`` (``{heading_deg: FragilityFit}`` of the headings
    that have one), ``pooled`` (the fit of all headings, its bootstrap by record; None
    when the pooled outcomes give no fit, ``pooled_note`` says why), ``naive_ci`` (the
    pooled median's interval of a bootstrap of runs, for comparison: too narrow),
    ``n_records``, ``im_name``, ``im_unit``. With fewer than
    :data:`~rocking.analysis.fragility.MIN_CLUSTERS` records, or where more than half of
    a bootstrap's replicates have separated outcomes, no interval is given (NaN) and
    ``pooled_note`` (or the heading's ``note``) says why.

    Examples
    --------
    >>> import pandas as pd
    >>> from rocking.analysis.headings import heading_fragility
    >>> rng = np.random.default_rng(0)
    >>> cap = 2.0 * np.exp(0.4 * rng.standard_normal(40))  # one capacity per record
    >>> rows = pd.DataFrame([(r, h, im, bool(im >= cap[r] * (1 + 0.2 * (h == 90))))
    ...                      for r in range(40) for h in (0.0, 90.0)
    ...                      for im in (1.0, 1.5, 2.0, 3.0, 4.0)],
    ...                     columns=["motion", "heading", "im", "overturned"])
    >>> hf = heading_fragility(rows, n_boot=50)
    >>> hf.worst_heading, hf.n_records
    (0.0, 40)
    >>> bool(hf.ci["median"][1] - hf.ci["median"][0] > hf.naive_ci[1] - hf.naive_ci[0])
    True
    """

    table: pd.DataFrame
    fits: dict
    pooled: FragilityFit | None
    pooled_note: str
    naive_ci: tuple
    n_records: int
    im_name: str = "im"
    im_unit: str | None = None

    @property
    def worst_heading(self) -> float:
        """The worst heading (deg): the smallest median (its upper bound where a heading
        has no fit; the first of equal ones, all marked in ``table.worst``); NaN when no
        heading gives either."""
        w = self.table[self.table["worst"]]
        return float(w["heading_deg"].iloc[0]) if len(w) else math.nan

    @property
    def ci(self) -> dict:
        """The pooled fit's intervals (:data:`CI_LEVEL`) of the median and beta, from the
        bootstrap by record."""
        if self.pooled is None or self.pooled.n_boot == 0:
            return {"median": (math.nan, math.nan), "beta": (math.nan, math.nan),
                    "level": CI_LEVEL}
        return self.pooled.ci(CI_LEVEL)

    def plot(self, *, title: str | None = None, scale: float = 1.0, unit: str | None = None):
        """Left: the median IM of overturning against the heading on polar axes (a dot
        per fitted heading with its by-record 95 % interval as a radial bar; where no fit
        exists, a bar between the bounds of the median), the pooled median as a circle
        with its interval shaded, the worst heading marked. Right: the curves of the
        worst and the best heading and the pooled curve with its by-record band.
        ``scale`` divides the IM for the polar axes (``G`` and ``unit="g"``: in g).
        Returns the figure.

        Examples
        --------
        >>> import pandas as pd
        >>> from rocking.analysis.headings import heading_fragility
        >>> rng = np.random.default_rng(0)
        >>> cap = 2.0 * np.exp(0.4 * rng.standard_normal(30))
        >>> rows = pd.DataFrame([(r, h, im, bool(im >= cap[r])) for r in range(30)
        ...                      for h in (0.0, 45.0, 90.0) for im in (1.0, 2.0, 4.0)],
        ...                     columns=["motion", "heading", "im", "overturned"])
        >>> fig = heading_fragility(rows, n_boot=20).plot()
        >>> [ax.name for ax in fig.axes]
        ['polar', 'rectilinear']
        """
        from matplotlib.figure import Figure

        from ..plot import im_label, style_axes, unit_label

        t = self.table.sort_values("heading_deg")
        unit = unit_label(unit if unit is not None else (self.im_unit or ""))
        fig = Figure(figsize=(12.5, 5.4), layout="constrained")
        axp = fig.add_subplot(1, 2, 1, projection="polar")
        axc = fig.add_subplot(1, 2, 2)
        h = np.radians(t["heading_deg"].to_numpy(float)) % (2 * math.pi)
        med = t["median"].to_numpy(float) / scale
        clo = t["median_ci_lower"].to_numpy(float) / scale
        chi = t["median_ci_upper"].to_numpy(float) / scale
        lo = t["median_lower_bound"].to_numpy(float) / scale
        hi = t["median_upper_bound"].to_numpy(float) / scale
        pooled = math.nan if self.pooled is None else self.pooled.median / scale
        plo, phi = (v / scale for v in self.ci["median"])
        finite = np.concatenate([med, chi, lo, hi, [pooled, phi, 1e-9]])
        finite = finite[np.isfinite(finite)]
        top = 1.15 * float(finite.max())
        fitted = np.isfinite(med)
        ring = np.linspace(0.0, 2 * math.pi, 181)
        if math.isfinite(pooled):
            if math.isfinite(plo) and math.isfinite(phi):
                axp.fill_between(ring, min(plo, top), min(phi, top), color=PALETTE[2],
                                 alpha=0.18, lw=0,
                                 label=f"all headings: {100 * CI_LEVEL:g}% interval "
                                       "(bootstrap by record)")
            axp.plot(ring, np.full_like(ring, pooled), color=PALETTE[2], lw=1.2, ls="--",
                     label=f"all headings: median {pooled:.3g} {unit}")
        if fitted.any():
            x, y = h[fitted], med[fitted]
            if fitted.all() and len(x) > 2 and np.ptp(x) > 1.5 * math.pi:  # all round
                x, y = np.append(x, x[0]), np.append(y, y[0])
            axp.plot(x, y, "-o", ms=4, color=PALETTE[0], lw=1.2,
                     label="median of each heading's fit")
            for i in np.flatnonzero(fitted & np.isfinite(clo) & np.isfinite(chi)):
                axp.plot([h[i], h[i]], [clo[i], min(chi[i], top)], color=PALETTE[0],
                         lw=2, alpha=0.45,
                         label=(f"{100 * CI_LEVEL:g}% interval (by record)"
                                if i == np.flatnonzero(fitted)[0] else None))
        first = True
        for i in np.flatnonzero(~fitted):
            a = 0.0 if np.isnan(lo[i]) else lo[i]
            b = top if np.isnan(hi[i]) else hi[i]
            if np.isnan(lo[i]) and np.isnan(hi[i]):
                continue
            axp.plot([h[i], h[i]], [a, b], color=PALETTE[1], lw=3, alpha=0.7,
                     solid_capstyle="butt",
                     label="no fit: bounds of the median" if first else None)
            first = False
        w = self.table[self.table["worst"]]
        if 0 < len(w) < len(self.table):
            for j, wd in enumerate(w["heading_deg"].to_numpy(float)):
                axp.plot([math.radians(wd)] * 2, [0.0, top], color="k", ls=":", lw=1.0,
                         label=None if j else "worst: " + ", ".join(
                             f"{v:g}" for v in w["heading_deg"]) + " deg")
        axp.set_ylim(0.0, top)
        axp.set_theta_zero_location("E")
        axp.set_theta_direction(1)
        axp.set_title(f"Median {im_label(self.im_name)} of overturning ({unit}) by heading\n"
                      "(deg, ccw: the body's x axis from the\npair's first component)",
                      fontsize=10)
        fig.legend(*axp.get_legend_handles_labels(), fontsize=8, loc="outside lower left",
                   frameon=False, ncol=2)
        picks = []
        if self.fits:
            order = sorted(self.fits, key=lambda k: self.fits[k].median)
            same = math.isclose(self.fits[order[0]].median, self.fits[order[-1]].median,
                                rel_tol=1e-9)
            picks = [order[0]] + ([order[-1]] if len(order) > 1 and not same else [])
        for n, k in enumerate(picks):
            f = self.fits[k]
            f.plot(axc, data=False, band=False, color=PALETTE[n % len(PALETTE)],
                   ls=LINESTYLES[n % len(LINESTYLES)],
                   label=f"{'worst' if n == 0 and len(picks) > 1 else 'best' if n else 'every'}"
                         f" heading{'' if len(picks) < 2 else ' ' + format(k, 'g') + ' deg'}"
                         ": median "
                         f"{f.median / scale:.3g} {unit}, beta {f.beta:.2f}")
        if self.pooled is not None:
            self.pooled.plot(axc, data=False, band=self.pooled.n_boot > 0, color=PALETTE[2],
                             ls="--", label=f"all headings: median "
                                            f"{self.pooled.median / scale:.3g} {unit}, "
                                            f"beta {self.pooled.beta:.2f}")
        if picks or self.pooled is not None:
            axc.set_title("Fragility: the worst and the best heading, and all headings",
                          fontsize=10)
            style_axes(axc, axc.get_xlabel(), "probability of overturning")
        else:
            axc.set_axis_off()
            axc.text(0.5, 0.5, "no fragility fit\n(outcomes separated by the level: the "
                     "bounds of the median, left)", ha="center", va="center",
                     transform=axc.transAxes)
        fig.suptitle(title or f"Overturning fragility by heading ({len(t)} headings, "
                     f"{self.n_records} records)", fontsize=11)
        return fig


def _column(rows: pd.DataFrame, name: str, what: str) -> np.ndarray:
    if name not in rows.columns:
        raise ParameterError(f"{what}: the rows have no column {name!r} (columns: "
                             f"{', '.join(map(str, rows.columns))})")
    return rows[name].to_numpy()


def heading_fragility(rows: pd.DataFrame, *, im: str = "im", failed: str = "overturned",
                      heading: str = "heading", record: str = "motion", n_boot: int = 200,
                      seed: int | None = 0, im_name: str | None = None,
                      im_unit: str | None = None) -> HeadingFragility:
    """Fragility by heading, the worst heading and the pooled fit with a bootstrap by
    record (module docstring), from ``rows``: one row per run with the columns ``im``
    (the IM, > 0), ``failed`` (the outcome), ``heading`` (deg) and ``record`` (the
    record's label: every run with the same label is one cluster of the bootstrap;
    a campaign's ``motion``).

    Each heading's curve: :func:`rocking.analysis.fragility` of its runs, its interval
    from ``n_boot`` draws of its records (``bootstrap="cluster"``), or the bounds of its
    median (:func:`rocking.analysis.fragility.fit_or_bounds`). The worst heading has the
    smallest median (a heading without a fit counts with its upper bound, if any). The
    pooled curve fits all runs; its band and interval resample the records, each with its
    runs at every heading and level; ``naive_ci`` is the same interval from a bootstrap
    of runs (``bootstrap="resample"``), which treats them as independent.

    Raises :class:`~rocking.ParameterError` when a column is missing, a heading is not
    finite, or fewer than two records are given.

    Examples
    --------
    Two headings, the one at 90 deg weaker by construction:

    >>> import pandas as pd
    >>> from rocking.analysis import heading_fragility
    >>> rng = np.random.default_rng(1)
    >>> cap = 2.0 * np.exp(0.4 * rng.standard_normal(30))  # one capacity per record
    >>> rows = pd.DataFrame([(r, h, im, bool(im >= cap[r] / (1 + 0.3 * (h == 90))))
    ...                      for r in range(30) for h in (0.0, 90.0)
    ...                      for im in (0.5, 1.0, 1.5, 2.0, 3.0, 4.0)],
    ...                     columns=["motion", "heading", "im", "overturned"])
    >>> hf = heading_fragility(rows, n_boot=20)
    >>> hf.worst_heading, hf.n_records
    (90.0, 30)
    """
    for k, v in (("im", im), ("failed", failed), ("heading", heading), ("record", record)):
        if not isinstance(v, str):
            raise ParameterError(f"{k} must be a column name, got {v!r}")
    if not isinstance(rows, pd.DataFrame) or rows.empty:
        raise ParameterError("rows must be a non-empty pandas DataFrame (one row per run)")
    x = np.asarray(_column(rows, im, "im"), dtype=float)
    y = np.asarray(_column(rows, failed, "failed")).astype(bool)
    hd = np.asarray(_column(rows, heading, "heading"), dtype=float)
    rec = _column(rows, record, "record")
    if not np.all(np.isfinite(hd)):
        raise ParameterError(f"heading: the column {heading!r} has non-finite values")
    n_rec = int(pd.unique(rec).size)
    if n_rec < 2:
        raise ParameterError(f"record: the column {record!r} names {n_rec} record; a "
                             "bootstrap by record needs at least 2")
    name = im_name or im
    note = ""
    if n_boot and n_rec < MIN_CLUSTERS:
        note = (f"no intervals: {n_rec} records are too few for a bootstrap by record (at "
                f"least {MIN_CLUSTERS})")
        n_boot = 0
    kw = {"n_boot": n_boot, "seed": seed, "im_name": name, "im_unit": im_unit}
    out, fits = [], {}
    for hv in np.unique(hd):
        sel = hd == hv
        row = {"heading_deg": float(hv), "n": int(sel.sum()),
               "n_records": int(pd.unique(rec[sel]).size), "n_overturned": int(y[sel].sum()),
               "median": math.nan, "beta": math.nan, "median_se": math.nan,
               "median_ci_lower": math.nan, "median_ci_upper": math.nan,
               "median_lower_bound": math.nan, "median_upper_bound": math.nan, "note": ""}
        boot = "cluster" if row["n_records"] >= MIN_CLUSTERS and n_boot else "normal"
        try:
            fit, lo, hi, why = fit_or_bounds(
                x[sel], y[sel], bootstrap=boot, label=f"overturning, {hv:g} deg",
                clusters=rec[sel] if boot == "cluster" else None, **kw)
        except ParameterError as e:
            fit, lo, hi, why = None, math.nan, math.nan, str(e)
        if fit is not None:
            fits[float(hv)] = fit
            row.update(median=fit.median, beta=fit.beta, median_se=fit.median_se)
            if boot == "cluster" and bootstrap_reliable(fit):
                row["median_ci_lower"], row["median_ci_upper"] = fit.ci(CI_LEVEL)["median"]
            elif boot == "cluster":
                row["note"] = unreliable_note(fit)
        else:
            row.update(median_lower_bound=lo, median_upper_bound=hi,
                       note=f"no fragility fit ({why}): bounds of the median")
        out.append(row)
    table = pd.DataFrame(out)
    est = np.where(np.isfinite(table["median"]), table["median"],
                   np.where(np.isfinite(table["median_upper_bound"]),
                            table["median_upper_bound"], np.inf))
    table["worst"] = False
    if np.isfinite(est).any():  # ties (a symmetric body): every one of them
        table["worst"] = est <= np.min(est) * (1.0 + 1e-9)
    table = table[list(HEADING_FIT_COLUMNS)]
    pooled, naive = None, (math.nan, math.nan)
    try:
        pooled = fragility(x, y, bootstrap="cluster" if n_boot else "normal",
                           clusters=rec if n_boot else None, label="overturning, all headings",
                           **kw)
        if n_boot and not bootstrap_reliable(pooled):
            note = unreliable_note(pooled)
            pooled = fragility(x, y, n_boot=0, seed=seed, label="overturning, all headings",
                               im_name=name, im_unit=im_unit)
        elif n_boot:
            naive = fragility(x, y, bootstrap="resample", **kw).ci(CI_LEVEL)["median"]
    except ParameterError as e:
        note = f"no pooled fit: {e}"
    return HeadingFragility(table=table, fits=fits, pooled=pooled, pooled_note=note,
                            naive_ci=tuple(naive), n_records=n_rec, im_name=name,
                            im_unit=im_unit)


__all__ = ["HeadingFragility", "heading_fragility", "HEADING_FIT_COLUMNS"]
