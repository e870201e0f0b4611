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

The file is checked before trimesh reads it (trimesh drops or reshapes what it does not
understand): a vertex line without three numbers, a non-finite coordinate or one beyond
``COORD_LIMIT`` (no block is that large; such numbers overflow the mass properties), a face
of fewer than three vertices or one that indexes a vertex the file does not hold, a facet
of an ASCII STL without three vertices, a binary STL whose size disagrees with its
triangle count, are each refused in one line naming the file, the line (the triangle of a
binary STL, the vertex of a binary PLY) and the defect.

Only numpy and scipy are needed (trimesh's readers for STL, OBJ and PLY need numpy alone;
nothing here calls the functions of trimesh that need networkx).
"""

from __future__ import annotations

import math
import os

import numpy as np

from ..errors import ParameterError
from ..units import LENGTH

FORMATS = ("stl", "obj", "ply")
"""File types read (by their extension)."""

UNITS = ("m", "cm", "mm")
"""Length units of a mesh file (scans often come in mm)."""


COORD_LIMIT = 1e9
"""Largest coordinate magnitude accepted (in the file's units, and in m for arrays)."""


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
    check_file(path, ext)
    try:
        mesh = trimesh.load(path, file_type=ext, force="mesh", process=False)
    except Exception as exc:  # a reader's own error: one line, with the file's name
        raise ParameterError(f"cannot read mesh {path!r}: {type(exc).__name__}: {exc}"
                             ) from None
    vertices = np.asarray(getattr(mesh, "vertices", ()), dtype=np.float64)
    faces = np.asarray(getattr(mesh, "faces", ()), dtype=np.int64)
    if vertices.ndim != 2 or vertices.shape[1:] != (3,) or faces.ndim != 2 or \
            faces.shape[1:] != (3,):
        raise ParameterError(f"cannot read mesh {path!r}: not a triangle mesh (vertices "
                             f"{vertices.shape}, faces {faces.shape})")
    if len(faces) == 0:
        raise ParameterError(f"mesh {path!r} has no triangles")
    _check_arrays(vertices, faces, f"mesh {path!r}", COORD_LIMIT)
    return vertices * scale, faces


def _check_arrays(v: np.ndarray, f: np.ndarray, what: str, limit: float) -> None:
    """Refuse non-finite or too large coordinates and faces indexing missing vertices,
    naming the first vertex or face (1-based)."""
    bad = np.flatnonzero(~np.isfinite(v).all(axis=1))
    if bad.size:
        raise ParameterError(f"{what}: vertex {bad[0] + 1} has a non-finite coordinate "
                             f"{v[bad[0]].tolist()}")
    big = np.flatnonzero((np.abs(v) > limit).any(axis=1))
    if big.size:
        raise ParameterError(f"{what}: vertex {big[0] + 1} has a coordinate beyond "
                             f"{limit:g} in magnitude {v[big[0]].tolist()} (no block is that "
                             "large; such numbers overflow the mass properties)")
    out = np.flatnonzero(((f < 0) | (f >= len(v))).any(axis=1)) if len(f) else []
    if len(out):
        raise ParameterError(f"{what}: face {out[0] + 1} indexes a vertex outside "
                             f"1..{len(v)} ({(f[out[0]] + 1).tolist()}, 1-based)")


def _number(path, ln: int, tok: str, what: str) -> float:
    try:
        x = float(tok)
    except ValueError:
        raise ParameterError(f"mesh {path!r}, line {ln}: non-numeric {what} {tok!r}"
                             ) from None
    if not math.isfinite(x):
        raise ParameterError(f"mesh {path!r}, line {ln}: non-finite {what} {tok!r}")
    if abs(x) > COORD_LIMIT:
        raise ParameterError(f"mesh {path!r}, line {ln}: {what} {tok} beyond {COORD_LIMIT:g} "
                             "in magnitude (no block is that large; such numbers overflow the "
                             "mass properties)")
    return x


def _index(path, ln: int, tok: str, what: str) -> int:
    try:
        return int(tok)
    except ValueError:
        raise ParameterError(f"mesh {path!r}, line {ln}: {what} {tok!r} is not a whole "
                             "number") from None


def check_file(path, ext: str) -> None:
    """Refuse a malformed STL, OBJ or PLY file in one line naming the file, the line (or
    the binary record) and the defect (module doc); a file trimesh reads as it is passes."""
    with open(path, "rb") as fh:
        data = fh.read()
    if ext == "obj":
        _check_obj(path, data)
    elif ext == "stl":
        _check_stl(path, data)
    else:
        _check_ply(path, data)


def _lines(data: bytes) -> list[str]:
    return data.decode("utf-8", errors="replace").splitlines()


def _check_obj(path, data: bytes) -> None:
    lines = _lines(data)
    nv = sum(1 for ln in lines if ln.lstrip().startswith(("v ", "v\t")))
    seen = 0
    for i, line in enumerate(lines, 1):
        toks = line.split("#", 1)[0].split()
        if not toks:
            continue
        if toks[0] == "v":
            if len(toks) < 4:
                raise ParameterError(f"mesh {path!r}, line {i}: a vertex line with "
                                     f"{len(toks) - 1} coordinate(s); x y z needed")
            for t, axis in zip(toks[1:4], "xyz", strict=True):
                _number(path, i, t, f"{axis} coordinate")
            seen += 1
        elif toks[0] == "f":
            if len(toks) < 4:
                raise ParameterError(f"mesh {path!r}, line {i}: a face of {len(toks) - 1} "
                                     "vertex index(es); a face needs at least 3")
            for t in toks[1:]:
                k = _index(path, i, t.split("/", 1)[0], "vertex index")
                j = k if k > 0 else seen + k + 1  # negative: relative to the vertices so far
                if k == 0 or not 1 <= j <= nv:
                    raise ParameterError(f"mesh {path!r}, line {i}: vertex index {k} "
                                         f"outside the file's {nv} vertices (1..{nv}, or "
                                         "-1 back)")


_STL_RECORD = np.dtype([("normal", "<f4", (3,)), ("v", "<f4", (3, 3)), ("attr", "<u2")])


def _check_stl(path, data: bytes) -> None:
    if len(data) >= 84:
        n = int(np.frombuffer(data, "<u4", 1, 80)[0])
        if len(data) == 84 + 50 * n:  # binary
            tri = np.frombuffer(data, _STL_RECORD, n, 84)["v"].astype(np.float64)
            bad = np.flatnonzero(~(np.isfinite(tri) & (np.abs(tri) <= COORD_LIMIT))
                                 .reshape(n, 9).all(axis=1))
            if bad.size:
                k = int(bad[0])
                what = ("a non-finite coordinate" if not np.isfinite(tri[k]).all() else
                        f"a coordinate beyond {COORD_LIMIT:g} in magnitude (no block is that "
                        "large; such numbers overflow the mass properties)")
                raise ParameterError(f"mesh {path!r}: binary STL triangle {k + 1} (byte "
                                     f"{84 + 50 * k}) has {what}: {tri[k].tolist()}")
            return
        if not data.lstrip()[:5].lower() == b"solid":
            raise ParameterError(f"mesh {path!r}: a binary STL's header states {n} "
                                 f"triangles, i.e. 84 + 50 x {n} = {84 + 50 * n} bytes, but "
                                 f"the file has {len(data)} bytes (the file looks cut or "
                                 "corrupt)")
    elif not data.lstrip()[:5].lower() == b"solid":
        raise ParameterError(f"mesh {path!r}: {len(data)} bytes, neither an ASCII STL "
                             "('solid ...') nor a binary one (84 bytes at least)")
    corners, facet = 0, None
    for i, line in enumerate(_lines(data), 1):
        toks = line.split()
        if not toks:
            continue
        word = toks[0].lower()
        if word == "vertex":
            if len(toks) != 4:
                raise ParameterError(f"mesh {path!r}, line {i}: a vertex line with "
                                     f"{len(toks) - 1} coordinate(s); x y z needed")
            for t, axis in zip(toks[1:], "xyz", strict=True):
                _number(path, i, t, f"{axis} coordinate")
            corners += 1
        elif word == "facet":
            corners, facet = 0, i
        elif word == "endfacet":
            if corners != 3:
                raise ParameterError(f"mesh {path!r}, line {facet or i}: a facet with "
                                     f"{corners} vertices; a triangle needs 3")
            facet = None
    if facet is not None:
        raise ParameterError(f"mesh {path!r}, line {facet}: the facet is not closed "
                             "('endfacet' missing: the file looks cut)")


_PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2",
              "int16": "i2", "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4",
              "uint": "u4", "uint32": "u4", "float": "f4", "float32": "f4", "double": "f8",
              "float64": "f8"}


def _check_ply(path, data: bytes) -> None:
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise ParameterError(f"mesh {path!r}: not a PLY file (it must start with 'ply' and "
                             "have an 'end_header' line)")
    head = data[:end].decode("ascii", errors="replace").splitlines()
    fmt, elements = None, []  # [name, count, [(property, type or ('list', ctype, itype))]]
    for i, line in enumerate(head, 1):
        toks = line.split()
        if not toks:
            continue
        if toks[0] == "format" and len(toks) > 1:
            fmt = toks[1]
        elif toks[0] == "element":
            if len(toks) != 3 or not toks[2].isdigit():
                raise ParameterError(f"mesh {path!r}, line {i}: expected 'element <name> "
                                     f"<count>', got {line.strip()!r}")
            elements.append([toks[1], int(toks[2]), []])
        elif toks[0] == "property" and elements:
            if any(toks[-1] == q for q, _ in elements[-1][2]):
                raise ParameterError(f"mesh {path!r}, line {i}: the property {toks[-1]!r} of "
                                     f"the element {elements[-1][0]!r} is declared twice")
            elements[-1][2].append((toks[-1], tuple(toks[1:-1])))
    names = [e[0] for e in elements]
    if "vertex" not in names:
        raise ParameterError(f"mesh {path!r}: the PLY header declares no vertex element")
    nv = elements[names.index("vertex")][1]
    body = data[end + len(b"end_header"):]
    body = body[1:] if body.startswith(b"\n") else body[2:] if body.startswith(b"\r\n") \
        else body
    if fmt == "ascii":
        rows = _lines(body)
        first = len(head) + 2  # 1-based line of the first data row
        r = 0
        for name, count, props in elements:
            for _ in range(count):
                while r < len(rows) and not rows[r].split():
                    r += 1
                if r >= len(rows):
                    raise ParameterError(f"mesh {path!r}: the header declares {count} "
                                         f"{name} lines, the file ends before (the file "
                                         "looks cut)")
                _ply_row(path, first + r, rows[r].split(), name, props, nv)
                r += 1
    elif fmt in ("binary_little_endian", "binary_big_endian") and elements[0][0] == "vertex":
        props = elements[0][2]
        if all(len(t) == 1 and t[0] in _PLY_TYPES for _, t in props):
            order = "<" if fmt == "binary_little_endian" else ">"
            dt = np.dtype([(nm, order + _PLY_TYPES[t[0]]) for nm, t in props])
            if len(body) < dt.itemsize * nv:
                raise ParameterError(f"mesh {path!r}: the header declares {nv} vertices "
                                     f"({dt.itemsize * nv} bytes), the file ends before "
                                     "(the file looks cut)")
            rec = np.frombuffer(body, dt, nv)
            axes = [a for a in "xyz" if a in dt.names]
            if len(axes) < 3:
                raise ParameterError(f"mesh {path!r}: the PLY vertex element has no "
                                     "x, y and z properties")
            xyz = np.column_stack([rec[a].astype(np.float64) for a in axes])
            _check_arrays(xyz, np.empty((0, 3), np.int64), f"mesh {path!r}", COORD_LIMIT)


def _ply_row(path, ln: int, toks: list[str], name: str, props: list, nv: int) -> None:
    """One row of an ASCII PLY element: the vertex's x y z, a face's index list."""
    k = 0
    for prop, typ in props:
        if k >= len(toks):
            raise ParameterError(f"mesh {path!r}, line {ln}: a {name} line with {len(toks)} "
                                 f"value(s); the header declares {len(props)} properties")
        if typ and typ[0] == "list":
            c = _index(path, ln, toks[k], "list count")
            vals = toks[k + 1:k + 1 + c]
            if len(vals) < c:
                raise ParameterError(f"mesh {path!r}, line {ln}: a list of {c} values holds "
                                     f"{len(vals)}")
            if name == "face" and prop in ("vertex_indices", "vertex_index"):
                if c < 3:
                    raise ParameterError(f"mesh {path!r}, line {ln}: a face of {c} vertex "
                                         "index(es); a face needs at least 3")
                for t in vals:
                    j = _index(path, ln, t, "vertex index")
                    if not 0 <= j < nv:
                        raise ParameterError(f"mesh {path!r}, line {ln}: vertex index {j} "
                                             f"outside the file's {nv} vertices (0..{nv - 1})")
            k += 1 + c
        else:
            if name == "vertex" and prop in ("x", "y", "z"):
                _number(path, ln, toks[k], f"{prop} coordinate")
            k += 1
    if k != len(toks):
        raise ParameterError(f"mesh {path!r}, line {ln}: a {name} line with {len(toks)} "
                             f"values; the header's properties take {k}")


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
    _check_arrays(v, f, "the mesh", COORD_LIMIT)
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
