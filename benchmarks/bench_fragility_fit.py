"""Benchmark: fragility fits on synthetic outcomes (no simulation).

Times, on 20 stripes x 50 records drawn from a lognormal fragility (median 2 m/s^2,
beta 0.4) and on 200 right-censored IDA capacities:

* :func:`rocking.analysis.fragility.fragility` with ``n_boot=0``, with the ``"normal"``
  bootstrap (``--n-boot`` draws, 1,000) and with the ``"resample"`` bootstrap (a fifth as
  many refits, 200);
* :func:`rocking.analysis.fragility.fragility_ida` (``n_boot=0``);
* :func:`rocking.analysis.damage.fragility_curves` (3 states, common beta, ``--n-boot``).

Each time is the median of ``--repeat`` warm calls (the first, import-laden, call is
reported apart). Nothing is written to disk. ``--quick`` (a smoke check of the script):
one warm call, 50 bootstrap draws, unless given. Usage::

    .venv/bin/python benchmarks/bench_fragility_fit.py [--repeat 5] [--n-boot 1000] [--quick]
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np
from scipy.stats import norm

from rocking.analysis.damage import fragility_curves
from rocking.analysis.fragility import fragility, fragility_ida

MEDIAN, BETA = 2.0, 0.4


def timed(fn, repeat: int):
    t0 = time.perf_counter()
    fn()
    cold = time.perf_counter() - t0
    warm = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        warm.append(time.perf_counter() - t0)
    return cold, statistics.median(warm)


QUICK = {"repeat": 1, "n_boot": 50}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--n-boot", type=int, default=1000, help="bootstrap draws")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)
    nb = args.n_boot
    rng = np.random.default_rng(0)
    im = np.repeat(MEDIAN * np.exp(np.linspace(-2, 2, 20) * BETA), 50)
    failed = rng.random(im.size) < norm.cdf(np.log(im / MEDIAN) / BETA)
    cap = MEDIAN * np.exp(BETA * rng.standard_normal(200))
    cens = cap > 1.2 * MEDIAN
    cap[cens] = 1.2 * MEDIAN
    u = rng.standard_normal(im.size)
    med = np.array([1.0, 2.0, 3.0])
    state = (np.cumprod(np.log(im)[:, None] - np.log(med) >= BETA * u[:, None], axis=1)
             .sum(axis=1))
    cases = {
        "fragility, n_boot=0": lambda: fragility(im, failed, n_boot=0),
        f"fragility, normal bootstrap {nb}": lambda: fragility(im, failed, n_boot=nb),
        f"fragility, resample bootstrap {max(1, nb // 5)}":
            lambda: fragility(im, failed, n_boot=max(1, nb // 5), bootstrap="resample"),
        "fragility_ida, 200 records": lambda: fragility_ida(cap, cens, n_boot=0),
        "fragility_curves, 3 states": lambda: fragility_curves(im, state, n_boot=nb),
    }
    print(f"{'case':40s} {'cold (s)':>10s} {'warm (s)':>10s}")
    for name, fn in cases.items():
        cold, warm = timed(fn, args.repeat)
        print(f"{name:40s} {cold:10.3f} {warm:10.4f}")


if __name__ == "__main__":
    main()
