"""Rigid blocks and their classical rocking parameters (Peña et al. 2007, Eqs 2-4).

A block rocking on a rigid base is described, in the classical (Housner) theory, by three
parameters:

* ``alpha`` (rad): the critical (slenderness) angle, ``alpha = atan(b/h)`` (Eq 2), where
  2b is the full width and 2h the full height of a rectangular block;
* ``p`` (1/s): the frequency parameter, ``p^2 = M g R / I_O`` (Eq 3), which reduces to
  ``3 g / (4 R)`` for a rectangle, with ``R = sqrt(b^2 + h^2)`` the distance from a base
  corner to the centroid and ``I_O = (4/3) M R^2`` the moment of inertia about that corner;
* ``mu``: the coefficient of restitution, the ratio of angular velocities after and before
  an impact. Conservation of angular momentum about the new pivot gives Housner's value
  ``mu = 1 - (3/2) sin^2(alpha)`` (Eq 4).

All quantities are SI: m, kg, kg m^2, rad, 1/s.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from ._validate import in_range, positive
from .errors import ParameterError
from .units import G


def housner_mu(alpha: float) -> float:
    """Housner's coefficient of restitution of a rectangular block, Eq 4."""
    return 1.0 - 1.5 * math.sin(alpha) ** 2


@dataclass(frozen=True)
class Block:
    """A rigid block for planar rocking.

    Build one with :meth:`rectangular` (from its geometry) or :meth:`from_params` (from
    the classical parameters directly). ``alpha``, ``p`` and ``mu`` are all that the
    classical and CCRR models need; the geometric fields are optional and are ``None``
    when unknown.
    """

    alpha: float
    p: float
    mu: float
    R: float | None = None
    mass: float | None = None
    I_O: float | None = None
    width: float | None = None
    height: float | None = None
    thickness: float | None = None
    name: str = ""

    def __post_init__(self):
        object.__setattr__(self, "alpha", in_range("alpha", self.alpha, 0.0, math.pi / 2,
                                                   shown="(0, pi/2) rad"))
        object.__setattr__(self, "p", positive("p", self.p, "1/s"))
        object.__setattr__(self, "mu", in_range("mu", self.mu, 0.0, 1.0, hi_open=False))
        for f in ("R", "mass", "I_O", "width", "height", "thickness"):
            v = getattr(self, f)
            if v is not None:
                object.__setattr__(self, f, positive(f, v, "(SI units)"))

    # ------------------------------------------------------------------ constructors
    @classmethod
    def rectangular(
        cls,
        width: float,
        height: float,
        mass: float | None = None,
        thickness: float | None = None,
        *,
        mu: float | None = None,
        p: float | None = None,
        name: str = "",
    ) -> Block:
        """A rectangular block of full width ``2b`` and full height ``2h`` (m), as in Table I.

        ``alpha`` follows Eq 2, ``p`` Eq 3 (``3g/4R``) and ``mu`` Eq 4 (Housner), unless
        ``mu`` or ``p`` is given. ``I_O = (4/3) M R^2`` is set when ``mass`` is known.
        """
        width = positive("width", width, "m")
        height = positive("height", height, "m")
        if mass is not None:
            mass = positive("mass", mass, "kg")
        if thickness is not None:
            thickness = positive("thickness", thickness, "m")
        b, h = width / 2.0, height / 2.0
        alpha = math.atan2(b, h)
        R = math.hypot(b, h)
        p_geo = math.sqrt(3.0 * G / (4.0 * R))
        if mu is None and housner_mu(alpha) <= 0.0:
            raise ParameterError(
                f"Eq 4 gives mu = {housner_mu(alpha):.3f} <= 0 for this squat block "
                f"(alpha = {math.degrees(alpha):.1f} deg; Housner's restitution needs alpha < "
                "54.7 deg, i.e. width/height < 1.41); pass mu explicitly, in (0, 1]")
        return cls(
            alpha=alpha,
            p=p_geo if p is None else p,
            mu=housner_mu(alpha) if mu is None else mu,
            R=R,
            mass=mass,
            I_O=None if mass is None else 4.0 / 3.0 * mass * R * R,
            width=width,
            height=height,
            thickness=thickness,
            name=name,
        )

    @classmethod
    def from_params(cls, alpha: float, p: float, mu: float, *, name: str = "", **geometry) -> Block:
        """A block given by its classical parameters ``alpha`` (rad), ``p`` (1/s), ``mu``."""
        return cls(alpha=alpha, p=p, mu=mu, name=name, **geometry)

    def with_params(self, **changes) -> Block:
        """A copy with fields replaced (validated again), e.g. ``block.with_params(mu=0.9)``."""
        return dataclasses.replace(self, **changes)

    # ------------------------------------------------------------------ derived values
    @property
    def b(self) -> float | None:
        """Half-width (m), if the geometry is known."""
        return None if self.width is None else self.width / 2.0

    @property
    def h(self) -> float | None:
        """Half-height (m), if the geometry is known."""
        return None if self.height is None else self.height / 2.0

    @property
    def uplift_acceleration(self) -> float:
        """Ground acceleration (m/s^2) above which the block uplifts from rest: ``g tan(alpha)``."""
        return G * math.tan(self.alpha)

    def params(self) -> dict:
        """The classical parameters as a plain dict (``alpha``, ``p``, ``mu``, ``R``)."""
        return {"alpha": self.alpha, "p": self.p, "mu": self.mu, "R": self.R}

    def __repr__(self) -> str:  # short and readable in notebooks
        name = f"{self.name!r}, " if self.name else ""
        return (f"Block({name}alpha={self.alpha:.4f} rad, p={self.p:.4f} 1/s, mu={self.mu:.4f}"
                + (f", R={self.R:.4f} m" if self.R else "") + ")")
