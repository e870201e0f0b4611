"""The motion catalog: one entry per kind of base motion, with its declared parameters.

Every way of making a motion from names and numbers -- ``rocking simulate --motion``,
a campaign spec's ``[motions]`` table, ``rocking motions`` (the list), the README's table
of spec keys -- goes through :data:`KINDS`. An entry (:class:`MotionKind`) has one name,
a dataclass of parameters declared with :func:`rocking.options.option` (default, help, SI
unit, range; one unit per parameter name across the package: ``amplitude`` is always a
peak acceleration in m/s^2, ``displacement`` a table displacement in m, ``frequency``
Hz, ``period`` and ``duration`` s) and a function that makes the motion::

    >>> from rocking.motions.catalog import build
    >>> build("one_sine", amplitude="0.3g", period=0.5)
    OneSine(amplitude=2.941995, length=0.5, t0=0.0, duration=10.0, scale=1.0)

Adding a motion kind is one entry here (and its class): the CLI, the campaign spec, the
analysis and the docs take it from the catalog (``docs/architecture.md``, "How to add a
motion kind").

Old spellings (``one-sine``, ``mp``) still resolve, with a :class:`DeprecationWarning`
(:func:`kind`).
"""

from __future__ import annotations

import dataclasses
import glob as _glob
import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ..errors import ParameterError
from ..options import REQUIRED, Options, option
from ..units import ACCELERATION
from .base import Motion

MAX_DURATION = 1e4
"""Longest motion the catalog makes (s): ``duration``, or ``cycles / frequency`` of a
sine. The longest strong-motion records are a few hundred seconds (long-period records of
the 2011 Tohoku earthquake: about 300-600 s); 1e4 s (2.8 h) is 15 times more, while a sine
of 1e9 s would run for days and a stochastic record of 1e9 s would allocate 745 GB."""
MAX_SAMPLES = 10 ** 7
"""Most samples of one stochastic record (``duration / dt + 1``): 80 MB per array."""


@dataclass(frozen=True)
class Context:
    """What making a motion may need besides its parameters: the folder that relative
    record paths start from, and the seed of generated records."""

    base_dir: Path = Path(".")
    seed: int = 0

    def path(self, p) -> Path:
        q = Path(p).expanduser()
        return q if q.is_absolute() else Path(self.base_dir) / q


def _amplitude(help_: str = "peak ground acceleration", required: bool = True):
    return option(REQUIRED, help=help_, unit="m/s^2", lo=0.0, lo_open=False,
                  quantity="acceleration", required=required)


def _duration(help_: str, required: bool = False):
    return option(REQUIRED, help=help_, unit="s", lo=0.0, hi=MAX_DURATION,
                  quantity="time", required=required)


def _frequency(help_: str, required: bool = True):
    return option(REQUIRED, help=help_, unit="Hz", lo=0.0, quantity="frequency",
                  required=required)


def _period(help_: str, required: bool = True):
    return option(REQUIRED, help=help_, unit="s", lo=0.0, hi=MAX_DURATION, quantity="time",
                  required=required)


def _one_of(obj, names: tuple[str, ...], what: str) -> str:
    given = [n for n in names if getattr(obj, n) is not None]
    if len(given) != 1:
        raise ParameterError(f"{' or '.join(names)}: give exactly one ({what}); got "
                             f"{', '.join(given) or 'neither'}")
    return given[0]


# ------------------------------------------------------------------------------- harmonic
@dataclass(frozen=True)
class HarmonicParams(Options):
    frequency: float = _frequency("frequency of the table motion")
    amplitude: float | None = _amplitude("peak table acceleration (or give displacement)",
                                         required=False)
    displacement: float | None = option(REQUIRED, help="table displacement amplitude (or give "
                                        "amplitude)", unit="m", lo=0.0, lo_open=False,
                                        quantity="length")
    duration: float | None = _duration("length of the table motion (or give cycles)")
    cycles: float | None = option(REQUIRED, help="number of cycles (duration = cycles / "
                                  "frequency)", lo=0.0)
    phase: float = option(0.0, help="phase of the sine (harmonic sine only)", unit="rad")

    def check(self):
        _one_of(self, ("amplitude", "displacement"), "the size of the motion")
        _one_of(self, ("duration", "cycles"), "the length of the motion")
        if self.duration is None and not self.cycles / self.frequency <= MAX_DURATION:
            raise ParameterError(f"cycles: {self.cycles:g} cycles at {self.frequency:g} Hz "
                                 f"last {self.cycles / self.frequency:g} s; at most "
                                 f"{MAX_DURATION:g} s")

    @property
    def length(self) -> float:
        return self.duration if self.duration is not None else self.cycles / self.frequency


def _sine(p: HarmonicParams, ctx: Context) -> Motion:
    from .harmonic import Sine
    if p.amplitude is not None:
        return Sine.from_acceleration(p.frequency, p.amplitude, p.length, phase=p.phase)
    return Sine(p.frequency, p.displacement, p.length, phase=p.phase)


def _hanning(p: HarmonicParams, ctx: Context) -> Motion:
    from .harmonic import HanningSine
    if p.phase != 0.0:
        raise ParameterError("phase applies to kind 'sine' only")
    x = (p.displacement if p.amplitude is None
         else p.amplitude / (2 * math.pi * p.frequency) ** 2)
    return HanningSine(p.frequency, x, p.length)


# --------------------------------------------------------------------------------- pulses
@dataclass(frozen=True)
class PulseParams(Options):
    amplitude: float = _amplitude()
    period: float = _period("pulse period Tp (for half_sine and rectangular: the pulse's "
                            "length)")
    t0: float = option(0.0, help="start time of the pulse", unit="s", lo=0.0, lo_open=False,
                       quantity="time")
    duration: float | None = _duration("simulation window (default t0 + max(10 s, 5 Tp))")


def _pulse(cls_name: str):
    def make(p: PulseParams, ctx: Context) -> Motion:
        from . import pulses
        return getattr(pulses, cls_name)(p.amplitude, p.period, t0=p.t0, duration=p.duration)
    return make


@dataclass(frozen=True)
class RickerParams(Options):
    amplitude: float = _amplitude()
    frequency: float | None = _frequency("peak frequency fp (or give period)", required=False)
    period: float | None = _period("1 / fp (or give frequency)", required=False)
    tc: float | None = option(REQUIRED, help="centre time (default such that the pulse "
                              "starts at rest)", unit="s", lo=0.0, lo_open=False,
                              quantity="time")
    duration: float | None = _duration("simulation window (default: the pulse and 10 s)")

    def check(self):
        _one_of(self, ("frequency", "period"), "the peak frequency")


def _ricker(p: RickerParams, ctx: Context) -> Motion:
    from .pulses import Ricker
    fp = p.frequency if p.frequency is not None else 1.0 / p.period
    return Ricker(p.amplitude, fp, tc=p.tc, duration=p.duration)


@dataclass(frozen=True)
class MPParams(Options):
    amplitude: float = _amplitude("peak ground acceleration of the pulse")
    frequency: float = _frequency("prevailing frequency fp")
    gamma: float = option(REQUIRED, help="oscillatory character (> 1)", lo=1.0,
                          required=True)
    nu: float = option(REQUIRED, help="phase", unit="rad", quantity="angle", required=True)
    t0: float | None = option(REQUIRED, help="centre of the envelope (default gamma / "
                              "(2 fp))", unit="s", lo=0.0, lo_open=False, quantity="time")
    duration: float | None = _duration("simulation window")


def _mp(p: MPParams, ctx: Context) -> Motion:
    from .pulses import MavroeidisPapageorgiou
    return MavroeidisPapageorgiou(p.amplitude, p.frequency, p.gamma, p.nu, t0=p.t0,
                                  duration=p.duration)


# -------------------------------------------------------------------------------- records
_UNITS = tuple(ACCELERATION)


@dataclass(frozen=True)
class RecordParams(Options):
    file: str = option(REQUIRED, help="record file (PEER .AT2, ESM, COSMOS V2, K-NET/KiK-net, "
                       "CSV or columns, recognised by content; in a spec "
                       "relative to the spec, and a list or glob gives one motion each)",
                       kind=str, required=True)
    units: str = option("g", help="unit of the file's accelerations", choices=_UNITS)
    dt: float | None = option(REQUIRED, help="time step of a one-column file", unit="s",
                              lo=0.0, quantity="time")


def _record(p: RecordParams, ctx: Context) -> Motion:
    from .records import Record
    return Record.from_file(ctx.path(p.file), units=p.units, dt=p.dt)


def _builtin_names() -> tuple[str, ...]:
    from .io import builtin_records
    return tuple(builtin_records(three_component=True))


@dataclass(frozen=True)
class BuiltinParams(Options):
    name: str = option(REQUIRED, help="a record shipped with the package "
                       "(rocking.motions.builtin_records)", kind=str, required=True)

    def check(self):
        if self.name not in _builtin_names():
            raise ParameterError(f"name must be one of {', '.join(_builtin_names())}; got "
                                 f"{self.name!r}")


def _every_builtin() -> tuple[str, ...]:
    """The horizontal records shipped with the package (not the three-component sets)."""
    from .io import builtin_records
    return tuple(builtin_records())


def _builtin(p: BuiltinParams, ctx: Context) -> Motion:
    from .records import load_builtin
    return load_builtin(p.name)


@dataclass(frozen=True)
class EarthquakeParams(Options):
    number: int = option(REQUIRED, help="the paper's spectrum-compatible earthquake "
                         "(rocking.motions.seed_earthquakes)", lo=1, hi=30, lo_open=False,
                         kind=int, required=True)


def _earthquake(p: EarthquakeParams, ctx: Context) -> Motion:
    from .synthetic import paper_earthquake
    return paper_earthquake(p.number)


@dataclass(frozen=True)
class EC8EarthquakeParams(Options):
    number: int = option(REQUIRED, help="record of the set (rocking.motions.ec8_earthquakes)",
                         lo=1, hi=10, lo_open=False, kind=int, required=True)
    ground: str = option(REQUIRED, help="EN 1998-1 ground type of the set's spectrum",
                         choices=("A", "B", "C", "D", "E"), kind=str, required=True)
    spectrum_type: int = option(1, help="EN 1998-1 spectrum type: 1 (large earthquakes) "
                                "or 2 (magnitude below about 5.5)", choices=(1, 2), kind=int)


def _ec8_earthquake(p: EC8EarthquakeParams, ctx: Context) -> Motion:
    from .ec8_records import ec8_earthquake
    return ec8_earthquake(p.number, p.ground, p.spectrum_type)


def _set_names() -> tuple[str, ...]:
    from .io import builtin_sets
    return tuple(builtin_sets())


@dataclass(frozen=True)
class GroundParams(Options):
    set: str | None = option(REQUIRED, help="a three-component set shipped with the package "
                             "(rocking.motions.builtin_sets; or give file and vertical_file)",
                             kind=str)
    horizontal: int = option(1, help="which horizontal component of the set", lo=1, hi=2,
                             lo_open=False, kind=int)
    file: str | None = option(REQUIRED, help="horizontal record file (with vertical_file)",
                              kind=str)
    vertical_file: str | None = option(REQUIRED, help="vertical record file (positive "
                                       "upwards)", kind=str)
    units: str = option("g", help="unit of the files' accelerations", choices=_UNITS)
    dt: float | None = option(REQUIRED, help="time step of one-column files", unit="s",
                              lo=0.0, quantity="time")
    vertical_factor: float = option(1.0, help="the vertical component times this (relative "
                                    "to the horizontal one)", lo=0.0, lo_open=False)

    def check(self):
        if (self.set is None) == (self.file is None):
            raise ParameterError("set or file: give exactly one (a built-in set, or a "
                                 "horizontal file with its vertical_file)")
        if self.set is not None:
            if self.set not in _set_names():
                raise ParameterError(f"set must be one of {', '.join(_set_names())}; got "
                                     f"{self.set!r}")
            if self.vertical_file is not None:
                raise ParameterError("vertical_file applies with file, not with set")
        elif self.vertical_file is None:
            raise ParameterError("vertical_file is required with file (the vertical record)")
        elif self.horizontal != 1:
            raise ParameterError("horizontal applies with set only")


def _ground(p: GroundParams, ctx: Context) -> Motion:
    from .ground import GroundMotion
    if p.set is not None:
        m = GroundMotion.builtin(p.set, horizontal=p.horizontal)
    else:
        m = GroundMotion.from_files(ctx.path(p.file), ctx.path(p.vertical_file),
                                    units=p.units, dt=p.dt)
    return m if p.vertical_factor == 1.0 else m.scaled(1.0, vertical=p.vertical_factor)


def _stochastic_defaults() -> dict:
    from .stochastic import DEFAULTS
    return DEFAULTS


@dataclass(frozen=True)
class StochasticParams(Options):
    index: int = option(0, help="record number: records are a function of (seed, index); "
                        "in a spec, n = N gives indices 0 .. N-1", lo=0, lo_open=False,
                        kind=int)
    Ia: float | None = option(REQUIRED, help="expected Arias intensity (default 0.5)",
                              unit="m/s", lo=0.0)
    D5_95: float | None = option(REQUIRED, help="significant duration 5-95 % (default 10)",
                                 unit="s", lo=0.0)
    t_mid: float | None = option(REQUIRED, help="middle of the strong motion (default 6)",
                                 unit="s", lo=0.0)
    omega_mid: float | None = option(REQUIRED, help="filter frequency at t_mid (default "
                                     "2 pi 5)", unit="rad/s", lo=0.0)
    omega_prime: float | None = option(REQUIRED, help="rate of change of the filter "
                                       "frequency (default -2 pi 0.1)", unit="rad/s^2")
    zeta_f: float | None = option(REQUIRED, help="filter damping ratio (default 0.3)",
                                  lo=0.0, hi=1.0, hi_open=True)
    omega_c: float | None = option(REQUIRED, help="high-pass corner (default 2 pi 0.1)",
                                   unit="rad/s", lo=0.0, lo_open=False)
    dt: float | None = option(REQUIRED, help="time step (default 0.01)", unit="s", lo=0.0,
                              quantity="time")
    duration: float | None = _duration("record length (default: until the modulating "
                                       "function has decayed)")

    def generator(self) -> dict:
        """The keyword arguments of :func:`rocking.motions.stochastic_records`."""
        return {k: v for k, v in dataclasses.asdict(self).items()
                if k != "index" and v is not None}

    def check(self):
        from .stochastic import HP_DECAY, modulating_parameters, record_model
        kw = {**_stochastic_defaults(), **self.generator()}
        if kw.get("duration") is not None:
            length, key = kw["duration"], "duration"
        else:  # the generator's default length (rocking.motions.stochastic.record_model)
            tail = modulating_parameters(kw["Ia"], kw["D5_95"], kw["t_mid"])["t_tail"]
            hp = HP_DECAY / kw["omega_c"] if kw["omega_c"] > 0 else 0.0
            length, key = tail + hp, "dt"
            if not length <= MAX_DURATION:
                raise ParameterError(
                    f"{'omega_c' if hp > tail else 't_mid'}: the records would last "
                    f"{length:g} s (t_tail {tail:g} s + {HP_DECAY:g} / omega_c); at most "
                    f"{MAX_DURATION:g} s (or give duration)")
        if not length / kw["dt"] + 1 <= MAX_SAMPLES:
            raise ParameterError(f"{key}: a record of {length:g} s at dt = {kw['dt']:g} s "
                                 f"would have {length / kw['dt']:.3g} samples; at most "
                                 f"{MAX_SAMPLES:.0e} (raise dt or shorten duration)")
        record_model(**kw)


def _stochastic(p: StochasticParams, ctx: Context) -> Motion:
    from .stochastic import stochastic_records
    return stochastic_records(1, seed=ctx.seed, start=p.index, **p.generator())[0]


def _stochastic_many(ps: list, ctx: Context) -> list:
    """Records of consecutive indices in one call each (same records as one by one)."""
    from .stochastic import stochastic_records
    out, i = [], 0
    while i < len(ps):
        j = i
        while j + 1 < len(ps) and ps[j + 1].index == ps[j].index + 1 \
                and ps[j + 1].generator() == ps[i].generator():
            j += 1
        out += stochastic_records(j - i + 1, seed=ctx.seed, start=ps[i].index,
                                  **ps[i].generator())
        i = j + 1
    return out


# -------------------------------------------------------------------------------- catalog
@dataclass(frozen=True)
class MotionKind:
    """One kind of base motion (see the module docstring)."""

    name: str
    summary: str
    Params: type[Options]
    make: Callable[[Options, Context], Motion]
    label: Callable[[Options], str]
    """The motion's id in tables and stores (``"sine:2Hz"``, ``"seed:20"``)."""
    sweep: tuple[str, ...] = ()
    """Parameters that a spec may give as a list or grid: one motion per value."""
    aliases: tuple[str, ...] = ()
    """Old names, still accepted with a DeprecationWarning."""
    vertical: bool = False
    """The motions have a vertical component (``lift_off_time`` is meaningful)."""
    make_many: Callable | None = None
    """Optional: make several motions in one call (the same motions as one by one)."""
    every: Callable[[], tuple] | None = None
    """Optional: the values of the swept parameter that a spec which omits it runs (every
    record of a finite set: the 30 earthquakes, the shipped records)."""
    files: tuple[str, ...] = ()
    """Parameters that are file paths (a spec reads them when checked, and hashes their
    contents into the spec hash)."""

    def params(self, **values) -> Options:
        """The checked parameters (unknown names refused)."""
        self.Params.unknown(values, f"motion kind {self.name!r}")
        return self.Params(**values)

    def build(self, ctx: Context | None = None, /, **values) -> Motion:
        """The motion of these parameters."""
        return self.make(self.params(**values), ctx or Context())

    def describe(self) -> list[dict]:
        """One dict per parameter (name, default, unit, range, help, required)."""
        return self.Params.describe()


def _fmt(x) -> str:
    return f"{x:g}"


def _pulse_kind(name: str, cls_name: str, what: str, alias: str) -> MotionKind:
    return MotionKind(name, what, PulseParams, _pulse(cls_name),
                      lambda p, n=name: f"{n}:{_fmt(p.period)}s", sweep=("period",),
                      aliases=(alias,))


def _ricker_label(p: RickerParams) -> str:
    return (f"ricker:{_fmt(p.period)}s" if p.period is not None
            else f"ricker:{_fmt(p.frequency)}Hz")


KINDS: dict[str, MotionKind] = {k.name: k for k in (
    MotionKind("sine", "harmonic table motion (rocking.motions.Sine)", HarmonicParams, _sine,
               lambda p: f"sine:{_fmt(p.frequency)}Hz", sweep=("frequency",)),
    MotionKind("hanning", "sine under a Hann window (rocking.motions.HanningSine)",
               HarmonicParams, _hanning, lambda p: f"hanning:{_fmt(p.frequency)}Hz",
               sweep=("frequency",)),
    _pulse_kind("one_sine", "OneSine", "one full sine cycle (rocking.motions.OneSine)",
                "one-sine"),
    _pulse_kind("one_cosine", "OneCosine", "one full cosine cycle (rocking.motions.OneCosine)",
                "one-cosine"),
    _pulse_kind("half_sine", "HalfSine", "half a sine cycle (rocking.motions.HalfSine)",
                "half-sine"),
    _pulse_kind("rectangular", "Rectangular", "constant acceleration for one period "
                "(rocking.motions.Rectangular)", "rect"),
    MotionKind("ricker", "Ricker wavelet (rocking.motions.Ricker)", RickerParams, _ricker,
               _ricker_label, sweep=("period", "frequency")),
    MotionKind("mavroeidis_papageorgiou", "near-fault pulse of Mavroeidis and Papageorgiou "
               "2003 (rocking.motions.MavroeidisPapageorgiou)", MPParams, _mp,
               lambda p: f"mavroeidis_papageorgiou:{_fmt(p.frequency)}Hz",
               sweep=("frequency",), aliases=("mp",)),
    MotionKind("record", "a recorded accelerogram from a file (rocking.motions.Record)",
               RecordParams, _record, lambda p: p.file, sweep=("file",), files=("file",)),
    MotionKind("builtin", "a record shipped with the package (rocking.motions.load_builtin)",
               BuiltinParams, _builtin, lambda p: p.name, sweep=("name",),
               every=_every_builtin),
    MotionKind("earthquake", "the paper's spectrum-compatible earthquakes "
               "(rocking.motions.paper_earthquake)", EarthquakeParams, _earthquake,
               lambda p: f"seed:{p.number:02d}", sweep=("number",),
               every=lambda: tuple(range(1, 31))),
    MotionKind("ec8_earthquake", "synthetic earthquakes compatible with EN 1998-1 on a "
               "ground type, to 4 s (rocking.motions.ec8_earthquakes)", EC8EarthquakeParams,
               _ec8_earthquake,
               lambda p: f"ec8-{p.spectrum_type}{p.ground}:{p.number:02d}", sweep=("number",),
               every=lambda: tuple(range(1, 11))),
    MotionKind("ground_motion", "horizontal and vertical components "
               "(rocking.motions.GroundMotion)", GroundParams, _ground,
               lambda p: (f"{p.set}:h{p.horizontal}" if p.set is not None
                          else f"{p.file}+{p.vertical_file}"),
               sweep=("set", "horizontal", "file"), vertical=True,
               files=("file", "vertical_file")),
    MotionKind("stochastic", "stochastic accelerograms of Rezaeian and Der Kiureghian 2008 "
               "(rocking.motions.stochastic_records)", StochasticParams, _stochastic,
               lambda p: f"stochastic:{p.index}", sweep=("index",),
               make_many=_stochastic_many),
)}
"""The motion kinds by name."""



# ----------------------------------------------------------------- 3-D kinds (pairs)
@dataclass(frozen=True)
class PairParams(Options):
    set: str | None = option(REQUIRED, help="a three-component set shipped with the package "
                             "(rocking.motions.builtin_sets; or give file and second_file)",
                             kind=str)
    file: str | None = option(REQUIRED, help="first horizontal component's file (with "
                              "second_file)", kind=str)
    second_file: str | None = option(REQUIRED, help="second horizontal component's file",
                                     kind=str)
    vertical_file: str | None = option(REQUIRED, help="vertical component's file (positive "
                                       "upwards; optional)", kind=str)
    units: str = option("g", help="unit of the files' accelerations", choices=_UNITS)
    dt: float | None = option(REQUIRED, help="time step of one-column files", unit="s",
                              lo=0.0, quantity="time")
    vertical_factor: float = option(1.0, help="the vertical component times this (relative "
                                    "to the horizontal ones; 0: without it)", lo=0.0,
                                    lo_open=False)

    def check(self):
        if (self.set is None) == (self.file is None):
            raise ParameterError("set or file: give exactly one (a built-in set, or the "
                                 "first horizontal file with its second_file)")
        if self.set is not None:
            if self.set not in _set_names():
                raise ParameterError(f"set must be one of {', '.join(_set_names())}; got "
                                     f"{self.set!r}")
            for k in ("second_file", "vertical_file"):
                if getattr(self, k) is not None:
                    raise ParameterError(f"{k} applies with file, not with set")
        elif self.second_file is None:
            raise ParameterError("second_file is required with file (the second horizontal "
                                 "component)")


def _pair(p: PairParams, ctx: Context):
    from .pair import HorizontalPair

    if p.set is not None:
        pair = HorizontalPair.builtin(p.set, vertical=p.vertical_factor > 0.0)
    else:
        pair = HorizontalPair.from_files(
            ctx.path(p.file), ctx.path(p.second_file),
            None if p.vertical_file is None or p.vertical_factor == 0.0
            else ctx.path(p.vertical_file), units=p.units, dt=p.dt,
            name=f"{Path(p.file).stem}+{Path(p.second_file).stem}")
    if pair.vertical is not None and p.vertical_factor != 1.0:
        pair = HorizontalPair(pair.first, pair.second, azimuths=pair.azimuths,
                              vertical=pair.vertical.scaled(p.vertical_factor),
                              name=pair.name)
    return pair


KINDS_3D: dict[str, MotionKind] = {k.name: k for k in (
    MotionKind("pair", "two horizontal components (and the vertical) for a 3-D model "
               "(rocking.motions.HorizontalPair; model rigid3d, oriented by its heading)",
               PairParams, _pair,
               lambda p: p.set if p.set is not None else f"{p.file}+{p.second_file}",
               sweep=("set",), vertical=True,
               files=("file", "second_file", "vertical_file")),
)}
"""The motion kinds of the 3-D models (a campaign's ``[motions]``): their motions are not
:class:`~rocking.motions.Motion` objects of one component but
:class:`~rocking.motions.HorizontalPair` objects, which only a 3-D model (``rigid3d``)
takes; kept apart from :data:`KINDS`, which the planar tools enumerate."""


def any_kind(name: str, *, param: str = "kind") -> MotionKind:
    """The entry ``name`` of :data:`KINDS` (:func:`kind`) or of :data:`KINDS_3D`."""
    if isinstance(name, str) and name in KINDS_3D:
        return KINDS_3D[name]
    try:
        return kind(name, param=param)
    except ParameterError:
        raise ParameterError(f"{param} must be one of {', '.join([*KINDS, *KINDS_3D])}; got "
                             f"{name!r}") from None


ALIASES = {a: k.name for k in KINDS.values() for a in k.aliases}


def kind(name: str, *, param: str = "kind") -> MotionKind:
    """The catalog entry ``name`` (an old spelling gives a DeprecationWarning)."""
    if isinstance(name, str) and name in ALIASES:
        new = ALIASES[name]
        warnings.warn(f"{param} {name!r} is deprecated: write {new!r} (removed in the next "
                      "release)", DeprecationWarning, stacklevel=3)
        name = new
    if not isinstance(name, str) or name not in KINDS:
        raise ParameterError(f"{param} must be one of {', '.join(KINDS)}; got {name!r}")
    return KINDS[name]


def build(name: str, ctx: Context | None = None, /, **params) -> Motion:
    """The motion of kind ``name`` with ``params`` (numbers in SI units, or strings with a
    unit such as ``"0.3g"``).

    Examples
    --------
    >>> build("sine", frequency="5Hz", displacement="5mm", duration=20).acc_amplitude
    4.934802200544679
    """
    return kind(name).build(ctx, **params)


def expand_files(pattern: str, ctx: Context) -> list[str]:
    """``pattern`` if it names a file, else the files it matches as a glob (sorted, as
    written: relative patterns give relative paths); [] if none."""
    if not _glob.has_magic(pattern):
        return [pattern]
    base = Path(ctx.base_dir)
    rel = not Path(pattern).expanduser().is_absolute()
    hits = sorted(_glob.glob(str(ctx.path(pattern))))
    return [str(Path(h).relative_to(base)) if rel else h for h in hits if Path(h).is_file()]


def table() -> list[dict]:
    """Every kind and parameter, one dict each: ``kind`` (the motion kind), ``name``,
    ``unit``, ``default``, ``range``, ``required``, ``help``, ``type`` (the Python type of
    the value) and ``sweep`` (what ``rocking motions`` prints and the README's table is
    made from)."""
    rows = []
    for k in KINDS.values():
        for d in k.describe():
            rows.append({**d, "type": d["kind"], "kind": k.name,
                         "sweep": d["name"] in k.sweep})
    return rows
