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

With a vertical ground acceleration ``a_v`` (positive upwards) ``g`` would become
``g + a_v`` in every gravity term below; this reference takes horizontal motions only.

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

then ``theta''`` from the first equation. ``1 - gamma lambda cos^2(phi) > 0`` since
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
``|A| = |F| / M`` first exceeds ``g tan(alpha)``. At rest ``A = -F(u, u')/M`` is a
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

Rest after an impact (Zeno rule, as in :mod:`rocking.testing.housner_reference`): if the
amplitude that free motion of the block on a fixed base would reach from the post-impact
``theta'`` is below ``rest_tol * alpha`` and the plate cannot uplift the block there, the
block is put at rest; the plate then takes the common velocity that conserves ``P``,
``v -> v - gamma h theta'``.

Overturning: ``|theta|`` reaches ``pi/2`` (the run stops). Clearance: ``|u|`` reaches
``clearance`` (the moat wall; no stop is modelled, so the run stops there and the time is
an outcome). Energy in free motion (``a_g = 0``): ``T + V`` above, conserved with
``zeta_b = 0`` (``mu_f = 0``) and restitution 1.
"""

from __future__ import annotations

__all__: list[str] = []
