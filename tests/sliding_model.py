"""A toy model in one file: a rigid block sliding on the ground with Coulomb friction.

It is the executable proof of the model contract (:mod:`rocking.models.base`, issue 29):
this file plus one registry line, ``rocking.models.register(Sliding)``, and the model
runs through :func:`rocking.simulate`, :func:`rocking.simulate_many`, a campaign and
:func:`rocking.testing.check_model`, with no other file of the package touched
(``tests/test_toy_model.py``; the documentation's "How to add a model" page shows it).

Physics. The block's displacement relative to the ground ``x`` (m), positive along a
positive ground acceleration ``a``, and its velocity ``v`` (m/s): while it slides,
``x'' = -a - mu N/m sgn(v)`` with ``N = m (g + a_v)``; it sticks (``v = 0``) while
``|a| <= mu (g + a_v)``. Between steps the ground acceleration is linear in time
(trapezoid), so a constant acceleration is integrated exactly: a ground accelerating at
``a > mu g`` from rest makes the block slide with ``x = -(a - mu g) t^2 / 2``; released
with ``v0`` on still ground it stops after ``v0^2 / (2 mu g)``.
"""

from __future__ import annotations

import math
from collections import namedtuple
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from rocking import G
from rocking.models import (
    GENERIC_OUTPUTS,
    Model,
    ModelOptions,
    Output,
    option,
    row_args,
    same_block,
    store_row,
)
from rocking.motions._kernel import ground_acc, ground_acc_hv, has_vertical, next_breakpoint

SlidingParams = namedtuple("SlidingParams", ["friction", "max_step"])


@njit(cache=True)
def _acc(kind, prm, samples, t):
    """``(a_h, g + a_v)`` of the ground at ``t``."""
    if has_vertical(prm):
        ah, av = ground_acc_hv(kind, prm, samples, t)
        return ah, G + av
    return ground_acc(kind, prm, samples, t), G


@njit(cache=True)
def _output(hist, k, dt_out, t, h, x0, v0, x1, v1):
    """Write the output samples inside the step ``[t, t + h]``: ``x`` quadratic through
    ``x0``, ``v0`` and ``x1`` (exact under a constant acceleration), ``v`` linear. The
    outputs never change the steps, so a batch without histories gives the same run."""
    while k < hist.shape[0] and k * dt_out <= t + h + 1e-12:
        tau = k * dt_out - t
        c = (x1 - x0 - v0 * h) / (h * h)
        hist[k, 0] = x0 + v0 * tau + c * tau * tau
        hist[k, 1] = v0 + (v1 - v0) * tau / h
        k += 1
    return k


@njit(cache=True)
def kernel(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp, res, extra):
    """One run (the kernel contract of :mod:`rocking.models.base`)."""
    h0 = min(0.25 * h_scan, mp.max_step)
    n_out = hist.shape[0]
    t, x, v = 0.0, y0[0], y0[1]
    a0, n0 = _acc(kind, prm, samples, t)
    slipping = v != 0.0 or abs(a0) > mp.friction * n0
    t_up = 0.0 if slipping else math.nan
    peak, k, n_steps, t_lift = abs(x), 0, 0, math.nan
    while True:
        if k == 0 and n_out > 0:
            hist[0, 0], hist[0, 1] = x, v
            k = 1
        if n0 <= 0.0:  # the base falls away: no friction, no model of flight
            t_lift = t
            break
        if not t < t_end - 1e-12 or (t >= t_quiet - 1e-12 and not slipping and v == 0.0):
            break
        t1 = min(t + h0, t_end, next_breakpoint(kind, prm, samples, t))
        h = t1 - t
        x_prev, v_prev = x, v
        a1, n1 = _acc(kind, prm, samples, t1)
        n_steps += 1
        if not slipping:
            if abs(a1) > mp.friction * n1:  # the ground drags harder than friction holds
                slipping = True
                if t_up != t_up:
                    t_up = t1
            t, a0, n0 = t1, a1, n1
            k = _output(hist, k, dt_out, t - h, h, x, 0.0, x, 0.0)
            continue
        s = 1.0 if v > 0.0 else (-1.0 if v < 0.0 else -math.copysign(1.0, a1))
        acc0 = -a0 - s * mp.friction * n0
        acc1 = -a1 - s * mp.friction * n1
        v1 = v + 0.5 * h * (acc0 + acc1)
        if s * v1 < 0.0:  # the velocity reaches 0 inside the step: stop there
            f = v / (v - v1) if v != 0.0 else 0.0
            x = x + 0.5 * f * h * v
            v1 = 0.0
            slipping = abs(a1) > mp.friction * n1
        else:
            x = x + 0.5 * h * (v + v1)
        v = v1
        peak = max(peak, abs(x))
        k = _output(hist, k, dt_out, t, h, x_prev, v_prev, x, v)
        t, a0, n0 = t1, a1, n1
    res.n_out = k
    res.n_steps = n_steps
    res.status = 0
    res.settled = v == 0.0 and not slipping and t_lift != t_lift
    res.overturned = False
    res.uplift_time = t_up
    res.lift_off_time = t_lift
    res.max_slide = peak
    res.residual_slide = x


@njit(cache=True, parallel=True)
def batch_kernel(mp, extra0, rows, blocks):
    """The batch kernel (the same lines in every model)."""
    for i in prange(rows.kinds.shape[0]):
        kernel(same_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
        store_row(i, rows)


@dataclass(frozen=True)
class SlidingOptions(ModelOptions):
    """Options of the sliding block."""

    friction: float = option(0.5, lo=0.0, hi=10.0, help="Coulomb friction coefficient")
    max_step: float = option(1e-3, unit="s", lo=0.0, hi=0.1, help="largest time step")


class Sliding(Model):
    """A rigid block that slides (never rocks) on the ground with Coulomb friction."""

    name = "sliding"
    label = "sliding block (toy)"
    Options = SlidingOptions
    kernel = kernel
    batch_kernel = batch_kernel
    state_names = ("x", "v")
    state_units = ("m", "m/s")
    tags = {"planar": False, "symmetry": "mirror"}
    outputs = GENERIC_OUTPUTS + (
        Output("max_slide", "m", False, "largest |x| relative to the ground"),
        Output("residual_slide", "m", False, "x when the run ended"),
    )

    def kernel_params(self, dt_out, theta0, omega0):
        return SlidingParams(self.options.friction, self.options.max_step)

    def check_state(self, y0):
        y = np.asarray(y0, dtype=np.float64).reshape(-1)
        if y.size != 2 or not np.all(np.isfinite(y)):
            from rocking import ParameterError
            raise ParameterError(f"state0 must be (x, v) in (m, m/s), got {y0!r}")
        return y.copy()
