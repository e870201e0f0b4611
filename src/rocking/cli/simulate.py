"""``rocking simulate``: one block under one base motion, with any registered model.

::

    rocking simulate --specimen 2 --params experimental --motion sine --freq 5 --amp 5mm \\
        --duration 25 --out out/
    rocking simulate --specimen 2 --record quake.AT2 --units g --load-factor 1.2 --out out/
    rocking simulate --specimen 2 --model ccrr --option rtol=1e-9 --motion free \\
        --theta0 0.05 --duration 5
    rocking simulate --specimen 1 --motion mavroeidis_papageorgiou --amp 0.3g --freq 1 \\
        --param gamma=2 --param nu=0
    rocking simulate --specimen 2 --record Rinaldi228 --building shear --storeys 5 \\
        --building-period 0.5 --building-damping 5% --floor 3
    rocking simulate --model rigid3d --mesh statue.ply --density 2600 \\
        --pair H1.AT2 H2.AT2 --vertical UP.AT2 --heading 30 --out out/
    rocking simulate --model rigid3d --box 0.4 0.4 1.2 --record Rinaldi228 --direction 30

A 3-D model (``--model rigid3d``) takes a body (``--mesh``, ``--box LX LY LZ``,
``--cylinder R H``, or a rectangular block or specimen as a box), a single motion along
``--direction`` or a pair of horizontal components (``--pair H1 H2``, ``--vertical``) at
``--heading``, and ``--out`` writes its tilt, slide and twist, the path of its centre of
mass and its overturning azimuth: :mod:`rocking.cli.simulate3d`.

Motions are built by :mod:`rocking.motions.catalog` (``rocking motions`` lists the kinds):
``--motion`` is a kind's name, ``--amp``, ``--freq``, ``--tp`` and ``--duration`` set its
``amplitude`` (or ``displacement``), ``frequency``, ``period`` and ``duration``, and
``--param KEY=VALUE`` any of its parameters. ``--record`` is the kind ``record`` (or
``builtin``, by name), ``--earthquake N`` the kind ``earthquake``; ``--record`` with
``--vertical`` is a GroundMotion of two such records (for two files, the kind
``ground_motion``). Blocks are built by :func:`rocking.blocks.factory.make_block`
(:func:`rocking.cli.common.make_block`).

``--building KIND`` puts the block on a floor of a building of
:mod:`rocking.buildings.catalog` (``rocking buildings`` lists the kinds): ``--storeys``,
``--building-period`` and ``--building-damping`` set its ``storeys``, ``period`` and
``damping_ratio``, ``--building-param KEY=VALUE`` any other key (a list as JSON:
``masses=[2,1,1]``); ``--floor K`` (0 the ground) or ``--height-ratio X`` (z/H, a
continuous building) says where the block stands. The motion of the other flags is then the
ground motion, and the block feels :class:`rocking.buildings.FloorMotion` of it.

``--model`` is a name of :data:`rocking.models.MODELS` and ``--option KEY=VALUE``
(repeatable) passes an option of that model's ``Options`` (``rocking models`` lists them);
the model validates the options. Every declared option of every registered model also has a
flag of its own, generated from its declaration (:class:`~rocking.cli.common.
ModelFlagsCommand`; help, unit and range from :func:`rocking.options.option`), so a new
model's options get flags without editing this module::

    rocking simulate --specimen 2 --record Rinaldi228 --model isolated \
        --isolation-period 2.5 --isolation-damping 10% --clearance 0.15m
    rocking simulate --specimen 2 --record Rinaldi228 --model anchored \
        --anchor-strength 0.3 --anchors elastic --anchor-stiffness 200

A number takes a unit of its quantity (``2.5s``, ``15cm``; a dimensionless one ``10%`` or
``0.1``; a bare number is in the declared SI unit), ``none`` the automatic default, a bool
option is ``--settled/--no-settled``. The DEM's ``--friction-angle`` (a bare number in
degrees, deprecated), ``--stiffness`` and ``--damping`` (``calibrated``, ``paper``) are
read their own way (:data:`FLAG_READERS`). A flag of an option the model lacks, or an
option given both by its flag and by ``--option``, is refused (exit code 2).

Options WITHOUT a flag, since theirs is already a flag of this command (set them with
``--option KEY=VALUE``): ``dt`` (ccrr, dem: ``--dt`` is a record's time step), ``mu``
(isolated's restitution: ``--mu`` is the impact restitution of every model, so with the
isolated model it imposes that option, derived from the momentum of block and plate
without it; ``--alpha A --p P --mu MU --model isolated`` runs with ``mu = MU``),
``linear`` (housner: ``--linear`` is that option already) and ``direction`` (rigid3d:
``--direction`` is that option already, the direction of shaking from the body's x axis,
the same quantity as a ``--mesh``'s planar direction: :mod:`rocking.cli.simulate3d`).
``ModelFlagsCommand.skipped()`` lists them; a test checks this list against it.

Models with row outputs (:attr:`rocking.models.base.Model.row_outputs`: the isolated
base's ``max_base_displacement``, ``max_plate_acceleration``, ``clearance_exceeded``,
``clearance_time``; the anchors' ``max_anchor_force``, ``anchor_break_time_plus``/``minus``,
``anchor_broken_plus``/``minus``) print them, with units, after the rocking response;
``--json`` prints the summary (also in ``summary.json``), with ``row_outputs``:
``{name: {value, unit, flag, help}}`` (a NaN time as null).
"""

from __future__ import annotations

import dataclasses
import json
import math
import warnings
from pathlib import Path

import click
import numpy as np

from .._atomic import atomic_write
from .._validate import as_float
from ..errors import ParameterError
from ..options import check_option
from ..units import ACCELERATION, LENGTH, G, split_quantity
from . import simulate3d
from .common import (
    BUILDING_FLAGS,
    CONTEXT,
    ModelChoice,
    ModelFlagsCommand,
    block_options,
    building_options,
    check_positive,
    declared_value,
    force_option,
    in_flag_words,
    integer,
    json_default,
    make_block,
    make_building,
    model_classes,
    model_flag_values,
    model_flags_given,
    models_with_option,
    number,
    one_line,
    option_declarations,
    parse_options,
    positive_quantity,
    quantity,
    read_record_arg,
    validate_options,
)
from .simulate3d import is_3d, refuse_3d_flags

HARMONIC = ("sine", "hanning")
PULSES = ("one_sine", "one_cosine", "half_sine", "rectangular")
CATALOG_MOTIONS = (*HARMONIC, *PULSES, "ricker", "mavroeidis_papageorgiou")
"""The kinds of :data:`rocking.motions.catalog.KINDS` that ``--motion`` names (``record``
too, with ``--record``; ``earthquake`` with ``--earthquake``)."""
MOTION_CHOICES = (*CATALOG_MOTIONS, "record", "free")
FLAG_OF = {"frequency": "freq", "period": "tp", "amplitude": "amp", "displacement": "amp",
           "duration": "duration"}
"""The catalog parameters that have a flag of their own (the others: ``--param``)."""
UNITS_HELP = "g, m/s^2 or cm/s^2"


class MotionChoice(click.ParamType):
    """``--motion``: ``free`` or any kind of :data:`rocking.motions.catalog.KINDS` (the
    kinds of :data:`MOTION_CHOICES` have flags of their own; every kind takes ``--param
    KEY=VALUE``), or an old spelling of one (``one-sine``; resolved by the catalog, with a
    warning)."""

    name = "motion"

    def get_metavar(self, param, ctx=None):  # click >= 8.2 passes ctx
        return "KIND"

    def convert(self, value, param, ctx):
        if value in MOTION_CHOICES:
            return value
        from ..motions.catalog import ALIASES, KINDS  # lazy: the motions import numba

        if value in KINDS or value in ALIASES:
            return value
        self.fail(f"{value!r} is not one of free, {', '.join(KINDS)} (rocking motions "
                  "lists them)", param, ctx)


# ----------------------------------------------------------------------------- motions
def _amp_param(text, kind: str) -> str:
    """The catalog parameter that ``--amp`` sets: ``displacement`` (a length, sine and
    hanning) or ``amplitude`` (an acceleration). A unit is required: ``--amp 5`` could be
    5 m or 5 mm."""
    parts = split_quantity(text)
    unit = "?" if parts is None else parts[1]  # "?": not a number, the catalog says so
    if kind in HARMONIC:
        if not unit:
            raise ParameterError(f"amp needs a unit for --motion {kind}: a table displacement "
                                 "with a length unit such as 5mm (or an acceleration such as "
                                 f"0.3g); got {text!r}")
        return "amplitude" if unit in ACCELERATION else "displacement"
    hint = "an acceleration with a unit such as 0.3g or 2.8m/s2"
    if unit in LENGTH:
        raise ParameterError(f"amp for --motion {kind} is a peak acceleration, not a length: "
                             f"give {hint}; got {text!r}")
    if not unit:
        raise ParameterError(f"amp needs a unit for --motion {kind}: {hint}; got {text!r}")
    return "amplitude"


def _catalog_values(kind: str, freq, amp, tp, duration, pairs) -> tuple[dict, dict]:
    """The catalog parameters of ``kind`` from the flags and the ``--param`` pairs, and
    the words of messages (:func:`~rocking.cli.common.in_flag_words`)."""
    from ..motions.catalog import KINDS

    names = KINDS[kind].Params.names()
    flags = {"frequency": freq, "period": tp, "duration": duration}
    if amp is not None:
        flags[_amp_param(amp, kind)] = amp
    values = {k: v for k, v in flags.items() if v is not None}
    for key in values:
        if key not in names:
            raise ParameterError(f"{FLAG_OF[key]} does not apply to --motion {kind}")
    extra = parse_options(pairs, flag="param", example="gamma=2")
    for key in extra:
        if key in values:
            raise ParameterError(f"{key} given twice (--{FLAG_OF[key]} and --param "
                                 f"{key}=...)")
    words = {k: (f, flags.get(k)) for k, f in FLAG_OF.items() if k not in extra}
    return {**values, **extra}, words


def _build(kind: str, values: dict, words: dict):
    """``(checked parameters, motion)`` of a catalog kind; errors in the flags' words."""
    from ..motions import catalog

    entry = catalog.KINDS[kind]
    try:
        p = entry.params(**values)
        return p, entry.make(p, catalog.Context())
    except ParameterError as e:
        msg = one_line(in_flag_words(e, words))
        name = msg.split(" ", 1)[0]
        if msg.startswith(f"{name} is required") and name not in FLAG_OF.values():
            msg += f"; give --param {name}=VALUE"  # a parameter without a flag of its own
        raise type(e)(msg) from None


def _describe(kind: str, m) -> dict:
    """The summary.json description of a catalog motion (SI units)."""
    d: dict = {"type": kind}
    if kind in HARMONIC:
        d.update(freq=m.freq, amplitude=m.amplitude,
                 acc_amplitude=m.amplitude * (2.0 * math.pi * m.freq) ** 2)
        if getattr(m, "phase", 0.0):
            d["phase"] = m.phase
    elif kind in PULSES:
        d.update(amplitude=m.amplitude, tp=m.length)
        if m.t0:
            d["t0"] = m.t0
    elif kind == "ricker":
        d.update(amplitude=m.amplitude, fp=m.fp, tc=m.tc)
    elif kind == "mavroeidis_papageorgiou":
        d.update(amplitude=m.amplitude, fp=m.fp, gamma=m.gamma, nu=m.nu, t0=m.t0)
    d["duration"] = m.duration
    return d


def _other_motion(kind: str, freq, amp, tp, pairs):
    """``(motion, description)`` of a catalog kind without flags of its own (``--param
    KEY=VALUE``: a built-in three-component set, a stochastic record with seed 0, ...)."""
    values, words = _catalog_values(kind, freq, amp, tp, None, pairs)
    p, m = _build(kind, values, words)
    defaults = {d["name"]: d["default"] for d in p.describe()}
    desc = {"type": kind, **{k: v for k, v in p.to_dict().items()
                             if v is not None and v != defaults[k]}, "pga": m.pga}
    return m, desc


def _catalog_motion(kind: str, freq, amp, tp, duration, pairs):
    """``(motion, description, duration for simulate)`` of a catalog kind: for sine and
    hanning ``--duration`` is the motion's length, for pulses the run's."""
    values, words = _catalog_values(kind, freq, amp, tp, duration, pairs)
    _, m = _build(kind, values, words)
    run = m.duration if values.get("duration") is not None and kind not in HARMONIC \
        else None
    return m, _describe(kind, m), run


def _earthquake(text):
    """One of the paper's earthquakes (catalog kind ``earthquake``)."""
    p, m = _build("earthquake", {"number": text}, {"number": ("earthquake", text)})
    return m, {"type": "earthquake", "number": p.number, "dt": m.dt, "pga": m.pga}


def _record(record, units, dt):
    """A record file or a built-in record (catalog kinds ``record``, ``builtin``)."""
    rec, src = read_record_arg(record, "record", units, dt)
    return rec, {"type": "record", "file": src, "units": "g" if units is None else units,
                 "dt": rec.dt, "n": len(rec), "pga": rec.pga}


def _ground(rec, desc: dict, vertical, vertical_factor, units, dt, lf: float):
    """``--record`` and ``--vertical`` as a GroundMotion: the horizontal component times the
    load factor, the vertical one times ``--vertical-factor`` (default the load factor)."""
    from ..motions import GroundMotion

    vrec, vsrc = read_record_arg(vertical, "vertical", units, dt)
    fv = None if vertical_factor is None else as_float("vertical-factor", vertical_factor)
    m = GroundMotion(rec, vrec).scaled(lf, vertical=fv)
    desc.update(vertical=vsrc, vertical_factor=lf if fv is None else fv,
                pga=m.pga, pga_vertical=m.pga_vertical,  # as run (scaled)
                repr=f"{m.horizontal!r} + vertical {m.vertical!r}", load_factor=lf)
    return m, desc


def _scaled(m, desc: dict, lf: float):
    """The motion times the load factor, and its description as run."""
    if lf != 1.0:
        m = m.scaled(lf)
    if "pga" in desc:
        desc["pga"] = m.pga
    desc.update(load_factor=lf, repr=repr(m))
    return m, desc


def _kind_name(motion: str) -> str:
    """The catalog's name of ``--motion`` (an old spelling warns)."""
    from ..motions.catalog import kind

    return kind(motion, param="motion").name


def _source(motion, record, earthquake, vertical, vertical_factor) -> str:
    """What the flags ask for: a catalog kind, ``record``, ``free`` or ``earthquake``."""
    if vertical is None and vertical_factor is not None:
        raise ParameterError("vertical-factor applies with --vertical V.AT2 only")
    if vertical is not None and record is None:
        raise ParameterError("vertical: --vertical needs the horizontal --record FILE")
    if earthquake is not None:
        if motion is not None or record is not None:
            raise ParameterError("earthquake: --earthquake cannot be combined with --motion "
                                 "or --record")
        return "--earthquake"
    if motion is None:
        if record is None:
            raise ParameterError(f"motion: give --motion ({', '.join(MOTION_CHOICES)}) "
                                 f"or --record FILE")
        return "record"
    name = "free" if motion == "free" else _kind_name(motion)
    if name == "record" and record is None:
        raise ParameterError("record: --motion record needs --record FILE")
    if record is not None and name != "record":
        raise ParameterError(f"record: --record cannot be combined with --motion {name}")
    return name


def _refuse(source: str, given: dict) -> None:
    """An error for a flag that does not apply to the motion."""
    applies = {"free": (), "--earthquake": (), "record": ("units", "dt")}.get(
        source, ("freq", "amp", "tp", "param"))
    label = source if source == "--earthquake" else f"--motion {source}"
    for flag, value in given.items():
        if value is None or flag in applies:
            continue
        if flag in ("units", "dt"):
            raise ParameterError(f"{flag} applies to --record only")
        raise ParameterError(f"{flag} does not apply to {label}")


def make_motion(motion, freq, amp, tp, duration, record, units, dt, load_factor,
                earthquake=None, vertical=None, vertical_factor=None, params=()):
    """``(motion or None, description dict, duration for simulate)`` from the flags, built
    by :mod:`rocking.motions.catalog` (``params``: the ``--param KEY=VALUE`` pairs)."""
    source = _source(motion, record, earthquake, vertical, vertical_factor)
    _refuse(source, {"freq": freq, "amp": amp, "tp": tp, "param": params or None,
                     "units": units, "dt": dt})
    lf = 1.0 if load_factor is None else as_float("load-factor", load_factor)
    if source in CATALOG_MOTIONS:
        m, desc, run = _catalog_motion(source, freq, amp, tp, duration, params)
        return (*_scaled(m, desc, lf), run)
    # default (None): the run goes on after the motion until the block has settled
    run = positive_quantity(duration, "time", "duration", "s", "s")
    if source == "free":
        return None, {"type": "free", "load_factor": lf}, run
    if source not in ("--earthquake", "record"):
        return (*_scaled(*_other_motion(source, freq, amp, tp, params), lf), run)
    if source == "--earthquake":
        m, desc = _earthquake(earthquake)
    else:
        m, desc = _record(record, units, dt)
        if vertical is not None:
            return (*_ground(m, desc, vertical, vertical_factor, units, dt, lf), run)
    return (*_scaled(m, desc, lf), run)


# ----------------------------------------------------------------------------- buildings
def _where(building, floor, height_ratio) -> dict:
    """``{"floor": K}`` or ``{"height_ratio": X}`` of the flags (one of them)."""
    if building is None:
        for flag, v in (("floor", floor), ("height-ratio", height_ratio)):
            if v is not None:
                raise ParameterError(f"{flag}: --{flag} applies with --building KIND only")
        return {}
    if floor is not None and height_ratio is not None:
        raise ParameterError("floor or height-ratio: give one, not both")
    if height_ratio is not None:
        return {"height_ratio": number(height_ratio, "height-ratio")}
    if floor is None:
        raise ParameterError("floor: --building needs --floor K (0 the ground, 1 .. the top "
                             "floor) or --height-ratio X (z/H)")
    return {"floor": integer(floor, "floor", lo=0)}


def on_floor(mot, building_flags: dict, floor, height_ratio):
    """``(motion the block stands on, floor description or None)``: ``mot`` itself without
    ``--building``, else :class:`rocking.buildings.FloorMotion` of it (the ground motion)
    at ``--floor`` or ``--height-ratio``."""
    kind = building_flags.get("kind")
    if kind is None:
        flags = {"storeys": "storeys", "period": "building-period",
                 "damping": "building-damping", "param": "building-param"}
        given = [flags[k] for k, v in building_flags.items() if v and k in flags]
        if given:
            raise ParameterError(f"{given[0]}: --{given[0]} applies with --building KIND "
                                 "only")
        _where(None, floor, height_ratio)
        return mot, None
    building, bdesc = make_building(kind, building_flags["storeys"], building_flags["period"],
                                    building_flags["damping"], building_flags["param"])
    where = _where(building, floor, height_ratio)
    if mot is None:
        raise ParameterError("building: --building needs a ground motion (not --motion free)")
    from ..buildings import FloorMotion

    try:
        fm = FloorMotion(mot, building, **where)
    except ParameterError as e:
        msg = one_line(in_flag_words(e, {"height_ratio": ("height-ratio", height_ratio)}))
        msg = msg.replace("give height_ratio", "give --height-ratio X")
        raise type(e)(msg) from None
    return fm, {"building": bdesc, **where, "floor_pga": fm.pga, "where": fm.where}


# ----------------------------------------------------------------------------- model options
def _friction_angle(model: str, text) -> float:
    """``--friction-angle 30deg`` (or ``0.52rad``) in rad, checked by the model's declared
    option; a bare number is read in degrees, deprecated (a warning)."""
    s = str(text).strip()
    parts = split_quantity(s)
    if parts is not None and not parts[1]:
        warnings.warn(f"friction-angle: a bare number is read in degrees, which is "
                      f"deprecated: write {s}deg (or the angle in rad, e.g. "
                      f"{math.radians(parts[0]):.4g}rad)", DeprecationWarning, stacklevel=3)
        s += "deg"
    meta = {f.name: f.metadata for f in dataclasses.fields(model_classes()[model].Options)}
    try:
        return check_option("friction_angle", s, meta["friction_angle"])
    except ParameterError as e:
        raise in_flag_words(e, {"friction_angle": ("friction-angle", text)}) from None


def _stiffness(model: str, text) -> float:
    """``--stiffness 1e6`` (or ``1e6N/m``), > 0."""
    return check_positive(number(text, "stiffness", ("n/m",)), "stiffness", "N/m")


def _damping(model: str, text):
    """``--damping 0.001`` (s, ``1ms``), ``calibrated`` or ``paper``."""
    d = str(text).strip().lower()
    if d in ("calibrated", "paper"):
        return d
    value = as_float("damping", number(d, "damping", ("s",)))
    if value < 0:
        raise ParameterError(f"damping must be >= 0 s, 'calibrated' or 'paper'; got {text!r}")
    return value


FLAG_READERS = {"friction_angle": _friction_angle, "stiffness": _stiffness,
                "damping": _damping}
"""The model flags read their own way (the DEM's: a bare friction angle in degrees,
damping words); the others by their declaration
(:func:`~rocking.cli.common.declared_value`)."""

FLAG_HELP = {
    "friction_angle": ("ANGLE", "dem: contact friction angle with its unit, e.g. 30deg or "
                                "0.52rad (default 30deg; a bare number is degrees, "
                                "deprecated)."),
    "stiffness": ("K", "dem: normal contact stiffness per contact point (N/m; default "
                       "physical, a settlement of 1e-7 of the height)."),
    "damping": ("B", "dem: stiffness-proportional damping b (s), or 'calibrated' (default: "
                     "matches mu) or 'paper' (Eq 20)."),
}
"""Metavar and help of the model flags whose generated ones would not say enough."""


def flag_options(model: str, friction_angle=None, stiffness=None, damping=None, *,
                 flags: dict | None = None) -> dict:
    """The options given by their own flags (the DEM's three, and ``flags``: ``{option
    name: text or None}`` of the generated ones), read; an error for a model without
    them (:func:`~rocking.cli.common.model_flag_values`)."""
    given = {"friction_angle": friction_angle, "stiffness": stiffness, "damping": damping,
             **(flags or {})}
    return model_flag_values(model, given, FLAG_READERS)


def _option_pairs(model: str, pairs) -> dict:
    """``--option KEY=VALUE`` pairs; a text value of a declared number read with its unit
    (``--option clearance=15cm``) as the flag would."""
    opts = parse_options(pairs)
    decls = option_declarations()
    for key, value in opts.items():
        f = decls.get(key, {}).get(model)
        if isinstance(value, str) and f is not None and f.metadata.get("kind") in (int, float) \
                and key not in FLAG_READERS:
            opts[key] = declared_value(key, value, f, flag=f"option {key}")
    return opts


def model_options(model: str, pairs, friction_angle=None, stiffness=None, damping=None, *,
                  flags: dict | None = None) -> dict:
    """``--option KEY=VALUE`` pairs and the model flags as one options dict, checked by the
    model (unknown names, ranges)."""
    opts = _option_pairs(model, pairs)
    flagged = flag_options(model, friction_angle, stiffness, damping, flags=flags)
    both = sorted(set(opts) & set(flagged))
    if both:
        raise ParameterError(f"option {both[0]} given twice (--{both[0].replace('_', '-')} "
                             f"and --option {both[0]}=...)")
    opts.update(flagged)
    words = {k: (k.replace("_", "-"), None) for k in flagged}
    try:
        validate_options(model, opts)
    except ParameterError as e:  # a check of several options: in the flags' words
        raise in_flag_words(e, words) from None
    return opts


# ----------------------------------------------------------------------------- request
def _linear_option(model: str, linear: bool, options: dict) -> None:
    """``--linear`` as the option ``linear=true`` (one way into the model's options)."""
    if linear:
        owners = models_with_option("linear")
        if model not in owners:
            raise ParameterError(f"linear applies to --model {' or '.join(owners)} only")
        options["linear"] = True


def _run_settings(dt_out, max_free_time, duration) -> dict:
    """``dt_out`` and ``max_free_time`` of :func:`rocking.models.simulate`, where given
    (``--max-free-time`` only without ``--duration``)."""
    run = {}
    if dt_out is not None:
        run["dt_out"] = positive_quantity(dt_out, "time", "dt_out", "s", "s")
    if max_free_time is not None:
        if duration is not None:
            raise ParameterError("max-free-time applies without --duration only (--duration "
                                 "is the run's length exactly)")
        mft = quantity(max_free_time, "time", "max-free-time", default_unit="s")
        if not mft >= 0.0:
            raise ParameterError(f"max-free-time must be >= 0 s, got {max_free_time!r}")
        run["max_free_time"] = mft
    return run


@dataclasses.dataclass(frozen=True)
class SimulateRequest:
    """``rocking simulate``'s options, read and checked (:meth:`from_options`): the block,
    the motion it stands on, the model with its options, the run's settings and where the
    results go; :meth:`simulate` runs it."""

    block: object
    block_info: dict
    motion: object
    """The motion the block stands on (a FloorMotion with ``--building``), or None."""
    motion_info: dict
    floor_info: dict | None
    duration: float | None
    model: str
    options: dict
    linear: bool
    theta0: float | None
    omega0: float | None
    run: dict
    """``dt_out`` and ``max_free_time``, where given."""
    out: str | None
    as_json: bool
    html: bool = True
    """A 3-D model: ``--out`` writes the page ``motion.html`` (``--no-html``: not)."""
    animate: bool = False
    """A 3-D model: ``--out`` writes the animation ``motion.gif`` (``--animate``)."""

    @classmethod
    def from_options(cls, *, specimen, params_set, width, height, alpha, p, mu, model,
                     model_opts, motion, freq, amp, tp, motion_params, duration,
                     max_free_time, record, vertical, vertical_factor, units, dt, earthquake,
                     load_factor, theta0, omega0, linear, dt_out, building, storeys,
                     building_period, building_damping, building_params, floor,
                     height_ratio, out, as_json, box=None, cylinder=None, pair=None,
                     html=None, animate=False, **model_flags):
        """The request of the command's options (click's values; ``model_flags``: the
        generated flags of the models' options). A 3-D model (``rigid3d``): the body, pair
        and direction of :mod:`rocking.cli.simulate3d`."""
        if is_3d(model):
            return cls._from_options_3d(
                specimen=specimen, params_set=params_set, width=width, height=height,
                alpha=alpha, p=p, mu=mu, model=model, model_opts=model_opts, motion=motion,
                freq=freq, amp=amp, tp=tp, motion_params=motion_params, duration=duration,
                max_free_time=max_free_time, record=record, vertical=vertical,
                vertical_factor=vertical_factor, units=units, dt=dt, earthquake=earthquake,
                load_factor=load_factor, theta0=theta0, omega0=omega0, linear=linear,
                dt_out=dt_out, building=building, storeys=storeys,
                building_period=building_period, building_damping=building_damping,
                building_params=building_params, floor=floor, height_ratio=height_ratio,
                out=out, as_json=as_json, box=box, cylinder=cylinder, pair=pair,
                model_flags=model_flags, html=html, animate=animate)
        refuse_3d_flags(model, box, cylinder, pair)
        simulate3d.refuse_viewer_flags(model, html, animate)
        block, binfo = make_block(specimen, params_set, width, height, None, alpha, p, mu,
                                  allow_classical=True)
        mot, mdesc, sim_dur = make_motion(motion, freq, amp, tp, duration, record, units, dt,
                                          load_factor, earthquake, vertical, vertical_factor,
                                          params=motion_params)
        mot, fdesc = on_floor(mot, {"kind": building, "storeys": storeys,
                                    "period": building_period, "damping": building_damping,
                                    "param": building_params}, floor, height_ratio)
        options = model_options(model, model_opts, flags=model_flags_given(model_flags))
        if mu is not None and model in models_with_option("mu"):
            # --mu is the impact restitution whatever the model: where the model has its
            # own option mu (the isolated base derives one by default), --mu imposes it
            if "mu" in options and options["mu"] != block.mu:
                raise ParameterError(f"mu given twice: --mu {mu} and --option mu="
                                     f"{options['mu']:g}; give one")
            options["mu"] = block.mu
        _linear_option(model, linear, options)
        th0 = quantity(theta0, "angle", "theta0", default_unit="rad")
        om0 = number(omega0, "omega0", ("rad/s", "1/s"))
        run = _run_settings(dt_out, max_free_time, sim_dur)
        return cls(block=block, block_info=binfo, motion=mot, motion_info=mdesc,
                   floor_info=fdesc, duration=sim_dur, model=model, options=options,
                   linear=bool(options.get("linear", False)), theta0=th0, omega0=om0,
                   run=run, out=out, as_json=as_json)

    @classmethod
    def _from_options_3d(cls, *, specimen, params_set, width, height, alpha, p, mu, model,
                         model_opts, motion, freq, amp, tp, motion_params, duration,
                         max_free_time, record, vertical, vertical_factor, units, dt,
                         earthquake, load_factor, theta0, omega0, linear, dt_out, building,
                         storeys, building_period, building_damping, building_params, floor,
                         height_ratio, out, as_json, box, cylinder, pair, model_flags,
                         html=None, animate=False):
        """The request of a 3-D model (:mod:`rocking.cli.simulate3d`)."""
        simulate3d.check_viewer_flags(out, html, animate)
        for flag, v in (("theta0", theta0), ("omega0", omega0)):
            if v is not None:
                raise ParameterError(f"{flag}: --model {model} has no planar angle; give its "
                                     "initial tilt as --tilt0 (rad)")
        body, binfo, direction = simulate3d.make_body(specimen, params_set, width, height,
                                                      alpha, p, mu, box, cylinder)
        options = model_options(model, model_opts, flags=model_flags_given(model_flags))
        _linear_option(model, linear, options)
        if direction is not None:
            if "direction" in options:
                raise ParameterError("option direction given twice (--direction and "
                                     "--option direction=...)")
            options["direction"] = simulate3d.direction_deg(body, direction)
            binfo["direction"] = str(direction)
            validate_options(model, options)
        simulate3d.check_orientation(options, bool(pair), direction)
        if pair:
            for flag, v in (("record", record), ("motion", motion),
                            ("earthquake", earthquake)):
                if v is not None:
                    raise ParameterError(f"{flag}: --pair is the motion; --{flag} cannot be "
                                         "combined with it")
            for flag, v in (("freq", freq), ("amp", amp), ("tp", tp),
                            ("param", motion_params or None)):
                if v is not None:
                    raise ParameterError(f"{flag} does not apply to --pair")
            if building is not None:
                raise ParameterError("building: --building takes one horizontal ground motion "
                                     "(--record), not --pair")
            mot, mdesc = simulate3d.make_pair(pair, vertical, vertical_factor, units, dt,
                                              load_factor)
            sim_dur = positive_quantity(duration, "time", "duration", "s", "s")
            fdesc = None
        else:
            mot, mdesc, sim_dur = make_motion(motion, freq, amp, tp, duration, record, units,
                                              dt, load_factor, earthquake, vertical,
                                              vertical_factor, params=motion_params)
            mot, fdesc = on_floor(mot, {"kind": building, "storeys": storeys,
                                        "period": building_period,
                                        "damping": building_damping,
                                        "param": building_params}, floor, height_ratio)
        run = _run_settings(dt_out, max_free_time, sim_dur)
        return cls(block=body, block_info=binfo, motion=mot, motion_info=mdesc,
                   floor_info=fdesc, duration=sim_dur, model=model, options=options,
                   linear=False, theta0=None, omega0=None, run=run, out=out,
                   as_json=as_json, html=html is not False, animate=bool(animate))

    @property
    def is_3d(self) -> bool:
        """A 3-D model's request (``rigid3d``)."""
        return is_3d(self.model)

    def simulate(self):
        """The response of :func:`rocking.models.simulate`."""
        from ..models import simulate  # lazy: the models import numba

        return simulate(self.block, self.motion, model=self.model, duration=self.duration,
                        theta0=0.0 if self.theta0 is None else self.theta0,
                        omega0=0.0 if self.omega0 is None else self.omega0,
                        **self.run, **self.options)


def _summary(req: SimulateRequest, resp) -> dict:
    """summary.json: the response's summary with the inputs of the run."""
    block, binfo, fdesc = req.block, req.block_info, req.floor_info
    summary = resp.summary()
    blk = (simulate3d.summary_block(block, binfo) if req.is_3d else
           {**binfo, "alpha": block.alpha, "p": block.p, "mu": block.mu, "R": block.R,
            "name": block.name})
    inputs = ({"block": blk, "model": req.model, "motion": req.motion_info} if req.is_3d
              else {"block": blk, "model": req.model, "linear": bool(req.linear),
                    "motion": req.motion_info, "theta0": req.theta0 or 0.0,
                    "omega0": req.omega0 or 0.0})  # a 3-D body: tilt0 among the options
    if req.options:
        inputs["options"] = req.options
    inputs.update(req.run)
    summary["specimen"] = binfo.get("specimen")
    summary["params"] = binfo.get("params")
    if fdesc is not None:  # where the block stands, also among the inputs
        floor_keys = {k: v for k, v in fdesc.items() if k != "where"}
        summary.update(floor_keys)
        inputs.update(floor_keys)
    summary["inputs"] = inputs
    return summary


def _write_outputs(req: SimulateRequest, resp, summary: dict) -> None:
    """OUT: response.csv, summary.json and theta.png."""
    folder = Path(req.out)
    folder.mkdir(parents=True, exist_ok=True)
    resp.to_csv(folder / "response.csv")
    atomic_write(folder / "summary.json",
                 json.dumps(summary, indent=2, default=json_default))
    if req.is_3d:
        mdesc = req.motion_info
        what = (simulate3d.motion_title(mdesc, req.options) if mdesc.get("type") == "pair"
                else f"{_motion_title(mdesc)}, direction "
                     f"{req.options.get('direction', 0.0):g} deg")
        title = f"{req.block.name or 'body'}: {what}"
        simulate3d.write_plots(resp, title, folder)
        plots = ", ".join(simulate3d.PLOTS + simulate3d.write_viewer(
            resp, title, folder, html=req.html, gif=req.animate))
    else:
        _theta_png(resp, req.block, req.motion_info, folder / "theta.png", req.floor_info)
        plots = "theta.png"
    if not req.as_json:
        click.echo(f"wrote       {folder / 'response.csv'}, summary.json, {plots}")


# ----------------------------------------------------------------------------- command
@click.command("simulate", cls=ModelFlagsCommand, flag_help=FLAG_HELP,
               option_flags={"linear": "--linear", "direction": "--direction"},
               context_settings=CONTEXT)
@block_options(classical=True)
@click.option("--box", nargs=3, metavar="LX LY LZ", default=None,
              help="rigid3d: a box (m; LZ vertical; --density or --mass, default "
                   "1000 kg/m^3).")
@click.option("--cylinder", nargs=2, metavar="R H", default=None,
              help="rigid3d: a circular cylinder of radius R and height H (m).")
@click.option("--pair", nargs=2, metavar="H1 H2", default=None,
              help="rigid3d: two horizontal components (files or built-in names, e.g. "
                   "Rinaldi228 Rinaldi318; --vertical UP too), oriented by --heading.")
@click.option("--model", type=ModelChoice(), default="housner", show_default=True,
              help="Rocking model (see 'rocking models').")
@click.option("--option", "model_opts", multiple=True, metavar="KEY=VALUE",
              help="A model option, repeatable (e.g. --option rtol=1e-9); "
                   "'rocking models' lists them.")
@click.option("--motion", type=MotionChoice(),
              help="Base motion, a kind of 'rocking motions' (--record FILE implies record).")
@click.option("--freq", metavar="F",
              help="Frequency (Hz): sine, hanning, mavroeidis_papageorgiou; ricker: peak "
                   "frequency.")
@click.option("--amp", metavar="AMP",
              help="sine/hanning: table displacement with a unit (5mm) or peak acceleration "
                   "(0.3g); pulses: peak acceleration (0.3g, 2.8m/s2).")
@click.option("--tp", metavar="T", help="Pulse period/length (s); ricker: 1 / peak frequency.")
@click.option("--param", "motion_params", multiple=True, metavar="KEY=VALUE",
              help="A parameter of the motion kind, repeatable (e.g. --param gamma=2 --param "
                   "nu=0); 'rocking motions KIND' lists them.")
@click.option("--duration", metavar="T",
              help="Simulated time (s), exactly. Default: the motion, then free motion "
                   "until the block is at rest or has overturned (at most --max-free-time "
                   "more). Required for sine and hanning (the motion's length).")
@click.option("--max-free-time", "max_free_time", metavar="T",
              help="Cap of the free motion after the ground motion ends (s; default 60).")
@click.option("--record", metavar="FILE",
              help="Accelerogram file (.AT2, CSV or columns), or a built-in record's name "
                   "(e.g. Rinaldi228).")
@click.option("--vertical", metavar="FILE",
              help="Vertical accelerogram (positive upwards; same --units and --dt), or a "
                   "built-in record's name (e.g. RinaldiUP).")
@click.option("--vertical-factor", "vertical_factor", metavar="F",
              help="Scale of the vertical component (default: the load factor).")
@click.option("--units", metavar="U", help=f"Units of the record: {UNITS_HELP} (default g).")
@click.option("--dt", metavar="DT", help="Time step of a one-column record (s).")
@click.option("--earthquake", metavar="N",
              help="One of the paper's 30 synthetic EC8 records (1-30), see 'rocking motion'.")
@click.option("--load-factor", metavar="F", help="Scale the motion (default 1).")
@click.option("--theta0", metavar="ANGLE", help="Initial angle (bare number: rad; or 2deg).")
@click.option("--omega0", metavar="W", help="Initial angular velocity (rad/s).")
@click.option("--linear", is_flag=True, help="Small-angle (linearised) equation of motion.")
@click.option("--dt-out", metavar="DT", help="Output time step (s; default 0.002).")
@building_options("Put the block on a floor of a building of this kind ('rocking "
                  "buildings'); the motion is then the ground motion.")
@click.option("--floor", metavar="K", help="The floor the block stands on (0 the ground).")
@click.option("--height-ratio", "height_ratio", metavar="X",
              help="Instead of --floor: the height z/H in [0, 1] (a continuous building).")
@click.option("--out", type=click.Path(file_okay=False),
              help="Write response.csv, summary.json and theta.png to this folder "
                   "(rigid3d: three plots and the page motion.html).")
@click.option("--html/--no-html", "html", default=None,
              help="rigid3d with --out: write motion.html, a self-contained page that "
                   "plays the motion in a browser (default: on; about 0.7 MB).")
@click.option("--animate", is_flag=True,
              help="rigid3d with --out: also write motion.gif, an animation of the body "
                   "(about 2 s per 5 s of motion).")
@click.option("--json", "as_json", is_flag=True,
              help="Print the summary (summary.json's content, SI units) as JSON.")
@force_option
def simulate_cmd(**options):
    """Simulate one block under one base motion (on a floor of a building: --building)."""
    req = SimulateRequest.from_options(**options)
    resp = req.simulate()
    summary = _summary(req, resp)
    outputs = row_outputs(model_classes()[req.model], resp.info)
    if outputs:
        summary["row_outputs"] = outputs

    if not resp.settled and not resp.lifted_off:
        fix = "extend --duration" if req.duration is not None else "raise --max-free-time"
        click.echo(f"warning: still rocking at the end (t = {resp.duration:.4g} s): the "
                   f"outcome may change; {fix}", err=True)
    if req.as_json:
        click.echo(json.dumps(summary, indent=2, default=json_default))
    elif req.is_3d:
        width = max((len(k) for k in outputs), default=0) + 2
        click.echo("\n".join(
            simulate3d.text_lines(resp, req.block, req.model, req.motion_info, req.options,
                                  req.floor_info)
            + [f"{k:<{width}}{row_output_text(d)}" for k, d in outputs.items()]))
    else:
        click.echo("\n".join(_text_lines(resp, req.block, req.model, req.linear,
                                          req.motion_info, req.floor_info, outputs)))
    if req.out is not None:
        _write_outputs(req, resp, summary)


def row_outputs(cls, info: dict) -> dict:
    """The model's row outputs (:attr:`rocking.models.base.Model.row_outputs`) of one run:
    ``{name: {"value", "unit", "flag", "help"}}`` (a NaN value as None: never reached)."""
    out = {}
    for r in getattr(cls, "row_outputs", ()):
        v = info.get(r.name)
        if v is not None and not r.flag:
            v = float(v)
            v = v if math.isfinite(v) else None
        out[r.name] = {"value": bool(v) if r.flag and v is not None else v, "unit": r.unit,
                       "flag": bool(r.flag), "help": r.help}
    return out


def row_output_text(d: dict) -> str:
    """One row output as text: ``yes: <help>``/``no`` (a flag), ``-`` (not reached), else the
    value with its unit (an acceleration also in g; a ratio with its help)."""
    v = d["value"]
    if d["flag"]:
        return "-" if v is None else (f"yes: {d['help']}" if v else "no")
    if v is None:
        return "-"
    if d["unit"] == "m/s^2":
        return f"{v:.6g} m/s^2 ({v / G:.4g} g)"
    if not d["unit"]:
        return f"{v:.6g} ({d['help']})"
    return f"{v:.6g} {d['unit']}"


def _of_alpha(resp, block) -> str:
    """max ``|theta|`` over alpha; for an asymmetric block, each side's peak over its own
    alpha (the histories' peaks)."""
    th = resp.max_abs_theta
    if block.symmetric or resp.theta is None or len(resp.theta) == 0:
        return f"{th / block.alpha:.3g} alpha"
    theta = np.asarray(resp.theta, dtype=float)
    tp, tm = max(float(np.nanmax(theta)), 0.0), max(float(-np.nanmin(theta)), 0.0)
    return (f"{tp / block.alpha_plus:.3g} alpha+ on side +, {tm / block.alpha_minus:.3g} "
            "alpha- on side -")


def _text_lines(resp, block, model: str, linear: bool, mdesc: dict, fdesc, outputs: dict):
    """The text report of one run: block, motion, max angle, outcome, the model's row
    outputs."""
    th = resp.max_abs_theta
    on = "" if fdesc is None else (
        f" on {fdesc['where']} of the {fdesc['building']['name']} (peak floor acceleration "
        f"{fdesc['floor_pga'] / G:.3g} g)")
    lines = [f"block       {block!r}",
             f"motion      {mdesc.get('repr', 'free rocking')}{on}  [{model}"
             f"{', linear' if linear else ''}]",
             (f"max |theta| {math.degrees(th):.4g} deg ({th:.6g} rad, "
              f"{_of_alpha(resp, block)})" if th is not None
              else f"states      {', '.join(resp.state_names)} (no planar angle)"),
             f"overturned  yes, at t = {resp.overturn_time:.4g} s" if resp.overturned
             else "overturned  no"]
    up = "-" if math.isnan(resp.uplift_time) else f"t = {resp.uplift_time:.4g} s"
    lines += [f"uplift      {up}"] + ([f"impacts     {resp.n_impacts}"]
                                      if "n_impacts" in resp.outputs else [])
    if "vertical" in mdesc:
        lo = ("-" if not resp.lifted_off else f"yes, at t = {resp.lift_off_time:.4g} s: "
              "g + a_v <= 0, the block leaves the ground and the run stops there")
        lines += [f"vertical    {mdesc['vertical']} x {mdesc['vertical_factor']:g} "
                  f"(peak {mdesc['pga_vertical'] / G:.3g} g)", f"lift-off    {lo}"]
    width = max((len(k) for k in outputs), default=0) + 2
    lines += [f"{k:<{width}}{row_output_text(d)}" for k, d in outputs.items()]
    return lines


# ----------------------------------------------------------------------------- figure
def _motion_title(d: dict) -> str:
    """A short description of the motion for plot titles."""
    kind = d.get("type")
    lf = d.get("load_factor", 1.0)
    tail = f", load factor {lf:g}" if lf != 1.0 else ""
    if kind in HARMONIC:
        return (f"{kind} {d['freq']:g} Hz, {1e3 * d['amplitude']:.3g} mm "
                f"({d['acc_amplitude'] / G:.3g} g){tail}")
    if kind == "ricker":
        return f"Ricker pulse {d['amplitude'] / G:.3g} g, fp {d['fp']:g} Hz{tail}"
    if kind == "mavroeidis_papageorgiou":
        return (f"Mavroeidis-Papageorgiou pulse {d['amplitude'] / G:.3g} g, fp {d['fp']:g} Hz, "
                f"gamma {d['gamma']:g}{tail}")
    if kind in PULSES:
        return f"{kind.replace('_', '-')} pulse {d['amplitude'] / G:.3g} g, {d['tp']:g} s{tail}"
    if kind == "record" and "vertical" in d:
        vf = d.get("vertical_factor", lf)
        tail = (f", load factor {lf:g}" + (f" ({vf:g} vertical)" if vf != lf else "")
                if lf != 1.0 or vf != 1.0 else "")
        return (f"record {Path(d['file']).name} + vertical {Path(d['vertical']).name} "
                f"(PGA {d['pga'] / G:.3g} g, {d['pga_vertical'] / G:.3g} g vertical){tail}")
    if kind == "record":
        return f"record {Path(d['file']).name} (PGA {d['pga'] / G:.3g} g){tail}"
    if kind == "earthquake":
        return f"earthquake {d['number']} (PGA {d['pga'] / G:.3g} g){tail}"
    if kind not in (None, "free"):  # a kind given by --param: its parameters
        shown = ", ".join(f"{k} {v}" for k, v in d.items()
                          if k not in ("type", "pga", "load_factor", "repr"))
        return f"{kind} {shown} (PGA {d['pga'] / G:.3g} g){tail}"
    return "free rocking"


def _theta_png(resp, block, mdesc, path, fdesc=None):
    from ..plot import figure, plot_response, save_figure  # lazy: matplotlib

    fig, ax = figure()
    title = f"{block.name or 'block'}: {_motion_title(mdesc)}"
    if fdesc is not None:
        title += f", {fdesc['where']} of a {fdesc['building']['name']}"
    plot_response(resp, ax=ax, show_alpha=True, title=title)
    save_figure(fig, path)


__all__ = ["simulate_cmd", "make_motion", "model_options", "flag_options", "row_outputs",
           "row_output_text", "FLAG_READERS", "FLAG_HELP", "MOTION_CHOICES", "MotionChoice",
           "make_building", "on_floor", "BUILDING_FLAGS"]
