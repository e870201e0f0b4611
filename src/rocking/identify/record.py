"""The measured record: input checks, units, noise level and a despiked copy.

The noise level is estimated from third differences of the record (white noise has
``var(d3) = 20 sigma^2``); a running median of 5 samples removes isolated spikes for the
coarse steps (which would otherwise split half-cycles).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import IdentificationError, ParameterError, UnitError


@dataclass(frozen=True)
class Record:
    """A checked record in rad, with its noise std and the detector thresholds."""

    t: np.ndarray  # sample times (s), strictly increasing
    y: np.ndarray  # rocking angle (rad), offset not removed
    ym: np.ndarray  # running median of 5 samples of y (coarse steps only)
    units: str  # units of the input angle (for messages)
    factor: float  # rad per input unit
    sigma: float  # estimated noise std (rad)
    sig: float  # the same, floored at 1e-7 of the span (used for thresholds)
    span: float  # max(y) - min(y)
    dt: float  # median sampling step (s)

    @classmethod
    def measure(cls, t, y, units: str) -> Record:
        """The noise level and despiked copy of a checked record (see :func:`check_record`)."""
        span = float(np.max(y) - np.min(y))
        if span == 0.0:
            raise IdentificationError("the record is constant: the block never rocks")
        sigma = _noise_sigma(y)
        return cls(t=t, y=y, ym=_median5(y), units=units, factor=angle_factor(units),
                   sigma=sigma, sig=max(sigma, 1e-7 * span), span=span,
                   dt=float(np.median(np.diff(t))))

    def hysteresis(self, z) -> float:
        """Half-width of the crossing detector for the centred record ``z``."""
        return 5.0 * self.sig + 1e-5 * float(np.max(np.abs(z)))


def check_record(t, theta, units: str):
    """``(t, theta in rad)`` as checked float arrays: 1-D, of the same length (at least 20
    samples), finite, ``t`` strictly increasing."""
    factor = angle_factor(units)
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


def angle_factor(units) -> float:
    """The factor from ``units`` (``"rad"`` or ``"deg"``) to rad."""
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
