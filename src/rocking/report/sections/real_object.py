"""Section: a real object (beyond the paper; issue 20).

The example mesh shipped with the package (:func:`rocking.shapes.load_example`, a
synthetic statue-like body of density 2600 kg/m^3) is read, validated and given its mass
properties; its directional parameters (:func:`rocking.shapes.directional_parameters`)
every 15 deg give the weakest and the strongest direction of shaking (the smallest and the
largest critical angle of the weaker side). The overturning fragility of the planar
blocks of those two directions (classical model, asymmetric sides) is fitted against the
PGA from the seed earthquakes of the paper's random tests scaled to a ladder of PGAs, the
same motions in both directions. Finally the two horizontal components of the built-in
Northridge 1994 Rinaldi record (228 and 318 deg; the object's x axis along the first) are
projected on every direction and run at a few scale factors
(:func:`rocking.analysis.direction_sweep`), with and without the vertical component:
max ``|theta|`` / alpha against the direction, and the worst direction against the static
weakest one.

The planar analysis in each direction is the standard engineering answer until a 3-D
model exists: no coupling between directions, no twisting, no wobbling.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from ...analysis import direction_sweep
from ...analysis.directions import plot_sweeps
from ...analysis.fragility import fit_or_bounds
from ...blocks import Block
from ...models import simulate_many
from ...motions import HorizontalPair, seed_earthquakes
from ...plot import PALETTE, style_axes
from ...shapes import (
    directional_parameters,
    load_example,
    plot_directional,
    strongest_direction,
    weakest_direction,
)
from ...units import G
from .. import html as H
from ..core import section

DENSITY = 2600.0  # kg/m^3
TABLE_STEP = 15.0  # deg: the directional table
PAIR = "rinaldi"
SCALES = ((0.25, 0.5, 1.0), (0.25, 0.5, 0.75, 1.0))  # quick, default
SWEEP_STEP = (15.0, 7.5)  # deg, over [0, 180)
N_RECORDS = (10, 20)  # quick, default (the fits need enough runs near the median)
N_LEVELS = (8, 10)
PGA_RANGE = (0.1, 2.5)  # g
N_BOOT = (50, 200)


# ------------------------------------------------------------------------ computations
def mass_table(shape) -> pd.DataFrame:
    """The mass properties as rows ``(quantity, value, unit)``."""
    w = np.linalg.eigvalsh(np.asarray(shape.inertia))
    com = np.asarray(shape.com)
    rows = [("triangles", len(shape.faces), "-"), ("vertices", len(shape.vertices), "-"),
            ("height", shape.height, "m"), ("volume", shape.volume, "m^3"),
            ("density", shape.density, "kg/m^3"), ("mass", shape.mass, "kg"),
            ("centre of mass x", com[0], "m"), ("centre of mass y", com[1], "m"),
            ("centre of mass z", com[2], "m"),
            ("h (centre of mass above the base)", shape.h, "m"),
            ("principal inertia I1", w[0], "kg m^2"), ("principal inertia I2", w[1], "kg m^2"),
            ("principal inertia I3", w[2], "kg m^2"),
            ("support area", shape.support_area, "m^2"),
            ("support hull vertices", len(shape.support), "-"),
            ("contact points", shape.contact_points, "-")]
    return pd.DataFrame(rows, columns=["quantity", "value", "unit"])


def pga_levels(quick: bool) -> np.ndarray:
    """PGA levels (g) per record, ``(records, levels)``: ``records x levels`` values
    log-spaced over :data:`PGA_RANGE` dealt out to the records in turn (as in the
    mitigation section), so that the runs of a direction cover distinct PGAs."""
    nr, nl = N_RECORDS[not quick], N_LEVELS[not quick]
    return np.geomspace(*PGA_RANGE, nr * nl).reshape(nl, nr).T.copy()


def fragility_runs(shape, directions: dict, quick: bool) -> pd.DataFrame:
    """The seed earthquakes scaled to :func:`pga_levels`, run on the planar block of each
    direction (classical model; one :func:`rocking.simulate_many` batch per direction, the
    same motions in each)."""
    recs = seed_earthquakes()[:N_RECORDS[not quick]]
    levels = pga_levels(quick)
    motions, meta = [], []
    for i, r in enumerate(recs):
        for lev in levels[i]:
            motions.append(r.scaled(lev * G / r.pga))
            meta.append((i + 1, float(lev)))
    rows = []
    for label, d in directions.items():
        blk = Block.from_shape(shape, d.phi)
        res = simulate_many(blk, motions)
        for j, (rid, lev) in enumerate(meta):
            rows.append({"direction": label, "phi_deg": d.phi_deg,
                         "alpha_plus": blk.alpha_plus, "alpha_minus": blk.alpha_minus,
                         "record": rid, "pga_g": lev,
                         "max_abs_theta": float(res.max_abs_theta[j]),
                         "overturned": bool(res.overturned[j]),
                         "uplifted": bool(res.rocked[j])})
    return pd.DataFrame(rows)


def fit_fragility(runs: pd.DataFrame, quick: bool) -> tuple[pd.DataFrame, dict]:
    """A lognormal fit (:func:`rocking.analysis.fragility`, IM = PGA in g) per direction;
    where the outcomes do not admit one, bounds on the median instead."""
    rows, fits = [], {}
    for label, g in runs.groupby("direction", sort=False):
        x, y = g.pga_g.to_numpy(float), g.overturned.to_numpy(bool)
        row = {"direction": label, "phi_deg": float(g.phi_deg.iloc[0]),
               "alpha_plus": float(g.alpha_plus.iloc[0]),
               "alpha_minus": float(g.alpha_minus.iloc[0]), "n": len(g),
               "n_overturned": int(y.sum()), "median_g": math.nan, "beta": math.nan,
               "median_se_g": math.nan, "median_lower_bound_g": math.nan,
               "median_upper_bound_g": math.nan, "note": ""}
        fit, lo, hi, why = fit_or_bounds(x, y, n_boot=N_BOOT[not quick], seed=0,
                                         im_name="pga", im_unit="g",
                                         label=f"overturning, {label}")
        if fit is not None:
            fits[label] = fit
            row.update(median_g=fit.median, beta=fit.beta, median_se_g=fit.median_se)
        else:  # no MLE: the median lies between the PGAs the outcomes allow
            row.update(median_lower_bound_g=lo, median_upper_bound_g=hi,
                       note=f"no fragility fit ({why}): bounds of the median")
        rows.append(row)
    return pd.DataFrame(rows), fits


def sweep_directions(quick: bool) -> np.ndarray:
    return np.radians(np.arange(0.0, 180.0 - 1e-9, SWEEP_STEP[not quick]))


def sweeps(shape, pair, quick: bool) -> tuple[pd.DataFrame, dict]:
    """:func:`rocking.analysis.direction_sweep` of the shape under the pair at each scale,
    without and with the vertical component; the long table and the sweeps by
    ``(scale, vertical)``."""
    phis = sweep_directions(quick)
    out, frames = {}, []
    for vertical in (False, True):
        for s in SCALES[not quick]:
            sw = direction_sweep(shape, pair, phis, scale=s, vertical=vertical)
            out[(s, vertical)] = sw
            t = sw.table.copy()
            t.insert(0, "vertical", vertical)
            t.insert(0, "scale", s)
            frames.append(t)
    return pd.concat(frames, ignore_index=True), out


def worst_table(sw: dict, weak) -> pd.DataFrame:
    """The worst direction of each sweep and its angle to the static weakest direction
    (modulo 180 deg: ``phi + 180`` is the mirror image)."""
    rows = []
    for (s, vertical), x in sw.items():
        w = x.worst
        t = x.table
        d = abs((w.phi_deg - weak.phi_deg + 90.0) % 180.0 - 90.0)
        dem = t.loc[t.uplift_demand.idxmax()]
        rows.append({"scale": s, "vertical": vertical, "worst_phi_deg": float(w.phi_deg),
                     "worst_overturned": bool(w.overturned),
                     "worst_overturn_time": float(w.overturn_time),
                     "worst_max_abs_theta_over_alpha": float(w.max_abs_theta_over_alpha),
                     "n_overturned": int(t.overturned.sum()), "n_directions": len(t),
                     "n_uplifted": int(t.uplift_time.notna().sum()),
                     "static_weakest_phi_deg": weak.phi_deg,
                     "angle_to_static_weakest_deg": float(d),
                     "max_uplift_demand_phi_deg": float(dem.phi_deg),
                     "max_uplift_demand": float(dem.uplift_demand),
                     "pga_at_worst_g": float(w.pga) / G,
                     "pga_at_static_weakest_g": float(
                         t.loc[(t.phi_deg - weak.phi_deg % 180.0).abs().idxmin(), "pga"]) / G})
    return pd.DataFrame(rows)


def compute(quick: bool) -> dict:
    """Every table of the section, from the fixed lists and ``quick``."""
    shape = load_example(density=DENSITY)
    table = directional_parameters(shape, np.radians(np.arange(0.0, 360.0, TABLE_STEP)))
    weak, strong = weakest_direction(table), strongest_direction(table)
    runs = fragility_runs(shape, {"weakest": weak, "strongest": strong}, quick)
    frag, fits = fit_fragility(runs, quick)
    pair = HorizontalPair.builtin(PAIR)
    long, sw = sweeps(shape, pair, quick)
    return {"quick": quick, "shape": shape, "mass": mass_table(shape), "table": table,
            "weak": weak, "strong": strong, "exact_weak": shape.weakest(), "runs": runs,
            "fragility": frag, "fits": fits, "pair": pair, "sweep": long, "sweeps": sw,
            "worst": worst_table(sw, weak)}


# ----------------------------------------------------------------------------- figures
def _mesh_figure(shape, weak):
    from matplotlib.collections import PolyCollection
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    v, f = np.asarray(shape.local_vertices), np.asarray(shape.faces)
    tri = v[f]
    fig = Figure(figsize=(12.0, 3.9), layout="constrained")
    ax3 = fig.add_subplot(1, 4, 1, projection="3d")
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.linalg.norm(n, axis=1, keepdims=True) + 1e-300
    light = np.array([-0.4, -0.6, 0.7]) / np.linalg.norm([-0.4, -0.6, 0.7])
    shade = 0.35 + 0.6 * np.clip(n @ light, 0.0, 1.0)
    base = np.array([0.80, 0.74, 0.62])
    ax3.add_collection3d(Poly3DCollection(tri, facecolors=shade[:, None] * base,
                                          edgecolors="none"))
    lo, hi = v.min(axis=0), v.max(axis=0)
    half = 0.5 * float(np.max(hi - lo))
    mid = 0.5 * (lo + hi)
    ax3.set_xlim(mid[0] - half, mid[0] + half)
    ax3.set_ylim(mid[1] - half, mid[1] + half)
    ax3.set_zlim(0.0, 2 * half)
    ax3.set_box_aspect((1, 1, 1))
    ax3.view_init(elev=18, azim=-60)
    ticks = np.round(np.linspace(-0.5, 0.5, 3) * half, 1)
    ax3.set_xticks(mid[0] + ticks, [f"{t:g}" for t in ticks])
    ax3.set_yticks(mid[1] + ticks, [f"{t:g}" for t in ticks])
    ax3.set_zticks(np.round(np.linspace(0.0, 2 * half, 3), 1))
    ax3.set_xlabel("x (m)", fontsize=8)
    ax3.set_ylabel("y (m)", fontsize=8)
    ax3.tick_params(labelsize=7)
    ax3.set_title("the example mesh", fontsize=10)
    for k, (i, name) in enumerate(((0, "x"), (1, "y"))):
        ax = fig.add_subplot(1, 4, 2 + k)
        ax.add_collection(PolyCollection(tri[:, :, [i, 2]], facecolors="0.55",
                                         edgecolors="0.55", linewidths=0.3))
        ax.plot([0.0], [shape.h], "o", color=PALETTE[1], ms=5)
        ax.annotate("centre of mass", (0.0, shape.h), xytext=(6, -12),
                    textcoords="offset points", fontsize=7, color=PALETTE[1])
        ax.axvline(0.0, color=PALETTE[1], lw=0.8, ls=":")
        ax.set_xlim(mid[i] - 0.6 * half * 1.2, mid[i] + 0.6 * half * 1.2)
        ax.set_ylim(0.0, shape.height * 1.03)
        ax.set_aspect("equal")
        style_axes(ax, f"{name} (m)", "z (m)" if k == 0 else None)
        ax.set_title(f"silhouette on the {name}-z plane", fontsize=10)
    ax = fig.add_subplot(1, 4, 4)
    ax.add_collection(PolyCollection(tri[:, :, :2], facecolors="0.85", edgecolors="0.85",
                                     linewidths=0.3))
    ax.plot([], [], color="0.85", lw=6, label="the body seen from above")
    sup = np.vstack([shape.support, shape.support[:1]])
    ax.plot(sup[:, 0], sup[:, 1], color=PALETTE[0], lw=1.5, label="support hull")
    ax.plot([0.0], [0.0], "o", color=PALETTE[1], ms=5, label="centre of mass")
    r = float(np.min(np.hypot(shape.support[:, 0], shape.support[:, 1])))
    ph = weak.phi
    ax.plot([-r * math.cos(ph), r * math.cos(ph)], [-r * math.sin(ph), r * math.sin(ph)],
            color=PALETTE[3], lw=1.6, label=f"weakest direction, {weak.phi_deg:.0f} deg")
    ax.set_title("plan", fontsize=10)
    ax.set_xlim(lo[0] - 0.05, hi[0] + 0.05)
    ax.set_ylim(lo[1] - 0.05, hi[1] + 0.05)
    ax.set_aspect("equal")
    style_axes(ax, "x (m)", "y (m)")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.22), frameon=False,
              ncols=2)
    return fig


def _fragility_figure(runs, frag, fits):
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.0, 4.2), layout="constrained")
    ax = fig.add_subplot()
    x = np.geomspace(PGA_RANGE[0], PGA_RANGE[1] * 1.5, 200)
    for i, r in enumerate(frag.itertuples()):
        c = PALETTE[i]
        g = runs[runs.direction == r.direction]
        lab = (f"{r.direction}: phi = {r.phi_deg:.0f} deg, α+ / α- = {r.alpha_plus:.3f} / "
               f"{r.alpha_minus:.3f} rad")
        if r.direction in fits:
            ax.semilogx(x, fits[r.direction].probability(x), color=c, lw=1.6,
                        label=f"{lab}; median {r.median_g:.2f} g, β {r.beta:.2f}")
        else:
            ax.plot([], [], color=c, label=f"{lab}; no fit")
        off = 1.0 + 0.02 * (i - 0.5)
        ax.semilogx(g.pga_g * off, g.overturned.astype(float), "o", mfc="none", color=c,
                    ms=4)
    ax.set_ylim(-0.05, 1.05)
    style_axes(ax, "PGA (g)", "P(overturning)")
    fig.legend(*ax.get_legend_handles_labels(), fontsize=8, loc="outside lower center",
               frameon=False)
    return fig


def _sweep_figure(sw, weak, scales, pair):
    from matplotlib.figure import Figure

    fig = Figure(figsize=(11.0, 4.8), layout="constrained")
    axp = fig.add_subplot(1, 2, 1, projection="polar")
    sel = [sw[(s, False)] for s in scales]
    plot_sweeps(sel, [f"scale {s:g} (PGA {s * pair.pga_components[0] / G:.2f} g on the "
                      f"{pair.azimuths_deg[0]:.0f} deg component)" for s in scales],
                reference=weak.phi, ax=axp)
    axp.get_legend().remove()
    fig.legend(*axp.get_legend_handles_labels(), loc="outside lower left", fontsize=8,
               frameon=False)
    axp.set_title("max |θ| / α against phi (x: overturned; dashed: static weakest)",
                  fontsize=9)
    ax = fig.add_subplot(1, 2, 2)
    t = sw[(1.0, False)].table
    ax.plot(t.phi_deg, t.pga / G, color=PALETTE[0], marker="o", ms=3,
            label="PGA along phi at scale 1 (g)")
    cap = np.minimum(np.tan(t.alpha_plus), np.tan(t.alpha_minus))
    ax.plot(t.phi_deg, cap, color=PALETTE[2], marker="s", ms=3,
            label="uplift of the weaker side, tan α (g)")
    ax.axvline(weak.phi_deg % 180.0, color="k", ls="--", lw=1.0,
               label="static weakest direction")
    ax.set_xlim(0.0, 180.0)
    ax.set_ylim(bottom=0.0)
    ax.set_xticks(np.arange(0, 181, 30))
    style_axes(ax, "direction phi (deg)", "acceleration (g)")
    ax2 = ax.twinx()
    ax2.plot(t.phi_deg, t.uplift_demand, color=PALETTE[1], ls="--",
             label="demand / capacity (right axis)")
    ax2.set_ylim(bottom=0.0)
    ax2.set_ylabel("PGA along phi / uplift acceleration of the side", fontsize=9)
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=8, frameon=False, loc="lower left")
    ax.set_title("the record's demand and the object's capacity per direction", fontsize=9)
    return fig


# ----------------------------------------------------------------------------- the page
@section("real_object", "Beyond the paper: a real object (a 3-D mesh)", order=68, cost=4)
def build(ctx) -> str:
    res = compute(ctx.quick)
    shape, table, weak = res["shape"], res["table"], res["weak"]
    frag, runs, long, worst = res["fragility"], res["runs"], res["sweep"], res["worst"]
    pair = res["pair"]
    scales = SCALES[not ctx.quick]
    ctx.save_csv(res["mass"], "mass_properties", float_format="%.8g")
    ctx.save_csv(table, "directional", float_format="%.8g")
    ctx.save_csv(runs, "fragility_runs", float_format="%.8g")
    ctx.save_csv(frag, "fragility", float_format="%.8g")
    ctx.save_csv(long, "sweep", float_format="%.17g")
    ctx.save_csv(worst, "worst", float_format="%.8g")

    fig_m = ctx.save_figure(
        _mesh_figure(shape, weak), "mesh",
        caption=("The example mesh (rocking.shapes.load_example: a synthetic statue-like "
                 "body written by data/make_example.py): a shaded view, its silhouettes "
                 "on the two vertical planes of the axes with the centre of mass, and the "
                 "plan with the support hull (the contact patch's convex hull) and the "
                 "weakest direction of the table."))
    fig_d = ctx.save_figure(
        plot_directional(table), "directional",
        caption=(f"Directional parameters every {TABLE_STEP:g} deg "
                 "(rocking.shapes.plot_directional): the smaller critical angle of the "
                 "two sides and the smaller uplift acceleration against the direction of "
                 "shaking, the weakest direction marked."))
    fig_f = ctx.save_figure(
        _fragility_figure(runs, frag, res["fits"]), "fragility",
        caption=("Overturning fragility of the planar blocks of the weakest and the "
                 "strongest direction (classical model with the two sides' α, p and "
                 "restitutions), against the PGA, from the same scaled seed earthquakes; "
                 "circles: each run (1: overturned), shifted apart slightly."))
    fig_s = ctx.save_figure(
        _sweep_figure(res["sweeps"], weak, scales, pair), "sweep",
        caption=("Two horizontal components: the Rinaldi record (Northridge 1994) projected "
                 "on each direction phi of the object (its x axis along the "
                 f"{pair.azimuths_deg[0]:.0f} deg component), horizontal only. Left: "
                 "max |θ| / α (capped at 1; the side's α) at each scale factor, "
                 "phi + 180 deg drawn as the mirror image of phi; the dashed line is the "
                 "static weakest direction. Right: at scale 1, the PGA along phi, the "
                 "uplift acceleration of the weaker side (g tan α, in g) and their ratio."))

    m = res["mass"].set_index("quantity")
    mrows = [[H.Cell(q, "l"), H.fmt(float(r.value), 4) if r.unit != "-" else f"{int(r.value)}",
              r.unit] for q, r in m.iterrows()]
    tbl_m = H.table(["quantity", "value", "unit"], mrows,
                    caption="Mass properties of the example mesh (coordinates of the file)")
    drows = []
    for r in table.iloc[::2].itertuples():
        drows.append([f"{r.phi_deg:.0f}", f"{r.alpha_plus:.4f}", f"{r.alpha_minus:.4f}",
                      f"{r.p_plus:.3f}", f"{r.p_minus:.3f}", f"{r.mu_plus:.3f}",
                      f"{r.mu_minus:.3f}", f"{r.uplift_plus / G:.3f}",
                      f"{r.uplift_minus / G:.3f}"])
    tbl_d = H.table(["phi (deg)", "α+ (rad)", "α- (rad)", "p+ (1/s)", "p- (1/s)", "μ+", "μ-",
                     "uplift + (g)", "uplift - (g)"], drows,
                    caption=(f"Directional parameters every {2 * TABLE_STEP:g} deg (every "
                             f"{TABLE_STEP:g} deg in the CSV)"))
    frows = []
    for r in frag.itertuples():
        med = (f"{r.median_g:.3f} ± {r.median_se_g:.3f}" if np.isfinite(r.median_g) else
               f"{H.fmt(r.median_lower_bound_g)}–{H.fmt(r.median_upper_bound_g)}")
        frows.append([H.Cell(r.direction, "l"), f"{r.phi_deg:.0f}",
                      f"{min(r.alpha_plus, r.alpha_minus):.4f}", f"{r.n_overturned} / {r.n}",
                      med, H.fmt(r.beta, 2)])
    tbl_f = H.table(["direction", "phi (deg)", "α of the weaker side (rad)", "overturned",
                     "median PGA (g)", "β"], frows,
                    caption="Fragility in the weakest and the strongest direction")
    wrows = []
    for r in worst.itertuples():
        wrows.append([f"{r.scale:g}", "yes" if r.vertical else "no",
                      f"{r.worst_phi_deg:.1f}",
                      (f"overturned at {r.worst_overturn_time:.2f} s" if r.worst_overturned
                       else f"max |θ|/α = {r.worst_max_abs_theta_over_alpha:.3f}"),
                      f"{r.n_overturned} / {r.n_directions}",
                      f"{r.angle_to_static_weakest_deg:.1f}",
                      f"{r.max_uplift_demand_phi_deg:.1f}"])
    tbl_w = H.table(["scale", "vertical", "worst phi (deg)", "worst response",
                     "directions overturned", "angle to the static weakest (deg)",
                     "phi of the largest PGA / (g tan α) (deg)"], wrows,
                    caption="The worst direction of each sweep")
    text = _text(res)
    return (H.p(text[0]) + fig_m + tbl_m + H.p(text[1]) + fig_d + tbl_d + H.p(text[2])
            + fig_f + tbl_f + H.p(text[3]) + fig_s + tbl_w + H.p(text[4]) + H.p(text[5])
            + ctx.files_html())


def _text(res) -> list[str]:
    """The section's paragraphs, every number from the tables of :func:`compute`."""
    shape, table, weak, strong = res["shape"], res["table"], res["weak"], res["strong"]
    exact, frag, worst, pair = res["exact_weak"], res["fragility"], res["worst"], res["pair"]
    runs = res["runs"]
    nrec = int(runs.record.nunique())
    nlev = len(runs) // (2 * nrec)
    w_ = table.iloc[int(weak.index)]
    s_ = table.iloc[int(strong.index)]
    intro = (
        f"A scanned object is a mesh, not a rectangle. The example mesh shipped with the "
        f"package ({len(shape.faces)} triangles, {shape.height:.2f} m tall) is read, welded "
        "and checked (watertight, consistent winding, positive volume), and its mass "
        f"properties follow from the divergence theorem: with a density of {DENSITY:g} "
        f"kg/m^3 it weighs {shape.mass:.1f} kg, its centre of mass is {shape.h:.3f} m above "
        f"the base, and it stands on a contact patch of {shape.contact_points} vertices "
        f"whose convex hull (the support) has {len(shape.support)} corners and "
        f"{shape.support_area:.4f} m^2.")
    direc = (
        "Each horizontal direction of shaking phi has its own planar block: the pivot lines "
        "are the support hull's supporting lines normal to phi, one on each side, so the "
        "block is asymmetric (α+, α-, p, and the restitution from angular momentum about "
        f"the new pivot, per side). Over the table every {TABLE_STEP:g} deg the critical "
        f"angle of the weaker side ranges from {table.alpha_min.min():.4f} to "
        f"{table.alpha_min.max():.4f} rad: the weakest direction of the table is phi = "
        f"{weak.phi_deg:.0f} deg (side {weak.side}, α = {weak.alpha:.4f} rad, uplift at "
        f"{weak.uplift_g:.3f} g), the exact one, the normal of the support edge nearest to "
        f"the centre of mass, phi = {exact.phi_deg:.1f} deg (side {exact.side}, α = "
        f"{exact.alpha:.4f} rad; phi + 180 deg with the other side is the same pivot); "
        f"the strongest is phi = {strong.phi_deg:.0f} deg (its weaker side α = "
        f"{strong.alpha:.4f} rad, uplift at {strong.uplift_g:.3f} g). The frequency "
        f"parameter p barely changes ({table[['p_plus', 'p_minus']].min().min():.3f} to "
        f"{table[['p_plus', 'p_minus']].max().max():.3f} 1/s): the body's size is the "
        "same in every direction, its slenderness is not.")
    fw = frag.set_index("direction")

    def med(label):
        r = fw.loc[label]
        if np.isfinite(r.median_g):
            return f"{r.median_g:.3f} g (± {r.median_se_g:.3f}, β = {r.beta:.2f})"
        return (f"between {H.fmt(r.median_lower_bound_g)} and "
                f"{H.fmt(r.median_upper_bound_g)} g (no fit: {r.note})")

    ratio = fw.loc["weakest", "median_g"] / fw.loc["strongest", "median_g"]
    uplift_ratio = weak.uplift / strong.uplift
    cmp_ = (f"the weakest direction's median is {ratio:.2f} times the strongest's, against "
            f"a ratio of the weaker sides' uplift accelerations of {uplift_ratio:.2f}: "
            + ("the dynamic margin between the directions is larger than the static one"
               if ratio < uplift_ratio else
               "the dynamic margin between the directions is not larger than the static one")
            if np.isfinite(ratio) else "no ratio of the medians exists in this run")
    fragt = (
        f"Fragility. The {nrec} first seed earthquakes of the paper's random tests, each "
        f"scaled to {nlev} PGAs ({nrec * nlev} distinct PGAs from {PGA_RANGE[0]:g} to "
        f"{PGA_RANGE[1]:g} g), run on the planar blocks of the weakest (phi = "
        f"{weak.phi_deg:.0f} deg, α+ / α- = {w_.alpha_plus:.4f} / {w_.alpha_minus:.4f} rad) "
        f"and the strongest direction (phi = {strong.phi_deg:.0f} deg, "
        f"{s_.alpha_plus:.4f} / {s_.alpha_minus:.4f} rad), the same motions in both. "
        f"Median PGA of overturning: weakest {med('weakest')}, strongest "
        f"{med('strongest')}; {cmp_}. Overturned runs: "
        f"{int(fw.loc['weakest', 'n_overturned'])} and "
        f"{int(fw.loc['strongest', 'n_overturned'])} of {int(fw.loc['weakest', 'n'])}.")
    az = pair.azimuths_deg
    h1 = worst[~worst.vertical]
    calm = h1[h1.n_uplifted == 0]
    still = ("" if calm.empty else
             " At scale " + ", ".join(f"{v:g}" for v in calm.scale) + " the block lifts off "
             "in no direction: the worst direction is then the one of the largest ratio of "
             "the PGA along phi to the side's uplift acceleration.")
    sweep = (
        f"Two horizontal components. The Rinaldi record of the Northridge 1994 earthquake "
        f"(components at {az[0]:.0f} and {az[1]:.0f} deg, PGA {pair.pga_components[0] / G:.3f}"
        f" and {pair.pga_components[1] / G:.3f} g, the largest horizontal acceleration "
        f"vector {pair.peak_resultant / G:.3f} g; vertical RinaldiUP) is projected on each "
        f"direction of the object, whose x axis is taken along the {az[0]:.0f} deg "
        "component (the orientation of a real object on site is an input), and each "
        "projection runs on that direction's planar block (rocking.analysis."
        "direction_sweep), at the scale factors "
        + ", ".join(f"{s:g}" for s in h1.scale)
        + ". Without the vertical component the worst direction is phi = "
        + ", ".join(f"{r.worst_phi_deg:.1f}" for r in h1.itertuples())
        + " deg respectively ("
        + ", ".join(f"{r.n_overturned} of {r.n_directions}" for r in h1.itertuples())
        + " directions overturn); the directions where the PGA along phi over the weaker "
          "side's g tan α is largest are phi = "
        + ", ".join(f"{r.max_uplift_demand_phi_deg:.1f}" for r in h1.itertuples())
        + " deg (ratio " + ", ".join(f"{r.max_uplift_demand:.2f}" for r in h1.itertuples())
        + "). With the vertical component: phi = "
        + ", ".join(f"{r.worst_phi_deg:.1f}" for r in worst[worst.vertical].itertuples())
        + " deg." + still)
    d = h1.angle_to_static_weakest_deg.to_numpy(float)
    coincide = bool(np.all(d <= SWEEP_STEP[0] / 2 + 1e-9))
    p_w = h1.pga_at_static_weakest_g.iloc[-1]
    p_x = h1.pga_at_worst_g.iloc[-1]
    why = (
        ("The worst direction of the sweep and the static weakest direction coincide "
         f"(within {max(d):.1f} deg)." if coincide else
         "The worst direction of the sweep does not coincide with the static weakest "
         f"direction ({_rng(d)} deg apart, modulo 180 deg). ")
        + "The static analysis ranks the directions by the object alone (g tan α of the "
          "weaker side); the response also depends on how much of the record falls on "
          "each direction. The Rinaldi record is strongly polarised (its near-fault pulse "
          f"lies along the {az[0]:.0f} deg component): at scale {h1.scale.iloc[-1]:g} the "
          f"PGA along the static weakest direction is {p_w:.3f} g, along the worst one "
          f"{p_x:.3f} g; the worst direction follows the direction of the largest demand "
          f"over capacity (phi = {h1.max_uplift_demand_phi_deg.iloc[-1]:.1f} deg, the "
          f"bearing {(az[0] - h1.max_uplift_demand_phi_deg.iloc[-1]) % 180.0:.1f} / "
          f"{(az[0] - h1.max_uplift_demand_phi_deg.iloc[-1]) % 180.0 + 180.0:.1f} deg), not "
          f"the weakest direction (bearing {(az[0] - weak.phi_deg) % 180.0:.1f} / "
          f"{(az[0] - weak.phi_deg) % 180.0 + 180.0:.1f} deg). The capacity changes little "
          "with phi (α from "
          f"{table.alpha_min.min():.3f} to {table.alpha_min.max():.3f} rad), the demand "
          "a lot, so the record's orientation decides; turned by 90 deg on its plinth, the "
          "object would have another worst direction. A design check should therefore "
          "sweep the orientation too, or take the weakest direction under the strongest "
          "component.")
    limits = (
        "Limits. This planar analysis per direction is the standard engineering answer "
        "until a 3-D model exists: in each direction the body rocks in that vertical plane "
        "only, under the component of the shaking along it; the other component, which "
        "acts at the same time, is ignored there. There is no coupling between "
        "directions, no twisting about the vertical, no wobbling (rolling on the edge of "
        "a round base) and no sliding; a body shaken obliquely to its support's edges can "
        "uplift earlier than either planar block says (the dashed curve of the "
        "directional figure). The mesh is a synthetic example and the motions a few "
        "records: the method, not the assessment of any object.")
    return [intro, direc, fragt, sweep, why, limits]


def _rng(v) -> str:
    v = np.asarray(v, dtype=float)
    lo, hi = float(v.min()), float(v.max())
    return f"{lo:.1f}" if abs(hi - lo) < 0.05 else f"{lo:.1f}–{hi:.1f}"
