"""``rocking motion floor RECORD --building ... --out DIR`` (issue 18): the floor records
written are the library's FloorMotion of the record in the catalog's building, in m/s^2
whatever units the record was read in; floors.csv is consistent with them and with the
codes' formulas (ASCE/SEI 7-22 Eq 13.3-4, EN 1998-1 Eq 4.25 for a rigid element); the
spectra are those of the written records; bad flags are one ``error:`` line, exit 2."""

from __future__ import annotations

import io
import math
from contextlib import redirect_stderr, redirect_stdout

import numpy as np
import pandas as pd
import pytest
from cli_helpers import assert_one_line_error, run_main

from rocking.buildings import FloorMotion
from rocking.buildings.catalog import make_building
from rocking.cli import main
from rocking.motions import Record, load_builtin, response_spectrum

SHEAR = ["--building", "shear", "--storeys", "4", "--building-period", "0.4",
         "--building-damping", "5%"]
SHEAR_KEYS = {"kind": "shear", "storeys": 4, "period": 0.4, "damping_ratio": 0.05}


@pytest.fixture(scope="module")
def shear_run(tmp_path_factory):
    """One run on every floor of a 4-storey shear building under Rinaldi228."""
    out = tmp_path_factory.mktemp("floors")
    buf, err = io.StringIO(), io.StringIO()
    with redirect_stdout(buf), redirect_stderr(err), pytest.raises(SystemExit) as exc:
        main(["motion", "floor", "Rinaldi228", *SHEAR, "--out", str(out)])
    assert exc.value.code == 0, err.getvalue()
    return out, buf.getvalue()


def read_floor(path) -> Record:
    return Record.from_file(path, units="m/s^2")


def test_the_written_floor_records_are_the_floor_motions(shear_run):
    out, stdout = shear_run
    ground = load_builtin("Rinaldi228")
    building = make_building(SHEAR_KEYS)
    for k in range(5):
        rec = read_floor(out / f"floor_{k}.csv")
        expected = FloorMotion(ground, building, floor=k).record
        assert rec.dt == pytest.approx(expected.dt, rel=1e-12)
        assert np.array_equal(rec.values, expected.values)  # full precision, bit for bit
    # floor 0 is the ground itself; the others ring down after it
    assert np.array_equal(read_floor(out / "floor_0.csv").values, ground.values)
    assert read_floor(out / "floor_4.csv").duration > ground.duration
    head = (out / "floor_4.csv").read_text().splitlines()[:5]
    assert "# units: m/s^2" in head and head[-1] == "t,acc"
    assert "wrote" in stdout and "floors.csv" in stdout


def test_the_summary_is_consistent_with_the_records_and_the_codes(shear_run):
    out, _ = shear_run
    table = pd.read_csv(out / "floors.csv")
    ground = load_builtin("Rinaldi228")
    T1 = 0.4
    assert list(table.floor) == [0, 1, 2, 3, 4]
    for _, r in table.iterrows():
        rec = read_floor(out / r.file)
        z = r.height_ratio
        assert z == pytest.approx(r.floor / 4, abs=1e-12)  # uniform storeys: k/N
        assert r.pga_ms2 == pytest.approx(ground.pga, rel=1e-9)
        assert r.pfa_ms2 == pytest.approx(np.max(np.abs(rec.values)), rel=1e-9)
        assert r.pfa_over_pga == pytest.approx(r.pfa_ms2 / r.pga_ms2, rel=1e-9)
        # ASCE/SEI 7-22 Eq (13.3-4), Ta = T1; EN 1998-1 Eq (4.25) at Ta = 0
        hf = 1 + min(1 / T1, 2.5) * z + max(1 - (0.4 / T1) ** 2, 0.0) * z ** 10
        assert r.asce7_hf == pytest.approx(hf, rel=1e-9)
        assert r.ec8_rigid == pytest.approx(max(3 * (1 + z) / 2 - 0.5, 1.0), rel=1e-9)
    assert table.pfa_over_pga.iloc[0] == 1.0
    # the building amplifies the motion up its height (first mode dominant)
    assert np.all(np.diff(table.pfa_ms2) > 0)


def test_the_spectra_are_those_of_the_written_records(shear_run):
    out, _ = shear_run
    spectra = pd.read_csv(out / "floor_spectra.csv")
    T = spectra.period_s.to_numpy()
    assert T[0] == pytest.approx(0.02) and T[-1] == pytest.approx(4.0) and T.size == 100
    ground = load_builtin("Rinaldi228")
    np.testing.assert_allclose(spectra.ground_psa_ms2, response_spectrum(ground, T),
                               rtol=1e-5)
    table = pd.read_csv(out / "floors.csv")
    for _, r in table.iterrows():
        col = spectra[f"floor_{r.floor}_psa_ms2"].to_numpy()
        rec = read_floor(out / r.file)
        np.testing.assert_allclose(col, response_spectrum(rec, T, damping=0.05), rtol=1e-5)
        # a stiff oscillator (0.02 s, well below the building's 0.4 s) follows the floor
        assert col[0] == pytest.approx(r.pfa_ms2, rel=0.05)
    # resonance: on the roof the spectrum peaks near the building's period
    roof = spectra["floor_4_psa_ms2"].to_numpy()
    assert 0.3 < T[np.argmax(roof)] < 0.5
    np.testing.assert_array_equal(spectra.floor_0_psa_ms2, spectra.ground_psa_ms2)


def test_pngs_are_written(shear_run):
    out, _ = shear_run
    for name in ("floor_accelerations.png", "floor_spectra.png"):
        assert (out / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_file_in_gal_gives_floor_records_in_si(capsys, tmp_path):
    """A CSV record in cm/s^2 (--units cm/s^2): the floor records are in m/s^2."""
    t = np.arange(0, 4.0, 0.005)
    acc_gal = 300.0 * np.sin(2 * np.pi * 2.5 * t) * np.exp(-t)
    src = tmp_path / "quake.csv"
    np.savetxt(src, np.column_stack([t, acc_gal]), delimiter=",", fmt="%.17g")
    code, _, err = run_main(capsys, "motion", "floor", src, "--units", "cm/s^2",
                            "--building", "sdof", "--building-period", "0.4",
                            "--floors", "1", "--no-plots", "--out", tmp_path / "o")
    assert code == 0, err
    ground = Record(acc_gal / 100.0, 0.005)
    expected = FloorMotion(ground, make_building({"kind": "sdof", "period": 0.4}),
                           floor=1).record
    got = read_floor(tmp_path / "o" / "floor_1.csv")
    np.testing.assert_allclose(got.values, expected.values, rtol=0,
                               atol=1e-12 * expected.pga)
    assert not list((tmp_path / "o").glob("*.png"))
    table = pd.read_csv(tmp_path / "o" / "floors.csv")
    assert table.pga_ms2.iloc[0] == pytest.approx(3.0 * np.max(np.abs(
        np.sin(2 * np.pi * 2.5 * t) * np.exp(-t))), rel=1e-9)


def test_height_ratios_of_a_continuous_building(capsys, tmp_path):
    code, _, err = run_main(capsys, "motion", "floor", "Rinaldi228", "--building",
                            "continuous", "--building-period", "0.8", "--building-param",
                            "stiffness_ratio=5", "--height-ratios", "1,0.5", "--tmax", "2",
                            "--n", "20", "--out", tmp_path)
    assert code == 0, err
    b = make_building({"kind": "continuous", "period": 0.8, "stiffness_ratio": 5})
    ground = load_builtin("Rinaldi228")
    table = pd.read_csv(tmp_path / "floors.csv")
    assert list(table.height_ratio) == [0.5, 1.0]  # bottom to top
    assert table.floor.isna().all()
    for x in (0.5, 1.0):
        got = read_floor(tmp_path / f"height_ratio_{x:g}.csv")
        assert np.array_equal(got.values,
                              FloorMotion(ground, b, height_ratio=x).record.values)
    spectra = pd.read_csv(tmp_path / "floor_spectra.csv")
    assert list(spectra.columns) == ["period_s", "ground_psa_ms2",
                                     "height_ratio_0.5_psa_ms2", "height_ratio_1_psa_ms2"]


def test_a_modal_building_without_heights_leaves_the_code_columns_empty(capsys, tmp_path):
    code, out, err = run_main(capsys, "motion", "floor", "Rinaldi228", "--building", "modal",
                              "--building-param", "periods=[0.6, 0.2]", "--building-param",
                              "shapes=[[0.5, 1], [1, -0.6]]", "--building-param",
                              "participation=[1.2, -0.25]", "--no-plots", "--out", tmp_path)
    assert code == 0, err
    table = pd.read_csv(tmp_path / "floors.csv")
    assert list(table.floor) == [0, 1, 2]
    assert table.height_ratio.isna().all() and table.asce7_hf.isna().all()
    assert table.ec8_rigid.isna().all() and "no z/H" in out
    assert np.all(np.isfinite(table.pfa_over_pga))


BASE = ["motion", "floor", "Rinaldi228"]


@pytest.mark.parametrize("args, name", [
    (["--storeys", "3"], "building"),
    (["--building", "tower", "--building-period", "1"], "building"),
    (["--building", "shear", "--building-period", "1"], "storeys"),
    ([*SHEAR[:4], "--building-period", "0"], "building-period"),
    ([*SHEAR[:6], "--building-damping", "0"], "building-damping"),
    ([*SHEAR, "--floors", "0,5"], "floors"),
    ([*SHEAR, "--floors", "one"], "floors"),
    ([*SHEAR, "--floors", "1,1"], "floors"),
    ([*SHEAR, "--floors", ""], "floors"),
    ([*SHEAR, "--floors", "1", "--height-ratios", "1"], "height-ratios"),
    ([*SHEAR, "--height-ratios", "0.3"], "height-ratios"),
    ([*SHEAR, "--height-ratios", "1.5"], "height-ratios"),
    ([*SHEAR, "--height-ratios", "x"], "height-ratios"),
    (["--building", "continuous", "--building-period", "1", "--building-param",
      "stiffness_ratio=5"], "height-ratios"),
    ([*SHEAR, "--damping", "150%"], "damping"),
    ([*SHEAR, "--tmin", "0"], "tmin"),
    ([*SHEAR, "--n", "1"], "n"),
    ([*SHEAR, "--units", "furlongs"], "units"),
])
def test_bad_flags(capsys, tmp_path, args, name):
    code, _, err = run_main(capsys, *BASE, *args, "--out", tmp_path / "o")
    assert_one_line_error(code, err, name)
    assert not (tmp_path / "o").exists()  # checked before anything is written


def test_bad_record_and_missing_out(capsys, tmp_path):
    code, _, err = run_main(capsys, "motion", "floor", tmp_path / "nosuch.csv", *SHEAR,
                            "--out", tmp_path / "o")
    assert_one_line_error(code, err, "record")
    code, _, err = run_main(capsys, *BASE, *SHEAR)
    assert_one_line_error(code, err, "--out")


def test_floor_zero_only(capsys, tmp_path):
    code, _, err = run_main(capsys, *BASE, *SHEAR, "--floors", "0", "--out", tmp_path)
    assert code == 0, err
    assert np.array_equal(read_floor(tmp_path / "floor_0.csv").values,
                          load_builtin("Rinaldi228").values)
    assert math.isclose(pd.read_csv(tmp_path / "floors.csv").pfa_over_pga.iloc[0], 1.0)
