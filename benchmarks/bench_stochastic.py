"""Benchmark: stochastic records (Rezaeian & Der Kiureghian 2008) per second.

Generates ``--n`` records with the default parameters (32.7 s at 100 Hz, 3274 samples)
after a warm-up call (loading or compiling the numba kernels), and reports the median of
``--repeat`` runs as records per second. Usage::

    .venv/bin/python benchmarks/bench_stochastic.py [--n 200] [--repeat 3] [--quick]

``--quick`` (a smoke check of the script): 4 records, one run, unless given.
"""

from __future__ import annotations

import argparse
import statistics
import time

QUICK = {"n": 4, "repeat": 1}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=200, help="records per run")
    ap.add_argument("--repeat", type=int, default=3, help="runs")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)
    t0 = time.perf_counter()
    from rocking.motions import stochastic_records

    stochastic_records(2, seed=0)
    print(f"import + first call (kernels loaded or compiled): {time.perf_counter() - t0:.2f} s")
    times = []
    for k in range(args.repeat):
        t = time.perf_counter()
        stochastic_records(args.n, seed=k)
        times.append(time.perf_counter() - t)
    med = statistics.median(times)
    print(f"{args.n} records: median {med:.3f} s over {args.repeat} runs "
          f"= {args.n / med:.0f} records/s")


if __name__ == "__main__":
    main()
