r"""The classical (Housner) rocking model: Eq (1) between impacts, Eq (4) at impacts.

Equation of motion (Peña et al. 2007, Eq 1), for ``theta > 0`` (pivot O) and
``theta < 0`` (pivot O'):

.. math::

    \theta'' = -\operatorname{sgn}(\theta)\, p^2 \sin(\alpha - |\theta|)
               + p^2 \cos(\alpha - |\theta|)\, a(\tau)/g

**Sign convention.** ``a`` is the horizontal ground acceleration with the sign of Eq (1):
a positive ``a`` drives ``theta`` positive. Physically, the inertial force ``-M a_g``
tilts the block away from the direction in which the ground accelerates, so ``theta``
is positive when the block rotates *against* the positive direction of the table's
acceleration; flipping the sign of the motion flips the response. The block is at rest
with ``theta = 0``.

``linear=True`` uses the small-angle form ``theta'' = p^2 (theta - sgn(theta) alpha) + p^2 a/g``.

**Vertical ground motion** (:class:`rocking.motions.GroundMotion`; ``a_v`` positive
upwards). In the frame of the base, which accelerates by ``(a_h, a_v)``, the block feels
its weight ``M g`` downwards plus the inertial force ``-M (a_h, a_v)``: a horizontal force
``-M a_h`` and a vertical one ``-M a_v``, i.e. the effective gravity ``g + a_v``. Moments
about the pivot O (``theta > 0``), with the centre of mass at distance ``R`` and angle
``alpha - theta`` from the vertical through O::

    I_O theta'' = -M (g + a_v) R sin(alpha - theta) + M a_h R cos(alpha - theta)

and with ``p^2 = M g R / I_O`` (Eq 3),

.. math::

    \theta'' = -\operatorname{sgn}(\theta)\, p^2 (1 + a_v/g) \sin(\alpha - |\theta|)
               + p^2 \cos(\alpha - |\theta|)\, a_h(\tau)/g ,

Eq (1) with ``g`` replaced by ``g + a_v`` in the gravity term (``p^2`` becomes
``p^2 (1 + a_v/g)``: under a constant ``a_v`` the free-rocking period scales as
``1/sqrt(1 + a_v/g)``). At rest (``theta = 0``) the moments balance while
``|a_h| <= (g + a_v) tan(alpha)``: uplift starts when ``|a_h| > (g + a_v) tan(alpha)``
(located by bisection on that margin). Impacts keep Eq (4): ``a_v`` is bounded and does
no impulsive work. Where ``g + a_v <= 0`` the base falls away faster than gravity and
the block leaves the ground; the model cannot represent flight, so the run stops at the
first such instant (located by bisection; an analytic vertical motion is also scanned
inside each step, every quarter of its scan step) and the result carries
``lift_off_time`` (``lifted_off``). This is the criterion of a block at rest: while it
rocks, the pivot's normal force ``M [g + a_v + R (sin(alpha - theta) theta'' -
cos(alpha - theta) theta'^2)]`` (pivot O; the vertical acceleration of the centre of mass
is the derivative of ``R sin(alpha - theta) theta'``) can vanish a little earlier, which
the model does not check (the DEM resolves it through its contacts). Without a vertical
component the arithmetic is that of Eq (1) exactly (bit-identical results).

**Asymmetric blocks** (:meth:`rocking.Block.from_geometry`; Contento and Di Egidio
2009). On the branch ``s`` (``theta > 0``: pivot +, ``theta < 0``: pivot -) Eq (1) uses
that side's ``alpha_s`` and ``p_s``; a block at rest uplifts towards ``s = sign(a)`` when
``s a > (g + a_v) tan(alpha_s)``; an impact that ends rocking on side ``s`` multiplies
``theta'`` by ``mu_s`` (angular momentum about the new pivot); the Zeno rule and the
energy decision at the cap of the free motion (:func:`free_outcome_sides`) use the
parameters of each side. The step sizes follow the faster side (largest ``p``), the
error norm the smaller ``alpha``. With equal sides every floating-point operation is that
of the symmetric model (the side's parameter is selected, the expressions are the same):
a symmetric block gives bit-identical results.

**Events.**

* *Uplift*: a block at rest uplifts exactly when ``|a| > g tan(alpha)`` (``g alpha`` when
  linear), in the direction of ``sign(a)``, including at ``t = 0``. The crossing time is
  found by bisection on ``|a(t)| - g tan(alpha)``.
* *Impact*: when ``theta`` reaches 0 the angular velocity is multiplied by ``mu`` (Eq 4)
  and the pivot switches. The impact time is located by safeguarded Newton iteration on
  the length of the Runge-Kutta step (not by the nearest time step).
* *Return to rest (Zeno rule)*: free rocking of a Housner block has infinitely many
  impacts in finite time (each half-cycle lasts ``~ (2/p) sqrt(2 theta_max/alpha)``). After
  each impact we compute from energy the amplitude ``theta_max`` the block would reach in
  free motion; if ``theta_max < rest_tol * alpha`` and the ground acceleration cannot
  uplift the block (``|a| <= g tan(alpha)``), the block is set to rest
  (``theta = omega = 0``) and stays there until the uplift criterion holds again. Once
  the ground is still (after the motion) the threshold is ``free_rest_tol`` (1e-3):
  nothing can lift the block again, so the micro-rocking below it changes no result but
  ``n_impacts``.
* *Overturning*: ``|theta|`` reaches ``pi/2``. The simulation stops there.

**Integration.** Dormand-Prince 5(4) with adaptive steps (mixed relative/absolute error
control, ``rtol``), which steps exactly onto the kinks of the excitation (the samples of a
record, the start and end of a pulse). The branch (pivot) is frozen within a step so that
the right-hand side is smooth; impacts are then located inside the step. Everything runs
in one compiled numba function per simulation; :func:`rocking.simulate_many` runs a
batch in parallel with no Python per time step.

``method="taylor"`` (not the default) replaces the adaptive steps, on a record without a
vertical component or without motion, by fixed steps of the Taylor series of Eq 1
(:func:`taylor_step`, degree :data:`TAYLOR_ORDER`), one per sample (at most ``0.05/p``):
the ground acceleration is linear between samples, so the series is that of the exact
solution, and an impact inside a step is located on the step's polynomial. Every event
and rule above is the same (the shared loop, :mod:`rocking.models._numerics.fixed`). On
the 20 s records of ``benchmarks/bench_taylor.py`` it is 2.5 times as fast as the
default and closer to a tight reference (median error of ``max |theta|`` 1e-10 against
1e-8). Other motions run with Dormand-Prince.
"""

from __future__ import annotations

import math
from collections import namedtuple
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from ..motions._kernel import (
    NONE,
    RECORD,
    ground_acc,
    ground_acc_hv,
    has_vertical,
    vertical_acc,
)
from ..units import G
from ._numerics import dopri as D
from ._numerics import events as E
from ._numerics import fixed as F
from ._numerics import loop as L
from .base import Model, ModelOptions, option, row_args, set_planar_result, store_row

INV_G = 1.0 / G


@njit(cache=True)
def _acc(th, t, s, alpha, p2, lin, kind, prm, samples):
    """Angular acceleration of Eq 1 on branch ``s`` (+1 pivot O, -1 pivot O'), with
    ``g`` replaced by ``g + a_v`` in the gravity term when the motion has a vertical
    component."""
    if has_vertical(prm):
        ah, av = ground_acc_hv(kind, prm, samples, t)
        a = ah * INV_G
        gf = 1.0 + av * INV_G
        if lin:
            return p2 * gf * (th - s * alpha) + p2 * a
        return -s * p2 * gf * math.sin(alpha - s * th) + p2 * math.cos(alpha - s * th) * a
    a = ground_acc(kind, prm, samples, t) / G
    if lin:
        return p2 * (th - s * alpha) + p2 * a
    return -s * p2 * math.sin(alpha - s * th) + p2 * math.cos(alpha - s * th) * a


@njit(cache=True)
def amplitude_from_energy(om, alpha, p2, lin):
    """Amplitude reached in free motion from theta = 0 with angular velocity om (Eq 1 with
    ``a = 0``, energy conserved; infinite if it passes the tipping point)."""
    if lin:
        d = alpha * alpha - om * om / p2
        return alpha - math.sqrt(d) if d > 0.0 else math.inf
    c = math.cos(alpha) + 0.5 * om * om / p2
    return alpha - math.acos(c) if c < 1.0 else math.inf


@njit(cache=True)
def free_outcome(th, om, s, alpha, p2, mu, lin):
    """The outcome of free rocking (no ground motion) from ``(th, om)`` on pivot ``s``,
    decided by energy: ``(overturns, amplitude)``.

    Between impacts ``E = om^2/2 + p^2 cos(alpha - |th|)`` is conserved (Eq 1 with
    ``a = 0``; ``om^2/2 - p^2 (|th| - alpha)^2 / 2`` when linear); an impact (Eq 4)
    multiplies ``om^2`` at ``th = 0``, i.e. the energy above the rest position, by
    ``mu^2``. Moving away from ``th = 0`` the block overturns iff ``E`` exceeds the
    potential at ``|th| = alpha``; moving towards it, iff the energy after the next impact
    does (past ``|th| = alpha`` it falls unless it comes back over the top); after that
    every impact lowers the energy, so it never overturns. Otherwise it
    returns to rest and ``amplitude`` is the largest ``|th|`` it will still reach (0 if
    none beyond ``|th|``): exact for the classical model.
    """
    a = abs(th)
    if lin:
        e = 0.5 * om * om - 0.5 * p2 * (a - alpha) ** 2
        top = 0.0
        bottom = -0.5 * p2 * alpha * alpha
    else:
        e = 0.5 * om * om + p2 * math.cos(alpha - a)
        top = p2
        bottom = p2 * math.cos(alpha)
    away = th * om > 0.0 or (th == 0.0 and s * om > 0.0)
    if a > alpha and (away or e <= top):
        return True, D.HALF_PI  # past the tipping point and not coming back over it
    if not away:
        e = bottom + mu * mu * (e - bottom)
    if e > top:
        return True, D.HALF_PI
    if lin:
        amp = alpha - math.sqrt(max(-2.0 * e / p2, 0.0))
    else:
        amp = alpha - math.acos(min(e / p2, 1.0))
    return False, amp


@njit(cache=True)
def free_cap(th, om, s, alpha, p, mu, lin, t, free_time, peak):
    """At the cap of the free motion (the ground still) the energy decides the outcome
    exactly (:func:`free_outcome`). Returns ``(decided, peak, t_end)``: decided, the block
    returns to rest and ``peak`` includes the amplitude it will still reach; else it will
    overturn and the run follows it there, up to ``t_end``: near the top the motion is
    slow, ~ (1/p) ln(1/(E - p^2)), and 100/p covers any margin above double precision."""
    will, amp = free_outcome(th, om, s, alpha, p * p, mu, lin)
    if not will:
        return True, max(peak, amp), t
    return False, peak, t + max(free_time, 100.0 / p)


@njit(cache=True)
def _energy(a, om, alpha, p2, lin):
    """``(E, E_top, E_bottom)`` per unit moment of inertia on one side at ``|th| = a``
    (:func:`free_outcome`)."""
    if lin:
        return 0.5 * om * om - 0.5 * p2 * (a - alpha) ** 2, 0.0, -0.5 * p2 * alpha * alpha
    return 0.5 * om * om + p2 * math.cos(alpha - a), p2, p2 * math.cos(alpha)


@njit(cache=True)
def _amplitude(e, alpha, p2, lin):
    """The largest ``|th|`` reached on one side with the energy ``e`` (below the top)."""
    if lin:
        return alpha - math.sqrt(max(-2.0 * e / p2, 0.0))
    return alpha - math.acos(min(e / p2, 1.0))


@njit(cache=True)
def free_outcome_sides(th, om, s, alpha_p, p2_p, mu_p, alpha_m, p2_m, mu_m, lin):
    """:func:`free_outcome` of an asymmetric block (side + for ``theta > 0``, side - for
    ``theta < 0``; ``mu_s`` ends rocking on side ``s``); equal sides call
    :func:`free_outcome` itself (the same arithmetic).

    On each side its own energy is conserved; an impact ending rocking on side ``s``
    turns the kinetic energy ``K`` at ``theta = 0`` (per unit inertia) into ``mu_s^2 K``
    on the other side. ``K`` falls at every impact, so the block can overturn only on the
    current side (moving away), on the other side after the next impact, or back on this
    side after the one after (when it now moves towards ``theta = 0`` with more energy
    than this side's top: a smaller restitution on the way there may not be enough); the
    amplitude is the largest of those excursions."""
    if alpha_p == alpha_m and p2_p == p2_m and mu_p == mu_m:
        return free_outcome(th, om, s, alpha_p, p2_p, mu_p, lin)
    if s > 0.0:
        al, p2, mu, al_o, p2_o, mu_o = alpha_p, p2_p, mu_p, alpha_m, p2_m, mu_m
    else:
        al, p2, mu, al_o, p2_o, mu_o = alpha_m, p2_m, mu_m, alpha_p, p2_p, mu_p
    a = abs(th)
    e, top, bottom = _energy(a, om, al, p2, lin)
    away = th * om > 0.0 or (th == 0.0 and s * om > 0.0)
    if a > al and (away or e <= top):
        return True, D.HALF_PI
    amp = 0.0
    if away:
        if e > top:
            return True, D.HALF_PI
        amp = _amplitude(e, al, p2, lin)
    k1 = mu * mu * (e - bottom)  # kinetic energy after the next impact (other side)
    e1, top1, bottom1 = _energy(0.0, 0.0, al_o, p2_o, lin)
    e1 = bottom1 + k1
    if e1 > top1:
        return True, D.HALF_PI
    amp = max(amp, _amplitude(e1, al_o, p2_o, lin))
    e2 = bottom + mu_o * mu_o * k1  # back on this side
    if e2 > top:
        return True, D.HALF_PI
    return False, max(amp, _amplitude(e2, al, p2, lin))


@njit(cache=True)
def free_cap_sides(th, om, s, alpha_p, p_p, mu_p, alpha_m, p_m, mu_m, lin, t, free_time,
                   peak):
    """:func:`free_cap` of an asymmetric block (:func:`free_outcome_sides`; the run is
    followed for ``100/p`` of the slower side); equal sides: :func:`free_cap` exactly."""
    if alpha_p == alpha_m and p_p == p_m and mu_p == mu_m:
        return free_cap(th, om, s, alpha_p, p_p, mu_p, lin, t, free_time, peak)
    will, amp = free_outcome_sides(th, om, s, alpha_p, p_p * p_p, mu_p, alpha_m, p_m * p_m,
                                   mu_m, lin)
    if not will:
        return True, max(peak, amp), t
    return False, peak, t + max(free_time, 100.0 / min(p_p, p_m))


# ---- the model's part of the shared step loop (:func:`rocking.models._numerics.loop.run`);
# its parameters ``mp`` are a :data:`SideParams`, no state of its own
SideParams = namedtuple("SideParams", [
    "alpha_p", "p_p", "mu_p", "alpha_m", "p_m", "mu_m", "lin", "p2_p", "p2_m", "c_p", "c_m",
    "thr_p", "thr_m", "rest_tol", "free_rest_tol"])
"""The parameters of the classical model's hooks in the shared step loop: both sides'
``alpha``, ``p``, ``mu``, ``p^2``, uplift ratios ``c`` (``tan alpha``; ``alpha`` when
linear) and thresholds ``g c``, the ``linear`` flag and the rest tolerances."""

TaylorSideParams = namedtuple("TaylorSideParams", SideParams._fields + ("buf",))
""":data:`SideParams` and the work array of :func:`taylor_step` (``method="taylor"``)."""

TAYLOR_ORDER = 8
"""Degree of the Taylor polynomial of :func:`taylor_step`: with ``p h <= 0.05`` its
remainder is ``~(p h)^9 / 9! < 1e-17`` of the angle scale."""

_INV_M = tuple(1.0 / max(m, 1) for m in range(TAYLOR_ORDER + 1))
_INV_K2 = tuple(1.0 / ((k + 1) * (k + 2)) for k in range(TAYLOR_ORDER))


@njit(cache=True, inline="always")
def taylor_step(mp, args, t, th, om, a0, h):
    r"""One step of Eq 1 by its Taylor series (``method="taylor"``): exact up to
    ``h^TAYLOR_ORDER`` when the ground acceleration is linear over the step (a record
    between two samples, or no motion). Returns ``(theta, omega, theta'')`` at ``t + h``.

    With ``phi = alpha_s - s theta`` (the angle of the centre of mass from the vertical
    through the pivot) Eq 1 reads ``phi'' = p^2 (sin phi - s cos phi A(t))``, ``A = a/g``
    linear over the step: ``A = A0 + A1 tau``. The coefficients ``phi_k`` of ``phi(t +
    tau) = sum phi_k tau^k`` follow from ``(k+1)(k+2) phi_(k+2) = p^2 (u_k - s (A0 v_k +
    A1 v_(k-1)))`` with ``u = sin phi``, ``v = cos phi`` and ``u' = v phi'``, ``v' = -u
    phi'``: ``k u_k = sum_j j phi_j v_(k-j)``, ``k v_k = -sum_j j phi_j u_(k-j)`` (the
    recurrences of automatic differentiation; Moore 1966). The linear form has ``u =
    phi``, ``v = 1``. One sine and cosine at the start, one at the end for ``theta''``.
    ``A`` is taken from the motion at ``h/4`` and ``3h/4`` (exact on a linear piece, and
    blind to a jump at the ends, e.g. after the end of a record). A step from the same
    start as the last one and no longer (the loop locating an impact inside it) evaluates
    the last polynomial instead (the start, the side, the length and ``A`` are kept in
    ``mp.buf[4]``).
    """
    s, alpha, p2, lin, kind, prm, samples = args
    buf = mp.buf
    ph = buf[0]
    dph = buf[1]  # k phi_k
    u = buf[2]
    v = buf[3]
    n = TAYLOR_ORDER
    key = buf[4]
    if key[0] == t and key[1] == th and key[2] == om and key[3] == s and h <= key[4]:
        # the same start as the last step (an event inside it): its polynomial
        return _taylor_eval(ph, dph, key[5], key[6], s, p2, lin, th, h)
    q1 = ground_acc(kind, prm, samples, t + 0.25 * h) * INV_G
    q3 = ground_acc(kind, prm, samples, t + 0.75 * h) * INV_G
    a_1 = (q3 - q1) / (0.5 * h) if h > 0.0 else 0.0
    a_0 = q1 - 0.25 * h * a_1
    key[0], key[1], key[2], key[3], key[4], key[5], key[6] = t, th, om, s, h, a_0, a_1
    ph[0] = alpha - s * th
    ph[1] = -s * om
    dph[1] = ph[1]
    if lin:
        u[0], v[0] = ph[0], 1.0
    else:
        u[0], v[0] = math.sin(ph[0]), math.cos(ph[0])
    for k in range(n - 1):
        # phi_(k+2) from u_k, v_k, v_(k-1)
        vk1 = v[k - 1] if k > 0 else 0.0
        ph[k + 2] = p2 * (u[k] - s * (a_0 * v[k] + a_1 * vk1)) * _INV_K2[k]
        dph[k + 2] = (k + 2) * ph[k + 2]
        m = k + 1  # u_m, v_m from phi_1..phi_m
        if lin:
            u[m] = ph[m]
            v[m] = 0.0
        else:
            su = 0.0
            sv = 0.0
            for j in range(1, m + 1):
                su += dph[j] * v[m - j]
                sv += dph[j] * u[m - j]
            u[m] = su * _INV_M[m]
            v[m] = -sv * _INV_M[m]
    return _taylor_eval(ph, dph, a_0, a_1, s, p2, lin, th, h)


@njit(cache=True, inline="always")
def _taylor_eval(ph, dph, a_0, a_1, s, p2, lin, th, tau):
    """``(theta, omega, theta'')`` at ``tau`` from the coefficients of :func:`taylor_step`
    from ``th``. The angle is ``th`` plus the series' increment, not ``s (alpha - phi)``:
    near ``theta = 0`` the latter would lose it below ``alpha`` times the machine epsilon
    (a block just uplifted, or at the top of a tiny rebound)."""
    n = TAYLOR_ORDER
    g = ph[n]
    df = dph[n]
    for k in range(n - 1, 0, -1):
        g = g * tau + ph[k]
        df = df * tau + dph[k]
    inc = g * tau  # phi(tau) - phi(0)
    f = ph[0] + inc
    a_h = a_0 + a_1 * tau
    if lin:
        d2 = p2 * (f - s * a_h)
    else:
        d2 = p2 * (math.sin(f) - s * math.cos(f) * a_h)
    return th - s * inc, -s * df, -s * d2


@njit(cache=True, inline="always")
def _rhs_args(mp, xs, s, kind, prm, samples):
    """The arguments of :func:`_acc` on pivot ``s`` (that side's ``alpha``, ``p^2``)."""
    alpha, p2 = (mp.alpha_p, mp.p2_p) if s > 0.0 else (mp.alpha_m, mp.p2_m)
    return (s, alpha, p2, mp.lin, kind, prm, samples)


@njit(cache=True, inline="always")
def _start(mp, resting, s, th0):
    return 0.0


@njit(cache=True, inline="always")
def _at_rest(mp, xs, kind, prm, samples, t, t_lim, h_scan, dt_out, k, out_th, out_om, t_up):
    t, k, d, t_up = E.rest_advance_sides(kind, prm, samples, t, t_lim, h_scan, mp.thr_p, mp.c_p,
                                         mp.thr_m, mp.c_m, dt_out, k, out_th, out_om, t_up)
    return t, k, d, t_up, xs


@njit(cache=True, inline="always")
def _cap(mp, xs, th, om, s, t, free_time, peak):
    """The cap of the free motion: the energy decides the outcome exactly."""
    decided, peak, t_end = free_cap_sides(th, om, s, mp.alpha_p, mp.p_p, mp.mu_p, mp.alpha_m,
                                          mp.p_m, mp.mu_m, mp.lin, t, free_time, peak)
    return decided, decided, peak, t_end


@njit(cache=True, inline="always")
def _inside(args, mp, xs, t, th, om, a0, th1, om1, a1, h, s, dt_out, k, out_th, out_om):
    return 0, t, th, om, k, 0.0, h, xs


@njit(cache=True, inline="always")
def _impact_tol(mp, s):
    return 1e-15 * (mp.alpha_p if s > 0.0 else mp.alpha_m)


@njit(cache=True, inline="always")
def _after_impact(mp, xs, s, t, omc, pk, kind, prm, samples, t_quiet, hv):
    """Eq 4 (rocking on side ``s`` ends) and the Zeno rule: ``(rest, om, s, xs)``."""
    alpha_p, mu_p, alpha_m, mu_m, lin, p2_p, p2_m = (mp.alpha_p, mp.mu_p, mp.alpha_m, mp.mu_m,
                                                     mp.lin, mp.p2_p, mp.p2_m)
    om = (mu_p if s > 0.0 else mu_m) * omc  # rocking on side s ends
    ag = ground_acc(kind, prm, samples, t)
    sn = E.rebound_side(om, ag)
    al_n, p2_n = (alpha_p, p2_p) if sn > 0.0 else (alpha_m, p2_m)
    p2e = p2_n * (1.0 + vertical_acc(prm, samples, t) / G) if hv else p2_n
    rt = mp.rest_tol if t < t_quiet else max(mp.rest_tol, mp.free_rest_tol)
    if om == 0.0 or amplitude_from_energy(om, al_n, p2e, lin) < rt * al_n:
        if abs(ag) <= E.threshold_sides(ag, mp.thr_p, mp.c_p, mp.thr_m, mp.c_m, prm, samples, t):
            return True, 0.0, s, xs
    return False, om, sn, xs


@njit(cache=True, inline="always")
def _on_overturn(mp, xs, s):
    return xs


@njit(cache=True, inline="always")
def _on_segment(mp, xs, s, pk):
    return xs


# the stepper of ``method="taylor"`` in the shared loop: :mod:`rocking.models._numerics.fixed`
# with :func:`taylor_step` (named here, not passed on: module docstring of the loop)

@njit(cache=True, inline="always")
def _taylor_trial(acc, mp, args, t, th, om, a0, h, h_max, t_end, bp, s, atol_th, atol_om,
                  rtol):
    return F.trial(taylor_step, mp, args, t, th, om, a0, h, h_max, t_end, bp, s)


@njit(cache=True, inline="always")
def _taylor_stop_inside(acc, mp, args, t, th, om, a0, tc, s, dt_out, k, out_th, out_om, peak):
    return F.stop_inside(taylor_step, mp, args, t, th, om, a0, tc, s, dt_out, k, out_th,
                         out_om, peak)


@njit(cache=True, inline="always")
def _taylor_impact(acc, mp, args, t, th, om, a0, th1, om1, a1, h, s, tol, dt_out, k, out_th,
                   out_om, peak, imp, n_imp):
    return F.impact(taylor_step, mp, args, t, th, om, a0, th1, om1, a1, h, s, tol, dt_out, k,
                    out_th, out_om, peak, imp, n_imp)


@njit(cache=True)
def integrate(alpha_p, p_p, mu_p, alpha_m, p_m, mu_m, lin, kind, prm, samples, t_end,
              t_quiet, th0, om0, rtol, rest_tol, free_rest_tol, h_max, h_scan, dt_out, out_th,
              out_om, imp):
    """Integrate one simulation. Returns (n_out, n_impacts, max_abs_theta, overturned,
    overturn_time, uplift_time, n_steps, lift_off_time, settled).

    The block's sides: ``alpha_p``, ``p_p`` on pivot + (``theta > 0``), ``alpha_m``,
    ``p_m`` on pivot -; ``mu_p``/``mu_m`` multiply the velocity at an impact that ends
    rocking on side +/- (equal sides: a symmetric block, the arithmetic of Eq 1 and Eq 4
    exactly). ``out_th``/``out_om`` receive the history at ``k*dt_out`` (length 0: none
    stored); ``imp`` receives impact times up to its length (impacts are counted beyond
    it). From ``t_quiet`` on the ground is still: the run stops once the block is at rest;
    a block still rocking at ``t_end > t_quiet`` is decided by :func:`free_outcome_sides`
    (exact). Adaptive Dormand-Prince steps under ``rtol`` (:func:`integrate_taylor`: the
    Taylor steps of ``method="taylor"``).
    """
    p2_p = p_p * p_p
    p2_m = p_m * p_m
    c_p = alpha_p if lin else math.tan(alpha_p)
    c_m = alpha_m if lin else math.tan(alpha_m)
    p_hi = max(p_p, p_m)  # the step sizes follow the faster side
    atol_th, atol_om = D.abs_tols(rtol, min(alpha_p, alpha_m), p_hi)
    mp = SideParams(alpha_p, p_p, mu_p, alpha_m, p_m, mu_m, lin, p2_p, p2_m, c_p, c_m, G * c_p,
                    G * c_m, rest_tol, free_rest_tol)
    k, n_imp, peak, overturned, t_over, t_up, n_steps, t_lift, settled, _xs = L.run(
        _acc, D.loop_trial, D.loop_stop_inside, D.loop_impact, D.segment, D.rebound_length,
        _rhs_args, _start, _at_rest, _cap, _inside, _impact_tol, _after_impact, _on_overturn,
        _on_segment, mp, kind, prm, samples, t_end, t_quiet, (th0, om0),
        (rtol, atol_th, atol_om), p_hi, h_max, h_scan, dt_out, (out_th, out_om), imp)
    return k, n_imp, peak, overturned, t_over, t_up, n_steps, t_lift, settled


@njit(cache=True)
def integrate_taylor(alpha_p, p_p, mu_p, alpha_m, p_m, mu_m, lin, kind, prm, samples, t_end,
                     t_quiet, th0, om0, rtol, rest_tol, free_rest_tol, h_max, h_scan, dt_out,
                     out_th, out_om, imp):
    """:func:`integrate` with the fixed Taylor steps of :func:`taylor_step`
    (``method="taylor"``, ``rtol`` unused; :mod:`rocking.models._numerics.fixed`) on a
    record without a vertical component or no motion; other motions: :func:`integrate`
    (Dormand-Prince)."""
    if not ((kind == RECORD or kind == NONE) and not has_vertical(prm)):
        return integrate(alpha_p, p_p, mu_p, alpha_m, p_m, mu_m, lin, kind, prm, samples,
                         t_end, t_quiet, th0, om0, rtol, rest_tol, free_rest_tol, h_max,
                         h_scan, dt_out, out_th, out_om, imp)
    p2_p = p_p * p_p
    p2_m = p_m * p_m
    c_p = alpha_p if lin else math.tan(alpha_p)
    c_m = alpha_m if lin else math.tan(alpha_m)
    p_hi = max(p_p, p_m)
    buf = np.full((5, TAYLOR_ORDER + 1), np.nan)
    mp = TaylorSideParams(alpha_p, p_p, mu_p, alpha_m, p_m, mu_m, lin, p2_p, p2_m, c_p, c_m,
                          G * c_p, G * c_m, rest_tol, free_rest_tol, buf)
    k, n_imp, peak, overturned, t_over, t_up, n_steps, t_lift, settled, _xs = L.run(
        _acc, _taylor_trial, _taylor_stop_inside, _taylor_impact, F.segment, F.rebound_length,
        _rhs_args, _start, _at_rest, _cap, _inside, _impact_tol, _after_impact, _on_overturn,
        _on_segment, mp, kind, prm, samples, t_end, t_quiet, (th0, om0), (rtol, 0.0, 0.0),
        p_hi, h_max, h_scan, dt_out, (out_th, out_om), imp)
    return k, n_imp, peak, overturned, t_over, t_up, n_steps, t_lift, settled


HousnerParams = namedtuple("HousnerParams", [
    "alpha_p", "p_p", "mu_p", "linear", "rtol", "rest_tol", "free_rest_tol", "alpha_m", "p_m",
    "mu_m"])
"""The kernel parameters ``mp`` of the classical model: both sides' ``alpha`` (rad), ``p``
(1/s) and ``mu``, the ``linear`` flag and the tolerances (:class:`HousnerOptions`)."""


@njit(cache=True)
def kernel(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp, res, extra):
    """The single-run kernel of the model interface (:mod:`rocking.models.base`)."""
    h_max = min(0.05 / max(mp.p_p, mp.p_m), 8.0 * h_scan)
    k, n_imp, peak, over, t_over, t_up, n_steps, t_lift, settled = integrate(
        mp.alpha_p, mp.p_p, mp.mu_p, mp.alpha_m, mp.p_m, mp.mu_m, mp.linear, kind, prm,
        samples, t_end, t_quiet, y0[0], y0[1], mp.rtol, mp.rest_tol, mp.free_rest_tol, h_max,
        h_scan, dt_out, hist[:, 0], hist[:, 1], imp)
    set_planar_result(res, k, n_imp, peak, over, t_over, t_up, n_steps, 0, t_lift, settled)


@njit(cache=True)
def with_block(mp, b):
    """``mp`` with the block parameters ``b = (alpha_plus, p_plus, mu_plus, alpha_minus,
    p_minus, mu_minus)`` of a batch row."""
    return HousnerParams(b[0], b[1], b[2], mp.linear, mp.rtol, mp.rest_tol, mp.free_rest_tol,
                         b[3], b[4], b[5])


@njit(cache=True, parallel=True)
def batch_kernel(mp, extra0, rows, blocks):
    """The batch kernel: the kernel over the rows of :func:`rocking.models.base.row_args`."""
    for i in prange(rows.kinds.shape[0]):
        kernel(with_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
        store_row(i, rows)


@njit(cache=True)
def kernel_taylor(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp, res,
                  extra):
    """:func:`kernel` with :func:`integrate_taylor` (``method="taylor"``)."""
    h_max = min(0.05 / max(mp.p_p, mp.p_m), 8.0 * h_scan)
    k, n_imp, peak, over, t_over, t_up, n_steps, t_lift, settled = integrate_taylor(
        mp.alpha_p, mp.p_p, mp.mu_p, mp.alpha_m, mp.p_m, mp.mu_m, mp.linear, kind, prm,
        samples, t_end, t_quiet, y0[0], y0[1], mp.rtol, mp.rest_tol, mp.free_rest_tol, h_max,
        h_scan, dt_out, hist[:, 0], hist[:, 1], imp)
    set_planar_result(res, k, n_imp, peak, over, t_over, t_up, n_steps, 0, t_lift, settled)


@njit(cache=True, parallel=True)
def batch_kernel_taylor(mp, extra0, rows, blocks):
    """:func:`batch_kernel` with :func:`kernel_taylor` (``method="taylor"``)."""
    for i in prange(rows.kinds.shape[0]):
        kernel_taylor(with_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
        store_row(i, rows)


# ------------------------------------------------------------------------------- the model
DEFAULT_RTOL = 1e-8
DEFAULT_REST_TOL = 1e-12
"""Default Zeno threshold (fraction of alpha), from the convergence study
``benchmarks/study_rest_tol.py`` (13,600 runs: 16 blocks, 34 records, 25 load factors),
kept as ``tests/test_rest_rule.py``: at 1e-12 no maximum angle changes by 0.1 % when the
threshold is made 100 times smaller (worst 8e-10) and no overturning outcome flips; 1e-10
and 1e-11 still fail on 2 runs, 1e-6 (the former default) on 3 % of them (Gazli: 0.61
alpha instead of 0.71 alpha). The cost is 1.6-1.75 times the CPU time of 1e-6."""


DEFAULT_FREE_REST_TOL = 1e-3
"""Zeno threshold (fraction of alpha) once the ground is still. ``rest_tol`` must be tiny
while the ground shakes, because a block put to rest too early is lifted again
differently; once the motion has ended nothing can lift it again, its outcome and its
largest angle are decided (:func:`free_outcome`), and the rocking below 1e-3 alpha
(0.01 deg for specimen 2) changes no result but ``n_impacts``: with ``mu = 0.973`` it
would take 380 more impacts to fall from 1e-3 to 1e-12 alpha, the bulk of the cost of
the free motion (``benchmarks/bench_campaign.py --only tail``)."""


@dataclass(frozen=True)
class ClassicalTolerances(ModelOptions):
    """The options of the classical integration (error control and Zeno rule), shared by
    the models built on it (:mod:`rocking.models.anchored`)."""

    rtol: float = option(DEFAULT_RTOL, lo=1e-13, hi=1e-2, lo_open=False,
                         help="relative tolerance of the adaptive Dormand-Prince steps")
    rest_tol: float = option(DEFAULT_REST_TOL, lo=0.0, hi=1e-2,
                             help="Zeno rule: free amplitude (fraction of alpha) below "
                                  "which the block is put to rest after an impact")
    free_rest_tol: float = option(DEFAULT_FREE_REST_TOL, lo=0.0, hi=1.0,
                                  help="Zeno rule once the ground is still (after the "
                                       "motion): free amplitude (fraction of alpha) below "
                                       "which the block is at rest")


METHODS = ("dopri", "taylor")
"""The integrators of the classical model (``method``): ``"dopri"`` (default) adaptive
Dormand-Prince 5(4) steps under ``rtol``; ``"taylor"`` fixed steps of the Taylor series
of Eq 1 (:func:`taylor_step`), one per sample of a record (at most ``0.05/p`` long), with
the same events, rules and outputs (``rtol`` is not used). The Taylor series needs the
ground acceleration to be linear over a step: a motion other than a record without a
vertical component runs with ``"dopri"``."""


@dataclass(frozen=True)
class HousnerOptions(ClassicalTolerances):
    """Options of the classical model."""

    linear: bool = option(False, help="small-angle form of Eq 1")
    method: str = option("dopri", choices=METHODS,
                         help="integrator: 'dopri' adaptive Dormand-Prince 5(4) under rtol; "
                              "'taylor' fixed Taylor-series steps, one per record sample "
                              "(faster on records; other motions use dopri; rtol unused)")


class Housner(Model):
    """The classical model: Eq 1 between impacts, Eq 4 at impacts (module docstring)."""

    name = "housner"
    label = "classical (Housner)"
    Options = HousnerOptions
    kernel = kernel
    batch_kernel = batch_kernel

    accepts_asymmetric = True

    @classmethod
    def block_row(cls, block) -> tuple:
        return (block.alpha_plus, block.p_plus, block.mu_plus, block.alpha_minus,
                block.p_minus, block.mu_minus)

    @property
    def result_name(self) -> str:
        return "housner-linear" if self.options.linear else "housner"

    def kernel_params(self, dt_out, theta0, omega0) -> tuple:
        b, o = self.block, self.options
        return HousnerParams(b.alpha_plus, b.p_plus, b.mu_plus, o.linear, o.rtol, o.rest_tol,
                             o.free_rest_tol, b.alpha_minus, b.p_minus, b.mu_minus)

    def kernels(self) -> tuple:
        """The Taylor pair (:func:`kernel_taylor`, :func:`batch_kernel_taylor`) when
        ``method="taylor"``, else the default (Dormand-Prince) pair."""
        if self.options.method == "taylor":
            return kernel_taylor, batch_kernel_taylor
        return kernel, batch_kernel
