"""Result objects of :func:`rocking.simulate` and :func:`rocking.simulate_many`.

Angles are in rad, angular velocities in rad/s, times in s. ``theta`` follows the sign
convention of the paper's Eq (1) (see :mod:`rocking.models.housner`).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np


def _none_if_nan(x) -> float | None:
    x = float(x)
    return None if math.isnan(x) else x


@dataclass
class Response:
    """Time history and summary of one simulation."""

    t: np.ndarray
    theta: np.ndarray
    omega: np.ndarray
    impact_times: np.ndarray
    max_abs_theta: float
    overturned: bool
    overturn_time: float | None
    uplift_time: float | None
    model: str = "housner"
    block: object = None
    motion: object = None
    info: dict = field(default_factory=dict)
    # ---- discrete element model only (None for the classical and CCRR models)
    x: np.ndarray | None = None
    """Horizontal displacement (m) of the centroid relative to the base (DEM)."""
    y: np.ndarray | None = None
    """Vertical displacement (m) of the centroid from its nominal position on undeformed
    contacts (DEM; at rest it is minus the static settlement)."""
    theta_all: np.ndarray | None = None
    """Rotation (rad) of every block of a stack, shape ``(n_blocks, n_t)`` (DEM)."""
    x_all: np.ndarray | None = None
    """``x`` of every block, shape ``(n_blocks, n_t)`` (DEM)."""
    y_all: np.ndarray | None = None
    """``y`` of every block, shape ``(n_blocks, n_t)`` (DEM)."""
    contact_forces: dict | None = None
    """Contact forces on request (DEM, ``return_forces=True``); see
    :func:`rocking.models.dem.simulate`."""

    @property
    def n_impacts(self) -> int:
        """Number of impacts (passages through theta = 0)."""
        return int(self.impact_times.size)

    @property
    def rocked(self) -> bool:
        """True if the block ever left its rest position."""
        return self.uplift_time is not None or self.max_abs_theta > 0.0

    def half_cycle_peaks(self) -> tuple[np.ndarray, np.ndarray]:
        """Times (s) and values (rad, signed) of the largest |theta| in each half-cycle.

        Half-cycles are delimited by the impacts; each peak is refined by a parabola
        through the three output samples around it (accuracy ~ (omega dt_out)^2).
        """
        edges = np.concatenate(([self.t[0] if self.t.size else 0.0], self.impact_times,
                                [self.t[-1] if self.t.size else 0.0]))
        a = np.abs(self.theta)
        tp, vp = [], []
        for lo, hi in zip(edges[:-1], edges[1:], strict=True):
            idx = np.flatnonzero((self.t >= lo) & (self.t <= hi))
            if idx.size == 0:
                continue
            i = idx[np.argmax(a[idx])]
            if a[i] == 0.0:
                continue
            t_i, v_i = self.t[i], self.theta[i]
            if 0 < i < a.size - 1 and idx[0] < i < idx[-1]:
                y0, y1, y2 = a[i - 1], a[i], a[i + 1]
                den = y0 - 2 * y1 + y2
                if den < 0:
                    d = 0.5 * (y0 - y2) / den
                    dt = self.t[i + 1] - self.t[i]
                    t_i = t_i + d * dt
                    v_i = np.sign(v_i) * (y1 - 0.25 * (y0 - y2) * d)
            tp.append(t_i)
            vp.append(v_i)
        return np.asarray(tp), np.asarray(vp)

    def summary(self) -> dict:
        """JSON-ready summary (SI units; ``max_abs_theta_deg`` for convenience)."""
        d = {
            "model": self.model,
            "max_abs_theta": float(self.max_abs_theta),
            "max_abs_theta_deg": math.degrees(self.max_abs_theta),
            "overturned": bool(self.overturned),
            "overturn_time": self.overturn_time,
            "uplift_time": self.uplift_time,
            "n_impacts": self.n_impacts,
            "duration": float(self.t[-1]) if self.t.size else 0.0,
        }
        if self.block is not None and hasattr(self.block, "params"):
            d["block"] = {k: v for k, v in self.block.params().items()}
            d["block"]["name"] = getattr(self.block, "name", "")
        if self.motion is not None:
            d["motion"] = repr(self.motion)
        d.update({k: v for k, v in self.info.items() if isinstance(v, int | float | str | bool)})
        return d

    def to_dataframe(self):
        """``pandas.DataFrame`` with columns ``t``, ``theta``, ``omega``."""
        import pandas as pd

        return pd.DataFrame({"t": self.t, "theta": self.theta, "omega": self.omega})

    def to_csv(self, path) -> Path:
        """Write ``t, theta, omega`` (s, rad, rad/s) to ``path`` as CSV."""
        path = Path(path)
        self.to_dataframe().to_csv(path, index=False, float_format="%.10g")
        return path

    def to_json(self, path) -> Path:
        """Write :meth:`summary` to ``path``."""
        path = Path(path)
        path.write_text(json.dumps(self.summary(), indent=2))
        return path

    def plot(self, ax=None, **kw):
        """Plot theta(t) in degrees; returns the matplotlib Axes."""
        from .plot import plot_response

        return plot_response(self, ax=ax, **kw)


@dataclass
class BatchResponse:
    """Summaries of a batch of simulations, one entry per motion (numpy arrays).

    ``overturn_time`` and ``uplift_time`` are NaN where the event did not happen.
    ``theta``/``omega`` (shape ``(n_motions, n_times)``) are present only when histories
    were requested; after an overturn they are NaN.
    """

    max_abs_theta: np.ndarray
    overturned: np.ndarray
    overturn_time: np.ndarray
    uplift_time: np.ndarray
    n_impacts: np.ndarray
    t: np.ndarray | None = None
    theta: np.ndarray | None = None
    omega: np.ndarray | None = None
    model: str = "housner"

    def __len__(self) -> int:
        return int(self.max_abs_theta.size)

    def to_dataframe(self):
        """One row per motion with the summary quantities."""
        import pandas as pd

        return pd.DataFrame({
            "max_abs_theta": self.max_abs_theta,
            "overturned": self.overturned,
            "overturn_time": self.overturn_time,
            "uplift_time": self.uplift_time,
            "n_impacts": self.n_impacts,
        })
