"""Rigid blocks and their classical rocking parameters (Peña et al. 2007, Eqs 2-4).

A block rocking on a rigid base is described, in the classical (Housner) theory, by three
parameters:

* ``alpha`` (rad): the critical (slenderness) angle, ``alpha = atan(b/h)`` (Eq 2), where
  2b is the full width and 2h the full height of a rectangular block;
* ``p`` (1/s): the frequency parameter, ``p^2 = M g R / I_O`` (Eq 3), which reduces to
  ``3 g / (4 R)`` for a rectangle, with ``R = sqrt(b^2 + h^2)`` the distance from a base
  corner to the centroid and ``I_O = (4/3) M R^2`` the moment of inertia about that corner;
* ``mu``: the coefficient of restitution, the ratio of angular velocities after and before
  an impact. Conservation of angular momentum about the new pivot gives Housner's value
  ``mu = 1 - (3/2) sin^2(alpha)`` (Eq 4).

Blocks of any convex polygonal shape (the cut corners of the specimens, trapezoids) are
built with :meth:`Block.polygon`: the centroid and the moment of inertia follow from the
polygon formulas, the rocking corners are the two ends of the (horizontal) base face, and
``alpha``, ``R``, ``p`` and ``mu`` are those of the rocking about these corners, with the
generalised Housner restitution (angular momentum about the new corner)

.. math:: \\mu = \\frac{I_c + M\\,(c - O)\\cdot(c - O')}{I_O} ,

which is ``1 - (2 M R^2 / I_O) sin^2(alpha)`` for a symmetric block and Eq 4 for a
rectangle. The discrete element model (``model="dem"``) uses the polygon as the contact
geometry.

All quantities are SI: m, kg, kg m^2, rad, 1/s.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from .._validate import as_float, in_range, non_negative, positive, warn_implausible
from ..errors import ParameterError
from ..units import G

PLAUSIBLE_SIZE = 50.0
"""A block width or height (m) above this gets a warning (likely mm given as m)."""

GRANITE_DENSITY = 2650.0
"""Density (kg/m^3) used when a polygon is given neither a mass nor a density."""


def polygon_properties(vertices) -> dict:
    """Area (m^2), centroid (m) and polar second moment about the centroid per unit area
    (m^2, ``J_c / A``) of a simple polygon given counter-clockwise (Green's theorem)."""
    v = [(float(x), float(y)) for x, y in vertices]
    n = len(v)
    a2 = cx = cy = jo = 0.0
    for i in range(n):
        x0, y0 = v[i]
        x1, y1 = v[(i + 1) % n]
        cr = x0 * y1 - x1 * y0
        a2 += cr
        cx += (x0 + x1) * cr
        cy += (y0 + y1) * cr
        jo += cr * (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1)
    area = 0.5 * a2
    cx /= 3.0 * a2
    cy /= 3.0 * a2
    jo /= 12.0  # polar second moment about the origin
    return {"area": area, "centroid": (cx, cy), "j_c": jo / area - (cx * cx + cy * cy)}


def _check_polygon(vertices) -> tuple:
    """Vertices as a counter-clockwise tuple of (x, y) floats, translated so that the base
    face (the lowest edge, which must be horizontal) runs from (-b0, 0) to (b0, 0)."""
    try:
        pts = [(as_float("vertices", x), as_float("vertices", y)) for x, y in vertices]
    except (TypeError, ValueError) as exc:
        if isinstance(exc, ParameterError):
            raise
        raise ParameterError("vertices must be a sequence of (x, y) pairs in m") from None
    n = len(pts)
    if n < 3:
        raise ParameterError(f"vertices must hold at least 3 points, got {n}")
    area2 = sum(pts[i][0] * pts[(i + 1) % n][1] - pts[(i + 1) % n][0] * pts[i][1]
                for i in range(n))
    if area2 < 0.0:
        pts = pts[::-1]
    size = max(max(x for x, _ in pts) - min(x for x, _ in pts),
               max(y for _, y in pts) - min(y for _, y in pts))
    if not abs(area2) > 1e-12 * size * size:
        raise ParameterError("vertices enclose no area")
    for i in range(n):  # strictly convex, counter-clockwise
        (x0, y0), (x1, y1), (x2, y2) = pts[i - 1], pts[i], pts[(i + 1) % n]
        cr = (x1 - x0) * (y2 - y1) - (y1 - y0) * (x2 - x1)
        if cr <= 1e-12 * size * size:
            raise ParameterError(
                f"vertices must form a strictly convex polygon (vertex {i} at ({x1:g}, {y1:g}) "
                "is a reflex or collinear corner)")
    ymin = min(y for _, y in pts)
    low = [i for i, (_, y) in enumerate(pts) if y - ymin <= 1e-9 * size]
    if len(low) != 2:
        raise ParameterError("the polygon must stand on a horizontal base face: exactly two "
                             "vertices must share the lowest y")
    xm = 0.5 * (pts[low[0]][0] + pts[low[1]][0])
    # start the list at the left end of the base face
    i0 = min(low, key=lambda i: pts[i][0])
    pts = pts[i0:] + pts[:i0]
    return tuple((x - xm, 0.0 if y - ymin <= 1e-9 * size else y - ymin) for x, y in pts)


def housner_mu(alpha: float) -> float:
    """Housner's coefficient of restitution of a rectangular block, Eq 4."""
    return 1.0 - 1.5 * math.sin(alpha) ** 2


@dataclass(frozen=True)
class Block:
    """A rigid block for planar rocking.

    Build one with :meth:`rectangular` (from its geometry) or :meth:`from_params` (from
    the classical parameters directly). ``alpha``, ``p`` and ``mu`` are all that the
    classical and CCRR models need; the geometric fields are optional and are ``None``
    when unknown.
    """

    alpha: float
    p: float
    mu: float
    R: float | None = None
    mass: float | None = None
    I_O: float | None = None
    width: float | None = None
    height: float | None = None
    thickness: float | None = None
    name: str = ""
    vertices: tuple | None = None

    def __post_init__(self):
        object.__setattr__(self, "alpha", in_range("alpha", self.alpha, 0.0, math.pi / 2,
                                                   shown="(0, pi/2) rad"))
        object.__setattr__(self, "p", positive("p", self.p, "1/s"))
        object.__setattr__(self, "mu", in_range("mu", self.mu, 0.0, 1.0, hi_open=False))
        for f in ("R", "mass", "I_O", "width", "height", "thickness"):
            v = getattr(self, f)
            if v is not None:
                object.__setattr__(self, f, positive(f, v, "(SI units)"))
        if self.vertices is not None:
            object.__setattr__(self, "vertices", _check_polygon(self.vertices))

    # ------------------------------------------------------------------ constructors
    @classmethod
    def rectangular(
        cls,
        width: float,
        height: float,
        mass: float | None = None,
        thickness: float | None = None,
        *,
        mu: float | None = None,
        p: float | None = None,
        name: str = "",
        corner_cut: float = 0.0,
    ) -> Block:
        """A rectangular block of full width ``2b`` and full height ``2h`` (m), as in Table I.

        ``alpha`` follows Eq 2, ``p`` Eq 3 (``3g/4R``) and ``mu`` Eq 4 (Housner), unless
        ``mu`` or ``p`` is given. ``I_O = (4/3) M R^2`` is set when ``mass`` is known.

        ``corner_cut`` (m) cuts both base corners at 45 degrees with legs of that length (the
        specimens' 5 mm and 40 mm cuts): the block is then the hexagon of
        :meth:`polygon` (its rocking corners are the ends of the narrowed base face) with
        ``mass`` its actual mass; ``width``/``height`` keep the bounding box.
        """
        width = positive("width", width, "m")
        height = positive("height", height, "m")
        for what, x in (("width", width), ("height", height)):
            if x > PLAUSIBLE_SIZE:
                warn_implausible(f"Block.rectangular: {what} {x:g} m is above 50 m; check "
                                 "the units (width and height are in m: 170 mm is 0.17)")
        if mass is not None:
            mass = positive("mass", mass, "kg")
        if thickness is not None:
            thickness = positive("thickness", thickness, "m")
        b, h = width / 2.0, height / 2.0
        c = non_negative("corner_cut", corner_cut, "m")
        if c > 0.0:
            if not (c < b and c < height):
                raise ParameterError(f"corner_cut must be < width/2 = {b:g} m and < height, "
                                     f"got {corner_cut!r}")
            verts = ((-b + c, 0.0), (b - c, 0.0), (b, c), (b, height), (-b, height), (-b, c))
            blk = cls.polygon(verts, mass=mass, thickness=thickness, name=name, mu=mu)
            return dataclasses.replace(blk, width=width, height=height,
                                       p=blk.p if p is None else p)
        alpha = math.atan2(b, h)
        R = math.hypot(b, h)
        p_geo = math.sqrt(3.0 * G / (4.0 * R))
        if mu is None and housner_mu(alpha) <= 0.0:
            raise ParameterError(
                f"Eq 4 gives mu = {housner_mu(alpha):.3f} <= 0 for this squat block "
                f"(alpha = {math.degrees(alpha):.1f} deg; Housner's restitution needs alpha < "
                "54.7 deg, i.e. width/height < 1.41); pass mu explicitly, in (0, 1]")
        return cls(
            alpha=alpha,
            p=p_geo if p is None else p,
            mu=housner_mu(alpha) if mu is None else mu,
            R=R,
            mass=mass,
            I_O=None if mass is None else 4.0 / 3.0 * mass * R * R,
            width=width,
            height=height,
            thickness=thickness,
            name=name,
            vertices=((-b, 0.0), (b, 0.0), (b, height), (-b, height)),
        )

    @classmethod
    def polygon(
        cls,
        vertices,
        mass: float | None = None,
        density: float | None = None,
        thickness: float | None = None,
        name: str = "",
        *,
        mu: float | None = None,
    ) -> Block:
        """A rigid convex polygonal block (vertices in m, counter-clockwise or clockwise).

        The polygon must stand on a horizontal base face (its lowest edge); the ends of
        that face are the rocking corners O (left, pivot of ``theta > 0``) and O' (right).
        Centroid and inertia follow from the polygon formulas. ``mass`` (kg) wins over
        ``density`` (kg/m^3, times the area and ``thickness``, default 1 m); with neither,
        the mass is left unknown (``alpha``, ``p`` and ``mu`` do not depend on it).

        ``alpha`` is the smaller of the angles at the two corners between the vertical and
        the line to the centroid (both are in :attr:`alphas`); ``R`` is the distance from
        that corner to the centroid, ``I_O = I_c + M R^2``, ``p^2 = M g R / I_O``, and
        ``mu`` the generalised Housner restitution of the module docstring (geometric mean
        of the two directions if the block is asymmetric) unless ``mu`` is given.
        """
        verts = _check_polygon(vertices)
        props = polygon_properties(verts)
        cx, cy = props["centroid"]
        jc = props["j_c"]  # I_c / M
        if thickness is not None:
            thickness = positive("thickness", thickness, "m")
        if mass is not None:
            mass = positive("mass", mass, "kg")
        elif density is not None:
            mass = positive("density", density, "kg/m^3") * props["area"] * (
                1.0 if thickness is None else thickness)
        (xl, _), (xr, _) = verts[0], verts[1]
        al, ar = math.atan2(cx - xl, cy), math.atan2(xr - cx, cy)
        xo = xl if al <= ar else xr
        R = math.hypot(cx - xo, cy)
        io_m = jc + R * R  # I_O / M
        p = math.sqrt(G * R / io_m)
        il, ir = jc + (cx - xl) ** 2 + cy * cy, jc + (cx - xr) ** 2 + cy * cy
        mu_geo = (jc + (cx - xl) * (cx - xr) + cy * cy) / math.sqrt(il * ir)
        if mu is None and mu_geo <= 0.0:
            raise ParameterError(
                f"the generalised Housner restitution is {mu_geo:.3f} <= 0 for this squat "
                "polygon; pass mu explicitly, in (0, 1]")
        xs = [x for x, _ in verts]
        ys = [y for _, y in verts]
        return cls(alpha=min(al, ar), p=p, mu=mu_geo if mu is None else mu, R=R, mass=mass,
                   I_O=None if mass is None else mass * io_m, width=max(xs) - min(xs),
                   height=max(ys) - min(ys), thickness=thickness, name=name, vertices=verts)

    @classmethod
    def from_params(cls, alpha: float, p: float, mu: float, *, name: str = "", **geometry) -> Block:
        """A block given by its classical parameters ``alpha`` (rad), ``p`` (1/s), ``mu``."""
        return cls(alpha=alpha, p=p, mu=mu, name=name, **geometry)

    def with_params(self, **changes) -> Block:
        """A copy with fields replaced (validated again), e.g. ``block.with_params(mu=0.9)``."""
        return dataclasses.replace(self, **changes)

    # ------------------------------------------------------------------ derived values
    @property
    def b(self) -> float | None:
        """Half-width (m), if the geometry is known."""
        return None if self.width is None else self.width / 2.0

    @property
    def h(self) -> float | None:
        """Half-height (m), if the geometry is known."""
        return None if self.height is None else self.height / 2.0

    @property
    def alphas(self) -> tuple[float, float]:
        """``(alpha_O, alpha_O')``: the critical angles for ``theta > 0`` (pivot O, the left
        base corner) and ``theta < 0`` (pivot O'); equal for symmetric blocks and
        ``(alpha, alpha)`` when the block has no polygon."""
        if self.vertices is None:
            return (self.alpha, self.alpha)
        cx, cy = polygon_properties(self.vertices)["centroid"]
        (xl, _), (xr, _) = self.vertices[0], self.vertices[1]
        return (math.atan2(cx - xl, cy), math.atan2(xr - cx, cy))

    @property
    def centroid(self) -> tuple[float, float] | None:
        """Centroid of the polygon (m) in the frame of :attr:`vertices` (origin at the
        middle of the base face), or None without a polygon."""
        if self.vertices is None:
            return None
        return polygon_properties(self.vertices)["centroid"]

    @property
    def uplift_acceleration(self) -> float:
        """Ground acceleration (m/s^2) above which the block uplifts from rest: ``g tan(alpha)``."""
        return G * math.tan(self.alpha)

    def params(self) -> dict:
        """The classical parameters as a plain dict (``alpha``, ``p``, ``mu``, ``R``)."""
        return {"alpha": self.alpha, "p": self.p, "mu": self.mu, "R": self.R}

    def __repr__(self) -> str:  # short and readable in notebooks
        name = f"{self.name!r}, " if self.name else ""
        return (f"Block({name}alpha={self.alpha:.4f} rad, p={self.p:.4f} 1/s, mu={self.mu:.4f}"
                + (f", R={self.R:.4f} m" if self.R else "") + ")")
