r"""Selection of amplitude-scaled records that match a target spectrum (issue 21).

EN 1998-1 §3.2.3.1.2 asks for a set of records (at least 3; 7 to use the mean response)
whose **mean** 5 %-damped elastic spectrum is **not below 90 %** of the target spectrum at
any period of the range of interest. :func:`select_records` chooses ``n`` of the candidates,
each multiplied by its own amplitude scale factor ``s_i`` in ``[1/max_scale, max_scale]``:

1. the pseudo-acceleration spectrum of every candidate (m/s^2, 5 % damping,
   :func:`rocking.motions.spectra.response_spectrum`: one compiled call per record for all
   periods) is computed once; a 2-D array of precomputed spectra is accepted instead;
2. forward (greedy) selection: records are added one at a time, each the one that gives
   the least misfit of the running mean, at the better of two scales (its own best
   scale, the geometric-mean ratio ``exp(mean ln(target / S_i))``, or the scale that best
   fills the gap between the running sum and the target); all candidates at once,
   vectorised over candidates and periods;
3. the ``n`` scale factors are refined jointly (bounded least squares on ``ln s``), then
   one selected record is swapped for an unselected one while that lowers the misfit,
   with a joint refinement after each pass of swaps; the whole search is repeated from
   each of the ``restarts`` best single records (default 8) and the best set kept, then
   polished by swaps judged after a joint refinement of all scales;
4. (the scales stay in ``[1/max_scale, max_scale]`` throughout);
5. if the mean falls below 90 % of the target somewhere, all factors are multiplied by a
   common factor that lifts the minimum ratio to 0.9, when the bounds allow it; otherwise
   the factors are raised individually, changed least (sum of relative changes, a linear
   program: the mean is linear in the factors), when any factors within the bounds meet
   the rule; and if none do, the compliant set of ``n`` candidates closest to the target
   (least sum of ``|mean/target - 1|``) is sought among all of them by a mixed-integer
   linear program, so that a set is flagged non-compliant only when no compliant set
   exists.

The misfit is the root-mean-square log ratio over the periods
``sqrt(mean_k ln(mean_k / target_k)^2)`` (0 for a perfect match; 0.1 is about 10 %).
When no factor within ``max_scale`` can honour the 90 % rule the set is returned with
``compliant=False`` and a :class:`~rocking.errors.PlausibilityWarning` (the factors then
those that maximise the worst ratio within ``max_scale``, again a linear program): never a
silently non-compliant set. The search is a heuristic (the exact problem is
combinatorial): it finds a set that matches the target exactly when one exists among
well-separated distractors (``tests/test_selection.py``), not a proven optimum in general.

**The period range of a rocking block** (:func:`default_periods`) is not a structural
period. The overturning spectra of :mod:`rocking.analysis.overturning` (Dimitrakopoulos
and DeJong 2012) are functions of ``omega_p / p`` only: a pulse of period ``T_p = 2 pi /
omega_p`` overturns the block at an acceleration close to the static ``g tan alpha`` when
``omega_p / p`` is below about 1 (long pulses: the block sees a slowly varying tilt), and
at an acceleration that grows fast above it. For specimen 2 under one-sine pulses
(Housner's model; ``overturning_spectrum(specimen(2), "one_sine", ...)``) the least
overturning ``a_p / (g tan alpha)`` is 1.04, 1.10, 1.22, 1.7, 8.0 and 14 at ``omega_p / p``
= 0.5, 1, 2, 4, 8 and 10, and above 20 at 15: beyond ``omega_p / p`` of about 10 the
required acceleration exceeds what earthquakes provide.
The spectral ordinates that govern overturning are therefore those at periods from ``2 pi
/ (10 p)`` to ``2 pi / p`` (and a little beyond, where the quasi-static bound holds): the
default range is ``[2 pi / (omega_ratio_max p), 2 pi / (omega_ratio_min p)]`` with
``omega_ratio_max = 10`` and ``omega_ratio_min = 1``, log-spaced.
"""

from __future__ import annotations

import math
import re
import warnings
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares, linprog

from .._validate import as_float, as_int, positive
from ..errors import ParameterError, PlausibilityWarning, UnitError
from ..motions.base import is_sampled
from ..motions.spectra import response_spectrum
from ..units import acceleration_factor
from .hazard import HazardCurve

__all__ = ["select_records", "SelectionResult", "default_periods", "candidate_spectra",
           "log_misfit", "uniform_hazard_spectrum", "CODE_RATIO"]

CODE_RATIO = 0.9
"""EN 1998-1 §3.2.3.1.2: the mean spectrum not below 90 % of the target in the range."""


def default_periods(block, n: int = 100, omega_ratio_min: float = 1.0,
                    omega_ratio_max: float = 10.0) -> np.ndarray:
    """``n`` log-spaced periods (s) from ``2 pi / (omega_ratio_max p)`` to ``2 pi /
    (omega_ratio_min p)``: the pulse periods that govern a block's overturning (module doc).

    ``block`` is a :class:`~rocking.blocks.Block` (its ``p``, 1/s) or ``p`` itself.

    Examples
    --------
    The pulse periods ``2 pi / omega_p`` for ``omega_p / p`` from 10 down to 1:

    >>> import math
    >>> import rocking
    >>> from rocking.analysis import default_periods
    >>> block = rocking.specimen(2)  # p = 3.81 1/s
    >>> T = default_periods(block, n=5)
    >>> T.round(3).tolist()
    [0.165, 0.293, 0.522, 0.927, 1.649]
    >>> bool(np.isclose(T[-1], 2 * math.pi / block.p))
    True
    """
    p = getattr(block, "p", block)
    try:
        p = positive("block", p, "1/s (the block's frequency parameter p)")
    except ParameterError:
        raise ParameterError(f"block must be a Block or its p > 0 (1/s); got {block!r}") from None
    n = as_int("n", n, lo=2)
    lo = positive("omega_ratio_min", omega_ratio_min)
    hi = positive("omega_ratio_max", omega_ratio_max)
    if not hi > lo:
        raise ParameterError(f"omega_ratio_max must be > omega_ratio_min = {lo:g}; got {hi!r}")
    return np.geomspace(2.0 * math.pi / (hi * p), 2.0 * math.pi / (lo * p), n)


_SA = re.compile(r"^\s*(?:SA|PSA|Sa)\s*\(\s*([0-9.eE+-]+)\s*\)\s*$")


def uniform_hazard_spectrum(curves, return_period: float = 475.0):
    """The uniform hazard spectrum ``(periods, values)`` (s, m/s^2) of SA hazard curves.

    ``curves`` is a list of :class:`~rocking.analysis.hazard.HazardCurve` of spectral
    acceleration, each named ``"SA(T)"`` (OpenQuake's IMT names; T in s), or a dict
    ``{T: curve}``; a ``"PGA"`` curve is left out (T = 0 has no log). At each period the
    value exceeded at the rate ``1 / return_period`` (years) is read off the curve
    (:meth:`HazardCurve.im_at_return_period`). The result is a table for
    :func:`select_records`'s ``target_spectrum`` (log-log interpolated, no extrapolation:
    the curves' periods must cover the periods of the match). A return period beyond a
    curve's rates is read off its power-law tail, with a
    :class:`~rocking.errors.PlausibilityWarning`.

    Examples
    --------
    Three SA hazard curves (EN 1998-1 power laws through the values at 475 years): the
    spectrum at 475 years is those values, in m/s^2:

    >>> from rocking.analysis import HazardCurve, uniform_hazard_spectrum
    >>> curves = [HazardCurve.from_code_value(a, im_name=f"SA({T})")  # a in g
    ...           for T, a in ((0.1, 0.5), (0.5, 0.6), (1.0, 0.3))]
    >>> periods, values = uniform_hazard_spectrum(curves, return_period=475)
    >>> periods.tolist(), (values / 9.80665).round(6).tolist()
    ([0.1, 0.5, 1.0], [0.5, 0.6, 0.3])
    """
    tr = positive("return_period", return_period, "years")
    items = list(curves.items()) if isinstance(curves, dict) else [(None, c) for c in
                                                                   curves]
    pts = {}
    for T, c in items:
        if not isinstance(c, HazardCurve):
            raise ParameterError(f"curves must be HazardCurves; got {type(c).__name__}")
        if T is None:
            if c.im_name.strip().upper() == "PGA":
                continue
            m = _SA.match(c.im_name)
            if not m:
                raise ParameterError(f"curves: cannot read a period from im_name "
                                     f"{c.im_name!r} (expected 'SA(0.2)'); pass a dict "
                                     "{period: curve}")
            T = float(m[1])
        T = positive("curves (period)", T, "s")
        try:
            cs = c.to_unit("m/s^2")
        except ParameterError:
            raise ParameterError(f"curves: the curve at T = {T:g} s is not in an "
                                 f"acceleration unit ({c.unit!r})") from None
        if T in pts:
            raise ParameterError(f"curves: two curves for the period {T:g} s")
        if not cs.rate.min() <= 1.0 / tr <= cs.rate.max():
            warnings.warn(f"uniform_hazard_spectrum: 1/{tr:g} per year is beyond the rates "
                          f"of the curve at T = {T:g} s ({cs.rate.min():.3g} to "
                          f"{cs.rate.max():.3g}): its value is extrapolated along the "
                          "curve's power-law tail", PlausibilityWarning, stacklevel=2)
        pts[T] = cs.im_at_return_period(tr)
    if len(pts) < 2:
        raise ParameterError("curves must hold SA curves at >= 2 periods > 0")
    P = np.array(sorted(pts))
    return P, np.array([pts[t] for t in P])


def _periods(periods) -> np.ndarray:
    try:
        T = np.asarray(periods, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError("periods must be numbers (s) > 0") from None
    if T.ndim != 1 or T.size < 2:
        raise ParameterError(f"periods must be a 1-D array of at least 2 periods (s); got "
                             f"shape {T.shape}")
    if not np.all(np.isfinite(T)) or np.any(T <= 0.0):
        raise ParameterError("periods must be finite and > 0 s (the misfit is in log)")
    return T


def _target(target, T: np.ndarray, unit: str) -> np.ndarray:
    """The target in m/s^2 at ``T`` from an array, a callable or a (periods, values) table."""
    try:
        f = acceleration_factor(unit)
    except UnitError:
        raise ParameterError(f"target_unit must be an acceleration unit (m/s^2, g, cm/s^2, "
                             f"gal); got {unit!r}") from None
    if callable(target):
        vals = target(T)
    elif isinstance(target, tuple) and len(target) == 2:
        try:
            tp = np.asarray(target[0], dtype=np.float64)
            tv = np.asarray(target[1], dtype=np.float64)
        except (TypeError, ValueError):
            raise ParameterError("target_spectrum table must be (periods, values) of "
                                 "numbers") from None
        if tp.ndim != 1 or tp.shape != tv.shape or tp.size < 2 or np.any(np.diff(tp) <= 0) \
                or np.any(tp <= 0) or np.any(tv <= 0):
            raise ParameterError("target_spectrum table must be (periods, values): two 1-D "
                                 "arrays of the same length >= 2, periods increasing > 0, "
                                 "values > 0")
        if T[0] < tp[0] * (1 - 1e-12) or T[-1] > tp[-1] * (1 + 1e-12) \
                or T.min() < tp[0] * (1 - 1e-12) or T.max() > tp[-1] * (1 + 1e-12):
            raise ParameterError(f"target_spectrum table covers {tp[0]:g} to {tp[-1]:g} s; "
                                 f"the periods go from {T.min():g} to {T.max():g} s "
                                 "(no extrapolation)")
        vals = np.exp(np.interp(np.log(T), np.log(tp), np.log(tv)))
    else:
        vals = target
    try:
        vals = np.asarray(vals, dtype=np.float64) * f
    except (TypeError, ValueError):
        raise ParameterError("target_spectrum must be numbers, a callable T -> Sa or a "
                             "(periods, values) table") from None
    if vals.shape != T.shape:
        raise ParameterError(f"target_spectrum must have one value per period ({T.size}); "
                             f"got shape {vals.shape}")
    if not np.all(np.isfinite(vals)) or np.any(vals <= 0):
        raise ParameterError("target_spectrum must be finite and > 0 at every period")
    return vals


def candidate_spectra(candidates, periods, damping: float = 0.05) -> np.ndarray:
    """(m, k) pseudo-acceleration spectra (m/s^2) of ``m`` records at ``k`` periods, once
    per record (a 2-D array of precomputed spectra is checked and returned as is)."""
    T = _periods(periods)
    if isinstance(candidates, np.ndarray) and candidates.ndim == 2:
        S = np.asarray(candidates, dtype=np.float64)
        if S.shape[1] != T.size:
            raise ParameterError(f"candidates as precomputed spectra must have one column per "
                                 f"period ({T.size}); got shape {S.shape}")
    else:
        try:
            items = list(candidates)
        except TypeError:
            raise ParameterError("candidates must be a list of Records or an (m, k) array of "
                                 "spectra (m/s^2)") from None
        bad = [i for i, r in enumerate(items) if not is_sampled(r)]
        if bad:
            raise ParameterError(f"candidates must be Records (sampled motions); item "
                                 f"{bad[0]} is {type(items[bad[0]]).__name__}")
        S = np.empty((len(items), T.size))
        for i, r in enumerate(items):
            S[i] = response_spectrum(r, T, damping)
    if not np.all(np.isfinite(S)) or np.any(S <= 0):
        raise ParameterError("candidates: every spectral ordinate must be finite and > 0")
    return S


def log_misfit(mean, target) -> float:
    """Root-mean-square log ratio ``sqrt(mean ln(mean / target)^2)``."""
    d = np.log(np.asarray(mean) / np.asarray(target))
    return float(np.sqrt(np.mean(d * d)))


@dataclass
class SelectionResult:
    """The chosen records: ``indices`` into the candidates, their ``scales``, the ``mean``
    scaled spectrum and ``target`` (m/s^2) at ``periods`` (s), the ``misfit`` (RMS log
    ratio), ``min_ratio`` (min of mean / target) and ``compliant`` (min_ratio >= 0.9 with
    every scale within ``max_scale``); ``notes`` says what was adjusted (the common factor)
    and what the code would also ask (at least 3 records).

    Examples
    --------
    Three candidates' spectra (m/s^2) at 0.2, 0.5 and 1 s; the second, doubled, is the
    target:

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from rocking.analysis import select_records
    >>> target = np.array([6.0, 5.0, 2.5])
    >>> spectra = np.array([[6.0, 4.0, 1.0], [3.0, 2.5, 1.25], [2.0, 2.0, 2.0]])
    >>> sel = select_records(spectra, target, [0.2, 0.5, 1.0], n=1)
    >>> sel.indices.tolist(), sel.scales.tolist(), sel.min_ratio, sel.compliant
    ([1], [2.0], 1.0, True)
    >>> type(sel.plot()).__name__
    'Axes'
    """

    indices: np.ndarray
    scales: np.ndarray
    periods: np.ndarray
    target: np.ndarray
    mean: np.ndarray
    spectra: np.ndarray
    misfit: float
    min_ratio: float
    compliant: bool
    max_scale: float
    notes: list = field(default_factory=list)

    def records(self, candidates) -> list:
        """The selected candidates, each scaled (``Record.scaled``) by its factor.

        Examples
        --------
        The target is the spectrum of the second record, doubled:

        >>> from rocking.analysis import select_records
        >>> from rocking.analysis.selection import candidate_spectra
        >>> from rocking.motions import Record
        >>> t, T = np.arange(0.0, 4.0, 0.01), [0.2, 0.5, 1.0]  # s
        >>> recs = [Record(np.sin(2 * np.pi * f * t) * np.exp(-t), 0.01) for f in (1, 2, 4)]
        >>> sel = select_records(recs, 2.0 * candidate_spectra(recs, T)[1], T, n=1)
        >>> sel.indices.tolist(), sel.scales.tolist()
        ([1], [2.0])
        >>> chosen = sel.records(recs)
        >>> chosen[0].scale, bool(np.allclose(chosen[0].values, 2.0 * recs[1].values))
        (2.0, True)
        """
        return [candidates[i].scaled(s) for i, s in zip(self.indices, self.scales, strict=True)]

    def plot(self, ax=None):
        """Target, 90 % of it, the scaled spectra and their mean; returns the Axes.

        Examples
        --------
        >>> from rocking.analysis import select_records
        >>> from rocking.analysis.selection import candidate_spectra
        >>> from rocking.motions import Record
        >>> t, T = np.arange(0.0, 4.0, 0.01), [0.2, 0.5, 1.0]  # s
        >>> recs = [Record(np.sin(2 * np.pi * f * t) * np.exp(-t), 0.01) for f in (1, 2, 4)]
        >>> sel = select_records(recs, 2.0 * candidate_spectra(recs, T)[1], T, n=1)
        >>> ax = sel.plot()
        >>> ax.get_xlabel(), ax.get_title()
        ('period T (s)', 'record selection (EN 1998-1 3.2.3.1.2)')
        >>> [t.get_text() for t in ax.get_legend().get_texts()]  # the target met exactly
        ['target', '90 % target', 'mean of 1 (misfit 0.000)']
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        for s in self.spectra:
            ax.loglog(self.periods, s, color="0.75", lw=0.8)
        ax.loglog(self.periods, self.target, "k-", lw=2, label="target")
        ax.loglog(self.periods, CODE_RATIO * self.target, "k--", lw=1, label="90 % target")
        ax.loglog(self.periods, self.mean, "C3-", lw=2,
                  label=f"mean of {len(self.indices)} (misfit {self.misfit:.3f})")
        ax.set_xlabel("period T (s)")
        ax.set_ylabel("Sa (m/s^2), 5 % damping")
        title = "record selection (EN 1998-1 3.2.3.1.2)"
        if not self.compliant:
            title += ": NOT compliant"
        ax.set_title(title)
        ax.legend()
        return ax


def _step_costs(lt, t, S, own, base, j, lo, hi):
    """Cost (mean squared log misfit) and scale of adding each candidate to ``base`` (the
    sum of the other ``j - 1`` scaled spectra): the better of the record's own best scale
    and the scale that best fills the gap ``j t - base`` (least squares relative to t)."""
    R = S / t
    g = j - base / t
    fill = np.exp(np.clip(np.log(np.maximum((R @ g) / np.sum(R * R, axis=1), 1e-300)),
                          lo, hi))
    best_c = best_s = None
    for sc in (own, fill):
        d = np.log((base + sc[:, None] * S) / j) - lt
        c = np.mean(d * d, axis=1)
        if best_c is None:
            best_c, best_s = c, sc.copy()
        else:
            better = c < best_c
            best_c = np.where(better, c, best_c)
            best_s = np.where(better, sc, best_s)
    return best_c, best_s


def _refine(lt, S, idx, x0, lo, hi):
    """Joint bounded least squares on the ln of the selected records' scales."""
    Ssel = S[idx]
    n = len(idx)

    def resid(x):
        return np.log(np.exp(x) @ Ssel / n) - lt

    if not hi > 0:
        return x0
    x = least_squares(resid, np.clip(x0, lo, hi), bounds=(lo, hi), xtol=1e-14, ftol=1e-14,
                      gtol=1e-14).x
    return x if np.sum(resid(x) ** 2) <= np.sum(resid(x0) ** 2) else x0


def _pinned_note(scales, max_scale: float, mean, target) -> str | None:
    """A note when scale factors sit at a limit (``1/max_scale`` or ``max_scale``): the
    match is then the limit's, not the target's (a target far below or above every
    record). None when none does, or when ``max_scale`` is 1 (no scaling asked)."""
    if max_scale <= 1.0:
        return None
    low = int(np.sum(scales <= (1.0 / max_scale) * (1 + 1e-9)))
    high = int(np.sum(scales >= max_scale * (1 - 1e-9)))
    if not (low or high):
        return None
    n = len(scales)
    r = np.asarray(mean) / np.asarray(target)
    parts = []
    if low:
        parts.append(f"{'all' if low == n else low} of the {n} scale factors at the lower "
                     f"limit 1/max_scale = {1.0 / max_scale:.4g} (the records are stronger "
                     "than the target even scaled down that far)")
    if high:
        parts.append(f"{'all' if high == n else high} of the {n} scale factors at the upper "
                     f"limit max_scale = {max_scale:.4g} (the records are weaker than the "
                     "target even scaled up that far)")
    return ("; ".join(parts) + f": the mean is {r.min():.4g} to {r.max():.4g} times the "
            "target, the match is limited by max_scale")


def _search(lt, S, own, n, lo, hi, first=None):
    """Forward selection (from record ``first`` if given), then single swaps and joint
    refinement while they help; returns (indices, ln scales, cost)."""
    t = np.exp(lt)
    m = S.shape[0]
    idx: list[int] = []
    x: list[float] = []
    free = np.ones(m, dtype=bool)
    total = np.zeros(lt.size)
    for j in range(1, n + 1):
        cost, sc = _step_costs(lt, t, S, own, total, j, lo, hi)
        cost[~free] = np.inf
        i = int(np.argmin(cost)) if (j > 1 or first is None) else int(first)
        idx.append(i)
        x.append(math.log(sc[i]))
        free[i] = False
        total = total + sc[i] * S[i]
    xs = np.array(x)

    def cost_of(xs):
        return float(np.mean((np.log(np.exp(xs) @ S[idx] / n) - lt) ** 2))

    xs = _refine(lt, S, idx, xs, lo, hi)
    best = cost_of(xs)
    for _ in range(20):  # outer passes: swaps, then a joint refinement
        swapped = False
        for pos in range(n):
            total = np.exp(xs) @ S[idx]
            base = total - math.exp(xs[pos]) * S[idx[pos]]
            cost, sc = _step_costs(lt, t, S, own, base, n, lo, hi)
            cost[~free] = np.inf
            i = int(np.argmin(cost))
            if cost[i] < best * (1 - 1e-9) - 1e-30:
                free[idx[pos]] = True
                free[i] = False
                idx[pos] = i
                xs[pos] = math.log(sc[i])
                best = float(cost[i])
                swapped = True
        if not swapped:
            break
        xs = _refine(lt, S, idx, xs, lo, hi)
        best = cost_of(xs)
    return np.array(idx), xs, best


def _polish(lt, S, own, idx, xs, best, lo, hi, top: int = 8):
    """Swaps judged after a joint refinement: for each selected record the ``top`` best
    replacements (by the cheap swap cost) are tried with all scales re-fitted."""
    t = np.exp(lt)
    n = len(idx)
    idx = list(idx)
    free = np.ones(S.shape[0], dtype=bool)
    free[idx] = False
    for _ in range(10):
        improved = False
        for pos in range(n):
            base = np.exp(xs) @ S[idx] - math.exp(xs[pos]) * S[idx[pos]]
            cost, sc = _step_costs(lt, t, S, own, base, n, lo, hi)
            cost[~free] = np.inf
            for i in np.argsort(cost, kind="stable")[:top]:
                if not np.isfinite(cost[i]):
                    break
                trial = idx.copy()
                trial[pos] = int(i)
                x0 = xs.copy()
                x0[pos] = math.log(sc[i])
                x1 = _refine(lt, S, trial, x0, lo, hi)
                c = float(np.mean((np.log(np.exp(x1) @ S[trial] / n) - lt) ** 2))
                if c < best * (1 - 1e-9) - 1e-30:
                    free[idx[pos]] = True
                    free[i] = False
                    idx, xs, best, improved = trial, x1, c, True
                    break
        if not improved:
            break
    return np.array(idx), xs


def _comply(R: np.ndarray, s0: np.ndarray, max_scale: float) -> tuple[np.ndarray, bool]:
    """Scale factors in ``[1/max_scale, max_scale]`` whose mean ``s @ R / n`` (``R`` the
    spectra over the target, n x periods) is >= 0.9 at every period, changed least from
    ``s0`` (sum of ``|s_i - s0_i| / s0_i``): a linear program, since the mean is linear in
    the factors. If none exists, the factors that maximise the worst ratio, and False."""
    n, k = R.shape
    lo, hi = 1.0 / max_scale, max_scale
    goal = CODE_RATIO * (1 + 1e-9)
    # variables (s, d): min sum d_i / s0_i with |s_i - s0_i| <= d_i and -R^T s / n <= -goal
    eye = np.eye(n)
    A = np.vstack([np.hstack([eye, -eye]), np.hstack([-eye, -eye]),
                   np.hstack([-R.T / n, np.zeros((k, n))])])
    b = np.concatenate([s0, -s0, np.full(k, -goal)])
    res = linprog(np.concatenate([np.zeros(n), 1.0 / s0]), A_ub=A, b_ub=b,
                  bounds=[(lo, hi)] * n + [(0, None)] * n, method="highs")
    if res.status == 0:
        return np.clip(res.x[:n], lo, hi), True
    # variables (s, r): max r with r - R^T s / n <= 0
    A = np.hstack([-R.T / n, np.ones((k, 1))])
    res = linprog(np.concatenate([np.zeros(n), [-1.0]]), A_ub=A, b_ub=np.zeros(k),
                  bounds=[(lo, hi)] * n + [(0, None)], method="highs")
    if res.status != 0:  # cannot happen (s = hi, r = 0 is feasible); keep the factors
        return np.clip(s0, lo, hi), False
    return np.clip(res.x[:n], lo, hi), False


def _compliant_set(R: np.ndarray, n: int, max_scale: float, time_limit: float = 3.0):
    """``(indices, scales, proven)`` of ``n`` of the candidates (``R``: spectra over the
    target, m x periods) whose mean is >= 0.9 of the target at every period with every
    factor in ``[1/max_scale, max_scale]``, with the least sum of ``|mean / target - 1|``:
    a mixed-integer linear program (HiGHS). Within ``time_limit`` s the best set found is
    returned (``proven`` False: compliant, not proven the closest; 500 candidates over 100
    periods do not finish in 20 s, but a compliant set is found well within 1 s);
    ``"none"`` if no such set exists (proven), ``"timeout"`` if none was found in time."""
    from scipy.optimize import Bounds, LinearConstraint, milp

    m, k = R.shape
    lo, hi = 1.0 / max_scale, max_scale
    goal = CODE_RATIO * (1 + 1e-9)
    # variables: s (m), z (m, binary), e (k): min sum e, mean_k = R[:, k] @ s / n
    nv = 2 * m + k
    cost = np.concatenate([np.zeros(2 * m), np.ones(k)])
    eye_m, eye_k = np.eye(m), np.eye(k)
    zeros_mk = np.zeros((m, k))
    A = [np.hstack([eye_m, -lo * eye_m, zeros_mk]),          # s - lo z >= 0
         np.hstack([eye_m, -hi * eye_m, zeros_mk]),          # s - hi z <= 0
         np.concatenate([np.zeros(m), np.ones(m), np.zeros(k)])[None, :],  # sum z = n
         np.hstack([R.T / n, np.zeros((k, m)), np.zeros((k, k))]),        # mean >= 0.9
         np.hstack([R.T / n, np.zeros((k, m)), -eye_k]),     # mean - e <= 1
         np.hstack([R.T / n, np.zeros((k, m)), eye_k])]      # mean + e >= 1
    lb = np.concatenate([np.zeros(m), np.full(m, -np.inf), [n], np.full(k, goal),
                         np.full(k, -np.inf), np.ones(k)])
    ub = np.concatenate([np.full(m, np.inf), np.zeros(m), [n], np.full(k, np.inf),
                         np.ones(k), np.full(k, np.inf)])
    integrality = np.concatenate([np.zeros(m), np.ones(m), np.zeros(k)])
    bounds = Bounds(np.zeros(nv), np.concatenate([np.full(m, hi), np.ones(m),
                                                  np.full(k, np.inf)]))
    res = milp(cost, constraints=LinearConstraint(np.vstack(A), lb, ub),
               integrality=integrality, bounds=bounds,
               options={"time_limit": time_limit})
    if res.x is None:  # status 2: proven infeasible; else no solution within the limit
        return "none" if res.status == 2 else "timeout"
    z = res.x[m:2 * m] > 0.5
    if int(z.sum()) != n:
        return "timeout"
    idx = np.flatnonzero(z)
    scales = np.clip(res.x[:m][idx], lo, hi)
    if np.min(scales @ R[idx] / n) < CODE_RATIO * (1 - 1e-9):
        return "timeout"
    return idx, scales, res.status == 0


def select_records(candidates, target_spectrum, periods=None, n: int = 11,
                   max_scale: float = 4.0, *, block=None, target_unit: str = "m/s^2",
                   damping: float = 0.05, restarts: int = 8) -> SelectionResult:
    """``n`` amplitude-scaled records whose mean spectrum matches a target (module doc).

    Parameters
    ----------
    candidates : list of Record or array (m, k)
        Records (their 5 %-damped pseudo-acceleration spectra, m/s^2, are computed once),
        or their precomputed spectra at ``periods``.
    target_spectrum : array, callable or (periods, values)
        The target over ``periods``: one value per period, a callable ``T -> Sa`` (e.g.
        :class:`rocking.motions.ec8.DesignSpectrum`), or a table interpolated in log-log
        (e.g. :func:`uniform_hazard_spectrum` of SA hazard curves).
    periods : array of float, optional
        Periods (s) > 0 of the match; default :func:`default_periods` of ``block``.
    n : int
        Number of records (1 to the number of candidates; EN 1998-1 asks for >= 3).
    max_scale : float
        Scale factors are kept within ``[1/max_scale, max_scale]`` (>= 1).
    block : Block, optional
        For the default period range.
    target_unit : str
        Unit of the target's values: ``"m/s^2"`` (default), ``"g"``, ``"cm/s^2"``...
    damping : float
        Damping ratio of the spectra (0.05; the target must refer to the same).
    restarts : int
        The search is repeated from each of the ``restarts`` best first records; the set
        of least misfit is kept (>= 1; more is slower and rarely better).

    Returns
    -------
    SelectionResult
        ``compliant=False`` (with a PlausibilityWarning) if the 90 % rule cannot be met
        within ``max_scale``.

    Examples
    --------
    Precomputed spectra (m/s^2) of seven candidates at three periods: five of other shapes
    and two with the target's shape (half and 1.5 times it). The pair of those two, scaled
    by 2 and 2/3, matches the target exactly:

    >>> from rocking.analysis import select_records
    >>> periods = np.array([0.2, 0.5, 1.0])  # s
    >>> target = np.array([6.0, 5.0, 2.5])  # m/s^2
    >>> rng = np.random.default_rng(1)
    >>> others = target * np.exp(rng.normal(0.0, 0.5, (5, 3)))
    >>> spectra = np.vstack([others, target / 2.0, 1.5 * target])
    >>> sel = select_records(spectra, target, periods, n=2)
    >>> sel.indices.tolist(), sel.scales.round(4).tolist(), round(sel.misfit, 6)
    ([5, 6], [2.0, 0.6667], 0.0)
    >>> sel.compliant, sel.notes[0][:10]
    (True, 'n = 2 < 3:')
    """
    if periods is None:
        if block is None:
            raise ParameterError("periods (s) must be given, or block= for the default "
                                 "range of a rocking block (default_periods)")
        periods = default_periods(block)
    T = _periods(periods)
    max_scale = as_float("max_scale", max_scale)
    if not (max_scale >= 1.0 and math.isfinite(max_scale)):
        raise ParameterError(f"max_scale must be a finite number >= 1; got {max_scale!r}")
    td = getattr(target_spectrum, "damping", None)
    if td is not None and not math.isclose(float(td), float(damping), rel_tol=1e-9):
        raise ParameterError(f"target_spectrum is for {100 * td:g} % damping but damping = "
                             f"{damping!r}: compare spectra of the same damping "
                             "(DesignSpectrum.with_damping)")
    target = _target(target_spectrum, T, target_unit)
    S = candidate_spectra(candidates, T, damping)
    m = S.shape[0]
    n = as_int("n", n, lo=1)
    if n > m:
        raise ParameterError(f"n must be <= the number of candidates ({m}); got {n}")
    lt = np.log(target)
    lo, hi = -math.log(max_scale), math.log(max_scale)
    own = np.exp(np.clip(np.mean(lt - np.log(S), axis=1), lo, hi))  # each record's own scale
    restarts = as_int("restarts", restarts, lo=1)
    c1, _ = _step_costs(lt, target, S, own, np.zeros(T.size), 1, lo, hi)
    best = None
    for first in np.argsort(c1, kind="stable")[:restarts]:
        trial = _search(lt, S, own, n, lo, hi, first)
        if best is None or trial[2] < best[2] * (1 - 1e-9):
            best = trial
    idx, x, cost = best
    idx, x = _polish(lt, S, own, idx, x, cost, lo, hi)
    Ssel = S[idx]
    scales = np.exp(x)
    mean = scales @ Ssel / n
    notes: list[str] = []
    if n < 3:
        notes.append(f"n = {n} < 3: EN 1998-1 3.2.3.1.2 asks for at least 3 records "
                     "(compliant refers to the 90 % rule only)")
    ratio = float(np.min(mean / target))
    if ratio < CODE_RATIO:
        c = CODE_RATIO / ratio * (1 + 1e-12)
        if np.all(scales * c <= max_scale * (1 + 1e-12)):
            scales = np.minimum(scales * c, max_scale)
            notes.append(f"all factors multiplied by {c:.4g} to meet the 90 % rule")
        else:
            scales, met = _comply(Ssel / target, scales, max_scale)
            if met:
                notes.append("scale factors raised individually (least total relative "
                             "change, a linear program) to meet the 90 % rule")
            else:  # another set may comply: an exact search among all the candidates
                found = _compliant_set(S / target, n, max_scale)
                if found == "none":
                    notes.append("the 90 % rule cannot be met within max_scale by any set "
                                 "of n candidates (a mixed-integer program over all of "
                                 "them): factors chosen to raise the worst ratio as far as "
                                 "they allow")
                elif found == "timeout":
                    notes.append("the 90 % rule cannot be met within max_scale by the "
                                 "least-misfit set, and a mixed-integer program over all "
                                 "candidates found no compliant set within its time limit "
                                 "(not proven that none exists): factors chosen to raise "
                                 "the worst ratio as far as they allow")
                else:
                    idx, scales, proven = found
                    Ssel = S[idx]
                    notes.append("the least-misfit set could not meet the 90 % rule within "
                                 "max_scale: this set does (a mixed-integer program over "
                                 "all candidates, least sum of |mean/target - 1|"
                                 + (")" if proven else "; the best found in its time "
                                    "limit, not proven the closest)"))
        mean = scales @ Ssel / n
        ratio = float(np.min(mean / target))
    compliant = bool(ratio >= CODE_RATIO * (1 - 1e-9))
    if (note := _pinned_note(scales, max_scale, mean, target)) is not None:
        notes.append(note)
    if not compliant:
        warnings.warn(f"select_records: the mean of the {n} selected records is "
                      f"{100 * ratio:.1f} % of the target at worst (< 90 %, EN 1998-1 "
                      f"3.2.3.1.2) with scale factors <= max_scale = {max_scale:g}: the "
                      "set is NOT compliant (result.compliant is False)",
                      PlausibilityWarning, stacklevel=2)
    return SelectionResult(indices=idx, scales=scales, periods=T, target=target, mean=mean,
                           spectra=Ssel * scales[:, None], misfit=log_misfit(mean, target),
                           min_ratio=ratio, compliant=compliant, max_scale=max_scale,
                           notes=notes)
