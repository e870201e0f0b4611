"""Compare mitigations (issue 19): fragility, hazard and isolator demand per mitigation.

:func:`compare_mitigations` takes a table of simulations (one row per run, as a campaign
with ``[[mitigation]]`` produces it) and, for each group (block, floor, ...) and each
mitigation, fits a lognormal fragility curve with the package's :func:`~.fragility.fragility`
(a probit GLM on ``ln im`` by maximum likelihood, the multiple-stripe likelihood of
Baker 2015, Eq. 11; bootstrap ``"normal"``: the asymptotic distribution of the MLE),
compares its median with that of the unmitigated block (``"none"``), integrates it over a
hazard curve with :func:`~.fragility.annual_frequency` (Cornell et al. 2002,
``lambda_f = int P(f | im) |d lambda / d im| d im``) and summarises the isolator's
displacement demand against a clearance.

A mitigation that never (or always) fails in a group has no fragility fit (the MLE does
not exist): its median is NaN, with a ``note`` and a bound (``median_lower_bound``: the
largest IM run without failure), never an invented number.

References: J. W. Baker (2015), Efficient analytical fragility function fitting using
dynamic structural analysis, Earthquake Spectra 31(1). C. A. Cornell, F. Jalayer,
R. O. Hamburger, D. A. Foutch (2002), Probabilistic basis for 2000 SAC Federal Emergency
Management Agency steel moment frame guidelines, J. Struct. Eng. 128(4).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
import pandas as pd

from ..errors import ParameterError
from ..plot import PALETTE, im_label, plain_log_ticks, style_axes, unit_label
from ..units import acceleration_unit, parse_quantity
from .fragility import (
    IM_UNITS,
    FragilityFit,
    annual_frequency,
    as_bool_array,
    fit_or_bounds,
)
from .hazard import RETURN_PERIODS, HazardCurve, probability_in, risk

FAILURES = ("overturned", "overturned_or_clearance")
"""What counts as a failure: the block overturned, or (also) the isolator reached its
clearance (the base hit the moat)."""
DEFAULT_BY = ("block_name", "floor", "height_ratio")
"""The grouping columns used by default, those present in the table."""
REFERENCE = "none"
"""The name of the unmitigated entry (the block as it stands), the reference of the
ratios."""
IM_NAMES = {"pga": "PGA", "floor_pga": "floor PGA", "im": "IM"}

#: The columns of :attr:`MitigationComparison.table`, after the grouping columns.
COLUMNS = (
    "mitigation", "model", "n", "n_failed", "n_excluded", "n_unsettled", "im_min", "im_max",
    "median", "beta", "median_ci_low", "median_ci_high", "beta_ci_low", "beta_ci_high",
    "median_lower_bound", "median_upper_bound", "median_ratio", "median_ratio_lower_bound",
    "annual_frequency", "annual_frequency_lower_bound", "annual_frequency_upper_bound",
    "annual_frequency_ratio", "annual_frequency_low", "annual_frequency_high",
    "probability", "failure", "verdict", "reason", "displacement_max",
    "n_clearance_exceeded", "p_clearance_exceeded", "clearance",
    "clearance_annual_frequency", "clearance_probability", "note",
)
"""The per-return-period columns of the isolator's demand follow (:func:`demand_columns`)."""

VERDICTS = ("reference", "better", "worse", "same", "not distinguishable", "not known")
"""``verdict`` of a mitigation against the reference ("none"): its annual frequency of
failure (with a hazard), else its median, compared with the reference's; "not
distinguishable" where both annual frequencies have intervals (``annual_frequency_low`` /
``_high``) and they overlap: the difference of the estimates is within what the records
leave uncertain, so neither "better" nor "worse" is claimed."""
AMPLIFY_BAND = (0.7, 1.4)
"""An isolator whose period is within this ratio of the building's period is near
resonance with the floor's motion (a likely reason for an isolator that makes it worse)."""


def demand_columns(T: float) -> tuple[str, ...]:
    """The columns of the isolator's demand at return period ``T`` (years): the IM there
    (``im_<T>yr``), the median and 84th percentile of the base displacement at that IM
    (``displacement_median_<T>yr``, ``displacement_p84_<T>yr``, m) and the probability
    that it reaches the clearance there (``p_clearance_<T>yr``).

    Examples
    --------
    >>> from rocking.analysis.mitigation import demand_columns
    >>> demand_columns(475)
    ('im_475yr', 'displacement_median_475yr', 'displacement_p84_475yr', 'p_clearance_475yr')
    """
    t = f"{T:g}yr"
    return (f"im_{t}", f"displacement_median_{t}", f"displacement_p84_{t}", f"p_clearance_{t}")


# --------------------------------------------------------------------------- inputs

def unit_kind(unit: str | None):
    """``(kind, SI value of one unit)`` of an IM unit (``"g"`` -> acceleration, 9.80665),
    None if not known (the units of :data:`rocking.analysis.fragility.IM_UNITS`, and any
    spelling of an acceleration that :func:`rocking.units.acceleration_unit` knows)."""
    if unit is None:
        return None
    u = str(unit).strip()
    for key in (u, u.replace(" ", ""), u.replace(" ", "").lower()):
        if key in IM_UNITS:
            return IM_UNITS[key]
    acc = acceleration_unit(u)
    return IM_UNITS.get(acc) if acc else None


def parse_hazard(hazard, im_unit: str | None):
    """``(hazard_im, hazard_rate)`` in the IM unit ``im_unit``, from ``(im, rate, unit)`` or
    ``{"im": ..., "rate": ..., "unit": ...}``. A hazard in another unit of the same kind
    (g against m/s^2) is converted; one of another kind, or an unknown unit, is refused."""
    if isinstance(hazard, dict):
        missing = [k for k in ("im", "rate", "unit") if k not in hazard]
        extra = sorted(set(hazard) - {"im", "rate", "unit"})
        if missing or extra:
            raise ParameterError(f"hazard must be a dict with keys 'im', 'rate' and 'unit' "
                                 f"(missing {missing}, unknown {extra})")
        x, rate, unit = hazard["im"], hazard["rate"], hazard["unit"]
    elif isinstance(hazard, list | tuple):
        if len(hazard) != 3:
            raise ParameterError("hazard must be (im_values, annual_rates, unit), e.g. "
                                 f"([0.1, 0.5, 1.0], [1e-2, 1e-3, 1e-4], 'g'); got "
                                 f"{len(hazard)} items (the unit is required)")
        x, rate, unit = hazard
    else:
        raise ParameterError("hazard must be (im_values, annual_rates, unit) or a dict "
                             f"{{'im', 'rate', 'unit'}}, got {type(hazard).__name__}")
    if not isinstance(unit, str) or not unit.strip():
        raise ParameterError(f"hazard unit must be a unit string such as 'g' or 'm/s^2', "
                             f"got {unit!r}")
    if im_unit is None:
        raise ParameterError("im_unit is required with a hazard curve: the IM's unit "
                             "must be known to check the hazard's")
    try:
        x = np.atleast_1d(np.asarray(x, dtype=float))
        rate = np.atleast_1d(np.asarray(rate, dtype=float))
    except (TypeError, ValueError):
        raise ParameterError("hazard im and rate must be arrays of numbers") from None
    a, b = unit_kind(im_unit), unit_kind(unit)
    if a is None or b is None:
        if str(unit).replace(" ", "").lower() != str(im_unit).replace(" ", "").lower():
            raise ParameterError(f"hazard unit {unit!r} cannot be checked against im_unit "
                                 f"{im_unit!r} (unknown unit): give both in known units "
                                 f"({', '.join(sorted(IM_UNITS))})")
        factor = 1.0
    elif a[0] != b[0]:
        raise ParameterError(f"hazard unit {unit!r} ({b[0]}) is incompatible with im_unit "
                             f"{im_unit!r} ({a[0]}): the hazard curve must be of the IM "
                             "that the fragility is fitted on")
    else:
        factor = b[1] / a[1]
    x = x * factor

    class _Never:  # validates the curve through annual_frequency (its checks, not copies)
        def probability(self, im):
            return np.zeros_like(np.asarray(im, dtype=float))

    annual_frequency(_Never(), x, rate)
    return x, rate


def rate_at(x: float, hx: np.ndarray, hr: np.ndarray) -> float:
    """The hazard curve's rate at ``x`` (log-log interpolation); NaN outside it."""
    if not (math.isfinite(x) and hx[0] <= x <= hx[-1]):
        return math.nan
    return float(np.exp(np.interp(math.log(x), np.log(hx), np.log(hr))))


def parse_clearance(clearance) -> float:
    """The clearance in m (a number in m, or a quantity such as ``"0.15m"``), > 0."""
    if clearance is None:
        return math.nan
    if isinstance(clearance, bool):
        raise ParameterError(f"clearance must be a length > 0 (m), got {clearance!r}")
    if isinstance(clearance, str):
        c = parse_quantity(clearance, "length", name="clearance", default_unit="m")
    else:
        try:
            c = float(clearance)
        except (TypeError, ValueError):
            raise ParameterError(f"clearance must be a length > 0 (m) such as 0.15 or "
                                 f"'15cm', got {clearance!r}") from None
    if not (math.isfinite(c) and c > 0):
        raise ParameterError(f"clearance must be a finite length > 0 (m), got {clearance!r}")
    return c


def _flags(table: pd.DataFrame, col: str) -> np.ndarray:
    """A flag column as floats: 1, 0 or NaN (missing: a row of a model without it)."""
    if col not in table:
        return np.full(len(table), np.nan)
    v = table[col]
    out = pd.to_numeric(v.map(lambda e: float(e) if isinstance(e, bool | np.bool_) else e),
                        errors="coerce").to_numpy(float)
    bad = np.isfinite(out) & (out != 0) & (out != 1)
    if bad.any():
        first = v.iloc[np.flatnonzero(bad)[0]]
        raise ParameterError(f"column {col!r} must be boolean, got {first!r}")
    return out


def _check_table(table, im, failure, by, mit_col):
    if not isinstance(table, pd.DataFrame):
        raise ParameterError(f"table must be a pandas DataFrame (one row per run), got "
                             f"{type(table).__name__}")
    if len(table) == 0:
        raise ParameterError("table is empty: no run to compare")
    if failure not in (*FAILURES, "auto"):
        raise ParameterError(f"failure must be one of {(*FAILURES, 'auto')}, got {failure!r}")
    if not isinstance(im, str):
        raise ParameterError(f"im must be a column name such as 'pga', got {im!r}")
    need = [im, "overturned"]
    missing = [c for c in need if c not in table.columns]
    if missing:
        raise ParameterError(f"table has no column {missing[0]!r} (needed: {need}; the "
                             f"columns are {list(table.columns)})")
    if mit_col is None:
        raise ParameterError("table needs a 'mitigation' column (or a 'model' column) "
                             "naming the mitigation of each run")
    if by is None:
        by = [c for c in DEFAULT_BY if c in table.columns]
    else:
        by = [by] if isinstance(by, str) else list(by)
        for c in by:
            if not isinstance(c, str) or c not in table.columns:
                raise ParameterError(f"by: table has no column {c!r} (columns: "
                                     f"{list(table.columns)})")
        if mit_col in by:
            raise ParameterError(f"by must not contain {mit_col!r}: the mitigations are "
                                 "compared within each group")
    return by


# --------------------------------------------------------------------------- one fit

def _bins(x: np.ndarray, max_levels: int = 25):
    """``(idx, im)``: the IM level of each run; with more than ``max_levels`` distinct IMs,
    bins of equal count in ``ln im`` (``im``: the geometric mean of the bin)."""
    levels = np.unique(x)
    if levels.size <= max_levels:
        return np.searchsorted(levels, x), levels
    edges = np.quantile(np.log(x), np.linspace(0, 1, 11))
    idx = np.clip(np.searchsorted(edges, np.log(x), side="right") - 1, 0, 9)
    keep = np.unique(idx)
    idx = np.searchsorted(keep, idx)
    return idx, np.array([math.exp(np.log(x[idx == k]).mean()) for k in range(keep.size)])


def _stripes(x: np.ndarray, y: np.ndarray, max_levels: int = 25) -> pd.DataFrame:
    """The observed failed fraction per IM level (``im``, ``n``, ``n_failed``); with more
    than ``max_levels`` distinct IMs, per bin of equal count in ``ln im`` (``im``: the
    geometric mean of the bin)."""
    idx, im = _bins(x, max_levels)
    n = np.bincount(idx, minlength=im.size)
    k = np.bincount(idx, weights=y.astype(float), minlength=im.size).astype(int)
    return pd.DataFrame({"im": im, "n": n, "n_failed": k})


def _fit_one(x, y, *, im, im_unit, n_boot, seed, label):
    """``(fit or None, row fields)``: the fragility fit, or, when :func:`~.fragility.fragility`
    refuses the data (its ``check_separation``: the MLE does not exist), the bounds of the
    median that the data do give and a note."""
    name = IM_NAMES.get(im, im)
    unit = f" {im_unit}" if im_unit else ""
    out = {"median": math.nan, "beta": math.nan, "median_ci_low": math.nan,
           "median_ci_high": math.nan, "beta_ci_low": math.nan, "beta_ci_high": math.nan,
           "median_lower_bound": math.nan, "median_upper_bound": math.nan, "note": ""}
    fit, lo, hi, why = fit_or_bounds(x, y, n_boot=n_boot, seed=seed, im_name=im,
                                     im_unit=im_unit, label=label)
    if fit is None:
        out["median_lower_bound"], out["median_upper_bound"] = lo, hi
        if why == "none failed":  # P(f | im <= im_max) is small: the median is above
            out["note"] = f"no failure up to {name} = {lo:.4g}{unit} ({y.size} runs)"
        elif why == "all failed":
            out["note"] = (f"every run failed, down to {name} = {hi:.4g}{unit} "
                           f"({y.size} runs)")
        elif why == "separated":
            out["note"] = (f"outcomes separated by the IM (no failure up to {name} = "
                           f"{lo:.4g}{unit}, every run failed from {hi:.4g}"
                           f"{unit}): no fit (beta -> 0); the median lies between them")
        else:
            out["note"] = ("no fragility fit: failures happen only at lower IM than the "
                           "survivals")
        return None, out
    out.update(median=fit.median, beta=fit.beta)
    if fit.n_boot:
        with np.errstate(invalid="ignore"):  # draws with b1 <= 0: an infinite median
            ci = fit.ci(0.95)
        out.update(median_ci_low=ci["median"][0], median_ci_high=ci["median"][1],
                   beta_ci_low=ci["beta"][0], beta_ci_high=ci["beta"][1])
    if fit.median > x.max() or fit.median < x.min():
        out["note"] = (f"median extrapolated beyond the IMs run ({x.min():.4g} to "
                       f"{x.max():.4g}{unit})")
    return fit, out


def demand_stripes(x: np.ndarray, d: np.ndarray, exceeded: np.ndarray,
                   cap: float = math.inf) -> pd.DataFrame:
    """The isolator's displacement demand per IM level (the levels of :func:`_stripes`):
    ``im``, ``n`` (runs with a displacement), ``displacement_median``,
    ``displacement_p84`` (m), ``p_clearance`` (the share of runs known to reach the
    clearance) and ``censored`` (True where a quantile is at or above ``cap``, the
    smallest displacement at which the model stopped a run: runs stopped at the moat have
    their clearance as maximum, so such a quantile is a lower bound only).

    Examples
    --------
    >>> from rocking.analysis.mitigation import demand_stripes
    >>> x = np.repeat([1.0, 2.0], 4)  # PGA (m/s^2)
    >>> d = np.array([.01, .02, .03, .04, .02, .04, .06, .08])  # max |u| (m)
    >>> t = demand_stripes(x, d, d >= 0.05)
    >>> t[["im", "n", "displacement_median", "p_clearance"]].values.tolist()
    [[1.0, 4.0, 0.025, 0.0], [2.0, 4.0, 0.05, 0.5]]
    """
    idx, im = _bins(x)
    rows = []
    for k, level in enumerate(im):
        sel = idx == k
        dk = d[sel]
        dk = dk[np.isfinite(dk)]
        ek = exceeded[sel]
        ek = ek[np.isfinite(ek)]
        med = float(np.median(dk)) if dk.size else math.nan
        p84 = float(np.percentile(dk, 84)) if dk.size else math.nan
        rows.append({"im": float(level), "n": int(dk.size), "displacement_median": med,
                     "displacement_p84": p84,
                     "p_clearance": float(ek.mean()) if ek.size else math.nan,
                     "censored": bool(dk.size and p84 >= cap)})
    return pd.DataFrame(rows)


def demand_at(stripes: pd.DataFrame, im: float) -> dict:
    """The demand of :func:`demand_stripes` at the IM ``im``: the median, 84th percentile
    and P(reaching the clearance) interpolated between the levels (log-log for the
    displacements, linear in ``ln im`` for the probability); NaN beyond the IMs run (no
    extrapolation) and ``"beyond"`` then True; ``censored`` where a level used is.

    Examples
    --------
    >>> import pandas as pd
    >>> from rocking.analysis.mitigation import demand_at
    >>> s = pd.DataFrame({"im": [1.0, 4.0], "n": [9, 9], "displacement_median": [0.01, 0.04],
    ...                   "displacement_p84": [0.02, 0.08], "p_clearance": [0.0, 0.5],
    ...                   "censored": [False, False]})
    >>> {k: round(v, 4) for k, v in demand_at(s, 2.0).items() if k.startswith(("d", "p"))}
    {'displacement_median': 0.02, 'displacement_p84': 0.04, 'p_clearance': 0.25}
    """
    nan = {"displacement_median": math.nan, "displacement_p84": math.nan,
           "p_clearance": math.nan, "censored": False, "beyond": True}
    s = stripes[(stripes["n"] > 0) & (stripes["displacement_median"] > 0)]
    if len(s) == 0 or not math.isfinite(im) or im <= 0:
        return nan
    x = np.log(s["im"].to_numpy(float))
    u = math.log(im)
    if not x[0] - 1e-12 <= u <= x[-1] + 1e-12:
        return nan
    out = {"beyond": False}
    for col in ("displacement_median", "displacement_p84"):
        out[col] = float(np.exp(np.interp(u, x, np.log(s[col].to_numpy(float)))))
    out["p_clearance"] = float(np.interp(u, x, s["p_clearance"].to_numpy(float)))
    j = np.searchsorted(x, u)
    near = s["censored"].to_numpy(bool)[max(j - 1, 0):j + 1]
    out["censored"] = bool(near.any())
    return {k: out[k] for k in ("displacement_median", "displacement_p84", "p_clearance",
                                "censored", "beyond")}


# --------------------------------------------------------------------------- result

class MitigationComparison:
    """The result of :func:`compare_mitigations`.

    ``table``: one row per (group..., mitigation) (see :func:`compare_mitigations` for the
    columns); ``fits``: the fitted :class:`~.fragility.FragilityFit` by key (the
    mitigation's name without grouping columns, else the tuple ``(*group, mitigation)``;
    the mitigations that could not be fitted are absent); ``stripes``: the observed
    failed fraction per IM level, same keys, every mitigation; ``keys``: the key of each
    row of ``table``; ``by``, ``im``, ``im_unit``,
    ``failure``, ``clearance``, ``reference``.

    Examples
    --------
    >>> import pandas as pd
    >>> from rocking.analysis import compare_mitigations
    >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
    >>> j = np.tile(np.arange(10), 5)
    >>> runs = pd.concat([pd.DataFrame({"mitigation": "none", "pga": im,
    ...                                 "overturned": j < np.repeat([1, 3, 5, 7, 9], 10)}),
    ...                   pd.DataFrame({"mitigation": "anchored", "pga": im,
    ...                                 "overturned": np.zeros(50, bool)})])
    >>> cmp = compare_mitigations(runs, n_boot=0)
    >>> cmp
    MitigationComparison(2 rows, mitigations ['none', 'anchored'], by [], failure 'overturned')
    >>> list(cmp.fits)  # the anchored block never failed: no fit, a bound instead
    ['none']
    >>> float(cmp.table.set_index("mitigation").loc["anchored", "median_lower_bound"])
    8.0
    """

    def __init__(self, table, fits, stripes, *, by, im, im_unit, failure, clearance,
                 reference, hazard=None, keys=None, demand=None, return_periods=(),
                 t_years=50.0):
        self.table = table
        self.keys = list(keys) if keys is not None else [
            self.key(r["mitigation"], tuple(r[c] for c in by)) for _, r in table.iterrows()]
        """The key of each row of :attr:`table` (in :attr:`fits` and :attr:`stripes`)."""
        self.fits = fits
        self.stripes = stripes
        self.by = list(by)
        self.im = im
        self.im_unit = im_unit
        self.failure = failure
        self.clearance = clearance
        self.reference = reference
        self.hazard = hazard
        self.demand = demand or {}
        """The isolator's displacement demand per IM level (:func:`demand_stripes`) by key,
        for the mitigations whose runs have a ``max_base_displacement``."""
        self.return_periods = tuple(return_periods)
        self.t_years = t_years

    def __repr__(self) -> str:
        mits = list(dict.fromkeys(self.table["mitigation"]))
        return (f"MitigationComparison({len(self.table)} rows, mitigations {mits}, by "
                f"{self.by}, failure {self.failure!r})")

    def key(self, mitigation: str, group=()) -> object:
        """The key of :attr:`fits` for ``mitigation`` in ``group`` (a tuple of the ``by``
        values).

        Examples
        --------
        >>> import pandas as pd
        >>> from rocking.analysis import compare_mitigations
        >>> im, j = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10), np.tile(np.arange(10), 5)
        >>> runs = pd.concat([pd.DataFrame({"mitigation": name, "pga": im,  # m/s^2
        ...                                 "overturned": j < np.repeat(k, 10)})
        ...                   for name, k in (("none", [1, 3, 5, 7, 9]),
        ...                                   ("isolated", [0, 1, 3, 5, 7]))])
        >>> cmp = compare_mitigations(runs, n_boot=0)  # no grouping: the name is the key
        >>> cmp.key("isolated"), cmp.fits[cmp.key("isolated")].label
        ('isolated', 'isolated')
        >>> two = pd.concat([runs.assign(block_name=b) for b in ("B2", "B3")])
        >>> compare_mitigations(two, n_boot=0).key("isolated", "B3")  # grouped by block_name
        ('B3', 'isolated')
        """
        group = group if isinstance(group, tuple) else (group,)
        return tuple(group) + (mitigation,) if self.by else mitigation

    def to_frame(self) -> pd.DataFrame:
        """A copy of :attr:`table`.

        Examples
        --------
        >>> import pandas as pd
        >>> from rocking.analysis import compare_mitigations
        >>> im, j = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10), np.tile(np.arange(10), 5)
        >>> runs = pd.concat([pd.DataFrame({"mitigation": name, "pga": im,  # m/s^2
        ...                                 "overturned": j < np.repeat(k, 10)})
        ...                   for name, k in (("none", [1, 3, 5, 7, 9]),
        ...                                   ("isolated", [0, 1, 3, 5, 7]))])
        >>> cmp = compare_mitigations(runs, n_boot=0)
        >>> df = cmp.to_frame()
        >>> df is not cmp.table and df.equals(cmp.table)
        True
        >>> r = df.set_index("mitigation")  # the isolated block's median over the reference's
        >>> bool(np.isclose(r.loc["isolated", "median_ratio"],
        ...                 r.loc["isolated", "median"] / r.loc["none", "median"]))
        True
        """
        return self.table.copy()

    def plot(self, **kw):
        """:func:`plot_mitigations` of this comparison; returns the Figure.

        Examples
        --------
        >>> import pandas as pd
        >>> from rocking.analysis import compare_mitigations
        >>> im, j = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10), np.tile(np.arange(10), 5)
        >>> runs = pd.concat([pd.DataFrame({"mitigation": name, "pga": im,  # m/s^2
        ...                                 "overturned": j < np.repeat(k, 10)})
        ...                   for name, k in (("none", [1, 3, 5, 7, 9]),
        ...                                   ("isolated", [0, 1, 3, 5, 7]))])
        >>> cmp = compare_mitigations(runs, n_boot=0)
        >>> ax = cmp.plot().axes[0]
        >>> ax.get_xlabel(), ax.get_ylabel()
        ('PGA (m/s$^2$)', 'P(overturned)')
        >>> legend = [t.get_text() for t in ax.get_legend().get_texts()]
        >>> legend[0]
        'none: median 2 m/s$^2$, beta 1.14'
        >>> legend[1].splitlines()  # every mitigation states its ratio to none
        ['isolated: median 4.11 m/s$^2$, beta 1.06', '2.05 × the median of none: better']
        >>> from rocking.analysis import plot_mitigations  # the same figure
        >>> ax2 = plot_mitigations(cmp).axes[0]
        >>> [t.get_text() for t in ax2.get_legend().get_texts()] == legend
        True
        """
        return plot_mitigations(self, **kw)


def _lifted_planar(table) -> np.ndarray:
    """The runs a planar model stopped because the block left the ground (``lifted_off``:
    ``g + a_v <= 0``, which it cannot represent): neither overturned nor survived, so left
    out of the comparison, as failed runs are (a 3-D model follows the flight)."""
    if "lifted_off" not in table:
        return np.zeros(len(table), bool)
    lifted = table["lifted_off"].fillna(False).to_numpy(bool)
    if "model" not in table:
        return lifted
    from ..models.registry import MODELS

    planar = table["model"].map(lambda m: bool(MODELS[m].tags.get("planar", True))
                                if m in MODELS else True).to_numpy(bool)
    return lifted & planar


def compare_mitigations(table, *, im="pga", im_unit="m/s^2", failure="auto", by=None,
                        hazard=None, clearance=None, n_boot=200, seed=0,
                        reference=REFERENCE, return_periods=(), t_years=50.0,
                        building_period=None, isolation_periods=None, records=None,
                        ground=None) -> MitigationComparison:
    """Compare the mitigations of a table of runs, group by group.

    ``table``: one row per run, with a ``mitigation`` column (without it, ``model`` names
    the mitigations), the IM column ``im`` (``pga``, ``floor_pga``, ``im``; in ``im_unit``)
    and ``overturned``; optional ``status`` (runs with a non-zero status are left out and
    counted in ``n_excluded``; a missing status counts as 0), ``settled`` (counted in
    ``n_unsettled``), ``max_base_displacement`` (m), ``clearance_exceeded``. Runs whose IM
    is not finite and > 0 are left out and counted too. ``im_unit`` is the unit of the
    IM column: a campaign's ``pga`` and ``floor_pga`` are in m/s^2, its ``im`` in the unit
    of its manifest (``manifest["im"]["unit"]``; a table whose ``attrs`` state another unit
    is refused).

    ``failure``: ``"overturned"`` or ``"overturned_or_clearance"`` (a run whose isolator
    reached the clearance, ``clearance_exceeded`` or ``max_base_displacement >= clearance``,
    failed too); ``"auto"`` (default): ``"overturned_or_clearance"`` when some runs were
    stopped at the model's clearance (``clearance_exceeded``: whether they would have
    overturned is unknown, so they are not counted as survivors), else ``"overturned"``; the
    rule used is :attr:`MitigationComparison.failure`. ``by``: the grouping columns (default
    those of :data:`DEFAULT_BY` present). ``clearance`` (m or a quantity string,
    ``"0.15m"``): the displacement capacity of the isolator; or ``{mitigation: clearance}``,
    each mitigation's own (the campaign report passes its isolators' ``clearance``
    options; a mitigation not named has none). ``reference``: the unmitigated
    entry's name; without a ``mitigation`` column and without that name, the one model of
    the group that is not a mitigation (``Model.mitigation`` false) is the reference.

    Each (group, mitigation) is fitted with :func:`~.fragility.fragility` (probit GLM MLE,
    Baker 2015; ``n_boot`` draws of the ``"normal"`` bootstrap with ``seed`` give the 95%
    intervals). ``hazard``: ``(im, rate, unit)`` or ``{"im", "rate", "unit"}``, a hazard
    curve (annual rate of exceeding each IM) converted to ``im_unit`` when of the same
    kind (g to m/s^2), refused otherwise; the annual frequency of failure is
    :func:`~.fragility.annual_frequency` of the fit (Cornell et al. 2002) over the curve's
    range (the IMs beyond its ends flagged in ``note`` when they matter). A
    :class:`~.hazard.HazardCurve` instead: :func:`~.hazard.risk` over the whole IM range,
    power-law tails included (its IM name must be the fit's).

    Columns of the result's ``table`` (one row per group and mitigation): the ``by``
    columns, ``mitigation``, ``model`` (the model(s) run), ``n`` (runs used), ``n_failed``,
    ``n_excluded``, ``n_unsettled``, ``im_min``/``im_max``, ``median`` and ``beta`` (the fit,
    in ``im_unit``), ``median_ci_low/high`` and ``beta_ci_low/high`` (95% bootstrap),
    ``median_lower_bound``/``median_upper_bound`` (when no fit exists: no failure up to
    ``im_max``, every run failed from ``im_min``, or outcomes separated by the IM; what
    the data show, not confidence bounds: ``n`` runs at an IM without a failure bound
    ``P(f | im)`` below about ``3 / n`` at 95%, the rule of three),
    ``median_ratio`` (median / the reference's median in the group; NaN without a
    reference), ``median_ratio_lower_bound`` (a never-failing mitigation's lower bound over
    the reference's median), ``annual_frequency`` (with ``hazard``),
    ``annual_frequency_lower_bound``/``_upper_bound`` (without a fit: the hazard rate at the
    bounds of the median, i.e. the frequency if the fragility were a step there; NaN
    beyond the hazard curve), ``annual_frequency_ratio`` (to the reference's: every
    comparison states it), ``annual_frequency_low``/``_high`` (the 90 % interval of
    :func:`~.hazard.risk`, with a :class:`~.hazard.HazardCurve`), ``probability`` (in
    ``t_years``), ``failure`` (the rule of the row), ``verdict`` (:data:`VERDICTS`:
    "worse" when its annual frequency, or without a hazard its median, is worse than the
    reference's) and ``reason`` (for a worse one, the likely reason the runs show:
    failures that are runs stopped at the moat, an isolation period near
    ``building_period`` on a floor (within :data:`AMPLIFY_BAND`; ``isolation_periods``
    ``{mitigation: s}`` or an ``isolation_period`` column), anchors that broke; else "no
    reason visible in the runs"), ``displacement_max`` (m, of ``max_base_displacement``;
    NaN without it; a run stopped at the model's clearance has the clearance as its
    maximum), ``n_clearance_exceeded`` and ``p_clearance_exceeded`` (over all runs,
    whatever their IM: runs with ``clearance_exceeded`` or ``max_base_displacement >=
    clearance``; NaN when neither is known), ``clearance`` (m, NaN if not given; with a
    mapping, the row's mitigation's),
    ``clearance_annual_frequency`` and ``clearance_probability`` (in ``t_years``: a
    fragility of "reached the clearance" integrated over the hazard), ``note``; then, with
    a hazard, for each return period T of :data:`~.hazard.RETURN_PERIODS` (475 and 2475
    years) and ``return_periods``, the columns of :func:`demand_columns`: the IM at T and
    the isolator's demand there (median and 84th percentile of ``max_base_displacement``
    and P(reaching the clearance), interpolated between the IM levels run, log-log; NaN
    beyond them, with a note: no extrapolation). The demand per level is
    :attr:`MitigationComparison.demand` (:func:`demand_stripes`): the displacement is not
    pooled over the levels, which would make it depend on the levels chosen.

    ``records`` (the records that were run, optional) are checked at the isolators'
    periods and ``building_period`` against EN 1998-1 on ``ground`` (A-E; without it,
    Type 1 on ground A) by :func:`rocking.motions.check_records_fit`: a
    :class:`~rocking.motions.RecordFitWarning` where their mean spectrum falls more than
    10 % below it.

    Raises :class:`~rocking.ParameterError` for a missing column, an unknown ``failure``,
    a hazard in an incompatible unit, or a group whose runs were all left out.

    Examples
    --------
    Planted stripes: the unmitigated block fails on a lognormal curve of median 3 m/s^2,
    the isolated one on a curve of median 6 m/s^2 (beta 0.4 both); the comparison recovers
    the ratio of the medians, 2:

    >>> import pandas as pd
    >>> from scipy.stats import norm
    >>> from rocking.analysis import compare_mitigations
    >>> im = np.repeat([1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0], 40)  # PGA (m/s^2)
    >>> j = np.tile(np.arange(40), 7)
    >>> runs = pd.concat([pd.DataFrame({"mitigation": name, "pga": im, "overturned":
    ...                                 j < np.round(40 * norm.cdf(np.log(im / m) / 0.4))})
    ...                   for name, m in (("none", 3.0), ("isolated", 6.0))])
    >>> cmp = compare_mitigations(runs, n_boot=0)
    >>> cmp.table[["mitigation", "median", "beta", "median_ratio"]].round(1).values.tolist()
    [['none', 3.0, 0.4, 1.0], ['isolated', 6.0, 0.4, 2.0]]
    """
    mit_col = ("mitigation" if isinstance(table, pd.DataFrame) and "mitigation" in table
               else "model" if isinstance(table, pd.DataFrame) and "model" in table else None)
    by = _check_table(table, im, failure, by, mit_col)
    if not isinstance(reference, str):
        raise ParameterError(f"reference must be a mitigation name, got {reference!r}")
    if im_unit is not None and not isinstance(im_unit, str):
        raise ParameterError(f"im_unit must be a unit string such as 'm/s^2', got {im_unit!r}")
    attrs_unit = _attrs_unit(table, im)
    if attrs_unit is not None and im_unit is not None and unit_kind(attrs_unit) != unit_kind(
            im_unit) and attrs_unit.strip() != im_unit.strip():
        raise ParameterError(f"im_unit={im_unit!r} contradicts the table's own IM unit "
                             f"{attrs_unit!r} (table.attrs)")
    if isinstance(clearance, Mapping):  # {mitigation: clearance}: each its own
        names = set(table[mit_col].astype(str))
        clear_of = {str(k): parse_clearance(v) for k, v in clearance.items()}
        if set(clear_of) - names:
            raise ParameterError(f"clearance: no mitigation named "
                                 f"{sorted(set(clear_of) - names)} in column {mit_col!r} "
                                 f"(it has {sorted(names)})")
        clear = math.nan
    else:
        clear_of = {}
        clear = parse_clearance(clearance)
    clear_rows = np.array([clear_of.get(m, clear) for m in table[mit_col].astype(str)],
                          dtype=float)
    curve = hazard if isinstance(hazard, HazardCurve) else None
    if curve is not None:
        if im_unit is None:
            raise ParameterError("im_unit is required with a hazard curve: the IM's unit "
                                 "must be known to check the hazard's")
        hazard = (curve.im, curve.rate, curve.unit)
    hz = parse_hazard(hazard, im_unit) if hazard is not None else None
    if curve is not None:
        hz = (hz[0], hz[1], curve)
    table = table.reset_index(drop=True)  # positions, whatever the caller's index

    if table[mit_col].isna().any():
        i = int(np.flatnonzero(table[mit_col].isna().to_numpy())[0])
        raise ParameterError(f"column {mit_col!r} names the mitigation of each run: row {i} "
                             "has none (NaN)")
    x_all = pd.to_numeric(table[im], errors="coerce").to_numpy(float)
    status = (pd.to_numeric(table["status"], errors="coerce").fillna(0).to_numpy(float)
              if "status" in table else np.zeros(len(table)))
    bad_im = ~(np.isfinite(x_all) & (x_all > 0))
    excluded = (status != 0) | bad_im | _lifted_planar(table)
    disp_all = (pd.to_numeric(table["max_base_displacement"], errors="coerce").to_numpy(float)
                if "max_base_displacement" in table else np.full(len(table), np.nan))
    flag_all = _flags(table, "clearance_exceeded")
    asked = failure
    if failure == "overturned_or_clearance" and not (
            "clearance_exceeded" in table or (np.isfinite(clear_rows).any()
                                              and "max_base_displacement" in table)):
        raise ParameterError("failure='overturned_or_clearance' needs a "
                             "'clearance_exceeded' column, or a 'max_base_displacement' "
                             "column and clearance=")
    if np.isfinite(clear_rows).any() and "max_base_displacement" not in table and (
            "clearance_exceeded" not in table):
        raise ParameterError("clearance: the table has no 'max_base_displacement' column "
                             "(nor 'clearance_exceeded') to compare with it")
    with np.errstate(invalid="ignore"):
        by_disp = np.where(np.isfinite(disp_all) & np.isfinite(clear_rows),
                           (disp_all >= clear_rows).astype(float), np.nan)
    # 1: exceeded by either source; 0: known not exceeded; NaN: not known
    exceeded = np.where((flag_all == 1) | (by_disp == 1), 1.0,
                        np.where(np.isfinite(flag_all) | np.isfinite(by_disp), 0.0, np.nan))
    settled = _flags(table, "settled")
    broken = np.zeros(len(table), bool)
    for col in ("anchor_broken_plus", "anchor_broken_minus"):
        broken |= _flags(table, col) == 1
    curve_im = _im_curve(hz, im, im_unit)
    periods = sorted({*RETURN_PERIODS, *_periods(return_periods)})
    t_years = _positive_years(t_years)
    iso_T = _isolation_periods(table, mit_col, isolation_periods)
    if building_period is not None:
        building_period = _positive_period("building_period", building_period)

    if records is not None:  # do they fit the periods that matter? (issue 31)
        from ..motions.ec8_records import check_records_fit

        why = {f"the isolation period of {m!r}": T for m, T in iso_T.items()}
        if building_period is not None:
            why["the building's first period"] = building_period
        if why:
            check_records_fit(records, why, ground=ground, what="compare_mitigations: "
                              "the records run", stacklevel=3)

    rows, fits, stripes, keys, demand, diag = [], {}, {}, [], {}, {}
    groups = table.groupby(by, sort=False, dropna=False) if by else [((), table)]
    for gkey, g in groups:
        gkey = gkey if isinstance(gkey, tuple) else (gkey,)
        gdesc = ", ".join(f"{c}={v}" for c, v in zip(by, gkey, strict=True)) or "the table"
        pos = g.index.to_numpy()
        names = list(dict.fromkeys(g[mit_col].astype(str)))
        if reference in names:
            names.remove(reference)
            names.insert(0, reference)
        for mname in names:
            p = pos[(g[mit_col].astype(str) == mname).to_numpy()]
            ok = p[~excluded[p]]
            label = f"{gdesc}, mitigation {mname!r}" if by else f"mitigation {mname!r}"
            if ok.size == 0:
                raise ParameterError(f"{label}: no usable run ({p.size} runs, all with a "
                                     "non-zero status or no valid IM): an empty group")
            x = x_all[ok]
            ovt = as_bool_array(f"overturned ({label})", table["overturned"].to_numpy()[ok])
            exc = exceeded[ok]
            own = flag_all[ok] == 1  # stopped by the model at its own clearance (moat)
            # "auto": per mitigation; a moat the model did not have (a "no moat" isolator)
            # is no failure: clearance= then measures the demand only
            fail_m = (failure if failure != "auto" else
                      "overturned_or_clearance" if own.any() else "overturned")
            if fail_m == "overturned":
                y = ovt.copy()
            elif failure == "auto":
                y = ovt | own
            else:
                y = ovt | (exc == 1)
            key = tuple(gkey) + (mname,) if by else mname
            fit, fields = _fit_one(x, y, im=im, im_unit=im_unit, n_boot=n_boot, seed=seed,
                                   label=mname)
            if fit is not None:
                fits[key] = fit
            stripes[key] = _stripes(x, y)
            note = fields.pop("note")
            notes = [note] if note else []
            n_exc = int(excluded[p].sum())
            if n_exc:
                notes.append(f"{n_exc} runs left out (non-zero status or no valid IM)")
            n_stop = int(np.sum((flag_all[ok] == 1) & ~ovt))
            if fail_m == "overturned" and n_stop:
                notes.append(f"{n_stop} runs stopped at the isolator's clearance "
                             "(clearance_exceeded): whether they would have overturned is "
                             "not known, they count as not overturned "
                             "(failure='overturned_or_clearance' counts them as failed)")
            d_ok = disp_all[ok]
            d = d_ok[np.isfinite(d_ok)]
            known = exc[np.isfinite(exc)]
            if d.size:
                cap = float(np.min(d_ok[own & np.isfinite(d_ok)])) if np.any(
                    own & np.isfinite(d_ok)) else math.inf
                demand[key] = demand_stripes(x, d_ok, exc, cap)
            diag[key] = {"n_failed": int(y.sum()), "n_stop_failed": int(np.sum(y & ~ovt)),
                         "n_broken_failed": int(np.sum(y & broken[ok])),
                         "clearance": (float(np.min(d_ok[own])) if own.any() and np.isfinite(
                             d_ok[own]).any() else clear_of.get(mname, clear)),
                         "period": iso_T.get(mname), "floor": (
                             g["floor"].iloc[0] if "floor" in g else None)}
            row = dict(zip(by, gkey, strict=True))
            models = (", ".join(dict.fromkeys(g["model"].astype(str).to_numpy()[
                (g[mit_col].astype(str) == mname).to_numpy()]))
                if "model" in g else "")
            row.update(
                mitigation=mname, model=models, n=int(ok.size), n_failed=int(y.sum()),
                n_excluded=n_exc,
                n_unsettled=int(np.sum(settled[ok] == 0)),
                im_min=float(x.min()), im_max=float(x.max()), **fields,
                failure=fail_m,
                displacement_max=float(d.max()) if d.size else math.nan,
                n_clearance_exceeded=int(known.sum()) if known.size else 0,
                p_clearance_exceeded=float(known.mean()) if known.size else math.nan,
                clearance=clear_of.get(mname, clear), note="; ".join(notes))
            _hazard_fields(row, fit, hz, im_unit, t_years)
            _clearance_risk(row, x, exc, curve_im, t_years)
            _demand_fields(row, demand.get(key), curve_im, periods)
            rows.append(row)
            keys.append(key)
    out = pd.DataFrame(rows)
    _ratios(out, by, reference, mit_col, table)
    _verdicts(out, by, reference, mit_col, table, dict(zip(out.index, keys, strict=True)),
              diag, building_period)
    extra = [c for T in periods for c in demand_columns(T)] if curve_im is not None else []
    out = out[[*by, *COLUMNS, *extra]]
    if failure == "auto":
        failure = ("overturned_or_clearance" if (out["failure"] == "overturned_or_clearance")
                   .any() else "overturned")
    out.attrs.update(im=im, im_unit=im_unit, failure=failure, reference=reference,
                     clearance=dict(clear_of) if clear_of else clear, by=list(by),
                     fit_method="rocking.analysis.fragility.fragility: probit GLM MLE "
                                "(Baker 2015)",
                     hazard="Cornell et al. (2002)" if hz is not None else None)
    out.attrs.update(failure_asked=asked, return_periods=periods if curve_im is not None
                     else [], t_years=t_years)
    return MitigationComparison(out, fits, stripes, by=by, im=im, im_unit=im_unit,
                                failure=failure,
                                clearance=dict(clear_of) if clear_of else clear,
                                reference=reference,
                                hazard=hz, keys=keys, demand=demand,
                                return_periods=periods if curve_im is not None else (),
                                t_years=t_years)


def _attrs_unit(table: pd.DataFrame, im: str) -> str | None:
    """The IM unit that the table states in its ``attrs`` (``{"im": {"name", "unit"}}``
    as a campaign manifest has it, or ``im_unit``), if any and if it is about ``im``."""
    a = table.attrs or {}
    spec = a.get("im")
    if isinstance(spec, dict) and spec.get("unit") and im == "im":
        return str(spec["unit"])
    if isinstance(a.get("im_unit"), str) and a.get("im_name", im) == im:
        return a["im_unit"]
    return None


def _im_curve(hz, im: str, im_unit) -> HazardCurve | None:
    """The hazard as a :class:`HazardCurve` in the IM's unit (for its return periods),
    None without a hazard (or in a unit a HazardCurve does not know)."""
    if hz is None:
        return None
    try:
        return HazardCurve(hz[0], hz[1], im_name=IM_NAMES.get(im, im), unit=im_unit)
    except (ParameterError, ValueError):
        return None


def _periods(values) -> list[float]:
    """Return periods (years) the user names, checked: numbers > 0."""
    vals = [values] if isinstance(values, int | float) else list(values or ())
    out = []
    for v in vals:
        try:
            T = float(v)
        except (TypeError, ValueError):
            T = math.nan
        if isinstance(v, bool) or not (math.isfinite(T) and T > 0):
            raise ParameterError(f"return_periods must be return periods > 0 (years), such "
                                 f"as (100, 975), got {values!r}")
        out.append(T)
    return out


def _positive_years(t) -> float:
    try:
        v = float(t)
    except (TypeError, ValueError):
        v = math.nan
    if isinstance(t, bool) or not (math.isfinite(v) and v > 0):
        raise ParameterError(f"t_years must be a service life > 0 (years), got {t!r}")
    return v


def _positive_period(name: str, value) -> float:
    try:
        v = float(parse_quantity(value, "time", name=name, default_unit="s")
                  if isinstance(value, str) else value)
    except (TypeError, ValueError):
        v = math.nan
    if isinstance(value, bool) or not (math.isfinite(v) and 0 < v <= 20):
        raise ParameterError(f"{name} must be a period in (0, 20] s, got {value!r}")
    return v


def _isolation_periods(table, mit_col, given) -> dict:
    """``{mitigation: isolation period (s)}``: ``given`` (a dict), else the table's
    ``isolation_period`` column (the first value of each mitigation), if any."""
    out = {}
    if "isolation_period" in table.columns:
        for name, v in table.groupby(table[mit_col].astype(str))["isolation_period"]:
            vals = pd.to_numeric(v, errors="coerce").dropna()
            if len(vals):
                out[name] = float(vals.iloc[0])
    if given is not None:
        if not isinstance(given, dict):
            raise ParameterError(f"isolation_periods must be a dict {{mitigation: period "
                                 f"(s)}}, got {given!r}")
        for k, v in given.items():
            out[str(k)] = _positive_period(f"isolation_periods[{k!r}]", v)
    return out


def _clearance_risk(row: dict, x, exc, curve: HazardCurve | None, t_years: float) -> None:
    """The annual frequency of reaching the clearance (and its probability in
    ``t_years``): a fragility of the event "reached the clearance" on the runs where it
    is known, integrated over the hazard (:func:`~.hazard.risk`); NaN without a hazard,
    a clearance, or a fit."""
    row.update(clearance_annual_frequency=math.nan, clearance_probability=math.nan)
    known = np.isfinite(exc)
    if curve is None or known.sum() < 2:
        return
    fit, *_ = fit_or_bounds(x[known], exc[known] == 1, n_boot=0,
                            im_name=curve.im_name, im_unit=curve.unit, label="clearance")
    if fit is None:
        return
    r = risk(fit, curve, t_years=t_years)
    row.update(clearance_annual_frequency=r.annual_frequency,
               clearance_probability=r.probability_50)


def _demand_fields(row: dict, stripes, curve: HazardCurve | None, periods) -> None:
    """The isolator's demand at the IM of each return period (:func:`demand_at`)."""
    if curve is None:
        return
    for T in periods:
        c_im, c_med, c_p84, c_p = demand_columns(T)
        a = float(curve.im_at_return_period(T))
        row[c_im] = a
        d = demand_at(stripes, a) if stripes is not None else None
        row[c_med] = d["displacement_median"] if d else math.nan
        row[c_p84] = d["displacement_p84"] if d else math.nan
        row[c_p] = d["p_clearance"] if d else math.nan
        if d and d["beyond"] and len(stripes):
            row["note"] = "; ".join(filter(None, [row["note"], (
                f"no demand at {T:g} years: its IM {a:.4g} is beyond the IMs run "
                f"({stripes['im'].min():.4g} to {stripes['im'].max():.4g})")]))
        elif d and d["censored"]:
            row["note"] = "; ".join(filter(None, [row["note"], (
                f"the demand at {T:g} years is censored by the moat (runs stopped at the "
                "clearance): a lower bound")]))


def _hazard_fields(row: dict, fit: FragilityFit | None, hz, im_unit,
                   t_years: float = 50.0) -> None:
    row.update(annual_frequency=math.nan, annual_frequency_lower_bound=math.nan,
               annual_frequency_upper_bound=math.nan, annual_frequency_low=math.nan,
               annual_frequency_high=math.nan, probability=math.nan)
    if hz is None:
        return
    hx, hr = hz[:2]
    if fit is not None and len(hz) == 3:  # a HazardCurve: the whole IM range, tails too
        r = risk(fit, hz[2], t_years=t_years)
        row["annual_frequency"] = r.annual_frequency
        row["annual_frequency_low"], row["annual_frequency_high"] = \
            r.annual_frequency_interval
        row["probability"] = r.probability_50
        if r.tail_share > 0.1:
            row["note"] = "; ".join(s for s in (row["note"], (
                f"{100 * r.tail_share:.0f} % of the annual frequency comes from the "
                "hazard curve's power-law tails beyond its ends")) if s)
        return
    if fit is not None:
        af = annual_frequency(fit, hx, hr, hazard_unit=im_unit)
        row["annual_frequency"] = af
        row["probability"] = probability_in(t_years, af)
        # beyond the curve: the tail adds lambda(x_N) P(x_N), at most lambda(x_N) is right;
        # below it, failures at im < x_0 are not counted (at most lambda(x_0) - lambda(0))
        p_hi, p_lo = fit.probability(float(hx[-1])), fit.probability(float(hx[0]))
        miss = float(hr[-1]) * (1.0 - p_hi)
        if miss > 1e-3 * af:
            row["note"] = "; ".join(s for s in (row["note"], (
                f"annual frequency is a lower bound: the hazard curve ends at {hx[-1]:.4g} "
                f"{im_unit} where P(failure) = {p_hi:.3g} (up to {miss:.3g}/yr more)")) if s)
        if p_lo > 1e-3:
            row["note"] = "; ".join(s for s in (row["note"], (
                f"annual frequency is a lower bound: the hazard curve starts at {hx[0]:.4g} "
                f"{im_unit} where P(failure) = {p_lo:.3g} already")) if s)
        return
    lo, hi = row["median_lower_bound"], row["median_upper_bound"]
    # a step fragility at m has lambda_f = lambda(m): lambda_f <= lambda(lo), >= lambda(hi)
    if math.isfinite(lo):
        row["annual_frequency_upper_bound"] = (float(hr[-1]) if lo > hx[-1]
                                               else rate_at(lo, hx, hr))
    if math.isfinite(hi):
        row["annual_frequency_lower_bound"] = (float(hr[0]) if hi < hx[0]
                                               else rate_at(hi, hx, hr))
    what = ("upper bound: the rate of the largest IM without failure" if math.isfinite(lo)
            else "")
    what += ("; " if what and math.isfinite(hi) else "") + (
        "lower bound: the rate of the smallest IM with failure" if math.isfinite(hi) else "")
    row["note"] = "; ".join(s for s in (row["note"], f"annual frequency not fitted ({what}, "
                                        "if the fragility were a step there)") if s)


def _reference_of(g: pd.DataFrame, reference: str, mit_col: str, table) -> str | None:
    names = set(g["mitigation"])
    if reference in names:
        return reference
    if mit_col != "model":
        return None
    from ..models import MODELS

    plain = [n for n in names if n in MODELS and not MODELS[n].mitigation]
    return plain[0] if len(plain) == 1 else None


def _ratios(out: pd.DataFrame, by, reference, mit_col, table) -> None:
    out["median_ratio"] = math.nan
    out["median_ratio_lower_bound"] = math.nan
    out["annual_frequency_ratio"] = math.nan
    parts = out.groupby(by, sort=False, dropna=False) if by else [((), out)]
    for _, g in parts:
        ref = _reference_of(g, reference, mit_col, table)
        if ref is None:
            continue
        r = g[g["mitigation"] == ref].iloc[0]
        idx = g.index
        out.loc[idx, "median_ratio"] = g["median"] / r["median"]
        out.loc[idx, "median_ratio_lower_bound"] = g["median_lower_bound"] / r["median"]
        out.loc[idx, "annual_frequency_ratio"] = g["annual_frequency"] / r["annual_frequency"]


def _verdicts(out: pd.DataFrame, by, reference, mit_col, table, keys: dict, diag: dict,
              building_period) -> None:
    """``verdict`` and ``reason`` of every row: against the reference of its group, by
    the annual frequency of failure (with a hazard) or else the median (the bounds when
    there is no fit); a worse mitigation gets the likely reason that the runs show."""
    out["verdict"] = "not known"
    out["reason"] = ""
    parts = out.groupby(by, sort=False, dropna=False) if by else [((), out)]
    for _, g in parts:
        ref = _reference_of(g, reference, mit_col, table)
        if ref is None:
            continue
        r0 = g[g["mitigation"] == ref].iloc[0]
        for i, r in g.iterrows():
            if r["mitigation"] == ref:
                out.loc[i, "verdict"] = "reference"
                continue
            v = verdict_of(r, r0)
            out.loc[i, "verdict"] = v
            if v == "worse":
                out.loc[i, "reason"] = _reason(r, diag.get(keys[i], {}), building_period)


def verdict_of(r, r0) -> str:
    """The verdict (:data:`VERDICTS`) of the comparison row ``r`` against the reference's
    row ``r0``: by the annual frequency (not distinguishable where both intervals exist and
    overlap), else the bounds of the annual frequency, else the medians."""
    af, af0 = r["annual_frequency"], r0["annual_frequency"]
    if math.isfinite(af) and math.isfinite(af0):
        lo, hi = r.get("annual_frequency_low", math.nan), r.get("annual_frequency_high",
                                                                 math.nan)
        lo0, hi0 = r0.get("annual_frequency_low", math.nan), r0.get("annual_frequency_high",
                                                                    math.nan)
        if (af != af0 and all(math.isfinite(v) for v in (lo, hi, lo0, hi0))
                and lo <= hi0 and lo0 <= hi):
            return "not distinguishable"
        return "worse" if af > af0 else "better" if af < af0 else "same"
    up, lo = r["annual_frequency_upper_bound"], r["annual_frequency_lower_bound"]
    if math.isfinite(af0) and math.isfinite(up) and up < af0:
        return "better"
    if math.isfinite(af0) and math.isfinite(lo) and lo > af0:
        return "worse"
    (a, b), (a0, b0) = _median_span(r), _median_span(r0)
    if a == b and a0 == b0 and math.isfinite(a) and math.isfinite(a0):
        return "worse" if a < a0 else "better" if a > a0 else "same"
    if b < a0:  # its median is below every median the reference's runs allow
        return "worse"
    if a > b0:
        return "better"
    return "not known"


def _median_span(r) -> tuple[float, float]:
    """What the runs say of a row's median: ``(m, m)`` with a fit, else the interval its
    bounds give (no failure up to ``median_lower_bound``: above it; every run failed from
    ``median_upper_bound``: below it); ``(nan, nan)`` when nothing is known."""
    m = r["median"]
    if math.isfinite(m):
        return m, m
    lo, hi = r["median_lower_bound"], r["median_upper_bound"]
    if not (math.isfinite(lo) or math.isfinite(hi)):
        return math.nan, math.nan
    return (lo if math.isfinite(lo) else 0.0), (hi if math.isfinite(hi) else math.inf)


def _reason(r, d: dict, building_period) -> str:
    """The likely reason why a mitigation is worse, from what its runs show."""
    why = []
    n, stop = d.get("n_failed", 0), d.get("n_stop_failed", 0)
    T = d.get("period")
    if T and building_period and d.get("floor") not in (0, None) and \
            AMPLIFY_BAND[0] <= T / building_period <= AMPLIFY_BAND[1]:
        why.append(f"the isolator's period {T:g} s is near the building's {building_period:g}"
                   " s: the floor's motion, narrow-band at the building's period, is "
                   "amplified by the isolator (resonance); a longer isolation period")
    elif T and building_period and d.get("floor") is None and \
            AMPLIFY_BAND[0] <= T / building_period <= AMPLIFY_BAND[1]:
        why.append(f"the isolator's period {T:g} s is near the building's {building_period:g}"
                   " s (resonance with the floor's motion)")
    if n and stop >= 0.5 * n:
        c = d.get("clearance", math.nan)
        cl = f" ({c:.3g} m)" if c == c and math.isfinite(c) else ""
        d475 = r.get("displacement_median_475yr", math.nan)
        need = (f"; the median demand at 475 years is {d475:.3g} m" if isinstance(
            d475, float) and math.isfinite(d475) else "")
        why.append(f"{stop} of its {n} failures are runs stopped at the clearance{cl}, "
                   "not overturning: its risk is that of reaching the moat (a larger "
                   f"clearance lowers it){need}")
    if n and d.get("n_broken_failed", 0) >= 0.5 * n:
        why.append(f"the anchors broke in {d['n_broken_failed']} of its {n} failures: "
                   "brittle anchors release a block that is already rocking (stronger "
                   "anchors, or none)")
    return "; ".join(why) if why else "no reason visible in the runs"


# --------------------------------------------------------------------------- plot

LINESTYLES = ("-", "--", "-.", ":", (0, (5, 1)), (0, (3, 1, 1, 1, 1, 1)))
"""Line styles of the mitigations' curves (with the colours: no two curves look alike)."""
MARKERS = ("o", "s", "^", "D", "v", "P", "X")
_BY_WORDS = {"block_name": "block", "height_ratio": "z/H"}


def _verdict_label(r) -> str:
    """The ratio to the reference and the verdict for a legend ("" for the reference)."""
    v = r.get("verdict", "")
    if v in ("reference", "", None) or v != v:
        return ""
    af, med = r.get("annual_frequency_ratio", math.nan), r.get("median_ratio", math.nan)
    ratio = (f"{af:.3g} × the annual frequency" if isinstance(af, float) and math.isfinite(af)
             else f"{med:.3g} × the median" if isinstance(med, float) and math.isfinite(med)
             else "")
    word = "WORSE than none" if v == "worse" else v
    return f"\n{ratio} of none: {word}" if ratio else f"\n{word}"


def plot_mitigations(comparison: MitigationComparison, *, band: bool = False,
                     level: float = 0.95, ncols: int = 3, figsize=None):
    """Fragility curves of the mitigations side by side: one panel per group, the curves
    of all its mitigations overlaid (with the ``level`` bootstrap band if ``band``), the
    observed failed fraction per IM level as markers (per bin of equal count when the IMs
    are not on stripes). A mitigation without a fit shows its markers only, its note in
    the legend. Returns a matplotlib Figure (no pyplot).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import pandas as pd
    >>> from rocking.analysis import compare_mitigations, plot_mitigations
    >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
    >>> j = np.tile(np.arange(10), 5)
    >>> runs = pd.concat([pd.DataFrame({"mitigation": name, "pga": im,
    ...                                 "overturned": j < np.repeat(k, 10)})
    ...                   for name, k in (("none", [1, 3, 5, 7, 9]),
    ...                                   ("isolated", [0, 1, 3, 5, 7]))])
    >>> fig = plot_mitigations(compare_mitigations(runs, n_boot=0))
    >>> type(fig).__name__
    'Figure'
    """
    from matplotlib.figure import Figure

    if not isinstance(comparison, MitigationComparison):
        raise ParameterError("comparison must be a MitigationComparison, got "
                             f"{type(comparison).__name__}")
    if isinstance(ncols, bool) or not isinstance(ncols, int) or ncols < 1:
        raise ParameterError(f"ncols must be an integer >= 1, got {ncols!r}")
    t = comparison.table
    by = comparison.by
    groups = list(t.groupby(by, sort=False, dropna=False)) if by else [((), t)]
    ncols = min(ncols, len(groups))
    nrows = math.ceil(len(groups) / ncols)
    fig = Figure(figsize=figsize or (max(6.4, 5.4 * ncols), 5.1 * nrows),
                 layout="constrained")
    axes = fig.subplots(nrows, ncols, squeeze=False).ravel()
    lo = float(t["im_min"].min())
    hi = float(t["im_max"].max())
    meds = t["median"].to_numpy(float)
    if np.isfinite(meds).any():
        lo, hi = min(lo, np.nanmin(meds) / 3.0), max(hi, np.nanmax(meds) * 3.0)
    grid = np.geomspace(lo * 0.8, hi * 1.2, 200)
    names = list(dict.fromkeys(t["mitigation"]))
    style = {m: (PALETTE[i % len(PALETTE)], LINESTYLES[i % len(LINESTYLES)],
                 MARKERS[i % len(MARKERS)]) for i, m in enumerate(names)}
    unit = comparison.im_unit
    row_key = dict(zip(t.index, comparison.keys, strict=True))
    both = "failure" in t and (t["failure"] == "overturned_or_clearance").any()
    for ax, (gkey, g) in zip(axes, groups, strict=False):
        gkey = gkey if isinstance(gkey, tuple) else (gkey,)
        for j, (i, r) in enumerate(g.iterrows()):
            m = r["mitigation"]
            key = row_key[i]
            c, ls, mk = style[m]
            shift = math.exp(0.02 * (j - (len(g) - 1) / 2))  # coincident points stay seen
            s = comparison.stripes[key]
            ax.plot(s["im"] * shift, s["n_failed"] / s["n"], mk, ms=4.5, mfc="none",
                    color=c)
            what = (" (overturned or clearance)" if both and r.get("failure") ==
                    "overturned_or_clearance" else "")
            verdict = _verdict_label(r)
            fit = comparison.fits.get(key)
            if fit is None:  # the bound in the legend (short), the note in the table
                lo, hi = r["median_lower_bound"], r["median_upper_bound"]
                if np.isfinite(lo) and np.isfinite(hi):
                    text = f"median in [{lo:.3g}, {hi:.3g}] {unit_label(unit)} (no fit)"
                elif np.isfinite(lo):
                    text = f"median > {lo:.3g} {unit_label(unit)} (no failure)"
                elif np.isfinite(hi):
                    text = f"median < {hi:.3g} {unit_label(unit)} (all failed)"
                else:
                    text = "no fit"
                ax.plot([], [], mk, mfc="none", color=c, label=f"{m}{what}: {text}{verdict}")
                continue
            ax.plot(grid, fit.probability(grid), color=c, ls=ls, lw=1.4,
                    label=f"{m}{what}: median {fit.median:.3g} {unit_label(unit)}, "
                          f"beta {fit.beta:.2f}{verdict}")
            if band and fit.n_boot:
                b = fit.band(grid, level)
                ax.fill_between(grid, b["lower"], b["upper"], color=c, alpha=0.15, lw=0)
        style_axes(ax, im_label(comparison.im if comparison.im in ("pga", "im") else
                                IM_NAMES.get(comparison.im, comparison.im), unit),
                   "P(failure)" if both else f"P({comparison.failure.replace('_', ' ')})")
        ax.set_xscale("log")
        ax.set_ylim(-0.02, 1.02)
        plain_log_ticks(ax)
        title = (", ".join(f"{_BY_WORDS.get(c, c)} {v}" for c, v in zip(by, gkey, strict=True))
                 if by else "")
        if title:
            ax.set_title(title, fontsize="medium")
        ax.legend(frameon=False, fontsize="x-small", loc="upper center",
                  bbox_to_anchor=(0.5, -0.2), borderaxespad=0.0)
    fig.suptitle("Fragility per mitigation\nlines: lognormal fits; markers: the failed share "
                 "of the runs per level", fontsize="medium")
    for ax in axes[len(groups):]:
        ax.set_visible(False)
    return fig


__all__ = ["compare_mitigations", "MitigationComparison", "plot_mitigations", "FAILURES",
           "DEFAULT_BY", "REFERENCE", "unit_kind", "parse_hazard", "parse_clearance"]
