"""An animation (GIF, or MP4 where ffmpeg exists) of a 3-D response: the body's mesh
moving over the ground plane, drawn with matplotlib (Agg, no display needed)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from .._validate import positive
from ..errors import ParameterError
from .scene import grid_spacing, rotation_matrices, scene, tilt

LIGHT = np.array([0.35, -0.55, 0.76])
"""The direction towards the light (ground frame) of the flat shading."""
BODY_RGB = np.array([0.78, 0.62, 0.45])
"""The body's colour (a stone)."""


def frame_times(t_end: float, fps: float, speed: float) -> np.ndarray:
    """The response times (s) of an animation's frames: frame ``k`` shows
    ``t = k speed / fps``, up to ``t_end``.

    Examples
    --------
    >>> from rocking.viewer3d import frame_times
    >>> frame_times(1.0, 10, 1.0).size, frame_times(1.0, 10, 2.0).tolist()
    (11, [0.0, 0.2, 0.4, 0.6, 0.8, 1.0])
    """
    step = speed / fps
    n = int(math.floor(t_end / step + 1e-9)) + 1
    return np.round(np.arange(n) * step, 12)


def _shade(normals: np.ndarray) -> np.ndarray:
    lit = np.clip(normals @ (LIGHT / np.linalg.norm(LIGHT)), 0.0, 1.0)
    rgb = BODY_RGB[None, :] * (0.35 + 0.65 * lit[:, None])
    return np.column_stack([rgb, np.ones(len(rgb))])


def animate(response, path, *, shape=None, fps: float = 12.0, speed: float = 1.0,
            ground: bool = False, max_faces: int = 1500, size: tuple = (480, 480),
            elev: float = 20.0, azim: float = -60.0, max_frames: int = 1500) -> Path:
    """Write an animation of a 3-D ``response`` (model ``rigid3d``, with histories) to
    ``path``: a GIF (``.gif``, Pillow) or an MP4 (``.mp4``, needs ffmpeg).

    Frame ``k`` shows the body at ``t = k speed / fps`` (``speed`` > 1 plays faster than
    real time), over the whole response, with ``t`` and the tilt of the body's up axis
    from the vertical in the title. The mesh is decimated to ``max_faces`` triangles for
    drawing (:func:`rocking.viewer3d.scene.decimate`).

    Parameters
    ----------
    response : Response
        A response of model ``rigid3d`` (states ``x, y, z, q0..q3``).
    path : str or Path
        ``.gif`` or ``.mp4``.
    shape : Shape, optional
        The body (default: the response's).
    fps : float
        Frames per second of the file.
    speed : float
        Response seconds per second of the file.
    ground : bool
        Draw in a fixed frame, the ground's own displacement included (its grid moves);
        default: in the ground's frame (the body's motion relative to the ground).
    max_faces : int
        Triangles drawn (the mesh is decimated above it).
    size : (int, int)
        Width and height in pixels.
    elev, azim : float
        The camera's elevation and azimuth (deg, matplotlib's).
    max_frames : int
        Refuse (ParameterError naming ``fps``) an animation of more frames.

    Returns
    -------
    Path

    Examples
    --------
    >>> import rocking
    >>> from rocking.shapes import Shape
    >>> from rocking.viewer3d import animate
    >>> body = Shape.box(0.4, 0.4, 1.2, mass=400.0)
    >>> r = rocking.simulate(body, rocking.motions.Sine(freq=2.0, amplitude=0.05,
    ...                      duration=1.0), model="rigid3d", duration=1.0)
    >>> from PIL import Image
    >>> Image.open(animate(r, "box.gif", fps=10)).n_frames  # t = 0, 0.1, ..., 1.0
    11
    """
    import matplotlib

    path = Path(path)
    fps = positive("fps", fps, "1/s")
    speed = positive("speed", speed)
    suffix = path.suffix.lower()
    if suffix not in (".gif", ".mp4"):
        raise ParameterError(f"path: an animation is written as .gif or .mp4, got {path.name!r}")
    w_px, h_px = (int(s) for s in size)
    if w_px < 16 or h_px < 16:
        raise ParameterError(f"size: at least 16 x 16 pixels, got {size}")
    sc = scene(response, shape, ground=ground, max_faces=max_faces)
    times = frame_times(float(sc.t[-1]), fps, speed)
    if len(times) > max_frames:
        raise ParameterError(f"fps: {len(times)} frames (a {sc.t[-1]:.3g} s response at "
                             f"fps={fps:g}, speed={speed:g}) exceed max_frames={max_frames}; "
                             f"lower fps or raise speed")
    pos, quat, gnd = sc.at(times)
    if gnd is None:
        gnd = np.zeros_like(pos)
    R = rotation_matrices(quat)
    verts = sc.vertices
    tri = verts[sc.faces]                              # (k, 3, 3) body frame
    nrm = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    nrm /= np.maximum(np.linalg.norm(nrm, axis=1), 1e-300)[:, None]
    tilts = np.degrees(tilt(quat))
    t_over = float(response.overturn_time) if response.overturned else math.inf

    # the view: a cube around every position of the body (the ground's included)
    world = pos + gnd                                  # centre of mass, fixed frame
    hull = verts[np.unique(sc.faces)]
    pts = np.einsum("fij,vj->fvi", R, hull) + world[:, None, :]
    lo = pts.reshape(-1, 3).min(axis=0)
    hi = pts.reshape(-1, 3).max(axis=0)
    half = 0.55 * float(np.max(hi[:2] - lo[:2]))
    half = max(half, 0.5 * float(hi[2] - min(lo[2], 0.0)))
    cx, cy = 0.5 * (lo[:2] + hi[:2])
    zc = half
    spacing = grid_spacing(2 * half, 8)

    import matplotlib.pyplot as plt
    from matplotlib import animation as manim
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

    if suffix == ".mp4" and not manim.FFMpegWriter.isAvailable():
        raise ParameterError(f"path: writing {path.name!r} needs ffmpeg, which was not "
                             f"found; write a .gif")
    with matplotlib.rc_context({"figure.dpi": 100}):
        fig = plt.figure(figsize=(w_px / 100, h_px / 100), dpi=100)
    try:
        ax = fig.add_axes((0.0, 0.0, 1.0, 0.92), projection="3d")
        ax.set_proj_type("persp", focal_length=0.6)
        ax.computed_zorder = False
        ax.set_xlim(cx - half, cx + half)
        ax.set_ylim(cy - half, cy + half)
        ax.set_zlim(zc - half, zc + half)
        ax.set_box_aspect((1, 1, 1), zoom=1.1)
        ax.view_init(elev=elev, azim=azim)
        ax.set_axis_off()
        gh = 1.3 * half  # the ground's square, a little beyond the view
        plane = Poly3DCollection([[(cx - gh, cy - gh, 0), (cx + gh, cy - gh, 0),
                                   (cx + gh, cy + gh, 0), (cx - gh, cy + gh, 0)]],
                                 facecolors=(0.86, 0.88, 0.9, 1.0), edgecolors="none",
                                 zorder=0)
        ax.add_collection3d(plane, autolim=False)
        grid = Line3DCollection(_grid(cx, cy, gh, spacing, gnd[0, :2]),
                                colors=(0.55, 0.58, 0.62, 1.0), linewidths=0.6, zorder=1)
        ax.add_collection3d(grid, autolim=False)
        body = Poly3DCollection(tri @ R[0].T + world[0], linewidths=0.4, zorder=2)
        ax.add_collection3d(body, autolim=False)
        label = fig.text(0.5, 0.955, "", ha="center", va="center", family="monospace",
                         fontsize=10)
        fig.text(0.99, 0.01, sc.name or "", ha="right", va="bottom", fontsize=8,
                 color="0.4")
        if suffix == ".gif":
            writer = manim.PillowWriter(fps=fps)
        else:
            writer = manim.FFMpegWriter(fps=fps, codec="libx264",
                                        extra_args=["-pix_fmt", "yuv420p"])
        path.parent.mkdir(parents=True, exist_ok=True)
        with writer.saving(fig, str(path), dpi=100):
            for k in range(len(times)):
                Rk = R[k]
                body.set_verts(tri @ Rk.T + world[k])
                rgba = _shade(nrm @ Rk.T)
                body.set_facecolor(rgba)
                body.set_edgecolor(rgba)  # hides the seams between triangles
                grid.set_segments(_grid(cx, cy, gh, spacing, gnd[k, :2]))
                over = "  overturned" if times[k] >= t_over else ""
                label.set_text(f"t = {times[k]:6.2f} s   tilt = {tilts[k]:5.2f} deg{over}")
                writer.grab_frame()
    finally:
        plt.close(fig)
    return path


def _grid(cx, cy, half, spacing, shift) -> list:
    """The ground's grid lines inside the square, moved by ``shift`` (the ground)."""
    segs = []
    for axis in (0, 1):
        c = (cx, cy)[axis]
        k0 = math.ceil((c - half - shift[axis]) / spacing)
        k1 = math.floor((c + half - shift[axis]) / spacing)
        for k in range(k0, k1 + 1):
            u = k * spacing + shift[axis]
            if axis == 0:
                segs.append([(u, cy - half, 0.0), (u, cy + half, 0.0)])
            else:
                segs.append([(cx - half, u, 0.0), (cx + half, u, 0.0)])
    return segs
