r"""Fixed steps with a model's own one-step map: a stepper of the shared step loop
(:func:`rocking.models._numerics.loop.run`), the classical model's ``method="taylor"``
(:func:`rocking.models.housner.taylor_step`; the model wraps :func:`trial`,
:func:`stop_inside` and :func:`impact` in functions that name its map, and passes them
with :func:`segment` and :func:`rebound_length`).

The model gives ``fstep(mp, args, t, theta, omega, acc0, h) -> (theta, omega, acc_end)``,
a one-step map accurate enough to need no error control. The loop steps from breakpoint
to breakpoint of the excitation (every sample of a record) in steps of at most ``h_max``,
shorter only to resolve two crossings of ``theta = 0`` hidden in a step (after an impact
a step goes over the rebound whole: its return is an impact located inside it). Events
(impact, lift-off) are located by safeguarded Newton iteration on the length of the step,
as with Dormand-Prince (:mod:`.dopri`), so the impact velocity is that of the one-step
map (which may keep its last polynomial to answer these shorter steps from the same
start: :func:`rocking.models.housner.taylor_step`). Peaks and output samples come from
the quintic Hermite interpolant of the step's ends (:func:`segment`), its roots by Newton
or secant iteration (:func:`hermite_root`).

A fixed 4th-order Runge-Kutta-Nystrom step (3 evaluations) was tried first and dropped:
on 20 s records at one step per 0.01 s sample its error in ``max |theta|`` was 1e-3 to
17 % (converging as ``h^4``), because rocking amplifies a local error at every impact;
the adaptive Dormand-Prince steps (7 evaluations) reach 1e-8.
"""

from __future__ import annotations

from numba import njit

from . import dopri as D


@njit(cache=True)
def hermite_root(th0, om0, a0, th1, om1, a1, h, target, which, sgn_lo):
    """:func:`.dopri.hermite_root` by safeguarded Newton (angle, ``which=0``: its derivative
    is the interpolated velocity) or secant (velocity, ``which=1``) iteration inside the
    bracket, in a handful of evaluations instead of 52 bisections. ``sgn_lo``: the sign
    of (value - target) just after ``x = 0`` (a root *at* 0 is not returned); 1 if the
    value keeps that sign at ``x = 1``."""
    g1 = D.hermite5(th0, om0, a0, th1, om1, a1, h, 1.0)[which] - target
    if g1 != 0.0 and (g1 > 0.0) == (sgn_lo > 0.0):
        return 1.0
    lo, hi = 0.0, 1.0
    g0 = D.hermite5(th0, om0, a0, th1, om1, a1, h, 0.0)[which] - target
    # secant through the ends (from x = 0 only if the value there is not the root)
    x = g0 / (g0 - g1) if g0 != 0.0 and (g0 > 0.0) == (sgn_lo > 0.0) else 0.5
    if not (0.0 < x < 1.0):
        x = 0.5
    xp, gp = 1.0, g1
    for _ in range(60):
        th, om = D.hermite5(th0, om0, a0, th1, om1, a1, h, x)
        g = (th if which == 0 else om) - target
        if g != 0.0 and (g > 0.0) == (sgn_lo > 0.0):
            lo = x
        else:
            hi = x
        if g == 0.0 or hi - lo < 1e-15:
            break
        if which == 0:
            new = x - g / (om * h) if om != 0.0 else -1.0
        else:
            new = x - g * (x - xp) / (g - gp) if g != gp else -1.0
        if not (lo < new < hi):
            new = 0.5 * (lo + hi)
        if abs(new - x) < 1e-15:
            x = new
            break
        xp, gp, x = x, g, new
    return x


@njit(cache=True)
def seg_peak(th0, om0, a0, th1, om1, a1, h, peak):
    """:func:`.dopri.seg_peak` with :func:`hermite_root`."""
    peak = max(peak, abs(th1))
    if om0 * om1 < 0.0 and h > 0.0:
        x = hermite_root(th0, om0, a0, th1, om1, a1, h, 0.0, 1, om0)
        peak = max(peak, abs(D.hermite5(th0, om0, a0, th1, om1, a1, h, x)[0]))
    return peak


@njit(cache=True)
def segment(t0, th0, om0, a0, t1, th1, om1, a1, h, dt_out, k, out_th, out_om, peak):
    """:func:`.dopri.segment` with :func:`seg_peak`: returns ``(k, peak)``."""
    if out_th.shape[0] > 0:
        k = D.emit(t0, th0, om0, a0, t1, th1, om1, a1, dt_out, k, out_th, out_om)
    return k, seg_peak(th0, om0, a0, th1, om1, a1, h, peak)


@njit(cache=True, inline="always")
def trial(fstep, mp, args, t, th, om, a0, h, h_max, t_end, bp, s):
    """One step from ``t`` of length ``hh = min(h, h_max, t_end - t)``, shortened onto the
    breakpoint ``bp`` (``hit_bp``). Returns ``(hh, hit_bp, theta, omega, acc_end, ok,
    h_next)`` like :func:`.dopri.trial`: ``ok`` False only if the step hides two crossings
    of ``theta = 0`` on branch ``s`` (retry with half the length, down to ``1e-9 h_max``:
    a crossing hidden in a shorter step is immaterial, and the halving must end);
    ``h_next`` is ``h_max`` (the next breakpoint shortens it)."""
    hh = min(h, h_max, t_end - t)
    hit_bp = False
    if t + hh >= bp - 1e-12:
        hh = bp - t
        hit_bp = True
    th1, om1, a1 = fstep(mp, args, t, th, om, a0, hh)
    if (s * th1 >= 0.0 and hh > 1e-9 * h_max
            and D.may_hide_crossing(th, om, a0, th1, om1, a1, hh, s)):
        if (D.sign_changes(th, om, a0, th1, om1, a1, hh, s) >= 2
                or D.dips_below(th, om, a0, th1, om1, a1, hh, s)):
            return hh, hit_bp, th1, om1, a1, False, 0.5 * hh
    return hh, hit_bp, th1, om1, a1, True, h_max


@njit(cache=True, inline="always")
def locate(fstep, mp, args, t, th, om, a0, th1, om1, a1, h, s, level, rising, tol, iters):
    """:func:`.dopri.locate` with the model's step: where ``s theta - level`` reaches 0
    inside the step, by :func:`.dopri.newton_locate` on the model's one-step map from the
    Hermite estimate (:func:`hermite_root`). Returns ``(length, theta, omega, acc)``."""
    x = hermite_root(th, om, a0, th1, om1, a1, h, s * level, 0, -s if rising else s)
    return D.newton_locate(fstep, mp, args, t, th, om, a0, x, h, s, level, rising, tol,
                           iters, th1, om1, a1)


@njit(cache=True, inline="always")
def impact(fstep, mp, args, t, th, om, a0, th1, om1, a1, h, s, tol, dt_out, k, out_th,
           out_om, peak, imp, n_imp):
    """:func:`.dopri.impact` with :func:`locate`: returns ``(t_impact, length,
    omega_before, k, peak, n_imp + 1)``."""
    sig, thc, omc, ac = locate(fstep, mp, args, t, th, om, a0, th1, om1, a1, h, s, 0.0,
                               False, tol, 40)
    tc = t + sig
    k, peak = segment(t, th, om, a0, tc, 0.0, omc, ac, sig, dt_out, k, out_th, out_om, peak)
    if n_imp < imp.shape[0]:
        imp[n_imp] = tc
    return tc, sig, omc, k, peak, n_imp + 1


@njit(cache=True, inline="always")
def stop_inside(fstep, mp, args, t, th, om, a0, tc, s, dt_out, k, out_th, out_om, peak):
    """:func:`.dopri.stop_inside` with the model's step."""
    thc, omc, ac = fstep(mp, args, t, th, om, a0, tc - t)
    if not (s * thc >= 0.0 and abs(thc) < D.HALF_PI):
        return False, thc, omc, k, peak
    k, peak = segment(t, th, om, a0, tc, thc, omc, ac, tc - t, dt_out, k, out_th, out_om,
                        peak)
    return True, thc, omc, k, peak


# The loop's ``rebound`` for fixed steps (with :func:`segment`; a model wraps
# :func:`trial`, :func:`stop_inside` and :func:`impact` naming its one-step map, as
# :mod:`rocking.models.housner` does for ``method="taylor"``).

@njit(cache=True)
def rebound_length(hh, h_min, h_max, om, a):
    """The first step after an impact: ``h_max`` (no error control, so one step over the
    rebound is as exact; its return is an impact located inside it)."""
    return h_max
