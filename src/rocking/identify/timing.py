"""The measured times of the half-cycles used, and their weights in Eq 13.

Each half-cycle ``k`` rises from the crossing before it to its peak and falls back to the
crossing after it; both should last ``T(r_k)`` (Eq 11, corrected). A crossing is estimated
from each neighbouring half-cycle's exact-shape fit, and the two estimates are combined by
their variances. The weight of a rise or fall time in Eq 13 is the inverse of the timing
precision of its half-cycle.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .shape import LobeFit


@dataclass
class HalfCycleTimes:
    """Peaks, crossings, rise and fall times of the ``m`` half-cycles used (s, rad).

    ``ks`` are the lobe indices (0 is the release, whose rise is not timed: ``half``);
    ``cr``/``cv`` (``m x 2``) hold the crossing before and after each half-cycle and their
    variances (s^2), ``s_k`` the timing precision of each half-cycle (s) and ``wk`` (1/s)
    the weight of its rise and fall times in Eq 13.
    """

    ks: list[int]
    half: np.ndarray
    amp: np.ndarray
    tpk: np.ndarray
    vtp: np.ndarray
    cr: np.ndarray
    cv: np.ndarray
    rise: np.ndarray
    fall: np.ndarray
    s_k: np.ndarray
    wk: np.ndarray

    @classmethod
    def from_fits(cls, ks: list[int], fits: dict[int, LobeFit], dt: float) -> HalfCycleTimes:
        """The times of half-cycles ``ks`` from their shape fits (``dt``: sampling step)."""
        m = len(ks)
        half = np.array([k == 0 for k in ks])
        amp = np.array([fits[k].r for k in ks])
        tpk = np.array([fits[k].tp for k in ks])
        vtp = np.array([fits[k].var_tp for k in ks])
        cr = np.full((m, 2), np.nan)  # crossing before, after each half-cycle
        cv = np.full((m, 2), np.nan)
        for i, k in enumerate(ks):
            for side, j in ((0, k - 1), (1, k)):  # crossing j lies between lobes j, j + 1
                if j >= 0 and (est := _crossing(fits, j)) is not None:
                    cr[i, side], cv[i, side] = est
        rise = tpk - cr[:, 0]
        fall = cr[:, 1] - tpk
        floor2 = (1e-6 * dt) ** 2 + (1e-6 * fall) ** 2
        s_k = np.where(half, np.sqrt(cv[:, 1] + vtp + floor2),
                       np.sqrt(np.nan_to_num(cv[:, 0]) + cv[:, 1] + 4.0 * floor2))
        wk = np.where(half, 1.0 / s_k, math.sqrt(2.0) / s_k)  # weight of each rise/fall
        return cls(ks, half, amp, tpk, vtp, cr, cv, rise, fall, s_k, wk)

    @property
    def release(self) -> bool:
        """Whether the first half-cycle is the release (only its fall is timed)."""
        return bool(self.half[0])

    def intervals(self):
        """The Eq 13 data: (amplitude, duration, weight, half-cycle index), see
        :func:`flatten_intervals`."""
        return flatten_intervals(self.amp, self.rise, self.fall, self.wk)


def _crossing(fits: dict[int, LobeFit], j: int):
    """``(time, variance)`` of crossing ``j`` (after lobe ``j``) from the fits of the lobes
    on both sides, combined by their variances; None if neither gives it."""
    est = [fits[j].right if j in fits else None, fits[j + 1].left if j + 1 in fits else None]
    est = [e for e in est if e is not None and np.isfinite(e[0]) and np.isfinite(e[1])]
    if not est:
        return None
    w = np.array([1.0 / max(e[1], 1e-300) for e in est])
    return float(np.sum(w * np.array([e[0] for e in est])) / np.sum(w)), float(1.0 / np.sum(w))


def flatten_intervals(amp, rise, fall, wk):
    """Flatten the measured rise and fall times into (r, d, weight, half-cycle index)."""
    n = amp.size
    r2 = np.concatenate((amp, amp))
    d2 = np.concatenate((rise, fall))
    v2 = np.concatenate((wk, wk))
    owner = np.concatenate((np.arange(n), np.arange(n)))
    ok = np.isfinite(d2)
    return r2[ok], d2[ok], v2[ok], owner[ok]
