"""The site's hazard of a campaign (issue 21): the ``[hazard]`` table of a spec, the curve
kept in the store's manifest, and the IM check against the campaign's IM.

A ``[hazard]`` table gives one seismic hazard curve (:class:`rocking.analysis.HazardCurve`)
from a file (an OpenQuake engine export or a CSV of IM and annual rate or return period)
or from a code value (EN 1998-1 2.1(4) note: the reference PGA at 475 years and a slope k;
an approximation, labelled so wherever it appears). ``rocking campaign report`` then gives,
per group (model or mitigation, block, floor), the annual frequency of overturning and the
probability over ``t_years`` (:func:`rocking.analysis.risk`); for a group with runs stopped
at an isolator's clearance also of "overturned or clearance reached" (those runs are no
known survivors; :mod:`rocking.campaign.report`).

**The curve's points are kept in the manifest** (:func:`record`), with the file's sha256 and
the site chosen, not re-read from the file at report time: a report must not change
silently when a file next to the spec changes or disappears, and a store must be
reportable where the file is not (another machine). The sha256 says which file it was.

**The hazard does not enter the spec hash** (:attr:`rocking.campaign.CampaignSpec.hash`):
it changes no run, only the report. A store resumed with another ``[hazard]`` (or none)
keeps its chunks; its manifest and ``spec.toml`` take the new hazard (the run says so in
one line), and the next report uses it.
"""

from __future__ import annotations

import hashlib
import math
import re
from pathlib import Path

import numpy as np

from ..analysis.fragility import IM_UNITS
from ..analysis.hazard import MAX_SITE_DISTANCE_KM, HazardCurve
from ..errors import ParameterError
from ..units import G

FORMATS = ("auto", "openquake", "csv")
"""Formats of a hazard file: ``auto`` tells an OpenQuake export by its first line (a ``#``
comment with ``investigation_time``), else a CSV."""
DEFAULT_T_YEARS = 50.0
"""Default service life (years) of the probability ``1 - exp(-lambda t)``."""
MAX_T_YEARS = 1e4
"""Longest service life accepted (years)."""
HAZARD_KEYS = {
    "file": "a hazard-curve file, relative to the spec: an OpenQuake engine export "
            "(`hazard_curve-<kind>-<IMT>_<id>.csv`) or a CSV of IM and annual rate or "
            "return period (header `PGA (g)`, `rate` or `return period`, in years unless it "
            "says `(months)`, `(days)`, `1/month`, `%/yr`); or give pga_475",
    "format": f"{', '.join(FORMATS)} (default auto: an OpenQuake export by its first line)",
    "site": "OpenQuake: the site, a row index (default 0) or [lon, lat] (the nearest)",
    "max_distance_km": "OpenQuake, with site = [lon, lat]: refuse a nearest site farther "
                       f"than this, km, > 0; default {MAX_SITE_DISTANCE_KM:g}",
    "im": "CSV: the IM's name (e.g. \"PGA\") where the header names none (`IM (g)`); "
          "one that names another IM is refused",
    "unit": "CSV: the IM's unit if the header states none (g, m/s^2, ...)",
    "investigation_time": "CSV of a probability of exceedance (header `poe`): the years T "
                          "it refers to, > 0; read as rate = -ln(1 - poe)/T",
    "pga_475": "instead of file: the reference PGA at 475 years, a number in g (0.25) or "
               "with its unit (\"0.25g\", \"2.45m/s^2\"), EN 1998-1 2.1(4): lambda = "
               "(1/475) (a / a_475)^-k, an approximation (labelled so)",
    "k": "with pga_475: the slope of the power law, (0, 20]; default 3 (EN 1998-1 note)",
    "pga_2475": "with pga_475, instead of k: the PGA at 2475 years (sets k), in the same "
                "forms",
    "fractiles": "with an OpenQuake file: the model's fractile exports of the same "
                 "calculation (a list of files relative to the spec, "
                 "`hazard_curve-quantile-0.05-PGA_<id>.csv`, ...; at least two), read at "
                 "the same site: the risk's interval then includes the hazard's "
                 "uncertainty",
    "t_years": f"the service life of the probability 1 - exp(-lambda t), years, (0, "
               f"{MAX_T_YEARS:g}]; default {DEFAULT_T_YEARS:g}",
    "label": "the curve's name in the report (default: from the file or the code value)",
}
"""The keys of ``[hazard]``."""


def sha256(path) -> str:
    """The SHA-256 of a file's bytes."""
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def file_format(path) -> str:
    """``openquake`` if the file's first non-blank line is a ``#`` comment that states
    ``investigation_time`` (the engine's metadata line), else ``csv``."""
    try:
        with open(path, encoding="utf-8", errors="replace") as fh:
            for line in fh:
                if line.strip():
                    s = line.lstrip().lstrip("\ufeff")
                    return ("openquake" if s.startswith("#") and "investigation_time" in s
                            else "csv")
    except OSError as e:
        raise ParameterError(f"file: cannot read {path}: {e.strerror or e}") from None
    return "csv"


def parse_site(text):
    """A site as the command line gives it: ``"3"`` (a row index) or ``"LON,LAT"``."""
    parts = [t.strip() for t in str(text).split(",")]
    try:
        if len(parts) == 1:
            return int(parts[0])
        if len(parts) == 2:
            return [float(parts[0]), float(parts[1])]
    except ValueError:
        pass
    raise ParameterError(f"site must be a site index (0, 1, ...) or LON,LAT, got {text!r}")


def read_hazard(path, *, format: str = "auto", site=None, im=None, unit=None,
                label: str = "", investigation_time=None, max_distance_km=None,
                fractiles=()) -> tuple[HazardCurve, dict]:
    """The hazard curve in ``path`` and its source (file name, sha256, format, site; for
    an OpenQuake export its metadata and the ``site_distance_km`` of a site given by
    [lon, lat], refused beyond ``max_distance_km`` (default
    :data:`~rocking.analysis.hazard.MAX_SITE_DISTANCE_KM`); for a CSV of a probability of
    exceedance its ``investigation_time``, :meth:`HazardCurve.from_csv`). ``fractiles``:
    an OpenQuake export's fractile exports (paths; at least two), read at the same site
    (:meth:`HazardCurve.from_openquake`), each named in the source with its sha256 and q.
    Errors (:class:`~rocking.errors.ParameterError`) start with the argument's name:
    ``file``, ``format``, ``site``, ``im``, ``unit``, ``investigation_time``,
    ``max_distance_km``, ``fractiles``."""
    p = Path(path)
    if not p.is_file():
        raise ParameterError(f"file: no such hazard-curve file {str(path)!r}")
    if isinstance(fractiles, str | Path):
        fractiles = [fractiles]
    fractiles = [Path(f) for f in (fractiles or ())]
    for f in fractiles:
        if not f.is_file():
            raise ParameterError(f"fractiles: no such hazard-curve file {str(f)!r}")
    if len(fractiles) == 1:
        raise ParameterError(f"fractiles: give at least two fractile exports (e.g. "
                             f"quantile-0.05 and quantile-0.95), got one: {fractiles[0].name}")
    if format not in FORMATS:
        raise ParameterError(f"format must be one of {', '.join(FORMATS)}, got {format!r}")
    fmt = file_format(p) if format == "auto" else format
    src = {"file": p.name, "path": str(p.resolve()), "sha256": sha256(p), "format": fmt}
    try:
        if fmt == "openquake":
            for k, v in (("im", im), ("unit", unit)):
                if v is not None:
                    raise ParameterError(f"{k} applies to a CSV only (an OpenQuake export "
                                         "states its IMT; its PGA and SA levels are in g)")
            if investigation_time is not None:
                raise ParameterError("investigation_time applies to a CSV of a probability "
                                     "of exceedance only (an OpenQuake export states it)")
            s = 0 if site is None else site
            if isinstance(s, list):
                s = tuple(s)
            if max_distance_km is not None and not isinstance(s, tuple):
                raise ParameterError("max_distance_km applies with a site given as "
                                     "[lon, lat] only (a row index is that site)")
            dmax = MAX_SITE_DISTANCE_KM if max_distance_km is None else max_distance_km
            try:
                curve = HazardCurve.from_openquake(p, site=s, label=label,
                                                   max_distance_km=dmax,
                                                   fractiles=fractiles)
            except ParameterError as e:  # a fractile file's own error: say which key
                msg = str(e)
                if fractiles and not msg.startswith(("fractiles", "site")) and any(
                        f.name in msg for f in fractiles):
                    raise ParameterError(f"fractiles: {msg.removeprefix('path: ')}") from None
                raise
            meta = getattr(curve, "metadata", {})
            if fractiles:
                src["fractiles"] = [{"file": f.name, "sha256": sha256(f), "q": q}
                                    for f, q in zip(fractiles, _quantiles(fractiles),
                                                    strict=True)]
            src["site"] = list(s) if isinstance(s, tuple) else s
            src.update({k: meta[k] for k in ("site_index", "lon", "lat",
                                             "site_distance_km", "investigation_time",
                                             "kind", "generated_by", "dropped_levels")
                        if k in meta and meta[k] is not None})
            if isinstance(s, tuple):
                src["max_distance_km"] = float(dmax)
        else:
            if fractiles:
                raise ParameterError("fractiles applies to an OpenQuake export only (its "
                                     "quantile exports: a CSV states no fractile)")
            for k, v in (("site", site), ("max_distance_km", max_distance_km)):
                if v is not None:
                    raise ParameterError(f"{k} applies to an OpenQuake export only (a CSV "
                                         "holds one curve)")
            curve = HazardCurve.from_csv(p, im_name=im, unit=unit, label=label,
                                         investigation_time=investigation_time)
            if investigation_time is not None:
                src["investigation_time"] = float(investigation_time)
    except ParameterError as e:
        msg = str(e)
        if msg.startswith("im_name"):  # from_csv's im_name is this im
            msg = "im" + msg.removeprefix("im_name")
        if not re.match(r"(site|im|unit|format|investigation_time|max_distance_km|fractiles)\b",
                        msg):
            msg = "file: " + msg.removeprefix("path: ")
        raise ParameterError(msg) from None
    except (OSError, UnicodeDecodeError, ValueError) as e:
        raise ParameterError(f"file: cannot read {p.name} as a hazard curve "
                             f"({type(e).__name__}: {str(e).splitlines()[0][:100]})") from None
    return curve, src


def _quantiles(paths) -> list:
    """The fractile q of each OpenQuake quantile export (its ``kind`` metadata, else its
    name), as :meth:`HazardCurve.from_openquake` reads it; None where neither says."""
    out = []
    for f in paths:
        try:
            first = Path(f).read_text(encoding="utf-8", errors="replace").split("\n", 1)[0]
        except OSError:
            first = ""
        m = re.search(r"quantile-([0-9.]+)", first + " " + Path(f).name)
        out.append(float(m.group(1).rstrip(".")) if m else None)
    return out


def code_value(pga_475: float, *, k=None, pga_2475=None, label: str = ""
               ) -> tuple[HazardCurve, dict]:
    """The EN 1998-1 power law through ``pga_475`` (m/s^2) at 475 years with slope ``k``
    (default 3) or through ``pga_2475`` (m/s^2) at 2475 years, in g; flagged approximate."""
    if k is not None and pga_2475 is not None:
        raise ParameterError("k: give k or pga_2475 (which sets k), not both")
    a = pga_475 / G
    a2 = None if pga_2475 is None else pga_2475 / G
    curve = HazardCurve.from_code_value(a, 3.0 if k is None else k, unit="g", im_name="PGA",
                                        pga_2475=a2, label=label)
    slope = float(-np.log(curve.rate[-1] / curve.rate[0])
                  / np.log(curve.im[-1] / curve.im[0]))
    return curve, {"code_value": "EN 1998-1 2.1(4)", "pga_475_g": a, "k": slope,
                   **({"pga_2475_g": a2} if a2 is not None else {})}


# ------------------------------------------------------------------ the campaign's IM
def campaign_im(im_name: str | None) -> dict:
    """The IM of a campaign's report, ``{"name", "unit"}``: the spec's ``motions.im``
    (its unit from :data:`rocking.analysis.ida.IMS`), else the PGA of each run in m/s^2
    (as :mod:`rocking.campaign.report` takes it)."""
    from ..analysis.ida import IMS
    if im_name:
        return {"name": im_name, "unit": IMS[im_name][0]}
    return {"name": "pga", "unit": "m/s^2"}


def _key(name: str) -> str:
    return re.sub(r"[\s_]", "", str(name)).lower()


def unit_factor(unit: str):
    """``(kind, SI value of one unit)`` of an IM unit, None if unknown."""
    u = str(unit).strip()
    for key in (u, u.replace(" ", ""), u.replace(" ", "").lower()):
        if key in IM_UNITS:
            return IM_UNITS[key]
    return None


def mismatch(curve: HazardCurve, im: dict) -> str | None:
    """Why ``curve`` cannot be integrated with fits of the campaign's IM ``im``
    (``{"name", "unit"}``), naming both; None if it can (same IM, units of one kind)."""
    theirs = f"{curve.im_name} ({curve.unit})"
    ours = f"{im['name']} ({im['unit']})" if im.get("unit") else str(im["name"])
    a, b = unit_factor(curve.unit), unit_factor(im.get("unit") or "")
    if _key(curve.im_name) != _key(im["name"]):
        hint = (' (a PGA hazard needs motions.im = "pga", or no im: the PGA of each run)'
                if _key(curve.im_name) == "pga" else "")
        return (f"the hazard curve is of {theirs} and the campaign's IM is {ours}: they must "
                f"be the same IM{hint}")
    if a is None or b is None or a[0] != b[0]:
        return (f"the hazard curve's unit {curve.unit!r} ({theirs}) is not a unit of the "
                f"campaign's IM {ours}")
    return None


def to_im_unit(x, curve: HazardCurve, im_unit: str):
    """``x`` in the campaign's IM unit ``im_unit`` expressed in the curve's unit."""
    return np.asarray(x, dtype=float) * unit_factor(im_unit)[1] / unit_factor(curve.unit)[1]


# ------------------------------------------------------------------ the manifest's record
def record(curve: HazardCurve, source: dict, t_years: float) -> dict:
    """The manifest's ``hazard``: the curve's points (exactly: JSON keeps every digit of a
    float), its IM, unit, label, whether it is an approximation, the service life and the
    source (file and sha256, site; or the code value)."""
    out = {"label": curve.label, "im_name": curve.im_name, "unit": curve.unit,
           "approximate": curve.approximate, "t_years": float(t_years),
           "im": [float(v) for v in curve.im], "rate": [float(v) for v in curve.rate],
           "source": source}
    if curve.fractiles:  # the hazard's fractile curves: the interval of the risk
        out["fractiles"] = {repr(q): {"im": [float(v) for v in c.im],
                                      "rate": [float(v) for v in c.rate]}
                            for q, c in curve.fractiles.items()}
    return out


def curve_of(rec) -> HazardCurve:
    """The :class:`~rocking.analysis.HazardCurve` of a manifest's ``hazard`` record (or a
    HazardCurve itself)."""
    if isinstance(rec, HazardCurve):
        return rec
    if not isinstance(rec, dict):
        raise ParameterError(f"hazard must be a HazardCurve or the manifest's hazard record, "
                             f"got {type(rec).__name__}")
    missing = [k for k in ("im", "rate", "im_name", "unit") if k not in rec]
    if missing:
        raise ParameterError(f"hazard: the manifest's hazard record lacks "
                             f"{', '.join(missing)}")
    curve = HazardCurve(rec["im"], rec["rate"], im_name=rec["im_name"], unit=rec["unit"],
                        label=rec.get("label", ""), approximate=bool(rec.get("approximate")))
    fr = rec.get("fractiles")
    if fr:  # {q: {"im", "rate"}}, the same IM and unit
        curve = curve.with_fractiles({
            float(q): HazardCurve(c["im"], c["rate"], im_name=rec["im_name"],
                                  unit=rec["unit"]) for q, c in fr.items()})
    return curve


def check_t_years(t, name: str = "t_years") -> float:
    """A service life in (0, :data:`MAX_T_YEARS`] years."""
    if isinstance(t, bool):
        raise ParameterError(f"{name} must be a number of years in (0, {MAX_T_YEARS:g}], "
                             f"got {t!r}")
    try:
        v = float(t)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number of years in (0, {MAX_T_YEARS:g}], "
                             f"got {t!r}") from None
    if not (math.isfinite(v) and 0 < v <= MAX_T_YEARS):
        raise ParameterError(f"{name} must be a number of years in (0, {MAX_T_YEARS:g}], "
                             f"got {t!r}")
    return v


__all__ = ["FORMATS", "HAZARD_KEYS", "DEFAULT_T_YEARS", "read_hazard", "code_value",
           "campaign_im", "mismatch", "record", "curve_of", "parse_site", "file_format",
           "check_t_years", "to_im_unit", "unit_factor", "sha256"]
