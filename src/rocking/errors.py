"""Exceptions raised for bad input.

Every error that a user can cause derives from :class:`RockingError` and from
:class:`ValueError`, and its message names the offending parameter and the allowed
range. The command line prints such messages as one ``error: ...`` line.
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
