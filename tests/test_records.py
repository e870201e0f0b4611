"""Sampled accelerograms: the Record motion, file reading/writing and the shipped PEER data."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from rocking.errors import ParameterError, RecordError, UnitError
from rocking.motions import Record, Sine, load_builtin, sample
from rocking.motions import _kernel as K
from rocking.motions.io import builtin_records, read_record, write_csv
from rocking.units import G

# from the README of the PEER files: NPTS and DT (s)
PEER = {
    "RSN126_GAZLI_GAZ000": (2048, 0.0066),
    "RSN183_IMPVALL.H_H-E08140": (7554, 0.005),
    "RSN948_NORTHR_CAM009": (3499, 0.01),
    "RSN982_NORTHR_JEN292": (5720, 0.005),
}


def write(tmp_path: Path, name: str, text: str) -> Path:
    p = tmp_path / name
    p.write_text(text)
    return p


# ------------------------------------------------------------------------------ Record
class TestRecord:
    def test_linear_between_samples_and_zero_after_the_end(self):
        r = Record([0.0, 1.0, -1.0, 2.0], dt=0.1)
        assert r.duration == pytest.approx(0.3)
        assert r.acceleration(0.05) == pytest.approx(0.5)
        assert r.acceleration(0.125) == pytest.approx(0.5)  # 1/4 of the way from 1 to -1
        assert r.acceleration(0.25) == pytest.approx(0.5)
        np.testing.assert_allclose(r.acceleration(r.t), r.acc, atol=1e-12)
        assert r.acceleration(0.3) == pytest.approx(2.0)  # the last sample holds at the end
        assert r.acceleration(0.3 + 1e-6) == 0.0
        assert r.acceleration(5.0) == 0.0
        assert r.acceleration(-0.01) == 0.0

    def test_interpolation_matches_numpy(self):
        rng = np.random.default_rng(1)
        acc = rng.normal(size=500)
        r = Record(acc, dt=0.02)
        t = rng.uniform(0.0, r.duration, 2000)
        np.testing.assert_allclose(r.acceleration(t), np.interp(t, r.t, acc), atol=1e-12)

    def test_scaled_and_negated(self):
        r = Record([0.0, 1.0, -3.0, 2.0], dt=0.01, name="x")
        t = np.linspace(0.0, 0.03, 31)
        s = r.scaled(2.5)
        np.testing.assert_allclose(s.acceleration(t), 2.5 * r.acceleration(t))
        np.testing.assert_allclose((-r).acceleration(t), -r.acceleration(t))
        assert s.pga == pytest.approx(7.5)
        assert (-r).pga == pytest.approx(3.0)
        np.testing.assert_allclose(s.values, 2.5 * r.acc)
        np.testing.assert_array_equal(s.acc, r.acc)  # raw samples untouched
        assert s.name == "x" and r.scale == 1.0

    def test_samples_are_copied_and_read_only(self):
        a = np.array([0.0, 1.0, 2.0])
        r = Record(a, dt=0.1)
        a[1] = 99.0
        assert r.acc[1] == 1.0
        with pytest.raises(ValueError):
            r.acc[0] = 5.0

    def test_breakpoints_are_the_sample_times(self):
        r = Record(np.arange(5.0), dt=0.1)
        kind, prm, smp = r.spec()
        assert K.next_breakpoint(kind, prm, smp, -1.0) == 0.0
        assert K.next_breakpoint(kind, prm, smp, 0.0) == pytest.approx(0.1)
        assert K.next_breakpoint(kind, prm, smp, 0.15) == pytest.approx(0.2)
        assert K.next_breakpoint(kind, prm, smp, 0.4) == math.inf

    @pytest.mark.parametrize(
        "acc, words",
        [
            ([0.0, math.nan, 1.0], "NaN"),
            ([0.0, math.inf], "non-finite"),
            ([1.0], "at least 2 samples"),
            ([], "at least 2 samples"),
            ([[0.0, 1.0], [2.0, 3.0]], "1-D"),
            (["a", "b"], "numbers"),
        ],
    )
    def test_validation(self, acc, words):
        with pytest.raises(RecordError, match=words):
            Record(acc, dt=0.01)

    def test_dt_must_be_positive(self):
        with pytest.raises(ParameterError, match="dt"):
            Record([0.0, 1.0], dt=0.0)

    def test_sample_of_sine_keeps_amplitude(self):
        m = Sine(5.0, 0.005, 2.0)
        rec = sample(m, 0.001)
        assert rec.pga == pytest.approx(m.acc_amplitude, rel=1e-3)


# --------------------------------------------------------------------------- PEER AT2
class TestPeerFiles:
    def test_builtin_list(self):
        assert builtin_records() == sorted(PEER)

    @pytest.mark.parametrize("name", sorted(PEER))
    def test_npts_dt_and_pga(self, records_dir, name):
        npts, dt = PEER[name]
        rec = Record.from_file(records_dir / f"{name}.AT2")
        assert len(rec) == npts
        assert rec.dt == pytest.approx(dt, rel=1e-12)
        assert rec.name == name
        assert rec.meta["format"] == "AT2" and rec.meta["npts"] == npts
        # real strong motion: PGA between 0.05 g and 1.5 g, and not a constant trace
        assert 0.05 * G < rec.pga < 1.5 * G
        assert np.std(rec.acc) > 0.005 * G
        assert rec.duration == pytest.approx((npts - 1) * dt)

    def test_values_are_g_times_standard_gravity(self, records_dir):
        rec = Record.from_file(records_dir / "RSN126_GAZLI_GAZ000.AT2")
        # the first and last data lines of the file, in g
        first = [.1717907E-01, .1723899E-01, .1729868E-01, .1735789E-01, .1741676E-01]
        last = [.2690760E-01, .2684498E-01, .2675242E-01]  # a short last line
        np.testing.assert_allclose(rec.acc[:5], np.array(first) * 9.80665, rtol=1e-12)
        np.testing.assert_allclose(rec.acc[-3:], np.array(last) * 9.80665, rtol=1e-12)

    def test_header_with_filter_text_and_description(self, records_dir):
        rec = Record.from_file(records_dir / "RSN982_NORTHR_JEN292.AT2")  # "4 POLE @ 20 HZ ..."
        assert len(rec) == 5720
        assert "Northridge-01" in rec.meta["description"]
        assert "Jensen" in rec.meta["station"]
        assert rec.meta["event"] == "Northridge-01"
        assert rec.meta["t_start"] == 0.0

    def test_load_builtin_by_name_prefix_and_extension(self, records_dir):
        a = load_builtin("RSN982_NORTHR_JEN292")
        b = load_builtin("rsn982")
        c = load_builtin("RSN982_NORTHR_JEN292.AT2")
        np.testing.assert_array_equal(a.acc, b.acc)
        np.testing.assert_array_equal(a.acc, c.acc)
        assert a.dt == 0.005 and a.name == "RSN982_NORTHR_JEN292"
        ref = Record.from_file(records_dir / "RSN982_NORTHR_JEN292.AT2")
        np.testing.assert_array_equal(a.acc, ref.acc)

    def test_load_builtin_unknown(self):
        with pytest.raises(RecordError, match="unknown built-in record 'RSN1'.*RSN126"):
            load_builtin("RSN1")
        with pytest.raises(RecordError, match="unknown built-in record ''"):
            load_builtin("")

    def test_at2_is_always_in_g(self, records_dir):
        with pytest.raises(RecordError, match=r"RSN126_GAZLI_GAZ000\.AT2.*in g"):
            Record.from_file(records_dir / "RSN126_GAZLI_GAZ000.AT2", units="m/s^2")
        assert len(Record.from_file(records_dir / "RSN126_GAZLI_GAZ000.AT2", units="G")) == 2048

    def test_at2_dt_must_agree(self, records_dir):
        Record.from_file(records_dir / "RSN948_NORTHR_CAM009.AT2", dt=0.01)
        with pytest.raises(RecordError, match="RSN948_NORTHR_CAM009.*DT=0.01"):
            Record.from_file(records_dir / "RSN948_NORTHR_CAM009.AT2", dt=0.02)


AT2_HEAD = ("PEER NGA STRONG MOTION DATABASE RECORD\n"
            "Somewhere, 1/1/2000, Station, 90\n"
            "ACCELERATION TIME SERIES IN UNITS OF G\n")


class TestAt2Variants:
    def test_alternative_header_and_fortran_numbers(self, tmp_path):
        p = write(tmp_path, "alt.AT2", AT2_HEAD + "    7    0.0100    NPTS, DT\n"
                  "  .1E-01  -.5E-03  1.0  -.25D+00  2.5E-1\n  0.0  -.1\n")
        acc, dt, meta = read_record(p)
        assert dt == 0.01 and meta["npts"] == 7
        np.testing.assert_allclose(acc / G, [0.01, -0.0005, 1.0, -0.25, 0.25, 0.0, -0.1])
        assert meta["station"] == "Station"

    def test_detected_by_content_without_extension(self, tmp_path):
        p = write(tmp_path, "rec.txt", AT2_HEAD + "NPTS=  3, DT= .005 SEC\n .1 .2 .3\n")
        acc, dt, meta = read_record(p)
        assert meta["format"] == "AT2" and dt == 0.005
        np.testing.assert_allclose(acc, np.array([0.1, 0.2, 0.3]) * G)

    @pytest.mark.parametrize(
        "body, words",
        [
            ("NPTS=  4, DT= .01 SEC\n .1 .2 .3\n", r"NPTS=4 .* only 3 values"),
            ("NPTS=  2, DT= .01 SEC\n .1 .2\n .3\n", r"line 6: 1 value\(s\) beyond NPTS=2"),
            ("NPTS=  3, DT= .01 SEC\n .1 .2\n abc\n", r"line 6: non-numeric value 'abc'"),
            ("NPTS=  3, DT= .01 SEC\n .1 NaN .3\n", r"line 5: NaN or infinite"),
            ("NPTS=  3, DT= .01 SEC\n .1 .2\n inf\n", r"line 6: NaN or infinite"),
            ("NPTS=  3, DT= .01 SEC\n", r"no data"),
            ("NPTS=  1, DT= .01 SEC\n .1\n", r"line 4: .*at least 2 samples"),
            ("NPTS=  3, DT= 0 SEC\n .1 .2 .3\n", r"line 4: DT must be > 0"),
            ("3 points every .01 s\n .1 .2 .3\n", r"line 4: not a valid PEER \.AT2 header"),
        ],
    )
    def test_malformed(self, tmp_path, body, words):
        p = write(tmp_path, "bad_rec.AT2", AT2_HEAD + body)
        with pytest.raises(RecordError, match=words) as exc:
            read_record(p)
        assert "bad_rec.AT2" in str(exc.value)

    def test_too_short_header(self, tmp_path):
        p = write(tmp_path, "short.AT2", "PEER\nx\n")
        with pytest.raises(RecordError, match=r"short\.AT2.*4 header lines"):
            read_record(p)

    def test_velocity_file_refused(self, tmp_path):
        p = write(tmp_path, "vel.VT2.AT2", AT2_HEAD.replace(
            "ACCELERATION TIME SERIES IN UNITS OF G", "VELOCITY TIME SERIES IN UNITS OF CM/S")
            + "NPTS=  2, DT= .01 SEC\n .1 .2\n")
        with pytest.raises(RecordError, match=r"vel\.VT2\.AT2, line 3: .*units of G"):
            read_record(p)


# ---------------------------------------------------------------------- CSV / columns
class TestColumns:
    def test_two_column_csv_with_header(self, tmp_path):
        p = write(tmp_path, "r.csv", "time,acc\n0,0.1\n0.01,0.2\n0.02,-0.3\n")
        rec = Record.from_file(p)
        assert rec.dt == pytest.approx(0.01)
        np.testing.assert_allclose(rec.acc, np.array([0.1, 0.2, -0.3]) * G)
        assert rec.meta["format"] == "csv" and rec.meta["npts"] == 3
        assert rec.name == "r"

    def test_semicolon_csv(self, tmp_path):
        p = write(tmp_path, "s.csv", "t;acc\n0;1.5\n0.02;2.5\n")
        rec = Record.from_file(p, units="m/s^2")
        assert rec.dt == pytest.approx(0.02)
        np.testing.assert_allclose(rec.acc, [1.5, 2.5])
        q = write(tmp_path, "euro.csv", "t;acc\n0,00;1,5\n0,02;2,5\n")  # decimal commas
        with pytest.raises(RecordError, match=r"euro\.csv, line 2: non-numeric value '0,00'"):
            Record.from_file(q)

    def test_whitespace_columns_with_comments_and_offset_start(self, tmp_path):
        p = write(tmp_path, "r.txt", "# recorded on a table\n# another comment\n\n"
                  "  5.00   1.0\n  5.02   2.0  # inline\n\n  5.04   3.0\n")
        rec = Record.from_file(p, units="m/s^2")
        assert rec.dt == pytest.approx(0.02)
        np.testing.assert_allclose(rec.acc, [1.0, 2.0, 3.0])
        assert rec.meta["format"] == "columns"
        assert rec.meta["t_start"] == pytest.approx(5.0)
        assert rec.acceleration(0.0) == pytest.approx(1.0)  # re-based to start at t = 0

    def test_one_column_needs_dt(self, tmp_path):
        p = write(tmp_path, "one.txt", "0.1\n0.2\n0.3\n")
        with pytest.raises(RecordError, match=r"dt is required for a one-column record.*one\.txt"):
            Record.from_file(p)
        rec = Record.from_file(p, dt=0.02)
        assert rec.dt == 0.02 and len(rec) == 3

    def test_one_column_dt_and_units_from_header(self, tmp_path):
        p = write(tmp_path, "hdr.txt", "# dt = 0.005 s\n# units: gal\nacc\n10\n20\n-30\n")
        rec = Record.from_file(p, units="gal")
        assert rec.dt == 0.005
        np.testing.assert_allclose(rec.acc, [0.1, 0.2, -0.3])
        q = write(tmp_path, "ms.txt", "# dt: 10 ms\n1\n2\n")
        assert read_record(q)[1] == pytest.approx(0.01)

    def test_header_units_must_agree_with_units_passed(self, tmp_path):
        p = write(tmp_path, "u.csv", "# units: cm/s^2\nt,acc\n0,1\n0.01,2\n")
        with pytest.raises(RecordError, match=r"u\.csv, line 1: .*'cm/s\^2'.*units='g'"):
            Record.from_file(p)
        np.testing.assert_allclose(Record.from_file(p, units="cm/s^2").acc, [0.01, 0.02])

    def test_dt_disagreements(self, tmp_path):
        p = write(tmp_path, "d.csv", "0,1\n0.01,2\n0.02,3\n")
        assert Record.from_file(p, dt=0.01).dt == pytest.approx(0.01)
        with pytest.raises(RecordError, match=r"d\.csv.*dt=0.02 s was passed.*0.01"):
            Record.from_file(p, dt=0.02)
        q = write(tmp_path, "h.csv", "# dt = 0.02 s\n0,1\n0.01,2\n0.02,3\n")
        with pytest.raises(RecordError, match=r"h\.csv.*header \(line 1\)"):
            Record.from_file(q)
        r = write(tmp_path, "o.txt", "# dt = 0.02 s\n1\n2\n")
        with pytest.raises(RecordError, match=r"o\.txt, line 1: dt=0.01 s was passed"):
            Record.from_file(r, dt=0.01)

    @pytest.mark.parametrize("units, factor", [("g", G), ("m/s^2", 1.0), ("cm/s^2", 0.01),
                                               ("gal", 0.01), ("mm/s^2", 0.001)])
    def test_unit_factors(self, tmp_path, units, factor):
        p = write(tmp_path, "x.csv", "0,1.5\n0.01,-2.0\n")
        np.testing.assert_allclose(Record.from_file(p, units=units).acc,
                                   np.array([1.5, -2.0]) * factor, rtol=1e-15)

    def test_same_record_in_g_gal_and_si(self, tmp_path):
        a_si = np.array([0.0, 1.2, -3.4, 2.2, 0.5])
        def col(values):
            return "\n".join(map(repr, values.tolist()))

        rg = Record.from_file(write(tmp_path, "g.txt", col(a_si / G)), units="g", dt=0.01)
        rgal = Record.from_file(write(tmp_path, "gal.txt", col(a_si * 100)), units="gal",
                                dt=0.01)
        rcm = Record.from_file(write(tmp_path, "cm.txt", col(a_si * 100)), units="cm/s^2",
                               dt=0.01)
        for r in (rg, rgal, rcm):
            np.testing.assert_allclose(r.acc, a_si, rtol=1e-12, atol=1e-15)

    def test_unknown_units(self, tmp_path):
        p = write(tmp_path, "x.csv", "0,1\n0.01,2\n")
        with pytest.raises(UnitError, match="furlong"):
            Record.from_file(p, units="furlong/fortnight")

    @pytest.mark.parametrize(
        "text, words",
        [
            ("t,acc\n0,1\n0.01,2\n0.02,abc\n", r"line 4: non-numeric value 'abc'"),
            ("t,acc\n0,1\n0.01,nan\n0.02,1\n", r"line 3: NaN or infinite"),
            ("# c\n0 1\n0.01 inf\n", r"line 3: NaN or infinite"),
            ("t,acc\n0,1\n0.01,2\n0.025,3\n0.035,4\n", r"line 4: uneven time step 0.015"),
            ("0,1\n0.01,2\n0.01,3\n", r"line 3: time does not increase"),
            ("0,1\n-0.01,2\n-0.02,3\n", r"line 2: time does not increase"),
            ("", r"empty"),
            ("   \n\n", r"empty"),
            ("# nothing here\n# at all\n", r"no data"),
            ("time,acc\n", r"no data"),
            ("0,1\n", r"line 1: a record needs at least 2 samples"),
            ("0,1,2\n0.01,2,3\n", r"line 1: 3 columns"),
            ("0,1\n0.01,2\n0.02\n", r"line 3: 1 column\(s\), but line 1 has 2"),
            ("t acc\nfoo bar\n0 1\n", r"line 2: non-numeric value 'foo'"),
            ("0,1\n0.01,,\n", r"line 2: empty value"),
            ("# units: furlongs\n0,1\n0.01,2\n", r"line 1: unknown units 'furlongs'"),
        ],
    )
    def test_malformed(self, tmp_path, text, words):
        p = write(tmp_path, "bad_file.csv", text)
        with pytest.raises(RecordError, match=words) as exc:
            Record.from_file(p)
        assert "bad_file.csv" in str(exc.value)

    def test_uneven_step_within_tolerance_is_accepted(self, tmp_path):
        t = np.arange(6) * 0.01
        t[3] += 1e-10  # far below 1e-6 dt
        p = tmp_path / "ok.csv"
        np.savetxt(p, np.column_stack([t, np.ones(6)]), delimiter=",", fmt="%.17g")
        assert Record.from_file(p).dt == pytest.approx(0.01)
        t[3] += 1e-7  # 1e-5 dt
        np.savetxt(p, np.column_stack([t, np.ones(6)]), delimiter=",", fmt="%.17g")
        with pytest.raises(RecordError, match=r"ok\.csv, line 4: uneven"):
            Record.from_file(p)

    def test_file_not_found_and_directory(self, tmp_path):
        with pytest.raises(RecordError, match=r"not found.*missing\.csv"):
            Record.from_file(tmp_path / "missing.csv")
        with pytest.raises(RecordError, match="directory"):
            Record.from_file(tmp_path)

    def test_large_file(self, tmp_path):
        n = 100_000
        t = np.arange(n) * 0.005
        a = np.sin(t)
        p = tmp_path / "big.txt"
        np.savetxt(p, np.column_stack([t, a]), fmt="%.10g")
        rec = Record.from_file(p, units="m/s^2")
        assert len(rec) == n and rec.dt == pytest.approx(0.005)
        np.testing.assert_allclose(rec.acc, a, atol=1e-9)


# --------------------------------------------------------------------------- write_csv
class TestWriteCsv:
    def test_round_trip(self, tmp_path):
        rng = np.random.default_rng(7)
        rec = Record(rng.normal(scale=3.0, size=1000), dt=0.0066, name="noise")
        p = write_csv(rec, tmp_path / "noise.csv")
        back = Record.from_file(p, units="m/s^2")
        assert back.dt == pytest.approx(rec.dt, rel=1e-9)
        np.testing.assert_allclose(back.acc, rec.acc, rtol=1e-9, atol=1e-12)
        t = np.linspace(0.0, rec.duration + 0.1, 5000)
        np.testing.assert_allclose(back.acceleration(t), rec.acceleration(t), atol=1e-9)
        text = p.read_text()
        assert "m/s^2" in text and "dt" in text and "t,acc" in text

    def test_round_trip_of_a_real_record_with_load_factor(self, tmp_path):
        rec = load_builtin("RSN126").scaled(1.5)
        back = Record.from_file(write_csv(rec, tmp_path / "gazli.csv"), units="m/s^2")
        np.testing.assert_allclose(back.acc, 1.5 * rec.acc, rtol=1e-9, atol=1e-12)
        assert back.pga == pytest.approx(rec.pga, rel=1e-9)

    def test_default_units_g_refuse_an_si_file(self, tmp_path):
        p = write_csv(Record([0.0, 1.0], dt=0.1), tmp_path / "si.csv")
        with pytest.raises(RecordError, match=r"si\.csv.*m/s\^2"):
            Record.from_file(p)  # default units="g" contradicts '# units: m/s^2'

    def test_refuses_non_records(self, tmp_path):
        with pytest.raises(TypeError, match="sample"):
            write_csv(Sine(1.0, 0.01, 1.0), tmp_path / "s.csv")
