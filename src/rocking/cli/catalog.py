"""``rocking motions``, ``rocking blocks`` and ``rocking buildings``: the motion kinds of
:mod:`rocking.motions.catalog`, the block forms of :mod:`rocking.blocks.factory` and the
building kinds of :mod:`rocking.buildings.catalog`, with their declared parameters (name,
default, unit, range, help).

::

    rocking motions              # every kind and its parameters
    rocking motions ricker       # one kind
    rocking blocks [FORM] [--json]
    rocking buildings [KIND] [--json]
"""

from __future__ import annotations

import dataclasses
import json

import click

from ..errors import ParameterError
from .common import CONTEXT, describe_table, json_default


def _jsonable(rows: list[dict]) -> list[dict]:
    """Declarations with the Python type as its name (``float``)."""
    return [{**d, "kind": getattr(d.get("kind"), "__name__", str(d.get("kind")))}
            for d in rows]


def motions_dict(name: str | None = None) -> list[dict]:
    """One dict per motion kind (or the kind ``name``): ``name``, ``summary``, ``aliases``,
    ``sweep``, ``parameters``."""
    from ..motions import catalog  # lazy: the motions import numba

    kinds = [catalog.kind(name)] if name is not None else list(catalog.KINDS.values())
    return [{"name": k.name, "summary": k.summary, "aliases": list(k.aliases),
             "sweep": list(k.sweep), "parameters": _jsonable(k.describe())} for k in kinds]


def blocks_dict(name: str | None = None) -> list[dict]:
    """One dict per block form (or the form ``name``): ``name``, ``key``, ``summary``,
    ``keys``."""
    from ..blocks.factory import FORMS

    if name is not None and name not in FORMS:
        raise ParameterError(f"form must be one of {', '.join(FORMS)}; got {name!r}")
    forms = [FORMS[name]] if name is not None else list(FORMS.values())
    return [{"name": f.name, "key": f.key, "summary": f.summary,
             "keys": _jsonable(f.describe())} for f in forms]


def buildings_dict(name: str | None = None) -> list[dict]:
    """One dict per building kind (or the kind ``name``): ``name``, ``summary``, ``keys``."""
    from ..buildings.catalog import KINDS

    if name is not None and name not in KINDS:
        raise ParameterError(f"kind must be one of {', '.join(KINDS)}; got {name!r}")
    kinds = [KINDS[name]] if name is not None else list(KINDS.values())
    return [{"name": k.name, "summary": k.summary, "keys": _jsonable(k.describe())}
            for k in kinds]


def _echo(items: list[dict], as_json: bool, title, rows: str, head: str, footer: str):
    """Print ``items`` as JSON, or as one table each (``title(item)``, ``item[rows]``)
    followed by ``footer``."""
    if as_json:
        click.echo(json.dumps(items, indent=2, default=json_default))
        return
    click.echo("\n\n".join("\n".join([title(i), *describe_table(i[rows], head, unset="-")])
                           for i in items))
    click.echo("\n" + footer)


@dataclasses.dataclass(frozen=True)
class CatalogRequest:
    """The options of ``rocking motions``, ``blocks`` and ``buildings``
    (:meth:`from_options`): the one entry to list (or None: all) and whether to print
    JSON."""

    name: str | None
    """KIND or FORM, as given."""
    as_json: bool

    @classmethod
    def from_options(cls, *, as_json, kind=None, form=None):
        """The request of the command's options (click's values: ``kind`` or ``form``)."""
        return cls(name=form if kind is None else kind, as_json=as_json)


@click.command("motions", context_settings=CONTEXT)
@click.argument("kind", required=False)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def motions_cmd(**options):
    """List the motion kinds and their parameters (or those of KIND)."""
    req = CatalogRequest.from_options(**options)
    _echo(motions_dict(req.name), req.as_json,
          lambda k: f"{k['name']}: {k['summary']}"
          + (f" (old spelling: {', '.join(k['aliases'])})" if k["aliases"] else ""),
          "parameters", "parameter",
          "simulate --motion KIND: --amp is amplitude (for sine and hanning, displacement if "
          "a length: 5mm), --freq frequency, --tp period, --duration duration, --param "
          "KEY=VALUE any parameter; numbers in the unit shown or with a unit (0.3g, 5mm, "
          "2Hz). A campaign spec: [motions] kind = KIND and the parameters by name.")


@click.command("blocks", context_settings=CONTEXT)
@click.argument("form", required=False)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def blocks_cmd(**options):
    """List the block forms and their keys (or those of FORM)."""
    req = CatalogRequest.from_options(**options)
    _echo(blocks_dict(req.name), req.as_json,
          lambda f: f"{f['name']}: {f['summary']} (told by the key {f['key']})", "keys", "key",
          "simulate/params: --specimen N, --width W --height H or --alpha A --p P --mu MU; a "
          "campaign spec: [[blocks]] with the keys by name")


@click.command("buildings", context_settings=CONTEXT)
@click.argument("kind", required=False)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def buildings_cmd(**options):
    """List the building kinds and their keys (or those of KIND)."""
    req = CatalogRequest.from_options(**options)
    _echo(buildings_dict(req.name), req.as_json, lambda k: f"{k['name']}: {k['summary']}", "keys",
          "key",
          "simulate --building KIND: --storeys is storeys, --building-period period, "
          "--building-damping damping_ratio, --building-param KEY=VALUE any key (a list as "
          "JSON: masses=[2,1,1]); --floor K (0 the ground) or --height-ratio X says where "
          "the block stands. A campaign spec: [building] kind = KIND, the keys by name, and "
          'floors = [0, 3] or "all" (or height_ratios).')


__all__ = ["motions_cmd", "blocks_cmd", "buildings_cmd", "motions_dict", "blocks_dict",
           "buildings_dict"]
