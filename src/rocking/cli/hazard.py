"""``rocking hazard show FILE``: a hazard curve as read by :class:`~rocking.analysis.HazardCurve`.

::

    rocking hazard show hazard_curve-mean-PGA_22.csv [--site 0 | --site 13.4,42.35] [--json]
    rocking hazard show site.csv [--unit g] [--investigation-time 50]

An OpenQuake engine export (first line a ``#`` comment with ``investigation_time``) is read
with :meth:`HazardCurve.from_openquake`, any other CSV with :meth:`HazardCurve.from_csv`
(IM and annual rate or return period; a probability of exceedance with
``--investigation-time``). Prints the curve's label, IM and unit, the OpenQuake site chosen
(and its distance from ``--site LON,LAT``) and the levels dropped (poe 1 or 0), its points
and the IM exceeded at 475 and 2475 years (rate 1/475, 1/2475). Bad input: one line, exit 2.
"""

from __future__ import annotations

import dataclasses
import json

import click

from ..analysis.hazard import MAX_SITE_DISTANCE_KM, RETURN_PERIODS, HazardCurve
from .common import CONTEXT, json_default, read_hazard_option


def read_curve(path, site=None, unit=None, investigation_time=None,
               max_distance_km=None) -> HazardCurve:
    """The hazard curve in ``path``: an OpenQuake export or a plain CSV (by content)."""
    return read_hazard_option(path, site=site, unit=unit,
                              investigation_time=investigation_time,
                              max_distance_km=max_distance_km)


@click.group("hazard", context_settings=CONTEXT)
def hazard():
    """Seismic hazard curves (OpenQuake exports, CSV of IM and rate or return period)."""


@dataclasses.dataclass(frozen=True)
class HazardShowRequest:
    """``rocking hazard show``'s options, read and checked (:meth:`from_options`): the
    curve read from FILE."""

    file: str
    site: str | None
    """``--site`` as given (for the distance line)."""
    curve: HazardCurve
    as_json: bool

    @classmethod
    def from_options(cls, *, file, site, unit, investigation_time, max_distance_km,
                     as_json):
        """The request of the command's options (click's values)."""
        curve = read_curve(file, site, unit, investigation_time, max_distance_km)
        return cls(file=file, site=site, curve=curve, as_json=as_json)


@hazard.command("show", context_settings=CONTEXT)
@click.argument("file", metavar="FILE")
@click.option("--site", default=None, help="OpenQuake: site index or LON,LAT (nearest).")
@click.option("--unit", default=None, help="CSV: unit of the IM column if its header "
              "states none (g, m/s^2).")
@click.option("--investigation-time", default=None, help="CSV: the years of a "
              "probability-of-exceedance column (poe), read as rate = -ln(1 - poe)/T.")
@click.option("--max-distance-km", type=float, default=None, help="OpenQuake: refuse a "
              f"--site LON,LAT farther than this from every site (default "
              f"{MAX_SITE_DISTANCE_KM:g} km).")
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def show_cmd(**options):
    """The hazard curve in FILE, its IM and unit, and the IM at 475 and 2475 years."""
    req = HazardShowRequest.from_options(**options)
    c, site = req.curve, req.site
    meta = getattr(c, "metadata", {})
    at = {int(T): c.im_at_return_period(T) for T in RETURN_PERIODS}
    outside = {int(T): not (c.rate[-1] <= 1 / T <= c.rate[0]) for T in RETURN_PERIODS}
    if req.as_json:
        click.echo(json.dumps({
            "label": c.label, "im_name": c.im_name, "unit": c.unit,
            "approximate": c.approximate, "im": c.im.tolist(), "rate": c.rate.tolist(),
            "im_at_return_period": {str(k): v for k, v in at.items()},
            "extrapolated": {str(k): v for k, v in outside.items()},
            "metadata": meta,
        }, default=json_default, indent=2))
        return
    click.echo(f"{c.label}")
    click.echo(f"IM: {c.im_name} in {c.unit}; {c.im.size} points"
               + ("; APPROXIMATION (code value)" if c.approximate else ""))
    if "site_index" in meta:
        d = meta.get("site_distance_km")
        click.echo(f"site {meta['site_index']} at (lon {meta['lon']:g}, lat {meta['lat']:g})"
                   + ("" if d is None else f", {d:.3g} km from --site {site}"))
    dropped = meta.get("dropped_levels") or []
    if dropped:
        poes = meta.get("dropped_poe") or [None] * len(dropped)
        items = ", ".join(f"{x:g} (poe {q:g})" if q is not None else f"{x:g}"
                          for x, q in zip(dropped, poes, strict=True))
        click.echo(f"dropped levels ({c.unit}; poe 1 or 0 give no finite non-zero rate): "
                   f"{items}")
    click.echo(f"{'IM (' + c.unit + ')':>14} {'rate (1/yr)':>12} {'T (yr)':>10}")
    for x, r in zip(c.im, c.rate, strict=True):
        click.echo(f"{x:14.4g} {r:12.4g} {1 / r:10.4g}")
    for T, x in at.items():
        note = " (power-law extrapolation beyond the curve)" if outside[T] else ""
        click.echo(f"{T} years (rate {1 / T:.4g}/yr): {c.im_name} = {x:.4g} {c.unit}{note}")
