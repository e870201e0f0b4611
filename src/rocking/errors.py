"""Exceptions of the package, all exported from :mod:`rocking`.

Two families:

* **bad input** derives from :class:`RockingError` (and from :class:`ValueError`): the
  message names the offending parameter and the allowed range. The command line prints it
  as one ``error: ...`` line and exits with code 2.
* **numerical failure** is a :class:`SimulationError` (a :class:`RuntimeError`): the input
  was valid but an integration could not be completed (an unstable explicit step, a
  constant step too large near a singularity). The message says what to change. The
  command line prints it as one line and exits with code 1.
"""

from __future__ import annotations


class RockingError(ValueError):
    """Base class of the errors caused by bad input.

    Examples
    --------
    Every bad-input error of the package is a ``RockingError`` and a ``ValueError``:

    >>> import rocking
    >>> issubclass(rocking.SpecError, rocking.RockingError)
    True
    >>> try:
    ...     rocking.Block.rectangular(0.2, -1.0)
    ... except rocking.RockingError as e:
    ...     print(isinstance(e, ValueError), e)
    True height must be > 0 m, got -1.0
    """


class ParameterError(RockingError):
    """A parameter is outside its allowed range, or of the wrong kind.

    Examples
    --------
    The message names the parameter and the allowed range:

    >>> import rocking
    >>> try:
    ...     rocking.simulate(rocking.specimen(2), theta0=2.0)
    ... except rocking.ParameterError as e:
    ...     print(e)
    theta0 must be in (-pi/2, pi/2) rad, got 2.0
    """


class SpecimenError(ParameterError):
    """An unknown specimen or parameter set was asked for.

    Examples
    --------
    >>> import rocking
    >>> try:
    ...     rocking.specimen(7)
    ... except rocking.SpecimenError as e:
    ...     print(e)
    specimen must be one of [1, 2, 3, 4], got 7
    """


class RecordError(RockingError):
    """An accelerogram is empty, malformed, or has unknown units.

    Examples
    --------
    >>> import rocking
    >>> try:
    ...     rocking.motions.read_record("missing.csv")
    ... except rocking.RecordError as e:
    ...     print(e)
    record file not found: missing.csv
    """


class UnitError(ParameterError):
    """A quantity has a missing or unknown unit.

    Examples
    --------
    Quantities given as text need a known unit (``"15cm"``, ``"0.15m"``):

    >>> import rocking
    >>> try:
    ...     rocking.simulate(rocking.specimen(2), model="isolated", clearance="15 parsec")
    ... except rocking.UnitError as e:
    ...     print(e)
    clearance: unknown length unit 'parsec'; allowed: m, cm, mm, um, in, ft
    """


class OutputTooLargeError(ParameterError):
    """The requested output (``duration / dt_out`` samples) would not fit in memory.

    Examples
    --------
    Refused before any memory is taken:

    >>> import rocking
    >>> try:
    ...     rocking.simulate(rocking.specimen(2), duration=1e9, dt_out=1e-6)
    ... except rocking.OutputTooLargeError as e:
    ...     print(e)
    dt_out = 1e-06 s over a duration of 1e+09 s needs 1.6e+07 GB of output ...
    """


class IdentificationError(RockingError):
    """The record does not allow an identification (no rocking, too few impacts, ...).

    Examples
    --------
    >>> import rocking
    >>> try:
    ...     rocking.identify.free_rocking([0.0, 0.1, 0.2], [0.0, 0.0, 0.0])
    ... except rocking.IdentificationError as e:
    ...     print(e)
    the record has only 3 samples; a free-rocking identification needs several half-cycles
    """


class SpecError(ParameterError):
    """A campaign spec (TOML) is malformed: the message names the key.

    Examples
    --------
    >>> from rocking import SpecError
    >>> from rocking.campaign import parse_spec
    >>> try:
    ...     parse_spec("[campaign]\\nnme = 'typo'\\n")
    ... except SpecError as e:
    ...     print(e)
    spec: campaign.nme: unknown key (allowed in [campaign]: duration, ...)
    """


class StoreError(RockingError):
    """A campaign store does not match its spec, or is not a store.

    Examples
    --------
    >>> from rocking import StoreError
    >>> from rocking.campaign import load
    >>> try:
    ...     load("not_a_store")
    ... except StoreError as e:
    ...     print(e)
    not_a_store is not a campaign store (no manifest.json)
    """


class SimulationError(RuntimeError):
    """A numerical failure of a model on valid input (not bad input).

    Examples
    --------
    A constant CCRR step far too large for its regularisation; the message says what to
    change:

    >>> import rocking
    >>> block = rocking.specimen(2)
    >>> try:
    ...     rocking.simulate(block, theta0=0.1, model="ccrr", duration=1.0, dt=0.1)
    ... except rocking.SimulationError as e:
    ...     print(isinstance(e, RuntimeError), e)
    True ccrr integration failed near the origin at t = ...; use a smaller dt or the
    adaptive mode (dt=None)
    """


class PlausibilityWarning(UserWarning):
    """A valid but implausible input (a 6 g record, a 60 m block): most likely a unit
    mistake. A warning, not an error: the run goes on (the CLI prints one ``warning:``
    line).

    Examples
    --------
    A 170 m tall block (170 mm meant):

    >>> import warnings
    >>> import rocking
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     block = rocking.Block.rectangular(0.17, 170.0)
    >>> issubclass(caught[0].category, rocking.PlausibilityWarning)  # a UnitSlipWarning
    True
    >>> print(caught[0].message)
    Block.rectangular: height 170 m is above 50 m; check the units ...
    """


class UnitSlipWarning(PlausibilityWarning):
    """A value that is surely a unit slip: outside the limits of
    :data:`rocking.PLAUSIBLE_LIMITS` (a density outside 300-25,000 kg/m^3, a site PGA
    above 2 g, a block or mesh larger than 50 m, a building period above 20 s). The
    Python API warns (one line); the command line refuses it (exit code 2) unless
    ``--force``, with the same limits.

    Examples
    --------
    A statue's density typed in t/m^3 (2.6 for 2600 kg/m^3):

    >>> import warnings
    >>> import rocking
    >>> from rocking.shapes import Shape
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     box = Shape.box(0.4, 0.6, 2.0, density=2.6)
    >>> caught[0].category.__name__
    'UnitSlipWarning'
    >>> print(caught[0].message)
    density = 2.6 kg/m^3 is outside 300-25,000 kg/m^3: a unit slip? ...
    """


__all__ = ["RockingError", "ParameterError", "SpecimenError", "RecordError", "UnitError",
           "OutputTooLargeError", "IdentificationError", "SimulationError",
           "SpecError", "StoreError", "PlausibilityWarning", "UnitSlipWarning"]
