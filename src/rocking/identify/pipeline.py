"""Free-rocking identification as a pipeline of named stages (:func:`free_rocking`).

1. input: check the record and the options, estimate the noise (:mod:`.record`);
2. offset: remove the rest level (:mod:`.offset`);
3. events: half-cycles, coarse peaks and crossings, the usable run (:mod:`.events`);
4. a first ``(alpha, p)`` from the coarse times (Eq 13, unweighted; :mod:`.fits`);
5. refinement: exact half-cycle fits (:mod:`.shape`, :mod:`.release`) alternating with
   weighted Eq 13 on the measured times (:mod:`.timing`, :mod:`.fits`) until ``alpha`` and
   ``p`` settle;
6. uncertainties (Jacobian or bootstrap) and ``mu_n`` from Eq 12 (:mod:`.fits`);
7. the result (:class:`.result.FreeRockingFit`).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import IdentificationError, ParameterError
from .events import Events, amplitude_threshold, find_events, usable_run
from .fits import coarse_alpha_p, covariance, fit_times, restitution, uncertainties
from .offset import offset_found, remove_offset
from .record import Record, check_record
from .release import Release, find_release
from .result import FreeRockingFit
from .shape import Lobe, LobeFit, shape_fits
from .time_model import scaled_quarter_time
from .timing import HalfCycleTimes

_LOSSES = ("linear", "soft_l1", "huber", "cauchy", "arctan")
_MAX_PASSES = 6  # of the alternation of half-cycle fits and Eq 13


def free_rocking(t, theta, *, units: str = "rad", offset="auto", min_amplitude=None,
                 use_release: bool = True, loss: str = "soft_l1", n_boot: int = 0,
                 seed=None) -> FreeRockingFit:
    """Identify ``alpha``, ``p`` and ``mu`` of the classical model from a free-rocking record.

    Parameters
    ----------
    t, theta : array_like
        Sample times (s, strictly increasing; any rate, e.g. 50-1000 Hz) and rocking angle
        (in ``units``). The record may start anywhere: at rest or during a hold before the
        release, or mid-swing (an incomplete first half-cycle is used only if its peak is
        recorded); it may end at rest or while the block still rocks (then with enough
        peaks for the centre of the oscillation, or with ``offset`` given).
    units : {"rad", "deg"}
        Units of ``theta``. Results are always in rad.
    offset : "auto", "rest", "symmetric" or float
        Constant offset of the record: the level where the record ends at rest
        (``"rest"``), the centre of the oscillation from successive signed peaks
        (``"symmetric"``), ``"auto"`` (rest if the record ends at rest, else symmetric),
        or a known value in ``units`` (``FreeRockingFit.offset`` is in rad). A record that
        neither ends at rest nor has peaks enough for the centre (two windows of four
        successive peaks above 10 % of the largest, besides the first and last) is
        refused: give the offset.
    use_release : bool
        Also use the first, incomplete half-cycle when its peak is in the record (a
        release from rest, possibly after a hold): its fall time ``T(r_0)``, at the largest
        amplitude, is the most informative on ``alpha``. It is skipped when the record
        starts after that peak.
    min_amplitude : float, optional
        Smallest half-cycle amplitude used (in ``units``); by default
        ``max(15 noise std, 2 % of the largest amplitude)``.
    loss : str
        Loss of the final least-squares (``"soft_l1"``, ``"huber"``, ``"cauchy"`` or
        ``"linear"``; see :func:`scipy.optimize.least_squares`).
    n_boot : int
        If > 0, ``alpha_std`` and ``p_std`` come from a bootstrap over half-cycles with
        ``n_boot`` resamples (``seed`` for the generator) instead of the Jacobian.

    Returns
    -------
    FreeRockingFit
        ``alpha`` (rad), ``p`` (1/s), ``mu`` and their uncertainties, ``mu_n``, the peaks
        and crossings used, the residuals; ``summary()``, ``to_block()``,
        ``plot_error_surface()``, ``plot_fit()``.

    Raises
    ------
    IdentificationError
        No rocking, fewer than three usable half-cycles (e.g. no impact or one impact),
        a rest level (offset) that cannot be found (give ``offset``), or an error surface
        without an interior minimum (alpha not identifiable).
    ParameterError
        Malformed input: NaN or inf samples, non-increasing times, mismatched lengths.

    Examples
    --------
    Identify specimen 2 back from its own simulated free rocking (classical model,
    500 Hz): the fit recovers the parameters it was simulated with.

    >>> import rocking
    >>> from rocking.identify import free_rocking
    >>> block = rocking.specimen(2)
    >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
    >>> fit = free_rocking(r.t, r.theta)
    >>> round(fit.alpha, 3), round(fit.p, 2), round(fit.mu, 3)
    (0.168, 3.81, 0.958)
    >>> (block.alpha, block.p, block.mu)
    (0.168, 3.81, 0.958)
    """
    rec, n_boot = _read_input(t, theta, units, loss, n_boot)
    z, c, method = remove_offset(rec, offset)
    ev = find_events(rec, z, c)
    r_min = amplitude_threshold(rec, ev, min_amplitude)
    k0, k1 = usable_run(rec, ev, r_min)
    offset_found(rec, method)
    alpha, p = coarse_alpha_p(ev.amp[k0:k1], ev.tpk[k0:k1], ev.cross[k0 - 1:k1])
    release = find_release(rec, rec.ym - c, ev, k0, p) if use_release else None
    times, alpha, p = _refine(rec, z, ev, range(k0, k1), release, r_min, alpha, p, loss)
    cov, how = uncertainties(times, alpha, p, n_boot, seed)
    nimp, mu_n, mu, mu_std = restitution(times.amp, times.ks, alpha)
    alpha_std, p_std = (float(math.sqrt(max(cov[i, i], 0.0))) for i in range(2))
    Tm = scaled_quarter_time(times.amp, alpha) / p
    return FreeRockingFit(
        alpha=alpha, p=p, mu=mu, alpha_std=alpha_std, p_std=p_std, mu_std=mu_std,
        mu_n=mu_n, peak_times=times.tpk, peak_values=ev.sign[times.ks] * times.amp,
        crossing_times=times.cr, offset=c,
        residuals=np.column_stack((times.rise - Tm, times.fall - Tm)), impact_numbers=nimp,
        crossing_std=np.sqrt(times.cv), weights=times.wk, cov=cov, noise=rec.sigma,
        sampling_rate=1.0 / rec.dt, offset_method=method, min_amplitude=r_min,
        uncertainty=how, n_lobes_found=int(ev.sign.size), release=times.release,
        t=rec.t, theta=z,
    )


def _read_input(t, theta, units: str, loss: str, n_boot) -> tuple[Record, int]:
    """Stage 1: the checked record in rad with its noise level, and the checked options."""
    t, y = check_record(t, theta, units)
    if loss not in _LOSSES:
        raise ParameterError(f"loss must be one of {', '.join(_LOSSES)}; got {loss!r}")
    n_boot = int(n_boot)
    return Record.measure(t, y, units), n_boot


def _refine(rec: Record, z, ev: Events, run: range, release: Release | None, r_min: float,
            alpha: float, p: float, loss: str) -> tuple[HalfCycleTimes, float, float]:
    """Stage 5: alternate the exact half-cycle fits at the current ``alpha`` with the
    weighted Eq 13 fit of the times they give, until ``alpha`` and ``p`` settle (two or
    three passes; at most six). Returns the final times and ``(alpha, p)``."""
    lobes = [_run_lobe(ev, k, p, rec.dt) for k in run]
    x0 = None  # the first Eq 13 fit searches globally, the next ones start from the last
    for _ in range(_MAX_PASSES):
        fits = _fit_half_cycles(rec, z, ev, run, lobes, release, alpha, r_min)
        times = HalfCycleTimes.from_fits(sorted(fits), fits, rec.dt)  # the release is lobe 0
        sol = fit_times(times, loss, x0=x0)
        a_new, p_new = float(sol.x[0]), float(sol.x[1])
        cov = covariance(times, a_new, p_new)
        tol_a = max(0.03 * math.sqrt(max(cov[0, 0], 0.0)), 1e-7 * a_new)
        tol_p = max(0.03 * math.sqrt(max(cov[1, 1], 0.0)), 1e-7 * p_new)
        done = abs(a_new - alpha) < tol_a and abs(p_new - p) < tol_p
        alpha, p = a_new, p_new
        if done:
            break
        x0 = (alpha, p)
        for lb, k in zip(lobes, run, strict=True):  # warm start of the next pass
            if k in fits:
                lb.tp, lb.r, lb.p = fits[k].tp, min(fits[k].r, alpha * (1 - 1e-6)), fits[k].p
    return times, alpha, p


def _run_lobe(ev: Events, k: int, p: float, dt: float) -> Lobe:
    """The window of half-cycle ``k`` for its shape fit: between its coarse crossings, kept
    3 of their std (and 0.1 sample) away from them; started at its coarse peak."""
    dl = 3.0 * math.sqrt(ev.cvar[k - 1]) + 0.1 * dt
    dh = 3.0 * math.sqrt(ev.cvar[k]) + 0.1 * dt
    return Lobe(int(ev.sign[k]), ev.cross[k - 1] + dl, ev.cross[k] - dh, float(ev.tpk[k]),
                 float(ev.amp[k]), p)


def _fit_half_cycles(rec: Record, z, ev: Events, run: range, lobes: list[Lobe],
                     release: Release | None, alpha: float, r_min: float) -> dict[int, LobeFit]:
    """Exact-shape fits at ``alpha`` of the run and the release: ``{lobe index: fit}``.

    A half-cycle of the run is kept if its fit worked and its amplitude is within 20 % of
    the coarse one; the release (lobe 0) if its fit is plausible. At least three
    half-cycles of the run are needed.
    """
    extra = release.lobes if release is not None else []
    res = shape_fits(rec.t, z, lobes + extra, alpha, rec.sig)
    fits = {k: f for k, f in zip(run, res[:len(lobes)], strict=True)
            if f is not None and abs(f.r / ev.amp[k] - 1.0) < 0.2}
    if len(fits) < 3:
        raise IdentificationError("fewer than three half-cycles could be fitted")
    if release is not None:
        rel = release.accept(res[len(lobes):], rec, alpha, r_min, ev.amp[1])
        if rel is not None:
            fits[0] = rel
    return fits
