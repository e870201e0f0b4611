"""The base-motion interface.

Every motion gives the horizontal ground acceleration ``a(t)`` in m/s^2 as a vectorised
function of time (:meth:`Motion.acceleration`) and a ``duration`` (s), the default length
of a simulation. Sign convention: ``a`` is the ground acceleration of the paper's Eq (1),
so a positive ``a`` drives the rocking angle ``theta`` positive (see
:mod:`rocking.models.housner`). ``-motion`` or ``motion.scaled(-1)`` flips the motion.

Internally a motion is handed to compiled kernels as a *spec* ``(kind, prm, samples)``
that this package's compiled motion kernels evaluate; the numpy evaluation uses the same
compiled code, so the Python and the kernel views of a motion can never disagree.
"""

from __future__ import annotations

from typing import ClassVar

import numpy as np

from .._validate import as_float, positive
from ..errors import RecordError
from . import _kernel as K


class Motion:
    """Abstract base of all base motions (dataclasses with a ``scale`` load factor).

    Examples
    --------
    >>> from rocking.motions import Motion, Sine
    >>> s = Sine(freq=2.0, amplitude=0.01, duration=5.0)
    >>> isinstance(s, Motion), round(s.acceleration(0.125), 4)  # a = -X (2 pi f)^2 at u = X
    (True, -1.5791)
    >>> round((-s)(0.125), 4), round(s.scaled(2.0)(0.125), 4)
    (1.5791, -3.1583)
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
        return self.kind, prm, np.ascontiguousarray(self._samples(), dtype=np.float64)

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

    @property
    def pga(self) -> float:
        """Peak absolute ground acceleration (m/s^2), sampled at ``scan_step / 4``."""
        t = self.time(min(self.scan_step / 4.0, self.duration / 100.0))
        return float(np.max(np.abs(self.acceleration(t))))


def validate_scale(scale) -> float:
    return as_float("scale", scale)


# ---- sampled accelerograms (what processing, spectra and io work on, without a Record)
def is_sampled(obj) -> bool:
    """True for a sampled accelerogram: an object with ``acc`` (m/s^2), ``dt`` (s) and
    ``values`` (``acc`` times its load factor), such as a
    :class:`~rocking.motions.records.Record`."""
    return all(hasattr(obj, a) for a in ("acc", "dt", "values"))


def as_samples(acc) -> np.ndarray:
    """``acc`` as a contiguous 1-D float64 array of at least 2 finite samples."""
    try:
        a = np.asarray(acc, dtype=np.float64)
    except (TypeError, ValueError):
        raise RecordError("the accelerogram must be a 1-D array of numbers") from None
    if a.ndim != 1 or a.size < 2:
        raise RecordError(f"the accelerogram must be a 1-D array of at least 2 samples, got "
                          f"shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise RecordError("the accelerogram has a non-finite value (NaN or inf)")
    return np.ascontiguousarray(a)
