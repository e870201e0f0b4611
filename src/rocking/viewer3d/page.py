"""One self-contained HTML page that plays a 3-D response in a browser (three.js, inlined
from the copy vendored in ``rocking/viewer3d/vendor/three``: the page needs no network).

The page holds the data as JSON in ``<script type="application/json" id="rocking-data">``
(:func:`read_page_data` reads it back): the body's mesh (``vertices``, flat, m, relative to
its centre of mass in its own frame; ``faces``, flat), and per frame ``t`` (s), ``pos`` (the
centre of mass relative to the ground, m, flat x, y, z), ``quat`` (q0..q3, body to
ground, flat), ``tilt`` (rad) and ``ground`` (the ground's displacement, m, or null).
The frames are every ``k``-th sample of the response (``k`` the integer nearest
``1 / (fps dt_out)``, at least 1), the last sample always included: no interpolation, the
page's poses are the response's to the JSON's rounding (1e-7 m, 1e-8).
"""

from __future__ import annotations

import html
import json
import math
import re
from importlib import resources
from pathlib import Path

import numpy as np

from .._atomic import atomic_write
from .._validate import positive
from ..errors import ParameterError
from .scene import decimate, grid_spacing, scene, tilt

THREE_VERSION = "147"
"""The vendored three.js release (npm ``three@0.147.0``; ``vendor/three/README.md``)."""
DATA_ID = "rocking-data"
"""The id of the page's JSON data element."""


def vendored(name: str) -> str:
    """The text of a vendored file (``three.min.js``, ``OrbitControls.js``, ``LICENSE``)."""
    return resources.files(__package__).joinpath("vendor", "three", name).read_text("utf-8")


def frame_indices(n: int, dt: float, fps: float) -> np.ndarray:
    """The samples shown: every ``k``-th of ``n`` (``k = max(1, round(1 / (fps dt)))``),
    the last one always included.

    Examples
    --------
    >>> from rocking.viewer3d import frame_indices
    >>> frame_indices(11, 0.002, 100).tolist()  # k = 5
    [0, 5, 10]
    >>> frame_indices(12, 0.002, 100).tolist()
    [0, 5, 10, 11]
    """
    k = max(1, int(round(1.0 / (fps * dt)))) if dt > 0 else 1
    idx = np.arange(0, n, k)
    if idx[-1] != n - 1:
        idx = np.append(idx, n - 1)
    return idx


def _flat(a, decimals: int) -> list:
    return np.round(np.asarray(a, dtype=np.float64), decimals).ravel().tolist()


def write_html(response, path, *, shape=None, fps: float = 60.0, ground: bool = False,
               max_faces: int = 10000, title: str | None = None) -> Path:
    """Write one self-contained HTML page that plays a 3-D ``response`` (model
    ``rigid3d``, with histories) in a browser: play/pause (space), a time slider, the
    playback speed, loop, an orbit camera (drag: turn, wheel: zoom, right drag: pan), and
    ``t`` and the tilt of the body's up axis from the vertical.

    three.js is inlined (no network: the page works offline, from a file). The mesh is
    decimated to ``max_faces`` triangles for the page
    (:func:`rocking.viewer3d.scene.decimate`); the motion is subsampled to about ``fps``
    frames per second of the response (:func:`frame_indices`), and the page interpolates
    between them. ``page.html#t=1.5`` opens it paused at t = 1.5 s.

    Parameters
    ----------
    response : Response
        A response of model ``rigid3d`` (states ``x, y, z, q0..q3``).
    path : str or Path
        The HTML file.
    shape : Shape, optional
        The body (default: the response's).
    fps : float
        Frames kept per second of the response.
    ground : bool
        Play in a fixed frame, the ground's own displacement included; default: in the
        ground's frame.
    max_faces : int
        Triangles in the page (the mesh is decimated above it).
    title : str, optional
        The page's title (default: the body and the model).

    Returns
    -------
    Path

    Examples
    --------
    >>> import rocking
    >>> from rocking.shapes import Shape
    >>> from rocking.viewer3d import read_page_data, write_html
    >>> body = Shape.box(0.4, 0.4, 1.2, mass=400.0)
    >>> r = rocking.simulate(body, rocking.motions.Sine(freq=2.0, amplitude=0.05,
    ...                      duration=1.0), model="rigid3d", duration=1.0)
    >>> page = write_html(r, "box.html", fps=50)
    >>> data = read_page_data(page)
    >>> len(data["t"]), data["t"][-1]  # every 10th sample of dt_out = 2 ms
    (51, 1.0)
    """
    import rocking

    path = Path(path)
    fps = positive("fps", fps, "1/s")
    sc = scene(response, shape, ground=ground, max_faces=None)
    verts, faces = decimate(sc.vertices, sc.faces, int(max_faces))
    dt = float(np.min(np.diff(sc.t))) if len(sc.t) > 1 else 0.0
    idx = frame_indices(len(sc.t), dt, fps)
    pos, quat = sc.position[idx], sc.quaternion[idx]
    info = response.info or {}
    name = sc.name or "body"
    ttl = title if title is not None else f"{name}: model {response.model}"
    outcome = "overturned" if response.overturned else "did not overturn"
    max_tilt = response.outputs.get("max_tilt", info.get("max_tilt"))
    bits = [outcome]
    if max_tilt is not None and np.isfinite(max_tilt):
        bits.append(f"max tilt {math.degrees(max_tilt):.2f} deg")
    for key, label, unit, scale in (("max_slide", "max slide", "mm", 1e3),
                                    ("max_twist", "max twist", "deg", 180 / math.pi)):
        v = response.outputs.get(key)
        if v is not None and np.isfinite(v):
            bits.append(f"{label} {scale * v:.2f} {unit}")
    if response.motion is not None:
        bits.append(type(response.motion).__name__)
    key = "heading" if type(response.motion).__name__ == "HorizontalPair" else "direction"
    if key in info:
        bits.append(f"{key} {info[key]:g} deg")
    reach = float(np.max(np.linalg.norm(verts, axis=1)))
    lo = np.min(sc.vertices, axis=0)
    hi = np.max(sc.vertices, axis=0)
    size = float(np.max(hi - lo))
    world = sc.position[:, :2] + (sc.ground[:, :2] if sc.ground is not None else 0.0)
    centre = 0.5 * (world.min(axis=0) + world.max(axis=0))
    extent = float(np.max(world.max(axis=0) - world.min(axis=0)))
    span = 2.0 * (extent + 2.0 * reach) + 2.0 * size
    step = grid_spacing(span, 12)
    span = step * math.ceil(span / step)
    data = {
        "title": ttl,
        "subtitle": ", ".join(bits),
        "model": response.model,
        "name": name,
        "vertices": _flat(verts, 7),
        "faces": np.asarray(faces, dtype=np.int64).ravel().tolist(),
        "size": size,
        "height": float(hi[2] - lo[2]),
        "comHeight": float(-lo[2]),
        "centre": _flat(centre, 7),
        "span": span,
        "gridStep": step,
        "gridLabel": f"grid {step:g} m",
        "t": _flat(sc.t[idx], 9),
        "pos": _flat(pos, 7),
        "quat": _flat(quat, 8),
        "tilt": _flat(tilt(quat), 8),
        "ground": _flat(sc.ground[idx], 7) if sc.ground is not None else None,
        "overturnTime": float(response.overturn_time) if response.overturned else None,
    }
    blob = json.dumps(data, separators=(",", ":"), allow_nan=False).replace("</", "<\\/")
    page = resources.files(__package__).joinpath("template.html").read_text("utf-8")
    values = {"__THREE_JS__": vendored("three.min.js"),
              "__ORBIT_JS__": vendored("OrbitControls.js"),
              "__DATA__": blob, "__TITLE__": html.escape(ttl),
              "__THREE_VERSION__": THREE_VERSION, "__VERSION__": rocking.__version__}
    for key in ("__THREE_JS__", "__ORBIT_JS__", "__DATA__"):
        if "</script" in values[key].lower():
            raise RuntimeError(f"{key} holds '</script': it cannot be inlined")
    # one pass: a placeholder inside an inlined file is not replaced
    page = re.sub("|".join(values), lambda m: values[m.group(0)], page)
    path.parent.mkdir(parents=True, exist_ok=True)
    atomic_write(path, page)
    return path


def read_page_data(path) -> dict:
    """The JSON data of a page written by :func:`write_html` (module docstring).

    Examples
    --------
    >>> from rocking.viewer3d import read_page_data, write_html
    >>> import rocking
    >>> from rocking.shapes import Shape
    >>> r = rocking.simulate(Shape.box(0.4, 0.4, 1.2, mass=400.0),
    ...                      rocking.motions.Sine(freq=2.0, amplitude=0.001, duration=0.1),
    ...                      model="rigid3d", duration=0.1)
    >>> data = read_page_data(write_html(r, "box.html"))
    >>> len(data["faces"]) // 3, data["pos"][:3], data["quat"][:4]  # a box: 12 triangles
    (12, [0.0, 0.0, 0.6], [1.0, 0.0, 0.0, 0.0])
    """
    text = Path(path).read_text("utf-8")
    m = re.search(rf'<script type="application/json" id="{DATA_ID}">(.*?)</script>', text,
                  re.S)
    if m is None:
        raise ParameterError(f"path: {path} holds no rocking viewer data")
    return json.loads(m.group(1))
