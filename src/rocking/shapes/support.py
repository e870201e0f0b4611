"""The vertical frame of a mesh and its support (the contact patch and its convex hull).

**Frame.** ``up`` is "x", "y", "z", "-x", "-y", "-z" or a 3-vector (the mesh's upward
direction, normalised). The horizontal axes are ``e1``, the mesh's x axis projected on the
horizontal plane (its y axis if x is vertical), and ``e2 = up x e1``: (e1, e2, up) is a
right-handed orthonormal frame, and a direction ``phi`` of the horizontal plane is
``cos(phi) e1 + sin(phi) e2``, counter-clockwise from e1 looking down the ``up`` axis.
With ``up="z"`` the frame is the mesh's own (e1 = x, e2 = y).

**Support.** The body stands on its lowest plane (normal to ``up``). The contact patch is
the set of vertices within ``tol`` of that plane (default 1e-3 of the body's height: a
scanned base is never exactly flat; the patch of a slightly tilted or rough base then
still spans it), and the support is the patch's convex hull in the horizontal plane (qhull,
:class:`scipy.spatial.ConvexHull`). A patch with fewer than three non-collinear points (a
body on a point or an edge) is refused; so is a centre of mass whose vertical does not
fall strictly inside the support (the body cannot stand). Both refusals name the way to
analyse such a body: ``settle=True`` (:mod:`rocking.shapes.rest`: the resting pose, its
face exact) and ``model="rigid3d"``.
"""

from __future__ import annotations

import numpy as np

from .._validate import positive
from ..errors import ParameterError
from ..units import parse_quantity

AXES = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}

DEFAULT_TOL = 1e-3
"""Default contact tolerance, as a fraction of the body's height."""


def up_vector(up) -> np.ndarray:
    """``up`` ("x", "-z", ... or a 3-vector) as a unit vector."""
    if isinstance(up, str):
        word = up.strip().lower()
        sign = -1.0 if word.startswith("-") else 1.0
        word = word.lstrip("+-")
        if word not in AXES:
            raise ParameterError(f"up must be x, y, z, -x, -y, -z or a 3-vector, got {up!r}")
        return sign * np.array(AXES[word])
    try:
        u = np.array(up, dtype=np.float64).reshape(3)
    except (TypeError, ValueError):
        raise ParameterError(f"up must be x, y, z, -x, -y, -z or a 3-vector, got {up!r}"
                             ) from None
    n = float(np.linalg.norm(u))
    if not (np.all(np.isfinite(u)) and n > 0.0):
        raise ParameterError(f"up must be a finite non-zero 3-vector, got {up!r}")
    return u / n


def frame(up) -> np.ndarray:
    """Rows e1, e2, up of the right-handed frame of ``up`` (module docstring)."""
    z = up_vector(up)
    for axis in (np.array(AXES["x"]), np.array(AXES["y"])):
        e1 = axis - np.dot(axis, z) * z
        n = float(np.linalg.norm(e1))
        if n > 1e-6:
            break
    e1 /= n
    e2 = np.cross(z, e1)
    return np.vstack([e1, e2, z])


def contact_tolerance(tol, height: float) -> float:
    """``tol`` in m (a number in m, a string with a length unit such as "2mm", or None for
    :data:`DEFAULT_TOL` of ``height``)."""
    if tol is None:
        return DEFAULT_TOL * height
    if isinstance(tol, str):
        tol = parse_quantity(tol, "length", name="tol", default_unit="m")
    return positive("tol", tol, "m")


def support_hull(local_vertices, tol: float) -> tuple[np.ndarray, np.ndarray]:
    """The contact patch's indices into ``local_vertices`` (frame coordinates, z up) and
    its convex hull's vertices (k, 2), counter-clockwise, in the horizontal plane."""
    from scipy.spatial import ConvexHull, QhullError

    z = local_vertices[:, 2]
    patch = np.flatnonzero(z <= z.min() + tol)
    pts = local_vertices[patch, :2]
    size = float(np.max(np.ptp(local_vertices, axis=0)))
    what = ("a point" if len(pts) == 0 or float(np.max(np.ptp(pts, axis=0))) <= 1e-9 * size
            else "a line")
    if len(pts) >= 3:
        try:
            hull = ConvexHull(pts)
        except (QhullError, ValueError):
            hull = None
        if hull is not None and hull.volume > 1e-9 * size * size:
            return patch, pts[hull.vertices]  # 2-D hulls are counter-clockwise
    raise ParameterError(
        f"no flat base: the body stands on {what} (the contact patch within tol = "
        f"{tol:.3g} m of the lowest plane has no area); check `up`, or raise tol, or "
        f"analyse it with model=\"rigid3d\", which settles it into its resting pose with "
        f"no tol (load it with settle=True)")


def inside_margin(hull_xy, point) -> float:
    """The distance from ``point`` to the nearest edge line of the convex polygon
    ``hull_xy`` (counter-clockwise), positive inside."""
    a = np.asarray(hull_xy)
    b = np.roll(a, -1, axis=0)
    edge = b - a
    length = np.hypot(edge[:, 0], edge[:, 1])
    rel = np.asarray(point)[None, :] - a
    return float(np.min((edge[:, 0] * rel[:, 1] - edge[:, 1] * rel[:, 0]) / length))


__all__ = ["DEFAULT_TOL", "contact_tolerance", "frame", "inside_margin", "support_hull",
           "up_vector"]


def polygon_centroid(xy) -> tuple[float, float]:
    """The area centroid of a counter-clockwise polygon (k, 2) (its vertex if k < 3).

    Examples
    --------
    >>> from rocking.shapes.support import polygon_centroid
    >>> polygon_centroid([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]])
    (1.0, 0.5)
    """
    xy = np.asarray(xy, dtype=np.float64)
    if len(xy) < 3:
        c = xy.mean(axis=0)
        return float(c[0]), float(c[1])
    x, y = xy[:, 0], xy[:, 1]
    x1, y1 = np.roll(x, -1), np.roll(y, -1)
    cr = x * y1 - x1 * y
    a = 0.5 * cr.sum()
    return float(((x + x1) * cr).sum() / (6 * a)), float(((y + y1) * cr).sum() / (6 * a))
