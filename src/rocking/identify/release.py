"""The release: a first half-cycle cut by the start of the record, used when its peak is seen.

A release from rest (fitted as flat before the peak, if the block was held) contributes
its fall time ``T(r_0)`` (Eq 11, corrected) at the largest amplitude, the most telling
about ``alpha``. From the first sample within 3 noise std of its maximum to the crossing
after it, it is fitted as a free half-cycle and as a release after a hold; the smaller
chi^2 wins, if its peak is plausible.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .events import Events
from .record import Record
from .shape import Lobe, LobeFit


@dataclass
class Release:
    """The windows of the release's two fits (free, held) and the limits of its peak."""

    lobes: list[Lobe]  # fitted free, then as a release after a hold
    t_top: float  # last sample within 3 noise std of the maximum (s)
    t_cross: float  # the coarse crossing after the release (s)

    def accept(self, fits: list[LobeFit | None], rec: Record, alpha: float, r_min: float,
               next_amp: float) -> LobeFit | None:
        """The better of the two fits if its peak is plausible, else None.

        Plausible: the peak lies no earlier than the record's start (within its timing
        precision) and before halfway from the top to the crossing, and its amplitude is
        usable (``r_min <= r < alpha``) and larger than that of the next half-cycle.
        """
        cands = [f for f in fits if f is not None]
        if not cands:
            return None
        f = min(cands, key=lambda f: f.chi2)
        if (f.tp >= rec.t[0] - 0.5 * rec.dt - 3.0 * math.sqrt(f.var_tp)
                and f.tp <= self.t_top + 0.5 * (self.t_cross - self.t_top)
                and r_min <= f.r < alpha and f.r > next_amp):
            return f._replace(left=(np.nan, np.nan))  # its rise is not in the record
        return None


def find_release(rec: Record, zm, ev: Events, k0: int, p: float) -> Release | None:
    """The release before the run starting at lobe ``k0`` (1: right after the first lobe),
    or None. ``zm`` is the despiked record centred on its offset, ``p`` the current one."""
    if k0 != 1 or not np.isfinite(ev.cross[0]):
        return None
    t, dt = rec.t, rec.dt
    sz0 = ev.sign[0] * zm[:ev.last[0] + 1]
    top = float(np.max(sz0))
    ia = int(np.flatnonzero(sz0 >= top - 3.0 * rec.sig)[0])
    wend = int(np.flatnonzero(sz0 >= top - 3.0 * rec.sig)[-1])
    dh = 3.0 * math.sqrt(ev.cvar[0]) + 0.1 * dt
    lobes = [Lobe(int(ev.sign[0]), t[ia] - 1e-9 * dt, ev.cross[0] - dh,
                   float(t[wend if hold else int(np.argmax(sz0))]), top, p, hold)
             for hold in (False, True)]
    return Release(lobes, float(t[wend]), float(ev.cross[0]))
