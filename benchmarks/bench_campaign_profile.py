"""Benchmark: where a campaign's time goes, stage by stage, with 1 and 2 numba threads,
and the speed-up that Amdahl's law predicts on more cores (issue 33).

The campaign: specimen 2 (Table II E parameters) x ``--records`` stochastic records (20 s
at 100 Hz) x ``--levels`` load factors 0.25-2.5 (default 80 x 250 = 2 x 10^4 runs),
classical model, summaries only, ``chunk_size`` 2000, run by ``rocking.campaign.run`` with
the local executor into a fresh store. The numba cache is warmed first by a tiny campaign
(compilation is not timed). Each stage is timed inside that run, by wrapping the
functions that do it (exclusive times: a wrapped function's time less that of the wrapped
functions it calls):

* ``records``: the stochastic records (``MotionSet.prepare``);
* ``plan``: the table of inputs, scaled motions and blocks (``Campaign.inputs``, its
  records excluded), for the chunks and for the check of the first chunk before the
  store is made;
* ``batch setup``: :func:`rocking.simulate_many` around its compiled kernel (packing the
  motions, validation, result arrays);
* ``kernels``: the compiled batch kernel (numba ``prange``: the only parallel stage);
* ``results``: the rest of ``Campaign.run_ids`` (result columns, damage states);
* ``writing``: ``Store.write_chunk`` (Parquet, sha256, the chunk's record);
* ``bookkeeping``: the rest of ``campaign.run`` (store lock, manifest, check, status).

Runs alternate 1 and 2 threads (``numba.set_num_threads``), ``--repeat`` pairs (default 2),
each into a fresh store; the best of each is kept. The serial fraction ``s`` is the share
of the 1-thread run outside the kernels; Amdahl's law predicts the speed-up
``1 / (s + (1 - s) / N)`` on ``N`` cores (2, to compare with the measured 2-thread ratio,
16 and 64), and its limit ``1 / s``. That ``s`` is an upper bound: the records' generation
has parallel (``prange``) kernels of its own (:mod:`rocking.motions.stochastic`); each
stage's 1-thread / 2-thread time ratio is printed too, and the ``s`` that Amdahl's law
fits to the measured 2-thread speed-up ``S2`` (``s = 2 / S2 - 1``). On a machine shared
with other jobs the 2-thread figures are noisy (the load average is printed before each
run).

``--uncertain``: the same campaign with ``alpha``, ``p`` and ``mu`` uncertain (those of
``examples/fragility.toml``): each row draws its block (the plan stage grows).

``--quick``: 4 records x 10 load factors, chunks of 20, one pair: seconds, not figures::

    .venv/bin/python benchmarks/bench_campaign_profile.py [--quick] [--uncertain]
        [--records 80] [--levels 250] [--repeat 2]
"""

from __future__ import annotations

import argparse
import contextlib
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

STAGES = ("records", "plan", "batch setup", "kernels", "results", "writing", "bookkeeping")
SERIAL = tuple(s for s in STAGES if s != "kernels")


UNCERTAIN = """
[uncertain]
alpha = {dist = "normal", cov = 0.015}
p = {dist = "normal", cov = 0.03}
mu = {dist = "normal", std = 0.0075}
"""
"""``--uncertain``: the uncertain parameters of ``examples/fragility.toml``."""


def stochastic_spec(n, num, chunk_size, uncertain=False):
    return f"""
[campaign]
name = "bench-campaign-profile"
seed = 11
model = "housner"

[[blocks]]
specimen = 2
params = "experimental"

[motions]
kind = "stochastic"
n = {n}
duration = 20.0
dt = 0.01
load_factors = {{start = 0.25, stop = 2.5, num = {num}}}

{UNCERTAIN if uncertain else ""}
[run]
chunk_size = {chunk_size}
"""


def loadavg() -> str:
    try:
        return " ".join(Path("/proc/loadavg").read_text().split()[:3])
    except OSError:
        return "n/a"


class Stages:
    """Exclusive wall times of wrapped functions, by stage name."""

    def __init__(self):
        self.t = dict.fromkeys(STAGES, 0.0)
        self.stack: list[list[float]] = []  # [start, time of wrapped callees]

    def wrap(self, func, stage):
        def timed(*args, **kwargs):
            self.stack.append([time.perf_counter(), 0.0])
            try:
                return func(*args, **kwargs)
            finally:
                t0, inner = self.stack.pop()
                dt = time.perf_counter() - t0
                self.t[stage] += dt - inner
                if self.stack:
                    self.stack[-1][1] += dt
        return timed


@contextlib.contextmanager
def instrumented(stages: Stages):
    """Wrap the functions of each stage (module attributes and class attributes), and put
    them back afterwards."""
    from rocking.campaign import execute, plan, store
    from rocking.models import MODELS
    targets = [(plan.MotionSet, "prepare", "records"), (plan.Campaign, "inputs", "plan"),
               (plan, "simulate_many", "batch setup"),
               (MODELS["housner"], "batch_kernel", "kernels"),
               (plan.Campaign, "run_ids", "results"), (store.Store, "write_chunk", "writing"),
               (execute, "_run_local", "bookkeeping")]
    saved = [(obj, name, obj.__dict__[name] if isinstance(obj, type) else getattr(obj, name))
             for obj, name, _ in targets]
    try:
        for obj, name, stage in targets:
            setattr(obj, name, stages.wrap(getattr(obj, name), stage))
        yield
    finally:
        for obj, name, old in saved:
            setattr(obj, name, old)


def run_once(spec_path: Path, store: Path, threads: int) -> tuple[float, dict]:
    import numba

    from rocking import campaign
    numba.set_num_threads(threads)
    stages = Stages()
    with instrumented(stages):
        t0 = time.perf_counter()
        st = stages.wrap(campaign.run, "bookkeeping")(spec_path, store, progress=False)
        total = time.perf_counter() - t0
    assert st["complete"], st
    return total, stages.t


def amdahl(s: float, n: int) -> float:
    return 1.0 / (s + (1.0 - s) / n)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="tiny campaign, one pair of runs")
    ap.add_argument("--records", type=int, default=80, help="stochastic records")
    ap.add_argument("--levels", type=int, default=250, help="load factors")
    ap.add_argument("--chunk", type=int, default=2000, help="chunk_size")
    ap.add_argument("--repeat", type=int, default=2, help="pairs of runs (1 and 2 threads)")
    ap.add_argument("--uncertain", action="store_true",
                    help="alpha, p, mu uncertain (as in examples/fragility.toml)")
    args = ap.parse_args(argv)
    if args.quick:
        args.records, args.levels, args.chunk, args.repeat = 4, 10, 20, 1
    import numba

    import rocking
    from rocking import campaign
    max_threads = numba.config.NUMBA_NUM_THREADS
    threads = (1, 2) if max_threads >= 2 else (1,)
    print(f"rocking {rocking.__version__}, {os.cpu_count()} cores, numba {numba.__version__} "
          f"({max_threads} threads at most), load {loadavg()}")
    root = Path(tempfile.mkdtemp(prefix="bench-campaign-profile-"))
    try:
        warm = root / "warm.toml"
        warm.write_text(stochastic_spec(2, 2, 4))
        t0 = time.perf_counter()
        campaign.run(warm, root / "warm-store", progress=False)
        print(f"warm-up (numba cache, imports): {time.perf_counter() - t0:.2f} s, not timed")
        spec_path = root / "spec.toml"
        spec_path.write_text(stochastic_spec(args.records, args.levels, args.chunk,
                                             args.uncertain))
        spec = campaign.read_spec(spec_path)
        n = spec.n_sims
        unc = " (alpha, p, mu uncertain)" if args.uncertain else ""
        print(f"\n{n:,} runs: specimen 2 x {args.records} stochastic records (20 s, 100 Hz) x "
              f"{args.levels} load factors{unc}, chunk_size {spec.chunk_size} ({spec.n_chunks} "
              f"chunks), housner, local executor; {args.repeat} pair(s), 1 and 2 threads "
              "alternating, best of each")
        best: dict[int, tuple[float, dict]] = {}
        print(f"{'run':>4} {'threads':>7} {'loadavg':>16} {'wall s':>8} {'sims/s':>8}")
        k = 0
        for i in range(args.repeat):
            for th in threads:
                k += 1
                la = loadavg()
                total, t = run_once(spec_path, root / f"store-{k}", th)
                shutil.rmtree(root / f"store-{k}")
                print(f"{i + 1:>4} {th:>7} {la:>16} {total:8.2f} {n / total:8.0f}")
                if th not in best or total < best[th][0]:
                    best[th] = (total, t)

        print(f"\n{'stage':<14}" + "".join(f"{f'{th} thread(s) s':>16}{'share':>7}"
                                            for th in threads) + f"{'us/run (1)':>12}"
              + (f"{'1/2 thr':>8}" if 2 in best else ""))
        for stage in STAGES:
            line = f"{stage:<14}"
            for th in threads:
                total, t = best[th]
                line += f"{t[stage]:16.3f}{t[stage] / total:7.1%}"
            ratio = (f"{best[1][1][stage] / best[2][1][stage]:8.2f}"
                     if 2 in best and best[2][1][stage] > 0 else "")
            print(line + f"{1e6 * best[1][1][stage] / n:12.1f}" + ratio)
        line = f"{'total':<14}"
        for th in threads:
            line += f"{best[th][0]:16.3f}{1:7.0%}"
        print(line + f"{1e6 * best[1][0] / n:12.1f}")
        total1, t1 = best[1]
        s = 1.0 - t1["kernels"] / total1
        biggest = max(SERIAL, key=lambda k: t1[k])
        print(f"\nserial fraction s (1 thread, all but the kernels): {s:.3f}; biggest serial "
              f"stage: {biggest} ({t1[biggest]:.3f} s, {t1[biggest] / total1:.1%})")
        if 2 in best:
            s2 = total1 / best[2][0]
            print(f"measured speed-up at 2 threads: {s2:.2f} (Amdahl predicts "
                  f"{amdahl(s, 2):.2f}); the s it fits: {2 / s2 - 1:.3f}"
                  + (f", N=16: {amdahl(2 / s2 - 1, 16):.1f}, N=64: {amdahl(2 / s2 - 1, 64):.1f}"
                     if 0 < 2 / s2 - 1 < 1 else " (outside (0, 1): noise)"))
        print("Amdahl's law, speed-up on N cores over 1: "
              + ", ".join(f"N={m}: {amdahl(s, m):.1f}" for m in (2, 16, 64))
              + f"; limit 1/s = {1 / s:.1f}")
        rest = s - t1[biggest] / total1
        print(f"Amdahl's law, speed-up without the {biggest} stage (s = {rest:.3f}): "
              + ", ".join(f"N={m}: {amdahl(rest, m):.1f}" for m in (16, 64))
              + f"; limit {1 / rest:.1f}")
    finally:
        with contextlib.suppress(OSError):
            shutil.rmtree(root)
    return 0


if __name__ == "__main__":
    sys.exit(main())
