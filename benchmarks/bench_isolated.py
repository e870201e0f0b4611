"""Isolated-base vs classical model throughput on the same 400 records (issue 19).

Times ``rocking.simulate_many(..., model="isolated")`` (default options: a linear isolator
of 2 s, 5 % damping, plate as heavy as the block; and a friction pendulum of radius 2 m,
friction 0.05) against the classical model (``model="housner"``) on the records of
``bench_housner.py`` (band-limited noise, 20 s at 100 Hz, specimen 2 with the
experimental parameters), in one run, and reports the throughput ratio
isolated/classical (goal >= 0.3). A stiffer isolator (0.5 s), under which the block rocks
and overturns, is timed too.

``--v-eps-study``: the convergence of the friction pendulum's ``tanh`` regularisation on the
first ``--study-n`` records: each ``v_eps`` of ``--v-eps`` against the smallest, for the
default pendulum (friction 0.05, radius 2 m: the plate slides, the block stays down) and a
pendulum whose friction (0.2, radius 1 m) exceeds ``tan(alpha)``, so that the block rocks
on a plate that sticks: relative differences of ``max |u|``, ``max |A|`` and
``max |theta|`` (median and largest over the records; ``theta`` of the blocks standing in
both), overturning flips, the median of ``max |theta|`` and the steps. The last line is
the figures as JSON.

Timings are the best of ``--repeat`` runs after a warm-up. ``--quick`` (a smoke check of
the script): 4 records of 4 s, one run, the study on 2 records with three ``v_eps``, unless
given.

    .venv/bin/python benchmarks/bench_isolated.py [--n 400] [--repeat 3] [--quick]
    .venv/bin/python benchmarks/bench_isolated.py --n 40 --repeat 1 --v-eps-study
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

import rocking

sys.path.insert(0, str(Path(__file__).parent))
from bench_housner import make_records  # noqa: E402

CASES = {
    "linear": {},  # the model's defaults
    "pendulum": {"isolation": "pendulum"},
    "linear-0.5s": {"isolation_period": 0.5},
}


def timed(block, records, model, repeat=3, **options):
    rocking.simulate_many(block, records[:2], model=model, **options)  # JIT warm-up / cache
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        res = rocking.simulate_many(block, records, model=model, **options)
        best = min(best, time.perf_counter() - t0)
    return res, best


STUDY = {"default pendulum": {"isolation": "pendulum"},
         "friction 0.2, radius 1 m": {"isolation": "pendulum", "friction": 0.2,
                                      "radius": 1.0}}


def v_eps_study(block, records, values):
    """Each ``v_eps`` against the smallest (module docstring); returns the figures."""
    values = sorted(values, reverse=True)
    figures = {}
    for name, options in STUDY.items():
        runs = {}
        for ve in values:
            t0 = time.perf_counter()
            runs[ve] = (rocking.simulate_many(block, records, model="isolated", v_eps=ve,
                                              **options), time.perf_counter() - t0)
        ref = runs[values[-1]][0]
        print(f"v_eps study, {name} ({len(records)} records; reference v_eps = "
              f"{values[-1]:g} m/s): {int((ref.max_abs_theta > 0).sum())} rocked, "
              f"{int(ref.overturned.sum())} overturned")
        print(f"{'v_eps':>8}{'d max|u|':>18}{'d max|A|':>18}{'d max|th|':>18}{'flips':>7}"
              f"{'med max|th|':>13}{'steps':>9}{'time':>8}")
        for ve, (r, dt) in runs.items():
            du = np.abs(r.max_base_displacement / ref.max_base_displacement - 1)
            da = np.abs(r.max_plate_acceleration / ref.max_plate_acceleration - 1)
            ok = (ref.max_abs_theta > 0) & ~ref.overturned & ~r.overturned
            dth = np.abs(r.max_abs_theta[ok] / ref.max_abs_theta[ok] - 1) if ok.any() \
                else np.zeros(1)
            flips = int((r.overturned != ref.overturned).sum())
            pair = [f"{np.median(x):.1e}/{x.max():.1e}" for x in (du, da, dth)]
            print(f"{ve:>8.0e}{pair[0]:>18}{pair[1]:>18}{pair[2]:>18}{flips:>7}"
                  f"{np.median(r.max_abs_theta):>13.4g}{np.median(r.n_steps):>9.0f}"
                  f"{dt:>7.2f}s")
            figures[f"v_eps_{name}_{ve:g}"] = {
                "max_u_median": float(np.median(du)), "max_u_max": float(du.max()),
                "max_A_median": float(np.median(da)), "max_A_max": float(da.max()),
                "max_theta_median": float(np.median(dth)), "overturn_flips": flips}
    return figures


QUICK = {"n": 4, "duration": 4.0, "repeat": 1, "v_eps_study": True, "study_n": 2,
         "v_eps": "1e-2,1e-3,1e-4"}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=400)
    ap.add_argument("--duration", type=float, default=20.0)
    ap.add_argument("--seed", type=int, default=2007)
    ap.add_argument("--repeat", type=int, default=3, help="timed runs (best reported)")
    ap.add_argument("--v-eps-study", action="store_true",
                    help="the convergence study of v_eps (module docstring)")
    ap.add_argument("--study-n", type=int, default=40, help="records of the v_eps study")
    ap.add_argument("--v-eps", default="1e-2,3e-3,1e-3,3e-4,1e-4,3e-5",
                    help="the v_eps of the study (m/s, comma-separated)")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)
    block = rocking.specimen(2, "experimental")
    records = make_records(args.n, args.duration, args.seed)
    h, th = timed(block, records, "housner", args.repeat)
    print(f"{args.n} records of {args.duration:g} s, {block!r}")
    print(f"{'model':<22}{'time (s)':>10}{'sims/s':>10}{'ratio':>8}{'steps':>9}"
          f"{'rocked':>8}{'overt.':>8}")
    print(f"{'housner':<22}{th:>10.3f}{args.n / th:>10.1f}{1.0:>8.3f}"
          f"{np.median(h.n_steps):>9.0f}{int((h.max_abs_theta > 0).sum()):>8}"
          f"{int(h.overturned.sum()):>8}")
    figures = {"n": args.n, "duration": args.duration, "housner_sims_per_s": args.n / th}
    for name, options in CASES.items():
        r, t = timed(block, records, "isolated", args.repeat, **options)
        ratio = th / t
        print(f"{'isolated ' + name:<22}{t:>10.3f}{args.n / t:>10.1f}{ratio:>8.3f}"
              f"{np.median(r.n_steps):>9.0f}{int((r.max_abs_theta > 0).sum()):>8}"
              f"{int(r.overturned.sum()):>8}")
        figures[f"isolated_{name}_sims_per_s"] = args.n / t
        figures[f"ratio_{name}"] = ratio
    print(f"throughput ratio isolated/housner (default options): {figures['ratio_linear']:.3f}"
          " (goal >= 0.3)")
    if args.v_eps_study:
        figures.update(v_eps_study(block, records[:args.study_n],
                                   [float(x) for x in args.v_eps.split(",")]))
    print(json.dumps({k: round(v, 4) if isinstance(v, float) else v
                      for k, v in figures.items()}))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
