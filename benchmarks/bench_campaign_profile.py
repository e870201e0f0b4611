"""Benchmark: where a campaign's time goes, stage by stage, with 1 and 2 numba threads,
and the speed-up that Amdahl's law predicts on more cores (issue 33).

The campaign: specimen 2 (Table II E parameters) x ``--records`` stochastic records (20 s
at 100 Hz) x ``--levels`` load factors 0.25-2.5 (default 80 x 250 = 2 x 10^4 runs),
classical model, summaries only, ``chunk_size`` 2000, run by ``rocking.campaign.run`` with
the local executor into a fresh store. The numba cache is warmed first by a tiny campaign
(compilation is not timed). Each stage is timed inside that run, by wrapping the
functions that do it (exclusive times: a wrapped function's time less that of the wrapped
functions it calls in the same thread), in wall time and in the CPU time of the thread
that runs it (``time.thread_time``: insensitive to other jobs on a shared machine):

* ``records``: the stochastic records (``MotionSet.prepare``), but for
* ``records (prange)``: the generator's compiled parallel kernels (the noise filter, the
  high-pass, the pulse energies of :mod:`rocking.motions.stochastic`);
* ``plan``: the table of inputs, scaled motions and blocks (``Campaign.inputs``, its
  records excluded), for the chunks and for the check of the first chunk before the
  store is made;
* ``batch setup``: :func:`rocking.simulate_many` around its compiled kernel (packing the
  motions, validation, result arrays);
* ``kernels``: the compiled batch kernel (numba ``prange``);
* ``results``: the rest of ``Campaign.run_ids`` (result columns, damage states);
* ``writing``: ``Store.write_chunk`` in the main thread (the serial loop before issue 33);
* ``waits``: the main thread waiting for the local executor's helper threads (issue 33:
  ``ChunkWriter.put`` on a full queue, ``ChunkWriter.close`` for the last writes,
  ``PlanAhead.take`` for inputs not built yet);
* ``bookkeeping``: the rest of ``campaign.run`` (store lock, manifest, check, status);
* ``records (thread)``, ``plan (thread)``, ``results (thread)``, ``writing (thread)``:
  the same work in the helper threads of the local executor (issue 33): the next chunk's
  inputs (``PlanAhead``), the previous chunk's table (``Campaign.assemble``) and its
  Parquet file, sha256 and record (``ChunkWriter``), while the main thread runs the
  batches.

**Serial fraction.** ``s`` is the share of the one-thread run's work that nothing
parallelises: every main-thread stage but the two compiled parallel ones (``kernels``,
``records (prange)``: their work divides among the cores), over the whole work, the
helper threads' included. The helper threads' stages (``... (thread)``) run concurrently
with the kernels, so only the main thread's ``waits`` for them are serial; their work is
counted as parallel work, which overstates what it costs the kernels on N cores (the
helper threads take at most two of them, while the main thread runs only the batches).
``s`` is computed from the CPU times (``time.thread_time``) with numba's ``omp``
threading layer (whose calling thread runs a one-thread ``prange`` itself, so that the
kernels' CPU time is in the main thread's), the ``waits`` in wall time (a wait costs no
CPU, but the cores wait too), else from wall times. Amdahl's law predicts the speed-up
``1 / (s + (1 - s) / N)`` on ``N`` cores (2, to compare with the measured 2-thread
ratio, 16 and 64), and its limit ``1 / s``. Each stage's 1-thread / 2-thread wall-time
ratio is printed too, and the ``s`` that Amdahl's law fits to the measured 2-thread
speed-up ``S2`` (``s = 2 / S2 - 1``); on a machine shared with other jobs the 2-thread
figures are noisy (the load average is printed before each run). What Amdahl's law
leaves out: the load balance of the kernels' ``prange`` (runs of unequal lengths: see
``rocking.campaign.plan.balanced_order``, the order of the runs in a batch) and memory
bandwidth.

Runs alternate 1 and 2 threads (``numba.set_num_threads``), ``--repeat`` pairs (default
2), each into a fresh store; the best of each is kept. ``--baseline SRC``: the same pairs
alternate between the package in ``SRC`` (another checkout's ``src``, e.g. before a
change) and this one, each in a fresh process (``--json`` is how they report), and both
stage tables are printed with their serial fractions.

``--balance``: first, each run of the first chunk timed on its own, and the share of the
cores' time that ``prange``'s equal contiguous shares keep busy on 2, 16 and 64 threads,
with the runs in ``sim_id`` order and in their batch order (:func:`balanced_order
<rocking.campaign.plan.balanced_order>`).

``--uncertain``: the same campaign with ``alpha``, ``p`` and ``mu`` uncertain (those of
``examples/fragility.toml``): each row draws its block (the plan stage grows).

``--quick``: 4 records x 10 load factors, chunks of 20, one pair: seconds, not figures::

    .venv/bin/python benchmarks/bench_campaign_profile.py [--quick] [--uncertain]
        [--records 80] [--levels 250] [--repeat 2] [--baseline ../main/src]
        [--balance]
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

STAGES = ("records", "records (prange)", "plan", "batch setup", "kernels", "results",
          "writing", "waits", "bookkeeping", "records (thread)", "plan (thread)",
          "results (thread)", "writing (thread)")
PARALLEL = ("records (prange)", "kernels")
"""Stages inside compiled ``prange`` regions: their work divides among the cores."""
OVERLAPPED = ("records (thread)", "plan (thread)", "results (thread)", "writing (thread)")
"""Stages in the local executor's helper threads, concurrent with the kernels."""
SERIAL = tuple(s for s in STAGES if s not in PARALLEL + OVERLAPPED)


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
    """Exclusive wall and thread-CPU times of wrapped functions, by stage name (one stack
    of open calls per thread)."""

    def __init__(self):
        self.wall = dict.fromkeys(STAGES, 0.0)
        self.cpu = dict.fromkeys(STAGES, 0.0)
        self.local = threading.local()
        self.lock = threading.Lock()

    def wrap(self, func, stage):
        """``func`` timed as ``stage`` (as ``stage (thread)`` outside the main thread,
        where there is such a stage)."""
        thread_stage = f"{stage} (thread)" if f"{stage} (thread)" in STAGES else None
        def timed(*args, **kwargs):
            stack = self.local.__dict__.setdefault("stack", [])
            stack.append([time.perf_counter(), time.thread_time(), 0.0, 0.0])
            try:
                return func(*args, **kwargs)
            finally:
                w0, c0, wi, ci = stack.pop()
                dw, dc = time.perf_counter() - w0, time.thread_time() - c0
                name = stage
                if thread_stage and threading.current_thread() is not threading.main_thread():
                    name = thread_stage
                with self.lock:
                    self.wall[name] += dw - wi
                    self.cpu[name] += dc - ci
                if stack:
                    stack[-1][2] += dw
                    stack[-1][3] += dc
        return timed


@contextlib.contextmanager
def instrumented(stages: Stages):
    """Wrap the functions of each stage (module attributes and class attributes), and put
    them back afterwards (those this version of the package has)."""
    from rocking.campaign import execute, plan, store
    from rocking.models import MODELS
    from rocking.motions import stochastic
    targets = [(plan.MotionSet, "prepare", "records"),
               (stochastic, "_filtered", "records (prange)"),
               (stochastic, "_highpass", "records (prange)"),
               (stochastic, "_pulse_energy", "records (prange)"),
               (plan.Campaign, "inputs", "plan"),
               (plan, "simulate_many", "batch setup"),
               (MODELS["housner"], "batch_kernel", "kernels"),
               (plan.Campaign, "run_ids", "results"),
               (store.Store, "write_chunk", "writing"),
               (execute, "_run_local", "bookkeeping")]
    # issue 33's pipeline, where this version has it: the main thread's waits for the
    # chunk writer and for the inputs built ahead, the steps of run_ids
    for cls, name, stage in (("ChunkWriter", "put", "waits"),
                             ("ChunkWriter", "close", "waits"),
                             ("PlanAhead", "take", "waits")):
        if hasattr(execute, cls):
            targets.append((getattr(execute, cls), name, stage))
    if hasattr(plan.Campaign, "assemble"):
        targets += [(plan.Campaign, "simulate", "results"),
                    (plan.Campaign, "assemble", "results")]
    saved = [(obj, name, obj.__dict__[name] if isinstance(obj, type) else getattr(obj, name))
             for obj, name, _ in targets]
    model = MODELS["housner"]
    if "kernels" in vars(model):  # the runners take the compiled pair from kernels()
        saved.append((model, "kernels", model.__dict__["kernels"]))
    try:
        for obj, name, stage in targets:
            setattr(obj, name, stages.wrap(getattr(obj, name), stage))
        if "kernels" in vars(model):
            pair = model.__dict__["kernels"]

            def kernels(self):
                k, bk = pair(self)
                return k, stages.wrap(bk, "kernels")
            model.kernels = kernels
        yield
    finally:
        for obj, name, old in saved:
            setattr(obj, name, old)


def run_once(spec_path: Path, store: Path, threads: int) -> tuple[float, dict, dict]:
    import numba

    from rocking import campaign
    numba.set_num_threads(threads)
    stages = Stages()
    with instrumented(stages):
        t0 = time.perf_counter()
        st = stages.wrap(campaign.run, "bookkeeping")(spec_path, store, progress=False)
        total = time.perf_counter() - t0
    assert st["complete"], st
    return total, stages.wall, stages.cpu


def amdahl(s: float, n: int) -> float:
    return 1.0 / (s + (1.0 - s) / n)


def basis(wall: dict, cpu: dict, layer: str) -> tuple[dict, str]:
    """The stage times that the serial fraction is computed from (see the module
    docstring): CPU times with the ``omp`` layer, the main thread's waits in wall time
    (a wait costs no CPU, but the kernels wait too)."""
    if layer != "omp":
        return wall, "wall times"
    return {**cpu, "waits": wall["waits"]}, "CPU times, waits in wall time"


def serial_fraction(wall: dict, cpu: dict, layer: str) -> tuple[float, str]:
    """``(s, basis)`` of a one-thread run (see the module docstring)."""
    t, how = basis(wall, cpu, layer)
    return sum(t[k] for k in SERIAL) / sum(t.values()), how


def measure(args, spec_path: Path, root: Path, n: int) -> dict:
    """Alternate 1 and 2 threads, ``args.repeat`` pairs; the best run of each."""
    import numba
    max_threads = numba.config.NUMBA_NUM_THREADS
    threads = (1, 2) if max_threads >= 2 else (1,)
    best: dict = {}
    k = 0
    for i in range(args.repeat):
        for th in threads:
            k += 1
            la = loadavg()
            total, wall, cpu = run_once(spec_path, root / f"store-{k}", th)
            shutil.rmtree(root / f"store-{k}")
            if not args.json:
                print(f"{i + 1:>4} {th:>7} {la:>16} {total:8.2f} {n / total:8.0f}")
            if th not in best or total < best[th]["total"]:
                best[th] = {"total": total, "wall": wall, "cpu": cpu, "load": la,
                            "layer": numba.threading_layer()}
    return best


def print_tables(best: dict, n: int, title: str = "") -> float:
    threads = sorted(best)
    if title:
        print(f"\n== {title}")
    print(f"\n{'stage':<17}" + "".join(f"{f'{th} thread(s) s':>15}{'share':>7}"
                                       for th in threads)
          + f"{'CPU s (1)':>10}{'us/run (1)':>11}" + (f"{'1/2 thr':>8}" if 2 in best else ""))
    for stage in STAGES:
        line = f"{stage:<17}"
        for th in threads:
            b = best[th]
            line += f"{b['wall'][stage]:15.3f}{b['wall'][stage] / b['total']:7.1%}"
        one = best[1]
        ratio = (f"{one['wall'][stage] / best[2]['wall'][stage]:8.2f}"
                 if 2 in best and best[2]["wall"][stage] > 0 else "")
        kind = " (parallel)" if stage in PARALLEL else (
            " (overlapped)" if stage in OVERLAPPED else "")
        print(line + f"{one['cpu'][stage]:10.3f}{1e6 * one['cpu'][stage] / n:11.1f}" + ratio
              + kind)
    line = f"{'total (wall)':<17}"
    for th in threads:
        line += f"{best[th]['total']:15.3f}{1:7.0%}"
    print(line + f"{sum(best[1]['cpu'].values()):10.3f}"
          f"{1e6 * sum(best[1]['cpu'].values()) / n:11.1f}")
    b1 = best[1]
    if b1["cpu"]["kernels"] <= 0.0:
        # the kernels' wrapper saw nothing: the runners call the kernel some other way
        # than this script patches, and the stages' shares would be wrong, not merely off
        raise SystemExit(f"the kernels stage measured {b1['cpu']['kernels']:.3f} s of "
                         f"{b1['total']:.3f} s: not instrumented (see patched())")
    s, how = serial_fraction(b1["wall"], b1["cpu"], b1["layer"])
    t, _ = basis(b1["wall"], b1["cpu"], b1["layer"])
    biggest = max(SERIAL, key=lambda k: t[k])
    work = sum(t.values())
    print(f"\nserial fraction s (1 thread, {how}; serial stages: {', '.join(SERIAL)}): "
          f"{s:.4f}; biggest serial stage: {biggest} ({t[biggest]:.3f} s, "
          f"{t[biggest] / work:.2%})")
    if 2 in best:
        s2 = best[1]["total"] / best[2]["total"]
        print(f"measured speed-up at 2 threads: {s2:.2f} (Amdahl predicts "
              f"{amdahl(s, 2):.2f}); the s it fits: {2 / s2 - 1:.3f}"
              + (f", N=16: {amdahl(2 / s2 - 1, 16):.1f}, N=64: {amdahl(2 / s2 - 1, 64):.1f}"
                 if 0 < 2 / s2 - 1 < 1 else " (outside (0, 1): noise)"))
    print("Amdahl's law, speed-up on N cores over 1: "
          + ", ".join(f"N={m}: {amdahl(s, m):.1f}" for m in (2, 16, 64))
          + f"; limit 1/s = {1 / s:.1f}")
    rest = s - t[biggest] / work
    print(f"Amdahl's law, speed-up without the {biggest} stage (s = {rest:.4f}): "
          + ", ".join(f"N={m}: {amdahl(rest, m):.1f}" for m in (16, 64))
          + (f"; limit {1 / rest:.1f}" if rest > 0 else ""))
    return s


def balance(spec_path: Path, chunk: int = 0) -> None:
    """``--balance``: each run of one chunk timed on its own (thread CPU time, one thread,
    less the time of a run of 0.01 s), and the share of the cores' time that numba's
    equal contiguous ``prange`` shares would keep busy on T threads, in ``sim_id`` order
    and in the batch order of :func:`rocking.campaign.plan.balanced_order` (the mean
    share over the slowest)."""
    import numba
    import numpy as np

    from rocking import campaign, simulate_many
    from rocking.campaign import plan
    numba.set_num_threads(1)
    spec = campaign.read_spec(spec_path)
    c = campaign.Campaign(spec)
    ids = np.arange(*c.chunk_range(chunk))
    _, blocks, motions = c.inputs(ids)
    kw = {"model": "housner", "max_free_time": spec.max_free_time, "errors": "nan"}

    def cpu(i, **more):
        t0 = time.thread_time()
        simulate_many(blocks[i:i + 1], motions[i:i + 1], **{**kw, **more})
        return time.thread_time() - t0

    cpu(0)
    empty = min(cpu(0, duration=0.01) for _ in range(5))
    cost = np.clip(np.array([cpu(i) for i in range(ids.size)]) - empty, 1e-6, None)
    order = plan.balanced_order(ids.size)
    print(f"\nload balance, chunk {chunk} ({ids.size} runs, each run's CPU time "
          f"{1e3 * cost.min():.2f} to {1e3 * cost.max():.2f} ms): busy share of the cores "
          "(mean / slowest prange share), sim_id order -> batch order")
    for T in (2, 16, 64):
        eff = [np.mean(s := [p.sum() for p in np.array_split(cost[o], T)]) / np.max(s)
               for o in (np.arange(ids.size), order)]
        print(f"  {T:>2} threads: {eff[0]:.3f} -> {eff[1]:.3f}")


def compare(args, argv) -> int:
    """``--baseline``: alternate fresh processes of the baseline package and this one."""
    import rocking
    here = str(Path(rocking.__file__).resolve().parents[1])
    trees = {"before": str(Path(args.baseline).resolve()), "after": here}
    rest = [a for a in argv if a not in ("--baseline", args.baseline)]
    runs: dict = {k: {} for k in trees}
    n = None
    print(f"alternating {args.repeat} pair(s) per tree: before = {trees['before']}, "
          f"after = {trees['after']}")
    for i in range(args.repeat):
        for name, src in trees.items():
            with tempfile.NamedTemporaryFile(suffix=".json") as f:
                env = dict(os.environ, PYTHONPATH=src)
                cmd = [sys.executable, __file__, *rest, "--repeat", "1", "--json", f.name]
                subprocess.run(cmd, env=env, check=True)
                got = json.loads(Path(f.name).read_text())
            n = got["n"]
            for th, b in got["best"].items():
                th = int(th)
                print(f"{i + 1:>4} {name:>7} {th:>7} threads  load {b['load']:>16} "
                      f"{b['total']:8.2f} s {n / b['total']:8.0f} sims/s")
                if th not in runs[name] or b["total"] < runs[name][th]["total"]:
                    runs[name][th] = b
    ss = {name: print_tables(runs[name], n, f"{name}: {trees[name]}") for name in trees}
    print(f"\nserial fraction before -> after: {ss['before']:.4f} -> {ss['after']:.4f}; "
          f"Amdahl N=16: {amdahl(ss['before'], 16):.1f} -> {amdahl(ss['after'], 16):.1f}, "
          f"N=64: {amdahl(ss['before'], 64):.1f} -> {amdahl(ss['after'], 64):.1f}")
    return 0


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="tiny campaign, one pair of runs")
    ap.add_argument("--records", type=int, default=80, help="stochastic records")
    ap.add_argument("--levels", type=int, default=250, help="load factors")
    ap.add_argument("--chunk", type=int, default=2000, help="chunk_size")
    ap.add_argument("--repeat", type=int, default=2, help="pairs of runs (1 and 2 threads)")
    ap.add_argument("--uncertain", action="store_true",
                    help="alpha, p, mu uncertain (as in examples/fragility.toml)")
    ap.add_argument("--baseline", metavar="SRC",
                    help="compare with the package in SRC, alternating fresh processes")
    ap.add_argument("--balance", action="store_true",
                    help="also time each run of the first chunk: prange load balance")
    ap.add_argument("--json", metavar="FILE", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.baseline:
        return compare(args, argv)
    if args.quick:
        args.records, args.levels, args.chunk, args.repeat = 4, 10, 20, 1
    import numba

    import rocking
    from rocking import campaign
    quiet = bool(args.json)
    if not quiet:
        print(f"rocking {rocking.__version__} ({Path(rocking.__file__).parent}), "
              f"{os.cpu_count()} cores, numba {numba.__version__} "
              f"({numba.config.NUMBA_NUM_THREADS} threads at most), load {loadavg()}")
    root = Path(tempfile.mkdtemp(prefix="bench-campaign-profile-"))
    try:
        warm = root / "warm.toml"
        warm.write_text(stochastic_spec(2, 2, 4))
        t0 = time.perf_counter()
        campaign.run(warm, root / "warm-store", progress=False)
        if not quiet:
            print(f"warm-up (numba cache, imports): {time.perf_counter() - t0:.2f} s, not "
                  f"timed; threading layer {numba.threading_layer()}")
        spec_path = root / "spec.toml"
        spec_path.write_text(stochastic_spec(args.records, args.levels, args.chunk,
                                             args.uncertain))
        spec = campaign.read_spec(spec_path)
        n = spec.n_sims
        if not quiet:
            unc = " (alpha, p, mu uncertain)" if args.uncertain else ""
            print(f"\n{n:,} runs: specimen 2 x {args.records} stochastic records (20 s, "
                  f"100 Hz) x {args.levels} load factors{unc}, chunk_size {spec.chunk_size} "
                  f"({spec.n_chunks} chunks), housner, local executor; {args.repeat} "
                  "pair(s), 1 and 2 threads alternating, best of each")
            if args.balance:
                balance(spec_path)
                print()
            print(f"{'run':>4} {'threads':>7} {'loadavg':>16} {'wall s':>8} {'sims/s':>8}")
        best = measure(args, spec_path, root, n)
        if quiet:
            Path(args.json).write_text(json.dumps({"n": n, "best": best}))
        else:
            print_tables(best, n)
    finally:
        with contextlib.suppress(OSError):
            shutil.rmtree(root)
    return 0


if __name__ == "__main__":
    sys.exit(main())
