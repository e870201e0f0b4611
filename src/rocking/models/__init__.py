"""Rocking models behind one interface.

``simulate(block, motion, model=...)`` and ``simulate_many(block, motions, model=...)``
dispatch to a registered model. Each model module keeps a compiled (numba) kernel; a plain
reference implementation lives beside it for testing.

Registered models: ``"housner"`` (the classical piecewise model, Eq 1 + Eq 4),
``"ccrr"`` (complex coupled rocking rotations, Eqs 5-10) and ``"dem"`` (the discrete
element model of Section 2.3: rigid polygons on contact springs, also for stacks).
"""

from __future__ import annotations

from ..errors import ParameterError
from . import ccrr, dem, housner

MODELS = {"housner": housner, "ccrr": ccrr, "dem": dem}


def _model(name: str):
    try:
        return MODELS[str(name).lower()]
    except KeyError:
        raise ParameterError(f"model must be one of {', '.join(MODELS)}; got {name!r}") from None


def simulate(block, motion=None, model: str = "housner", duration: float | None = None,
             theta0: float = 0.0, omega0: float = 0.0, linear: bool = False, **options):
    """Simulate one block under one base motion and return a :class:`~rocking.Response`.

    Parameters
    ----------
    block : Block
        The block (its ``alpha``, ``p`` and ``mu`` drive the classical model).
    motion : Motion or None
        Base motion; ``None`` means free rocking from ``theta0``, ``omega0``.
    model : str
        ``"housner"`` (classical model, Eq 1) or ``"ccrr"`` (Eq 10).
    duration : float, optional
        Simulated time (s). Defaults to ``motion.duration``; required for free rocking.
    theta0, omega0 : float
        Initial angle (rad) and angular velocity (rad/s).
    linear : bool
        Use the small-angle form of Eq 1 (for comparison with closed forms).
    **options
        Model options, e.g. ``rtol``, ``dt_out``, ``rest_tol`` for ``"housner"``.
    """
    return _model(model).simulate(block, motion, duration=duration, theta0=theta0,
                                  omega0=omega0, linear=linear, **options)


def simulate_many(block, motions, model: str = "housner", duration: float | None = None,
                  **options):
    """Simulate one block under many motions in one compiled, parallel call.

    Returns a :class:`~rocking.results.BatchResponse` with numpy arrays ``max_abs_theta``
    and ``overturned`` (one entry per motion); time histories only with
    ``return_histories=True``.
    """
    return _model(model).simulate_many(block, motions, duration=duration, **options)
