"""``rocking params``: the classical parameters alpha, p, mu, R of a block (Eqs 2-4).

::

    rocking params --specimen 2 [--params theoretical|experimental|geometric] [--json]
    rocking params --width 0.17 --height 1.0 [--mass 228] [--json]
"""

from __future__ import annotations

import dataclasses
import json
import math

import click

from ..units import G
from .common import CONTEXT, block_options, make_block


def block_lines(block) -> list[str]:
    """The parameters of ``block`` as text lines."""
    lines = []
    if block.name:
        lines.append(f"block           {block.name}")
    lines += [
        f"alpha           {block.alpha:.6g} rad = {math.degrees(block.alpha):.4g} deg",
        f"p               {block.p:.6g} 1/s",
        f"mu              {block.mu:.6g}",
    ]
    if block.R is not None:
        lines.append(f"R               {block.R:.6g} m")
    if block.width is not None:
        lines.append(f"width x height  {block.width:g} m x {block.height:g} m")
    if block.mass is not None:
        lines.append(f"mass            {block.mass:g} kg")
    if block.I_O is not None:
        lines.append(f"I_O             {block.I_O:.6g} kg m^2")
    ua = block.uplift_acceleration
    lines.append(f"uplift g tan(a)  {ua:.6g} m/s^2 = {ua / G:.4g} g")
    return lines


@dataclasses.dataclass(frozen=True)
class ParamsRequest:
    """``rocking params``'s options, read and checked (:meth:`from_options`): the block."""

    block: object
    block_info: dict
    """How the block was given (``specimen``, ``params``, ...: :func:`make_block`)."""
    as_json: bool

    @classmethod
    def from_options(cls, *, specimen, params_set, width, height, mass, as_json):
        """The request of the command's options (click's values)."""
        block, info = make_block(specimen, params_set, width, height, mass)
        return cls(block=block, block_info=info, as_json=as_json)


@click.command("params", context_settings=CONTEXT)
@block_options(mass=True)
@click.option("--json", "as_json", is_flag=True, help="Print a JSON object (SI units).")
def params_cmd(**options):
    """Classical parameters alpha, p, mu, R of a block (Eqs 2-4)."""
    req = ParamsRequest.from_options(**options)
    block, info = req.block, req.block_info
    if req.as_json:
        d = {k: (None if v is None else float(v)) for k, v in block.params().items()}
        d.update(
            alpha_deg=math.degrees(block.alpha),
            uplift_acceleration=block.uplift_acceleration,
            uplift_acceleration_g=block.uplift_acceleration / G,
            width=block.width, height=block.height, mass=block.mass, I_O=block.I_O,
            name=block.name,
        )
        d.update({k: v for k, v in info.items() if k in ("specimen", "params")})
        click.echo(json.dumps(d, indent=2))
    else:
        click.echo("\n".join(block_lines(block)))


__all__ = ["params_cmd", "block_lines"]
