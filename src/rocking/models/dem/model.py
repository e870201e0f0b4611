"""The DEM as a model of the common interface (:mod:`rocking.models.base`): its options,
the resolution of the default stiffness and damping, and its extra outputs."""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from ...blocks import Stack
from ...errors import ParameterError
from ...results import DEMResponse
from ...units import G
from ..base import Model, ModelOptions, option
from . import geometry as GEO
from . import statics as ST
from .calibration import calibrate_damping, damping_cap
from .friction import DEFAULT_FRICTION_ANGLE, HALF_PI, degrees_if_bare
from .kernel import batch_kernel, kernel
from .parameters import paper_parameters


@dataclass(frozen=True)
class DEMOptions(ModelOptions):
    """Options of the discrete element model."""

    friction_angle: float = option(
        DEFAULT_FRICTION_ANGLE, unit="rad", quantity="angle", lo=0.0, hi=HALF_PI,
        lo_open=False, hi_open=True,
        help="friction angle phi of every contact (default 30 degrees; '30deg' accepted; "
             "a bare number >= pi/2 is read as degrees, deprecated)")
    stiffness: float | None = option(None, unit="N/m", lo=0.0,
                                     help="normal stiffness K of one contact point "
                                          "(default: settlement 1e-7 of the height)")
    shear_stiffness: float | None = option(None, unit="N/m", lo=0.0,
                                           help="shear stiffness Ks (default K)")
    damping: float | str | None = option(
        None, kind=object, unit="s", help="stiffness-proportional damping b (s, C = b K), "
                                "'calibrated' (default: matches mu) or 'paper' (Eq 20)")
    cohesion: float = option(0.0, unit="N", lo=0.0, lo_open=False,
                             help="cohesive shear strength of one contact point")
    geometry: str = option("auto", choices=GEO.GEOMETRIES,
                           help="body of a Block: auto, polygon, body (a mesh block's "
                                "outline with its own mass and inertia), equivalent (Eq "
                                "18), classical")
    dt: float | None = option(None, unit="s", lo=0.0,
                              help="time step (default: from the stability limit)")
    settled: bool = option(True, help="start at static equilibrium on the contacts")
    impact_tol: float = option(1e-3, lo=0.0, lo_open=False,
                               help="|theta| (fraction of alpha) to exceed between two "
                                    "counted zero crossings")
    return_forces: bool = option(False, help="record the contact forces (single runs)")
    return_energy: bool = option(False, help="record kinetic, potential and spring "
                                             "energies (single runs)")

    def __post_init__(self):
        # a bare number >= pi/2 is an angle in degrees (deprecated), before the range check
        object.__setattr__(self, "friction_angle", degrees_if_bare(self.friction_angle))
        super().__post_init__()

    def check(self):
        d = self.damping
        if d is None or (isinstance(d, str) and d in ("calibrated", "paper")):
            return
        try:
            x = float(d)
        except (TypeError, ValueError):
            x = math.nan
        if isinstance(d, str) or not (math.isfinite(x) and x >= 0.0):
            raise ParameterError(f"damping must be a number >= 0 s, 'calibrated' or "
                                 f"'paper'; got {d!r}")
        object.__setattr__(self, "damping", x)


def _slot_labels(model: GEO.Assembly) -> list[str]:
    n, vmax = model.n, model.lv.shape[1]
    return [f"block {i} vertex {k} / {'base' if j == n else f'block {j}'}"
            for i in range(n) for k in range(vmax) for j in range(n + 1)]


class DEM(Model):
    """Discrete elements: rigid polygons on contact springs (:mod:`rocking.models.dem`)."""

    name = "dem"
    label = "DEM"
    Options = DEMOptions
    kernel = kernel
    batch_kernel = batch_kernel
    accepts_stack = True
    slow = True
    batch_initial_state = False  # the initial state of the contacts is built per batch
    append_overturn = False
    response_class = DEMResponse
    tags = {"planar": True, "symmetry": "mirror"}

    @property
    def state_names(self) -> tuple:
        """Every block's ``x_cm``, ``y_cm`` (its centroid in the base's frame; m) and
        ``theta`` (rad), then every block's ``vx_cm``, ``vy_cm`` (m/s) and ``omega``
        (rad/s); ``_1`` ... ``_n`` from the bottom block up in a stack. (``DEMResponse.x``
        and ``y`` are the top centroid's displacements from its nominal position.)"""
        n = self.assembly.n
        sfx = [""] if n == 1 else [f"_{i + 1}" for i in range(n)]
        pos = [f"{v}{x}" for x in sfx for v in ("x_cm", "y_cm", "theta")]
        vel = [f"{v}{x}" for x in sfx for v in ("vx_cm", "vy_cm", "omega")]
        return tuple(pos + vel)

    @property
    def state_units(self) -> tuple:
        return ("m", "m", "rad") * self.assembly.n + ("m/s", "m/s", "rad/s") * self.assembly.n

    def planar_shorthand(self) -> tuple[int, int]:
        """The top block's ``theta`` and ``omega``."""
        n = self.assembly.n
        return 3 * (n - 1) + 2, 3 * n + 3 * (n - 1) + 2

    def initial_state(self, theta0: float = 0.0, omega0: float = 0.0) -> np.ndarray:
        """The bodies rotated by ``theta0`` about the pivot with ``omega0``, settled on
        their contact springs (:func:`rocking.models.dem.statics.state_vector`)."""
        return ST.state_vector(self.assembly, self.K, self.Ks, theta0, omega0,
                               self.options.settled)

    def check_state(self, y0):
        """The DEM takes its initial state as ``theta0``, ``omega0``: the contacts' initial
        forces are built from them (:meth:`initial_state`)."""
        raise ParameterError("model 'dem' takes its initial state as theta0 and omega0 (the "
                             "contact forces of the initial state are built from them), "
                             "not state0")

    @staticmethod
    def check_bodies(block, assembly: GEO.Assembly) -> None:
        """An asymmetric block (its two sides differ) is simulated as the rigid body its
        polygon outlines (geometry ``"body"``: a mesh block, :mod:`rocking.shapes`); the
        rectangles of ``"classical"``/``"equivalent"`` and a polygon's own mass and
        inertia would be another, symmetric body: refused."""
        blocks = block.blocks if isinstance(block, Stack) else (block,)
        for b, bd in zip(blocks, assembly.bodies, strict=True):
            if not b.symmetric and bd.mode != "body":
                raise ParameterError(
                    f"model 'dem' takes symmetric blocks only, or an asymmetric one as the "
                    "rigid body of its outline (geometry 'body': a mesh block, "
                    f"rocking.shapes); {b.name or 'the block'} has alpha_plus = "
                    f"{b.alpha_plus:.4g}, alpha_minus = {b.alpha_minus:.4g} rad and geometry "
                    f"{bd.mode!r}; use model='housner' or 'ccrr'")

    @staticmethod
    def plastic_impact_damping(block, K, geometry, Ks) -> float:
        """The damping of an asymmetric block's body (geometry ``"body"``): the cap of
        :func:`~rocking.models.dem.damping_cap`, where the DEM's impact is plastic and its
        restitutions are the angular-momentum balance of the body about the new pivot,
        i.e. the block's ``mu_plus`` and ``mu_minus`` when derived (Housner's argument; the
        calibration of :func:`~rocking.models.dem.calibrate_damping` measures one
        symmetric restitution). A block whose restitutions were given otherwise is
        refused: give ``damping`` (s)."""
        xg, yg, i_g = GEO.rigid_body(block)
        (xl, _), (xr, _) = block.vertices[0], block.vertices[1]
        bp, bm, rg2 = xg - xl, xr - xg, i_g / block.mass
        derived = ((rg2 + yg * yg - bp * bm) / (rg2 + bm * bm + yg * yg),
                   (rg2 + yg * yg - bp * bm) / (rg2 + bp * bp + yg * yg))
        given = (block.mu_plus, block.mu_minus)
        if any(abs(d - g) > 1e-6 for d, g in zip(derived, given, strict=True)):
            raise ParameterError(
                f"damping: the DEM's damping of an asymmetric block is that of a plastic "
                f"impact, whose restitutions are the body's (mu_plus = {derived[0]:.4f}, "
                f"mu_minus = {derived[1]:.4f}); {block.name or 'the block'} has mu_plus = "
                f"{given[0]:.4f}, mu_minus = {given[1]:.4f}: give damping (s) explicitly")
        return damping_cap(block, K, geometry, Ks)

    def __init__(self, block, options=None):
        super().__init__(block, options)
        o = self.options
        self.assembly = md = GEO.build_assembly(block, o.geometry)
        self.check_bodies(block, md)
        self.K = GEO.default_stiffness(md) if o.stiffness is None else o.stiffness
        self.Ks = self.K if o.shear_stiffness is None else o.shear_stiffness
        top = block.blocks[-1] if isinstance(block, Stack) else block
        if (o.damping is None or o.damping == "calibrated") and not top.symmetric:
            self.b = self.plastic_impact_damping(top, self.K, o.geometry, self.Ks)
            self.damping_source = "plastic impact (asymmetric body)"
        elif o.damping is None or o.damping == "calibrated":
            cal = calibrate_damping(top, top.mu, self.K, geometry=o.geometry,
                                    friction_angle=o.friction_angle,
                                    shear_stiffness=self.Ks, full=True)
            self.b, self.damping_source = cal["b"], "calibrated"
            if abs(cal["mu_dem"] - top.mu) > 5e-3:
                warnings.warn(f"DEM damping: {cal['note']}; the DEM's restitution is "
                              f"{cal['mu_dem']:.4f}", RuntimeWarning, stacklevel=5)
        elif o.damping == "paper":
            self.b, self.damping_source = paper_parameters(top)["b"], "paper (Eq 20)"
        else:
            self.b, self.damping_source = float(o.damping), "given"
        self.th_tol = o.impact_tol * min(bd.alpha for bd in md.bodies)

    def step(self, dt_out: float) -> tuple[float, int]:
        """``(dt, every)``: the time step (s) for the output interval ``dt_out`` (s), and
        the steps per output sample (:func:`rocking.models.dem.statics.time_step`)."""
        return ST.time_step(self.assembly, self.K, self.Ks, self.b, self.options.dt, dt_out)

    def kernel_params(self, dt_out, theta0, omega0) -> tuple:
        o = self.options
        dt, every = self.step(dt_out)
        return ST.kernel_params(self.assembly, self.K, self.Ks, self.b,
                                math.tan(o.friction_angle), o.cohesion,
                                dt, every, self.th_tol, theta0, omega0, o.settled)

    def check_batch(self) -> None:
        for name in ("return_forces", "return_energy"):
            if getattr(self.options, name):
                raise ParameterError(f"{name}=True is for single runs (rocking.simulate); "
                                     "simulate_many keeps theta and omega only")

    def extra_buffers(self, n_out: int) -> tuple:
        md = self.assembly
        n, vmax = md.n, md.lv.shape[1]
        n_e = n_out if self.options.return_energy else 0
        n_f = n_out if self.options.return_forces else 0
        return (np.empty((n_e, 3)), np.empty((n_f, n * vmax * (n + 1), 4)))

    def extra_bytes(self, n_out: int) -> int:
        md = self.assembly
        n, vmax = md.n, md.lv.shape[1]
        per = (3 if self.options.return_energy else 0)
        per += 4 * n * vmax * (n + 1) if self.options.return_forces else 0
        return 8 * (per + 6 * n) * n_out  # the kernel's own copy of the positions, velocities

    def extra_fields(self, k: int, states: np.ndarray, extra: tuple, dt_out: float) -> dict:
        md = self.assembly
        out_e, out_f = extra
        out_pos = states[:k, : 3 * md.n].reshape(k, md.n, 3)
        rel = out_pos - md.nominal[None, :, :]
        th_all = out_pos[:, :, 2].T.copy()
        x_all = rel[:, :, 0].T.copy()
        y_all = rel[:, :, 1].T.copy()
        info = {"max_abs_theta_all": [float(np.max(np.abs(th_all[i]))) if k else 0.0
                                      for i in range(md.n)]}
        t = np.arange(k) * dt_out
        forces = None
        if self.options.return_energy or self.options.return_forces:
            if self.options.return_energy:
                info["energy"] = {"t": t, "kinetic": out_e[:k, 0].copy(),
                                  "potential": out_e[:k, 1].copy(),
                                  "spring": out_e[:k, 2].copy()}
            if self.options.return_forces:
                used = (np.flatnonzero(np.any(out_f[:k, :, 0] > 0.0, axis=0)) if k
                        else np.empty(0, int))
                labels = _slot_labels(md)
                forces = {"t": t, "normal": out_f[:k, used, 0].copy(),
                          "shear": out_f[:k, used, 1].copy(), "x": out_f[:k, used, 2].copy(),
                          "y": out_f[:k, used, 3].copy(), "labels": [labels[s] for s in used]}
        return {"x": x_all[-1].copy(), "y": y_all[-1].copy(), "theta_all": th_all,
                "x_all": x_all, "y_all": y_all, "contact_forces": forces, "info": info}

    def info(self, dt_out: float | None = None) -> dict:
        md = self.assembly
        return {"dt": self.step(dt_out)[0] if dt_out else math.nan, "stiffness": self.K,
                "shear_stiffness": self.Ks, "damping": self.b,
                "damping_source": self.damping_source,
                "friction_angle": float(self.options.friction_angle), "n_blocks": md.n,
                "geometry": ",".join(bd.mode for bd in md.bodies),
                "xi_max": 0.5 * self.b * ST.omega_max(md, self.K, self.Ks),
                "settlement": md.total_mass * G / (2.0 * self.K)}

    def failure(self, status, t, dt_out=None) -> str:
        at = f" at t = {t:.4g} s" if t == t else ""
        dt = f" (dt = {self.step(dt_out)[0]:.3g} s)" if dt_out else ""
        return f"the DEM integration became unstable{at}{dt}; use a smaller dt"
