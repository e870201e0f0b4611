"""The resting pose of a body lowered onto a plane and released under gravity (issue 30).

A scanned body rarely stands on an exactly flat face: a rock rests on three points, and
the patch of vertices within a tolerance of its lowest plane (:mod:`rocking.shapes.support`)
depends on that tolerance. Here the body is instead *settled*: lowered along ``up`` onto
the plane until its lowest point touches, then rolled quasi-statically over its convex
hull (only the hull's vertices can touch a plane) until it rests on a face whose polygon
holds the centre of mass's vertical. Each stage is exact geometry (a rotation to the next
vertex that reaches the plane); the only threshold is rounding, :data:`REST_EPS` of the
body's size.

**The roll.** With the body touching the plane on the contact set ``C`` (the hull's
vertices at the lowest height, to rounding), ``S`` the convex hull of ``C`` projected on
the plane (a point, a segment or a polygon) and ``g`` the centre of mass's projection:

* ``g`` strictly inside a polygon ``S``: the body rests; done;
* otherwise let ``s`` be the point of ``S`` nearest to ``g`` and ``d = (g - s) / |g - s|``:
  the body tips about ``s`` (about the edge through ``s`` when ``s`` is inside an edge of
  ``S``; the other contacts lift, as they all lie behind ``s`` along ``d``), the up vector
  turning as ``u cos(t) - d sin(t)``, which lowers the centre of mass, until the first
  vertex ahead (``w . d > 0`` with ``w`` its offset from ``s``) reaches the plane, at
  ``tan(t) = (w . u) / (w . d)``;
* ``g`` on the boundary of ``S`` (``|g - s|`` at rounding): the body is balanced on an edge
  or a vertex, its resting pose is not defined (refused: tilt ``up`` slightly).

The centre of mass's height falls at every stage and the contact sets are finitely many,
so the roll ends; it ends on a face because the centre of mass of a solid lies strictly
inside its hull. This is the pose a body reaches when it is set down slowly; a body
dropped with speed may bounce or roll past it (``tests/test_rest.py`` checks both against
:mod:`rocking.models.rigid3d`).

:func:`rest_pose` returns the settled :class:`~rocking.shapes.Shape` (the same mesh and
mass, its ``up`` the resting pose's: the body rotated into that pose; its support the
resting face, exactly, with ``tol`` at rounding). :func:`load_shape` and
:meth:`Shape.from_arrays` do the same with ``settle=True``; :func:`is_resting` tells
whether a shape already rests exactly on its declared base.
"""

from __future__ import annotations

import math
from collections import namedtuple

import numpy as np

from ..errors import ParameterError

REST_EPS = 1e-9
"""Rounding threshold of the roll, as a fraction of the body's size (the largest side of
its bounding box): vertices within it of the plane touch it."""

Rest = namedtuple("Rest", ["up", "contacts", "stages", "angle"])
Rest.__doc__ = """A resting pose (:func:`settle`): ``up`` (3,) the unit vector, in the mesh's
coordinates, that points up at rest (the resting face's inward normal); ``contacts`` the
indices of the points on the plane at rest; ``stages`` the number of tipping stages of the
roll; ``angle`` (rad) between the given ``up`` and the resting one."""


def _basis(u):
    """Two unit vectors completing ``u`` to an orthonormal basis."""
    a = np.array([1.0, 0.0, 0.0]) if abs(u[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = a - (a @ u) * u
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(u, e1)


def _nearest(poly, g, eps):
    """The point of the convex set of the 2-D points ``poly`` nearest to ``g`` and whether
    ``g`` lies strictly inside it (by more than ``eps``; a polygon only)."""
    from scipy.spatial import ConvexHull, QhullError

    pts = np.asarray(poly)
    if len(pts) >= 3:
        try:
            hull = ConvexHull(pts)
            ring = pts[hull.vertices]
        except (QhullError, ValueError):
            ring = None
        if ring is not None and hull.volume > eps * eps:
            a, b = ring, np.roll(ring, -1, axis=0)
            e = b - a
            ln = np.hypot(e[:, 0], e[:, 1])
            rel = g[None, :] - a
            dist = (e[:, 0] * rel[:, 1] - e[:, 1] * rel[:, 0]) / ln  # > 0 inside (ccw)
            if float(dist.min()) > eps:
                return g.copy(), True
            return _nearest_on_segments(a, b, g), False
    # a point or a segment: its two extreme points along its longest spread
    if len(pts) == 1:
        return pts[0].copy(), False
    span = pts - pts[0]
    axis = span[int(np.argmax(np.hypot(span[:, 0], span[:, 1])))]
    if not np.hypot(*axis) > eps:
        return pts[0].copy(), False
    t = span @ axis
    a, b = pts[int(np.argmin(t))], pts[int(np.argmax(t))]
    return _nearest_on_segments(a[None], b[None], g), False


def _nearest_on_segments(a, b, g):
    """The point nearest to ``g`` on the segments ``a[i] b[i]``."""
    e = b - a
    ll = np.einsum("ij,ij->i", e, e)
    t = np.clip(np.einsum("ij,ij->i", g[None, :] - a, e) / np.where(ll > 0, ll, 1.0), 0, 1)
    p = a + t[:, None] * e
    return p[int(np.argmin(np.hypot(*(p - g[None, :]).T)))].copy()


def settle(points, com, up, *, max_stages=None) -> Rest:
    """The resting pose of the convex hull of ``points`` (n, 3), with its centre of mass
    at ``com`` (3,), lowered along ``up`` (3,, a unit vector pointing up; the mesh's
    coordinates throughout) and released: the quasi-static roll of the module docstring.

    Raises :class:`~rocking.errors.ParameterError` (naming ``up``) where the body is
    balanced on an edge or a vertex, and (naming ``block``) where the centre of mass is
    not strictly inside the hull or the roll does not end in ``max_stages`` stages
    (default ``10 n + 100``).

    Examples
    --------
    A 1 x 1 x 2 box set down on an edge, tilted by 20 deg: its centre of mass's vertical
    falls inside its base (alpha = atan(1/2) = 26.6 deg), so it rolls back onto it (a
    rotation of 20 deg); tilted by 60 deg it falls onto its side, 30 deg further.

    >>> import math
    >>> import numpy as np
    >>> from rocking.shapes.rest import settle
    >>> corners = np.array([(x, y, z) for x in (-.5, .5) for y in (-.5, .5) for z in (0, 2)])
    >>> com = np.array([0.0, 0.0, 1.0])
    >>> def tilted(deg):  # the world's up vector in the box's coordinates
    ...     t = math.radians(deg)
    ...     return np.array([-math.sin(t), 0.0, math.cos(t)])
    >>> r = settle(corners, com, tilted(20))
    >>> np.round(r.up, 12).tolist(), len(r.contacts), round(math.degrees(r.angle), 9)
    ([0.0, 0.0, 1.0], 4, 20.0)
    >>> r = settle(corners, com, tilted(60))
    >>> (np.round(r.up, 12) + 0.0).tolist(), round(math.degrees(r.angle), 9)
    ([-1.0, 0.0, 0.0], 30.0)
    """
    from scipy.spatial import ConvexHull, QhullError

    p = np.asarray(points, dtype=np.float64)
    c = np.asarray(com, dtype=np.float64).reshape(3)
    u0 = np.asarray(up, dtype=np.float64).reshape(3)
    u0 = u0 / np.linalg.norm(u0)
    size = float(np.max(np.ptp(p, axis=0)))
    eps = REST_EPS * size
    try:
        hull = ConvexHull(p)
    except (QhullError, ValueError):
        raise ParameterError("block: the body's convex hull has no volume (a flat or "
                             "degenerate mesh): it cannot rest on the plane") from None
    inside = float(np.max(hull.equations[:, :3] @ c + hull.equations[:, 3]))
    if not inside < -eps:
        raise ParameterError(
            f"block: the centre of mass is {'outside' if inside > 0 else 'on'} the body's "
            "convex hull (inconsistent mass properties): it cannot rest on the plane")
    idx = hull.vertices
    hp = p[idx]
    u = u0.copy()
    limit = 10 * len(hp) + 100 if max_stages is None else int(max_stages)
    stages = 0
    while True:
        z = hp @ u
        zmin = float(z.min())
        on = np.flatnonzero(z - zmin <= eps)
        e1, e2 = _basis(u)
        xy = np.column_stack([hp[on] @ e1, hp[on] @ e2])
        g = np.array([c @ e1, c @ e2])
        s, rests = _nearest(xy, g, eps)
        if rests:
            break
        off = g - s
        dist = float(np.hypot(*off))
        if not dist > eps:
            what = "a vertex" if len(on) == 1 else "an edge"
            raise ParameterError(
                f"up: the body set down along up = {np.round(u0, 6).tolist()} balances on "
                f"{what} of its convex hull (the centre of mass's vertical is on it): its "
                "resting pose is not defined; tilt up slightly towards the side it should "
                "fall")
        if stages >= limit:
            raise ParameterError(f"block: the roll into the resting pose did not end in "
                                 f"{limit} stages")
        d = (off[0] * e1 + off[1] * e2) / dist
        s3 = s[0] * e1 + s[1] * e2 + zmin * u
        w = hp - s3
        wu, wd = w @ u, w @ d
        ahead = wd > eps
        if not ahead.any():  # cannot happen for a centre of mass inside the hull
            raise ParameterError("block: the roll into the resting pose found no vertex "
                                 "ahead of the pivot (a degenerate hull)")
        t = float(np.min(np.arctan2(np.maximum(wu[ahead], 0.0), wd[ahead])))
        u = u * math.cos(t) - d * math.sin(t)
        u /= np.linalg.norm(u)
        stages += 1
    if stages:  # snap up to the resting face's plane (the rounding of the rotations)
        q = hp[on] - hp[on].mean(axis=0)
        n = np.linalg.svd(q)[2][-1]
        u = n if n @ u > 0 else -n
        z = hp @ u
        on = np.flatnonzero(z - z.min() <= eps)
    angle = math.atan2(float(np.linalg.norm(np.cross(u0, u))), float(u0 @ u))
    return Rest(up=u, contacts=idx[on], stages=stages, angle=angle)


def is_resting(shape) -> bool:
    """Whether ``shape`` rests exactly on its declared base: every hull vertex of its
    contact patch (within ``tol``) is on the base plane to rounding (:data:`REST_EPS` of
    its size), so that the patch is the face it touches (its centre of mass's vertical is
    strictly inside the patch's hull: :class:`~rocking.shapes.Shape` checks it). A base
    within ``tol`` but not flat (a rock resting on three points, a scan tilted by a
    fraction of a degree) is not resting: it touches the plane at fewer points than its
    patch.

    Examples
    --------
    >>> from rocking.shapes import Shape
    >>> from rocking.shapes.rest import is_resting, rest_pose
    >>> box = Shape.box(0.4, 0.6, 2.0, density=2000.0)
    >>> is_resting(box)
    True
    >>> v = box.vertices.copy()
    >>> v[(v[:, 0] < 0) & (v[:, 2] == 0), 2] -= 1e-4  # a base edge 0.1 mm lower (tol 2 mm)
    >>> rock = Shape.from_arrays(v, box.faces, density=2000.0)
    >>> rock.contact_points, is_resting(rock), is_resting(rest_pose(rock))
    (4, False, True)
    """
    pts = np.asarray(shape.hull_points())
    eps = rest_tolerance(shape.vertices)
    patch = pts[pts[:, 2] <= shape.tol]
    return bool(len(patch) >= 3 and float(patch[:, 2].max()) <= eps)


def rest_pose(shape):
    """``shape`` settled into its resting pose (:func:`settle` from its ``up``): the same
    mesh and mass, with ``up`` the resting pose's, the support its resting face and
    ``tol`` at rounding (:data:`REST_EPS` of its size). A shape already resting exactly on
    its base (:func:`is_resting`) is returned as it is.

    Examples
    --------
    A box tilted by 10 deg about y (its mesh turned, ``up="z"`` kept): given a tolerance
    wide enough for its lower face it stands on that face within ``tol``; settled, it
    stands on it exactly: 4 corners, up along the face's normal, ``tol`` at rounding.

    >>> import math
    >>> import numpy as np
    >>> from rocking.shapes import Shape
    >>> from rocking.shapes.rest import rest_pose
    >>> box = Shape.box(0.4, 0.6, 2.0, density=2000.0)
    >>> t = math.radians(10.0)
    >>> turn = np.array([[math.cos(t), 0, math.sin(t)], [0, 1, 0],
    ...                  [-math.sin(t), 0, math.cos(t)]])
    >>> tilted = Shape.from_arrays(box.vertices @ turn.T, box.faces, density=2000.0,
    ...                            tol=0.1)
    >>> rested = rest_pose(tilted)
    >>> rested.contact_points, round(rested.h, 9), bool(rested.tol < 1e-8)
    (4, 1.0, True)
    >>> np.round(rested.frame[2], 12).tolist()  # the face's normal, in the mesh's axes
    [0.173648177667, 0.0, 0.984807753012]
    """
    if is_resting(shape):
        return shape
    return type(shape).from_arrays(shape.vertices, shape.faces, mass=shape.mass,
                                   up=shape.frame[2], settle=True, name=shape.name,
                                   source=shape.source)


def resting_up(vertices, com, up="z") -> np.ndarray:
    """The up vector (3,, the mesh's coordinates) of the resting pose of the body of
    ``vertices`` (n, 3) with its centre of mass at ``com``, set down along ``up`` ("z",
    "-y", ... or a 3-vector; :func:`rocking.shapes.support.up_vector`): :func:`settle`'s."""
    from .support import up_vector

    return settle(vertices, com, up_vector(up)).up


def rest_tolerance(vertices) -> float:
    """The contact tolerance (m) of a settled shape: :data:`REST_EPS` of its size."""
    return REST_EPS * float(np.max(np.ptp(np.asarray(vertices), axis=0)))


__all__ = ["REST_EPS", "Rest", "is_resting", "rest_pose", "rest_tolerance", "resting_up",
           "settle"]
