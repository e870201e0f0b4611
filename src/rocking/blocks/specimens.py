"""The four granite specimens of Peña et al. (2007), Tables I-III, as package data.

``specimen(n, params=...)`` returns a :class:`~rocking.blocks.Block` with the Table I
geometry and mass, and the classical parameters chosen by ``params``:

* ``"theoretical"``: Table II, column T, as printed in the paper;
* ``"experimental"``: Table II, column E (identified from free-rocking tests);
* ``"geometric"``: recomputed by us from the Table I geometry with Eqs 2-4 (the report
  compares this with column T; they differ for specimen 4, whose cut base the paper does
  not fully describe, and slightly for specimen 1).

``shape`` chooses the geometry kept in the block's polygon (:attr:`Block.vertices`, the
contact geometry of the discrete element model): ``"rectangle"`` (Table I, the default) or
``"cut"`` (Table I with the 45 degree cuts of the base corners, 5 mm for specimens 1-3 and
40 mm for specimen 4). With ``params="geometric"`` the classical parameters are those of
that shape (``Block.polygon``); the other parameter sets override them.
"""

from __future__ import annotations

import json
from functools import cache
from importlib import resources

from ..errors import SpecimenError
from .block import Block

#: The parameter sets of :func:`specimen`: Table II column T, column E, or Eqs 2-4.
PARAM_SETS = ("theoretical", "experimental", "geometric")
#: The geometries of :func:`specimen`: Table I's rectangle, or with the cut corners.
SHAPES = ("rectangle", "cut")


@cache
def paper_data() -> dict:
    """The paper's tables (I-V) as a dict, read from ``rocking/blocks/data/pena2007.json``.

    Examples
    --------
    Table I's geometry of specimen 2 and its Table II theoretical alpha, which is Eq 2,
    ``atan(b/h)``, of that geometry to the printed three decimals:

    >>> import math
    >>> from rocking.blocks import paper_data
    >>> s2 = paper_data()["specimens"]["2"]
    >>> s2["width"], s2["height"], s2["theoretical"]["alpha"]
    (0.17, 1.0, 0.168)
    >>> round(math.atan(s2["width"] / s2["height"]), 3)
    0.168
    """
    with resources.files("rocking.blocks").joinpath("data/pena2007.json").open() as f:
        return json.load(f)


def specimen_ids() -> list[int]:
    """Numbers of the catalogued specimens.

    Examples
    --------
    >>> from rocking.blocks import specimen_ids
    >>> specimen_ids()
    [1, 2, 3, 4]
    """
    return sorted(int(k) for k in paper_data()["specimens"])


def specimen(n, params: str = "theoretical", shape: str = "rectangle") -> Block:
    """Specimen ``n`` (1-4) of the paper as a :class:`Block` (see the module docstring).

    Examples
    --------
    Specimen 2 (Table I: 0.17 m x 1.0 m) with the Table II parameters (column T), close
    to ``atan(b/h)`` of its geometry (Eq 2):

    >>> import math
    >>> import rocking
    >>> block = rocking.specimen(2)
    >>> block.width, block.height
    (0.17, 1.0)
    >>> block.alpha, round(math.atan(block.width / block.height), 4)
    (0.168, 0.1684)
    >>> block.mu, rocking.specimen(2, "experimental").mu  # Table II, columns T and E
    (0.958, 0.973)
    """
    ids = specimen_ids()
    try:
        key = int(n)
    except (TypeError, ValueError):
        key = None
    if key not in ids:
        raise SpecimenError(f"specimen must be one of {ids}, got {n!r}")
    if params not in PARAM_SETS:
        raise SpecimenError(f"params must be one of {', '.join(PARAM_SETS)}; got {params!r}")
    if shape not in SHAPES:
        raise SpecimenError(f"shape must be one of {', '.join(SHAPES)}; got {shape!r}")
    d = paper_data()["specimens"][str(key)]
    cut = float(d.get("corner_cut", 0.0)) if shape == "cut" else 0.0
    geo = Block.rectangular(d["width"], d["height"], mass=d["mass"], thickness=d["thickness"],
                            name=f"specimen {key}" + (" (cut)" if cut else ""),
                            corner_cut=cut)
    if params == "geometric":
        return geo
    c = d[params]
    return geo.with_params(alpha=c["alpha"], p=c["p"], mu=c["mu"],
                           name=f"specimen {key} ({params}{', cut' if cut else ''})")
