"""The fits: ``alpha`` and ``p`` from Eq 13, their uncertainties, and ``mu`` from Eq 12.

**Eq 13.** The residuals are the measured rise (crossing to peak) and fall (peak to
crossing) times minus ``T(r_k)``, weighted by the timing precision of each half-cycle.
Since ``T = G(r, alpha) / p``, the error surface is a quadratic in ``1/p`` for each
``alpha``: a grid over ``alpha`` with ``p`` profiled out in closed form gives a global
start, which :func:`scipy.optimize.least_squares` refines (plain, then with a robust loss
scaled to the residuals).

**Uncertainties** come from the Jacobian of the half-cycle durations (the rise-minus-fall
part of the residuals carries no information on ``alpha`` and ``p``), never below the
timing noise, or from a bootstrap over half-cycles.

**Eq 12.** ``mu_n = (E_n / E_0)^(1 / 2n)`` with ``E = cos(alpha - r) - cos(alpha)``, the
first used amplitude as ``r_0``; ``mu`` is their mean and ``mu_std`` their spread.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import least_squares

from ..errors import IdentificationError
from .time_model import scaled_quarter_time, scaled_quarter_time_dalpha, sigma_coefficients
from .timing import HalfCycleTimes

_NOT_IDENTIFIABLE = (
    "alpha cannot be identified: the error surface decreases up to alpha = pi/2. The "
    "amplitudes are too small compared with alpha (only p*sqrt(alpha) is determined) or the "
    "times do not follow free rocking")


def _fit_alpha_p(r, d, v, loss: str, x0=None):
    """Eq 13: weighted (robust) least squares of durations ``d`` against ``G(r, alpha)/p``.

    Without a start ``x0`` the error surface is first profiled over a grid of ``alpha``
    (``p`` in closed form) for a global start.
    """
    r_max = float(r.max())
    a_lo = r_max * (1.0 + 1e-9)
    a_hi = 0.5 * math.pi - 1e-9
    if a_lo >= a_hi:
        raise IdentificationError(f"the largest amplitude ({r_max:.4g} rad) is not below "
                                  "pi/2: this is not free rocking")
    if x0 is None or not a_lo < x0[0] < a_hi:
        grid = r_max + (a_hi - r_max) * np.logspace(-4, 0, 160)
        A, B, C = sigma_coefficients(r, d, v * v, grid)
        with np.errstate(divide="ignore", invalid="ignore"):
            prof = np.where(B > 0, A - B * B / C, np.inf)
        j = int(np.argmin(prof))
        if not np.isfinite(prof[j]):
            raise IdentificationError("the error surface has no finite minimum")
        if j == grid.size - 1:
            raise IdentificationError(_NOT_IDENTIFIABLE)
        x0 = np.array([grid[j], C[j] / B[j]])
    x0 = np.asarray(x0, dtype=float)

    def fun(x):
        return v * (d - scaled_quarter_time(r, x[0]) / x[1])

    def jac(x):
        G = scaled_quarter_time(r, x[0])
        return np.column_stack((-v * scaled_quarter_time_dalpha(r, x[0]) / x[1],
                                v * G / (x[1] * x[1])))

    lb, ub = np.array([a_lo, 1e-9]), np.array([a_hi, np.inf])
    x0 = np.clip(x0, lb + 1e-12, ub - 1e-12)
    sol = least_squares(fun, x0, jac=jac, bounds=(lb, ub), x_scale=np.abs(x0), method="trf",
                        xtol=1e-12, ftol=1e-12, gtol=1e-12)
    if loss != "linear":
        e = sol.fun
        scale = 1.4826 * float(np.median(np.abs(e - np.median(e))))
        if scale > 0:
            sol = least_squares(fun, sol.x, jac=jac, bounds=(lb, ub), x_scale=np.abs(sol.x),
                                method="trf", loss=loss, f_scale=2.5 * scale,
                                xtol=1e-12, ftol=1e-12, gtol=1e-12)
    if sol.x[0] > a_hi - 1e-6:
        raise IdentificationError(_NOT_IDENTIFIABLE)
    return sol


def coarse_alpha_p(amp, tpk, cross) -> tuple[float, float]:
    """A first ``(alpha, p)`` from the coarse events of ``n`` consecutive half-cycles.

    ``amp``, ``tpk`` are their amplitudes and peak times, ``cross`` the ``n + 1`` crossings
    around them: unweighted Eq 13 on the rise and fall times, or, if that fails, twice the
    largest amplitude and ``p`` from the half-cycle durations ``2 T(r)``.
    """
    n = amp.size
    try:
        sol = _fit_alpha_p(np.concatenate((amp, amp)),
                           np.concatenate((tpk - cross[:-1], cross[1:] - tpk)),
                           np.ones(2 * n), "linear")
        return float(sol.x[0]), float(sol.x[1])
    except IdentificationError:  # rough: twice the largest amplitude, p from small swings
        alpha = min(2.0 * float(np.max(amp)), 0.5 * math.pi - 1e-6)
        half = 0.5 * np.diff(cross)
        return alpha, float(np.median(scaled_quarter_time(amp, alpha) / half))


def fit_times(times: HalfCycleTimes, loss: str, x0=None):
    """Weighted Eq 13 on the measured rise and fall times (see :func:`_fit_alpha_p`)."""
    r2, d2, v2, _ = times.intervals()
    return _fit_alpha_p(r2, d2, v2, loss, x0=x0)


def covariance(times: HalfCycleTimes, alpha: float, p: float) -> np.ndarray:
    """Covariance of ``(alpha, p)`` from the Jacobian of the normalised half-cycle durations
    ``D_k = 2 T(r_k)`` (the fall ``T(r_0)`` for the release); the rise-minus-fall part of
    the residuals does not depend on ``alpha``, ``p``."""
    amp, rise, fall, s_k, half = times.amp, times.rise, times.fall, times.s_k, times.half
    G = scaled_quarter_time(amp, alpha)
    dG = scaled_quarter_time_dalpha(amp, alpha)
    mult = np.where(half, 1.0, 2.0)
    D = np.where(half, fall, rise + fall)
    u = (D - mult * G / p) / s_k
    Ju = np.column_stack((-mult * dG / p, mult * G / p ** 2)) / s_k[:, None]
    rob = 1.4826 * float(np.median(np.abs(u - np.median(u))))
    keep = np.abs(u) <= 5.0 * rob if rob > 0 else np.ones_like(u, dtype=bool)
    dof = max(int(keep.sum()) - 2, 1)
    s_u2 = max(float(np.sum(u[keep] ** 2)) / dof, 1.0)  # never below the timing noise
    try:
        return s_u2 * np.linalg.inv(Ju[keep].T @ Ju[keep])
    except np.linalg.LinAlgError:
        return np.full((2, 2), np.nan)


def uncertainties(times: HalfCycleTimes, alpha: float, p: float, n_boot: int,
                  seed) -> tuple[np.ndarray, str]:
    """``(cov, how)``: the covariance of ``(alpha, p)`` from the Jacobian
    (:func:`covariance`) or, if ``n_boot > 0``, from bootstrap resamples of the half-cycles
    (Eq 13 refitted on each)."""
    if n_boot > 0 and (boot := _bootstrap(times, n_boot, seed)) is not None:
        return boot
    return covariance(times, alpha, p), "jacobian"


def _bootstrap(times: HalfCycleTimes, n_boot: int, seed):
    """``(cov, how)`` from resampling the half-cycles, or None with fewer than 2 fits."""
    r2, d2, v2, owner = times.intervals()
    n = times.amp.size
    rng = np.random.default_rng(seed)
    est = []
    for _ in range(n_boot):
        pick = rng.integers(0, n, n)
        if np.unique(pick).size < 3:
            continue
        ii = np.concatenate([np.flatnonzero(owner == k) for k in pick])
        try:
            b = _fit_alpha_p(r2[ii], d2[ii], v2[ii], "linear")
        except IdentificationError:
            continue
        est.append(b.x)
    if len(est) < 2:
        return None
    return np.cov(np.asarray(est).T), f"bootstrap ({len(est)} resamples)"


def restitution(amp, ks, alpha: float):
    """Eq 12: ``(impact_numbers, mu_n, mu, mu_std)`` from the amplitudes ``amp`` of lobes
    ``ks`` (the first is ``r_0``; ``n = ks - ks[0]`` impacts separate them)."""
    nimp = np.array(ks) - ks[0]
    E = _energy(amp, alpha)
    mu_n = (E[1:] / E[0]) ** (1.0 / (2.0 * nimp[1:]))
    mu = float(np.mean(mu_n))
    mu_std = float(np.std(mu_n, ddof=1)) if mu_n.size > 1 else float("nan")
    return nimp, mu_n, mu, mu_std


def _energy(r, alpha):
    """``cos(alpha - r) - cos(alpha)`` without cancellation (Eq 12)."""
    return 2.0 * np.sin(alpha - 0.5 * r) * np.sin(0.5 * r)
