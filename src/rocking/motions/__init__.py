"""Base motions: harmonic table motions, pulses, recorded and synthetic accelerograms.

All accelerations are in m/s^2 and follow the sign convention of the paper's Eq (1);
a vertical component (:class:`GroundMotion`) is positive upwards (effective gravity
``g + a_v``).
``motion=None`` in :func:`rocking.simulate` means free rocking from initial conditions.

Earthquake input:

* design spectra: :func:`ec8_spectrum` (EN 1998-1 §3.2.2.2), :class:`DesignSpectrum` (the
  same shape with user values), :func:`paper_target` (the paper's target);
* response spectra: :func:`response_spectrum` (exact piecewise-linear recurrence);
* synthetic spectrum-compatible records: :func:`synthetic`, the paper's set of 30
  :func:`seed_earthquakes` (:func:`paper_earthquake`, :func:`earthquake_motion`) and
  :func:`check_compatibility` (EN 1998-1 §3.2.3.1.2);
* sets compatible with EN 1998-1 on each ground type, to 4 s (isolators):
  :func:`ec8_earthquakes`, :func:`ec8_earthquake`; :func:`check_records_fit` warns when a
  study's records fall short of the target at the periods that matter;
* processing of real records (:mod:`rocking.motions.processing`): :func:`resample`,
  :func:`bandpass`, :func:`baseline_correct`, and :func:`intensity_measures` (PGA, PGV,
  PGD, Arias intensity, significant duration).
"""

from .base import Motion
from .ec8 import DesignSpectrum, ec8_spectrum, paper_target
from .ec8_records import RecordFitWarning, check_records_fit, ec8_earthquake, ec8_earthquakes
from .ground import GroundMotion
from .harmonic import HanningSine, Sine
from .io import builtin_records, builtin_sets, read_record, write_csv
from .pair import HorizontalPair
from .processing import (
    arias_intensity,
    bandpass,
    baseline_correct,
    displacement,
    intensity_measures,
    pga,
    pgd,
    pgv,
    resample,
    significant_duration,
    velocity,
)
from .pulses import HalfSine, MavroeidisPapageorgiou, OneCosine, OneSine, Rectangular, Ricker
from .records import Record, load_builtin, sample
from .spectra import response_spectra, response_spectrum, sdof_response
from .stochastic import stochastic_records
from .synthetic import (
    Compatibility,
    Envelope,
    check_compatibility,
    earthquake_motion,
    paper_earthquake,
    seed_earthquakes,
    synthetic,
)

__all__ = [
    "Motion", "Sine", "HanningSine", "OneSine", "OneCosine", "HalfSine", "Rectangular",
    "Ricker", "Record", "sample", "read_record", "write_csv", "builtin_records",
    "GroundMotion", "builtin_sets", "HorizontalPair",
    "MavroeidisPapageorgiou",
    "load_builtin",
    "ec8_spectrum", "DesignSpectrum", "paper_target",
    "response_spectrum", "response_spectra", "sdof_response",
    "synthetic", "Envelope", "seed_earthquakes", "paper_earthquake", "earthquake_motion",
    "check_compatibility", "Compatibility",
    "ec8_earthquakes", "ec8_earthquake", "check_records_fit", "RecordFitWarning",
    "stochastic_records",
    "resample", "bandpass", "baseline_correct", "velocity", "displacement", "pga", "pgv",
    "pgd", "arias_intensity", "significant_duration", "intensity_measures",
]
