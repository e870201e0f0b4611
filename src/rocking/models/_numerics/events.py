"""Compiled event helpers shared by the model kernels (rest and uplift)."""

from __future__ import annotations

import math

from numba import njit

from ...motions._kernel import ground_acc, next_breakpoint


@njit(cache=True)
def rest_advance(kind, prm, samples, t, t_end, h_scan, thr, dt_out, k, out_th, out_om, t_up):
    """Advance a block at rest until the uplift criterion ``|a| > thr`` holds or ``t_end``.

    Scans the excitation with steps ``h_scan`` (and onto every breakpoint), locates the
    first exceedance by bisection, and writes zeros to the output buffers meanwhile.
    Returns ``(t, k, direction, t_up)``: ``direction`` is +1/-1 (sign of ``a``) if the
    block uplifts at ``t``, 0 if it is still at rest at ``t_end``; ``t_up`` is the first
    uplift time (``t`` if the given ``t_up`` is NaN and the block uplifts now).
    """
    n_out = out_th.shape[0]
    while True:
        ag = ground_acc(kind, prm, samples, t)
        if abs(ag) > thr:
            while k < n_out and k * dt_out < t - 1e-12:
                out_th[k] = 0.0
                out_om[k] = 0.0
                k += 1
            return t, k, 1.0 if ag > 0.0 else -1.0, t if math.isnan(t_up) else t_up
        if t >= t_end - 1e-12:
            while k < n_out and k * dt_out <= t + 1e-12:
                out_th[k] = 0.0
                out_om[k] = 0.0
                k += 1
            return t, k, 0.0, t_up
        t1 = min(t + h_scan, next_breakpoint(kind, prm, samples, t), t_end)
        if abs(ground_acc(kind, prm, samples, t1)) > thr:
            lo, hi = t, t1
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                if abs(ground_acc(kind, prm, samples, mid)) > thr:
                    hi = mid
                else:
                    lo = mid
                if hi - lo < 1e-13:
                    break
            t1 = hi
        while k < n_out and k * dt_out < t1 - 1e-12:
            out_th[k] = 0.0
            out_om[k] = 0.0
            k += 1
        t = t1
