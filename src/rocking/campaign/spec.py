"""The campaign spec: one TOML file that declares a study, checked key by key.

::

    [campaign]
    name = "fragility-2-4"
    seed = 7                      # every random draw derives from (seed, sim_id)
    model = "housner"             # or a list: ["housner", "ccrr"]
    duration = 25.0               # s, optional: default each motion's own duration, then
                                  # free rocking until the block has settled
    max_free_time = 60.0          # s, optional (only without duration)
    samples = 1                   # optional: realizations of [uncertain] per (block, motion, level)
    thresholds = [0.25, 0.5]      # optional: damage states on max|theta|/alpha

    [[blocks]]                    # one table per block: any form of rocking.blocks.factory
    specimen = 2
    params = "experimental"
    [[blocks]]
    stack = [{width = 0.2, height = 0.4, mass = 10}, {width = 0.2, height = 0.4, mass = 10}]

    [motions]
    kind = "earthquake"           # any kind of rocking.motions.catalog, with its parameters
    number = [3, 20]              # one parameter of the kind's sweep may be a list or a grid
    load_factors = {start = 0.5, stop = 3.0, num = 11}   # or a list
    # or: im = "pga" and levels = [1.0, 2.0, 4.0]

    [uncertain]                   # one entry per parameter (rocking.analysis.montecarlo)
    alpha = {dist = "normal", cov = 0.02}

    [run]
    chunk_size = 2000

    [options.housner]             # optional model options (rocking models)
    rest_tol = 1e-12

    [building]                    # optional: the blocks stand on floors of a building
    kind = "shear"                # any kind of rocking.buildings.catalog, with its keys
    storeys = 3
    period = 0.4
    damping_ratio = "5%"
    floors = "all"                # or a list, 0 the ground; or height_ratios (continuous)

    [[mitigation]]                # optional: the mitigation axis, one table per entry
    name = "none"                 # the block as it stands: the campaign's model
    [[mitigation]]
    name = "isolated-2.5s"
    model = "isolated"            # the model this entry runs
    isolation_period = "2.5s"     # any option of that model (a quantity with its unit,
    isolation_damping = "10%"     # or a number in the option's SI unit)
    clearance = "0.15m"
    [[mitigation]]
    name = "anchored"
    model = "anchored"
    anchor_strength = 0.3

    [hazard]                      # optional: the site's hazard, for the report's risk
    file = "hazard_curve-mean-PGA_0.csv"   # an OpenQuake export or a CSV (IM, rate)
    site = 0                      # OpenQuake: a row index or [lon, lat]
    # max_distance_km = 50        # OpenQuake, site = [lon, lat]: refused farther away
    # fractiles = ["hazard_curve-quantile-0.05-PGA_0.csv", "hazard_curve-quantile-0.95-PGA_0.csv"]
    # investigation_time = 50     # a CSV of poe in T years: rate = -ln(1 - poe)/T
    t_years = 50                  # service life: P = 1 - exp(-lambda t)
    # or: pga_475 = "0.25g" and k = 3 (EN 1998-1 code value: an approximation)

Every key is listed by :func:`keys_table` (the README's table, generated from the motion
catalog and the block factory). ``[motions]``: ``kind`` names a catalog entry
(:data:`rocking.motions.catalog.KINDS`) and the other keys are its parameters; one
parameter of its ``sweep`` may be a list or a grid ``{start, stop, num, spacing}`` and sets
the motion axis (one motion per value); ``file`` takes paths or glob patterns (relative to
the spec); ``n = N`` stands for ``index = 0 .. N-1`` (stochastic records); a kind with a
finite set (``earthquake``, ``builtin``) runs all of it when its parameter is omitted. The
old spellings (:data:`LEGACY`) still work, with a :class:`DeprecationWarning` that says how
to write them now, and give the same rows.

A malformed spec raises :class:`~rocking.errors.SpecError` with one line that names the key
and what it allows. Everything that a spec can get wrong is found by :func:`parse_spec`,
before a store is created: every number is a number (never a bool), record files are read,
a motion's length and sample count are bounded (:data:`MAX_RECORD_DURATION`,
:data:`MAX_RECORD_SAMPLES`), the number of simulations fits ``sim_id`` (int64), each block
suits each model, and every ``[uncertain]`` distribution has at most 1 % of its mass
outside its parameter's range (:func:`rocking.analysis.montecarlo.distributions`).

A :class:`~rocking.Stack` stands in the table (``alpha``, ``p``, ``mu``, the ratio IMs,
``max_abs_theta_over_alpha``, damage states) by its top block, the one whose angle
``max_abs_theta`` is (:func:`nominal`); its ``block_name`` is the stack's.

``[building]`` (optional) puts the blocks on the floors of a building
(:mod:`rocking.buildings`): its keys are those of
:func:`rocking.buildings.catalog.make_building`, and ``floors`` (floor numbers, 0 the
ground, or ``"all"``: 0 .. n_floors) or ``height_ratios`` (``z/H`` in [0, 1], a
``continuous`` building) set the floor axis of the table. Each motion of ``[motions]`` is
the ground motion; a block feels the absolute floor acceleration
(:class:`rocking.buildings.FloorMotion`). The intensity axis scales the ground motion:
every floor of a level has the same ground intensity (``pga``, ``im``, ``load_factor``),
and ``floor_pga`` is the peak floor acceleration of the run's motion.

``[[mitigation]]`` (optional; issue 19) compares ways of making the block safe on the same
runs. Each entry has a ``name`` (required, unique, at most :data:`MAX_NAME` characters:
the table's ``mitigation`` column), a ``model`` (default: the campaign's model, which must
then be a single one: a list of models with ``[[mitigation]]`` is refused, each entry
names the model it runs) and any option of that model, merged over ``[options.<model>]``
and checked by the model's ``Options``. An entry is nothing more than a model and its
options: an entry without ``model`` runs the campaign's model (the block as it stands,
"none" by convention) and may set its options too (a variant of it). Model options given
as strings with a unit (``"2.5s"``, ``"0.15m"``, ``"10%"``) are converted to the option's
SI unit (:func:`option_values`), here and in ``[options.<model>]``.

The mitigation axis comes right after the model axis: ``(models, mitigations, blocks,
floors, motions, levels, samples)`` (:attr:`CampaignSpec.axes`); it has size 1 without
``[[mitigation]]``, so that a spec without it keeps its ``sim_id``, rows and columns.
The table then has a ``mitigation`` column (the entry's name) after ``model`` (the model
actually run), and the row outputs of every model run (``Model.row_outputs``) after the
result columns. The uncertain draws of a row do not depend on its mitigation (common
random numbers, :mod:`rocking.campaign.plan`): the mitigations are compared on the same
realizations.

``[hazard]`` (optional; issue 21) gives the site's hazard curve (:mod:`rocking.campaign.hazard`):
``file`` (an OpenQuake engine export, told by its first line, or a CSV of IM and annual
rate or return period; ``format``, ``site``, ``max_distance_km``, ``im``, ``unit``,
``investigation_time`` for a CSV of a probability of exceedance) or ``pga_475`` with ``k`` or
``pga_2475`` (the EN 1998-1 power law: an approximation, labelled so), and ``t_years`` (the
service life). :func:`parse_spec` reads the file and refuses a curve whose IM is not the
campaign's (``motions.im``, or the PGA of each run without it), naming both. The curve's
points go into the manifest, so that the report does not change when the file does. The
hazard changes no run: it is not in :attr:`CampaignSpec.hash`, and a store is resumed with
another ``[hazard]`` (its manifest takes the new one).
"""

from __future__ import annotations

import dataclasses
import glob
import hashlib
import json
import math
import re
import sys
import tomllib
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple, NoReturn

import numpy as np

from .._validate import as_int, each_warning_once, in_range
from ..analysis.damage import DEFAULT_THRESHOLDS, state_labels
from ..analysis.ida import IMS
from ..analysis.montecarlo import PARAMETERS, RANGES, distributions
from ..blocks import Block, Stack, factory
from ..buildings import catalog as buildings
from ..errors import ParameterError, RockingError, SpecError
from ..models.registry import MODELS
from ..motions import catalog
from ..options import check_option
from ..units import parse_quantity
from . import hazard as site_hazard

SECTIONS = {"campaign", "blocks", "motions", "uncertain", "run", "options", "building",
            "mitigation", "hazard"}
CAMPAIGN_KEYS = {
    "name": "the campaign's name (required)",
    "seed": "every random draw derives from (seed, sim_id); integer >= 0 (required)",
    "model": f"a model or a list of them: {', '.join(MODELS)} (required)",
    "duration": "s, (0, 1e6]: every run lasts exactly this; default: each motion's own "
                "duration, then free rocking until the block has settled",
    "max_free_time": "s, [0, 1e4], only without duration: cap of that free rocking "
                     "(default 60; 0 stops with each motion)",
    "samples": "realizations of [uncertain] per (block, motion, level); default 1",
    "thresholds": "damage states on max|theta|/alpha, increasing; default "
                  f"{list(DEFAULT_THRESHOLDS)}",
}
RUN_KEYS = {"chunk_size": "simulations per chunk (a Parquet file); default 2000",
            "window": "chunks in flight with Dask (default 2 per worker thread); not hashed"}
INTENSITY_KEYS = {
    "load_factors": "factors on every motion: a list or {start, stop, num, spacing}, > 0; "
                    "default [1.0]",
    "im": f"scale each motion to IM levels instead: {', '.join(IMS)} (a ground motion: "
          "its horizontal component's)",
    "levels": "the IM levels (units of im): a list or a grid, > 0",
}
COUNT, COUNTER = "n", "index"
"""``n = N`` in ``[motions]`` stands for ``index = 0 .. N-1`` (kinds with an ``index``: the
stochastic records); the kind's check does not depend on the index, which is checked alone."""
LEGACY = {
    "seed_earthquakes": ("earthquake", {"records": "number"}),
    "files": ("record", {"paths": "file"}),
    "builtin": ("builtin", {"names": "name"}),
    "sine_grid": ("sine", {"frequencies": "frequency", "record_duration": "duration"}),
    "pulse_grid": (None, {"pulse": "kind", "periods": "period", "record_duration": "duration"}),
    "stochastic": ("stochastic", {"record_duration": "duration"}),
}
"""Old spellings of ``[motions]``: old kind -> (new kind, or None: ``pulse`` names it;
{old key: new key}); read with a DeprecationWarning, and give the same rows."""
LEGACY_DEFAULTS = {"sine_grid": {"amplitude": 1.0, "cycles": 10},
                   "pulse_grid": {"amplitude": 1.0}}
"""Defaults of the old kinds (the catalog has none: write them)."""
PULSES = ("one_sine", "one_cosine", "half_sine", "rectangular", "ricker")
"""The pulses of the old ``pulse_grid``."""
MAX_RECORD_DURATION = catalog.MAX_DURATION
"""Longest motion a spec may define (s): see :data:`rocking.motions.catalog.MAX_DURATION`."""
MAX_RECORD_SAMPLES = catalog.MAX_SAMPLES
"""Most samples of one stochastic record (:data:`rocking.motions.catalog.MAX_SAMPLES`)."""
FLOOR_KEYS = {
    "floors": 'the floors the blocks stand on: a list of floor numbers (0 the ground, '
              '1 .. n_floors) or "all" (0 .. n_floors)',
    "height_ratios": "instead of floors, for a continuous building: heights z/H in [0, 1], "
                     "a list or a grid",
}
"""The keys of ``[building]`` that set the floor axis (the others are the building's)."""
MAX_SIMS = 2 ** 63 - 1
"""Most simulations of a campaign: ``sim_id`` is an int64."""
MITIGATION_KEYS = {
    "name": "the entry's name, unique, at most 64 characters: the table's mitigation column "
            "(required)",
    "model": "the model this entry runs (default: the campaign's model, a single one)",
    "(options)": "any option of that model (`rocking models`), merged over "
                 "[options.<model>]; a quantity may carry its unit (\"2.5s\", \"0.15m\", "
                 "\"10%\")",
}
"""The keys of a ``[[mitigation]]`` entry."""
MAX_NAME = 64
"""Longest ``[[mitigation]]`` name."""
AXES = ("model", "mitigation", "heading", "block", "floor", "motion", "level", "sample")
"""The axes of a campaign's table, in the order of ``sim_id`` (the last fastest)."""


def _fail(key: str, msg: str) -> NoReturn:
    raise SpecError(f"spec: {key}: {msg}")


def _number(key: str, v, lo: float = -math.inf, hi: float = math.inf, *, lo_open=False,
            integer: bool = False):
    """A TOML number (never a bool or a string) in ``[lo, hi]``, checked by
    :mod:`rocking._validate` (an integer exactly, with ``integer``)."""
    if isinstance(v, bool) or not isinstance(v, int | float):
        _fail(key, f"must be a {'whole number' if integer else 'number'}, "
                   f"got {type(v).__name__} {v!r}")
    try:
        if integer:
            return as_int(key, v, None if lo == -math.inf else int(lo),
                          None if hi == math.inf else int(hi))
        return in_range(key, v, lo, hi, lo_open=lo_open, hi_open=False)
    except ParameterError as e:
        _fail(key, str(e).removeprefix(key).strip())


def _string(key: str, v, choices=None) -> str:
    if not isinstance(v, str):
        _fail(key, f"must be a string, got {type(v).__name__} {v!r}")
    if choices is not None and v not in choices:
        _fail(key, f"must be one of {', '.join(map(str, choices))}; got {v!r}")
    return v


def _table(key: str, v) -> dict:
    if not isinstance(v, dict):
        _fail(key, f"must be a table, got {type(v).__name__} {v!r}")
    return v


def _printable(key: str, name: str) -> str:
    """``name`` if it prints on one line (no newline, tab or other control character: it
    heads the report's tables and rows), else refused naming ``key``."""
    bad = next((ch for ch in name if not ch.isprintable()), None)
    if bad is not None:
        _fail(key, f"must print on one line (it holds {bad!r}: a newline or other control "
                   f"character breaks the report's tables); got {name!r}")
    return name


def _known(key: str, table: dict, allowed) -> None:
    unknown = sorted(set(table) - set(allowed))
    if unknown:
        where = f"{key}." if key else ""
        _fail(f"{where}{unknown[0]}", f"unknown key (allowed in [{key or 'spec'}]: "
                                      f"{', '.join(sorted(allowed))})")


_UNKNOWN = re.compile(r"((?:\w+(?:\[\d+\])?\.)*)unknown parameter\(s\) for ([^:]*): "
                      r"([^ ,]+)[^(]*\(allowed: ([^)]*)\)")
_NAMED = re.compile(r"([A-Za-z_]\w*)((?:\[\d+\])?(?:\.\w+(?:\[\d+\])?)*)(:)? (.*)")


def _param_fail(prefix: str, e: Exception, names, keys: dict | None = None) -> NoReturn:
    """A catalog or factory error as a SpecError naming ``prefix.<parameter>`` (the
    message starts with the parameter's name; ``keys`` overrides a parameter's key)."""
    msg = (str(e).splitlines() or [""])[0] or type(e).__name__
    u = _UNKNOWN.match(msg)
    if u:
        _fail(f"{prefix}.{u[1]}{u[3]}", f"unknown key (allowed in {u[2]}: {u[4]})")
    m = _NAMED.match(msg)
    if m is None or (m[1] not in names and not m[3]):
        _fail(prefix, msg)
    if m[1] not in names:  # "block: give exactly one of ..."
        _fail(prefix, m[4])
    key = (keys or {}).get(m[1]) or f"{prefix}.{m[1]}{m[2]}"
    said = m[3] or m[4].startswith(("must ", "is ", "applies ", "has "))
    _fail(key, m[4] if said else msg)


def grid(key: str, v, lo: float = 0.0, *, lo_open: bool = True) -> np.ndarray:
    """A list of numbers, or ``{start, stop, num}`` (linear; ``spacing = "log"`` for log)."""
    if isinstance(v, dict):
        _known(key, v, {"start", "stop", "num", "spacing"})
        for k in ("start", "stop", "num"):
            if k not in v:
                _fail(f"{key}.{k}", "missing (a grid is {start, stop, num})")
        a = _number(f"{key}.start", v["start"], lo, lo_open=lo_open)
        b = _number(f"{key}.stop", v["stop"], lo, lo_open=lo_open)
        n = _number(f"{key}.num", v["num"], 1, 1e7, integer=True)
        spacing = _string(f"{key}.spacing", v.get("spacing", "linear"), ("linear", "log"))
        if spacing == "log":
            if a <= 0:
                _fail(f"{key}.start", "must be > 0 for a log grid")
            return np.geomspace(a, b, n)
        return np.linspace(a, b, n)
    if not isinstance(v, list):
        _fail(key, f"must be a list of numbers or {{start, stop, num}}, got {v!r}")
    if not v:
        _fail(key, "is empty")
    return np.array([_number(f"{key}[{i}]", x, lo, lo_open=lo_open) for i, x in enumerate(v)],
                    dtype=float)


# ------------------------------------------------------------------ the checked tables
def _frozen(v):
    """``v`` with every list made a tuple (recursively): a value that nothing can change."""
    if isinstance(v, list | tuple):
        return tuple(_frozen(x) for x in v)
    return v


def _thawed(v):
    """The inverse of :func:`_frozen`: tuples as lists (as TOML and JSON give them)."""
    if isinstance(v, tuple):
        return [_thawed(x) for x in v]
    return v


@dataclass(frozen=True)
class MotionAxis:
    """The checked ``[motions]`` table: the motion axis and the intensity axis
    (:attr:`CampaignSpec.motion_axis`).

    ``kind`` is the catalog's name (:data:`rocking.motions.catalog.KINDS`), ``template``
    the checked parameters of motion 0 (the kind's ``Params``), ``fixed`` the names of the
    parameters the spec gives one value, ``sweep`` the swept parameter (None: one motion),
    ``n`` the number of motions, ``axis`` the key that sets them, ``values`` the swept
    parameter's values (None for ``n = N``: the index itself), ``digests`` the content
    digests of record files (None without files), and ``load_factors`` or ``im`` +
    ``levels``. ``records`` holds the motions made while checking the record files (the
    files are read once: :class:`rocking.campaign.plan.MotionSet` takes them); it is not
    compared, and not pickled (a Dask worker reads the files it needs).
    :meth:`to_dict` is the table as a plain dict (:attr:`CampaignSpec.motions`, the
    manifest's ``motions``).

    Examples
    --------
    >>> from rocking.campaign import EXAMPLE_SPEC, parse_spec
    >>> axis = parse_spec(EXAMPLE_SPEC).motion_axis
    >>> axis.kind, axis.n, axis.sweep, axis.load_factors
    ('one_sine', 1, None, (1.0, 1.5, 2.0, 3.0))
    >>> axis.params(0).period, axis.to_dict()["params"]
    (0.5, {'period': 0.5, 'amplitude': 1.0})
    """

    kind: str
    template: object
    fixed: tuple[str, ...]
    sweep: str | None
    n: int
    axis: str
    values: tuple | None = None
    digests: tuple[str, ...] | None = None
    load_factors: tuple[float, ...] | None = None
    im: str | None = None
    levels: tuple[float, ...] | None = None
    records: tuple | None = field(default=None, compare=False, repr=False)

    def __getstate__(self) -> dict:
        return {**self.__dict__, "records": None}

    def __setstate__(self, state: dict) -> None:
        for k, v in state.items():
            object.__setattr__(self, k, v)

    @property
    def catalog_kind(self) -> catalog.MotionKind:
        """The catalog entry of the motions (:data:`~rocking.motions.catalog.KINDS`, or
        :data:`~rocking.motions.catalog.KINDS_3D`: a pair)."""
        return catalog.any_kind(self.kind)

    def value(self, j: int):
        """The swept parameter's value of motion ``j`` (the index itself for ``n``)."""
        return self.values[j] if self.values is not None else j

    def params(self, j: int):
        """The checked catalog parameters of motion ``j``: :attr:`template` with its
        swept parameter's value (``dataclasses.replace``, checked again)."""
        if self.sweep is None or j == 0:
            return self.template
        return dataclasses.replace(self.template, **{self.sweep: self.value(j)})

    @property
    def intensity_levels(self) -> tuple[float, ...]:
        """The intensity axis: :attr:`levels` with ``im``, else :attr:`load_factors`."""
        return self.levels if self.im is not None else self.load_factors

    def to_dict(self) -> dict:
        """The table as a plain dict, as the spec kept it before it was typed: ``kind``,
        ``params`` (the fixed parameters), ``sweep``, ``n``, ``axis``, ``values`` (absent
        for ``n``), ``digests`` (of record files), ``load_factors`` or ``im`` +
        ``levels``."""
        out = {"kind": self.kind,
               "params": {k: getattr(self.template, k) for k in self.fixed},
               "sweep": self.sweep, "n": self.n, "axis": self.axis}
        if self.values is not None:
            out["values"] = list(self.values)
        if self.digests is not None:
            out["digests"] = list(self.digests)
        if self.im is None:
            out["load_factors"] = list(self.load_factors)
        else:
            out["im"], out["levels"] = self.im, list(self.levels)
        return out


@dataclass(frozen=True)
class Distribution:
    """One checked ``[uncertain]`` entry: the ``parameter`` (a name of
    :data:`rocking.analysis.montecarlo.PARAMETERS`) and its table's ``items`` (``dist``
    and its parameters, in the spec's order; :mod:`rocking.analysis.distributions`).

    Examples
    --------
    >>> from rocking.campaign.spec import Distribution
    >>> d = Distribution("alpha", (("dist", "normal"), ("cov", 0.02)))
    >>> d.dist, d.to_dict()
    ('normal', {'dist': 'normal', 'cov': 0.02})
    """

    parameter: str
    items: tuple[tuple[str, object], ...]

    @property
    def dist(self) -> str:
        return dict(self.items)["dist"]

    def to_dict(self) -> dict:
        """The distribution as :func:`rocking.analysis.distributions.frozen` takes it."""
        return {k: _thawed(v) for k, v in self.items}


@dataclass(frozen=True)
class UncertainParameters:
    """The checked ``[uncertain]`` table (:attr:`CampaignSpec.uncertain_parameters`): one
    :class:`Distribution` per uncertain parameter, in the spec's order. Its length is the
    number of uncertain parameters; :meth:`to_dict` gives ``{parameter: distribution}``
    for :func:`rocking.analysis.montecarlo.distributions` (and
    :attr:`CampaignSpec.uncertain`).

    Examples
    --------
    >>> from rocking.campaign import EXAMPLE_SPEC, parse_spec
    >>> spec = parse_spec(EXAMPLE_SPEC + '[uncertain]\\nmu = {dist = "normal", cov = 0.01}\\n')
    >>> u = spec.uncertain_parameters
    >>> len(u), u.names, u.to_dict()
    (1, ('mu',), {'mu': {'dist': 'normal', 'cov': 0.01}})
    """

    parameters: tuple[Distribution, ...] = ()

    def __len__(self) -> int:
        return len(self.parameters)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(d.parameter for d in self.parameters)

    def to_dict(self) -> dict:
        return {d.parameter: d.to_dict() for d in self.parameters}


@dataclass(frozen=True)
class BuildingAxis:
    """The checked ``[building]`` table (:attr:`CampaignSpec.building_axis`): ``params``
    (the keys for :func:`~rocking.buildings.catalog.make_building`, as given), ``axis``
    (``floor`` or ``height_ratio``), ``values`` (the floors or height ratios),
    ``n_floors``, the modal ``periods`` (s), the building's ``name`` and its ``checked``
    keys (SI). :meth:`model` builds the building; :meth:`to_dict` is the table as a plain
    dict (:attr:`CampaignSpec.building`, the manifest's ``building``).

    Examples
    --------
    >>> from rocking.campaign import EXAMPLE_SPEC, parse_spec
    >>> b = parse_spec(EXAMPLE_SPEC + '[building]\\nkind = "shear"\\nstoreys = 2\\n'
    ...                'period = 0.3\\nfloors = "all"\\n').building_axis
    >>> b.axis, b.values, b.n_floors, b.model().n_floors
    ('floor', (0, 1, 2), 2, 2)
    """

    params: tuple[tuple[str, object], ...]
    axis: str
    values: tuple
    n_floors: int | None
    periods: tuple[float, ...]
    name: str
    checked: tuple[tuple[str, object], ...]

    def model(self):
        """The :class:`~rocking.buildings.Building`."""
        return buildings.make_building(self.params_dict())

    def params_dict(self) -> dict:
        """:attr:`params` as a dict (lists as TOML gave them)."""
        return {k: _thawed(v) for k, v in self.params}

    def to_dict(self) -> dict:
        """``params``, ``axis``, ``values``, ``n_floors``, ``periods``, ``name`` and
        ``checked``, as the spec kept them before they were typed."""
        return {"params": self.params_dict(), "axis": self.axis, "values": list(self.values),
                "n_floors": self.n_floors, "periods": list(self.periods), "name": self.name,
                "checked": dict(self.checked)}


# ------------------------------------------------------------------------------- blocks
BLOCK_KEYS = {"name", *(k for f in factory.FORMS.values() for k in f.Params.names())}


def nominal(block) -> Block:
    """The block whose ``alpha``, ``p`` and ``mu`` stand for ``block`` in the table: the
    block itself, a :class:`~rocking.Stack`'s top block (whose angle is the result), or
    for a 3-D body (a :class:`~rocking.shapes.Shape`, model ``rigid3d``) its planar block
    in its weakest direction (:meth:`rocking.Block.from_shape` along
    :meth:`~rocking.shapes.Shape.weakest`: the smallest uplift acceleration, the critical
    tilt ``alpha`` of that side; kept with the body)."""
    if isinstance(block, Stack):
        return block.top
    if isinstance(block, Block):
        return block
    planar = _NOMINAL.get(id(block))
    if planar is None or planar[0] is not block:
        planar = _NOMINAL[id(block)] = (block, Block.from_shape(block, block.weakest().phi,
                                                                name=block.name))
    return planar[1]


_NOMINAL: dict = {}


def is_3d(model: str) -> bool:
    """True for a model of a 3-D body (:func:`rocking.models.is_3d`: ``rigid3d``): its
    bodies are 3-D shapes (:func:`rocking.blocks.factory.make_body`)."""
    from ..models import is_3d as three_d

    return three_d(model)


def _block(i: int, t, base_dir, body: bool = False) -> tuple[list, list]:
    """``[[blocks]]`` table ``i`` through :func:`rocking.blocks.factory.make_blocks` (one
    block, or one per item of a mesh's ``direction`` list, in place); without a ``name``,
    the form's name and the block's place (``0.25 x 1 m block (blocks[1])``), except a
    specimen's, which says which it is. Also the content digests of the files the table
    names (a mesh; relative paths start from ``base_dir``)."""
    key = f"blocks[{i}]"
    t = _table(key, t)
    try:
        form = factory.form_of({k: v for k, v in t.items() if k != "name"})
        bs = ([factory.make_body(t, base_dir=base_dir)] if body
              else factory.make_blocks(t, base_dir=base_dir))
        if "name" not in t and form.name != "specimen":
            bs = [factory.renamed(b, f"{b.name} ({key})") for b in bs]
    except (RockingError, TypeError, ValueError) as e:
        _param_fail(key, e, BLOCK_KEYS)
    digests = [_digest(f"{key}.{k}", Path(base_dir) / t[k]) for k in form.paths if k in t]
    return bs, digests


def _blocks(raw: dict, base_dir=".", body: bool = False) -> tuple[tuple, tuple]:
    """The blocks of ``[[blocks]]`` and the digests of the files they name (``body``: the
    3-D bodies of a 3-D model, :func:`rocking.blocks.factory.make_body`)."""
    if "blocks" not in raw:
        _fail("blocks", "missing (one [[blocks]] table per block)")
    if not isinstance(raw["blocks"], list) or not raw["blocks"]:
        _fail("blocks", "must be one or more [[blocks]] tables")
    blocks, digests, named = [], [], {}
    for i, b in enumerate(raw["blocks"]):
        if isinstance(b, dict) and isinstance(b.get("name"), str):
            key = f"blocks[{i}].name"
            if not b["name"].strip():
                _fail(key, "must not be blank (it names the block in the table and report)")
            _printable(key, b["name"])
            if b["name"].strip() in named:
                _fail(key, f"{b['name']!r} is already the name of "
                           f"blocks[{named[b['name'].strip()]}] (names are unique: the "
                           "report, risk.csv and pelicun.csv group the runs by them)")
            named[b["name"].strip()] = i
        bs, ds = _block(i, b, base_dir, body)
        blocks += bs
        digests += ds
    return tuple(factory.unique_names(blocks)), tuple(digests)


# ------------------------------------------------------------------------------ motions
def _toml(v) -> str:
    """``v`` written as a TOML value (for messages)."""
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k} = {_toml(x)}" for k, x in v.items()) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(map(_toml, v)) + "]"
    if isinstance(v, bool):
        return str(v).lower()
    return json.dumps(v) if isinstance(v, str) else repr(v)


def _outside() -> int:
    """The ``stacklevel`` of the caller's first frame outside the package (a warning then
    shows in the user's script, or the ``rocking`` command's)."""
    package = str(Path(__file__).resolve().parents[1])
    level, f = 1, sys._getframe(1)
    while f is not None and f.f_code.co_filename.startswith(package):
        f, level = f.f_back, level + 1
    return level


def _legacy(t: dict) -> tuple[dict, dict]:
    """``[motions]`` in the catalog's vocabulary (an old spelling, :data:`LEGACY`, is
    translated with a DeprecationWarning), and ``{new key: old key}`` for messages."""
    old = t.get("kind")
    if not isinstance(old, str) or old not in LEGACY:
        return t, {}
    new, keys = LEGACY[old]
    if new == old and not set(keys) & set(t):
        return t, {}
    if new is None and "pulse" not in t:
        _fail("motions.pulse", f"missing (one of {', '.join(PULSES)})")
    both = [k for k in keys if k in t and keys[k] in t and keys[k] != "kind"]
    if both:
        _fail(f"motions.{keys[both[0]]}", f"give {keys[both[0]]} or {both[0]} (its old "
                                          "spelling), not both")
    out = {"kind": new} if new else {}
    out.update({keys.get(k, k): v for k, v in t.items() if k != "kind"})
    for k, v in LEGACY_DEFAULTS.get(old, {}).items():
        if not (k == "cycles" and "duration" in out):
            out.setdefault(k, v)
    now = ", ".join(f"{k} = {_toml(v)}" for k, v in out.items() if k not in INTENSITY_KEYS)
    warnings.warn(f"spec: [motions] kind = {old!r} is deprecated (removed in the next "
                  f"release): write {now}", DeprecationWarning, stacklevel=_outside())
    return out, {v: k for k, v in keys.items()}


def _renamed(e: SpecError, renamed: dict) -> SpecError:
    """``e`` naming the key as the spec wrote it (an old spelling)."""
    m = re.match(r"spec: motions\.(\w+)", str(e))
    if not m or m[1] not in renamed:
        return e
    return SpecError(str(e)[:m.start(1)] + renamed[m[1]] + str(e)[m.end(1):])


class _Axis(NamedTuple):
    """The motion axis: the swept parameter (None: one motion), the key that gives it, its
    values (or their number for ``n``), and the key of each value (for messages)."""

    param: str | None
    key: str
    values: list | int
    where: list


def _motion_kind(t: dict) -> catalog.MotionKind:
    if "kind" not in t:
        _fail("motions.kind", f"missing (one of {', '.join(catalog.KINDS)})")
    try:
        kind = catalog.any_kind(t["kind"])
    except ParameterError as e:
        _param_fail("motions", e, {"kind"})
    counted = {COUNT} if COUNTER in kind.sweep else set()
    _known("motions", t, {"kind", *INTENSITY_KEYS, *kind.Params.names(), *counted})
    return kind


def _is_glob(v) -> bool:
    return isinstance(v, str) and glob.has_magic(v)


def _files(key: str, v, ctx: catalog.Context) -> _Axis:
    """A file parameter given as paths or glob patterns: one motion per file."""
    items = v if isinstance(v, list) else [v]
    values, where = [], []
    for i, p in enumerate(items):
        w = f"{key}[{i}]" if isinstance(v, list) else key
        if not isinstance(p, str):
            _fail(w, f"must be a file path or a glob pattern, got {type(p).__name__} {p!r}")
        hits = catalog.expand_files(p, ctx)
        if not hits:
            _fail(w, f"no file matches {p!r} (relative to {ctx.base_dir})")
        values += hits
        where += [w] * len(hits)
    return _Axis(key.split(".")[1], key, values, where)


def _swept(kind: catalog.MotionKind, param: str, v, ctx: catalog.Context) -> _Axis:
    key = f"motions.{param}"
    if param in kind.files:
        return _files(key, v, ctx)
    if isinstance(v, dict):
        values = grid(key, v, -math.inf).tolist()
        return _Axis(param, key, values, [key] * len(values))
    return _Axis(param, key, list(v), [f"{key}[{i}]" for i in range(len(v))])


def _axis(kind: catalog.MotionKind, t: dict, ctx: catalog.Context) -> _Axis:
    """The motion axis of ``[motions]`` (at most one parameter gives several motions)."""
    given = {k: v for k, v in t.items() if k in kind.Params.names()}
    swept = [k for k, v in given.items() if isinstance(v, list | dict)
             or (k in kind.files and _is_glob(v))]
    for k in swept:
        if k not in kind.sweep:
            _fail(f"motions.{k}", "takes one value (a list or grid only for: "
                                  f"{', '.join(kind.sweep) or 'none'})")
    if COUNT in t:
        if COUNTER in given:
            _fail(f"motions.{COUNT}", f"give {COUNT} or {COUNTER}, not both")
        swept.append(COUNT)
    if len(swept) > 1:
        _fail(f"motions.{swept[1]}", f"only one parameter may give several motions "
                                     f"(motions.{swept[0]} does)")
    if swept == [COUNT]:
        return _Axis(COUNTER, f"motions.{COUNT}",
                     _number(f"motions.{COUNT}", t[COUNT], 0, 1e7, integer=True), [])
    if swept:
        return _swept(kind, swept[0], given[swept[0]], ctx)
    first = kind.sweep[0] if kind.sweep else None
    if kind.every is not None and first not in given:
        values = list(kind.every())
        return _Axis(first, f"motions.{first}", values, [f"motions.{first}"] * len(values))
    if COUNTER in kind.sweep and COUNTER not in given:
        _fail(f"motions.{COUNT}", f"missing (the number of records: {COUNTER} 0 .. n-1)")
    return _Axis(None, "motions", [None], ["motions"])


def _params(kind: catalog.MotionKind, fixed: dict, param, value, where: str):
    """The checked parameters of one motion (a catalog error names its key)."""
    values = dict(fixed) if param is None else {**fixed, param: value}
    try:
        return kind.Params(**values)
    except ParameterError as e:
        _param_fail("motions", e, kind.Params.names(), {param: where})


def _digest(key: str, path: Path) -> str:
    if not path.is_file():
        _fail(key, f"no such file: {path}")
    try:
        data = path.read_bytes()
    except OSError as e:
        _fail(key, f"cannot read {path}: {type(e).__name__}: {str(e).splitlines()[0]}")
    return hashlib.sha256(data).hexdigest()[:16]


def _read(kind: catalog.MotionKind, p, ctx: catalog.Context, where: str,
          param) -> tuple[str, object]:
    """Read the files of motion ``p`` as a run will (refused if they cannot be read or
    parsed): their content digest (``+`` between files) and the motion made from them
    (``("", None)`` when the motion names no file)."""
    given = [f for f in kind.files if getattr(p, f) is not None]
    if not given:
        return "", None
    paths = [ctx.path(getattr(p, f)) for f in given]
    keys = [where if f == param else f"motions.{f}" for f in given]
    digest = "+".join(_digest(k, q) for k, q in zip(keys, paths, strict=True))
    try:
        motion = kind.make(p, ctx)
    except RockingError as e:
        _fail(keys[0], f"{', '.join(q.name for q in paths)}: "
                       f"{(str(e).splitlines() or [type(e).__name__])[0]}")
    except (OSError, ValueError) as e:  # unreadable, not text, ...
        _fail(keys[0], f"cannot read {', '.join(map(str, paths))}: {type(e).__name__}: "
                       f"{(str(e).splitlines() or [''])[0]}")
    return digest, motion


def _checked(kind: catalog.MotionKind, t: dict, axis: _Axis, ctx: catalog.Context) -> dict:
    """Every motion's parameters checked by the catalog: the keys of :class:`MotionAxis`
    but the intensity axis (``records``: the motions made from record files)."""
    fixed = {k: v for k, v in t.items() if k in kind.Params.names() and k != axis.param}
    n = axis.values if isinstance(axis.values, int) else len(axis.values)
    if n == 0:
        _fail(axis.key, "empty motion set (no motion to run)")
    values = [0] if isinstance(axis.values, int) else axis.values
    where = axis.where or [axis.key]
    template = _params(kind, fixed, axis.param, values[0], where[0])
    out = {"kind": kind.name, "template": template, "fixed": tuple(fixed),
           "sweep": axis.param, "n": n, "axis": axis.key.removeprefix("motions.")}
    if axis.param == COUNTER:  # the index alone: the kind's check does not depend on it
        meta = {f.name: f.metadata for f in dataclasses.fields(kind.Params)}[COUNTER]
        ps = [template]
        if not isinstance(axis.values, int):
            out["values"] = tuple(_index(v, w, meta)
                                  for v, w in zip(values, where, strict=True))
    else:
        ps = [_params(kind, fixed, axis.param, v, w) for v, w in zip(values, where,
                                                                        strict=True)]
        if axis.param is not None:
            out["values"] = tuple(getattr(p, axis.param) for p in ps)
    if "values" in out and len(set(out["values"])) != n:
        _fail(axis.key, "has repeated values (one motion each)")
    ids: dict[str, str] = {}
    for p, w in zip(ps, where, strict=False):  # one per motion (the index alone: one)
        label = kind.label(p)
        if label in ids:
            digits = ("; make the values differ in their first 6 significant digits"
                      if isinstance(getattr(p, axis.param or "", None), float) else "")
            _fail(w, f"gives the motion id {label!r} as {ids[label]} does (motion ids are "
                     f"unique: the table and the report name the motions by them){digits}")
        _printable(w, label)
        ids[label] = w
    read = ([_read(kind, p, ctx, w, axis.param) for p, w in zip(ps, where, strict=True)]
            if kind.files else [])
    if any(d for d, _ in read):  # record files (not a built-in set)
        out["digests"] = tuple(d for d, _ in read)
        if all(m is not None for _, m in read) and len(read) == n:
            out["records"] = tuple(m for _, m in read)
    return out


def _index(v, where: str, meta: dict) -> int:
    try:
        return check_option(COUNTER, v, meta)
    except ParameterError as e:
        _param_fail("motions", e, {COUNTER}, {COUNTER: where})


def _intensity(t: dict) -> dict:
    """The intensity axis: ``load_factors``, or ``im`` + ``levels``."""
    has_lf, has_im = "load_factors" in t, ("im" in t or "levels" in t)
    if has_lf and has_im:
        _fail("motions.load_factors", "give load_factors or im + levels, not both")
    if not has_im:
        return {"load_factors": tuple(grid("motions.load_factors",
                                           t.get("load_factors", [1.0])).tolist())}
    if "im" not in t:
        _fail("motions.im", f"missing with levels (one of {', '.join(IMS)})")
    if "levels" not in t:
        _fail("motions.levels", f"missing with im = {t['im']!r}")
    return {"im": _string("motions.im", t["im"], tuple(IMS)),
            "levels": tuple(grid("motions.levels", t["levels"]).tolist())}


def _motions(t, base_dir: Path, seed: int) -> MotionAxis:
    """The checked ``[motions]`` (:class:`MotionAxis`)."""
    t, renamed = _legacy(_table("motions", t))
    try:
        kind = _motion_kind(t)
        ctx = catalog.Context(Path(base_dir), seed)
        out = _checked(kind, t, _axis(kind, t, ctx), ctx)
        out.update(_intensity(t))
    except SpecError as e:
        raise _renamed(e, renamed) from None
    out["axis"] = renamed.get(out["axis"], out["axis"])
    return MotionAxis(**out)


def motion_kind(m) -> catalog.MotionKind:
    """The catalog entry of a checked ``[motions]`` table (a :class:`MotionAxis`, or its
    :meth:`~MotionAxis.to_dict`)."""
    return catalog.any_kind(m.kind if isinstance(m, MotionAxis) else m["kind"])


def motion_value(m, j: int):
    """The swept parameter's value of motion ``j`` of a checked ``[motions]`` table (a
    :class:`MotionAxis`, or its :meth:`~MotionAxis.to_dict`)."""
    if isinstance(m, MotionAxis):
        return m.value(j)
    return m["values"][j] if "values" in m else j


def n_motions(m) -> int:
    """Number of motions of a checked ``[motions]`` table (a :class:`MotionAxis`, or its
    :meth:`~MotionAxis.to_dict`)."""
    return m.n if isinstance(m, MotionAxis) else m["n"]


# ----------------------------------------------------------------------------- building
BUILDING_KEYS = {"kind", *(k for b in buildings.KINDS.values() for k in b.Params.names())}


def building_model(b):
    """The :class:`~rocking.buildings.Building` of a checked ``[building]`` table (a
    :class:`BuildingAxis`, or its :meth:`~BuildingAxis.to_dict`)."""
    return b.model() if isinstance(b, BuildingAxis) else buildings.make_building(b["params"])


def _building_kind(t: dict) -> buildings.BuildingKind:
    if "kind" not in t:
        _fail("building.kind", f"missing (one of {', '.join(buildings.KINDS)})")
    name = _string("building.kind", t["kind"], tuple(buildings.KINDS))
    kind = buildings.KINDS[name]
    _known("building", t, {"kind", *kind.Params.names(), *FLOOR_KEYS})
    return kind


def _floor_list(v, top: int | None, kind: str) -> list[int]:
    key = "building.floors"
    if top is None:
        _fail(key, f"this {kind} building has no floors (give storeys, or height_ratios)")
    if v == "all":
        return list(range(top + 1))
    if not isinstance(v, list) or not v:
        _fail(key, f'must be "all" or a list of floor numbers in 0..{top}, got {_toml(v)}')
    out = [_number(f"{key}[{i}]", x, 0, top, integer=True) for i, x in enumerate(v)]
    if len(set(out)) != len(out):
        _fail(key, "has repeated floors (one each)")
    return out


def _ratios(v, building) -> list[float]:
    """The height ratios, each where the building has a floor (or any z/H of a continuous
    building): the building's own check (:meth:`~rocking.buildings.Building.modal_factors`)."""
    key = "building.height_ratios"
    out = grid(key, v, 0.0, lo_open=False).tolist()
    for i, x in enumerate(out):
        try:
            building.modal_factors(height_ratio=x)
        except ParameterError as e:
            _fail(f"{key}[{i}]" if isinstance(v, list) else key, str(e))
    if len(set(out)) != len(out):
        _fail(key, "has repeated values (one each)")
    return out


def _building(raw: dict) -> BuildingAxis | None:
    """The checked ``[building]`` (:class:`BuildingAxis`); None without the table."""
    if "building" not in raw:
        return None
    t = _table("building", raw["building"])
    kind = _building_kind(t)
    params = {k: v for k, v in t.items() if k not in FLOOR_KEYS}
    try:
        b = buildings.make_building(params)
    except (RockingError, TypeError, ValueError) as e:
        _param_fail("building", e, BUILDING_KEYS, {"damping": "building.damping_ratio"})
    given = [k for k in FLOOR_KEYS if k in t]
    if len(given) > 1:
        _fail("building.height_ratios", "give floors or height_ratios, not both")
    if not given:
        _fail("building.floors", 'missing (a list of floors, 0 the ground, or "all"'
                                 '; or height_ratios, z/H)')
    if given == ["floors"]:
        axis, values = "floor", _floor_list(t["floors"], b.n_floors, kind.name)
    else:
        axis, values = "height_ratio", _ratios(t["height_ratios"], b)
    checked = kind.Params(**{k: v for k, v in params.items() if k != "kind"}).to_dict()
    return BuildingAxis(
        params=tuple((k, _frozen(v)) for k, v in params.items()), axis=axis,
        values=tuple(values), n_floors=b.n_floors, periods=tuple(b.periods.tolist()),
        name=b.name, checked=(("kind", kind.name), *((k, v) for k, v in checked.items()
                                                     if v is not None)))


# ------------------------------------------------------------------------------- hazard
def _hazard_fail(e: ParameterError, given: dict) -> NoReturn:
    """A hazard loader's error as a SpecError naming ``hazard.<key>`` (its message starts
    with the argument's name)."""
    msg = (str(e).splitlines() or [""])[0]
    name, _, rest = msg.partition(" ")
    name = name.rstrip(":")
    if "=" in name:  # "investigation_time=30 contradicts ...": the whole message
        name, rest = name.partition("=")[0], msg
    if name == "pga_475" or name == "pga_2475" or name == "k":
        _fail(f"hazard.{name}", rest)
    if name in site_hazard.HAZARD_KEYS and name in given:
        _fail(f"hazard.{name}", rest)
    if name in ("unit", "im", "investigation_time"):  # a CSV that does not say it
        rest = rest.replace("investigation_time=", "investigation_time = ")
        _fail(f"hazard.{name}", f"missing: {rest}")
    _fail("hazard.file" if "file" in given else "hazard", msg)


def _hazard(raw: dict, base_dir: Path, motions: MotionAxis) -> dict | None:
    """The checked ``[hazard]`` as the manifest's record (:func:`rocking.campaign.hazard.
    record`: the curve's points, IM, unit, label, source, ``t_years``); None without it.
    The file is read here, and a curve of another IM than the campaign's is refused."""
    if "hazard" not in raw:
        return None
    t = _table("hazard", raw["hazard"])
    _known("hazard", t, site_hazard.HAZARD_KEYS)
    has_file, has_code = "file" in t, "pga_475" in t
    if has_file == has_code:
        _fail("hazard.file", "give file (a hazard-curve file) or pga_475 (a code value), "
                             + ("not both" if has_file else "one of them"))
    t_years = (_number("hazard.t_years", t["t_years"], 0, site_hazard.MAX_T_YEARS,
                       lo_open=True) if "t_years" in t else site_hazard.DEFAULT_T_YEARS)
    label = _string("hazard.label", t["label"]) if "label" in t else ""
    given = dict(t)
    try:
        if has_file:
            for k in ("k", "pga_2475"):
                if k in t:
                    _fail(f"hazard.{k}", "applies with pga_475 only (a file is the curve)")
            path = Path(base_dir) / _string("hazard.file", t["file"])
            fmt = _string("hazard.format", t.get("format", "auto"), site_hazard.FORMATS)
            site = t.get("site")
            if site is not None:
                if isinstance(site, list):
                    if len(site) != 2:
                        _fail("hazard.site", f"must be a row index or [lon, lat], got "
                                             f"{_toml(site)}")
                    site = [_number(f"hazard.site[{i}]", v, -360, 360)
                            for i, v in enumerate(site)]
                else:
                    site = _number("hazard.site", site, 0, MAX_SIMS, integer=True)
            im = _string("hazard.im", t["im"]) if "im" in t else None
            unit = _string("hazard.unit", t["unit"]) if "unit" in t else None
            inv = (_number("hazard.investigation_time", t["investigation_time"], 0,
                           site_hazard.MAX_T_YEARS, lo_open=True)
                   if "investigation_time" in t else None)
            dmax = (_number("hazard.max_distance_km", t["max_distance_km"], 0, math.inf,
                            lo_open=True) if "max_distance_km" in t else None)
            fr = t.get("fractiles", [])
            if isinstance(fr, str):
                fr = [fr]
            if not isinstance(fr, list):
                _fail("hazard.fractiles", f"must be a list of fractile files, got "
                                          f"{_toml(fr)}")
            fr = [Path(base_dir) / _string(f"hazard.fractiles[{i}]", f)
                  for i, f in enumerate(fr)]
            curve, source = site_hazard.read_hazard(path, format=fmt, site=site, im=im,
                                                    unit=unit, label=label,
                                                    investigation_time=inv,
                                                    max_distance_km=dmax, fractiles=fr)
        else:
            for k in ("format", "site", "im", "unit", "investigation_time",
                      "max_distance_km", "fractiles"):
                if k in t:
                    _fail(f"hazard.{k}", "applies with file only (pga_475 is a code value)")
            a = _quantity("hazard.pga_475", t["pga_475"])
            a2 = _quantity("hazard.pga_2475", t["pga_2475"]) if "pga_2475" in t else None
            k = _number("hazard.k", t["k"], 0, 20, lo_open=True) if "k" in t else None
            curve, source = site_hazard.code_value(a, k=k, pga_2475=a2, label=label)
    except ParameterError as e:
        if isinstance(e, SpecError):
            raise
        _hazard_fail(e, given)
    im = site_hazard.campaign_im(motions.im)
    why = site_hazard.mismatch(curve, im)
    if why is not None:
        _fail("hazard.file" if has_file else "hazard.pga_475",
              f"{why} ({'motions.im' if motions.im else 'no motions.im'})")
    return site_hazard.record(curve, source, t_years)


def _quantity(key: str, v) -> float:
    """A code PGA, in m/s^2, > 0: a bare number in g (the unit of
    :meth:`rocking.analysis.HazardCurve.from_code_value`) or a string with its unit
    (``"0.25g"``, ``"2.45m/s^2"``)."""
    if isinstance(v, bool) or not isinstance(v, str | int | float):
        _fail(key, f"must be a PGA: a number in g (0.25) or a string with its unit such as "
                   f"\"0.25g\", got {type(v).__name__} {v!r}")
    try:
        a = parse_quantity(v, "acceleration", name=key, default_unit="g")
    except ParameterError as e:
        _fail(key, str(e).removeprefix(key).lstrip(": "))
    if not a > 0:
        _fail(key, f"must be > 0, got {v!r}")
    return a


EXAMPLE_SPEC = """\
campaign = {name = "pulses", seed = 1, model = "housner"}
blocks = [{specimen = 2}]
run = {chunk_size = 2}
[motions]
kind = "one_sine"          # one-sine pulses of 1 m/s^2 ...
period = 0.5
amplitude = 1.0
load_factors = [1.0, 1.5, 2.0, 3.0]   # ... scaled: PGA 1 to 3 m/s^2
"""
"""A minimal campaign spec (TOML): four one-sine pulses on specimen 2, in two chunks. The
docstrings' examples run it; a starting point for a spec of your own."""

# ------------------------------------------------------------------------------ the spec
@dataclass(frozen=True)
class CampaignSpec:
    """A checked campaign spec (see the module docstring); build it with :func:`read_spec`
    or :func:`parse_spec`.

    Examples
    --------
    Four one-sine pulses on specimen 2, in chunks of two runs (:data:`EXAMPLE_SPEC`; a
    TOML inline table such as ``campaign = {...}`` is the same as a ``[campaign]`` table):

    >>> from rocking.campaign import EXAMPLE_SPEC, parse_spec
    >>> print(EXAMPLE_SPEC)
    campaign = {name = "pulses", seed = 1, model = "housner"}
    blocks = [{specimen = 2}]
    run = {chunk_size = 2}
    [motions]
    kind = "one_sine"          # one-sine pulses of 1 m/s^2 ...
    period = 0.5
    amplitude = 1.0
    load_factors = [1.0, 1.5, 2.0, 3.0]   # ... scaled: PGA 1 to 3 m/s^2
    <BLANKLINE>
    >>> spec = parse_spec(EXAMPLE_SPEC)
    >>> spec.name, spec.models, spec.n_sims, spec.n_chunks
    ('pulses', ('housner',), 4, 2)
    >>> spec.blocks[0].name
    'specimen 2 (theoretical)'
    """

    name: str
    seed: int
    models: tuple[str, ...]
    duration: float | None
    samples: int
    thresholds: tuple[float, ...]
    blocks: tuple
    """:class:`~rocking.Block` or :class:`~rocking.Stack` each (:func:`nominal`)."""
    motion_axis: MotionAxis
    """The checked ``[motions]`` (:class:`MotionAxis`; :attr:`motions` as a dict)."""
    uncertain_parameters: UncertainParameters
    """The checked ``[uncertain]`` (:class:`UncertainParameters`; :attr:`uncertain` as a
    dict)."""
    chunk_size: int
    window: int | None
    options: dict
    text: str = field(repr=False)
    raw: dict = field(repr=False)
    base_dir: str = "."
    """The folder that relative record paths start from."""
    max_free_time: float | None = None
    """Cap (s) of the free rocking after each motion (``duration`` unset); None: the
    package's default (:data:`rocking.models.run.DEFAULT_MAX_FREE_TIME`)."""
    building_axis: BuildingAxis | None = None
    """The checked ``[building]`` (:class:`BuildingAxis`; :attr:`building` as a dict), or
    None: the blocks stand on the ground."""
    mitigations: tuple = ()
    """The checked ``[[mitigation]]`` entries (:class:`Mitigation`), or ``()``: none given
    (the mitigation axis has size 1 and the table no ``mitigation`` column)."""
    block_digests: tuple = ()
    """Content digests of the files that ``[[blocks]]`` name (a mesh), in :attr:`hash`."""
    hazard: dict | None = None
    """The checked ``[hazard]``: the manifest's record of the site's hazard curve
    (:func:`rocking.campaign.hazard.record`), or None. Not in :attr:`hash`: it changes no
    run, only the report."""
    headings: tuple = ()
    """The heading axis (deg; a 3-D model's ``[options.rigid3d] heading`` given as a list
    or grid: the body's x axis from a pair's first component), or ``()``: none (size 1,
    the table without a ``heading`` column)."""

    @property
    def motions(self) -> dict:
        """The checked ``[motions]`` as a plain dict (:meth:`MotionAxis.to_dict`, a new one
        each time; the manifest's ``motions``)."""
        return self.motion_axis.to_dict()

    @property
    def uncertain(self) -> dict:
        """The checked ``[uncertain]`` as ``{parameter: distribution}`` (a new dict each
        time: :meth:`UncertainParameters.to_dict`)."""
        return self.uncertain_parameters.to_dict()

    @property
    def building(self) -> dict | None:
        """The checked ``[building]`` as a plain dict (:meth:`BuildingAxis.to_dict`, a new
        one each time; :func:`building_model` builds it), or None: the blocks stand on the
        ground."""
        return None if self.building_axis is None else self.building_axis.to_dict()

    @property
    def runs(self) -> tuple[tuple[str, dict], ...]:
        """``(model, options)`` of each index of the first axis of :attr:`shape` (the
        models, or with ``[[mitigation]]`` the mitigations of the single model; with a
        heading axis each of them once per heading, the heading fastest): what a row
        runs."""
        base = (tuple((m.model, m.options) for m in self.mitigations) if self.mitigations
                else tuple((m, self.options.get(m, {})) for m in self.models))
        if not self.headings:
            return base
        return tuple((m, {**o, "heading": h}) for m, o in base for h in self.headings)

    @property
    def run_models(self) -> tuple[str, ...]:
        """The models the campaign runs, in the order of their first appearance."""
        return tuple(dict.fromkeys(m for m, _ in self.runs))

    @property
    def hash(self) -> str:
        """SHA-256 of what the results depend on: the parsed TOML (not its formatting or
        comments; without ``[run] window``, which only schedules, and without ``[hazard]``,
        which only the report uses) and, for record and mesh files, their contents (a
        digest each), not where they are."""
        raw = {k: v for k, v in self.raw.items() if k not in ("run", "hazard")}
        raw["run"] = {k: v for k, v in self.raw.get("run", {}).items() if k != "window"}
        digests = self.motion_axis.digests
        content = {"raw": raw, "digests": None if digests is None else list(digests)}
        if self.block_digests:  # a mesh file's content (absent: the hash of older specs)
            content["block_digests"] = list(self.block_digests)
        return hashlib.sha256(json.dumps(content, sort_keys=True, default=str)
                              .encode()).hexdigest()

    @property
    def levels(self) -> np.ndarray:
        """The intensity axis: load factors, or IM levels when ``im`` is set."""
        return np.asarray(self.motion_axis.intensity_levels)

    @property
    def im(self) -> str | None:
        return self.motion_axis.im

    @property
    def motion_kind(self) -> catalog.MotionKind:
        """The catalog entry of the motions."""
        return self.motion_axis.catalog_kind

    @property
    def n_motions(self) -> int:
        return self.motion_axis.n

    @property
    def floors(self) -> list:
        """The floor axis: floor numbers or height ratios (``[0]`` without a building)."""
        return [0] if self.building_axis is None else list(self.building_axis.values)

    @property
    def axes(self) -> dict[str, int]:
        """The size of each axis of :data:`AXES` (``model``, ``mitigation``, ``heading``,
        ``block``, ``floor``, ``motion``, ``level``, ``sample``), in the order of ``sim_id``
        (the last fastest): the mitigation axis has size 1 without ``[[mitigation]]``, the
        heading axis without a list of headings and the floor axis without
        ``[building]``, so that the ids of a spec without them are those of the other
        axes."""
        return dict(zip(AXES, (len(self.models), max(1, len(self.mitigations)),
                               max(1, len(self.headings)),
                               len(self.blocks), len(self.floors), self.n_motions,
                               self.levels.size, self.samples), strict=True))

    @property
    def shape(self) -> tuple[int, int, int, int, int, int]:
        """``(runs, blocks, floors, motions, levels, samples)``: the axes of the
        simulation table, ``sim_id`` running fastest over the last; ``runs`` is the model
        axis, or with ``[[mitigation]]`` (one model) the mitigation axis, times the
        heading axis: :attr:`runs`.
        The same ids as :attr:`axes` (one of the model and mitigation axes has size 1)."""
        a = self.axes
        return (a["model"] * a["mitigation"] * a["heading"], a["block"], a["floor"],
                a["motion"], a["level"], a["sample"])

    @property
    def n_sims(self) -> int:
        return math.prod(self.shape)  # Python ints: no overflow

    @property
    def n_chunks(self) -> int:
        return -(-self.n_sims // self.chunk_size)


def _models(c: dict) -> tuple[str, ...]:
    listed = isinstance(c["model"], list)
    models = c["model"] if listed else [c["model"]]
    if not models:
        _fail("campaign.model", "is empty")
    models = tuple(_string(f"campaign.model[{i}]" if listed else "campaign.model", m,
                           tuple(MODELS)) for i, m in enumerate(models))
    if len(set(models)) != len(models):
        _fail("campaign.model", "has repeated models")
    return models


def _thresholds(c: dict) -> tuple[float, ...]:
    thr = c.get("thresholds", list(DEFAULT_THRESHOLDS))
    if not isinstance(thr, list):
        _fail("campaign.thresholds", f"must be a list of numbers, got {thr!r}")
    for i, x in enumerate(thr):
        _number(f"campaign.thresholds[{i}]", x, 0, lo_open=True)
    try:
        state_labels(thr)
    except ParameterError as e:
        _fail("campaign.thresholds", str(e))
    return tuple(float(x) for x in thr)


def _campaign(raw: dict) -> dict:
    """The checked ``[campaign]`` table."""
    c = _table("campaign", raw.get("campaign", {}))
    _known("campaign", c, CAMPAIGN_KEYS)
    for k in ("name", "seed", "model"):
        if k not in c:
            _fail(f"campaign.{k}", "missing")
    out = {"name": _string("campaign.name", c["name"]),
           "seed": _number("campaign.seed", c["seed"], 0, MAX_SIMS, integer=True),
           "models": _models(c),
           "duration": (_number("campaign.duration", c["duration"], 0, 1e6, lo_open=True)
                        if "duration" in c else None),
           "max_free_time": None}
    if "max_free_time" in c:
        out["max_free_time"] = _number("campaign.max_free_time", c["max_free_time"], 0,
                                       MAX_RECORD_DURATION)
        if out["duration"] is not None:
            _fail("campaign.max_free_time", "applies only without campaign.duration (a run "
                                            "with a duration stops exactly there)")
    out["samples"] = _number("campaign.samples", c.get("samples", 1), 1, 1e9, integer=True)
    out["thresholds"] = _thresholds(c)
    return out


def _uncertain(raw: dict, c: dict, blocks: tuple, motions: MotionAxis,
               models: tuple) -> UncertainParameters:
    """The checked ``[uncertain]`` table (each distribution against each block)."""
    uncertain = _table("uncertain", raw.get("uncertain", {}))
    _known("uncertain", uncertain, PARAMETERS)
    for k, d in uncertain.items():
        if not isinstance(d, dict):
            _fail(f"uncertain.{k}", f"must be a table with dist, got {d!r}")
    for i, b in enumerate(blocks):
        try:
            distributions(nominal(b), uncertain, where=lambda k: f"uncertain.{k}",
                          of=f" of blocks[{i}]" if len(blocks) > 1 else "")
        except ParameterError as e:  # "uncertain.k.sub must ..." or "uncertain.k: ..."
            key, _, msg = str(e).partition(" ")
            _fail(key.rstrip(":"), msg)
    if c["samples"] > 1 and not uncertain:
        _fail("campaign.samples", f"is {c['samples']}, but nothing is uncertain: the samples "
                                  "would be identical runs (give [uncertain] parameters, or "
                                  "samples = 1)")
    geometry = sorted(set(uncertain) & {"alpha", "p", "mu", "theta0"})
    if geometry and "dem" in models:
        _fail(f"uncertain.{geometry[0]}", "not supported with model 'dem' (its geometry and "
                                          "contacts define alpha, p and mu; it starts at rest)")
    if "noise" in uncertain and motions.catalog_kind.vertical:
        _fail("uncertain.noise", f"not supported with kind {motions.kind!r} (the noise is "
                                 "added to samples of the horizontal component only)")
    return UncertainParameters(tuple(
        Distribution(k, tuple((key, _frozen(v)) for key, v in d.items()))
        for k, d in uncertain.items()))


def _check_size(c: dict, blocks: tuple, motions: MotionAxis, building: BuildingAxis | None,
                n_mitigations: int = 0, n_headings: int = 0) -> None:
    floors = [0] if building is None else building.values
    shape = (len(c["models"]) * max(1, n_mitigations) * max(1, n_headings), len(blocks),
             len(floors),
             motions.n, len(motions.intensity_levels), c["samples"])
    if math.prod(shape) > MAX_SIMS:
        axes = {"mitigation" if n_mitigations else "campaign.model": shape[0],
                "blocks": shape[1],
                f"building.{building.axis}s" if building else "building": shape[2],
                f"motions.{motions.axis}": shape[3],
                "motions.levels" if motions.im else "motions.load_factors": shape[4],
                "campaign.samples": shape[5]}
        key = max(axes, key=axes.get)
        _fail(key, f"the campaign would have {math.prod(shape):.3g} simulations ("
                   + " x ".join(f"{v} {k}" for k, v in axes.items())
                   + "); at most 2^63 - 1 (sim_id is an int64)")


def _run(raw: dict) -> tuple[int, int | None]:
    r = _table("run", raw.get("run", {}))
    _known("run", r, RUN_KEYS)
    chunk = _number("run.chunk_size", r.get("chunk_size", 2000), 1, 1e7, integer=True)
    window = _number("run.window", r["window"], 1, 1e5, integer=True) if "window" in r \
        else None
    return chunk, window


QUANTITIES = {"m": "length", "s": "time", "m/s^2": "acceleration", "Hz": "frequency",
              "rad": "angle", "": "ratio"}
"""The quantity (:data:`rocking.units.KINDS`) of a model option's SI unit: a string with a
unit given for an option that declares no ``quantity`` is read as this one."""


def option_values(model: str, values: dict, key: str) -> dict:
    """``values`` (options of ``model``) with every string that carries a unit (``"2.5s"``,
    ``"0.15m"``, ``"10%"``) converted to the option's SI unit: as the option's declared
    ``quantity`` (as its ``Options`` would), or else as the quantity of its unit
    (:data:`QUANTITIES`; a bare number in a string is then refused). Errors name
    ``key.<option>``."""
    fields = {f.name: f.metadata for f in dataclasses.fields(MODELS[model].Options)}
    out = dict(values)
    for name, v in values.items():
        m = fields.get(name)
        if not (isinstance(v, str) and m and m.get("kind") is float
                and (m.get("quantity") or m.get("unit", "") in QUANTITIES)):
            continue
        declared = m.get("quantity")
        try:
            out[name] = parse_quantity(v, declared or QUANTITIES[m.get("unit", "")],
                                       name=name,
                                       default_unit=m.get("unit", "") if declared else None)
        except ParameterError as e:
            _fail(f"{key}.{name}", f"{str(e).removeprefix(name).lstrip(': ')} (the option "
                                   f"is in {m.get('unit') or 'a ratio'})")
    return out


def _build_options(model: str, values: dict, key: str, given=None) -> None:
    """Check ``values`` with the model's ``Options``; an error names ``key.<option>`` when
    the option is among ``given`` (default: all of ``values``), else ``key``."""
    given = values if given is None else given
    try:
        MODELS[model].Options.build(model, **values)
    except (TypeError, RockingError) as e:
        msg = str(e).splitlines()[0]
        opt = msg.split(" ", 1)[0]
        if opt in given and " " in msg:  # "rest_tol must be ...": name the option's key
            _fail(f"{key}.{opt}", msg.split(" ", 1)[1])
        _fail(key, msg)


def _options(raw: dict, models) -> dict:
    opts = _table("options", raw.get("options", {}))
    _known("options", opts, models)
    options = {}
    for m, o in opts.items():
        o = _table(f"options.{m}", o)
        if is_3d(m) and isinstance(o.get("heading"), list | dict):
            o = {k: v for k, v in o.items() if k != "heading"}  # the heading axis
        o = option_values(m, o, f"options.{m}")
        _build_options(m, o, f"options.{m}")
        options[m] = dict(o)
    return options


@dataclass(frozen=True)
class Mitigation:
    """A checked ``[[mitigation]]`` entry: its ``name``, the ``model`` it runs and that
    model's ``options`` (``[options.<model>]`` with the entry's own over them, SI; a dict
    of its own, for :func:`rocking.simulate_many` and the manifest).

    Examples
    --------
    >>> from rocking.campaign import EXAMPLE_SPEC, parse_spec
    >>> mit = 'mitigation = [{name = "none"}, {name = "anchors", model = "anchored"}]\\n'
    >>> [(m.name, m.model) for m in parse_spec(mit + EXAMPLE_SPEC).mitigations]
    [('none', 'housner'), ('anchors', 'anchored')]
    """

    name: str
    model: str
    options: dict = field(hash=False)


def _mitigation_entries(raw: dict, c: dict) -> list[tuple[str, str, dict, bool]]:
    """The ``[[mitigation]]`` entries checked for their form, names and models:
    ``(name, model, own options, model given)`` each; ``[]`` without the section."""
    if "mitigation" not in raw:
        return []
    t = raw["mitigation"]
    if isinstance(t, dict):
        _fail("mitigation", "must be [[mitigation]] tables, one per mitigation (write "
                            "[[mitigation]], not [mitigation])")
    if not isinstance(t, list) or not t:
        _fail("mitigation", "must be one or more [[mitigation]] tables")
    if len(c["models"]) > 1:
        _fail("campaign.model", f"must be a single model with [[mitigation]], got "
                                f"{len(c['models'])} (each entry names the model it runs, "
                                "and an entry without model runs the campaign's)")
    entries, seen = [], {}
    for i, e in enumerate(t):
        key = f"mitigation[{i}]"
        e = _table(key, e)
        if "name" not in e:
            _fail(f"{key}.name", "missing (a short name: the table's mitigation column)")
        name = _string(f"{key}.name", e["name"])
        if not name.strip() or len(name) > MAX_NAME:
            _fail(f"{key}.name", f"must be 1 to {MAX_NAME} characters, not blank; got "
                                 f"{name!r}")
        _printable(f"{key}.name", name)
        if name.strip() in seen:
            _fail(f"{key}.name", f"{name!r} is already the name of "
                                 f"mitigation[{seen[name.strip()]}] (names are unique)")
        seen[name.strip()] = i
        model = (_string(f"{key}.model", e["model"], tuple(MODELS)) if "model" in e
                 else c["models"][0])
        own = {k: v for k, v in e.items() if k not in ("name", "model")}
        _known(key, own, {"name", "model", *MODELS[model].Options.names()})
        entries.append((name, model, own, "model" in e))
    return entries


def _mitigations(entries: list, options: dict) -> tuple[Mitigation, ...]:
    """The checked entries: each one's options (SI) merged over ``[options.<model>]`` and
    checked by its model's ``Options``."""
    out = []
    for i, (name, model, own, _) in enumerate(entries):
        key = f"mitigation[{i}]"
        own = option_values(model, own, key)
        merged = {**options.get(model, {}), **own}
        _build_options(model, merged, key, own)
        out.append(Mitigation(name, model, dict(merged)))
    return tuple(out)


def _usable(models: tuple, blocks: tuple, options: dict, entries=(),
            mitigations=()) -> None:
    """Each block must suit each model run (the DEM needs a geometry; a stack, the DEM)."""
    if mitigations:
        for i, ((_, _, _, given), mit) in enumerate(zip(entries, mitigations, strict=True)):
            for j, b in enumerate(blocks):
                try:
                    with each_warning_once():  # said here, not again by each chunk
                        MODELS[mit.model].from_kwargs(b, **mit.options)
                except RockingError as e:
                    if given:
                        _fail(f"mitigation[{i}].model", f"model {mit.model!r} cannot take "
                                                        f"blocks[{j}] ({b.name}): {e}")
                    _fail(f"blocks[{j}]", f"not usable with model {mit.model!r} (of "
                                          f"mitigation[{i}] {mit.name!r}): {e}")
        return
    for m in models:
        for i, b in enumerate(blocks):
            try:
                with each_warning_once():
                    MODELS[m].from_kwargs(b, **options.get(m, {}))
            except RockingError as e:
                _fail(f"blocks[{i}]", f"not usable with model {m!r}: {e}")


def parse_spec(text: str, base_dir=".") -> CampaignSpec:
    """Check a spec given as TOML text (record paths relative to ``base_dir``).

    Examples
    --------
    >>> from rocking.campaign import EXAMPLE_SPEC, parse_spec
    >>> spec = parse_spec(EXAMPLE_SPEC)
    >>> spec.n_sims, spec.motions["load_factors"]
    (4, [1.0, 1.5, 2.0, 3.0])
    """
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise SpecError(f"spec: not valid TOML: {e}") from None
    _known("", raw, SECTIONS)
    c = _campaign(raw)
    entries = _mitigation_entries(raw, c)
    run_models = tuple(dict.fromkeys(e[1] for e in entries)) if entries else c["models"]
    body = _three_d(c, run_models, raw)
    blocks, block_digests = _blocks(raw, Path(base_dir).resolve(), body)
    if "motions" not in raw:
        _fail("motions", "missing (a [motions] table with kind)")
    motions = _motions(raw["motions"], Path(base_dir).resolve(), c["seed"])
    if motions.kind in catalog.KINDS_3D and not body:
        _fail("motions.kind", f"{motions.kind!r} (two horizontal components) needs a 3-D "
                              f"model: campaign.model = \"rigid3d\" (the planar models take "
                              "one component)")
    uncertain = _uncertain(raw, c, blocks, motions, run_models)
    building = _building(raw)
    headings = _headings(raw, run_models)
    if body:
        _orientation(raw, run_models, motions.kind in catalog.KINDS_3D)
    _check_size(c, blocks, motions, building, len(entries), len(headings))
    chunk, window = _run(raw)
    options = _options(raw, tuple(dict.fromkeys(c["models"] + run_models)))
    mitigations = _mitigations(entries, options)
    _usable(c["models"], blocks, options, entries, mitigations)
    hazard = _hazard(raw, Path(base_dir).resolve(), motions)
    return CampaignSpec(name=c["name"], seed=c["seed"], models=c["models"],
                        duration=c["duration"], samples=c["samples"],
                        thresholds=c["thresholds"], blocks=blocks, motion_axis=motions,
                        uncertain_parameters=uncertain, chunk_size=chunk, window=window,
                        options=options, text=text, raw=raw,
                        base_dir=str(Path(base_dir).resolve()),
                        max_free_time=c["max_free_time"], building_axis=building,
                        mitigations=mitigations, block_digests=block_digests,
                        hazard=hazard, headings=headings)


def read_spec(path) -> CampaignSpec:
    """Read and check the spec at ``path`` (see the module docstring).

    Examples
    --------
    >>> from pathlib import Path
    >>> from rocking.campaign import EXAMPLE_SPEC, read_spec
    >>> _ = Path("pulses.toml").write_text(EXAMPLE_SPEC)
    >>> spec = read_spec("pulses.toml")
    >>> spec.name, spec.n_sims
    ('pulses', 4)
    """
    p = Path(path)
    if not p.is_file():
        raise SpecError(f"spec: no such file: {p}")
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise SpecError(f"spec: cannot read {p}: {e}") from None
    return parse_spec(text, base_dir=p.resolve().parent)


# ------------------------------------------------------------------ the README's table
KEYS_START, KEYS_END = "<!-- spec-keys:start -->", "<!-- spec-keys:end -->"
"""The markers of the README's generated table (:func:`write_keys_table`)."""


def _cell(x) -> str:
    return str(x).replace("|", "\\|")


def _rows(head: list[str], rows: list[list]) -> list[str]:
    return (["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
            + ["| " + " | ".join(_cell(x) for x in r) + " |" for r in rows])


def _default(d: dict, every=None) -> str:
    if every is not None:
        return f"all {len(every())}"
    if d["required"]:
        return "required"
    return "" if d["default"] is None else f"`{_toml(d['default'])}`"


def _several(kind: catalog.MotionKind, d: dict) -> str:
    """How a parameter may give several motions (the README's column)."""
    if d["name"] == COUNTER and COUNTER in kind.sweep:
        return f"list, grid, or {COUNT}"
    if d["name"] not in kind.sweep:
        return ""
    return "list, glob" if d["name"] in kind.files else \
        "list, grid" if d["kind"] in (int, float) else "list"


def _motion_rows() -> list[list]:
    rows = [["(all)", f"`{k}`", "", "", "", "", h] for k, h in
            {"kind": "the motion kind (below)", **INTENSITY_KEYS}.items()]
    for k in [*catalog.KINDS.values(), *catalog.KINDS_3D.values()]:
        if COUNTER in k.sweep:
            rows.append([f"`{k.name}`", f"`{COUNT}`", "", "[0, 1e7]", "required", "",
                         f"the records {COUNTER} = 0 .. n-1 (or give {COUNTER})"])
        for d in k.describe():
            every = k.every if k.sweep and d["name"] == k.sweep[0] else None
            rows.append([f"`{k.name}`", f"`{d['name']}`", d["unit"], d["range"],
                         _default(d, every), _several(k, d), d["help"]])
    return rows


def _legacy_text() -> str:
    old = []
    for o, (n, keys) in LEGACY.items():
        renamed = ", ".join(f"`{a}` → `{b}`" for a, b in keys.items() if b != "kind")
        implied = ", ".join(f"{k} = {v}" for k, v in LEGACY_DEFAULTS.get(o, {}).items())
        old.append(f"`{o}` → `{n}`" if n else f"`{o}` → the kind its `pulse` names")
        old[-1] += f" ({renamed}" + (f"; write {implied}, once implied" if implied else "") + ")"
    return ("Old spellings, still read with a DeprecationWarning that says how to write them: "
            + "; ".join(old) + ".")


def keys_table() -> str:
    """Every spec key as Markdown, generated from the sections' keys, the block factory
    (:data:`rocking.blocks.factory.FORMS`) and the motion catalog
    (:data:`rocking.motions.catalog.KINDS`): the README's table."""
    out = ["**`[campaign]`**", ""] + _rows(["key", "meaning"], [[f"`{k}`", h] for k, h in
                                                                CAMPAIGN_KEYS.items()])
    blocks = [["(all)", "`name`", "", "", "the form's name and `(blocks[i])`",
               "names the block in the table (`block_name`)"]]
    blocks += [[f"{f.name} (`{f.key}`)", f"`{d['name']}`", d["unit"], d["range"],
                _default(d), d["help"]] for f in factory.FORMS.values() for d in f.describe()]
    out += ["", "**`[[blocks]]`**, one table per block; its form is told by its key (a "
            "stack is stood for by its top block in `alpha`, `p`, `mu`). A 3-D model "
            "(`rigid3d`, which then runs alone) takes 3-D bodies: `box`, `cylinder`, a `mesh` "
            "(the whole mesh, without its planar keys), or a rectangle or specimen as a box; "
            "its rows' `alpha`, `p`, `mu` are those of the body's weakest direction and "
            "`max_abs_theta` its `max_tilt`:", ""]
    out += _rows(["form", "key", "unit", "range", "default", "meaning"], blocks)
    out += ["", "**`[motions]`**: `kind` and that kind's parameters; at most one parameter "
            "gives several motions (the motion axis), as a list, a grid `{start, stop, num, "
            "spacing}` or glob patterns (file paths are relative to the spec):", ""]
    out += _rows(["kind", "key", "unit", "range", "default", "several", "meaning"],
                 _motion_rows())
    out += ["", _legacy_text()]
    out += ["", "**`[uncertain]`**: `{dist = ...}` per parameter "
            "(`rocking.analysis.montecarlo`; a drawn `alpha`, `p` or `mu` of an asymmetric "
            "block, e.g. a `mesh` block, scales both its sides by drawn / nominal):", ""]
    out += _rows(["key", "range"], [[f"`{k}`", RANGES[k]] for k in PARAMETERS])
    out += ["", "**`[run]`**", ""] + _rows(["key", "meaning"],
                                          [[f"`{k}`", h] for k, h in RUN_KEYS.items()])
    out += ["", "**`[options.<model>]`**: the model's options, as `rocking models` lists "
            "them (a quantity may carry its unit: `\"2.5s\"`, `\"0.15m\"`, `\"10%\"`). "
            "`[options.rigid3d] heading` (deg) given as a list or a grid is the heading axis "
            "(after the model and mitigation axes; a `heading` column): every run once per "
            "heading of the pair."]
    out += ["", "**`[[mitigation]]`** (optional): one table per mitigation, the mitigation "
            "axis (after the model axis; `campaign.model` then a single model); the table "
            "gets a `mitigation` column and the models' row outputs:", ""]
    out += _rows(["key", "meaning"], [[f"`{k}`" if k[0] != "(" else k, h]
                                      for k, h in MITIGATION_KEYS.items()])
    out += ["", "**`[building]`** (optional): the blocks stand on floors of a building "
            "(`rocking buildings`); `kind` and that kind's keys, and the floor axis. The "
            "levels scale the ground motion (the same ground intensity on every floor):", ""]
    shown = {"kind": ("", "required"), "floors": ("0 .. n_floors", "floors or height_ratios"),
             "height_ratios": ("[0, 1]", "")}
    rows = [["(all)", f"`{k}`", "", *shown[k], h] for k, h in
            {"kind": "the building kind (below)", **FLOOR_KEYS}.items()]
    rows += [[f"`{d['kind']}`", f"`{d['name']}`", d["unit"], d["range"], _default(d),
              d["help"]] for d in buildings.table()]
    out += _rows(["kind", "key", "unit", "range", "default", "meaning"], rows)
    out += ["", "**`[hazard]`** (optional): the site's hazard curve, for the annual frequency "
            "of overturning and its probability over `t_years` in `rocking campaign report`; "
            "`file` or `pga_475`. Its IM must be the campaign's (`motions.im`, or the PGA of "
            "each run); its points are kept in the manifest; it is not in the spec hash (a "
            "store resumes with another `[hazard]`):", ""]
    out += _rows(["key", "meaning"], [[f"`{k}`", h] for k, h in
                                      site_hazard.HAZARD_KEYS.items()])
    return "\n".join(out) + "\n"


def write_keys_table(readme) -> None:
    """Rewrite the table between :data:`KEYS_START` and :data:`KEYS_END` in ``readme``."""
    p = Path(readme)
    text = p.read_text(encoding="utf-8")
    head, _, rest = text.partition(KEYS_START)
    _, _, tail = rest.partition(KEYS_END)
    p.write_text(f"{head}{KEYS_START}\n{keys_table()}{KEYS_END}{tail}", encoding="utf-8")


# ------------------------------------------------------------------------------- 3-D
HEADING_KEY = "heading"
"""``[options.rigid3d] heading`` given as a list or a grid ``{start, stop, num}`` (deg)
sets the heading axis (:attr:`CampaignSpec.headings`): every run once per heading."""


def _three_d(c: dict, run_models: tuple, raw: dict) -> bool:
    """True if the campaign runs a 3-D model (``rigid3d``): then it runs 3-D models only
    (its ``[[blocks]]`` are 3-D bodies), with neither ``[uncertain]`` nor ``[building]``."""
    models = tuple(dict.fromkeys(c["models"] + run_models))
    three = [m for m in models if is_3d(m)]
    if not three:
        return False
    if len(three) != len(models):
        planar = next(m for m in models if not is_3d(m))
        _fail("campaign.model", f"{three[0]!r} is a 3-D model (its [[blocks]] are 3-D bodies: "
                                f"box, cylinder, mesh) and {planar!r} a planar one: run them "
                                "in separate campaigns")
    for section, why in (("uncertain", "a 3-D body's geometry is its shape"),
                         ("building", "floor motions are one horizontal component")):
        if section in raw:
            _fail(section, f"not supported with model {three[0]!r} ({why})")
    return True


def _headings(raw: dict, models: tuple) -> tuple[float, ...]:
    """The heading axis (deg): ``[options.<3-D model>] heading`` as a list or a grid;
    ``()`` when it is a single value or absent."""
    opts = raw.get("options", {})
    if not isinstance(opts, dict):
        return ()
    for m in models:
        o = opts.get(m)
        if not (is_3d(m) and isinstance(o, dict) and isinstance(o.get(HEADING_KEY),
                                                               list | dict)):
            continue
        key = f"options.{m}.{HEADING_KEY}"
        v = o[HEADING_KEY]
        values = grid(key, v, -360.0, lo_open=False).tolist() if isinstance(v, dict) else [
            _number(f"{key}[{i}]", x, -360.0, 360.0) for i, x in enumerate(v)]
        if not values:
            _fail(key, "is empty (a list of headings in deg, or one number)")
        if any(not -360.0 <= x <= 360.0 for x in values):
            _fail(key, "must lie in [-360, 360] deg")
        if len(set(values)) != len(values):
            _fail(key, "has repeated values (one heading each)")
        return tuple(float(x) for x in values)
    return ()


def _orientation(raw: dict, models: tuple, pair: bool) -> None:
    """Never an option the runs would ignore: ``heading`` orients a pair (``kind =
    "pair"``), ``direction`` a single horizontal motion (with a pair it only says where
    ``tilt0`` leans)."""
    opts = raw.get("options", {})
    tables = [(f"options.{m}", opts.get(m)) for m in models]
    tables += [(f"mitigation[{i}]", e) for i, e in enumerate(raw.get("mitigation") or [])]
    for key, t in tables:
        if not isinstance(t, dict):
            continue
        if "heading" in t and not pair:
            _fail(f"{key}.heading", 'orients a pair of horizontal components (motions.kind = '
                                    '"pair"); a single horizontal motion acts along direction')
        if "direction" in t and pair and not t.get("tilt0"):
            _fail(f"{key}.direction", "with a pair the body's orientation is heading (deg "
                                      "from the first component); direction only says where "
                                      "tilt0 leans")
