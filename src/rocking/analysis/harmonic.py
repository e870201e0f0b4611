"""The rocking-motion space of Table IV (Peña et al. 2007, Section 5.1) as a function.

For a block under constant (or Hanning-windowed) sines of table-displacement amplitude ``X``
and frequency ``f``, which cells rock, which overturn, and how far. One compiled batch over
the whole grid.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from .._validate import positive
from ..errors import ParameterError
from ..models import simulate_many
from ..motions import catalog
from ..plot import figure, style_axes
from ..units import G

KINDS = ("sine", "hanning")
"""The table motions of :func:`motion_space`: names of :data:`rocking.motions.catalog.KINDS`
(the constant sine and the Hanning-windowed one)."""


def _grid(name: str, values) -> np.ndarray:
    try:
        arr = np.atleast_1d(np.asarray(values, dtype=float))
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a non-empty sequence of numbers > 0") from None
    if arr.ndim != 1 or arr.size == 0:
        raise ParameterError(f"{name} must be a non-empty sequence of numbers")
    for v in arr:
        positive(name, v)
    return arr


def motion_space(block, freqs, amplitudes, kind: str = "sine", duration: float = 20.0,
                 model="housner", **options) -> pd.DataFrame:
    """The rocking-motion space (Table IV): one row per (frequency, amplitude) cell.

    Parameters
    ----------
    block : Block
    freqs : sequence of float
        Frequencies of the table motion (Hz).
    amplitudes : sequence of float
        Table displacement amplitudes (m); the acceleration amplitude is
        ``(2 pi f)^2 X``.
    kind : ``"sine"`` (constant) or ``"hanning"`` (Hanning-windowed sine)
        The catalog's motion kind (:mod:`rocking.motions.catalog`), built from its
        ``frequency``, ``displacement`` and ``duration``.
    duration : float
        Length of each motion (s).
    model, **options
        As in :func:`rocking.simulate_many`.

    Returns
    -------
    DataFrame with ``freq`` (Hz), ``amplitude`` (m), ``acc_amplitude`` (m/s^2),
    ``acc_ratio`` (acceleration amplitude / (g tan alpha), the uplift criterion of a block at
    rest is ``acc_ratio > 1`` for the constant sine), ``max_abs_theta`` (rad),
    ``max_abs_theta_over_alpha``, ``n_impacts``, ``rocked`` and ``overturned``.

    Examples
    --------
    Constant sines on specimen 2: a block at rest lifts off when the acceleration amplitude
    ``(2 pi f)^2 X`` exceeds ``g tan alpha`` (``acc_ratio > 1``):

    >>> import rocking
    >>> from rocking.analysis import motion_space
    >>> df = motion_space(rocking.specimen(2), [1.0, 2.0], [0.005, 0.05], duration=3.0)
    >>> df["acc_ratio"].round(2).tolist()
    [0.12, 1.19, 0.47, 4.75]
    >>> df["rocked"].tolist(), bool((df["rocked"] == (df["acc_ratio"] > 1)).all())
    ([False, True, False, True], True)
    """
    if kind not in KINDS:
        raise ParameterError(f"kind must be one of {', '.join(KINDS)}; got {kind!r}")
    f = _grid("freqs", freqs)
    x = _grid("amplitudes", amplitudes)
    duration = positive("duration", duration, "s")
    ff, xx = np.meshgrid(f, x, indexing="ij")
    motions = [catalog.build(kind, frequency=fi, displacement=xi, duration=duration)
               for fi, xi in zip(ff.ravel(), xx.ravel(), strict=True)]
    res = simulate_many(block, motions, model=model, **options)
    acc = (2.0 * math.pi * ff.ravel()) ** 2 * xx.ravel()
    alpha = block.alpha
    return pd.DataFrame({
        "freq": ff.ravel(), "amplitude": xx.ravel(), "acc_amplitude": acc,
        "acc_ratio": acc / (G * math.tan(alpha)),
        "max_abs_theta": res.max_abs_theta,
        "max_abs_theta_over_alpha": res.max_abs_theta / alpha,
        "n_impacts": res.n_impacts, "rocked": res.rocked, "overturned": res.overturned,
    })


def plot_motion_space(df: pd.DataFrame, ax=None):
    """Map of a :func:`motion_space` table: max ``|theta|`` / alpha per cell, overturned cells
    marked, no-rocking cells blank. Returns the Axes.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import rocking
    >>> from rocking.analysis import motion_space, plot_motion_space
    >>> df = motion_space(rocking.specimen(2), [1.0, 2.0], [0.005, 0.05], duration=3.0)
    >>> ax = plot_motion_space(df)
    >>> type(ax).__name__, ax.get_xlabel()
    ('Axes', 'frequency (Hz)')
    """

    if ax is None:
        _, ax = figure()
    freqs = np.unique(df["freq"])
    amps = np.unique(df["amplitude"])
    grid = df.pivot(index="amplitude", columns="freq", values="max_abs_theta_over_alpha")
    over = df.pivot(index="amplitude", columns="freq", values="overturned").to_numpy(bool)
    z = np.where(df.pivot(index="amplitude", columns="freq", values="rocked").to_numpy(bool),
                 grid.to_numpy(), np.nan)
    z = np.where(over, np.nan, z)
    mesh = ax.pcolormesh(np.arange(freqs.size + 1) - 0.5, np.arange(amps.size + 1) - 0.5, z,
                         cmap="viridis", vmin=0.0, vmax=1.0)
    yy, xx = np.nonzero(over)
    ax.plot(xx, yy, "x", color="#C00000", label="overturned")
    ax.set_xticks(range(freqs.size), [f"{v:g}" for v in freqs])
    ax.set_yticks(range(amps.size), [f"{1e3 * v:g}" for v in amps])
    ax.figure.colorbar(mesh, ax=ax, label=r"max $|\theta|/\alpha$")
    style_axes(ax, "frequency (Hz)", "table amplitude (mm)")
    return ax
