"""Section: Table II analogue, free-rocking identification of alpha, p, mu (Section 4.1).

The paper identifies alpha and p of each stone by minimising the error surface of Eq 13
over the times of its free-rocking peaks, and mu from Eq 12 (Table II, column E). We have
no raw records from the laboratory, so we *simulate* the free-rocking tests and run the same
identification (:func:`rocking.identify.free_rocking`) on them:

* **DEM records** (when ``"dem"`` is a registered model): the discrete element model of each
  stone, with the 45 degree cuts of its base corners when the package knows them
  (``specimen(n, "geometric", shape="cut")``), released from rest at 0.8 of its alpha;
* **placeholder** (when the DEM model is not there): classical-model records of the Table I
  rectangle. These recover the input by construction and only exercise the pipeline.

Every record is treated as a measurement: a 0.5 s hold before the release, sampling at
200 Hz, Gaussian noise of 0.5 % of the release angle and a constant offset (seeded). The
table compares the identified parameters with the theoretical ones (Eqs 2-4 of the Table I
rectangle), as Table II does, and says whether alpha falls below the geometric value as the
paper found. A second table varies the DEM contact stiffness, to see what soft contacts
alone do to the identified alpha.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from ...blocks import paper_data, specimen, specimen_ids
from ...identify import free_rocking
from ...models import MODELS, simulate
from ...models import dem as D
from ...units import G
from .. import html as H
from ..core import section

DURATION = 30.0  # s of free rocking after the release
QUICK_DURATION = 12.0  # s, quick mode
HOLD = 0.5  # s held at theta0 before the release
FS = 200.0  # Hz
NOISE = 0.005  # std of the measurement noise, fraction of theta0
THETA0 = 0.8  # release angle, fraction of the simulated block's alpha
SEED = 2007
STIFFNESS_FACTORS = (1.0, 0.1, 0.01, 0.001)  # DEM contact stiffness / default


def dem_available() -> bool:
    return "dem" in MODELS


def simulated_block(n: int):
    """The stone as simulated: with its corner cuts if the package models them."""
    if dem_available():
        try:
            return specimen(n, "geometric", shape="cut"), "Table I with 45° base cuts"
        except TypeError:  # specimen() without shapes
            pass
    return specimen(n, "geometric"), "Table I rectangle"


def free_record(block, model: str, theta0: float, duration: float, **options):
    """(t, theta) of free rocking from rest at ``theta0``, sampled at FS."""
    if model == "dem":
        # ---- DEM records: soft contacts at the corners of the (cut) polygon ----
        r = simulate(block, None, model="dem", duration=duration, theta0=theta0,
                     dt_out=1.0 / FS, **options)
    else:
        # ---- PLACEHOLDER until the DEM model exists: classical-model records ----
        r = simulate(block, None, model="housner", duration=duration, theta0=theta0,
                     dt_out=1.0 / FS)
    t = np.arange(0.0, r.t[-1] + 1e-9, 1.0 / FS)
    return t, np.interp(t, r.t, r.theta)


def measured(t, theta, theta0, rng):
    """A 'measured' record: a hold before the release, noise and a constant offset."""
    nh = int(round(HOLD * FS))
    tm = np.concatenate((np.arange(nh) / FS, t + nh / FS))
    th = np.concatenate((np.full(nh, theta[0]), theta))
    offset = rng.uniform(-0.05, 0.05) * theta0
    return tm, th + NOISE * theta0 * rng.standard_normal(tm.size) + offset


def runs(quick: bool) -> dict:
    """{specimen: dict(fit, theoretical block, simulated block, ...)}."""
    rng = np.random.default_rng(SEED)
    duration = QUICK_DURATION if quick else DURATION
    model = "dem" if dem_available() else "housner"
    out = {}
    for n in specimen_ids():
        block, shape = simulated_block(n)
        theta0 = THETA0 * block.alpha
        t, th = free_record(block, model, theta0, duration)
        tm, y = measured(t, th, theta0, rng)
        fit = free_rocking(tm, y)
        out[n] = {"fit": fit, "T": specimen(n, "geometric"), "sim": block, "shape": shape,
                  "theta0": theta0, "model": model}
    return out


def stiffness_study(quick: bool) -> pd.DataFrame | None:
    """Identified parameters of DEM records of the specimen 2 rectangle, softer contacts."""
    if not dem_available():
        return None
    block = specimen(2, "geometric")
    try:  # the DEM's own default stiffness (API of rocking.models.dem)
        k0 = D.default_stiffness(D.build_assembly(block))
    except (AttributeError, TypeError):
        return None
    rows = []
    for f in (STIFFNESS_FACTORS[0], STIFFNESS_FACTORS[-1]) if quick else STIFFNESS_FACTORS:
        t, th = free_record(block, "dem", THETA0 * block.alpha,
                            QUICK_DURATION if quick else DURATION, stiffness=k0 * f)
        fit = free_rocking(t, th)
        rows.append({"stiffness_factor": f, "K_N_per_m": k0 * f,
                     "settlement_m": block.mass * G / (2.0 * k0 * f),
                     "alpha": fit.alpha, "alpha_std": fit.alpha_std,
                     "alpha_diff_pct": 100 * (fit.alpha / block.alpha - 1),
                     "p": fit.p, "p_diff_pct": 100 * (fit.p / block.p - 1),
                     "mu": fit.mu, "mu_diff_pct": 100 * (fit.mu / block.mu - 1)})
    return pd.DataFrame(rows)


def table(res: dict) -> pd.DataFrame:
    data = paper_data()["table2_percent"]
    rows = []
    for n, r in res.items():
        fit, T, sim = r["fit"], r["T"], r["sim"]
        row = {"specimen": n, "source": r["model"], "shape": r["shape"],
               "theta0": r["theta0"], "n_half_cycles": fit.n_half_cycles}
        for k in ("alpha", "mu", "p"):
            v = getattr(fit, k)
            row[f"{k}_T"] = getattr(T, k)
            row[f"{k}_simulated_block"] = getattr(sim, k)
            row[f"{k}_identified"] = v
            row[f"{k}_std"] = getattr(fit, f"{k}_std")
            row[f"{k}_diff_pct"] = 100 * (v / getattr(T, k) - 1)
            row[f"{k}_vs_simulated_pct"] = 100 * (v / getattr(sim, k) - 1)
            row[f"{k}_paper_pct"] = float(data[str(n)][k])
        rows.append(row)
    return pd.DataFrame(rows)


def _cls(ours: float, paper: float) -> str:
    if math.copysign(1, ours) == math.copysign(1, paper) or abs(ours) < 0.5:
        return "ok" if abs(ours - paper) < 2.0 else "warn"
    return "bad"


def _html_table(df: pd.DataFrame) -> str:
    top = "<tr><th></th>" + "".join(f'<th class="c" colspan="5">{H.esc(lab)}</th>'
                                    for lab in ("α (rad)", "μ", "p (1/s)")) + "</tr>"
    header = ["Specimen"] + ["T", "simulated", "identified ± std", "%", "paper %"] * 3
    rows = []
    nd = {"alpha": 4, "mu": 4, "p": 3}
    for _, r in df.iterrows():
        cells = [H.Cell(int(r.specimen), "c")]
        for k in ("alpha", "mu", "p"):
            cells += [H.fmt(r[f"{k}_T"], nd[k]), H.fmt(r[f"{k}_simulated_block"], nd[k]),
                      f"{r[f'{k}_identified']:.{nd[k]}f} ± {r[f'{k}_std']:.{nd[k]}f}",
                      H.Cell(H.pct(r[f"{k}_diff_pct"]),
                             _cls(r[f"{k}_diff_pct"], r[f"{k}_paper_pct"])),
                      H.Cell(H.pct(r[f"{k}_paper_pct"]), "na")]
        rows.append(cells)
    t = H.table(header, rows, caption="Table II analogue: theoretical (T, Eqs 2-4 of the "
                "Table I rectangle), the simulated stone, identified (Eqs 12-13) and their "
                "difference %, next to the paper's % (E vs T)")
    return t.replace("<thead>", "<thead>" + top, 1)


def _figures(res: dict, ctx) -> str:
    from matplotlib.figure import Figure

    ids = list(res)
    # error surfaces
    fig = Figure(figsize=(10.0, 8.0), layout="constrained")
    axs = fig.subplots(2, 2).ravel()
    for ax, n in zip(axs, ids, strict=False):
        r = res[n]
        T = r["T"]
        near = abs(T.alpha / r["fit"].alpha - 1) < 0.15 and abs(T.p / r["fit"].p - 1) < 0.15
        r["fit"].plot_error_surface(ax=ax, theoretical=T if near else None,
                                    n=61 if ctx.quick else 121)
        ax.set_title(f"specimen {n}: Σ(α, p), {r['fit'].n_half_cycles} half-cycles",
                     fontsize=9.5)
    html = ctx.save_figure(
        fig, "error_surface",
        caption="Error surface Σ(α, p) of Eq 13 (weighted; log10 of Σ/Σmin) around the "
                "minimum for each specimen, with the identified parameters (star, ±1 std) "
                "and the theoretical ones (cross, when inside the window). The valley "
                "p*(α) shows the trade-off between α and p: the times fix p√α well and "
                "α itself less well.")
    # Fig. 4 a/b analogue
    fig = Figure(figsize=(11.0, 2.3 * len(ids)), layout="constrained")
    axs = fig.subplots(len(ids), 2, sharex="row", squeeze=False)
    for i, n in enumerate(ids):
        r = res[n]
        r["fit"].plot_fit(ax=[axs[i, 0], axs[i, 1]], theoretical=r["T"])
        for j, lab in enumerate(("theoretical (T)", "identified")):
            axs[i, j].set_title(f"specimen {n}: classical model with {lab} parameters",
                                fontsize=9, loc="left")
            axs[i, j].legend(loc="upper right", fontsize=6.5, framealpha=0.85)
            axs[i, j].set_xlabel("time (s)" if i == len(ids) - 1 else "")
    html += ctx.save_figure(
        fig, "fit",
        caption="Figure 4 analogue: the simulated 'measured' record (grey) against the "
                "classical model released from its first peak, (left) with the theoretical "
                "parameters of the Table I rectangle and (right) with the identified ones.")
    return html


def _discussion(df: pd.DataFrame, res: dict, stiff: pd.DataFrame | None) -> str:
    dem = dem_available()
    paper = paper_data()["specimens"]
    items = []
    for _, r in df.iterrows():
        n = int(r.specimen)
        d, dp = r.alpha_diff_pct, r.alpha_paper_pct
        rel = "below" if d < 0 else "above"
        items.append(
            f"Specimen {n}: identified α = {r.alpha_identified:.4f} ± {r.alpha_std:.4f} rad, "
            f"{abs(d):.1f} % {rel} the geometric {r.alpha_T:.4f} (paper: {dp:+.1f} %, "
            f"E = {paper[str(n)]['experimental']['alpha']:.3f}); the simulated body's own α "
            f"is {r.alpha_simulated_block:.4f}, recovered to {r.alpha_vs_simulated_pct:+.2f} "
            f"%. μ {r.mu_diff_pct:+.1f} % (paper {r.mu_paper_pct:+.1f} %), p "
            f"{r.p_diff_pct:+.1f} % (paper {r.p_paper_pct:+.1f} %).")
    below = df[df.alpha_diff_pct < -0.5].specimen.astype(int).tolist()
    by = {int(r.specimen): -r.alpha_diff_pct for _, r in df.iterrows()}
    worst = float(np.max(np.abs(df.alpha_vs_simulated_pct)))
    z = float(np.max(np.abs(df.alpha_identified - df.alpha_simulated_block) / df.alpha_std))
    if dem:
        shapes = {r["shape"] for r in res.values()}
        amounts = ", ".join(f"{by[s]:.1f} %" for s in below)
        e_dev = {int(r.specimen): 100 * (r.alpha_identified
                                         / paper[str(int(r.specimen))]["experimental"]["alpha"]
                                         - 1) for _, r in df.iterrows()}
        close = [n for n, v in e_dev.items() if abs(v) < 3.0]
        far = [n for n in e_dev if n not in close]
        head = (
            f"Identified from DEM records ({', '.join(sorted(shapes))}): α falls below the "
            f"geometric α of the Table I rectangle for specimen(s) "
            f"{', '.join(map(str, below)) or 'none'}"
            + (f", by {amounts} respectively" if below else "")
            + f". The identification returns the α of the simulated body itself (to "
            f"{worst:.2f} %, at most {z:.1f} of its standard errors): in this DEM a stone "
            "rocks about the corners of its polygon, so its rotation points move inward by "
            "the base cuts only.")
        if stiff is not None and len(stiff):
            sft = stiff.sort_values("stiffness_factor")
            head += (
                " The contact compliance does not move them inward (second table): with the "
                f"stiffness divided by {1 / sft.stiffness_factor.min():.0f} the identified α "
                f"changes by {sft.alpha_diff_pct.iloc[0]:+.2f} %.")
        if close:
            head += (
                " Against the paper's identified values (its column E), the cut stones come "
                f"within 3 % for specimen(s) {', '.join(map(str, close))} ("
                + ", ".join(f"{e_dev[n]:+.1f} %" for n in close)
                + "), as the paper itself suggests for specimens 1 and 2 (their small "
                "shortfall is 'related to the small cuts at 45°').")
        if far:
            why = []
            if 3 in far:
                why.append("the paper attributes the +29.4 % of specimen 3 to torsion, a 3D "
                           "effect that a planar model cannot show")
            if 4 in far:
                why.append("the base of specimen 4 is not described well enough to be "
                           "modelled (see the Table II section): its 40 mm cuts as modelled "
                           f"here move α by {-by[4]:+.1f} %, the paper found −13.5 %")
            head += (f" Not for specimen(s) {', '.join(map(str, far))} ("
                     + ", ".join(f"{e_dev[n]:+.1f} %" for n in far) + ")"
                     + (": " + "; ".join(why) if why else "") + ".")
    else:
        head = (
            "PLACEHOLDER RESULTS: these records come from the classical model of the Table I "
            "rectangle, so the identified α equals the geometric one within the noise "
            f"(worst {worst:.2f} %) and cannot fall below it; the paper's shortfall needs "
            "the DEM records (rocking.simulate(block, None, model=\"dem\", ...)), used here "
            "automatically once the DEM model is registered.")
    return H.p(head) + H.ul(items)


def _stiff_table(stiff: pd.DataFrame) -> str:
    rows = [[H.fmt(r.stiffness_factor, 3), f"{r.K_N_per_m:.3g}", f"{r.settlement_m:.2g}",
             f"{r.alpha:.5f} ± {r.alpha_std:.5f}", H.pct(r.alpha_diff_pct, 2),
             H.pct(r.p_diff_pct, 2), H.pct(r.mu_diff_pct, 2)] for _, r in stiff.iterrows()]
    return H.table(["K / default", "K (N/m)", "static settlement (m)", "identified α",
                    "α vs geometric", "p vs geometric", "μ vs Eq 4"], rows,
                   caption="DEM contact stiffness and the identified parameters (specimen 2, "
                           "Table I rectangle, noise-free records)")


@section("identification", "Table II analogue — identification from free-rocking records",
         order=15, cost=8)
def build(ctx) -> str:
    res = runs(ctx.quick)
    df = table(res)
    ctx.save_csv(df, "parameters", float_format="%.6g")
    halves = pd.concat([r["fit"].table().assign(specimen=n) for n, r in res.items()])
    ctx.save_csv(halves, "half_cycles", float_format="%.8g")
    stiff = stiffness_study(ctx.quick)
    if stiff is not None:
        ctx.save_csv(stiff, "stiffness", float_format="%.6g")
    source = ("DEM records (rocking.simulate(block, None, model=\"dem\"))" if dem_available()
              else "PLACEHOLDER: classical-model records, until the DEM model exists")
    intro = H.p(
        "The paper identifies α and p by minimising the error surface of Eq 13 over the "
        "times of the free-rocking peaks and μ from Eq 12 (its Table II, column E). We have "
        "no raw records from the laboratory, so each stone's free-rocking test is simulated "
        f"and identified with rocking.identify.free_rocking. Records: {source}; released "
        f"from rest at {THETA0:g} α after a {HOLD:g} s hold, "
        f"{QUICK_DURATION if ctx.quick else DURATION:g} s, sampled at "
        f"{FS:g} Hz with Gaussian noise of {100 * NOISE:g} % of the release angle and a "
        "random constant offset. T: Eqs 2-4 of the Table I rectangle (as the table2 "
        "section); 'simulated': the parameters of the simulated body; %: identified vs T.")
    if not dem_available():
        intro = H.box("<strong>PLACEHOLDER:</strong> the DEM model is not registered; this "
                      "section uses classical-model records. It switches to DEM records by "
                      "itself when <code>\"dem\" in rocking.models.MODELS</code>.") + intro
    out = intro + _html_table(df) + _discussion(df, res, stiff)
    if stiff is not None:
        out += _stiff_table(stiff)
    return out + _figures(res, ctx) + ctx.files_html()
