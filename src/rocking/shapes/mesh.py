"""Reading, welding and validating a triangle mesh (STL, OBJ, PLY through trimesh).

A mesh is trusted only if it bounds a solid: the mass properties by the divergence
theorem (:mod:`rocking.shapes.mass`) are those of the enclosed volume only when the surface
is closed and consistently oriented (trimesh's maintainers warn that meshes in the wild
rarely are). :func:`check_mesh` therefore checks, after welding the vertices:

* **watertight**: every edge is shared by exactly two faces (an edge used once is an open
  edge, a hole; used three times or more, a non-manifold edge);
* **consistent winding**: the two faces sharing an edge traverse it in opposite
  directions (else the normals flip from face to face);
* **positive volume**: with outward normals the signed volume is positive; a negative one
  means inverted normals (the faces are wound clockwise seen from outside).

The first defect found is reported in one line (:class:`rocking.errors.ParameterError`),
e.g. ``mesh is not watertight: 12 open edges``. With ``repair="hull"`` the convex hull of
the vertices is used instead (:func:`convex_hull`), with a warning stating the volume it
adds. Self-intersections are not checked (a self-intersecting closed surface counts the
overlap twice): this is the scan software's job.

Welding merges the vertices closer than ``weld`` (m; default 1e-9 of the bounding box's
diagonal; STL files store every triangle's corners separately), drops the faces that
welding made degenerate (two equal corners) and the unused vertices. A mesh of several
closed parts is accepted as one rigid body, with a warning (a hollow body's inner surface,
wound inwards, is one of them; floating debris of a scan is another).

Only numpy and scipy are needed (trimesh's readers for STL, OBJ and PLY need numpy alone;
nothing here calls the functions of trimesh that need networkx).
"""

from __future__ import annotations

import os

import numpy as np

from ..errors import ParameterError
from ..units import LENGTH

FORMATS = ("stl", "obj", "ply")
"""File types read (by their extension)."""

UNITS = ("m", "cm", "mm")
"""Length units of a mesh file (scans often come in mm)."""


def unit_scale(units) -> float:
    """The factor (m per file unit) of ``units`` ("m", "cm" or "mm")."""
    if not isinstance(units, str) or units.strip().lower() not in UNITS:
        raise ParameterError(f"units must be one of {', '.join(UNITS)}, got {units!r}")
    return LENGTH[units.strip().lower()]


def read_mesh(path, units="m") -> tuple[np.ndarray, np.ndarray]:
    """Vertices (n, 3) in m and faces (m, 3) of the triangle mesh in ``path`` (STL, OBJ or
    PLY; several objects in one file are concatenated), not yet welded or checked."""
    import trimesh  # ~0.3 s to import: only when a mesh is read

    scale = unit_scale(units)
    path = os.fspath(path)
    ext = os.path.splitext(path)[1].lower().lstrip(".")
    if ext not in FORMATS:
        raise ParameterError(f"mesh file must be .stl, .obj or .ply, got {path!r}")
    if not os.path.isfile(path):
        raise ParameterError(f"mesh file {path!r} does not exist")
    try:
        mesh = trimesh.load(path, file_type=ext, force="mesh", process=False)
    except Exception as exc:  # a reader's own error: one line, with the file's name
        raise ParameterError(f"cannot read mesh {path!r}: {type(exc).__name__}: {exc}"
                             ) from None
    vertices = np.asarray(getattr(mesh, "vertices", ()), dtype=np.float64).reshape(-1, 3)
    faces = np.asarray(getattr(mesh, "faces", ()), dtype=np.int64).reshape(-1, 3)
    if len(faces) == 0:
        raise ParameterError(f"mesh {path!r} has no triangles")
    return vertices * scale, faces


def as_arrays(vertices, faces) -> tuple[np.ndarray, np.ndarray]:
    """``vertices`` (n, 3) finite floats and ``faces`` (m, 3) valid indices, checked."""
    try:
        v = np.array(vertices, dtype=np.float64).reshape(-1, 3)
        f = np.array(faces, dtype=np.int64).reshape(-1, 3)
    except (TypeError, ValueError):
        raise ParameterError("a mesh needs vertices (n, 3) and triangular faces (m, 3)"
                             ) from None
    if len(f) == 0:
        raise ParameterError("the mesh has no triangles")
    if not np.all(np.isfinite(v)):
        raise ParameterError("the mesh has non-finite vertex coordinates")
    if f.min() < 0 or f.max() >= len(v):
        raise ParameterError(f"the mesh's faces index vertices outside 0..{len(v) - 1}")
    return v, f


def weld(vertices, faces, tol=None) -> tuple[np.ndarray, np.ndarray]:
    """Merge the vertices closer than ``tol`` (m; None: 1e-9 of the bounding box's
    diagonal), drop the degenerate faces and the unused vertices."""
    v, f = as_arrays(vertices, faces)
    diag = float(np.linalg.norm(np.ptp(v, axis=0))) if len(v) else 0.0
    if tol is None:
        tol = 1e-9 * diag
    # exact duplicates first (a lexicographic sort; -0.0 + 0.0 is 0.0), then the near ones
    w = v + 0.0
    order = np.lexsort(w.T[::-1])
    srt = w[order]
    new = np.concatenate([[True], np.any(srt[1:] != srt[:-1], axis=1)])
    inv = np.empty(len(w), dtype=np.int64)
    inv[order] = np.cumsum(new) - 1
    uniq = srt[new]
    if tol > 0.0 and len(uniq) > 1:
        from scipy.sparse import coo_matrix
        from scipy.sparse.csgraph import connected_components
        from scipy.spatial import cKDTree

        pairs = cKDTree(uniq).query_pairs(r=tol, output_type="ndarray")
        if len(pairs):
            n = len(uniq)
            graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
            _, label = connected_components(graph, directed=False)
            # one representative (the first) per group
            first = np.full(label.max() + 1, -1, dtype=np.int64)
            order = np.arange(n)[::-1]
            first[label[order]] = order
            uniq = uniq[first]
            inv = label[inv]
    f = inv[f]
    keep = (f[:, 0] != f[:, 1]) & (f[:, 1] != f[:, 2]) & (f[:, 2] != f[:, 0])
    f = f[keep]
    used = np.unique(f)
    remap = np.full(len(uniq), -1, dtype=np.int64)
    remap[used] = np.arange(len(used))
    return uniq[used], remap[f]


def edge_defects(faces) -> dict:
    """Counts of the edge defects of a triangle mesh: ``open`` (edges used by one face),
    ``non_manifold`` (by three or more) and ``inconsistent`` (by two faces that traverse
    it in the same direction)."""
    f = np.asarray(faces, dtype=np.int64)
    a = f.reshape(-1)
    b = np.roll(f, -1, axis=1).reshape(-1)  # directed edges (f0 f1), (f1 f2), (f2 f0)
    n = int(f.max()) + 1 if len(f) else 1
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    key = lo * n + hi
    uniq, inv, count = np.unique(key, return_inverse=True, return_counts=True)
    forward = np.bincount(inv.reshape(-1), weights=(a < b).astype(np.float64),
                          minlength=len(uniq))
    two = count == 2
    return {"edges": int(len(uniq)),
            "open": int(np.sum(count == 1)),
            "non_manifold": int(np.sum(count > 2)),
            "inconsistent": int(np.sum(two & (forward != 1)))}


def count_parts(faces) -> int:
    """The number of connected parts of a mesh (faces linked through shared vertices)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    f = np.asarray(faces, dtype=np.int64)
    n = int(f.max()) + 1
    a = f.reshape(-1)
    b = np.roll(f, -1, axis=1).reshape(-1)
    graph = coo_matrix((np.ones(len(a), dtype=np.int8), (a, b)), shape=(n, n))
    return int(connected_components(graph, directed=False)[0])


def signed_volume(vertices, faces) -> float:
    """The signed volume enclosed by the triangles (divergence theorem; positive for
    outward normals), about the vertices' mean for accuracy."""
    v = np.asarray(vertices, dtype=np.float64)
    v = v - v.mean(axis=0)
    t = v[np.asarray(faces)]
    return float(np.sum(np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])))) / 6.0


def check_mesh(vertices, faces) -> str | None:
    """The first defect of a welded mesh as one line, or None if it bounds a solid."""
    d = edge_defects(faces)
    if d["open"] or d["non_manifold"]:
        parts = []
        if d["open"]:
            parts.append(f"{d['open']} open edge{'s' if d['open'] != 1 else ''}")
        if d["non_manifold"]:
            parts.append(f"{d['non_manifold']} edge{'s' if d['non_manifold'] != 1 else ''} "
                         "shared by more than two faces")
        return "mesh is not watertight: " + ", ".join(parts)
    if d["inconsistent"]:
        return (f"mesh winding is inconsistent: {d['inconsistent']} edge"
                f"{'s' if d['inconsistent'] != 1 else ''} traversed in the same direction "
                "by both of their faces")
    vol = signed_volume(vertices, faces)
    scale = float(np.max(np.ptp(vertices, axis=0))) ** 3
    if not vol > 1e-12 * scale:
        if vol < -1e-12 * scale:
            return (f"inverted normals: volume < 0 ({vol:.6g} m^3; the faces are wound "
                    "clockwise seen from outside)")
        return "mesh encloses no volume"
    return None


def convex_hull(vertices) -> tuple[np.ndarray, np.ndarray]:
    """The convex hull of ``vertices`` as a closed mesh with outward normals (qhull)."""
    from scipy.spatial import ConvexHull, QhullError

    v = np.asarray(vertices, dtype=np.float64)
    c = v.mean(axis=0)
    try:
        hull = ConvexHull(v - c)
    except (QhullError, ValueError):
        raise ParameterError("the mesh's convex hull has no volume (flat or degenerate "
                             "mesh)") from None
    used = hull.vertices
    remap = np.full(len(v), -1, dtype=np.int64)
    remap[used] = np.arange(len(used))
    f = hull.simplices.copy()
    t = v[f] - c
    normal = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    flip = np.einsum("ij,ij->i", normal, hull.equations[:, :3]) < 0.0
    f[flip] = f[flip][:, ::-1]
    return v[used], remap[f]


def validated(vertices, faces, *, repair=None, weld_tol=None, warn=None
              ) -> tuple[np.ndarray, np.ndarray]:
    """The welded mesh if it bounds a solid; else (``repair="hull"``) its convex hull,
    after ``warn(message)`` with the defect and the volume added; else a ParameterError
    naming the defect."""
    if repair not in (None, "hull"):
        raise ParameterError(f"repair must be None or 'hull', got {repair!r}")
    v, f = weld(vertices, faces, weld_tol)
    if len(f) < 4:
        defect = f"mesh has {len(f)} non-degenerate triangles (a solid needs at least 4)"
    else:
        defect = check_mesh(v, f)
    if defect is None:
        return v, f
    if repair is None:
        raise ParameterError(defect + " (repair='hull' uses the convex hull instead)")
    hv, hf = convex_hull(v)
    v_hull = signed_volume(hv, hf)
    v_mesh = abs(signed_volume(v, f)) if len(f) else 0.0
    added = v_hull - v_mesh
    msg = (f"{defect}; repair='hull': using the convex hull, which adds {added:.4g} m^3, "
           f"{100.0 * added / v_hull:.3g} % of the hull's volume {v_hull:.4g} m^3 (the "
           "defective mesh's own volume, taken as if closed, is "
           f"{v_mesh:.4g} m^3)")
    if warn is not None:
        warn(msg)
    return hv, hf


def size_of(vertices) -> float:
    """The bounding box's largest side (m)."""
    return float(np.max(np.ptp(np.asarray(vertices), axis=0)))


__all__ = ["FORMATS", "UNITS", "as_arrays", "check_mesh", "convex_hull", "count_parts",
           "edge_defects", "read_mesh", "signed_volume", "size_of", "unit_scale", "validated",
           "weld"]
