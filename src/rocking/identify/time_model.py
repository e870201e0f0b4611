r"""The time model of free rocking: the quarter period (Eq 11, corrected) and Eq 13.

Between two impacts energy is conserved,
``theta'^2 = 2 p^2 [cos(alpha - r) - cos(alpha - |theta|)]`` for a half-cycle of amplitude
``r``, so the time from the peak ``r`` to ``theta = 0`` is the energy integral

.. math::

    T(r) = \frac{1}{p\sqrt 2}\int_0^r \frac{dx}{\sqrt{\cos(\alpha - r) - \cos(\alpha - x)}}

(Eq 11 as printed, with ``cos(x - alpha) - cos(alpha)`` under the root and the amplitude in
the limits only, is not this integral). :func:`quarter_time` evaluates it with the
substitution ``x = r (1 - u^2)``, which removes the inverse-square-root singularity at
``x = r``, and a fixed 32-point Gauss-Legendre rule in ``u`` (error < 1e-10 for
``r < 0.98 alpha``), vectorised over ``r``, ``alpha`` and ``p``. Since ``T = G(r, alpha) / p``,
the error surface of Eq 13 (:func:`sigma_surface`) is a quadratic in ``1/p`` for each
``alpha``.
"""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError

_N_GAUSS = 32
_gx, _gw = np.polynomial.legendre.leggauss(_N_GAUSS)
_U = 0.5 * (_gx + 1.0)
_WU = 0.5 * _gw * _U  # weights with the Jacobian factor u of x = r (1 - u^2)
_HALF_U2 = 0.5 * _U * _U


def scaled_quarter_time(r, alpha):
    """``p * T(r)``: the quarter-period integral without the 1/p (broadcasting).

    With ``x = r (1 - u^2)``, ``cos(alpha - r) - cos(alpha - x)`` becomes
    ``2 sin(alpha - r + r u^2 / 2) sin(r u^2 / 2)``, and
    ``p T = int_0^1 r u du / sqrt(sin(alpha - r + r u^2/2) sin(r u^2/2))``, smooth in ``u``.
    ``inf`` where ``r >= alpha`` (the block does not come back), 0 where ``r == 0``.
    """
    r = np.asarray(r, dtype=float)[..., None]
    a = np.asarray(alpha, dtype=float)[..., None]
    s = r * _HALF_U2
    with np.errstate(invalid="ignore", divide="ignore"):
        f = np.sin(a - r + s) * np.sin(s)
        val = np.sum(_WU * r / np.sqrt(f), axis=-1)
    rr, aa = r[..., 0], a[..., 0]
    val = np.where(rr >= aa, np.inf, val)
    return np.where(rr == 0.0, 0.0, val)


def scaled_quarter_time_dalpha(r, alpha):
    """``d(p T)/d alpha`` (same broadcasting as :func:`scaled_quarter_time`)."""
    r = np.asarray(r, dtype=float)[..., None]
    a = np.asarray(alpha, dtype=float)[..., None]
    s = r * _HALF_U2
    with np.errstate(invalid="ignore", divide="ignore"):
        sa = np.sin(a - r + s)
        val = -0.5 * np.sum(_WU * r * np.cos(a - r + s) / (sa * np.sqrt(sa * np.sin(s))),
                            axis=-1)
    return np.where(r[..., 0] == 0.0, 0.0, val)


def quarter_time(r, alpha, p):
    """Time (s) from a peak of amplitude ``r`` (rad) to ``theta = 0`` in free rocking.

    The exact quarter period of the classical model (energy conservation), vectorised:
    ``r``, ``alpha`` and ``p`` broadcast against each other. ``inf`` where ``r >= alpha``.
    For ``r << alpha`` it tends to ``sqrt(2 r / sin(alpha)) / p``; for slender blocks, to
    the linearised model's ``acosh(alpha / (alpha - r)) / p``.

    Examples
    --------
    The first impact of specimen 2 released at half its critical angle, against the
    simulation and the linearised model:

    >>> import math
    >>> import rocking
    >>> from rocking.identify import quarter_time
    >>> block = rocking.specimen(2)
    >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0)
    >>> round(float(quarter_time(0.5 * block.alpha, block.alpha, block.p)), 4)
    0.3459
    >>> round(float(r.impact_times[0]), 4), round(math.acosh(2) / block.p, 4)
    (0.3459, 0.3457)
    """
    r = np.abs(np.asarray(r, dtype=float))
    p = np.asarray(p, dtype=float)
    return scaled_quarter_time(r, alpha) / p


def sigma_surface(amplitudes, durations, alpha, p, weights=None):
    """The error surface of Eq 13, ``Sigma = sum_j w_j^2 (tau_j - T(r_j; alpha, p))^2``.

    ``amplitudes`` (rad) and ``durations`` (s) are 1-D and pair each measured time interval
    (crossing to peak or peak to crossing) with the amplitude of its half-cycle;
    ``weights`` (1/s, default 1) scale each interval. ``alpha`` and ``p`` broadcast against
    each other (e.g. from :func:`numpy.meshgrid`); the result has their broadcast shape.
    The cost is one quadrature per distinct ``alpha``: ``Sigma`` is a quadratic in ``1/p``.

    Examples
    --------
    Durations computed with the true parameters make ``Sigma`` vanish there, and only
    there:

    >>> from rocking.identify import quarter_time, sigma_surface
    >>> amps = np.array([0.08, 0.05, 0.03])
    >>> durations = quarter_time(amps, 0.168, 3.81)
    >>> S = sigma_surface(amps, durations, [0.168, 0.150], 3.81)
    >>> bool(abs(S[0]) < 1e-12), bool(S[1] > 1e-4)
    (True, True)
    """
    r = np.abs(np.asarray(amplitudes, dtype=float)).ravel()
    d = np.asarray(durations, dtype=float).ravel()
    if r.size != d.size:
        raise ParameterError(f"amplitudes and durations must have the same length, got "
                             f"{r.size} and {d.size}")
    w2 = np.ones_like(d) if weights is None else np.asarray(weights, float).ravel() ** 2
    alpha, p = np.broadcast_arrays(np.asarray(alpha, float), np.asarray(p, float))
    ua, inv = np.unique(alpha, return_inverse=True)
    A, B, C = sigma_coefficients(r, d, w2, ua)
    inv = inv.reshape(alpha.shape)
    q = 1.0 / p
    return A - 2.0 * B[inv] * q + C[inv] * q * q


def sigma_coefficients(r, d, w2, alphas, chunk: int = 64):
    """Coefficients of ``Sigma(alpha, p) = A - 2 B / p + C / p^2`` for each alpha."""
    A = float(np.sum(w2 * d * d))
    B = np.empty(alphas.size)
    C = np.empty(alphas.size)
    for i in range(0, alphas.size, chunk):
        G = scaled_quarter_time(r[None, :], alphas[i:i + chunk, None])
        B[i:i + chunk] = np.sum(w2 * d * G, axis=1)
        C[i:i + chunk] = np.sum(w2 * G * G, axis=1)
    return A, B, C

