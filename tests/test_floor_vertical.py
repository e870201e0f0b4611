"""Floor motions (issue 18): the vertical building filter, and convergence with the number
of modes of a continuous building.

Vertical: ``FloorMotion(ground, building, floor=k, vertical_building=vb)`` filters the
ground's vertical component by ``vb``'s modes at the same floor (Eq 1 of
:mod:`rocking.buildings.floor`). Checks: a building far stiffer than the record can excite
returns the ground's vertical (the rigid limit); an SDOF vertical filter agrees with an
independent scipy integration of its oscillator; a block feels the filtered vertical (it
lifts off on a floor tuned to a vertical sine that leaves it in contact on the ground);
floor 0 is the ground bit for bit; linearity.

Modes: the floor motion of Miranda and Taghavi's continuous building (a truncated modal
sum, :meth:`Building.continuous`) converges as modes are added: the peak difference
between ``n`` and ``2n`` modes decreases, and is small against the peak with many modes.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import rocking
from rocking.buildings import Building, FloorMotion
from rocking.errors import ParameterError
from rocking.motions import GroundMotion, Sine, load_builtin
from rocking.motions import _kernel as K


@pytest.fixture(scope="module")
def rinaldi():
    """Rinaldi228 with its vertical component RinaldiUP (1994 Northridge)."""
    return GroundMotion.builtin("rinaldi")


def sdof_absolute(acc, dt, T, zeta, t_eval):
    """Absolute acceleration ``-(2 zeta w u' + w^2 u)`` of an SDOF oscillator on a base
    ``acc`` (linear between samples of step ``dt``, zero after the last), from rest, at
    ``t_eval`` (multiples of ``dt``), by solve_ivp (DOP853, rtol 1e-12) one sample interval
    at a time, where the forcing is smooth."""
    w = 2 * math.pi / T
    A = np.array([[0.0, 1.0], [-w * w, -2 * zeta * w]])
    t_end = (acc.size - 1) * dt
    n_end = int(round(t_eval[-1] / dt))
    out = {0: 0.0}
    y = np.zeros(2)
    atol = 1e-15 * np.max(np.abs(acc)) * np.array([1 / w**2, 1 / w])
    for i in range(n_end):
        t0, t1 = i * dt, (i + 1) * dt
        a0, a1 = (acc[i], acc[i + 1]) if t1 <= t_end + 1e-9 * dt else (0.0, 0.0)
        s = (a1 - a0) / dt
        sol = solve_ivp(lambda t, yy, a0=a0, s=s, t0=t0:
                        A @ yy - np.array([0.0, a0 + s * (t - t0)]),
                        (t0, t1), y, method="DOP853", rtol=1e-12, atol=atol)
        assert sol.success
        y = sol.y[:, -1]
        out[i + 1] = -(2 * zeta * w * y[1] + w * w * y[0])
    return np.array([out[int(round(t / dt))] for t in t_eval])


# ------------------------------------------------------------------ vertical building
class TestVerticalBuilding:
    @pytest.mark.parametrize("building, vertical, where", [
        (Building.sdof(0.5), Building.sdof(1e-4, 0.05), {"floor": 1}),
        (Building.shear(3, 0.4), Building.shear(3, 1e-4), {"floor": 2}),
        (Building.continuous(0.8, 5.0, n_floors=4), Building.continuous(1e-4, 5.0),
         {"height_ratio": 0.5}),
    ])
    def test_a_very_stiff_vertical_building_returns_the_ground_vertical(
            self, rinaldi, building, vertical, where):
        """Vertical modes far above what the record (step 0.01 s) can excite follow the
        ground quasi-statically: the floor's vertical is the ground's at its samples, from
        the second one on (at t = 0 the building is at rest: the first sample of
        RinaldiUP, 1e-5 of its peak, is a jump that the modes do not follow, module
        docstring of rocking.buildings.floor)."""
        fm = FloorMotion(rinaldi, building, **where, vertical_building=vertical)
        v = rinaldi.vertical
        assert fm.vertical is not v  # filtered, not passed through
        t = v.t[1:]
        got = fm.vertical_acceleration(t)
        err = np.max(np.abs(got - v.values[1:])) / v.pga
        assert err < 1e-6, err
        # the horizontal component is the building's, as without a vertical building
        assert np.array_equal(fm.samples, FloorMotion(rinaldi, building, **where).samples)

    def test_an_sdof_vertical_filter_against_scipy(self, rinaldi):
        T, zeta = 0.1, 0.05
        fm = FloorMotion(rinaldi, Building.sdof(0.5), floor=1,
                         vertical_building=Building.sdof(T, zeta))
        v = rinaldi.vertical
        vf = fm.vertical
        assert vf.dt == pytest.approx(v.dt / 2)  # 20 steps per period of the 0.1 s mode
        # the record and 2 s of ring-down, on the ground's grid
        t = np.arange(int(round((v.duration + 2.0) / v.dt)) + 1) * v.dt
        ref = sdof_absolute(v.values, v.dt, T, zeta, t)
        peak = np.max(np.abs(ref))
        err = np.max(np.abs(fm.vertical_acceleration(t) - ref)) / peak
        assert err < 1e-6, err
        # the building amplifies a vertical mode of 0.1 s under this near-fault record
        assert vf.pga > 1.5 * v.pga
        # it rings down (below 1e-6 of the peak) after the ground stops
        assert vf.duration > v.duration
        assert fm.quiet_time >= vf.duration
        # the kernels see the filtered vertical
        _, prm, samples = fm.spec()
        ts = np.linspace(0.0, vf.duration, 1001)
        ks = np.array([K.vertical_acc(prm, samples, x) for x in ts])
        np.testing.assert_allclose(ks, fm.vertical_acceleration(ts), rtol=0,
                                   atol=1e-12 * vf.pga)

    def test_a_block_feels_the_filtered_vertical(self):
        """A 10 Hz vertical sine of 0.5 g leaves a block in contact on the ground
        (g + a_v >= 0.5 g); on a floor whose vertical mode is tuned to it (0.1 s, 5 %) it
        is amplified about 10 times and the base falls faster than gravity: lift-off."""
        h = Sine.from_acceleration(2.0, 0.02 * rocking.units.G, duration=3.0)
        v = Sine.from_acceleration(10.0, 0.5 * rocking.units.G, duration=3.0)
        ground = GroundMotion(h, v)
        block = rocking.Block.rectangular(0.2, 1.0)
        b = Building.sdof(0.5)
        on_ground = rocking.simulate(block, ground, duration=3.0)
        passes = rocking.simulate(block, FloorMotion(ground, b, floor=1), duration=3.0)
        fm = FloorMotion(ground, b, floor=1, vertical_building=Building.sdof(0.1, 0.05))
        tuned = rocking.simulate(block, fm, duration=3.0)
        assert not on_ground.lifted_off and not passes.lifted_off
        assert fm.vertical.pga > 5 * v.pga
        assert tuned.lifted_off
        # it lifts off where the floor's vertical first reaches -g
        t = np.arange(0.0, 3.0, 1e-4)
        first = t[np.argmax(fm.vertical_acceleration(t) <= -rocking.units.G)]
        assert tuned.lift_off_time == pytest.approx(first, abs=2e-3)

    def test_floor_zero_is_the_ground_bit_for_bit(self, rinaldi):
        for where in ({"floor": 0}, {"height_ratio": 0.0}):
            fm = FloorMotion(rinaldi, Building.sdof(0.5), **where,
                             vertical_building=Building.sdof(0.1))
            for a, b in zip(fm.spec(), rinaldi.spec(), strict=True):
                assert np.array_equal(a, b)
            assert fm.vertical is rinaldi.vertical

    def test_linear_in_the_ground(self, rinaldi):
        b, vb = Building.sdof(0.5), Building.sdof(0.1)
        base = FloorMotion(rinaldi, b, floor=1, vertical_building=vb)
        two = FloorMotion(rinaldi.scaled(2.0), b, floor=1, vertical_building=vb)
        assert np.array_equal(two.vertical.values, 2 * base.vertical.values)  # exact
        t = np.linspace(0.0, base.quiet_time, 2001)
        assert np.array_equal(base.scaled(0.5).vertical_acceleration(t),
                              0.5 * base.vertical_acceleration(t))

    def test_without_a_vertical_component_there_is_nothing_to_filter(self, rinaldi):
        fm = FloorMotion(rinaldi.horizontal, Building.sdof(0.5), floor=1,
                         vertical_building=Building.sdof(0.1))
        assert fm.vertical is None
        assert fm.vertical_acceleration(1.0) == 0.0

    @pytest.mark.parametrize("vertical, where, match", [
        ("stiff", {"floor": 1}, r"vertical_building must be a rocking\.buildings\.Building"),
        (Building.sdof(0.1), {"floor": 2},
         r"vertical_building: floor must be an integer \[0, 1\], got 2"),
        (Building.sdof(0.1, 0.0), {"floor": 1},
         r"vertical_building damping\[0\] must be in \(0, 1\)"),
    ])
    def test_bad_vertical_building(self, rinaldi, vertical, where, match):
        with pytest.raises(ParameterError, match=match):
            FloorMotion(rinaldi, Building.shear(3, 0.4), **where, vertical_building=vertical)


# ------------------------------------------------------------------ convergence with modes
def padded_difference(a: np.ndarray, b: np.ndarray) -> float:
    """max |a - b| over the longer record (the shorter one is zero after its end: the
    ring-down is cut when it is below 1e-6 of the peak)."""
    n = max(a.size, b.size)
    return float(np.max(np.abs(np.pad(a, (0, n - a.size)) - np.pad(b, (0, n - b.size)))))


@pytest.mark.parametrize("alpha", [0.0, 5.0, 30.0])
@pytest.mark.parametrize("height_ratio", [1.0, 0.5])
def test_continuous_floor_motion_converges_with_the_number_of_modes(alpha, height_ratio):
    """Issue 18: the truncated modal sum (B2) of Building.continuous converges as modes are
    added. Every run is on the same grid (dt = 1 ms: the record's step / 10; the
    recurrence is exact at any step), so the records compare sample by sample.

    Measured (T1 = 1 s, Rinaldi228; max|a_n - a_2n| / peak for n = 2, 4, 8, 16, then 25
    against 50): alpha 0 roof 7.3e-2, 6.2e-3, 8.0e-4, 1.1e-4, 6.1e-5; alpha 5 roof 1.6e-1,
    3.0e-2, 4.2e-3, 2.9e-4, 8.4e-5; alpha 30 roof 1.3e-1, 5.4e-2, 1.3e-2, 1.3e-3, 1.9e-4
    (mid-height: the same pattern, 2.2e-4 and 3.9e-4 at 25 against 50 for alpha 5, 30)."""
    ground = load_builtin("Rinaldi228")

    def floor(n):
        b = Building.continuous(1.0, alpha, damping=0.05, n_modes=n)
        return FloorMotion(ground, b, height_ratio=height_ratio, dt=ground.dt / 10).samples

    runs = {n: floor(n) for n in (2, 4, 8, 16, 25, 32, 50)}
    peak = float(np.max(np.abs(runs[50])))
    diffs = [padded_difference(runs[n], runs[2 * n]) / peak for n in (2, 4, 8, 16)]
    assert all(b < a for a, b in zip(diffs, diffs[1:], strict=False)), diffs
    assert diffs[-1] < 0.1 * diffs[0], diffs
    many = padded_difference(runs[25], runs[50]) / peak
    assert many < 1e-3, many
    # the building amplifies the ground: the modes converge to a floor motion, not to it
    assert peak > ground.pga
