r"""Records that fit EN 1998-1 on a ground type, and the check that a study's records fit
the periods that matter (issue 31).

The paper's set (:func:`~rocking.motions.seed_earthquakes`) matches the paper's target
(TC = 0.3 s, TD = 1.2 s, :func:`~rocking.motions.ec8.paper_target`): beyond 1.2 s its
spectrum falls as ``1/T^2`` from a short corner, 3 times below EN 1998-1 Type 1 on ground C
at 2.5 s. An isolator (periods of 2-4 s) or a flexible building sized with it is sized on a
third of the displacement the standard asks for.

**The EC8 sets** (:func:`ec8_earthquakes`): for each ground type A-E and spectrum type 1 or
2, :data:`EC8_COUNT` synthetic records (:func:`~rocking.motions.synthetic`: random-phase
sum of sinusoids, Jennings envelope of 2 s rise and 10 s stationary part, iterative
spectral matching) of :data:`EC8_DURATION` s at 100 Hz, matched to the EN 1998-1 elastic
spectrum (5 % damping, :func:`~rocking.motions.ec8_spectrum`) with ``ag`` =
:data:`EC8_AG` (0.25 g) from 0.05 s to :data:`EC8_PERIOD_RANGE`\ [1] = 4 s (the periods of
isolators), seed :data:`EC8_SEED` and the set's index (so each set is its own
realisation). They are made once (a few seconds) and cached in memory and on disk
(:func:`~rocking.motions.synthetic.cache_dir`), a cache keyed by the settings and a digest
of the generating code. In a campaign: ``kind = "ec8_earthquake"``, ``ground = "C"``,
``number = [1, 2, ...]``.

**The check** (:func:`check_records_fit`): records are scaled to intensity levels of PGA
(or by load factors), so what matters is the shape of their spectrum, ``Sa(T) / PGA``.
The mean over the records of each one's 5 %-damped ``Sa(T) / PGA`` is compared with the
target's ``Se(T) / Se(0)`` at the periods that matter (an isolator's period, a building's
first period): more than 10 % below (EN 1998-1 3.2.3.1.2(4)'s tolerance) gives a
:class:`RecordFitWarning` that names the period, why it matters and the shortfall. The
target: EN 1998-1 on the ground type given; without one, Type 1 on ground A, the least
demanding Type 1 shape beyond TC (``2.5 TC TD / T^2``: 2.0 for A against 2.5-4.0 for
B-E), so that records below it understate every Type 1 site.
"""

from __future__ import annotations

import hashlib
import warnings
from pathlib import Path

import numpy as np

from ..errors import ParameterError
from ..units import G
from .ec8 import DesignSpectrum, ec8_parameters, ec8_spectrum
from .records import Record
from .spectra import response_spectrum
from .synthetic import GEN_VERSION, Envelope, cache_dir, save_set, synthetic

__all__ = ["ec8_earthquakes", "ec8_earthquake", "check_records_fit", "spectral_shape_ratio",
           "RecordFitWarning", "EC8_COUNT", "EC8_AG", "EC8_SEED", "EC8_PERIOD_RANGE",
           "EC8_DURATION", "FIT_TOLERANCE"]

EC8_COUNT = 10
"""Records per set (EN 1998-1 4.3.3.4.3: 7 or more to use the mean response)."""
EC8_AG = 0.25 * G
"""Design ground acceleration of the sets, m/s^2 (0.25 g on type A ground; the PGA is
``ag S``). Campaigns scale the records to their own levels."""
EC8_SEED = 1998
"""Seed of the sets (EN 1998): set (ground, type) uses ``EC8_SEED + 10 type + index``."""
EC8_PERIOD_RANGE = (0.05, 4.0)
"""Periods (s) over which the sets match the spectrum: rocking blocks, floors, isolators."""
EC8_DURATION = 25.0
"""Length of the records (s): 2 s rise, 10 s stationary, decay to the end."""
FIT_TOLERANCE = 0.10
"""A mean spectrum more than this fraction below the target is flagged (EN 1998-1
3.2.3.1.2(4): nowhere below 90 % of the target)."""

_MEMORY: dict[str, tuple[Record, ...]] = {}


class RecordFitWarning(UserWarning):
    """The records of a study fall below the target spectrum at a period that matters
    (:func:`check_records_fit`).

    Examples
    --------
    >>> import warnings
    >>> from rocking.motions import RecordFitWarning, seed_earthquakes, check_records_fit
    >>> with warnings.catch_warnings(record=True) as w:
    ...     warnings.simplefilter("always")
    ...     _ = check_records_fit(seed_earthquakes()[:7], {"an isolator": 3.0}, ground="C")
    >>> w[0].category is RecordFitWarning, issubclass(RecordFitWarning, UserWarning)
    (True, True)
    """


def _set(ground, spectrum_type) -> tuple[str, int]:
    prm = ec8_parameters(ground, spectrum_type)  # checks both
    del prm
    return str(ground).strip().upper(), int(str(spectrum_type).strip())


def _target(ground: str, st: int) -> DesignSpectrum:
    return DesignSpectrum.ec8(EC8_AG, ground, st)


def _key(ground: str, st: int) -> str:
    here = Path(__file__).resolve().parent
    h = hashlib.sha1(repr((GEN_VERSION, ground, st, EC8_COUNT, EC8_AG, EC8_SEED,
                           EC8_PERIOD_RANGE, EC8_DURATION)).encode())
    for name in ("ec8_records.py", "synthetic.py", "spectra.py", "processing.py", "ec8.py"):
        try:
            h.update((here / name).read_bytes())
        except OSError:  # pragma: no cover - a zipped install
            h.update(name.encode())
    return h.hexdigest()[:16]


def _generate(ground: str, st: int) -> tuple[Record, ...]:
    seed = EC8_SEED + 10 * st + "ABCDE".index(ground)
    env = Envelope(rise=2.0, stationary=10.0, duration=EC8_DURATION)
    recs = synthetic(_target(ground, st), n=EC8_COUNT, seed=seed, envelope=env,
                     period_range=EC8_PERIOD_RANGE)
    out = []
    for r in recs:
        meta = {**r.meta, "ground": ground, "spectrum_type": st,
                "set": f"EN 1998-1 Type {st}, ground {ground}"}
        out.append(Record(r.acc, r.dt, name=f"EC8 type {st} ground {ground} earthquake "
                          f"{r.number}", number=r.number, meta=meta))
    return tuple(out)


def _cache_file(ground: str, st: int) -> Path:
    return cache_dir() / f"ec8_type{st}_{ground}_v{GEN_VERSION}_{_key(ground, st)}.npz"


def _save(records, path: Path, key: str) -> None:
    """Write the set atomically (:func:`rocking.motions.synthetic.save_set`)."""
    save_set(records, path, key)


def _load(path: Path, key: str, ground: str, st: int) -> tuple[Record, ...] | None:
    try:
        with np.load(path, allow_pickle=False) as z:
            if str(z["key"]) != key:
                return None
            acc, dt = z["acc"], float(z["dt"])
            err, fac = z["match_error"], z["pga_factor"]
    except (OSError, ValueError, KeyError, EOFError):
        return None
    if acc.shape[0] != EC8_COUNT or not np.all(np.isfinite(acc)):
        return None
    t = _target(ground, st)
    return tuple(Record(acc[i], dt, name=f"EC8 type {st} ground {ground} earthquake {i + 1}",
                        number=i + 1, meta={
                            "generator": f"rocking.motions.synthetic v{GEN_VERSION}",
                            "target": t.describe(), "ground": ground, "spectrum_type": st,
                            "set": f"EN 1998-1 Type {st}, ground {ground}",
                            "match_error": float(err[i]), "pga_factor": float(fac[i]),
                            "damping": 0.05, "period_range": EC8_PERIOD_RANGE,
                            "units": "m/s^2"})
                 for i in range(acc.shape[0]))


def ec8_earthquakes(ground: str = "C", spectrum_type: int = 1, *,
                    use_cache: bool = True) -> list[Record]:
    """The :data:`EC8_COUNT` synthetic records compatible with EN 1998-1's elastic spectrum
    of ``spectrum_type`` (1: large earthquakes, 2: magnitude below about 5.5) on ground
    type ``ground`` (A-E), 5 % damping, ``ag`` = :data:`EC8_AG`, from 0.05 to 4 s (see
    the module doc). Numbered 1 to :data:`EC8_COUNT`, m/s^2, ``dt`` = 0.01 s.

    Examples
    --------
    >>> import numpy as np
    >>> from rocking.motions import ec8_earthquakes, ec8_spectrum, response_spectrum
    >>> recs = ec8_earthquakes("C")
    >>> len(recs), recs[0].number, round(recs[0].duration, 1)
    (10, 1, 25.0)
    >>> sa = np.mean([response_spectrum(r, 2.5, damping=0.10) for r in recs])
    >>> target = ec8_spectrum(2.5, 0.25 * 9.80665, "C", 1, damping=0.10)
    >>> bool(abs(sa / target - 1) < 0.10)  # an isolator's period, 10 % damping
    True
    """
    ground, st = _set(ground, spectrum_type)
    if not use_cache:
        return list(_generate(ground, st))
    key = _key(ground, st)
    recs = _MEMORY.get(key)
    if recs is None:
        path = _cache_file(ground, st)
        recs = _load(path, key, ground, st) if path.exists() else None
        if recs is None:
            recs = _generate(ground, st)
            _save(recs, path, key)
        _MEMORY[key] = recs
    return list(recs)


def ec8_earthquake(number, ground: str = "C", spectrum_type: int = 1) -> Record:
    """Record ``number`` (1 to :data:`EC8_COUNT`) of :func:`ec8_earthquakes`.

    Examples
    --------
    >>> from rocking.motions import ec8_earthquake
    >>> ec8_earthquake(3, "D").name
    'EC8 type 1 ground D earthquake 3'
    """
    try:
        k = int(number)
        ok = k == number and not isinstance(number, bool)
    except (TypeError, ValueError):
        ok = False
    if not ok or not 1 <= k <= EC8_COUNT:
        raise ParameterError(f"number must be an integer from 1 to {EC8_COUNT}, got "
                             f"{number!r}")
    return ec8_earthquakes(ground, spectrum_type)[k - 1]


# ----------------------------------------------------------------------------- the check

def _target_shape(periods, ground, spectrum_type):
    g = "A" if ground is None else ground
    st = 1 if spectrum_type is None else spectrum_type
    return (np.asarray(ec8_spectrum(periods, 1.0, g, st), dtype=float)
            / ec8_spectrum(0.0, 1.0, g, st))


def spectral_shape_ratio(records, periods, *, ground=None, spectrum_type=1,
                         damping: float = 0.05) -> np.ndarray:
    """At each period, the mean over ``records`` of ``Sa(T) / PGA`` (``damping``-damped
    pseudo-acceleration) over the target's ``Se(T) / Se(0)`` (EN 1998-1, ``spectrum_type``,
    ``ground``; without a ground, Type 1 on A: the least demanding Type 1 shape).

    Examples
    --------
    >>> from rocking.motions import seed_earthquakes
    >>> from rocking.motions.ec8_records import spectral_shape_ratio
    >>> r = spectral_shape_ratio(seed_earthquakes()[:10], [0.2, 2.5], ground="C")
    >>> bool(r[0] > 0.9), bool(r[1] < 0.5)  # the paper's set: short TC and TD
    (True, True)
    """
    recs = list(records)
    if not recs:
        raise ParameterError("records: no record to check")
    T = np.atleast_1d(np.asarray(periods, dtype=float))
    if not np.all(np.isfinite(T)) or np.any(T <= 0):
        raise ParameterError(f"periods must be periods > 0 (s), got {periods!r}")
    shapes = [np.asarray(response_spectrum(r, T, damping=damping), dtype=float) / r.pga
              for r in recs]
    return np.mean(shapes, axis=0) / _target_shape(T, ground, spectrum_type)


def check_records_fit(records, periods: dict, *, ground=None, spectrum_type=1,
                      tolerance: float = FIT_TOLERANCE, what: str = "records",
                      stacklevel: int = 2) -> list[str]:
    """Warn (:class:`RecordFitWarning`) where the mean 5 %-damped spectral shape of
    ``records`` (:func:`spectral_shape_ratio`) falls more than ``tolerance`` below the
    target's at a period that matters. ``periods``: ``{why: period (s)}``, e.g.
    ``{"the isolator's period": 2.5, "the building's first period": 0.5}``. Returns the
    messages (one per period short of the target; none: they fit).

    Examples
    --------
    >>> import warnings
    >>> from rocking.motions import ec8_earthquakes, seed_earthquakes
    >>> from rocking.motions.ec8_records import check_records_fit
    >>> with warnings.catch_warnings(record=True) as w:
    ...     warnings.simplefilter("always")
    ...     msgs = check_records_fit(seed_earthquakes()[:10], {"the isolator's period": 2.5})
    >>> len(msgs), len(w), "below EN 1998-1 Type 1, ground A" in msgs[0]
    (1, 1, True)
    >>> check_records_fit(ec8_earthquakes("C"), {"the isolator's period": 2.5}, ground="C")
    []
    """
    if not isinstance(periods, dict) or not periods:
        raise ParameterError("periods must be a dict {why: period (s)}, e.g. "
                             "{\"the isolator's period\": 2.5}")
    recs = list(records)
    names = list(periods)
    T = np.array([float(periods[k]) for k in names])
    ratio = spectral_shape_ratio(recs, T, ground=ground, spectrum_type=spectrum_type)
    target = (f"EN 1998-1 Type {spectrum_type}, ground {ground}" if ground is not None
              else "EN 1998-1 Type 1, ground A (the least demanding Type 1 shape; give the "
                   "site's ground type)")
    msgs = []
    for name, t, r in zip(names, T, ratio, strict=True):
        if r < 1.0 - tolerance:
            msgs.append(
                f"{what}: at {t:g} s ({name}) the mean 5 %-damped spectrum of the "
                f"{len(recs)} records, scaled to the same PGA, is {100 * (1 - r):.0f} % "
                f"below {target}: they understate the demand there (an isolator's "
                "displacement, a floor's motion); use records that fit the site, e.g. "
                "rocking.motions.ec8_earthquakes(ground=...) (motions kind "
                "'ec8_earthquake')")
    for m in msgs:
        warnings.warn(m, RecordFitWarning, stacklevel=stacklevel + 1)
    return msgs
