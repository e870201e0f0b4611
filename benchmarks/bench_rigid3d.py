"""The 3-D rigid body's cost (``model="rigid3d"``, issue 30): CPU seconds per 20 s
three-component record for a box and the example statue, and the cost against the number
of hull vertices.

Goals (issue 30): a box under a 20 s three-component record in at most 0.1 s per core;
the example statue in at most 0.3 s. The record: Northridge 1994 at Rinaldi (both
horizontal components and the vertical, ``HorizontalPair.builtin("rinaldi")``), scaled
by 0.35 so that the 0.25 x 0.5 x 1 m box rocks hard (tilt 0.13 rad, about 65 impacts)
without overturning, and at full scale (it overturns). CPU time (``time.process_time``)
of one thread, the best of three, the kernels compiled beforehand.

Cost against the hull: regular n-gon prisms (meshes, r = 0.2 m, H = 1.2 m) under the same
record; no hull simplification is made (every hull vertex within reach of the ground is a
contact candidate), so the error in alpha is the polygon's own, ``alpha_n`` of the weakest
direction against the circle's ``atan(r / h)``, listed beside the exact cylinder
(``Shape.cylinder``: its rims are exact, 8 candidates whatever the drawing's segments).

Convergence (``--convergence PNG``, not in ``--quick``): the planar limit against the
classical model (box 0.25 x 0.5 x 1 m, friction 2, restitution 0): the largest tilt error
of free rocking from alpha / 2 (2 s, four impacts) and of a sine along x at 1.5 g
tan(alpha) (1.5 s) relative to the amplitude, the first impact's ratio against Eq 4, and
the exact cylinder's against its closed form, for steps from 1 ms to 25 us; the table and
the figure of ``docs/guide/rigid3d.rst``.

Run: ``python benchmarks/bench_rigid3d.py [--quick] [--convergence PNG]`` (``--quick``:
2 s of record, fewer prisms; every section).
"""

from __future__ import annotations

import argparse
import math
import time
import warnings

import numpy as np

import rocking
from rocking.models.rigid3d import Rigid3d
from rocking.motions import HorizontalPair
from rocking.shapes import Shape, load_example

SCALE = 0.35


def cpu(body, motion, duration, repeat=3):
    """Best CPU seconds of ``repeat`` runs and the last result."""
    best = math.inf
    for _ in range(repeat):
        t0 = time.process_time()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            r = rocking.simulate(body, motion, model="rigid3d", duration=duration,
                                 dt_out=0.01)
        best = min(best, time.process_time() - t0)
    return best, r


def row(name, body, motion, duration, repeat=3):
    s, r = cpu(body, motion, duration, repeat)
    step = Rigid3d.from_kwargs(body).info(0.01)["step_used"]
    print(f"  {name:<28} {s:8.3f} s  {s * 20.0 / duration:8.3f} s/20 s   step {step:.3g} s"
          f"   tilt {r.max_tilt:6.3f}  impacts {r.n_impacts:5d}  overturned "
          f"{str(r.overturned):5}  unconverged {r.unconverged_steps}")
    return s * 20.0 / duration


def tilt_of(states):
    q = states[:, 3:7]
    return 2.0 * np.arcsin(np.clip(np.hypot(q[:, 1], q[:, 2]), 0.0, 1.0))


def convergence(png):
    """The planar-limit convergence table, and its figure in ``png``."""
    from rocking import G
    from rocking.models.rigid3d import STEP_P
    from rocking.motions import Sine

    box = Shape.box(0.25, 0.5, 1.0, density=2500.0)
    blk = rocking.Block.rectangular(width=0.25, height=1.0)
    th0 = 0.5 * blk.alpha
    free = rocking.simulate(blk, None, model="housner", duration=2.0, theta0=th0,
                            dt_out=1e-3)
    sine = Sine.from_acceleration(2.0, 1.5 * G * math.tan(blk.alpha), 1.5)
    forced = rocking.simulate(blk, sine, model="housner", duration=1.5, dt_out=1e-3)
    r_, height = 0.2, 1.2
    cyl = Shape.cylinder(r_, height, density=2500.0)
    hc = 0.5 * height
    mu_cyl = 1 - 2 * r_**2 / (5 * r_**2 / 4 + 4 * hc**2 / 3)
    kw = {"model": "rigid3d", "friction": 2.0}
    steps = (1e-3, 5e-4, 2.5e-4, 2e-4, 1e-4, 5e-5, 2.5e-5)
    rows = []
    print("== convergence in the planar limit (box 0.25 x 0.5 x 1 m; cylinder r 0.2 m, "
          "H 1.2 m)")
    print(f"  {'h (s)':>8} {'h p':>8} {'free':>9} {'forced':>9} {'Eq 4':>9} {'cylinder':>9}"
          "   (largest tilt error / amplitude; |ratio - closed form|)")
    for h in steps:
        a = rocking.simulate(box, None, duration=2.0, tilt0=th0, dt_out=1e-3, step=h, **kw)
        e_free = np.max(np.abs(tilt_of(a.states) - np.abs(free.theta))) / th0
        b = rocking.simulate(box, sine, duration=1.5, dt_out=1e-3, step=h, **kw)
        e_forced = (np.max(np.abs(tilt_of(b.states) - np.abs(forced.theta)))
                    / forced.max_abs_theta)
        ratios = []
        for body, t0, mu in ((box, th0, blk.mu), (cyl, 0.5 * math.atan(r_ / hc), mu_cyl)):
            c = rocking.simulate(body, None, duration=0.6, tilt0=t0, dt_out=h, step=h, **kw)
            k = int(round(c.impact_times[0] / h))
            ratios.append(abs(c.states[k, 11] / c.states[k - 1, 11] - mu))
        rows.append((h, e_free, e_forced, *ratios))
        print(f"  {h:8.2g} {h * blk.p:8.2g} {e_free:9.2e} {e_forced:9.2e} {ratios[0]:9.2e}"
              f" {ratios[1]:9.2e}")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    arr = np.array(rows)
    fig, ax = plt.subplots(figsize=(6.4, 4.2), constrained_layout=True)
    for j, label in enumerate(("free rocking: max tilt error / amplitude",
                               "forced (sine 1.5 g tan alpha): max error / amplitude",
                               "box impact ratio - Eq 4",
                               "cylinder impact ratio - closed form"), start=1):
        ax.loglog(arr[:, 0], arr[:, j], "o-", label=label)
    ax.loglog(arr[:, 0], arr[:, 0] * (arr[-1, 1] / arr[-1, 0]), "k:", label="slope 1")
    h_def = STEP_P / blk.p
    ax.axvline(h_def, color="grey", lw=0.8)
    ax.axhline(0.01, color="grey", lw=0.8, ls="--")
    ax.text(h_def, 3e-2, " default step\n (7.5e-4 / p)", fontsize=8, color="grey")
    ax.set_xlabel("time step h (s)")
    ax.set_ylabel("error")
    ax.set_title("rigid3d against the classical model (planar limit)", fontsize=10)
    ax.legend(fontsize=7, loc="lower right")
    fig.savefig(png, dpi=110)
    print(f"  figure: {png}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="2 s of record, fewer prisms")
    ap.add_argument("--convergence", metavar="PNG", help="the convergence study's figure")
    args = ap.parse_args(argv)
    if args.convergence and not args.quick:
        convergence(args.convergence)
    duration = 2.0 if args.quick else 20.0
    repeat = 1 if args.quick else 3
    pair = HorizontalPair.builtin("rinaldi")
    box = Shape.box(0.25, 0.5, 1.0, density=2500.0)
    statue = load_example()
    cpu(box, pair.scaled(SCALE), 0.5, repeat=1)  # compile
    print(f"== rigid3d: CPU s per record ({duration:g} s of Rinaldi, 3 components; one "
          "thread)")
    b = row(f"box x{SCALE}", box, pair.scaled(SCALE), duration, repeat)
    row("box x1 (overturns)", box, pair, duration, repeat)
    s = row(f"statue x{SCALE}", statue, pair.scaled(SCALE), duration, repeat)
    row("statue x1 (overturns)", statue, pair, duration, repeat)
    print(f"  goal: box <= 0.1 s per 20 s ({b:.3f}), statue <= 0.3 s ({s:.3f})")

    print("== cost against the number of hull vertices (n-gon prisms r = 0.2 m, H = 1.2 m; "
          f"x{SCALE})")
    r_, height = 0.2, 1.2
    exact = math.atan(r_ / (0.5 * height))
    print(f"  {'body':<28} {'hull':>5} {'s/20 s':>8}   alpha_min  error in alpha")
    for n in ((8, 64) if args.quick else (4, 8, 16, 32, 64, 128)):
        prism = Shape.cylinder(r_, height, segments=n, density=2500.0)
        mesh = Shape.from_arrays(prism.vertices, prism.faces, density=2500.0,
                                 name=f"{n}-gon prism")
        a = mesh.parameters(mesh.weakest().phi)["alpha_plus"]
        c, _ = cpu(mesh, pair.scaled(SCALE), duration, repeat=1)
        print(f"  {mesh.name:<28} {len(mesh.hull_points()):5d} {c * 20 / duration:8.3f}"
              f"   {a:.5f}    {a / exact - 1:+.2e}")
    cyl = Shape.cylinder(r_, height, density=2500.0)
    c, _ = cpu(cyl, pair.scaled(SCALE), duration, repeat=1)
    print(f"  {'cylinder (exact rims)':<28} {8:5d} {c * 20 / duration:8.3f}   {exact:.5f}"
          f"    {0.0:+.2e}")
    print("  cost per hull vertex: the candidates are only the vertices within reach of "
          "the ground")


if __name__ == "__main__":
    main()
