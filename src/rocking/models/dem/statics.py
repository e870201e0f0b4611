"""Linear statics of the DEM assembly: contacts at a position, the stiffness matrix, the
highest natural frequency, the stable time step, the static equilibrium and the initial
state (see :mod:`rocking.models.dem`)."""

from __future__ import annotations

import math

import numpy as np

from ...errors import ParameterError
from ...units import G
from .geometry import Assembly
from .kernel import DEMParams, probe_contacts

SAFETY = 0.8
"""Fraction of the stability limit of central differences used as the time step."""
ACCURACY = 0.2
"""Largest ``omega_max dt``: about 30 steps per period of the stiffest contact mode, so that
the closing and opening of contacts (resolved to first order only) cost little energy."""


def contacts_at(model: Assembly, pos: np.ndarray, tol: float) -> np.ndarray:
    """Contacts (rows i, k, j, e, px, py, nx, ny) with signed distance below ``tol``."""
    out = np.empty((model.n * model.lv.shape[1] * (model.n + 1), 8))
    c = probe_contacts(np.ascontiguousarray(pos, dtype=np.float64), model.lv, model.lvn, model.len_,
               model.nv, model.rad, model.rr, tol, out)
    return out[:c]


def stiffness_matrix(model: Assembly, pos, K: float, Ks: float, contacts=None):
    """Stiffness matrix (3N x 3N) of the blocks on their closed contacts at ``pos``, and
    the constraint rows (normal, tangential) of each contact."""
    n = model.n
    if contacts is None:
        contacts = contacts_at(model, pos, 1e-9 * model.rr)
    Kmat = np.zeros((3 * n, 3 * n))
    rows = []
    for i, _k, j, _e, px, py, nx, ny in contacts:
        i, j = int(i), int(j)
        ux, uy = -ny, nx
        gn = np.zeros(3 * n)
        gt = np.zeros(3 * n)
        for b, sgn in ((i, 1.0), (j, -1.0)):
            if b >= n:
                continue
            rx, ry = px - pos[b, 0], py - pos[b, 1]
            gn[3 * b: 3 * b + 3] += sgn * np.array([nx, ny, rx * ny - ry * nx])
            gt[3 * b: 3 * b + 3] += sgn * np.array([ux, uy, rx * uy - ry * ux])
        Kmat += K * np.outer(gn, gn) + Ks * np.outer(gt, gt)
        rows.append((gn, gt))
    return Kmat, rows


def omega_max(model: Assembly, K: float, Ks: float) -> float:
    """Highest natural frequency (rad/s) of the blocks resting on closed contacts."""
    Kmat, _ = stiffness_matrix(model, model.nominal, K, Ks)
    m = np.stack([model.mass, model.mass, model.inertia], axis=1).ravel()
    s = 1.0 / np.sqrt(m)
    lam = np.linalg.eigvalsh(Kmat * s[:, None] * s[None, :])
    return float(math.sqrt(max(lam.max(), 0.0)))


def stable_dt(model: Assembly, K: float, Ks: float, b: float, safety: float = SAFETY) -> float:
    """Time step (s): ``safety`` x the stability limit of central differences with the
    lagged stiffness-proportional damping ``b``, and at most ``ACCURACY / omega_max``
    (see the module docstring)."""
    w = omega_max(model, K, Ks)
    xi = 0.5 * b * w
    return min(safety * 2.0 * (math.sqrt(1.0 + xi * xi) - xi), ACCURACY) / w


def static_state(model: Assembly, K: float, Ks: float):
    """Static equilibrium under gravity on the contacts closed at the nominal positions:
    ``(pos, fs, sedge)`` (linear solution; exact for the linear contact springs)."""
    n = model.n
    vmax = model.lv.shape[1]
    pos = model.nominal.copy()
    fs = np.zeros((n, vmax, n + 1))
    sedge = np.full((n, vmax, n + 1), -1, dtype=np.int64)
    contacts = contacts_at(model, pos, 1e-9 * model.rr)
    Kmat, rows = stiffness_matrix(model, pos, K, Ks, contacts)
    f = np.zeros(3 * n)
    f[1::3] = -model.mass * G
    try:
        u = np.linalg.solve(Kmat, f)
    except np.linalg.LinAlgError:
        return pos, fs, sedge
    if not np.all(np.isfinite(u)) or np.abs(Kmat @ u - f).max() > 1e-6 * np.abs(f).max():
        return pos, fs, sedge
    pos = pos + u.reshape(n, 3)
    for (i, k, j, e, *_), (_gn, gt) in zip(contacts, rows, strict=True):
        i, k, j = int(i), int(k), int(j)
        fs[i, k, j] = -Ks * float(gt @ u)
        sedge[i, k, j] = int(e)
    return pos, fs, sedge


def initial_state(model: Assembly, K: float, Ks: float, theta0: float, omega0: float,
                  settled: bool):
    """Positions, velocities, shear histories and contact edges at t = 0."""
    n = model.n
    vmax = model.lv.shape[1]
    if theta0 == 0.0 and omega0 == 0.0:
        if settled:
            pos, fs, sedge = static_state(model, K, Ks)
        else:
            pos = model.nominal.copy()
            fs = np.zeros((n, vmax, n + 1))
            sedge = np.full((n, vmax, n + 1), -1, dtype=np.int64)
        return pos, np.zeros((n, 3)), fs, sedge
    s = theta0 if theta0 != 0.0 else omega0
    v0 = model.lv[0, 0] if s > 0 else model.lv[0, 1]  # pivot: left (O) or right (O')
    px, py = model.nominal[0, 0] + v0[0], model.nominal[0, 1] + v0[1]
    c, sn = math.cos(theta0), math.sin(theta0)
    pos = model.nominal.copy()
    vel = np.zeros((n, 3))
    sink = model.total_mass * G / K if settled else 0.0  # the pivot carries the weight
    for i in range(n):
        dx, dy = model.nominal[i, 0] - px, model.nominal[i, 1] - py
        pos[i] = (px + c * dx - sn * dy, py + sn * dx + c * dy - sink, theta0)
        vel[i] = (-omega0 * (pos[i, 1] + sink - py), omega0 * (pos[i, 0] - px), omega0)
    return (pos, vel, np.zeros((n, vmax, n + 1)),
            np.full((n, vmax, n + 1), -1, dtype=np.int64))


def time_step(model: Assembly, K: float, Ks: float, b: float, dt: float | None,
              dt_out: float) -> tuple[float, int]:
    """``(dt, every)``: the step (the stable one of :func:`stable_dt`, or ``dt`` if given)
    rounded down to divide ``dt_out``, and the number of steps per output interval.
    A ``dt`` above the stability limit raises :class:`ParameterError`."""
    h = stable_dt(model, K, Ks, b)
    if dt is not None:
        if dt > h / SAFETY:
            raise ParameterError(f"dt = {dt:g} s exceeds the stability limit "
                                 f"{h / SAFETY:.3g} s of central differences")
        h = dt
    every = max(1, int(math.ceil(dt_out / h - 1e-9)))
    return dt_out / every, every


def kernel_params(model: Assembly, K: float, Ks: float, b: float, tanphi: float,
                  cohesion: float, dt: float, every: int, th_tol: float, theta0: float,
                  omega0: float, settled: bool) -> tuple:
    """The parameter tuple ``mp`` of :func:`rocking.models.dem.kernel.kernel` for a run
    released from ``theta0``, ``omega0`` (the contacts' initial state; the bodies'
    positions and velocities travel in the state vector, :func:`state_vector`)."""
    _, _, fs, sedge = initial_state(model, K, Ks, theta0, omega0, settled)
    return DEMParams(model.lv, model.lvn, model.len_, model.nv, model.mass, model.inertia,
                     model.rad, model.rr, K, Ks, b * K, b * Ks, tanphi, cohesion, dt, every,
                     fs, sedge, model.nominal, model.n - 1, th_tol,
                     theta0 == 0.0 and omega0 == 0.0)


def state_vector(model: Assembly, K: float, Ks: float, theta0: float, omega0: float,
                 settled: bool) -> np.ndarray:
    """The state vector of a run released from ``theta0``, ``omega0``: every block's
    ``(x, y, theta)``, then every block's ``(vx, vy, omega)`` (:func:`initial_state`)."""
    pos, vel, _, _ = initial_state(model, K, Ks, theta0, omega0, settled)
    return np.concatenate((pos.ravel(), vel.ravel()))
