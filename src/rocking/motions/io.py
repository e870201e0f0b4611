"""Reading and writing accelerograms.

:func:`read_record` (behind :meth:`Record.from_file <rocking.motions.records.Record.from_file>`)
reads, recognising each format by its content (a file's extension is not needed):

* the files of the strong-motion databases, read by :mod:`rocking.motions.formats`: ESM
  ASCII (esm-db.eu), COSMOS Volume 2 corrected acceleration (CESMD and other COSMOS
  networks) and K-NET / KiK-net ASCII (NIED; read with obspy, the scale factor applied);
* PEER NGA ``.AT2`` files (recognised by the extension or by an ``NPTS`` header on line 4):
  four header lines, the third stating the units (``... IN UNITS OF G``; g if it states
  none), the fourth ``NPTS=  2048, DT=   .0066 SEC`` (possibly followed by filter
  information) or ``2048    0.0066    NPTS, DT``; then the samples in Fortran E format
  (``.1717907E-01``), five to a line, the last line possibly short;
* CSV or whitespace-separated columns: ``time, acceleration`` with uniform time steps, or
  a single acceleration column with a time step ``dt`` given by the caller or stated in a
  header comment (``# dt = 0.01 s``). Lines starting with ``#`` are comments; the first
  non-numeric line is taken as a column header (so is a comment line just above the data
  that names the columns, ``# time_s, acc_g``). Whitespace-only lines are blank lines.

Records are read exactly, or refused:

* **units.** Every unit word is understood, in any case: time ``s``/``sec``/``second(s)``,
  ``ms``/``msec``/``millisecond(s)``, ``us``/``µs``/``usec``/``microsecond(s)``;
  acceleration ``g``, ``gal``, ``cm/s^2`` (``cm/s2``, ``cm/sec^2``, ``cm/s/s``, ``cm s^-2``),
  ``m/s^2``, ``mm/s^2``. They are read from ``dt`` statements (``# dt = 10 msec``,
  ``# dt (ms) = 10``, ``# dt_ms = 10``, AT2 ``DT= 5 MSEC``; a bare number is in s), from a
  ``# units: gal`` comment, from the AT2 units line and from column names (``time_ms``,
  ``acc_g``, ``Acceleration (cm/s^2)``, ``t [s]``, ``acceleration in g``). A word where a
  unit goes that is not one of these is refused by name; a time column in ms or us is
  converted. An acceleration unit stated in the file must agree with ``units``: otherwise
  the error names both (the file is never silently re-scaled, either way). ``units=None``
  takes the unit the file states (g if it states none).
* **counts.** A declared count (AT2 ``NPTS``, ``# npts = N``) must equal the values read.
* **cut files.** A last value that is only the beginning of the file's fixed number format
  (``-.1094953E-0`` after thousands of ``.dddddddE-dd``) is refused; so is a column file
  that declares ``npts`` but does not end with a line break.

:func:`write_csv` writes a record as ``t,acc`` columns in m/s^2 that :func:`read_record`
reads back with ``units="m/s^2"``. :func:`builtin_records` and :func:`read_builtin` give
the PEER records shipped with the package (``rocking/motions/data/records``).

This module works on arrays and metadata and does not know the
:class:`~rocking.motions.records.Record` class: :meth:`Record.from_file
<rocking.motions.records.Record.from_file>` and :func:`~rocking.motions.records.load_builtin`
build records from what it reads.
"""

from __future__ import annotations

import io as _io
import math
import re
from importlib import resources
from pathlib import Path

import numpy as np

from .._atomic import atomic_path
from .._validate import positive
from ..errors import RecordError
from ..units import (
    ACCELERATION,
    ACCELERATION_UNITS,
    TIME_FACTORS,
    acceleration_factor,
    acceleration_unit,
    time_unit,
)
from . import formats
from .samples import is_sampled

__all__ = ["read_record", "write_csv", "builtin_records", "read_builtin"]

_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?"
_WORD = "[A-Za-z\u00b5\u03bc][^\\s,;]*"  # a unit word: starts with a letter (or a micro sign)
_BRACKET = r"[(\[{]\s*([^)\]}]*?)\s*[)\]}]"  # "(ms)", "[s]", "{g}"
_AT2_NPTS = re.compile(r"NPTS\s*=\s*(\d+)", re.I)
_AT2_DT = re.compile(rf"\bDT\s*=\s*({_NUM})(?:\s*({_WORD}))?", re.I)
_AT2_ALT = re.compile(rf"^\s*(\d+)\s*,?\s+({_NUM})\s*,?\s*NPTS\s*,?\s*DT", re.I)
_AT2_UNITS = re.compile(r"UNITS\s+OF\s+(.+?)\s*(?:[,;]|\s\s|$)", re.I)
_AT2_KIND = re.compile(r"\b(ACCELERATION|VELOCITY|DISPLACEMENT)\b", re.I)
_FORTRAN_D = re.compile(r"(?<=[\d.])[dD](?=[-+]?\d)")
# statements start a comment or follow a ',' or ';' (not inside a record's name)
_HDR_DT = re.compile(
    rf"(?:^|[#,;])\s*dt(?:_({_WORD})|\s*{_BRACKET})?\s*[=:]\s*({_NUM})(?:\s*{_BRACKET}|\s*({_WORD}))?",
    re.I)
_HDR_NPTS = re.compile(r"(?:^|[#,;])\s*npts\s*[=:]\s*([^\s,;]*)", re.I)
_HDR_UNITS = re.compile(r"^\s*#?\s*(?:acc\w*\s+)?units?\s*[=:]\s*([^,;]*?)\s*(?:[,;].*)?$",
                        re.I)
_SPLIT = re.compile(r"[,;\s]+")
_TITLE = re.compile(r"^#\s*rocking record:")

# column names: "<qualifiers> <quantity> <qualifiers> <unit>", e.g. "time_ms", "acc_g",
# "Acceleration (cm/s^2)", "ground acc NS [gal]", "acceleration in g"
_TIME_NAMES = {"t", "time"}
_ACC_NAMES = {"a", "acc", "accel", "acceleration", "ag"}
_QUALIFIERS = {"in", "of", "ground", "horizontal", "vertical", "hor", "ver", "vert", "h", "v",
               "x", "y", "z", "n", "e", "ns", "ew", "ud", "up", "h1", "h2", "component",
               "comp", "abs", "absolute", "input", "base", "table", "record", "value"}

_AT2_MAX_DT = 1.0  # s: the longest time step of a PEER .AT2 file read (1 Hz)
_DT_RTOL = 1e-6  # relative tolerance on time steps (uneven steps, dt disagreements)


# ------------------------------------------------------------------------------------ public
def read_record(path, units: str | None = "g",
                dt: float | None = None) -> tuple[np.ndarray, float, dict]:
    """Read an accelerogram file.

    Parameters
    ----------
    path : str or path-like
        An ESM, COSMOS V2 or K-NET/KiK-net file (:mod:`rocking.motions.formats`), a PEER
        NGA ``.AT2`` file, or a CSV / whitespace-column file (see the module doc); the
        format is recognised by the content.
    units : str or None
        Units of the acceleration values in the file: ``g``, ``m/s^2``, ``cm/s^2`` or
        ``gal`` (also ``mm/s^2``). A unit stated in the file (``.AT2`` files: g unless
        their third line says otherwise; ESM, COSMOS and K-NET files always state theirs,
        cm/s^2 or gal) must agree with it. None: the unit the file states, g if none.
    dt : float, optional
        Time step (s). Required for a one-column file that does not state ``dt`` in a
        header comment; otherwise, if given, it must agree with the file.

    Returns
    -------
    acc : numpy.ndarray
        Samples in m/s^2 (float64), the first at ``t = 0``.
    dt : float
        Time step (s).
    meta : dict
        ``name`` (file stem), ``format`` (``"ESM"``, ``"COSMOS-V2"``, ``"KNET"``,
        ``"KiK-net"``, ``"AT2"``, ``"csv"`` or ``"columns"``), ``path``,
        ``npts``, ``dt``, ``units`` (canonical name), ``t_start`` (s, original start
        time), ``time_units`` (two-column files: the time column's unit) and, for
        ``.AT2`` files, ``description`` (event and station line), ``title``, ``header`` (the
        four header lines) and, when the description has the usual four comma-separated
        fields, ``event``, ``date``, ``station`` and ``component``. The database formats give
        ``network``, ``station``, ``component``, ``event``, ``pga_declared`` (the peak the
        header states, in ``units``) and more (:mod:`rocking.motions.formats`). Always
        ``units_stated`` (True when the file states its unit) and ``units_from``: ``"file"``
        (stated), ``"convention"`` (an ``.AT2`` file that states none: g, the PEER
        convention), ``"caller"`` (a column file that states none, read in ``units``) or
        ``"default"`` (a column file that states none read with ``units=None``: g assumed).

    Raises
    ------
    RecordError
        The file is missing, empty or malformed (message names the file and line).
    UnitError
        ``units`` is not an acceleration unit.

    Examples
    --------
    >>> from rocking.motions import load_builtin, read_record, write_csv
    >>> rec = load_builtin("RSN126_GAZLI_GAZ000")
    >>> path = write_csv(rec, "gazli.csv")
    >>> acc, dt, meta = read_record("gazli.csv", units="m/s^2")
    >>> dt, meta["npts"], meta["format"], bool(np.array_equal(acc, rec.values))
    (0.0066, 2048, 'csv', True)
    """
    p = Path(path)
    factor = None if units is None else acceleration_factor(units)
    if dt is not None:
        dt = positive("dt", dt, "s")
    text = _read_text(p)
    lines = text.splitlines()
    kind = formats.detect(lines)
    if kind == "ESM":
        out = formats.read_esm(p, lines, units, factor, dt)
    elif kind == "COSMOS":
        out = formats.read_cosmos(p, lines, units, factor, dt)
    elif kind == "KNET":
        out = formats.read_knet(p, lines, units, factor, dt, text)
    elif _is_at2(p, lines):
        out = _read_at2(p, lines, units, factor, dt)
    else:
        out = _read_columns(p, lines, units, factor, dt, text.endswith(("\n", "\r")))
    meta = out[2]
    meta.setdefault("units_from", "file")  # the database formats always state their unit
    meta["units_stated"] = meta["units_from"] == "file"
    return out


def write_csv(record, path) -> Path:
    """Write ``record`` to ``path`` as CSV columns ``t,acc`` (s, m/s^2); returns the path.

    ``record`` is a :class:`~rocking.motions.records.Record` (or any sampled accelerogram
    with ``values``, ``dt``, ``t`` and ``name``). The samples are written with the record's
    load factor applied (``record.values``) and with full float precision. A comment header
    states the units and ``dt``, so the file reads back with
    ``read_record(path, units="m/s^2")`` or ``Record.from_file(path, units="m/s^2")``.

    Examples
    --------
    >>> from rocking.motions import Record, Sine, sample, write_csv
    >>> rec = sample(Sine(freq=2.0, amplitude=0.01, duration=1.0), dt=0.01)
    >>> path = write_csv(rec, "sine.csv")
    >>> back = Record.from_file(path, units="m/s^2")
    >>> path.name, back.dt, bool(np.array_equal(back.values, rec.values))
    ('sine.csv', 0.01, True)
    """
    if not is_sampled(record):
        raise TypeError(
            f"write_csv needs a Record, got {type(record).__name__}; "
            "sample other motions first with rocking.motions.sample(motion, dt)"
        )
    p = Path(path)
    name = " ".join(str(record.name or p.stem).split())
    header = "\n".join([
        f"# rocking record: {name}",
        "# units: m/s^2",
        f"# dt = {record.dt!r} s",
        f"# npts = {len(record.values)}",
        "t,acc",
    ])
    data = np.column_stack([record.t, record.values])
    try:
        with atomic_path(p) as tmp:
            np.savetxt(tmp, data, fmt="%.17g", delimiter=",", header=header, comments="")
    except OSError as e:
        raise RecordError(f"cannot write {p}: {e.strerror or e}") from None
    return p


def _stems(folder) -> list[str]:
    try:
        entries = list(folder.iterdir())
    except (FileNotFoundError, NotADirectoryError):
        return []
    return sorted(e.name[:-4] for e in entries if e.name.upper().endswith(".AT2"))


def builtin_records(three_component: bool = False) -> list[str]:
    """Names of the PEER NGA records shipped with the package (for :func:`load_builtin`):
    the four horizontal records; with ``three_component=True`` also the six files of the
    three-component sets (:func:`builtin_sets`).

    Examples
    --------
    >>> from rocking.motions import builtin_records
    >>> builtin_records()
    ['RSN126_GAZLI_GAZ000', 'RSN183_IMPVALL.H_H-E08140', 'RSN948_NORTHR_CAM009',
     'RSN982_NORTHR_JEN292']
    >>> len(builtin_records(three_component=True))
    10
    """
    names = _stems(_builtin_dir())
    if three_component:
        names += _stems(_builtin_dir() / THREE_COMPONENT)
    return names


THREE_COMPONENT = "three_component"
SETS = {"rinaldi": ("Rinaldi228", "Rinaldi318", "RinaldiUP"),
        "duzce": ("RSN1158_KOCAELI_DZC180", "RSN1158_KOCAELI_DZC270", "RSN1158_KOCAELI_DZC-UP")}


def builtin_sets() -> dict[str, tuple[str, str, str]]:
    """The three-component sets shipped with the package: ``{name: (H1, H2, UP)}``
    (Northridge 1994 at Rinaldi, Kocaeli 1999 at Duzce).

    Examples
    --------
    >>> from rocking.motions import builtin_sets
    >>> builtin_sets()["rinaldi"]
    ('Rinaldi228', 'Rinaldi318', 'RinaldiUP')
    >>> sorted(builtin_sets())
    ['duzce', 'rinaldi']
    """
    return dict(SETS)


def read_builtin(name: str) -> tuple[np.ndarray, float, dict]:
    """:func:`read_record` of a record shipped with the package, by name (see
    :func:`builtin_records`); ``meta["builtin"]`` is True.

    ``name`` is the file stem (``"RSN982_NORTHR_JEN292"``), optionally with ``.AT2``, or
    an unambiguous leading part of it such as ``"RSN982"``; case is ignored.
    """
    available = builtin_records(three_component=True)
    key = str(name).strip()
    if key.upper().endswith(".AT2"):
        key = key[:-4]
    matches = [s for s in available if s.upper() == key.upper()]
    if not matches and key:
        matches = [s for s in available if s.upper().startswith(key.upper() + "_")]
    if len(matches) != 1:
        what = "ambiguous" if matches else "unknown"
        raise RecordError(
            f"{what} built-in record {name!r}; available: {', '.join(available) or 'none'}"
        )
    folder = _builtin_dir()
    if matches[0] not in _stems(folder):
        folder = folder / THREE_COMPONENT
    res = folder / f"{matches[0]}.AT2"
    with resources.as_file(res) as fp:
        acc, dt, meta = read_record(fp, units="g")
    meta["builtin"] = True
    return acc, dt, meta


# ------------------------------------------------------------------------------- internals
def _builtin_dir():
    return resources.files("rocking.motions") / "data" / "records"


def _read_text(p: Path) -> str:
    try:
        raw = p.read_bytes()
    except FileNotFoundError:
        raise RecordError(f"record file not found: {p}") from None
    except IsADirectoryError:
        raise RecordError(f"{p} is a directory, not a record file") from None
    except OSError as e:
        raise RecordError(f"cannot read record file {p}: {e.strerror or e}") from None
    text = raw.decode("utf-8", errors="replace")
    if text.startswith("\ufeff"):
        text = text[1:]
    if not text.strip():
        raise RecordError(f"{p}: the file is empty (no data)")
    return text


def _is_at2(p: Path, lines: list[str]) -> bool:
    if p.suffix.lower() == ".at2":
        return True
    if len(lines) < 4 or lines[3].lstrip().startswith("#"):
        return False
    line = lines[3]
    return bool(_AT2_NPTS.search(line) or _AT2_ALT.match(line))


def _float(s: str) -> float:
    return float(_FORTRAN_D.sub("E", s))


def _close(a: float, b: float) -> bool:
    return abs(a - b) <= _DT_RTOL * max(abs(a), abs(b))


def _tokens(line: str) -> list[str]:
    return _FORTRAN_D.sub("E", line).split()


# ---- PEER NGA .AT2
def _at2_factor(p: Path, lines: list[str], units: str,
                factor: float) -> tuple[float, str, bool]:
    """SI factor and name of the samples' unit: the one line 3 states (``UNITS OF G``; g if
    it states none), which must agree with ``units``; and whether line 3 states it."""
    line3 = lines[2] if len(lines) > 2 else ""
    m_k, m_u = _AT2_KIND.search(line3), _AT2_UNITS.search(line3)
    if m_k and m_k[1].upper() != "ACCELERATION":
        raise RecordError(f"{p}, line 3: expected an acceleration time series in units of G, "
                          f"got {line3.strip()!r}")
    word = m_u[1] if m_u else "G"
    key = acceleration_unit(word)
    if key is None:
        raise RecordError(f"{p}, line 3: unknown acceleration unit {word!r}; known: "
                          f"{', '.join(ACCELERATION_UNITS)}")
    if factor is not None and not _close(ACCELERATION[key], factor):
        where = f"line 3 states units of {word}" if m_u else "a PEER .AT2 file is in g"
        raise RecordError(f"{p}: the file is in {key} ({where}) but units={units!r} was "
                          f"passed; pass units={key!r}")
    return ACCELERATION[key], key, m_u is not None


def _read_at2(p: Path, lines: list[str], units: str, factor: float, dt: float | None):
    if len(lines) < 4:
        raise RecordError(
            f"{p}: not a valid PEER .AT2 file: expected 4 header lines, the 4th stating "
            f"'NPTS= <n>, DT= <s> SEC'; the file has only {len(lines)} line(s)"
        )
    factor, unit_key, unit_stated = _at2_factor(p, lines, units, factor)
    hdr = lines[3]
    m_n, m_dt, m_alt = _AT2_NPTS.search(hdr), _AT2_DT.search(hdr), _AT2_ALT.match(hdr)
    if m_n and m_dt:
        npts, step = int(m_n[1]), _float(m_dt[1]) * _time_factor(p, 4, m_dt[2], "DT")
        for m in _AT2_NPTS.finditer(hdr):  # stated twice: the statements must agree
            if int(m[1]) != npts:
                raise RecordError(f"{p}, line 4: NPTS={m[1]} contradicts NPTS={m_n[1]} on "
                                  "the same line")
        for m in _AT2_DT.finditer(hdr):
            if not _close(_float(m[1]) * _time_factor(p, 4, m[2], "DT"), step):
                raise RecordError(f"{p}, line 4: DT={m[1]} contradicts DT={m_dt[1]} on the "
                                  "same line")
    elif m_alt:
        npts, step = int(m_alt[1]), _float(m_alt[2])
    else:
        raise RecordError(
            f"{p}, line 4: not a valid PEER .AT2 header: expected 'NPTS= <n>, DT= <s> SEC' "
            f"(or '<n> <dt> NPTS, DT'), got {hdr.strip()!r}"
        )
    if npts < 2:
        raise RecordError(f"{p}, line 4: a record needs at least 2 samples, the header "
                          f"states NPTS={npts}")
    if not (math.isfinite(step) and step > 0.0):
        raise RecordError(f"{p}, line 4: DT must be > 0 s, got {step!r}")
    if step > _AT2_MAX_DT:  # no other field to check it against: a bound
        raise RecordError(f"{p}, line 4: DT = {step:g} s; an accelerogram is sampled every "
                          f"{_AT2_MAX_DT:g} s or less (is DT in ms? write 'DT= {step:g} MSEC')")
    if dt is not None and not _close(dt, step):
        raise RecordError(f"{p}: dt={dt:g} s was passed but the header (line 4) states "
                          f"DT={step:g} s")

    first = 4  # 0-based index of the first data line
    tokens = _tokens("\n".join(lines[first:]))
    if not tokens:
        raise RecordError(f"{p}: no data after the 4 header lines (NPTS={npts})")
    try:
        vals = np.array(tokens, dtype=np.float64)
    except ValueError:
        vals = None
    if vals is None:
        for i in range(first, len(lines)):
            for tok in _tokens(lines[i]):
                try:
                    float(tok)
                except ValueError:
                    cut = (" (the file looks cut)" if i == len(lines) - 1 and
                           tok == _tokens(lines[i])[-1] else "")
                    raise RecordError(f"{p}, line {i + 1}: non-numeric value {tok!r}"
                                      f"{cut}") from None
        raise RecordError(f"{p}: cannot read the samples")  # pragma: no cover
    bad = np.flatnonzero(~np.isfinite(vals))
    if bad.size:
        ln = _line_of_token(lines, first, int(bad[0]))
        raise RecordError(f"{p}, line {ln}: NaN or infinite value {tokens[bad[0]]!r}")
    if vals.size < npts:
        raise RecordError(f"{p}: the header (line 4) states NPTS={npts} but only "
                          f"{vals.size} values follow (the file looks cut)")
    if vals.size > npts:
        ln = _line_of_token(lines, first, npts)
        raise RecordError(f"{p}, line {ln}: {vals.size - npts} value(s) beyond "
                          f"NPTS={npts} stated in the header (line 4)")
    _check_last_field(p, lines, first, tokens)

    desc = lines[1].strip()
    meta = {
        "name": p.stem, "format": "AT2", "path": str(p), "npts": npts, "dt": step,
        "units": unit_key, "units_from": "file" if unit_stated else "convention",
        "t_start": 0.0, "title": lines[0].strip(), "description": desc,
        "header": [ln.rstrip() for ln in lines[:4]],
    }
    parts = [s.strip() for s in desc.split(",")]
    if len(parts) == 4:
        meta.update(event=parts[0], date=parts[1], station=parts[2], component=parts[3])
    return vals * factor, step, meta


# the layout of a number: digits as 'd', signs dropped, exponent letter as 'E'
_LAYOUT = str.maketrans({**{c: "d" for c in "0123456789"}, "+": None, "-": None,
                         "e": "E", "D": "E"})


def _check_last_field(p: Path, lines: list[str], first: int, tokens: list[str]) -> None:
    """Refuse a file whose last value is cut short: all the other values have one fixed
    format and the last one has only its beginning (``-.1094953E-0`` for ``.dddddddE-dd``:
    a valid-looking number that lost its exponent)."""
    layouts = " ".join(tokens).translate(_LAYOUT).split()
    last = layouts.pop()
    ref = set(layouts)
    if len(ref) != 1 or "." not in next(iter(ref)):
        return  # not a fixed format: nothing to compare with
    (shape,) = ref
    if last != shape and shape.startswith(last):  # a prefix of the format: cut short
        ln = _line_of_token(lines, first, len(tokens) - 1)
        raise RecordError(f"{p}, line {ln}: the last value {tokens[-1]!r} does not have the "
                          f"number format of all the others (like {tokens[-2]!r}): the file "
                          "looks cut")


def _time_factor(p: Path, line: int, word, what: str) -> float:
    """SI factor of the time unit ``word`` stated for ``what`` on ``line`` (None: s)."""
    if word is None or not word.strip():
        return 1.0
    key = time_unit(word)
    if key is None:
        raise RecordError(f"{p}, line {line}: unknown time unit {word!r} for {what}; known: "
                          "s (sec, seconds), ms (msec, milliseconds), us (usec, microseconds)")
    return TIME_FACTORS[key]


def _line_of_token(lines: list[str], first: int, k: int) -> int:
    """1-based line number of the ``k``-th (0-based) whitespace token from line ``first``."""
    counts = np.cumsum([len(ln.split()) for ln in lines[first:]])
    return first + int(np.searchsorted(counts, k, side="right")) + 1


# ---- CSV / whitespace columns
def _strip_comment(line: str) -> str:
    j = line.find("#")
    return (line if j < 0 else line[:j]).strip()


def _is_numeric_line(s: str) -> bool:
    toks = [t.strip('"\'') for t in _SPLIT.split(s.strip()) if t]
    if not toks:
        return False
    try:
        for t in toks:
            float(t)
    except ValueError:
        return False
    return True


def _header_statements(p: Path, lines: list[str], i: int, s: str, found: dict) -> None:
    """Collect ``dt``, ``npts`` and ``units`` stated on header line ``i`` (0-based)."""
    if _TITLE.match(s):
        return  # write_csv's title line holds the record's name, whatever it says
    ln = i + 1
    for m in _HDR_DT.finditer(s):
        pre, pre_b, num, post_b, post = m.groups()
        before, after = pre or pre_b, post_b if post_b is not None else post
        f_before = _time_factor(p, ln, before, "dt")
        f_after = _time_factor(p, ln, after, "dt")
        if before and after and not _close(f_before, f_after):
            raise RecordError(f"{p}, line {ln}: dt is stated in {before!r} and in {after!r}")
        v = _float(num) * (f_before if before else f_after)
        if "dt" in found:  # stated again: it must agree
            if not _close(found["dt"][0], v):
                raise RecordError(f"{p}, line {ln}: dt = {v:g} s contradicts dt = "
                                  f"{found['dt'][0]:g} s stated on line {found['dt'][1]}")
            continue
        found["dt"] = (v, ln)
    for m in _HDR_NPTS.finditer(s):
        if not m[1].isdigit():
            raise RecordError(f"{p}, line {ln}: npts must be a whole number, got {m[1]!r}")
        if "npts" in found:
            if found["npts"][0] != int(m[1]):
                raise RecordError(f"{p}, line {ln}: npts = {m[1]} contradicts npts = "
                                  f"{found['npts'][0]} stated on line {found['npts'][1]}")
            continue
        found["npts"] = (int(m[1]), ln)
    m = _HDR_UNITS.match(s)
    if m:
        u = m[1]
        key = acceleration_unit(u)
        if key is None:
            raise RecordError(f"{p}, line {ln}: unknown units {u!r} stated in the header; "
                              f"use one of {', '.join(ACCELERATION_UNITS)}")
        if "units" in found:
            u0, key0, ln0 = found["units"]
            if not _close(ACCELERATION[key], ACCELERATION[key0]):
                raise RecordError(f"{p}, line {ln}: units {u!r} contradict units {u0!r} "
                                  f"stated on line {ln0}")
            return
        found["units"] = (u, key, ln)


def _column_names(text: str, delim) -> list[str]:
    """The column names of a header line (brackets kept with their name)."""
    text = text.lstrip("#").strip()
    if delim and delim in text:
        parts = text.split(delim)
    else:
        text = re.sub(r"\s+(?=[(\[{])", "", text)  # "time (s)" -> "time(s)"
        text = re.sub(r"[(\[{][^)\]}]*[)\]}]", lambda m: "".join(m[0].split()), text)
        parts = text.split()
    return [q.strip().strip("\"'").strip() for q in parts]


def _name_unit(p: Path, ln: int, name: str):
    """``(quantity, unit word)`` of a column name: quantity ``"time"``, ``"acc"`` or None;
    the unit word or None. An unknown word where a unit goes raises a RecordError."""
    b = list(re.finditer(_BRACKET, name))
    base = re.sub(_BRACKET, " ", name)
    words = [w for w in re.split(r"[\s_]+", base.strip()) if w]
    qty, k = None, -1
    for j, w in enumerate(words):
        if w.lower() in _TIME_NAMES or w.lower() in _ACC_NAMES:
            qty, k = ("time" if w.lower() in _TIME_NAMES else "acc"), j
    unit = b[-1][1] if b else None
    if k >= 0:  # words after the quantity: qualifiers, then the unit
        rest = words[k + 1:]
        while rest and rest[0].lower() in _QUALIFIERS:
            rest = rest[1:]
        while rest and rest[-1].lower() in _QUALIFIERS:
            rest = rest[:-1]
        if rest:
            word = " ".join(rest)
            if unit is not None:
                raise RecordError(f"{p}, line {ln}: column {name!r} states two units, "
                                  f"{word!r} and {unit!r}")
            unit = word
    if unit is not None and time_unit(unit) is None and acceleration_unit(unit) is None:
        raise RecordError(f"{p}, line {ln}: unknown unit {unit!r} in column name {name!r}; "
                          f"known: {', '.join(ACCELERATION_UNITS)}; s, ms, us")
    return qty, unit


def _column_units(p: Path, ln: int, text: str, delim, ncols: int):
    """``(time unit, acceleration unit, its word as written)`` (canonical names or None)
    from the header line ``text`` (line ``ln``) of a file with ``ncols`` columns."""
    names = _column_names(text, delim)
    roles = ("time", "acc") if ncols == 2 else ("acc",)
    t_unit = a_unit = a_word = None
    if len(names) == ncols:
        pairs = [(role, nm, *_name_unit(p, ln, nm)) for role, nm in zip(roles, names,
                                                                          strict=True)]
    else:  # names not separable: each unit word found, placed by its kind
        pairs = [(None, nm, *_name_unit(p, ln, nm)) for nm in names]
    for role, nm, qty, unit in pairs:
        if role is not None and qty is not None and qty != role:
            want = "the time" if role == "time" else "the acceleration"
            raise RecordError(f"{p}, line {ln}: column {roles.index(role) + 1} is named "
                              f"{nm!r} but holds {want}; expected "
                              + ("'time, acceleration'" if ncols == 2 else "one acceleration"
                                 " column"))
        if unit is None:
            continue
        tu, au = time_unit(unit), acceleration_unit(unit)
        kind = role or qty or ("time" if tu else "acc")
        if kind == "time":
            if tu is None or ncols == 1:
                raise RecordError(f"{p}, line {ln}: column {nm!r}: {unit!r} is not a time unit"
                                  if tu is None else f"{p}, line {ln}: column {nm!r} states "
                                  f"a time unit ({unit!r}) but the file has one column "
                                  "(acceleration)")
            t_unit = tu
        else:
            if au is None:
                raise RecordError(f"{p}, line {ln}: column {nm!r}: {unit!r} is not an "
                                  f"acceleration unit ({', '.join(ACCELERATION_UNITS)})")
            if a_unit is not None and a_unit != au:
                raise RecordError(f"{p}, line {ln}: the header states two acceleration "
                                  f"units, {a_unit!r} and {au!r}")
            a_unit, a_word = au, unit
    return t_unit, a_unit, a_word


def _looks_like_names(text: str, delim, ncols: int) -> bool:
    """Whether a comment line such as ``# time_s, acc_g`` names the columns."""
    names = _column_names(text, delim)
    if len(names) != ncols:
        return False
    for nm in names:
        words = re.split(r"[\s_(\[{]+", nm.lower())
        if not words or (words[0] not in _TIME_NAMES and words[0] not in _ACC_NAMES):
            return False
    return True


def _read_columns(p: Path, lines: list[str], units: str, factor: float, dt: float | None,
                  ends_nl: bool = True):
    found: dict = {}
    header_text = header_ln = None
    last_comment = None
    i = 0
    while i < len(lines):
        s = lines[i].strip()
        if not s:
            i += 1
            continue
        if s.startswith("#") or (header_text is None
                                   and not _is_numeric_line(_strip_comment(s))):
            if not s.startswith("#"):
                header_text, header_ln = s, i + 1
            else:
                last_comment = (s, i + 1)
            _header_statements(p, lines, i, s, found)
            i += 1
            continue
        break
    if i >= len(lines):
        raise RecordError(f"{p}: no data (the file holds only comments or a header line)")

    hdr_dt = found.get("dt")
    if hdr_dt is not None:
        v, ln = hdr_dt
        if not (math.isfinite(v) and v > 0.0):
            raise RecordError(f"{p}, line {ln}: dt stated in the header must be > 0 s, "
                              f"got {v!r}")
        if dt is not None and not _close(dt, v):
            raise RecordError(f"{p}, line {ln}: dt={dt:g} s was passed but the header "
                              f"states dt = {v:g} s")

    first = i
    first_data = _strip_comment(lines[first])
    # ';' first: with decimal commas ("0,01;1,5") a ',' split would misread the numbers
    delim = ";" if ";" in first_data else ("," if "," in first_data else None)
    # whitespace-only lines are blank lines (loadtxt would count their empty field)
    body = "\n".join(ln if ln.strip() else "" for ln in lines[first:])
    try:
        arr = np.loadtxt(_io.StringIO(body), delimiter=delim,
                         comments="#", ndmin=2, dtype=np.float64, quotechar='"')
    except ValueError as e:
        _raise_column_problem(p, lines, first, delim, str(e))
    n, ncols = arr.shape
    if ncols > 2:
        raise RecordError(f"{p}, line {first + 1}: {ncols} columns; expected 1 (acceleration)"
                          " or 2 (time, acceleration)")
    bad = np.flatnonzero(~np.isfinite(arr).all(axis=1))
    if bad.size:
        ln = _data_line_numbers(lines, first)[bad[0]]
        raise RecordError(f"{p}, line {ln}: NaN or infinite value")
    if n < 2:
        raise RecordError(f"{p}, line {first + 1}: a record needs at least 2 samples, "
                          f"found {n}")

    # units stated in the file (column names, '# units:') must agree with the units passed
    t_unit = a_unit = a_word = None
    names_text, names_ln = header_text, header_ln
    if names_text is None and last_comment is not None and last_comment[1] == first and \
            _looks_like_names(last_comment[0], delim, ncols):
        names_text, names_ln = last_comment
    if names_text is not None:
        t_unit, a_unit, a_word = _column_units(p, names_ln, names_text, delim, ncols)
    stated = []
    if "units" in found:
        u, key, ln = found["units"]
        stated.append((u, key, f"line {ln}"))
    if a_unit is not None:
        stated.append((a_word, a_unit, f"line {names_ln} (column names)"))
    for u, key, where in stated:
        if factor is None:  # units=None: the unit the file states (they agree), else g
            if not _close(ACCELERATION[key], ACCELERATION[stated[0][1]]):
                raise RecordError(f"{p}, {where}: the file states units {u!r} and "
                                  f"{stated[0][0]!r}")
        elif not _close(ACCELERATION[key], factor):
            raise RecordError(f"{p}, {where}: the file states units {u!r} but units="
                              f"{units!r} was passed; pass units={key!r}")
    if factor is None:
        factor = ACCELERATION[stated[0][1]] if stated else ACCELERATION["g"]
        unit_name = stated[0][1] if stated else "g"
    else:
        unit_name = stated[0][1] if stated else (acceleration_unit(units) or str(units))

    npts = found.get("npts")
    if npts is not None and npts[0] != n:
        raise RecordError(f"{p}, line {npts[1]}: the header states npts = {npts[0]} but "
                          f"{n} samples were read" + (" (the file looks cut)"
                                                      if n < npts[0] else ""))
    if not ends_nl:
        _check_cut_columns(p, lines, first, delim, npts is not None)

    if ncols == 2:
        tf = TIME_FACTORS[t_unit] if t_unit else 1.0
        t, a = arr[:, 0] * tf, arr[:, 1]
        steps = np.diff(t)
        back = np.flatnonzero(steps <= 0.0)
        if back.size:
            k = int(back[0]) + 1
            ln = _data_line_numbers(lines, first)[k]
            raise RecordError(f"{p}, line {ln}: time does not increase ({t[k]:.9g} s after "
                              f"{t[k - 1]:.9g} s); the first column must be the time")
        mid = (steps.size - 1) // 2
        ref = float(np.partition(steps, mid)[mid])  # a typical step (lower median)
        uneven = np.flatnonzero(np.abs(steps - ref) > _DT_RTOL * ref)
        if uneven.size:
            k = int(uneven[0]) + 1
            ln = _data_line_numbers(lines, first)[k]
            raise RecordError(f"{p}, line {ln}: uneven time step {steps[k - 1]:.9g} s (the "
                              f"typical step is {ref:.9g} s); a record needs uniform time "
                              "steps: resample it first")
        step = float((t[-1] - t[0]) / (n - 1))
        t_start = float(t[0])
        checks = [] if dt is None else [(dt, "was passed")]
        if hdr_dt is not None:
            checks.append((hdr_dt[0], f"is stated in the header (line {hdr_dt[1]})"))
        for given, where in checks:
            if not _close(given, step):
                raise RecordError(f"{p}: dt={given:g} s {where} but the time column has a "
                                  f"step of {step:.9g} s")
    else:
        a = arr[:, 0]
        t_start = 0.0
        if dt is not None:
            step = dt
        elif hdr_dt is not None:
            step = hdr_dt[0]
        else:
            raise RecordError(f"dt is required for a one-column record ({p}): pass dt=... "
                              "or state it in a header comment such as '# dt = 0.01 s'")

    meta = {
        "name": p.stem, "format": "columns" if delim is None else "csv", "path": str(p),
        "npts": n, "dt": step, "units": unit_name, "t_start": t_start, "columns": ncols,
        "units_from": "file" if stated else "default" if units is None else "caller",
    }
    if ncols == 2:
        meta["time_units"] = t_unit or "s"
    if header_text is not None:
        meta["header"] = header_text
    return np.ascontiguousarray(a * factor), step, meta


def _check_cut_columns(p: Path, lines: list[str], first: int, delim, declared: bool) -> None:
    """Checks of a column file that does not end with a line break (a cut file): refused
    if it declares its length (``# npts``), or if its last value does not have the fixed
    format of the values above it (``-1.094953e-0`` below ``...e-03`` values)."""
    last_j = max(j for j in range(first, len(lines)) if _strip_comment(lines[j]))
    if declared:
        raise RecordError(f"{p}, line {last_j + 1}: the file declares npts but does not end "
                          "with a line break after its last value: the file looks cut (add "
                          "the line break if the file is complete)")

    def fields(j):
        r = _strip_comment(lines[j])
        return [t.strip().strip('"') for t in (r.split(delim) if delim else r.split())]

    toks = fields(last_j)
    above = [fields(j) for j in range(max(first, last_j - 50), last_j)
             if _strip_comment(lines[j])]
    col = len(toks) - 1
    layouts = {r[col].translate(_LAYOUT) if len(r) > col else "" for r in above}
    (ref,) = layouts if len(layouts) == 1 else ("",)
    last = toks[col].translate(_LAYOUT)
    if "." in ref and "E" in ref and last != ref and ref.startswith(last):  # cut short
        raise RecordError(f"{p}, line {last_j + 1}: the last value {toks[col]!r} does not "
                          f"have the number format of the values above it (like "
                          f"{above[-1][col]!r}): the file looks cut")


def _data_line_numbers(lines: list[str], first: int) -> list[int]:
    """1-based numbers of the lines from ``first`` that hold data (error path only)."""
    return [j + 1 for j in range(first, len(lines)) if _strip_comment(lines[j])]


def _raise_column_problem(p: Path, lines: list[str], first: int, delim, msg: str):
    """Find the line that made ``np.loadtxt`` fail and raise a RecordError naming it."""
    ncols = None
    ref = None
    for j in _data_line_numbers(lines, first):
        s = _strip_comment(lines[j - 1])
        toks = [t.strip().strip('"') for t in (s.split(delim) if delim else s.split())]
        for tok in toks:
            try:
                float(tok)
            except ValueError:
                shown = f"non-numeric value {tok!r}" if tok else "empty value"
                raise RecordError(f"{p}, line {j}: {shown}") from None
        if ncols is None:
            ncols, ref = len(toks), j
        elif len(toks) != ncols:
            raise RecordError(f"{p}, line {j}: {len(toks)} column(s), but line {ref} has "
                              f"{ncols}")
    raise RecordError(f"{p}: cannot read the columns: {msg}")
