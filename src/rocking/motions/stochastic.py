r"""Stochastic ground motions: modulated, filtered white noise with a time-varying filter.

The records of :func:`stochastic_records` are *not* spectrum-matched: they keep the
record-to-record variability that fragility studies need (the 30 spectrum-matched
:func:`~rocking.motions.synthetic.seed_earthquakes` remove most of it).

**Model** (Rezaeian & Der Kiureghian 2008, "A stochastic ground motion model with separable
temporal and spectral nonstationarities", *Earthquake Engng Struct. Dyn.* 37:1565-1584; the
parametrisation by ``Ia``, ``D5_95``, ``t_mid`` is that of Rezaeian & Der Kiureghian 2010,
*EESD* 39:1155-1180). The acceleration before the high-pass is

.. math::  x(t) = q(t; \alpha)\, \frac{1}{\sigma_f(t)} \sum_{i:\, t_i \le t}
           h\!\left[t - t_i; \lambda(t_i)\right] u_i, \qquad
           \sigma_f^2(t) = \sum_{i:\, t_i \le t} h^2\!\left[t - t_i; \lambda(t_i)\right]

(the paper's discretised form: white-noise pulses ``u_i``, independent standard normal, at
the sample times ``t_i = i dt``; the normalisation makes the filtered noise exactly of unit
variance at every sample, so that the variance of ``x`` is ``q^2``), with

* the impulse response of a linear oscillator whose parameters are those *at the time of
  the pulse*, ``lambda(tau) = (omega_f(tau), zeta_f)``:

  .. math:: h[t - \tau; \lambda(\tau)] = \frac{\omega_f(\tau)}{\sqrt{1 - \zeta_f^2}}
            e^{-\zeta_f \omega_f(\tau) (t - \tau)}
            \sin\!\left[\omega_f(\tau) \sqrt{1 - \zeta_f^2}\, (t - \tau)\right],
            \quad t \ge \tau,

* a filter frequency varying linearly in time, ``omega_f(t) = omega_mid + omega_prime
  (t - t_mid)``, and a constant damping ratio ``zeta_f``;
* the gamma-like modulating function

  .. math:: q(t; \alpha) = \alpha_1 t^{\alpha_2 - 1} e^{-\alpha_3 t}, \quad t \ge 0,

  whose parameters follow from the physical ones: ``q^2`` is proportional to the density
  of a gamma distribution of shape ``k = 2 alpha_2 - 1`` and rate ``2 alpha_3``, so the
  expected Husid curve is its CDF; ``D5_95`` is the time between its 5 % and 95 % points
  and ``t_mid`` its 45 % point (the paper's definition of the middle of the strong
  motion), which fix ``k`` (a 1-D root) and ``alpha_3``; then ``alpha_1`` gives the
  expected Arias intensity ``Ia = pi / (2 g) int q^2 dt = pi / (2 g) alpha_1^2
  Gamma(k) / (2 alpha_3)^k``. ``alpha_2 > 1`` (``q(0) = 0``) requires
  ``D5_95 < 4.925 t_mid``.

**High-pass** (Rezaeian & Der Kiureghian's post-processing): ``x`` drives a critically
damped oscillator ``z'' + 2 omega_c z' + omega_c^2 z = x(t)`` from rest, and the record is
``a = z'' = x - 2 omega_c z' - omega_c^2 z``: a second-order high-pass of corner
``omega_c`` whose ground velocity ``z'`` and displacement ``z`` return to zero once the
motion has died out. It is integrated exactly for ``x`` linear between samples (matrix
exponential). ``omega_c = 0`` skips it.

**What the parameters mean for the records.** ``D5_95`` and ``t_mid`` are those of the
*expected* Husid curve of ``q``; the records scatter around them (the high-pass adds a
little low-frequency tail). ``Ia`` is the expected Arias intensity *of the final records*
as :func:`~rocking.motions.processing.intensity_measures` measures it (after the high-pass,
linear between samples): ``alpha_1`` is multiplied by the factor
(``meta["alpha1_factor"]``, 1.03 for the defaults) that makes the exact expectation
``pi / (2 g) sum_i int a_i^2 dt`` equal ``Ia``, ``a_i`` being the final record made by the
unit pulse ``i`` alone. With the paper's ``alpha_1`` the defaults' records would average
6 % below ``Ia``: the high-pass removes the content below about ``omega_c`` and the linear
interpolation loses ``(1 - rho) / 3`` of the energy (``rho`` the correlation of successive
samples).

**Implementation.** The sum over pulses is computed directly (``O(N L)`` per record,
compiled with numba, records in parallel): each pulse is a complex phasor
``(omega_i / sqrt(1 - zeta_f^2)) u_i exp[(-zeta_f + i sqrt(1 - zeta_f^2)) omega_i
(t - t_i)]`` rotated by a constant factor per step, whose imaginary part is ``h u_i``;
pulses older than ``L`` samples, whose envelope has decayed below ``1e-16`` of its start,
are dropped (below the rounding of the sum). ``sigma_f`` does not depend on the noise and is
computed once per call.

**Seeds.** Record ``i`` (``start <= i < start + n``) draws its ``N`` pulses from
``numpy.random.default_rng(numpy.random.SeedSequence(seed, spawn_key=(STREAM, i)))``: a record
depends only on ``(seed, i)`` and the parameters, so generating records 0-9 and then 10-19
(``start=10``) gives the same records, bit for bit, as generating 0-19 at once.

**Record-to-record variability of the parameters.** The parameters are scalars. To draw
them per record (e.g. from the joint distribution that Rezaeian & Der Kiureghian 2010 fit
to the NGA records, or from a ground-motion model for a scenario), draw one parameter set
per record and generate each record on its own with its index, which keeps the noise of
record ``i`` tied to ``(seed, i)``::

    rng = np.random.default_rng(7)
    records = [stochastic_records(1, seed=42, start=i, Ia=ia, D5_95=d)[0]
               for i, (ia, d) in enumerate(zip(rng.lognormal(np.log(0.5), 0.6, 100),
                                               rng.lognormal(np.log(10.0), 0.4, 100)))]
"""

from __future__ import annotations

import functools
import math
import numbers

import numpy as np
from numba import njit, prange

from .._validate import as_float, in_range, non_negative, positive
from ..errors import ParameterError
from ..units import G
from .records import Record

__all__ = ["stochastic_records", "modulating_parameters", "modulating_function",
           "filter_frequency", "DEFAULTS"]

DEFAULTS = {
    "Ia": 0.5,                          # m/s: expected Arias intensity (moderate shaking)
    "D5_95": 10.0,                      # s: significant duration 5-95 %
    "t_mid": 6.0,                       # s: time of 45 % of the Arias intensity
    "omega_mid": 2.0 * math.pi * 5.0,   # rad/s: filter frequency at t_mid (5 Hz)
    "omega_prime": -2.0 * math.pi * 0.1,  # rad/s^2: its rate of change (-0.1 Hz/s)
    "zeta_f": 0.3,                      # filter damping ratio
    "omega_c": 2.0 * math.pi * 0.2,     # rad/s: high-pass corner (0.2 Hz)
    "dt": 0.01,                         # s: time step (100 Hz)
    "duration": None,                   # s: None = until the motion and high-pass die out
}
"""Default parameters (SI units): a moderate earthquake, PGA ~ 0.2 g."""

_P5, _P45, _P95 = 0.05, 0.45, 0.95
_TAIL = 0.9999            # the default duration covers this fraction of the expected Ia,
                          # plus HP_DECAY / omega_c
_DROP = math.log(1e16)    # a pulse is dropped when its envelope has decayed by this (log)

HP_DECAY = 10.0
"""The default duration is ``t_tail`` plus this many ``1/omega_c``, for the high-pass to
die out."""

STREAM = 2
"""Tag of this generator's random streams (``SeedSequence`` spawn key ``(STREAM, i)``), so
that the same seed in another seeded part of the package draws independent numbers."""


# --------------------------------------------------------------------------- modulation
def _ratio(k: float) -> float:
    """D5-95 / t_mid of the gamma Husid curve of shape ``k`` (scale-free)."""
    from scipy.special import gammaincinv

    return float((gammaincinv(k, _P95) - gammaincinv(k, _P5)) / gammaincinv(k, _P45))


_RATIO_MAX = None  # D5_95 / t_mid at alpha_2 -> 1 (k -> 1): 4.925, computed on first use


def _ratio_max() -> float:
    global _RATIO_MAX
    if _RATIO_MAX is None:
        _RATIO_MAX = (math.log(1 / (1 - _P95)) - math.log(1 / (1 - _P5))) / math.log(
            1 / (1 - _P45))
    return _RATIO_MAX


def modulating_parameters(Ia: float, D5_95: float, t_mid: float) -> dict:
    """``alpha_1, alpha_2, alpha_3`` of ``q(t) = alpha_1 t^(alpha_2 - 1) exp(-alpha_3 t)``
    from the expected Arias intensity ``Ia`` (m/s), ``D5_95`` (s) and ``t_mid`` (s).

    Also returns the gamma shape ``k = 2 alpha_2 - 1``, the rate ``2 alpha_3`` (1/s) and the
    expected Husid times ``t5``, ``t45`` (= ``t_mid``), ``t95`` (s). The root finding is
    done once per parameter set (kept, :data:`CACHE_SIZE` sets); each call returns a new
    dict.
    """
    return dict(_cached(_modulating_parameters, Ia, D5_95, t_mid))


def _cached(func, *args):
    """``func(*args)`` through its cache; arguments that cannot be hashed (a list, an
    array: refused by the checks) bypass it, so the error is the checks' own."""
    try:
        hash(args)
    except TypeError:
        return func.__wrapped__(*args)
    return func(*args)


CACHE_SIZE = 32
"""Parameter sets whose noise-free part (:func:`record_model`, :func:`modulating_parameters`)
is kept: a campaign checks every record's parameters and makes its records chunk by chunk,
all with the same parameters, so that part is computed once, not once per record or chunk
(a 20 s record: 25 ms of serial work, five times the record's own noise filtering)."""


@functools.lru_cache(maxsize=CACHE_SIZE, typed=True)
def _modulating_parameters(Ia, D5_95, t_mid) -> dict:
    Ia = positive("Ia", Ia, "m/s")
    D5_95 = positive("D5_95", D5_95, "s")
    t_mid = positive("t_mid", t_mid, "s")
    rmax = _ratio_max()
    if not D5_95 < rmax * t_mid * (1 - 1e-9):
        raise ParameterError(
            f"D5_95 must be in (0, {rmax:.4f} t_mid) = (0, {rmax * t_mid:g}) s for "
            f"t_mid = {t_mid:g} s (the modulating function needs alpha_2 > 1), "
            f"got {D5_95!r}")
    from scipy.optimize import brentq
    from scipy.special import gammaincinv, gammaln

    target = D5_95 / t_mid
    lo, hi = math.log1p(1e-9), math.log(1e8)
    if _ratio(math.exp(hi)) >= target:
        raise ParameterError(f"D5_95 / t_mid = {target:g} is too small (a modulating "
                             f"function narrower than the gamma family allows); got "
                             f"D5_95={D5_95!r} s, t_mid={t_mid!r} s")
    logk = brentq(lambda x: _ratio(math.exp(x)) - target, lo, hi, xtol=1e-14, rtol=1e-14)
    k = math.exp(logk)
    scale = t_mid / float(gammaincinv(k, _P45))  # 1 / (2 alpha_3)
    rate = 1.0 / scale
    energy = Ia * 2.0 * G / math.pi              # int q^2 dt = a1^2 Gamma(k) / rate^k
    log_a1 = 0.5 * (math.log(energy) + k * math.log(rate) - float(gammaln(k)))
    return {
        "alpha1": math.exp(log_a1), "alpha2": 0.5 * (k + 1.0), "alpha3": 0.5 * rate,
        "k": k, "rate": rate,
        "t5": scale * float(gammaincinv(k, _P5)), "t45": t_mid,
        "t95": scale * float(gammaincinv(k, _P95)),
        "t_tail": scale * float(gammaincinv(k, _TAIL)),
    }


def modulating_function(t, Ia: float, D5_95: float, t_mid: float) -> np.ndarray:
    """``q(t)`` (m/s^2): the standard deviation of the acceleration before the high-pass."""
    a = modulating_parameters(Ia, D5_95, t_mid)
    t = np.asarray(t, dtype=np.float64)
    out = np.zeros(t.shape)
    pos = t > 0.0
    tp = t[pos]
    out[pos] = np.exp(math.log(a["alpha1"]) + (a["alpha2"] - 1.0) * np.log(tp)
                      - a["alpha3"] * tp)
    return out


def filter_frequency(t, omega_mid: float, omega_prime: float, t_mid: float) -> np.ndarray:
    """``omega_f(t) = omega_mid + omega_prime (t - t_mid)`` (rad/s)."""
    return omega_mid + omega_prime * (np.asarray(t, dtype=np.float64) - t_mid)


# --------------------------------------------------------------------------- kernels
@njit(cache=True)
def _sigma2(amp, rot_re, rot_im, L):
    """``sigma_f^2`` at the samples: the same recurrence as :func:`_filtered`, ``u = 1``."""
    N = amp.size
    zr = np.zeros(N)
    zi = np.zeros(N)
    out = np.zeros(N)
    for k in range(N):
        acc = 0.0
        for i in range(max(0, k - L + 1), k):
            a = zr[i] * rot_re[i] - zi[i] * rot_im[i]
            b = zr[i] * rot_im[i] + zi[i] * rot_re[i]
            zr[i] = a
            zi[i] = b
            acc += b * b
        zr[k] = amp[k]
        out[k] = acc
    return out


@njit(cache=True, parallel=True)
def _filtered(u, amp, rot_re, rot_im, scale, L):
    """``x[r, k] = scale[k] sum_{i<k} h(t_k - t_i; omega_i) u[r, i]`` for every record r.

    Pulse i is the phasor ``amp_i u_i exp(c omega_i (t - t_i))``, multiplied by
    ``rot_i = exp(c omega_i dt)`` at every step; its imaginary part is ``h u_i``.
    Each record is computed sequentially on its own (the same numbers whatever ``n``)."""
    n, N = u.shape
    out = np.zeros((n, N))
    for r in prange(n):
        zr = np.zeros(N)
        zi = np.zeros(N)
        for k in range(N):
            acc = 0.0
            for i in range(max(0, k - L + 1), k):
                a = zr[i] * rot_re[i] - zi[i] * rot_im[i]
                b = zr[i] * rot_im[i] + zi[i] * rot_re[i]
                zr[i] = a
                zi[i] = b
                acc += b
            zr[k] = amp[k] * u[r, k]
            out[r, k] = scale[k] * acc
    return out


@njit(cache=True, parallel=True)
def _pulse_energy(amp, rot_re, rot_im, scale, L, phi, e0, e1, dt, wc, hp):
    """``int a_i(t)^2 dt`` of the final record ``a_i`` made by a unit pulse at ``t_i``, for
    every ``i`` (``a`` linear between samples, as the records are measured). The expected
    ``int a^2 dt`` of a record is their sum (the pulses are independent, unit variance)."""
    N = amp.size
    out = np.zeros(N)
    for i in prange(N):
        zr = amp[i]
        zi = 0.0
        z = 0.0
        v = 0.0
        a_prev = 0.0
        x_prev = 0.0
        e = 0.0
        for k in range(i + 1, N):
            x = 0.0
            if k - i < L:
                a = zr * rot_re[i] - zi * rot_im[i]
                b = zr * rot_im[i] + zi * rot_re[i]
                zr = a
                zi = b
                x = scale[k] * b
            if hp:
                sl = (x - x_prev) / dt
                z1 = phi[0, 0] * z + phi[0, 1] * v + e0[0] * x_prev + e1[0] * sl
                v1 = phi[1, 0] * z + phi[1, 1] * v + e0[1] * x_prev + e1[1] * sl
                z = z1
                v = v1
                acc = x - 2.0 * wc * v - wc * wc * z
            else:
                acc = x
            e += dt * (a_prev * a_prev + a_prev * acc + acc * acc) / 3.0
            a_prev = acc
            x_prev = x
        out[i] = e
    return out


@njit(cache=True, parallel=True)
def _highpass(x, phi, e0, e1, dt, wc):
    """``z''`` of ``z'' + 2 wc z' + wc^2 z = x`` from rest, exact for ``x`` linear between
    samples: ``s_{k+1} = phi s_k + e0 x_k + e1 (x_{k+1} - x_k) / dt`` with ``s = (z, z')``."""
    n, N = x.shape
    out = np.empty((n, N))
    for r in prange(n):
        z = 0.0
        v = 0.0
        for k in range(N):
            out[r, k] = x[r, k] - 2.0 * wc * v - wc * wc * z
            if k + 1 < N:
                xk = x[r, k]
                sl = (x[r, k + 1] - xk) / dt
                z1 = phi[0, 0] * z + phi[0, 1] * v + e0[0] * xk + e1[0] * sl
                v1 = phi[1, 0] * z + phi[1, 1] * v + e0[1] * xk + e1[1] * sl
                z = z1
                v = v1
    return out


def _highpass_matrices(wc: float, dt: float):
    """``phi``, ``e0``, ``e1`` of :func:`_highpass` (matrix exponential of the augmented
    system ``[z, z', x, x']``, ``x'`` constant over the step)."""
    from scipy.linalg import expm

    M = np.zeros((4, 4))
    M[0, 1] = 1.0
    M[1, 0] = -wc * wc
    M[1, 1] = -2.0 * wc
    M[1, 2] = 1.0
    M[2, 3] = 1.0
    E = expm(M * dt)
    return (np.ascontiguousarray(E[:2, :2]), np.ascontiguousarray(E[:2, 2]),
            np.ascontiguousarray(E[:2, 3]))


# --------------------------------------------------------------------------- generator
def _check_n(name: str, value, lo: int) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < lo:
        raise ParameterError(f"{name} must be an integer >= {lo}, got {value!r}")
    return int(value)


def _check_seed(seed):
    if seed is None:
        return int(np.random.SeedSequence().entropy)
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or seed < 0:
        raise ParameterError(f"seed must be a non-negative integer (or None), got {seed!r}")
    return int(seed)


def record_model(Ia, D5_95, t_mid, omega_mid, omega_prime, zeta_f, omega_c, dt,
                 duration) -> dict:
    """Validated parameters and everything that does not depend on the noise (raises
    :class:`~rocking.ParameterError` as :func:`stochastic_records` does: the campaign spec
    calls it to check a stochastic motion before any record is generated).

    Computed once per parameter set (the last :data:`CACHE_SIZE` sets are kept, keyed by
    the values and their types: a value refused once is refused again): the returned dict
    and its arrays are shared by every call with the same parameters and must not be
    modified.

    Examples
    --------
    >>> from rocking.motions.stochastic import record_model
    >>> args = (0.5, 10.0, 6.0, 31.4, -0.6, 0.3, 1.2, 0.01, 20.0)
    >>> m = record_model(*args)
    >>> m["N"], record_model(*args) is m
    (2001, True)
    """
    return _cached(_record_model, Ia, D5_95, t_mid, omega_mid, omega_prime, zeta_f,
                   omega_c, dt, duration)


@functools.lru_cache(maxsize=CACHE_SIZE, typed=True)
def _record_model(Ia, D5_95, t_mid, omega_mid, omega_prime, zeta_f, omega_c, dt,
                  duration) -> dict:
    alpha = modulating_parameters(Ia, D5_95, t_mid)
    omega_mid = positive("omega_mid", omega_mid, "rad/s")
    omega_prime = as_float("omega_prime", omega_prime)
    zeta_f = in_range("zeta_f", zeta_f, 0.0, 1.0)
    omega_c = non_negative("omega_c", omega_c, "rad/s")
    dt = positive("dt", dt, "s")
    if duration is None:
        duration = alpha["t_tail"] + (HP_DECAY / omega_c if omega_c > 0.0 else 0.0)
        N = int(math.ceil(duration / dt - 1e-9)) + 1
    else:
        duration = positive("duration", duration, "s")
        if duration < alpha["t95"]:
            raise ParameterError(
                f"duration must be >= t95 = {alpha['t95']:g} s (the expected 95 % Arias "
                f"time of the modulating function), got {duration!r}")
        N = int(round(duration / dt)) + 1
    if N < 4:
        raise ParameterError(f"dt must be < duration / 3 = {duration / 3:g} s, got {dt!r}")
    t = np.arange(N) * dt
    w = filter_frequency(t, omega_mid, omega_prime, t_mid)
    w_hi = math.pi / (2.0 * dt)  # at least 4 samples per filter period
    for tt, ww in ((t[0], w[0]), (t[-1], w[-1])):
        if not 0.0 < ww < w_hi:
            raise ParameterError(
                f"omega_f(t) = omega_mid + omega_prime (t - t_mid) must stay in (0, "
                f"pi / (2 dt)) = (0, {w_hi:g}) rad/s over the record; at t = {tt:g} s it is "
                f"{ww:g} (omega_mid={omega_mid:g} rad/s, omega_prime={omega_prime:g} "
                f"rad/s^2, duration={t[-1]:g} s, dt={dt:g} s)")
    sq = math.sqrt(1.0 - zeta_f * zeta_f)
    amp = w / sq
    rot = np.exp(complex(-zeta_f, sq) * w * dt)
    L = int(min(N, math.ceil(_DROP / (zeta_f * float(w.min()) * dt)) + 1))
    rot_re = np.ascontiguousarray(rot.real)
    rot_im = np.ascontiguousarray(rot.imag)
    s2 = _sigma2(amp, rot_re, rot_im, L)
    q = np.zeros(N)
    q[1:] = np.exp(math.log(alpha["alpha1"]) + (alpha["alpha2"] - 1.0) * np.log(t[1:])
                   - alpha["alpha3"] * t[1:])
    scale = np.zeros(N)
    scale[1:] = q[1:] / np.sqrt(s2[1:])
    if omega_c > 0.0:
        phi, e0, e1 = _highpass_matrices(omega_c, dt)
    else:
        phi, e0, e1 = np.eye(2), np.zeros(2), np.zeros(2)
    energy = _pulse_energy(amp, rot_re, rot_im, scale, L, phi, e0, e1, dt, omega_c,
                           omega_c > 0.0)
    ia_model = math.pi / (2.0 * G) * math.fsum(energy.tolist())
    factor = math.sqrt(Ia / ia_model)
    scale *= factor
    return {
        "params": {"Ia": Ia, "D5_95": D5_95, "t_mid": t_mid, "omega_mid": omega_mid,
                   "omega_prime": omega_prime, "zeta_f": zeta_f, "omega_c": omega_c,
                   "dt": dt, "duration": float(t[-1])},
        "alpha": alpha, "N": N, "L": L, "amp": amp, "rot_re": rot_re, "rot_im": rot_im,
        "scale": scale, "q": q * factor, "alpha1_factor": factor,
        "hp": (phi, e0, e1),
    }


def stochastic_records(n: int, seed: int | None = 0, *, start: int = 0,
                       Ia: float = DEFAULTS["Ia"], D5_95: float = DEFAULTS["D5_95"],
                       t_mid: float = DEFAULTS["t_mid"],
                       omega_mid: float = DEFAULTS["omega_mid"],
                       omega_prime: float = DEFAULTS["omega_prime"],
                       zeta_f: float = DEFAULTS["zeta_f"],
                       omega_c: float = DEFAULTS["omega_c"],
                       dt: float = DEFAULTS["dt"],
                       duration: float | None = DEFAULTS["duration"]) -> list[Record]:
    r"""``n`` stochastic accelerograms (Rezaeian & Der Kiureghian 2008; see the module doc).

    Parameters
    ----------
    n : int
        Number of records (>= 1).
    seed : int, optional
        Non-negative integer (default 0); the records are a function of ``(seed, index)``.
        ``None`` draws fresh entropy (stored in each record's ``meta["seed"]`` to repeat it).
    start : int
        Index of the first record (>= 0): records ``start .. start + n - 1``.
    Ia : float
        Expected Arias intensity (m/s), > 0. Default 0.5.
    D5_95 : float
        Significant duration 5-95 % (s), in ``(0, 4.925 t_mid)``. Default 10.
    t_mid : float
        Time of the middle of the strong motion, 45 % of ``Ia`` (s), > 0. Default 6.
    omega_mid : float
        Filter frequency at ``t_mid`` (rad/s), > 0. Default ``2 pi 5`` (5 Hz).
    omega_prime : float
        Rate of change of the filter frequency (rad/s^2). Default ``-2 pi 0.1``
        (-0.1 Hz/s). ``omega_f(t)`` must stay in ``(0, pi / (2 dt))`` over the record.
    zeta_f : float
        Filter damping ratio, in (0, 1). Default 0.3.
    omega_c : float
        Corner of the critically damped high-pass (rad/s), >= 0 (0: none). Default
        ``2 pi 0.2`` (0.2 Hz).
    dt : float
        Time step (s), > 0. Default 0.01.
    duration : float, optional
        Record length (s), >= the expected ``t95``. Default: until 99.99 % of the expected
        Arias intensity, plus ``10 / omega_c`` for the high-pass oscillator to come to rest
        (so that the final velocity and displacement are ~0): 32.7 s for the defaults.

    Returns
    -------
    list of Record
        In m/s^2, sampled every ``dt`` from ``t = 0``; ``number`` is the record's index,
        ``meta`` holds ``seed``, ``index``, the model name and its parameters.

    Examples
    --------
    >>> from rocking.motions import stochastic_records
    >>> recs = stochastic_records(2, seed=0)
    >>> [r.number for r in recs], recs[0].dt
    ([0, 1], 0.01)
    >>> again = stochastic_records(1, seed=0, start=1)[0]  # a function of (seed, index)
    >>> bool(np.array_equal(again.values, recs[1].values))
    True
    """
    n = _check_n("n", n, 1)
    start = _check_n("start", start, 0)
    seed = _check_seed(seed)
    m = record_model(Ia, D5_95, t_mid, omega_mid, omega_prime, zeta_f, omega_c, dt, duration)
    N = m["N"]
    u = np.empty((n, N))
    for j in range(n):
        rng = np.random.default_rng(np.random.SeedSequence(seed,
                                                           spawn_key=(STREAM, start + j)))
        u[j] = rng.standard_normal(N)
    x = _filtered(u, m["amp"], m["rot_re"], m["rot_im"], m["scale"], m["L"])
    p = m["params"]
    if p["omega_c"] > 0.0:
        x = _highpass(x, *m["hp"], p["dt"], p["omega_c"])
    out = []
    for j in range(n):
        i = start + j
        meta = {"model": "Rezaeian & Der Kiureghian (2008)", "seed": seed, "index": i,
                **p, "alpha1_factor": m["alpha1_factor"]}
        out.append(Record(x[j], p["dt"], name=f"stochastic {i}", number=i, meta=meta))
    return out
