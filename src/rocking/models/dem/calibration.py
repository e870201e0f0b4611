"""Calibration of the DEM contact damping to the classical restitution (beyond Eq 20).

**Beyond Eq 20** (:func:`calibrate_damping`): the damping factor ``b`` that makes the
DEM's apparent coefficient of restitution of one impact equal to ``mu`` (Eq 12 with n = 1
on the amplitudes before and after the impact of a free-rocking run), found by a root
search (Brent) and cached.
"""

from __future__ import annotations

import functools
import math

import numpy as np
from scipy.optimize import brentq

from ..._validate import as_float, positive
from ...blocks import Block
from ...errors import ParameterError
from ...motions._kernel import NPRM
from ..base import GENERIC_OUTPUTS, PLANAR_OUTPUTS, empty_results
from . import geometry as GEO
from . import statics as ST
from .friction import DEFAULT_FRICTION_ANGLE, check_friction_angle
from .kernel import kernel

XI_CAP = 4.0
"""Largest damping ratio of the stiffest contact mode that the calibration will use."""


def free_rocking_restitution(block, b: float, K: float | None = None, *,
                             theta0_frac: float = 0.5, geometry: str = "auto",
                             friction_angle: float = DEFAULT_FRICTION_ANGLE,
                             shear_stiffness: float | None = None) -> float:
    """Apparent coefficient of restitution of the DEM: release ``block`` from
    ``theta0 = theta0_frac * alpha`` with damping ``b`` (s) and stiffness ``K`` and
    compare the amplitude ``r1`` after the first impact with ``r0 = theta0`` through the
    energy (Eq 12 with n = 1): ``sqrt((cos(alpha - r1) - cos alpha) / (cos(alpha - r0) -
    cos alpha))``, with the DEM body's alpha. ``friction_angle`` is in rad
    (:func:`rocking.models.dem.friction.check_friction_angle`)."""
    friction_angle = check_friction_angle(friction_angle)
    md = GEO.build_assembly(block, geometry)
    bd = md.bodies[0]
    al, p = bd.alpha, bd.p
    r0 = theta0_frac * al
    # time to the first impact of the classical model (energy: theta'^2 / 2 =
    # p^2 (cos(alpha - r0) - cos(alpha - theta))), with theta = r0 - u^2 (no singularity)
    u = np.linspace(0.0, math.sqrt(r0), 2001)[1:]
    g = 2.0 * u / np.sqrt(math.cos(al - r0) - np.cos(al - r0 + u * u))
    g = np.concatenate(([2.0 / math.sqrt(math.sin(al - r0))], g))
    u = np.concatenate(([0.0], u))
    t1 = float(np.trapezoid(g, u)) / (p * math.sqrt(2.0))
    dt_out = min(2e-4, t1 / 400.0)
    t, theta, impacts, overturned = _free_run(md, b, K, shear_stiffness, friction_angle,
                                              r0, 2.4 * t1, dt_out)
    if overturned or impacts.size == 0:
        return math.nan
    t_i = impacts[0]
    t_end = impacts[1] if impacts.size > 1 else t[-1]
    m = (t > t_i) & (t <= t_end)
    th = np.abs(theta)
    i = int(np.flatnonzero(m)[np.argmax(th[m])])
    r1 = th[i]
    if 0 < i < th.size - 1:  # parabola through the three samples around the peak
        y0, y1, y2 = th[i - 1], th[i], th[i + 1]
        den = y0 - 2 * y1 + y2
        if den < 0:
            r1 = y1 - 0.125 * (y0 - y2) ** 2 / den
    e0 = math.cos(al - r0) - math.cos(al)
    e1 = math.cos(al - r1) - math.cos(al)
    return math.sqrt(max(e1, 0.0) / e0)


def _free_run(md, b, K, Ks, friction_angle, theta0, duration, dt_out):
    """Free rocking of the assembly ``md`` from ``theta0`` (settled on its pivot):
    ``(t, theta, impact_times, overturned)`` at the output interval ``dt_out``."""
    K = GEO.default_stiffness(md) if K is None else float(K)
    Ks = K if Ks is None else float(Ks)
    dt, every = ST.time_step(md, K, Ks, b, None, dt_out)
    th_tol = 1e-3 * min(bd.alpha for bd in md.bodies)
    mp = ST.kernel_params(md, K, Ks, b, math.tan(friction_angle), 0.0, dt,
                          every, th_tol, theta0, 0.0, True)
    n_out = int(math.floor(duration / dt_out + 1e-9)) + 1
    n, vmax = md.n, md.lv.shape[1]
    y0 = ST.state_vector(md, K, Ks, theta0, 0.0, True)
    hist, imp = np.empty((n_out, 6 * n)), np.empty(16)
    extra = (np.empty((0, 3)), np.empty((0, n * vmax * (n + 1), 4)))
    res = empty_results(GENERIC_OUTPUTS + PLANAR_OUTPUTS, 1)
    kernel(mp, 0, np.zeros(NPRM), np.empty(0), duration, math.inf, duration, y0, dt_out, hist,
           imp, res[0], extra)
    k, n_imp = int(res["n_out"][0]), int(res["n_impacts"][0])
    return (np.arange(k) * dt_out, hist[:k, 3 * (n - 1) + 2].copy(), imp[: min(n_imp, imp.size)],
            bool(res["overturned"][0]))


def damping_cap(block, K: float | None = None, geometry: str = "auto",
                shear_stiffness: float | None = None) -> float:
    """Largest damping factor the calibration uses (s): ``xi = XI_CAP`` in the stiffest
    contact mode (beyond it the apparent restitution no longer changes: it has reached the
    plastic-impact value of Housner, Eq 4, and the time step only shrinks)."""
    md = GEO.build_assembly(block, geometry)
    K = GEO.default_stiffness(md) if K is None else float(K)
    Ks = K if shear_stiffness is None else float(shear_stiffness)
    return 2.0 * XI_CAP / ST.omega_max(md, K, Ks)


@functools.lru_cache(maxsize=256)
def _calibrate(block, mu, K, geometry, friction_angle, Ks):
    def f(b):
        return free_rocking_restitution(block, b, K, geometry=geometry,
                                        friction_angle=friction_angle,
                                        shear_stiffness=Ks) - mu

    b_cap = damping_cap(block, K, geometry, Ks)
    f0 = f(0.0)
    if not f0 > 0.0:
        return 0.0, mu + f0, b_cap, (
            f"mu = {mu:.5f} is above the restitution of the undamped DEM ({mu + f0:.5f}: "
            "energy goes into bouncing); no damping")
    fc = f(b_cap)
    if not fc < 0.0:
        if fc < 2e-3:
            note = (f"mu = {mu:.5f} is the plastic-impact (Housner) restitution of the DEM "
                    f"body ({mu + fc:.5f} at the cap xi = {XI_CAP:g})")
        else:
            note = (f"mu = {mu:.5f} is below the DEM body's plastic-impact restitution "
                    f"{mu + fc:.5f}; damping capped at xi = {XI_CAP:g}")
        return b_cap, mu + fc, b_cap, note
    b = float(brentq(f, 0.0, b_cap, xtol=1e-6 * b_cap, rtol=1e-6))
    return b, mu + f(b), b_cap, "root of the apparent restitution"


def calibrate_damping(block, mu: float | None = None, K: float | None = None, *,
                      geometry: str = "auto", friction_angle: float = DEFAULT_FRICTION_ANGLE,
                      shear_stiffness: float | None = None, full: bool = False):
    """Damping factor ``b`` (s, ``C = b K`` at every closed contact) for which the DEM's
    apparent coefficient of restitution (:func:`free_rocking_restitution`) equals ``mu``
    (default: the block's). ``K`` defaults to the DEM's default stiffness; ``friction_angle``
    is in rad (default 30 degrees; :func:`rocking.models.dem.friction.check_friction_angle`).

    Brent's method on ``b`` in ``[0, b_cap]`` (:func:`damping_cap`). The apparent
    restitution falls monotonically as ``b`` grows, from its undamped value (the landing
    corner bounces and part of the energy goes into the bounce: 0.93-0.99 for the
    specimens) to the plastic-impact value of Housner (angular momentum conservation,
    Eq 4 for a rectangle) of the DEM body. A ``mu`` above the first gives ``b = 0``, a
    ``mu`` at or below the second gives ``b_cap`` (the default ``"classical"`` body of a
    block given by its classical parameters is built so that its plastic-impact
    restitution *is* ``mu``). Results are cached (inputs rounded to 9 significant digits).

    ``full=True`` returns a dict: ``b``, ``mu_dem`` (the DEM's apparent restitution with
    that ``b``), ``b_cap`` and ``note``.
    """
    if not isinstance(block, Block):
        raise ParameterError(f"block must be a rocking.Block, got {type(block).__name__}")
    mu = block.mu if mu is None else as_float("mu", mu)
    if not 0.0 < mu <= 1.0:
        raise ParameterError(f"mu must be in (0, 1], got {mu!r}")
    if K is None:
        K = GEO.default_stiffness(GEO.build_assembly(block, geometry))
    K = float(f"{positive('K', K, 'N/m'):.9g}")
    Ks = None if shear_stiffness is None else float(f"{shear_stiffness:.9g}")
    b, mu_dem, b_cap, note = _calibrate(block, float(f"{mu:.9g}"), K, geometry,
                                        check_friction_angle(friction_angle), Ks)
    if full:
        return {"b": b, "mu_dem": mu_dem, "b_cap": b_cap, "note": note}
    return b
