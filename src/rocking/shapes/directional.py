r"""Rocking parameters of a 3-D body for every horizontal direction of shaking.

**Directions** (:mod:`rocking.shapes.support` for the frame): ``phi`` (rad) is measured
counter-clockwise from the frame's e1 (the mesh's x axis when ``up="z"``), looking down
the ``up`` axis; the ground acceleration ``a(t)`` of the planar analysis acts along
``e_phi = (cos phi, sin phi)``. A positive ``a`` tips the body towards ``-e_phi`` (the
inertial force is ``-m a e_phi``), about the "+" pivot (``theta > 0``, the sign convention
of Eq 1, :mod:`rocking.models.housner`): the support's supporting line normal to
``e_phi`` on the ``-e_phi`` side. The "-" pivot is the one on the ``+e_phi`` side. With
``S`` the support hull's vertices relative to the centre of mass's vertical,

.. math:: b_+(\varphi) = \max_{s \in S} (-s \cdot e_\varphi), \qquad
          b_-(\varphi) = \max_{s \in S} (s \cdot e_\varphi) ,

the support function of the hull (one matrix product for all directions), so that
``phi + pi`` swaps the sides. The body rotates about the pivot line, a horizontal axis
along ``u = (-sin phi, cos phi, 0)``; only the moment of inertia about that axis enters
(the products of inertia load the pivot, not the rotation): with ``I_G`` the inertia
tensor about the centre of mass, ``r_g^2 = u . I_G . u / m``.

**Per side** ``s`` (the contract of issue 20; ``h`` is the centre of mass's height above
the base, ``o`` the other side): ``alpha_s = atan(b_s / h)``, ``R_s = hypot(b_s, h)``,
``I_s = m (r_g^2 + R_s^2)`` (parallel axes), ``p_s^2 = m g R_s / I_s = g R_s / (r_g^2 +
R_s^2)`` (Eq 3), the uplift acceleration ``g tan(alpha_s) = g b_s / h`` (moments about the
pivot at rest) and the restitution of the impact that ends rocking on side ``s``:

.. math:: \mu_s = \frac{r_g^2 + h^2 - b_s b_o}{r_g^2 + R_o^2} .

*Derivation* (Housner's argument for a general body: the impact is instantaneous, the
impulse acts at the new pivot O' only, no bounce and no slip, so the angular momentum
about O' is conserved). In the plane of shaking put the centre of mass G at ``(0, h)``,
the old pivot O at ``(-b_s, 0)`` and the new one O' at ``(b_o, 0)``. Before the impact the
body turns about O at the rate ``w1``: ``v_G = w1 x (G - O) = w1 (-h, b_s)``. Its angular
momentum about O' is ``I_G w1 + m (G - O') x v_G`` with ``G - O' = (-b_o, h)``:
``(G - O') x v_G = (-b_o)(w1 b_s) - h(-w1 h) = w1 (h^2 - b_s b_o)``, so ``H_O' = m w1
(r_g^2 + h^2 - b_s b_o)``. After the impact it turns about O' at ``w2``: ``H_O' = I_o w2 =
m (r_g^2 + R_o^2) w2``, hence ``mu_s = w2 / w1`` above. For a rectangle (``b_s = b_o = b``,
``r_g^2 = R^2/3``) it is ``(R^2/3 + h^2 - b^2) / (4 R^2/3) = 1 - 1.5 sin^2(alpha)``, Eq 4.

**Uplift of the 3-D body.** At rest, the body under the acceleration ``a e_phi`` tips
when the resultant of its weight and inertial force, the line from the centre of mass
along ``(-a e_phi, -g)``, leaves the support: at ``a = g t_s / h`` with ``t_s`` the
distance from the centre of mass's vertical to the support's boundary along ``-e_phi``
(side "+"; along ``+e_phi`` for "-"), through whichever edge the ray crosses. The planar
pivot line, normal to ``e_phi`` through the support's extreme point, gives ``b_s >= t_s``
instead: equal where the ray leaves through a vertex or an edge normal to ``e_phi``,
larger where it crosses an edge obliquely (a box shaken along a direction between its
axes tips about its long edge first, a planar block of that direction does not). The
columns ``uplift_3d_plus`` / ``uplift_3d_minus`` (m/s^2) give ``g t_s / h``: where they
are below ``uplift_s``, the planar block of that direction overestimates the uplift
acceleration (unconservative). Both agree on the weakest direction and its uplift (the
normal of the support edge nearest to the centre of mass, where the support function and
the ray distance have the same minimum: that edge's distance).

**Other contacts.** While the body rocks on side ``s`` by the tilt ``theta``, a point of
it beyond the pivot (outward distance ``d > 0``, height ``z``) reaches the ground when
``tan(theta) = z / d``: the column ``contact_s`` is the smallest such tilt over the
body's convex hull (``pi/2`` if nothing overhangs the pivot). Where ``contact_s <
alpha_s`` the body would land on that overhang before passing its overturning angle, which
the planar model of one pivot per side does not represent: such a direction is flagged
(``overhang``) rather than trusted.

The columns of :func:`directional_parameters` (SI units; angles in rad except
``phi_deg``): phi, phi_deg, h, b_plus, b_minus, radius_of_gyration, alpha_plus,
alpha_minus, R_plus, R_minus, I_plus, I_minus (kg m^2), p_plus, p_minus, mu_plus,
mu_minus, uplift_plus, uplift_minus (m/s^2), alpha_min, uplift_min (m/s^2), weak_side
("+" or "-", the side of ``uplift_min``), uplift_3d_plus, uplift_3d_minus (m/s^2),
contact_plus, contact_minus (rad) and overhang (bool: ``contact_s < alpha_s`` on either
side).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._validate import as_int, warn_implausible
from ..errors import ParameterError
from ..units import G, parse_quantity, split_quantity

#: The columns of the table of :func:`directional_parameters`, one row per direction.
COLUMNS = ("phi", "phi_deg", "h", "b_plus", "b_minus", "radius_of_gyration", "alpha_plus",
           "alpha_minus", "R_plus", "R_minus", "I_plus", "I_minus", "p_plus", "p_minus",
           "mu_plus", "mu_minus", "uplift_plus", "uplift_minus", "alpha_min", "uplift_min",
           "weak_side", "uplift_3d_plus", "uplift_3d_minus", "contact_plus", "contact_minus",
           "overhang")


def as_directions(directions) -> np.ndarray:
    """``directions`` as an array of angles (rad): an int ``n`` gives ``n`` directions
    evenly spaced over [0, 2 pi); a number or a sequence is taken in rad."""
    if isinstance(directions, int | np.integer) and not isinstance(directions, bool):
        n = as_int("directions", directions, lo=1)
        return np.arange(n) * (2.0 * math.pi / n)
    if isinstance(directions, bool | np.bool_):
        raise ParameterError(f"directions must be a count or angles in rad, got {directions!r}")
    try:
        phi = np.array(directions, dtype=np.float64).reshape(-1)
    except (TypeError, ValueError):
        raise ParameterError("directions must be a count or angles in rad, got "
                             f"{directions!r}") from None
    if len(phi) == 0 or not np.all(np.isfinite(phi)):
        raise ParameterError(f"directions must be finite angles in rad, got {directions!r}")
    warn_if_degrees(phi)
    return phi


def warn_if_degrees(phi) -> None:
    """Warn when angles meant in rad look like degrees (some ``|phi| > 4 pi``: ``phi + pi``
    of a direction up to ``2 pi`` stays below)."""
    big = np.abs(np.asarray(phi, dtype=float))
    if big.size and big.max() > 4.0 * math.pi:
        warn_implausible(f"directions are angles in rad; got {big.max():g}, above 4 pi: "
                         "degrees? (np.radians(...); a count of directions is an int)")


def side_arrays(support, h, inertia_local, mass, phi, hull=None) -> dict:
    """The table's columns as arrays (module docstring), vectorised over ``phi``.

    ``support`` (k, 2): the support hull relative to the centre of mass's vertical;
    ``inertia_local`` (3, 3) about the centre of mass in the frame (e1, e2, up); ``hull``
    (j, 3): the body's convex hull's vertices in that frame (base at z = 0), for the
    other contacts (None: not computed)."""
    phi = np.asarray(phi, dtype=np.float64)
    c, s = np.cos(phi), np.sin(phi)
    proj = np.asarray(support) @ np.vstack([c, s])  # (k, n): s . e_phi
    b_minus = proj.max(axis=0)
    b_plus = -proj.min(axis=0)
    ii = np.asarray(inertia_local)
    rg2 = (ii[0, 0] * s * s - 2.0 * ii[0, 1] * s * c + ii[1, 1] * c * c) / mass
    out = {"phi": phi, "phi_deg": np.degrees(phi), "h": np.full_like(phi, h),
           "b_plus": b_plus, "b_minus": b_minus, "radius_of_gyration": np.sqrt(rg2)}
    R = {"plus": np.hypot(b_plus, h), "minus": np.hypot(b_minus, h)}
    b = {"plus": b_plus, "minus": b_minus}
    for side in ("plus", "minus"):
        out[f"alpha_{side}"] = np.arctan2(b[side], h)
        out[f"R_{side}"] = R[side]
        out[f"I_{side}"] = mass * (rg2 + R[side] ** 2)
        out[f"p_{side}"] = np.sqrt(G * R[side] / (rg2 + R[side] ** 2))
    for side, other in (("plus", "minus"), ("minus", "plus")):
        out[f"mu_{side}"] = (rg2 + h * h - b[side] * b[other]) / (rg2 + R[other] ** 2)
    for side in ("plus", "minus"):
        out[f"uplift_{side}"] = G * b[side] / h
    out["alpha_min"] = np.minimum(out["alpha_plus"], out["alpha_minus"])
    out["uplift_min"] = np.minimum(out["uplift_plus"], out["uplift_minus"])
    out["weak_side"] = np.where(out["uplift_plus"] <= out["uplift_minus"], "+", "-")
    # the ray from the centre of mass's vertical to the support's boundary: edge i is the
    # half-plane n_i . x <= c_i (outward unit normal, c_i > 0 for a point inside)
    sup = np.asarray(support)
    edge = np.roll(sup, -1, axis=0) - sup
    normal = np.column_stack([edge[:, 1], -edge[:, 0]]) / np.hypot(edge[:, 0], edge[:, 1])[:, None]
    dist = np.einsum("ij,ij->i", normal, sup)[:, None]  # (k, 1)
    ne = normal @ np.vstack([c, s])  # (k, n): n_i . e_phi
    with np.errstate(divide="ignore"):
        t_minus = np.where(ne > 1e-15, dist / np.where(ne > 1e-15, ne, 1.0), np.inf).min(axis=0)
        t_plus = np.where(ne < -1e-15, dist / np.where(ne < -1e-15, -ne, 1.0), np.inf).min(axis=0)
    out["uplift_3d_plus"] = G * np.minimum(t_plus, b_plus) / h
    out["uplift_3d_minus"] = G * np.minimum(t_minus, b_minus) / h
    if hull is not None:
        hull = np.asarray(hull)
        x = hull[:, :2] @ np.vstack([c, s])  # (j, n)
        z = hull[:, 2:3]
        eps = 1e-9 * (float(np.ptp(hull[:, 2])) + float(np.ptp(hull[:, :2])))
        for side, d in (("plus", -b_plus[None, :] - x), ("minus", x - b_minus[None, :])):
            ang = np.where(d > eps, np.arctan2(z, np.where(d > eps, d, 1.0)), 0.5 * np.pi)
            out[f"contact_{side}"] = ang.min(axis=0)
        out["overhang"] = ((out["contact_plus"] < out["alpha_plus"])
                           | (out["contact_minus"] < out["alpha_minus"]))
    return out


def directional_parameters(shape, directions=360):
    """The rocking parameters of ``shape`` (:class:`rocking.shapes.Shape`) per direction
    of shaking: a :class:`pandas.DataFrame`, one row per ``phi`` (rad; an int ``n``: ``n``
    directions evenly spaced over [0, 2 pi), default one per degree), the columns of
    :data:`COLUMNS` (module docstring).

    Examples
    --------
    >>> import trimesh
    >>> from rocking.shapes import Shape
    >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)), density=2000.0)
    >>> from rocking.shapes import directional_parameters
    >>> tab = directional_parameters(box, 4)  # phi = 0, 90, 180, 270 deg
    >>> [round(float(a), 4) for a in tab["alpha_plus"]]  # atan(0.2/1), atan(0.3/1)
    [0.1974, 0.2915, 0.1974, 0.2915]
    """
    import pandas as pd

    phi = as_directions(directions)
    cols = side_arrays(shape.support, shape.h, shape.inertia_local, shape.mass, phi,
                       shape.hull_points())
    return pd.DataFrame({k: cols[k] for k in COLUMNS})


@dataclass(frozen=True)
class Direction:
    """One named direction (the weakest, the strongest): ``phi`` (rad, in [0, 2 pi)),
    ``phi_deg``, the ``side`` that uplifts first there, its ``alpha`` (rad) and ``uplift``
    acceleration (m/s^2; ``uplift_g`` in g), and ``index``, the table's row label (the row
    at ``phi``; the row at ``phi - pi`` where the table has no row at ``phi``; None for
    :meth:`Shape.weakest`).

    **The convention** (one for every function, command, table and plot; the shapes
    guide): the side is always "+". ``phi`` and ``phi + pi`` are the same pivot line with
    the sides swapped, so a direction can be named two ways; the package names it by the
    ``phi`` whose "+" side is the weak (or strong) one. Then the planar block of that
    direction (:meth:`rocking.Block.from_shape`, ``Block.from_mesh(direction="weakest")``)
    has ``alpha_plus == alpha``, and a positive ground acceleration along ``e_phi`` tips
    the body over that side, towards ``phi + 180`` deg (the module docstring).

    Examples
    --------
    >>> import trimesh
    >>> from rocking.shapes import Shape
    >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)), density=2000.0)
    >>> from rocking.shapes import directional_parameters, weakest_direction
    >>> d = weakest_direction(directional_parameters(box, 4))  # along the 0.4 m side
    >>> d.phi_deg, d.side, round(d.alpha, 4), round(float(np.arctan(0.2 / 1.0)), 4)
    (0.0, '+', 0.1974, 0.1974)
    >>> round(d.uplift_g, 6)  # tan(alpha) = b / h
    0.2
    """

    phi: float
    phi_deg: float
    side: str
    alpha: float
    uplift: float
    uplift_g: float
    index: object


def pick(table, which: str) -> Direction:
    """The row of the smallest (``which="weakest"``) or largest (``"strongest"``)
    ``min(uplift_plus, uplift_minus)`` of a directional table (first one on ties), as a
    :class:`Direction` in the package's convention: its side is always "+" (see
    :class:`Direction`). Where the row's weaker side is "-", the direction returned is the
    row's mirror ``phi + pi`` (the same pivot line, the sides swapped)."""
    missing = [c for c in ("phi", "uplift_plus", "uplift_minus", "alpha_plus", "alpha_minus")
               if c not in getattr(table, "columns", ())]
    if missing or len(table) == 0:
        raise ParameterError("expected a non-empty table of directional_parameters, "
                             f"missing columns {missing}" if missing else "the table is empty")
    up = np.minimum(table["uplift_plus"].to_numpy(), table["uplift_minus"].to_numpy())
    i = int(np.argmin(up) if which == "weakest" else np.argmax(up))
    row = table.iloc[i]
    phi, key, index = float(row["phi"]), "plus", table.index[i]
    if row["uplift_minus"] < row["uplift_plus"]:  # the weaker side is "-": take the mirror
        phi, key = (phi + math.pi) % (2.0 * math.pi), "minus"
        gap = np.abs((table["phi"].to_numpy(float) - phi + math.pi) % (2.0 * math.pi)
                     - math.pi)
        if gap.min() < 1e-9:
            index = table.index[int(np.argmin(gap))]
    return Direction(phi=phi, phi_deg=math.degrees(phi), side="+",
                     alpha=float(row[f"alpha_{key}"]), uplift=float(row[f"uplift_{key}"]),
                     uplift_g=float(row[f"uplift_{key}"]) / G, index=index)


def weakest_direction(table) -> Direction:
    """The direction of the table with the smallest uplift acceleration
    ``min(uplift_plus, uplift_minus)``, named by the ``phi`` whose "+" side is the weak one
    (the convention of :class:`Direction`). The table samples the directions:
    the exact minimum is at a normal of the support hull's edge nearest to the centre of
    mass (the support function's minimum); :meth:`Shape.weakest` gives it.

    Examples
    --------
    >>> import trimesh
    >>> from rocking.shapes import Shape
    >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)), density=2000.0)
    >>> from rocking.shapes import directional_parameters, weakest_direction
    >>> d = weakest_direction(directional_parameters(box, 72))
    >>> d.phi_deg, round(d.uplift_g, 6)  # the smaller half-width: 0.2 / 1.0
    (0.0, 0.2)
    """
    return pick(table, "weakest")


def strongest_direction(table) -> Direction:
    """The direction of the table whose smaller uplift acceleration is the largest, named
    by the ``phi`` whose "+" side is the weaker of the two there (:class:`Direction`).

    Examples
    --------
    >>> import trimesh
    >>> from rocking.shapes import Shape
    >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)), density=2000.0)
    >>> from rocking.shapes import directional_parameters, strongest_direction
    >>> d = strongest_direction(directional_parameters(box, 72))  # every 5 deg
    >>> d.phi_deg, round(d.uplift_g, 2), round(float(np.hypot(0.2, 0.3)), 2)  # max b(phi)/h
    (55.0, 0.36, 0.36)
    """
    return pick(table, "strongest")


__all__ = ["COLUMNS", "Direction", "as_directions", "directional_parameters", "pick",
           "side_arrays", "strongest_direction", "weakest_direction"]


NAMED_DIRECTIONS = ("weakest", "strongest")
"""The named directions of shaking (:func:`parse_direction`)."""


def parse_direction(value):
    """One ``direction`` of shaking as given by a user: an angle, returned in rad (a bare
    number is in degrees, the unit of ``direction`` at every edge: spec, CLI,
    :meth:`rocking.Block.from_mesh`; a string may carry its unit, ``"30deg"``,
    ``"0.5rad"``), or ``"weakest"`` / ``"strongest"`` (returned as such).

    Examples
    --------
    >>> from rocking.shapes import parse_direction
    >>> round(parse_direction(30), 6), round(float(np.radians(30)), 6)  # a bare number: deg
    (0.523599, 0.523599)
    >>> parse_direction("0.5rad"), parse_direction("weakest")
    (0.5, 'weakest')
    """
    if isinstance(value, str) and value.strip().lower() in NAMED_DIRECTIONS:
        return value.strip().lower()
    if isinstance(value, bool) or not isinstance(value, int | float | str):
        raise ParameterError("direction must be an angle (a number in deg, '30deg'), "
                             f"'weakest' or 'strongest'; got {value!r}")
    if isinstance(value, str) and split_quantity(value) is None:  # a word: a misspelt name?
        import difflib

        near = difflib.get_close_matches(value.strip().lower(), NAMED_DIRECTIONS, n=1,
                                         cutoff=0.6)
        hint = f"; did you mean {near[0]!r}?" if near else ""
        raise ParameterError(f"direction: {value!r} is not a direction{hint} (an angle in "
                             "deg such as 30 or '30deg', 'weakest' or 'strongest')")
    return parse_quantity(value, "angle", name="direction", default_unit="deg")


def resolve_direction(shape, direction) -> float:
    """The angle ``phi`` (rad) of one :func:`parse_direction` result for ``shape``:
    ``"weakest"`` is :meth:`Shape.weakest` (exact: the normal of the support edge nearest
    to the centre of mass), ``"strongest"`` the largest smaller uplift acceleration over
    3600 directions refined by a bounded search, each named by the ``phi`` whose "+" side
    is the weaker one (the convention of :class:`Direction`); an angle is returned as it
    is.

    Examples
    --------
    >>> import trimesh
    >>> from rocking.shapes import Shape
    >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)), density=2000.0)
    >>> from rocking.shapes import resolve_direction
    >>> round(abs(float(np.cos(resolve_direction(box, "weakest")))), 6)  # normal to the 0.6 m face
    1.0
    >>> round(resolve_direction(box, "strongest"), 4), round(float(np.arctan(0.3 / 0.2)), 4)
    (0.9828, 0.9828)
    """
    if direction == "weakest":
        return float(shape.weakest().phi)
    if direction == "strongest":
        from scipy.optimize import minimize_scalar

        table = directional_parameters(shape, 3600)
        d = strongest_direction(table)
        step = 2.0 * math.pi / 3600

        def minus_uplift(phi):
            q = shape.parameters(phi)
            return -min(q["uplift_plus"], q["uplift_minus"])

        r = minimize_scalar(minus_uplift, bounds=(d.phi - step, d.phi + step),
                            method="bounded", options={"xatol": 1e-10})
        phi = float(r.x) if r.fun <= -d.uplift else d.phi
        q = shape.parameters(phi)
        if q["uplift_minus"] < q["uplift_plus"]:  # the side is "+" (Direction)
            phi += math.pi
        return phi % (2.0 * math.pi)
    return float(direction)

