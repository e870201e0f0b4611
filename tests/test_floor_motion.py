"""Floor motions (issue 18): a linear building filters the ground acceleration into the
absolute acceleration of a floor, on which an object rocks (cascade).

Physics checks: the closed-form steady-state transmissibility of an SDOF building, an
independent scipy integration of the modal oscillators (ground linear between samples),
the rigid-building and ground-floor limits, linearity, and a block that overturns at a
lower ground intensity on the floor of a building tuned to the pulse than on the ground.
"""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest
from scipy import signal
from scipy.integrate import solve_ivp

import rocking
from rocking.buildings import (
    Building,
    FloorMotion,
    asce7_hf,
    code_floor_spectrum_ec8,
    floor_spectrum,
    plot_floor_spectrum,
)
from rocking.buildings import floor as floor_module
from rocking.buildings import spectra as spectra_module
from rocking.errors import ParameterError
from rocking.motions import GroundMotion, OneSine, Sine, load_builtin, response_spectrum


@pytest.fixture(scope="module")
def rinaldi():
    return load_builtin("Rinaldi228")


# ------------------------------------------------------------------ independent reference
def scipy_floor(acc, dt, omegas, zetas, gphis, t_eval, t_end):
    """Absolute floor acceleration ``a_g + sum_j g_j u_j''`` at ``t_eval`` by solve_ivp
    (DOP853, rtol 1e-12) on the modal oscillators from rest, the ground linear between
    its samples (step ``dt``) and zero after ``t_end``: one call per interval between
    consecutive times of ``t_eval`` and of the ground's samples, where the forcing is
    smooth (the kinks of a_g cost no accuracy)."""
    tg = np.arange(acc.size) * dt
    w = np.asarray(omegas, dtype=float)
    z = np.asarray(zetas, dtype=float)
    g = np.asarray(gphis, dtype=float)
    n = w.size
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.diag(w * w), -np.diag(2 * z * w)]])
    ones = np.concatenate([np.zeros(n), np.ones(n)])
    atol = 1e-14 * max(np.max(np.abs(acc)), 1e-300) * np.concatenate([1 / w**2, 1 / w])

    def ground(t):
        return float(np.interp(t, tg, acc)) if t <= t_end + 1e-12 else 0.0

    def floor_acc(t, y):
        ag = ground(t)
        return ag + g @ (-ag - 2 * z * w * y[n:] - w * w * y[:n])

    knots = np.union1d(tg[tg <= t_end + 1e-12], t_eval)
    knots = knots[np.concatenate([[True], np.diff(knots) > 1e-9 * dt])]  # merge equal times
    vals = np.empty(knots.size)
    y = np.zeros(2 * n)
    vals[0] = floor_acc(knots[0], y)
    for i, (t0, t1) in enumerate(zip(knots[:-1], knots[1:], strict=True)):
        moving = t0 < t_end - 1e-12  # the ground stops at t_end
        a0, a1 = (ground(t0), ground(t1)) if moving else (0.0, 0.0)
        slope = (a1 - a0) / (t1 - t0)
        sol = solve_ivp(lambda tt, yy, t0=t0, a0=a0, s=slope:
                        A @ yy - ones * (a0 + s * (tt - t0)),
                        (t0, t1), y, method="DOP853", rtol=1e-12, atol=atol)
        assert sol.success
        y = sol.y[:, -1]
        vals[i + 1] = floor_acc(t1, y)
    idx = np.searchsorted(knots, np.asarray(t_eval) - 1e-9 * dt)
    assert np.allclose(knots[idx], t_eval, rtol=0, atol=1e-9 * dt)
    return vals[idx]


def lsim_floor(acc, dt, T, zeta):
    """The SDOF floor by scipy.signal.lsim (matrix exponential, first-order hold: exact
    for the ground linear between samples), at the samples."""
    w = 2 * np.pi / T
    sys = signal.StateSpace([[0.0, 1.0], [-w * w, -2 * zeta * w]], [[0.0], [-1.0]],
                            [[-w * w, -2 * zeta * w]], [[0.0]])
    _, y, _ = signal.lsim(sys, acc, np.arange(acc.size) * dt, interp=True)
    return y


def floor_times(fm):
    return np.arange(fm.samples.size) * fm.step


# ------------------------------------------------------------------ closed form
class TestHarmonicTransmissibility:
    """SDOF building under a long sine: the floor's steady-state amplitude over the
    ground's is |1 + r^2 / (1 - r^2 + 2 i zeta r)| (Chopra 3.6)."""

    @pytest.mark.parametrize("r", [0.5, 0.9, 1.0, 1.5, 3.0])
    def test_steady_state_amplitude(self, r):
        T, zeta, A = 0.5, 0.05, 1.0
        f = r / T
        ground = Sine.from_acceleration(f, A, duration=40.0)
        fm = FloorMotion(ground, Building.sdof(T, zeta), floor=1)
        t = floor_times(fm)
        # the last 10 whole cycles before the ground stops (transients e^-18 below)
        sel = (t > 40.0 - 10.0 / f - 1e-9) & (t <= 40.0 - 1e-9)
        wt = 2 * np.pi * f * t[sel]
        M = np.column_stack([np.sin(wt), np.cos(wt)])
        coef, *_ = np.linalg.lstsq(M, fm.samples[sel], rcond=None)
        amp = math.hypot(*coef) / A
        exact = math.sqrt((1 + (2 * zeta * r) ** 2) / ((1 - r * r) ** 2 + (2 * zeta * r) ** 2))
        assert abs(1 + r * r / complex(1 - r * r, 2 * zeta * r)) == pytest.approx(exact)
        assert amp == pytest.approx(exact, rel=1e-3)
        # sharper: the sampled sine is linear between samples (a convolution with a
        # triangle of half-width dt), which multiplies its fundamental by sinc^2(f dt)
        assert amp == pytest.approx(exact * np.sinc(f * fm.step) ** 2, rel=1e-7)

    def test_ring_down_after_the_ground_stops(self):
        """After the ground stops the floor is the building's free vibration, cut off when
        it is below RING_DOWN_TOL of the peak; the decay rate is zeta omega."""
        T, zeta = 0.5, 0.05
        fm = FloorMotion(Sine.from_acceleration(2.0, 1.0, duration=10.0),
                         Building.sdof(T, zeta), floor=1)
        t = floor_times(fm)
        tail = fm.samples[t > fm.ground_end + 1e-9]
        assert tail.size > 0 and fm.end > fm.ground_end
        peak = np.max(np.abs(fm.samples))
        # what is cut off (the free vibration after the last sample, by scipy) is below
        # RING_DOWN_TOL of the peak, and the cut is not later than it needs to be
        ground = Sine.from_acceleration(2.0, 1.0, duration=10.0)
        acc = ground.acceleration(np.arange(fm.ground_end / fm.step + 1) * fm.step)
        wd = 2 * np.pi / T * math.sqrt(1 - zeta**2)
        after = fm.end + np.arange(0, 3 * 2 * np.pi / wd, fm.step)
        t_ref = np.concatenate([t[::50], after[1:]])
        ref = scipy_floor(acc, fm.step, *Building.sdof(T, zeta).modal_factors(floor=1),
                          t_ref, fm.ground_end)
        np.testing.assert_allclose(fm.samples[::50], ref[: t[::50].size], rtol=0,
                                   atol=1e-9 * peak)
        cut = np.abs(ref[t[::50].size:]).max()
        assert cut < floor_module.RING_DOWN_TOL * peak
        assert cut > 0.3 * floor_module.RING_DOWN_TOL * peak
        # the envelope decays as exp(-zeta w t): peaks one damped period apart
        npp = int(round(2 * np.pi / wd / fm.step))
        seg = np.abs(tail[: 4 * npp])
        p1, p2 = seg[:npp].max(), seg[2 * npp: 3 * npp].max()
        assert p2 / p1 == pytest.approx(math.exp(-zeta * 2 * np.pi / T * 2 * 2 * np.pi / wd),
                                        rel=0.02)
        assert fm.quiet_time == pytest.approx(fm.end)
        assert fm.duration == pytest.approx(fm.end)

    def test_zero_damping_is_refused(self):
        with pytest.raises(ParameterError, match=r"damping\[0\].*\(0, 1\).*never rings"):
            FloorMotion(Sine(2.0, 0.01, 5.0), Building.sdof(0.5, 0.0), floor=1)


# ------------------------------------------------------------------ scipy reference
class TestAgainstScipy:
    def test_sdof_under_a_real_record(self, rinaldi):
        b = Building.sdof(0.4, 0.05)
        fm = FloorMotion(rinaldi, b, floor=1)
        assert fm.step == rinaldi.dt  # T = 0.4 s has 40 steps of 0.01 s per period
        t = floor_times(fm)
        keep = t <= fm.ground_end + 5.0  # the record and 5 s of ring-down
        ref = scipy_floor(rinaldi.values, rinaldi.dt, *b.modal_factors(floor=1), t[keep],
                          rinaldi.duration)
        peak = np.max(np.abs(ref))
        err = np.max(np.abs(fm.samples[keep] - ref)) / peak
        assert err < 1e-9, err  # measured 8e-14
        # the recurrence is exact: a matrix-exponential solution agrees to rounding
        n = rinaldi.acc.size
        exact = lsim_floor(rinaldi.values, rinaldi.dt, 0.4, 0.05)
        assert np.max(np.abs(fm.samples[:n] - exact)) < 1e-11 * peak
        # at every sample, the motion the kernels see is the floor's
        np.testing.assert_allclose(fm.acceleration(t), fm.samples, rtol=0,
                                   atol=1e-12 * peak)
        assert fm.quiet_time == fm.end > fm.ground_end == rinaldi.duration

    def test_three_modes_with_substeps(self, rinaldi):
        """Building.modal with 3 modes (truncated: sum of Gamma phi != 1, so the rigid
        part a_g (1 - sum) counts), the shortest mode 0.08 s: 3 sub-steps per 0.01 s."""
        shapes = [[0.45, 1.0, 1.0], [0.8, 0.4, -0.9], [1.0, -0.7, 0.5]]
        gamma = [1.25, -0.35, 0.12]
        b = Building.modal([1.0, 0.3, 0.08], [0.05, 0.03, 0.04], shapes, gamma)
        for k in (1, 3):
            w, z, g = b.modal_factors(floor=k)
            assert abs(1 - g.sum()) > 1e-3
            fm = FloorMotion(rinaldi, b, floor=k)
            assert fm.step == pytest.approx(rinaldi.dt / 3)
            t = floor_times(fm)
            sub = (t <= fm.ground_end + 3.0) & (np.arange(t.size) % 7 == 0)
            ref = scipy_floor(rinaldi.values, rinaldi.dt, w, z, g, t[sub], rinaldi.duration)
            err = np.max(np.abs(fm.samples[sub] - ref)) / np.max(np.abs(ref))
            assert err < 1e-9, (k, err)  # measured 5e-13

    def test_superposition_of_independent_modes(self, rinaldi):
        """The floor of a 2-mode building is the sum of two SDOF floors weighted by
        Gamma phi, plus the rigid part: each mode integrated on its own by scipy."""
        b = Building.modal([0.6, 0.2], 0.05, [[0.6, 0.9], [1.0, -0.5]], [1.3, -0.3])
        fm = FloorMotion(rinaldi, b, floor=2)
        w, z, g = b.modal_factors(floor=2)
        t = floor_times(fm)
        sub = (t <= fm.ground_end + 3.0) & (np.arange(t.size) % 5 == 0)
        t = t[sub]
        total = (1 - g.sum()) * np.where(t <= rinaldi.duration,
                                         np.interp(t, rinaldi.t, rinaldi.values), 0.0)
        for j in range(2):  # each absolute modal acceleration a_g + u_j'', alone
            total += g[j] * scipy_floor(rinaldi.values, rinaldi.dt, w[j:j + 1], z[j:j + 1],
                                        [1.0], t, rinaldi.duration)
        err = np.max(np.abs(fm.samples[sub] - total)) / np.max(np.abs(total))
        assert err < 1e-9, err

    def test_shear_building_against_direct_integration(self, rinaldi):
        """A 4-storey shear building (all modes: sum of Gamma phi = 1 at every floor)
        against rocking.testing.building_reference: M u'' + C u' + K u = -M 1 a_g
        integrated directly (no modes), one solve_ivp call per sample interval."""
        ref_mod = pytest.importorskip("rocking.testing.building_reference")
        b = Building.shear(4, 0.6, damping=0.05)
        arrays = ref_mod.arrays_of(b)
        for k in (2, 4):
            fm = FloorMotion(rinaldi, b, floor=k)
            np.testing.assert_allclose(b.modal_factors(floor=k)[2].sum(), 1.0, atol=1e-12)
            n = int(round(8.0 / fm.step)) + 1  # the first 8 s (the strong motion)
            t = np.arange(n) * fm.step
            ag = np.interp(t, rinaldi.t, rinaldi.values)
            direct = ref_mod.floor_response(arrays, t, ag, k)
            err = np.max(np.abs(fm.samples[:n] - direct)) / np.max(np.abs(direct))
            assert err < 1e-9, (k, err)  # measured 1e-12


# ------------------------------------------------------------------ limits
class TestLimits:
    def test_floor_zero_is_the_ground_bit_for_bit(self, rinaldi):
        b = Building.sdof(0.5)
        for ground in (rinaldi, OneSine(3.0, 0.4), GroundMotion.builtin("rinaldi")):
            fm = FloorMotion(ground, b, floor=0)
            for a, c in zip(fm.spec(), ground.spec(), strict=True):
                assert np.array_equal(a, c)
            assert fm.duration == ground.duration and fm.quiet_time == ground.quiet_time
            assert fm.scan_step == ground.scan_step
            s = fm.scaled(1.5).spec()
            for a, c in zip(s, ground.scaled(1.5).spec(), strict=True):
                assert np.array_equal(a, c)
        cont = Building(periods=[0.5], damping=0.05, participation=[1.0],
                        shape_function=lambda x: np.array([x]))
        fm = FloorMotion(rinaldi, cont, height_ratio=0.0)
        assert all(np.array_equal(a, c) for a, c in zip(fm.spec(), rinaldi.spec(),
                                                        strict=True))

    def test_rigid_building_gives_the_ground(self, rinaldi):
        fm = FloorMotion(rinaldi, Building.sdof(1e-4, 0.05), floor=1)
        assert fm.step == rinaldi.dt  # a mode above the record's Nyquist: no sub-steps
        n = rinaldi.acc.size
        err = np.max(np.abs(fm.samples[1:n] - rinaldi.values[1:]))
        assert err < 1e-6 * rinaldi.pga, err / rinaldi.pga
        # at t = 0 the building is at rest: its absolute acceleration starts at 0 (it is
        # continuous), while the record starts with a jump from 0 to its first sample
        assert rinaldi.values[0] != 0.0 and fm.samples[0] == 0.0

    def test_linearity(self, rinaldi):
        b = Building.modal([0.7, 0.25], [0.05, 0.04], [[0.5, 1.0], [1.0, -0.6]],
                           [1.2, -0.2])
        base = FloorMotion(rinaldi, b, floor=2)
        t = np.linspace(0.0, base.end, 7001)
        two = FloorMotion(rinaldi.scaled(2), b, floor=2)
        assert np.array_equal(two.acceleration(t), base.scaled(2).acceleration(t))
        assert np.array_equal(two.samples, 2 * base.samples)  # a power of 2: exact
        f = FloorMotion(rinaldi.scaled(-0.7), b, floor=2)
        np.testing.assert_allclose(f.acceleration(t), base.scaled(-0.7).acceleration(t),
                                   rtol=0, atol=1e-12 * base.pga)
        assert (-base).pga == base.pga
        # scaled is cheap: the floor samples are shared, not recomputed
        assert base.scaled(3.0).samples is base.samples

    def test_vertical_passes_through(self):
        gm = GroundMotion.builtin("rinaldi")
        b = Building.sdof(0.5)
        fm = FloorMotion(gm, b, floor=1)
        h_only = FloorMotion(gm.horizontal, b, floor=1)
        assert np.array_equal(fm.samples, h_only.samples)
        t = np.linspace(0, 30, 3001)
        assert np.array_equal(fm.vertical_acceleration(t), gm.vertical_acceleration(t))
        assert np.array_equal(fm.scaled(0.5).vertical_acceleration(t),
                              gm.scaled(0.5).vertical_acceleration(t))
        # the kernels see both: the vertical spec is the ground's
        from rocking.motions import _kernel as K
        kind, prm, samples = fm.spec()
        vs = np.array([K.vertical_acc(prm, samples, x) for x in t])
        assert np.array_equal(vs, gm.vertical_acceleration(t))

    def test_analytic_ground_is_sampled(self):
        pulse = OneSine(3.0, 0.5)
        b = Building.sdof(0.5)
        fm = FloorMotion(pulse, b, floor=1)
        assert fm.step == pytest.approx(pulse.scan_step / 4)
        # the pulse's window (10 s) or the ring-down, whichever ends later
        assert fm.duration == max(pulse.duration, fm.end) and fm.quiet_time == fm.end
        ref = scipy_floor(pulse.acceleration(np.arange(int(round(0.5 / fm.step)) + 1)
                                             * fm.step), fm.step, *b.modal_factors(floor=1),
                          floor_times(fm)[::10], 0.5)
        assert np.max(np.abs(fm.samples[::10] - ref)) < 1e-9 * np.max(np.abs(ref))
        fine = FloorMotion(pulse, b, floor=1, dt=0.001)
        assert fine.step == 0.001

    def test_record_substeps_by_dt(self, rinaldi):
        b = Building.sdof(0.5)
        coarse = FloorMotion(rinaldi, b, floor=1)
        fine = FloorMotion(rinaldi, b, floor=1, dt=0.0025)
        assert fine.step == pytest.approx(0.0025)
        # same exact values at the record's samples (the recurrence is exact)
        np.testing.assert_allclose(fine.samples[::4][:coarse.samples.size - 1],
                                   coarse.samples[:-1], rtol=0, atol=1e-9 * coarse.pga)

    def test_repr_name(self, rinaldi):
        fm = FloorMotion(rinaldi, Building.sdof(0.5, name="clinic"), floor=1)
        assert fm.name == "Rinaldi228 at floor 1 of clinic"
        r = repr(fm.scaled(2))
        assert r.startswith("FloorMotion('Rinaldi228' at floor 1 of 'clinic'")
        assert "scale=2" in r and len(r) < 140
        assert "the ground" in repr(FloorMotion(rinaldi, Building.sdof(0.5), floor=0))


# ------------------------------------------------------------------ rocking on a floor
def min_overturning_factor(block, motions, factors):
    """Smallest load factor of the ladder at which the block overturns (inf if none)."""
    res = rocking.simulate_many(block, [m.scaled(f) for m in motions for f in factors])
    over = res.overturned.reshape(len(motions), len(factors))
    return [factors[np.argmax(row)] if row.any() else math.inf for row in over]


class TestRockingOnAFloor:
    def test_tuned_building_overturns_the_block_at_a_lower_pga(self):
        block = rocking.Block.rectangular(0.2, 1.0)
        g_tan = 9.81 * math.tan(block.alpha)
        Tp = 0.5
        ground = OneSine(g_tan, Tp)  # a one-sine pulse at the uplift level
        floor = FloorMotion(ground, Building.sdof(Tp, 0.05), floor=1)
        factors = [0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0]
        on_ground, on_floor = min_overturning_factor(block, [ground, floor], factors)
        assert factors[0] < on_floor < math.inf  # the ladder starts below the minimum
        assert on_floor < on_ground, (on_floor, on_ground)

    def test_simulate_many_equals_simulate(self, rinaldi):
        block = rocking.Block.rectangular(0.2, 1.0)
        motions = [FloorMotion(rinaldi, Building.sdof(T, 0.05), floor=1).scaled(s)
                   for T, s in ((0.3, 0.3), (0.6, 0.5), (1.0, 0.4))]
        motions.append(FloorMotion(GroundMotion.builtin("rinaldi"), Building.sdof(0.5),
                                   floor=1).scaled(0.4))
        many = rocking.simulate_many(block, motions)
        single = [rocking.simulate(block, m) for m in motions]
        for name in ("max_abs_theta", "overturned", "uplift_time", "n_impacts",
                     "overturn_time"):
            ours = np.array([getattr(r, name) for r in single])
            assert np.array_equal(getattr(many, name), ours, equal_nan=True), name
        assert many.overturned.any() or many.max_abs_theta.max() > 0


# ------------------------------------------------------------------ spectra and codes
class TestFloorSpectrum:
    def test_rigid_oscillator_and_ground_floor(self, rinaldi):
        b = Building.sdof(0.5)
        T = np.array([0.0, 0.2, 0.5, 1.0])
        roof = floor_spectrum(rinaldi, b, floor=1, periods=T)
        fm = FloorMotion(rinaldi, b, floor=1)
        assert roof[0] == fm.pfa  # T = 0: the peak floor acceleration
        np.testing.assert_array_equal(roof, response_spectrum(fm.record, T))
        np.testing.assert_array_equal(floor_spectrum(fm, periods=T), roof)
        ground = floor_spectrum(rinaldi, b, floor=0, periods=T)
        np.testing.assert_array_equal(ground, response_spectrum(rinaldi, T))
        assert roof[2] > 2 * ground[2]  # resonance at the building's period

    def test_ec8_eq_4_25(self):
        # limiting cases of the formula: rigid element at the ground and on the roof,
        # resonance on the roof, the lower bound for long periods
        assert code_floor_spectrum_ec8(0.0, 2.0, 0.0, 0.6) == pytest.approx(2.0)
        assert code_floor_spectrum_ec8(0.0, 2.0, 1.0, 0.6) == pytest.approx(5.0)
        assert code_floor_spectrum_ec8(0.6, 2.0, 1.0, 0.6) == pytest.approx(11.0)
        assert code_floor_spectrum_ec8(0.6, 2.0, 0.5, 0.6) == pytest.approx(2 * 4.0)
        # the bracket reaches the lower bound 1 at Ta = 2 T1 (ground), (1 + sqrt 3) T1 (roof)
        Ta = np.array([2.0, 1.0 + math.sqrt(3.0)]) * 0.6
        np.testing.assert_allclose(code_floor_spectrum_ec8(Ta, 1.0, np.array([0.0, 1.0]),
                                                           0.6), 1.0)
        big = code_floor_spectrum_ec8(np.array([3.0, 10.0]), 1.0, 1.0, 0.6)
        np.testing.assert_array_equal(big, [1.0, 1.0])

    def test_asce7_hf(self):
        assert asce7_hf(0.0, 0.7) == 1.0
        assert asce7_hf(1.0, 0.4) == pytest.approx(3.5)  # a1 = 2.5, a2 = 0
        assert asce7_hf(1.0, 0.2) == pytest.approx(3.5)  # a1 capped, a2 floored
        assert asce7_hf(1.0, 1.0) == pytest.approx(1 + 1 + 0.84)
        assert asce7_hf(0.5, 2.0) == pytest.approx(1 + 0.25 + 0.96 / 1024)
        assert asce7_hf(0.6) == pytest.approx(2.5)  # Eq 13.3-5
        np.testing.assert_allclose(asce7_hf(np.array([0.0, 1.0]), 0.5),
                                   [1.0, 1 + 2.0 + (1 - 0.64)])

    def test_plot(self, rinaldi):
        matplotlib = pytest.importorskip("matplotlib")
        matplotlib.use("Agg")
        from matplotlib.figure import Figure
        b = Building.sdof(0.5)
        T = np.geomspace(0.05, 3.0, 30)
        ax = Figure().add_subplot()
        out = plot_floor_spectrum(ax, T, floor_spectrum(rinaldi, b, floor=1, periods=T),
                                  response_spectrum(rinaldi, T),
                                  references={"EN 1998-1 Eq 4.25":
                                              code_floor_spectrum_ec8(T, rinaldi.pga, 1.0,
                                                                      0.5)},
                                  units="g")
        assert out is ax and len(ax.lines) == 3 and ax.get_xscale() == "log"


# ------------------------------------------------------------------ errors
class TestErrors:
    @pytest.mark.parametrize(("kw", "words"), [
        ({"floor": 2}, r"floor must be an integer \[0, 1\]"),
        ({"floor": -1}, r"floor must be an integer \[0, 1\]"),
        ({"floor": 1, "height_ratio": 1.0}, "floor or height_ratio"),
        ({}, "floor or height_ratio"),
        ({"height_ratio": 1.5}, r"height_ratio must be in \[0, 1\]"),
        ({"floor": 1, "dt": 0.003}, r"dt must be the ground record's step 0.01 s divided"),
        ({"floor": 1, "dt": 0.02}, "dt must be the ground record's step"),
        ({"floor": 1, "dt": -0.01}, r"dt must be > 0 s"),
        ({"floor": 1, "scale": "x"}, "scale must be a finite number"),
    ])
    def test_bad_floor_motion(self, rinaldi, kw, words):
        with pytest.raises(ParameterError, match=words):
            FloorMotion(rinaldi, Building.sdof(0.5), **kw)

    def test_bad_objects(self, rinaldi):
        with pytest.raises(ParameterError, match="ground must be a rocking.motions.Motion"):
            FloorMotion(rinaldi.acc, Building.sdof(0.5), floor=1)
        with pytest.raises(ParameterError, match="building must be a rocking.buildings"):
            FloorMotion(rinaldi, 0.5, floor=1)
        with pytest.raises(ParameterError, match="damping"):
            FloorMotion(rinaldi, Building.sdof(0.5, 1e-9), floor=1)  # never rings down

    @pytest.mark.parametrize(("call", "words"), [
        (lambda: code_floor_spectrum_ec8(0.5, 1.0, 1.5, 0.5), r"z_over_H must be in \[0, 1\]"),
        (lambda: code_floor_spectrum_ec8(0.5, 1.0, 0.5, 0.0), "T1 must be > 0 s"),
        (lambda: code_floor_spectrum_ec8(-0.5, 1.0, 0.5, 0.5), "periods must be"),
        (lambda: code_floor_spectrum_ec8(0.5, -1.0, 0.5, 0.5), "ag_S must be >= 0"),
        (lambda: asce7_hf(-0.1, 0.5), r"z_over_h must be in \[0, 1\]"),
        (lambda: asce7_hf(0.5, 0.0), "Ta must be > 0 s"),
    ])
    def test_bad_code_inputs(self, call, words):
        with pytest.raises(ParameterError, match=words):
            call()

    def test_bad_floor_spectrum(self, rinaldi):
        b = Building.sdof(0.5)
        with pytest.raises(ParameterError, match="periods"):
            floor_spectrum(rinaldi, b, floor=1)
        with pytest.raises(ParameterError, match="kind must be one of"):
            floor_spectrum(rinaldi, b, floor=1, periods=[0.5], kind="xx")
        with pytest.raises(ParameterError, match="building"):
            floor_spectrum(rinaldi, periods=[0.5], floor=1)
        with pytest.raises(ParameterError, match="already has them"):
            floor_spectrum(FloorMotion(rinaldi, b, floor=1), b, periods=[0.5])
        with pytest.raises(ParameterError, match="damping"):
            floor_spectrum(rinaldi, b, floor=1, periods=[0.5], damping=1.0)


def test_docstring_examples():
    for mod in (floor_module, spectra_module):
        res = doctest.testmod(mod, optionflags=doctest.ELLIPSIS)
        assert res.failed == 0 and res.attempted > 0, mod.__name__
