"""Lognormal fragility curves: stripes (MSA) and incremental dynamic analysis (IDA).

A fragility curve is ``P(failure | IM = im) = Phi(ln(im / median) / beta)``.

* :func:`fragility` fits it by maximum likelihood to binary outcomes. Repeated IM values
  are stripes, so one binomial likelihood covers multiple-stripe analysis (Baker 2015,
  Eq. 11). The fit is a statsmodels binomial GLM with a probit link on ``ln im``:
  ``P = Phi(b0 + b1 ln im)``, hence ``median = exp(-b0 / b1)`` and ``beta = 1 / b1``;
  standard errors by the delta method from the GLM covariance.
* :func:`fragility_ida` fits the IM capacities of an IDA, right-censored for the records
  that never failed (scipy's ``CensoredData`` and ``lognorm.fit(..., floc=0)``).
* :func:`annual_frequency` integrates a fit over a hazard curve (Cornell et al. 2002).

A fit carries the name and unit of its IM (``im_name``, ``im_unit``: ``fragility(...,
im_name="pga", im_unit="m/s^2")``), which label its plot and let :func:`annual_frequency`
refuse a hazard curve in another unit (a hazard in g integrated with a fit in m/s^2 is off
by orders of magnitude, with no error). The package's IMs are in SI units (PGA in m/s^2)
or dimensionless; :meth:`FragilityFit.to_pelicun` converts the median at the edge, to the
units of a pelicun fragility table.

References: J. W. Baker (2015), Efficient analytical fragility function fitting using
dynamic structural analysis, Earthquake Spectra 31(1). C. A. Cornell et al. (2002),
Probabilistic basis for the 2000 SAC/FEMA steel moment frame guidelines, J. Struct. Eng.
128(4). pelicun (NHERI SimCenter), damage model CSV format.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
from scipy import stats
from scipy.integrate import quad
from scipy.stats import norm

from .._atomic import atomic_path
from .._validate import in_range
from ..errors import ParameterError, PlausibilityWarning, SimulationError
from ..plot import CURVE_GID, LINESTYLES, PALETTE, figure, im_label, style_axes, unit_label
from ..results import jsonable
from ..units import ACCELERATION, G

#: How the bootstrap band is drawn: ``"normal"`` draws the curve's coefficients from
#: the asymptotic normal distribution of the MLE (vectorised, cheap); ``"resample"``
#: resamples the records (within each stripe when every IM value is a stripe) and
#: refits each replicate; ``"cluster"`` resamples clusters of runs that are not
#: independent (:func:`fragility`'s ``clusters``: the runs of one ground-motion record
#: at several headings and levels), each drawn with all its runs, and refits.
BOOTSTRAP_METHODS = ("normal", "resample", "cluster")
MIN_CLUSTERS = 5
"""Fewer clusters than this make a cluster bootstrap's interval unreliable (with ``m``
clusters there are at most ``C(2m - 1, m)`` distinct draws: 3 for two records, and many
of them separated): :func:`fragility` warns, and :func:`rocking.analysis.heading_fragility`
gives no interval."""
_BAND_NAME = {"normal": "parametric bootstrap, asymptotic normal",
              "resample": "bootstrap, resampled records",
              "cluster": "bootstrap, resampled clusters"}

#: SI value of one unit, for the units of pelicun's ``default_units.json`` that an IM
#: may have (``Theta_0`` is written in the ``Demand-Unit``).
PELICUN_UNITS = {
    "mps2": ("acceleration", 1.0), "g": ("acceleration", G),
    "inps2": ("acceleration", 0.0254), "inchps2": ("acceleration", 0.0254),
    "ftps2": ("acceleration", 0.3048),
    "mps": ("velocity", 1.0), "cmps": ("velocity", 0.01), "inps": ("velocity", 0.0254),
    "inchps": ("velocity", 0.0254), "ftps": ("velocity", 0.3048),
    "m": ("length", 1.0), "mm": ("length", 0.001), "cm": ("length", 0.01),
    "in": ("length", 0.0254), "inch": ("length", 0.0254), "ft": ("length", 0.3048),
    "unitless": ("unitless", 1.0), "ea": ("unitless", 1.0), "rad": ("unitless", 1.0),
}
_SI_UNIT = {"acceleration": "mps2", "velocity": "mps", "length": "m", "unitless": "unitless"}

#: Units an IM may be stated in (``im_unit``): ``(kind, SI value of one unit)``, with the
#: package's spellings (``m/s^2``) beside pelicun's (``mps2``).
IM_UNITS = {
    **{k: ("acceleration", v) for k, v in ACCELERATION.items()},
    **PELICUN_UNITS,
    "m/s": ("velocity", 1.0), "cm/s": ("velocity", 0.01), "-": ("unitless", 1.0),
}


def _unit(name: str, unit) -> str | None:
    """``unit`` as a stripped string (None stays None: not stated)."""
    if unit is None:
        return None
    if not isinstance(unit, str):
        raise ParameterError(f"{name} must be a unit string such as 'm/s^2' or 'g', or "
                             f"None, got {unit!r}")
    return unit.strip()


def _unit_info(u: str):
    """``(kind, SI value)`` of an IM unit, None if unknown."""
    for key in (u, u.replace(" ", ""), u.replace(" ", "").lower()):
        if key in IM_UNITS:
            return IM_UNITS[key]
    return None


def _same_unit(a: str, b: str) -> bool:
    """Whether two IM units are the same quantity in the same unit (``m/s^2`` and
    ``mps2`` are; ``g`` and ``m/s^2`` are not)."""
    ka, kb = _unit_info(a), _unit_info(b)
    if ka is None or kb is None:
        return a.replace(" ", "").lower() == b.replace(" ", "").lower()
    return ka[0] == kb[0] and math.isclose(ka[1], kb[1], rel_tol=1e-12)

#: Columns of a pelicun fragility (damage model) table, before the limit-state columns.
PELICUN_COLUMNS = ("Incomplete", "Demand-Type", "Demand-Unit", "Demand-Offset",
                   "Demand-Directional")


# --------------------------------------------------------------------------- validation

def _as_im(name: str, value) -> np.ndarray:
    """A non-empty 1-D array of finite IM values > 0."""
    try:
        x = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be an array of numbers > 0, got {value!r}") from None
    x = np.atleast_1d(x)
    if x.ndim != 1:
        raise ParameterError(f"{name} must be one-dimensional, got shape {x.shape}")
    if x.size == 0:
        raise ParameterError(f"{name} must not be empty")
    bad = np.flatnonzero(~np.isfinite(x))
    if bad.size:
        raise ParameterError(f"{name} must be finite, got {name}[{bad[0]}] = {x[bad[0]]}")
    bad = np.flatnonzero(x <= 0.0)
    if bad.size:
        raise ParameterError(f"{name} must be > 0 (an intensity measure), got "
                             f"{name}[{bad[0]}] = {x[bad[0]]:g}")
    return x


def as_bool_array(name: str, value) -> np.ndarray:
    """A 1-D boolean array from booleans or 0/1 numbers (NaN and strings refused)."""
    arr = np.atleast_1d(np.asarray(value))
    if arr.ndim != 1:
        raise ParameterError(f"{name} must be one-dimensional, got shape {arr.shape}")
    if arr.dtype == bool:
        return arr
    if arr.dtype.kind in "iuf":
        ok = (arr == 0) | (arr == 1)
        if ok.all():
            return arr.astype(bool)
        i = int(np.flatnonzero(~ok)[0])
        raise ParameterError(f"{name} must be boolean (True/False or 0/1), got "
                             f"{name}[{i}] = {arr[i]!r}")
    for i, v in enumerate(arr.tolist()):
        if not (isinstance(v, bool | np.bool_) or (isinstance(v, int | float)
                                                  and v in (0, 1))):
            raise ParameterError(f"{name} must be boolean (True/False or 0/1), got "
                                 f"{name}[{i}] = {v!r}")
    return arr.astype(bool)


def _is_ragged(value) -> bool:
    if isinstance(value, np.ndarray):
        return value.ndim == 2 or value.dtype == object
    if isinstance(value, list | tuple):
        return any(isinstance(v, list | tuple | np.ndarray) for v in value)
    return False


def records(im, failed, *, names=("im", "failed")) -> tuple[np.ndarray, np.ndarray]:
    """``(im, failed)`` per record, validated.

    ``failed`` is either one boolean per record (``im`` the same length) or one sequence
    of booleans per stripe (``im`` the stripe levels); an empty stripe is refused.
    """
    n_im, n_f = names
    x = _as_im(n_im, im)
    if _is_ragged(failed):
        stripes = list(failed)
        if len(stripes) != x.size:
            raise ParameterError(f"{n_f} has {len(stripes)} stripes but {n_im} has {x.size} "
                                 "levels: give one sequence of outcomes per IM level")
        ims, fs = [], []
        for j, s in enumerate(stripes):
            f = as_bool_array(f"{n_f}[{j}]", s)
            if f.size == 0:
                raise ParameterError(f"{n_f}[{j}] (the stripe at {n_im} = {x[j]:g}) is "
                                     "empty: every stripe needs at least one record")
            ims.append(np.full(f.size, x[j]))
            fs.append(f)
        return np.concatenate(ims), np.concatenate(fs)
    f = as_bool_array(n_f, failed)
    if f.size != x.size:
        raise ParameterError(f"{n_im} and {n_f} must have the same length, got {x.size} "
                             f"and {f.size}")
    return x, f


def check_separation(x: np.ndarray, y: np.ndarray, what: str = "failed") -> None:
    """Refuse outcomes for which the probit MLE does not exist."""
    n1 = int(y.sum())
    if n1 == 0:
        raise ParameterError(f"{what}: no record failed, so no fragility curve can be "
                             "fitted; add stronger IM levels")
    if n1 == y.size:
        raise ParameterError(f"{what}: every record failed, so no fragility curve can be "
                             "fitted; add weaker IM levels")
    lo_fail, hi_safe = x[y].min(), x[~y].max()
    if lo_fail >= hi_safe:
        where = (f"between im = {hi_safe:g} and {lo_fail:g}" if lo_fail > hi_safe
                 else f"near im = {lo_fail:g}")
        raise ParameterError(
            f"{what} is perfectly separated by the IM (every record that failed is at im "
            f">= {lo_fail:g}, none below; every record that did not is at im <= "
            f"{hi_safe:g}): the likelihood has no maximum (beta -> 0); add records or "
            f"levels {where}")
    if x[y].max() <= x[~y].min():
        raise ParameterError(f"{what}: failures happen only at lower IM than the survivals; "
                             "a fragility curve must increase with the IM")


def fit_or_bounds(im, failed, **kwargs):
    """The fragility fit of ``im``/``failed`` (:func:`fragility`, ``kwargs`` passed on), or
    the bounds of the median that outcomes without a maximum-likelihood fit still give
    (the cases :func:`check_separation` refuses).

    Returns ``(fit, lower, upper, reason)``: ``fit`` is a :class:`FragilityFit` (bounds
    NaN, ``reason`` ``""``) or None with ``reason`` ``"none failed"`` (``lower`` = the
    largest IM run: the median is above it), ``"all failed"`` (``upper`` = the smallest
    IM run), ``"separated"`` (no failure up to ``lower``, every run failed from
    ``upper``: the median lies between) or ``"decreasing"`` (failures only below the
    survivals: no bound). Bounds are what the data show, not confidence bounds. Bad input
    (a non-positive IM, mismatched lengths, ...) raises as in :func:`fragility`.
    """
    x, y = records(im, failed)
    nan = math.nan
    n1 = int(y.sum())
    if n1 == 0:
        return None, float(x.max()), nan, "none failed"
    if n1 == y.size:
        return None, nan, float(x.min()), "all failed"
    lo_fail, hi_safe = float(x[y].min()), float(x[~y].max())
    if lo_fail >= hi_safe:
        return None, hi_safe, lo_fail, "separated"
    if x[y].max() <= x[~y].min():
        return None, nan, nan, "decreasing"
    return fragility(x, y, **kwargs), nan, nan, ""


def make_rng(seed):
    """The bootstrap's random generator from ``seed`` (an int, a SeedSequence or None)."""
    if seed is not None and not isinstance(seed, int | np.integer | np.random.SeedSequence):
        raise ParameterError(f"seed must be an int, a numpy SeedSequence or None, got "
                             f"{seed!r}")
    return np.random.default_rng(seed)


def check_n_boot(n_boot) -> int:
    """``n_boot`` checked: an integer >= 0 (the number of bootstrap draws)."""
    if isinstance(n_boot, bool) or not isinstance(n_boot, int | np.integer) or n_boot < 0:
        raise ParameterError(f"n_boot must be an integer >= 0, got {n_boot!r}")
    return int(n_boot)


def check_bootstrap(method) -> str:
    """``method`` checked: one of :data:`BOOTSTRAP_METHODS`."""
    if method not in BOOTSTRAP_METHODS:
        raise ParameterError(f"bootstrap must be one of {BOOTSTRAP_METHODS}, got {method!r}")
    return method


# --------------------------------------------------------------------------- the fit

def _delta(coef: np.ndarray, cov: np.ndarray) -> np.ndarray:
    """Covariance of ``(median, beta)`` from that of ``(b0, b1)`` (delta method)."""
    b0, b1 = coef
    median = math.exp(-b0 / b1)
    jac = np.array([[-median / b1, median * b0 / b1**2],   # d median / d(b0, b1)
                    [0.0, -1.0 / b1**2]])                    # d beta / d(b0, b1)
    return jac @ cov @ jac.T


@dataclass
class FragilityFit:
    """A lognormal fragility curve ``P = Phi(ln(im / median) / beta)`` and its uncertainty.

    ``coef = (b0, b1)`` are the probit coefficients on ``ln im`` (``median = exp(-b0/b1)``,
    ``beta = 1/b1``) and ``coef_cov`` their covariance; ``cov`` is the covariance of
    ``(median, beta)`` by the delta method. ``boot_coef`` holds the ``n_boot`` bootstrap
    coefficient pairs behind :meth:`band`. ``median`` is in the IM's unit ``im_unit``
    (``None``: not stated); ``im_name`` names the IM (``"pga"``, ...). The scalar fields are
    plain Python floats; the repr is one short line (no arrays).

    Examples
    --------
    >>> from rocking.analysis import fragility
    >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
    >>> failed = np.tile(np.arange(10), 5) < np.repeat([1, 3, 5, 7, 9], 10)
    >>> fit = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
    >>> fit
    FragilityFit('failure', pga: median 2 m/s^2, beta ..., n 50, glm-probit ...)
    >>> float(fit.probability(fit.median))  # the median is the 50 % point
    0.5
    >>> bool(np.isclose(fit.median, np.exp(-fit.coef[0] / fit.coef[1])))
    True
    """

    median: float
    beta: float
    median_se: float
    beta_se: float
    cov: np.ndarray
    coef: np.ndarray
    coef_cov: np.ndarray
    method: str
    data: object = None
    """The data: a DataFrame of stripes (``im``, ``n``, ``n_failed``) for :func:`fragility`,
    of records (``capacity``, ``censored``) for :func:`fragility_ida`."""
    boot_coef: np.ndarray = field(default_factory=lambda: np.empty((0, 2)))
    bootstrap: str = "normal"
    seed: int | None = None
    n_boot_failed: int = 0
    loglike: float = math.nan
    label: str = "failure"
    im_name: str = "im"
    im_unit: str | None = None

    def __post_init__(self):
        for k in ("median", "beta", "median_se", "beta_se", "loglike"):
            setattr(self, k, float(getattr(self, k)))
        self.n_boot_failed = int(self.n_boot_failed)
        self.im_name = str(self.im_name)
        self.im_unit = _unit("im_unit", self.im_unit)

    def __repr__(self) -> str:
        unit = f" {self.im_unit}" if self.im_unit else ""
        n = self._counts().get("n")
        return (f"FragilityFit({self.label!r}, {self.im_name}: median {self.median:.4g}{unit}"
                f", beta {self.beta:.3g}, n {n}, {self.method}, n_boot {self.n_boot})")

    def _counts(self) -> dict:
        if self.data is None:
            return {}
        if "n" in self.data:
            return {"n": int(self.data["n"].sum()), "n_failed": int(self.data["n_failed"].sum()),
                    "n_stripes": len(self.data)}
        return {"n": len(self.data), "n_censored": int(self.data["censored"].sum())}

    @property
    def im_axis_label(self) -> str:
        """The IM and its unit for a plot axis, e.g. ``PGA (m/s$^2$)``."""
        return im_label(self.im_name, self.im_unit)

    @property
    def n_boot(self) -> int:
        return int(self.boot_coef.shape[0])

    @property
    def im_range(self) -> tuple[float, float]:
        """The smallest and largest IM of the data."""
        col = "im" if "im" in self.data else "capacity"
        v = np.asarray(self.data[col], dtype=float)
        return float(v.min()), float(v.max())

    def probability(self, im):
        """P(failure | im) (an array like ``im``; scalar in, float out).

        ``Phi(ln(im / median) / beta)``: 1/2 at the median, symmetric in ``ln im`` about it.

        Examples
        --------
        >>> from rocking.analysis import fragility
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
        >>> failed = np.tile(np.arange(10), 5) < np.repeat([1, 3, 5, 7, 9], 10)
        >>> fit = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
        >>> fit.median, fit.probability(fit.median)
        (2.0, 0.5)
        >>> p = fit.probability([1.0, 4.0])  # a factor 2 below and above the median
        >>> round(float(p[0] + p[1]), 12)
        1.0
        """

        x = _as_im("im", im)
        p = norm.cdf(np.log(x / self.median) / self.beta)
        return float(p[0]) if np.ndim(im) == 0 else p

    def band(self, im, level: float = 0.95):
        """The pointwise bootstrap band at ``im``: a DataFrame with ``im``,
        ``probability``, ``lower``, ``upper`` (equal-tailed percentiles at ``level``).

        Examples
        --------
        >>> from rocking.analysis import fragility
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
        >>> failed = np.tile(np.arange(10), 5) < np.repeat([1, 3, 5, 7, 9], 10)
        >>> fit = fragility(im, failed, n_boot=200, seed=0, im_name="pga", im_unit="m/s^2")
        >>> b = fit.band([1.0, 2.0, 4.0], level=0.9)
        >>> b.columns.tolist()
        ['im', 'probability', 'lower', 'upper']
        >>> bool(np.all((b["lower"] < b["probability"]) & (b["probability"] < b["upper"])))
        True
        """

        x = _as_im("im", im)
        level = in_range("level", level, 0.0, 1.0)
        if self.n_boot == 0:
            raise ParameterError("n_boot: this fit has no bootstrap sample (n_boot=0); "
                                 "refit with n_boot > 0")
        b = self.boot_coef
        p = norm.cdf(b[:, :1] + b[:, 1:] * np.log(x)[None, :])
        q = 100.0 * (1.0 - level) / 2.0
        lo, hi = np.percentile(p, [q, 100.0 - q], axis=0)
        return pd.DataFrame({"im": x, "probability": self.probability(x),
                             "lower": lo, "upper": hi})

    def ci(self, level: float = 0.95) -> dict:
        """Bootstrap percentile intervals of ``median`` and ``beta`` (draws with
        ``b1 <= 0`` count as an infinite median and beta).

        Examples
        --------
        >>> from rocking.analysis import fragility
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
        >>> failed = np.tile(np.arange(10), 5) < np.repeat([1, 3, 5, 7, 9], 10)
        >>> fit = fragility(im, failed, n_boot=200, seed=0, im_name="pga", im_unit="m/s^2")
        >>> ci = fit.ci(0.95)
        >>> lo, hi = ci["median"]
        >>> bool(lo < fit.median < hi), bool(ci["beta"][0] < fit.beta < ci["beta"][1])
        (True, True)
        >>> ci == fit.ci(0.95)  # the same bootstrap sample: reproducible
        True
        """
        level = in_range("level", level, 0.0, 1.0)
        if self.n_boot == 0:
            raise ParameterError("n_boot: this fit has no bootstrap sample (n_boot=0)")
        b0, b1 = self.boot_coef.T
        with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
            med = np.where(b1 > 0, np.exp(-b0 / b1), np.inf)
            beta = np.where(b1 > 0, 1.0 / b1, np.inf)
        q = 100.0 * (1.0 - level) / 2.0
        return {"median": tuple(np.percentile(med, [q, 100 - q]).tolist()),
                "beta": tuple(np.percentile(beta, [q, 100 - q]).tolist()), "level": level}

    def summary(self) -> dict:
        """JSON-ready summary: the parameters, their standard errors and 95% bootstrap
        intervals, the data counts.

        Examples
        --------
        >>> from rocking.analysis import fragility
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
        >>> failed = np.tile(np.arange(10), 5) < np.repeat([1, 3, 5, 7, 9], 10)
        >>> fit = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
        >>> s = fit.summary()
        >>> s["median"], s["im_unit"], s["n"], s["n_failed"], s["n_stripes"]
        (2.0, 'm/s^2', 50, 25, 5)
        >>> bool(np.isclose(s["beta_se"] ** 2, s["cov"][1][1]))  # delta-method covariance
        True
        """
        d = {"label": self.label, "im_name": self.im_name, "im_unit": self.im_unit,
             "method": self.method, "median": self.median,
             "beta": self.beta, "median_se": self.median_se, "beta_se": self.beta_se,
             "cov": self.cov, "loglike": self.loglike, "bootstrap": self.bootstrap,
             "n_boot": self.n_boot, "n_boot_failed": self.n_boot_failed, "seed": self.seed,
             "im_range": self.im_range}
        d.update(self._counts())
        if self.n_boot:
            ci = self.ci(0.95)
            d.update(median_ci95=ci["median"], beta_ci95=ci["beta"])
        return jsonable(d)

    def to_dict(self) -> dict:
        """Everything, JSON-ready: the summary, the coefficients, the data and the
        bootstrap sample.

        Examples
        --------
        >>> from rocking.analysis import fragility
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
        >>> failed = np.tile(np.arange(10), 5) < np.repeat([1, 3, 5, 7, 9], 10)
        >>> fit = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
        >>> d = fit.to_dict()
        >>> d["data"]["n_failed"]  # the failures of each stripe
        [1, 3, 5, 7, 9]
        >>> b0, b1 = d["coef"]  # probit coefficients: median = exp(-b0 / b1)
        >>> round(float(np.exp(-b0 / b1)), 6), round(1 / b1, 6) == round(d["beta"], 6)
        (2.0, True)
        """
        d = self.summary()
        d["coef"] = jsonable(self.coef)
        d["coef_cov"] = jsonable(self.coef_cov)
        d["data"] = jsonable({k: np.asarray(v) for k, v in self.data.items()})
        d["boot_coef"] = jsonable(self.boot_coef)
        return d

    def to_pelicun(self, id: str = "rocking.overturning", *,
                   demand_type: str = "Peak Ground Acceleration", demand_unit: str = "g",
                   im_unit: str | None = None, directional: bool = True, path=None):
        """This curve as a one-row pelicun fragility table (a DataFrame indexed by ``ID``).

        Columns: ``Incomplete``, ``Demand-Type``, ``Demand-Unit``, ``Demand-Offset``,
        ``Demand-Directional``, ``LS1-Family`` (``lognormal``), ``LS1-Theta_0`` (the median,
        in ``Demand-Unit``) and ``LS1-Theta_1`` (beta, dimensionless). ``im_unit`` is the
        unit of the fitted IM: by default the fit's own ``im_unit``, else the SI unit of
        ``demand_unit``'s kind (m/s^2 for ``g``); one that contradicts the fit's is refused.
        ``path`` also writes the CSV.

        Examples
        --------
        >>> from rocking.analysis import fragility
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
        >>> failed = np.tile(np.arange(10), 5) < np.repeat([1, 3, 5, 7, 9], 10)
        >>> fit = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
        >>> row = fit.to_pelicun(path="fragility.csv")  # the median in g
        >>> row.loc["rocking.overturning", ["Demand-Unit", "LS1-Family"]].tolist()
        ['g', 'lognormal']
        >>> round(float(row["LS1-Theta_0"].iloc[0]), 5), round(2.0 / 9.80665, 5)
        (0.20394, 0.20394)
        >>> import pandas as pd
        >>> pd.read_csv("fragility.csv", index_col="ID").columns.tolist()[-2:]
        ['LS1-Theta_0', 'LS1-Theta_1']
        """
        return pelicun_table([self], id=id, demand_type=demand_type,
                             demand_unit=demand_unit, im_unit=im_unit,
                             directional=directional, path=path)

    def plot(self, ax=None, *, level: float = 0.95, band: bool = True, data: bool = True,
             im=None, label: str | None = None, color=None, ls=None):
        """The curve, its bootstrap band and the data (the failed fraction of each stripe,
        or the Kaplan-Meier estimate of the IDA capacities); returns the Axes.

        Several fits drawn on one ``ax`` get distinct colours and line styles (the ``k``-th
        fragility curve on the axes: :data:`rocking.plot.PALETTE` and
        :data:`rocking.plot.LINESTYLES`, unless ``color`` / ``ls`` are given), and the
        legend stands outside the data, to the right of the axes.

        Examples
        --------
        >>> from rocking.analysis import fragility
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
        >>> failed = np.tile(np.arange(10), 5) < np.repeat([1, 3, 5, 7, 9], 10)
        >>> fit = fragility(im, failed, n_boot=200, seed=0, im_name="pga", im_unit="m/s^2")
        >>> ax = fit.plot()
        >>> ax.get_xlabel()
        'PGA (m/s$^2$)'
        >>> [t.get_text() for t in ax.get_legend().get_texts()]
        ['failure: median 2 m/s$^2$, beta 1.14',
         '95% band (parametric bootstrap, asymptotic normal)']
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """

        if ax is None:
            _, ax = figure()
        k = sum(ln.get_gid() == CURVE_GID for ln in ax.lines)  # curves already drawn
        color = color or PALETTE[k % len(PALETTE)]
        ls = ls or LINESTYLES[k % len(LINESTYLES)]
        lo, hi = self.im_range
        x = (_as_im("im", im) if im is not None else
             np.geomspace(min(lo, self.median * math.exp(-2.5 * self.beta)),
                          max(hi, self.median * math.exp(2.5 * self.beta)), 200))
        unit = unit_label(self.im_unit)
        ax.plot(x, self.probability(x), color=color, ls=ls, gid=CURVE_GID,
                label=label or f"{self.label}: median {self.median:.3g}"
                               f"{' ' + unit if unit else ''}, beta {self.beta:.2f}")
        if band and self.n_boot:
            b = self.band(x, level)
            ax.fill_between(x, b["lower"], b["upper"], color=color, alpha=0.2, lw=0,
                            label=f"{100 * level:g}% band ({_BAND_NAME[self.bootstrap]})")
        if data:
            self._plot_data(ax, color)
        style_axes(ax, self.im_axis_label, "probability of exceedance")
        ax.set_ylim(-0.02, 1.02)
        handles, labels = ax.get_legend_handles_labels()
        bands = [i for i, t in enumerate(labels) if "% band (" in t]
        if len(bands) > 1:  # one entry, in grey, for the bands of every curve
            from matplotlib.patches import Patch

            first = labels[bands[0]]
            handles = [h for i, h in enumerate(handles) if i not in bands] + [
                Patch(color="0.6", alpha=0.35, lw=0)]
            labels = [t for i, t in enumerate(labels) if i not in bands] + [first]
        ax.legend(handles, labels, frameon=False, fontsize="small", loc="upper left",
                  bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
        return ax

    def _plot_data(self, ax, color):
        if "n" in self.data:
            d = self.data
            ax.plot(d["im"], d["n_failed"] / d["n"], "o", ms=4, color=color, mfc="none")
            return

        d = self.data
        from statsmodels.duration.survfunc import SurvfuncRight

        sf = SurvfuncRight(np.asarray(d["capacity"]), (~np.asarray(d["censored"])).astype(int))
        ax.step(sf.surv_times, 1.0 - sf.surv_prob, where="post", color=color, lw=0.8,
                ls="--", label="Kaplan-Meier")


def pelicun_table(fits, *, id: str, demand_type: str, demand_unit: str,
                  im_unit: str | None = None, directional: bool = True, path=None):
    """A one-row pelicun fragility table with one limit state per fit (``LS1``,
    ``LS2``, ...); see :meth:`FragilityFit.to_pelicun`."""

    if demand_unit not in PELICUN_UNITS:
        raise ParameterError(f"demand_unit must be one of pelicun's units "
                             f"{sorted(PELICUN_UNITS)}, got {demand_unit!r}")
    kind, to_si = PELICUN_UNITS[demand_unit]
    stated = {f.im_unit for f in fits if getattr(f, "im_unit", None)}
    if len(stated) > 1:
        raise ParameterError(f"the fits have different IM units {sorted(stated)}: one "
                             "pelicun row needs one")
    if im_unit is None and stated:
        own = stated.pop()
        im_unit = next((k for k, v in PELICUN_UNITS.items()
                        if k == own or v == _unit_info(own)), None)
        if im_unit is None:
            raise ParameterError(f"im_unit: the fits' IM unit {own!r} is not one of "
                                 f"pelicun's units {sorted(PELICUN_UNITS)}; give im_unit")
    elif im_unit is not None and stated:
        own = stated.pop()
        if not _same_unit(own, im_unit):
            raise ParameterError(f"im_unit={im_unit!r} contradicts the fits' IM unit "
                                 f"{own!r}")
    im_unit = _SI_UNIT[kind] if im_unit is None else im_unit
    if im_unit not in PELICUN_UNITS or PELICUN_UNITS[im_unit][0] != kind:
        raise ParameterError(f"im_unit must be a {kind} unit of {sorted(PELICUN_UNITS)} "
                             f"(like demand_unit={demand_unit!r}), got {im_unit!r}")
    factor = PELICUN_UNITS[im_unit][1] / to_si
    row = {"Incomplete": 0, "Demand-Type": str(demand_type), "Demand-Unit": demand_unit,
           "Demand-Offset": 0, "Demand-Directional": int(bool(directional))}
    for k, f in enumerate(fits, start=1):
        row[f"LS{k}-Family"] = "lognormal"
        row[f"LS{k}-Theta_0"] = f.median * factor
        row[f"LS{k}-Theta_1"] = f.beta
    df = pd.DataFrame([row], index=pd.Index([str(id)], name="ID"))
    if path is not None:
        with atomic_path(path) as tmp:
            df.to_csv(tmp)
    return df


def _glm(x: np.ndarray, k: np.ndarray, n: np.ndarray):
    """The probit GLM on ``ln x`` of ``k`` failures out of ``n`` per row."""

    exog = np.column_stack([np.ones_like(x), np.log(x)])
    endog = np.column_stack([k, n - k])
    import statsmodels.api as sm  # statsmodels is imported on first use (1-1.5 s)

    model = sm.GLM(endog, exog, family=sm.families.Binomial(link=sm.families.links.Probit()))
    return model.fit()


def stripe_counts(x: np.ndarray, y: np.ndarray):
    """``(levels, n, k, inv)``: the distinct IM levels, the records and failures at each,
    and each record's level index."""
    levels, inv = np.unique(x, return_inverse=True)
    n = np.bincount(inv, minlength=levels.size)
    k = np.bincount(inv, weights=y, minlength=levels.size).astype(int)
    return levels, n, k, inv


def fragility(im, failed, *, n_boot: int = 1000, seed: int | None = 0,
              bootstrap: str = "normal", label: str = "failure", im_name: str = "im",
              im_unit: str | None = None, clusters=None) -> FragilityFit:
    """A lognormal fragility curve fitted by maximum likelihood (Baker 2015).

    ``im``: the IM of each record (> 0, SI units or dimensionless); ``failed``: its
    outcome (booleans or 0/1). Alternatively ``im`` are the stripe levels and ``failed``
    one sequence of outcomes per stripe. Records at the same IM form a stripe, so one
    binomial likelihood covers multiple-stripe analysis.

    The fit is a statsmodels binomial GLM with a probit link on ``ln im``;
    ``median = exp(-b0/b1)``, ``beta = 1/b1``, standard errors by the delta method.
    The band uses ``n_boot`` bootstrap draws (``seed``): ``bootstrap="normal"`` draws
    ``(b0, b1)`` from the GLM's asymptotic normal distribution (the default: vectorised;
    its pointwise band is the Wald interval of the linear predictor mapped through Phi);
    ``"resample"`` resamples the records within each stripe (all records when some IM
    has a single record) and refits each replicate; ``"cluster"`` resamples the
    ``clusters`` (one label per outcome: runs that are not independent of each other,
    such as the runs of one ground-motion record at several headings and levels), each
    drawn cluster with all its runs, and refits (the cluster bootstrap: Cameron, Gelbach
    and Miller 2008, J. Econometrics; with perfectly correlated runs in clusters of ``k``
    its interval is about ``sqrt(k)`` times the others'). Replicates with separated data
    are skipped and counted in ``n_boot_failed``.

    ``im_name`` and ``im_unit`` name the IM and its unit (e.g. ``"pga"``, ``"m/s^2"``, as
    in the ``attrs`` of an :func:`~rocking.analysis.ida` table); the fit carries them to its
    plot, to :func:`annual_frequency` (which then refuses a hazard curve in another unit)
    and to :meth:`FragilityFit.to_pelicun`.

    Raises :class:`~rocking.ParameterError` for bad input, and when the MLE does not
    exist: no failure, all failed, or outcomes perfectly separated by the IM.

    Examples
    --------
    Planted stripes: at each PGA level the failed fraction of a lognormal curve of median
    3 m/s^2 and beta 0.4; the fit recovers them.

    >>> from scipy.stats import norm
    >>> from rocking.analysis import fragility
    >>> im = np.repeat([1.0, 2.0, 3.0, 4.0, 6.0], 100)  # PGA (m/s^2), 100 records each
    >>> n_fail = np.round(100 * norm.cdf(np.log(im / 3.0) / 0.4))
    >>> failed = np.tile(np.arange(100), 5) < n_fail
    >>> fit = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
    >>> round(fit.median, 1), round(fit.beta, 1)
    (3.0, 0.4)
    """

    im_unit = _unit("im_unit", im_unit)
    x, y = records(im, failed)
    n_boot, rng, bootstrap = check_n_boot(n_boot), make_rng(seed), check_bootstrap(bootstrap)
    cl = _clusters(clusters, x.size, bootstrap)
    check_separation(x, y)
    levels, n, k, inv = stripe_counts(x, y)
    res = _glm(levels, k, n)
    coef = np.asarray(res.params, dtype=float)
    coef_cov = np.asarray(res.cov_params(), dtype=float)
    if not np.all(np.isfinite(coef_cov)) or coef[1] <= 0:
        raise SimulationError("the probit GLM did not give a finite, increasing fit "
                              f"(b1 = {coef[1]:g}); check the data")
    n_fail = 0
    if n_boot == 0:
        boot = np.empty((0, 2))
    elif bootstrap == "normal":
        boot = rng.multivariate_normal(coef, coef_cov, size=n_boot)
    elif bootstrap == "cluster":
        boot, n_fail = _resample_clusters(x, y, cl, n_boot, rng)
    else:
        boot, n_fail = _resample_glm(levels, n, k, x, y, inv, n_boot, rng)
    return make_fit(coef, coef_cov, "glm-probit (Baker 2015)",
                    pd.DataFrame({"im": levels, "n": n, "n_failed": k}), boot, bootstrap,
                    seed, n_fail, float(res.llf), label, im_name, im_unit)


def _clusters(clusters, n: int, bootstrap: str) -> np.ndarray | None:
    """The cluster label of each of the ``n`` outcomes (integers 0..m-1), checked: given
    iff ``bootstrap == "cluster"``, one per outcome, at least two clusters."""
    if clusters is None:
        if bootstrap == "cluster":
            raise ParameterError("clusters: bootstrap='cluster' needs a cluster label per "
                                 "outcome (e.g. the record of each run)")
        return None
    if bootstrap != "cluster":
        raise ParameterError(f"clusters are used by bootstrap='cluster' only, got "
                             f"bootstrap={bootstrap!r}")
    c = np.asarray(clusters)
    if c.ndim != 1 or c.size != n:
        raise ParameterError(f"clusters must be one label per outcome ({n}), got shape "
                             f"{c.shape}")
    _, inv = np.unique(c, return_inverse=True)
    m = int(inv.max(initial=0)) + 1
    if m < 2:
        raise ParameterError("clusters: at least 2 clusters are needed to resample them")
    if m < MIN_CLUSTERS:
        warnings.warn(f"clusters: {m} clusters are too few for a bootstrap of them (at "
                      f"least {MIN_CLUSTERS}): its band and intervals are unreliable, "
                      "degenerate for 2", PlausibilityWarning, stacklevel=3)
    return inv


def bootstrap_reliable(fit: FragilityFit) -> bool:
    """Whether a fit's bootstrap interval can be shown: at most half of its replicates
    failed (separated outcomes: ``n_boot_failed``) and they are not all the same (a
    bootstrap of two clusters can draw nothing new)."""
    return (fit.n_boot > 0 and fit.n_boot_failed <= fit.n_boot
            and np.unique(np.round(fit.boot_coef, 12), axis=0).shape[0] > 1)


def unreliable_note(fit: FragilityFit) -> str:
    """Why a fit's bootstrap gives no interval (:func:`bootstrap_reliable` false)."""
    return (f"no interval: {fit.n_boot_failed} of {fit.n_boot + fit.n_boot_failed} "
            "bootstrap replicates had separated outcomes or none differed (too few "
            "records, or too few levels between the first overturning and the last "
            "survival)")


def _resample_clusters(x, y, cl, n_boot, rng):
    """Bootstrap refits drawing the clusters ``cl`` (labels 0..m-1) with replacement, each
    with all its outcomes."""
    m = int(cl.max()) + 1
    order = np.argsort(cl, kind="stable")
    starts = np.searchsorted(cl[order], np.arange(m + 1))
    members = [order[starts[j]:starts[j + 1]] for j in range(m)]
    out, failed = [], 0
    for _ in range(n_boot):
        idx = np.concatenate([members[j] for j in rng.integers(0, m, m)])
        xb, yb = x[idx], y[idx]
        try:
            check_separation(xb, yb)
            lv, nb, kb, _ = stripe_counts(xb, yb)
            r = _glm(lv, kb, nb)
        except (ParameterError, ValueError, np.linalg.LinAlgError):
            failed += 1
            continue
        out.append(np.asarray(r.params, dtype=float))
    return (np.array(out) if out else np.empty((0, 2))), failed


def _resample_glm(levels, n, k, x, y, inv, n_boot, rng):
    """Bootstrap refits: within stripes when every stripe has >= 2 records (a binomial
    draw of each stripe's count), else plain case resampling."""
    stratified = bool(n.min() >= 2)
    out, failed = [], 0
    for _ in range(n_boot):
        if stratified:
            kb, nb, xb = rng.binomial(n, k / n), n, levels
        else:
            idx = rng.integers(0, x.size, x.size)
            xb, nb, kb, _ = stripe_counts(x[idx], y[idx])
        yb = np.concatenate([np.r_[np.ones(a, bool), np.zeros(b - a, bool)]
                             for a, b in zip(kb, nb, strict=True)])
        try:
            check_separation(np.repeat(xb, nb), yb)
            r = _glm(xb, kb, nb)
        except (ParameterError, ValueError, np.linalg.LinAlgError):
            failed += 1
            continue
        out.append(np.asarray(r.params, dtype=float))
    return (np.array(out) if out else np.empty((0, 2))), failed


def make_fit(coef, coef_cov, method, data, boot, bootstrap, seed, n_fail, llf, label,
             im_name="im", im_unit=None):
    """A :class:`FragilityFit` from the probit coefficients ``(b0, b1)`` and their
    covariance (median, beta and their standard errors by the delta method)."""
    cov = _delta(coef, coef_cov)
    return FragilityFit(
        median=math.exp(-coef[0] / coef[1]), beta=1.0 / coef[1],
        median_se=math.sqrt(cov[0, 0]), beta_se=math.sqrt(cov[1, 1]), cov=cov, coef=coef,
        coef_cov=coef_cov, method=method, data=data, boot_coef=np.asarray(boot, float),
        bootstrap=bootstrap, seed=seed if isinstance(seed, int | type(None)) else None,
        n_boot_failed=n_fail, loglike=llf, label=label, im_name=im_name, im_unit=im_unit)


# --------------------------------------------------------------------------- IDA

def _censored_loglike(mu, log_beta, cap, cens):

    z = (np.log(cap) - mu) / math.exp(log_beta)
    return float(np.sum(norm.logpdf(z[~cens]) - log_beta - np.log(cap[~cens]))
                 + np.sum(norm.logsf(z[cens])))


def _lognorm_fit(cap, cens):

    data = stats.CensoredData(uncensored=cap[~cens], right=cap[cens])
    s, _, scale = stats.lognorm.fit(data, floc=0)
    return math.log(scale), float(s)


def fragility_ida(capacity, censored=None, *, n_boot: int = 1000, seed: int | None = 0,
                  bootstrap: str = "normal", label: str = "failure", im_name: str = "im",
                  im_unit: str | None = None) -> FragilityFit:
    """A lognormal fragility curve from IDA capacities, with right-censoring.

    ``capacity``: per record, the IM at which it first failed; for a ``censored`` record
    (one that never failed up to the largest level run) that largest level: its capacity
    is only known to exceed it. The fit maximises the censored likelihood
    ``prod f(c_i) * prod (1 - F(c_j))`` with scipy (``CensoredData`` and
    ``lognorm.fit(..., floc=0)``); the covariance is the inverse of the observed
    information (statsmodels' numerical Hessian at the MLE).

    Dropping the censored records biases the median low: they are the strongest records,
    and deleting them leaves a sample truncated from above (every capacity below the top
    level). Treating them as failing at the top level biases it low too. The censored
    likelihood uses exactly what is known about them.

    ``n_boot``, ``seed``, ``bootstrap``, ``im_name`` and ``im_unit`` as in
    :func:`fragility` (``"resample"`` resamples records and refits, about 0.1 s per
    replicate).

    Examples
    --------
    Capacities of a lognormal (median 3, beta 0.4) known up to 5 only: the records above
    are censored at 5, and the censored likelihood still recovers the median and beta.

    >>> from scipy.stats import norm
    >>> from rocking.analysis import fragility_ida
    >>> capacity = 3.0 * np.exp(0.4 * norm.ppf((np.arange(200) + 0.5) / 200))
    >>> censored = capacity > 5.0
    >>> fit = fragility_ida(np.minimum(capacity, 5.0), censored, n_boot=0)
    >>> int(censored.sum()), round(fit.median, 1), round(fit.beta, 1)
    (20, 3.0, 0.4)
    """

    im_unit = _unit("im_unit", im_unit)
    cap = _as_im("capacity", capacity)
    cens = (np.zeros(cap.size, bool) if censored is None else as_bool_array("censored", censored))
    if cens.size != cap.size:
        raise ParameterError(f"capacity and censored must have the same length, got "
                             f"{cap.size} and {cens.size}")
    n_boot, rng, bootstrap = check_n_boot(n_boot), make_rng(seed), check_bootstrap(bootstrap)
    if bootstrap == "cluster":
        raise ParameterError("bootstrap='cluster' is for fragility(..., clusters=...); "
                             "fragility_ida takes 'normal' or 'resample'")
    unc = cap[~cens]
    if unc.size < 2 or np.unique(unc).size < 2:
        raise ParameterError("capacity: at least two distinct uncensored capacities are "
                             f"needed to fit a median and a beta, got {unc.size} "
                             f"uncensored of {cap.size}")
    mu, beta = _lognorm_fit(cap, cens)
    if not (math.isfinite(mu) and beta > 0):
        raise SimulationError("the censored lognormal fit did not converge")
    theta = np.array([mu, math.log(beta)])
    from statsmodels.tools.numdiff import approx_hess3

    hess = approx_hess3(theta, lambda t: _censored_loglike(t[0], t[1], cap, cens))
    try:
        cov_t = np.linalg.inv(-hess)              # covariance of (mu, ln beta)
    except np.linalg.LinAlgError:
        raise SimulationError("the censored likelihood is flat at its maximum") from None
    # (mu, ln beta) -> (b0, b1) = (-mu / beta, 1 / beta)
    jac = np.array([[-1.0 / beta, mu / beta], [0.0, -1.0 / beta]])
    coef = np.array([-mu / beta, 1.0 / beta])
    coef_cov = jac @ cov_t @ jac.T
    n_fail = 0
    if n_boot == 0:
        draws = np.empty((0, 2))
    elif bootstrap == "normal":
        draws = rng.multivariate_normal(theta, cov_t, size=n_boot)
    else:
        draws = []
        for _ in range(n_boot):
            idx = rng.integers(0, cap.size, cap.size)
            if np.unique(cap[idx][~cens[idx]]).size < 2:
                n_fail += 1
                continue
            m, b = _lognorm_fit(cap[idx], cens[idx])
            draws.append((m, math.log(b)))
        draws = np.array(draws).reshape(-1, 2)
    bb = np.exp(draws[:, 1])
    boot = np.column_stack([-draws[:, 0] / bb, 1.0 / bb])
    llf = _censored_loglike(mu, math.log(beta), cap, cens)
    return make_fit(coef, coef_cov, "censored lognormal MLE (IDA)",
                    pd.DataFrame({"capacity": cap, "censored": cens}), boot, bootstrap,
                    seed, n_fail, llf, label, im_name, im_unit)


# --------------------------------------------------------------------------- hazard

def annual_frequency(fit, hazard_im, hazard_rate, *, hazard_unit: str | None = None,
                     tail: bool = True):
    """The mean annual frequency of exceeding the state of ``fit`` (Cornell et al. 2002):
    ``lambda_f = integral P(f | im) |d lambda_IM / d im| d im``.

    ``hazard_unit`` is the unit of ``hazard_im``. It must be given, and equal the fit's
    ``im_unit``, when the fit states its unit: a hazard curve in g with a fit in m/s^2 is
    refused (integrated as it stands it would be wrong by orders of magnitude). A fit
    without a stated unit cannot be checked: ``hazard_im`` is taken in its IM's units.

    ``hazard_im`` (increasing, > 0, in the fit's IM units) and ``hazard_rate`` (the annual
    rate of exceeding each IM: > 0, non-increasing, not all equal) are the hazard curve,
    interpolated log-log between its points; each segment is integrated with
    ``scipy.integrate.quad``. With ``tail`` the records beyond the last point add
    ``lambda(im_max) * P(f | im_max)`` (a lower bound of their share). For a power-law
    hazard ``k0 im^-k`` this tends to ``k0 median^-k exp(k^2 beta^2 / 2)``.

    ``fit``: a :class:`FragilityFit` (returns a float) or anything with
    ``probability(im)`` and a sequence ``fits`` (one float per fit, as a list).

    Examples
    --------
    On a power-law hazard ``lambda = k0 im^-k`` the result approaches Cornell's closed form
    ``k0 median^-k exp(k^2 beta^2 / 2)``:

    >>> from rocking.analysis import annual_frequency, fragility
    >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
    >>> failed = np.tile(np.arange(10), 5) < np.repeat([1, 3, 5, 7, 9], 10)
    >>> fit = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
    >>> x = np.logspace(-4, 3, 80)  # m/s^2
    >>> lam = annual_frequency(fit, x, 1e-2 * x**-2.0, hazard_unit="m/s^2")
    >>> closed = 1e-2 * fit.median**-2.0 * np.exp(2.0 * fit.beta**2)
    >>> bool(abs(lam / closed - 1) < 1e-3)
    True
    """

    x = _as_im("hazard_im", hazard_im)
    lam = np.atleast_1d(np.asarray(hazard_rate, dtype=float))
    if lam.shape != x.shape:
        raise ParameterError(f"hazard_im and hazard_rate must have the same length, got "
                             f"{x.size} and {lam.size}")
    if x.size < 2:
        raise ParameterError("hazard_im must have at least 2 points")
    if not np.all(np.diff(x) > 0):
        raise ParameterError("hazard_im must be strictly increasing")
    if not np.all(np.isfinite(lam)) or np.any(lam <= 0):
        raise ParameterError("hazard_rate must be finite and > 0 (annual rates of "
                             "exceedance; log-log interpolation)")
    if np.any(np.diff(lam) > 0) or lam[0] == lam[-1]:
        raise ParameterError("hazard_rate must be non-increasing with hazard_im (a rate of "
                             "exceedance), and not constant")
    hazard_unit = _unit("hazard_unit", hazard_unit)
    fits = getattr(fit, "fits", None)
    if fits is not None:
        return [annual_frequency(f, x, lam, hazard_unit=hazard_unit, tail=tail)
                for f in fits]
    if not callable(getattr(fit, "probability", None)):
        raise ParameterError(f"fit must be a FragilityFit, got {type(fit).__name__}")
    own = getattr(fit, "im_unit", None)
    if own:
        what = f"{getattr(fit, 'im_name', 'im')} in {own}"
        if hazard_unit is None:
            raise ParameterError(f"hazard_unit is required: the fit's IM is {what}; give "
                                 f"the unit of hazard_im (hazard_unit={own!r} if it is the "
                                 "same)")
        if not _same_unit(own, hazard_unit):
            a, b = _unit_info(own), _unit_info(hazard_unit)
            hint = (f"; convert hazard_im (1 {hazard_unit} = {b[1] / a[1]:.6g} {own})"
                    if a and b and a[0] == b[0] else "")
            raise ParameterError(f"hazard_unit={hazard_unit!r} differs from the fit's IM "
                                 f"unit ({what}): the hazard curve and the fragility curve "
                                 f"must be in the same unit{hint}")
    u, ll = np.log(x), np.log(lam)
    slope = -np.diff(ll) / np.diff(u)              # local hazard exponent k_i >= 0
    total = 0.0
    for i in range(x.size - 1):
        if slope[i] == 0.0:
            continue

        def integrand(v, i=i):
            rate = math.exp(ll[i] - slope[i] * (v - u[i]))
            return float(fit.probability(math.exp(v))) * slope[i] * rate

        val, _ = quad(integrand, u[i], u[i + 1], limit=200, epsabs=0.0, epsrel=1e-10)
        total += val
    if tail:
        total += float(lam[-1]) * float(fit.probability(float(x[-1])))
    return total


__all__ = ["FragilityFit", "fragility", "fragility_ida", "annual_frequency", "records",
           "pelicun_table", "BOOTSTRAP_METHODS", "PELICUN_UNITS", "PELICUN_COLUMNS",
           "IM_UNITS"]
