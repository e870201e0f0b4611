"""Damage states of a rocking block and their fragility curves.

A damage state is a threshold on ``max |theta| / alpha``: by default state 1 from 0.25,
state 2 from 0.5 and the last state, overturning (:data:`DEFAULT_THRESHOLDS`).
:func:`fragility_curves` fits ``P(DS >= k | im)`` for every state k >= 1.

Successive curves must not cross. The default ``method="common_beta"`` guarantees it:
one ordered-probit model (statsmodels ``OrderedModel``, maximum likelihood over all the
records and states at once) gives every state the same beta and increasing medians, as
the damage-state families of pelicun / FEMA P-58 usually do, so the curves are parallel
in ``ln im`` and never cross, for the fit and for every bootstrap draw.
``method="separate"`` fits each state alone (:func:`~rocking.analysis.fragility.fragility`)
and refuses the result if two curves cross within the IM range of the data.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..errors import ParameterError, SimulationError
from ..plot import PALETTE, figure, unit_label
from ..results import jsonable
from .fragility import (
    FragilityFit,
    as_bool_array,
    check_bootstrap,
    check_n_boot,
    check_separation,
    fragility,
    make_fit,
    make_rng,
    pelicun_table,
    records,
    stripe_counts,
)

#: Default thresholds on ``max |theta| / alpha`` (states 1 and 2); overturning is the
#: last state.
DEFAULT_THRESHOLDS = (0.25, 0.5)

METHODS = ("common_beta", "separate")


def _thresholds(thresholds) -> np.ndarray:
    try:
        t = np.atleast_1d(np.asarray(thresholds, dtype=float))
    except (TypeError, ValueError):
        raise ParameterError(f"thresholds must be numbers, got {thresholds!r}") from None
    if t.ndim != 1 or not np.all(np.isfinite(t)) or np.any(t <= 0) or np.any(np.diff(t) <= 0):
        raise ParameterError("thresholds must be finite, > 0 and strictly increasing "
                             f"(on max |theta| / alpha), got {thresholds!r}")
    return t


def damage_state(max_abs_theta, alpha, overturned, thresholds=DEFAULT_THRESHOLDS):
    """Integer damage states ``0..len(thresholds) + 1`` of each run.

    State ``k`` (1 <= k <= len(thresholds)) when ``max_abs_theta / alpha`` reached
    ``thresholds[k-1]`` (and not the next one), the last state when the block overturned
    (whatever its recorded angle; it may be NaN), 0 otherwise. ``alpha`` (rad) is a
    scalar or one per run.

    Examples
    --------
    A block of slenderness 0.2 rad: 0.01 rad is below the first threshold (0.25 alpha),
    0.05 rad reaches it, 0.1 rad reaches 0.5 alpha, and an overturned run is in the last
    state whatever its angle:

    >>> from rocking.analysis import damage_state
    >>> damage_state([0.01, 0.05, 0.1, np.nan], 0.2, [False, False, False, True])
    array([0, 1, 2, 3])
    """
    t = _thresholds(thresholds)
    th = np.atleast_1d(np.asarray(max_abs_theta, dtype=float))
    ov = as_bool_array("overturned", overturned)
    if th.ndim != 1 or th.size != ov.size:
        raise ParameterError(f"max_abs_theta and overturned must have the same length, got "
                             f"{th.size} and {ov.size}")
    a = np.broadcast_to(np.asarray(alpha, dtype=float), th.shape) if np.ndim(alpha) == 0 \
        else np.asarray(alpha, dtype=float)
    if a.shape != th.shape:
        raise ParameterError(f"alpha must be a scalar or one per run ({th.size}), got "
                             f"shape {a.shape}")
    if not np.all(np.isfinite(a) & (a > 0)):
        raise ParameterError("alpha must be finite and > 0 (rad)")
    bad = np.flatnonzero(~ov & ~(np.isfinite(th) & (th >= 0)))
    if bad.size:
        raise ParameterError(f"max_abs_theta must be finite and >= 0 for the runs that did "
                             f"not overturn, got max_abs_theta[{bad[0]}] = {th[bad[0]]}")
    with np.errstate(invalid="ignore"):
        state = np.searchsorted(t, np.where(ov, 0.0, th / a), side="right")
    state[ov] = t.size + 1
    return state.astype(int)


def state_labels(thresholds=DEFAULT_THRESHOLDS) -> list[str]:
    """Labels of the states 1..n (``DS1: max|theta|/alpha >= 0.25``, ..., overturning)."""
    t = _thresholds(thresholds)
    return [f"DS{k}: max|theta|/alpha >= {v:g}" for k, v in enumerate(t, 1)] + \
        [f"DS{t.size + 1}: overturning"]


@dataclass
class FragilityCurves:
    """One :class:`FragilityFit` per damage state (``fits[k-1]`` is ``P(DS >= k)``).

    Examples
    --------
    >>> from rocking.analysis import fragility_curves
    >>> im = np.repeat([1.0, 2.0, 4.0, 8.0], 10)  # PGA (m/s^2), 10 records each
    >>> j = np.tile(np.arange(10), 4)
    >>> ds1 = j < np.repeat([3, 7, 9, 10], 10)  # reached DS1 or worse
    >>> ds2 = j < np.repeat([0, 2, 5, 8], 10)  # overturned
    >>> curves = fragility_curves(im, ds1.astype(int) + ds2, thresholds=(0.25,), n_boot=0)
    >>> curves.labels
    ('DS1', 'DS2')
    >>> p = curves.state_probability([1.0, 3.0])  # P(DS = k): the states sum to one
    >>> np.allclose(p[["DS0", "DS1", "DS2"]].sum(axis=1), 1.0)
    True
    """

    fits: tuple
    thresholds: tuple | None
    method: str
    labels: tuple

    def __len__(self) -> int:
        return len(self.fits)

    @property
    def medians(self) -> np.ndarray:
        return np.array([f.median for f in self.fits])

    @property
    def betas(self) -> np.ndarray:
        return np.array([f.beta for f in self.fits])

    def probability(self, im):
        """``P(DS >= k | im)``: a DataFrame with ``im`` and one column per state label.

        Examples
        --------
        >>> from scipy.stats import norm
        >>> from rocking.analysis import fragility_curves
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 20)  # PGA (m/s^2)
        >>> j = np.tile(np.arange(20), 5)  # planted medians 1 and 4 m/s^2, beta 0.4:
        >>> state = sum(j < np.round(20 * norm.cdf(np.log(im / m) / 0.4)) for m in (1, 4))
        >>> curves = fragility_curves(im, state, n_boot=0, im_name="pga", im_unit="m/s^2")
        >>> p = curves.probability(curves.medians)  # each state is 50 % at its median
        >>> np.round(np.diag(p[["DS1", "DS2"]].to_numpy()), 3).tolist()
        [0.5, 0.5]
        >>> bool(np.all(p["DS2"] <= p["DS1"]))  # DS2 or worse is rarer than DS1 or worse
        True
        """

        x = np.atleast_1d(np.asarray(im, dtype=float))
        d = {"im": x}
        d.update({lab: f.probability(x) for lab, f in zip(self.labels, self.fits,
                                                           strict=True)})
        return pd.DataFrame(d)

    def state_probability(self, im):
        """``P(DS = k | im)`` for k = 0..n (columns ``DS0`` to ``DSn``), summing to 1.

        Examples
        --------
        >>> from scipy.stats import norm
        >>> from rocking.analysis import fragility_curves
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 20)  # PGA (m/s^2)
        >>> j = np.tile(np.arange(20), 5)  # planted medians 1 and 4 m/s^2, beta 0.4:
        >>> state = sum(j < np.round(20 * norm.cdf(np.log(im / m) / 0.4)) for m in (1, 4))
        >>> curves = fragility_curves(im, state, n_boot=0, im_name="pga", im_unit="m/s^2")
        >>> p = curves.state_probability([1.0, 2.0, 4.0])
        >>> np.allclose(p[["DS0", "DS1", "DS2"]].sum(axis=1), 1.0)
        True
        >>> pe = curves.probability([1.0, 2.0, 4.0])  # P(DS = 1) = P(DS >= 1) - P(DS >= 2)
        >>> np.allclose(p["DS1"], pe["DS1"] - pe["DS2"])
        True
        """

        x = np.atleast_1d(np.asarray(im, dtype=float))
        pe = np.column_stack([np.ones_like(x)] + [f.probability(x) for f in self.fits]
                             + [np.zeros_like(x)])
        p = pe[:, :-1] - pe[:, 1:]
        return pd.DataFrame({"im": x, **{f"DS{k}": p[:, k] for k in range(p.shape[1])}})

    def to_pelicun(self, id: str = "rocking.block", *, demand_type: str =
                   "Peak Ground Acceleration", demand_unit: str = "g",
                   im_unit: str | None = None, directional: bool = True, path=None):
        """One pelicun fragility row with a limit state per damage state (``LS1-Family``,
        ``LS1-Theta_0`` (median in ``Demand-Unit``), ``LS1-Theta_1`` (beta), ``LS2-...``);
        see :meth:`FragilityFit.to_pelicun`.

        Examples
        --------
        >>> from scipy.stats import norm
        >>> from rocking.analysis import fragility_curves
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 20)  # PGA (m/s^2)
        >>> j = np.tile(np.arange(20), 5)  # planted medians 1 and 4 m/s^2, beta 0.4:
        >>> state = sum(j < np.round(20 * norm.cdf(np.log(im / m) / 0.4)) for m in (1, 4))
        >>> curves = fragility_curves(im, state, n_boot=0, im_name="pga", im_unit="m/s^2")
        >>> row = curves.to_pelicun(path="block.csv")  # medians converted to g
        >>> np.allclose(row[["LS1-Theta_0", "LS2-Theta_0"]].iloc[0] * 9.80665, curves.medians)
        True
        >>> import pandas as pd
        >>> pd.read_csv("block.csv").columns.tolist()[:3]
        ['ID', 'Incomplete', 'Demand-Type']
        """
        return pelicun_table(self.fits, id=id, demand_type=demand_type,
                             demand_unit=demand_unit, im_unit=im_unit,
                             directional=directional, path=path)

    def summary(self) -> dict:
        """JSON-ready: the method, thresholds and each state's fit summary.

        Examples
        --------
        >>> from scipy.stats import norm
        >>> from rocking.analysis import fragility_curves
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 20)  # PGA (m/s^2)
        >>> j = np.tile(np.arange(20), 5)  # planted medians 1 and 4 m/s^2, beta 0.4:
        >>> state = sum(j < np.round(20 * norm.cdf(np.log(im / m) / 0.4)) for m in (1, 4))
        >>> curves = fragility_curves(im, state, n_boot=0, im_name="pga", im_unit="m/s^2")
        >>> s = curves.summary()
        >>> s["method"], [st["label"] for st in s["states"]]
        ('common_beta', ['DS1', 'DS2'])
        >>> [round(st["median"]) for st in s["states"]]  # the planted medians (m/s^2)
        [1, 4]
        """
        return jsonable({"method": self.method, "thresholds": self.thresholds,
                         "states": [f.summary() for f in self.fits]})

    def to_dict(self) -> dict:
        """Everything, JSON-ready: :meth:`summary` with each state's full
        :meth:`FragilityFit.to_dict` (coefficients, data, bootstrap sample).

        Examples
        --------
        >>> from scipy.stats import norm
        >>> from rocking.analysis import fragility_curves
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 20)  # PGA (m/s^2)
        >>> j = np.tile(np.arange(20), 5)  # planted medians 1 and 4 m/s^2, beta 0.4:
        >>> state = sum(j < np.round(20 * norm.cdf(np.log(im / m) / 0.4)) for m in (1, 4))
        >>> curves = fragility_curves(im, state, n_boot=0, im_name="pga", im_unit="m/s^2")
        >>> import json
        >>> d = json.loads(json.dumps(curves.to_dict()))  # plain JSON
        >>> d["states"][1]["data"]["n_failed"]  # records in DS2 or worse, per stripe
        [0, 0, 1, 10, 19]
        """
        d = self.summary()
        d["states"] = [f.to_dict() for f in self.fits]
        return d

    def plot(self, ax=None, *, level: float = 0.95, band: bool = True, data: bool = True):
        """Every state's curve (with its band and data); returns the Axes.

        One legend entry per state (its median, in the IM's unit, and beta) and one for
        the bands, outside the axes on the right so that it covers no curve.

        Examples
        --------
        >>> from scipy.stats import norm
        >>> from rocking.analysis import fragility_curves
        >>> im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0], 20)  # PGA (m/s^2)
        >>> j = np.tile(np.arange(20), 5)  # planted medians 1 and 4 m/s^2, beta 0.4:
        >>> state = sum(j < np.round(20 * norm.cdf(np.log(im / m) / 0.4)) for m in (1, 4))
        >>> curves = fragility_curves(im, state, n_boot=0, im_name="pga", im_unit="m/s^2")
        >>> ax = curves.plot()
        >>> ax.get_xlabel(), ax.get_ylabel()
        ('PGA (m/s$^2$)', 'probability of exceedance')
        >>> [t.get_text().split("\\n")[0] for t in ax.get_legend().get_texts()]
        ['DS1', 'DS2']
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """

        if ax is None:
            _, ax = figure(figsize=(8.0, 3.6))
        lo = min(f.median * math.exp(-2.5 * f.beta) for f in self.fits)
        hi = max(f.median * math.exp(2.5 * f.beta) for f in self.fits)
        lo, hi = min(lo, self.fits[0].im_range[0]), max(hi, self.fits[0].im_range[1])
        x = np.geomspace(lo, hi, 200)
        unit = unit_label(self.fits[0].im_unit)
        unit = f" {unit}" if unit else ""
        for i, f in enumerate(self.fits):
            f.plot(ax, level=level, band=band, data=data, im=x,
                   color=PALETTE[i % len(PALETTE)],
                   label=f"{f.label}\n(median {f.median:.3g}{unit}, beta {f.beta:.2f})")
        handles, labels = ax.get_legend_handles_labels()
        keep = [k for k, t in enumerate(labels) if "band" not in t]
        if band and len(keep) < len(labels):  # one entry for all the bands, in grey
            from matplotlib.patches import Patch

            first = next(t for t in labels if "band" in t)
            handles = [handles[k] for k in keep] + [Patch(color="0.6", alpha=0.35, lw=0)]
            labels = [labels[k] for k in keep] + [first]
        ax.legend(handles, labels, frameon=False, fontsize="small", loc="upper left",
                  bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
        return ax


def _ordered_probit(x, state, n_states):
    """statsmodels ``OrderedModel`` (probit) of the states on ``ln x``: the common beta,
    the thresholds, and the model (to transform bootstrap draws)."""

    from statsmodels.miscmodels.ordinal_model import OrderedModel  # 1.3 s to import

    model = OrderedModel(state, np.log(x)[:, None], distr="probit")
    res = model.fit(method="bfgs", disp=False, maxiter=500)
    if not res.mle_retvals.get("converged", True):
        raise SimulationError("the ordered-probit fit of the damage states did not converge")
    return model, np.asarray(res.params, float), np.asarray(res.cov_params(), float), \
        float(res.llf)


def _cuts(params: np.ndarray) -> np.ndarray:
    """Thresholds ``t_0 < t_1 < ...`` from OrderedModel's parameters
    ``[b, t_0, ln(t_1 - t_0), ...]`` (vectorised over rows)."""
    p = np.atleast_2d(params)
    return np.cumsum(np.column_stack([p[:, 1], np.exp(p[:, 2:])]), axis=1)


def missing_states_message(missing, n_states: int, thresholds=None) -> str:
    """The one-line refusal of :func:`fragility_curves` when a damage state has no record:
    which states are empty, in words, and what to change.

    Examples
    --------
    >>> from rocking.analysis.damage import missing_states_message
    >>> print(missing_states_message([], 0))  # doctest: +NORMALIZE_WHITESPACE
    state: no record reached a damage state (every record is in state 0, undamaged), so
    there is no curve to fit; add stronger IM levels
    >>> print(missing_states_message([3], 3, (0.25, 0.5)))  # doctest: +NORMALIZE_WHITESPACE
    state: no record is in damage state 3 (DS3: overturning) of the states 0..3; every
    state needs records to fit its curve; add stronger IM levels
    """
    if n_states < 1:
        return ("state: no record reached a damage state (every record is in state 0, "
                "undamaged), so there is no curve to fit; add stronger IM levels")
    names = (state_labels(thresholds) if thresholds is not None else
             [f"DS{k}" for k in range(1, n_states + 1)])

    def name(k):
        return "0 (undamaged)" if k == 0 else (
            f"{k} ({names[k - 1]})" if ":" in names[k - 1] else str(k))

    listed = ", ".join(name(k) for k in missing)
    what = "damage states" if len(missing) > 1 else "damage state"
    todo = []
    if 0 in missing:
        todo.append("weaker IM levels")
    if n_states in missing:
        todo.append("stronger IM levels")
    if any(0 < k < n_states for k in missing):
        todo.append("levels in between")
    fix = f"add {' and '.join(todo)}" + (
        " (or change the thresholds)" if thresholds is not None
        and any(0 < k < n_states for k in missing) else "")
    return (f"state: no record is in {what} {listed} of the states 0..{n_states}; every "
            f"state needs records to fit its curve; {fix}")


def fragility_curves(im, state=None, *, ratio=None, overturned=None,
                     thresholds=DEFAULT_THRESHOLDS, method: str = "common_beta",
                     n_boot: int = 1000, seed: int | None = 0, bootstrap: str = "normal",
                     im_name: str = "im", im_unit: str | None = None):
    """Fragility curves ``P(DS >= k | im)`` of every damage state k >= 1.

    Give the integer ``state`` of each record (:func:`damage_state`), or ``ratio``
    (``max |theta| / alpha``) and ``overturned``, classified with ``thresholds``. Every
    state 0..n must occur in the data. ``method="common_beta"`` (default): an ordered
    probit on ``ln im`` fitted by statsmodels; one beta, medians
    ``exp(t_{k-1} / b)``, standard errors by the delta method; the ``"normal"``
    bootstrap draws all parameters jointly, so no draw crosses either.
    ``method="separate"``: one :func:`fragility` per state, refused if two curves cross
    within the data's IM range. ``im_name`` and ``im_unit`` as in :func:`fragility` (every
    state's fit carries them). Baker (2015); pelicun's limit-state families.

    Examples
    --------
    Planted damage states: at each PGA level the fractions of three lognormal curves of
    medians 1, 2 and 4 m/s^2 and common beta 0.3; the ordered probit recovers them.

    >>> from scipy.stats import norm
    >>> from rocking.analysis import fragility_curves
    >>> im = np.repeat([0.5, 1.0, 2.0, 3.0, 4.0, 6.0, 8.0], 50)  # PGA (m/s^2)
    >>> j = np.tile(np.arange(50), 7)
    >>> state = sum(j < np.round(50 * norm.cdf(np.log(im / m) / 0.3)) for m in (1, 2, 4))
    >>> curves = fragility_curves(im, state, n_boot=0, im_name="pga", im_unit="m/s^2")
    >>> curves.labels, np.round(curves.medians, 1).tolist(), np.round(curves.betas, 1).tolist()
    (('DS1', 'DS2', 'DS3'), [1.0, 2.0, 4.0], [0.3, 0.3, 0.3])
    """

    if method not in METHODS:
        raise ParameterError(f"method must be one of {METHODS}, got {method!r}")
    t = _thresholds(thresholds) if state is None else None
    if (state is None) == (ratio is None):
        raise ParameterError("give either state or ratio (with overturned), not both")
    if state is None:
        if overturned is None:
            raise ParameterError("overturned is required with ratio")
        x, ov = records(im, overturned, names=("im", "overturned"))
        r = np.atleast_1d(np.asarray(ratio, dtype=float))
        if r.shape != x.shape:
            raise ParameterError(f"im and ratio must have the same length, got {x.size} "
                                 f"and {r.size}")
        s = damage_state(r, 1.0, ov, t)
        n_states = t.size + 1
    else:
        st = np.atleast_1d(np.asarray(state))
        if st.dtype == bool or st.dtype.kind not in "iuf" or st.ndim != 1 \
                or not np.all(np.isfinite(st)) or np.any(st != np.round(st)) or np.any(st < 0):
            raise ParameterError("state must be integers >= 0 (damage states), got "
                                 f"{state!r}")
        x, _ = records(im, np.zeros(st.size, bool), names=("im", "state"))
        s = st.astype(int)
        n_states = int(s.max())
    missing = sorted(set(range(n_states + 1)) - set(s.tolist()))
    if missing or n_states < 1:
        raise ParameterError(missing_states_message(missing, n_states, t))
    labels = tuple(state_labels(t) if t is not None else
                   [f"DS{k}" for k in range(1, n_states + 1)])
    n_boot, rng, bootstrap = check_n_boot(n_boot), make_rng(seed), check_bootstrap(bootstrap)
    if bootstrap == "cluster":
        raise ParameterError("bootstrap='cluster' is for fragility(..., clusters=...); "
                             "fragility_curves takes 'normal' or 'resample'")
    thr = None if t is None else tuple(t.tolist())
    if method == "separate":
        fits = tuple(fragility(x, s >= k, n_boot=n_boot, seed=seed, bootstrap=bootstrap,
                               label=labels[k - 1], im_name=im_name, im_unit=im_unit)
                     for k in range(1, n_states + 1))
        _check_no_crossing(fits, x.min(), x.max())
        return FragilityCurves(fits, thr, method, labels)
    if bootstrap != "normal":
        raise ParameterError("bootstrap must be 'normal' with method='common_beta'")
    splits_ok = 0
    for k in range(1, n_states + 1):
        try:
            check_separation(x, s >= k)
            splits_ok += 1
        except ParameterError:
            pass
    if splits_ok == 0:
        check_separation(x, s >= 1, what=f"state >= 1 (of {n_states})")
    _, params, pcov, llf = _ordered_probit(x, s, n_states)
    b = params[0]
    if b <= 0:
        raise SimulationError(f"the ordered-probit slope is not positive (b = {b:g})")
    cuts = _cuts(params)[0]
    draws = rng.multivariate_normal(params, pcov, size=n_boot) if n_boot else \
        np.empty((0, params.size))
    boot_cuts = _cuts(draws) if n_boot else np.empty((0, n_states))
    levels, n, _, _ = stripe_counts(x, s >= 1)
    fits = []
    for k in range(1, n_states + 1):
        j = k - 1
        # P(DS >= k) = Phi(b ln im - t_{k-1}): coef (b0, b1) = (-t_j, b)
        jac = np.zeros((2, params.size))
        jac[0, 1] = -1.0
        jac[0, 2:2 + j] = -np.exp(params[2:2 + j])
        jac[1, 0] = 1.0
        coef = np.array([-cuts[j], b])
        kk = np.bincount(np.searchsorted(levels, x), weights=s >= k, minlength=levels.size)
        data = pd.DataFrame({"im": levels, "n": n, "n_failed": kk.astype(int)})
        boot = np.column_stack([-boot_cuts[:, j], draws[:, 0]]) if n_boot else \
            np.empty((0, 2))
        fits.append(make_fit(coef, jac @ pcov @ jac.T, "ordered probit, common beta",
                             data, boot, bootstrap, seed, 0, llf, labels[j], im_name,
                             im_unit))
    return FragilityCurves(tuple(fits), thr, method, labels)


def _check_no_crossing(fits, lo: float, hi: float) -> None:
    x = np.geomspace(lo, hi, 400)
    p = np.array([f.probability(x) for f in fits])
    for k in range(len(fits) - 1):
        bad = np.flatnonzero(p[k + 1] > p[k] + 1e-12)
        if bad.size:
            raise ParameterError(
                f"method='separate': the curves of {fits[k].label} and {fits[k + 1].label} "
                f"cross at im = {x[bad[0]]:.4g} within the data's IM range; use "
                "method='common_beta'")


__all__ = ["DEFAULT_THRESHOLDS", "FragilityCurves", "FragilityFit", "damage_state",
           "fragility_curves", "state_labels"]
