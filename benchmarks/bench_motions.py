"""Benchmark: synthetic earthquakes and response spectra.

* the 30 paper records (:func:`rocking.motions.seed_earthquakes`) generated cold, i.e.
  without the memory or disk cache (``use_cache=False``), first in a fresh process (which
  includes loading the compiled numba kernels, or compiling them on a first install) and
  then again (warm);
* reading them back from the disk cache;
* one response spectrum over 200 log-spaced periods (0.02-4 s) of a 20 s record at
  100 Hz (2001 samples), the median of ``--repeat`` runs, and the same with pyrotd (a
  frequency-domain implementation) for reference if it is installed.

Nothing is written except the cache under a temporary ``ROCKING_CACHE_DIR``, removed at
the end. ``--quick`` (a smoke check of the script): 3 spectrum runs and no warm uncached
generation (``--no-warm``), unless ``--repeat`` (the 30 records are the package's fixed
set). Usage::

    .venv/bin/python benchmarks/bench_motions.py [--repeat 50] [--no-warm] [--quick]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import tempfile
import time

QUICK = {"repeat": 3, "warm": False}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=50, help="runs of the spectrum timing")
    ap.add_argument("--no-warm", dest="warm", action="store_false",
                    help="skip the second (warm) uncached generation of the 30 records")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)

    tmp = tempfile.mkdtemp(prefix="rocking-bench-")
    old = os.environ.get("ROCKING_CACHE_DIR")
    os.environ["ROCKING_CACHE_DIR"] = tmp
    try:
        run(args)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
        if old is None:
            os.environ.pop("ROCKING_CACHE_DIR", None)
        else:
            os.environ["ROCKING_CACHE_DIR"] = old


def run(args) -> None:
    import numpy as np

    import rocking
    from rocking.motions import check_compatibility, response_spectrum, seed_earthquakes
    from rocking.motions.spectra import log_periods
    from rocking.motions.synthetic import _cache_file, clear_cache

    print(f"rocking {rocking.__version__}, numpy {np.__version__}, {os.cpu_count()} CPU(s)")

    t0 = time.perf_counter()
    recs = seed_earthquakes(use_cache=False)
    t_first = time.perf_counter() - t0
    print(f"30 paper records, no cache, first call in this process: {t_first:6.2f} s")
    if args.warm:
        t0 = time.perf_counter()
        recs2 = seed_earthquakes(use_cache=False)
        t_warm = time.perf_counter() - t0
        same = all(np.array_equal(a.acc, b.acc) for a, b in zip(recs, recs2, strict=True))
        print(f"30 paper records, no cache, again (warm):                {t_warm:6.2f} s"
              f"   (identical: {same})")

    recs2 = seed_earthquakes()  # fills the memory and disk caches
    same = all(np.array_equal(a.acc, b.acc) for a, b in zip(recs, recs2, strict=True))
    print(f"30 paper records through the caches: identical to the uncached ones: {same}")
    clear_cache()
    t0 = time.perf_counter()
    seed_earthquakes()
    t_disk = time.perf_counter() - t0
    print(f"30 paper records from the disk cache:                    {t_disk * 1e3:6.1f} ms"
          f"   ({_cache_file().stat().st_size / 1e6:.2f} MB)")
    c = check_compatibility(recs)
    dev = c.record_deviation()
    print(f"  EC8 check: {'PASS' if c.passed else 'FAIL'}; mean/target over 0.05-3 s "
          f"{c.min_ratio:.3f}-{c.max_ratio:.3f}; records within {100 * dev.max():.1f} % "
          f"(median {100 * np.median(dev):.1f} %); mean PGA {c.mean_pga:.2f} m/s^2")

    rec = recs[19]
    T = log_periods(0.02, 4.0, 200)
    response_spectrum(rec, T)  # warm up
    times = []
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        response_spectrum(rec, T)
        times.append(time.perf_counter() - t0)
    print(f"response spectrum, 200 periods, 20 s at 100 Hz: median "
          f"{statistics.median(times) * 1e3:.2f} ms, min {min(times) * 1e3:.2f} ms "
          f"({args.repeat} runs)")
    try:
        import pyrotd
    except ImportError:
        print("pyrotd not installed: no reference timing")
    else:
        acc = np.concatenate([rec.acc, np.zeros(8 * rec.acc.size)]) / rocking.G
        t0 = time.perf_counter()
        pyrotd.calc_spec_accels(rec.dt, acc, 1.0 / T, 0.05)
        print(f"pyrotd {pyrotd.__version__} (FFT, zero-padded x9), same periods: "
              f"{(time.perf_counter() - t0) * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
