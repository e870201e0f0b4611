"""Write the example mesh ``statue.ply``: a synthetic statue-like body (no plinth).

A loft of stacked elliptical rings (64 points each) through key sections interpolated
with monotone cubics (PCHIP) in height: an elliptic base 0.45 m x 0.35 m with a vertical
rim 8 cm high, a robe tapering up to the waist, a chest and shoulders twisted by 20 deg,
a neck and a head, 1.62 m in all. The upper sections lean forward (+x, 7 cm at the head)
and a little to the side (+y), so the centre of mass is off the footprint's centre and
the weakest direction is not an axis of the footprint. The bottom is one flat ellipse (a
fan from its centre) on z = 0; the top closes on one apex vertex. About 2,700 vertices
and 5,400 triangles; watertight, outward normals.

Run ``python -m rocking.shapes.data.make_example`` (or this file) to rewrite it.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

# key sections: height (m), semi-axes along x and y (m), centre (x, y) (m), twist (deg)
KEYS = np.array([
    # z     a      b      cx     cy     twist
    [0.00, 0.225, 0.175, 0.000, 0.000, 0.0],
    [0.08, 0.225, 0.175, 0.000, 0.000, 0.0],
    [0.12, 0.190, 0.150, 0.010, 0.000, 0.0],
    [0.50, 0.170, 0.125, 0.030, 0.008, 3.0],
    [0.90, 0.150, 0.100, 0.045, 0.015, 8.0],
    [1.18, 0.185, 0.110, 0.055, 0.020, 15.0],
    [1.32, 0.205, 0.100, 0.060, 0.022, 20.0],
    [1.37, 0.070, 0.060, 0.065, 0.022, 20.0],
    [1.42, 0.055, 0.050, 0.068, 0.022, 20.0],
    [1.46, 0.090, 0.095, 0.070, 0.020, 20.0],
    [1.52, 0.100, 0.105, 0.072, 0.020, 20.0],
    [1.58, 0.085, 0.090, 0.072, 0.020, 20.0],
    [1.61, 0.045, 0.050, 0.072, 0.020, 20.0],
])
APEX = (0.072, 0.020, 1.62)
N_RING = 64
N_LEVELS = 42


def statue(n_ring: int = N_RING, n_levels: int = N_LEVELS) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (m) and triangles (outward normals) of the statue."""
    from scipy.interpolate import PchipInterpolator

    zk = KEYS[:, 0]
    # levels: the two base rings exactly, then evenly spaced up to the last key section
    z = np.concatenate([[0.0, 0.08], np.linspace(0.08, zk[-1], n_levels - 1)[1:]])
    cols = [PchipInterpolator(zk, KEYS[:, j])(z) for j in range(1, 6)]
    a, b, cx, cy, tw = cols
    t = np.linspace(0.0, 2.0 * np.pi, n_ring, endpoint=False)
    rings = []
    for i in range(len(z)):
        x, y = a[i] * np.cos(t), b[i] * np.sin(t)
        c, s = np.cos(np.radians(tw[i])), np.sin(np.radians(tw[i]))
        rings.append(np.column_stack([cx[i] + c * x - s * y, cy[i] + s * x + c * y,
                                      np.full(n_ring, z[i])]))
    verts = np.vstack(rings + [[[0.0, 0.0, 0.0]], [list(APEX)]])
    bottom, top = len(verts) - 2, len(verts) - 1
    faces = []
    j = np.arange(n_ring)
    k = (j + 1) % n_ring
    for i in range(len(z) - 1):  # side walls, counter-clockwise seen from outside
        lo, hi = i * n_ring, (i + 1) * n_ring
        faces.append(np.column_stack([lo + j, lo + k, hi + k]))
        faces.append(np.column_stack([lo + j, hi + k, hi + j]))
    faces.append(np.column_stack([np.full(n_ring, bottom), k, j]))  # bottom, facing down
    last = (len(z) - 1) * n_ring
    faces.append(np.column_stack([last + j, last + k, np.full(n_ring, top)]))
    return verts, np.vstack(faces)


def write(path: Path | None = None) -> Path:
    """Write the statue as a binary PLY (float32 vertices) and return its path."""
    import trimesh

    path = Path(path) if path is not None else Path(__file__).resolve().parent / "statue.ply"
    v, f = statue()
    mesh = trimesh.Trimesh(v.astype(np.float32).astype(np.float64), f, process=False)
    path.write_bytes(mesh.export(file_type="ply", encoding="binary"))
    return path


if __name__ == "__main__":
    print(write())
