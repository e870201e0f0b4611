"""Benchmark: record selection, 11 records from 500 candidates over 100 periods (issue 21).

The candidates are stochastic records (:func:`rocking.motions.stochastic_records`, 32.7 s
at 100 Hz) in five groups of different filter frequency (1 to 8 Hz at mid-record, falling
by 2 % of it per s), so that their spectral shapes differ; their generation is not timed.
Timed separately, after a warm-up on 3 records (numba kernels loaded or compiled): the
5 %-damped spectra of all candidates (once per record,
:func:`rocking.analysis.selection.candidate_spectra`) and the selection on those spectra
(:func:`rocking.analysis.select_records`), against the EN 1998-1 Type 1 spectrum, ground
B, ag = 0.25 g, over the default period range of specimen 2
(:func:`rocking.analysis.default_periods`). Goal: under 5 s in total. Prints one JSON
line. Usage::

    .venv/bin/python benchmarks/bench_selection.py [--candidates 500] [--n 11]
        [--periods 100] [--quick]

``--quick`` (a smoke check of the script): 20 candidates, 3 records, 20 periods.
"""

from __future__ import annotations

import argparse
import json
import math
import time

QUICK = {"candidates": 20, "n": 3, "periods": 20}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--candidates", type=int, default=500, help="candidate records")
    ap.add_argument("--n", type=int, default=11, help="records to select")
    ap.add_argument("--periods", type=int, default=100, help="periods of the match")
    ap.add_argument("--max-scale", type=float, default=4.0, help="max scale factor")
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)  # sizes given on the command line still win
    args = ap.parse_args(argv)

    import rocking
    from rocking.analysis import default_periods, select_records
    from rocking.analysis.selection import candidate_spectra
    from rocking.motions import stochastic_records
    from rocking.motions.ec8 import DesignSpectrum
    from rocking.units import G

    t0 = time.perf_counter()
    groups = 5
    per = math.ceil(args.candidates / groups)
    recs = []
    for g, f in enumerate((1.0, 2.0, 3.0, 5.0, 8.0)):
        w = 2 * math.pi * f
        recs += stochastic_records(per, seed=g, omega_mid=w, omega_prime=-0.02 * w)
    recs = recs[:args.candidates]
    t_gen = time.perf_counter() - t0
    block = rocking.specimen(2)
    T = default_periods(block, n=args.periods)
    target = DesignSpectrum.ec8(0.25 * G, ground="B")

    candidate_spectra(recs[:3], T)  # warm-up
    t = time.perf_counter()
    S = candidate_spectra(recs, T)
    t_spec = time.perf_counter() - t
    t = time.perf_counter()
    res = select_records(S, target, T, n=args.n, max_scale=args.max_scale)
    t_sel = time.perf_counter() - t
    out = {
        "candidates": len(recs), "n": args.n, "periods": int(T.size),
        "period_range_s": [round(float(T[0]), 4), round(float(T[-1]), 4)],
        "samples_per_record": int(recs[0].values.size),
        "generation_s": round(t_gen, 3), "spectra_s": round(t_spec, 3),
        "selection_s": round(t_sel, 3), "total_s": round(t_spec + t_sel, 3),
        "goal_s": 5.0, "misfit": round(res.misfit, 5), "min_ratio": round(res.min_ratio, 4),
        "compliant": res.compliant,
        "scales": [round(float(s), 3) for s in res.scales],
    }
    print(json.dumps(out))
    print(f"spectra {t_spec:.2f} s + selection {t_sel:.2f} s = total {t_spec + t_sel:.2f} s "
          "(goal < 5 s)")


if __name__ == "__main__":
    main()
