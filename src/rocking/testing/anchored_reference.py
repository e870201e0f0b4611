r"""Plain event-driven reference of a rocking block anchored at its base corners.

Issue 19 (part 2). A rectangular block of half-width ``b``, half-height ``h``
(``R = sqrt(b^2 + h^2)``, ``tan(alpha) = b/h``, ``p^2 = m g R / I_O``) rocks on a rigid base
as in the classical model (Peña et al. 2007, Eq 1 and Eq 4;
:mod:`rocking.models.housner`), and each of its two base corners is tied to the base by
a vertical anchor (restrainer). Written, like
:mod:`rocking.testing.housner_reference`, in plain Python on
:func:`scipy.integrate.solve_ivp` with events, to check a compiled kernel against; it
reuses only :class:`~rocking.testing.housner_reference.Excitation` (the motion as smooth
pieces).

Parameters of the anchors (dimensionless, one meaning per name; neither is in
:data:`rocking.options.UNITS`, whose ``stiffness`` is in N/m, hence the prefix):

* ``anchor_strength`` ``q = F_a / (m g)``: the tensile strength ``F_a`` (N) of one anchor
  as a fraction of the block's weight;
* ``anchor_stiffness`` ``kappa = k_a (2 b) / (m g)``: the anchor's axial stiffness
  ``k_a`` (N/m) times the base width, over the weight (the anchor force, as a fraction of
  the weight, per unit of ``elongation / (2 b)``); ``inf`` (default): rigid anchors.

Sign convention: the anchor ``+`` is the one stretched when ``theta > 0`` (the block pivots
on O and the corner O' lifts), the anchor ``-`` the one stretched when ``theta < 0``.

Equation of motion
------------------
On the branch ``s = sgn(theta)`` the lifting corner rises by ``2 b sin|theta|`` (the
anchor's elongation, its horizontal drift neglected) and the anchor pulls it down with
``F = k_a 2 b sin|theta|``, whose lever arm about the pivot is ``2 b cos(theta)``. Moments
about the pivot (``I_O theta'' = -s m g R sin(alpha - s theta) + m a R cos(alpha - s theta)
- s F 2 b cos(theta)``), divided by ``I_O`` with ``2 b = 2 R sin(alpha)``:

.. math::

    \theta'' = -s p^2 \sin(\alpha - s\theta) + p^2 \cos(\alpha - s\theta)\, a/g
               - s\, p^2\, 2 f \sin\alpha \cos\theta, \qquad f = F/(m g)

with ``f = kappa sin|theta|`` while the anchor of side ``s`` is intact and ``f = 0`` once
it has broken: Eq (1) of Peña et al. plus the anchor's moment.

Uplift with anchors (Makris and Zhang 2001)
-------------------------------------------
At rest (``theta = 0``) the block and the base are rigid. Moments about the corner O
(side ``+``) of the horizontal inertial force ``m a`` (lever ``h``), the weight (lever
``b``) and the anchor force ``F`` at O' (lever ``2 b``): the block stays down while
``m a h <= m g b + 2 b F``. An anchor with a tensile strength ``F_a`` can supply
``F <= F_a``, so

* **rigid anchors** (``kappa = inf``, the anchorage of Makris and Zhang 2001, "Rocking
  response of anchored blocks under pulse-type motions", J. Eng. Mech. 127(5),
  484-493: a restrainer holds the block down until its tensile strength is reached): the
  block uplifts towards side ``s`` when ``s a > g tan(alpha) (1 + 2 q)`` with the anchor
  ``s`` intact (the overturning moment exceeds gravity's ``m g b`` plus the anchor's
  ultimate moment ``2 b F_a``), ``g tan(alpha)`` once it has broken. Before, the anchor
  carries ``f = (s a / (g tan(alpha)) - 1) / 2`` (when positive); at the uplift it has
  reached ``F_a`` and, brittle, breaks: the block leaves rest as a free block
  (``theta = omega = 0``, no impulse: the force falls from ``F_a`` to 0). A rigid anchor
  cannot stretch, so an impact that would carry the block with a non-zero velocity onto
  the side of an intact rigid anchor breaks it at the impact (the force that would stop
  the block at once is unbounded): the block goes on with ``mu omega`` as a free block;
* **elastic anchors** (finite ``kappa``, not pre-tensioned): a rigid block on a rigid
  base lifts its corner by ``2 b sin|theta|``, so at ``theta = 0`` the anchor's force is
  zero and the uplift threshold is gravity's alone, ``g tan(alpha)``; once the corner
  lifts the anchor adds the restoring moment above, and it breaks (brittle) the first
  time ``f = kappa sin|theta|`` reaches ``q`` (an event of the integration), for good.
  In the quasi-static limit ``kappa -> inf`` the anchor's force at ``f = q`` is reached
  at ``a -> g tan(alpha) (1 + 2 q)``: the two laws agree.

An anchor of zero strength breaks as soon as it would carry a force (at the uplift towards
its side): the block is then the free (classical) block. After an anchor breaks its side
rocks freely; after both have broken the block is the classical one.

Asymmetric blocks
-----------------
A body whose pivots are at the horizontal distances ``b_+``, ``b_-`` from its centre of
mass (height ``h``; :meth:`rocking.Block.from_geometry`, :meth:`rocking.Block.from_mesh`;
Contento and Di Egidio 2009) rocks on side ``s`` with that side's ``alpha_s = atan(b_s /
h)``, ``p_s`` and ``R_s``, and an impact that ends rocking on side ``s`` multiplies the
velocity by ``mu_s`` (:mod:`rocking.models.housner`). The anchors sit at the two pivots,
the base width ``L = b_+ + b_- = h (tan(alpha_+) + tan(alpha_-))`` apart (``2 b`` above):
on side ``s`` the lifting corner rises by ``L sin|theta|``, the anchor's force ``F = k_a L
sin|theta|`` (``kappa = k_a L / (m g)``) has the lever arm ``L cos(theta)``, and the
moment equation above becomes

.. math::

    \theta'' = -s p_s^2 \sin(\alpha_s - s\theta) + p_s^2 \cos(\alpha_s - s\theta)\, a/g
               - s\, p_s^2\, f\, (L / R_s) \cos\theta,

``L / R_s = 2 sin(alpha)`` for a symmetric block. At rest the moments about the pivot
``s`` give ``m |a| h <= m g b_s + L F``: a rigid anchor ``s`` holds the block down until
``s a > g (tan(alpha_s) + q (tan(alpha_+) + tan(alpha_-)))`` (Makris and Zhang's ``g
tan(alpha) (1 + 2 q)`` for a symmetric block), carrying ``f = (|a|/g - tan(alpha_s)) /
(tan(alpha_+) + tan(alpha_-))`` before. An anchor of zero strength leaves the classical
asymmetric block.

Impacts (Eq 4), rest (Zeno rule) and overturning are those of
:mod:`rocking.testing.housner_reference`: at ``theta = 0`` the velocity is multiplied by
``mu``; after an impact the block is put at rest if the amplitude that free motion of the
*free* block would reach is below ``rest_tol * alpha`` (an upper bound with an intact
elastic anchor) and the ground cannot uplift it there; it overturns when ``|theta|``
reaches ``pi/2``. Uplift times are located by bisection (to rounding) on a scan of the
motion at its ``scan_step``, with an interior search of ``|a|`` near the threshold on
smooth pieces.

Outputs: ``max_abs_theta``, ``overturned`` and ``overturn_time``, ``uplift_time``,
``impact_times``, ``max_anchor_force`` (``F/(m g)``, and in N when the block's mass is
known), ``anchor_broken`` and ``anchor_break_time`` (``(+, -)``), the history and the
state at any time (:meth:`AnchoredResponse.state_at`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import minimize_scalar

from .._validate import non_negative, positive
from ..errors import ParameterError
from ..motions import Motion
from ..motions.ground import GroundMotion
from ..units import G
from .housner_reference import Excitation, FunctionMotion, free_amplitude

HALF_PI = 0.5 * math.pi
DEFAULT_REST_TOL = 1e-12

__all__ = ["AnchoredResponse", "simulate_anchored_reference"]


@dataclass
class AnchoredResponse:
    """What :func:`simulate_anchored_reference` returns (times in s, angles in rad)."""

    t: np.ndarray
    theta: np.ndarray
    omega: np.ndarray
    max_abs_theta: float
    overturned: bool
    overturn_time: float
    uplift_time: float
    impact_times: np.ndarray
    max_anchor_force: float
    """Largest anchor force over the run, as a fraction of the weight ``m g``."""
    max_anchor_force_n: float
    """The same in N (NaN when the block's mass is unknown)."""
    anchor_broken: tuple
    """Whether the anchors ``+`` (stretched by ``theta > 0``) and ``-`` broke."""
    anchor_break_time: tuple
    """When they broke (s; NaN: intact)."""
    settled: bool
    pieces: list = field(repr=False, default_factory=list)

    @property
    def n_impacts(self) -> int:
        return int(self.impact_times.size)

    def state_at(self, t: float) -> tuple[float, float]:
        """``(theta, omega)`` at time ``t`` (after an impact at ``t``: the velocity after it)."""
        found = None
        for ta, tb, sol in self.pieces:
            if ta <= t <= tb:
                found = (ta, tb, sol)  # the last piece containing t wins
        if found is None:
            raise ValueError(f"t = {t} is outside the simulated window")
        ta, tb, sol = found
        if sol is None:
            return 0.0, 0.0
        y = sol.sol(min(max(t, ta), tb))
        return float(y[0]), float(y[1])


def _point_values(exc: Excitation, t: float) -> tuple[float, ...]:
    """The one-sided values of ``a`` at ``t`` (both at a piece boundary)."""
    k = exc.piece(t)
    vals = (exc.fns[k](t),)
    if k > 0 and t == exc.starts[k]:
        vals += (exc.fns[k - 1](t),)
    return vals


def _first_uplift(exc: Excitation, t_from: float, t_end: float, thr_p: float,
                  thr_m: float):
    """First time in ``[t_from, t_end]`` with ``a > thr_p`` (uplift towards ``+``) or
    ``-a > thr_m`` (towards ``-``), and that direction; ``None`` if there is none."""

    def margin(a):
        return max(a - thr_p, -a - thr_m)

    def direction(a):
        return 1.0 if a - thr_p > -a - thr_m else -1.0

    for a0 in _point_values(exc, t_from):
        if margin(a0) > 0.0:
            return t_from, direction(a0)
    thr = min(thr_p, thr_m)
    k = exc.piece(t_from)
    while exc.starts[k] <= t_end:
        fn = exc.fns[k]
        lo = max(exc.starts[k], t_from)
        hi = min(exc.end(k), t_end)
        grid = exc.scan_grid(k, lo, hi)

        def f(t, fn=fn):
            return margin(fn(t))

        f_prev = f(grid[0])
        for g0, g1 in zip(grid[:-1], grid[1:], strict=True):
            f1 = f(g1)
            if f1 > 0.0:
                return _bisect(f, fn, g0, g1, direction)
            if (not exc.linear[k]) and max(f_prev, f1) > -0.05 * thr:
                res = minimize_scalar(lambda t, f=f: -f(t), bounds=(g0, g1),
                                      method="bounded", options={"xatol": 1e-13})
                if -res.fun > 0.0:
                    return _bisect(f, fn, g0, float(res.x), direction)
            f_prev = f1
        if hi >= t_end or not math.isfinite(hi):
            return None
        for a_b in _point_values(exc, hi):  # a jump into a pulse counts at its first instant
            if margin(a_b) > 0.0:
                return hi, direction(a_b)
        k += 1
    return None


def _bisect(f, fn, lo, hi, direction):
    """Bisection to rounding on ``f(lo) <= 0 < f(hi)``; the exceeding end and its direction."""
    for _ in range(400):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break
        if f(mid) > 0.0:
            hi = mid
        else:
            lo = mid
    return hi, direction(fn(hi))


def simulate_anchored_reference(block, motion, t_end: float, anchor_strength: float,
                                anchor_stiffness: float = math.inf, *, rtol: float = 1e-10,
                                atol=None, method: str = "DOP853",
                                rest_tol: float = DEFAULT_REST_TOL,
                                scan_step: float | None = None) -> AnchoredResponse:
    """The anchored block (module docstring) from rest, integrated to ``t_end`` (s).

    Parameters
    ----------
    block : Block
    motion : Motion or callable
        The horizontal ground acceleration: a :class:`rocking.motions.Motion` (no vertical
        component), or a function ``a(t)`` in m/s^2 with ``scan_step`` (s) a step that
        resolves it (for the uplift scan).
    t_end : float
        Simulated time (s).
    anchor_strength : float
        ``q = F_a / (m g)`` of each anchor (>= 0).
    anchor_stiffness : float
        ``kappa = k_a 2 b / (m g)`` (> 0); ``inf``: rigid anchors (Makris and Zhang 2001).
    rtol, atol, method : tolerances and method of :func:`scipy.integrate.solve_ivp`
        (``atol`` defaults to ``1e-3 rtol (alpha, alpha p)``).
    rest_tol : float
        Zeno rule (fraction of ``alpha``).
    """
    t_end = positive("t_end", t_end, "s")
    q = non_negative("anchor_strength", anchor_strength)
    kappa = float(anchor_stiffness)
    if not kappa > 0.0:  # inf (rigid) is allowed, NaN is not
        raise ParameterError(f"anchor_stiffness must be > 0 (inf: rigid), got {anchor_stiffness!r}")
    rigid = math.isinf(kappa)
    if isinstance(motion, GroundMotion) and motion.vertical is not None:
        raise ParameterError("the anchored reference takes a horizontal motion only")
    if isinstance(motion, Motion):
        exc = Excitation(motion)
    elif callable(motion):
        if scan_step is None:
            raise ParameterError("a motion given as a function needs scan_step (s)")
        exc = Excitation(FunctionMotion(motion, positive("scan_step", scan_step, "s")))
    else:
        raise ParameterError("motion must be a rocking Motion or a function a(t)")
    # the sides (module docstring, asymmetric blocks): alpha, p, mu, and the lever ratio
    # L / R_s of the elastic anchor's moment, L = b_+ + b_- the base width
    side = {1.0: (block.alpha_plus, block.p_plus, block.mu_plus, block.R_plus),
            -1.0: (block.alpha_minus, block.p_minus, block.mu_minus, block.R_minus)}
    tan_sum = math.tan(side[1.0][0]) + math.tan(side[-1.0][0])  # L / h
    if block.R_plus is not None:  # L from the pivots' distances b_s = R_s sin(alpha_s)
        width = sum(R * math.sin(a) for a, _, _, R in side.values())
        lever = {s: width / side[s][3] for s in side}
    else:  # one height h: R_s = h / cos(alpha_s)
        lever = {s: tan_sum * math.cos(side[s][0]) for s in side}
    a_lo = min(side[1.0][0], side[-1.0][0])
    p_hi = max(side[1.0][1], side[-1.0][1])
    if atol is None:
        atol = [1e-3 * rtol * a_lo, 1e-3 * rtol * a_lo * p_hi]

    broken = {1.0: False, -1.0: False}
    t_break = {1.0: math.nan, -1.0: math.nan}
    f_max = 0.0

    def breaks(side, t):
        nonlocal f_max
        broken[side] = True
        t_break[side] = t
        f_max = max(f_max, q)

    def thr(s):  # uplift threshold towards `s` (m/s^2): m a h = m g b_s (+ L F_a)
        ta = math.tan(side[s][0])
        return G * (ta + q * tan_sum) if rigid and not broken[s] else G * ta

    def hold_force(a):  # rigid anchors at rest: the force the intact one carries
        s = 1.0 if a > 0.0 else -1.0
        if not rigid or broken[s]:
            return 0.0
        return min(q, max(0.0, (abs(a) / G - math.tan(side[s][0])) / tan_sum))

    t, th, om = 0.0, 0.0, 0.0
    resting = True
    uplift_time = math.nan
    s = 1.0
    peak = 0.0
    impacts: list[float] = []
    pieces: list = []
    overturned, t_over = False, math.nan

    while t < t_end:
        if resting:
            up = _first_uplift(exc, t, t_end, thr(1.0), thr(-1.0))
            t_stop = t_end if up is None else up[0]
            if rigid and t_stop > t:  # the force the anchors carry while the block is down
                f_max = max(f_max, _max_hold(exc, t, t_stop, hold_force))
            if up is None:
                pieces.append((t, t_end, None))
                t = t_end
                break
            tu, s = up
            if tu > t:
                pieces.append((t, tu, None))
            t, th, om = tu, 0.0, 0.0
            resting = False
            if math.isnan(uplift_time):
                uplift_time = tu
            if not broken[s] and (rigid or q == 0.0):
                breaks(s, tu)  # its strength is reached at the uplift
        k = exc.piece(t)
        tb = min(exc.end(k), t_end)
        fn = exc.fns[k]
        anch = not broken[s]  # only an elastic anchor can be intact while its side rocks

        alpha, p, _, _ = side[s]
        p2 = p * p

        def rhs(tt, y, s=s, fn=fn, anch=anch, alpha=alpha, p2=p2, lr=lever[s]):
            x = alpha - s * y[0]
            acc = -s * p2 * math.sin(x) + p2 * math.cos(x) * fn(tt) / G
            if anch:
                acc -= p2 * lr * kappa * math.sin(y[0]) * math.cos(y[0])
            return (y[1], acc)

        def ev_impact(tt, y, s=s, t_start=t):
            if tt == t_start and y[0] == 0.0:
                return 1e-300  # leaving theta = 0: find the end of the excursion
            return s * y[0]

        def ev_over(tt, y, s=s):
            return s * y[0] - HALF_PI

        def ev_peak(tt, y):
            return y[1]

        def ev_break(tt, y, s=s, anch=anch):
            return kappa * math.sin(s * y[0]) - q if anch else -1.0

        ev_impact.terminal, ev_impact.direction = True, -1.0
        ev_over.terminal, ev_over.direction = True, 1.0
        ev_peak.terminal, ev_peak.direction = False, 0.0
        ev_break.terminal, ev_break.direction = True, 1.0
        opts = {}
        if th == 0.0 and om != 0.0:
            acc0 = rhs(t, (th, om))[1]
            if s * acc0 < 0.0:
                fs = max(0.5 * abs(om / acc0), 100.0 * math.ulp(max(t, 1.0)))
                opts["first_step"] = min(fs, tb - t)
        sol = solve_ivp(rhs, (t, tb), [th, om], method=method, rtol=rtol, atol=atol,
                        events=(ev_impact, ev_over, ev_peak, ev_break), dense_output=True,
                        **opts)
        if sol.status < 0:
            raise RuntimeError(f"solve_ivp failed at t = {t}: {sol.message}")
        for ye in sol.y_events[2]:
            peak = max(peak, abs(ye[0]))
            if anch:
                f_max = max(f_max, kappa * abs(math.sin(ye[0])))
        pieces.append((t, float(sol.t[-1]), sol))
        if sol.t_events[1].size:
            overturned, t_over, peak = True, float(sol.t_events[1][0]), HALF_PI
            t = t_over
            break
        if sol.t_events[3].size:
            te = float(sol.t_events[3][0])
            breaks(s, te)
            th, om = float(sol.y_events[3][0][0]), float(sol.y_events[3][0][1])
            peak = max(peak, abs(th))
            t = te
            continue
        if sol.t_events[0].size:
            te = float(sol.t_events[0][0])
            impacts.append(te)
            om = side[s][2] * float(sol.y_events[0][0][1])  # rocking on side s ends
            th, t = 0.0, te
            a_t = _point_values(exc, t)[0]
            can_lift = a_t > thr(1.0) or -a_t > thr(-1.0)
            sn = 1.0 if om > 0.0 else -1.0  # the side it rebounds on
            if om == 0.0 or (free_amplitude(om, side[sn][0], side[sn][1])
                             < rest_tol * side[sn][0] and not can_lift):
                resting, om = True, 0.0
                continue
            s = sn
            if not broken[s] and (rigid or q == 0.0):
                breaks(s, t)  # a rigid anchor cannot stop the block: it breaks at the impact
            continue
        th, om = float(sol.y[0, -1]), float(sol.y[1, -1])
        peak = max(peak, abs(th))
        t = tb

    ts = [np.array([a, b]) if sol is None else sol.t for a, b, sol in pieces]
    ths = [np.zeros(2) if sol is None else sol.y[0] for a, b, sol in pieces]
    oms = [np.zeros(2) if sol is None else sol.y[1] for a, b, sol in pieces]
    mass = getattr(block, "mass", None)
    return AnchoredResponse(
        t=np.concatenate(ts) if ts else np.zeros(0),
        theta=np.concatenate(ths) if ths else np.zeros(0),
        omega=np.concatenate(oms) if oms else np.zeros(0),
        max_abs_theta=float(peak), overturned=overturned, overturn_time=t_over,
        uplift_time=uplift_time, impact_times=np.asarray(impacts, dtype=float),
        max_anchor_force=float(f_max),
        max_anchor_force_n=math.nan if mass is None else float(f_max * mass * G),
        anchor_broken=(broken[1.0], broken[-1.0]),
        anchor_break_time=(t_break[1.0], t_break[-1.0]),
        settled=overturned or resting, pieces=pieces)


def _max_hold(exc: Excitation, t0: float, t1: float, hold_force) -> float:
    """Largest force (fraction of the weight) the rigid anchors carry at rest on
    ``[t0, t1]``, from the acceleration sampled at its ``scan_step`` and the piece ends."""
    step = exc.scan_step if math.isfinite(exc.scan_step) else t1 - t0
    if not math.isfinite(t1 - t0):
        return 0.0
    n = max(2, min(200_000, int(math.ceil((t1 - t0) / step)) * 4 + 1))
    ts = np.unique(np.concatenate([np.linspace(t0, t1, n),
                                   [x for x in exc.starts if t0 <= x <= t1]]))
    return max((hold_force(v) for x in ts for v in _point_values(exc, float(x))),
               default=0.0)
