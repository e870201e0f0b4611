"""A plain reference of the 3-D rigid body (:mod:`rocking.models.rigid3d`): the same
Moreau-Jean scheme written independently with numpy, slowly and plainly, for the tests to
compare the compiled kernel with on short runs.

What is independent: the rotation (scipy's :class:`~scipy.spatial.transform.Rotation`), the
quaternion exponential (``Rotation.from_rotvec``), the contact problem assembled as an
explicit Delassus matrix ``W = H^T M^-1 H`` (``H`` the contact Jacobian, built column by
column) and the Gauss-Seidel sweeps on ``W`` (the kernel never forms ``W``: it
accumulates the impulses' effect on the velocities), the residual of the contact laws
computed from ``W``. What is shared is the scheme itself (module docstring of
:mod:`rocking.models.rigid3d`), which is what a reference of a time-stepping scheme checks:
the kernel computes what the scheme says.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.spatial.transform import Rotation

from ..units import G


def _rot(q):
    """Rotation of the quaternion ``(q0, q1, q2, q3)`` (scalar first)."""
    return Rotation.from_quat([q[1], q[2], q[3], q[0]])


def _quat(rot):
    x, y, z, w = rot.as_quat()
    return np.array([w, x, y, z])


def _advance(q, w_body, dt):
    """``q exp(dt w)``: the body turned by the body angular velocity ``w`` over ``dt``."""
    return _quat(_rot(q) * Rotation.from_rotvec(np.asarray(w_body) * dt))


def solve_contacts(W, u_free, bias, mu, P0, tol, max_iter, vscale, trace=None):
    """Projected Gauss-Seidel on ``U = u_free + W P`` (3 per contact: x, y, normal z):
    normal ``U_n + bias >= 0 _|_ P_n >= 0``, Coulomb ``|P_t| <= mu P_n``, until the laws
    hold in velocity to ``tol vscale`` (``trace``: a list that gets each sweep's residual).
    Returns ``P``."""
    n = len(bias)
    P = P0.copy()
    for _sweep in range(max_iter):
        for i in range(n):
            a = 3 * i
            # normal
            U = u_free + W @ P
            pn = max(0.0, P[a + 2] - (U[a + 2] + bias[i]) / W[a + 2, a + 2])
            pt = P[a:a + 2].copy()
            lim = mu * pn
            if np.linalg.norm(pt) > lim:
                pt = pt * (lim / np.linalg.norm(pt)) if np.linalg.norm(pt) > 0 else pt
            P[a:a + 3] = (pt[0], pt[1], pn)
            # tangential
            U = u_free + W @ P
            Wt = W[a:a + 2, a:a + 2]
            Wt = 0.5 * (Wt + Wt.T)
            trial = P[a:a + 2] - np.linalg.solve(Wt, U[a:a + 2])
            if trial @ trial > lim * lim:
                trial = P[a:a + 2] - U[a:a + 2] / np.linalg.eigvalsh(Wt)[-1]
                nt = np.linalg.norm(trial)
                if nt > lim:
                    trial = trial * (lim / nt)
            P[a:a + 2] = trial
        U = u_free + W @ P
        resid = 0.0
        for i in range(n):
            a = 3 * i
            un = U[a + 2] + bias[i]
            r = abs(un) if P[a + 2] > 0 else max(0.0, -un)
            ut = U[a:a + 2]
            pt = np.linalg.norm(P[a:a + 2])
            if P[a + 2] <= 0.0 or mu == 0.0:
                pass  # no normal impulse: no friction
            elif pt < mu * P[a + 2] * (1 - 1e-12):
                r = max(r, np.linalg.norm(ut))
            else:
                r = max(r, np.linalg.norm(ut + np.linalg.norm(ut) * P[a:a + 2] / pt))
            resid = max(resid, r)
        if trace is not None:
            trace.append(resid)
        if resid <= tol * vscale:
            break
    return P


def rim_points(mp, R, a, dirb):
    """A cylinder's contact candidates (8, 3) in the body's frame (the scheme of
    :func:`rocking.models.rigid3d._rim_points`, derived in the ground's frame): on each
    rim, the point nearest the ground (the rim's centre minus r times the downward vertical
    projected on the rim's plane), the opposite one and the two between; flat on the base
    (the rim's height varies by less than ``gap_tol``), the direction of the horizontal
    inertial load ``-a`` (``dirb``: the last direction, a list of 2 kept in place)."""
    r, zb, zt = mp.rim
    axis = R[:, 2]
    down = np.array([0.0, 0.0, -1.0])
    d = down - (down @ axis) * axis  # the steepest descent in the rim's plane
    if 2.0 * r * np.linalg.norm(d) <= mp.gap_tol:
        load = -np.array([a[0], a[1], 0.0])
        dl = R.T @ load
        if np.hypot(dl[0], dl[1]) > 0.0:
            dirb[:] = dl[:2] / np.hypot(dl[0], dl[1])
        elif np.linalg.norm(d) > 0.0:
            db = R.T @ d
            dirb[:] = db[:2] / np.hypot(db[0], db[1])
    else:
        db = R.T @ d
        dirb[:] = db[:2] / np.hypot(db[0], db[1])
    c, s = r * dirb[0], r * dirb[1]
    ring = [(c, s), (-c, -s), (-s, c), (s, -c)]
    return np.array([(x, y, z) for z in (zb, zt) for x, y in ring])


def simulate(mp, accel, y0, t_end, trace=None):
    """The states (steps + 1, 13) of a run of ``t_end`` (s) with the kernel parameters ``mp``
    (:class:`rocking.models.rigid3d.Rigid3dParams`) under the ground acceleration
    ``accel(t) -> (ax, ay, az)`` (m/s^2, in the ground frame) from the state ``y0``
    (``trace``: a list that gets the solver's residual after each sweep)."""
    h = mp.step
    m = mp.mass
    I = np.asarray(mp.inertia)
    Iinv = np.asarray(mp.inv_inertia)
    cyl = mp.rim[0] > 0.0
    dirb = [1.0, 0.0]
    verts = np.asarray(mp.verts)
    nv = len(verts)
    x = np.array(y0[0:3], dtype=float)
    q = np.array(y0[3:7], dtype=float) / np.linalg.norm(y0[3:7])
    v = np.array(y0[7:10], dtype=float)
    L = _rot(q).as_matrix() @ I @ np.array(y0[10:13], dtype=float)
    P_prev = np.zeros((nv, 3))
    was = np.zeros(nv, bool)
    out = [np.concatenate([x, q, v, y0[10:13]])]
    n_steps = int(math.floor(t_end / h + 1e-9))
    for k in range(n_steps):
        t = k * h
        a = np.array(accel(t + 0.5 * h))
        R = _rot(q).as_matrix()
        w_body = Iinv @ R.T @ L
        xm = x + 0.5 * h * v
        qm = _advance(q, w_body, 0.5 * h)
        RM = _rot(qm).as_matrix()
        Jinv = RM @ Iinv @ RM.T
        w_w = Jinv @ L
        f = np.array([-a[0], -a[1], -(G + a[2])])
        if cyl:
            verts = rim_points(mp, RM, a, dirb)
        vf = v + h * f
        act, rho, bias = [], [], []
        now = np.zeros(nv, bool)
        for i in range(nv):
            r = RM @ verts[i]
            gm = xm[2] + r[2]
            un = (v + np.cross(w_w, r))[2]
            unf = un + h * f[2]
            if gm <= mp.gap_tol or (was[i] and gm + 0.5 * h * min(unf, 0.0) <= mp.gap_tol):
                act.append(i)
                rho.append(r)
                bias.append(2.0 * gm / h if (was[i] and gm > 0.0)
                            else mp.restitution * min(un, 0.0))
                now[i] = True
        n = len(act)
        if n:
            # H: the velocity of contact i is v + w x rho_i = v - [rho_i]x J^-1 L
            # U = u_free + W P with W = sum over the body of H_i^T M^-1 H_j
            Minv = np.zeros((6, 6))
            Minv[:3, :3] = np.eye(3) / m
            Minv[3:, 3:] = Jinv
            Hc = np.zeros((3 * n, 6))  # maps (dv, dL) to the contact velocities
            for c, r in enumerate(rho):
                cx = np.array([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])
                Hc[3 * c:3 * c + 3, :3] = np.eye(3)
                Hc[3 * c:3 * c + 3, 3:] = -cx  # w x r = -[r]x w ; w = Jinv L
            Hg = np.zeros((6, 3 * n))  # maps P to (dv, dL): dv = P, dL = r x P
            for c, r in enumerate(rho):
                cx = np.array([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])
                Hg[:3, 3 * c:3 * c + 3] = np.eye(3)
                Hg[3:, 3 * c:3 * c + 3] = cx
            W = Hc @ Minv @ Hg
            u_free = Hc @ Minv @ np.concatenate([m * vf, L])
            P0 = np.concatenate([P_prev[i] for i in act])
            vscale = np.abs(bias).sum() + np.linalg.norm(vf) + 1e-300
            P = solve_contacts(W, u_free, np.array(bias), mp.friction, P0, mp.tol,
                               mp.max_iter, vscale, trace)
            Pm = P.reshape(n, 3)
            dv = Pm.sum(axis=0) / m
            dL = sum(np.cross(r, p) for r, p in zip(rho, Pm, strict=True))
        else:
            Pm = np.zeros((0, 3))
            dv = np.zeros(3)
            dL = np.zeros(3)
        P_prev[:] = 0.0
        for c, i in enumerate(act):
            P_prev[i] = Pm[c]
        was = now
        v = vf + dv
        L = L + dL
        x = xm + 0.5 * h * v
        w_plus = RM.T @ (Jinv @ L)
        q = _advance(qm, w_plus, 0.5 * h)
        R = _rot(q).as_matrix()
        out.append(np.concatenate([x, q, v, Iinv @ R.T @ L]))
    return np.array(out)
