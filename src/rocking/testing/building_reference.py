r"""Plain reference for buildings: a shear building integrated directly, without modes.

API (for tests)::

    from rocking.buildings import Building
    from rocking.testing.building_reference import arrays_of, floor_response

    b = Building.shear(5, 0.5, damping=0.05)
    arrays = arrays_of(b)                      # M, C, K (ShearBuildingArrays)
    a_floor = floor_response(arrays, t, a_g, floor=3)   # absolute acceleration at t

* :func:`shear_building_arrays` ``(masses, stiffnesses, damping)`` builds ``M =
  diag(m_i)``, the tridiagonal ``K`` of the storey stiffnesses ``k_1..k_N`` (bottom to
  top; assembled here, storey by storey, not with :mod:`rocking.buildings`' code) and the
  classical damping matrix with ratio ``zeta_j`` in mode ``j`` (Chopra, *Dynamics of
  Structures*, 11.4: superposition of modal damping matrices)

  .. math:: C = M \Phi \,\mathrm{diag}(2 \zeta_j \omega_j / m_j)\, \Phi^T M,
     \qquad m_j = \phi_j^T M \phi_j,

  with ``(omega_j, Phi)`` from :func:`scipy.linalg.eigh` ``(K, M)`` (modes in increasing
  frequency, the order of ``damping``).
* :func:`arrays_of` ``(building)`` is the same for a :meth:`Building.shear
  <rocking.buildings.Building.shear>`, from its public ``storey_masses``,
  ``storey_stiffnesses`` (already scaled to its first period) and ``damping``.
* :func:`floor_response` ``(arrays, t, a_g, floor)`` integrates

  .. math:: M u'' + C u' + K u = -M 1 a_g(t)

  from rest at ``t[0]`` with :func:`scipy.integrate.solve_ivp` (DOP853, ``rtol`` 1e-12 by
  default, ``atol`` scaled to the response), ``a_g`` linear between its samples: one call
  per sample interval, where the forcing is smooth, so that the kinks of ``a_g`` at the
  samples cost no accuracy. It returns the absolute acceleration of ``floor`` (0 is the
  ground: ``a_g`` itself) at the times ``t``: ``a_g + u_floor'' = -(M^{-1}(C u' + K
  u))_floor``.

It is slow (one ``solve_ivp`` call per sample; ~0.3 s for 1000 samples of a 5-storey
building) and meant for tests. Against the closed-form modal response to a ramp
(``tests/test_buildings.py``) it agrees to ~1e-11 of the peak acceleration.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from scipy.integrate import solve_ivp
from scipy.linalg import eigh

from .._validate import as_int
from ..errors import ParameterError


class ShearBuildingArrays(NamedTuple):
    """``M``, ``C``, ``K`` of a shear building (floors 1..N), in consistent units."""

    M: np.ndarray
    C: np.ndarray
    K: np.ndarray


def shear_building_arrays(masses, stiffnesses, damping) -> ShearBuildingArrays:
    """``M``, classical ``C`` and ``K`` of the shear building with floor ``masses``,
    storey ``stiffnesses`` (bottom to top) and modal ``damping`` (one ratio or one per
    mode); see the module docstring."""
    m = np.asarray(masses, dtype=float)
    k = np.asarray(stiffnesses, dtype=float)
    if m.ndim != 1 or m.shape != k.shape or m.size == 0 or np.any(m <= 0) or np.any(k <= 0):
        raise ParameterError("masses and stiffnesses must be N > 0 values each, positive")
    n = m.size
    zeta = np.asarray(damping, dtype=float)
    if zeta.shape not in ((), (n,)) or np.any(zeta < 0) or np.any(zeta >= 1):
        raise ParameterError(f"damping must be one ratio or {n}, each in [0, 1)")
    M = np.diag(m)
    K = np.zeros((n, n))
    for i in range(n):  # storey i + 1 joins level i (ground for i = 0) to level i + 1
        K[i, i] += k[i]
        if i > 0:
            K[i - 1, i - 1] += k[i]
            K[i - 1, i] -= k[i]
            K[i, i - 1] -= k[i]
    w2, phi = eigh(K, M)
    zeta = np.broadcast_to(zeta, (n,))
    mj = np.einsum("ij,ik,kj->j", phi, M, phi)
    C = M @ phi @ np.diag(2.0 * zeta * np.sqrt(w2) / mj) @ phi.T @ M
    return ShearBuildingArrays(M, C, K)


def arrays_of(building) -> ShearBuildingArrays:
    """:func:`shear_building_arrays` of a :meth:`~rocking.buildings.Building.shear`."""
    if building.storey_stiffnesses is None:
        raise ParameterError(f"building must be a shear building (Building.shear), got a "
                             f"{building.kind} building")
    return shear_building_arrays(building.storey_masses, building.storey_stiffnesses,
                                 building.damping)


def floor_response(arrays: ShearBuildingArrays, t, a_g, floor: int, *,
                   rtol: float = 1e-12) -> np.ndarray:
    """Absolute acceleration of ``floor`` at the times ``t`` (increasing) under the ground
    acceleration samples ``a_g`` (linear between them), from rest; see the module
    docstring."""
    M, C, K = (np.asarray(x, dtype=float) for x in arrays)
    n = M.shape[0]
    f = as_int("floor", floor, 0, n)
    t = np.asarray(t, dtype=float)
    a = np.asarray(a_g, dtype=float)
    if t.ndim != 1 or t.shape != a.shape or t.size < 2 or np.any(np.diff(t) <= 0):
        raise ParameterError("t and a_g must be equal-length samples, t increasing")
    if f == 0:
        return a.copy()
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])
    ones = np.concatenate([np.zeros(n), np.ones(n)])
    # the acceleration is -M^-1 (C u' + K u): an error du costs omega_max^2 du, so atol is
    # scaled to the highest mode's static response to the peak of a_g
    w_max = math.sqrt(np.max(np.linalg.eigvals(np.linalg.solve(M, K)).real))
    peak = max(np.max(np.abs(a)), 1e-300)
    atol = rtol * peak * np.concatenate([np.full(n, 1.0 / w_max ** 2), np.full(n, 1.0 / w_max)])
    y = np.zeros(2 * n)
    out = np.empty_like(a)
    out[0] = -(Minv[f - 1] @ (C @ y[n:] + K @ y[:n]))
    for i in range(t.size - 1):
        t0, t1, a0, a1 = t[i], t[i + 1], a[i], a[i + 1]
        slope = (a1 - a0) / (t1 - t0)

        def rhs(tt, yy, t0=t0, a0=a0, slope=slope):
            return A @ yy - ones * (a0 + slope * (tt - t0))

        sol = solve_ivp(rhs, (t0, t1), y, method="DOP853", rtol=rtol, atol=atol)
        if not sol.success:
            raise RuntimeError(f"solve_ivp failed on [{t0}, {t1}]: {sol.message}")
        y = sol.y[:, -1]
        out[i + 1] = -(Minv[f - 1] @ (C @ y[n:] + K @ y[:n]))
    return out
