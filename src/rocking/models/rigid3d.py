r"""A rigid body on a rigid ground plane that moves with three components of acceleration
(issue 30): unilateral contact, an isotropic Coulomb cone, impacts with Newton's law.
Rocking, wobbling, rolling, sliding, twisting, flight and landing all emerge from them.

Model
-----
The body is a :class:`rocking.shapes.Shape` (a mesh; :meth:`rocking.shapes.Shape.box` for a
box); its contact points are the vertices of its convex hull (a box: its 8 corners), which
is exact for a convex polyhedron on a plane (a plane touches a convex polyhedron at a
vertex, an edge or a face, and the forces on an edge or a face are equivalent to forces at
its vertices). A :meth:`rocking.shapes.Shape.cylinder` is exact: its contact candidates
are computed on its two rims each step (:func:`_rim_points`: the lowest point, the
opposite one and the two between; flat on its base, turned to the horizontal load). A
rectangular :class:`rocking.Block` with its ``width``, ``height`` (and
``thickness``: the depth; its width if not given) is taken as that box.

Frame: the ground's frame, which translates with the ground (it never rotates): ``x``, ``y``
horizontal, the body's axes at rest (the motion's components reach the body through
:meth:`rocking.motions.Motion.spec3`, heading ``-direction``), ``z`` up. In it the body
feels, per unit mass, ``(-a_x, -a_y, -(g + a_z))`` (``a_z`` positive upwards: gravity is
``g + a_v``), applied at the centre of mass: no torque.

State (13): ``x, y, z`` the centre of mass relative to the ground (m; at rest ``z = h``),
the quaternion ``q0..q3`` (body to ground; 1, 0, 0, 0 at rest), ``vx, vy, vz`` the centre
of mass's velocity relative to the ground (m/s) and ``wx, wy, wz`` the angular velocity in
the body's frame (rad/s).

Scheme (Moreau-Jean, midpoint, fixed step ``h``: by default ``STEP_P / p``, at most
``STEP_MAX``, from the planar-limit convergence study of ``docs/guide/rigid3d.rst``; Jean
1999, "The non-smooth contact dynamics method", Comput. Methods Appl. Mech. Engrg.
177:235-257; Acary and Brogliato 2008, "Numerical methods for nonsmooth dynamical
systems", Ch. 10). With ``L = R I w`` the
angular momentum about the centre of mass in the ground's frame (``R`` the rotation of the
quaternion, ``I`` the inertia tensor in the body's frame):

1. midpoint: ``x_M = x + h/2 v``, ``q_M = q exp(h/2 w)`` (the exact rotation of the body
   angular velocity ``w = I^-1 R^T L`` over ``h/2``), ``t_M = t + h/2``;
2. contacts: the hull's vertices whose height ``z_i = z_M + (R_M r_i)_z`` is at most
   ``gap_tol`` (1e-9 of the body's size);
3. impulses: with ``rho_i = R_M r_i`` and ``J_M^-1 = R_M I^-1 R_M^T``,
   ``v+ = v + h f(t_M) + sum P_i / m``, ``L+ = L + sum rho_i x P_i``; the velocity of
   contact ``i`` is ``U_i = v + (J_M^-1 L) x rho_i``. Newton's law on the normal,
   ``U_n+ + e min(U_n-, 0) >= 0 _|_ P_n >= 0``, and Coulomb's law on the tangential
   impulse, ``|P_t| <= mu P_n`` with ``P_t = -mu P_n U_t+ / |U_t+|`` when it slips
   (maximal dissipation), solved by projected Gauss-Seidel over the contacts (the normal
   impulse by its diagonal Delassus term, the tangential one by a projected gradient step
   on the disc ``|P_t| <= mu P_n``, whose fixed points are exactly Coulomb's law), warm
   started from the previous step's impulses, until the contact laws hold in velocity to
   ``tol`` times the free velocity. Exact shortcuts, each taken only where it satisfies
   every contact law: every contact sticking (:func:`_stick`: one 6 x 6 solve; an edge
   keeps its rotation), tried first; the iterate's loaded contacts sticking alone
   (:func:`_polish`, an active set), every 25 sweeps; the iterate's loaded contacts each
   sticking or slipping (:func:`_mixed`: a least-squares problem in the body's 6
   velocities, the guess corrected until every law holds), after 200 and 800 sweeps and
   at the last; where Gauss-Seidel still stalls, the step again with no drift gap closed
   (the plain Moreau-Jean law: the gap-closing velocities of two contacts on a line that
   is not level can contradict sticking at both); a body at rest skips the step while
   its support holds it (:func:`_holds`: the centre of pressure inside the contacts' hull,
   the load inside the friction cone; necessary and sufficient on a plane). The contact
   candidates are the vertices within reach of the ground (:func:`_candidates`).
4. end: ``x+ = x_M + h/2 v+``, ``q+ = q_M exp(h/2 w+)`` with ``w+ = R_M^T J_M^-1 L+``
   (the quaternion renormalised), and the state's ``w = I^-1 R+^T L+``.

In flight the momentum and the angular momentum ``L`` are kept exactly (to rounding) and a
constant acceleration is integrated exactly; the scheme is first order at impacts and
stick-slip transitions (Moreau-Jean is). Newton's law with ``e = 0`` (the default) makes
each impact plastic: the velocity jump is the one that minimises the kinetic energy under
the contact constraints, which in the planar limit (a box rocking about one edge onto the
other, friction sticking) conserves the angular momentum about the new edge: Housner's
Eq 4, ``mu = 1 - 1.5 sin^2(alpha)``, emerges with no parameter to calibrate
(``tests/test_rigid3d.py`` checks it).

Outputs
-------
``max_tilt`` the largest angle of the body's initial up axis from the vertical; an
*overturn* is, whichever comes first: the tilt reaching pi/2; the ground touched by a hull
vertex at least as high above the base as the centre of mass (a body that lies on another
face: the head of a fallen statue, the top corner of a box on its side); or the body held
at rest on a support that is not its base (it came to rest on another face). A vertex off
the base but lower, a bevel or a settled rock's neighbouring vertex, touched while the body
rocks, is not an overturn. The run stops there (``overturn_time``; ``overturn_azimuth``, deg, the
bearing of the fall counter-clockwise from the ground's ``x`` axis: where the tilted up
axis points); ``uplift_time`` when the body first left its rest position (a base vertex
above the ground, a slide or a twist beyond ``1e-6`` of its size, or a velocity relative to
the ground above ``1e3 tol g h``, a thousand times the contact solver's noise: a body
held by its support has none, to rounding); ``n_impacts`` the steps
at which a vertex lands with an approach speed above ``v_impact``; ``max_slide`` and
``residual_slide`` the horizontal distance of the base point (the centroid of the support
at rest, carried with the body) from where it started; ``max_twist`` (largest absolute)
and ``residual_twist`` (signed, counter-clockwise looking down) the rotation about the
vertical (the twist of the swing-twist decomposition, followed continuously);
``lifted_off`` whether the body left the ground entirely (``lift_off_time``: when it first
did; the run goes on, flight is modelled); ``settled`` at rest on its base (once the
ground is still; the run stops) or overturned; ``unconverged_steps`` (a diagnostic) the
steps whose contact problem did not reach ``tol`` in ``max_iter`` sweeps (their impulses
are the last sweep's: projected Gauss-Seidel on Coulomb's non-associated law has no
convergence guarantee; it is slow where many contacts share an indeterminate load while
slipping, a flat base sliding on many vertices; ``docs/guide/rigid3d.rst`` gives their
counts: 18 steps in the report's 64 statue runs, none in the cylinder's).

A vertex that lands between two steps may overlap the ground by up to one step's travel
(about 1e-4 of the body's size); the overlap is not removed (Newton's law acts on
velocities; a drift gap is closed only while positive), see ``docs/guide/rigid3d.rst``.
"""

from __future__ import annotations

import math
from collections import namedtuple
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from .._validate import warn_implausible
from ..errors import ParameterError
from ..motions._kernel import ground_acc3
from ..shapes.support import polygon_centroid
from ..units import G
from .base import (
    GENERIC_OUTPUTS,
    Model,
    ModelOptions,
    Output,
    option,
    row_args,
    same_block,
    store_row,
)

Rigid3dParams = namedtuple("Rigid3dParams", [
    "mass", "inertia", "inv_inertia", "verts", "is_base", "base_point", "friction",
    "restitution", "step", "tol", "max_iter", "gap_tol", "lift_tol", "v_rest", "v_impact",
    "v_up", "rim"])
Rigid3dParams.__doc__ = """The kernel parameters of :class:`Rigid3d` (SI): mass, the
inertia tensor about the centre of mass in the body's frame and its inverse, the hull's
vertices relative to the centre of mass (n, 3), 1.0 for the vertices of the base, the base
point (3,), the options and the tolerances (m, m/s; ``v_up``: the speed that marks an
uplift, :mod:`rocking.models.rigid3d`), ``rim`` (3,): a cylinder's radius and its rims'
heights from the centre of mass (radius 0: not a cylinder)."""

STEP_P = 7.5e-4
"""The default step times the body's frequency parameter ``p`` (Eq 3): the planar-limit
convergence study (``docs/guide/rigid3d.rst``) gives a largest tilt error below 1 % of the
amplitude over four impacts at ``h p = 7.5e-4``."""

STEP_MAX = 2e-4
"""The largest default step (s): the record's samples (5 to 10 ms) and the shortest pulses
are resolved at least 25 times over."""

STATUS_NONFINITE = 1
"""The state became non-finite."""


# ================================================================ compiled helpers
@njit(cache=True, inline="always")
def _rot(q0, q1, q2, q3, out):
    """The rotation matrix of a unit quaternion into ``out`` (3, 3)."""
    out[0, 0] = 1.0 - 2.0 * (q2 * q2 + q3 * q3)
    out[0, 1] = 2.0 * (q1 * q2 - q0 * q3)
    out[0, 2] = 2.0 * (q1 * q3 + q0 * q2)
    out[1, 0] = 2.0 * (q1 * q2 + q0 * q3)
    out[1, 1] = 1.0 - 2.0 * (q1 * q1 + q3 * q3)
    out[1, 2] = 2.0 * (q2 * q3 - q0 * q1)
    out[2, 0] = 2.0 * (q1 * q3 - q0 * q2)
    out[2, 1] = 2.0 * (q2 * q3 + q0 * q1)
    out[2, 2] = 1.0 - 2.0 * (q1 * q1 + q2 * q2)


@njit(cache=True, inline="always")
def _advance(q, wx, wy, wz, dt):
    """``q exp(dt w)``: the quaternion ``q`` (4,) turned in place by the body angular
    velocity ``w`` over ``dt``, renormalised."""
    wn = math.sqrt(wx * wx + wy * wy + wz * wz)
    ang = 0.5 * wn * dt
    if wn > 0.0:
        s = math.sin(ang) / wn
        c = math.cos(ang)
    else:
        s = 0.5 * dt
        c = 1.0
    r0, r1, r2, r3 = c, s * wx, s * wy, s * wz
    a0, a1, a2, a3 = q[0], q[1], q[2], q[3]
    b0 = a0 * r0 - a1 * r1 - a2 * r2 - a3 * r3
    b1 = a0 * r1 + a1 * r0 + a2 * r3 - a3 * r2
    b2 = a0 * r2 - a1 * r3 + a2 * r0 + a3 * r1
    b3 = a0 * r3 + a1 * r2 - a2 * r1 + a3 * r0
    n = math.sqrt(b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3)
    q[0], q[1], q[2], q[3] = b0 / n, b1 / n, b2 / n, b3 / n


@njit(cache=True)
def _world_inv_inertia(R, Iinv, out):
    """``R Iinv R^T`` into ``out``."""
    for i in range(3):
        for j in range(3):
            s = 0.0
            for k in range(3):
                for m in range(3):
                    s += R[i, k] * Iinv[k, m] * R[j, m]
            out[i, j] = s


@njit(cache=True, inline="always")
def _mv(A, x0, x1, x2):
    return (A[0, 0] * x0 + A[0, 1] * x1 + A[0, 2] * x2,
            A[1, 0] * x0 + A[1, 1] * x1 + A[1, 2] * x2,
            A[2, 0] * x0 + A[2, 1] * x1 + A[2, 2] * x2)


@njit(cache=True, inline="always")
def _mtv(A, x0, x1, x2):
    return (A[0, 0] * x0 + A[1, 0] * x1 + A[2, 0] * x2,
            A[0, 1] * x0 + A[1, 1] * x1 + A[2, 1] * x2,
            A[0, 2] * x0 + A[1, 2] * x1 + A[2, 2] * x2)


@njit(cache=True)
def _effect(mp, n_act, rho, P, dv, dL):
    """``dv = sum P_i / m`` and ``dL = sum rho_i x P_i`` (in place)."""
    m_inv = 1.0 / mp.mass
    dv[0] = dv[1] = dv[2] = 0.0
    dL[0] = dL[1] = dL[2] = 0.0
    for i in range(n_act):
        px, py, pz = P[i, 0], P[i, 1], P[i, 2]
        dv[0] += px * m_inv
        dv[1] += py * m_inv
        dv[2] += pz * m_inv
        rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
        dL[0] += ry * pz - rz * py
        dL[1] += rz * px - rx * pz
        dL[2] += rx * py - ry * px


@njit(cache=True)
def _residual(mp, n_act, rho, bias, P, vf, Lf, Jinv, dv, dL):
    """The largest violation (m/s) of the contact laws by the impulses ``P``: Signorini-
    Newton on the normal, Coulomb (stick inside the cone, slip opposed on its boundary) on
    the tangent. Impulses in a null space of the Delassus matrix do not count: an
    indeterminate support converges in velocity, not in impulse."""
    mu = mp.friction
    wx, wy, wz = _mv(Jinv, Lf[0] + dL[0], Lf[1] + dL[1], Lf[2] + dL[2])
    resid = 0.0
    for i in range(n_act):
        rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
        ux = vf[0] + dv[0] + wy * rz - wz * ry
        uy = vf[1] + dv[1] + wz * rx - wx * rz
        un = vf[2] + dv[2] + wx * ry - wy * rx + bias[i]
        pn = P[i, 2]
        if pn < 0.0:
            return math.inf
        r = abs(un) if pn > 0.0 else max(0.0, -un)
        ut = math.sqrt(ux * ux + uy * uy)
        pt = math.sqrt(P[i, 0] ** 2 + P[i, 1] ** 2)
        if pt > mu * pn * (1.0 + 1e-12):
            return math.inf  # outside the cone
        if pn == 0.0 or mu == 0.0:
            pass  # no normal impulse: no friction, any slip
        elif pt < mu * pn * (1.0 - 1e-12):
            r = max(r, ut)  # sticking: no slip
        else:  # slipping: the friction impulse opposes the slip
            r = max(r, math.sqrt((ux + ut * P[i, 0] / pt) ** 2
                                 + (uy + ut * P[i, 1] / pt) ** 2))
        resid = max(resid, r)
    return resid


@njit(cache=True)
def _accept(mp, n_act, rho, bias, Pc, vf, Lf, Jinv, dv2, dL2, vscale, P, dv, dL):
    """Whether the candidate impulses ``Pc`` satisfy every contact law to ``tol`` (their
    velocity changes into ``dv2``, ``dL2``); if so they become the step's ``P``, ``dv``,
    ``dL``."""
    _effect(mp, n_act, rho, Pc, dv2, dL2)
    if not _residual(mp, n_act, rho, bias, Pc, vf, Lf, Jinv, dv2, dL2) <= mp.tol * vscale:
        return False  # (a NaN residual too)
    for i in range(n_act):
        P[i, 0], P[i, 1], P[i, 2] = Pc[i, 0], Pc[i, 1], Pc[i, 2]
    for a in range(3):
        dv[a], dL[a] = dv2[a], dL2[a]
    return True


@njit(cache=True)
def _chol_solve(S, b, n):
    """Solve ``S x = b`` in place of ``b`` for a symmetric positive definite ``S`` (n, n)
    by Cholesky (``S`` overwritten); False if ``S`` is singular (a pivot below 1e-12 of
    the largest diagonal term)."""
    big = 0.0
    for i in range(n):
        big = max(big, S[i, i])
    for j in range(n):
        d = S[j, j]
        for k in range(j):
            d -= S[j, k] * S[j, k]
        if not d > 1e-12 * big:
            return False
        d = math.sqrt(d)
        S[j, j] = d
        for i in range(j + 1, n):
            x = S[i, j]
            for k in range(j):
                x -= S[i, k] * S[j, k]
            S[i, j] = x / d
    for i in range(n):  # L y = b
        x = b[i]
        for k in range(i):
            x -= S[i, k] * b[k]
        b[i] = x / S[i, i]
    for i in range(n - 1, -1, -1):  # L^T x = y
        x = b[i]
        for k in range(i + 1, n):
            x -= S[k, i] * b[k]
        b[i] = x / S[i, i]
    return True


@njit(cache=True)
def _add_line(S, N):
    """``S += N N^T`` (6 x 6)."""
    for a in range(6):
        for b in range(6):
            S[a, b] += N[a] * N[b]


@njit(cache=True)
def _stick(mp, n_act, rho, bias, vf, Lf, J, P, S, y, S2, lam, H, W, N):
    """The impulses ``P`` (in place) if every contact sticks; False if the contacts do not
    hold the body (fewer than two). With ``H_i`` the map from the body's velocity ``(v, w)``
    to contact ``i``'s (``v + w x rho_i``) and ``S = sum H_i^T H_i`` (6 x 6): the body's
    velocity that stops every contact, ``U_i + bias_i e_z = 0``, is
    ``S^-1 sum H_i^T (-bias_i e_z)`` (0 without bias). Contacts on one line (an edge: two
    corners) leave the rotation about it free, ``N = (rho_0 x e, e)``: ``N N^T`` is added
    to ``S`` (which does not change the stopping velocities, ``H_i N = 0``), and the
    velocity is the stopping one plus the rotation about the edge that keeps the momentum
    along ``N`` (the kinetic metric's projection). The generalized impulse ``Lam`` that
    brings the free motion there (``m dv``, ``J dw - dL``) is spread over the contacts with
    the least norm, ``P_i = H_i S^-1 Lam``. A candidate only: the caller checks it against
    the contact laws (:func:`_residual`). ``J``: the inertia tensor in the ground's frame;
    ``S``, ``y``, ``S2``, ``lam``, ``H``, ``W``, ``N``: work arrays (6, 6), (6,), (6, 6),
    (6,), (3, 6), (n,), (6,)."""
    if n_act < 2:
        return False
    for a in range(6):
        y[a] = 0.0
        for b in range(6):
            S[a, b] = 0.0
    for i in range(n_act):
        rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
        r2 = rx * rx + ry * ry + rz * rz
        # H_i^T H_i = [[I, -[r]x], [[r]x, |r|^2 I - r r^T]]
        S[0, 0] += 1.0
        S[1, 1] += 1.0
        S[2, 2] += 1.0
        # -[r]x in the upper right block: -[[0, -rz, ry], [rz, 0, -rx], [-ry, rx, 0]]
        S[0, 4] += rz
        S[0, 5] -= ry
        S[1, 3] -= rz
        S[1, 5] += rx
        S[2, 3] += ry
        S[2, 4] -= rx
        S[3, 3] += r2 - rx * rx
        S[4, 4] += r2 - ry * ry
        S[5, 5] += r2 - rz * rz
        S[3, 4] -= rx * ry
        S[3, 5] -= rx * rz
        S[4, 5] -= ry * rz
        # right-hand side: -H_i^T (bias_i e_z) = -(b e_z ; b rho x e_z)
        b = bias[i]
        y[2] -= b
        y[3] -= b * ry
        y[4] += b * rx
    for a in range(6):  # the symmetric lower triangle
        for b in range(a):
            S[a, b] = S[b, a]
    for a in range(6):
        lam[a] = y[a]
        for b in range(6):
            S2[a, b] = S[a, b]
    line = n_act == 2 or not _chol_solve(S, y, 6)
    if line:  # the contacts on one line: its direction e from the farthest pair
        j = 1
        dmax = 0.0
        for i in range(1, n_act):
            d = ((rho[i, 0] - rho[0, 0]) ** 2 + (rho[i, 1] - rho[0, 1]) ** 2
                 + (rho[i, 2] - rho[0, 2]) ** 2)
            if d > dmax:
                dmax, j = d, i
        if not dmax > 0.0:
            return False
        dl = math.sqrt(dmax)
        ex = (rho[j, 0] - rho[0, 0]) / dl
        ey = (rho[j, 1] - rho[0, 1]) / dl
        ez = (rho[j, 2] - rho[0, 2]) / dl
        rx, ry, rz = rho[0, 0], rho[0, 1], rho[0, 2]
        N[0], N[1], N[2] = ry * ez - rz * ey, rz * ex - rx * ez, rx * ey - ry * ex
        N[3], N[4], N[5] = ex, ey, ez
        _add_line(S2, N)
        for a in range(6):
            y[a] = lam[a]
            for b in range(6):
                S[a, b] = S2[a, b]
        if not _chol_solve(S, y, 6):
            return False
        # the rotation about the line that keeps the momentum along N
        jx, jy, jz = _mv(J, y[3], y[4], y[5])
        num = mp.mass * (N[0] * (vf[0] - y[0]) + N[1] * (vf[1] - y[1])
                         + N[2] * (vf[2] - y[2])) \
            + N[3] * (Lf[0] - jx) + N[4] * (Lf[1] - jy) + N[5] * (Lf[2] - jz)
        jx, jy, jz = _mv(J, ex, ey, ez)
        den = mp.mass * (N[0] ** 2 + N[1] ** 2 + N[2] ** 2) + ex * jx + ey * jy + ez * jz
        sN = num / den
        for a in range(6):
            y[a] += sN * N[a]
    # the generalized impulse: m (v+ - vf), J w+ - L
    wx, wy, wz = _mv(J, y[3], y[4], y[5])
    y[0] = mp.mass * (y[0] - vf[0])
    y[1] = mp.mass * (y[1] - vf[1])
    y[2] = mp.mass * (y[2] - vf[2])
    y[3], y[4], y[5] = wx - Lf[0], wy - Lf[1], wz - Lf[2]
    for a in range(6):
        lam[a] = y[a]
    _chol_solve(S2, y, 6)
    for i in range(n_act):  # P_i = H_i y = y_v + y_w x rho_i
        rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
        P[i, 0] = y[0] + y[4] * rz - y[5] * ry
        P[i, 1] = y[1] + y[5] * rx - y[3] * rz
        P[i, 2] = y[2] + y[3] * ry - y[4] * rx
    # the least norm spreads friction evenly, also where the load is light: spread it in
    # proportion to the normal impulses instead (a weighted least norm, P_i = W_i H_i y
    # with S_w = sum H_i^T W_i H_i), which fits in the cones whenever an even utilisation
    # of friction does
    for a in range(3):
        for b in range(6):
            H[a, b] = 0.0
    for _ in range(3):
        pn_mean = 0.0
        fits = True
        for i in range(n_act):
            pn_mean += max(P[i, 2], 0.0) / n_act
            pt = math.sqrt(P[i, 0] ** 2 + P[i, 1] ** 2)
            if P[i, 2] < 0.0 or pt > mp.friction * P[i, 2]:
                fits = False
        if fits or not pn_mean > 0.0:
            break
        for a in range(6):
            for b in range(6):
                S[a, b] = 0.0
        for i in range(n_act):
            rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
            H[0, 0], H[1, 1], H[2, 2] = 1.0, 1.0, 1.0
            H[0, 4], H[0, 5] = rz, -ry
            H[1, 3], H[1, 5] = -rz, rx
            H[2, 3], H[2, 4] = ry, -rx
            wt = max(P[i, 2], 1e-6 * pn_mean) / pn_mean
            for a in range(6):
                for b in range(6):
                    S[a, b] += wt * (H[0, a] * H[0, b] + H[1, a] * H[1, b]) \
                        + H[2, a] * H[2, b]
            W[i] = wt
        if line:
            _add_line(S, N)
        for a in range(6):
            y[a] = lam[a]
        if not _chol_solve(S, y, 6):
            return True
        for i in range(n_act):
            rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
            P[i, 0] = W[i] * (y[0] + y[4] * rz - y[5] * ry)
            P[i, 1] = W[i] * (y[1] + y[5] * rx - y[3] * rz)
            P[i, 2] = y[2] + y[3] * ry - y[4] * rx
    return True


@njit(cache=True)
def _stick_set(mp, m, rho_s, bias_s, vf, Lf, Jinv, J, P_s, ws6, ws, wn, N):
    """The impulses ``P_s`` of the contacts ``0..m-1`` all sticking (:func:`_stick`; one
    contact: its 3 x 3 Delassus block); False if they do not hold the body."""
    if m == 1:
        rx, ry, rz = rho_s[0, 0], rho_s[0, 1], rho_s[0, 2]
        m_inv = 1.0 / mp.mass
        S = ws6[0]
        b = ws[0]
        # W = I / m + [rho]x^T Jinv [rho]x by columns: W e = e / m + (Jinv (rho x e)) x rho
        for c in range(3):
            ex = 1.0 if c == 0 else 0.0
            ey = 1.0 if c == 1 else 0.0
            ez = 1.0 if c == 2 else 0.0
            jx, jy, jz = _mv(Jinv, ry * ez - rz * ey, rz * ex - rx * ez, rx * ey - ry * ex)
            S[0, c] = ex * m_inv + jy * rz - jz * ry
            S[1, c] = ey * m_inv + jz * rx - jx * rz
            S[2, c] = ez * m_inv + jx * ry - jy * rx
        for a in range(3):
            for c in range(a):
                S[a, c] = S[c, a] = 0.5 * (S[a, c] + S[c, a])
        wx, wy, wz = _mv(Jinv, Lf[0], Lf[1], Lf[2])
        b[0] = -(vf[0] + wy * rz - wz * ry)
        b[1] = -(vf[1] + wz * rx - wx * rz)
        b[2] = -(vf[2] + wx * ry - wy * rx + bias_s[0])
        if not _chol_solve(S, b, 3):
            return False
        P_s[0, 0], P_s[0, 1], P_s[0, 2] = b[0], b[1], b[2]
        return True
    return _stick(mp, m, rho_s, bias_s, vf, Lf, J, P_s, ws6[0], ws[0], ws6[1], ws[1],
                  ws6[2][:3], wn, N)


@njit(cache=True)
def _polish(mp, n_act, rho, bias, P, vf, Lf, Jinv, J, dv, dL, vscale, ws6, ws, wn, N, sub):
    """Active-set polishing of a Gauss-Seidel iterate ``P``: the contacts it loads
    (``P_n > 0``) all sticking (:func:`_stick`; one contact: its 3 x 3 Delassus block),
    the others free, dropping the one that pulls most until none pulls. Where that
    satisfies every contact's laws to ``tol`` it is a solution, exact: ``P``, ``dv``,
    ``dL`` are set to it (True). A body that starts to
    rock on the edge of a base of many vertices is solved so; Gauss-Seidel alone spends
    thousands of sweeps on the unloaded ones. ``sub``: the work arrays (rho, bias, P,
    candidate P, index, dv, dL)."""
    rho_s, bias_s, P_s, Pc, sidx, dv2, dL2 = sub
    m = 0
    for i in range(n_act):
        if P[i, 2] > 0.0:
            sidx[m] = i
            rho_s[m, 0], rho_s[m, 1], rho_s[m, 2] = rho[i, 0], rho[i, 1], rho[i, 2]
            bias_s[m] = bias[i]
            m += 1
    if m == 0 or m == n_act:  # all loaded: the caller tried them all sticking
        return False
    for _ in range(n_act):  # drop the contact that pulls most, and solve again
        if not _stick_set(mp, m, rho_s, bias_s, vf, Lf, Jinv, J, P_s, ws6, ws, wn, N):
            return False
        worst = -1
        for c in range(m):
            if P_s[c, 2] < 0.0 and (worst < 0 or P_s[c, 2] < P_s[worst, 2]):
                worst = c
        if worst < 0:  # none pulls: a solution if every contact's laws hold
            for i in range(n_act):
                Pc[i, 0] = Pc[i, 1] = Pc[i, 2] = 0.0
            for c in range(m):
                i = sidx[c]
                Pc[i, 0], Pc[i, 1], Pc[i, 2] = P_s[c, 0], P_s[c, 1], P_s[c, 2]
            if _accept(mp, n_act, rho, bias, Pc, vf, Lf, Jinv, dv2, dL2, vscale, P, dv, dL):
                return True
            # not a solution (a contact outside its cone, or one pressed into the ground
            # by the others: the set holds the body too much): drop the least loaded one
            # of a set of at most three. Neighbouring vertices of a many-sided base share
            # a load that Gauss-Seidel shifts between them slowly, while the body pivots
            # on one of them (a larger set: a sliding base, which no sticking set solves)
            if m > 3:
                return False
            for c in range(m):
                if worst < 0 or P_s[c, 2] < P_s[worst, 2]:
                    worst = c
        if m == 1:
            return False
        m -= 1
        for c in range(worst, m):
            sidx[c] = sidx[c + 1]
            rho_s[c, 0], rho_s[c, 1], rho_s[c, 2] = rho_s[c + 1, 0], rho_s[c + 1, 1], \
                rho_s[c + 1, 2]
            bias_s[c] = bias_s[c + 1]
    return False


@njit(cache=True)
def _mixed_from(mp, n_act, rho, bias, P, vf, Lf, Jinv, dv, dL, vscale, mx, strict):
    """The corrections of :func:`_mixed` from the guess in ``mx`` (status: 0 free, 1
    sticking, 2 slipping, and the slipping contacts' friction directions); ``strict``:
    only the friction directions are corrected, a wrong status fails."""
    status, dirs, C, r, Pc, Q, dv2, dL2 = mx[0], mx[1], mx[2], mx[3], mx[4], mx[5], mx[6], mx[7]
    mu = mp.friction
    m_inv = 1.0 / mp.mass
    wfx, wfy, wfz = _mv(Jinv, Lf[0], Lf[1], Lf[2])
    for _ in range(12):
        # Q = G G^T: sum over sticking contacts of H_i^T H_i, over slipping ones g g^T
        for a in range(6):
            for b in range(6):
                Q[a, b] = 0.0
        k = 0
        for i in range(n_act):
            if status[i] == 0:
                continue
            rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
            for part in range(3):
                # the rows h of u = v + w x rho: hx, hy, hz
                C[k, 0] = 1.0 if part == 0 else 0.0
                C[k, 1] = 1.0 if part == 1 else 0.0
                C[k, 2] = 1.0 if part == 2 else 0.0
                if part == 0:
                    C[k, 3], C[k, 4], C[k, 5] = 0.0, rz, -ry
                elif part == 1:
                    C[k, 3], C[k, 4], C[k, 5] = -rz, 0.0, rx
                else:
                    C[k, 3], C[k, 4], C[k, 5] = ry, -rx, 0.0
                k += 1
            k -= 3
            if status[i] == 1:
                for part in range(3):
                    for a in range(6):
                        for b in range(6):
                            Q[a, b] += C[k + part, a] * C[k + part, b]
            else:
                dx, dy = mu * dirs[i, 0], mu * dirs[i, 1]
                for a in range(6):
                    ga = C[k + 2, a] + dx * C[k, a] + dy * C[k + 1, a]
                    for b in range(6):
                        Q[a, b] += ga * (C[k + 2, b] + dx * C[k, b] + dy * C[k + 1, b])
            k += 3
        if k == 0:
            return False
        # the constrained rows A B with B = M^-1 Q, and r = -(A V_f + bias)
        k = 0
        for i in range(n_act):
            if status[i] == 0:
                continue
            rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
            ufx = vf[0] + wfy * rz - wfz * ry
            ufy = vf[1] + wfz * rx - wfx * rz
            ufz = vf[2] + wfx * ry - wfy * rx + bias[i]
            first = 0 if status[i] == 1 else 2
            for part in range(first, 3):
                hx, hy, hz = (1.0 if part == 0 else 0.0), (1.0 if part == 1 else 0.0), \
                    (1.0 if part == 2 else 0.0)
                if part == 0:
                    h3, h4, h5 = 0.0, rz, -ry
                elif part == 1:
                    h3, h4, h5 = -rz, 0.0, rx
                else:
                    h3, h4, h5 = ry, -rx, 0.0
                # (h^T M^-1) = (h_v / m, Jinv h_w) (Jinv symmetric), then times Q
                j3, j4, j5 = _mv(Jinv, h3, h4, h5)
                for b in range(6):
                    C[k, b] = (hx * Q[0, b] + hy * Q[1, b] + hz * Q[2, b]) * m_inv \
                        + j3 * Q[3, b] + j4 * Q[4, b] + j5 * Q[5, b]
                r[k] = -(ufx if part == 0 else (ufy if part == 1 else ufz))
                k += 1
        w = np.linalg.lstsq(C[:k], r[:k], 1e-12)[0]
        # lam = G^T w
        for i in range(n_act):
            Pc[i, 0] = Pc[i, 1] = Pc[i, 2] = 0.0
            if status[i] == 0:
                continue
            rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
            px = w[0] + w[4] * rz - w[5] * ry
            py = w[1] + w[5] * rx - w[3] * rz
            pz = w[2] + w[3] * ry - w[4] * rx
            if status[i] == 1:
                Pc[i, 0], Pc[i, 1], Pc[i, 2] = px, py, pz
            else:
                pn = pz + mu * (dirs[i, 0] * px + dirs[i, 1] * py)
                Pc[i, 0], Pc[i, 1], Pc[i, 2] = mu * pn * dirs[i, 0], mu * pn * dirs[i, 1], pn
        # contacts that pull are freed
        pulls = False
        for i in range(n_act):
            if status[i] != 0 and Pc[i, 2] < 0.0:
                pulls = True
                if not strict:
                    status[i] = 0
        if pulls:
            if strict:
                return False
            continue
        if _accept(mp, n_act, rho, bias, Pc, vf, Lf, Jinv, dv2, dL2, vscale, P, dv, dL):
            return True
        # correct the guess from the contacts' velocities
        wx, wy, wz = _mv(Jinv, Lf[0] + dL2[0], Lf[1] + dL2[1], Lf[2] + dL2[2])
        changed = False
        for i in range(n_act):
            rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
            ux = vf[0] + dv2[0] + wy * rz - wz * ry
            uy = vf[1] + dv2[1] + wz * rx - wx * rz
            un = vf[2] + dv2[2] + wx * ry - wy * rx + bias[i]
            ut = math.sqrt(ux * ux + uy * uy)
            if status[i] == 1:
                pt = math.sqrt(Pc[i, 0] ** 2 + Pc[i, 1] ** 2)
                if pt > mu * Pc[i, 2]:
                    if strict:
                        return False
                    status[i] = 2
                    dirs[i, 0], dirs[i, 1] = Pc[i, 0] / pt, Pc[i, 1] / pt
                    changed = True
            elif status[i] == 2:
                if ut > 0.0:
                    dx, dy = -ux / ut, -uy / ut
                    if dx * dirs[i, 0] + dy * dirs[i, 1] < 0.0:  # the slip reversed: sticks
                        if strict:
                            return False
                        status[i] = 1
                    else:
                        dirs[i, 0], dirs[i, 1] = dx, dy
                    changed = True
            elif un < -mp.tol * vscale:  # a free contact that penetrates
                if strict:
                    return False
                status[i] = 1
                changed = True
        if not changed:
            return False
    return False


@njit(cache=True)
def _mixed(mp, n_act, rho, bias, P, vf, Lf, Jinv, dv, dL, vscale, mx, search):
    """Active-set polishing with sticking *and* slipping contacts: from a Gauss-Seidel
    iterate ``P``, each loaded contact sticks (inside its cone) or slips (on the cone,
    its friction along the iterate's ``P_t``), the others are free. For that guess the
    laws are linear: a sticking contact's velocity is zero, a slipping one's normal
    velocity is zero and its impulse is ``P_n (e_z + mu d_i)``. With ``G`` the
    generalized impulse directions (6 x k) and ``A`` the constrained velocity rows
    (k x 6), the impulses ``lam`` solve ``A M^-1 G lam = r``; the least-norm solution
    lies in the range of ``G^T``, so ``lam = G^T w`` with ``w`` (6) the least-squares
    solution of ``(A M^-1 G G^T) w = r`` (a k x 6 problem, rank-deficient where many
    contacts share an indeterminate load: ``lstsq`` takes the least norm). The guess
    is then corrected (the contacts that pull are freed, a sticking one outside its cone
    slips, a slipping one turns its friction against its slip, a free one that
    penetrates sticks) until every contact's law holds to ``tol`` (True: ``P``, ``dv``,
    ``dL`` set to it, exact) or 12 corrections are spent (False, ``P`` unchanged).
    Gauss-Seidel converges slowly where a body pivots on one vertex of a many-sided
    base while a neighbouring one slips at the cone. ``mx``: work arrays (status (n,),
    directions (n, 2), rows (3n, 6), right-hand side (3n,), impulses (n, 3), 6 x 6,
    dv, dL, loaded indices (n,)).

    Tried where the iterate loads at most 8 contacts (each try is a least-squares
    problem; a base sliding on many vertices is left to Gauss-Seidel). Where the
    iterate's guess fails, it loads at most three contacts and ``search`` is
    True, every status
    of those (free, sticking, slipping: at most 26) is tried in turn, the friction of a
    slipping one against the iterate's slip, then along the iterate's friction (a body
    pivoting on an edge whose iterate has the stick and the slip of its two ends
    swapped)."""
    status, dirs = mx[0], mx[1]
    loaded = mx[8]
    mu = mp.friction
    wx, wy, wz = _mv(Jinv, Lf[0] + dL[0], Lf[1] + dL[1], Lf[2] + dL[2])
    m = 0
    for i in range(n_act):
        status[i] = 0
        pn = P[i, 2]
        if pn > 0.0:
            loaded[m] = i
            m += 1
            pt = math.sqrt(P[i, 0] ** 2 + P[i, 1] ** 2)
            if pt > 0.0 and pt >= mu * pn * (1.0 - 1e-6):
                status[i] = 2
                dirs[i, 0], dirs[i, 1] = P[i, 0] / pt, P[i, 1] / pt
            else:
                status[i] = 1
    if m > 8:  # a sliding base of many vertices: Gauss-Seidel is the cheaper way
        return False
    if _mixed_from(mp, n_act, rho, bias, P, vf, Lf, Jinv, dv, dL, vscale, mx, False):
        return True
    if not search or m == 0 or m > 3:
        return False
    n_codes = 3 ** m
    for code in range(1, 2 * n_codes):
        for i in range(n_act):
            status[i] = 0
        cc = code % n_codes
        slips = False
        for j in range(m):
            i = loaded[j]
            status[i] = cc % 3
            cc //= 3
            if status[i] == 2:  # against the iterate's slip, or along its friction
                slips = True
                rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
                ux = vf[0] + dv[0] + wy * rz - wz * ry
                uy = vf[1] + dv[1] + wz * rx - wx * rz
                ut = math.sqrt(ux * ux + uy * uy)
                pt = math.sqrt(P[i, 0] ** 2 + P[i, 1] ** 2)
                if ut > 0.0 and (code < n_codes or not pt > 0.0):
                    dirs[i, 0], dirs[i, 1] = -ux / ut, -uy / ut
                elif pt > 0.0:
                    dirs[i, 0], dirs[i, 1] = P[i, 0] / pt, P[i, 1] / pt
                else:
                    dirs[i, 0], dirs[i, 1] = 1.0, 0.0
        if code % n_codes == 0 or (code >= n_codes and not slips):
            continue
        if _mixed_from(mp, n_act, rho, bias, P, vf, Lf, Jinv, dv, dL, vscale, mx, True):
            return True
    return False


@njit(cache=True)
def _solve_contacts(mp, n_act, rho, bias, P, vf, Lf, Jinv, J, dv, dL, wnn, wt, Pw, ws6, ws,
                    wn, sub, mx):
    """Projected Gauss-Seidel on the contacts ``0..n_act-1`` (lever arms ``rho``, normal
    laws ``U_n+ + bias >= 0 _|_ P_n >= 0``, impulses ``P`` warm-started and updated in
    place), for the free velocities ``vf`` and momentum ``Lf``: the velocity change ``dv``
    and momentum change ``dL`` (in place; ``J`` the inertia tensor in the ground's frame,
    ``Jinv`` its inverse; ``wnn``, ``wt``, ``Pw``, ``ws6`` (3, 6, 6), ``ws`` (2, 6), ``wn``
    (n,), ``sub`` (:func:`_polish`): work arrays). With two contacts or more, the solution
    with every contact sticking (:func:`_stick`) is tried first: exact when it satisfies
    the laws (a body held still by its support converges slowly in Gauss-Seidel). Returns
    the number of sweeps (0: the sticking solution held; -1: not converged in ``max_iter``
    sweeps, the impulses are the last sweep's). After 5 sweeps and every 25, the
    iterate's loaded contacts are tried alone (:func:`_polish`)."""
    m_inv = 1.0 / mp.mass
    mu = mp.friction
    # diagonal Delassus terms W_ii = 1/m + [rho]x^T Jinv [rho]x: the normal one, the
    # largest eigenvalue of the tangential 2 x 2 block and that block's inverse
    vscale = 0.0
    for i in range(n_act):
        rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
        # W e_x: (Jinv (rho x e_x)) x rho + e_x / m, rho x e_x = (0, rz, -ry)
        jx, jy, jz = _mv(Jinv, 0.0, rz, -ry)
        w00 = m_inv + (jy * rz - jz * ry)
        w10 = jz * rx - jx * rz
        jx, jy, jz = _mv(Jinv, -rz, 0.0, rx)  # rho x e_y
        w01 = jy * rz - jz * ry
        w11 = m_inv + (jz * rx - jx * rz)
        jx, jy, jz = _mv(Jinv, ry, -rx, 0.0)  # rho x e_z
        wnn[i] = m_inv + (jx * ry - jy * rx)
        b_ = 0.5 * (w01 + w10)
        wt[i, 0] = 0.5 * (w00 + w11) + math.sqrt(0.25 * (w00 - w11) ** 2 + b_ * b_)
        det = w00 * w11 - b_ * b_
        wt[i, 1], wt[i, 2], wt[i, 3] = w11 / det, -b_ / det, w00 / det  # W_tt^-1
        vscale += abs(bias[i])
    vscale += math.sqrt(vf[0] ** 2 + vf[1] ** 2 + vf[2] ** 2) + 1e-300
    if n_act >= 2:  # a support that may hold the body still: try every contact sticking
        for i in range(n_act):
            Pw[i, 0], Pw[i, 1], Pw[i, 2] = P[i, 0], P[i, 1], P[i, 2]
        if _stick(mp, n_act, rho, bias, vf, Lf, J, P, ws6[0], ws[0], ws6[1], ws[1],
                  ws6[2][:3], wn, ws6[2][3]):
            _effect(mp, n_act, rho, P, dv, dL)
            if _residual(mp, n_act, rho, bias, P, vf, Lf, Jinv, dv, dL) <= mp.tol * vscale:
                return 0
        for i in range(n_act):  # not a solution: Gauss-Seidel from the warm start
            P[i, 0], P[i, 1], P[i, 2] = Pw[i, 0], Pw[i, 1], Pw[i, 2]
    _effect(mp, n_act, rho, P, dv, dL)  # the warm start's effect
    sweeps = 0
    while sweeps < mp.max_iter:
        sweeps += 1
        for i in range(n_act):
            rx, ry, rz = rho[i, 0], rho[i, 1], rho[i, 2]
            for part in range(2):  # 0: normal, 1: tangential
                wx, wy, wz = _mv(Jinv, Lf[0] + dL[0], Lf[1] + dL[1], Lf[2] + dL[2])
                ux = vf[0] + dv[0] + wy * rz - wz * ry
                uy = vf[1] + dv[1] + wz * rx - wx * rz
                uz = vf[2] + dv[2] + wx * ry - wy * rx
                px, py, pz = P[i, 0], P[i, 1], P[i, 2]
                if part == 0:
                    target = uz + bias[i]
                    nz = max(0.0, pz - target / wnn[i])
                    nx, ny = px, py
                    lim = mu * nz
                    tn = math.sqrt(nx * nx + ny * ny)
                    if tn > lim:  # the cone shrank with the normal impulse
                        f = lim / tn if tn > 0.0 else 0.0
                        nx, ny = nx * f, ny * f
                else:
                    nz = pz
                    lim = mu * nz
                    nx = px - (wt[i, 1] * ux + wt[i, 2] * uy)  # sticking: u_t+ = 0
                    ny = py - (wt[i, 2] * ux + wt[i, 3] * uy)
                    if nx * nx + ny * ny > lim * lim:  # slipping: a projected gradient step
                        nx = px - ux / wt[i, 0]
                        ny = py - uy / wt[i, 0]
                        tn = math.sqrt(nx * nx + ny * ny)
                        if tn > lim:
                            f = lim / tn
                            nx, ny = nx * f, ny * f
                ddx, ddy, ddz = nx - px, ny - py, nz - pz
                if ddx == 0.0 and ddy == 0.0 and ddz == 0.0:
                    continue
                P[i, 0], P[i, 1], P[i, 2] = nx, ny, nz
                dv[0] += ddx * m_inv
                dv[1] += ddy * m_inv
                dv[2] += ddz * m_inv
                dL[0] += ry * ddz - rz * ddy
                dL[1] += rz * ddx - rx * ddz
                dL[2] += rx * ddy - ry * ddx
        resid = _residual(mp, n_act, rho, bias, P, vf, Lf, Jinv, dv, dL)
        if resid <= mp.tol * vscale:
            return sweeps
        if n_act > 1 and (sweeps == 5 or sweeps % 25 == 0) and \
                _polish(mp, n_act, rho, bias, P, vf, Lf, Jinv, J, dv, dL, vscale, ws6, ws, wn,
                        ws6[2][3], sub):
            return sweeps
        if (sweeps == 200 or sweeps == 800 or sweeps == mp.max_iter) and \
                _mixed(mp, n_act, rho, bias, P, vf, Lf, Jinv, dv, dL, vscale, mx, True):
            return sweeps
    return -1


@njit(cache=True)
def _rim_points(mp, R, ax, ay, dirb, out):
    """The contact candidates of a cylinder (``mp.rim`` = radius, bottom and top heights
    from the centre of mass) in the body's frame into ``out`` (8, 3): on each rim, the
    lowest point (exact: along the body-frame direction of steepest descent of the rim's
    plane, ``-(R_zx, R_zy)``), the highest and the two between. Where the base is flat to
    ``gap_tol`` (the direction is undefined), the direction is that of the horizontal
    inertial load ``-(ax, ay)`` in the body's frame (the rim point where the centre of
    pressure goes), else the last one (``dirb`` (2,), kept in place)."""
    rad = mp.rim[0]
    sx, sy = -R[2, 0], -R[2, 1]
    n = math.sqrt(sx * sx + sy * sy)
    if 2.0 * rad * n <= mp.gap_tol:
        bx = -(R[0, 0] * ax + R[1, 0] * ay)
        by = -(R[0, 1] * ax + R[1, 1] * ay)
        nb = math.sqrt(bx * bx + by * by)
        if nb > 0.0:
            dirb[0], dirb[1] = bx / nb, by / nb
        elif n > 0.0:
            dirb[0], dirb[1] = sx / n, sy / n
    else:
        dirb[0], dirb[1] = sx / n, sy / n
    c, s = rad * dirb[0], rad * dirb[1]
    for k in range(2):
        zr = mp.rim[1 + k]
        j = 4 * k
        out[j, 0], out[j, 1], out[j, 2] = c, s, zr
        out[j + 1, 0], out[j + 1, 1], out[j + 1, 2] = -c, -s, zr
        out[j + 2, 0], out[j + 2, 1], out[j + 2, 2] = -s, c, zr
        out[j + 3, 0], out[j + 3, 1], out[j + 3, 2] = s, -c, zr


@njit(cache=True)
def _candidates(verts, R, z, reach, was_active, cand):
    """The vertices within ``reach`` of the ground (or in contact at the last step) into
    ``cand``; their number. Only they can touch it while the vertices' vertical travel
    since this call stays below ``reach`` (the kernel rebuilds the list before)."""
    n = 0
    for i in range(verts.shape[0]):
        zi = z + R[2, 0] * verts[i, 0] + R[2, 1] * verts[i, 1] + R[2, 2] * verts[i, 2]
        if zi <= reach or was_active[i]:
            cand[n] = i
            n += 1
    return n


@njit(cache=True)
def _rest_polygon(rho, n_act, hp, tmp, order):
    """The convex hull (Andrew's monotone chain) of the contacts' horizontal positions
    ``rho[:n_act, :2]`` (from the centre of mass) as half-planes ``nx x + ny y <= d`` in
    ``hp`` (rows nx, ny, d; ``tmp`` (n, 2), ``order`` (n,) work); their number (0: fewer
    than three points not on a line)."""
    if n_act < 3:
        return 0
    keys = np.empty(n_act)
    for i in range(n_act):
        keys[i] = rho[i, 0] * 1e6 + rho[i, 1]
    srt = np.argsort(keys)
    for i in range(n_act):
        order[i] = srt[i]
    m = 0
    for half in range(2):
        start = m
        for jj in range(n_act):
            j = order[jj] if half == 0 else order[n_act - 1 - jj]
            px, py = rho[j, 0], rho[j, 1]
            while m >= start + 2:
                ox, oy = tmp[m - 2, 0], tmp[m - 2, 1]
                ax_, ay_ = tmp[m - 1, 0], tmp[m - 1, 1]
                if (ax_ - ox) * (py - oy) - (ay_ - oy) * (px - ox) <= 0.0:
                    m -= 1
                else:
                    break
            tmp[m, 0], tmp[m, 1] = px, py
            m += 1
        m -= 1  # the last point is the next chain's first
    if m < 3:
        return 0
    for i in range(m):
        x0, y0 = tmp[i, 0], tmp[i, 1]
        x1, y1 = tmp[(i + 1) % m, 0], tmp[(i + 1) % m, 1]
        nx, ny = y1 - y0, x0 - x1  # outward for a counter-clockwise ring
        ln = math.sqrt(nx * nx + ny * ny)
        if ln == 0.0:
            return 0
        hp[i, 0], hp[i, 1], hp[i, 2] = nx / ln, ny / ln, (nx * x0 + ny * y0) / ln
    return m


@njit(cache=True)
def _holds(mp, n_hp, hp, z, ax, ay, az, margin):
    """Whether a body at rest on its contacts (half-planes ``hp``, or the disc of a
    cylinder's base) stays at rest under the ground acceleration: the resultant of its
    weight and inertial force, through the centre of mass (height ``z``), meets the ground
    inside the contacts' hull (the centre of pressure: a distribution of positive normal
    forces exists) and its horizontal part is within the friction cone (friction in
    proportion to the normal forces then balances it, moments included). Exact for
    contacts on the ground plane; ``margin`` (m) keeps the boundary out (there the full
    step decides)."""
    gz = G + az
    if not gz > 0.0:
        return False
    mu = mp.friction
    if ax * ax + ay * ay >= (mu * gz) ** 2 * (1.0 - 1e-12):
        return False
    s = z / gz
    px, py = -ax * s, -ay * s
    if mp.rim[0] > 0.0:
        return math.sqrt(px * px + py * py) < mp.rim[0] - margin
    if n_hp < 3:
        return False
    for i in range(n_hp):
        if hp[i, 0] * px + hp[i, 1] * py - hp[i, 2] > -margin:
            return False
    return True


@njit(cache=True)
def kernel(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp, res, extra):
    """One run (the kernel contract of :mod:`rocking.models.base`; the scheme of the
    module docstring, with its exact shortcuts: the contact candidates are the vertices
    within reach of the ground, and a body at rest skips the solver while its support
    holds it)."""
    h = mp.step
    cyl = mp.rim[0] > 0.0
    nv = 8 if cyl else mp.verts.shape[0]
    n_out = hist.shape[0]
    n_imp_cap = imp.shape[0]
    every = int(round(dt_out / h))
    n_total = int(math.floor(t_end / h + 1e-9))
    Iinv = mp.inv_inertia
    I = mp.inertia
    R = np.empty((3, 3))
    RM = np.empty((3, 3))
    Jinv = np.empty((3, 3))
    J = np.empty((3, 3))
    rho = np.empty((nv, 3))
    idx = np.empty(nv, dtype=np.int64)
    cand = np.empty(nv, dtype=np.int64)
    un_minus = np.empty(nv)
    gaps = np.empty(nv)
    bias = np.empty(nv)
    closing = np.zeros(nv, dtype=np.bool_)
    wnn = np.empty(nv)
    wn = np.empty(nv)
    wt = np.empty((nv, 4))
    Pw = np.empty((nv, 3))
    ws6 = np.empty((3, 6, 6))
    ws = np.empty((2, 6))
    hp = np.empty((nv + 1, 3))
    tmp2 = np.empty((2 * nv + 2, 2))
    order = np.empty(nv, dtype=np.int64)
    P = np.zeros((nv, 3))
    sub = (np.empty((nv, 3)), np.empty(nv), np.empty((nv, 3)), np.empty((nv, 3)),
           np.empty(nv, dtype=np.int64), np.empty(3), np.empty(3))
    mx = (np.empty(nv, dtype=np.int64), np.empty((nv, 2)), np.empty((3 * nv, 6)),
          np.empty(3 * nv), np.empty((nv, 3)), np.empty((6, 6)), np.empty(3), np.empty(3),
          np.empty(nv, dtype=np.int64))
    P_prev = np.zeros((nv, 3))
    was_active = np.zeros(nv, dtype=np.bool_)
    now_active = np.zeros(nv, dtype=np.bool_)
    vf = np.empty(3)
    Lf = np.empty(3)
    dv = np.empty(3)
    dL = np.empty(3)
    verts = mp.verts if not cyl else np.zeros((8, 3))
    dirb = np.array([1.0, 0.0])
    size = mp.lift_tol * 1e6
    rmax = 0.0
    for i in range(mp.verts.shape[0]):
        rmax = max(rmax, math.sqrt(mp.verts[i, 0] ** 2 + mp.verts[i, 1] ** 2
                                   + mp.verts[i, 2] ** 2))
    reach = 0.05 * size
    n_base = 0
    for i in range(nv):
        if mp.is_base[i] > 0.0:
            n_base += 1
    # state
    x, y, z = y0[0], y0[1], y0[2]
    q = np.empty(4)
    qn = math.sqrt(y0[3] ** 2 + y0[4] ** 2 + y0[5] ** 2 + y0[6] ** 2)
    for i in range(4):
        q[i] = y0[3 + i] / qn
    vx, vy, vz = y0[7], y0[8], y0[9]
    _rot(q[0], q[1], q[2], q[3], R)
    if cyl:
        _rim_points(mp, R, 0.0, 0.0, dirb, verts)
    iw0, iw1, iw2 = _mv(I, y0[10], y0[11], y0[12])
    L0, L1, L2 = _mv(R, iw0, iw1, iw2)
    bpx, bpy, bpz = mp.base_point[0], mp.base_point[1], mp.base_point[2]
    b0x = x + R[0, 0] * bpx + R[0, 1] * bpy + R[0, 2] * bpz
    b0y = y + R[1, 0] * bpx + R[1, 1] * bpy + R[1, 2] * bpz
    tw_prev = 2.0 * math.atan2(q[3], q[0])
    twist = 0.0
    # outputs
    max_tilt = math.atan2(math.sqrt(R[0, 2] ** 2 + R[1, 2] ** 2), R[2, 2])
    max_slide = 0.0
    max_twist = 0.0
    slide = 0.0
    t_up = math.nan
    t_lift = math.nan
    t_over = math.nan
    az_over = math.nan
    over = False
    on_other = False
    at_rest = False
    resting = False
    n_hp = 0
    n_imp = 0
    status = 0
    # is the initial state at rest on its base?
    v0n = math.sqrt(vx * vx + vy * vy + vz * vz)
    w0n = math.sqrt(y0[10] ** 2 + y0[11] ** 2 + y0[12] ** 2)
    moving = v0n > mp.v_rest or w0n * size > mp.v_rest
    for i in range(nv):
        if mp.is_base[i] > 0.0:
            zi = z + R[2, 0] * verts[i, 0] + R[2, 1] * verts[i, 1] + R[2, 2] * verts[i, 2]
            if zi > mp.lift_tol:
                moving = True
    if moving:
        t_up = 0.0
    # the contact candidates
    if cyl:
        n_cand = nv
        for i in range(nv):
            cand[i] = i
    else:
        n_cand = _candidates(verts, R, z, reach, was_active, cand)
    drift = 0.0
    wn_old = 0.0
    k = 0
    k_out = 0
    n_unconv = 0
    if n_out > 0:
        hist[0, 0], hist[0, 1], hist[0, 2] = x, y, z
        hist[0, 3], hist[0, 4], hist[0, 5], hist[0, 6] = q[0], q[1], q[2], q[3]
        hist[0, 7], hist[0, 8], hist[0, 9] = vx, vy, vz
        hist[0, 10], hist[0, 11], hist[0, 12] = y0[10], y0[11], y0[12]
        k_out = 1
    while k < n_total:
        t = k * h
        if t >= t_quiet - 1e-12 and at_rest:
            break
        tm = t + 0.5 * h
        ax, ay, az = ground_acc3(kind, prm, samples, tm)
        if resting:  # at rest: nothing moves while the support holds the body
            if _holds(mp, n_hp, hp, z, ax, ay, az, 1e-12 * size):
                k += 1
                if n_out > 0 and k % every == 0 and k_out < n_out:
                    hist[k_out, 0], hist[k_out, 1], hist[k_out, 2] = x, y, z
                    hist[k_out, 3], hist[k_out, 4] = q[0], q[1]
                    hist[k_out, 5], hist[k_out, 6] = q[2], q[3]
                    for c in range(7, 13):
                        hist[k_out, c] = 0.0
                    k_out += 1
                continue
            resting = False
        # 1. midpoint
        bx, by, bz = _mtv(R, L0, L1, L2)
        wbx, wby, wbz = _mv(Iinv, bx, by, bz)
        wn_old = math.sqrt(wbx * wbx + wby * wby + wbz * wbz)
        if not cyl and drift + h * (abs(vz) + wn_old * rmax) >= 0.5 * reach:
            reach = max(reach, 4.0 * h * (abs(vz) + wn_old * rmax))
            n_cand = _candidates(verts, R, z, reach, was_active, cand)
            drift = 0.0
        xm = x + 0.5 * h * vx
        ym = y + 0.5 * h * vy
        zm = z + 0.5 * h * vz
        _advance(q, wbx, wby, wbz, 0.5 * h)
        _rot(q[0], q[1], q[2], q[3], RM)
        _world_inv_inertia(RM, Iinv, Jinv)
        wwx, wwy, wwz = _mv(Jinv, L0, L1, L2)
        if cyl:
            _rim_points(mp, RM, ax, ay, dirb, verts)
        # 2. contacts
        n_act = 0
        vfz = vz - h * (G + az)
        for c in range(n_cand):
            i = cand[c]
            rx, ry, rz = _mv(RM, verts[i, 0], verts[i, 1], verts[i, 2])
            now_active[i] = False
            gm = zm + rz
            un = vz + wwx * ry - wwy * rx
            if gm <= mp.gap_tol or (was_active[i] and gm + 0.5 * h * min(un + vfz - vz, 0.0)
                                    <= mp.gap_tol):
                rho[n_act, 0], rho[n_act, 1], rho[n_act, 2] = rx, ry, rz
                un_minus[n_act] = un
                gaps[n_act] = gm
                if was_active[i] and gm > 0.0:  # a lasting contact closes its drift gap
                    bias[n_act] = 2.0 * gm / h
                    closing[n_act] = True
                else:  # Newton's law
                    bias[n_act] = mp.restitution * min(un, 0.0)
                    closing[n_act] = False
                idx[n_act] = i
                P[n_act, 0] = P_prev[i, 0]
                P[n_act, 1] = P_prev[i, 1]
                P[n_act, 2] = P_prev[i, 2]
                now_active[i] = True
                n_act += 1
        # 3. impulses
        vf[0] = vx - h * ax
        vf[1] = vy - h * ay
        vf[2] = vz - h * (G + az)
        Lf[0], Lf[1], Lf[2] = L0, L1, L2
        dv[0] = dv[1] = dv[2] = 0.0
        dL[0] = dL[1] = dL[2] = 0.0
        sweeps = -2
        if n_act > 0:
            _world_inv_inertia(RM, I, J)
            sweeps = _solve_contacts(mp, n_act, rho, bias, P, vf, Lf, Jinv, J, dv, dL, wnn,
                                     wt, Pw, ws6, ws, wn, sub, mx)
            if sweeps < 0:
                # the drift gaps' closing velocities can contradict each other (two
                # contacts on a line not quite level, one closing its gap, the other
                # just landed: no rigid motion sticks at both): solve the plain
                # Moreau-Jean problem, no gap closed at this step (the next steps close
                # them), from the last sweep's impulses
                again = False
                for c in range(n_act):
                    if closing[c] and bias[c] != 0.0:
                        bias[c] = 0.0
                        again = True
                if again:
                    sweeps = _solve_contacts(mp, n_act, rho, bias, P, vf, Lf, Jinv, J, dv,
                                             dL, wnn, wt, Pw, ws6, ws, wn, sub, mx)
            if sweeps < 0:
                n_unconv += 1
        impact = False
        on_other = False
        for c in range(n_cand):
            i = cand[c]
            P_prev[i, 0] = P_prev[i, 1] = P_prev[i, 2] = 0.0
        for c in range(n_act):
            i = idx[c]
            P_prev[i, 0], P_prev[i, 1], P_prev[i, 2] = P[c, 0], P[c, 1], P[c, 2]
            if not was_active[i] and un_minus[c] < -mp.v_impact:
                impact = True
            if mp.is_base[i] == 0.0:
                on_other = True
                if verts[i, 2] >= 0.0:
                    over = True  # a point as high as the centre of mass (at rest) touches
        for c in range(n_cand):
            i = cand[c]
            was_active[i] = now_active[i]
        vx, vy, vz = vf[0] + dv[0], vf[1] + dv[1], vf[2] + dv[2]
        L0, L1, L2 = Lf[0] + dL[0], Lf[1] + dL[1], Lf[2] + dL[2]
        # 4. end of the step
        x = xm + 0.5 * h * vx
        y = ym + 0.5 * h * vy
        z = zm + 0.5 * h * vz
        wx, wy, wz = _mv(Jinv, L0, L1, L2)
        bx, by, bz = _mtv(RM, wx, wy, wz)
        _advance(q, bx, by, bz, 0.5 * h)
        _rot(q[0], q[1], q[2], q[3], R)
        k += 1
        t1 = k * h
        if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(z)
                and math.isfinite(L0 + L1 + L2 + vx + vy + vz)):
            status = STATUS_NONFINITE
            break
        vn = math.sqrt(vx * vx + vy * vy + vz * vz)
        wn_new = math.sqrt(wx * wx + wy * wy + wz * wz)
        drift += 0.5 * h * (abs(vz) + abs(vf[2] + h * (G + az)) + (wn_old + wn_new) * rmax)
        # held still by a sticking support: at rest (to rounding) from here on
        if sweeps == 0 and not over and vn + wn_new * size <= 1e-3 * mp.v_up:
            n_hp = 0 if cyl else _rest_polygon(rho, n_act, hp, tmp2, order)
            if cyl or n_hp >= 3:
                resting = True
                vx = vy = vz = 0.0
                L0 = L1 = L2 = 0.0
                wx = wy = wz = 0.0
                vn = wn_new = 0.0
        if impact:
            if n_imp < n_imp_cap:
                imp[n_imp] = t1
            n_imp += 1
        # outputs of the step
        tilt = math.atan2(math.sqrt(R[0, 2] ** 2 + R[1, 2] ** 2), R[2, 2])
        max_tilt = max(max_tilt, tilt)
        if tilt >= 0.5 * math.pi:
            over = True
        sx = x + R[0, 0] * bpx + R[0, 1] * bpy + R[0, 2] * bpz - b0x
        sy = y + R[1, 0] * bpx + R[1, 1] * bpy + R[1, 2] * bpz - b0y
        slide = math.sqrt(sx * sx + sy * sy)
        max_slide = max(max_slide, slide)
        tw = 2.0 * math.atan2(q[3], q[0])
        d = tw - tw_prev
        d -= 2.0 * math.pi * math.floor((d + math.pi) / (2.0 * math.pi))
        twist += d
        tw_prev = tw
        max_twist = max(max_twist, abs(twist))
        if not cyl and drift >= 0.5 * reach:
            n_cand = _candidates(verts, R, z, reach, was_active, cand)
            drift = 0.0
        if cyl:
            _rim_points(mp, R, ax, ay, dirb, verts)
        # the vertices off the list are above reach - drift > lift_tol
        zmin = math.inf
        n_base_seen = 0
        base_up = False
        for c in range(n_cand):
            i = cand[c]
            zi = z + R[2, 0] * verts[i, 0] + R[2, 1] * verts[i, 1] + R[2, 2] * verts[i, 2]
            zmin = min(zmin, zi)
            if mp.is_base[i] > 0.0:
                n_base_seen += 1
                if zi > mp.lift_tol:
                    base_up = True
        if n_base_seen < n_base:
            base_up = True
        if resting and on_other:  # held at rest on a vertex off its base: another face
            over = True
        if t_lift != t_lift and zmin > mp.lift_tol:
            t_lift = t1
        if t_up != t_up and (vn + wn_new * size > mp.v_up or base_up or slide > mp.lift_tol
                             or abs(twist) * size > mp.lift_tol):
            t_up = t1
        at_rest = not base_up and vn <= mp.v_rest and wn_new * size <= mp.v_rest
        if n_out > 0 and k % every == 0 and k_out < n_out:
            hist[k_out, 0], hist[k_out, 1], hist[k_out, 2] = x, y, z
            hist[k_out, 3], hist[k_out, 4] = q[0], q[1]
            hist[k_out, 5], hist[k_out, 6] = q[2], q[3]
            hist[k_out, 7], hist[k_out, 8], hist[k_out, 9] = vx, vy, vz
            ox, oy, oz = _mtv(R, L0, L1, L2)
            ox, oy, oz = _mv(Iinv, ox, oy, oz)
            hist[k_out, 10], hist[k_out, 11], hist[k_out, 12] = ox, oy, oz
            k_out += 1
        if over:
            t_over = t1
            az_over = math.degrees(math.atan2(R[1, 2], R[0, 2]))
            if t_up != t_up:
                t_up = t1
            break
    res.n_out = k_out
    res.n_steps = k
    res.status = status
    res.settled = over or at_rest
    res.overturned = over
    res.overturn_time = t_over
    res.uplift_time = t_up
    res.lift_off_time = t_lift
    res.max_tilt = max_tilt
    res.overturn_azimuth = az_over
    res.n_impacts = n_imp
    res.max_slide = max_slide
    res.residual_slide = slide
    res.max_twist = max_twist
    res.residual_twist = twist
    res.lifted_off = t_lift == t_lift
    res.unconverged_steps = n_unconv


@njit(cache=True, parallel=True)
def batch_kernel(mp, extra0, rows, blocks):
    """The batch kernel (the same lines in every model)."""
    for i in prange(rows.kinds.shape[0]):
        kernel(same_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
        store_row(i, rows)


# ================================================================ options and class
def warn_unconverged(steps: int, runs: int) -> None:
    """Warn that ``steps`` time steps of ``runs`` run(s) ended with a contact problem that
    missed the solver's tolerance (``unconverged_steps``): what is verified and what not."""
    if steps > 0:
        warn_implausible(
            f"model 'rigid3d': {steps} time step(s) of {runs} run(s) ended with a contact "
            "problem that missed tol (output unconverged_steps; their impulses are the last "
            "Gauss-Seidel sweep's). Every other step satisfies the contact laws to tol; the "
            "model is verified against closed forms and the classical model for boxes and "
            "cylinders (uplift, Eq 4, sliding, flight, rolling), not step by step for a "
            "slipping many-vertex support such as a scanned mesh's: compare a run with a "
            "larger max_iter before relying on it")


@dataclass(frozen=True)
class Rigid3dOptions(ModelOptions):
    """Options of the 3-D rigid body (:mod:`rocking.models.rigid3d`)."""

    friction: float = option(
        0.7, lo=0.0, hi=10.0,
        help="Coulomb friction coefficient of the isotropic cone (default 0.7: dry stone on "
             "stone, within Byerlee's 0.6-0.85, Byerlee 1978, 'Friction of rocks', Pure "
             "Appl. Geophys. 116:615-626)")
    restitution: float = option(
        0.0, lo=0.0, hi=1.0, lo_open=False,
        help="Newton's normal coefficient of restitution (default 0: plastic impacts, "
             "which give Housner's Eq 4 in the planar limit)")
    step: float | None = option(
        None, unit="s", lo=0.0, hi=0.01,
        help="time step h (s; made to divide dt_out); None: STEP_P / p (p the frequency "
             "parameter of the body's weakest direction, Eq 3), at most STEP_MAX = 2e-4 s, "
             "which keeps max |theta| within 1 % of the classical model in the planar limit "
             "(docs/guide/rigid3d.rst)")
    direction: float = option(0.0, unit="deg", lo=-360.0, hi=360.0, lo_open=False,
                              help="direction (deg) along which a single horizontal motion "
                                   "acts, counter-clockwise from the body's x axis")
    heading: float = option(0.0, unit="deg", lo=-360.0, hi=360.0, lo_open=False,
                            help="for a HorizontalPair: the body's x axis, deg "
                                 "counter-clockwise from the first component")
    tilt0: float = option(0.0, unit="rad", lo=-1.5, hi=1.5,
                          help="initial tilt (rad) about the horizontal axis normal to "
                               "direction, on the support's extreme point: positive leans the "
                               "up axis towards -direction, as theta > 0 of the planar models")
    tol: float = option(1e-8, lo=0.0, hi=1e-3,
                        help="tolerance of the contact solver: the contact laws hold in "
                             "velocity to tol times the free velocity")
    max_iter: int = option(2000, kind=int, lo=1, hi=10 ** 6, lo_open=False,
                           help="largest number of Gauss-Seidel sweeps per step")
    v_impact: float = option(1e-3, unit="m/s", lo=0.0, hi=10.0, lo_open=False,
                             help="approach speed (m/s) above which a landing vertex "
                                  "counts as an impact")
    v_rest: float = option(1e-5, unit="m/s", lo=0.0, hi=1.0,
                           help="speed (m/s; rotations times the body's size) below which "
                                "a body flat on its base is at rest once the ground is "
                                "still")


def box_of(block):
    """The :class:`~rocking.shapes.Shape` of a rectangular :class:`~rocking.Block`: the box
    ``width`` x ``thickness`` (its width if not given) x ``height`` (mass: the block's, or
    a density of 1000 kg/m^3; the motion does not depend on it)."""
    from ..shapes import Shape

    if block.width is None or block.height is None:
        raise ParameterError("model 'rigid3d' takes a rocking.shapes.Shape, or a rectangular "
                             f"rocking.Block with width and height; got {block!r}")
    depth = block.thickness if block.thickness is not None else block.width
    kw = {"mass": block.mass} if block.mass else {"density": 1000.0}
    _warn_unused_params(block)
    return Shape.box(block.width, depth, block.height, name=block.name or "box", **kw)


def _warn_unused_params(block) -> None:
    """Warn where a rectangular block carries alpha, p or mu other than its geometry's
    (Eqs 2-4: a specimen's identified parameters, a ``with_params`` restitution): the 3-D
    body is made of the width, height and thickness alone, its restitution emerges from
    its impacts, so those values would be silently unused."""
    from ..blocks import Block

    geo = Block.rectangular(width=block.width, height=block.height)
    diff = [f"{k} = {getattr(block, k):.4g} (geometry: {getattr(geo, k):.4g})"
            for k in ("alpha", "p", "mu")
            if abs(getattr(block, k) - getattr(geo, k)) > 1e-2 * abs(getattr(geo, k))]
    if diff:
        warn_implausible(
            f"model 'rigid3d' makes the block {block.name or ''!s} a box of its width, "
            f"height and thickness only: its {', '.join(diff)} are not used (the 3-D body's "
            "restitution emerges from its impacts: Eq 4 in the planar limit; give "
            "restitution= for Newton's law, or a rocking.shapes.Shape.box)")


class Rigid3d(Model):
    """A 3-D rigid body on a moving rigid ground: contact, Coulomb friction, Newton
    impacts (module docstring)."""

    name = "rigid3d"
    label = "3-D rigid body (Moreau-Jean)"
    Options = Rigid3dOptions
    kernel = kernel
    batch_kernel = batch_kernel
    state_names = ("x", "y", "z", "q0", "q1", "q2", "q3", "vx", "vy", "vz", "wx", "wy", "wz")
    state_units = ("m", "m", "m", "", "", "", "", "m/s", "m/s", "m/s", "rad/s", "rad/s",
                   "rad/s")
    tags = {"planar": False, "symmetry": "rotation"}
    append_overturn = False
    outputs = GENERIC_OUTPUTS + (
        Output("max_tilt", "rad", False, "largest angle of the body's initial up axis from "
                                         "the vertical"),
        Output("overturn_azimuth", "deg", False, "bearing of the fall, counter-clockwise "
                                                 "from x (NaN: never)"),
        Output("n_impacts", "", False, "steps at which a vertex landed faster than "
                                       "v_impact", True),
        Output("max_slide", "m", False, "largest horizontal displacement of the base point"),
        Output("residual_slide", "m", False, "horizontal displacement of the base point at "
                                             "the end"),
        Output("max_twist", "rad", False, "largest |rotation about the vertical|"),
        Output("residual_twist", "rad", False, "rotation about the vertical at the end "
                                               "(counter-clockwise looking down)"),
        Output("lifted_off", "", True, "the body left the ground entirely"),
        Output("unconverged_steps", "", False, "steps whose contact problem missed tol in "
                                               "max_iter sweeps (a diagnostic)", True),
    )

    @classmethod
    def check_block(cls, block):
        """The body as a :class:`~rocking.shapes.Shape` at rest: a rectangular
        :class:`~rocking.Block` becomes its box (:func:`box_of`); a shape that does not
        rest exactly on its declared base (its contact patch within ``tol`` is not flat:
        :func:`rocking.shapes.rest.is_resting`; a rock on three points, a scan tilted by
        a fraction of a degree) is first settled under gravity into its resting pose
        (:func:`settled_body`), so that no base tolerance matters."""
        from ..blocks import Block
        from ..shapes import Shape

        if isinstance(block, Shape):
            return settled_body(block)
        if isinstance(block, Block):
            return box_of(block)
        raise ParameterError(f"block must be a rocking.shapes.Shape (or a rectangular "
                             f"rocking.Block) for model 'rigid3d', got {type(block).__name__}")

    def __init__(self, block, options=None):
        super().__init__(block, options)
        self._geom = self._geometry()  # the hull, once (kernel_params changes nothing)
        # p of the weakest direction (Eq 3), for the default step
        self._p = float(self.block.parameters(self.block.weakest().phi)["p_plus"])
        self._rim = np.zeros(3)
        cyl = cylinder_of(self.block)
        if cyl is not None:
            r, height = cyl
            self._rim = np.array([r, -self.block.h, height - self.block.h])
        pts = self._geom[0]
        self._size = float(np.max(np.linalg.norm(pts[:, None, :] - pts[None, :, :], axis=2)))

    def result_info(self, values: dict) -> dict:
        """The model's own outputs; a run whose contact problems did not all converge is
        flagged with a warning (its outputs depend on ``max_iter``: verified for boxes,
        not yet for many-vertex supports such as scanned meshes)."""
        warn_unconverged(values["unconverged_steps"], 1)
        return super().result_info(values)

    def check_results(self, out: dict) -> None:
        """Warn where runs of a batch had contact problems that did not converge."""
        bad = out["unconverged_steps"] > 0
        if bad.any():
            warn_unconverged(int(out["unconverged_steps"][bad].sum()), int(bad.sum()))

    def motion_spec(self, motion):
        """The three-component spec: a single motion along ``direction`` (deg from the
        body's x axis); a :class:`~rocking.motions.HorizontalPair` at ``heading``."""
        from ..motions import HorizontalPair

        if isinstance(motion, HorizontalPair):
            return motion.spec3(math.radians(self.options.heading))
        return motion.spec3(-math.radians(self.options.direction))

    def _geometry(self):
        shape = self.block
        cyl = cylinder_of(shape)
        if cyl is not None:  # the rims' points of the kernel (:func:`_rim_points`)
            r, height = cyl
            a = 0.5 * np.pi * np.arange(4)
            ring = np.column_stack([r * np.cos(a), r * np.sin(a)])
            verts = np.vstack([np.column_stack([ring, np.full(4, -shape.h)]),
                               np.column_stack([ring, np.full(4, height - shape.h)])])
            return verts, np.repeat([1.0, 0.0], 4), np.array([0.0, 0.0, -shape.h])
        pts = np.asarray(shape.hull_points(), dtype=np.float64)
        verts = pts - np.array([0.0, 0.0, shape.h])
        is_base = (pts[:, 2] <= shape.tol).astype(np.float64)
        sup = np.asarray(shape.support)
        cx, cy = polygon_centroid(sup)
        base_point = np.array([cx, cy, -shape.h])
        return verts, is_base, base_point

    def default_step(self) -> float:
        """The step (s): the option ``step``, or ``STEP_P / p`` (``p`` of the weakest
        direction) at most ``STEP_MAX`` (before it is made to divide ``dt_out``)."""
        if self.options.step is not None:
            return float(self.options.step)
        return min(STEP_MAX, STEP_P / self._p)

    def size(self) -> float:
        """The body's size (m): the largest distance between two hull vertices."""
        return self._size

    def kernel_params(self, dt_out, theta0, omega0):
        o = self.options
        verts, is_base, base_point = self._geom
        inertia = np.array(self.block.inertia_local, dtype=np.float64)
        n = max(1, int(math.ceil(dt_out / self.default_step() - 1e-9)))
        size = self.size()
        return Rigid3dParams(
            float(self.block.mass), inertia, np.linalg.inv(inertia), verts, is_base,
            base_point, float(o.friction), float(o.restitution), float(dt_out / n),
            float(o.tol), int(o.max_iter), 1e-9 * size, 1e-6 * size, float(o.v_rest),
            float(o.v_impact), 1e3 * float(o.tol) * G * float(dt_out / n), self._rim)

    def initial_state(self, theta0=0.0, omega0=0.0):
        if theta0 or omega0:
            raise ParameterError("model 'rigid3d' has no planar angle: give its initial tilt "
                                 "as the option tilt0 (rad) or its state as state0")
        return rest_state(self.block, self.options.tilt0,
                          math.radians(self.options.direction))

    def check_state(self, y0):
        y = super().check_state(y0)
        qn = float(np.linalg.norm(y[3:7]))
        if not qn > 0.0:
            raise ParameterError("state0: the quaternion q0..q3 must not be zero")
        y = y.copy()
        y[3:7] /= qn
        from scipy.spatial.transform import Rotation

        R = Rotation.from_quat([y[4], y[5], y[6], y[3]]).as_matrix()
        zmin = lowest(self.block, y[2], R)
        if zmin < -1e-6 * self.size():
            raise ParameterError(f"state0: the body is {-zmin:.3g} m below the ground")
        return y

    @staticmethod
    def rotate_state(y, beta: float) -> np.ndarray:
        """The state ``y`` turned by ``beta`` (rad) counter-clockwise about the vertical
        (looking down): positions and velocities turned, the quaternion pre-multiplied by
        the turn, the body's angular velocity unchanged.

        Examples
        --------
        >>> import math
        >>> from rocking.models.rigid3d import Rigid3d
        >>> y = Rigid3d.rotate_state([1.0, 0, 0.5, 1, 0, 0, 0, 0, 2.0, 0, 0, 0, 0], math.pi / 2)
        >>> np.round(y[[0, 1, 3, 6, 7, 8]], 12).tolist()
        [0.0, 1.0, 0.707106781187, 0.707106781187, -2.0, 0.0]
        """
        y = np.array(y, dtype=np.float64)
        c, s = math.cos(beta), math.sin(beta)
        out = y.copy()
        for i in (0, 7):
            out[i], out[i + 1] = c * y[i] - s * y[i + 1], s * y[i] + c * y[i + 1]
        r0, r3 = math.cos(0.5 * beta), math.sin(0.5 * beta)
        a0, a1, a2, a3 = y[3:7]
        out[3:7] = (r0 * a0 - r3 * a3, r0 * a1 - r3 * a2, r0 * a2 + r3 * a1, r0 * a3 + r3 * a0)
        return out

    def info(self, dt_out=None):
        out = super().info(dt_out)
        # the base point (m, body frame, from the centre of mass): the slide's reference
        out["base_point"] = [float(v) for v in self._geom[2]]
        if dt_out is not None:
            out["step_used"] = self.kernel_params(dt_out, 0.0, 0.0).step
        return out

    def failure(self, status, t, dt_out=None):
        if status == STATUS_NONFINITE:
            return f"model 'rigid3d': the state became non-finite near t = {t:.4g} s"
        return super().failure(status, t, dt_out)


def cylinder_of(shape):
    """``(radius, height)`` of a :meth:`rocking.shapes.Shape.cylinder` (its rims are
    exact in the kernel), None for any other body."""
    prim = getattr(shape, "primitive", None)
    if prim and prim[0] == "cylinder":
        return float(prim[1]), float(prim[2])
    return None


def lowest(shape, z, R) -> float:
    """The height (m) of the lowest point of ``shape`` with its centre of mass at height
    ``z`` and turned by the rotation matrix ``R`` (a cylinder's rims exactly, else the
    hull's vertices)."""
    cyl = cylinder_of(shape)
    if cyl is not None:
        r, height = cyl
        tilt = math.hypot(R[2, 0], R[2, 1])
        return z + min(-shape.h * R[2, 2], (height - shape.h) * R[2, 2]) - r * tilt
    pts = np.asarray(shape.hull_points()) - np.array([0.0, 0.0, shape.h])
    return float(np.min(z + pts @ R[2]))


def rest_state(shape, tilt0: float = 0.0, direction: float = 0.0) -> np.ndarray:
    """The state (13) of ``shape`` standing on its base, tilted by ``tilt0`` (rad) about the
    horizontal axis normal to ``direction`` (rad, counter-clockwise from x): the up axis
    leans towards ``-direction`` for ``tilt0 > 0`` (the body rotates about the support's
    extreme point on that side, which stays in place), at rest."""
    y = np.zeros(13)
    y[2] = shape.h
    y[3] = 1.0
    if tilt0 == 0.0:
        return y
    c, s = math.cos(direction), math.sin(direction)
    sign = 1.0 if tilt0 > 0 else -1.0
    # axis of rotation: tilting the up axis towards -sign*e_d, about n = e_z x (-sign e_d)
    ed = np.array([c, s, 0.0])
    axis = np.cross(np.array([0.0, 0.0, 1.0]), -sign * ed)
    half = 0.5 * abs(tilt0)
    q = np.array([math.cos(half), *(math.sin(half) * axis)])
    pts = np.asarray(shape.hull_points()) - np.array([0.0, 0.0, shape.h])
    cyl = cylinder_of(shape)
    if cyl is not None:  # the rim's exact point
        pivot = np.array([-sign * cyl[0] * c, -sign * cyl[0] * s, -shape.h])
    else:
        base = pts[pts[:, 2] <= -shape.h + shape.tol]
        pivot = base[np.argmin(base @ (sign * ed))]  # the support's extreme point there
    from scipy.spatial.transform import Rotation

    R = Rotation.from_quat([q[1], q[2], q[3], q[0]]).as_matrix()
    # the pivot stays where it was: com + R pivot = pivot0 = (0, 0, h) + pivot
    com = np.array([0.0, 0.0, shape.h]) + pivot - R @ pivot
    com[2] -= lowest(shape, com[2], R)  # the lowest point on the ground
    y[:3] = com
    y[3:7] = q
    return y


def settled_body(shape):
    """``shape`` in its resting pose (:func:`rocking.shapes.rest.rest_pose`): itself if
    it rests exactly on its base, else settled under gravity from its given orientation,
    with a warning where it rolls off its declared base (the patch within ``tol``) onto
    another face. A shape whose declared support cannot carry it (its centre of mass's
    vertical not strictly inside the support, or the centre of mass not strictly inside
    its hull: mass properties that do not belong to its mesh) is refused (``block``). A
    settled pose is kept per shape (a weak reference): a batch or a campaign settles each
    body once."""
    import weakref

    from ..shapes.rest import REST_EPS, is_resting, rest_pose
    from ..shapes.support import inside_margin

    cache = _SETTLED.setdefault("shapes", weakref.WeakKeyDictionary())
    hit = cache.get(shape)
    if hit is not None:
        return hit

    pts = np.asarray(shape.hull_points())
    size = float(np.max(np.ptp(pts, axis=0)))
    if not inside_margin(shape.support, np.zeros(2)) > REST_EPS * size:
        raise ParameterError("block: the centre of mass's vertical is not strictly inside "
                             "the shape's declared support: it cannot rest on the plane")
    from scipy.spatial import ConvexHull

    eq = ConvexHull(pts).equations
    if not float(np.max(eq[:, :3] @ np.array([0.0, 0.0, shape.h]) + eq[:, 3])) \
            < -REST_EPS * size:
        raise ParameterError("block: the centre of mass (at height h) is not strictly "
                             "inside the shape's convex hull: its mass properties do not "
                             "belong to its mesh, and it cannot rest on the plane")
    if is_resting(shape):
        return shape
    rested = rest_pose(shape)
    cache[shape] = rested
    v = np.asarray(shape.vertices)
    z0 = v @ shape.frame[2]
    z1 = v @ rested.frame[2]
    patch = z0 - z0.min() <= shape.tol
    on = z1 - z1.min() <= rested.tol
    if np.any(on & ~patch):
        turn = math.degrees(math.acos(min(1.0, float(shape.frame[2] @ rested.frame[2]))))
        warn_implausible(
            f"block: {shape.name or 'the body'} does not rest on its declared base (the "
            f"patch within tol = {shape.tol:.3g} m): settled under gravity it rolls onto "
            f"another face, turning by {turn:.3g} deg; model 'rigid3d' runs it in that pose "
            "(rocking.shapes.rest.rest_pose)")
    return rested


_SETTLED: dict = {}
"""The settled bodies of :func:`settled_body`, per shape (weak keys)."""
