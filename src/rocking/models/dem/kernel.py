"""The compiled DEM kernel: contact detection, the contact law and explicit central
differences (see :mod:`rocking.models.dem` for the equations and the event rules)."""

from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit, prange

from ...motions._kernel import ground_acc, ground_acc_hv, has_vertical
from ...units import G
from ..base import row_args, same_block, set_planar_result, store_row

HALF_PI = 0.5 * math.pi


@njit(cache=True, inline="always")
def _world(pos, lv, lvn, len_, nv, wv, wn, en):
    """World coordinates of the vertices, vertex normals and edge normals of every block."""
    for i in range(nv.shape[0]):
        c = math.cos(pos[i, 2])
        s = math.sin(pos[i, 2])
        for k in range(nv[i]):
            x, y = lv[i, k, 0], lv[i, k, 1]
            wv[i, k, 0] = pos[i, 0] + c * x - s * y
            wv[i, k, 1] = pos[i, 1] + s * x + c * y
            x, y = lvn[i, k, 0], lvn[i, k, 1]
            wn[i, k, 0] = c * x - s * y
            wn[i, k, 1] = s * x + c * y
            if nv.shape[0] > 1:  # edge normals: block-block contacts only
                x, y = len_[i, k, 0], len_[i, k, 1]
                en[i, k, 0] = c * x - s * y
                en[i, k, 1] = s * x + c * y


@njit(cache=True, inline="always")
def _find_edge(px, py, nvx, nvy, i, j, pos, wv, en, nv, rad, rr, tol):
    """Edge of block ``j`` touched by vertex (px, py) of block ``i`` (outward vertex normal
    (nvx, nvy)): ``(edge, d)`` with ``d`` the signed distance (< tol), or ``(-1, 0)``.

    A vertex outside the convex polygon by more than the rounding ``rr`` touches nothing.
    Of the edges that face the vertex and whose (extended) span contains its projection,
    the nearest (largest ``d``) is the contact face; the vertex touches it if ``d < tol``.
    """
    dx = px - pos[j, 0]
    dy = py - pos[j, 1]
    lim = rad[j] + rr
    if dx * dx + dy * dy > lim * lim:
        return -1, 0.0
    if i < j:  # a lower block's vertex at an upper block's corner: the upper one counts
        for m in range(nv[j]):
            ex = px - wv[j, m, 0]
            ey = py - wv[j, m, 1]
            if ex * ex + ey * ey <= rr * rr:
                return -1, 0.0
    best = -1
    bestd = -math.inf
    k = nv[j]
    for e in range(k):
        nx, ny = en[j, e, 0], en[j, e, 1]
        qx, qy = wv[j, e, 0], wv[j, e, 1]
        d = (px - qx) * nx + (py - qy) * ny
        if d > rr:  # outside the (convex) polygon, beyond the rounding
            return -1, 0.0
        if nx * nvx + ny * nvy >= 0.0 or d <= bestd:
            continue
        e1 = e + 1 if e + 1 < k else 0
        ux, uy = wv[j, e1, 0] - qx, wv[j, e1, 1] - qy
        ln = math.sqrt(ux * ux + uy * uy)
        s = ((px - qx) * ux + (py - qy) * uy) / ln
        if s < -rr or s > ln + rr:
            continue
        best = e
        bestd = d
    if best < 0 or bestd >= tol:  # the nearest face is not penetrated
        return -1, 0.0
    return best, bestd


@njit(cache=True)
def _contact_law(K, Ks, cn, cs, tanphi, coh, pen, vn, vt, fs_prev, dt):
    """One contact point: normal spring without tension plus its dashpot, and the
    incremental shear spring (plus dashpot) capped by Coulomb friction. Returns the normal
    and shear forces and the new shear-spring force (the spring slips at the cap)."""
    fn = K * pen - cn * vn
    if fn < 0.0:
        fn = 0.0
    fsp = fs_prev - Ks * vt * dt
    ft = fsp - cs * vt
    fmax = fn * tanphi + coh
    if abs(ft) > fmax:
        ft = math.copysign(fmax, ft)
        fsp = ft
    return fn, ft, fsp


@njit(cache=True, inline="always")
def _forces(pos, vel, t, dt, lv, lvn, len_, nv, mass, inertia, rad, rr, K, Ks, cn, cs,
            tanphi, coh, kind, prm, samples, wv, wn, en, fs, sedge, F, cf, rec):
    """Contact and body forces at positions ``pos`` with (half-step) velocities ``vel``.

    Updates the shear histories ``fs`` and contact edges ``sedge`` (-1: open) of every slot
    (vertex i,k against target j; j = N is the base), writes the forces on the blocks in
    ``F`` (N, 3) and, if ``rec``, the contact forces (Fn, Fs, x, y) of each closed slot in
    ``cf``. Returns
    ``(spring energy, a contact opened, a block other than the bottom one touched the
    base)``.
    """
    n = nv.shape[0]
    _world(pos, lv, lvn, len_, nv, wv, wn, en)
    if has_vertical(prm):
        ag, av = ground_acc_hv(kind, prm, samples, t)
        ge = G + av  # the effective gravity g + a_v
    else:
        ag, ge = ground_acc(kind, prm, samples, t), G
    for i in range(n):
        F[i, 0] = -mass[i] * ag
        F[i, 1] = -mass[i] * ge
        F[i, 2] = 0.0
    energy = 0.0
    opened = False
    fell = False
    for i in range(n):
        xi, yi = pos[i, 0], pos[i, 1]
        vxi, vyi, wi = vel[i, 0], vel[i, 1], vel[i, 2]
        for k in range(nv[i]):
            px, py = wv[i, k, 0], wv[i, k, 1]
            rx, ry = px - xi, py - yi
            vpx = vxi - wi * ry
            vpy = vyi + wi * rx
            # ---- the base: half-plane y < 0, normal (0, 1), tangent (1, 0)
            if py < 0.0 and wn[i, k, 1] < 0.0:
                if i > 0:
                    fell = True
                pen = -py
                fn, ft, fsp = _contact_law(K, Ks, cn, cs, tanphi, coh, pen, vpy, vpx,
                                           fs[i, k, n], dt)
                fs[i, k, n] = fsp
                sedge[i, k, n] = 0
                F[i, 0] += ft
                F[i, 1] += fn
                F[i, 2] += rx * fn - ry * ft
                energy += 0.5 * K * pen * pen + 0.5 * fsp * fsp / Ks
                if rec:
                    cf[i, k, n, 0] = fn
                    cf[i, k, n, 1] = ft
                    cf[i, k, n, 2] = px
                    cf[i, k, n, 3] = py
            elif sedge[i, k, n] >= 0:
                opened = True
                sedge[i, k, n] = -1
                fs[i, k, n] = 0.0
            # ---- other blocks
            for j in range(n):
                if j == i:
                    continue
                e, d = _find_edge(px, py, wn[i, k, 0], wn[i, k, 1], i, j, pos, wv, en, nv,
                                  rad, rr, 0.0)
                if e < 0:
                    if sedge[i, k, j] >= 0:
                        opened = True
                        sedge[i, k, j] = -1
                        fs[i, k, j] = 0.0
                    continue
                if sedge[i, k, j] != e:
                    fs[i, k, j] = 0.0
                    sedge[i, k, j] = e
                nx, ny = en[j, e, 0], en[j, e, 1]
                ux, uy = -ny, nx
                sx, sy = px - pos[j, 0], py - pos[j, 1]
                wj = vel[j, 2]
                rvx = vpx - (vel[j, 0] - wj * sy)
                rvy = vpy - (vel[j, 1] + wj * sx)
                vn = rvx * nx + rvy * ny
                vt = rvx * ux + rvy * uy
                pen = -d
                fn, ft, fsp = _contact_law(K, Ks, cn, cs, tanphi, coh, pen, vn, vt,
                                           fs[i, k, j], dt)
                fs[i, k, j] = fsp
                fx = fn * nx + ft * ux
                fy = fn * ny + ft * uy
                F[i, 0] += fx
                F[i, 1] += fy
                F[i, 2] += rx * fy - ry * fx
                F[j, 0] -= fx
                F[j, 1] -= fy
                F[j, 2] -= sx * fy - sy * fx
                energy += 0.5 * K * pen * pen + 0.5 * fsp * fsp / Ks
                if rec:
                    cf[i, k, j, 0] = fn
                    cf[i, k, j, 1] = ft
                    cf[i, k, j, 2] = px
                    cf[i, k, j, 3] = py
    return energy, opened, fell


@njit(cache=True)
def integrate(lv, lvn, len_, nv, mass, inertia, rad, rr, K, Ks, cn, cs, tanphi, coh, kind,
              prm, samples, t_end, t_quiet, dt, every, pos, vel, fs, sedge, nominal, iout,
              th_tol, resting, out_pos, out_vel, out_e, out_f, imp):
    """Integrate from ``pos``/``vel`` (updated in place) until ``t_end``. Returns
    ``(n_out, n_impacts, max|theta|, overturned, overturn_time, uplift_time, n_steps, ok,
    settled)``.

    From ``t_quiet`` on the ground is still, and the run stops at the first output step
    at which every block is at rest (:func:`at_rest`).

    Output every ``every`` steps into ``out_pos``/``out_vel`` (n_out, N, 3) (length 0:
    none), energies (kinetic, potential, spring) into ``out_e`` and slot forces into
    ``out_f`` when they have rows; impact times into ``imp`` up to its length.
    """
    n = nv.shape[0]
    vmax = lv.shape[1]
    wv = np.empty((n, vmax, 2))
    wn = np.empty((n, vmax, 2))
    en = np.empty((n, vmax, 2))
    F = np.empty((n, 3))
    cf = np.zeros((n, vmax, n + 1, 4))
    vnew = np.empty((n, 3))
    n_out = out_pos.shape[0]
    n_e = out_e.shape[0]
    n_f = out_f.shape[0]
    cap = imp.shape[0]
    n_steps = int(math.ceil(t_end / dt - 1e-9))
    k = 0
    n_imp = 0
    peak = abs(pos[iout, 2])
    armed = peak > th_tol
    overturned = False
    t_over = math.nan
    t_up = math.nan if resting else 0.0
    ok = True
    settled = False
    q_step = int(math.ceil(t_quiet / dt - 1e-9)) if t_quiet < t_end else n_steps + 1
    step = 0
    while True:
        t = step * dt
        out_step = step % every == 0 and k < n_out
        e_spring, opened, fell = _forces(pos, vel, t, dt, lv, lvn, len_, nv, mass, inertia,
                                         rad, rr, K, Ks, cn, cs, tanphi, coh, kind, prm,
                                         samples, wv, wn, en, fs, sedge, F, cf,
                                         out_step and k < n_f)
        if opened and math.isnan(t_up):
            t_up = t
        h = dt if step > 0 else 0.5 * dt
        for i in range(n):
            vnew[i, 0] = vel[i, 0] + h * F[i, 0] / mass[i]
            vnew[i, 1] = vel[i, 1] + h * F[i, 1] / mass[i]
            vnew[i, 2] = vel[i, 2] + h * F[i, 2] / inertia[i]
        if out_step:
            ke = 0.0
            pe = 0.0
            for i in range(n):
                for c in range(3):
                    out_pos[k, i, c] = pos[i, c]
                    out_vel[k, i, c] = 0.5 * (vel[i, c] + vnew[i, c]) if step > 0 \
                        else vel[i, c]
                ke += 0.5 * (mass[i] * (out_vel[k, i, 0] ** 2 + out_vel[k, i, 1] ** 2)
                             + inertia[i] * out_vel[k, i, 2] ** 2)
                pe += mass[i] * G * (pos[i, 1] - nominal[i, 1])
            if k < n_e:
                out_e[k, 0] = ke
                out_e[k, 1] = pe
                out_e[k, 2] = e_spring
            if k < n_f:
                for i in range(n):
                    for kk in range(vmax):
                        for j in range(n + 1):
                            s = (i * vmax + kk) * (n + 1) + j
                            for c in range(4):
                                out_f[k, s, c] = cf[i, kk, j, c] if sedge[i, kk, j] >= 0 \
                                    else (0.0 if c < 2 else math.nan)
            k += 1
        if fell:
            overturned = True
            t_over = t
            break
        if step >= q_step and step % every == 0 and at_rest(pos, vel, mass, inertia, rad,
                                                             th_tol):
            settled = True
            break
        if step >= n_steps:
            settled = at_rest(pos, vel, mass, inertia, rad, th_tol)
            break
        th_old = pos[iout, 2]
        for i in range(n):
            for c in range(3):
                vel[i, c] = vnew[i, c]
                pos[i, c] += dt * vnew[i, c]
        step += 1
        th = pos[iout, 2]
        if not (abs(th) < 1e6 and abs(pos[iout, 0]) < 1e6):
            ok = False
            break
        a = abs(th)
        if a > peak:
            peak = a
        if a > th_tol:
            armed = True
        if armed and th * th_old < 0.0:
            if n_imp < cap:
                imp[n_imp] = t + dt * th_old / (th_old - th)
            n_imp += 1
            armed = False
        over = False
        for i in range(n):
            if abs(pos[i, 2]) >= HALF_PI:
                over = True
        if over:
            overturned = True
            t_over = step * dt
            if a >= HALF_PI:
                t_over -= dt * (a - HALF_PI) / max(a - abs(th_old), 1e-300)
            break
    return k, n_imp, peak, overturned, t_over, t_up, step, ok, settled or overturned


@njit(cache=True)
def at_rest(pos, vel, mass, inertia, rad, th_tol):
    """Every block at rest: ``|theta| <= th_tol`` and a kinetic energy below
    ``m g R th_tol^2`` (``R``: the block's radius), far below the energy of a rocking
    amplitude of ``th_tol`` (``~ m g R sin(alpha) th_tol``): the motion left is the
    vibration of the contact springs."""
    for i in range(mass.shape[0]):
        if abs(pos[i, 2]) > th_tol:
            return False
        ke = 0.5 * (mass[i] * (vel[i, 0] ** 2 + vel[i, 1] ** 2) + inertia[i] * vel[i, 2] ** 2)
        if ke > mass[i] * G * rad[i] * th_tol * th_tol:
            return False
    return True


@njit(cache=True)
def _row(out, c, i, k, j, e, px, py, nx, ny):
    out[c, 0] = i
    out[c, 1] = k
    out[c, 2] = j
    out[c, 3] = e
    out[c, 4] = px
    out[c, 5] = py
    out[c, 6] = nx
    out[c, 7] = ny


@njit(cache=True)
def probe_contacts(pos, lv, lvn, len_, nv, rad, rr, tol, out):
    """Contacts with signed distance < ``tol`` at ``pos``: rows (i, k, j, e, px, py, nx, ny)
    in ``out`` (j = N: the base). Returns their number."""
    n = nv.shape[0]
    vmax = lv.shape[1]
    wv = np.empty((n, vmax, 2))
    wn = np.empty((n, vmax, 2))
    en = np.empty((n, vmax, 2))
    _world(pos, lv, lvn, len_, nv, wv, wn, en)
    c = 0
    for i in range(n):
        for k in range(nv[i]):
            px, py = wv[i, k, 0], wv[i, k, 1]
            if py < tol and wn[i, k, 1] < 0.0:
                _row(out, c, i, k, n, 0, px, py, 0.0, 1.0)
                c += 1
            for j in range(n):
                if j == i:
                    continue
                e, d = _find_edge(px, py, wn[i, k, 0], wn[i, k, 1], i, j, pos, wv, en, nv,
                                  rad, rr, tol)
                if e >= 0:
                    _row(out, c, i, k, j, e, px, py, en[j, e, 0], en[j, e, 1])
                    c += 1
    return c


DEMParams = namedtuple("DEMParams", [
    "lv", "lvn", "len_", "nv", "mass", "inertia", "rad", "rr", "K", "Ks", "cn", "cs", "tanphi",
    "coh", "dt", "every", "fs0", "sedge0", "nominal", "iout", "th_tol", "resting"])
"""The kernel parameters ``mp`` of the DEM: the packed assembly (vertices, normals,
masses, inertias, radii, rounding), the contact law (stiffnesses, damping, friction,
cohesion), the step and output stride, the contacts' initial shear forces and edges,
the nominal positions, the output block, the impact tolerance and whether the run starts
at rest (:func:`rocking.models.dem.statics.kernel_params`)."""


@njit(cache=True)
def kernel(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp, res, extra):
    """The single-run kernel of the model interface (:mod:`rocking.models.base`).

    The state (``y0``, the rows of ``hist``) is every block's ``(x, y, theta)`` (m, m,
    rad; the centroid in the base's frame), then every block's ``(vx, vy, omega)``;
    ``extra = (out_e, out_f)`` receives the energies and the contact forces when its
    arrays have rows (single runs on request)."""
    out_e, out_f = extra
    n = mp.nv.shape[0]
    n_out = hist.shape[0]
    op = np.empty((n_out, n, 3))
    ov = np.empty((n_out, n, 3))
    pos = np.empty((n, 3))
    vel = np.empty((n, 3))
    for i in range(n):
        for c in range(3):
            pos[i, c] = y0[3 * i + c]
            vel[i, c] = y0[3 * n + 3 * i + c]
    k, n_imp, peak, over, t_over, t_up, n_steps, ok, settled = integrate(
        mp.lv, mp.lvn, mp.len_, mp.nv, mp.mass, mp.inertia, mp.rad, mp.rr, mp.K, mp.Ks, mp.cn,
        mp.cs, mp.tanphi, mp.coh, kind, prm, samples, t_end, t_quiet, mp.dt, mp.every, pos,
        vel, mp.fs0.copy(), mp.sedge0.copy(), mp.nominal, mp.iout, mp.th_tol, mp.resting, op,
        ov, out_e, out_f, imp)
    for j in range(k):
        for i in range(n):
            for c in range(3):
                hist[j, 3 * i + c] = op[j, i, c]
                hist[j, 3 * n + 3 * i + c] = ov[j, i, c]
    set_planar_result(res, k, n_imp, peak, over, t_over, t_up, n_steps, 0 if ok else 1,
                      math.nan, ok and settled)


@njit(cache=True, parallel=True)
def batch_kernel(mp, extra0, rows, blocks):
    """The batch kernel: the kernel over the rows of :func:`rocking.models.base.row_args`
    (one assembly and initial contact state per batch: ``same_block``)."""
    for i in prange(rows.kinds.shape[0]):
        kernel(same_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
        store_row(i, rows)
