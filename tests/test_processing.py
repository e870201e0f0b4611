"""Record processing (resampling, filtering, baseline correction), intensity measures, and
round trips of processed records through every file format."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rocking.errors import ParameterError, RecordError
from rocking.motions import (
    Record,
    arias_intensity,
    bandpass,
    baseline_correct,
    displacement,
    intensity_measures,
    load_builtin,
    pga,
    pgd,
    pgv,
    resample,
    response_spectrum,
    significant_duration,
    velocity,
    write_csv,
)
from rocking.motions.processing import (
    bandpass_acc,
    baseline_correct_acc,
    husid,
    integrate,
    intensity_measures_acc,
    resample_acc,
    significant_duration_acc,
)
from rocking.units import G


def sines(t):
    """A band-limited test signal (1.3 and 4.1 Hz)."""
    return np.sin(2 * np.pi * 1.3 * t) + 0.5 * np.sin(2 * np.pi * 4.1 * t + 0.3)


def noisy_record(seed=0, n=2001, dt=0.01, offset=0.05):
    rng = np.random.default_rng(seed)
    t = np.arange(n) * dt
    env = np.sin(np.pi * t / t[-1]) ** 2
    return Record(rng.standard_normal(n) * env + offset, dt, name="noise", number=7)


# ----------------------------------------------------------------------------- integration
class TestIntegration:
    def test_exact_for_piecewise_linear(self):
        dt = 0.01
        t = np.arange(101) * dt
        v, d = integrate(np.full(101, 2.0), dt)
        np.testing.assert_allclose(v, 2.0 * t, atol=1e-14)
        np.testing.assert_allclose(d, t**2, atol=1e-14)
        v, d = integrate(3.0 * t, dt)  # a = 3 t: v = 1.5 t^2, d = t^3 / 2
        np.testing.assert_allclose(v, 1.5 * t**2, atol=1e-13)
        np.testing.assert_allclose(d, 0.5 * t**3, atol=1e-13)

    def test_pgv_pgd_of_a_sine(self):
        """a = A sin(w t): v = A/w (1 - cos w t), PGV = 2A/w; d(T0) = A T0 / w."""
        A, f, dt = 2.0, 1.5, 1e-4
        w = 2 * np.pi * f
        t = np.arange(int(round(1 / f / dt)) + 1) * dt
        rec = Record(A * np.sin(w * t), dt)
        assert pgv(rec) == pytest.approx(2 * A / w, rel=1e-6)
        d_exact = A / w * (t - np.sin(w * t) / w)
        np.testing.assert_allclose(displacement(rec), d_exact, atol=1e-7 * d_exact[-1])
        assert pgd(rec) == pytest.approx(d_exact.max(), rel=1e-6)
        np.testing.assert_allclose(velocity(rec), A / w * (1 - np.cos(w * t)), atol=1e-8)
        assert pga(rec) == pytest.approx(A, rel=1e-6)

    def test_load_factor_applies(self):
        rec = noisy_record()
        r2 = rec.scaled(2.0)
        assert pgv(r2) == pytest.approx(2 * pgv(rec))
        assert arias_intensity(r2) == pytest.approx(4 * arias_intensity(rec))
        np.testing.assert_allclose(r2.displacement(), 2 * rec.displacement())


# ----------------------------------------------------------------------------- measures
class TestMeasures:
    def test_arias_of_a_sine(self):
        """Ia = pi / (2 g) * A^2 D / 2 for a sine over a whole number of cycles."""
        A, f, D, dt = 3.0, 2.0, 5.0, 1e-3
        t = np.arange(int(round(D / dt)) + 1) * dt
        rec = Record(A * np.sin(2 * np.pi * f * t), dt)
        expected = math.pi / (2 * G) * A**2 * D / 2
        # exact for the linear interpolation of the samples, which differs from the sine's
        # integral by ~(w dt)^2 / 6 = 3e-5 here
        assert arias_intensity(rec) == pytest.approx(expected, rel=1e-4)

    def test_arias_exact_for_linear_segments(self):
        rec = Record([0.0, 1.0, 1.0, 0.0], 0.5)  # integral of a^2 = 1/6 + 1/2 + 1/6
        expected = math.pi / (2 * G) * (0.5 * (1 / 3 + 1 + 1 / 3))
        assert arias_intensity(rec) == pytest.approx(expected)

    def test_significant_duration_of_a_burst(self):
        """Constant |a| from 2 to 6 s: the Husid plot is linear there, D5-95 = 0.9 * 4 s."""
        dt = 0.001
        t = np.arange(int(10 / dt) + 1) * dt
        acc = np.where((t >= 2.0) & (t <= 6.0), np.where(np.arange(t.size) % 2, 1.0, -1.0), 0.0)
        rec = Record(acc, dt)
        d, ta, tb = significant_duration(rec, return_times=True)
        assert d == pytest.approx(3.6, abs=5 * dt)
        assert ta == pytest.approx(2.2, abs=5 * dt) and tb == pytest.approx(5.8, abs=5 * dt)
        assert significant_duration(rec, 0.0, 1.0) == pytest.approx(4.0, abs=5 * dt)
        h = husid(rec)
        assert h[0] == 0.0 and h[-1] == 1.0 and np.all(np.diff(h) >= 0)

    def test_significant_duration_errors(self):
        rec = noisy_record()
        with pytest.raises(ParameterError, match="start must be < end"):
            significant_duration(rec, 0.9, 0.1)
        with pytest.raises(RecordError, match="identically zero"):
            husid(Record(np.zeros(10), 0.01))

    def test_intensity_measures(self):
        rec = load_builtin("RSN948")
        im = rec.intensity_measures()
        assert im == intensity_measures(rec)
        assert im["pga"] == pytest.approx(rec.pga)
        assert im["pga_g"] == pytest.approx(rec.pga / G)
        assert im["npts"] == len(rec) and im["dt"] == rec.dt
        assert 0.0 < im["t5"] < im["t95"] <= rec.duration
        assert im["d5_95"] == pytest.approx(im["t95"] - im["t5"])
        for k in ("pgv", "pgd", "arias"):
            assert im[k] > 0
        assert intensity_measures(Record(np.zeros(5), 0.01))["pga"] == 0.0

    def test_needs_a_record(self):
        with pytest.raises(ParameterError, match="expected a Record"):
            pgv([0.0, 1.0])


# ----------------------------------------------------------------------------- transforms
class TestBaseline:
    def test_final_velocity_and_displacement_are_zero(self):
        rec = noisy_record(offset=0.05)
        v, d = integrate(rec.acc, rec.dt)
        assert abs(v[-1]) > 0.5 and abs(d[-1]) > 1.0  # the offset makes it drift
        bc = baseline_correct(rec)
        im = bc.intensity_measures()
        assert abs(im["v_end"]) < 1e-12 * pgv(bc)
        assert abs(im["d_end"]) < 1e-12 * pgd(bc)
        # the first and last samples are not changed, the record keeps its identity
        assert bc.acc[0] == rec.acc[0] and bc.acc[-1] == rec.acc[-1]
        assert (bc.name, bc.number, bc.dt) == (rec.name, rec.number, rec.dt)
        assert "baseline" in bc.meta["processing"][-1]

    def test_short_periods_hardly_change(self):
        rec = noisy_record(offset=0.0)
        T = np.geomspace(0.05, 1.0, 20)
        np.testing.assert_allclose(response_spectrum(rec.baseline_corrected(), T),
                                   response_spectrum(rec, T), rtol=0.02)

    def test_keeps_the_load_factor(self):
        rec = noisy_record().scaled(1.5)
        bc = rec.baseline_corrected()
        assert bc.scale == 1.5
        assert abs(bc.velocity()[-1]) < 1e-12

    def test_too_short(self):
        with pytest.raises(RecordError, match="at least 4 samples"):
            baseline_correct(Record([0.0, 1.0, 0.0], 0.01))


class TestResample:
    @pytest.mark.parametrize("new_dt", [0.01, 0.0066, 0.002, 0.004])
    def test_band_limited_signal_is_preserved(self, new_dt):
        dt = 0.005
        t = np.arange(int(20 / dt) + 1) * dt
        rec = Record(sines(t), dt, name="s", number=3)
        r = resample(rec, new_dt)
        assert r.dt == new_dt and "polyphase" in r.meta["processing"][-1]
        assert r.duration <= rec.duration + 1e-12 and r.duration > rec.duration - new_dt
        inner = (r.t > 1.0) & (r.t < 19.0)  # away from the ends (zero padding)
        np.testing.assert_allclose(r.acc[inner], sines(r.t[inner]), atol=2e-3)
        assert (r.name, r.number) == ("s", 3)

    def test_linear_for_an_irrational_ratio(self):
        dt = 0.005
        t = np.arange(int(20 / dt) + 1) * dt
        rec = Record(sines(t), dt)
        new = dt * math.pi / 3
        r = rec.resampled(new)
        assert "linear" in r.meta["processing"][-1]
        inner = (r.t > 1.0) & (r.t < 19.0)
        np.testing.assert_allclose(r.acc[inner], sines(r.t[inner]), atol=5e-3)
        with pytest.raises(ParameterError, match="method='linear'"):
            resample(rec, new, method="polyphase")

    @pytest.mark.parametrize("method", ["polyphase", "linear"])
    def test_downsampling_removes_instead_of_aliasing(self, method):
        dt = 0.005
        t = np.arange(int(20 / dt) + 1) * dt
        rec = Record(sines(t) + 0.8 * np.sin(2 * np.pi * 40.0 * t), dt)
        r = resample(rec, 0.02, method=method)  # new Nyquist 25 Hz: 40 Hz would alias to 10
        inner = (r.t > 2.0) & (r.t < 18.0)
        err = np.max(np.abs(r.acc[inner] - sines(r.t[inner])))
        assert err < (0.02 if method == "polyphase" else 0.05)

    def test_same_dt_and_errors(self):
        rec = noisy_record()
        np.testing.assert_array_equal(resample(rec, rec.dt).acc, rec.acc)
        with pytest.raises(ParameterError, match="method must be"):
            resample(rec, 0.02, method="cubic")
        with pytest.raises(ParameterError, match="longer than the record"):
            resample(rec, 100.0)
        with pytest.raises(ParameterError, match="dt must be > 0"):
            resample(rec, 0.0)

    def test_real_record(self):
        rec = load_builtin("RSN126")  # dt = 0.0066 s
        r = rec.resampled(0.01)
        assert r.pga == pytest.approx(rec.pga, rel=0.1)
        T = np.geomspace(0.1, 3.0, 15)
        np.testing.assert_allclose(response_spectrum(r, T), response_spectrum(rec, T),
                                   rtol=0.03)


class TestBandpass:
    def test_pass_band_and_stop_band(self):
        dt = 0.01
        t = np.arange(int(60 / dt) + 1) * dt
        inband = np.sin(2 * np.pi * 3.0 * t)
        rec = Record(inband + np.sin(2 * np.pi * 0.02 * t) + np.sin(2 * np.pi * 40 * t), dt)
        r = bandpass(rec, 0.5, 15.0)
        inner = (t > 10) & (t < 50)
        np.testing.assert_allclose(r.acc[inner], inband[inner], atol=0.01)
        assert "band-pass" in r.meta["processing"][-1]
        hp = rec.filtered(low=0.5)
        high_part = np.sin(2 * np.pi * 40 * t[inner])
        np.testing.assert_allclose(hp.acc[inner], inband[inner] + high_part, atol=0.01)
        lp = rec.filtered(low=None, high=15.0)
        low_part = np.sin(2 * np.pi * 0.02 * t[inner])
        np.testing.assert_allclose(lp.acc[inner], inband[inner] + low_part, atol=0.01)

    def test_keep_pads_then_baseline(self):
        rec = noisy_record(offset=0.02)
        padded = rec.filtered(0.2, keep_pads=True)
        assert len(padded) > len(rec) and padded.meta["t_shift"] > 0
        r = rec.filtered(0.2).baseline_corrected()
        assert len(r) == len(rec)
        assert abs(r.velocity()[-1]) < 1e-12 and abs(r.displacement()[-1]) < 1e-12
        assert len(r.meta["processing"]) == 2

    @pytest.mark.parametrize(("kw", "words"), [
        ({"low": None, "high": None}, "give low and/or high"),
        ({"low": 60.0}, "low must be in (0, 50"),
        ({"low": 1.0, "high": 50.0}, "high must be in (0, 50"),
        ({"low": 5.0, "high": 1.0}, "low must be < high"),
        ({"order": 0}, "order must be an integer"),
    ])
    def test_errors(self, kw, words):
        with pytest.raises(ParameterError) as ei:
            bandpass(noisy_record(), **kw)
        assert words in str(ei.value)



# ----------------------------------------------------------------------------- array forms
class TestArrayForms:
    """The array functions are the work; the record functions and methods wrap them."""

    def test_same_numbers_as_the_record_forms(self):
        rec = noisy_record().scaled(1.3)
        for arr, r in [
            (resample_acc(rec.acc, rec.dt, 0.02), resample(rec, 0.02)),
            (resample_acc(rec.acc, rec.dt, 0.013, method="linear"),
             rec.resampled(0.013, method="linear")),
            (bandpass_acc(rec.acc, rec.dt, 0.2, 20.0), bandpass(rec, 0.2, 20.0)),
            (bandpass_acc(rec.acc, rec.dt, 0.2, keep_pads=True), rec.filtered(0.2, keep_pads=True)),
            (baseline_correct_acc(rec.acc, rec.dt), rec.baseline_corrected()),
        ]:
            np.testing.assert_array_equal(arr, r.acc)
            assert r.scale == rec.scale and r.name == rec.name
        im = intensity_measures_acc(rec.values, rec.dt)
        assert im == intensity_measures(rec) == rec.intensity_measures()
        assert significant_duration_acc(rec.values, rec.dt) == significant_duration(
            rec, return_times=True)

    def test_array_errors(self):
        with pytest.raises(RecordError, match="1-D array"):
            resample_acc(np.zeros((3, 3)), 0.01, 0.02)
        with pytest.raises(RecordError, match="non-finite"):
            bandpass_acc([0.0, np.nan, 0.0], 0.01, 1.0)
        with pytest.raises(ParameterError, match="dt must be > 0"):
            baseline_correct_acc(np.zeros(10), 0.0)

    def test_transforms_keep_the_record_class(self):
        class Tagged(Record):
            pass

        rec = Tagged(noisy_record().acc, 0.01, name="tagged")
        for r in (resample(rec, 0.02), rec.filtered(0.2), baseline_correct(rec)):
            assert type(r) is Tagged and r.name == "tagged"


# ----------------------------------------------------------------------------- file formats
def write_at2(rec: Record, path):
    """A PEER NGA .AT2 file of ``rec`` in g (5 values a line, E format)."""
    vals = rec.values / G
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD",
             f"{rec.name or 'synthetic'}, 2007, ROCKING, 000",
             "ACCELERATION TIME SERIES IN UNITS OF G",
             f"NPTS= {vals.size:7d}, DT= {rec.dt:.5f} SEC"]
    for i in range(0, vals.size, 5):
        lines.append("".join(f"{v:16.8E}" for v in vals[i:i + 5]))
    path.write_text("\n".join(lines) + "\n")
    return path


class TestRoundTrips:
    @pytest.fixture()
    def rec(self):
        return noisy_record(offset=0.0).filtered(0.2, 20.0).baseline_corrected().scaled(1.3)

    def test_csv(self, rec, tmp_path):
        p = write_csv(rec, tmp_path / "r.csv")
        back = Record.from_file(p, units="m/s^2")
        np.testing.assert_array_equal(back.acc, rec.values)
        assert back.dt == rec.dt
        text = p.read_text()
        assert "# units: m/s^2" in text and f"# dt = {rec.dt!r} s" in text

    def test_at2(self, rec, tmp_path):
        back = Record.from_file(write_at2(rec, tmp_path / "r.AT2"))
        np.testing.assert_allclose(back.acc, rec.values, rtol=1e-7, atol=1e-9)
        assert back.dt == pytest.approx(rec.dt)

    def test_one_column_with_dt_header_in_gal(self, rec, tmp_path):
        p = tmp_path / "r.txt"
        np.savetxt(p, rec.values * 100.0, fmt="%.17g",
                   header=f"units: cm/s^2\ndt = {rec.dt!r} s")
        back = Record.from_file(p, units="cm/s^2")
        np.testing.assert_allclose(back.acc, rec.values, rtol=1e-15)
        assert back.dt == rec.dt

    def test_two_whitespace_columns_in_g(self, rec, tmp_path):
        p = tmp_path / "r.dat"
        np.savetxt(p, np.column_stack([rec.t, rec.values / G]), fmt="%.17g")
        back = Record.from_file(p, units="g")
        np.testing.assert_allclose(back.acc, rec.values, rtol=1e-14, atol=1e-15)
        assert back.dt == pytest.approx(rec.dt, rel=1e-9)

    def test_processing_survives_the_round_trip(self, rec, tmp_path):
        back = Record.from_file(write_csv(rec, tmp_path / "r.csv"), units="m/s^2")
        im_a, im_b = rec.intensity_measures(), back.intensity_measures()
        for k in ("pga", "pgv", "pgd", "arias", "d5_95"):
            assert im_b[k] == pytest.approx(im_a[k], rel=1e-12)

    @pytest.mark.parametrize(("text", "line", "words"), [
        ("t,acc\n0,0\n0.01,nan\n0.02,0\n", 3, "NaN"),
        ("t,acc\n0,0\n0.01,1\n0.025,0\n0.035,1\n", 4, "uneven time step"),
        ("t,acc\n0,0\n0.01,abc\n", 3, "non-numeric"),
    ])
    def test_malformed_csv_names_file_and_line(self, tmp_path, text, line, words):
        p = tmp_path / "bad.csv"
        p.write_text(text)
        with pytest.raises(RecordError) as ei:
            Record.from_file(p, units="m/s^2")
        msg = str(ei.value)
        assert str(p) in msg and f"line {line}" in msg and words in msg

    def test_malformed_at2_and_empty(self, tmp_path):
        p = tmp_path / "bad.AT2"
        p.write_text("PEER\nx\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=, DT= SEC\n1 2\n")
        with pytest.raises(RecordError, match=r"bad\.AT2, line 4: not a valid PEER"):
            Record.from_file(p)
        e = tmp_path / "empty.csv"
        e.write_text("")
        with pytest.raises(RecordError, match=r"empty\.csv: the file is empty"):
            Record.from_file(e, units="m/s^2")
