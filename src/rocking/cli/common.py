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

import json
import math
import re
from pathlib import Path

import click

from .._validate import as_float
from ..blocks import PARAM_SETS, specimen_ids
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


BLOCK_FLAGS = {"specimen": "--specimen", "rectangular": "--width/--height",
               "classical": "--alpha"}
"""The block forms of :mod:`rocking.blocks.factory` that the flags give, by the flag that
tells them."""
_BLOCK_USAGE = {"specimen": "--specimen N", "rectangular": "--width W --height H",
                "classical": "--alpha A --p P --mu MU"}
_BLOCK_UNITS = {"mass": ("kg",), "p": ("1/s", "rad/s")}
"""Units a bare-number key may carry on the command line (taken off before the factory)."""


def _block_form(specimen, width, height, alpha, allow_classical: bool) -> str:
    """The factory form that the flags describe (exactly one)."""
    given = [f for f, v in (("specimen", specimen), ("rectangular", width or height),
                            ("classical", alpha)) if v is not None]
    if len(given) > 1:
        raise ParameterError(f"block: give only one of "
                             f"{' or '.join(BLOCK_FLAGS[f] for f in given)}")
    if not given:
        forms = ("specimen", "rectangular", "classical")[:3 if allow_classical else 2]
        raise ParameterError(f"block: give {', or '.join(_BLOCK_USAGE[f] for f in forms)}")
    return given[0]


def _bare(text, units: tuple[str, ...]) -> str:
    """``text`` without one of ``units`` at its end (``228kg`` -> ``228``)."""
    s = str(text).strip()
    for u in units:
        if s.lower().endswith(u):
            return s[: -len(u)].strip()
    return s


def make_block(specimen=None, params=None, width=None, height=None, mass=None, alpha=None,
               p=None, mu=None, allow_classical: bool = False):
    """``(block, info)`` from exactly one of: specimen, width/height, alpha/p/mu, built by
    :func:`rocking.blocks.factory.make_block` (which checks the values)."""
    from ..blocks.factory import FORMS
    from ..blocks.factory import make_block as build

    form = _block_form(specimen, width, height, alpha, allow_classical)
    texts = {k: v for k, v in (("specimen", specimen), ("params", params), ("width", width),
                               ("height", height), ("mass", mass), ("alpha", alpha),
                               ("p", p), ("mu", mu)) if v is not None}
    keys = FORMS[form].Params.names()
    for k in texts:
        if k not in keys:
            where = " or ".join(flag for f, flag in BLOCK_FLAGS.items()
                                if k in FORMS[f].Params.names())
            raise ParameterError(f"{k} does not apply to {BLOCK_FLAGS[form]} (only to "
                                 f"{where})")
    given = {k: _bare(v, _BLOCK_UNITS.get(k, ())) for k, v in texts.items()}
    words = {k: (k, v) for k, v in texts.items()}
    try:
        checked = FORMS[form].Params(**given)  # the factory's checks, for the info below
    except ParameterError as e:
        msg = one_line(in_flag_words(e, words))
        if " is required" in msg:
            msg += f"; give {_BLOCK_USAGE[form]}"
        raise type(e)(msg) from None
    try:
        block = build(given)
    except ParameterError as e:  # valid keys, but no block (sizes beyond floating point)
        if form != "rectangular":
            raise
        raise ParameterError(_size_problem(width, height, e)) from None
    return block, _block_info(form, checked, block, texts)


def _block_info(form: str, checked, block, texts: dict) -> dict:
    """What summary.json records of the block's source (and the overrides)."""
    if form == "classical":
        return {"alpha": block.alpha, "p": block.p, "mu": block.mu}
    if form == "specimen":
        info = {"specimen": checked.specimen, "params": checked.params}
    else:
        info = {"width": block.width, "height": block.height, "mass": block.mass}
    info.update({f"{k}_override": getattr(checked, k) for k in ("p", "mu") if k in texts})
    return info


def _size_problem(width, height, e: ParameterError) -> str:
    """The message of a block that ``--width``/``--height`` cannot make, in their words.

    Sizes so large that ``R``, ``p = sqrt(3 g / 4 R)`` or the area leave floating point
    (``--width 1e308``) would otherwise be reported as ``p must be > 0`` or ``vertices
    enclose no area``, naming what the user never gave."""
    given = f"--width {width} --height {height}"
    msg = one_line(e)
    w = quantity(width, "length", "width", default_unit="m")
    h = quantity(height, "length", "height", default_unit="m")
    with_r = math.hypot(w / 2.0, h / 2.0)
    if not (math.isfinite(w * h) and math.isfinite(with_r * with_r) and with_r * with_r > 0):
        return (f"{given}: too large (or too small) a block for floating point ({w:g} m x "
                f"{h:g} m): give the sizes in m, e.g. --width 0.17 --height 1 or 170mm")
    return f"{given}: {msg}"


_HEAD = re.compile(r"([A-Za-z_]\w*(?: or [A-Za-z_]\w*)*)(?=[ :,]|$)")


def in_flag_words(e: ParameterError, words: dict) -> ParameterError:
    """``e`` with the parameter names that start its message in the command line's words.

    ``words`` maps a library name to ``(flag, text typed or None)``: ``period must be in
    (0, 10000] s, got 0.0`` becomes ``tp must be in (0, 10000] s, got '0'``. Other
    messages are returned unchanged."""
    msg = one_line(e)
    m = _HEAD.match(msg)
    names = m.group(1).split(" or ") if m else []
    if not any(n in words for n in names):
        return e
    flags = dict.fromkeys(words[n][0] if n in words else n for n in names)
    head = " or ".join(flags)
    if len(flags) < len(names):  # amplitude or displacement: both --amp
        head += f" ({m.group(1)})"
    out = head + msg[m.end():]
    text = words[names[0]][1] if len(names) == 1 else None
    if text is not None:  # the value as typed
        out = re.sub(r", got [^,;]*$", lambda _: f", got {str(text)!r}", out)
    elif len(names) > 1:  # "got frequency, period": the names given, as flags
        out = re.sub(r"; got ([\w, ]+)$", lambda g: "; got " + ", ".join(
            dict.fromkeys(words.get(n, (n,))[0] for n in g.group(1).split(", "))), out)
    return type(e)(out)


# ----------------------------------------------------------------------------- buildings
BUILDING_FLAGS = {"storeys": "storeys", "period": "building-period",
                  "damping_ratio": "building-damping"}
"""The building catalog keys that have a flag of their own (the others:
``--building-param``)."""


def building_options(building_help: str):
    """Decorator adding ``--building --storeys --building-period --building-damping
    --building-param``: a building of :mod:`rocking.buildings.catalog`, read by
    :func:`make_building` (``rocking simulate``, ``rocking motion floor``)."""
    opts = [
        click.option("--building", metavar="KIND", help=building_help),
        click.option("--storeys", metavar="N",
                     help="Storeys of the building (shear, continuous)."),
        click.option("--building-period", "building_period", metavar="T",
                     help="First-mode period of the building (s)."),
        click.option("--building-damping", "building_damping", metavar="Z",
                     help="Modal damping ratio of the building (5% or 0.05; default 5%)."),
        click.option("--building-param", "building_params", multiple=True,
                     metavar="KEY=VALUE",
                     help="Another key of the building kind, repeatable (e.g. "
                          "stiffness_ratio=5, masses=[2,1,1]); 'rocking buildings KIND' "
                          "lists them."),
    ]

    def decorate(f):
        for o in reversed(opts):
            f = o(f)
        return f

    return decorate


def _building_values(kind, storeys, period, damping, pairs) -> tuple[dict, dict]:
    """The building catalog mapping of the flags (``kind`` and its keys), and the words of
    messages."""
    flags = {"storeys": storeys, "period": period, "damping_ratio": damping}
    values = {k: v for k, v in flags.items() if v is not None}
    extra = parse_options(pairs, flag="building-param", example="stiffness_ratio=5")
    for key, v in extra.items():
        if key in values:
            raise ParameterError(f"{key} given twice (--{BUILDING_FLAGS[key]} and "
                                 f"--building-param {key}=...)")
        if isinstance(v, str) and v.lstrip().startswith("["):
            try:
                extra[key] = json.loads(v)
            except ValueError:
                raise ParameterError(f"building-param {key} must be a number, a quantity or "
                                     f"a JSON list such as [2, 1, 1]; got {v!r}") from None
    words = {k: (f, flags[k]) for k, f in BUILDING_FLAGS.items() if k not in extra}
    words["kind"] = ("building", kind)
    return {"kind": kind, **values, **extra}, words


def make_building(kind, storeys=None, period=None, damping=None, pairs=()):
    """``(building, description)`` of the ``--building`` flags, built by
    :func:`rocking.buildings.catalog.make_building` (which checks the keys)."""
    from ..buildings import catalog

    mapping, words = _building_values(kind, storeys, period, damping, pairs)
    try:
        building = catalog.make_building(mapping)
    except ParameterError as e:
        msg = one_line(in_flag_words(e, words))
        name = msg.split(" ", 1)[0]
        if msg.startswith(f"{name} is required"):
            msg += (f"; give --{name} VALUE" if name in BUILDING_FLAGS.values()
                    else f"; give --building-param {name}=VALUE")
        raise type(e)(msg) from None
    checked = catalog.KINDS[kind].Params(**{k: v for k, v in mapping.items() if k != "kind"})
    desc = {"kind": kind, **{k: v for k, v in checked.to_dict().items() if v is not None},
            "name": building.name, "periods": building.periods.tolist(),
            "n_floors": building.n_floors}
    return building, desc


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


def parse_options(pairs, flag: str = "option", example: str = "rtol=1e-8") -> dict:
    """``("KEY=VALUE", ...)`` of a repeatable ``--option`` (or ``--param``: ``flag``) as a
    dict (values parsed by :func:`option_value`; names may use ``-`` for ``_``)."""
    out: dict = {}
    for pair in pairs or ():
        key, sep, value = str(pair).partition("=")
        key = key.strip().replace("-", "_")
        if not sep or not key:
            raise ParameterError(f"{flag} must be KEY=VALUE (e.g. --{flag} {example}), "
                                 f"got {pair!r}")
        if key in out:
            raise ParameterError(f"{flag} {key} given twice")
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
    return describe_table(cls.Options.describe())


def describe_table(rows: list[dict], head: str = "option", unset: str = "auto") -> list[str]:
    """Declared parameters (:func:`rocking.options.describe_field` dicts) as text lines:
    name, default (``required``, or ``unset`` for None), unit, range, help."""
    cells = [(d["name"], "required" if d.get("required") else _shown(d["default"], unset),
              d["unit"] or "-", d["range"] or "-", d["help"]) for d in rows]
    if not cells:
        return ["  (no options)"]
    top = (head, "default", "unit", "range", "help")
    widths = [max(len(r[i]) for r in (top, *cells)) for i in range(4)]
    return ["  " + "  ".join(f"{c:<{w}}" for c, w in zip(r[:4], widths, strict=True))
            + f"  {r[4]}" for r in (top, *cells)]


def _shown(value, unset: str = "auto") -> str:
    if value is None:
        return unset
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


def read_record_arg(path, name: str, units, dt):
    """``(record, source)`` from a file (catalog kind ``record``), or from the records
    shipped with the package by name (kind ``builtin``).

    ``units`` None: the user gave no ``--units``; a file is read in g (the default) and a
    message says so rather than naming a ``units='g'`` the user never wrote. ``dt`` may be
    text (``10ms``) or seconds."""
    from ..motions import catalog  # lazy: the motions import numba
    from ..motions.io import builtin_records

    record = catalog.KINDS["record"]
    checked = record.params(file=str(path), units="g" if units is None else units, dt=dt)
    p = Path(path)
    if not p.exists():
        known = builtin_records(three_component=True)
        stem = p.name[:-4] if p.name.upper().endswith(".AT2") else p.name
        match = [k for k in known if k.upper() == stem.upper()]
        if match:
            if units not in (None, "g") or dt is not None:
                raise ParameterError(f"{name}: {stem} is a built-in record (PEER .AT2, in g): "
                                     "--units and --dt apply to record files only")
            return catalog.build("builtin", name=match[0]), f"{stem} (built-in)"
        raise RecordError(f"{name}: no such file or built-in record: {path} (built-in: "
                          f"{', '.join(known)})")
    if p.is_dir():
        raise RecordError(f"{name}: {path} is a directory, not a record file")
    try:
        return record.make(checked, catalog.Context()), str(path)
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
           "models_with_option", "options_table", "describe_table", "one_line",
           "read_record_arg", "output_too_large_message", "error_report", "in_flag_words",
           "BLOCK_FLAGS", "BUILDING_FLAGS", "building_options", "make_building"]
