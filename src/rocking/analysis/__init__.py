"""Analysis layer: stochastic analysis, overturning spectra, Monte Carlo and fragility.

Built on the model interface (:func:`rocking.simulate`, :func:`rocking.simulate_many`);
every function returns a tidy :class:`pandas.DataFrame` or a result object with a
``plot()``.

* :func:`motion_space`: the rocking-motion space of Table IV;
* :func:`fourier_spectrum`: amplitude spectrum of theta(t) and its peaks (Fig. 6b);
* :func:`overturning_spectrum`, :func:`outcome_map`: pulses in the dimensionless plane
  (omega_p/p, a_p/(g tan alpha)) of Dimitrakopoulos and DeJong (2012);
* :func:`monte_carlo`: uncertain block, initial tilt and table motion; P(overturn) with a
  Wilson interval (:func:`wilson_interval`);
* :func:`ida`: records scaled to intensity levels (stripes / IDA), :func:`ida_capacity`;
* :func:`fragility`, :func:`fragility_ida`, :func:`fragility_curves` (damage states,
  :func:`damage_state`), :func:`annual_frequency`;
* :func:`compare_mitigations`: fragility, hazard and isolator demand per mitigation
  (:class:`MitigationComparison`, :func:`plot_mitigations`; issue 19);
* :func:`direction_sweep`: a 3-D body's planar analysis in every direction under two
  horizontal components, and its worst direction (:class:`DirectionSweep`), and
  :func:`direction_fragility`, a fragility curve per direction (issue 20); its 3-D
  counterpart :func:`heading_sweep`, the body itself (``rigid3d``) at every heading of a
  pair (:class:`HeadingSweep`; issue 30), and :func:`heading_fragility`, a fragility
  curve per heading of a campaign's rows, the worst heading and the pooled curve with a
  bootstrap by record (:class:`HeadingFragility`);
* :func:`select_records`: amplitude-scaled records whose mean spectrum matches a target
  (EN 1998-1 3.2.3.1.2; :class:`SelectionResult`, :func:`default_periods`,
  :func:`uniform_hazard_spectrum` of SA hazard curves as a target; issue 21);
* :class:`HazardCurve` (OpenQuake export, CSV, EN 1998-1 code value), :func:`risk` (annual
  frequency with power-law tails, probability in 50 years), :func:`probability_in`,
  :func:`plot_risk` (issue 21).
"""

from .damage import DEFAULT_THRESHOLDS, FragilityCurves, damage_state, fragility_curves
from .directions import (
    DirectionFragility,
    DirectionSweep,
    HeadingSweep,
    direction_fragility,
    direction_sweep,
    heading_sweep,
    plot_sweeps,
)
from .fourier import FourierSpectrum, fourier_spectrum
from .fragility import FragilityFit, annual_frequency, fragility, fragility_ida
from .harmonic import motion_space, plot_motion_space
from .hazard import HazardCurve, Risk, plot_risk, probability_in, risk
from .headings import HeadingFragility, heading_fragility
from .ida import ida, ida_capacity, plot_ida
from .mitigation import MitigationComparison, compare_mitigations, plot_mitigations
from .montecarlo import MonteCarloResult, monte_carlo, wilson_interval
from .overturning import (
    PULSES,
    outcome_map,
    overturning_spectrum,
    plot_outcome_map,
    plot_overturning_spectrum,
    pulse_motion,
)
from .selection import (
    SelectionResult,
    default_periods,
    select_records,
    uniform_hazard_spectrum,
)

__all__ = [
    "motion_space", "plot_motion_space", "monte_carlo", "MonteCarloResult", "wilson_interval",
    "ida", "ida_capacity", "plot_ida", "fragility", "fragility_ida", "FragilityFit",
    "annual_frequency", "compare_mitigations", "MitigationComparison", "plot_mitigations",
    "fragility_curves", "FragilityCurves", "damage_state", "DEFAULT_THRESHOLDS",
    "fourier_spectrum", "FourierSpectrum", "overturning_spectrum", "outcome_map",
    "plot_overturning_spectrum", "plot_outcome_map", "pulse_motion", "PULSES",
    "direction_sweep", "DirectionSweep", "plot_sweeps", "direction_fragility",
    "DirectionFragility", "heading_sweep", "HeadingSweep", "heading_fragility",
    "HeadingFragility", "HazardCurve", "Risk", "risk",
    "probability_in", "plot_risk",
    "select_records", "SelectionResult", "default_periods", "uniform_hazard_spectrum",
]
