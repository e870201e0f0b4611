"""Asymmetric planar blocks (issue 20): Block.from_geometry, its per-side parameters and
the restitution from angular momentum about the new pivot."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rocking import Block
from rocking.errors import ParameterError
from rocking.units import G


def _rel(a, b):
    return abs(a - b) / abs(b)


# ---------------------------------------------------------------------- the Block API
@pytest.mark.parametrize("width,height", [(0.17, 0.75), (0.25, 1.0), (0.6, 0.9), (1.0, 1.2)])
def test_rectangle_from_geometry_is_eqs_2_to_4(width, height):
    """b_plus = b_minus = b, r_g^2 = (b^2 + h^2)/3: Eqs 2, 3 and 4 of a rectangle."""
    b, h = width / 2, height / 2
    ref = Block.rectangular(width, height)
    blk = Block.from_geometry(h, b, b, math.sqrt((b * b + h * h) / 3.0))
    assert blk.symmetric
    for got, want in ((blk.alpha, ref.alpha), (blk.p, ref.p), (blk.R, ref.R),
                      (blk.mu, 1.0 - 1.5 * math.sin(ref.alpha) ** 2),
                      (blk.p, math.sqrt(3 * G / (4 * ref.R)))):
        assert _rel(got, want) <= 1e-15
    for s in ("plus", "minus"):
        for k in ("alpha", "p", "mu", "R"):
            assert getattr(blk, f"{k}_{s}") == getattr(blk, k)


def test_existing_blocks_are_symmetric_and_unchanged():
    """Every existing constructor gives a symmetric block whose side attributes are its
    alpha, p, mu, R; equality and hash do not see the new field."""
    from rocking import specimen

    blocks = [Block.rectangular(0.2, 0.8), Block.rectangular(0.2, 0.8, corner_cut=0.01),
              Block.from_params(0.2, 3.0, 0.9), specimen(2),
              Block.polygon([(-0.1, 0), (0.1, 0), (0.05, 0.6), (-0.05, 0.6)])]
    for b in blocks:
        assert b.symmetric and b.sides is None
        assert (b.alpha_plus, b.alpha_minus, b.p_plus, b.p_minus) == (b.alpha, b.alpha,
                                                                      b.p, b.p)
        assert (b.mu_plus, b.mu_minus, b.R_plus, b.R_minus) == (b.mu, b.mu, b.R, b.R)
    a, b = Block.rectangular(0.2, 0.8), Block.rectangular(0.2, 0.8)
    assert a == b and hash(a) == hash(b)
    # the hash is that of the fields the block had before asymmetric blocks existed
    fields = (a.alpha, a.p, a.mu, a.R, a.mass, a.I_O, a.width, a.height, a.thickness,
              a.name, a.vertices)
    assert hash(a) == hash(fields)


def test_asymmetric_sides_and_weaker_side():
    h, bp, bm, rg = 0.5, 0.08, 0.14, 0.2
    blk = Block.from_geometry(h, bp, bm, rg, mass=12.0, name="x")
    assert not blk.symmetric
    for s, b in (("plus", bp), ("minus", bm)):
        R = math.hypot(b, h)
        assert getattr(blk, f"alpha_{s}") == pytest.approx(math.atan2(b, h), rel=1e-15)
        assert getattr(blk, f"R_{s}") == pytest.approx(R, rel=1e-15)
        assert getattr(blk, f"p_{s}") == pytest.approx(math.sqrt(G * R / (rg * rg + R * R)),
                                                      rel=1e-14)
    # the weaker side (+: the smaller b) gives the one-number summaries
    assert (blk.alpha, blk.p, blk.mu, blk.R) == (blk.alpha_plus, blk.p_plus, blk.mu_plus,
                                                 blk.R_plus)
    assert blk.uplift_acceleration == pytest.approx(G * bp / h, rel=1e-14)
    assert blk.I_O == pytest.approx(12.0 * (rg * rg + blk.R_plus ** 2), rel=1e-15)
    assert blk.alphas == (blk.alpha_plus, blk.alpha_minus)
    # the mirror image swaps the sides; the weaker side is then "-"
    m = blk.mirrored()
    assert (m.alpha_plus, m.mu_plus, m.p_plus) == (blk.alpha_minus, blk.mu_minus, blk.p_minus)
    assert (m.alpha, m.mu) == (blk.alpha_plus, blk.mu_plus)
    assert m == Block.from_geometry(h, bm, bp, rg, mass=12.0, name="x")
    assert m != blk and m.mirrored() == blk
    # one mu for both sides
    one = Block.from_geometry(h, bp, bm, rg, mu=0.9)
    assert one.mu_plus == one.mu_minus == 0.9 and not one.symmetric
    # with_params on the sides
    w = blk.with_params(mu=0.8)
    assert (w.mu_plus, w.mu_minus, w.alpha_minus) == (0.8, 0.8, blk.alpha_minus)
    w = blk.with_params(alpha_plus=0.5)  # now "-" is the weaker side
    assert (w.alpha, w.p) == (blk.alpha_minus, blk.p_minus)
    with pytest.raises(ParameterError, match="alpha_plus or alpha_minus"):
        blk.with_params(alpha=0.1)


def _impact_ratio(h, b_old, b_new, rg):
    """omega'/omega of an impact ending rocking about the pivot at distance b_old (on
    one side of the centre of mass), the body landing on the pivot at distance b_new on
    the other side: the velocities of the centre of mass before and after, and the
    angular momentum about the new pivot (the impulse acts there), written out."""
    c = np.array([0.0, h])  # centre of mass
    o_old, o_new = np.array([-b_old, 0.0]), np.array([b_new, 0.0])
    omega = -1.7  # any value: the ratio does not depend on it

    def cross(a, b):
        return a[0] * b[1] - a[1] * b[0]

    def momentum(pivot, w):  # angular momentum about o_new, unit mass
        r = c - pivot
        v = w * np.array([-r[1], r[0]])  # v = omega e_z x (c - pivot)
        return rg * rg * w + cross(c - o_new, v)

    before = momentum(o_old, omega)
    after_per_unit = momentum(o_new, 1.0)  # rotation about the new pivot
    return before / after_per_unit / omega


def test_restitution_is_angular_momentum_about_the_new_pivot():
    rng = np.random.default_rng(20)
    for _ in range(200):
        h = rng.uniform(0.1, 2.0)
        bp, bm = rng.uniform(0.02, 0.6, size=2) * h
        rg = rng.uniform(0.2, 1.0) * math.hypot(max(bp, bm), h)
        try:
            blk = Block.from_geometry(h, bp, bm, rg)
        except ParameterError:  # a squat body: no positive restitution
            assert min(_impact_ratio(h, bp, bm, rg), _impact_ratio(h, bm, bp, rg)) <= 0
            continue
        assert blk.mu_plus == pytest.approx(_impact_ratio(h, bp, bm, rg), rel=1e-12)
        assert blk.mu_minus == pytest.approx(_impact_ratio(h, bm, bp, rg), rel=1e-12)


@pytest.mark.parametrize("args,kw,match", [
    ((0.0, 0.1, 0.1, 0.2), {}, r"h must be > 0"),
    ((-1, 0.1, 0.1, 0.2), {}, r"h must be > 0"),
    ((0.5, 0.0, 0.1, 0.2), {}, r"b_plus must be > 0"),
    ((0.5, 0.1, -0.1, 0.2), {}, r"b_minus must be > 0"),
    ((0.5, 0.1, 0.1, 0.0), {}, r"radius_of_gyration must be > 0"),
    ((0.5, 0.1, float("nan"), 0.2), {}, r"b_minus must be a finite number"),
    ((0.5, 0.1, 0.1, 0.2), {"mu": 1.5}, r"mu must be in"),
    ((0.5, 0.1, 0.1, 0.2), {"mu": -0.1}, r"mu must be in"),
    ((0.5, 0.1, 0.1, 0.2), {"mass": 0}, r"mass must be > 0"),
    ((0.2, 0.5, 0.5, 0.05), {}, r"restitution .* <= 0 .* pass mu"),
])
def test_bad_geometry_is_refused(args, kw, match):
    with pytest.raises(ParameterError, match=match):
        Block.from_geometry(*args, **kw)


def test_from_mesh_delegates_to_shapes(tmp_path):
    """Block.from_mesh is Block.from_shape of the loaded mesh, its ``direction`` in degrees
    (a number, a string with its unit, or a named direction) as everywhere a user gives it
    (a box: a symmetric block in its principal direction, Eqs 2-4 to the precision of the
    mesh's mass properties)."""
    import trimesh

    from rocking.shapes import load_shape

    path = tmp_path / "box.stl"
    trimesh.creation.box(extents=(0.3, 0.2, 1.0)).export(path)
    shape = load_shape(path, density=2000.0)
    for given, phi in ((0.0, 0.0), (57.0, math.radians(57.0)), ("1rad", 1.0),
                       ("weakest", shape.weakest().phi)):
        blk = Block.from_mesh(path, density=2000.0, direction=given)
        assert blk == Block.from_shape(shape, phi)
    blk = Block.from_mesh(path, density=2000.0)
    ref = Block.rectangular(0.3, 1.0)
    assert blk.symmetric
    for k in ("alpha", "p", "mu"):
        assert getattr(blk, k) == pytest.approx(getattr(ref, k), rel=1e-6)
    assert blk.mass == pytest.approx(2000.0 * 0.3 * 0.2 * 1.0, rel=1e-6)  # STL: float32


# ---------------------------------------------------------------------- the models
from rocking import simulate, simulate_many  # noqa: E402
from rocking.motions import GroundMotion, OneSine, Record, Sine  # noqa: E402
from rocking.testing.housner_reference import simulate_reference  # noqa: E402
from rocking.testing.records import random_record  # noqa: E402

# a body whose centre of mass is off-centre (b_plus < b_minus): "+" is the weaker side
ASYM = Block.from_geometry(0.45, 0.07, 0.12, 0.22, name="asym")
SIDES = ("plus", "minus")


def _side(blk, s):
    """(alpha, p, mu) of side s (+1/-1)."""
    k = "plus" if s > 0 else "minus"
    return tuple(getattr(blk, f"{q}_{k}") for q in ("alpha", "p", "mu"))


def test_asymmetric_block_is_really_asymmetric():
    a_p, p_p, m_p = _side(ASYM, 1)
    a_m, p_m, m_m = _side(ASYM, -1)
    assert a_m / a_p > 1.6 and abs(p_m / p_p - 1) > 5e-3 and abs(m_m / m_p - 1) > 0.03


@pytest.mark.parametrize("model", ["housner", "ccrr"])
def test_sides_differing_only_in_mu_run_as_the_symmetric_block_until_the_first_impact(model):
    """The kernel selects the side's parameters with the same arithmetic: a block whose
    sides differ only in mu follows the symmetric block bit for bit until its first
    impact (and, in the batch, row by row)."""
    sym = Block.from_params(0.2, 3.0, 0.9)
    asym = sym.with_params(mu_minus=0.8)
    assert not asym.symmetric and asym.alpha_minus == sym.alpha
    m = OneSine(0.26 * G, 0.6, duration=4.0)
    a = simulate(sym, m, model=model, dt_out=1e-3)
    b = simulate(asym, m, model=model, dt_out=1e-3)
    assert a.n_impacts > 2
    assert a.uplift_time == b.uplift_time
    before = a.t[:b.t.size] < a.impact_times[0] - 1e-3
    assert before.sum() > 100
    if model == "housner":
        assert np.array_equal(a.theta[:b.t.size][before], b.theta[before])
        assert a.impact_times[0] == b.impact_times[0]
    else:  # CCRR's damping acts (weakly) along the whole excursion, not at impacts only
        np.testing.assert_allclose(a.theta[:b.t.size][before], b.theta[before], rtol=0,
                                   atol=1e-9)
    n = min(a.t.size, b.t.size)
    assert not np.array_equal(a.theta[:n], b.theta[:n])  # side - has another restitution


def _until_first_impact(a, b):
    """The histories of two runs before the first impact of ``a``."""
    n = min(a.t.size, b.t.size)
    before = a.t[:n] < a.impact_times[0] if a.n_impacts else np.ones(n, dtype=bool)
    return a.theta[:n][before], b.theta[:n][before], before.sum()


@pytest.mark.parametrize("model", ["housner", "ccrr"])
def test_rocking_on_one_side_is_the_symmetric_kernel_bit_for_bit(model):
    """On side + (the weaker side, with the larger p: the same step sizes and error norm)
    the asymmetric kernel does the arithmetic of the symmetric block (alpha_+, p_+, mu_+)
    until the first impact: the same bits, in single runs and in a batch, with and
    without a vertical component. (That equal sides reproduce the symmetric kernel of
    before asymmetric blocks, bit for bit, was checked against the previous version:
    every CSV and figure of ``rocking reproduce`` identical.)"""
    sym = Block.from_params(ASYM.alpha_plus, ASYM.p_plus, ASYM.mu_plus)
    assert ASYM.alpha_minus > ASYM.alpha_plus and ASYM.p_minus < ASYM.p_plus
    ms = [OneSine(0.4 * G, 0.5, duration=3.0), OneSine(0.25 * G, 0.8, duration=3.0),
          GroundMotion(OneSine(0.3 * G, 0.6, duration=3.0), Sine(3.0, 0.01, 3.0)),
          GroundMotion(OneSine(0.3 * G, 0.6, duration=3.0), random_record(8, 3.0, 3.0))]
    batch_a = simulate_many(sym, ms, model=model, return_histories=True)
    batch_b = simulate_many(ASYM, ms, model=model, return_histories=True)
    for i, m in enumerate(ms):
        a = simulate(sym, m, model=model)
        b = simulate(ASYM, m, model=model)
        assert a.uplift_time == b.uplift_time and a.theta[a.theta != 0][0] > 0  # side +
        x, y, n = _until_first_impact(a, b)
        assert n > 20 and np.array_equal(x, y)
        if a.n_impacts and model == "housner":
            assert a.impact_times[0] == b.impact_times[0]
        elif a.n_impacts:  # CCRR's steps of an asymmetric block land on the passage
            assert a.impact_times[0] == pytest.approx(b.impact_times[0], abs=1e-9)
        else:
            assert a.overturned and b.overturned and a.overturn_time == b.overturn_time
        k = min(n, batch_a.theta.shape[1])
        assert np.array_equal(batch_a.theta[i, :k], x[:k])
        assert np.array_equal(batch_b.theta[i, :k], y[:k])


def _ramp(slope, t_end=3.0, dt=0.01):
    t = np.arange(int(round(t_end / dt)) + 1) * dt
    return Record(slope * t, dt, name="ramp")


@pytest.mark.parametrize("impl", [simulate, simulate_reference], ids=["compiled", "reference"])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_uplift_at_g_tan_alpha_of_each_side(impl, sign):
    """A slow ramp a = +-k t uplifts the block at rest when |a| reaches g tan(alpha_s) of
    the side it pushes towards (s = sign(a)), and it rocks towards that side."""
    k = 1.0  # m/s^3
    alpha_s = ASYM.alpha_plus if sign > 0 else ASYM.alpha_minus
    t_up = G * math.tan(alpha_s) / k
    r = impl(ASYM, _ramp(sign * k), duration=t_up + 0.05)
    assert r.uplift_time == pytest.approx(t_up, abs=1e-9)
    moved = np.flatnonzero(r.theta != 0.0)
    assert np.sign(r.theta[moved[0]]) == sign
    # the other side's (lower or higher) threshold plays no role
    other = ASYM.alpha_minus if sign > 0 else ASYM.alpha_plus
    assert abs(G * math.tan(other) / k - t_up) > 0.3


@pytest.mark.parametrize("model", ["housner", "ccrr"])
def test_uplift_with_a_vertical_component_uses_the_sides_threshold(model):
    """Uplift towards s when |a_h| > (g + a_v) tan(alpha_s): a constant a_v = 0.2 g."""
    k = 1.0
    ones = np.ones(401)
    for sign, alpha_s in ((1.0, ASYM.alpha_plus), (-1.0, ASYM.alpha_minus)):
        gm = GroundMotion(_ramp(sign * k, 4.0), Record(0.2 * G * ones, 0.01))
        t_up = 1.2 * G * math.tan(alpha_s) / k
        r = simulate(ASYM, gm, model=model, duration=t_up + 0.05)
        assert r.uplift_time == pytest.approx(t_up, abs=1e-9)


def _free_run(blk, s, model="housner", duration=None, dt_out=1e-4):
    """Free rocking from 0.4 alpha_+ (side +) or 0.15 alpha_- (side -: the block lands on
    its weaker side +), released at rest."""
    th0 = s * (0.4 if s > 0 else 0.15) * _side(blk, s)[0]
    dur = duration or 3.0
    return simulate(blk, None, model=model, duration=dur, theta0=th0, dt_out=dt_out,
                    rtol=1e-10 if model == "housner" else 1e-8)


def _energy(om, th, alpha, p):
    return 0.5 * om * om + p * p * math.cos(alpha - abs(th))


@pytest.mark.parametrize("s", [1.0, -1.0])
def test_impact_restitution_is_the_angular_momentum_ratio(s):
    """The velocities just before and after the first impact (from the energy of each side,
    exact in free rocking) have the ratio of the independent angular-momentum
    computation: mu_s for an impact ending rocking on side s."""
    h, bp, bm, rg = 0.45, 0.07, 0.12, 0.22
    r = _free_run(ASYM, s)
    a_s, p_s, _ = _side(ASYM, s)
    a_o, p_o, _ = _side(ASYM, -s)
    th0 = (0.4 if s > 0 else 0.15) * a_s
    om_before = math.sqrt(2 * p_s ** 2 * (math.cos(a_s - th0) - math.cos(a_s)))
    t1, t2 = r.impact_times[:2]
    seg = (r.t > t1) & (r.t < t2)
    r1 = np.abs(r.theta[seg]).max()  # the excursion on the other side
    assert np.all(np.sign(r.theta[seg][np.abs(r.theta[seg]) > 1e-9]) == -s)
    om_after = math.sqrt(2 * p_o ** 2 * (math.cos(a_o - r1) - math.cos(a_o)))
    want = _impact_ratio(h, bp, bm, rg) if s > 0 else _impact_ratio(h, bm, bp, rg)
    assert om_after / om_before == pytest.approx(want, rel=1e-6)


def test_energy_of_each_side_is_conserved_between_impacts():
    r = _free_run(ASYM, 1.0, duration=2.0)
    imp = r.impact_times
    assert imp.size >= 3
    for k in range(3):
        lo = imp[k - 1] if k else 0.0
        seg = (r.t > lo + 1e-3) & (r.t < imp[k] - 1e-3)
        s = 1.0 if np.mean(r.theta[seg]) > 0 else -1.0
        a, p, _ = _side(ASYM, s)
        e = np.array([_energy(o, t, a, p) for o, t in zip(r.omega[seg], r.theta[seg],
                                                          strict=True)])
        assert np.ptp(e) <= 1e-7 * p * p


@pytest.mark.parametrize("motion,kw", [
    pytest.param(None, {"duration": 3.0, "theta0": -0.7 * ASYM.alpha_minus}, id="free"),
    pytest.param(OneSine(0.30 * G, 0.5, duration=5.0), {}, id="pulse-survives"),
    pytest.param(OneSine(0.45 * G, 0.5, duration=5.0), {}, id="pulse-big"),
    pytest.param(-OneSine(0.30 * G, 0.5, duration=5.0), {}, id="pulse-flipped"),
    pytest.param(random_record(2, 3.0, duration=6.0), {}, id="record"),
    pytest.param(OneSine(0.22 * G, 0.5, duration=5.0), {"linear": True}, id="pulse-linear"),
])
def test_compiled_matches_reference(motion, kw):
    """The compiled classical kernel against the plain scipy reference, with the
    tolerances of tests/test_housner.py."""
    c = simulate(ASYM, motion, rtol=1e-10, **kw)
    r = simulate_reference(ASYM, motion, rtol=1e-10, **kw)
    assert r.max_abs_theta > 1e-3
    assert c.overturned == r.overturned
    assert c.n_impacts == r.n_impacts
    assert c.max_abs_theta == pytest.approx(r.max_abs_theta, rel=1e-5)
    n = min(c.n_impacts, 10)
    np.testing.assert_allclose(c.impact_times[:n], r.impact_times[:n], rtol=0, atol=1e-6)
    if c.overturned:
        assert c.overturn_time == pytest.approx(r.overturn_time, abs=1e-6)
    if motion is not None:
        assert c.uplift_time == pytest.approx(r.uplift_time, abs=1e-9)


def _amplitudes(r):
    a = np.abs(r.theta)
    i = np.flatnonzero((a[1:-1] >= a[:-2]) & (a[1:-1] >= a[2:]) & (a[1:-1] > 0)) + 1
    return a[i]


@pytest.mark.parametrize("s", [1.0, -1.0])
def test_classical_and_ccrr_agree_on_free_rocking(s):
    """The tolerance of tests/test_ccrr.py (0.5 % on the first six amplitudes and
    zero-crossing times)."""
    n = 6
    rh = _free_run(ASYM, s, duration=4.0, dt_out=2e-4)
    rc = _free_run(ASYM, s, model="ccrr", duration=4.0, dt_out=2e-4)
    amp = np.abs(_amplitudes(rc)[:n] / _amplitudes(rh)[:n] - 1).max()
    tim = np.abs(rc.impact_times[:n] / rh.impact_times[:n] - 1).max()
    assert amp < 5e-3 and tim < 5e-3


def test_classical_and_ccrr_agree_under_a_sine():
    """The case and tolerance of tests/test_ccrr.py (2 % on the largest angle)."""
    m = Sine(5.0, 0.005, 6.0)
    rh = simulate(ASYM, m)
    rc = simulate(ASYM, m, model="ccrr")
    assert 0.2 * ASYM.alpha < rh.max_abs_theta < ASYM.alpha
    assert rc.max_abs_theta == pytest.approx(rh.max_abs_theta, rel=0.02)
    assert rc.uplift_time == pytest.approx(rh.uplift_time, abs=1e-6)


@pytest.mark.parametrize("model,tol", [("housner", 1e-9), ("ccrr", 1e-9)])
@pytest.mark.parametrize("motion", [Sine(5.0, 0.005, 6.0), random_record(3, 3.0, 6.0),
                                    GroundMotion(random_record(3, 3.0, 6.0),
                                                 random_record(5, 2.0, 6.0))],
                         ids=["sine", "record", "vertical"])
def test_mirror_image(model, tol, motion):
    """The block under -a is its mirror image (sides swapped) under a, theta negated."""
    kw = {"rtol": 1e-10} if model == "ccrr" else {}
    a = simulate(ASYM, -motion, model=model, **kw)
    b = simulate(ASYM.mirrored(), motion, model=model, **kw)
    assert a.max_abs_theta > 1e-3
    assert a.t.shape == b.t.shape
    np.testing.assert_allclose(a.theta, -b.theta, rtol=0, atol=tol)
    assert a.n_impacts == b.n_impacts and a.overturned == b.overturned
    # and the asymmetry matters: the unmirrored block under a rocks differently
    c = simulate(ASYM, motion, model=model, **kw)
    n = min(a.t.size, c.t.size)
    assert np.abs(c.theta[:n] + a.theta[:n]).max() > 1e-3


@pytest.mark.parametrize("model", ["housner", "ccrr"])
def test_batch_rows_equal_single_runs(model):
    """One block per row (asymmetric and symmetric mixed): one compiled call, each row
    bit-identical to its single run."""
    blocks = [ASYM, ASYM.mirrored(), Block.rectangular(0.2, 0.8), ASYM.with_params(mu=0.85)]
    ms = [OneSine(0.35 * G, 0.5, duration=4.0), random_record(1, 3.0, 5.0),
          GroundMotion(random_record(4, 3.0, 5.0), random_record(6, 2.0, 5.0)),
          Sine(2.5, 0.025, 4.0)]
    res = simulate_many(blocks, ms, model=model)
    for i, (b, m) in enumerate(zip(blocks, ms, strict=True)):
        r = simulate(b, m, model=model)
        assert res.max_abs_theta[i] == r.max_abs_theta
        assert res.n_impacts[i] == r.n_impacts
        assert res.overturned[i] == r.overturned


@pytest.mark.parametrize("amp", [0.30, 0.36, 0.42, 0.5])
def test_energy_decision_at_the_free_time_cap(amp):
    """At the cap of the free motion the energy decides the outcome (free_outcome_sides):
    a short cap gives the outcome and the largest angle of a long one, on either side."""
    for blk in (ASYM, ASYM.mirrored()):
        m = OneSine(amp * G, 0.5)
        short = simulate(blk, m, max_free_time=0.3)
        long = simulate(blk, m, max_free_time=60.0)
        assert long.settled and short.settled
        assert short.overturned == long.overturned
        assert short.max_abs_theta == pytest.approx(long.max_abs_theta, rel=1e-6)


@pytest.mark.parametrize("model", ["dem"])
def test_other_models_refuse_asymmetric_blocks(model):
    """The DEM takes an asymmetric block as the body of its outline only (the isolated and
    anchored models take both sides: tests/test_asymmetric_mitigation.py)."""
    with pytest.raises(ParameterError, match=rf"model '{model}' takes symmetric blocks only"):
        simulate(ASYM, None, model=model, duration=1.0, theta0=0.01)
    simulate(Block.rectangular(0.2, 0.8, mass=50.0), None, model=model, duration=0.2,
             theta0=0.01)
