"""Uncertain parameters: distributions given as plain dicts (also the campaign spec format).

A distribution is a dict with ``dist`` and its parameters, e.g.::

    {"dist": "normal", "mean": 0.163, "std": 0.004}
    {"dist": "normal", "cov": 0.02}               # mean = the nominal value
    {"dist": "lognormal", "median": 4.05, "beta": 0.05}
    {"dist": "uniform", "low": 0.0, "high": 0.002}
    {"dist": "fixed", "value": 0.97}

A missing ``mean`` or ``median`` is the parameter's nominal value. Draws are made with a
:class:`numpy.random.Generator` (scipy.stats frozen distributions, ``random_state=rng``).
"""

from __future__ import annotations

import math

from scipy import stats

from .._validate import as_float, positive
from ..errors import ParameterError

DISTS = ("normal", "lognormal", "uniform", "fixed")


def frozen(name: str, spec, nominal: float):
    """The scipy.stats frozen distribution of parameter ``name`` from its dict ``spec``."""
    if not isinstance(spec, dict) or "dist" not in spec:
        raise ParameterError(f"uncertain[{name!r}] must be a dict with 'dist' (one of "
                             f"{', '.join(DISTS)}) and its parameters, got {spec!r}")
    kind = spec["dist"]
    keys = {"normal": {"mean", "std", "cov"}, "lognormal": {"median", "beta"},
            "uniform": {"low", "high"}, "fixed": {"value"}}
    if kind not in keys:
        raise ParameterError(f"uncertain[{name!r}]['dist'] must be one of {', '.join(DISTS)}, "
                             f"got {kind!r}")
    extra = set(spec) - keys[kind] - {"dist"}
    if extra:
        raise ParameterError(f"uncertain[{name!r}]: unknown key(s) {', '.join(sorted(extra))} "
                             f"for dist {kind!r} (allowed: {', '.join(sorted(keys[kind]))})")
    where = f"uncertain[{name!r}]"
    if kind == "normal":
        mean = as_float(f"{where}['mean']", spec.get("mean", nominal))
        if ("std" in spec) == ("cov" in spec):
            raise ParameterError(f"{where}: give exactly one of 'std' or 'cov' for a normal")
        std = (positive(f"{where}['std']", spec["std"]) if "std" in spec
               else positive(f"{where}['cov']", spec["cov"]) * abs(mean))
        return stats.norm(mean, std)
    if kind == "lognormal":
        med = positive(f"{where}['median']", spec.get("median", nominal))
        return stats.lognorm(positive(f"{where}['beta']", spec.get("beta")), scale=med)
    if kind == "uniform":
        lo = as_float(f"{where}['low']", spec.get("low"))
        hi = as_float(f"{where}['high']", spec.get("high"))
        if not hi > lo:
            raise ParameterError(f"{where}: 'high' must exceed 'low', got {lo:g}, {hi:g}")
        return stats.uniform(lo, hi - lo)
    return _Fixed(as_float(f"{where}['value']", spec.get("value", nominal)))


class _Fixed:
    """A parameter that is not uncertain (the scipy.stats ``rvs`` interface)."""

    def __init__(self, value: float):
        self.value = value

    def rvs(self, random_state=None) -> float:
        return self.value


def draw(dist, rng, lo: float = -math.inf, hi: float = math.inf, name: str = "",
         tries: int = 1000) -> float:
    """One draw of ``dist`` inside ``(lo, hi)``, by rejection (the distribution truncated to
    the physical range of the parameter)."""
    for _ in range(tries):
        x = float(dist.rvs(random_state=rng))
        if lo < x < hi:
            return x
    raise ParameterError(f"uncertain[{name!r}] almost never falls inside its range "
                         f"({lo:g}, {hi:g}): check its distribution")
