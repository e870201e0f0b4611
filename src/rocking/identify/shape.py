"""Fits of each measured half-cycle with the exact half-cycle of the classical model.

Between impacts ``pi + theta - alpha`` swings as a pendulum, so a half-cycle of amplitude
``r_k`` peaking at ``t_k`` is ``theta(t) = alpha - pi + 2 asin(k cd(p_k (t - t_k) | k^2))``
with ``k = cos((alpha - r_k)/2)`` (Jacobi ``cd``). A batched Levenberg-Marquardt over
``(t_k, r_k, p_k)`` per half-cycle, at the current ``alpha``, gives the peak time and
amplitude and, as ``t_k -+ T(r_k)`` (Eq 11, corrected), the crossings on both sides, all to
sub-sample accuracy and without the bias of a truncated polynomial.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from scipy.special import ellipj

from .time_model import scaled_quarter_time


class LobeFit(NamedTuple):
    """The exact-shape fit of one half-cycle (s, rad; variances in s^2)."""

    tp: float  # peak time
    r: float  # amplitude
    left: tuple  # (time, variance) of the crossing before: tp - T(r; alpha, p)
    right: tuple  # (time, variance) of the crossing after: tp + T(r; alpha, p)
    var_tp: float  # variance of tp
    chi2: float  # residual sum of squares per degree of freedom
    p: float  # the half-cycle's own p


def _shape(s, r, alpha, p):
    """Exact half-cycle of the classical model and its slope, ``s`` s from the peak.

    Between impacts ``chi = pi + theta - alpha`` obeys the pendulum equation
    ``chi'' = -p^2 sin(chi)`` with turning point ``pi - alpha + r``, so
    ``theta(s) = alpha - pi + 2 asin(k cd(p s | m))``, ``k = cos((alpha - r)/2)``,
    ``m = k^2`` (Jacobi elliptic ``cd = cn/dn``). Returns ``(theta, dtheta/ds)``.
    """
    k = np.cos(0.5 * (alpha - r))
    m = k * k
    sn, cn, dn, _ = ellipj(p * s, m)
    x = np.clip(k * cn / dn, -1.0, 1.0)
    th = alpha - math.pi + 2.0 * np.arcsin(x)
    with np.errstate(invalid="ignore", divide="ignore"):
        dth = -2.0 * k * p * (1.0 - m) * sn / (dn * dn * np.sqrt(1.0 - x * x))
    return th, np.nan_to_num(dth)


@dataclass
class Lobe:
    """One half-cycle to fit with :func:`shape_fits`: its sign, fitting window, first guess
    of the peak time ``tp``, amplitude ``r`` and local ``p``."""

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


def shape_fits(t, z, lobes, alpha, sigma, iters: int = 40):
    """Fit each half-cycle with the exact shape :func:`_shape` at the given ``alpha``.

    Per half-cycle the unknowns are the peak time ``tp``, the amplitude ``r`` and a local
    ``p_k``; all half-cycles are solved together by a batched Levenberg-Marquardt. Samples
    more than 5 noise std (or 5 robust residual std) off the fit are then dropped as
    outliers (spikes, dropouts) and the fit is repeated. The crossings on either side are
    ``tp -+ T(r; alpha, p_k)``. Returns a list of :class:`LobeFit` (None where a fit
    failed).
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
    G = scaled_quarter_time(P[:, 1], alpha)
    dG = (scaled_quarter_time(P[:, 1] + eps, alpha) - G) / eps
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
        out[j] = LobeFit(tp, P[j, 1], (tp - T, max(float(gl @ C @ gl), 0.0)),
                         (tp + T, max(float(gr @ C @ gr), 0.0)), max(float(C[0, 0]), 0.0),
                         float(rss[j]) / max(cnt[j] - 3, 1), P[j, 2])
    return out


def _lm(P, tt, y, lab, hold, alpha, r_hi, s2, L, iters):
    """Batched Levenberg-Marquardt for :func:`shape_fits`; returns the parameters."""
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

