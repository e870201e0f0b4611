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

Run: ``python benchmarks/bench_rigid3d.py [--quick]`` (``--quick``: 2 s of record, fewer
prisms; every section).
"""

from __future__ import annotations

import argparse
import math
import time
import warnings

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


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="2 s of record, fewer prisms")
    args = ap.parse_args(argv)
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
