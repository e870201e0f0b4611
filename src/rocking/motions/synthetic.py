r"""Synthetic spectrum-compatible accelerograms, and the paper's set of 30 earthquakes.

Peña et al. (2007, Section 3.3) drove their blocks with 30 synthetic earthquakes compatible
with a Eurocode 8 design spectrum (plateau 0.1-0.3 s at 7 m/s^2, PGA 2.8 m/s^2), numbered by
generation. Their records are not published; :func:`seed_earthquakes` makes a set of our
own with the same target (:func:`~rocking.motions.ec8.paper_target`), numbered 1-30, from a
fixed seed. Only statistics can be compared with the paper's: our record 20 is not theirs.

**Generation** (:func:`synthetic`), for each record number ``k`` with its own random stream
``numpy.random.default_rng([seed, k])`` (so a record does not depend on how many others are
made):

1. *Stationary random-phase sum of sinusoids* (Gasparini & Vanmarcke's SIMQKE):
   ``x(t) = sum_j A_j sin(2 pi f_j t + phi_j)`` with independent uniform phases, on the
   frequencies of an FFT grid 4 times longer than the record (spacing ~0.012 Hz), limited
   to the band ``0.8 / T_max`` to ``1 / T_min`` of the control periods (0.2-25 Hz by
   default). The initial amplitudes follow the target: ``A_j ~ Sa(1/f_j) / sqrt(f_j)``.
2. *Envelope*: ``a(t) = I(t) x(t)`` with a Jennings-type (default) or trapezoidal
   :class:`Envelope`: rise over ``rise`` s, a stationary part of ``stationary`` s (EC8
   asks for at least 10 s), decay to zero at the end.
3. *Baseline correction* so that the table velocity and displacement return to zero
   (:func:`~rocking.motions.processing.baseline_correct`), at every iteration, so that
   the spectral correction sees the record as it will be used.
4. *Iterative spectral correction* on 120 control periods (log-spaced from ``0.8 T_lo``
   to ``1.33 T_hi`` of the period range): the stationary amplitudes are multiplied by the
   ratio target / computed 5 %-damped pseudo-acceleration, interpolated in log frequency
   (8 iterations); then the same correction is applied to the Fourier amplitudes of the
   enveloped record itself, keeping its phases (and its time-varying character), with a
   0.25 s cosine taper at both ends and a high-pass that removes the content below half
   the band's lowest frequency (sin^2 ramp; without it the table displacement of some
   records reached 0.4 m, with it the set's PGD is ~4 cm on average, 8 cm at most), for
   up to 40 iterations, stopping when every control period is within ``tolerance``. The
   iterate with the smallest largest deviation over the period range is kept.
5. *Peak ground acceleration*: if the mean PGA of the records made in one call is below
   the target's zero-period value, all of them are scaled up by the same factor (recorded
   as ``meta["pga_factor"]``), so that the set meets EC8's zero-period condition. Only
   then does a record depend on the others made with it (for the paper's set the
   factor is 1: its mean PGA already exceeds 2.8 m/s^2). Individual PGAs scatter around
   the target (the spectrum is matched from 0.04 s up, not at ``T = 0``).

**Compatibility** (EN 1998-1 §3.2.3.1.2), checked by :func:`check_compatibility`: a
stationary part of at least 10 s; the mean PGA (zero-period spectral value) at least the
target's; the mean 5 %-damped spectrum of the set nowhere below 90 % of the target over the
period range that matters, which EC8 sets to 0.2 T1-2 T1 for a building of period T1. A
rocking block has no fixed period, so we take :data:`PERIOD_RANGE` = 0.05-3 s: the
free-rocking period ``(4/p) arccosh(1 / (1 - theta0/alpha))`` of the paper's specimens 2-4
(p = 3.6-5.0 1/s) spans 0.26-2.5 s for amplitudes ``theta0`` from 5 % to 80 % of
``alpha``, and the uplift of a block from rest is governed by peak accelerations,
i.e. short periods, down to 0.05 s (20 Hz) and below.

**The paper's set** (:func:`seed_earthquakes`): 30 records of 20 s at 100 Hz (Jennings
envelope: 2 s rise, 10 s stationary, 8 s decay), seed :data:`PAPER_SEED`. They are made
once and cached in memory and on disk (``$ROCKING_CACHE_DIR``, else
``$XDG_CACHE_HOME/rocking``, else ``~/.cache/rocking``); generation is deterministic from
the seed, so the cache is only a speed-up.
"""

from __future__ import annotations

import hashlib
import math
import os
import tempfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .._validate import as_float, in_range, positive
from ..errors import ParameterError
from .ec8 import DesignSpectrum, paper_target
from .processing import baseline_operator
from .records import Record
from .spectra import peak_responses, response_spectrum

__all__ = ["Envelope", "synthetic", "seed_earthquakes", "paper_earthquake",
           "earthquake_motion", "check_compatibility", "Compatibility", "cache_dir",
           "clear_cache", "PAPER_SEED", "PAPER_COUNT", "PERIOD_RANGE", "GEN_VERSION"]

PAPER_SEED = 2007
"""Seed of the paper's set (the year of the paper)."""
PAPER_COUNT = 30
PERIOD_RANGE = (0.05, 3.0)
"""Periods (s) over which the set must match the target (see the module doc)."""
GEN_VERSION = 1
"""Version of the generation algorithm. The cache key holds it, the settings and a digest of
the generating source files, so a cached set is never stale."""

N_CONTROL = 120
STAGE1_ITERATIONS = 8
STAGE2_ITERATIONS = 40
TOLERANCE = 0.05
FFT_FACTOR = 4
END_TAPER = 0.25  # s
ENVELOPES = ("jennings", "trapezoidal")


# ----------------------------------------------------------------------------- envelope
@dataclass(frozen=True)
class Envelope:
    """Amplitude envelope ``I(t)`` of a synthetic record (0 at both ends, 1 when stationary).

    ``kind="jennings"`` (Jennings, Housner & Tsai 1968): ``(t / t1)^2`` for ``t < t1``,
    1 up to ``t2 = t1 + stationary``, then an exponential decay ``exp(-decay (t - t2))``,
    shifted and rescaled to reach exactly 0 at ``duration``. ``kind="trapezoidal"``:
    linear rise, flat, linear decay to 0 at ``duration``. Times in s, ``decay`` in 1/s.

    Examples
    --------
    >>> from rocking.motions import Envelope
    >>> e = Envelope()  # Jennings: 2 s rise, 10 s stationary, 20 s in all
    >>> e.t1, e.t2
    (2.0, 12.0)
    >>> [round(float(x), 4) for x in e([0.0, 1.0, 5.0, 20.0])]  # (t/t1)^2, 1, 0 at the end
    [0.0, 0.25, 1.0, 0.0]
    """

    kind: str = "jennings"
    rise: float = 2.0
    stationary: float = 10.0
    duration: float = 20.0
    decay: float = 0.4

    def __post_init__(self):
        if self.kind not in ENVELOPES:
            raise ParameterError(f"envelope must be one of {', '.join(ENVELOPES)}; "
                                 f"got {self.kind!r}")
        rise = positive("rise", self.rise, "s")
        stat = positive("stationary", self.stationary, "s")
        dur = positive("duration", self.duration, "s")
        if not rise + stat < dur:
            raise ParameterError(f"duration must be > rise + stationary = {rise + stat:g} s "
                                 f"(a decay is needed), got {self.duration!r}")
        object.__setattr__(self, "rise", rise)
        object.__setattr__(self, "stationary", stat)
        object.__setattr__(self, "duration", dur)
        object.__setattr__(self, "decay", positive("decay", self.decay, "1/s"))

    @property
    def t1(self) -> float:
        """Start of the stationary part (s)."""
        return self.rise

    @property
    def t2(self) -> float:
        """End of the stationary part (s)."""
        return self.rise + self.stationary

    def __call__(self, t) -> np.ndarray:
        t = np.asarray(t, dtype=np.float64)
        t1, t2, te = self.t1, self.t2, self.duration
        out = np.zeros_like(t)
        up = (t > 0) & (t < t1)
        flat = (t >= t1) & (t <= t2)
        down = (t > t2) & (t < te)
        out[flat] = 1.0
        if self.kind == "jennings":
            out[up] = (t[up] / t1) ** 2
            end = math.exp(-self.decay * (te - t2))
            out[down] = (np.exp(-self.decay * (t[down] - t2)) - end) / (1.0 - end)
        else:
            out[up] = t[up] / t1
            out[down] = (te - t[down]) / (te - t2)
        return out

    def describe(self) -> str:
        """One line: the shape of the envelope and its times (s).

        Examples
        --------
        >>> from rocking.motions import Envelope
        >>> print(Envelope(kind="trapezoidal", rise=1.0, stationary=8.0, duration=12.0).describe())
        trapezoidal envelope: linear rise over 1 s, stationary 1-9 s (8 s),
        linear decay to zero at 12 s
        """
        rise = "quadratic" if self.kind == "jennings" else "linear"
        fall = (f"exponential decay ({self.decay:g} 1/s) to zero" if self.kind == "jennings"
                else "linear decay to zero")
        return (f"{self.kind} envelope: {rise} rise over {self.rise:g} s, stationary "
                f"{self.t1:g}-{self.t2:g} s ({self.stationary:g} s), {fall} at "
                f"{self.duration:g} s")


def _envelope(envelope, duration) -> Envelope:
    if isinstance(envelope, Envelope):
        if duration is not None and not math.isclose(as_float("duration", duration),
                                                      envelope.duration):
            raise ParameterError(f"duration={duration!r} s disagrees with the envelope's "
                                 f"duration {envelope.duration:g} s; give one of them")
        return envelope
    if not isinstance(envelope, str) or envelope.lower() not in ENVELOPES:
        raise ParameterError(f"envelope must be one of {', '.join(ENVELOPES)} or an "
                             f"Envelope; got {envelope!r}")
    return Envelope(kind=envelope.lower(), duration=20.0 if duration is None else duration)


# ----------------------------------------------------------------------------- generator
def _int(name: str, value, lo: int) -> int:
    try:
        ok = int(value) == value
    except (TypeError, ValueError):
        ok = False
    if not ok or isinstance(value, bool) or int(value) < lo:
        raise ParameterError(f"{name} must be an integer >= {lo}, got {value!r}")
    return int(value)


def _target_values(target, periods) -> np.ndarray:
    try:
        v = np.asarray(target(periods), dtype=np.float64)
    except Exception as exc:  # a user callable that cannot take an array
        raise ParameterError(f"target must be a DesignSpectrum or a function of an array of "
                             f"periods (s) returning m/s^2: {exc}") from None
    if v.shape != np.shape(periods) or not np.all(np.isfinite(v)) or np.any(v <= 0.0):
        raise ParameterError("target must return finite spectral accelerations > 0 m/s^2 "
                             "for every period")
    return v


class _Plan:
    """Arrays shared by every record of a call (grid, envelope, control periods...)."""

    def __init__(self, target, env: Envelope, dt: float, damping: float, period_range):
        self.dt = dt
        self.damping = damping
        self.n = int(round(env.duration / dt)) + 1
        self.t = np.arange(self.n) * dt
        self.env = env(self.t)
        lo, hi = period_range
        self.ctrl = np.geomspace(0.8 * lo, hi / 0.75, N_CONTROL)
        self.in_range = (self.ctrl >= lo * (1 - 1e-9)) & (self.ctrl <= hi * (1 + 1e-9))
        self.q = _target_values(target, self.ctrl)
        self.pga = float(_target_values(target, np.array([0.0]))[0])
        self.omega2 = (2.0 * np.pi / self.ctrl) ** 2
        self.nfft = FFT_FACTOR * 2 ** int(math.ceil(math.log2(self.n)))
        self.f = np.fft.rfftfreq(self.nfft, dt)
        f_lo, f_hi = 0.8 / self.ctrl[-1], 1.0 / self.ctrl[0]
        if f_hi > 0.45 / dt:
            raise ParameterError(
                f"dt = {dt:g} s is too coarse for periods down to {lo:g} s: it needs "
                f"dt <= {0.45 * self.ctrl[0]:.4g} s")
        self.band = (self.f >= f_lo) & (self.f <= f_hi)
        # stage 2 high-pass: 0 below f_lo / 2, sin^2 ramp to 1 at f_lo (limits the drift)
        x = np.clip((self.f - 0.5 * f_lo) / (0.5 * f_lo), 0.0, 1.0)
        self.highpass = np.sin(0.5 * np.pi * x) ** 2
        fb = self.f[self.band]
        self.amp0 = np.zeros(self.f.size)
        self.amp0[self.band] = _target_values(target, 1.0 / fb) / np.sqrt(fb)
        self.logf = np.log(fb)
        self.logfc = np.log(1.0 / self.ctrl[::-1])
        self.baseline = baseline_operator(self.n, dt)
        k = max(1, int(round(END_TAPER / dt)))
        self.taper = np.ones(self.n)
        ramp = 0.5 - 0.5 * np.cos(np.pi * np.arange(k) / k)
        self.taper[:k] = ramp
        self.taper[self.n - k:] = ramp[::-1]

    def spectrum(self, a) -> np.ndarray:
        return peak_responses(a, self.dt, self.ctrl, self.damping)[:, 0] * self.omega2

    def correction(self, sa) -> np.ndarray:
        """Multiplier of the Fourier amplitudes (1 outside the band)."""
        r = self.q / sa
        out = np.ones(self.f.size)
        out[self.band] = np.interp(self.logf, self.logfc, r[::-1])
        return out

    def error(self, sa) -> float:
        return float(np.max(np.abs(np.log(sa[self.in_range] / self.q[self.in_range]))))


def _one(plan: _Plan, seed: int, number: int, it1: int, it2: int, tol: float):
    rng = np.random.default_rng([seed, number])
    phase = np.exp(1j * rng.uniform(0.0, 2.0 * np.pi, plan.f.size))
    amp = plan.amp0.copy()
    best = (math.inf, None)
    # stage 1: stationary amplitudes (SIMQKE)
    for i in range(it1):
        x = np.fft.irfft(amp * phase, plan.nfft)[: plan.n]
        a = plan.baseline(plan.env * x)
        if i == 0:
            k = plan.pga / np.max(np.abs(a))
            amp *= k
            a *= k
        sa = plan.spectrum(a)
        err = plan.error(sa)
        if err < best[0]:
            best = (err, a)
        amp *= plan.correction(sa)
    # stage 2: Fourier amplitudes of the enveloped record, phases kept
    a = best[1]
    for _ in range(it2):
        sa = plan.spectrum(a)
        err = plan.error(sa)
        if err < best[0]:
            best = (err, a)
        if err < tol:
            break
        spec = np.fft.rfft(a, plan.nfft) * (plan.correction(sa) * plan.highpass)
        a = plan.baseline(np.fft.irfft(spec, plan.nfft)[: plan.n] * plan.taper)
    else:
        sa = plan.spectrum(a)
        err = plan.error(sa)
        if err < best[0]:
            best = (err, a)
    return best[1], best[0]


def _describe_target(target) -> str:
    return target.describe() if isinstance(target, DesignSpectrum) else repr(target)


def synthetic(target=None, n: int = 1, duration: float | None = None, seed: int = 0,
              envelope="jennings", *, dt: float = 0.01, damping: float = 0.05,
              first_number: int = 1, period_range=PERIOD_RANGE,
              iterations: tuple[int, int] = (STAGE1_ITERATIONS, STAGE2_ITERATIONS),
              tolerance: float = TOLERANCE) -> list[Record]:
    """Spectrum-compatible synthetic accelerograms (see the module doc for the method).

    Parameters
    ----------
    target : DesignSpectrum or callable, optional
        Target pseudo-acceleration spectrum (m/s^2) as a function of an array of periods
        (s); its value at ``T = 0`` is the target PGA. Default: :func:`paper_target`.
    n : int
        Number of records.
    duration : float, optional
        Record length (s); default 20 s, or the envelope's.
    seed : int
        Seed; record ``k`` uses ``numpy.random.default_rng([seed, k])``.
    envelope : {"jennings", "trapezoidal"} or Envelope
        Amplitude envelope (default: 2 s rise, 10 s stationary, decay to the end).
    dt : float
        Time step (s).
    damping : float
        Damping ratio of the matched spectrum (0.05).
    first_number : int
        Number of the first record; the others follow (``first_number + i``).
    period_range : (float, float)
        Periods (s) over which the spectrum is matched and judged.
    iterations : (int, int)
        Iterations of the two correction stages.
    tolerance : float
        Stop when every control period in the range is within this relative deviation
        (in log: ``|ln(Sa / target)| < tolerance``).

    Returns
    -------
    list of Record
        Accelerations in m/s^2 with ``number`` set and ``meta`` holding ``seed``,
        ``stationary`` (start, end in s), ``match_error`` (largest ``|ln(Sa/target)|``
        over the control periods in the range), ``pga_factor`` (the set's PGA scaling, 1
        if none) and the generation details.

    Examples
    --------
    >>> from rocking.motions import Envelope, synthetic
    >>> env = Envelope(rise=1.0, stationary=5.0, duration=8.0)
    >>> recs = synthetic(n=1, duration=8.0, envelope=env, seed=1)  # paper target
    >>> len(recs), recs[0].dt, len(recs[0]), recs[0].meta["stationary"]
    (1, 0.01, 801, (1.0, 6.0))
    """
    target = paper_target() if target is None else target
    if not callable(target):
        raise ParameterError(f"target must be a DesignSpectrum or a function of periods, "
                             f"got {type(target).__name__}")
    n = _int("n", n, 1)
    seed = _int("seed", seed, 0)
    first = _int("first_number", first_number, 0)
    env = _envelope(envelope, duration)
    dt = positive("dt", dt, "s")
    damping = in_range("damping", damping, 0.0, 1.0, lo_open=False,
                       shown="[0, 1) (a fraction: 0.05 is 5 %)")
    try:
        lo, hi = (float(x) for x in period_range)
    except (TypeError, ValueError):
        raise ParameterError(f"period_range must be two periods (s), got "
                             f"{period_range!r}") from None
    if not (0.0 < lo < hi and math.isfinite(hi)):
        raise ParameterError(f"period_range must satisfy 0 < low < high, got {period_range!r}")
    try:
        it1, it2 = (int(x) for x in iterations)
    except (TypeError, ValueError):
        raise ParameterError(f"iterations must be two integers, got {iterations!r}") from None
    if it1 < 1 or it2 < 0:
        raise ParameterError(f"iterations must be (>= 1, >= 0), got {iterations!r}")
    tol = positive("tolerance", tolerance)
    if env.duration < 2 * hi:
        raise ParameterError(f"duration {env.duration:g} s is too short for periods up to "
                             f"{hi:g} s")
    plan = _Plan(target, env, dt, damping, (lo, hi))
    numbers = range(first, first + n)
    workers = min(n, os.cpu_count() or 1)
    if workers > 1:  # records are independent (own random stream): same result as serial
        with ThreadPoolExecutor(workers) as pool:
            res = list(pool.map(lambda k: _one(plan, seed, k, it1, it2, tol), numbers))
    else:
        res = [_one(plan, seed, k, it1, it2, tol) for k in numbers]
    # EC8: the mean PGA of the set must reach the target's zero-period value
    mean_pga = float(np.mean([np.max(np.abs(acc)) for acc, _ in res]))
    fac = max(1.0, plan.pga / mean_pga)
    return [_make_record(acc * fac, dt, k, seed, target, env, err, fac, damping, (lo, hi))
            for k, (acc, err) in zip(numbers, res, strict=True)]


def _make_record(acc, dt, number, seed, target, env, err, factor, damping, prange_):
    meta = {
        "generator": f"rocking.motions.synthetic v{GEN_VERSION}",
        "seed": int(seed),
        "number": int(number),
        "target": _describe_target(target),
        "envelope": env.describe(),
        "stationary": (env.t1, env.t2),
        "damping": damping,
        "period_range": tuple(prange_),
        "match_error": float(err),
        "pga_factor": float(factor),
        "units": "m/s^2",
    }
    return Record(acc, dt, name=f"synthetic earthquake {number}", number=int(number),
                  meta=meta)


# ----------------------------------------------------------------------------- the paper's set
_MEMORY: dict[str, tuple[Record, ...]] = {}


def cache_dir() -> Path:
    """Directory of the on-disk cache: ``$ROCKING_CACHE_DIR``, else
    ``$XDG_CACHE_HOME/rocking``, else ``~/.cache/rocking``."""
    env = os.environ.get("ROCKING_CACHE_DIR")
    if env:
        return Path(env).expanduser()
    xdg = os.environ.get("XDG_CACHE_HOME")
    base = Path(xdg).expanduser() if xdg else Path.home() / ".cache"
    return base / "rocking"


def _paper_settings() -> dict:
    t = paper_target()
    return {
        "version": GEN_VERSION, "seed": PAPER_SEED, "count": PAPER_COUNT,
        "target": (t.pga, t.plateau, t.tb, t.tc, t.td, t.damping),
        "envelope": Envelope(), "dt": 0.01, "period_range": PERIOD_RANGE,
        "iterations": (STAGE1_ITERATIONS, STAGE2_ITERATIONS), "tolerance": TOLERANCE,
        "control": (N_CONTROL, FFT_FACTOR, END_TAPER),
    }


def _source_digest() -> str:
    """Digest of the code that makes the records: any change to it invalidates the cache."""
    h = hashlib.sha1()
    here = Path(__file__).resolve().parent
    for name in ("synthetic.py", "spectra.py", "processing.py", "ec8.py"):
        try:
            h.update((here / name).read_bytes())
        except OSError:  # pragma: no cover - e.g. a zipped install: fall back on the version
            h.update(name.encode())
    return h.hexdigest()


def _paper_key() -> str:
    text = repr(sorted(_paper_settings().items())) + _source_digest()
    return hashlib.sha1(text.encode()).hexdigest()[:16]


def _cache_file() -> Path:
    return cache_dir() / f"paper_earthquakes_v{GEN_VERSION}_{_paper_key()}.npz"


def _generate_paper() -> tuple[Record, ...]:
    s = _paper_settings()
    return tuple(synthetic(paper_target(), n=PAPER_COUNT, seed=PAPER_SEED,
                           envelope=s["envelope"], dt=s["dt"], period_range=PERIOD_RANGE,
                           iterations=s["iterations"], tolerance=s["tolerance"]))


def _save(records, path: Path) -> None:
    """Write the paper's set atomically (:func:`save_set`)."""
    save_set(records, path, _paper_key())


def save_set(records, path: Path, key: str) -> None:
    """Write a generated set of records (``acc``, ``dt``, ``numbers``, each one's
    ``match_error`` and ``pga_factor``, and the ``key`` of its settings) to the ``.npz``
    ``path`` atomically; an OSError is ignored (the cache is only a speed-up)."""
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=".tmp_", suffix=".npz", dir=path.parent)
        with os.fdopen(fd, "wb") as f:
            np.savez(f, key=np.array(key),
                     acc=np.stack([r.acc for r in records]),
                     dt=np.array(records[0].dt),
                     numbers=np.array([r.number for r in records]),
                     match_error=np.array([r.meta["match_error"] for r in records]),
                     pga_factor=np.array([r.meta["pga_factor"] for r in records]))
        os.replace(tmp, path)
        tmp = None
    except OSError:
        pass
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass


def _load(path: Path) -> tuple[Record, ...] | None:
    try:
        with np.load(path, allow_pickle=False) as z:
            if str(z["key"]) != _paper_key():
                return None
            acc, dt, numbers = z["acc"], float(z["dt"]), z["numbers"]
            err, fac = z["match_error"], z["pga_factor"]
    except (OSError, ValueError, KeyError, EOFError):
        return None
    if acc.shape[0] != PAPER_COUNT or not np.all(np.isfinite(acc)):
        return None
    t = paper_target()
    env = Envelope()
    return tuple(_make_record(acc[i], dt, int(numbers[i]), PAPER_SEED, t, env, err[i], fac[i],
                              0.05, PERIOD_RANGE) for i in range(acc.shape[0]))


def seed_earthquakes(use_cache: bool = True) -> list[Record]:
    """The 30 synthetic earthquakes of the paper's random tests (our own realisation).

    Records numbered 1-30, 20 s at ``dt = 0.01`` s, acceleration in m/s^2, compatible with
    :func:`~rocking.motions.ec8.paper_target` (see the module doc). Made once, then
    cached in memory and on disk (see :func:`cache_dir`); ``use_cache=False`` regenerates
    them (a few seconds) without touching either cache.

    Examples
    --------
    >>> from rocking.motions import seed_earthquakes
    >>> eqs = seed_earthquakes()
    >>> len(eqs), eqs[0].number, eqs[0].dt, round(eqs[0].duration, 2)
    (30, 1, 0.01, 20.0)
    """
    if not use_cache:
        return list(_generate_paper())
    key = _paper_key()
    recs = _MEMORY.get(key)
    if recs is None:
        path = _cache_file()
        recs = _load(path) if path.exists() else None
        if recs is None:
            recs = _generate_paper()
            _save(recs, path)
        _MEMORY[key] = recs
    return list(recs)


def clear_cache(disk: bool = False) -> None:
    """Forget the in-memory set; with ``disk=True`` also delete the cache file."""
    _MEMORY.clear()
    if disk:
        try:
            _cache_file().unlink()
        except OSError:
            pass


def _number(n) -> int:
    try:
        ok = int(n) == n and not isinstance(n, bool)
    except (TypeError, ValueError):
        ok = False
    if isinstance(n, str):
        try:
            n, ok = int(n.strip()), True
        except ValueError:
            ok = False
    if not ok or not 1 <= int(n) <= PAPER_COUNT:
        raise ParameterError(f"earthquake number must be an integer from 1 to {PAPER_COUNT}, "
                             f"got {n!r}")
    return int(n)


def paper_earthquake(n) -> Record:
    """Record number ``n`` (1-30) of :func:`seed_earthquakes`.

    Examples
    --------
    >>> from rocking.motions import paper_earthquake
    >>> rec = paper_earthquake(3)
    >>> rec.number, rec.name, rec.meta["stationary"]
    (3, 'synthetic earthquake 3', (2.0, 12.0))
    """
    k = _number(n)
    return seed_earthquakes()[k - 1]


def earthquake_motion(n, load_factor: float = 1.0) -> Record:
    """Our earthquake ``n`` (1-30) multiplied by ``load_factor`` (> 0), for
    ``rocking simulate --earthquake N --load-factor F``.

    Examples
    --------
    >>> from rocking.motions import earthquake_motion, paper_earthquake
    >>> m = earthquake_motion(3, load_factor=0.5)
    >>> m.scale, round(m.pga / paper_earthquake(3).pga, 6)
    (0.5, 0.5)
    """
    k = _number(n)
    f = positive("load_factor", load_factor)
    rec = paper_earthquake(k)
    return rec.scaled(f) if f != 1.0 else rec


# ----------------------------------------------------------------------------- compatibility
@dataclass
class Compatibility:
    """Result of :func:`check_compatibility` (accelerations in m/s^2, periods in s).

    Examples
    --------
    >>> from rocking.motions import check_compatibility, seed_earthquakes
    >>> c = check_compatibility(seed_earthquakes())
    >>> bool(c.min_ratio >= 0.9), bool(c.mean_pga >= c.target_pga)  # EC8 3.2.3.1.2
    (True, True)
    """

    passed: bool
    checks: dict
    n_records: int
    period_range: tuple
    target_pga: float
    mean_pga: float
    min_stationary: float | None
    min_ratio: float
    period_at_min: float
    max_ratio: float
    period_at_max: float
    periods: np.ndarray = field(repr=False)
    target: np.ndarray = field(repr=False)
    spectra: np.ndarray = field(repr=False)

    @property
    def mean(self) -> np.ndarray:
        """Mean spectrum of the set at :attr:`periods`."""
        return self.spectra.mean(axis=0)

    @property
    def std(self) -> np.ndarray:
        """Standard deviation of the spectra (sample, ``ddof=1`` when possible)."""
        return self.spectra.std(axis=0, ddof=1 if len(self.spectra) > 1 else 0)

    def record_deviation(self) -> np.ndarray:
        """Largest ``|Sa / target - 1|`` of each record over the period range.

        Examples
        --------
        >>> from rocking.motions import check_compatibility, seed_earthquakes
        >>> c = check_compatibility(seed_earthquakes()[:3])
        >>> dev = c.record_deviation()  # one per record
        >>> dev.shape, bool(np.all(dev >= 0))
        ((3,), True)
        >>> bool(dev.max() >= max(1 - c.min_ratio, c.max_ratio - 1))  # the mean is closer
        True
        """
        m = self._in_range()
        return np.max(np.abs(self.spectra[:, m] / self.target[m] - 1.0), axis=1)

    def _in_range(self):
        lo, hi = self.period_range
        return (self.periods >= lo * (1 - 1e-9)) & (self.periods <= hi * (1 + 1e-9))

    def summary(self) -> str:
        """A few lines: the verdict, then each check of EN 1998-1 §3.2.3.1.2 with its
        figures.

        Examples
        --------
        >>> from rocking.motions import check_compatibility, seed_earthquakes
        >>> print(check_compatibility(seed_earthquakes()[:3]).summary())  # mean PGA too low
        EC8 §3.2.3.1.2 compatibility of 3 record(s): FAIL
          stationary part >= 10 s: shortest 10.0 s [ok]
          mean PGA ... m/s^2 >= target 2.800 m/s^2 [FAIL]
          mean spectrum / target over 0.05-3 s: min ... (>= 0.90), max ... [ok]
        """
        lo, hi = self.period_range
        stat = ("unknown" if self.min_stationary is None
                else f"{self.min_stationary:.1f} s")
        lines = [
            f"EC8 §3.2.3.1.2 compatibility of {self.n_records} record(s): "
            f"{'PASS' if self.passed else 'FAIL'}",
            f"  stationary part >= 10 s: shortest {stat} "
            f"[{_ok(self.checks.get('stationary'))}]",
            f"  mean PGA {self.mean_pga:.3f} m/s^2 >= target {self.target_pga:.3f} m/s^2 "
            f"[{_ok(self.checks['pga'])}]",
            f"  mean spectrum / target over {lo:g}-{hi:g} s: min {self.min_ratio:.3f} at "
            f"{self.period_at_min:.3g} s (>= 0.90), max {self.max_ratio:.3f} at "
            f"{self.period_at_max:.3g} s [{_ok(self.checks['spectrum'])}]",
        ]
        return "\n".join(lines)


def _ok(v) -> str:
    return "n/a" if v is None else ("ok" if v else "FAIL")


def check_compatibility(records, target=None, period_range=PERIOD_RANGE,
                        damping: float = 0.05, periods=None,
                        min_stationary: float = 10.0) -> Compatibility:
    """Check a set of records against EN 1998-1 §3.2.3.1.2 (see the module doc).

    ``periods`` (default: 200 log-spaced from 0.02 to 4 s plus the ends of the range) are
    where the spectra are computed; only those inside ``period_range`` are judged. The
    stationary duration is read from ``record.meta["stationary"]`` (synthetic records);
    for other records it is not known and the check is reported as ``None``.

    Examples
    --------
    >>> from rocking.motions import check_compatibility, seed_earthquakes
    >>> c = check_compatibility(seed_earthquakes())
    >>> c.passed, c.n_records, c.checks
    (True, 30, {'stationary': True, 'pga': True, 'spectrum': True})
    """
    recs = list(records)
    if not recs:
        raise ParameterError("check_compatibility needs at least one record")
    target = paper_target() if target is None else target
    lo, hi = (float(x) for x in period_range)
    if periods is None:
        periods = np.unique(np.concatenate([np.geomspace(0.02, 4.0, 200), [lo, hi]]))
    T = np.asarray(periods, dtype=np.float64)
    tgt = _target_values(target, T)
    spectra = np.array([response_spectrum(r, T, damping) for r in recs])
    mean = spectra.mean(axis=0)
    m = (T >= lo * (1 - 1e-9)) & (T <= hi * (1 + 1e-9))
    ratio = mean[m] / tgt[m]
    i_min, i_max = int(np.argmin(ratio)), int(np.argmax(ratio))
    pga_t = float(_target_values(target, np.array([0.0]))[0])
    mean_pga = float(np.mean([r.pga for r in recs]))
    stats = [r.meta.get("stationary") for r in recs]
    if all(s is not None for s in stats):
        min_stat = float(min(b - a for a, b in stats))
        ok_stat = min_stat >= min_stationary - 1e-9
    else:
        min_stat, ok_stat = None, None
    checks = {"stationary": ok_stat, "pga": mean_pga >= pga_t * (1 - 1e-9),
              "spectrum": bool(ratio.min() >= 0.9)}
    passed = all(v is not False for v in checks.values())
    return Compatibility(
        passed=bool(passed), checks=checks, n_records=len(recs), period_range=(lo, hi),
        target_pga=pga_t, mean_pga=mean_pga, min_stationary=min_stat,
        min_ratio=float(ratio[i_min]), period_at_min=float(T[m][i_min]),
        max_ratio=float(ratio[i_max]), period_at_max=float(T[m][i_max]),
        periods=T, target=tgt, spectra=spectra)

