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

from . import dem, motions
from .blocks import Block, Stack, housner_mu, specimen
from .errors import ParameterError, RecordError, RockingError, SpecimenError, UnitError
from .models import simulate, simulate_many
from .results import BatchResponse, Response
from .units import G

__version__ = "0.1.0"

__all__ = [
    "Block", "Stack", "housner_mu", "specimen", "simulate", "simulate_many", "Response",
    "BatchResponse", "motions", "dem", "G", "RockingError", "ParameterError", "RecordError",
    "SpecimenError", "UnitError", "__version__",
]
