"""CCRR vs classical model throughput on the same 400 records (issue 3).

Times ``rocking.simulate_many(..., model="ccrr")`` (adaptive RKF45, default l) against the
classical model on the records of ``bench_housner.py`` (band-limited noise, 20 s at 100 Hz,
specimen 2 with the experimental parameters), and compares the maximum angles.

Timings are the best of ``--repeat`` runs after a warm-up. ``--quick`` (a smoke check of
the script): 4 records of 4 s, one run, unless given.

    .venv/bin/python benchmarks/bench_ccrr.py [--n 400] [--repeat 3] [--quick]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

import rocking

sys.path.insert(0, str(Path(__file__).parent))
from bench_housner import make_records  # noqa: E402


def timed(block, records, model, repeat=3):
    rocking.simulate_many(block, records[:2], model=model)  # JIT warm-up / cache load
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        res = rocking.simulate_many(block, records, model=model)
        best = min(best, time.perf_counter() - t0)
    return res, best


QUICK = {"n": 4, "duration": 4.0, "repeat": 1}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=400)
    ap.add_argument("--duration", type=float, default=20.0)
    ap.add_argument("--seed", type=int, default=2007)
    ap.add_argument("--repeat", type=int, default=3, help="timed runs (best reported)")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)
    block = rocking.specimen(2, "experimental")
    records = make_records(args.n, args.duration, args.seed)
    h, th = timed(block, records, "housner", args.repeat)
    c, tc = timed(block, records, "ccrr", args.repeat)
    both = ~h.overturned & ~c.overturned
    rel = np.abs(c.max_abs_theta[both] / h.max_abs_theta[both] - 1)
    print(f"{args.n} records of {args.duration:g} s, {block!r}")
    print(f"{'model':<10}{'time (s)':>10}{'sims/s':>10}")
    print(f"{'housner':<10}{th:>10.3f}{args.n / th:>10.1f}")
    print(f"{'ccrr':<10}{tc:>10.3f}{args.n / tc:>10.1f}")
    print(f"throughput ratio ccrr/housner: {th / tc:.3f} (goal >= 0.2)")
    print("statistics (single random-record trajectories are chaotic; compare the set):")
    print(f"  overturned: housner {h.overturned.mean():.3f}, ccrr {c.overturned.mean():.3f}")
    print(f"  median max|theta| of standing blocks: housner "
          f"{np.median(h.max_abs_theta[~h.overturned]):.4f} rad, ccrr "
          f"{np.median(c.max_abs_theta[~c.overturned]):.4f} rad")
    print(f"  record by record (both standing, {both.sum()}): median |rel. diff| "
          f"{np.median(rel):.2e}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
