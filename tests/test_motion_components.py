"""A motion's own peaks (PGA, PGV, duration) and its three components.

Peaks: the closed forms of the kinds that state them are checked against the finely
sampled motion (the velocity integrated independently, by scipy's cumulative trapezoids);
the default of the other kinds is the sampled motion of ``rocking.motions.sample``, exactly.

Three components: ``ground_acc3`` of a pair equals the rotation of its two interpolated
components into the body's frame, ``(a_x cos h + a_y sin h, -a_x sin h + a_y cos h, a_v)``
with ``a_x = a1`` and ``a_y`` the ground acceleration 90 deg counter-clockwise of the first
component (``a2`` for a pair without azimuths, ``-a2`` for a clockwise one); its projection
on a direction ``phi`` of the body is ``HorizontalPair.motion(phi)``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid

from rocking.errors import ParameterError
from rocking.motions import (
    GroundMotion,
    HalfSine,
    HanningSine,
    HorizontalPair,
    MavroeidisPapageorgiou,
    OneCosine,
    OneSine,
    Record,
    Rectangular,
    Ricker,
    Sine,
    intensity_measures,
    load_builtin,
    pga,
    pgv,
    sample,
)
from rocking.motions import _kernel as K


def fine_peaks(m, dt=2e-5, t_end=None):
    """``(max |a|, max |v|)`` of ``m`` on a fine grid, ``v`` from rest at t = 0."""
    t_end = m.duration if t_end is None else t_end
    t = np.linspace(0.0, t_end, int(round(t_end / dt)) + 1)
    a = m.acceleration(t)
    v = cumulative_trapezoid(a, t, initial=0.0)
    return float(np.max(np.abs(a))), float(np.max(np.abs(v)))


# ----------------------------------------------------------------------- closed forms
PULSES = [
    (OneSine(2.0, 0.5, t0=0.1), 2.0 * 0.5 / math.pi),          # A Tp / pi
    (OneCosine(2.0, 0.5), 2.0 * 0.5 / (2.0 * math.pi)),        # A Tp / (2 pi)
    (HalfSine(2.0, 0.4, t0=0.3), 2.0 * 2.0 * 0.4 / math.pi),   # 2 A t1 / pi
    (Rectangular(2.0, 0.4), 2.0 * 0.4),                        # A t1
]


@pytest.mark.parametrize("m, v_peak", PULSES, ids=lambda x: type(x).__name__)
def test_pulse_peaks_are_their_closed_forms(m, v_peak):
    assert m.pga == m.amplitude
    assert m.pgv == pytest.approx(v_peak, rel=1e-14)
    a_max, v_max = fine_peaks(m, t_end=m.t0 + 2.0 * m.length)
    assert a_max == pytest.approx(m.pga, rel=1e-6)
    assert v_max == pytest.approx(m.pgv, rel=1e-4)  # a rectangular pulse's jumps: O(dt)


@pytest.mark.parametrize("tc", [None, 0.0, 0.1])
def test_ricker_pgv_from_rest(tc):
    """v = A / (pi fp) (x exp(-x^2) + x0 exp(-x0^2)): from rest at t = 0 (x = -x0), its
    largest value at x = 1/sqrt(2); tc = 0.1 s at fp = 2 Hz makes the offset large."""
    m = Ricker(3.0, 2.0, tc=tc, duration=3.0)
    x0 = math.pi * m.fp * m.tc
    expected = m.amplitude / (math.pi * m.fp) * (math.exp(-0.5) / math.sqrt(2.0)
                                                 + x0 * math.exp(-x0 * x0))
    assert m.pgv == pytest.approx(expected, rel=1e-14)
    a_max, v_max = fine_peaks(m)
    assert v_max == pytest.approx(m.pgv, rel=1e-7)
    assert a_max == pytest.approx(m.pga, rel=1e-7) and m.pga == 3.0


@pytest.mark.parametrize("nu", [0.0, 0.3, math.pi / 2])
def test_mavroeidis_papageorgiou_peaks(nu):
    m = MavroeidisPapageorgiou(4.0, 1.5, 2.5, nu)
    t = np.linspace(0.0, m.t0 + m.half_length, 400_001)
    v = m.velocity(t)
    assert m.pgv == pytest.approx(float(np.max(np.abs(v))), rel=1e-8)
    a_max, v_max = fine_peaks(m, dt=1e-5, t_end=t[-1])
    assert v_max == pytest.approx(m.pgv, rel=1e-6)
    assert a_max == pytest.approx(m.pga, rel=1e-6) and m.pga == 4.0
    if nu == 0.0:
        assert m.pgv == pytest.approx(m.velocity_amplitude, rel=1e-12)  # v(t0) = A


def test_sine_peaks_are_x_omega_squared_and_x_omega():
    """The sine states its table displacement u = X sin(w t + ph): PGA X w^2 and PGV X w,
    the peak of u' (the table moves at u'(0) when the sine starts: integrated from rest,
    the acceleration gives u' - u'(0))."""
    f, X, ph = 2.0, 0.01, 0.4
    m = Sine(f, X, 3.0, phase=ph, scale=1.5)
    w = 2.0 * math.pi * f
    assert m.pga == m.acc_amplitude == pytest.approx(1.5 * X * w * w, rel=1e-14)
    assert m.pgv == pytest.approx(1.5 * X * w, rel=1e-14)
    t = np.linspace(0.0, 3.0, 300_001)
    u = 1.5 * X * np.sin(w * t + ph)
    assert float(np.max(np.abs(np.gradient(u, t)))) == pytest.approx(m.pgv, rel=1e-6)
    a_max, _ = fine_peaks(m)
    assert a_max == pytest.approx(m.pga, rel=1e-8)
    v_rest = cumulative_trapezoid(m.acceleration(t), t, initial=0.0)
    np.testing.assert_allclose(v_rest + 1.5 * X * w * math.cos(ph),
                               1.5 * X * w * np.cos(w * t + ph), atol=1e-6 * m.pgv)


# ---------------------------------------------------------------------------- defaults
def test_default_peaks_are_those_of_the_sampled_motion():
    """A kind that states no peaks (a Hann-windowed sine) answers those of
    ``sample(m, min(scan_step, 0.005))``, bit for bit."""
    for m in (HanningSine(3.0, 0.005, 2.0), HanningSine(0.5, 0.05, 6.0, scale=-1.3)):
        r = sample(m, min(m.scan_step, 0.005))
        assert m.sampling_step == min(m.scan_step, 0.005)
        assert m.pga == pga(r)
        assert m.pgv == pgv(r)
        a_max, v_max = fine_peaks(m)  # and close to the motion's own
        assert m.pga == pytest.approx(a_max, rel=2e-3)
        assert m.pgv == pytest.approx(v_max, rel=2e-3)


def test_record_and_ground_motion_peaks_come_from_the_samples():
    rec = load_builtin("Rinaldi228").scaled(0.7)
    im = intensity_measures(rec)
    assert rec.pga == im["pga"] and rec.pgv == im["pgv"]
    assert rec.duration == (len(rec) - 1) * rec.dt
    gm = GroundMotion.builtin("rinaldi").scaled(0.5)
    h = gm.horizontal
    assert gm.pga == h.pga and gm.pgv == h.pgv
    assert gm.pga_vertical == gm.vertical.pga


ALL = [Sine(2.0, 0.01, 3.0, phase=0.2), HanningSine(3.0, 0.005, 2.0),
       OneSine(2.0, 0.5, t0=0.1), OneCosine(2.0, 0.5), HalfSine(2.0, 0.4),
       Rectangular(2.0, 0.4), Ricker(2.0, 1.5), MavroeidisPapageorgiou(3.0, 1.0, 2.0, 0.3),
       Record(np.array([0.0, 1.0, -2.0, 0.5, 0.0]), 0.01),
       GroundMotion(Sine(2.0, 0.01, 3.0), Sine(4.0, 0.001, 3.0))]


@pytest.mark.parametrize("m", ALL, ids=lambda m: type(m).__name__)
def test_scaling_scales_the_peaks(m):
    s = m.scaled(-2.0)  # a power of 2: exact for the closed forms and the samples
    assert s.pga == 2.0 * m.pga
    assert s.pgv == 2.0 * m.pgv
    assert s.duration == m.duration > 0.0
    t = m.scaled(0.3)
    assert t.pga == pytest.approx(0.3 * m.pga, rel=1e-12)
    assert t.pgv == pytest.approx(0.3 * m.pgv, rel=1e-12)


# -------------------------------------------------------------------- three components
def records(n=40, dt=0.01, seed=0):
    rng = np.random.default_rng(seed)
    return [Record(rng.normal(0.0, 1.0, n), dt) for _ in range(3)]


def interp(rec, t):
    """The record at ``t``: linear between samples, zero after the last (np.interp)."""
    return np.where(t <= rec.duration, np.interp(t, rec.t, rec.values), 0.0)


TIMES = np.array([0.0, 0.01, 0.013, 0.1, 0.2155, 0.37, 0.39, 0.3951, 0.5])


@pytest.mark.parametrize("azimuths, k", [(None, 1.0), (("228deg", "318deg"), -1.0),
                                         (("10deg", "-80deg"), 1.0)])
@pytest.mark.parametrize("heading", [0.0, 0.4, "90deg", -2.1])
@pytest.mark.parametrize("same_grid", [True, False])
def test_ground_acc3_of_a_pair_is_the_rotated_ground_vector(azimuths, k, heading, same_grid):
    """a_y = k a2: k = 1 when the second component is 90 deg counter-clockwise of the
    first (no azimuths, or a pair numbered that way), -1 when clockwise (the NGA pairs)."""
    r1, r2, rv = records()
    if not same_grid:
        rv = Record(rv.acc[:25], 0.013)
    pair = HorizontalPair(r1, r2, azimuths=azimuths, vertical=rv)
    kind, prm, samples = pair.spec3(heading=heading)
    assert kind == K.PAIR and prm.size == K.NPRM3
    assert (prm[K.V_SAME] == 1.0) == same_grid
    h = pair.orientation_of(0.0) - pair.orientation_of(heading)  # the heading in rad
    ax_g, ay_g, av = interp(r1, TIMES), k * interp(r2, TIMES), interp(rv, TIMES)
    got = K.acc3_many(kind, prm, samples, TIMES)
    np.testing.assert_allclose(got[:, 0], ax_g * math.cos(h) + ay_g * math.sin(h),
                               rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(got[:, 1], -ax_g * math.sin(h) + ay_g * math.cos(h),
                               rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(got[:, 2], av, rtol=1e-12, atol=1e-14)
    for i, t in enumerate(TIMES):  # the scalar accessor is the vectorised one
        assert K.ground_acc3(kind, prm, samples, t) == tuple(got[i])
    without = K.acc3_many(*pair.spec3(heading=heading, vertical=False), TIMES)
    assert np.array_equal(without[:, :2], got[:, :2]) and not np.any(without[:, 2])


def test_a_pair_along_its_axes_is_its_components_exactly():
    r1, r2, rv = records(seed=1)
    pair = HorizontalPair(r1, r2, vertical=rv)  # counter-clockwise: a_y = a2
    got = K.acc3_many(*pair.spec3(), TIMES)
    assert np.array_equal(got[:, 0], r1.acceleration(TIMES))
    assert np.array_equal(got[:, 1], r2.acceleration(TIMES))
    assert np.array_equal(got[:, 2], rv.acceleration(TIMES))
    turned = K.acc3_many(*pair.spec3(heading="90deg"), TIMES)  # x along y: (a_y, -a_x)
    assert np.array_equal(turned[:, 0], got[:, 1]) and np.array_equal(turned[:, 1], -got[:, 0])


@pytest.mark.parametrize("heading", [0.0, "25deg", -1.3])
@pytest.mark.parametrize("phi", [0.0, 0.7, "90deg", "180deg", -2.0])
def test_projection_of_the_three_components_is_the_planar_motion(heading, phi):
    pair = HorizontalPair.builtin("rinaldi")  # clockwise, with its vertical
    planar = pair.on_plane(phi, heading)
    direct = pair.motion(phi, pair.orientation_of(heading))
    for a, b in zip(planar.spec(), direct.spec(), strict=True):
        assert np.array_equal(a, b)
    if heading == 0.0:  # the default orientation: HorizontalPair.motion(phi) itself
        for a, b in zip(planar.spec(), pair.motion(phi).spec(), strict=True):
            assert np.array_equal(a, b)
    t = np.linspace(0.0, pair.duration, 3001) + 0.0037
    a3 = K.acc3_many(*pair.spec3(heading=heading), t)
    p = math.radians(float(phi[:-3])) if isinstance(phi, str) else phi
    along = a3[:, 0] * math.cos(p) + a3[:, 1] * math.sin(p)
    np.testing.assert_allclose(along, planar.acceleration(t), rtol=0,
                               atol=1e-12 * pair.peak_resultant)
    np.testing.assert_array_equal(a3[:, 2], planar.vertical_acceleration(t))


def test_projection_on_a_component_axis_is_exact():
    """At multiples of 90 deg the weights are exact: the projection of the spec's body
    components on the body's axes is the planar motion bit for bit."""
    pair = HorizontalPair.builtin("duzce")
    t = np.linspace(0.0, 5.0, 1001) + 0.0013
    a3 = K.acc3_many(*pair.spec3(heading="90deg"), t)
    assert np.array_equal(a3[:, 0], pair.on_plane(0.0, "90deg").acceleration(t))
    assert np.array_equal(a3[:, 1], pair.on_plane("90deg", "90deg").acceleration(t))
    assert np.array_equal(-a3[:, 1], pair.on_plane("-90deg", "90deg").acceleration(t))


@pytest.mark.parametrize("m", ALL + [GroundMotion.builtin("rinaldi")],
                         ids=lambda m: type(m).__name__)
def test_a_planar_motion_is_along_x(m):
    """spec3 keeps the planar spec (the planar models' input) and adds the body's axes;
    ground_acc3 of the planar spec and of spec3 (heading 0) is (a, 0, a_v) exactly."""
    kind, prm, samples = m.spec()
    k3, p3, s3 = m.spec3()
    assert k3 == kind and np.array_equal(s3, samples) and np.array_equal(p3[:K.NPRM], prm)
    t = np.linspace(-0.1, min(m.duration, 5.0) + 0.2, 997)
    a = m.acceleration(t)
    av = (m.vertical_acceleration(t) if hasattr(m, "vertical_acceleration")
          else np.zeros_like(t))
    for spec in ((kind, prm, samples), (k3, p3, s3)):
        got = K.acc3_many(*spec, t)
        assert np.array_equal(got[:, 0], a)
        assert not np.any(got[:, 1])
        assert np.array_equal(got[:, 2], av)
    h = 0.6
    got = K.acc3_many(*m.spec3(heading=h), t)
    np.testing.assert_allclose(got[:, 0], a * math.cos(h), rtol=1e-14, atol=0)
    np.testing.assert_allclose(got[:, 1], -a * math.sin(h), rtol=1e-14, atol=0)
    assert np.array_equal(got[:, 2], av)
    # its projection on a direction of the body: a cos(h + phi), the vertical unchanged
    phi = 0.5
    on = m.on_plane(phi, heading=h)
    np.testing.assert_allclose(on.acceleration(t), a * math.cos(h + phi), rtol=1e-14,
                               atol=1e-14 * m.pga)
    np.testing.assert_allclose(got[:, 0] * math.cos(phi) + got[:, 1] * math.sin(phi),
                               on.acceleration(t), rtol=0, atol=1e-14 * m.pga)
    if hasattr(m, "vertical_acceleration"):
        assert np.array_equal(on.vertical_acceleration(t), av)
    assert m.on_plane(0.0) is m


def test_breakpoints_of_a_pair_are_its_samples():
    r1, r2, rv = records(seed=2)
    pair = HorizontalPair(r1, r2, vertical=Record(rv.acc[:10], 0.013))
    spec3 = pair.spec3(heading=0.3)
    ref = GroundMotion(r1, Record(rv.acc[:10], 0.013)).spec()
    for t in (-1.0, 0.0, 0.004, 0.05, 0.1, 0.39, 0.45):
        assert K.next_breakpoint(*spec3, t) == K.next_breakpoint(*ref, t)


def test_bad_headings_are_refused():
    pair = HorizontalPair(*records()[:2])
    for bad in (None, math.nan, "north", True):
        with pytest.raises(ParameterError, match="heading"):
            pair.spec3(heading=bad)
        with pytest.raises(ParameterError, match="heading"):
            Sine(2.0, 0.01, 1.0).spec3(heading=bad)
    with pytest.raises(ParameterError, match="phi"):
        Sine(2.0, 0.01, 1.0).on_plane("up")
