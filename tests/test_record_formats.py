"""Record files as the databases distribute them (issue 21): ESM ASCII, COSMOS Volume 2 and
K-NET / KiK-net ASCII, recognised by their content.

Each file is written here from the format's specification (ESM "DYNA 1.2" header; COSMOS
Strong Motion Data Format v1.20; NIED's "About K-NET ASCII format") from a PEER record
shipped with the package, read back with :func:`rocking.motions.io.read_record`, and
compared with the same record read from its ``.AT2`` file: the same samples to the
rounding of the written number format, the same time step. Then the contracts: detection by
content, declared counts, units, peaks and cut files.
"""

from __future__ import annotations

import re
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from cli_helpers import assert_one_line_error, run_main

from rocking.errors import PlausibilityWarning, RecordError
from rocking.motions import Record, catalog
from rocking.motions.io import read_builtin, read_record

NAME = "RSN948_NORTHR_CAM009"  # Northridge 1994, Arcadia: dt 0.01 s, PGA 0.09 g
GAL = 0.01  # m/s^2 per gal (cm/s^2)


@pytest.fixture(scope="module")
def at2():
    """The AT2 record (m/s^2) cut to 3400 samples (34.00 s: a whole number of seconds, as
    K-NET's Duration Time states it)."""
    acc, dt, meta = read_builtin(NAME)
    return acc[:3400].copy(), dt


# ------------------------------------------------------------------------- ESM writer
ESM_KEYS = [  # the 64 lines of the DYNA 1.2 header, in order
    "EVENT_NAME", "EVENT_ID", "EVENT_DATE_YYYYMMDD", "EVENT_TIME_HHMMSS",
    "EVENT_LATITUDE_DEGREE", "EVENT_LONGITUDE_DEGREE", "EVENT_DEPTH_KM",
    "HYPOCENTER_REFERENCE", "MAGNITUDE_W", "MAGNITUDE_W_REFERENCE", "MAGNITUDE_L",
    "MAGNITUDE_L_REFERENCE", "FOCAL_MECHANISM", "NETWORK", "STATION_CODE", "STATION_NAME",
    "STATION_LATITUDE_DEGREE", "STATION_LONGITUDE_DEGREE", "STATION_ELEVATION_M",
    "LOCATION", "SENSOR_DEPTH_M", "VS30_M/S", "SITE_CLASSIFICATION_EC8",
    "MORPHOLOGIC_CLASSIFICATION", "EPICENTRAL_DISTANCE_KM",
    "EARTHQUAKE_BACKAZIMUTH_DEGREE", "DATE_TIME_FIRST_SAMPLE_YYYYMMDD_HHMMSS",
    "DATE_TIME_FIRST_SAMPLE_PRECISION", "SAMPLING_INTERVAL_S", "NDATA", "DURATION_S",
    "STREAM", "UNITS", "INSTRUMENT", "INSTRUMENT_ANALOG/DIGITAL",
    "INSTRUMENTAL_FREQUENCY_HZ", "INSTRUMENTAL_DAMPING", "FULL_SCALE_G",
    "N_BIT_DIGITAL_CONVERTER", "PGA_CM/S^2", "TIME_PGA_S", "BASELINE_CORRECTION",
    "FILTER_TYPE", "FILTER_ORDER", "LOW_CUT_FREQUENCY_HZ", "HIGH_CUT_FREQUENCY_HZ",
    "LATE/NORMAL_TRIGGERED", "DATABASE_VERSION", "HEADER_FORMAT", "DATA_TYPE", "PROCESSING",
    "DATA_TIMESTAMP_YYYYMMDD_HHMMSS", "DATA_LICENSE", "DATA_CITATION", "DATA_CREATOR",
    "ORIGINAL_DATA_MEDIATOR_CITATION", "ORIGINAL_DATA_MEDIATOR",
    "ORIGINAL_DATA_CREATOR_CITATION", "ORIGINAL_DATA_CREATOR",
    "USER1", "USER2", "USER3", "USER4", "USER5"]


def esm_text(acc, dt, **over) -> str:
    """An ESM ASCII acceleration file: the header, then one value (cm/s^2) per line."""
    cm = [f"{v / GAL:.6f}" for v in acc]
    k = int(np.argmax(np.abs(np.array([float(c) for c in cm]))))
    hdr = dict.fromkeys(ESM_KEYS, "")
    hdr.update({
        "EVENT_NAME": "NORTHRIDGE", "EVENT_ID": "US-1994-0001",
        "EVENT_DATE_YYYYMMDD": "19940117", "EVENT_TIME_HHMMSS": "123055",
        "MAGNITUDE_W": "6.7", "NETWORK": "CI", "STATION_CODE": "CAM",
        "STATION_NAME": "Arcadia - Campus Dr", "LOCATION": "00",
        "DATE_TIME_FIRST_SAMPLE_YYYYMMDD_HHMMSS": "19940117_123100.000",
        "SAMPLING_INTERVAL_S": f"{dt:.6f}", "NDATA": str(len(cm)),
        "DURATION_S": f"{len(cm) * dt:.3f}", "STREAM": "HNE", "UNITS": "cm/s^2",
        "PGA_CM/S^2": cm[k], "TIME_PGA_S": f"{k * dt:.6f}",
        "BASELINE_CORRECTION": "BASELINE REMOVED", "FILTER_TYPE": "BUTTERWORTH",
        "DATABASE_VERSION": "ESM 2018", "HEADER_FORMAT": "DYNA 1.2",
        "DATA_TYPE": "ACCELERATION", "PROCESSING": "manual (Paolucci et al., 2011)",
    })
    hdr.update(over)
    return "\n".join([f"{key}: {v}" for key, v in hdr.items()] + cm) + "\n"


# ---------------------------------------------------------------------- COSMOS writer
def cosmos_text(acc, dt, product="Corrected acceleration", stage=2, param=1, code=4,
                quantity="acceleration", units_text="cm/sec2(04)", npts=None, peak=None,
                dt_ms=None, dt_s=None, e_format=False) -> str:
    """A COSMOS v1.20 file with one channel: 13 text lines, 100 integers (10I8), 100 reals
    (5F15.6), one comment, the data header and the values in (8F10.5), cm/s^2; with
    ``e_format`` one value per line in (1E15.6), as gmprocess writes them."""
    cm = np.asarray(acc) / GAL if e_format else np.round(np.asarray(acc) / GAL, 5)
    n = len(cm)
    k = int(np.argmax(np.abs(cm)))
    text = [
        f"{product:<25s} (Format v01.20 with 13 text lines) Src: rocking test",
        "Northridge earthquake                   January 17, 1994 04:30 PST",
        "Hypocenter: 34.206  -118.554   H= 18km(NEIC) M=6.7",
        "Origin: 01/17/1994, 12:30:55.4 UTC (NEIC)",
        "Statn No: 24-  461  Code:CI-CAM    CGS  Arcadia - Campus Dr",
        "Coords: 34.1310 -118.0540  Site geology:Alluvium",
        "Recorder: SMA-1  s/n: 1234 (  3 Chns of  3 at Sta) Sensor:FBA        s/n",
        "Rcrd start time:01/17/1994, 12:31:00.000 UTC (Q=5) RcrdId:24461-S1234-94017.02",
        "Sta Chan   1:  9 deg (Rcrdr Chan  1) Location:Free field",
        f"Raw record length = {n * dt:7.3f} sec, Uncor max =    0.000        at    0.000 sec",
        f"Processed: 02/01/1994, 10:00:00  CGS   Max = {abs(cm[k]):9.3f} cm/s^2 at "
        f"{k * dt:7.3f} sec",
        "Record filtered below  0.10 Hz (periods over  10.0 secs)  and above 25.0 Hz",
        "Values used when parameter or data value is unknown/unspecified:   -999, -999.0",
    ]
    ints = np.full(100, -999, dtype=int)
    ints[:4] = [stage, param, code, 120]
    reals = np.full(100, -999.0)
    reals[33] = dt if dt_s is None else dt_s            # #34 sampling interval (s)
    reals[61] = dt * 1000.0 if dt_ms is None else dt_ms  # #62 time step (ms)
    reals[62] = n * dt                                 # #63 series length npts dt (s)
    reals[63] = cm[k] if peak is None else peak        # #64 maximum value
    reals[64] = k * dt                                 # #65 time of the maximum (s)
    out = [*text, "100 Integer-header values follow on 10 lines, Format= (10I8)"]
    out += ["".join(f"{v:8d}" for v in ints[r:r + 10]) for r in range(0, 100, 10)]
    out.append("100 Real-header values follow on 20 lines, Format= (5F15.6)")
    out += ["".join(f"{v:15.6f}" for v in reals[r:r + 5]) for r in range(0, 100, 5)]
    out += ['   1 Comment line(s) follow, each starting with a "|":',
            "| written by tests/test_record_formats.py from the COSMOS v1.20 specification"]
    out.append(f"{n if npts is None else npts:8d} {quantity} pts, approx {int(n * dt):4d} "
               f"secs, units={units_text}, Format=({'1E15.6' if e_format else '8F10.5'})")
    if e_format:
        out += [f"{v:15.6E}" for v in cm]
    else:
        out += ["".join(f"{v:10.5f}" for v in cm[r:r + 8]) for r in range(0, n, 8)]
    out.append(f"End-of-data for Chan  1 {quantity}")
    return "\n".join(out) + "\n"


# ----------------------------------------------------------------------- K-NET writer
SCALE = (7845, 8223790)  # 'Scale Factor 7845(gal)/8223790': gal per count = 7845/8223790


def knet_counts(acc, offset=8000):
    return np.round(np.asarray(acc) / GAL * SCALE[1] / SCALE[0]).astype(int) + offset


def knet_text(counts, dt, direction="N-S", duration=None, max_acc=None) -> str:
    """A K-NET ASCII file (17 header lines, counts 8 to a line, each line ending in LF)."""
    n = len(counts)
    scale = SCALE[0] / SCALE[1]
    peak = np.max(np.abs(counts - counts.mean())) * scale  # NIED: after the mean
    hdr = [
        "Origin Time       2006/01/18 23:25:00", "Lat.              37.798",
        "Long.             142.200", "Depth. (km)       36", "Mag.              5.7",
        "Station Code      MYG002", "Station Lat.      38.7262",
        "Station Long.     141.5109", "Station Height(m) 79",
        "Record Time       2006/01/18 23:25:46",
        f"Sampling Freq(Hz) {round(1 / dt)}Hz",
        f"Duration Time(s)  {round(n * dt) if duration is None else duration}",
        f"Dir.              {direction}",
        f"Scale Factor      {SCALE[0]}(gal)/{SCALE[1]}",
        f"Max. Acc. (gal)   {peak:.3f}" if max_acc is None else f"Max. Acc. (gal)   {max_acc}",
        "Last Correction   2006/01/18 23:25:31", "Memo.             ",
    ]
    rows = ["".join(f"{c:8d} " for c in counts[r:r + 8]) for r in range(0, n, 8)]
    return "\n".join(hdr + rows) + "\n"


def write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(text)
    return p


# ------------------------------------------------------- the same motion as in AT2
def test_esm_reads_as_the_at2(tmp_path, at2):
    acc, dt = at2
    p = write(tmp_path, "CI.CAM.00.HNE.D.19940117.123100.C.ACC.ASC", esm_text(acc, dt))
    got, step, meta = read_record(p, units="cm/s^2")
    assert step == dt
    np.testing.assert_allclose(got, acc, rtol=0, atol=0.5e-6 * GAL * (1 + 1e-9))
    assert meta["format"] == "ESM" and meta["units"] == "cm/s^2"
    assert (meta["network"], meta["station"], meta["component"]) == ("CI", "CAM", "HNE")
    assert meta["event"] == "US-1994-0001" and meta["npts"] == len(acc)
    assert abs(meta["pga_declared"]) * GAL == pytest.approx(np.max(np.abs(acc)), abs=1e-8)


def test_cosmos_v2_reads_as_the_at2(tmp_path, at2):
    acc, dt = at2
    p = write(tmp_path, "CAM009.V2", cosmos_text(acc, dt))
    got, step, meta = read_record(p, units="cm/s^2")
    assert step == pytest.approx(dt, rel=1e-12)
    np.testing.assert_allclose(got, acc, rtol=0, atol=0.5e-5 * GAL * (1 + 1e-9))
    assert meta["format"] == "COSMOS-V2" and meta["units"] == "cm/s^2"
    assert (meta["network"], meta["station"], meta["component"]) == ("CI", "CAM", "9 deg")
    assert "Northridge" in meta["event"] and meta["npts"] == len(acc)


def test_knet_reads_as_the_at2_with_the_scale_factor_once(tmp_path, at2):
    """Counts times 7845/8223790 gal, less the mean of the whole record (NIED's
    definition of the data behind Max. Acc.), equal the AT2 record less its mean, to
    half a count."""
    acc, dt = at2
    p = write(tmp_path, "MYG0020601182325.NS", knet_text(knet_counts(acc), dt))
    got, step, meta = read_record(p, units="gal")
    assert step == pytest.approx(dt, rel=1e-12)
    scale = SCALE[0] / SCALE[1] * GAL  # m/s^2 per count
    np.testing.assert_allclose(got, acc - acc.mean(), rtol=0, atol=scale)
    assert meta["format"] == "KNET" and meta["units"] == "gal"
    assert (meta["station"], meta["component"], meta["network"]) == ("MYG002", "NS", "BO")
    assert meta["sampling_frequency"] == pytest.approx(1 / dt)
    # the offset of the counts (8000 here) is what was removed, in gal
    assert meta["offset"] == pytest.approx(8000 * SCALE[0] / SCALE[1], rel=1e-3)


def test_knet_offset_does_not_change_the_motion(tmp_path, at2):
    acc, dt = at2
    a = read_record(write(tmp_path, "a.EW", knet_text(knet_counts(acc, 0), dt,
                                                      "E-W")), units="gal")[0]
    b = read_record(write(tmp_path, "b.EW", knet_text(knet_counts(acc, -24710), dt,
                                                      "E-W")), units="gal")[0]
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-12)


def test_kiknet_direction_names_the_sensor(tmp_path, at2):
    acc, dt = at2
    p = write(tmp_path, "TCGH130007210339.EW1", knet_text(knet_counts(acc[:800]), dt, "2"))
    meta = read_record(p, units="gal")[2]
    assert meta["format"] == "KiK-net" and meta["sensor"] == "borehole"
    assert meta["component"] == "EW"


# --------------------------------------------------------------- detection by content
@pytest.mark.parametrize("name", ["record.AT2", "record.txt", "record"])
def test_detected_by_content_not_extension(tmp_path, at2, name):
    acc, dt = at2
    short = acc[:400]
    for kind, text, units in (("ESM", esm_text(short, dt), "cm/s^2"),
                              ("COSMOS-V2", cosmos_text(short, dt), "cm/s^2"),
                              ("KNET", knet_text(knet_counts(short), dt,
                                                 duration=4), "gal")):
        p = write(tmp_path, name, text)
        got, step, meta = read_record(p, units=units)
        assert meta["format"] == kind and step == pytest.approx(dt)
        assert got.size == short.size


# ----------------------------------------------------------------------------- units
def test_file_units_must_agree_with_the_units_passed(tmp_path, at2):
    acc, dt = at2
    files = {"esm": write(tmp_path, "e.asc", esm_text(acc[:300], dt)),
             "cosmos": write(tmp_path, "c.v2", cosmos_text(acc[:300], dt)),
             "knet": write(tmp_path, "k.ns", knet_text(knet_counts(acc[:300]), dt,
                                                       duration=3))}
    for p in files.values():
        for wrong in ("g", "m/s^2"):  # the default g is a stated unit, as for AT2 files
            with pytest.raises(RecordError, match=rf"units='{re.escape(wrong)}' was passed; pass "
                               r"units='(cm/s\^2|gal)'"):
                read_record(p, units=wrong)
        a = read_record(p, units="gal")[0]  # gal and cm/s^2: the same unit
        b = read_record(p, units="cm/s^2")[0]
        c, _, meta = read_record(p, units=None)  # None: the file's own unit
        np.testing.assert_array_equal(a, b)
        np.testing.assert_array_equal(a, c)
        assert meta["units"] in ("cm/s^2", "gal")
    with pytest.raises(RecordError, match="pass units='cm/s\\^2'"):
        Record.from_file(files["esm"])  # Record.from_file's default is g


def test_cosmos_units_code_and_name_must_agree(tmp_path, at2):
    acc, dt = at2
    p = write(tmp_path, "c.v2", cosmos_text(acc[:80], dt, units_text="g(04)"))
    with pytest.raises(RecordError, match="units name and code disagree"):
        read_record(p, units=None)
    p = write(tmp_path, "d.v2", cosmos_text(acc[:80], dt, code=11, units_text="mg(11)"))
    with pytest.raises(RecordError, match=r"code 11 \(mg\)"):
        read_record(p, units=None)


# ---------------------------------------------------------------- declared counts, cuts
def test_wrong_declared_counts_refused(tmp_path, at2):
    acc, dt = at2
    a = acc[:400]
    n = len(a)
    with pytest.raises(RecordError, match=rf"NDATA: {n + 1} but {n} values"):
        read_record(write(tmp_path, "e1", esm_text(a, dt, NDATA=str(n + 1))), units=None)
    with pytest.raises(RecordError, match=rf"1 value\(s\) beyond NDATA: {n - 1}"):
        read_record(write(tmp_path, "e2", esm_text(a, dt, NDATA=str(n - 1))), units=None)
    with pytest.raises(RecordError, match="more than the"):  # 399 declared, 400 written
        read_record(write(tmp_path, "c1", cosmos_text(a, dt, npts=n - 1)), units=None)
    with pytest.raises(RecordError, match="Duration Time 5 s at 100 Hz, i.e. 500 values, but "
                       "400 were read"):
        read_record(write(tmp_path, "k1", knet_text(knet_counts(a), dt, duration=5)),
                    units=None)


def test_cut_files_refused(tmp_path, at2):
    acc, dt = at2
    a = acc[:403]
    esm = esm_text(a, dt)
    with pytest.raises(RecordError, match="looks cut"):  # whole lines lost
        read_record(write(tmp_path, "e1", esm[:esm.rindex("\n", 0, len(esm) - 200)]),
                    units=None)
    lines = esm.rstrip("\n").split("\n")  # cut inside the last number: count unchanged
    lines[-1] = lines[-1][:-3]
    with pytest.raises(RecordError, match="last value .* looks cut"):
        read_record(write(tmp_path, "e2", "\n".join(lines)), units=None)
    cos = cosmos_text(a, dt)
    body = cos[:cos.index("End-of-data")].rstrip("\n")
    with pytest.raises(RecordError, match="line is shorter .*looks cut"):
        read_record(write(tmp_path, "c1", body[:-4]), units=None)
    kn = knet_text(knet_counts(a), dt, duration=4.03)
    assert read_record(write(tmp_path, "k0", kn), units=None)[0].size == 403
    with pytest.raises(RecordError, match="does not end with a line break.*looks cut"):
        read_record(write(tmp_path, "k1", kn.rstrip("\n")[:-3]), units=None)
    with pytest.raises(RecordError, match="looks cut"):
        read_record(write(tmp_path, "k2", kn[:kn.rindex("\n", 0, len(kn) - 100) + 1]),
                    units=None)


# ------------------------------------------------------------- what the file holds
def test_cosmos_v1_velocity_and_raw_refused_by_name(tmp_path, at2):
    acc, dt = at2
    a = acc[:200]
    v1 = cosmos_text(a, dt, product="Uncorrected acceleration", stage=1)
    with pytest.raises(RecordError, match=r"Volume 1 \(uncorrected.*only Volume 2"):
        read_record(write(tmp_path, "v1", v1), units=None)
    v0 = cosmos_text(a, dt, product="Raw acceleration counts", stage=0, code=50,
                     units_text="counts(50)")
    with pytest.raises(RecordError, match=r"Volume 0 \(raw counts\)"):
        read_record(write(tmp_path, "v0", v0), units=None)
    vel = cosmos_text(a, dt, product="Velocity data", param=2, code=5,
                      quantity="velocity", units_text="cm/sec(05)")
    with pytest.raises(RecordError, match="holds velocity data, no acceleration"):
        read_record(write(tmp_path, "vel", vel), units=None)
    # a V2 file that also carries the integrated velocity: its acceleration is read
    both = cosmos_text(a, dt) + vel
    got = read_record(write(tmp_path, "both", both), units=None)[0]
    np.testing.assert_allclose(got, a, rtol=0, atol=0.5e-5 * GAL * (1 + 1e-9))
    two = cosmos_text(a, dt) + cosmos_text(a, dt)
    with pytest.raises(RecordError, match="2 acceleration channels"):
        read_record(write(tmp_path, "two", two), units=None)


def test_esm_velocity_refused(tmp_path, at2):
    acc, dt = at2
    p = write(tmp_path, "v.ASC", esm_text(acc[:100], dt, DATA_TYPE="VELOCITY",
                                          UNITS="cm/s"))
    with pytest.raises(RecordError, match="DATA_TYPE: VELOCITY; only ACCELERATION"):
        read_record(p, units=None)


# ------------------------------------------------------------------- stated peaks
def test_stated_peak_disagreement(tmp_path, at2):
    acc, dt = at2
    a = acc[:500]
    pga = np.max(np.abs(a)) / GAL
    with pytest.raises(RecordError, match="states a peak of .* contradicts itself"):
        read_record(write(tmp_path, "e", esm_text(a, dt, **{"PGA_CM/S^2": f"{9.81 * pga:.6f}"})),
                    units=None)
    with pytest.warns(PlausibilityWarning, match="states a peak"):
        read_record(write(tmp_path, "e2", esm_text(a, dt, **{"PGA_CM/S^2": f"{1.005 * pga:.6f}"})),
                    units=None)
    with pytest.raises(RecordError, match="real header #64"):
        read_record(write(tmp_path, "c", cosmos_text(a, dt, peak=100 * pga)), units=None)
    with pytest.raises(RecordError, match=r"Max\. Acc\."):
        read_record(write(tmp_path, "k", knet_text(knet_counts(a), dt, max_acc="0.050")),
                    units=None)
    with warnings.catch_warnings():  # the written peaks agree: no warning
        warnings.simplefilter("error")
        read_record(write(tmp_path, "ok", esm_text(a, dt)), units=None)
        read_record(write(tmp_path, "ok2", cosmos_text(a, dt)), units=None)


def test_dt_passed_must_agree(tmp_path, at2):
    acc, dt = at2
    p = write(tmp_path, "c.v2", cosmos_text(acc[:100], dt, dt_ms=10.0))
    assert read_record(p, units=None, dt=dt)[1] == pytest.approx(dt)
    with pytest.raises(RecordError, match=r"dt=0.02 s was passed but .*#62"):
        read_record(p, units=None, dt=0.02)


def test_knet_without_obspy_says_what_to_install(tmp_path, at2, monkeypatch):
    acc, dt = at2
    p = write(tmp_path, "k.NS", knet_text(knet_counts(acc[:100]), dt, duration=1))
    monkeypatch.setitem(sys.modules, "obspy", None)  # import obspy -> ImportError
    with pytest.raises(RecordError, match=r'pip install "rocking\[records\]"'):
        read_record(p, units="gal")


# --------------------------------------------------------- through the catalog and CLI
def test_catalog_record_kind_reads_esm(tmp_path, at2):
    acc, dt = at2
    write(tmp_path, "quake.asc", esm_text(acc, dt))
    rec = catalog.build("record", catalog.Context(base_dir=tmp_path), file="quake.asc",
                        units="cm/s^2")
    assert isinstance(rec, Record) and rec.dt == dt
    np.testing.assert_allclose(rec.acc, acc, rtol=0, atol=1e-8)
    assert rec.meta["format"] == "ESM" and rec.meta["station"] == "CAM"


def test_cli_motion_show_reads_esm(tmp_path, at2, capsys):
    acc, dt = at2
    p = write(tmp_path, "quake.asc", esm_text(acc, dt))
    code, out, err = run_main(capsys, "motion", "show", p, "--units", "cm/s^2", "--no-plot")
    assert code == 0, err
    pga = np.max(np.abs(acc))
    assert f"{len(acc)} samples, dt = {dt:g} s" in out
    assert f"PGA {pga:.4g} m/s^2" in out
    code, out, err = run_main(capsys, "motion", "show", p, "--no-plot")  # default: g
    assert_one_line_error(code, err, "--units cm/s^2")


def test_knet_real_nied_file_shipped_with_obspy():
    """A real K-NET file (AKT013, 1996, the one obspy tests with): 59 s at 100 Hz give
    5900 values, and the peak after removing the mean equals the header's Max. Acc.
    (4.383 gal) to its rounding."""
    import obspy

    p = Path(obspy.__file__).parent / "io/nied/tests/data/test.knet"
    if not p.is_file():
        pytest.skip("obspy installed without its test data")
    acc, dt, meta = read_record(p, units="gal")
    assert (acc.size, dt, meta["station"], meta["component"]) == (5900, 0.01, "AKT013", "EW")
    assert np.max(np.abs(acc)) / GAL == pytest.approx(4.383, abs=5e-4)
    counts = np.array([int(t) for ln in p.read_text().splitlines()[17:] for t in ln.split()])
    np.testing.assert_allclose(acc, (counts - counts.mean()) * 2000 / 8388608 * GAL,
                               rtol=1e-12, atol=0)


def test_units_none_takes_the_unit_at2_and_column_files_state(tmp_path):
    """``units=None`` (the caller states no unit): the file's own unit, g if it states
    none; never a re-scaling of a stated unit."""
    at2 = ("PEER STRONG MOTION DATABASE RECORD\nTEST, 1/1/2000, STA, 0\n"
           "ACCELERATION TIME SERIES IN UNITS OF CM/S/S\nNPTS=    3, DT=   .0100 SEC\n"
           "  .1000000E+01  .2000000E+01 -.3000000E+01\n")
    acc, _, meta = read_record(write(tmp_path, "a.AT2", at2), units=None)
    np.testing.assert_allclose(acc, [0.01, 0.02, -0.03], rtol=1e-15)
    assert meta["units"] == "cm/s^2"
    acc, _, meta = read_record(write(tmp_path, "b.csv", "# units: gal\nt,acc\n0,1\n0.01,2\n"),
                               units=None)
    np.testing.assert_allclose(acc, [0.01, 0.02], rtol=1e-15)
    assert meta["units"] == "gal"
    acc, _, meta = read_record(write(tmp_path, "c.csv", "t,acc\n0,1\n0.01,2\n"), units=None)
    np.testing.assert_allclose(acc, [9.80665, 19.6133], rtol=1e-15)
    assert meta["units"] == "g"


def test_e_format_peak_rounding_is_relative(tmp_path, at2):
    """Data in (1E15.6) carry 7 significant digits: 2677.000456 cm/s^2 is written
    2.677000E+03, 4.6e-4 from the real header's 2677.000456 (F15.6), within half a unit
    in the last place of the E value (5e-4), so it agrees: no warning. A stated peak off by
    more than that rounding still warns (both peaks printed in full) or is refused."""
    acc, dt = at2
    a = acc[:600].copy()
    k = int(np.argmax(np.abs(a)))
    a[k] = 2677.000456 * GAL
    p = write(tmp_path, "e.v2", cosmos_text(a, dt, e_format=True, peak=2677.000456))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        got, step, meta = read_record(p, units=None)
    assert got[k] / GAL == pytest.approx(2677.0, abs=1e-9)  # the E value as written
    np.testing.assert_allclose(got / GAL, a / GAL, rtol=0.5e-6, atol=0)  # 7 digits
    with pytest.warns(PlausibilityWarning, match=r"peak of 2677\.912345 cm/s\^2 .* is 2677 "):
        read_record(write(tmp_path, "w.v2", cosmos_text(a, dt, e_format=True,
                                                        peak=2677.912345)), units=None)
    with pytest.raises(RecordError, match="real header #64"):
        read_record(write(tmp_path, "x.v2", cosmos_text(a, dt, e_format=True, peak=2800.0)),
                    units=None)
    # ESM: a PGA written with an exponent is precise to its last digit (0.5 cm/s^2 here)
    b = acc[:600].copy()
    b[k] = 2677.4 * GAL
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_record(write(tmp_path, "e.asc", esm_text(b, dt, **{"PGA_CM/S^2": "2.677E+03"})),
                    units=None)
    with pytest.warns(PlausibilityWarning, match="states a peak"):
        read_record(write(tmp_path, "f.asc", esm_text(b, dt, **{"PGA_CM/S^2": "2.676E+03"})),
                    units=None)


def test_cosmos_without_a_time_step_takes_the_dt_passed(tmp_path, at2):
    """Real #62 and #34 unknown (-999): refused without dt; with dt it is the record (the
    same samples as when the file states it), said in meta; a dt that contradicts the
    series length #63 the file states is refused."""
    acc, dt = at2
    a = acc[:800]
    p = write(tmp_path, "nodt.v2", cosmos_text(a, dt, dt_ms=-999.0, dt_s=-999.0))
    with pytest.raises(RecordError, match=r"states no time step .*pass dt"):
        read_record(p, units=None)
    got, step, meta = read_record(p, units=None, dt=dt)
    ref, ref_step, ref_meta = read_record(write(tmp_path, "dt.v2", cosmos_text(a, dt)),
                                          units=None)
    assert step == dt and meta["dt_from"] == "caller" and ref_meta["dt_from"] == "file"
    np.testing.assert_array_equal(got, ref)
    with pytest.raises(RecordError, match="#63 states a series length"):
        read_record(p, units=None, dt=2 * dt)


def test_meta_says_whether_the_file_states_its_unit(tmp_path, at2):
    """``units_stated``/``units_from``: the database formats and an AT2 units line state
    the unit; an AT2 file without one is in g by the PEER convention; a column file without
    one is in the caller's unit, or g assumed with units=None."""
    acc, dt = at2
    body = "NPTS=    3, DT=   .0100 SEC\n  .1000000E+01  .2000000E+01 -.3000000E+01\n"
    cases = [
        (esm_text(acc[:100], dt), "e.asc", None, "file"),
        (cosmos_text(acc[:100], dt), "c.v2", None, "file"),
        ("PEER\nX, 1/1/2000, S, 0\nACCELERATION TIME SERIES IN UNITS OF G\n" + body,
         "a.AT2", None, "file"),
        ("PEER\nX, 1/1/2000, S, 0\nACCELERATION TIME SERIES\n" + body, "b.AT2", None,
         "convention"),
        ("t,acc\n0,1\n0.01,2\n", "n.csv", None, "default"),
        ("t,acc\n0,1\n0.01,2\n", "n.csv", "g", "caller"),
        ("t,acc_g\n0,1\n0.01,2\n", "s.csv", None, "file"),
    ]
    for text, name, units, where in cases:
        _, _, meta = read_record(write(tmp_path, name, text), units=units)
        assert (meta["units_from"], meta["units_stated"]) == (where, where == "file"), name
    assert meta["units"] == "g"
