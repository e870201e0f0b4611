"""``rocking motion select`` (issue 21): a planted set recovered through the command line, the
90 % rule and max_scale in selection.json, EC8 and uniform-hazard targets against their closed
forms, and every bad input as one ``error:`` line with exit code 2."""

import json
import math
from importlib import resources

import numpy as np
import pandas as pd
import pytest
from cli_helpers import assert_one_line_error, run_main

import rocking
from rocking.motions.io import builtin_records, write_csv
from rocking.motions.records import Record, load_builtin
from rocking.motions.spectra import response_spectrum
from rocking.units import G

T_TABLE = np.geomspace(0.05, 2.0, 20)
PERIODS = "0.05:2:20"  # the table's own periods: the match is at the table's points
PLANTED = {"planted_a.csv": (0, 1.3), "planted_b.csv": (3, 0.7), "planted_c.csv": (7, 2.0)}
NPTS = 1500  # the shipped records cut short: a fast test
AT2 = "RSN126_GAZLI_GAZ000.AT2"


def _base_records():
    return [Record(r.acc[:NPTS], r.dt, name=r.name)
            for r in map(load_builtin, builtin_records(three_component=True))]


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    """30 candidate record files -- 3 planted (scaled copies of 3 shipped records), the 7
    other shipped records (scaled) and 20 filtered versions (low-pass 1.5 Hz, high-pass
    4 Hz) of all 10 -- plus a text file and a shipped AT2 file in g, both refused with
    ``--units m/s^2`` (the files written by write_csv state m/s^2)."""
    d = tmp_path_factory.mktemp("cands")
    base = _base_records()
    for name, (i, s) in PLANTED.items():
        write_csv(base[i].scaled(s), d / name)
    used = {i for i, _ in PLANTED.values()}
    for i, r in enumerate(base):
        if i not in used:
            write_csv(r.scaled(0.5 + 0.1 * i), d / f"other_{i}.csv")
        write_csv(r.filtered(low=None, high=1.5), d / f"lowpass_{i}.csv")
        write_csv(r.filtered(low=4.0, high=None), d / f"highpass_{i}.csv")
    (d / "readme.txt").write_text("records downloaded for the site\n")
    src = resources.files("rocking.motions") / "data" / "records" / AT2
    (d / AT2).write_bytes(src.read_bytes())
    return d


def _mean_spectrum(files, T):
    """Mean 5 %-damped pseudo-acceleration (m/s^2) of record files in m/s^2."""
    return np.mean([response_spectrum(Record.from_file(f, units="m/s^2"), T) for f in files],
                   axis=0)


@pytest.fixture(scope="module")
def target(folder):
    """The planted set's mean spectrum at T_TABLE (m/s^2), from the files as read back."""
    return _mean_spectrum([folder / f for f in PLANTED], T_TABLE)


def _write_table(path, T, sa_ms2, header="T (s),Sa (g)", factor=1.0 / G):
    rows = "\n".join(f"{float(t)!r},{float(v * factor)!r}"
                     for t, v in zip(T, sa_ms2, strict=True))
    path.write_text(f"# a site's target spectrum\n{header}\n{rows}\n")
    return path


def _results(out):
    return json.loads((out / "selection.json").read_text()), pd.read_csv(out / "selection.csv")


def test_planted_set_recovered_and_written_records_reproduce_the_target(
        capsys, tmp_path, folder, target):
    """The target is the mean spectrum of 3 planted files: the command picks those 3 at
    scale 1 among 30 candidates, and the records it writes, read back (by the library and
    by the CLI reader of `rocking simulate --record`), have that mean spectrum."""
    table = _write_table(tmp_path / "target.csv", T_TABLE, target)
    out = tmp_path / "out"
    code, stdout, err = run_main(capsys, "motion", "select", folder, "--target", table,
                                 "--n", 3, "--periods", PERIODS, "--units", "m/s^2",
                                 "--out", out)
    assert code == 0, err
    assert "warning" not in err
    assert "compliant" in stdout and "skipped" in stdout
    js, sel = _results(out)
    assert js["candidates"] == 30 and js["files"] == 32
    assert sorted(s["file"] for s in js["skipped"]) == sorted([AT2, "readme.txt"])
    assert all(s["reason"] for s in js["skipped"])
    assert sorted(sel["source"]) == sorted(PLANTED)
    np.testing.assert_allclose(sel["scale"], 1.0, rtol=1e-4)
    assert js["misfit"] < 1e-6 and js["compliant"] is True
    assert js["min_ratio"] == pytest.approx(1.0, abs=1e-5)
    assert js["target"]["kind"] == "table" and js["target"]["unit"] == "g"
    assert js["period_range"]["source"] == "--periods"
    # the written records, read back, reproduce the target
    files = [out / f for f in sel["file"]]
    np.testing.assert_allclose(_mean_spectrum(files, T_TABLE), target, rtol=1e-6)
    for f, src, pga in zip(files, sel["source"], sel["pga_ms2"], strict=True):
        rec = Record.from_file(f, units="m/s^2")
        orig = Record.from_file(folder / src, units="m/s^2")
        assert rec.pga == pytest.approx(pga, rel=1e-8)
        np.testing.assert_allclose(rec.values, orig.values, rtol=1e-4, atol=1e-12)
    # the CLI's record reader (rocking simulate --record, motion spectrum) reads them back
    code, stdout, err = run_main(capsys, "motion", "spectrum", files[0], "--units", "m/s^2",
                                 "--json", "--no-plot")
    assert code == 0, err
    assert json.loads(stdout)["intensity_measures"]["pga"] == pytest.approx(
        sel["pga_ms2"][0], rel=1e-8)
    sp = pd.read_csv(out / "selection_spectra.csv")
    np.testing.assert_allclose(sp["period_s"], T_TABLE, rtol=1e-9)
    np.testing.assert_allclose(sp["target_ms2"], target, rtol=1e-8)
    assert (out / "selection.png").stat().st_size > 0


def test_90_percent_rule_and_max_scale_when_the_target_is_out_of_reach(
        capsys, tmp_path, folder, target):
    """A target 50 times the planted mean with --max-scale 2: the best set is written, every
    factor within [1/2, 2], and flagged non-compliant (one warning line, compliant false,
    exit 0); its min_ratio is that of the written records' mean spectrum."""
    table = _write_table(tmp_path / "high.csv", T_TABLE, 50.0 * target,
                         header="period_s,sa_ms2", factor=1.0)
    out = tmp_path / "out"
    code, stdout, err = run_main(capsys, "motion", "select", folder, "--target", table,
                                 "--n", 4, "--max-scale", 2, "--periods", PERIODS,
                                 "--units", "m/s^2", "--out", out, "--json")
    assert code == 0, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("warning:") and "90" in lines[0]
    js, sel = _results(out)
    assert json.loads(stdout)["compliant"] is False and js["compliant"] is False
    assert js["max_scale"] == 2.0 and len(sel) == 4
    assert np.all(sel["scale"] <= 2.0 * (1 + 1e-9)) and np.all(sel["scale"] >= 0.5)
    mean = _mean_spectrum([out / f for f in sel["file"]], T_TABLE)
    ratio = mean / (50.0 * target)
    assert js["min_ratio"] == pytest.approx(ratio.min(), rel=1e-6)
    assert ratio.min() < 0.9
    assert any("cannot be met" in n for n in js["notes"])


def test_ec8_target_with_the_block_period_range(capsys, tmp_path, folder):
    """--target ec8 --ag 0.1g --ground B and --specimen 2: the period range runs from
    2 pi/(10 p) to 2 pi/p, the target is EN 1998-1's closed form (type 1, ground B: S 1.2,
    TB 0.15, TC 0.5, TD 2 s), the set is compliant (mean >= 90 % of it at every period,
    recomputed from the written files) with factors within --max-scale."""
    out = tmp_path / "out"
    code, stdout, err = run_main(capsys, "motion", "select", folder, "--target", "ec8",
                                 "--ag", "0.1g", "--ground", "B", "--specimen", 2, "--n", 5,
                                 "--units", "m/s^2", "--out", out, "--no-plot")
    assert code == 0, err
    js, sel = _results(out)
    p = rocking.specimen(2).p
    sp = pd.read_csv(out / "selection_spectra.csv")
    T = sp["period_s"].to_numpy()
    assert T[0] == pytest.approx(2 * math.pi / (10 * p), rel=1e-6)
    assert T[-1] == pytest.approx(2 * math.pi / p, rel=1e-6)
    ag, S, TC = 0.1 * G, 1.2, 0.5
    closed = np.where(T <= TC, 2.5 * S * ag, 2.5 * S * ag * TC / T)
    assert np.all((T >= 0.15) & (T <= 2.0))
    np.testing.assert_allclose(sp["target_ms2"], closed, rtol=1e-6)
    assert js["target"]["kind"] == "ec8" and js["period_range"]["source"] == "block"
    assert "2 pi/(10 p)" in js["period_range"]["why"]
    assert js["compliant"] is True
    assert np.all(sel["scale"] <= 4.0 * (1 + 1e-9)) and np.all(sel["scale"] >= 0.25)
    mean = _mean_spectrum([out / f for f in sel["file"]], T)
    assert np.min(mean / closed) >= 0.9 * (1 - 1e-6)
    assert np.min(mean / closed) == pytest.approx(js["min_ratio"], rel=1e-6)
    assert not (out / "selection.png").exists()


def test_uhs_target_from_power_law_hazard_curves(capsys, tmp_path, folder):
    """SA(T) curves lambda(a) = (a / a475(T))^-k / 475 with a475 = A T^-0.5: the uniform
    hazard spectrum at 2475 years is A T^-0.5 (2475/475)^(1/k) g (log-log exact between
    the curves' periods); a PGA curve is left out with a note."""
    A, k = 0.2, 3.0
    files = []
    for Tc in (0.1, 0.3, 1.0, 2.0):
        a475 = A * Tc ** -0.5
        im = a475 * np.geomspace(0.1, 10.0, 15)
        lines = [f"SA({Tc:g}) (g),rate"] + [f"{float(x)!r},{float((x / a475) ** -k / 475)!r}"
                                            for x in im]
        f = tmp_path / f"SA{Tc:g}.csv"
        f.write_text("\n".join(lines) + "\n")
        files.append(f)
    pga = tmp_path / "pga.csv"
    pga.write_text("PGA (g),return period (years)\n0.1,100\n0.2,475\n0.4,2475\n")
    args = [a for f in [*files, pga] for a in ("--hazard", f)]
    out = tmp_path / "out"
    code, stdout, err = run_main(capsys, "motion", "select", folder, "--target", "uhs", *args,
                                 "--return-period", "2475", "--periods", "0.1:1.5:15",
                                 "--n", 3, "--units", "m/s^2", "--out", out, "--no-plot")
    assert code == 0, err
    js, _ = _results(out)
    sp = pd.read_csv(out / "selection_spectra.csv")
    T = sp["period_s"].to_numpy()
    closed = A * T ** -0.5 * (2475.0 / 475.0) ** (1.0 / k) * G
    np.testing.assert_allclose(sp["target_ms2"], closed, rtol=1e-6)
    assert js["target"]["kind"] == "uhs" and js["target"]["return_period"] == 2475.0
    assert any("PGA curve is not used" in n for n in js["notes"])


def _sa_curves(tmp_path, A=0.2, k=3.0, t_poe=None):
    """SA(T) CSV curves lambda(a) = (a / a475(T))^-k / 475, a475 = A T^-0.5, as annual
    rates or (``t_poe``) as probabilities of exceedance 1 - exp(-lambda t) in t years."""
    files = []
    for Tc in (0.1, 0.3, 1.0, 2.0):
        a475 = A * Tc ** -0.5
        im = a475 * np.geomspace(0.5, 10.0, 15)  # poe < 1 in double precision
        lam = (im / a475) ** -k / 475
        col, y = (("rate", lam) if t_poe is None
                  else (f"poe in {t_poe:g} years", -np.expm1(-t_poe * lam)))
        f = tmp_path / f"SA{Tc:g}.csv"
        rows = [f"{float(x)!r},{float(v)!r}" for x, v in zip(im, y, strict=True)]
        f.write_text("\n".join([f"SA({Tc:g}) (g),{col}", *rows]) + "\n")
        files.append(f)
    return files


def _oq_sa(tmp_path, A=0.2, k=3.0, site=(13.4, 42.35)):
    """OpenQuake SA(T) exports (the engine's layout: a metadata comment line, then
    lon,lat,depth,poe-<level>) of the same law at one site, poe in 50 years."""
    files = []
    for Tc in (0.1, 0.3, 1.0, 2.0):
        a475 = A * Tc ** -0.5
        im = a475 * np.geomspace(0.5, 10.0, 15)
        poe = -np.expm1(-50.0 * (im / a475) ** -k / 475)
        f = tmp_path / f"hazard_curve-mean-SA({Tc:g})_3.csv"
        f.write_text("\n".join([
            f"#,,,,,\"generated_by='OpenQuake engine 3.18.0', kind='mean', "
            f"investigation_time=50.0, imt='SA({Tc:g})'\"",
            "lon,lat,depth," + ",".join(f"poe-{float(x)!r}" for x in im),
            f"{site[0]:.5f},{site[1]:.5f},-0.10000," + ",".join(f"{float(q)!r}" for q in poe)])
            + "\n")
        files.append(f)
    return files


def test_uhs_from_poe_curves_and_a_far_openquake_site(capsys, tmp_path, folder):
    """--investigation-time: poe curves in 50 years give the rate curves' spectrum (the
    closed form A T^-0.5 (Tr/475)^(1/k) g); --max-distance-km: OpenQuake curves asked one
    degree of latitude (111.19 km) from their site are refused (exit 2) at the default
    50 km and accepted at 200 km, with the same spectrum and that distance recorded."""
    A, k, tr = 0.2, 3.0, 2475.0
    common = ("--return-period", "2475", "--periods", "0.1:1.5:15", "--n", 3, "--units",
              "m/s^2", "--no-plot")
    poe = [a for f in _sa_curves(tmp_path, A, k, t_poe=50.0) for a in ("--hazard", f)]
    code, _, err = run_main(capsys, "motion", "select", folder, "--target", "uhs", *poe,
                            *common, "--out", tmp_path / "x")
    assert_one_line_error(code, err, "investigation-time")
    code, _, err = run_main(capsys, "motion", "select", folder, "--target", "uhs", *poe,
                            *common, "--investigation-time", "50", "--out", tmp_path / "a")
    assert code == 0, err
    sp = pd.read_csv(tmp_path / "a" / "selection_spectra.csv")
    T = sp["period_s"].to_numpy()
    closed = A * T ** -0.5 * (tr / 475.0) ** (1.0 / k) * G
    np.testing.assert_allclose(sp["target_ms2"], closed, rtol=1e-6)

    (tmp_path / "oq").mkdir()
    oq = [a for f in _oq_sa(tmp_path / "oq", A, k) for a in ("--hazard", f)]
    far = ("--site", "13.4,43.35")
    code, _, err = run_main(capsys, "motion", "select", folder, "--target", "uhs", *oq, *far,
                            *common, "--out", tmp_path / "y")
    assert_one_line_error(code, err, "max-distance-km")
    assert "111.2 km" in err
    code, _, err = run_main(capsys, "motion", "select", folder, "--target", "uhs", *oq, *far,
                            *common, "--max-distance-km", "200", "--out", tmp_path / "b")
    assert code == 0, err
    js, _ = _results(tmp_path / "b")
    for h in js["target"]["hazard"]:
        assert h["site_distance_km"] == pytest.approx(math.pi * 6371.0 / 180.0, rel=1e-9)
    sp = pd.read_csv(tmp_path / "b" / "selection_spectra.csv")
    np.testing.assert_allclose(sp["target_ms2"], closed, rtol=1e-6)


@pytest.mark.parametrize("args, name", [
    (("--target", "ec8", "--investigation-time", "50"), "investigation-time"),
    (("--target", "ec8", "--max-distance-km", "100"), "max-distance-km"),
    (("--target", "uhs", "--hazard", "SA.csv", "--investigation-time", "-5"),
     "investigation-time"),
    (("--target", "uhs", "--hazard", "SA.csv", "--max-distance-km", "far"),
     "max-distance-km"),
])
def test_poe_and_distance_options_bad_input_is_one_line(capsys, tmp_path, folder, args,
                                                        name):
    code, _, err = run_main(capsys, "motion", "select", folder, *args, "--periods",
                            "0.1:1:5", "--out", tmp_path / "o")
    assert_one_line_error(code, err, name)


@pytest.mark.parametrize("table, extra, name", [
    ("T (s)\n0.1\n1\n", (), "target"),                                   # one column
    ("T (s),Sa (g)\n0.1,0.5\n1,abc\n", (), "target"),                      # not numbers
    ("T (s),Sa\n0.1,0.5\n1,0.2\n", (), "target-unit"),                     # no unit
    ("T (s),Sa (g)\n0.1,0.5\n1,0.2\n", ("--target-unit", "m/s^2"), "target-unit"),
    ("T (s),Sa (g)\n1,0.5\n0.1,0.2\n", (), "target"),                      # not increasing
    ("T (s),Sa (g)\n0.1,0.5\n1,-0.2\n", (), "target"),                     # Sa <= 0
    ("T (s),Sa (g)\n0.2,0.5\n1,0.2\n", (), "periods"),                     # 0.1 s not covered
])
def test_target_table_in_the_wrong_form_is_one_line(capsys, tmp_path, folder, table, extra,
                                                    name):
    f = tmp_path / "t.csv"
    f.write_text(table)
    code, _, err = run_main(capsys, "motion", "select", folder, "--target", f, *extra,
                            "--periods", "0.1:1:5", "--units", "m/s^2", "--out",
                            tmp_path / "o")
    assert_one_line_error(code, err, name)


@pytest.mark.parametrize("args, name", [
    (("--n", "0"), "n"),
    (("--n", "31"), "n"),                     # 30 readable records
    (("--n", "x"), "n"),
    (("--max-scale", "0"), "max-scale"),
    (("--max-scale", "-2"), "max-scale"),
    (("--max-scale", "0.5"), "max-scale"),
    (("--max-scale", "abc"), "max-scale"),
    (("--periods", "2:1"), "periods"),
    (("--periods", "a:b"), "periods"),
    (("--periods", "0.1:2:1"), "periods"),
    (("--periods", "0.1"), "periods"),
    (("--periods", "0:2"), "periods"),
    (("--restarts", "0"), "restarts"),
    (("--damping", "150%"), "damping"),
    (("--units", "furlong"), "units"),
    (("--specimen", "2"), "periods"),          # --periods and a block
    (("--hazard", "x.csv"), "hazard"),         # uhs flags with --target ec8
    (("--target-unit", "g"), "target-unit"),
])
def test_bad_options_are_one_line(capsys, tmp_path, folder, args, name):
    base = {"--target": "ec8", "--n": "3", "--periods": "0.1:1:5", "--units": "m/s^2"}
    given = dict(zip(args[::2], args[1::2], strict=True))
    argv = [a for kv in {**base, **given}.items() for a in kv]
    code, _, err = run_main(capsys, "motion", "select", folder, *argv, "--out", tmp_path / "o")
    assert_one_line_error(code, err, name)
    assert not (tmp_path / "o").exists()


def test_bad_folder_target_and_period_source_are_one_line(capsys, tmp_path, folder):
    common = ("--n", "3", "--units", "m/s^2", "--out", tmp_path / "o")
    empty = tmp_path / "junk"
    empty.mkdir()
    (empty / "a.txt").write_text("not a record\n")
    cases = [
        ((tmp_path / "missing", "--target", "ec8", "--periods", "0.1:1:5"), "FOLDER"),
        ((folder / "readme.txt", "--target", "ec8", "--periods", "0.1:1:5"), "FOLDER"),
        ((empty, "--target", "ec8", "--periods", "0.1:1:5"), "FOLDER"),
        ((folder, "--target", tmp_path / "none.csv", "--periods", "0.1:1:5"), "target"),
        ((folder, "--target", "uhs", "--periods", "0.1:1:5"), "hazard"),
        ((folder, "--target", "uhs", "--hazard", tmp_path / "none.csv", "--periods",
          "0.1:1:5"), "hazard"),
        ((folder, "--target", "uhs", "--hazard", tmp_path / "none.csv", "--damping", "2%",
          "--periods", "0.1:1:5"), "damping"),
        ((folder, "--target", "ec8"), "periods"),                       # no range at all
        ((folder, "--target", "ec8", "--periods", "0.1:1:5", "--return-period", "475"),
         "return-period"),
    ]
    for args, name in cases:
        code, _, err = run_main(capsys, "motion", "select", *args, *common)
        assert_one_line_error(code, err, name)
    code, _, err = run_main(capsys, "motion", "select", folder, "--target", "ec8",
                            "--periods", "0.1:1:5", "--n", "3", "--out", folder)
    assert_one_line_error(code, err, "out")


def test_vertical_components_skipped_and_each_file_in_its_own_unit(capsys, tmp_path):
    """A folder of downloads: shipped AT2 files in g (two horizontals and the vertical
    ``UP``) and a CSV in m/s^2 that states its unit. Without --units every file is read in
    the unit it states (the CSV's samples equal the record's), the vertical component is
    skipped with the reason, and the 90 % rule still holds (EC8, --ag 0.2g, ground A)."""
    src = tmp_path / "in"
    src.mkdir()
    root = resources.files("rocking.motions") / "data" / "records"
    for name in ("three_component/RSN1158_KOCAELI_DZC180.AT2",
                 "three_component/RSN1158_KOCAELI_DZC-UP.AT2", AT2):
        (src / name.split("/")[-1]).write_bytes((root / name).read_bytes())
    rec = load_builtin("RSN948_NORTHR_CAM009")
    write_csv(rec, src / "cam009_ms2.csv")
    out = tmp_path / "out"
    code, stdout, err = run_main(capsys, "motion", "select", src, "--target", "ec8", "--ag",
                                 "0.2g", "--periods", "0.2:1.5:15", "--n", 3, "--out", out,
                                 "--no-plot", "--json")
    assert code == 0, err
    js, sel = _results(out)
    skipped = {s["file"]: s["reason"] for s in js["skipped"]}
    assert list(skipped) == ["RSN1158_KOCAELI_DZC-UP.AT2"]
    assert "vertical" in skipped["RSN1158_KOCAELI_DZC-UP.AT2"]
    assert js["candidates"] == 3 and js["compliant"] is True
    back = Record.from_file(src / "cam009_ms2.csv", units=None)
    np.testing.assert_allclose(back.acc, rec.acc, rtol=1e-12, atol=1e-12)


def _shipped(src, *names):
    root = resources.files("rocking.motions") / "data" / "records"
    for name in names:
        (src / name).write_bytes((root / name).read_bytes())


def _select(capsys, src, out, *args):
    code, stdout, err = run_main(capsys, "motion", "select", src, "--target", "ec8", "--ag",
                                 "0.2g", "--out", out, "--no-plot", *args)
    assert code == 0, err
    js, _ = _results(out)
    return js, {s["file"]: s["reason"] for s in js["skipped"]}, stdout


def test_files_without_a_unit_and_short_records_are_skipped(capsys, tmp_path):
    """Without --units a column file that states no unit is skipped (g would be a guess;
    an AT2 file is in g by the PEER convention and is read); with --units g it is read.
    A record shorter than max(5 s, 2 Tmax) is skipped: a 6 s record (stating its unit) is
    a candidate for periods up to 2.5 s (5 s needed) and not up to 4 s (8 s needed); the
    reviewer's 4-sample, 0.03 s file is never one."""
    src = tmp_path / "in"
    src.mkdir()
    _shipped(src, AT2, "RSN948_NORTHR_CAM009.AT2")
    rec = load_builtin("RSN982_NORTHR_JEN292")
    np.savetxt(src / "nounit.csv", np.column_stack([rec.t, rec.acc / G]), delimiter=",",
               header="t,acc", comments="")  # long, in g, but says nothing
    short = Record(rec.acc[:round(6.0 / rec.dt)], rec.dt, name="short")
    write_csv(short, src / "short_ms2.csv")
    (src / "tiny.csv").write_text("t,acc\n0,0.1\n0.01,0.2\n0.02,-0.1\n0.03,0.05\n")

    js, skipped, stdout = _select(capsys, src, tmp_path / "o1", "--periods", "0.2:2.5:8",
                                  "--n", "2")
    assert skipped == {"nounit.csv": "states no unit: pass --units to read such files",
                       "tiny.csv": "states no unit: pass --units to read such files"}
    assert js["candidates"] == 3  # the two AT2 files and the 6 s record (>= 5 s)
    assert "skipped     nounit.csv: states no unit" in stdout

    js, skipped, _ = _select(capsys, src, tmp_path / "o2", "--periods", "0.2:4:8", "--n", "2")
    assert js["candidates"] == 2
    assert skipped["short_ms2.csv"].startswith(f"too short: {short.duration:.4g} s, less "
                                               "than 8 s")

    # --units g: the unit-less files are read in g; short_ms2.csv states m/s^2 (refused)
    js, skipped, _ = _select(capsys, src, tmp_path / "o3", "--periods", "0.2:2.5:8", "--n",
                             "2", "--units", "g")
    assert "nounit.csv" not in skipped and js["candidates"] == 3
    assert skipped["tiny.csv"].startswith("too short: 0.03 s, less than 5 s")
    assert "m/s^2" in skipped["short_ms2.csv"]


def test_the_same_motion_in_two_files_is_noted(capsys, tmp_path):
    """A record shipped as AT2 (g) and the same motion scaled by 0.5 in a CSV (m/s^2):
    their spectra are in the constant ratio 0.5, so when both are selected a note names the
    two (in selection.json and on the terminal), and no other record; distinct records
    are not named."""
    src = tmp_path / "in"
    src.mkdir()
    _shipped(src, AT2, "RSN948_NORTHR_CAM009.AT2", "RSN183_IMPVALL.H_H-E08140.AT2")
    write_csv(load_builtin("RSN948_NORTHR_CAM009").scaled(0.5), src / "cam_copy.csv")
    js, _, stdout = _select(capsys, src, tmp_path / "o", "--periods", "0.2:1.5:10", "--n",
                            "4")
    same = [s for s in js["notes"] if "nearly identical spectra" in s]
    assert len(same) == 1
    assert "RSN948_NORTHR_CAM009.AT2" in same[0] and "cam_copy.csv" in same[0]
    assert AT2 not in same[0] and "IMPVALL" not in same[0]
    assert f"note        {same[0]}" in stdout
