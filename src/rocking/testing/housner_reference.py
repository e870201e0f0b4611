r"""Plain event-driven reference implementation of the classical (Housner) model.

This module integrates the same piecewise model as :mod:`rocking.models.housner`, but
written independently, in plain Python on top of :func:`scipy.integrate.solve_ivp`, so
that the compiled kernel can be checked against it. It is slow (one ``solve_ivp`` call
per smooth piece of the excitation and per impact) and meant for tests and benchmarks.

The model (Peña et al. 2007, Section 2.1):

* Between impacts, Eq (1) on the branch ``s = sgn(theta)`` (pivot O for ``s = +1``,
  O' for ``s = -1``):

  .. math:: \theta'' = -s\,p^2 \sin(\alpha - s\theta) + p^2 \cos(\alpha - s\theta)\,a(t)/g

  or, with ``linear=True``, ``theta'' = p^2 (theta - s alpha) + p^2 a/g``. A positive
  ``a`` drives ``theta`` positive. With a vertical acceleration ``a_v`` (positive
  upwards, :class:`rocking.motions.GroundMotion`) ``g`` becomes ``g + a_v`` in the gravity
  term (the first one), in the uplift threshold and in the Zeno rule's energy; where
  ``g + a_v <= 0`` the base falls away from the block and the run stops (lift-off).
* *Impact* (event ``theta = 0``, crossed from the side ``s``, terminal): the angular
  velocity is multiplied by ``mu`` (Eq 4) and the pivot switches; a new ``solve_ivp``
  call starts from ``theta = 0``.
* *Rest (Zeno rule)*: after an impact with post-impact velocity ``omega``, the amplitude
  that free motion would reach is obtained from energy conservation,
  ``cos(alpha - r) = cos(alpha) + omega^2 / (2 p^2)`` (``(alpha - r)^2 = alpha^2 -
  omega^2/p^2`` when linear). If ``r < rest_tol * alpha`` and ``|a| <= g tan(alpha)`` at
  that instant, the block is put at rest (``theta = omega = 0``).
* *Uplift*: a block at rest starts to rock, in the direction of ``sign(a)``, at the first
  time at which ``|a| > g tan(alpha)`` (``g alpha`` when linear), including ``t = 0``.
  The acceleration is scanned on a grid of ``motion.scan_step`` (for records the sample
  points, where linear interpolation makes the check exact; for smooth motions each grid
  interval close to the threshold is also searched for an interior maximum of ``|a|``)
  and the crossing is refined with :func:`scipy.optimize.brentq`.
* *Overturning*: ``|theta|`` reaches ``pi/2`` (event, terminal); the simulation stops.

The excitation is split into smooth pieces at its kinks and jumps (every sample of a
record, the start and end of a pulse or of a sine) and each piece is integrated by its
own ``solve_ivp`` call, with the one-sided (smooth) expression of ``a(t)`` on that piece.
At a jump, the point value is the one of the pulse or record (the closed-interval
convention of :mod:`rocking.motions`); it only matters for the uplift test. The
excitation formulas are written here from the definitions in :mod:`rocking.motions`
rather than taken from the compiled motion kernel, so they are checked too.

Peaks of ``|theta|`` are located as non-terminal events ``omega = 0`` on the solver's
dense output (and at the ends of each piece). An impact whose dip across ``theta = 0`` and
back falls inside one solver step shows no sign change at the step's ends, so its event
is not triggered; its minimum is then a peak event on the wrong side, and the impact is
the first root of ``theta`` before it on the dense output (:func:`_missed_impact`).

*Asymmetric blocks* (:meth:`rocking.Block.from_geometry`, issue 20): on the branch ``s``
Eq (1) uses that side's ``alpha_s`` and ``p_s``; the block at rest uplifts towards + when
``a > g tan(alpha_+)`` and towards - when ``-a > g tan(alpha_-)`` (found on the scan grid
of every piece, with the interior extrema of ``a`` near a level, by bisection); an impact
ending rocking on side ``s`` multiplies the velocity by ``mu_s``, and the Zeno rule uses
the parameters of the side the block rebounds onto.
"""

from __future__ import annotations

import bisect
import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar

from .._validate import positive
from ..errors import ParameterError
from ..models.housner import DEFAULT_FREE_REST_TOL, DEFAULT_REST_TOL, Housner
from ..models.run import check_run
from ..motions import (
    HalfSine,
    HanningSine,
    Motion,
    OneCosine,
    OneSine,
    Record,
    Rectangular,
    Ricker,
    Sine,
)
from ..motions.ground import GroundMotion
from ..results import Response
from ..units import G

HALF_PI = 0.5 * math.pi
METHODS = ("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")

__all__ = ["simulate_reference", "Excitation", "FunctionMotion", "free_amplitude"]


# ------------------------------------------------------------------------- excitation
class Excitation:
    """A motion as a list of smooth pieces ``[start, end]`` covering ``[0, inf)``.

    ``fns[k]`` is the smooth expression of the acceleration (m/s^2) on piece ``k``,
    valid on the closed piece (one-sided limits at its ends); ``linear[k]`` tells whether
    it is linear in ``t`` (then ``|a|`` can only exceed a level at the piece's ends).
    """

    def __init__(self, motion: Motion | None):
        self.motion = motion
        self.vfns = None  # the vertical acceleration on each piece (None: no vertical)
        if isinstance(motion, GroundMotion):
            h = motion.horizontal.scaled(motion.scale)
            eh = Excitation(h)
            if motion.vertical is None:
                self.starts, self.fns, self.linear = eh.starts, eh.fns, eh.linear
                self.scan_step = eh.scan_step
                return
            ev = Excitation(motion.vertical.scaled(motion.scale))
            self.starts = sorted(set(eh.starts) | set(ev.starts))
            self.fns = [eh.fns[eh.piece(t)] for t in self.starts]
            self.vfns = [ev.fns[ev.piece(t)] for t in self.starts]
            self.linear = [eh.linear[eh.piece(t)] and ev.linear[ev.piece(t)]
                           for t in self.starts]
            self.scan_step = min(eh.scan_step, ev.scan_step)
            self._h, self._v = eh, ev
            return
        starts: list[float] = [0.0]
        fns: list = []
        lin: list[bool] = []
        zero = _const(0.0)
        if motion is None:
            fns, lin = [zero], [True]
            self.scan_step = math.inf
        elif isinstance(motion, Record):
            a = np.asarray(motion.acc, dtype=float) * motion.scale
            dt = motion.dt
            n = a.size
            starts = [i * dt for i in range(n)]  # pieces [i dt, (i+1) dt], then zero
            for i in range(n - 1):
                ti, ai = i * dt, float(a[i])
                slope = (float(a[i + 1]) - ai) / dt
                fns.append(_linear(ti, ai, slope))
                lin.append(True)
            fns.append(zero)
            lin.append(True)
            self.scan_step = dt
        elif isinstance(motion, Sine | HanningSine):
            starts = [0.0, motion.duration]
            fns = [_harmonic(motion), zero]
            lin = [False, True]
            self.scan_step = motion.scan_step
        elif isinstance(motion, OneSine | OneCosine | HalfSine | Rectangular):
            t0, T = motion.t0, motion.length
            body = _pulse(motion)
            if t0 > 0.0:
                starts, fns, lin = [0.0, t0, t0 + T], [zero, body, zero], [True, False, True]
            else:
                starts, fns, lin = [0.0, T], [body, zero], [False, True]
            if isinstance(motion, Rectangular):
                lin = [True] * len(fns)
            self.scan_step = motion.scan_step
        elif isinstance(motion, Ricker):
            A, x0, tc = motion.amplitude * motion.scale, math.pi * motion.fp, motion.tc

            def ricker(t):
                x = x0 * (t - tc)
                return A * (1.0 - 2.0 * x * x) * math.exp(-x * x)

            fns, lin = [ricker], [False]
            self.scan_step = motion.scan_step
        else:  # an unknown Motion subclass: one piece, point values from the motion itself
            fns, lin = [lambda t: float(motion.acceleration(t))], [False]
            self.scan_step = motion.scan_step
        self.starts = starts
        self.fns = fns
        self.linear = lin

    def piece(self, t: float) -> int:
        """Index of the piece containing ``t`` (the one that starts at ``t`` at a boundary)."""
        return max(0, bisect.bisect_right(self.starts, t) - 1)

    def scan_grid(self, k: int, lo: float, hi: float) -> list:
        """The times at which piece ``k`` is scanned over ``[lo, hi]``: its ends if it is
        linear (or has no scan step), else every multiple of the scan step between them."""
        if self.linear[k] or not math.isfinite(self.scan_step):
            return [lo, hi] if hi > lo else [lo]
        step = self.scan_step
        inner = np.arange(math.floor(lo / step) + 1, math.ceil(hi / step)) * step
        return [lo, *[x for x in inner.tolist() if lo < x < hi], hi]

    def end(self, k: int) -> float:
        return self.starts[k + 1] if k + 1 < len(self.starts) else math.inf

    def vertical(self, t: float) -> float:
        """Point value of the vertical acceleration (m/s^2, positive upwards)."""
        return 0.0 if self.vfns is None else self._v(t)

    def __call__(self, t: float) -> float:
        """Point value of the acceleration (m/s^2); at a jump, the larger in magnitude of
        the two one-sided values (the pulse or record value, never the zero outside)."""
        if self.vfns is not None:
            return self._h(t)
        k = self.piece(t)
        v = self.fns[k](t)
        if k > 0 and t == self.starts[k]:
            w = self.fns[k - 1](t)
            if abs(w) > abs(v):
                v = w
        return v


class FunctionMotion:
    """A plain function ``a(t)`` (m/s^2) as something :class:`Excitation` takes, scanned
    every ``scan_step`` (s) for the crossings of a level."""

    def __init__(self, fn, scan_step):
        self.acceleration = fn
        self.scan_step = scan_step


def _const(c):
    return lambda t: c


def _linear(ti, ai, slope):
    return lambda t: ai + (t - ti) * slope


def _harmonic(m):
    s, X, w = m.scale, m.amplitude, 2.0 * math.pi * m.freq
    if isinstance(m, Sine):
        ph = m.phase
        return lambda t: -s * X * w * w * math.sin(w * t + ph)
    W = 2.0 * math.pi / m.duration

    def hanning(t):  # d2/dt2 of X (1 - cos W t)/2 sin(w t)
        win = 0.5 * (1.0 - math.cos(W * t))
        dwin = 0.5 * W * math.sin(W * t)
        ddwin = 0.5 * W * W * math.cos(W * t)
        sn, cs = math.sin(w * t), math.cos(w * t)
        return s * X * (ddwin * sn + 2.0 * dwin * w * cs - win * w * w * sn)

    return hanning


def _pulse(m):
    A, T, t0 = m.amplitude * m.scale, m.length, m.t0
    if isinstance(m, Rectangular):
        return _const(A)
    if isinstance(m, OneSine):
        return lambda t: A * math.sin(2.0 * math.pi * (t - t0) / T)
    if isinstance(m, OneCosine):
        return lambda t: A * math.cos(2.0 * math.pi * (t - t0) / T)
    return lambda t: A * math.sin(math.pi * (t - t0) / T)  # HalfSine


# ---------------------------------------------------------------------------- uplift
def _first_exceedance(exc: Excitation, t_from: float, t_end: float, thr: float,
                      c: float = 0.0):
    """First time in ``[t_from, t_end]`` at which ``|a| > thr`` (with a vertical component:
    ``|a_h| > c (g + a_v)`` or ``g + a_v <= 0``), with ``sign(a)`` there; ``None`` if there
    is none."""
    if exc.vfns is not None:
        return _first_exceedance_v(exc, t_from, t_end, c)
    a0 = exc(t_from)
    if abs(a0) > thr:
        return t_from, math.copysign(1.0, a0)
    k = exc.piece(t_from)
    while exc.starts[k] <= t_end:
        fn = exc.fns[k]
        lo = max(exc.starts[k], t_from)
        hi = min(exc.end(k), t_end)
        grid = exc.scan_grid(k, lo, hi)
        f_prev = abs(fn(grid[0])) - thr
        for g0, g1 in zip(grid[:-1], grid[1:], strict=True):
            f1 = abs(fn(g1)) - thr
            if f1 > 0.0:
                return _refine(fn, g0, g1, thr)
            if (not exc.linear[k]) and max(f_prev, f1) > -0.05 * thr:
                res = minimize_scalar(lambda t, fn=fn: -abs(fn(t)), bounds=(g0, g1),
                                      method="bounded", options={"xatol": 1e-13})
                if -res.fun > thr:
                    return _refine(fn, g0, float(res.x), thr)
            f_prev = f1
        if hi >= t_end or not math.isfinite(hi):
            return None
        # point value at the boundary (a jump into a pulse counts at its first instant)
        a_b = exc(hi)
        if abs(a_b) > thr:
            return hi, math.copysign(1.0, a_b)
        k += 1
    return None


def _first_exceedance_v(exc: Excitation, t_from: float, t_end: float, c: float):
    """:func:`_first_exceedance` with a vertical component: the margin
    ``|a_h| - c (g + a_v)`` (and ``-(g + a_v)``) on a grid of ``scan_step`` and at every
    piece boundary, refined by bisection."""

    def trips(t):
        ge = G + exc.vertical(t)
        return ge <= 0.0 or abs(exc(t)) > c * ge

    if trips(t_from):
        return t_from, math.copysign(1.0, exc(t_from))
    step = exc.scan_step if math.isfinite(exc.scan_step) else t_end - t_from
    k = exc.piece(t_from)
    grid = [t_from]
    while True:
        hi = min(exc.end(k), t_end)
        n = max(1, math.ceil((hi - grid[-1]) / step - 1e-9)) if not exc.linear[k] else 1
        grid += np.linspace(grid[-1], hi, n + 1)[1:].tolist()
        if hi >= t_end or not math.isfinite(hi):
            break
        k += 1
    for g0, g1 in zip(grid[:-1], grid[1:], strict=True):
        if trips(g1):
            lo, hi = g0, g1
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if not lo < mid < hi:
                    break
                if trips(mid):
                    hi = mid
                else:
                    lo = mid
            return hi, math.copysign(1.0, exc(hi))
    return None


def _refine(fn, lo, hi, thr):
    """Crossing of ``|fn| = thr`` in ``(lo, hi]`` with ``|fn(lo)| <= thr < |fn(hi)|``: brentq,
    then a few bisections so that the returned time is on the exceeding side."""

    def f(t):
        return abs(fn(t)) - thr

    r = brentq(f, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps)
    if f(r) > 0.0:
        hi = r
    else:
        lo = r
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break
        if f(mid) > 0.0:
            hi = mid
        else:
            lo = mid
    return hi, math.copysign(1.0, fn(hi))


def _first_exceedance_sides(exc: Excitation, t_from: float, t_end: float, c_p: float,
                            c_m: float):
    """First time in ``[t_from, t_end]`` at which ``a > c_p (g + a_v)`` (uplift towards +),
    ``-a > c_m (g + a_v)`` (towards -) or ``g + a_v <= 0`` (lift-off), with the direction
    (the sign of ``a``); ``None`` if there is none. The margins are checked on the scan
    grid of every piece (its ends for a linear piece), at the interior extrema of ``a``
    near a level (bounded minimisation), and the crossing refined by bisection."""

    def trips(t):
        ge = G + exc.vertical(t)
        a = exc(t)
        return ge <= 0.0 or a > c_p * ge or -a > c_m * ge

    def margin(t):  # > 0: trips (without the lift-off)
        ge = G + exc.vertical(t)
        a = exc(t)
        return max(a - c_p * ge, -a - c_m * ge)

    if trips(t_from):
        return t_from, math.copysign(1.0, exc(t_from))
    step = exc.scan_step if math.isfinite(exc.scan_step) else t_end - t_from
    level = min(c_p, c_m) * G
    k = exc.piece(t_from)
    t0 = t_from
    while True:
        hi = min(exc.end(k), t_end)
        n = 1 if exc.linear[k] else max(1, math.ceil((hi - t0) / step - 1e-9))
        grid = np.linspace(t0, hi, n + 1).tolist()
        for g0, g1 in zip(grid[:-1], grid[1:], strict=True):
            hit = g1 if trips(g1) else None
            if hit is None and not exc.linear[k] and max(margin(g0), margin(g1)) > \
                    -0.05 * level:
                res = minimize_scalar(lambda t: -margin(t), bounds=(g0, g1), method="bounded",
                                      options={"xatol": 1e-13})
                if trips(float(res.x)):
                    hit = float(res.x)
            if hit is not None:
                lo, up = g0, hit
                for _ in range(200):
                    mid = 0.5 * (lo + up)
                    if not lo < mid < up:
                        break
                    if trips(mid):
                        up = mid
                    else:
                        lo = mid
                return up, math.copysign(1.0, exc(up))
        if hi >= t_end or not math.isfinite(hi):
            return None
        t0 = hi
        k += 1


# ------------------------------------------------------------------------------ model
def free_amplitude(om, alpha, p, linear=False):
    """Amplitude reached in free motion from theta = 0 with angular velocity ``om``
    (energy conservation of Eq 1 with a = 0); inf if the block would pass alpha."""
    if linear:
        d = alpha * alpha - (om / p) ** 2
        return alpha - math.sqrt(d) if d > 0.0 else math.inf
    c = math.cos(alpha) + 0.5 * (om / p) ** 2
    return alpha - math.acos(c) if c < 1.0 else math.inf


def simulate_reference(block, motion=None, duration=None, theta0=0.0, omega0=0.0,
                       linear=False, rtol=1e-8, atol=None, method="DOP853",
                       rest_tol=DEFAULT_REST_TOL,
                       dt_out=None, max_free_time=None,
                       free_rest_tol=DEFAULT_FREE_REST_TOL):
    """Classical model integrated with :func:`scipy.integrate.solve_ivp` and events.

    Parameters
    ----------
    block : Block
    motion : Motion or None
        ``None``: free rocking from ``theta0``, ``omega0`` (then ``duration`` is required).
    duration : float, optional
        Simulated time (s), exactly; by default the motion and then free rocking until
        the block is at rest or has overturned, at most ``max_free_time`` more
        (:func:`rocking.models.run.run_window`; here no energy decision at the cap: a
        block still rocking there is unsettled).
    theta0, omega0 : float
        Initial angle (rad, in ``(-pi/2, pi/2)``) and angular velocity (rad/s).
    linear : bool
        Small-angle form of Eq 1.
    rtol, atol : float
        Tolerances of ``solve_ivp``; ``atol`` defaults to
        ``(1e-3 rtol alpha, 1e-3 rtol alpha p)`` for ``(theta, omega)``.
    method : str
        ``solve_ivp`` method, ``"DOP853"`` by default.
    rest_tol : float
        Zeno rule: rest when the post-impact free amplitude is below ``rest_tol * alpha``.
    free_rest_tol : float
        The same once the ground is still (after ``t_quiet``), as in the compiled model.
    dt_out : float, optional
        If given, the history is sampled on ``k * dt_out`` from the dense output; by
        default it holds the solver's own points (impact times appear twice, with the
        velocities before and after the impact).

    Returns
    -------
    Response
        ``info`` holds ``n_solve_ivp`` (number of calls) and ``nfev``.
    """
    # input validation is shared with the compiled model (the physics below is not)
    opts = Housner.from_kwargs(block, rtol=rtol, rest_tol=rest_tol,
                               free_rest_tol=free_rest_tol).options
    rtol, rest_tol, free_rest_tol = opts.rtol, opts.rest_tol, opts.free_rest_tol
    t_end, t_quiet, theta0, omega0 = check_run(motion, duration, theta0, omega0,
                                               max_free_time)
    if method not in METHODS:
        raise ParameterError(f"method must be one of {', '.join(METHODS)}; got {method!r}")
    if dt_out is not None:
        dt_out = positive("dt_out", dt_out, "s")
    sides = {1.0: (block.alpha_plus, block.p_plus, block.mu_plus),
             -1.0: (block.alpha_minus, block.p_minus, block.mu_minus)}
    alpha, p = min(sides[1.0][0], sides[-1.0][0]), max(sides[1.0][1], sides[-1.0][1])
    if atol is None:
        atol = [1e-3 * rtol * alpha, 1e-3 * rtol * alpha * p]
    else:
        atol = [positive("atol", x) for x in np.atleast_1d(atol)]
        if len(atol) not in (1, 2):
            raise ParameterError("atol must be a number or a pair (theta, omega)")

    linear = bool(linear)
    c_side = {s: (a if linear else math.tan(a)) for s, (a, _, _) in sides.items()}
    c_up = c_side[1.0]  # a symmetric block: one threshold
    thr = G * c_up
    exc = Excitation(motion)
    has_v = exc.vfns is not None
    lift_off_time = math.nan

    t, th, om = 0.0, theta0, omega0
    resting = th == 0.0 and om == 0.0
    uplift_time = math.nan if resting else 0.0
    s = 1.0 if (th > 0.0 or (th == 0.0 and om > 0.0)) else -1.0
    peak = abs(th)
    impacts: list[float] = []
    pieces: list[tuple] = []  # (t_start, t_stop, OdeResult or None for rest)
    overturned, t_over = False, None
    n_calls = nfev = 0
    stalls = 0

    while t < t_end:
        if resting:
            if t >= t_quiet:
                break  # the ground is still: at rest for good
            t_stop = min(t_end, t_quiet)
            up = (_first_exceedance(exc, t, t_stop, thr, c_up) if block.symmetric else
                  _first_exceedance_sides(exc, t, t_stop, c_side[1.0], c_side[-1.0]))
            if up is None:
                pieces.append((t, t_stop, None))
                t = t_stop
                break
            tu, sgn = up
            if tu > t:
                pieces.append((t, tu, None))
            if has_v and G + exc.vertical(tu) <= 0.0:
                lift_off_time = tu
                t = tu
                break
            t, th, om, s = tu, 0.0, 0.0, sgn
            resting = False
            if math.isnan(uplift_time):
                uplift_time = tu
        k = exc.piece(t)
        tb = min(exc.end(k), t_end)
        if tb <= t:  # zero-length piece (cannot happen with increasing starts)
            t = tb
            continue
        fn = exc.fns[k]
        vfn = exc.vfns[k] if has_v else _const(0.0)
        alpha, p, mu = sides[s]  # the side rocked on
        p2 = p * p

        def rhs(tt, y, s=s, fn=fn, vfn=vfn, alpha=alpha, p2=p2):
            a = fn(tt) / G
            gf = 1.0 + vfn(tt) / G
            if linear:
                return (y[1], gf * p2 * (y[0] - s * alpha) + p2 * a)
            x = alpha - s * y[0]
            return (y[1], -s * gf * p2 * math.sin(x) + p2 * math.cos(x) * a)

        def ev_lift(tt, y, vfn=vfn):
            return G + vfn(tt)

        def ev_impact(tt, y, s=s, t_start=t):
            # At the start of a piece that begins at theta = 0 (after an impact or an
            # uplift) the function is nudged positive, so that when one solver step spans
            # a whole small excursion the root search finds its end, not its start.
            if tt == t_start and y[0] == 0.0:
                return 1e-300
            return s * y[0]

        def ev_over(tt, y, s=s):
            return s * y[0] - HALF_PI

        def ev_peak(tt, y):
            return y[1]

        ev_impact.terminal, ev_impact.direction = True, -1.0
        ev_over.terminal, ev_over.direction = True, 1.0
        ev_peak.terminal, ev_peak.direction = False, 0.0
        ev_lift.terminal, ev_lift.direction = True, -1.0

        opts = {}
        if th == 0.0 and om != 0.0:
            # leaving theta = 0 against the acceleration: keep the first step within the
            # excursion, so that the return to theta = 0 is bracketed by the solver steps
            acc0 = rhs(t, (th, om))[1]
            if s * acc0 < 0.0:
                fs = max(0.5 * abs(om / acc0), 100.0 * math.ulp(max(t, 1.0)))
                opts["first_step"] = min(fs, tb - t)
        sol = solve_ivp(rhs, (t, tb), [th, om], method=method, rtol=rtol, atol=atol,
                        events=(ev_impact, ev_over, ev_peak, ev_lift),
                        dense_output=True, **opts)
        n_calls += 1
        nfev += sol.nfev
        if sol.status < 0:
            raise RuntimeError(f"solve_ivp failed at t = {t}: {sol.message}")
        missed = _missed_impact(sol, s, t)
        for te_p, ye in zip(sol.t_events[2], sol.y_events[2], strict=True):
            if missed is None or te_p < missed:
                peak = max(peak, abs(ye[0]))
        pieces.append((t, float(sol.t[-1]) if missed is None else missed, sol))
        if missed is not None:  # before any terminal event of this solve
            te_imp, om_imp = missed, float(sol.sol(missed)[1])
        elif sol.t_events[0].size and not sol.t_events[3].size and not sol.t_events[1].size:
            te_imp, om_imp = float(sol.t_events[0][0]), float(sol.y_events[0][0][1])
        else:
            te_imp = None
        if te_imp is None and sol.t_events[3].size:
            lift_off_time = float(sol.t_events[3][0])
            th, om = float(sol.y[0, -1]), float(sol.y[1, -1])
            peak = max(peak, abs(th))
            t = lift_off_time
            break
        if te_imp is None and sol.t_events[1].size:
            overturned = True
            t_over = float(sol.t_events[1][0])
            peak = HALF_PI
            t = t_over
            break
        if te_imp is not None:
            te = te_imp
            stalls = stalls + 1 if te <= t else 0
            if stalls > 10_000:
                raise RuntimeError(f"impacts do not advance in time at t = {t}")
            impacts.append(te)
            om = mu * om_imp
            th = 0.0
            t = te
            gf = 1.0 + exc.vertical(t) / G
            a_t = exc(t)
            c_t = c_side[1.0 if a_t > 0.0 else -1.0]  # the uplift towards sign(a)
            thr_t = c_t * G * gf if has_v else G * c_t
            a_n, p_n, _ = sides[1.0 if om > 0.0 else -1.0]  # the side it rebounds onto
            rt = rest_tol if t < t_quiet else max(rest_tol, free_rest_tol)
            if om == 0.0 or (free_amplitude(om, a_n, p_n * math.sqrt(max(gf, 1e-300)),
                                             linear) < rt * a_n
                             and abs(a_t) <= thr_t):
                resting = True  # uplift test again from here (immediate if |a| > thr)
                om = 0.0
            else:
                s = 1.0 if om > 0.0 else -1.0
            continue
        th, om = float(sol.y[0, -1]), float(sol.y[1, -1])
        peak = max(peak, abs(th))
        t = tb

    t_stop = t_over if overturned else (lift_off_time if has_v and lift_off_time == t
                                        else t)
    t_out, th_out, om_out = _history(pieces, dt_out, t_stop)
    return Response(
        t=t_out, theta=th_out, omega=om_out, impact_times=np.asarray(impacts, dtype=float),
        max_abs_theta=float(peak), overturned=overturned,
        overturn_time=math.nan if t_over is None else t_over, uplift_time=uplift_time,
        n_impacts=len(impacts),
        model=("housner-linear" if linear else "housner") + "-reference", block=block,
        motion=motion,
        info={"rtol": rtol, "method": method, "n_solve_ivp": n_calls, "nfev": int(nfev)},
        lift_off_time=lift_off_time,
        settled=overturned or (resting and math.isnan(lift_off_time)),
    )


def _missed_impact(sol, s, t0):
    """The time of an impact that the events missed, or None: a dip of ``s theta`` below 0
    and back inside one solver step has no sign change at the step's ends, so the impact
    event does not see it, but its minimum is a peak event (``omega = 0``) on the wrong
    side. The impact is then the first root of ``s theta`` before that minimum, in the
    solver step holding it, located on the dense output (a grid of 64, then
    :func:`scipy.optimize.brentq`)."""
    from scipy.optimize import brentq

    for tp, yp in zip(sol.t_events[2], sol.y_events[2], strict=True):
        if s * yp[0] >= 0.0:
            continue
        i = max(0, int(np.searchsorted(sol.t, tp)) - 1)
        ta = max(float(sol.t[i]), t0)
        grid = np.linspace(ta, tp, 65)
        g = s * sol.sol(grid)[0]
        pos = np.flatnonzero(g > 0.0)
        if pos.size == 0:
            return None  # no positive point to bracket from: leave it to the events
        j = int(pos[0])
        neg = np.flatnonzero(g[j:] <= 0.0)
        k = j + int(neg[0])
        return float(brentq(lambda x: s * sol.sol(x)[0], grid[k - 1], grid[k],
                            xtol=1e-15, rtol=4 * np.finfo(float).eps))
    return None


def _history(pieces, dt_out, t_stop):
    if dt_out is None:
        ts, ths, oms = [], [], []
        for ta, tb, sol in pieces:
            if sol is None:
                ts.append(np.array([ta, tb]))
                ths.append(np.zeros(2))
                oms.append(np.zeros(2))
            else:
                ts.append(sol.t)
                ths.append(sol.y[0])
                oms.append(sol.y[1])
        if not ts:
            return np.zeros(0), np.zeros(0), np.zeros(0)
        t = np.concatenate(ts)
        th = np.concatenate(ths)
        om = np.concatenate(oms)
        keep = np.ones(t.size, dtype=bool)  # drop the repeated joints of smooth pieces
        keep[1:] = ~((t[1:] == t[:-1]) & (om[1:] == om[:-1]) & (th[1:] == th[:-1]))
        return t[keep], th[keep], om[keep]
    n = int(math.floor(t_stop / dt_out + 1e-9)) + 1
    t = np.arange(n) * dt_out
    th = np.zeros(n)
    om = np.zeros(n)
    for ta, tb, sol in pieces:
        i0 = int(math.ceil(ta / dt_out - 1e-9))
        i1 = min(int(math.floor(tb / dt_out + 1e-9)), n - 1)
        if i1 < i0:
            continue
        if sol is None:
            th[i0:i1 + 1] = 0.0
            om[i0:i1 + 1] = 0.0
        else:
            y = sol.sol(np.clip(t[i0:i1 + 1], ta, tb))
            th[i0:i1 + 1] = y[0]
            om[i0:i1 + 1] = y[1]
    return t, th, om
