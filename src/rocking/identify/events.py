"""Measured events: half-cycles (lobes), their peaks and the zero crossings between them.

Half-cycles are separated with hysteresis (5 noise std) on the despiked record and located
coarsely: a polynomial through each top gives the peak, a straight line through each
crossing its time and variance. Only a run of consecutive half-cycles above a noise
threshold (by default 15 noise std and 2 % of the largest amplitude) is used, so the last
ones before rest, dominated by noise, are left out.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._validate import positive
from ..errors import IdentificationError
from .record import Record


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
class Events:
    """The half-cycles of a record found by :func:`detect_events`: per lobe its sign, first
    and last sample, coarse amplitude and peak time; per crossing its time and variance."""

    sign: np.ndarray  # (L,) lobe signs
    first: np.ndarray
    last: np.ndarray
    amp: np.ndarray  # (L,) amplitude (nan if not located)
    tpk: np.ndarray  # (L,) peak time
    cross: np.ndarray  # (L-1,) crossing between lobe k and k+1 (nan if not located)
    cvar: np.ndarray  # (L-1,) its variance (s^2)


def detect_events(t, z, sigma, h, frac=0.3) -> Events:
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
    return Events(sign, first, last, amp, tpk, cross, cvar)


def find_events(rec: Record, z, c: float) -> Events:
    """Coarse events of the despiked record centred on ``c``; at least four impacts.

    ``z`` is the centred record (it sets the hysteresis of the crossing detector).
    """
    ev = detect_events(rec.t, rec.ym - c, rec.sig, rec.hysteresis(z))
    L = ev.sign.size
    if L < 2:
        raise IdentificationError("no impact: the record never crosses its rest level, so "
                                  "there is no free-rocking half-cycle to time")
    if L < 5:
        raise IdentificationError(
            f"only {L - 1} impact(s) found; free-rocking identification needs at least three "
            "complete half-cycles (four impacts) above the noise")
    return ev


def amplitude_threshold(rec: Record, ev: Events, min_amplitude) -> float:
    """Smallest amplitude used (rad): ``min_amplitude`` (in the record's units) or, by
    default, ``max(15 noise std, 2 % of the largest amplitude)``."""
    if min_amplitude is not None:
        return positive("min_amplitude", min_amplitude) * rec.factor
    big = float(np.nanmax(ev.amp)) if np.isfinite(ev.amp).any() else 0.0
    return max(15.0 * rec.sig, 0.02 * big)


def usable_run(rec: Record, ev: Events, r_min: float) -> tuple[int, int]:
    """``(k0, k1)``: the longest run ``k0 <= k < k1`` of consecutive usable half-cycles.

    Usable: complete (crossings on both sides, located around the peak), at least five
    samples long and of amplitude ``>= r_min``. At least three are needed.
    """
    L = ev.sign.size
    ok = np.zeros(L, dtype=bool)
    for k in range(1, L - 1):
        ok[k] = (np.isfinite(ev.amp[k]) and ev.amp[k] >= r_min
                 and np.isfinite(ev.cross[k - 1]) and np.isfinite(ev.cross[k])
                 and ev.cross[k - 1] < ev.tpk[k] < ev.cross[k]
                 and ev.last[k] - ev.first[k] >= 4)
    best, run_start = (0, 0), None
    for k in range(L + 1):
        if k < L and ok[k]:
            run_start = k if run_start is None else run_start
        elif run_start is not None:
            if k - run_start > best[1] - best[0]:
                best = (run_start, k)
            run_start = None
    k0, k1 = best
    if k1 - k0 < 3:
        raise IdentificationError(
            f"only {k1 - k0} complete half-cycle(s) above the noise threshold "
            f"({r_min / rec.factor:.3g} {rec.units}) found among {L} lobes; free-rocking "
            "identification needs at least three")
    return k0, k1
