r"""Linear elastic buildings with modal damping, described by their modes at the floors.

A building is a set of modes ``j`` with circular frequency ``omega_j = 2 pi / T_j``,
damping ratio ``zeta_j``, shape ``phi_j`` (at each floor, or as a function of the height
ratio ``z/H`` for the continuous model) and participation factor ``Gamma_j``
(``Gamma_j = phi_j^T M 1 / phi_j^T M phi_j``). Under a horizontal ground acceleration
``a_g(t)`` each mode is an oscillator (Chopra, *Dynamics of Structures*, 13.1)

    (B1)  u_j'' + 2 zeta_j omega_j u_j' + omega_j^2 u_j = -a_g(t),

and the absolute acceleration of a point at height ``z`` is

    (B2)  a(z, t) = a_g(t) + sum_j Gamma_j phi_j(z) u_j''(t),

exact with all modes of a discrete model and truncated to the modes given otherwise.
:meth:`Building.modal_factors` returns ``(omega_j, zeta_j, Gamma_j phi_j(z))`` at a
floor or a height ratio, which is all a floor motion needs
(:class:`rocking.buildings.FloorMotion`). ``Gamma_j phi_j`` does not depend on how the
shapes are normalised; :meth:`Building.continuous` gives ``phi_j = 1`` at the roof,
:meth:`Building.shear` a largest ``|phi_j|`` of 1, positive at the roof.

Constructors: :meth:`Building.sdof` (one oscillator; the floor is its mass),
:meth:`Building.modal` (modal properties from the user's own structural model, e.g.
exported from OpenSees or ETABS), :meth:`Building.shear` (a shear building) and
:meth:`Building.continuous` (Miranda and Taghavi's shear-flexural beam, 2005).

Shear building (Chopra 9.2, 10.2)
---------------------------------
Floor masses ``m_i`` and storey stiffnesses ``k_i`` (storey ``i`` joins level ``i - 1``
to level ``i``; level 0 is the ground) give ``M = diag(m_i)`` and the tridiagonal
``K_ii = k_i + k_{i+1}`` (``k_{N+1} = 0``), ``K_{i,i+1} = -k_{i+1}``; the modes solve

    (S1)  K phi_j = omega_j^2 M phi_j,      (S2)  Gamma_j = phi_j^T M 1 / phi_j^T M phi_j.

With uniform ``m`` and ``k`` (the closed form of this tridiagonal eigenproblem)

    (S3)  omega_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2N + 1))),
          phi_ij  ∝ sin((2j - 1) i pi / (2N + 1)).

Continuous shear-flexural beam (Miranda and Reyes 2002; Miranda and Taghavi 2005)
---------------------------------------------------------------------------------
A flexural cantilever (``EI``) and a shear cantilever (``GA``) tied by axially rigid links,
of uniform mass ``rho`` per height and height ``H``. With ``x = z/H`` and the lateral
stiffness ratio ``alpha = H sqrt(GA / EI)`` (the paper's ``alpha_0``), the free vibration
``u(x) e^{i omega t}`` satisfies

    (C1)  u'''' - alpha^2 u'' - (rho H^4 omega^2 / EI) u = 0,

with ``u = u' = 0`` at the base and, at the free top, no moment and no total shear:
``u'' = 0`` and ``u''' - alpha^2 u' = 0``. The roots ``r^2 = beta^2`` and ``-gamma^2`` of
``r^4 - alpha^2 r^2 - rho H^4 omega^2 / EI = 0`` give

    (C2)  beta_j^2 = gamma_j^2 + alpha^2,     omega_j^2 = (EI / rho H^4) gamma_j^2 beta_j^2,

the base conditions give the shape

    (C3)  phi_j(x) = sin(gamma_j x) - (gamma_j / beta_j) sinh(beta_j x)
                     + eta_j [cosh(beta_j x) - cos(gamma_j x)],
    (C4)  eta_j = (gamma_j^2 sin gamma_j + gamma_j beta_j sinh beta_j)
                  / (gamma_j^2 cos gamma_j + beta_j^2 cosh beta_j)      (u''(1) = 0),

and the shear condition at the top, with (C4), the characteristic equation

    (C5)  2 + [2 + alpha^4 / (gamma^2 beta^2)] cos(gamma) cosh(beta)
            + [alpha^2 / (gamma beta)] sin(gamma) sinh(beta) = 0.

Hence the period ratios and the participation factors (uniform mass)

    (C6)  T_1 / T_j = (gamma_j beta_j) / (gamma_1 beta_1),
    (C7)  Gamma_j = int_0^1 phi_j dx / int_0^1 phi_j^2 dx.

(C2)-(C7) are derived here from (C1) and its boundary conditions (``eta_j`` eliminated
between ``u''(1) = 0`` and ``u'''(1) = alpha^2 u'(1)``, then ``cosh^2 - sinh^2 = 1``);
they have the form of Miranda and Taghavi (2005), J. Struct. Eng. 131(2), whose text
could not be consulted here, so no equation number of the paper is quoted; the tests
check them against a finite-element model of the same beam.

Limits: ``alpha = 0`` gives ``cos(gamma) cosh(gamma) = -1``, the flexural cantilever
(``gamma_j = 1.8751, 4.6941, 7.8548, 10.9955``, ``T_1/T_j = (gamma_j/gamma_1)^2 = 1,
6.267, 17.55, 34.39``); ``alpha -> inf`` gives ``cos(gamma) = 0``, the shear cantilever
(``gamma_j = (2j - 1) pi / 2``, ``T_1/T_j = 2j - 1``, ``phi_j = sin(gamma_j x)``,
``Gamma_j phi_j(1) = 4 (-1)^(j+1) / ((2j - 1) pi)``). The operator of (C1) is self-adjoint
under these boundary conditions (the energy is ``int EI u''^2 + GA u'^2``), so the shapes
are orthogonal: ``int phi_i phi_j dx = 0`` for ``i != j``.

Numerics. (C5) is solved divided by ``(2 + alpha^4/(gamma^2 beta^2)) cosh(beta)``
(:func:`characteristic`), which tends to ``cos(gamma) + 1/cosh(gamma)`` as ``alpha -> 0``
and to ``cos(gamma)`` as ``alpha -> inf`` and never overflows; it is ``(-1)^j (1 +
o(1))`` at ``gamma = j pi`` and positive at ``gamma -> 0``, and it has exactly one root in
each ``((j - 1) pi, j pi)`` (checked on a fine grid for ``alpha`` from 0 to 1e4 and
against a finite-element model in the tests), found by :func:`scipy.optimize.brentq`.
(C3) is evaluated as ``sin(gamma x) - eta cos(gamma x) + P e^{beta (x - 1)} + Q e^{-beta
x}`` with ``P = (eta - gamma/beta) e^beta / 2`` and ``Q = (eta + gamma/beta) / 2`` written
without ``sinh``/``cosh`` of large arguments (:class:`ShearFlexuralShapes`): the direct
form (C3) loses every digit to cancellation for ``alpha`` above about 30 (``eta ->
gamma/beta`` and ``sinh``, ``cosh`` grow as ``e^beta``). The integrals of (C7) are closed
forms of that expression. ``alpha = math.inf`` is the exact shear limit.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy.linalg import eigh
from scipy.optimize import brentq

from .._validate import as_int, check_plausible, in_range, positive, warn_implausible
from ..errors import ParameterError

MAX_DAMPING = 1.0
"""Modal damping ratios are in [0, 1): an underdamped oscillator per mode."""

MAX_STOREYS = 1000
"""Largest number of storeys of :meth:`Building.shear` (and floors of a continuous
building)."""

MAX_CONTINUOUS_MODES = 50
"""Largest number of modes kept by :meth:`Building.continuous`."""

DEFAULT_CONTINUOUS_MODES = 6
"""Modes kept by :meth:`Building.continuous` by default (see its truncation note)."""


def _damping(damping, n: int) -> np.ndarray:
    """``damping`` as ``n`` ratios in [0, 1): one ratio for every mode, or one per mode."""
    shown = "[0, 1) (a ratio: 5 % is 0.05)"
    if np.ndim(damping) == 0:
        z = in_range("damping", damping, 0.0, MAX_DAMPING, lo_open=False, hi_open=True,
                     shown=shown)
        return np.full(n, z)
    try:
        arr = np.asarray(damping, dtype=object)
    except ValueError:  # ragged
        arr = None
    if arr is None or arr.shape != (n,):
        shape = "ragged" if arr is None else arr.shape
        raise ParameterError(f"damping must be one ratio or one per mode ({n}), got shape "
                             f"{shape}")
    items = list(arr)
    return np.array([in_range(f"damping[{i}]", x, 0.0, MAX_DAMPING, lo_open=False,
                              hi_open=True, shown=shown) for i, x in enumerate(items)])


def _positive_values(name: str, values, n: int, what: str) -> np.ndarray:
    """``values`` as ``n`` finite numbers > 0 (``None``: ``n`` ones)."""
    if values is None:
        return np.ones(n)
    if isinstance(values, str) or np.ndim(values) != 1 or len(values) != n:
        raise ParameterError(f"{name} must be {n} positive numbers ({what}, one per storey, "
                             f"bottom to top), got {values!r}")
    return np.array([positive(f"{name}[{i}]", x) for i, x in enumerate(values)])


def _heights(heights, n_floors: int) -> np.ndarray:
    """Height ratios ``z/H`` of levels 0..n_floors (``n_floors`` values: floors 1..N, the
    ground 0 is added), increasing in [0, 1] and rising to 1 (the top floor)."""
    try:
        h = np.asarray(heights, dtype=float).ravel()
    except (TypeError, ValueError):
        raise ParameterError(f"heights must be the height ratios z/H of the floors, got "
                             f"{heights!r}") from None
    if h.size == n_floors:
        h = np.concatenate([[0.0], h])
    if (h.size != n_floors + 1 or not np.all(np.isfinite(h)) or h[0] != 0.0
            or np.any(np.diff(h) <= 0.0) or h[-1] > 1.0):
        raise ParameterError(f"heights must be {n_floors} increasing height ratios z/H in "
                             f"(0, 1] (floors 1..{n_floors}; the ground, 0, may lead), got "
                             f"{heights!r}")
    if abs(h[-1] - 1.0) > 1e-9:
        raise ParameterError(f"heights must rise to 1 (z/H of the top floor, {n_floors}: H is "
                             f"the building's height), got {heights!r} ending at {h[-1]:g}; "
                             "divide the floors' heights by the top floor's")
    h[-1] = 1.0
    return h


# ---------------------------------------------------------------- the shear building
def shear_stiffness_matrix(stiffnesses) -> np.ndarray:
    """The tridiagonal stiffness matrix ``K`` of a shear building (module docstring, above
    (S1)) from its storey stiffnesses ``k_1..k_N``, bottom to top."""
    k = np.asarray(stiffnesses, dtype=float)
    above = np.append(k[1:], 0.0)
    return np.diag(k + above) - np.diag(k[1:], 1) - np.diag(k[1:], -1)


# ------------------------------------------------------------- the continuous beam
def _sech_tanh(b: float) -> tuple[float, float, float]:
    """``(e^{-b}, 1/cosh b, tanh b)`` without overflow for ``b >= 0``."""
    em = math.exp(-b)
    return em, 2.0 * em / (1.0 + em * em), (1.0 - em * em) / (1.0 + em * em)


def characteristic(gamma: float, alpha: float) -> float:
    """Left side of (C5) divided by ``(2 + alpha^4/(gamma^2 beta^2)) cosh(beta)``.

    With ``r = alpha^2 / (gamma beta)`` it is ``cos(gamma) + (2 sech(beta) + r sin(gamma)
    tanh(beta)) / (2 + r^2)``; finite for every ``alpha`` in [0, inf] (module docstring).
    """
    if math.isinf(alpha):
        return math.cos(gamma)
    b = math.hypot(gamma, alpha)
    _, sech, tanh = _sech_tanh(b)
    r = (alpha / gamma) * (alpha / b)
    if r < 1.0:
        return math.cos(gamma) + (2.0 * sech + r * math.sin(gamma) * tanh) / (2.0 + r * r)
    return math.cos(gamma) + (2.0 * sech / r + math.sin(gamma) * tanh) / (2.0 / r + r)


def shear_flexural_gammas(alpha: float, n_modes: int) -> np.ndarray:
    """The first ``n_modes`` roots ``gamma_j`` of (C5), one in each ``((j-1) pi, j pi)``."""
    if math.isinf(alpha):
        return (2.0 * np.arange(1, n_modes + 1) - 1.0) * (math.pi / 2.0)
    out = []
    for j in range(1, n_modes + 1):
        lo = (j - 1) * math.pi if j > 1 else 1e-9
        out.append(brentq(characteristic, lo, j * math.pi, args=(alpha,), xtol=1e-14,
                          rtol=4.0 * np.finfo(float).eps, maxiter=200))
    return np.array(out)


class ShearFlexuralShapes:
    """The mode shapes (C3) of the shear-flexural beam, ``phi_j(1) = 1``: ``shapes(x)``.

    Parameters
    ----------
    alpha : float
        Lateral stiffness ratio in [0, inf] (inf: the shear beam, ``phi_j = sin(gamma_j
        x) / sin(gamma_j)``).
    gammas : array_like
        Roots of (C5), :func:`shear_flexural_gammas`.

    Calling it with a height ratio ``x`` in [0, 1] gives the ``n_modes`` values
    ``phi_j(x)``; with an array of ``x``, an array of shape ``x.shape + (n_modes,)``.
    """

    def __init__(self, alpha: float, gammas):
        self.alpha = float(alpha)
        g = np.asarray(gammas, dtype=float)
        self.gammas = g
        if math.isinf(self.alpha):
            self.betas = np.full_like(g, math.inf)
            self.eta = np.zeros_like(g)
            self.P = np.zeros_like(g)
            self.Q = np.zeros_like(g)
        else:
            b = np.hypot(g, self.alpha)
            em = np.exp(-b)
            sech = 2.0 * em / (1.0 + em * em)
            tanh = (1.0 - em * em) / (1.0 + em * em)
            rho = g / b  # gamma/beta in (0, 1]
            s, c = np.sin(g), np.cos(g)
            d = 1.0 + rho * rho * c * sech  # (gamma^2 cos + beta^2 cosh) / (beta^2 cosh)
            self.betas = b
            self.eta = (rho * rho * s * sech + rho * tanh) / d  # (C4)
            # (eta - gamma/beta) e^beta / 2, with sinh - cosh = -e^{-beta} done exactly
            self.P = (rho * rho * s - rho ** 3 * c - rho * em) / (d * (1.0 + em * em))
            self.Q = 0.5 * (self.eta + rho)
        self.scale = 1.0 / self._raw(np.array(1.0))  # phi_j(1) = 1

    def _raw(self, x: np.ndarray) -> np.ndarray:
        x = np.asarray(x, dtype=float)[..., None]
        g = self.gammas
        out = np.sin(g * x) - self.eta * np.cos(g * x)
        if not math.isinf(self.alpha):
            b = self.betas
            out = out + self.P * np.exp(b * (x - 1.0)) + self.Q * np.exp(-b * x)
        return out

    def __call__(self, x) -> np.ndarray:
        xs = np.asarray(x, dtype=float)
        if not np.all((xs >= 0.0) & (xs <= 1.0)):
            raise ParameterError(f"height_ratio must be in [0, 1], got {x!r}")
        return self._raw(xs) * self.scale

    def integrals(self) -> tuple[np.ndarray, np.ndarray]:
        """``(int_0^1 phi_j dx, int_0^1 phi_j^2 dx)`` in closed form, for (C7)."""
        g = self.gammas
        s, c = np.sin(g), np.cos(g)
        eta = self.eta
        i1 = (1.0 - c) / g - eta * s / g
        i2 = (0.5 - np.sin(2 * g) / (4 * g) - eta * s * s / g
              + eta * eta * (0.5 + np.sin(2 * g) / (4 * g)))
        if not math.isinf(self.alpha):
            b, P, Q = self.betas, self.P, self.Q
            em = np.exp(-b)
            rho = g / b
            i1 = i1 + (P + Q) * (1.0 - em) / b
            i2 = i2 + (P * P + Q * Q) * (-np.expm1(-2.0 * b)) / (2.0 * b) + 2.0 * P * Q * em
            den = b * (1.0 + rho * rho)  # (beta^2 + gamma^2) / beta
            sp = (s - rho * c + rho * em) / den  # int sin(gamma x) e^{beta (x - 1)}
            cp = (c + rho * s - em) / den  # int cos(gamma x) e^{beta (x - 1)}
            sq = (rho - em * (s + rho * c)) / den  # int sin(gamma x) e^{-beta x}
            cq = (1.0 + em * (rho * s - c)) / den  # int cos(gamma x) e^{-beta x}
            i2 = i2 + 2.0 * (P * (sp - eta * cp) + Q * (sq - eta * cq))
        return i1 * self.scale, i2 * self.scale ** 2

    def __repr__(self) -> str:
        return f"ShearFlexuralShapes(alpha={self.alpha:g}, n_modes={self.gammas.size})"


def _alpha(alpha) -> float:
    """``alpha`` in [0, inf] (``math.inf`` allowed: the shear limit)."""
    shown = "[0, inf] (0: flexural cantilever, inf: shear cantilever)"
    if isinstance(alpha, bool | np.bool_):
        raise ParameterError(f"alpha must be a number in {shown}, not a bool, got {alpha!r}")
    try:
        a = float(alpha)
    except (TypeError, ValueError):
        raise ParameterError(f"alpha must be a number in {shown}, got {alpha!r}") from None
    if not a >= 0.0:  # also NaN
        raise ParameterError(f"alpha must be in {shown}, got {alpha!r}")
    return a


def _check_expansion(participation: np.ndarray, shapes: np.ndarray) -> None:
    """Warn when ``sum_j Gamma_j phi_j`` at a floor is far from 1: with every mode it is
    exactly 1 (the modes expand the rigid-body vector), with truncated modes close to it;
    far from 1 the participation factors and the shapes were normalised differently and
    every floor acceleration would be wrong by that factor."""
    total = shapes[1:] @ participation
    worst = int(np.argmax(np.abs(total - 1.0)))
    if not 0.0 <= total[worst] <= 2.0:
        warn_implausible(f"participation: sum_j Gamma_j phi_j at floor {worst + 1} is "
                         f"{total[worst]:.3g}, not about 1: are the participation factors "
                         "normalised with the same shapes (Gamma_j = phi_j^T M 1 / "
                         "phi_j^T M phi_j)?")


class Building:
    """A linear elastic building with modal damping (see the module docstring).

    Build one with :meth:`sdof`, :meth:`modal`, :meth:`shear` or :meth:`continuous`.

    Attributes
    ----------
    periods : ndarray
        Modal periods ``T_j`` (s), first mode first.
    damping : ndarray
        Modal damping ratios ``zeta_j``.
    participation : ndarray
        ``Gamma_j``.
    shapes : ndarray or None
        ``(n_floors + 1, n_modes)``: ``phi_j`` at the floors, row 0 the ground (zeros).
    shape_function : callable or None
        ``f(x) -> (n_modes,)``: ``phi_j`` at the height ratio ``x = z/H`` in [0, 1]
        (continuous model; discrete models give the floors only).
    heights : ndarray or None
        ``(n_floors + 1,)``: the height ratio ``z/H`` of each level, 0 (the ground) first.
    mass_matrix, stiffness_matrix : ndarray or None
        ``M`` and ``K`` of a shear building (:meth:`shear`; None otherwise), floors 1..N,
        in the unit of its ``masses`` (and that unit per s^2).
    storey_masses, storey_stiffnesses : ndarray or None
        Their diagonal and the storey stiffnesses ``k_1..k_N`` (bottom to top), scaled to
        the first period (:meth:`shear`).
    alpha : float or None
        Lateral stiffness ratio of a continuous building (:meth:`continuous`).

    Examples
    --------
    >>> import math
    >>> from rocking.buildings import Building
    >>> b = Building.shear(3, period=0.6)  # uniform masses and storey stiffnesses
    >>> ratio = math.sin(3 * math.pi / 14) / math.sin(math.pi / 14)  # omega_j ~ sin((2j-1) pi/14)
    >>> round(float(b.periods[0] / b.periods[1]), 4), round(ratio, 4)
    (2.8019, 2.8019)
    >>> omega, zeta, gamma_phi = b.modal_factors(floor=3)
    >>> round(float(gamma_phi.sum()), 6)  # sum of Gamma_j phi_j = 1 at every floor
    1.0
    """

    def __init__(self, periods, damping, participation, shapes=None,
                 shape_function: Callable | None = None, heights=None, name: str = "",
                 kind: str = "modal"):
        T = np.atleast_1d(np.asarray(periods, dtype=float))
        if T.ndim != 1 or T.size == 0:
            raise ParameterError("periods must be one or more modal periods (s)")
        for i, t in enumerate(T):
            positive(f"periods[{i}]", t, "s")
        check_plausible("building_period", float(T.max()), "the building's first period")
        self.periods = T
        self.damping = _damping(damping, T.size)
        g = np.atleast_1d(np.asarray(participation, dtype=float))
        if g.shape != T.shape or not np.all(np.isfinite(g)):
            raise ParameterError(f"participation must be one finite factor per mode "
                                 f"({T.size}), got {participation!r}")
        self.participation = g
        if shapes is None and shape_function is None:
            raise ParameterError("shapes: give the mode shapes at the floors")
        if shapes is not None:
            try:
                s = np.asarray(shapes, dtype=float)
            except (TypeError, ValueError):
                raise ParameterError(f"shapes must be (floors, modes) = (n, {T.size}) numbers, "
                                     "one row per floor with one value per mode") from None
            if s.ndim == 1 and T.size == 1:
                s = s[:, None]
            if s.ndim != 2 or s.shape[1] != T.size or not np.all(np.isfinite(s)):
                raise ParameterError(f"shapes must be (floors, modes) = (n, {T.size}) finite "
                                     f"values, got shape {s.shape}")
            if not np.all(s[0] == 0.0):
                s = np.vstack([np.zeros(T.size), s])  # the ground does not move
            shapes = s
        self.shapes = shapes
        self.shape_function = shape_function
        if shapes is not None:
            _check_expansion(g, shapes)
        if heights is not None and shapes is None:
            raise ParameterError("heights: give them with the shapes at the floors")
        self.heights = None if heights is None else _heights(heights, shapes.shape[0] - 1)
        self.name = str(name)
        self.kind = kind
        self.mass_matrix = self.stiffness_matrix = None
        self.storey_masses = self.storey_stiffnesses = None
        self.alpha = None

    # ------------------------------------------------------------------ constructors
    @classmethod
    def sdof(cls, period: float, damping: float = 0.05, name: str = "") -> Building:
        """One oscillator of period ``period`` (s) and damping ratio ``damping``: floor 1 is
        its mass (``Gamma phi = 1``).

        Examples
        --------
        >>> import math
        >>> from rocking.buildings import Building
        >>> b = Building.sdof(0.5, damping=0.05)
        >>> omega, zeta, gamma_phi = b.modal_factors(floor=1)
        >>> round(float(omega[0]), 4), round(2 * math.pi / 0.5, 4)  # omega = 2 pi / T
        (12.5664, 12.5664)
        >>> zeta.tolist(), gamma_phi.tolist()
        ([0.05], [1.0])
        """
        T = positive("period", period, "s")
        return cls([T], damping, [1.0], shapes=[[0.0], [1.0]], heights=[0.0, 1.0],
                   name=name or f"SDOF building, T = {T:g} s", kind="sdof")

    @classmethod
    def modal(cls, periods, damping, shapes, participation, heights=None,
              name: str = "") -> Building:
        """Modal properties from the user's own structural model: ``periods`` (s),
        ``damping`` (one ratio or one per mode), ``shapes`` ``(n_floors, n_modes)`` at
        floors 1..N (the ground row is added) and ``participation`` ``Gamma_j`` (with the
        same normalisation of the shapes); ``heights``, optional, the height ratios ``z/H``
        of floors 1..N (increasing, in (0, 1], the last 1: the top floor is at ``H``) for
        ``modal_factors(height_ratio=...)``.

        Examples
        --------
        The modes of a two-storey model solved by hand (unit masses and storey
        stiffnesses: ``K = [[2, -1], [-1, 1]]``, ``M = I``) give the floor factors of
        :meth:`shear` for the same building:

        >>> import numpy as np
        >>> from scipy.linalg import eigh
        >>> from rocking.buildings import Building
        >>> lam, phi = eigh([[2.0, -1.0], [-1.0, 1.0]])
        >>> gamma = phi.sum(axis=0) / (phi**2).sum(axis=0)  # (S2) with M = I
        >>> b = Building.modal(2 * np.pi / np.sqrt(lam), 0.05, phi, gamma)
        >>> ref = Building.shear(2, period=b.periods[0])
        >>> b.modal_factors(floor=2)[2].round(6), ref.modal_factors(floor=2)[2].round(6)
        (array([ 1.17082, -0.17082]), array([ 1.17082, -0.17082]))
        """
        return cls(periods, damping, participation, shapes=shapes, heights=heights,
                   name=name or "modal building", kind="modal")

    @classmethod
    def shear(cls, n_storeys: int, period: float, damping=0.05, masses=None,
              stiffnesses=None, heights=None, name: str = "") -> Building:
        """A shear building of ``n_storeys`` lumped floors, scaled to the first period.

        Parameters
        ----------
        n_storeys : int
            Number of storeys N in [1, 1000] (floors 1..N; floor N is the roof).
        period : float
            First-mode period ``T_1`` (s), > 0: the storey stiffnesses are scaled to it.
        damping : float or array_like
            Modal damping ratio in [0, 1), one for all modes or one per mode (N).
        masses, stiffnesses : array_like, optional
            N relative floor masses and storey stiffnesses, bottom to top, > 0 (default
            uniform). Storey ``i`` joins level ``i - 1`` to level ``i``.
        heights : array_like, optional
            N storey heights, bottom to top, > 0, in any unit (default equal: ``z/H =
            k/N``); they only place the floors at their ``z/H`` (:attr:`heights`).
        name : str
            A label.

        Notes
        -----
        Solves (S1) with :func:`scipy.linalg.eigh` and keeps all N modes, so that (B2) is
        exact; ``phi_j`` has a largest ``|phi_j|`` of 1 over the floors and is positive at
        the roof, and ``Gamma_j`` is (S2). ``mass_matrix`` is ``diag(masses)`` and
        ``stiffness_matrix`` is ``K`` scaled so that ``T_1 = period``.

        Examples
        --------
        Two uniform storeys: (S3) gives ``T_1 / T_2 = sin(3 pi/10) / sin(pi/10)``, the
        golden ratio squared, and a first mode with ``phi_1 / phi_2`` its inverse:

        >>> import math
        >>> from rocking.buildings import Building
        >>> b = Building.shear(2, period=0.5)
        >>> golden = (1 + math.sqrt(5)) / 2
        >>> round(float(b.periods[0] / b.periods[1]), 6), round(golden**2, 6)
        (2.618034, 2.618034)
        >>> round(float(b.shapes[1, 0] / b.shapes[2, 0]), 6), round(1 / golden, 6)
        (0.618034, 0.618034)
        """
        n = as_int("n_storeys", n_storeys, 1, MAX_STOREYS)
        T1 = positive("period", period, "s")
        zeta = _damping(damping, n)
        m = _positive_values("masses", masses, n, "relative floor masses")
        k0 = _positive_values("stiffnesses", stiffnesses, n, "relative storey stiffnesses")
        h = _positive_values("heights", heights, n, "storey heights")
        lam0, vec = eigh(shear_stiffness_matrix(k0), np.diag(m))
        scale = (2.0 * math.pi / T1) ** 2 / lam0[0]
        k = k0 * scale
        omegas = np.sqrt(lam0 * scale)
        # largest |phi_j| 1, roof positive (the roof value of a high mode of an irregular
        # building can be ~1e-11 of its largest: no good divisor)
        big = vec[np.argmax(np.abs(vec), axis=0), np.arange(n)]
        phi = vec / np.abs(big) * np.where(vec[-1] < 0.0, -1.0, 1.0)
        gam = (phi.T @ m) / np.einsum("ij,i,ij->j", phi, m, phi)
        z = np.concatenate([[0.0], np.cumsum(h)])
        z = z / z[-1]
        b = cls(2.0 * math.pi / omegas, zeta, gam, shapes=np.vstack([np.zeros(n), phi]),
                heights=z, name=name or f"{n}-storey shear building, T1 = {T1:g} s",
                kind="shear")
        b.periods[0] = T1  # exact, not 2 pi / sqrt(omega^2) rounded
        b.storey_masses, b.storey_stiffnesses = m, k
        b.mass_matrix, b.stiffness_matrix = np.diag(m), shear_stiffness_matrix(k)
        return b

    @classmethod
    def continuous(cls, period: float, alpha: float, damping=0.05,
                   n_modes: int = DEFAULT_CONTINUOUS_MODES, n_floors: int | None = None,
                   name: str = "") -> Building:
        """Miranda and Taghavi's (2005) uniform shear-flexural beam (module docstring).

        Parameters
        ----------
        period : float
            First-mode period ``T_1`` (s), > 0; ``T_j`` follow from (C6).
        alpha : float
            Lateral stiffness ratio ``alpha_0 = H sqrt(GA/EI)`` in [0, inf]: 0 is a
            flexural cantilever (walls), large a shear cantilever (frames), ``math.inf``
            the shear limit exactly. Any value is handled without overflow (module
            docstring, Numerics); above ~1e4 the modes equal the shear limit to ~1e-4.
        damping : float or array_like
            Modal damping ratio in [0, 1), one for all modes or one per mode.
        n_modes : int
            Modes kept, in [1, 50] (default 6).
        n_floors : int, optional
            In [1, 1000]: floors at ``z/H = k/n_floors`` for ``modal_factors(floor=k)``
            (default: ``height_ratio`` only).
        name : str
            A label.

        Notes
        -----
        ``phi_j(1) = 1``; ``Gamma_j`` is (C7) in closed form. Truncation: (B2) adds the
        ground acceleration itself, so modes much stiffer than the excitation add almost
        nothing (their relative acceleration is small); the first 6 modes carry 96.6 % of
        the mass of the shear beam and 93.3 % of the flexural one (``sum Gamma_j^2 int
        phi_j^2``), and their periods reach ``T_1/11`` and ``T_1/85``.

        Examples
        --------
        The two limits of the module docstring: the flexural cantilever (``alpha = 0``,
        ``T_1/T_j = (gamma_j/gamma_1)^2 = 1, 6.267, 17.55``) and the shear cantilever
        (``T_1/T_j = 2j - 1``, ``Gamma_1 phi_1(1) = 4/pi``).

        >>> import math
        >>> from rocking.buildings import Building
        >>> wall = Building.continuous(1.0, alpha=0.0, n_modes=3)
        >>> (1 / wall.periods).round(2)
        array([ 1.  ,  6.27, 17.55])
        >>> frame = Building.continuous(1.0, alpha=math.inf, n_modes=3)
        >>> (1 / frame.periods).round(6), round(4 / math.pi, 6)
        (array([1., 3., 5.]), 1.27324)
        >>> round(float(frame.modal_factors(height_ratio=1.0)[2][0]), 6)
        1.27324
        """
        T1 = positive("period", period, "s")
        a = _alpha(alpha)
        nm = as_int("n_modes", n_modes, 1, MAX_CONTINUOUS_MODES)
        zeta = _damping(damping, nm)
        nf = None if n_floors is None else as_int("n_floors", n_floors, 1, MAX_STOREYS)
        g = shear_flexural_gammas(a, nm)
        freq = g if math.isinf(a) else g * np.hypot(g, a)  # omega_j ∝ gamma_j beta_j (C2)
        periods = T1 * freq[0] / freq
        periods[0] = T1
        shapes_fn = ShearFlexuralShapes(a, g)
        i1, i2 = shapes_fn.integrals()
        shapes = heights = None
        if nf is not None:
            heights = np.arange(nf + 1) / nf
            shapes = shapes_fn(heights)
            shapes[0] = 0.0  # phi(0) = 0 exactly (rounding leaves ~1e-16)
        label = "inf" if math.isinf(a) else f"{a:g}"
        b = cls(periods, zeta, i1 / i2, shapes=shapes, shape_function=shapes_fn,
                heights=heights, kind="continuous",
                name=name or f"shear-flexural building, alpha = {label}, T1 = {T1:g} s")
        b.alpha = a
        return b

    # ------------------------------------------------------------------ the modes
    @property
    def n_modes(self) -> int:
        return int(self.periods.size)

    @property
    def n_floors(self) -> int | None:
        """Floors above the ground (None for a continuous model without floors)."""
        return None if self.shapes is None else self.shapes.shape[0] - 1

    @property
    def omegas(self) -> np.ndarray:
        """Circular frequencies ``2 pi / T_j`` (rad/s)."""
        return 2.0 * math.pi / self.periods

    def modal_factors(self, floor: int | None = None, height_ratio: float | None = None
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(omega_j, zeta_j, Gamma_j phi_j)`` at ``floor`` (0 is the ground) or at the
        height ratio ``z/H`` (continuous models, or a discrete model's floor heights).

        Examples
        --------
        With every mode the rigid-body vector is expanded exactly: ``sum_j Gamma_j phi_j =
        1`` at each floor, 0 at the ground. A continuous building's floor 2 of 4 is its
        height ratio 0.5:

        >>> from rocking.buildings import Building
        >>> b = Building.shear(4, period=0.8)
        >>> [round(float(b.modal_factors(floor=k)[2].sum()), 6) for k in range(5)]
        [0.0, 1.0, 1.0, 1.0, 1.0]
        >>> c = Building.continuous(1.0, alpha=5.0, n_floors=4)
        >>> bool(np.allclose(c.modal_factors(floor=2)[2], c.modal_factors(height_ratio=0.5)[2]))
        True
        """
        if (floor is None) == (height_ratio is None):
            raise ParameterError("floor or height_ratio: give exactly one")
        if floor is not None:
            if self.shapes is None:
                raise ParameterError(f"floor: this {self.kind} building has no floors; give "
                                     "height_ratio (z/H)")
            k = as_int("floor", floor, 0, self.n_floors)
            phi = self.shapes[k]
        else:
            x = in_range("height_ratio", height_ratio, 0.0, 1.0, lo_open=False, hi_open=False,
                         shown="[0, 1]")
            if self.shape_function is not None:
                phi = np.asarray(self.shape_function(x), dtype=float)
            elif self.heights is not None:
                hits = np.flatnonzero(np.isclose(self.heights, x, rtol=0, atol=1e-12))
                if hits.size == 0:
                    raise ParameterError(f"height_ratio {x:g} is not a floor of this building "
                                         f"(floors at z/H = {np.round(self.heights, 4)})")
                phi = self.shapes[hits[0]]
            else:
                raise ParameterError("height_ratio: this building gives its floors only")
        return self.omegas, self.damping, self.participation * phi

    def __repr__(self) -> str:
        T = ", ".join(f"{t:.3g}" for t in self.periods[:3])
        more = ", ..." if self.n_modes > 3 else ""
        return (f"Building({self.name!r}, {self.n_modes} mode(s), T = [{T}{more}] s, "
                f"zeta = {self.damping[0]:g})")
