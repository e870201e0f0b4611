r"""Two-component base motion: a horizontal motion and an optional vertical one.

**Sign conventions.** The horizontal acceleration ``a_h`` keeps the sign of Eq (1): a
positive ``a_h`` drives ``theta`` positive. The vertical acceleration ``a_v`` is positive
*upwards*: a base that accelerates upwards presses the block onto it, and in the frame of
the base the block feels the effective gravity ``g + a_v`` (``a_v = -g`` is free fall of
the base: the block leaves the ground). Every model replaces ``g`` by ``g + a_v(t)`` in
its gravity terms (see :mod:`rocking.models.housner`).

Each component may be any :class:`~rocking.motions.Motion` (a record, a sine, a pulse).
``GroundMotion(h)`` is the horizontal motion ``h`` exactly: the kernels see the same spec
and give bit-identical results.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._validate import as_float
from ..errors import ParameterError
from . import _kernel as K
from .base import Motion
from .records import Record


@dataclass(frozen=True)
class GroundMotion(Motion):
    """A horizontal motion and an optional vertical one (m/s^2, ``a_v`` positive upwards).

    ``duration`` is the longer of the two; ``scale`` multiplies both components
    (:meth:`scaled` puts its factors on the components and leaves ``scale`` at 1). ``pga``
    and ``pgv`` are the horizontal component's, ``pga_vertical`` the vertical one's.

    Examples
    --------
    >>> from rocking.motions import GroundMotion, Sine
    >>> gm = GroundMotion.builtin("rinaldi")  # Northridge 1994, H1 and UP
    >>> gm.horizontal.name, gm.vertical.name, round(gm.duration, 2)
    ('Rinaldi228', 'RinaldiUP', 19.9)
    >>> gm2 = GroundMotion(Sine(2.0, 0.01, 5.0), Sine(4.0, 0.001, 8.0), scale=2.0)
    >>> gm2.duration  # the longer component
    8.0
    """

    horizontal: Motion
    vertical: Motion | None = None
    scale: float = 1.0

    def __post_init__(self):
        if isinstance(self.horizontal, GroundMotion) or not isinstance(self.horizontal,
                                                                         Motion):
            raise ParameterError("horizontal must be a rocking.motions.Motion (a record, a "
                                 f"sine, a pulse), got {type(self.horizontal).__name__}")
        if self.vertical is not None and (isinstance(self.vertical, GroundMotion)
                                          or not isinstance(self.vertical, Motion)):
            raise ParameterError("vertical must be a rocking.motions.Motion or None, got "
                                 f"{type(self.vertical).__name__}")
        object.__setattr__(self, "scale", as_float("scale", self.scale))

    # ---- constructors
    @classmethod
    def from_files(cls, h_path, v_path=None, units: str = "g", dt: float | None = None,
                   **kw) -> GroundMotion:
        """Read a horizontal record and, optionally, the vertical one (same ``units``:
        ``g``, ``m/s^2``, ``cm/s^2``; see :meth:`Record.from_file`).

        Examples
        --------
        >>> from rocking.motions import GroundMotion, Sine, sample, write_csv
        >>> h = write_csv(sample(Sine(2.5, 0.01, 1.0), 0.01), "h.csv")
        >>> v = write_csv(sample(Sine(5.0, 0.001, 1.0), 0.01), "v.csv")
        >>> gm = GroundMotion.from_files(h, v, units="m/s^2")
        >>> gm.name, gm.duration
        ('h + v', 1.0)
        >>> round(gm.acceleration(0.1), 4), round(-0.01 * (2 * np.pi * 2.5) ** 2, 4)  # u = X
        (-2.4674, -2.4674)
        """
        h = Record.from_file(h_path, units=units, dt=dt)
        v = Record.from_file(v_path, units=units, dt=dt) if v_path is not None else None
        return cls(h, v, **kw)

    @classmethod
    def builtin(cls, name: str, horizontal: int = 1) -> GroundMotion:
        """A three-component set shipped with the package (``"rinaldi"``, ``"duzce"``; see
        :func:`rocking.motions.builtin_sets`), with its horizontal component 1 or 2 and its
        vertical component.

        Examples
        --------
        >>> from rocking.motions import GroundMotion, builtin_sets, load_builtin
        >>> gm = GroundMotion.builtin("rinaldi", horizontal=2)
        >>> gm.name, builtin_sets()["rinaldi"]
        ('Rinaldi318 + RinaldiUP', ('Rinaldi228', 'Rinaldi318', 'RinaldiUP'))
        >>> gm.pga == load_builtin("Rinaldi318").pga  # the record itself
        True
        """
        from .io import builtin_sets
        from .records import load_builtin
        sets = builtin_sets()
        if name.lower() not in sets:
            raise ParameterError(f"name must be one of {', '.join(sets)}, got {name!r}")
        if horizontal not in (1, 2):
            raise ParameterError(f"horizontal must be 1 or 2, got {horizontal!r}")
        h1, h2, up = sets[name.lower()]
        return cls(load_builtin(h1 if horizontal == 1 else h2), load_builtin(up))

    # ---- Motion interface
    @property
    def duration(self) -> float:
        d = self.horizontal.duration
        return d if self.vertical is None else max(d, self.vertical.duration)

    @property
    def quiet_time(self) -> float:
        q = self.horizontal.quiet_time
        return q if self.vertical is None else max(q, self.vertical.quiet_time)

    @property
    def kind(self) -> int:
        """The motion kind of the kernel's spec: that of the horizontal motion."""
        return self.horizontal.kind

    @property
    def scan_step(self) -> float:
        h = self.horizontal.scan_step
        return h if self.vertical is None else min(h, self.vertical.scan_step)

    def spec(self) -> tuple[int, np.ndarray, np.ndarray]:
        """The horizontal spec carrying the vertical one (``with_vertical`` of the kernel
        module); without a vertical component, the horizontal motion's spec exactly.

        Examples
        --------
        >>> from rocking.motions import GroundMotion, Sine
        >>> h = Sine(freq=2.0, amplitude=0.01, duration=5.0)
        >>> (k1, p1, s1), (k2, p2, s2) = GroundMotion(h).spec(), h.spec()
        >>> k1 == k2, bool(np.array_equal(p1, p2)), s1.size == s2.size  # bit-identical
        (True, True, True)
        >>> GroundMotion(h, Sine(4.0, 0.001, 5.0)).spec()[0] == h.kind  # horizontal kind
        True
        """
        h = self.horizontal if self.scale == 1.0 else self.horizontal.scaled(self.scale)
        kind, prm, samples = h.spec()
        if self.vertical is None:
            return kind, prm, samples
        v = self.vertical if self.scale == 1.0 else self.vertical.scaled(self.scale)
        prm, samples = K.with_vertical(kind, prm, samples, *v.spec())
        return kind, prm, samples

    def acceleration(self, t):
        """Horizontal acceleration (m/s^2) at ``t`` (s).

        Examples
        --------
        >>> from rocking.motions import GroundMotion, Sine
        >>> h = Sine(freq=2.0, amplitude=0.01, duration=5.0)
        >>> gm = GroundMotion(h, Sine(4.0, 0.001, 5.0), scale=2.0)
        >>> round(gm.acceleration(0.125), 4), round(2.0 * h(0.125), 4)  # scale applied
        (-3.1583, -3.1583)
        """
        return self.horizontal.scaled(self.scale).acceleration(t)

    def vertical_acceleration(self, t):
        """Vertical acceleration (m/s^2, positive upwards) at ``t`` (s); 0 without one.

        Examples
        --------
        >>> from rocking.motions import GroundMotion, Sine
        >>> gm = GroundMotion(Sine(2.0, 0.01, 5.0), Sine(4.0, 0.001, 5.0))
        >>> round(gm.vertical_acceleration(0.0625), 4), round(-0.001 * (8 * np.pi) ** 2, 4)
        (-0.6317, -0.6317)
        >>> GroundMotion(Sine(2.0, 0.01, 5.0)).vertical_acceleration([0.0, 1.0]).tolist()
        [0.0, 0.0]
        """
        arr = np.asarray(t, dtype=np.float64)
        if self.vertical is None:
            return np.zeros(arr.shape) if arr.ndim else 0.0
        return self.vertical.scaled(self.scale).acceleration(t)

    # ---- scaling
    def scaled(self, factor: float, vertical: float | None = None) -> GroundMotion:
        """Both components times ``factor``; with ``vertical``, the horizontal component
        times ``factor`` and the vertical one times ``vertical``. The factors go to the
        components themselves, so ``GroundMotion(h).scaled(a).scaled(b)`` is
        ``GroundMotion(h.scaled(a).scaled(b))`` exactly.

        Examples
        --------
        >>> from rocking.motions import GroundMotion, Sine
        >>> gm = GroundMotion(Sine(2.0, 0.01, 5.0), Sine(4.0, 0.001, 5.0))
        >>> g2 = gm.scaled(2.0, vertical=0.5)
        >>> g2.scale, g2.horizontal.scale, g2.vertical.scale
        (1.0, 2.0, 0.5)
        >>> av, av2 = gm.vertical_acceleration(0.1), g2.vertical_acceleration(0.1)
        >>> round(g2(0.1) / gm(0.1), 12), round(av2 / av, 12)
        (2.0, 0.5)
        """
        f = as_float("factor", factor)
        if vertical is not None and self.vertical is None:
            raise ParameterError("vertical: this GroundMotion has no vertical component to "
                                 "scale")
        fv = f if vertical is None else as_float("vertical", vertical)
        h = self.horizontal.scaled(self.scale).scaled(f) if self.scale != 1.0 \
            else self.horizontal.scaled(f)
        v = None
        if self.vertical is not None:
            v = self.vertical.scaled(self.scale).scaled(fv) if self.scale != 1.0 \
                else self.vertical.scaled(fv)
        return GroundMotion(h, v)

    def __neg__(self):
        """The horizontal component reversed (the vertical one unchanged)."""
        return GroundMotion(-self.horizontal.scaled(self.scale),
                            None if self.vertical is None
                            else self.vertical.scaled(self.scale))

    @property
    def name(self) -> str:
        hn = getattr(self.horizontal, "name", type(self.horizontal).__name__)
        if self.vertical is None:
            return hn
        return f"{hn} + {getattr(self.vertical, 'name', type(self.vertical).__name__)}"

    @property
    def pga(self) -> float:
        """Peak horizontal acceleration (m/s^2), as the horizontal motion's own ``pga``."""
        return self.horizontal.scaled(self.scale).pga

    @property
    def pgv(self) -> float:
        """Peak horizontal velocity (m/s), as the horizontal motion's own ``pgv``."""
        return self.horizontal.scaled(self.scale).pgv

    def horizontal_scaled(self, factor: float) -> GroundMotion:
        """The horizontal component times ``factor``, the vertical one unchanged
        (:meth:`scaled` with ``vertical=1``).

        Examples
        --------
        >>> from rocking.motions import GroundMotion, Sine
        >>> gm = GroundMotion(Sine(2.0, 0.01, 5.0), Sine(4.0, 0.001, 5.0), scale=2.0)
        >>> h = gm.horizontal_scaled(-1.0)
        >>> h.horizontal.scale, h.vertical.scale, h.pga == gm.pga
        (-2.0, 2.0, True)
        """
        if self.vertical is None:
            return self.scaled(factor)
        return self.scaled(factor, vertical=1.0)

    @property
    def pga_vertical(self) -> float:
        """Peak vertical acceleration (m/s^2); 0 without a vertical component."""
        return 0.0 if self.vertical is None else self.vertical.scaled(self.scale).pga
