r"""Plain reference for the mass properties of a closed triangle mesh, and test meshes.

:func:`mass_properties` is written independently of trimesh (whose
:func:`trimesh.triangles.mass_properties` follows Eberly's closed-form subexpressions): by
the divergence theorem, a volume integral of ``f`` is the flux of any field ``F`` with
``div F = f`` through the boundary,

.. math:: \int_V f\,dV = \sum_{T} \int_T F \cdot n\, dA ,

and the flux through each triangle is integrated *exactly* by a quadrature rule: ``F`` is
a polynomial of degree at most 3 for ``f`` in {1, x, x x^T}, and Radon's 7-point rule on a
triangle (Stroud T2:5-1) is exact to degree 5. Fields: ``f = 1``: ``F = r/3``;
``f = x_i``: ``F = (x_i^2/2) e_i``; ``f = x_i^2``: ``F = (x_i^3/3) e_i``; ``f = x_i x_j``
(i != j): ``F = (x_i^2 x_j / 2) e_i``. Plain Python loops over the triangles (meant for
small meshes in tests), about the vertices' mean (for accuracy). Mirtich (1996) and
Eberly (2002) reduce the same flux integrals in closed form instead.

The mesh builders (:func:`box`, :func:`extrude`, :func:`regular_prism`,
:func:`regular_pyramid`, :func:`l_block`) return ``(vertices, faces)`` with outward
normals, for the tests of :mod:`rocking.shapes`.
"""

from __future__ import annotations

import math

import numpy as np

_S15 = math.sqrt(15.0)
_A1 = (6.0 - _S15) / 21.0
_A2 = (6.0 + _S15) / 21.0
_W1 = (155.0 - _S15) / 1200.0
_W2 = (155.0 + _S15) / 1200.0
RADON7 = ([(1 / 3, 1 / 3, 1 / 3, 9 / 40)]
          + [(a, a, 1 - 2 * a, w) for a, w in ((_A1, _W1), (_A2, _W2))]
          + [(a, 1 - 2 * a, a, w) for a, w in ((_A1, _W1), (_A2, _W2))]
          + [(1 - 2 * a, a, a, w) for a, w in ((_A1, _W1), (_A2, _W2))])
"""Radon's 7-point rule on a triangle: barycentric coordinates and weights (sum 1),
exact for polynomials of degree <= 5."""


def mass_properties(vertices, faces, density: float = 1.0) -> dict:
    """``volume`` (m^3), ``mass`` (kg), ``com`` (3,) and ``inertia`` (3, 3, about the
    centre of mass, ``int (|r|^2 1 - r r^T) dm``) of the solid bounded by the triangles
    (outward normals), by the divergence theorem with exact quadrature (module docstring)."""
    v = [tuple(float(c) for c in p) for p in np.asarray(vertices, dtype=float)]
    o = [sum(p[i] for p in v) / len(v) for i in range(3)]
    v = [(p[0] - o[0], p[1] - o[1], p[2] - o[2]) for p in v]
    vol = 0.0
    first = [0.0, 0.0, 0.0]
    second = [[0.0] * 3 for _ in range(3)]  # int x_i x_j dV
    for tri in np.asarray(faces):
        p0, p1, p2 = (v[int(k)] for k in tri)
        e1 = [p1[i] - p0[i] for i in range(3)]
        e2 = [p2[i] - p0[i] for i in range(3)]
        # n dA integrated over the triangle = cross(e1, e2) / 2 (constant normal)
        na = [0.5 * (e1[1] * e2[2] - e1[2] * e2[1]),
              0.5 * (e1[2] * e2[0] - e1[0] * e2[2]),
              0.5 * (e1[0] * e2[1] - e1[1] * e2[0])]
        for l0, l1, l2, w in RADON7:
            x = [l0 * p0[i] + l1 * p1[i] + l2 * p2[i] for i in range(3)]
            vol += w * sum(x[i] * na[i] for i in range(3)) / 3.0
            for i in range(3):
                first[i] += w * 0.5 * x[i] * x[i] * na[i]
                second[i][i] += w * x[i] ** 3 / 3.0 * na[i]
                for j in range(3):
                    if j != i and j > i:
                        second[i][j] += w * 0.5 * x[i] * x[i] * x[j] * na[i]
    for i in range(3):
        for j in range(i):
            second[i][j] = second[j][i]
    com = [first[i] / vol for i in range(3)]
    # second moments about the centre of mass (per unit density)
    c2 = [[second[i][j] - vol * com[i] * com[j] for j in range(3)] for i in range(3)]
    trace = c2[0][0] + c2[1][1] + c2[2][2]
    inertia = [[density * ((trace if i == j else 0.0) - c2[i][j]) for j in range(3)]
               for i in range(3)]
    return {"volume": vol, "mass": density * vol,
            "com": np.array([com[i] + o[i] for i in range(3)]),
            "inertia": np.array(inertia)}


# ---------------------------------------------------------------------------- meshes
def extrude(profile, cap_triangles, depth: float):
    """The prism of the polygon ``profile`` ((x, z) pairs, counter-clockwise in the x-z
    plane seen from -y) extruded along y over ``[-depth/2, depth/2]``; ``cap_triangles``
    triangulate the profile (index triples, counter-clockwise)."""
    p = np.asarray(profile, dtype=float)
    n = len(p)
    front = np.column_stack([p[:, 0], np.full(n, -0.5 * depth), p[:, 1]])  # y = -d/2
    back = np.column_stack([p[:, 0], np.full(n, 0.5 * depth), p[:, 1]])
    verts = np.vstack([front, back])
    faces = []
    # a triangle counter-clockwise in (x, z) has its right-hand normal along -y: outward
    # on the front cap (y = -d/2), reversed on the back cap
    for a, b, c in cap_triangles:
        faces.append((a, b, c))
        faces.append((n + a, n + c, n + b))
    # walls: the outward normal of the counter-clockwise edge i -> j is (dz, 0, -dx)
    for i in range(n):
        j = (i + 1) % n
        faces.append((i, n + j, j))
        faces.append((i, n + i, n + j))
    return verts, np.array(faces)


def _outward(v, f):
    """Flip every face if the signed volume is negative (a builder's orientation)."""
    t = v[f] - v.mean(axis=0)
    vol = np.sum(np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])))
    return (v, f) if vol > 0 else (v, f[:, ::-1].copy())


def box(a: float, b: float, c: float):
    """A box [-a/2, a/2] x [-b/2, b/2] x [0, c] (12 triangles)."""
    prof = [(-a / 2, 0.0), (a / 2, 0.0), (a / 2, c), (-a / 2, c)]
    return extrude(prof, [(0, 1, 2), (0, 2, 3)], b)


def l_block(a: float, t: float, height: float, depth: float):
    """An extruded L: the foot [0, a] x [0, t] and the upright [0, t] x [t, height] in the
    x-z plane, depth ``depth`` along y (a non-convex solid)."""
    prof = [(0.0, 0.0), (a, 0.0), (a, t), (t, t), (t, height), (0.0, height)]
    # a fan from the reflex corner (t, t), index 3
    tris = [(3, 4, 5), (3, 5, 0), (3, 0, 1), (3, 1, 2)]
    return extrude(prof, tris, depth)


def regular_prism(radius: float, height: float, n: int, phase: float = 0.0):
    """A right prism on the regular n-gon of circumradius ``radius`` (vertex k at angle
    ``phase + 2 pi k / n``), base on z = 0."""
    ang = phase + 2.0 * np.pi * np.arange(n) / n
    ring = np.column_stack([radius * np.cos(ang), radius * np.sin(ang)])
    v = np.vstack([np.column_stack([ring, np.zeros(n)]),
                   np.column_stack([ring, np.full(n, height)])])
    f = [(0, k + 1, k) for k in range(1, n - 1)]  # bottom (normal -z)
    f += [(n, n + k, n + k + 1) for k in range(1, n - 1)]  # top
    for k in range(n):
        j = (k + 1) % n
        f += [(k, j, n + j), (k, n + j, n + k)]
    return _outward(v, np.array(f))


def regular_pyramid(radius: float, height: float, n: int, phase: float = 0.0):
    """A right pyramid on the regular n-gon of circumradius ``radius`` (z = 0), apex at
    ``(0, 0, height)``: a polygonal cone."""
    ang = phase + 2.0 * np.pi * np.arange(n) / n
    v = np.vstack([np.column_stack([radius * np.cos(ang), radius * np.sin(ang), np.zeros(n)]),
                   [[0.0, 0.0, height]]])
    f = [(0, k + 1, k) for k in range(1, n - 1)]
    f += [(k, (k + 1) % n, n) for k in range(n)]
    return _outward(v, np.array(f))


__all__ = ["RADON7", "box", "extrude", "l_block", "mass_properties", "regular_prism",
           "regular_pyramid"]
