r"""The absolute acceleration of a building's floor: the base motion of an object inside.

A linear building with modal damping (:class:`~rocking.buildings.Building`) filters the
horizontal ground acceleration ``a_g(t)``. Each mode ``j`` is an oscillator (Chopra,
*Dynamics of Structures*, 13.1)

.. math::  \ddot u_j + 2 \zeta_j \omega_j \dot u_j + \omega_j^2 u_j = -a_g(t)

and the absolute acceleration of the floor (or height ratio) where the modal factors are
``Gamma_j phi_j`` is

.. math::  a(t) = a_g(t) + \sum_j \Gamma_j \phi_j \ddot u_j(t)
                = \Big(1 - \sum_j \Gamma_j \phi_j\Big) a_g(t)
                  - \sum_j \Gamma_j \phi_j \,(2 \zeta_j \omega_j \dot u_j
                  + \omega_j^2 u_j),                                   \qquad (1)

the second form from the equation of motion (with every mode of a discrete model
``sum_j Gamma_j phi_j = 1`` at each floor and the first term vanishes; with truncated
modes it is the rigid, "missing-mass" part of the response). The building starts at
rest, so at ``t = 0`` the floor is ``(1 - sum_j Gamma_j phi_j) a_g(0)``: a record whose
first sample is not zero starts with a jump, which the oscillators do not follow.

**Integration.** Each oscillator is advanced by the exact recurrence for a
piecewise-linear excitation (Nigam and Jennings 1969; Chopra 5.2), the one of the
response spectra (:func:`rocking.motions.spectra.sdof_history`), on the time grid of the
ground record: (1) is exact at every sample for the record as
:class:`~rocking.motions.Record` defines it (linear between samples). Between samples the
floor motion is linear too (it is handed to the models as a record), which resolves a
mode of period ``T_j`` when the step is small against it; the floor step is therefore the
ground step divided by ``m = ceil(20 h / T_r)`` (``MIN_STEPS_PER_PERIOD`` = 20 steps per
period of the shortest mode ``T_r`` that the ground can excite, ``T_r >= 2 h``: a mode
shorter than twice the ground's step lies above the record's Nyquist frequency and
responds quasi-statically, its samples following the ground). Within a ground step the
ground stays linear, so the sub-steps are exact as well. An analytic ground motion (a
sine, a pulse) is first sampled at ``h = scan_step / 4`` divided by the same ``m``
(:func:`rocking.motions.sample`), or at the ``dt`` given.

**Ring-down.** After the ground stops (its ``quiet_time``) the building vibrates freely;
mode ``j``'s absolute acceleration decays within the envelope ``omega_j^2 R_j
exp(-zeta_j omega_j tau)`` (``R_j`` the amplitude of the free vibration,
``u_j = Re(c e^{lambda t})`` with ``|c| = R_j`` and ``|lambda| = omega_j``). The floor
record is extended, in closed form (free vibration), until every mode's envelope is below
``tol / n_modes`` times the peak floor acceleration (:data:`RING_DOWN_TOL` = 1e-6), so
that what is cut off is below ``tol`` times the peak. An undamped mode never rings down:
every modal damping ratio must be > 0.

**Vertical component.** A building filters the vertical ground acceleration too, through
its vertical modes (the axial modes of its columns and walls, the slabs' out-of-plane
modes). Given a second, *vertical* building (its vertical modes, in the same
:class:`~rocking.buildings.Building` form), the vertical ground acceleration ``a_v`` is
filtered by Eq (1) with that building's modal factors at the same floor (or height ratio):
the same modal superposition, integration and ring-down as the horizontal component. The
axial vibration of a uniform bar, ``rho A u_tt = (EA u_z)_z``, is the shear beam's equation
with ``EA`` for ``GA`` (Clough and Penzien, *Dynamics of Structures*, 2nd ed., chapters 18
and 19), so ``Building.shear(N, T_v)`` with the building's storeys and its first vertical
period ``T_v`` is a lumped model of the columns' axial filter, and ``Building.sdof(T_v,
zeta)`` a single vertical mode (floor 1). Without a vertical building the vertical
component passes through unchanged: the building is taken as rigid vertically.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from .._validate import as_float, in_range, positive
from ..errors import ParameterError, PlausibilityWarning
from ..motions import _kernel as K
from ..motions.base import Motion, is_sampled
from ..motions.ground import GroundMotion
from ..motions.records import Record
from ..motions.spectra import MIN_STEPS_PER_PERIOD, sdof_history
from .building import Building

__all__ = ["FloorMotion", "RING_DOWN_TOL", "MAX_FLOOR_SAMPLES"]

RING_DOWN_TOL = 1e-6
"""The floor record goes on after the ground stops until the free vibration of the
building is below this fraction of the peak floor acceleration (all modes together)."""

MAX_FLOOR_SAMPLES = 20_000_000
"""A floor record longer than this (160 MB) is refused: a smaller damping ratio than any
real building's, or a time step far below what the motion needs."""

ANALYTIC_STEPS_PER_SCAN = 4
"""An analytic ground motion is sampled at ``scan_step / 4`` (or finer, see the module
docstring) before it is filtered."""


def _split(ground: Motion) -> tuple[Motion, Motion | None]:
    """``(horizontal, vertical)`` of a ground motion, load factors applied."""
    if isinstance(ground, FloorMotion):
        return ground.record, ground.vertical
    if isinstance(ground, GroundMotion):
        s = ground.scale
        h = ground.horizontal if s == 1.0 else ground.horizontal.scaled(s)
        v = None if ground.vertical is None else (
            ground.vertical if s == 1.0 else ground.vertical.scaled(s))
        return h, v
    return ground, None


def _substeps(h0: float, periods: np.ndarray) -> int:
    """Sub-steps per ground step ``h0`` that give ``MIN_STEPS_PER_PERIOD`` steps per period
    of the shortest mode the ground can excite (period >= 2 h0, its Nyquist period)."""
    excited = periods[periods >= 2.0 * h0]
    if excited.size == 0:
        return 1
    return max(1, math.ceil(MIN_STEPS_PER_PERIOD * h0 / float(excited.min()) - 1e-9))


def _ground_samples(h: Motion, periods: np.ndarray, dt) -> tuple[np.ndarray, float]:
    """The horizontal ground acceleration on the floor's time grid: ``(samples, step)``."""
    if is_sampled(h) and h.kind == K.RECORD:
        vals = np.ascontiguousarray(h.values, dtype=np.float64)
        if dt is None:
            m = _substeps(h.dt, periods)
        else:
            step = positive("dt", dt, "s")
            m = round(h.dt / step)
            if m < 1 or not math.isclose(m * step, h.dt, rel_tol=1e-9):
                raise ParameterError(f"dt must be the ground record's step {h.dt:g} s "
                                     f"divided by a whole number ({h.dt:g}, {h.dt / 2:g}, "
                                     f"{h.dt / 3:g} s, ...), got {dt!r}")
        if m == 1:
            return vals, float(h.dt)
        _guard(m * (vals.size - 1) + 1, "dt")
        fine = np.arange(m * (vals.size - 1) + 1) / m
        return np.interp(fine, np.arange(vals.size), vals), float(h.dt) / m
    try:
        t_end = h.quiet_time
    except NotImplementedError:
        t_end = h.duration
    if dt is None:
        h0 = h.scan_step / ANALYTIC_STEPS_PER_SCAN
        step = h0 / _substeps(h0, periods)
    else:
        step = positive("dt", dt, "s")
    n = math.ceil(t_end / step - 1e-9) + 1
    _guard(n, "dt")
    return np.ascontiguousarray(h.acceleration(np.arange(n) * step), dtype=np.float64), step


def _guard(n: int, name: str) -> None:
    if n > MAX_FLOOR_SAMPLES:
        raise ParameterError(f"{name}: the floor record would have {n:,} samples (limit "
                             f"{MAX_FLOOR_SAMPLES:,}); use a larger time step or a "
                             "realistic damping ratio")


def _check_damping(zetas, what: str) -> None:
    """Every modal damping ratio > 0 (an undamped mode never rings down)."""
    for j, z in enumerate(zetas):
        if not z > 0.0:
            raise ParameterError(
                f"{what}damping[{j}] must be in (0, 1) for a floor motion (an undamped "
                f"building never rings down), got {z!r}")


def floor_history(acc: np.ndarray, step: float, omegas, zetas, gphis,
                  tol: float = RING_DOWN_TOL) -> np.ndarray:
    """Absolute floor acceleration (Eq 1 of the module docstring) at the samples of
    ``acc`` (m/s^2, step ``step`` s, linear between samples, zero after the last one),
    followed by the building's free vibration until it is below ``tol`` times the peak.

    ``omegas``, ``zetas``, ``gphis``: the modal factors of
    :meth:`~rocking.buildings.Building.modal_factors` (``zetas > 0``). The time loops
    are compiled (:func:`~rocking.motions.spectra.sdof_history`); the ring-down is the
    closed-form free vibration.
    """
    n = acc.size
    out = (1.0 - float(np.sum(gphis))) * acc
    ends = []
    u = np.empty(n)
    v = np.empty(n)
    for w, z, g in zip(omegas, zetas, gphis, strict=True):
        if g == 0.0:
            continue
        sdof_history(acc, step, float(w), float(z), 1, u, v)
        out -= g * (2.0 * z * w * v + w * w * u)
        ends.append((float(w), float(z), float(g), float(u[-1]), float(v[-1])))
    peak = float(np.max(np.abs(out)))
    if peak == 0.0 or not ends:
        return out
    # ring-down: each mode's envelope |g| w^2 R exp(-z w tau) below tol * peak / n_modes
    tau_end = 0.0
    for w, z, g, u0, v0 in ends:
        wd = w * math.sqrt(1.0 - z * z)
        env = abs(g) * w * w * math.hypot(u0, (v0 + z * w * u0) / wd)
        lim = tol * peak / len(ends)
        if env > lim:
            tau_end = max(tau_end, math.log(env / lim) / (z * w))
    k = math.ceil(tau_end / step - 1e-9)
    _guard(n + k, "damping")
    if k == 0:
        return out
    tau = np.arange(1, k + 1) * step
    tail = np.zeros(k)
    for w, z, g, u0, v0 in ends:
        wd = w * math.sqrt(1.0 - z * z)
        e = np.exp(-z * w * tau)
        c, s = np.cos(wd * tau), np.sin(wd * tau)
        b = (v0 + z * w * u0) / wd
        uu = e * (u0 * c + b * s)
        vv = e * ((wd * b - z * w * u0) * c - (wd * u0 + z * w * b) * s)
        tail -= g * (2.0 * z * w * vv + w * w * uu)
    return np.concatenate([out, tail])


@dataclass(frozen=True, eq=False)
class FloorMotion(Motion):
    r"""The absolute acceleration of a floor of a building under a ground motion.

    The building (linear elastic, modal damping) filters the horizontal ground
    acceleration by modal superposition, Eq (1) of :mod:`rocking.buildings.floor`,
    integrated exactly for the piecewise-linear ground record (Nigam and Jennings 1969),
    and rings down after the ground stops until its free vibration is below
    :data:`RING_DOWN_TOL` (1e-6) of the peak floor acceleration. The result is handed to
    the models as a sampled record, so :func:`rocking.simulate` and
    :func:`rocking.simulate_many` take it unchanged. The floor samples are computed once,
    when the motion is built; :meth:`scaled` only changes the load factor.

    **Cascade assumption.** The object rocks on the floor without acting back on the
    building: its inertia force on the floor is neglected. This holds when the object's
    mass ``m`` is small against the building's effective mass at the floor for each
    mode, ``M_j / phi_j(floor)^2`` (``M_j`` the modal mass for shapes ``phi_j``: for
    :meth:`Building.sdof` the floor mass itself). Igusa and Der Kiureghian (1985,
    *Earthq. Eng. Struct. Dyn.* 13, 661-676) show that the interaction of light equipment
    with its supporting structure grows with this mass ratio and with the tuning of the
    two, and the decoupling criteria in use for secondary systems (Hadjian and Ellison
    1986, *J. Pressure Vessel Technol.* 108, 78; U.S. NRC Standard Review Plan 3.7.2)
    allow the cascade for any tuning below a mass ratio of 1 %, and up to 10 % only for
    detuned systems. A rocking object has no fixed frequency (its period grows with the
    amplitude), so it is never safely detuned: **our limit is a mass ratio of 1 %**;
    above a few percent the floor motion is no longer independent of the object and a
    coupled model is needed (not provided).

    Parameters
    ----------
    ground : Motion
        The ground motion: a :class:`~rocking.motions.Record`, an analytic motion (sampled
        first, see ``dt``), a :class:`~rocking.motions.GroundMotion` (its horizontal
        component is filtered by ``building``, its vertical one by ``vertical_building``
        or, without one, **passes through unchanged**) or another ``FloorMotion``.
    building : Building
        The building; every modal damping ratio must be > 0 (an undamped building never
        rings down).
    floor : int, optional
        Floor number (0 is the ground). Give ``floor`` or ``height_ratio``.
    height_ratio : float, optional
        ``z/H`` in [0, 1] (continuous models, or a discrete model's floor heights).
    dt : float, optional
        Time step of the floor record (s). For a record ground: its step divided by a
        whole number (default: sub-steps so that the shortest mode the record can excite
        has 20 steps per period). For an analytic ground: the sampling step (default
        ``scan_step / 4``, or finer by the same rule).
    scale : float
        Load factor (multiplies both components).
    vertical_building : Building, optional
        The building's vertical modes (e.g. ``Building.sdof(0.1, 0.05)``, one vertical mode
        at floor 1, or ``Building.shear(N, T_v)``, the columns' axial modes; see
        :mod:`rocking.buildings.floor`): the ground's vertical component is filtered by it
        at the same ``floor`` or ``height_ratio`` (which must be a floor of it), by the
        same modal superposition (1), on the vertical record's own time grid (same ``dt``
        rule). Every modal damping ratio must be > 0. Without a vertical component in the
        ground it has nothing to filter and the floor has no vertical motion either; at
        floor 0 it is the ground's, unchanged.

    Attributes
    ----------
    samples : ndarray
        Floor acceleration (m/s^2) at ``0, step, 2 step, ...``, before ``scale``; the
        ground part then the ring-down.
    step : float
        Time step of ``samples`` (s).
    ground_end : float
        When the ground stops (s); the ring-down follows.
    vertical : Motion or None
        The vertical component: the ground's, unchanged, without ``vertical_building``;
        with it, the vertical floor acceleration as a :class:`~rocking.motions.Record`
        (m/s^2, positive upwards, before ``scale``), ringing down like ``samples``.

    Notes
    -----
    ``floor=0`` (or ``height_ratio=0``) is the ground itself: the kernels get the ground's
    own spec, bit for bit (with or without a ``vertical_building``, whose modes do not
    move the ground either). ``FloorMotion(ground.scaled(f), ...)`` equals
    ``FloorMotion(ground, ...).scaled(f)`` (linearity; bit for bit when ``f`` is a power
    of 2).

    References
    ----------
    Nigam N.C., Jennings P.C. (1969) Calculation of response spectra from strong-motion
    earthquake records. *Bull. Seismol. Soc. Am.* 59(2), 909-922.
    Chopra A.K. *Dynamics of Structures*, 5.2 and 13.1.
    Igusa T., Der Kiureghian A. (1985) Generation of floor response spectra including
    oscillator-structure interaction. *Earthq. Eng. Struct. Dyn.* 13(5), 661-676.

    Examples
    --------
    >>> import rocking
    >>> from rocking.buildings import Building, FloorMotion
    >>> ground = rocking.motions.load_builtin("Rinaldi228")
    >>> roof = FloorMotion(ground, Building.sdof(0.5, 0.05), floor=1)
    >>> roof.step, roof.quiet_time > ground.duration
    (0.01, True)
    >>> r = rocking.simulate(rocking.Block.rectangular(0.2, 1.0), roof)

    With the vertical component of the record filtered by a vertical mode of 0.1 s:

    >>> g3 = rocking.motions.GroundMotion.builtin("rinaldi")  # Rinaldi228 + RinaldiUP
    >>> up = FloorMotion(g3, Building.sdof(0.5, 0.05), floor=1,
    ...                  vertical_building=Building.sdof(0.1, 0.05))
    >>> bool(up.vertical.pga > g3.pga_vertical)
    True
    """

    ground: Motion
    building: Building
    floor: int | None = None
    height_ratio: float | None = None
    dt: float | None = None
    scale: float = 1.0
    vertical_building: Building | None = None
    samples: np.ndarray = field(init=False, repr=False)
    step: float = field(init=False, repr=False)
    ground_end: float = field(init=False, repr=False)
    vertical: Motion | None = field(init=False, repr=False)
    identity: bool = field(init=False, repr=False)

    def __post_init__(self):
        if not isinstance(self.ground, Motion):
            raise ParameterError(f"ground must be a rocking.motions.Motion (a record, a "
                                 f"sine, a pulse, a GroundMotion), got "
                                 f"{type(self.ground).__name__}")
        if not isinstance(self.building, Building):
            raise ParameterError(f"building must be a rocking.buildings.Building, got "
                                 f"{type(self.building).__name__}")
        vb = self.vertical_building
        if vb is not None and not isinstance(vb, Building):
            raise ParameterError(f"vertical_building must be a rocking.buildings.Building "
                                 f"(its vertical modes) or None, got {type(vb).__name__}")
        set_ = object.__setattr__
        set_(self, "scale", as_float("scale", self.scale))
        if self.floor is not None and self.height_ratio is not None:
            raise ParameterError("floor or height_ratio: give exactly one")
        if self.floor is None and self.height_ratio is None:
            raise ParameterError("floor or height_ratio: give exactly one (floor=0 is "
                                 "the ground)")
        omegas, zetas, gphis = self.building.modal_factors(self.floor, self.height_ratio)
        if self.height_ratio is not None:
            set_(self, "height_ratio", in_range("height_ratio", self.height_ratio, 0.0,
                                                1.0, lo_open=False, hi_open=False))
        _check_damping(zetas, "")
        vfactors = None
        if vb is not None:
            try:
                vfactors = vb.modal_factors(self.floor, self.height_ratio)
            except ParameterError as e:
                raise ParameterError(f"vertical_building: {e} (the vertical building is "
                                     "read at the same floor or height_ratio)") from None
            _check_damping(vfactors[1], "vertical_building ")
        if self.dt is not None:
            set_(self, "dt", positive("dt", self.dt, "s"))
        h, v = _split(self.ground)
        filtered = v is not None and vfactors is not None and bool(np.any(vfactors[2] != 0.0))
        if filtered:
            vacc, vstep = _ground_samples(v, vb.periods, self.dt)
            vout = floor_history(vacc, vstep, *vfactors)
            with warnings.catch_warnings():  # an amplified floor may exceed 5 g
                warnings.simplefilter("ignore", PlausibilityWarning)
                v = Record(vout, vstep, name=f"{getattr(v, 'name', '') or 'vertical'} "
                           f"through {vb.name or 'the vertical building'}")
        set_(self, "vertical", v)
        identity = not np.any(gphis != 0.0) and not filtered
        set_(self, "identity", identity)
        if identity:  # the ground itself: its own spec
            set_(self, "samples", np.empty(0))
            set_(self, "step", float(self.ground.scan_step))
            try:
                set_(self, "ground_end", float(self.ground.quiet_time))
            except NotImplementedError:
                set_(self, "ground_end", float(self.ground.duration))
            return
        acc, step = _ground_samples(h, self.building.periods, self.dt)
        out = floor_history(acc, step, omegas, zetas, gphis)
        out.setflags(write=False)
        set_(self, "samples", out)
        set_(self, "step", float(step))
        set_(self, "ground_end", (acc.size - 1) * float(step))

    # ---- Motion interface
    @property
    def kind(self) -> int:
        """The motion kind of the kernel's spec: the ground's own at the ground floor,
        else a sampled record."""
        return self.ground.kind if self.identity else K.RECORD

    @property
    def end(self) -> float:
        """Time of the last floor sample (s): the building has rung down."""
        return (self.samples.size - 1) * self.step

    @property
    def duration(self) -> float:
        """The ground's duration, or the end of the ring-down if later (s)."""
        if self.identity:
            return self.ground.duration
        return max(self.ground.duration, self.end)

    @property
    def quiet_time(self) -> float:
        """The end of the ring-down (s), or of the vertical component if later."""
        if self.identity:
            return self.ground.quiet_time
        q = self.end
        return q if self.vertical is None else max(q, self.vertical.quiet_time)

    @property
    def scan_step(self) -> float:
        if self.identity:
            return self.ground.scan_step
        return self.step if self.vertical is None else min(self.step,
                                                             self.vertical.scan_step)

    def _params(self):
        return (self.step, float(self.samples.size))

    def _samples(self):
        return self.samples

    def spec(self) -> tuple[int, np.ndarray, np.ndarray]:
        """The floor record's spec carrying the vertical component, if any (the ground's
        own spec at floor 0).

        Examples
        --------
        Above the ground the spec is a record (``prm``: scale, step, number of samples)
        of the floor samples; at floor 0 it is the ground's own spec, bit for bit.

        >>> from rocking.buildings import Building, FloorMotion
        >>> from rocking.motions import Sine
        >>> ground = Sine(freq=2.0, amplitude=0.01, duration=1.0)
        >>> level = FloorMotion(ground, Building.sdof(0.5, 0.1), floor=1)
        >>> kind, prm, samples = level.spec()
        >>> prm[:3].tolist() == [1.0, level.step, samples.size]
        True
        >>> bool(np.array_equal(samples, level.samples)), samples.size * level.step > 1.0
        (True, True)
        >>> at_ground = FloorMotion(ground, Building.sdof(0.5, 0.1), floor=0).spec()
        >>> all(np.array_equal(a, b) for a, b in zip(at_ground, ground.spec()))
        True
        """
        if self.identity:
            g = self.ground if self.scale == 1.0 else self.ground.scaled(self.scale)
            return g.spec()
        kind, prm, samples = super().spec()
        if self.vertical is None:
            return kind, prm, samples
        v = self.vertical if self.scale == 1.0 else self.vertical.scaled(self.scale)
        prm, samples = K.with_vertical(kind, prm, samples, *v.spec())
        return kind, prm, samples

    # ---- conveniences
    @property
    def record(self) -> Record:
        """The horizontal floor acceleration as a :class:`~rocking.motions.Record` (load
        factor applied; at floor 0 the ground sampled at ``scan_step / 4``)."""
        with warnings.catch_warnings():  # an amplified floor may exceed 5 g: not a unit slip
            warnings.simplefilter("ignore", PlausibilityWarning)
            if self.identity:
                h, _ = _split(self.ground if self.scale == 1.0
                              else self.ground.scaled(self.scale))
                if is_sampled(h):
                    return Record(h.values, h.dt, name=self.name)
                acc, step = _ground_samples(h, self.building.periods, self.dt)
                return Record(acc, step, name=self.name)
            return Record(self.samples, self.step, name=self.name, scale=self.scale)

    def vertical_acceleration(self, t):
        """Vertical acceleration (m/s^2, positive upwards) at ``t`` (s): the ground's, or
        its floor motion through ``vertical_building``; 0 without one.

        Examples
        --------
        Without a vertical building the ground's vertical component passes through
        unchanged (times the load factor):

        >>> from rocking.buildings import Building, FloorMotion
        >>> from rocking.motions import GroundMotion, Sine
        >>> ground = GroundMotion(Sine(2.0, 0.01, 1.0), Sine(4.0, 0.002, 1.0))
        >>> floor = FloorMotion(ground, Building.sdof(0.5, 0.1), floor=1, scale=2.0)
        >>> t = np.array([0.1, 0.3, 0.6])
        >>> bool(np.allclose(floor.vertical_acceleration(t),
        ...                  2.0 * ground.vertical.acceleration(t)))
        True
        >>> level = FloorMotion(Sine(2.0, 0.01, 1.0), Building.sdof(0.5, 0.1), floor=1)
        >>> level.vertical_acceleration(0.3)  # no vertical component
        0.0
        """
        arr = np.asarray(t, dtype=np.float64)
        if self.vertical is None:
            return np.zeros(arr.shape) if arr.ndim else 0.0
        return self.vertical.scaled(self.scale).acceleration(t)

    @property
    def pga(self) -> float:
        """Peak floor acceleration (m/s^2), horizontal, load factor applied."""
        if self.identity:
            return self.ground.scaled(self.scale).pga
        return float(np.max(np.abs(self.samples))) * abs(self.scale)

    @property
    def pgv(self) -> float:
        """Peak horizontal floor velocity (m/s) from rest, load factor applied: that of the
        floor samples (:meth:`~rocking.motions.Record.velocity` of :attr:`record`); at
        floor 0 the ground's own ``pgv``."""
        if self.identity:
            return self.ground.scaled(self.scale).pgv
        return float(np.max(np.abs(self.record.velocity())))

    def horizontal_scaled(self, factor: float) -> Motion:
        """The horizontal floor acceleration times ``factor``, the vertical component
        unchanged: the floor motion scaled without a vertical component; with one, a
        :class:`~rocking.motions.GroundMotion` of the floor record (the ground's own
        motion at floor 0).

        Examples
        --------
        >>> from rocking.buildings import Building, FloorMotion
        >>> from rocking.motions import GroundMotion, Sine
        >>> ground = GroundMotion(Sine(2.0, 0.01, 1.0), Sine(4.0, 0.002, 1.0))
        >>> floor = FloorMotion(ground, Building.sdof(0.5, 0.1), floor=1)
        >>> h = floor.horizontal_scaled(0.5)
        >>> type(h).__name__, h.horizontal.scale, h.vertical.scale
        ('GroundMotion', 0.5, 1.0)
        >>> bool(np.array_equal(h.acceleration([0.3, 0.7]), 0.5 * floor.acceleration([0.3, 0.7])))
        True
        """
        if self.vertical is None:
            return self.scaled(factor)
        if self.identity:
            g = self.ground if self.scale == 1.0 else self.ground.scaled(self.scale)
            return g.horizontal_scaled(factor)
        with warnings.catch_warnings():  # an amplified floor may exceed 5 g: not a unit slip
            warnings.simplefilter("ignore", PlausibilityWarning)
            h = Record(self.samples, self.step, name=self.name,
                       scale=self.scale * as_float("factor", factor))
        return GroundMotion(h, self.vertical if self.scale == 1.0
                            else self.vertical.scaled(self.scale))

    @property
    def pfa(self) -> float:
        """Peak floor acceleration (m/s^2): :attr:`pga` by its floor name."""
        return self.pga

    @property
    def where(self) -> str:
        """``"floor k"`` or ``"z/H = x"``."""
        return (f"floor {self.floor}" if self.floor is not None
                else f"z/H = {self.height_ratio:g}")

    @property
    def name(self) -> str:
        gname = getattr(self.ground, "name", "") or type(self.ground).__name__
        bname = self.building.name or "building"
        return f"{gname} at {self.where} of {bname}"

    def __repr__(self) -> str:
        sc = f", scale={self.scale:g}" if self.scale != 1.0 else ""
        gname = getattr(self.ground, "name", "") or type(self.ground).__name__
        if self.identity:
            return f"FloorMotion({self.where} = the ground {gname!r}{sc})"
        vb = ("" if self.vertical_building is None
              else f", vertical through {self.vertical_building.name!r}")
        return (f"FloorMotion({gname!r} at {self.where} of {self.building.name!r}{vb}, "
                f"n={self.samples.size}, dt={self.step:g} s, pfa={self.pga:.3f} m/s^2{sc})")
