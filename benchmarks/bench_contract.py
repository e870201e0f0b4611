"""Benchmark: batch throughput of the classical and CCRR models, this tree against an
earlier commit, back to back in one run (issue 29: the model contract for any state must
cost no more than 3 %).

The earlier commit is checked out with ``git worktree`` into a temporary folder; each
round runs one subprocess per tree (alternating which goes first), each timing
``rocking.simulate_many`` on the same ``--n`` records of ``--duration`` s (the records of
``bench_housner.py``: band-limited noise, PGA 2.8-4.0 m/s^2 on specimen 2) after a warm-up
that compiles the kernels, on one numba thread, the least CPU time (``process_time``) of
three calls: the machine may be shared, and CPU time of one thread is what the contract
could change. Reported: sims/s per tree and round, and the ratio of the medians (this
tree / the base). The batches' ``max_abs_theta`` of both trees must agree
bit for bit (the contract changed no arithmetic). Usage::

    .venv/bin/python benchmarks/bench_contract.py --base 39fa9ec --n 400 --rounds 5
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

CHILD = r"""
import json, sys, time
sys.path.insert(0, {bench!r})
import numpy as np
import rocking
from bench_housner import make_records
recs = make_records({n}, {duration}, 7)
block = rocking.specimen(2, "experimental")
out = {{}}
for model in ("housner", "ccrr"):
    rocking.simulate_many(block, recs[:4], model=model)  # compile (or load the cache)
    best = float("inf")
    for _ in range({repeat}):  # the least CPU time of a few calls: the machine is shared
        t0 = time.process_time()
        res = rocking.simulate_many(block, recs, model=model)
        best = min(best, time.process_time() - t0)
    out[model] = {{"sims_per_s": len(recs) / best,
                   "max_abs_theta": res.max_abs_theta.tolist()}}
print(json.dumps(out))
"""


def run_tree(src: Path, n: int, duration: float) -> dict:
    code = CHILD.format(bench=str(ROOT / "benchmarks"), n=n, duration=duration, repeat=3)
    env = {"PYTHONPATH": str(src), "PATH": "/usr/bin:/bin", "NUMBA_NUM_THREADS": "1"}
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                       check=True)
    return json.loads(r.stdout.strip().splitlines()[-1])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", default="39fa9ec", help="the earlier commit")
    ap.add_argument("--n", type=int, default=400, help="records per batch")
    ap.add_argument("--duration", type=float, default=20.0, help="record length (s)")
    ap.add_argument("--rounds", type=int, default=5, help="alternating rounds")
    ap.add_argument("--quick", action="store_true",
                    help="a smoke check of the script: 4 records of 4 s, one round, this tree "
                         "against itself (no checkout)")
    args = ap.parse_args(argv)
    if args.quick:
        args.n, args.duration, args.rounds = 4, 4.0, 1
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp) / "base"
        if not args.quick:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "-q", "--detach",
                            str(base), args.base], check=True)
        try:
            trees = {"new": ROOT / "src", "base": ROOT / "src" if args.quick else base / "src"}
            runs: dict = {k: {"housner": [], "ccrr": []} for k in trees}
            same = True
            for r in range(args.rounds + 1):  # round 0 compiles both: not counted
                order = list(trees) if r % 2 else list(trees)[::-1]
                got = {k: run_tree(trees[k], args.n, args.duration) for k in order}
                for model in ("housner", "ccrr"):
                    same &= got["new"][model]["max_abs_theta"] == \
                        got["base"][model]["max_abs_theta"]
                    if r:
                        for k in trees:
                            runs[k][model].append(got[k][model]["sims_per_s"])
        finally:
            if not args.quick:
                subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force",
                                str(base)], check=False)
    print(f"{args.n} records of {args.duration:g} s, {args.rounds} alternating rounds "
          f"(base {args.base})")
    for model in ("housner", "ccrr"):
        med = {k: statistics.median(v[model]) for k, v in runs.items()}
        print(f"{model:8s} new {med['new']:8.1f} sims/s  base {med['base']:8.1f} sims/s  "
              f"ratio {med['new'] / med['base']:.3f}   (rounds: new "
              f"{[round(x) for x in runs['new'][model]]}, base "
              f"{[round(x) for x in runs['base'][model]]})")
    print("max_abs_theta identical in both trees:", same)
    print("ratio = this tree / base (goal: >= 0.97 for both models)")


if __name__ == "__main__":
    main()
