"""The shared step loop against the per-model copies it replaced: throughput, back to back.

``src/rocking/models/_numerics/loop.py`` holds the event-driven loop of the classical and
anchored models (``docs/architecture.md``, "One step loop"). This script times
``rocking.simulate_many`` on the records of ``bench_housner.py`` with the working tree's
package ("new") and with the package of an older commit ("old", ``--old``, extracted with
``git archive`` into a temporary folder), each in its own subprocess, alternating
old/new ``--rounds`` times (ABAB...) so that the load of a shared machine hits both alike,
and reports per model the median times, the ratio of the medians (new/old; above 1: the
new loop is slower), the ratio of the minima and the range of the ratios of each old/new
pair, in CPU time of the process (``time.process_time``, steadier than the wall time on a
loaded machine; ``--threads 1`` keeps it to one core) and in wall time. Each subprocess
loads its compiled kernels (a first, untimed pass compiles them into the numba cache of
each tree) and reports the best of ``--repeat`` batches.

``--check`` also compares the outputs of both trees (``max_abs_theta``, ``overturn_time``,
``uplift_time``, ``n_impacts``, ``n_steps`` and the histories) with ``np.array_equal``.
``--quick`` (a smoke check of the script): 4 records of 4 s, one round, the working tree
against itself. Usage::

    .venv/bin/python benchmarks/bench_step_loop.py --old 39fa9ec [--models housner anchored]
        [--n 200] [--duration 20] [--rounds 3] [--threads 1] [--check] [--quick]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent

MODELS = {"housner": {}, "anchored": {}, "anchored-elastic": {"anchors": "elastic"},
          "ccrr": {}}

CHILD = r"""
import json, sys, time
import numpy as np
import rocking
from bench_housner import make_records
a = json.loads(sys.argv[1])
block = rocking.specimen(2, "experimental")
records = make_records(a["n"], a["duration"], a["seed"])
out = {}
for name in a["models"]:
    model = name.split("-")[0]
    opts = dict(a["options"][name])
    rocking.simulate_many(block, records[:2], model=model, **opts)  # compiled kernels
    wall = cpu = float("inf")
    for _ in range(a["repeat"]):
        t0, c0 = time.perf_counter(), time.process_time()
        res = rocking.simulate_many(block, records, model=model, **opts)
        wall = min(wall, time.perf_counter() - t0)
        cpu = min(cpu, time.process_time() - c0)
    out[name] = {"wall": wall, "cpu": cpu}
    if a["dump"]:
        h = rocking.simulate_many(block, records, model=model, return_histories=True, **opts)
        np.savez(f"{a['dump']}-{name}.npz", **{f: np.asarray(getattr(h, f)) for f in (
            "max_abs_theta", "overturn_time", "uplift_time", "n_impacts", "n_steps",
            "theta", "omega")})
print("RESULT " + json.dumps(out))
"""


def run_child(src: Path, args, dump: str = "") -> dict:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(src), str(HERE)]))
    if args.threads:
        env["NUMBA_NUM_THREADS"] = str(args.threads)
    a = {"n": args.n, "duration": args.duration, "seed": args.seed, "repeat": args.repeat,
         "models": args.models, "options": {m: MODELS[m] for m in args.models}, "dump": dump}
    p = subprocess.run([sys.executable, "-c", CHILD, json.dumps(a)], env=env,
                       capture_output=True, text=True, check=False)
    lines = [ln for ln in p.stdout.splitlines() if ln.startswith("RESULT ")]
    if p.returncode != 0 or not lines:
        raise SystemExit(f"benchmark child failed ({src}):\n{p.stdout}\n{p.stderr}")
    return json.loads(lines[-1][7:])


def extract(ref: str, into: Path) -> Path:
    """The package of commit ``ref`` (``git archive``), under ``into``."""
    tar = subprocess.run(["git", "-C", str(ROOT), "archive", ref, "src"], capture_output=True,
                         check=True).stdout
    subprocess.run(["tar", "-x", "-C", str(into)], input=tar, check=True)
    return into / "src"


def compare(old: str, new: str, models) -> int:
    import numpy as np

    bad = 0
    for m in models:
        a, b = np.load(f"{old}-{m}.npz"), np.load(f"{new}-{m}.npz")
        for f in a.files:
            same = np.array_equal(a[f], b[f], equal_nan=a[f].dtype.kind == "f")
            bad += not same
            if not same:
                print(f"  {m}: {f} differs")
        print(f"  {m}: {len(a['max_abs_theta'])} runs, "
              f"{'bit-identical' if not bad else 'DIFFERENT'}")
    return bad


QUICK = {"n": 4, "duration": 4.0, "rounds": 1, "repeat": 1, "old": ""}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--old", default="39fa9ec",
                    help="commit with the per-model loops ('': the working tree itself)")
    ap.add_argument("--models", nargs="+", default=["housner", "anchored"],
                    choices=sorted(MODELS))
    ap.add_argument("--n", type=int, default=200, help="records in the batch")
    ap.add_argument("--duration", type=float, default=20.0, help="record length (s)")
    ap.add_argument("--seed", type=int, default=2007)
    ap.add_argument("--rounds", type=int, default=3, help="old/new pairs, alternated")
    ap.add_argument("--repeat", type=int, default=3, help="batches per child (best kept)")
    ap.add_argument("--threads", type=int, default=0, help="NUMBA_NUM_THREADS (0: numba's)")
    ap.add_argument("--check", action="store_true", help="compare the outputs bit for bit")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)
    args = ap.parse_args(argv)
    new_src = ROOT / "src"
    with tempfile.TemporaryDirectory(prefix="bench-step-loop-") as tmp:
        old_src = extract(args.old, Path(tmp)) if args.old else new_src
        print(f"old: {args.old or 'working tree'}, new: working tree; {args.n} records of "
              f"{args.duration:g} s, models {', '.join(args.models)}, "
              f"threads {args.threads or 'numba default'}")
        # compile (or load) both trees' kernels, and keep their outputs for --check
        d_old, d_new = (str(Path(tmp) / "old"), str(Path(tmp) / "new")) if args.check else ("",
                                                                                         "")
        run_child(old_src, args, d_old)
        run_child(new_src, args, d_new)
        if args.check and compare(d_old, d_new, args.models):
            print("outputs differ")
        times = {"old": [], "new": []}
        for r in range(args.rounds):
            for which, src in (("old", old_src), ("new", new_src)):
                times[which].append(run_child(src, args))
                print(f"round {r + 1} {which}: " + ", ".join(
                    f"{m} {t['cpu']:.3f} s CPU ({t['wall']:.3f} s wall)"
                    for m, t in times[which][-1].items()), flush=True)
    for clock in ("cpu", "wall"):
        print(f"\n{clock} time (best of {args.repeat} per child)")
        print(f"{'model':<18}{'old median (s)':>15}{'new median (s)':>15}{'new/old':>9}"
              f"{'of minima':>10}{'min..max of pairs':>20}")
        for m in args.models:
            o = [t[m][clock] for t in times["old"]]
            n = [t[m][clock] for t in times["new"]]
            pairs = [b / a for a, b in zip(o, n, strict=True)]
            print(f"{m:<18}{statistics.median(o):>15.3f}{statistics.median(n):>15.3f}"
                  f"{statistics.median(n) / statistics.median(o):>9.3f}"
                  f"{min(n) / min(o):>10.3f}{f'{min(pairs):.3f}..{max(pairs):.3f}':>20}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
