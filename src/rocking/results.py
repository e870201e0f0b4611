"""Result objects of :func:`rocking.simulate` and :func:`rocking.simulate_many`.

One convention for every model:

* SI units: angles in rad, angular velocities in rad/s, times in s; ``theta`` follows the
  sign convention of the paper's Eq (1) (see :mod:`rocking.models.housner`);
* an event that did not happen has the time **NaN** (``overturn_time``, ``uplift_time``),
  in single and batch results alike (``summary()`` and ``to_dict()`` write it as ``None``
  in JSON);
* ``n_impacts`` is the number of impacts, i.e. passages of ``theta`` through zero, over
  the whole run (``impact_times`` keeps the first ``max_impacts`` of them); the DEM counts
  a zero crossing once ``|theta|`` has exceeded its ``impact_tol`` since the previous one
  (contact springs make tiny oscillations at rest);
* ``settled``: the block was at rest or had overturned when the run ended. With the
  default ``duration`` a run goes on after the motion until it has settled, up to
  ``max_free_time`` (:func:`rocking.simulate`); an unsettled run's outcome may still
  change, so it is flagged, never silently counted as a survivor;
* the default output interval is :data:`DEFAULT_DT_OUT` everywhere;
* every result has ``summary()`` (a small JSON-ready dict) and ``to_dict()`` (everything,
  JSON-ready).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ._atomic import atomic_path, atomic_write

DEFAULT_DT_OUT = 0.002
"""Default output interval (s) of the time histories, for single runs and batches."""


def jsonable(x):
    """``x`` as plain JSON data: NaN and inf -> None, numpy -> Python, arrays -> lists."""
    if isinstance(x, dict):
        return {str(k): jsonable(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [jsonable(v) for v in x]
    if isinstance(x, np.ndarray):
        return jsonable(x.tolist())
    if isinstance(x, bool | np.bool_):
        return bool(x)
    if isinstance(x, int | np.integer):
        return int(x)
    if isinstance(x, float | np.floating):
        x = float(x)
        return x if math.isfinite(x) else None
    if x is None or isinstance(x, str):
        return x
    return repr(x)


QUATERNION = ("q0", "q1", "q2", "q3")
"""The state names of an orientation quaternion (body to ground, scalar first)."""


def tilt_angle(q) -> np.ndarray:
    """The angle (rad) of the body's up axis from the vertical for the unit quaternions
    ``q`` (..., 4; body to ground, scalar first): ``R_zz = cos(tilt) = 1 - 2 (q1^2 +
    q2^2)``, written as ``2 atan2(sqrt(q1^2 + q2^2), sqrt(q0^2 + q3^2))``, accurate at
    small tilts too.

    Examples
    --------
    >>> import math
    >>> q = [math.cos(0.15), math.sin(0.15), 0.0, 0.0]  # 0.3 rad about x
    >>> round(float(tilt_angle(q)), 12)
    0.3
    """
    q = np.asarray(q, dtype=np.float64)
    return 2.0 * np.arctan2(np.hypot(q[..., 1], q[..., 2]), np.hypot(q[..., 0], q[..., 3]))


def twist_angle(q) -> np.ndarray:
    """The twist (rad) about the vertical of the quaternion history ``q`` (samples x 4):
    the twist of the swing-twist decomposition, ``2 atan2(q3, q0)``, unwrapped and
    relative to the first sample (counter-clockwise looking down).

    Examples
    --------
    >>> import math
    >>> q = [[math.cos(a / 2), 0.0, 0.0, math.sin(a / 2)] for a in (0.0, 3.0, -3.0)]
    >>> np.round(twist_angle(q), 12).tolist()  # -3 rad is 2 pi - 3 past +3: unwrapped
    [0.0, 3.0, 3.28318530718]
    """
    q = np.atleast_2d(np.asarray(q, dtype=np.float64))
    tw = np.unwrap(2.0 * np.arctan2(q[:, 3], q[:, 0]))
    return tw - tw[0]


def rotation_matrices(q) -> np.ndarray:
    """The rotation matrices (..., 3, 3) of the unit quaternions ``q`` (..., 4; scalar
    first)."""
    q = np.asarray(q, dtype=np.float64)
    q0, q1, q2, q3 = (q[..., i] for i in range(4))
    return np.stack([
        np.stack([1 - 2 * (q2 * q2 + q3 * q3), 2 * (q1 * q2 - q0 * q3),
                  2 * (q1 * q3 + q0 * q2)], -1),
        np.stack([2 * (q1 * q2 + q0 * q3), 1 - 2 * (q1 * q1 + q3 * q3),
                  2 * (q2 * q3 - q0 * q1)], -1),
        np.stack([2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1),
                  1 - 2 * (q1 * q1 + q2 * q2)], -1)], -2)


def support_base_point(shape) -> np.ndarray:
    """The base point of a :class:`~rocking.shapes.Shape` relative to its centre of mass
    in the body's frame (m, (3,)): the area centroid of its support at rest, on the
    ground (as :mod:`rocking.models.rigid3d` measures the slide)."""
    from .shapes.support import polygon_centroid

    cx, cy = polygon_centroid(np.asarray(shape.support))
    return np.array([cx, cy, -float(shape.h)])


def base_point_path(com, q, base_point) -> np.ndarray:
    """The horizontal displacement (samples x 2, m) of the point ``base_point`` (3,), fixed
    in the body (relative to its centre of mass), from its first position: ``com + R
    base_point``, for the centre of mass ``com`` (samples x 3) and orientation ``q``
    (samples x 4)."""
    p = np.asarray(com, dtype=np.float64) + rotation_matrices(q) @ np.asarray(base_point)
    return p[:, :2] - p[0, :2]


def _block_dict(block) -> dict | None:
    if block is None:
        return None
    if hasattr(block, "params"):
        d = dict(block.params())
        d["name"] = getattr(block, "name", "")
        return d
    return {"repr": repr(block)}


@dataclass
class Response:
    """Time history and summary of one simulation.

    Examples
    --------
    Free rocking of specimen 2 released at half its critical angle: in the linearised
    Eq 1 the first impact comes at ``acosh(2) / p``, and the amplitude never grows.

    >>> import math
    >>> import rocking
    >>> block = rocking.specimen(2)
    >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0, linear=True)
    >>> round(float(r.impact_times[0]), 4), round(math.acosh(2) / block.p, 4)
    (0.3457, 0.3457)
    >>> r.overturned, r.n_impacts, round(r.max_abs_theta / block.alpha, 3)
    (False, 2, 0.5)
    """

    t: np.ndarray
    theta: np.ndarray
    omega: np.ndarray
    impact_times: np.ndarray
    max_abs_theta: float | None
    """Largest ``|theta|`` (rad); None for a model without a planar angle."""
    overturned: bool
    overturn_time: float
    """Time (s) at which ``|theta|`` reached pi/2; NaN if the block did not overturn."""
    uplift_time: float
    """First time (s) the block left its rest position; NaN if it never did."""
    n_impacts: int
    """Number of impacts (passages through theta = 0) over the whole run (for the DEM,
    see :mod:`rocking.models.dem`)."""
    model: str = "housner"
    block: object = None
    motion: object = None
    info: dict = field(default_factory=dict)
    lift_off_time: float = math.nan
    """Time (s) at which the base fell away from the block (``g + a_v <= 0``, a vertical
    motion); the classical and CCRR models stop there. NaN if it never happened."""
    settled: bool = True
    """True if the block was at rest or had overturned when the run ended (the classical
    model also settles a block whose outcome the energy decides exactly; see
    :mod:`rocking.models.housner`). False: it was still moving (extend the duration)."""
    states: np.ndarray | None = None
    """The state history, samples x states (``state_names``; for the planar models
    ``theta`` and ``omega``, the DEM its bodies' positions and velocities)."""
    state_names: tuple = ()
    """The names of the columns of ``states`` (``Model.state_names``)."""
    outputs: dict = field(default_factory=dict)
    """Every declared output of the run (``Model.outputs``) by name; those that are not
    fields are attributes too (``r.max_base_displacement``)."""

    def __getattr__(self, name):
        outputs = self.__dict__.get("outputs") or {}
        if name in outputs:
            return outputs[name]
        raise AttributeError(f"{type(self).__name__!s} has no attribute {name!r}")

    def state(self, name: str) -> np.ndarray:
        """The history of the state variable ``name`` (one of :attr:`state_names`).

        Examples
        --------
        >>> import rocking
        >>> block = rocking.specimen(2)
        >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0)
        >>> r.state_names, bool((r.state("theta") == r.theta).all())
        (('theta', 'omega'), True)
        """
        if name not in self.state_names:
            raise KeyError(f"no state {name!r}; the states are {', '.join(self.state_names)}")
        return self.states[:, self.state_names.index(name)]

    # ------------------------------------------------------------ 3-D histories
    def _quaternions(self) -> np.ndarray | None:
        """The orientation history ``q0..q3`` (samples x 4), None without one."""
        names = tuple(self.state_names)
        if self.states is None or not all(n in names for n in QUATERNION):
            return None
        return self.states[:, [names.index(n) for n in QUATERNION]]

    @property
    def tilt(self) -> np.ndarray | None:
        """The tilt history (rad): the angle of the body's initial up axis from the
        vertical (:func:`tilt_angle`), for a model whose state has an orientation
        (``rigid3d``); None for the planar models (their angle is :attr:`theta`).

        Examples
        --------
        Released from a tilt of 0.05 rad, the box starts at that tilt:

        >>> import rocking
        >>> from rocking.shapes import Shape
        >>> box = Shape.box(0.4, 0.4, 1.2, density=2000.0)
        >>> r = rocking.simulate(box, model="rigid3d", duration=0.02, tilt0=0.05)
        >>> round(float(r.tilt[0]), 12), rocking.simulate(rocking.specimen(2), duration=0.1).tilt
        (0.05, None)
        """
        q = self._quaternions()
        return None if q is None else tilt_angle(q)

    @property
    def twist(self) -> np.ndarray | None:
        """The twist history (rad, counter-clockwise looking down): the rotation about the
        vertical of the swing-twist decomposition, followed continuously from the start
        (:func:`twist_angle`; ``residual_twist`` is its last value); None for the planar
        models."""
        q = self._quaternions()
        return None if q is None else twist_angle(q)

    def base_path(self) -> np.ndarray | None:
        """The horizontal displacement (m) of the body's base point (the centroid of its
        support at rest, carried with the body) from where it started, samples x 2
        (``x``, ``y`` in the ground's frame): the quantity of ``max_slide`` and
        ``residual_slide``. None for the planar models.

        Examples
        --------
        A box released from a tilt rocks about its edge: its base point moves, the
        largest distance (sampled every step) is ``max_slide``.

        >>> import rocking
        >>> from rocking.shapes import Shape
        >>> box = Shape.box(0.4, 0.4, 1.2, density=2000.0)
        >>> r = rocking.simulate(box, model="rigid3d", duration=0.2, tilt0=0.1, step=1e-3,
        ...                      dt_out=1e-3)
        >>> p = r.base_path()
        >>> p.shape, p[0].tolist()
        ((201, 2), [0.0, 0.0])
        >>> bool(np.isclose(np.hypot(p[:, 0], p[:, 1]).max(), r.max_slide, rtol=1e-12))
        True
        """
        q = self._quaternions()
        if q is None:
            return None
        # the base point the model measured the slide from (Model.info), or the shape's
        bp = self.info.get("base_point")
        bp = support_base_point(self.block) if bp is None else np.asarray(bp, float)
        return base_point_path(self.states[:, [self.state_names.index(n) for n in "xyz"]],
                               q, bp)

    @property
    def slide(self) -> np.ndarray | None:
        """The slide history (m): the horizontal distance of the base point from where it
        started (:meth:`base_path`; ``max_slide`` is its largest value, ``residual_slide``
        its last); None for the planar models."""
        p = self.base_path()
        return None if p is None else np.hypot(p[:, 0], p[:, 1])

    def com_path(self) -> np.ndarray | None:
        """The path of the centre of mass seen from above (m): its ``x``, ``y`` relative to
        the ground (samples x 2); None for the planar models.

        Examples
        --------
        Released from a tilt ``th`` about the edge at ``x = -b`` (``b``, ``h``: half the
        width and height), the centre of mass starts at ``x = -b + b cos(th) - h sin(th)``:

        >>> import math
        >>> import rocking
        >>> from rocking.shapes import Shape
        >>> box = Shape.box(0.4, 0.4, 1.2, density=2000.0)
        >>> r = rocking.simulate(box, model="rigid3d", duration=0.2, tilt0=0.1, step=1e-3)
        >>> x0, y0 = r.com_path()[0]
        >>> round(float(x0), 9), round(-0.2 + 0.2 * math.cos(0.1) - 0.6 * math.sin(0.1), 9)
        (-0.060899217, -0.060899217)
        """
        if self._quaternions() is None:
            return None
        names = tuple(self.state_names)
        return self.states[:, [names.index("x"), names.index("y")]].copy()

    @property
    def lifted_off(self) -> bool:
        """True if the run stopped because the block left the ground (``g + a_v <= 0``)."""
        return not math.isnan(self.lift_off_time)

    @property
    def rocked(self) -> bool:
        """True if the block ever left its rest position."""
        return not math.isnan(self.uplift_time) or bool(self.max_abs_theta)

    @property
    def duration(self) -> float:
        """Simulated time (s): the last output time."""
        return float(self.t[-1]) if self.t.size else 0.0

    def half_cycle_peaks(self) -> tuple[np.ndarray, np.ndarray]:
        """Times (s) and values (rad, signed) of the largest ``|theta|`` in each half-cycle.

        Half-cycles are delimited by the impacts; each peak is refined by a parabola
        through the three output samples around it (accuracy ~ (omega dt_out)^2). Only
        reached peaks count: none when the block never uplifted (``uplift_time`` NaN; a
        DEM block's contact springs still move it by a micro-radian); none in the first
        half-cycle of a run that starts moving towards ``theta = 0``; none in the last
        half-cycle when the run ends (or the block overturns) while ``|theta|`` still
        grows.

        Examples
        --------
        Free rocking released at ``theta0 = alpha/2`` (linearised Eq 1): the impact
        multiplies ``omega`` by ``mu``, so the next peak is ``alpha (1 - sqrt(1 - (3/4)
        mu^2))``, on the other side.

        >>> import math
        >>> import rocking
        >>> block = rocking.specimen(2)
        >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0, linear=True)
        >>> times, peaks = r.half_cycle_peaks()
        >>> round(float(peaks[0] / block.alpha), 4), round(float(peaks[1] / block.alpha), 4)
        (0.5, -0.4417)
        >>> round(1 - math.sqrt(1 - 0.75 * block.mu**2), 4)
        0.4417
        """
        if math.isnan(self.uplift_time) or self.t.size < 2:
            return np.empty(0), np.empty(0)
        edges = np.concatenate(([self.t[0]], self.impact_times, [self.t[-1]]))
        a = np.abs(self.theta)
        growing = self.theta * self.omega  # > 0: |theta| grows
        last = a.size - 1
        tp, vp = [], []
        for lo, hi in zip(edges[:-1], edges[1:], strict=True):
            idx = np.flatnonzero((self.t >= lo) & (self.t <= hi))
            if idx.size == 0:
                continue
            i = idx[np.argmax(a[idx])]
            if (a[i] == 0.0 or (i == 0 and growing[0] < 0.0)
                    or (i == last and hi == edges[-1] and growing[last] > 0.0)):
                continue
            t_i, v_i = self.t[i], self.theta[i]
            c = i if 0 < i < last and idx[0] < i < idx[-1] else (
                i - 1 if i == last and i >= 2 and idx[0] < i - 1 else -1)
            if c > 0:  # the parabola through samples c - 1, c, c + 1
                y0, y1, y2 = a[c - 1], a[c], a[c + 1]
                den = y0 - 2 * y1 + y2
                d = 0.5 * (y0 - y2) / den if den < 0 else math.nan
                if -1.0 <= d <= 1.0:
                    t_i = self.t[c] + d * (self.t[c + 1] - self.t[c])
                    v_i = np.sign(v_i) * (y1 - 0.25 * (y0 - y2) * d)
            tp.append(t_i)
            vp.append(v_i)
        return np.asarray(tp), np.asarray(vp)

    def summary(self) -> dict:
        """JSON-ready summary (SI units; ``max_abs_theta_deg`` for convenience; NaN times
        as None).

        Examples
        --------
        Released at ``alpha/2``, free rocking never exceeds it; the block did not
        overturn, so its ``overturn_time`` (NaN) is written as None:

        >>> import math
        >>> import rocking
        >>> block = rocking.specimen(2)
        >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0, linear=True)
        >>> s = r.summary()
        >>> round(s["max_abs_theta_deg"], 4), round(math.degrees(0.5 * block.alpha), 4)
        (4.8128, 4.8128)
        >>> s["overturned"], s["overturn_time"], s["n_impacts"], s["block"]["mu"]
        (False, None, 2, 0.958)
        """
        planar = self.max_abs_theta is not None
        d = {
            "model": self.model,
            **({"max_abs_theta": float(self.max_abs_theta),
                "max_abs_theta_deg": math.degrees(self.max_abs_theta)} if planar else {}),
            "overturned": bool(self.overturned),
            "overturn_time": self.overturn_time,
            "uplift_time": self.uplift_time,
            **({"n_impacts": int(self.n_impacts)}
               if not self.outputs or "n_impacts" in self.outputs else {}),
            "lifted_off": self.lifted_off,
            "lift_off_time": self.lift_off_time,
            "settled": bool(self.settled),
            "duration": self.duration,
        }
        for k, v in self.outputs.items():  # the model's declared outputs
            d.setdefault(k, v)
        blk = _block_dict(self.block)
        if blk is not None:
            d["block"] = blk
        if self.motion is not None:
            d["motion"] = repr(self.motion)
        d.update({k: v for k, v in self.info.items() if isinstance(v, int | float | str | bool)})
        return jsonable(d)

    def to_dict(self) -> dict:
        """Everything, JSON-ready: the summary, ``info`` and the time histories.

        Examples
        --------
        >>> import json
        >>> import rocking
        >>> block = rocking.specimen(2)
        >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0, linear=True)
        >>> d = json.loads(json.dumps(r.to_dict()))  # plain JSON, round trip
        >>> len(d["t"]) == len(d["theta"]) == r.t.size, d["t"][-1]
        (True, 1.0)
        >>> d["theta"] == r.theta.tolist(), d["overturn_time"]  # NaN -> None
        (True, None)
        """
        d = self.summary()
        d["info"] = jsonable({k: v for k, v in self.info.items()})
        d["impact_times"] = jsonable(self.impact_times)
        d["t"] = jsonable(self.t)
        d["theta"] = jsonable(self.theta)
        d["omega"] = jsonable(self.omega)
        if self.states is not None and tuple(self.state_names) != ("theta", "omega"):
            d["state_names"] = list(self.state_names)
            d["states"] = jsonable(self.states)
        return d

    def to_dataframe(self):
        """``pandas.DataFrame`` with columns ``t``, ``theta``, ``omega`` (planar models) and
        every state variable (:attr:`state_names`) not among them; for a 3-D body
        (``rigid3d``) then ``tilt`` (rad), ``slide`` (m) and ``twist`` (rad)
        (:attr:`tilt`, :attr:`slide`, :attr:`twist`).

        Examples
        --------
        >>> import rocking
        >>> block = rocking.specimen(2)
        >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0, linear=True)
        >>> df = r.to_dataframe()
        >>> df.columns.tolist(), len(df)  # 1 s at the default 2 ms
        (['t', 'theta', 'omega'], 501)
        >>> round(float(df["theta"].abs().max() / block.alpha), 4)  # released at alpha/2
        0.5
        """
        import pandas as pd  # lazy: keeps `import rocking` at 0.2 s (pandas: 0.45 s)

        cols = {"t": self.t}
        if self.theta is not None:
            cols |= {"theta": self.theta, "omega": self.omega}
        if self.states is not None:
            for j, name in enumerate(self.state_names):
                cols.setdefault(name, self.states[:, j])
        if self._quaternions() is not None:  # a 3-D body: its derived histories
            cols |= {"tilt": self.tilt, "slide": self.slide, "twist": self.twist}
        return pd.DataFrame(cols)

    def to_csv(self, path) -> Path:
        """Write ``t, theta, omega`` (s, rad, rad/s) to ``path`` as CSV.

        Examples
        --------
        >>> import pandas as pd
        >>> import rocking
        >>> block = rocking.specimen(2)
        >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0, linear=True)
        >>> r.to_csv("free_rocking.csv").name  # the path written
        'free_rocking.csv'
        >>> back = pd.read_csv("free_rocking.csv")
        >>> back.columns.tolist(), bool(np.allclose(back["theta"], r.theta, rtol=1e-9))
        (['t', 'theta', 'omega'], True)
        """
        path = Path(path)
        with atomic_path(path) as tmp:
            self.to_dataframe().to_csv(tmp, index=False, float_format="%.10g")
        return path

    def to_json(self, path) -> Path:
        """Write :meth:`summary` to ``path``.

        Examples
        --------
        >>> import json
        >>> import rocking
        >>> block = rocking.specimen(2)
        >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0, linear=True)
        >>> path = r.to_json("free_rocking.json")
        >>> with open(path) as f:
        ...     saved = json.load(f)
        >>> saved == r.summary(), saved["overturned"], saved["n_impacts"]
        (True, False, 2)
        """
        path = Path(path)
        atomic_write(path, json.dumps(self.summary(), indent=2))
        return path

    def plot(self, ax=None, **kw):
        """Plot theta(t) in degrees; returns the matplotlib Axes.

        Keyword arguments go to :func:`rocking.plot.plot_response` (``deg``, ``label``,
        ``show_alpha``, ``title``, and ``Axes.plot``'s).

        Examples
        --------
        >>> import math
        >>> import matplotlib.pyplot as plt
        >>> import rocking
        >>> block = rocking.specimen(2)
        >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0, linear=True)
        >>> ax = r.plot()
        >>> ax.get_xlabel(), round(float(max(ax.lines[0].get_ydata())), 3)  # alpha/2 in degrees
        ('time t (s)', 4.813)
        >>> round(math.degrees(0.5 * block.alpha), 3)
        4.813
        >>> plt.close("all")
        """
        from .plot import plot_response  # lazy: plot imports the motions (numba)

        return plot_response(self, ax=ax, **kw)


@dataclass
class DEMResponse(Response):
    """A :class:`Response` of the discrete element model, with its extra fields.

    Examples
    --------
    Specimen 2 released at half its critical angle: its first impact agrees with the
    classical model's (0.346 s) to the output interval.

    >>> import rocking
    >>> block = rocking.specimen(2)
    >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=0.5, model="dem")
    >>> type(r).__name__, r.theta_all.shape
    ('DEMResponse', (1, 251))
    >>> round(float(r.impact_times[0]), 2)
    0.35
    """

    x: np.ndarray | None = None
    """Horizontal displacement (m) of the centroid relative to the base."""
    y: np.ndarray | None = None
    """Vertical displacement (m) of the centroid from its nominal position on undeformed
    contacts (at rest it is minus the static settlement)."""
    theta_all: np.ndarray | None = None
    """Rotation (rad) of every block of a stack, shape ``(n_blocks, n_t)``."""
    x_all: np.ndarray | None = None
    """``x`` of every block, shape ``(n_blocks, n_t)``."""
    y_all: np.ndarray | None = None
    """``y`` of every block, shape ``(n_blocks, n_t)``."""
    contact_forces: dict | None = None
    """Contact forces on request (``return_forces=True``); see
    :mod:`rocking.models.dem`."""

    def to_dataframe(self):
        """``t``, ``theta``, ``omega``, ``x``, ``y`` (top block), then every state of the
        model not among them (``x_cm``, ``y_cm``, ``vx_cm``, ``vy_cm``: the state vector).

        Examples
        --------
        Released at ``theta0 = alpha/2`` about its corner, the centroid starts at ``x =
        R (sin(alpha - theta0) - sin(alpha))``, ``y = R (cos(alpha - theta0) -
        cos(alpha))`` (up to the contact springs' settlement, ~1e-7 m):

        >>> import math
        >>> import rocking
        >>> block = rocking.specimen(2)
        >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=0.5, model="dem")
        >>> df = r.to_dataframe()
        >>> df.columns.tolist()[:5]  # then the states not among them (x_cm, y_cm, ...)
        ['t', 'theta', 'omega', 'x', 'y']
        >>> a, R = block.alpha, block.R
        >>> round(float(df["x"][0]), 4), round(R * (math.sin(a / 2) - math.sin(a)), 4)
        (-0.0423, -0.0423)
        >>> round(float(df["y"][0]), 4), round(R * (math.cos(a / 2) - math.cos(a)), 4)
        (0.0054, 0.0054)
        """
        df = super().to_dataframe()
        df.insert(3, "x", self.x)
        df.insert(4, "y", self.y)
        return df

    def to_dict(self) -> dict:
        """Everything of :meth:`Response.to_dict`, JSON-ready, with ``x``, ``y`` and the
        histories of every block of a stack (``theta_all``, ``x_all``, ``y_all``; the
        ``contact_forces`` if recorded).

        Examples
        --------
        >>> import json
        >>> import rocking
        >>> block = rocking.specimen(2)
        >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=0.5, model="dem")
        >>> d = json.loads(json.dumps(r.to_dict()))  # plain JSON, round trip
        >>> len(d["theta_all"]), len(d["theta_all"][0]) == len(d["t"]) == len(d["x"])
        (1, True)
        >>> d["theta_all"][0] == d["theta"]  # one block: the stack is the block
        True
        """
        d = super().to_dict()
        for k in ("x", "y", "theta_all", "x_all", "y_all"):
            d[k] = jsonable(getattr(self, k))
        if self.contact_forces is not None:
            d["contact_forces"] = jsonable(self.contact_forces)
        return d


@dataclass
class BatchResponse:
    """Summaries of a batch of simulations, one entry per motion (numpy arrays).

    ``overturn_time``, ``uplift_time`` and ``lift_off_time`` are NaN where the event did
    not happen; ``lifted_off`` marks the runs in which the block left the ground (``g + a_v
    <= 0`` under a vertical motion): a planar model (classical, CCRR) stops there, which
    decides neither an overturn nor a survival; ``rigid3d`` follows the flight.
    ``theta``/``omega`` (shape ``(n_motions, n_times)``) are present only when histories
    were requested; after the end of a run (an overturn, or the block at rest after the
    motion) they are NaN. ``status`` is 0 for a successful run (see ``errors=`` of
    :func:`rocking.simulate_many`). ``settled`` is True where the block was at rest or
    had overturned when the run ended (see :class:`Response`).

    Examples
    --------
    Two one-sine pulses, below and above the uplift acceleration ``g tan(alpha)``: the
    first does not rock the block at all.

    >>> import math
    >>> import rocking
    >>> from rocking.motions import OneSine
    >>> block = rocking.specimen(2)
    >>> a_up = rocking.G * math.tan(block.alpha)
    >>> res = rocking.simulate_many(block, [OneSine(0.9 * a_up, 0.5),
    ...                                     OneSine(1.5 * a_up, 0.5)], duration=3.0)
    >>> np.isnan(res.uplift_time), res.overturned
    (array([ True, False]), array([False,  True]))
    """

    max_abs_theta: np.ndarray | None
    overturned: np.ndarray
    overturn_time: np.ndarray
    uplift_time: np.ndarray
    n_impacts: np.ndarray | None
    n_steps: np.ndarray | None = None
    status: np.ndarray | None = None
    t: np.ndarray | None = None
    theta: np.ndarray | None = None
    omega: np.ndarray | None = None
    model: str = "housner"
    block: object = None
    info: dict = field(default_factory=dict)
    lift_off_time: np.ndarray | None = None
    settled: np.ndarray | None = None
    outputs: dict = field(default_factory=dict)
    """The model's own scalar outputs per run (``Model.row_outputs``), by name; each is
    also an attribute (``res.max_base_displacement``)."""
    states: np.ndarray | None = None
    """The state histories, runs x samples x states (``state_names``), with
    ``return_histories=True``; NaN past the end of each run."""
    state_names: tuple = ()
    """The names of the last axis of ``states`` (``Model.state_names``)."""

    def __getattr__(self, name):
        outputs = self.__dict__.get("outputs") or {}
        if name in outputs:
            return outputs[name]
        raise AttributeError(f"{type(self).__name__!s} has no attribute {name!r}"
                             + (f" (outputs of this model: {', '.join(outputs)})"
                                if outputs else ""))

    def __post_init__(self):
        if self.lift_off_time is None:
            self.lift_off_time = np.full(np.shape(self.overturned), np.nan)
        if self.settled is None:
            self.settled = np.ones(np.shape(self.overturned), dtype=bool)

    @property
    def lifted_off(self) -> np.ndarray:
        """True where the run stopped because the block left the ground."""
        return ~np.isnan(self.lift_off_time)

    def __len__(self) -> int:
        return int(np.size(self.overturned))

    @property
    def rocked(self) -> np.ndarray:
        """True where the block left its rest position."""
        if self.max_abs_theta is None:
            return ~np.isnan(self.uplift_time)
        return ~np.isnan(self.uplift_time) | (self.max_abs_theta > 0.0)

    def to_dataframe(self):
        """One row per motion with the summary quantities (and the model's own
        :attr:`outputs`).

        Examples
        --------
        Two one-sine pulses, below and above the uplift acceleration ``g tan(alpha)``:

        >>> import math
        >>> import rocking
        >>> from rocking.motions import OneSine
        >>> block = rocking.specimen(2)
        >>> a_up = rocking.G * math.tan(block.alpha)  # uplift acceleration
        >>> res = rocking.simulate_many(block, [OneSine(0.9 * a_up, 0.5),
        ...                                     OneSine(1.5 * a_up, 0.5)], duration=3.0)
        >>> df = res.to_dataframe()
        >>> len(df), df["overturned"].tolist(), df["uplift_time"].isna().tolist()
        (2, [False, True], [True, False])
        """
        import pandas as pd  # lazy: keeps `import rocking` at 0.2 s (pandas: 0.45 s)

        cols = {
            "max_abs_theta": self.max_abs_theta,
            "overturned": self.overturned,
            "overturn_time": self.overturn_time,
            "uplift_time": self.uplift_time,
            "n_impacts": self.n_impacts,
            "lifted_off": self.lifted_off,
            "lift_off_time": self.lift_off_time,
            "settled": self.settled,
            **self.outputs,
        }
        return pd.DataFrame({k: v for k, v in cols.items() if v is not None})

    def summary(self) -> dict:
        """JSON-ready statistics over the batch: counts, the overturned fraction, and the
        median and largest ``max_abs_theta`` of the runs that did not overturn.

        Examples
        --------
        The pulse below ``g tan(alpha)`` does not rock the block, the one above overturns
        it:

        >>> import math
        >>> import rocking
        >>> from rocking.motions import OneSine
        >>> block = rocking.specimen(2)
        >>> a_up = rocking.G * math.tan(block.alpha)  # uplift acceleration
        >>> res = rocking.simulate_many(block, [OneSine(0.9 * a_up, 0.5),
        ...                                     OneSine(1.5 * a_up, 0.5)], duration=3.0)
        >>> s = res.summary()
        >>> s["n"], s["n_overturned"], s["overturned_fraction"], s["n_rocked"]
        (2, 1, 0.5, 1)
        >>> s["max_max_abs_theta_survived"]  # the survivor never left its rest position
        0.0
        """
        n = len(self)
        peak = (self.max_abs_theta if self.max_abs_theta is not None
                else np.full(n, np.nan))
        ok = ~self.overturned & np.isfinite(peak)
        surv = peak[ok]
        d = {
            "model": self.model,
            "n": n,
            "n_overturned": int(np.count_nonzero(self.overturned)),
            "overturned_fraction": float(np.mean(self.overturned)) if n else math.nan,
            "n_rocked": int(np.count_nonzero(self.rocked)),
            "median_max_abs_theta_survived": float(np.median(surv)) if surv.size else None,
            "max_max_abs_theta_survived": float(np.max(surv)) if surv.size else None,
            "n_impacts_sum": int(np.sum(self.n_impacts)) if self.n_impacts is not None else 0,
            "n_lifted_off": int(np.count_nonzero(self.lifted_off)),
            "n_unsettled": int(np.count_nonzero(~self.settled)),
            "n_failed": int(np.count_nonzero(self.status)) if self.status is not None else 0,
        }
        blk = _block_dict(self.block)
        if blk is not None:
            d["block"] = blk
        d.update({k: v for k, v in self.info.items() if isinstance(v, int | float | str | bool)})
        return jsonable(d)

    def to_dict(self) -> dict:
        """Everything, JSON-ready: the summary, the per-motion arrays and the histories.

        Examples
        --------
        Events that did not happen (NaN times) are None, and histories not requested too:

        >>> import math
        >>> import rocking
        >>> from rocking.motions import OneSine
        >>> block = rocking.specimen(2)
        >>> a_up = rocking.G * math.tan(block.alpha)  # uplift acceleration
        >>> res = rocking.simulate_many(block, [OneSine(0.9 * a_up, 0.5),
        ...                                     OneSine(1.5 * a_up, 0.5)], duration=3.0)
        >>> d = res.to_dict()
        >>> d["overturned"], d["uplift_time"][0], d["overturn_time"][0], d["theta"]
        ([False, True], None, None, None)
        >>> round(d["uplift_time"][1], 4) == round(float(res.uplift_time[1]), 4)
        True
        """
        d = self.summary()
        for k in ("max_abs_theta", "overturned", "overturn_time", "uplift_time", "n_impacts",
                  "lifted_off", "lift_off_time", "settled", "n_steps", "status", "t", "theta",
                  "omega"):
            d[k] = jsonable(getattr(self, k))
        return d
