r"""A rigid block standing free on a seismically isolated base (``model="isolated"``).

Issue 19 (part 1). The physics, derived in :mod:`rocking.testing.isolated_reference`
(Vassiliou and Makris 2012; Roussis and Odysseos 2017): a base plate of mass
``mass_ratio * m`` on a linear isolator (``isolation_period`` of block plus plate,
``isolation_damping`` ratio) or a friction pendulum (``radius``, ``friction``, ``tanh``
regularisation ``v_eps``). The block rocks under the plate's absolute acceleration ``A``,
coupled to the plate's displacement ``u``; it uplifts when ``|A|`` exceeds ``g tan(alpha)``;
at impacts ``theta'`` is multiplied by ``mu_iso = 1 - 2 lambda sin^2(alpha) / (1 - gamma
lambda cos^2(alpha))`` (or ``mu``) and the plate's velocity jumps by ``gamma h (mu_iso - 1)
theta'``. The run stops when ``|u|`` reaches ``clearance``.

Integration: constant-step classical Runge-Kutta (4th order) on ``(theta, theta', u, u')``
stepping onto the motion's breakpoints, events (impact, uplift, clearance) located by
bisection on the exact Runge-Kutta sub-step.

Vertical ground motion (:class:`rocking.motions.GroundMotion`, ``a_v`` positive upwards;
also the vertical floor motion of :class:`rocking.buildings.FloorMotion`): ``g`` becomes
``g + a_v`` in the block's gravity terms (``theta''`` and the plate's ``A``), in the uplift
threshold ``(g + a_v) tan(alpha)`` and in the Zeno rule, and the friction pendulum's
restoring and friction forces scale with its normal force, ``(g + a_v) / g`` (the linear
isolator's stiffness and damping do not); derived in
:mod:`rocking.testing.isolated_reference`. Where ``g + a_v <= 0`` the run stops at the
first such instant (``lift_off_time``; not settled), as in the classical model. Without a
vertical component, or with a zero one on the horizontal record's grid, the arithmetic is
the horizontal model's (bit-identical results).

Row outputs (``Response.info`` of single runs, ``BatchResponse.outputs`` of batches,
columns of campaigns): ``max_base_displacement`` (m, ``max |u|`` at the steps),
``max_plate_acceleration`` (m/s^2, ``max |A|`` at the steps), ``clearance_exceeded`` and
``clearance_time`` (s, NaN if not). Rest: after an impact, the Zeno rule of the classical
model with the plate taking the common velocity that conserves the horizontal momentum;
once the ground is still (``t_quiet``) a block at rest is settled when an energy bound of
the plate's free motion shows that ``|A|`` can no longer reach ``g tan(alpha)`` (with a
friction pendulum whose ``mu_f g`` exceeds it, the run goes to its time cap).

Checked against :func:`rocking.testing.isolated_reference.simulate_isolated_reference`
and with :func:`rocking.testing.check_model` in ``tests/test_isolated.py``. Not yet in
:data:`rocking.models.MODELS` (pass ``model=Isolated``): registering it is one line of
``models/registry.py`` plus the README's spec-key table regenerated
(``tests/test_spec_catalog.py`` says how).
"""

from __future__ import annotations

import math
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
from ._numerics import events as E
from .base import KernelResult, Model, ModelOptions, RowOutput, option, row_args_out, store_row

HALF_PI = 0.5 * math.pi


@njit(cache=True)
def _force(mp, u, v, gf):
    """Isolator force per unit of the isolated mass (m/s^2); ``gf = 1 + a_v / g`` scales
    the friction pendulum's (its normal force), not the linear isolator's."""
    if mp[6] == 0.0:
        return mp[7] * u + mp[8] * v
    return gf * (mp[7] * u + mp[8] * math.tanh(v / mp[9]))


@njit(cache=True)
def _gf(prm, samples, t):
    """``1 + a_v(t) / g`` (1 without a vertical component)."""
    if not has_vertical(prm):
        return 1.0
    return 1.0 + vertical_acc(prm, samples, t) / G


@njit(cache=True)
def _rhs(mp, y0, y1, y2, y3, t, s, rock, kind, prm, samples):
    alpha, p, R, lam, gam = mp[0], mp[1], mp[3], mp[4], mp[5]
    if has_vertical(prm):
        ag, av = ground_acc_hv(kind, prm, samples, t)
        gf = 1.0 + av / G
    else:
        ag, gf = ground_acc(kind, prm, samples, t), 1.0
    f = _force(mp, y2, y3, gf)
    if not rock:
        return 0.0, 0.0, y3, -f - ag
    phi = alpha - s * y0
    c, sn = math.cos(phi), math.sin(phi)
    p2 = p * p
    A = (-f + s * gam * R * sn * (y1 * y1 - p2 * gf * c)) / (1.0 - gam * lam * c * c)
    return y1, p2 * (c * A / G - s * gf * sn), y3, A - ag


@njit(cache=True)
def _rk4(mp, y, t, h, s, rock, kind, prm, samples):
    a = _rhs(mp, y[0], y[1], y[2], y[3], t, s, rock, kind, prm, samples)
    b = _rhs(mp, y[0] + 0.5 * h * a[0], y[1] + 0.5 * h * a[1], y[2] + 0.5 * h * a[2],
             y[3] + 0.5 * h * a[3], t + 0.5 * h, s, rock, kind, prm, samples)
    c = _rhs(mp, y[0] + 0.5 * h * b[0], y[1] + 0.5 * h * b[1], y[2] + 0.5 * h * b[2],
             y[3] + 0.5 * h * b[3], t + 0.5 * h, s, rock, kind, prm, samples)
    d = _rhs(mp, y[0] + h * c[0], y[1] + h * c[1], y[2] + h * c[2], y[3] + h * c[3],
             t + h, s, rock, kind, prm, samples)
    out = np.empty(4)
    for i in range(4):
        out[i] = y[i] + h * (a[i] + 2.0 * b[i] + 2.0 * c[i] + d[i]) / 6.0
    if not rock:
        out[0] = 0.0
        out[1] = 0.0
    return out


@njit(cache=True)
def _event(mp, y, s, rock, which, t, prm, samples):
    """Event functions at time ``t``, positive once the event has happened: 0 impact,
    1 uplift (``|A| > (g + a_v) tan(alpha)``), 2 clearance."""
    if which == 0:
        return -s * y[0]
    if which == 1:  # (where g + a_v <= 0 the lift-off comes first: no uplift)
        gf = _gf(prm, samples, t)
        return abs(_force(mp, y[2], y[3], gf)) - G * gf * math.tan(mp[0]) if gf > 0.0 else -1.0
    return abs(y[2]) - mp[10]


@njit(cache=True)
def _locate(mp, y, t, h, s, rock, kind, prm, samples, which):
    lo, hi = 0.0, h
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if not (lo < mid < hi):
            break
        if _event(mp, _rk4(mp, y, t, mid, s, rock, kind, prm, samples), s, rock, which,
                  t + mid, prm, samples) > 0:
            hi = mid
        else:
            lo = mid
    return hi


@njit(cache=True)
def _amp_bound(mp, y):
    """An upper bound of the plate's |A| in free motion of the resting system."""
    if mp[6] == 0.0:
        w2 = mp[7]
        e2 = y[3] * y[3] + w2 * y[2] * y[2]
        return math.sqrt(w2 * e2) * math.sqrt(1.0 + mp[8] * mp[8] / w2)
    e2 = y[3] * y[3] + mp[7] * y[2] * y[2]
    return math.sqrt(mp[7] * e2) + mp[8]


@njit(cache=True)
def kernel(mp, kind, prm, samples, t_end, t_quiet, th0, om0, h_scan, dt_out, out_th,
           out_om, imp, extra):
    alpha, p, mu, R, gam, h_max, rest_tol = mp[0], mp[1], mp[2], mp[3], mp[5], mp[11], mp[12]
    hc = R * math.cos(alpha)
    tan_a = math.tan(alpha)
    thr = G * tan_a
    hv = has_vertical(prm)
    h0 = min(h_max, 2e-3 / p, 0.25 * h_scan)
    y = np.zeros(4)
    y[0], y[1] = th0, om0
    t, k, n_imp, n_steps = 0.0, 0, 0, 0
    peak, peak_u, peak_a = abs(th0), 0.0, 0.0
    rock = not (th0 == 0.0 and om0 == 0.0)
    t_up = 0.0 if rock else math.nan
    s = 1.0 if (th0 > 0.0 or (th0 == 0.0 and om0 > 0.0)) else -1.0
    over, t_over, cleared, t_clear = False, math.nan, False, math.nan
    t_lift = math.nan
    n_out = out_th.shape[0]
    if n_out > 0:
        out_th[0], out_om[0] = th0, om0
        k = 1
    if hv and E.lifts_off(prm, samples, 0.0):
        t_end = 0.0  # the base falls away at once
        t_lift = 0.0
    while t < t_end - 1e-12:
        if not rock:
            if t >= t_quiet and _amp_bound(mp, y) <= thr:
                break  # the ground is still and the plate cannot uplift the block
            gf = _gf(prm, samples, t)
            a0 = -_force(mp, y[2], y[3], gf)
            if abs(a0) > thr * gf:
                rock, s = True, (1.0 if a0 > 0.0 else -1.0)
                if math.isnan(t_up):
                    t_up = t
        h = min(h0, t_end - t, next_breakpoint(kind, prm, samples, t) - t)
        if h <= 0.0:
            h = min(h0, t_end - t)
        y1 = _rk4(mp, y, t, h, s, rock, kind, prm, samples)
        n_steps += 1
        ev = -1
        hev = h
        checks = (0, 2) if rock else (1, 2)
        for which in checks:
            if _event(mp, y1, s, rock, which, t + h, prm, samples) > 0.0:
                he = _locate(mp, y, t, h, s, rock, kind, prm, samples, which)
                if he < hev or ev < 0:
                    ev, hev = which, he
        if hv:  # the base falls away (g + a_v <= 0): the model cannot represent flight
            tl = E.first_lift_off(prm, samples, t, t + hev, h_scan)
            if tl == tl and (ev < 0 or tl - t <= hev):
                ev, hev = 3, tl - t
        if ev >= 0:
            h = hev
            y1 = _rk4(mp, y, t, h, s, rock, kind, prm, samples)
        while k < n_out and k * dt_out <= t + h + 1e-12:  # cubic Hermite output
            x = (k * dt_out - t) / h
            out_th[k] = ((2 * x**3 - 3 * x**2 + 1) * y[0] + (x**3 - 2 * x**2 + x) * h * y[1]
                         + (3 * x**2 - 2 * x**3) * y1[0] + (x**3 - x**2) * h * y1[1])
            out_om[k] = (1.0 - x) * y[1] + x * y1[1]
            k += 1
        th_prev = y[0]
        t += h
        y = y1
        peak = max(peak, abs(y[0]))
        peak_u = max(peak_u, abs(y[2]))
        d = _rhs(mp, y[0], y[1], y[2], y[3], t, s, rock, kind, prm, samples)
        peak_a = max(peak_a, abs(d[3] + ground_acc(kind, prm, samples, t)))
        if rock and abs(y[0]) >= HALF_PI:
            over, peak = True, HALF_PI
            t_over = t - h * (abs(y[0]) - HALF_PI) / max(abs(y[0]) - abs(th_prev), 1e-300)
            break
        if ev == 3:
            t_lift = t
            break
        if ev == 2:
            cleared, t_clear = True, t
            break
        if ev == 1:
            rock = True
            s = 1.0 if -_force(mp, y[2], y[3], _gf(prm, samples, t)) > 0.0 else -1.0
            if math.isnan(t_up):
                t_up = t
        elif ev == 0:
            if n_imp < imp.shape[0]:
                imp[n_imp] = t
            n_imp += 1
            om1 = y[1]
            om2 = mu * om1
            y[0] = 0.0
            y[1] = om2
            y[3] += gam * hc * (om2 - om1)
            gf = _gf(prm, samples, t)
            c = math.cos(alpha) + 0.5 * (om2 / p) ** 2 / gf if gf > 0.0 else 2.0
            amp = alpha - math.acos(c) if c < 1.0 else math.inf
            v_rest = y[3] - gam * hc * om2
            if om2 == 0.0 or (amp < rest_tol * alpha
                              and abs(_force(mp, y[2], v_rest, gf)) <= thr * gf):
                y[1], y[3] = 0.0, v_rest
                rock = False
            else:
                s = 1.0 if om2 > 0.0 else -1.0
    if extra[0].shape[0] > 0:
        extra[0][0], extra[0][1], extra[0][2], extra[0][3] = (peak_u, peak_a,
                                                              1.0 if cleared else 0.0,
                                                              t_clear)
    return KernelResult(k, n_imp, peak, over, t_over, t_up, n_steps, 0, t_lift,
                        (over or not rock) and t_lift != t_lift)


@njit(cache=True)
def with_block(mp, b):
    return mp


@njit(cache=True, parallel=True)
def batch_kernel(mp, extra0, rows, blocks):
    for i in prange(rows[0].shape[0]):
        store_row(i, kernel(with_block(mp, blocks[i]), *row_args_out(i, rows)), rows)


@dataclass(frozen=True)
class IsolatedOptions(ModelOptions):
    isolation: str = option("linear", choices=("linear", "pendulum"),
                            help="isolator: linear (period, damping ratio) or friction "
                                 "pendulum (radius, friction)")
    isolation_period: float = option(2.0, unit="s", lo=0.0, hi=100.0,
                                     help="period of block and plate on the linear isolator")
    isolation_damping: float = option(0.05, unit="", lo=0.0, hi=10.0, lo_open=False,
                                      help="damping ratio of the linear isolator")
    mass_ratio: float = option(1.0, lo=0.0, hi=1e12, help="plate mass / block mass")
    radius: float = option(2.0, unit="m", lo=0.0, hi=1e4,
                           help="radius of curvature of the friction pendulum")
    friction: float = option(0.05, lo=0.0, hi=1.0, lo_open=False,
                             help="friction coefficient of the friction pendulum")
    v_eps: float = option(1e-3, unit="m/s", lo=0.0, hi=1.0,
                          help="velocity of the tanh regularisation of friction")
    clearance: float | None = option(None, unit="m", lo=0.0, hi=1e3,
                                     help="moat clearance: the run stops when |u| reaches "
                                          "it (None: no moat)")
    mu: float | None = option(None, lo=0.0, hi=1.0,
                              help="restitution (None: derived from the momentum balance)")
    rest_tol: float = option(1e-12, lo=0.0, hi=1e-2, lo_open=False,
                             help="Zeno threshold (fraction of alpha)")
    max_step: float = option(1e-3, unit="s", lo=0.0, hi=0.1, help="largest time step")


class Isolated(Model):
    mitigation = True
    name = "isolated"
    label = "block on an isolated base"
    Options = IsolatedOptions
    kernel = kernel
    batch_kernel = batch_kernel
    row_outputs = (
        RowOutput("max_base_displacement", "m", False, "max |u| of the base plate"),
        RowOutput("max_plate_acceleration", "m/s^2", False,
                  "max absolute acceleration of the plate"),
        RowOutput("clearance_exceeded", "", True, "|u| reached the clearance (the run "
                                                 "stopped there)"),
        RowOutput("clearance_time", "s", False, "when |u| reached the clearance (NaN: never)"),
    )

    def kernel_params(self, dt_out, theta0, omega0):
        b, o = self.block, self.options
        R = b.R if b.R is not None else 3.0 * G / (4.0 * b.p ** 2)
        lam = R * b.p ** 2 / G
        gam = 1.0 / (1.0 + o.mass_ratio)
        if o.mu is None:
            mu = 1.0 - 2.0 * lam * math.sin(b.alpha) ** 2 / (
                1.0 - gam * lam * math.cos(b.alpha) ** 2)
        else:
            mu = o.mu
        if o.isolation == "linear":
            w = 2.0 * math.pi / o.isolation_period
            iso, c1, c2, veps = 0.0, w * w, 2.0 * o.isolation_damping * w, 1.0
            h = o.isolation_period / 200.0
        else:
            iso, c1, c2, veps = 1.0, G / o.radius, o.friction * G, o.v_eps
            h = 2.0 * math.pi * math.sqrt(o.radius / G) / 200.0
            if o.friction > 0.0:
                h = min(h, 0.5 * o.v_eps / (o.friction * G))
        clear = math.inf if o.clearance is None else o.clearance
        return (b.alpha, b.p, mu, R, lam, gam, iso, c1, c2, veps, clear,
                min(h, o.max_step), o.rest_tol)
