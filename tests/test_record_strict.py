"""Records are read exactly, or refused (issue 16, section 2).

Every unit word of a header or a column name is understood or refused by name; a unit in
the file must agree with ``units=`` (and ``--units``); a declared count must equal the
values read; a file cut inside its last value is refused; whitespace-only lines are blank
lines; implausible inputs (PGA > 5 g, dt > 0.1 s, a 60 m block, a 2 m sine) warn.
"""

from __future__ import annotations

import math
import re
import warnings
from pathlib import Path

import numpy as np
import pytest
from cli_helpers import run_main
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rocking
from rocking import PlausibilityWarning
from rocking.errors import RecordError
from rocking.motions import HanningSine, Record, Sine
from rocking.motions.io import read_record, write_csv
from rocking.units import G

SHARED = Path("/work/shared/data/records")

TIME_WORDS = {  # word -> seconds
    "s": 1.0, "S": 1.0, "sec": 1.0, "SEC": 1.0, "secs": 1.0, "second": 1.0, "seconds": 1.0,
    "Seconds": 1.0,
    "ms": 1e-3, "MS": 1e-3, "msec": 1e-3, "MSEC": 1e-3, "msecs": 1e-3, "millisecond": 1e-3,
    "milliseconds": 1e-3, "Milliseconds": 1e-3,
    "us": 1e-6, "US": 1e-6, "\u00b5s": 1e-6, "\u03bcs": 1e-6, "usec": 1e-6,
    "microsecond": 1e-6, "microseconds": 1e-6,
}
ACC_WORDS = {  # word -> (m/s^2 per unit, the canonical name to pass as units=)
    "g": (G, "g"), "G": (G, "g"),
    "gal": (0.01, "gal"), "Gal": (0.01, "gal"), "GALS": (0.01, "gal"),
    "cm/s^2": (0.01, "cm/s^2"), "cm/s2": (0.01, "cm/s^2"), "cm/sec^2": (0.01, "cm/s^2"),
    "CM/SEC/SEC": (0.01, "cm/s^2"), "cm/s/s": (0.01, "cm/s^2"), "cm/sec2": (0.01, "cm/s^2"),
    "cm/s\u00b2": (0.01, "cm/s^2"),
    "m/s^2": (1.0, "m/s^2"), "m/s2": (1.0, "m/s^2"), "M/S^2": (1.0, "m/s^2"),
    "m/sec^2": (1.0, "m/s^2"), "m s^-2": (1.0, "m/s^2"), "m/s**2": (1.0, "m/s^2"),
    "mps2": (1.0, "m/s^2"),
    "mm/s^2": (1e-3, "mm/s^2"), "mm/s2": (1e-3, "mm/s^2"), "mm/sec^2": (1e-3, "mm/s^2"),
}
OTHER_UNITS = {"g": "m/s^2", "gal": "g", "cm/s^2": "g", "m/s^2": "g", "mm/s^2": "cm/s^2"}
FACTOR = {"g": G, "gal": 0.01, "cm/s^2": 0.01, "m/s^2": 1.0, "mm/s^2": 1e-3}


def write(tmp_path: Path, name: str, text: str) -> Path:
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def at2_text(values_g, dt_text: str = ".0100 SEC", units_line: str = "G") -> str:
    """A PEER .AT2 file of ``values_g`` in Fortran E15.7, five to a line."""
    head = ("PEER NGA STRONG MOTION DATABASE RECORD\n"
            "Somewhere, 1/1/2000, Station, 90\n"
            f"ACCELERATION TIME SERIES IN UNITS OF {units_line}\n"
            f"NPTS= {len(values_g):6d}, DT= {dt_text},   4 POLE @    20.00000 HZ\n")
    fields = [fortran_e(v) for v in values_g]
    rows = ["".join(fields[i:i + 5]) for i in range(0, len(fields), 5)]
    return head + "\n".join(rows) + "\n"


def fortran_e(x: float) -> str:
    """``x`` as Fortran E15.7 (``   -.1234567E-02``)."""
    if x == 0.0:
        body = ".0000000E+00"
    else:
        mant, exp = f"{abs(x):.6E}".split("E")
        digits = mant.replace(".", "")
        body = f".{digits}E{int(exp) + 1:+03d}"
    return f"{'-' if x < 0 else '':>1}{body}".rjust(15)


# --------------------------------------------------------------------- time-unit words
class TestTimeUnits:
    @pytest.mark.parametrize("word, factor", TIME_WORDS.items())
    def test_dt_header_word(self, tmp_path, word, factor):
        value = 0.01 / factor  # 0.01 s in that unit
        p = write(tmp_path, "one.txt", f"# dt = {value:g} {word}\n0.1\n0.2\n-0.3\n")
        acc, dt, meta = read_record(p)
        assert dt == pytest.approx(0.01, rel=1e-12)
        assert meta["npts"] == 3

    @pytest.mark.parametrize("form", ["# dt = {v} {w}", "# dt: {v}{w}", "# dt ({w}) = {v}",
                                      "# dt [{w}] = {v}", "# dt_{w} = {v}", "# dt = {v} ({w})",
                                      "# DT = {v} {w}, npts = 3"])
    def test_dt_header_forms(self, tmp_path, form):
        p = write(tmp_path, "f.txt", form.format(v=10, w="msec") + "\n1\n2\n3\n")
        assert read_record(p)[1] == pytest.approx(0.01, rel=1e-12)

    def test_dt_without_unit_is_seconds(self, tmp_path):
        assert read_record(write(tmp_path, "b.txt", "# dt = 0.02\n1\n2\n"))[1] == 0.02

    @pytest.mark.parametrize("word", ["fortnights", "days", "hz", "mm", "approx"])
    def test_unknown_dt_word_refused(self, tmp_path, word):
        p = write(tmp_path, "u.txt", f"# dt = 10 {word}\n1\n2\n3\n")
        with pytest.raises(RecordError, match=rf"u\.txt, line 1: unknown time unit "
                                              rf"'{word}'"):
            read_record(p)

    @pytest.mark.parametrize("word, factor", [("SEC", 1.0), ("S", 1.0), ("MSEC", 1e-3),
                                              ("ms", 1e-3), ("USEC", 1e-6)])
    def test_at2_dt_word(self, tmp_path, word, factor):
        p = write(tmp_path, "r.AT2", at2_text([0.1, -0.2, 0.3], f"{0.005 / factor:g} {word}"))
        assert read_record(p)[1] == pytest.approx(0.005, rel=1e-12)

    def test_at2_unknown_dt_word_refused(self, tmp_path):
        p = write(tmp_path, "r.AT2", at2_text([0.1, -0.2, 0.3], "5 JIFFIES"))
        with pytest.raises(RecordError, match=r"r\.AT2, line 4: unknown time unit 'JIFFIES'"):
            read_record(p)

    @pytest.mark.parametrize("name, factor", [("time_ms", 1e-3), ("time (msec)", 1e-3),
                                              ("t [us]", 1e-6), ("Time (s)", 1.0),
                                              ("time_seconds", 1.0), ("t_sec", 1.0)])
    def test_time_column_unit(self, tmp_path, name, factor):
        step = 0.02 / factor  # 0.02 s in that unit
        rows = "\n".join(f"{k * step!r},{a}" for k, a in enumerate([0.1, 0.2, -0.1, 0.0]))
        p = write(tmp_path, "t.csv", f"{name},acc\n{rows}\n")
        acc, dt, meta = read_record(p)
        assert dt == pytest.approx(0.02, rel=1e-9)
        np.testing.assert_allclose(acc, np.array([0.1, 0.2, -0.1, 0.0]) * G)

    def test_time_column_unit_and_dt_agree_after_conversion(self, tmp_path):
        p = write(tmp_path, "t.csv", "# dt = 20 ms\ntime_ms,acc\n0,1\n20,2\n40,3\n")
        assert read_record(p, dt=0.02)[1] == pytest.approx(0.02)
        with pytest.raises(RecordError, match="dt=0.01 s was passed"):
            read_record(p, dt=0.01)

    def test_time_unit_on_the_acceleration_column_refused(self, tmp_path):
        p = write(tmp_path, "x.csv", "t,acc_ms\n0,1\n0.01,2\n")
        with pytest.raises(RecordError, match=r"'ms' is not an acceleration unit"):
            read_record(p)


# ------------------------------------------------------------- acceleration-unit words
class TestAccelerationUnits:
    @pytest.mark.parametrize("word, f_name", ACC_WORDS.items())
    @pytest.mark.parametrize("style", ["comment", "paren", "bracket", "suffix", "in"])
    def test_unit_word_read_and_checked(self, tmp_path, word, f_name, style):
        factor, name = f_name
        header = {"comment": f"# units: {word}\nt,acc",
                  "paren": f"time,Acceleration ({word})",
                  "bracket": f"t [s],acc [{word}]",
                  "suffix": f"time_s,acc_{word}",
                  "in": f"time,acceleration in {word}"}[style]
        p = write(tmp_path, "a.csv", f"{header}\n0,1.5\n0.01,-2.5\n0.02,0.5\n")
        acc, dt, meta = read_record(p, units=name)
        np.testing.assert_allclose(acc, np.array([1.5, -2.5, 0.5]) * factor, rtol=1e-15)
        assert meta["units"] == name
        other = OTHER_UNITS[name]
        with pytest.raises(RecordError) as exc:  # the file's unit against the one passed
            read_record(p, units=other)
        msg = str(exc.value)
        assert word in msg and f"units={other!r}" in msg and "\n" not in msg

    def test_default_units_refuse_a_file_in_gal(self, tmp_path):
        p = write(tmp_path, "a.csv", "Time (s),Acceleration (cm/s^2)\n0,1\n0.01,2\n")
        with pytest.raises(RecordError, match=r"'cm/s\^2' but units='g'"):
            Record.from_file(p)
        np.testing.assert_allclose(Record.from_file(p, units="gal").acc, [0.01, 0.02])

    def test_whitespace_columns_with_spaced_names(self, tmp_path):
        p = write(tmp_path, "w.txt", "Time (s)    Acceleration (m/s^2)\n0 1\n0.01 2\n")
        np.testing.assert_allclose(read_record(p, units="m/s^2")[0], [1.0, 2.0])
        with pytest.raises(RecordError, match=r"'m/s\^2' but units='g'"):
            read_record(p)

    def test_comment_line_naming_the_columns(self, tmp_path):
        p = write(tmp_path, "c.csv", "# time_s, acc_gal\n0, 1\n0.01, 2\n")
        with pytest.raises(RecordError, match=r"'gal' but units='g'"):
            read_record(p)
        np.testing.assert_allclose(read_record(p, units="gal")[0], [0.01, 0.02])

    def test_one_column_name_with_unit(self, tmp_path):
        p = write(tmp_path, "o.txt", "# dt = 0.01 s\nground acceleration NS (gal)\n1\n2\n")
        np.testing.assert_allclose(read_record(p, units="gal")[0], [0.01, 0.02])
        with pytest.raises(RecordError, match=r"'gal' but units='m/s\^2'"):
            read_record(p, units="m/s^2")

    def test_names_without_units_keep_the_units_passed(self, tmp_path):
        p = write(tmp_path, "n.csv", "time,acc_NS\n0,1\n0.01,2\n")
        np.testing.assert_allclose(read_record(p, units="m/s^2")[0], [1.0, 2.0])

    @pytest.mark.parametrize("header, word", [
        ("t,acc_furlong", "furlong"), ("time,Acceleration (ft/s^2)", "ft/s^2"),
        ("t [fortnight],acc", "fortnight"), ("time,acc (kine)", "kine"),
        ("# units: m/s\nt,acc", "m/s"), ("# units: ms^-2\nt,acc", "ms^-2"),
    ])
    def test_unknown_unit_word_refused(self, tmp_path, header, word):
        p = write(tmp_path, "u.csv", f"{header}\n0,1\n0.01,2\n")
        with pytest.raises(RecordError) as exc:
            read_record(p)
        assert f"'{word}'" in str(exc.value) and "u.csv" in str(exc.value)

    def test_file_states_two_different_units(self, tmp_path):
        p = write(tmp_path, "t.csv", "# units: g\nt,acc (gal)\n0,1\n0.01,2\n")
        with pytest.raises(RecordError, match="units"):
            read_record(p, units="g")

    def test_swapped_column_names_refused(self, tmp_path):
        p = write(tmp_path, "s.csv", "acc,time\n0,1\n0.01,2\n")
        with pytest.raises(RecordError, match=r"column 1 is named 'acc'"):
            read_record(p)

    @pytest.mark.parametrize("line3, name, factor", [("G", "g", G),
                                                      ("CM/SEC/SEC", "cm/s^2", 0.01),
                                                      ("GAL", "gal", 0.01)])
    def test_at2_units_line(self, tmp_path, line3, name, factor):
        p = write(tmp_path, "u.AT2", at2_text([0.1, -0.2, 0.3], units_line=line3))
        np.testing.assert_allclose(read_record(p, units=name)[0],
                                   np.array([0.1, -0.2, 0.3]) * factor, rtol=1e-15)
        other = OTHER_UNITS[name]
        with pytest.raises(RecordError, match=rf"in {re.escape(name)}.*units="
                                              rf"{re.escape(repr(other))}"):
            read_record(p, units=other)

    def test_at2_unknown_units_line(self, tmp_path):
        p = write(tmp_path, "u.AT2", at2_text([0.1, -0.2, 0.3], units_line="FT/S/S"))
        with pytest.raises(RecordError, match=r"line 3: unknown acceleration unit 'FT/S/S'"):
            read_record(p)


# -------------------------------------------------------------------- declared counts
class TestCounts:
    def test_write_csv_cut_at_a_line_is_refused(self, tmp_path):
        rec = Record(np.sin(np.arange(2001) * 0.01), 0.01, name="whole")
        p = write_csv(rec, tmp_path / "whole.csv")
        lines = p.read_text().splitlines(keepends=True)
        assert len(read_record(p, units="m/s^2")[0]) == 2001
        cut = write(tmp_path, "cut.csv", "".join(lines[:1000]))
        with pytest.raises(RecordError, match=r"cut\.csv, line \d+: .*npts = 2001.*cut"):
            read_record(cut, units="m/s^2")

    def test_write_csv_cut_inside_its_last_line_is_refused(self, tmp_path):
        rec = Record(np.cos(np.arange(300) * 0.05), 0.01)
        p = write_csv(rec, tmp_path / "w.csv")
        text = p.read_text()
        cut = write(tmp_path, "cut.csv", text.rstrip("\n")[:-3])
        with pytest.raises(RecordError, match=r"cut\.csv.*looks cut"):
            read_record(cut, units="m/s^2")

    def test_write_csv_reads_back_whatever_the_name(self, tmp_path):
        rec = Record(np.sin(np.arange(50) * 0.3), 0.02, name="shake dt = 5 s, npts: many")
        acc, dt, meta = read_record(write_csv(rec, tmp_path / "n.csv"), units="m/s^2")
        np.testing.assert_array_equal(acc, rec.acc)
        assert dt == rec.dt and meta["npts"] == 50

    def test_npts_agrees(self, tmp_path):
        p = write(tmp_path, "n.txt", "# dt = 0.01 s, npts = 3\n1\n2\n3\n")
        assert read_record(p)[2]["npts"] == 3
        q = write(tmp_path, "m.txt", "# dt = 0.01 s\n# npts: 4\n1\n2\n3\n")
        with pytest.raises(RecordError, match=r"m\.txt, line 2: .*npts = 4 but 3"):
            read_record(q)
        r = write(tmp_path, "x.txt", "# dt = 0.01 s\n# npts = 2\n1\n2\n3\n")
        with pytest.raises(RecordError, match=r"npts = 2 but 3"):
            read_record(r)
        s = write(tmp_path, "y.txt", "# dt = 0.01 s\n# npts = many\n1\n2\n")
        with pytest.raises(RecordError, match=r"npts must be a whole number, got 'many'"):
            read_record(s)

    @pytest.mark.parametrize("name", ["RSN982_NORTHR_JEN292.AT2", "Rinaldi228.AT2"])
    def test_at2_cut_at_a_line_is_refused(self, tmp_path, name):
        lines = (SHARED / name).read_text().splitlines(keepends=True)
        p = write(tmp_path, name, "".join(lines[:200]))
        with pytest.raises(RecordError, match=r"NPTS=\d+ but only \d+ values.*cut"):
            read_record(p)


class TestCutLastField:
    @pytest.mark.parametrize("name", ["RSN982_NORTHR_JEN292.AT2", "RSN948_NORTHR_CAM009.AT2",
                                      "Rinaldi228.AT2", "RSN1158_KOCAELI_DZC-UP.AT2"])
    @pytest.mark.parametrize("k", [1, 2, 3, 4, 5, 8, 11])
    def test_real_at2_cut_inside_its_last_value(self, tmp_path, name, k):
        whole = (SHARED / name).read_text()
        body = whole.rstrip()
        last = body.split()[-1]
        assert k < len(last)
        p = write(tmp_path, name, body[:-k])
        with pytest.raises(RecordError, match=rf"{re.escape(name)}, line \d+: .*cut"):
            read_record(p)
        # the same file, not cut (with or without its final line break), reads
        assert len(read_record(write(tmp_path, "whole.AT2", body))[0]) == len(
            read_record(SHARED / name)[0])

    def test_the_issue_example_lost_exponent(self, tmp_path):
        vals = [0.1096612e-3, -0.1094953e-3, 0.2e-3, -0.3e-3, 0.4e-3, -0.1094953e-3]
        text = at2_text(vals).rstrip()
        assert text.endswith("-.1094953E-03")
        p = write(tmp_path, "c.AT2", text[:-1])  # '-.1094953E-0': a valid-looking number
        with pytest.raises(RecordError, match=r"'-\.1094953E-0'.*cut"):
            read_record(p)

    def test_free_format_at2_is_not_refused(self, tmp_path):
        p = write(tmp_path, "free.AT2", at2_text([0.1]).split("NPTS")[0]
                  + "NPTS=  4, DT= .01 SEC\n 0.1 -0.25 0.125\n 0.5")
        np.testing.assert_allclose(read_record(p)[0] / G, [0.1, -0.25, 0.125, 0.5])

    def test_fixed_e_columns_cut_inside_last_value(self, tmp_path):
        rows = "".join(f"{0.01 * k:.3f},{math.sin(k) * 1e-3:.6e}\n" for k in range(40))
        p = write(tmp_path, "e.csv", rows)
        assert len(read_record(p)[0]) == 40
        q = write(tmp_path, "cut.csv", rows.rstrip("\n")[:-1])
        with pytest.raises(RecordError, match=r"cut\.csv, line 40: .*looks cut"):
            read_record(q)


# ---------------------------------------------------------------- whitespace-only lines
class TestWhitespaceLines:
    @pytest.mark.parametrize("blank", ["   ", "\t", " \t  "])
    @pytest.mark.parametrize("sep", [",", ";", " "])
    def test_whitespace_line_in_data(self, tmp_path, blank, sep):
        text = f"t{sep}acc\n0{sep}1\n0.01{sep}2\n{blank}\n0.02{sep}3\n{blank}\n"
        acc, dt, meta = read_record(write(tmp_path, "w.csv", text), units="m/s^2")
        np.testing.assert_allclose(acc, [1.0, 2.0, 3.0])
        assert dt == pytest.approx(0.01) and meta["npts"] == 3

    def test_whitespace_line_in_one_column_and_at2(self, tmp_path):
        acc = read_record(write(tmp_path, "o.txt", "# dt = 0.01 s\n1\n   \n2\n"), units="g")[0]
        np.testing.assert_allclose(acc, [G, 2 * G])
        head, _, body = at2_text([0.1, 0.2, 0.3, 0.4, 0.5, 0.6]).partition("HZ\n")
        text = head + "HZ\n  \t \n" + body.replace("\n", "\n    \n")
        assert read_record(write(tmp_path, "w.AT2", text))[2]["npts"] == 6


# ---------------------------------------------------------------- plausibility warnings
def no_warning(fn, *args, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return fn(*args, **kw)


class TestPlausibility:
    def test_warning_class(self):
        assert issubclass(PlausibilityWarning, UserWarning)
        assert rocking  # the package imports

    def test_record_pga_above_5g(self, tmp_path):
        with pytest.warns(PlausibilityWarning, match=r"PGA 6 g is above 5 g") as rec:
            Record(np.array([0.0, 6.0 * G, -1.0]), 0.01)
        assert len(str(rec[0].message).splitlines()) == 1
        assert Path(rec[0].filename).resolve() == Path(__file__).resolve()  # the caller's
        no_warning(Record, np.array([0.0, 4.99 * G, -5.0 * G]), 0.01)
        p = write(tmp_path, "gal.csv", "t,acc\n0,0\n0.01,300\n0.02,-120\n")
        with pytest.warns(PlausibilityWarning, match=r"'gal'.*PGA 30\.6 g"):
            Record.from_file(p, units="m/s^2")  # a file in gal read as m/s^2
        no_warning(Record.from_file, p, units="gal")

    def test_record_dt_above_0_1_s(self, tmp_path):
        with pytest.warns(PlausibilityWarning, match=r"time step 0\.5 s is above 0\.1 s"):
            Record([0.0, 1.0, 0.0], 0.5)
        no_warning(Record, [0.0, 1.0, 0.0], 0.1)
        p = write(tmp_path, "ms.txt", "# dt = 10\n1\n2\n3\n")  # 10 ms written without unit
        with pytest.warns(PlausibilityWarning, match="time step 10 s"):
            Record.from_file(p, units="m/s^2")

    def test_block_above_50_m(self):
        with pytest.warns(PlausibilityWarning, match=r"width 60 m is above 50 m"):
            rocking.Block.rectangular(60.0, 50.0)
        with pytest.warns(PlausibilityWarning, match=r"height 60 m is above 50 m"):
            rocking.Block.rectangular(10.0, 60.0)
        no_warning(rocking.Block.rectangular, 20.0, 50.0)

    def test_sine_amplitude_above_1_m(self):
        with pytest.warns(PlausibilityWarning, match=r"amplitude 5 m is above 1 m"):
            Sine(5.0, 5.0, 2.0)
        with pytest.warns(PlausibilityWarning, match=r"amplitude 2 m is above 1 m"):
            HanningSine(1.0, 2.0, 2.0)
        no_warning(Sine, 0.2, 1.0, 2.0)     # 1 m at 0.2 Hz: 1.58 m/s^2
        no_warning(Sine, 5.0, 0.005, 2.0)

    def test_scaled_records_do_not_warn(self):
        rec = no_warning(Record, np.array([0.0, 4.0 * G, -1.0]), 0.01)
        no_warning(rec.scaled, 3.0)  # a load factor (IDA) is not a unit mistake


# ------------------------------------------------------------- round trip (hypothesis)
def _num(x: float) -> str:
    return repr(float(x))


def _layout_text(layout: str, vals: np.ndarray, dt: float, unit: str):
    """``(file name, text, units to pass, expected samples in m/s^2, dt in s)`` of a valid
    record ``vals`` (in ``unit``) with time step ``dt`` written in ``layout``."""
    n = len(vals)
    f = FACTOR[unit]
    if layout == "at2":
        fields = [fortran_e(v * f / G) for v in vals]  # an AT2 file is in g
        text = at2_text([0.0] * n, f"{dt:.6g} SEC").split("\n")[:4]
        rows = ["".join(fields[i:i + 5]) for i in range(0, n, 5)]
        expected = np.array([float(x) for x in fields]) * G
        return "r.AT2", "\n".join(text + rows) + "\n", "g", expected, float(f"{dt:.6g}")
    expected = np.array([float(_num(v)) for v in vals]) * f
    col = [_num(v) for v in vals]
    t_s = [_num(k * dt) for k in range(n)]
    if layout == "one-column":
        ms = float(_num(dt * 1000.0))
        text = f"# rocking test\n# dt = {_num(ms)} msec\n# npts = {n}\nacc ({unit})\n"
        return "o.txt", text + "\n".join(col) + "\n", unit, expected, ms * 1e-3
    headers = {
        "csv-plain": ("t,acc", ",", t_s, None),
        "csv-units-comment": (f"# units: {unit}\n# npts = {n}\ntime,acc", ",", t_s, None),
        "csv-parens": (f"Time (s),Acceleration ({unit})", ",", t_s, None),
        "csv-suffix-ms": (f"time_ms,acc_{unit}", ",", None, 1e3),
        "csv-brackets-semicolon": (f"t [sec];acc [{unit}]", ";", t_s, None),
        "csv-comment-names": (f"# time_s, acc_{unit}", ", ", t_s, None),
        "two-column": (f"# dt = {_num(dt)} s\n", " ", t_s, None),
        "two-column-names": (f"Time (seconds)   Acceleration ({unit})", "   ", t_s, None),
    }
    header, sep, times, scale = headers[layout]
    if times is None:
        times = [_num(k * dt * scale) for k in range(n)]
    rows = "\n".join(f"{a}{sep}{b}" for a, b in zip(times, col, strict=True))
    pass_units = "m/s^2" if layout in ("csv-plain", "two-column") else unit
    if pass_units != unit:
        expected = np.array([float(c) for c in col])
    return "c.csv", f"{header}\n{rows}\n", pass_units, expected, dt


LAYOUTS = ["at2", "one-column", "csv-plain", "csv-units-comment", "csv-parens",
           "csv-suffix-ms", "csv-brackets-semicolon", "csv-comment-names", "two-column",
           "two-column-names"]


@settings(max_examples=200, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(layout=st.sampled_from(LAYOUTS),
       unit=st.sampled_from(sorted(FACTOR)),
       n=st.integers(2, 40),
       dt=st.floats(1e-4, 0.1),
       data=st.data())
def test_round_trip_every_layout(tmp_path, layout, unit, n, dt, data):
    """A random valid record, written in each supported layout, reads back the same
    samples (to the printed precision) and the same dt."""
    top = 4.0 * G / FACTOR[unit]  # within 4 g: no plausibility warning
    vals = np.array(data.draw(st.lists(st.floats(-top, top, allow_subnormal=False),
                                       min_size=n, max_size=n)))
    name, text, units, expected, step = _layout_text(layout, vals, dt, unit)
    p = write(tmp_path, name, text)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        acc, got_dt, meta = read_record(p, units=units)
    assert meta["npts"] == n
    assert got_dt == pytest.approx(step, rel=1e-9)
    np.testing.assert_allclose(acc, expected, rtol=1e-14, atol=0.0)


# ------------------------------------------------------------------------------- CLI


def assert_one_line_error(code, err, *words):
    assert code == 2, err
    lines = err.strip("\n").splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    for w in words:
        assert w.lower() in lines[0].lower(), (w, err)


CLI_CASES = [
    ("ms.csv", "# dt = 10 fortnights\n1\n2\n3\n", "m/s^2", ["fortnights"]),
    ("gal.csv", "Time (s),Acceleration (cm/s^2)\n0,1\n0.01,2\n", "m/s^2",
     ["cm/s^2", "m/s^2"]),
    ("g.csv", "time,acc_g\n0,1\n0.01,2\n", "gal", ["'g'", "gal"]),
    ("n.csv", "# npts = 5\nt,acc\n0,1\n0.01,2\n0.02,3\n", "m/s^2", ["npts = 5"]),
    ("f.csv", "t,acc_furlong\n0,1\n0.01,2\n", "m/s^2", ["furlong"]),
    ("in_g.AT2", None, "m/s^2", ["in g", "m/s^2"]),
    ("cut.AT2", "cut", "g", ["cut"]),
]


def _cli_file(tmp_path, name, text):
    if text is None:
        text = at2_text([0.1, -0.2, 0.3, 0.1, 0.0, -0.1])
    elif text == "cut":
        text = at2_text([0.1, -0.2, 0.3, 0.1, 0.0, -0.1]).rstrip()[:-2]
    return write(tmp_path, name, text)


@pytest.mark.parametrize("name, text, units, words", CLI_CASES)
def test_cli_simulate_record_error_is_one_line(capsys, tmp_path, name, text, units, words):
    p = _cli_file(tmp_path, name, text)
    code, out, err = run_main(capsys, "simulate", "--width", "0.2", "--height", "1",
                              "--record", p, "--units", units, "--out", tmp_path / "out")
    assert_one_line_error(code, err, name, *words)
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("cmd", ["show", "spectrum"])
@pytest.mark.parametrize("name, text, units, words", CLI_CASES)
def test_cli_motion_record_error_is_one_line(capsys, tmp_path, cmd, name, text, units, words):
    p = _cli_file(tmp_path, name, text)
    code, out, err = run_main(capsys, "motion", cmd, p, "--units", units, "--no-plot")
    assert_one_line_error(code, err, name, *words)


def test_cli_reads_units_from_a_matching_header(capsys, tmp_path):
    p = write(tmp_path, "gal.csv", "Time (s),Acceleration (cm/s^2)\n0,0\n0.01,100\n0.02,0\n")
    code, out, err = run_main(capsys, "motion", "show", p, "--units", "gal", "--no-plot")
    assert code in (0, None), err
    assert re.search(r"PGA 1 m/s\^2", out), out
