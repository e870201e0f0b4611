"""Synthetic test records: band-limited Gaussian noise under an envelope (for tests)."""

from __future__ import annotations

import numpy as np
from scipy.signal import butter, sosfiltfilt

from ..motions import Record


def random_record(seed: int, pga: float, duration: float = 10.0, dt: float = 0.01,
                  band: tuple[float, float] = (0.3, 8.0)) -> Record:
    """Band-limited Gaussian noise (``band`` in Hz) under a trapezoidal envelope (1.5 s
    rise, 3 s decay), scaled to the peak ``pga`` (m/s^2); reproducible from ``seed``."""
    rng = np.random.default_rng(seed)
    n = int(round(duration / dt)) + 1
    sos = butter(4, band, btype="bandpass", fs=1.0 / dt, output="sos")
    x = sosfiltfilt(sos, rng.standard_normal(n))
    t = np.arange(n) * dt
    x *= np.clip(t / 1.5, 0.0, 1.0) * np.clip((duration - t) / 3.0, 0.0, 1.0)
    return Record(x * pga / np.abs(x).max(), dt, name=f"noise-{seed}")
