"""The discrete element model (``model="dem"``), polygonal blocks, stacks and the paper's
DEM parameters (Peña et al. 2007, Section 2.3, Eqs 14-22, Table III).

Expected values are closed forms (static settlement, Coulomb sliding, polygon integrals by
decomposition), the printed tables, or the classical model run independently.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import rocking
from rocking import Block, ParameterError, Stack, simulate, simulate_many
from rocking.blocks import polygon_properties
from rocking.blocks.specimens import paper_data
from rocking.models import dem as D
from rocking.models import dem as PD
from rocking.motions import HalfSine, Rectangular, Sine
from rocking.units import G


# ============================================================================ geometry
@pytest.mark.parametrize("w,h,m", [(0.17, 1.0, 228.0), (0.25, 1.0, 503.0), (0.6, 0.5, 10.0)])
def test_rectangle_polygon_equals_rectangular(w, h, m):
    r = Block.rectangular(w, h, mass=m, mu=0.9 if w / h > 1.4 else None)
    q = Block.polygon([(0, 0), (w, 0), (w, h), (0, h)], mass=m, mu=0.9 if w / h > 1.4 else None)
    for f in ("alpha", "p", "mu", "I_O", "R", "width", "height"):
        assert getattr(q, f) == pytest.approx(getattr(r, f), rel=1e-12), f
    assert r.vertices == q.vertices  # normalised: base face centred on the origin
    assert q.alphas == pytest.approx((r.alpha, r.alpha), rel=1e-12)


def test_cut_corner_centroid_and_inertia_by_decomposition():
    """Rectangle minus two right isosceles triangles (legs c), by the parallel-axis rule."""
    w, H, c, M = 0.16, 0.457, 0.040, 245.0
    blk = Block.rectangular(w, H, mass=M, corner_cut=c)
    A_r, A_t = w * H, 0.5 * c * c
    # rectangle centred at (0, H/2); triangles with centroids at (+-(w/2 - c/3), c/3)
    parts = [(A_r, 0.0, H / 2, A_r * (w * w + H * H) / 12.0)]
    for sx in (1.0, -1.0):
        # polar moment of a right isosceles triangle about its centroid: A (2 c^2)/18
        parts.append((-A_t, sx * (w / 2 - c / 3), c / 3, -A_t * 2 * c * c / 18.0))
    A = sum(a for a, *_ in parts)
    cx = sum(a * x for a, x, _, _ in parts) / A
    cy = sum(a * y for a, _, y, _ in parts) / A
    J = sum(j + a * ((x - cx) ** 2 + (y - cy) ** 2) for a, x, y, j in parts)
    pr = polygon_properties(blk.vertices)
    assert pr["area"] == pytest.approx(A, rel=1e-12)
    assert pr["centroid"] == pytest.approx((cx, cy), rel=1e-12, abs=1e-15)
    assert pr["j_c"] == pytest.approx(J / A, rel=1e-12)
    # the rocking corners are the ends of the narrowed base face
    R = math.hypot(w / 2 - c, cy)
    assert blk.alpha == pytest.approx(math.atan2(w / 2 - c, cy), rel=1e-12)
    assert blk.R == pytest.approx(R, rel=1e-12)
    assert blk.I_O == pytest.approx(M * (J / A + R * R), rel=1e-12)
    assert blk.p == pytest.approx(math.sqrt(M * G * R / blk.I_O), rel=1e-12)
    assert blk.mu == pytest.approx(1 - 2 * M * R * R / blk.I_O * math.sin(blk.alpha) ** 2,
                                   rel=1e-12)


def test_specimen_shapes():
    rect = rocking.specimen(2, "geometric")
    cut = rocking.specimen(2, "geometric", shape="cut")
    assert len(rect.vertices) == 4 and len(cut.vertices) == 6
    assert cut.alpha < rect.alpha  # the 5 mm cuts narrow the base: alpha 0.159 vs 0.168
    assert rocking.specimen(4, "geometric", shape="cut").alpha == pytest.approx(0.1698, abs=1e-4)
    # the parameter sets still override the classical parameters
    assert rocking.specimen(2, "experimental", shape="cut").alpha == 0.163
    with pytest.raises(rocking.SpecimenError):
        rocking.specimen(2, shape="round")


def test_asymmetric_polygon_alphas():
    blk = Block.polygon([(0, 0), (0.3, 0), (0.2, 1.0), (0.0, 1.0)], mass=10.0)
    a_o, a_o2 = blk.alphas
    cx, cy = blk.centroid
    assert a_o == pytest.approx(math.atan2(cx + 0.15, cy))
    assert a_o2 == pytest.approx(math.atan2(0.15 - cx, cy))
    assert blk.alpha == min(a_o, a_o2)


@pytest.mark.parametrize("verts", [
    [(0, 0), (1, 0), (0.5, 0.2), (1, 1), (0, 1)],  # reflex vertex
    [(0, 0), (1, 0.1), (1, 1), (0, 1)],  # no horizontal base face
    [(0, 0), (1, 0)],
])
def test_bad_polygons(verts):
    with pytest.raises(ParameterError):
        Block.polygon(verts)


# ========================================================================== Table III
def test_paper_parameters_equations():
    d = paper_data()["specimens"]["2"]
    blk = rocking.specimen(2, "theoretical")
    pp = PD.paper_parameters(blk)
    M, p, mu, R = d["mass"], 3.81, 0.958, math.hypot(0.085, 0.5)
    K = 0.5 * M * (p * p + 3 * G / (4 * R))  # Eq 17
    assert pp["K"] == pytest.approx(K, rel=1e-12)
    assert pp["K1"] == pytest.approx(M * p * p)  # Eq 14
    assert pp["gamma"] == pytest.approx(0.5 * M * (R * p * p + 0.75 * G), rel=1e-12)  # Eq 19
    b = (0.0057 * math.log(pp["gamma"] / mu ** 2) - 0.0336) ** 2  # Eq 20
    assert pp["b"] == pytest.approx(b, rel=1e-12)
    assert pp["f_min"] == p  # Eq 21
    assert pp["xi_min"] == pytest.approx(2 * math.pi * b * p, rel=1e-12)  # Eq 22
    assert pp["width_eq"] == pytest.approx(2 * 0.5 * math.tan(0.168), rel=1e-12)  # Eq 18
    assert PD.paper_parameters(2)["K"] == pytest.approx(pp["K"])


def test_table3_against_the_printed_values():
    t = PD.table3().set_index(["specimen", "column"])
    # Eq 17 reproduces the printed K(T) of specimens 1 and 2 to 1 %...
    for n in (1, 2):
        assert abs(t.loc[(n, "T"), "K_diff_pct"]) < 1.0
    # ... but not that of specimen 3 (1174 printed, Eq 17 gives 1752)
    assert t.loc[(3, "T"), "K_ours"] == pytest.approx(1752, rel=1e-3)
    assert t.loc[(3, "T"), "K_diff_pct"] > 40.0
    # f_min = p exactly (Eq 21); 2 b_eq (Eq 18) to the printed 2 decimals, specimens 1-3
    assert (t.f_min_diff_pct.abs() < 1e-9).all()
    for n in (1, 2, 3):
        for col in ("T", "F"):
            assert abs(t.loc[(n, col), "width_eq_ours"] - t.loc[(n, col), "width_eq_paper"]) \
                <= 0.0056
    # the paper's Eq 20 is a fit on the F column: the refit recovers its coefficients
    fit = PD.refit_eq20()
    assert fit["slope"] == pytest.approx(0.0057, rel=0.25)
    assert fit["intercept"] == pytest.approx(-0.0336, rel=0.3)


def test_settlement_of_the_printed_stiffness():
    """K = 3302 for specimen 2, read as N/m per contact point: 0.34 m of settlement."""
    s = PD.settlement_table().set_index(["specimen", "reading"])
    lit = s.loc[(2, "N/m per contact point (literal)"), "settlement_m"]
    assert lit == pytest.approx(228 * G / (2 * 3302), rel=1e-12)
    assert lit > 0.3
    mpa = s.loc[(2, "MPa/m joint stiffness x base area"), "settlement_m"]
    assert mpa == pytest.approx(228 * G / (3302e6 * 0.17 * 0.502), rel=1e-12)
    assert 1e-6 < mpa < 1e-5


# ================================================================ statics and friction
def test_block_settles_by_mg_over_nk():
    blk = rocking.specimen(2, "geometric")
    K = 1e9
    r = simulate(blk, None, model="dem", duration=0.3, settled=False, stiffness=K,
                 damping=2e-4)
    assert r.y[-1] == pytest.approx(-228 * G / (2 * K), rel=0.01)
    assert abs(r.y[-1] - r.y[-20]) < 1e-3 * abs(r.y[-1])
    assert math.isnan(r.uplift_time) and r.max_abs_theta < 1e-6
    # settled=True starts there, with forces summing to the weight
    r = simulate(blk, None, model="dem", duration=0.01, stiffness=K, damping=0.0,
                 return_forces=True)
    assert r.y[0] == pytest.approx(-228 * G / (2 * K), rel=1e-9)
    assert r.contact_forces["normal"][0].sum() == pytest.approx(228 * G, rel=1e-9)
    assert len(r.contact_forces["labels"]) == 2


def test_stack_at_rest_stays_at_rest():
    blk = rocking.specimen(2, "geometric")
    r = simulate(Stack([blk, blk]), None, model="dem", duration=10.0, damping=0.0)
    assert r.theta_all.shape == (2, r.t.size)
    drift = np.hypot(r.x_all - r.x_all[:, :1], r.y_all - r.y_all[:, :1]).max()
    assert drift < 1e-6
    K = r.info["stiffness"]
    assert r.y_all[:, 0] == pytest.approx([-2 * 228 * G / (2 * K), -3 * 228 * G / (2 * K)],
                                          rel=1e-9)
    assert math.isnan(r.uplift_time) and not r.overturned


def _squat():
    # b/h = 1.25 > tan(30 deg): it slides before it rocks (tan(alpha) = 1.25)
    return Block.rectangular(1.0, 0.4, mass=500.0, mu=0.5)


@pytest.mark.parametrize("phi", ["30deg", 0.5])
def test_coulomb_sliding_rate(phi):
    """The block slides at a - g tan(phi), phi the friction angle in rad (or with its unit)."""
    blk, a = _squat(), 0.8 * G
    r = simulate(blk, Rectangular(a, 2.0, duration=1.2), model="dem", friction_angle=phi,
                 damping=1e-4, dt_out=1e-3)
    m = (r.t >= 0.3) & (r.t <= 1.2)
    acc = 2.0 * np.polyfit(r.t[m], r.x[m], 2)[0]
    rad = math.radians(30.0) if phi == "30deg" else phi
    expected = a - G * math.tan(rad)
    assert acc < 0.0  # the block lags behind the table: x decreases
    assert abs(acc) == pytest.approx(expected, rel=0.01)
    assert r.max_abs_theta < 1e-5  # it slides, it does not rock
    assert r.info["friction_angle"] == rad


def test_no_sliding_below_the_friction_threshold():
    blk = _squat()
    a = 0.9 * G * math.tan(math.radians(30.0))
    r = simulate(blk, Rectangular(a, 2.0, duration=1.2), model="dem",
                 friction_angle=math.radians(30.0), damping=1e-4)
    assert np.abs(r.x).max() < 1e-6  # elastic shear deformation only (~1e-7 m)


def test_friction_angle_is_in_rad_with_a_deprecated_reading_in_degrees():
    """Default 30 degrees in rad; "30deg" is the same number; a bare number >= pi/2 cannot
    be rad: it is read as degrees with a DeprecationWarning (same run as in rad)."""
    opts = D.DEMOptions()
    assert opts.friction_angle == math.radians(30.0) == D.DEFAULT_FRICTION_ANGLE
    assert D.DEMOptions(friction_angle="30deg").friction_angle == math.radians(30.0)
    assert D.DEMOptions(friction_angle=0.3).friction_angle == 0.3  # < pi/2: rad
    unit = {d["name"]: d["unit"] for d in D.DEMOptions.describe()}
    assert unit["friction_angle"] == "rad"
    blk, a = _squat(), 0.8 * G
    motion = Rectangular(a, 2.0, duration=0.3)
    want = simulate(blk, motion, model="dem", friction_angle=math.radians(25.0), damping=1e-4)
    with pytest.warns(DeprecationWarning, match="friction_angle is in rad") as rec:
        got = simulate(blk, motion, model="dem", friction_angle=25.0, damping=1e-4)
    assert all(w.filename == __file__ for w in rec)  # attributed to the caller
    np.testing.assert_array_equal(got.x, want.x)
    np.testing.assert_array_equal(got.theta, want.theta)
    spec = rocking.specimen(2, "theoretical")
    with pytest.warns(DeprecationWarning, match="radians"):
        assert D.calibrate_damping(spec, friction_angle=30.0) == D.calibrate_damping(spec)


@pytest.mark.parametrize("phi", [95.0, 90, "100deg", -0.1, "2 rad", "30mm", math.inf])
def test_friction_angle_out_of_range(phi, recwarn):
    with pytest.raises(ParameterError, match="friction_angle"):
        D.DEMOptions(friction_angle=phi)
    with pytest.raises(ParameterError, match="friction_angle"):
        D.check_friction_angle(phi)
    assert not [w for w in recwarn if issubclass(w.category, DeprecationWarning)]


# ====================================================================== energy
def test_energy_conserved_without_damping():
    """Frictionless contacts (no mechanism can dissipate), zero damping, 10 rocking
    cycles: kinetic + potential + spring energy conserved to 0.1 %. The step is a
    quarter of the default cap (omega_max dt = 0.05): closing contacts are resolved to
    first order, and the error falls with dt (asserted too)."""
    blk = rocking.specimen(2, "geometric")
    md = D.build_assembly(blk)
    K = D.default_stiffness(md)
    w = D.omega_max(md, K, K)
    errs = []
    for wdt in (0.2, 0.05):
        r = simulate(blk, None, model="dem", duration=7.0, theta0=0.5 * blk.alpha,
                     damping=0.0, friction_angle=0.0, dt=wdt / w, return_energy=True,
                     dt_out=1e-3)
        e = r.info["energy"]
        tot = e["kinetic"] + e["potential"] + e["spring"]
        errs.append(np.abs(tot - tot[0]).max() / tot[0])
    assert r.n_impacts >= 20  # 10 cycles at least
    assert errs[1] < 1e-3
    assert errs[1] < errs[0]


def test_stack_conserves_energy_without_damping():
    blk = rocking.specimen(2, "geometric")
    st = Stack([blk, blk])
    md = D.build_assembly(st)
    K = D.default_stiffness(md)
    w = D.omega_max(md, K, K)
    r = simulate(st, None, model="dem", duration=2.5, theta0=0.3 * blk.alpha, damping=0.0,
                 friction_angle=0.0, dt=0.05 / w, return_energy=True, dt_out=1e-3)
    e = r.info["energy"]
    tot = e["kinetic"] + e["potential"] + e["spring"]
    assert np.abs(tot - tot[0]).max() / tot[0] < 1e-3
    assert r.n_impacts >= 2


# ============================================================ against the classical model
@pytest.mark.parametrize("params", ["theoretical", "experimental", "geometric"])
def test_free_rocking_matches_classical(params):
    blk = rocking.specimen(2, params)
    th0 = 0.5 * blk.alpha
    r = simulate(blk, None, model="dem", duration=3.5, theta0=th0, dt_out=5e-4)
    h = simulate(blk, None, duration=3.5, theta0=th0, dt_out=5e-4)
    a = np.abs(r.half_cycle_peaks()[1])
    a0 = np.abs(h.half_cycle_peaks()[1])
    assert np.max(np.abs(a[1:6] / a0[1:6] - 1)) < 0.03
    assert np.max(np.abs(r.impact_times[:5] / h.impact_times[:5] - 1)) < 0.02
    assert r.info["damping_source"] == "calibrated"


def test_calibrated_damping_reaches_mu_inside_the_range():
    """A restitution between the plastic-impact and the undamped values is hit by the
    root search, and the free rocking then follows the classical model with that mu."""
    blk = rocking.specimen(2, "geometric").with_params(mu=0.97)
    cal = PD.calibrate_damping(blk, full=True)
    assert 0.0 < cal["b"] < cal["b_cap"]
    assert cal["mu_dem"] == pytest.approx(0.97, abs=1e-4)
    assert PD.free_rocking_restitution(blk, cal["b"]) == pytest.approx(0.97, abs=1e-4)
    r = simulate(blk, None, model="dem", duration=3.5, theta0=0.5 * blk.alpha, dt_out=5e-4)
    h = simulate(blk, None, duration=3.5, theta0=0.5 * blk.alpha, dt_out=5e-4)
    a, a0 = np.abs(r.half_cycle_peaks()[1]), np.abs(h.half_cycle_peaks()[1])
    assert np.max(np.abs(a[1:6] / a0[1:6] - 1)) < 0.03
    assert np.max(np.abs(r.impact_times[:5] / h.impact_times[:5] - 1)) < 0.02


def test_restitution_bounds_of_the_dem():
    """The apparent restitution falls from its undamped value to Housner's plastic impact
    (Eq 4) as the damping grows."""
    blk = rocking.specimen(2, "geometric")
    vals = [PD.free_rocking_restitution(blk, b) for b in (0.0, 3e-5, 1e-3)]
    assert vals[0] > vals[1] > vals[2]
    assert vals[2] == pytest.approx(blk.mu, abs=2e-4)


@pytest.mark.parametrize("params", ["experimental", "geometric"])
def test_sine_5hz_5mm_matches_classical(params):
    blk = rocking.specimen(2, params)
    m = Sine(5.0, 0.005, 25.0)
    r = simulate(blk, m, model="dem")
    h = simulate(blk, m)
    assert not r.overturned and not h.overturned
    assert r.max_abs_theta == pytest.approx(h.max_abs_theta, rel=0.05)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_sign_convention_agrees_with_classical(sign):
    blk = rocking.specimen(2, "geometric")
    m = HalfSine(3.0, 0.2).scaled(sign)
    r = simulate(blk, m, model="dem", duration=0.6)
    h = simulate(blk, m, duration=0.6)
    i = int(np.argmax(np.abs(h.theta)))
    assert np.sign(r.theta[i]) == np.sign(h.theta[i]) == sign
    assert r.theta[i] == pytest.approx(h.theta[i], rel=0.02)
    # the centroid moves against the table's acceleration: x < 0 for a > 0
    assert np.sign(r.x[i]) == -sign


def test_uplift_threshold():
    """A slowly applied acceleration uplifts the block when it exceeds g tan(alpha) (a step
    would overshoot on the elastic contacts)."""
    blk = rocking.specimen(2, "geometric")
    a_up = blk.uplift_acceleration
    lo = simulate(blk, HalfSine(0.98 * a_up, 2.0, duration=1.2), model="dem")
    hi = simulate(blk, HalfSine(1.02 * a_up, 2.0, duration=1.2), model="dem")
    assert math.isnan(lo.uplift_time) and lo.max_abs_theta < 1e-4
    assert not math.isnan(hi.uplift_time) and hi.max_abs_theta > 1e-3
    # the crossing of the threshold: sin(pi t / 2) = 1 / 1.02
    assert hi.uplift_time == pytest.approx(2.0 / math.pi * math.asin(1 / 1.02), abs=0.01)


def test_batch_matches_single_runs():
    blk = rocking.specimen(2, "geometric")
    ms = [HalfSine(abs(A), 0.25, duration=2.0).scaled(math.copysign(1.0, A))
          for A in (2.0, 3.0, -3.0)]
    b = simulate_many(blk, ms, model="dem", return_histories=True)
    for i, m in enumerate(ms):
        r = simulate(blk, m, model="dem")  # the same default dt_out: the same run
        assert b.max_abs_theta[i] == r.max_abs_theta
        assert b.overturned[i] == r.overturned
        assert np.array_equal(b.theta[i, : r.t.size], r.theta)


# ==================================================================== API and errors
def test_api_errors():
    blk = rocking.specimen(2)
    with pytest.raises(ParameterError):
        simulate(blk, None, model="dem", duration=1.0, linear=True)
    with pytest.raises(ParameterError):
        simulate(blk, None, model="dem", duration=1.0, friction=30)
    with pytest.raises(ParameterError):
        simulate(blk, None, model="dem", duration=1.0, friction_angle=95.0)
    with pytest.raises(ParameterError):
        simulate(blk, None, model="dem", duration=1.0, damping="lots")
    with pytest.raises(ParameterError):
        simulate(Stack([blk, blk]), None, duration=1.0)  # the classical model: no stacks
    with pytest.raises(ParameterError):
        Stack([blk, "brick"])


def test_stack_geometry_and_outputs():
    plinth = Block.rectangular(1.0, 0.25, mass=500.0, mu=0.5)
    blk = rocking.specimen(2, "geometric")
    st = Stack([plinth, blk], offsets=[0.0, 0.1])
    md = D.build_assembly(st)
    # block 2 stands on the plinth's top face, 0.1 m right of its middle
    assert md.nominal[1, 0] == pytest.approx(0.1)
    assert md.nominal[1, 1] == pytest.approx(0.25 + 0.5)
    r = simulate(st, HalfSine(2.5, 0.25), model="dem", duration=1.5, return_forces=True)
    assert r.theta_all.shape == r.x_all.shape == (2, r.t.size)
    assert np.array_equal(r.theta, r.theta_all[1])
    assert r.max_abs_theta > 1e-3  # the block rocks on the plinth...
    assert r.info["max_abs_theta_all"][0] < 1e-4  # ... which does not
    fn = r.contact_forces["normal"]
    labels = r.contact_forces["labels"]
    on_base = [i for i, s in enumerate(labels) if s.startswith("block 0") and "base" in s]
    assert fn[0, on_base].sum() == pytest.approx((500 + 228) * G, rel=1e-6)


# ================================================================================= CLI
def test_cli_dem_params():
    from click.testing import CliRunner

    from rocking.cli.dem import dem_params

    r = CliRunner().invoke(dem_params, ["--specimen", "2"])
    assert r.exit_code == 0, r.output
    assert "K (Eq 17)             3308 N/m   paper 3302" in r.output
    assert "column F" in r.output
    r = CliRunner().invoke(dem_params, ["--specimen", "3", "--params", "theoretical", "--json"])
    d = json.loads(r.output)
    assert d["paper"]["K"] == 1174 and d["K"] == pytest.approx(1752, rel=1e-3)
    r = CliRunner().invoke(dem_params, ["--specimen", "9"])
    assert isinstance(r.exception, ParameterError)
