"""Harmonic shaking-table motions: constant sine and Hanning-windowed sine.

Both are specified as a table would be: a frequency ``freq`` (Hz) and a *displacement*
amplitude ``amplitude`` (m). The table displacement is

* :class:`Sine`: ``u(t) = X sin(2 pi f t + phase)`` for ``0 <= t <= duration``;
* :class:`HanningSine`: ``u(t) = X w(t) sin(2 pi f t)`` with the Hann window
  ``w(t) = (1 - cos(2 pi t / duration)) / 2``, which starts and ends at rest;

and the ground acceleration is ``a = u''`` (exactly, including the window's derivatives).
The acceleration amplitude of a constant sine is ``X (2 pi f)^2``: 5 mm at 5 Hz is
4.93 m/s^2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .._validate import as_float, non_negative, positive, warn_implausible
from ..units import G
from . import _kernel as K
from .base import Motion

PLAUSIBLE_AMPLITUDE = 1.0
"""A displacement amplitude (m) above this gets a warning (a table stroke is centimetres)."""


PLAUSIBLE_ACCELERATION = 5.0 * G
"""An acceleration amplitude ``X (2 pi f)^2`` (m/s^2) above this (5 g, as a record's PGA in
:mod:`rocking.motions.records`) gets a warning: an acceleration given as ``amplitude``."""


def _check_amplitude(cls: str, x: float, freq: float) -> None:
    if x > PLAUSIBLE_AMPLITUDE:
        warn_implausible(f"{cls}: displacement amplitude {x:g} m is above 1 m; check the "
                         "units (amplitude is in m: 5 mm is 0.005)")
        return
    acc = x * (2.0 * math.pi * freq) ** 2
    if acc > PLAUSIBLE_ACCELERATION:
        warn_implausible(f"{cls}: displacement amplitude {x:g} m at {freq:g} Hz is an "
                         f"acceleration amplitude of {acc:.3g} m/s^2 ({acc / G:.3g} g), above "
                         f"5 g; amplitude is the table displacement in m (for an "
                         f"acceleration: Sine.from_acceleration, or the catalog's "
                         f"amplitude=)")


@dataclass(frozen=True)
class Sine(Motion):
    """Constant sine of frequency ``freq`` (Hz) and displacement amplitude ``amplitude`` (m).

    Examples
    --------
    >>> import math
    >>> from rocking.motions import Sine
    >>> s = Sine(freq=2.0, amplitude=0.01, duration=5.0)  # 10 mm at 2 Hz
    >>> round(s.acc_amplitude, 4), round(0.01 * (2 * math.pi * 2.0) ** 2, 4)  # X (2 pi f)^2
    (1.5791, 1.5791)
    >>> round(s.acceleration(0.125), 4)  # u = X at t = 1/(4 f)
    -1.5791
    >>> s.pga == s.acc_amplitude, round(s.pgv, 6) == round(0.01 * 2 * math.pi * 2.0, 6)
    (True, True)
    """

    freq: float
    amplitude: float
    duration: float
    phase: float = 0.0
    scale: float = 1.0
    kind = K.SINE

    def __post_init__(self):
        object.__setattr__(self, "freq", positive("freq", self.freq, "Hz"))
        object.__setattr__(self, "amplitude", non_negative("amplitude", self.amplitude, "m"))
        object.__setattr__(self, "duration", positive("duration", self.duration, "s"))
        object.__setattr__(self, "phase", as_float("phase", self.phase))
        _check_amplitude("Sine", self.amplitude, self.freq)
        object.__setattr__(self, "scale", as_float("scale", self.scale))

    @classmethod
    def from_acceleration(cls, freq: float, acc_amplitude: float, duration: float, **kw) -> Sine:
        """A sine given by its acceleration amplitude (m/s^2) instead of its displacement.

        The displacement amplitude is ``X = acc_amplitude / (2 pi freq)^2``.

        Examples
        --------
        >>> from rocking.motions import Sine
        >>> s = Sine.from_acceleration(freq=5.0, acc_amplitude=4.93, duration=2.0)
        >>> round(s.amplitude * 1000, 2), round(s.acc_amplitude, 4)  # 5 mm at 5 Hz: 4.93
        (5.0, 4.93)
        >>> round(abs(s.acceleration(0.05)), 4)  # the peak, at u = X (t = 1 / (4 freq))
        4.93
        """
        freq = positive("freq", freq, "Hz")
        acc = non_negative("acc_amplitude", acc_amplitude, "m/s^2")
        return cls(freq, acc / (2 * math.pi * freq) ** 2, duration, **kw)

    @property
    def acc_amplitude(self) -> float:
        """Peak acceleration (m/s^2)."""
        return abs(self.scale) * self.amplitude * (2 * math.pi * self.freq) ** 2

    @property
    def pga(self) -> float:
        """The acceleration amplitude ``X (2 pi f)^2`` (m/s^2, :attr:`acc_amplitude`),
        reached when the sine lasts half a period or more."""
        return self.acc_amplitude

    @property
    def pgv(self) -> float:
        """The table's velocity amplitude ``X 2 pi f`` (m/s): the peak of ``u' = X 2 pi f
        cos(2 pi f t + phase)``. (The table moves at ``u'(0)`` when the sine starts: the
        acceleration integrated from rest differs from ``u'`` by that constant.)"""
        return abs(self.scale) * self.amplitude * (2 * math.pi * self.freq)

    def _params(self):
        return (self.freq, self.amplitude, self.duration, self.phase)

    @property
    def scan_step(self) -> float:
        return 1.0 / (64.0 * self.freq)

    @property
    def quiet_time(self) -> float:
        return self.duration  # the table stops at the end of the window


@dataclass(frozen=True)
class HanningSine(Motion):
    """Sine of frequency ``freq`` (Hz) and displacement amplitude ``amplitude`` (m) under a
    Hann window that spans ``duration`` (s).

    Examples
    --------
    >>> from rocking.motions import HanningSine, displacement, sample, velocity
    >>> m = HanningSine(freq=2.0, amplitude=0.01, duration=2.0)
    >>> bool(abs(m(0.0)) < 1e-12 and abs(m(2.0)) < 1e-12)  # a = 0 at both ends
    True
    >>> r = sample(m, 0.001)
    >>> abs(round(float(velocity(r)[-1]), 6)), round(float(displacement(r).max()), 4)  # v = 0
    (0.0, 0.0096)
    """

    freq: float
    amplitude: float
    duration: float
    scale: float = 1.0
    kind = K.HANNING

    def __post_init__(self):
        object.__setattr__(self, "freq", positive("freq", self.freq, "Hz"))
        object.__setattr__(self, "amplitude", non_negative("amplitude", self.amplitude, "m"))
        object.__setattr__(self, "duration", positive("duration", self.duration, "s"))
        object.__setattr__(self, "scale", as_float("scale", self.scale))
        _check_amplitude("HanningSine", self.amplitude, self.freq)

    def _params(self):
        return (self.freq, self.amplitude, self.duration)

    @property
    def scan_step(self) -> float:
        return 1.0 / (64.0 * self.freq)

    @property
    def quiet_time(self) -> float:
        return self.duration  # the table stops at the end of the window
