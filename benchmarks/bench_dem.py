"""Benchmark: speed of the discrete element model (simulated seconds per wall second).

Specimen 2 (Table I geometry, ``rocking.specimen(2, "geometric")``) under a ``--duration``
s synthetic record (seeded Gaussian noise band-limited to 1-10 Hz under an envelope, at
100 Hz), with the default (physical) stiffness and the damping calibrated to mu:

* a single block (PGA ``--pga``, above the uplift acceleration g tan(alpha) = 1.67 m/s^2);
* a two-block stack (specimen 2 on specimen 2, PGA ``--pga-stack``: the stack, twice as
  slender, uplifts at 0.83 m/s^2);
* the single block at other stiffnesses (the time step scales as 1/sqrt(K));
* a batch of records through ``simulate_many`` (parallel over records).

Wall times are the best of ``--repeat`` runs after a JIT warm-up (numba's cache and the
damping calibration's cache are filled by the warm-up). Nothing is written to disk.
``--quick`` (a smoke check of the script): 2 s records, one run, a batch of 2, unless
given::

    .venv/bin/python benchmarks/bench_dem.py --duration 20 [--quick]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import rocking

sys.path.insert(0, str(Path(__file__).parent))
from bench_housner import make_records  # noqa: E402

DT = 0.01


def make_record(duration, seed, pga, band=(1.0, 10.0)):
    """One band-limited noise record of peak ``pga`` (the generator of bench_housner.py)."""
    return make_records(1, duration, seed, band=band, pga=(pga, pga))[0]


def timed(fn, repeat):
    best = math.inf
    out = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


QUICK = {"duration": 2.0, "repeat": 1, "batch": 2}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--duration", type=float, default=20.0, help="record length (s)")
    ap.add_argument("--pga", type=float, default=2.5, help="PGA of the single block (m/s^2)")
    ap.add_argument("--pga-stack", type=float, default=1.2, help="PGA of the stack (m/s^2)")
    ap.add_argument("--seed", type=int, default=2007)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--batch", type=int, default=8, help="records in the batch run")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)

    blk = rocking.specimen(2, "geometric")
    stack = rocking.Stack([blk, blk])
    rec = make_record(args.duration, args.seed, args.pga)
    rec_s = make_record(args.duration, args.seed, args.pga_stack)

    t0 = time.perf_counter()
    rocking.simulate(blk, rec, model="dem", duration=1.0)  # JIT cache + damping calibration
    rocking.simulate(stack, rec_s, model="dem", duration=1.0)
    rocking.simulate_many(blk, [rec, rec], model="dem", duration=1.0)
    warm = time.perf_counter() - t0

    rows = []

    def run(label, block, motion, **kw):
        wall, r = timed(lambda: rocking.simulate(block, motion, model="dem", **kw), args.repeat)
        sim = r.info["n_steps"] * r.info["dt"]
        h = None
        if isinstance(block, rocking.Block):
            h = rocking.simulate(block, motion)
        rows.append((label, r.info["stiffness"], r.info["dt"], r.info["n_steps"], sim, wall,
                     sim / wall, 1e9 * wall / r.info["n_steps"], math.degrees(r.max_abs_theta),
                     None if h is None else math.degrees(h.max_abs_theta), r.overturned))

    run("single block (default K)", blk, rec)
    run("two-block stack (default K)", stack, rec_s)
    for K in (1e9, 1e11):
        run(f"single block, K = {K:.0e} N/m", blk, rec, stiffness=K)

    recs = [make_record(args.duration, args.seed + i, args.pga) for i in range(args.batch)]
    wall_b, b = timed(lambda: rocking.simulate_many(blk, recs, model="dem"), args.repeat)

    print(f"{blk!r}; {args.duration:g} s records at {1 / DT:g} Hz; warm-up {warm:.1f} s")
    print(f"{'run':<30}{'K (N/m)':>10}{'dt (s)':>10}{'steps':>10}{'sim s':>7}{'wall s':>8}"
          f"{'sim/wall':>9}{'ns/step':>8}{'max|th| DEM':>12}{'classical':>10}{'OVT':>5}")
    for (lab, K, dt, n, sim, wall, sps, ns, th, thh, ovt) in rows:
        print(f"{lab:<30}{K:>10.2e}{dt:>10.2e}{n:>10d}{sim:>7.1f}{wall:>8.3f}{sps:>9.1f}"
              f"{ns:>8.0f}{th:>11.3f}°{'' if thh is None else f'{thh:.3f}°':>10}"
              f"{'yes' if ovt else 'no':>5}")
    print(f"batch of {args.batch} records (simulate_many, parallel): {wall_b:.3f} s wall, "
          f"{args.batch * args.duration / wall_b:.1f} simulated s per wall s "
          f"({int(b.overturned.sum())} overturned)")
    per20 = rows[0][5] * 20.0 / args.duration
    print(f"single block: {per20:.3f} s of wall time per 20 s of record (goal, issue 33: "
          f"<= 0.3 s): {'ok' if per20 <= 0.3 else 'MISSED'}")
    goal = rows[0][5] <= 10.0 * args.duration / 20.0 and rows[1][5] <= 10.0 * args.duration / 20
    print(f"goal (20 s of motion in < 10 s of wall time, single block and stack): "
          f"{'ok' if goal else 'MISSED'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
