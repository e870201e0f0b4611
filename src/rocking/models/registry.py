"""The registry of models: one line per model (see :mod:`rocking.models.base`)."""

from __future__ import annotations

from .anchored import Anchored
from .base import Model
from .ccrr import CCRR
from .dem import DEM
from .housner import Housner
from .isolated import Isolated

MODELS: dict[str, type[Model]] = {cls.name: cls for cls in (Housner, CCRR, DEM, Anchored, Isolated)}
"""Registered models by name, in the order the CLI and the report list them."""


def available() -> tuple[str, ...]:
    """Names of the registered models.

    Examples
    --------
    >>> from rocking.models import available
    >>> available()
    ('housner', 'ccrr', 'dem', 'anchored', 'isolated')
    """
    return tuple(MODELS)
