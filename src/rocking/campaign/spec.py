"""The campaign spec: one TOML file that declares a study, checked key by key.

::

    [campaign]
    name = "fragility-2-4"
    seed = 7                      # every random draw derives from (seed, sim_id)
    model = "housner"             # or a list: ["housner", "ccrr"]
    duration = 25.0               # s, optional: default each motion's own duration, then
                                  # free rocking until the block has settled
    max_free_time = 60.0          # s, optional (only without duration): cap of that free
                                  # rocking (default rocking.models.run.DEFAULT_MAX_FREE_TIME;
                                  # 0 stops at the end of each motion)
    samples = 1                   # optional: realizations of [uncertain] per (block, motion, level)
    thresholds = [0.25, 0.5]      # optional: damage states on max|theta|/alpha

    [[blocks]]                    # one table per block, one of three forms
    specimen = 2
    params = "experimental"       # theoretical | experimental | geometric
    [[blocks]]
    width = 0.25                  # m, full width and height (Eq 2, Eq 3, Eq 4)
    height = 1.0
    [[blocks]]
    alpha = 0.2                   # rad
    p = 2.1                       # 1/s
    mu = 0.96

    [motions]
    kind = "stochastic"           # seed_earthquakes | files | builtin | stochastic
                                  # | sine_grid | pulse_grid
    n = 100
    load_factors = {start = 0.5, stop = 3.0, num = 11}   # or a list
    # or: im = "pga" and levels = [1.0, 2.0, 4.0]          (m/s^2 for pga; pga_ratio and
    #     pgv_ratio use each block's nominal alpha and p, before any uncertain draw)

    [uncertain]                   # one entry per parameter (rocking.analysis.montecarlo)
    alpha = {dist = "normal", cov = 0.02}
    theta0 = {dist = "uniform", low = -0.001, high = 0.001}

    [run]
    chunk_size = 2000

    [options.housner]             # optional model options (rocking models)
    rest_tol = 1e-12

Every motion kind and its keys are listed in :data:`MOTION_KEYS`. A malformed spec raises
:class:`~rocking.errors.SpecError` with one line that names the key and what it allows.
Everything that a spec can get wrong is found by :func:`parse_spec`, before a store is
created: every number is a number (never a bool: ``cov = true`` is refused), record files
are read (an unreadable one is refused), a record's length and sample count are bounded
before anything is allocated (:data:`MAX_RECORD_DURATION`, :data:`MAX_RECORD_SAMPLES`),
the number of simulations fits ``sim_id`` (int64), and every ``[uncertain]`` distribution
has at most 1 % of its mass outside its parameter's range (for ``theta0``: beyond +-alpha
of each block; :func:`rocking.analysis.montecarlo.distributions`).
"""

from __future__ import annotations

import hashlib
import json
import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..analysis.damage import DEFAULT_THRESHOLDS, state_labels
from ..analysis.ida import IMS
from ..analysis.montecarlo import PARAMETERS, distributions
from ..blocks import Block, specimen
from ..blocks.specimens import PARAM_SETS, specimen_ids
from ..errors import ParameterError, RockingError, SpecError
from ..models.registry import MODELS
from ..units import ACCELERATION

SECTIONS = {"campaign", "blocks", "motions", "uncertain", "run", "options"}
CAMPAIGN_KEYS = {"name", "seed", "model", "duration", "max_free_time", "samples",
                 "thresholds"}
RUN_KEYS = {"chunk_size", "window"}
BLOCK_FORMS = ({"specimen", "params"}, {"width", "height", "mass"}, {"alpha", "p", "mu"})
MOTION_KINDS = ("seed_earthquakes", "files", "builtin", "stochastic", "sine_grid", "pulse_grid")
STOCHASTIC_KEYS = {"n", "Ia", "D5_95", "t_mid", "omega_mid", "omega_prime", "zeta_f",
                   "omega_c", "dt", "record_duration"}
MOTION_KEYS = {
    "seed_earthquakes": {"records"},
    "files": {"paths", "units", "dt"},
    "builtin": {"names"},
    "stochastic": STOCHASTIC_KEYS,
    "sine_grid": {"frequencies", "amplitude", "cycles", "record_duration"},
    "pulse_grid": {"pulse", "periods", "amplitude", "record_duration"},
}
"""Keys of ``[motions]`` for each ``kind`` (besides ``kind``, ``load_factors``, ``im`` and
``levels``):

* ``seed_earthquakes``: ``records`` (numbers 1-30, default all 30): the paper's
  spectrum-compatible set (:func:`rocking.motions.seed_earthquakes`).
* ``files``: ``paths`` (relative to the spec file), ``units`` (``g``, ``m/s^2``,
  ``cm/s^2``; default ``g``), ``dt`` (s, for one-column files).
* ``builtin``: ``names`` (default all): the records shipped with the package.
* ``stochastic``: ``n`` records of :func:`rocking.motions.stochastic_records` with its
  parameters (``Ia``, ``D5_95``, ``t_mid``, ``omega_mid``, ``omega_prime``, ``zeta_f``,
  ``omega_c``, ``dt``; ``record_duration`` its ``duration``), seeded from the campaign seed.
* ``sine_grid``: ``frequencies`` (Hz), ``amplitude`` (peak acceleration, m/s^2, default 1:
  the load factor is then the amplitude in m/s^2), ``cycles`` (default 10) or
  ``record_duration`` (s).
* ``pulse_grid``: ``pulse`` (``one_sine``, ``one_cosine``, ``half_sine``, ``rectangular``,
  ``ricker``), ``periods`` (s; the Ricker's 1/fp), ``amplitude`` (m/s^2, default 1),
  ``record_duration`` (s, optional window).
"""
PULSES = ("one_sine", "one_cosine", "half_sine", "rectangular", "ricker")
MAX_RECORD_DURATION = 1e4
"""Longest motion a spec may define (s): ``record_duration``, or ``cycles / frequency`` of
a sine. The longest strong-motion records are a few hundred seconds (long-period records
of the 2011 Tohoku earthquake: about 300-600 s); 1e4 s (2.8 h) is 15 times more, while a
sine of 1e9 s would run for days and a stochastic record of 1e9 s would allocate 745 GB."""
MAX_RECORD_SAMPLES = 10 ** 7
"""Most samples of one stochastic record (``duration / dt + 1``): 80 MB per array (the
generator holds a few such arrays per record, and a worker keeps many records)."""
MAX_SIMS = 2 ** 63 - 1
"""Most simulations of a campaign: ``sim_id`` is an int64."""


def _fail(key: str, msg: str):
    raise SpecError(f"spec: {key}: {msg}")


def _number(key: str, v, lo: float = -math.inf, hi: float = math.inf, *, lo_open=False,
            integer: bool = False) -> float:
    if isinstance(v, bool) or not isinstance(v, int | float):
        _fail(key, f"must be a {'whole number' if integer else 'number'}, "
                   f"got {type(v).__name__} {v!r}")
    if integer and not isinstance(v, int):
        _fail(key, f"must be a whole number, got {v!r}")
    if not math.isfinite(v) or v < lo or v > hi or (lo_open and v == lo):
        lo_s = "-inf" if lo == -math.inf else f"{lo:g}"
        hi_s = "inf" if hi == math.inf else f"{hi:g}"
        _fail(key, f"must be in {'(' if lo_open else '['}{lo_s}, {hi_s}], got {v!r}")
    return v


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


def _known(key: str, table: dict, allowed) -> None:
    unknown = sorted(set(table) - set(allowed))
    if unknown:
        where = f"{key}." if key else ""
        _fail(f"{where}{unknown[0]}", f"unknown key (allowed in [{key or 'spec'}]: "
                                      f"{', '.join(sorted(allowed))})")


def grid(key: str, v, lo: float = 0.0, *, lo_open: bool = True) -> np.ndarray:
    """A list of numbers, or ``{start, stop, num}`` (linear; ``spacing = "log"`` for log)."""
    if isinstance(v, dict):
        _known(key, v, {"start", "stop", "num", "spacing"})
        for k in ("start", "stop", "num"):
            if k not in v:
                _fail(f"{key}.{k}", "missing (a grid is {start, stop, num})")
        a = _number(f"{key}.start", v["start"], lo, lo_open=lo_open)
        b = _number(f"{key}.stop", v["stop"], lo, lo_open=lo_open)
        n = int(_number(f"{key}.num", v["num"], 1, 1e7, integer=True))
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


# ------------------------------------------------------------------------------- blocks
def _block(i: int, t) -> Block:
    key = f"blocks[{i}]"
    t = _table(key, t)
    allowed = set().union(*BLOCK_FORMS) | {"name"}
    _known(key, t, allowed)
    forms = [f for f in BLOCK_FORMS if set(t) & f - ({"params"} if "specimen" in f else set())]
    if len(forms) != 1:
        _fail(key, "give exactly one of: specimen (+ params), width + height (+ mass), "
                   f"alpha + p + mu; got keys {', '.join(sorted(t)) or 'none'}")
    name = _string(f"{key}.name", t["name"]) if "name" in t else None
    f = forms[0]
    missing = sorted(f - set(t) - {"params", "mass"})
    if missing:
        _fail(f"{key}.{missing[0]}", "missing")
    try:
        if "specimen" in f:
            n = t["specimen"]
            if isinstance(n, bool) or not isinstance(n, int) or n not in specimen_ids():
                _fail(f"{key}.specimen", f"unknown specimen {n!r} (known: "
                                         f"{', '.join(map(str, specimen_ids()))})")
            params = _string(f"{key}.params", t.get("params", "theoretical"), PARAM_SETS)
            b = specimen(n, params)
        elif "width" in f:
            mass = _number(f"{key}.mass", t["mass"], 0, lo_open=True) if "mass" in t else None
            w = _number(f"{key}.width", t["width"], 0, lo_open=True)
            h = _number(f"{key}.height", t["height"], 0, lo_open=True)
            # without a name: what the block is, and where it stands in the spec
            b = Block.rectangular(w, h, mass=mass, name=f"{w:g} x {h:g} m block ({key})")
        else:
            a = _number(f"{key}.alpha", t["alpha"], 0, math.pi / 2, lo_open=True)
            p = _number(f"{key}.p", t["p"], 0, lo_open=True)
            b = Block.from_params(a, p, _number(f"{key}.mu", t["mu"], 0, 1, lo_open=True),
                                  name=f"alpha {a:.4g} rad, p {p:.4g} 1/s block ({key})")
    except SpecError:
        raise
    except RockingError as e:
        _fail(key, str(e))
    return b.with_params(name=name) if name else b


# ------------------------------------------------------------------------------ motions
def _motions(t: dict, base_dir: Path) -> dict:
    t = _table("motions", t)
    if "kind" not in t:
        _fail("motions.kind", f"missing (one of {', '.join(MOTION_KINDS)})")
    kind = _string("motions.kind", t["kind"], MOTION_KINDS)
    _known("motions", t, MOTION_KEYS[kind] | {"kind", "load_factors", "im", "levels"})
    out: dict = {"kind": kind}
    if kind == "seed_earthquakes":
        recs = t.get("records", list(range(1, 31)))
        if not isinstance(recs, list):
            _fail("motions.records", f"must be a list of record numbers 1-30, got {recs!r}")
        out["records"] = [int(_number(f"motions.records[{i}]", r, 1, 30, integer=True))
                          for i, r in enumerate(recs)]
        if len(set(out["records"])) != len(out["records"]):
            _fail("motions.records", "has repeated record numbers")
    elif kind == "files":
        paths = t.get("paths")
        if paths is None:
            _fail("motions.paths", "missing (a list of record files)")
        if not isinstance(paths, list) or not all(isinstance(p, str) for p in paths):
            _fail("motions.paths", f"must be a list of file paths, got {paths!r}")
        units = _string("motions.units", t.get("units", "g"), tuple(ACCELERATION))
        dt = _number("motions.dt", t["dt"], 0, lo_open=True) if "dt" in t else None
        resolved, digests = [], []
        for i, p in enumerate(paths):
            q = Path(p).expanduser()
            q = q if q.is_absolute() else base_dir / q
            if not q.is_file():
                _fail(f"motions.paths[{i}]", f"no such file: {q}")
            resolved.append(str(q.resolve()))
            digests.append(_read_record(f"motions.paths[{i}]", q, units, dt))
        out["paths"] = resolved
        out["names"] = list(paths)  # as written: the motion ids
        out["digests"] = digests
        out["units"] = units
        if dt is not None:
            out["dt"] = dt
    elif kind == "builtin":
        from ..motions import builtin_records
        names = t.get("names", builtin_records())
        if not isinstance(names, list):
            _fail("motions.names", f"must be a list of record names, got {names!r}")
        for i, n in enumerate(names):
            _string(f"motions.names[{i}]", n, builtin_records(three_component=True))
        out["names"] = list(names)
    elif kind == "stochastic":
        if "n" not in t:
            _fail("motions.n", "missing (the number of stochastic records)")
        out["n"] = int(_number("motions.n", t["n"], 0, 1e7, integer=True))
        for k in sorted(STOCHASTIC_KEYS - {"n"}):
            if k in t:
                out[k] = _number(f"motions.{k}", t[k])
        if "record_duration" in out:
            _number("motions.record_duration", out["record_duration"], 0,
                    MAX_RECORD_DURATION, lo_open=True)
        from ..motions.stochastic import DEFAULTS, HP_DECAY, modulating_parameters, record_model
        kw = {**DEFAULTS, **{k: v for k, v in out.items() if k in DEFAULTS}}
        if "record_duration" in out:
            kw["duration"] = out["record_duration"]
        try:
            _number("motions.dt", kw["dt"], 0, lo_open=True)
            if kw.get("duration") is not None:
                length, key = kw["duration"], "motions.record_duration"
            else:  # the generator's default length (rocking.motions.stochastic.record_model)
                tail = modulating_parameters(kw["Ia"], kw["D5_95"], kw["t_mid"])["t_tail"]
                hp = HP_DECAY / kw["omega_c"] if kw["omega_c"] > 0 else 0.0
                length, key = tail + hp, "motions.dt"
                if not length <= MAX_RECORD_DURATION:
                    _fail("motions.omega_c" if hp > tail else "motions.t_mid",
                          f"the records would last {length:g} s (t_tail {tail:g} s + "
                          f"{HP_DECAY:g} / omega_c); at most {MAX_RECORD_DURATION:g} s "
                          "(or give record_duration)")
            if not length / kw["dt"] + 1 <= MAX_RECORD_SAMPLES:
                _fail(key, f"a record of {length:g} s at dt = {kw['dt']:g} s would have "
                           f"{length / kw['dt']:.3g} samples; at most {MAX_RECORD_SAMPLES:.0e} "
                           "(raise dt or shorten record_duration)")
            record_model(**kw)
        except RockingError as e:
            if isinstance(e, SpecError):
                raise
            name = str(e).split()[0]
            _fail("motions." + ("record_duration" if name == "duration" else name), str(e))
    elif kind == "sine_grid":
        if "frequencies" not in t:
            _fail("motions.frequencies", "missing (Hz)")
        out["frequencies"] = grid("motions.frequencies", t["frequencies"]).tolist()
        out["amplitude"] = _number("motions.amplitude", t.get("amplitude", 1.0), 0,
                                   lo_open=True)
        if "cycles" in t and "record_duration" in t:
            _fail("motions.cycles", "give cycles or record_duration, not both")
        if "record_duration" in t:
            out["record_duration"] = _number("motions.record_duration",
                                             t["record_duration"], 0, MAX_RECORD_DURATION,
                                             lo_open=True)
        else:
            out["cycles"] = _number("motions.cycles", t.get("cycles", 10), 0, lo_open=True)
            longest = out["cycles"] / min(out["frequencies"])
            if longest > MAX_RECORD_DURATION:
                _fail("motions.cycles", f"{out['cycles']:g} cycles at "
                                        f"{min(out['frequencies']):g} Hz last {longest:g} s; "
                                        f"at most {MAX_RECORD_DURATION:g} s")
    else:  # pulse_grid
        if "pulse" not in t:
            _fail("motions.pulse", f"missing (one of {', '.join(PULSES)})")
        out["pulse"] = _string("motions.pulse", t["pulse"], PULSES)
        if "periods" not in t:
            _fail("motions.periods", "missing (s)")
        out["periods"] = grid("motions.periods", t["periods"]).tolist()
        out["amplitude"] = _number("motions.amplitude", t.get("amplitude", 1.0), 0,
                                   lo_open=True)
        if "record_duration" in t:
            out["record_duration"] = _number("motions.record_duration",
                                             t["record_duration"], 0, MAX_RECORD_DURATION,
                                             lo_open=True)
    # the intensity axis
    has_lf, has_im = "load_factors" in t, ("im" in t or "levels" in t)
    if has_lf and has_im:
        _fail("motions.load_factors", "give load_factors or im + levels, not both")
    if has_im:
        if "im" not in t:
            _fail("motions.im", f"missing with levels (one of {', '.join(IMS)})")
        if "levels" not in t:
            _fail("motions.levels", f"missing with im = {t['im']!r}")
        out["im"] = _string("motions.im", t["im"], tuple(IMS))
        out["levels"] = grid("motions.levels", t["levels"]).tolist()
    else:
        lf = grid("motions.load_factors", t.get("load_factors", [1.0]))
        out["load_factors"] = lf.tolist()
    return out


def _read_record(key: str, path: Path, units: str, dt: float | None) -> str:
    """Read the record file ``path`` as a run will (refused if it cannot be read or
    parsed); its content digest."""
    from ..motions import Record
    try:
        data = path.read_bytes()
        Record.from_file(path, units=units, dt=dt)
    except RockingError as e:
        _fail(key, f"{path.name}: {str(e).splitlines()[0] if str(e) else type(e).__name__}")
    except (OSError, ValueError) as e:  # unreadable, not text, ...
        _fail(key, f"cannot read {path}: {type(e).__name__}: "
                   f"{str(e).splitlines()[0] if str(e) else ''}")
    return hashlib.sha256(data).hexdigest()[:16]


def n_motions(m: dict) -> int:
    """Number of motions of a checked ``[motions]`` table."""
    return len(m.get("records") or m.get("paths") or m.get("names") or m.get("frequencies")
               or m.get("periods") or []) if m["kind"] != "stochastic" else m["n"]


def _motion_axis_key(m: dict) -> str:
    """The key of ``[motions]`` that sets the number of motions."""
    return {"seed_earthquakes": "records", "files": "paths", "builtin": "names",
            "stochastic": "n", "sine_grid": "frequencies", "pulse_grid": "periods"}[m["kind"]]


# ------------------------------------------------------------------------------ the spec
@dataclass(frozen=True)
class CampaignSpec:
    """A checked campaign spec (see the module docstring); build it with :func:`read_spec`
    or :func:`parse_spec`."""

    name: str
    seed: int
    models: tuple[str, ...]
    duration: float | None
    samples: int
    thresholds: tuple[float, ...]
    blocks: tuple[Block, ...]
    motions: dict
    uncertain: dict
    chunk_size: int
    window: int | None
    options: dict
    text: str = field(repr=False)
    raw: dict = field(repr=False)
    base_dir: str = "."
    """The folder that relative record paths (``kind = "files"``) start from."""
    max_free_time: float | None = None
    """Cap (s) of the free rocking after each motion (``duration`` unset); None: the
    package's default (:data:`rocking.models.run.DEFAULT_MAX_FREE_TIME`)."""

    @property
    def hash(self) -> str:
        """SHA-256 of what the results depend on: the parsed TOML (not its formatting or
        comments; without ``[run] window``, which only schedules) and, for record files,
        their contents (a digest each), not where they are."""
        raw = {k: v for k, v in self.raw.items() if k != "run"}
        raw["run"] = {k: v for k, v in self.raw.get("run", {}).items() if k != "window"}
        content = {"raw": raw, "digests": self.motions.get("digests")}
        return hashlib.sha256(json.dumps(content, sort_keys=True, default=str)
                              .encode()).hexdigest()

    @property
    def levels(self) -> np.ndarray:
        """The intensity axis: load factors, or IM levels when ``im`` is set."""
        return np.asarray(self.motions.get("levels", self.motions.get("load_factors")))

    @property
    def im(self) -> str | None:
        return self.motions.get("im")

    @property
    def n_motions(self) -> int:
        return n_motions(self.motions)

    @property
    def shape(self) -> tuple[int, int, int, int, int]:
        """``(models, blocks, motions, levels, samples)``: the axes of the simulation table,
        ``sim_id`` running fastest over the last."""
        return (len(self.models), len(self.blocks), self.n_motions, self.levels.size,
                self.samples)

    @property
    def n_sims(self) -> int:
        return math.prod(self.shape)  # Python ints: no overflow

    @property
    def n_chunks(self) -> int:
        return -(-self.n_sims // self.chunk_size)


def parse_spec(text: str, base_dir=".") -> CampaignSpec:
    """Check a spec given as TOML text (``files`` paths relative to ``base_dir``)."""
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise SpecError(f"spec: not valid TOML: {e}") from None
    _known("", raw, SECTIONS)
    c = _table("campaign", raw.get("campaign", {}))
    _known("campaign", c, CAMPAIGN_KEYS)
    for k in ("name", "seed", "model"):
        if k not in c:
            _fail(f"campaign.{k}", "missing")
    name = _string("campaign.name", c["name"])
    seed = int(_number("campaign.seed", c["seed"], 0, 2**63 - 1, integer=True))
    models = c["model"] if isinstance(c["model"], list) else [c["model"]]
    if not models:
        _fail("campaign.model", "is empty")
    models = tuple(_string(f"campaign.model[{i}]" if isinstance(c["model"], list)
                           else "campaign.model", m, tuple(MODELS)) for i, m in enumerate(models))
    if len(set(models)) != len(models):
        _fail("campaign.model", "has repeated models")
    duration = (_number("campaign.duration", c["duration"], 0, 1e6, lo_open=True)
                if "duration" in c else None)
    max_free_time = None
    if "max_free_time" in c:
        max_free_time = _number("campaign.max_free_time", c["max_free_time"], 0,
                                MAX_RECORD_DURATION)
        if duration is not None:
            _fail("campaign.max_free_time", "applies only without campaign.duration (a run "
                                            "with a duration stops exactly there)")
    samples = int(_number("campaign.samples", c.get("samples", 1), 1, 1e9, integer=True))
    thr = c.get("thresholds", list(DEFAULT_THRESHOLDS))
    if not isinstance(thr, list):
        _fail("campaign.thresholds", f"must be a list of numbers, got {thr!r}")
    for i, x in enumerate(thr):
        _number(f"campaign.thresholds[{i}]", x, 0, lo_open=True)
    try:
        state_labels(thr)
    except ParameterError as e:
        _fail("campaign.thresholds", str(e))
    thresholds = tuple(float(x) for x in thr)

    if "blocks" not in raw:
        _fail("blocks", "missing (one [[blocks]] table per block)")
    if not isinstance(raw["blocks"], list) or not raw["blocks"]:
        _fail("blocks", "must be one or more [[blocks]] tables")
    blocks = tuple(_block(i, b) for i, b in enumerate(raw["blocks"]))

    if "motions" not in raw:
        _fail("motions", "missing (a [motions] table with kind)")
    motions = _motions(raw["motions"], Path(base_dir))
    if n_motions(motions) == 0:
        _fail(f"motions.{_motion_axis_key(motions)}", "empty motion set (no motion to run)")

    uncertain = _table("uncertain", raw.get("uncertain", {}))
    _known("uncertain", uncertain, PARAMETERS)
    for k, d in uncertain.items():
        if not isinstance(d, dict):
            _fail(f"uncertain.{k}", f"must be a table with dist, got {d!r}")
    for i, b in enumerate(blocks):
        try:
            distributions(b, uncertain, where=lambda k: f"uncertain.{k}",
                          of=f" of blocks[{i}]" if len(blocks) > 1 else "")
        except ParameterError as e:  # "uncertain.k.sub must ..." or "uncertain.k: ..."
            key, _, msg = str(e).partition(" ")
            _fail(key.rstrip(":"), msg)
    if samples > 1 and not uncertain:
        _fail("campaign.samples", f"is {samples}, but nothing is uncertain: the samples would "
                                  "be identical runs (give [uncertain] parameters, or samples = 1)")
    if uncertain and "dem" in models and set(uncertain) & {"alpha", "p", "mu", "theta0"}:
        bad = sorted(set(uncertain) & {"alpha", "p", "mu", "theta0"})[0]
        _fail(f"uncertain.{bad}", "not supported with model 'dem' (its geometry and contacts "
                                  "define alpha, p and mu; it starts at rest)")

    shape = (len(models), len(blocks), n_motions(motions),
             len(motions.get("levels", motions.get("load_factors", []))), samples)
    if math.prod(shape) > MAX_SIMS:
        axes = {"campaign.model": shape[0], "blocks": shape[1],
                f"motions.{_motion_axis_key(motions)}": shape[2],
                "motions.levels" if "levels" in motions else "motions.load_factors": shape[3],
                "campaign.samples": shape[4]}
        key = max(axes, key=axes.get)
        _fail(key, f"the campaign would have {math.prod(shape):.3g} simulations ("
                   + " x ".join(f"{v} {k}" for k, v in axes.items())
                   + "); at most 2^63 - 1 (sim_id is an int64)")

    r = _table("run", raw.get("run", {}))
    _known("run", r, RUN_KEYS)
    chunk = int(_number("run.chunk_size", r.get("chunk_size", 2000), 1, 1e7, integer=True))
    window = (int(_number("run.window", r["window"], 1, 1e5, integer=True))
              if "window" in r else None)

    opts = _table("options", raw.get("options", {}))
    _known("options", opts, models)
    options = {}
    for m, o in opts.items():
        o = _table(f"options.{m}", o)
        try:
            MODELS[m].Options.build(m, **o)
        except (TypeError, RockingError) as e:
            msg = str(e).splitlines()[0]
            opt = msg.split(" ", 1)[0]
            if opt in o and " " in msg:  # "rest_tol must be ...": name the option's key
                _fail(f"options.{m}.{opt}", msg.split(" ", 1)[1])
            _fail(f"options.{m}", msg)
        options[m] = dict(o)
    for m in models:  # each block must suit each model (the DEM needs a geometry)
        for i, b in enumerate(blocks):
            try:
                MODELS[m].from_kwargs(b, **options.get(m, {}))
            except RockingError as e:
                _fail(f"blocks[{i}]", f"not usable with model {m!r}: {e}")
    return CampaignSpec(name=name, seed=seed, models=models, duration=duration,
                        samples=samples, thresholds=thresholds, blocks=blocks, motions=motions,
                        uncertain=uncertain, chunk_size=chunk, window=window, options=options,
                        text=text, raw=raw, base_dir=str(Path(base_dir).resolve()),
                        max_free_time=max_free_time)


def read_spec(path) -> CampaignSpec:
    """Read and check the spec at ``path`` (see the module docstring)."""
    p = Path(path)
    if not p.is_file():
        raise SpecError(f"spec: no such file: {p}")
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise SpecError(f"spec: cannot read {p}: {e}") from None
    return parse_spec(text, base_dir=p.resolve().parent)
