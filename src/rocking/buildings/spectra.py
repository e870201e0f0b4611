r"""Floor response spectra, and the codes' curves for non-structural elements.

* :func:`floor_spectrum`: the response spectrum of the floor motion
  (:class:`~rocking.buildings.FloorMotion`): the peak response of a light oscillator
  (an object, a piece of equipment) of period ``T`` standing on the floor, by the same
  exact recurrence as the ground's spectra
  (:func:`rocking.motions.response_spectrum`).
* :func:`code_floor_spectrum_ec8`: EN 1998-1:2004 4.3.5.2, Eq (4.25), the seismic
  coefficient of a non-structural element of period ``Ta`` at height ``z`` of a building
  of height ``H`` and fundamental period ``T1``:

  .. math::  S_a = \alpha S \left[\frac{3 (1 + z/H)}{1 + (1 - T_a/T_1)^2} - 0.5\right]
             \ge \alpha S

  (``alpha = a_g / g``; here in acceleration units, ``a_g S`` times the bracket). It is
  ``a_g S`` at the ground for a rigid element (``z = 0``, ``Ta = 0``), ``2.5 a_g S`` on
  the roof for a rigid element and ``5.5 a_g S`` on the roof at resonance
  (``Ta = T1``); the lower bound ``a_g S`` governs for ``Ta > 2 T1`` at the ground and
  ``Ta > (1 + sqrt 3) T1`` on the roof (the bracket falls below 1 there).
* :func:`asce7_hf`: ASCE/SEI 7-22 13.3.1.1, the amplification of the peak floor
  acceleration with height, Eq (13.3-4)

  .. math::  H_f = 1 + a_1 \frac{z}{h} + a_2 \left(\frac{z}{h}\right)^{10}, \quad
             a_1 = \frac{1}{T_a} \le 2.5, \quad a_2 = 1 - \left(\frac{0.4}{T_a}\right)^2
             \ge 0

  (``Ta`` the building's approximate fundamental period, 12.8.2.1), or Eq (13.3-5)
  ``H_f = 1 + 2.5 z/h`` when the period is not known. The component force is then
  ``F_p = 0.4 S_DS I_p W_p (H_f / R_mu)(C_AR / R_po)`` (Eq 13.3-1): ``0.4 S_DS H_f`` is
  the peak floor acceleration and the component resonance factor ``C_AR`` (Tables
  13.5-1 and 13.6-1) turns it into the component's peak acceleration. ``H_f`` is
  continuous at ``Ta = 0.4 s`` (``a1 = 2.5``, ``a2 = 0``: ``H_f(roof) = 3.5``); at
  ``Ta = 1 s`` the roof value is ``1 + 1 + 0.84 = 2.84``.

A rocking object is not a linear oscillator: the spectra tell how the building
amplifies the motion at the periods near its modes (where a block's rocking period,
which grows with the amplitude, may come to lie), not whether the block overturns; for
that, simulate the block on the floor motion itself.
"""

from __future__ import annotations

import numpy as np

from .._validate import in_range, non_negative, positive
from ..errors import ParameterError
from ..motions.base import Motion
from ..motions.spectra import KINDS, response_spectrum
from .building import Building
from .floor import FloorMotion

__all__ = ["floor_spectrum", "code_floor_spectrum_ec8", "asce7_hf", "plot_floor_spectrum"]

EC8_RIGID_ROOF = 2.5
"""Eq (4.25) at ``z = H``, ``Ta = 0``: ``3 * 2 / 2 - 0.5``."""
EC8_RESONANT_ROOF = 5.5
"""Eq (4.25) at ``z = H``, ``Ta = T1``: ``3 * 2 / 1 - 0.5``."""


def floor_spectrum(ground, building: Building | None = None, floor: int | None = None,
                   periods=None, damping: float = 0.05, *, height_ratio: float | None = None,
                   kind: str = "psa", dt: float | None = None):
    """The floor response spectrum: the peak response of an oscillator on the floor.

    Parameters
    ----------
    ground : Motion or FloorMotion
        The ground motion (with ``building`` and ``floor``/``height_ratio``), or a
        :class:`~rocking.buildings.FloorMotion` already built (then leave ``building``,
        ``floor``, ``height_ratio`` and ``dt`` out).
    building : Building
    floor : int, optional
        Floor (0 is the ground); or ``height_ratio`` ``z/H``.
    periods : array_like
        Oscillator periods (s), >= 0 (``T = 0``: the peak floor acceleration).
    damping : float
        The oscillator's damping ratio (0.05 = 5 %).
    kind : {"psa", "sa", "sd", "psv", "sv"}
        Spectral quantity (:func:`rocking.motions.response_spectrum`); the default is the
        pseudo-acceleration ``omega^2 max|u|`` (m/s^2).
    dt : float, optional
        The floor record's step (:class:`~rocking.buildings.FloorMotion`).

    Returns
    -------
    numpy.ndarray or float
        One value per period.

    Examples
    --------
    >>> import numpy as np, rocking
    >>> from rocking.buildings import Building, floor_spectrum
    >>> g = rocking.motions.load_builtin("Rinaldi228")
    >>> T = np.array([0.0, 0.5, 1.0])
    >>> roof = floor_spectrum(g, Building.sdof(0.5), floor=1, periods=T)
    >>> bool(roof[1] > rocking.motions.response_spectrum(g, 0.5))  # resonance at T1
    True
    """
    if periods is None:
        raise ParameterError("periods: give the oscillator periods (s)")
    if kind not in KINDS:
        raise ParameterError(f"kind must be one of {', '.join(KINDS)}; got {kind!r}")
    if isinstance(ground, FloorMotion):
        if building is not None or floor is not None or height_ratio is not None \
                or dt is not None:
            raise ParameterError("building, floor, height_ratio, dt: a FloorMotion already "
                                 "has them; leave them out")
        fm = ground
    else:
        if not isinstance(ground, Motion):
            raise ParameterError(f"ground must be a rocking.motions.Motion, got "
                                 f"{type(ground).__name__}")
        if building is None:
            raise ParameterError("building: give the Building the floor belongs to")
        fm = FloorMotion(ground, building, floor=floor, height_ratio=height_ratio, dt=dt)
    return response_spectrum(fm.record, periods, damping=damping, kind=kind)


def _ratio(name: str, x) -> np.ndarray:
    try:
        a = np.asarray(x, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number in [0, 1], got {x!r}") from None
    if not np.all(np.isfinite(a)) or np.any(a < 0.0) or np.any(a > 1.0):
        raise ParameterError(f"{name} must be in [0, 1] (a height ratio), got {x!r}")
    return a


def _periods(name: str, x) -> np.ndarray:
    try:
        a = np.asarray(x, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be periods >= 0 s, got {x!r}") from None
    if a.size == 0 or not np.all(np.isfinite(a)) or np.any(a < 0.0):
        raise ParameterError(f"{name} must be finite periods >= 0 s, got {x!r}")
    return a


def code_floor_spectrum_ec8(periods, ag_S: float, z_over_H, T1: float):
    r"""EN 1998-1:2004 4.3.5.2 Eq (4.25): the seismic coefficient of a non-structural
    element, as an acceleration.

    .. math::  S_a(T_a) = a_g S \max\left(\frac{3 (1 + z/H)}{1 + (1 - T_a/T_1)^2} - 0.5,
               \; 1\right)

    Parameters
    ----------
    periods : float or array_like
        ``Ta``, the element's fundamental period (s), >= 0.
    ag_S : float
        Design ground acceleration times the soil factor, ``a_g S`` (``alpha S g``), >= 0;
        the result is in its units (m/s^2 or g).
    z_over_H : float or array_like
        Height of the element over the building's height, in [0, 1] (broadcast with
        ``periods``).
    T1 : float
        The building's fundamental period (s), > 0.

    Returns
    -------
    numpy.ndarray or float
        ``Sa`` times ``g`` in the units of ``ag_S`` (the code's ``Sa`` is a fraction of
        ``g``: divide by ``g``). The lower bound ``alpha S`` of the code is applied.

    Examples
    --------
    >>> from rocking.buildings import code_floor_spectrum_ec8
    >>> [float(code_floor_spectrum_ec8(T, 1.0, 1.0, 0.5)) for T in (0.0, 0.5, 5.0)]
    [2.5, 5.5, 1.0]
    """
    Ta = _periods("periods", periods)
    a = non_negative("ag_S", ag_S)
    x = _ratio("z_over_H", z_over_H)
    T1 = positive("T1", T1, "s")
    Sa = a * np.maximum(3.0 * (1.0 + x) / (1.0 + (1.0 - Ta / T1) ** 2) - 0.5, 1.0)
    return float(Sa) if Sa.ndim == 0 else Sa


def asce7_hf(z_over_h, Ta: float | None = None):
    r"""ASCE/SEI 7-22 13.3.1.1: the factor ``H_f`` of the peak floor acceleration over the
    peak ground acceleration at height ``z/h``.

    Eq (13.3-4), with the building's approximate fundamental period ``Ta`` (s):

    .. math::  H_f = 1 + a_1 (z/h) + a_2 (z/h)^{10}, \quad a_1 = \min(1/T_a, 2.5),
               \quad a_2 = \max(1 - (0.4/T_a)^2, 0);

    Eq (13.3-5) when ``Ta`` is not known (``Ta=None``): ``H_f = 1 + 2.5 z/h``.

    Parameters
    ----------
    z_over_h : float or array_like
        Height of the attachment over the structure's height, in [0, 1].
    Ta : float, optional
        The building's approximate fundamental period (s), > 0.

    Returns
    -------
    numpy.ndarray or float

    Examples
    --------
    >>> from rocking.buildings import asce7_hf
    >>> asce7_hf(1.0, 0.4), round(asce7_hf(1.0, 1.0), 6), asce7_hf(1.0)
    (3.5, 2.84, 3.5)
    """
    x = _ratio("z_over_h", z_over_h)
    if Ta is None:
        hf = 1.0 + 2.5 * x
    else:
        Ta = positive("Ta", Ta, "s")
        a1 = min(1.0 / Ta, 2.5)
        a2 = max(1.0 - (0.4 / Ta) ** 2, 0.0)
        hf = 1.0 + a1 * x + a2 * x ** 10
    return float(hf) if np.ndim(hf) == 0 else hf


def plot_floor_spectrum(ax, periods, floor, ground=None, *, references=None,
                        damping: float | None = 0.05, units: str = "m/s^2",
                        label: str = "floor", title: str | None = None):
    """Draw a floor response spectrum on a matplotlib Axes; returns the Axes.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    periods : array_like
        Periods (s) of the spectra; a log axis over the positive ones.
    floor : array_like
        The floor spectrum (pseudo-acceleration, m/s^2), e.g. :func:`floor_spectrum`.
    ground : array_like, optional
        The ground's spectrum at the same periods (drawn thin, black).
    references : dict, optional
        ``{label: values}`` reference curves at ``periods`` (m/s^2), drawn dashed: e.g.
        :func:`code_floor_spectrum_ec8`, or ``asce7_hf(z/h, Ta) * pga`` as a constant.
    damping : float or None
        The oscillators' damping ratio, for the legend (None: not shown).
    units : {"m/s^2", "g"}
        Display units (values are divided by g for ``"g"``).
    label, title : str
        Legend label of the floor curve; Axes title.

    Notes
    -----
    The style is :func:`rocking.plot.style_axes` with the colour palette
    :data:`rocking.plot.PALETTE`.

    Examples
    --------
    >>> import numpy as np, rocking
    >>> from matplotlib.figure import Figure
    >>> from rocking.buildings import Building, floor_spectrum, plot_floor_spectrum
    >>> g = rocking.motions.load_builtin("Rinaldi228")
    >>> T = np.geomspace(0.05, 3.0, 40)
    >>> ax = plot_floor_spectrum(Figure().add_subplot(), T,
    ...                          floor_spectrum(g, Building.sdof(0.5), floor=1, periods=T),
    ...                          rocking.motions.response_spectrum(g, T), units="g")
    """
    from ..plot import PALETTE, style_axes
    from ..units import G

    if units not in ("m/s^2", "g"):
        raise ParameterError(f"units must be 'm/s^2' or 'g', got {units!r}")
    T = _periods("periods", periods)
    k = 1.0 / G if units == "g" else 1.0
    dmp = ""
    if damping is not None:
        zeta = in_range("damping", damping, 0.0, 1.0, lo_open=False)
        dmp = f" ({100 * zeta:g} % damping)"
    ax.plot(T, k * np.asarray(floor, dtype=float), color=PALETTE[0], lw=1.6,
            label=f"{label}{dmp}", zorder=4)
    if ground is not None:
        ax.plot(T, k * np.asarray(ground, dtype=float), color=PALETTE[6], lw=1.0,
                label="ground", zorder=3)
    for i, (name, vals) in enumerate((references or {}).items()):
        ax.plot(T, k * np.asarray(vals, dtype=float), color=PALETTE[1 + i % 5], lw=1.2,
                ls="--", label=name, zorder=3)
    pos = T[T > 0]
    if pos.size:
        ax.set_xscale("log")
        ax.set_xlim(pos.min(), T.max())
    ax.set_ylim(bottom=0.0)
    style_axes(ax, "period T (s)",
               f"pseudo-acceleration ({'g' if units == 'g' else 'm/s²'})")
    if title:
        ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8, framealpha=0.9)
    return ax
