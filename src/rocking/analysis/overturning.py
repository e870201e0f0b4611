r"""Overturning spectra and outcome maps of rocking blocks under idealised pulses.

**Dimensionless axes** (Dimitrakopoulos and DeJong 2012). With the dimensionless time
``tau = p t``, Eq (1) reads

.. math::

    \frac{d^2\theta}{d\tau^2} = -\operatorname{sgn}(\theta)\sin(\alpha - |\theta|)
        + \cos(\alpha - |\theta|)\,\tan\alpha\;\frac{a_p}{g\tan\alpha}\,
          f\!\left(\frac{\omega_p}{p}\,\tau\right)

for a pulse ``a(t) = a_p f(omega_p t)``, and an impact multiplies ``d theta / d tau`` by
``mu``. So ``theta`` as a function of ``p t`` depends only on ``omega_p / p``,
``a_p / (g tan alpha)``, ``alpha`` and ``mu``: two blocks of different size (different
``p``) with the same ``alpha`` and ``mu`` have the same overturning spectrum in these
axes. Every simulation window here is dimensionless too: the pulse plus ``tail / p`` of
free motion (default ``tail = 60``, i.e. about ten free rocking periods of a small-amplitude
block; a block that has not overturned by then cannot any more, its energy only decreasing
at impacts). ``tests/test_overturning.py`` checks the similarity to 1e-6.

**Pulses** (``pulse=``, the names of :mod:`rocking.motions.catalog`), each of peak ground
acceleration ``a_p`` (``amplitude``):

* ``"one_sine"`` (default): :class:`~rocking.motions.OneSine`, one full sine cycle of
  period ``Tp = 2 pi / omega_p``;
* ``"one_cosine"``: :class:`~rocking.motions.OneCosine`, one full cosine cycle, ``Tp = 2 pi
  / omega_p``;
* ``"ricker"``: :class:`~rocking.motions.Ricker` of peak frequency ``fp = omega_p / (2
  pi)`` (the frequency where its Fourier amplitude peaks), centred at ``1.5 / fp``;
* ``"mavroeidis_papageorgiou"``: :class:`~rocking.motions.MavroeidisPapageorgiou` with
  ``fp = omega_p / (2 pi)``; it needs ``gamma`` (> 1) and ``nu`` (rad) in
  ``pulse_params``.

The pulse is built by :func:`rocking.motions.catalog.build`; ``pulse_params`` holds the
catalog parameters that the point of the plane does not set (``gamma``, ``nu``): the
amplitude, the frequency or period and the window come from ``accel_ratio``,
``omega_ratio`` and ``tail``. The model's options are keywords (``rtol=1e-10``), as in
:func:`rocking.simulate_many`. The old names ``"sine"``, ``"cosine"`` and ``"mp"``, the
``options={...}`` dict and ``gamma=``/``nu=`` as keywords still work for one release, with
a :class:`DeprecationWarning`.

**Overturning modes** (Zhang and Makris 2001, J. Eng. Mech. 127(5)): *mode 1* overturns
after an impact (``n_impacts >= 1`` at overturning: under a one-sine pulse the block
rocks to one side, impacts once and overturns to the other side), *mode 2* overturns
without any impact (``n_impacts == 0``). For the one-sine pulse mode 1 is the tongue at
the lower amplitudes and mode 2 the region above it. (Up to rocking 0.1.0 the ``mode``
column numbered them the other way round.)

**Method of** :func:`overturning_spectrum`. The overturning boundary is not monotonic in
the amplitude: for the one-sine pulse a safe region lies between the mode-1 tongue and the
mode-2 boundary, so a plain bisection between "safe" and "overturns" can miss the minimum.
The amplitude ratio is therefore first scanned upwards on a grid (``accel_ratio``,
default 95 levels from 1 to 100 in steps of 5%) for the lowest overturning level, then
refined by a scan of that grid step at relative spacing ``tol`` (one tongue of overturning
narrower than the grid step, but wider than ``tol``, is found there), and last by bisection.
The result is the lowest overturning amplitude to the relative precision ``tol``, except
for tongues of overturning narrower than ``tol``, which any sampling can miss.
Every step (one chunk of grid levels, the fine scan, one bisection step) is one
:func:`rocking.simulate_many` call over all the frequency ratios still open.
"""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np
import pandas as pd

from .._validate import in_range, positive
from ..errors import ParameterError
from ..models import get_model, simulate_many
from ..motions import catalog
from ..plot import PALETTE, new_axes, style_axes
from ..units import G

PULSES = ("one_sine", "one_cosine", "ricker", "mavroeidis_papageorgiou")
"""The pulses of :func:`overturning_spectrum` and :func:`outcome_map`: names of
:data:`rocking.motions.catalog.KINDS`."""

_OLD_PULSES = {"sine": "one_sine", "cosine": "one_cosine", "mp": "mavroeidis_papageorgiou"}
"""Old names, accepted for one release with a DeprecationWarning (in the catalog
``"sine"`` is the harmonic motion, not a one-sine pulse)."""

_SET_HERE = ("amplitude", "frequency", "period", "t0", "tc", "duration")
"""Catalog parameters set by the point of the plane and the window (not ``pulse_params``):
the pulses start at rest at t = 0 (their default ``t0``, ``tc``)."""

TAIL = 60.0
"""Default free motion simulated after the pulse, in units of ``1/p``."""

DEFAULT_ACCEL_RATIO = np.geomspace(1.0, 100.0, 95)
"""Default scan grid of ``a_p / (g tan alpha)`` of :func:`overturning_spectrum` (5% steps)."""

_CHUNK = 12  # grid levels per simulate_many call of the upward scan
_MODE_LABELS = {0: "safe", 1: "mode 1 (after an impact)", 2: "mode 2 (no impact)"}
"""Labels of the ``mode`` column (Zhang and Makris 2001)."""


# ---------------------------------------------------------------- validation and pulses
def _ratios(name: str, value, *, sort: bool = False) -> np.ndarray:
    try:
        a = np.atleast_1d(np.asarray(value, dtype=np.float64))
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number or a 1-D array of numbers > 0, got "
                             f"{value!r}") from None
    if a.ndim != 1 or a.size == 0:
        raise ParameterError(f"{name} must be a non-empty 1-D array of numbers > 0")
    bad = ~np.isfinite(a) | (a <= 0.0)
    if bad.any():
        raise ParameterError(f"{name} must hold finite numbers > 0, got {a[bad][0]!r}")
    return np.unique(a) if sort else a


def _check_block(block):
    for attr in ("alpha", "p", "mu"):
        if not hasattr(block, attr):
            raise ParameterError(f"block must be a rocking.Block, got {type(block).__name__}")
    return block


def _pulse_name(pulse) -> str:
    """The catalog name of ``pulse`` (an old name gives a DeprecationWarning, attributed to
    the caller of the public function)."""
    if isinstance(pulse, str) and pulse in _OLD_PULSES:
        new = _OLD_PULSES[pulse]
        warnings.warn(f"pulse={pulse!r} is deprecated: write {new!r} (the catalog's name; "
                      "removed in the next release)", DeprecationWarning, stacklevel=4)
        return new
    if not isinstance(pulse, str) or pulse not in PULSES:
        raise ParameterError(f"pulse must be one of {', '.join(map(repr, PULSES))}, "
                             f"got {pulse!r}")
    return pulse


def _free_params(name: str) -> tuple[str, ...]:
    """The catalog parameters of pulse ``name`` that ``pulse_params`` may set."""
    return tuple(k for k in catalog.KINDS[name].Params.names() if k not in _SET_HERE)


def _resolve(func: str, pulse, model, pulse_params, options: dict):
    """``(pulse name, pulse_params, model options)`` with the deprecated spellings
    (old pulse names, ``options={...}``, ``gamma=``/``nu=`` as keywords) moved to their
    place, each with a DeprecationWarning. ``model=None``: no model options (pulse_motion)."""
    name = _pulse_name(pulse)
    if pulse_params is None:
        pulse_params = {}
    elif not isinstance(pulse_params, dict):
        raise ParameterError(f"pulse_params must be a dict of the pulse's parameters, got "
                             f"{pulse_params!r}")
    options = dict(options)
    if model is not None and "options" in options:
        old = options.pop("options")
        warnings.warn(f"{func}(options={{...}}) is deprecated: pass the model's options as "
                      f"keywords, {func}(..., rtol=1e-10) (removed in the next release)",
                      DeprecationWarning, stacklevel=3)
        if old is not None and not isinstance(old, dict):
            raise ParameterError(f"options must be a dict of the model's options, got {old!r}")
        both = sorted(set(old or {}) & set(options))
        if both:
            raise ParameterError(f"{', '.join(both)}: given both in options={{...}} and as "
                                 "a keyword")
        options = {**(old or {}), **options}
    model_names = () if model is None else get_model(model).Options.names()
    moved = {k: options.pop(k) for k in list(options)
             if k in _free_params(name) and k not in model_names}
    if moved:
        shown = ", ".join(f"{k!r}: {v!r}" for k, v in moved.items())
        warnings.warn(f"{func}({', '.join(f'{k}=' for k in moved)}) is deprecated: pass the "
                      f"pulse's parameters as pulse_params={{{shown}}} (removed in the next "
                      "release)", DeprecationWarning, stacklevel=3)
        both = sorted(set(moved) & set(pulse_params))
        if both:
            raise ParameterError(f"{', '.join(both)}: given both in pulse_params and as a "
                                 "keyword")
        pulse_params = {**moved, **pulse_params}
    if model is None and options:
        raise ParameterError(f"unknown parameter(s) of {func}: {', '.join(options)} (the "
                             f"pulse's parameters go in pulse_params)")
    return name, pulse_params, options


def _axes(name: str, wr: float, p: float, t_free: float, prm: dict) -> dict:
    """The catalog parameters that the point ``omega_p / p = wr`` sets: the period or the
    frequency, and the window (the pulse plus ``t_free``, s)."""
    if name in ("one_sine", "one_cosine"):
        tp = 2.0 * math.pi / (wr * p)
        return {"period": tp, "duration": tp + t_free}
    fp = wr * p / (2.0 * math.pi)
    length = 3.0 / fp if name == "ricker" else prm["gamma"] / fp
    return {"frequency": fp, "duration": length + t_free}


def _pulse_factory(block, name: str, pulse_params: dict, tail: float):
    """A function ``(omega_ratio, accel_ratio) -> Motion`` for ``block`` (validated once)."""
    kind = catalog.KINDS[name]
    free = _free_params(name)
    bad = [k for k in pulse_params if k not in free]
    if bad:
        raise ParameterError(
            f"pulse_params: unknown parameter(s) {', '.join(map(repr, bad))} for pulse "
            f"{name!r} (allowed: {', '.join(free) or 'none'}; the amplitude, the frequency "
            "or period and the window are set by accel_ratio, omega_ratio and tail)")
    fields = {f.name: f for f in dataclasses.fields(kind.Params)}
    missing = [k for k in free if fields[k].metadata.get("required") and k not in pulse_params]
    if missing:
        need = "; ".join(f"{k}: {fields[k].metadata['help']}" for k in missing)
        raise ParameterError(f"pulse={name!r} needs pulse_params {', '.join(missing)} "
                             f"({need})")
    tail = positive("tail", tail, "(units of 1/p)")
    p = float(block.p)
    ag = G * math.tan(block.alpha)
    t_free = tail / p
    # validated once (ranges, "30deg" strings): the checked values are used at every point
    axis = "period" if name in ("one_sine", "one_cosine") else "frequency"
    probe = kind.params(amplitude=ag, **{axis: 1.0}, **pulse_params)
    prm = {k: getattr(probe, k) for k in pulse_params}

    def make(wr, ar):
        try:
            return kind.build(None, amplitude=ar * ag, **_axes(name, wr, p, t_free, prm),
                              **prm)
        except ParameterError as e:
            raise ParameterError(f"the pulse at omega_ratio = {wr:g}, accel_ratio = {ar:g} "
                                 f"(window: the pulse and tail / p = {t_free:g} s): {e}"
                                 ) from None
    make.pulse_params = {k: float(v) for k, v in prm.items()}  # for df.attrs
    return make


def pulse_motion(block, pulse: str, omega_ratio: float, accel_ratio: float, *,
                 tail: float = TAIL, pulse_params: dict | None = None, **deprecated):
    """The pulse of the dimensionless point ``(omega_ratio, accel_ratio)`` for ``block``.

    ``omega_p = omega_ratio * p`` and peak ground acceleration ``a_p = accel_ratio * g *
    tan(alpha)``; the window is the pulse plus ``tail / p`` (s); ``pulse`` is a name of
    :data:`PULSES` and ``pulse_params`` its other catalog parameters (``gamma``, ``nu``).
    This is the motion that :func:`overturning_spectrum` and :func:`outcome_map` simulate
    at that point.

    Examples
    --------
    The pulse's peak is ``accel_ratio * g tan alpha`` and its period ``2 pi / omega_p`` with
    ``omega_p = omega_ratio * p``:

    >>> import math
    >>> import rocking
    >>> from rocking.analysis import pulse_motion
    >>> block = rocking.specimen(2)
    >>> m = pulse_motion(block, "one_sine", 2.0, 1.5)
    >>> round(m.pga / (rocking.G * math.tan(block.alpha)), 6)
    1.5
    >>> round(m.length, 6) == round(2 * math.pi / (2.0 * block.p), 6)
    True
    """
    name, pulse_params, _ = _resolve("pulse_motion", pulse, None, pulse_params, deprecated)
    _check_block(block)
    wr = positive("omega_ratio", omega_ratio)
    ar = positive("accel_ratio", accel_ratio)
    return _pulse_factory(block, name, pulse_params, tail)(wr, ar)


def _run(block, motions, model, options):
    return simulate_many(block, motions, model=model, **options)


# ---------------------------------------------------------------- overturning spectrum
def overturning_spectrum(block, pulse: str = "one_sine", omega_ratio=None, model="housner",
                         *, tol: float = 0.005, accel_ratio=None, tail: float = TAIL,
                         pulse_params: dict | None = None, **options):
    """The overturning spectrum: the minimum ``a_p / (g tan alpha)`` that overturns the
    block, for each ``omega_p / p``.

    The axes are dimensionless (Dimitrakopoulos and DeJong 2012): the result depends only
    on ``omega_p / p``, ``a_p / (g tan alpha)``, ``alpha`` and ``mu`` (module docstring).

    Parameters
    ----------
    block : Block
    pulse : {"one_sine", "one_cosine", "ricker", "mavroeidis_papageorgiou"}
        The pulse, a name of :mod:`rocking.motions.catalog` (module docstring: what
        ``omega_p`` is for each).
    omega_ratio : float or array of float
        The frequency ratios ``omega_p / p`` (> 0).
    model : str or Model class
        As in :func:`rocking.simulate_many`.
    tol : float
        Relative precision of the threshold, in [1e-6, 0.2]: the bisection stops when the
        bracket ``(safe_ratio, min_overturn_ratio]`` is narrower than ``tol *
        min_overturn_ratio``.
    accel_ratio : array of float, optional
        The scan grid of ``a_p / (g tan alpha)`` (default :data:`DEFAULT_ACCEL_RATIO`,
        1 to 100 in 5% steps). The lowest overturning level on this grid is refined by a
        scan of the step below it at spacing ``tol`` and then by bisection.
    tail : float
        Free motion simulated after the pulse, in units of ``1/p`` (default 60).
    pulse_params : dict, optional
        The pulse's other catalog parameters: ``gamma`` (> 1) and ``nu`` (rad) for
        ``"mavroeidis_papageorgiou"``.
    **options
        The model's options (e.g. ``rtol=1e-10``) and the other keywords of
        :func:`rocking.simulate_many`.

    Returns
    -------
    pandas.DataFrame
        One row per frequency ratio: ``omega_ratio``, ``min_overturn_ratio`` (the lowest
        amplitude ratio found to overturn; NaN if nothing on the grid overturns),
        ``mode`` (as in Zhang and Makris 2001: 1, overturning after one or more impacts;
        2, overturning without any impact; <NA> if not found), ``safe_ratio`` (the
        largest amplitude ratio below it found not to overturn) and ``n_impacts`` (of the run at
        ``min_overturn_ratio``). ``df.attrs`` holds the block's ``alpha``, ``p``, ``mu``,
        ``pulse``, ``tol``, ``model`` and ``n_simulations``. Plot with
        :func:`plot_overturning_spectrum`.

    Examples
    --------
    Specimen 2 under one-sine pulses: the least overturning ``a_p / (g tan alpha)`` is just
    above the static uplift bound 1 for long pulses and grows with ``omega_p / p``:

    >>> import rocking
    >>> from rocking.analysis import overturning_spectrum
    >>> sp = overturning_spectrum(rocking.specimen(2), "one_sine", [1.0, 4.0], tol=0.02)
    >>> sp["min_overturn_ratio"].round(1).tolist(), sp["mode"].tolist()
    ([1.1, 1.7], [1, 1])
    >>> bool((sp["safe_ratio"] < sp["min_overturn_ratio"]).all())
    True
    """

    name, pulse_params, options = _resolve("overturning_spectrum", pulse, model, pulse_params,
                                           options)
    _check_block(block)
    if omega_ratio is None:
        raise ParameterError("omega_ratio must be given: the frequency ratios omega_p/p > 0")
    w = _ratios("omega_ratio", omega_ratio)
    tol = in_range("tol", tol, 1e-6, 0.2, lo_open=False, hi_open=False, shown="[1e-6, 0.2]")
    grid = _ratios("accel_ratio", DEFAULT_ACCEL_RATIO if accel_ratio is None else accel_ratio,
                   sort=True)
    make = _pulse_factory(block, name, pulse_params, tail)
    n, m = w.size, grid.size
    first = np.full(n, -1)
    imp_hi = np.zeros(n, dtype=np.int64)
    n_sim = 0
    # 1. upward scan of the grid, a chunk of levels at a time, for the open ratios only
    for start in range(0, m, _CHUNK):
        open_ = np.flatnonzero(first < 0)
        if open_.size == 0:
            break
        levels = grid[start:start + _CHUNK]
        res = _run(block, [make(w[i], a) for i in open_ for a in levels], model, options)
        n_sim += len(res)
        over = res.overturned.reshape(open_.size, levels.size)
        imps = res.n_impacts.reshape(open_.size, levels.size)
        for row, i in enumerate(open_):
            hit = np.flatnonzero(over[row])
            if hit.size:
                first[i] = start + hit[0]
                imp_hi[i] = imps[row, hit[0]]
    found = first >= 0
    hi = np.where(found, grid[np.maximum(first, 0)], np.nan)
    lo = np.where(first > 0, grid[np.maximum(first - 1, 0)], 0.0)
    lo[~found] = grid[-1]
    # 2. a fine scan of each bracket at relative spacing tol, so that an overturning
    #    tongue narrower than the grid step but wider than tol is not missed (the boundary
    #    is not monotonic: e.g. the one-cosine pulse near omega_p/p = 1)
    fine = np.flatnonzero(found & (lo > 0.0) & (hi - lo > tol * hi))
    if fine.size:
        k = np.ceil(np.log(hi[fine] / lo[fine]) / math.log1p(tol)).astype(int)
        pts = [(i, lo[i] * (1.0 + tol) ** j) for i, kk in zip(fine, k, strict=True)
               for j in range(1, kk) if lo[i] * (1.0 + tol) ** j < hi[i]]
        if pts:
            res = _run(block, [make(w[i], a) for i, a in pts], model, options)
            n_sim += len(res)
            done = set()
            for (i, a), ov, nimp in zip(pts, res.overturned, res.n_impacts, strict=True):
                if i in done:
                    continue
                if ov:  # the first overturning point of the fine scan
                    hi[i], imp_hi[i] = a, nimp
                    done.add(i)
                else:
                    lo[i] = a
    # 3. vectorised bisection between the last safe and the first overturning level
    while True:
        act = np.flatnonzero(found & (hi - lo > tol * hi))
        if act.size == 0:
            break
        mid = 0.5 * (lo[act] + hi[act])
        res = _run(block, [make(w[i], a) for i, a in zip(act, mid, strict=True)], model,
                   options)
        n_sim += len(res)
        ov = np.asarray(res.overturned, dtype=bool)
        hi[act[ov]] = mid[ov]
        imp_hi[act[ov]] = res.n_impacts[ov]
        lo[act[~ov]] = mid[~ov]
    mode = pd.array(_mode(imp_hi), dtype="Int64")
    mode[~found] = pd.NA
    df = pd.DataFrame({
        "omega_ratio": w,
        "min_overturn_ratio": hi,
        "mode": mode,
        "safe_ratio": lo,
        "n_impacts": pd.array(np.where(found, imp_hi, 0), dtype="Int64"),
    })
    df.loc[~found, "n_impacts"] = pd.NA
    df.attrs.update({"pulse": name, "alpha": float(block.alpha), "p": float(block.p),
                     "mu": float(block.mu), "tol": tol, "model": _model_name(model),
                     "n_simulations": int(n_sim), "accel_ratio_max": float(grid[-1]),
                     "tail": float(tail), **make.pulse_params})
    return df


def _mode(n_impacts) -> np.ndarray:
    """Zhang and Makris (2001): mode 1 overturns after an impact, mode 2 without one."""
    return np.where(np.asarray(n_impacts) > 0, 1, 2)


def _model_name(model) -> str:
    return model if isinstance(model, str) else getattr(model, "name", str(model))


# ---------------------------------------------------------------- outcome map
def outcome_map(block, pulse: str = "one_sine", omega_ratio=None, accel_ratio=None,
                model="housner", *, tail: float = TAIL, pulse_params: dict | None = None,
                **options):
    """The outcome of every cell of an ``(omega_p / p, a_p / (g tan alpha))`` grid.

    The axes are dimensionless (Dimitrakopoulos and DeJong 2012; module docstring). All the
    cells are run in one :func:`rocking.simulate_many` call.

    Parameters
    ----------
    block, pulse, model, tail, pulse_params, **options
        As in :func:`overturning_spectrum`.
    omega_ratio, accel_ratio : array of float
        The frequency ratios ``omega_p / p`` and amplitude ratios ``a_p / (g tan alpha)``
        (> 0).

    Returns
    -------
    pandas.DataFrame
        Tidy, one row per cell (``omega_ratio`` outer, ``accel_ratio`` inner):
        ``omega_ratio``, ``accel_ratio``, ``overturned``, ``mode`` (0: safe; Zhang and
        Makris 2001: 1, overturned after one or more impacts; 2, overturned without any
        impact), ``n_impacts``, ``rocked`` (the block left rest) and
        ``max_abs_theta_over_alpha``. For the one-sine pulse the map shows the safe region
        between the mode-1 tongue and the mode-2 boundary. Plot with
        :func:`plot_outcome_map`.

    Examples
    --------
    Below ``a_p / (g tan alpha) = 1`` the block does not even lift off; at
    ``omega_p / p = 4`` the safe region between the mode-1 and mode-2 boundaries shows:

    >>> import rocking
    >>> from rocking.analysis import outcome_map
    >>> om = outcome_map(rocking.specimen(2), "one_sine", [1.0, 4.0], [0.9, 1.5, 3.0])
    >>> om["accel_ratio"].tolist()
    [0.9, 1.5, 3.0, 0.9, 1.5, 3.0]
    >>> om["rocked"].tolist()
    [False, True, True, False, True, True]
    >>> om["mode"].tolist()  # 0 safe, 1 overturned after impacts, 2 without any
    [0, 2, 2, 0, 0, 1]
    """

    name, pulse_params, options = _resolve("outcome_map", pulse, model, pulse_params,
                                           options)
    _check_block(block)
    if omega_ratio is None or accel_ratio is None:
        raise ParameterError("omega_ratio and accel_ratio must be given (arrays of numbers "
                             "> 0)")
    w = _ratios("omega_ratio", omega_ratio)
    a = _ratios("accel_ratio", accel_ratio)
    make = _pulse_factory(block, name, pulse_params, tail)
    ww, aa = np.repeat(w, a.size), np.tile(a, w.size)
    res = _run(block, [make(x, y) for x, y in zip(ww, aa, strict=True)], model, options)
    over = np.asarray(res.overturned, dtype=bool)
    nimp = np.asarray(res.n_impacts, dtype=np.int64)
    df = pd.DataFrame({
        "omega_ratio": ww,
        "accel_ratio": aa,
        "overturned": over,
        "mode": np.where(over, _mode(nimp), 0),
        "n_impacts": nimp,
        "rocked": np.asarray(res.rocked, dtype=bool),
        "max_abs_theta_over_alpha": np.asarray(res.max_abs_theta) / block.alpha,
    })
    df.attrs.update({"pulse": name, "alpha": float(block.alpha), "p": float(block.p),
                     "mu": float(block.mu), "model": _model_name(model),
                     "n_simulations": len(res), "tail": float(tail),
                     **make.pulse_params})
    return df


# ---------------------------------------------------------------- plots
_XLABEL = r"frequency ratio $\omega_p / p$"
_YLABEL = r"acceleration ratio $a_p / (g \tan\alpha)$"
_COLORS = {"no rocking": "#F2F2F2", "rocking, safe": "#BFD7EA",
           _MODE_LABELS[1]: "#E69F00", _MODE_LABELS[2]: "#D55E00"}


def _title(attrs) -> str:
    bits = [f"{attrs.get('pulse', '').replace('_', '-')} pulse"]
    if "alpha" in attrs:
        bits.append(f"alpha = {attrs['alpha']:.3g} rad")
    if "mu" in attrs:
        bits.append(f"mu = {attrs['mu']:.3g}")
    return ", ".join(bits)


def plot_overturning_spectrum(df, ax=None, *, label: str | None = None, **kw):
    """Plot an :func:`overturning_spectrum`: ``min_overturn_ratio`` against
    ``omega_ratio``, the points marked by overturning mode. Returns the Axes.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import rocking
    >>> from rocking.analysis import overturning_spectrum, plot_overturning_spectrum
    >>> sp = overturning_spectrum(rocking.specimen(2), "one_sine", [1.0, 4.0], tol=0.05)
    >>> ax = plot_overturning_spectrum(sp, label="specimen 2")
    >>> type(ax).__name__
    'Axes'
    """

    if ax is None:
        _, ax = new_axes()
    x = np.asarray(df["omega_ratio"], dtype=float)
    y = np.asarray(df["min_overturn_ratio"], dtype=float)
    mode = df["mode"].to_numpy(dtype=float, na_value=np.nan)
    kw.setdefault("color", PALETTE[0])
    kw.setdefault("linewidth", 1.2)
    ax.plot(x, y, label=label or "minimum overturning level", **kw)
    for md, marker in ((1, "o"), (2, "s")):
        col = _COLORS[_MODE_LABELS[md]]
        sel = mode == md
        if sel.any():
            ax.plot(x[sel], y[sel], linestyle="none", marker=marker, markersize=4, color=col,
                    label=_MODE_LABELS[md])
    style_axes(ax, _XLABEL, _YLABEL)
    ax.set_ylim(bottom=0.0)
    ax.legend(frameon=False, fontsize=8)
    ax.set_title(_title(df.attrs), fontsize=10)
    return ax


def _edges(v: np.ndarray) -> np.ndarray:
    if v.size == 1:
        return np.array([v[0] * 0.95, v[0] * 1.05])
    mid = 0.5 * (v[1:] + v[:-1])
    return np.concatenate([[v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]])


def plot_outcome_map(df, ax=None, *, spectrum=None):
    """Plot an :func:`outcome_map`: the cells coloured by outcome (no rocking, rocking
    without overturning, overturning in mode 1 or mode 2), which shows both overturning
    modes and the safe region between them. ``spectrum`` (an :func:`overturning_spectrum`
    of the same block and pulse) is overlaid as a line. Returns the Axes.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import rocking
    >>> from rocking.analysis import outcome_map, plot_outcome_map
    >>> om = outcome_map(rocking.specimen(2), "one_sine", [1.0, 4.0], [0.9, 1.5, 3.0])
    >>> type(plot_outcome_map(om)).__name__
    'Axes'
    """
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.patches import Patch

    if ax is None:
        _, ax = new_axes(figsize=(6.4, 4.4))
    w = np.unique(np.asarray(df["omega_ratio"], dtype=float))
    a = np.unique(np.asarray(df["accel_ratio"], dtype=float))
    cat = np.where(df["mode"] == 1, 2, np.where(df["mode"] == 2, 3,
                                                np.where(df["rocked"], 1, 0)))
    grid = np.full((a.size, w.size), np.nan)
    iw = np.searchsorted(w, np.asarray(df["omega_ratio"], dtype=float))
    ia = np.searchsorted(a, np.asarray(df["accel_ratio"], dtype=float))
    grid[ia, iw] = cat
    names = list(_COLORS)
    cmap = ListedColormap([_COLORS[k] for k in names])
    ax.pcolormesh(_edges(w), _edges(a), grid, cmap=cmap,
                  norm=BoundaryNorm([-0.5, 0.5, 1.5, 2.5, 3.5], 4), shading="flat")
    handles = [Patch(color=_COLORS[k], label=k) for k in names]
    if spectrum is not None:
        (line,) = ax.plot(spectrum["omega_ratio"], spectrum["min_overturn_ratio"], color="k",
                          linewidth=1.2, label="overturning spectrum")
        handles.append(line)
    style_axes(ax, _XLABEL, _YLABEL)
    ax.grid(False)
    ax.legend(handles=handles, fontsize=8, loc="lower right", framealpha=0.9)
    ax.set_title(_title(df.attrs), fontsize=10)
    return ax
