"""Benchmark: the classical model's ``method="taylor"`` against the default ``"dopri"``.

The inputs of ``benchmarks/bench_housner.py`` (specimen 2, ``--n`` band-limited 20 s
records at 100 Hz, PGA 2.8-4.0 m/s^2, each run over the record's window). In one run:

* sims/s of ``method="dopri"`` (default), ``method="taylor"`` and of the linearised model
  (``linear=True``, the issue's other candidate), on 1 thread (CPU time,
  ``time.process_time``, best of ``--repeat``) and on 2 threads (wall time, best of
  ``--repeat``; on a shared machine the 2-thread figures are only as good as its load);
* the error in ``max |theta|`` against the tight nonlinear reference: the independent
  scipy implementation (:mod:`rocking.testing.housner_reference`, DOP853, rtol 1e-11) on
  the first ``--ref-n`` records, and the compiled default at rtol 1e-11 on all of them:
  median, 95th percentile and maximum of ``|max theta - ref| / ref``, records beyond 1 %,
  and the overturning outcomes that differ.

Usage::

    .venv/bin/python benchmarks/bench_taylor.py --n 400 --ref-n 40 [--quick]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numba
import numpy as np

import rocking
from rocking.testing.housner_reference import simulate_reference

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_housner import make_records  # noqa: E402

QUICK = {"n": 6, "duration": 4.0, "ref_n": 2, "repeat": 1}
VARIANTS = (("dopri (default)", {}), ("taylor", {"method": "taylor"}),
            ("linear=True (dopri)", {"linear": True}))


def timed(block, records, opts, threads, repeat, window):
    """Best-of-``repeat`` sims/s on ``threads`` threads (CPU time on 1, wall time on more)
    and the last result."""
    numba.set_num_threads(threads)
    clock = time.process_time if threads == 1 else time.perf_counter
    best, res = math.inf, None
    for _ in range(repeat):
        t0 = clock()
        res = rocking.simulate_many(block, records, **opts, **window)
        best = min(best, clock() - t0)
    return len(records) / best, res


def errors(x, ref, over, over_ref):
    """``(median, p95, max, n > 1 %, n outcome flips)`` of ``|x - ref| / ref``."""
    e = np.abs(x - ref) / np.where(ref > 0, ref, 1.0)
    return (float(np.median(e)), float(np.percentile(e, 95)), float(e.max()),
            int((e > 1e-2).sum()), int((np.asarray(over) != np.asarray(over_ref)).sum()))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=400, help="number of records")
    ap.add_argument("--duration", type=float, default=20.0, help="record length (s)")
    ap.add_argument("--ref-n", type=int, default=40, help="records run with the scipy "
                    "reference (about 1 s each)")
    ap.add_argument("--repeat", type=int, default=2, help="best of this many timings")
    ap.add_argument("--seed", type=int, default=2007)
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)
    args = ap.parse_args(argv)
    ref_n = max(1, min(args.ref_n, args.n))
    block = rocking.specimen(2, "experimental")
    records = make_records(args.n, args.duration, args.seed)
    window = {"duration": args.duration}
    print(f"{block!r}; {args.n} records of {args.duration:g} s at 100 Hz")
    for _, opts in VARIANTS:  # compile (or load the cache)
        rocking.simulate_many(block, records[:2], **opts, **window)
    threads0 = numba.get_num_threads()
    sps = {}
    res = {}
    for name, opts in VARIANTS:
        for th in (1, 2):
            sps[name, th], res[name] = timed(block, records, opts, min(th, threads0),
                                             args.repeat, window)
    numba.set_num_threads(threads0)
    tight = rocking.simulate_many(block, records, rtol=1e-11, **window)
    t0 = time.perf_counter()
    ref = [simulate_reference(block, r, rtol=1e-11, method="DOP853", **window)
           for r in records[:ref_n]]
    t_ref = time.perf_counter() - t0
    ref_th = np.array([r.max_abs_theta for r in ref])
    ref_over = np.array([r.overturned for r in ref])

    base = VARIANTS[0][0]
    print()
    print(f"{'variant':<22}{'1 thread':>10}{'ratio':>7}{'2 threads':>11}{'ratio':>7}  "
          f"(sims/s; 1 thread: CPU time, 2 threads: wall time)")
    for name, _ in VARIANTS:
        print(f"{name:<22}{sps[name, 1]:>10.0f}{sps[name, 1] / sps[base, 1]:>7.2f}"
              f"{sps[name, 2]:>11.0f}{sps[name, 2] / sps[base, 2]:>7.2f}")
    print()
    print(f"error in max|theta| against the nonlinear reference "
          f"(scipy DOP853 rtol 1e-11: {ref_n} records, {t_ref / ref_n:.2f} s each; "
          f"compiled dopri rtol 1e-11: {args.n} records)")
    print(f"{'variant':<22}{'reference':<16}{'median':>10}{'p95':>10}{'max':>10}"
          f"{'>1%':>6}{'flips':>7}")
    for name, _ in VARIANTS:
        x = res[name]
        for rname, e in (
                (f"scipy ({ref_n})", errors(x.max_abs_theta[:ref_n], ref_th,
                                            x.overturned[:ref_n], ref_over)),
                (f"compiled ({args.n})", errors(x.max_abs_theta, tight.max_abs_theta,
                                                x.overturned, tight.overturned))):
            print(f"{name:<22}{rname:<16}{e[0]:>10.1e}{e[1]:>10.1e}{e[2]:>10.1e}{e[3]:>6d}"
                  f"{e[4]:>7d}")
    print()
    goal = sps["taylor", 2]
    print(f"goal: taylor on 2 threads {goal:.0f} sims/s (>= 3000: "
          f"{'ok' if goal >= 3000 else 'MISSED'}); 1 thread {sps['taylor', 1]:.0f} sims/s, "
          f"x2 = {2 * sps['taylor', 1]:.0f}")
    print(f"rocked {int((tight.max_abs_theta > 0).sum())}, overturned "
          f"{int(tight.overturned.sum())} of {args.n} (compiled reference)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
