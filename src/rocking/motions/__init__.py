"""Base motions: harmonic table motions, pulses and recorded accelerograms.

All accelerations are in m/s^2 and follow the sign convention of the paper's Eq (1).
``motion=None`` in :func:`rocking.simulate` means free rocking from initial conditions.
"""

from .base import Motion
from .harmonic import HanningSine, Sine
from .io import builtin_records, load_builtin, read_record, write_csv
from .pulses import HalfSine, OneCosine, OneSine, Rectangular, Ricker
from .records import Record, sample

__all__ = [
    "Motion", "Sine", "HanningSine", "OneSine", "OneCosine", "HalfSine", "Rectangular",
    "Ricker", "Record", "sample", "read_record", "write_csv", "builtin_records",
    "load_builtin",
]
