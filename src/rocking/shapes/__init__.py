"""Rigid bodies from 3-D meshes (a scan of a statue, a vase): rocking parameters per
direction of horizontal shaking (issue 20).

* :func:`load_shape` reads an STL, OBJ or PLY file (trimesh), welds and validates the
  mesh (watertight, consistent winding, positive volume; ``repair="hull"`` for the convex
  hull of a defective one), computes its mass properties and finds its support (the
  contact patch on the lowest plane along ``up`` and its convex hull): a :class:`Shape`.
* :func:`directional_parameters` tabulates, per direction ``phi`` of shaking, the planar
  block of each side (alpha, R, p, the restitution, the uplift acceleration);
  :func:`weakest_direction` / :func:`strongest_direction` pick from it;
  :func:`plot_directional` draws it (polar).
* :meth:`rocking.Block.from_shape` is the planar :class:`rocking.Block` of one direction and
  :meth:`Shape.polygon` its outline for the DEM.
* :func:`rest_pose` settles a body whose base is not flat (a rock on three points) under
  gravity into its resting pose, its support then exact (``settle=True`` in
  :func:`load_shape`; :mod:`rocking.shapes.rest`); :func:`is_resting` tells whether a shape
  already rests exactly on its base.
* :func:`example_mesh_path` / :func:`load_example`: a small synthetic statue shipped with
  the package (``data/statue.ply``, written by ``data/make_example.py``).

The planar analysis in every direction is the standard engineering answer for a 3-D body
until a 3-D model exists: the body is assumed to rock about one pivot line at a time, in
the vertical plane of the shaking (no wobbling, no twisting, no sliding).
"""

from __future__ import annotations

from .directional import (
    COLUMNS,
    NAMED_DIRECTIONS,
    Direction,
    directional_parameters,
    parse_direction,
    resolve_direction,
    strongest_direction,
    weakest_direction,
)
from .example import example_mesh_path, load_example
from .plot import plot_directional
from .rest import is_resting, rest_pose
from .shape import MeshRepairWarning, Shape, load_shape

__all__ = ["COLUMNS", "NAMED_DIRECTIONS", "Direction", "MeshRepairWarning", "Shape",
           "directional_parameters", "example_mesh_path", "is_resting", "load_example",
           "load_shape", "parse_direction", "plot_directional", "resolve_direction",
           "rest_pose", "strongest_direction", "weakest_direction"]
