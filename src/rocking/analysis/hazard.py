"""Seismic hazard curves and the risk of a fragility over a service life (issue 21).

A :class:`HazardCurve` is the annual rate of exceeding an intensity measure (IM), with the
IM's name and unit. It is built from

* an OpenQuake engine export (:meth:`HazardCurve.from_openquake`, the documented
  ``hazard_curve-<kind>-<IMT>_<id>.csv``: probabilities of exceedance ``poe`` in the
  investigation time ``T`` become rates ``-ln(1 - poe) / T``);
* a plain CSV of IM and annual rate or return period (:meth:`HazardCurve.from_csv`; a
  probability of exceedance only with its ``investigation_time``);
* a code value (:meth:`HazardCurve.from_code_value`): EN 1998-1 (2004) 2.1(4) note,
  ``lambda(a) = (1/475) (a / a_475)^-k`` with k of the order of 3 -- an approximation,
  flagged ``approximate=True`` and labelled so.

:func:`risk` integrates a fragility against the curve over the whole IM range
(Cornell et al. 2002, ``lambda_f = integral P(f | im) |d lambda / d im| d im``). Tail model:
beyond its first and last points the curve is extended as a power law, below the first
with the log-log slope of its first two points and above the last with that of its last
two (:attr:`HazardCurve.tail_slopes`), so the integral runs from 0 to infinity; the share of the
result that comes from these extrapolated tails is reported (``tail_share``).
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import ParameterError
from ..plot import PALETTE, figure, im_label, style_axes
from .fragility import IM_UNITS

#: Reference return periods of EN 1998-1 (no-collapse and a rarer check), years.
RETURN_PERIODS = (475.0, 2475.0)


def _unit_factor(unit: str):
    """``(kind, SI value of one unit)`` of an IM unit, None if unknown."""
    for key in (unit, unit.replace(" ", ""), unit.replace(" ", "").lower()):
        if key in IM_UNITS:
            return IM_UNITS[key]
    return None


#: Default ``max_distance_km`` of :meth:`HazardCurve.from_openquake`: a site chosen by
#: (lon, lat) farther than this from the nearest site of the file is refused.
MAX_SITE_DISTANCE_KM = 50.0
EARTH_RADIUS_KM = 6371.0  # mean radius (IUGG R1 = 6371.0088 km)


def great_circle_km(lon0, lat0, lon, lat):
    """Great-circle distance (km) on a sphere of radius :data:`EARTH_RADIUS_KM`
    (haversine formula), degrees in; periodic in longitude.

    Examples
    --------
    >>> from rocking.analysis.hazard import great_circle_km
    >>> round(float(great_circle_km(0, 0, 1, 0)), 3)  # pi R / 180
    111.195
    """
    lo0, la0, lo, la = (np.radians(np.asarray(v, dtype=float)) for v in (lon0, lat0, lon, lat))
    h = (np.sin((la - la0) / 2) ** 2
         + np.cos(la) * np.cos(la0) * np.sin((lo - lo0) / 2) ** 2)
    return 2 * EARTH_RADIUS_KM * np.arcsin(np.sqrt(np.clip(h, 0.0, 1.0)))


def _lon_lat(site) -> tuple[float, float]:
    """``(lon, lat)`` in degrees, checked: finite, lon in [-180, 360), lat in [-90, 90]."""
    if len(site) != 2:
        raise ParameterError(f"site must be an index or (lon, lat), got {site!r}")
    try:
        lon, lat = (float(v) for v in site)
    except (TypeError, ValueError):
        raise ParameterError(f"site must be an index or (lon, lat) in degrees, got "
                             f"{site!r}") from None
    if not (math.isfinite(lon) and -180.0 <= lon < 360.0):
        raise ParameterError(f"site: lon must be finite, in [-180, 360) degrees, got "
                             f"{site[0]!r}")
    if not (math.isfinite(lat) and -90.0 <= lat <= 90.0):
        raise ParameterError(f"site: lat must be finite, in [-90, 90] degrees, got "
                             f"{site[1]!r}")
    return lon, lat


def _positive(name: str, value) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number > 0, got {value!r}") from None
    if not math.isfinite(v) or v <= 0:
        raise ParameterError(f"{name} must be a finite number > 0, got {value!r}")
    return v


def code_pga(name: str, value, unit: str = "g") -> float:
    """A code PGA (``pga_475``, ``pga_2475``) in ``unit``: a bare number in ``unit``
    (default g), or a string with its unit (``"0.25g"``, ``"2.45m/s^2"``; a bare string
    is in ``unit``), the same forms as the campaign spec's; > 0. A site PGA above 2 g
    (:data:`rocking.PLAUSIBLE_LIMITS`) gets a :class:`~rocking.errors.UnitSlipWarning`.

    Examples
    --------
    >>> from rocking.analysis.hazard import code_pga
    >>> code_pga("pga_475", 0.25), round(code_pga("pga_475", "2.4516625m/s^2"), 9)
    (0.25, 0.25)
    """
    from .._validate import check_plausible
    from ..units import acceleration_factor, parse_quantity

    try:
        factor = acceleration_factor(unit)
    except ParameterError:
        factor = None  # a unit of the user's own (a label): bare numbers only
    if isinstance(value, str):
        if factor is None:
            raise ParameterError(f"{name}: a value with a unit ({value!r}) needs an "
                                 f"acceleration unit=, got unit={unit!r}")
        si = parse_quantity(value, "acceleration", name=name, default_unit=unit)
        v = _positive(name, si / factor)
    else:
        if isinstance(value, bool):
            raise ParameterError(f"{name} must be a number > 0 (in {unit}) or a string "
                                 f"with its unit such as '0.25g', got {value!r}")
        v = _positive(name, value)
    if factor is not None:
        check_plausible("site_pga", v * factor, name, shown=f"{value!r} ({v:g} {unit})")
    return v


#: Second-column header words of :meth:`HazardCurve.from_csv` (shown in its refusals).
RATE_WORDS = ("rate", "annual rate", "lambda", "AFE", "MAFE", "frequency", "1/yr",
              "per year")
PERIOD_WORDS = ("return period", "T_R", "Tr", "RP", "T", "years")
POE_WORDS = ("poe", "prob", "probability")

#: Days in a year of a hazard header's ``days`` (the Julian year); a month is 1/12 year.
DAYS_PER_YEAR = 365.25
#: Units of time of a hazard header, in years.
TIME_UNITS = {**dict.fromkeys(("y", "yr", "yrs", "year", "years", "annum", "a"), 1.0),
              **dict.fromkeys(("month", "months", "mo", "mon", "mos", "mth", "mths"),
                              1.0 / 12.0),
              **dict.fromkeys(("day", "days", "d"), 1.0 / DAYS_PER_YEAR)}
_RATE_TOKENS = {"rate", "rates", "lambda", "afe", "mafe", "frequency", "freq"}
_PERIOD_TOKENS = {"period", "periods", "return", "tr", "rp", "t"}
_POE_TOKENS = {"poe", "poes", "prob", "probability", "probabilities", "ape"}
_ANNUAL_TOKENS = {"annual", "annually", "yearly"}
_FILLER_TOKENS = {"of", "in", "exceedance", "exceedances", "exceeding", "mean", "the",
                  "within", "average"}
_SEPARATORS = set("()[]{},:;-")
HEADER_UNITS = ("years, months or days (a return period: 'return period (months)'); per "
                "year, month or day ('rate (1/month)', 'rate per day'); percent ('%/yr'); "
                "a probability in T years ('probability of exceedance in 50 years')")
"""What a hazard CSV's second header may say of its unit (shown in refusals)."""


def _words_hint() -> str:
    return (f"head it with an annual rate of exceedance ({', '.join(RATE_WORDS)}) or a "
            f"return period ({', '.join(PERIOD_WORDS)}); a probability of exceedance "
            f"({', '.join(POE_WORDS)}) needs investigation_time=; units: {HEADER_UNITS}")


def _as_written(word: str, header: str) -> str:
    """``word`` (lower case) as ``header`` spells it."""
    m = re.search(r"(?<![a-z])" + re.escape(word) + r"(?![a-z])", header, re.I)
    return m.group(0) if m else word


def column_meaning(header: str) -> tuple[str, float, tuple]:
    """``(kind, factor, stated_years)`` of a hazard CSV's second-column header, every word
    of it understood or refused (:class:`~rocking.errors.ParameterError` naming the word).

    ``kind``: ``"rate"`` (rate words, ``annual`` or a ``per`` unit of time), ``"period"``
    (return-period words or a bare unit of time) or ``"poe"`` (a probability of
    exceedance). ``factor`` takes a value to an annual rate (``rate (1/month)``: 12), a
    return period in years (``return period (days)``: 1/365.25) or a probability
    (``poe (%)``: 0.01). ``stated_years``: the times a poe header states, in years
    (``poe_50yr`` -> 50, ``annual`` -> 1). Units: years, months (1/12 year), days
    (1/:data:`DAYS_PER_YEAR` year), ``per`` / ``1/`` / ``^-1`` of these, ``%``.

    Examples
    --------
    >>> from rocking.analysis.hazard import column_meaning
    >>> column_meaning("annual rate (1/year)"), column_meaning("return period (months)")
    (('rate', 1.0, ()), ('period', 0.08333333333333333, ()))
    >>> column_meaning("exceedance rate (%/yr)"), column_meaning("poe_50yr")
    (('rate', 0.01, ()), ('poe', 1.0, (50.0,)))
    >>> try:
    ...     column_meaning("frequency (Hz)")
    ... except ValueError as e:
    ...     print(str(e)[:60])
    the second column's header 'frequency (Hz)': 'Hz' is not a w
    """
    head = str(header).strip()
    low = head.lower()
    low = re.sub(r"(?<![a-z0-9])p\s*\(\s*(?:im|x|iml)?\s*>\s*[a-z0-9.]*\s*\)", " poe ", low)
    low = re.sub(r"(?<![a-z0-9])t[\s_-]?r(?![a-z0-9])", " tr ", low)
    low = low.replace("_", " ")
    low = re.sub(r"(?<![\d.])1\s*/\s*", " per ", low)
    low = low.replace("/", " per ")
    low = re.sub(r"([a-z]+)\s*\^\s*-\s*1(?![\d.])|([a-z]+)\s*-\s*1(?![\d.])",
                 lambda m: f" per {m.group(1) or m.group(2)} ", low)
    low = low.replace("%", " percent ")
    low = re.sub(r"(\d)([a-z])", r"\1 \2", low)
    toks = re.findall(r"[a-z]+|\d+(?:\.\d+)?|\S", low)
    where = f"the second column's header {head!r}"

    def unknown(word):
        shown = _as_written(word, head)
        raise ParameterError(f"{where}: {shown!r} is not a word of a hazard header; "
                             + _words_hint())

    kinds, per, bare, stated = set(), [], [], []
    percent = annual = False
    i = 0
    while i < len(toks):
        w = toks[i]
        nxt = toks[i + 1] if i + 1 < len(toks) else None
        if w in _SEPARATORS:
            pass
        elif w == "per":
            if nxt is None or nxt not in TIME_UNITS:
                unknown(nxt if nxt is not None and nxt not in _SEPARATORS else "per")
            per.append(nxt)
            i += 1
        elif w[0].isdigit():
            if nxt is None or nxt not in TIME_UNITS:
                raise ParameterError(
                    f"{where}: the number {w} must be a time with its unit ('in 50 years', "
                    f"'poe_50yr'); " + _words_hint())
            stated.append(float(w) * TIME_UNITS[nxt])
            i += 1
        elif w in TIME_UNITS and w != "a":
            bare.append(w)
        elif w == "percent":
            percent = True
        elif w in _ANNUAL_TOKENS:
            annual = True
        elif w in _RATE_TOKENS:
            kinds.add("rate")
        elif w in _PERIOD_TOKENS:
            kinds.add("period")
        elif w in _POE_TOKENS:
            kinds.add("poe")
            annual = annual or w == "ape"
        elif w not in _FILLER_TOKENS:
            unknown(w)
        i += 1
    scale = 0.01 if percent else 1.0
    if "poe" in kinds:
        if kinds - {"poe"} or per:
            raise ParameterError(f"{where} names a probability of exceedance and a "
                                 f"{'rate' if 'rate' in kinds or per else 'return period'}:"
                                 " keep one")
        if bare:
            raise ParameterError(f"{where}: a probability of exceedance has no unit of "
                                 f"time ({_as_written(bare[0], head)!r}); state the years "
                                 "it refers to as 'poe in 50 years'")
        if annual:
            stated.append(1.0)
        return "poe", scale, tuple(sorted(set(stated)))
    if stated:
        raise ParameterError(f"{where}: a time ('{stated[0]:g} years') belongs to a "
                             "probability of exceedance only; " + _words_hint())
    rate = bool(kinds & {"rate"}) or bool(per) or annual
    if rate and ("period" in kinds or bare):
        raise ParameterError(f"{where} names both a rate and a return period (in "
                             f"{_as_written((bare or ['years'])[0], head)}): keep one")
    if rate:
        units = {TIME_UNITS[u] for u in per} | ({1.0} if annual else set())
        if len(units) > 1:
            raise ParameterError(f"{where} states two units of time "
                                 f"({', '.join(sorted({*per, *(['annual'] if annual else [])}))})"
                                 ": keep one")
        return "rate", scale / (units.pop() if units else 1.0), ()
    if "period" in kinds or bare:
        units = {TIME_UNITS[u] for u in bare}
        if len(units) > 1:
            raise ParameterError(f"{where} states two units of time ({', '.join(bare)}): "
                                 "keep one")
        if percent:
            raise ParameterError(f"{where}: a return period is not a percentage (%); "
                                 + _words_hint())
        return "period", (units.pop() if units else 1.0), ()
    raise ParameterError(f"{where} does not say what it holds: " + _words_hint())


def _text(p: Path) -> str:
    """The text of hazard file ``p`` (UTF-8, a BOM allowed); a binary or UTF-16 file is
    refused naming it."""
    try:
        data = p.read_bytes()
    except OSError as e:
        raise ParameterError(f"{p.name}: cannot read it ({e.strerror or e})") from None
    if data[:2] in (b"\xff\xfe", b"\xfe\xff"):
        raise ParameterError(f"{p.name} is UTF-16 text: save it as UTF-8 (a CSV in UTF-8)")
    nul = data.find(b"\x00")
    if nul >= 0:
        raise ParameterError(f"{p.name} is not a text file (a NUL byte at offset {nul}: "
                             "binary or UTF-16): a hazard file is a CSV in UTF-8")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as e:
        raise ParameterError(f"{p.name} is not UTF-8 text (byte 0x{data[e.start]:02x} at "
                             f"offset {e.start}): save it as UTF-8") from None


def _csv_row(line: str, name: str, n: int) -> list[str]:
    try:
        return next(csv.reader([line]))
    except (csv.Error, StopIteration) as e:
        raise ParameterError(f"{name}, line {n}: not a CSV row ({e})") from None


#: IM headers that name no IM (the ``im_name`` given names it).
GENERIC_IM_NAMES = ("im", "iml", "imls", "intensity", "intensitymeasure", "level", "levels",
                    "x")


def _im_key(name: str) -> str:
    return re.sub(r"[\s_]", "", str(name)).lower()


def same_im(a: str, b: str) -> bool:
    """Whether two IM names are the same IM: case, blanks and underscores aside, and
    ``SA(1)`` the same as ``SA(1.0)``.

    Examples
    --------
    >>> from rocking.analysis.hazard import same_im
    >>> same_im("PGA", "pga"), same_im("SA(1)", "Sa(1.0)"), same_im("SA(1.0)", "PGA")
    (True, True, False)
    """
    ka, kb = _im_key(a), _im_key(b)
    if ka == kb:
        return True
    ma, mb = (re.fullmatch(r"sa\(([0-9.]+)s?\)", k) for k in (ka, kb))
    try:
        return bool(ma and mb and float(ma.group(1)) == float(mb.group(1)))
    except ValueError:
        return False


def probability_in(t_years, annual_frequency):
    """Probability of at least one event in ``t_years`` for a Poisson process of annual
    rate ``annual_frequency``: ``1 - exp(-lambda t)``.

    Examples
    --------
    >>> from rocking.analysis import probability_in
    >>> import math
    >>> round(probability_in(50, 1e-3), 6), round(1 - math.exp(-0.05), 6)
    (0.048771, 0.048771)
    >>> round(probability_in(50, 1 / 475), 3)  # EN 1998-1: 10 % in 50 years
    0.1
    """
    t = np.asarray(t_years, dtype=float)
    lam = np.asarray(annual_frequency, dtype=float)
    if np.any(~np.isfinite(t)) or np.any(t < 0):
        raise ParameterError(f"t_years must be finite and >= 0, got {t_years!r}")
    if np.any(~np.isfinite(lam)) or np.any(lam < 0):
        raise ParameterError(f"annual_frequency must be finite and >= 0, got "
                             f"{annual_frequency!r}")
    p = -np.expm1(-lam * t)
    return float(p) if p.ndim == 0 else p


def _is_float(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


_KEYS_FIRST = re.compile(r"(path|site|im_name|unit|investigation_time|max_distance_km|"
                         r"label)\b")


def _in_file(msg: str, name: str) -> str:
    """``msg`` naming the file ``name``: as it is if it does, else ``name: msg`` (or
    ``msg (name)`` where it starts with an argument's name)."""
    if name in msg:
        return msg
    return f"{msg} ({name})" if _KEYS_FIRST.match(msg) else f"{name}: {msg}"


class HazardCurve:
    """Annual rate of exceeding an IM: ``rate[i]`` is the rate of ``IM > im[i]``.

    ``im`` > 0 strictly increasing in ``unit``; ``rate`` > 0 and non-increasing (not
    constant). Interpolated log-log between points; beyond its ends (:meth:`rate_at`,
    :func:`risk`) extended as a power law with the slope of the first two points (below)
    and of the last two (above), :attr:`tail_slopes`.
    ``approximate`` flags a curve that is not a hazard model's output (a code value).

    Examples
    --------
    The EN 1998-1 approximation passes through (0.25 g, 1/475) with slope k = 3:

    >>> from rocking.analysis import HazardCurve
    >>> curve = HazardCurve.from_code_value(0.25)  # PGA 0.25 g at 475 years
    >>> round(curve.rate_at(0.25) * 475, 6), round(curve.im_at_return_period(475), 6)
    (1.0, 0.25)
    >>> round(curve.rate_at(0.5) / curve.rate_at(0.25), 6)  # 2^-3
    0.125
    >>> curve.to_unit("m/s^2")
    HazardCurve('EN 1998-1 power law: ...', PGA in m/s^2, 30 points 0.2452..24.52, approximate)
    """

    def __init__(self, im, rate, *, im_name: str, unit: str, label: str = "",
                 approximate: bool = False):
        x = np.atleast_1d(np.asarray(im, dtype=float)).ravel()
        lam = np.atleast_1d(np.asarray(rate, dtype=float)).ravel()
        if x.size < 2:
            raise ParameterError(f"im must have at least 2 points, got {x.size}")
        if lam.size != x.size:
            raise ParameterError(f"im and rate must have the same length, got {x.size} "
                                 f"and {lam.size}")
        if not np.all(np.isfinite(x)) or np.any(x <= 0):
            raise ParameterError("im must be finite and > 0 (log-log interpolation)")
        if not np.all(np.diff(x) > 0):
            raise ParameterError("im must be strictly increasing")
        if not np.all(np.isfinite(lam)) or np.any(lam <= 0):
            raise ParameterError("rate must be finite and > 0 (annual rates of exceedance)")
        if np.any(np.diff(lam) > 0) or lam[0] == lam[-1]:
            raise ParameterError("rate must be non-increasing with im (a rate of "
                                 "exceedance) and not constant")
        if not isinstance(im_name, str) or not im_name.strip():
            raise ParameterError(f"im_name must be a non-empty string such as 'PGA', got "
                                 f"{im_name!r}")
        if not isinstance(unit, str) or _unit_factor(unit.strip()) is None:
            raise ParameterError(f"unit must be one of {sorted(IM_UNITS)}, got {unit!r}")
        self.im, self.rate = x, lam
        self.im_name, self.unit = im_name.strip(), unit.strip()
        self.approximate = bool(approximate)
        lab = str(label)
        if self.approximate and "approximat" not in lab.lower():
            lab = (lab + " " if lab else "") + "(approximation)"
        self.label = lab
        self.fractiles: dict = {}
        """The hazard's fractile curves ``{q: HazardCurve}`` (:meth:`with_fractiles`),
        used by :func:`risk` for the interval of the annual frequency; empty: none."""

    def with_fractiles(self, fractiles) -> HazardCurve:
        """This curve with the hazard model's fractile curves ``{q: HazardCurve}`` (q in
        (0, 1), at least two; e.g. OpenQuake's ``quantile-0.05`` and ``quantile-0.95``
        exports read with :meth:`from_openquake`), of the same IM and a unit of the same
        kind (converted to this curve's). :func:`risk` then propagates them into the
        interval of the annual frequency (:func:`risk_interval`).

        Examples
        --------
        >>> from rocking.analysis import HazardCurve
        >>> mean = HazardCurve.from_code_value(0.25)
        >>> lo, hi = HazardCurve.from_code_value(0.18), HazardCurve.from_code_value(0.33)
        >>> c = mean.with_fractiles({0.05: lo, 0.95: hi})
        >>> sorted(c.fractiles), c.fractiles[0.95].unit
        ([0.05, 0.95], 'g')
        """
        if not isinstance(fractiles, dict) or len(fractiles) < 2:
            raise ParameterError("fractiles must be a dict {q: HazardCurve} of at least two "
                                 f"fractiles (q in (0, 1)), got {fractiles!r}")
        out = {}
        for q, c in fractiles.items():
            try:
                qv = float(q)
            except (TypeError, ValueError):
                qv = math.nan
            if not 0.0 < qv < 1.0:
                raise ParameterError(f"fractiles: a fractile q must be in (0, 1) (0.05, not "
                                     f"5), got {q!r}")
            if not isinstance(c, HazardCurve):
                raise ParameterError(f"fractiles: the curve of q = {qv:g} must be a "
                                     f"HazardCurve, got {type(c).__name__}")
            if not same_im(c.im_name, self.im_name):
                raise ParameterError(f"fractiles: the curve of q = {qv:g} is of "
                                     f"{c.im_name}, this curve of {self.im_name}: the same "
                                     "IM is needed")
            out[qv] = c.to_unit(self.unit)
        new = HazardCurve(self.im, self.rate, im_name=self.im_name, unit=self.unit,
                          label=self.label, approximate=self.approximate)
        new.fractiles = dict(sorted(out.items()))
        return new

    def __repr__(self) -> str:
        approx = ", approximate" if self.approximate else ""
        return (f"HazardCurve({self.label!r}, {self.im_name} in {self.unit}, "
                f"{self.im.size} points {self.im[0]:.4g}..{self.im[-1]:.4g}{approx})")

    @property
    def return_periods(self) -> np.ndarray:
        """Return period ``1 / rate`` of each point (years)."""
        return 1.0 / self.rate

    @property
    def tail_slopes(self) -> tuple[float, float]:
        """Log-log slopes ``k = -d ln(rate) / d ln(im)`` of the power-law extensions
        below the first and above the last point."""
        u, ll = np.log(self.im), np.log(self.rate)
        return float(-(ll[1] - ll[0]) / (u[1] - u[0])), \
            float(-(ll[-1] - ll[-2]) / (u[-1] - u[-2]))

    def _log_rate(self, u):
        """ln(rate) at ln(im) ``u``, log-log interpolated, power-law extended."""
        lu, ll = np.log(self.im), np.log(self.rate)
        k0, k1 = self.tail_slopes
        u = np.asarray(u, dtype=float)
        out = np.interp(u, lu, ll)
        out = np.where(u < lu[0], ll[0] - k0 * (u - lu[0]), out)
        return np.where(u > lu[-1], ll[-1] - k1 * (u - lu[-1]), out)

    def rate_at(self, x):
        """Annual rate of exceeding ``x`` (in the curve's unit); power law beyond the
        curve's ends.

        Examples
        --------
        >>> from rocking.analysis import HazardCurve
        >>> curve = HazardCurve.from_code_value(0.25)  # (1/475) (a / 0.25 g)^-3
        >>> float(curve.im[-1])  # the last point (g); beyond it the power law goes on
        2.5
        >>> np.round(curve.rate_at([0.25, 5.0]) * 475, 9).tolist()  # 1 and (5 / 0.25)^-3
        [1.0, 0.000125]
        """
        xa = np.asarray(x, dtype=float)
        if np.any(~np.isfinite(xa)) or np.any(xa <= 0):
            raise ParameterError(f"x must be finite and > 0, got {x!r}")
        r = np.exp(self._log_rate(np.log(xa)))
        return float(r) if r.ndim == 0 else r

    def im_at_return_period(self, T):
        """The IM exceeded once in ``T`` years on average (rate ``1/T``), log-log
        interpolated; power law beyond the curve's ends (flat parts are refused).

        Examples
        --------
        >>> from rocking.analysis import HazardCurve
        >>> curve = HazardCurve.from_code_value(0.25)  # (1/475) (a / 0.25 g)^-3
        >>> a = curve.im_at_return_period([475, 2475])  # 0.25 (2475 / 475)^(1/3) g
        >>> np.round(a, 4).tolist(), round(0.25 * (2475 / 475) ** (1 / 3), 4)
        ([0.25, 0.4334], 0.4334)
        >>> round(curve.rate_at(a[1]) * 2475, 6)  # the inverse of rate_at
        1.0
        """
        Ta = np.asarray(T, dtype=float)
        if np.any(~np.isfinite(Ta)) or np.any(Ta <= 0):
            raise ParameterError(f"T must be a return period > 0 (years), got {T!r}")
        target = -np.log(Ta)
        lu, ll = np.log(self.im), np.log(self.rate)
        k0, k1 = self.tail_slopes
        # ll is non-increasing: interpolate on the reversed arrays, keeping strict drops
        keep = np.r_[True, np.diff(ll) < 0]
        out = np.interp(-target, -ll[keep], lu[keep])
        with np.errstate(divide="ignore", invalid="ignore"):
            lo = lu[0] - (target - ll[0]) / k0
            hi = lu[-1] - (target - ll[-1]) / k1
        out = np.where(target > ll[0], lo, out)
        out = np.where(target < ll[-1], hi, out)
        if np.any(~np.isfinite(out)):
            raise ParameterError(f"T={T!r} is beyond a flat end of the hazard curve")
        r = np.exp(out)
        return float(r) if r.ndim == 0 else r

    def to_unit(self, unit: str) -> HazardCurve:
        """The same curve with its IM in ``unit`` (same kind of quantity).

        Examples
        --------
        >>> from rocking.analysis import HazardCurve
        >>> curve = HazardCurve.from_code_value(0.25)  # (1/475) (a / 0.25 g)^-3
        >>> si = curve.to_unit("m/s^2")
        >>> si.unit, round(si.im_at_return_period(475), 4), round(0.25 * 9.80665, 4)
        ('m/s^2', 2.4517, 2.4517)
        >>> bool(np.allclose(si.rate, curve.rate))  # the same rates, the IM rescaled
        True
        """
        a, b = _unit_factor(self.unit), _unit_factor(str(unit).strip())
        if b is None or a[0] != b[0]:
            raise ParameterError(f"unit must be a {a[0]} unit like {self.unit!r}, got "
                                 f"{unit!r}")
        out = HazardCurve(self.im * a[1] / b[1], self.rate, im_name=self.im_name,
                          unit=str(unit).strip(), label=self.label,
                          approximate=self.approximate)
        out.fractiles = {q: c.to_unit(unit) for q, c in self.fractiles.items()}
        return out

    # ------------------------------------------------------------------ constructors

    @classmethod
    def from_code_value(cls, pga_475, k: float = 3.0, *, unit: str = "g",
                        im_name: str = "PGA", pga_2475=None, points: int = 30,
                        label: str = ""):
        """EN 1998-1 2.1(4) note: ``lambda(a) = (1/475) (a / a_475)^-k``, k of the order of
        3; with ``pga_2475`` the slope is that of the two return periods,
        ``k = ln(2475/475) / ln(a_2475 / a_475)``. Flagged ``approximate``. ``pga_475``
        and ``pga_2475``: a bare number in ``unit`` (default g) or a string with its unit
        (``"0.25g"``, ``"2.45m/s^2"``), as in a campaign spec (:func:`code_pga`; above
        2 g a :class:`~rocking.errors.UnitSlipWarning`).

        Examples
        --------
        >>> import math
        >>> from rocking.analysis import HazardCurve
        >>> curve = HazardCurve.from_code_value(0.25, pga_2475=0.45)  # PGA in g
        >>> round(curve.tail_slopes[0], 4), round(math.log(2475 / 475) / math.log(0.45 / 0.25), 4)
        (2.8083, 2.8083)
        >>> round(curve.im_at_return_period(2475), 6), curve.approximate
        (0.45, True)
        >>> round(HazardCurve.from_code_value("0.25g").im_at_return_period(475), 9)  # a unit
        0.25
        """
        a = code_pga("pga_475", pga_475, unit)
        if pga_2475 is not None:
            a2 = code_pga("pga_2475", pga_2475, unit)
            if a2 <= a:
                raise ParameterError(f"pga_2475 must exceed pga_475 ({a}), got {pga_2475!r}")
            k = math.log(2475.0 / 475.0) / math.log(a2 / a)
        k = _positive("k", k)
        x = a * np.logspace(-1.0, 1.0, int(points))
        lab = label or (f"EN 1998-1 power law: {im_name} {a:g} {unit} at 475 years, "
                        f"k={k:.3g} (approximation)")
        return cls(x, (x / a) ** -k / 475.0, im_name=im_name, unit=unit, label=lab,
                   approximate=True)

    @classmethod
    def from_csv(cls, path, *, im_name: str | None = None, unit: str | None = None,
                 label: str = "", investigation_time=None):
        """A CSV with two columns: the IM and, by the second header
        (:func:`column_meaning`), the annual rate of exceedance (``rate``, ``annual rate``,
        ``lambda``, ``AFE``, ``MAFE``, ``frequency``, ``1/yr``, ``per year``) or the return
        period (``return period``, ``T_R``, ``Tr``, ``RP``, ``T``, ``years``), in the unit
        it states: ``return period (months)``, ``T_R (days)``, ``rate (1/month)``,
        ``rate per day``, ``exceedance rate (%/yr)`` (a month is 1/12 year, a day
        1/365.25 year); any other word is refused, naming it. A probability of exceedance
        (``poe``, ``probability``, ``probability of exceedance in 50 years``, ``poe (%)``)
        is read only with ``investigation_time`` T (years), which must agree with the time
        the header states: ``rate = -ln(1 - poe) / T`` (Poisson, as for OpenQuake). The IM
        and its unit are taken from the first header (``pga_g``, ``PGA (g)``,
        ``SA(1.0) [m/s^2]``) unless given as ``im_name`` and ``unit``, which must then
        agree with it (an ``im_name`` names a header such as ``IM (g)``). Lines starting
        with ``#`` and blank lines are skipped; a row of another length than the header,
        or a value that is not a finite number, is refused with its line number; the file
        must be UTF-8 text.

        Examples
        --------
        >>> from rocking.analysis import HazardCurve
        >>> with open("hazard.csv", "w") as f:
        ...     _ = f.write("PGA (g),return period (years)\\n0.1,100\\n0.2,1000\\n0.4,10000\\n")
        >>> curve = HazardCurve.from_csv("hazard.csv")
        >>> curve
        HazardCurve('hazard.csv', PGA in g, 3 points 0.1..0.4)
        >>> curve.rate.tolist(), round(curve.im_at_return_period(1000), 6)  # rate = 1 / T
        ([0.01, 0.001, 0.0001], 0.2)
        >>> with open("months.csv", "w") as f:  # the same curve, return periods in months
        ...     _ = f.write("PGA (g),return period (months)\\n0.1,1200\\n0.2,12000\\n0.4,120000\\n")
        >>> HazardCurve.from_csv("months.csv").rate.tolist()
        [0.01, 0.001, 0.0001]
        """
        p = Path(path)
        if not p.is_file():
            raise ParameterError(f"path: no such hazard-curve file {str(path)!r}")
        try:
            return cls._from_csv(p, im_name, unit, label, investigation_time)
        except ParameterError as e:
            raise ParameterError(_in_file(str(e), p.name)) from None

    @classmethod
    def _from_csv(cls, p: Path, im_name, unit, label, investigation_time):
        rows = [(n, _csv_row(line, p.name, n))
                for n, line in enumerate(_text(p).splitlines(), 1)
                if line.strip() and not line.lstrip().startswith("#")]
        if len(rows) < 3 or len(rows[0][1]) < 2:
            raise ParameterError(f"{p.name}: a header and at least 2 rows of two columns "
                                 "(IM, annual rate or return period) are needed")
        header = rows[0][1]
        h_im, h_y = header[0].strip(), header[1].strip()
        m = re.match(r"^\s*([A-Za-z][\w.]*?(?:\(\s*[0-9.]+\s*s?\s*\))?)\s*(?:[\[(]\s*"
                     r"([^\])]+?)\s*[\])]|_(g|mps2|m/s\^?2|cm/s\^?2|gal))?\s*$", h_im)
        head_name = m.group(1) if m else None
        if im_name is not None:
            if not isinstance(im_name, str) or not im_name.strip():
                raise ParameterError(f"im_name must be a non-empty string such as 'PGA', "
                                     f"got {im_name!r}")
            if head_name and _im_key(head_name) not in GENERIC_IM_NAMES \
                    and not same_im(head_name, im_name):
                raise ParameterError(
                    f"im_name: the IM asked for is {im_name!r} and {p.name}'s header "
                    f"{h_im!r} is of {head_name}: they must be the same IM (a curve of "
                    "one IM is not a curve of another)")
        name = im_name or head_name or h_im or "IM"
        head_unit = (m.group(2) or m.group(3)) if m else None
        if unit is None and head_unit is None:
            raise ParameterError(f"unit: {p.name}'s IM header {h_im!r} states no unit; "
                                 f"give unit='g' or write it as '{head_name or 'PGA'} (g)'")
        if head_unit is not None and _unit_factor(head_unit.strip()) is None:
            raise ParameterError(f"unit: {p.name}'s IM header {h_im!r} states the unit "
                                 f"{head_unit!r}, not one of {sorted(IM_UNITS)}")
        u = (unit or head_unit).strip()
        if unit and head_unit and _unit_factor(head_unit) != _unit_factor(unit):
            raise ParameterError(f"unit={unit!r} contradicts the header {h_im!r}")
        kind, factor, stated = column_meaning(h_y)
        if kind == "poe" and investigation_time is None:
            hint = (f"{stated[0]:g} (the years it refers to)" if len(stated) == 1
                    else "T (the years it refers to, e.g. 50)")
            raise ParameterError(
                f"investigation_time: {p.name}'s column {h_y!r} is a probability of "
                f"exceedance, not an annual rate: give investigation_time={hint} to "
                "convert it by rate = -ln(1 - poe)/T, or convert it and head the column "
                "'annual rate'")
        if kind != "poe" and investigation_time is not None:
            raise ParameterError(f"investigation_time applies to a probability-of-"
                                 f"exceedance column only; {p.name}'s {h_y!r} is a {kind}")
        width = len(header)
        data, lines = [], []
        for n, r in rows[1:]:
            if len(r) != width:
                raise ParameterError(
                    f"{p.name}, line {n}: {len(r)} values where the header has {width} "
                    f"({', '.join(repr(h.strip()) for h in header)}): a value missing or "
                    "one too many")
            try:
                xy = [float(r[0]), float(r[1])]
            except ValueError:
                bad = next(c for c in r[:2] if not _is_float(c))
                raise ParameterError(f"{p.name}, line {n}: {bad.strip()!r} is not a number "
                                     "(every row holds the IM and its value)") from None
            if not all(math.isfinite(v) for v in xy):
                raise ParameterError(f"{p.name}, line {n}: values must be finite numbers, "
                                     f"got {', '.join(c.strip() for c in r[:2])}")
            data.append(xy)
            lines.append(n)
        data = np.array(data)
        v = data[:, 1] * factor
        if kind == "period":
            if np.any(~(v > 0)):
                n = lines[int(np.flatnonzero(~(v > 0))[0])]
                raise ParameterError(f"{p.name}, line {n}: return periods must be > 0")
            y = 1.0 / v
        elif kind == "poe":
            T = _positive("investigation_time", investigation_time)
            if stated and not any(math.isclose(T, s, rel_tol=1e-9) for s in stated):
                raise ParameterError(f"investigation_time={T:g} contradicts {p.name}'s "
                                     f"header {h_y!r} ({', '.join(f'{s:g}' for s in stated)}"
                                     " years)")
            if np.any(~((v > 0) & (v < 1))):
                bad = data[~((v > 0) & (v < 1)), 0]
                raise ParameterError(f"{p.name}: a probability of exceedance must be in "
                                     f"(0, 1) (0 and 1 carry no finite non-zero rate); "
                                     f"not so at IM {', '.join(f'{x:g}' for x in bad)}")
            y = -np.log1p(-v) / T
        else:
            y = v
        return cls(data[:, 0], y, im_name=name, unit=u, label=label or p.name)

    @classmethod
    def from_openquake(cls, path, site=0, *, label: str = "",
                       max_distance_km: float = MAX_SITE_DISTANCE_KM, fractiles=()):
        """An OpenQuake engine hazard-curve export (``hazard_curve-<kind>-<IMT>_<id>.csv``):
        a first comment line of ``key=value`` metadata (``investigation_time``, ``imt``),
        then the header ``lon,lat,depth,poe-<level>,...`` and one row per site.
        ``poe`` in ``investigation_time`` T becomes ``rate = -ln(1 - poe) / T``; a poe that
        rises with the level is refused; levels with poe 1 or 0 (no finite non-zero rate)
        are dropped and listed in ``metadata["dropped_levels"]``.
        ``site``: a row index, or ``(lon, lat)`` in degrees (lon in [-180, 360), lat in
        [-90, 90]) for the nearest site on a sphere of radius 6371.0 km (haversine); its
        distance is ``metadata["site_distance_km"]`` and a nearest site farther than
        ``max_distance_km`` is refused. PGA and SA(T) levels are in g.

        Examples
        --------
        The ILLUSTRATIVE example file shipped with the report (made-up power laws in the
        engine's layout): site (0.1, 0) is ``1e-3 (PGA / 0.05 g)^-2.5``.

        >>> from importlib.resources import files
        >>> from rocking.analysis import HazardCurve
        >>> path = files("rocking.report") / "data" / "hazard_curve-mean-PGA_illustrative.csv"
        >>> curve = HazardCurve.from_openquake(path, site=(0.1, 0.0))  # the nearest site
        >>> curve.im_name, curve.unit, curve.metadata["site_index"]
        ('PGA', 'g', 1)
        >>> round(curve.rate_at(0.05), 8), np.round(curve.tail_slopes, 6).tolist()
        (0.001, [2.5, 2.5])

        ``fractiles``: the model's fractile exports of the same calculation
        (``hazard_curve-quantile-0.05-PGA_<id>.csv``, ...), read at the same site; each
        one's fractile from its metadata ``kind='quantile-0.05'`` (or its name). They go
        to :meth:`with_fractiles`, and :func:`risk` gives the interval they imply.
        """
        p = Path(path)
        if not p.is_file():
            raise ParameterError(f"path: no such OpenQuake file {str(path)!r}")
        try:
            curve = cls._from_openquake(p, site, label, max_distance_km)
        except ParameterError as e:
            raise ParameterError(_in_file(str(e), p.name)) from None
        if isinstance(fractiles, str | Path):
            fractiles = [fractiles]
        if not fractiles:
            return curve
        fr = {}
        for f in fractiles:
            c = cls.from_openquake(f, site, max_distance_km=max_distance_km)
            text = str(c.metadata.get("kind", "")) + " " + Path(f).name
            m = re.search(r"quantile-([0-9.]+)", text)
            if m is None:
                raise ParameterError(f"fractiles: {Path(f).name} is not a quantile export "
                                     "(its kind must be 'quantile-<q>', e.g. "
                                     "'quantile-0.05')")
            if not same_im(c.im_name, curve.im_name):
                raise ParameterError(f"fractiles: {Path(f).name} is of {c.im_name}, "
                                     f"{p.name} of {curve.im_name}")
            fr[float(m.group(1).rstrip("."))] = c
        out = curve.with_fractiles(fr)
        out.metadata = curve.metadata
        return out

    @classmethod
    def _from_openquake(cls, p: Path, site, label, max_distance_km):
        lines = _text(p).splitlines()
        if not lines or not lines[0].lstrip().startswith("#"):
            raise ParameterError(f"{p.name}: not an OpenQuake hazard-curve export (no "
                                 "first comment line of metadata)")
        pair = re.compile(r"(\w+)\s*=\s*(?:'([^']*)'|([^,'\"]*))")
        first = lines[0].lstrip().removeprefix("#")
        meta = {m.group(1): (m.group(2) if m.group(2) is not None else m.group(3)).strip()
                for m in pair.finditer(first)}
        rest = re.sub(r"[\s,\"]", "", pair.sub("", first))
        if rest:
            raise ParameterError(f"{p.name}, line 1: the metadata line holds {rest[:40]!r} "
                                 "outside its key=value pairs")
        try:
            T = float(meta["investigation_time"])
        except (KeyError, ValueError):
            raise ParameterError(f"{p.name}: the metadata line states no "
                                 "investigation_time") from None
        if not (math.isfinite(T) and T > 0):
            raise ParameterError(f"{p.name}: the metadata line's investigation_time must be "
                                 f"a finite number of years > 0, got "
                                 f"{meta['investigation_time']!r}")
        imt = meta.get("imt", "").strip()
        if not imt:
            mt = re.search(r"hazard_curve-[^-]+-(.+?)_\d+\.csv$", p.name)
            imt = mt.group(1) if mt else ""
        if not re.fullmatch(r"PGA|SA\([0-9.]+\)", imt):
            raise ParameterError(f"{p.name}: IMT {imt!r} is not PGA or SA(T) (in g)")
        rows = [(n, _csv_row(line, p.name, n)) for n, line in enumerate(lines[1:], 2)
                if line.strip()]
        if not rows:
            raise ParameterError(f"{p.name}: no header line after the metadata line")
        header = [h.strip() for h in rows[0][1]]
        if "lon" not in header or "lat" not in header:
            raise ParameterError(f"{p.name}: header must hold lon,lat (and poe-<level> "
                                 f"columns), got {header[:4]}")
        ilon, ilat = header.index("lon"), header.index("lat")
        cols = [i for i, h in enumerate(header) if h.startswith("poe-")]
        odd = [h for h in header if h not in ("lon", "lat", "depth") and not
               h.startswith("poe-")]
        if odd or len(set(header) & {"lon", "lat", "depth"}) != \
                sum(h in ("lon", "lat", "depth") for h in header):
            raise ParameterError(f"{p.name}, line {rows[0][0]}: the header holds lon, lat, "
                                 f"depth (once each) and poe-<level> columns only, got "
                                 f"{odd[0] if odd else 'a repeated lon, lat or depth'!r}")
        if not cols:
            raise ParameterError(f"{p.name}: no poe-<level> columns")
        for n, r in rows[1:]:
            if len(r) != len(header):
                raise ParameterError(
                    f"{p.name}, line {n}: {len(r)} values where the header has "
                    f"{len(header)} (lon, lat, depth and {len(cols)} poe-<level>): a value "
                    "missing or one too many would shift every later level")
        data = [r for _, r in rows[1:]]
        try:
            levels = np.array([float(header[i][4:]) for i in cols])
        except ValueError:
            raise ParameterError(f"{p.name}: the poe-<level> headers must hold numbers, "
                                 f"got {[header[i] for i in cols]}") from None
        if not (np.all(np.isfinite(levels)) and np.all(levels > 0)):
            raise ParameterError(f"{p.name}: the poe-<level> levels must be finite and "
                                 f"> 0 (g), got {[header[i] for i in cols]}")
        if np.unique(levels).size != levels.size:
            raise ParameterError(f"{p.name}: a poe-<level> column is repeated "
                                 f"({[header[i] for i in cols]})")
        for n, r in rows[1:]:
            bad = next((c for c in r if not _is_float(c)), None)
            if bad is not None:
                raise ParameterError(f"{p.name}, line {n}: {bad.strip()!r} is not a number "
                                     "(lon, lat, depth and every poe-<level> hold numbers)")
            lo, la = float(r[ilon]), float(r[ilat])
            if not (math.isfinite(lo) and -180 <= lo < 360 and math.isfinite(la)
                    and -90 <= la <= 90):
                raise ParameterError(f"{p.name}, line {n}: lon {r[ilon].strip()}, lat "
                                     f"{r[ilat].strip()} is not a site (lon in [-180, 360), "
                                     "lat in [-90, 90] degrees)")
        if not data:
            raise ParameterError(f"{p.name}: no site rows")
        dist = None
        if isinstance(site, (tuple, list, np.ndarray)):
            lon0, lat0 = _lon_lat(site)
            dmax = _positive("max_distance_km", max_distance_km)
            lon = np.array([float(r[ilon]) for r in data])
            lat = np.array([float(r[ilat]) for r in data])
            d_km = great_circle_km(lon0, lat0, lon, lat)
            idx = int(np.argmin(d_km))
            dist = float(d_km[idx])
            if dist > dmax:
                swapped = ""
                if -90 <= lon0 <= 90 and -180 <= lat0 < 360:
                    ds = great_circle_km(lat0, lon0, lon, lat)
                    if ds.min() <= dmax:
                        swapped = (f"; (lon {lat0:g}, lat {lon0:g}) is {ds.min():.3g} km from site "
                                   f"{int(np.argmin(ds))}: lon and lat swapped?")
                raise ParameterError(
                    f"site: the nearest site of {p.name} to (lon {lon0:g}, lat {lat0:g}) is "
                    f"site {idx} at ({data[idx][ilon].strip()}, {data[idx][ilat].strip()}), "
                    f"{dist:.4g} km away, beyond max_distance_km={dmax:g}{swapped}; give the "
                    f"site by its index (site={idx}) or a larger max_distance_km if it is "
                    "meant")
        else:
            if isinstance(site, bool) or not isinstance(site, (int, np.integer)) \
                    or not 0 <= site < len(data):
                raise ParameterError(f"site must be an index 0..{len(data) - 1} or "
                                     f"(lon, lat), got {site!r}")
            idx = int(site)
        row = data[idx]
        poe = np.array([float(row[i]) for i in cols])
        if np.any(~np.isfinite(poe)) or np.any(poe < 0) or np.any(poe > 1):
            bad = next(row[i].strip() for i, v in zip(cols, poe, strict=True)
                       if not 0 <= v <= 1)
            raise ParameterError(f"{p.name}, line {rows[idx + 1][0]}: poe must be in [0, 1], "
                                 f"got {bad}")
        order = np.argsort(levels, kind="stable")
        lv, pv = levels[order], poe[order]
        rise = np.flatnonzero(np.diff(pv) > 0)
        if rise.size:
            i = int(rise[0])
            raise ParameterError(
                f"{p.name}: site {idx}'s poe rises with the level (a probability of "
                f"exceedance cannot): {pv[i]:g} at poe-{lv[i]:g} then {pv[i + 1]:g} at "
                f"poe-{lv[i + 1]:g}" + (f" ({rise.size} rises)" if rise.size > 1 else ""))
        # poe = 1 (infinite rate) and poe = 0 levels carry no rate: dropped and recorded
        keep = (poe > 0) & (poe < 1)
        rate = np.full(poe.shape, np.nan)
        rate[keep] = -np.log1p(-poe[keep]) / T
        if keep.sum() < 2:
            raise ParameterError(f"{p.name}: site {idx} has fewer than 2 non-zero poe")
        where = "" if dist is None else f", {dist:.3g} km from the site asked"
        lab = label or (f"OpenQuake {imt} at ({row[ilon].strip()}, {row[ilat].strip()})"
                        f"{where}, {meta.get('kind', p.name)}")
        curve = cls(levels[keep], rate[keep], im_name=imt, unit="g", label=lab)
        curve.metadata = {**meta, "site_index": idx, "lon": float(row[ilon]),
                          "lat": float(row[ilat]), "site_distance_km": dist,
                          "dropped_levels": [float(v) for v in levels[~keep]],
                          "dropped_poe": [float(v) for v in poe[~keep]]}
        return curve


# --------------------------------------------------------------------------- risk

#: Default level of the interval of :func:`risk`: the central 90 % (the 5 % and 95 %
#: percentiles), the fractiles an OpenQuake hazard model usually exports.
INTERVAL_LEVEL = 0.90


@dataclass(frozen=True)
class Risk:
    """The risk of one fragility under one hazard curve (:func:`risk`).

    ``annual_frequency`` is the point estimate (the fit's curve on the hazard curve);
    ``annual_frequency_interval`` the central ``interval_level`` interval (default 90 %:
    the 5th and 95th percentiles) of the annual frequency propagated from the fit's
    bootstrap and the hazard's fractile curves (``interval_source`` says which, NaN when
    neither is there); ``probability_interval`` the same interval of the probability in
    ``t_years`` (``1 - exp(-lambda t)`` is increasing in lambda).

    Examples
    --------
    >>> from rocking.analysis import Risk
    >>> r = Risk(annual_frequency=1e-3, tail_share=0.0, probability_50=0.0488)
    >>> round(r.probability_in(100), 4)  # 1 - exp(-0.1)
    0.0952
    >>> r.annual_frequency_interval  # no bootstrap, no fractiles: no interval
    (nan, nan)
    """

    annual_frequency: float
    tail_share: float
    probability_50: float
    label: str = ""
    annual_frequency_interval: tuple = (math.nan, math.nan)
    probability_interval: tuple = (math.nan, math.nan)
    interval_level: float = math.nan
    interval_source: str = ""
    t_years: float = 50.0

    def probability_interval_in(self, t_years) -> tuple[float, float]:
        """The interval of the probability in ``t_years``: :func:`probability_in` of the
        ends of :attr:`annual_frequency_interval` (NaN without one).

        Examples
        --------
        >>> from rocking.analysis import Risk
        >>> r = Risk(1e-3, 0.0, 0.0488, annual_frequency_interval=(5e-4, 2e-3))
        >>> [round(p, 5) for p in r.probability_interval_in(50)]  # 1 - exp(-lambda 50)
        [0.02469, 0.09516]
        """
        lo, hi = self.annual_frequency_interval
        if not (math.isfinite(lo) and math.isfinite(hi)):
            return (math.nan, math.nan)
        return (float(probability_in(t_years, lo)), float(probability_in(t_years, hi)))

    def probability_in(self, t_years):
        """Probability in ``t_years`` (``1 - exp(-lambda t)``), :func:`probability_in` of
        this risk's ``annual_frequency``.

        Examples
        --------
        >>> from rocking.analysis import Risk, probability_in
        >>> r = Risk(annual_frequency=1 / 475, tail_share=0.0, probability_50=0.0999)
        >>> r.probability_in(50) == probability_in(50, 1 / 475)
        True
        >>> np.round(r.probability_in([50, 475]), 4).tolist()  # 1 - exp(-t / 475)
        [0.0999, 0.6321]
        """
        return probability_in(t_years, self.annual_frequency)


def _fit_factor(fit, curve: HazardCurve) -> float:
    """Factor taking the curve's IM into the fit's unit; refuses a mismatch."""
    own = getattr(fit, "im_unit", None)
    if not own:
        raise ParameterError("fit states no im_unit: fit it with im_unit= (e.g. 'm/s^2') "
                             "so that its IM can be checked against the hazard curve's "
                             f"({curve.im_name} in {curve.unit})")
    name = getattr(fit, "im_name", "im")
    if not same_im(name, curve.im_name):
        raise ParameterError(f"the fit's IM is {name!r} and the hazard curve's is "
                             f"{curve.im_name!r}: they must be the same IM (fit with "
                             f"im_name={curve.im_name.lower()!r} if it is)")
    a, b = _unit_factor(curve.unit), _unit_factor(own)
    if b is None or a[0] != b[0]:
        raise ParameterError(f"the fit's IM unit {own!r} is not a {a[0]} unit like the "
                             f"hazard curve's {curve.unit!r}")
    return a[1] / b[1]


def _log_rates(curve: HazardCurve, u, score=None):
    """ln(rate) at ln(im) ``u`` (shape (B, n)); with ``score`` (shape (B,)), of the curve
    at that normal score of the hazard's epistemic uncertainty: the fractile curves'
    ln(rate) interpolated linearly in the normal score ``Phi^-1(q)`` of their fractiles
    (extrapolated beyond the extreme ones), i.e. fractile curves that move together at
    every IM (fully correlated across the IM)."""
    from scipy.stats import norm

    if score is None:
        return curve._log_rate(u)
    qs = np.array(sorted(curve.fractiles))
    zs = norm.ppf(qs)
    ll = np.stack([curve.fractiles[q]._log_rate(u) for q in qs])  # (Q, B, n)
    j = np.clip(np.searchsorted(zs, score) - 1, 0, zs.size - 2)
    w = (score - zs[j]) / (zs[j + 1] - zs[j])
    rows = np.arange(u.shape[0])
    return (1.0 - w)[:, None] * ll[j, rows] + w[:, None] * ll[j + 1, rows]


def lognormal_risks(median, beta, curve: HazardCurve, *, factor: float = 1.0,
                    score=None, n: int = 4001) -> np.ndarray:
    """Annual frequencies of many lognormal fragilities (``median``, ``beta``: arrays, the
    median in the fit's unit, ``factor`` taking the curve's IM into it) under ``curve``
    (or, with ``score``, its fractile curves at those normal scores: :func:`_log_rates`),
    vectorised: by parts, ``lambda_f = int lambda(im) dP(im) = E[lambda(median e^(beta Z))]``
    with Z standard normal, a trapezoid rule over ``n`` points of Z from
    ``-(k beta + 10)`` to 10 (k: the curve's steepest log-log slope, at most 20, which
    moves the integrand's mass to ``Z = -k beta``). The same integral as :func:`risk`'s
    quadrature, to about 1e-6 relatively.

    Examples
    --------
    On a power law ``k0 a^-k`` the closed form is ``k0 median^-k exp(k^2 beta^2 / 2)``:

    >>> from rocking.analysis import HazardCurve
    >>> from rocking.analysis.hazard import lognormal_risks
    >>> curve = HazardCurve.from_code_value(0.25)  # (1/475) (a / 0.25)^-3, a in g
    >>> med, beta = np.array([0.5, 1.0]), np.array([0.3, 0.5])
    >>> lam = lognormal_risks(med, beta, curve)
    >>> closed = (0.25 / med) ** 3 / 475 * np.exp(9 * beta**2 / 2)
    >>> bool(np.allclose(lam, closed, rtol=1e-6))
    True
    """
    med = np.atleast_1d(np.asarray(median, dtype=float))
    beta = np.atleast_1d(np.asarray(beta, dtype=float))
    slopes = [*curve.tail_slopes, *(-np.diff(np.log(curve.rate)) / np.diff(np.log(curve.im)))]
    for c in curve.fractiles.values() if score is not None else ():
        slopes += list(c.tail_slopes)
    k = min(max(max(slopes), 0.0), 20.0)
    z_lo = -(k * beta + 10.0)
    t = np.linspace(0.0, 1.0, int(n))
    z = z_lo[:, None] + (10.0 - z_lo)[:, None] * t[None, :]
    u = np.log(med / factor)[:, None] + beta[:, None] * z
    logf = _log_rates(curve, u, score) - 0.5 * z * z - 0.5 * math.log(2.0 * math.pi)
    with np.errstate(over="ignore"):  # a degenerate bootstrap draw: an infinite rate
        return np.trapezoid(np.exp(logf), z, axis=1)


def risk_interval(fit, curve: HazardCurve, *, level: float = INTERVAL_LEVEL, seed=0,
                  factor: float | None = None):
    """The central ``level`` interval of the annual frequency of ``fit`` under ``curve``
    and where it comes from: ``(low, high, source, draws)``.

    * **The fit's bootstrap** (``fit.boot_coef``, the probit ``(b0, b1)`` of each draw;
      draws with ``b1 <= 0``, an infinite median, are left out): the annual frequency of
      each draw (:func:`lognormal_risks`), its percentiles.
    * **The hazard's fractile curves** (:meth:`HazardCurve.with_fractiles`), read as one
      normal score Z_H of the hazard model's epistemic uncertainty that moves every IM's
      rate together (each rate's fractiles at ``Phi(Z_H)``, interpolated in the score).
      Alone (a fit without bootstrap), the annual frequency is monotone in Z_H: its
      percentiles are those of the fractile curves at the interval's own fractiles, exactly.
    * **Both**: each bootstrap draw is paired with an independent Z_H (random, ``seed``),
      the percentiles of the pairs (a Monte Carlo of the two sources, independent).

    ``(nan, nan, "", empty)`` when there is neither.

    Examples
    --------
    >>> from scipy.stats import norm
    >>> from rocking.analysis import HazardCurve, fragility
    >>> from rocking.analysis.hazard import risk_interval
    >>> im = np.repeat([1.0, 2.0, 3.0, 4.0, 6.0], 40)  # PGA (m/s^2)
    >>> failed = np.tile(np.arange(40), 5) < np.round(40 * norm.cdf(np.log(im / 3) / 0.4))
    >>> fit = fragility(im, failed, n_boot=400, seed=1, im_name="pga", im_unit="m/s^2")
    >>> lo, hi, source, draws = risk_interval(fit, HazardCurve.from_code_value(0.25))
    >>> bool(lo < hi), source, draws.size
    (True, 'fit bootstrap (400 draws)', 400)
    """
    from scipy.stats import norm

    level = float(level)
    if not 0.0 < level < 1.0:
        raise ParameterError(f"level must be in (0, 1) (0.9: the 5-95 % interval), got "
                             f"{level!r}")
    c = _fit_factor(fit, curve) if factor is None else factor
    q = 0.5 * (1.0 - level)
    b = np.asarray(getattr(fit, "boot_coef", np.empty((0, 2))), dtype=float).reshape(-1, 2)
    b = b[np.isfinite(b).all(axis=1) & (b[:, 1] > 0)]
    has_f = len(curve.fractiles) >= 2
    lognormal = hasattr(fit, "median") and hasattr(fit, "beta")
    if not lognormal or (b.shape[0] < 2 and not has_f):
        return math.nan, math.nan, "", np.empty(0)
    if b.shape[0] < 2:  # the fractiles only: exact, monotone in the score
        z = norm.ppf([q, 1.0 - q])
        lam = lognormal_risks(np.full(2, fit.median), np.full(2, fit.beta), curve,
                              factor=c, score=z)
        return (float(lam[0]), float(lam[1]),
                f"hazard fractiles ({', '.join(f'{v:g}' for v in curve.fractiles)})", lam)
    med, beta = np.exp(-b[:, 0] / b[:, 1]), 1.0 / b[:, 1]
    score = None
    source = f"fit bootstrap ({med.size} draws)"
    if has_f:
        score = np.random.default_rng(seed).standard_normal(med.size)
        source += (" and hazard fractiles ("
                   f"{', '.join(f'{v:g}' for v in curve.fractiles)})")
    lam = lognormal_risks(med, beta, curve, factor=c, score=score)
    lo, hi = np.quantile(lam, [q, 1.0 - q])
    return float(lo), float(hi), source, lam


def risk(fit, curve: HazardCurve, *, t_years: float = 50.0,
         level: float = INTERVAL_LEVEL):
    """Annual frequency of the state of ``fit`` under ``curve`` over the whole IM range
    (Cornell et al. 2002), the share from the power-law tails beyond the curve's ends, and
    the probability in ``t_years`` (``Risk.probability_50`` for the default 50).

    ``lambda_f = integral_0^inf P(f | im) |d lambda / d im| d im``, computed in ``ln im``
    with ``scipy.integrate.quad``. Its uncertainty: the central ``level`` interval
    (default 0.9: 5-95 %) from the fit's bootstrap and the curve's fractile curves
    (:func:`risk_interval`), in ``Risk.annual_frequency_interval`` and
    ``Risk.probability_interval`` (NaN without either). The IM names must agree and the
    units be of the same
    kind (g and m/s^2 are converted). ``fit``: a :class:`FragilityFit` (one :class:`Risk`)
    or damage-state curves with ``fits`` (a list, one per state).

    Examples
    --------
    On a power-law hazard ``k0 a^-k`` the risk equals Cornell's closed form
    ``k0 median^-k exp(k^2 beta^2 / 2)``:

    >>> from scipy.stats import norm
    >>> from rocking.analysis import HazardCurve, fragility, risk
    >>> im = np.repeat([1.0, 2.0, 3.0, 4.0, 6.0], 100)  # PGA (m/s^2)
    >>> failed = np.tile(np.arange(100), 5) < np.round(100 * norm.cdf(np.log(im / 3) / 0.4))
    >>> fit = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
    >>> curve = HazardCurve.from_code_value(0.25)  # in g: converted to the fit's m/s^2
    >>> r = risk(fit, curve)
    >>> k0 = (0.25 * 9.80665) ** 3 / 475  # lambda(a) = k0 a^-3, a in m/s^2
    >>> closed = k0 * fit.median**-3 * np.exp(9 * fit.beta**2 / 2)
    >>> bool(np.isclose(r.annual_frequency, closed, rtol=1e-6)), round(r.probability_50, 3)
    (True, 0.109)
    """
    from scipy.integrate import quad
    from scipy.special import log_ndtr  # what scipy.stats.norm.logcdf evaluates, per call

    if not isinstance(curve, HazardCurve):
        raise ParameterError(f"curve must be a HazardCurve, got {type(curve).__name__}")
    fits = getattr(fit, "fits", None)
    if fits is not None:
        return [risk(f, curve, t_years=t_years, level=level) for f in fits]
    if not callable(getattr(fit, "probability", None)):
        raise ParameterError(f"fit must be a FragilityFit, got {type(fit).__name__}")
    t_years = _positive("t_years", t_years)
    c = _fit_factor(fit, curve)
    lu = np.log(curve.im)
    ll = np.log(curve.rate)
    slopes = -np.diff(ll) / np.diff(lu)
    k0, k1 = curve.tail_slopes

    lognormal = hasattr(fit, "median") and hasattr(fit, "beta")
    l0, l1 = float(lu[0]), float(lu[-1])

    def log_rate(u):
        # curve._log_rate for a scalar, with the same floating-point operations
        if u < l0:
            return ll[0] - k0 * (u - lu[0])
        if u > l1:
            return ll[-1] - k1 * (u - lu[-1])
        return np.interp(u, lu, ll)

    def integrand(u, k):
        # |d lambda / d ln im| = k lambda(im) on a power-law piece of slope k; in logs,
        # so that the tails (lambda -> inf, P -> 0 as im -> 0) do not overflow
        if lognormal:
            logp = float(log_ndtr((u + math.log(c) - math.log(fit.median)) / fit.beta))
        else:
            x = math.exp(u) * c
            if not 0.0 < x < math.inf:
                return 0.0
            pv = float(fit.probability(x))
            logp = math.log(pv) if pv > 0 else -math.inf
        v = logp + math.log(k) + float(log_rate(u))
        return math.exp(v) if v > -745.0 else 0.0

    opts = {"epsabs": 0.0, "epsrel": 1e-11, "limit": 200}
    inner = sum(quad(integrand, lu[i], lu[i + 1], args=(slopes[i],), **opts)[0]
                for i in range(lu.size - 1) if slopes[i] > 0)
    low = quad(integrand, -np.inf, lu[0], args=(k0,), **opts)[0] if k0 > 0 else 0.0
    high = quad(integrand, lu[-1], np.inf, args=(k1,), **opts)[0] if k1 > 0 else 0.0
    total = inner + low + high
    share = (low + high) / total if total > 0 else 0.0
    lo, hi, source, _ = risk_interval(fit, curve, level=level, factor=c,
                                      seed=getattr(fit, "seed", 0) or 0)
    pint = ((probability_in(t_years, lo), probability_in(t_years, hi)) if source
            else (math.nan, math.nan))
    return Risk(total, share, probability_in(t_years, total),
                label=getattr(fit, "label", ""), annual_frequency_interval=(lo, hi),
                probability_interval=pint, interval_level=float(level) if source
                else math.nan, interval_source=source, t_years=t_years)


def plot_risk(curve: HazardCurve, fit, ax=None):
    """Hazard curve, fragility and the risk integrand ``P(f|im) |d lambda/d ln im|`` (which
    IM levels contribute), on a common IM axis in the curve's unit. Returns the Figure.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from rocking.analysis import HazardCurve, fragility, plot_risk
    >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2)
    >>> failed = np.tile(np.arange(10), 5) < np.repeat([1, 3, 5, 7, 9], 10)
    >>> fit = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
    >>> fig = plot_risk(HazardCurve.from_code_value(0.25), fit)
    >>> type(fig).__name__, len(fig.axes)
    ('Figure', 2)
    """
    c = _fit_factor(fit, curve)
    res = risk(fit, curve)
    if ax is None:
        fig, ax = figure((10.0, 4.2))
    else:
        fig = ax.figure
    lo = min(curve.im[0], fit.median / c * math.exp(-4 * fit.beta))
    hi = max(curve.im[-1], fit.median / c * math.exp(4 * fit.beta))
    x = np.logspace(math.log10(lo), math.log10(hi), 300)
    lam = curve.rate_at(x)
    inside = (x >= curve.im[0]) & (x <= curve.im[-1])
    ax.loglog(x[inside], lam[inside], color=PALETTE[0], label=curve.label or "hazard")
    ax.loglog(x, np.where(inside, np.nan, lam), color=PALETTE[0], ls=":",
              label="power-law tails (extrapolated)")
    ax.plot(curve.im, curve.rate, "o", ms=3, color=PALETTE[0])
    if len(curve.fractiles) >= 2:
        qs = sorted(curve.fractiles)
        lo_c, hi_c = curve.fractiles[qs[0]], curve.fractiles[qs[-1]]
        ax.fill_between(x, lo_c.rate_at(x), hi_c.rate_at(x), color=PALETTE[0], alpha=0.15,
                        lw=0, label=f"hazard fractiles {qs[0]:g}-{qs[-1]:g}")
    style_axes(ax, im_label(curve.im_name, curve.unit), "annual rate of exceedance")
    ax2 = ax.twinx()
    pf = np.asarray(fit.probability(x * c), dtype=float)
    u = np.log(x)
    dlam = -np.gradient(np.log(lam), u) * lam
    dens = pf * dlam
    ax2.plot(x, pf, color=PALETTE[1], ls="--", label=f"fragility {fit.label}".strip())
    if getattr(fit, "n_boot", 0):
        b = fit.band(x * c, res.interval_level if res.interval_source else INTERVAL_LEVEL)
        ax2.fill_between(x, b["lower"], b["upper"], color=PALETTE[1], alpha=0.15, lw=0,
                         label="fragility bootstrap band")
    peak = dens.max() if dens.max() > 0 else 1.0
    ax2.fill_between(x, 0, dens / peak, color=PALETTE[2], alpha=0.3,
                     label="integrand P(f|im) |dλ/d ln im| (scaled)")
    ax2.set_ylim(0, 1.05)
    ax2.set_ylabel("probability / relative contribution")
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=7, loc="upper left", bbox_to_anchor=(1.12, 1.0),
              borderaxespad=0.0, frameon=False)
    ax.set_title(risk_text(res), fontsize=9)
    return fig


def risk_text(r: Risk) -> str:
    """One line of a :class:`Risk`: the annual frequency and the probability in its
    service life, each with its interval when it has one.

    Examples
    --------
    >>> from rocking.analysis import Risk
    >>> from rocking.analysis.hazard import risk_text
    >>> risk_text(Risk(1.3e-3, 0.0, 0.063, annual_frequency_interval=(8e-4, 5.4e-3),
    ...                probability_interval=(0.039, 0.237), interval_level=0.9,
    ...                interval_source="fit bootstrap (1000 draws)"))
    'annual frequency 0.0013/yr (90 %: 0.0008-0.0054), P(50 yr) 0.063 (0.039-0.24)'
    """
    lo, hi = r.annual_frequency_interval
    pl, ph = r.probability_interval
    has = bool(r.interval_source) and math.isfinite(lo) and math.isfinite(hi)
    a = f"annual frequency {r.annual_frequency:.3g}/yr"
    p = f"P({r.t_years:g} yr) {r.probability_50:.3g}"
    if has:
        a += f" ({100 * r.interval_level:.0f} %: {lo:.2g}-{hi:.2g})"
        p += f" ({pl:.2g}-{ph:.2g})"
    tails = f", tails {100 * r.tail_share:.0f} %" if r.tail_share >= 0.005 else ""
    return f"{a}, {p}{tails}"
