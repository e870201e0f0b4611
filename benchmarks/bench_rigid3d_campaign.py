"""Benchmark: 10^4 runs of the 3-D rigid body (``model = "rigid3d"``) in a campaign, the
figure of issue 30 ("10^4 runs in a campaign: at most 10 minutes on 2 cores").

The campaign (``rocking.campaign.run`` with the local executor: numba ``prange`` over
every core the process may use, one compiled parallel call per chunk; the records read
and the bodies settled once): four bodies (a slender box 0.2 x 0.2 x 1.0 m, a squat box
0.3 x 0.4 x 1.2 m, the exact cylinder r = 0.15 m, H = 1.0 m, and the example statue,
``rocking.shapes.example``, 2600 kg/m^3) x the two built-in three-component pairs
(``rinaldi``: Northridge 1994, 20 s, 0.87 g; ``duzce``: Kocaeli 1999 at Duzce, 27 s,
0.36 g; each with its vertical) x 25 headings (0-345.6 deg) x 50 load factors
(0.05-2.5): 10,000 runs, each to the record's end and then on until the body is at rest
or has overturned (the campaign's default), at the model's default step. Summaries only
(no histories), ``chunk_size = 500``.

The kernels are compiled (or loaded from numba's cache) by a tiny campaign first, not
timed. Printed: the wall time, the process's CPU time (all threads), the machine's load
before and after (``/proc/loadavg``: on a shared machine the wall time is an upper bound),
simulations per second, the time extrapolated to 10^4 runs, and per body the share that
overturned, the share settled (at rest or overturned when the run ended), the mean
number of impacts and the runs with unconverged contact steps (``unconverged_steps``).

``--quick``: ~100 runs (the four bodies x the two pairs x 3 headings x 4 levels, 2 s
windows: ``duration = 2``, no warm-up), for the benchmarks' smoke test; its rate is not
the figure (short windows, the kernels loaded and Python around each chunk).
``--blocks box,statue`` keeps some bodies (the full grid then has fewer runs; the
extrapolation still says 10^4); ``--headings N --levels M`` a coarser grid of the same
ranges (a sample of the full campaign, for a shared machine: the time for 10^4 runs is
extrapolated from the wall time and, for 2 idle cores, from the CPU time: CPU per run x
10^4 / 2). Stores and specs go to a temporary directory, removed at the end::

    .venv/bin/python benchmarks/bench_rigid3d_campaign.py [--quick] [--blocks box,statue]

To measure on exactly 2 cores of a larger machine: ``NUMBA_NUM_THREADS=2 taskset -c 0,1
python benchmarks/bench_rigid3d_campaign.py``.
"""

from __future__ import annotations

import argparse
import os
import shutil
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

from rocking.errors import PlausibilityWarning
from rocking.shapes import example

BODIES = {
    "box": 'name = "slender box"\nbox = [0.2, 0.2, 1.0]\nmass = 100.0',
    "squat": 'name = "squat box"\nbox = [0.3, 0.4, 1.2]\ndensity = 2000.0',
    "cylinder": 'name = "cylinder"\ncylinder = [0.15, 1.0]\ndensity = 2000.0',
    "statue": f'name = "statue"\nmesh = "{example.example_mesh_path()}"\ndensity = 2600',
}


def spec_text(name: str, bodies, n_head: int, n_lev: int, chunk: int,
              duration: float | None) -> str:
    blocks = "\n".join(f"[[blocks]]\n{BODIES[b]}\n" for b in bodies)
    heads = ", ".join(f"{h:g}" for h in np.arange(n_head) * 360.0 / n_head)
    dur = "" if duration is None else f"duration = {duration}"
    return f"""
[campaign]
name = "{name}"
seed = 30
model = "rigid3d"
{dur}

{blocks}
[motions]
kind = "pair"
set = ["rinaldi", "duzce"]
load_factors = {{start = 0.05, stop = 2.5, num = {n_lev}}}

[options.rigid3d]
heading = [{heads}]

[run]
chunk_size = {chunk}
"""


def loadavg() -> str:
    try:
        return " ".join(Path("/proc/loadavg").read_text().split()[:3])
    except OSError:
        return "n/a"


def cores() -> str:
    try:
        n = len(os.sched_getaffinity(0))
    except AttributeError:
        n = os.cpu_count()
    import numba

    return f"{n} cores usable, numba threads {numba.config.NUMBA_NUM_THREADS}"


def run_campaign(root: Path, text: str, stem: str):
    from rocking import campaign

    spec = root / f"{stem}.toml"
    spec.write_text(text, encoding="utf-8")
    store = root / f"{stem}-store"
    t0, c0 = time.perf_counter(), time.process_time()
    with warnings.catch_warnings():  # counted from the rows (unconverged_steps) instead
        warnings.simplefilter("ignore", PlausibilityWarning)
        status = campaign.run(spec, store, progress=False, log=lambda *a: None)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    return status, campaign.load(store), wall, cpu


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="~100 runs of 2 s (a smoke test)")
    ap.add_argument("--headings", type=int, default=25, help="headings (full mode)")
    ap.add_argument("--levels", type=int, default=50, help="load factors (full mode)")
    ap.add_argument("--blocks", default=",".join(BODIES),
                    help=f"bodies, comma-separated, of {', '.join(BODIES)}")
    a = ap.parse_args(argv)
    bodies = [b.strip() for b in a.blocks.split(",") if b.strip()]
    bad = [b for b in bodies if b not in BODIES]
    if bad or not bodies:
        ap.error(f"--blocks: choose among {', '.join(BODIES)} (got {a.blocks!r})")
    n_head, n_lev, chunk, dur = ((3, 4, 50, 2.0) if a.quick
                                 else (a.headings, a.levels, 500, None))

    root = Path(tempfile.mkdtemp(prefix="rocking-bench-r3dc-"))
    try:
        print(f"machine: {cores()}; load {loadavg()}")
        if not a.quick:  # --quick: its rate is no figure (the first chunk loads too)
            t0 = time.perf_counter()
            run_campaign(root, spec_text("bench-warm", ["box"], 1, 1, 2, 0.5), "warm")
            print(f"warm-up (numba cache, imports): {time.perf_counter() - t0:.2f} s, not "
                  "timed")

        text = spec_text("bench-rigid3d", bodies, n_head, n_lev, chunk, dur)
        print(f"\n== campaign: {len(bodies)} bodies x 2 pairs x {n_head} headings x {n_lev} "
              f"levels{'' if dur is None else f', {dur:g} s windows'} (local executor)")
        load0 = loadavg()
        status, rows, wall, cpu = run_campaign(root, text, "run")
        n = len(rows)
        assert n == status["sims_done"] == len(bodies) * 2 * n_head * n_lev, (n, status)
        print(f"  runs {n}, wall {wall:.1f} s, CPU {cpu:.1f} s (all threads), load before "
              f"{load0}, after {loadavg()}")
        failed = int((rows["status"] != 0).sum())
        print(f"  failed runs: {failed}")
        print(f"  {'body':<14} {'runs':>5} {'overturned':>10} {'settled':>8} "
              f"{'impacts':>8} {'unconverged runs':>16}")
        for name, g in rows.groupby("block_name", sort=False):
            unconv = (int((g["unconverged_steps"] > 0).sum())
                      if "unconverged_steps" in g.columns else -1)
            print(f"  {name:<14} {len(g):5d} {g['overturned'].mean():10.3f} "
                  f"{g['settled'].mean():8.3f} {g['n_impacts'].mean():8.1f} {unconv:16d}")
        rate = n / wall
        two = cpu / n * 1e4 / 2.0  # 10^4 runs' CPU time shared by 2 cores, no other load
        print(f"\nsims/s {rate:.1f} (wall), CPU {cpu / n * 1e3:.1f} ms per run; 10^4 runs "
              f"extrapolated: {1e4 / rate:.0f} s = {1e4 / rate / 60:.1f} min from the wall "
              f"time, {two:.0f} s = {two / 60:.1f} min from the CPU time on 2 idle cores "
              f"(goal <= 10 min on 2 cores)")
    finally:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    main()
