"""Validation and packing shared by every model's Python API (the edge of the kernels)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._validate import as_float, in_range, positive
from ..blocks import Block
from ..errors import ParameterError  # noqa: F401  (re-exported for models)
from ..motions import Motion
from ..motions._kernel import NPRM

HALF_PI = 0.5 * math.pi


def no_unknown(model: str, unknown: dict) -> None:
    if unknown:
        raise ParameterError(f"unknown option(s) for model {model!r}: {', '.join(unknown)}")


def check_block(block) -> Block:
    if not isinstance(block, Block):
        raise ParameterError(f"block must be a rocking.Block, got {type(block).__name__}")
    return block


def check_rtol(rtol) -> float:
    return in_range("rtol", rtol, 1e-13, 1e-2, shown="[1e-13, 1e-2]", lo_open=False,
                    hi_open=False)


def check_rest_tol(rest_tol) -> float:
    return in_range("rest_tol", rest_tol, 0.0, 1e-2, shown="(0, 1e-2]", hi_open=False)


@dataclass
class Single:
    """A validated single-run problem: motion spec, window and initial state."""

    kind: int
    prm: np.ndarray
    samples: np.ndarray
    duration: float
    theta0: float
    omega0: float
    h_scan: float
    dt_out: float

    @property
    def n_out(self) -> int:
        return int(math.floor(self.duration / self.dt_out + 1e-9)) + 1


def prepare_single(motion, duration, theta0, omega0, dt_out) -> Single:
    """Validate the common arguments of ``simulate`` and build the motion spec."""
    if motion is not None and not isinstance(motion, Motion):
        raise ParameterError(f"motion must be a rocking.motions.Motion or None, "
                             f"got {type(motion).__name__}")
    if duration is None:
        if motion is None:
            raise ParameterError("duration is required for free rocking (motion=None), in s > 0")
        duration = motion.duration
    duration = positive("duration", duration, "s")
    theta0 = in_range("theta0", theta0, -HALF_PI, HALF_PI, shown="(-pi/2, pi/2) rad")
    omega0 = as_float("omega0", omega0)
    dt_out = positive("dt_out", dt_out, "s")
    if motion is None:
        kind, prm, samples, h_scan = 0, np.zeros(NPRM), np.empty(0), duration
    else:
        (kind, prm, samples), h_scan = motion.spec(), motion.scan_step
    return Single(kind, prm, samples, duration, theta0, omega0, h_scan, dt_out)


def pack_motions(motions, duration=None):
    """Pack motions into padded arrays for the batch kernels.

    Returns ``kinds, prms, samples, nsamp, t_ends, h_scans``.
    """
    if isinstance(motions, Motion):
        motions = [motions]
    motions = list(motions)
    if not motions:
        raise ParameterError("motions must be a non-empty sequence of Motion objects")
    for i, m in enumerate(motions):
        if not isinstance(m, Motion):
            raise ParameterError(f"motions[{i}] must be a rocking.motions.Motion, "
                                 f"got {type(m).__name__}")
    specs = [m.spec() for m in motions]
    n = len(motions)
    nsamp = np.array([s[2].size for s in specs], dtype=np.int64)
    samples = np.zeros((n, max(1, int(nsamp.max()))))
    for i, s in enumerate(specs):
        samples[i, : s[2].size] = s[2]
    kinds = np.array([s[0] for s in specs], dtype=np.int64)
    prms = np.stack([s[1] for s in specs])
    if duration is None:
        t_ends = np.array([m.duration for m in motions], dtype=np.float64)
    else:
        t_ends = np.full(n, positive("duration", duration, "s"))
    h_scans = np.array([m.scan_step for m in motions], dtype=np.float64)
    return kinds, prms, samples, nsamp, t_ends, h_scans


def finish_history(k, out_th, out_om, dt_out, overturned, t_over):
    """Trim the output buffers to the written part; append the overturning point."""
    t = np.arange(k) * dt_out
    th, om = out_th[:k], out_om[:k]
    if overturned and (k == 0 or t[-1] < t_over):
        t = np.append(t, t_over)
        th = np.append(th, math.copysign(HALF_PI, th[-1] if k else 1.0))
        om = np.append(om, om[-1] if k else 0.0)
    return t, th, om
