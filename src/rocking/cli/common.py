"""Shared parsing of the ``rocking`` command line: quantities, numbers, blocks, models, errors.

Every command module (``params``, ``simulate``, ``motion``, ``dem``, ``identify``,
``reproduce``, ``models``) takes its option parsers from here; this module imports no
command module. Parsers raise :class:`~rocking.errors.ParameterError` naming the option;
:func:`rocking.cli.main` prints it as one line ``error: ...`` (exit code 2), see
:func:`error_report`.

Quantities accept units at the edge (``170mm``, ``0.3g``, ``5Hz``, ``9.6deg``); see
:func:`rocking.units.parse_quantity`.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import click

from .._validate import as_float
from ..blocks import PARAM_SETS, Block, specimen_ids
from ..blocks import specimen as get_specimen
from ..errors import (
    OutputTooLargeError,
    ParameterError,
    RecordError,
    RockingError,
    SimulationError,
)
from ..units import parse_quantity

CONTEXT = {"help_option_names": ["-h", "--help"]}


# ----------------------------------------------------------------------------- numbers
def quantity(text, kind: str, name: str, default_unit: str | None = None) -> float | None:
    """``text`` as an SI float of ``kind`` (``"length"``, ``"time"``, ...); None stays None."""
    if text is None:
        return None
    return parse_quantity(text, kind, name=name, default_unit=default_unit)


def number(text, name: str, units: tuple[str, ...] = ()) -> float | None:
    """A plain finite number, optionally followed by one of ``units`` (e.g. ``1/s``)."""
    if text is None:
        return None
    s = str(text).strip()
    for u in units:
        if s.lower().endswith(u):
            s = s[: -len(u)].strip()
            break
    return as_float(name, s)


def check_positive(value, name: str, unit: str):
    """``value`` if it is None or > 0, else a :class:`ParameterError`."""
    if value is not None and not value > 0:
        raise ParameterError(f"{name} must be > 0 {unit}; got {value:g}")
    return value


def positive_quantity(text, kind: str, name: str, default_unit: str, unit: str):
    """:func:`quantity` checked > 0 (None stays None)."""
    return check_positive(quantity(text, kind, name, default_unit), name, unit)


def integer(text, name: str, lo: int = 1, hi: int | None = None) -> int:
    """A whole number in ``lo..hi``."""
    try:
        n = int(str(text).strip())
    except ValueError:
        raise ParameterError(f"{name} must be an integer, got {text!r}") from None
    if n < lo or (hi is not None and n > hi):
        rng = f">= {lo}" if hi is None else f"in {lo}..{hi}"
        raise ParameterError(f"{name} must be {rng}, got {text!r}")
    return n


def specimen_number(text) -> int:
    """The number of a catalogued specimen (Table I)."""
    ids = specimen_ids()
    try:
        n = int(str(text).strip())
    except ValueError:
        n = None
    if n not in ids:
        raise ParameterError(f"specimen must be one of {ids}, got {text!r}")
    return n


def json_default(o):
    """``json.dumps(default=...)``: numbers as floats (non-finite as null), others as text."""
    try:
        x = float(o)
    except (TypeError, ValueError):
        return str(o)
    return x if math.isfinite(x) else None


# ----------------------------------------------------------------------------- blocks
def block_options(classical: bool = False, mass: bool = False):
    """Decorator adding ``--specimen --params --width --height`` (and ``--mass``, or
    ``--alpha --p --mu`` for a block given by its classical parameters)."""
    opts = [
        click.option("--specimen", metavar="N",
                     help="Specimen of Pena et al. (2007), Table I (1-4)."),
        click.option("--params", "params_set", type=click.Choice(PARAM_SETS),
                     help="Parameter set of a specimen (default theoretical)."),
        click.option("--width", metavar="W", help="Full width 2b (bare number: m; or 170mm)."),
        click.option("--height", metavar="H", help="Full height 2h (bare number: m)."),
    ]
    if mass:
        opts.append(click.option("--mass", metavar="M", help="Mass (kg), with --width/--height."))
    if classical:
        opts += [
            click.option("--alpha", metavar="A",
                         help="Critical angle (bare number: rad; or 9.6deg)."),
            click.option("--p", metavar="P",
                         help="Frequency parameter p (1/s); overrides a specimen's."),
            click.option("--mu", metavar="MU",
                         help="Coefficient of restitution in (0, 1]; overrides."),
        ]

    def decorate(f):
        for o in reversed(opts):
            f = o(f)
        return f

    return decorate


def make_block(specimen=None, params=None, width=None, height=None, mass=None, alpha=None,
               p=None, mu=None, allow_classical: bool = False):
    """``(block, info)`` from exactly one of: specimen, width/height, alpha/p/mu."""
    sources = [s for s, given in (("--specimen", specimen is not None),
                                  ("--width/--height", width is not None or height is not None),
                                  ("--alpha", alpha is not None)) if given]
    if len(sources) > 1:
        raise ParameterError(f"block: give only one of {' or '.join(sources)}")
    if not sources:
        what = ("--specimen N, --width W --height H, or --alpha A --p P --mu M"
                if allow_classical else "--specimen N or --width W --height H")
        raise ParameterError(f"block: give {what}")
    if params is not None and specimen is None:
        raise ParameterError("params applies to --specimen only")
    if mass is not None and specimen is not None:
        raise ParameterError("mass applies to --width/--height only (the specimens "
                             "have their Table I mass)")

    info: dict = {}
    if specimen is not None:
        n = specimen_number(specimen)
        ps = params or "theoretical"
        block = get_specimen(n, params=ps)
        info.update(specimen=n, params=ps)
    elif width is not None or height is not None:
        if width is None or height is None:
            missing = "width" if width is None else "height"
            raise ParameterError(f"{missing} is required with --width/--height "
                                 f"(full size, e.g. 0.17 or 170mm)")
        w = quantity(width, "length", "width", default_unit="m")
        h = quantity(height, "length", "height", default_unit="m")
        try:
            block = Block.rectangular(w, h, mass=number(mass, "mass", ("kg",)),
                                      mu=None if mu is None else number(mu, "mu"),
                                      name="rectangular block")
        except ParameterError as e:  # name what the user gave, not p or the vertices
            raise ParameterError(_size_problem(width, height, w, h, e)) from None
        info.update(width=block.width, height=block.height, mass=block.mass)
    else:
        if p is None or mu is None:
            missing = [n for n, v in (("p", p), ("mu", mu)) if v is None]
            raise ParameterError(f"{' and '.join(missing)} required with --alpha "
                                 f"(give --alpha A --p P --mu M)")
        a = quantity(alpha, "angle", "alpha", default_unit="rad")
        block = Block.from_params(a, number(p, "p", ("1/s", "rad/s")), number(mu, "mu"),
                                  name="block")
        info.update(alpha=block.alpha, p=block.p, mu=block.mu)
        return block, info
    # overrides on a specimen or a rectangle
    changes = {}
    if p is not None:
        changes["p"] = number(p, "p", ("1/s", "rad/s"))
    if mu is not None:
        changes["mu"] = number(mu, "mu")
    if changes:
        block = block.with_params(**changes)
        info.update({f"{k}_override": v for k, v in changes.items()})
    return block, info


def _size_problem(width, height, w: float, h: float, e: ParameterError) -> str:
    """The message of a block that ``--width``/``--height`` cannot make, in their words.

    Sizes so large that ``R``, ``p = sqrt(3 g / 4 R)`` or the area leave floating point
    (``--width 1e308``) would otherwise be reported as ``p must be > 0`` or ``vertices
    enclose no area``, naming what the user never gave."""
    given = f"--width {width} --height {height}"
    msg = one_line(e)
    if msg.startswith(("width", "height", "mass")):
        return msg
    with_r = math.hypot(w / 2.0, h / 2.0)
    if not (math.isfinite(w * h) and math.isfinite(with_r * with_r) and with_r * with_r > 0):
        return (f"{given}: too large (or too small) a block for floating point ({w:g} m x "
                f"{h:g} m): give the sizes in m, e.g. --width 0.17 --height 1 or 170mm")
    return f"{given}: {msg}"


# ----------------------------------------------------------------------------- models
def model_classes() -> dict:
    """:data:`rocking.models.MODELS`, read at run time (lazy: the models import numba)."""
    from ..models import MODELS

    return MODELS


class ModelChoice(click.ParamType):
    """A choice among :data:`rocking.models.MODELS`, read at run time."""

    name = "model"

    def get_metavar(self, param, ctx=None):  # click >= 8.2 passes ctx
        return "[" + "|".join(model_classes()) + "]"

    def convert(self, value, param, ctx):
        names = list(model_classes())
        key = str(value).strip().lower()
        if key not in names:
            self.fail(f"{value!r} is not one of {', '.join(names)}", param, ctx)
        return key


def option_value(text: str):
    """A ``--option`` value: ``true``/``false`` (bool), ``none`` (None: the automatic
    default), an int, a float, else the text itself."""
    s = text.strip()
    low = s.lower()
    if low in ("true", "yes", "on"):
        return True
    if low in ("false", "no", "off"):
        return False
    if low in ("none", "null"):
        return None
    for conv in (int, float):
        try:
            return conv(s)
        except ValueError:
            pass
    return s


def parse_options(pairs) -> dict:
    """``("KEY=VALUE", ...)`` of a repeatable ``--option`` as a dict (values parsed by
    :func:`option_value`; names may use ``-`` for ``_``)."""
    out: dict = {}
    for pair in pairs or ():
        key, sep, value = str(pair).partition("=")
        key = key.strip().replace("-", "_")
        if not sep or not key:
            raise ParameterError(f"option must be KEY=VALUE (e.g. --option rtol=1e-8), "
                                 f"got {pair!r}")
        if key in out:
            raise ParameterError(f"option {key} given twice")
        out[key] = option_value(value)
    return out


def validate_options(model: str, options: dict) -> None:
    """Let the model check ``options`` (unknown names, ranges): a ParameterError."""
    cls = model_classes()[model]
    cls.Options.build(cls.name, **options)


def models_with_option(name: str) -> list[str]:
    """Registered models whose ``Options`` has the field ``name``."""
    return [k for k, cls in model_classes().items()
            if any(d["name"] == name for d in cls.Options.describe())]


def options_table(cls) -> list[str]:
    """The options of a model class as text lines (from ``Options.describe()``)."""
    rows = [(d["name"], _shown(d["default"]), d["unit"] or "-", d["range"] or "-",
             d["help"]) for d in cls.Options.describe()]
    if not rows:
        return ["  (no options)"]
    head = ("option", "default", "unit", "range", "help")
    widths = [max(len(r[i]) for r in (head, *rows)) for i in range(4)]
    return ["  " + "  ".join(f"{c:<{w}}" for c, w in zip(r[:4], widths, strict=True))
            + f"  {r[4]}" for r in (head, *rows)]


def _shown(value) -> str:
    if value is None:
        return "auto"
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)


# ----------------------------------------------------------------------------- records
def _option_words(msg: str, units, dt) -> str:
    """A record reader's message in the CLI's words: ``units='g' was passed`` becomes
    ``--units g was given`` (or, when the user gave no ``--units``, ``--units was not
    given (the default is g)``), ``pass units='m/s^2'`` becomes ``pass --units m/s^2``,
    ``dt=0.01 s was passed`` becomes ``--dt 0.01 s was given``."""
    said = (r"--units \1 was given" if units is not None
            else "--units was not given (the default is g)")
    msg = re.sub(r"\bunits='([^']*)' was passed", said, msg)
    msg = re.sub(r"\bpass units='([^']*)'", r"pass --units \1", msg)
    if dt is not None:
        msg = re.sub(r"\bdt=(\S+) s was passed", r"--dt \1 s was given", msg)
    return msg


def read_record_arg(M, path, name: str, units, dt):
    """``(record, source)`` from a file, or from the records shipped with the package by
    name (``M`` is :mod:`rocking.motions`, passed in to keep numba out of this module).

    ``units`` None: the user gave no ``--units``; a file is read in g (the default) and a
    message says so rather than naming a ``units='g'`` the user never wrote."""
    from ..units import ACCELERATION

    if units is not None and units not in ACCELERATION:
        raise ParameterError(f"units must be one of {', '.join(ACCELERATION)}, got {units!r}")
    p = Path(path)
    if not p.exists():
        known = M.builtin_records(three_component=True)
        stem = p.name[:-4] if p.name.upper().endswith(".AT2") else p.name
        if stem.upper() in (k.upper() for k in known):
            if units not in (None, "g") or dt is not None:
                raise ParameterError(f"{name}: {stem} is a built-in record (PEER .AT2, in g): "
                                     "--units and --dt apply to record files only")
            return M.load_builtin(stem), f"{stem} (built-in)"
        raise RecordError(f"{name}: no such file or built-in record: {path} (built-in: "
                          f"{', '.join(known)})")
    if p.is_dir():
        raise RecordError(f"{name}: {path} is a directory, not a record file")
    try:
        return M.Record.from_file(p, units="g" if units is None else units, dt=dt), str(path)
    except RockingError as e:
        msg = _option_words(str(e), units, dt)
        if msg == str(e):
            raise
        raise type(e)(msg) from None
    except (OSError, ValueError, UnicodeError) as e:
        raise RecordError(f"{name}: cannot read {path}: {e}") from None


# ----------------------------------------------------------------------------- errors
def one_line(msg) -> str:
    return " ".join(str(msg).split())


def output_too_large_message(e: OutputTooLargeError) -> str:
    """The library's message (``dt_out``, ``duration``) in the CLI's option names."""
    msg = one_line(e)
    msg = re.sub(r"\bdt_out\s*=\s*", "--dt-out ", msg)
    msg = re.sub(r"\bdt_out\b", "--dt-out", msg)
    msg = re.sub(r"\b(over )?a duration of\s*", "over --duration ", msg).replace(
        "over over", "over")
    msg = msg.replace("the duration", "--duration")
    if "--dt-out" not in msg or "--duration" not in msg:
        msg += ": increase --dt-out or shorten --duration"
    return msg


def error_report(e: BaseException) -> tuple[str, int] | None:
    """``(one-line message, exit code)`` of a library error, None if not one of ours.

    Bad input (:class:`~rocking.errors.RockingError`): code 2, the output guard
    (:class:`~rocking.errors.OutputTooLargeError`) worded with ``--dt-out``/``--duration``;
    a numerical failure on valid input (:class:`~rocking.errors.SimulationError`): code 1.
    """
    if isinstance(e, OutputTooLargeError):
        return output_too_large_message(e), 2
    if isinstance(e, RockingError):
        return one_line(e), 2
    if isinstance(e, SimulationError):
        return one_line(e), 1
    return None


__all__ = ["CONTEXT", "quantity", "number", "check_positive", "positive_quantity", "integer",
           "specimen_number", "json_default", "block_options", "make_block", "model_classes",
           "ModelChoice", "option_value", "parse_options", "validate_options",
           "models_with_option", "options_table", "one_line", "read_record_arg",
           "output_too_large_message", "error_report"]
