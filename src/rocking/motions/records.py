"""Sampled accelerograms.

A :class:`Record` holds a ground acceleration ``acc`` (m/s^2) sampled every ``dt`` seconds
from ``t = 0``. Between samples the acceleration is linear; after the last sample it is
zero. ``Record.from_file`` reads PEER NGA ``.AT2`` files and plain or CSV columns (see
:mod:`rocking.motions.io`) and :func:`load_builtin` the records shipped with the package.

The processing and spectrum methods call the array functions of
:mod:`rocking.motions.processing` and :mod:`rocking.motions.spectra` (which do not import
this module: dependencies point from ``Record`` to them).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .._validate import as_float, positive, warn_implausible
from ..errors import RecordError
from ..units import G
from . import _kernel as K
from .base import Motion
from .io import read_builtin, read_record
from .processing import (
    bandpass,
    baseline_correct,
    integrate,
    intensity_measures_acc,
    resample,
)
from .spectra import response_spectrum

__all__ = ["Record", "sample", "load_builtin"]


@dataclass(frozen=True, eq=False)
class Record(Motion):
    """A sampled accelerogram: ``acc`` in m/s^2, time step ``dt`` in s.

    A PGA above 5 g (before the load factor) or a time step above 0.1 s is valid but
    most likely a unit mistake: it gives a one-line
    :class:`~rocking._validate.PlausibilityWarning`.

    Examples
    --------
    >>> from rocking.motions import Record, load_builtin
    >>> rec = load_builtin("RSN126_GAZLI_GAZ000")  # Gazli 1976, PEER NGA
    >>> rec.dt, len(rec), round(rec.duration, 4)  # duration = (npts - 1) dt
    (0.0066, 2048, 13.5102)
    >>> r = Record(np.array([0.0, 1.0, -2.0, 0.5]), dt=0.01, name="toy", scale=0.5)
    >>> r.pga, r.values.tolist()  # the load factor applied
    (1.0, [0.0, 0.5, -1.0, 0.25])
    >>> r.pgv == float(np.max(np.abs(r.velocity()))), r.duration  # from rest; (n - 1) dt
    (True, 0.03)
    """

    acc: np.ndarray
    dt: float
    name: str = ""
    number: int | None = None
    scale: float = 1.0
    meta: dict = field(default_factory=dict, repr=False)
    kind = K.RECORD

    def __post_init__(self):
        try:
            acc = np.array(self.acc, dtype=np.float64)
        except (TypeError, ValueError):
            raise RecordError("acc must be a 1-D array of numbers (m/s^2)") from None
        if acc.ndim != 1:
            raise RecordError(f"acc must be a 1-D array, got shape {acc.shape}")
        if acc.size < 2:
            raise RecordError(f"a record needs at least 2 samples, got {acc.size}")
        bad = np.flatnonzero(~np.isfinite(acc))
        if bad.size:
            raise RecordError(f"acc has a non-finite value (NaN or inf) at sample {bad[0]}")
        acc.setflags(write=False)
        object.__setattr__(self, "acc", acc)
        object.__setattr__(self, "dt", positive("dt", self.dt, "s"))
        object.__setattr__(self, "scale", as_float("scale", self.scale))
        _check_plausible(acc, self.dt, self.name)

    @classmethod
    def from_file(cls, path, units: str = "g", dt: float | None = None, **kw) -> Record:
        """Read a record from ``path``.

        Formats, recognised by content: PEER NGA ``.AT2``; ESM ASCII, COSMOS Volume 2 and
        K-NET / KiK-net ASCII files as downloaded (:mod:`rocking.motions.formats`); CSV or
        whitespace columns with either time and acceleration (uniform steps) or one
        acceleration column plus ``dt``. ``units`` is one of ``g``, ``m/s^2``, ``cm/s^2``
        (``gal``) and applies to the acceleration column; a unit the file states must
        agree with it (``units=None``: the file's own, g if it states none; see
        :mod:`rocking.motions.io`). The record is stored in m/s^2.

        Examples
        --------
        >>> from rocking.motions import Record
        >>> np.savetxt("acc.txt", [0.0, 0.1, -0.2, 0.05])  # one column, in g
        >>> rec = Record.from_file("acc.txt", units="g", dt=0.01)
        >>> rec.name, rec.dt, len(rec), round(rec.pga, 5)  # 0.2 g in m/s^2
        ('acc', 0.01, 4, 1.96133)
        """
        return cls._from_read(*read_record(path, units=units, dt=dt), **kw)

    @classmethod
    def _from_read(cls, acc, step, meta: dict, **kw) -> Record:
        """A record from what :mod:`rocking.motions.io` reads: ``(acc, dt, meta)``."""
        kw.setdefault("name", meta.pop("name", ""))
        return cls(acc, step, meta=meta, **kw)

    # ---- Motion interface
    @property
    def duration(self) -> float:
        """Time of the last sample (s)."""
        return (self.acc.size - 1) * self.dt

    def _params(self):
        return (self.dt, float(self.acc.size))

    def _samples(self):
        return self.acc

    @property
    def scan_step(self) -> float:
        return self.dt

    @property
    def quiet_time(self) -> float:
        return self.duration

    # ---- conveniences
    @property
    def t(self) -> np.ndarray:
        """Sample times (s)."""
        return np.arange(self.acc.size) * self.dt

    @property
    def values(self) -> np.ndarray:
        """Samples with the load factor applied (m/s^2)."""
        return self.acc * self.scale

    @property
    def pga(self) -> float:
        """Peak ground acceleration (m/s^2): the largest ``|value|``."""
        return float(np.max(np.abs(self.values)))

    @property
    def pgv(self) -> float:
        """Peak ground velocity (m/s): the largest ``|v|`` at the samples of the velocity
        from rest (:meth:`velocity`; ``intensity_measures()["pgv"]``)."""
        return float(np.max(np.abs(self.velocity())))

    # ---- processing (see rocking.motions.processing)
    def resampled(self, dt: float, method: str = "auto") -> Record:
        """A copy resampled to time step ``dt`` (s); see :func:`~.processing.resample`.

        Examples
        --------
        >>> from rocking.motions import load_builtin, resample
        >>> rec = load_builtin("RSN126_GAZLI_GAZ000")  # dt = 0.0066 s
        >>> r = rec.resampled(0.01)
        >>> r.dt, r.meta["processing"]
        (0.01, ['resample 0.0066 s -> 0.01 s (polyphase, up 33 / down 50)'])
        >>> bool(np.array_equal(r.values, resample(rec, 0.01).values))  # the same
        True
        >>> T = [0.5, 1.0, 2.0]  # the spectrum well below the new Nyquist frequency is kept
        >>> np.round(r.response_spectrum(T) / rec.response_spectrum(T), 3).tolist()
        [1.0, 1.0, 1.0]
        """
        return resample(self, dt, method=method)

    def filtered(self, low: float | None = 0.1, high: float | None = None, order: int = 4,
                 keep_pads: bool = False) -> Record:
        """Zero-phase Butterworth filtered copy; see :func:`~.processing.bandpass`.

        Examples
        --------
        >>> from rocking.motions import bandpass, load_builtin
        >>> rec = load_builtin("RSN126_GAZLI_GAZ000")
        >>> f = rec.filtered(low=0.1)  # 0.1 Hz high-pass
        >>> bool(np.array_equal(f.values, bandpass(rec, low=0.1).values)), len(f) == len(rec)
        (True, True)
        >>> T = [0.2, 1.0]  # periods well below 1 / 0.1 Hz hardly change
        >>> np.round(f.response_spectrum(T) / rec.response_spectrum(T), 2).tolist()
        [1.0, 1.0]
        """
        return bandpass(self, low=low, high=high, order=order, keep_pads=keep_pads)

    def baseline_corrected(self) -> Record:
        """Copy with zero final velocity and displacement; see
        :func:`~.processing.baseline_correct`.

        Examples
        --------
        >>> from rocking.motions import baseline_correct, load_builtin
        >>> rec = load_builtin("RSN126_GAZLI_GAZ000")
        >>> b = rec.baseline_corrected()
        >>> bool(abs(b.velocity()[-1]) < 1e-12 and abs(b.displacement()[-1]) < 1e-12)
        True
        >>> bool(np.array_equal(b.values, baseline_correct(rec).values))
        True
        """
        return baseline_correct(self)

    def velocity(self) -> np.ndarray:
        """Ground velocity (m/s) at the samples, from rest, load factor applied.

        Examples
        --------
        >>> from rocking.motions import Record
        >>> rec = Record(np.full(101, 2.0), dt=0.01, scale=0.5)  # 1 m/s^2 for 1 s
        >>> v = rec.velocity()
        >>> round(float(v[50]), 10), round(float(v[-1]), 10)  # v = a t
        (0.5, 1.0)
        """
        return integrate(self.values, self.dt)[0]

    def displacement(self) -> np.ndarray:
        """Ground displacement (m) at the samples, from rest, load factor applied.

        Examples
        --------
        >>> from rocking.motions import Record
        >>> rec = Record(np.full(101, 2.0), dt=0.01, scale=0.5)  # 1 m/s^2 for 1 s
        >>> d = rec.displacement()
        >>> round(float(d[50]), 10), round(float(d[-1]), 10)  # d = a t^2 / 2
        (0.125, 0.5)
        """
        return integrate(self.values, self.dt)[1]

    def intensity_measures(self, block=None) -> dict:
        """PGA, PGV, PGD, Arias intensity, D5-95... (with a ``block``, also ``pga_ratio``
        and ``pgv_ratio``); see :func:`~.processing.intensity_measures`.

        Examples
        --------
        >>> import math
        >>> import rocking
        >>> from rocking.motions import load_builtin
        >>> rec = load_builtin("RSN126_GAZLI_GAZ000")
        >>> block = rocking.Block.rectangular(0.2, 1.0)
        >>> im = rec.intensity_measures(block=block)
        >>> im["pga"] == rec.pga, im["npts"], bool(im["t5"] < im["t95"] <= im["duration"])
        (True, 2048, True)
        >>> round(im["pga_ratio"], 4), round(rec.pga / (rocking.G * math.tan(block.alpha)), 4)
        (3.5085, 3.5085)
        """
        return intensity_measures_acc(self.values, self.dt, block=block)

    def response_spectrum(self, periods, damping: float = 0.05, kind: str = "psa"):
        """Elastic response spectrum; see :func:`~.spectra.response_spectrum`.

        Examples
        --------
        >>> from rocking.motions import load_builtin, response_spectrum
        >>> rec = load_builtin("RSN126_GAZLI_GAZ000")
        >>> T = [0.0, 0.5, 1.0]
        >>> bool(np.array_equal(rec.response_spectrum(T), response_spectrum(rec, T)))
        True
        >>> round(rec.response_spectrum(0.0), 6) == round(rec.pga, 6)  # T = 0: the PGA
        True
        >>> sa, sd = rec.response_spectrum(1.0), rec.response_spectrum(1.0, kind="sd")
        >>> round(sa / sd, 6) == round((2 * np.pi) ** 2, 6)  # psa = omega^2 sd
        True
        """
        return response_spectrum(self, periods, damping=damping, kind=kind)

    def __len__(self) -> int:
        return self.acc.size

    def __repr__(self) -> str:
        nm = f"{self.name!r}, " if self.name else ""
        sc = f", scale={self.scale:g}" if self.scale != 1.0 else ""
        return f"Record({nm}n={self.acc.size}, dt={self.dt:g} s, pga={self.pga:.3f} m/s^2{sc})"


PLAUSIBLE_PGA = 5.0 * G
"""A record whose PGA (m/s^2, before the load factor) is above this gets a warning."""
PLAUSIBLE_DT = 0.1
"""A record whose time step (s) is above this gets a warning."""


def _check_plausible(acc: np.ndarray, dt: float, name: str) -> None:
    """Warn (:class:`~rocking._validate.PlausibilityWarning`) on a PGA above 5 g or a time
    step above 0.1 s: valid, but most likely a unit mistake."""
    what = f"record {name!r}" if name else "record"
    pga = float(np.max(np.abs(acc)))
    if pga > PLAUSIBLE_PGA:
        warn_implausible(f"{what}: PGA {pga / G:.3g} g is above 5 g; check the units "
                         "(acc is in m/s^2; a file in cm/s^2 or gal needs units='cm/s^2')")
    if dt > PLAUSIBLE_DT:
        warn_implausible(f"{what}: time step {dt:g} s is above 0.1 s; check that dt is in "
                         "seconds")


def sample(motion: Motion, dt: float, duration: float | None = None) -> Record:
    """Sample any motion on a uniform grid of step ``dt`` into a :class:`Record`.

    Examples
    --------
    >>> from rocking.motions import Sine, sample
    >>> r = sample(Sine(freq=2.0, amplitude=0.01, duration=5.0), dt=0.005)
    >>> len(r), r.dt, round(r.pga, 4)  # a sample at t = 1/(4 f) hits X (2 pi f)^2
    (1001, 0.005, 1.5791)
    """
    dt = positive("dt", dt, "s")
    dur = motion.duration if duration is None else positive("duration", duration, "s")
    t = np.arange(int(round(dur / dt)) + 1) * dt
    return Record(motion.acceleration(t), dt, name=type(motion).__name__)


def load_builtin(name: str) -> Record:
    """A record shipped with the package, by name (see
    :func:`~rocking.motions.io.builtin_records`).

    ``name`` is the file stem (``"RSN982_NORTHR_JEN292"``), optionally with ``.AT2``, or
    an unambiguous leading part of it such as ``"RSN982"``; case is ignored.

    Examples
    --------
    >>> from rocking.motions import load_builtin
    >>> rec = load_builtin("RSN126")  # an unambiguous leading part of the name
    >>> rec.name, rec.dt, len(rec)
    ('RSN126_GAZLI_GAZ000', 0.0066, 2048)
    >>> round(rec.pga / 9.80665, 3)  # PGA in g
    0.702
    """
    return Record._from_read(*read_builtin(name))
