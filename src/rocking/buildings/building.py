r"""Linear elastic buildings with modal damping, described by their modes at the floors.

A building is a set of modes ``j`` with circular frequency ``omega_j = 2 pi / T_j``,
damping ratio ``zeta_j``, shape ``phi_j`` (at each floor, or as a function of the height
ratio ``z/H`` for the continuous model) and participation factor ``Gamma_j``
(``Gamma_j = phi_j^T M 1 / phi_j^T M phi_j``). Under a horizontal ground acceleration
``a_g(t)`` (the paper's Eq (1) convention) each mode is an oscillator

    u_j'' + 2 zeta_j omega_j u_j' + omega_j^2 u_j = -a_g(t),

and the absolute acceleration of a point at height ``z`` is (Chopra, *Dynamics of
Structures*, 13.1)

    a(z, t) = a_g(t) + sum_j Gamma_j phi_j(z) u_j''(t),

exact with all modes of a discrete model and truncated to the modes given otherwise.
:meth:`Building.modal_factors` returns ``(omega_j, zeta_j, Gamma_j phi_j(z))`` at a
floor or a height ratio, which is all a floor motion needs
(:class:`rocking.buildings.FloorMotion`).

Constructors: :meth:`Building.sdof` (one oscillator; the floor is its mass),
:meth:`Building.modal` (modal properties from the user's own structural model, e.g.
exported from OpenSees or ETABS), :meth:`Building.shear` (a shear building) and
:meth:`Building.continuous` (Miranda and Taghavi's shear-flexural beam, 2005).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from .._validate import as_int, in_range, positive
from ..errors import ParameterError

MAX_DAMPING = 1.0
"""Modal damping ratios are in [0, 1): an underdamped oscillator per mode."""


def _damping(damping, n: int) -> np.ndarray:
    z = np.broadcast_to(np.asarray(damping, dtype=float), (n,)).copy() \
        if np.ndim(damping) == 0 else np.asarray(damping, dtype=float)
    if z.shape != (n,):
        raise ParameterError(f"damping must be one ratio or one per mode ({n}), got shape "
                             f"{z.shape}")
    for i, x in enumerate(z):
        in_range(f"damping[{i}]" if n > 1 else "damping", x, 0.0, MAX_DAMPING,
                 lo_open=False, hi_open=True, shown="[0, 1) (a ratio: 5 % is 0.05)")
    return z


class Building:
    """A linear elastic building with modal damping (see the module docstring).

    Build one with :meth:`sdof`, :meth:`modal`, :meth:`shear` or :meth:`continuous`.

    Attributes
    ----------
    periods : ndarray
        Modal periods ``T_j`` (s), first mode first.
    damping : ndarray
        Modal damping ratios ``zeta_j``.
    participation : ndarray
        ``Gamma_j``.
    shapes : ndarray or None
        ``(n_floors + 1, n_modes)``: ``phi_j`` at the floors, row 0 the ground (zeros).
    shape_function : callable or None
        ``f(x) -> (n_modes,)``: ``phi_j`` at the height ratio ``x = z/H`` in [0, 1]
        (continuous model; discrete models give the floors only).
    """

    def __init__(self, periods, damping, participation, shapes=None,
                 shape_function: Callable | None = None, heights=None, name: str = "",
                 kind: str = "modal"):
        T = np.atleast_1d(np.asarray(periods, dtype=float))
        if T.ndim != 1 or T.size == 0:
            raise ParameterError("periods must be one or more modal periods (s)")
        for i, t in enumerate(T):
            positive(f"periods[{i}]", t, "s")
        self.periods = T
        self.damping = _damping(damping, T.size)
        g = np.atleast_1d(np.asarray(participation, dtype=float))
        if g.shape != T.shape or not np.all(np.isfinite(g)):
            raise ParameterError(f"participation must be one finite factor per mode "
                                 f"({T.size}), got {participation!r}")
        self.participation = g
        if shapes is None and shape_function is None:
            raise ParameterError("shapes: give the mode shapes at the floors")
        if shapes is not None:
            s = np.asarray(shapes, dtype=float)
            if s.ndim == 1 and T.size == 1:
                s = s[:, None]
            if s.ndim != 2 or s.shape[1] != T.size or not np.all(np.isfinite(s)):
                raise ParameterError(f"shapes must be (floors, modes) = (n, {T.size}) finite "
                                     f"values, got shape {s.shape}")
            if not np.all(s[0] == 0.0):
                s = np.vstack([np.zeros(T.size), s])  # the ground does not move
            shapes = s
        self.shapes = shapes
        self.shape_function = shape_function
        self.heights = None if heights is None else np.asarray(heights, dtype=float)
        self.name = str(name)
        self.kind = kind

    # ------------------------------------------------------------------ constructors
    @classmethod
    def sdof(cls, period: float, damping: float = 0.05, name: str = "") -> Building:
        """One oscillator of period ``period`` (s) and damping ratio ``damping``: floor 1 is
        its mass (``Gamma phi = 1``)."""
        T = positive("period", period, "s")
        return cls([T], damping, [1.0], shapes=[[0.0], [1.0]], heights=[0.0, 1.0],
                   name=name or f"SDOF building, T = {T:g} s", kind="sdof")

    @classmethod
    def modal(cls, periods, damping, shapes, participation, heights=None,
              name: str = "") -> Building:
        """Modal properties from the user's own structural model: ``periods`` (s),
        ``damping`` (one ratio or one per mode), ``shapes`` ``(n_floors, n_modes)`` at
        floors 1..N (the ground row is added) and ``participation`` ``Gamma_j`` (with the
        same normalisation of the shapes)."""
        return cls(periods, damping, participation, shapes=shapes, heights=heights,
                   name=name or "modal building", kind="modal")

    # ------------------------------------------------------------------ the modes
    @property
    def n_modes(self) -> int:
        return int(self.periods.size)

    @property
    def n_floors(self) -> int | None:
        """Floors above the ground (None for a continuous model without floors)."""
        return None if self.shapes is None else self.shapes.shape[0] - 1

    @property
    def omegas(self) -> np.ndarray:
        """Circular frequencies ``2 pi / T_j`` (rad/s)."""
        return 2.0 * math.pi / self.periods

    def modal_factors(self, floor: int | None = None, height_ratio: float | None = None
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(omega_j, zeta_j, Gamma_j phi_j)`` at ``floor`` (0 is the ground) or at the
        height ratio ``z/H`` (continuous models, or a discrete model's floor heights)."""
        if (floor is None) == (height_ratio is None):
            raise ParameterError("floor or height_ratio: give exactly one")
        if floor is not None:
            if self.shapes is None:
                raise ParameterError(f"floor: this {self.kind} building has no floors; give "
                                     "height_ratio (z/H)")
            k = as_int("floor", floor, 0, self.n_floors)
            phi = self.shapes[k]
        else:
            x = in_range("height_ratio", height_ratio, 0.0, 1.0, lo_open=False, hi_open=False,
                         shown="[0, 1]")
            if self.shape_function is not None:
                phi = np.asarray(self.shape_function(x), dtype=float)
            elif self.heights is not None:
                hits = np.flatnonzero(np.isclose(self.heights, x, rtol=0, atol=1e-12))
                if hits.size == 0:
                    raise ParameterError(f"height_ratio {x:g} is not a floor of this building "
                                         f"(floors at z/H = {np.round(self.heights, 4)})")
                phi = self.shapes[hits[0]]
            else:
                raise ParameterError("height_ratio: this building gives its floors only")
        return self.omegas, self.damping, self.participation * phi

    def __repr__(self) -> str:
        T = ", ".join(f"{t:.3g}" for t in self.periods[:3])
        more = ", ..." if self.n_modes > 3 else ""
        return (f"Building({self.name!r}, {self.n_modes} mode(s), T = [{T}{more}] s, "
                f"zeta = {self.damping[0]:g})")
