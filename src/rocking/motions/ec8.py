r"""Design spectra: the Eurocode 8 horizontal elastic spectrum and custom spectra of its shape.

EN 1998-1:2004 §3.2.2.2, Eqs (3.2)-(3.5): for a design ground acceleration ``ag`` on
ground type A, soil factor ``S``, corner periods ``TB``, ``TC``, ``TD`` and damping
correction ``eta = sqrt(10 / (5 + xi)) >= 0.55`` (``xi`` in percent):

.. math::

    S_e(T) = a_g S \begin{cases}
        1 + \frac{T}{T_B} (2.5\,\eta - 1) & 0 \le T \le T_B \\
        2.5\,\eta & T_B \le T \le T_C \\
        2.5\,\eta\, \frac{T_C}{T} & T_C \le T \le T_D \\
        2.5\,\eta\, \frac{T_C T_D}{T^2} & T_D \le T
    \end{cases}

``S``, ``TB``, ``TC``, ``TD`` come from Table 3.2 (Type 1, large earthquakes) and Table 3.3
(Type 2, magnitude below about 5.5), recommended values, for ground types A-E. The
standard defines the spectrum up to 4 s; beyond 4 s we continue the last branch (the
standard's Annex A gives a displacement spectrum there instead).

:class:`DesignSpectrum` is the same four-branch shape with user-chosen zero-period value
(the PGA, ``ag S``), plateau value and corner periods. :func:`paper_target` is the target of
the synthetic earthquakes of Peña et al. (2007), Section 3.3: plateau from 0.1 to 0.3 s at
7 m/s^2, PGA 2.8 m/s^2 (7 / 2.8 = 2.5, the EC8 plateau factor at 5 % damping). The paper
does not state ``TD``; we take ``TD = 1.2 s``, because the paper's corner periods
``TB = 0.1 s`` and ``TC = 0.3 s`` are exactly those of the EC8 Type 2 spectrum on ground
type D (Table 3.3: S = 1.8, TB = 0.10, TC = 0.30, TD = 1.2 s), whose ``ag = 2.8 / 1.8 =
1.56 m/s^2`` (0.16 g) is a plausible Portuguese design value; no other row of Tables
3.2/3.3 has these corner periods. All accelerations are in m/s^2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from .._validate import as_float, in_range, non_negative, positive
from ..errors import ParameterError

__all__ = ["ec8_spectrum", "ec8_parameters", "eta", "DesignSpectrum", "paper_target",
           "GROUND_TYPES", "EC8_TABLES", "PAPER_TD"]

GROUND_TYPES = ("A", "B", "C", "D", "E")

EC8_TABLES = {
    # EN 1998-1 Table 3.2: Type 1 elastic response spectrum (recommended values)
    1: {"A": (1.00, 0.15, 0.4, 2.0), "B": (1.20, 0.15, 0.5, 2.0),
        "C": (1.15, 0.20, 0.6, 2.0), "D": (1.35, 0.20, 0.8, 2.0),
        "E": (1.40, 0.15, 0.5, 2.0)},
    # EN 1998-1 Table 3.3: Type 2 elastic response spectrum (recommended values)
    2: {"A": (1.00, 0.05, 0.25, 1.2), "B": (1.35, 0.05, 0.25, 1.2),
        "C": (1.50, 0.10, 0.25, 1.2), "D": (1.80, 0.10, 0.30, 1.2),
        "E": (1.60, 0.05, 0.25, 1.2)},
}
"""``{spectrum type: {ground type: (S, TB, TC, TD)}}`` (periods in s)."""

PAPER_TD = 1.2
"""TD (s) of :func:`paper_target`: EC8 Type 2, ground D, whose TB and TC match the paper."""

PLATEAU_FACTOR = 2.5  # spectral amplification of the plateau at 5 % damping


def eta(damping) -> float:
    """EC8 damping correction factor ``sqrt(10 / (5 + xi)) >= 0.55``, ``damping`` a fraction.

    ``damping=0.05`` (5 %) gives 1; the floor 0.55 is reached at 28 % damping.
    """
    d = _damping(damping)
    return max(math.sqrt(10.0 / (5.0 + 100.0 * d)), 0.55)


def _damping(damping) -> float:
    d = in_range("damping", damping, 0.0, 1.0, lo_open=False, hi_open=True,
                 shown="[0, 1) (a fraction of critical: 0.05 is 5 %)")
    return d


def ec8_parameters(ground: str = "A", spectrum_type: int = 1) -> dict:
    """``{"S", "TB", "TC", "TD"}`` of EN 1998-1 Table 3.2 (Type 1) or 3.3 (Type 2)."""
    g = str(ground).strip().upper()
    if g not in GROUND_TYPES:
        raise ParameterError(f"ground must be one of {', '.join(GROUND_TYPES)}; got {ground!r}")
    st = {"1": 1, "2": 2}.get(str(spectrum_type).strip())
    if st is None:
        raise ParameterError(f"spectrum_type must be 1 or 2; got {spectrum_type!r}")
    S, TB, TC, TD = EC8_TABLES[st][g]
    return {"S": S, "TB": TB, "TC": TC, "TD": TD}


def _periods(periods) -> np.ndarray:
    try:
        T = np.asarray(periods, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError("periods must be numbers (s)") from None
    if not np.all(np.isfinite(T)) or np.any(T < 0.0):
        raise ParameterError("periods must be finite and >= 0 s")
    return T


def _shape(T: np.ndarray, pga: float, plateau: float, TB: float, TC: float,
           TD: float) -> np.ndarray:
    """The four branches of EC8 Eqs (3.2)-(3.5) with Se(0) = pga and plateau value."""
    Tc = np.where(T > 0.0, T, 1.0)
    return np.where(
        T <= TB, pga + (plateau - pga) * T / TB,
        np.where(T <= TC, plateau,
                 np.where(T <= TD, plateau * TC / Tc, plateau * TC * TD / Tc ** 2)))


def ec8_spectrum(periods, ag, ground: str = "A", spectrum_type: int = 1,
                 damping: float = 0.05):
    """EN 1998-1 horizontal elastic response spectrum ``Se(T)`` (m/s^2), §3.2.2.2.

    Parameters
    ----------
    periods : float or array_like
        Periods ``T`` (s), >= 0. A scalar in gives a float out.
    ag : float
        Design ground acceleration on type A ground (m/s^2), ``gamma_I * agR``.
    ground : {"A", "B", "C", "D", "E"}
        Ground type (Table 3.1).
    spectrum_type : {1, 2}
        Type 1 (Table 3.2) or Type 2 (Table 3.3) recommended parameters.
    damping : float
        Viscous damping ratio as a fraction (0.05 = 5 %), giving ``eta``.

    Examples
    --------
    >>> from rocking.motions import ec8_spectrum
    >>> [round(float(s), 4) for s in ec8_spectrum([0.0, 0.3], ag=2.0, ground="C")]  # S = 1.15
    [2.3, 5.75]
    >>> round(2.5 * 1.15 * 2.0, 4)  # plateau 2.5 S ag (eta = 1 at 5 %)
    5.75
    """
    ag = non_negative("ag", ag, "m/s^2")
    prm = ec8_parameters(ground, spectrum_type)
    e = eta(damping)
    T = _periods(periods)
    S = ag * prm["S"]
    out = _shape(T, S, S * PLATEAU_FACTOR * e, prm["TB"], prm["TC"], prm["TD"])
    return float(out) if out.ndim == 0 else out


@dataclass(frozen=True)
class DesignSpectrum:
    """A design spectrum of the EC8 shape with user values (accelerations in m/s^2).

    ``pga`` is the zero-period value (``ag S`` in EC8), ``plateau`` the value between
    ``tb`` and ``tc`` (``2.5 eta ag S``); the spectrum rises linearly from ``pga`` at
    ``T = 0`` to ``plateau`` at ``tb``, decays as ``1/T`` up to ``td`` and as ``1/T^2``
    after. ``damping`` is the damping ratio the values refer to. Call it with periods::

        target = DesignSpectrum(pga=2.8, plateau=7.0, tb=0.1, tc=0.3, td=1.2)
        target([0.0, 0.2, 1.0])   # -> array([2.8, 7.0, 2.1])

    Examples
    --------
    >>> from rocking.motions import DesignSpectrum
    >>> target = DesignSpectrum(pga=2.8, plateau=7.0, tb=0.1, tc=0.3, td=1.2)
    >>> [round(float(s), 4) for s in target([0.0, 0.2, 1.0, 2.4])]  # 7 tc/T, 7 tc td/T^2
    [2.8, 7.0, 2.1, 0.4375]
    """

    pga: float
    plateau: float
    tb: float
    tc: float
    td: float
    damping: float = 0.05
    name: str = field(default="custom spectrum", compare=False)

    def __post_init__(self):
        pga = non_negative("pga", self.pga, "m/s^2")
        plateau = non_negative("plateau", self.plateau, "m/s^2")
        tb = positive("tb", self.tb, "s")
        tc = as_float("tc", self.tc)
        td = as_float("td", self.td)
        if not tb < tc:
            raise ParameterError(f"tc must be > tb = {tb:g} s, got {self.tc!r}")
        if not tc <= td:
            raise ParameterError(f"td must be >= tc = {tc:g} s, got {self.td!r}")
        object.__setattr__(self, "pga", pga)
        object.__setattr__(self, "plateau", plateau)
        object.__setattr__(self, "tb", tb)
        object.__setattr__(self, "tc", tc)
        object.__setattr__(self, "td", td)
        object.__setattr__(self, "damping", _damping(self.damping))

    @classmethod
    def ec8(cls, ag, ground: str = "A", spectrum_type: int = 1,
            damping: float = 0.05) -> DesignSpectrum:
        """The EN 1998-1 elastic spectrum as a :class:`DesignSpectrum` (:func:`ec8_spectrum`).

        Examples
        --------
        >>> from rocking.motions import DesignSpectrum, ec8_spectrum
        >>> s = DesignSpectrum.ec8(ag=2.0, ground="C")  # Table 3.2: S = 1.15, TB-TD 0.2-2 s
        >>> round(s.pga, 4), round(s.plateau, 4), s.tb, s.tc, s.td  # ag S, 2.5 ag S
        (2.3, 5.75, 0.2, 0.6, 2.0)
        >>> T = [0.1, 0.4, 1.0, 3.0]
        >>> bool(np.allclose(s(T), ec8_spectrum(T, ag=2.0, ground="C")))
        True
        """
        ag = non_negative("ag", ag, "m/s^2")
        prm = ec8_parameters(ground, spectrum_type)
        S = ag * prm["S"]
        return cls(pga=S, plateau=S * PLATEAU_FACTOR * eta(damping), tb=prm["TB"],
                   tc=prm["TC"], td=prm["TD"], damping=damping,
                   name=f"EC8 Type {spectrum_type}, ground {str(ground).upper()}, "
                        f"ag = {ag:.3g} m/s^2, {100 * _damping(damping):g} % damping")

    def __call__(self, periods):
        """Spectral acceleration (m/s^2) at ``periods`` (s); scalar in, float out."""
        T = _periods(periods)
        out = _shape(T, self.pga, self.plateau, self.tb, self.tc, self.td)
        return float(out) if out.ndim == 0 else out

    @property
    def amplification(self) -> float:
        """Plateau over PGA (2.5 eta in EC8)."""
        return self.plateau / self.pga if self.pga > 0 else math.inf

    def scaled(self, factor) -> DesignSpectrum:
        """The spectrum with every ordinate multiplied by ``factor`` (> 0).

        Examples
        --------
        >>> from rocking.motions import paper_target
        >>> t = paper_target()
        >>> half = t.scaled(0.5)  # the corner periods do not change
        >>> half.pga, half.plateau, half.tb, half.tc, half.td
        (1.4, 3.5, 0.1, 0.3, 1.2)
        >>> round(half(2.0) / t(2.0), 12)  # every ordinate, the 1/T^2 branch too
        0.5
        """
        f = positive("factor", factor)
        return replace(self, pga=self.pga * f, plateau=self.plateau * f)

    def with_damping(self, damping) -> DesignSpectrum:
        """The spectrum for another damping ratio: the plateau and the decaying branches
        scale by ``eta(damping) / eta(self.damping)``; the PGA does not change (as in EC8).

        Examples
        --------
        >>> from rocking.motions import paper_target
        >>> t10 = paper_target().with_damping(0.10)  # eta = sqrt(10 / (5 + 10))
        >>> t10.pga, round(t10.plateau, 4), round(7.0 * (10 / 15) ** 0.5, 4)
        (2.8, 5.7155, 5.7155)
        >>> round(t10.with_damping(0.05).plateau, 12)  # back to 5 %: eta = 1
        7.0
        """
        d = _damping(damping)
        r = eta(d) / eta(self.damping)
        return replace(self, plateau=self.plateau * r, damping=d)

    def describe(self) -> str:
        """One line: the values and corner periods.

        Examples
        --------
        >>> from rocking.motions import DesignSpectrum
        >>> print(DesignSpectrum.ec8(ag=2.0, ground="C").describe())
        EC8 Type 1, ground C, ag = 2 m/s^2, 5 % damping: PGA 2.3 m/s^2,
        plateau 5.75 m/s^2 from TB = 0.2 s to TC = 0.6 s, TD = 2 s, 5 % damping
        """
        return (f"{self.name}: PGA {self.pga:.3g} m/s^2, plateau {self.plateau:.3g} m/s^2 "
                f"from TB = {self.tb:g} s to TC = {self.tc:g} s, TD = {self.td:g} s, "
                f"{100 * self.damping:g} % damping")


def paper_target() -> DesignSpectrum:
    """Target spectrum of the paper's 30 synthetic earthquakes (Section 3.3).

    Plateau 7 m/s^2 from 0.1 to 0.3 s, PGA 2.8 m/s^2, 5 % damping, and ``TD = 1.2 s``
    (EC8 Type 2, ground D; the paper does not state TD, see the module doc).

    Examples
    --------
    >>> from rocking.motions import paper_target
    >>> t = paper_target()
    >>> t.pga, t.plateau, t.tb, t.tc, t.td
    (2.8, 7.0, 0.1, 0.3, 1.2)
    >>> round(float(t(0.6)), 4)  # 7 tc / T on the 1/T branch
    3.5
    """
    return DesignSpectrum(pga=2.8, plateau=7.0, tb=0.1, tc=0.3, td=PAPER_TD, damping=0.05,
                          name="paper target (EC8 shape, Type 2 ground D corners)")
