"""Study: convergence of the Zeno (return-to-rest) rule in ``rest_tol``.

Criterion (the issue): with the default threshold ``T``, the maximum angle must not change by
more than 0.1% when the threshold is made 100 times smaller (``T/100``), and no run may
change its overturning outcome.

The study runs the classical model (``model="housner"``) over

* blocks: the specimens 2, 3, 4 with theoretical and experimental parameters, a grid
  ``alpha`` in {0.1, 0.2, 0.3} x ``p`` in {1.5, 2.5, 4} 1/s and the block of the issue
  (``alpha = 0.25``, ``p = 2``), all with Eq 4 ``mu`` except the experimental specimens;
* records: the 4 bundled PEER records and the 30 seed earthquakes;
* load factors ``f = c g tan(alpha) / PGA`` with ``c`` geometric from ``--c-min`` (just above
  the uplift level) to ``--c-max`` (beyond overturning of every block);
* duration = record duration + 2 s;

for every ``rest_tol`` in 1e-4 ... 1e-14 (``--exps`` and two decades below) and a reference
``--ref`` (default 1e-13), one ``simulate_many`` call per (block, record set of equal
duration) and threshold. For each candidate ``T`` it prints: the fraction of uplifted runs
not overturned at either threshold whose maximum angle changes by more than 0.1% between
``T`` and ``T/100`` and between ``T`` and the reference, the worst relative change, the number
of overturning outcomes that flip, the fraction of runs that stay within 0.1% of the
reference (same outcome) at every threshold ``<= T`` ("converged"), and the cost of that
pass: summed wall time of the batches, wall time per batch, CPU time, impacts and
integration steps, the last three relative to 1e-6 (steps of the whole batch where
``simulate_many`` reports them, else from single runs on the bundled records). Then the
distance to the reference per threshold (does it shrink monotonically?), the worst cases,
and a timing section (min wall and CPU time over round-robin repeats, for a machine shared
with other jobs).

Two gauges of the intrinsic sensitivity, at the reference threshold: the load factors
perturbed by a relative ``--perturb`` (rocking under random input is chaotic: a change of
the rest threshold perturbs the state by about ``T alpha``), and ``rtol`` tightened to
``--rtol-gauge`` (the integration error itself).

A shorter CCRR section (``model="ccrr"``): its rest threshold is
``max(rest_tol, 2 chi_c)`` with ``chi_c = (l^2 alpha / sin alpha)^(1/3)``, about 9.3e-6 at the
default ``l = 1e-8``, so below that ``rest_tol`` has no effect; the section compares
``rest_tol`` above that floor, the floor at smaller ``l``, and different ``l``.

Nothing is written to disk. The full default study takes about 8-10 minutes on 2 cores;
``--quick`` is a smoke check of every section on tiny inputs (see ``QUICK``; sizes given on
the command line still win)::

    .venv/bin/python benchmarks/study_rest_tol.py
    .venv/bin/python benchmarks/study_rest_tol.py --n-c 8 --n-seed 10 --no-ccrr   # shorter
    .venv/bin/python benchmarks/study_rest_tol.py --quick                         # seconds
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

import rocking
from rocking.motions import builtin_records, load_builtin, seed_earthquakes

G = 9.80665
TOL = 1e-3  # the criterion: 0.1% on the maximum angle


def make_blocks(which: str):
    """(label, Block) pairs."""
    if which == "tiny":  # --quick: one specimen and the block of the issue
        return [("spec2-theo", rocking.specimen(2, params="theoretical")),
                ("a0.25-p2", rocking.Block.from_params(0.25, 2.0, rocking.housner_mu(0.25)))]
    out = []
    for n in (2, 3, 4):
        for ps in ("theoretical", "experimental"):
            out.append((f"spec{n}-{ps[:4]}", rocking.specimen(n, params=ps)))
    grid = [(0.25, 2.0)]
    if which == "full":
        grid += [(a, p) for a in (0.1, 0.2, 0.3) for p in (1.5, 2.5, 4.0)]
    else:
        grid += [(0.1, 1.5), (0.3, 4.0)]
    for a, p in grid:
        out.append((f"a{a:g}-p{p:g}", rocking.Block.from_params(a, p, rocking.housner_mu(a))))
    return out


def make_groups(n_seed: int):
    """Record sets of equal duration: (labels, records, duration = record + 2 s)."""
    groups = []
    for name in builtin_records():
        rec = load_builtin(name)
        groups.append(([name.split("_")[0] + "_" + name.split("_")[1]], [rec],
                       rec.duration + 2.0))
    if n_seed > 0:
        eqs = seed_earthquakes()[:n_seed]
        by_dur = {}
        for i, e in enumerate(eqs):
            by_dur.setdefault(round(e.duration, 9), []).append((f"seed{i + 1}", e))
        for dur, lst in by_dur.items():
            groups.append(([lab for lab, _ in lst], [e for _, e in lst], dur + 2.0))
    return groups


class Study:
    """The run table: one entry per (block, record, c), batched per (block, group)."""

    def __init__(self, blocks, groups, cs):
        self.blocks, self.groups, self.cs = blocks, groups, np.asarray(cs)
        self.batches = []  # (block, motions, duration, slice)
        self.labels = []
        self.bundled = []  # indices of runs on the bundled records (for the step counts)
        k = 0
        for bl, b in blocks:
            thr = G * math.tan(b.alpha)
            for gi, (labs, recs, dur) in enumerate(groups):
                ms = []
                for lab, rec in zip(labs, recs, strict=True):
                    for c in self.cs:
                        ms.append(rec.scaled(c * thr / rec.pga))
                        self.labels.append((bl, lab, float(c)))
                        if len(recs) == 1 and gi < len(builtin_records()):
                            self.bundled.append((b, ms[-1], dur, k))
                        k += 1
                self.batches.append((b, ms, dur, slice(k - len(ms), k)))
        self.n = k

    def run(self, model="housner", scale=1.0, **opts):
        th = np.empty(self.n)
        ov = np.empty(self.n, dtype=bool)
        ni = np.empty(self.n, dtype=np.int64)
        wall = cpu = 0.0
        steps = 0
        for b, ms, dur, sl in self.batches:
            if scale != 1.0:
                ms = [m.scaled(scale) for m in ms]
            t0, c0 = time.perf_counter(), time.process_time()
            r = rocking.simulate_many(b, ms, model=model, duration=dur, **opts)
            wall += time.perf_counter() - t0
            cpu += time.process_time() - c0
            th[sl] = np.asarray(r.max_abs_theta) / b.alpha
            ov[sl] = np.asarray(r.overturned)
            ni[sl] = np.asarray(r.n_impacts)
            ns = getattr(r, "n_steps", None)  # batches report steps in newer versions
            steps = None if ns is None or steps is None else steps + int(np.sum(ns))
        return {"theta": th, "over": ov, "imp": ni, "wall": wall, "cpu": cpu, "steps": steps,
                "n_batch": len(self.batches)}

    def steps(self, model="housner", **opts):
        """Total integration steps over the bundled-record runs (single runs)."""
        tot = 0
        for b, m, dur, _k in self.bundled:
            r = rocking.simulate(b, m, model=model, duration=dur, **opts)
            tot += int(r.info["n_steps"])
        return tot


def compare(a, b):
    """(n uplifted non-overturned, fraction > TOL, worst relative change, flips, rel array)."""
    flips = int(np.sum(a["over"] != b["over"]))
    keep = ~a["over"] & ~b["over"] & ((a["theta"] > 0) | (b["theta"] > 0))
    rel = np.zeros(a["theta"].size)
    den = np.maximum(np.maximum(a["theta"], b["theta"]), 1e-300)
    rel[keep] = np.abs(a["theta"][keep] - b["theta"][keep]) / den[keep]
    n = int(keep.sum())
    frac = float(np.mean(rel[keep] > TOL)) if n else 0.0
    worst = float(rel[keep].max()) if n else 0.0
    return n, frac, worst, flips, rel


def housner_section(study, exps, ref_exp, perturb, rtol_gauge, with_steps, top):
    # results are keyed by the exponent e of rest_tol = 10^-e
    es = sorted(set(exps) | {e + 2 for e in exps} | {ref_exp, 6})
    res = {}
    for e in es:
        res[e] = study.run(rest_tol=10.0 ** -e)
        if with_steps and res[e]["steps"] is None:
            res[e]["steps"] = study.steps(rest_tol=10.0 ** -e)
        print(f"  rest_tol 1e-{e:<2d}: {res[e]['wall']:.2f} s for {study.n} runs "
              f"({res[e]['n_batch']} batches), {int(res[e]['over'].sum())} overturned",
              flush=True)
    ref = res[ref_exp]
    base = res[6]

    def cost(r):
        stp = f"{r['steps'] / base['steps']:6.3f}" if with_steps else f"{'-':>6}"
        return (f"{r['wall']:6.2f} {r['wall'] / r['n_batch']:7.3f} "
                f"{r['cpu'] / base['cpu']:5.2f} "
                f"{r['imp'].sum() / base['imp'].sum():7.3f} {stp}")

    print(f"\nconvergence ({study.n} runs; criterion: max angle within {TOL:.1%}, same "
          "overturning; n = uplifted runs not overturned at T nor T/100)")
    hdr = (f"{'T':>7} | {'n':>5} {'>0.1% vs T/100':>14} {'worst':>9} {'flips':>5} | "
           f"{'>0.1% vs ref':>12} {'worst':>9} {'flips':>5} | {'converged':>9} | "
           f"{'wall s':>6} {'s/batch':>7} {'cpu':>5} {'impacts':>7} {'steps':>6}")
    print(hdr)
    print("-" * len(hdr))
    for e in sorted(exps):
        n, f1, w1, fl1, _ = compare(res[e], res[e + 2])
        _, f2, w2, fl2, _ = compare(res[e], ref)
        # converged: within TOL of the reference (same outcome) at every threshold <= 10^-e
        ok = np.ones(study.n, dtype=bool)
        for e2 in es:
            if e2 >= e:
                _, _, _, _, rel = compare(res[e2], ref)
                ok &= (rel <= TOL) & (res[e2]["over"] == ref["over"])
        print(f"  1e-{e:<2d} | {n:5d} {f1:14.2%} {w1:9.2e} {fl1:5d} | {f2:12.2%} {w2:9.2e} "
              f"{fl2:5d} | {ok.mean():9.2%} | {cost(res[e])}")
    print(f"  1e-{ref_exp:<2d} | {'(reference)':>68} | {cost(ref)}")
    if perturb:
        pr = study.run(rest_tol=10.0 ** -ref_exp, scale=1.0 + perturb)
        n, f, w, fl, _ = compare(pr, ref)
        print(f"\nchaos gauge: load factors x (1 + {perturb:g}) at the reference threshold: "
              f"{f:.2%} of {n} runs change by > 0.1% (worst {w:.2e}), {fl} flips")
    if rtol_gauge:
        pr = study.run(rest_tol=10.0 ** -ref_exp, rtol=rtol_gauge)
        n, f, w, fl, _ = compare(pr, ref)
        print(f"numerical gauge: rtol {rtol_gauge:g} instead of the default at the reference "
              f"threshold: {f:.2%} of {n} runs change by > 0.1% (worst {w:.2e}), {fl} flips")
    # do the differences shrink monotonically? per threshold, distance to the reference
    print("\ndistance to the reference, per threshold (uplifted, non-overturned runs)")
    print(f"{'T':>7} {'n diff>1e-9':>11} {'>0.1%':>6} {'>1%':>5} {'99th pct':>9} {'max':>9} "
          f"{'flips':>5}")
    for e in es:
        if e == ref_exp:
            continue
        n, f, w, fl, rel = compare(res[e], ref)
        nz = rel[rel > 0]
        print(f"  1e-{e:<2d} {int(np.sum(rel > 1e-9)):11d} {int(np.sum(rel > TOL)):6d} "
              f"{int(np.sum(rel > 1e-2)):5d} "
              f"{np.quantile(nz, 0.99) if nz.size else 0.0:9.2e} {w:9.2e} {fl:5d}")
    if top:
        print("\nworst cases, T vs T/100 (max angle / alpha):")
        for e in sorted(exps):
            a, b = res[e], res[e + 2]
            _, _, _, _, rel = compare(a, b)
            flip = np.flatnonzero(a["over"] != b["over"])
            idx = list(flip) + [i for i in np.argsort(rel)[::-1][:top] if rel[i] > TOL]
            for i in idx[:top]:
                bl, lab, c = study.labels[i]
                print(f"  T=1e-{e:<2d} {bl:>18} {lab:>14} c={c:6.3f}: "
                      f"{a['theta'][i]:.5f} ({'over' if a['over'][i] else 'up'}) "
                      f"vs {b['theta'][i]:.5f} ({'over' if b['over'][i] else 'up'}), "
                      f"ref {ref['theta'][i]:.5f} ({'over' if ref['over'][i] else 'up'})")
    return res


def timing_section(study, exps, repeats):
    """Cost of smaller thresholds: min wall and CPU time over round-robin repeats."""
    wall = {e: [] for e in exps}
    cpu = {e: [] for e in exps}
    for _ in range(repeats):
        for e in exps:
            r = study.run(rest_tol=10.0 ** -e)
            wall[e].append(r["wall"])
            cpu[e].append(r["cpu"])
    b = exps[0]
    print(f"\ncost ({study.n} runs per threshold, {len(study.batches)} simulate_many calls; "
          f"min over {repeats} round-robin repeats; ratios to 1e-{b})")
    print(f"{'T':>7} {'wall s':>7} {'ratio':>6} {'cpu s':>7} {'ratio':>6} {'ms/run':>7}")
    for e in exps:
        w, c = min(wall[e]), min(cpu[e])
        print(f"  1e-{e:<2d} {w:7.2f} {w / min(wall[b]):6.3f} {c:7.2f} {c / min(cpu[b]):6.3f} "
              f"{1e3 * w / study.n:7.3f}")


def ccrr_section(study):
    """Brief: rest_tol above the floor 2 chi_c at the default l, and the floor at smaller l."""
    cases = [("l=1e-8", 1e-8, 1e-3), ("l=1e-8", 1e-8, 1e-4), ("l=1e-8", 1e-8, 1e-5),
             ("l=1e-8", 1e-8, 1e-6), ("l=1e-9", 1e-9, 1e-6), ("l=1e-10", 1e-10, 1e-6),
             ("l=1e-11", 1e-11, 1e-5), ("l=1e-11", 1e-11, 1e-7), ("l=1e-11", 1e-11, 1e-9)]
    res = {}
    for lab, ell, T in cases:
        res[(ell, T)] = study.run(model="ccrr", l=ell, rest_tol=T)
        a = study.blocks[0][1].alpha
        floor = 2.0 * (ell * ell * a / math.sin(a)) ** (1.0 / 3.0)
        print(f"  ccrr {lab} rest_tol {T:.0e} (effective ~{max(T, floor):.1e}): "
              f"{res[(ell, T)]['wall']:.2f} s, {int(res[(ell, T)]['over'].sum())} overturned",
              flush=True)
    print(f"\nCCRR ({study.n} runs): pairs compared")
    print(f"{'case A':>22} {'case B':>22} | {'n':>5} {'>0.1%':>7} {'worst':>9} {'flips':>5}")
    pairs = [((1e-8, 1e-3), (1e-8, 1e-5)), ((1e-8, 1e-4), (1e-8, 1e-6)),
             ((1e-8, 1e-5), (1e-8, 1e-6)), ((1e-11, 1e-5), (1e-11, 1e-7)),
             ((1e-11, 1e-7), (1e-11, 1e-9)), ((1e-8, 1e-6), (1e-9, 1e-6)),
             ((1e-8, 1e-6), (1e-10, 1e-6)), ((1e-8, 1e-6), (1e-11, 1e-9))]
    for A, B in pairs:
        n, f, w, fl, _ = compare(res[A], res[B])
        la = f"l={A[0]:.0e} rt={A[1]:.0e}"
        lb = f"l={B[0]:.0e} rt={B[1]:.0e}"
        print(f"{la:>22} {lb:>22} | {n:5d} {f:7.2%} {w:9.2e} {fl:5d}")


QUICK = {"blocks": "tiny", "n_seed": 1, "n_c": 2, "exps": [6], "ref": 8, "top": 1,
         "timing_repeats": 1, "timing_exps": [6, 8], "ccrr_n_seed": 1, "ccrr_n_c": 2}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--blocks", choices=("full", "small", "tiny"), default="full",
                    help="full: 6 specimens + 9 (alpha, p) + issue block; small: 6 + 3 (and "
                    "the CCRR section's set); tiny: specimen 2 + issue block (also for CCRR)")
    ap.add_argument("--n-seed", type=int, default=30, help="seed earthquakes used (0-30)")
    ap.add_argument("--n-c", type=int, default=25, help="load factors per block and record")
    ap.add_argument("--c-min", type=float, default=1.05, help="smallest c (f = c g tan a/PGA)")
    ap.add_argument("--c-max", type=float, default=16.0, help="largest c")
    ap.add_argument("--exps", type=int, nargs="+", default=[4, 5, 6, 7, 8, 9, 10, 11, 12],
                    help="candidate thresholds 10^-e")
    ap.add_argument("--ref", type=int, default=13, help="reference threshold 10^-ref")
    ap.add_argument("--perturb", type=float, default=1e-8,
                    help="relative load-factor perturbation of the chaos gauge (0: skip)")
    ap.add_argument("--rtol-gauge", type=float, default=1e-9,
                    help="rtol of the numerical gauge run (0: skip)")
    ap.add_argument("--no-steps", action="store_true", help="skip the step counts")
    ap.add_argument("--top", type=int, default=3, help="worst cases listed per threshold")
    ap.add_argument("--timing-repeats", type=int, default=2,
                    help="round-robin timing repeats of the whole study (0: skip)")
    ap.add_argument("--timing-exps", type=int, nargs="+", default=[6, 8, 10, 12],
                    help="thresholds timed (the first is the base of the ratios)")
    ap.add_argument("--no-ccrr", action="store_true", help="skip the CCRR section")
    ap.add_argument("--ccrr-n-seed", type=int, default=10, help="seed earthquakes for CCRR")
    ap.add_argument("--ccrr-n-c", type=int, default=10, help="load factors for CCRR")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)
    args = ap.parse_args(argv)

    print("Gazli (RSN126), alpha 0.25, p 2, Eq 4 mu, load factor 1.0917, record + 2 s:")
    rec = load_builtin("RSN126_GAZLI_GAZ000")
    b = rocking.Block.from_params(0.25, 2.0, rocking.housner_mu(0.25))
    m = rec.scaled(1.0917)
    for e in range(4, 14):
        r = rocking.simulate(b, m, rest_tol=10.0 ** -e, duration=rec.duration + 2.0)
        print(f"  housner rest_tol 1e-{e:<2d}: max/alpha {r.max_abs_theta / b.alpha:.6f}  "
              f"impacts {r.n_impacts}  steps {r.info['n_steps']}")
    if not args.no_ccrr:
        for ell, T in ((1e-8, 1e-4), (1e-8, 1e-6), (1e-10, 1e-6), (1e-11, 1e-9)):
            r = rocking.simulate(b, m, model="ccrr", l=ell, rest_tol=T,
                                 duration=rec.duration + 2.0)
            print(f"  ccrr l {ell:.0e} rest_tol {T:.0e}: max/alpha "
                  f"{r.max_abs_theta / b.alpha:.6f}")

    blocks = make_blocks(args.blocks)
    groups = make_groups(args.n_seed)
    cs = np.geomspace(args.c_min, args.c_max, args.n_c)
    study = Study(blocks, groups, cs)
    print(f"\nstudy: {len(blocks)} blocks x ({len(builtin_records())} bundled + {args.n_seed} "
          f"seed records) x {args.n_c} load factors c in [{args.c_min:g}, {args.c_max:g}] = "
          f"{study.n} runs per threshold")
    warm = Study(blocks[:1], groups[:1], cs[:2])
    warm.run(rest_tol=1e-6)  # JIT / cache warm-up, not timed
    t0 = time.perf_counter()
    housner_section(study, args.exps, args.ref, args.perturb, args.rtol_gauge,
                    not args.no_steps, args.top)
    print(f"\nhousner section: {time.perf_counter() - t0:.0f} s")
    if args.timing_repeats > 0:
        timing_section(study, args.timing_exps, args.timing_repeats)

    if not args.no_ccrr:
        t0 = time.perf_counter()
        cblocks = make_blocks("tiny" if args.blocks == "tiny" else "small")
        cstudy = Study(cblocks, make_groups(args.ccrr_n_seed),
                       np.geomspace(args.c_min, args.c_max, args.ccrr_n_c))
        Study(cblocks[:1], cstudy.groups[:1], cs[:2]).run(model="ccrr")  # warm-up
        print(f"\nCCRR study: {len(cblocks)} blocks x ({len(builtin_records())} + "
              f"{args.ccrr_n_seed} records) x {args.ccrr_n_c} load factors = {cstudy.n} runs")
        ccrr_section(cstudy)
        print(f"\nccrr section: {time.perf_counter() - t0:.0f} s")


if __name__ == "__main__":
    main()
