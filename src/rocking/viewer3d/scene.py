"""What the 3-D views show, as arrays: the body's mesh, and its pose at chosen times.

A response of a 3-D model (``rigid3d``) holds the state ``x, y, z`` (the centre of mass
relative to the ground, m) and ``q0..q3`` (the quaternion, body to ground) in the ground's
frame (it translates with the ground, it never rotates). A point ``r`` of the body (its
coordinates relative to the centre of mass in the body's frame: the shape's
``local_vertices`` less ``(0, 0, h)``) is at ``x + R(q) r``.

The ground's own displacement is the double integral of its acceleration (the model's
:meth:`~rocking.models.base.Model.motion_spec`, read by
:func:`rocking.motions._kernel.ground_acc3`). The motion fixes the acceleration only: the
ground's initial velocity changes nothing in the body's motion relative to it (Galilean
invariance), and it is taken here so that the ground's mean velocity over the motion's
duration is zero (no drift: a :class:`~rocking.motions.Sine` then moves the ground by
exactly its displacement amplitude).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from ..errors import ParameterError

POSE_STATES = ("x", "y", "z", "q0", "q1", "q2", "q3")
"""The states a response needs for a 3-D view (the pose)."""


@dataclass(frozen=True)
class Scene:
    """A response's body and poses, ready to draw (:func:`scene`).

    ``vertices`` (n, 3) the body's vertices relative to its centre of mass in the body's
    frame (m), ``faces`` (k, 3), ``t`` (s), ``position`` (m, ground frame) and
    ``quaternion`` (q0..q3) per sample, ``ground`` the ground's displacement (m) per
    sample or None, ``name`` the body's name.

    Examples
    --------
    A box at rest: its lowest vertex is on the ground.

    >>> from rocking.viewer3d import scene
    >>> import rocking
    >>> from rocking.shapes import Shape
    >>> r = rocking.simulate(Shape.box(0.4, 0.4, 1.2, mass=400.0),
    ...                      rocking.motions.Sine(freq=2.0, amplitude=0.001, duration=0.1),
    ...                      model="rigid3d", duration=0.1)
    >>> s = scene(r)
    >>> s.vertices.shape, s.position[0].tolist(), s.quaternion[0].tolist()
    ((8, 3), [0.0, 0.0, 0.6], [1.0, 0.0, 0.0, 0.0])
    >>> float(s.position[0, 2] + s.vertices[:, 2].min())
    0.0
    """

    vertices: np.ndarray
    faces: np.ndarray
    t: np.ndarray
    position: np.ndarray
    quaternion: np.ndarray
    ground: np.ndarray | None
    name: str = ""

    def at(self, times) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
        """Position, quaternion and ground displacement at ``times`` (s): linear in
        position, normalised linear in the quaternion (the samples are close: ``dt_out``).

        Examples
        --------
        >>> from rocking.viewer3d import Scene
        >>> import numpy as np
        >>> s = Scene(np.zeros((3, 3)), np.array([[0, 1, 2]]), np.array([0.0, 1.0]),
        ...           np.array([[0, 0, 1.0], [2, 0, 1.0]]),
        ...           np.array([[1.0, 0, 0, 0], [0.0, 0, 0, 1]]), None)
        >>> pos, q, g = s.at([0.5])
        >>> pos.tolist(), np.round(q, 6).tolist(), g
        ([[1.0, 0.0, 1.0]], [[0.707107, 0.0, 0.0, 0.707107]], None)
        """
        times = np.asarray(times, dtype=np.float64)
        pos = np.column_stack([np.interp(times, self.t, self.position[:, j]) for j in range(3)])
        q = np.column_stack([np.interp(times, self.t, self.quaternion[:, j]) for j in range(4)])
        q /= np.linalg.norm(q, axis=1)[:, None]
        g = None
        if self.ground is not None:
            g = np.column_stack([np.interp(times, self.t, self.ground[:, j]) for j in range(3)])
        return pos, q, g


def rotation_matrices(q) -> np.ndarray:
    """The rotation matrices (n, 3, 3) of unit quaternions ``q0..q3`` (n, 4), scalar first.

    Examples
    --------
    >>> from rocking.viewer3d import rotation_matrices
    >>> import math
    >>> R = rotation_matrices([[math.cos(math.pi / 4), 0, 0, math.sin(math.pi / 4)]])
    >>> np.round(R[0] @ [1.0, 0, 0], 12).tolist()  # a quarter turn about z
    [0.0, 1.0, 0.0]
    """
    q = np.atleast_2d(np.asarray(q, dtype=np.float64))
    w, x, y, z = q.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], axis=1)


def tilt(q) -> np.ndarray:
    """The angle (rad) of the body's initial up axis from the vertical, per quaternion:
    ``R_zz = cos(tilt) = 1 - 2 (q1^2 + q2^2)``, so ``tilt = 2 asin(sqrt(q1^2 + q2^2))``
    (well conditioned near 0).

    Examples
    --------
    >>> from rocking.viewer3d import tilt
    >>> import math
    >>> round(float(tilt([[math.cos(0.15), math.sin(0.15), 0, 0]])[0]), 12)  # 0.3 rad about x
    0.3
    """
    q = np.atleast_2d(np.asarray(q, dtype=np.float64))
    q = q / np.linalg.norm(q, axis=1)[:, None]
    return 2.0 * np.arcsin(np.minimum(1.0, np.hypot(q[:, 1], q[:, 2])))


def decimate(vertices, faces, max_faces: int) -> tuple[np.ndarray, np.ndarray]:
    """A mesh of at most ``max_faces`` triangles for display, by vertex clustering: the
    vertices are merged per cell of a cubic grid (each cell's mean), the triangles that
    collapse are dropped; the coarsest grid that keeps at most ``max_faces`` is found by
    bisection on the number of cells. For display only: the mass properties and the
    contacts come from the full mesh.

    Examples
    --------
    >>> from rocking.viewer3d import decimate
    >>> import trimesh
    >>> m = trimesh.creation.icosphere(subdivisions=4)  # 5120 triangles
    >>> v, f = decimate(m.vertices, m.faces, 500)
    >>> len(f) <= 500, len(f) > 100
    (True, True)
    """
    v = np.asarray(vertices, dtype=np.float64)
    f = np.asarray(faces, dtype=np.int64)
    if max_faces < 4:
        raise ParameterError(f"max_faces must be at least 4, got {max_faces}")
    if len(f) <= max_faces:
        return v, f
    lo, span = v.min(axis=0), np.ptp(v, axis=0).max()

    def cluster(n):
        cell = span / n
        keys = np.floor((v - lo) / cell).astype(np.int64)
        _, inv = np.unique(keys, axis=0, return_inverse=True)
        inv = inv.ravel()
        nv = inv.max() + 1
        cnt = np.bincount(inv, minlength=nv)
        vv = np.column_stack([np.bincount(inv, v[:, j], nv) / cnt for j in range(3)])
        ff = inv[f]
        keep = (ff[:, 0] != ff[:, 1]) & (ff[:, 1] != ff[:, 2]) & (ff[:, 0] != ff[:, 2])
        ff = ff[keep]
        _, first = np.unique(np.sort(ff, axis=1), axis=0, return_index=True)
        ff = ff[np.sort(first)]
        used = np.unique(ff)
        remap = np.full(nv, -1)
        remap[used] = np.arange(len(used))
        return vv[used], remap[ff]

    a, b = 2, 2  # the number of cells along the largest extent: grow b until too fine
    best = cluster(a)
    while True:
        b *= 2
        out = cluster(b)
        if len(out[1]) > max_faces or b > 4096:
            break
        a, best = b, out
    while b - a > 1:
        m = (a + b) // 2
        out = cluster(m)
        if len(out[1]) <= max_faces:
            a, best = m, out
        else:
            b = m
    return best


def grid_spacing(width: float, lines: int) -> float:
    """A round spacing (1, 2 or 5 times a power of ten, m) giving about ``lines`` grid
    lines across ``width`` (m).

    Examples
    --------
    >>> from rocking.viewer3d.scene import grid_spacing
    >>> grid_spacing(5.4, 12), grid_spacing(2.0, 8)
    (0.5, 0.2)
    """
    raw = width / lines
    p = 10.0 ** math.floor(math.log10(raw))
    return min((m * p for m in (1.0, 2.0, 5.0, 10.0)), key=lambda s: abs(s - raw))


def resolve_shape(response, shape=None):
    """The body of ``response``: ``shape`` if given, else the response's block (a
    rectangular :class:`~rocking.Block` is taken as the model takes it: its box)."""
    from ..shapes import Shape

    body = shape if shape is not None else response.block
    if isinstance(body, Shape):
        return body
    if body is None:
        raise ParameterError("shape: the response holds no body; pass shape=")
    from ..models import MODELS

    cls = MODELS.get(response.model)
    if cls is None:
        raise ParameterError(f"shape: {type(body).__name__} is not a rocking.shapes.Shape")
    body = cls.check_block(body)
    if not isinstance(body, Shape):
        raise ParameterError(f"shape: model {response.model!r} does not take its block as a "
                             f"rocking.shapes.Shape; pass shape=")
    return body


def pose_columns(response) -> np.ndarray:
    """The columns of ``response.states`` holding ``x, y, z, q0..q3``; ParameterError
    naming the response when it has none (a planar model, or no histories)."""
    names = tuple(getattr(response, "state_names", ()) or ())
    states = getattr(response, "states", None)
    missing = [n for n in POSE_STATES if n not in names]
    if missing or states is None or len(states) == 0:
        raise ParameterError(
            f"response: a 3-D view needs the states {', '.join(POSE_STATES)} (model "
            f"'rigid3d', with histories); this response of model {response.model!r} has "
            f"{', '.join(names) or 'no states'}")
    return np.array([names.index(n) for n in POSE_STATES])


def ground_displacement(response, shape, t) -> np.ndarray:
    """The ground's displacement (m, (n, 3): x, y in the ground frame's axes, z up) at
    the times ``t`` (s), from the model's three-component spec of the response's motion
    (module docstring: zero mean velocity over the motion's duration)."""
    from ..models import MODELS
    from ..motions._kernel import ground_acc3

    t = np.asarray(t, dtype=np.float64)
    if response.motion is None or len(t) == 0:
        return np.zeros((len(t), 3))
    cls = MODELS.get(response.model)
    if cls is None or not hasattr(cls, "motion_spec"):
        raise ParameterError(f"ground: model {response.model!r} is not registered")
    info = response.info or {}
    names = {f.name for f in dataclasses.fields(cls.Options)}
    model = cls.from_kwargs(shape, **{k: v for k, v in info.items() if k in names})
    kind, prm, samples = model.motion_spec(response.motion)
    # a grid fine enough for the motion (its own scan step) and the output
    try:
        dt_motion = float(response.motion.scan_step)
    except (AttributeError, NotImplementedError):
        dt_motion = math.inf
    dt_out = float(np.min(np.diff(t))) if len(t) > 1 else 1.0
    dt = min(dt_out / 4.0, dt_motion / 2.0) if math.isfinite(dt_motion) else dt_out / 4.0
    # over the whole motion, even where the run stopped before its end (an overturn)
    dur = float(getattr(response.motion, "duration", 0.0) or 0.0)
    if not (math.isfinite(dur) and dur > 0.0):
        dur = float(t[-1])
    t_last = max(float(t[-1]), dur)
    n = max(2, int(math.ceil(t_last / max(dt, 1e-6))) + 1)
    tt = np.linspace(0.0, t_last, n)
    a = np.array([ground_acc3(kind, prm, samples, float(s)) for s in tt])
    v = np.concatenate([np.zeros((1, 3)),
                        np.cumsum(0.5 * (a[1:] + a[:-1]) * np.diff(tt)[:, None], axis=0)])
    d = np.concatenate([np.zeros((1, 3)),
                        np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(tt)[:, None], axis=0)])
    # the initial velocity v0 of zero mean velocity over the motion's duration T:
    # d(T) + v0 T = 0
    if dur > 0.0:
        d -= np.outer(tt, [np.interp(dur, tt, d[:, j]) / dur for j in range(3)])
    return np.column_stack([np.interp(t, tt, d[:, j]) for j in range(3)])


def scene(response, shape=None, *, ground: bool = False, max_faces: int | None = None
          ) -> Scene:
    """The :class:`Scene` of a 3-D ``response`` (``rigid3d``): its body (``shape``, or the
    response's; decimated to ``max_faces`` triangles if given) and poses, and the ground's
    displacement if ``ground``.

    Examples
    --------
    The ground's displacement under a :class:`~rocking.motions.Sine` along the body's x
    axis is its displacement amplitude times ``sin(2 pi f t)``:

    >>> from rocking.viewer3d import scene
    >>> import math
    >>> import rocking
    >>> from rocking.shapes import Shape
    >>> r = rocking.simulate(Shape.box(0.4, 0.4, 1.2, mass=400.0),
    ...                      rocking.motions.Sine(freq=2.0, amplitude=0.001, duration=0.5),
    ...                      model="rigid3d", duration=0.5)
    >>> s = scene(r, ground=True)
    >>> i = int(round(0.125 / (r.t[1] - r.t[0])))  # t = 1/(4 f)
    >>> round(float(s.ground[i, 0]), 6), round(float(s.ground[i, 1]), 9)
    (0.001, 0.0)
    """
    cols = pose_columns(response)
    body = resolve_shape(response, shape)
    states = np.asarray(response.states, dtype=np.float64)
    t = np.asarray(response.t, dtype=np.float64)
    pose = states[:, cols]
    verts = np.asarray(body.local_vertices, dtype=np.float64) - np.array([0.0, 0.0, body.h])
    faces = np.asarray(body.faces, dtype=np.int64)
    if max_faces is not None:
        verts, faces = decimate(verts, faces, int(max_faces))
    g = ground_displacement(response, body, t) if ground else None
    q = pose[:, 3:7] / np.linalg.norm(pose[:, 3:7], axis=1)[:, None]
    return Scene(verts, faces, t, pose[:, :3].copy(), q, g, getattr(body, "name", ""))
