"""The report of a campaign store: P(overturn) per level, fragility curves, plots, summary.

:func:`report` reads the store's table (one row per simulation) and its manifest and
writes, in one folder:

* ``p_overturn.csv``: per (model, block, level) the IM, the number of runs, of overturned
  runs, P(overturn) with its Wilson 95% interval, the median max|theta|/alpha of the
  survivors and P(DS >= k) of every damage state;
* ``fragility.csv``: per (model, block) the lognormal overturning curve fitted to the
  outcomes of every run (:func:`rocking.analysis.fragility`: repeated IM values are
  stripes, one binomial likelihood, Baker 2015) and the damage-state curves
  (:func:`rocking.analysis.fragility_curves`, one common beta); a group that cannot be
  fitted (nothing or everything overturned, outcomes separated by the IM) gets a note
  instead of numbers;
* ``pelicun.csv``: the damage-state curves as a pelicun fragility table (PGA and PGV);
* ``p_overturn_<model>.png``: the stripes with Wilson error bars and the fitted curves
  with their bootstrap bands, one colour per block;
* ``risk.csv`` (with a hazard: the store's ``[hazard]``, or one given to :func:`report`):
  per group and fit (overturning, each damage state) the annual frequency, its share from
  the hazard curve's extrapolated tails and the probability over the service life
  (:func:`rocking.analysis.risk`); a group without an overturning fit gets the rates of its
  IM bounds (a step fragility there) and a note, never a fitted number; an approximate
  (code-value) hazard is named so in its ``hazard`` and ``approximate`` columns;
  a group with runs stopped at an isolator's clearance also gets a row ``fit =
  overturned_or_clearance`` (below); every fitted number with its 90 % interval
  (``annual_frequency_low``/``_high``, ``probability_low``/``_high``: the fit's bootstrap
  and the hazard's fractile curves, :func:`rocking.analysis.hazard.risk_interval`), and
  ``risk.png``, every group's annual frequency with its interval and its service-life
  probability;
* ``mitigation.csv`` (with ``[[mitigation]]``): every mitigation against ``none``
  (:func:`rocking.analysis.compare_mitigations`: the ratio of the annual frequencies, or
  of the medians without a hazard, the verdict and the likely reason of a worse one) and
  the isolator's displacement at 475 and 2475 years with P(reaching the clearance);
* ``report.md``: a short markdown summary linking the above. The campaign's records are
  checked at the isolators' and the building's periods
  (:func:`rocking.motions.check_records_fit`): a warning and a note where they fall more
  than 10 % below EN 1998-1.

A table with a ``floor`` column (a campaign with ``[building]``) is grouped by (model,
block, floor): every file above has a ``floor`` column (and ``height_ratio`` when the
floors were given by height), each floor is a curve of its own in the plots, and
``report.md`` has a table of P(overturn) by floor per (model, block) (rows the levels,
columns the floors) before the per-floor tables. The IM of a floor's runs is the ground's
(the campaign scaled the ground motion).

A table with a ``mitigation`` column (a campaign with ``[[mitigation]]``) is grouped by
(mitigation, block, floor): every file above has a ``mitigation`` column after ``model``,
the fragility sections and plots are one per mitigation (``p_overturn_<mitigation>.png``),
and ``report.md`` begins its tables with P(overturn) by mitigation per block (rows the
levels, columns the mitigations: the same realizations, common random numbers). With a
hazard, ``risk.csv`` and the risk section have a row per mitigation and block. The
comparison itself (medians and risk relative to the unmitigated block, isolator demand) is
:mod:`rocking.analysis.mitigation`'s.

The IM is the table's ``im`` column when the campaign scaled its motions to intensity
levels (name and unit from ``manifest["im"]``, so every run of a level has the same IM),
else the PGA of each run as run (``pga``, m/s^2): the points of a level are then drawn at
the median PGA of its runs, while the fit uses each run's own PGA. Runs with a non-zero
``status`` (numerical failure) are left out of every count and fit, and counted; so are
the runs a planar model stopped because the block left the ground (``lifted_off``: the
vertical acceleration exceeded g, which a planar model cannot represent; ``status``
:data:`STATUS_LIFTED_OFF` in the report's table), neither overturned nor survived. Runs
still rocking when they ended (``settled`` false: neither at rest nor overturned at the
spec's ``duration``, or ``max_free_time`` after their motion) are counted as survivors,
with the max|theta|/alpha they reached, and flagged: their number is in ``report.md``, in
the terminal summary and per level (``n_unsettled`` in ``p_overturn.csv``). Initial tilts
redrawn because a draw lay beyond +-alpha (``theta0_truncated``) are counted the same way,
and so are the flags among the models' row outputs (``clearance_exceeded``: the isolated
base reached its clearance and the run stopped there, a survivor with the angle it had
reached; ``anchor_broken_plus``/``_minus``), among the runs of the models that report them.

**Runs stopped at the clearance are no known survivors.** Whether a run that the isolated
model stopped when its base reached the clearance (the moat) would have overturned is not
known; counted as survivors they make P(overturn), its fit and its risk too small. A group
with such runs (``clearance_exceeded`` and not overturned) therefore also gets the fit of
the combined failure "overturned or clearance reached" (those runs failed, as
:func:`rocking.analysis.mitigation.compare_mitigations` with ``failure="auto"``): a row
``fit = overturned_or_clearance`` (``state`` -1, not a damage state) in ``fragility.csv``
and, with a hazard, in ``risk.csv`` (its annual frequency and probability, or the rates of
its IM bounds), a table of its own in ``report.md`` and a line in the terminal. Its
overturning and damage-state rows keep their numbers with a note saying how many runs
stopped at the clearance they count as survivors (not conservative); the overturning
row's "no run overturned up to IM: at most ... per year" bound is left out when runs
stopped at or below that IM (it is no bound then; the combined row's is).
``p_overturn.csv`` then ends with ``n_clearance_exceeded``, those runs per level (a column
only when some run stopped at a clearance: other campaigns' files are as before).

**Headings.** A table with a ``heading`` column of several values (a 3-D campaign's heading
axis) runs every record at every heading. Its groups' fits pool the headings (the outcome
at a heading drawn uniformly); the runs of one record at several headings are not
independent (the same shaking, turned), so the overturning fit's band, interval and risk
interval come from a bootstrap that resamples records (``motion``), each with its runs at
every heading and level (:func:`rocking.analysis.fragility`, ``bootstrap="cluster"``).
Each group also gets a fit per heading and its worst heading
(:func:`rocking.analysis.heading_fragility`): ``headings.csv`` (a row per heading, and one
``heading_deg`` NaN for all headings, with the interval of a bootstrap of runs beside the
by-record one in its note), ``headings_<model>_<block>.png`` (the medians against the
heading) and a section of ``report.md``. The damage-state curves still draw their bands
as if the runs were independent (the ordered probit's asymptotic normal): too narrow, as
a note says.
"""

from __future__ import annotations

import math
import re
import warnings
from collections.abc import Mapping
from pathlib import Path

import numpy as np
import pandas as pd

from .._atomic import atomic_path, atomic_write
from ..analysis import DEFAULT_THRESHOLDS, fragility, fragility_curves, wilson_interval
from ..analysis.damage import state_labels
from ..analysis.fragility import (
    MIN_CLUSTERS,
    bootstrap_reliable,
    fit_or_bounds,
    unreliable_note,
)
from ..analysis.hazard import HazardCurve, probability_in, risk
from ..analysis.headings import HEADING_FIT_COLUMNS, heading_fragility
from ..errors import ParameterError, SimulationError
from ..models import require_planar
from ..models.registry import MODELS
from ..plot import PALETTE, figure, im_label, plain_log_ticks, save_figure, style_axes, unit_label
from ..units import G
from . import hazard as site_hazard
from .plan import row_output_columns

#: Columns the table must have.
REQUIRED_COLUMNS = (
    "sim_id", "model", "block", "block_name", "alpha", "p", "mu", "motion", "motion_id",
    "level", "load_factor", "sample", "theta0", "amplitude", "noise", "pga",
    "max_abs_theta", "max_abs_theta_over_alpha", "overturned", "overturn_time",
    "uplift_time", "n_impacts", "damage_state", "status")

#: pelicun demand type and unit of the IMs it knows.
PELICUN_DEMAND = {"pga": ("Peak Ground Acceleration", "g"),
                  "pgv": ("Peak Ground Velocity", "mps")}
_PELICUN_UNIT = {"m/s^2": "mps2", "m/s2": "mps2", "g": "g", "m/s": "mps", "m": "m",
                 "-": "unitless", "": "unitless"}

TAIL_NOTE = 0.1
"""A risk whose share from the hazard curve's extrapolated tails exceeds this gets a note
(the number rests on the power-law extension beyond the curve's ends)."""
RISK_COLUMNS = ("fit", "state", "label", "median", "beta", "im_unit", "annual_frequency",
                "tail_share", "probability", "t_years", "annual_frequency_low",
                "annual_frequency_high", "probability_low", "probability_high",
                "interval_level", "interval_source", "annual_frequency_lower_bound",
                "annual_frequency_upper_bound", "probability_lower_bound",
                "probability_upper_bound", "hazard", "approximate", "note")
"""The columns of ``risk.csv`` after the group's (model, mitigation, block, floor). The
``*_lower_bound``/``*_upper_bound`` columns of a group without a fit are the annual
frequency (and probability) of a step fragility at the IM bounds its outcomes give (the
largest IM without failure, the smallest with): bounds only under that step model, not
statistical confidence bounds (a fragility could rise below the largest IM run without
failure). ``annual_frequency_low``/``_high`` and ``probability_low``/``_high``: the
central ``interval_level`` interval (0.9: the 5th and 95th percentiles) propagated from the
fit's bootstrap and the hazard's fractile curves when it has them (``interval_source``;
:func:`rocking.analysis.hazard.risk_interval`); NaN for a group without a fit."""

CLEARANCE_FIT = "overturned_or_clearance"
"""The ``fit`` of the combined failure of a group whose runs were stopped at the isolator's
clearance: overturned, or the clearance reached (``clearance_exceeded``), as
:func:`rocking.analysis.mitigation.compare_mitigations` with ``failure="auto"``."""
CLEARANCE_LABEL = "overturned or clearance reached"
"""The ``label`` of the :data:`CLEARANCE_FIT` rows."""
STOPPED = "stopped at the isolator's clearance"
"""The words of the warning on a group's overturning (and damage-state) rows when some of
its runs were stopped at the clearance and count as survivors."""

N_BOOT = 200
"""Bootstrap draws of the bands (asymptotic normal: cheap)."""
DPI = 110
_FIT_ERRORS = (ParameterError, SimulationError, ValueError, np.linalg.LinAlgError)


# --------------------------------------------------------------------------- input

STATUS_LIFTED_OFF = 90
"""The ``status`` the report gives a planar run stopped at lift-off (``lifted_off``): left
out of every count and fit, and counted."""


def _check(table, manifest) -> tuple[pd.DataFrame, dict, tuple]:
    """The table with typed columns, the IM ``{"name", "unit", "column"}``, thresholds."""
    if not isinstance(manifest, Mapping):
        raise ParameterError(f"manifest must be a dict (the store's manifest.json), got "
                             f"{type(manifest).__name__}")
    if not isinstance(table, pd.DataFrame):
        raise ParameterError(f"table must be a pandas DataFrame, got {type(table).__name__}")
    missing = [c for c in REQUIRED_COLUMNS if c not in table.columns]
    if missing:
        raise ParameterError(f"table: missing column(s) {', '.join(missing)} (a campaign "
                             "store's table has one row per simulation)")
    if len(table) == 0:
        raise ParameterError("table is empty: the store holds no simulation (run the "
                             "campaign first)")
    im = _im_of(table, manifest)
    if "model" in table.columns:  # damage states need max |theta| / alpha
        for name in dict.fromkeys(table["model"].tolist()):  # (a 3-D body: its max_tilt)
            if name in MODELS and "max_tilt" not in {o.name for o in MODELS[name].outputs}:
                require_planar(name, "the campaign report (damage states and fragility)")
    t = table.copy()
    for col in ("alpha", "load_factor", "pga", "max_abs_theta", "max_abs_theta_over_alpha",
                *(["im"] if "im" in t else [])):
        t[col] = _numeric(t, col, float)
    for col in ("level", "block", "damage_state", "status",
                *(["floor"] if "floor" in t else [])):
        t[col] = _numeric(t, col, int)
    # overturned, and the optional ones (older stores lack settled and theta0_truncated;
    # lifted_off: motions with a vertical component)
    for col in ("overturned", "settled", "theta0_truncated", "lifted_off"):
        if col in t.columns and t[col].dtype != bool:
            if not t[col].isin([0, 1, True, False]).all():
                raise ParameterError(f"table: column {col} must be boolean")
            t[col] = t[col].astype(bool)
    if "lifted_off" in t.columns and "model" in t.columns:
        # a planar model stops a run where the block leaves the ground (g + a_v <= 0), which
        # it cannot represent: neither overturned nor survived, so it is left out of every
        # count and fit, as a failed run is, and counted (a 3-D model follows the flight)
        planar = t["model"].map(lambda m: bool(MODELS[m].tags.get("planar", True))
                                if m in MODELS else True)
        t.loc[t["lifted_off"] & planar & (t["status"] == 0), "status"] = STATUS_LIFTED_OFF
    thresholds = manifest.get("thresholds")
    thresholds = tuple(DEFAULT_THRESHOLDS if thresholds is None else
                       (float(v) for v in thresholds))
    top = len(thresholds) + 1
    bad = t["damage_state"][(t["status"] == 0) & ~t["damage_state"].between(0, top)]
    if len(bad):
        raise ParameterError(f"table: column damage_state must be in 0..{top} (thresholds "
                             f"{list(thresholds)} and overturning), got {int(bad.iloc[0])}")
    return t, im, thresholds


def _im_of(table: pd.DataFrame, manifest) -> dict:
    """The IM ``{"name", "unit", "column"}``: the manifest's, an ``im`` column, or PGA."""
    im_spec = manifest.get("im")
    if im_spec:
        if "im" not in table.columns:
            raise ParameterError(f"table: missing column im (manifest['im'] = {im_spec!r} "
                                 "says the motions were scaled to intensity levels)")
        return {"name": str(im_spec.get("name", "im")), "unit": str(im_spec.get("unit", "")),
                "column": "im"}
    if "im" in table.columns:
        return {"name": "im", "unit": "", "column": "im"}
    return {"name": "pga", "unit": "m/s^2", "column": "pga"}


def _numeric(t: pd.DataFrame, col: str, kind) -> pd.Series:
    try:
        s = pd.to_numeric(t[col], errors="raise")
    except (TypeError, ValueError):
        raise ParameterError(f"table: column {col} must be numeric") from None
    if kind is int:
        if s.isna().any() or (s != np.round(s)).any():
            raise ParameterError(f"table: column {col} must hold whole numbers")
        return s.astype(np.int64)
    return s.astype(float)


def _where(key: dict) -> str:
    """A floor in words: ``floor 2``, or ``z/H = 0.5`` (floors given by height)."""
    if "height_ratio" in key:
        return f"z/H = {_g(key['height_ratio'])}"
    return f"floor {key['floor']}" if "floor" in key else ""


def _group_name(name: str, key: dict) -> str:
    """A group's name: the block's, and its floor if there is a floor axis."""
    where = _where(key)
    return f"{name}, {where}" if where else str(name)


def _run_name(key: dict) -> str:
    """What a group ran: its mitigation and model (``isolated-2.5s (isolated)``), or its
    model; a mitigation named as its model once (``isolated``, not ``isolated
    (isolated)``)."""
    m = key.get("mitigation")
    if m is None or str(m) == str(key["model"]):
        return str(key["model"])
    return f"{m} ({key['model']})"


def _im_label(im: dict) -> str:
    return f"{im['name']} ({im['unit']})" if im["unit"] else im["name"]


def _safe(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", str(name)) or "model"


def _g(x, digits: int = 3) -> str:
    """``x`` to ``digits`` significant figures; NaN as a dash."""
    try:
        x = float(x)
    except (TypeError, ValueError):
        return str(x)
    return "–" if not math.isfinite(x) else f"{x:.{digits}g}"


# --------------------------------------------------------------------------- tables

def _p_overturn(g: pd.DataFrame, im_col: str, n_states: int,
                clearance: bool = False) -> pd.DataFrame:
    """The per-level table of one (model, block) group (all rows, failed runs counted);
    ``clearance``: with ``n_clearance_exceeded``, the runs of the level stopped at the
    isolator's clearance (counted among the survivors)."""
    rows = []
    for lv, d in g.groupby("level", sort=True):
        ok = d[d["status"] == 0]
        n, k = len(ok), int(ok["overturned"].sum())
        lo, hi = wilson_interval(k, n) if n else (math.nan, math.nan)
        if n:  # exact at k = 0 or n (statsmodels leaves a rounding error of ~1e-17)
            lo, hi = min(max(lo, 0.0), k / n), max(min(hi, 1.0), k / n)
        surv = ok.loc[~ok["overturned"], "max_abs_theta_over_alpha"].dropna()
        imv = ok[im_col] if n else d[im_col]
        row = {"level": int(lv), "im": float(np.nanmedian(imv)) if imv.notna().any()
               else math.nan,
               "load_factor": float(d["load_factor"].median()), "n": n, "n_overturned": k,
               "p_overturn": k / n if n else math.nan, "ci_lower": lo, "ci_upper": hi,
               "median_ratio_survivors": float(surv.median()) if len(surv) else math.nan,
               "n_excluded": int(len(d) - n)}
        if "settled" in ok.columns:
            row["n_unsettled"] = int((~ok["settled"]).sum())
        for s in range(1, n_states + 1):
            row[f"p_ds_ge_{s}"] = float((ok["damage_state"] >= s).mean()) if n else math.nan
        if clearance:  # last: the columns before it as without stopped runs
            row["n_clearance_exceeded"] = int(_stopped(ok).sum())
        rows.append(row)
    return pd.DataFrame(rows)


def _stopped(d: pd.DataFrame) -> np.ndarray:
    """The runs of ``d`` stopped at the isolator's clearance without having overturned
    (``clearance_exceeded``; False without the column): their overturning is not known."""
    if "clearance_exceeded" not in d.columns:
        return np.zeros(len(d), dtype=bool)
    return (d["clearance_exceeded"] == 1).to_numpy(bool) & ~d["overturned"].to_numpy(bool)


def _stopped_note(n: int, total: int, what: str = "not overturned") -> str:
    """The warning of a fit that counts ``n`` runs stopped at the clearance as survivors."""
    return (f"{n} of {total} runs {STOPPED} (clearance_exceeded) count as {what}: whether "
            f"they would have overturned is not known, so this is not conservative (the "
            f"{CLEARANCE_FIT} rows count them as failures)")


def _fit_group(ok: pd.DataFrame, im: dict, labels: list[str], n_boot: int, seed,
               by_record: bool = False):
    """Overturning fit and damage-state curves of one group: ``(rows, fit, curves,
    notes, clear)``; a fit that cannot be made leaves a row with a note. A group with runs
    stopped at the isolator's clearance also gets the fit of :data:`CLEARANCE_FIT`
    (overturned or clearance reached: those runs failed; ``clear`` is that fit, or None),
    and its overturning and damage-state rows say how many runs count as survivors though
    stopped (:func:`_stopped_note`). ``clear`` is ``False`` for a group without such
    runs (its rows as before). ``by_record``: the overturning (and combined) fits'
    bootstrap resamples the records (``motion``), each with all its runs (a campaign with
    several headings)."""
    n_states = len(labels)
    base = {"n": len(ok)}
    rows, notes = [], []
    x = ok[im["column"]].to_numpy(float)
    units = {"im_name": im["name"], "im_unit": im["unit"] or None}  # carried by the fits
    good = np.isfinite(x) & (x > 0)
    if not good.all():
        notes.append(f"{int((~good).sum())} run(s) without a finite IM > 0 left out of the "
                     "fits")
    x, ov = x[good], ok["overturned"].to_numpy(bool)[good]
    ds = ok["damage_state"].to_numpy(int)[good]
    stop = _stopped(ok)[good]
    n_stop = int(stop.sum())
    base["n"] = int(x.size)
    boot, no_band = {"n_boot": n_boot}, ""
    n_rec = int(ok["motion"][good].nunique())
    if by_record and n_boot and n_rec >= MIN_CLUSTERS:
        boot.update(bootstrap="cluster", clusters=ok["motion"].to_numpy()[good])
    elif by_record and n_boot:  # runs of a record are not independent: no honest band
        boot["n_boot"] = 0
        no_band = (f"no band: {n_rec} records are too few for a bootstrap by record (at "
                   f"least {MIN_CLUSTERS})")

    def fit_of(outcome, label):  # a bootstrap by record with no interval: none shown
        nonlocal no_band
        f = fragility(x, outcome, seed=seed, label=label, **units, **boot)
        if "clusters" in boot and not bootstrap_reliable(f):
            no_band = unreliable_note(f).replace("no interval", "no band")
            f = fragility(x, outcome, n_boot=0, seed=seed, label=label, **units)
        return f

    def attempt(fn):
        if x.size == 0:
            return None, "no run with a valid IM"
        if np.unique(x).size < 2:
            return None, f"a single IM value ({x[0]:.4g}): no curve can be fitted"
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                return fn(), ""
        except _FIT_ERRORS as e:
            return None, str(e)

    fit, why = attempt(lambda: fit_of(ov, "overturning"))
    row = {"fit": "overturning", "state": n_states, "label": labels[-1], **base,
           "n_exceed": int(ov.sum())}
    if fit is None:
        rows.append({**row, "median": math.nan, "median_se": math.nan, "beta": math.nan,
                     "beta_se": math.nan, "note": f"no overturning fit: {why}"})
    else:
        note = "" if math.isfinite(fit.median_se) and math.isfinite(fit.beta_se) else \
            "standard errors not finite (nearly separated data)"
        note = "; ".join(filter(None, [note, no_band]))
        rows.append({**row, "median": fit.median, "median_se": fit.median_se,
                     "beta": fit.beta, "beta_se": fit.beta_se, "note": note})
    clear = False
    if n_stop:  # runs stopped at the clearance: not known survivors
        rows[-1]["note"] = "; ".join(filter(None, [rows[-1]["note"],
                                                   _stopped_note(n_stop, x.size)]))
        failed = ov | stop
        clear, why = attempt(lambda: fit_of(failed, CLEARANCE_LABEL))
        crow = {"fit": CLEARANCE_FIT, "state": -1, "label": CLEARANCE_LABEL, **base,
                "n_exceed": int(failed.sum())}
        what = (f"failures: the runs that overturned ({int(ov.sum())}) or were {STOPPED} "
                f"({n_stop}), as rocking.analysis.mitigation's failure="
                f"'overturned_or_clearance'")
        if clear is None:
            rows.append({**crow, "median": math.nan, "median_se": math.nan,
                         "beta": math.nan, "beta_se": math.nan,
                         "note": f"no {CLEARANCE_LABEL} fit: {why}; {what}"})
        else:
            se = "" if math.isfinite(clear.median_se) and math.isfinite(clear.beta_se) \
                else "standard errors not finite (nearly separated data); "
            rows.append({**crow, "median": clear.median, "median_se": clear.median_se,
                         "beta": clear.beta, "beta_se": clear.beta_se, "note": se + what})
    curves, why = attempt(lambda: fragility_curves(x, ds, n_boot=n_boot, seed=seed, **units))
    if curves is None:
        rows.append({"fit": "damage_states", "state": -1, "label": "all states", **base,
                     "n_exceed": -1, "median": math.nan, "median_se": math.nan,
                     "beta": math.nan, "beta_se": math.nan,
                     "note": f"no damage-state curves: {why}"})
    else:
        for s, f in enumerate(curves.fits, start=1):
            rows.append({"fit": "damage_states", "state": s, "label": labels[s - 1], **base,
                         "n_exceed": int((ds >= s).sum()), "median": f.median,
                         "median_se": f.median_se, "beta": f.beta, "beta_se": f.beta_se,
                         "note": "common beta (ordered probit)" + (
                             "; " + _stopped_note(n_stop, x.size, "survivors with the "
                                                  "angle they had reached")
                             if n_stop else "")})
        if len(curves.fits) < n_states:
            notes.append(f"damage states above DS{len(curves.fits)} never reached: no "
                         "curve for them")
    return rows, fit, curves, notes, clear


def _pelicun(curves, im: dict, ident: str):
    """The pelicun row of ``curves``, or a note why not."""
    if im["name"] not in PELICUN_DEMAND:
        return None, f"no pelicun demand type for IM {im['name']!r}"
    unit = _PELICUN_UNIT.get(im["unit"])
    if unit is None:
        return None, f"no pelicun unit for {im['unit']!r}"
    dtype, dunit = PELICUN_DEMAND[im["name"]]
    try:
        return curves.to_pelicun(id=ident, demand_type=dtype, demand_unit=dunit,
                                 im_unit=unit), ""
    except ParameterError as e:
        return None, str(e)


# --------------------------------------------------------------------------- risk

def _site(manifest, hazard, t_years, im: dict) -> dict | None:
    """The hazard of the report: ``hazard`` (a HazardCurve or a manifest record, given at
    report time) or the manifest's ``hazard``; ``{"curve", "t_years", "source", "given",
    "replaces"}``, or None without one. A curve of another IM than the table's is refused
    (naming both)."""
    stored = manifest.get("hazard")
    rec = hazard if hazard is not None else stored
    if rec is None:
        if t_years is not None:
            raise ParameterError("t_years needs a hazard curve: the store has no [hazard] "
                                 "(give one)")
        return None
    curve = site_hazard.curve_of(rec)
    why = site_hazard.mismatch(curve, im)
    if why is not None:
        raise ParameterError(f"hazard: {why}")
    if t_years is None:
        t_years = rec.get("t_years") if isinstance(rec, dict) else None
    t = site_hazard.check_t_years(site_hazard.DEFAULT_T_YEARS if t_years is None
                                  else t_years)
    src = (rec.get("source") or {}) if isinstance(rec, dict) else {}
    replaces = (str(stored.get("label", "?")) if hazard is not None
                and isinstance(stored, dict) else None)
    return {"curve": curve, "t_years": t, "source": src, "given": hazard is not None,
            "replaces": replaces}


def _unit_text(unit: str) -> str:
    return f" {unit}" if unit else ""


def _risk_row(f, curve: HazardCurve, t: float) -> dict:
    """The risk of one fit: annual frequency, tail share, probability in ``t`` years."""
    r = risk(f, curve, t_years=t)
    note = ""
    if r.tail_share > TAIL_NOTE:
        note = (f"{100 * r.tail_share:.0f}% of it from the power-law tails beyond the hazard "
                f"curve ({_g(curve.im[0])}..{_g(curve.im[-1])} {curve.unit}): it rests on "
                "that extrapolation")
    lo, hi = r.annual_frequency_interval
    pl, ph = r.probability_interval_in(t)
    return {"median": f.median, "beta": f.beta, "annual_frequency": r.annual_frequency,
            "tail_share": r.tail_share, "probability": r.probability_in(t),
            "annual_frequency_low": lo, "annual_frequency_high": hi, "probability_low": pl,
            "probability_high": ph, "interval_level": r.interval_level,
            "interval_source": r.interval_source, "note": note}


def _bounds(ok: pd.DataFrame, im: dict, curve: HazardCurve, t: float,
            combined: bool = False) -> dict:
    """A group without an overturning fit: the rate of the IM bounds that the outcomes
    give (:func:`rocking.analysis.fragility.fit_or_bounds`), as the annual frequency of a
    step fragility there, and a note; never a fitted number. ``combined``: the failure is
    :data:`CLEARANCE_FIT` (overturned, or stopped at the isolator's clearance). Without
    it, runs stopped at the clearance are survivors of unknown fate: "no run overturned up
    to IM" is then no bound if one of them ran at or below that IM (the upper bound is
    left out and the note says why; the combined row has the bound)."""
    nan = math.nan
    out = {"annual_frequency_lower_bound": nan, "annual_frequency_upper_bound": nan,
           "probability_lower_bound": nan, "probability_upper_bound": nan}
    x = ok[im["column"]].to_numpy(float)
    good = np.isfinite(x) & (x > 0)
    stop = _stopped(ok)[good]
    x, ov = x[good], ok["overturned"].to_numpy(bool)[good]
    if combined:
        ov = ov | stop
    unit = _unit_text(im["unit"])
    fit_name, verb = ((f"{CLEARANCE_LABEL} fit", "overturned or reached the clearance")
                      if combined else ("overturning fit", "overturned"))
    warn = "" if combined or not stop.any() else \
        "; " + _stopped_note(int(stop.sum()), x.size)
    if x.size == 0:
        return {**out, "note": "no fit, no run with a valid IM: no number"}
    try:
        _, lo, hi, why = fit_or_bounds(x, ov, n_boot=0)
    except _FIT_ERRORS as e:
        return {**out, "note": f"no fit ({_line(e)}): no number{warn}"}
    def rate(v):
        c = float(site_hazard.to_im_unit(v, curve, im["unit"]))
        beyond = not curve.im[0] <= c <= curve.im[-1]
        return curve.rate_at(c), " (that IM is beyond the hazard curve: its power-law " \
            "tail)" * beyond

    if why == "separated" and lo >= hi:  # mixed outcomes at one IM, none below, all above
        lam, beyond = rate(hi)
        return {**out, "note": f"no {fit_name} ({verb} from {_g(hi)}{unit} on, "
                               f"none below; survivors there too): no fitted number; the "
                               f"rate of that IM is {_g(lam)} per year{beyond} (the annual "
                               f"frequency if the fragility were a step there, not a "
                               f"bound){warn}"}
    if why not in ("none failed", "all failed", "separated"):
        return {**out, "note": f"no {fit_name} (the outcomes give no bound of the "
                               f"median): no number{warn}"}
    parts = []

    if math.isfinite(lo) and warn and (x[stop] <= lo).any():  # unknown fates below lo
        k = int((x[stop] <= lo).sum())
        parts.append(f"no bound: {k} runs up to {_g(lo)}{unit} were {STOPPED}")
    elif math.isfinite(lo):  # no overturning up to lo: a step there has rate lambda(lo)
        lam, beyond = rate(lo)
        out["annual_frequency_upper_bound"] = lam
        out["probability_upper_bound"] = probability_in(t, lam)
        parts.append(f"no run {verb} up to {_g(lo)}{unit}: at most {_g(lam)} per year "
                     f"if the fragility were a step there{beyond}")
    if math.isfinite(hi):  # every run overturned from hi: a step there has rate lambda(hi)
        lam, beyond = rate(hi)
        out["annual_frequency_lower_bound"] = lam
        out["probability_lower_bound"] = probability_in(t, lam)
        parts.append(f"every run {verb} from {_g(hi)}{unit}: at least {_g(lam)} per "
                     f"year if the fragility were a step there{beyond}")
    what = {"none failed": f"no run {verb}", "all failed": f"every run {verb}",
            "separated": "outcomes separated by the IM",
            "decreasing": f"{verb} only below the survivals"}.get(why, why)
    note = f"no {fit_name} ({what}): no fitted number"
    if parts:
        note += "; " + "; ".join(parts)
    return {**out, "note": note + warn}


def _line(e) -> str:
    return (str(e).splitlines() or [type(e).__name__])[0]


def _risk_rows(key: dict, ok: pd.DataFrame, im: dict, fit, curves, labels: list[str],
               site: dict, clear=False) -> list[dict]:
    """The rows of ``risk.csv`` of one group: overturning (a fit, or bounds and a note),
    for a group with runs stopped at the isolator's clearance (``clear`` not False: the
    :data:`CLEARANCE_FIT` fit or None) the risk of overturned or clearance reached (a fit,
    or bounds) right after it, and every damage state with a curve. The overturning and
    damage-state rows of such a group say that those runs count as survivors."""
    curve, t = site["curve"], site["t_years"]
    nan = math.nan
    base = {**key, "im_unit": im["unit"], "t_years": t, "hazard": curve.label,
            "approximate": curve.approximate, "annual_frequency_low": nan,
            "annual_frequency_high": nan, "probability_low": nan, "probability_high": nan,
            "interval_level": nan, "interval_source": "",
            "annual_frequency_lower_bound": nan, "annual_frequency_upper_bound": nan,
            "probability_lower_bound": nan, "probability_upper_bound": nan}
    x = ok[im["column"]].to_numpy(float)
    good = np.isfinite(x) & (x > 0)
    n_stop, n_good = int(_stopped(ok)[good].sum()), int(good.sum())

    def warned(r: dict, what: str = "not overturned") -> dict:
        if n_stop:
            r["note"] = "; ".join(filter(None, [r["note"],
                                                _stopped_note(n_stop, n_good, what)]))
        return r

    row = {**base, "fit": "overturning", "state": len(labels), "label": labels[-1]}
    if fit is not None:
        rows = [warned({**row, **_risk_row(fit, curve, t)})]
    else:  # _bounds says it
        rows = [{**row, "median": nan, "beta": nan, "annual_frequency": nan,
                 "tail_share": nan, "probability": nan, **_bounds(ok, im, curve, t)}]
    if clear is not False:
        row = {**base, "fit": CLEARANCE_FIT, "state": -1, "label": CLEARANCE_LABEL}
        if clear is not None:
            rows.append({**row, **_risk_row(clear, curve, t)})
        else:
            rows.append({**row, "median": nan, "beta": nan, "annual_frequency": nan,
                         "tail_share": nan, "probability": nan,
                         **_bounds(ok, im, curve, t, combined=True)})
    if curves is not None:
        for s, f in enumerate(curves.fits, start=1):
            rows.append(warned({**base, "fit": "damage_states", "state": s,
                                "label": labels[s - 1], **_risk_row(f, curve, t)},
                               "survivors with the angle they had reached"))
    return rows


# --------------------------------------------------------------------------- plots

def _plot_name(name: str, blocks) -> str:
    """A block's name for a legend. The spec's default ``block i`` (no ``name`` key) says
    nothing to a reader: it becomes the block's size from the manifest's ``alpha`` and
    ``p`` (Eqs 2-3: ``R = 3 g / 4 p^2``, width ``2 R sin(alpha)``, height
    ``2 R cos(alpha)``; for a block given by ``alpha, p, mu`` the rectangle with the same
    parameters) and its place in the spec, e.g. ``0.2 × 1 m block (blocks[0])``."""
    m = re.fullmatch(r"block (\d+)", str(name))
    if m is None or not blocks or int(m[1]) >= len(blocks):
        return str(name)
    i = int(m[1])
    try:
        a, p = float(blocks[i]["alpha"]), float(blocks[i]["p"])
    except (KeyError, TypeError, ValueError):
        return str(name)
    if not (math.isfinite(a) and math.isfinite(p) and p > 0):
        return str(name)
    r = 3.0 * G / (4.0 * p * p)
    return f"{2 * r * math.sin(a):.3g} × {2 * r * math.cos(a):.3g} m block (blocks[{i}])"


MARKERS = ("o", "s", "^", "D", "v", "P", "X")
"""Markers of the groups of a plot (with the colours: no two groups look alike)."""
LINESTYLES = ("-", "-.", (0, (5, 1)), ":")
"""Line styles of the groups' fits (the combined failure is always dashed)."""


def _fit_range(d: pd.DataFrame, fit) -> np.ndarray:
    """IMs to draw a fit over: the levels run and the fit's median +- 2 beta, within a
    factor 4 of the levels (a fit with a large beta or a median far beyond the data must
    not stretch the axis over decades where nothing was run)."""
    lo = np.nanmin(d["im"]) if len(d) else fit.median
    hi = np.nanmax(d["im"]) if len(d) else fit.median
    a = max(min(lo, fit.median * math.exp(-2.0 * fit.beta)), lo / 4.0)
    b = min(max(hi, fit.median * math.exp(2.0 * fit.beta)), hi * 4.0)
    return np.geomspace(a, b, 150)


def _plot_model(model: str, groups: list, im: dict, path: Path, blocks=None) -> Path:
    """P(overturn) vs IM of one model: stripes with Wilson bars, fits with bands; the IM's
    unit in mathtext (``m/s$^2$``), the blocks named by :func:`_plot_name` (and their
    floor), the legend beside the axes (it covered the curves of the weaker blocks).
    Each group has its own colour, marker and line style, and its points are shifted
    a little along the IM (a few %, in log) so that groups with the same outcomes (every
    floor of an isolated block at P = 0) do not hide one another. A group with runs
    stopped at the isolator's clearance also shows P(overturned or clearance reached)
    per level (filled markers) and its fit (dashed): the y label names both."""
    fig, ax = figure(figsize=(9.2, 4.0))
    unit = unit_label(im["unit"])
    n_groups = len(groups)
    any_clear = False
    for i, (key, pt, fit, *clear) in enumerate(groups):
        c = PALETTE[i % len(PALETTE)]
        mk = MARKERS[i % len(MARKERS)]
        ls = LINESTYLES[i % len(LINESTYLES)]
        shift = math.exp(0.025 * (i - (n_groups - 1) / 2)) if n_groups > 1 else 1.0
        d = pt[(pt["n"] > 0) & pt["im"].notna()]
        yerr = np.vstack([d["p_overturn"] - d["ci_lower"], d["ci_upper"] - d["p_overturn"]])
        lab = _plot_name(key["block_name"], blocks)
        lab += f", {_where(key)}" if _where(key) else ""
        if fit is not None:
            x = _fit_range(d, fit)
            ax.plot(x, fit.probability(x), color=c, lw=1.3, ls=ls)
            if fit.n_boot:
                b = fit.band(x)
                ax.fill_between(x, b["lower"], b["upper"], color=c, alpha=0.18, lw=0)
            lab += f"\nmedian {_g(fit.median)}{' ' + unit if unit else ''}, beta {_g(fit.beta, 2)}"
        stopped = "n_clearance_exceeded" in pt and bool(pt["n_clearance_exceeded"].sum())
        if stopped:
            any_clear = True
            lab += (f"\n{int(pt['n_clearance_exceeded'].sum())} runs stopped at the "
                    "clearance")
        ax.errorbar(d["im"] * shift, d["p_overturn"], yerr=np.clip(yerr, 0, None), fmt=mk,
                    ms=4.5, mfc="none", color=c, capsize=2, lw=0.8,
                    label=lab + ("\nopen: overturned" if stopped else ""))
        if stopped:  # the combined failure per level, filled, and its fit dashed
            k = (d["n_overturned"] + d["n_clearance_exceeded"]).to_numpy(int)
            n = d["n"].to_numpy(int)
            ci = np.array([wilson_interval(int(a), int(b)) for a, b in zip(k, n, strict=True)])
            pc = k / n
            cl = f"filled: {CLEARANCE_LABEL}"
            cf = clear[0] if clear and clear[0] else None
            if cf is not None:
                x = _fit_range(d, cf)
                ax.plot(x, cf.probability(x), color=c, lw=1.3, ls="--")
                if cf.n_boot:  # its band too, as the title says of every fit
                    b = cf.band(x)
                    ax.fill_between(x, b["lower"], b["upper"], color=c, alpha=0.10, lw=0,
                                    hatch="//")
                cl += (f"\n(dashed fit: median {_g(cf.median)}"
                       f"{' ' + unit if unit else ''}, beta {_g(cf.beta, 2)})")
            ax.errorbar(d["im"] / shift, pc, yerr=np.clip(np.vstack([pc - ci[:, 0],
                                                                      ci[:, 1] - pc]), 0,
                                                           None),
                        fmt=mk, ms=4.5, color=c, capsize=2, lw=0.8, label=cl)
    ims = np.concatenate([g[1]["im"].dropna().to_numpy(float) for g in groups] or [[]])
    ims = ims[ims > 0]
    if ims.size and ims.max() > 8 * ims.min():  # levels spread over a decade: log axis
        ax.set_xscale("log")
    ylabel = (f"P(overturn), P({CLEARANCE_LABEL})" if any_clear else "P(overturn)")
    style_axes(ax, im_label(im["name"], im["unit"]), ylabel)
    ax.set_ylim(-0.03, 1.03)
    if ax.get_xscale() == "log":
        plain_log_ticks(ax)  # 0.5, 1, 2, 5 rather than 3 x 10^0 beside 4 x 10^0
    what = (f"P(overturn) and P({CLEARANCE_LABEL})" if any_clear else "P(overturn)")
    ax.set_title(f"{model}: {what} per level (95% Wilson bars), lognormal fits "
                 "(95% bands)", fontsize=10)
    ax.legend(frameon=False, fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0),
              borderaxespad=0.0, labelspacing=0.9)
    return save_figure(fig, path, dpi=DPI)


def _plot_risk(rk: pd.DataFrame, site: dict, path: Path) -> Path | None:
    """The risk of every group at a glance (for a director): the annual frequency of
    overturning (and of overturned or clearance reached) with its interval, one row per
    group, on a log axis, the probability over the service life written beside it; a
    group without a fit shows the bound of a step fragility (a triangle) if it has one.
    A group with runs stopped at the isolator's clearance shows only its "overturned or
    clearance reached" row (its overturning row counts those runs as survivors)."""
    keep = rk[rk["fit"].isin(["overturning", CLEARANCE_FIT])]
    rows = []
    for _, r in keep.iterrows():
        d = r.to_dict()
        if d["fit"] == "overturning" and ((keep["fit"] == CLEARANCE_FIT)
                                          & _same_group(keep, d)).any():
            continue  # runs stopped at the moat count as survivors there: not shown
        lam = d["annual_frequency"]
        up = d.get("annual_frequency_upper_bound", math.nan)
        if not (math.isfinite(lam) or math.isfinite(up)):
            continue
        rows.append(d)
    if not rows:
        return None
    t = site["t_years"]
    names = list(dict.fromkeys(_run_name(d) for d in rows))
    fig, ax = figure(figsize=(9.0, 1.2 + 0.42 * len(rows)))
    labels = []
    for y, d in enumerate(rows):
        c = PALETTE[names.index(_run_name(d)) % len(PALETTE)]
        comb = d["fit"] == CLEARANCE_FIT
        labels.append(f"{_group_name(d['block_name'], d)} — {_run_name(d)}"
                      + (f"\n({CLEARANCE_LABEL})" if comb else ""))
        lam = d["annual_frequency"]
        if math.isfinite(lam):
            lo, hi = d.get("annual_frequency_low", math.nan), d.get(
                "annual_frequency_high", math.nan)
            err = (np.array([[lam - lo], [hi - lam]]) if math.isfinite(lo)
                   and math.isfinite(hi) else None)
            ax.errorbar([lam], [y], xerr=err, fmt="s" if comb else "o", color=c, ms=6,
                        mfc="white" if comb else c, capsize=3, lw=1.2)
            p = f"P({_g(t, 6)} yr) {_g(d['probability'], 2)}"
            if math.isfinite(d.get("probability_low", math.nan)):
                p += f" ({_g(d['probability_low'], 2)}–{_g(d['probability_high'], 2)})"
            ax.annotate(p, (hi if err is not None else lam, y), xytext=(8, 0),
                        textcoords="offset points", va="center", fontsize=8)
        else:
            up = d["annual_frequency_upper_bound"]
            ax.plot([up], [y], "<", color=c, ms=7)
            ax.annotate(f"at most {_g(up, 2)}/yr (no fit: a step-fragility bound)",
                        (up, y), xytext=(8, 0), textcoords="offset points",
                        va="center", fontsize=8)
    ax.set_yticks(range(len(rows)), labels, fontsize=8)
    ax.invert_yaxis()
    ax.set_xscale("log")
    lo_x, hi_x = ax.get_xlim()
    ax.set_xlim(lo_x, hi_x * 30)  # room for the probabilities
    style_axes(ax, "annual frequency (per year)")
    lv = rk["interval_level"].dropna()
    what = (f"bars: {100 * float(lv.iloc[0]):.0f} % interval" if len(lv) else "no interval")
    ax.set_title(f"Risk at the site: annual frequency and P({_g(t, 6)} yr) ({what})"
                 + (" — APPROXIMATE hazard" if site["curve"].approximate else ""),
                 fontsize=10)
    return save_figure(fig, path, dpi=DPI)


# --------------------------------------------------------------------------- markdown

def _pm(x, se, digits: int) -> str:
    return "–" if not math.isfinite(x) else f"{_g(x, digits)} ± {_g(se, 2)}"


def _md_table(header: list[str], rows: list[list[str]]) -> list[str]:
    """A markdown table (a ``|`` in a cell, as in ``max|theta|``, escaped)."""
    def cells(r):
        return "| " + " | ".join(str(c).replace("|", "\\|") for c in r) + " |"
    return [cells(header), "|" + "---|" * len(header), *(cells(r) for r in rows), ""]


def _run_counts(t: pd.DataFrame) -> tuple[list[str], list[str], dict]:
    """How the runs were made and ended: ``(lines for report.md, those of them with a
    non-zero count for the terminal, the counts)``."""
    lines, alerts, counts = [], [], {}
    if "theta0_truncated" in t.columns:
        k = counts["n_theta0_truncated"] = int(t["theta0_truncated"].sum())
        if k or t["theta0"].ne(0).any():  # theta0 was uncertain
            lines.append(f"initial tilt: {k} of {len(t)} runs drew theta0 at or beyond "
                         "+-alpha and redrew it (theta0 truncated to |theta0| < alpha)")
            alerts += lines[-1:] if k else []
    if "settled" in t.columns:
        ok = t["status"] == 0
        k = counts["n_unsettled"] = int((ok & ~t["settled"]).sum())
        lines.append(f"unsettled: {k} of {int(ok.sum())} runs were still rocking when they "
                     "ended (neither at rest nor overturned); they count as survivors with "
                     "the max|theta|/alpha they reached (column settled = false; raise "
                     "max_free_time or duration to decide them)")
        alerts += lines[-1:] if k else []
    for name, o in row_output_columns(MODELS).items():  # the models' flags (row outputs)
        if not o.flag or name not in t.columns:
            continue
        models = [m for m, c in MODELS.items() if name in {r.name for r in c.row_outputs}]
        runs = t[t["model"].isin(models)]
        k = counts[f"n_{name}"] = int(runs[name].astype(bool).sum())
        lines.append(f"{name}: {k} of {len(runs)} {'/'.join(models)} runs ({o.help})")
        alerts += lines[-1:] if k else []
    return lines, alerts, counts


APPROXIMATE = ("APPROXIMATION: the hazard curve is a code value (EN 1998-1 power law), not "
               "a hazard model's output; the risk figures are approximate")
"""What an approximate hazard is, said wherever its risk appears."""


def _source_text(src: dict) -> str:
    if not src:
        return ""
    if "code_value" in src:
        two = (f", {_g(src['pga_2475_g'])} g at 2475 years" if "pga_2475_g" in src else "")
        return (f"{src['code_value']}: PGA {_g(src['pga_475_g'])} g at 475 years{two}, "
                f"k = {_g(src.get('k'))}")
    out = f"{src.get('format', 'file')} file {src.get('file', '?')}"
    if "sha256" in src:
        out += f" (sha256 {str(src['sha256'])[:12]})"
    if "site_index" in src:
        out += (f", site {src['site_index']} at ({_g(src.get('lon'), 6)}, "
                f"{_g(src.get('lat'), 6)})")
    if "investigation_time" in src:
        out += f", investigation time {src['investigation_time']} years"
    return out


def _span(lo, hi) -> str:
    """``"lo–hi"`` of an interval, ``"–"`` without one."""
    if not (isinstance(lo, float | int) and math.isfinite(lo) and math.isfinite(hi)):
        return "–"
    return f"{_g(lo, 2)}–{_g(hi, 2)}"


def _interval_words(rk: pd.DataFrame) -> str:
    """What the intervals of ``rk`` are (their level and sources), for report.md."""
    lv = rk["interval_level"].dropna() if "interval_level" in rk else pd.Series([], float)
    if lv.empty:
        return "no interval: the fits have no bootstrap and the hazard no fractile curves"
    src = sorted({str(v) for v in rk["interval_source"] if v and v == v})
    return (f"{100 * float(lv.iloc[0]):.0f} % interval (the {50 * (1 - float(lv.iloc[0])):g}th "
            f"and {100 - 50 * (1 - float(lv.iloc[0])):g}th percentiles) from "
            + "; ".join(src))


def _risk_md(rk: pd.DataFrame, site: dict) -> list[str]:
    """The risk section of ``report.md``."""
    c, t = site["curve"], site["t_years"]
    head = "## Risk at the site" + (" (approximate hazard)" if c.approximate else "")
    out = [head, ""]
    if c.approximate:
        out += [f"**{APPROXIMATE}.**", ""]
    out += [f"- hazard: {c.label}; {c.im_name} in {c.unit}, {c.im.size} points "
            f"{_g(c.im[0])}..{_g(c.im[-1])} {c.unit}, annual rates {_g(c.rate[0])}.."
            f"{_g(c.rate[-1])}",
            *([f"- source: {_source_text(site['source'])}"] if site["source"] else []),
            *(["- given at report time" + (f", in place of the store's [hazard] "
                                           f"{site['replaces']!r}" if site["replaces"]
                                           else "")] if site["given"] else []),
            f"- service life: {_g(t, 6)} years", "",
            "Annual frequency lambda = integral of P(state | IM) |d lambda_IM / d IM| over "
            "the whole IM range (Cornell et al. 2002; rocking.analysis.risk), the hazard "
            "curve extended beyond its ends as power laws with its end slopes; tails: the "
            f"share of lambda from those extensions. P({_g(t, 6)} yr) = 1 - exp(-lambda t). "
            "A group without a fit has no number: the note gives the rate of the IM up to "
            "which nothing overturned (or from which everything did).",
            f"Intervals: {_interval_words(rk)} (rocking.analysis.hazard.risk_interval).",
            ""]
    ov = rk[rk["fit"] == "overturning"]
    by = "mitigation" if "mitigation" in rk.columns else "model"
    ty = f"P({_g(t, 6)} yr)"
    for _, f in ov.groupby(by, sort=False):
        out += [f"### {_run_name(f.iloc[0].to_dict())}: overturning", ""]
        rows = [[_group_name(r["block_name"], r.to_dict()), _g(r["annual_frequency"]),
                 _span(r["annual_frequency_low"], r["annual_frequency_high"]),
                 _g(r["probability"]), _span(r["probability_low"], r["probability_high"]),
                 _g(100 * r["tail_share"], 2) + " %"
                 if math.isfinite(r["tail_share"]) else "–", r["note"] or ""]
                for _, r in f.iterrows()]
        out += _md_table(["block", "annual frequency (/yr)", "interval (/yr)", ty,
                          "interval", "tails", "note"], rows)
    for _, f in rk[rk["fit"] == CLEARANCE_FIT].groupby(by, sort=False):
        out += [f"### {_run_name(f.iloc[0].to_dict())}: {CLEARANCE_LABEL}", "",
                "The runs stopped at the isolator's clearance (clearance_exceeded) are no "
                "known survivors: here they count as failures with those that overturned "
                "(the fit of that combined failure; rocking.analysis.mitigation, "
                "failure='overturned_or_clearance'), the conservative counterpart of the "
                "overturning rows above, which count them as survivors.", ""]
        rows = [[_group_name(r["block_name"], r.to_dict()), _g(r["annual_frequency"]),
                 _span(r["annual_frequency_low"], r["annual_frequency_high"]),
                 _g(r["probability"]), _span(r["probability_low"], r["probability_high"]),
                 _g(100 * r["tail_share"], 2) + " %"
                 if math.isfinite(r["tail_share"]) else "–", r["note"] or ""]
                for _, r in f.iterrows()]
        out += _md_table(["block", "annual frequency (/yr)", "interval (/yr)", ty,
                          "interval", "tails", "note"], rows)
    ds = rk[rk["fit"] == "damage_states"]
    if len(ds):
        out += ["### Damage states", "",
                "From the damage-state curves (common beta); the last state is "
                "overturning.", ""]
        rows = [[_run_name(r.to_dict()), _group_name(r["block_name"], r.to_dict()),
                 str(r["label"]), _g(r["annual_frequency"]),
                 _g(r["probability"]), _g(100 * r["tail_share"], 2) + " %"]
                for _, r in ds.iterrows()]
        out += _md_table(["run", "block", "state", "annual frequency (/yr)", ty, "tails"],
                         rows)
    return out


def _markdown(manifest, im, n_runs, n_excl, fr, po, images, notes, n_states,
              counts=(), risk=None, site=None, mitigation=None, headings=()) -> str:
    unit = f" ({im['unit']})" if im["unit"] else ""
    src = ("the im column (motions scaled to intensity levels)" if im["column"] == "im"
           else "the PGA of each run as run (no intensity scaling)")
    out = [f"# Campaign report: {manifest.get('name', 'campaign')}", "",
           f"- version: {manifest.get('version', '–')}",
           f"- spec hash: {manifest.get('spec_hash', '–')}",
           f"- runs: {n_runs} ({n_excl} failed numerically, excluded from counts and fits)",
           *(f"- {c}" for c in counts),
           f"- IM: {_im_label(im)}, from {src}", "",
           "## Overturning fragility", "",
           "Lognormal curves P(overturn | IM) = Phi(ln(IM / median) / beta), maximum "
           "likelihood over the runs (stripes, Baker 2015); ± one standard error.", ""]
    by = "mitigation" if "mitigation" in fr.columns else "model"
    for _, f in fr[fr["fit"] == "overturning"].groupby(by, sort=False):
        out += [f"### {_run_name(f.iloc[0].to_dict())}", ""]
        rows = [[_group_name(r.block_name, r._asdict()), _pm(r.median, r.median_se, 3),
                 _pm(r.beta, r.beta_se, 2), str(r.n), str(r.n_exceed), r.note or ""]
                for r in f.itertuples()]
        out += _md_table(["block", f"median{unit}", "beta", "runs", "overturned", "note"],
                         rows)
    for _, f in fr[fr["fit"] == CLEARANCE_FIT].groupby(by, sort=False):
        out += [f"### {_run_name(f.iloc[0].to_dict())}: {CLEARANCE_LABEL}", "",
                "Runs stopped at the isolator's clearance (clearance_exceeded) count as "
                "failures with those that overturned: whether they would have overturned "
                "is not known (rocking.analysis.mitigation, failure='overturned_or_"
                "clearance').", ""]
        rows = [[_group_name(r.block_name, r._asdict()), _pm(r.median, r.median_se, 3),
                 _pm(r.beta, r.beta_se, 2), str(r.n), str(r.n_exceed), r.note or ""]
                for r in f.itertuples()]
        out += _md_table(["block", f"median{unit}", "beta", "runs", "failed", "note"], rows)
    out += list(headings)
    if risk is not None:
        out += _risk_md(risk, site)
    if mitigation is not None:
        out += _mitigation_md(mitigation, im, site)
    out += _by_mitigation(po, unit)
    out += _by_floor(po, unit)
    out += ["## P(overturn) per level", "",
            "Wilson 95% intervals; ratio: median max|theta|/alpha of the survivors; "
            "P(DS>=k) with the manifest's thresholds (the last state is overturning).", ""]
    keys = ["model", *(["mitigation"] if "mitigation" in po.columns else []), "block_name",
            *(["floor"] if "floor" in po.columns else [])]
    for _, d in po.groupby(keys, sort=False):
        out += [f"### {_run_name(d.iloc[0].to_dict())}, "
                f"{_group_name(d['block_name'].iloc[0], d.iloc[0].to_dict())}", ""]
        stops = "n_clearance_exceeded" in d and bool(d["n_clearance_exceeded"].sum())
        rows = [[str(r["level"]), _g(r["im"]), str(r["n"]), str(r["n_overturned"]),
                 *([str(r["n_clearance_exceeded"])] if stops else []),
                 _g(r["p_overturn"]), f"{_g(r['ci_lower'], 2)}–{_g(r['ci_upper'], 2)}",
                 _g(r["median_ratio_survivors"]),
                 *(_g(r[f"p_ds_ge_{s}"], 2) for s in range(1, n_states))]
                for _, r in d.iterrows()]
        if stops:
            out += [f"{int(d['n_clearance_exceeded'].sum())} runs stopped at the isolator's "
                    "clearance (column stopped) count as not overturned: P and its interval "
                    "are not conservative.", ""]
        out += _md_table(["level", f"IM{unit}", "runs", "overturned",
                          *(["stopped"] if stops else []), "P", "95% CI",
                          "ratio", *(f"P(DS>={s})" for s in range(1, n_states))], rows)
    if images:
        out += ["## Figures", ""] + [f"![P(overturn), {m}]({p.name})" for m, p in images]
        out.append("")
    if notes:
        out += ["## Notes", ""] + [f"- {n}" for n in notes] + [""]
    return "\n".join(out)


def _by_heading(ok: pd.DataFrame, key: dict, im: dict, n_boot: int, seed, out: Path,
                title: str):
    """The fit of each heading of one group, its worst heading and the pooled fit by
    record (:func:`rocking.analysis.heading_fragility`): ``(rows, markdown, images)``,
    the rows of ``headings.csv`` (:data:`HEADING_FIT_COLUMNS` after the group's key, and
    one row ``heading_deg`` NaN for all headings)."""
    d = ok[np.isfinite(ok[im["column"]].to_numpy(float)) & (ok[im["column"]] > 0)]
    unit = f" {im['unit']}" if im["unit"] else ""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            hf = heading_fragility(d, im=im["column"], record="motion", n_boot=n_boot,
                                   seed=seed, im_name=im["name"], im_unit=im["unit"] or None)
    except _FIT_ERRORS as e:
        return [], [f"### By heading: {title}", "", f"No fit by heading: {e}", ""], []
    rows = [{**key, **r} for r in hf.table.to_dict("records")]
    pooled = {c: math.nan for c in HEADING_FIT_COLUMNS}
    lo, hi = hf.ci["median"]
    naive = f"{_g(hf.naive_ci[0])}–{_g(hf.naive_ci[1])}"
    pooled.update(n=len(d), n_records=hf.n_records, n_overturned=int(d["overturned"].sum()),
                  median_ci_lower=lo, median_ci_upper=hi, worst=False,
                  note=("all headings; " + (hf.pooled_note or
                                            "the interval of a bootstrap of runs (as if "
                                            f"independent): {naive}")))
    if hf.pooled is not None:
        pooled.update(median=hf.pooled.median, beta=hf.pooled.beta,
                      median_se=hf.pooled.median_se)
    rows.append({**key, **pooled})
    md = [f"### By heading: {title}", "",
          "A lognormal fit per heading (its 95 % interval from a bootstrap of the records); "
          "where a heading's outcomes give no fit, the bounds of its median. The worst "
          "heading has the smallest median.", ""]
    tab = []
    for r in hf.table.itertuples():
        ci = (f" ({_g(r.median_ci_lower)}–{_g(r.median_ci_upper)})"
              if math.isfinite(r.median_ci_lower) else "")
        med = (f"{_g(r.median)}{ci}" if math.isfinite(r.median) else
               f"between {_g(r.median_lower_bound)} and {_g(r.median_upper_bound)}")
        tab.append([f"{r.heading_deg:g}" + (" (worst)" if r.worst else ""), str(r.n),
                    str(r.n_overturned), med,
                    _g(r.beta, 2) if math.isfinite(r.beta) else "–", r.note or ""])
    md += _md_table(["heading (deg)", "runs", "overturned", f"median{unit} (95% CI)",
                     "beta", "note"], tab)
    if hf.pooled is not None and hf.pooled_note:
        md += [f"All headings: median {_g(hf.pooled.median)}{unit}; {hf.pooled_note}.", ""]
    elif hf.pooled is not None:
        md += [f"All headings: median {_g(hf.pooled.median)}{unit}, 95 % interval "
               f"{_g(lo)}–{_g(hi)} from a bootstrap by record ({hf.n_records} records, each "
               f"with its runs at every heading and level); a bootstrap of runs, as if "
               f"they were independent, gives {naive}: too narrow.", ""]
    else:
        md += [hf.pooled_note, ""]
    tail = "".join("_" + _safe(str(key[c])) for c in ("mitigation", "floor") if c in key)
    path = out / f"headings_{_safe(key['model'])}_{_safe(str(key['block_name']))}{tail}.png"
    fig = hf.plot(title=f"{title}: overturning fragility by heading")
    return rows, md, [(f"by heading, {title}", save_figure(fig, path, dpi=DPI))]


def _by_mitigation(po: pd.DataFrame, unit: str) -> list[str]:
    """P(overturn) by mitigation: per (block, floor) a table with a row per level and a
    column per mitigation (none without a mitigation column)."""
    if "mitigation" not in po.columns:
        return []
    out = ["## P(overturn) by mitigation", "",
           "Overturned fraction of each level (rows) for each mitigation (columns), runs "
           "that did not fail numerically; every mitigation ran the same realizations "
           "(common random numbers). The same runs as the per-level tables below." + (
               " \"k stopped\": k runs stopped at the isolator's clearance, counted as not "
               "overturned (their overturning is not known)."
               if "n_clearance_exceeded" in po and po["n_clearance_exceeded"].sum() else ""),
           ""]
    where = [c for c in ("floor", "height_ratio") if c in po.columns]
    names = list(dict.fromkeys(po["mitigation"]))
    for _, d in po.groupby(["block", *where[:1]], sort=False):
        rows = []
        for lv, g in d.groupby("level", sort=True):
            p = {r["mitigation"]: f"{_g(r['p_overturn'])} ({r['n_overturned']}/{r['n']}"
                 + (f"; {r['n_clearance_exceeded']} stopped" if r.get(
                     "n_clearance_exceeded", 0) else "") + ")"
                 for _, r in g.iterrows()}
            rows.append([str(lv), _g(g["im"].median()), *(p.get(m, "–") for m in names)])
        first = d.iloc[0].to_dict()
        out += [f"### {_group_name(first['block_name'], first)}", ""]
        out += _md_table(["level", f"IM{unit}", *names], rows)
    return out


def _by_floor(po: pd.DataFrame, unit: str) -> list[str]:
    """P(overturn) by floor: per (model, block) a table with a row per level and a column
    per floor (none without a floor axis)."""
    if "floor" not in po.columns:
        return []
    out = ["## P(overturn) by floor", "",
           "P(overturn) of each level (rows; the ground motion's IM) on each floor "
           "(columns); the same runs as the per-floor tables below.", ""]
    runs = ["model", *(["mitigation"] if "mitigation" in po.columns else [])]
    for _, d in po.groupby([*runs, "block_name"], sort=False):
        model, name = _run_name(d.iloc[0].to_dict()), d["block_name"].iloc[0]
        floors = d.drop_duplicates("floor").sort_values("floor")
        heads = [_where(r.to_dict()) for _, r in floors.iterrows()]
        rows = []
        for lv, g in d.groupby("level", sort=True):
            p = {int(r["floor"]): _g(r["p_overturn"]) for _, r in g.iterrows()}
            rows.append([str(lv), _g(g["im"].median()),
                         *(p.get(int(f), "–") for f in floors["floor"])])
        out += [f"### {model}, {name}", ""]
        out += _md_table(["level", f"IM{unit}", *heads], rows)
    return out


# --------------------------------------------------------------------------- mitigations

def _compare(t: pd.DataFrame, im: dict, site, manifest: dict, n_boot: int, seed):
    """:func:`rocking.analysis.mitigation.compare_mitigations` of the campaign's runs
    (grouped by block and floor; the site's hazard; the isolators' periods and
    clearances and the building's first period from the manifest): ``(table, note)``,
    ``(None, note)`` when it cannot be made."""
    from ..analysis.mitigation import compare_mitigations

    col, name = im["column"], im["name"]
    tt = t.drop(columns=[c for c in ("mitigation_name",) if c in t.columns])
    if col != name:  # the fits carry the IM's name (checked against the hazard's)
        tt = tt.drop(columns=[name], errors="ignore").rename(columns={col: name})
    iso = {m["name"]: float(m["options"]["isolation_period"])
           for m in manifest.get("mitigations") or ()
           if isinstance(m, dict) and "isolation_period" in (m.get("options") or {})}
    clr = {m["name"]: m["options"]["clearance"] for m in manifest.get("mitigations") or ()
           if isinstance(m, dict) and (m.get("options") or {}).get("clearance") is not None}
    b = manifest.get("building") or {}
    t1 = float(b["periods"][0]) if b.get("periods") else None
    by = [c for c in ("block_name", "floor", "height_ratio") if c in tt.columns]
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            cmp = compare_mitigations(
                tt, im=name, im_unit=im["unit"], by=by,
                hazard=site["curve"] if site is not None else None, n_boot=n_boot,
                seed=seed, t_years=site["t_years"] if site is not None else 50.0,
                building_period=t1, isolation_periods=iso or None, clearance=clr or None)
    except (ParameterError, SimulationError, ValueError) as e:
        return None, f"mitigations not compared: {_line(e)}"
    return cmp.table, ""


def records_fit(manifest: dict, *, stacklevel: int = 3) -> list[str]:
    """The campaign's records checked at the periods that matter (the isolators' periods,
    the building's first period) by :func:`rocking.motions.check_records_fit` (a
    :class:`~rocking.motions.RecordFitWarning` each, and the messages for report.md);
    nothing when there are no such periods or the motions are not records. Called by the
    report and, before any run, by :func:`rocking.campaign.run` and ``rocking campaign run
    --dry-run`` (``manifest``: :func:`~rocking.campaign.store.manifest_for` of the spec)."""
    from ..motions import Record, catalog
    from ..motions.ec8_records import check_records_fit

    why = {f"the isolation period of {m['name']!r}": float(m["options"]["isolation_period"])
           for m in manifest.get("mitigations") or ()
           if isinstance(m, dict) and "isolation_period" in (m.get("options") or {})}
    b = manifest.get("building") or {}
    if b.get("periods"):
        why["the building's first period"] = float(b["periods"][0])
    mo = manifest.get("motions") or {}
    if not why or not isinstance(mo, dict) or "kind" not in mo:
        return []
    params = dict(mo.get("params") or {})
    ctx = catalog.Context(base_dir=Path(manifest.get("spec_dir") or "."))
    try:
        recs = [catalog.build(mo["kind"], ctx, **params, **({mo["sweep"]: v} if mo.get(
            "sweep") else {})) for v in (mo.get("values") or [None])]
    except (ParameterError, OSError, ValueError, TypeError, KeyError):
        return []
    recs = [r for r in recs if isinstance(r, Record)]
    if not recs:
        return []
    ground = params.get("ground") if mo["kind"] == "ec8_earthquake" else None
    st = params.get("spectrum_type", 1) if ground else 1
    return check_records_fit(recs, why, ground=ground, spectrum_type=st,
                             what="the campaign's records", stacklevel=stacklevel)


def _ratio_text(r) -> str:
    """``"2.27 x none's annual frequency"`` (or its median), ``"–"`` without one."""
    af = r.get("annual_frequency_ratio", math.nan)
    if isinstance(af, float) and math.isfinite(af):
        return f"{_g(af)} × the annual frequency"
    m = r.get("median_ratio", math.nan)
    if isinstance(m, float) and math.isfinite(m):
        return f"{_g(m)} × the median"
    return "–"


def _mitigation_md(cmp: pd.DataFrame, im: dict, site) -> list[str]:
    """The section of ``report.md`` that compares the mitigations with "none"."""
    unit = f" {im['unit']}" if im["unit"] else ""
    out = ["## Mitigations compared with none", "",
           "Each mitigation against the block as it stands (\"none\"), group by group "
           "(rocking.analysis.compare_mitigations; failure: overturned, or also the moat "
           "reached for an isolator whose runs stopped there): the ratio of its annual "
           "frequency of failure to none's (with a hazard, else of its median), the verdict, "
           "and for a mitigation that is **worse** the likely reason the runs show.", ""]
    rows = []
    for _, r in cmp.iterrows():
        d = r.to_dict()
        where = _where(d)
        verdict = str(d["verdict"]).upper() if d["verdict"] == "worse" else str(d["verdict"])
        rows.append([str(d["block_name"]) + (f", {where}" if where else ""),
                     str(d["mitigation"]), str(d["failure"]).replace("_", " "),
                     _g(d["annual_frequency"]) if site is not None else _g(d["median"]),
                     _ratio_text(d) if d["verdict"] != "reference" else "1", verdict,
                     d["reason"] or ""])
    out += _md_table(["block", "mitigation", "failure",
                      "annual frequency (/yr)" if site is not None else f"median{unit}",
                      "ratio to none", "verdict", "likely reason"], rows)
    cols = [c for c in cmp.columns if c.startswith("displacement_median_")]
    if cols and cmp["displacement_max"].notna().any():
        periods = [c.removeprefix("displacement_median_") for c in cols]
        out += ["### The isolator's displacement demand", "",
                "At the IM of each return period of the site's hazard: the median and 84th "
                "percentile of the base displacement (m) of the runs, interpolated between "
                "the levels run (no extrapolation: – beyond them; ≥: runs stopped at the "
                "moat, a lower bound), and P(reaching the clearance) there; the annual "
                "frequency of reaching the clearance and its "
                f"probability in {_g(site['t_years'], 6)} years.", ""]
        rows = []
        for _, r in cmp[cmp["displacement_max"].notna()].iterrows():
            d = r.to_dict()
            where = _where(d)
            cells = []
            cap = d["displacement_max"] if d.get("n_clearance_exceeded", 0) else math.inf

            def at_least(v, cap=cap):  # a quantile at the moat: runs stopped there
                return f"≥ {_g(v)}" if math.isfinite(v) and v >= cap * (1 - 1e-9) else _g(v)

            for T in periods:
                cells += [f"{_g(d['im_' + T])}{unit}",
                          f"{at_least(d['displacement_median_' + T])} / "
                          f"{at_least(d['displacement_p84_' + T])}",
                          _g(d["p_clearance_" + T], 2)]
            rows.append([str(d["block_name"]) + (f", {where}" if where else ""),
                         str(d["mitigation"]), *cells,
                         _g(d["clearance_annual_frequency"]),
                         _g(d["clearance_probability"])])
        heads = []
        for T in periods:
            heads += [f"IM {T}", f"median / p84 {T} (m)", f"P(clearance) {T}"]
        out += _md_table(["block", "mitigation", *heads, "clearance reached (/yr)",
                          f"P({_g(site['t_years'], 6)} yr)"], rows)
    return out


def mitigation_lines(result: dict) -> list[str]:
    """The terminal's lines of the comparison of mitigations: per group and mitigation
    its ratio to none and the verdict, a worse one with its likely reason."""
    cmp = result.get("mitigation")
    if cmp is None:
        return []
    lines = []
    for _, r in cmp[cmp["verdict"] != "reference"].iterrows():
        d = r.to_dict()
        where = _where(d)
        head = f"{d['mitigation']} / {d['block_name']}" + (f", {where}" if where else "")
        text = f"{head}: {_ratio_text(d)} of none, {d['verdict']}"
        if d["verdict"] == "worse":
            text = f"{head}: WORSE than none ({_ratio_text(d)} of none): {d['reason']}"
        lines.append(text)
    return lines


# --------------------------------------------------------------------------- public

def report(table: pd.DataFrame, manifest: dict, out, *, n_boot: int = N_BOOT,
           seed: int = 0, hazard=None, t_years=None) -> dict:
    """Write the campaign report of ``table`` (the store's rows) and ``manifest`` to the
    folder ``out`` (created). See the module docstring for the files.

    Returns ``{"files": [Path], "fragility": DataFrame, "p_overturn": DataFrame,
    "notes": [str], "im": {"name", "unit", "column"}, "n_runs": int, "n_excluded": int,
    "run_notes": [str], "run_alerts": [str], "n_theta0_truncated": int,
    "n_unsettled": int}``: ``run_notes`` say how the runs were made and ended (initial
    tilts redrawn, runs still rocking at their end) in ``report.md``, ``run_alerts`` are
    those with a non-zero count (the terminal summary); the counts only for a table with
    the column (``theta0_truncated``, ``settled``).
    With a hazard (the manifest's ``hazard``, from the spec's ``[hazard]``, or ``hazard``:
    a :class:`~rocking.analysis.HazardCurve` or such a record, which replaces it), also
    ``risk.csv`` and ``"risk"`` (a DataFrame, :data:`RISK_COLUMNS` after the group's) and
    ``"hazard"`` (``{"label", "approximate", "t_years", "im_name", "unit", "source",
    "given", "replaces"}``): per group the annual frequency of overturning and of each
    damage state (:func:`rocking.analysis.risk`), its share from the curve's extrapolated
    tails and the probability in ``t_years`` (default: the record's, else 50); for a
    group with runs stopped at an isolator's clearance also of :data:`CLEARANCE_FIT`
    (overturned or clearance reached; see the module docstring).
    Raises :class:`~rocking.ParameterError` for an empty table or a missing column, or a
    hazard of another IM than the table's.
    """
    t, im, thresholds = _check(table, manifest)
    site = _site(manifest, hazard, t_years, im)
    labels = state_labels(thresholds)
    n_states = len(labels)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    failed = t["status"] != 0
    n_excl = int(failed.sum())
    n_lift = int((t["status"] == STATUS_LIFTED_OFF).sum())
    run_lines, run_alerts, run_counts = _run_counts(t)
    notes = []
    if n_excl - n_lift:
        notes.append(f"{n_excl - n_lift} of {len(t)} runs failed numerically (status != 0) "
                     "and are excluded")
    headings = "heading" in t.columns and t["heading"].nunique() > 1
    if headings:
        notes.append(f"the fits pool the {t['heading'].nunique()} headings of every record "
                     "(the outcome at a heading drawn uniformly); the runs of one record at "
                     "several headings are not independent, so the overturning fit's band "
                     "and interval (and its risk interval) come from a bootstrap by record "
                     "(each record with its runs at every heading and level); the "
                     "damage-state curves' bands still treat the runs as independent: "
                     "they are too narrow. headings.csv gives the fit of each heading and "
                     "the worst heading")
    if n_lift:
        notes.append(f"{n_lift} of {len(t)} runs of a planar model left the ground (the "
                     "vertical acceleration exceeded g: lifted_off), which the planar model "
                     "cannot represent; they are neither overturned nor survived and are "
                     "excluded from every count and fit (model='rigid3d' follows the flight)")
    po_parts, fr_rows, pel_rows, by_model, risk_rows = [], [], [], {}, []
    hd_rows, hd_md, hd_images = [], [], []
    any_stopped = bool(_stopped(t[~failed]).any())  # p_overturn.csv: n_clearance_exceeded
    floor = [c for c in ("floor", "height_ratio") if c in t.columns]
    mit = ["mitigation"] if "mitigation" in t.columns else []
    for _, g in t.groupby(["model", *mit, "block", *floor[:1]], sort=False):
        model, block = g["model"].iloc[0], g["block"].iloc[0]
        key = {"model": model, **{c: str(g[c].iloc[0]) for c in mit}, "block": int(block),
               "block_name": str(g["block_name"].iloc[0]),
               **{c: g[c].iloc[0].item() for c in floor}}
        name = _group_name(key["block_name"], key)
        model = _run_name(key)  # with its mitigation, in the notes and the plots
        pt = _p_overturn(g, im["column"], n_states, clearance=any_stopped)
        po_parts.append(pt.assign(**key)[[*key, *pt.columns]])
        ok = g[g["status"] == 0]
        rows, fit, curves, gnotes, clear = _fit_group(ok, im, labels, n_boot, seed,
                                                      by_record=headings)
        if headings:
            hrows, md, img = _by_heading(ok, key, im, n_boot, seed, out,
                                         f"{model}, {name}")
            hd_rows += hrows
            hd_md += md
            hd_images += img
        fr_rows += [{**key, **r} for r in rows]
        if site is not None:
            risk_rows += _risk_rows(key, ok, im, fit, curves, labels, site, clear)
        notes += [f"{model}, {name}: {n}" for n in gnotes]
        notes += [f"{model}, {name}: {r['note']}" for r in rows
                  if r["note"].startswith("no ")]
        if curves is not None:
            ident = f"{_safe(manifest.get('name', 'campaign'))}.{_safe(model)}.{_safe(name)}"
            pel, why = _pelicun(curves, im, ident)
            if pel is not None:
                pel_rows.append(pel)
            elif f"pelicun: {why}" not in notes:
                notes.append(f"pelicun: {why}")
        by_model.setdefault(model, []).append((key, pt, fit, clear))
    po = pd.concat(po_parts, ignore_index=True)
    fr = pd.DataFrame(fr_rows)
    hd = pd.DataFrame(hd_rows) if headings else None
    files = []
    for fname, df in (("p_overturn.csv", po), ("fragility.csv", fr),
                      *((("headings.csv", hd),) if hd is not None and len(hd) else ())):
        with atomic_path(out / fname) as tmp:
            df.to_csv(tmp, index=False, float_format="%.6g")
        files.append(out / fname)
    rk = None
    if site is not None:
        rk = pd.DataFrame(risk_rows)
        keys = [c for c in rk.columns if c not in RISK_COLUMNS]
        rk = rk[[*keys, *RISK_COLUMNS]]
        with atomic_path(out / "risk.csv") as tmp:
            rk.to_csv(tmp, index=False, float_format="%.10g")
        files.append(out / "risk.csv")
        if site["given"]:
            notes.append("hazard given at report time: " + site["curve"].label + (
                f" (replaces the store's [hazard] {site['replaces']!r})" if site["replaces"]
                else ""))
    notes += records_fit(manifest)
    cmp = None
    if mit:
        cmp, why = _compare(t[~failed], im, site, manifest, n_boot, seed)
        if cmp is not None:
            with atomic_path(out / "mitigation.csv") as tmp:
                cmp.to_csv(tmp, index=False, float_format="%.6g")
            files.append(out / "mitigation.csv")
        else:
            notes.append(why)
    if pel_rows:
        with atomic_path(out / "pelicun.csv") as tmp:
            pd.concat(pel_rows).to_csv(tmp, float_format="%.6g")
        files.append(out / "pelicun.csv")
    images = []
    if rk is not None:
        p = _plot_risk(rk, site, out / "risk.png")
        if p is not None:
            images.append(("risk at the site", p))
            files.append(p)
    for model, groups in by_model.items():
        stem = _safe(groups[0][0].get("mitigation", model))
        p = _plot_model(model, groups, im, out / f"p_overturn_{stem}.png",
                        blocks=manifest.get("blocks"))
        images.append((model, p))
        files.append(p)
    images += hd_images
    files += [p for _, p in hd_images]
    md = _markdown(manifest, im, len(t), n_excl, fr, po, images, notes, n_states,
                   counts=run_lines, risk=rk, site=site, mitigation=cmp, headings=hd_md)
    atomic_write(out / "report.md", md)
    files.append(out / "report.md")
    return {"files": files, "fragility": fr, "p_overturn": po, "notes": notes, "im": im,
            "n_runs": len(t), "n_excluded": n_excl, "run_notes": run_lines,
            "run_alerts": run_alerts, **run_counts,
            **({} if cmp is None else {"mitigation": cmp}),
            **({} if hd is None else {"headings": hd}),
            **({} if site is None else {"risk": rk, "hazard": _hazard_info(site)})}


def _hazard_info(site: dict) -> dict:
    c = site["curve"]
    return {"label": c.label, "approximate": c.approximate, "t_years": site["t_years"],
            "im_name": c.im_name, "unit": c.unit, "im_range": (float(c.im[0]),
                                                               float(c.im[-1])),
            "source": site["source"], "given": site["given"], "replaces": site["replaces"]}


def summary_lines(result: dict) -> list[str]:
    """A few lines for the terminal: per model and block the overturning median and beta
    (with units), or why there is no fit; a group with runs stopped at an isolator's
    clearance says how many it counted as survivors, and has a line of
    overturned-or-clearance-reached after it."""
    im = result.get("im", {"name": "IM", "unit": ""})
    unit = f" {im['unit']}" if im.get("unit") else ""
    lines = [f"{result.get('n_runs', '?')} runs ({result.get('n_excluded', 0)} failed, "
             f"excluded); IM: {_im_label(im)}", *result.get("run_alerts", ())]
    fr = result["fragility"]
    for r in fr[fr["fit"] == "overturning"].itertuples():
        head = f"{_run_name(r._asdict())} / {_group_name(r.block_name, r._asdict())}:"
        if math.isfinite(r.median):
            lines.append(f"{head} overturning median {_g(r.median)}{unit} "
                         f"(± {_g(r.median_se, 2)}), beta {_g(r.beta, 2)} "
                         f"(± {_g(r.beta_se, 2)}), {r.n} runs{_stop_part(r.note)}")
        else:
            lines.append(f"{head} {r.note}")
        c = fr[(fr["fit"] == CLEARANCE_FIT) & _same_group(fr, r._asdict())]
        for q in c.itertuples():
            if math.isfinite(q.median):
                lines.append(f"{head} {CLEARANCE_LABEL}: median {_g(q.median)}{unit} "
                             f"(± {_g(q.median_se, 2)}), beta {_g(q.beta, 2)} "
                             f"(± {_g(q.beta_se, 2)}), {q.n_exceed} of {q.n} runs failed")
            else:
                lines.append(f"{head} {q.note}")
    return lines + risk_lines(result) + mitigation_lines(result)


def _interval_part(r) -> str:
    """`` (90 % interval: ... per year, P ...)`` of a risk row, ``""`` without one."""
    lo, hi = r.get("annual_frequency_low", math.nan), r.get("annual_frequency_high", math.nan)
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return ""
    return (f" ({100 * r['interval_level']:.0f} % interval: {_span(lo, hi)} per year, "
            f"probability {_span(r['probability_low'], r['probability_high'])})")


def _stop_part(note) -> str:
    """``"; <the warning>"`` if ``note`` holds :func:`_stopped_note`'s, else ``""``."""
    parts = [p for p in str(note or "").split("; ") if STOPPED in p]
    return f"; {parts[0]}" if parts else ""


def _same_group(df: pd.DataFrame, key: dict) -> pd.Series:
    """The rows of ``df`` of the group (model, mitigation, block, floor) of ``key``."""
    m = pd.Series(True, index=df.index)
    for c in ("model", "mitigation", "block", "floor", "height_ratio"):
        if c in df.columns and c in key:
            m &= df[c] == key[c]
    return m


def risk_lines(result: dict) -> list[str]:
    """The terminal's lines of the risk (none without a hazard): the hazard, then per
    group the annual frequency of overturning and its probability over the service life,
    or why there is no number (with runs stopped at an isolator's clearance: how many it
    counted as survivors, then the line of overturned or clearance reached); an
    approximate hazard says so on every line."""
    rk, hz = result.get("risk"), result.get("hazard")
    if rk is None or hz is None:
        return []
    t = hz["t_years"]
    tag = " [approximate hazard]" if hz["approximate"] else ""
    lines = [f"hazard: {hz['label']} ({hz['im_name']} in {hz['unit']}); service life "
             f"{_g(t, 6)} years" + (f"; {APPROXIMATE}" if hz["approximate"] else "")]
    for _, r in rk[rk["fit"] == "overturning"].iterrows():
        d = r.to_dict()
        head = f"{_run_name(d)} / {_group_name(d['block_name'], d)}:"
        if math.isfinite(r["annual_frequency"]):
            tails = (f" ({_g(100 * r['tail_share'], 2)}% from the extrapolated tails"
                     + (": it rests on that extrapolation" if r["tail_share"] > TAIL_NOTE
                        else "") + ")" if r["tail_share"] >= 0.005 else "")
            lines.append(f"{head} annual frequency of overturning "
                         f"{_g(r['annual_frequency'])} per year, {_g(t, 6)}-year probability "
                         f"{_g(r['probability'])}{_interval_part(r)}{tails}"
                         f"{_stop_part(r['note'])}{tag}")
        else:
            lines.append(f"{head} {r['note']}{tag}")
        for _, q in rk[(rk["fit"] == CLEARANCE_FIT) & _same_group(rk, d)].iterrows():
            if math.isfinite(q["annual_frequency"]):
                tails = (f" ({_g(100 * q['tail_share'], 2)}% from the extrapolated tails"
                         + (": it rests on that extrapolation"
                            if q["tail_share"] > TAIL_NOTE else "") + ")"
                         if q["tail_share"] >= 0.005 else "")
                lines.append(f"{head} {CLEARANCE_LABEL} (runs {STOPPED} count as "
                             f"failures): annual frequency {_g(q['annual_frequency'])} per "
                             f"year, {_g(t, 6)}-year probability {_g(q['probability'])}"
                             f"{_interval_part(q)}{tails}{tag}")
            else:
                lines.append(f"{head} {CLEARANCE_LABEL} (runs {STOPPED} count as "
                             f"failures): {q['note']}{tag}")
    return lines


__all__ = ["report", "summary_lines", "risk_lines", "mitigation_lines", "REQUIRED_COLUMNS",
           "PELICUN_DEMAND",
           "RISK_COLUMNS", "CLEARANCE_FIT", "CLEARANCE_LABEL"]
