"""Quantities with units at the edges (CLI options such as ``--amp 5mm``).

Everything inside the package is SI: m, s, kg, rad, m/s^2. These helpers turn strings such
as ``"5mm"``, ``"0.3g"``, ``"280 cm/s^2"``, ``"5Hz"`` or ``"2 deg"`` into SI floats.
"""

from __future__ import annotations

import math
import re

from .errors import UnitError

G = 9.80665
"""Standard gravity (m/s^2), used for every conversion from g."""

LENGTH = {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "in": 0.0254, "ft": 0.3048}
ACCELERATION = {
    "m/s^2": 1.0, "m/s2": 1.0, "mps2": 1.0,
    "cm/s^2": 1e-2, "cm/s2": 1e-2, "gal": 1e-2,
    "mm/s^2": 1e-3, "mm/s2": 1e-3,
    "g": G,
}
TIME = {"s": 1.0, "ms": 1e-3, "min": 60.0}
FREQUENCY = {"hz": 1.0, "khz": 1e3}
ANGLE = {"rad": 1.0, "deg": math.pi / 180.0}

KINDS = {
    "length": LENGTH,
    "acceleration": ACCELERATION,
    "time": TIME,
    "frequency": FREQUENCY,
    "angle": ANGLE,
}

_QTY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([^\s\d].*)?\s*$")


def acceleration_factor(units: str) -> float:
    """SI factor of an acceleration unit name (``g``, ``m/s^2``, ``cm/s^2``, ``gal``)."""
    key = str(units).strip().lower().replace(" ", "")
    if key not in ACCELERATION:
        allowed = ", ".join(["g", "m/s^2", "cm/s^2", "gal", "mm/s^2"])
        raise UnitError(f"units must be one of {allowed}; got {units!r}")
    return ACCELERATION[key]


def split_quantity(text) -> tuple[float, str] | None:
    """Split ``"5 mm"`` into ``(5.0, "mm")`` (unit lower-cased, spaces removed; ``""`` for a
    bare number); ``None`` if ``text`` does not start with a number."""
    m = _QTY.match(str(text))
    if not m:
        return None
    return float(m.group(1)), (m.group(2) or "").strip().lower().replace(" ", "")


def parse_quantity(text, kind: str, *, name: str = "value",
                   default_unit: str | None = None) -> float:
    """Parse ``text`` (e.g. ``"5mm"``) as a quantity of ``kind`` and return it in SI units.

    A bare number takes ``default_unit``; if that is None, a unit is required (a bare
    ``--amp 5`` is ambiguous between 5 m and 5 mm, so we refuse to guess).
    """
    table = KINDS[kind]
    if isinstance(text, int | float):
        text = repr(text)
    m = _QTY.match(str(text))
    if not m:
        examples = {"length": "5mm", "acceleration": "0.3g", "time": "2s",
                    "frequency": "5Hz", "angle": "2deg"}[kind]
        raise UnitError(f"{name} must be a number with a {kind} unit such as {examples!r}; "
                        f"got {text!r}")
    number = float(m.group(1))
    unit = (m.group(2) or "").strip().lower().replace(" ", "")
    if not unit:
        if default_unit is None:
            raise UnitError(f"{name} needs a {kind} unit ({', '.join(table)}); got {text!r}")
        unit = default_unit.lower()
    if unit not in table:
        raise UnitError(f"{name}: unknown {kind} unit {m.group(2)!r}; allowed: {', '.join(table)}")
    if not math.isfinite(number):
        raise UnitError(f"{name} must be finite; got {text!r}")
    return number * table[unit]
