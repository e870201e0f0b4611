"""The building catalog: each kind of building with its declared parameters.

``rocking simulate --building shear --storeys 5 --building-period 0.5
--building-damping 5% --floor 3`` and a campaign spec's ``[building]`` table build through
:func:`make_building`, as motions build through :mod:`rocking.motions.catalog` and blocks
through :mod:`rocking.blocks.factory`::

    >>> from rocking.buildings.catalog import make_building
    >>> make_building({"kind": "sdof", "period": "0.4s", "damping_ratio": "5%"})
    Building('SDOF building, T = 0.4 s', 1 mode(s), T = [0.4] s, zeta = 0.05)

One unit per parameter name (:data:`rocking.options.UNITS`): the damping is named
``damping_ratio`` here (a ratio: ``5%`` or 0.05) because ``damping`` is the DEM's
stiffness-proportional coefficient in s, and Miranda and Taghavi's ``alpha`` is
``stiffness_ratio`` because ``alpha`` is a block's slenderness in rad; the Python
constructors of :class:`~rocking.buildings.Building` keep the papers' names ``damping``
and ``alpha``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from .._validate import PLAUSIBLE_LIMITS
from ..errors import ParameterError
from ..options import REQUIRED, Options, option
from .building import DEFAULT_CONTINUOUS_MODES, MAX_CONTINUOUS_MODES, MAX_STOREYS, Building

MAX_PERIOD = PLAUSIBLE_LIMITS["building_period"][1]
"""Longest first-mode period a building may have (s): the tallest buildings have T1 of
about 10 s; a larger value is a unit mistake (500 for 0.5 s). The limit of
:data:`rocking.PLAUSIBLE_LIMITS` (the Python constructors warn above it)."""


def _period(help_: str = "first-mode period"):
    return option(REQUIRED, help=help_, unit="s", lo=0.0, hi=MAX_PERIOD, quantity="time",
                  required=True)


def _damping():
    return option(0.05, help="modal damping ratio (5% or 0.05; > 0: an undamped building "
                  "never rings down)", lo=0.0, hi=1.0, lo_open=True, hi_open=True,
                  quantity="ratio")


@dataclass(frozen=True)
class SdofParams(Options):
    period: float = _period("period of the oscillator (the floor is its mass)")
    damping_ratio: float = _damping()


@dataclass(frozen=True)
class ShearParams(Options):
    storeys: int = option(REQUIRED, help="number of storeys (floors 1..storeys)", lo=1,
                          hi=MAX_STOREYS, lo_open=False, kind=int, required=True)
    period: float = _period()
    damping_ratio: float = _damping()
    masses: tuple | None = option(REQUIRED, help="relative storey masses, bottom to top "
                                  "(default uniform)", kind=object)
    stiffnesses: tuple | None = option(REQUIRED, help="relative storey stiffnesses, bottom "
                                       "to top (default uniform)", kind=object)


@dataclass(frozen=True)
class ContinuousParams(Options):
    period: float = _period()
    stiffness_ratio: float = option(REQUIRED, help="lateral stiffness ratio alpha_0 of "
                                    "Miranda and Taghavi (2005): 0 flexural, large shear "
                                    "(about 0-5 for walls, 5-20 for frames)", lo=0.0,
                                    lo_open=False, required=True)
    damping_ratio: float = _damping()
    n_modes: int = option(DEFAULT_CONTINUOUS_MODES, help="modes kept", lo=1,
                          hi=MAX_CONTINUOUS_MODES, lo_open=False, kind=int)
    storeys: int | None = option(REQUIRED, help="floors at z/H = k/storeys (default: "
                                 "height_ratio only)", lo=1, hi=MAX_STOREYS, lo_open=False,
                                 kind=int)


@dataclass(frozen=True)
class ModalParams(Options):
    periods: tuple = option(REQUIRED, help="modal periods (s), first mode first",
                            kind=object, required=True)
    shapes: tuple = option(REQUIRED, help="mode shapes at floors 1..N: one row per floor, "
                           "one column per mode", kind=object, required=True)
    participation: tuple = option(REQUIRED, help="participation factors, one per mode "
                                  "(with the same normalisation of the shapes)",
                                  kind=object, required=True)
    damping_ratio: float = _damping()
    heights: tuple | None = option(REQUIRED, help="height ratio z/H of floors 1..N, "
                                   "increasing to 1 (for height_ratio and the code floor "
                                   "spectra)", kind=object)


def _sdof(p: SdofParams) -> Building:
    return Building.sdof(p.period, p.damping_ratio)


def _shear(p: ShearParams) -> Building:
    return Building.shear(p.storeys, p.period, p.damping_ratio, masses=p.masses,
                          stiffnesses=p.stiffnesses)


def _continuous(p: ContinuousParams) -> Building:
    return Building.continuous(p.period, p.stiffness_ratio, p.damping_ratio, n_modes=p.n_modes,
                               n_floors=p.storeys)


def _modal(p: ModalParams) -> Building:
    return Building.modal(p.periods, p.damping_ratio, p.shapes, p.participation,
                          heights=p.heights)


@dataclass(frozen=True)
class BuildingKind:
    """One kind of building: its declared parameters and the constructor."""

    name: str
    summary: str
    Params: type[Options]
    make: Callable[[Options], Building]

    def describe(self) -> list[dict]:
        return self.Params.describe()


KINDS: dict[str, BuildingKind] = {k.name: k for k in (
    BuildingKind("sdof", "one oscillator (rocking.buildings.Building.sdof)", SdofParams,
                 _sdof),
    BuildingKind("shear", "a shear building of lumped storeys (Building.shear)",
                 ShearParams, _shear),
    BuildingKind("continuous", "Miranda and Taghavi's shear-flexural beam "
                 "(Building.continuous)", ContinuousParams, _continuous),
    BuildingKind("modal", "modal properties from your own structural model "
                 "(Building.modal)", ModalParams, _modal),
)}
"""The building kinds by name."""


def make_building(mapping: dict) -> Building:
    """The :class:`~rocking.buildings.Building` of ``mapping`` (``kind`` and that kind's
    parameters; numbers in SI or strings with a unit). Raises
    :class:`~rocking.errors.ParameterError` naming the key."""
    if not isinstance(mapping, dict):
        raise ParameterError(f"building must be a table of keys, got {mapping!r}")
    values = dict(mapping)
    name = values.pop("kind", None)
    if name not in KINDS:
        raise ParameterError(f"kind must be one of {', '.join(KINDS)}; got {name!r}")
    k = KINDS[name]
    k.Params.unknown(values, f"a {name} building")
    return k.make(k.Params(**values))


def table() -> list[dict]:
    """Every kind and key, one dict each (``kind``, ``name``, ``unit``, ``range``, ...)."""
    return [{**d, "type": d["kind"], "kind": k.name} for k in KINDS.values()
            for d in k.describe()]
