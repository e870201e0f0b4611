"""Rocking models behind one interface.

``simulate(block, motion, model=...)`` and ``simulate_many(block, motions, model=...)``
run a registered model (a name in :data:`MODELS`) or any :class:`Model` subclass. What a
model must provide is documented in :mod:`rocking.models.base`; the shared driver is
:mod:`rocking.models.run`; the plain reference implementations that check the compiled
kernels are in :mod:`rocking.testing`.

Registered models: ``"housner"`` (the classical piecewise model, Eq 1 + Eq 4),
``"ccrr"`` (complex coupled rocking rotations, Eqs 5-10) and ``"dem"`` (the discrete
element model of Section 2.3: rigid polygons on contact springs, also for stacks).
"""

from __future__ import annotations

from .base import (
    GENERIC_OUTPUTS,
    PLANAR_OUTPUTS,
    Batch,
    Model,
    ModelOptions,
    Output,
    option,
    row_args,
    same_block,
    set_planar_result,
    store_row,
)
from .registry import MODELS, available, register
from .run import (
    PackedMotions,
    get_model,
    is_3d,
    pack_motions,
    require_planar,
    simulate,
    simulate_many,
)

__all__ = ["Model", "ModelOptions", "option", "row_args", "same_block", "store_row",
           "set_planar_result", "Output", "GENERIC_OUTPUTS", "PLANAR_OUTPUTS", "Batch",
           "MODELS", "available", "register", "get_model", "require_planar", "is_3d",
           "pack_motions", "PackedMotions", "simulate", "simulate_many"]
