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

import dataclasses
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
    UnitSlipWarning,
)
from ..options import check_option, describe_field
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
MESH_FLAGS = {"mesh": "--mesh", "density": "--density", "mass": "--mass", "up": "--up",
              "direction": "--direction", "units": "--mesh-units", "repair": "--repair"}
"""The flags of the ``mesh`` block form (:mod:`rocking.blocks.factory`) by its key."""
MESH_META = "rocking.mesh"
"""Where :func:`block_options` leaves the mesh flags for :func:`make_block` (the click
context's ``meta``), so that every command taking a block takes ``--mesh`` too."""


def block_options(classical: bool = False, mass: bool = False):
    """Decorator adding ``--specimen --params --width --height`` (and ``--mass``, or
    ``--alpha --p --mu`` for a block given by its classical parameters), and the mesh
    block's ``--mesh --density --mass --up --direction --mesh-units --repair`` (the factory
    form ``mesh``: :func:`make_block` reads them from the click context; the command's
    callback does not see them, except ``--mass`` where the command has it)."""
    opts = [
        click.option("--specimen", metavar="N",
                     help="Specimen of Pena et al. (2007), Table I (1-4)."),
        click.option("--params", "params_set", type=click.Choice(PARAM_SETS),
                     help="Parameter set of a specimen (default theoretical)."),
        click.option("--width", metavar="W", help="Full width 2b (bare number: m; or 170mm)."),
        click.option("--height", metavar="H", help="Full height 2h (bare number: m)."),
    ]
    if mass:
        opts.append(click.option("--mass", metavar="M",
                                 help="Mass (kg), with --width/--height or --mesh."))
    if classical:
        opts += [
            click.option("--alpha", metavar="A",
                         help="Critical angle (bare number: rad; or 9.6deg)."),
            click.option("--p", metavar="P",
                         help="Frequency parameter p (1/s); overrides a specimen's."),
            click.option("--mu", metavar="MU",
                         help="Coefficient of restitution in (0, 1]; overrides (with "
                              "--model isolated: imposed on its impacts, instead of the "
                              "one derived from the moving plate)."),
        ]
    mesh_dest = {"mesh": "mesh_path", "density": "mesh_density", "up": "mesh_up",
                 "direction": "mesh_direction", "units": "mesh_units",
                 "repair": "mesh_repair"}
    if not mass:
        mesh_dest["mass"] = "mesh_mass"
    mesh_help = {
        "mesh": ("FILE", "A 3-D mesh (STL, OBJ, PLY): its planar block in --direction "
                 "(rocking.shapes; 'rocking shape FILE' tabulates the directions)."),
        "density": ("RHO", "Density of the --mesh (or rigid3d's --box, --cylinder; "
                    "kg/m^3), or --mass."),
        "mass": ("M", "Mass of the --mesh (or --box, --cylinder; kg), instead of "
                 "--density."),
        "up": ("AXIS", "The --mesh's vertical axis: x, y, z (default), -x, -y, -z."),
        "direction": ("DIR", "Direction of shaking from the body's x axis, "
                      "counter-clockwise looking down --up (bare number: deg; 0.5rad), "
                      "weakest or strongest (default 0): the --mesh's planar block; "
                      "rigid3d: where a single horizontal motion acts (its option "
                      "direction)."),
        "units": ("U", "Length unit of the --mesh file: m (default), cm, mm."),
        "repair": ("hull", "Use the convex hull of an open or inconsistent --mesh."),
    }
    opts += [click.option(MESH_FLAGS[k], dest, metavar=mesh_help[k][0], help=mesh_help[k][1])
             for k, dest in mesh_dest.items()]

    def decorate(f):
        import functools

        @functools.wraps(f)
        def callback(*args, **kwargs):
            given = {k: kwargs.pop(dest) for k, dest in mesh_dest.items()}
            ctx = click.get_current_context(silent=True)
            if ctx is not None:
                ctx.meta[MESH_META] = {k: v for k, v in given.items() if v is not None}
            return f(*args, **kwargs)

        for o in reversed(opts):
            callback = o(callback)
        return callback

    return decorate


BLOCK_FLAGS = {"specimen": "--specimen", "rectangular": "--width/--height",
               "classical": "--alpha", "mesh": "--mesh"}
"""The block forms of :mod:`rocking.blocks.factory` that the flags give, by the flag that
tells them."""
_BLOCK_USAGE = {"specimen": "--specimen N", "rectangular": "--width W --height H",
                "classical": "--alpha A --p P --mu MU",
                "mesh": "--mesh FILE --density RHO (or --mass M)"}
_BLOCK_UNITS = {"mass": ("kg",), "p": ("1/s", "rad/s"), "density": ("kg/m^3", "kg/m3")}
"""Units a bare-number key may carry on the command line (taken off before the factory)."""


def _block_form(specimen, width, height, alpha, allow_classical: bool, mesh=None) -> str:
    """The factory form that the flags describe (exactly one)."""
    given = [f for f, v in (("specimen", specimen), ("rectangular", width or height),
                            ("classical", alpha), ("mesh", mesh)) if v is not None]
    if len(given) > 1:
        raise ParameterError(f"block: give only one of "
                             f"{' or '.join(BLOCK_FLAGS[f] for f in given)}")
    if not given:
        forms = ("specimen", "rectangular", *(("classical",) if allow_classical else ()),
                 "mesh")
        raise ParameterError(f"block: give {', or '.join(_BLOCK_USAGE[f] for f in forms)}")
    return given[0]


def mesh_flags() -> dict:
    """The mesh flags given to the running command (:func:`block_options`), by key."""
    ctx = click.get_current_context(silent=True)
    return dict(ctx.meta.get(MESH_META, {})) if ctx is not None else {}


def _bare(text, units: tuple[str, ...]) -> str:
    """``text`` without one of ``units`` at its end (``228kg`` -> ``228``)."""
    s = str(text).strip()
    for u in units:
        if s.lower().endswith(u):
            return s[: -len(u)].strip()
    return s


def make_block(specimen=None, params=None, width=None, height=None, mass=None, alpha=None,
               p=None, mu=None, allow_classical: bool = False):
    """``(block, info)`` from exactly one of: specimen, width/height, alpha/p/mu, or the
    mesh flags of :func:`block_options` (``--mesh``), built by
    :func:`rocking.blocks.factory.make_block` (which checks the values)."""
    from ..blocks.factory import FORMS
    from ..blocks.factory import make_block as build

    meshed = mesh_flags()
    if "mass" in meshed:
        mass = meshed.pop("mass")
    form = _block_form(specimen, width, height, alpha, allow_classical, meshed.get("mesh"))
    if form != "mesh" and meshed:
        raise ParameterError(f"{MESH_FLAGS[next(iter(meshed))][2:]} applies to --mesh only")
    texts = {k: v for k, v in (("specimen", specimen), ("params", params), ("width", width),
                               ("height", height), ("mass", mass), ("alpha", alpha),
                               ("p", p), ("mu", mu), *meshed.items()) if v is not None}
    keys = FORMS[form].Params.names()
    for k in texts:
        if k not in keys:
            where = " or ".join(flag for f, flag in BLOCK_FLAGS.items()
                                if k in FORMS[f].Params.names())
            raise ParameterError(f"{k} does not apply to {BLOCK_FLAGS[form]} (only to "
                                 f"{where})")
    given = {k: _bare(v, _BLOCK_UNITS.get(k, ())) for k, v in texts.items()}
    words = {k: (MESH_FLAGS.get(k, "--" + k)[2:] if form == "mesh" else k, v)
             for k, v in texts.items()}
    try:
        checked = FORMS[form].Params(**given)  # the factory's checks, for the info below
    except ParameterError as e:
        msg = one_line(in_flag_words(e, words))
        if " is required" in msg:
            msg += f"; give {_BLOCK_USAGE[form]}"
        raise type(e)(msg) from None
    try:
        block = build(given)
    except UnitSlipWarning as w:  # refused (force_option): in the flags' words
        if form != "rectangular":
            raise
        raise UnitSlipWarning(f"--width {width} --height {height}: {one_line(w)}") from None
    except ParameterError as e:  # valid keys, but no block (sizes beyond floating point)
        if form == "mesh":
            raise type(e)(one_line(in_flag_words(e, words))) from None
        if form != "rectangular":
            raise
        raise ParameterError(_size_problem(width, height, e)) from None
    return block, _block_info(form, checked, block, texts)


def _block_info(form: str, checked, block, texts: dict) -> dict:
    """What summary.json records of the block's source (and the overrides)."""
    if form == "classical":
        return {"alpha": block.alpha, "p": block.p, "mu": block.mu}
    if form == "mesh":
        from ..blocks.factory import load_mesh, mesh_directions, resolve_direction

        phi = resolve_direction(load_mesh(checked), mesh_directions(checked.direction)[0])
        return {"mesh": checked.mesh, "density": checked.density, "mass": block.mass,
                "up": checked.up, "direction": texts.get("direction", "0"),
                "direction_deg": math.degrees(phi)}
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


def options_table(cls, flags: dict | None = None) -> list[str]:
    """The options of a model class as text lines (from ``Options.describe()``); with
    ``flags`` (option name -> flag of ``rocking simulate``) a column of the flags, ``--option``
    for an option without one."""
    return describe_table(cls.Options.describe(), flags=flags)


def describe_table(rows: list[dict], head: str = "option", unset: str = "auto",
                   flags: dict | None = None) -> list[str]:
    """Declared parameters (:func:`rocking.options.describe_field` dicts) as text lines:
    name, (flag,) default (``required``, or ``unset`` for None), unit, range, help."""
    cells = [(d["name"], "required" if d.get("required") else _shown(d["default"], unset),
              d["unit"] or "-", d["range"] or "-", d["help"]) for d in rows]
    top = (head, "default", "unit", "range", "help")
    if flags is not None:
        cells = [(c[0], flags.get(c[0]) or f"--option {c[0]}=", *c[1:]) for c in cells]
        top = (head, "flag", *top[1:])
    if not cells:
        return ["  (no options)"]
    n = len(top) - 1
    widths = [max(len(r[i]) for r in (top, *cells)) for i in range(n)]
    return ["  " + "  ".join(f"{c:<{w}}" for c, w in zip(r[:n], widths, strict=True))
            + f"  {r[n]}" for r in (top, *cells)]


def _shown(value, unset: str = "auto") -> str:
    if value is None:
        return unset
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)


# ----------------------------------------------------------------------------- model flags
QUANTITY_OF_UNIT = {"s": "time", "m": "length", "rad": "angle", "m/s^2": "acceleration",
                    "Hz": "frequency", "": "ratio"}
"""The quantity that a declared option's SI unit stands for when the declaration names
none: a flag's value may then carry any unit of it (``2.5s``, ``15cm``, ``10%``; a bare
number is in the declared unit). Options in other units (``N/m``, ``m/s``) take a bare
number or the number followed by that unit."""

MODEL_FLAG_DEST = "model_flag__"
"""Prefix of the keyword under which a generated model flag reaches the command's
callback (``model_flag__isolation_period``)."""


def option_flag(name: str) -> str:
    """The flag of a model option: ``isolation_period`` -> ``--isolation-period``."""
    return "--" + name.replace("_", "-")


def option_declarations() -> dict[str, dict]:
    """``{option name: {model name: its dataclass field}}`` over the registered models (in
    the order of :data:`rocking.models.MODELS` and of each model's fields)."""
    out: dict[str, dict] = {}
    for model, cls in model_classes().items():
        for f in dataclasses.fields(cls.Options):
            if f.metadata:
                out.setdefault(f.name, {})[model] = f
    return out


def declared_value(name: str, text, field: dataclasses.Field, flag: str | None = None):
    """``text`` (a flag's value) as the value of the declared model option ``field``,
    checked against its range (:func:`rocking.options.check_option`).

    A number may carry a unit of the option's quantity (``quantity`` of the declaration, or
    :data:`QUANTITY_OF_UNIT` of its unit): ``2.5s``, ``15cm``, ``10%``; ``none`` is the
    automatic default of an option whose default is None; bool and free-form options read
    as :func:`option_value`. Errors name ``flag`` (default: the name with dashes) and the
    value as typed."""
    word = (flag or option_flag(name)).lstrip("-")
    m = field.metadata
    try:
        if not isinstance(text, str):
            return check_option(name, text, m)
        s = text.strip()
        if field.default is None and s.lower() in ("none", "null", "auto"):
            return None
        kind = m["kind"]
        if kind is bool or kind is object:
            return check_option(name, option_value(s), m)
        if m.get("choices") or kind is str:
            low = s.lower()
            return check_option(name, low if low in (m.get("choices") or ()) else s, m)
        unit = m.get("unit", "")
        qty = m.get("quantity") or QUANTITY_OF_UNIT.get(unit)
        if qty is not None:
            value = parse_quantity(s, qty, name=name, default_unit=unit)
        else:
            value = number(s, name, (unit.lower(),) if unit else ())
        return check_option(name, value, m)
    except ParameterError as e:
        raise in_flag_words(e, {name: (word, text)}) from None


def model_flag_values(model: str, given: dict, readers: dict | None = None) -> dict:
    """The model options given by flags (``{option name: text or None}``), read: an error
    naming the flag and the models that have the option if ``model`` lacks it; ``readers``
    (option name -> ``f(model, text)``) read options of their own way, the others
    :func:`declared_value` with the model's declaration."""
    decls = option_declarations()
    out = {}
    for key, text in given.items():
        if text is None:
            continue
        flag = key.replace("_", "-")
        owners = list(decls.get(key, {}))
        if model not in owners:
            raise ParameterError(f"{flag} applies to --model {' or '.join(owners)} only")
        reader = (readers or {}).get(key)
        out[key] = (reader(model, text) if reader is not None
                    else declared_value(key, text, decls[key][model]))
    return out


class ModelFlagsCommand(click.Command):
    """A command with a flag per option of the registered models, generated from their
    declarations (:func:`rocking.options.option`: help, unit, range, choices) when the
    command line is parsed or its help shown (the models are imported then, not before).

    ``--isolation-period 2.5s`` is the option ``isolation_period``; a bool option is a pair
    ``--settled/--no-settled``. An option whose flag is already a flag of the command (the
    command's own ``--dt``) gets none (:meth:`skipped`): ``--option KEY=VALUE`` still sets
    it. The callback receives the flags as ``model_flag__NAME`` keywords (None: not
    given). ``flag_help`` overrides ``(metavar, help)`` of some options; ``option_flags``
    names the options that one of the command's own flags sets (``--linear``)."""

    def __init__(self, *args, flag_help: dict | None = None,
                 option_flags: dict | None = None, **kwargs):
        super().__init__(*args, **kwargs)
        self.flag_help = dict(flag_help or {})
        self.option_flags = dict(option_flags or {})
        """Options that one of the command's own flags sets (``{"linear": "--linear"}``)."""
        self._generated: tuple = ((), [])

    def own_flags(self) -> set:
        """The flags of the command itself (``--dt``, ``--mu``, ...)."""
        return {o for p in self.params for o in (*p.opts, *p.secondary_opts)}

    def model_flags(self) -> dict:
        """``{option name: flag}`` of the options that have a generated flag."""
        own = self.own_flags()
        return {k: option_flag(k) for k in option_declarations() if option_flag(k) not in own}

    def flag_of(self) -> dict:
        """``{option name: flag}`` of every option that a flag sets: the generated ones
        and :attr:`option_flags` (``rocking models`` shows them)."""
        decls = option_declarations()
        return {**self.model_flags(),
                **{k: v for k, v in self.option_flags.items() if k in decls}}

    def skipped(self) -> dict:
        """``{option name: flag}`` of the options without a flag: it is one of the
        command's own (set them with ``--option KEY=VALUE``)."""
        own = self.own_flags()
        return {k: option_flag(k) for k in option_declarations() if option_flag(k) in own}

    def generated_params(self) -> list:
        key = tuple((k, id(c)) for k, c in model_classes().items())
        if self._generated[0] != key:
            decls = option_declarations()
            self._generated = (key, [self._option(k, decls[k])
                                     for k in self.model_flags()])
        return self._generated[1]

    def _option(self, name: str, fields: dict) -> click.Option:
        f = next(iter(fields.values()))
        m = f.metadata
        flag, dest = option_flag(name), MODEL_FLAG_DEST + name
        metavar, text = self.flag_help.get(name, (None, None))
        if text is None:
            shown = {(d["unit"], d["range"]) for d in map(describe_field, fields.values())}
            bits = ["see 'rocking models'"]
            if len(shown) == 1 and not m.get("choices") and m.get("kind") is not bool:
                unit, rng = shown.pop()
                bits = [b for b in (unit, rng) if b]
            if f.default is None and m.get("kind") is not bool:
                bits.append("'none': the default")
            text = f"{', '.join(fields)}: {m.get('help', '')}" + (
                f" [{'; '.join(bits)}]" if bits and m.get("kind") is not bool
                and not m.get("choices") else "")
        if m.get("kind") is bool:
            return click.Option([f"{flag}/--no-{flag[2:]}", dest], default=None, help=text)
        if metavar is None:
            metavar = "[" + "|".join(map(str, m["choices"])) + "]" if m.get("choices") \
                else "VALUE"
        return click.Option([flag, dest], metavar=metavar, help=text)

    def get_params(self, ctx):
        params = super().get_params(ctx)
        help_option = self.get_help_option(ctx)
        own = [p for p in params if p is not help_option]
        return [*own, *self.generated_params(), *([help_option] if help_option else [])]


def model_flags_given(kwargs: dict) -> dict:
    """``{option name: value}`` of the generated flags among a callback's keywords."""
    return {k[len(MODEL_FLAG_DEST):]: v for k, v in kwargs.items()
            if k.startswith(MODEL_FLAG_DEST)}


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


# ------------------------------------------------------------------- unit slips, --force
FORCE_HELP = ("Run with a value that is surely a unit slip (a density outside 300-25,000 "
              "kg/m^3, a site PGA above 2 g, a block or mesh larger than 50 m: "
              "rocking.PLAUSIBLE_LIMITS), with a warning instead of a refusal.")


def force_option(f):
    """Decorator (below ``@click.command``) adding ``--force`` to a command: without it, a
    :class:`~rocking.errors.UnitSlipWarning` of the library (the limits of
    :data:`rocking.PLAUSIBLE_LIMITS`, the same as the Python API's warnings) is a refusal:
    one line ``error: ...; give --force to run with it`` and exit code 2."""
    import functools
    import warnings

    @functools.wraps(f)
    def wrapper(*args, force=False, **kwargs):
        with warnings.catch_warnings():
            if not force:
                warnings.simplefilter("error", UnitSlipWarning)
            try:
                return f(*args, **kwargs)
            except UnitSlipWarning as w:
                raise ParameterError(f"{one_line(str(w))}; give --force to run with it "
                                     "anyway") from None

    return click.option("--force", is_flag=True, help=FORCE_HELP)(wrapper)


# ------------------------------------------------------------------------- hazard curves
def _positive_with_suffix(text, suffix: str, name: str, what: str) -> float | None:
    """A number > 0, optionally followed by one of the words of the regex ``suffix``."""
    if text is None:
        return None
    m = re.fullmatch(rf"\s*([0-9.eE+-]+)\s*(?:{suffix})?\s*", str(text))
    try:
        v = float(m.group(1)) if m else math.nan
    except ValueError:
        v = math.nan
    if not (math.isfinite(v) and v > 0):
        raise ParameterError(f"{name} must be {what}, got {text!r}")
    return v


def years_option(text, name: str = "investigation-time") -> float | None:
    """``--investigation-time``: years > 0, as ``50``, ``50y``, ``50yr`` or ``50 years``."""
    return _positive_with_suffix(text, "y|yr|yrs|year|years", name,
                                 "a number of years > 0 (e.g. 50 or 50yr)")


def km_option(text, name: str = "max-distance-km") -> float | None:
    """``--max-distance-km``: km > 0 (a number, or with ``km``)."""
    return _positive_with_suffix(text, "km", name, "a distance in km > 0")


def hazard_option_words(msg: str) -> str:
    """A hazard reader's message with the command line's option names."""
    for key, opt in (("investigation_time", "--investigation-time"),
                     ("max_distance_km", "--max-distance-km")):
        msg = msg.replace(f"{key}=", f"{opt} ").replace(key, opt)
    return msg.replace("(site=", "(--site ")


def read_hazard_option(path, *, site=None, unit=None, investigation_time=None,
                       max_distance_km=None, file_name: str = "FILE",
                       unit_name: str = "--unit"):
    """The hazard curve in ``path`` as an option gives it: an OpenQuake export (first line
    a ``#`` comment naming ``investigation_time``; ``site`` an index or ``LON,LAT``,
    refused beyond ``max_distance_km``) or a CSV of one curve
    (:meth:`rocking.analysis.HazardCurve.from_csv`, ``investigation_time`` for a column of
    probabilities of exceedance). Errors name ``file_name`` and the options."""
    from ..analysis.hazard import MAX_SITE_DISTANCE_KM, HazardCurve
    from ..campaign.hazard import parse_site

    p = Path(path)
    if not p.is_file():
        raise ParameterError(f"{file_name}: no such file {str(path)!r}")
    try:
        with p.open() as fh:
            first = fh.readline()
    except (OSError, UnicodeDecodeError) as e:
        raise ParameterError(f"{file_name}: cannot read {p.name} as text ({e})") from None
    years = years_option(investigation_time)
    dmax = km_option(max_distance_km)
    try:
        if first.lstrip().startswith("#") and "investigation_time" in first:
            if unit is not None:
                raise ParameterError(f"{unit_name} does not apply to the OpenQuake export "
                                     f"{p.name} (its PGA and SA levels are in g)")
            if years is not None:
                raise ParameterError(f"--investigation-time does not apply to the OpenQuake "
                                     f"export {p.name} (its metadata line states it)")
            return HazardCurve.from_openquake(
                p, site=0 if site is None else parse_site(site),
                max_distance_km=MAX_SITE_DISTANCE_KM if dmax is None else dmax)
        if site is not None or dmax is not None:
            raise ParameterError(f"--site and --max-distance-km apply to OpenQuake exports "
                                 f"only ({p.name} is a CSV of one curve)")
        return HazardCurve.from_csv(p, unit=unit, investigation_time=years)
    except ParameterError as e:
        msg = hazard_option_words(one_line(e)).replace("give unit='g'",
                                                       f"give {unit_name} g")
        msg = re.sub(r"^unit\b", unit_name, msg)
        raise ParameterError(msg if p.name in msg else f"{file_name} {p.name}: {msg}") \
            from None


__all__ = ["CONTEXT", "quantity", "number", "check_positive", "positive_quantity", "integer",
           "specimen_number", "json_default", "block_options", "make_block", "model_classes",
           "ModelChoice", "option_value", "parse_options", "validate_options",
           "models_with_option", "options_table", "describe_table", "one_line",
           "read_record_arg", "output_too_large_message", "error_report", "in_flag_words",
           "BLOCK_FLAGS", "MESH_FLAGS", "mesh_flags", "BUILDING_FLAGS", "building_options",
           "make_building",
           "QUANTITY_OF_UNIT", "MODEL_FLAG_DEST", "option_flag", "option_declarations",
           "declared_value", "model_flag_values", "ModelFlagsCommand", "model_flags_given",
           "years_option", "km_option", "hazard_option_words", "read_hazard_option"]
