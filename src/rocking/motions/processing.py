r"""Processing of accelerograms and their intensity measures.

The work is done on arrays: acceleration samples ``acc`` (m/s^2) and a time step ``dt`` (s)
(:func:`integrate`, :func:`resample_acc`, :func:`bandpass_acc`, :func:`baseline_correct_acc`,
:func:`arias_cumulative`, :func:`significant_duration_acc`, :func:`intensity_measures_acc`).
The :class:`~rocking.motions.records.Record` methods call them, and so do the functions of
the same names without ``_acc``, which take a record: any sampled accelerogram with
``acc``, ``dt`` and ``values`` (see :func:`~rocking.motions.base.is_sampled`). The ones that
transform a record (:func:`resample`, :func:`bandpass`, :func:`baseline_correct`) return a
new record of the same class (``dataclasses.replace``) with the same ``name``, ``number``
and load factor ``scale`` (they are linear, so they commute with the load factor) and
append a description of the step to ``meta["processing"]``. The measures (:func:`pgv`,
:func:`arias_intensity`, ...) use the samples *with* the load factor applied
(``record.values``).

Integration is exact for the piecewise-linear acceleration that a Record stands for
(linear between samples): over a step ``h``

.. math:: v_{i+1} = v_i + \tfrac{h}{2} (a_i + a_{i+1}), \qquad
          d_{i+1} = d_i + h v_i + \tfrac{h^2}{6} (2 a_i + a_{i+1}),

from ``v = d = 0`` at ``t = 0``. Velocities are in m/s and displacements in m when the
record is in m/s^2. A raw record usually ends with a drifting velocity and displacement;
:func:`baseline_correct` removes the drift so that both return to zero.
"""

from __future__ import annotations

import math
from dataclasses import replace
from fractions import Fraction

import numpy as np

from .._validate import in_range, positive
from ..errors import ParameterError, RecordError
from ..units import G
from .samples import as_samples, is_sampled

__all__ = ["resample", "bandpass", "baseline_correct", "velocity", "displacement",
           "integrate", "pga", "pgv", "pgd", "arias_intensity", "husid",
           "significant_duration", "intensity_measures",
           "resample_acc", "bandpass_acc", "baseline_correct_acc", "baseline_operator",
           "arias_cumulative", "significant_duration_acc", "intensity_measures_acc"]

_RATIO_RTOL = 1e-9  # a dt ratio closer than this to a fraction p/q counts as rational
_MAX_UPDOWN = 1000  # largest polyphase up/down factor


def _check_record(record):
    if not is_sampled(record):
        raise ParameterError(
            f"expected a Record, got {type(record).__name__}; sample other motions first "
            "with rocking.motions.sample(motion, dt)")
    return record


def _derived(record, acc: np.ndarray, dt: float, step: str, **meta):
    """A record of the same class as ``record`` with new samples and the step recorded."""
    m = dict(record.meta)
    m["processing"] = [*record.meta.get("processing", []), step]
    m.update(meta)
    return replace(record, acc=acc, dt=dt, meta=m)


# --------------------------------------------------------------------------- integration
def integrate(acc, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """Velocity and displacement of the piecewise-linear ``acc`` from rest (exact)."""
    a = np.asarray(acc, dtype=np.float64)
    v = np.zeros(a.size)
    d = np.zeros(a.size)
    if a.size > 1:
        v[1:] = np.cumsum(0.5 * dt * (a[:-1] + a[1:]))
        d[1:] = np.cumsum(dt * v[:-1] + dt * dt / 6.0 * (2.0 * a[:-1] + a[1:]))
    return v, d


def velocity(record) -> np.ndarray:
    """Ground velocity (m/s) at the samples, from rest, load factor applied.

    Examples
    --------
    >>> from rocking.motions import Rectangular, sample
    >>> r = sample(Rectangular(amplitude=1.0, length=2.0, duration=2.0), dt=0.01)  # A = 1, t1 = 2
    >>> from rocking.motions import velocity
    >>> round(float(velocity(r)[-1]), 6)  # A t1
    2.0
    """
    r = _check_record(record)
    return integrate(r.values, r.dt)[0]


def displacement(record) -> np.ndarray:
    """Ground (table) displacement (m) at the samples, from rest, load factor applied.

    Examples
    --------
    >>> from rocking.motions import Rectangular, sample
    >>> r = sample(Rectangular(amplitude=1.0, length=2.0, duration=2.0), dt=0.01)  # A = 1, t1 = 2
    >>> from rocking.motions import displacement
    >>> round(float(displacement(r)[-1]), 6)  # A t1^2 / 2
    2.0
    """
    r = _check_record(record)
    return integrate(r.values, r.dt)[1]


# --------------------------------------------------------------------------- transforms
def _end_values(acc, dt) -> np.ndarray:
    v, d = integrate(acc, dt)
    return np.array([v[-1], d[-1]])


def baseline_operator(n: int, dt: float):
    """``f(acc) -> corrected acc`` for records of ``n`` samples (see :func:`baseline_correct`).

    The operator is linear; building it once serves many records of the same length."""
    t = np.arange(n) * dt
    T = t[-1]
    b0 = t * (T - t) / (T * T)
    b1 = b0 * t / T
    Minv = np.linalg.inv(np.column_stack([_end_values(b0, dt), _end_values(b1, dt)]))

    def apply(acc):
        c = Minv @ _end_values(acc, dt)
        return acc - c[0] * b0 - c[1] * b1

    return apply


def baseline_correct_acc(acc, dt: float) -> np.ndarray:
    """``acc`` (m/s^2, step ``dt`` s) with zero final velocity and displacement; see
    :func:`baseline_correct`."""
    a = as_samples(acc)
    dt = positive("dt", dt, "s")
    if a.size < 4:
        raise RecordError(f"baseline correction needs at least 4 samples, got {a.size}")
    return baseline_operator(a.size, dt)(a)


def baseline_correct(record):
    r"""Make the final ground velocity and displacement zero (table back at its start).

    Subtracts the smallest smooth correction that does it: a cubic
    ``t (T - t) (c_0 + c_1 t)`` in the acceleration (``T`` the duration), which vanishes
    at both ends (the first and last samples do not change) and has its energy at periods
    of the order of the duration, so the response spectrum at periods well below ``T``
    is hardly changed. ``c_0, c_1`` solve the two linear conditions ``v(T) = d(T) = 0``
    exactly (the integration is exact for the piecewise-linear record). Pass a record
    through :func:`bandpass` first if it has a large low-frequency noise.

    Examples
    --------
    >>> from rocking.motions import baseline_correct, displacement, load_builtin, velocity
    >>> rec = load_builtin("RSN126_GAZLI_GAZ000")
    >>> b = baseline_correct(rec)
    >>> bool(abs(velocity(b)[-1]) < 1e-12 and abs(displacement(b)[-1]) < 1e-12)
    True
    >>> bool(b.values[0] == rec.values[0]), bool(b.values[-1] == rec.values[-1])  # ends kept
    (True, True)
    """
    r = _check_record(record)
    acc = baseline_correct_acc(r.acc, r.dt)
    return _derived(r, acc, r.dt, "baseline correction (cubic, zero final v and d)")


def _ratio(old: float, new: float) -> Fraction | None:
    ratio = old / new
    frac = Fraction(ratio).limit_denominator(_MAX_UPDOWN)
    if frac.numerator > _MAX_UPDOWN or frac.numerator == 0:
        return None
    if abs(float(frac) - ratio) > _RATIO_RTOL * ratio:
        return None
    return frac


def _resample(acc, dt: float, new_dt: float, method: str) -> tuple[np.ndarray, str | None]:
    """Resampled samples and a description of the step (``None``: ``dt`` unchanged)."""
    a = as_samples(acc)
    dt = positive("dt", dt, "s")
    new = positive("dt", new_dt, "s")
    if method not in ("auto", "polyphase", "linear"):
        raise ParameterError(f"method must be 'auto', 'polyphase' or 'linear'; got {method!r}")
    n_new = int(math.floor((a.size - 1) * dt / new + 1e-9)) + 1
    if n_new < 2:
        raise ParameterError(f"dt = {new:g} s is longer than the record "
                             f"({(a.size - 1) * dt:g} s)")
    if math.isclose(new, dt, rel_tol=_RATIO_RTOL):
        return a.copy(), None
    frac = _ratio(dt, new) if method != "linear" else None
    if method == "polyphase" and frac is None:
        raise ParameterError(
            f"dt ratio {dt:g}/{new:g} is not a fraction up/down with up, down <= "
            f"{_MAX_UPDOWN}; use method='linear'")
    from scipy import signal  # lazy: 1.4-2 s to import, more than rocking.motions

    if frac is not None:
        up, down = frac.numerator, frac.denominator
        y = signal.resample_poly(a, up, down, padtype="constant")
        if y.size < n_new:  # pragma: no cover - resample_poly returns ceil(n up / down)
            y = np.concatenate([y, np.zeros(n_new - y.size)])
        out = y[:n_new]
        how = f"polyphase, up {up} / down {down}"
    else:
        x = a
        if new > dt:
            fc = 0.8 * 0.5 / new
            sos = signal.butter(8, fc, btype="lowpass", fs=1.0 / dt, output="sos")
            x = signal.sosfiltfilt(sos, x)
        out = np.interp(np.arange(n_new) * new, np.arange(a.size) * dt, x)
        how = "linear interpolation" + (" after an anti-alias low-pass" if new > dt else "")
    return np.ascontiguousarray(out), f"resample {dt:g} s -> {new:g} s ({how})"


def resample_acc(acc, dt: float, new_dt: float, method: str = "auto") -> np.ndarray:
    """``acc`` (step ``dt`` s) resampled to the step ``new_dt`` (s); see :func:`resample`."""
    return _resample(acc, dt, new_dt, method)[0]


def resample(record, dt: float, method: str = "auto"):
    """The record resampled to the time step ``dt`` (s), over the same duration.

    ``method``:

    * ``"polyphase"``: band-limited resampling by ``scipy.signal.resample_poly`` with its
      anti-aliasing FIR filter (Kaiser window); needs ``record.dt / dt`` to be a fraction
      ``up / down`` with both at most 1000 (true for decimal time steps such as 0.005 ->
      0.01 or 0.0066 -> 0.01 = 33/50).
    * ``"linear"``: linear interpolation, after a zero-phase Butterworth low-pass at 80 %
      of the new Nyquist frequency when the step grows (anti-aliasing).
    * ``"auto"`` (default): ``"polyphase"`` when possible, else ``"linear"``.

    Content above the new Nyquist frequency ``1 / (2 dt)`` is removed when downsampling.
    The last sample is at or just before the original end.

    Examples
    --------
    >>> from rocking.motions import load_builtin, resample
    >>> rec = load_builtin("RSN126_GAZLI_GAZ000")  # dt = 0.0066 s
    >>> r = resample(rec, 0.01)  # polyphase, 50/33
    >>> r.dt, len(r), bool(r.duration <= rec.duration)
    (0.01, 1352, True)
    """
    r = _check_record(record)
    acc, how = _resample(r.acc, r.dt, dt, method)
    if how is None:
        return _derived(r, acc, r.dt, "resample: unchanged")
    return _derived(r, acc, float(dt), how)


def _bandpass(acc, dt: float, low, high, order) -> tuple[np.ndarray, int, str]:
    """Filtered samples with their zero pads, the pad length (samples) and a description."""
    a = as_samples(acc)
    dt = positive("dt", dt, "s")
    nyq = 0.5 / dt
    if low is None and high is None:
        raise ParameterError("give low and/or high (Hz) for bandpass")
    if low is not None:
        low = in_range("low", low, 0.0, nyq, shown=f"(0, {nyq:g}) Hz (Nyquist)")
    if high is not None:
        high = in_range("high", high, 0.0, nyq, shown=f"(0, {nyq:g}) Hz (Nyquist)")
    if low is not None and high is not None and not low < high:
        raise ParameterError(f"low must be < high; got low={low:g} Hz, high={high:g} Hz")
    if int(order) != order or not 1 <= order <= 12:
        raise ParameterError(f"order must be an integer in 1..12, got {order!r}")
    order = int(order)
    from scipy import signal  # lazy: 1.4-2 s to import, more than rocking.motions

    if low is not None and high is not None:
        sos = signal.butter(order, [low, high], btype="bandpass", fs=1.0 / dt, output="sos")
    elif low is not None:
        sos = signal.butter(order, low, btype="highpass", fs=1.0 / dt, output="sos")
    else:
        sos = signal.butter(order, high, btype="lowpass", fs=1.0 / dt, output="sos")
    fc = low if low is not None else high
    npad = int(math.ceil(1.5 * order / fc / dt))
    x = np.concatenate([np.zeros(npad), a, np.zeros(npad)])
    y = signal.sosfiltfilt(sos, x, padtype=None)
    desc = (f"Butterworth {'band' if low and high else ('high' if low else 'low')}-pass, "
            f"order {order} x2 (zero phase), corners "
            f"{'' if low is None else f'{low:g} Hz'}"
            f"{' - ' if low is not None and high is not None else ''}"
            f"{'' if high is None else f'{high:g} Hz'}, zero pads {npad * dt:g} s")
    return y, npad, desc


def bandpass_acc(acc, dt: float, low: float | None = 0.1, high: float | None = None,
                 order: int = 4, keep_pads: bool = False) -> np.ndarray:
    """Zero-phase Butterworth filtered ``acc`` (step ``dt`` s); see :func:`bandpass`."""
    y, npad, _ = _bandpass(acc, dt, low, high, order)
    return y if keep_pads else np.ascontiguousarray(y[npad:y.size - npad])


def bandpass(record, low: float | None = 0.1, high: float | None = None, order: int = 4,
             keep_pads: bool = False):
    """Zero-phase Butterworth band-pass (or high-/low-pass) filter of the record.

    ``low`` and ``high`` are the corner frequencies (Hz; ``None`` for no high-pass or no
    low-pass corner; ``high`` below the Nyquist frequency). The filter is applied forwards
    and backwards (``scipy.signal.sosfiltfilt``, effective order ``2 * order``, no phase
    shift) to the record padded with zeros of ``1.5 order / low`` seconds at both ends
    (Converse & Brady 1992; Boore 2005) so that the filter transients fit in the pads.
    ``keep_pads=True`` returns the padded record (its velocity and displacement are then
    consistent with the acceleration; ``meta["t_shift"]`` says how much earlier it starts);
    by default the pads are cut off, and :func:`baseline_correct` can then bring the final
    velocity and displacement back to zero.

    Examples
    --------
    >>> from rocking.motions import bandpass, load_builtin
    >>> rec = load_builtin("RSN126_GAZLI_GAZ000")
    >>> f = bandpass(rec, low=0.1)  # 0.1 Hz high-pass, zero phase
    >>> len(f) == len(rec), f.dt, round(f.pga / rec.pga, 2)
    (True, 0.0066, 1.0)
    """
    r = _check_record(record)
    y, npad, desc = _bandpass(r.acc, r.dt, low, high, order)
    if keep_pads:
        return _derived(r, y, r.dt, desc + " (kept)",
                        t_shift=float(r.meta.get("t_shift", 0.0)) + npad * r.dt)
    return _derived(r, np.ascontiguousarray(y[npad:npad + r.acc.size]), r.dt, desc)


# --------------------------------------------------------------------------- measures
def pga(record) -> float:
    """Peak ground acceleration (units of the record, m/s^2).

    Examples
    --------
    >>> from rocking.motions import Sine, pga, sample
    >>> r = sample(Sine(freq=2.0, amplitude=0.01, duration=2.0), dt=0.005)
    >>> round(pga(r), 4), round(0.01 * (2 * np.pi * 2.0) ** 2, 4)  # X (2 pi f)^2
    (1.5791, 1.5791)
    """
    return float(np.max(np.abs(_check_record(record).values)))


def pgv(record) -> float:
    """Peak ground velocity (m/s).

    Examples
    --------
    >>> from rocking.motions import Rectangular, sample
    >>> r = sample(Rectangular(amplitude=1.0, length=2.0, duration=2.0), dt=0.01)  # A = 1, t1 = 2
    >>> from rocking.motions import pgv
    >>> round(pgv(r), 6)  # A t1
    2.0
    """
    return float(np.max(np.abs(velocity(record))))


def pgd(record) -> float:
    """Peak ground (table) displacement (m).

    Examples
    --------
    >>> from rocking.motions import Rectangular, sample
    >>> r = sample(Rectangular(amplitude=1.0, length=2.0, duration=2.0), dt=0.01)  # A = 1, t1 = 2
    >>> from rocking.motions import pgd
    >>> round(pgd(r), 6)  # A t1^2 / 2
    2.0
    """
    return float(np.max(np.abs(displacement(record))))


def arias_cumulative(acc, dt: float) -> np.ndarray:
    """Cumulative Arias intensity (m/s for ``acc`` in m/s^2) at the samples, from 0."""
    a = np.asarray(acc)
    seg = dt * (a[:-1] ** 2 + a[:-1] * a[1:] + a[1:] ** 2) / 3.0  # exact for linear a
    out = np.zeros(a.size)
    out[1:] = np.cumsum(seg)
    return out * (math.pi / (2.0 * G))


def _husid(acc, dt: float) -> np.ndarray:
    c = arias_cumulative(acc, dt)
    if c[-1] <= 0.0:
        raise RecordError("the record is identically zero: no Arias intensity")
    return c / c[-1]


def arias_intensity(record) -> float:
    """Arias intensity ``pi / (2 g) * integral a^2 dt`` (m/s for a record in m/s^2).

    Examples
    --------
    >>> from rocking.motions import Rectangular, sample
    >>> r = sample(Rectangular(amplitude=1.0, length=2.0, duration=2.0), dt=0.01)  # A = 1, t1 = 2
    >>> from rocking.motions import arias_intensity
    >>> round(arias_intensity(r), 4), round(np.pi / (2 * 9.80665) * 1.0**2 * 2.0, 4)
    (0.3204, 0.3204)
    """
    r = _check_record(record)
    return float(arias_cumulative(r.values, r.dt)[-1])


def husid(record) -> np.ndarray:
    """Normalised cumulative Arias intensity (0 to 1) at the samples (the Husid plot)."""
    r = _check_record(record)
    return _husid(r.values, r.dt)


def significant_duration_acc(acc, dt: float, start: float = 0.05, end: float = 0.95
                             ) -> tuple[float, float, float]:
    """``(duration, t_start, t_end)`` (s) of ``acc`` (step ``dt`` s); see
    :func:`significant_duration`."""
    start = in_range("start", start, 0.0, 1.0, lo_open=False)
    end = in_range("end", end, 0.0, 1.0, hi_open=False)
    if not start < end:
        raise ParameterError(f"start must be < end; got {start:g}, {end:g}")
    h = _husid(acc, dt)
    t = np.arange(h.size) * dt
    # h is non-decreasing: interpolate the time as a function of h on the samples that
    # bound a rising step (flat stretches, e.g. before the first motion, are skipped, so
    # that a level is reached where the energy starts to grow, not at t = 0)
    rise = np.diff(h) > 0
    keep = np.concatenate([rise, [False]]) | np.concatenate([[False], rise])
    ta, tb = np.interp([start, end], h[keep], t[keep])
    return float(tb - ta), float(ta), float(tb)


def significant_duration(record, start: float = 0.05, end: float = 0.95,
                         return_times: bool = False):
    """Time (s) between the ``start`` and ``end`` fractions of the Arias intensity.

    The default 5-95 % is the usual ``D5-95``. The crossing times are interpolated
    linearly between samples. ``return_times=True`` gives ``(duration, t_start, t_end)``.

    Examples
    --------
    >>> from rocking.motions import Rectangular, sample
    >>> r = sample(Rectangular(amplitude=1.0, length=2.0, duration=2.0), dt=0.01)  # A = 1, t1 = 2
    >>> from rocking.motions import significant_duration
    >>> d, t5, t95 = significant_duration(r, return_times=True)  # uniform a: 0.9 t1
    >>> round(d, 6), round(t5, 6), round(t95, 6)
    (1.8, 0.1, 1.9)
    """
    r = _check_record(record)
    res = significant_duration_acc(r.values, r.dt, start, end)
    return res if return_times else res[0]


def _block_terms(block) -> tuple[float, float]:
    """``(g tan alpha, p)`` of a block-like object (``alpha`` rad, ``p`` 1/s), validated."""
    try:
        alpha, p = block.alpha, block.p
    except AttributeError:
        raise ParameterError(
            f"block must have attributes alpha (rad) and p (1/s), e.g. a rocking.Block; "
            f"got {type(block).__name__}") from None
    alpha = in_range("block.alpha", alpha, 0.0, math.pi / 2, shown="(0, pi/2) rad")
    p = positive("block.p", p, "1/s")
    return G * math.tan(alpha), p


def intensity_measures_acc(acc, dt: float, block=None) -> dict:
    """:func:`intensity_measures` of the samples ``acc`` (m/s^2, step ``dt`` s)."""
    gta = _block_terms(block) if block is not None else None
    a = np.asarray(acc, dtype=np.float64)
    v, d = integrate(a, dt)
    p = float(np.max(np.abs(a)))
    if p > 0.0:
        d595, t5, t95 = significant_duration_acc(a, dt)
    else:
        d595 = t5 = t95 = float("nan")
    out = {
        "pga": p,
        "pga_g": p / G,
        "pgv": float(np.max(np.abs(v))),
        "pgd": float(np.max(np.abs(d))),
        "arias": float(arias_cumulative(a, dt)[-1]),
        "d5_95": d595,
        "t5": t5,
        "t95": t95,
        "duration": (a.size - 1) * dt,
        "dt": dt,
        "npts": int(a.size),
        "v_end": float(v[-1]),
        "d_end": float(d[-1]),
    }
    if gta is not None:
        g_tan, bp = gta
        out["pga_ratio"] = out["pga"] / g_tan
        out["pgv_ratio"] = out["pgv"] * bp / g_tan
    return out


def intensity_measures(record, block=None) -> dict:
    """Common measures of a record, in SI units.

    ``pga`` (m/s^2), ``pga_g``, ``pgv`` (m/s), ``pgd`` (m), ``arias`` (m/s), ``d5_95``
    (s) with ``t5``/``t95``, ``duration`` (s), ``dt`` (s), ``npts``, and the final
    velocity and displacement ``v_end`` (m/s), ``d_end`` (m), which are 0 for a
    baseline-corrected record.

    Given a ``block`` (any object with ``alpha`` in rad and ``p`` in 1/s, e.g. a
    :class:`rocking.Block`), also the dimensionless rocking measures ``pga_ratio`` =
    ``PGA / (g tan alpha)`` (> 1 is needed to uplift a block from rest) and ``pgv_ratio`` =
    ``PGV p / (g tan alpha)``.

    Examples
    --------
    >>> import rocking
    >>> from rocking.motions import intensity_measures, load_builtin
    >>> block = rocking.specimen(2)
    >>> im = intensity_measures(load_builtin("RSN126_GAZLI_GAZ000"), block)
    >>> im["npts"], im["dt"], round(im["pga_g"], 3)
    (2048, 0.0066, 0.702)
    >>> bool(np.isclose(im["pga_ratio"], im["pga"] / (9.80665 * np.tan(block.alpha))))
    True
    """
    r = _check_record(record)
    return intensity_measures_acc(r.values, r.dt, block=block)
