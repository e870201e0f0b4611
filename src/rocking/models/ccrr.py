r"""The CCRR model: complex coupled rocking rotations (Peña et al. 2007, Eqs 5-10).

**Derivation.** Write the rocking angle as a complex number ``theta = r e^{i psi}``
(Eq 5): ``r = |theta|`` and the sign of ``theta`` lives in the phase ``psi``. The
Lagrangian (Eq 6) is

.. math:: L_0 = \tfrac{I}{2}(r'^2 + r^2 \psi'^2) - M g R \cos(\alpha - r).

Lagrange's equations with the generalised forces of Eq 9 (``Q_psi = 0``) give

.. math::

    I r'' - I r \psi'^2 + M g R \sin(\alpha - r) = Q_r^d + Q_r^s, \qquad
    \frac{d}{d\tau}(I r^2 \psi') = 0 .

The second equation conserves the angular momentum: ``r^2 psi'`` is constant. With
``chi = r / alpha``, the adimensional time ``t = p tau`` (``p^2 = M g R / I``, Eq 3) and
``l = chi^2 dpsi/dt``, dividing the first equation by ``I p^2 alpha`` gives Eq 10:

.. math::

    \ddot\chi = \frac{l^2}{\chi^3} - \frac{1}{\alpha}\sin(\alpha - \alpha\chi)
       + c\,\frac{l}{\chi^2}\,\dot\chi
       + \frac{a(t/p)}{g\alpha}\cos(\alpha - \alpha\chi)\cos\psi,
    \qquad \dot\psi = \frac{l}{\chi^2}.

**Damping coefficient.** We take ``c = 2 ln(mu) / pi`` (Eq 10), not the ``ln(mu)/pi``
implied by Eq 9. Near the origin the motion is almost free, ``chi_dot^2 + l^2/chi^2
~ v^2``, and along the passage ``chi_dot^2 = v^2 sin^2(psi - psi_c)``, so the energy
``E = v^2/2`` obeys ``d ln E = 2 c sin^2(u) du`` over ``u`` in (-pi/2, pi/2): one
passage multiplies ``E`` by ``exp(c pi)``. ``c = 2 ln(mu)/pi`` gives ``mu^2`` (velocity
times ``mu``, the classical restitution of Eq 4); Eq 9's coefficient would give
``sqrt(mu)`` per passage. The tests check the ratio ``mu`` through one passage, and that
the model tends to the classical one as ``l -> 0``.

**The regularising angular momentum** ``l``. ``l > 0`` keeps the trajectory away from the
singular origin: it passes at ``chi_min ~ l / v``. As ``l -> 0`` the model tends to the
classical one, and the cost of a passage grows like ``log(1/l)``. The default
``l = 1e-8`` comes from two convergence studies kept as tests (``tests/test_ccrr.py``):

* free rocking: amplitudes and zero-crossing times agree with the classical model to
  better than 0.5% over the first six half-cycles for every ``l <= 1e-5`` (``l = 1e-4``
  misses by 1.7% for specimen 4);
* earthquake statistics: over 200 random records, the overturning fraction and the median
  maximum angle converge to the classical model's only for ``l <= 1e-8`` (``l = 1e-6``
  still biases the median by -8%): under strong shaking a finite ``l`` switches the
  excitation off during each passage (``cos(psi) ~ 0``) for a time ``~ l / v^2``.

Single earthquake trajectories cannot be compared: rocking under random input is chaotic
(changing ``mu`` by 1e-4 moves the maximum angle of a typical record by 2%).

**Sign convention and events.** ``theta = alpha chi cos(psi)``, with the ground-motion
term as in Eq 10 and the sign convention of Eq 1 (see :mod:`rocking.models.housner`).

* Rest and uplift as in the classical model: at rest until ``|a| > g tan(alpha)``; then
  the motion starts from the small modulus ``chi_start = sqrt(l)`` with ``chi_dot = 0`` and
  ``psi = 0`` (``a > 0``) or ``pi`` (``a < 0``). The centrifugal energy injected,
  ``l/2``, is negligible (5e-9 of the potential energy at ``theta = alpha``).
* An *impact* is a passage of ``theta`` through zero: ``psi`` crossing ``pi/2 + k pi``.
* Return to rest: with ``l > 0`` the block never quite stops; it settles on a small
  circular orbit of radius ``chi_c = (l^2 alpha / sin(alpha))^(1/3)``. After each passage,
  if the amplitude that the energy allows is below ``rest_chi = max(rest_tol, 2 chi_c)``
  (in units of alpha) and ``|a| <= g tan(alpha)``, the block is put to rest; once the
  ground is still (after the motion) the threshold is at least ``free_rest_tol``
  (1e-3, as in :mod:`rocking.models.housner`).
* Overturning: ``r = alpha chi`` reaches ``pi/2``.

**Asymmetric blocks** (:meth:`rocking.Block.from_geometry`). The side is that of
``cos(psi)`` (``theta = alpha chi cos(psi)``); Eq 10 there is written with the side's
``alpha_s`` and ``(p_s/p)^2`` in the gravity and excitation terms, ``chi`` and the time
being scaled by the weaker side's ``alpha`` and ``p`` (on a tie the smaller ``p``), and
the uplift thresholds are those of the classical model. The damping of a passage is
``2 ln(mu_s)/pi`` of the side ``s`` it leaves (set at the start and at every largest
excursion, where the damping force vanishes): it multiplies the velocity by ``mu_s``, the
classical restitution of an impact that ends rocking on side ``s``. The side is frozen
within a step and the adaptive steps land just past each passage through ``theta = 0``,
where it switches. Equal sides: Eq 10's arithmetic exactly (bit-identical results).

**Integration.** Runge-Kutta-Fehlberg 4(5) as in the paper: with a constant step ``dt``
(s), for fidelity to the paper, propagating the fourth-order solution; or adaptive (the
default), with the embedded error estimate controlling the step and the fifth-order
solution carried forward (local extrapolation). The phase error is weighted by the
modulus (the arc ``chi dpsi`` is controlled, not ``psi``), since ``theta`` does not depend
on ``psi`` at the origin. The passage near ``chi = 0`` needs tiny steps (``chi_min ~ l/v``),
so a passage costs ~100 steps; default ``rtol = 1e-6`` (the maximum angle of specimen 2
under the 5 Hz, 5 mm sine changes by 1e-5 between ``rtol`` 1e-6 and 1e-10). Compiled with
numba; batches run in parallel.
"""

from __future__ import annotations

import math
from collections import namedtuple
from dataclasses import dataclass

from numba import njit, prange

from ..motions._kernel import (
    ground_acc,
    ground_acc_hv,
    has_vertical,
    next_breakpoint,
    vertical_acc,
)
from ..units import G
from ._numerics import events as E
from .base import Model, ModelOptions, option, row_args, set_planar_result, store_row
from .housner import DEFAULT_FREE_REST_TOL

HALF_PI = 0.5 * math.pi
INV_G = 1.0 / G
DEFAULT_L = 1e-8
DEFAULT_RTOL = 1e-6

# Fehlberg 4(5) tableau
C2, C3, C4, C5, C6 = 1 / 4, 3 / 8, 12 / 13, 1.0, 1 / 2
A21 = 1 / 4
A31, A32 = 3 / 32, 9 / 32
A41, A42, A43 = 1932 / 2197, -7200 / 2197, 7296 / 2197
A51, A52, A53, A54 = 439 / 216, -8.0, 3680 / 513, -845 / 4104
A61, A62, A63, A64, A65 = -8 / 27, 2.0, -3544 / 2565, 1859 / 4104, -11 / 40
B1, B3, B4, B5 = 25 / 216, 1408 / 2565, 2197 / 4104, -1 / 5
R1, R3, R4, R5, R6 = 1 / 360, -128 / 4275, -2197 / 75240, 1 / 50, 2 / 55  # 5th - 4th order


@njit(cache=True)
def _f(chi, v, psi, t, p, alpha, l, sd, kind, prm, samples):
    """Time derivatives (physical time) of (chi, chi_dot, psi); chi_dot is per adim. time.
    With a vertical component, ``g`` becomes ``g + a_v`` in the gravity term of Eq 10.

    ``sd = (alpha_s, q_s, c)``: the side rocked on (:func:`_side`, frozen within a step),
    ``q_s = (p_s/p)^2``, and the damping ``c``; ``chi = r/alpha``, ``t = p tau`` with the
    block's ``alpha``, ``p`` (those of its weaker side). Equal sides: ``alpha_s = alpha``,
    ``q = 1`` and Eq 10's arithmetic exactly."""
    inv = 1.0 / chi
    inv2 = inv * inv
    cp = math.cos(psi)
    al, q, c = sd
    if has_vertical(prm):
        ah, av = ground_acc_hv(kind, prm, samples, t)
        a = ah * INV_G
        gf = 1.0 + av * INV_G
        acc = (l * l * inv2 * inv - gf * q * math.sin(al - alpha * chi) / alpha
               + c * l * inv2 * v + q * a / alpha * math.cos(al - alpha * chi) * cp)
    else:
        a = ground_acc(kind, prm, samples, t) / G
        acc = (l * l * inv2 * inv - q * math.sin(al - alpha * chi) / alpha + c * l * inv2 * v
               + q * a / alpha * math.cos(al - alpha * chi) * cp)
    return p * v, p * acc, p * l * inv2


@njit(cache=True)
def _side(psi, sides):
    """``(alpha_s, q_s, c_s)`` of the side ``s`` of the phase ``psi`` (side + where
    ``cos(psi) >= 0``) from ``sides = (alpha_+, q_+, c_+, alpha_-, q_-, c_-)``; ``c_s =
    2 ln(mu_s)/pi`` is the damping of the passage that ends rocking on side ``s``. The
    side is frozen within a step; the adaptive steps of an asymmetric block land on the
    passages through ``theta = 0``, where it switches (:func:`integrate`)."""
    if math.cos(psi) >= 0.0:
        return sides[0], sides[1], sides[2]
    return sides[3], sides[4], sides[5]


@njit(cache=True)
def _step(t, x, v, s, h, p, alpha, l, sd, kind, prm, samples):
    """One RKF45 step; returns the 4th-order state and the (5th - 4th) error estimates."""
    k1x, k1v, k1s = _f(x, v, s, t, p, alpha, l, sd, kind, prm, samples)
    k2x, k2v, k2s = _f(x + h * A21 * k1x, v + h * A21 * k1v, s + h * A21 * k1s, t + C2 * h,
                       p, alpha, l, sd, kind, prm, samples)
    k3x, k3v, k3s = _f(x + h * (A31 * k1x + A32 * k2x), v + h * (A31 * k1v + A32 * k2v),
                       s + h * (A31 * k1s + A32 * k2s), t + C3 * h, p, alpha, l, sd, kind, prm,
                       samples)
    k4x, k4v, k4s = _f(x + h * (A41 * k1x + A42 * k2x + A43 * k3x),
                       v + h * (A41 * k1v + A42 * k2v + A43 * k3v),
                       s + h * (A41 * k1s + A42 * k2s + A43 * k3s), t + C4 * h,
                       p, alpha, l, sd, kind, prm, samples)
    k5x, k5v, k5s = _f(x + h * (A51 * k1x + A52 * k2x + A53 * k3x + A54 * k4x),
                       v + h * (A51 * k1v + A52 * k2v + A53 * k3v + A54 * k4v),
                       s + h * (A51 * k1s + A52 * k2s + A53 * k3s + A54 * k4s), t + C5 * h,
                       p, alpha, l, sd, kind, prm, samples)
    k6x, k6v, k6s = _f(x + h * (A61 * k1x + A62 * k2x + A63 * k3x + A64 * k4x + A65 * k5x),
                       v + h * (A61 * k1v + A62 * k2v + A63 * k3v + A64 * k4v + A65 * k5v),
                       s + h * (A61 * k1s + A62 * k2s + A63 * k3s + A64 * k4s + A65 * k5s),
                       t + C6 * h, p, alpha, l, sd, kind, prm, samples)
    x1 = x + h * (B1 * k1x + B3 * k3x + B4 * k4x + B5 * k5x)
    v1 = v + h * (B1 * k1v + B3 * k3v + B4 * k4v + B5 * k5v)
    s1 = s + h * (B1 * k1s + B3 * k3s + B4 * k4s + B5 * k5s)
    ex = h * (R1 * k1x + R3 * k3x + R4 * k4x + R5 * k5x + R6 * k6x)
    ev = h * (R1 * k1v + R3 * k3v + R4 * k4v + R5 * k5v + R6 * k6v)
    es = h * (R1 * k1s + R3 * k3s + R4 * k4s + R5 * k5s + R6 * k6s)
    return x1, v1, s1, ex, ev, es


@njit(cache=True)
def _theta(x, v, s, p, alpha, l):
    """Physical angle and angular velocity from (chi, chi_dot, psi)."""
    cs = math.cos(s)
    return alpha * x * cs, alpha * p * (v * cs - l / x * math.sin(s))


@njit(cache=True)
def _herm3(y0, d0, y1, d1, h, u):
    """Cubic Hermite value and derivative at fraction u of a step of length h."""
    u2 = u * u
    u3 = u2 * u
    y = ((2 * u3 - 3 * u2 + 1) * y0 + (u3 - 2 * u2 + u) * h * d0 + (-2 * u3 + 3 * u2) * y1
         + (u3 - u2) * h * d1)
    dy = ((6 * u2 - 6 * u) * y0 + (3 * u2 - 4 * u + 1) * h * d0 + (-6 * u2 + 6 * u) * y1
          + (3 * u2 - 2 * u) * h * d1) / h
    return y, dy


@njit(cache=True)
def _amp_chi(x, v, alpha, l, al, q):
    """Modulus reachable with the current energy (centrifugal part included), in alpha units,
    on the side of critical angle ``al`` and ``q = (p_side/p)^2`` (``al = alpha``, ``q = 1``:
    a symmetric block)."""
    e = 0.5 * v * v + 0.5 * l * l / (x * x) + q * (math.cos(al - alpha * x) - math.cos(al)) \
        / (alpha * alpha)
    cm = math.cos(al) + alpha * alpha * e / q
    if cm >= 1.0:
        return math.inf
    return (al - math.acos(cm)) / alpha


@njit(cache=True)
def _amp_chi_g(x, v, alpha, l, gf, al, q):
    """:func:`_amp_chi` under the effective gravity ``gf g`` (``gf = 1 + a_v/g``)."""
    e = 0.5 * v * v + 0.5 * l * l / (x * x) + gf * q * (math.cos(al - alpha * x)
                                                        - math.cos(al)) / (alpha * alpha)
    cm = math.cos(al) + alpha * alpha * e / (gf * q)
    if cm >= 1.0:
        return math.inf
    return (al - math.acos(cm)) / alpha


@njit(cache=True)
def integrate(alpha_p, p_p, mu_p, alpha_m, p_m, mu_m, l, kind, prm, samples, t_end, t_quiet,
              th0, om0, rtol, dt_fixed, rest_chi, free_rest_chi, chi_start, h_max, h_scan,
              dt_out, out_th, out_om, imp):
    """Integrate one CCRR simulation. Returns
    (n_out, n_impacts, max_abs_theta, overturned, overturn_time, uplift_time, n_steps, ok,
    lift_off_time, settled).
    The block's sides: ``alpha_p``, ``p_p`` (``theta > 0``), ``alpha_m``, ``p_m``; ``mu_p``/
    ``mu_m`` the restitutions of the passages that end rocking on side +/- (equal sides:
    Eq 10 exactly). ``dt_fixed > 0`` selects constant steps; otherwise adaptive with
    ``rtol``. From ``t_quiet`` on the ground is still: the run stops once the block is at
    rest.
    """
    # chi = r / alpha and t = p tau with the weaker side's alpha, p (on a tie the smaller
    # p: the scales, and l with them, do not depend on which side is called +)
    weak_m = alpha_m < alpha_p or (alpha_m == alpha_p and p_m < p_p)
    alpha, p = (alpha_m, p_m) if weak_m else (alpha_p, p_p)
    q_p = (p_p / p) ** 2
    q_m = (p_m / p) ** 2
    sides = (alpha_p, q_p, 2.0 * math.log(mu_p) / math.pi,
             alpha_m, q_m, 2.0 * math.log(mu_m) / math.pi)
    asym = not (alpha_p == alpha_m and p_p == p_m and mu_p == mu_m)
    ct_p = math.tan(alpha_p)
    ct_m = math.tan(alpha_m)
    thr_p = G * ct_p
    thr_m = G * ct_m
    p_hi = max(p_p, p_m)
    hv = has_vertical(prm)
    t_lift = math.nan
    x_over = HALF_PI / alpha
    fixed = dt_fixed > 0.0
    n_out = out_th.shape[0]
    cap = imp.shape[0]
    atol = rtol * 1e-3
    t = 0.0
    k = 0
    n_imp = 0
    n_steps = 0
    ok = True
    overturned = False
    t_over = math.nan
    t_up = math.nan
    resting = False
    x, v, s = 1.0, 0.0, 0.0
    if th0 == 0.0 and om0 == 0.0:
        resting = True
    elif th0 != 0.0:
        x = abs(th0) / alpha
        s = 0.0 if th0 > 0.0 else math.pi
        v = om0 / (alpha * p * math.cos(s))
        t_up = 0.0
    else:
        x = chi_start
        v = abs(om0) / (alpha * p)
        s = -HALF_PI if om0 > 0.0 else HALF_PI
        t_up = 0.0
    peak = abs(th0)
    # the damping of the next passage: that of the side rocked on, set where the block
    # starts and at every largest excursion (chi_dot from >= 0 to < 0), where the damping
    # force c l chi_dot / chi^2 vanishes
    c_now = _side(s, sides)[2]
    h = dt_fixed if fixed else min(h_max, 1e-3 / p_hi)
    while t < t_end - 1e-12:
        if resting:
            if t >= t_quiet - 1e-12:
                break  # the ground is still: at rest for good
            t, k, d, t_up = E.rest_advance_sides(kind, prm, samples, t, min(t_end, t_quiet),
                                                 h_scan, thr_p, ct_p, thr_m, ct_m, dt_out, k,
                                                 out_th, out_om, t_up)
            resting = d == 0.0
            if resting:  # still at rest at t_end (or t_quiet)
                break
            if d == E.LIFT_OFF:
                t_lift = t
                break
            x, v = chi_start, 0.0  # uplift from the small modulus, towards sign(a)
            s = 0.0 if d > 0.0 else math.pi
            c_now = _side(s, sides)[2]
            h = dt_fixed if fixed else min(h_max, 1e-3 / p_hi)
            continue
        hh = min(h, t_end - t)
        if not fixed:
            hh = min(hh, h_max, next_breakpoint(kind, prm, samples, t) - t)
        al, q, _c = _side(s, sides)
        sd = (al, q, c_now)
        x1, v1, s1, ex, ev, es = _step(t, x, v, s, hh, p, alpha, l, sd, kind, prm, samples)
        if not fixed:  # local extrapolation: carry the fifth-order solution
            x1 += ex
            v1 += ev
            s1 += es
        n_steps += 1
        bad = not (x1 > 0.0) or not (abs(v1) < 1e300) or not (abs(s1) < 1e300)
        if fixed:
            if bad:
                ok = False
                break
            err = 0.0
        else:
            sx = atol + rtol * max(abs(x), abs(x1))
            sv = atol + rtol * max(abs(v), abs(v1))
            ss = sx / max(abs(x), abs(x1))  # controls the arc chi*dpsi, not psi itself
            err = math.sqrt(((ex / sx) ** 2 + (ev / sv) ** 2 + (es / ss) ** 2) / 3.0)
            if bad or not (err <= 1.0):
                fac = 0.9 * err ** -0.2 if (not bad and err == err) else 0.1
                h = hh * max(0.1, fac)
                if h < 1e-14:
                    ok = False
                    break
                continue
            if asym:
                # land the step just past the passage through theta = 0, where the side
                # (frozen within the step) switches
                sc = HALF_PI + (math.floor((s - HALF_PI) / math.pi) + 1.0) * math.pi
                if s1 > sc:
                    frac = (sc - s) / (s1 - s)
                    if frac < 0.999 and hh * frac > 1e-12:
                        h = hh * min(frac * 1.0005, 0.999)
                        continue
        tc = E.first_lift_off(prm, samples, t, t + hh, h_scan) if hv else math.nan
        if tc == tc:
            # the base falls away (g + a_v <= 0): stop at that instant, the model cannot
            # represent flight
            x2, v2, s2, ex2, ev2, es2 = _step(t, x, v, s, tc - t, p, alpha, l, sd, kind, prm,
                                              samples)
            if not fixed:
                x2 += ex2
                v2 += ev2
                s2 += es2
            if alpha * x2 < HALF_PI and x2 > 0.0:
                hh, x1, v1, s1 = tc - t, x2, v2, s2
                t_lift = tc
        th_a, om_a = _theta(x, v, s, p, alpha, l)
        th_b, om_b = _theta(x1, v1, s1, p, alpha, l)
        # passages through theta = 0: psi crosses pi/2 + j pi
        j0 = math.floor((s - HALF_PI) / math.pi)
        j1 = math.floor((s1 - HALF_PI) / math.pi)
        passed = j1 != j0
        if passed:
            for j in range(int(j0) + 1, int(j1) + 1):
                sc = HALF_PI + j * math.pi
                tc = t + hh * (sc - s) / (s1 - s)
                if n_imp < cap:
                    imp[n_imp] = tc
                n_imp += 1
        if alpha * x1 >= HALF_PI:
            u = (x_over - x) / (x1 - x)
            t_over = t + u * hh
            overturned = True
            peak = HALF_PI
            while k < n_out and k * dt_out <= t_over + 1e-12:
                out_th[k], out_om[k] = _herm3(th_a, om_a, th_b, om_b, hh, (k * dt_out - t) / hh)
                k += 1
            t = t_over
            break
        while k < n_out and k * dt_out <= t + hh + 1e-12:
            out_th[k], out_om[k] = _herm3(th_a, om_a, th_b, om_b, hh,
                                          min(max((k * dt_out - t) / hh, 0.0), 1.0))
            k += 1
        peak = max(peak, abs(th_b))
        if om_a * om_b < 0.0:
            lo, hi = 0.0, 1.0
            flo = om_a
            for _ in range(50):
                mid = 0.5 * (lo + hi)
                fm = _herm3(th_a, om_a, th_b, om_b, hh, mid)[1]
                if (fm > 0.0) == (flo > 0.0):
                    lo, flo = mid, fm
                else:
                    hi = mid
            peak = max(peak, abs(_herm3(th_a, om_a, th_b, om_b, hh, 0.5 * (lo + hi))[0]))
        t += hh
        if v >= 0.0 and v1 < 0.0:
            c_now = _side(s1, sides)[2]
        x, v, s = x1, v1, s1
        if not math.isnan(t_lift):
            break
        al, q, _c = _side(s, sides)  # the side now
        amp = (_amp_chi_g(x, v, alpha, l, 1.0 + vertical_acc(prm, samples, t) * INV_G, al, q)
               if hv else _amp_chi(x, v, alpha, l, al, q)) if passed else math.inf
        if amp < (rest_chi if t < t_quiet else max(rest_chi, free_rest_chi)):
            ag = ground_acc(kind, prm, samples, t)
            if abs(ag) <= E.threshold_sides(ag, thr_p, ct_p, thr_m, ct_m, prm, samples, t):
                resting = True
        if not fixed:
            fac = 0.9 * err ** -0.2 if err > 0.0 else 5.0
            h = hh * min(5.0, max(0.2, fac))
    settled = ok and (overturned or resting)
    return k, n_imp, peak, overturned, t_over, t_up, n_steps, ok, t_lift, settled


CCRRParams = namedtuple("CCRRParams", [
    "alpha_p", "p_p", "mu_p", "l", "rtol", "dt_fixed", "rest_tol", "free_rest_tol", "alpha_m",
    "p_m", "mu_m"])
"""The kernel parameters ``mp`` of the CCRR model: both sides' ``alpha`` (rad), ``p``
(1/s) and ``mu``, and the options (:class:`CCRROptions`; ``dt_fixed`` 0: adaptive)."""


@njit(cache=True)
def kernel(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp, res, extra):
    """The single-run kernel of the model interface (:mod:`rocking.models.base`)."""
    l = mp.l
    alpha = min(mp.alpha_p, mp.alpha_m)  # the weaker side: the scale of chi
    chi_c = (l * l * alpha / math.sin(alpha)) ** (1.0 / 3.0)  # orbit that l sustains
    rest_chi = max(mp.rest_tol, 2.0 * chi_c)
    chi_start = math.sqrt(l)
    h_max = min(0.05 / max(mp.p_p, mp.p_m), 8.0 * h_scan)
    k, n_imp, peak, over, t_over, t_up, n_steps, ok, t_lift, settled = integrate(
        mp.alpha_p, mp.p_p, mp.mu_p, mp.alpha_m, mp.p_m, mp.mu_m, l, kind, prm, samples, t_end,
        t_quiet, y0[0], y0[1], mp.rtol, mp.dt_fixed, rest_chi, mp.free_rest_tol, chi_start,
        h_max, h_scan, dt_out, hist[:, 0], hist[:, 1], imp)
    set_planar_result(res, k, n_imp, peak, over, t_over, t_up, n_steps, 0 if ok else 1,
                      t_lift, settled)


@njit(cache=True)
def with_block(mp, b):
    """``mp`` with the block parameters ``b = (alpha_plus, p_plus, mu_plus, alpha_minus,
    p_minus, mu_minus)`` of a batch row."""
    return CCRRParams(b[0], b[1], b[2], mp.l, mp.rtol, mp.dt_fixed, mp.rest_tol,
                      mp.free_rest_tol, b[3], b[4], b[5])


@njit(cache=True, parallel=True)
def batch_kernel(mp, extra0, rows, blocks):
    """The batch kernel: the kernel over the rows of :func:`rocking.models.base.row_args`."""
    for i in prange(rows.kinds.shape[0]):
        kernel(with_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
        store_row(i, rows)


# ------------------------------------------------------------------------------- the model
DEFAULT_REST_TOL = 1e-6


@dataclass(frozen=True)
class CCRROptions(ModelOptions):
    """Options of the CCRR model."""

    l: float = option(DEFAULT_L, lo=0.0, hi=0.1,
                      help="regularising angular momentum (adimensional)")
    rtol: float = option(DEFAULT_RTOL, lo=1e-13, hi=1e-2, lo_open=False,
                         help="relative tolerance of the adaptive RKF45 steps")
    dt: float | None = option(None, unit="s", lo=0.0,
                              help="constant RKF45 step instead of adaptive steps")
    rest_tol: float = option(DEFAULT_REST_TOL, lo=0.0, hi=1e-2,
                             help="rest threshold (fraction of alpha); at least twice the "
                                  "radius of the orbit that l sustains")
    free_rest_tol: float = option(DEFAULT_FREE_REST_TOL, lo=0.0, hi=1.0,
                                  help="rest threshold once the ground is still (after "
                                       "the motion), as in the classical model")


class CCRR(Model):
    """Complex coupled rocking rotations, Eq 10 (module docstring)."""

    name = "ccrr"
    label = "CCRR"
    Options = CCRROptions
    kernel = kernel
    batch_kernel = batch_kernel

    accepts_asymmetric = True

    @classmethod
    def block_row(cls, block) -> tuple:
        return (block.alpha_plus, block.p_plus, block.mu_plus, block.alpha_minus,
                block.p_minus, block.mu_minus)

    def kernel_params(self, dt_out, theta0, omega0) -> tuple:
        b, o = self.block, self.options
        return CCRRParams(b.alpha_plus, b.p_plus, b.mu_plus, o.l, o.rtol, o.dt or 0.0,
                          o.rest_tol, o.free_rest_tol, b.alpha_minus, b.p_minus, b.mu_minus)

    def failure(self, status, t, dt_out=None) -> str:
        at = f" at t = {t:.4g} s" if t == t else ""
        return (f"ccrr integration failed near the origin{at}: the constant step dt = "
                f"{self.options.dt} s is too large for l = {self.options.l:g}; use a smaller "
                "dt or the adaptive mode (dt=None)")
