"""The friction angle of the DEM contacts, in rad like every angle of the package.

The Coulomb limit of a contact is ``|Fs| <= Fn tan(phi) + c`` (:mod:`rocking.models.dem`),
``phi = friction_angle`` in rad, default 30 degrees (``math.radians(30.0)``). A string
with its unit is accepted (``"30deg"``). Up to rocking 0.1 the angle was in degrees: a bare
number ``>= pi/2`` cannot be a friction angle in rad, so for one release it is still read
as degrees, with a :class:`DeprecationWarning`; a bare number ``< pi/2`` is rad.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from ..._validate import in_range, warn_deprecated
from ...errors import ParameterError
from ...units import parse_quantity

DEFAULT_FRICTION_ANGLE = math.radians(30.0)
"""Default friction angle of the contacts (rad): 30 degrees."""

HALF_PI = 0.5 * math.pi

def degrees_if_bare(value, name: str = "friction_angle"):
    """``value``, with a bare number ``>= pi/2`` read as degrees (deprecated: a
    DeprecationWarning) and returned in rad; anything else unchanged (checked by the
    caller). A bare number of 90 or more is refused: it is no angle in either unit."""
    if isinstance(value, bool | np.bool_) or not isinstance(value, numbers.Real):
        return value
    x = float(value)
    if not x >= HALF_PI:  # rad (or NaN: refused by the range check)
        return value
    if not x < 90.0:
        raise ParameterError(f"{name} must be in [0, pi/2) rad, or a string with its unit "
                             f"such as '30deg'; got {value!r} (a bare number >= pi/2 is read "
                             "as degrees, and must then be below 90)")
    warn_deprecated(f"{name} is in rad; write math.radians({x:g}) or '{x:g}deg' (a bare number "
                ">= pi/2 is read as degrees for one release)")
    return math.radians(x)


def check_friction_angle(value, name: str = "friction_angle") -> float:
    """The friction angle in rad, in ``[0, pi/2)``: a number in rad, a string with its unit
    (``"30deg"``) or, deprecated, a bare number ``>= pi/2`` in degrees."""
    value = degrees_if_bare(value, name)
    if isinstance(value, str):
        value = parse_quantity(value, "angle", name=name, default_unit="rad")
    return in_range(name, value, 0.0, HALF_PI, lo_open=False, hi_open=True,
                    shown="[0, pi/2) rad")
