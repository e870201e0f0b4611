"""A rigid body from a triangle mesh: validated, with its mass properties and its support.

Build one with :func:`load_shape` (a file: STL, OBJ, PLY), :meth:`Shape.from_trimesh`
or :meth:`Shape.from_arrays`. Each welds and validates the mesh
(:mod:`rocking.shapes.mesh`: refused with one line naming the defect unless
``repair="hull"``), computes the mass properties (:mod:`rocking.shapes.mass`; exactly one
of ``density`` in kg/m^3 and ``mass`` in kg), sets up the vertical frame of ``up`` and
finds the support (:mod:`rocking.shapes.support`). Lengths are in m; a file in mm or cm is
read with ``units="mm"`` / ``"cm"`` (a body taller than 50 m gets a warning: likely mm
read as m).

Attributes (SI): ``mass``, ``density``, ``volume``, ``com`` (3,) and ``inertia`` (3, 3,
about the centre of mass) in the mesh's own coordinates; ``frame`` (rows e1, e2, up);
``local_vertices`` (the vertices in the frame, relative to the centre of mass's vertical,
base at z = 0: the centre of mass is at ``(0, 0, h)``), ``inertia_local`` (the inertia
tensor in the frame), ``h`` (the centre of mass's height above the base), ``height``,
``support`` (the contact patch's convex hull, (k, 2), counter-clockwise, in the frame's
horizontal coordinates relative to the centre of mass's vertical), ``support_area``,
``contact_points`` (the patch's size), ``tol`` (m), ``repaired`` (the convex hull was used),
``primitive`` (an exact body the mesh stands for: ``("cylinder", r, H)``; else None).

Per direction: :func:`rocking.shapes.directional_parameters` (the table),
:meth:`Shape.parameters` (one direction as a dict), :meth:`rocking.Block.from_shape` (the
planar :class:`rocking.Block` of a direction), :meth:`Shape.polygon` (the planar outline
for the DEM) and
:meth:`Shape.weakest` (the exact weakest direction).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .._validate import PLAUSIBLE_LIMITS, as_float, check_plausible, warn_implausible
from ..errors import ParameterError
from ..units import G
from .directional import Direction, side_arrays
from .mass import resolve_mass, volume_properties
from .mesh import count_parts, read_mesh, size_of, validated
from .rest import rest_tolerance, resting_up
from .support import contact_tolerance, frame, inside_margin, support_hull

PLAUSIBLE_HEIGHT = PLAUSIBLE_LIMITS["size"][1]
"""A body larger than this (m) in any direction gets a
:class:`~rocking.errors.UnitSlipWarning` (likely a mesh in mm read as m; the command line
refuses it unless ``--force``): the limit of :data:`rocking.PLAUSIBLE_LIMITS`."""


class MeshRepairWarning(UserWarning):
    """A defective mesh was replaced by its convex hull (``repair="hull"``).

    Examples
    --------
    >>> import warnings, trimesh
    >>> from rocking.shapes import MeshRepairWarning, load_shape
    >>> mesh = trimesh.creation.box(extents=(0.4, 0.6, 2.0))
    >>> mesh.faces = mesh.faces[:-1]  # one triangle missing: not watertight
    >>> _ = mesh.export("open_box.stl")
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     shape = load_shape("open_box.stl", density=2000.0, repair="hull")
    >>> caught[0].category is MeshRepairWarning, shape.repaired, round(shape.volume, 6)
    (True, True, 0.48)
    """


@dataclass(frozen=True, eq=False)
class Shape:
    """A validated watertight mesh with its mass properties and support (module
    docstring). Build it with :func:`load_shape` or :meth:`from_trimesh`.

    Examples
    --------
    >>> import trimesh
    >>> from rocking.shapes import Shape
    >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)), density=2000.0)
    >>> round(box.mass, 6), round(box.h, 6), round(box.height, 6)  # 2000 x 0.48 m^3; h = H/2
    (960.0, 1.0, 2.0)
    >>> box.contact_points, bool(np.allclose(box.com, 0.0))  # 4 corners; centred box
    (4, True)
    """

    vertices: np.ndarray
    faces: np.ndarray
    mass: float
    density: float
    volume: float
    com: np.ndarray
    inertia: np.ndarray
    frame: np.ndarray
    local_vertices: np.ndarray
    inertia_local: np.ndarray
    h: float
    height: float
    support: np.ndarray
    contact_points: int
    tol: float
    up: object = "z"
    name: str = ""
    repaired: bool = False
    source: str | None = None
    primitive: tuple | None = None
    _hull: list = field(default_factory=list, init=False, repr=False)

    # ------------------------------------------------------------------ constructors
    @classmethod
    def from_arrays(cls, vertices, faces, *, density=None, mass=None, up="z", repair=None,
                    tol=None, weld=None, name="", source=None, settle=False) -> Shape:
        """A shape from vertices (n, 3) in m and triangles (m, 3) (module docstring).

        ``settle=True``: the body, lowered along ``up``, is first settled under gravity
        into its resting pose (:mod:`rocking.shapes.rest`: a quasi-static roll over its
        convex hull); ``up`` becomes that pose's and the support its resting face,
        exactly, with ``tol`` at rounding (no tolerance to choose: ``tol`` must not be
        given).

        Examples
        --------
        The 8 corners and 12 triangles of a 0.4 m x 0.6 m x 2 m box of 960 kg: its
        density is the mass over the volume, 960 / 0.48.

        >>> import trimesh
        >>> from rocking.shapes import Shape
        >>> mesh = trimesh.creation.box(extents=(0.4, 0.6, 2.0))
        >>> box = Shape.from_arrays(mesh.vertices, mesh.faces, mass=960.0)
        >>> round(box.volume, 6), round(box.density, 6), round(box.h, 6)
        (0.48, 2000.0, 1.0)
        """
        notes = []
        v, f = validated(vertices, faces, repair=repair, weld_tol=weld, warn=notes.append)
        for note in notes:
            warn_implausible(note, MeshRepairWarning)
        parts = count_parts(f)
        if parts > 1:
            warn_implausible(f"the mesh has {parts} separate parts, taken as one rigid body "
                             "(a hollow body's inner surface is one of them)")
        props = volume_properties(v, f)
        m, rho = resolve_mass(props["volume"], density, mass)
        com = props["com"]
        if settle:
            if tol is not None:
                raise ParameterError("tol: a settled shape has no contact tolerance to "
                                     "choose (settle=True finds its resting face exactly)")
            up, tol = resting_up(v, com, up), rest_tolerance(v)
        fr = frame(up)
        inertia = props["inertia"] * rho
        z = v @ fr[2]
        zmin = float(z.min())
        height = float(z.max()) - zmin
        size = float(np.ptp(v, axis=0).max())
        check_plausible("size", size, "the mesh's largest extent",
                        shown=f"{size:.4g} m ({height:.4g} m tall along up={up!r})")
        local = np.column_stack([(v - com) @ fr[0], (v - com) @ fr[1], z - zmin])
        tol_m = contact_tolerance(tol, height)
        patch, hull2 = support_hull(local, tol_m)
        margin = inside_margin(hull2, np.zeros(2))
        if not margin > 1e-9 * size_of(v):
            where = (f"{-margin:.3g} m outside the support" if margin < 0.0
                     else "on the support's edge")
            raise ParameterError(f"the centre of mass's vertical falls {where}: the body "
                                 f"cannot stand on its base along up={up!r}; analyse it "
                                 "with model=\"rigid3d\", which settles it into its "
                                 "resting pose with no tol (load it with settle=True)")
        return cls(vertices=v, faces=f, mass=float(m), density=float(rho),
                   volume=props["volume"], com=com, inertia=inertia, frame=fr,
                   local_vertices=local, inertia_local=fr @ inertia @ fr.T,
                   h=float(float(com @ fr[2]) - zmin), height=height, support=hull2,
                   contact_points=int(len(patch)), tol=tol_m, up=up, name=str(name or ""),
                   repaired=bool(notes), source=source)

    @classmethod
    def from_trimesh(cls, mesh, **kwargs) -> Shape:
        """A shape from a :class:`trimesh.Trimesh` (its vertices and faces; keyword
        arguments as :func:`load_shape`).

        Examples
        --------
        The same box standing on its 0.4 m x 2 m face (``up="y"``): 0.6 m tall, its centre
        of mass at mid-height.

        >>> import trimesh
        >>> from rocking.shapes import Shape
        >>> mesh = trimesh.creation.box(extents=(0.4, 0.6, 2.0))
        >>> lying = Shape.from_trimesh(mesh, density=2000.0, up="y")
        >>> round(lying.height, 6), round(lying.h, 6), round(lying.support_area, 6)
        (0.6, 0.3, 0.8)
        """
        return cls.from_arrays(np.asarray(mesh.vertices), np.asarray(mesh.faces), **kwargs)

    @classmethod
    def box(cls, lx, ly, lz, *, density=None, mass=None, name="box") -> Shape:
        """A rectangular box ``lx`` x ``ly`` x ``lz`` (m; ``lz`` vertical) standing on its
        ``lx`` x ``ly`` face, centred on the origin in plan (the 8 corners and 12
        outward triangles; the mass properties follow exactly from them:
        ``I_xx = m (ly^2 + lz^2) / 12``, ...). Exactly one of ``density`` (kg/m^3) and
        ``mass`` (kg).

        Examples
        --------
        >>> from rocking.shapes import Shape
        >>> b = Shape.box(0.4, 0.6, 2.0, mass=960.0)
        >>> round(b.density, 6), round(b.h, 6), b.contact_points, len(b.hull_points())
        (2000.0, 1.0, 4, 8)
        >>> np.round(np.diag(b.inertia_local), 6).tolist()  # m (ly^2 + lz^2) / 12, ...
        [348.8, 332.8, 41.6]
        """
        from .._validate import positive

        a = 0.5 * positive("lx", lx, "m")
        b = 0.5 * positive("ly", ly, "m")
        c = positive("lz", lz, "m")
        v = np.array([[-a, -b, 0.0], [a, -b, 0.0], [a, b, 0.0], [-a, b, 0.0],
                      [-a, -b, c], [a, -b, c], [a, b, c], [-a, b, c]])
        f = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
                      [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]])
        return cls.from_arrays(v, f, density=density, mass=mass, name=name)

    @classmethod
    def cylinder(cls, radius, height, *, density=None, mass=None, segments=64,
                 name="cylinder") -> Shape:
        """A circular cylinder of ``radius`` and ``height`` (m) standing on an end, exact:
        its mass properties are the cylinder's, ``V = pi r^2 H``, ``I_zz = m r^2 / 2``,
        ``I_xx = I_yy = m (3 r^2 + H^2) / 12``, and :mod:`rocking.models.rigid3d` touches
        the ground with its rims' exact lowest points (``primitive = ("cylinder", r, H)``).
        The mesh, the regular prism of ``segments`` sides inscribed in it, is for drawing
        and for the planar analyses (its support is that polygon: within ``1 - cos(pi /
        segments)`` of the circle). Exactly one of ``density`` (kg/m^3) and ``mass`` (kg).

        Examples
        --------
        >>> import math
        >>> from rocking.shapes import Shape
        >>> c = Shape.cylinder(0.3, 1.0, mass=100.0)
        >>> c.primitive, round(c.volume / (math.pi * 0.3**2), 12), round(c.h, 12)
        (('cylinder', 0.3, 1.0), 1.0, 0.5)
        >>> np.round(np.diag(c.inertia_local), 10).tolist()  # m(3r^2+H^2)/12, ..., m r^2/2
        [10.5833333333, 10.5833333333, 4.5]
        """
        import dataclasses

        from .._validate import as_int, positive

        r = positive("radius", radius, "m")
        c = positive("height", height, "m")
        n = as_int("segments", segments, 3, 100000)
        a = 2.0 * np.pi * np.arange(n) / n
        ring = np.column_stack([r * np.cos(a), r * np.sin(a)])
        v = np.vstack([np.column_stack([ring, np.zeros(n)]),
                       np.column_stack([ring, np.full(n, c)]),
                       [[0.0, 0.0, 0.0], [0.0, 0.0, c]]])
        bot, top = 2 * n, 2 * n + 1
        f = []
        for i in range(n):
            j = (i + 1) % n
            f += [[bot, j, i], [top, n + i, n + j], [i, j, n + j], [i, n + j, n + i]]
        prism = cls.from_arrays(v, np.array(f), density=1000.0,
                                 name=name)  # its mass properties are replaced below
        volume = math.pi * r * r * c
        m, rho = resolve_mass(volume, density, mass)
        inertia = np.diag([m * (3 * r * r + c * c) / 12, m * (3 * r * r + c * c) / 12,
                           m * r * r / 2])
        return dataclasses.replace(
            prism, mass=float(m), density=float(rho), volume=volume,
            com=np.array([0.0, 0.0, 0.5 * c]), inertia=inertia,
            inertia_local=prism.frame @ inertia @ prism.frame.T, h=0.5 * c,
            primitive=("cylinder", r, c))

    def __post_init__(self):
        for name in ("vertices", "faces", "com", "inertia", "frame", "local_vertices",
                     "inertia_local", "support"):
            getattr(self, name).setflags(write=False)

    def __repr__(self) -> str:
        return (f"Shape({self.name!r}, mass={self.mass:.6g} kg, volume={self.volume:.6g} m^3, "
                f"height={self.height:.4g} m, h={self.h:.4g} m, {len(self.faces)} triangles"
                f"{', repaired' if self.repaired else ''})")

    # ------------------------------------------------------------------ properties
    @property
    def support_area(self) -> float:
        """The support hull's area (m^2)."""
        x, y = self.support[:, 0], self.support[:, 1]
        return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))

    def describe(self) -> dict:
        """The mass properties and the support as a dict of plain values (SI).

        Examples
        --------
        A box's support is its 0.4 m x 0.6 m base, with its 4 corners:

        >>> import trimesh
        >>> from rocking.shapes import Shape
        >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)),
        ...                          density=2000.0)
        >>> d = box.describe()
        >>> round(d["mass"], 6), round(d["support_area"], 6), d["contact_points"], d["up"]
        (960.0, 0.24, 4, [0.0, 0.0, 1.0])
        """
        return {"name": self.name, "source": self.source, "vertices": int(len(self.vertices)),
                "triangles": int(len(self.faces)), "volume": self.volume, "mass": self.mass,
                "density": self.density, "com": self.com.tolist(),
                "inertia": self.inertia.tolist(), "up": self.frame[2].tolist(),
                "height": self.height, "h": self.h, "support_area": self.support_area,
                "contact_points": self.contact_points, "tol": self.tol,
                "repaired": self.repaired}

    # ------------------------------------------------------------------ per direction
    def parameters(self, direction: float = 0.0) -> dict:
        """The directional parameters of one direction (rad) as a dict of floats (the
        columns of :func:`rocking.shapes.directional_parameters`).

        Examples
        --------
        Along x a 0.4 m x 0.6 m x 2 m box is the 0.4 m x 2 m rectangle: ``alpha =
        atan(0.2 / 1.0)`` and ``r_g^2 = (0.4^2 + 2^2) / 12``.

        >>> import math, trimesh
        >>> from rocking.shapes import Shape
        >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)),
        ...                          density=2000.0)
        >>> q = box.parameters(0.0)
        >>> round(q["alpha_plus"], 4), round(math.atan(0.2), 4), q["weak_side"]
        (0.1974, 0.1974, '+')
        >>> round(q["radius_of_gyration"], 4), round(math.sqrt((0.4**2 + 2**2) / 12), 4)
        (0.5888, 0.5888)
        """
        phi = as_float("direction", direction)
        cols = side_arrays(self.support, self.h, self.inertia_local, self.mass,
                           np.array([phi]), self.hull_points())
        return {k: (v[0].item() if hasattr(v[0], "item") else v[0]) for k, v in cols.items()}

    def inertia_about(self, direction: float = 0.0) -> float:
        """The moment of inertia (kg m^2) about the horizontal axis through the centre of
        mass normal to the plane of shaking of ``direction`` (rad): ``u . I . u``, ``u =
        (-sin phi, cos phi, 0)`` in the frame (the DEM's body inertia).

        Examples
        --------
        A box of mass ``m`` about its centroidal axis along y: ``m (a^2 + c^2) / 12`` with
        ``a`` = 0.4 m (x) and ``c`` = 2 m (height); shaken along y, ``a`` = 0.6 m.

        >>> import math, trimesh
        >>> from rocking.shapes import Shape
        >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)),
        ...                          density=2000.0)
        >>> round(box.inertia_about(0.0), 4), round(960 * (0.4**2 + 2**2) / 12, 4)
        (332.8, 332.8)
        >>> round(box.inertia_about(math.pi / 2), 4), round(960 * (0.6**2 + 2**2) / 12, 4)
        (348.8, 348.8)
        """
        phi = as_float("direction", direction)
        u = np.array([-math.sin(phi), math.cos(phi), 0.0])
        return float(u @ self.inertia_local @ u)

    def hull_points(self) -> np.ndarray:
        """The vertices of the body's 3-D convex hull in the local frame (cached).

        Examples
        --------
        A box's hull is its 8 corners, centred on the centre of mass's vertical, from the
        base (z = 0) to the top:

        >>> import trimesh
        >>> from rocking.shapes import Shape
        >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)),
        ...                          density=2000.0)
        >>> pts = box.hull_points()
        >>> pts.shape, np.abs(pts).max(axis=0).round(6).tolist()
        ((8, 3), [0.2, 0.3, 2.0])
        """
        if not self._hull:
            from scipy.spatial import ConvexHull

            self._hull.append(self.local_vertices[ConvexHull(self.local_vertices).vertices])
        return self._hull[0]

    def polygon(self, direction: float = 0.0) -> np.ndarray:
        """The body's outline for planar (DEM) analysis in the direction ``direction``
        (rad): the convex hull of the vertices projected on the vertical plane of shaking,
        (n, 2) counter-clockwise, ``x`` along ``e_phi`` from the centre of mass's
        vertical, ``z`` up from the base (the contact patch, within ``tol``, is flattened
        onto z = 0). The centre of mass is at ``(0, h)``; the DEM must use the mesh's
        ``mass`` and ``parameters(direction)["radius_of_gyration"]``, not the polygon's
        area and inertia.

        Examples
        --------
        A box's outline along x is its 0.4 m x 2 m side, counter-clockwise from the left
        end of the base:

        >>> import trimesh
        >>> from rocking.shapes import Shape
        >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)),
        ...                          density=2000.0)
        >>> box.polygon(0.0).round(6).tolist()
        [[-0.2, 0.0], [0.2, 0.0], [0.2, 2.0], [-0.2, 2.0]]
        """
        from scipy.spatial import ConvexHull

        phi = as_float("direction", direction)
        pts = self.hull_points()
        x = pts[:, 0] * math.cos(phi) + pts[:, 1] * math.sin(phi)
        z = np.where(pts[:, 2] <= self.tol, 0.0, pts[:, 2])
        p2 = np.column_stack([x, z])
        ring = p2[ConvexHull(p2).vertices]
        # drop the nearly collinear corners (qhull may keep them)
        size = self.height + float(np.ptp(x))
        keep = []
        n = len(ring)
        for i in range(n):
            a, b, c = ring[i - 1], ring[i], ring[(i + 1) % n]
            cr = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
            if cr > 1e-9 * size * size:
                keep.append(i)
        ring = ring[keep]
        start = int(np.argmin(ring[:, 1] * size * 1e3 + ring[:, 0]))  # left end of the base
        return np.roll(ring, -start, axis=0)

    def weakest(self) -> Direction:
        """The exact weakest direction: the normal of the support hull's edge nearest to
        the centre of mass's vertical (where the support function is smallest), as the
        direction whose "+" side tips over that edge.

        Examples
        --------
        A 2 m tall prism on the right triangle (0, 0), (1, 0), (0, 1): the centroid's
        vertical, at (1/3, 1/3), is nearest to the hypotenuse, at ``b = 1 / (3 sqrt 2)``,
        so the weakest direction is normal to it and ``tan(alpha) = b / h`` (``h`` = 1 m).

        >>> import math, trimesh
        >>> from rocking.shapes import Shape
        >>> corners = [(x, y, z) for x, y in ((0, 0), (1, 0), (0, 1)) for z in (0, 2)]
        >>> prism = Shape.from_trimesh(trimesh.Trimesh(corners).convex_hull, density=1000.0)
        >>> d = prism.weakest()
        >>> round(d.phi_deg % 180, 6), d.side  # normal to the hypotenuse
        (45.0, '+')
        >>> round(d.uplift_g, 6), round(1 / (3 * math.sqrt(2)), 6)  # tan(alpha) = b / h
        (0.235702, 0.235702)
        """
        a = self.support
        b = np.roll(a, -1, axis=0)
        edge = b - a
        length = np.hypot(edge[:, 0], edge[:, 1])
        dist = (edge[:, 0] * -a[:, 1] - edge[:, 1] * -a[:, 0]) / length
        i = int(np.argmin(dist))
        normal = np.array([edge[i, 1], -edge[i, 0]]) / length[i]  # outward (ccw ring)
        phi = math.atan2(-normal[1], -normal[0]) % (2.0 * math.pi)
        q = self.parameters(phi)
        return Direction(phi=phi, phi_deg=math.degrees(phi), side="+", alpha=q["alpha_plus"],
                         uplift=q["uplift_plus"], uplift_g=q["uplift_plus"] / G,
                         index=None)


def load_shape(path, *, density=None, mass=None, up="z", repair=None, tol=None,
               units="m", weld=None, name=None, settle=False) -> Shape:
    """Read, weld and validate the mesh in ``path`` (STL, OBJ or PLY) and return its
    :class:`Shape`.

    ``density`` (kg/m^3) or ``mass`` (kg): exactly one. ``up``: the vertical axis ("z",
    "-y", ... or a 3-vector). ``repair="hull"``: use the convex hull of a defective mesh
    (with a :class:`MeshRepairWarning` stating the volume added) instead of refusing it.
    ``tol``: the contact patch's tolerance (m, or "2mm"; default 1e-3 of the height).
    ``units``: the file's length unit ("m", "cm", "mm"). ``weld``: the vertex-merging
    distance (m; default 1e-9 of the bounding box's diagonal). ``settle=True``: settle the
    body, set down along ``up``, under gravity into its resting pose
    (:mod:`rocking.shapes.rest`; its support is then its resting face, exactly, and
    ``tol`` is not given): a scanned body whose base is not flat, a rock on three points.

    Examples
    --------
    >>> import trimesh
    >>> from rocking.shapes import load_shape
    >>> _ = trimesh.creation.box(extents=(0.4, 0.6, 2.0)).export("box.stl")
    >>> box = load_shape("box.stl", density=2000.0)
    >>> round(box.mass, 3), round(box.h, 6)  # 2000 kg/m^3 x 0.48 m^3; h = H/2
    (960.0, 1.0)
    >>> round(load_shape("box.stl", mass=0.001, units="cm").height, 6)  # a 2 cm box, 1 g
    0.02
    """
    import os

    v, f = read_mesh(path, units)
    stem = os.path.splitext(os.path.basename(os.fspath(path)))[0]
    return Shape.from_arrays(v, f, density=density, mass=mass, up=up, repair=repair,
                             tol=tol, weld=weld, name=stem if name is None else name,
                             source=os.fspath(path), settle=settle)


__all__ = ["MeshRepairWarning", "PLAUSIBLE_HEIGHT", "Shape", "load_shape"]
