r"""Plain event-driven reference of a rigid block on a seismically isolated base.

Issue 19 (part 1). A rigid block (mass ``m``, :class:`~rocking.Block`: ``alpha``, ``p``,
``R``; ``I_O = m g R / p^2``, ``4/3 m R^2`` for a rectangle) stands free on a base plate of
mass ``m_b = mass_ratio * m``, which rests on an isolation layer, after Vassiliou and Makris
(2012), "Analysis of the rocking response of rigid blocks standing free on a seismically
isolated base", Earthquake Engng Struct. Dyn. 41, 177-196, and Roussis and Odysseos
(2017), "Rocking response of seismically-isolated rigid blocks under simple acceleration
pulses and earthquake excitations", Open Constr. Build. Technol. J. 11, 217-. The block
does not slide on the plate (enough friction) and does not fly. Written, like
:mod:`rocking.testing.housner_reference`, in plain Python on
:func:`scipy.integrate.solve_ivp` with events; it reuses only
:class:`~rocking.testing.housner_reference.Excitation` (the motion as smooth pieces).

Notation: ``M = m + m_b`` (the isolated mass), ``gamma = m / M = 1 / (1 + mass_ratio)``,
``b = R sin(alpha)``, ``h = R cos(alpha)`` (the half-width and the height of the centre of
mass above the base), ``lambda = m R^2 / I_O = R p^2 / g`` (3/4 for a rectangle).
``u`` is the plate's displacement relative to the ground, ``x_g`` the ground's, ``a_g =
x_g''``; ``A = a_g + u''`` is the plate's *absolute* acceleration.

Isolation layer (force ``F`` on the plate, opposing, per unit of ``M``):

* ``"linear"``: ``F / M = omega_b^2 u + 2 zeta_b omega_b u'`` with ``omega_b = 2 pi / T_b``:
  ``T_b = 2 pi sqrt(M / k)`` is the period of block and plate moving together, ``zeta_b``
  the damping ratio;
* ``"pendulum"`` (friction pendulum of radius ``R_c``, friction coefficient ``mu_f``):
  ``F / M = g u / R_c + mu_f g tanh(u' / v_eps)``: the restoring force ``M g u / R_c`` and
  Coulomb friction ``mu_f N sgn(u')`` regularised by ``tanh`` (``v_eps``, m/s). The normal
  force is taken as the weight, ``N = M g`` (exact while the block is at rest; the vertical
  inertia of the rocking block, ``m Y_c''``, is neglected in ``N``). Small oscillations
  (``mu_f = 0``) have the period ``2 pi sqrt(R_c / g)``; the plate does not slide while
  ``|a_g| < mu_f g`` (up to the creep ``v_eps atanh(|a_g| / (mu_f g))`` of the
  regularisation).

Vertical ground motion: with a vertical ground acceleration ``a_v`` (positive upwards;
:class:`rocking.motions.GroundMotion`) the plate moves vertically with the ground (the
isolation layer is rigid vertically), and in the frame of the ground every mass feels the
effective gravity ``g_e = g + a_v``: ``g`` becomes ``g_e`` in every gravity term below
(derivation in the next section), in the uplift threshold, ``g_e tan(alpha)``, and in the
friction pendulum's normal force, ``N = M g_e``: its restoring force ``M g_e u / R_c`` and
its friction ``mu_f M g_e tanh(u' / v_eps)`` both scale with ``g_e / g`` (a pendulum's
restoring force is the normal force times ``u / R_c``). The linear isolator's horizontal
stiffness and damping do not depend on the vertical load (taken so). Where ``g_e <= 0``
the base falls away faster than gravity and the block and plate would leave the ground;
neither model represents flight, so the run stops at the first such instant
(``lift_off_time``, not settled), as in :mod:`rocking.testing.housner_reference`.

Equations of motion (Lagrange)
------------------------------
Take the package's convention (Eq 1 of Peña et al.: a positive base acceleration drives
``theta`` positive): on the branch ``s = sgn(theta)`` the block pivots on the corner at
``x = -s b`` of the plate, ``theta`` is its counter-clockwise rotation and, with
``phi = alpha - s theta``, its centre of mass is at

.. math:: X_c = x_g + u - s b + s R \sin\phi, \qquad Y_c = R\cos\phi,

so ``X_c' = v - R cos(phi) theta'`` and ``Y_c' = s R sin(phi) theta'`` with ``v = x_g' + u'``
the plate's absolute velocity. The kinetic and potential energies are

.. math::

    T = \tfrac12 M v^2 - m R\cos\phi\; v\,\theta' + \tfrac12 I_O \theta'^2, \qquad
    V = m g R \cos\phi + V_{iso}(u),

and the isolator's damping or friction is a generalised force on ``u``. Lagrange's equation
for ``theta`` (the terms in ``v theta'`` cancel):

.. math:: I_O\,\theta'' = m R\,[\cos\phi\; A - s g \sin\phi]
          \;\Leftrightarrow\;
          \theta'' = p^2\,[\cos\phi\; A/g - s \sin\phi],

the classical Eq (1) with the ground acceleration replaced by the plate's absolute
acceleration ``A``. For ``u``:

.. math:: M A - m R\cos\phi\;\theta'' - s\, m R \sin\phi\;\theta'^2 = -F .

Eliminating ``theta''``:

.. math::

    A\,(1 - \gamma\lambda\cos^2\phi) = -F/M + s\,\gamma R \sin\phi\,(\theta'^2 - p^2\cos\phi),
    \qquad u'' = A - a_g,

then ``theta''`` from the first equation.

*With a vertical motion* the ground, and with it the plate and the pivot, is at height
``y_g(t)``, ``y_g'' = a_v``: then ``Y_c = y_g + R cos(phi)``; ``T`` gains
``m y_g' Y_c'`` (and terms in ``y_g'`` alone), ``V`` gains ``(m + m_b) g y_g``. In
Lagrange's equation for ``theta`` the new terms are ``d/dt (m y_g' dY_c/dtheta) -
m y_g' d(Y_c')/dtheta = m a_v dY_c/dtheta = m a_v s R sin(phi)``, the gravity term's
``m g s R sin(phi)`` with ``g -> a_v``; ``Y_c`` does not depend on ``u``, so the equation
for ``u`` gains nothing but the ``theta''`` it contains. Hence the equations above with
``g`` replaced by ``g_e = g + a_v`` in the gravity terms (not in ``p^2`` nor ``lambda``,
constants of the block), on both pivots ``s = +1, -1``:

.. math::

    \theta'' = p^2\,[\cos\phi\; A/g - s\,(g_e/g) \sin\phi], \qquad
    A\,(1 - \gamma\lambda\cos^2\phi) = -F/M
        + s\,\gamma R \sin\phi\,(\theta'^2 - p^2 (g_e/g)\cos\phi),

and the plate's equation ``u'' = A - a_g``, with ``F`` the isolator's force under the
normal force ``M g_e`` (above). ``1 - gamma lambda cos^2(phi) > 0`` since
``lambda <= 1``. As ``mass_ratio -> inf`` (``gamma -> 0``) ``A = -F/M`` is the isolated
oscillator's, unaffected by the block; a stiff isolator (``T_b -> 0``) then gives
``A -> a_g``: the classical model.

At rest
-------
With ``theta = theta' = 0`` block and plate move together: ``M A = -F``, i.e.
``u'' = -F/M - a_g`` (for the linear isolator ``u'' + 2 zeta_b omega_b u' + omega_b^2 u =
-a_g``, the oscillator of the whole mass). The block stays down while neither pivot can
start: on pivot ``s = +1`` (the corner at ``-b``) ``theta'' = p^2 [cos(alpha) A/g -
sin(alpha)] > 0`` needs ``A > g tan(alpha)``; on ``s = -1`` ``theta'' < 0`` needs
``A < -g tan(alpha)``. So the block uplifts, in the direction ``sgn(A)``, when
``|A| = |F| / M`` first exceeds ``g tan(alpha)`` (``g_e tan(alpha)`` under a vertical
motion, a threshold that jumps where ``a_v`` does). At rest ``A = -F(u, u')/M`` is a
continuous function of the state, so a jump of ``a_g`` cannot trigger the uplift by itself.
The coupled ``theta''`` vanishes at the threshold (substitute ``-F/M = s g tan(alpha)``
above: ``A = s g tan(alpha)``), so leaving rest is smooth.

Impact
------
When ``theta`` returns to 0 from the side ``s`` the block hits the plate with its other
corner (at ``x = +s b``), which becomes the pivot (``s -> -s``); the old pivot releases
(Housner's assumptions). The impulse at the new pivot is internal to block plus plate and the
isolator's force is finite, so the horizontal momentum of block plus plate, ``P = d T /
d u' = M v - m h theta'`` (at ``theta = 0``, ``R cos(phi) = h`` on both sides), is conserved;
the block's angular momentum about the new pivot (a fixed point of space at the instant of
impact) is conserved too. With the centre at ``(-s b, h)`` from the new pivot and its
velocity ``(v - h theta', s' b theta')`` on the branch ``s'``:

.. math::

    H_{before} = (I_O - 2 m b^2)\,\theta'_1 - m h v_1, \qquad
    H_{after} = I_O\,\theta'_2 - m h v_2, \qquad
    M v_2 - m h\,\theta'_2 = M v_1 - m h\,\theta'_1 .

The second gives ``v_2 - v_1 = gamma h (theta'_2 - theta'_1)``; in the first,
``theta'_2 (I_O - gamma m h^2) = theta'_1 (I_O - 2 m b^2 - gamma m h^2)``:

.. math::

    \mu_{iso} = \frac{\theta'_2}{\theta'_1}
              = 1 - \frac{2 m b^2 / I_O}{1 - \gamma\, m h^2 / I_O}
              = 1 - \frac{2\lambda\sin^2\alpha}{1 - \gamma\lambda\cos^2\alpha},
    \qquad \Delta u' = \Delta v = \gamma\, h\,(\mu_{iso} - 1)\,\theta'_1

(``x_g'`` is continuous). For a rectangle (``lambda = 3/4``)
``mu_iso = 1 - (3/2) sin^2(alpha) / (1 - (3/4) gamma cos^2(alpha))``, which tends to Eq 4,
``1 - (3/2) sin^2(alpha)``, as ``mass_ratio -> inf`` (``gamma -> 0``): a plate that cannot
move is the rigid base. A light plate takes part of the momentum (``mu_iso < mu``). With a
given restitution ``mu`` instead (``mu=...``: ``theta'_2 = mu theta'_1``) the plate's jump
follows from the momentum balance alone, ``Delta v = gamma h (mu - 1) theta'_1``; with
``mu = 1`` nothing changes and the energy is conserved.

Asymmetric blocks
-----------------
A body whose pivots are at different distances from its centre of mass
(:meth:`rocking.Block.from_geometry`, :meth:`rocking.Block.from_mesh`; Contento and Di
Egidio 2009): side ``s`` has its own ``alpha_s``, ``p_s``, ``R_s``, ``lambda_s = R_s p_s^2
/ g`` (``b_s = R_s sin(alpha_s)``; one height ``h = R_s cos(alpha_s)`` of the centre of
mass and one centroidal inertia ``m r_g^2 = I_{O_s} - m R_s^2``). On the branch ``s`` the
block pivots on the corner at ``x = -s b_s``, and the Lagrangian above holds with that
side's parameters (``phi = alpha_s - s theta``): the equations of motion are those above
with ``alpha, p, R, lambda`` replaced by ``alpha_s, p_s, R_s, lambda_s``. At rest the
block uplifts towards ``+`` when ``A > g_e tan(alpha_+)``, towards ``-`` when ``-A > g_e
tan(alpha_-)``.

At an impact that ends rocking on side ``s`` the block lands on the pivot ``o = -s``: with
the centre at ``(-s b_o, h)`` from it and its velocity ``(v - h theta', s b_s theta')``
before (rotation about the old pivot) and ``(v - h theta', -s b_o theta')`` after, the
angular momentum about the new pivot and the horizontal momentum ``P = M v - m h theta'``
give

.. math::

    H_{before} = m\,(r_g^2 + h^2 - b_s b_o)\,\theta'_1 - m h v_1, \qquad
    H_{after} = I_{O_o}\,\theta'_2 - m h v_2,

and, with ``v_2 - v_1 = gamma h (theta'_2 - theta'_1)`` as above,

.. math::

    \mu_{iso,s} = \frac{\theta'_2}{\theta'_1}
        = \frac{r_g^2 + h^2 - b_s b_o - \gamma h^2}{r_g^2 + R_o^2 - \gamma h^2}
        = 1 - \frac{\lambda_o \sin\alpha_o\,(\sin\alpha_o + (R_s/R_o)\sin\alpha_s)}
                   {1 - \gamma\lambda_o\cos^2\alpha_o},

which is :attr:`rocking.Block.mu_plus` / ``mu_minus`` (the fixed-base restitution of
:meth:`rocking.Block.from_geometry`, from the same angular momentum) as ``gamma -> 0`` and
the symmetric ``mu_iso`` for equal sides; ``Delta v = gamma h (mu_iso,s - 1) theta'_1``.
Where a block's sides do not make one rigid body exactly (a side changed by
:meth:`rocking.Block.with_params`, a drawn ``alpha`` scaling both sides) the impact takes
``h``, ``r_g`` and ``b_o`` from the landing side ``o`` (this reference and the compiled
model alike). A given ``mu`` applies to both sides.

Rest after an impact (Zeno rule, as in :mod:`rocking.testing.housner_reference`): if the
amplitude that free motion of the block on a fixed base would reach from the post-impact
``theta'`` (under the gravity ``g_e`` of that instant) is below ``rest_tol * alpha`` and
the plate cannot uplift the block there (towards either side), the block is put at rest;
the plate then takes the common velocity that conserves ``P``, ``v -> v - gamma h
theta'``. (The amplitude is that of the landing side, whose pivot the block now rocks
on.)

Overturning: ``|theta|`` reaches ``pi/2`` (the run stops). Clearance: ``|u|`` reaches
``clearance`` (the moat wall). Without a stop the run stops there and the time is an
outcome; with ``stop_period`` ``T_s`` the wall is a linear spring beyond the clearance, a
force per unit of ``M``

.. math:: F_s / M = \omega_s^2\,(|u| - c)\,\operatorname{sgn}(u) \quad (|u| > c),
          \qquad \omega_s = 2\pi / T_s,

(``T_s``: the period of block and plate on the spring alone), added to ``F``; it derives
from ``V_s = M omega_s^2 (|u| - c)^2 / 2``, so it conserves the energy, and the contacts
(``|u|`` crossing ``c`` either way) are located as events. Energy in free motion (``a_g =
0``): ``T + V`` above (``+ V_s``), conserved with ``zeta_b = 0`` (``mu_f = 0``) and
restitution 1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import minimize_scalar

from .._validate import positive
from ..errors import ParameterError
from ..motions import Motion
from ..units import G
from .housner_reference import Excitation

HALF_PI = 0.5 * math.pi
ISOLATIONS = ("linear", "pendulum")
DEFAULT_REST_TOL = 1e-12

__all__ = ["IsolatedResponse", "isolated_restitution", "isolation_force",
           "simulate_isolated_reference"]


def _geometry(block):
    """``(R, lambda)``: ``R`` from the block (a rectangle's ``3 g / (4 p^2)`` if unknown)
    and ``lambda = m R^2 / I_O = R p^2 / g``."""
    R = block.R if block.R is not None else 3.0 * G / (4.0 * block.p ** 2)
    return R, R * block.p ** 2 / G


def _side(block, s: float) -> tuple[float, float, float, float]:
    """``(alpha, p, R, lambda)`` of the side ``s`` (+1: the pivot of ``theta > 0``, -1:
    the other); ``R`` a rectangle's ``3 g / (4 p^2)`` if unknown."""
    alpha, p, R = ((block.alpha_plus, block.p_plus, block.R_plus) if s > 0.0
                   else (block.alpha_minus, block.p_minus, block.R_minus))
    R = R if R is not None else 3.0 * G / (4.0 * p ** 2)
    return alpha, p, R, R * p * p / G


def isolated_restitution(block, mass_ratio: float, side: str | None = None) -> float:
    """``mu_iso = theta'_after / theta'_before`` of an impact on a plate of mass
    ``mass_ratio * m`` (module docstring): ``1 - 2 lambda sin^2(alpha) / (1 - gamma lambda
    cos^2(alpha))``, ``gamma = 1 / (1 + mass_ratio)``, for a symmetric block; for an
    asymmetric one, that of the impact that ends rocking on ``side`` (``"+"`` or ``"-"``;
    None: the weaker side, the smaller ``alpha``) from the angular momentum about the new
    pivot (module docstring, asymmetric blocks)."""
    gam = 1.0 / (1.0 + mass_ratio)
    if block.symmetric:
        _, lam = _geometry(block)
        a = block.alpha
        return 1.0 - 2.0 * lam * math.sin(a) ** 2 / (1.0 - gam * lam * math.cos(a) ** 2)
    if side is None:
        side = "-" if block.alpha_minus < block.alpha_plus else "+"
    if side not in ("+", "-"):
        raise ParameterError(f"side must be '+' or '-', got {side!r}")
    s = 1.0 if side == "+" else -1.0
    a_s, _, R_s, _ = _side(block, s)
    a_o, p_o, R_o, _ = _side(block, -s)  # the landing side: the new pivot
    h, b_s, b_o = R_o * math.cos(a_o), R_s * math.sin(a_s), R_o * math.sin(a_o)
    rg2 = G * R_o / p_o ** 2 - R_o ** 2  # I_O = m (r_g^2 + R^2) = m g R / p^2
    return (rg2 + h * h - b_s * b_o - gam * h * h) / (rg2 + R_o * R_o - gam * h * h)


def isolation_force(isolation: str, u, v, *, period=None, damping=0.0, radius=None,
                    friction=0.0, v_eps=1e-4, g_e=G):
    """The isolator's force on the plate per unit of ``M = m + m_b`` (m/s^2), opposing;
    ``g_e`` is the effective gravity ``g + a_v`` (the friction pendulum's normal force)."""
    if isolation == "linear":
        w = 2.0 * math.pi / period
        return w * w * u + 2.0 * damping * w * v
    return g_e * u / radius + friction * g_e * np.tanh(v / v_eps)


@dataclass
class IsolatedResponse:
    """What :func:`simulate_isolated_reference` returns (SI units)."""

    t: np.ndarray
    theta: np.ndarray
    omega: np.ndarray
    u: np.ndarray
    """The plate's displacement relative to the ground (m)."""
    v: np.ndarray
    """``u'`` (m/s)."""
    max_abs_theta: float
    overturned: bool
    overturn_time: float
    uplift_time: float
    impact_times: np.ndarray
    max_abs_u: float
    max_plate_acc: float
    """Largest ``|A|``, the plate's absolute acceleration (m/s^2), on the solver's points
    and 8 dense points per step, refined (bounded scalar search on the dense output) where
    a piece's largest sample raises it."""
    clearance_exceeded: bool
    clearance_time: float
    restitution: float
    settled: bool
    lift_off_time: float = math.nan
    """When ``g + a_v`` first reached 0 (s; the run stopped there), NaN if never."""
    pieces: list = field(repr=False, default_factory=list)

    @property
    def n_impacts(self) -> int:
        return int(self.impact_times.size)

    def state_at(self, t: float) -> tuple[float, float, float, float]:
        """``(theta, theta', u, u')`` at ``t`` (at an impact: after it)."""
        found = None
        for ta, tb, sol, _ in self.pieces:
            if ta <= t <= tb:
                found = (ta, tb, sol)
        if found is None:
            raise ValueError(f"t = {t} is outside the simulated window")
        ta, tb, sol = found
        return tuple(float(x) for x in sol.sol(min(max(t, ta), tb)))


class _Callable:
    """A plain function ``a(t)`` (m/s^2) as something :class:`Excitation` takes."""

    def __init__(self, fn, scan_step):
        self.acceleration = fn
        self.scan_step = scan_step


def _free_amplitude(om, alpha, p):
    c = math.cos(alpha) + 0.5 * (om / p) ** 2
    return alpha - math.acos(c) if c < 1.0 else math.inf


def simulate_isolated_reference(block, motion_fn, t_end: float, mass_ratio: float,
                                isolation: str = "linear", *, period: float | None = None,
                                damping: float = 0.0, radius: float | None = None,
                                friction: float = 0.0, v_eps: float = 1e-4,
                                clearance: float = math.inf,
                                stop_period: float | None = None, mu: float | None = None,
                                theta0: float = 0.0, omega0: float = 0.0, u0: float = 0.0,
                                v0: float = 0.0, rtol: float = 1e-10, atol=None,
                                method: str = "DOP853", rest_tol: float = DEFAULT_REST_TOL,
                                scan_step: float | None = None,
                                max_step: float = math.inf) -> IsolatedResponse:
    """A block on an isolated base (module docstring) integrated with ``solve_ivp``.

    Parameters
    ----------
    block : Block
    motion_fn : Motion, callable ``a_g(t)`` (m/s^2, then ``scan_step`` is required) or None
    t_end : float
        Simulated time (s).
    mass_ratio : float
        ``m_b / m``.
    isolation : ``"linear"`` (``period`` ``T_b``, s, and ``damping`` ``zeta_b``) or
        ``"pendulum"`` (``radius`` ``R_c``, m, ``friction`` ``mu_f``, ``v_eps``, m/s).
    clearance : float
        The moat wall (m): the run stops when ``|u|`` reaches it, unless ``stop_period``.
    stop_period : float, optional
        The wall as a linear spring beyond ``clearance`` (module docstring; s).
    mu : float, optional
        Restitution ``theta'_after / theta'_before``; default :func:`isolated_restitution`.
    theta0, omega0, u0, v0 : the initial state (rad, rad/s, m, m/s).
    """
    t_end = positive("t_end", t_end, "s")
    mass_ratio = positive("mass_ratio", mass_ratio)
    if isolation not in ISOLATIONS:
        raise ParameterError(f"isolation must be one of {ISOLATIONS}; got {isolation!r}")
    if isolation == "linear":
        period = positive("period", period, "s")
    else:
        radius = positive("radius", radius, "m")
        if friction > 0.0:
            v_eps = positive("v_eps", v_eps, "m/s")
    if motion_fn is None or isinstance(motion_fn, Motion):
        exc = Excitation(motion_fn)
    else:
        exc = Excitation(_Callable(motion_fn, positive("scan_step", scan_step, "s")))
    has_v = exc.vfns is not None
    ws2 = 0.0
    if stop_period is not None:
        stop_period = positive("stop_period", stop_period, "s")
        if not math.isfinite(clearance):
            raise ParameterError("stop_period needs a finite clearance (m)")
        ws2 = (2.0 * math.pi / stop_period) ** 2

    sides = {1.0: _side(block, 1.0), -1.0: _side(block, -1.0)}  # (alpha, p, R, lambda)
    gam = 1.0 / (1.0 + mass_ratio)
    if mu is not None:
        mu_side = {1.0: float(mu), -1.0: float(mu)}
    elif block.symmetric:
        mu_side = dict.fromkeys((1.0, -1.0), isolated_restitution(block, mass_ratio))
    else:
        mu_side = {1.0: isolated_restitution(block, mass_ratio, "+"),
                   -1.0: isolated_restitution(block, mass_ratio, "-")}
    thr_s = {s: G * math.tan(sides[s][0]) for s in (1.0, -1.0)}  # uplift towards s
    a_lo = min(sides[1.0][0], sides[-1.0][0])
    p_hi = max(sides[1.0][1], sides[-1.0][1])
    if atol is None:
        atol = [1e-3 * rtol * a_lo, 1e-3 * rtol * a_lo * p_hi, 1e-12, 1e-12]

    def force(u, v, ge=G):
        f = isolation_force(isolation, u, v, period=period, damping=damping,
                            radius=radius, friction=friction, v_eps=v_eps, g_e=ge)
        if ws2 > 0.0 and abs(u) > clearance:
            f += ws2 * (abs(u) - clearance) * math.copysign(1.0, u)
        return f

    def plate_acc(y, s, rocking, ge=G):
        """The plate's absolute acceleration A and theta'' under the gravity ``ge``."""
        f = force(y[2], y[3], ge)
        if not rocking:
            return -f, 0.0
        alpha, p, R, lam = sides[s]
        p2 = p * p
        phi = alpha - s * y[0]
        c, sn = math.cos(phi), math.sin(phi)
        gf = ge / G
        A = (-f + s * gam * R * sn * (y[1] ** 2 - p2 * gf * c)) / (1.0 - gam * lam * c * c)
        return A, p2 * (c * A / G - s * gf * sn)

    def zero(tt):
        return 0.0

    t = 0.0
    y = np.array([theta0, omega0, u0, v0], dtype=float)
    rocking = not (theta0 == 0.0 and omega0 == 0.0)
    s = 1.0 if (theta0 > 0.0 or (theta0 == 0.0 and omega0 > 0.0)) else -1.0
    uplift_time = 0.0 if rocking else math.nan
    peak, peak_u, peak_a = abs(theta0), abs(u0), 0.0
    impacts: list[float] = []
    pieces: list = []
    overturned, t_over = False, math.nan
    cleared, t_clear = False, math.nan
    lift_off_time = math.nan
    stalls = 0

    while t < t_end:
        k = exc.piece(t)
        tb = min(exc.end(k), t_end)
        fn = exc.fns[k]
        vfn = exc.vfns[k] if has_v else zero
        ge0 = G + vfn(t)
        if ge0 <= 0.0:  # the base falls away at the start of this piece
            lift_off_time = t
            break
        if not rocking:  # uplift at once if |A| already exceeds the threshold
            A0 = -force(y[2], y[3], ge0)
            if A0 > thr_s[1.0] * ge0 / G or -A0 > thr_s[-1.0] * ge0 / G:
                rocking, s = True, math.copysign(1.0, A0)
                y[0] = y[1] = 0.0
                if math.isnan(uplift_time):
                    uplift_time = t

        def rhs(tt, yy, s=s, fn=fn, vfn=vfn, rocking=rocking):
            A, thdd = plate_acc(yy, s, rocking, G + vfn(tt))
            return (yy[1] if rocking else 0.0, thdd, yy[3], A - fn(tt))

        def ev_impact(tt, yy, s=s, t_start=t):
            if tt == t_start and yy[0] == 0.0:
                return 1e-300
            return s * yy[0]

        def ev_over(tt, yy, s=s):
            return s * yy[0] - HALF_PI

        def ev_clear(tt, yy, t_start=t):
            if tt == t_start and abs(yy[2]) == clearance:
                return 1e-300  # just left or reached the stop: not a new contact
            return abs(yy[2]) - clearance

        def ev_leave(tt, yy, t_start=t):
            if tt == t_start and abs(yy[2]) == clearance:
                return -1e-300
            return abs(yy[2]) - clearance

        def ev_up_p(tt, yy, vfn=vfn):
            ge = G + vfn(tt)
            return -force(yy[2], yy[3], ge) - thr_s[1.0] * ge / G

        def ev_up_m(tt, yy, vfn=vfn):
            ge = G + vfn(tt)
            return -force(yy[2], yy[3], ge) + thr_s[-1.0] * ge / G

        def ev_lift(tt, yy, vfn=vfn):
            return G + vfn(tt)

        def ev_peak(tt, yy):
            return yy[1]

        def ev_peak_u(tt, yy):
            return yy[3]

        ev_impact.terminal, ev_impact.direction = True, -1.0
        ev_over.terminal, ev_over.direction = True, 1.0
        ev_clear.terminal, ev_clear.direction = True, 1.0
        ev_leave.terminal, ev_leave.direction = True, -1.0
        ev_up_p.terminal, ev_up_p.direction = True, 1.0
        ev_up_m.terminal, ev_up_m.direction = True, -1.0
        ev_lift.terminal, ev_lift.direction = True, -1.0
        if rocking:
            events = [ev_impact, ev_over, ev_clear, ev_peak, ev_leave, ev_lift, ev_peak_u]
        else:
            events = [ev_up_p, ev_up_m, ev_clear, ev_leave, ev_lift, ev_peak_u]
        opts = {}
        if rocking and y[0] == 0.0 and y[1] != 0.0:
            acc0 = rhs(t, y)[1]
            if s * acc0 < 0.0:  # keep the first step within a small excursion
                fs = max(0.5 * abs(y[1] / acc0), 100.0 * math.ulp(max(t, 1.0)))
                opts["first_step"] = min(fs, tb - t)
        if ws2 > 0.0 and abs(y[2]) == clearance:  # on the wall: steps of the stop's scale
            opts["first_step"] = min(opts.get("first_step", math.inf), 0.01 * stop_period,
                                     tb - t)
        sol = solve_ivp(rhs, (t, tb), y, method=method, rtol=rtol, atol=atol,
                        events=events, dense_output=True, max_step=max_step, **opts)
        if sol.status < 0:
            raise RuntimeError(f"solve_ivp failed at t = {t}: {sol.message}")
        t1 = float(sol.t[-1])
        pieces.append((t, t1, sol, rocking))
        # peaks: events, ends, and |A| on the solver's points and dense points
        for ye in (sol.y_events[3] if rocking else []):
            peak = max(peak, abs(ye[0]))
        for ye in sol.y_events[-1]:
            peak_u = max(peak_u, abs(ye[2]))
        peak = max(peak, float(np.max(np.abs(sol.y[0]))))
        peak_u = max(peak_u, float(np.max(np.abs(sol.y[2]))))
        tt = sol.t
        if tt.size > 1:
            tt = np.concatenate([tt, (tt[:-1, None] + np.diff(tt)[:, None]
                                      * np.linspace(0, 1, 9)[None, 1:-1]).ravel()])
        tt = np.sort(tt)

        def abs_acc(x, sol=sol, s=s, rocking=rocking, vfn=vfn):
            return abs(plate_acc(sol.sol(x), s, rocking, G + vfn(x))[0])

        aa = np.array([abs_acc(x) for x in tt])
        i = int(np.argmax(aa))
        if aa[i] > peak_a and 0 < i < tt.size - 1:  # refine a peak inside the piece
            opt = minimize_scalar(lambda x: -abs_acc(x), bounds=(tt[i - 1], tt[i + 1]),
                                  method="bounded", options={"xatol": 1e-13})
            peak_a = max(peak_a, -float(opt.fun))
        peak_a = max(peak_a, float(aa[i]))
        y = sol.y[:, -1].copy()
        t = t1
        if sol.t_events[2].size or sol.t_events[-3].size:
            if sol.t_events[2].size and not cleared:
                cleared, t_clear = True, float(sol.t_events[2][0])
            if ws2 == 0.0:
                break
            y[2] = math.copysign(clearance, y[2])  # on the wall, to the event's accuracy
            continue
        if sol.t_events[-2].size:
            lift_off_time = float(sol.t_events[-2][0])
            break
        if rocking:
            if sol.t_events[1].size:
                overturned, t_over, peak = True, float(sol.t_events[1][0]), HALF_PI
                break
            if sol.t_events[0].size:
                te = float(sol.t_events[0][0])
                stalls = stalls + 1 if te <= pieces[-1][0] else 0
                if stalls > 10_000:
                    raise RuntimeError(f"impacts do not advance in time at t = {t}")
                impacts.append(te)
                ye = sol.y_events[0][0]
                om1 = float(ye[1])
                om2 = mu_side[s] * om1  # rocking on side s ends
                sn = 1.0 if om2 > 0.0 else -1.0  # the landing side
                a_n, p_n, R_n, _ = sides[sn]
                h = R_n * math.cos(a_n)
                v2 = float(ye[3]) + gam * h * (om2 - om1)
                y = np.array([0.0, om2, float(ye[2]), v2])
                v_rest = v2 - gam * h * om2  # plastic: the common velocity conserving P
                ge = G + vfn(te)
                pe = p_n * math.sqrt(max(ge / G, 1e-300))  # free rocking under g_e
                f_rest = force(y[2], v_rest, ge)
                if om2 == 0.0 or (_free_amplitude(om2, a_n, pe) < rest_tol * a_n
                                  and -f_rest <= thr_s[1.0] * ge / G
                                  and f_rest <= thr_s[-1.0] * ge / G):
                    y[1], y[3] = 0.0, v_rest
                    rocking = False
                else:
                    s = sn
                continue
        else:
            for j, sg in ((0, 1.0), (1, -1.0)):
                if sol.t_events[j].size and float(sol.t_events[j][0]) == t:
                    rocking, s = True, sg
                    y[0] = y[1] = 0.0
                    if math.isnan(uplift_time):
                        uplift_time = t
                    break

    ts, ys = [], []
    for _ta, _tb, sol, _ in pieces:
        ts.append(sol.t)
        ys.append(sol.y)
    tcat = np.concatenate(ts) if ts else np.zeros(0)
    ycat = np.concatenate(ys, axis=1) if ys else np.zeros((4, 0))
    return IsolatedResponse(
        t=tcat, theta=ycat[0], omega=ycat[1], u=ycat[2], v=ycat[3],
        max_abs_theta=float(peak), overturned=overturned, overturn_time=t_over,
        uplift_time=uplift_time, impact_times=np.asarray(impacts, dtype=float),
        max_abs_u=float(peak_u), max_plate_acc=float(peak_a),
        clearance_exceeded=cleared, clearance_time=t_clear,
        restitution=mu_side[-1.0 if block.alpha_minus < block.alpha_plus else 1.0],
        settled=(overturned or not rocking) and math.isnan(lift_off_time),
        lift_off_time=lift_off_time, pieces=pieces)
