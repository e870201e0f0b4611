"""Benchmark: a fragility study from start to fitted curves.

Specimens 2, 3 and 4 (Table II E parameters) x the 30 seed earthquakes x 20 PGA levels
(1,800 simulations with the classical model): :func:`rocking.analysis.ida.ida` (one
compiled batch per specimen), then :func:`rocking.analysis.damage.fragility_curves` (three
damage states, common beta, ``--n-boot`` = 1,000 bootstrap draws) and the overturning curve
of :func:`rocking.analysis.fragility.fragility`. Prints the time of each phase, simulations
per second and the fitted medians and betas. ``--quick`` (a smoke check of the script): 8
levels, 50 bootstrap draws, unless given.

    .venv/bin/python benchmarks/bench_fragility_study.py [--levels 20] [--model housner]
        [--n-boot 1000] [--quick]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import rocking
from rocking.analysis.damage import fragility_curves
from rocking.analysis.fragility import fragility
from rocking.analysis.ida import ida
from rocking.motions import seed_earthquakes

QUICK = {"levels": 8, "n_boot": 50}  # fewer levels can leave a damage state empty


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--levels", type=int, default=20)
    ap.add_argument("--model", default="housner")
    ap.add_argument("--n-boot", type=int, default=1000, help="bootstrap draws of the fits")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)
    t0 = time.perf_counter()
    recs = seed_earthquakes()
    t_rec = time.perf_counter() - t0
    rocking.simulate_many(rocking.specimen(2), recs[:2], model=args.model)  # JIT warm-up
    t_sim = t_fit = 0.0
    n_sim = 0
    print(f"{'specimen':>8} {'sims':>5} {'sim s':>7} {'fit s':>6}  medians (m/s^2) of DS1..DS3, "
          "beta; overturning alone")
    for n in (2, 3, 4):
        blk = rocking.specimen(n, "experimental")
        lo = rocking.G * np.tan(blk.alpha)  # uplift of a block at rest
        levels = np.geomspace(0.8 * lo, 6.0 * lo, args.levels)
        t1 = time.perf_counter()
        table = ida(blk, recs, im="pga", levels=levels, model=args.model)
        t2 = time.perf_counter()
        curves = fragility_curves(table["im"], table["damage_state"], n_boot=args.n_boot,
                                  seed=0)
        ovt = fragility(table["im"], table["overturned"], n_boot=args.n_boot, seed=0)
        t3 = time.perf_counter()
        t_sim += t2 - t1
        t_fit += t3 - t2
        n_sim += len(table)
        med = ", ".join(f"{m:.2f}" for m in curves.medians)
        print(f"{n:>8} {len(table):>5} {t2 - t1:7.2f} {t3 - t2:6.2f}  {med}; "
              f"{curves.betas[0]:.3f}; {ovt.median:.2f} (beta {ovt.beta:.3f})")
    total = t_rec + t_sim + t_fit
    print(f"records {t_rec:.2f} s, simulations {t_sim:.2f} s ({n_sim / t_sim:.0f} sims/s), "
          f"fits {t_fit:.2f} s, total {total:.2f} s for {n_sim} simulations")


if __name__ == "__main__":
    main()
