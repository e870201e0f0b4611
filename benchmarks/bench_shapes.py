"""Benchmark: a 200,000-triangle mesh, loaded and tabulated in 360 directions.

The example statue (:mod:`rocking.shapes.data.make_example`) is regenerated finely
(``--triangles``, 200,000: 400 points per ring) and written to a temporary binary STL
(float32, every triangle's corners stored apart, as scanners write them) and a binary
PLY. Timed, each the median of ``--repeat`` runs after a first (import-laden) one:

* :func:`rocking.shapes.load_shape` in full (read, weld, validate, mass properties,
  support), and its stages apart (:func:`rocking.shapes.mesh.read_mesh`,
  :func:`~rocking.shapes.mesh.weld`, :func:`~rocking.shapes.mesh.check_mesh`,
  :func:`~rocking.shapes.mass.volume_properties`);
* :func:`rocking.shapes.directional_parameters` for ``--directions`` (360) directions, and
  :meth:`rocking.shapes.Shape.polygon` for one direction.

Goal (issue 20): loading and the table under 2 s in all. Prints one JSON object of the
times (s). ``--quick``: 20,000 triangles, one repeat. Usage::

    .venv/bin/python benchmarks/bench_shapes.py [--triangles 200000] [--directions 360]
        [--repeat 3] [--quick]
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import tempfile
import time

import numpy as np

QUICK = {"triangles": 20_000, "repeat": 1}


def timed(fn, repeat: int):
    t0 = time.perf_counter()
    out = fn()
    first = time.perf_counter() - t0
    warm = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        warm.append(time.perf_counter() - t0)
    return out, first, statistics.median(warm)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--triangles", type=int, default=200_000)
    ap.add_argument("--directions", type=int, default=360)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help=f"tiny sizes (smoke check): {QUICK}")
    if ap.parse_known_args(argv)[0].quick:
        ap.set_defaults(**QUICK)
    args = ap.parse_args(argv)

    import trimesh

    from rocking.shapes import directional_parameters, load_shape
    from rocking.shapes.data.make_example import statue
    from rocking.shapes.mass import volume_properties
    from rocking.shapes.mesh import check_mesh, read_mesh, weld

    # 2 n_ring (n_levels - 1) walls + 2 n_ring caps = 2 n_ring n_levels triangles
    n_ring = max(16, int(round(math.sqrt(args.triangles / 2.0 * 400 / 250))))
    n_levels = max(4, int(round(args.triangles / (2.0 * n_ring))))
    v, f = statue(n_ring, n_levels)
    result = {"triangles": int(len(f)), "vertices": int(len(v)),
              "directions": args.directions, "repeat": args.repeat}
    with tempfile.TemporaryDirectory(prefix="bench-shapes-") as tmp:
        mesh = trimesh.Trimesh(v, f, process=False)
        paths = {"stl": os.path.join(tmp, "statue.stl"), "ply": os.path.join(tmp, "statue.ply")}
        mesh.export(paths["stl"])
        mesh.export(paths["ply"])
        result["stl_bytes"] = os.path.getsize(paths["stl"])
        for ext, path in paths.items():
            shape, first, warm = timed(lambda p=path: load_shape(p, density=2600.0),
                                       args.repeat)
            result[f"load_{ext}_first"], result[f"load_{ext}"] = first, warm
        (rv, rf), _, t_read = timed(lambda: read_mesh(paths["stl"]), args.repeat)
        (wv, wf), _, t_weld = timed(lambda: weld(rv, rf), args.repeat)
        _, _, t_check = timed(lambda: check_mesh(wv, wf), args.repeat)
        _, _, t_mass = timed(lambda: volume_properties(wv, wf), args.repeat)
        result.update(stl_read=t_read, stl_weld=t_weld, check=t_check, mass=t_mass)
        table, first, warm = timed(lambda: directional_parameters(shape, args.directions),
                                   args.repeat)
        result["table_first"], result["table"] = first, warm
        _, first, warm = timed(lambda: shape.polygon(0.3), args.repeat)
        result["polygon_first"], result["polygon"] = first, warm
        result["total_stl"] = result["load_stl"] + result["table"]
        result["weakest_phi_deg"] = float(table["phi_deg"][np.argmin(table["uplift_min"])])
    print(json.dumps(result, indent=1))
    print(f"total (goal < 2 s): load {result['load_stl']:.3f} s + table "
          f"{result['table']:.4f} s = {result['total_stl']:.3f} s for "
          f"{result['triangles']} triangles (STL) and {args.directions} directions")


if __name__ == "__main__":
    main()
