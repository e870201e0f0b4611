"""The four granite specimens of Peña et al. (2007), Tables I-III, as package data.

``specimen(n, params=...)`` returns a :class:`~rocking.blocks.Block` with the Table I
geometry and mass, and the classical parameters chosen by ``params``:

* ``"theoretical"``: Table II, column T, as printed in the paper;
* ``"experimental"``: Table II, column E (identified from free-rocking tests);
* ``"geometric"``: recomputed by us from the Table I geometry with Eqs 2-4 (the report
  compares this with column T; they differ for specimen 4, whose cut base the paper does
  not fully describe, and slightly for specimen 1).
"""

from __future__ import annotations

import json
from functools import cache
from importlib import resources

from .blocks import Block
from .errors import SpecimenError

PARAM_SETS = ("theoretical", "experimental", "geometric")


@cache
def paper_data() -> dict:
    """The paper's tables (I-V) as a dict, read from ``rocking/data/pena2007.json``."""
    with resources.files("rocking").joinpath("data/pena2007.json").open() as f:
        return json.load(f)


def specimen_ids() -> list[int]:
    """Numbers of the catalogued specimens."""
    return sorted(int(k) for k in paper_data()["specimens"])


def specimen(n, params: str = "theoretical") -> Block:
    """Specimen ``n`` (1-4) of the paper as a :class:`Block`."""
    ids = specimen_ids()
    try:
        key = int(n)
    except (TypeError, ValueError):
        key = None
    if key not in ids:
        raise SpecimenError(f"specimen must be one of {ids}, got {n!r}")
    if params not in PARAM_SETS:
        raise SpecimenError(f"params must be one of {', '.join(PARAM_SETS)}; got {params!r}")
    d = paper_data()["specimens"][str(key)]
    geo = Block.rectangular(d["width"], d["height"], mass=d["mass"], thickness=d["thickness"],
                            name=f"specimen {key}")
    if params == "geometric":
        return geo
    c = d[params]
    return geo.with_params(alpha=c["alpha"], p=c["p"], mu=c["mu"],
                           name=f"specimen {key} ({params})")
