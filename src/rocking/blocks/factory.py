"""The block factory: every block form built from one mapping by one function.

``rocking simulate --specimen 2``, ``--width 0.17 --height 0.75`` and a campaign spec's
``[[blocks]]`` table all go through :func:`make_block`; a form is one entry of
:data:`FORMS`, its keys declared with :func:`rocking.options.option` (SI unit, range,
help; ``rocking blocks`` and the README's spec-key table are made from them)::

    >>> from rocking.blocks.factory import make_block
    >>> make_block({"width": "170mm", "height": 0.75}).alpha
    0.22296...
    >>> make_block({"stack": [{"width": 0.2, "height": 0.4, "mass": 10},
    ...                       {"width": 0.2, "height": 0.4, "mass": 10}]})
    Stack(...)

The form is told by its distinguishing key: ``specimen``, ``width`` (with ``height``),
``alpha`` (with ``p`` and ``mu``), ``vertices`` or ``stack``. Values are SI numbers or
strings with a unit (``"170mm"``, ``"9.6deg"``); ``name`` names the block in tables.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass

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
    BlockForm("stack", "stack", StackForm, _stack,
              "blocks stacked bottom to top (rocking.Stack; the DEM)"),
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


def make_block(mapping: dict, *, name: str | None = None):
    """The :class:`~rocking.Block` (or :class:`~rocking.Stack`) described by ``mapping``
    (see the module docstring); ``name`` (or ``mapping["name"]``) names it.

    Raises :class:`~rocking.errors.ParameterError` naming the key: an unknown key, a
    missing one, or a value out of its range.
    """
    if not isinstance(mapping, dict):
        raise ParameterError(f"block must be a table of keys, got {mapping!r}")
    values = dict(mapping)
    name = values.pop("name", name)
    if name is not None and not isinstance(name, str):
        raise ParameterError(f"name must be a string, got {name!r}")
    form = form_of(values)
    form.Params.unknown(values, f"a {form.name} block")
    block = form.make(form.Params(**values))
    if name:
        return (dataclasses.replace(block, name=name) if isinstance(block, Block)
                else Stack(block.blocks, block.offsets, name=name))
    return block


def table() -> list[dict]:
    """Every form and key, one dict each (``form``, ``name``, ``unit``, ``range``, ...)."""
    return [{"form": f.name, **d, "type": d["kind"]} for f in FORMS.values()
            for d in f.describe()]
