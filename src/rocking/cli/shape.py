"""``rocking shape``: the rocking parameters of a 3-D mesh (a scan of a statue, a vase) in
every direction of horizontal shaking (:mod:`rocking.shapes`, issue 20).

::

    rocking shape scan.stl --density 2600 [--up z] [--mass 900] [--repair hull]
        [--units mm] [--directions 360] [--every 15] [--out DIR] [--json]

Prints the mass properties (mass, volume, centre of mass, principal moments of inertia
about it), the directional table every ``--every`` degrees (the planar block of each
side: alpha, p, mu, the uplift acceleration ``g tan(alpha)``), and the weakest and the
strongest directions (the side that uplifts first there, its alpha and uplift
acceleration in m/s^2 and g). ``--out DIR`` writes ``directions.csv`` (all
``--directions`` directions, the columns of :func:`rocking.shapes.directional_parameters`),
``polar.png`` (:func:`rocking.shapes.plot_directional`) and ``shape.json`` (what
``--json`` prints). The weakest direction is exact (:meth:`rocking.shapes.Shape.weakest`),
the strongest the best of 3600 directions refined by a bounded search
(:func:`rocking.blocks.factory.resolve_direction`). Bad input (no such file, an open or
inconsistent mesh, ``--density`` with ``--mass`` or neither) is one line ``error: ...``
with exit code 2.
"""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import click
import numpy as np

from ..errors import ParameterError
from ..units import G
from .common import CONTEXT, check_positive, force_option, integer, json_default, number

TEXT_COLUMNS = (("phi_deg", "phi", 1.0, "{:7.1f}"), ("alpha_plus", "alpha+", None, "{:8.3f}"),
                ("alpha_minus", "alpha-", None, "{:8.3f}"), ("p_plus", "p+", 1.0, "{:7.4f}"),
                ("p_minus", "p-", 1.0, "{:7.4f}"), ("mu_plus", "mu+", 1.0, "{:7.4f}"),
                ("mu_minus", "mu-", 1.0, "{:7.4f}"), ("uplift_plus", "up+", 1.0 / G, "{:7.4f}"),
                ("uplift_minus", "up-", 1.0 / G, "{:7.4f}"))
"""The text table's columns: (column, heading, scale (None: rad -> deg), format)."""


def _direction(shape, phi: float) -> dict:
    """One direction's summary: phi, the weaker side, its alpha and uplift acceleration,
    named as everywhere by the ``phi`` whose "+" side is the weaker one
    (:class:`rocking.shapes.Direction`)."""
    q = shape.parameters(phi)
    if q["uplift_minus"] < q["uplift_plus"]:
        phi = (phi + math.pi) % (2.0 * math.pi)
        q = shape.parameters(phi)
    side, key = "+", "plus"
    return {"phi": phi, "phi_deg": math.degrees(phi), "side": side,
            "alpha": q[f"alpha_{key}"], "alpha_deg": math.degrees(q[f"alpha_{key}"]),
            "uplift": q[f"uplift_{key}"], "uplift_g": q[f"uplift_{key}"] / G,
            "alpha_plus": q["alpha_plus"], "alpha_minus": q["alpha_minus"],
            "p_plus": q["p_plus"], "p_minus": q["p_minus"], "mu_plus": q["mu_plus"],
            "mu_minus": q["mu_minus"], "overhang": bool(q["overhang"])}


def shape_summary(shape, directions: int = 360) -> dict:
    """What ``rocking shape`` reports (SI units): the mass properties, the principal
    moments, the weakest and strongest directions, and the table of ``directions``
    directions (``table``: a DataFrame, not JSON)."""
    from ..blocks.factory import resolve_direction
    from ..shapes import directional_parameters

    moments, axes = np.linalg.eigh(np.asarray(shape.inertia))
    table = directional_parameters(shape, directions)
    weak = shape.weakest().phi
    strong = resolve_direction(shape, "strongest")
    return {**shape.describe(), "principal_moments": moments.tolist(),
            "principal_axes": axes.T.tolist(), "weakest": _direction(shape, weak),
            "strongest": _direction(shape, strong), "table": table}


def _lines(s: dict, text_table) -> list[str]:
    com = ", ".join(f"{x:.6g}" for x in s["com"])
    lines = [
        f"mesh             {s['source']}: {s['triangles']} triangles, {s['vertices']} "
        f"vertices{' (convex hull: repaired)' if s['repaired'] else ''}",
        f"mass             {s['mass']:.6g} kg (density {s['density']:.6g} kg/m^3)",
        f"volume           {s['volume']:.6g} m^3",
        f"centre of mass   ({com}) m in the mesh's coordinates; {s['h']:.6g} m above the "
        f"base (height {s['height']:.6g} m)",
        "principal moments " + ", ".join(f"{x:.6g}" for x in s["principal_moments"])
        + " kg m^2 (about the centre of mass)",
        f"support          {s['support_area']:.6g} m^2 ({s['contact_points']} contact "
        f"vertices within {s['tol']:.3g} m of the base)",
        "",
        "directions: phi (deg) from the mesh's x axis, counter-clockwise looking down up; "
        "side + tips towards -phi; alpha (deg), p (1/s), mu, uplift g tan(alpha) (g):",
        " ".join(f"{h:>{len(fmt.format(0.0))}}" for _, h, _, fmt in TEXT_COLUMNS),
    ]
    for _, row in text_table.iterrows():
        cells = []
        for col, _, scale, fmt in TEXT_COLUMNS:
            v = float(row[col])
            cells.append(fmt.format(math.degrees(v) if scale is None else v * scale))
        lines.append(" ".join(cells) + ("  overhang" if bool(row["overhang"]) else ""))
    lines.append("")
    for which in ("weakest", "strongest"):
        d = s[which]
        lines.append(f"{which + ':':10s} phi = {d['phi_deg']:.4f} deg, side {d['side']} "
                     f"(tips towards {(d['phi_deg'] + 180.0) % 360.0:.1f} deg): "
                     f"alpha = {d['alpha']:.10g} rad ({d['alpha_deg']:.4f} deg), uplift "
                     f"{d['uplift']:.6g} m/s^2 = {d['uplift_g']:.6g} g")
    return lines


@dataclasses.dataclass(frozen=True)
class ShapeRequest:
    """``rocking shape``'s options, read and checked (:meth:`from_options`): the mesh file
    and how to read it, the directions and where the results go; :meth:`load` reads the
    shape."""

    path: str
    density: float | None
    mass: float | None
    up: str
    units: str
    repair: str | None
    directions: int
    every: float
    """Step (deg) of the printed table."""
    out: str | None
    as_json: bool

    @classmethod
    def from_options(cls, *, path, density, mass, up, units, repair, directions, every, out,
                     as_json):
        """The request of the command's options (click's values)."""
        rho = check_positive(number(density, "density", ("kg/m^3", "kg/m3")), "density",
                             "kg/m^3")
        m = check_positive(number(mass, "mass", ("kg",)), "mass", "kg")
        if (rho is None) == (m is None):
            raise ParameterError("density or mass: give exactly one (--density RHO in kg/m^3 "
                                 "or --mass M in kg)" + ("" if rho is None else ", not both"))
        n = integer(directions, "directions", lo=1, hi=100_000)
        step = check_positive(number(every, "every", ("deg",)), "every", "deg")
        if not step <= 360.0:
            raise ParameterError(f"every must be in (0, 360] deg, got {every!r}")
        return cls(path=path, density=rho, mass=m, up=up, units=units, repair=repair,
                   directions=n, every=step, out=out, as_json=as_json)

    def load(self):
        """The :class:`rocking.shapes.Shape` of the mesh."""
        from ..shapes import load_shape

        return load_shape(self.path, density=self.density, mass=self.mass, up=self.up,
                          repair=self.repair, units=self.units)


@click.command("shape", context_settings=CONTEXT)
@click.argument("path", metavar="FILE")
@click.option("--density", metavar="RHO", help="Density (kg/m^3); or --mass.")
@click.option("--mass", metavar="M", help="Mass (kg), instead of --density.")
@click.option("--up", default="z", show_default=True, metavar="AXIS",
              help="The mesh's vertical axis: x, y, z, -x, -y, -z.")
@click.option("--units", type=click.Choice(("m", "cm", "mm")), default="m",
              show_default=True, help="Length unit of the mesh file.")
@click.option("--repair", type=click.Choice(("hull",)),
              help="Use the convex hull of an open or inconsistent mesh (with a warning "
                   "stating the volume added).")
@click.option("--directions", default="360", show_default=True, metavar="N",
              help="Directions evenly spaced over 360 deg (the CSV, the plot, --json).")
@click.option("--every", default="15", show_default=True, metavar="DEG",
              help="Step (deg) of the printed table.")
@click.option("--out", type=click.Path(file_okay=False),
              help="Write directions.csv, polar.png and shape.json to this folder.")
@click.option("--json", "as_json", is_flag=True, help="Print JSON (SI units, angles in rad).")
@force_option
def shape_cmd(**options):
    """Mass properties and rocking parameters of a 3-D mesh (STL, OBJ, PLY) in every
    direction of horizontal shaking; the weakest and strongest directions."""
    from ..shapes import directional_parameters

    req = ShapeRequest.from_options(**options)
    shape = req.load()
    s = shape_summary(shape, req.directions)
    table = s.pop("table")
    s["directions"] = table.to_dict(orient="records")
    if req.out is not None:
        _write(req, shape, s, table)
    if req.as_json:
        click.echo(json.dumps(s, indent=1, default=json_default))
        return
    text = directional_parameters(shape, np.radians(np.arange(0.0, 360.0 - 1e-9, req.every)))
    click.echo("\n".join(_lines(s, text)))
    if req.out is not None:
        click.echo(f"\nwrote {Path(req.out) / 'directions.csv'}, polar.png, shape.json")


def _write(req: ShapeRequest, shape, s: dict, table) -> None:
    """OUT: directions.csv, polar.png and shape.json."""
    from ..shapes import plot_directional

    d = Path(req.out)
    d.mkdir(parents=True, exist_ok=True)
    table.to_csv(d / "directions.csv", index=False)
    fig = plot_directional(table, title=f"{shape.name}: {shape.mass:.4g} kg",
                           weakest=shape.weakest())
    fig.savefig(d / "polar.png", dpi=120)
    (d / "shape.json").write_text(json.dumps(s, indent=1, default=json_default))


__all__ = ["shape_cmd", "shape_summary"]
