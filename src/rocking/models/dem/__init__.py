r"""The discrete element model (DEM): rigid polygons on contact springs (Peña et al. 2007,
Section 2.3 and Eqs 14-22), in the style of UDEC, as ``model="dem"``.

Unlike the classical and CCRR models, the blocks here have three degrees of freedom each
(horizontal and vertical translation of the centroid, rotation), so they can bounce,
slide and stack: ``rocking.simulate(rocking.Stack([b1, b2]), motion, model="dem")``.

**Frame and ground motion.** We integrate in the frame of the base (the shaking table).
A rigid base with a prescribed acceleration ``a_t(t)`` is dynamically equivalent to a
fixed base with the body force ``-M a_t`` on every block: the contact forces depend only
on relative positions and relative velocities (all the damping is in the contacts), so
nothing else changes. This is exact and needs no integration of the acceleration into
table displacements (no baseline correction, no drift). With the sign convention of the
paper's Eq (1) (a positive ``a`` drives ``theta`` positive, see
:mod:`rocking.models.housner`) the body force is ``-M a(t)`` along +x: it tilts the block
counter-clockwise about its left base corner O, and ``theta`` is the counter-clockwise
rotation of the block. ``x`` and ``y`` are thus displacements *relative to the base*.

**Blocks.** Rigid convex polygons (:meth:`rocking.Block.polygon`; rectangles and the
specimens' cut corners). The geometry used for a :class:`~rocking.Block` is chosen by the
``geometry`` option:

* ``"polygon"``: the block's own polygon (:attr:`Block.vertices`), with the mass and the
  inertia of the polygon;
* ``"equivalent"``: the paper's equivalent block (Eq 18): a rectangle of the block's
  height ``2h`` and width ``2 b_eq = 2 h tan(alpha)``, whose moment of inertia is set to
  ``I_O = M g R / p^2`` so that ``alpha`` *and* ``p`` are exactly the block's; its
  plastic-impact restitution is then not ``mu`` in general;
* ``"classical"``: the rigid rectangle whose ``alpha``, ``p`` *and* Housner restitution
  are the block's: half-diagonal ``R = (1 - mu) g / (2 p^2 sin^2 alpha)`` (from
  ``mu = 1 - 2 M R^2 sin^2(alpha) / I_O`` and ``p^2 = M g R / I_O``), inertia from ``p``.
  It exists when ``mu > cos(2 alpha)``. For Table II's T parameters of specimen 2 it is
  the Table I rectangle to 0.1 %; for its E parameters (``mu`` = 0.973 exceeds Eq 4) it
  is 0.61 m tall instead of 1 m. The classical models depend on ``alpha``, ``p``
  and ``mu`` only, and this body reproduces them with well-damped contacts (the damping
  calibrated to ``mu`` is then the plastic-impact one). The DEM's restitution lies between
  its undamped (bouncing) value and the plastic impact of its body
  (:func:`rocking.models.dem.calibrate_damping`): the Eq 18 body reaches the E values of ``mu``
  only with nearly undamped contacts on which the landing corner bounces, and its forced
  response is then erratic (specimen 2 overturns under the 5 Hz, 5 mm sine of Fig 7, where
  the classical model reaches 1.77 degrees);
* ``"auto"`` (default): the polygon if the block's ``alpha`` and ``p`` are those of its
  polygon (a block built from its geometry), else the classical body (the equivalent one
  if ``mu <= cos(2 alpha)``).

A block with no known mass gets that of granite (2650 kg/m^3) times its area and
thickness (1 m if unknown); the rocking motion does not depend on it (the default
stiffness scales with the mass).

**Contacts.** Vertex-to-edge, detected geometrically at every step: a vertex of one block
is in contact with an edge of another block (or with the base, the half-plane ``y < 0``)
when it penetrates it, lies within the edge's span (extended by a rounding length
``r = 1e-3`` of the smaller block size, so that coincident corners of stacked blocks of
equal width stay in contact) and faces it (the vertex's outward normal opposes the
edge's). Of two coincident corners, only the upper block's counts. A flat face on a flat
face therefore has two contact points, at its ends (the paper's "contact points located
at the corners"). Each contact point has

* a normal spring ``K`` (N/m), linear in compression, no tension;
* a shear spring ``Ks = K`` (default), incremental (the shear force is history, kept per
  (vertex, edge) pair), elastic-perfectly plastic with the Coulomb limit
  ``|Fs| <= Fn tan(phi) + c`` (``phi``: the option ``friction_angle``, in rad like every
  angle of the package, default 30 degrees = ``math.radians(30.0)``, or a string such as
  ``"30deg"``; a bare number ``>= pi/2`` cannot be an angle in rad and is read as degrees,
  deprecated, :mod:`.friction`; ``c``: cohesion, N per contact point, 0 by default);
* viscous dashpots ``C = b K`` and ``b Ks`` (stiffness-proportional Rayleigh damping,
  no mass-proportional part, as in the paper's Section 4.4), only while the contact is
  closed: the normal force ``K d - b K d_dot`` is clipped at zero (no tension), and a
  sliding contact carries only its Coulomb force.

A vertex that separates or leaves the edge's span ends the contact and resets its shear
force.

**Default stiffness.** ``K = M g / (2 delta_0)`` per contact point with
``delta_0 = 1e-7 H``: the static settlement of a block (or of a stack, with its total mass
``M`` and height ``H``) standing on two contact points is 1e-7 of its height, 0.1 µm for
the 1 m specimens (``K = 1.1e10 N/m`` for specimen 2). That is physical for granite: an
elastic half-space loaded over a strip the length of the thickness ``t`` has a stiffness
of order ``E t``, 2.5e10 N/m for ``E = 50 GPa`` and ``t = 0.5 m``; and it is a joint
stiffness ``K / (b t) = 2.6e11 Pa/m`` over half the base of specimen 2 (rock joints:
1e9 - 1e12 Pa/m). See :mod:`rocking.models.dem.parameters` for why the paper's
``K = M p^2`` (Eq 17) cannot be a stiffness in N/m.

**Default damping.** ``b`` is calibrated so that the apparent coefficient of restitution
of one impact in free rocking equals the block's ``mu``
(:func:`rocking.models.dem.calibrate_damping`).

**Integration.** Explicit central differences, as in UDEC: velocities at half steps,
positions at full steps; the damping and the shear-spring increments use the half-step
relative velocities. The time step is ``0.8 x 2 (sqrt(1 + xi^2) - xi) / omega_max``, the
stability limit of the scheme with the lagged stiffness-proportional damping
(``xi = b omega_max / 2``; the characteristic equation of the scheme gives exactly this
bound), where ``omega_max`` is the highest natural frequency of the blocks on their
closed contacts (an eigenvalue problem solved once, at rest). It is capped at
``0.2 / omega_max`` (about 30 steps per period of the stiffest mode): a contact closes and
opens between steps, which central differences resolve to first order only, and at the
stability limit an undamped bouncing block gains or loses percents of its energy at each
impact (with the default, calibrated damping the stability limit is already below the
cap). The step is then rounded down to divide the output interval. Everything per step
runs in one compiled numba function; :func:`rocking.simulate_many` runs a batch in
parallel.

**Response.** ``theta`` is the rotation of the block (for a stack: of the top block; all
blocks in ``theta_all``, ``x_all``, ``y_all``, shape ``(n_blocks, n_t)``); ``x``, ``y``
the displacement of its centroid relative to the base (``y`` from its nominal position
on undeformed contacts, so that at rest ``y`` is minus the settlement). Impacts are the
sign changes of ``theta`` (located by linear interpolation between steps, counted once
``|theta|`` has exceeded ``impact_tol`` since the previous one); ``uplift_time`` is the
first time a closed contact opens; the block *overturns* when any block's ``|theta|``
reaches ``pi/2`` or a block of a stack falls onto the base. Initial conditions
``theta0``, ``omega0`` rotate the whole stack rigidly about the bottom block's pivot
corner. By default the blocks start at static equilibrium (``settled=True``: the contact
springs already carry the weights).

**Package layout.** :mod:`.geometry` (bodies, Eq 18, the packed assembly),
:mod:`.friction` (the friction angle, rad), :mod:`.kernel` (compiled contact law and
central differences), :mod:`.statics` (stiffness, stable step, static equilibrium),
:mod:`.parameters` (the paper's Eqs 14-22 and Table III),
:mod:`.calibration` (the damping that gives ``mu``), :mod:`.model` (the model class
:class:`DEM` behind :func:`rocking.simulate`).
"""

from .calibration import XI_CAP, calibrate_damping, damping_cap, free_rocking_restitution
from .friction import DEFAULT_FRICTION_ANGLE, check_friction_angle
from .geometry import (
    DEFAULT_SETTLEMENT,
    GEOMETRIES,
    ROUNDING,
    Assembly,
    Body,
    body_of,
    build_assembly,
    default_stiffness,
)
from .model import DEM, DEMOptions
from .parameters import (
    EQ20,
    READINGS,
    paper_parameters,
    refit_eq20,
    settlement,
    settlement_table,
    table3,
)
from .statics import (
    ACCURACY,
    SAFETY,
    contacts_at,
    initial_state,
    omega_max,
    stable_dt,
    static_state,
    stiffness_matrix,
)

__all__ = [
    "DEM", "DEMOptions", "Assembly", "Body", "body_of", "build_assembly", "default_stiffness",
    "calibrate_damping", "damping_cap", "free_rocking_restitution", "paper_parameters",
    "refit_eq20", "settlement", "settlement_table", "table3", "contacts_at", "initial_state",
    "omega_max", "stable_dt", "static_state", "stiffness_matrix", "DEFAULT_SETTLEMENT",
    "GEOMETRIES", "ROUNDING", "EQ20", "READINGS", "XI_CAP", "ACCURACY", "SAFETY",
    "DEFAULT_FRICTION_ANGLE", "check_friction_angle",
]
