"""Overturning spectrum of 40 frequency ratios to 0.5% precision (issue 10).

Times :func:`rocking.analysis.overturning.overturning_spectrum` (upward scan of the default
amplitude grid, 5% steps, then vectorised bisection; one ``simulate_many`` call per step)
for specimen 2 (experimental parameters) under each pulse, and prints the wall time, the
number of simulations and the simulations per second. ``--quick`` (a smoke check of the
script): 2 ratios to 5 %, unless given.

    .venv/bin/python benchmarks/bench_overturning.py [--n 40] [--tol 0.005] [--pulse one_sine]
        [--quick]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import rocking
from rocking.analysis.overturning import PULSES, overturning_spectrum

QUICK = {"n": 2, "tol": 0.05}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=40, help="number of frequency ratios")
    ap.add_argument("--tol", type=float, default=0.005)
    ap.add_argument("--wmax", type=float, default=10.0, help="largest omega_p/p")
    ap.add_argument("--pulse", choices=PULSES + ("all",), default="all")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)
    block = rocking.specimen(2, "experimental")
    wr = np.linspace(0.5, args.wmax, args.n)
    # warm-up: numba cache load / compilation is not part of the figure
    overturning_spectrum(block, "one_sine", [1.0], tol=0.1)
    pulses = PULSES if args.pulse == "all" else (args.pulse,)
    print(f"{block!r}: {args.n} ratios omega_p/p in [0.5, {args.wmax:g}], tol {args.tol:g}")
    print(f"{'pulse':<24}{'wall (s)':>10}{'sims':>8}{'sims/s':>10}{'found':>7}{'mode 1':>8}"
          f"{'mode 2':>8}")
    for pulse in pulses:
        prm = {"gamma": 2.0, "nu": 0.0} if pulse == "mavroeidis_papageorgiou" else None
        t0 = time.perf_counter()
        df = overturning_spectrum(block, pulse, wr, tol=args.tol, pulse_params=prm)
        wall = time.perf_counter() - t0
        n = df.attrs["n_simulations"]
        found = df["mode"].notna()
        print(f"{pulse:<24}{wall:>10.2f}{n:>8d}{n / wall:>10.0f}{int(found.sum()):>7d}"
              f"{int((df['mode'] == 1).sum()):>8d}{int((df['mode'] == 2).sum()):>8d}")


if __name__ == "__main__":
    main()
