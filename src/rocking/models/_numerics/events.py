"""Compiled event helpers shared by the model kernels (rest and uplift)."""

from __future__ import annotations

import math

from numba import njit

from ...motions._kernel import (
    ground_acc,
    has_vertical,
    next_breakpoint,
    vertical_acc,
    vertical_is_record,
)
from ...units import G

LIFT_OFF = 2.0
"""``direction`` of :func:`rest_advance` when the base falls faster than gravity."""


@njit(cache=True)
def threshold(thr, c, prm, samples, t):
    """The uplift threshold at ``t``: ``thr`` (= ``c g``) without a vertical component,
    ``c (g + a_v(t))`` with one (``c`` = tan(alpha), or alpha for the linear form)."""
    if not has_vertical(prm):
        return thr
    return c * (G + vertical_acc(prm, samples, t))


@njit(cache=True)
def threshold_sides(ag, thr_p, c_p, thr_m, c_m, prm, samples, t):
    """:func:`threshold` of the side towards which the ground acceleration ``ag`` would
    uplift a block at rest: side + (``thr_p``, ``c_p``) if ``ag > 0``, else side -
    (asymmetric blocks; equal sides give :func:`threshold` exactly)."""
    if ag > 0.0:
        return threshold(thr_p, c_p, prm, samples, t)
    return threshold(thr_m, c_m, prm, samples, t)


@njit(cache=True)
def lifts_off(prm, samples, t):
    """Whether the base accelerates downwards at least as fast as gravity at ``t``
    (``g + a_v <= 0``): the block leaves the ground."""
    return has_vertical(prm) and G + vertical_acc(prm, samples, t) <= 0.0


@njit(cache=True)
def _trips(kind, prm, samples, t, thr_p, c_p, thr_m, c_m):
    """Uplift (``a_h > c_p (g + a_v)`` towards +, ``-a_h > c_m (g + a_v)`` towards -) or
    lift-off (``g + a_v <= 0``) at ``t``. With equal sides the comparisons are those of
    ``|a_h| > c (g + a_v)`` exactly (``|a| = a`` for ``a > 0``, ``-a`` otherwise)."""
    if not has_vertical(prm):
        a = ground_acc(kind, prm, samples, t)
        return a > thr_p if a > 0.0 else -a > thr_m
    ge = G + vertical_acc(prm, samples, t)
    if ge <= 0.0:
        return True
    a = ground_acc(kind, prm, samples, t)
    return a > c_p * ge if a > 0.0 else -a > c_m * ge


@njit(cache=True)
def lift_off_time(prm, samples, t0, t1):
    """First time in ``(t0, t1]`` with ``g + a_v <= 0`` (bisection; ``t1`` lifts off)."""
    lo, hi = t0, t1
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if lifts_off(prm, samples, mid):
            hi = mid
        else:
            lo = mid
        if hi - lo < 1e-13:
            break
    return hi


@njit(cache=True)
def first_lift_off(prm, samples, t0, t1, h_scan):
    """First time in ``(t0, t1]`` with ``g + a_v <= 0``, NaN if none. A vertical record is
    linear between its samples, which are breakpoints of every step: its value at ``t1``
    decides. An analytic vertical motion is also scanned inside the interval every
    ``h_scan / 4`` (a dip below ``-g`` narrower than that may be missed)."""
    if not has_vertical(prm):
        return math.nan
    if vertical_is_record(prm):
        return lift_off_time(prm, samples, t0, t1) if lifts_off(prm, samples, t1) else math.nan
    n = max(1, int(math.ceil((t1 - t0) / (0.25 * h_scan) - 1e-9)))
    a = t0
    for k in range(1, n + 1):
        b = t1 if k == n else t0 + (t1 - t0) * k / n
        if lifts_off(prm, samples, b):
            return lift_off_time(prm, samples, a, b)
        a = b
    return math.nan


@njit(cache=True)
def initial_state(th0, om0):
    """``(resting, s, t_up)`` of a run from ``(th0, om0)``: at rest iff both are 0; the
    branch ``s`` (pivot, +1/-1) of the angle, or of the velocity at ``th0 = 0``; the uplift
    time 0 if the block starts rocking (NaN: not yet)."""
    resting = th0 == 0.0 and om0 == 0.0
    s = -1.0 if th0 < 0.0 or (th0 == 0.0 and om0 < 0.0) else 1.0
    return resting, s, math.nan if resting else 0.0


@njit(cache=True)
def rebound_side(om, ag):
    """The branch (pivot, +1/-1) after an impact: that of the velocity ``om``, or of the
    ground acceleration ``ag`` if ``om`` underflowed to 0 while the ground can uplift."""
    if om != 0.0:
        return 1.0 if om > 0.0 else -1.0
    return 1.0 if ag > 0.0 else -1.0


@njit(cache=True)
def rest_fill(k, t_lim, dt_out, out_th, out_om):
    """Write zeros (at rest) to the output samples ``k * dt_out < t_lim``; returns next k."""
    n_out = out_th.shape[0]
    while k < n_out and k * dt_out < t_lim:
        out_th[k] = 0.0
        out_om[k] = 0.0
        k += 1
    return k


@njit(cache=True)
def rest_advance(kind, prm, samples, t, t_end, h_scan, thr, c, dt_out, k, out_th, out_om,
                 t_up):
    """:func:`rest_advance_sides` of a symmetric block (the same threshold both ways)."""
    return rest_advance_sides(kind, prm, samples, t, t_end, h_scan, thr, c, thr, c, dt_out,
                              k, out_th, out_om, t_up)


@njit(cache=True)
def rest_advance_sides(kind, prm, samples, t, t_end, h_scan, thr_p, c_p, thr_m, c_m, dt_out,
                       k, out_th, out_om, t_up):
    """Advance a block at rest until the uplift criterion ``|a_h| > c (g + a_v)`` holds or
    ``t_end`` (``|a_h| > thr`` without a vertical component); ``c``, ``thr`` are those of
    the side towards which ``a_h`` pushes: ``c_p``, ``thr_p`` (= ``c_p g``) for ``a_h > 0``
    (uplift onto pivot +), ``c_m``, ``thr_m`` for ``a_h < 0`` (asymmetric blocks).

    Scans the excitation with steps ``h_scan`` (and onto every breakpoint), locates the
    first exceedance by bisection, and writes zeros to the output buffers meanwhile.
    Returns ``(t, k, direction, t_up)``: ``direction`` is +1/-1 (sign of ``a``) if the
    block uplifts at ``t``, :data:`LIFT_OFF` if the base falls away from it
    (``g + a_v <= 0``), 0 if it is still at rest at ``t_end``; ``t_up`` is the first
    uplift time (``t`` if the given ``t_up`` is NaN and the block uplifts now).
    """
    n_out = out_th.shape[0]
    while True:
        if _trips(kind, prm, samples, t, thr_p, c_p, thr_m, c_m):
            k = rest_fill(k, t - 1e-12, dt_out, out_th, out_om)
            if lifts_off(prm, samples, t):
                return t, k, LIFT_OFF, t_up
            ag = ground_acc(kind, prm, samples, t)
            return t, k, 1.0 if ag > 0.0 else -1.0, t if math.isnan(t_up) else t_up
        if t >= t_end - 1e-12:
            while k < n_out and k * dt_out <= t + 1e-12:
                out_th[k] = 0.0
                out_om[k] = 0.0
                k += 1
            return t, k, 0.0, t_up
        t1 = min(t + h_scan, next_breakpoint(kind, prm, samples, t), t_end)
        if has_vertical(prm) and not vertical_is_record(prm):  # a dip below -g inside the step
            tl = first_lift_off(prm, samples, t, t1, h_scan)
            if tl == tl:
                t1 = tl
        if _trips(kind, prm, samples, t1, thr_p, c_p, thr_m, c_m):
            lo, hi = t, t1
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                if _trips(kind, prm, samples, mid, thr_p, c_p, thr_m, c_m):
                    hi = mid
                else:
                    lo = mid
                if hi - lo < 1e-13:
                    break
            t1 = hi
        k = rest_fill(k, t1 - 1e-12, dt_out, out_th, out_om)
        t = t1
