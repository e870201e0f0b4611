"""Uncertain parameters: distributions given as plain dicts (also the campaign spec format).

A distribution is a dict with ``dist`` and its parameters, e.g.::

    {"dist": "normal", "mean": 0.163, "std": 0.004}
    {"dist": "normal", "cov": 0.02}               # mean = the nominal value
    {"dist": "lognormal", "median": 4.05, "beta": 0.05}
    {"dist": "uniform", "low": 0.0, "high": 0.002}
    {"dist": "fixed", "value": 0.97}

A missing ``mean`` or ``median`` is the parameter's nominal value. Every number must be a
real number (never a bool or a string: ``cov = true`` is refused, not read as 1). Draws are
made with a :class:`numpy.random.Generator` (scipy.stats frozen distributions,
``random_state=rng``).

Truncation: a parameter has a range (its physical range, and for the initial tilt
``|theta0| < alpha``). :func:`draw` truncates the distribution to it by rejection: a draw
outside is redrawn from the same generator, so the draws follow the truncated
distribution exactly, and a draw that falls inside at once consumes the generator exactly
as an untruncated draw would. :func:`draw_counted` also returns the number of redraws. A
distribution with more than :data:`MAX_OUTSIDE` of its mass outside the range is refused
(:func:`check_mass`): truncating it would change it, not trim it.
"""

from __future__ import annotations

import math
import numbers
import weakref

import numpy as np
from scipy import stats

from .._validate import as_float
from ..errors import ParameterError

DISTS = ("normal", "lognormal", "uniform", "fixed")
KEYS = {"normal": {"mean", "std", "cov"}, "lognormal": {"median", "beta"},
        "uniform": {"low", "high"}, "fixed": {"value"}}
MAX_OUTSIDE = 0.01
"""Largest fraction of a distribution's mass allowed outside its parameter's range (the
rest is redrawn). For a normal given by its ``cov`` around a positive nominal value and a
parameter that must be > 0 (``alpha``, ``p``, ``amplitude``) this bounds ``cov`` at
``-1 / Phi^-1(0.01)`` = 0.43 (:data:`MAX_COV`)."""
MAX_COV = -1.0 / float(stats.norm.ppf(MAX_OUTSIDE))
"""0.4299...: the largest ``cov`` of a normal whose mass below zero is at most
:data:`MAX_OUTSIDE`."""


def _sub(where: str, key: str) -> str:
    """The name of ``key`` inside ``where``: ``uncertain['p']['cov']`` (Python) or
    ``uncertain.p.cov`` (a spec)."""
    return f"{where}[{key!r}]" if where.endswith("]") else f"{where}.{key}"


def _number(name: str, value) -> float:
    """A finite real number: bools and strings are refused."""
    if isinstance(value, bool | np.bool_) or not isinstance(value, numbers.Real):
        raise ParameterError(f"{name} must be a finite number, got {type(value).__name__} "
                             f"{value!r}")
    return as_float(name, value)


def _positive(name: str, value) -> float:
    x = _number(name, value)
    if x <= 0.0:
        raise ParameterError(f"{name} must be > 0, got {value!r}")
    return x


def frozen(name: str, spec, nominal: float, where: str | None = None):
    """The scipy.stats frozen distribution of parameter ``name`` from its dict ``spec``.

    ``where`` names the dict in messages (default ``uncertain['name']``; a campaign spec
    passes ``uncertain.name``)."""
    where = where or f"uncertain[{name!r}]"
    if not isinstance(spec, dict) or "dist" not in spec:
        raise ParameterError(f"{where} must be a table with dist (one of {', '.join(DISTS)}) "
                             f"and its parameters, got {spec!r}")
    kind = spec["dist"]
    if not isinstance(kind, str) or kind not in KEYS:
        raise ParameterError(f"{_sub(where, 'dist')} must be one of {', '.join(DISTS)}, "
                             f"got {kind!r}")
    extra = set(spec) - KEYS[kind] - {"dist"}
    if extra:
        raise ParameterError(f"{where}: unknown key(s) {', '.join(sorted(map(str, extra)))} "
                             f"for dist {kind!r} (allowed: {', '.join(sorted(KEYS[kind]))})")
    if kind == "normal":
        mean = _number(_sub(where, "mean"), spec.get("mean", nominal))
        if ("std" in spec) == ("cov" in spec):
            raise ParameterError(f"{where}: give exactly one of 'std' or 'cov' for a normal")
        if "std" in spec:
            std = _positive(_sub(where, "std"), spec["std"])
        else:
            cov = _positive(_sub(where, "cov"), spec["cov"])
            if mean == 0.0:
                raise ParameterError(f"{_sub(where, 'cov')} needs a mean != 0 (the std is "
                                     f"cov x |mean|); give std instead")
            std = cov * abs(mean)
        return stats.norm(mean, std)
    if kind == "lognormal":
        med = _positive(_sub(where, "median"), spec.get("median", nominal))
        if "beta" not in spec:
            raise ParameterError(f"{_sub(where, 'beta')} missing (the log standard "
                                 "deviation, > 0)")
        return stats.lognorm(_positive(_sub(where, "beta"), spec["beta"]), scale=med)
    if kind == "uniform":
        for k in ("low", "high"):
            if k not in spec:
                raise ParameterError(f"{_sub(where, k)} missing (a uniform needs low < high)")
        lo = _number(_sub(where, "low"), spec["low"])
        hi = _number(_sub(where, "high"), spec["high"])
        if not hi > lo:
            raise ParameterError(f"{where}: 'high' must exceed 'low', got {lo:g}, {hi:g}")
        if not math.isfinite(hi - lo):
            raise ParameterError(f"{where}: high - low must be finite, got {lo:g}, {hi:g}")
        return stats.uniform(lo, hi - lo)
    return _Fixed(_number(_sub(where, "value"), spec.get("value", nominal)))


class _Fixed:
    """A parameter that is not uncertain (the scipy.stats ``rvs`` interface)."""

    def __init__(self, value: float):
        self.value = value

    def rvs(self, random_state=None) -> float:
        return self.value


def mass_outside(dist, lo: float, hi: float) -> float:
    """The probability that a draw of ``dist`` falls outside the open interval
    ``(lo, hi)``."""
    if isinstance(dist, _Fixed):
        return 0.0 if lo < dist.value < hi else 1.0
    return float(min(1.0, dist.cdf(lo) + dist.sf(hi)))


def mass_beyond(dist, bound, bound_range=(0.0, math.inf)) -> float:
    """The probability that ``|x| >= bound`` for ``x`` drawn from ``dist`` and ``bound``
    either a number or itself a distribution (then truncated to ``bound_range``, as
    :func:`draw` does, and the probability is averaged over it)."""
    if isinstance(bound, numbers.Real):
        return mass_outside(dist, -float(bound), float(bound))
    if isinstance(bound, _Fixed):
        return mass_outside(dist, -bound.value, bound.value)
    lo, hi = bound_range
    return float(bound.expect(lambda a: mass_outside(dist, -a, a), lb=lo, ub=hi,
                              conditional=True))


def _pct(x: float) -> str:
    return f"{100 * x:.3g}%"


def check_mass(where: str, dist, lo: float, hi: float, what: str = "") -> None:
    """Refuse ``dist`` if more than :data:`MAX_OUTSIDE` of its mass lies outside
    ``(lo, hi)`` (``what`` describes the range in the message)."""
    m = mass_outside(dist, lo, hi)
    if m > MAX_OUTSIDE:
        rng = what or f"({lo:g}, {hi:g})"
        hint = ""
        if getattr(getattr(dist, "dist", None), "name", "") == "norm" and abs(lo) < 1e-12 \
                and dist.mean() > 0 and dist.cdf(lo) > MAX_OUTSIDE:
            hint = f" (a normal needs std/mean <= {MAX_COV:.2f})"
        raise ParameterError(f"{where}: {_pct(m)} of the distribution lies outside {rng}; "
                             f"at most {_pct(MAX_OUTSIDE)} may{hint}")


_SAMPLERS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
"""Frozen distribution -> its one-draw function (:func:`_sampler`), made once."""


def _sampler(dist):
    """``f(rng)``: one draw of ``dist``, the very value of ``dist.rvs(random_state=rng)``.

    A scipy.stats frozen continuous distribution checks and broadcasts its parameters at
    every ``rvs`` call (most of a campaign row's time with uncertain parameters); here
    that is done once, and each draw is the distribution's own ``_rvs`` with the same
    arguments, then ``vals * scale + loc`` as in ``rv_generic.rvs``: the same arithmetic,
    the same generator consumption. Anything else (``_Fixed``, invalid parameters, which
    ``rvs`` refuses) draws through ``rvs``."""
    try:
        return _SAMPLERS[dist]
    except (KeyError, TypeError):
        pass
    f = None
    gen = getattr(dist, "dist", None)
    if isinstance(gen, stats.rv_continuous) and isinstance(getattr(dist, "kwds", None), dict):
        args, loc, scale, size = gen._parse_args_rvs(*dist.args, **dist.kwds)
        if (np.all(np.logical_and(gen._argcheck(*args), scale >= 0))
                and not np.all(scale == 0)):
            def f(rng, _rvs=gen._rvs, args=args, loc=loc, scale=scale, size=size):
                return float(_rvs(*args, size=size, random_state=rng) * scale + loc)
    if f is None:
        def f(rng, dist=dist):
            return float(dist.rvs(random_state=rng))
    try:
        _SAMPLERS[dist] = f
    except TypeError:  # not weakly referenceable: not kept
        pass
    return f


def draw_counted(dist, rng, lo: float = -math.inf, hi: float = math.inf, name: str = "",
                 tries: int = 1000) -> tuple[float, int]:
    """One draw of ``dist`` inside ``(lo, hi)`` by rejection (the distribution truncated to
    the interval), and the number of draws rejected on the way."""
    one = _sampler(dist)
    for k in range(tries):
        x = one(rng)
        if lo < x < hi:
            return x, k
    raise ParameterError(f"uncertain[{name!r}] almost never falls inside its range "
                         f"({lo:g}, {hi:g}): check its distribution")


def draw(dist, rng, lo: float = -math.inf, hi: float = math.inf, name: str = "",
         tries: int = 1000) -> float:
    """One draw of ``dist`` inside ``(lo, hi)``, by rejection (the distribution truncated to
    the physical range of the parameter)."""
    return draw_counted(dist, rng, lo, hi, name, tries)[0]
