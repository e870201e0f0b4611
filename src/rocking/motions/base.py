"""The base-motion interface.

Every motion gives the horizontal ground acceleration ``a(t)`` in m/s^2 as a vectorised
function of time (:meth:`Motion.acceleration`) and a ``duration`` (s), the default length
of a simulation. Sign convention: ``a`` is the ground acceleration of the paper's Eq (1),
so a positive ``a`` drives the rocking angle ``theta`` positive (see
:mod:`rocking.models.housner`). ``-motion`` or ``motion.scaled(-1)`` flips the motion.

Internally a motion is handed to compiled kernels as a *spec* ``(kind, prm, samples)``
that this package's compiled motion kernels evaluate; the numpy evaluation uses the same
compiled code, so the Python and the kernel views of a motion can never disagree. A 3-D
body gets a *three-component* spec (:meth:`Motion.spec3`: the motion along the body's
``x`` axis turned by a heading, and the vertical component), and a planar model the
motion along one direction of the body (:meth:`Motion.on_plane`); see
:mod:`rocking.motions.components` for the angles.

**Peaks.** Every motion answers its ``pga`` (m/s^2), ``pgv`` (m/s) and ``duration`` (s),
load factor applied. A kind that states them gives them exactly (a record: from its
samples; a sine and the pulses: their closed forms). For the others the default is that
of the motion sampled as :func:`rocking.motions.sample` does it, with the step
:attr:`Motion.sampling_step` (``min(scan_step, 5 ms)``, the sampling that the intensity
measures of campaigns and Monte Carlo use): the largest ``|a|`` of the samples, and the
largest ``|v|`` of the velocity integrated from rest at ``t = 0`` (exactly, for the
piecewise-linear samples: :func:`rocking.motions.velocity`).
"""

from __future__ import annotations

from typing import ClassVar

import numpy as np

from .._validate import as_float, positive
from . import _kernel as K
from .components import angle, plane_weights
from .processing import integrate
from .samples import as_samples, is_sampled  # noqa: F401 (their former home)

SAMPLING_STEP = 0.005
"""The largest step (s) at which a motion whose kind states no peaks is sampled for them
(:attr:`Motion.sampling_step`)."""


class Motion:
    """Abstract base of all base motions (dataclasses with a ``scale`` load factor).

    Attributes
    ----------
    duration : float
        The default length of a simulation (s): a record's last sample, a harmonic motion's
        window, a pulse's window (past the pulse).
    scale : float
        The load factor.
    pga : float
        Peak ground acceleration (m/s^2), load factor applied (module docstring: exact
        where the kind states it, else from the motion sampled at :attr:`sampling_step`).
        A vertical component has its own (``GroundMotion.pga_vertical``).
    pgv : float
        Peak ground velocity (m/s), load factor applied, the same way: the velocity the kind
        states, else the acceleration integrated from rest at ``t = 0``.
    sampling_step : float
        ``min(scan_step, 5 ms)`` (s): the step of the default peaks.

    Examples
    --------
    >>> from rocking.motions import Motion, Sine
    >>> s = Sine(freq=2.0, amplitude=0.01, duration=5.0)
    >>> isinstance(s, Motion), round(s.acceleration(0.125), 4)  # a = -X (2 pi f)^2 at u = X
    (True, -1.5791)
    >>> round((-s)(0.125), 4), round(s.scaled(2.0)(0.125), 4)
    (1.5791, -3.1583)
    >>> round(s.pga, 4), round(s.pgv, 5), s.scaled(-2.0).pga == 2.0 * s.pga  # X w^2, X w
    (1.5791, 0.12566, True)
    """

    kind: ClassVar[int] = K.NONE
    duration: float
    scale: float

    # ---- to be provided by subclasses
    def _params(self) -> tuple:
        """Kind-specific parameters after ``scale`` (see ``_kernel``)."""
        raise NotImplementedError

    def _samples(self) -> np.ndarray:
        return np.empty(0)

    @property
    def scan_step(self) -> float:
        """A time step that resolves the motion (s): used to scan for uplift from rest."""
        raise NotImplementedError

    @property
    def quiet_time(self) -> float:
        """The time (s) from which the ground acceleration is zero for good: a run with
        the default ``duration`` goes on past ``max(duration, quiet_time)`` only while the
        block still moves (:func:`rocking.simulate`)."""
        raise NotImplementedError(f"{type(self).__name__} does not say when it ends "
                                  "(quiet_time); pass an explicit duration")

    # ---- shared behaviour
    def spec(self) -> tuple[int, np.ndarray, np.ndarray]:
        """``(kind, prm, samples)`` for the compiled kernels.

        ``prm`` holds ``scale`` then the kind-specific parameters, zero-padded to a
        fixed length; ``samples`` is empty for an analytic motion.

        Examples
        --------
        >>> from rocking.motions import Sine
        >>> s = Sine(freq=2.0, amplitude=0.01, duration=5.0, scale=3.0)
        >>> kind, prm, samples = s.spec()
        >>> kind == s.kind, prm[:5].tolist(), samples.size  # scale, freq, X, duration, phase
        (True, [3.0, 2.0, 0.01, 5.0, 0.0], 0)
        """
        prm = np.zeros(K.NPRM)
        vals = (self.scale, *self._params())
        prm[: len(vals)] = vals
        samples = np.ascontiguousarray(self._samples(), dtype=np.float64)
        # writable, as the batches' packed samples: numba compiles a kernel again for a
        # read-only array (a record's), minutes of first compilation for nothing
        return self.kind, prm, samples if samples.flags.writeable else samples.copy()

    def acceleration(self, t) -> np.ndarray:
        """Ground acceleration (m/s^2) at times ``t`` (s); scalar in, scalar out.

        Calling the motion, ``motion(t)``, is the same.

        Examples
        --------
        >>> from rocking.motions import Sine
        >>> s = Sine(freq=2.0, amplitude=0.01, duration=5.0)
        >>> a = s.acceleration(np.array([0.125, 0.375]))  # u = +X, -X: a = -u (2 pi f)^2
        >>> np.round(a, 4).tolist(), round(0.01 * (2 * np.pi * 2.0) ** 2, 4)
        ([-1.5791, 1.5791], 1.5791)
        >>> type(s.acceleration(0.125)).__name__, s.acceleration(0.3) == s(0.3)
        ('float', True)
        """
        kind, prm, samples = self.spec()
        arr = np.asarray(t, dtype=np.float64)
        out = K.acc_many(kind, prm, samples, np.atleast_1d(arr).ravel())
        return out.reshape(arr.shape) if arr.ndim else float(out[0])

    __call__ = acceleration

    def scaled(self, factor: float):
        """A copy with the acceleration multiplied by ``factor`` (a load factor).

        The factors multiply: ``m.scaled(a).scaled(b).scale == m.scale * a * b``; the
        original is unchanged (motions are immutable).

        Examples
        --------
        >>> from rocking.motions import Sine
        >>> s = Sine(freq=2.0, amplitude=0.01, duration=5.0)
        >>> s2 = s.scaled(2.0)
        >>> s2.scale, s.scale, bool(s2(0.3) == 2.0 * s(0.3))
        (2.0, 1.0, True)
        >>> s2.scaled(-0.5).scale, bool((-s)(0.3) == -s(0.3))  # -m is m.scaled(-1)
        (-1.0, True)
        """
        f = as_float("factor", factor)
        # a copy of the validated fields with a new scale: no need to validate them again
        # (a record's check scans every sample; campaigns scale thousands of motions)
        new = object.__new__(type(self))
        new.__dict__.update(self.__dict__)
        object.__setattr__(new, "scale", self.scale * f)
        return new

    def __neg__(self):
        return self.scaled(-1.0)

    def time(self, dt: float) -> np.ndarray:
        """A uniform time grid ``0, dt, ..., duration`` (s).

        Examples
        --------
        >>> from rocking.motions import Sine
        >>> t = Sine(freq=2.0, amplitude=0.01, duration=5.0).time(0.01)
        >>> len(t), float(t[0]), round(float(t[-1]), 10)  # duration / dt + 1 points
        (501, 0.0, 5.0)
        """
        dt = positive("dt", dt, "s")
        return np.arange(int(round(self.duration / dt)) + 1) * dt

    # ---- peaks (module docstring): the defaults, from the sampled motion
    @property
    def sampling_step(self) -> float:
        """The step (s) of the default peaks: ``min(scan_step, SAMPLING_STEP)``."""
        return min(self.scan_step, SAMPLING_STEP)

    def _sampled(self) -> tuple[np.ndarray, float]:
        """``(acc, dt)``: the motion on the grid of :func:`rocking.motions.sample` with the
        step :attr:`sampling_step` (the same samples, bit for bit)."""
        dt = self.sampling_step
        return np.asarray(self.acceleration(self.time(dt)), dtype=np.float64), dt

    @property
    def pga(self) -> float:
        """Peak absolute ground acceleration (m/s^2) of the sampled motion."""
        return float(np.max(np.abs(self._sampled()[0])))

    @property
    def pgv(self) -> float:
        """Peak absolute ground velocity (m/s) of the sampled motion, from rest."""
        acc, dt = self._sampled()
        return float(np.max(np.abs(integrate(acc, dt)[0])))

    # ---- directions (rocking.motions.components)
    def spec3(self, heading=0.0) -> tuple[int, np.ndarray, np.ndarray]:
        """The three-component spec (:func:`~rocking.motions._kernel.ground_acc3` reads
        it): the motion is along the ground's ``x`` axis, the body's ``x`` axis at
        ``heading`` (rad, or ``"30deg"``) counter-clockwise of it looking down; the body
        sees ``(a cos h, -a sin h, a_v)``.

        Examples
        --------
        >>> import math
        >>> from rocking.motions import Sine
        >>> from rocking.motions import _kernel as K
        >>> s = Sine(freq=2.0, amplitude=0.01, duration=5.0)
        >>> K.ground_acc3(*s.spec3(), 0.125) == (s(0.125), 0.0, 0.0)  # along x
        True
        >>> ax, ay, az = K.ground_acc3(*s.spec3("30deg"), 0.125)
        >>> round(ax / s(0.125), 6), round(ay / s(0.125), 6)  # cos 30, -sin 30
        (0.866025, -0.5)
        """
        o = -angle("heading", heading)  # the bearing of the body's x axis (module docs)
        kind, prm, samples = self.spec()
        wx = plane_weights(0.0, o)
        wy = plane_weights(0.5 * np.pi, o)
        return kind, K.with_axes(prm, wx, wy), samples

    def on_plane(self, phi, heading=0.0) -> Motion:
        """The planar motion along the body's direction ``phi`` (rad, or ``"30deg"``;
        counter-clockwise from its ``x`` axis), the body's ``x`` axis at ``heading`` from
        the motion's direction (:meth:`spec3`): the horizontal acceleration times
        ``cos(heading + phi)``, the vertical component unchanged; the motion itself when
        that is 1.

        Examples
        --------
        >>> from rocking.motions import Sine
        >>> s = Sine(freq=2.0, amplitude=0.01, duration=5.0)
        >>> s.on_plane(0.0) is s, s.on_plane("90deg").scale, s.on_plane("180deg").scale
        (True, 0.0, -1.0)
        >>> round(s.on_plane("20deg", heading="40deg").scale, 12)  # cos 60
        0.5
        """
        w, _ = plane_weights(angle("phi", phi), -angle("heading", heading))
        return self if w == 1.0 else self.horizontal_scaled(w)

    def horizontal_scaled(self, factor: float) -> Motion:
        """A copy with the horizontal acceleration times ``factor`` and the vertical
        component (if any) unchanged: :meth:`scaled` for a motion without one.

        Examples
        --------
        >>> from rocking.motions import GroundMotion, Sine
        >>> gm = GroundMotion(Sine(2.0, 0.01, 5.0), Sine(4.0, 0.001, 5.0))
        >>> h = gm.horizontal_scaled(0.5)
        >>> h.horizontal.scale, h.vertical.scale, Sine(2.0, 0.01, 5.0).horizontal_scaled(3).scale
        (0.5, 1.0, 3.0)
        """
        return self.scaled(factor)


def validate_scale(scale) -> float:
    return as_float("scale", scale)
