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
    """Base class of the errors caused by bad input."""


class ParameterError(RockingError):
    """A parameter is outside its allowed range, or of the wrong kind."""


class SpecimenError(ParameterError):
    """An unknown specimen or parameter set was asked for."""


class RecordError(RockingError):
    """An accelerogram is empty, malformed, or has unknown units."""


class UnitError(ParameterError):
    """A quantity has a missing or unknown unit."""


class OutputTooLargeError(ParameterError):
    """The requested output (``duration / dt_out`` samples) would not fit in memory."""


class IdentificationError(RockingError):
    """The record does not allow an identification (no rocking, too few impacts, ...)."""


class SpecError(ParameterError):
    """A campaign spec (TOML) is malformed: the message names the key."""


class StoreError(RockingError):
    """A campaign store does not match its spec, or is not a store."""


class SimulationError(RuntimeError):
    """A numerical failure of a model on valid input (not bad input)."""


class PlausibilityWarning(UserWarning):
    """A valid but implausible input (a 6 g record, a 60 m block): most likely a unit
    mistake. A warning, not an error: the run goes on (the CLI prints one ``warning:``
    line)."""


__all__ = ["RockingError", "ParameterError", "SpecimenError", "RecordError", "UnitError",
           "OutputTooLargeError", "IdentificationError", "SimulationError",
           "SpecError", "StoreError", "PlausibilityWarning"]
