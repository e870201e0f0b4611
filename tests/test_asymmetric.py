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
    """Block.from_mesh is Shape.block of the loaded mesh (a box: a symmetric block in its
    principal direction, Eqs 2-4 to the precision of the mesh's mass properties)."""
    trimesh = pytest.importorskip("trimesh")
    from rocking.shapes import load_shape

    path = tmp_path / "box.stl"
    trimesh.creation.box(extents=(0.3, 0.2, 1.0)).export(path)
    for phi in (0.0, 1.0):
        blk = Block.from_mesh(path, density=2000.0, direction=phi)
        assert blk == load_shape(path, density=2000.0).block(phi)
    blk = Block.from_mesh(path, density=2000.0)
    ref = Block.rectangular(0.3, 1.0)
    assert blk.symmetric
    for k in ("alpha", "p", "mu"):
        assert getattr(blk, k) == pytest.approx(getattr(ref, k), rel=1e-6)
    assert blk.mass == pytest.approx(2000.0 * 0.3 * 0.2 * 1.0, rel=1e-6)  # STL: float32
