r"""A rigid block standing free on a seismically isolated base (``model="isolated"``).

Issue 19 (part 1). The physics, derived in :mod:`rocking.testing.isolated_reference`
(Vassiliou and Makris 2012; Roussis and Odysseos 2017): a base plate of mass
``mass_ratio * m`` on a linear isolator (``isolation_period`` of block plus plate,
``isolation_damping`` ratio) or a friction pendulum (``radius``, ``friction``, ``tanh``
regularisation ``v_eps``). The block rocks under the plate's absolute acceleration ``A``,
coupled to the plate's displacement ``u``; it uplifts when ``|A|`` exceeds ``g tan(alpha)``;
at impacts ``theta'`` is multiplied by ``mu_iso = 1 - 2 lambda sin^2(alpha) / (1 - gamma
lambda cos^2(alpha))`` (or ``mu``) and the plate's velocity jumps by ``gamma h (mu_iso - 1)
theta'``. The run stops when ``|u|`` reaches ``clearance`` (the moat wall), unless the
wall is modelled as a stiff linear spring beyond it (``stop_period``: the period of block
and plate on that spring alone, ``omega_s = 2 pi / stop_period``, a force
``omega_s^2 (|u| - clearance) sgn(u)`` per unit of the isolated mass, elastic: the energy
is conserved; the contacts are located as events, and ``clearance_time`` is the first).

Integration: adaptive Dormand-Prince 5(4) on ``(theta, theta', u, u')`` (the tableau and
Hermite interpolants of :mod:`rocking.models._numerics.dopri`, as the classical model),
mixed error control (``rtol``; absolute tolerances ``1e-3 rtol alpha`` on ``theta``, ``rtol
b`` on ``u``, ``b = R sin(alpha)`` the block's half-width, and these times ``p`` on the
velocities), stepping onto the motion's breakpoints, at most ``max_step``, ``0.05 / p``, 4
scan steps, a twentieth of the isolator's period and, with friction, ``2 v_eps / (mu_f
g)`` (the explicit steps' stability on the regularised friction) and a twentieth of
``stop_period``. The pivot is frozen
within a step; events are located on the exact Dormand-Prince sub-step: impacts by
safeguarded Newton from the Hermite estimate, uplift and clearance by bisection (the
uplift margin and ``|A|`` are also sampled at a quarter, half and three quarters of each
step on the Hermite interpolants, so that an excursion inside a step is not missed).
``max |theta|`` and ``max |u|`` include the extrema inside the steps; ``max |A|`` the
ends, the samples and, where one comes within 1 % of the running peak, a golden-section
search around it; all end at the overturning point. Measured against the reference
(``tests/test_isolated.py``): largest angles to 1.2e-7 (relative), uplift times to 2.4e-9
s, impact times to 2.2e-7 s, ``max |u|`` to 1.1e-8 and ``max |A|`` to 4.5e-7 (3e-6 over
16 random configurations with vertical motions, stops and overturning). Throughput
(``benchmarks/bench_isolated.py``, the 400 records of ``bench_housner.py``, in one run
against the classical model): 1.1 to 1.2 times the classical model's with the default
linear isolator (0.075 with the former fixed-step RK4), 0.54 to 0.59 with a 0.5 s isolator
under which the blocks rock (0.10 before), 0.20 to 0.23 with the default friction pendulum
(0.15 before: where the plate sticks, the tanh regularisation is stiff, about 10,000 steps
per 20 s record against the classical model's 2,700).

Friction regularisation: convergence study of ``v_eps`` (``benchmarks/bench_isolated.py
--n 40 --repeat 1 --v-eps-study``: the first 40 records of ``bench_housner.py``, 20 s,
specimen 2), relative differences against ``v_eps = 3e-5`` m/s, median / largest over the
records:

=========  ==================  ==================  ===================  ==================
v_eps      default pendulum (friction 0.05, 2 m)   friction 0.2, 1 m (block rocks)
---------  --------------------------------------  ---------------------------------------
(m/s)      ``max |u|``         ``max |A|``         ``max |theta|``      ``max |A|``
=========  ==================  ==================  ===================  ==================
1e-2       6.6e-2 / 2.1e-1     1.5e-2 / 3.9e-2     2.2e-1 / 8.6e-1      1.6e-1 / 6.4e-1
3e-3       2.8e-2 / 9.2e-2     5.1e-3 / 1.3e-2     1.9e-1 / 8.4e-1      1.0e-1 / 7.3e-1
1e-3       1.3e-2 / 4.9e-2     2.2e-3 / 5.7e-3     1.3e-1 / 6.9e-1      1.1e-1 / 7.7e-1
3e-4       5.1e-3 / 1.9e-2     7.8e-4 / 1.9e-3     6.3e-2 / 6.7e-1      1.2e-2 / 5.9e-1
1e-4       1.5e-3 / 5.9e-3     2.5e-4 / 5.8e-4     4.7e-2 / 8.8e-1      4.0e-4 / 4.8e-1
=========  ==================  ==================  ===================  ==================

With the default pendulum the plate slides and the block stays down: the results converge
at first order (``v_eps^0.8`` to ``v_eps^0.9``), and the default ``v_eps = 1e-3`` m/s gives
``max |u|`` to about 1 % (5 % at worst) and ``max |A|`` to 0.2 % (0.6 %), at 10,000 steps
per 20 s record (51,000 at 1e-4, 165,000 at 3e-5). With a friction above ``tan(alpha)``
the block rocks on a plate that mostly sticks, and the response, chaotic record by record,
converges slowly: the median of ``max |theta|`` over the records is 0.0821, 0.0907, 0.0853
rad at ``v_eps`` = 1e-2, 1e-3, 1e-4 (0.0854 at 3e-5), 1 or 2 of the 40 overturning
outcomes flip, and the steps grow to 92,000 per record at 1e-3 (790,000 at 1e-4). A
sticking plate creeps at ``u' = v_eps atanh(|F| / (mu_f N))``: its ``max |u|`` is then the
regularisation's creep (it changes by factors with ``v_eps``), not sliding. Use ``v_eps <=
1e-4`` m/s where the plate sticks while the block rocks, and compare statistics over
records rather than single records.

Vertical ground motion (:class:`rocking.motions.GroundMotion`, ``a_v`` positive upwards;
also the vertical floor motion of :class:`rocking.buildings.FloorMotion`): ``g`` becomes
``g + a_v`` in the block's gravity terms (``theta''`` and the plate's ``A``), in the uplift
threshold ``(g + a_v) tan(alpha)`` and in the Zeno rule, and the friction pendulum's
restoring and friction forces scale with its normal force, ``(g + a_v) / g`` (the linear
isolator's stiffness and damping do not); derived in
:mod:`rocking.testing.isolated_reference`. Where ``g + a_v <= 0`` the run stops at the
first such instant (``lift_off_time``; not settled), as in the classical model. Without a
vertical component, or with a zero one on the horizontal record's grid, the arithmetic is
the horizontal model's (bit-identical results).

Row outputs (``Response.info`` of single runs, ``BatchResponse.outputs`` of batches,
columns of campaigns): ``max_base_displacement`` (m, ``max |u|`` at the steps),
``max_plate_acceleration`` (m/s^2, ``max |A|`` at the steps), ``clearance_exceeded`` and
``clearance_time`` (s, NaN if not). Rest: after an impact, the Zeno rule of the classical
model with the plate taking the common velocity that conserves the horizontal momentum;
once the ground is still (``t_quiet``) a block at rest is settled when an energy bound of
the plate's free motion shows that ``|A|`` can no longer reach ``g tan(alpha)`` (with a
friction pendulum whose ``mu_f g`` exceeds it, the run goes to its time cap).

Asymmetric blocks (:meth:`rocking.Block.from_geometry`, :meth:`rocking.Block.from_mesh`,
mesh directions; derived in the reference's "Asymmetric blocks", after Vassiliou and
Makris 2012's Lagrangian and impact, with Contento and Di Egidio 2009's two sides): on the
pivot ``s`` the equations of motion take that side's ``alpha_s``, ``p_s``, ``R_s``,
``lambda_s``; a block at rest uplifts towards ``+`` when ``A > (g + a_v) tan(alpha_+)``,
towards ``-`` when ``-A > (g + a_v) tan(alpha_-)``; an impact that ends rocking on side
``s`` multiplies ``theta'`` by ``mu_iso,s = 1 - lambda_o sin(alpha_o) (sin(alpha_o) +
(R_s/R_o) sin(alpha_s)) / (1 - gamma lambda_o cos^2(alpha_o))`` (``o`` the landing side;
the block's fixed-base ``mu_s`` as ``gamma -> 0``) and the plate's velocity by ``gamma h_o
(mu_iso,s - 1) theta'``; the Zeno rule uses the landing side. The step sizes follow the
faster side (largest ``p``), the error norms the smaller ``alpha`` and half-width. With
equal sides every operation is the symmetric one (bit-identical results). A given ``mu``
applies to both sides.

Batches may hold one block per row (campaigns with uncertain ``alpha`` and ``p``): one
compiled call, :meth:`Isolated.block_row` ``(alpha_+, p_+, R_+, alpha_-, p_-, R_-)`` and
:func:`with_block` rebuilding ``lambda`` and the derived restitutions with the same
compiled :func:`side_terms` as :meth:`Isolated.kernel_params` (rows bit-identical to single
runs).

Checked against :func:`rocking.testing.isolated_reference.simulate_isolated_reference`
and with :func:`rocking.testing.check_model` in ``tests/test_isolated.py``. Registered as
``model="isolated"`` (:data:`rocking.models.MODELS`).
"""

from __future__ import annotations

import math
from collections import namedtuple
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from .._validate import warn_implausible
from ..errors import ParameterError
from ..motions._kernel import (
    ground_acc,
    ground_acc_hv,
    has_vertical,
    next_breakpoint,
    vertical_acc,
)
from ..units import G
from ._numerics import dopri as D
from ._numerics import events as E
from .base import (
    GENERIC_OUTPUTS,
    PLANAR_OUTPUTS,
    Model,
    ModelOptions,
    Output,
    option,
    row_args,
    set_planar_result,
    store_row,
)

HALF_PI = 0.5 * math.pi
DEFAULT_RTOL = 1e-8


IsolatedParams = namedtuple("IsolatedParams", [
    "alpha", "p", "mu", "R", "lam", "gam", "iso", "c1", "c2", "veps", "clearance", "h_max",
    "rest_tol", "rtol", "mu_given", "ws2", "alpha_m", "p_m", "mu_m", "R_m", "lam_m"])
"""The kernel parameters ``mp`` of the isolated model: the block's side + (``alpha``,
``p``, ``mu`` used at an impact that ends rocking on side +, ``R``, ``lam = R p^2 / g``),
``gam = 1 / (1 + mass_ratio)``, the isolator (``iso`` 0: linear, 1: pendulum; its ``c1``,
``c2``, ``veps``), the clearance (m, inf: none), the largest step (s), the tolerances, the
given restitution (NaN: derived), the stop's ``omega_s^2`` (0: none) and the block's side
- (``alpha_m``, ``p_m``, ``mu_m``, ``R_m``, ``lam_m``; equal to side + for a symmetric
block)."""


@njit(cache=True)
def _force(mp, u, v, gf):
    """Isolator force per unit of the isolated mass (m/s^2); ``gf = 1 + a_v / g`` scales
    the friction pendulum's (its normal force), not the linear isolator's. Beyond the
    clearance, the stop's spring ``omega_s^2 (|u| - clearance) sgn(u)`` (``mp.ws2``)."""
    if mp.iso == 0.0:
        f = mp.c1 * u + mp.c2 * v
    else:
        f = gf * (mp.c1 * u + mp.c2 * math.tanh(v / mp.veps))
    if mp.ws2 > 0.0 and abs(u) > mp.clearance:
        f += mp.ws2 * (u - mp.clearance) if u > 0.0 else mp.ws2 * (u + mp.clearance)
    return f


@njit(cache=True)
def _gf(prm, samples, t):
    """``1 + a_v(t) / g`` (1 without a vertical component)."""
    if not has_vertical(prm):
        return 1.0
    return 1.0 + vertical_acc(prm, samples, t) / G


@njit(cache=True)
def _acc(mp, th, om, u, v, s, rock, gf):
    """``(A, theta'')`` of the state ``(th, om, u, v)`` on pivot ``s`` under the gravity
    ``gf g``: the plate's absolute acceleration and the block's (reference docstring)."""
    f = _force(mp, u, v, gf)
    if not rock:
        return -f, 0.0
    if s > 0.0:  # the parameters of the pivot's side
        alpha, p, R, lam = mp.alpha, mp.p, mp.R, mp.lam
    else:
        alpha, p, R, lam = mp.alpha_m, mp.p_m, mp.R_m, mp.lam_m
    gam = mp.gam
    phi = alpha - s * th
    c, sn = math.cos(phi), math.sin(phi)
    p2 = p * p
    A = (-f + s * gam * R * sn * (om * om - p2 * gf * c)) / (1.0 - gam * lam * c * c)
    return A, p2 * (c * A / G - s * gf * sn)


@njit(cache=True)
def _deriv(mp, th, om, u, v, t, s, rock, kind, prm, samples):
    """``(theta'', u'', A)`` at time ``t`` (``u'' = A - a_g``)."""
    if has_vertical(prm):
        ag, av = ground_acc_hv(kind, prm, samples, t)
        gf = 1.0 + av / G
    else:
        ag, gf = ground_acc(kind, prm, samples, t), 1.0
    A, thdd = _acc(mp, th, om, u, v, s, rock, gf)
    return thdd, A - ag, A


@njit(cache=True)
def _step(mp, t, th, om, u, v, a1, b1, h, s, rock, kind, prm, samples):
    """One Dormand-Prince 5(4) step of ``(theta, theta', u, u')`` from ``t`` with the
    accelerations ``a1 = theta''``, ``b1 = u''`` there (the tableau of
    :mod:`rocking.models._numerics.dopri`). Returns the state at ``t + h``, its
    ``(theta'', u'', A)`` (first same as last) and the four error estimates."""
    x_t = th + h * D.A21 * om
    x_o = om + h * D.A21 * a1
    x_u = u + h * D.A21 * v
    x_v = v + h * D.A21 * b1
    k2t, k2u = x_o, x_v
    a2, b2, _ = _deriv(mp, x_t, x_o, x_u, x_v, t + D.C2 * h, s, rock, kind, prm, samples)
    x_t = th + h * (D.A31 * om + D.A32 * k2t)
    x_o = om + h * (D.A31 * a1 + D.A32 * a2)
    x_u = u + h * (D.A31 * v + D.A32 * k2u)
    x_v = v + h * (D.A31 * b1 + D.A32 * b2)
    k3t, k3u = x_o, x_v
    a3, b3, _ = _deriv(mp, x_t, x_o, x_u, x_v, t + D.C3 * h, s, rock, kind, prm, samples)
    x_t = th + h * (D.A41 * om + D.A42 * k2t + D.A43 * k3t)
    x_o = om + h * (D.A41 * a1 + D.A42 * a2 + D.A43 * a3)
    x_u = u + h * (D.A41 * v + D.A42 * k2u + D.A43 * k3u)
    x_v = v + h * (D.A41 * b1 + D.A42 * b2 + D.A43 * b3)
    k4t, k4u = x_o, x_v
    a4, b4, _ = _deriv(mp, x_t, x_o, x_u, x_v, t + D.C4 * h, s, rock, kind, prm, samples)
    x_t = th + h * (D.A51 * om + D.A52 * k2t + D.A53 * k3t + D.A54 * k4t)
    x_o = om + h * (D.A51 * a1 + D.A52 * a2 + D.A53 * a3 + D.A54 * a4)
    x_u = u + h * (D.A51 * v + D.A52 * k2u + D.A53 * k3u + D.A54 * k4u)
    x_v = v + h * (D.A51 * b1 + D.A52 * b2 + D.A53 * b3 + D.A54 * b4)
    k5t, k5u = x_o, x_v
    a5, b5, _ = _deriv(mp, x_t, x_o, x_u, x_v, t + D.C5 * h, s, rock, kind, prm, samples)
    x_t = th + h * (D.A61 * om + D.A62 * k2t + D.A63 * k3t + D.A64 * k4t + D.A65 * k5t)
    x_o = om + h * (D.A61 * a1 + D.A62 * a2 + D.A63 * a3 + D.A64 * a4 + D.A65 * a5)
    x_u = u + h * (D.A61 * v + D.A62 * k2u + D.A63 * k3u + D.A64 * k4u + D.A65 * k5u)
    x_v = v + h * (D.A61 * b1 + D.A62 * b2 + D.A63 * b3 + D.A64 * b4 + D.A65 * b5)
    k6t, k6u = x_o, x_v
    a6, b6, _ = _deriv(mp, x_t, x_o, x_u, x_v, t + h, s, rock, kind, prm, samples)
    th1 = th + h * (D.B1 * om + D.B3 * k3t + D.B4 * k4t + D.B5 * k5t + D.B6 * k6t)
    om1 = om + h * (D.B1 * a1 + D.B3 * a3 + D.B4 * a4 + D.B5 * a5 + D.B6 * a6)
    u1 = u + h * (D.B1 * v + D.B3 * k3u + D.B4 * k4u + D.B5 * k5u + D.B6 * k6u)
    v1 = v + h * (D.B1 * b1 + D.B3 * b3 + D.B4 * b4 + D.B5 * b5 + D.B6 * b6)
    a7, b7, A7 = _deriv(mp, th1, om1, u1, v1, t + h, s, rock, kind, prm, samples)
    e_t = h * (D.E1 * om + D.E3 * k3t + D.E4 * k4t + D.E5 * k5t + D.E6 * k6t + D.E7 * om1)
    e_o = h * (D.E1 * a1 + D.E3 * a3 + D.E4 * a4 + D.E5 * a5 + D.E6 * a6 + D.E7 * a7)
    e_u = h * (D.E1 * v + D.E3 * k3u + D.E4 * k4u + D.E5 * k5u + D.E6 * k6u + D.E7 * v1)
    e_v = h * (D.E1 * b1 + D.E3 * b3 + D.E4 * b4 + D.E5 * b5 + D.E6 * b6 + D.E7 * b7)
    return th1, om1, u1, v1, a7, b7, A7, e_t, e_o, e_u, e_v


@njit(cache=True)
def _sq(e, y0, y1, atol, rtol):
    return (e / (atol + rtol * max(abs(y0), abs(y1)))) ** 2


@njit(cache=True)
def _emit(t0, th0, om0, a0, t1, th1, om1, a1, dt_out, k, out_th, out_om):
    """Write the samples ``k * dt_out`` in ``(t0, t1]`` (quintic Hermite); returns the
    next ``k``."""
    n = out_th.shape[0]
    h = t1 - t0
    while k < n and k * dt_out <= t1 + 1e-12:
        if h > 0.0:
            x = min(max((k * dt_out - t0) / h, 0.0), 1.0)
            out_th[k], out_om[k] = D.hermite5(th0, om0, a0, th1, om1, a1, h, x)
        else:
            out_th[k], out_om[k] = th1, om1
        k += 1
    return k


@njit(cache=True)
def _extremum(x0, v0, a0, x1, v1, a1, h, peak):
    """The running ``max |x|`` with the segment's end and its extremum inside, if any."""
    peak = max(peak, abs(x1))
    if v0 * v1 < 0.0 and h > 0.0:
        z = D.hermite_root(x0, v0, a0, x1, v1, a1, h, 0.0, 1, v0)
        peak = max(peak, abs(D.hermite5(x0, v0, a0, x1, v1, a1, h, z)[0]))
    return peak


@njit(cache=True)
def _acc_at(mp, seg, x, s, rock, prm, samples):
    """``A`` at the fraction ``x`` of the step ``seg`` (``t, h`` and both ends' states and
    accelerations), on the Hermite interpolants of ``theta`` and ``u``."""
    t, h = seg[0], seg[1]
    th, om = D.hermite5(seg[2], seg[3], seg[6], seg[7], seg[8], seg[11], h, x)
    u, v = D.hermite5(seg[4], seg[5], seg[12], seg[9], seg[10], seg[13], h, x)
    return _acc(mp, th, om, u, v, s, rock, _gf(prm, samples, t + x * h))[0]


@njit(cache=True)
def _up_margin(A, thr, gf):
    """How far the plate's acceleration ``A`` of a block at rest is beyond the uplift
    threshold of the side it drives (positive: it uplifts): ``A - gf g tan(alpha_+)``
    towards +, ``-A - gf g tan(alpha_-)`` towards -; ``thr = (g tan(alpha_+),
    g tan(alpha_-))``. Equal sides: ``|A| - gf g tan(alpha)`` exactly."""
    return max(A - thr[0] * gf, -A - thr[1] * gf)


@njit(cache=True)
def _peak_acc(mp, seg, s, rock, prm, samples, peak, a0, a1, thr):
    """The running ``max |A|`` over the step: the ends (``a0``, ``a1``), ``x = 1/4, 1/2,
    3/4`` and, where a sample comes within 1 % of the running peak, a golden-section search
    around the largest; and the first sample ``x`` at which a block at rest uplifts
    (:func:`_up_margin` > 0; 2 if none)."""
    best, xb = a0, 0.0
    if a1 > best:
        best, xb = a1, 1.0
    x_up = 2.0
    for j in range(1, 4):
        x = 0.25 * j
        a_s = _acc_at(mp, seg, x, s, rock, prm, samples)
        a = abs(a_s)
        if a > best:
            best, xb = a, x
        if not rock and x_up > 1.0:
            gf = _gf(prm, samples, seg[0] + x * seg[1])
            if gf > 0.0 and _up_margin(a_s, thr, gf) > 0.0:
                x_up = x
    if best > 0.99 * peak:
        lo, hi = max(xb - 0.25, 0.0), min(xb + 0.25, 1.0)
        r = 0.5 * (math.sqrt(5.0) - 1.0)
        c = hi - r * (hi - lo)
        d = lo + r * (hi - lo)
        fc = abs(_acc_at(mp, seg, c, s, rock, prm, samples))
        fd = abs(_acc_at(mp, seg, d, s, rock, prm, samples))
        for _ in range(30):
            if fc > fd:
                hi, d, fd = d, c, fc
                c = hi - r * (hi - lo)
                fc = abs(_acc_at(mp, seg, c, s, rock, prm, samples))
            else:
                lo, c, fc = c, d, fd
                d = lo + r * (hi - lo)
                fd = abs(_acc_at(mp, seg, d, s, rock, prm, samples))
        best = max(best, fc, fd)
    return max(peak, best), x_up


@njit(cache=True)
def _event(mp, which, th, u, v, t, s, prm, samples, thr):
    """Event functions at ``t``, positive once the event has happened: 1 uplift of a block
    at rest (``A = -F/M`` beyond ``(g + a_v) tan(alpha_s)`` towards its side ``s``,
    :func:`_up_margin`; never where ``g + a_v <= 0``: the lift-off comes first), 2
    clearance."""
    if which == 1:
        gf = _gf(prm, samples, t)
        return _up_margin(-_force(mp, u, v, gf), thr, gf) if gf > 0.0 else -1.0
    if which == 2:
        return abs(u) - mp.clearance
    return mp.clearance - abs(u)  # 4: the plate leaves the stop


@njit(cache=True)
def _locate(mp, which, t, y, d, hi, s, rock, kind, prm, samples, thr):
    """The first time (as a step length in ``(0, hi]``) at which event ``which`` holds,
    by bisection on the exact Dormand-Prince sub-step (the event holds at ``hi``)."""
    lo = 0.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not (lo < mid < hi) or hi - lo <= 1e-15 * (1.0 + t):
            break
        r = _step(mp, t, y[0], y[1], y[2], y[3], d[0], d[1], mid, s, rock, kind, prm,
                  samples)
        if _event(mp, which, r[0], r[2], r[3], t + mid, s, prm, samples, thr) > 0.0:
            hi = mid
        else:
            lo = mid
    return hi


@njit(cache=True)
def _locate_impact(mp, t, y, d, hh, y1, d1, s, rock, kind, prm, samples):
    """The step length to the impact (``theta`` back to 0) in ``(0, hh]``: safeguarded
    Newton on the exact sub-step from the Hermite estimate (as the classical model)."""
    x = D.hermite_root(y[0], y[1], d[0], y1[0], y1[1], d1[0], hh, 0.0, 0, s)
    lo, hi = 0.0, hh
    sig = x * hh
    for _ in range(60):
        r = _step(mp, t, y[0], y[1], y[2], y[3], d[0], d[1], sig, s, rock, kind, prm,
                  samples)
        thc, omc = r[0], r[1]
        if s * thc > 0.0:
            lo = sig
        else:
            hi = sig
        if abs(thc) <= 1e-15 * (mp.alpha if s > 0.0 else mp.alpha_m) or (
                hi - lo <= 1e-15 * (1.0 + t)):
            break
        new = sig - thc / omc if omc != 0.0 else -1.0
        if not (lo < new < hi):
            new = 0.5 * (lo + hi)
        sig = new
    return sig


@njit(cache=True)
def _amp_bound(mp, y):
    """An upper bound of the plate's |A| in free motion of the resting system (infinite
    while the energy could still carry the plate onto the stop)."""
    if mp.ws2 > 0.0 and (y[3] * y[3] / mp.c1 + y[2] * y[2]) >= mp.clearance * mp.clearance:
        return math.inf
    if mp.iso == 0.0:
        w2 = mp.c1
        e2 = y[3] * y[3] + w2 * y[2] * y[2]
        return math.sqrt(w2 * e2) * math.sqrt(1.0 + mp.c2 * mp.c2 / w2)
    e2 = y[3] * y[3] + mp.c1 * y[2] * y[2]
    return math.sqrt(mp.c1 * e2) + mp.c2


@njit(cache=True)
def kernel(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp, res, extra):
    """The single-run kernel of the model interface (:mod:`rocking.models.base`)."""
    th0, om0 = y0[0], y0[1]
    out_th, out_om = hist[:, 0], hist[:, 1]
    gam, rest_tol, rtol = mp.gam, mp.rest_tol, mp.rtol
    # the heights of the centre of mass seen from either pivot (one height for a rigid
    # body; the landing side's is used at an impact) and the uplift thresholds
    hc_p, hc_m = mp.R * math.cos(mp.alpha), mp.R_m * math.cos(mp.alpha_m)
    thr = (G * math.tan(mp.alpha), G * math.tan(mp.alpha_m))
    thr_lo = min(thr[0], thr[1])
    p = max(mp.p, mp.p_m)  # the step sizes follow the faster side, the errors the smaller
    alpha = min(mp.alpha, mp.alpha_m)
    hv = has_vertical(prm)
    h_max = min(mp.h_max, 0.05 / p, 4.0 * h_scan)
    atol_th = 1e-3 * rtol * alpha
    atol_om = atol_th * p
    # the plate to rtol of the block's half-width b (the smaller side's)
    if mp.R * math.sin(mp.alpha) <= mp.R_m * math.sin(mp.alpha_m):
        atol_u = rtol * mp.R * math.sin(mp.alpha)
    else:
        atol_u = rtol * mp.R_m * math.sin(mp.alpha_m)
    atol_v = atol_u * p
    y = np.zeros(4)
    y[0], y[1] = th0, om0
    d = np.zeros(3)  # theta'', u'', A at (t, y)
    y1 = np.zeros(4)
    d1 = np.zeros(3)
    seg = np.zeros(14)
    t, k, n_imp, n_steps = 0.0, 0, 0, 0
    peak, peak_u, peak_a = abs(th0), 0.0, 0.0
    rock = not (th0 == 0.0 and om0 == 0.0)
    t_up = 0.0 if rock else math.nan
    s = 1.0 if (th0 > 0.0 or (th0 == 0.0 and om0 > 0.0)) else -1.0
    over, t_over, cleared, t_clear = False, math.nan, False, math.nan
    t_lift = math.nan
    n_out = out_th.shape[0]
    if n_out > 0:
        out_th[0], out_om[0] = th0, om0
        k = 1
    if hv and E.lifts_off(prm, samples, 0.0):
        t_end = 0.0  # the base falls away at once
        t_lift = 0.0
    h = min(h_max, 0.01 / p)
    need_d = True
    while t < t_end - 1e-12:
        if not rock:
            if t >= t_quiet and _amp_bound(mp, y) <= thr_lo:
                break  # the ground is still and the plate cannot uplift the block
            gf = _gf(prm, samples, t)
            a0 = -_force(mp, y[2], y[3], gf)
            if _up_margin(a0, thr, gf) > 0.0:
                rock, s, need_d = True, (1.0 if a0 > 0.0 else -1.0), True
                if math.isnan(t_up):
                    t_up = t
        if need_d:
            d[0], d[1], d[2] = _deriv(mp, y[0], y[1], y[2], y[3], t, s, rock, kind, prm,
                                      samples)
            peak_a = max(peak_a, abs(d[2]))
            need_d = False
        bp = next_breakpoint(kind, prm, samples, t)
        hh = min(h, h_max, t_end - t)
        hit_bp = False
        if t + hh >= bp - 1e-12:
            hh = bp - t
            hit_bp = True
        r = _step(mp, t, y[0], y[1], y[2], y[3], d[0], d[1], hh, s, rock, kind, prm,
                  samples)
        n_steps += 1
        if rock:
            err = math.sqrt(0.25 * (_sq(r[7], y[0], r[0], atol_th, rtol)
                                    + _sq(r[8], y[1], r[1], atol_om, rtol)
                                    + _sq(r[9], y[2], r[2], atol_u, rtol)
                                    + _sq(r[10], y[3], r[3], atol_v, rtol)))
        else:
            err = math.sqrt(0.5 * (_sq(r[9], y[2], r[2], atol_u, rtol)
                                   + _sq(r[10], y[3], r[3], atol_v, rtol)))
        if not (err <= 1.0):
            fac = 0.9 * err ** -0.2 if err == err else 0.1
            h = hh * max(0.1, fac)
            continue
        y1[0], y1[1], y1[2], y1[3] = r[0], r[1], r[2], r[3]
        d1[0], d1[1], d1[2] = r[4], r[5], r[6]
        # ---- accepted: events. A step that hides two zero crossings is retried shorter
        # (seen at the step's quarters, or a dip below 0 where the velocity vanishes).
        if rock and (D.sign_changes(y[0], y[1], d[0], y1[0], y1[1], d1[0], hh, s) >= 2 or (
                s * y1[0] >= 0.0 and hh > 1e-9 * h_max  # (the halving must end)
                and D.may_hide_crossing(y[0], y[1], d[0], y1[0], y1[1], d1[0], hh, s)
                and D.dips_below(y[0], y[1], d[0], y1[0], y1[1], d1[0], hh, s))):
            h = 0.5 * hh
            continue
        seg[0], seg[1] = t, hh
        seg[2], seg[3], seg[4], seg[5], seg[6] = y[0], y[1], y[2], y[3], d[0]
        seg[7], seg[8], seg[9], seg[10], seg[11] = y1[0], y1[1], y1[2], y1[3], d1[0]
        seg[12], seg[13] = d[1], d1[1]
        pa, x_up = _peak_acc(mp, seg, s, rock, prm, samples, peak_a, abs(d[2]), abs(d1[2]),
                             thr)
        ev = -1
        sig = hh
        if rock:
            if s * y1[0] < 0.0:
                ev, sig = 0, _locate_impact(mp, t, y, d, hh, y1, d1, s, rock, kind, prm,
                                            samples)
        else:
            if _event(mp, 1, 0.0, y1[2], y1[3], t + hh, s, prm, samples, thr) > 0.0:
                x_up = min(x_up, 1.0)
            if x_up <= 1.0:
                ev, sig = 1, _locate(mp, 1, t, y, d, x_up * hh, s, rock, kind, prm, samples,
                                     thr)
        x_cl = 2.0  # clearance: at the end or at the extremum of u inside the step
        w_cl = 2  # reaching the clearance; 4: leaving the stop (stop_period)
        if abs(y[2]) >= mp.clearance:  # on the stop (only with a stop: otherwise the run ended)
            w_cl = 4
            if abs(y1[2]) < mp.clearance:
                x_cl = 1.0
        elif abs(y1[2]) >= mp.clearance:
            x_cl = 1.0
        elif y[3] * y1[3] < 0.0:
            z = D.hermite_root(y[2], y[3], d[1], y1[2], y1[3], d1[1], hh, 0.0, 1, y[3])
            if abs(D.hermite5(y[2], y[3], d[1], y1[2], y1[3], d1[1], hh, z)[0]) >= mp.clearance:
                x_cl = z
        if x_cl <= 1.0 and x_cl * hh <= sig:
            sc = _locate(mp, w_cl, t, y, d, x_cl * hh, s, rock, kind, prm, samples, thr)
            if ev < 0 or sc < sig:
                ev, sig = w_cl, sc
        if hv:  # the base falls away (g + a_v <= 0): the model cannot represent flight
            tl = E.first_lift_off(prm, samples, t, t + sig, h_scan)
            if tl == tl and tl - t <= sig:
                ev, sig = 3, tl - t
        if ev >= 0:
            if sig != hh:
                r = _step(mp, t, y[0], y[1], y[2], y[3], d[0], d[1], sig, s, rock, kind,
                          prm, samples)
                y1[0], y1[1], y1[2], y1[3] = r[0], r[1], r[2], r[3]
                d1[0], d1[1], d1[2] = r[4], r[5], r[6]
                seg[1] = sig
                seg[7], seg[8], seg[9], seg[10], seg[11] = y1[0], y1[1], y1[2], y1[3], d1[0]
                seg[13] = d1[1]
                pa, x_up = _peak_acc(mp, seg, s, rock, prm, samples, peak_a, abs(d[2]),
                                     abs(d1[2]), thr)
            if ev == 0:
                y1[0] = 0.0
        if rock and ev != 0 and abs(y1[0]) >= HALF_PI:  # overturning inside the step
            x = D.hermite_root(y[0], y[1], d[0], y1[0], y1[1], d1[0], sig, s * HALF_PI, 0,
                               -s)
            so = x * sig  # the exact sub-step to the overturning: peaks up to it only
            r = _step(mp, t, y[0], y[1], y[2], y[3], d[0], d[1], so, s, rock, kind, prm,
                      samples)
            y1[0], y1[1], y1[2], y1[3] = r[0], r[1], r[2], r[3]
            d1[0], d1[1], d1[2] = r[4], r[5], r[6]
            seg[1] = so
            seg[7], seg[8], seg[9], seg[10], seg[11] = y1[0], y1[1], y1[2], y1[3], d1[0]
            seg[13] = d1[1]
            peak_a = _peak_acc(mp, seg, s, rock, prm, samples, peak_a, abs(d[2]),
                               abs(d1[2]), thr)[0]
            t_over = t + so
            if n_out > 0:
                k = _emit(t, y[0], y[1], d[0], t_over, s * HALF_PI, y1[1], d1[0], dt_out, k,
                          out_th, out_om)
            peak_u = _extremum(y[2], y[3], d[1], y1[2], y1[3], d1[1], so, peak_u)
            over, peak = True, HALF_PI
            t = t_over
            break
        if n_out > 0:
            k = _emit(t, y[0], y[1], d[0], t + sig, y1[0], y1[1], d1[0], dt_out, k, out_th,
                      out_om)
        peak = _extremum(y[0], y[1], d[0], y1[0], y1[1], d1[0], sig, peak)
        peak_u = _extremum(y[2], y[3], d[1], y1[2], y1[3], d1[1], sig, peak_u)
        peak_a = pa
        t = t + sig
        y[0], y[1], y[2], y[3] = y1[0], y1[1], y1[2], y1[3]
        d[0], d[1], d[2] = d1[0], d1[1], d1[2]
        if ev < 0:
            if hit_bp:
                need_d = True  # the excitation has a kink or jump here
            fac = 0.9 * err ** -0.2 if err > 0.0 else 5.0
            h = hh * min(5.0, max(0.2, fac)) if not hit_bp or hh >= h else max(h, hh)
            continue
        need_d = True
        if ev == 3:
            t_lift = t
            break
        if ev == 2 or ev == 4:
            if ev == 2 and not cleared:
                cleared, t_clear = True, t
            if mp.ws2 == 0.0:
                break  # no stop modelled: the run ends at the clearance
            continue
        if ev == 1:
            rock = True
            s = 1.0 if -_force(mp, y[2], y[3], _gf(prm, samples, t)) > 0.0 else -1.0
            if math.isnan(t_up):
                t_up = t
            continue
        # ev == 0: impact
        if n_imp < imp.shape[0]:
            imp[n_imp] = t
        n_imp += 1
        om1 = y[1]
        om2 = (mp.mu if s > 0.0 else mp.mu_m) * om1  # rocking on side s ends
        sn = 1.0 if om2 > 0.0 else -1.0  # the landing side (the new pivot's)
        al_n, p_n, hc = (mp.alpha, mp.p, hc_p) if sn > 0.0 else (mp.alpha_m, mp.p_m, hc_m)
        y[0] = 0.0
        y[1] = om2
        y[3] += gam * hc * (om2 - om1)
        gf = _gf(prm, samples, t)
        c = math.cos(al_n) + 0.5 * (om2 / p_n) ** 2 / gf if gf > 0.0 else 2.0
        amp = al_n - math.acos(c) if c < 1.0 else math.inf
        v_rest = y[3] - gam * hc * om2
        if om2 == 0.0 or (amp < rest_tol * al_n
                          and _up_margin(-_force(mp, y[2], v_rest, gf), thr, gf) <= 0.0):
            y[1], y[3] = 0.0, v_rest
            rock = False
        else:
            s = sn
            d[0], d[1], d[2] = _deriv(mp, y[0], y[1], y[2], y[3], t, s, rock, kind, prm,
                                      samples)
            peak_a = max(peak_a, abs(d[2]))
            need_d = False
            h = min(h_max, max(sig, 1e-6 / p))
            if y[1] * d[0] < 0.0:  # the rebound lasts 2|om/a|: do not jump over it
                h = min(h, 0.5 * abs(y[1] / d[0]))
    set_planar_result(res, k, n_imp, peak, over, t_over, t_up, n_steps, 0, t_lift,
                      (over or not rock) and t_lift != t_lift)
    res.max_base_displacement = peak_u
    res.max_plate_acceleration = peak_a
    res.clearance_exceeded = cleared
    res.clearance_time = t_clear


@njit(cache=True)
def block_terms(alpha, p, R, gam, mu_given):
    """``(lambda, mu)`` of a symmetric block (``lambda = R p^2 / g``; ``mu``: ``mu_given``,
    or the derived restitution ``1 - 2 lambda sin^2(alpha) / (1 - gamma lambda
    cos^2(alpha))`` where it is NaN)."""
    lam = R * p * p / G
    if mu_given == mu_given:
        return lam, mu_given
    return lam, 1.0 - 2.0 * lam * math.sin(alpha) ** 2 / (
        1.0 - gam * lam * math.cos(alpha) ** 2)


@njit(cache=True)
def side_terms(alpha_p, p_p, R_p, alpha_m, p_m, R_m, gam, mu_given):
    """``(lambda_+, mu_+, lambda_-, mu_-)`` of a block's two sides: ``lambda_s = R_s p_s^2
    / g``, and ``mu_s`` (the restitution of an impact that ends rocking on side ``s``)
    ``mu_given``, or where it is NaN the one derived from the momentum balance with the
    plate (:mod:`rocking.testing.isolated_reference`, asymmetric impact), with ``o`` the
    landing side:

    ``mu_s = 1 - lambda_o sin(alpha_o) (sin(alpha_o) + (R_s/R_o) sin(alpha_s)) / (1 - gamma
    lambda_o cos^2(alpha_o))``.

    Equal sides: :func:`block_terms` (the symmetric arithmetic exactly). Compiled, and used
    by both :meth:`Isolated.kernel_params` and :func:`with_block`, so that batch rows are
    bit-identical to single runs."""
    if alpha_p == alpha_m and p_p == p_m and R_p == R_m:
        lam, mu = block_terms(alpha_p, p_p, R_p, gam, mu_given)
        return lam, mu, lam, mu
    lam_p = R_p * p_p * p_p / G
    lam_m = R_m * p_m * p_m / G
    if mu_given == mu_given:
        return lam_p, mu_given, lam_m, mu_given
    sp, sm = math.sin(alpha_p), math.sin(alpha_m)
    cp, cm = math.cos(alpha_p), math.cos(alpha_m)
    mu_p = 1.0 - lam_m * sm * (sm + R_p / R_m * sp) / (1.0 - gam * lam_m * cm * cm)
    mu_m = 1.0 - lam_p * sp * (sp + R_m / R_p * sm) / (1.0 - gam * lam_p * cp * cp)
    return lam_p, mu_p, lam_m, mu_m


@njit(cache=True)
def with_block(mp, b):
    """``mp`` with the block ``b = (alpha_+, p_+, R_+, alpha_-, p_-, R_-)`` of a batch row
    (``lambda`` and the derived restitutions rebuilt from it, :func:`side_terms`)."""
    lam_p, mu_p, lam_m, mu_m = side_terms(b[0], b[1], b[2], b[3], b[4], b[5], mp.gam,
                                          mp.mu_given)
    return IsolatedParams(b[0], b[1], mu_p, b[2], lam_p, mp.gam, mp.iso, mp.c1, mp.c2,
                          mp.veps, mp.clearance, mp.h_max, mp.rest_tol, mp.rtol, mp.mu_given,
                          mp.ws2, b[3], b[4], mu_m, b[5], lam_m)


@njit(cache=True, parallel=True)
def batch_kernel(mp, extra0, rows, blocks):
    """The batch kernel: the kernel over the rows of :func:`rocking.models.base.row_args`."""
    for i in prange(rows.kinds.shape[0]):
        kernel(with_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
        store_row(i, rows)


@dataclass(frozen=True)
class IsolatedOptions(ModelOptions):
    isolation: str = option("linear", choices=("linear", "pendulum"),
                            help="isolator: linear (period, damping ratio) or friction "
                                 "pendulum (radius, friction)")
    isolation_period: float = option(2.0, quantity="time", unit="s", lo=0.0, hi=100.0,
                                     help="period of block and plate on the linear isolator")
    isolation_damping: float = option(0.05, quantity="ratio", unit="", lo=0.0, hi=1.0,
                                      lo_open=False,
                                      help="damping ratio of the linear isolator (0.1 or "
                                           "'10%')")
    mass_ratio: float = option(1.0, lo=0.0, hi=1e12, help="plate mass / block mass")
    radius: float = option(2.0, quantity="length", unit="m", lo=0.0, hi=1e4,
                           help="radius of curvature of the friction pendulum")
    friction: float = option(0.05, lo=0.0, hi=1.0, lo_open=False,
                             help="friction coefficient of the friction pendulum")
    v_eps: float = option(1e-3, unit="m/s", lo=1e-5, hi=1.0, lo_open=False,
                          help="velocity of the tanh regularisation of friction (below "
                               "1e-5 m/s the steps it needs, ~2 v_eps/(friction g), make a "
                               "run of seconds last hours)")
    clearance: float | None = option(None, quantity="length", unit="m", lo=0.0, hi=1e3,
                                     help="moat clearance: the run stops when |u| reaches "
                                          "it, unless stop_period is given (None: no moat)")
    stop_period: float | None = option(None, quantity="time", unit="s", lo=0.0, hi=100.0,
                                       help="the moat wall as a stiff linear spring beyond "
                                            "the clearance: the period of block and plate "
                                            "on it alone (None: the run stops at the "
                                            "clearance)")
    mu: float | None = option(None, lo=0.0, hi=1.0,
                              help="restitution (None: derived from the momentum balance)")
    rest_tol: float = option(1e-12, lo=0.0, hi=1e-2, lo_open=False,
                             help="Zeno threshold (fraction of alpha)")
    max_step: float = option(0.01, unit="s", lo=0.0, hi=0.1,
                             help="largest time step of the adaptive steps")
    rtol: float = option(DEFAULT_RTOL, lo=1e-13, hi=1e-2, lo_open=False,
                         help="relative tolerance of the adaptive Dormand-Prince steps")



class Isolated(Model):
    mitigation = True
    name = "isolated"
    label = "block on an isolated base"
    Options = IsolatedOptions
    kernel = kernel
    batch_kernel = batch_kernel
    outputs = GENERIC_OUTPUTS + PLANAR_OUTPUTS + (
        Output("max_base_displacement", "m", False, "max |u| of the base plate"),
        Output("max_plate_acceleration", "m/s^2", False,
               "max absolute acceleration of the plate"),
        Output("clearance_exceeded", "", True, "|u| reached the clearance (the run "
                                              "stopped there, unless stop_period)"),
        Output("clearance_time", "s", False, "when |u| first reached the clearance "
                                             "(NaN: never)"),
    )

    accepts_asymmetric = True

    LINEAR_ONLY = ("isolation_period", "isolation_damping")
    PENDULUM_ONLY = ("radius", "friction", "v_eps")

    @classmethod
    def from_kwargs(cls, block, **options):
        """The model from keyword options; an option of the other isolator (``radius``
        with the linear one, ``isolation_period`` with the pendulum) is warned about: it
        is not used."""
        iso = options.get("isolation", "linear")
        unused = cls.PENDULUM_ONLY if iso == "linear" else cls.LINEAR_ONLY
        for k in unused:
            if k in options:
                other = "pendulum" if iso == "linear" else "linear"
                warn_implausible(f"model 'isolated': {k} applies to isolation={other!r} "
                                 f"only; with isolation={iso!r} it is not used")
        return super().from_kwargs(block, **options)

    def __init__(self, block, options=None):
        super().__init__(block, options)
        o = self.options
        if o.clearance is not None and o.clearance > 2.0:
            warn_implausible(f"model 'isolated': clearance {o.clearance:g} m is above 2 m; "
                             "check the units (lengths are in m: '15cm' is 0.15)")
        if o.mu is None:  # the derived restitution replaces the block's own mu: say so
            row = self.block_row(self.block)
            gam = 1.0 / (1.0 + o.mass_ratio)
            _, fix_p, _, fix_m = side_terms(*row, 0.0, math.nan)  # on a fixed base
            _, iso_p, _, iso_m = side_terms(*row, gam, math.nan)
            if min(iso_p, iso_m) <= 0.0:
                raise ParameterError(
                    f"model 'isolated': the restitution derived from the momentum of block "
                    f"and plate is {min(iso_p, iso_m):.4f} <= 0 for this squat block "
                    f"(mass_ratio = {o.mass_ratio:g}): the block would not rock on the "
                    "plate as Housner's impact assumes; pass mu=... in (0, 1] to impose one")
            own = (self.block.mu_plus, self.block.mu_minus)
            if max(abs(own[0] - fix_p), abs(own[1] - fix_m)) > 1e-3:  # 3 decimals of tables
                if self.block.symmetric:
                    what = (f"({iso_p:.4f} here; {fix_p:.4f} on a fixed base, Eq 4 for this "
                            f"geometry): the block's own mu = {own[0]:.4f} is not used")
                else:
                    what = (f"({iso_p:.4f}/{iso_m:.4f} here, sides +/-; {fix_p:.4f}/"
                            f"{fix_m:.4f} on a fixed base, from angular momentum for this "
                            f"geometry): the block's own mu = {own[0]:.4f}/{own[1]:.4f} is "
                            "not used")
                warn_implausible("model 'isolated' derives the impact restitution from the "
                                 f"momentum of block and plate {what}; pass mu=... to "
                                 "impose one")

    @classmethod
    def block_row(cls, block) -> tuple:
        """``(alpha_+, p_+, R_+, alpha_-, p_-, R_-)`` (both sides; equal for a symmetric
        block); ``R`` a rectangle's ``3 g / (4 p^2)`` when the block has none."""
        out = []
        for alpha, p, R in ((block.alpha_plus, block.p_plus, block.R_plus),
                            (block.alpha_minus, block.p_minus, block.R_minus)):
            out += [float(alpha), float(p),
                    float(R if R is not None else 3.0 * G / (4.0 * p ** 2))]
        return tuple(out)

    def restitutions(self) -> tuple[float, float]:
        """``(mu_+, mu_-)``: the impact restitutions used (``mu``, or those derived from the
        momentum of block and plate, :func:`side_terms`)."""
        mu_given = math.nan if self.options.mu is None else float(self.options.mu)
        _, mu_p, _, mu_m = side_terms(*self.block_row(self.block),
                                      1.0 / (1.0 + self.options.mass_ratio), mu_given)
        return float(mu_p), float(mu_m)

    def kernel_params(self, dt_out, theta0, omega0):
        b, o = self.block, self.options
        row = self.block_row(b)
        gam = 1.0 / (1.0 + o.mass_ratio)
        mu_given = math.nan if o.mu is None else float(o.mu)
        lam, mu, lam_m, mu_m = side_terms(*row, gam, mu_given)
        if o.isolation == "linear":
            w = 2.0 * math.pi / o.isolation_period
            iso, c1, c2, veps = 0.0, w * w, 2.0 * o.isolation_damping * w, 1.0
            h = o.isolation_period / 20.0
        else:
            iso, c1, c2, veps = 1.0, G / o.radius, o.friction * G, o.v_eps
            h = 2.0 * math.pi * math.sqrt(o.radius / G) / 20.0
            if o.friction > 0.0:  # within the explicit steps' stability on the friction
                h = min(h, 2.0 * o.v_eps / (o.friction * G))
        clear = math.inf if o.clearance is None else o.clearance
        ws2 = 0.0
        if o.stop_period is not None:
            if o.clearance is None:
                raise ParameterError("stop_period (s) needs a clearance (m): the stop is the "
                                     "moat wall at |u| = clearance")
            ws2 = (2.0 * math.pi / o.stop_period) ** 2
            h = min(h, o.stop_period / 20.0)
        alpha, p, R, alpha_m, p_m, R_m = row
        return IsolatedParams(*(float(x) for x in (
            alpha, p, mu, R, lam, gam, iso, c1, c2, veps, clear, min(h, o.max_step),
            o.rest_tol, o.rtol, mu_given, ws2, alpha_m, p_m, mu_m, R_m, lam_m)))

    def info(self, dt_out=None):
        """The options, and ``restitution``: the impact restitution used (``mu``, or the
        one derived from the momentum of block and plate); for an asymmetric block that of
        an impact ending rocking on its weaker side, and both as ``restitution_plus``,
        ``restitution_minus``."""
        mu_p, mu_m = self.restitutions()
        b = self.block
        out = {**super().info(dt_out),
               "restitution": mu_m if b.alpha_minus < b.alpha_plus else mu_p}
        if not b.symmetric:
            out.update(restitution_plus=mu_p, restitution_minus=mu_m)
        return out
