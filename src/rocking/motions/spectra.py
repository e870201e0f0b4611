r"""Elastic response spectra of accelerograms.

The single-degree-of-freedom oscillator of natural period ``T`` (``omega = 2 pi / T``) and
damping ratio ``zeta``, relative displacement ``u``, under the ground acceleration ``a_g``:

.. math::  \ddot u + 2 \zeta \omega \dot u + \omega^2 u = -a_g(t)

is integrated by the exact recurrence for a piecewise-linear excitation (Nigam & Jennings
1969; Chopra, *Dynamics of Structures*, §5.2): over a step ``h`` with ``a_g`` linear,

.. math::  u_{i+1} = A u_i + B \dot u_i + C p_i + D p_{i+1}, \quad
           \dot u_{i+1} = A' u_i + B' \dot u_i + C' p_i + D' p_{i+1}

with ``p = -a_g``. The recurrence is exact for the linear interpolation of the samples,
which is how :class:`~rocking.motions.records.Record` defines the motion between samples,
so the only approximation is that the peak is taken at the evaluation points. For short
periods each time step is split into ``ceil(20 dt / T)`` equal sub-steps (still exact: the
excitation stays linear within a step), so that every oscillator cycle is sampled at
least 20 times (worst-case peak error ``1 - cos(pi / 20) = 1.2 %``, typically far less).
After the record ends the ground is at rest and the oscillator rings freely; its peak over
the following damped period (the largest of all later peaks) is included.

All periods are integrated in one compiled call (an outer loop over the periods, an inner
loop over time; large problems share the periods among threads with numba ``prange``): no
Python loop per time step.

Spectral quantities (``kind``): ``"psa"`` pseudo-acceleration ``omega^2 max|u|`` (the
default, m/s^2 if the record is), ``"sa"`` absolute acceleration ``max|u'' + a_g|``,
``"sd"`` relative displacement ``max|u|``, ``"psv"`` pseudo-velocity ``omega max|u|``,
``"sv"`` relative velocity ``max|u'|``. At ``T = 0`` (a rigid oscillator) ``psa = sa =``
PGA and the other quantities are 0.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from .._validate import in_range, positive
from ..errors import ParameterError
from ..units import G
from .samples import as_samples, is_sampled

__all__ = ["response_spectrum", "response_spectra", "sdof_response", "log_periods", "KINDS",
           "plot_spectra",
           "MIN_STEPS_PER_PERIOD"]

KINDS = ("psa", "sa", "sd", "psv", "sv")
MIN_STEPS_PER_PERIOD = 20
"""Each oscillator cycle is sampled at least this many times (sub-steps for short T)."""
PARALLEL_WORK = 5e6  # oscillator steps above which the periods are shared among threads


# ------------------------------------------------------------------------------ kernels
@njit(cache=True)
def _coefficients(w, zeta, h):
    """Nigam-Jennings coefficients (A, B, C, D, A', B', C', D') for m = 1, k = w^2."""
    k = w * w
    sq = math.sqrt(1.0 - zeta * zeta)
    wd = w * sq
    e = math.exp(-zeta * w * h)
    s = math.sin(wd * h)
    c = math.cos(wd * h)
    z = zeta / sq
    A = e * (z * s + c)
    B = e * s / wd
    C = (2.0 * zeta / (w * h) + e * (((1.0 - 2.0 * zeta * zeta) / (wd * h) - z) * s
                                     - (1.0 + 2.0 * zeta / (w * h)) * c)) / k
    D = (1.0 - 2.0 * zeta / (w * h) + e * ((2.0 * zeta * zeta - 1.0) / (wd * h) * s
                                           + 2.0 * zeta / (w * h) * c)) / k
    A1 = -e * w / sq * s
    B1 = e * (c - z * s)
    C1 = (-1.0 / h + e * ((w / sq + zeta / (h * sq)) * s + c / h)) / k
    D1 = (1.0 - e * (z * s + c)) / (k * h)
    return A, B, C, D, A1, B1, C1, D1


@njit(cache=True, nogil=True)
def _peak_one(acc, dt, w, zeta, m, ntail, out):
    """Peaks of |u|, |u'|, |u'' + a_g| of one oscillator (``m`` sub-steps per step)."""
    n = acc.shape[0]
    h = dt / m
    A, B, C, D, A1, B1, C1, D1 = _coefficients(w, zeta, h)
    c_v = 2.0 * zeta * w
    c_u = w * w
    u = 0.0
    v = 0.0
    umax = 0.0
    vmax = 0.0
    amax = 0.0
    for i in range(n - 1):
        a0 = acc[i]
        da = (acc[i + 1] - a0) / m
        p1 = -a0
        for q in range(m):
            p0 = p1
            p1 = -(a0 + (q + 1) * da)
            un = A * u + B * v + C * p0 + D * p1
            v = A1 * u + B1 * v + C1 * p0 + D1 * p1
            u = un
            umax = max(umax, abs(u))
            vmax = max(vmax, abs(v))
            amax = max(amax, abs(c_v * v + c_u * u))
    # free vibration after the record (the ground is at rest after its last sample)
    for _q in range(ntail):
        un = A * u + B * v
        v = A1 * u + B1 * v
        u = un
        umax = max(umax, abs(u))
        vmax = max(vmax, abs(v))
        amax = max(amax, abs(c_v * v + c_u * u))
    out[0] = umax
    out[1] = vmax
    out[2] = amax


@njit(cache=True, nogil=True)
def _peaks(acc, dt, omegas, zeta, nsub, ntail, out):
    """Peaks of |u|, |u'| and |u'' + a_g| for each omega; ``out`` has shape (n, 3)."""
    for j in range(omegas.shape[0]):
        _peak_one(acc, dt, omegas[j], zeta, nsub[j], ntail[j], out[j])


@njit(cache=True, parallel=True)
def _peaks_parallel(acc, dt, omegas, zeta, nsub, ntail, out):
    for j in prange(omegas.shape[0]):
        _peak_one(acc, dt, omegas[j], zeta, nsub[j], ntail[j], out[j])


@njit(cache=True)
def sdof_history(acc, dt, w, zeta, m, u_out, v_out):
    """Relative displacement and velocity of one oscillator at the samples (compiled).

    ``acc`` (contiguous float64, step ``dt`` s, linear between samples), ``w`` (rad/s),
    ``zeta``, ``m`` sub-steps per step; ``u_out`` and ``v_out`` (``acc``'s length) receive
    ``u`` and ``u'`` from rest. The exact Nigam-Jennings recurrence of the module
    docstring, without checks: the inner loop of :func:`sdof_response` and of
    :class:`rocking.buildings.FloorMotion`."""
    n = acc.shape[0]
    h = dt / m
    A, B, C, D, A1, B1, C1, D1 = _coefficients(w, zeta, h)
    u = 0.0
    v = 0.0
    u_out[0] = 0.0
    v_out[0] = 0.0
    for i in range(n - 1):
        a0 = acc[i]
        da = (acc[i + 1] - a0) / m
        p1 = -a0
        for q in range(m):
            p0 = p1
            p1 = -(a0 + (q + 1) * da)
            un = A * u + B * v + C * p0 + D * p1
            v = A1 * u + B1 * v + C1 * p0 + D1 * p1
            u = un
        u_out[i + 1] = u
        v_out[i + 1] = v


# ------------------------------------------------------------------------------ helpers
def _signal(record, dt) -> tuple[np.ndarray, float]:
    """(samples in the record's units with its load factor, dt) from a record or an array."""
    if is_sampled(record):
        if dt is not None and not math.isclose(float(dt), record.dt, rel_tol=1e-9):
            raise ParameterError(f"dt={dt!r} s was passed but the record has dt = "
                                 f"{record.dt:g} s; leave dt out for a Record")
        return np.ascontiguousarray(record.values, dtype=np.float64), record.dt
    if hasattr(record, "acceleration") and hasattr(record, "duration"):
        raise ParameterError(f"response spectra need a sampled record, got "
                             f"{type(record).__name__}; sample it first with "
                             "rocking.motions.sample(motion, dt)")
    if dt is None:
        raise ParameterError("dt (s) is required when the accelerogram is an array")
    dt = positive("dt", dt, "s")
    return as_samples(record), dt


def _period_array(periods) -> np.ndarray:
    try:
        T = np.asarray(periods, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError("periods must be numbers (s)") from None
    if T.size == 0:
        raise ParameterError("periods must not be empty")
    if not np.all(np.isfinite(T)) or np.any(T < 0.0):
        raise ParameterError("periods must be finite and >= 0 s")
    return T


def _check_damping(damping) -> float:
    return in_range("damping", damping, 0.0, 1.0, lo_open=False, hi_open=True,
                    shown="[0, 1) (a fraction of critical: 0.05 is 5 %)")


def log_periods(tmin: float = 0.02, tmax: float = 4.0, n: int = 100) -> np.ndarray:
    """``n`` periods (s) spaced evenly in log from ``tmin`` to ``tmax``."""
    tmin = positive("tmin", tmin, "s")
    tmax = positive("tmax", tmax, "s")
    if not tmax > tmin:
        raise ParameterError(f"tmax must be > tmin = {tmin:g} s, got {tmax!r}")
    if int(n) != n or n < 2:
        raise ParameterError(f"n must be an integer >= 2, got {n!r}")
    return np.geomspace(tmin, tmax, int(n))


def peak_responses(acc, dt, T, zeta) -> np.ndarray:
    """(len(T), 3) peaks of |u|, |u'|, |u''+a_g|; rows with T == 0 are left for the caller.

    ``acc`` a contiguous float64 array (step ``dt`` s), ``T`` the periods (s) as an array,
    ``zeta`` the damping ratio: no checks (the inner loop of :func:`synthetic
    <rocking.motions.synthetic.synthetic>`)."""
    flat = T.ravel()
    pos = flat > 0.0
    out = np.zeros((flat.size, 3))
    if pos.any():
        Tp = flat[pos]
        w = 2.0 * np.pi / Tp
        nsub = np.maximum(1, np.ceil(MIN_STEPS_PER_PERIOD * dt / Tp - 1e-9)).astype(np.int64)
        ntail = np.ceil(Tp / (dt / nsub) / math.sqrt(1.0 - zeta * zeta)).astype(np.int64) + 1
        res = np.empty((Tp.size, 3))
        work = float(np.sum(nsub)) * acc.size
        kernel = _peaks_parallel if work > PARALLEL_WORK else _peaks
        kernel(acc, float(dt), w, float(zeta), nsub, ntail, res)
        out[pos] = res
    return out


# ------------------------------------------------------------------------------ public
def response_spectra(record, periods, damping: float = 0.05, *, dt: float | None = None
                     ) -> dict[str, np.ndarray]:
    """All spectral quantities at once: ``{"T", "psa", "sa", "sd", "psv", "sv"}``.

    Same arguments as :func:`response_spectrum`; one integration gives every quantity.

    Examples
    --------
    >>> from rocking.motions import load_builtin, response_spectra
    >>> sp = response_spectra(load_builtin("RSN126_GAZLI_GAZ000"), [0.5, 1.0])
    >>> sorted(sp)
    ['T', 'psa', 'psv', 'sa', 'sd', 'sv']
    >>> bool(np.allclose(sp["psv"], 2 * np.pi / sp["T"] * sp["sd"]))  # psv = omega sd
    True
    """
    acc, dt = _signal(record, dt)
    T = _period_array(periods)
    zeta = _check_damping(damping)
    peaks = peak_responses(acc, dt, T, zeta)
    flat = T.ravel()
    w = np.where(flat > 0.0, 2.0 * np.pi / np.where(flat > 0.0, flat, 1.0), 0.0)
    pga = float(np.max(np.abs(acc)))
    sd = peaks[:, 0]
    res = {
        "T": flat.copy(),
        "sd": sd,
        "psv": w * sd,
        "psa": np.where(flat > 0.0, w * w * sd, pga),
        "sv": peaks[:, 1],
        "sa": np.where(flat > 0.0, peaks[:, 2], pga),
    }
    return {k: v.reshape(T.shape) for k, v in res.items()}


def response_spectrum(record, periods, damping: float = 0.05, kind: str = "psa", *,
                      dt: float | None = None):
    """Elastic response spectrum of an accelerogram.

    Parameters
    ----------
    record : Record or array_like
        A :class:`~rocking.motions.records.Record` (its load factor applied) or an array of
        acceleration samples (then ``dt`` is required).
    periods : float or array_like
        Oscillator periods (s), >= 0; ``T = 0`` gives the PGA for ``psa``/``sa``.
    damping : float
        Damping ratio as a fraction of critical (0.05 = 5 %).
    kind : {"psa", "sa", "sd", "psv", "sv"}
        Spectral quantity (see the module doc). ``psa`` and ``sa`` are in the record's
        acceleration units (m/s^2 for a Record), ``sd`` in m, ``psv``/``sv`` in m/s.
    dt : float, optional
        Time step (s) of an array input.

    Returns
    -------
    numpy.ndarray or float
        One value per period (a float for a scalar period).

    Examples
    --------
    >>> from rocking.motions import load_builtin, response_spectrum
    >>> rec = load_builtin("RSN126_GAZLI_GAZ000")
    >>> round(response_spectrum(rec, 0.0), 4) == round(rec.pga, 4)  # T = 0: the PGA
    True
    >>> sa, sd = (response_spectrum(rec, 1.0, kind=k) for k in ("psa", "sd"))
    >>> round(sa / sd, 4) == round((2 * np.pi / 1.0) ** 2, 4)  # psa = omega^2 sd
    True
    """
    if kind not in KINDS:
        raise ParameterError(f"kind must be one of {', '.join(KINDS)}; got {kind!r}")
    out = response_spectra(record, periods, damping, dt=dt)[kind]
    return float(out) if np.ndim(out) == 0 else out


def sdof_response(record, period: float, damping: float = 0.05, *, dt: float | None = None,
                  substeps: int = 1) -> dict[str, np.ndarray]:
    """Time history of the oscillator at the record's samples (same recurrence).

    Returns ``{"t", "u", "v", "a"}``: time (s), relative displacement, relative velocity and
    absolute acceleration ``u'' + a_g`` (from the equation of motion). ``substeps`` splits
    each step (the result at the samples does not depend on it: the recurrence is exact).

    Examples
    --------
    >>> from rocking.motions import load_builtin, response_spectrum, sdof_response
    >>> rec = load_builtin("RSN126_GAZLI_GAZ000")
    >>> h = sdof_response(rec, period=1.0)
    >>> sorted(h), len(h["t"]) == len(rec)
    (['a', 't', 'u', 'v'], True)
    >>> bool(np.isclose(np.abs(h["u"]).max(), response_spectrum(rec, 1.0, kind="sd")))
    True
    """
    acc, dt = _signal(record, dt)
    T = positive("period", period, "s")
    zeta = _check_damping(damping)
    if int(substeps) != substeps or substeps < 1:
        raise ParameterError(f"substeps must be an integer >= 1, got {substeps!r}")
    w = 2.0 * math.pi / T
    u = np.empty(acc.size)
    v = np.empty(acc.size)
    sdof_history(acc, float(dt), w, zeta, int(substeps), u, v)
    return {"t": np.arange(acc.size) * dt, "u": u, "v": v,
            "a": -(2.0 * zeta * w * v + w * w * u)}


# ------------------------------------------------------------------------------ plotting
def plot_spectra(ax, periods, spectra, target=None, *, period_range=None, labels=None,
                 show_individual: bool = True, units: str = "m/s^2", logx: bool = True,
                 title: str | None = None):
    """Draw response spectra on a matplotlib Axes; returns the Axes.

    ``spectra`` is one spectrum or a 2-D array (one row per record). With several rows the
    mean, the mean +- one standard deviation (band) and, if ``show_individual``, every
    record (thin grey) are drawn. ``target`` (a callable of periods, e.g. a
    :class:`~rocking.motions.ec8.DesignSpectrum`) adds the target and 90 % of it (EC8's
    lower bound for the mean); ``period_range`` shades the periods where the match
    counts. ``units`` is ``"m/s^2"`` or ``"g"`` (values are divided by g for display).
    """
    T = np.asarray(periods, dtype=np.float64)
    S = np.atleast_2d(np.asarray(spectra, dtype=np.float64))
    k = 1.0 / G if units == "g" else 1.0
    if period_range is not None:
        ax.axvspan(*period_range, color="#e8eef8", lw=0, zorder=0,
                   label=f"period range {period_range[0]:g}-{period_range[1]:g} s")
    if S.shape[0] > 1:
        if show_individual:
            for i, row in enumerate(S):
                ax.plot(T, k * row, color="0.72", lw=0.5, zorder=1,
                        label="individual records" if i == 0 else None)
        mean = S.mean(axis=0)
        std = S.std(axis=0, ddof=1)
        ax.fill_between(T, k * (mean - std), k * (mean + std), color="#0072B2", alpha=0.18,
                        lw=0, zorder=2, label="mean ± 1 std")
        ax.plot(T, k * mean, color="#0072B2", lw=1.8, zorder=4,
                label=f"mean of {S.shape[0]} records")
    else:
        ax.plot(T, k * S[0], color="#0072B2", lw=1.4, zorder=4,
                label=(labels[0] if labels else "response spectrum"))
    if target is not None:
        Tt = np.geomspace(max(T[T > 0].min(), 1e-3), T.max(), 400)
        tv = np.asarray(target(Tt))
        ax.plot(Tt, k * tv, color="#D55E00", lw=1.8, zorder=5, label="target")
        ax.plot(Tt, 0.9 * k * tv, color="#D55E00", lw=1.1, ls="--", zorder=5,
                label="90 % of target")
    if logx:
        ax.set_xscale("log")
    ax.set_xlim(T[T > 0].min(), T.max())
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel("period T (s)")
    ax.set_ylabel(f"pseudo-acceleration ({'g' if units == 'g' else 'm/s²'})")
    ax.grid(True, which="both", alpha=0.3)
    if title:
        ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8, loc="upper right", framealpha=0.9)
    return ax
