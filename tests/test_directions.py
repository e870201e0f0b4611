"""Two horizontal components (rocking.motions.HorizontalPair) and the planar analysis in
every direction (rocking.analysis.direction_sweep): the projection's convention against an
independent vector computation, its linearity and invariance under a turn of the sensor
axes, the sweep at the components' own directions against the planar runs, the mirror
symmetry of phi + 180 deg, and the refusals."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

import rocking
from rocking.analysis import direction_sweep
from rocking.analysis.directions import worst_index
from rocking.errors import ParameterError
from rocking.motions import HorizontalPair, Record, load_builtin
from rocking.shapes import load_example

SUMMARY = ("max_abs_theta", "overturned", "overturn_time", "uplift_time", "n_impacts")


@pytest.fixture(scope="module")
def rinaldi():
    return HorizontalPair.builtin("rinaldi")


@pytest.fixture(scope="module")
def shape():
    return load_example()


@pytest.fixture(scope="module")
def short_pair():
    """Two synthetic orthogonal components without azimuths (5 s, 0.01 s)."""
    t = np.arange(501) * 0.01
    a1 = 3.0 * np.sin(2 * np.pi * 1.3 * t) * np.exp(-0.3 * t)
    a2 = 2.5 * np.sin(2 * np.pi * 0.9 * t + 0.7) * np.exp(-0.2 * t)
    return HorizontalPair(Record(a1, 0.01, name="c1"), Record(a2, 0.01, name="c2"))


def _same(row, resp):
    """A sweep's row equals a planar run bit for bit (NaN where both are NaN)."""
    for k in SUMMARY:
        a, b = row[k], getattr(resp, k)
        assert (a == b) or (np.isnan(a) and np.isnan(b)), (k, a, b)


def _bearing_vector(b):
    """The unit vector (east, north) of the compass bearing b (rad, clockwise from N)."""
    return np.array([math.sin(b), math.cos(b)])


# ------------------------------------------------------------------ the projection
def test_nga_azimuths_are_read_and_the_builtin_pairs_are_clockwise(rinaldi):
    assert rinaldi.azimuths_deg == pytest.approx((228.0, 318.0))
    assert rinaldi.handedness == 1 and rinaldi.vertical is not None
    duzce = HorizontalPair.builtin("duzce", vertical=False)
    assert duzce.azimuths_deg == pytest.approx((180.0, 270.0)) and duzce.vertical is None
    same = HorizontalPair.builtin("Rinaldi228", "Rinaldi318")
    np.testing.assert_array_equal(same.a1, rinaldi.a1)
    assert same.azimuths == rinaldi.azimuths


def test_projection_against_the_vector_of_the_ground_acceleration(rinaldi):
    """a_phi = a . e_phi with a = a1 n(A1) + a2 n(A2) in (east, north) and e_phi at the
    bearing orientation - phi (phi counter-clockwise looking down)."""
    a_vec = (rinaldi.a1[:, None] * _bearing_vector(rinaldi.azimuths[0])
             + rinaldi.a2[:, None] * _bearing_vector(rinaldi.azimuths[1]))
    for orient in (None, math.radians(10.0), math.radians(300.0)):
        o = rinaldi.azimuths[0] if orient is None else orient
        for phi in np.radians([0.0, 17.0, 90.0, 133.0, 250.0]):
            ref = a_vec @ _bearing_vector(o - phi)
            got = rinaldi.along(phi, orient).acc
            np.testing.assert_allclose(got, ref, rtol=0, atol=1e-12 * rinaldi.peak_resultant)


def test_components_on_their_own_axes_bit_for_bit(rinaldi, short_pair):
    r = rinaldi
    np.testing.assert_array_equal(r.along(0.0).acc, r.first.acc)
    # NGA pairs are numbered clockwise: the second is at -90 deg in a right-handed frame
    np.testing.assert_array_equal(r.along(-math.pi / 2).acc, r.second.acc)
    np.testing.assert_array_equal(r.along(math.pi / 2).acc, -r.second.acc)
    np.testing.assert_array_equal(r.along(0.0, orientation="318deg").acc, r.second.acc)
    np.testing.assert_array_equal(r.along(math.pi).acc, -r.first.acc)
    # no azimuths: a right-handed ground frame, first = x, second = y
    p = short_pair
    np.testing.assert_array_equal(p.along(0.0).acc, p.first.acc)
    np.testing.assert_array_equal(p.along(math.pi / 2).acc, p.second.acc)
    np.testing.assert_array_equal(p.along("90deg").acc, p.second.acc)


def test_projection_is_linear(short_pair):
    p = short_pair
    for phi in (0.3, 1.1, 2.5, -0.7, 4.0):
        np.testing.assert_array_equal(p.along(phi).acc,
                                      math.cos(phi) * p.a1 + math.sin(phi) * p.a2)
    # the load factor of the components is applied, and scaled() is linear
    q = HorizontalPair(p.first.scaled(2.0), p.second.scaled(-0.5))
    tol = 1e-14 * p.peak_resultant
    np.testing.assert_allclose(q.along(0.4).acc, 2.0 * math.cos(0.4) * p.a1
                               - 0.5 * math.sin(0.4) * p.a2, rtol=0, atol=tol)
    np.testing.assert_allclose(p.scaled(3.0).along(0.4).acc, 3.0 * p.along(0.4).acc,
                               rtol=0, atol=3 * tol)


def test_turning_the_sensor_axes_leaves_the_ground_motion_unchanged(rinaldi, short_pair):
    for pair in (rinaldi, short_pair):
        turned = pair.rotated(math.radians(90.0))
        # clockwise pair: the new first is the old second; counter-clockwise: minus it
        np.testing.assert_array_equal(turned.a1, pair.handedness * pair.a2)
        for d in (0.37, 2.0):
            t = pair.rotated(d)
            for phi in (0.0, 0.9, 2.2):
                o = math.radians(40.0)
                np.testing.assert_allclose(t.along(phi, o).acc, pair.along(phi, o).acc,
                                           rtol=0, atol=1e-12 * pair.peak_resultant)
    t = rinaldi.rotated("90deg")
    np.testing.assert_array_equal(t.a1, rinaldi.a2)
    np.testing.assert_array_equal(t.a2, -rinaldi.a1)


def test_peak_resultant_bounds_every_direction(rinaldi):
    phis = np.linspace(0.0, math.pi, 361)
    pgas = np.array([rinaldi.along(f).pga for f in phis])
    assert np.all(pgas <= rinaldi.peak_resultant * (1 + 1e-12))
    # the grid's step 0.5 deg: the best direction within cos(0.25 deg) of the resultant
    assert pgas.max() >= rinaldi.peak_resultant * math.cos(math.radians(0.25)) - 1e-12
    assert pgas.max() >= max(rinaldi.pga_components)


def test_shorter_component_is_padded_with_zeros():
    a = Record(np.linspace(0.0, 1.0, 11), 0.1)
    b = Record(np.ones(6), 0.1)
    p = HorizontalPair(a, b)
    assert p.n == 11 and p.duration == pytest.approx(1.0)
    np.testing.assert_array_equal(p.along(math.pi / 2).acc, np.r_[np.ones(6), np.zeros(5)])


# ------------------------------------------------------------------ the sweep
def test_sweep_at_the_components_equals_the_planar_runs(shape, rinaldi):
    """phi = 0: the planar block of direction 0 under the first component; phi = -90 deg
    (the second component of the clockwise NGA pair): bit for bit, through
    rocking.simulate; also with a load factor and with the vertical component."""
    block = rocking.Block.from_shape
    sw = direction_sweep(shape, rinaldi, [0.0, -math.pi / 2], vertical=False)
    _same(sw.table.iloc[0], rocking.simulate(block(shape, 0.0), rinaldi.first))
    _same(sw.table.iloc[1], rocking.simulate(block(shape, -math.pi / 2), rinaldi.second))
    sw = direction_sweep(shape, rinaldi, [0.0], scale=0.6, vertical=False)
    _same(sw.table.iloc[0], rocking.simulate(block(shape, 0.0), rinaldi.first.scaled(0.6)))
    sw = direction_sweep(shape, rinaldi, [0.0], scale=0.6)
    gm = rocking.motions.GroundMotion(rinaldi.first, load_builtin("RinaldiUP")).scaled(0.6)
    _same(sw.table.iloc[0], rocking.simulate(block(shape, 0.0), gm))


def test_sweep_at_90_degrees_of_a_counter_clockwise_pair(shape, short_pair):
    sw = direction_sweep(shape, short_pair.scaled(1.5), [math.pi / 2])
    _same(sw.table.iloc[0], rocking.simulate(rocking.Block.from_shape(shape, math.pi / 2),
                                             short_pair.second.scaled(1.5)))


def test_phi_plus_180_is_the_mirror_image(shape, rinaldi):
    """The planar block of phi + 180 deg is that of phi with its sides swapped, under the
    negated acceleration: theta is negated, so the peaks on the two sides swap and max
    |theta|, the overturning and the times are the same."""
    phis = np.radians([0.0, 40.0, 75.0])
    a = direction_sweep(shape, rinaldi, phis, scale=0.5, vertical=False).table
    b = direction_sweep(shape, rinaldi, phis + math.pi, scale=0.5, vertical=False).table
    np.testing.assert_allclose(b.alpha_plus, a.alpha_minus, rtol=1e-12)
    np.testing.assert_allclose(b.max_abs_theta, a.max_abs_theta, rtol=1e-9, atol=1e-12)
    np.testing.assert_array_equal(b.overturned, a.overturned)
    np.testing.assert_allclose(b.uplift_time, a.uplift_time, rtol=1e-9)
    np.testing.assert_allclose(b.max_abs_theta_over_alpha, a.max_abs_theta_over_alpha,
                               rtol=1e-6)
    np.testing.assert_allclose(b.uplift_demand, a.uplift_demand, rtol=1e-12)
    # a symmetric block: the mirror image under the negated record
    blk = rocking.Block.rectangular(0.3, 1.2)
    s = direction_sweep(blk, rinaldi, [0.6, 0.6 + math.pi], vertical=False).table
    assert s.max_abs_theta[0] == pytest.approx(s.max_abs_theta[1], rel=1e-9, abs=1e-12)
    assert s.overturned[0] == s.overturned[1]


def test_a_symmetric_block_responds_at_least_as_much_as_to_either_component(rinaldi):
    """A block the same in every direction (a cylinder-like footprint): the sweep's
    largest response is at least the planar response to either component."""
    blk = rocking.specimen(2)
    pair = rinaldi.scaled(0.25)
    sw = direction_sweep(blk, pair, 24, vertical=False)
    worst = sw.table.max_abs_theta.max()
    for rec in (pair.first, pair.second):
        r = rocking.simulate(blk, rec)
        assert worst >= r.max_abs_theta
    assert sw.worst["max_abs_theta"] == worst or sw.worst["overturned"]
    # the pga of each direction is bounded by the resultant and reaches the components'
    assert sw.table.pga.max() <= pair.peak_resultant * (1 + 1e-12)
    assert sw.table.pga.max() >= max(pair.pga_components) * (1 - 1e-12)


def test_uplift_demand_is_the_static_uplift_criterion(shape, rinaldi):
    """A direction whose demand is below 1 never lifts the block from rest; one above 1
    does (the classical model lifts off at |a| = g tan alpha_side)."""
    sw = direction_sweep(shape, rinaldi, 12, scale=0.5, vertical=False).table
    below = sw[sw.uplift_demand < 0.999]
    above = sw[sw.uplift_demand > 1.001]
    assert len(below) and len(above)
    assert below.max_abs_theta.eq(0.0).all() and below.uplift_time.isna().all()
    assert above.uplift_time.notna().all()


def test_worst_direction_ranking():
    t = pd.DataFrame({"overturned": [False, True, True, False],
                      "overturn_time": [np.nan, 5.0, 3.0, np.nan],
                      "max_abs_theta_over_alpha": [0.9, 5.0, 5.0, 0.2],
                      "uplift_demand": [2.0, 2.0, 2.0, 9.0]})
    assert worst_index(t) == 2  # overturned earliest
    t.loc[:, "overturned"] = False
    assert worst_index(t) in (1, 2)  # the largest rotation
    t.loc[:, "max_abs_theta_over_alpha"] = 0.0
    assert worst_index(t) == 3  # nothing rocks: the largest uplift demand


def test_worst_direction_of_the_sweep_is_flagged(shape, rinaldi):
    sw = direction_sweep(shape, rinaldi, 6, scale=0.5, vertical=False)
    assert sw.table.worst.sum() == 1
    assert sw.table[sw.table.worst].index[0] == sw.worst.name
    assert sw.worst_phi == sw.worst["phi"]
    fig = sw.plot()
    assert fig.axes and fig.axes[0].name == "polar"


# ------------------------------------------------------------------ refusals
def test_bad_pairs(rinaldi):
    r1, r2 = rinaldi.first, rinaldi.second
    with pytest.raises(ParameterError, match="second: its time step"):
        HorizontalPair(r1, r2.resampled(0.005))
    with pytest.raises(ParameterError, match="azimuths must be orthogonal"):
        HorizontalPair(r1, r2, azimuths=("228deg", "300deg"))
    with pytest.raises(ParameterError, match="azimuths must be two angles"):
        HorizontalPair(r1, r2, azimuths=1.0)
    with pytest.raises(ParameterError, match="first must be a rocking.motions.Record"):
        HorizontalPair(np.ones(10), r2)
    with pytest.raises(ParameterError, match="vertical must be"):
        HorizontalPair(r1, r2, vertical=np.ones(3))
    with pytest.raises(ParameterError, match="name must be a three-component set"):
        HorizontalPair.builtin("nowhere")
    with pytest.raises(ParameterError, match="phi"):
        rinaldi.along(float("nan"))
    with pytest.raises(ParameterError, match="orientation"):
        rinaldi.along(0.0, orientation="north")
    with pytest.raises(ParameterError, match="factor"):
        rinaldi.scaled(float("inf"))


def test_bad_sweeps(shape, rinaldi):
    with pytest.raises(ParameterError, match="pair must be"):
        direction_sweep(shape, rinaldi.first)
    with pytest.raises(ParameterError, match="body must be"):
        direction_sweep("statue.ply", rinaldi)
    with pytest.raises(ParameterError, match="directions"):
        direction_sweep(shape, rinaldi, [])
    with pytest.raises(ParameterError, match="directions"):
        direction_sweep(shape, rinaldi, [0.0, float("nan")])
    with pytest.raises(ParameterError, match="directions"):
        direction_sweep(shape, rinaldi, 0)
    with pytest.raises(ParameterError, match="scale must be > 0"):
        direction_sweep(shape, rinaldi, scale=0.0)
    with pytest.raises(ParameterError, match="vertical must be True or False"):
        direction_sweep(shape, rinaldi, vertical="yes")
    with pytest.raises(ParameterError, match="body\\(phi\\) must return"):
        direction_sweep(lambda phi: 3.0, rinaldi, [0.0])


def test_uplift_side_of_an_asymmetric_block():
    """A positive acceleration lifts the block on side + (Eq 1's sign), at g tan
    alpha_plus: a one-signed pulse between the two sides' uplift accelerations lifts an
    asymmetric block in one direction and not in the opposite one, as uplift_demand says."""
    blk = rocking.Block.from_geometry(0.6, 0.25, 0.15, 0.35, mass=100.0)
    assert blk.alpha_plus > blk.alpha_minus
    amp = 0.5 * (math.tan(blk.alpha_plus) + math.tan(blk.alpha_minus)) * 9.80665
    t = np.arange(201) * 0.005
    pulse = amp * np.sin(np.pi * t / t[-1])
    pair = HorizontalPair(Record(pulse, 0.005), Record(np.zeros(201), 0.005))
    sw = direction_sweep(blk, pair, [0.0, math.pi], duration=3.0).table
    assert sw.uplift_demand[0] < 1.0 < sw.uplift_demand[1]
    assert np.isnan(sw.uplift_time[0]) and sw.max_abs_theta[0] == 0.0
    assert np.isfinite(sw.uplift_time[1]) and sw.max_theta_minus[1] > 0.0
    assert sw.max_theta_plus[1] <= sw.max_theta_minus[1]


# ------------------------------------------------------------------ fragility per direction
def test_direction_fragility_runs_are_the_sweeps_runs(shape, rinaldi, short_pair):
    """Each run of the fragility batch equals the sweep of its pair at its load factor
    (the same planar block and projected motion), and the levels are the pairs' IM."""
    from rocking.analysis import direction_fragility
    from rocking.analysis.directions import pair_im

    pairs = [rinaldi, short_pair]
    levels = np.array([[2.0, 6.0], [3.0, 9.0]])
    phis = np.radians([0.0, 50.0, 110.0])
    fr = direction_fragility(shape, pairs, levels, phis, im="resultant", vertical=False,
                             n_boot=0)
    assert len(fr.runs) == 2 * 2 * 3 and len(fr.table) == 3
    for r in fr.runs.itertuples():
        pair = pairs[r.pair]
        assert r.scale * pair_im(pair, "resultant") == pytest.approx(r.level, rel=1e-12)
        sw = direction_sweep(shape, pair, [phis[r.direction]], scale=r.scale,
                             vertical=False).table.iloc[0]
        assert sw.max_abs_theta == r.max_abs_theta and sw.overturned == r.overturned
    assert (fr.table.n_overturned == fr.runs.groupby("direction").overturned.sum()).all()
    assert pair_im(rinaldi, "geomean") <= pair_im(rinaldi, "larger") \
        <= pair_im(rinaldi, "resultant")


def test_direction_fragility_of_a_symmetric_block_is_mirror_symmetric(rinaldi):
    from rocking.analysis import direction_fragility

    blk = rocking.specimen(2)
    fr = direction_fragility(blk, rinaldi, np.geomspace(0.5, 6.0, 10), [0.4, 0.4 + math.pi],
                             vertical=False, n_boot=0)
    a, b = fr.table.iloc[0], fr.table.iloc[1]
    assert a.n_overturned == b.n_overturned
    for k in ("median", "median_lower_bound", "median_upper_bound"):
        assert a[k] == pytest.approx(b[k], rel=1e-9, nan_ok=True)


def test_direction_fragility_leaves_out_the_runs_that_lift_off(rinaldi):
    """Where the scaled vertical component exceeds g the planar block leaves the ground and
    its run stops (lifted_off): neither an overturn nor a survival. Counted as survivals
    (the old behaviour) they would lower P(overturn) at the strongest levels; they are
    left out of the fit and counted in n_lifted_off."""
    from rocking.analysis import direction_fragility

    blk = rocking.specimen(2)
    levels = np.geomspace(2.0, 20.0, 8)  # m/s^2: the vertical (0.96 g at 8.6) exceeds g
    fr = direction_fragility(blk, rinaldi, levels, [0.0], n_boot=0)
    lifted = fr.runs.lifted_off.to_numpy()
    assert lifted.any() and not lifted.all()
    row = fr.table.iloc[0]
    assert row.n_lifted_off == lifted.sum() and row.n == (~lifted).sum()
    assert row.n_overturned == fr.runs.overturned[~lifted].sum()


def test_direction_fragility_refusals(shape, rinaldi):
    from rocking.analysis import direction_fragility

    with pytest.raises(ParameterError, match="pairs must be"):
        direction_fragility(shape, [], [1.0])
    with pytest.raises(ParameterError, match="im must be one of"):
        direction_fragility(shape, rinaldi, [1.0], im="rotd50")
    with pytest.raises(ParameterError, match="levels must be finite and > 0"):
        direction_fragility(shape, rinaldi, [1.0, -2.0])
    with pytest.raises(ParameterError, match="one row per pair"):
        direction_fragility(shape, [rinaldi, rinaldi], np.ones((3, 2)))


def test_pair_from_files_reads_the_azimuths(rinaldi):
    paths = [rinaldi.first.meta["path"], rinaldi.second.meta["path"],
             rinaldi.vertical.meta["path"]]
    p = HorizontalPair.from_files(*paths)
    assert p.azimuths == rinaldi.azimuths and p.vertical is not None
    np.testing.assert_array_equal(p.a2, rinaldi.a2)
    q = HorizontalPair.from_files(*paths[:2], azimuths=None)
    assert q.azimuths is None and q.handedness == -1 and q.vertical is None
    r = HorizontalPair.builtin("Rinaldi228", "Rinaldi318", vertical="RinaldiUP")
    np.testing.assert_array_equal(r.vertical.acc, rinaldi.vertical.acc)
