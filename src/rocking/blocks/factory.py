"""The block factory: every block form built from one mapping by one function.

``rocking simulate --specimen 2``, ``--width 0.17 --height 0.75`` and a campaign spec's
``[[blocks]]`` table all go through :func:`make_block`; a form is one entry of
:data:`FORMS`, its keys declared with :func:`rocking.options.option` (SI unit, range,
help; ``rocking blocks`` and the README's spec-key table are made from them)::

    >>> from rocking.blocks.factory import make_block
    >>> make_block({"width": "170mm", "height": 0.75}).alpha
    0.22290...
    >>> make_block({"stack": [{"width": 0.2, "height": 0.4, "mass": 10},
    ...                       {"width": 0.2, "height": 0.4, "mass": 10}]})
    Stack(...)

The form is told by its distinguishing key: ``specimen``, ``width`` (with ``height``),
``alpha`` (with ``p`` and ``mu``), ``vertices``, ``mesh`` or ``stack``. Values are SI numbers
or strings with a unit (``"170mm"``, ``"9.6deg"``); ``name`` names the block in tables.

The ``mesh`` form (issue 20) is the planar block of a 3-D mesh (STL, OBJ, PLY) for one
direction of shaking, through :mod:`rocking.shapes`: its two sides from
:meth:`rocking.Block.from_shape` and, for the DEM, the outline
:meth:`~rocking.shapes.Shape.polygon` with the mesh's true mass and moment of inertia
(:func:`mesh_block`). ``direction`` is in degrees (a bare number; ``"30deg"``,
``"0.5rad"``), ``"weakest"`` or ``"strongest"``; a list gives one block per direction
(:func:`make_blocks`, a campaign spec). With ``plinth_width``, ``plinth_depth`` and
``plinth_height`` the statue stands on a rectangular plinth: a two-block
:class:`~rocking.Stack` for the DEM (:func:`statue_on_plinth`). A relative ``mesh`` path
starts from ``base_dir`` (a campaign spec's folder).
"""

from __future__ import annotations

import dataclasses
import functools
import math
import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import ParameterError
from ..options import REQUIRED, Options, option
from .block import Block
from .specimens import PARAM_SETS, SHAPES, specimen, specimen_ids
from .stack import Stack


def _length(help_: str, required: bool = False):
    return option(REQUIRED, help=help_, unit="m", lo=0.0, quantity="length",
                  required=required)


def _p(help_: str = "frequency parameter (overrides Eq 3)", required: bool = False):
    return option(REQUIRED, help=help_, unit="1/s", lo=0.0, required=required)


def _mu(help_: str = "coefficient of restitution (overrides Eq 4)", required: bool = False):
    return option(REQUIRED, help=help_, lo=0.0, hi=1.0, required=required)


def _mass(help_: str = "mass"):
    return option(REQUIRED, help=help_, unit="kg", lo=0.0)


@dataclass(frozen=True)
class SpecimenForm(Options):
    specimen: int = option(REQUIRED, help="specimen of Pena et al. (2007), Table I", lo=1,
                           hi=len(specimen_ids()), lo_open=False, kind=int, required=True)
    params: str = option("theoretical", help="parameter set (Tables I-III)",
                         choices=PARAM_SETS)
    shape: str = option("rectangle", help="'cut': the measured corner cuts (the DEM)",
                        choices=SHAPES)
    p: float | None = _p("frequency parameter (overrides the specimen's)")
    mu: float | None = _mu("coefficient of restitution (overrides the specimen's)")


@dataclass(frozen=True)
class RectangularForm(Options):
    width: float = _length("full width 2b", required=True)
    height: float = _length("full height 2h", required=True)
    mass: float | None = _mass()
    thickness: float | None = _length("out-of-plane thickness")
    corner_cut: float = option(0.0, help="45-degree cut of both base corners (legs)",
                               unit="m", lo=0.0, lo_open=False, quantity="length")
    p: float | None = _p()
    mu: float | None = _mu()


@dataclass(frozen=True)
class ClassicalForm(Options):
    alpha: float = option(REQUIRED, help="slenderness angle (Eq 2)", unit="rad", lo=0.0,
                          hi=1.5707963267948966, hi_open=True, quantity="angle",
                          required=True)
    p: float = _p("frequency parameter (Eq 3)", required=True)
    mu: float = _mu("coefficient of restitution (Eq 4)", required=True)


@dataclass(frozen=True)
class PolygonForm(Options):
    vertices: tuple = option(REQUIRED, help="[[x, y], ...] in m, standing on its lowest "
                             "edge (rocking.Block.polygon)", kind=object, required=True)
    mass: float | None = _mass()
    density: float | None = option(REQUIRED, help="density (mass = density x area x "
                                   "thickness)", unit="kg/m^3", lo=0.0)
    thickness: float | None = _length("out-of-plane thickness (default 1 m)")
    mu: float | None = _mu("coefficient of restitution (default: generalised Eq 4)")


@dataclass(frozen=True)
class StackForm(Options):
    stack: tuple = option(REQUIRED, help="the blocks bottom to top, one table each (any "
                          "form but stack; the DEM)", kind=object, required=True)
    offsets: tuple | None = option(REQUIRED, help="horizontal offset of each block (m)",
                                   kind=object)


MESH_UNITS = ("m", "cm", "mm")
"""Length units of a mesh file (:func:`rocking.shapes.load_shape`)."""


@dataclass(frozen=True)
class MeshForm(Options):
    mesh: str = option(REQUIRED, help="3-D mesh file (STL, OBJ, PLY; relative to the spec "
                       "in a campaign): rocking.shapes", kind=str, required=True)
    density: float | None = option(REQUIRED, help="density (give density or mass)",
                                   unit="kg/m^3", lo=0.0)
    mass: float | None = _mass("mass (instead of density)")
    direction: object = option(0.0, help="direction of shaking from the mesh's x axis, "
                               "counter-clockwise looking down up (a number in deg, '30deg', "
                               "'weakest', 'strongest'; a list in a campaign: one block per "
                               "direction)", unit="deg", kind=object)
    up: str = option("z", help="the mesh's vertical axis (x, y, z, -x, -y, -z)", kind=str)
    units: str = option("m", help="length unit of the mesh file", choices=MESH_UNITS)
    repair: str | None = option(REQUIRED, help="'hull': the convex hull of an open or "
                                "inconsistent mesh (default: refused)", choices=("hull",))
    mu: float | None = _mu("coefficient of restitution of both sides (default: angular "
                           "momentum about the new pivot)")
    plinth_width: float | None = _length("plinth: size along the mesh's x axis (with "
                                         "plinth_depth and plinth_height: a stack, the DEM)")
    plinth_depth: float | None = _length("plinth: size along the mesh's y axis")
    plinth_height: float | None = _length("plinth: height")
    plinth_density: float | None = option(REQUIRED, help="plinth: density (or plinth_mass)",
                                          unit="kg/m^3", lo=0.0)
    plinth_mass: float | None = _mass("plinth: mass (instead of plinth_density)")

    def check(self):
        if (self.density is None) == (self.mass is None):
            raise ParameterError("density or mass: give exactly one (density in kg/m^3 or "
                                 "mass in kg) of the mesh block"
                                 + ("" if self.density is None else ", not both"))
        mesh_directions(self.direction)
        sizes = (self.plinth_width, self.plinth_depth, self.plinth_height)
        given = [k for k, v in zip(("plinth_width", "plinth_depth", "plinth_height"), sizes,
                                   strict=True) if v is not None]
        if given and len(given) < 3:
            missing = sorted({"plinth_width", "plinth_depth", "plinth_height"} - set(given))
            raise ParameterError(f"{missing[0]} is required with {given[0]} (a plinth "
                                 "needs plinth_width, plinth_depth and plinth_height)")
        rho_m = (self.plinth_density, self.plinth_mass)
        if given and (rho_m[0] is None) == (rho_m[1] is None):
            raise ParameterError("plinth_density or plinth_mass: give exactly one with a "
                                 "plinth")
        if not given and any(v is not None for v in rho_m):
            raise ParameterError("plinth_density or plinth_mass applies with plinth_width, "
                                 "plinth_depth and plinth_height only")


def _sizes(key: str, value, n: int, what: str) -> tuple:
    """``value`` as ``n`` positive lengths (m; numbers, or strings with a unit such as
    ``"40cm"``)."""
    from ..units import parse_quantity

    if not isinstance(value, list | tuple) or len(value) != n:
        raise ParameterError(f"{key} must be a list of {n} lengths [{what}] (m, or strings "
                             f"with a unit such as '40cm'), got {value!r}")
    out = []
    for i, v in enumerate(value):
        if isinstance(v, bool):
            raise ParameterError(f"{key}[{i}] must be a length, got {v!r}")
        x = parse_quantity(v, "length", name=f"{key}[{i}]", default_unit="m")
        if not (x > 0.0 and math.isfinite(x)):
            raise ParameterError(f"{key}[{i}] must be > 0 m, got {v!r}")
        out.append(float(x))
    return tuple(out)


def _density_or_mass(density, mass) -> dict:
    if density is not None and mass is not None:
        raise ParameterError("density or mass: give one (density in kg/m^3 or mass in kg), "
                             "not both")
    return {"mass": mass} if mass is not None else {"density": density or DEFAULT_DENSITY}


DEFAULT_DENSITY = 1000.0
"""Density (kg/m^3) of a ``box`` or ``cylinder`` body given neither density nor mass: the
motion of a rigid body on a rigid ground does not depend on its mass (every force scales
with it), only its reported mass does."""


@dataclass(frozen=True)
class BoxForm(Options):
    box: tuple = option(REQUIRED, help="[lx, ly, lz]: a rectangular box (m) standing on its lx "
                        "x ly face, lz vertical; a 3-D body (rocking.shapes.Shape.box, model "
                        "rigid3d)", kind=object, required=True)
    density: float | None = option(REQUIRED, help="density (or mass; default 1000 kg/m^3: "
                                   "the motion does not depend on it)", unit="kg/m^3", lo=0.0)
    mass: float | None = _mass("mass (instead of density)")

    def check(self):
        _sizes("box", self.box, 3, "lx, ly, lz")
        _density_or_mass(self.density, self.mass)


@dataclass(frozen=True)
class CylinderForm(Options):
    cylinder: tuple = option(REQUIRED, help="[radius, height]: a circular cylinder (m) "
                             "standing on an end; a 3-D body (rocking.shapes.Shape.cylinder, "
                             "model rigid3d)", kind=object, required=True)
    density: float | None = option(REQUIRED, help="density (or mass; default 1000 kg/m^3: "
                                   "the motion does not depend on it)", unit="kg/m^3", lo=0.0)
    mass: float | None = _mass("mass (instead of density)")

    def check(self):
        _sizes("cylinder", self.cylinder, 2, "radius, height")
        _density_or_mass(self.density, self.mass)


def _box(f: BoxForm):
    from ..shapes import Shape  # lazy: trimesh

    lx, ly, lz = _sizes("box", f.box, 3, "lx, ly, lz")
    return Shape.box(lx, ly, lz, name=f"{lx:g} x {ly:g} x {lz:g} m box",
                     **_density_or_mass(f.density, f.mass))


def _cylinder(f: CylinderForm):
    from ..shapes import Shape  # lazy: trimesh

    r, h = _sizes("cylinder", f.cylinder, 2, "radius, height")
    return Shape.cylinder(r, h, name=f"cylinder r {r:g} x {h:g} m",
                          **_density_or_mass(f.density, f.mass))


def mesh_direction(value):
    """One ``direction`` of a mesh block (:func:`rocking.shapes.parse_direction`: an angle
    in rad from a number in degrees or a string with its unit, or ``"weakest"`` /
    ``"strongest"``)."""
    from ..shapes import parse_direction

    return parse_direction(value)


def mesh_directions(value) -> list:
    """``direction`` as a list (:func:`mesh_direction` of each item; a list must not be
    empty)."""
    if isinstance(value, list | tuple):
        if not value:
            raise ParameterError("direction must be an angle, 'weakest', 'strongest' or a "
                                 "non-empty list of them; got []")
        return [mesh_direction(v) for v in value]
    return [mesh_direction(value)]


@functools.lru_cache(maxsize=16)
def _load(path: str, stamp: tuple, density, mass, up, units, repair, settle=False):
    from .. import shapes  # lazy: trimesh

    return shapes.load_shape(path, density=density, mass=mass, up=up, repair=repair,
                             units=units, settle=settle)


def load_mesh(f: MeshForm, *, settle: bool = False):
    """The :class:`rocking.shapes.Shape` of a mesh form (cached per file content stamp);
    ``settle=True``: settled into its resting pose (:func:`rocking.shapes.load_shape`)."""
    path = os.path.abspath(os.fspath(f.mesh))
    try:
        st = os.stat(path)
        stamp = (st.st_mtime_ns, st.st_size)
    except OSError:
        stamp = ()
    return _load(path, stamp, f.density, f.mass, f.up, f.units, f.repair, settle)


def load_body(f: MeshForm):
    """The 3-D body of a mesh form for ``rigid3d`` (:func:`make_body`): the mesh on its
    declared base (``up``) where its centre of mass's vertical falls inside that base's
    patch (the model then settles it exactly, warning where it rolls onto another face:
    :func:`rocking.models.rigid3d.settled_body`); a mesh with no such base (a scanned rock
    on three points, whose lowest vertex alone is within the planar tolerance) settled
    under gravity from ``up`` into its resting pose (``settle=True``): no tolerance to
    choose either way, as issue 30 asks."""
    try:
        return load_mesh(f)
    except ParameterError:
        return load_mesh(f, settle=True)  # a bad file or mass is refused again here


def resolve_direction(shape, direction) -> float:
    """The angle (rad) of one :func:`mesh_direction` for ``shape``
    (:func:`rocking.shapes.resolve_direction`)."""
    from ..shapes import resolve_direction as resolve

    return resolve(shape, direction)


def direction_label(direction, phi: float) -> str:
    """``30 deg`` for an angle, ``weakest (254.4 deg)`` for a named direction."""
    deg = math.degrees(phi)
    if isinstance(direction, str):
        return f"{direction} ({deg:.1f} deg)"
    return f"{round(deg, 9):g} deg"


def mesh_block(shape, direction: float, *, name: str | None = None, mu=None) -> Block:
    """The planar block of ``shape`` (:class:`rocking.shapes.Shape`) for shaking along
    ``direction`` (rad) with its outline: :meth:`rocking.Block.from_shape` (both sides, the
    mesh's mass, ``I_O = m (r_g^2 + R^2)`` of the weaker side, the outline
    :meth:`~rocking.shapes.Shape.polygon` as :attr:`~rocking.Block.vertices`), so that the
    DEM (geometry ``"body"``, :func:`rocking.models.dem.body_of`) rocks the outline with
    the mesh's true mass, centre of mass and moment of inertia
    (:meth:`~rocking.shapes.Shape.inertia_about`), not the polygon's."""
    return Block.from_shape(shape, direction, name=name, mu=mu)


def plinth_shape(width: float, depth: float, height: float, *, density=None, mass=None):
    """A rectangular plinth as a :class:`rocking.shapes.Shape` (a box mesh: ``width``
    along x, ``depth`` along y, ``height`` along z, m)."""
    import trimesh

    from .. import shapes

    box = trimesh.creation.box(extents=(width, depth, height))
    return shapes.Shape.from_trimesh(box, density=density, mass=mass, name="plinth")


def statue_on_plinth(shape, direction: float, plinth, *, name: str | None = None,
                     mu=None) -> Stack:
    """``shape`` (the statue, :class:`rocking.shapes.Shape`) standing on ``plinth`` (a
    box, :func:`plinth_shape`, in the statue's horizontal frame) with its centre of mass
    over the plinth's centre, for shaking along ``direction`` (rad): a two-block
    :class:`~rocking.Stack` for the DEM, each block the :func:`mesh_block` of its body
    (true mass and inertia). The statue's support must lie on the plinth's top face. The
    plinth's own restitution is not used by the DEM (its contact damping follows the top
    block's); a squat plinth, for which the angular-momentum restitution is not positive,
    gets a nominal 1."""
    half = 0.5 * np.ptp(plinth.support, axis=0)
    sup = np.asarray(shape.support)
    if np.any(np.abs(sup) > half[None, :] * (1.0 + 1e-9)):
        ext = np.abs(sup).max(axis=0)
        raise ParameterError(
            f"plinth_width or plinth_depth: the statue's base reaches {ext[0]:.4g} m along "
            f"x and {ext[1]:.4g} m along y from its centre of mass, beyond the plinth's "
            f"half-sizes {half[0]:.4g} x {half[1]:.4g} m")
    q = plinth.parameters(direction)
    squat = min(q["mu_plus"], q["mu_minus"]) <= 0.0
    base = mesh_block(plinth, direction, name="plinth", mu=1.0 if squat else None)
    top = mesh_block(shape, direction, name=name, mu=mu)
    p = shape.parameters(direction)
    offset = 0.5 * (p["b_minus"] - p["b_plus"])  # the centre of mass over the plinth's axis
    return Stack([base, top], offsets=(0.0, offset),
                 name=f"{top.name} on a plinth")


def _mesh(f: MeshForm, direction=None) -> Block | Stack:
    shape = load_mesh(f)
    dirs = mesh_directions(f.direction if direction is None else direction)
    if len(dirs) != 1:
        raise ParameterError("direction: a list gives one block per direction (a campaign "
                             "spec, or rocking.blocks.factory.make_blocks); give one here")
    phi = resolve_direction(shape, dirs[0])
    label = f"{shape.name or 'mesh'} @ {direction_label(dirs[0], phi)}"
    if f.plinth_width is None:
        return mesh_block(shape, phi, name=label, mu=f.mu)
    plinth = plinth_shape(f.plinth_width, f.plinth_depth, f.plinth_height,
                          density=f.plinth_density, mass=f.plinth_mass)
    return statue_on_plinth(shape, phi, plinth, name=label, mu=f.mu)


def _specimen(f: SpecimenForm) -> Block:
    b = specimen(f.specimen, f.params, shape=f.shape)
    changes = {k: v for k, v in (("p", f.p), ("mu", f.mu)) if v is not None}
    return b.with_params(**changes) if changes else b


def _rectangular(f: RectangularForm) -> Block:
    return Block.rectangular(f.width, f.height, mass=f.mass, thickness=f.thickness,
                             mu=f.mu, p=f.p, corner_cut=f.corner_cut,
                             name=f"{f.width:g} x {f.height:g} m block")


def _classical(f: ClassicalForm) -> Block:
    return Block.from_params(f.alpha, f.p, f.mu,
                             name=f"alpha {f.alpha:.4g} rad, p {f.p:.4g} 1/s block")


def _polygon(f: PolygonForm) -> Block:
    v = f.vertices
    if not isinstance(v, list | tuple) or not all(isinstance(x, list | tuple) for x in v):
        raise ParameterError(f"vertices must be a list of [x, y] pairs (m), got {v!r}")
    return Block.polygon([tuple(x) for x in v], mass=f.mass, density=f.density,
                         thickness=f.thickness, mu=f.mu, name=f"{len(v)}-vertex polygon block")


def _stack(f: StackForm) -> Stack:
    if not isinstance(f.stack, list | tuple) or len(f.stack) < 1:
        raise ParameterError("stack must be a list of one or more block tables")
    blocks = []
    for i, t in enumerate(f.stack):
        if not isinstance(t, dict) or "stack" in t:
            raise ParameterError(f"stack[{i}] must be a block table (not a stack), got {t!r}")
        try:
            blocks.append(make_block(t))
        except ParameterError as e:
            raise ParameterError(f"stack[{i}].{e}") from None
    return Stack(blocks, offsets=f.offsets, name=f"stack of {len(blocks)} blocks")


@dataclass(frozen=True)
class BlockForm:
    """One block form: the key that tells it, its declared keys, and the constructor."""

    name: str
    key: str
    Params: type[Options]
    make: Callable
    summary: str
    paths: tuple = ()
    """Keys that name files (relative to ``base_dir`` in :func:`make_block`)."""
    several: str | None = None
    """The key whose list gives several blocks (:func:`make_blocks`)."""

    def describe(self) -> list[dict]:
        return self.Params.describe()


FORMS: dict[str, BlockForm] = {f.name: f for f in (
    BlockForm("specimen", "specimen", SpecimenForm, _specimen,
              "a specimen of the paper (rocking.specimen)"),
    BlockForm("rectangular", "width", RectangularForm, _rectangular,
              "a rectangle from its size (rocking.Block.rectangular, Eqs 2-4)"),
    BlockForm("classical", "alpha", ClassicalForm, _classical,
              "the classical parameters (rocking.Block.from_params)"),
    BlockForm("polygon", "vertices", PolygonForm, _polygon,
              "a convex polygon (rocking.Block.polygon)"),
    BlockForm("mesh", "mesh", MeshForm, _mesh,
              "the planar block of a 3-D mesh in one direction of shaking (rocking.shapes; "
              "with a plinth: a stack)", paths=("mesh",), several="direction"),
    BlockForm("stack", "stack", StackForm, _stack,
              "blocks stacked bottom to top (rocking.Stack; the DEM)"),
    BlockForm("box", "box", BoxForm, _box,
              "a 3-D rectangular box (rocking.shapes.Shape.box; model rigid3d)"),
    BlockForm("cylinder", "cylinder", CylinderForm, _cylinder,
              "a 3-D circular cylinder (rocking.shapes.Shape.cylinder; model rigid3d)"),
)}
"""The block forms by name."""


def form_of(mapping: dict) -> BlockForm:
    """The form that ``mapping`` describes (by its distinguishing key)."""
    forms = [f for f in FORMS.values()
             if f.key in mapping or (f.key == "width" and "height" in mapping)]
    if len(forms) != 1:
        keys = ", ".join(sorted(mapping)) or "none"
        what = "; ".join(f"{f.key} ({f.name})" for f in FORMS.values())
        raise ParameterError(f"block: give exactly one of {what}; got keys {keys}")
    return forms[0]


def renamed(block, name: str):
    """``block`` (a Block, a Stack or a 3-D :class:`~rocking.shapes.Shape`) with the name
    ``name``."""
    if isinstance(block, Stack):
        return Stack(block.blocks, block.offsets, name=name)
    return dataclasses.replace(block, name=name)


def _prepared(mapping: dict, name, base_dir) -> tuple:
    """``(form, values, name)`` of ``mapping``: the form, its keys (file paths resolved
    against ``base_dir``) and the name."""
    if not isinstance(mapping, dict):
        raise ParameterError(f"block must be a table of keys, got {mapping!r}")
    values = dict(mapping)
    name = values.pop("name", name)
    if name is not None and not isinstance(name, str):
        raise ParameterError(f"name must be a string, got {name!r}")
    form = form_of(values)
    form.Params.unknown(values, f"a {form.name} block")
    for key in form.paths:
        v = values.get(key)
        if v is not None and not isinstance(v, str | os.PathLike):
            raise ParameterError(f"{key} must be a file path, got {type(v).__name__} {v!r}")
        if v is not None and base_dir is not None and not Path(v).is_absolute():
            values[key] = str(Path(base_dir) / v)
    return form, values, name


def make_block(mapping: dict, *, name: str | None = None, base_dir=None):
    """The :class:`~rocking.Block` (or :class:`~rocking.Stack`) described by ``mapping``
    (see the module docstring); ``name`` (or ``mapping["name"]``) names it; relative file
    paths (``mesh``) start from ``base_dir`` (default: the working directory).

    Raises :class:`~rocking.errors.ParameterError` naming the key: an unknown key, a
    missing one, or a value out of its range.
    """
    form, values, name = _prepared(mapping, name, base_dir)
    block = form.make(form.Params(**values))
    return renamed(block, name) if name else block


def make_blocks(mapping: dict, *, name: str | None = None, base_dir=None) -> list:
    """The blocks described by ``mapping``: one (:func:`make_block`), or one per item of
    the list of its form's ``several`` key (a mesh's ``direction = [0, 45, "weakest"]``),
    each named ``"<name> @ <direction>"`` (``statue @ 30 deg``)."""
    form, values, name = _prepared(mapping, name, base_dir)
    key = form.several
    if key is None or not isinstance(values.get(key), list | tuple):
        block = form.make(form.Params(**values))
        return [renamed(block, name) if name else block]
    params = form.Params(**values)  # every item checked before any block is built
    out = []
    for item in values[key]:
        block = form.make(params, item)
        if name:
            block = renamed(block, f"{name} @ {block.name.partition(' @ ')[2]}")
        out.append(block)
    return unique_names(out)


def unique_names(blocks: list) -> list:
    """``blocks`` with names made unique: a name already taken, by another block or by a
    direction that prints alike (``direction = [0, 0]``), gets ``#2``, ``#3`` ...

    Examples
    --------
    >>> from rocking.blocks.factory import make_blocks
    >>> from rocking.shapes.example import example_mesh_path
    >>> [b.name for b in make_blocks({"mesh": str(example_mesh_path()), "density": 2600,
    ...                              "direction": [0, 0]},
    ...                              name="statue")]
    ['statue @ 0 deg', 'statue @ 0 deg #2']
    """
    taken = {b.name.strip() for b in blocks}
    seen, out = set(), []
    for b in blocks:
        name = b.name
        if name.strip() in seen:
            k = 2
            while f"{name} #{k}".strip() in seen or f"{name} #{k}".strip() in taken:
                k += 1
            b = renamed(b, f"{name} #{k}")
        seen.add(b.name.strip())
        out.append(b)
    return out


def table() -> list[dict]:
    """Every form and key, one dict each (``form``, ``name``, ``unit``, ``range``, ...)."""
    return [{"form": f.name, **d, "type": d["kind"]} for f in FORMS.values()
            for d in f.describe()]


BODY_FORMS = ("box", "cylinder", "mesh", "rectangular", "specimen")
"""The forms that describe a 3-D body (:func:`make_body`)."""
PLANAR_MESH_KEYS = ("direction", "mu", "plinth_width", "plinth_depth", "plinth_height",
                    "plinth_density", "plinth_mass")
"""Keys of the ``mesh`` form that make its planar block, not the 3-D body."""


def make_body(mapping: dict, *, name: str | None = None, base_dir=None):
    """The 3-D body (:class:`rocking.shapes.Shape`) described by ``mapping``, for a 3-D
    model (``rigid3d``): ``box = [lx, ly, lz]``, ``cylinder = [radius, height]``, a
    ``mesh`` (the whole mesh: its mass properties, contact on its hull; one with no flat
    base, a rock on three points, settled into its resting pose: :func:`load_body`), or a
    rectangular block (``width``, ``height``, ``thickness``: the box ``width`` x
    ``thickness`` (its width if not given) x ``height``) or a ``specimen`` (its box).
    ``density`` or ``mass`` (a box or cylinder without either: :data:`DEFAULT_DENSITY`).
    A mesh's planar keys (``direction``, ``mu``, a plinth) are refused: a 3-D model takes
    the direction of a single horizontal motion as its option ``direction``.

    Examples
    --------
    >>> from rocking.blocks.factory import make_body
    >>> body = make_body({"box": [0.4, "30cm", 1.2], "mass": 144.0})
    >>> body.name, round(body.h, 6), round(body.density, 6)
    ('0.4 x 0.3 x 1.2 m box', 0.6, 1000.0)
    """
    form, values, name = _prepared(mapping, name, base_dir)
    if form.name not in BODY_FORMS:
        raise ParameterError(f"{form.key}: a 3-D body (model rigid3d) needs its shape: give "
                             "box = [lx, ly, lz], cylinder = [radius, height], mesh, width "
                             f"and height, or specimen (not the {form.name} form)")
    if form.name == "mesh":
        planar = [k for k in PLANAR_MESH_KEYS if k in values]
        if planar:
            raise ParameterError(
                f"{planar[0]}: a key of the mesh's planar block; a 3-D model (rigid3d) "
                "takes the whole mesh (set where a single horizontal motion acts with its "
                "option direction, deg, and a pair's orientation with heading)")
        body = load_body(form.Params(**values))
    elif form.name in ("box", "cylinder"):
        body = form.make(form.Params(**values))
    else:
        from ..shapes import Shape  # lazy: trimesh

        for k in ("p", "mu", "corner_cut", "shape"):
            if values.get(k) not in (None, 0, 0.0, "rectangle"):
                raise ParameterError(f"{k}: a planar block's key; a 3-D body (rigid3d) "
                                     "takes its shape, mass and inertia from its geometry "
                                     "(a corner cut: give a mesh)")
        block = form.make(form.Params(**values))
        if block.width is None or block.height is None:
            raise ParameterError(f"{form.key}: this block has no rectangular size for a 3-D "
                                 "body; give box = [lx, ly, lz]")
        depth = block.thickness if block.thickness is not None else block.width
        kw = {"mass": block.mass} if block.mass else {"density": DEFAULT_DENSITY}
        body = Shape.box(block.width, depth, block.height, name=block.name or "box", **kw)
    return renamed(body, name) if name else body
