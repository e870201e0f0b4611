"""rocking: dynamics of free-standing rigid blocks (rocking, impact, overturning).

Implements the models of Peña, Prieto, Lourenço, Campos Costa & Lemos (2007), "On the
dynamics of rocking motion of single rigid-block structures", EESD 36:2383-2399.

Quick start::

    import rocking
    from rocking.motions import Sine
    block = rocking.specimen(2, params="experimental")
    r = rocking.simulate(block, Sine(freq=5.0, amplitude=0.005, duration=25.0))
    r.max_abs_theta, r.overturned

Units are SI throughout: m, s, kg, rad, m/s^2.
"""

import importlib
import importlib.abc
import importlib.util
import sys

from ._numba_cache import ensure_numba_cache
from ._validate import PLAUSIBLE_LIMITS
from .blocks import Block, Stack, housner_mu, specimen
from .errors import (
    IdentificationError,
    OutputTooLargeError,
    ParameterError,
    PlausibilityWarning,
    RecordError,
    RockingError,
    SimulationError,
    SpecError,
    SpecimenError,
    StoreError,
    UnitError,
    UnitSlipWarning,
)
from .results import BatchResponse, DEMResponse, Response
from .units import G

ensure_numba_cache()  # before any kernel is compiled: a cache numba can write, or none
del ensure_numba_cache

__version__ = "0.1.0"

_SUBMODULES = ("blocks", "motions", "buildings", "models", "results", "identify", "analysis",
               "campaign", "report", "cli", "testing", "units", "errors", "plot",
               "viewer3d")
"""Submodules loaded on first access (PEP 562): ``rocking.identify.free_rocking`` works
after ``import rocking``, and ``import rocking`` stays cheap (no numba compilation)."""
_LAZY = {"simulate": ("rocking.models", "simulate"),
         "simulate_many": ("rocking.models", "simulate_many"),
         "MODELS": ("rocking.models", "MODELS"),
         "dem": ("rocking.models.dem", None)}


def __getattr__(name: str):
    if name in _SUBMODULES:
        return importlib.import_module(f"{__name__}.{name}")
    if name in _LAZY:
        module, attr = _LAZY[name]
        mod = importlib.import_module(module)
        value = mod if attr is None else getattr(mod, attr)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


class _Alias(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Former module names still importable (``import rocking.dem``, ``from rocking.dem
    import paper_parameters``): each is the module it moved to, imported on first use."""

    MOVED = {"rocking.dem": "rocking.models.dem"}

    def find_spec(self, name, path=None, target=None):
        if name in self.MOVED:
            return importlib.util.spec_from_loader(name, self)
        return None

    def create_module(self, spec):
        module = importlib.import_module(self.MOVED[spec.name])
        self._spec = module.__spec__
        return module

    def exec_module(self, module):
        module.__spec__ = self._spec  # the import system set the alias's spec: restore it


if not any(isinstance(f, _Alias) for f in sys.meta_path):
    sys.meta_path.append(_Alias())


def __dir__():
    return sorted(set(globals()) | set(_SUBMODULES) | set(_LAZY))


__all__ = [
    "Block", "Stack", "housner_mu", "specimen", "simulate", "simulate_many", "Response",
    "BatchResponse", "DEMResponse", "MODELS", "G", "RockingError", "ParameterError",
    "RecordError", "SpecimenError", "UnitError", "OutputTooLargeError", "IdentificationError",
    "SimulationError", "SpecError", "StoreError", "PlausibilityWarning", "UnitSlipWarning",
    "PLAUSIBLE_LIMITS", "__version__",
]
