"""Compiled evaluation of base motions, shared by every model kernel.

A motion reaches compiled code as a *spec*: an integer ``kind``, a float parameter vector
``prm`` (``prm[0]`` is always a load factor) and a sample array (empty except for
records). ``ground_acc`` evaluates the horizontal acceleration at one time;
``next_breakpoint`` gives the next time at which the acceleration (of either component)
has a kink or a jump, so that integrators can step exactly onto it.

A vertical component (:class:`rocking.motions.GroundMotion`) travels in the same spec,
written by :func:`with_vertical` only and read by the named accessors :func:`has_vertical`,
:func:`vertical_is_record`, :func:`vertical_acc` and :func:`ground_acc_hv` (no other module
indexes ``prm`` beyond the horizontal parameters):
``prm[:NPRM1]`` is the horizontal motion, ``prm[V_KIND]`` the vertical motion's kind
(``NONE``: no vertical component), ``prm[V_OFFSET]`` the index where its samples start in
``samples`` (after the horizontal record's), ``prm[V0:V0 + NPRM1]`` its parameters and
``prm[V_SAME]`` 1 when both components are records on the same time grid (one
interpolation index serves both: :func:`ground_acc_hv`).
``vertical_acc`` evaluates it (m/s^2, positive upwards).

**Three components** (a 3-D body: two horizontal components and the vertical one,
:meth:`rocking.motions.Motion.spec3`, :meth:`rocking.motions.HorizontalPair.spec3`). A
three-component spec is a spec as above whose ``prm`` is longer, :data:`NPRM3`, written by
:func:`with_axes` only: ``prm[AXES:AXES + 4] = (wx1, wx2, wy1, wy2)`` give the body's
horizontal components from the two horizontal components ``h1``, ``h2`` of the spec:
``ax = wx1 h1 + wx2 h2``, ``ay = wy1 h1 + wy2 h2`` (the weights of the body's ``x`` and
``y`` axes, :func:`rocking.motions.components.plane_weights`). ``h1`` is what
:func:`ground_acc` reads and ``h2`` is 0, except for the kind :data:`PAIR` (written by
:func:`pair_spec`): two records on one time grid, ``prm[:3] = (scale, dt, n)`` and
``samples[:n]``, ``samples[n:2 n]`` the first and the second component (the scale applies
to both); a vertical component follows in the vertical slot as above (its samples from
``2 n``; ``prm[V_SAME] = 1`` when it is a record on the same grid: one interpolation index
for the three). :func:`ground_acc3` reads any spec, planar or not: a planar spec (length
:data:`NPRM`, today's) answers ``(a, 0, a_v)``. The planar accessors (:func:`ground_acc`,
:func:`ground_acc_hv`) do not read a :data:`PAIR` spec: project it on a plane first
(``HorizontalPair.on_plane``); :func:`next_breakpoint` reads every spec.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

NONE = 0
RECORD = 1  # prm: scale, dt, n
SINE = 2  # prm: scale, freq, amplitude (displacement), duration, phase
HANNING = 3  # prm: scale, freq, amplitude (displacement), duration
ONE_SINE = 4  # prm: scale, amplitude (acc), period, t0
ONE_COSINE = 5  # prm: scale, amplitude (acc), period, t0
HALF_SINE = 6  # prm: scale, amplitude (acc), length, t0
RECTANGULAR = 7  # prm: scale, amplitude (acc), length, t0
RICKER = 8  # prm: scale, amplitude (acc), peak frequency, centre time
MAVROEIDIS_PAPAGEORGIOU = 9  # prm: scale, velocity amplitude A, fp, gamma, nu, centre t0
PAIR = 10  # prm: scale, dt, n; samples: first (n), second (n): three-component specs only

NPRM1 = 6  # parameters of one component
V_KIND = 6  # prm[V_KIND]: kind of the vertical component (NONE: none)
V_OFFSET = 7  # prm[V_OFFSET]: first index of its samples
V0 = 8  # prm[V0:V0 + NPRM1]: its parameters
V_SAME = V0 + NPRM1  # prm[V_SAME] = 1: both components are records on the same time grid
NPRM = V_SAME + 1
AXES = NPRM  # prm[AXES:AXES + 4] = (wx1, wx2, wy1, wy2): the body's axes (3 components)
NPRM3 = AXES + 4
TWO_PI = 2.0 * math.pi


@njit(cache=True)
def ground_acc(kind, prm, samples, t):
    """Horizontal ground acceleration (m/s^2) at time ``t`` of the motion
    ``(kind, prm, samples)``."""
    s = prm[0]
    if kind == NONE:
        return 0.0
    if kind == RECORD:
        dt = prm[1]
        n = min(int(prm[2]), samples.shape[0])
        if t < 0.0 or n == 0:
            return 0.0
        x = t / dt
        i = int(math.floor(x))
        if i >= n - 1:
            # the last sample holds at t = (n-1) dt exactly, zero after the end
            if i == n - 1 and x - i < 1e-9:
                return s * samples[n - 1]
            return 0.0
        f = x - i
        return s * (samples[i] + f * (samples[i + 1] - samples[i]))
    if kind == SINE:
        f, X, dur, ph = prm[1], prm[2], prm[3], prm[4]
        if t < 0.0 or t > dur:
            return 0.0
        w = TWO_PI * f
        return -s * X * w * w * math.sin(w * t + ph)
    if kind == HANNING:
        f, X, dur = prm[1], prm[2], prm[3]
        if t < 0.0 or t > dur:
            return 0.0
        w = TWO_PI * f
        W = TWO_PI / dur
        win = 0.5 * (1.0 - math.cos(W * t))
        dwin = 0.5 * W * math.sin(W * t)
        ddwin = 0.5 * W * W * math.cos(W * t)
        # second derivative of the table displacement X * win(t) * sin(w t)
        return s * X * (ddwin * math.sin(w * t) + 2.0 * dwin * w * math.cos(w * t)
                        - win * w * w * math.sin(w * t))
    if kind == MAVROEIDIS_PAPAGEORGIOU:
        # exact derivative of v = A/2 [1 + cos(w tau / gamma)] cos(w tau + nu), w = 2 pi fp,
        # for |tau| <= gamma / (2 fp) (Mavroeidis and Papageorgiou 2003)
        A, fp, gam, nu, tc = prm[1], prm[2], prm[3], prm[4], prm[5]
        tau = t - tc
        half = 0.5 * gam / fp
        if tau < -half or tau > half:
            return 0.0
        w = TWO_PI * fp
        u = w * tau / gam
        ph = w * tau + nu
        return -0.5 * s * A * w * (math.sin(u) * math.cos(ph) / gam
                                   + (1.0 + math.cos(u)) * math.sin(ph))
    A, T, t0 = prm[1], prm[2], prm[3]
    if kind == RICKER:
        x = math.pi * T * (t - t0)  # T holds the peak frequency here
        return s * A * (1.0 - 2.0 * x * x) * math.exp(-x * x)
    tau = t - t0
    if tau < 0.0 or tau > T:
        return 0.0
    if kind == ONE_SINE:
        return s * A * math.sin(TWO_PI * tau / T)
    if kind == ONE_COSINE:
        return s * A * math.cos(TWO_PI * tau / T)
    if kind == HALF_SINE:
        return s * A * math.sin(math.pi * tau / T)
    if kind == RECTANGULAR:
        return s * A
    return 0.0


@njit(cache=True)
def has_vertical(prm):
    """Whether the spec carries a vertical component."""
    return prm.shape[0] > V_KIND and prm[V_KIND] != 0.0


@njit(cache=True)
def vertical_is_record(prm):
    """Whether the vertical component is a sampled record (linear between samples)."""
    return has_vertical(prm) and prm[V_KIND] == RECORD


def with_vertical(kind, prm, samples, v_kind, v_prm, v_samples):
    """``(prm, samples)`` of the horizontal spec ``(kind, prm, samples)`` carrying the
    vertical spec ``(v_kind, v_prm, v_samples)``: the one place that writes the layout of
    the module docstring (the kernels read it through :func:`has_vertical`,
    :func:`vertical_is_record`, :func:`vertical_acc` and :func:`ground_acc_hv`)."""
    prm = prm.copy()
    prm[V_KIND] = v_kind
    prm[V_OFFSET] = samples.size
    prm[V0:V0 + NPRM1] = v_prm[:NPRM1]
    n_h = 2 * int(prm[2]) if kind == PAIR else int(prm[2])  # horizontal samples
    if ((kind == RECORD or kind == PAIR) and v_kind == RECORD and v_prm[1] == prm[1]
            and v_prm[2] == prm[2] and samples.size == n_h):
        prm[V_SAME] = 1.0
    return prm, np.ascontiguousarray(np.concatenate([samples, v_samples]))


@njit(cache=True)
def vertical_acc(prm, samples, t):
    """Vertical ground acceleration (m/s^2, positive upwards) at time ``t``; 0 without a
    vertical component. A vertical record is read in place (no slicing: this runs at every
    evaluation of a model's right-hand side)."""
    if not has_vertical(prm):
        return 0.0
    if prm[V_KIND] == RECORD:
        return _interp(samples, int(prm[V_OFFSET]), int(prm[V0 + 2]), prm[V0 + 1], prm[V0], t)
    return ground_acc(int(prm[V_KIND]), prm[V0:], samples[int(prm[V_OFFSET]):], t)


@njit(cache=True)
def ground_acc_hv(kind, prm, samples, t):
    """``(horizontal, vertical)`` accelerations at ``t`` (m/s^2): :func:`ground_acc` and
    :func:`vertical_acc`, with one interpolation index when both are records on the same
    time grid (a three-component set)."""
    if prm[V_SAME] == 1.0:  # set by GroundMotion.spec: the vertical samples follow at n
        dt, n = prm[1], int(prm[2])
        off = n
        if t < 0.0 or n == 0:
            return 0.0, 0.0
        x = t / dt
        i = int(math.floor(x))
        if i >= n - 1:
            if i == n - 1 and x - i < 1e-9:
                return prm[0] * samples[n - 1], prm[V0] * samples[off + n - 1]
            return 0.0, 0.0
        f = x - i
        return (prm[0] * (samples[i] + f * (samples[i + 1] - samples[i])),
                prm[V0] * (samples[off + i] + f * (samples[off + i + 1] - samples[off + i])))
    return ground_acc(kind, prm, samples, t), vertical_acc(prm, samples, t)


@njit(cache=True)
def next_breakpoint(kind, prm, samples, t):
    """The first time > ``t`` (+1e-12) where either component has a kink or jump (inf if
    none)."""
    b = _breakpoint(kind, prm, samples, t)
    if has_vertical(prm):
        b = min(b, _breakpoint(int(prm[V_KIND]), prm[V0:], samples[int(prm[V_OFFSET]):], t))
    return b


@njit(cache=True)
def _breakpoint(kind, prm, samples, t):
    """:func:`next_breakpoint` of one component."""
    eps = 1e-12
    if kind == RECORD or kind == PAIR:
        dt = prm[1]
        n = min(int(prm[2]), samples.shape[0])
        end = (n - 1) * dt
        if t < -eps:
            return 0.0
        if t >= end - eps:
            return math.inf
        k = math.floor(t / dt + 1e-9) + 1.0
        return min(k * dt, end)
    if kind == SINE or kind == HANNING:
        dur = prm[3]
        if t < -eps:
            return 0.0
        if t < dur - eps:
            return dur
        return math.inf
    if kind >= ONE_SINE and kind <= RECTANGULAR:
        t0, T = prm[3], prm[2]
        if t < t0 - eps:
            return t0
        if t < t0 + T - eps:
            return t0 + T
        return math.inf
    if kind == MAVROEIDIS_PAPAGEORGIOU:
        half = 0.5 * prm[3] / prm[2]
        start, end = prm[5] - half, prm[5] + half
        if t < start - eps:
            return start
        if t < end - eps:
            return end
        return math.inf
    return math.inf


@njit(cache=True)
def acc_many(kind, prm, samples, t):
    """Vectorised :func:`ground_acc` over an array of times."""
    out = np.empty(t.shape[0])
    for i in range(t.shape[0]):
        out[i] = ground_acc(kind, prm, samples, t[i])
    return out


# ---------------------------------------------------------------- three components
def pair_spec(dt, first, second, scale=1.0):
    """``(PAIR, prm, samples)`` of two horizontal records ``first``, ``second`` (m/s^2) on
    one time grid of step ``dt`` (s), of equal lengths, times ``scale``; ``prm`` of length
    :data:`NPRM3`, the body's axes along the components (:func:`with_axes` turns them)."""
    n = first.size
    if second.size != n:
        raise ValueError("the two components must have the same number of samples")
    prm = np.zeros(NPRM3)
    prm[0], prm[1], prm[2] = scale, dt, float(n)
    prm[AXES:AXES + 4] = (1.0, 0.0, 0.0, 1.0)
    samples = np.ascontiguousarray(np.concatenate([first, second]), dtype=np.float64)
    return PAIR, prm, samples


def with_axes(prm, wx, wy):
    """``prm`` (a planar or three-component spec's) of length :data:`NPRM3` with the body's
    axes: ``ax = wx[0] h1 + wx[1] h2``, ``ay = wy[0] h1 + wy[1] h2`` (module docstring)."""
    out = np.zeros(NPRM3)
    out[:NPRM] = prm[:NPRM]
    out[AXES:AXES + 4] = (wx[0], wx[1], wy[0], wy[1])
    return out


@njit(cache=True)
def _interp(samples, off, n, dt, s, t):
    """``s`` times the record ``samples[off:off + n]`` (step ``dt``) at ``t``, as
    :func:`ground_acc` reads a record."""
    if t < 0.0 or n == 0:
        return 0.0
    x = t / dt
    i = int(math.floor(x))
    if i >= n - 1:
        if i == n - 1 and x - i < 1e-9:
            return s * samples[off + n - 1]
        return 0.0
    f = x - i
    return s * (samples[off + i] + f * (samples[off + i + 1] - samples[off + i]))


@njit(cache=True)
def ground_acc3(kind, prm, samples, t):
    """``(ax, ay, az)``: the ground acceleration (m/s^2) at ``t`` of any spec in the body's
    frame (module docstring): ``ax``, ``ay`` horizontal, ``az`` vertical, positive upwards;
    ``(a, 0, a_v)`` for a planar spec."""
    if kind == PAIR:
        s, dt, n = prm[0], prm[1], int(prm[2])
        if prm[V_SAME] == 1.0:  # one interpolation index for the three components
            off = int(prm[V_OFFSET])
            if t < 0.0 or n == 0:
                h1 = h2 = av = 0.0
            else:
                x = t / dt
                i = int(math.floor(x))
                if i >= n - 1:
                    if i == n - 1 and x - i < 1e-9:
                        h1, h2 = s * samples[n - 1], s * samples[2 * n - 1]
                        av = prm[V0] * samples[off + n - 1]
                    else:
                        h1 = h2 = av = 0.0
                else:
                    f = x - i
                    h1 = s * (samples[i] + f * (samples[i + 1] - samples[i]))
                    h2 = s * (samples[n + i] + f * (samples[n + i + 1] - samples[n + i]))
                    av = prm[V0] * (samples[off + i] + f * (samples[off + i + 1]
                                                            - samples[off + i]))
        else:
            h1 = _interp(samples, 0, n, dt, s, t)
            h2 = _interp(samples, n, n, dt, s, t)
            av = vertical_acc(prm, samples, t)
    else:
        h1, av = ground_acc_hv(kind, prm, samples, t)
        h2 = 0.0
    if prm.shape[0] < NPRM3:
        return h1, h2, av
    return (prm[AXES] * h1 + prm[AXES + 1] * h2, prm[AXES + 2] * h1 + prm[AXES + 3] * h2,
            av)


@njit(cache=True)
def acc3_many(kind, prm, samples, t):
    """Vectorised :func:`ground_acc3` over an array of times: an array ``(len(t), 3)``."""
    out = np.empty((t.shape[0], 3))
    for i in range(t.shape[0]):
        ax, ay, az = ground_acc3(kind, prm, samples, t[i])
        out[i, 0] = ax
        out[i, 1] = ay
        out[i, 2] = az
    return out
