r"""A rocking block anchored at its base corners (issue 19, part 2): ``model="anchored"``.

The physics is that of :mod:`rocking.testing.anchored_reference` (the plain scipy
reference this kernel is checked against; see its docstring for the derivation): the
classical model (Eq 1 between impacts, Eq 4 at impacts, :mod:`rocking.models.housner`,
which this file does not touch) plus two brittle anchors, ``+`` (stretched when
``theta > 0``) and ``-``, each of tensile strength ``F_a = q m g``
(``anchor_strength = q``):

* ``anchors="rigid"`` (Makris and Zhang 2001, J. Eng. Mech. 127(5)): at rest the block
  uplifts towards ``s`` when ``s a > g tan(alpha) (1 + 2 q)`` with the anchor ``s``
  intact (gravity's moment ``m g b`` plus the anchor's ultimate moment ``2 b F_a``), when
  ``s a > g tan(alpha)`` once it has broken; the anchor breaks at the uplift (it has
  reached ``F_a``), and an impact that carries the block onto the side of an intact rigid
  anchor breaks it too. While the block is down the intact anchor carries
  ``(|a|/(g tan(alpha)) - 1)/2`` of the weight (sampled at the motion's scan step);
* ``anchors="elastic"``: the anchor of the lifting side adds ``-p^2 2 kappa sin(alpha)
  sin(theta) cos(theta)`` to Eq 1 (``anchor_stiffness = kappa = k_a 2 b/(m g)``) and
  breaks, for good, when ``kappa sin|theta|`` reaches ``q`` (located inside the step);
  the uplift threshold is gravity's (no force at ``theta = 0``).

A block that starts tilted (``theta0 != 0``) with a rigid anchor on that side has it
broken at ``t = 0``. A vertical motion replaces ``g`` by ``g + a_v`` in the gravity term
and in gravity's part of the uplift threshold (not in the anchors'); the run stops where
``g + a_v <= 0`` (lift-off), as in the classical model. Once the ground is still the run
stops at rest; at the cap of the free motion a block with no intact elastic anchor is
decided by energy (:func:`rocking.models.housner.free_outcome`), otherwise it is
reported unsettled.

Extra outputs of a single run (``Response.info``): ``max_anchor_force`` (fraction of
``m g``; ``max_anchor_force_n`` in N when the block's mass is known), ``anchor_broken``
and ``anchor_break_time`` (``[+, -]``, s, NaN: intact); the row outputs
(``max_anchor_force``, ``anchor_break_time_plus``/``_minus``,
``anchor_broken_plus``/``_minus``) also in batches (``BatchResponse.outputs``) and
campaigns.
"""

from __future__ import annotations

import math
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
from ._numerics import dopri as D
from ._numerics import events as E
from .base import (
    KernelResult,
    Model,
    ModelOptions,
    RowOutput,
    option,
    row_args_out,
    row_output_values,
    store_row,
)
from .housner import DEFAULT_FREE_REST_TOL, DEFAULT_REST_TOL, DEFAULT_RTOL, free_outcome

HALF_PI = 0.5 * math.pi
INV_G = 1.0 / G


@njit(cache=True)
def _acc(th, t, s, alpha, p2, ka, kind, prm, samples):
    """Eq 1 on branch ``s`` plus the elastic anchor's moment (``ka``: its stiffness kappa
    while intact on this side, else 0)."""
    if has_vertical(prm):
        ah, av = ground_acc_hv(kind, prm, samples, t)
        a = ah * INV_G
        gf = 1.0 + av * INV_G
    else:
        a = ground_acc(kind, prm, samples, t) * INV_G
        gf = 1.0
    acc = -s * p2 * gf * math.sin(alpha - s * th) + p2 * math.cos(alpha - s * th) * a
    if ka > 0.0:
        acc -= p2 * 2.0 * math.sin(alpha) * ka * math.sin(th) * math.cos(th)
    return acc


@njit(cache=True)
def _step(t, th, om, a1, h, s, alpha, p2, ka, kind, prm, samples):
    """One Dormand-Prince step; returns (theta, omega, acc_end, err_theta, err_omega)."""
    k1t, k1o = om, a1
    k2t = om + h * D.A21 * k1o
    k2o = _acc(th + h * D.A21 * k1t, t + D.C2 * h, s, alpha, p2, ka, kind, prm, samples)
    k3t = om + h * (D.A31 * k1o + D.A32 * k2o)
    k3o = _acc(th + h * (D.A31 * k1t + D.A32 * k2t), t + D.C3 * h, s, alpha, p2, ka,
               kind, prm, samples)
    k4t = om + h * (D.A41 * k1o + D.A42 * k2o + D.A43 * k3o)
    k4o = _acc(th + h * (D.A41 * k1t + D.A42 * k2t + D.A43 * k3t), t + D.C4 * h, s, alpha,
               p2, ka, kind, prm, samples)
    k5t = om + h * (D.A51 * k1o + D.A52 * k2o + D.A53 * k3o + D.A54 * k4o)
    k5o = _acc(th + h * (D.A51 * k1t + D.A52 * k2t + D.A53 * k3t + D.A54 * k4t),
               t + D.C5 * h, s, alpha, p2, ka, kind, prm, samples)
    k6t = om + h * (D.A61 * k1o + D.A62 * k2o + D.A63 * k3o + D.A64 * k4o + D.A65 * k5o)
    k6o = _acc(th + h * (D.A61 * k1t + D.A62 * k2t + D.A63 * k3t + D.A64 * k4t
                         + D.A65 * k5t), t + h, s, alpha, p2, ka, kind, prm, samples)
    th1 = th + h * (D.B1 * k1t + D.B3 * k3t + D.B4 * k4t + D.B5 * k5t + D.B6 * k6t)
    om1 = om + h * (D.B1 * k1o + D.B3 * k3o + D.B4 * k4o + D.B5 * k5o + D.B6 * k6o)
    k7o = _acc(th1, t + h, s, alpha, p2, ka, kind, prm, samples)
    k7t = om1
    et = h * (D.E1 * k1t + D.E3 * k3t + D.E4 * k4t + D.E5 * k5t + D.E6 * k6t + D.E7 * k7t)
    eo = h * (D.E1 * k1o + D.E3 * k3o + D.E4 * k4o + D.E5 * k5o + D.E6 * k6o + D.E7 * k7o)
    return th1, om1, k7o, et, eo


@njit(cache=True)
def _emit(t0, th0, om0, a0, t1, th1, om1, a1, dt_out, k, out_th, out_om):
    """Write output samples k*dt_out in (t0, t1] by Hermite interpolation; returns next k."""
    n = out_th.shape[0]
    h = t1 - t0
    while k < n and k * dt_out <= t1 + 1e-12:
        tk = k * dt_out
        if h > 0.0:
            x = min(max((tk - t0) / h, 0.0), 1.0)
            th, om = D.hermite5(th0, om0, a0, th1, om1, a1, h, x)
        else:
            th, om = th1, om1
        out_th[k] = th
        out_om[k] = om
        k += 1
    return k


@njit(cache=True)
def _seg_peak(th0, om0, a0, th1, om1, a1, h):
    """Largest |theta| over a segment (an interior extremum included)."""
    peak = max(abs(th0), abs(th1))
    if om0 * om1 < 0.0 and h > 0.0:
        x = D.hermite_root(th0, om0, a0, th1, om1, a1, h, 0.0, 1, om0)
        peak = max(peak, abs(D.hermite5(th0, om0, a0, th1, om1, a1, h, x)[0]))
    return peak


@njit(cache=True)
def _amplitude_from_energy(om, alpha, p2):
    c = math.cos(alpha) + 0.5 * om * om / p2
    return alpha - math.acos(c) if c < 1.0 else math.inf


@njit(cache=True)
def _thr(side, rigid, q, bp, bm, c, gf):
    """Uplift threshold (m/s^2) towards ``side`` with the effective gravity ``gf g``."""
    intact = (not bp) if side > 0.0 else (not bm)
    extra = 2.0 * q * c * G if (rigid and intact) else 0.0
    return c * G * gf + extra


@njit(cache=True)
def _trips(kind, prm, samples, t, rigid, q, bp, bm, c):
    """Whether the block at rest uplifts at ``t`` (or the base falls away): returns the
    direction (+1/-1), E.LIFT_OFF, or 0."""
    gf = 1.0
    if has_vertical(prm):
        gf = 1.0 + vertical_acc(prm, samples, t) * INV_G
        if gf <= 0.0:
            return E.LIFT_OFF
    a = ground_acc(kind, prm, samples, t)
    if a > _thr(1.0, rigid, q, bp, bm, c, gf):
        return 1.0
    if -a > _thr(-1.0, rigid, q, bp, bm, c, gf):
        return -1.0
    return 0.0


@njit(cache=True)
def _hold(kind, prm, samples, t, rigid, q, bp, bm, c):
    """Force (fraction of m g) an intact rigid anchor carries at rest at ``t``."""
    if not rigid:
        return 0.0
    a = ground_acc(kind, prm, samples, t)
    intact = (not bp) if a > 0.0 else (not bm)
    if not intact:
        return 0.0
    return min(q, max(0.0, 0.5 * (abs(a) / (c * G) - 1.0)))


@njit(cache=True)
def _rest(kind, prm, samples, t, t_end, h_scan, rigid, q, bp, bm, c, dt_out, k, out_th,
          out_om, fmax):
    """Advance a block at rest to its uplift (or ``t_end``); returns
    ``(t, k, direction, fmax)`` (direction 0: still at rest at ``t_end``)."""
    n_out = out_th.shape[0]
    while True:
        fmax = max(fmax, _hold(kind, prm, samples, t, rigid, q, bp, bm, c))
        d = _trips(kind, prm, samples, t, rigid, q, bp, bm, c)
        if d != 0.0 or t >= t_end - 1e-12:
            t_w = t - 1e-12 if d != 0.0 else t + 1e-12  # up to the uplift, or through t_end
            while k < n_out and k * dt_out < t_w:
                out_th[k] = 0.0
                out_om[k] = 0.0
                k += 1
            return t, k, d, fmax
        t1 = min(t + h_scan, next_breakpoint(kind, prm, samples, t), t_end)
        if _trips(kind, prm, samples, t1, rigid, q, bp, bm, c) != 0.0:
            lo, hi = t, t1
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if not (lo < mid < hi):
                    break
                if _trips(kind, prm, samples, mid, rigid, q, bp, bm, c) != 0.0:
                    hi = mid
                else:
                    lo = mid
            t1 = hi
        while k < n_out and k * dt_out < t1 - 1e-12:
            out_th[k] = 0.0
            out_om[k] = 0.0
            k += 1
        t = t1


@njit(cache=True)
def integrate(alpha, p, mu, q, kappa, rigid, kind, prm, samples, t_end, t_quiet, th0, om0,
              rtol, rest_tol, free_rest_tol, h_max, h_scan, dt_out, out_th, out_om, imp,
              anch):
    """One simulation; ``anch`` (length >= 5, else ignored) receives ``[max force, t_break+,
    t_break-, broken+, broken-]``. Returns the fields of :data:`KernelResult`."""
    p2 = p * p
    c = math.tan(alpha)
    hv = has_vertical(prm)
    t_lift = math.nan
    atol_th = rtol * alpha * 1e-3
    atol_om = atol_th * p
    n_out = out_th.shape[0]
    cap = imp.shape[0]
    th_b = math.asin(min(q / kappa, 1.0)) if not rigid else 0.0
    t = 0.0
    th = th0
    om = om0
    k = 0
    n_imp = 0
    n_steps = 0
    peak = abs(th0)
    overturned = False
    decided = False
    t_over = math.nan
    t_up = math.nan
    bp = False
    bm = False
    tbp = math.nan
    tbm = math.nan
    fmax = 0.0
    resting = th0 == 0.0 and om0 == 0.0
    s = 1.0
    if th0 < 0.0 or (th0 == 0.0 and om0 < 0.0):
        s = -1.0
    if not resting:
        t_up = 0.0
        if rigid or q == 0.0:  # already lifted: that anchor has given way
            if s > 0.0:
                bp, tbp = True, 0.0
            else:
                bm, tbm = True, 0.0
            fmax = q
        elif kappa * math.sin(abs(th0)) >= q:
            if s > 0.0:
                bp, tbp = True, 0.0
            else:
                bm, tbm = True, 0.0
            fmax = q
    h = min(h_max, 0.01 / p)
    a_cur = 0.0
    need_a = True
    free_time = t_end - t_quiet
    extended = False
    while True:
        intact_s = (not bp) if s > 0.0 else (not bm)
        ka = kappa if (intact_s and not rigid and not resting) else 0.0
        if not t < t_end - 1e-12:
            if resting or overturned or t_quiet > t_end or extended:
                break
            if (not rigid) and ((not bp) or (not bm)):
                break  # an intact elastic anchor: no exact energy decision
            will, amp = free_outcome(th, om, s, alpha, p2, mu, False)
            if not will:
                peak = max(peak, amp)
                decided = True
                break
            t_end = t + max(free_time, 100.0 / p)
            extended = True
            continue
        if resting:
            if t >= t_quiet - 1e-12:
                break
            t, k, d, fmax = _rest(kind, prm, samples, t, min(t_end, t_quiet), h_scan, rigid,
                                  q, bp, bm, c, dt_out, k, out_th, out_om, fmax)
            if d == 0.0:
                continue  # at rest through min(t_end, t_quiet): the tests above decide
            if d == E.LIFT_OFF:
                t_lift = t
                break
            resting, s, need_a, h = False, d, True, min(h_max, 0.01 / p)
            if t_up != t_up:
                t_up = t
            if rigid or q == 0.0:
                if s > 0.0 and not bp:
                    bp, tbp, fmax = True, t, q
                elif s < 0.0 and not bm:
                    bm, tbm, fmax = True, t, q
            continue
        if need_a:
            a_cur = _acc(th, t, s, alpha, p2, ka, kind, prm, samples)
            need_a = False
        bpt = next_breakpoint(kind, prm, samples, t)
        hh = min(h, h_max, t_end - t)
        hit_bp = False
        if t + hh >= bpt - 1e-12:
            hh = bpt - t
            hit_bp = True
        th1, om1, a1, et, eo = _step(t, th, om, a_cur, hh, s, alpha, p2, ka, kind, prm,
                                     samples)
        n_steps += 1
        err = D.err_norm(et, eo, th, th1, om, om1, atol_th, atol_om, rtol)
        if not (err <= 1.0):
            fac = 0.9 * err ** -0.2 if err == err else 0.1
            h = hh * max(0.1, fac)
            continue
        if D.sign_changes(th, om, a_cur, th1, om1, a1, hh, s) >= 2:
            h = 0.5 * hh
            continue
        tc = E.first_lift_off(prm, samples, t, t + hh, h_scan) if hv else math.nan
        if tc == tc:
            thc, omc, ac, _e1, _e2 = _step(t, th, om, a_cur, tc - t, s, alpha, p2, ka, kind,
                                           prm, samples)
            if s * thc >= 0.0 and abs(thc) < HALF_PI:
                if n_out > 0:
                    k = _emit(t, th, om, a_cur, tc, thc, omc, ac, dt_out, k, out_th, out_om)
                peak = max(peak, _seg_peak(th, om, a_cur, thc, omc, ac, tc - t))
                t, th, om = tc, thc, omc
                t_lift = tc
                break
        # ---- the elastic anchor of this side reaches its strength inside the step
        if ka > 0.0:
            if s * th1 < th_b and _seg_peak(th, om, a_cur, th1, om1, a1, hh) >= th_b:
                h = 0.5 * hh  # the crossing is before an interior peak: a shorter step
                continue
            if s * th1 >= th_b:
                x = D.hermite_root(th, om, a_cur, th1, om1, a1, hh, s * th_b, 0, -s)
                lo, hi = 0.0, hh
                sig = x * hh
                thc, omc, ac = th1, om1, a1
                for _ in range(60):
                    thc, omc, ac, _e1, _e2 = _step(t, th, om, a_cur, sig, s, alpha, p2, ka,
                                                   kind, prm, samples)
                    g = s * thc - th_b
                    if g >= 0.0:
                        hi = sig
                    else:
                        lo = sig
                    if abs(g) <= 1e-15 * alpha or hi - lo <= 1e-15 * (1.0 + t):
                        break
                    new = sig - g / (s * omc) if omc != 0.0 else -1.0
                    if not (lo < new < hi):
                        new = 0.5 * (lo + hi)
                    sig = new
                tc = t + sig
                if n_out > 0:
                    k = _emit(t, th, om, a_cur, tc, thc, omc, ac, dt_out, k, out_th, out_om)
                peak = max(peak, _seg_peak(th, om, a_cur, thc, omc, ac, sig))
                if s > 0.0:
                    bp, tbp = True, tc
                else:
                    bm, tbm = True, tc
                fmax = q
                t, th, om = tc, thc, omc
                need_a = True
                h = max(sig, 1e-6 / p)
                continue
        if s * th1 < 0.0:
            x = D.hermite_root(th, om, a_cur, th1, om1, a1, hh, 0.0, 0, s)
            lo, hi = 0.0, hh
            sig = x * hh
            thc, omc, ac = th1, om1, a1
            for _ in range(40):
                thc, omc, ac, _e1, _e2 = _step(t, th, om, a_cur, sig, s, alpha, p2, ka,
                                               kind, prm, samples)
                if s * thc > 0.0:
                    lo = sig
                else:
                    hi = sig
                if abs(thc) <= 1e-15 * alpha or hi - lo <= 1e-15 * (1.0 + t):
                    break
                new = sig - thc / omc if omc != 0.0 else -1.0
                if not (lo < new < hi):
                    new = 0.5 * (lo + hi)
                sig = new
            tc = t + sig
            k = _emit(t, th, om, a_cur, tc, 0.0, omc, ac, dt_out, k, out_th, out_om) \
                if n_out > 0 else k
            pk = _seg_peak(th, om, a_cur, 0.0, omc, ac, sig)
            peak = max(peak, pk)
            if ka > 0.0:
                fmax = max(fmax, kappa * math.sin(pk))
            if n_imp < cap:
                imp[n_imp] = tc
            n_imp += 1
            t = tc
            th = 0.0
            om = mu * omc
            ag = ground_acc(kind, prm, samples, t)
            gf = 1.0 + vertical_acc(prm, samples, t) * INV_G if hv else 1.0
            rt = rest_tol if t < t_quiet else max(rest_tol, free_rest_tol)
            if om == 0.0 or _amplitude_from_energy(om, alpha, p2 * gf) < rt * alpha:
                if ag <= _thr(1.0, rigid, q, bp, bm, c, gf) and \
                        -ag <= _thr(-1.0, rigid, q, bp, bm, c, gf):
                    resting = True
                    om = 0.0
                    continue
            if om != 0.0:
                s = 1.0 if om > 0.0 else -1.0
            else:
                s = 1.0 if ag > 0.0 else -1.0
            if rigid or q == 0.0:  # an intact rigid anchor cannot stop the block
                if s > 0.0 and not bp:
                    bp, tbp, fmax = True, t, q
                elif s < 0.0 and not bm:
                    bm, tbm, fmax = True, t, q
            intact_s = (not bp) if s > 0.0 else (not bm)
            ka = kappa if (intact_s and not rigid) else 0.0
            a_cur = _acc(0.0, t, s, alpha, p2, ka, kind, prm, samples)
            need_a = False
            h = min(h_max, max(hh, 1e-6 / p))
            if om * a_cur < 0.0:
                h = min(h, 0.5 * abs(om / a_cur))
            continue
        if abs(th1) >= HALF_PI:
            x = D.hermite_root(th, om, a_cur, th1, om1, a1, hh, s * HALF_PI, 0, -s)
            t_over = t + x * hh
            thx, omx = D.hermite5(th, om, a_cur, th1, om1, a1, hh, x)
            if n_out > 0:
                k = _emit(t, th, om, a_cur, t_over, s * HALF_PI, omx, a1, dt_out, k,
                          out_th, out_om)
            overturned = True
            peak = HALF_PI
            t = t_over
            break
        if n_out > 0:
            k = _emit(t, th, om, a_cur, t + hh, th1, om1, a1, dt_out, k, out_th, out_om)
        pk = _seg_peak(th, om, a_cur, th1, om1, a1, hh)
        peak = max(peak, pk)
        if ka > 0.0:
            fmax = max(fmax, kappa * math.sin(min(pk, HALF_PI)))
        t = t + hh
        th, om, a_cur = th1, om1, a1
        if hit_bp:
            need_a = True
        fac = 0.9 * err ** -0.2 if err > 0.0 else 5.0
        h = hh * min(5.0, max(0.2, fac)) if not hit_bp or hh >= h else max(h, hh)
    settled = overturned or decided or (resting and t_lift != t_lift)
    if anch.shape[0] >= 5:
        anch[0] = fmax
        anch[1] = tbp
        anch[2] = tbm
        anch[3] = 1.0 if bp else 0.0
        anch[4] = 1.0 if bm else 0.0
    return k, n_imp, peak, overturned, t_over, t_up, n_steps, t_lift, settled


@njit(cache=True)
def kernel(mp, kind, prm, samples, t_end, t_quiet, th0, om0, h_scan, dt_out, out_th, out_om,
           imp, extra):
    """The single-run kernel of the model interface (:mod:`rocking.models.base`)."""
    alpha, p, mu, q, kappa, rigid, rtol, rest_tol, free_rest_tol = mp
    h_max = min(0.05 / p, 8.0 * h_scan)
    if not rigid:
        h_max = min(h_max, 0.05 / (p * math.sqrt(1.0 + kappa)))
    k, n_imp, peak, over, t_over, t_up, n_steps, t_lift, settled = integrate(
        alpha, p, mu, q, kappa, rigid, kind, prm, samples, t_end, t_quiet, th0, om0, rtol,
        rest_tol, free_rest_tol, h_max, h_scan, dt_out, out_th, out_om, imp, extra[0])
    return KernelResult(k, n_imp, peak, over, t_over, t_up, n_steps, 0, t_lift, settled)


@njit(cache=True)
def with_block(mp, b):
    """``mp`` with the block parameters ``b = (alpha, p, mu)`` of a batch row."""
    return (b[0], b[1], b[2], mp[3], mp[4], mp[5], mp[6], mp[7], mp[8])


@njit(cache=True, parallel=True)
def batch_kernel(mp, extra0, rows, blocks):
    """The batch kernel: the kernel over the rows of
    :func:`rocking.models.base.row_args_out` (each row writes its own row outputs)."""
    for i in prange(rows[0].shape[0]):
        store_row(i, kernel(with_block(mp, blocks[i]), *row_args_out(i, rows)), rows)


# ------------------------------------------------------------------------------- the model
@dataclass(frozen=True)
class AnchoredOptions(ModelOptions):
    """Options of the anchored block."""

    anchor_strength: float = option(
        0.5, lo=0.0, hi=1e3, lo_open=False, unit="",
        help="tensile strength of each anchor as a fraction of the block's weight, "
             "q = F_a/(m g)")
    anchors: str = option("rigid", choices=("rigid", "elastic"),
                          help="rigid-brittle (Makris and Zhang 2001: uplift at "
                               "g tan(alpha)(1 + 2q)) or elastic-brittle anchors")
    anchor_stiffness: float = option(
        100.0, lo=0.0, hi=1e9, unit="",
        help="elastic anchors: kappa = k_a 2b/(m g), the anchor force (fraction of m g) "
             "per unit of elongation/(2b)")
    rtol: float = option(DEFAULT_RTOL, lo=1e-13, hi=1e-2, lo_open=False,
                         help="relative tolerance of the adaptive Dormand-Prince steps")
    rest_tol: float = option(DEFAULT_REST_TOL, lo=0.0, hi=1e-2,
                             help="Zeno rule: free amplitude (fraction of alpha) below "
                                  "which the block is put to rest after an impact")
    free_rest_tol: float = option(DEFAULT_FREE_REST_TOL, lo=0.0, hi=1.0,
                                  help="Zeno rule once the ground is still (fraction of "
                                       "alpha)")


class Anchored(Model):
    """A block anchored at its base corners, brittle anchors (module docstring)."""

    mitigation = True
    name = "anchored"
    label = "anchored block"
    Options = AnchoredOptions
    kernel = kernel
    batch_kernel = batch_kernel
    row_outputs = (
        RowOutput("max_anchor_force", "", False,
                  "largest anchor force, as a fraction of the block's weight m g"),
        RowOutput("anchor_break_time_plus", "s", False,
                  "when the + anchor (stretched by theta > 0) broke (NaN: intact)"),
        RowOutput("anchor_break_time_minus", "s", False,
                  "when the - anchor broke (NaN: intact)"),
        RowOutput("anchor_broken_plus", "", True, "the + anchor broke"),
        RowOutput("anchor_broken_minus", "", True, "the - anchor broke"),
    )

    @classmethod
    def block_row(cls, block) -> tuple:
        return (block.alpha, block.p, block.mu)

    def kernel_params(self, dt_out, theta0, omega0) -> tuple:
        b, o = self.block, self.options
        return (b.alpha, b.p, b.mu, o.anchor_strength, o.anchor_stiffness,
                o.anchors == "rigid", o.rtol, o.rest_tol, o.free_rest_tol)

    def extra_fields(self, n_out: int, extra: tuple, dt_out: float) -> dict:
        a = extra[0]
        mass = getattr(self.block, "mass", None)
        return {"info": {
            **row_output_values(self.row_outputs, a),
            "max_anchor_force_n": math.nan if mass is None else float(a[0] * mass * G),
            "anchor_broken": [bool(a[3]), bool(a[4])],
            "anchor_break_time": [float(a[1]), float(a[2])]}}
