"""Benchmark: campaigns on the floors of a building (issue 18) against the same runs on
the ground.

10^4 classical runs (``--records`` 100 stochastic records of 20 s at 100 Hz x ``--levels``
100 load factors 0.25-2.5, specimen 2 experimental, chunks of 2000) on the roof of a
5-storey shear building (T1 = 0.5 s, 5 %), in one process, CPU time (all threads,
``time.process_time``) of every chunk of a fresh :class:`rocking.campaign.Campaign`:

* ``floors``: the spec with ``[building]`` (``floors = [5]``): the ground records are
  made, filtered once per (floor, record) into :class:`rocking.buildings.FloorMotion`, and
  every row runs on its floor motion scaled to its level.
* ``same runs on the ground``: the same rows with no building layer: the spec without
  ``[building]`` whose rows get, instead of their ground motion, the same floor
  acceleration as a plain :class:`rocking.motions.Record` (computed before the timing).
  The block feels the same acceleration, so the rows must be bit-identical (checked);
  the CPU-time ratio is the cost of the building layer (the filter, the floor motions).
  Goal: at most 1.10.
* ``ground motion itself`` (context): the spec without ``[building]`` as it is (the block
  on the ground under the ground records). Not the same runs: the roof motion is stronger
  and longer (the building rings down after the ground stops), so the block rocks longer;
  its ratio follows the integration steps, printed with it.

The cases are timed in turn, ``--repeat`` times (best and spread). ``--quick``: 4
records x 10 levels, chunks of 20, one repetition (a smoke check: seconds, not figures).
Nothing is written to disk::

    .venv/bin/python benchmarks/bench_floors.py [--records 100] [--levels 100] [--repeat 3]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from bench_campaign import stochastic_spec  # the same ground-motion campaign

from rocking import campaign
from rocking.models import simulate_many

BUILDING = """
[building]
kind = "shear"
storeys = 5
period = 0.5
damping_ratio = "5%"
floors = [5]
"""
RESULTS = ("max_abs_theta", "overturned", "overturn_time", "n_impacts", "settled")
QUICK = {"records": 4, "levels": 10, "chunk": 20, "repeat": 1}


class SameRunsOnTheGround(campaign.Campaign):
    """The ground spec's rows, each with the floor acceleration of its (motion, level) as
    a plain Record instead of its ground motion: the runs of the floor campaign without
    the building layer."""

    def __init__(self, spec, records):
        super().__init__(spec)
        self.records = records

    def inputs(self, ids):
        table, blocks, _ = super().inputs(ids)
        motions = [self.records[j].scaled(lf) for j, lf in
                   zip(table["motion"], table["load_factor"], strict=True)]
        return table, blocks, motions


def cpu_run(make):
    """CPU and wall time of every chunk of a fresh campaign ``make()``; its rows."""
    t0, w0 = time.process_time(), time.perf_counter()
    c = make()
    rows = [c.run_chunk(k) for k in range(c.spec.n_chunks)]
    return time.process_time() - t0, time.perf_counter() - w0, rows


def steps(c) -> int:
    """Integration steps of every run of campaign ``c`` (an untimed extra pass)."""
    _, blocks, motions = c.inputs(np.arange(c.spec.n_sims))
    return int(simulate_many(blocks, motions, model="housner").n_steps.sum())


def spread(xs) -> str:
    return f"{min(xs):.2f} s" + (f" ({min(xs):.2f}-{max(xs):.2f})" if len(xs) > 1 else "")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--records", type=int, default=100)
    ap.add_argument("--levels", type=int, default=100)
    ap.add_argument("--chunk", type=int, default=2000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)
    args = ap.parse_args(argv)
    base = stochastic_spec(args.records, args.levels, args.chunk, name="bench-floors")
    floors = campaign.parse_spec(base + BUILDING)
    ground = campaign.parse_spec(base)
    n = floors.n_sims
    print(f"{n} classical runs: specimen 2 (E) x {args.records} stochastic records (20 s, "
          f"100 Hz) x {args.levels} load factors, on the roof of a 5-storey shear building "
          f"(T1 = 0.5 s, 5 %); chunks of {args.chunk}; CPU time of all threads")

    warm = campaign.Campaign(floors)  # compile or load the kernels; the floor records
    warm.run_ids(np.arange(min(8, n)))
    warm.motions.prepare(range(args.records))
    t0 = time.process_time()
    fms = [warm.motions.on_floor(0, j) for j in range(args.records)]
    t_filter = time.process_time() - t0
    records = {j: fm.record for j, fm in enumerate(fms)}
    print(f"the building filter: {t_filter:.2f} s CPU for the {args.records} floor motions "
          f"(once per (floor, record)); {records[0].acc.size} samples at "
          f"{records[0].dt:.4g} s each (the ground: 2001 at 0.01 s)")

    cases = {"floors": lambda: campaign.Campaign(floors),
             "same runs on the ground": lambda: SameRunsOnTheGround(ground, records),
             "ground motion itself": lambda: campaign.Campaign(ground)}
    times = {k: [] for k in cases}
    rows = {}
    for _ in range(args.repeat):
        for name, make in cases.items():
            cpu, wall, r = cpu_run(make)
            times[name].append(cpu)
            rows[name] = r
    identical = all(np.array_equal(a[c].to_numpy(), b[c].to_numpy(),
                                   equal_nan=a[c].dtype.kind == "f")
                    for a, b in zip(rows["floors"], rows["same runs on the ground"],
                                    strict=True) for c in RESULTS)
    n_steps = {"floors": steps(campaign.Campaign(floors)),
               "ground motion itself": steps(campaign.Campaign(ground))}
    best = {k: min(v) for k, v in times.items()}
    print(f"{'case':<24} {'CPU, best (spread)':>22} {'runs/s CPU':>11} {'ratio':>6}")
    for k, v in times.items():
        print(f"{k:<24} {spread(v):>22} {n / best[k]:11.0f} "
              f"{best['floors'] / best[k]:6.3f}")
    ratio = best["floors"] / best["same runs on the ground"]
    print(f"rows of floors and of the same runs on the ground bit-identical: "
          f"{'yes' if identical else 'NO'}")
    print(f"CPU-time ratio, floors / the same runs on the ground: {ratio:.3f} "
          f"(goal <= 1.10: {'met' if ratio <= 1.10 else 'NOT met'})")
    a, b = n_steps["floors"], n_steps["ground motion itself"]
    print(f"context, floors / the ground motion itself: CPU "
          f"{best['floors'] / best['ground motion itself']:.3f}, integration steps "
          f"{a / b:.3f} ({a} / {b}: the roof shakes harder and longer)")


if __name__ == "__main__":
    main()
