"""Benchmark: campaigns (``rocking.campaign``) end to end, the figures of issue 11.

Sections (``--only local,dask,memory,dem,tail``; all by default), each run ``--repeat``
times (default 2) with the machine's load (``/proc/loadavg``) printed before each run:

* ``local``: 100,000 classical-model simulations, specimen 2 (Table II E parameters) x 400
  stochastic records (20 s at 100 Hz) x 250 load factors 0.25-2.5, summaries only,
  ``chunk_size = 2000``: the wall time of ``rocking.campaign.run(spec, store)`` into a fresh
  store with the local executor (numba ``prange`` over every core), records' generation
  included. The numba cache is warmed first by a tiny campaign (compilation is not timed).
  Also: the time to generate the 400 records alone (by chunks, as the run does) and a
  cProfile of one chunk (compiled kernel vs Python around it vs the Parquet write).
  Goal: <= 60 s on a 2-core machine.
* ``dask``: the same campaign through a Dask ``LocalCluster`` of 2 process workers
  (``executor="dask", dask_local=2``: one numba thread each), cluster start-up included;
  the start-up + shutdown of a bare cluster timed alone, and from the run itself the time
  from the workers ready (the executor's log line, just before the first chunk is
  submitted) to the last chunk written (the newest chunk file's mtime). Checks that the
  rows equal the local store's. Goal: within 25 % of the local time.
* ``memory``: peak RSS of a fresh Python process that runs the local executor at 10^4 and
  10^5 simulations (25 and 250 load factors, the same 400 records, ``chunk_size = 2000``)
  and at 10^5 with ``chunk_size`` 500 and 8000, next to a process that only imports the
  package and loads the kernels: the peak should follow the chunk size, not the campaign
  size. The peak is the child's ``VmHWM`` (``/proc/self/status``); its ``ru_maxrss`` is
  printed too but is not the child's own: Linux carries the high-water mark of the
  process image replaced by ``exec`` over, so a child of this (large, Dask-importing)
  process reports at least this process's peak. The children get the environment this
  script started with (checked after the Dask runs: ``rocking.campaign`` restores the
  environment that distributed's nanny changes when it starts workers).
* ``dem``: 1,000 runs of the discrete element model (specimen 2, Table I geometry) under
  one-sine pulses (20 periods 0.2-1.0 s x 50 amplitudes 1-6 m/s^2, 3 s windows) through
  the same engine (local executor, ``chunk_size = 250``), after a handful of single runs
  that give the rate; and the same spec with the classical model for comparison. The
  windows are set (``duration = 3.0``), so that the figures do not depend on the free
  motion after the pulse.
* ``tail`` (issue 16): the ``local`` campaign (10^5 classical runs, no ``duration``) with
  the old behaviour, each run stopped at the record's end (``max_free_time = 0`` in
  ``[campaign]``), and with the default free motion after the record (runs continue until
  the block is at rest or has overturned), timed back to back, interleaved (old, new, old,
  new, ... ``--repeat`` pairs), each into a fresh store; then the outcomes compared run by
  run: overturning flips (survivors at the record's end that overturn in the tail),
  ``settled`` counts, maximum angles that grow in the tail. Goal: new within 15 % of old.
  Skipped, with a line saying so, by a package without the ``max_free_time`` spec key.

``--quick`` is a smoke check of every section on tiny inputs (4 records x 10 load factors,
chunks of 20, 2 x 2 pulses, one run of each measurement unless ``--repeat``; the memory
section runs only the baseline and one campaign): seconds, not figures. Stores and specs
go to a temporary directory, removed at the end; nothing is written to the repository::

    .venv/bin/python benchmarks/bench_campaign.py [--quick] [--only local,tail] [--repeat 2]
"""

from __future__ import annotations

import argparse
import contextlib
import cProfile
import json
import os
import pstats
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

SECTIONS = ("local", "dask", "memory", "dem", "tail")
ENV0 = dict(os.environ)  # before any Dask cluster: its nanny updates os.environ (see dask)


def stochastic_spec(n, num, chunk_size, name="bench-campaign", extra=""):
    """Specimen 2 (E) x ``n`` stochastic records (20 s, 100 Hz) x ``num`` load factors;
    ``extra``: more lines of the ``[campaign]`` table."""
    return f"""
[campaign]
name = "{name}"
seed = 11
model = "housner"
{extra}

[[blocks]]
specimen = 2
params = "experimental"

[motions]
kind = "stochastic"
n = {n}
duration = 20.0
dt = 0.01
load_factors = {{start = 0.25, stop = 2.5, num = {num}}}

[run]
chunk_size = {chunk_size}
"""


def pulse_spec(model, n_periods, n_amplitudes, chunk_size=250):
    """Specimen 2 (Table I geometry) under one-sine pulses: amplitudes in m/s^2."""
    return f"""
[campaign]
name = "bench-pulses-{model}"
seed = 11
model = "{model}"
duration = 3.0

[[blocks]]
specimen = 2
params = "geometric"

[motions]
kind = "one_sine"
period = {{start = 0.2, stop = 1.0, num = {n_periods}}}
amplitude = 1.0
duration = 3.0
load_factors = {{start = 1.0, stop = 6.0, num = {n_amplitudes}}}

[run]
chunk_size = {chunk_size}
"""


def loadavg() -> str:
    try:
        return " ".join(Path("/proc/loadavg").read_text().split()[:3])
    except OSError:
        return "n/a"


def spread(xs) -> str:
    """``best (min-max)`` of a list of times."""
    xs = list(xs)
    if len(xs) == 1:
        return f"{xs[0]:.2f}"
    return f"{min(xs):.2f} ({min(xs):.2f}-{max(xs):.2f})"


class Bench:
    def __init__(self, root: Path, repeat: int, quick: bool):
        self.root, self.repeat, self.quick = root, repeat, quick
        self.n_rec = 4 if quick else 400  # stochastic records
        self.n_lev = 10 if quick else 250  # load factors
        self.chunk = 20 if quick else 2000  # chunk_size of the local, dask and tail runs
        self.n_dem = (2, 2) if quick else (20, 50)
        self._k = 0
        self.local_store: Path | None = None
        self.summary: list[tuple[str, str, str]] = []  # (figure, value, goal)

    def path(self, stem: str) -> Path:
        self._k += 1
        return self.root / f"{stem}-{self._k}"

    def spec_file(self, text: str, stem: str = "spec") -> Path:
        p = self.path(stem).with_suffix(".toml")
        p.write_text(text, encoding="utf-8")
        return p

    def warm(self):
        """Load (or compile) the kernels and import what a run uses (a tiny campaign)."""
        from rocking import campaign
        t0 = time.perf_counter()
        campaign.run(self.spec_file(stochastic_spec(2, 2, 4)), self.path("warm"),
                     progress=False)
        campaign.run(self.spec_file(pulse_spec("dem", 1, 1, 1)), self.path("warm"),
                     progress=False)
        print(f"warm-up (numba cache, DEM damping calibration, imports): "
              f"{time.perf_counter() - t0:.2f} s, not timed below")

    # ------------------------------------------------------------------ local
    def local(self):
        from rocking import campaign
        from rocking.campaign.plan import Campaign
        from rocking.campaign.store import Store
        spec_path = self.spec_file(stochastic_spec(self.n_rec, self.n_lev, self.chunk))
        spec = campaign.read_spec(spec_path)
        n = spec.n_sims
        print(f"\n== local: {n:,} simulations ({self.n_rec} stochastic records x {self.n_lev} "
              f"load factors, 20 s at 100 Hz), chunk_size {spec.chunk_size} "
              f"({spec.n_chunks} chunks), housner, summaries only")

        # records alone, built by chunks as the run builds them
        per_chunk = spec.chunk_size // self.n_lev
        t_rec = []
        for _ in range(self.repeat):
            c = Campaign(spec)
            t0 = time.perf_counter()
            for lo in range(0, self.n_rec, per_chunk):
                c.motions.prepare(range(lo, min(lo + per_chunk, self.n_rec)))
            t_rec.append(time.perf_counter() - t0)

        times = []
        print(f"{'run':>4} {'loadavg':>16} {'wall s':>8} {'sims/s':>8}")
        for i in range(self.repeat):
            store = self.path("local")
            la = loadavg()
            t0 = time.perf_counter()
            st = campaign.run(spec_path, store, progress=False)
            t = time.perf_counter() - t0
            assert st["complete"] and st["sims_done"] == n, st
            times.append(t)
            print(f"{i + 1:>4} {la:>16} {t:8.2f} {n / t:8.0f}")
            if self.local_store is None:
                self.local_store = store
            else:
                shutil.rmtree(store)
        best = min(times)
        print(f"records alone ({self.n_rec} x 20 s, by chunks of {per_chunk}): "
              f"{spread(t_rec)} s = {min(t_rec) / best:.1%} of the run")

        # where one chunk's time goes
        c = Campaign(spec)
        c.motions.prepare(range(self.n_rec))  # records out of the profile
        tab = c.run_chunk(1)  # the chunk's first run (allocations, caches)
        prof = cProfile.Profile()
        prof.enable()
        tab = c.run_chunk(1)
        s = Store(self.path("profile")).prepare()  # a new store, made as campaign.run does
        s.lock()
        try:
            s.open_for(spec)
            s.write_chunk(1, tab)
        finally:
            s.unlock()
        prof.disable()
        st = pstats.Stats(prof).stats
        total = sum(v[2] for v in st.values())  # tottime over every function

        def cum(func, file_part=""):
            return sum(v[3] for k, v in st.items() if k[2] == func and file_part in k[0])
        t_kernel = cum("batch_kernel")
        t_sim = cum("simulate_many")
        t_inputs = cum("inputs", "campaign")
        t_write = cum("write_chunk")
        t_run = cum("run_ids", "campaign")
        print(f"one chunk ({spec.chunk_size} sims) under cProfile: {total:.3f} s = compiled "
              f"kernel {t_kernel:.3f} ({t_kernel / total:.0%}), simulate_many around it "
              f"{t_sim - t_kernel:.3f}, inputs (scaling, table) {t_inputs:.3f}, "
              f"rest of run_ids {t_run - t_sim - t_inputs:.3f}, Parquet write "
              f"{t_write:.3f} ({t_write / total:.0%})")
        self.summary += [
            (f"local, {n:,} sims: wall s, best (min-max)", spread(times),
             "(quick: no goal)" if self.quick else
             f"<= 60 s {'ok' if best <= 60.0 else 'MISSED'}"),
            ("local: sims/s (best)", f"{n / best:.0f}", ""),
            ("local: records' generation s", spread(t_rec), f"{min(t_rec) / best:.1%} of run"),
            ("local: kernel share of a chunk", f"{t_kernel / total:.0%}", ""),
        ]
        self.local_times = times

    # ------------------------------------------------------------------ dask
    def dask(self):
        import pandas as pd
        from distributed import Client

        from rocking import campaign
        spec_path = self.spec_file(stochastic_spec(self.n_rec, self.n_lev, self.chunk))
        n = campaign.read_spec(spec_path).n_sims
        print(f"\n== dask: the same {n:,} simulations, LocalCluster of 2 process workers")
        if self.local_store is None:  # --only dask: a local store to compare with
            self.local_store = self.path("local")
            t0 = time.perf_counter()
            campaign.run(spec_path, self.local_store, progress=False)
            self.local_times = [time.perf_counter() - t0]
            print(f"local reference run: {self.local_times[0]:.2f} s")

        t_up, t_down = [], []
        for _ in range(self.repeat):
            la = loadavg()
            t0 = time.perf_counter()
            cluster = campaign.local_cluster(2)
            client = Client(cluster)
            client.wait_for_workers(2)
            t1 = time.perf_counter()
            client.close()
            cluster.close()
            t_up.append(t1 - t0)
            t_down.append(time.perf_counter() - t1)
            print(f"bare cluster (load {la}): start {t_up[-1]:.2f} s, close {t_down[-1]:.2f} s")

        print(f"{'run':>4} {'loadavg':>16} {'wall s':>8} {'sims/s':>8} {'to ready':>9} "
              f"{'ready->last':>12} {'close':>7}")
        walls, compute, ready = [], [], []
        same = None
        for i in range(self.repeat):
            store = self.path("dask")
            marks = []

            def log(msg, marks=marks):
                marks.append((time.time(), msg))
            la = loadavg()
            w0 = time.time()
            t0 = time.perf_counter()
            st = campaign.run(spec_path, store, executor="dask", dask_local=2,
                              progress=False, log=log)
            t = time.perf_counter() - t0
            w1 = time.time()
            assert st["complete"] and st["sims_done"] == n, st
            last = max(f.stat().st_mtime for f in (store / "chunks").glob("chunk-*.parquet"))
            t_ready = marks[0][0] - w0 if marks else float("nan")
            walls.append(t)
            ready.append(t_ready)
            compute.append(last - marks[0][0] if marks else float("nan"))
            print(f"{i + 1:>4} {la:>16} {t:8.2f} {n / t:8.0f} {t_ready:9.2f} "
                  f"{compute[-1]:12.2f} {w1 - last:7.2f}")
            if i == 0:
                print(f"     executor: {marks[0][1] if marks else '(no log line)'}")
                a, b = campaign.load(self.local_store), campaign.load(store)
                pd.testing.assert_frame_equal(a, b)
                same = len(a)
                print(f"     rows: dask store == local store ({same:,} rows, "
                      "assert_frame_equal)")
            shutil.rmtree(store)
        # distributed's Nanny sets its pre-spawn-environ (OMP_NUM_THREADS=1, ...) in the
        # os.environ of the process that starts the workers; rocking.campaign restores it.
        # Check, and put it back if anything is left (later children would inherit it).
        leaked = {k: v for k, v in os.environ.items() if ENV0.get(k) != v}
        if leaked:
            print("     os.environ changed by the Dask runs (restored here): "
                  + ", ".join(f"{k}={v}" for k, v in sorted(leaked.items())))
            os.environ.clear()
            os.environ.update(ENV0)
        best_local = min(self.local_times)
        ratio = min(walls) / best_local
        ratio_c = min(compute) / best_local
        self.summary += [
            ("dask 2 workers: wall s incl. start-up", spread(walls),
             f"{ratio - 1:+.0%} vs local: {'ok' if ratio <= 1.25 else 'MISSED'} (<= +25 %)"),
            ("dask: bare cluster start + close s", spread(np.add(t_up, t_down)),
             f"start {spread(t_up)}"),
            ("dask: start to workers ready s", spread(ready), "cluster + kernels loaded"),
            ("dask: workers ready -> last chunk s", spread(compute),
             f"{ratio_c - 1:+.0%} vs local"),
            ("dask rows == local rows", f"{same:,} rows" if same else "not checked", ""),
        ]

    # ------------------------------------------------------------------ memory
    def memory(self):
        print("\n== memory: peak RSS of a fresh process running the local executor")
        code = """
import json, resource, sys, time
t0 = time.perf_counter()
from rocking import campaign
if sys.argv[1] == "-":
    from rocking.campaign.execute import warm_up
    warm_up(campaign.read_spec(sys.argv[2]))
    import pyarrow  # noqa: F401
else:
    campaign.run(sys.argv[1], sys.argv[2], progress=False)
hwm = [line for line in open("/proc/self/status") if line.startswith("VmHWM:")]
print(json.dumps({"maxrss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
                  "hwm_mb": int(hwm[0].split()[1]) / 1024 if hwm else float("nan"),
                  "seconds": time.perf_counter() - t0}))
"""
        r, lv, cs = self.n_rec, self.n_lev, self.chunk
        cases = [("import + kernels only", None, 0),
                 (f"{r * lv // 10:,} sims", stochastic_spec(r, lv // 10, cs), cs),
                 (f"{r * lv:,} sims", stochastic_spec(r, lv, cs), cs),
                 (f"{r * lv:,} sims", stochastic_spec(r, lv, cs // 4), cs // 4),
                 (f"{r * lv:,} sims", stochastic_spec(r, lv, cs * 4), cs * 4)]
        if self.quick:  # every line of the loop, in two fresh processes
            cases = [cases[0], cases[2]]
        warm_spec = self.spec_file(stochastic_spec(2, 2, 4))
        print(f"{'case':>22} {'chunk':>6} {'run':>4} {'loadavg':>16} {'VmHWM MB':>9} "
              f"{'+base':>6} {'ru_maxrss':>9} {'wall s':>7}")
        rows = {}
        for label, text, cs in cases:
            spec = self.spec_file(text) if text else None
            for i in range(self.repeat):
                store = self.path("mem")
                args = [str(spec), str(store)] if spec else ["-", str(warm_spec)]
                la = loadavg()
                p = subprocess.run([sys.executable, "-c", code, *args], capture_output=True,
                                   text=True, check=True, env=ENV0)
                out = json.loads(p.stdout.strip().splitlines()[-1])
                rows.setdefault((label, cs), []).append(out["hwm_mb"])
                base = min(rows[cases[0][0], 0])
                print(f"{label:>22} {cs or '-':>6} {i + 1:>4} {la:>16} "
                      f"{out['hwm_mb']:9.0f} {out['hwm_mb'] - base:+6.0f} "
                      f"{out['maxrss_mb']:9.0f} {out['seconds']:7.2f}")
                shutil.rmtree(store, ignore_errors=True)
        base = min(rows[cases[0][0], 0])
        for (label, cs), mbs in rows.items():
            self.summary.append((f"peak RSS, {label}" + (f", chunk {cs}" if cs else ""),
                                 f"{min(mbs):.0f}-{max(mbs):.0f} MB",
                                 f"{max(mbs) - base:+.0f} MB over import + kernels"
                                 if cs else "baseline"))

    # ------------------------------------------------------------------ dem
    def dem(self):
        from rocking import campaign
        from rocking.campaign.plan import Campaign
        n_per, n_amp = self.n_dem
        print(f"\n== dem: specimen 2 (geometric) under one-sine pulses, {n_per} periods x "
              f"{n_amp} amplitudes, 3 s windows")
        # a handful of runs first: the rate that sizes the campaign
        spec = campaign.parse_spec(pulse_spec("dem", n_per, n_amp))
        c = Campaign(spec)
        k = min(8, spec.n_sims)
        ids = np.linspace(0, spec.n_sims - 1, k).astype(np.int64)
        t0 = time.perf_counter()
        c.run_ids(ids)
        t8 = time.perf_counter() - t0
        print(f"{k} DEM runs spread over the grid: {t8:.2f} s ({k / t8:.1f} sims/s; "
              f"{spec.n_sims:,} runs projected at {spec.n_sims * t8 / k:.0f} s)")
        print(f"{'model':>8} {'sims':>6} {'run':>4} {'loadavg':>16} {'wall s':>8} "
              f"{'sims/s':>8} {'overturned':>10}")
        res = {}
        for model in ("dem", "housner"):
            spec_path = self.spec_file(pulse_spec(model, n_per, n_amp))
            n = campaign.read_spec(spec_path).n_sims
            for i in range(self.repeat):
                store = self.path(model)
                la = loadavg()
                t0 = time.perf_counter()
                campaign.run(spec_path, store, progress=False)
                t = time.perf_counter() - t0
                ov = int(campaign.load(store)["overturned"].sum())
                res.setdefault(model, []).append(t)
                print(f"{model:>8} {n:>6} {i + 1:>4} {la:>16} {t:8.2f} {n / t:8.1f} "
                      f"{ov:>10}")
                shutil.rmtree(store)
            self.summary.append((f"{model}, {n:,} pulse runs: wall s", spread(res[model]),
                                 f"{n / min(res[model]):.1f} sims/s"))

    # ------------------------------------------------------------------ tail
    def tail(self):
        """The local campaign stopped at the record's end (old) and with the default free
        motion after it (new), interleaved, and the outcomes compared run by run."""
        import pandas as pd

        from rocking import campaign
        from rocking.errors import SpecError
        # the old behaviour exactly: every run stops at its record's end (20 s records)
        old_text = stochastic_spec(self.n_rec, self.n_lev, self.chunk, name="bench-tail",
                                   extra="duration = 20.0")
        new_text = stochastic_spec(self.n_rec, self.n_lev, self.chunk, name="bench-tail")
        try:
            campaign.parse_spec(old_text)
        except SpecError as e:
            if "max_free_time" not in str(e):
                raise
            print(f"\n== tail: skipped, this package has no [campaign] max_free_time ({e})")
            self.summary.append(("tail: old vs new default", "skipped",
                                 "no max_free_time spec key"))
            return
        specs = {"old": self.spec_file(old_text, "tail-old"),
                 "new": self.spec_file(new_text, "tail-new")}
        n = campaign.read_spec(specs["new"]).n_sims
        print(f"\n== tail: the local campaign ({n:,} simulations, no duration) stopped at the "
              "record's end (old: duration = 20 s, the records' length) and with the "
              "default free motion after it (new), interleaved")
        print(f"{'run':>4} {'case':>4} {'loadavg':>16} {'wall s':>8} {'sims/s':>8} "
              f"{'cpu s':>8}")
        times = {"old": [], "new": []}
        cpus = {"old": [], "new": []}  # CPU time of this process (all its threads)
        stores = {}
        for i in range(self.repeat):
            for case, spec_path in specs.items():
                store = self.path(f"tail-{case}")
                la = loadavg()
                t0, c0 = time.perf_counter(), time.process_time()
                st = campaign.run(spec_path, store, progress=False)
                t, c = time.perf_counter() - t0, time.process_time() - c0
                assert st["complete"] and st["sims_done"] == n, st
                times[case].append(t)
                cpus[case].append(c)
                print(f"{i + 1:>4} {case:>4} {la:>16} {t:8.2f} {n / t:8.0f} {c:8.2f}")
                if case in stores:
                    shutil.rmtree(store)
                else:
                    stores[case] = store
        best = {k: min(v) for k, v in times.items()}
        ratio = best["new"] / best["old"]
        pairs = [b / a for a, b in zip(times["old"], times["new"], strict=True)]
        cpu_ratio = min(cpus["new"]) / min(cpus["old"])
        print(f"best: old {best['old']:.2f} s, new {best['new']:.2f} s, new/old {ratio:.3f} "
              f"(pair by pair: {', '.join(f'{r:.3f}' for r in pairs)}); goal <= 1.15: "
              f"{'ok' if ratio <= 1.15 else 'MISSED'}; CPU time new/old {cpu_ratio:.3f} "
              "(less sensitive to other jobs on the machine)")

        a = campaign.load(stores["old"]).set_index("sim_id").sort_index()
        b = campaign.load(stores["new"]).set_index("sim_id").sort_index()
        pd.testing.assert_index_equal(a.index, b.index)
        ov_a, ov_b = a["overturned"].to_numpy(bool), b["overturned"].to_numpy(bool)
        to_over = int(np.sum(~ov_a & ov_b))  # survivors at the record's end, over in the tail
        to_up = int(np.sum(ov_a & ~ov_b))  # must be 0: the runs agree up to the record's end
        up = ~ov_a & ~ov_b
        th_a = a["max_abs_theta"].to_numpy(float)[up]
        th_b = b["max_abs_theta"].to_numpy(float)[up]
        grew = int(np.sum(th_b > th_a))
        imp_a, imp_b = a["n_impacts"].to_numpy(), b["n_impacts"].to_numpy()
        moving = int(np.sum(imp_b > imp_a))  # impacts in the tail: rocking at the record's end
        print(f"outcomes, {n:,} runs: overturned old {int(ov_a.sum()):,}, new "
              f"{int(ov_b.sum()):,}: {to_over:,} survivors at the record's end overturn in "
              f"the tail, {to_up} the other way; of {int(up.sum()):,} standing in both, "
              f"{grew:,} reach a larger max|theta| in the tail")
        print(f"impacts: old {int(imp_a.sum()):,}, new {int(imp_b.sum()):,} "
              f"({imp_b.sum() / max(imp_a.sum(), 1) - 1:+.0%}); {moving:,} runs have impacts "
              "in the tail (still rocking at the record's end)")
        flips = f"{to_over:,} survivor -> overturned, {to_up} back"
        if "settled" in a.columns and "settled" in b.columns:
            set_a = a["settled"].to_numpy(bool)
            s_a, s_b = int(set_a.sum()), int(b["settled"].to_numpy(bool).sum())
            odd = int(np.sum(set_a & (imp_b > imp_a)))
            print(f"settled flag (at rest or overturned at the run's end): old {s_a:,} of "
                  f"{n:,}, new {s_b:,} (unsettled at the cap: {n - s_b:,})"
                  + (f"; {odd:,} runs flagged settled at the record's end rock after it "
                     "(outcome decided there, not at rest)" if odd else ""))
            settled = f"old {s_a:,}, new {s_b:,} of {n:,}"
        else:
            print("no settled column in the rows")
            settled = "no settled column"
        self.summary += [
            (f"tail: {n:,} sims, old (stop at record end) s", spread(times["old"]), ""),
            (f"tail: {n:,} sims, new default s", spread(times["new"]),
             f"new/old {ratio:.3f}: {'ok' if ratio <= 1.15 else 'MISSED'} (<= 1.15)"),
            ("tail: CPU s, old / new", f"{min(cpus['old']):.2f} / {min(cpus['new']):.2f}",
             f"new/old {cpu_ratio:.3f}"),
            ("tail: overturning flips", flips, ""),
            ("tail: runs with impacts in the tail", f"{moving:,} of {n:,}",
             f"impacts {imp_b.sum() / max(imp_a.sum(), 1) - 1:+.0%}"),
            ("tail: settled runs", settled, ""),
        ]

    def report(self):
        print("\n== summary")
        w = max(len(a) for a, _, _ in self.summary) + 2
        for a, b, c in self.summary:
            print(f"{a:<{w}}{b:>22}  {c}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true",
                    help="smoke check: tiny campaigns, one run of each (unless --repeat)")
    ap.add_argument("--only", default=",".join(SECTIONS),
                    help=f"comma-separated sections among {', '.join(SECTIONS)}")
    ap.add_argument("--repeat", type=int, default=2, help="runs of each measurement")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(repeat=1)  # --repeat on the command line still wins
    args = ap.parse_args(argv)
    only = [s.strip() for s in args.only.split(",") if s.strip()]
    bad = sorted(set(only) - set(SECTIONS))
    if bad:
        ap.error(f"unknown section {bad[0]!r} (choose among {', '.join(SECTIONS)})")
    import numba

    import rocking
    print(f"rocking {rocking.__version__}, {os.cpu_count()} cores, numba {numba.__version__} "
          f"({numba.config.NUMBA_NUM_THREADS} threads), load {loadavg()}")
    root = Path(tempfile.mkdtemp(prefix="bench-campaign-"))
    try:
        b = Bench(root, max(1, args.repeat), args.quick)
        b.warm()
        for s in SECTIONS:
            if s in only:
                getattr(b, s)()
        b.report()
    finally:
        with contextlib.suppress(OSError):
            shutil.rmtree(root)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
