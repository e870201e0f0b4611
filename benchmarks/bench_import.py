"""Benchmark: start-up cost of ``import rocking`` and of the lazy submodules.

Each figure is the median wall time of ``--repeat`` fresh interpreters (subprocesses), minus
the median of a bare interpreter start, so it is the cost of the import alone. With
``--src DIR`` it times another checkout (e.g. an older commit) for comparison.

    .venv/bin/python benchmarks/bench_import.py --repeat 15

``--quick`` (a smoke check of the script): one interpreter per case, unless ``--repeat``.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time

CASES = {
    "python (baseline)": "pass",
    "import rocking": "import rocking",
    "import rocking; rocking.identify.free_rocking":
        "import rocking; rocking.identify.free_rocking",
    "import rocking; rocking.simulate": "import rocking; rocking.simulate",
}


def wall(code: str, env: dict) -> float:
    """Wall time of a fresh interpreter running ``code`` (NaN if it fails)."""
    t0 = time.perf_counter()
    ok = subprocess.run([sys.executable, "-c", code], env=env,
                        stderr=subprocess.DEVNULL).returncode == 0
    return time.perf_counter() - t0 if ok else float("nan")


QUICK = {"repeat": 1}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=11)
    ap.add_argument("--src", help="time the package found in this src folder instead")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)
    env = dict(os.environ)
    if args.src:
        env["PYTHONPATH"] = args.src
    res = {}
    for _ in range(args.repeat):  # round-robin, fair to a machine shared with other jobs
        for name, code in CASES.items():
            res.setdefault(name, []).append(wall(code, env))
    base = statistics.median(res["python (baseline)"])
    failed = 0
    for name, ts in res.items():
        med = statistics.median(ts)
        if med != med:
            print(f"{name:48s} fails")
            failed += 1
            continue
        extra = "" if name.startswith("python") else f"  (import cost {med - base:.3f} s)"
        print(f"{name:48s} median {med:.3f} s{extra}")
    return 1 if failed else 0  # a case that fails is a broken import, not a figure


if __name__ == "__main__":
    raise SystemExit(main())
