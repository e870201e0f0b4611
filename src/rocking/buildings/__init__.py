"""Buildings as linear filters of the ground motion: the floors that objects stand on.

A light object on a floor responds to the floor's motion without acting back on the
building (the cascade of FEMA E-74, ASCE 7-22 chapter 13 and EN 1998-1 4.3.5): the
building turns the ground acceleration into an absolute floor acceleration, by modal
superposition (:class:`Building`, :class:`FloorMotion`).
"""

from .building import Building
from .floor import FloorMotion
from .spectra import asce7_hf, code_floor_spectrum_ec8, floor_spectrum, plot_floor_spectrum

__all__ = ["Building", "FloorMotion", "floor_spectrum", "code_floor_spectrum_ec8", "asce7_hf",
           "plot_floor_spectrum"]
