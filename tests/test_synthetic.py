"""Synthetic spectrum-compatible records and the paper's set of 30 earthquakes."""

from __future__ import annotations

import importlib

import numpy as np
import pytest

from rocking.errors import ParameterError
from rocking.motions import (
    DesignSpectrum,
    Envelope,
    Record,
    check_compatibility,
    earthquake_motion,
    paper_earthquake,
    paper_target,
    seed_earthquakes,
    synthetic,
)
from rocking.motions.processing import integrate

# (``import rocking.motions.synthetic as S`` would give the function of that name)
S = importlib.import_module("rocking.motions.synthetic")


class TestPaperSet:
    def test_thirty_numbered_records(self, paper_set):
        assert len(paper_set) == 30
        assert [r.number for r in paper_set] == list(range(1, 31))
        for r in paper_set:
            assert isinstance(r, Record)
            assert r.dt == 0.01 and r.duration == pytest.approx(20.0)
            assert r.meta["seed"] == S.PAPER_SEED
            assert r.meta["stationary"] == (2.0, 12.0)
            assert 1.5 < r.pga < 4.5  # m/s^2, around the target PGA of 2.8 m/s^2

    def test_ec8_compatibility(self, paper_set):
        c = check_compatibility(paper_set)
        assert c.passed, c.summary()
        assert c.checks == {"stationary": True, "pga": True, "spectrum": True}
        assert c.min_stationary >= 10.0
        assert c.mean_pga >= 2.8
        assert c.min_ratio >= 0.9  # EC8's criterion ...
        assert 0.95 <= c.min_ratio and c.max_ratio <= 1.08  # ... and how well we do
        assert c.period_range == (0.05, 3.0)
        assert c.periods.min() <= 0.05 and c.periods.max() >= 3.0

    def test_each_record_is_close_to_the_target(self, paper_set):
        dev = check_compatibility(paper_set).record_deviation()
        assert dev.max() < 0.2
        assert np.median(dev) < 0.12

    def test_table_returns_to_rest_and_fits_a_stroke(self, paper_set):
        for r in paper_set:
            v, d = integrate(r.values, r.dt)
            assert abs(v[-1]) < 1e-10 and abs(d[-1]) < 1e-10
            assert r.acc[0] == 0.0 and abs(r.acc[-1]) < 1e-9
            assert np.max(np.abs(d)) < 0.10  # m: a +-100 mm table stroke
        pgd = [r.intensity_measures()["pgd"] for r in paper_set]
        assert np.mean(pgd) < 0.06

    def test_memory_and_disk_cache(self, paper_set, paper_cache, monkeypatch):
        assert seed_earthquakes()[5] is paper_set[5]  # the in-memory cache
        files = list(paper_cache.glob("paper_earthquakes_*.npz"))
        assert len(files) == 1
        S.clear_cache()

        def no_generation():
            raise AssertionError("the records were generated again instead of read")

        monkeypatch.setattr(S, "_generate_paper", no_generation)
        again = seed_earthquakes()  # from disk
        for a, b in zip(again, paper_set, strict=True):
            np.testing.assert_array_equal(a.acc, b.acc)
            assert a.number == b.number and a.meta == b.meta

    def test_same_seed_same_records(self, paper_set):
        """The cache is only a speed-up: regenerating gives the same records."""
        one = synthetic(paper_target(), n=1, seed=S.PAPER_SEED, first_number=20)[0]
        np.testing.assert_allclose(one.acc, paper_set[19].acc, rtol=0, atol=1e-12)
        assert one.number == 20
        two = synthetic(paper_target(), n=1, seed=S.PAPER_SEED, first_number=20)[0]
        np.testing.assert_array_equal(one.acc, two.acc)
        other = synthetic(paper_target(), n=1, seed=S.PAPER_SEED + 1, first_number=20)[0]
        assert np.max(np.abs(other.acc - one.acc)) > 0.5

    def test_corrupt_or_unwritable_cache(self, paper_set, paper_cache, monkeypatch):
        calls = []

        def fake():
            calls.append(1)
            return tuple(paper_set)

        monkeypatch.setattr(S, "_generate_paper", fake)
        path = S._cache_file()
        path.write_bytes(b"not an npz file")
        S.clear_cache()
        assert seed_earthquakes()[0].number == 1 and calls == [1]  # regenerated, rewritten
        S.clear_cache()
        seed_earthquakes()
        assert calls == [1]  # the rewritten file was good
        blocker = paper_cache / "a-file"
        blocker.write_text("")
        monkeypatch.setenv("ROCKING_CACHE_DIR", str(blocker / "sub"))  # cannot be created
        S.clear_cache()
        assert len(seed_earthquakes()) == 30 and calls == [1, 1]
        S.clear_cache()

    def test_paper_earthquake_and_motion(self, paper_set):
        np.testing.assert_array_equal(paper_earthquake(20).acc, paper_set[19].acc)
        assert paper_earthquake(20).number == 20
        assert paper_earthquake("18").number == 18
        m = earthquake_motion(20, 1.1)
        assert m.scale == pytest.approx(1.1) and m.number == 20
        np.testing.assert_allclose(m.values, 1.1 * paper_set[19].acc)
        assert m.pga == pytest.approx(1.1 * paper_set[19].pga)
        assert earthquake_motion(3).scale == 1.0 and earthquake_motion(3).number == 3

    @pytest.mark.parametrize("n", [0, 31, 2.5, "x", None, True])
    def test_bad_numbers(self, paper_set, n):
        with pytest.raises(ParameterError, match="from 1 to 30"):
            paper_earthquake(n)

    @pytest.mark.parametrize("f", [0.0, -1.0, float("nan"), "a"])
    def test_bad_load_factor(self, paper_set, f):
        with pytest.raises(ParameterError, match="load_factor"):
            earthquake_motion(1, f)


class TestSynthetic:
    def test_custom_ec8_target_and_trapezoidal_envelope(self):
        target = DesignSpectrum.ec8(0.2 * 9.81, ground="B", spectrum_type=1)
        env = Envelope("trapezoidal", rise=3.0, stationary=12.0, duration=25.0)
        recs = synthetic(target, n=3, seed=5, envelope=env)
        assert [r.number for r in recs] == [1, 2, 3]
        assert all(r.duration == pytest.approx(25.0) for r in recs)
        c = check_compatibility(recs, target)
        assert c.passed, c.summary()
        assert c.min_stationary == pytest.approx(12.0)

    def test_callable_target_and_period_range(self):
        def flat(T):
            return np.where(np.asarray(T) == 0.0, 2.0, 4.0)

        recs = synthetic(flat, n=2, duration=15.0, seed=1, period_range=(0.1, 2.0),
                         first_number=7)
        assert [r.number for r in recs] == [7, 8]
        c = check_compatibility(recs, flat, period_range=(0.1, 2.0))
        assert c.checks["spectrum"], c.summary()

    def test_set_pga_scaling(self):
        """The mean PGA of a call reaches the target's zero-period value."""
        low_pga = DesignSpectrum(pga=1.0, plateau=7.0, tb=0.1, tc=0.3, td=1.2)
        recs = synthetic(low_pga, n=2, seed=3, iterations=(3, 3))
        assert np.mean([r.pga for r in recs]) >= 1.0
        high_pga = DesignSpectrum(pga=6.5, plateau=7.0, tb=0.1, tc=0.3, td=1.2)
        recs = synthetic(high_pga, n=2, seed=3, iterations=(3, 3))
        assert np.mean([r.pga for r in recs]) == pytest.approx(6.5)
        assert recs[0].meta["pga_factor"] > 1.0

    @pytest.mark.parametrize(("kw", "words"), [
        ({"n": 0}, "n must be an integer >= 1"),
        ({"seed": -1}, "seed must be an integer >= 0"),
        ({"envelope": "boxcar"}, "envelope must be one of"),
        ({"dt": 0.05}, "too coarse"),
        ({"duration": 4.0}, "duration must be > rise + stationary"),
        ({"period_range": (2.0, 1.0)}, "0 < low < high"),
        ({"iterations": (0, 5)}, "iterations"),
        ({"target": 3.0}, "target must be"),
        ({"target": lambda T: -np.ones_like(T)}, "target must return"),
        ({"envelope": Envelope(duration=30.0), "duration": 20.0}, "disagrees"),
    ])
    def test_errors(self, kw, words):
        with pytest.raises(ParameterError) as ei:
            synthetic(**kw)
        assert words in str(ei.value)


class TestEnvelope:
    def test_jennings(self):
        e = Envelope()
        t = np.linspace(0.0, 20.0, 2001)
        v = e(t)
        assert v[0] == 0.0 and v[-1] == 0.0
        assert e(1.0) == pytest.approx(0.25)
        assert np.all(e(np.linspace(2.0, 12.0, 50)) == 1.0)
        assert np.all(np.diff(v[t > 12.0]) < 0)
        assert np.all(np.diff(v[t < 2.0]) > 0)
        assert "stationary 2-12 s (10 s)" in e.describe()

    def test_trapezoidal(self):
        e = Envelope("trapezoidal", rise=1.0, stationary=10.0, duration=15.0)
        np.testing.assert_allclose(e([0.0, 0.5, 1.0, 11.0, 13.0, 15.0]),
                                   [0.0, 0.5, 1.0, 1.0, 0.5, 0.0])

    @pytest.mark.parametrize(("kw", "words"), [
        ({"kind": "x"}, "envelope must be one of"),
        ({"rise": 0.0}, "rise must be > 0"),
        ({"stationary": 19.0}, "duration must be >"),
        ({"decay": -1.0}, "decay must be > 0"),
    ])
    def test_errors(self, kw, words):
        with pytest.raises(ParameterError) as ei:
            Envelope(**kw)
        assert words in str(ei.value)


class TestCompatibilityCheck:
    def test_failures_are_reported(self, paper_set):
        weak = [r.scaled(0.85) for r in paper_set[:5]]
        c = check_compatibility(weak)
        assert not c.passed
        assert not c.checks["spectrum"] and not c.checks["pga"]
        assert "FAIL" in c.summary()

    def test_real_records_have_unknown_stationary_part(self):
        from rocking.motions import load_builtin

        c = check_compatibility([load_builtin("RSN948")])
        assert c.checks["stationary"] is None
        assert "unknown" in c.summary()

    def test_needs_records(self):
        with pytest.raises(ParameterError, match="at least one record"):
            check_compatibility([])


# ----------------------------------------------------------------------------- CLI, report
class TestSynthCommand:
    def test_paper_records(self, paper_set, tmp_path):
        from click.testing import CliRunner

        from rocking.cli.motion import motion

        out = tmp_path / "q"
        res = CliRunner().invoke(motion, ["synth", "--count", "3", "--out", str(out)])
        assert res.exit_code == 0, res.output
        assert "the paper's set" in res.output and "PGD" in res.output
        for k in (1, 2, 3):
            back = Record.from_file(out / f"earthquake_{k:02d}.csv", units="m/s^2")
            np.testing.assert_array_equal(back.acc, paper_set[k - 1].acc)
            assert back.dt == 0.01
            assert (out / f"earthquake_{k:02d}_spectrum.png").stat().st_size > 10_000
            header = (out / f"earthquake_{k:02d}.csv").read_text().splitlines()[:3]
            assert header[1] == "# units: m/s^2" and header[2] == "# dt = 0.01 s"
        assert (out / "spectra.png").exists() and (out / "compatibility.txt").exists()
        import pandas as pd

        summary = pd.read_csv(out / "summary.csv")
        assert list(summary["number"]) == [1, 2, 3]
        np.testing.assert_allclose(summary["pga_ms2"], [r.pga for r in paper_set[:3]],
                                   rtol=1e-5)

    def test_custom_ec8_set_without_plots(self, tmp_path):
        from click.testing import CliRunner

        from rocking.cli.motion import motion

        out = tmp_path / "c"
        res = CliRunner().invoke(motion, ["synth", "--count", "2", "--seed", "4", "--ag",
                                          "0.25g", "--ground", "c", "--type", "1",
                                          "--duration", "15s", "--no-plots", "--out", str(out)])
        assert res.exit_code == 0, res.output
        assert "EC8 Type 1, ground C" in res.output
        assert sorted(p.name for p in out.glob("earthquake_*")) == ["earthquake_01.csv",
                                                                    "earthquake_02.csv"]
        assert Record.from_file(out / "earthquake_02.csv", units="m/s^2").duration == 15.0

    @pytest.mark.parametrize(("args", "words"), [
        (["--count", "0"], "count must be in 1..1000"),
        (["--seed", "-3"], "seed must be >= 0"),
        (["--ground", "C"], "--ground/--type need --ag"),
        (["--dt", "0.05"], "too coarse"),
        (["--ag", "0.3"], "ag needs an acceleration unit"),
    ])
    def test_errors(self, tmp_path, args, words):
        from click.testing import CliRunner

        from rocking.cli.motion import motion
        from rocking.errors import RockingError

        res = CliRunner().invoke(motion, ["synth", "--out", str(tmp_path), *args])
        assert isinstance(res.exception, RockingError), res.output
        assert words in str(res.exception)


class TestReportSections:
    def test_table5_compute(self, paper_set):
        from rocking.report.sections.earthquakes import table5_compute

        res = table5_compute(quick=True, models=["housner"])
        rows = res["rows"]
        assert list(rows["specimen"]) == [2, 3, 4]
        assert np.all(rows["dynamic_deg"] > 0.5 * rows["alpha_E_deg"])
        assert np.all(rows["runs"] == res["n_records"] * res["ladder"].size)
        assert np.all(rows["runs_overturned"] > 0)
        # no surviving run above its own dynamic critical angle
        runs = res["runs"]
        for spec, dyn in zip(rows["specimen"], rows["dynamic_deg"], strict=True):
            r = runs[(runs["specimen"] == spec) & ~runs["overturned"]]
            assert r["max_abs_theta_deg"].max() == pytest.approx(dyn)

    def test_spectra_section(self, paper_set, tmp_path):
        import pandas as pd

        from rocking.report import reproduce

        index = reproduce(tmp_path, quick=True, progress=False, only=["earthquakes"])
        html = index.read_text()
        assert "EN 1998-1 §3.2.3.1.2" in html and "TD = 1.2 s" in html
        spec = pd.read_csv(tmp_path / "earthquakes_spectra.csv")
        inside = spec[(spec.period_s >= 0.05) & (spec.period_s <= 3.0)]
        assert (inside.mean_ms2 / inside.target_ms2).min() >= 0.9
        recs = pd.read_csv(tmp_path / "earthquakes_records.csv")
        assert len(recs) == 30 and recs["pgd"].max() < 0.1
