"""Section: what would make it safe (beyond the paper; issue 19).

Specimens 2-4 (Table II E) and the statue of the buildings section (a rigid block 0.5 m x
1.8 m) stand on the ground and on the roof of that section's 8-storey shear building,
free (classical model), on a seismically isolated base (``model="isolated"``: a linear
isolator of period 2 or 3 s, 10 % damping, plate mass = block mass, no moat, so that the
whole displacement demand is recorded) or anchored (``model="anchored"``: rigid brittle
anchors of strength ``q = F_a / (m g) = 0.3``). The seed earthquakes of the paper's random
tests are scaled to a ladder of ground PGAs (IDA style, one :func:`rocking.simulate_many`
batch per mitigation, block and floor), and
:func:`rocking.analysis.mitigation.compare_mitigations` fits the overturning fragility
curves against the ground PGA, integrates them over the ILLUSTRATIVE hazard curve of the
fragility section (:func:`.fragility.hazard_curve`: the shipped OpenQuake-format example
file, not the hazard of any site) and sets the isolator's displacement demand against a
0.15 m clearance.

Where isolation does not help: Vassiliou and Makris (2012, Earthquake Engng Struct. Dyn.
41(2), 177-196) found that an isolated base can make a small block *more* vulnerable to
long-period pulses. The overturning spectra of one-sine pulses
(:func:`rocking.analysis.overturning_spectrum`, any model) of specimen 2 and the statue,
free and isolated, against the pulse period show whether and where we see it.
"""

from __future__ import annotations

import contextlib
import math
import warnings

import numpy as np
import pandas as pd

from ...analysis import compare_mitigations
from ...analysis.overturning import overturning_spectrum, pulse_motion
from ...blocks import specimen
from ...buildings import FloorMotion
from ...errors import PlausibilityWarning
from ...models import get_model, simulate_many
from ...motions import seed_earthquakes
from ...motions.ec8 import paper_target
from ...plot import PALETTE, style_axes
from ...units import G
from .. import html as H
from ..core import section
from .buildings import STATUE_HEIGHT, STATUE_WIDTH, make_buildings, statue
from .fragility import HAZARD_A0, HAZARD_FILE, HAZARD_K, HAZARD_K0, HAZARD_SITE, hazard_curve

SPECIMENS = (2, 3, 4)
STATUE = "statue"
STOREYS = 8  # the taller building of the buildings section; its roof is the upper floor
FLOORS = ("ground", "roof")
CLEARANCE = 0.15  # m: the moat the displacement demand is compared with
ISOLATION_PERIODS = (2.0, 3.0)  # s
ISOLATION_DAMPING = 0.10
MASS_RATIO = 1.0  # plate mass over block mass
ANCHOR_STRENGTH = 0.3  # q = F_a / (m g)
MITIGATIONS = {
    "none": ("housner", {}),
    **{f"isolated_{t:g}s": ("isolated", {"isolation": "linear", "isolation_period": t,
                                          "isolation_damping": ISOLATION_DAMPING,
                                          "mass_ratio": MASS_RATIO, "clearance": None})
       for t in ISOLATION_PERIODS},
    "anchored": ("anchored", {"anchor_strength": ANCHOR_STRENGTH, "anchors": "rigid"}),
}
"""Mitigation id -> (model, options of :func:`rocking.simulate_many`)."""
LABELS = {"none": "free (no mitigation)",
          **{f"isolated_{t:g}s": f"isolated, T_b = {t:g} s" for t in ISOLATION_PERIODS},
          "anchored": f"anchored, q = {ANCHOR_STRENGTH:g}"}
N_BOOT = (50, 200)
N_RECORDS = (3, 8)  # quick, default
N_LEVELS = (6, 8)
PGA_RANGE = (0.05, 2.0)  # g
PULSE_BLOCKS = ("specimen 2", STATUE)
PULSE_MITIGATIONS = ("none",) + tuple(f"isolated_{t:g}s" for t in ISOLATION_PERIODS)
PULSE_TP = (0.2, 5.0)  # s
N_PULSE_TP = (4, 12)
PULSE_GRID = (0.2, 30.0)  # the scan of a_p / (g tan alpha)
N_PULSE_GRID = (20, 60)
PULSE_TOL = (0.05, 0.01)


# ------------------------------------------------------------------------ the inputs
def make_blocks() -> dict:
    """``{"specimen 2": ..., "specimen 3": ..., "specimen 4": ..., "statue": ...}``."""
    out = {f"specimen {n}": specimen(n, "experimental") for n in SPECIMENS}
    out[STATUE] = statue()
    return out


@contextlib.contextmanager
def derived_restitution_stated():
    """Silence the isolated model's notice that it derives its own restitution (the
    blocks' measured ``mu`` unused): the section's text states both values (the report's
    own choice, said in the page, not in the terminal)."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="model 'isolated' derives the impact "
                                "restitution", category=PlausibilityWarning)
        yield


def isolated_restitution(block) -> float:
    """The restitution the isolated model uses for ``block`` (derived from the momentum
    balance with the moving plate, Vassiliou and Makris 2012; the same for both
    isolation periods)."""
    model = get_model("isolated")
    opts = model.Options(**MITIGATIONS[f"isolated_{ISOLATION_PERIODS[0]:g}s"][1])
    with derived_restitution_stated():
        return float(model(block, opts).kernel_params(0.01, 0.0, 0.0).mu)


def building():
    """The 8-storey shear building of the buildings section."""
    return make_buildings()[STOREYS]


def records(quick: bool) -> list:
    """The first seed earthquakes of the paper's random tests."""
    return seed_earthquakes()[:N_RECORDS[not quick]]


def pga_levels(quick: bool) -> np.ndarray:
    """Ground PGA levels (g) of each record, shape ``(records, levels)``: ``records x
    levels`` values log-spaced from 0.05 to 2 g (the isolated blocks overturn only near
    the top of this range), dealt out in turn, so that record ``i`` has every
    ``records``-th value from the ``i``-th: every record spans the range, and the runs of
    a configuration cover ``records x levels`` distinct PGAs (a stripe design on a
    ladder this coarse separates the outcomes: no fragility fit exists)."""
    nr, nl = N_RECORDS[not quick], N_LEVELS[not quick]
    return np.geomspace(*PGA_RANGE, nr * nl).reshape(nl, nr).T.copy()


def floor_motions(recs: list, bld) -> dict:
    """``{"ground": [record, ...], "roof": [FloorMotion at the roof, ...]}`` (unscaled)."""
    return {"ground": list(recs),
            "roof": [FloorMotion(r, bld, floor=bld.n_floors) for r in recs]}


# ---------------------------------------------------------------------- computations
def run_all(blocks: dict, recs: list, fms: dict, levels: np.ndarray) -> pd.DataFrame:
    """Every run: each record scaled to its ground PGAs (g; ``levels[i]`` for record
    ``i``, :func:`pga_levels`) on each floor, for each block and mitigation; one
    :func:`~rocking.simulate_many` call per (mitigation, block, floor)."""
    rows = []
    for floor in FLOORS:
        motions, meta = [], []
        for i, (r, m) in enumerate(zip(recs, fms[floor], strict=True)):
            for lev in levels[i]:
                mm = m.scaled(lev * G / r.pga)
                motions.append(mm)
                meta.append((i + 1, float(lev), float(mm.pga) / G))
        for label, blk in blocks.items():
            for mit, (model, opts) in MITIGATIONS.items():
                res = simulate_many(blk, motions, model=model, **opts)
                out = res.outputs
                nan = np.full(len(motions), np.nan)
                u = np.asarray(out.get("max_base_displacement", nan), dtype=float)
                a = np.asarray(out.get("max_plate_acceleration", nan), dtype=float)
                fa = np.asarray(out.get("max_anchor_force", nan), dtype=float)
                broken = (np.asarray(out["anchor_broken_plus"], dtype=bool)
                          | np.asarray(out["anchor_broken_minus"], dtype=bool)
                          if "anchor_broken_plus" in out else np.zeros(len(motions), bool))
                for j, (rid, lev, fpga) in enumerate(meta):
                    rows.append({
                        "mitigation": mit, "model": model, "block": label, "floor": floor,
                        "record": rid, "pga_g": lev, "floor_pga_g": fpga,
                        "overturned": bool(res.overturned[j]),
                        "max_theta_over_alpha": float(res.max_abs_theta[j] / blk.alpha),
                        "uplifted": bool(res.rocked[j]), "settled": bool(res.settled[j]),
                        "max_base_displacement_m": float(u[j]),
                        "max_plate_acceleration_g": float(a[j]) / G,
                        "max_anchor_force": float(fa[j]),
                        "anchor_broken": bool(broken[j]),
                    })
    return pd.DataFrame(rows)


def pulse_periods(quick: bool) -> np.ndarray:
    return np.geomspace(*PULSE_TP, N_PULSE_TP[not quick])


def pulse_study(blocks: dict, quick: bool) -> pd.DataFrame:
    """Overturning spectra of one-sine pulses against the pulse period ``T_p`` (s), free
    and isolated, for :data:`PULSE_BLOCKS`: the minimum ``a_p / (g tan alpha)`` that
    overturns the block (:func:`~rocking.analysis.overturning_spectrum`) and, for the
    isolated base, the plate's displacement demand at that amplitude (no moat)."""
    tp = pulse_periods(quick)
    grid = np.geomspace(*PULSE_GRID, N_PULSE_GRID[not quick])
    tol = PULSE_TOL[not quick]
    rows = []
    for label in PULSE_BLOCKS:
        blk = blocks[label]
        w = 2.0 * math.pi / (tp * blk.p)
        for mit in PULSE_MITIGATIONS:
            model, opts = MITIGATIONS[mit]
            df = overturning_spectrum(blk, "one_sine", omega_ratio=w, model=model, tol=tol,
                                      accel_ratio=grid, **opts)
            ratio = df.min_overturn_ratio.to_numpy(dtype=float)
            disp = np.full(tp.size, np.nan)
            if model == "isolated":
                ok = np.flatnonzero(np.isfinite(ratio))
                if ok.size:
                    res = simulate_many(blk, [pulse_motion(blk, "one_sine", w[i], ratio[i])
                                              for i in ok], model=model, **opts)
                    disp[ok] = res.outputs["max_base_displacement"]
            for i in range(tp.size):
                rows.append({"block": label, "mitigation": mit, "tp_s": float(tp[i]),
                             "omega_ratio": float(w[i]),
                             "min_overturn_ratio": float(ratio[i]),
                             "min_overturn_pga_g": float(ratio[i] * math.tan(blk.alpha)),
                             "mode": df["mode"].iloc[i],
                             "base_displacement_at_overturn_m": float(disp[i]),
                             "n_simulations": int(df.attrs["n_simulations"])})
    return pd.DataFrame(rows)


def displacement_per_g(runs: pd.DataFrame) -> pd.DataFrame:
    """The isolator's displacement demand per g of ground PGA, per floor, isolation
    period and record: while the block stands on the plate the isolated system is linear
    (plate and block move as one mass), so ``max |u| = k PGA`` with ``k`` (m/g) fixed by
    the record; ``k`` is taken from the runs in which the block did not uplift (median
    over blocks and levels, with their relative spread as a check of the linearity)."""
    d = runs[(runs.model == "isolated") & ~runs.uplifted].copy()
    d["k"] = d.max_base_displacement / d.pga
    rows = []
    for (floor, mit, rec), g in d.groupby(["floor", "mitigation", "record"], sort=False):
        k = g.k.to_numpy()
        rows.append({"floor": floor, "mitigation": mit, "record": rec,
                     "displacement_per_g_m": float(np.median(k)),
                     "relative_spread": float((k.max() - k.min()) / np.median(k)),
                     "n_runs": len(k)})
    return pd.DataFrame(rows)


def clearance_pga(disp: pd.DataFrame) -> pd.DataFrame:
    """Per floor and isolation period: the ground PGA (g) at which the median (and the
    84th percentile) over the records of the displacement demand reaches the clearance."""
    rows = []
    for (floor, mit), g in disp.groupby(["floor", "mitigation"], sort=False):
        k = g.displacement_per_g_m.to_numpy()
        k50, k84 = float(np.median(k)), float(np.percentile(k, 84))
        rows.append({"floor": floor, "mitigation": mit, "n_records": len(k),
                     "displacement_per_g_median_m": k50, "displacement_per_g_p84_m": k84,
                     "pga_median_reaches_clearance_g": CLEARANCE / k50,
                     "pga_p84_reaches_clearance_g": CLEARANCE / k84})
    return pd.DataFrame(rows)


def compare(runs: pd.DataFrame, failure: str, quick: bool):
    """:func:`~rocking.analysis.compare_mitigations` of the runs by block and floor, IM =
    ground PGA in g, on the ILLUSTRATIVE hazard curve of the fragility section
    (:func:`.fragility.hazard_curve`, power-law tails beyond its ends), against
    :data:`CLEARANCE`."""
    hz = hazard_curve()
    return compare_mitigations(runs, im="pga", im_unit="g", failure=failure,
                               by=["block", "floor"], clearance=CLEARANCE,
                               hazard=hz,
                               n_boot=N_BOOT[not quick], seed=0)


def compute(quick: bool) -> dict:
    """Every table of the section (DataFrames), from the fixed lists and ``quick``.

    The specimens' measured restitutions (Table II E) are not used by the isolated model,
    which derives its own from the momentum of block and plate: the text states both, so
    the model's warning that says so is expected here and silenced."""
    with derived_restitution_stated():
        return compute_all(quick)


def compute_all(quick: bool) -> dict:
    """:func:`compute`, warnings as they come."""
    blocks, bld = make_blocks(), building()
    recs, levels = records(quick), pga_levels(quick)
    fms = floor_motions(recs, bld)
    runs = run_all(blocks, recs, fms, levels).rename(
        columns={"pga_g": "pga", "max_base_displacement_m": "max_base_displacement"})
    disp = displacement_per_g(runs)
    return {"quick": quick, "blocks": blocks, "building": bld, "records": recs,
            "levels": levels,
            "runs": runs, "comparison": compare(runs, "overturned", quick),
            "comparison_clearance": compare(runs, "overturned_or_clearance", quick),
            "displacement": disp, "clearance_pga": clearance_pga(disp),
            "pulses": pulse_study(blocks, quick)}


# ----------------------------------------------------------------------------- figures
def _iso_colours():
    return {m: PALETTE[i + 1] for i, m in enumerate(PULSE_MITIGATIONS[1:])}


def _fragility_figure(comparison):
    """:meth:`MitigationComparison.plot` with one legend for the figure (the mitigations'
    labels; the notes of the fits are in the tables) and short panel titles."""
    from matplotlib.lines import Line2D

    fig = comparison.plot(ncols=4, figsize=(14.0, 6.6))
    colours = {}
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        for h, lab in zip(*ax.get_legend_handles_labels(), strict=True):
            colours.setdefault(lab.split(":")[0], h.get_color())
        if ax.get_legend() is not None:
            ax.get_legend().remove()
        ax.set_title(ax.get_title().replace("block ", "").replace(", floor ", ", "),
                     fontsize=10)
    handles = [Line2D([], [], color=colours[m], marker="o", mfc="none", ms=4,
                      label=LABELS[m]) for m in MITIGATIONS if m in colours]
    fig.legend(handles=handles, loc="outside lower center", ncols=len(handles),
               fontsize=9, frameon=False)
    return fig


def _displacement_figure(runs, cpga):
    from matplotlib.figure import Figure

    fig = Figure(figsize=(10.0, 4.2), layout="constrained")
    axs = fig.subplots(1, len(FLOORS), sharey=True)
    cols = _iso_colours()
    iso = runs[runs.model == "isolated"]
    x = np.geomspace(*PGA_RANGE, 50)
    for ax, floor in zip(axs, FLOORS, strict=True):
        for mit, c in cols.items():
            d = iso[(iso.floor == floor) & (iso.mitigation == mit)]
            sel = d[d.block == STATUE]  # the plate's motion; every block gives the same
            up = sel.uplifted.to_numpy()
            ax.loglog(sel.pga[~up], sel.max_base_displacement[~up], "o", ms=3, color=c,
                      alpha=0.6, mec="none")
            ax.loglog(sel.pga[up], sel.max_base_displacement[up], "x", ms=4, color=c)
            r = cpga[(cpga.floor == floor) & (cpga.mitigation == mit)].iloc[0]
            ax.loglog(x, r.displacement_per_g_median_m * x, color=c, lw=1.4,
                      label=f"{LABELS[mit]}: median, {r.displacement_per_g_median_m:.3f} m/g")
            ax.loglog(x, r.displacement_per_g_p84_m * x, color=c, lw=1.0, ls="--",
                      label=f"{LABELS[mit]}: 84th percentile")
        ax.axhline(CLEARANCE, color="k", lw=1.0, ls=":")
        ax.text(PGA_RANGE[0] * 1.05, CLEARANCE * 1.08, f"clearance {CLEARANCE:g} m",
                fontsize=8)
        ax.set_title("ground" if floor == "ground" else
                     f"roof of the {STOREYS}-storey building", fontsize=10)
        style_axes(ax, "ground PGA (g)", "max base displacement |u| (m)" if floor == "ground"
                   else None)
    h, lab = axs[0].get_legend_handles_labels()
    fig.legend(h, lab, loc="outside lower center", ncols=2, fontsize=8, frameon=False)
    return fig


def _pulse_figure(pul, blocks):
    from matplotlib.figure import Figure

    fig = Figure(figsize=(10.5, 6.6), layout="constrained")
    axs = fig.subplots(2, len(PULSE_BLOCKS), sharex=True)
    cols = {"none": PALETTE[0], **_iso_colours()}
    for j, label in enumerate(PULSE_BLOCKS):
        blk = blocks[label]
        a0, a1 = axs[0, j], axs[1, j]
        free = pul[(pul.block == label) & (pul.mitigation == "none")]
        for mit in PULSE_MITIGATIONS:
            d = pul[(pul.block == label) & (pul.mitigation == mit)]
            a0.loglog(d.tp_s, d.min_overturn_ratio, marker="o", ms=3.5, lw=1.3,
                      color=cols[mit], label=LABELS[mit])
            if mit == "none":
                continue
            worse = d.min_overturn_ratio.to_numpy() < free.min_overturn_ratio.to_numpy()
            a0.loglog(d.tp_s[worse], d.min_overturn_ratio[worse], "o", ms=7, mfc="none",
                      color=cols[mit])
            a1.semilogx(d.tp_s, d.base_displacement_at_overturn_m, marker="o", ms=3.5,
                        color=cols[mit], label=LABELS[mit])
            tb = float(MITIGATIONS[mit][1]["isolation_period"])
            a1.axhline(G * math.tan(blk.alpha) * tb ** 2 / (4 * math.pi ** 2),
                       color=cols[mit], ls="--", lw=0.9)
        a0.axhline(1.0, color="0.5", lw=0.8, ls=":")
        a1.axhline(CLEARANCE, color="k", lw=1.0, ls=":")
        a1.text(PULSE_TP[0], CLEARANCE * 1.04, f"clearance {CLEARANCE:g} m", fontsize=8)
        a1.set_ylim(bottom=0.0)
        a0.set_title(f"{label} (α = {blk.alpha:.3f} rad, p = {blk.p:.2f} 1/s)", fontsize=10)
        style_axes(a0, None, "min overturning a_p / (g tan α)" if j == 0 else None)
        style_axes(a1, "pulse period T_p (s)",
                   "base displacement at that pulse (m)" if j == 0 else None)
        a0.legend(fontsize=8, frameon=False)
        ticks = [v for v in (0.2, 0.5, 1.0, 2.0, 5.0) if PULSE_TP[0] <= v <= PULSE_TP[1]]
        a1.set_xticks(ticks, [f"{v:g}" for v in ticks])
        a1.set_xticks([], minor=True)
    return fig


# ----------------------------------------------------------------------------- the page
def _median_cell(r) -> str:
    """The fitted median (g), or its bounds, with the ratio to the free block's."""
    if np.isfinite(r["median"]):
        out = f"{r['median']:.3f}" + ("*" if "extrapolated" in str(r.note) else "")
        if r.mitigation != "none" and np.isfinite(r.median_ratio):
            out += f" (×{r.median_ratio:.2f})"
        return out
    lo, hi = r.median_lower_bound, r.median_upper_bound
    if np.isfinite(lo) and np.isfinite(hi):
        return f"{lo:.3f}–{hi:.3f}"
    if np.isfinite(lo):
        out = f"> {lo:.3g}"
        if np.isfinite(r.median_ratio_lower_bound):
            out += f" (×>{r.median_ratio_lower_bound:.1f})"
        return out
    return f"< {hi:.3g}" if np.isfinite(hi) else "–"


def _af_cell(r) -> str:
    if np.isfinite(r.annual_frequency):
        out = f"{r.annual_frequency:.1e}"
        if r.mitigation != "none" and np.isfinite(r.annual_frequency_ratio):
            out += f" (×{r.annual_frequency_ratio:#.2g})"
        return out
    lo, hi = r.annual_frequency_lower_bound, r.annual_frequency_upper_bound
    if np.isfinite(lo) and np.isfinite(hi):
        return f"{lo:.1e}–{hi:.1e}"
    if np.isfinite(hi):
        return f"< {hi:.1e}"
    return f"> {lo:.1e}" if np.isfinite(lo) else "–"


def _result_table(tab, cell, caption) -> str:
    rows = []
    for (blk, floor), g in tab.groupby(["block", "floor"], sort=False):
        rows.append([H.Cell(blk, "l"), H.Cell(floor, "l")]
                    + [cell(g[g.mitigation == m].iloc[0]) for m in MITIGATIONS])
    return H.table(["block", "floor"] + [LABELS[m] for m in MITIGATIONS], rows,
                   caption=caption)


@section("mitigation", "Beyond the paper: what would make it safe (isolation, anchorage)",
         order=67, cost=20)
def build(ctx) -> str:
    res = compute(ctx.quick)
    blocks, runs, cmp_, cmpc = (res["blocks"], res["runs"], res["comparison"],
                                res["comparison_clearance"])
    pul, cpga, disp = res["pulses"], res["clearance_pga"], res["displacement"]
    nrec, nlev = res["levels"].shape
    ctx.save_csv(runs, "runs", float_format="%.6g")
    ctx.save_csv(cmp_.table, "comparison", float_format="%.6g")
    ctx.save_csv(cmpc.table, "comparison_with_clearance", float_format="%.6g")
    ctx.save_csv(disp, "displacement_per_g", float_format="%.6g")
    ctx.save_csv(cpga, "clearance_pga", float_format="%.6g")
    ctx.save_csv(pul, "pulses", float_format="%.6g")

    fig_f = ctx.save_figure(
        _fragility_figure(cmp_), "fragility",
        caption=(f"Overturning fragility against the ground PGA of each block on the ground "
                 f"and on the roof of the {STOREYS}-storey building, free, isolated and "
                 f"anchored ({nrec} seed earthquakes × {nlev} PGAs each, "
                 "rocking.analysis.compare_mitigations: probit GLM, Baker 2015). Circles: "
                 "the observed fraction overturned in bins of equal count of the PGA; a "
                 "mitigation without a fit (its outcomes separated by the PGA, or no "
                 "failure) shows its points only."))
    fig_d = ctx.save_figure(
        _displacement_figure(runs, cpga), "displacement",
        caption=("Displacement demand of the isolator (max |u| of the base plate relative to "
                 "the floor, no moat) against the ground PGA, statue runs (the plate moves "
                 "the same under every block while the block stands): dots, the block did "
                 "not uplift; crosses, it rocked (and the run stopped if it overturned); "
                 "lines, the median and 84th percentile over the records of the linear "
                 "system's demand per g; dotted, the 0.15 m clearance."))
    fig_p = ctx.save_figure(
        _pulse_figure(pul, blocks), "pulses",
        caption=("Where isolation does not help. Top: the minimum one-sine pulse amplitude "
                 "that overturns the block, a_p / (g tan α), against the pulse period, "
                 "free and isolated (rocking.analysis.overturning_spectrum with the model's "
                 "options); open circles: the isolated block overturns at a smaller "
                 "pulse than the free one. Bottom: the base plate's displacement at that "
                 "pulse (no moat); dashed, g tan α T_b² / (4π²), the displacement at which "
                 "the isolator's spring alone lifts the block; dotted, the 0.15 m "
                 "clearance."))
    tbl_m = _result_table(cmp_.table, _median_cell,
                          "Median ground PGA (g) of overturning (× the free block's); a range "
                          "or a bound where no fit exists (see the CSV's note); *: beyond "
                          f"the PGAs run (up to {PGA_RANGE[1]:g} g), extrapolated")
    tbl_c = _result_table(cmpc.table, _median_cell,
                          f"The same, counting a run whose isolator reached the {CLEARANCE:g} "
                          "m clearance as a failure")
    tbl_a = _result_table(cmp_.table, _af_cell,
                          "Mean annual frequency of overturning (1/yr) on the ILLUSTRATIVE "
                          "hazard curve (× the free block's); bounds where no fit exists")
    text = _text(res)
    return (H.p(text[0]) + H.p(text[1]) + fig_f + tbl_m + H.p(text[2]) + tbl_a
            + H.p(text[3]) + fig_d + tbl_c + H.p(text[4]) + fig_p + H.p(text[5])
            + ctx.files_html())


def _range(v, fmt="{:.2f}") -> str:
    v = np.asarray(v, dtype=float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return "–"
    lo, hi = float(v.min()), float(v.max())
    return fmt.format(lo) if fmt.format(lo) == fmt.format(hi) else (
        f"{fmt.format(lo)}–{fmt.format(hi)}")


def _intervals(x: np.ndarray, mask: np.ndarray) -> str:
    """The runs of consecutive grid points where ``mask`` holds, as "a–b s" ranges."""
    out, i = [], 0
    while i < mask.size:
        if not mask[i]:
            i += 1
            continue
        j = i
        while j + 1 < mask.size and mask[j + 1]:
            j += 1
        out.append(f"{x[i]:.2f} s" if i == j else f"{x[i]:.2f}–{x[j]:.2f} s")
        i = j + 1
    return " and ".join(out)


def _factor(v, what: str = "where both are fitted") -> str:
    """``"by a factor a–b where both are fitted"``, or that there is no such fit."""
    v = np.asarray(v, dtype=float)
    if not np.isfinite(v).any():
        return "(no configuration where both are fitted: see the bounds in the table)"
    return f"by a factor {_range(v)} {what}"


def _where(t, sel) -> str:
    return ", ".join(f"{r.block} on the {r.floor}" for r in t[sel].itertuples()) or "none"


def _text(res) -> list[str]:
    """The section's paragraphs, every number from the tables of :func:`compute`."""
    blocks, bld, runs = res["blocks"], res["building"], res["runs"]
    t, tc = res["comparison"].table, res["comparison_clearance"].table
    pul, cpga = res["pulses"], res["clearance_pga"]
    nrec, nlev = res["levels"].shape
    st = blocks[STATUE]
    iso_ids = [m for m in MITIGATIONS if m.startswith("isolated")]
    q = ANCHOR_STRENGTH

    setup = (
        "Which of the objects of the buildings section would a mitigation save, and at what "
        "cost? Specimens " + ", ".join(map(str, SPECIMENS)) + " (Table II E; α = "
        + ", ".join(f"{blocks[f'specimen {n}'].alpha:.3f}" for n in SPECIMENS)
        + " rad) and the statue of the buildings section (one rigid block "
          f"{STATUE_WIDTH:g} m wide and {STATUE_HEIGHT:g} m tall, {st.mass:.0f} kg: α = "
          f"{st.alpha:.3f} rad, p = {st.p:.2f} 1/s, R = {st.R:.2f} m) stand on the ground "
          f"and on the roof of its {STOREYS}-storey shear building (T1 = "
          f"{bld.periods[0]:.2f} s), each free (classical model), on an isolated base "
          "(model 'isolated': a linear isolator of period T_b = "
        + " or ".join(f"{v:g}" for v in ISOLATION_PERIODS)
        + f" s for plate and block together, {100 * ISOLATION_DAMPING:g} % damping, a plate "
          "as heavy as the block, the restitution derived from the momentum balance with "
          "the moving plate: " + ", ".join(f"{isolated_restitution(b):.3f}"
                                          for b in blocks.values())
        + " against the free blocks' " + ", ".join(f"{b.mu:.3f}" for b in blocks.values())
        + "; no moat, so that the isolator's whole displacement demand is "
          "recorded) and anchored (model 'anchored': rigid brittle anchors of strength "
          f"q = F_a / (m g) = {q:g} on each side; at rest the block lifts off only when the "
          f"floor acceleration exceeds (1 + 2q) g tan α = {1 + 2 * q:g} g tan α, and the "
          "anchor of that side breaks then; Makris and Zhang 2001). The motions are the "
          f"first {nrec} seed earthquakes of the paper's random tests, each scaled to "
          f"{nlev} ground PGAs: {nrec * nlev} PGAs log-spaced from {PGA_RANGE[0]:g} to "
          f"{PGA_RANGE[1]:g} g dealt out to the records in turn, so that each "
          f"configuration covers {nrec * nlev} distinct PGAs; on the roof the building "
          f"filters them (rocking.buildings.FloorMotion). {len(runs)} runs in all, each "
          "until the block settles or overturns. This is an example of the method on a few "
          "records, one building and a made-up hazard curve, not the assessment of any "
          "object or site.")

    # the fragility shift
    def ratios(m):
        d = t[t.mitigation == m]
        return d.median_ratio.to_numpy(float), d

    parts = []
    for m in iso_ids:
        r, d = ratios(m)
        lb = d.median_ratio_lower_bound.to_numpy(float)
        s = f"{LABELS[m]} multiplies the median {_factor(r)}"
        none_ = d[d.n_failed == 0]
        if len(none_):
            s += (f", and no record overturns {_where(d, d.n_failed == 0)} up to "
                  f"{PGA_RANGE[1]:g} g")
            if np.isfinite(lb).any():
                s += (f" (its median more than {_range(lb, '{:.1f}')} times the free "
                      "block's)")
        parts.append(s)
    ra, da = ratios("anchored")
    lower = da[da.median_ratio < 1.0]
    free = t[t.mitigation == "none"].set_index(["block", "floor"])
    fr = runs[runs.mitigation == "none"].set_index(["floor", "block", "record", "pga"])
    an = runs[runs.mitigation == "anchored"].set_index(["floor", "block", "record", "pga"])
    worse = int((an.overturned & ~fr.overturned).sum())
    better = int((~an.overturned & fr.overturned).sum())
    anch = (f"The anchors (q = {q:g}) change the median {_factor(ra)}")
    if len(lower):
        anch += ("; for " + ", ".join(
            f"{r.block} on the {r.floor} (median {r.median:.3f} g, 95 % "
            f"{r.median_ci_low:.3f}–{r.median_ci_high:.3f}, against the free block's "
            f"{free.loc[(r.block, r.floor), 'median']:.3f} g)" for r in lower.itertuples())
            + " the anchored median is even lower")
    anch += (f". Run by run, {worse} anchored blocks overturned where the free one did not "
             f"and {better} the other way round (of {len(an)} pairs): anchors add "
             "resistance at rest, not along every trajectory; a block held down until the "
             f"floor acceleration reaches {1 + 2 * q:g} g tan α is then released, its "
             "anchor broken, into a stronger motion than the one that lifts the free "
             "block.")
    frag = ("Fragility. The medians of overturning (table below; IM: the ground PGA, also "
            "for the roof, so that the building's amplification is part of the curve): "
            + "; ".join(parts) + ". " + anch)

    # annual frequency
    f_af = t[t.mitigation == "none"]
    rep = (f_af.annual_frequency.fillna(f_af.annual_frequency_upper_bound)
           .fillna(f_af.annual_frequency_lower_bound))
    lo_f, hi_f = f_af.loc[rep.idxmin()], f_af.loc[rep.idxmax()]
    af_parts = []
    for m in [*iso_ids, "anchored"]:
        d = t[t.mitigation == m]
        s = (f"{LABELS[m]}: × {_range(d.annual_frequency_ratio, '{:#.2g}')}"
             if np.isfinite(d.annual_frequency_ratio).any() else f"{LABELS[m]}: no ratio")
        nb = d[~np.isfinite(d.annual_frequency)]
        if len(nb):
            s += f" ({len(nb)} configurations without a fit: bounds in the table)"
        af_parts.append(s)
    afreq = (
        f"Annual frequency (ILLUSTRATIVE): on the example hazard curve of the fragility "
        f"section (site {HAZARD_SITE} of the shipped OpenQuake-format file "
        f"{HAZARD_FILE.name}, a made-up power law λ(PGA) = {HAZARD_K0:g} (PGA / "
        f"{HAZARD_A0:g} g)^−{HAZARD_K:g} per year, not the hazard of any site), the free "
        "blocks overturn with a mean annual "
        f"frequency from {_af_cell(lo_f)}/yr ({lo_f.block} on the {lo_f.floor}) "
        f"to {_af_cell(hi_f)}/yr ({hi_f.block} on the {hi_f.floor}); relative to "
        "them, " + "; ".join(af_parts) + ". The integrals run over the whole PGA range: "
        "beyond the file's levels (0.01-3 g) the curve goes on as a power law of its end "
        "slopes, as in the fragility section (rocking.analysis.hazard.risk). Only the "
        "method is meant: a real assessment needs the site's hazard curve, and more "
        "records.")

    # displacement demand against the clearance
    cp = cpga.set_index(["floor", "mitigation"])
    dparts = []
    for floor in FLOORS:
        dparts.append(f"on the {floor}, " + " and ".join(
            f"{cp.loc[(floor, m), 'displacement_per_g_median_m']:.3f} m per g "
            f"(T_b = {MITIGATIONS[m][1]['isolation_period']:g} s)" for m in iso_ids))
    reach = []
    for floor in FLOORS:
        reach.append(f"on the {floor} at " + " and ".join(
            f"{cp.loc[(floor, m), 'pga_median_reaches_clearance_g']:.2f} g "
            f"({cp.loc[(floor, m), 'pga_p84_reaches_clearance_g']:.2f} g for the 84th "
            "percentile)" for m in iso_ids))
    iso_t = t[t.mitigation.isin(iso_ids)]
    iso_c = tc[tc.mitigation.isin(iso_ids)]
    below = []
    for r in iso_t.itertuples():
        lim = cp.loc[(r.floor, r.mitigation), "pga_median_reaches_clearance_g"]
        med = r.median if np.isfinite(r.median) else r.median_lower_bound
        below.append(bool(lim < med))
    nb = sum(below)
    still = runs[(runs.model == "isolated") & ~runs.uplifted]
    acc = (still.max_plate_acceleration_g / still.floor_pga_g).groupby(
        [still.floor, still.mitigation]).median()
    m2, m3 = iso_ids[0], iso_ids[-1]
    fitted = iso_c[np.isfinite(iso_c.median_ratio)]
    least = fitted.loc[fitted.median_ratio.idxmin()] if len(fitted) else None
    dratio = [cp.loc[(f, m3), "displacement_per_g_median_m"]
              / cp.loc[(f, m2), "displacement_per_g_median_m"] for f in FLOORS]
    ex = iso_c.drop_duplicates(["floor", "mitigation"])
    disp = (
        "Displacement demand. While the block stands, plate and block move as one linear "
        "oscillator, so the isolator's displacement is proportional to the PGA; the median "
        "over the records is " + "; ".join(dparts) + " of ground PGA. The median demand "
        f"reaches the {CLEARANCE:g} m clearance " + "; ".join(reach) + ". That is below "
        "the isolated blocks' median overturning PGA (or its lower bound) in "
        + ("every configuration" if nb == len(below) else f"{nb} of {len(below)} "
           "configurations")
        + (": with a moat of this size the base would hit it before the block overturns, "
           "and the isolator's displacement, not the rocking, limits what isolation "
           "achieves" if 2 * nb > len(below) else "")
        + ". Counting a run whose base reached the clearance as a failure (second table), "
        f"the isolated medians become {_range(iso_c['median'], '{:.2f}')} g where fitted"
        + (f" (× {_range(iso_c.median_ratio)} the free block's; least gained: "
           f"{least.block} on the {least.floor}, {LABELS[least.mitigation]}, "
           f"× {least.median_ratio:.2f})" if least is not None else "")
        + f". T_b = {MITIGATIONS[m3][1]['isolation_period']:g} s gives a median plate "
        "acceleration of " + " and ".join(f"{acc[(f, m3)]:.2f}" for f in FLOORS)
        + " times the floor's PGA (ground, roof; T_b = "
        f"{MITIGATIONS[m2][1]['isolation_period']:g} s: "
        + " and ".join(f"{acc[(f, m2)]:.2f}" for f in FLOORS) + ") and "
        + " and ".join(f"{v:.2f}" for v in dratio) + " times its displacement"
        + (": the longer period lowers the acceleration but leaves the displacement "
           "demand about the same, as the records' target spectrum has a constant "
           f"displacement beyond T_D = {paper_target().td:g} s (EN 1998-1 shape)"
           if all(0.8 < v < 1.25 for v in dratio) else "")
        + ". Over the whole PGA ladder, the share of the isolated runs whose base reached "
          "the clearance is " + "; ".join(
            f"{floor}: " + ", ".join(
                f"{100 * ex[(ex.floor == floor) & (ex.mitigation == m)].p_clearance_exceeded.iloc[0]:.0f} % "  # noqa: E501
                f"(T_b = {MITIGATIONS[m][1]['isolation_period']:g} s)" for m in iso_ids)
            for floor in FLOORS) + ".")

    # pulses
    pparts, dmin, dmax, rel, over, any_worse = [], [], [], [], [], False
    for label in PULSE_BLOCKS:
        f = pul[(pul.block == label) & (pul.mitigation == "none")].set_index("tp_s")
        for m in PULSE_MITIGATIONS[1:]:
            d = pul[(pul.block == label) & (pul.mitigation == m)].set_index("tp_s")
            r = d.min_overturn_ratio / f.min_overturn_ratio
            worse_tp = r.index[r < 1.0]
            tb = MITIGATIONS[m][1]["isolation_period"]
            if len(worse_tp):
                any_worse = True
                k = r.idxmin()
                short = d.min_overturn_ratio[(r < 1.0) & (r.index < 0.5 * tb)]
                extra = (f" (below T_p = {0.5 * tb:g} s only above a_p = "
                         f"{short.min() * math.tan(blocks[label].alpha):.1f} g, "
                         f"{short.min():.0f} g tan α)" if len(short) else "")
                s = (f"{label}, T_b = {tb:g} s: more vulnerable at T_p = "
                     f"{_intervals(r.index.to_numpy(), (r < 1.0).to_numpy())}{extra}, at "
                     "worst at T_p = "
                     f"{k:.2f} s, where {r[k]:.2f} of the free block's pulse overturns it "
                     f"(a_p = {d.min_overturn_ratio[k]:.2f} g tan α)")
            else:
                s = f"{label}, T_b = {tb:g} s: never more vulnerable on this grid"
            safer = r[np.isfinite(r) & (r >= 1.0)]
            if len(safer):
                s += (f"; safer at T_p = {_intervals(r.index.to_numpy(), (r >= 1.0).to_numpy())}"
                      f", by a factor up to {safer.max():.1f} (T_p = {safer.idxmax():.2f} s)")
            never = d.index[~np.isfinite(d.min_overturn_ratio)]
            if len(never):
                s += (f", and not overturned at all (up to {PULSE_GRID[1]:g} g tan α) at "
                      f"T_p = {', '.join(f'{v:.2f}' for v in never)} s")
            pparts.append(s)
            u = d.base_displacement_at_overturn_m.to_numpy(float)
            u = u[np.isfinite(u)]
            if u.size:
                ustar = G * math.tan(blocks[label].alpha) * tb ** 2 / (4 * math.pi ** 2)
                dmin.append(u.min())
                dmax.append(u.max())
                rel.extend(u / ustar)
                over.append(bool(np.all(u > CLEARANCE)))
    lower_mu = all(isolated_restitution(blocks[b]) < blocks[b].mu for b in PULSE_BLOCKS)
    tp_long = float(pul.tp_s.max())
    lg = pul[pul.tp_s == tp_long]
    long_free = lg[lg.mitigation == "none"].min_overturn_ratio
    long_iso = lg[lg.mitigation != "none"].min_overturn_ratio
    ustar_all = {(label, m): G * math.tan(blocks[label].alpha)
             * MITIGATIONS[m][1]["isolation_period"] ** 2 / (4 * math.pi ** 2)
             for label in PULSE_BLOCKS for m in PULSE_MITIGATIONS[1:]}
    pulses = (
        "Where isolation does not help. Vassiliou and Makris (2012, Earthquake Engng "
        "Struct. Dyn. 41, 177-196) found that an isolated base can make a small free-"
        "standing block more vulnerable to long-period pulses: the isolator, tuned to "
        "filter short periods, amplifies the pulses near its own period and moves the "
        "plate with them. The overturning spectra of one-sine pulses (figure; "
        f"{pul.tp_s.nunique()} periods from {PULSE_TP[0]:g} to {PULSE_TP[1]:g} s, each "
        f"threshold to {100 * PULSE_TOL[not res['quick']]:g} %) show "
        + ("it here too: " if any_worse else "no such case here: ")
        + "; ".join(pparts) + ". "
        + ("The isolated block loses more energy at each impact than the free one (its "
           "restitution is lower, see above), so a smaller loss at impacts does not explain "
           "it. " if lower_mu and any_worse else "")
        + f"At T_p = {tp_long:.2f} s the free blocks need a_p = "
        + _range(long_free) + " g tan α (1: the quasi-static uplift), the isolated ones "
        + _range(long_iso) + ". At the isolated blocks' thresholds the plate moves "
        f"{min(dmin):.2f}–{max(dmax):.2f} m relative to the ground, {_range(rel)} times "
        "g tan α T_b² / (4π²) ("
        + ", ".join(f"{v:.2f} m" for v in ustar_all.values())
        + " for " + ", ".join(f"{lab}, T_b = {MITIGATIONS[m][1]['isolation_period']:g} s"
                              for lab, m in ustar_all)
        + "), the displacement at which the isolator's spring alone pushes the plate hard "
          "enough to lift the block: "
        + ("more than the 0.15 m clearance in every case, so with such a moat the base "
           "would hit it first and what the impact does decides the outcome (not modelled: "
           "the run stops there)." if all(over) else
           "not always more than the 0.15 m clearance (see the CSV)."))

    limits = (
        "Limits: a linear isolator with viscous damping (a friction pendulum, "
        "isolation='pendulum', behaves differently at small amplitudes), a rigid plate "
        "whose mass equals the block's, no impact with the moat (the run stops at the "
        "clearance, and here no clearance was set), planar motion without sliding, "
        f"brittle rigid anchors of one strength (q = {q:g}, chosen for the example), "
        "horizontal motions only, the roof of one linear building, and "
        f"{nrec} records per configuration: the fits' β and the bounds are coarse (the CSVs "
        "hold the 95 % intervals and every run).")
    return [setup, frag, afreq, disp, pulses, limits]
