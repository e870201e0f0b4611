"""The example mesh shipped with the package: a synthetic statue-like body
(``data/statue.ply``, written by ``data/make_example.py``; see that script for its
geometry)."""

from __future__ import annotations

from pathlib import Path

EXAMPLE = Path(__file__).resolve().parent / "data" / "statue.ply"


def example_mesh_path() -> Path:
    """The path of the example mesh (a binary PLY in m, ``up="z"``).

    Examples
    --------
    >>> from rocking.shapes import example_mesh_path
    >>> p = example_mesh_path()
    >>> p.name, p.is_file()
    ('statue.ply', True)
    """
    return EXAMPLE


def load_example(*, density: float | None = 2600.0, mass=None, **kwargs):
    """The example mesh as a :class:`rocking.shapes.Shape` (marble-like density 2600
    kg/m^3 unless ``mass`` or another ``density`` is given).

    Examples
    --------
    >>> from rocking.shapes import load_example
    >>> statue = load_example()
    >>> statue.name, round(statue.mass / statue.volume, 6)  # density 2600 kg/m^3
    ('statue', 2600.0)
    >>> round(statue.height, 2)
    1.62
    """
    from .shape import load_shape

    if mass is not None:
        density = None
    return load_shape(EXAMPLE, density=density, mass=mass, name="statue", **kwargs)


__all__ = ["example_mesh_path", "load_example"]
