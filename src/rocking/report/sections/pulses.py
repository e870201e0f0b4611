"""Section: overturning spectra of the four specimens under one-sine and one-cosine pulses.

Beyond the paper (issue 10). For each specimen (Table II E parameters) and pulse,
:func:`rocking.analysis.overturning_spectrum` finds by bisection the minimum
``a_p / (g tan alpha)`` that overturns the block for each ``omega_p / p``; an
:func:`rocking.analysis.outcome_map` of specimen 1 under the one-sine pulse shows the two
overturning modes and the safe region between them. The axes are dimensionless
(Dimitrakopoulos and DeJong 2012): the response depends only on ``omega_p / p``,
``a_p / (g tan alpha)``, ``alpha`` and ``mu``.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...analysis import outcome_map, overturning_spectrum, plot_outcome_map
from ...blocks import specimen
from ...plot import PALETTE
from .. import html as H
from ..core import section

SPECIMENS = (1, 2, 3, 4)
PULSES = ("one_sine", "one_cosine")  # names of rocking.motions.catalog
PULSE_LABELS = {"one_sine": "one-sine", "one_cosine": "one-cosine"}
MAP_SPECIMEN = 1
W_RANGE = (0.5, 12.0)  # omega_p / p


def grids(quick: bool):
    """``(omega ratios of the spectra, tol, map omega ratios, map accel ratios)``."""
    if quick:
        return (np.geomspace(*W_RANGE, 5), 0.05, np.geomspace(*W_RANGE, 12),
                np.geomspace(0.8, 15.0, 12))
    return (np.geomspace(*W_RANGE, 25), 0.01, np.geomspace(*W_RANGE, 48),
            np.geomspace(0.8, 15.0, 48))


def spectra_table(quick: bool) -> pd.DataFrame:
    """Every specimen and pulse: the long table of the overturning spectra."""
    wr, tol, _, _ = grids(quick)
    parts = []
    for n in SPECIMENS:
        b = specimen(n, "experimental")
        for pulse in PULSES:
            df = overturning_spectrum(b, pulse, wr, model="housner", tol=tol)
            df.insert(0, "pulse", pulse)
            df.insert(0, "specimen", n)
            df["alpha"], df["p"], df["mu"] = b.alpha, b.p, b.mu
            df["tol"] = tol
            parts.append(df)
    out = pd.concat(parts, ignore_index=True)
    out["mode"] = out["mode"].astype("Int64")
    return out


@section("pulses", "Beyond the paper: overturning spectra under one-sine and one-cosine pulses",
         order=62, cost=12)
def build(ctx) -> str:
    from matplotlib.figure import Figure
    from matplotlib.ticker import NullFormatter

    wr, tol, mw, ma = grids(ctx.quick)
    spec = spectra_table(ctx.quick)
    ctx.save_csv(spec, "spectra", float_format="%.6g")
    bmap = specimen(MAP_SPECIMEN, "experimental")
    omap = outcome_map(bmap, "one_sine", mw, ma, model="housner")
    ctx.save_csv(omap, "outcome_map", float_format="%.6g")

    fig = Figure(figsize=(10.0, 3.8), layout="constrained")
    axs = fig.subplots(1, 2, sharey=True)
    for ax, pulse in zip(axs, PULSES, strict=True):
        for i, n in enumerate(SPECIMENS):
            d = spec[(spec.specimen == n) & (spec.pulse == pulse)]
            c = PALETTE[i % len(PALETTE)]
            ax.plot(d.omega_ratio, d.min_overturn_ratio, color=c, lw=1.1, marker="o", ms=3,
                    label=f"specimen {n} (α = {d.alpha.iloc[0]:.3f}, μ = {d.mu.iloc[0]:.3f})")
            m2 = d[d["mode"] == 2]  # Zhang and Makris (2001): mode 2, no impact
            ax.plot(m2.omega_ratio, m2.min_overturn_ratio, ls="none", marker="s", ms=6,
                    mfc="none", mec=c)
        ax.axhline(1.0, color="0.4", ls=":", lw=0.9)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xlabel("ω_p / p")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_title(f"{PULSE_LABELS[pulse]} pulse (squares: mode 2, overturning without "
                     "impact)", fontsize=9.5)
    axs[0].set_ylabel("minimum overturning a_p / (g tan α)")
    axs[1].legend(fontsize=7.5, loc="upper left")
    fig_spec = ctx.save_figure(
        fig, "spectra",
        caption=("Overturning spectra of the four specimens (Table II E parameters, "
                 "classical model): the minimum pulse acceleration a_p/(g tan α) that "
                 "overturns the block, against the pulse frequency ω_p/p, found by "
                 f"bisection to {100 * tol:g} % (open squares: overturning without any "
                 "impact, mode 2 of Zhang and Makris 2001; other points: after one or more "
                 "impacts, mode 1). Dotted: the uplift acceleration."))

    fig2 = Figure(figsize=(7.5, 4.6), layout="constrained")
    ax = fig2.add_subplot()
    plot_outcome_map(omap, ax, spectrum=spec[(spec.specimen == MAP_SPECIMEN)
                                             & (spec.pulse == "one_sine")].reset_index(drop=True))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_title(f"Specimen {MAP_SPECIMEN} (α = {bmap.alpha:.3f}, μ = {bmap.mu:.3f}), "
                 "one-sine pulse", fontsize=9.5)
    fig_map = ctx.save_figure(
        fig2, "outcome_map",
        caption=(f"Outcome of each cell of a {len(mw)} × {len(ma)} grid (ω_p/p, a_p/(g tan α)) "
                 f"for specimen {MAP_SPECIMEN} under the one-sine pulse, with its overturning "
                 "spectrum. The safe region lies between the cells that overturn after an "
                 "impact (mode 1 of Zhang and Makris 2001, at lower amplitudes) and those "
                 "that overturn without one (mode 2, at higher amplitudes)."))

    rows, summ = [], []
    for n in SPECIMENS:
        for pulse in PULSES:
            d = spec[(spec.specimen == n) & (spec.pulse == pulse)]
            k = int(np.nanargmin(d.min_overturn_ratio.to_numpy()))
            lowest = d.iloc[k]
            at = {w: float(np.interp(np.log(w), np.log(d.omega_ratio),
                                     d.min_overturn_ratio)) for w in (2.0, 5.0)}
            n2 = int((d["mode"] == 2).sum())  # without impact
            summ.append({"specimen": n, "pulse": pulse, "lowest": lowest.min_overturn_ratio,
                         "at_w": lowest.omega_ratio, "r2": at[2.0], "r5": at[5.0], "n2": n2,
                         "found": int(d["mode"].notna().sum())})
            rows.append([str(n), PULSE_LABELS[pulse], f"{lowest.min_overturn_ratio:.3f}",
                         f"{lowest.omega_ratio:.2f}", f"{at[2.0]:.2f}", f"{at[5.0]:.2f}",
                         f"{n2} / {len(d)}"])
    tbl = H.table(["specimen", "pulse", "lowest a_p/(g tan α)", "at ω_p/p",
                   "at ω_p/p = 2", "at ω_p/p = 5", "points in mode 2 (no impact)"], rows,
                  caption="Overturning spectra: summary (interpolated on the log grid)")
    s = pd.DataFrame(summ)
    mode_counts = omap["mode"].value_counts().to_dict()
    safe_above = []  # omega ratios where a safe cell lies above an overturning cell
    for w, g in omap.groupby("omega_ratio"):
        o = g.sort_values("accel_ratio")["overturned"].to_numpy()
        if o.any() and (~o[np.argmax(o):]).any():
            safe_above.append(w)
    sine, cos = s[s.pulse == "one_sine"], s[s.pulse == "one_cosine"]
    g = spec.groupby(["pulse", "omega_ratio"]).min_overturn_ratio
    rel = 100.0 * ((g.max() - g.min()) / g.mean()).dropna()
    spread, spread_max = float(rel.median()), float(rel.max())
    text = [
        "The axes are dimensionless (Dimitrakopoulos and DeJong 2012): a block's response to "
        "a pulse depends only on ω_p/p, a_p/(g tan α), α and μ, so one curve serves every "
        "block of the same slenderness and restitution whatever its size; a larger block "
        "(smaller p) sees the same pulse at a higher ω_p/p. We use the Table II E "
        "parameters and the classical model.",
        f"The one-sine pulse needs at least {sine.lowest.min():.2f}-{sine.lowest.max():.2f} "
        f"times the uplift acceleration to overturn the specimens (lowest at ω_p/p = "
        f"{sine.at_w.min():.2f}-{sine.at_w.max():.2f}); the one-cosine pulse "
        f"{cos.lowest.min():.2f}-{cos.lowest.max():.2f}. Every threshold is at least 1 (no "
        "overturning below uplift). The thresholds rise steeply with ω_p/p: at ω_p/p = 5 "
        f"they are {sine.r5.min():.1f}-{sine.r5.max():.1f} (one-sine) and "
        f"{cos.r5.min():.1f}-{cos.r5.max():.1f} (one-cosine), i.e. short pulses need far "
        "more than the static uplift acceleration. "
        f"Between the four specimens the thresholds differ by {spread:.0f} % at the median "
        f"frequency ratio (largest {spread_max:.0f} %): the axes remove their size (p) and "
        "the scale of α, and what is left comes from α itself and μ (between "
        f"{spec.mu.min():.3f} and {spec.mu.max():.3f}).",
        f"The outcome map of specimen {MAP_SPECIMEN} ({len(omap)} cells) has "
        f"{mode_counts.get(0, 0)} safe cells, {mode_counts.get(1, 0)} that overturn after "
        f"an impact (mode 1) and {mode_counts.get(2, 0)} without one (mode 2), in the "
        "numbering of Zhang and Makris (2001). "
        + (f"At {len(safe_above)} of the {omap.omega_ratio.nunique()} frequency ratios "
           f"(ω_p/p from {min(safe_above):.2f} to {max(safe_above):.2f}) a larger pulse is "
           "safe above an overturning one: the safe region between the two modes found by "
           "Zhang and Makris (2001) for the one-sine pulse."
           if safe_above else "No safe region above the first overturning level appears "
           "on this grid."),
        "The paper does not study pulses; this section answers the question a designer "
        "asks of a single block (what pulse overturns it) that its Table V answers only "
        "statistically for earthquakes.",
    ]
    return ("".join(H.p(t) for t in text) + fig_spec + tbl + fig_map + ctx.files_html())
