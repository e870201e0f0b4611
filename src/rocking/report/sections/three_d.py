"""Section: in three dimensions (issue 30).

The 3-D rigid-body model :mod:`rocking.models.rigid3d` (unilateral contact, Coulomb
friction, Newton impacts, Moreau-Jean time stepping) against the planar theory:

1. **The planar limit.** Specimen 2 as a box (Table I: 0.17 x 0.502 x 1.0 m, 228 kg)
   released from ``theta0 = alpha/2`` in the plane of its width and under the 5 Hz, 5 mm
   sine of Figure 7: the 3-D body's rocking angle against the classical model's (geometric
   alpha, p, and Housner's Eq 4 restitution, which the 3-D model is not given: it emerges
   from plastic impacts), and the error as the time step shrinks.
2. **Specimen 3 and torsion.** Peña et al. explain the 29 % difference between the
   identified alpha of specimen 3 (Table II, E: 0.154) and its theoretical one (T: 0.119) by
   3-D effects, a torsion about the vertical that makes the block behave as one with a
   larger base (their Fig 3). The 3-D model can test it: specimen 3 with its 5 mm cut
   corners is released from a small tilt, alone, with a twist velocity, and in a plane
   oblique to its width; alpha, p and mu are identified from each 3-D response with the
   paper's procedure (Eqs 11-13, :func:`rocking.identify.free_rocking`) and set against
   Table II.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from ... import identify
from ...blocks import Block, specimen
from ...models import MODELS, simulate
from ...motions import Sine
from ...plot import PALETTE, style_axes
from ...shapes import Shape
from ...shapes.mesh import convex_hull
from .. import html as H
from ..core import section

STEPS = (4e-4, 2e-4, 1e-4, 5e-5)  # s: the convergence study of the planar limit
FREE_T = (3.0, 4.0)  # s: quick, default
SINE_T = (2.5, 5.0)
SPEC3_T = (4.0, 6.0)
SPEC3_TILT = 0.05  # rad: about 0.4 alpha
# (label, release direction deg, twist velocity rad/s, friction)
SPEC3_CASES = (("in the plane of the width", 0.0, 0.0, 0.7),
               ("with a twist of 2 rad/s", 0.0, 2.0, 0.7),
               ("with a twist of 5 rad/s", 0.0, 5.0, 0.7),
               ("twist 2 rad/s, friction 0.3", 0.0, 2.0, 0.3),
               ("released 15 deg off the width's plane", 15.0, 0.0, 0.7))


# ------------------------------------------------------------------------ computations
def prism(block: Block, name: str) -> Shape:
    """The 3-D body of a planar :class:`Block` with a polygon: the polygon (x, z) extruded
    over the block's ``thickness`` (y), of the block's mass."""
    half = 0.5 * block.thickness
    v = np.array([(x, y, z) for y in (-half, half) for x, z in block.vertices])
    v, f = convex_hull(v)
    return Shape.from_arrays(v, f, mass=block.mass, name=name)


def planar_angle(resp, direction_deg: float = 0.0) -> np.ndarray:
    """The rocking angle of a ``rigid3d`` response in the vertical plane of ``direction``
    (deg from x), signed as the planar models' theta (positive: the up axis leans towards
    ``-direction``)."""
    q0, q1, q2, q3 = (resp.states[:, k] for k in range(3, 7))
    ux, uy = 2 * (q1 * q3 + q0 * q2), 2 * (q2 * q3 - q0 * q1)
    uz = 1 - 2 * (q1 ** 2 + q2 ** 2)
    c, s = math.cos(math.radians(direction_deg)), math.sin(math.radians(direction_deg))
    return -np.arctan2(ux * c + uy * s, uz)


def signed_tilt(resp, direction_deg: float = 0.0) -> np.ndarray:
    """The tilt of a ``rigid3d`` response (the angle of the body's up axis from the
    vertical, whatever the plane it leans in) with the sign of :func:`planar_angle`: the
    rocking angle of a body that rocks about an edge not normal to ``direction``."""
    q1, q2 = resp.states[:, 4], resp.states[:, 5]
    tilt = np.arccos(np.clip(1.0 - 2.0 * (q1 ** 2 + q2 ** 2), -1.0, 1.0))
    return np.where(planar_angle(resp, direction_deg) < 0.0, -tilt, tilt)


def planar_limit(quick: bool) -> dict:
    """Specimen 2 as a box and as a classical block: free rocking and Figure 7's sine; the
    3-D runs at each step of :data:`STEPS`."""
    b = specimen(2, params="geometric")
    box = Shape.box(b.width, b.thickness, b.height, mass=b.mass, name="specimen 2")
    classical = b.with_params(mu=1.0 - 1.5 * math.sin(b.alpha) ** 2)  # Eq 4
    i = 0 if quick else 1
    cases = {"free": (Sine(freq=1.0, amplitude=0.0, duration=FREE_T[i]), 0.5 * b.alpha),
             "sine": (Sine(freq=5.0, amplitude=0.005, duration=SINE_T[i]), 0.0)}
    out = {"block": classical, "runs": {}}
    for key, (motion, theta0) in cases.items():
        ref = simulate(classical, motion, model="housner", theta0=theta0, dt_out=1e-3,
                       duration=motion.duration)
        runs = {}
        for h in STEPS:
            r = simulate(box, motion, model="rigid3d", tilt0=theta0, step=h, dt_out=1e-3,
                         duration=motion.duration)
            runs[h] = r
        out["runs"][key] = (ref, runs)
    return out


def planar_table(res: dict) -> pd.DataFrame:
    rows = []
    for key, (ref, runs) in res["runs"].items():
        th_ref = np.interp(runs[STEPS[0]].t, ref.t, ref.theta)
        peak = float(np.max(np.abs(ref.theta)))
        for h, r in runs.items():
            th = planar_angle(r)
            n = min(len(th), len(th_ref))
            rows.append({
                "case": key, "step_s": h,
                "max_abs_theta_classical": peak,
                "max_abs_theta_3d": float(np.max(np.abs(th))),
                "max_error_over_peak": float(np.max(np.abs(th[:n] - th_ref[:n]))) / peak,
                "out_of_plane_tilt_max": float(np.max(np.abs(
                    planar_angle(r, 90.0)))),
                "twist_max": float(r.outputs["max_twist"]),
                "base_point_max_m": float(r.outputs["max_slide"]),
            })
    return pd.DataFrame(rows)


def planar_figure(res: dict):
    from matplotlib.figure import Figure

    fig = Figure(figsize=(9, 3.4), layout="constrained")
    axs = fig.subplots(1, 2)
    for ax, (key, (ref, runs)) in zip(axs, res["runs"].items(), strict=True):
        r = runs[STEPS[-1]]
        ax.plot(ref.t, np.degrees(ref.theta), color=PALETTE[0], lw=1.6,
                label="classical (Eq 4 restitution)")
        ax.plot(r.t, np.degrees(planar_angle(r)), color=PALETTE[1], ls="--", lw=1.2,
                label=f"3-D rigid body, step {STEPS[-1]:g} s")
        style_axes(ax, "time (s)", "θ (deg)")
        ax.set_title("free rocking from α/2" if key == "free"
                     else "5 Hz, 5 mm sine (Figure 7)", fontsize=10)
    handles, labels = axs[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncols=2, fontsize=8)
    fig.suptitle("Specimen 2 as a 3-D box in the planar limit", fontsize=10)
    return fig


def spec3_runs(quick: bool) -> pd.DataFrame:
    """Specimen 3 (5 mm cut corners) released from :data:`SPEC3_TILT`: each case of
    :data:`SPEC3_CASES` identified with Eqs 11-13."""
    block = specimen(3, params="geometric", shape="cut")
    body = prism(block, "specimen 3 (cut)")
    model = MODELS["rigid3d"]
    duration = SPEC3_T[0 if quick else 1]
    rows = []
    for label, direction, wz, friction in SPEC3_CASES:
        m = model(body, model.Options(tilt0=SPEC3_TILT, direction=direction,
                                      friction=friction))
        y0 = m.initial_state()
        y0[12] = wz
        r = simulate(body, Sine(freq=1.0, amplitude=0.0, duration=duration),
                     model="rigid3d", state0=y0, tilt0=SPEC3_TILT, direction=direction,
                     friction=friction, dt_out=1e-3, duration=duration)
        theta = signed_tilt(r, direction)
        fit = identify.free_rocking(r.t, theta)
        rows.append({"case": label, "direction_deg": direction, "twist_velocity_rad_s": wz,
                     "friction": friction, "alpha": fit.alpha, "p": fit.p, "mu": fit.mu,
                     "max_twist_rad": float(r.outputs["max_twist"]),
                     "max_out_of_plane_rad": float(np.max(np.abs(planar_angle(r, 90.0))))})
    return pd.DataFrame(rows), block


# ----------------------------------------------------------------------------- section
@section("three_d", "Beyond the paper: in three dimensions (the 3-D rigid-body model)",
         order=69)
def build(ctx) -> str:
    res = planar_limit(ctx.quick)
    tab = planar_table(res)
    ctx.save_csv(tab, "planar_limit", float_format="%.6g")
    fig = ctx.save_figure(planar_figure(res), "planar_limit",
                          caption="Specimen 2 as a 3-D box (rigid3d) and as the classical "
                          "block: the 3-D body is given no restitution; plastic impacts "
                          "give Housner's Eq 4.")
    b = res["block"]
    trs = [[H.Cell(r.case, "l"), f"{r.step_s:g}", H.fmt(r.max_abs_theta_classical, 5),
            H.fmt(r.max_abs_theta_3d, 5), f"{100 * r.max_error_over_peak:.2f} %",
            f"{r.out_of_plane_tilt_max:.1e}", f"{r.twist_max:.1e}", f"{r.base_point_max_m:.1e}"]
           for r in tab.itertuples()]
    html = H.p(
        "The planar limit. Specimen 2 (Table I) as a 3-D box on a rigid ground with "
        "Coulomb friction 0.7 and no restitution, released from θ0 = α/2 and shaken by "
        "the 5 Hz, 5 mm sine of Figure 7 along its width; the classical model with the "
        f"geometric α = {b.alpha:.4f} rad, p = {b.p:.4f} 1/s and Housner's Eq 4 "
        f"μ = {b.mu:.4f}. The 3-D model is not given μ: each plastic impact conserves "
        "the angular momentum about the new edge, which is Eq 4. The error is the largest "
        "difference of θ(t) over the run, relative to the classical peak; it shrinks with "
        "the step (Moreau-Jean is first order at impacts). The base point (the centre of the "
        "base, carried with the body) moves with the rocking, b (1 - cos θ) for an edge at "
        "b; no sliding, no twist and no tilt out of the plane appear, to rounding.")
    html += H.table(["case", "step (s)", "max |θ| classical (rad)", "max |θ| 3-D (rad)",
                     "max error / peak", "out of plane (rad)", "twist (rad)",
                     "base point moved (m)"],
                    trs)
    html += fig

    df, block = spec3_runs(ctx.quick)
    ctx.save_csv(df, "specimen3", float_format="%.6g")
    paper_t, paper_e = 0.119, 0.154  # Table II, specimen 3
    geo = math.atan(0.5 * block.width / (0.5 * block.height))
    cut_alpha = block.alpha
    trs = [[H.Cell(r.case, "l"), H.fmt(r.alpha, 4), H.fmt(r.p, 3), H.fmt(r.mu, 4),
            f"{r.max_twist_rad:.3g}", f"{r.max_out_of_plane_rad:.2g}"]
           for r in df.itertuples()]
    dev = float(np.max(np.abs(df["alpha"] / cut_alpha - 1.0)))
    html += H.p(
        "Specimen 3 and torsion. Peña et al. attribute the identified α of specimen 3 "
        f"(Table II, E: {paper_e}) being 29 % above the theoretical one (T: {paper_t}) to "
        "a torsion about the vertical, seen under a 5 Hz sine (their Fig 3). Here specimen 3 "
        f"with its 5 mm cut corners (geometric α {cut_alpha:.4f} rad; {geo:.4f} without "
        f"the cuts) is released in the 3-D model from a tilt of {SPEC3_TILT} rad, alone, "
        "with a twist velocity, with less friction, and in a plane oblique to its width, "
        "and α, p and μ are identified from each response as the paper did (Eqs 11-13).")
    html += H.table(["release", "α identified (rad)", "p (1/s)", "μ", "max twist (rad)",
                     "max tilt about x (rad)"], trs)
    html += H.p(
        f"What comes out: the identified α stays within {100 * dev:.1f} % of the cut "
        f"shape's geometric {cut_alpha:.4f} rad in every case, below "
        f"Table II's T ({paper_t}) and far from E ({paper_e}). A rigid block that twists "
        "while it rocks still pivots on its base edge, so its α is that edge's; friction "
        "on the edge stops the twist within a few rocking cycles; and a release oblique "
        "to the width, which starts on a corner, settles into rocking about the edge "
        "(its α is the tilt's, whatever the plane; lower, not higher, while on the "
        "corner). In this rigid-body model torsion does not explain specimen 3's larger α "
        "in free rocking: "
        "the paper's explanation needs something the model does not have (a base that is "
        "not rigid or not flat, the rocking about a finite contact surface that their "
        "section 4.1 describes for specimen 4, or a torsion sustained by the forcing, which "
        "free rocking lacks).")
    return html + ctx.files_html()
