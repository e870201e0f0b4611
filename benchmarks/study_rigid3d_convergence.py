"""Study: the contact solver's convergence of ``rigid3d`` on many-vertex supports (issue 30).

Counts the time steps whose contact problem missed its tolerance (``unconverged_steps``)
on the runs where they were seen: the example statue (its 64-sided round plinth) under the
built-in pairs (Rinaldi, Duzce with their verticals) turned to 4 headings and scaled to 8
PGAs each, as the report's section "In three dimensions" (64 runs), the exact cylinder
(r = 0.15 m, H = 1.0 m) and the slender box (0.2 x 0.2 x 1.0 m) of
``bench_rigid3d_campaign.py`` under the same grid, and the CPU time of each set (one
process; the batch's threads as numba has them: compare the ratios printed in one run).

Measured (the 2-core development machine, one numba thread, the two versions in one
session; statue / cylinder / box, runs with unconverged steps and their steps, of 64):
before the mixed stick/slip polish and the plain Moreau-Jean fallback 41/855, 16/51,
22/37; after 12/18, 0/0, 4/4 (the box's: each the last step of a run that overturns).
CPU time of the grid, after/before (best of two, run in turn): 0.62, 1.00, 1.00.

Run: ``python benchmarks/study_rigid3d_convergence.py [--quick] [--max-iter N]``.
"""

from __future__ import annotations

import argparse
import math
import time
import warnings

import numpy as np

from rocking import G, simulate_many
from rocking.motions import HorizontalPair
from rocking.shapes import Shape, load_example

PAIRS = ("rinaldi", "duzce")
HEADINGS = (0.0, 90.0, 180.0, 270.0)
PGA = (0.1, 2.0)


def samples(n_levels: int):
    """The report's statue grid: every (pair, heading) its own PGAs of a ladder."""
    n_s = len(PAIRS) * len(HEADINGS)
    levels = np.geomspace(*PGA, n_s * n_levels).reshape(-1, n_s).T
    out, k = [], 0
    for name in PAIRS:
        pair = HorizontalPair.builtin(name)
        big = max(pair.pga_components)
        for heading in HEADINGS:
            turned = pair.rotated(-math.radians(heading))
            for lev in levels[k]:
                out.append(turned.scaled(lev * G / big))
            k += 1
    return out


def bodies():
    return {
        "statue": load_example(density=2600.0),
        "cylinder": Shape.cylinder(0.15, 1.0, density=2000.0),
        "box": Shape.box(0.2, 0.2, 1.0, mass=100.0),
    }


def count(body, motions, **options):
    t0 = time.process_time()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = simulate_many(body, motions, model="rigid3d", **options)
    cpu = time.process_time() - t0
    u = np.asarray(r.outputs["unconverged_steps"], int)
    return u, cpu, r


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="2 PGAs per (pair, heading)")
    ap.add_argument("--max-iter", type=int, default=None)
    ap.add_argument("--bodies", default="statue,cylinder,box")
    a = ap.parse_args(argv)
    ms = samples(2 if a.quick else 8)
    opts = {} if a.max_iter is None else {"max_iter": a.max_iter}
    bs = bodies()
    count(bs["box"], ms[:1], duration=0.2)  # compile / load
    print(f"== unconverged contact steps ({len(ms)} runs per body: 2 pairs x "
          f"{len(HEADINGS)} headings x {len(ms) // 8} PGAs)")
    for name in a.bodies.split(","):
        u, cpu, r = count(bs[name], ms, **opts)
        print(f"  {name:<9} runs with unconverged steps {int((u > 0).sum()):3d} / {len(u)}, "
              f"steps {int(u.sum()):6d}, overturned {int(np.sum(r.overturned)):3d}, "
              f"CPU {cpu:7.2f} s")


if __name__ == "__main__":
    main()
