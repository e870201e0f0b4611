"""The offset of the record (the rest level of the block) and its removal.

The offset is the level where the record ends at rest or, if it does not, the centre of
the oscillation from a binomial (1, 3, 3, 1)/8 filter of successive signed peaks (which
cancels the decay of the amplitudes to third order). If neither can be found, the record
is refused: the caller gives the offset.
"""

from __future__ import annotations

import numpy as np

from .._validate import as_float
from ..errors import IdentificationError, ParameterError
from .events import detect_events
from .record import Record


def remove_offset(rec: Record, offset) -> tuple[np.ndarray, float, str]:
    """``(z, c, method)``: the record centred on its offset ``c`` (rad) and how ``c`` was
    found; raises if the centred record never leaves the noise (the block never rocks)."""
    c, method = _choose_offset(rec, offset)
    z = rec.y - c
    amax = float(np.max(np.abs(z)))
    h = rec.hysteresis(z)
    if amax <= 3.0 * h or amax <= 10.0 * rec.sig:
        raise IdentificationError(
            f"the block never rocks: the record stays within {amax / rec.factor:.3g} "
            f"{rec.units} of its rest level, comparable with its noise "
            f"({rec.sigma / rec.factor:.2g} {rec.units} std)")
    return z, c, method


def _choose_offset(rec: Record, offset) -> tuple[float, str]:
    """``offset`` ("auto", "rest", "symmetric" or a number in the record's units) -> (c, how)."""
    if not isinstance(offset, str):
        return as_float("offset", offset) * rec.factor, "given"
    rest = _rest_level(rec.t, rec.ym, 5.0 * rec.sig + 1e-5 * rec.span)
    mode = offset.strip().lower()
    if mode not in ("auto", "rest", "symmetric"):
        raise ParameterError(f"offset must be 'auto', 'rest', 'symmetric' or a number, "
                             f"got {offset!r}")
    if mode in ("auto", "rest") and rest is not None:
        return rest[0], "rest"
    if mode == "rest":
        raise IdentificationError("offset='rest' but the record does not end at rest "
                                  "(use offset='symmetric' or give the offset)")
    c0 = float(np.median(rec.y))
    c = _symmetric_offset(rec.t, rec.ym, c0, rec.sig, rec.hysteresis)
    if c is not None:
        return c, "symmetric"
    if mode == "symmetric":
        raise IdentificationError(f"{TOO_FEW_PEAKS} (offset='symmetric')")
    return c0, "median"  # a stand-in for finding the events: refused by offset_found


TOO_FEW_PEAKS = ("too few half-cycles to find the centre of the oscillation from its "
                 "peaks (two windows of four successive peaks above 10 % of the largest, "
                 "besides the first and last)")


def offset_found(rec: Record, method: str) -> None:
    """Refuse an offset that is only the median of the samples (``method == "median"``):
    a short record spends most of its time on one side, so it is no rest level (3 s of
    specimen 2 released from 0.6 alpha gave alpha 70 % off). Called once the record is
    known to hold enough impacts, so that a record without them is refused for that."""
    if method == "median":
        raise IdentificationError(
            f"the record's rest level (offset) cannot be found: the record does not end "
            f"at rest and has {TOO_FEW_PEAKS}; give it: offset=<the angle at rest, in "
            f"{rec.units}> (--offset on the command line; 0 if the record is zeroed at "
            f"rest), or record until the block is at rest")


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


def _symmetric_offset(t, y, c0, sigma, h_of):
    """Centre of the oscillation from signed peaks: binomial (1, 3, 3, 1)/8 filter, median."""
    c = c0
    for _ in range(4):
        z = y - c
        ev = detect_events(t, z, sigma, h_of(z))
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

