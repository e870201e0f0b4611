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

Asymmetric blocks (issue 20; Contento and Di Egidio 2009) rock about two pivots with
different parameters: side "+" is the pivot of ``theta > 0`` (a positive ground
acceleration drives ``theta`` positive, Eq 1), side "-" the other.
:meth:`Block.from_geometry` builds one from the centre of mass's height ``h``, its
horizontal distances ``b_plus``, ``b_minus`` to the two pivots and the centroidal radius
of gyration ``r_g``: per side ``s``

.. math:: \\alpha_s = \\arctan(b_s/h),\\quad R_s = \\sqrt{b_s^2 + h^2},\\quad
          p_s^2 = \\frac{g R_s}{r_g^2 + R_s^2},\\quad
          \\mu_s = \\frac{r_g^2 + h^2 - b_s b_{\\bar s}}{r_g^2 + R_{\\bar s}^2},

``mu_s`` being the restitution of the impact that ends rocking on side ``s`` (the body
lands on the other pivot ``s̄``; angular momentum about the new pivot is conserved: before
the impact the centre of mass moves with ``omega x (c - O_s)``, so ``H_{O_s̄} = m omega
(r_g^2 + h^2 - b_s b_s̄)``, after it ``m (r_g^2 + R_s̄^2) omega'``). For a rectangle
(``b_s = b``, ``r_g^2 = R^2/3``) these are Eqs 2-4. The per-side values are the
attributes ``alpha_plus``/``alpha_minus``, ``p_*``, ``R_*``, ``mu_*`` (equal to ``alpha``,
``p``, ``R``, ``mu`` for a symmetric block); the one-number summaries ``alpha``, ``p``,
``R``, ``mu`` (and ``uplift_acceleration``) of an asymmetric block are those of its
*weaker side*, the one with the smaller ``alpha`` ("+" on a tie): the side it uplifts and
overturns towards first. ``mu`` is then the restitution of the impact that ends rocking on
that side. The classical, CCRR, anchored and isolated models use both sides; the DEM
rocks the body's outline (geometry ``"body"``) and refuses an asymmetric block otherwise.

All quantities are SI: m, kg, kg m^2, rad, 1/s.
"""

from __future__ import annotations

import dataclasses
import math
import sys
from dataclasses import dataclass, field

from .._validate import (
    PLAUSIBLE_LIMITS,
    as_float,
    check_plausible,
    in_range,
    non_negative,
    positive,
    warn_implausible,
)
from ..errors import ParameterError, UnitSlipWarning
from ..units import G

PLAUSIBLE_SIZE = PLAUSIBLE_LIMITS["size"][1]
"""A block width or height (m) above this gets a :class:`~rocking.errors.UnitSlipWarning`
(likely mm given as m; the command line refuses it unless ``--force``): the limit of
:data:`rocking.PLAUSIBLE_LIMITS`."""

GRANITE_DENSITY = 2650.0
"""Density (kg/m^3) used when a polygon is given neither a mass nor a density."""


def polygon_properties(vertices) -> dict:
    """Area (m^2), centroid (m) and polar second moment about the centroid per unit area
    (m^2, ``J_c / A``) of a simple polygon given counter-clockwise (Green's theorem).

    Examples
    --------
    A 2 m x 1 m rectangle: ``J_c / A = (w^2 + h^2) / 12``.

    >>> from rocking.blocks import polygon_properties
    >>> props = polygon_properties([(0, 0), (2, 0), (2, 1), (0, 1)])
    >>> props["area"], props["centroid"]
    (2.0, (1.0, 0.5))
    >>> round(props["j_c"], 4), round((2**2 + 1**2) / 12, 4)
    (0.4167, 0.4167)
    """
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


_SIDE_KEYS = {f"{k}_{s}": (i, j) for i, s in enumerate(("plus", "minus"))
              for j, k in enumerate(("alpha", "p", "mu", "R"))}


def _check_sides(sides) -> tuple:
    """``((alpha, p, mu, R), (alpha, p, mu, R))`` of sides + and -, validated (R may be
    None on both sides)."""
    try:
        pair = tuple(tuple(s) for s in sides)
    except TypeError:
        pair = ()
    if len(pair) != 2 or any(len(s) != 4 for s in pair):
        raise ParameterError("sides must be ((alpha, p, mu, R) of side +, the same of side -)")
    out = []
    for s, (alpha, p, mu, R) in zip(("plus", "minus"), pair, strict=True):
        out.append((in_range(f"alpha_{s}", alpha, 0.0, math.pi / 2, shown="(0, pi/2) rad"),
                    positive(f"p_{s}", p, "1/s"),
                    in_range(f"mu_{s}", mu, 0.0, 1.0, hi_open=False),
                    None if R is None else positive(f"R_{s}", R, "m")))
    if (out[0][3] is None) != (out[1][3] is None):
        raise ParameterError("R_plus and R_minus must be both given or both None")
    return (out[0], out[1])


def _weaker(sides) -> int:
    """Index of the weaker side (the smaller alpha; "+" on a tie)."""
    return 1 if sides[1][0] < sides[0][0] else 0


def _warn_energy_gain(block, where: str) -> None:
    """A :class:`PlausibilityWarning` when an impact of ``block`` creates kinetic energy
    (:meth:`Block.impact_energy_ratios` above 1): given restitutions that ignore the
    inertias of the two pivots (one ``mu`` for both sides of an asymmetric body)."""
    ratios = block.impact_energy_ratios()
    if ratios is None or block.sides is None or max(ratios) <= 1.0 + 1e-12:
        return
    s = "+" if ratios[0] >= ratios[1] else "-"
    o = "-" if s == "+" else "+"
    warn_implausible(
        f"{where}: an impact that ends rocking on side {s} would create energy (kinetic "
        f"energy ratio mu_{'plus' if s == '+' else 'minus'}^2 I_O{o} / I_O{s} = "
        f"{max(ratios):.4f} > 1: side {o}'s inertia is the larger); the restitutions of "
        "an asymmetric body follow from angular momentum about the new pivot: leave mu "
        "out (Block.from_geometry, Block.from_mesh) or give each side's")


def housner_mu(alpha: float) -> float:
    """Housner's coefficient of restitution of a rectangular block, Eq 4.

    Examples
    --------
    ``mu = 1 - (3/2) sin^2(alpha)``; a slender block (``b/h = 1/4``) loses little energy
    per impact:

    >>> import math
    >>> import rocking
    >>> round(rocking.housner_mu(math.atan(0.25)), 4)
    0.9118
    """
    return 1.0 - 1.5 * math.sin(alpha) ** 2


@dataclass(frozen=True)
class Block:
    """A rigid block for planar rocking.

    Build one with :meth:`rectangular` (from its geometry) or :meth:`from_params` (from
    the classical parameters directly). ``alpha``, ``p`` and ``mu`` are all that the
    classical and CCRR models need; the geometric fields are optional and are ``None``
    when unknown. :meth:`from_geometry` and :meth:`from_mesh` build asymmetric blocks
    (``alpha_plus``, ``alpha_minus``, ...; module docstring): ``sides`` holds their two
    sides, None for a symmetric block. :meth:`polygon` keeps one set of parameters (the
    smaller corner angle; both are in :attr:`alphas`).

    Examples
    --------
    A block 0.2 m wide and 1 m tall: ``alpha = atan(b/h)`` (Eq 2), ``p^2 = 3 g / (4 R)``
    (Eq 3) and Housner's ``mu`` (Eq 4).

    >>> import math
    >>> import rocking
    >>> block = rocking.Block.rectangular(0.2, 1.0)
    >>> round(block.alpha, 4), round(math.atan(0.1 / 0.5), 4)
    (0.1974, 0.1974)
    >>> round(block.p, 3), round(math.sqrt(3 * rocking.G / (4 * block.R)), 3)
    (3.798, 3.798)
    >>> block.mu == rocking.housner_mu(block.alpha)
    True
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
    # asymmetric blocks only: ((alpha, p, mu, R) of side "+", the same of side "-");
    # None for a symmetric block (so a symmetric block's fields, equality and hash are
    # those it had before asymmetric blocks existed)
    sides: tuple | None = field(default=None, hash=False, repr=False)

    def __post_init__(self):
        object.__setattr__(self, "alpha", in_range("alpha", self.alpha, 0.0, math.pi / 2,
                                                   shown="(0, pi/2) rad"))
        object.__setattr__(self, "p", positive("p", self.p, "1/s"))
        object.__setattr__(self, "mu", in_range("mu", self.mu, 0.0, 1.0, hi_open=False))
        if self.sides is not None:
            object.__setattr__(self, "sides", _check_sides(self.sides))
            if self.sides[0] == self.sides[1]:
                object.__setattr__(self, "sides", None)
            else:
                weak = self.sides[_weaker(self.sides)]
                if (self.alpha, self.p, self.mu) != weak[:3] or (
                        self.R is not None and self.R != weak[3]):
                    raise ParameterError(
                        "an asymmetric block's alpha, p, mu and R are those of its weaker "
                        "side; change a side with with_params(alpha_plus=..., mu_minus=...)")
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

        Examples
        --------
        A 0.4 m x 1.2 m block of 100 kg: ``alpha = atan(b/h)`` (Eq 2) and ``I_O = (4/3) M
        R^2``.

        >>> import math
        >>> from rocking import Block
        >>> block = Block.rectangular(0.4, 1.2, mass=100.0)
        >>> round(block.alpha, 4), round(math.atan(0.2 / 0.6), 4)
        (0.3218, 0.3218)
        >>> round(block.I_O, 4), round(4 / 3 * 100.0 * (0.2**2 + 0.6**2), 4)
        (53.3333, 53.3333)

        Cutting the corners by 40 mm moves the pivots 40 mm inwards: ``alpha`` is then
        ``atan(0.16 / y_c)`` with ``y_c`` the hexagon's centroid height.

        >>> cut = Block.rectangular(0.4, 1.2, corner_cut=0.04)
        >>> round(cut.alpha, 4), round(math.atan(0.16 / cut.centroid[1]), 4)
        (0.2598, 0.2598)
        """
        width = positive("width", width, "m")
        height = positive("height", height, "m")
        for what, x in (("width", width), ("height", height)):
            if x > PLAUSIBLE_SIZE:
                warn_implausible(f"Block.rectangular: {what} {x:g} m is above 50 m; check "
                                 "the units (width and height are in m: 170 mm is 0.17)",
                                 UnitSlipWarning)
        if mass is not None:
            mass = positive("mass", mass, "kg")
        if thickness is not None:
            thickness = positive("thickness", thickness, "m")
        b, h = width / 2.0, height / 2.0
        tiny, huge = sys.float_info.min, sys.float_info.max
        if not all(tiny < v < huge for v in (width * height, b * b + h * h,
                                             3.0 * G / (4.0 * math.hypot(b, h)))):
            raise ParameterError(
                f"width and height: a {width:g} m x {height:g} m block is too "
                f"{'large' if max(width, height) > 1.0 else 'small'} for floating point (its "
                "area, R^2 or p = sqrt(3 g / 4 R) leave the range of a float): give the sizes "
                "in m, e.g. width=0.17, height=1.0")
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

        Examples
        --------
        A rectangle given as a polygon is :meth:`rectangular`'s block:

        >>> import math
        >>> from rocking import Block
        >>> poly = Block.polygon([(0, 0), (0.4, 0), (0.4, 1.2), (0, 1.2)])
        >>> rect = Block.rectangular(0.4, 1.2)
        >>> round(poly.alpha, 4), round(rect.alpha, 4), round(poly.mu, 4), round(rect.mu, 4)
        (0.3218, 0.3218, 0.85, 0.85)

        A trapezoid 0.6 m wide at its base, 0.2 m at its top and 1 m tall has its centroid
        at ``y_c = (h/3) (B + 2T) / (B + T) = 5/12`` m, so ``alpha = atan(0.3 / y_c)``:

        >>> trap = Block.polygon([(-0.3, 0), (0.3, 0), (0.1, 1.0), (-0.1, 1.0)])
        >>> round(trap.centroid[1], 4), round(trap.alpha, 4), round(math.atan(0.3 * 12 / 5), 4)
        (0.4167, 0.624, 0.624)
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
            rho = positive("density", density, "kg/m^3")
            check_plausible("density", rho, "density")
            mass = rho * props["area"] * (1.0 if thickness is None else thickness)
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
    def from_geometry(cls, h: float, b_plus: float, b_minus: float,
                      radius_of_gyration: float, *, mass: float | None = None,
                      name: str | None = None, mu: float | None = None) -> Block:
        """A planar block from its geometry (m): the centre of mass at height ``h`` above
        the base, at horizontal distances ``b_plus``/``b_minus`` from the pivots of
        ``theta > 0``/``theta < 0``, centroidal radius of gyration ``radius_of_gyration``
        (``I_G = m r_g^2``). Per side: ``alpha_s = atan(b_s/h)``, ``R_s``, ``p_s^2 = g R_s /
        (r_g^2 + R_s^2)`` and the restitution ``mu_s`` of the module docstring (angular
        momentum about the new pivot), unless ``mu`` (both sides) is given. Equal sides
        give a symmetric block. ``mass`` (kg) sets ``I_O`` of the weaker side.

        Examples
        --------
        A rectangle (``r_g^2 = (b^2 + h^2) / 3``) gives Eqs 2-4, the block of
        :meth:`rectangular`:

        >>> import math
        >>> from rocking import Block
        >>> rect = Block.from_geometry(0.6, 0.2, 0.2, math.sqrt((0.2**2 + 0.6**2) / 3))
        >>> rect.symmetric, round(rect.p, 4), round(Block.rectangular(0.4, 1.2).p, 4)
        (True, 3.4102, 3.4102)

        The centre of mass 0.1 m from the + pivot and 0.2 m from the - pivot: the +
        side, ``alpha_plus = atan(0.1 / 0.5)``, is the weaker one.

        >>> body = Block.from_geometry(0.5, 0.1, 0.2, 0.3)
        >>> body.symmetric, round(body.alpha, 4), round(math.atan(0.2), 4)
        (False, 0.1974, 0.1974)
        >>> round(body.alpha_minus, 4), round(math.atan(0.4), 4)
        (0.3805, 0.3805)
        """
        h = positive("h", h, "m")
        bp = positive("b_plus", b_plus, "m")
        bm = positive("b_minus", b_minus, "m")
        rg = positive("radius_of_gyration", radius_of_gyration, "m")
        for what, x in (("h", h), ("b_plus", bp), ("b_minus", bm)):
            if x > PLAUSIBLE_SIZE:
                warn_implausible(f"Block.from_geometry: {what} {x:g} m is above 50 m; check "
                                 "the units (lengths are in m: 170 mm is 0.17)",
                                 UnitSlipWarning)
        if mass is not None:
            mass = positive("mass", mass, "kg")
        if mu is not None:
            mu = in_range("mu", mu, 0.0, 1.0, hi_open=False)
        rg2 = rg * rg
        side = []
        for b, other in ((bp, bm), (bm, bp)):
            R, R_o = math.hypot(b, h), math.hypot(other, h)
            m_s = (rg2 + h * h - b * other) / (rg2 + R_o * R_o)
            if mu is None and m_s <= 0.0:
                raise ParameterError(
                    f"the restitution from angular momentum is {m_s:.3f} <= 0 for this squat "
                    "body (b_plus, b_minus, h, radius_of_gyration); pass mu explicitly, in "
                    "(0, 1]")
            side.append((math.atan(b / h), math.sqrt(G * R / (rg2 + R * R)),
                         m_s if mu is None else mu, R))
        sides = (side[0], side[1])
        alpha, p, mu_w, R = sides[_weaker(sides)]
        block = cls(alpha=alpha, p=p, mu=mu_w, R=R, mass=mass,
                    I_O=None if mass is None else mass * (rg2 + R * R),
                    name="" if name is None else str(name),
                    sides=None if sides[0] == sides[1] else sides)
        if mu is not None:
            _warn_energy_gain(block, "Block.from_geometry")
        return block

    @classmethod
    def from_shape(cls, shape, phi: float = 0.0, *, name: str | None = None, mu=None,
                   outline: bool = True) -> Block:
        """The planar block of a 3-D body (:class:`rocking.shapes.Shape`) for shaking along
        ``phi`` (rad, counter-clockwise from the body's x axis seen from above): its two
        sides (:meth:`rocking.shapes.Shape.parameters`) through :meth:`from_geometry`, with
        the body's mass; ``mu``: None for the derived restitutions, a number for both
        sides. With ``outline`` the block also carries the body's outline in the plane of
        shaking (:meth:`rocking.shapes.Shape.polygon`) as its :attr:`vertices`, so that the
        DEM rocks that outline with the body's true mass and inertia (geometry
        ``"body"``). A body that touches the ground beyond a pivot before its overturning
        angle (an overhang) is warned about: the planar block ignores that contact.

        Examples
        --------
        A 0.4 m x 0.6 m x 2 m box shaken along x is the 0.4 m x 2 m rectangle (Eqs 2-4),
        with the box's mass; along y (``phi = pi/2``) it is 0.6 m wide:

        >>> import math, trimesh
        >>> from rocking import Block
        >>> from rocking.shapes import Shape
        >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)),
        ...                          density=2000.0)
        >>> block = Block.from_shape(box)
        >>> round(block.p, 4), round(Block.rectangular(0.4, 2.0).p, 4), round(block.mass, 6)
        (2.6855, 2.6855, 960.0)
        >>> round(Block.from_shape(box, math.pi / 2).alpha, 4), round(math.atan(0.3), 4)
        (0.2915, 0.2915)
        """
        q = shape.parameters(phi)
        if q["overhang"]:
            tilt = math.degrees(min(q["contact_plus"], q["contact_minus"]))
            warn_implausible(
                f"direction {math.degrees(q['phi']):g} deg: the body touches the ground "
                f"beyond its pivot at a tilt of {tilt:.3g} deg, before its overturning "
                "angle; the planar block ignores that contact")
        label = name if name is not None else (
            f"{shape.name or 'mesh'} @ {math.degrees(q['phi']):.1f} deg")
        block = cls.from_geometry(q["h"], q["b_plus"], q["b_minus"], q["radius_of_gyration"],
                                  mass=shape.mass, name=label, mu=mu)
        if not outline:
            return block
        poly = shape.polygon(phi)
        xs, zs = poly[:, 0], poly[:, 1]
        return dataclasses.replace(block, vertices=tuple(map(tuple, poly.tolist())),
                                   width=float(xs.max() - xs.min()),
                                   height=float(zs.max() - zs.min()))

    @classmethod
    def from_mesh(cls, path, *, density: float | None = None, mass: float | None = None,
                  direction=0.0, up="z", repair=None, units: str = "m",
                  name: str | None = None, mu=None) -> Block:
        """The planar block of a 3-D mesh file (STL, OBJ, PLY) for shaking along
        ``direction``: :func:`rocking.shapes.load_shape` then :meth:`from_shape`.

        ``direction`` is in degrees, as everywhere a user gives it (the spec's ``mesh``
        blocks, ``--direction``): a number (deg), a string with its unit (``"30deg"``,
        ``"0.5rad"``), ``"weakest"`` or ``"strongest"``
        (:func:`rocking.shapes.parse_direction`); ``phi`` is the same angle in rad in
        :meth:`from_shape` and :func:`rocking.shapes.directional_parameters`.

        Examples
        --------
        The example statue, shaken along its weakest direction: the block's ``alpha`` is
        the critical angle of :meth:`rocking.shapes.Shape.weakest`.

        >>> import math
        >>> from rocking import Block
        >>> from rocking.shapes import example_mesh_path, load_shape
        >>> b = Block.from_mesh(example_mesh_path(), density=2600, direction="weakest")
        >>> round(math.degrees(b.alpha), 2)
        13.91
        >>> weak = load_shape(example_mesh_path(), density=2600).weakest()
        >>> round(weak.alpha, 6) == round(b.alpha, 6), b.name
        (True, 'statue @ 254.4 deg')
        """
        from ..shapes import load_shape, parse_direction, resolve_direction  # trimesh: lazy

        shape = load_shape(path, density=density, mass=mass, up=up, repair=repair,
                           units=units)
        return cls.from_shape(shape, resolve_direction(shape, parse_direction(direction)),
                              name=name, mu=mu)

    @classmethod
    def from_params(cls, alpha: float, p: float, mu: float, *, name: str = "", **geometry) -> Block:
        """A block given by its classical parameters ``alpha`` (rad), ``p`` (1/s), ``mu``.

        Examples
        --------
        Only the three parameters are known (``R`` is None); the block uplifts from rest
        at ``g tan(alpha)``:

        >>> import math
        >>> import rocking
        >>> block = rocking.Block.from_params(0.25, 2.0, 0.9)
        >>> block
        Block(alpha=0.2500 rad, p=2.0000 1/s, mu=0.9000)
        >>> round(block.uplift_acceleration, 4), round(rocking.G * math.tan(0.25), 4)
        (2.504, 2.504)
        """
        return cls(alpha=alpha, p=p, mu=mu, name=name, **geometry)

    def with_params(self, **changes) -> Block:
        """A copy with fields replaced (validated again), e.g. ``block.with_params(mu=0.9)``.

        An asymmetric block's sides change with ``alpha_plus``, ``p_minus``, ``mu_plus``,
        ... (``mu`` sets both sides' restitution); its ``alpha``, ``p`` and ``R`` follow
        from the sides.

        Examples
        --------
        >>> from rocking import Block
        >>> block = Block.rectangular(0.4, 1.2)
        >>> lossy = block.with_params(mu=0.7)
        >>> lossy.mu, lossy.alpha == block.alpha, round(block.mu, 4)  # the original is kept
        (0.7, True, 0.85)

        Changing one side's angle makes the block asymmetric; ``alpha`` is the weaker
        side's:

        >>> tilted = block.with_params(alpha_minus=0.2)
        >>> tilted.symmetric, tilted.alpha, round(tilted.alpha_plus, 4)
        (False, 0.2, 0.3218)
        """
        side_keys = {k for k in changes if k in _SIDE_KEYS}
        if self.sides is None and not side_keys:
            return dataclasses.replace(self, **changes)
        for k in ("alpha", "p", "R"):
            if k in changes and self.sides is not None:
                raise ParameterError(f"{k} of an asymmetric block is that of its weaker "
                                     f"side; set {k}_plus or {k}_minus instead")
        if "mu" in changes:
            changes.setdefault("mu_plus", changes["mu"])
            changes.setdefault("mu_minus", changes.pop("mu"))
        sides = [list(self.sides[0]), list(self.sides[1])] if self.sides is not None else [
            [self.alpha, self.p, self.mu, self.R], [self.alpha, self.p, self.mu, self.R]]
        for k in list(changes):
            if k in _SIDE_KEYS:
                i, j = _SIDE_KEYS[k]
                sides[i][j] = changes.pop(k)
        sides = _check_sides(sides)
        alpha, p, mu, R = sides[_weaker(sides)]
        if self.R is None and sides[0][3] is None:
            R = None
        block = dataclasses.replace(self, alpha=alpha, p=p, mu=mu, R=R,
                                    sides=None if sides[0] == sides[1] else sides, **changes)
        _warn_energy_gain(block, "Block.with_params")
        return block

    def mirrored(self) -> Block:
        """The block with its sides swapped (the same body seen from behind): under the
        ground acceleration ``-a`` it rocks as this block under ``a``, with ``theta``
        negated. The polygon, if any, is mirrored too.

        Examples
        --------
        >>> from rocking import Block
        >>> body = Block.from_geometry(0.5, 0.1, 0.2, 0.3)  # b_plus = 0.1, b_minus = 0.2 m
        >>> back = body.mirrored()
        >>> back.alpha_plus == body.alpha_minus, back.alpha_minus == body.alpha_plus
        (True, True)
        >>> back.mirrored() == body
        True
        """
        verts = None if self.vertices is None else tuple((-x, y) for x, y in self.vertices)
        sides = None if self.sides is None else (self.sides[1], self.sides[0])
        if sides is None:
            return dataclasses.replace(self, vertices=verts)
        alpha, p, mu, R = sides[_weaker(sides)]
        return dataclasses.replace(self, alpha=alpha, p=p, mu=mu, R=R, sides=sides,
                                   vertices=verts)

    # ------------------------------------------------------------------ the two sides
    @property
    def symmetric(self) -> bool:
        """True when both sides have the same ``alpha``, ``p``, ``mu`` and ``R`` (every
        block but those built asymmetric by :meth:`from_geometry` or ``with_params``)."""
        return self.sides is None

    def _side(self, i: int, j: int):
        if self.sides is None:
            return (self.alpha, self.p, self.mu, self.R)[j]
        return self.sides[i][j]

    alpha_plus = property(lambda self: self._side(0, 0),
                          doc="Critical angle (rad) of side + (the pivot of theta > 0).")
    alpha_minus = property(lambda self: self._side(1, 0),
                           doc="Critical angle (rad) of side - (the pivot of theta < 0).")
    p_plus = property(lambda self: self._side(0, 1), doc="Frequency parameter (1/s) of side +.")
    p_minus = property(lambda self: self._side(1, 1),
                       doc="Frequency parameter (1/s) of side -.")
    mu_plus = property(lambda self: self._side(0, 2),
                       doc="Restitution of an impact that ends rocking on side +.")
    mu_minus = property(lambda self: self._side(1, 2),
                        doc="Restitution of an impact that ends rocking on side -.")
    R_plus = property(lambda self: self._side(0, 3),
                      doc="Distance (m) from the + pivot to the centre of mass (or None).")
    R_minus = property(lambda self: self._side(1, 3),
                       doc="Distance (m) from the - pivot to the centre of mass (or None).")

    def impact_energy_ratios(self) -> tuple[float, float] | None:
        """``(r_+, r_-)``: the kinetic energy after over before an impact that ends rocking
        on side + (it lands on the - pivot) and on side -, ``r_s = mu_s^2 I_o / I_s`` (``o``
        the other side; ``I_s = m g R_s / p_s^2``, Eq 3); ``mu^2`` on both sides of a
        symmetric block; None when ``R`` is unknown. The angular-momentum restitutions
        (:meth:`from_geometry`) give ``r_+ = r_- = mu_+ mu_- < 1``; restitutions given
        otherwise may give ``r_s > 1``: an impact that creates energy.

        Examples
        --------
        >>> from rocking import Block
        >>> body = Block.from_geometry(0.5, 0.1, 0.3, 0.25)  # derived restitutions
        >>> r = body.impact_energy_ratios()
        >>> round(r[0], 12) == round(r[1], 12) == round(body.mu_plus * body.mu_minus, 12)
        True
        """
        if self.R_plus is None:
            return None
        i_p = self.R_plus / self.p_plus ** 2  # I_O / (m g)
        i_m = self.R_minus / self.p_minus ** 2
        return (self.mu_plus ** 2 * i_m / i_p, self.mu_minus ** 2 * i_p / i_m)

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
        if self.sides is not None:
            return (self.alpha_plus, self.alpha_minus)
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
        """The classical parameters as a plain dict (``alpha``, ``p``, ``mu``, ``R``; an
        asymmetric block adds ``alpha_plus``, ..., ``R_minus``).

        Examples
        --------
        >>> from rocking import Block
        >>> params = Block.rectangular(0.4, 1.2).params()
        >>> {k: round(v, 4) for k, v in params.items()}  # R = sqrt(0.2^2 + 0.6^2)
        {'alpha': 0.3218, 'p': 3.4102, 'mu': 0.85, 'R': 0.6325}
        >>> list(Block.from_geometry(0.5, 0.1, 0.2, 0.3).params())  # asymmetric
        ['alpha', 'p', 'mu', 'R', 'alpha_plus', 'p_plus', 'mu_plus', 'R_plus',
         'alpha_minus', 'p_minus', 'mu_minus', 'R_minus']
        """
        d = {"alpha": self.alpha, "p": self.p, "mu": self.mu, "R": self.R}
        if self.sides is not None:
            d.update({k: getattr(self, k) for k in _SIDE_KEYS})
        return d

    def __repr__(self) -> str:  # short and readable in notebooks
        name = f"{self.name!r}, " if self.name else ""
        if self.sides is not None:
            return (f"Block({name}asymmetric: alpha={self.alpha_plus:.4f}/"
                    f"{self.alpha_minus:.4f} rad, p={self.p_plus:.4f}/{self.p_minus:.4f} 1/s, "
                    f"mu={self.mu_plus:.4f}/{self.mu_minus:.4f} (+/-))")
        return (f"Block({name}alpha={self.alpha:.4f} rad, p={self.p:.4f} 1/s, mu={self.mu:.4f}"
                + (f", R={self.R:.4f} m" if self.R else "") + ")")
