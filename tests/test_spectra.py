"""Elastic response spectra: the exact piecewise-linear recurrence against closed forms,
scipy's linear systems and ODE solvers, and pyrotd (frequency domain) if it is installed."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import signal
from scipy.integrate import solve_ivp

from rocking.errors import ParameterError, RecordError
from rocking.motions import Record, Sine, response_spectra, response_spectrum, sdof_response
from rocking.motions.spectra import MIN_STEPS_PER_PERIOD, log_periods


def sine_response(t, A, Omega, T, zeta):
    """Closed-form u(t) of u'' + 2 zeta w u' + w^2 u = -A sin(Omega t) from rest.

    Steady state C sin + D cos (Chopra §3.2) plus the transient that meets u(0) = u'(0) = 0.
    """
    w = 2 * np.pi / T
    wd = w * np.sqrt(1 - zeta**2)
    r = Omega / w
    den = (1 - r**2) ** 2 + (2 * zeta * r) ** 2
    p0k = -A / w**2
    C = p0k * (1 - r**2) / den
    D = p0k * (-2 * zeta * r) / den
    E1 = -D
    E2 = (zeta * w * E1 - C * Omega) / wd
    return (C * np.sin(Omega * t) + D * np.cos(Omega * t)
            + np.exp(-zeta * w * t) * (E1 * np.cos(wd * t) + E2 * np.sin(wd * t)))


def lsim_response(acc, dt, T, zeta):
    """u, u' by scipy.signal.lsim with linear interpolation of the input (exact for it)."""
    w = 2 * np.pi / T
    sys = signal.StateSpace([[0.0, 1.0], [-w * w, -2 * zeta * w]], [[0.0], [-1.0]],
                            [[1.0, 0.0]], [[0.0]])
    t = np.arange(acc.size) * dt
    _, _, x = signal.lsim(sys, acc, t, interp=True)
    return x[:, 0], x[:, 1]


@pytest.fixture(scope="module")
def noise():
    rng = np.random.default_rng(42)
    acc = rng.standard_normal(1501)
    acc[[0, -1]] = 0.0  # a record is zero after its last sample: end there without a jump
    return acc, 0.01


class TestClosedForm:
    @pytest.mark.parametrize(("T", "f", "zeta"), [(0.5, 2.0, 0.05), (0.2, 2.0, 0.02),
                                                  (1.0, 0.7, 0.10), (0.3, 5.0, 0.0)])
    def test_sine_history(self, T, f, zeta):
        dt, A = 0.0005, 3.0
        t = np.arange(int(8.0 / dt) + 1) * dt
        acc = A * np.sin(2 * np.pi * f * t)
        h = sdof_response(acc, T, zeta, dt=dt)
        u = sine_response(t, A, 2 * np.pi * f, T, zeta)
        # the recurrence is exact for the linear interpolation of the samples; the sine
        # differs from it by O((Omega dt)^2 / 8) ~ 5e-5 here
        assert np.max(np.abs(h["u"] - u)) < 2e-4 * np.max(np.abs(u))

    def test_sine_spectrum_value(self):
        dt, A, f, T, zeta = 0.001, 2.0, 1.5, 0.6, 0.05
        t = np.arange(int(10.0 / dt) + 1) * dt
        acc = A * np.sin(2 * np.pi * f * t)
        tf = np.linspace(0.0, 10.0 + 2 * T, 400_001)
        u = sine_response(tf, A, 2 * np.pi * f, T, zeta)
        # after the record the oscillator rings freely: continue analytically from t = 10 s
        w = 2 * np.pi / T
        wd = w * math.sqrt(1 - zeta**2)
        i_end = np.searchsorted(tf, 10.0)
        u0 = sine_response(np.array([10.0]), A, 2 * np.pi * f, T, zeta)[0]
        eps = 1e-7
        v0 = (sine_response(np.array([10.0 + eps]), A, 2 * np.pi * f, T, zeta)[0]
              - sine_response(np.array([10.0 - eps]), A, 2 * np.pi * f, T, zeta)[0]) / (2 * eps)
        s = tf[i_end:] - 10.0
        u[i_end:] = np.exp(-zeta * w * s) * (u0 * np.cos(wd * s)
                                             + (v0 + zeta * w * u0) / wd * np.sin(wd * s))
        expected = w * w * np.max(np.abs(u))
        got = response_spectrum(acc, T, zeta, dt=dt)
        assert got == pytest.approx(expected, rel=5e-4)

    def test_resonant_steady_state(self):
        """A long resonant sine: the amplitude tends to A / (2 zeta w^2), psa to A / (2 zeta)."""
        dt, A, T, zeta = 0.002, 1.0, 0.5, 0.05
        t = np.arange(int(60.0 / dt) + 1) * dt
        acc = A * np.sin(2 * np.pi / T * t)
        assert response_spectrum(acc, T, zeta, dt=dt) == pytest.approx(
            A / (2 * zeta), rel=2e-3)


class TestIndependentIntegration:
    @pytest.mark.parametrize("T", [0.05, 0.2, 1.0, 3.0, 40.0])
    def test_history_matches_lsim(self, noise, T):
        acc, dt = noise
        u, v = lsim_response(acc, dt, T, 0.05)
        h = sdof_response(acc, T, 0.05, dt=dt)
        scale = np.max(np.abs(u))
        assert np.max(np.abs(h["u"] - u)) < 1e-9 * scale
        assert np.max(np.abs(h["v"] - v)) < 1e-9 * np.max(np.abs(v))
        w = 2 * np.pi / T
        np.testing.assert_allclose(h["a"], -(2 * 0.05 * w * v + w * w * u),
                                   atol=1e-9 * w * w * scale)

    def test_spectrum_matches_lsim_with_zero_padding(self, noise):
        """Periods with no sub-steps: the spectrum is the max over the samples plus one
        period of free vibration, which lsim gives on the zero-padded record."""
        acc, dt = noise
        T = np.array([0.2, 0.35, 0.8, 1.7, 3.0])
        assert np.all(T >= MIN_STEPS_PER_PERIOD * dt)
        got = response_spectra(acc, T, 0.05, dt=dt)
        for i, Ti in enumerate(T):
            ntail = int(np.ceil(Ti / dt / math.sqrt(1 - 0.05**2))) + 1
            padded = np.concatenate([acc, np.zeros(ntail)])
            u, v = lsim_response(padded, dt, Ti, 0.05)
            w = 2 * np.pi / Ti
            assert got["sd"][i] == pytest.approx(np.max(np.abs(u)), rel=1e-9)
            assert got["psa"][i] == pytest.approx(w * w * np.max(np.abs(u)), rel=1e-9)
            assert got["sv"][i] == pytest.approx(np.max(np.abs(v)), rel=1e-9)
            assert got["sa"][i] == pytest.approx(
                np.max(np.abs(2 * 0.05 * w * v + w * w * u)), rel=1e-9)

    def test_short_period_substeps_are_exact(self, noise):
        """T < 20 dt is integrated with sub-steps; linear interpolation of the record onto the
        sub-step grid and lsim there must give the same peak."""
        acc, dt = noise
        T = 0.03  # 20 dt / T = 6.67 -> 7 sub-steps
        m = int(np.ceil(MIN_STEPS_PER_PERIOD * dt / T))
        fine_t = np.arange((acc.size - 1) * m + 1) * dt / m
        fine = np.interp(fine_t, np.arange(acc.size) * dt, acc)
        ntail = int(np.ceil(T / (dt / m) / math.sqrt(1 - 0.05**2))) + 1
        u, _ = lsim_response(np.concatenate([fine, np.zeros(ntail)]), dt / m, T, 0.05)
        assert response_spectrum(acc, T, dt=dt, kind="sd") == pytest.approx(
            np.max(np.abs(u)), rel=1e-9)

    def test_white_noise_against_solve_ivp(self, noise):
        acc, dt = noise
        acc = acc[:201].copy()  # 2 s are enough (and keep the test fast)
        t = np.arange(acc.size) * dt

        def ag(tt):
            return np.interp(tt, t, acc)

        for T in (0.3, 1.0):
            w = 2 * np.pi / T
            sol = solve_ivp(lambda tt, y, w=w: [y[1], -2 * 0.05 * w * y[1] - w * w * y[0]
                                                - ag(tt)],
                            (0.0, t[-1]), [0.0, 0.0], t_eval=t, method="DOP853",
                            rtol=1e-11, atol=1e-13, max_step=dt)
            h = sdof_response(acc, T, 0.05, dt=dt)
            # (DOP853 steps across the kinks of the input at the samples: ~1e-7 accuracy)
            assert np.max(np.abs(h["u"] - sol.y[0])) < 1e-6 * np.max(np.abs(sol.y[0]))


class TestPyrotd:
    def test_band_limited_noise(self):
        pyrotd = pytest.importorskip("pyrotd")
        rng = np.random.default_rng(3)
        dt, n = 0.005, 4001
        sos = signal.butter(8, [0.2, 10.0], btype="bandpass", fs=1 / dt, output="sos")
        acc = signal.sosfiltfilt(sos, rng.standard_normal(n)) * np.hanning(n)
        T = np.geomspace(0.05, 4.0, 60)
        ours = response_spectrum(acc, T, 0.05, dt=dt)
        # pyrotd works in the frequency domain (circular): pad with zeros
        padded = np.concatenate([acc, np.zeros(16 * n)])
        theirs = pyrotd.calc_spec_accels(dt, padded, 1 / T, 0.05).spec_accel
        np.testing.assert_allclose(ours, theirs, rtol=0.02)


class TestProperties:
    def test_zero_period_is_pga_and_kinds_agree(self, noise):
        acc, dt = noise
        T = np.array([0.0, 0.1, 1.0])
        s = response_spectra(acc, T, 0.05, dt=dt)
        assert s["psa"][0] == s["sa"][0] == np.max(np.abs(acc))
        assert s["sd"][0] == s["psv"][0] == s["sv"][0] == 0.0
        w = 2 * np.pi / T[1:]
        np.testing.assert_allclose(s["psv"][1:], w * s["sd"][1:])
        np.testing.assert_allclose(s["psa"][1:], w * w * s["sd"][1:])

    def test_undamped_pseudo_equals_absolute(self, noise):
        acc, dt = noise
        T = [0.1, 0.5, 2.0]
        s = response_spectra(acc, T, 0.0, dt=dt)
        np.testing.assert_allclose(s["sa"], s["psa"], rtol=1e-12)

    def test_record_load_factor_and_linearity(self, noise):
        acc, dt = noise
        rec = Record(acc, dt)
        T = log_periods(0.05, 3.0, 20)
        base = response_spectrum(rec, T)
        np.testing.assert_allclose(response_spectrum(rec.scaled(2.5), T), 2.5 * base,
                                   rtol=1e-12)
        np.testing.assert_allclose(response_spectrum(-rec, T), base, rtol=1e-12)
        np.testing.assert_allclose(rec.response_spectrum(T), base)

    def test_shape_and_scalar(self, noise):
        acc, dt = noise
        assert isinstance(response_spectrum(acc, 0.5, dt=dt), float)
        assert response_spectrum(acc, [[0.1, 0.2], [0.3, 0.4]], dt=dt).shape == (2, 2)

    def test_log_periods(self):
        p = log_periods(0.02, 4.0, 200)
        assert p.size == 200 and p[0] == pytest.approx(0.02) and p[-1] == pytest.approx(4.0)
        with pytest.raises(ParameterError):
            log_periods(1.0, 0.5)

    @pytest.mark.parametrize(("args", "kw", "exc", "words"), [
        (([0.0, 1.0], [0.1]), {}, ParameterError, "dt (s) is required"),
        (([0.0, 1.0], [-0.1]), {"dt": 0.01}, ParameterError, "periods must be finite"),
        (([0.0, 1.0], []), {"dt": 0.01}, ParameterError, "must not be empty"),
        (([0.0, 1.0], [0.1]), {"dt": 0.01, "damping": 1.0}, ParameterError, "damping"),
        (([0.0, 1.0], [0.1]), {"dt": 0.01, "kind": "pga"}, ParameterError, "kind must be"),
        (([0.0, np.nan], [0.1]), {"dt": 0.01}, RecordError, "non-finite"),
        (([0.0], [0.1]), {"dt": 0.01}, RecordError, "at least 2 samples"),
        ((Sine(1.0, 0.01, 2.0), [0.1]), {}, ParameterError, "sample it first"),
    ])
    def test_errors(self, args, kw, exc, words):
        with pytest.raises(exc) as ei:
            response_spectrum(*args, **kw)
        assert words in str(ei.value)

    def test_dt_of_a_record_must_agree(self):
        with pytest.raises(ParameterError, match="leave dt out"):
            response_spectrum(Record([0.0, 1.0, 0.0], 0.01), [0.1], dt=0.02)

    # the speed of 200-period spectra is measured by benchmarks/bench_motions.py


class TestSpectrumCommand:
    AT2 = "RSN948_NORTHR_CAM009.AT2"

    @pytest.fixture()
    def at2(self, records_dir):
        return records_dir / self.AT2

    def test_table_and_plot(self, at2, tmp_path):
        from click.testing import CliRunner

        from rocking.cli.motion import motion
        from rocking.motions import Record

        png = tmp_path / "s.png"
        res = CliRunner().invoke(motion, ["spectrum", str(at2), "--n", "5",
                                          "--tmin", "0.1", "--tmax", "2", "--plot", str(png),
                                          "--target", "paper"])
        assert res.exit_code == 0, res.output
        lines = res.output.splitlines()
        rows = [ln.split() for ln in lines if ln.strip() and ln.split()[0][0].isdigit()]
        assert len(rows) == 5
        T = np.array([float(r[0]) for r in rows])
        psa = np.array([float(r[1]) for r in rows])
        rec = Record.from_file(at2)
        np.testing.assert_allclose(psa, response_spectrum(rec, T), rtol=1e-3)
        assert png.stat().st_size > 10_000
        assert "PGA" in res.output and "D5-95" in res.output

    def test_json_no_plot_and_damping(self, at2, tmp_path):
        import json

        from click.testing import CliRunner

        from rocking.cli.motion import motion

        res = CliRunner().invoke(motion, ["spectrum", str(at2), "--json",
                                          "--no-plot", "--damping", "2%", "--n", "4"])
        assert res.exit_code == 0, res.output
        d = json.loads(res.output)
        assert d["damping"] == 0.02 and len(d["psa_ms2"]) == 4
        assert d["intensity_measures"]["pga"] > 0

    def test_csv_with_units_and_errors(self, tmp_path):
        from click.testing import CliRunner

        from rocking.cli.motion import motion
        from rocking.errors import RockingError

        good = tmp_path / "r.csv"
        t = np.arange(501) * 0.01
        np.savetxt(good, np.column_stack([t, 100 * np.sin(2 * np.pi * 2 * t)]), delimiter=",",
                   header="t,acc", comments="")
        res = CliRunner().invoke(motion, ["spectrum", str(good), "--units", "cm/s^2",
                                          "--no-plot", "--n", "3"])
        assert res.exit_code == 0, res.output
        bad = tmp_path / "bad.csv"
        bad.write_text("t,acc\n0,0\n0.01,nan\n")
        res = CliRunner().invoke(motion, ["spectrum", str(bad), "--units", "m/s^2"])
        assert isinstance(res.exception, RockingError)
        assert "bad.csv, line 3" in str(res.exception)
        res = CliRunner().invoke(motion, ["spectrum", str(good), "--damping", "150%"])
        assert isinstance(res.exception, RockingError)
        assert "damping" in str(res.exception)
