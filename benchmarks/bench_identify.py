"""Benchmark: free-rocking identification of one 30 s record at 200 Hz.

Simulates a free-rocking test with the classical model (a 0.5 s hold, then the release
from rest at 0.8 alpha; 30 s at 200 Hz = 6,101 samples; Gaussian noise of 0.5 % of the
release angle; a constant offset), then times :func:`rocking.identify.free_rocking`:

* *cold*: the first call in this process (imports of scipy.optimize / scipy.special and
  first-call overheads included);
* *warm*: the median of ``--repeat`` further calls on the same record.

It prints the times and the identified parameters against the true ones, for each block
asked (``--blocks``: specimen numbers and/or ``slender``), and, with ``--rates``, the warm
time at other sampling rates. Nothing is written to disk. ``--quick`` (a smoke check of the
script): specimen 2 only, one warm call, the 50 Hz rate, unless given. Usage::

    .venv/bin/python benchmarks/bench_identify.py [--repeat 10] [--blocks 2 4 slender]
        [--rates 50 1000] [--quick]
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

import rocking

HOLD = 0.5
DURATION = 30.0
NOISE = 0.005
THETA0 = 0.8


def make_record(block, fs: float, seed: int = 2007):
    rng = np.random.default_rng(seed)
    th0 = THETA0 * block.alpha
    r = rocking.simulate(block, None, duration=DURATION, theta0=th0, dt_out=1.0 / fs)
    nh = int(round(HOLD * fs))
    t = np.concatenate((np.arange(nh) / fs, r.t + HOLD))
    th = np.concatenate((np.full(nh, th0), r.theta))
    y = th + NOISE * th0 * rng.standard_normal(t.size) + rng.uniform(-0.1, 0.1) * th0
    return t, y


def block_of(name: str):
    if name == "slender":
        return rocking.Block.from_params(0.08, 2.5, 0.95, name="slender")
    return rocking.specimen(int(name))


QUICK = {"repeat": 1, "blocks": ["2"], "rates": [50.0]}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=10, help="warm calls timed")
    ap.add_argument("--blocks", nargs="+", default=["2", "1", "4", "slender"],
                    help="specimen numbers and/or 'slender' (alpha 0.08, p 2.5, mu 0.95)")
    ap.add_argument("--rates", nargs="*", type=float, default=[50.0, 1000.0],
                    help="other sampling rates (Hz) timed warm")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)

    records = {name: make_record(block_of(name), 200.0) for name in args.blocks}
    t0 = time.perf_counter()
    from rocking.identify import free_rocking  # noqa: E402  (cold includes the import)

    first = args.blocks[0]
    fit = free_rocking(*records[first])
    cold = time.perf_counter() - t0
    print(f"one {DURATION:g} s record at 200 Hz ({records[first][0].size} samples), "
          f"0.5 % noise, offset, {HOLD:g} s hold")
    print(f"cold (first call, import included), {block_of(first).name}: {cold * 1e3:8.1f} ms")
    print()
    print(f"{'block':34s} {'warm median':>12s} {'min':>8s}  {'half-cycles':>11s}  "
          f"{'alpha err %':>11s} {'p err %':>8s} {'mu err %':>8s}")
    for name in args.blocks:
        block = block_of(name)
        t, y = records[name]
        times = []
        for _ in range(args.repeat):
            s = time.perf_counter()
            fit = free_rocking(t, y)
            times.append(time.perf_counter() - s)
        print(f"{block.name:34s} {statistics.median(times) * 1e3:9.1f} ms {min(times) * 1e3:5.1f}"
              f" ms  {fit.n_half_cycles:11d}  {100 * (fit.alpha / block.alpha - 1):+11.3f} "
              f"{100 * (fit.p / block.p - 1):+8.3f} {100 * (fit.mu / block.mu - 1):+8.3f}")
    for fs in args.rates:
        block = block_of(first)
        t, y = make_record(block, fs)
        times = []
        for _ in range(max(3, args.repeat // 2)):
            s = time.perf_counter()
            fit = free_rocking(t, y)
            times.append(time.perf_counter() - s)
        label = f"{block.name} at {fs:g} Hz"
        print(f"{label:34s} {statistics.median(times) * 1e3:9.1f} ms "
              f"{min(times) * 1e3:5.1f} ms  {fit.n_half_cycles:11d}  "
              f"{100 * (fit.alpha / block.alpha - 1):+11.3f} {100 * (fit.p / block.p - 1):+8.3f}"
              f" {100 * (fit.mu / block.mu - 1):+8.3f}")


if __name__ == "__main__":
    main()
