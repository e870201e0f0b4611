"""Idealised acceleration pulses (the classical overturning benchmarks).

Each pulse has an acceleration amplitude ``amplitude`` (m/s^2), a length in time, and a
start time ``t0`` (s, default 0). ``duration`` is the default simulation window, which
for a pulse must extend past the pulse itself because a block can overturn in the free
motion that follows: by default ``max(10 s, 5 x pulse length)`` after ``t0``.

* :class:`OneSine`: ``a = A sin(2 pi (t - t0) / Tp)`` for one full period ``Tp``;
* :class:`OneCosine`: ``a = A cos(2 pi (t - t0) / Tp)`` for one full period ``Tp``;
* :class:`HalfSine`: ``a = A sin(pi (t - t0) / t1)`` over a length ``t1``;
* :class:`Rectangular`: ``a = A`` over a length ``t1`` (Housner's rectangular pulse);
* :class:`Ricker`: ``a = A (1 - 2 x^2) exp(-x^2)``, ``x = pi fp (t - tc)``, with peak
  frequency ``fp`` (Hz) and centre ``tc`` (default ``1.5 / fp``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from .._validate import as_float, non_negative, positive
from . import _kernel as K
from .base import Motion


def _default_window(length: float, t0: float, duration):
    if duration is None:
        return t0 + max(10.0, 5.0 * length)
    return positive("duration", duration, "s")


@dataclass(frozen=True)
class _Pulse(Motion):
    amplitude: float
    length: float
    t0: float = 0.0
    duration: float | None = None
    scale: float = 1.0

    _length_name: ClassVar[str] = "length"

    def __post_init__(self):
        object.__setattr__(self, "amplitude", non_negative("amplitude", self.amplitude, "m/s^2"))
        object.__setattr__(self, "length", positive(self._length_name, self.length, "s"))
        object.__setattr__(self, "t0", non_negative("t0", self.t0, "s"))
        object.__setattr__(self, "duration", _default_window(self.length, self.t0, self.duration))
        object.__setattr__(self, "scale", as_float("scale", self.scale))

    def _params(self):
        return (self.amplitude, self.length, self.t0)

    @property
    def scan_step(self) -> float:
        return self.length / 128.0


@dataclass(frozen=True)
class OneSine(_Pulse):
    """One full sine cycle of period ``length`` (= Tp)."""

    kind = K.ONE_SINE
    _length_name = "Tp"


@dataclass(frozen=True)
class OneCosine(_Pulse):
    """One full cosine cycle of period ``length`` (= Tp)."""

    kind = K.ONE_COSINE
    _length_name = "Tp"


@dataclass(frozen=True)
class HalfSine(_Pulse):
    """Half a sine cycle lasting ``length`` (= t1)."""

    kind = K.HALF_SINE
    _length_name = "t1"


@dataclass(frozen=True)
class Rectangular(_Pulse):
    """Constant acceleration ``amplitude`` lasting ``length`` (= t1)."""

    kind = K.RECTANGULAR
    _length_name = "t1"


@dataclass(frozen=True)
class Ricker(Motion):
    """Ricker wavelet of peak frequency ``fp`` (Hz), centred at ``tc`` (default 1.5/fp)."""

    amplitude: float
    fp: float
    tc: float | None = None
    duration: float | None = None
    scale: float = 1.0
    kind = K.RICKER

    def __post_init__(self):
        object.__setattr__(self, "amplitude", non_negative("amplitude", self.amplitude, "m/s^2"))
        object.__setattr__(self, "fp", positive("fp", self.fp, "Hz"))
        tc = 1.5 / self.fp if self.tc is None else non_negative("tc", self.tc, "s")
        object.__setattr__(self, "tc", tc)
        if self.duration is None:
            object.__setattr__(self, "duration", 2 * tc + max(10.0, 5.0 / self.fp))
        else:
            object.__setattr__(self, "duration", positive("duration", self.duration, "s"))
        object.__setattr__(self, "scale", as_float("scale", self.scale))

    def _params(self):
        return (self.amplitude, self.fp, self.tc)

    @property
    def scan_step(self) -> float:
        return 1.0 / (128.0 * self.fp)
