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
RATIO = {"": 1.0, "%": 0.01}
"""A dimensionless ratio, bare or in percent (``5%`` is 0.05): damping ratios."""

KINDS = {
    "length": LENGTH,
    "acceleration": ACCELERATION,
    "time": TIME,
    "frequency": FREQUENCY,
    "angle": ANGLE,
    "ratio": RATIO,
}

_QTY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([^\s\d].*)?\s*$")


# ---- unit words in files (record headers, column names): every spelling, case-insensitive
_TIME_WORDS = {
    "s": ("s", "sec", "secs", "second", "seconds"),
    "ms": ("ms", "msec", "msecs", "millisecond", "milliseconds"),
    "us": ("us", "usec", "usecs", "microsecond", "microseconds"),
    "min": ("min", "mins", "minute", "minutes"),
}
_TIME_KEYS = {w: k for k, words in _TIME_WORDS.items() for w in words}
TIME_FACTORS = {"s": 1.0, "ms": 1e-3, "us": 1e-6, "min": 60.0}
"""SI factor of each canonical time unit that a record file may state."""

_PER_S2 = (r"(?:/\s*(?:s|sec|second)\s*(?:\^?\s*2|/\s*(?:s|sec|second))"  # /s^2, /sec2, /s/s
           r"|(?:\s+|\s*[*.\u00b7]\s*)(?:s|sec)\s*\^?\s*-\s*2"          # m s^-2, m*s-2
           r"|ps2)")                                                          # mps2
_ACC_WORD = re.compile(rf"^(m|cm|mm)\s*{_PER_S2}$")
_ACC_SIMPLE = {"g": "g", "gal": "gal", "gals": "gal"}
ACCELERATION_UNITS = ("g", "m/s^2", "cm/s^2", "gal", "mm/s^2")
"""Canonical acceleration units (keys of :data:`ACCELERATION`)."""


def _clean_word(word) -> str:
    w = " ".join(str(word).split()).lower().rstrip(".:")
    return (w.replace("\u00b5", "u").replace("\u03bc", "u").replace("**", "^")
            .replace("\u207b\u00b2", "^-2").replace("\u00b2", "^2"))


def acceleration_unit(word) -> str | None:
    """Canonical name (``g``, ``m/s^2``, ``cm/s^2``, ``gal``, ``mm/s^2``) of an acceleration
    unit written any usual way (``G``, ``Gal``, ``cm/sec^2``, ``cm/s2``, ``m s^-2``,
    ``m/s/s``, ``m/s²``...); None if ``word`` is not one."""
    w = _clean_word(word)
    if w in _ACC_SIMPLE:
        return _ACC_SIMPLE[w]
    m = _ACC_WORD.match(w)
    return f"{m[1]}/s^2" if m else None


def time_unit(word) -> str | None:
    """Canonical name (``s``, ``ms``, ``us``, ``min``) of a time unit written any usual way
    (``sec``, ``seconds``, ``msec``, ``milliseconds``, ``µs``, ``microsecond``...); None if
    ``word`` is not one."""
    return _TIME_KEYS.get(_clean_word(word).replace(" ", ""))


def acceleration_factor(units: str) -> float:
    """SI factor of an acceleration unit name (``g``, ``m/s^2``, ``cm/s^2``, ``gal``,
    ``mm/s^2``, in any spelling that :func:`acceleration_unit` knows)."""
    key = acceleration_unit(units)
    if key is None:
        raise UnitError(f"units must be one of {', '.join(ACCELERATION_UNITS)}; got {units!r}")
    return ACCELERATION[key]


def split_quantity(text) -> tuple[float, str] | None:
    """Split ``"5 mm"`` into ``(5.0, "mm")`` (unit lower-cased, spaces removed; ``""`` for a
    bare number); ``None`` if ``text`` does not start with a number."""
    m = _QTY.match(str(text))
    if not m:
        return None
    return float(m.group(1)), (m.group(2) or "").strip().lower().replace(" ", "")


def _a(word: str) -> str:
    """``word`` with its indefinite article: "an acceleration", "a length"."""
    return f"{'an' if word[:1].lower() in 'aeiou' else 'a'} {word}"


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
                    "frequency": "5Hz", "angle": "2deg", "ratio": "5%"}[kind]
        raise UnitError(f"{name} must be a number with {_a(kind)} unit such as {examples!r}; "
                        f"got {text!r}")
    number = float(m.group(1))
    unit = (m.group(2) or "").strip().lower().replace(" ", "")
    if not unit:
        if default_unit is None:
            raise UnitError(f"{name} needs {_a(kind)} unit ({', '.join(table)}); got {text!r}")
        unit = default_unit.lower()
    if unit not in table:
        raise UnitError(f"{name}: unknown {kind} unit {m.group(2)!r}; allowed: {', '.join(table)}")
    if not math.isfinite(number):
        raise UnitError(f"{name} must be finite; got {text!r}")
    return number * table[unit]
