"""Readers of accelerogram files as the strong-motion databases distribute them.

:func:`detect` recognises a file by its content (never by its extension alone) and
:func:`read_esm`, :func:`read_cosmos` and :func:`read_knet` read it;
:func:`rocking.motions.io.read_record` calls them, so ``Record.from_file``, the motion
catalog's ``record`` kind, ``rocking simulate --record`` and ``rocking motion show`` read
these files too.

* **ESM** ASCII (Engineering Strong-Motion database, esm-db.eu / ORFEUS; header format
  "DYNA 1.2"): 64 header lines ``KEY: value`` (``EVENT_NAME``, ``EVENT_ID``, ...,
  ``NETWORK``, ``STATION_CODE``, ``STREAM``, ``SAMPLING_INTERVAL_S``, ``NDATA``,
  ``UNITS``, ``PGA_CM/S^2``, ``DATA_TYPE``, ..., ``USER1``-``USER5``), then ``NDATA``
  values, one per line. Recognised by its first line ``EVENT_NAME:`` and the keys
  ``NDATA`` and ``SAMPLING_INTERVAL_S``. Layout as read by the public readers of INGV
  (``dyna-convert.py``, the DYNA/ESM converter) and USGS gmprocess (``io/esm/core.py``).
* **COSMOS Volume 2** (COSMOS Strong Motion Data Format, version 1.20, 2001): a text
  header whose line 1 names the data (``Corrected acceleration``) and states ``(Format
  v01.20 with 13 text lines)``; an integer header (``100 Integer-header values follow on
  10 lines, Format= (10I8)``) and a real header (``100 Real-header values follow on 20
  lines, Format= (5F15.6)``), each with its count and Fortran format; comment lines
  (``6 Comment line(s) follow, each starting with a "|":``); the data header ``8000
  acceleration pts, approx 40 secs, units=cm/sec2(04), Format=(8F10.5)``; the values in
  that fixed-width format; ``End-of-data for Chan 1 acceleration``. Used here (1-based
  numbers as in the specification): integer #1 processing stage (2 = V2, corrected),
  #2 physical parameter (1 = acceleration), #3 units code (Table 2: 04 = cm/s/s, 02 = g,
  10 = gal); real #62 the time step in **ms**, #63 the series length npts dt (s), #64 the
  maximum value (the signed peak, in the data's units) and #65 its time (real #34 is the
  sampling interval of the raw record, used only when #62 is unknown). The indices are
  those of the specification's tables as implemented by USGS PRISM
  (``COSMOSformat/VFileConstants.java``: ``DELTA_T = 61``, ``MAX_VAL = 63`` 0-based) and
  gmprocess (``io/cosmos/core.py``, ``flt_data[61]`` in ms). Only corrected acceleration
  is accepted: a Volume 1 (uncorrected) or raw file, or one that holds only velocity or
  displacement, is refused by name. A V2 file that also holds the integrated velocity and
  displacement (CGS files) is read for its acceleration.
* **K-NET / KiK-net** ASCII (NIED, kyoshin.bosai.go.jp, "About K-NET ASCII format"): 17
  header lines (``Origin Time``, ..., ``Sampling Freq(Hz) 100Hz``, ``Duration Time(s)``,
  ``Dir.``, ``Scale Factor 7845(gal)/8223790``, ``Max. Acc. (gal)``, ``Last Correction``,
  ``Memo.``) then integer counts, 8 to a line. Read with obspy (``obspy.read(path,
  format="KNET")``, extra ``rocking[records]``), which returns the **counts** and the scale
  factor as ``stats.calib`` (m/s^2 per count); the scale factor is applied here, once, and
  cross-checked against the header line. NIED defines the maximum acceleration "after
  subtracting the average of the whole data": the counts carry an offset (thousands of
  counts), so the mean of the whole record is removed and stated in ``meta["offset"]``
  (gal). ``Dir.`` 1-3 are KiK-net's borehole sensors, 4-6 its surface sensors.

Why obspy for K-NET only: obspy has a maintained K-NET/KiK-net reader
(``obspy.io.nied.knet``, tested on NIED files), but none for ESM or COSMOS: the 31
waveform formats obspy 1.5 registers (``obspy.plugin.waveform`` entry points: SAC,
MSEED, GSE2, SEGY, KINEMETRICS_EVT, KNET, ...) include neither, and ``obspy.io.nied``
reads only K-NET ASCII and F-net moment tensors. ESM and COSMOS are read here, from their
specifications (the readers of gmprocess need its own stream classes and configuration).

Every reader checks what the file declares and refuses a file that contradicts itself:

* **units.** The file's unit (ESM ``UNITS``, COSMOS units code and name, K-NET
  ``(gal)``) must agree with ``units`` when the caller states one (the message names both
  and says what to pass; the file is never re-scaled silently); with ``units=None`` the
  file's unit is used. A unit outside g, m/s^2, cm/s^2 (gal), mm/s^2 is refused by name.
* **counts.** ``NDATA``, the COSMOS point count, and K-NET's duration times sampling
  frequency must equal the number of values read; a cut file (too few values, a last value
  shorter than the file's number format, a K-NET file without its final line break) is
  refused.
* **peaks.** A peak the header states (ESM ``PGA_CM/S^2``, COSMOS real #64, K-NET ``Max.
  Acc.``) is compared with the peak of the data: within the rounding of the two numbers it
  agrees; up to 1 % off it gives a :class:`~rocking.errors.PlausibilityWarning`; beyond
  that the file is refused.
* **time step.** A ``dt`` passed by the caller must agree with the file's. A COSMOS file
  that states none (real #62 and #34 unknown) is read with the caller's ``dt`` (still
  checked against the series length #63), and ``meta["dt_from"]`` says ``"caller"``
  (``"file"`` otherwise); without ``dt`` it is refused.
* **rounding.** A number's rounding is half a unit in its last place as written: an
  absolute ``0.5 10^-d`` for ``d`` decimals, ``0.5 10^(e - d)`` with an exponent ``e``
  (``Format=(1E15.6)`` data, as gmprocess writes COSMOS files).
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from .._validate import warn_implausible
from ..errors import RecordError
from ..units import ACCELERATION, ACCELERATION_UNITS, acceleration_unit

__all__ = ["detect", "read_esm", "read_cosmos", "read_knet", "FORMATS"]

FORMATS = ("ESM", "COSMOS-V2", "KNET", "KiK-net")
"""Values of ``meta["format"]`` set by the readers of this module."""

_RTOL = 1e-6  # relative tolerance on time steps
_PEAK_WARN = 0.01  # a stated peak off by more than its rounding but < 1 %: a warning
_NUM = re.compile(r"^[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?$")


# ------------------------------------------------------------------------------ detection
_ESM_KEY = re.compile(r"^([A-Z][A-Z0-9_/^.\-]*)\s*:(.*)$")
_COSMOS_LINE1 = re.compile(r"\(\s*Format\s+v\s*(\d+(?:\.\d+)?)\s+with\s+(\d+)\s+text\s+lines?\s*\)",
                           re.I)
_ESM_HEADER_LINES = 64


def detect(lines: list[str]) -> str | None:
    """The format of a file from its first lines: ``"ESM"``, ``"COSMOS"``, ``"KNET"`` or
    None (not one of these; AT2 and columns are recognised by :mod:`rocking.motions.io`)."""
    if not lines:
        return None
    first = lines[0]
    if first.startswith("Origin Time") and len(lines) > 5 and \
            lines[5].startswith("Station Code"):
        return "KNET"  # obspy's and gmprocess's test: 'Origin Time', line 6 'Station Code'
    if _COSMOS_LINE1.search(first):
        return "COSMOS"
    if first.startswith("EVENT_NAME:"):
        keys = {m[1] for ln in lines[:_ESM_HEADER_LINES + 10] if (m := _ESM_KEY.match(ln))}
        if {"NDATA", "SAMPLING_INTERVAL_S"} <= keys:
            return "ESM"
    return None


# -------------------------------------------------------------------------------- helpers
def _close(a: float, b: float, rtol: float = _RTOL) -> bool:
    return abs(a - b) <= rtol * max(abs(a), abs(b))


def _factor(p: Path, key: str, where: str, units: str | None, factor: float | None) -> float:
    """SI factor of the file's unit ``key`` (stated at ``where``), which must agree with
    the caller's ``units`` (``factor``) unless the caller stated none."""
    if factor is not None and not _close(ACCELERATION[key], factor):
        raise RecordError(f"{p}: the file is in {key} ({where}) but units={units!r} was "
                          f"passed; pass units={key!r}")
    return ACCELERATION[key]


def _unit_key(p: Path, word: str, where: str) -> str:
    key = acceleration_unit(word)
    if key is None:
        raise RecordError(f"{p}: {where} states the unit {word!r}, which is not an "
                          f"acceleration unit read here ({', '.join(ACCELERATION_UNITS)})")
    return key


def _check_dt(p: Path, step: float, dt: float | None, where: str) -> None:
    if not (math.isfinite(step) and step > 0.0):
        raise RecordError(f"{p}: {where} states a time step of {step!r} s; it must be > 0")
    if dt is not None and not _close(dt, step):
        raise RecordError(f"{p}: dt={dt:g} s was passed but {where} states dt = {step:g} s")


def _decimals(text: str) -> int:
    """Digits after the decimal point of a number as written (0 if none)."""
    m = re.search(r"\.(\d*)", text)
    return len(m[1]) if m else 0


def _half_ulp(text: str) -> float:
    """Half a unit in the last place of a number as written: ``0.5 10^(e - d)`` for ``d``
    digits after the point and exponent ``e`` (0 without one): ``2677.001`` -> 5e-4,
    ``2.677001E+03`` -> 5e-4, ``0.2677E+04`` -> 0.5 (a fixed number of decimals is an
    absolute precision only without an exponent)."""
    t = text.strip()
    m = re.search(r"[eEdD]([-+]?\d+)$", t)
    e = int(m[1]) if m else 0
    return 0.5 * 10.0 ** (e - _decimals(t[:m.start()] if m else t))


def _agree(stated: float, peak: float, tol: float) -> bool:
    """Whether a stated peak and the data's agree within ``tol`` (their rounding)."""
    return abs(abs(stated) - peak) <= tol * (1.0 + 1e-9) + 1e-12 * peak


def _check_peak(p: Path, where: str, stated: float, peak: float, tol: float,
                unit: str) -> None:
    """The peak a header states against the data's: within ``tol`` (the rounding of both
    numbers) they agree; within 1 % a warning; beyond, a RecordError."""
    diff = abs(abs(stated) - peak)
    if _agree(stated, peak, tol):
        return
    msg = (f"{p}: {where} states a peak of {abs(stated):.15g} {unit} but the data's peak "
           f"is {peak:.15g} {unit}")
    if diff <= _PEAK_WARN * max(abs(stated), peak):
        warn_implausible(msg + f" ({100 * diff / max(abs(stated), peak):.2g} % apart)")
        return
    raise RecordError(msg + ": the file contradicts itself (a wrong header, scale or "
                      "truncated data)")


def _last_value_cut(p: Path, tokens: list[str], ln: int) -> None:
    """Refuse a last value written with fewer decimals than every other one (a file cut
    inside its last number)."""
    if len(tokens) < 3:
        return
    shape = {(_decimals(t), "e" in t.lower()) for t in tokens[:-1]}
    if len(shape) != 1:
        return
    (dec, exp), = shape
    last = tokens[-1]
    if dec > 0 and ((_decimals(last) < dec) or (exp and "e" not in last.lower())):
        raise RecordError(f"{p}, line {ln}: the last value {last!r} is shorter than the "
                          f"file's number format (like {tokens[-2]!r}): the file looks cut")


def _as_float(p: Path, ln: int, tok: str, what: str = "value") -> float:
    t = tok.strip()
    if not _NUM.match(t):
        raise RecordError(f"{p}, line {ln}: non-numeric {what} {t!r}")
    return float(t.replace("D", "E").replace("d", "e"))


# -------------------------------------------------------------------------------------- ESM
def read_esm(p: Path, lines: list[str], units: str | None, factor: float | None,
             dt: float | None) -> tuple[np.ndarray, float, dict]:
    """Read an ESM ASCII file (see the module doc): ``(acc m/s^2, dt s, meta)``."""
    hdr: dict[str, str] = {}
    where: dict[str, int] = {}  # key -> 1-based line
    first = None
    for i, ln in enumerate(lines):
        m = _ESM_KEY.match(ln.strip())
        if m is None:
            first = i
            break
        hdr.setdefault(m[1], m[2].strip())
        where.setdefault(m[1], i + 1)
    if first is None:
        raise RecordError(f"{p}: an ESM file with a header of {len(lines)} lines and no "
                          "data")

    def need(key: str) -> str:
        if not hdr.get(key):
            raise RecordError(f"{p}: the ESM header has no {key} (or it is empty)")
        return hdr[key]

    kind = need("DATA_TYPE").upper()
    if kind != "ACCELERATION":
        raise RecordError(f"{p}: the ESM file holds DATA_TYPE: {hdr['DATA_TYPE']}; only "
                          "ACCELERATION time series are read (download the .ACC file)")
    word = need("UNITS")
    key = _unit_key(p, word, f"UNITS: {word}")
    f = _factor(p, key, f"ESM header UNITS: {word}", units, factor)
    ndata_s = need("NDATA")
    if not ndata_s.isdigit():
        raise RecordError(f"{p}, line {where['NDATA']}: NDATA must be a whole number, got "
                          f"{ndata_s!r}")
    ndata = int(ndata_s)
    step = _as_float(p, where.get("SAMPLING_INTERVAL_S", 0), need("SAMPLING_INTERVAL_S"),
                     "SAMPLING_INTERVAL_S")
    _check_dt(p, step, dt, "the ESM header (SAMPLING_INTERVAL_S)")

    tokens: list[str] = []
    last_ln = first
    for j in range(first, len(lines)):
        parts = lines[j].split()
        if parts:
            tokens.extend(parts)
            last_ln = j
    bad = next((k for k, t in enumerate(tokens) if not _NUM.match(t)), None)
    if bad is not None:
        raise RecordError(f"{p}, line {_esm_line(lines, first, bad)}: non-numeric value "
                          f"{tokens[bad]!r}")
    vals = np.array([float(t.replace("D", "E").replace("d", "e")) for t in tokens])
    if vals.size < ndata:
        raise RecordError(f"{p}: the ESM header states NDATA: {ndata} but {vals.size} "
                          "values follow (the file looks cut)")
    if vals.size > ndata:
        raise RecordError(f"{p}: {vals.size - ndata} value(s) beyond NDATA: {ndata} stated "
                          "in the ESM header")
    if ndata < 2:
        raise RecordError(f"{p}: a record needs at least 2 samples, NDATA is {ndata}")
    _last_value_cut(p, tokens, last_ln + 1)
    bad = np.flatnonzero(~np.isfinite(vals))
    if bad.size:
        raise RecordError(f"{p}: NaN or infinite value at sample {bad[0]}")
    _esm_duration(p, hdr, where, ndata, step)

    peak = float(np.max(np.abs(vals)))
    pga_key = next((k for k in hdr if k.startswith("PGA_")), None)
    pga = None
    if pga_key and hdr[pga_key]:
        pga_unit = _unit_key(p, pga_key[4:], pga_key)
        s = hdr[pga_key]
        pga = _as_float(p, where[pga_key], s, pga_key)
        tol = _half_ulp(s) + _half_ulp(tokens[int(np.argmax(np.abs(vals)))])
        if ACCELERATION[pga_unit] != ACCELERATION[key] and _agree(pga, peak, tol):
            raise RecordError(f"{p}, line {where['UNITS']}: UNITS: {word} contradicts "
                              f"{pga_key} (line {where[pga_key]}): the data's peak "
                              f"{peak:.15g} is {pga_key}: {s} as a number, so the values are"
                              f" in {pga_unit}, not in {key}; the file contradicts itself")
        _check_peak(p, f"the ESM header ({pga_key})",
                    pga * ACCELERATION[pga_unit] / ACCELERATION[key], peak, tol, key)

    network, station = hdr.get("NETWORK", ""), hdr.get("STATION_CODE", "")
    meta = {
        "name": p.stem, "format": "ESM", "path": str(p), "npts": ndata, "dt": step,
        "units": key, "t_start": 0.0, "network": network, "station": station,
        "station_name": hdr.get("STATION_NAME", ""), "location": hdr.get("LOCATION", ""),
        "component": hdr.get("STREAM", ""), "event": hdr.get("EVENT_ID", ""),
        "event_name": hdr.get("EVENT_NAME", ""), "date": hdr.get("EVENT_DATE_YYYYMMDD", ""),
        "magnitude": hdr.get("MAGNITUDE_W") or hdr.get("MAGNITUDE_L", ""),
        "processing": hdr.get("PROCESSING", ""),
        "description": ", ".join(x for x in (hdr.get("EVENT_ID", ""),
                                             ".".join(x for x in (network, station) if x),
                                             hdr.get("STREAM", "")) if x),
        "header": [ln.rstrip() for ln in lines[:first]],
    }
    if pga is not None:
        meta["pga_declared"] = pga
    return vals * f, step, meta


def _esm_duration(p: Path, hdr: dict, where: dict, ndata: int, step: float) -> None:
    """``DURATION_S`` (if stated) against ``NDATA`` samples every ``SAMPLING_INTERVAL_S``:
    ``NDATA dt`` or ``(NDATA - 1) dt`` within the rounding of the three numbers as
    written (a step in ms written as s, or a wrong count, is refused)."""
    text = hdr.get("DURATION_S", "")
    if not text:
        return
    ln = where["DURATION_S"]
    dur = _as_float(p, ln, text, "DURATION_S")
    step_s = hdr["SAMPLING_INTERVAL_S"]
    tol = _half_ulp(text) + ndata * _half_ulp(step_s) + 1e-12 * abs(dur)
    if math.isfinite(dur) and min(abs(dur - ndata * step),
                                  abs(dur - (ndata - 1) * step)) <= tol * (1 + 1e-9):
        return
    hint = ""
    if dur > 0 and math.isfinite(dur):
        ratio = ndata * step / dur
        if 500 <= ratio <= 2000:
            hint = " (is SAMPLING_INTERVAL_S in ms?)"
    raise RecordError(f"{p}, line {ln}: DURATION_S: {text} contradicts NDATA: {ndata} "
                      f"(line {where['NDATA']}) and SAMPLING_INTERVAL_S: {step_s} (line "
                      f"{where['SAMPLING_INTERVAL_S']}): {ndata} samples every {step:g} s "
                      f"last {ndata * step:g} s{hint}; the file contradicts itself")


def _esm_line(lines: list[str], first: int, k: int) -> int:
    """1-based line of the ``k``-th value (error path: computed only when it is asked)."""
    n = 0
    for j in range(first, len(lines)):
        n += len(lines[j].split())
        if n > k:
            return j + 1
    return len(lines)


# ----------------------------------------------------------------------------------- COSMOS
_INT_HDR = re.compile(r"^\s*(\d+)\s+Integer-header\s+values\s+follow\s+on\s+(\d+)\s+lines?"
                      r"\s*,?\s*Format\s*=\s*\((.*?)\)", re.I)
_REAL_HDR = re.compile(r"^\s*(\d+)\s+Real-header\s+values\s+follow\s+on\s+(\d+)\s+lines?"
                       r"\s*,?\s*Format\s*=\s*\((.*?)\)", re.I)
_COMMENTS = re.compile(r"^\s*(\d+)\s+Comment\s+line", re.I)
_DATA_HDR = re.compile(r"^\s*(\d+)\s+([A-Za-z]+)\s+(?:pts|points)\b(.*?)units\s*=\s*(.*?)"
                       r"\s*,\s*Format\s*=\s*\((.*?)\)", re.I)
_APPROX = re.compile(r"approx\s+(\d+(?:\.\d*)?)\s*sec", re.I)
_FORTRAN = re.compile(r"^\s*(\d*)\s*([IFEGD])\s*(\d+)(?:\.(\d+))?", re.I)
_UNKNOWN = re.compile(r"unknown/unspecified\s*:\s*(-?\d+)\s*,?\s*(-?\d+\.?\d*)", re.I)
_UNITS_CODE = re.compile(r"^(.*?)\s*\(\s*(\d+)\s*\)\s*$")
_TEXT_MAX = re.compile(r"\bmax\s*=\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*"
                       r"([^\s,;]+)", re.I)
_END = re.compile(r"^\s*End[- ]of[- ]data", re.I)

COSMOS_UNITS = {2: "g", 4: "cm/s^2", 10: "gal"}
"""COSMOS Table 2 acceleration units codes read here (others, e.g. 07 in/s/s, 11 mg, 50
counts, are refused by name)."""
_COSMOS_UNIT_NAMES = {1: "s", 3: "s & g", 5: "cm/s", 6: "cm", 7: "in/s/s", 8: "in/s",
                      9: "in", 11: "mg", 12: "micro g", 50: "counts", 51: "volts"}
_COSMOS_PARAMS = {1: "acceleration", 2: "velocity", 3: "displacement (absolute)",
                  4: "displacement (relative)"}
_COSMOS_STAGES = {0: "Volume 0 (raw counts)", 1: "Volume 1 (uncorrected acceleration)",
                  2: "Volume 2 (corrected)", 3: "Volume 3 (response spectra)"}


def _fortran(p: Path, ln: int, fmt: str) -> tuple[int, int, int]:
    """``(values per line, field width, decimals)`` of a Fortran format such as
    ``8F10.5``, ``10I8``, ``1E15.6``."""
    m = _FORTRAN.match(fmt)
    if m is None:
        raise RecordError(f"{p}, line {ln}: cannot read the Fortran format ({fmt})")
    return int(m[1] or 1), int(m[3]), int(m[4] or 0)


def _fixed(p: Path, lines: list[str], start: int, n: int, fmt: str, fmt_ln: int,
           what: str) -> tuple[np.ndarray, int, int]:
    """Read ``n`` values in the fixed-width Fortran format ``fmt`` from line ``start``
    (0-based). Returns the values, the index of the line after them and the decimals."""
    per, width, dec = _fortran(p, fmt_ln, fmt)
    nlines = -(-n // per)
    if start + nlines > len(lines):
        got = sum(len(ln.rstrip("\r\n")) // width for ln in lines[start:])
        raise RecordError(f"{p}, line {fmt_ln}: {n} {what} declared but the file ends after "
                          f"about {got} (the file looks cut)")
    out = np.empty(n)
    k = 0
    for j in range(start, start + nlines):
        line = lines[j].rstrip("\r\n")
        m = min(per, n - k)  # fields right-justified: a shorter line lost digits
        if len(line) < m * width:
            raise RecordError(f"{p}, line {j + 1}: {m} {what} of format ({fmt}) expected, "
                              "the line is shorter (the file looks cut)")
        if line[m * width:].strip():
            raise RecordError(f"{p}, line {j + 1}: more than the {m} {what} of format "
                              f"({fmt}) on the line")
        for q in range(m):
            out[k] = _as_float(p, j + 1, line[q * width:(q + 1) * width], what.rstrip("s"))
            k += 1
    return out, start + nlines, dec


def _field(lines: list[str], start: int, fmt: str, k: int) -> str:
    """The text of the ``k``-th (0-based) value of a fixed-width block that starts at line
    ``start`` (0-based) in the Fortran format ``fmt`` (already read by :func:`_fixed`)."""
    m = _FORTRAN.match(fmt)
    per, width = int(m[1] or 1), int(m[3])
    return lines[start + k // per][(k % per) * width:(k % per + 1) * width]


def _cosmos_records(p: Path, lines: list[str]) -> list[dict]:
    """Parse every record (channel and quantity) of a COSMOS file."""
    recs = []
    i = 0
    while i < len(lines):
        if not lines[i].strip():
            i += 1
            continue
        m = _COSMOS_LINE1.search(lines[i])
        if m is None:
            raise RecordError(f"{p}, line {i + 1}: expected the first line of a COSMOS text "
                              "header ('... (Format v01.20 with 13 text lines)')")
        ntext = int(m[2])
        text = lines[i:i + ntext]
        if len(text) < ntext:
            raise RecordError(f"{p}, line {i + 1}: {ntext} text header lines declared, the "
                              "file ends before (the file looks cut)")
        rec = {"line": i + 1, "text": [t.rstrip() for t in text],
               "product": lines[i][:m.start()].strip(), "version": m[1]}
        j = i + ntext
        for key, rx, what in (("ints", _INT_HDR, "integer-header values"),
                              ("reals", _REAL_HDR, "real-header values")):
            mm = rx.match(lines[j]) if j < len(lines) else None
            if mm is None:
                raise RecordError(f"{p}, line {j + 1}: expected the line announcing the "
                                  f"{what} ('100 {'Integer' if key == 'ints' else 'Real'}"
                                  "-header values follow on ... lines, Format= (...)')")
            n, nl = int(mm[1]), int(mm[2])
            vals, nxt, dec = _fixed(p, lines, j + 1, n, mm[3], j + 1, what)
            if nxt != j + 1 + nl:
                raise RecordError(f"{p}, line {j + 1}: {n} {what} in format ({mm[3]}) take "
                                  f"{nxt - j - 1} lines, the line states {nl}")
            rec[key], rec[key + "_decimals"] = vals, dec
            rec[key + "_start"], rec[key + "_fmt"] = j + 1, mm[3]
            j = nxt
        mm = _COMMENTS.match(lines[j]) if j < len(lines) else None
        if mm is None:
            raise RecordError(f"{p}, line {j + 1}: expected the comment count line ('N "
                              "Comment line(s) follow, each starting with a \"|\":')")
        nc = int(mm[1])
        rec["comments"] = [c.rstrip() for c in lines[j + 1:j + 1 + nc]]
        j += 1 + nc
        mm = _DATA_HDR.match(lines[j]) if j < len(lines) else None
        if mm is None:
            raise RecordError(f"{p}, line {j + 1}: expected the data header ('N acceleration "
                              "pts, approx T secs, units=cm/sec2(04), Format=(8F10.5)')")
        rec.update(npts=int(mm[1]), quantity=mm[2].lower(), units_text=mm[4].strip(),
                   fmt=mm[5], data_line=j + 1, data_header=lines[j].rstrip())
        ap = _APPROX.search(mm[3])
        rec["approx"] = float(ap[1]) if ap else None
        vals, nxt, dec = _fixed(p, lines, j + 1, rec["npts"], mm[5], j + 1, "data values")
        rec["values"], rec["decimals"] = vals, dec
        rec["end_line"] = nxt
        if nxt < len(lines) and _END.match(lines[nxt]):
            nxt += 1
        i = nxt
        recs.append(rec)
    return recs


def read_cosmos(p: Path, lines: list[str], units: str | None, factor: float | None,
                dt: float | None) -> tuple[np.ndarray, float, dict]:
    """Read the corrected acceleration of a COSMOS Volume 2 file (see the module doc)."""
    recs = _cosmos_records(p, lines)
    acc = [r for r in recs if r["quantity"].startswith("acc")]
    if not acc:
        held = ", ".join(sorted({r["quantity"] for r in recs}))
        raise RecordError(f"{p}: the COSMOS file holds {held} data, no acceleration; only "
                          "corrected acceleration (Volume 2) is read")
    if len(acc) > 1:
        chans = "; ".join(_cosmos_component(r) or f"line {r['line']}" for r in acc)
        raise RecordError(f"{p}: the COSMOS file holds {len(acc)} acceleration channels "
                          f"({chans}); a record is one channel: split the file")
    r = acc[0]
    ints, reals = r["ints"], r["reals"]
    unk_i, unk_r = -999, -999.0
    if len(r["text"]) >= 13 and (m := _UNKNOWN.search(r["text"][12])):
        unk_i, unk_r = int(m[1]), float(m[2])

    def ival(k: int):  # 1-based integer header value, None if unknown
        v = int(ints[k - 1]) if len(ints) >= k else unk_i
        return None if v == unk_i else v

    def rval(k: int):
        v = float(reals[k - 1]) if len(reals) >= k else unk_r
        return None if v == unk_r else v

    product = r["product"]
    stage = ival(1)
    if stage != 2 or not product.lower().startswith("corrected"):
        what = (f"'{product}'" if stage == 2 else "of an unknown processing stage"
                if stage is None else _COSMOS_STAGES.get(stage, f"processing stage {stage}"))
        raise RecordError(f"{p}, line {r['line']}: the COSMOS file is {what} (line 1: "
                          f"'{product}', integer header #1 = {stage}); only Volume 2 "
                          "corrected acceleration is read")
    param = ival(2)
    if param is not None and param != 1:
        raise RecordError(f"{p}: the COSMOS integer header #2 states physical parameter "
                          f"{param} ({_COSMOS_PARAMS.get(param, 'unknown')}) for the "
                          "acceleration data; expected 1 (acceleration)")
    # units: the data header's name and code, and integer header #3, must agree
    mu = _UNITS_CODE.match(r["units_text"])
    word, code_s = (mu[1], mu[2]) if mu else (r["units_text"], None)
    codes = {int(code_s)} if code_s else set()
    if (c3 := ival(3)) is not None:
        codes.add(c3)
    if len(codes) > 1:
        raise RecordError(f"{p}, line {r['data_line']}: the units code of the data header "
                          f"({code_s}) and integer header #3 ({c3}) disagree")
    keys = set()
    for c in codes:
        if c not in COSMOS_UNITS:
            raise RecordError(f"{p}, line {r['data_line']}: COSMOS units code {c:02d} "
                              f"({_COSMOS_UNIT_NAMES.get(c, 'unknown')}) is not an "
                              f"acceleration unit read here ({', '.join(ACCELERATION_UNITS)})")
        keys.add(COSMOS_UNITS[c])
    if word:
        keys.add(_unit_key(p, word, f"line {r['data_line']} (units={r['units_text']})"))
    if not keys:
        raise RecordError(f"{p}, line {r['data_line']}: the data header states no units")
    if len({ACCELERATION[k] for k in keys}) > 1:
        raise RecordError(f"{p}, line {r['data_line']}: the units name and code disagree "
                          f"({r['units_text']}, integer header #3 = {c3})")
    key = sorted(keys, key=len)[-1]  # 'cm/s^2' over 'gal' for the same factor
    for t, line in enumerate(r["text"]):  # 'Max = 88.923 cm/s^2 at ...' (text lines 10, 11)
        for mm in _TEXT_MAX.finditer(line):
            tk = acceleration_unit(mm[1])
            if tk is not None and ACCELERATION[tk] != ACCELERATION[key]:
                raise RecordError(f"{p}, line {r['line'] + t}: the text header states "
                                  f"{mm[0].strip()!r} but the data header (line "
                                  f"{r['data_line']}) states units={r['units_text']}"
                                  + (f" and integer header #3 = {c3}" if c3 is not None
                                     else "") + ": the file contradicts itself")
    f = _factor(p, key, f"COSMOS data header units={r['units_text']}", units, factor)

    # time step: real #62 (ms), else real #34 (s), else the caller's dt
    dt_from = "file"
    if (ms := rval(62)) is not None:
        step, where = ms / 1000.0, "the COSMOS real header #62 (time step in ms)"
    elif (s34 := rval(34)) is not None:
        step, where = s34, "the COSMOS real header #34 (sampling interval in s)"
    elif dt is not None:  # the file states none: the caller's, still checked against #63
        step, where, dt_from = dt, "dt passed", "caller"
    else:
        raise RecordError(f"{p}: the COSMOS real header states no time step (#62 in ms, #34 "
                          "in s): pass dt")
    _check_dt(p, step, dt, where)
    vals, n = r["values"], r["npts"]
    if n < 2:
        raise RecordError(f"{p}, line {r['data_line']}: a record needs at least 2 samples")
    if (length := rval(63)) is not None:  # npts dt (or (npts - 1) dt) to their rounding
        tol = _half_ulp(_field(lines, r["reals_start"], r["reals_fmt"], 62))
        if dt_from == "file":
            k = 61 if rval(62) is not None else 33
            tol += n * _half_ulp(_field(lines, r["reals_start"], r["reals_fmt"], k)) * \
                (1e-3 if k == 61 else 1.0)
        if min(abs(length - n * step), abs(length - (n - 1) * step)) > tol * (1 + 1e-9) + \
                1e-12 * abs(length):
            raise RecordError(f"{p}, line {r['reals_start'] + 1 + 62 // 5}: the COSMOS real "
                              f"header #63 states a series length of {length:g} s but {n} "
                              f"points every {step:g} s ({where}) last {n * step:.9g} s "
                              "(the file looks cut or its time step is wrong)")
    if r["approx"] is not None and not (
            math.floor((n - 1) * step) - 1.0 <= r["approx"] <= math.ceil(n * step) + 1.0):
        raise RecordError(f"{p}, line {r['data_line']}: the data header states approx "
                          f"{r['approx']:g} secs but {n} points every {step:g} s last "
                          f"{n * step:g} s")
    peak = float(np.max(np.abs(vals)))
    pga = rval(64)
    if pga is not None:  # the rounding of both numbers as written (E formats: relative)
        tol = _half_ulp(_field(lines, r["reals_start"], r["reals_fmt"], 63)) + \
            _half_ulp(_field(lines, r["data_line"], r["fmt"], int(np.argmax(np.abs(vals)))))
        _check_peak(p, "the COSMOS real header #64 (maximum value)", pga, peak, tol, key)

    code = re.search(r"Code:\s*(\S+)", r["text"][4]) if len(r["text"]) > 4 else None
    network, station = "", ""
    if code:
        network, _, station = code[1].partition("-")
        if not station:
            network, station = "", network
    meta = {
        "name": p.stem, "format": "COSMOS-V2", "path": str(p), "npts": n, "dt": step,
        "units": key, "t_start": 0.0, "network": network, "station": station,
        "dt_from": dt_from, "component": _cosmos_component(r), "event": r["text"][1].strip() if
        len(r["text"]) > 1 else "", "product": product, "cosmos_version": r["version"],
        "description": r["text"][1].strip() if len(r["text"]) > 1 else "",
        "header": r["text"], "comments": r["comments"], "data_header": r["data_header"],
    }
    if len(r["text"]) > 4:
        meta["station_name"] = r["text"][4][40:].strip()
    if pga is not None:
        meta["pga_declared"] = pga
    return vals * f, step, meta


def _cosmos_component(r: dict) -> str:
    """The channel's orientation from text line 9 (``Sta Chan   1:270 deg (Rcrdr ...``)."""
    if len(r["text"]) < 9:
        return ""
    m = re.search(r"Sta\s+Chan\s*\d+\s*:\s*(.*?)\s*(?:\(|Location:|$)", r["text"][8])
    return m[1].strip() if m else ""


# ------------------------------------------------------------------------------ K-NET
_KNET_SCALE = re.compile(r"^Scale Factor\s+(\d+(?:\.\d*)?)\s*\(\s*([^)]*?)\s*\)\s*/\s*"
                         r"(\d+(?:\.\d*)?)\s*$")
_KNET_MAX = re.compile(r"^Max\.?\s*Acc\.?\s*\(\s*([^)]*?)\s*\)")
_KNET_HEADER_LINES = 17
_KIKNET_SENSORS = {"1": "borehole", "2": "borehole", "3": "borehole",
                   "4": "surface", "5": "surface", "6": "surface"}
_KNET_DIRS = {"1": "NS", "2": "EW", "3": "UD", "4": "NS", "5": "EW", "6": "UD",
              "N-S": "NS", "E-W": "EW", "U-D": "UD"}


def read_knet(p: Path, lines: list[str], units: str | None, factor: float | None,
              dt: float | None, text: str = "") -> tuple[np.ndarray, float, dict]:
    """Read a K-NET / KiK-net ASCII file with obspy (see the module doc)."""
    hdr = [ln.rstrip() for ln in lines[:_KNET_HEADER_LINES]]
    if len(hdr) < _KNET_HEADER_LINES or not hdr[-1].startswith("Memo"):
        raise RecordError(f"{p}: a K-NET/KiK-net file has {_KNET_HEADER_LINES} header lines "
                          "ending with 'Memo.'; this one does not")
    m = _KNET_SCALE.match(hdr[13])
    if m is None:
        raise RecordError(f"{p}, line 14: expected 'Scale Factor <n>(gal)/<d>', got "
                          f"{hdr[13]!r}")
    num, word, den = float(m[1]), m[2], float(m[3])
    key = _unit_key(p, word, "line 14 (Scale Factor)")
    f = _factor(p, key, f"K-NET Scale Factor in ({word})", units, factor)
    try:
        import obspy
    except ImportError:
        raise RecordError(f"{p}: K-NET/KiK-net files are read with obspy, which is not "
                          'installed: pip install "rocking[records]"') from None
    try:
        with np.errstate(all="ignore"):
            tr = obspy.read(str(p), format="KNET")[0]
    except ValueError as e:  # a non-numeric count, an unreadable date
        raise RecordError(f"{p}: not a readable K-NET/KiK-net file: {e}") from None
    except Exception as e:  # obspy's KNETException (a header line not as specified)
        raise RecordError(f"{p}: not a readable K-NET/KiK-net file: "
                          f"{' '.join(str(e).split())}") from None
    counts = np.asarray(tr.data, dtype=np.float64)
    calib = float(tr.stats.calib)  # m/s^2 per count (obspy: 0.01 num / den)
    scale = num / den  # gal per count, as the header states it
    if not _close(calib, 0.01 * scale, 1e-12):
        raise RecordError(f"{p}, line 14: obspy's calibration {calib!r} m/s^2 per count "
                          f"disagrees with the Scale Factor {m[1]}({word})/{m[3]}")
    fs = float(tr.stats.sampling_rate)
    step = 1.0 / fs
    _check_dt(p, step, dt, f"line 11 ({hdr[10].split()[-1]})")
    duration = float(tr.stats.knet.duration)
    want = round(duration * fs)
    n = counts.size
    if n != want:
        raise RecordError(f"{p}: the header states Duration Time {duration:g} s at {fs:g} Hz,"
                          f" i.e. {want} values, but {n} were read"
                          + (" (the file looks cut)" if n < want else ""))
    if text and not text.endswith(("\n", "\r")):
        raise RecordError(f"{p}, line {len(lines)}: the file does not end with a line break "
                          "after its last value (every K-NET line ends with one): the file "
                          "looks cut")
    if n < 2:
        raise RecordError(f"{p}: a record needs at least 2 samples, found {n}")
    offset = float(counts.mean())
    gal = (counts - offset) * scale  # NIED: data minus the average of the whole record
    peak = float(np.max(np.abs(gal)))
    stated_s = hdr[14].split()[-1]
    stated = _as_float(p, 15, stated_s, "Max. Acc.")
    if (mu := _KNET_MAX.match(hdr[14])) is not None:
        k15 = _unit_key(p, mu[1], "line 15 (Max. Acc.)")
        if ACCELERATION[k15] != ACCELERATION[key]:
            raise RecordError(f"{p}, line 15: Max. Acc. is stated in ({mu[1]}) but line 14's "
                              f"Scale Factor in ({word}): the file contradicts itself (which "
                              "unit are the counts scaled to?)")
    _check_peak(p, "line 15 (Max. Acc., after subtracting the mean)", stated, peak,
                0.5 * 10.0 ** -_decimals(stated_s), "gal")
    direction = hdr[12].split(None, 1)[1].strip() if len(hdr[12].split()) > 1 else ""
    kik = direction in _KIKNET_SENSORS
    meta = {
        "name": p.stem, "format": "KiK-net" if kik else "KNET", "path": str(p), "npts": n,
        "dt": step, "units": key, "t_start": 0.0, "network": str(tr.stats.network),
        "station": str(tr.stats.station), "component": _KNET_DIRS.get(direction, direction),
        "direction": direction, "sampling_frequency": fs, "duration_stated": duration,
        "scale_factor": f"{m[1]}({word})/{m[3]}", "offset": offset * scale,
        "pga_declared": stated, "event": hdr[0].split(None, 2)[-1].strip(),
        "magnitude": hdr[4].split()[-1] if len(hdr[4].split()) > 1 else "",
        "record_time": hdr[9].split(None, 2)[-1].strip(),
        "description": f"{hdr[5].split()[-1]} {direction}, origin {hdr[0].split(None, 2)[-1]}"
                       " (JST)",
        "header": hdr,
    }
    if kik:
        meta["sensor"] = _KIKNET_SENSORS[direction]
    return gal * f, step, meta
