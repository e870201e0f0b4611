"""The event-driven step loop of the models whose block rocks on a fixed pivot and whose
only continuous state is ``(theta, theta')``: the classical model
(:mod:`rocking.models.housner`) and the anchored block (:mod:`rocking.models.anchored`).

One run: rest and uplift, Dormand-Prince steps (:func:`dopri.trial`), lift-off under a
vertical motion, the impact located on the step (:func:`dopri.impact`) and the Zeno rule
after it, overturning, the output and the peak of every segment, and the cap of the free
motion. What a model adds is passed in as compiled functions (numba dispatchers). The
loop and the models' functions are ``inline="always"``: they resolve at compile time
into one function, the model's own ``integrate``, which numba caches with the model's
file (as separate calls they cost 3-5 % of CPU time; a ``run`` cached on its own would
not see a change in the model's file). A function that takes the right-hand side must
name it, not receive it: a dispatcher passed on at run time to a function that is not
inlined makes the kernel uncacheable ("dynamic globals"). The functions:

* ``acc(theta, t, *args)``: the right-hand side, with ``args = rhs_args(mp, xs, s, kind,
  prm, samples)`` on pivot ``s``;
* the stepper ``trial(acc, mp, args, ...)``, ``stop_inside(acc, mp, args, ...)``,
  ``impact(acc, mp, args, ...)``, ``segment`` and ``rebound``: Dormand-Prince
  (``dopri.loop_trial, dopri.loop_stop_inside, dopri.loop_impact, dopri.segment,
  dopri.rebound_length``), or fixed steps of a model's one-step map (the model's
  wrappers of :mod:`.fixed` that name its map, with ``fixed.segment`` and
  ``fixed.rebound_length``: the classical model's ``method="taylor"``). They are
  arguments, not a runtime flag, so that numba compiles for each model only the stepper
  it is given (a flag compiled both: the classical model's first compilation went from
  24 to 44 s);
* ``start(mp, resting, s, th0) -> xs``: the model's own state (a tuple, or a dummy
  value) at ``t = 0``;
* ``rest(mp, xs, kind, prm, samples, t, t_lim, h_scan, dt_out, k, out_th, out_om, t_up)
  -> (t, k, direction, t_up, xs)``: advance a block at rest (direction 0: still at rest
  at ``t_lim``, :data:`events.LIFT_OFF`, or the side +1/-1 it uplifts towards);
* ``cap(mp, xs, th, om, s, t, free_time, peak) -> (stop, decided, peak, t_end)``: at
  the end of the run after the motion, stop (``decided``: by energy) or follow the block
  on up to the new ``t_end``;
* ``inside(args, mp, xs, t, th, om, a0, th1, om1, a1, h, s, dt_out, k, out_th, out_om)
  -> (event, t, th, om, k, peak, h, xs)``: a model's own event inside an accepted step,
  before the impact (0: none; 1: retry the step with length ``h``; 2:
  the run moved to the event: ``(t, th, om)``, the segment's peak ``peak``, next length
  ``h``);
* ``impact_tol(mp, s)``: the tolerance on ``|theta|`` of the impact located on pivot
  ``s``;
* ``after_impact(mp, xs, s, t, om_before, seg_peak, kind, prm, samples, t_quiet, hv)
  -> (rest, om, s, xs)``: the impact map and the Zeno rule (``rest``: the block is put
  to rest, on the same pivot);
* ``on_overturn(mp, xs, s) -> xs`` and ``on_segment(mp, xs, s, seg_peak) -> xs``: the
  model's bookkeeping (e.g. the anchors' largest force).

Every arithmetic operation is that of the loops it replaced (bit-identical results).
The CCRR model (Fehlberg 4(5) on ``(chi, chi', psi)``, passages instead of impacts) and
the isolated base (four states, the plate integrated while the block rests) keep their
own loops: ``docs/architecture.md``, "One step loop".
"""

from __future__ import annotations

import math

from numba import njit

from ...motions._kernel import has_vertical, next_breakpoint
from . import dopri as D
from . import events as E


@njit(cache=True, inline="always")
def run(acc, trial, stop_inside, impact, segment, rebound, rhs_args, start, rest, cap, inside,
        impact_tol, after_impact, on_overturn, on_segment, mp, kind, prm, samples, t_end,
        t_quiet, y0, tols, p_ref, h_max, h_scan, dt_out, hist, imp):
    """One run of a model given by its functions (module docstring) and parameters ``mp``,
    from ``y0 = (theta0, omega0)``, the history into ``hist = (out_th, out_om)``. The
    stepper (``trial`` ... ``rebound``): the adaptive Dormand-Prince steps under ``tols =
    (rtol, atol_th, atol_om)``, or the model's fixed steps (:mod:`.fixed`; ``tols``
    unused) of at most ``h_max`` from breakpoint to breakpoint.
    ``p_ref``: the frequency parameter of the step lengths (first step ``0.01 / p_ref``,
    at least ``1e-6 / p_ref`` after an impact). Returns ``(n_out, n_impacts,
    max_abs_theta, overturned, overturn_time, uplift_time, n_steps, lift_off_time,
    settled, xs)``. (The arguments are at most 29, and some are tuples: CPython passes a
    call of more than 30 as ``*args``, which numba cannot inline.)"""
    th0, om0 = y0
    rtol, atol_th, atol_om = tols
    out_th, out_om = hist
    hv = has_vertical(prm)
    t, th, om, peak = 0.0, th0, om0, abs(th0)
    k = n_imp = n_steps = 0
    overturned = decided = False
    t_over = t_lift = math.nan
    resting, s, t_up = E.initial_state(th0, om0)
    xs = start(mp, resting, s, th0)
    h = min(h_max, 0.01 / p_ref)
    a_cur = 0.0
    need_a = True
    free_time = t_end - t_quiet  # the cap of the free motion (when t_quiet < t_end)
    extended = False
    while True:
        if not t < t_end - 1e-12:
            if resting or overturned or t_quiet > t_end or extended:
                break
            stop, decided, peak, t_end = cap(mp, xs, th, om, s, t, free_time, peak)
            if stop:
                break
            extended = True  # it will overturn: follow it there
            continue
        if resting:
            if t >= t_quiet - 1e-12:
                break  # the ground is still: at rest for good
            t, k, d, t_up, xs = rest(mp, xs, kind, prm, samples, t, min(t_end, t_quiet),
                                     h_scan, dt_out, k, out_th, out_om, t_up)
            if d == 0.0:
                break  # at rest through min(t_end, t_quiet)
            if d == E.LIFT_OFF:
                t_lift = t
                break
            # uplift towards sign(a), with a fresh acceleration and step
            resting, s, need_a, h = False, d, True, min(h_max, 0.01 / p_ref)
            continue
        args = rhs_args(mp, xs, s, kind, prm, samples)
        if need_a:
            a_cur = acc(th, t, *args)
            need_a = False
        hh, hit_bp, th1, om1, a1, ok, h_next = trial(
            acc, mp, args, t, th, om, a_cur, h, h_max, t_end,
            next_breakpoint(kind, prm, samples, t), s, atol_th, atol_om, rtol)
        n_steps += 1
        if not ok:  # too large an error, or two crossings hidden in the step: shorter
            h = h_next
            continue
        # ---- accepted step: events
        tc = E.first_lift_off(prm, samples, t, t + hh, h_scan) if hv else math.nan
        if tc == tc:
            # the base falls away (g + a_v <= 0): the model cannot represent flight
            stops, thc, omc, k, pk = stop_inside(acc, mp, args, t, th, om, a_cur, tc, s,
                                                 dt_out, k, out_th, out_om, abs(th))
            if stops:
                t, th, om, peak, t_lift = tc, thc, omc, max(peak, pk), tc
                break
        ev, t, th, om, k, pk, h_ev, xs = inside(args, mp, xs, t, th, om, a_cur, th1, om1, a1,
                                                hh, s, dt_out, k, out_th, out_om)
        if ev != 0:
            h = h_ev
            if ev == 2:
                peak = max(peak, pk)
                need_a = True
            continue
        if s * th1 < 0.0:
            # impact inside the step: safeguarded Newton on the step length
            t, sig, omc, k, pk, n_imp = impact(acc, mp, args, t, th, om, a_cur, th1,
                                               om1, a1, hh, s, impact_tol(mp, s), dt_out, k,
                                               out_th, out_om, abs(th), imp, n_imp)
            peak = max(peak, pk)
            th = 0.0
            stays, om, s, xs = after_impact(mp, xs, s, t, omc, pk, kind, prm, samples,
                                            t_quiet, hv)
            if stays:
                resting = True
                continue
            a_cur = acc(0.0, t, *rhs_args(mp, xs, s, kind, prm, samples))
            need_a = False
            h = rebound(hh, 1e-6 / p_ref, h_max, om, a_cur)
            continue
        if abs(th1) >= D.HALF_PI:
            t_over, k = D.overturn(t, th, om, a_cur, th1, om1, a1, hh, s, dt_out, k, out_th,
                                   out_om)
            t, overturned, peak = t_over, True, D.HALF_PI
            xs = on_overturn(mp, xs, s)
            break
        k, pk = segment(t, th, om, a_cur, t + hh, th1, om1, a1, hh, dt_out, k, out_th, out_om,
                        abs(th))
        peak = max(peak, pk)
        xs = on_segment(mp, xs, s, pk)
        t = t + hh
        th, om, a_cur = th1, om1, a1
        if hit_bp:
            need_a = True  # the excitation has a kink or jump here
        h = h_next
    settled = overturned or decided or (resting and t_lift != t_lift)
    return k, n_imp, peak, overturned, t_over, t_up, n_steps, t_lift, settled, xs
