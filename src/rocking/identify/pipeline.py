r"""Free-rocking identification of ``alpha``, ``p`` and ``mu`` (Peña et al. 2007, Sec. 4.1).

The paper calibrates the classical model on free-rocking tests: ``alpha`` and ``p`` minimise
an error surface between measured and predicted times of the rocking peaks (Eq 13), and
``mu`` follows from the energy of successive amplitudes (Eq 12). :func:`free_rocking` does
the same on a measured record::

    import rocking.identify as ri
    fit = ri.free_rocking(t, theta, units="deg")        # or ri.from_csv("test.csv")
    fit.alpha, fit.p, fit.mu, fit.alpha_std             # rad, 1/s, -, rad
    fit.plot_error_surface(); fit.plot_fit(theoretical=rocking.specimen(2))

**Time model.** Between two impacts energy is conserved,
``theta'^2 = 2 p^2 [cos(alpha - r) - cos(alpha - |theta|)]`` for a half-cycle of amplitude
``r``, so the time from the peak ``r`` to ``theta = 0`` is

.. math::

    T(r) = \frac{1}{p\sqrt 2}\int_0^r \frac{dx}{\sqrt{\cos(\alpha - r) - \cos(\alpha - x)}}

(Eq 11 as printed, with ``cos(x - alpha) - cos(alpha)`` under the root and the amplitude in
the limits only, is not this integral). Each half-cycle of amplitude ``r_k`` rises from the
crossing before it to its peak in ``T(r_k)`` and falls back in ``T(r_k)``; the impact
between half-cycles scales the velocity, so the next one has its own ``r_{k+1}``.
:func:`quarter_time` evaluates ``T`` with the substitution ``x = r (1 - u^2)``, which removes
the inverse-square-root singularity at ``x = r``, and a fixed 32-point Gauss-Legendre rule
in ``u`` (error < 1e-10 for ``r < 0.98 alpha``), vectorised over ``r``, ``alpha`` and ``p``.

**Measured events.** The noise level is estimated from third differences of the record; the
offset is the level where the record ends at rest, or, if it does not, the centre of the
oscillation from a binomial (1, 3, 3, 1)/8 filter of successive signed peaks (which cancels
the decay of the amplitudes to third order). Half-cycles are separated with hysteresis
(5 noise std) and located coarsely (a polynomial through each top, a straight line through
each crossing). Then every half-cycle is fitted, sample by sample, with the exact
classical half-cycle at the current ``alpha``: between impacts ``pi + theta - alpha``
swings as a pendulum, so ``theta(t) = alpha - pi + 2 asin(k cd(p_k (t - t_k) | k^2))``
with ``k = cos((alpha - r_k)/2)`` (Jacobi ``cd``), a batched Levenberg-Marquardt over
``(t_k, r_k, p_k)`` per half-cycle. This gives the peak time and amplitude and, as
``t_k -+ T(r_k)``, the crossings on both sides (one estimate from each neighbouring
half-cycle, combined by their variances), all to sub-sample accuracy and without the bias
of a truncated polynomial. A first half-cycle cut by the start of the record is used too
when its peak is recorded: a release from rest (fitted as flat before the peak, if the
block was held) contributes its fall time ``T(r_0)`` at the largest amplitude, the most
telling about ``alpha``. Only half-cycles above a noise threshold are used (by default
15 noise std and 2 % of the largest amplitude), so the last ones before rest, dominated by
noise, are left out.

**Fit.** The residuals are the measured rise (crossing to peak) and fall (peak to crossing)
times minus ``T(r_k)``, weighted by the timing precision of each half-cycle (Eq 13 with
weights). Since ``T = G(r, alpha) / p``, the error surface is a quadratic in ``1/p`` for
each ``alpha``: a grid over ``alpha`` with ``p`` profiled out in closed form gives a global
start, which :func:`scipy.optimize.least_squares` refines (plain, then with a ``soft_l1``
loss scaled to the residuals). The half-cycle fits and the Eq 13 fit alternate until
``alpha`` and ``p`` settle (two or three passes). Uncertainties come from the Jacobian of
the half-cycle durations (the rise-minus-fall part of the residuals carries no information
on ``alpha`` and ``p``), never below the timing noise, or from a bootstrap over
half-cycles (``n_boot``).

**What limits the accuracy.** For small amplitudes ``T ~ sqrt(2 r / alpha) / p``: the times
only fix ``p sqrt(alpha)``, and ``alpha`` and ``p`` separate through the departure from this
law at amplitudes comparable with ``alpha``. A record whose swings are all small compared
with ``alpha``, or a heavily damped block with few half-cycles, gives correlated and
uncertain ``alpha`` and ``p`` (see ``alpha_std``, ``p_std`` and ``alpha_p_corr``); the
release from a large angle helps most.

**Restitution.** ``mu_n`` follows Eq 12 with the fitted ``alpha`` and the first used
amplitude as ``r_0`` (the release, when it is used); ``mu`` is their mean and ``mu_std``
their spread (standard deviation).

All angles are in rad, times in s (the ``units`` argument converts a record in degrees).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import IdentificationError, ParameterError, RecordError, UnitError

__all__ = ["free_rocking", "from_csv", "read_record_csv", "quarter_time", "sigma_surface",
           "FreeRockingFit", "IdentificationError"]


# ----------------------------------------------------------------------------- time model
_N_GAUSS = 32
_gx, _gw = np.polynomial.legendre.leggauss(_N_GAUSS)
_U = 0.5 * (_gx + 1.0)
_WU = 0.5 * _gw * _U  # weights with the Jacobian factor u of x = r (1 - u^2)
_HALF_U2 = 0.5 * _U * _U


def _g(r, alpha):
    """``p * T(r)``: the quarter-period integral without the 1/p (broadcasting).

    With ``x = r (1 - u^2)``, ``cos(alpha - r) - cos(alpha - x)`` becomes
    ``2 sin(alpha - r + r u^2 / 2) sin(r u^2 / 2)``, and
    ``p T = int_0^1 r u du / sqrt(sin(alpha - r + r u^2/2) sin(r u^2/2))``, smooth in ``u``.
    ``inf`` where ``r >= alpha`` (the block does not come back), 0 where ``r == 0``.
    """
    r = np.asarray(r, dtype=float)[..., None]
    a = np.asarray(alpha, dtype=float)[..., None]
    s = r * _HALF_U2
    with np.errstate(invalid="ignore", divide="ignore"):
        f = np.sin(a - r + s) * np.sin(s)
        val = np.sum(_WU * r / np.sqrt(f), axis=-1)
    rr, aa = r[..., 0], a[..., 0]
    val = np.where(rr >= aa, np.inf, val)
    return np.where(rr == 0.0, 0.0, val)


def _g_dalpha(r, alpha):
    """``d(p T)/d alpha`` (same broadcasting as :func:`_g`)."""
    r = np.asarray(r, dtype=float)[..., None]
    a = np.asarray(alpha, dtype=float)[..., None]
    s = r * _HALF_U2
    with np.errstate(invalid="ignore", divide="ignore"):
        sa = np.sin(a - r + s)
        val = -0.5 * np.sum(_WU * r * np.cos(a - r + s) / (sa * np.sqrt(sa * np.sin(s))),
                            axis=-1)
    return np.where(r[..., 0] == 0.0, 0.0, val)


def quarter_time(r, alpha, p):
    """Time (s) from a peak of amplitude ``r`` (rad) to ``theta = 0`` in free rocking.

    The exact quarter period of the classical model (energy conservation), vectorised:
    ``r``, ``alpha`` and ``p`` broadcast against each other. ``inf`` where ``r >= alpha``.
    For ``r << alpha`` it tends to ``sqrt(2 r / sin(alpha)) / p``; for slender blocks, to
    the linearised model's ``acosh(alpha / (alpha - r)) / p``.
    """
    r = np.abs(np.asarray(r, dtype=float))
    p = np.asarray(p, dtype=float)
    return _g(r, alpha) / p


def sigma_surface(amplitudes, durations, alpha, p, weights=None):
    """The error surface of Eq 13, ``Sigma = sum_j w_j^2 (tau_j - T(r_j; alpha, p))^2``.

    ``amplitudes`` (rad) and ``durations`` (s) are 1-D and pair each measured time interval
    (crossing to peak or peak to crossing) with the amplitude of its half-cycle;
    ``weights`` (1/s, default 1) scale each interval. ``alpha`` and ``p`` broadcast against
    each other (e.g. from :func:`numpy.meshgrid`); the result has their broadcast shape.
    The cost is one quadrature per distinct ``alpha``: ``Sigma`` is a quadratic in ``1/p``.
    """
    r = np.abs(np.asarray(amplitudes, dtype=float)).ravel()
    d = np.asarray(durations, dtype=float).ravel()
    if r.size != d.size:
        raise ParameterError(f"amplitudes and durations must have the same length, got "
                             f"{r.size} and {d.size}")
    w2 = np.ones_like(d) if weights is None else np.asarray(weights, float).ravel() ** 2
    alpha, p = np.broadcast_arrays(np.asarray(alpha, float), np.asarray(p, float))
    ua, inv = np.unique(alpha, return_inverse=True)
    A, B, C = _abc(r, d, w2, ua)
    inv = inv.reshape(alpha.shape)
    q = 1.0 / p
    return A - 2.0 * B[inv] * q + C[inv] * q * q


def _abc(r, d, w2, alphas, chunk: int = 64):
    """Coefficients of ``Sigma(alpha, p) = A - 2 B / p + C / p^2`` for each alpha."""
    A = float(np.sum(w2 * d * d))
    B = np.empty(alphas.size)
    C = np.empty(alphas.size)
    for i in range(0, alphas.size, chunk):
        G = _g(r[None, :], alphas[i:i + chunk, None])
        B[i:i + chunk] = np.sum(w2 * d * G, axis=1)
        C[i:i + chunk] = np.sum(w2 * G * G, axis=1)
    return A, B, C


def _energy(r, alpha):
    """``cos(alpha - r) - cos(alpha)`` without cancellation (Eq 12)."""
    return 2.0 * np.sin(alpha - 0.5 * r) * np.sin(0.5 * r)


# ----------------------------------------------------------------------------- the record
def _as_record(t, theta, units: str):
    factor = _angle_factor(units)
    try:
        t = np.asarray(t, dtype=float)
        y = np.asarray(theta, dtype=float)
    except (TypeError, ValueError) as e:
        raise ParameterError(f"t and theta must be numeric arrays ({e})") from None
    if t.ndim != 1 or y.ndim != 1:
        raise ParameterError(f"t and theta must be 1-D arrays, got shapes {t.shape} and "
                             f"{y.shape}")
    if t.size != y.size:
        raise ParameterError(f"t and theta must have the same length, got {t.size} and "
                             f"{y.size}")
    if t.size < 20:
        raise IdentificationError(f"the record has only {t.size} samples; a free-rocking "
                                  "identification needs several half-cycles")
    for name, a in (("t", t), ("theta", y)):
        bad = np.flatnonzero(~np.isfinite(a))
        if bad.size:
            raise ParameterError(f"{name} contains {bad.size} non-finite value(s) (NaN or "
                                 f"inf), the first at index {bad[0]}; remove or interpolate "
                                 "them before identifying")
    dt = np.diff(t)
    if np.any(dt <= 0):
        i = int(np.flatnonzero(dt <= 0)[0])
        raise ParameterError(f"t must be strictly increasing; t[{i + 1}] = {t[i + 1]!r} "
                             f"after t[{i}] = {t[i]!r}")
    return t, y * factor


def _angle_factor(units) -> float:
    key = str(units).strip().lower()
    if key in ("rad", "radian", "radians"):
        return 1.0
    if key in ("deg", "degree", "degrees"):
        return math.pi / 180.0
    raise UnitError(f"units must be 'rad' or 'deg', got {units!r}")


def _noise_sigma(y) -> float:
    """Std of white measurement noise from the MAD of third differences (var = 20 s^2)."""
    d3 = np.diff(y, 3)
    return 1.4826 * float(np.median(np.abs(d3 - np.median(d3)))) / math.sqrt(20.0)


def _median5(y):
    """Running median of 5 samples (the ends keep their values)."""
    if y.size < 5:
        return y.copy()
    out = y.copy()
    out[2:-2] = np.median(np.lib.stride_tricks.sliding_window_view(y, 5), axis=1)
    return out


def _rest_level(t, y, thr: float):
    """(level, start time) of the rest at the end of the record, or None if it still moves."""
    n = y.size
    m = max(10, n // 20)
    level = float(np.median(y[-m:]))
    for _ in range(3):
        out = np.flatnonzero(np.abs(y - level) > thr)
        k = int(out[-1]) + 1 if out.size else 0
        if n - k < m // 2:
            return None
        level = float(np.median(y[k:]))
    if n - k < 20 or t[-1] - t[min(k, n - 1)] < 0.25:
        return None
    return level, float(t[min(k, n - 1)])


def _lobes(z, h):
    """Half-cycles of ``z`` by hysteresis: (sign, first, last) sample indices (inclusive)."""
    idx = np.flatnonzero(np.abs(z) > h)
    if idx.size == 0:
        return np.empty(0, int), np.empty(0, int), np.empty(0, int)
    sg = np.sign(z[idx]).astype(int)
    brk = np.flatnonzero(sg[1:] != sg[:-1])
    first = np.concatenate(([idx[0]], idx[brk + 1]))
    last = np.concatenate((idx[brk], [idx[-1]]))
    sign = np.concatenate(([sg[0]], sg[brk + 1]))
    return sign, first, last


def _polyfit(x, y, deg):
    """Least-squares polynomial (coefficients, low order first) and (X^T X)^-1."""
    X = np.vander(x, deg + 1, increasing=True)
    XtX = X.T @ X
    try:
        inv = np.linalg.inv(XtX)
    except np.linalg.LinAlgError:
        return None, None
    return inv @ (X.T @ y), inv


def _peval(c, x):
    return np.polynomial.polynomial.polyval(x, c)


def _peak(t, sz, lo, hi):
    """Sub-sample peak of ``sz`` (positive lobe) in samples lo..hi: (time, value) or None."""
    seg = sz[lo:hi + 1]
    j = int(np.argmax(seg))
    top = seg[j]
    if j == 0 or j == seg.size - 1:
        return None
    thr = top - 0.3 * top
    above = np.flatnonzero(seg >= thr)
    a, b = int(above[0]), int(above[-1])
    if b - a + 1 < 3:
        a, b = j - 1, j + 1
    n = b - a + 1
    deg = 4 if n >= 11 else 2
    i0 = lo + a
    tc = t[lo + j]
    scale = max(t[lo + b] - tc, tc - t[lo + a])
    x = (t[i0:i0 + n] - tc) / scale
    c, _ = _polyfit(x, sz[i0:i0 + n], deg)
    if c is None:
        return None
    dc = np.polynomial.polynomial.polyder(c)
    roots = np.polynomial.polynomial.polyroots(dc)
    roots = roots[np.abs(roots.imag) < 1e-9].real
    roots = roots[(roots >= x[0]) & (roots <= x[-1])]
    if roots.size == 0:
        return None
    vals = _peval(c, roots)
    k = int(np.argmax(vals))
    return tc + roots[k] * scale, float(vals[k])


@dataclass
class _Events:
    sign: np.ndarray  # (L,) lobe signs
    first: np.ndarray
    last: np.ndarray
    amp: np.ndarray  # (L,) amplitude (nan if not located)
    tpk: np.ndarray  # (L,) peak time
    cross: np.ndarray  # (L-1,) crossing between lobe k and k+1 (nan if not located)
    cvar: np.ndarray  # (L-1,) its variance (s^2)


def _events(t, z, sigma, h, frac=0.3) -> _Events:
    """Half-cycles (hysteresis), coarse peaks and coarse crossings of ``z``.

    A crossing is the zero of a straight line fitted to the samples on both sides of it
    within ``frac`` of the neighbouring amplitudes (and those in between); its variance
    is the line's, from the noise std ``sigma``.
    """
    sign, first, last = _lobes(z, h)
    L = sign.size
    amp = np.full(L, np.nan)
    tpk = np.full(L, np.nan)
    ipk = np.zeros(L, dtype=int)
    for k in range(L):
        sz = sign[k] * z
        pk = _peak(t, sz, first[k], last[k])
        ipk[k] = first[k] + int(np.argmax(sz[first[k]:last[k] + 1]))
        if pk is not None:
            tpk[k], amp[k] = pk
    cross = np.full(max(L - 1, 0), np.nan)
    cvar = np.full(max(L - 1, 0), np.nan)
    for k in range(L - 1):
        a_k = sign[k] * z[ipk[k]]
        a_n = sign[k + 1] * z[ipk[k + 1]]
        seg = np.arange(ipk[k] + 1, last[k] + 1)
        high = np.flatnonzero(sign[k] * z[seg] > frac * a_k)
        i0 = int(seg[high[-1] + 1]) if high.size and high[-1] + 1 < seg.size else last[k]
        seg = np.arange(first[k + 1], ipk[k + 1])
        high = np.flatnonzero(sign[k + 1] * z[seg] > frac * a_n)
        i1 = int(seg[high[0] - 1]) if high.size and high[0] > 0 else first[k + 1]
        i0, i1 = min(i0, last[k] - 1), max(i1, first[k + 1] + 1)
        idx = np.arange(max(i0, 0), min(i1, z.size - 1) + 1)
        if idx.size < 3:
            continue
        tc = 0.5 * (t[last[k]] + t[first[k + 1]])
        x = t[idx] - tc
        X = np.column_stack((np.ones_like(x), x))
        try:
            inv = np.linalg.inv(X.T @ X)
        except np.linalg.LinAlgError:
            continue
        c0, c1 = inv @ (X.T @ z[idx])
        if c1 == 0.0 or np.sign(c1) != -sign[k]:
            continue
        xr = float(np.clip(-c0 / c1, t[last[k]] - tc, t[first[k + 1]] - tc))
        v = np.array([1.0, xr])
        cross[k] = tc + xr
        cvar[k] = sigma * sigma * float(v @ inv @ v) / (c1 * c1)
    return _Events(sign, first, last, amp, tpk, cross, cvar)


def _shape(s, r, alpha, p):
    """Exact half-cycle of the classical model and its slope, ``s`` s from the peak.

    Between impacts ``chi = pi + theta - alpha`` obeys the pendulum equation
    ``chi'' = -p^2 sin(chi)`` with turning point ``pi - alpha + r``, so
    ``theta(s) = alpha - pi + 2 asin(k cd(p s | m))``, ``k = cos((alpha - r)/2)``,
    ``m = k^2`` (Jacobi elliptic ``cd = cn/dn``). Returns ``(theta, dtheta/ds)``.
    """
    from scipy.special import ellipj

    k = np.cos(0.5 * (alpha - r))
    m = k * k
    sn, cn, dn, _ = ellipj(p * s, m)
    x = np.clip(k * cn / dn, -1.0, 1.0)
    th = alpha - math.pi + 2.0 * np.arcsin(x)
    with np.errstate(invalid="ignore", divide="ignore"):
        dth = -2.0 * k * p * (1.0 - m) * sn / (dn * dn * np.sqrt(1.0 - x * x))
    return th, np.nan_to_num(dth)


@dataclass
class _Lobe:
    sign: int
    t_lo: float  # samples strictly inside (t_lo, t_hi) are fitted
    t_hi: float
    tp: float
    r: float
    p: float
    hold: bool = False  # held at r before tp (a release from rest): theta = r for t < tp


def _lobe_shape(s, r, alpha, p, hold):
    """:func:`_shape`, flat at ``r`` before the peak where ``hold`` (a held release)."""
    th, dth = _shape(s, r, alpha, p)
    if hold is not None:
        m = hold & (s < 0.0)
        if m.any():
            th = np.where(m, r, th)
            dth = np.where(m, 0.0, dth)
    return th, dth


def _normal(lab, J, res, L):
    """Per-half-cycle normal equations ``A = J^T J`` (L x 3 x 3) and ``b = J^T res``."""
    A = np.empty((L, 3, 3))
    for i in range(3):
        for j in range(i, 3):
            A[:, i, j] = A[:, j, i] = np.bincount(lab, J[:, i] * J[:, j], minlength=L)
    b = np.column_stack([np.bincount(lab, J[:, i] * res, minlength=L) for i in range(3)])
    return A, b


def _shape_fits(t, z, lobes, alpha, sigma, iters: int = 40):
    """Fit each half-cycle with the exact shape :func:`_shape` at the given ``alpha``.

    Per half-cycle the unknowns are the peak time ``tp``, the amplitude ``r`` and a local
    ``p_k``; all half-cycles are solved together by a batched Levenberg-Marquardt. Samples
    more than 5 noise std (or 5 robust residual std) off the fit are then dropped as
    outliers (spikes, dropouts) and the fit is repeated. The crossings on either side are
    ``tp -+ T(r; alpha, p_k)``. Returns a list (None where a fit failed) of
    ``(tp, r, (t_left, var_left), (t_right, var_right), var_tp, chi2, p_k)``.
    """
    L = len(lobes)
    idx, lab = [], []
    for j, lb in enumerate(lobes):
        i0 = int(np.searchsorted(t, lb.t_lo, side="right"))
        i1 = int(np.searchsorted(t, lb.t_hi, side="left"))
        if i1 - i0 >= 5:
            idx.append(np.arange(i0, i1))
            lab.append(np.full(i1 - i0, j))
    out = [None] * L
    if not idx:
        return out
    idx = np.concatenate(idx)
    lab = np.concatenate(lab)
    sg = np.array([lb.sign for lb in lobes], dtype=float)
    y = sg[lab] * z[idx]
    tt = t[idx]
    hl = np.array([lb.hold for lb in lobes], dtype=bool)
    hold = hl[lab] if hl.any() else None
    P = np.array([[lb.tp, lb.r, lb.p] for lb in lobes], dtype=float)
    r_hi = alpha * (1.0 - 1e-9)
    P[:, 1] = np.clip(P[:, 1], 1e-12, r_hi)
    s2 = sigma * sigma
    keep = np.ones(idx.size, dtype=bool)
    for _ in range(2):
        P = _lm(P, tt[keep], y[keep], lab[keep], None if hold is None else hold[keep],
                alpha, r_hi, s2, L, iters)
        res = y - _lobe_shape(tt - P[lab, 0], P[lab, 1], alpha, P[lab, 2], hold)[0]
        scale = max(sigma, 1.4826 * float(np.median(np.abs(res[keep]))),
                    1e-9 * float(np.max(np.abs(y))))
        new = np.abs(res) <= 5.0 * scale
        if np.array_equal(new, keep):
            break
        keep = new
    tt, y, lab = tt[keep], y[keep], lab[keep]
    hold = None if hold is None else hold[keep]
    cnt = np.bincount(lab, minlength=L)
    # covariance at the solution
    s = tt - P[lab, 0]
    th, dth = _lobe_shape(s, P[lab, 1], alpha, P[lab, 2], hold)
    rss = np.bincount(lab, (y - th) ** 2, minlength=L)
    eps = 1e-7 * np.maximum(P[:, 1], 1e-9)
    th2 = _lobe_shape(s, P[lab, 1] + eps[lab], alpha, P[lab, 2], hold)[0]
    J = np.column_stack((-dth, (th2 - th) / eps[lab], s / P[lab, 2] * dth))
    A, _ = _normal(lab, J, y - th, L)
    G = _g(P[:, 1], alpha)
    dG = (_g(P[:, 1] + eps, alpha) - G) / eps
    for j in range(L):
        if cnt[j] < 5 or not np.isfinite(P[j]).all():
            continue
        try:
            C = s2 * np.linalg.inv(A[j])
        except np.linalg.LinAlgError:
            continue
        T = G[j] / P[j, 2]
        gr = np.array([1.0, dG[j] / P[j, 2], -T / P[j, 2]])
        gl = gr * np.array([1.0, -1.0, -1.0])
        tp = P[j, 0]
        out[j] = (tp, P[j, 1], (tp - T, max(float(gl @ C @ gl), 0.0)),
                  (tp + T, max(float(gr @ C @ gr), 0.0)), max(float(C[0, 0]), 0.0),
                  float(rss[j]) / max(cnt[j] - 3, 1), P[j, 2])
    return out


def _lm(P, tt, y, lab, hold, alpha, r_hi, s2, L, iters):
    """Batched Levenberg-Marquardt for :func:`_shape_fits`; returns the parameters."""
    P = P.copy()
    cnt = np.bincount(lab, minlength=L)
    th = _lobe_shape(tt - P[lab, 0], P[lab, 1], alpha, P[lab, 2], hold)[0]
    rss = np.bincount(lab, (y - th) ** 2, minlength=L)
    lam = np.full(L, 1e-4)
    active = cnt >= 5
    span = np.maximum(np.bincount(lab, tt, minlength=L) * 0.0 + 1.0, 1.0)
    for j in np.flatnonzero(active):
        tj = tt[lab == j]
        span[j] = max(float(tj[-1] - tj[0]), 1e-12)
    for _ in range(iters):
        if not active.any():
            break
        sel = active[lab]
        lb_, s = lab[sel], tt[sel] - P[lab[sel], 0]
        r, pk = P[lb_, 1], P[lb_, 2]
        hs = None if hold is None else hold[sel]
        th_a, dth = _lobe_shape(s, r, alpha, pk, hs)
        eps = 1e-7 * np.maximum(P[:, 1], 1e-9)
        th2 = _lobe_shape(s, r + eps[lb_], alpha, pk, hs)[0]
        J = np.column_stack((-dth, (th2 - th_a) / eps[lb_], s / pk * dth))
        A, b = _normal(lb_, J, y[sel] - th_a, L)
        D = np.einsum("kii->ki", A)
        M = A + (lam[:, None] * np.maximum(D, 1e-300))[:, :, None] * np.eye(3)
        M[~active] = np.eye(3)
        b[~active] = 0.0
        try:
            step = np.linalg.solve(M, b[:, :, None])[:, :, 0]
        except np.linalg.LinAlgError:
            break
        Q = P + step
        Q[:, 1] = np.clip(Q[:, 1], 1e-12, r_hi)
        Q[:, 2] = np.maximum(Q[:, 2], 1e-3 * P[:, 2])
        th_q = _lobe_shape(tt[sel] - Q[lb_, 0], Q[lb_, 1], alpha, Q[lb_, 2], hs)[0]
        new = np.bincount(lb_, (y[sel] - th_q) ** 2, minlength=L)
        better = active & (new <= rss)
        P[better] = Q[better]
        small = ((np.abs(step[:, 0]) < 1e-10 * span) & (np.abs(step[:, 1]) < 1e-10 * P[:, 1])
                 & (np.abs(step[:, 2]) < 1e-10 * P[:, 2]))
        conv = active & ((better & ((rss - new) <= 1e-10 * rss + 1e-3 * s2 + 1e-300)) | small
                         | (~better & (lam > 1e6)))
        rss = np.where(better, new, rss)
        lam = np.where(better, lam * 0.1, lam * 10.0)
        active &= ~conv
    return P


def _symmetric_offset(t, y, c0, sigma, h_of):
    """Centre of the oscillation from signed peaks: binomial (1, 3, 3, 1)/8 filter, median."""
    c = c0
    for _ in range(4):
        z = y - c
        ev = _events(t, z, sigma, h_of(z))
        m = ev.sign * ev.amp + c  # signed peak levels in the record
        good = np.isfinite(m)
        good[0] = False
        if good.size:
            good[-1] = False
        if good.size:
            big = np.nanmax(np.where(good, ev.amp, np.nan)) if good.any() else 0.0
            good &= ev.amp > 0.1 * big
        est = []
        for k in range(m.size - 3):
            if good[k:k + 4].all():
                est.append((m[k] + 3 * m[k + 1] + 3 * m[k + 2] + m[k + 3]) / 8.0)
        if len(est) < 2:
            return None
        new = float(np.median(est))
        if abs(new - c) < 0.01 * sigma + 1e-15:
            return new
        c = new
    return c


# ----------------------------------------------------------------------------- the result
@dataclass
class FreeRockingFit:
    """Result of :func:`free_rocking` (rad, s, 1/s).

    ``peak_times``, ``peak_values`` (signed, offset removed) and ``impact_numbers`` describe
    the ``n`` half-cycles used; ``crossing_times`` (``n x 2``) holds the zero crossings
    before and after each (consecutive half-cycles share one). ``residuals`` (``n x 2``)
    are measured minus model rise (crossing to peak) and fall (peak to crossing) times.
    When ``release`` is True the first half-cycle is the release (cut by the start of the
    record): only its fall is timed, and ``crossing_times[0, 0]`` and ``residuals[0, 0]``
    are NaN. ``mu_n`` (Eq 12) has one value per half-cycle after the first, for
    ``n = impact_numbers[1:]`` impacts. ``alpha_std``, ``p_std`` are standard errors
    (``cov`` their covariance); ``mu_std`` is the spread (standard deviation) of ``mu_n``.
    ``offset`` (rad) was removed from the record, ``noise`` (rad) is its estimated noise
    std, ``t`` and ``theta`` keep the record (s; rad, offset removed) for the plots.
    ``weights`` (1/s) weight the rise and fall residuals of each half-cycle in Eq 13.
    """

    alpha: float
    p: float
    mu: float
    alpha_std: float
    p_std: float
    mu_std: float
    mu_n: np.ndarray
    peak_times: np.ndarray
    peak_values: np.ndarray
    crossing_times: np.ndarray
    offset: float
    residuals: np.ndarray
    impact_numbers: np.ndarray = field(repr=False, default=None)
    crossing_std: np.ndarray = field(repr=False, default=None)
    weights: np.ndarray = field(repr=False, default=None)
    cov: np.ndarray = field(repr=False, default=None)
    noise: float = 0.0
    sampling_rate: float = 0.0
    offset_method: str = ""
    min_amplitude: float = 0.0
    uncertainty: str = "jacobian"
    n_lobes_found: int = 0
    release: bool = False
    t: np.ndarray = field(repr=False, default=None)
    theta: np.ndarray = field(repr=False, default=None)

    def __repr__(self) -> str:
        return (f"FreeRockingFit(alpha={self.alpha:.5f} ± {self.alpha_std:.5f} rad, "
                f"p={self.p:.4f} ± {self.p_std:.4f} 1/s, mu={self.mu:.4f} ± "
                f"{self.mu_std:.4f}, {self.n_half_cycles} half-cycles"
                + (", release" if self.release else "") + ")")

    # ------------------------------------------------------------------ derived
    @property
    def amplitudes(self) -> np.ndarray:
        """Amplitudes ``|peak_values|`` (rad) of the half-cycles used."""
        return np.abs(self.peak_values)

    @property
    def n_half_cycles(self) -> int:
        return int(self.peak_times.size)

    @property
    def rise_times(self) -> np.ndarray:
        """Measured crossing-to-peak times (s)."""
        return self.peak_times - self.crossing_times[:, 0]

    @property
    def fall_times(self) -> np.ndarray:
        """Measured peak-to-crossing times (s)."""
        return self.crossing_times[:, 1] - self.peak_times

    @property
    def model_quarter_times(self) -> np.ndarray:
        """``T(r_k)`` with the fitted parameters (s)."""
        return quarter_time(self.amplitudes, self.alpha, self.p)

    @property
    def alpha_p_corr(self) -> float:
        """Correlation of the ``alpha`` and ``p`` estimates."""
        if self.cov is None:
            return float("nan")
        return float(self.cov[0, 1] / math.sqrt(self.cov[0, 0] * self.cov[1, 1]))

    def to_block(self, name: str = "identified", **geometry):
        """A :class:`~rocking.Block` with the identified ``alpha``, ``p``, ``mu``."""
        from ..blocks import Block

        if not 0.0 < self.mu <= 1.0:
            raise IdentificationError(
                f"the identified mu = {self.mu:.4f} is outside (0, 1]: the amplitudes do not "
                "decay as in free rocking of a rigid block")
        return Block.from_params(self.alpha, self.p, self.mu, name=name, **geometry)

    def error_surface(self, alphas=None, ps=None, n: int = 121, span: float | None = None):
        """``(alphas, ps, Sigma)`` on a grid around the fit; ``Sigma[i, j]`` at
        ``(alphas[i], ps[j])`` (weighted Eq 13, dimensionless)."""
        if span is None:
            rel_a = self.alpha_std / self.alpha if np.isfinite(self.alpha_std) else 0.0
            rel_p = self.p_std / self.p if np.isfinite(self.p_std) else 0.0
            span = float(np.clip(8.0 * max(rel_a, rel_p), 0.03, 0.5))
        r_max = float(self.amplitudes.max())
        if alphas is None:
            lo = max(self.alpha * (1.0 - span), r_max * (1.0 + 1e-6))
            hi = min(self.alpha * (1.0 + span), 0.5 * math.pi - 1e-9)
            alphas = np.linspace(lo, hi, n)
        if ps is None:
            ps = np.linspace(self.p * (1.0 - span), self.p * (1.0 + span), n)
        alphas, ps = np.asarray(alphas, float), np.asarray(ps, float)
        r, d, w, _ = self._intervals()
        S = sigma_surface(r, d, alphas[:, None], ps[None, :], weights=w)
        return alphas, ps, S

    def _intervals(self):
        """The measured intervals: (amplitude, duration, weight, half-cycle index)."""
        return _intervals(self.amplitudes, self.rise_times, self.fall_times, self.weights)

    def summary(self) -> dict:
        """JSON-ready summary (SI units; NaN as None)."""
        res = self.residuals
        return _json_safe({
            "alpha": self.alpha, "alpha_std": self.alpha_std,
            "alpha_deg": math.degrees(self.alpha),
            "p": self.p, "p_std": self.p_std,
            "mu": self.mu, "mu_std": self.mu_std,
            "alpha_p_correlation": self.alpha_p_corr,
            "uncertainty": self.uncertainty,
            "mu_n": [float(x) for x in self.mu_n],
            "n_half_cycles": self.n_half_cycles,
            "n_half_cycles_found": self.n_lobes_found,
            "amplitude_max": float(self.amplitudes.max()),
            "amplitude_min": float(self.amplitudes.min()),
            "min_amplitude": self.min_amplitude,
            "offset": self.offset, "offset_method": self.offset_method,
            "noise_std": self.noise, "sampling_rate": self.sampling_rate,
            "rms_residual": float(np.sqrt(np.nanmean(res ** 2))),
            "peak_times": [float(x) for x in self.peak_times],
            "peak_values": [float(x) for x in self.peak_values],
            "crossing_times": [[float(x) for x in row] for row in self.crossing_times],
            "release": bool(self.release),
        })

    def compare(self, theoretical):
        """Table II-style ``pandas.DataFrame``: theoretical, identified, std and % per parameter.

        ``theoretical`` is a :class:`~rocking.Block` (or anything with ``alpha``, ``p``,
        ``mu``, or a mapping with those keys).
        """
        import pandas as pd

        th = _params_of(theoretical)
        rows = []
        for k in ("alpha", "mu", "p"):
            v, s = getattr(self, k), getattr(self, f"{k}_std")
            rows.append({"parameter": k, "T": th[k], "identified": v, "std": s,
                         "diff_pct": (v - th[k]) / th[k] * 100.0})
        return pd.DataFrame(rows)

    def table(self):
        """Per-half-cycle ``pandas.DataFrame``: times, amplitude, model time, residuals, mu_n."""
        import pandas as pd

        mu_n = np.concatenate(([np.nan], self.mu_n))
        return pd.DataFrame({
            "impact": self.impact_numbers, "t_cross_before": self.crossing_times[:, 0],
            "t_peak": self.peak_times, "t_cross_after": self.crossing_times[:, 1],
            "amplitude": self.amplitudes, "rise": self.rise_times, "fall": self.fall_times,
            "T_model": self.model_quarter_times, "residual_rise": self.residuals[:, 0],
            "residual_fall": self.residuals[:, 1], "mu_n": mu_n,
        })

    # ------------------------------------------------------------------ plots
    def plot_error_surface(self, ax=None, theoretical=None, n: int = 121,
                           span: float | None = None):
        """Contours of ``log10(Sigma / Sigma_min)`` over ``(alpha, p)``, the minimum marked.

        ``theoretical`` (a Block or mapping) adds its point when it lies in the window (the
        window is widened to include it). Returns the Axes.
        """
        from ..plot import _style, figure

        if ax is None:
            _, ax = figure(figsize=(5.6, 4.4))
        if theoretical is not None and span is None:
            th = _params_of(theoretical)
            need = max(abs(th["alpha"] / self.alpha - 1), abs(th["p"] / self.p - 1))
            rel = max(self.alpha_std / self.alpha, self.p_std / self.p)
            span = float(np.clip(max(8.0 * rel, 1.25 * need), 0.03, 0.3))
        alphas, ps, S = self.error_surface(n=n, span=span)
        smin = float(np.min(S))
        L = np.log10(np.maximum(S / max(smin, 1e-300), 1.0))
        levels = np.linspace(0.0, max(float(L.max()), 1e-3), 21)
        cf = ax.contourf(alphas, ps, L.T, levels=levels, cmap="viridis_r")
        ax.contour(alphas, ps, L.T, levels=levels[::4], colors="white", linewidths=0.5,
                   alpha=0.7)
        cb = ax.figure.colorbar(cf, ax=ax)
        top = float(levels[-1])
        step = 0.5 if top <= 4 else 1.0 if top <= 8 else 2.0
        cb.set_ticks(np.arange(0.0, top + 1e-9, step))
        cb.set_label(r"$\log_{10}\,\Sigma/\Sigma_{\min}$")
        # valley: best p for each alpha
        r, d, w, _ = self._intervals()
        _, B, C = _abc(r, d, w * w, alphas)
        pv = C / B
        ok = (pv >= ps[0]) & (pv <= ps[-1])
        ax.plot(alphas[ok], pv[ok], color="white", ls="--", lw=1.0,
                label=r"valley $p^*(\alpha)$")
        ax.errorbar([self.alpha], [self.p], xerr=[self.alpha_std], yerr=[self.p_std],
                    color="#D55E00", marker="*", ms=13, mec="k", mew=0.6, capsize=3,
                    lw=1.2, ls="none", zorder=5,
                    label=f"identified α={self.alpha:.4f}, p={self.p:.3f}")
        if theoretical is not None:
            th = _params_of(theoretical)
            inside = (alphas[0] <= th["alpha"] <= alphas[-1]) and (ps[0] <= th["p"] <= ps[-1])
            ax.plot([th["alpha"]] if inside else [], [th["p"]] if inside else [], marker="X",
                    ms=10, color="#E69F00", mec="k", mew=0.6, ls="none", zorder=5,
                    label=f"theoretical α={th['alpha']:.4f}, p={th['p']:.3f}"
                    + ("" if inside else " (outside)"))
        _style(ax, r"$\alpha$ (rad)", r"$p$ (1/s)")
        ax.grid(False)
        ax.set_title(f"Error surface Σ(α, p), Eq 13 ({self.n_half_cycles} half-cycles)",
                     fontsize=10)
        ax.legend(loc="upper right", fontsize=7.5, framealpha=0.85)
        return ax

    def plot_fit(self, ax=None, theoretical=None, deg: bool = True):
        """Measured record against the classical model (Fig. 4 a/b analogue).

        The model is released from the first used peak with the fitted parameters and, if
        ``theoretical`` (a Block or mapping) is given, with those too. With ``ax=None`` a
        new figure is made with two panels (theoretical, identified) or one; ``ax`` may be
        one Axes (all curves on it) or two. Returns the Axes (a list of two for panels).
        """
        from ..plot import PALETTE, _style, figure

        panels = theoretical is not None
        if ax is None:
            if panels:
                from matplotlib.figure import Figure

                fig = Figure(figsize=(8.0, 5.6), layout="constrained")
                axs = list(fig.subplots(2, 1, sharex=True))
            else:
                _, a = figure(figsize=(8.0, 3.2))
                axs = [a]
        elif isinstance(ax, list | tuple | np.ndarray):
            axs = list(np.ravel(ax))
        else:
            axs = [ax]
        k = 180.0 / math.pi if deg else 1.0
        t_end = self._plot_end()
        sel = self.t <= t_end
        models = []
        if panels:
            models.append(("theoretical", _params_of(theoretical), PALETTE[3]))
        models.append(("identified", {"alpha": self.alpha, "p": self.p, "mu": self.mu},
                       PALETTE[0]))
        for i, (label, prm, col) in enumerate(models):
            a = axs[min(i, len(axs) - 1)]
            if i < len(axs) and (i == 0 or len(axs) > 1):
                a.plot(self.t[sel], k * self.theta[sel], color="0.55", lw=0.8,
                       label="measured (offset removed)")
            tm, thm = self._simulate(prm, t_end)
            a.plot(tm, k * thm, color=col, lw=1.1,
                   label=f"classical, {label}: α={prm['alpha']:.4f}, p={prm['p']:.3f}, "
                         f"μ={prm['mu']:.4f}")
        for a in axs:
            a.plot(self.peak_times, k * self.peak_values, ls="none", marker="o", ms=2.8,
                   mfc="none", mec="k", mew=0.6, label="peaks used")
            _style(a, None, r"$\theta$ (deg)" if deg else r"$\theta$ (rad)")
            a.legend(loc="upper right", fontsize=7.5, framealpha=0.85)
            a.set_xlim(self.t[0], t_end)
        axs[-1].set_xlabel("time (s)")
        if panels and len(axs) > 1:
            axs[0].set_title("(a) theoretical parameters", fontsize=10, loc="left")
            axs[1].set_title("(b) identified parameters", fontsize=10, loc="left")
        return axs if len(axs) > 1 else axs[0]

    def _plot_end(self) -> float:
        t_last = float(self.crossing_times[-1, 1])
        return float(min(self.t[-1], t_last + 0.15 * (t_last - self.t[0]) + 0.5))

    def _simulate(self, prm, t_end):
        from ..blocks import Block
        from ..models import simulate

        b = Block.from_params(prm["alpha"], prm["p"], min(max(prm["mu"], 1e-6), 1.0))
        t0 = float(self.peak_times[0])
        dt = min(0.002, float(np.median(np.diff(self.t))))
        th0 = float(self.peak_values[0])
        if abs(th0) >= b.alpha:
            return np.array([t0]), np.array([th0])
        r = simulate(b, None, duration=max(t_end - t0, dt), theta0=th0, dt_out=dt)
        return r.t + t0, r.theta


def _json_safe(x):
    """``x`` with numpy scalars as Python numbers and NaN/inf as None (recursively)."""
    if isinstance(x, dict):
        return {k: _json_safe(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [_json_safe(v) for v in x]
    if isinstance(x, bool | np.bool_):
        return bool(x)
    if isinstance(x, int | np.integer):
        return int(x)
    if isinstance(x, float | np.floating):
        return float(x) if math.isfinite(x) else None
    return x


def _params_of(x) -> dict:
    if isinstance(x, dict):
        try:
            return {k: float(x[k]) for k in ("alpha", "p", "mu")}
        except KeyError as e:
            raise ParameterError(f"theoretical parameters need alpha, p and mu; missing {e}")\
                from None
    try:
        return {k: float(getattr(x, k)) for k in ("alpha", "p", "mu")}
    except AttributeError:
        raise ParameterError("theoretical must be a rocking.Block or a mapping with alpha, p "
                             f"and mu, got {type(x).__name__}") from None


# ----------------------------------------------------------------------------- the fit
_NOT_IDENTIFIABLE = (
    "alpha cannot be identified: the error surface decreases up to alpha = pi/2. The "
    "amplitudes are too small compared with alpha (only p*sqrt(alpha) is determined) or the "
    "times do not follow free rocking")


def _fit_alpha_p(r, d, v, loss: str, x0=None):
    """Weighted (robust) least squares of durations ``d`` against ``G(r, alpha)/p``.

    Without a start ``x0`` the error surface is first profiled over a grid of ``alpha``
    (``p`` in closed form) for a global start.
    """
    from scipy.optimize import least_squares

    r_max = float(r.max())
    a_lo = r_max * (1.0 + 1e-9)
    a_hi = 0.5 * math.pi - 1e-9
    if a_lo >= a_hi:
        raise IdentificationError(f"the largest amplitude ({r_max:.4g} rad) is not below "
                                  "pi/2: this is not free rocking")
    if x0 is None or not a_lo < x0[0] < a_hi:
        grid = r_max + (a_hi - r_max) * np.logspace(-4, 0, 160)
        A, B, C = _abc(r, d, v * v, grid)
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
        return v * (d - _g(r, x[0]) / x[1])

    def jac(x):
        G = _g(r, x[0])
        return np.column_stack((-v * _g_dalpha(r, x[0]) / x[1], v * G / (x[1] * x[1])))

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


def free_rocking(t, theta, *, units: str = "rad", offset="auto", min_amplitude=None,
                 use_release: bool = True, loss: str = "soft_l1", n_boot: int = 0,
                 seed=None) -> FreeRockingFit:
    """Identify ``alpha``, ``p`` and ``mu`` of the classical model from a free-rocking record.

    Parameters
    ----------
    t, theta : array_like
        Sample times (s, strictly increasing; any rate, e.g. 50-1000 Hz) and rocking angle
        (in ``units``). The record may start anywhere: at rest or during a hold before the
        release, or mid-swing (an incomplete first half-cycle is used only if its peak is
        recorded); it may end at rest or while the block still rocks.
    units : {"rad", "deg"}
        Units of ``theta``. Results are always in rad.
    offset : "auto", "rest", "symmetric" or float
        Constant offset of the record: the level where the record ends at rest
        (``"rest"``), the centre of the oscillation from successive signed peaks
        (``"symmetric"``), ``"auto"`` (rest if the record ends at rest, else symmetric),
        or a known value in ``units`` (``FreeRockingFit.offset`` is in rad).
    use_release : bool
        Also use the first, incomplete half-cycle when its peak is in the record (a
        release from rest, possibly after a hold): its fall time ``T(r_0)``, at the largest
        amplitude, is the most informative on ``alpha``. It is skipped when the record
        starts after that peak.
    min_amplitude : float, optional
        Smallest half-cycle amplitude used (in ``units``); by default
        ``max(15 noise std, 2 % of the largest amplitude)``.
    loss : str
        Loss of the final least-squares (``"soft_l1"``, ``"huber"``, ``"cauchy"`` or
        ``"linear"``; see :func:`scipy.optimize.least_squares`).
    n_boot : int
        If > 0, ``alpha_std`` and ``p_std`` come from a bootstrap over half-cycles with
        ``n_boot`` resamples (``seed`` for the generator) instead of the Jacobian.

    Returns
    -------
    FreeRockingFit
        ``alpha`` (rad), ``p`` (1/s), ``mu`` and their uncertainties, ``mu_n``, the peaks
        and crossings used, the residuals; ``summary()``, ``to_block()``,
        ``plot_error_surface()``, ``plot_fit()``.

    Raises
    ------
    IdentificationError
        No rocking, fewer than three usable half-cycles (e.g. no impact or one impact),
        or an error surface without an interior minimum (alpha not identifiable).
    ParameterError
        Malformed input: NaN or inf samples, non-increasing times, mismatched lengths.
    """
    t, y = _as_record(t, theta, units)
    factor = _angle_factor(units)
    if loss not in ("linear", "soft_l1", "huber", "cauchy", "arctan"):
        raise ParameterError(f"loss must be one of linear, soft_l1, huber, cauchy, arctan; "
                             f"got {loss!r}")
    n_boot = int(n_boot)
    span = float(np.max(y) - np.min(y))
    if span == 0.0:
        raise IdentificationError("the record is constant: the block never rocks")
    sigma = _noise_sigma(y)
    ym = _median5(y)  # for the coarse steps only: isolated spikes would split half-cycles
    floor = 1e-7 * span
    sig = max(sigma, floor)

    def h_of(z):  # hysteresis half-width of the crossing detector
        return 5.0 * sig + 1e-5 * float(np.max(np.abs(z)))

    # ---- offset
    rest = _rest_level(t, ym, 5.0 * sig + 1e-5 * span)
    if isinstance(offset, str):
        mode = offset.strip().lower()
        if mode not in ("auto", "rest", "symmetric"):
            raise ParameterError(f"offset must be 'auto', 'rest', 'symmetric' or a number, "
                                 f"got {offset!r}")
        c = None
        if mode in ("auto", "rest") and rest is not None:
            c, method = rest[0], "rest"
        elif mode == "rest":
            raise IdentificationError("offset='rest' but the record does not end at rest "
                                      "(use offset='symmetric' or give the offset)")
        if c is None:
            c0 = float(np.median(y))
            c = _symmetric_offset(t, ym, c0, sig, h_of)
            method = "symmetric"
            if c is None:
                if mode == "symmetric":
                    raise IdentificationError("too few half-cycles to find the centre of the "
                                              "oscillation (offset='symmetric')")
                c, method = c0, "median"
    else:
        from .._validate import as_float

        c, method = as_float("offset", offset) * factor, "given"
    z = y - c
    amax = float(np.max(np.abs(z)))
    h = h_of(z)
    if amax <= 3.0 * h or amax <= 10.0 * sig:
        raise IdentificationError(
            f"the block never rocks: the record stays within {amax / factor:.3g} {units} of "
            f"its rest level, comparable with its noise ({sigma / factor:.2g} {units} std)")

    # ---- events
    ev = _events(t, ym - c, sig, h)  # coarse events on the despiked record
    L = ev.sign.size
    if L < 2:
        raise IdentificationError("no impact: the record never crosses its rest level, so "
                                  "there is no free-rocking half-cycle to time")
    if L < 5:
        raise IdentificationError(
            f"only {L - 1} impact(s) found; free-rocking identification needs at least three "
            "complete half-cycles (four impacts) above the noise")
    big = float(np.nanmax(ev.amp)) if np.isfinite(ev.amp).any() else 0.0
    if min_amplitude is None:
        r_min = max(15.0 * sig, 0.02 * big)
    else:
        from .._validate import positive

        r_min = positive("min_amplitude", min_amplitude) * factor
    dt_med = float(np.median(np.diff(t)))
    ok = np.zeros(L, dtype=bool)
    for k in range(1, L - 1):
        ok[k] = (np.isfinite(ev.amp[k]) and ev.amp[k] >= r_min
                 and np.isfinite(ev.cross[k - 1]) and np.isfinite(ev.cross[k])
                 and ev.cross[k - 1] < ev.tpk[k] < ev.cross[k]
                 and ev.last[k] - ev.first[k] >= 4)
    # the longest run of consecutive usable half-cycles
    best, run_start, k = (0, 0), None, 0
    for k in range(L + 1):
        if k < L and ok[k]:
            run_start = k if run_start is None else run_start
        elif run_start is not None:
            if k - run_start > best[1] - best[0]:
                best = (run_start, k)
            run_start = None
    k0, k1 = best
    n = k1 - k0
    if n < 3:
        raise IdentificationError(
            f"only {n} complete half-cycle(s) above the noise threshold "
            f"({r_min / factor:.3g} {units}) found among {L} lobes; free-rocking "
            "identification needs at least three")
    # ---- a first estimate of alpha, p from the coarse events
    cr0 = ev.cross[k0 - 1:k1]
    a0_, t0_ = ev.amp[k0:k1], ev.tpk[k0:k1]
    try:
        sol = _fit_alpha_p(np.concatenate((a0_, a0_)),
                           np.concatenate((t0_ - cr0[:-1], cr0[1:] - t0_)),
                           np.ones(2 * n), "linear")
        alpha, p = float(sol.x[0]), float(sol.x[1])
    except IdentificationError:  # rough: twice the largest amplitude, p from small swings
        alpha = min(2.0 * float(np.max(a0_)), 0.5 * math.pi - 1e-6)
        p = float(np.median(_g(a0_, alpha) / (0.5 * np.diff(cr0))))

    # ---- half-cycles to fit with the exact shape: the run, and the release if it is seen
    lobes = []
    for k in range(k0, k1):
        dl = 3.0 * math.sqrt(ev.cvar[k - 1]) + 0.1 * dt_med
        dh = 3.0 * math.sqrt(ev.cvar[k]) + 0.1 * dt_med
        lobes.append(_Lobe(int(ev.sign[k]), ev.cross[k - 1] + dl, ev.cross[k] - dh,
                           float(ev.tpk[k]), float(ev.amp[k]), p))
    rel_windows = []
    if use_release and k0 == 1 and np.isfinite(ev.cross[0]):
        # the first half-cycle is cut by the start of the record; if its peak is recorded
        # (a release from rest, possibly after a hold) its fall time T(r_0) is used. From
        # the first sample within 3 noise std of its maximum to the crossing, it is fitted
        # as a free half-cycle and as a release after a hold (flat before the peak); the
        # smaller chi^2 wins.
        sz0 = ev.sign[0] * (ym - c)[:ev.last[0] + 1]
        top = float(np.max(sz0))
        ia = int(np.flatnonzero(sz0 >= top - 3.0 * sig)[0])
        wend = int(np.flatnonzero(sz0 >= top - 3.0 * sig)[-1])
        dh = 3.0 * math.sqrt(ev.cvar[0]) + 0.1 * dt_med
        t_top = float(t[wend])
        for hold in (False, True):
            rel_windows.append((ia, _Lobe(int(ev.sign[0]), t[ia] - 1e-9 * dt_med,
                                          ev.cross[0] - dh, float(t[wend if hold else
                                                                     int(np.argmax(sz0))]),
                                          top, p, hold)))
    ks_run = list(range(k0, k1))
    first = True
    for _ in range(6):
        res_fit = _shape_fits(t, z, lobes + [lb for _, lb in rel_windows], alpha, sig)
        fits = {k: f for k, f in zip(ks_run, res_fit[:n], strict=True) if f is not None
                and abs(f[1] / ev.amp[k] - 1.0) < 0.2}
        release = None
        cands = [(i, f) for (i, _), f in zip(rel_windows, res_fit[n:], strict=True)
                 if f is not None]
        if cands:
            i, f = min(cands, key=lambda c: c[1][5])
            tp_r, r_r, vtp = f[0], f[1], f[4]
            if (tp_r >= t[0] - 0.5 * dt_med - 3.0 * math.sqrt(vtp)
                    and tp_r <= t_top + 0.5 * (ev.cross[0] - t_top)
                    and r_min <= r_r < alpha and r_r > ev.amp[1]):
                release = (f[0], f[1], (np.nan, np.nan), f[3], f[4], f[5], f[6])
                fits[0] = release
        ks = ([0] if release is not None else []) + [k for k in ks_run if k in fits]
        # keep the half-cycles whose shape fit worked, and the crossings next to them
        if len([k for k in ks if k > 0]) < 3:
            raise IdentificationError("fewer than three half-cycles could be fitted")
        m = len(ks)
        half = np.array([k == 0 for k in ks])
        amp = np.array([fits[k][1] for k in ks])
        tpk = np.array([fits[k][0] for k in ks])
        vtp = np.array([fits[k][4] for k in ks])
        cr = np.full((m, 2), np.nan)  # crossing before, after each half-cycle
        cv = np.full((m, 2), np.nan)
        for i, k in enumerate(ks):
            for side, j in ((0, k - 1), (1, k)):  # crossing j lies between lobes j, j + 1
                if j < 0:
                    continue
                est = [fits[j][3] if j in fits else None, fits[j + 1][2] if j + 1 in fits
                       else None]
                est = [e for e in est if e is not None and np.isfinite(e[0])
                       and np.isfinite(e[1])]
                if not est:
                    continue
                w = np.array([1.0 / max(e[1], 1e-300) for e in est])
                cr[i, side] = float(np.sum(w * np.array([e[0] for e in est])) / np.sum(w))
                cv[i, side] = float(1.0 / np.sum(w))
        rise = tpk - cr[:, 0]
        fall = cr[:, 1] - tpk
        floor2 = (1e-6 * dt_med) ** 2 + (1e-6 * fall) ** 2
        s_k = np.where(half, np.sqrt(cv[:, 1] + vtp + floor2),
                       np.sqrt(np.nan_to_num(cv[:, 0]) + cv[:, 1] + 4.0 * floor2))
        wk = np.where(half, 1.0 / s_k, math.sqrt(2.0) / s_k)  # weight of each rise/fall
        r2, d2, v2, owner = _intervals(amp, rise, fall, wk)
        sol = _fit_alpha_p(r2, d2, v2, loss, x0=None if first else (alpha, p))
        first = False
        a_new, p_new = float(sol.x[0]), float(sol.x[1])
        cov = _covariance(amp, rise, fall, s_k, half, a_new, p_new)
        tol_a = max(0.03 * math.sqrt(max(cov[0, 0], 0.0)), 1e-7 * a_new)
        tol_p = max(0.03 * math.sqrt(max(cov[1, 1], 0.0)), 1e-7 * p_new)
        done = abs(a_new - alpha) < tol_a and abs(p_new - p) < tol_p
        alpha, p = a_new, p_new
        if done:
            break
        for lb, k in zip(lobes, ks_run, strict=True):  # warm start of the next pass
            if k in fits:
                lb.tp, lb.r, lb.p = fits[k][0], min(fits[k][1], alpha * (1 - 1e-6)), fits[k][6]
    n = m

    # ---- uncertainties from the half-cycle durations D_k = 2 T(r_k) (fall T(r_0) for the
    # release); the rise-minus-fall part of the residuals does not depend on alpha, p
    cov = _covariance(amp, rise, fall, s_k, half, alpha, p)
    how = "jacobian"
    if n_boot > 0:
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
        if len(est) >= 2:
            cov = np.cov(np.asarray(est).T)
            how = f"bootstrap ({len(est)} resamples)"
    alpha_std, p_std = (float(math.sqrt(max(cov[i, i], 0.0))) for i in range(2))

    # ---- restitution, Eq 12
    nimp = np.array(ks) - ks[0]
    E = _energy(amp, alpha)
    mu_n = (E[1:] / E[0]) ** (1.0 / (2.0 * nimp[1:]))
    mu = float(np.mean(mu_n))
    mu_std = float(np.std(mu_n, ddof=1)) if mu_n.size > 1 else float("nan")

    Tm = _g(amp, alpha) / p
    res = np.column_stack((rise - Tm, fall - Tm))
    return FreeRockingFit(
        alpha=alpha, p=p, mu=mu, alpha_std=alpha_std, p_std=p_std, mu_std=mu_std,
        mu_n=mu_n, peak_times=tpk, peak_values=ev.sign[ks] * amp, crossing_times=cr,
        offset=c, residuals=res, impact_numbers=nimp, crossing_std=np.sqrt(cv),
        weights=wk, cov=cov, noise=sigma, sampling_rate=1.0 / dt_med,
        offset_method=method, min_amplitude=r_min, uncertainty=how, n_lobes_found=int(L),
        release=release is not None, t=t, theta=z,
    )


def _intervals(amp, rise, fall, wk):
    """Flatten the measured rise and fall times into (r, d, weight, half-cycle index)."""
    n = amp.size
    r2 = np.concatenate((amp, amp))
    d2 = np.concatenate((rise, fall))
    v2 = np.concatenate((wk, wk))
    owner = np.concatenate((np.arange(n), np.arange(n)))
    ok = np.isfinite(d2)
    return r2[ok], d2[ok], v2[ok], owner[ok]


def _covariance(amp, rise, fall, s_k, half, alpha, p):
    """Covariance of (alpha, p) from the Jacobian of the normalised half-cycle durations."""
    G = _g(amp, alpha)
    dG = _g_dalpha(amp, alpha)
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


# ----------------------------------------------------------------------------- CSV
_T_NAMES = ("t", "time", "time_s", "t_s", "time (s)", "t (s)", "seconds", "s")
_A_NAMES = ("theta", "angle", "rotation", "theta_rad", "theta_deg", "rocking", "rocking_angle")


def read_record_csv(path, units: str = "rad", time_col=None, angle_col=None):
    """``(t, theta)`` (s, rad) from a CSV file with a time and an angle column.

    The columns are chosen by name or 0-based index (``time_col``, ``angle_col``); by
    default a column named ``t``/``time`` and one named ``theta``/``angle``, else the
    first two columns. Files without a header, ``#`` comments and ``,``/``;``/tab/space
    separators are accepted. ``units`` is that of the angle column.
    """
    import pandas as pd

    factor = _angle_factor(units)
    path = Path(path)
    if not path.is_file():
        raise RecordError(f"record file not found: {path}")
    try:
        lines = [ln for ln in path.read_text().splitlines()
                 if ln.strip() and not ln.lstrip().startswith("#")]
    except (OSError, UnicodeDecodeError) as e:
        raise RecordError(f"{path}: cannot read as text ({e})") from None
    if not lines:
        raise RecordError(f"{path}: no data lines")
    first = lines[0]
    sep = next((c for c in (",", ";", "\t") if c in first), r"\s+")
    fields = [f.strip() for f in (first.split() if sep == r"\s+" else first.split(sep))]
    header = 0 if not all(_is_number(f) for f in fields if f) else None
    try:
        df = pd.read_csv(path, sep=sep, engine="python", comment="#", header=header,
                         skip_blank_lines=True)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, ValueError) as e:
        raise RecordError(f"{path}: cannot read as CSV ({' '.join(str(e).split())})") from None
    if df.shape[1] < 2:
        raise RecordError(f"{path}: needs at least two columns (time and angle), found "
                          f"{df.shape[1]}")
    cols = [str(c).strip() for c in df.columns]
    low = [c.lower() for c in cols]

    def pick(spec, names, default):
        if spec is None:
            for nm in names:
                if nm in low:
                    return low.index(nm)
            return default
        if isinstance(spec, int) or (isinstance(spec, str) and spec.strip().isdigit()
                                     and spec.strip().lower() not in low):
            i = int(spec)
            if not 0 <= i < len(cols):
                raise RecordError(f"{path}: column index {i} out of range (0..{len(cols) - 1})")
            return i
        key = str(spec).strip().lower()
        if key not in low:
            raise RecordError(f"{path}: no column {spec!r}; columns are {', '.join(cols)}")
        return low.index(key)

    it = pick(time_col, _T_NAMES, 0)
    ia = pick(angle_col, _A_NAMES, 1 if it != 1 else 0)
    if it == ia:
        raise RecordError(f"{path}: the time and angle columns are the same ({cols[it]!r})")
    try:
        t = pd.to_numeric(df.iloc[:, it]).to_numpy(dtype=float)
        a = pd.to_numeric(df.iloc[:, ia]).to_numpy(dtype=float)
    except (TypeError, ValueError) as e:
        raise RecordError(f"{path}: non-numeric value in the time or angle column ({e})")\
            from None
    return t, a * factor


def _is_number(x) -> bool:
    try:
        float(x)
    except (TypeError, ValueError):
        return False
    return True


def from_csv(path, units: str = "rad", time_col=None, angle_col=None, **kw) -> FreeRockingFit:
    """:func:`free_rocking` on a CSV record (see :func:`read_record_csv`); ``kw`` go to it.

    ``units`` is that of the angle column (``"rad"`` or ``"deg"``); a numeric ``offset`` or
    ``min_amplitude`` in ``kw`` is in the same units.
    """
    t, a = read_record_csv(path, units=units, time_col=time_col, angle_col=angle_col)
    f = _angle_factor(units)
    return free_rocking(t, a / f, units=units, **kw)
