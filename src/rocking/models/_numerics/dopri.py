"""Compiled building blocks shared by the model kernels: a Dormand-Prince 5(4) step for a
second-order scalar equation ``theta'' = f(t, theta)``, its step-size control, quintic
Hermite interpolation, and the location of crossings (impact ``theta = 0``, overturning
``|theta| = pi/2``, a level of ``theta``) inside a step, with the output and peak of a
segment.

Kept model-agnostic: the right-hand side is passed in as a compiled function ``acc`` with
its arguments ``args`` (``acc(theta, t, *args)``). The helpers that take ``acc`` are
``inline="always"``: inlined, the call is resolved at compile time, whereas a compiled
function passed on as a run-time value would keep its address in the machine code and
numba would refuse to cache the kernel ("dynamic globals").
"""

from __future__ import annotations

import math

from numba import njit

HALF_PI = 0.5 * math.pi

# Dormand-Prince 5(4) tableau (Hairer, Norsett & Wanner, Table II.5.2)
C2, C3, C4, C5 = 1 / 5, 3 / 10, 4 / 5, 8 / 9
A21 = 1 / 5
A31, A32 = 3 / 40, 9 / 40
A41, A42, A43 = 44 / 45, -56 / 15, 32 / 9
A51, A52, A53, A54 = 19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729
A61, A62, A63, A64, A65 = 9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656
B1, B3, B4, B5, B6 = 35 / 384, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84
E1, E3, E4, E5, E6, E7 = (71 / 57600, -71 / 16695, 71 / 1920, -17253 / 339200, 22 / 525,
                          -1 / 40)


@njit(cache=True)
def hermite5(th0, om0, a0, th1, om1, a1, h, x):
    """Quintic Hermite interpolant on a step of length ``h`` at ``x`` in [0, 1].

    Matches angle, velocity and acceleration at both ends; returns ``(theta, omega)``.
    """
    x2 = x * x
    x3 = x2 * x
    x4 = x3 * x
    x5 = x4 * x
    H0 = 1.0 - 10.0 * x3 + 15.0 * x4 - 6.0 * x5
    H1 = x - 6.0 * x3 + 8.0 * x4 - 3.0 * x5
    H2 = 0.5 * x2 - 1.5 * x3 + 1.5 * x4 - 0.5 * x5
    H3 = 0.5 * x3 - x4 + 0.5 * x5
    H4 = -4.0 * x3 + 7.0 * x4 - 3.0 * x5
    H5 = 10.0 * x3 - 15.0 * x4 + 6.0 * x5
    D0 = -30.0 * x2 + 60.0 * x3 - 30.0 * x4
    D1 = 1.0 - 18.0 * x2 + 32.0 * x3 - 15.0 * x4
    D2 = x - 4.5 * x2 + 6.0 * x3 - 2.5 * x4
    D3 = 1.5 * x2 - 4.0 * x3 + 2.5 * x4
    D4 = -12.0 * x2 + 28.0 * x3 - 15.0 * x4
    D5 = 30.0 * x2 - 60.0 * x3 + 30.0 * x4
    hh = h * h
    th = th0 * H0 + h * om0 * H1 + hh * a0 * H2 + hh * a1 * H3 + h * om1 * H4 + th1 * H5
    dth = th0 * D0 + h * om0 * D1 + hh * a0 * D2 + hh * a1 * D3 + h * om1 * D4 + th1 * D5
    return th, dth / h


@njit(cache=True)
def hermite_root(th0, om0, a0, th1, om1, a1, h, target, which, sgn_lo):
    """Bisection for ``x`` in [0, 1] where the interpolated angle (which=0) or velocity
    (which=1) equals ``target``. ``sgn_lo`` (+1 or -1) is the sign of (value - target) just
    after x = 0, so that a root *at* x = 0 (e.g. right after an impact) is not returned."""
    lo, hi = 0.0, 1.0
    for _ in range(52):
        mid = 0.5 * (lo + hi)
        fm = hermite5(th0, om0, a0, th1, om1, a1, h, mid)[which] - target
        if fm != 0.0 and (fm > 0.0) == (sgn_lo > 0.0):
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-15:
            break
    return 0.5 * (lo + hi)


@njit(cache=True)
def sign_changes(th0, om0, a0, th1, om1, a1, h, s):
    """Number of sign changes of ``s * theta`` over the step, seen at x = 0, 1/4, ..., 1
    (``theta(0)`` counts as on side ``s``): 2 or more means a missed double crossing."""
    n = 0
    prev = True
    for j in range(1, 5):
        th = hermite5(th0, om0, a0, th1, om1, a1, h, 0.25 * j)[0]
        cur = s * th >= 0.0
        if cur != prev:
            n += 1
        prev = cur
    return n


@njit(cache=True)
def may_hide_crossing(th0, om0, a0, th1, om1, a1, h, s):
    """Whether ``s theta``, positive at both ends of the step, can reach 0 inside it: it
    must travel ``s th0`` down and ``s th1`` up again within ``h`` at a speed of at most
    ``|om| + h |theta''|`` (generous bounds from both ends), else no check is needed."""
    reach = h * (abs(om0) + abs(om1)) + 2.0 * h * h * (abs(a0) + abs(a1))
    return s * th0 + s * th1 < 2.0 * reach


@njit(cache=True)
def velocity_roots(om, a0, a1, h):
    """The roots in ``(0, h)`` of ``om + a0 tau + (a1 - a0) tau^2 / (2 h)``, the velocity
    over a step whose acceleration goes linearly from ``a0`` to ``a1`` (-1.0 for none):
    where the angle may turn inside the step."""
    c = 0.5 * (a1 - a0) / h
    r1 = -1.0
    r2 = -1.0
    if c == 0.0:
        if a0 != 0.0:
            r1 = -om / a0
    else:
        d = a0 * a0 - 4.0 * c * om
        if d >= 0.0:
            q = -0.5 * (a0 + math.copysign(math.sqrt(d), a0))
            if q != 0.0:
                r1 = q / c
                r2 = om / q
            else:
                r1 = 0.0
    if not (0.0 < r1 < h):
        r1 = -1.0
    if not (0.0 < r2 < h):
        r2 = -1.0
    return r1, r2


@njit(cache=True)
def dips_below(th0, om0, a0, th1, om1, a1, h, s):
    """Whether ``s theta`` (>= 0 at both ends of the step) has a minimum inside the step
    below 0, on the quintic Hermite interpolant: the angle turns where the velocity
    vanishes, and the acceleration is nearly linear over a step where a crossing can hide
    (the angle is small and the ground acceleration linear between samples), so those
    times are the roots of a quadratic (:func:`velocity_roots`); at a minimum (the
    acceleration of sign ``s``) the interpolant's ``s theta < 0`` means a hidden
    crossing. Dips shorter than a quarter of the step escape :func:`sign_changes`: seen
    on a 20 s record with 10 ms fixed steps (``method="taylor"``), two impacts 53 us
    apart at ``|theta| ~ 1e-7``, missed, and the run went on 23 % off in ``max |theta|``."""
    r1, r2 = velocity_roots(om0, a0, a1, h)
    for r in (r1, r2):
        if r > 0.0 and s * (a0 + (a1 - a0) * r / h) > 0.0:
            if s * hermite5(th0, om0, a0, th1, om1, a1, h, r / h)[0] < 0.0:
                return True
    return False


@njit(cache=True)
def abs_tols(rtol, alpha, p):
    """Absolute tolerances ``(angle, velocity)`` of the error norm for a block of
    slenderness ``alpha`` and frequency parameter ``p``: ``1e-3 rtol alpha``, times ``p``."""
    atol_th = rtol * alpha * 1e-3
    return atol_th, atol_th * p


@njit(cache=True)
def err_norm(e_th, e_om, th0, th1, om0, om1, atol_th, atol_om, rtol):
    """RMS of the scaled error estimates (the usual mixed absolute/relative norm)."""
    s1 = atol_th + rtol * max(abs(th0), abs(th1))
    s2 = atol_om + rtol * max(abs(om0), abs(om1))
    return math.sqrt(0.5 * ((e_th / s1) ** 2 + (e_om / s2) ** 2))


@njit(cache=True, inline="always")
def step(acc, t, th, om, a1, h, args):
    """One Dormand-Prince step of ``theta'' = acc(theta, t, *args)`` from ``(th, om)`` at
    ``t``, with ``a1`` the acceleration there (first same as last); returns
    ``(theta, omega, acc_end, err_theta, err_omega)``."""
    k1t, k1o = om, a1
    k2t = om + h * A21 * k1o
    k2o = acc(th + h * A21 * k1t, t + C2 * h, *args)
    k3t = om + h * (A31 * k1o + A32 * k2o)
    k3o = acc(th + h * (A31 * k1t + A32 * k2t), t + C3 * h, *args)
    k4t = om + h * (A41 * k1o + A42 * k2o + A43 * k3o)
    k4o = acc(th + h * (A41 * k1t + A42 * k2t + A43 * k3t), t + C4 * h, *args)
    k5t = om + h * (A51 * k1o + A52 * k2o + A53 * k3o + A54 * k4o)
    k5o = acc(th + h * (A51 * k1t + A52 * k2t + A53 * k3t + A54 * k4t), t + C5 * h, *args)
    k6t = om + h * (A61 * k1o + A62 * k2o + A63 * k3o + A64 * k4o + A65 * k5o)
    k6o = acc(th + h * (A61 * k1t + A62 * k2t + A63 * k3t + A64 * k4t + A65 * k5t), t + h,
              *args)
    th1 = th + h * (B1 * k1t + B3 * k3t + B4 * k4t + B5 * k5t + B6 * k6t)
    om1 = om + h * (B1 * k1o + B3 * k3o + B4 * k4o + B5 * k5o + B6 * k6o)
    k7o = acc(th1, t + h, *args)
    k7t = om1
    et = h * (E1 * k1t + E3 * k3t + E4 * k4t + E5 * k5t + E6 * k6t + E7 * k7t)
    eo = h * (E1 * k1o + E3 * k3o + E4 * k4o + E5 * k5o + E6 * k6o + E7 * k7o)
    return th1, om1, k7o, et, eo


@njit(cache=True, inline="always")
def advance(acc, args, t, th, om, a0, h):
    """The end ``(theta, omega, acc)`` of the Dormand-Prince step of length ``h`` from ``t``
    (:func:`step` without its error estimates): the one-step map :func:`newton_locate`
    iterates on."""
    thc, omc, ac, _e1, _e2 = step(acc, t, th, om, a0, h, args)
    return thc, omc, ac


@njit(cache=True, inline="always")
def newton_locate(adv, p, args, t, th, om, a0, x, h, s, level, rising, tol, iters, th1, om1,
                  a1):
    """Where ``g = s theta - level`` reaches 0 inside the step ``(t, th, om, a0) -> (th1,
    om1, a1)`` of length ``h`` (``rising``: g goes from < 0 to >= 0, else from > 0 to <= 0):
    safeguarded Newton on the step's length, from ``x h`` (an interpolant's estimate), with
    the one-step map ``adv(p, args, t, theta, omega, acc0, length) -> (theta, omega,
    acc)``, at most ``iters`` steps, until ``|g| <= tol`` or the bracket is 1e-15 (1 + t)
    wide. Returns ``(length, theta, omega, acc)`` there. Shared by the adaptive steps
    (:func:`locate`, with :func:`advance`) and the fixed ones
    (:func:`rocking.models._numerics.fixed.locate`, with the model's map)."""
    lo, hi = 0.0, h
    sig = x * h
    thc, omc, ac = th1, om1, a1
    for _ in range(iters):
        thc, omc, ac = adv(p, args, t, th, om, a0, sig)
        g = s * thc - level
        past = g >= 0.0 if rising else not (g > 0.0)
        if past:
            hi = sig
        else:
            lo = sig
        if abs(g) <= tol or hi - lo <= 1e-15 * (1.0 + t):
            break
        new = sig - g / (s * omc) if omc != 0.0 else -1.0
        if not (lo < new < hi):
            new = 0.5 * (lo + hi)
        sig = new
    return sig, thc, omc, ac


@njit(cache=True, inline="always")
def locate(acc, args, t, th, om, a0, th1, om1, a1, h, s, level, rising, tol, iters):
    """Where ``g = s theta - level`` reaches 0 inside the step ``(t, th, om, a0) -> (th1,
    om1, a1)`` of length ``h``: :func:`newton_locate` on the length of the Dormand-Prince
    step (:func:`advance`) from the Hermite estimate (:func:`hermite_root`). Returns
    ``(length, theta, omega, acc)`` there."""
    x = hermite_root(th, om, a0, th1, om1, a1, h, s * level, 0, -s if rising else s)
    return newton_locate(advance, acc, args, t, th, om, a0, x, h, s, level, rising, tol,
                         iters, th1, om1, a1)


@njit(cache=True)
def emit(t0, th0, om0, a0, t1, th1, om1, a1, dt_out, k, out_th, out_om):
    """Write output samples k*dt_out in (t0, t1] by Hermite interpolation; returns next k."""
    n = out_th.shape[0]
    h = t1 - t0
    while k < n and k * dt_out <= t1 + 1e-12:
        tk = k * dt_out
        if h > 0.0:
            x = min(max((tk - t0) / h, 0.0), 1.0)
            th, om = hermite5(th0, om0, a0, th1, om1, a1, h, x)
        else:
            th, om = th1, om1
        out_th[k] = th
        out_om[k] = om
        k += 1
    return k


@njit(cache=True)
def seg_peak(th0, om0, a0, th1, om1, a1, h, peak):
    """``max(peak, |theta|)`` over a segment: its end and its interior extremum, if any."""
    peak = max(peak, abs(th1))
    if om0 * om1 < 0.0 and h > 0.0:
        x = hermite_root(th0, om0, a0, th1, om1, a1, h, 0.0, 1, om0)
        peak = max(peak, abs(hermite5(th0, om0, a0, th1, om1, a1, h, x)[0]))
    return peak


@njit(cache=True, inline="always")
def trial(acc, args, t, th, om, a0, h, h_max, t_end, bp, s, atol_th, atol_om, rtol):
    """One trial step from ``t`` of length ``hh = min(h, h_max, t_end - t)``, shortened onto
    the breakpoint ``bp`` of the excitation when it reaches it (``hit_bp``). Returns ``(hh,
    hit_bp, theta, omega, acc_end, ok, h_next)``: ``ok`` False if the error is too large or
    the step hides two crossings of ``theta = 0`` on branch ``s`` (``h_next``: the length to
    retry with), else ``h_next`` is the proposal for the next step (a step cut short by a
    breakpoint keeps the proposal ``h``)."""
    hh = min(h, h_max, t_end - t)
    hit_bp = False
    if t + hh >= bp - 1e-12:
        hh = bp - t
        hit_bp = True
    th1, om1, a1, et, eo = step(acc, t, th, om, a0, hh, args)
    err = err_norm(et, eo, th, th1, om, om1, atol_th, atol_om, rtol)
    if not (err <= 1.0):
        fac = 0.9 * err ** -0.2 if err == err else 0.1
        return hh, hit_bp, th1, om1, a1, False, hh * max(0.1, fac)
    if sign_changes(th, om, a0, th1, om1, a1, hh, s) >= 2 or (
            s * th1 >= 0.0 and hh > 1e-9 * h_max  # (the halving must end)
            and may_hide_crossing(th, om, a0, th1, om1, a1, hh, s)
            and dips_below(th, om, a0, th1, om1, a1, hh, s)):
        return hh, hit_bp, th1, om1, a1, False, 0.5 * hh
    fac = 0.9 * err ** -0.2 if err > 0.0 else 5.0
    h_next = hh * min(5.0, max(0.2, fac)) if not hit_bp or hh >= h else max(h, hh)
    return hh, hit_bp, th1, om1, a1, True, h_next


@njit(cache=True)
def rebound_length(hh, h_min, h_max, om, a):
    """The first step after an impact (velocity ``om``, acceleration ``a``): the rebound
    lasts ``2 |om/a|`` when ``a`` pulls back, and the step must not jump over it."""
    h = min(h_max, max(hh, h_min))
    if om * a < 0.0:
        h = min(h, 0.5 * abs(om / a))
    return h


@njit(cache=True)
def segment(t0, th0, om0, a0, t1, th1, om1, a1, h, dt_out, k, out_th, out_om, peak):
    """A segment of length ``h`` from ``t0`` to ``t1`` is done: its output samples
    (:func:`emit`, none if ``out_th`` is empty) and ``max(peak, |theta|)`` over it
    (:func:`seg_peak`). Returns ``(k, peak)``."""
    if out_th.shape[0] > 0:
        k = emit(t0, th0, om0, a0, t1, th1, om1, a1, dt_out, k, out_th, out_om)
    return k, seg_peak(th0, om0, a0, th1, om1, a1, h, peak)


@njit(cache=True, inline="always")
def stop_inside(acc, args, t, th, om, a0, tc, s, dt_out, k, out_th, out_om, peak):
    """The state at ``tc`` inside a step from ``t``, where the run stops (lift-off) if the
    block is still on branch ``s`` and below ``pi/2`` there (else an event comes first):
    returns ``(stops, theta, omega, k, peak)`` (:func:`segment` up to ``tc`` if it stops)."""
    thc, omc, ac, _e1, _e2 = step(acc, t, th, om, a0, tc - t, args)
    if not (s * thc >= 0.0 and abs(thc) < HALF_PI):
        return False, thc, omc, k, peak
    k, peak = segment(t, th, om, a0, tc, thc, omc, ac, tc - t, dt_out, k, out_th, out_om,
                      peak)
    return True, thc, omc, k, peak


@njit(cache=True, inline="always")
def impact(acc, args, t, th, om, a0, th1, om1, a1, h, s, tol, dt_out, k, out_th, out_om,
           peak, imp, n_imp):
    """The impact (``s theta`` falls to 0) inside the step: located by :func:`locate`
    (``|theta| <= tol``), :func:`segment` up to it, its time stored in ``imp`` (up to its
    length). Returns ``(t_impact, length, omega_before, k, peak, n_imp + 1)``."""
    sig, thc, omc, ac = locate(acc, args, t, th, om, a0, th1, om1, a1, h, s, 0.0, False, tol,
                               40)
    tc = t + sig
    k, peak = segment(t, th, om, a0, tc, 0.0, omc, ac, sig, dt_out, k, out_th, out_om, peak)
    if n_imp < imp.shape[0]:
        imp[n_imp] = tc
    return tc, sig, omc, k, peak, n_imp + 1


@njit(cache=True)
def overturn(t, th, om, a0, th1, om1, a1, h, s, dt_out, k, out_th, out_om):
    """The block reaches ``|theta| = pi/2`` inside the step: returns ``(t_over, k)`` (the
    output up to it)."""
    x = hermite_root(th, om, a0, th1, om1, a1, h, s * HALF_PI, 0, -s)
    t_over = t + x * h
    thx, omx = hermite5(th, om, a0, th1, om1, a1, h, x)
    if out_th.shape[0] > 0:
        k = emit(t, th, om, a0, t_over, s * HALF_PI, omx, a1, dt_out, k, out_th, out_om)
    return t_over, k


# The stepper of the shared step loop (:func:`.loop.run`): the adaptive steps above under
# the loop's uniform signatures (``mp`` is not used), with
# :func:`segment` and :func:`rebound_length`. Their arithmetic is that of the functions
# they call.

@njit(cache=True, inline="always")
def loop_trial(acc, mp, args, t, th, om, a0, h, h_max, t_end, bp, s, atol_th, atol_om, rtol):
    """:func:`trial` in the loop's signature."""
    return trial(acc, args, t, th, om, a0, h, h_max, t_end, bp, s, atol_th, atol_om, rtol)


@njit(cache=True, inline="always")
def loop_stop_inside(acc, mp, args, t, th, om, a0, tc, s, dt_out, k, out_th, out_om,
                     peak):
    """:func:`stop_inside` in the loop's signature."""
    return stop_inside(acc, args, t, th, om, a0, tc, s, dt_out, k, out_th, out_om, peak)


@njit(cache=True, inline="always")
def loop_impact(acc, mp, args, t, th, om, a0, th1, om1, a1, h, s, tol, dt_out, k,
                out_th, out_om, peak, imp, n_imp):
    """:func:`impact` in the loop's signature."""
    return impact(acc, args, t, th, om, a0, th1, om1, a1, h, s, tol, dt_out, k, out_th,
                  out_om, peak, imp, n_imp)
