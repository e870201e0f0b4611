"""The block factory's ``mesh`` form (issue 20): the planar block of a 3-D mesh in one
direction, the same entry for Python, the command line and campaign specs; the DEM's body
of a mesh block (the outline with the mesh's true mass, centre of mass and inertia); a
statue on a plinth as a two-block stack.

Expected values are closed forms of a box (Eqs 2-4 across its faces, its inertia about an
oblique axis), :mod:`rocking.shapes` computed independently of the factory, sums of the
parts, and the classical model run on the same block (the DEM-vs-classical tolerances of
tests/test_dem.py)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import trimesh
from cli_helpers import assert_one_line_error, run_main

from rocking import Block, simulate
from rocking.blocks.factory import make_block, make_blocks, mesh_block
from rocking.campaign import parse_spec
from rocking.errors import ParameterError, SpecError
from rocking.models import dem as D
from rocking.motions import HalfSine
from rocking.shapes import Shape, example_mesh_path, load_example, load_shape
from rocking.testing import mesh_reference as ref
from rocking.units import G

A, B, C, RHO = 0.5, 0.25, 1.25, 2000.0  # a box (m; exact in a file's float32)


@pytest.fixture(scope="module")
def box_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("mesh") / "box.ply"
    trimesh.Trimesh(*ref.box(A, B, C), process=False).export(path)
    return path


def eqs_2_to_4(half: float, hh: float) -> tuple:
    R = math.hypot(half, hh)
    alpha = math.atan(half / hh)
    return alpha, math.sqrt(3 * G / (4 * R)), 1 - 1.5 * math.sin(alpha) ** 2


# ------------------------------------------------------------------------- the form
@pytest.mark.parametrize("direction,half", [(0, A / 2), ("90deg", B / 2), (90, B / 2),
                                            (f"{math.pi}rad", A / 2), ("weakest", B / 2)])
def test_box_directions_give_eqs_2_to_4(box_file, direction, half):
    """Across a face of the box the block is Eqs 2-4 of that face's half-width; a bare
    number is in degrees, a string may carry its unit; "weakest" is across the narrow
    face."""
    b = make_block({"mesh": str(box_file), "density": RHO, "direction": direction})
    alpha, p, mu = eqs_2_to_4(half, C / 2)
    assert b.symmetric
    assert math.isclose(b.alpha, alpha, rel_tol=1e-9)
    assert math.isclose(b.p, p, rel_tol=1e-9)
    assert math.isclose(b.mu, mu, rel_tol=1e-9)
    assert math.isclose(b.mass, RHO * A * B * C, rel_tol=1e-12)


def test_the_form_is_shape_block(box_file):
    """The factory's block is rocking.shapes' block of that direction, with the outline
    Shape.polygon; a given mass replaces the density; the strongest direction is at least
    as strong as any other."""
    path = example_mesh_path()
    sh = load_example(mass=300.0)
    for deg in (0.0, 37.0, 200.0):
        b = make_block({"mesh": str(path), "mass": 300, "direction": deg})
        ref_block = Block.from_shape(sh, math.radians(deg))
        for k in ("alpha_plus", "alpha_minus", "p_plus", "p_minus", "mu_plus", "mu_minus",
                  "mass", "I_O"):
            assert math.isclose(getattr(b, k), getattr(ref_block, k), rel_tol=1e-12), k
        poly = sh.polygon(math.radians(deg))
        assert np.allclose(np.ptp(np.array(b.vertices), axis=0), np.ptp(poly, axis=0))
    strong = make_block({"mesh": str(path), "mass": 300, "direction": "strongest"})
    table_up = [min(q["uplift_plus"], q["uplift_minus"]) for q in
                (sh.parameters(phi) for phi in np.linspace(0, 2 * np.pi, 97))]
    assert strong.uplift_acceleration >= max(table_up) * (1 - 1e-12)


def test_a_list_of_directions_gives_one_block_each(box_file):
    bs = make_blocks({"mesh": str(box_file), "density": RHO, "direction": [0, 90, "weakest"]})
    weak = math.degrees(load_shape(box_file, density=RHO).weakest().phi)
    assert [b.name for b in bs] == ["box @ 0 deg", "box @ 90 deg",
                                    f"box @ weakest ({weak:.1f} deg)"]
    assert bs[1].alpha == pytest.approx(bs[2].alpha, rel=1e-12)
    assert bs[0].alpha > bs[1].alpha
    named = make_blocks({"mesh": str(box_file), "density": RHO, "direction": [0, 90],
                         "name": "plinth"})
    assert [b.name for b in named] == ["plinth @ 0 deg", "plinth @ 90 deg"]
    with pytest.raises(ParameterError, match="direction"):
        make_block({"mesh": str(box_file), "density": RHO, "direction": [0, 90]})


@pytest.mark.parametrize("keys,name", [
    ({"density": RHO, "mass": 3.0}, "density or mass"),
    ({}, "density or mass"),
    ({"density": RHO, "direction": "north"}, "direction"),
    ({"density": RHO, "direction": []}, "direction"),
    ({"density": RHO, "direction": True}, "direction"),
    ({"density": RHO, "units": "inch"}, "units"),
    ({"density": RHO, "plinth_width": 1.0}, "plinth_depth"),
    ({"density": RHO, "plinth_density": 1.0}, "plinth_density"),
])
def test_bad_keys_name_the_key(box_file, keys, name):
    with pytest.raises(ParameterError, match=name):
        make_block({"mesh": str(box_file), **keys})


def test_the_command_line_takes_mesh_flags(capsys, box_file, tmp_path):
    code, out, err = run_main(capsys, "params", "--mesh", box_file, "--density", RHO,
                              "--direction", "90", "--json")
    assert code == 0, err
    d = json.loads(out)
    assert math.isclose(d["alpha"], math.atan(B / C), rel_tol=1e-9)
    code, _, err = run_main(capsys, "params", "--mesh", box_file)
    assert_one_line_error(code, err, "density")
    out_dir = tmp_path / "run"
    code, _, err = run_main(capsys, "simulate", "--mesh", example_mesh_path(), "--mass", "250",
                            "--direction", "weakest", "--motion", "ricker", "--amp", "0.1g",
                            "--freq", "2Hz", "--out", out_dir)
    assert code == 0, err
    given = json.loads((out_dir / "summary.json").read_text())["inputs"]["block"]
    weak = load_example(mass=250.0).weakest()
    assert given["direction"] == "weakest"
    assert given["direction_deg"] == pytest.approx(weak.phi_deg, abs=1e-9)
    assert given["alpha"] == pytest.approx(weak.alpha, rel=1e-12)
    code, _, err = run_main(capsys, "params", "--width", "1", "--height", "2", "--up", "y")
    assert_one_line_error(code, err, "--mesh")
    code, _, err = run_main(capsys, "simulate", "--mesh", box_file, "--mass", "10",
                            "--direction", "sideways", "--motion", "ricker", "--amp", "0.1g",
                            "--freq", "2Hz")
    assert_one_line_error(code, err, "direction")


# ------------------------------------------------------------------- campaign spec
SPEC = """
[campaign]
name = "mesh"
seed = 1
model = "housner"

[[blocks]]
mesh = "{mesh}"
density = 2000
direction = [0, 90, "weakest"]

[[blocks]]
width = 0.2
height = 1.0

[motions]
kind = "builtin"
name = ["RSN126_GAZLI_GAZ000"]
load_factors = [0.5]
"""


def test_a_spec_with_a_mesh_block_and_a_direction_list(tmp_path, box_file):
    """Relative paths start from the spec's folder; the list gives three blocks in place;
    the mesh's content is in the spec's hash."""
    folder = tmp_path / "study"
    (folder / "scans").mkdir(parents=True)
    (folder / "scans" / "box.ply").write_bytes(box_file.read_bytes())
    text = SPEC.format(mesh="scans/box.ply")
    spec = parse_spec(text, base_dir=folder)
    names = [b.name for b in spec.blocks]
    assert len(names) == 4 and names[0].startswith("box @ 0 deg (blocks[0])")
    assert names[3].endswith("(blocks[1])")
    assert spec.blocks[1].alpha == pytest.approx(math.atan(B / C), rel=1e-9)
    h0 = spec.hash
    trimesh.Trimesh(*ref.box(A, B, 2 * C), process=False).export(folder / "scans" / "box.ply")
    again = parse_spec(text, base_dir=folder)
    assert again.hash != h0
    assert again.blocks[1].alpha == pytest.approx(math.atan(B / (2 * C)), rel=1e-9)
    with pytest.raises(SpecError, match=r"blocks\[0\]"):
        parse_spec(text, base_dir=tmp_path)  # no scans/ there
    with pytest.raises(SpecError, match=r"blocks\[0\].*direction"):
        parse_spec(text.replace('"weakest"', '"sideways"'), base_dir=folder)


# ------------------------------------------------------------------------- the DEM
def test_dem_body_is_the_mesh_body_and_rocks_like_the_classical_block(box_file):
    """Shaken obliquely (30 deg) the box's outline is a wider rectangle whose own inertia
    is not the box's about the oblique axis: the DEM takes the mesh's mass, centre of mass
    and inertia, and its free rocking then follows the classical model of Shape.block
    (tests/test_dem.py's tolerances)."""
    sh = load_shape(box_file, density=RHO)
    phi = math.radians(30.0)
    blk = mesh_block(sh, phi)
    bd = D.body_of(blk)
    assert bd.mode == "body"
    assert math.isclose(bd.mass, sh.mass, rel_tol=1e-12)
    assert math.isclose(bd.inertia, sh.inertia_about(phi), rel_tol=1e-9)
    m = RHO * A * B * C  # closed form about u = (-sin, cos, 0): sin^2 Ixx + cos^2 Iyy
    i_u = m / 12 * (math.sin(phi) ** 2 * (B * B + C * C) + math.cos(phi) ** 2 * (A * A + C * C))
    assert math.isclose(bd.inertia, i_u, rel_tol=1e-9)
    poly_own = D.body_of(blk, "polygon")
    assert abs(poly_own.inertia / bd.inertia - 1) > 0.03  # the polygon's would differ
    # the centre of mass is at the middle of the base, C/2 up
    assert np.allclose(0.5 * (bd.verts[0] + bd.verts[1]), [0.0, -C / 2], atol=1e-12)
    th0 = 0.5 * blk.alpha
    r = simulate(blk, None, model="dem", duration=3.0, theta0=th0, dt_out=5e-4)
    h = simulate(Block.from_shape(sh, phi), None, duration=3.0, theta0=th0, dt_out=5e-4)
    a, a0 = np.abs(r.half_cycle_peaks()[1]), np.abs(h.half_cycle_peaks()[1])
    assert np.max(np.abs(a[1:6] / a0[1:6] - 1)) < 0.03
    assert np.max(np.abs(r.impact_times[:5] / h.impact_times[:5] - 1)) < 0.02


def test_asymmetric_block_without_a_body_is_refused_by_the_dem():
    sh = load_example(density=2600.0)
    phi = sh.weakest().phi
    bare = Block.from_shape(sh, phi, outline=False)  # both sides, no outline
    assert not bare.symmetric
    with pytest.raises(ParameterError, match="geometry 'body'"):
        simulate(bare, None, model="dem", duration=0.1, theta0=0.01)
    with pytest.raises(ParameterError, match="geometry 'body'"):
        simulate(mesh_block(sh, phi), None, model="dem", duration=0.1, theta0=0.01,
                 geometry="equivalent")
    body = D.body_of(mesh_block(sh, phi))
    assert body.mode == "body" and math.isclose(body.inertia, sh.inertia_about(phi),
                                                rel_tol=1e-9)


# ---------------------------------------------------------------- statue on a plinth
def test_statue_on_a_plinth(tmp_path):
    """The stack's mass and centre of mass are the sums of the parts' (the statue's centre
    of mass over the plinth's axis, h above its top), each DEM body has its part's true
    mass and inertia, and it runs under a pulse with the DEM."""
    w, d, hp, rho_p = 0.6, 0.5, 0.8, 2400.0
    st = make_block({"mesh": str(example_mesh_path()), "density": 2600,
                     "direction": "weakest", "plinth_width": w, "plinth_depth": d,
                     "plinth_height": hp, "plinth_density": rho_p})
    sh = load_example(density=2600.0)
    phi = sh.weakest().phi
    md = D.build_assembly(st)
    assert [b.mode for b in md.bodies] == ["body", "body"]
    m_p = rho_p * w * d * hp
    assert np.allclose(md.mass, [m_p, sh.mass], rtol=1e-12)
    plinth = Shape.from_arrays(*ref.box(w, d, hp), density=rho_p)
    assert np.allclose(md.inertia, [plinth.inertia_about(phi), sh.inertia_about(phi)],
                       rtol=1e-9)
    total = md.mass.sum()
    com = (md.mass[:, None] * md.nominal[:, :2]).sum(axis=0) / total
    expected_y = (m_p * hp / 2 + sh.mass * (hp + sh.h)) / (m_p + sh.mass)
    assert math.isclose(total, m_p + sh.mass, rel_tol=1e-12)
    assert np.allclose(com, [0.0, expected_y], atol=1e-9)
    r = simulate(st, HalfSine(0.3 * G, 0.5), model="dem", duration=1.5, damping=0.0)
    assert r.theta_all.shape[0] == 2 and not r.overturned
    assert r.info["max_abs_theta_all"][1] > 1e-3  # the statue rocked on its plinth


def test_a_plinth_smaller_than_the_statue_s_base_is_refused():
    with pytest.raises(ParameterError, match="plinth_width or plinth_depth"):
        make_block({"mesh": str(example_mesh_path()), "density": 2600, "plinth_width": 0.2,
                    "plinth_depth": 0.2, "plinth_height": 0.5, "plinth_mass": 100})


def test_dem_rocks_an_asymmetric_mesh_block_like_the_classical_model():
    """The statue across its x axis (alpha_plus = 21.8, alpha_minus = 16.5 deg): the DEM
    damps an asymmetric body's impacts plastically (the damping at its cap, where the DEM's
    restitutions are the angular-momentum balance of the mesh body, i.e. mu_plus and
    mu_minus), and its free rocking follows the asymmetric classical model
    (tests/test_dem.py's tolerances). Restitutions given otherwise need a damping."""
    sh = load_example(density=2600.0)
    blk = mesh_block(sh, 0.0)
    assert not blk.symmetric and abs(blk.alpha_plus - blk.alpha_minus) > 0.05
    th0 = 0.5 * blk.alpha_plus
    r = simulate(blk, None, model="dem", duration=3.0, theta0=th0, dt_out=5e-4)
    assert r.info["damping_source"] == "plastic impact (asymmetric body)"
    assert r.info["damping"] == pytest.approx(D.damping_cap(blk), rel=1e-12)
    h = simulate(Block.from_shape(sh, 0.0), None, duration=3.0, theta0=th0, dt_out=5e-4)
    a, a0 = np.abs(r.half_cycle_peaks()[1]), np.abs(h.half_cycle_peaks()[1])
    n = min(len(a), len(a0), 6)
    assert n >= 4
    assert np.max(np.abs(a[1:n] / a0[1:n] - 1)) < 0.03
    assert np.max(np.abs(r.impact_times[:n - 1] / h.impact_times[:n - 1] - 1)) < 0.02
    with pytest.raises(ParameterError, match="give damping"):
        simulate(blk.with_params(mu=0.95), None, model="dem", duration=0.1, theta0=0.01)
    simulate(blk.with_params(mu=0.95), None, model="dem", duration=0.1, theta0=0.01,
             damping=1e-4)


def test_make_blocks_gives_repeated_directions_unique_names():
    """Issue 32: a mesh block with ``direction = [0, 0]`` built directly (not through a
    spec) gets two names, so results grouped by name keep both."""
    from rocking.blocks.factory import make_blocks
    from rocking.shapes.example import example_mesh_path

    blocks = make_blocks({"mesh": str(example_mesh_path()), "density": 2600,
                          "direction": [0, 0, 90]}, name="statue")
    names = [b.name for b in blocks]
    assert len(set(names)) == 3, names
    assert blocks[0].alpha == blocks[1].alpha
