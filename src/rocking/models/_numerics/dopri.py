"""Compiled building blocks shared by the model kernels: a Dormand-Prince 5(4) step for a
second-order scalar equation ``theta'' = f(t, theta)`` and quintic Hermite interpolation.

Kept model-agnostic: the right-hand side is passed in as a compiled function.
"""

from __future__ import annotations

import math

from numba import njit

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
def err_norm(e_th, e_om, th0, th1, om0, om1, atol_th, atol_om, rtol):
    """RMS of the scaled error estimates (the usual mixed absolute/relative norm)."""
    s1 = atol_th + rtol * max(abs(th0), abs(th1))
    s2 = atol_om + rtol * max(abs(om0), abs(om1))
    return math.sqrt(0.5 * ((e_th / s1) ** 2 + (e_om / s2) ** 2))
