"""Section: fragility curves of specimens 2-4, spectrum-matched against stochastic records.

Beyond the paper (issue 10). Each specimen (Table II E) is run under two record sets
scaled to a ladder of PGA levels (:func:`rocking.analysis.ida`, classical model): the 30
EC8-matched seed earthquakes of the paper's random tests (ours) and 30 records of the
Rezaeian and Der Kiureghian (2008) stochastic model (not spectrum-matched). The damage
states are the defaults of :data:`rocking.analysis.DEFAULT_THRESHOLDS` on max |theta| /
alpha, plus overturning; :func:`rocking.analysis.fragility_curves` fits them (ordered
probit, one beta) with bootstrap bands, and :func:`rocking.analysis.fragility` the
overturning curve alone (its own beta). The curves go to a pelicun-format table, and one
annual frequency is computed on an illustrative power-law hazard curve.

Units: the simulations run in SI (the IDA levels are PGAs in m/s^2), and the curves are
fitted to the PGA in g, the unit of the hazard curve and the pelicun table, so that the
plots, the table and the text all give medians in g (the fits state their unit, and
:func:`~rocking.analysis.annual_frequency` checks the hazard curve's against it).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...analysis import DEFAULT_THRESHOLDS, annual_frequency, fragility, fragility_curves, ida
from ...blocks import specimen
from ...motions import seed_earthquakes, stochastic_records
from ...plot import PALETTE
from ...units import G
from .. import html as H
from ..core import section

SPECIMENS = (2, 3, 4)
STOCHASTIC_SEED = 2008
SETS = {"matched": "30 EC8-matched seed earthquakes",
        "stochastic": "stochastic records (Rezaeian & Der Kiureghian 2008)"}
HAZARD_K0 = 1e-3  # 1/yr: annual rate of exceeding PGA = HAZARD_A0 (illustrative)
HAZARD_A0 = 0.1  # g
HAZARD_K = 2.5  # slope of the log-log hazard curve (illustrative)


def record_sets(quick: bool) -> dict:
    eq = seed_earthquakes()
    n_st = 10 if quick else 30
    return {"matched": eq, "stochastic": stochastic_records(n_st, seed=STOCHASTIC_SEED)}


def levels_for(block, quick: bool) -> np.ndarray:
    """PGA levels (m/s^2): 0.8 to 6 times the uplift acceleration g tan(alpha)."""
    lo = G * np.tan(block.alpha)
    return np.geomspace(0.8 * lo, 6.0 * lo, 6 if quick else 12)


def hazard_rate(pga_g):
    """The illustrative hazard curve: annual rate of exceeding ``pga_g`` (g)."""
    return HAZARD_K0 * (np.asarray(pga_g, dtype=float) / HAZARD_A0) ** (-HAZARD_K)


def run(quick: bool):
    """``(ida table, fits table, {(set, specimen): (curves, overturning fit)})``."""
    sets = record_sets(quick)
    n_boot = 200 if quick else 1000
    tables, fits, out = [], [], {}
    for sname, recs in sets.items():
        for n in SPECIMENS:
            b = specimen(n, "experimental")
            tab = ida(b, recs, im="pga", levels=levels_for(b, quick), model="housner")
            tab.insert(0, "specimen", n)
            tab.insert(0, "record_set", sname)
            tables.append(tab)
            pga_g = tab["im"].to_numpy() / G  # the levels are in m/s^2 (tab.attrs)
            curves = fragility_curves(pga_g, tab["damage_state"], n_boot=n_boot, seed=0,
                                      im_name="pga", im_unit="g")
            ovt = fragility(pga_g, tab["overturned"], n_boot=n_boot, seed=0,
                            label="overturning", im_name="pga", im_unit="g")
            out[(sname, n)] = (curves, ovt)
            for k, (lab, f) in enumerate(zip(curves.labels, curves.fits, strict=True), 1):
                fits.append({"record_set": sname, "specimen": n, "fit": "common_beta",
                             "state": k, "label": lab, "median_m_s2": f.median * G,
                             "median_g": f.median, "beta": f.beta,
                             "median_se_m_s2": f.median_se * G, "beta_se": f.beta_se,
                             "n_records": len(recs)})
            fits.append({"record_set": sname, "specimen": n, "fit": "overturning_alone",
                         "state": len(curves), "label": "overturning",
                         "median_m_s2": ovt.median * G, "median_g": ovt.median,
                         "beta": ovt.beta, "median_se_m_s2": ovt.median_se * G,
                         "beta_se": ovt.beta_se, "n_records": len(recs)})
    return pd.concat(tables, ignore_index=True), pd.DataFrame(fits), out


@section("fragility", "Beyond the paper: fragility curves of specimens 2-4 (IM = PGA)",
         order=64)
def build(ctx) -> str:
    from matplotlib.figure import Figure

    table, fits, res = run(ctx.quick)
    ctx.save_csv(table.drop(columns=["name"], errors="ignore"), "ida", float_format="%.6g")
    ctx.save_csv(fits, "fits", float_format="%.6g")
    pel = pd.concat([res[(s, n)][0].to_pelicun(id=f"rocking.specimen{n}.{s}",
                                               demand_unit="g")
                     for s in SETS for n in SPECIMENS])
    pel_name = ctx.save_csv(pel, "pelicun", index=True, float_format="%.6g")

    fig = Figure(figsize=(11.0, 6.4), layout="constrained")
    axs = fig.subplots(2, len(SPECIMENS), sharex="col", sharey=True)
    for i, s in enumerate(SETS):
        for j, n in enumerate(SPECIMENS):
            ax = axs[i, j]
            curves, _ = res[(s, n)]
            curves.plot(ax)
            h, lab = ax.get_legend_handles_labels()
            keep = [k for k, t in enumerate(lab) if "band" not in t]
            ax.legend([h[k] for k in keep], [lab[k].replace(" (median", "\n(median")
                                             for k in keep], fontsize=6, loc="lower right")
            ax.set_title(f"specimen {n}, {s} records", fontsize=9)
            ax.set_xlabel("PGA (g)" if i == 1 else "")
            ax.set_ylabel("P(DS ≥ k)" if j == 0 else "")
    thr = ", ".join(f"{t:g}" for t in DEFAULT_THRESHOLDS)
    fig_html = ctx.save_figure(
        fig, "curves",
        caption=(f"Fragility curves P(DS ≥ k | PGA) of specimens 2-4 (Table II E, classical "
                 f"model): damage states max|θ|/α ≥ {thr} and overturning; top: the "
                 "EC8-matched seed earthquakes, bottom: the stochastic records; shaded: "
                 "95 % bootstrap bands; points: the fraction of records in each state "
                 "at each PGA level."))

    # illustrative hazard curve and annual frequencies
    him = np.geomspace(0.02, 3.0, 13)  # PGA (g); exact log-log: a power law
    hr = hazard_rate(him)
    af_rows = []
    for s in SETS:
        for n in SPECIMENS:
            curves, ovt = res[(s, n)]
            lam = annual_frequency(curves, him, hr, hazard_unit="g")
            for k, (lab, v) in enumerate(zip(curves.labels, lam, strict=True), 1):
                af_rows.append({"record_set": s, "specimen": n, "state": k, "label": lab,
                                "annual_frequency": v, "return_period_yr": 1.0 / v})
    af = pd.DataFrame(af_rows)
    ctx.save_csv(af, "annual_frequency_illustrative", float_format="%.6g")
    fig2 = Figure(figsize=(10.0, 3.6), layout="constrained")
    a1, a2 = fig2.subplots(1, 2)
    a1.loglog(him, hr, color="k", lw=1.2)
    a1.set_xlabel("PGA (g)")
    a1.set_ylabel("annual rate of exceedance (1/yr)")
    a1.set_title(f"ILLUSTRATIVE hazard: λ = {HAZARD_K0:g} (PGA / {HAZARD_A0:g} g)^-{HAZARD_K:g}"
                 "\n(not a site's hazard)", fontsize=9)
    a1.grid(True, which="both", alpha=0.3)
    last = int(af.state.max())
    for i, n in enumerate(SPECIMENS):
        c = PALETTE[i % len(PALETTE)]
        for s, ls in zip(SETS, ("-", "--"), strict=True):
            d = af[(af.record_set == s) & (af.specimen == n)]
            a2.semilogy(d.state, d.annual_frequency, color=c, ls=ls, marker="o", ms=4,
                        label=f"specimen {n}, {s}")
    a2.set_xticks(range(1, last + 1))
    a2.set_xlabel("damage state k (last: overturning)")
    a2.set_ylabel("annual frequency of DS ≥ k (1/yr)")
    a2.grid(True, which="both", alpha=0.3)
    a2.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    a2.set_title("mean annual frequency on the illustrative hazard", fontsize=9)
    fig_af = ctx.save_figure(
        fig2, "annual_frequency",
        caption=("An ILLUSTRATIVE power-law hazard curve (made up for the example, not the "
                 "hazard of any site) and the mean annual frequency of each damage state it "
                 "gives with the fitted curves (Cornell et al. 2002)."))

    cb = fits[fits.fit == "common_beta"].drop_duplicates(["record_set", "specimen"])
    oa = fits[fits.fit == "overturning_alone"]
    rows = []
    for s in SETS:
        for n in SPECIMENS:
            f = fits[(fits.record_set == s) & (fits.specimen == n)]
            c = f[f.fit == "common_beta"]
            o = f[f.fit == "overturning_alone"].iloc[0]
            rows.append([H.Cell(s, "l"), str(n)]
                        + [f"{m:.3f}" for m in c.median_g]
                        + [f"{c.beta.iloc[0]:.3f} ± {c.beta_se.iloc[0]:.3f}",
                           f"{o.median_g:.3f}", f"{o.beta:.3f} ± {o.beta_se:.3f}"])
    labels = list(res[("matched", SPECIMENS[0])][0].labels)
    tbl = H.table(["records", "specimen"] + [f"median {lab} (g)" for lab in labels]
                  + ["common β ± se", "overturning alone: median (g)", "β ± se"], rows,
                  caption="Fitted lognormal fragility curves (IM = PGA)")

    def beta_of(frame, s):
        return frame[frame.record_set == s].set_index("specimen").beta

    bm, bs = beta_of(cb, "matched"), beta_of(cb, "stochastic")
    om, os_ = beta_of(oa, "matched"), beta_of(oa, "stochastic")
    ratio = float(np.mean(bm / bs))
    lower = int(np.sum(bm < bs))
    nst = int(table[table.record_set == "stochastic"].record.nunique())
    ovt_name = labels[-1]
    medians_ok = all(np.all(np.diff(res[k][0].medians) > 0) for k in res)
    af_ovt = af[af.state == last]
    n_levels = len(levels_for(specimen(SPECIMENS[0], "experimental"), ctx.quick))
    up = {n: G * np.tan(specimen(n, "experimental").alpha) for n in SPECIMENS}
    text = [
        f"Each specimen was run under {table[table.record_set == 'matched'].record.nunique()} "
        f"matched and {nst} stochastic records at "
        f"{n_levels} PGA levels from 0.8 to 6 times its uplift acceleration g tan α "
        f"({len(table)} simulations, classical model; each run goes on after its record "
        f"until the block has settled: {int((~table['settled']).sum())} of {len(table)} "
        "were still rocking at the cap and count as survivors with the angle they reached). "
        "The damage states are max|θ|/α ≥ "
        f"{thr} and overturning ({ovt_name}); the medians increase with the damage state "
        + ("for every specimen and record set" if medians_ok else
           "except for some fits (see the CSV)")
        + ". The overturning medians of the matched set are "
        + ", ".join(f"{o.median_g:.3f} g (specimen {o.specimen})"
                    for o in oa[oa.record_set == "matched"].itertuples())
        + ", i.e. "
        + ", ".join(f"{o.median_m_s2 / up[o.specimen]:.2f}"
                    for o in oa[oa.record_set == "matched"].itertuples())
        + " times the uplift acceleration: a specimen overturns at a PGA well above the "
          "one that lifts it, as in the paper's Table V.",
        "Dispersion. With one β for the damage states, the matched records give β = "
        + ", ".join(f"{v:.3f}" for v in bm) + " and the stochastic records β = "
        + ", ".join(f"{v:.3f}" for v in bs)
        + f" (specimens {', '.join(map(str, SPECIMENS))}): the matched set's β is lower for "
          f"{lower} of {len(SPECIMENS)} specimens, on average {100 * (ratio - 1):+.0f} %. The "
          "overturning curve fitted alone gives β = "
        + ", ".join(f"{v:.3f}" for v in om) + " (matched) against "
        + ", ".join(f"{v:.3f}" for v in os_)
        + " (stochastic). The issue expected the spectrum matching to remove most of the "
          "record-to-record variability; with PGA as the IM, the difference we find is "
          + ("small against the standard errors: rocking overturning is governed by the "
             "long-period content and the sequence of pulses, which spectrum matching over "
             "the EC8 period range does not fix, while the stochastic records at a given "
             "PGA differ in frequency content and duration mostly in ways a rocking block "
             "of these sizes is not very sensitive to."
             if abs(ratio - 1) < 0.25 else
             ("clear: matched records remove part of the record-to-record variability."
              if ratio < 1 else "the opposite of that expectation."))
        + " With few records per set (30) the β are known to about ±"
        + f"{100 * float(np.mean(cb.beta_se / cb.beta)):.0f} % (one standard error).",
        "Annual frequency (ILLUSTRATIVE): on a made-up power-law hazard curve λ(PGA) = "
        f"{HAZARD_K0:g} (PGA / {HAZARD_A0:g} g)^−{HAZARD_K:g} per year (not the hazard of "
        "any site), the mean annual frequency of overturning is "
        + ", ".join(f"{r.annual_frequency:.2e}/yr (specimen {r.specimen}, return period "
                    f"{r.return_period_yr:,.0f} yr)"
                    for r in af_ovt[af_ovt.record_set == "matched"].itertuples())
        + " with the matched set's curves; the stochastic set's give "
        + ", ".join(f"{r.annual_frequency:.2e}/yr"
                    for r in af_ovt[af_ovt.record_set == "stochastic"].itertuples())
        + ". Only the method is meant: a real assessment needs the site's hazard curve, "
          "in the same IM.",
        f"The pelicun-format table ({pel_name}) has one row per specimen and record set, "
        "with the limit states LS1-LS3 as lognormal (Theta_0: the median in g, Theta_1: "
        "β), demand 'Peak Ground Acceleration'.",
        "The paper does not compute fragility curves; it ends by asking for stochastic "
        "analysis. Our matched records are ours (the paper's are not published), and the "
        "stochastic model's parameters are its defaults (a moderate event, not fitted to "
        "the EC8 target), so the two sets differ in mean spectral shape as well as in "
        "their variability.",
    ]
    return ("".join(H.p(t) for t in text) + fig_html + tbl + fig_af + ctx.files_html())
