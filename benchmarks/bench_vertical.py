"""Benchmark: throughput with and without a vertical ground motion (issue 12).

The 400 records of ``bench_housner.py`` (band-limited noise, 20 s at 100 Hz, PGA
2.8-4.0 m/s^2, specimen 2 experimental) are run by the classical and CCRR models

* as plain records (the horizontal-only path);
* wrapped in ``GroundMotion(h)`` (no vertical component): must give bit-identical
  results at the same speed;
* as ``GroundMotion(h, v)`` with a vertical component: a second noise record of the same
  family (1-15 Hz), scaled to 2/3 of the horizontal PGA (a common V/H ratio).

Each case is timed ``--repeat`` times after a warm-up, the cases interleaved (best and
median reported); ``steps`` is the total number of integration steps, which the vertical
component changes (the blocks rock differently). The goal
is a vertical-component throughput within 15 % of the horizontal-only one. Nothing is
written to disk. ``--quick`` (a smoke check of the script): 4 records of 4 s, one run,
unless given. Usage::

    .venv/bin/python benchmarks/bench_vertical.py [--n 400] [--repeat 3] [--quick]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

import rocking
from rocking.motions import GroundMotion, Record

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_housner import make_records  # noqa: E402


def timed(block, cases, model, repeat):
    """Best and median time of each case, the cases interleaved in every repetition (so
    that warm-up, frequency scaling and load affect them alike)."""
    for ms in cases.values():
        rocking.simulate_many(block, ms[:8], model=model)  # warm-up (compile / cache)
    times = {k: [] for k in cases}
    res = {}
    for _ in range(repeat):
        for name, ms in cases.items():
            t0 = time.perf_counter()
            res[name] = rocking.simulate_many(block, ms, model=model)
            times[name].append(time.perf_counter() - t0)
    return {k: (res[k], min(v), statistics.median(v)) for k, v in times.items()}


QUICK = {"n": 4, "duration": 4.0, "repeat": 1}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=400)
    ap.add_argument("--duration", type=float, default=20.0)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--models", default="housner,ccrr")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)
    block = rocking.specimen(2, "experimental")
    hs = make_records(args.n, args.duration, 2007)
    vs = make_records(args.n, args.duration, 2012, band=(1.0, 15.0), pga=(1.0, 1.0))
    vs = [Record(v.acc * (2.0 / 3.0) * h.pga, v.dt, name=v.name) for h, v in zip(hs, vs,
                                                                                 strict=True)]
    cases = {"horizontal only": hs,
             "GroundMotion(h)": [GroundMotion(h) for h in hs],
             "GroundMotion(h, v)": [GroundMotion(h, v) for h, v in zip(hs, vs, strict=True)]}
    print(f"{args.n} records x {args.duration:g} s at 100 Hz, specimen 2 (experimental), "
          f"best / median of {args.repeat}")
    print(f"{'model':<8} {'case':<20} {'best s':>7} {'median s':>9} {'sims/s':>8} "
          f"{'vs H':>6} {'overturned':>10} {'identical':>9} {'steps':>9}")
    for model in args.models.split(","):
        out = timed(block, cases, model, args.repeat)
        base_res, base_best, _ = out["horizontal only"]
        for name, (res, best, med) in out.items():
            same = "-" if name == "horizontal only" else (
                "yes" if np.array_equal(res.max_abs_theta, base_res.max_abs_theta,
                                        equal_nan=True)
                and np.array_equal(res.n_impacts, base_res.n_impacts) else "no")
            print(f"{model:<8} {name:<20} {best:7.3f} {med:9.3f} {args.n / best:8.0f} "
                  f"{best / base_best:6.3f} {int(res.overturned.sum()):10d} {same:>9} "
                  f"{int(res.n_steps.sum()):>9d}")


if __name__ == "__main__":
    main()
