"""Validation helpers used at the edges of the API (scikit-learn style).

Each returns the validated value as a float and raises :class:`ParameterError` with a
message that names the parameter and the allowed range.
"""

from __future__ import annotations

import math

from .errors import ParameterError


def as_float(name: str, value) -> float:
    """``value`` as a finite float."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a finite number, got {value!r}") from None
    if not math.isfinite(x):
        raise ParameterError(f"{name} must be a finite number, got {value!r}")
    return x


def positive(name: str, value, unit: str = "") -> float:
    """A finite number > 0."""
    x = as_float(name, value)
    if x <= 0.0:
        u = f" {unit}" if unit else ""
        raise ParameterError(f"{name} must be > 0{u}, got {value!r}")
    return x


def non_negative(name: str, value, unit: str = "") -> float:
    """A finite number >= 0."""
    x = as_float(name, value)
    if x < 0.0:
        u = f" {unit}" if unit else ""
        raise ParameterError(f"{name} must be >= 0{u}, got {value!r}")
    return x


def in_range(
    name: str,
    value,
    lo: float,
    hi: float,
    *,
    lo_open: bool = True,
    hi_open: bool = True,
    shown: str | None = None,
) -> float:
    """A finite number in the interval lo..hi (open or closed at each end)."""
    x = as_float(name, value)
    ok_lo = x > lo if lo_open else x >= lo
    ok_hi = x < hi if hi_open else x <= hi
    if not (ok_lo and ok_hi):
        rng = shown or f"{'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}"
        raise ParameterError(f"{name} must be in {rng}, got {value!r}")
    return x


def sequence_of(name: str, value, cls, what: str) -> tuple:
    """``value`` as a non-empty tuple of ``cls`` instances (``what`` names them)."""
    try:
        items = tuple(value)
    except TypeError:
        raise ParameterError(f"{name} must be a sequence of {what} objects") from None
    if not items:
        raise ParameterError(f"{name} must be a non-empty sequence of {what} objects")
    for i, x in enumerate(items):
        if not isinstance(x, cls):
            raise ParameterError(f"{name}[{i}] must be a {what}, got {type(x).__name__}")
    return items
