r"""Two horizontal components of one earthquake (and optionally the vertical one).

A :class:`HorizontalPair` holds two horizontal accelerograms recorded on orthogonal axes
on a common time grid, with the compass azimuths of their positive directions, and gives
the acceleration projected on any horizontal direction (:meth:`HorizontalPair.along`):
the input of the planar analysis of a 3-D body in every direction of shaking
(:func:`rocking.analysis.direction_sweep`).

**Conventions.**

* ``azimuths = (A1, A2)`` (rad; ``"228deg"`` accepted): the compass bearings, clockwise
  from north looking down, of the positive directions of the first and the second
  component, as the PEER NGA files state them in their header (``Rinaldi228`` /
  ``Rinaldi318``: 228 and 318 deg; Kocaeli at Duzce ``DZC180`` / ``DZC270``: 180 and 270
  deg). They must be orthogonal (to 0.01 deg); only the handedness of the pair is taken
  from ``A2`` (the second is then exactly ``A1 + 90`` or ``A1 - 90`` deg). Without
  azimuths (``None``) the second component is taken 90 deg counter-clockwise of the first
  (``A2 = A1 - 90`` deg with ``A1 = 0``): a right-handed ground frame, first = x, second =
  y. Both NGA built-in pairs are numbered clockwise (``A2 = A1 + 90`` deg).
* ``phi`` (rad): a direction of the OBJECT's horizontal frame, counter-clockwise from its
  x axis looking down its ``up`` axis (the convention of :mod:`rocking.shapes`: the
  frame ``(x, y, up)`` is right-handed).
* ``orientation`` (rad or ``"228deg"``): the compass bearing of the object's x axis. The
  direction ``phi`` has the bearing ``B = orientation - phi``. ``None`` (default): the
  object's x axis along the first component (``orientation = A1``).
* The projection (the components are the projections of the ground acceleration vector on
  orthogonal axes): ``a_phi(t) = a1(t) cos(B - A1) + a2(t) cos(B - A2)``; for a pair with
  no azimuths (``A1 = 0``, ``A2 = -90`` deg), ``a_phi = a1 cos(phi - o) + a2 sin(phi - o)``
  with ``o`` the orientation. Hence, with the default orientation, ``phi = 0`` is the
  first component exactly, and ``phi = 90`` deg is the second for a counter-clockwise
  pair (no azimuths) and MINUS the second for a clockwise one (the NGA pairs: there
  ``phi = -90`` deg is the second); ``phi + 180`` deg is ``-a_phi``. Angles within 1e-9
  rad of a multiple of 90 deg are taken as exact (cos, sin in {-1, 0, 1}), so the
  projection on a component's own axis is that component bit for bit.

**Time grid.** Both components must have the same time step (to 1e-9 relative; resample
one with :meth:`~rocking.motions.Record.resampled` otherwise); a shorter one is padded with
zeros to the longer one's length (a record is zero after its last sample). A component's
load factor (``Record.scale``) is applied. The vertical component (positive upwards) is
any :class:`~rocking.motions.Motion`, not projected: :meth:`HorizontalPair.motion` returns
a :class:`~rocking.motions.GroundMotion` with it.

**Three components.** :meth:`HorizontalPair.spec3` hands both horizontal components and
the vertical one to a 3-D body's kernel, the body's ``x`` axis at a ``heading``
counter-clockwise of the first component; :meth:`HorizontalPair.on_plane` is its
projection on one direction of the body (:meth:`HorizontalPair.motion` with the
orientation of that heading). Both take their weights from
:func:`rocking.motions.components.plane_weights`, the one place that writes the projection.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import ParameterError
from . import _kernel as K
from .base import Motion
from .components import angle, cos_sin, plane_weights
from .ground import GroundMotion
from .records import Record, load_builtin

ORTHOGONALITY_TOL = math.radians(0.01)
"""How far (rad) the stated azimuths may be from orthogonal."""
DT_RTOL = 1e-9
"""Relative tolerance on the equality of the two components' time steps."""


def _component_azimuth(rec) -> float | None:
    """The compass azimuth (rad) an NGA header states for a component, or None."""
    comp = (getattr(rec, "meta", None) or {}).get("component")
    try:
        return math.radians(float(str(comp).strip()))
    except (TypeError, ValueError):
        return None


@dataclass(frozen=True, eq=False)
class HorizontalPair:
    """Two orthogonal horizontal components on a common time grid (module docstring).

    ``first``, ``second``: :class:`~rocking.motions.Record` (m/s^2); ``azimuths``: their
    compass bearings (rad, or ``"228deg"``; None: second 90 deg counter-clockwise of the
    first); ``vertical``: an optional vertical motion (positive upwards); ``name``.
    Attributes after construction: ``a1``, ``a2`` (the samples with their load factors,
    padded to a common length, read-only), ``dt`` (s), ``handedness`` (+1: the second is
    90 deg clockwise of the first, -1: counter-clockwise).

    Examples
    --------
    >>> from rocking.motions import HorizontalPair, pga
    >>> pair = HorizontalPair.builtin("rinaldi")  # Rinaldi228 / Rinaldi318
    >>> pair.dt, pair.handedness  # numbered clockwise
    (0.01, 1)
    >>> bool(np.array_equal(pair.along(0.0).values, pair.a1))  # phi = 0: the first component
    True
    >>> bool(pga(pair.along(0.7)) <= pair.peak_resultant)
    True
    """

    first: Record
    second: Record
    azimuths: tuple | None = None
    vertical: Motion | None = None
    name: str = ""

    def __post_init__(self):
        for nm in ("first", "second"):
            r = getattr(self, nm)
            if not isinstance(r, Record):
                raise ParameterError(f"{nm} must be a rocking.motions.Record (a sampled "
                                     f"horizontal component), got {type(r).__name__}")
        d1, d2 = self.first.dt, self.second.dt
        if abs(d1 - d2) > DT_RTOL * max(d1, d2):
            raise ParameterError(
                f"second: its time step {d2:g} s differs from the first's {d1:g} s; "
                "resample one (Record.resampled(dt)) so that both share a time grid")
        if self.vertical is not None and (isinstance(self.vertical, GroundMotion)
                                          or not isinstance(self.vertical, Motion)):
            raise ParameterError("vertical must be a rocking.motions.Motion (positive "
                                 f"upwards) or None, got {type(self.vertical).__name__}")
        v1, v2 = self.first.values, self.second.values
        for nm, v in (("first", v1), ("second", v2)):
            if not np.all(np.isfinite(v)):
                raise ParameterError(f"{nm}: non-finite acceleration (check its scale)")
        n = max(v1.size, v2.size)
        a1 = np.zeros(n)
        a2 = np.zeros(n)
        a1[: v1.size] = v1
        a2[: v2.size] = v2
        a1.setflags(write=False)
        a2.setflags(write=False)
        object.__setattr__(self, "a1", a1)
        object.__setattr__(self, "a2", a2)
        object.__setattr__(self, "dt", float(d1))
        if self.azimuths is None:
            object.__setattr__(self, "handedness", -1)
        else:
            try:
                az1, az2 = self.azimuths
            except (TypeError, ValueError):
                raise ParameterError("azimuths must be two angles (the compass bearings of "
                                     f"the components), got {self.azimuths!r}") from None
            az1, az2 = angle("azimuths[0]", az1), angle("azimuths[1]", az2)
            d = math.remainder(az2 - az1, 2.0 * math.pi)
            if abs(abs(d) - 0.5 * math.pi) > ORTHOGONALITY_TOL:
                raise ParameterError(
                    f"azimuths must be orthogonal (90 deg apart), got "
                    f"{math.degrees(az1):g} and {math.degrees(az2):g} deg")
            object.__setattr__(self, "azimuths", (az1, az2))
            object.__setattr__(self, "handedness", 1 if d > 0 else -1)
        if not self.name:
            object.__setattr__(self, "name", f"{self.first.name} / {self.second.name}")

    # ---------------------------------------------------------------- constructors
    @classmethod
    def from_files(cls, first, second, vertical=None, *, units: str = "g",
                   dt: float | None = None, azimuths="auto", name: str = "") -> HorizontalPair:
        """Read the two horizontal components (and the vertical one) from files (as
        :meth:`Record.from_file`, the same ``units``). ``azimuths="auto"``: from the
        files' headers when both state a number (the NGA component angle), else None.

        Examples
        --------
        >>> from rocking.motions import HorizontalPair, Record, write_csv
        >>> ns = write_csv(Record(np.array([0.0, 1.0, -1.0, 0.0]), 0.01), "ns.csv")
        >>> ew = write_csv(Record(np.array([0.0, 0.5, 0.5, 0.0]), 0.01), "ew.csv")
        >>> pair = HorizontalPair.from_files(ns, ew, units="m/s^2")
        >>> pair.azimuths, pair.handedness  # no angles in the files: second 90 deg ccw
        (None, -1)
        >>> pair.along(np.pi / 2).values.tolist()  # phi = 90 deg: the second component
        [0.0, 0.5, 0.5, 0.0]
        """
        r1 = Record.from_file(first, units=units, dt=dt)
        r2 = Record.from_file(second, units=units, dt=dt)
        v = Record.from_file(vertical, units=units, dt=dt) if vertical is not None else None
        return cls(r1, r2, azimuths=cls._auto(r1, r2, azimuths), vertical=v, name=name)

    @classmethod
    def from_records(cls, first, second, vertical=None, *, azimuths="auto",
                     name: str = "") -> HorizontalPair:
        """A pair of two :class:`Record` objects (and a vertical motion);
        ``azimuths="auto"``: from the records' NGA headers (``meta["component"]``) when
        both state a number, else None (as :meth:`from_files`).

        Examples
        --------
        >>> from rocking.motions import HorizontalPair, load_builtin
        >>> pair = HorizontalPair.from_records(load_builtin("Rinaldi228"),
        ...                                    load_builtin("Rinaldi318"))
        >>> [round(a, 6) for a in pair.azimuths_deg]
        [228.0, 318.0]
        """
        return cls(first, second, azimuths=cls._auto(first, second, azimuths),
                   vertical=vertical, name=name)

    @classmethod
    def builtin(cls, name: str, second: str | None = None, *, vertical=True) -> HorizontalPair:
        """A pair shipped with the package: a three-component set by name (``"rinaldi"``,
        ``"duzce"``; :func:`rocking.motions.builtin_sets`) with its vertical component
        unless ``vertical=False``, or two built-in record names (``"Rinaldi228"``,
        ``"Rinaldi318"``; ``vertical``: a record name or False). The azimuths come from
        the records' headers.

        Examples
        --------
        >>> from rocking.motions import HorizontalPair
        >>> pair = HorizontalPair.builtin("Rinaldi228", "Rinaldi318")  # no vertical
        >>> [round(a, 6) for a in pair.azimuths_deg], pair.handedness, pair.vertical
        ([228.0, 318.0], 1, None)
        >>> HorizontalPair.builtin("rinaldi").vertical.name  # a set: with its vertical
        'RinaldiUP'
        """
        from .io import builtin_sets

        sets = builtin_sets()
        if second is None:
            if str(name).lower() not in sets:
                raise ParameterError(f"name must be a three-component set ({', '.join(sets)})"
                                     f" or two record names, got {name!r}")
            h1, h2, up = sets[str(name).lower()]
            label = str(name).lower()
            vname = up if vertical is True else (vertical or None)
        else:
            h1, h2, label = name, second, ""
            vname = None if vertical is True or not vertical else vertical
        r1, r2 = load_builtin(h1), load_builtin(h2)
        v = load_builtin(vname) if vname else None
        return cls(r1, r2, azimuths=cls._auto(r1, r2, "auto"), vertical=v, name=label)

    @staticmethod
    def _auto(r1, r2, azimuths):
        if not (isinstance(azimuths, str) and azimuths == "auto"):
            return azimuths
        a1, a2 = _component_azimuth(r1), _component_azimuth(r2)
        return None if a1 is None or a2 is None else (a1, a2)

    # ---------------------------------------------------------------- grid
    @property
    def n(self) -> int:
        return int(self.a1.size)

    @property
    def duration(self) -> float:
        """Time of the last sample (s)."""
        return (self.n - 1) * self.dt

    @property
    def t(self) -> np.ndarray:
        return np.arange(self.n) * self.dt

    @property
    def scan_step(self) -> float:
        """A time step that resolves the pair (s): its sampling step (and the vertical
        component's scan step, if finer); what a 3-D model's run reads, as a motion's.

        Examples
        --------
        >>> from rocking.motions import HorizontalPair
        >>> HorizontalPair.builtin("rinaldi", vertical=False).scan_step
        0.01
        """
        return min(self.dt, self.vertical.scan_step) if self.vertical is not None \
            else self.dt

    @property
    def quiet_time(self) -> float:
        """From this time (s) the ground is still: the end of the records (and of the
        vertical component).

        Examples
        --------
        >>> from rocking.motions import HorizontalPair
        >>> pair = HorizontalPair.builtin("rinaldi", vertical=False)
        >>> pair.quiet_time == pair.duration
        True
        """
        if self.vertical is None:
            return self.duration
        return max(self.duration, self.vertical.duration, self.vertical.quiet_time)

    @property
    def azimuths_deg(self) -> tuple | None:
        return None if self.azimuths is None else tuple(math.degrees(a) for a in self.azimuths)

    # ---------------------------------------------------------------- projection
    def weights(self, phi, orientation=None) -> tuple[float, float]:
        """``(w1, w2)`` with ``along(phi) = w1 a1 + w2 a2`` (module docstring).

        Examples
        --------
        >>> from rocking.motions import HorizontalPair, Record
        >>> ns, ew = Record(np.array([0.0, 1.0]), 0.01), Record(np.array([0.0, 2.0]), 0.01)
        >>> pair = HorizontalPair(ns, ew, azimuths=("0deg", "90deg"))  # N, E: clockwise
        >>> pair.weights(0.0), pair.weights("-90deg")  # bearings 0 and 90 deg
        ((1.0, 0.0), (0.0, 1.0))
        >>> [round(w, 4) for w in pair.weights("30deg")]  # bearing -30 deg: cos 30, cos 120
        [0.866, -0.5]
        """
        p = angle("phi", phi)
        az1 = 0.0 if self.azimuths is None else self.azimuths[0]
        o = az1 if orientation is None else angle("orientation", orientation)
        return plane_weights(p, o, az1, self.handedness)

    def along(self, phi, orientation=None) -> Record:
        """The horizontal acceleration along the object's direction ``phi`` (rad) as a
        :class:`Record` (m/s^2, the pair's time step; module docstring for
        ``orientation``).

        Examples
        --------
        >>> from rocking.motions import HorizontalPair
        >>> pair = HorizontalPair.builtin("rinaldi")  # Rinaldi228 / Rinaldi318
        >>> r = pair.along("45deg")
        >>> w1, w2 = pair.weights("45deg")
        >>> r.name, bool(np.allclose(r.values, w1 * pair.a1 + w2 * pair.a2))
        ('rinaldi @ 45.0 deg', True)
        >>> bool(np.allclose(pair.along("225deg").values, -r.values))  # phi + 180 deg: -a
        True
        """
        w1, w2 = self.weights(phi, orientation)
        if w2 == 0.0:
            acc = w1 * self.a1
        elif w1 == 0.0:
            acc = w2 * self.a2
        else:
            acc = w1 * self.a1 + w2 * self.a2
        p = angle("phi", phi)
        return Record(acc, self.dt, name=f"{self.name} @ {math.degrees(p):.1f} deg",
                      meta={"pair": self.name, "phi": p, "weights": (w1, w2)})

    def motion(self, phi, orientation=None, *, vertical: bool = True) -> Motion:
        """:meth:`along` with the vertical component (a :class:`GroundMotion`) when the
        pair has one and ``vertical`` is True; else the :class:`Record`.

        Examples
        --------
        >>> from rocking.motions import HorizontalPair
        >>> pair = HorizontalPair.builtin("rinaldi")
        >>> m = pair.motion(0.0)  # phi = 0: the first component, with the vertical one
        >>> type(m).__name__, m.vertical.name, bool(np.array_equal(m.horizontal.values, pair.a1))
        ('GroundMotion', 'RinaldiUP', True)
        >>> type(pair.motion(0.0, vertical=False)).__name__
        'Record'
        """
        h = self.along(phi, orientation)
        return GroundMotion(h, self.vertical) if vertical and self.vertical is not None \
            else h

    def orientation_of(self, heading) -> float:
        """The compass bearing (rad) of a body's ``x`` axis at ``heading`` (rad or
        ``"30deg"``) counter-clockwise of the first component, looking down:
        ``A1 - heading`` (``A1 = 0`` without azimuths).

        Examples
        --------
        >>> import math
        >>> from rocking.motions import HorizontalPair
        >>> pair = HorizontalPair.builtin("rinaldi")  # first component: 228 deg
        >>> round(math.degrees(pair.orientation_of("30deg")), 9)  # 30 deg ccw: 198 deg
        198.0
        """
        az1 = 0.0 if self.azimuths is None else self.azimuths[0]
        return az1 - angle("heading", heading)

    def on_plane(self, phi, heading=0.0, *, vertical: bool = True) -> Motion:
        """The planar motion along the body's direction ``phi`` (rad or ``"30deg"``), its
        ``x`` axis at ``heading`` counter-clockwise of the first component: :meth:`motion`
        with ``orientation = A1 - heading`` (:meth:`orientation_of`), the projection of
        :meth:`spec3` on that direction.

        Examples
        --------
        >>> from rocking.motions import HorizontalPair
        >>> from rocking.motions import _kernel as K
        >>> pair = HorizontalPair.builtin("rinaldi")
        >>> m = pair.on_plane("30deg", heading="15deg")
        >>> bool(np.array_equal(m.horizontal.values, pair.along("30deg", "213deg").values))
        True
        >>> kind, prm, samples = pair.spec3(heading="15deg")
        >>> ax, ay, az = K.ground_acc3(kind, prm, samples, 3.0)  # projected on 30 deg:
        >>> c, s = np.cos(np.radians(30)), np.sin(np.radians(30))
        >>> bool(np.isclose(ax * c + ay * s, m.acceleration(3.0), rtol=1e-12))
        True
        """
        return self.motion(phi, self.orientation_of(heading), vertical=vertical)

    def spec3(self, heading=0.0, *, vertical: bool = True) -> tuple[int, np.ndarray,
                                                                      np.ndarray]:
        """The three-component spec of the pair (:mod:`rocking.motions.components`): the
        two components (kind ``PAIR``) and the vertical one when the pair has one and
        ``vertical`` is True; the body's ``x`` axis at ``heading`` (rad or ``"30deg"``)
        counter-clockwise of the first component, looking down. The body sees
        ``ax = a_x cos h + a_y sin h``, ``ay = -a_x sin h + a_y cos h`` with ``a_x = a1``
        and ``a_y`` the acceleration 90 deg counter-clockwise of the first component:
        ``a2`` for a counter-clockwise pair (no azimuths), ``-a2`` for a clockwise one.

        Examples
        --------
        >>> from rocking.motions import HorizontalPair, Record
        >>> from rocking.motions import _kernel as K
        >>> x, y = Record(np.array([0.0, 1.0, 0.0]), 0.01), Record(np.array([0.0, 2.0, 0.0]), 0.01)
        >>> pair = HorizontalPair(x, y)  # no azimuths: the second is y
        >>> K.ground_acc3(*pair.spec3(), 0.01), K.ground_acc3(*pair.spec3(), 0.015)
        ((1.0, 2.0, 0.0), (0.5, 1.0, 0.0))
        >>> K.ground_acc3(*pair.spec3(heading="90deg"), 0.01)  # x along y: (a_y, -a_x)
        (2.0, -1.0, 0.0)
        """
        o = self.orientation_of(heading)
        az1 = 0.0 if self.azimuths is None else self.azimuths[0]
        kind, prm, samples = K.pair_spec(self.dt, self.a1, self.a2)
        wx = plane_weights(0.0, o, az1, self.handedness)
        wy = plane_weights(0.5 * math.pi, o, az1, self.handedness)
        prm = K.with_axes(prm, wx, wy)
        if vertical and self.vertical is not None:
            prm, samples = K.with_vertical(kind, prm, samples, *self.vertical.spec())
        return kind, prm, samples

    def rotated(self, angle_: float) -> HorizontalPair:
        """The same ground motion recorded on axes turned clockwise by ``angle_`` (rad,
        looking down; the azimuths grow by it): its first component is the projection on
        bearing ``A1 + angle_``. Turning a clockwise pair by 90 deg makes the second
        component the first (and minus the first the second). A pair without azimuths
        gets those of its ground frame (``A1 = 0``, ``A2 = -90`` deg) turned by
        ``angle_``.

        Examples
        --------
        >>> from rocking.motions import HorizontalPair
        >>> pair = HorizontalPair.builtin("rinaldi")  # 228 / 318 deg, clockwise
        >>> r = pair.rotated("90deg")
        >>> [round(a) for a in r.azimuths_deg]
        [318, 48]
        >>> bool(np.array_equal(r.a1, pair.a2)), bool(np.array_equal(r.a2, -pair.a1))
        (True, True)
        >>> r30 = pair.rotated("30deg")  # the first: the projection on bearing 228 + 30 deg
        >>> bool(np.allclose(r30.a1, pair.along("-30deg").values))
        True
        >>> round(r30.peak_resultant, 10) == round(pair.peak_resultant, 10)  # same vector
        True
        """
        d = angle("angle", angle_)
        az = self.azimuths if self.azimuths is not None else (0.0, -0.5 * math.pi)
        h = self.handedness
        c, s = cos_sin(d)
        # a along bearing A1 + d: a1 cos d + a2 cos(d - h 90) = a1 c + h a2 s
        # a along bearing A2 + d = A1 + h 90 + d: a1 cos(h 90 + d) + a2 cos d = -h a1 s + a2 c
        n1 = _mix(self.a1, self.a2, c, h * s)
        n2 = _mix(self.a1, self.a2, -h * s, c)
        r1 = Record(n1, self.dt, name=f"{self.first.name} rotated {math.degrees(d):g} deg")
        r2 = Record(n2, self.dt, name=f"{self.second.name} rotated {math.degrees(d):g} deg")
        tau = 2.0 * math.pi
        return HorizontalPair(r1, r2, azimuths=((az[0] + d) % tau, (az[1] + d) % tau),
                              vertical=self.vertical,
                              name=f"{self.name} rotated {math.degrees(d):g} deg")

    def scaled(self, factor: float) -> HorizontalPair:
        """Every component (the vertical one too) times ``factor``.

        Examples
        --------
        >>> from rocking.motions import HorizontalPair
        >>> pair = HorizontalPair.builtin("rinaldi")
        >>> half = pair.scaled(0.5)
        >>> [round(b / a, 12) for a, b in zip(pair.pga_components, half.pga_components)]
        [0.5, 0.5]
        >>> round(half.vertical.pga / pair.vertical.pga, 12)
        0.5
        """
        from .._validate import as_float

        f = as_float("factor", factor)
        return HorizontalPair(self.first.scaled(f), self.second.scaled(f),
                              azimuths=self.azimuths,
                              vertical=None if self.vertical is None
                              else self.vertical.scaled(f), name=self.name)

    # ---------------------------------------------------------------- peaks
    @property
    def pga_components(self) -> tuple[float, float]:
        """The PGA (m/s^2) of each component."""
        return float(np.max(np.abs(self.a1))), float(np.max(np.abs(self.a2)))

    @property
    def peak_resultant(self) -> float:
        """``max_t |a(t)|`` (m/s^2), the largest horizontal acceleration vector: the largest
        PGA of :meth:`along` over every direction (RotD100 of the PGA)."""
        return float(np.max(np.hypot(self.a1, self.a2)))

    def __repr__(self) -> str:
        az = "" if self.azimuths is None else \
            ", azimuths=({:g}, {:g}) deg".format(*self.azimuths_deg)
        v = ", with vertical" if self.vertical is not None else ""
        return (f"HorizontalPair({self.name!r}, n={self.n}, dt={self.dt:g} s{az}{v}, "
                f"pga={self.pga_components[0]:.3f}/{self.pga_components[1]:.3f} m/s^2)")


def _mix(a1, a2, w1, w2):
    if w2 == 0.0:
        return w1 * a1
    if w1 == 0.0:
        return w2 * a2
    return w1 * a1 + w2 * a2


__all__ = ["HorizontalPair"]
