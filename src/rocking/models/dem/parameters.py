r"""Parameters of the discrete element model from the classical theory (Peña et al. 2007,
Section 4.2-4.4, Eqs 14-22, Table III), and our calibration of the contact damping.

**The paper's recipe** (:func:`paper_parameters`), for a block of mass ``M`` with the
classical parameters ``alpha``, ``p``, ``mu``:

* stiffness, Eq 16/17: ``K = (M/2) (p^2 + W R / I)`` with ``W = M g``; for a rectangle
  (``I = 4/3 M R^2``) ``K = (M/2) (p^2 + 3 g / 4R)`` (Eq 17), the mean of ``K_1 = M p^2``
  (Eq 14) and ``K_2 = M W R / I`` (Eq 15);
* generalised damping factor, Eq 19: ``Gamma = K R = (M/2)(R p^2 + 3g/4)``;
* stiffness-proportional damping, Eq 20 (an empirical fit on the four specimens):
  ``sqrt(b) = 0.0057 ln(Gamma / mu^2) - 0.0336``;
* ``f_min = p`` (Eq 21) and ``xi_min = 2 pi b f_min`` (Eq 22), the UDEC input pair;
* equivalent base, Eq 18: ``b_eq = h tan(alpha)``, a rectangle of width ``2 b_eq``.

**Units of K.** Eq 17 is dimensionally a stiffness (kg/s^2 = N/m), numerically ``M p^2``:
3302 for specimen 2. Read as the stiffness of a contact point in N/m, it would let the
block sink by ``M g / (2 K) = 0.34 m`` under its own weight (two contact points), which is
not rocking; the number makes sense only as a joint stiffness of UDEC (stress per unit
displacement) in MPa/m (settlement 8 µm over the base of specimen 2) or as a point
stiffness in MN/m (0.3 µm). :func:`settlement_table` lists every reading;
:mod:`rocking.models.dem` uses a physical default (settlement 1e-7 of the height).

The calibration of the damping that replaces Eq 20 is in
:mod:`rocking.models.dem.calibration`.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from ..._validate import as_float, positive
from ...blocks import Block, paper_data, specimen, specimen_ids
from ...errors import ParameterError
from ...units import G

if TYPE_CHECKING:
    import pandas as pd

EQ20 = (0.0057, -0.0336)
"""Coefficients of Eq 20: ``sqrt(b) = c1 ln(Gamma / mu^2) + c0``."""


def _block_and_geometry(block_or_specimen):
    if isinstance(block_or_specimen, Block):
        return block_or_specimen
    try:
        n = int(block_or_specimen)
    except (TypeError, ValueError):
        raise ParameterError("block_or_specimen must be a rocking.Block or a specimen "
                             f"number, got {block_or_specimen!r}") from None
    return specimen(n, "theoretical")


def paper_parameters(block_or_specimen, alpha=None, p=None, mu=None, *,
                     inertia: str = "rectangle") -> dict:
    """The DEM parameters of the paper's Section 4.2-4.4 (Eqs 14-22).

    ``block_or_specimen`` is a :class:`~rocking.Block` (with mass, height and ``R``) or a
    specimen number (Table I geometry, Table II T parameters unless given). ``alpha``
    (rad), ``p`` (1/s) and ``mu`` default to the block's. ``R`` and the height are the
    block's geometric ones (Table I for the specimens).

    ``inertia="rectangle"`` uses Eq 17 (``W R / I = 3 g / 4R``); ``"block"`` uses Eq 16
    with the block's own ``I_O``.

    Returns a dict: ``K`` (Eq 16/17, N/m as printed), ``K1`` (Eq 14), ``K2`` (Eq 15),
    ``gamma`` (Eq 19, N), ``b`` (Eq 20, s), ``f_min`` (Eq 21, the value of p, used as Hz),
    ``xi_min`` (Eq 22), ``width_eq`` (``2 b_eq`` of Eq 18, m), ``settlement`` (``M g / 2K``,
    m, if ``K`` were a contact-point stiffness in N/m) and the inputs.
    """
    blk = _block_and_geometry(block_or_specimen)
    if blk.mass is None or blk.R is None:
        raise ParameterError("paper_parameters needs a block with a known mass and R "
                             "(e.g. Block.rectangular(width, height, mass))")
    alpha = blk.alpha if alpha is None else as_float("alpha", alpha)
    p = blk.p if p is None else positive("p", p, "1/s")
    mu = blk.mu if mu is None else as_float("mu", mu)
    M, R = float(blk.mass), float(blk.R)
    h = 0.5 * blk.height if blk.height is not None else R * math.cos(alpha)
    if inertia == "rectangle":
        wr_i = 3.0 * G / (4.0 * R)
    elif inertia == "block":
        if blk.I_O is None:
            raise ParameterError("inertia='block' needs the block's I_O")
        wr_i = M * G * R / blk.I_O
    else:
        raise ParameterError(f"inertia must be 'rectangle' or 'block', got {inertia!r}")
    K1 = M * p * p
    K2 = M * wr_i
    K = 0.5 * (K1 + K2)
    gamma = K * R
    sb = EQ20[0] * math.log(gamma / mu ** 2) + EQ20[1]
    b = sb * sb if sb > 0.0 else 0.0
    f_min = p
    return {"K": K, "K1": K1, "K2": K2, "gamma": gamma, "b": b, "sqrt_b": sb,
            "xi_min": 2.0 * math.pi * b * f_min, "f_min": f_min,
            "width_eq": 2.0 * h * math.tan(alpha), "settlement": M * G / (2.0 * K),
            "alpha": alpha, "p": p, "mu": mu, "M": M, "R": R, "h": h}


def table3(variant: str = "eq17") -> pd.DataFrame:
    """Table III recomputed from Table I/II, side by side with the printed T and F columns.

    One row per specimen and column (T: Table II T parameters, F: Table II E parameters);
    for each quantity ``ours``, ``paper`` and ``diff_pct``. ``K`` follows Eq 17 (``variant
    "eq17"``) or Eq 16 with Table I's ``I_O`` (``"eq16"``); ``K_Mp2`` is Eq 14 alone. The
    damping ``zeta`` is Eq 22 with ``b`` of Eq 20 (the paper fitted the printed values).
    """
    import pandas as pd  # lazy: 0.45 s at import, needed only for these tables

    data = paper_data()["specimens"]
    rows = []
    for n in specimen_ids():
        d = data[str(n)]
        geo = Block.rectangular(d["width"], d["height"], mass=d["mass"])
        if variant == "eq16":
            geo = geo.with_params(I_O=float(d["I_O"]))
        for col, key in (("T", "theoretical"), ("F", "experimental")):
            c = d[key]
            pp = paper_parameters(geo, c["alpha"], c["p"], c["mu"],
                                  inertia="block" if variant == "eq16" else "rectangle")
            t3 = d["table3"]
            row = {"specimen": n, "column": col, "alpha": c["alpha"], "p": c["p"],
                   "mu": c["mu"], "K_Mp2": pp["K1"], "gamma": pp["gamma"], "b": pp["b"]}
            for q, ours, paper in (("K", pp["K"], t3["K"][col]),
                                   ("zeta_e3", 1e3 * pp["xi_min"], t3["zeta_e3"][col]),
                                   ("f_min", pp["f_min"], t3["f_min"][col]),
                                   ("width_eq", pp["width_eq"], t3["width_eq"][col])):
                row[f"{q}_ours"] = ours
                row[f"{q}_paper"] = float(paper)
                row[f"{q}_diff_pct"] = 100.0 * (ours / float(paper) - 1.0)
            # b implied by the printed zeta (Eq 22 with f_min = p)
            row["b_from_printed_zeta"] = 1e-3 * t3["zeta_e3"][col] / (2 * math.pi * c["p"])
            row["settlement_if_N_per_m"] = pp["settlement"]
            rows.append(row)
    return pd.DataFrame(rows)


def refit_eq20() -> dict:
    """Least-squares refit of Eq 20 on the printed Table III F column (the four points the
    paper fitted): ``sqrt(b)`` from the printed zeta (Eq 22) against ``ln(Gamma / mu^2)``
    with ``Gamma = K R`` from the printed K (Eq 19). Returns the slope, intercept and the
    points."""
    data = paper_data()["specimens"]
    xs, ys = [], []
    for n in specimen_ids():
        d = data[str(n)]
        R = math.hypot(d["width"] / 2, d["height"] / 2)
        c = d["experimental"]
        K = d["table3"]["K"]["F"]
        b = 1e-3 * d["table3"]["zeta_e3"]["F"] / (2 * math.pi * c["p"])
        xs.append(math.log(K * R / c["mu"] ** 2))
        ys.append(math.sqrt(b))
    slope, icpt = np.polyfit(xs, ys, 1)
    return {"slope": float(slope), "intercept": float(icpt), "x": xs, "sqrt_b": ys}


READINGS = (
    # label, factor to N/m (or to Pa/m for joint stiffnesses), per point (True) or joint
    ("N/m per contact point (literal)", 1.0, "point"),
    ("N/m for the whole joint", 1.0, "joint"),
    ("kN/m per contact point", 1e3, "point"),
    ("MN/m per contact point", 1e6, "point"),
    ("Pa/m joint stiffness (UDEC jkn) x base area", 1.0, "area"),
    ("kPa/m joint stiffness x base area", 1e3, "area"),
    ("MPa/m joint stiffness x base area", 1e6, "area"),
    ("GPa/m joint stiffness x base area", 1e9, "area"),
)


def settlement(M: float, K: float, reading: str = "point", area: float | None = None,
               n: int = 2) -> float:
    """Static settlement (m) of a block of mass ``M`` on a stiffness ``K`` read as: a
    contact-point stiffness (N/m, ``n`` points), a whole-joint stiffness (N/m) or a joint
    stiffness per unit area (Pa/m over ``area`` m^2): ``M g / (n K)``, ``M g / K``,
    ``M g / (K area)``."""
    if reading == "point":
        return M * G / (n * K)
    if reading == "joint":
        return M * G / K
    if reading == "area":
        if area is None:
            raise ParameterError("reading='area' needs the contact area")
        return M * G / (K * area)
    raise ParameterError(f"reading must be 'point', 'joint' or 'area', got {reading!r}")


def settlement_table() -> pd.DataFrame:
    """The printed Table III K (column T) of each specimen under every unit reading, with
    the static settlement it implies (``M g / (n K)``, n = 2) and the settlement relative
    to the block's height. The base area is width x thickness (Table I)."""
    import pandas as pd  # lazy: 0.45 s at import, needed only for these tables

    data = paper_data()["specimens"]
    rows = []
    for n in specimen_ids():
        d = data[str(n)]
        K = float(d["table3"]["K"]["T"])
        area = d["width"] * d["thickness"]
        for label, f, kind in READINGS:
            s = settlement(d["mass"], K * f, kind, area)
            k_point = d["mass"] * G / (2.0 * s)
            rows.append({"specimen": n, "reading": label, "K_printed": K,
                         "K_point_N_per_m": k_point, "settlement_m": s,
                         "settlement_over_height": s / d["height"],
                         "physical": 1e-9 <= s / d["height"] <= 1e-4})
    return pd.DataFrame(rows)
