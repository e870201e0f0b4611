"""rocking.shapes: rigid bodies from meshes and their rocking parameters per direction.

Every expected value is computed here by hand (closed forms of boxes, regular prisms,
regular pyramids and an extruded L, composite-body sums, an angular-momentum balance in
3-D vectors) or by an independent implementation (the divergence theorem with exact
quadrature in :mod:`rocking.testing.mesh_reference`, not trimesh's formulas); invariances
(rigid motions, re-triangulation, scaling, file formats) compare the code with itself
under transformations that must not change the physics.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st

from rocking import Block
from rocking.errors import ParameterError
from rocking.shapes import (
    MeshRepairWarning,
    Shape,
    directional_parameters,
    example_mesh_path,
    load_example,
    load_shape,
    plot_directional,
    strongest_direction,
    weakest_direction,
)
from rocking.shapes.mass import volume_properties
from rocking.shapes.mesh import check_mesh, weld
from rocking.testing import mesh_reference as ref
from rocking.units import G

RHO = 1000.0
SIDES = ("plus", "minus")


def shape(v, f, **kw):
    kw.setdefault("density", RHO)
    return Shape.from_arrays(v, f, **kw)


def close(a, b, rel=1e-9, abs_=1e-12):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return np.allclose(a, b, rtol=rel, atol=abs_)


def expected(h, bp, bm, rg2):
    """The contract's formulas for one direction, written out again."""
    out = {"h": h, "b_plus": bp, "b_minus": bm, "radius_of_gyration": math.sqrt(rg2)}
    b = {"plus": bp, "minus": bm}
    for s, o in (("plus", "minus"), ("minus", "plus")):
        R, Ro = math.hypot(b[s], h), math.hypot(b[o], h)
        out[f"alpha_{s}"] = math.atan(b[s] / h)
        out[f"R_{s}"] = R
        out[f"p_{s}"] = math.sqrt(G * R / (rg2 + R * R))
        out[f"mu_{s}"] = (rg2 + h * h - b[s] * b[o]) / (rg2 + Ro * Ro)
        out[f"uplift_{s}"] = G * math.tan(out[f"alpha_{s}"])
    return out


def check_row(row, exp, rel=1e-9):
    for k, v in exp.items():
        assert math.isclose(float(row[k]), v, rel_tol=rel, abs_tol=1e-12), (k, row[k], v)


# ------------------------------------------------------------------ the reference itself
def test_reference_matches_the_box_closed_form():
    a, b, c = 0.7, 0.4, 1.3
    r = ref.mass_properties(*ref.box(a, b, c), density=RHO)
    m = RHO * a * b * c
    assert math.isclose(r["volume"], a * b * c, rel_tol=1e-13)
    assert close(r["com"], [0.0, 0.0, c / 2], abs_=1e-14)
    assert close(r["inertia"], np.diag([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12,
                                        m * (a * a + b * b) / 12]), rel=1e-12, abs_=1e-12)


# ------------------------------------------------------------------ closed forms
def test_box_principal_directions_give_alpha_p_and_eq4():
    a, b, c = 0.5, 0.3, 1.2  # full sizes along x, y and up
    sh = shape(*ref.box(a, b, c))
    tab = directional_parameters(sh, [0.0, math.pi / 2, math.pi, 1.5 * math.pi])
    for i, (half, hh) in enumerate([(a / 2, c / 2), (b / 2, c / 2)] * 2):
        row = tab.iloc[i]
        R = math.hypot(half, hh)
        alpha = math.atan(half / hh)
        for s in SIDES:
            assert math.isclose(row[f"alpha_{s}"], alpha, rel_tol=1e-9)
            assert math.isclose(row[f"p_{s}"] ** 2, 3 * G / (4 * R), rel_tol=1e-9)
            assert math.isclose(row[f"mu_{s}"], 1 - 1.5 * math.sin(alpha) ** 2, rel_tol=1e-9)
            assert math.isclose(row[f"uplift_{s}"], G * half / hh, rel_tol=1e-9)
    assert math.isclose(sh.mass, RHO * a * b * c, rel_tol=1e-12)


def test_the_3d_uplift_is_where_the_resultant_leaves_the_support():
    """A box shaken at 60 deg from its long axis: the resultant's ray leaves the 0.5 x 0.3
    footprint through a long edge, at the distance 0.15 / sin(60 deg) < the planar b."""
    a, b, c = 0.5, 0.3, 1.2
    sh = shape(*ref.box(a, b, c))
    phi = math.radians(60.0)
    row = sh.parameters(phi)
    t = min(a / 2 / math.cos(phi), b / 2 / math.sin(phi))
    for s in SIDES:
        assert math.isclose(row[f"uplift_3d_{s}"], G * t / (c / 2), rel_tol=1e-12)
        assert math.isclose(row[f"b_{s}"], (a * math.cos(phi) + b * math.sin(phi)) / 2,
                            rel_tol=1e-12)
    # along an axis and along the diagonal both agree
    for phi in (0.0, math.pi / 2, math.atan2(b, a)):
        row = sh.parameters(phi)
        assert math.isclose(row["uplift_3d_plus"], row["uplift_plus"], rel_tol=1e-12)


def polygon_k2(r, n):
    """Second moment per unit area of the regular n-gon (circumradius r) about any
    centroidal axis: J/(2A) with J/A = r^2 (1 + 2 cos^2(pi/n)) / 6."""
    return r * r * (1 + 2 * math.cos(math.pi / n) ** 2) / 12


def ngon_support(r, n, phi, phase=0.0):
    """b(phi) = max_k r cos(phi - theta_k) for the regular n-gon's vertices."""
    th = phase + 2 * math.pi * np.arange(n) / n
    return float(np.max(r * np.cos(phi - th)))


def test_cylinder_has_the_same_alpha_in_every_direction():
    r, H, n = 0.3, 1.5, 64
    sh = shape(*ref.regular_prism(r, H, n))
    phis = np.linspace(0, 2 * np.pi, 73)
    tab = directional_parameters(sh, phis)
    rg2 = polygon_k2(r, n) + H * H / 12
    for phi, (_, row) in zip(phis, tab.iterrows(), strict=True):
        b = ngon_support(r, n, phi)
        bm = ngon_support(r, n, phi + math.pi)
        check_row(row, expected(H / 2, bm, b, rg2))
    # the same alpha in every direction, to the polygon's precision
    lo, hi = math.atan(r * math.cos(math.pi / n) / (H / 2)), math.atan(r / (H / 2))
    a = tab[["alpha_plus", "alpha_minus"]].to_numpy()
    assert np.all(a >= lo - 1e-12) and np.all(a <= hi + 1e-12)
    assert np.ptp(a) < hi - lo + 1e-12 and hi - lo < 2e-3


def test_cone_matches_the_pyramid_closed_form():
    r, H, n = 0.4, 1.0, 48
    sh = shape(*ref.regular_pyramid(r, H, n, phase=0.1))
    assert math.isclose(sh.h, H / 4, rel_tol=1e-12)
    assert math.isclose(sh.volume, 0.5 * n * r * r * math.sin(2 * math.pi / n) * H / 3,
                        rel_tol=1e-12)
    # int x^2 dm / m = 3 k^2 / 5; about the centre of mass vertically: 3 H^2 / 80
    rg2 = 3 * polygon_k2(r, n) / 5 + 3 * H * H / 80
    phis = np.linspace(-1.0, 7.0, 17)
    tab = directional_parameters(sh, phis)
    for phi, (_, row) in zip(phis, tab.iterrows(), strict=True):
        bp = ngon_support(r, n, phi + math.pi, 0.1)
        bm = ngon_support(r, n, phi, 0.1)
        check_row(row, expected(H / 4, bp, bm, rg2))


L_DIMS = (0.75, 0.25, 1.5, 0.5)  # foot length a, thickness t, height H, depth d (dyadic)


def l_hand(a, t, H, d):
    """The extruded L's centroid and centroidal second moments per unit area, by the
    composite-body rule (two rectangles in the x-z plane)."""
    parts = [(a * t, a / 2, t / 2, a, t), (t * (H - t), t / 2, (t + H) / 2, t, H - t)]
    A = sum(p[0] for p in parts)
    xc = sum(p[0] * p[1] for p in parts) / A
    zc = sum(p[0] * p[2] for p in parts) / A
    # about the y axis (shaking along x) and the x axis (shaking along y)
    iy = sum(p[0] * ((p[3] ** 2 + p[4] ** 2) / 12 + (p[1] - xc) ** 2 + (p[2] - zc) ** 2)
             for p in parts) / A
    ix = sum(p[0] * ((d * d + p[4] ** 2) / 12 + (p[2] - zc) ** 2) for p in parts) / A
    return A, xc, zc, iy, ix


def test_l_shaped_body_matches_hand_values():
    a, t, H, d = L_DIMS
    sh = shape(*ref.l_block(a, t, H, d))
    A, xc, zc, iy, ix = l_hand(a, t, H, d)
    assert math.isclose(sh.volume, A * d, rel_tol=1e-12)
    assert close(sh.com, [xc, 0.0, zc], abs_=1e-13)
    tab = directional_parameters(sh, [0.0, math.pi / 2, math.pi, -math.pi / 2])
    check_row(tab.iloc[0], expected(zc, xc, a - xc, iy))  # + pivot: the edge x = 0
    check_row(tab.iloc[1], expected(zc, d / 2, d / 2, ix))
    check_row(tab.iloc[2], expected(zc, a - xc, xc, iy))
    check_row(tab.iloc[3], expected(zc, d / 2, d / 2, ix))


def test_restitution_equals_an_angular_momentum_balance():
    """mu_s from 3-D vectors: rotation about the old pivot line, angular momentum about
    the new one (I_G from the independent reference), in an oblique direction."""
    v, f = ref.l_block(*L_DIMS)
    v = v @ rotation_z(0.3).T
    sh = shape(v, f)
    r = ref.mass_properties(v, f, density=RHO)
    m, G3, IG = r["mass"], r["com"], r["inertia"]
    for phi in (0.2, 1.1, 2.5, 4.0):
        e = np.array([math.cos(phi), math.sin(phi), 0.0])
        u = np.array([-math.sin(phi), math.cos(phi), 0.0])
        base = v[v[:, 2] < 1e-9]
        proj = (base - G3) @ e
        # the pivot lines' points at the base, on the centre of mass's vertical plane
        pivot = {"plus": np.array([G3[0], G3[1], 0.0]) + proj.min() * e,
                 "minus": np.array([G3[0], G3[1], 0.0]) + proj.max() * e}
        row = sh.parameters(phi)
        for s, o in (("plus", "minus"), ("minus", "plus")):
            w1 = u  # unit angular velocity about the pivot line of side s
            vG = np.cross(w1, G3 - pivot[s])
            H = IG @ w1 + m * np.cross(G3 - pivot[o], vG)
            d_o = (G3 - pivot[o]) - np.dot(G3 - pivot[o], u) * u
            I_new = u @ IG @ u + m * np.dot(d_o, d_o)
            assert math.isclose(row[f"mu_{s}"], np.dot(H, u) / I_new, rel_tol=1e-9)


# ------------------------------------------------------------------ mass properties
@pytest.mark.parametrize("seed", range(4))
def test_mass_properties_equal_the_reference_on_random_hulls(seed):
    rng = np.random.default_rng(seed)
    pts = rng.normal(size=(40, 3)) * [0.3, 0.5, 0.8] + rng.normal(size=3)
    hull = trimesh.convex.convex_hull(pts)
    v, f = weld(hull.vertices, hull.faces)
    assert check_mesh(v, f) is None
    mine = volume_properties(v, f)  # what Shape uses (a random hull stands on a point)
    r = ref.mass_properties(v, f)
    assert math.isclose(mine["volume"], r["volume"], rel_tol=1e-9)
    assert np.allclose(mine["com"], r["com"], rtol=0, atol=1e-9 * np.abs(r["com"]).max())
    scale = np.abs(r["inertia"]).max()
    assert np.allclose(mine["inertia"], r["inertia"], rtol=0, atol=1e-9 * scale)


def test_mass_properties_equal_the_reference_on_the_l_and_the_example():
    for sh in (shape(*ref.l_block(*L_DIMS)), load_example(density=RHO)):
        r = ref.mass_properties(sh.vertices, sh.faces, density=RHO)
        assert math.isclose(sh.volume, r["volume"], rel_tol=1e-9)
        assert np.allclose(sh.com, r["com"], rtol=0, atol=1e-9 * sh.height)
        scale = np.abs(r["inertia"]).max()
        assert np.allclose(sh.inertia, r["inertia"], rtol=0, atol=1e-9 * scale)


def test_a_given_mass_sets_the_density():
    v, f = ref.box(1.0, 0.5, 2.0)
    sh = Shape.from_arrays(v, f, mass=900.0)
    assert sh.mass == 900.0 and math.isclose(sh.density, 900.0, rel_tol=1e-12)
    assert math.isclose(sh.inertia[0, 0], 900.0 * (0.25 + 4.0) / 12, rel_tol=1e-12)
    for kw in ({}, {"mass": 1.0, "density": 2.0}, {"density": -1.0}):
        with pytest.raises(ParameterError, match="density|mass"):
            Shape.from_arrays(v, f, **kw)


# ------------------------------------------------------------------ invariances
def rotation_z(beta):
    c, s = math.cos(beta), math.sin(beta)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def random_rotation(q):
    q = np.asarray(q, dtype=float)
    q = q / np.linalg.norm(q)
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


NUMERIC = ["h", "b_plus", "b_minus", "radius_of_gyration", "alpha_plus", "alpha_minus",
           "R_plus", "R_minus", "I_plus", "I_minus", "p_plus", "p_minus", "mu_plus",
           "mu_minus", "uplift_plus", "uplift_minus"]
PHIS = np.linspace(0.0, 2 * np.pi, 24, endpoint=False)
L_SHAPE = None


def l_shape():
    global L_SHAPE
    if L_SHAPE is None:
        L_SHAPE = shape(*ref.l_block(*L_DIMS))
    return L_SHAPE


@settings(max_examples=12, deadline=None)
@given(q=st.lists(st.floats(-1, 1), min_size=4, max_size=4).filter(
           lambda q: np.linalg.norm(q) > 0.3),
       shift=st.lists(st.floats(-20, 20), min_size=3, max_size=3))
def test_rigid_motion_leaves_every_parameter_unchanged(q, shift):
    """Rotate the mesh by Q, translate it, and give up = Q z: the table is the same once
    phi is measured from the new frame's e1 (the projection of the mesh's x axis)."""
    base = l_shape()
    Q = random_rotation(q)
    v = base.vertices @ Q.T + np.asarray(shift)
    up = Q @ [0.0, 0.0, 1.0]
    sh = shape(v, base.faces, up=up)
    ex = np.array([1.0, 0.0, 0.0])
    e1 = ex - np.dot(ex, up) * up
    if np.linalg.norm(e1) < 1e-6:
        e1 = np.array([0.0, 1.0, 0.0]) - up[1] * up
    e1 /= np.linalg.norm(e1)
    qx = Q @ ex  # the body's old x axis, now horizontal
    delta = math.atan2(np.dot(up, np.cross(e1, qx)), np.dot(e1, qx))
    a = directional_parameters(base, PHIS)
    b = directional_parameters(sh, PHIS + delta)
    for k in NUMERIC:
        assert np.allclose(a[k], b[k], rtol=1e-9, atol=1e-12), k
    assert math.isclose(sh.mass, base.mass, rel_tol=1e-12)
    assert np.allclose(sh.com, Q @ base.com + shift, rtol=0, atol=1e-11)
    assert np.allclose(sh.inertia, Q @ base.inertia @ Q.T, rtol=0,
                       atol=1e-10 * np.abs(base.inertia).max())


def test_a_change_of_triangulation_leaves_every_parameter_unchanged():
    base = l_shape()
    sub = trimesh.Trimesh(base.vertices, base.faces, process=False).subdivide().subdivide()
    a, b = directional_parameters(base, PHIS), directional_parameters(Shape.from_trimesh(
        sub, density=RHO), PHIS)
    # the L with another fan for its caps (from the corner (0, 0))
    aa, t, H, d = L_DIMS
    prof = [(0.0, 0.0), (aa, 0.0), (aa, t), (t, t), (t, H), (0.0, H)]
    other = shape(*ref.extrude(prof, [(0, 1, 2), (0, 2, 3), (0, 3, 4), (0, 4, 5)], d))
    c = directional_parameters(other, PHIS)
    assert len(sub.faces) == 16 * len(base.faces)
    for k in NUMERIC:
        assert np.allclose(a[k], b[k], rtol=1e-9, atol=1e-12), k
        assert np.allclose(a[k], c[k], rtol=1e-9, atol=1e-12), k


@settings(max_examples=8, deadline=None)
@given(s=st.floats(0.05, 20.0))
def test_scaling_keeps_alpha_and_scales_p_as_one_over_root_size(s):
    base = l_shape()
    sh = shape(base.vertices * s, base.faces)
    a, b = directional_parameters(base, PHIS), directional_parameters(sh, PHIS)
    for side in SIDES:
        assert np.allclose(a[f"alpha_{side}"], b[f"alpha_{side}"], rtol=1e-9)
        assert np.allclose(a[f"mu_{side}"], b[f"mu_{side}"], rtol=1e-9)
        assert np.allclose(a[f"p_{side}"] / math.sqrt(s), b[f"p_{side}"], rtol=1e-9)
        assert np.allclose(a[f"R_{side}"] * s, b[f"R_{side}"], rtol=1e-9)


def test_phi_plus_pi_swaps_the_sides():
    sh = load_example()
    a = directional_parameters(sh, PHIS)
    b = directional_parameters(sh, PHIS + math.pi)
    for k in ("b", "alpha", "R", "I", "p", "mu", "uplift"):
        assert np.allclose(a[f"{k}_plus"], b[f"{k}_minus"], rtol=1e-12), k
        assert np.allclose(a[f"{k}_minus"], b[f"{k}_plus"], rtol=1e-12), k
    assert np.allclose(a["radius_of_gyration"], b["radius_of_gyration"], rtol=1e-12)


def test_stl_obj_and_ply_give_the_same_parameters(tmp_path):
    base = l_shape()
    mesh = trimesh.Trimesh(base.vertices, base.faces, process=False)
    ref_tab = directional_parameters(base, PHIS)
    for ext in ("stl", "obj", "ply"):
        path = tmp_path / f"l.{ext}"
        mesh.export(path)
        tab = directional_parameters(load_shape(path, density=RHO), PHIS)
        for k in NUMERIC:
            assert np.allclose(ref_tab[k], tab[k], rtol=1e-12, atol=1e-14), (ext, k)
    # the same body in mm
    mm = tmp_path / "l_mm.stl"
    trimesh.Trimesh(base.vertices * 1000.0, base.faces, process=False).export(mm)
    tab = directional_parameters(load_shape(mm, density=RHO, units="mm"), PHIS)
    for k in NUMERIC:
        assert np.allclose(ref_tab[k], tab[k], rtol=1e-12), k


def test_welding_merges_a_triangle_soup():
    """Every triangle with its own corners (as STL stores them), jittered by 1e-12 m."""
    v, f = ref.l_block(*L_DIMS)
    soup = v[f].reshape(-1, 3) + np.random.default_rng(1).normal(scale=1e-12, size=(3 * len(f), 3))
    faces = np.arange(3 * len(f)).reshape(-1, 3)
    sh = shape(soup, faces, weld=1e-9)
    assert len(sh.vertices) == len(v) and math.isclose(sh.volume, l_shape().volume,
                                                       rel_tol=1e-9)
    with pytest.raises(ParameterError, match="not watertight"):
        shape(soup, faces, weld=0.0)


# ------------------------------------------------------------------ refusals and repair
def one_line(exc):
    msg = str(exc.value)
    assert "\n" not in msg
    return msg


def test_an_open_mesh_is_refused_with_one_line():
    v, f = ref.box(1.0, 1.0, 2.0)
    with pytest.raises(ParameterError) as e:
        shape(v, f[1:])
    assert one_line(e).startswith("mesh is not watertight: 3 open edges")


def test_inverted_normals_are_refused_with_one_line():
    v, f = ref.box(1.0, 1.0, 2.0)
    with pytest.raises(ParameterError) as e:
        shape(v, f[:, ::-1])
    assert one_line(e).startswith("inverted normals: volume < 0")


def test_inconsistent_winding_is_refused_with_one_line():
    v, f = ref.box(1.0, 1.0, 2.0)
    f = f.copy()
    f[0] = f[0, ::-1]
    with pytest.raises(ParameterError) as e:
        shape(v, f)
    assert one_line(e).startswith("mesh winding is inconsistent: 3 edges")


@pytest.mark.parametrize("what, build, up", [
    ("a point", lambda: ref.regular_pyramid(0.3, 1.0, 8), "-z"),  # on its apex
    ("a line", lambda: ref.regular_prism(0.3, 1.0, 4, phase=0.0), "x"),  # on an edge
])
def test_a_body_without_a_flat_base_is_refused_with_one_line(what, build, up):
    with pytest.raises(ParameterError) as e:
        shape(*build(), up=up)
    msg = one_line(e)
    assert msg.startswith("no flat base") and f"stands on {what}" in msg


def test_a_body_whose_centre_of_mass_overhangs_its_base_is_refused():
    # an oblique prism leaning further than its width: the centre of mass is outside
    w, s, H = 0.2, 0.5, 1.0
    v, f = ref.extrude([(0, 0), (w, 0), (w + s, H), (s, H)], [(0, 1, 2), (0, 2, 3)], 0.3)
    with pytest.raises(ParameterError) as e:
        shape(v, f)
    assert "cannot stand" in one_line(e)


def test_repair_hull_warns_with_the_volume_added():
    a, t, H, d = L_DIMS
    v, f = ref.l_block(a, t, H, d)
    hull_added = d * (a - t) * (H - t) / 2  # the triangle (a, t), (t, t), (t, H)
    vol_l = l_hand(a, t, H, d)[0] * d
    with pytest.warns(MeshRepairWarning) as rec:
        sh = shape(v, f[:, ::-1], repair="hull")
    msg = str(rec[0].message)
    assert msg.startswith("inverted normals") and "\n" not in msg
    assert f"adds {hull_added:.4g} m^3" in msg
    assert f"{100 * hull_added / (vol_l + hull_added):.3g} %" in msg
    assert sh.repaired and math.isclose(sh.volume, vol_l + hull_added, rel_tol=1e-12)
    with pytest.warns(MeshRepairWarning, match="not watertight: "):
        shape(v, f[2:], repair="hull")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert not shape(v, f, repair="hull").repaired  # a valid mesh is kept as it is
    with pytest.raises(ParameterError, match="repair"):
        shape(v, f, repair="fix")


def test_bad_arguments_are_refused():
    v, f = ref.box(1.0, 1.0, 2.0)
    for kw, word in (({"up": "w"}, "up"), ({"up": [0, 0, 0]}, "up"), ({"tol": -1.0}, "tol"),
                     ({"tol": "2kg"}, "tol")):
        with pytest.raises(ParameterError, match=word):
            shape(v, f, **kw)
    assert math.isclose(shape(v, f, tol="2mm").tol, 0.002)
    with pytest.raises(ParameterError, match="units"):
        load_shape(example_mesh_path(), density=1.0, units="km")
    with pytest.raises(ParameterError, match=".stl, .obj or .ply"):
        load_shape("statue.step", density=1.0)


# ------------------------------------------------------------------ directions, outputs
def test_weakest_direction_is_the_support_edge_nearest_the_centre_of_mass():
    a, b, c = 0.5, 0.3, 1.2
    sh = shape(*ref.box(a, b, c))
    tab = directional_parameters(sh, 360)
    weak, strong = weakest_direction(tab), strongest_direction(tab)
    assert weak.phi_deg in (90.0, 270.0) and math.isclose(weak.uplift, G * b / c,
                                                          rel_tol=1e-9)
    # the strongest: the diagonal direction's min(b+, b-) is the largest
    diag = math.degrees(math.atan2(b, a))
    assert min(abs(strong.phi_deg % 180 - x) for x in (diag, 180 - diag)) <= 0.5
    # the example: the exact weakest is below every sampled direction, and close to them
    ex = load_example()
    tab = directional_parameters(ex, 3600)
    w, exact = weakest_direction(tab), ex.weakest()
    assert exact.uplift <= tab[["uplift_plus", "uplift_minus"]].to_numpy().min() + 1e-12
    assert math.isclose(exact.uplift, w.uplift, rel_tol=1e-4)
    assert math.isclose(exact.uplift, ex.parameters(exact.phi)["uplift_plus"], rel_tol=1e-12)


def test_polygon_is_the_projected_hull():
    a, b, c = 0.5, 0.3, 1.2
    sh = shape(*ref.box(a, b, c))
    for phi in (0.0, 0.4, 2.0):
        poly = sh.polygon(phi)
        w = a * abs(math.cos(phi)) + b * abs(math.sin(phi))
        assert len(poly) == 4
        assert close(sorted(map(tuple, poly)), sorted([(-w / 2, 0), (w / 2, 0), (w / 2, c),
                                                       (-w / 2, c)]), abs_=1e-12)
    aa, t, H, d = L_DIMS
    A, xc, zc, _, _ = l_hand(aa, t, H, d)
    poly = l_shape().polygon(0.0)
    hull = [(0, 0), (aa, 0), (aa, t), (t, H), (0, H)]
    assert close(poly, [(x - xc, z) for x, z in hull], abs_=1e-12)  # from the base's left end
    row = l_shape().parameters(0.0)
    assert math.isclose(-poly[0, 0], row["b_plus"]) and math.isclose(poly[1, 0], row["b_minus"])


def test_the_polygon_is_a_valid_dem_outline_and_the_true_inertia_is_at_hand():
    from rocking.blocks.block import Block

    sh = load_example()
    for phi in np.linspace(0.0, 2 * np.pi, 36, endpoint=False):
        poly = sh.polygon(phi)
        row = sh.parameters(phi)
        blk = Block.polygon(poly, mass=sh.mass)  # strictly convex, on a horizontal base
        base = [x for x, z in blk.vertices if z == 0.0]
        assert math.isclose(max(base) - min(base), row["b_plus"] + row["b_minus"],
                            rel_tol=1e-12)
        assert math.isclose(sh.inertia_about(phi), sh.mass * row["radius_of_gyration"] ** 2,
                            rel_tol=1e-12)
    # the axis normal to the plane of shaking along x is y: I_yy of the mesh
    assert math.isclose(sh.inertia_about(0.0), sh.inertia[1, 1], rel_tol=1e-12)


def test_block_of_a_direction_carries_both_sides():
    sh = l_shape()
    for phi in (0.0, 0.7, math.pi):
        row, blk = sh.parameters(phi), Block.from_shape(sh, phi)
        assert not blk.symmetric and blk.mass == sh.mass
        for s in SIDES:
            for k in ("alpha", "p", "mu", "R"):
                assert math.isclose(getattr(blk, f"{k}_{s}"), row[f"{k}_{s}"],
                                    rel_tol=1e-12), (k, s)
    both = Block.from_shape(sh, 0.7, mu=0.9)
    assert both.mu_plus == both.mu_minus == 0.9
    # a box in a principal direction: symmetric, Eqs 2-4
    a, b, c = 0.5, 0.3, 1.2
    blk = Block.from_shape(shape(*ref.box(a, b, c)), math.pi / 2)
    assert blk.symmetric and math.isclose(blk.alpha, math.atan(b / c), rel_tol=1e-12)
    assert math.isclose(blk.mu, 1 - 1.5 * math.sin(blk.alpha) ** 2, rel_tol=1e-12)
    # Block.from_mesh is the same block (its direction in degrees: "1rad" is phi = 1)
    m = Block.from_mesh(example_mesh_path(), density=2600.0, direction="1rad")
    e = Block.from_shape(load_example(), 1.0)
    assert (m.alpha_plus, m.alpha_minus, m.p_plus, m.mu_minus) == (
        e.alpha_plus, e.alpha_minus, e.p_plus, e.mu_minus)


def test_plot_directional_marks_the_weakest_direction():
    tab = directional_parameters(load_example(), 90)
    fig = plot_directional(tab, title="statue")
    assert len(fig.axes) == 2 and all(ax.name == "polar" for ax in fig.axes)
    w = weakest_direction(tab)
    marks = [ln for ln in fig.axes[1].lines if len(ln.get_xdata()) == 1]
    assert math.isclose(marks[0].get_xdata()[0], w.phi) and math.isclose(
        marks[0].get_ydata()[0], w.uplift_g)


def test_the_example_mesh_is_the_scripts_statue():
    from rocking.shapes.data.make_example import statue

    path = example_mesh_path()
    assert path.stat().st_size < 300_000
    v, f = statue()
    sh = load_example()
    assert len(sh.faces) == len(f)
    mesh = trimesh.load(path, process=False)
    assert np.allclose(mesh.vertices, v, rtol=0, atol=1e-6)  # float32 in the file
    # the footprint 0.45 m x 0.35 m, 1.62 m tall, its centre of mass off the centre
    foot = sh.local_vertices[sh.local_vertices[:, 2] <= sh.tol]
    assert math.isclose(np.ptp(foot[:, 0]), 0.45, rel_tol=1e-6)
    assert math.isclose(np.ptp(foot[:, 1]), 0.35, rel_tol=1e-6)
    assert math.isclose(sh.height, 1.62, rel_tol=1e-6)
    assert np.hypot(*sh.com[:2]) > 0.02
    # the weakest direction is none of the footprint's axes
    d = sh.weakest().phi_deg % 90.0
    assert 5.0 < d < 85.0


def test_an_overhang_below_the_overturning_angle_is_flagged():
    """A narrow stem (0.2 m wide, 0.1 m high) under a wide slab (1 m x 0.1 m): rocking on
    the stem, the slab's underside 0.4 m beyond the pivot touches the ground at a tilt of
    atan(0.1 / 0.4), well below alpha."""
    prof = [(-0.1, 0), (0.1, 0), (0.1, 0.1), (0.5, 0.1), (0.5, 0.2), (-0.5, 0.2), (-0.5, 0.1),
            (-0.1, 0.1)]
    tris = [(0, 1, 2), (0, 2, 7), (6, 7, 5), (7, 2, 5), (2, 4, 5), (2, 3, 4)]
    sh = shape(*ref.extrude(prof, tris, 0.2))
    zc = (0.02 * 0.05 + 0.1 * 0.15) / 0.12
    tab = directional_parameters(sh, [0.0, math.pi / 2])
    row = tab.iloc[0]
    assert math.isclose(row["alpha_plus"], math.atan(0.1 / zc), rel_tol=1e-9)
    for s in SIDES:
        assert math.isclose(row[f"contact_{s}"], math.atan(0.1 / 0.4), rel_tol=1e-9)
    assert bool(row["overhang"]) and not bool(tab.iloc[1]["overhang"])
    assert tab.iloc[1]["contact_plus"] == math.pi / 2
    # the statue does not overhang its base in any direction
    assert not directional_parameters(load_example(), 72)["overhang"].any()


def test_a_hollow_body_is_one_rigid_body_of_two_parts():
    """A box with a box-shaped cavity (the inner surface wound inwards): the mass
    properties are the difference of the two boxes', with a warning about the parts."""
    vo, fo = ref.box(1.0, 0.8, 2.0)
    vi, fi = ref.box(0.5, 0.4, 1.0)
    vi = vi + [0.1, 0.0, 0.5]
    v = np.vstack([vo, vi])
    f = np.vstack([fo, fi[:, ::-1] + len(vo)])
    with pytest.warns(UserWarning, match="2 separate parts"):
        sh = shape(v, f)
    m_o, m_i = RHO * 1.6, RHO * 0.2
    assert math.isclose(sh.mass, m_o - m_i, rel_tol=1e-12)
    assert np.allclose(sh.com, [-0.1 * m_i / (m_o - m_i), 0.0, 1.0], rtol=0, atol=1e-12)
    # parallel axes: the inner box's centre is 0.1 from the axis, the body's com at com_x
    izz = (m_o * (1.64 / 12 + sh.com[0] ** 2)
           - m_i * (0.41 / 12 + (0.1 - sh.com[0]) ** 2))
    assert math.isclose(sh.inertia[2, 2], izz, rel_tol=1e-12)
