"""The registry of models: one line per model (see :mod:`rocking.models.base`)."""

from __future__ import annotations

from .anchored import Anchored
from .base import Model
from .ccrr import CCRR
from .dem import DEM
from .housner import Housner
from .isolated import Isolated
from .rigid3d import Rigid3d

MODELS: dict[str, type[Model]] = {cls.name: cls for cls in (Housner, CCRR, DEM, Anchored, Isolated,
                                                     Rigid3d)}
"""Registered models by name, in the order the CLI and the report list them."""


def available() -> tuple[str, ...]:
    """Names of the registered models.

    Examples
    --------
    >>> from rocking.models import available
    >>> available()
    ('housner', 'ccrr', 'dem', 'anchored', 'isolated', 'rigid3d')
    """
    return tuple(MODELS)


def register(cls: type[Model]) -> type[Model]:
    """Register a model class under its ``name`` (one line: ``register(MyModel)``; also a
    class decorator), so that ``model="name"`` works in :func:`rocking.simulate`,
    :func:`rocking.simulate_many`, campaigns and the command line. A registered name is
    refused unless it is the same class (re-registering it is harmless).

    Examples
    --------
    >>> from rocking.models import MODELS, register
    >>> register(MODELS["housner"]) is MODELS["housner"]
    True
    """
    from ..errors import ParameterError
    if not (isinstance(cls, type) and issubclass(cls, Model)):
        raise ParameterError(f"register takes a rocking.models.Model subclass, got {cls!r}")
    if not cls.name or cls.kernel is None or cls.batch_kernel is None:
        raise ParameterError(f"model class {cls.__name__} must define name, kernel and "
                             "batch_kernel (see rocking.models.base)")
    known = MODELS.get(cls.name)
    if known is not None and known is not cls:
        raise ParameterError(f"a model named {cls.name!r} is registered already "
                             f"({known.__module__}.{known.__qualname__})")
    MODELS[cls.name] = cls
    return cls
