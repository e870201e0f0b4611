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
  frequency ``fp`` (Hz) and centre ``tc`` (default ``1.5 / fp``);
* :class:`MavroeidisPapageorgiou`: the near-fault velocity pulse of Mavroeidis and
  Papageorgiou (2003), ``v = A/2 [1 + cos(2 pi fp (t - t0) / gamma)] cos(2 pi fp (t - t0)
  + nu)`` for ``|t - t0| <= gamma / (2 fp)``; the motion is its exact derivative, scaled
  so that its peak acceleration is ``amplitude`` (like the other pulses).

Peaks (``pga``, ``pgv``; load factor applied): the PGA of each pulse is ``amplitude``; the
PGV is that of the ground velocity from rest (the ground is at rest before the pulse),
over the whole pulse: ``A Tp / pi`` (one sine, at ``Tp / 2``), ``A Tp / (2 pi)`` (one
cosine, at ``Tp / 4``), ``2 A t1 / pi`` (half sine, from its end on), ``A t1``
(rectangular, from its end on), ``A / (pi fp) (1 / sqrt(2 e) + x0 exp(-x0^2))`` with
``x0 = pi fp tc`` (Ricker: ``v = A / (pi fp) (x exp(-x^2) + x0 exp(-x0^2))`` since
``d/dx (x exp(-x^2)) = (1 - 2 x^2) exp(-x^2)``, largest at ``x = 1 / sqrt(2)``), and the
peak of the stated velocity ``v`` (Mavroeidis-Papageorgiou: ``A`` for ``nu = 0`` or
``pi``).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from .._validate import as_float, in_range, non_negative, positive
from ..errors import ParameterError
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
    _pgv_factor: ClassVar[float] = math.nan  # PGV / (A length), module docstring

    def __post_init__(self):
        object.__setattr__(self, "amplitude", non_negative("amplitude", self.amplitude, "m/s^2"))
        object.__setattr__(self, "length", positive(self._length_name, self.length, "s"))
        object.__setattr__(self, "t0", non_negative("t0", self.t0, "s"))
        object.__setattr__(self, "duration", _default_window(self.length, self.t0, self.duration))
        object.__setattr__(self, "scale", as_float("scale", self.scale))

    def _params(self):
        return (self.amplitude, self.length, self.t0)

    @property
    def pga(self) -> float:
        """``amplitude`` (m/s^2), load factor applied."""
        return abs(self.scale) * self.amplitude

    @property
    def pgv(self) -> float:
        """The peak ground velocity from rest (m/s), module docstring."""
        return abs(self.scale) * self.amplitude * self.length * self._pgv_factor

    @property
    def scan_step(self) -> float:
        return self.length / 128.0

    @property
    def quiet_time(self) -> float:
        return self.t0 + self.length


@dataclass(frozen=True)
class OneSine(_Pulse):
    """One full sine cycle of period ``length`` (= Tp).

    Examples
    --------
    >>> import math
    >>> from rocking.motions import OneSine
    >>> p = OneSine(amplitude=3.0, length=0.5)
    >>> [round(float(a), 6) for a in p.acceleration([0.125, 0.375, 0.6])]  # Tp/4, 3Tp/4, after
    [3.0, -3.0, 0.0]
    >>> p.duration  # max(10 s, 5 Tp) after t0
    10.0
    >>> p.pga, round(p.pgv, 6), round(3.0 * 0.5 / math.pi, 6)  # A, A Tp / pi
    (3.0, 0.477465, 0.477465)
    """

    kind = K.ONE_SINE
    _length_name = "Tp"
    _pgv_factor = 1.0 / math.pi


@dataclass(frozen=True)
class OneCosine(_Pulse):
    """One full cosine cycle of period ``length`` (= Tp).

    Examples
    --------
    >>> from rocking.motions import OneCosine
    >>> p = OneCosine(amplitude=3.0, length=0.5)
    >>> [round(float(a), 6) for a in p.acceleration([0.0, 0.25, 0.6])]  # 0, Tp/2, after
    [3.0, -3.0, 0.0]
    """

    kind = K.ONE_COSINE
    _length_name = "Tp"
    _pgv_factor = 0.5 / math.pi


@dataclass(frozen=True)
class HalfSine(_Pulse):
    """Half a sine cycle lasting ``length`` (= t1).

    Examples
    --------
    >>> from rocking.motions import HalfSine
    >>> p = HalfSine(amplitude=3.0, length=0.5, t0=0.1)
    >>> [round(float(a), 6) for a in p.acceleration([0.05, 0.35, 0.7])]  # before, peak, after
    [0.0, 3.0, 0.0]
    """

    kind = K.HALF_SINE
    _length_name = "t1"
    _pgv_factor = 2.0 / math.pi


@dataclass(frozen=True)
class Rectangular(_Pulse):
    """Constant acceleration ``amplitude`` lasting ``length`` (= t1).

    Examples
    --------
    >>> from rocking.motions import Rectangular, sample, velocity
    >>> p = Rectangular(amplitude=1.0, length=2.0, duration=2.0)
    >>> [float(a) for a in p.acceleration([1.0, 2.5])]
    [1.0, 0.0]
    >>> round(float(velocity(sample(p, 0.01))[-1]), 6)  # velocity change A t1
    2.0
    >>> p.pga, p.pgv
    (1.0, 2.0)
    """

    kind = K.RECTANGULAR
    _length_name = "t1"
    _pgv_factor = 1.0


@dataclass(frozen=True)
class Ricker(Motion):
    """Ricker wavelet of peak frequency ``fp`` (Hz), centred at ``tc`` (default 1.5/fp).

    Examples
    --------
    >>> import math
    >>> from rocking.motions import Ricker
    >>> w = Ricker(amplitude=4.0, fp=2.0)
    >>> w.tc, round(w(w.tc), 6)  # centre 1.5/fp, peak A
    (0.75, 4.0)
    >>> round(w(w.tc + 1 / (math.sqrt(2) * math.pi * w.fp)), 9)  # zero at x = 1/sqrt(2)
    0.0
    >>> w.pga, round(w.pgv, 6), round(4.0 / (math.pi * 2.0 * math.sqrt(2 * math.e)), 6)
    (4.0, 0.273035, 0.273035)
    """

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
    def pga(self) -> float:
        """``amplitude`` (m/s^2, at ``tc``), load factor applied."""
        return abs(self.scale) * self.amplitude

    @property
    def pgv(self) -> float:
        """``A / (pi fp) (1 / sqrt(2 e) + x0 exp(-x0^2))``, ``x0 = pi fp tc`` (m/s; module
        docstring), load factor applied."""
        x0 = math.pi * self.fp * self.tc
        k = 1.0 / math.sqrt(2.0 * math.e) + x0 * math.exp(-x0 * x0)
        return abs(self.scale) * self.amplitude / (math.pi * self.fp) * k

    @property
    def scan_step(self) -> float:
        return 1.0 / (128.0 * self.fp)

    @property
    def quiet_time(self) -> float:
        # |a| < 6e-16 A beyond tc + 2/fp (x = 2 pi): below double precision of the peak
        return self.tc + 2.0 / self.fp


def _peak_abs(f, gamma: float) -> float:
    """Peak of ``|f(u)|`` over ``|u| <= pi gamma``: the largest of >= 256 samples per
    oscillation, refined by a bounded search around it."""
    from scipy.optimize import minimize_scalar

    half = math.pi * gamma
    n = max(4097, int(512 * gamma) + 1)  # >= 256 points per oscillation
    u = np.linspace(-half, half, n)
    i = int(np.argmax(np.abs(f(u))))
    h = u[1] - u[0]
    lo, hi = max(-half, u[i] - h), min(half, u[i] + h)
    res = minimize_scalar(lambda x: -abs(float(f(x))), bounds=(lo, hi), method="bounded",
                          options={"xatol": 1e-12})
    return max(abs(float(f(u[i]))), -float(res.fun))


@functools.lru_cache(maxsize=256)
def _mp_peak(gamma: float, nu: float) -> float:
    """Peak of ``|g(u)|`` over ``|u| <= pi gamma``, where the acceleration of the M&P pulse
    of velocity amplitude ``A`` is ``-(A w / 2) g(w tau)`` (``w = 2 pi fp``)."""

    def g(u):
        return np.sin(u / gamma) * np.cos(u + nu) / gamma + (1.0 + np.cos(u / gamma)) * np.sin(
            u + nu)

    return _peak_abs(g, gamma)


@functools.lru_cache(maxsize=256)
def _mp_velocity_peak(gamma: float, nu: float) -> float:
    """Peak of ``|(1 + cos(u / gamma)) / 2 cos(u + nu)|`` over ``|u| <= pi gamma``: the
    PGV of the M&P pulse over its velocity amplitude ``A``."""

    def f(u):
        return 0.5 * (1.0 + np.cos(u / gamma)) * np.cos(u + nu)

    return _peak_abs(f, gamma)


@dataclass(frozen=True)
class MavroeidisPapageorgiou(Motion):
    """The near-fault pulse of Mavroeidis and Papageorgiou (2003, BSSA 93(3)).

    Ground velocity (m/s), with ``tau = t - t0``:

    ``v(t) = A/2 [1 + cos(2 pi fp tau / gamma)] cos(2 pi fp tau + nu)`` for
    ``|tau| <= gamma / (2 fp)``, zero outside.

    The motion (like every motion, an acceleration) is its exact derivative
    ``a = dv/dt``; it is continuous, zero at both ends of the pulse, and integrates back to
    ``v`` (the ground velocity returns to zero after the pulse).

    Parameters
    ----------
    amplitude : float
        Peak absolute ground **acceleration** (m/s^2), as for the other pulses, so that
        ``amplitude / (g tan alpha)`` is the dimensionless intensity of the overturning
        spectra. The velocity amplitude ``A`` (m/s) follows:
        :attr:`velocity_amplitude`.
    fp : float
        Frequency of the harmonic (Hz), > 0; ``omega_p = 2 pi fp``.
    gamma : float
        Oscillatory character (the number of half-cycles of the envelope, roughly), > 1.
        The pulse lasts ``gamma / fp``.
    nu : float
        Phase of the harmonic (rad); ``nu = 0`` or ``pi`` gives a symmetric velocity pulse,
        ``+-pi/2`` an antisymmetric one.
    t0 : float, optional
        Centre of the envelope (s), the paper's ``t0``; default ``gamma / (2 fp)`` (the
        pulse starts at ``t = 0``); must be ``>= gamma / (2 fp)``.
    duration : float, optional
        Simulation window (s); default the start of the pulse plus
        ``max(10 s, 5 gamma / fp)``.
    scale : float
        Load factor.

    Examples
    --------
    >>> from rocking.motions import MavroeidisPapageorgiou, pga, sample
    >>> mp = MavroeidisPapageorgiou(amplitude=5.0, fp=1.0, gamma=2.0, nu=0.0)
    >>> mp.half_length, mp.t0  # gamma / (2 fp): the pulse starts at t = 0
    (1.0, 1.0)
    >>> round(float(mp.velocity(mp.t0)) / mp.velocity_amplitude, 6)  # v(t0) = A for nu = 0
    1.0
    >>> round(pga(sample(mp, 0.001)), 3)  # the peak acceleration is ``amplitude``
    5.0
    >>> mp.pga, round(mp.pgv / mp.velocity_amplitude, 9)  # nu = 0: the PGV is A
    (5.0, 1.0)
    """

    amplitude: float
    fp: float
    gamma: float
    nu: float
    t0: float | None = None
    duration: float | None = None
    scale: float = 1.0
    kind = K.MAVROEIDIS_PAPAGEORGIOU

    def __post_init__(self):
        object.__setattr__(self, "amplitude", non_negative("amplitude", self.amplitude, "m/s^2"))
        object.__setattr__(self, "fp", positive("fp", self.fp, "Hz"))
        object.__setattr__(self, "gamma", in_range("gamma", self.gamma, 1.0, math.inf,
                                                   shown="(1, inf)"))
        object.__setattr__(self, "nu", as_float("nu", self.nu))
        half = self.half_length
        if self.t0 is None:
            t0 = half
        else:
            t0 = as_float("t0", self.t0)
            if t0 < half * (1.0 - 1e-12):
                raise ParameterError(f"t0 (the centre of the pulse) must be >= gamma / (2 fp) "
                                     f"= {half:g} s so that the pulse starts at t >= 0, "
                                     f"got {self.t0!r}")
        object.__setattr__(self, "t0", t0)
        if self.duration is None:
            object.__setattr__(self, "duration", t0 - half + max(10.0, 10.0 * half))
        else:
            object.__setattr__(self, "duration", positive("duration", self.duration, "s"))
        object.__setattr__(self, "scale", as_float("scale", self.scale))

    @property
    def half_length(self) -> float:
        """Half the length of the pulse, ``gamma / (2 fp)`` (s)."""
        return 0.5 * self.gamma / self.fp

    @property
    def velocity_amplitude(self) -> float:
        """The velocity amplitude ``A`` (m/s) of the formula, without the load factor:
        ``amplitude / (pi fp max|g|)`` with ``g`` the shape of the derivative."""
        return self.amplitude / (math.pi * self.fp * _mp_peak(self.gamma, self.nu))

    def velocity(self, t) -> np.ndarray:
        """Ground velocity (m/s) at times ``t`` (s): the formula above, times ``scale``.

        Examples
        --------
        >>> from rocking.motions import MavroeidisPapageorgiou, sample, velocity
        >>> mp = MavroeidisPapageorgiou(amplitude=5.0, fp=1.0, gamma=2.0, nu=0.0)
        >>> r = sample(mp, 0.002, duration=3.0)  # the acceleration, integrated back:
        >>> bool(np.allclose(velocity(r), mp.velocity(r.t), atol=1e-4))
        True
        >>> mp.velocity([0.0, 2.0, 2.5]).tolist()  # zero at both ends and after the pulse
        [0.0, 0.0, 0.0]
        """
        arr = np.asarray(t, dtype=np.float64)
        tau = arr - self.t0
        w = 2.0 * math.pi * self.fp
        v = (0.5 * self.scale * self.velocity_amplitude * (1.0 + np.cos(w * tau / self.gamma))
             * np.cos(w * tau + self.nu))
        v = np.where(np.abs(tau) <= self.half_length, v, 0.0)
        return v if arr.ndim else float(v)

    def _params(self):
        return (self.velocity_amplitude, self.fp, self.gamma, self.nu, self.t0)

    @property
    def pga(self) -> float:
        """``amplitude`` (m/s^2), load factor applied."""
        return abs(self.scale) * self.amplitude

    @property
    def pgv(self) -> float:
        """The peak of ``|v|`` (m/s), load factor applied: ``A`` for ``nu = 0`` or ``pi``."""
        return abs(self.scale) * self.velocity_amplitude * _mp_velocity_peak(self.gamma,
                                                                             self.nu)

    @property
    def scan_step(self) -> float:
        return 1.0 / (128.0 * self.fp)

    @property
    def quiet_time(self) -> float:
        return self.t0 + self.half_length
