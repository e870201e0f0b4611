"""Analytical base motions: harmonic table motions and idealised pulses.

The checks are physical: a harmonic motion's acceleration is the second derivative of the
table displacement it describes, and each pulse's single and double integrals match their
closed forms.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid

from rocking.errors import ParameterError, RockingError
from rocking.motions import (
    HalfSine,
    HanningSine,
    Motion,
    OneCosine,
    OneSine,
    Rectangular,
    Ricker,
    Sine,
    sample,
)
from rocking.motions import _kernel as K

TWO_PI = 2.0 * math.pi


def integrate(motion: Motion, t_end: float, n: int = 200_001):
    """Velocity and displacement from rest at t = 0 by cumulative trapezoids."""
    t = np.linspace(0.0, t_end, n)
    a = motion.acceleration(t)
    v = cumulative_trapezoid(a, t, initial=0.0)
    d = cumulative_trapezoid(v, t, initial=0.0)
    return t, a, v, d


# ------------------------------------------------------------------------------ Sine
class TestSine:
    def test_acceleration_amplitude_is_x_omega_squared(self):
        m = Sine(freq=5.0, amplitude=0.005, duration=4.0)
        expected = 0.005 * (TWO_PI * 5.0) ** 2
        assert expected == pytest.approx(4.9348, rel=1e-4)  # "5 mm at 5 Hz is 4.93 m/s^2"
        assert m.acc_amplitude == pytest.approx(expected, rel=1e-12)
        t = np.linspace(0.0, 4.0, 40_001)
        assert np.max(np.abs(m.acceleration(t))) == pytest.approx(expected, rel=1e-6)
        assert m.pga == pytest.approx(expected, rel=1e-4)

    def test_is_second_derivative_of_displacement(self):
        f, X, ph = 2.0, 0.01, 0.7
        m = Sine(freq=f, amplitude=X, duration=3.0, phase=ph)
        t = np.linspace(0.2, 2.8, 7)
        w = TWO_PI * f
        np.testing.assert_allclose(m.acceleration(t), -X * w * w * np.sin(w * t + ph),
                                   rtol=1e-12, atol=1e-12)

    def test_double_integral_reproduces_table_displacement(self):
        f, X, ph = 3.0, 0.004, 0.3
        m = Sine(freq=f, amplitude=X, duration=2.0, phase=ph)
        t, _, v, d = integrate(m, 2.0)
        w = TWO_PI * f
        # start from the table's own initial state u(0) = X sin(ph), u'(0) = X w cos(ph)
        u = X * np.sin(ph) + X * w * np.cos(ph) * t + d
        np.testing.assert_allclose(u, X * np.sin(w * t + ph), atol=1e-6 * X)

    def test_zero_outside_the_duration(self):
        m = Sine(freq=2.0, amplitude=0.01, duration=1.3, phase=0.5)
        assert m.acceleration(-1e-6) == 0.0
        assert m.acceleration(-3.0) == 0.0
        assert m.acceleration(1.3 + 1e-6) == 0.0
        np.testing.assert_array_equal(m.acceleration(np.array([2.0, 10.0, 1e6])), 0.0)
        assert m.acceleration(1.0) != 0.0

    def test_from_acceleration_round_trip(self):
        m = Sine.from_acceleration(4.0, 2.5, 3.0)
        assert m.amplitude == pytest.approx(2.5 / (TWO_PI * 4.0) ** 2)
        assert m.acc_amplitude == pytest.approx(2.5)

    def test_scalar_in_scalar_out_and_shape_kept(self):
        m = Sine(freq=1.0, amplitude=0.1, duration=2.0)
        assert isinstance(m.acceleration(0.25), float)
        assert isinstance(m(0.25), float)
        assert m.acceleration(np.zeros((3, 4))).shape == (3, 4)
        assert m.acceleration([0.1, 0.2]).shape == (2,)

    @pytest.mark.parametrize(
        "kw, word",
        [
            ({"freq": 0.0, "amplitude": 0.01, "duration": 1.0}, "freq"),
            ({"freq": -1.0, "amplitude": 0.01, "duration": 1.0}, "freq"),
            ({"freq": 1.0, "amplitude": -0.01, "duration": 1.0}, "amplitude"),
            ({"freq": 1.0, "amplitude": 0.01, "duration": 0.0}, "duration"),
            ({"freq": math.nan, "amplitude": 0.01, "duration": 1.0}, "freq"),
            ({"freq": "five", "amplitude": 0.01, "duration": 1.0}, "freq"),
        ],
    )
    def test_validation(self, kw, word):
        with pytest.raises(ParameterError, match=word):
            Sine(**kw)
        assert issubclass(ParameterError, ValueError)


# ---------------------------------------------------------------------------- Hanning
class TestHanningSine:
    f, X, dur = 3.0, 0.005, 2.0

    def displacement(self, t):
        w = 0.5 * (1.0 - np.cos(TWO_PI * t / self.dur))
        return self.X * w * np.sin(TWO_PI * self.f * t)

    def test_acceleration_is_numerical_second_derivative_of_displacement(self):
        m = HanningSine(self.f, self.X, self.dur)
        t = np.linspace(0.0, self.dur, 40_001)
        h = t[1] - t[0]
        u = self.displacement(t)
        num = (u[2:] - 2.0 * u[1:-1] + u[:-2]) / h**2  # central second difference
        peak = self.X * (TWO_PI * self.f) ** 2
        np.testing.assert_allclose(m.acceleration(t[1:-1]), num, atol=1e-5 * peak)

    def test_gradient_twice_agrees(self):
        m = HanningSine(self.f, self.X, self.dur)
        t = np.linspace(0.0, self.dur, 20_001)
        num = np.gradient(np.gradient(self.displacement(t), t), t)
        inner = slice(5, -5)  # np.gradient is one-sided at the ends
        peak = self.X * (TWO_PI * self.f) ** 2
        np.testing.assert_allclose(m.acceleration(t)[inner], num[inner], atol=1e-4 * peak)

    def test_table_starts_and_ends_at_rest(self):
        m = HanningSine(self.f, self.X, self.dur)
        t, a, v, d = integrate(m, self.dur)
        assert a[0] == pytest.approx(0.0, abs=1e-12)
        # integrating a from rest gives back X w(t) sin(2 pi f t): zero at both ends
        np.testing.assert_allclose(d, self.displacement(t), atol=1e-6 * self.X)
        assert v[-1] == pytest.approx(0.0, abs=1e-6 * self.X * TWO_PI * self.f)
        assert d[-1] == pytest.approx(0.0, abs=1e-6 * self.X)

    def test_window_envelope_and_peak(self):
        m = HanningSine(5.0, 0.004, 10.0)
        peak = 0.004 * (TWO_PI * 5.0) ** 2
        t = np.linspace(0.0, 10.0, 100_001)
        a = m.acceleration(t)
        # the envelope is small near the ends and reaches ~X w^2 in the middle
        assert np.max(np.abs(a[t < 0.2])) < 0.05 * peak
        assert np.max(np.abs(a[t > 9.8])) < 0.05 * peak
        assert np.max(np.abs(a)) == pytest.approx(peak, rel=0.01)

    def test_zero_outside(self):
        m = HanningSine(self.f, self.X, self.dur)
        assert m.acceleration(-0.01) == 0.0
        assert m.acceleration(self.dur + 0.01) == 0.0


# ----------------------------------------------------------------------------- pulses
class TestPulses:
    A = 2.0

    def test_one_sine_closed_form(self):
        Tp, t0 = 0.5, 0.3
        m = OneSine(self.A, Tp, t0=t0)
        t, a, v, d = integrate(m, t0 + Tp + 0.2)
        tau = np.clip(t - t0, 0.0, Tp)
        np.testing.assert_allclose(a, np.where((t >= t0) & (t <= t0 + Tp),
                                               self.A * np.sin(TWO_PI * tau / Tp), 0.0),
                                   atol=1e-12)
        v_exact = self.A * Tp / TWO_PI * (1.0 - np.cos(TWO_PI * tau / Tp))
        np.testing.assert_allclose(v, v_exact, atol=1e-7)
        # full cycle: the ground velocity returns to zero, displacement A Tp^2 / (2 pi)
        assert v[-1] == pytest.approx(0.0, abs=1e-7)
        assert d[t <= t0 + Tp][-1] == pytest.approx(self.A * Tp**2 / TWO_PI, rel=1e-5)

    def test_one_cosine_closed_form(self):
        Tp = 0.4
        m = OneCosine(self.A, Tp)
        t, a, v, d = integrate(m, Tp)
        np.testing.assert_allclose(v, self.A * Tp / TWO_PI * np.sin(TWO_PI * t / Tp),
                                   atol=1e-7)
        np.testing.assert_allclose(
            d, self.A * (Tp / TWO_PI) ** 2 * (1.0 - np.cos(TWO_PI * t / Tp)), atol=1e-8)
        assert v[-1] == pytest.approx(0.0, abs=1e-7)
        assert d[-1] == pytest.approx(0.0, abs=1e-8)

    def test_half_sine_closed_form(self):
        t1 = 0.25
        m = HalfSine(self.A, t1)
        t, a, v, d = integrate(m, t1)
        assert v[-1] == pytest.approx(2.0 * self.A * t1 / math.pi, rel=1e-6)
        assert d[-1] == pytest.approx(self.A * t1**2 / math.pi, rel=1e-6)
        assert np.max(a) == pytest.approx(self.A, rel=1e-6)
        assert np.min(a) >= 0.0

    def test_rectangular_closed_form(self):
        t1, t0 = 0.3, 0.1
        m = Rectangular(self.A, t1, t0=t0)
        assert m.acceleration(t0 + 0.5 * t1) == self.A
        assert m.acceleration(t0 - 1e-6) == 0.0
        assert m.acceleration(t0 + t1 + 1e-6) == 0.0
        t, a, v, d = integrate(m, t0 + t1, n=300_001)
        assert v[-1] == pytest.approx(self.A * t1, rel=1e-4)
        assert d[-1] == pytest.approx(0.5 * self.A * t1**2, rel=1e-4)

    def test_ricker_closed_form(self):
        fp = 2.0
        m = Ricker(self.A, fp)
        assert m.tc == pytest.approx(1.5 / fp)
        assert m.acceleration(m.tc) == pytest.approx(self.A)  # peak at the centre
        t, a, v, d = integrate(m, 2.0 * m.tc)
        # a = A (1 - 2x^2) exp(-x^2) is the derivative of v = A (t - tc) exp(-x^2)
        x = math.pi * fp * (t - m.tc)
        v_exact = self.A * (t - m.tc) * np.exp(-x * x)
        np.testing.assert_allclose(v - v[0], v_exact - v_exact[0], atol=1e-7)
        # zero mean: the wavelet leaves the ground at rest (up to the truncated tails)
        assert abs(v[-1]) < 1e-3 * self.A / fp

    def test_default_window_extends_past_the_pulse(self):
        assert OneSine(1.0, 0.5).duration == pytest.approx(10.0)
        assert OneSine(1.0, 4.0, t0=1.0).duration == pytest.approx(21.0)
        assert HalfSine(1.0, 0.5, duration=3.0).duration == 3.0
        assert Ricker(1.0, 1.0).duration > 2 * 1.5

    @pytest.mark.parametrize("cls", [OneSine, OneCosine, HalfSine, Rectangular])
    def test_pulse_validation_names_parameter(self, cls):
        with pytest.raises(ParameterError, match="amplitude"):
            cls(-1.0, 0.5)
        with pytest.raises(ParameterError, match="Tp|t1"):
            cls(1.0, 0.0)
        with pytest.raises(ParameterError, match="t0"):
            cls(1.0, 0.5, t0=-1.0)
        with pytest.raises(ParameterError, match="duration"):
            cls(1.0, 0.5, duration=-2.0)

    def test_ricker_validation(self):
        with pytest.raises(ParameterError, match="fp"):
            Ricker(1.0, 0.0)
        with pytest.raises(ParameterError, match="tc"):
            Ricker(1.0, 1.0, tc=-0.5)


# ------------------------------------------------------------------------ shared base
MOTIONS = [
    Sine(2.0, 0.01, 3.0, phase=0.2),
    HanningSine(3.0, 0.005, 2.0),
    OneSine(2.0, 0.5, t0=0.1),
    OneCosine(2.0, 0.5),
    HalfSine(2.0, 0.4),
    Rectangular(2.0, 0.4),
    Ricker(2.0, 1.5),
]


@pytest.mark.parametrize("m", MOTIONS, ids=lambda m: type(m).__name__)
class TestShared:
    def test_scaled_and_negated(self, m):
        t = np.linspace(-0.5, 3.5, 2001)
        a = m.acceleration(t)
        np.testing.assert_allclose(m.scaled(1.3).acceleration(t), 1.3 * a, rtol=1e-12)
        np.testing.assert_allclose((-m).acceleration(t), -a, rtol=1e-12)
        np.testing.assert_allclose(m.scaled(-1).acceleration(t), -a, rtol=1e-12)
        assert m.scaled(0.5).scaled(4.0).scale == pytest.approx(2.0 * m.scale)
        assert m.scaled(-2.0).pga == pytest.approx(2.0 * m.pga, rel=1e-9)
        with pytest.raises(RockingError):
            m.scaled(math.inf)

    def test_scaled_is_a_copy(self, m):
        s = m.scaled(2.0)
        assert s is not m
        assert m.scale == 1.0

    def test_time_grid(self, m):
        t = m.time(0.01)
        assert t[0] == 0.0
        assert t[-1] == pytest.approx(m.duration, abs=0.005)
        np.testing.assert_allclose(np.diff(t), 0.01)
        with pytest.raises(ParameterError, match="dt"):
            m.time(0.0)

    def test_kernel_breakpoints_bracket_the_support(self, m):
        kind, prm, samples = m.spec()
        bp = K.next_breakpoint(kind, prm, samples, -1.0)
        if isinstance(m, Ricker):
            assert bp == math.inf  # smooth everywhere
        else:
            # the first kink is where the motion starts, and nothing is nonzero before it
            assert bp == pytest.approx(getattr(m, "t0", 0.0))
            t = np.linspace(-1.0, bp, 50, endpoint=False)
            np.testing.assert_array_equal(m.acceleration(t), 0.0)

    def test_sample_reproduces_the_motion_at_sample_times(self, m):
        dt = 0.002
        rec = sample(m, dt)
        np.testing.assert_allclose(rec.acc, m.acceleration(rec.t), atol=1e-12)
        assert rec.duration == pytest.approx(m.duration, abs=dt)
        # between samples the record is the linear interpolant of the motion
        tm = rec.t[:-1] + 0.5 * dt
        np.testing.assert_allclose(rec.acceleration(tm), 0.5 * (rec.acc[:-1] + rec.acc[1:]),
                                   atol=1e-12)


@pytest.mark.parametrize("cls", [Sine, HanningSine])
def test_an_acceleration_given_as_displacement_warns(cls):
    """``amplitude`` of a harmonic motion is the table displacement (m): one whose
    acceleration amplitude X (2 pi f)^2 passes 5 g warns (an acceleration typed in its
    place), one just below does not."""
    import warnings

    from rocking.errors import PlausibilityWarning
    from rocking.units import G

    f = 5.0
    x5g = 5.0 * G / (2.0 * math.pi * f) ** 2     # 0.0497 m at 5 Hz
    with pytest.warns(PlausibilityWarning, match="table displacement in m"):
        cls(f, 1.01 * x5g, 2.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cls(f, 0.99 * x5g, 2.0)
        cls(5.0, 0.005, 25.0)                    # the paper's 5 mm at 5 Hz (0.5 g)
