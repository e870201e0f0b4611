"""Declared parameters: a default, a help text, one SI unit and a range, checked when built.

The one way the package declares what a user may set: a model's options
(:class:`rocking.models.ModelOptions`), a motion kind's parameters
(:mod:`rocking.motions.catalog`) and a block form's keys (:mod:`rocking.blocks.factory`)
are frozen dataclasses whose fields are made with :func:`option`. The metadata is what
``rocking models`` and ``rocking motions`` print, what the README's spec-key table is
generated from and what :func:`rocking.testing.check_model` probes, so the documentation
and the checks cannot drift from the code.

One unit per parameter name, across the package: a name (``amplitude``, ``frequency``,
``period``, ``duration``, ``friction_angle``...) always has the same SI unit wherever it
appears (:data:`UNITS`). A value may be given as a number in that unit or, for a
parameter declared with a ``quantity`` (``"acceleration"``, ``"length"``, ``"time"``,
``"frequency"``, ``"angle"``), as a string with an explicit unit (``"0.3g"``, ``"5mm"``,
``"30deg"``): :func:`rocking.units.parse_quantity` converts it to SI.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from ._validate import as_float, in_range
from .errors import ParameterError
from .units import parse_quantity

REQUIRED = None
"""The default of a parameter that has none (declare it with ``required=True``)."""

UNITS = {
    "amplitude": "m/s^2", "displacement": "m", "velocity": "m/s", "frequency": "Hz",
    "period": "s", "duration": "s", "cycles": "", "phase": "rad", "t0": "s", "tc": "s",
    "dt": "s", "gamma": "", "nu": "rad", "vertical_factor": "", "friction_angle": "rad",
    "width": "m", "height": "m", "mass": "kg", "density": "kg/m^3", "thickness": "m",
    "alpha": "rad", "p": "1/s", "mu": "", "stiffness": "N/m", "damping": "s",
    "damping_ratio": "", "storeys": "", "floor": "", "height_ratio": "",
    "stiffness_ratio": "",
}
"""The SI unit of each parameter name used by more than one declaration (a test checks
that every declared parameter of that name has this unit)."""


def option(default, *, help: str, unit: str = "", lo: float | None = None,
           hi: float | None = None, lo_open: bool = True, hi_open: bool = False,
           choices: tuple | None = None, kind: type | None = None,
           quantity: str | None = None, required: bool = False):
    """A declared parameter: a dataclass field with its default, unit and range.

    ``lo``/``hi`` bound a number (open or closed ends); ``choices`` lists allowed values;
    ``kind`` is ``bool``, ``int``, ``float`` (default for numbers), ``str`` or ``object``
    (free form, checked by the owner); ``quantity`` lets a string with a unit stand for the
    number (``"0.3g"``); ``required`` marks a parameter without a default. ``None`` is
    accepted when it is the default (meaning "automatic" or "not given").

    Examples
    --------
    A model's options declared with their range, checked when built:

    >>> from dataclasses import dataclass
    >>> from rocking.models import ModelOptions, option
    >>> @dataclass(frozen=True)
    ... class DampedOptions(ModelOptions):
    ...     damping_ratio: float = option(0.05, help="viscous damping ratio", lo=0.0,
    ...                                   hi=1.0, lo_open=False)
    >>> DampedOptions().damping_ratio
    0.05
    >>> try:
    ...     DampedOptions(damping_ratio=2.0)
    ... except ValueError as e:
    ...     print(e)
    damping_ratio must be in [0, 1], got 2.0
    """
    meta = {"help": help, "unit": unit, "lo": lo, "hi": hi, "lo_open": lo_open,
            "hi_open": hi_open, "choices": choices, "quantity": quantity,
            "required": required,
            "kind": kind or (type(default) if default is not None else float)}
    return dataclasses.field(default=default, metadata=meta)


def range_text(m: dict) -> str:
    """The range of a numeric declaration as text: ``(0, inf)``, ``[0, 1]``."""
    lo = "-inf" if m["lo"] is None else f"{m['lo']:g}"
    hi = "inf" if m["hi"] is None else f"{m['hi']:g}"
    a = "(" if m["lo_open"] or m["lo"] is None else "["
    b = ")" if m["hi_open"] or m["hi"] is None else "]"
    return f"{a}{lo}, {hi}{b}"


def describe_field(f: dataclasses.Field) -> dict:
    """One declaration as a dict: ``name``, ``default``, ``unit``, ``range``, ``help``,
    ``kind``, ``required``."""
    m = f.metadata
    rng = ", ".join(map(str, m["choices"])) if m.get("choices") else (
        range_text(m) if m.get("kind") in (int, float) else "")
    return {"name": f.name, "default": f.default, "unit": m.get("unit", ""), "range": rng,
            "help": m.get("help", ""), "kind": m.get("kind"),
            "required": bool(m.get("required"))}


def check_option(name: str, value, m: dict):
    """``value`` of the declaration ``m`` checked and converted (SI float, int, bool or
    one of the choices); a :class:`ParameterError` naming ``name`` and the range if not."""
    kind = m["kind"]
    if kind is object:  # free-form: the owner's check() validates it
        return value
    if kind is bool:
        if not isinstance(value, bool | np.bool_):
            raise ParameterError(f"{name} must be True or False, got {value!r}")
        return bool(value)
    if kind is str or m.get("choices"):
        if m.get("choices") and value not in m["choices"]:
            raise ParameterError(f"{name} must be one of {', '.join(map(str, m['choices']))}; "
                                 f"got {value!r}")
        if kind is str and not isinstance(value, str):
            raise ParameterError(f"{name} must be a string, got {type(value).__name__} "
                                 f"{value!r}")
        return value
    if m.get("quantity") and isinstance(value, str):
        value = parse_quantity(value, m["quantity"], name=name,
                               default_unit=m.get("unit", ""))
    x = as_float(name, value)
    if m["lo"] is not None or m["hi"] is not None:
        lo = -math.inf if m["lo"] is None else m["lo"]
        hi = math.inf if m["hi"] is None else m["hi"]
        unit = f" {m['unit']}" if m.get("unit") else ""
        shown = range_text(m) + unit
        if m.get("quantity") == "ratio" and 1.0 < x <= 100.0 and lo < x / 100.0 < hi:
            shown += (f" (a ratio: {x:g} % is {x / 100.0:g}, give {x / 100.0:g} or "
                      f"{x:g}%)")  # a percentage typed as a number
        x = in_range(name, x, lo, hi, lo_open=m["lo_open"] or m["lo"] is None,
                     hi_open=m["hi_open"] or m["hi"] is None, shown=shown)
    if kind is int:
        if x != int(x):
            raise ParameterError(f"{name} must be a whole number, got {value!r}")
        return int(x)
    return x


@dataclass(frozen=True)
class Options:
    """Base of the declared-parameter dataclasses (validated when built)."""

    def __post_init__(self):
        for f in dataclasses.fields(self):
            value = getattr(self, f.name)
            m = f.metadata
            if not m:
                continue
            if value is None and f.default is None:
                if m.get("required"):
                    raise ParameterError(f"{f.name} is required ({m['help']})")
                continue
            object.__setattr__(self, f.name, check_option(f.name, value, m))
        self.check()

    def check(self) -> None:
        """Checks that involve several parameters (override)."""

    @classmethod
    def names(cls) -> tuple[str, ...]:
        return tuple(f.name for f in dataclasses.fields(cls))

    @classmethod
    def unknown(cls, values, owner: str) -> None:
        """Refuse names that are not declared (``owner`` says whose they would be)."""
        names = cls.names()
        bad = [k for k in values if k not in names]
        if bad:
            raise ParameterError(f"unknown parameter(s) for {owner}: {', '.join(bad)} "
                                 f"(allowed: {', '.join(names) or 'none'})")

    @classmethod
    def describe(cls) -> list[dict]:
        """One dict per declaration (:func:`describe_field`)."""
        return [describe_field(f) for f in dataclasses.fields(cls)]

    def to_dict(self) -> dict:
        return dataclasses.asdict(self)
