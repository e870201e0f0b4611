"""Section: objects inside buildings (beyond the paper; issue 18).

The paper's specimens stood on a shaking table driven by ground motions. An object in a
museum or a hospital stands on a floor, whose motion is the ground's filtered by the
building. Here specimens 2-4 (Table II E) and a statue-sized block stand on the ground
and on every floor of a 3-storey and an 8-storey shear building
(:meth:`rocking.buildings.Building.shear`: uniform floor masses and storey stiffnesses,
storeys of 3 m, first period from EN 1998-1 Eq 4.6 for RC moment frames, 5 % damping in
every mode, all modes kept), under the 30 seed earthquakes of the paper's random tests
scaled to a ladder of PGA levels and under the Rinaldi record of Northridge 1994
(:class:`rocking.buildings.FloorMotion`, classical model, each run until the block
settles). Compared: P(overturn) and the median max ``|theta|`` / alpha against the floor, the
peak floor acceleration against ASCE 7-22's ``H_f`` and EN 1998-1's amplification, and the
roof's floor spectrum against EN 1998-1 Eq 4.25.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from ...analysis import wilson_interval
from ...blocks import Block, specimen
from ...buildings import (
    Building,
    FloorMotion,
    asce7_hf,
    code_floor_spectrum_ec8,
    floor_spectrum,
    plot_floor_spectrum,
)
from ...models import simulate_many
from ...motions import load_builtin, response_spectrum, seed_earthquakes
from ...motions.ec8 import paper_target
from ...plot import PALETTE, style_axes
from ...units import G
from .. import html as H
from ..core import section

SPECIMENS = (2, 3, 4)
STATUE = "statue"
STATUE_WIDTH = 0.5  # m
STATUE_HEIGHT = 1.8  # m
STATUE_DEPTH = 0.5  # m (out of plane)
MARBLE_DENSITY = 2700.0  # kg/m^3
STOREYS = (3, 8)
STOREY_HEIGHT = 3.0  # m
CT_RC_FRAME = 0.075  # EN 1998-1 Eq 4.6: T1 = Ct H^(3/4), Ct for moment-resistant RC frames
DAMPING = 0.05
FLOOR_MASS = 400e3  # kg: assumed, a 20 m x 20 m floor at 1 t/m^2 (only for the mass ratio)
CASCADE_LIMIT = 0.01  # the mass ratio limit of rocking.buildings.FloorMotion's docstring
RECORD = "Rinaldi228"
RECORD_LABEL = "Northridge 1994, Rinaldi 228°"
MODEL = "housner"
P_TARGET = 0.5  # P(overturn) whose ground PGA is reported
QUICK_RECORDS = 10


# ------------------------------------------------------------------------ the inputs
def building_period(n_storeys: int) -> float:
    """EN 1998-1 Eq 4.6: ``T1 = Ct H^0.75`` (s), ``H = 3 m x storeys``, RC frames."""
    return CT_RC_FRAME * (STOREY_HEIGHT * n_storeys) ** 0.75


def make_buildings() -> dict[int, Building]:
    """The shear buildings by number of storeys (uniform masses and stiffnesses)."""
    return {n: Building.shear(n, building_period(n), DAMPING,
                              name=f"{n}-storey RC frame")
            for n in STOREYS}


def statue() -> Block:
    """A life-size marble statue with its plinth as one rigid block: 0.5 m x 1.8 m, 0.5 m
    deep, 2700 kg/m^3."""
    mass = STATUE_WIDTH * STATUE_HEIGHT * STATUE_DEPTH * MARBLE_DENSITY
    return Block.rectangular(STATUE_WIDTH, STATUE_HEIGHT, mass=mass, thickness=STATUE_DEPTH,
                             name="statue 0.5 m x 1.8 m")


def make_blocks() -> dict[str, Block]:
    """``{"specimen 2": ..., "specimen 3": ..., "specimen 4": ..., "statue": ...}``."""
    out = {f"specimen {n}": specimen(n, "experimental") for n in SPECIMENS}
    out[STATUE] = statue()
    return out


def pga_levels(quick: bool) -> np.ndarray:
    """Ground PGA levels (g), log-spaced from 0.1 to 0.4 g (below 0.1 g no record
    overturns any of the blocks on any floor of these buildings; checked with 0.05 and
    0.07 g)."""
    return np.round(np.geomspace(0.1, 0.4, 3 if quick else 5), 4)


def seed_records(quick: bool) -> list:
    """The seed earthquakes used: all 30 (the first 10 in quick mode)."""
    eq = seed_earthquakes()
    return eq[:QUICK_RECORDS] if quick else eq


def floors_of(bld: Building) -> np.ndarray:
    return np.arange(bld.n_floors + 1)


# ---------------------------------------------------------------------- computations
def floor_motions(records: list, buildings: dict) -> dict[int, list[list[FloorMotion]]]:
    """``{storeys: [[FloorMotion of record i at floor k for k = 0..N] for each record]}``
    (unscaled; :meth:`~rocking.motions.Motion.scaled` gives the load factors)."""
    return {n: [[FloorMotion(r, bld, floor=int(k)) for k in floors_of(bld)] for r in records]
            for n, bld in buildings.items()}


def run_floors(blocks: dict, buildings: dict, records: list, fms: dict, levels: np.ndarray,
               record_ids=None) -> pd.DataFrame:
    """Every run: each record scaled to each PGA level (g) on each floor (0: the ground)
    of each building (``fms``: :func:`floor_motions`), each block. One
    :func:`~rocking.simulate_many` batch per building, level and block."""
    ids = list(range(1, len(records) + 1)) if record_ids is None else list(record_ids)
    rows = []
    for n, bld in buildings.items():
        fl = floors_of(bld)
        for lev in levels:
            motions = [fm.scaled(lev * G / r.pga)
                       for r, row in zip(records, fms[n], strict=True) for fm in row]
            for label, blk in blocks.items():
                res = simulate_many(blk, motions, model=MODEL)
                i = 0
                for rid in ids:
                    for k in fl:
                        rows.append({
                            "building": f"{n}-storey", "storeys": n, "floor": int(k),
                            "z_over_H": float(bld.heights[k]), "block": label,
                            "pga_g": float(lev), "record": rid,
                            "overturned": bool(res.overturned[i]),
                            "max_theta_over_alpha": float(res.max_abs_theta[i] / blk.alpha),
                            "uplifted": bool(res.rocked[i]),
                            "settled": bool(res.settled[i]),
                        })
                        i += 1
    return pd.DataFrame(rows)


def censored_median(theta: np.ndarray, overturned: np.ndarray) -> float:
    """Median of max ``|theta|`` / alpha with the overturned runs counted as infinite."""
    return float(np.median(np.where(overturned, np.inf, theta)))


def summarise(runs: pd.DataFrame) -> pd.DataFrame:
    """P(overturn) (Wilson 95 % band) and the median max ``|theta|`` / alpha per building,
    floor, block and PGA level."""
    out = []
    keys = ["building", "storeys", "floor", "z_over_H", "block", "pga_g"]
    for key, d in runs.groupby(keys, sort=False):
        n, k = len(d), int(d.overturned.sum())
        lo, hi = wilson_interval(k, n)
        out.append({**dict(zip(keys, key, strict=True)), "n_records": n,
                    "n_overturned": k, "p_overturn": k / n, "ci_low": lo, "ci_high": hi,
                    "p_uplift": float(d.uplifted.mean()),
                    "median_max_theta_over_alpha": censored_median(
                        d.max_theta_over_alpha.to_numpy(), d.overturned.to_numpy()),
                    "n_not_settled": int((~d.settled).sum())})
    return pd.DataFrame(out)


def pga_at(levels: np.ndarray, p: np.ndarray, target: float = P_TARGET) -> tuple[float, str]:
    """The ground PGA at which ``p`` (at ``levels``) first reaches ``target``, interpolated
    linearly in log PGA; ``(nan, "<")`` when it is reached at the lowest level already,
    ``(nan, ">")`` when never."""
    hit = np.flatnonzero(p >= target)
    if hit.size == 0:
        return math.nan, ">"
    i = int(hit[0])
    if i == 0:
        return math.nan, "<"
    x0, x1 = math.log(levels[i - 1]), math.log(levels[i])
    f = (target - p[i - 1]) / (p[i] - p[i - 1])
    return math.exp(x0 + f * (x1 - x0)), ""


def thresholds(summary: pd.DataFrame) -> pd.DataFrame:
    """Per block, building and floor: the ground PGA at which P(overturn) reaches 50 %,
    and the largest level at which no record overturns the block."""
    out = []
    for (b, n, k, blk), d in summary.groupby(["building", "storeys", "floor", "block"],
                                             sort=False):
        d = d.sort_values("pga_g")
        lev, p = d.pga_g.to_numpy(), d.p_overturn.to_numpy()
        x, bound = pga_at(lev, p)
        safe = lev[:np.argmax(p > 0)] if (p > 0).any() else lev
        out.append({"building": b, "storeys": n, "floor": k,
                    "z_over_H": float(d.z_over_H.iloc[0]), "block": blk,
                    "pga_p50_g": x, "pga_p50_bound": bound,
                    "pga_p50_bound_g": (lev[0] if bound == "<" else lev[-1]
                                        if bound == ">" else math.nan),
                    "max_pga_no_overturn_g": float(safe[-1]) if safe.size else math.nan})
    return pd.DataFrame(out)


def pfa_table(buildings: dict, records: list, fms: dict, real, real_fms: dict
              ) -> pd.DataFrame:
    """Peak floor acceleration / PGA per floor: median and 16-84 % of the seed records
    (``fms``: :func:`floor_motions`), the real record (``real_fms``), ASCE 7-22 ``H_f``
    (``Ta = T1``) and EN 1998-1 Eq 4.25's rigid-element amplification (``Ta = 0``:
    ``1 + 1.5 z/H``)."""
    rows = []
    for n, bld in buildings.items():
        T1 = float(bld.periods[0])
        ratios = np.array([[fm.pfa / r.pga for fm in row]
                           for r, row in zip(records, fms[n], strict=True)])
        for k in floors_of(bld):
            z = float(bld.heights[k])
            r = ratios[:, k]
            rows.append({"building": f"{n}-storey", "storeys": n, "floor": int(k),
                         "z_over_H": z, "T1_s": T1,
                         "pfa_over_pga_median": float(np.median(r)),
                         "pfa_over_pga_p16": float(np.percentile(r, 16)),
                         "pfa_over_pga_p84": float(np.percentile(r, 84)),
                         "pfa_over_pga_min": float(r.min()),
                         "pfa_over_pga_max": float(r.max()),
                         f"pfa_over_pga_{RECORD}": real_fms[n][0][k].pfa / real.pga,
                         "asce7_hf": float(asce7_hf(z, T1)),
                         "ec8_rigid": float(code_floor_spectrum_ec8(0.0, 1.0, z, T1)),
                         "n_records": len(records)})
    return pd.DataFrame(rows)


def modal_table(buildings: dict) -> pd.DataFrame:
    """Periods, participation at the roof and effective modal mass fractions."""
    rows = []
    for n, bld in buildings.items():
        m = np.diag(bld.mass_matrix)
        phi = bld.shapes[1:]
        for j in range(bld.n_modes):
            mj = float(phi[:, j] @ (m * phi[:, j]))
            lj = float(phi[:, j] @ m)
            rows.append({"building": f"{n}-storey", "storeys": n,
                         "height_m": STOREY_HEIGHT * n, "mode": j + 1,
                         "period_s": float(bld.periods[j]),
                         "damping": float(bld.damping[j]),
                         "gamma_phi_roof": float(bld.participation[j] * phi[-1, j]),
                         "effective_mass_fraction": lj * lj / mj / float(m.sum())})
    return pd.DataFrame(rows)


def mass_ratios(blocks: dict, buildings: dict) -> pd.DataFrame:
    """The object's mass over the smallest effective mass of the building at a floor,
    ``min_j,k M_j / phi_j(k)^2`` (``M_j`` the modal mass, floors of ``FLOOR_MASS``)."""
    rows = []
    for n, bld in buildings.items():
        m = np.diag(bld.mass_matrix) * FLOOR_MASS / np.diag(bld.mass_matrix)[0]
        phi = bld.shapes[1:]
        mj = np.einsum("ij,i,ij->j", phi, m, phi)
        with np.errstate(divide="ignore"):
            eff = np.where(phi != 0.0, mj / phi ** 2, np.inf)
        k, j = np.unravel_index(np.argmin(eff), eff.shape)
        for label, blk in blocks.items():
            rows.append({"block": label, "mass_kg": float(blk.mass),
                         "building": f"{n}-storey", "floor_mass_kg": float(m[0]),
                         "smallest_effective_mass_kg": float(eff[k, j]),
                         "at_floor": int(k) + 1, "mode": int(j) + 1,
                         "mass_ratio": float(blk.mass / eff[k, j]),
                         "limit": CASCADE_LIMIT})
    return pd.DataFrame(rows)


def floor_spectra(buildings: dict, real, periods: np.ndarray) -> pd.DataFrame:
    """The real record's 5 %-damped roof spectra (g) with the ground's and the codes'."""
    df = pd.DataFrame({"period_s": periods,
                       "ground_psa_g": response_spectrum(real, periods) / G})
    pga = real.pga
    for n, bld in buildings.items():
        T1 = float(bld.periods[0])
        df[f"roof_{n}_storey_psa_g"] = floor_spectrum(real, bld, floor=bld.n_floors,
                                                      periods=periods) / G
        df[f"ec8_roof_{n}_storey_g"] = code_floor_spectrum_ec8(periods, pga, 1.0, T1) / G
        df[f"asce7_pfa_roof_{n}_storey_g"] = asce7_hf(1.0, T1) * pga / G
    return df


def spectrum_periods(quick: bool) -> np.ndarray:
    return np.geomspace(0.02, 4.0, 60 if quick else 160)


# ----------------------------------------------------------------------------- figures
def _level_colours(levels):
    from matplotlib import colormaps

    cmap = colormaps["viridis"]
    return [cmap(0.9 * i / max(len(levels) - 1, 1)) for i in range(len(levels))]


def _grid(summary, buildings, blocks, levels, value, xlabel, *, theta=False):
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    fig = Figure(figsize=(12.0, 6.8), layout="constrained")
    axs = fig.subplots(len(buildings), len(blocks), sharey="row", sharex=True)
    cols = _level_colours(levels)
    for r, (n, bld) in enumerate(buildings.items()):
        for c, label in enumerate(blocks):
            ax = axs[r, c]
            d = summary[(summary.storeys == n) & (summary.block == label)]
            for i, (lev, col) in enumerate(zip(levels, cols, strict=True)):
                e = d[d.pga_g == lev].sort_values("floor")
                x = e[value].to_numpy()
                ax.plot(np.where(np.isfinite(x), x, np.nan), e.floor, color=col, marker="o",
                        ms=3.5, lw=1.3)
                if theta:  # a median that is "overturned": a cross near the right edge
                    inf = e[~np.isfinite(x)]
                    xc = 0.98 - 0.045 * (len(levels) - 1 - i)
                    ax.plot(np.full(len(inf), xc), inf.floor, ls="none", marker="x",
                            ms=6, mew=1.5, color=col, transform=ax.get_yaxis_transform())
            if theta:
                ax.set_xscale("symlog", linthresh=0.01)
                ax.set_xlim(0.0, 20.0)
                ax.set_xticks([0.0, 0.01, 0.1, 1.0])
                ax.axvline(1.0, color="0.5", ls=":", lw=0.8)
            else:
                ax.set_xlim(-0.03, 1.03)
            ax.set_yticks(floors_of(bld))
            style_axes(ax, xlabel if r == len(buildings) - 1 else None,
                       f"floor of the {n}-storey building\n(0 = ground)" if c == 0 else None)
            ax.set_title(f"{label}, {n}-storey (T1 = {bld.periods[0]:.2f} s)", fontsize=9)
    handles = [Line2D([], [], color=col, marker="o", ms=3.5, lw=1.3,
                      label=f"ground PGA {lev:.3g} g") for lev, col in zip(levels, cols,
                                                                           strict=True)]
    if theta:
        handles.append(Line2D([], [], color="0.3", marker="x", ls="none", ms=6,
                              label="median: overturned"))
    fig.legend(handles=handles, loc="outside upper center", ncols=len(handles),
               fontsize=8.5, frameon=False)
    return fig


def _pfa_figure(pfa, buildings):
    from matplotlib.figure import Figure

    fig = Figure(figsize=(10.0, 5.0), layout="constrained")
    axs = fig.subplots(1, len(buildings))
    for ax, (n, bld) in zip(axs, buildings.items(), strict=True):
        d = pfa[pfa.storeys == n].sort_values("floor")
        nr = int(d.n_records.iloc[0])
        ax.fill_betweenx(d.floor, d.pfa_over_pga_p16, d.pfa_over_pga_p84, color=PALETTE[0],
                         alpha=0.2, lw=0, label=f"16-84 %, {nr} seed earthquakes")
        ax.plot(d.pfa_over_pga_median, d.floor, color=PALETTE[0], marker="o", ms=4, lw=1.6,
                label="median, seed earthquakes")
        ax.plot(d[f"pfa_over_pga_{RECORD}"], d.floor, color=PALETTE[6], marker="s", ms=3.5,
                lw=1.0, label=RECORD_LABEL)
        ax.plot(d.asce7_hf, d.floor, color=PALETTE[1], ls="--", lw=1.4,
                label="ASCE 7-22 $H_f$, Eq 13.3-4 ($T_a$ = $T_1$)")
        ax.plot(d.ec8_rigid, d.floor, color=PALETTE[2], ls="-.", lw=1.4,
                label="EN 1998-1 Eq 4.25, rigid element: 1 + 1.5 z/H")
        ax.set_yticks(floors_of(bld))
        ax.set_xlim(left=min(0.75, float(d.pfa_over_pga_p16.min()) - 0.05))
        style_axes(ax, "peak floor acceleration / PGA", "floor (0 = ground)")
        ax.set_title(f"{n}-storey shear building, T1 = {bld.periods[0]:.2f} s", fontsize=10)
    fig.legend(*axs[0].get_legend_handles_labels(), loc="outside lower center", ncols=3,
               fontsize=8.5, frameon=False)
    return fig


def _spectra_figure(spec, buildings):
    from matplotlib.figure import Figure

    fig = Figure(figsize=(12.0, 4.8), layout="constrained")
    axs = fig.subplots(1, len(buildings), sharey=True)
    T = spec.period_s.to_numpy()
    for ax, (n, bld) in zip(axs, buildings.items(), strict=True):
        refs = {"EN 1998-1 Eq 4.25 at the roof ($a_g S$ = PGA)":
                spec[f"ec8_roof_{n}_storey_g"].to_numpy() * G,
                "ASCE 7-22 peak roof acceleration $H_f$ PGA":
                spec[f"asce7_pfa_roof_{n}_storey_g"].to_numpy() * G}
        plot_floor_spectrum(ax, T, spec[f"roof_{n}_storey_psa_g"].to_numpy() * G,
                            spec.ground_psa_g.to_numpy() * G, references=refs, units="g",
                            label="roof",
                            title=f"{RECORD_LABEL}: roof of the {n}-storey building "
                                  f"(T1 = {bld.periods[0]:.2f} s)")
        for j, t in enumerate(bld.periods[:3]):
            ax.axvline(t, color="0.6", lw=0.7, ls=":", zorder=1)
            ax.text(t, 0.99, f" T{j + 1}", transform=ax.get_xaxis_transform(), fontsize=7.5,
                    color="0.35", va="top")
        ax.get_legend().remove()
    fig.legend(*axs[0].get_legend_handles_labels(), loc="outside upper center", ncols=4,
               fontsize=8.5, frameon=False)
    return fig


# ----------------------------------------------------------------------------- the page
def _g(x) -> str:
    return "–" if not np.isfinite(x) else f"{x:.2f}"


def _thr_cell(row) -> str:
    if row.pga_p50_bound == "<":
        return f"< {row.pga_p50_bound_g:g}"
    if row.pga_p50_bound == ">":
        return f"> {row.pga_p50_bound_g:g}"
    return f"{row.pga_p50_g:.3f}"


def compute(quick: bool) -> dict:
    """Every table of the section (DataFrames), from the fixed lists and ``quick``."""
    blocks, buildings = make_blocks(), make_buildings()
    records, levels = seed_records(quick), pga_levels(quick)
    real = load_builtin(RECORD)
    fms, real_fms = floor_motions(records, buildings), floor_motions([real], buildings)
    runs = run_floors(blocks, buildings, records, fms, levels)
    summary = summarise(runs)
    rin = run_floors(blocks, buildings, [real], real_fms, levels, record_ids=[RECORD])
    return {"blocks": blocks, "buildings": buildings, "levels": levels, "real": real,
            "records": records, "runs": runs, "summary": summary,
            "thresholds": thresholds(summary),
            "rinaldi": rin.drop(columns=["record"]),
            "pfa": pfa_table(buildings, records, fms, real, real_fms),
            "modes": modal_table(buildings), "mass": mass_ratios(blocks, buildings),
            "spectra": floor_spectra(buildings, real, spectrum_periods(quick))}


@section("buildings", "Beyond the paper: objects inside buildings (floor motions)",
         order=66, cost=30)
def build(ctx) -> str:
    res = compute(ctx.quick)
    blocks, buildings, levels = res["blocks"], res["buildings"], res["levels"]
    summary, thr, pfa, rin = res["summary"], res["thresholds"], res["pfa"], res["rinaldi"]
    modes, mass, spec, real = res["modes"], res["mass"], res["spectra"], res["real"]
    nrec = len(res["records"])
    ctx.save_csv(modes, "modes", float_format="%.6g")
    ctx.save_csv(pfa, "pfa", float_format="%.6g")
    ctx.save_csv(summary, "p_overturn", float_format="%.6g")
    ctx.save_csv(thr, "thresholds", float_format="%.6g")
    ctx.save_csv(rin, "rinaldi", float_format="%.6g")
    ctx.save_csv(mass, "mass_ratio", float_format="%.6g")
    ctx.save_csv(spec, "floor_spectra", float_format="%.6g")

    fig_pfa = ctx.save_figure(
        _pfa_figure(pfa, buildings), "pfa",
        caption=(f"Peak floor acceleration over the PGA, floor by floor: median and 16-84 % "
                 f"band of the {nrec} seed earthquakes, the Rinaldi record, ASCE 7-22's "
                 "H_f (with the model's T1 as Ta) and EN 1998-1 Eq 4.25 for a rigid element "
                 "(Ta = 0) divided by a_g S. The building is linear: the ratio does not "
                 "depend on the PGA."))
    fig_p = ctx.save_figure(
        _grid(summary, buildings, blocks, levels, "p_overturn", "P(overturn)"), "p_overturn",
        caption=(f"P(overturn) over the {nrec} seed earthquakes, each scaled to the ground "
                 "PGA of the line, for a block standing on each floor (0: the ground), "
                 "classical model."))
    fig_t = ctx.save_figure(
        _grid(summary, buildings, blocks, levels, "median_max_theta_over_alpha",
              "median max |θ| / α", theta=True),
        "theta",
        caption=(f"Median over the {nrec} seed earthquakes of the peak rocking angle over "
                 "the slenderness, max |θ|/α, on each floor, the overturned runs counted as "
                 "infinite; crosses on the right (one column per PGA level, in the order of "
                 "the legend): more than half of the records overturn the block, so the "
                 "median is an overturning (0: no uplift; "
                 "symmetric-log axis, linear below 0.01; dotted: θ = α)."))
    fig_s = ctx.save_figure(
        _spectra_figure(spec, buildings), "floor_spectra",
        caption=(f"5 %-damped pseudo-acceleration spectra of the {RECORD_LABEL} record "
                 f"(PGA {real.pga / G:.2f} g) on the ground and at the roof of each "
                 "building, with EN 1998-1 Eq 4.25 at z = H anchored at a_g S = the "
                 "record's PGA and ASCE 7-22's peak roof acceleration H_f PGA (a "
                 "constant: the code's component amplification C_AR is not included); "
                 "dotted: the building's first three periods."))

    # ---- tables in the page
    mrows = []
    for n in buildings:
        d = modes[modes.storeys == n]
        mrows.append([f"{n}", f"{STOREY_HEIGHT * n:g}",
                      ", ".join(f"{t:.3f}" for t in d.period_s.head(3)),
                      ", ".join(f"{g:+.2f}" for g in d.gamma_phi_roof.head(3)),
                      f"{100 * d.effective_mass_fraction.iloc[0]:.1f} %",
                      f"{pfa[(pfa.storeys == n) & (pfa.floor == n)].asce7_hf.iloc[0]:.2f}"])
    tbl_b = H.table(["storeys", "H (m)", "T1, T2, T3 (s)", "Γ_j φ_j(roof), j = 1-3",
                     "mode 1 effective mass", "ASCE 7 H_f at the roof"], mrows,
                    caption="The buildings (uniform shear buildings, 5 % modal damping)")
    trows = []
    for label in blocks:
        row = [H.Cell(label, "l")]
        g = thr[(thr.block == label) & (thr.floor == 0)].iloc[0]
        row.append(_thr_cell(g))
        for n in buildings:
            d = thr[(thr.block == label) & (thr.storeys == n)].sort_values("floor")
            row.append(_thr_cell(d.iloc[len(d) // 2]))
            row.append(_thr_cell(d.iloc[-1]))
        trows.append(row)
    hdr = ["block", "ground"]
    for n in buildings:
        hdr += [f"floor {(n + 1) // 2}, {n}-storey", f"roof, {n}-storey"]
    tbl_t = H.table(
        hdr, trows,
        caption=(f"Ground PGA (g) at which P(overturn) over the {nrec} seed earthquakes "
                 "reaches 50 % (interpolated in log PGA between the levels; < and >: "
                 "outside the ladder)"))

    text = _text(res)
    return (H.p(text[0]) + tbl_b + fig_pfa + H.p(text[1]) + fig_p + fig_t + tbl_t
            + "".join(H.p(t) for t in text[2:-2]) + fig_s + H.p(text[-2]) + H.p(text[-1])
            + ctx.files_html())


def _text(res) -> list[str]:
    """The section's paragraphs, every number from the tables of :func:`compute`."""
    blocks, buildings, levels = res["blocks"], res["buildings"], res["levels"]
    summary, thr, pfa, rin, mass, spec = (res["summary"], res["thresholds"], res["pfa"],
                                          res["rinaldi"], res["mass"], res["spectra"])
    records, real = res["records"], res["real"]
    nrec = len(records)
    st = blocks[STATUE]
    periods = {n: float(b.periods[0]) for n, b in buildings.items()}
    target = paper_target()
    setup = (
        f"A block on a floor rocks under the floor's absolute acceleration, the ground's "
        f"filtered by the building. Two shear buildings of {' and '.join(map(str, STOREYS))} "
        f"storeys of {STOREY_HEIGHT:g} m (uniform floor masses and storey stiffnesses, "
        f"all modes, {100 * DAMPING:g} % damping in each) have the first period of EN "
        f"1998-1 Eq 4.6 for RC moment frames, T1 = {CT_RC_FRAME:g} H^0.75 (H in m): "
        + " and ".join(f"{v:.3f} s" for v in periods.values())
        + ". On the ground (floor 0) and on each floor stand specimens "
        + ", ".join(map(str, SPECIMENS))
        + f" (Table II E) and a statue: a life-size marble figure with its plinth taken as "
        f"one rigid block {STATUE_WIDTH:g} m wide, {STATUE_HEIGHT:g} m tall and "
        f"{STATUE_DEPTH:g} m deep ({MARBLE_DENSITY:g} kg/m³: {st.mass:.0f} kg; α = "
        f"{st.alpha:.3f} rad, R = {st.R:.2f} m, p = {st.p:.2f} 1/s, uplift at g tan α = "
        f"{math.tan(st.alpha):.3f} g). The motions are the {nrec} seed earthquakes of the "
        f"paper's random tests, each scaled to a ground PGA of "
        + ", ".join(f"{v:.3g}" for v in levels)
        + f" g, and the {RECORD_LABEL} record (recorded PGA "
        f"{real.pga / G:.2f} g) scaled to the same PGAs. The floor motions come from "
        "rocking.buildings.FloorMotion (modal superposition, exact for the piecewise-linear "
        "record, followed by the building's free vibration until it dies out), the blocks' "
        "response from the classical model, each run until the block settles ("
        f"{len(res['runs']) + len(rin)} runs; floor 0 is the ground motion itself).")

    # the peak floor acceleration against the codes
    parts = []
    for n in buildings:
        d = pfa[pfa.storeys == n].sort_values("floor")
        up = d[d.floor > 0]
        roof = d.iloc[-1]
        below_hf = int((up.pfa_over_pga_median <= up.asce7_hf).sum())
        below_ec8 = int((up.pfa_over_pga_median <= up.ec8_rigid).sum())
        over84 = int((up.pfa_over_pga_p84 > up.asce7_hf).sum())
        real_over = up[(up[f"pfa_over_pga_{RECORD}"] > up.asce7_hf)].floor.tolist()
        sa = np.median([float(response_spectrum(r, periods[n])) / r.pga for r in records])
        parts.append(
            f"at the roof of the {n}-storey building the peak floor acceleration is "
            f"{roof.pfa_over_pga_median:.2f} times the PGA (median; 16-84 %: "
            f"{roof.pfa_over_pga_p16:.2f}-{roof.pfa_over_pga_p84:.2f}; Rinaldi "
            f"{roof[f'pfa_over_pga_{RECORD}']:.2f}) against ASCE 7-22's H_f = "
            f"{roof.asce7_hf:.2f} and EN 1998-1's {roof.ec8_rigid:.2f}; over its {len(up)} "
            f"floors the median is at most H_f on {below_hf} and at most EN 1998-1's "
            f"value on {below_ec8 or 'none'}, the 84th percentile exceeds H_f on "
            f"{over84 or 'none'}, and the "
            "Rinaldi record exceeds H_f on "
            + (f"floors {', '.join(map(str, real_over))}" if real_over else "none")
            + f" (the seed earthquakes' median spectral acceleration at T1 is {sa:.2f} "
            "times their PGA)")
    amp = ("The buildings amplify the ground motion upwards: " + "; ".join(parts)
           + f". The seed earthquakes match a spectrum whose plateau runs from "
           f"{target.tb:g} to {target.tc:g} s, so a building with its first period near "
           "the plateau amplifies them most; the codes' height-wise rules are meant as "
           "envelopes over buildings and records, which a single record near resonance "
           "can exceed.")

    # what it means for the paper's specimens
    p_parts = []
    for label in blocks:
        g = thr[(thr.block == label) & (thr.floor == 0)].iloc[0]
        roofs = []
        for n in buildings:
            r = thr[(thr.block == label) & (thr.storeys == n) & (thr.floor == n)].iloc[0]
            roofs.append(f"{_thr_text(r)} at the roof of the {n}-storey building")
        p_parts.append(f"{label}: {_thr_text(g)} on the ground, " + ", ".join(roofs))
    p50 = ("The ground PGA at which half of the records overturn the block is, for "
           + "; ".join(p_parts) + ".")
    unsafe = []
    for label in blocks:
        g = thr[(thr.block == label) & (thr.floor == 0)].iloc[0]
        safe = g.max_pga_no_overturn_g
        if not np.isfinite(safe):
            unsafe.append(f"some record overturns {label} on the ground already at "
                          f"{levels[0]:g} g")
            continue
        ups = []
        for n in buildings:
            d = summary[(summary.block == label) & (summary.storeys == n)
                        & (summary.pga_g == safe)]
            worst = d.loc[d.p_overturn.idxmax()]
            ups.append(f"{int(worst.n_overturned)} of {nrec} on floor {int(worst.floor)} of "
                       f"the {n}-storey building" if worst.n_overturned
                       else f"none on any floor of the {n}-storey building")
        unsafe.append(f"at {safe:.3g} g, the largest PGA of the ladder at which no record "
                      f"overturns {label} on the ground, " + " and ".join(ups)
                      + (" do" if "of the" in ups[-1] else ""))
    ratios = []
    roof_amp = {n: float(pfa[(pfa.storeys == n) & (pfa.floor == n)].pfa_over_pga_median
                         .iloc[0]) for n in buildings}
    for label in blocks:
        g = thr[(thr.block == label) & (thr.floor == 0)].iloc[0]
        r = thr[(thr.block == label) & (thr.floor == thr.storeys)].set_index("storeys")
        if np.isfinite(g.pga_p50_g) and np.all(np.isfinite(r.pga_p50_g)):
            ratios.append((label, {n: float(r.pga_p50_g[n] / g.pga_p50_g)
                                   for n in buildings}))
    order = []
    for label in blocks:
        d = thr[thr.block == label]
        if (d.pga_p50_bound == "<").any():
            order.append((0.0, label, f"{label} (below {levels[0]:g} g)"))
        elif np.isfinite(d.pga_p50_g).any():
            lo = float(d.pga_p50_g.min())
            order.append((lo, label, f"{label} ({lo:.2f} g)"))
        else:
            order.append((math.inf, label, f"{label} (above {levels[-1]:g} g)"))
    order = [t for *_, t in sorted(order)]
    up_st = summary[(summary.block == STATUE) & (summary.floor > 0)]
    gr_st = summary[(summary.block == STATUE) & (summary.floor == 0)
                    & (summary.storeys == STOREYS[0])]
    unsafe_t = ("Upstairs the same ground motion is more dangerous: " + "; ".join(unsafe)
                + ". " + p50
                + _ratio_text(ratios, roof_amp, periods)
                + " Ranked by the lowest ground PGA that overturns half of the records on "
                "any floor: " + ", ".join(order) + ". Slenderness and size decide the "
                "ranking: specimens 2 and 3 lift off at g tan α = "
                + ", ".join(f"{math.tan(blocks[f'specimen {n}'].alpha):.2f} g"
                            for n in (2, 3))
                + f"; specimen 4 is stockier (α = {blocks['specimen 4'].alpha:.3f} rad) and "
                f"the statue, about as stocky (α = {st.alpha:.3f} rad) but larger (R = "
                f"{st.R:.2f} m against {blocks['specimen 4'].R:.2f} m), overturns in "
                f"{int(up_st.n_overturned.sum())} of its {int(up_st.n_records.sum())} runs "
                f"above the ground and {int(gr_st.n_overturned.sum())} of "
                f"{int(gr_st.n_records.sum())} on it.")

    # the real record
    rparts = []
    for label in blocks:
        d = rin[(rin.block == label) & rin.overturned]
        g = d[d.floor == 0].pga_g
        where = [f"{g.min():.3g} g on the ground" if len(g) else
                 f"not on the ground (up to {levels[-1]:g} g)"]
        for n in buildings:
            e = d[(d.storeys == n) & (d.floor > 0)]
            if len(e):
                lo = e.pga_g.min()
                fl = sorted(e[e.pga_g == lo].floor.tolist())
                where.append(f"{lo:.3g} g on floor{'s' if len(fl) > 1 else ''} "
                             f"{', '.join(map(str, fl))} of the {n}-storey building")
            else:
                where.append(f"never in the {n}-storey building")
        rparts.append(f"{label}: " + ", ".join(where))
    peaks = ", ".join(
        f"{spec.period_s[spec[f'roof_{n}_storey_psa_g'].idxmax()]:.2f} s at the roof of "
        f"the {n}-storey building" for n in buildings)
    pairs = rin.sort_values("pga_g").groupby(["storeys", "floor", "block"]).overturned
    back = int(pairs.apply(lambda o: bool(np.any(np.diff(o.to_numpy().astype(int)) < 0)))
               .sum())
    rin_t = (f"Under the {RECORD_LABEL} record alone the lowest PGA of the ladder that "
             "overturns each block is, for " + "; ".join(rparts) + ". One record gives one "
             "outcome per floor and level, not a probability, and the outcome need not grow "
             f"with the PGA: in {back} of the {pairs.ngroups} block-floor pairs the block "
             "survives a level above one that overturned it (the CSV has every run). The "
             "record's 5 % spectrum peaks at "
             f"{spec.period_s[spec.ground_psa_g.idxmax()]:.2f} s on the ground and at "
             f"{peaks}.")

    # cascade and limits
    mr = mass.sort_values("mass_ratio").iloc[-1]
    cascade = (
        "Cascade assumption: the block rocks on the floor without acting back on the "
        "building (its inertia force on the floor is neglected). The docstring of "
        "rocking.buildings.FloorMotion accepts this below a mass ratio of "
        f"{100 * CASCADE_LIMIT:g} % of the building's effective mass at the floor, "
        "M_j / φ_j(floor)² for each mode j (a rocking object has no fixed frequency, so it "
        f"is never safely detuned). With an assumed floor mass of {FLOOR_MASS / 1000:g} t "
        "(a 20 m × 20 m floor at 1 t/m²) the largest ratio here is "
        f"{100 * mr.mass_ratio:.2f} % ({mr.block}, {mr.mass_kg:.0f} kg, in the "
        f"{mr.building} building, whose smallest effective mass is "
        f"{mr.smallest_effective_mass_kg / 1000:.0f} t: mode {mr['mode']} at floor "
        f"{mr.at_floor}), far below the limit; heavy equipment on a light floor would "
        "need a coupled model (not provided).")
    limits = (
        "Limits: the buildings are linear elastic (no cracking or yielding, which would "
        "lengthen their periods and limit the floor accelerations at the higher PGAs), "
        "uniform shear buildings (no flexural deformation of walls, no torsion, rigid "
        "floors) with classical modal damping; the motions are horizontal only (the seed "
        "earthquakes have no vertical component and the Rinaldi record is used without its "
        "own), so there is no vertical building filter in these runs, although floors "
        "amplify the vertical motion too, most at mid-span (FloorMotion can filter a "
        "vertical component through a building's vertical modes, vertical_building=...; "
        "without one it passes the ground's through unchanged); the blocks do not slide. "
        "The periods come from the code's rule of thumb, not from a model of a real "
        "building, and EN 1998-1 Eq 4.25 is anchored at the record's PGA for the "
        "comparison only.")
    return [setup, amp, unsafe_t, rin_t, cascade, limits]


def _ratio_text(ratios, roof_amp, periods) -> str:
    """The roof's 50 % PGA over the ground's, against the reciprocal of the roof's
    amplification of the peak acceleration."""
    if not ratios:
        return ""
    inv = {n: 1.0 / a for n, a in roof_amp.items()}
    parts = [f"{label} " + ", ".join(f"{r[n]:.2f}" for n in inv) for label, r in ratios]
    more = [n for n in inv if all(r[n] < inv[n] for _, r in ratios)]
    less = [n for n in inv if all(r[n] > inv[n] for _, r in ratios)]
    out = (" At the roof the PGA that overturns half of the records is, over the ground's, "
           + "; ".join(parts) + " (" + ", ".join(f"{n}-storey" for n in inv) + "), "
           "against the reciprocal of the median roof amplification of the peak "
           "acceleration, " + ", ".join(f"{v:.2f}" for v in inv.values()) + ".")
    if less:
        out += (" The roof of the " + " and ".join(f"{n}-storey" for n in less)
                + " building is less dangerous than its peak acceleration suggests")
    if more:
        out += ((", and that of the " if less else " The roof of the ")
                + " and ".join(f"{n}-storey" for n in more)
                + " building more")
    if less or more:
        out += (": at the same peak, long-period cycles overturn a block more easily than "
                "short ones (Housner 1963; the overturning spectra of the pulse section "
                "above), and a floor's motion is dominated by the building's first period, T1 = "
                + ", ".join(f"{t:.2f} s" for t in periods.values()) + ".")
    return out


def _thr_text(row) -> str:
    if row.pga_p50_bound == "<":
        return f"below {row.pga_p50_bound_g:g} g"
    if row.pga_p50_bound == ">":
        return f"above {row.pga_p50_bound_g:g} g"
    return f"{row.pga_p50_g:.2f} g"
