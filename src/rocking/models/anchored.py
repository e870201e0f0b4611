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

Asymmetric blocks (:meth:`rocking.Block.from_geometry`, :meth:`rocking.Block.from_mesh`;
derived in the reference's "Asymmetric blocks"): side ``s`` rocks with its own
``alpha_s``, ``p_s`` (Eq 1) and ends with its own ``mu_s`` (Eq 4, angular momentum about
the new pivot), as in the classical model; the anchors are the base width ``L = h
(tan(alpha_+) + tan(alpha_-))`` apart, so a rigid anchor ``s`` holds the block down until
``s a > g (gf tan(alpha_s) + q (tan(alpha_+) + tan(alpha_-)))`` and the elastic anchor's
moment is ``-p_s^2 kappa (L / R_s) sin(theta) cos(theta)``, ``L / R_s = cos(alpha_s)
(tan(alpha_+) + tan(alpha_-))`` (``kappa = k_a L / (m g)``). With equal sides every
operation is the symmetric one (bit-identical results).

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
from collections import namedtuple
from dataclasses import dataclass

import numpy as np
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
from ._numerics import loop as L
from .base import (
    GENERIC_OUTPUTS,
    PLANAR_OUTPUTS,
    Model,
    Output,
    option,
    row_args,
    set_planar_result,
    store_row,
)
from .housner import ClassicalTolerances, amplitude_from_energy, free_cap_sides

INV_G = 1.0 / G


@njit(cache=True)
def _thr(side, rigid, q, bp, bm, c_p, c_m, gf):
    """Uplift threshold (m/s^2) towards ``side`` with the effective gravity ``gf g``:
    ``g (gf tan(alpha_s) + q (tan(alpha_+) + tan(alpha_-)))`` with the rigid anchor ``s``
    intact (``g tan(alpha) (gf + 2 q)`` for a symmetric block), gravity's alone once it has
    broken."""
    intact = (not bp) if side > 0.0 else (not bm)
    extra = q * (c_p + c_m) * G if (rigid and intact) else 0.0
    return (c_p if side > 0.0 else c_m) * G * gf + extra


@njit(cache=True)
def _trips(kind, prm, samples, t, rigid, q, bp, bm, c_p, c_m):
    """Whether the block at rest uplifts at ``t`` (or the base falls away): returns the
    direction (+1/-1), E.LIFT_OFF, or 0."""
    gf = 1.0
    if has_vertical(prm):
        gf = 1.0 + vertical_acc(prm, samples, t) * INV_G
        if gf <= 0.0:
            return E.LIFT_OFF
    a = ground_acc(kind, prm, samples, t)
    if a > _thr(1.0, rigid, q, bp, bm, c_p, c_m, gf):
        return 1.0
    if -a > _thr(-1.0, rigid, q, bp, bm, c_p, c_m, gf):
        return -1.0
    return 0.0


@njit(cache=True)
def _hold(kind, prm, samples, t, rigid, q, bp, bm, c_p, c_m):
    """Force (fraction of m g) an intact rigid anchor carries at rest at ``t``: the moment
    balance about the pivot ``s = sgn(a)``, ``L F = m h |a| - m (g + a_v) b_s`` (``L = b_+
    + b_-`` the base width), i.e. ``F/(m g) = (|a|/(g tan(alpha_s)) - (1 + a_v/g))
    tan(alpha_s) / (tan(alpha_+) + tan(alpha_-))``, a half of the bracket for a symmetric
    block (``a_v``: the vertical ground acceleration, positive upwards)."""
    if not rigid:
        return 0.0
    a = ground_acc(kind, prm, samples, t)
    intact = (not bp) if a > 0.0 else (not bm)
    if not intact:
        return 0.0
    gf = 1.0 + vertical_acc(prm, samples, t) * INV_G if has_vertical(prm) else 1.0
    c = c_p if a > 0.0 else c_m
    return min(q, max(0.0, c / (c_p + c_m) * (abs(a) / (c * G) - gf)))


@njit(cache=True)
def _rest(kind, prm, samples, t, t_end, h_scan, rigid, q, bp, bm, c_p, c_m, dt_out, k,
          out_th, out_om, fmax):
    """Advance a block at rest to its uplift (or ``t_end``); returns
    ``(t, k, direction, fmax)`` (direction 0: still at rest at ``t_end``)."""
    while True:
        fmax = max(fmax, _hold(kind, prm, samples, t, rigid, q, bp, bm, c_p, c_m))
        d = _trips(kind, prm, samples, t, rigid, q, bp, bm, c_p, c_m)
        if d != 0.0 or t >= t_end - 1e-12:
            t_w = t - 1e-12 if d != 0.0 else t + 1e-12  # up to the uplift, or through t_end
            return t, E.rest_fill(k, t_w, dt_out, out_th, out_om), d, fmax
        t1 = min(t + h_scan, next_breakpoint(kind, prm, samples, t), t_end)
        if _trips(kind, prm, samples, t1, rigid, q, bp, bm, c_p, c_m) != 0.0:
            lo, hi = t, t1
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if not (lo < mid < hi):
                    break
                if _trips(kind, prm, samples, mid, rigid, q, bp, bm, c_p, c_m) != 0.0:
                    hi = mid
                else:
                    lo = mid
            t1 = hi
        k = E.rest_fill(k, t1 - 1e-12, dt_out, out_th, out_om)
        t = t1


@njit(cache=True)
def _acc(th, t, s, alpha, p2, ka, lr, kind, prm, samples):
    """Eq 1 on branch ``s`` (that side's ``alpha``, ``p^2``) plus the elastic anchor's
    moment (``ka``: its stiffness kappa while intact on this side, else 0; ``lr = L /
    R_s``, the base width over the distance from the pivot to the centre of mass, ``2
    sin(alpha)`` for a symmetric block)."""
    if has_vertical(prm):
        ah, av = ground_acc_hv(kind, prm, samples, t)
        a = ah * INV_G
        gf = 1.0 + av * INV_G
    else:
        a = ground_acc(kind, prm, samples, t) * INV_G
        gf = 1.0
    acc = -s * p2 * gf * math.sin(alpha - s * th) + p2 * math.cos(alpha - s * th) * a
    if ka > 0.0:
        acc -= p2 * lr * ka * math.sin(th) * math.cos(th)
    return acc


# ---- the model's part of the shared step loop (:func:`rocking.models._numerics.loop.run`);
# its parameters ``mp`` are an :data:`AnchorLoopParams`, its state
# ``xs = (bp, bm, t_break_p, t_break_m, max_force)`` (bp, bm: the anchor +, - has broken)
AnchorLoopParams = namedtuple("AnchorLoopParams", [
    "alpha", "p", "mu", "q", "kappa", "rigid", "p2", "c", "th_b", "rest_tol",
    "free_rest_tol", "alpha_m", "p_m", "mu_m", "p2_m", "c_m", "lr", "lr_m"])
"""The parameters of the anchored model's hooks in the shared step loop: the block's side
+ (``alpha``, ``p``, ``mu``, ``p^2``, ``c = tan(alpha)``), the anchors' ``q``, ``kappa``,
rigid or elastic and the angle ``th_b`` at which an elastic anchor breaks, the rest
tolerances, the side - (``alpha_m``, ...; equal for a symmetric block) and the lever
ratios ``lr``, ``lr_m`` of the elastic anchors (:func:`_acc`)."""


@njit(cache=True, inline="always")
def _ka(mp, xs, s):
    """The elastic anchor's stiffness on pivot ``s`` while it is intact, else 0."""
    intact_s = (not xs[0]) if s > 0.0 else (not xs[1])
    return mp.kappa if (intact_s and not mp.rigid) else 0.0


@njit(cache=True, inline="always")
def _rhs_args(mp, xs, s, kind, prm, samples):
    """The arguments of :func:`_acc` on pivot ``s`` (that side's parameters)."""
    if s > 0.0:
        return (s, mp.alpha, mp.p2, _ka(mp, xs, s), mp.lr, kind, prm, samples)
    return (s, mp.alpha_m, mp.p2_m, _ka(mp, xs, s), mp.lr_m, kind, prm, samples)


@njit(cache=True, inline="always")
def _start(mp, resting, s, th0):
    """Already lifted: a rigid anchor on that side has given way, an elastic one if
    stretched to its strength."""
    q, kappa, rigid = mp.q, mp.kappa, mp.rigid
    bp = bm = False
    tbp = tbm = math.nan
    fmax = 0.0
    if not resting and (rigid or q == 0.0 or kappa * math.sin(abs(th0)) >= q):
        if s > 0.0:
            bp, tbp = True, 0.0
        else:
            bm, tbm = True, 0.0
        fmax = q
    return bp, bm, tbp, tbm, fmax


@njit(cache=True, inline="always")
def _at_rest(mp, xs, kind, prm, samples, t, t_lim, h_scan, dt_out, k, out_th, out_om, t_up):
    """:func:`_rest`; at the uplift a rigid (or zero-strength) anchor on that side breaks."""
    q, rigid = mp.q, mp.rigid
    bp, bm, tbp, tbm, fmax = xs
    t, k, d, fmax = _rest(kind, prm, samples, t, t_lim, h_scan, rigid, q, bp, bm, mp.c,
                          mp.c_m, dt_out, k, out_th, out_om, fmax)
    if d != 0.0 and d != E.LIFT_OFF:
        if t_up != t_up:
            t_up = t
        if rigid or q == 0.0:
            if d > 0.0 and not bp:
                bp, tbp, fmax = True, t, q
            elif d < 0.0 and not bm:
                bm, tbm, fmax = True, t, q
    return t, k, d, t_up, (bp, bm, tbp, tbm, fmax)


@njit(cache=True, inline="always")
def _cap(mp, xs, th, om, s, t, free_time, peak):
    """The cap of the free motion: decided by energy unless an elastic anchor is intact."""
    if (not mp.rigid) and ((not xs[0]) or (not xs[1])):
        return True, False, peak, t  # an intact elastic anchor: no exact energy decision
    decided, peak, t_end = free_cap_sides(th, om, s, mp.alpha, mp.p, mp.mu, mp.alpha_m, mp.p_m,
                                          mp.mu_m, False, t, free_time, peak)
    return decided, decided, peak, t_end


@njit(cache=True, inline="always")
def _inside(args, mp, xs, t, th, om, a0, th1, om1, a1, hh, s, dt_out, k, out_th, out_om):
    """The elastic anchor of this side reaches its strength inside the step."""
    th_b = mp.th_b
    if args[3] > 0.0:
        if s * th1 < th_b and D.seg_peak(th, om, a0, th1, om1, a1, hh, abs(th)) >= th_b:
            return 1, t, th, om, k, 0.0, 0.5 * hh, xs  # crossed before an interior peak
        if s * th1 >= th_b:
            sig, thc, omc, ac = D.locate(_acc, args, t, th, om, a0, th1, om1, a1, hh, s, th_b,
                                         True, 1e-15 * args[1], 60)
            tc = t + sig
            k, pk = D.segment(t, th, om, a0, tc, thc, omc, ac, sig, dt_out, k, out_th, out_om,
                              abs(th))
            bp, bm, tbp, tbm, fmax = xs
            if s > 0.0:
                bp, tbp = True, tc
            else:
                bm, tbm = True, tc
            fmax = mp.q
            return 2, tc, thc, omc, k, pk, max(sig, 1e-6 / max(mp.p, mp.p_m)), (
                bp, bm, tbp, tbm, fmax)
    return 0, t, th, om, k, 0.0, hh, xs


@njit(cache=True, inline="always")
def _impact_tol(mp, s):
    return 1e-15 * (mp.alpha if s > 0.0 else mp.alpha_m)


@njit(cache=True, inline="always")
def _after_impact(mp, xs, s, t, omc, pk, kind, prm, samples, t_quiet, hv):
    """Eq 4 (rocking on side ``s`` ends: that side's ``mu``), the Zeno rule with the side
    it rebounds on (at rest if no intact rigid anchor lets the ground lift the block) and
    the rigid anchor of the new side breaking: ``(rest, om, s, xs)``."""
    q, kappa, rigid, c_p, c_m = mp.q, mp.kappa, mp.rigid, mp.c, mp.c_m
    bp, bm, tbp, tbm, fmax = xs
    if _ka(mp, xs, s) > 0.0:
        fmax = max(fmax, kappa * math.sin(pk))
    om = (mp.mu if s > 0.0 else mp.mu_m) * omc
    ag = ground_acc(kind, prm, samples, t)
    sn = E.rebound_side(om, ag)
    alpha, p2 = (mp.alpha, mp.p2) if sn > 0.0 else (mp.alpha_m, mp.p2_m)
    gf = 1.0 + vertical_acc(prm, samples, t) * INV_G if hv else 1.0
    rt = mp.rest_tol if t < t_quiet else max(mp.rest_tol, mp.free_rest_tol)
    if om == 0.0 or amplitude_from_energy(om, alpha, p2 * gf, False) < rt * alpha:
        if ag <= _thr(1.0, rigid, q, bp, bm, c_p, c_m, gf) and -ag <= _thr(
                -1.0, rigid, q, bp, bm, c_p, c_m, gf):
            return True, 0.0, s, (bp, bm, tbp, tbm, fmax)
    s = sn
    if rigid or q == 0.0:  # an intact rigid anchor cannot stop the block
        if s > 0.0 and not bp:
            bp, tbp, fmax = True, t, q
        elif s < 0.0 and not bm:
            bm, tbm, fmax = True, t, q
    return False, om, s, (bp, bm, tbp, tbm, fmax)


@njit(cache=True, inline="always")
def _on_overturn(mp, xs, s):
    """An intact elastic anchor at pi/2 carries kappa sin(pi/2)."""
    if _ka(mp, xs, s) > 0.0:
        return xs[0], xs[1], xs[2], xs[3], max(xs[4], mp.kappa)
    return xs


@njit(cache=True, inline="always")
def _on_segment(mp, xs, s, pk):
    """The elastic anchor's force at the segment's largest angle."""
    if _ka(mp, xs, s) > 0.0:
        return xs[0], xs[1], xs[2], xs[3], max(xs[4], mp.kappa * math.sin(min(pk, D.HALF_PI)))
    return xs


@njit(cache=True)
def lever_ratios(alpha_p, alpha_m):
    """``(L / R_+, L / R_-)``: the base width ``L = b_+ + b_- = h (tan(alpha_+) +
    tan(alpha_-))`` over each pivot's distance ``R_s = h / cos(alpha_s)`` to the centre of
    mass (one height ``h`` of a rigid body); ``2 sin(alpha)`` for a symmetric block."""
    if alpha_p == alpha_m:
        lr = 2.0 * math.sin(alpha_p)
        return lr, lr
    w = math.tan(alpha_p) + math.tan(alpha_m)
    return math.cos(alpha_p) * w, math.cos(alpha_m) * w


@njit(cache=True)
def integrate(alpha, p, mu, q, kappa, rigid, kind, prm, samples, t_end, t_quiet, th0, om0,
              rtol, rest_tol, free_rest_tol, h_max, h_scan, dt_out, out_th, out_om, imp,
              anch, alpha_m, p_m, mu_m):
    """One simulation of a block with the sides + (``alpha``, ``p``, ``mu``) and -
    (``alpha_m``, ``p_m``, ``mu_m``); ``anch`` (length >= 5, else ignored) receives ``[max
    force, t_break+, t_break-, broken+, broken-]``. Returns ``(n_out, n_impacts, peak,
    overturned, t_over, t_up, n_steps, t_lift, settled)``."""
    p2 = p * p
    p2_m = p_m * p_m
    c = math.tan(alpha)
    c_m = math.tan(alpha_m)
    lr, lr_m = lever_ratios(alpha, alpha_m)
    # the elastic anchor breaks at kappa sin|theta| = q; never before pi/2 if q >= kappa
    th_b = (math.asin(q / kappa) if q < kappa else math.inf) if not rigid else 0.0
    p_hi = max(p, p_m)  # the step sizes follow the faster side, the errors the smaller alpha
    atol_th, atol_om = D.abs_tols(rtol, min(alpha, alpha_m), p_hi)
    mp = AnchorLoopParams(alpha, p, mu, q, kappa, rigid, p2, c, th_b, rest_tol, free_rest_tol,
                          alpha_m, p_m, mu_m, p2_m, c_m, lr, lr_m)
    k, n_imp, peak, overturned, t_over, t_up, n_steps, t_lift, settled, xs = L.run(
        _acc, D.loop_trial, D.loop_stop_inside, D.loop_impact, D.segment, D.rebound_length,
        _rhs_args, _start, _at_rest, _cap, _inside, _impact_tol, _after_impact, _on_overturn,
        _on_segment, mp, kind, prm, samples, t_end, t_quiet, (th0, om0),
        (rtol, atol_th, atol_om), p_hi, h_max, h_scan, dt_out, (out_th, out_om), imp)
    bp, bm, tbp, tbm, fmax = xs
    if anch.shape[0] >= 5:
        anch[0] = fmax
        anch[1] = tbp
        anch[2] = tbm
        anch[3] = 1.0 if bp else 0.0
        anch[4] = 1.0 if bm else 0.0
    return k, n_imp, peak, overturned, t_over, t_up, n_steps, t_lift, settled


AnchoredParams = namedtuple("AnchoredParams", [
    "alpha", "p", "mu", "strength", "stiffness", "rigid", "rtol", "rest_tol", "free_rest_tol",
    "alpha_m", "p_m", "mu_m"])
"""The kernel parameters ``mp`` of the anchored block: its side + ``alpha`` (rad), ``p``
(1/s), ``mu``, the anchors (``q``, ``kappa``, rigid or elastic), the tolerances and its
side - (``alpha_m``, ``p_m``, ``mu_m``; equal for a symmetric block)."""


@njit(cache=True)
def kernel(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp, res, extra):
    """The single-run kernel of the model interface (:mod:`rocking.models.base`)."""
    p, kappa, rigid = max(mp.p, mp.p_m), mp.stiffness, mp.rigid
    h_max = min(0.05 / p, 8.0 * h_scan)
    if not rigid:
        h_max = min(h_max, 0.05 / (p * math.sqrt(1.0 + kappa)))
    anch = np.full(5, np.nan)
    k, n_imp, peak, over, t_over, t_up, n_steps, t_lift, settled = integrate(
        mp.alpha, mp.p, mp.mu, mp.strength, kappa, rigid, kind, prm, samples, t_end, t_quiet,
        y0[0], y0[1], mp.rtol, mp.rest_tol, mp.free_rest_tol, h_max, h_scan, dt_out,
        hist[:, 0], hist[:, 1], imp, anch, mp.alpha_m, mp.p_m, mp.mu_m)
    set_planar_result(res, k, n_imp, peak, over, t_over, t_up, n_steps, 0, t_lift, settled)
    res.max_anchor_force = anch[0]
    res.anchor_break_time_plus = anch[1]
    res.anchor_break_time_minus = anch[2]
    res.anchor_broken_plus = anch[3] == 1.0
    res.anchor_broken_minus = anch[4] == 1.0


@njit(cache=True)
def with_block(mp, b):
    """``mp`` with the block parameters ``b = (alpha_+, p_+, mu_+, alpha_-, p_-, mu_-)`` of
    a batch row."""
    return AnchoredParams(b[0], b[1], b[2], mp.strength, mp.stiffness, mp.rigid, mp.rtol,
                          mp.rest_tol, mp.free_rest_tol, b[3], b[4], b[5])


@njit(cache=True, parallel=True)
def batch_kernel(mp, extra0, rows, blocks):
    """The batch kernel: the kernel over the rows of :func:`rocking.models.base.row_args`."""
    for i in prange(rows.kinds.shape[0]):
        kernel(with_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
        store_row(i, rows)


# ------------------------------------------------------------------------------- the model
@dataclass(frozen=True)
class AnchoredOptions(ClassicalTolerances):
    """Options of the anchored block (after those of the classical integration)."""

    anchor_strength: float = option(
        0.5, lo=0.0, hi=1e3, lo_open=False, quantity="ratio", unit="",
        help="tensile strength of each anchor as a fraction of the block's weight, "
             "q = F_a/(m g)")
    anchors: str = option("rigid", choices=("rigid", "elastic"),
                          help="rigid-brittle (Makris and Zhang 2001: uplift at "
                               "g tan(alpha)(1 + 2q)) or elastic-brittle anchors")
    anchor_stiffness: float = option(
        100.0, lo=0.0, hi=1e9, unit="",
        help="elastic anchors: kappa = k_a 2b/(m g), the anchor force (fraction of m g) "
             "per unit of elongation/(2b)")


class Anchored(Model):
    """A block anchored at its base corners, brittle anchors (module docstring)."""

    mitigation = True
    name = "anchored"
    label = "anchored block"
    Options = AnchoredOptions
    kernel = kernel
    batch_kernel = batch_kernel
    outputs = GENERIC_OUTPUTS + PLANAR_OUTPUTS + (
        Output("max_anchor_force", "", False,
               "largest anchor force, as a fraction of the block's weight m g"),
        Output("anchor_break_time_plus", "s", False,
               "when the + anchor (stretched by theta > 0) broke (NaN: intact)"),
        Output("anchor_break_time_minus", "s", False,
               "when the - anchor broke (NaN: intact)"),
        Output("anchor_broken_plus", "", True, "the + anchor broke"),
        Output("anchor_broken_minus", "", True, "the - anchor broke"),
    )

    accepts_asymmetric = True

    @classmethod
    def block_row(cls, block) -> tuple:
        """Both sides: ``(alpha_+, p_+, mu_+, alpha_-, p_-, mu_-)``."""
        return (block.alpha_plus, block.p_plus, block.mu_plus, block.alpha_minus,
                block.p_minus, block.mu_minus)

    def kernel_params(self, dt_out, theta0, omega0) -> tuple:
        b, o = self.block, self.options
        return AnchoredParams(b.alpha_plus, b.p_plus, b.mu_plus, o.anchor_strength,
                              o.anchor_stiffness, o.anchors == "rigid", o.rtol, o.rest_tol,
                              o.free_rest_tol, b.alpha_minus, b.p_minus, b.mu_minus)

    def result_info(self, values: dict) -> dict:
        """The row outputs, and the anchor force in N (with the block's mass), the broken
        flags and break times as ``[+, -]`` pairs."""
        mass = getattr(self.block, "mass", None)
        return {**super().result_info(values),
                "max_anchor_force_n": (math.nan if mass is None
                                       else float(values["max_anchor_force"] * mass * G)),
                "anchor_broken": [values["anchor_broken_plus"], values["anchor_broken_minus"]],
                "anchor_break_time": [values["anchor_break_time_plus"],
                                      values["anchor_break_time_minus"]]}
