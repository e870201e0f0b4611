r"""The horizontal directions of a motion: angles, and the one projection of the horizontal
components of a motion on a direction.

**Frames.** A motion's horizontal components are ``a1`` (the first: a single horizontal
motion, or the first component of a :class:`~rocking.motions.HorizontalPair`) and ``a2``
(the second; 0 for a single horizontal motion). Directions are given by compass-style
*bearings*, clockwise looking down (the convention of the pair's ``azimuths``): the first
component points at the bearing ``A1`` and the second at ``A1 + h 90 deg``, ``h`` the
pair's handedness (+1: clockwise, the NGA pairs; -1: counter-clockwise). A single
horizontal motion is a pair with ``A1 = 0``, ``h = -1`` and ``a2 = 0``.

An object's horizontal frame ``(x, y)`` (right-handed with its ``up`` axis: ``y`` is 90 deg
counter-clockwise of ``x`` looking down, as in :mod:`rocking.shapes`) has its ``x`` axis at
the bearing ``orientation``; its direction ``phi`` (rad, counter-clockwise from ``x``) has
the bearing ``B = orientation - phi``.

**The projection** (:func:`plane_weights`, the only place that writes it): the
acceleration along bearing ``B`` is ``a1 cos(B - A1) + a2 cos(B - A2) = w1 a1 + w2 a2`` with
``w1 = cos beta``, ``w2 = h sin beta``, ``beta = (orientation - phi) - A1``.
:meth:`~rocking.motions.HorizontalPair.along` (hence ``HorizontalPair.motion`` and
``HorizontalPair.on_plane``), :meth:`~rocking.motions.Motion.on_plane` and the
three-component specs (``spec3``: the weights of the directions ``phi = 0`` and
``phi = 90 deg``, the object's ``x`` and ``y`` axes) all take their weights from it.

**Heading.** ``spec3(heading)`` and ``on_plane(phi, heading)`` place the object's ``x``
axis at the angle ``heading`` (rad, or a string such as ``"30deg"``) counter-clockwise
from the first component, looking down: ``orientation = A1 - heading``. The ground
components seen in the object's frame are those of the ground frame ``(a_x, a_y)`` (the
first component, and the axis 90 deg counter-clockwise of it: ``a_y = -h a2``) rotated
by ``-heading``:

``ax = a_x cos(heading) + a_y sin(heading)``, ``ay = -a_x sin(heading) + a_y cos(heading)``.
"""

from __future__ import annotations

import math
import numbers

from ..errors import ParameterError
from ..units import parse_quantity

EXACT_TOL = 1e-9
"""Angles (rad) within this of a multiple of 90 deg are taken as exact."""


def angle(name: str, value) -> float:
    """An angle in rad: a number (rad) or a string with a unit (``"228deg"``).

    Examples
    --------
    >>> import math
    >>> from rocking.motions.components import angle
    >>> angle("heading", 0.5), round(angle("heading", "90deg"), 12) == round(math.pi / 2, 12)
    (0.5, True)
    """
    if isinstance(value, bool) or value is None:
        raise ParameterError(f"{name} must be an angle (rad, or a string such as '30deg'), "
                             f"got {value!r}")
    if isinstance(value, numbers.Real):
        x = float(value)
    else:
        try:
            x = parse_quantity(value, "angle", name=name, default_unit="rad")
        except Exception as exc:
            raise ParameterError(str(exc)) from None
    if not math.isfinite(x):
        raise ParameterError(f"{name} must be finite, got {value!r}")
    return float(x)


def cos_sin(a: float) -> tuple[float, float]:
    """``(cos a, sin a)``, exact (in {-1, 0, 1}) within :data:`EXACT_TOL` of a multiple of
    90 deg.

    Examples
    --------
    >>> import math
    >>> from rocking.motions.components import cos_sin
    >>> cos_sin(math.pi / 2), cos_sin(-math.pi)
    ((0.0, 1.0), (-1.0, 0.0))
    """
    q = a / (0.5 * math.pi)
    k = round(q)
    if abs(a - k * 0.5 * math.pi) <= EXACT_TOL:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[k % 4]
    return math.cos(a), math.sin(a)


def plane_weights(phi: float, orientation: float, first: float = 0.0,
                  handedness: int = -1) -> tuple[float, float]:
    """``(w1, w2)``: the acceleration along the object's direction ``phi`` (rad) is
    ``w1 a1 + w2 a2`` (module docstring), the object's ``x`` axis at the bearing
    ``orientation`` (rad), the first component at the bearing ``first`` (rad) and the
    second 90 deg clockwise (``handedness = 1``) or counter-clockwise (-1) of it.

    Examples
    --------
    >>> import math
    >>> from rocking.motions.components import plane_weights
    >>> plane_weights(0.0, 0.0), plane_weights(math.pi / 2, 0.0)  # x: a1; y: a2 (ccw pair)
    ((1.0, 0.0), (0.0, 1.0))
    >>> plane_weights(math.pi / 2, 0.0, handedness=1)  # a clockwise pair: y is -a2
    (0.0, -1.0)
    >>> [round(w, 6) for w in plane_weights(0.0, -math.pi / 6)]  # x turned 30 deg ccw
    [0.866025, 0.5]
    """
    c, s = cos_sin((orientation - phi) - first)  # B - A1
    # a_phi = a1 cos(B - A1) + a2 cos(B - A2), A2 = A1 + h 90deg: cos(B - A2) = h sin(B - A1)
    return c, handedness * s


__all__ = ["angle", "cos_sin", "plane_weights", "EXACT_TOL"]
