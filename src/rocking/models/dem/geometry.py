"""DEM geometry: the body of each block (Eq 18 and the classical body) and the packed
assembly of blocks that the kernel integrates (see :mod:`rocking.models.dem`).

Besides the geometries of :mod:`rocking.models.dem`, ``"body"`` (issue 20) is a block's
polygon as the *outline* of a rigid body whose mass, centre of mass and moment of inertia
are the block's own (:func:`rigid_body`): the planar block of a 3-D mesh
(:func:`rocking.blocks.factory.mesh_block`: the mesh's hull projected on the plane of
shaking, with the mesh's mass and its inertia about the axis normal to that plane), not
the polygon's area and second moment. ``"auto"`` takes it for a block whose polygon is not
its own body but whose sides, mass and ``I_O`` describe one standing on that polygon's
base face."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...blocks import GRANITE_DENSITY, Block, Stack, polygon_properties
from ...errors import ParameterError
from ...units import G

DEFAULT_SETTLEMENT = 1e-7
"""Default static settlement of a block under its own weight, as a fraction of its height."""
ROUNDING = 1e-3
"""Rounding length of the corners (span tolerance), as a fraction of the smaller block size."""
GEOMETRIES = ("auto", "polygon", "body", "equivalent", "classical")
BODY_TOL = 1e-9
"""Relative tolerance of the checks that a block's sides, mass and ``I_O`` describe a rigid
body standing on its polygon's base face (:func:`rigid_body`)."""


@dataclass
class Body:
    """One block as the DEM sees it: polygon about its centroid, mass and inertia."""

    verts: np.ndarray  # (n, 2), counter-clockwise, relative to the centroid
    mass: float
    inertia: float  # about the centroid (kg m^2)
    mode: str  # "polygon" or "equivalent"
    alpha: float
    p: float

    @property
    def base_mid(self) -> tuple[float, float]:
        """Middle of the base face relative to the centroid (vertices 0 and 1)."""
        v = self.verts
        return 0.5 * (v[0, 0] + v[1, 0]), v[0, 1]

    @property
    def top_mid(self) -> tuple[float, float]:
        """Middle of the flat top face relative to the centroid."""
        v = self.verts
        ymax = v[:, 1].max()
        top = np.flatnonzero(v[:, 1] >= ymax - 1e-9 * (ymax - v[:, 1].min()))
        if top.size != 2:
            raise ParameterError("a block that carries another one must have a flat "
                                   "horizontal top face")
        return float(v[top, 0].mean()), float(ymax)

    @property
    def height(self) -> float:
        return float(self.verts[:, 1].max() - self.verts[:, 1].min())

    @property
    def width(self) -> float:
        return float(self.verts[:, 0].max() - self.verts[:, 0].min())


def _polygon_alpha_p(block: Block) -> tuple[float, float]:
    pr = polygon_properties(block.vertices)
    cx, cy = pr["centroid"]
    (xl, _), (xr, _) = block.vertices[0], block.vertices[1]
    al, ar = math.atan2(cx - xl, cy), math.atan2(xr - cx, cy)
    xo = xl if al <= ar else xr
    R = math.hypot(cx - xo, cy)
    return min(al, ar), math.sqrt(G * R / (pr["j_c"] + R * R))


def _default_mass(block: Block, area: float) -> float:
    if block.mass is not None:
        return float(block.mass)
    return GRANITE_DENSITY * area * (block.thickness or 1.0)


def rigid_body(block: Block) -> tuple[float, float, float] | None:
    """``(x_G, y_G, I_G)``: the centre of mass (m, in the frame of :attr:`Block.vertices`)
    and the moment of inertia about it (kg m^2) of a block whose polygon is only its
    outline, the body's mass and inertia being its own (a mesh block of
    :mod:`rocking.shapes`: the hull projected on the plane of shaking, with the mesh's mass
    and inertia). Read from the block's two sides: ``b_s = R_s sin(alpha_s)``, ``h = R_s
    cos(alpha_s)`` put the centre of mass at ``(x_O + b_+, h)`` above the base face's ends
    ``O`` (left, the pivot of ``theta > 0``) and ``O'``, and ``I_G = I_O - m R^2`` (``R``
    of the weaker side, whose ``I_O`` the block carries). None unless the block has a
    polygon, ``R``, ``mass`` and ``I_O``, both sides give the same ``h``, ``b_+ + b_-`` is
    the base face's length, ``I_G > 0`` and each side's ``p^2 = g R_s / (I_G/m + R_s^2)``
    (Eq 3), all to :data:`BODY_TOL`."""
    v = block.vertices
    if v is None or block.R is None or block.mass is None or block.I_O is None:
        return None
    (xl, _), (xr, _) = v[0], v[1]
    size = max(block.width or 0.0, block.height or 0.0, block.R)
    sides = [(block.alpha_plus, block.p_plus, block.R_plus),
             (block.alpha_minus, block.p_minus, block.R_minus)]
    b = [R * math.sin(a) for a, _, R in sides]
    h = [R * math.cos(a) for a, _, R in sides]
    if abs(h[0] - h[1]) > BODY_TOL * size or abs((xr - xl) - (b[0] + b[1])) > BODY_TOL * size:
        return None
    rg2 = block.I_O / block.mass - block.R * block.R
    if not rg2 > 0.0:
        return None
    for _, p, R in sides:
        if abs(G * R / (rg2 + R * R) - p * p) > 2.0 * BODY_TOL * p * p:
            return None
    return xl + b[0], 0.5 * (h[0] + h[1]), block.mass * rg2


def body_of(block: Block, geometry: str = "auto") -> Body:
    """The DEM body of ``block`` (see the module docstring for ``geometry``)."""
    if geometry not in GEOMETRIES:
        raise ParameterError(f"geometry must be one of {', '.join(GEOMETRIES)}; "
                               f"got {geometry!r}")
    if geometry == "auto":
        geometry = "classical" if block.mu > math.cos(2.0 * block.alpha) else "equivalent"
        if block.vertices is not None:
            a, p = _polygon_alpha_p(block)
            if abs(a - block.alpha) <= 1e-9 * a and abs(p - block.p) <= 1e-9 * p:
                geometry = "polygon"
            elif rigid_body(block) is not None:
                geometry = "body"
    if geometry == "body":
        rb = rigid_body(block)
        if rb is None:
            raise ParameterError(
                "geometry='body' needs a block whose polygon outlines a rigid body of known "
                "mass, inertia and centre of mass (a mesh block: rocking.shapes, the block "
                "form 'mesh')")
        xg, yg, i_g = rb
        v = np.array(block.vertices, dtype=np.float64) - np.array([xg, yg])
        return Body(v, float(block.mass), i_g, "body", block.alpha, block.p)
    if geometry == "polygon":
        if block.vertices is None:
            raise ParameterError("geometry='polygon' needs a block with a polygon "
                                   "(Block.rectangular or Block.polygon)")
        pr = polygon_properties(block.vertices)
        cx, cy = pr["centroid"]
        v = np.array(block.vertices, dtype=np.float64) - np.array([cx, cy])
        m = _default_mass(block, pr["area"])
        a, p = _polygon_alpha_p(block)
        return Body(v, m, m * pr["j_c"], "polygon", a, p)
    if geometry == "classical":
        # rectangle whose Housner restitution, alpha and p are the block's
        s2 = math.sin(block.alpha) ** 2
        R = (1.0 - block.mu) * G / (2.0 * block.p ** 2 * s2)
        if not R * block.p ** 2 < G:
            raise ParameterError(
                f"no rigid rectangle-like body has alpha = {block.alpha:g}, p = {block.p:g} "
                f"and Housner restitution mu = {block.mu:g}: mu must exceed cos(2 alpha) = "
                f"{math.cos(2 * block.alpha):.4f}")
        h, b = R * math.cos(block.alpha), R * math.sin(block.alpha)
        m = _default_mass(block, 4.0 * b * h)
        i_c = m * G * R / block.p ** 2 - m * R * R
        v = np.array([(-b, -h), (b, -h), (b, h), (-b, h)], dtype=np.float64)
        return Body(v, m, i_c, "classical", block.alpha, block.p)
    # equivalent rectangle, Eq 18, with the inertia that gives p
    if block.height is not None:
        h = 0.5 * block.height
    else:
        R = block.R if block.R is not None else 3.0 * G / (4.0 * block.p ** 2)
        h = R * math.cos(block.alpha)
    b = h * math.tan(block.alpha)
    R = math.hypot(b, h)
    m = _default_mass(block, 4.0 * b * h)
    i_o = m * G * R / block.p ** 2
    i_c = i_o - m * R * R
    if not i_c > 0.0:
        raise ParameterError(
            f"no rigid body has p = {block.p:g} 1/s with alpha = {block.alpha:g} rad and "
            f"height {2 * h:g} m: p^2 must be < g/R = {G / R:.4g} 1/s^2")
    v = np.array([(-b, -h), (b, -h), (b, h), (-b, h)], dtype=np.float64)
    return Body(v, m, i_c, "equivalent", block.alpha, block.p)


@dataclass
class Assembly:
    """Everything the kernel needs about the blocks, packed in arrays."""

    bodies: list
    lv: np.ndarray  # (N, V, 2) local vertices
    lvn: np.ndarray  # (N, V, 2) local vertex outward normals
    len_: np.ndarray  # (N, V, 2) local edge outward normals
    nv: np.ndarray  # (N,)
    mass: np.ndarray
    inertia: np.ndarray
    rad: np.ndarray  # bounding radius about the centroid
    nominal: np.ndarray  # (N, 3) centroid positions on undeformed contacts
    rr: float  # rounding length
    block: object  # the Block or Stack given

    @property
    def n(self) -> int:
        return int(self.nv.size)

    @property
    def total_mass(self) -> float:
        return float(self.mass.sum())

    @property
    def total_height(self) -> float:
        top = self.nominal[-1, 1] + self.lv[-1, : self.nv[-1], 1].max()
        return float(top)


def build_assembly(block, geometry: str = "auto") -> Assembly:
    """Pack a Block or a Stack into an :class:`Assembly`."""
    if isinstance(block, Stack):
        blocks, offsets = list(block.blocks), list(block.offsets)
    elif isinstance(block, Block):
        blocks, offsets = [block], [0.0]
    else:
        raise ParameterError(f"block must be a rocking.Block or rocking.Stack, "
                               f"got {type(block).__name__}")
    bodies = [body_of(b, geometry) for b in blocks]
    n = len(bodies)
    vmax = max(b.verts.shape[0] for b in bodies)
    lv = np.zeros((n, vmax, 2))
    lvn = np.zeros((n, vmax, 2))
    len_ = np.zeros((n, vmax, 2))
    nv = np.zeros(n, dtype=np.int64)
    nominal = np.zeros((n, 3))
    x_top, y_top = 0.0, 0.0  # middle of the supporting face
    for i, (bd, off) in enumerate(zip(bodies, offsets, strict=True)):
        v = bd.verts
        k = v.shape[0]
        nv[i] = k
        lv[i, :k] = v
        for e in range(k):
            d = v[(e + 1) % k] - v[e]
            len_[i, e] = (d[1] / math.hypot(*d), -d[0] / math.hypot(*d))
        for e in range(k):
            s = len_[i, e] + len_[i, e - 1]
            lvn[i, e] = s / math.hypot(*s)
        bx, by = bd.base_mid
        nominal[i] = (x_top + off - bx, y_top - by, 0.0)
        if i < n - 1:
            tx, ty = bd.top_mid
            x_top, y_top = nominal[i, 0] + tx, nominal[i, 1] + ty
    size = min(min(b.width, b.height) for b in bodies)
    return Assembly(bodies, lv, lvn, len_, nv, np.array([b.mass for b in bodies]),
                 np.array([b.inertia for b in bodies]),
                 np.array([float(np.sqrt((b.verts ** 2).sum(axis=1)).max()) for b in bodies]),
                 nominal, ROUNDING * size, block)


def default_stiffness(model: Assembly) -> float:
    """Default contact stiffness (N/m): settlement ``DEFAULT_SETTLEMENT`` x height on two
    contact points under the total weight."""
    return model.total_mass * G / (2.0 * DEFAULT_SETTLEMENT * model.total_height)
