"""``rocking dem-params``: the DEM parameters of Table III (Eqs 14-22) for a specimen.

::

    rocking dem-params --specimen 2                 # T and F columns, ours vs printed
    rocking dem-params --specimen 3 --params experimental --json
    rocking dem-params --specimen 2 --calibrate     # + our DEM defaults (runs the DEM)

The command is registered in :mod:`rocking.cli`. Bad input raises
:class:`~rocking.errors.RockingError`; the main entry point prints it as one line
``error: ...``.
"""

from __future__ import annotations

import dataclasses
import json

import click

from ..blocks import paper_data, specimen
from ..units import G
from .common import CONTEXT, specimen_number

COLUMNS = {"theoretical": "T", "experimental": "F"}


def dem_params_dict(n: int, params: str, calibrate: bool = False) -> dict:
    """Table III quantities of specimen ``n`` for a Table II parameter set, with the printed
    values (and our DEM defaults if ``calibrate``)."""
    from ..models import dem as PD  # lazy: the models import numba

    blk = specimen(n, params)
    col = COLUMNS[params]
    pp = PD.paper_parameters(blk)
    t3 = paper_data()["specimens"][str(n)]["table3"]
    d = {"specimen": n, "params": params, "column": col,
         "alpha": pp["alpha"], "p": pp["p"], "mu": pp["mu"], "mass": pp["M"], "R": pp["R"],
         "K": pp["K"], "K1_Mp2": pp["K1"], "K2": pp["K2"], "gamma": pp["gamma"], "b": pp["b"],
         "xi_min": pp["xi_min"], "f_min": pp["f_min"], "width_eq": pp["width_eq"],
         "settlement_if_K_in_N_per_m": pp["settlement"],
         "paper": {"K": float(t3["K"][col]), "xi_min": 1e-3 * float(t3["zeta_e3"][col]),
                   "f_min": float(t3["f_min"][col]), "width_eq": float(t3["width_eq"][col])}}
    if calibrate:
        md = PD.build_assembly(blk)
        K = PD.default_stiffness(md)
        cal = PD.calibrate_damping(blk, full=True)
        d["dem_default"] = {
            "body": md.bodies[0].mode, "stiffness": K,
            "settlement": md.total_mass * G / (2.0 * K),
            "damping_b": cal["b"], "restitution": cal["mu_dem"], "note": cal["note"],
            "time_step": PD.stable_dt(md, K, K, cal["b"])}
    return d


def _lines(d: dict) -> list[str]:
    pa = d["paper"]

    def row(name, ours, paper, fmt, unit=""):
        diff = ("" if paper is None
                else f"   paper {paper:{fmt}}  ({100 * (ours / paper - 1):+.1f} %)")
        return f"{name:<22}{ours:{fmt}} {unit}{diff}"

    out = [f"specimen {d['specimen']}, Table II {d['params']} (Table III column {d['column']}): "
           f"alpha {d['alpha']:g} rad, p {d['p']:g} 1/s, mu {d['mu']:g}, M {d['mass']:g} kg, "
           f"R {d['R']:.4f} m",
           row("K (Eq 17)", d["K"], pa["K"], ".0f", "N/m"),
           row("K1 = M p^2 (Eq 14)", d["K1_Mp2"], None, ".0f", "N/m"),
           row("Gamma = K R (Eq 19)", d["gamma"], None, ".1f", "N"),
           row("b (Eq 20)", d["b"], None, ".3e", "s"),
           row("xi_min (Eq 22)", d["xi_min"], pa["xi_min"], ".3e"),
           row("f_min = p (Eq 21)", d["f_min"], pa["f_min"], ".2f", "Hz"),
           row("2 b_eq (Eq 18)", d["width_eq"], pa["width_eq"], ".4f", "m"),
           f"{'settlement M g/(2K)':<22}{d['settlement_if_K_in_N_per_m']:.3g} m if K were in "
           "N/m per contact point (physical only as MPa/m or MN/m)"]
    if "dem_default" in d:
        dd = d["dem_default"]
        out += [f"{'our DEM: body':<22}{dd['body']}",
                f"{'  stiffness':<22}{dd['stiffness']:.3g} N/m per contact point "
                f"(settlement {dd['settlement']:.2g} m)",
                f"{'  damping b':<22}{dd['damping_b']:.3e} s (restitution "
                f"{dd['restitution']:.4f}: {dd['note']})",
                f"{'  time step':<22}{dd['time_step']:.3g} s"]
    return out


@dataclasses.dataclass(frozen=True)
class DemParamsRequest:
    """``rocking dem-params``'s options, read and checked (:meth:`from_options`): the
    specimen and the Table II parameter sets."""

    specimen: int
    sets: tuple[str, ...]
    """``theoretical`` and/or ``experimental``."""
    calibrate: bool
    as_json: bool

    @classmethod
    def from_options(cls, *, specimen, params_set, calibrate, as_json):
        """The request of the command's options (click's values)."""
        n = specimen_number(specimen)
        sets = ("theoretical", "experimental") if params_set == "both" else (params_set,)
        return cls(specimen=n, sets=sets, calibrate=calibrate, as_json=as_json)


@click.command("dem-params", context_settings=CONTEXT)
@click.option("--specimen", "specimen", required=True, metavar="N", help="Specimen 1-4.")
@click.option("--params", "params_set", type=click.Choice(["theoretical", "experimental",
                                                           "both"]),
              default="both", show_default=True,
              help="Table II parameter set (theoretical = column T, experimental = F).")
@click.option("--calibrate", is_flag=True,
              help="Also give our DEM's default stiffness and calibrated damping "
                   "(runs a few short DEM simulations).")
@click.option("--json", "as_json", is_flag=True, help="Print JSON (SI units).")
def dem_params(**options):
    """Table III: the DEM parameters from the classical ones (Eqs 14-22), ours vs printed."""
    req = DemParamsRequest.from_options(**options)
    ds = [dem_params_dict(req.specimen, s, req.calibrate) for s in req.sets]
    if req.as_json:
        click.echo(json.dumps(ds if len(ds) > 1 else ds[0], indent=2))
        return
    click.echo("\n\n".join("\n".join(_lines(d)) for d in ds))


__all__ = ["dem_params", "dem_params_dict"]
