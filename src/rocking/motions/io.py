"""Reading and writing accelerograms.

:func:`read_record` (behind :meth:`Record.from_file <rocking.motions.records.Record.from_file>`)
reads

* PEER NGA ``.AT2`` files (recognised by the extension or by an ``NPTS`` header on line 4):
  four header lines, the fourth stating ``NPTS=  2048, DT=   .0066 SEC`` (possibly followed
  by filter information) or ``2048    0.0066    NPTS, DT``; then the samples in g, in
  Fortran E format (``.1717907E-01``), five to a line, the last line possibly short;
* CSV or whitespace-separated columns: ``time, acceleration`` with uniform time steps, or
  a single acceleration column with a time step ``dt`` given by the caller or stated in a
  header comment (``# dt = 0.01 s``). Lines starting with ``#`` are comments; the first
  non-numeric line is taken as a column header. A comment ``# units: g`` states the units
  of the acceleration column; it must agree with the ``units`` passed.

Samples are returned in m/s^2 and the record starts at ``t = 0`` (a time column that
starts elsewhere is re-based, the original start kept in ``meta["t_start"]``). Every
problem raises :class:`~rocking.errors.RecordError` with a message that names the file and,
where it applies, the 1-based line number.

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

from .._validate import positive
from ..errors import RecordError, UnitError
from ..units import G, acceleration_factor
from .base import is_sampled

__all__ = ["read_record", "write_csv", "builtin_records", "read_builtin"]

_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?"
_AT2_NPTS = re.compile(r"NPTS\s*=\s*(\d+)", re.I)
_AT2_DT = re.compile(rf"\bDT\s*=\s*({_NUM})", re.I)
_AT2_ALT = re.compile(rf"^\s*(\d+)\s*,?\s+({_NUM})\s*,?\s*NPTS\s*,?\s*DT", re.I)
_AT2_UNITS = re.compile(r"UNITS\s+OF\s+([^\s,.]+)", re.I)
_FORTRAN_D = re.compile(r"(?<=[\d.])[dD](?=[-+]?\d)")
_HDR_DT = re.compile(rf"\bdt\s*[=:]\s*({_NUM})\s*(ms|s)?\b", re.I)
_HDR_UNITS = re.compile(r"^\s*#?\s*(?:acc\w*\s+)?units?\s*[=:]\s*([^\s,;]+)\s*(?:[,;].*)?$",
                        re.I)
_SPLIT = re.compile(r"[,;\s]+")

_DT_RTOL = 1e-6  # relative tolerance on time steps (uneven steps, dt disagreements)


# ------------------------------------------------------------------------------------ public
def read_record(path, units: str = "g", dt: float | None = None) -> tuple[np.ndarray, float, dict]:
    """Read an accelerogram file.

    Parameters
    ----------
    path : str or path-like
        A PEER NGA ``.AT2`` file, or a CSV / whitespace-column file (see the module doc).
    units : str
        Units of the acceleration values in the file: ``g``, ``m/s^2``, ``cm/s^2`` or
        ``gal`` (also ``mm/s^2``). ``.AT2`` files are always in g.
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
        ``name`` (file stem), ``format`` (``"AT2"``, ``"csv"`` or ``"columns"``), ``path``,
        ``npts``, ``dt``, ``units``, ``t_start`` (s, original start time) and, for
        ``.AT2`` files, ``description`` (event and station line), ``title``, ``header`` (the
        four header lines) and, when the description has the usual four comma-separated
        fields, ``event``, ``date``, ``station`` and ``component``.

    Raises
    ------
    RecordError
        The file is missing, empty or malformed (message names the file and line).
    UnitError
        ``units`` is not an acceleration unit.
    """
    p = Path(path)
    factor = acceleration_factor(units)
    if dt is not None:
        dt = positive("dt", dt, "s")
    text = _read_text(p)
    lines = text.splitlines()
    if _is_at2(p, lines):
        return _read_at2(p, lines, units, factor, dt)
    return _read_columns(p, lines, units, factor, dt)


def write_csv(record, path) -> Path:
    """Write ``record`` to ``path`` as CSV columns ``t,acc`` (s, m/s^2); returns the path.

    ``record`` is a :class:`~rocking.motions.records.Record` (or any sampled accelerogram
    with ``values``, ``dt``, ``t`` and ``name``). The samples are written with the record's
    load factor applied (``record.values``) and with full float precision. A comment header
    states the units and ``dt``, so the file reads back with
    ``read_record(path, units="m/s^2")`` or ``Record.from_file(path, units="m/s^2")``.
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
        np.savetxt(p, data, fmt="%.17g", delimiter=",", header=header, comments="")
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
    three-component sets (:func:`builtin_sets`)."""
    names = _stems(_builtin_dir())
    if three_component:
        names += _stems(_builtin_dir() / THREE_COMPONENT)
    return names


THREE_COMPONENT = "three_component"
SETS = {"rinaldi": ("Rinaldi228", "Rinaldi318", "RinaldiUP"),
        "duzce": ("RSN1158_KOCAELI_DZC180", "RSN1158_KOCAELI_DZC270", "RSN1158_KOCAELI_DZC-UP")}


def builtin_sets() -> dict[str, tuple[str, str, str]]:
    """The three-component sets shipped with the package: ``{name: (H1, H2, UP)}``
    (Northridge 1994 at Rinaldi, Kocaeli 1999 at Duzce)."""
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
def _read_at2(p: Path, lines: list[str], units: str, factor: float, dt: float | None):
    if factor != G:
        raise RecordError(
            f"{p}: PEER .AT2 files are in g; got units={units!r} (leave units='g')"
        )
    if len(lines) < 4:
        raise RecordError(
            f"{p}: not a valid PEER .AT2 file: expected 4 header lines, the 4th stating "
            f"'NPTS= <n>, DT= <s> SEC'; the file has only {len(lines)} line(s)"
        )
    hdr = lines[3]
    m_n, m_dt, m_alt = _AT2_NPTS.search(hdr), _AT2_DT.search(hdr), _AT2_ALT.match(hdr)
    if m_n and m_dt:
        npts, step = int(m_n[1]), _float(m_dt[1])
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
    m_u = _AT2_UNITS.search(lines[2])
    if m_u and m_u[1].upper() != "G":
        raise RecordError(
            f"{p}, line 3: expected an acceleration time series in units of G, "
            f"got {lines[2].strip()!r}"
        )
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
                    raise RecordError(f"{p}, line {i + 1}: non-numeric value {tok!r}") from None
        raise RecordError(f"{p}: cannot read the samples")  # pragma: no cover
    bad = np.flatnonzero(~np.isfinite(vals))
    if bad.size:
        ln = _line_of_token(lines, first, int(bad[0]))
        raise RecordError(f"{p}, line {ln}: NaN or infinite value {tokens[bad[0]]!r}")
    if vals.size < npts:
        raise RecordError(f"{p}: the header (line 4) states NPTS={npts} but only "
                          f"{vals.size} values follow")
    if vals.size > npts:
        ln = _line_of_token(lines, first, npts)
        raise RecordError(f"{p}, line {ln}: {vals.size - npts} value(s) beyond "
                          f"NPTS={npts} stated in the header (line 4)")

    desc = lines[1].strip()
    meta = {
        "name": p.stem, "format": "AT2", "path": str(p), "npts": npts, "dt": step,
        "units": "g", "t_start": 0.0, "title": lines[0].strip(), "description": desc,
        "header": [ln.rstrip() for ln in lines[:4]],
    }
    parts = [s.strip() for s in desc.split(",")]
    if len(parts) == 4:
        meta.update(event=parts[0], date=parts[1], station=parts[2], component=parts[3])
    return vals * G, step, meta


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


def _read_columns(p: Path, lines: list[str], units: str, factor: float, dt: float | None):
    hdr_dt = hdr_units = None
    header_text = None
    i = 0
    while i < len(lines):
        raw = lines[i]
        s = raw.strip()
        if not s:
            i += 1
            continue
        if s.startswith("#") or (header_text is None
                                   and not _is_numeric_line(_strip_comment(s))):
            if not s.startswith("#"):
                header_text = s
            m = _HDR_DT.search(s)
            if m and hdr_dt is None:
                hdr_dt = (_float(m[1]) * (1e-3 if (m[2] or "").lower() == "ms" else 1.0), i + 1)
            m = _HDR_UNITS.match(s)
            if m and hdr_units is None:
                hdr_units = (m[1], i + 1)
            i += 1
            continue
        break
    if i >= len(lines):
        raise RecordError(f"{p}: no data (the file holds only comments or a header line)")

    # units stated in the file must agree with the units passed
    if hdr_units is not None:
        u, ln = hdr_units
        try:
            f_hdr = acceleration_factor(u)
        except UnitError:
            raise RecordError(f"{p}, line {ln}: unknown units {u!r} stated in the header; "
                              "use one of g, m/s^2, cm/s^2, gal") from None
        if not _close(f_hdr, factor):
            raise RecordError(f"{p}, line {ln}: the file states units {u!r} but units="
                              f"{units!r} was passed; pass units={u!r}")
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
    try:
        arr = np.loadtxt(_io.StringIO("\n".join(lines[first:])), delimiter=delim,
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

    if ncols == 2:
        t, a = arr[:, 0], arr[:, 1]
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
        "npts": n, "dt": step, "units": units, "t_start": t_start, "columns": ncols,
    }
    if header_text is not None:
        meta["header"] = header_text
    return np.ascontiguousarray(a * factor), step, meta


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
