"""Benchmark: compiled batch Housner model vs the scipy reference.

Builds ``--n`` synthetic accelerograms (seeded Gaussian noise band-limited to 1-10 Hz under
an envelope, ``--duration`` s at 100 Hz, PGA uniform in [2.8, 4.0] m/s^2 so that specimen 2
rocks and some records overturn it), then

* times ``rocking.simulate_many(rocking.specimen(2, "experimental"), records)`` (after a
  JIT warm-up on a small batch);
* times the scipy reference (``solve_ivp`` DOP853 with events, rtol 1e-8) on the first
  ``--ref-n`` records and extrapolates the time per simulation;
* compares ``max_abs_theta`` of the batch with a tight reference (rtol 1e-11) on those
  records.

Nothing is written to disk. ``--quick`` (a smoke check of the script): 4 records of 4 s,
one with the reference, unless given. Usage::

    .venv/bin/python benchmarks/bench_housner.py --n 400 --duration 20 --ref-n 10 [--quick]
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np
from scipy.signal import butter, sosfiltfilt

import rocking
from rocking.motions import Record
from rocking.testing.housner_reference import simulate_reference

DT = 0.01


def make_records(n, duration, seed, band=(1.0, 10.0), pga=(2.8, 4.0)):
    """``n`` band-limited noise records with a build-up / strong-motion / decay envelope."""
    rng = np.random.default_rng(seed)
    m = int(round(duration / DT)) + 1
    t = np.arange(m) * DT
    sos = butter(4, band, btype="bandpass", fs=1.0 / DT, output="sos")
    t1, t2 = 0.15 * duration, 0.55 * duration
    env = np.where(t < t1, (t / t1) ** 2,
                   np.where(t < t2, 1.0, np.exp(-3.0 * (t - t2) / (duration - t2))))
    out = []
    for i in range(n):
        x = sosfiltfilt(sos, rng.standard_normal(m)) * env
        x *= rng.uniform(*pga) / np.abs(x).max()
        out.append(Record(x, DT, name=f"noise-{seed}-{i}"))
    return out


QUICK = {"n": 4, "duration": 4.0, "ref_n": 1}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=400, help="number of records in the batch")
    ap.add_argument("--duration", type=float, default=20.0, help="record length (s)")
    ap.add_argument("--ref-n", type=int, default=10, help="records run with the reference")
    ap.add_argument("--seed", type=int, default=2007)
    ap.add_argument("--rtol", type=float, default=1e-8, help="rtol of the batch and of the "
                    "timed reference")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)
    ref_n = max(1, min(args.ref_n, args.n))

    block = rocking.specimen(2, "experimental")
    records = make_records(args.n, args.duration, args.seed)
    print(f"{block!r}")
    print(f"{args.n} records, {args.duration:g} s at {1 / DT:g} Hz, "
          f"pga {min(r.pga for r in records):.2f}-{max(r.pga for r in records):.2f} m/s^2 "
          f"(uplift at {block.uplift_acceleration:.2f} m/s^2)")

    # ---- compiled batch
    t0 = time.perf_counter()
    # the records' window exactly, as before runs went on until the block settles (issue 16)
    win = {"duration": args.duration}
    rocking.simulate_many(block, records[:2], rtol=args.rtol, **win)  # JIT warm-up / cache
    t_warm = time.perf_counter() - t0
    t_batch = math.inf
    for _ in range(3):  # best of 3
        t0 = time.perf_counter()
        batch = rocking.simulate_many(block, records, rtol=args.rtol, **win)
        t_batch = min(t_batch, time.perf_counter() - t0)
    sps_c = args.n / t_batch

    # ---- scipy reference, timed at the same rtol
    t0 = time.perf_counter()
    ref = [simulate_reference(block, r, rtol=args.rtol, method="DOP853", **win)
           for r in records[:ref_n]]
    t_ref = (time.perf_counter() - t0) / ref_n
    sps_r = 1.0 / t_ref

    # ---- accuracy against a tight reference
    t0 = time.perf_counter()
    tight = [simulate_reference(block, r, rtol=1e-11, method="DOP853", **win)
             for r in records[:ref_n]]
    t_tight = (time.perf_counter() - t0) / ref_n

    print()
    print(f"{'rec':>4} {'pga':>6} {'max|th| batch':>14} {'max|th| ref':>14} {'rel.err':>9} "
          f"{'imp b/r':>9} {'over b/r':>9}")
    errs = []
    for i, r in enumerate(tight):
        mb = float(batch.max_abs_theta[i])
        err = abs(mb - r.max_abs_theta) / r.max_abs_theta if r.max_abs_theta > 0 else (
            0.0 if mb == 0 else math.inf)
        errs.append(err)
        print(f"{i:>4} {records[i].pga:>6.2f} {mb:>14.8f} {r.max_abs_theta:>14.8f} {err:>9.2e} "
              f"{int(batch.n_impacts[i]):>4}/{r.n_impacts:<4} "
              f"{int(batch.overturned[i]):>4}/{int(r.overturned):<4}")
    same = sum(bool(batch.overturned[i]) == r.overturned for i, r in enumerate(tight))
    sens = [abs(a.max_abs_theta - b.max_abs_theta) / max(b.max_abs_theta, 1e-300)
            for a, b in zip(ref, tight, strict=True)]
    agree_ref = max(sens)
    # Rocking under random input can be chaotic: where the reference itself moves by more
    # than 0.1% between rtol 1e-8 and 1e-11, no tolerance gives a converged maximum.
    well = [e for e, d in zip(errs, sens, strict=True) if d < 1e-3]
    n_within = sum(e <= 1e-2 for e in errs)

    ratio = sps_c / sps_r
    max_err = max(errs)
    print()
    print(f"{'':<40}{'value':>14}  goal")
    print(f"{'JIT warm-up (2 records)':<40}{t_warm:>13.2f}s")
    print(f"{'compiled batch: time (best of 3)':<40}{t_batch:>13.3f}s")
    print(f"{'compiled batch: simulations/s':<40}{sps_c:>14.1f}")
    print(f"{f'reference (DOP853, rtol {args.rtol:g}): sims/s':<40}{sps_r:>14.3f}")
    print(f"{'reference (rtol 1e-11): s/simulation':<40}{t_tight:>13.3f}s")
    print(f"{'speed ratio compiled/reference':<40}{ratio:>14.0f}  >= 500 "
          f"{'ok' if ratio >= 500 else 'MISSED'}")
    print(f"{f'max rel. error max|theta| ({ref_n} recs)':<40}{max_err:>14.2e}  <= 1e-2 "
          f"{'ok' if max_err <= 1e-2 else 'MISSED'}")
    print(f"{'records within 1%':<40}{f'{n_within}/{ref_n}':>14}")
    print(f"{'max rel. error, well-conditioned recs':<40}{max(well, default=0.0):>14.2e}  "
          f"({len(well)} records whose reference moves < 0.1% with rtol)")
    print(f"{'overturn agreement':<40}{f'{same}/{ref_n}':>14}")
    print(f"{f'ref rtol {args.rtol:g} vs 1e-11: max rel. diff':<40}{agree_ref:>14.2e}")
    print(f"{'batch: overturned / rocked':<40}"
          f"{f'{int(batch.overturned.sum())}/{int((batch.max_abs_theta > 0).sum())}':>14}"
          f"  of {args.n}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
