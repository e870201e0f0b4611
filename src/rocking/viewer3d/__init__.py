"""Seeing a 3-D response (model ``rigid3d``): an animation and a page for the browser.

* :func:`animate` writes a GIF (or an MP4 where ffmpeg exists) of the body's mesh moving
  over the ground plane, with ``t`` and the tilt (matplotlib);
* :func:`write_html` writes one self-contained HTML page that plays the motion (three.js,
  vendored in ``vendor/three`` and inlined: no network), with play/pause, a time slider,
  the speed and an orbit camera; :func:`read_page_data` reads its data back.

Both take the response and, optionally, the body (``shape``: by default the response's);
``ground=True`` draws the ground's own displacement too. The poses come from the states
``x, y, z, q0..q3`` (:mod:`rocking.viewer3d.scene`).

Examples
--------
>>> import rocking
>>> from rocking.shapes import Shape
>>> from rocking.viewer3d import animate, write_html
>>> r = rocking.simulate(Shape.box(0.4, 0.4, 1.2, mass=400.0),
...                      rocking.motions.Sine(freq=2.0, amplitude=0.05, duration=1.0),
...                      model="rigid3d", duration=1.0)
>>> animate(r, "box.gif").suffix, write_html(r, "box.html").suffix
('.gif', '.html')
"""

from .animation import animate, frame_times
from .page import THREE_VERSION, frame_indices, read_page_data, write_html
from .scene import Scene, decimate, rotation_matrices, scene, tilt

__all__ = ["animate", "write_html", "read_page_data", "scene", "Scene", "tilt",
           "rotation_matrices", "decimate", "frame_times", "frame_indices", "THREE_VERSION"]
