r"""The discrete element model (DEM): rigid polygons on contact springs (Peña et al. 2007,
Section 2.3 and Eqs 14-22), in the style of UDEC, as ``model="dem"``.

Unlike the classical and CCRR models, the blocks here have three degrees of freedom each
(horizontal and vertical translation of the centroid, rotation), so they can bounce,
slide and stack: ``rocking.simulate(rocking.Stack([b1, b2]), motion, model="dem")``.

**Frame and ground motion.** We integrate in the frame of the base (the shaking table).
A rigid base with a prescribed acceleration ``a_t(t)`` is dynamically equivalent to a
fixed base with the body force ``-M a_t`` on every block: the contact forces depend only
on relative positions and relative velocities (all the damping is in the contacts), so
nothing else changes. This is exact and needs no integration of the acceleration into
table displacements (no baseline correction, no drift). With the sign convention of the
paper's Eq (1) (a positive ``a`` drives ``theta`` positive, see
:mod:`rocking.models.housner`) the body force is ``-M a(t)`` along +x: it tilts the block
counter-clockwise about its left base corner O, and ``theta`` is the counter-clockwise
rotation of the block. ``x`` and ``y`` are thus displacements *relative to the base*.

**Blocks.** Rigid convex polygons (:meth:`rocking.Block.polygon`; rectangles and the
specimens' cut corners). The geometry used for a :class:`~rocking.Block` is chosen by the
``geometry`` option:

* ``"polygon"``: the block's own polygon (:attr:`Block.vertices`), with the mass and the
  inertia of the polygon;
* ``"equivalent"``: the paper's equivalent block (Eq 18): a rectangle of the block's
  height ``2h`` and width ``2 b_eq = 2 h tan(alpha)``, whose moment of inertia is set to
  ``I_O = M g R / p^2`` so that ``alpha`` *and* ``p`` are exactly the block's; its
  plastic-impact restitution is then not ``mu`` in general;
* ``"classical"``: the rigid rectangle whose ``alpha``, ``p`` *and* Housner restitution
  are the block's: half-diagonal ``R = (1 - mu) g / (2 p^2 sin^2 alpha)`` (from
  ``mu = 1 - 2 M R^2 sin^2(alpha) / I_O`` and ``p^2 = M g R / I_O``), inertia from ``p``.
  It exists when ``mu > cos(2 alpha)``. For Table II's T parameters of specimen 2 it is
  the Table I rectangle to 0.1 %; for its E parameters (``mu`` = 0.973 exceeds Eq 4) it
  is 0.61 m tall instead of 1 m. The classical models depend on ``alpha``, ``p``
  and ``mu`` only, and this body reproduces them with well-damped contacts (the damping
  calibrated to ``mu`` is then the plastic-impact one). The DEM's restitution lies between
  its undamped (bouncing) value and the plastic impact of its body
  (:func:`rocking.dem.calibrate_damping`): the Eq 18 body reaches the E values of ``mu``
  only with nearly undamped contacts on which the landing corner bounces, and its forced
  response is then erratic (specimen 2 overturns under the 5 Hz, 5 mm sine of Fig 7, where
  the classical model reaches 1.77 degrees);
* ``"auto"`` (default): the polygon if the block's ``alpha`` and ``p`` are those of its
  polygon (a block built from its geometry), else the classical body (the equivalent one
  if ``mu <= cos(2 alpha)``).

A block with no known mass gets that of granite (2650 kg/m^3) times its area and
thickness (1 m if unknown); the rocking motion does not depend on it (the default
stiffness scales with the mass).

**Contacts.** Vertex-to-edge, detected geometrically at every step: a vertex of one block
is in contact with an edge of another block (or with the base, the half-plane ``y < 0``)
when it penetrates it, lies within the edge's span (extended by a rounding length
``r = 1e-3`` of the smaller block size, so that coincident corners of stacked blocks of
equal width stay in contact) and faces it (the vertex's outward normal opposes the
edge's). Of two coincident corners, only the upper block's counts. A flat face on a flat
face therefore has two contact points, at its ends (the paper's "contact points located
at the corners"). Each contact point has

* a normal spring ``K`` (N/m), linear in compression, no tension;
* a shear spring ``Ks = K`` (default), incremental (the shear force is history, kept per
  (vertex, edge) pair), elastic-perfectly plastic with the Coulomb limit
  ``|Fs| <= Fn tan(phi) + c`` (``c``: cohesion, N per contact point, 0 by default);
* viscous dashpots ``C = b K`` and ``b Ks`` (stiffness-proportional Rayleigh damping,
  no mass-proportional part, as in the paper's Section 4.4), only while the contact is
  closed: the normal force ``K d - b K d_dot`` is clipped at zero (no tension), and a
  sliding contact carries only its Coulomb force.

A vertex that separates or leaves the edge's span ends the contact and resets its shear
force.

**Default stiffness.** ``K = M g / (2 delta_0)`` per contact point with
``delta_0 = 1e-7 H``: the static settlement of a block (or of a stack, with its total mass
``M`` and height ``H``) standing on two contact points is 1e-7 of its height, 0.1 µm for
the 1 m specimens (``K = 1.1e10 N/m`` for specimen 2). That is physical for granite: an
elastic half-space loaded over a strip the length of the thickness ``t`` has a stiffness
of order ``E t``, 2.5e10 N/m for ``E = 50 GPa`` and ``t = 0.5 m``; and it is a joint
stiffness ``K / (b t) = 2.6e11 Pa/m`` over half the base of specimen 2 (rock joints:
1e9 - 1e12 Pa/m). See :mod:`rocking.dem` for why the paper's ``K = M p^2`` (Eq 17) cannot be a
stiffness in N/m.

**Default damping.** ``b`` is calibrated so that the apparent coefficient of restitution
of one impact in free rocking equals the block's ``mu``
(:func:`rocking.dem.calibrate_damping`).

**Integration.** Explicit central differences, as in UDEC: velocities at half steps,
positions at full steps; the damping and the shear-spring increments use the half-step
relative velocities. The time step is ``0.8 x 2 (sqrt(1 + xi^2) - xi) / omega_max``, the
stability limit of the scheme with the lagged stiffness-proportional damping
(``xi = b omega_max / 2``; the characteristic equation of the scheme gives exactly this
bound), where ``omega_max`` is the highest natural frequency of the blocks on their
closed contacts (an eigenvalue problem solved once, at rest). It is capped at
``0.2 / omega_max`` (about 30 steps per period of the stiffest mode): a contact closes and
opens between steps, which central differences resolve to first order only, and at the
stability limit an undamped bouncing block gains or loses percents of its energy at each
impact (with the default, calibrated damping the stability limit is already below the
cap). The step is then rounded down to divide the output interval. Everything per step
runs in one compiled numba function; :func:`simulate_many` runs a batch in parallel.

**Response.** ``theta`` is the rotation of the block (for a stack: of the top block; all
blocks in ``theta_all``, ``x_all``, ``y_all``, shape ``(n_blocks, n_t)``); ``x``, ``y``
the displacement of its centroid relative to the base (``y`` from its nominal position
on undeformed contacts, so that at rest ``y`` is minus the settlement). Impacts are the
sign changes of ``theta`` (located by linear interpolation between steps, counted once
``|theta|`` has exceeded ``impact_tol`` since the previous one); ``uplift_time`` is the
first time a closed contact opens; the block *overturns* when any block's ``|theta|``
reaches ``pi/2`` or a block of a stack falls onto the base. Initial conditions
``theta0``, ``omega0`` rotate the whole stack rigidly about the bottom block's pivot
corner. By default the blocks start at static equilibrium (``settled=True``: the contact
springs already carry the weights).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from .._validate import as_float, in_range, non_negative, positive
from ..blocks import GRANITE_DENSITY, Block, Stack, polygon_properties
from ..motions._kernel import ground_acc
from ..results import BatchResponse, Response
from ..units import G
from . import _common as C
from ._numerics import events as E

HALF_PI = 0.5 * math.pi
DEFAULT_SETTLEMENT = 1e-7
"""Default static settlement of a block under its own weight, as a fraction of its height."""
SAFETY = 0.8
"""Fraction of the stability limit of central differences used as the time step."""
ACCURACY = 0.2
"""Largest ``omega_max dt``: about 30 steps per period of the stiffest contact mode, so that
the closing and opening of contacts (resolved to first order only) cost little energy."""
ROUNDING = 1e-3
"""Rounding length of the corners (span tolerance), as a fraction of the smaller block size."""
GEOMETRIES = ("auto", "polygon", "equivalent", "classical")


# =============================================================================== geometry
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
            raise C.ParameterError("a block that carries another one must have a flat "
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


def body_of(block: Block, geometry: str = "auto") -> Body:
    """The DEM body of ``block`` (see the module docstring for ``geometry``)."""
    if geometry not in GEOMETRIES:
        raise C.ParameterError(f"geometry must be one of {', '.join(GEOMETRIES)}; "
                               f"got {geometry!r}")
    if geometry == "auto":
        geometry = "classical" if block.mu > math.cos(2.0 * block.alpha) else "equivalent"
        if block.vertices is not None:
            a, p = _polygon_alpha_p(block)
            if abs(a - block.alpha) <= 1e-9 * a and abs(p - block.p) <= 1e-9 * p:
                geometry = "polygon"
    if geometry == "polygon":
        if block.vertices is None:
            raise C.ParameterError("geometry='polygon' needs a block with a polygon "
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
            raise C.ParameterError(
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
        raise C.ParameterError(
            f"no rigid body has p = {block.p:g} 1/s with alpha = {block.alpha:g} rad and "
            f"height {2 * h:g} m: p^2 must be < g/R = {G / R:.4g} 1/s^2")
    v = np.array([(-b, -h), (b, -h), (b, h), (-b, h)], dtype=np.float64)
    return Body(v, m, i_c, "equivalent", block.alpha, block.p)


@dataclass
class Model:
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


def build_model(block, geometry: str = "auto") -> Model:
    """Pack a Block or a Stack into a :class:`Model`."""
    if isinstance(block, Stack):
        blocks, offsets = list(block.blocks), list(block.offsets)
    elif isinstance(block, Block):
        blocks, offsets = [block], [0.0]
    else:
        raise C.ParameterError(f"block must be a rocking.Block or rocking.Stack, "
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
    return Model(bodies, lv, lvn, len_, nv, np.array([b.mass for b in bodies]),
                 np.array([b.inertia for b in bodies]),
                 np.array([float(np.sqrt((b.verts ** 2).sum(axis=1)).max()) for b in bodies]),
                 nominal, ROUNDING * size, block)


def default_stiffness(model: Model) -> float:
    """Default contact stiffness (N/m): settlement ``DEFAULT_SETTLEMENT`` x height on two
    contact points under the total weight."""
    return model.total_mass * G / (2.0 * DEFAULT_SETTLEMENT * model.total_height)


# ================================================================================ kernel
@njit(cache=True)
def _world(pos, lv, lvn, len_, nv, wv, wn, en):
    """World coordinates of the vertices, vertex normals and edge normals of every block."""
    for i in range(nv.shape[0]):
        c = math.cos(pos[i, 2])
        s = math.sin(pos[i, 2])
        for k in range(nv[i]):
            x, y = lv[i, k, 0], lv[i, k, 1]
            wv[i, k, 0] = pos[i, 0] + c * x - s * y
            wv[i, k, 1] = pos[i, 1] + s * x + c * y
            x, y = lvn[i, k, 0], lvn[i, k, 1]
            wn[i, k, 0] = c * x - s * y
            wn[i, k, 1] = s * x + c * y
            if nv.shape[0] > 1:  # edge normals: block-block contacts only
                x, y = len_[i, k, 0], len_[i, k, 1]
                en[i, k, 0] = c * x - s * y
                en[i, k, 1] = s * x + c * y


@njit(cache=True)
def _find_edge(px, py, nvx, nvy, i, j, pos, wv, en, nv, rad, rr, tol):
    """Edge of block ``j`` touched by vertex (px, py) of block ``i`` (outward vertex normal
    (nvx, nvy)): ``(edge, d)`` with ``d`` the signed distance (< tol), or ``(-1, 0)``.

    A vertex outside the convex polygon by more than the rounding ``rr`` touches nothing.
    Of the edges that face the vertex and whose (extended) span contains its projection,
    the nearest (largest ``d``) is the contact face; the vertex touches it if ``d < tol``.
    """
    dx = px - pos[j, 0]
    dy = py - pos[j, 1]
    lim = rad[j] + rr
    if dx * dx + dy * dy > lim * lim:
        return -1, 0.0
    if i < j:  # a lower block's vertex at an upper block's corner: the upper one counts
        for m in range(nv[j]):
            ex = px - wv[j, m, 0]
            ey = py - wv[j, m, 1]
            if ex * ex + ey * ey <= rr * rr:
                return -1, 0.0
    best = -1
    bestd = -math.inf
    k = nv[j]
    for e in range(k):
        nx, ny = en[j, e, 0], en[j, e, 1]
        qx, qy = wv[j, e, 0], wv[j, e, 1]
        d = (px - qx) * nx + (py - qy) * ny
        if d > rr:  # outside the (convex) polygon, beyond the rounding
            return -1, 0.0
        if nx * nvx + ny * nvy >= 0.0 or d <= bestd:
            continue
        e1 = e + 1 if e + 1 < k else 0
        ux, uy = wv[j, e1, 0] - qx, wv[j, e1, 1] - qy
        ln = math.sqrt(ux * ux + uy * uy)
        s = ((px - qx) * ux + (py - qy) * uy) / ln
        if s < -rr or s > ln + rr:
            continue
        best = e
        bestd = d
    if best < 0 or bestd >= tol:  # the nearest face is not penetrated
        return -1, 0.0
    return best, bestd


@njit(cache=True)
def _forces(pos, vel, t, dt, lv, lvn, len_, nv, mass, inertia, rad, rr, K, Ks, cn, cs,
            tanphi, coh, kind, prm, samples, wv, wn, en, fs, sedge, F, cf, rec):
    """Contact and body forces at positions ``pos`` with (half-step) velocities ``vel``.

    Updates the shear histories ``fs`` and contact edges ``sedge`` (-1: open) of every slot
    (vertex i,k against target j; j = N is the base), writes the forces on the blocks in
    ``F`` (N, 3) and, if ``rec``, the contact forces (Fn, Fs, x, y) of each closed slot in
    ``cf``. Returns
    ``(spring energy, a contact opened, a block other than the bottom one touched the
    base)``.
    """
    n = nv.shape[0]
    _world(pos, lv, lvn, len_, nv, wv, wn, en)
    ag = ground_acc(kind, prm, samples, t)
    for i in range(n):
        F[i, 0] = -mass[i] * ag
        F[i, 1] = -mass[i] * 9.80665
        F[i, 2] = 0.0
    energy = 0.0
    opened = False
    fell = False
    for i in range(n):
        xi, yi = pos[i, 0], pos[i, 1]
        vxi, vyi, wi = vel[i, 0], vel[i, 1], vel[i, 2]
        for k in range(nv[i]):
            px, py = wv[i, k, 0], wv[i, k, 1]
            rx, ry = px - xi, py - yi
            vpx = vxi - wi * ry
            vpy = vyi + wi * rx
            # ---- the base: half-plane y < 0, normal (0, 1), tangent (1, 0)
            if py < 0.0 and wn[i, k, 1] < 0.0:
                if i > 0:
                    fell = True
                pen = -py
                fn, ft, fsp = _contact_law(K, Ks, cn, cs, tanphi, coh, pen, vpy, vpx,
                                           fs[i, k, n], dt)
                fs[i, k, n] = fsp
                sedge[i, k, n] = 0
                F[i, 0] += ft
                F[i, 1] += fn
                F[i, 2] += rx * fn - ry * ft
                energy += 0.5 * K * pen * pen + 0.5 * fsp * fsp / Ks
                if rec:
                    cf[i, k, n, 0] = fn
                    cf[i, k, n, 1] = ft
                    cf[i, k, n, 2] = px
                    cf[i, k, n, 3] = py
            elif sedge[i, k, n] >= 0:
                opened = True
                sedge[i, k, n] = -1
                fs[i, k, n] = 0.0
            # ---- other blocks
            for j in range(n):
                if j == i:
                    continue
                e, d = _find_edge(px, py, wn[i, k, 0], wn[i, k, 1], i, j, pos, wv, en, nv,
                                  rad, rr, 0.0)
                if e < 0:
                    if sedge[i, k, j] >= 0:
                        opened = True
                        sedge[i, k, j] = -1
                        fs[i, k, j] = 0.0
                    continue
                if sedge[i, k, j] != e:
                    fs[i, k, j] = 0.0
                    sedge[i, k, j] = e
                nx, ny = en[j, e, 0], en[j, e, 1]
                ux, uy = -ny, nx
                sx, sy = px - pos[j, 0], py - pos[j, 1]
                wj = vel[j, 2]
                rvx = vpx - (vel[j, 0] - wj * sy)
                rvy = vpy - (vel[j, 1] + wj * sx)
                vn = rvx * nx + rvy * ny
                vt = rvx * ux + rvy * uy
                pen = -d
                fn, ft, fsp = _contact_law(K, Ks, cn, cs, tanphi, coh, pen, vn, vt,
                                           fs[i, k, j], dt)
                fs[i, k, j] = fsp
                fx = fn * nx + ft * ux
                fy = fn * ny + ft * uy
                F[i, 0] += fx
                F[i, 1] += fy
                F[i, 2] += rx * fy - ry * fx
                F[j, 0] -= fx
                F[j, 1] -= fy
                F[j, 2] -= sx * fy - sy * fx
                energy += 0.5 * K * pen * pen + 0.5 * fsp * fsp / Ks
                if rec:
                    cf[i, k, j, 0] = fn
                    cf[i, k, j, 1] = ft
                    cf[i, k, j, 2] = px
                    cf[i, k, j, 3] = py
    return energy, opened, fell


@njit(cache=True)
def integrate(lv, lvn, len_, nv, mass, inertia, rad, rr, K, Ks, cn, cs, tanphi, coh, kind,
              prm, samples, t_end, dt, every, pos, vel, fs, sedge, nominal, iout, th_tol,
              resting, out_pos, out_vel, out_e, out_f, imp):
    """Integrate from ``pos``/``vel`` (updated in place) until ``t_end``. Returns
    ``(n_out, n_impacts, max|theta|, overturned, overturn_time, uplift_time, n_steps, ok)``.

    Output every ``every`` steps into ``out_pos``/``out_vel`` (n_out, N, 3) (length 0:
    none), energies (kinetic, potential, spring) into ``out_e`` and slot forces into
    ``out_f`` when they have rows; impact times into ``imp`` up to its length.
    """
    n = nv.shape[0]
    vmax = lv.shape[1]
    wv = np.empty((n, vmax, 2))
    wn = np.empty((n, vmax, 2))
    en = np.empty((n, vmax, 2))
    F = np.empty((n, 3))
    cf = np.zeros((n, vmax, n + 1, 4))
    vnew = np.empty((n, 3))
    n_out = out_pos.shape[0]
    n_e = out_e.shape[0]
    n_f = out_f.shape[0]
    cap = imp.shape[0]
    n_steps = int(math.ceil(t_end / dt - 1e-9))
    k = 0
    n_imp = 0
    peak = abs(pos[iout, 2])
    armed = peak > th_tol
    overturned = False
    t_over = math.nan
    t_up = math.nan if resting else 0.0
    ok = True
    step = 0
    while True:
        t = step * dt
        out_step = step % every == 0 and k < n_out
        e_spring, opened, fell = _forces(pos, vel, t, dt, lv, lvn, len_, nv, mass, inertia,
                                         rad, rr, K, Ks, cn, cs, tanphi, coh, kind, prm,
                                         samples, wv, wn, en, fs, sedge, F, cf,
                                         out_step and k < n_f)
        if opened and math.isnan(t_up):
            t_up = t
        h = dt if step > 0 else 0.5 * dt
        for i in range(n):
            vnew[i, 0] = vel[i, 0] + h * F[i, 0] / mass[i]
            vnew[i, 1] = vel[i, 1] + h * F[i, 1] / mass[i]
            vnew[i, 2] = vel[i, 2] + h * F[i, 2] / inertia[i]
        if out_step:
            ke = 0.0
            pe = 0.0
            for i in range(n):
                for c in range(3):
                    out_pos[k, i, c] = pos[i, c]
                    out_vel[k, i, c] = 0.5 * (vel[i, c] + vnew[i, c]) if step > 0 \
                        else vel[i, c]
                ke += 0.5 * (mass[i] * (out_vel[k, i, 0] ** 2 + out_vel[k, i, 1] ** 2)
                             + inertia[i] * out_vel[k, i, 2] ** 2)
                pe += mass[i] * 9.80665 * (pos[i, 1] - nominal[i, 1])
            if k < n_e:
                out_e[k, 0] = ke
                out_e[k, 1] = pe
                out_e[k, 2] = e_spring
            if k < n_f:
                for i in range(n):
                    for kk in range(vmax):
                        for j in range(n + 1):
                            s = (i * vmax + kk) * (n + 1) + j
                            for c in range(4):
                                out_f[k, s, c] = cf[i, kk, j, c] if sedge[i, kk, j] >= 0 \
                                    else (0.0 if c < 2 else math.nan)
            k += 1
        if fell:
            overturned = True
            t_over = t
            break
        if step >= n_steps:
            break
        th_old = pos[iout, 2]
        for i in range(n):
            for c in range(3):
                vel[i, c] = vnew[i, c]
                pos[i, c] += dt * vnew[i, c]
        step += 1
        th = pos[iout, 2]
        if not (abs(th) < 1e6 and abs(pos[iout, 0]) < 1e6):
            ok = False
            break
        a = abs(th)
        if a > peak:
            peak = a
        if a > th_tol:
            armed = True
        if armed and th * th_old < 0.0:
            if n_imp < cap:
                imp[n_imp] = t + dt * th_old / (th_old - th)
            n_imp += 1
            armed = False
        over = False
        for i in range(n):
            if abs(pos[i, 2]) >= HALF_PI:
                over = True
        if over:
            overturned = True
            t_over = step * dt
            if a >= HALF_PI:
                t_over -= dt * (a - HALF_PI) / max(a - abs(th_old), 1e-300)
            break
    return k, n_imp, peak, overturned, t_over, t_up, step, ok


@njit(cache=True, parallel=True)
def _batch(lv, lvn, len_, nv, mass, inertia, rad, rr, K, Ks, cn, cs, tanphi, coh, kinds,
           prms, samples, nsamp, t_ends, dt, every, pos0, vel0, fs0, sedge0, nominal, iout,
           th_tol, n_out, out_pos, out_vel, res_f, res_i):
    m = kinds.shape[0]
    n = nv.shape[0]
    for q in prange(m):
        pos = pos0.copy()
        vel = vel0.copy()
        fs = fs0.copy()
        sedge = sedge0.copy()
        imp = np.empty(0)
        oe = np.empty((0, 3))
        of = np.empty((0, 1, 4))
        if n_out > 0:
            op = out_pos[q]
            ov = out_vel[q]
        else:
            op = np.empty((0, n, 3))
            ov = np.empty((0, n, 3))
        kk, nimp, peak, over, tov, tup, nst, ok = integrate(
            lv, lvn, len_, nv, mass, inertia, rad, rr, K, Ks, cn, cs, tanphi, coh, kinds[q],
            prms[q], samples[q, : nsamp[q]], t_ends[q], dt, every, pos, vel, fs, sedge,
            nominal, iout, th_tol, True, op, ov, oe, of, imp)
        op[kk:] = math.nan
        ov[kk:] = math.nan
        E.store_result(res_f, res_i, q, peak, tov, tup, nimp, over, nst, ok)


@njit(cache=True)
def _contact_law(K, Ks, cn, cs, tanphi, coh, pen, vn, vt, fs_prev, dt):
    """One contact point: normal spring without tension plus its dashpot, and the
    incremental shear spring (plus dashpot) capped by Coulomb friction. Returns the normal
    and shear forces and the new shear-spring force (the spring slips at the cap)."""
    fn = K * pen - cn * vn
    if fn < 0.0:
        fn = 0.0
    fsp = fs_prev - Ks * vt * dt
    ft = fsp - cs * vt
    fmax = fn * tanphi + coh
    if abs(ft) > fmax:
        ft = math.copysign(fmax, ft)
        fsp = ft
    return fn, ft, fsp


@njit(cache=True)
def _row(out, c, i, k, j, e, px, py, nx, ny):
    out[c, 0] = i
    out[c, 1] = k
    out[c, 2] = j
    out[c, 3] = e
    out[c, 4] = px
    out[c, 5] = py
    out[c, 6] = nx
    out[c, 7] = ny


@njit(cache=True)
def _probe(pos, lv, lvn, len_, nv, rad, rr, tol, out):
    """Contacts with signed distance < ``tol`` at ``pos``: rows (i, k, j, e, px, py, nx, ny)
    in ``out`` (j = N: the base). Returns their number."""
    n = nv.shape[0]
    vmax = lv.shape[1]
    wv = np.empty((n, vmax, 2))
    wn = np.empty((n, vmax, 2))
    en = np.empty((n, vmax, 2))
    _world(pos, lv, lvn, len_, nv, wv, wn, en)
    c = 0
    for i in range(n):
        for k in range(nv[i]):
            px, py = wv[i, k, 0], wv[i, k, 1]
            if py < tol and wn[i, k, 1] < 0.0:
                _row(out, c, i, k, n, 0, px, py, 0.0, 1.0)
                c += 1
            for j in range(n):
                if j == i:
                    continue
                e, d = _find_edge(px, py, wn[i, k, 0], wn[i, k, 1], i, j, pos, wv, en, nv,
                                  rad, rr, tol)
                if e >= 0:
                    _row(out, c, i, k, j, e, px, py, en[j, e, 0], en[j, e, 1])
                    c += 1
    return c


# ==================================================================== linear analysis
def contacts_at(model: Model, pos: np.ndarray, tol: float) -> np.ndarray:
    """Contacts (rows i, k, j, e, px, py, nx, ny) with signed distance below ``tol``."""
    out = np.empty((model.n * model.lv.shape[1] * (model.n + 1), 8))
    c = _probe(np.ascontiguousarray(pos, dtype=np.float64), model.lv, model.lvn, model.len_,
               model.nv, model.rad, model.rr, tol, out)
    return out[:c]


def stiffness_matrix(model: Model, pos, K: float, Ks: float, contacts=None):
    """Stiffness matrix (3N x 3N) of the blocks on their closed contacts at ``pos``, and
    the constraint rows (normal, tangential) of each contact."""
    n = model.n
    if contacts is None:
        contacts = contacts_at(model, pos, 1e-9 * model.rr)
    Kmat = np.zeros((3 * n, 3 * n))
    rows = []
    for i, _k, j, _e, px, py, nx, ny in contacts:
        i, j = int(i), int(j)
        ux, uy = -ny, nx
        gn = np.zeros(3 * n)
        gt = np.zeros(3 * n)
        for b, sgn in ((i, 1.0), (j, -1.0)):
            if b >= n:
                continue
            rx, ry = px - pos[b, 0], py - pos[b, 1]
            gn[3 * b: 3 * b + 3] += sgn * np.array([nx, ny, rx * ny - ry * nx])
            gt[3 * b: 3 * b + 3] += sgn * np.array([ux, uy, rx * uy - ry * ux])
        Kmat += K * np.outer(gn, gn) + Ks * np.outer(gt, gt)
        rows.append((gn, gt))
    return Kmat, rows


def omega_max(model: Model, K: float, Ks: float) -> float:
    """Highest natural frequency (rad/s) of the blocks resting on closed contacts."""
    Kmat, _ = stiffness_matrix(model, model.nominal, K, Ks)
    m = np.stack([model.mass, model.mass, model.inertia], axis=1).ravel()
    s = 1.0 / np.sqrt(m)
    lam = np.linalg.eigvalsh(Kmat * s[:, None] * s[None, :])
    return float(math.sqrt(max(lam.max(), 0.0)))


def stable_dt(model: Model, K: float, Ks: float, b: float, safety: float = SAFETY) -> float:
    """Time step (s): ``safety`` x the stability limit of central differences with the
    lagged stiffness-proportional damping ``b``, and at most ``ACCURACY / omega_max``
    (see the module docstring)."""
    w = omega_max(model, K, Ks)
    xi = 0.5 * b * w
    return min(safety * 2.0 * (math.sqrt(1.0 + xi * xi) - xi), ACCURACY) / w


def static_state(model: Model, K: float, Ks: float):
    """Static equilibrium under gravity on the contacts closed at the nominal positions:
    ``(pos, fs, sedge)`` (linear solution; exact for the linear contact springs)."""
    n = model.n
    vmax = model.lv.shape[1]
    pos = model.nominal.copy()
    fs = np.zeros((n, vmax, n + 1))
    sedge = np.full((n, vmax, n + 1), -1, dtype=np.int64)
    contacts = contacts_at(model, pos, 1e-9 * model.rr)
    Kmat, rows = stiffness_matrix(model, pos, K, Ks, contacts)
    f = np.zeros(3 * n)
    f[1::3] = -model.mass * G
    try:
        u = np.linalg.solve(Kmat, f)
    except np.linalg.LinAlgError:
        return pos, fs, sedge
    if not np.all(np.isfinite(u)) or np.abs(Kmat @ u - f).max() > 1e-6 * np.abs(f).max():
        return pos, fs, sedge
    pos = pos + u.reshape(n, 3)
    for (i, k, j, e, *_), (_gn, gt) in zip(contacts, rows, strict=True):
        i, k, j = int(i), int(k), int(j)
        fs[i, k, j] = -Ks * float(gt @ u)
        sedge[i, k, j] = int(e)
    return pos, fs, sedge


def initial_state(model: Model, K: float, Ks: float, theta0: float, omega0: float,
                  settled: bool):
    """Positions, velocities, shear histories and contact edges at t = 0."""
    n = model.n
    vmax = model.lv.shape[1]
    if theta0 == 0.0 and omega0 == 0.0:
        if settled:
            pos, fs, sedge = static_state(model, K, Ks)
        else:
            pos = model.nominal.copy()
            fs = np.zeros((n, vmax, n + 1))
            sedge = np.full((n, vmax, n + 1), -1, dtype=np.int64)
        return pos, np.zeros((n, 3)), fs, sedge
    s = theta0 if theta0 != 0.0 else omega0
    v0 = model.lv[0, 0] if s > 0 else model.lv[0, 1]  # pivot: left (O) or right (O')
    px, py = model.nominal[0, 0] + v0[0], model.nominal[0, 1] + v0[1]
    c, sn = math.cos(theta0), math.sin(theta0)
    pos = model.nominal.copy()
    vel = np.zeros((n, 3))
    sink = model.total_mass * G / K if settled else 0.0  # the pivot carries the weight
    for i in range(n):
        dx, dy = model.nominal[i, 0] - px, model.nominal[i, 1] - py
        pos[i] = (px + c * dx - sn * dy, py + sn * dx + c * dy - sink, theta0)
        vel[i] = (-omega0 * (pos[i, 1] + sink - py), omega0 * (pos[i, 0] - px), omega0)
    return (pos, vel, np.zeros((n, vmax, n + 1)),
            np.full((n, vmax, n + 1), -1, dtype=np.int64))


# ============================================================================ Python API
@dataclass
class Setup:
    """Validated options of a DEM run."""

    model: Model
    K: float
    Ks: float
    b: float
    tanphi: float
    cohesion: float
    dt: float
    every: int
    dt_out: float
    th_tol: float
    damping_source: str


def _setup(block, *, friction_angle, stiffness, shear_stiffness, damping, cohesion,
           geometry, dt_out, dt, impact_tol) -> Setup:
    model = build_model(block, geometry)
    phi = in_range("friction_angle", friction_angle, 0.0, 90.0, shown="[0, 90) deg",
                   lo_open=False)
    K = default_stiffness(model) if stiffness is None else positive("stiffness", stiffness,
                                                                     "N/m")
    Ks = K if shear_stiffness is None else positive("shear_stiffness", shear_stiffness, "N/m")
    coh = non_negative("cohesion", cohesion, "N")
    if damping is None or (isinstance(damping, str) and damping == "calibrated"):
        from ..dem import calibrate_damping

        top = model.block.blocks[-1] if isinstance(model.block, Stack) else model.block
        cal = calibrate_damping(top, top.mu, K, geometry=geometry, friction_angle=phi,
                                shear_stiffness=Ks, full=True)
        b = cal["b"]
        source = "calibrated"
        if abs(cal["mu_dem"] - top.mu) > 5e-3:
            warnings.warn(f"DEM damping: {cal['note']}; the DEM's restitution is "
                          f"{cal['mu_dem']:.4f}", RuntimeWarning, stacklevel=4)
    elif isinstance(damping, str) and damping == "paper":
        from ..dem import paper_parameters

        top = model.block.blocks[-1] if isinstance(model.block, Stack) else model.block
        b = paper_parameters(top)["b"]
        source = "paper (Eq 20)"
    elif isinstance(damping, str):
        raise C.ParameterError(f"damping must be a number (s), 'calibrated' or 'paper'; "
                               f"got {damping!r}")
    else:
        b = non_negative("damping", damping, "s")
        source = "given"
    dt_out = positive("dt_out", dt_out, "s")
    h = stable_dt(model, K, Ks, b)
    if dt is not None:
        dt = positive("dt", dt, "s")
        if dt > h / SAFETY:
            raise C.ParameterError(f"dt = {dt:g} s exceeds the stability limit "
                                   f"{h / SAFETY:.3g} s of central differences")
        h = dt
    every = max(1, int(math.ceil(dt_out / h - 1e-9)))
    alpha = min(bd.alpha for bd in model.bodies)
    th_tol = as_float("impact_tol", impact_tol) * alpha
    return Setup(model, K, Ks, b, math.tan(math.radians(phi)), coh, dt_out / every, every,
                 dt_out, th_tol, source)


def _slot_labels(model: Model) -> list[str]:
    n, vmax = model.n, model.lv.shape[1]
    out = []
    for i in range(n):
        for k in range(vmax):
            for j in range(n + 1):
                tgt = "base" if j == n else f"block {j}"
                out.append(f"block {i} vertex {k} / {tgt}")
    return out


def simulate(block, motion=None, *, duration=None, theta0=0.0, omega0=0.0, linear=False,
             friction_angle=30.0, stiffness=None, shear_stiffness=None, damping=None,
             cohesion=0.0, geometry="auto", dt_out=0.002, dt=None, settled=True,
             impact_tol=1e-3, return_forces=False, return_energy=False,
             max_impacts=100_000, **unknown):
    """Discrete element model; see :func:`rocking.simulate` and the module docstring.

    Parameters (besides those of :func:`rocking.simulate`)
    ----------
    block : Block or Stack
    friction_angle : float
        Friction angle phi of every contact, degrees (default 30, as in the paper).
    stiffness : float, optional
        Normal stiffness K of one contact point, N/m (default: see the module docstring).
    shear_stiffness : float, optional
        Ks, N/m (default K).
    damping : float or str, optional
        Stiffness-proportional damping factor ``b`` (s, ``C = b K``); ``"calibrated"`` or
        None (default): calibrated to the block's ``mu``; ``"paper"``: Eq 20.
    cohesion : float
        Cohesive shear strength of one contact point, N (default 0).
    geometry : str
        ``"auto"``, ``"polygon"`` or ``"equivalent"`` (module docstring).
    dt_out : float
        Output interval, s. ``dt``: time step (s), default from the stability limit.
    settled : bool
        Start at static equilibrium (default) rather than on undeformed contacts.
    impact_tol : float
        |theta| (fraction of alpha) to exceed between two counted zero crossings.
    return_forces : bool
        Fill ``Response.contact_forces``: a dict with ``t`` (s), ``normal`` and ``shear``
        (N, shape (n_t, n_contacts), zero while open), ``x``, ``y`` (contact point, m, NaN
        while open) and ``labels`` (one per potential contact: block, vertex, target),
        restricted to the contacts that close at least once.
    return_energy : bool
        Put ``kinetic``, ``potential`` and ``spring`` energies (J, at the output times;
        potential from the nominal positions) in ``Response.info["energy"]``.
    """
    C.no_unknown("dem", unknown)
    if linear:
        raise C.ParameterError("linear=True is not available for model 'dem'")
    st = _setup(block, friction_angle=friction_angle, stiffness=stiffness,
                shear_stiffness=shear_stiffness, damping=damping, cohesion=cohesion,
                geometry=geometry, dt_out=dt_out, dt=dt, impact_tol=impact_tol)
    sp = C.prepare_single(motion, duration, theta0, omega0, dt_out)
    md = st.model
    n, vmax = md.n, md.lv.shape[1]
    pos, vel, fs, sedge = initial_state(md, st.K, st.Ks, sp.theta0, sp.omega0, bool(settled))
    resting = sp.theta0 == 0.0 and sp.omega0 == 0.0
    n_out = sp.n_out
    out_pos = np.empty((n_out, n, 3))
    out_vel = np.empty((n_out, n, 3))
    out_e = np.empty((n_out if return_energy else 0, 3))
    n_slots = n * vmax * (n + 1)
    out_f = np.empty((n_out if return_forces else 0, n_slots, 4))
    imp = np.empty(max(1, min(int(max_impacts), 1_000_000)))
    k, n_imp, peak, over, t_over, t_up, n_steps, ok = integrate(
        md.lv, md.lvn, md.len_, md.nv, md.mass, md.inertia, md.rad, md.rr, st.K, st.Ks,
        st.b * st.K, st.b * st.Ks, st.tanphi, st.cohesion, sp.kind, sp.prm, sp.samples,
        sp.duration, st.dt, st.every, pos, vel, fs, sedge, md.nominal, n - 1, st.th_tol,
        resting, out_pos, out_vel, out_e, out_f, imp)
    if not ok:
        raise C.ParameterError(f"the DEM integration became unstable at t = "
                               f"{n_steps * st.dt:.4g} s (dt = {st.dt:.3g} s); "
                               "use a smaller dt")
    t = np.arange(k) * st.dt_out
    rel = out_pos[:k] - md.nominal[None, :, :]
    th_all = out_pos[:k, :, 2].T.copy()
    x_all = rel[:, :, 0].T.copy()
    y_all = rel[:, :, 1].T.copy()
    info = {"n_steps": int(n_steps), "dt": st.dt, "stiffness": st.K, "shear_stiffness": st.Ks,
            "damping": st.b, "damping_source": st.damping_source,
            "friction_angle": float(friction_angle), "n_blocks": n,
            "geometry": ",".join(bd.mode for bd in md.bodies),
            "xi_max": 0.5 * st.b * omega_max(md, st.K, st.Ks),
            "settlement": st.model.total_mass * G / (2.0 * st.K),
            "n_impacts_total": int(n_imp),
            "max_abs_theta_all": [float(np.max(np.abs(th_all[i]))) if k else 0.0
                                  for i in range(n)]}
    if return_energy:
        info["energy"] = {"t": t, "kinetic": out_e[:k, 0].copy(),
                          "potential": out_e[:k, 1].copy(), "spring": out_e[:k, 2].copy()}
    forces = None
    if return_forces:
        used = np.flatnonzero(np.any(out_f[:k, :, 0] > 0.0, axis=0)) if k else np.empty(0, int)
        labels = _slot_labels(md)
        forces = {"t": t, "normal": out_f[:k, used, 0].copy(), "shear": out_f[:k, used, 1].copy(),
                  "x": out_f[:k, used, 2].copy(), "y": out_f[:k, used, 3].copy(),
                  "labels": [labels[s] for s in used]}
    return Response(
        t=t, theta=th_all[-1].copy(), omega=out_vel[:k, -1, 2].copy(),
        impact_times=imp[: min(n_imp, imp.size)].copy(), max_abs_theta=float(peak),
        overturned=bool(over), overturn_time=float(t_over) if over else None,
        uplift_time=None if math.isnan(t_up) else float(t_up), model="dem", block=block,
        motion=motion, info=info, x=x_all[-1].copy(), y=y_all[-1].copy(),
        theta_all=th_all, x_all=x_all, y_all=y_all, contact_forces=forces,
    )


def simulate_many(block, motions, *, duration=None, linear=False, friction_angle=30.0,
                  stiffness=None, shear_stiffness=None, damping=None, cohesion=0.0,
                  geometry="auto", dt=None, impact_tol=1e-3, return_histories=False,
                  dt_out=0.01, **unknown):
    """Batch of DEM simulations from rest (settled), one per motion, in parallel.

    ``theta``/``omega`` histories (of the top block) only with ``return_histories=True``.
    """
    C.no_unknown("dem", unknown)
    if linear:
        raise C.ParameterError("linear=True is not available for model 'dem'")
    st = _setup(block, friction_angle=friction_angle, stiffness=stiffness,
                shear_stiffness=shear_stiffness, damping=damping, cohesion=cohesion,
                geometry=geometry, dt_out=dt_out, dt=dt, impact_tol=impact_tol)
    kinds, prms, samples, nsamp, t_ends, _h = C.pack_motions(motions, duration)
    md = st.model
    n = md.n
    m = kinds.size
    pos, vel, fs, sedge = initial_state(md, st.K, st.Ks, 0.0, 0.0, True)
    n_out = int(math.floor(t_ends.max() / st.dt_out + 1e-9)) + 1 if return_histories else 0
    out_pos = np.empty((m, n_out, n, 3))
    out_vel = np.empty((m, n_out, n, 3))
    res_f = np.empty((m, 3))
    res_i = np.empty((m, 3), dtype=np.int64)
    _batch(md.lv, md.lvn, md.len_, md.nv, md.mass, md.inertia, md.rad, md.rr, st.K, st.Ks,
           st.b * st.K, st.b * st.Ks, st.tanphi, st.cohesion, kinds, prms, samples, nsamp,
           t_ends, st.dt, st.every, pos, vel, fs, sedge, md.nominal, n - 1, st.th_tol, n_out,
           out_pos, out_vel, res_f, res_i)
    if np.isnan(res_f[:, 0]).any():
        raise C.ParameterError("the DEM integration became unstable; use a smaller dt")
    return BatchResponse(
        max_abs_theta=res_f[:, 0].copy(), overturned=res_i[:, 1].astype(bool),
        overturn_time=res_f[:, 1].copy(), uplift_time=res_f[:, 2].copy(),
        n_impacts=res_i[:, 0].copy(),
        t=np.arange(n_out) * st.dt_out if return_histories else None,
        theta=out_pos[:, :, -1, 2].copy() if return_histories else None,
        omega=out_vel[:, :, -1, 2].copy() if return_histories else None,
        model="dem",
    )
