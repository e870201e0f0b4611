"""Validation helpers used at the edges of the API (scikit-learn style).

Each returns the validated value (a float, or a bool/int for :func:`as_bool` and
:func:`as_int`) and raises :class:`ParameterError` with a message that names the
parameter and the allowed values.

Types are strict: a number is never a bool (``True`` is not 1 m), a bool is only
``True``/``False`` (or ``numpy.bool_``; never a string such as ``"false"``), and a count
is a Python or numpy integer (a float is refused, even a whole one such as ``2.0``, so
that a count never comes from arithmetic that may have rounded).
"""

from __future__ import annotations

import contextlib
import math
import numbers
import os
import sys
import warnings

import numpy as np

from .errors import ParameterError, PlausibilityWarning, UnitSlipWarning
from .units import G

_PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__)) + os.sep


def _inside(code) -> bool:
    """A frame of the package (or a dataclass's generated ``__init__``)."""
    name = code.co_filename
    if name == "<string>" and code.co_name == "__init__":
        return True
    return os.path.abspath(name).startswith(_PACKAGE_DIR)


def warn_implausible(message: str, category: type[Warning] = PlausibilityWarning) -> None:
    """Issue a one-line :class:`PlausibilityWarning` (or ``category``), attributed to the
    first caller outside the package (so that it is shown once per place in the user's
    code)."""
    level, f = 1, sys._getframe(0)
    while f is not None and _inside(f.f_code):
        f, level = f.f_back, level + 1
    warnings.warn(message, category, stacklevel=level)


_SHOWN: set = set()
"""``(category, text)`` of the warnings :func:`each_warning_once` has let through."""


@contextlib.contextmanager
def each_warning_once():
    """Inside, every warning is shown at most once per process (by category and text),
    then with the filters in force outside (``ignore``, ``error``, ...): for work that
    repeats, such as a campaign's chunks, each of which builds its model again (the
    isolated model's notice about the restitution it derives, issue 31). The warnings are
    recorded inside and issued again on the way out, even if the body raises.

    Examples
    --------
    >>> import warnings
    >>> from rocking._validate import each_warning_once
    >>> with warnings.catch_warnings(record=True) as seen:
    ...     warnings.simplefilter("always")
    ...     for _ in range(3):
    ...         with each_warning_once():
    ...             warnings.warn("said once (doctest of each_warning_once)")
    >>> len(seen)
    1
    """
    caught: list = []
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            yield
    finally:
        for w in caught:
            key = (w.category, str(w.message))
            if key not in _SHOWN:
                _SHOWN.add(key)
                warnings.warn_explicit(w.message, w.category, w.filename, w.lineno,
                                       source=w.source)


def warn_deprecated(message: str) -> None:
    """A one-line :class:`DeprecationWarning` attributed to the first caller outside the
    package (:func:`warn_implausible`)."""
    warn_implausible(message, DeprecationWarning)


PLAUSIBLE_LIMITS = {
    "density": (300.0, 25_000.0, "kg/m^3",
                "lighter than most woods, or denser than any metal: osmium is 22,590",
                "2.6 g/cm^3 (t/m^3) is 2600 kg/m^3"),
    "site_pga": (0.0, 2.0 * G, "m/s^2",
                 "no code gives a site PGA near it",
                 "2.45 m/s^2 is 0.25 g, not 2.45 g"),
    "size": (0.0, 50.0, "m", "larger than 50 m",
             "a mesh in mm read as m? units='mm' (--units mm); 170 mm is 0.17 m"),
    "building_period": (0.0, 20.0, "s",
                        "the tallest buildings have a first period of about 10 s",
                        "0.5 s typed as 500?"),
}
"""The one set of limits beyond which a value is surely a unit slip, shared by the Python
API (a :class:`~rocking.errors.UnitSlipWarning`) and the command line (a refusal unless
``--force``): ``kind -> (low, high, SI unit, why, hint)`` (the message states the value,
the limit and the hint). A density outside
300-25,000 kg/m^3, a site's reference PGA (``pga_475``, ``pga_2475``) above 2 g, a block
or a mesh larger than 50 m, a building's first period above 20 s."""


def check_plausible(kind: str, value: float, name: str, *, shown: str | None = None,
                    hint: str | None = None) -> bool:
    """Warn (:class:`~rocking.errors.UnitSlipWarning`, one line) when ``value`` (SI) is
    outside :data:`PLAUSIBLE_LIMITS` ``[kind]``; ``name`` names it, ``shown`` is the value
    as the user gave it (default: ``value`` in the SI unit), ``hint`` replaces the limit's
    hint. Returns whether it is inside."""
    lo, hi, unit, why, own_hint = PLAUSIBLE_LIMITS[kind]
    hint = own_hint if hint is None else hint
    if lo <= value <= hi:
        return True
    rng = (f"{lo:,.0f}-{hi:,.0f} {unit}" if kind == "density" else
           "2 g" if kind == "site_pga" else f"{hi:g} {unit}")
    where = "outside" if kind == "density" else "above"
    given = shown if shown is not None else f"{value:g} {unit}"
    warn_implausible(f"{name} = {given} is {where} {rng}: a unit slip? ({hint})",
                     UnitSlipWarning)
    return False


def _is_bool(value) -> bool:
    return isinstance(value, bool | np.bool_)


def as_bool(name: str, value) -> bool:
    """``value`` as a bool: only ``True``/``False`` (or ``numpy.bool_``) are accepted."""
    if not _is_bool(value):
        raise ParameterError(f"{name} must be True or False, got {value!r}")
    return bool(value)


def as_int(name: str, value, lo: int | None = None, hi: int | None = None) -> int:
    """``value`` as an int in ``[lo, hi]`` (either bound may be None).

    Only Python and numpy integers are accepted; bools and floats (even ``2.0``) are not.
    """
    if _is_bool(value) or not isinstance(value, numbers.Integral | np.integer):
        raise ParameterError(f"{name} must be an integer, got {value!r}")
    n = int(value)
    if (lo is not None and n < lo) or (hi is not None and n > hi):
        rng = (f"[{lo}, {hi}]" if lo is not None and hi is not None
               else f">= {lo}" if lo is not None else f"<= {hi}")
        raise ParameterError(f"{name} must be an integer {rng}, got {value!r}")
    return n


def as_float(name: str, value) -> float:
    """``value`` as a finite float (a bool is refused; a numeric string is accepted)."""
    if _is_bool(value):
        raise ParameterError(f"{name} must be a finite number, not a bool, got {value!r}")
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
