"""The result of a free-rocking identification: :class:`FreeRockingFit`.

Besides the identified ``alpha``, ``p`` and ``mu`` it keeps what they came from (peaks,
crossings, residuals, weights, the record), so that the Eq 13 error surface can be
re-evaluated (:meth:`FreeRockingFit.error_surface`) and plotted, and the record compared
with the classical model (:meth:`FreeRockingFit.plot_fit`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields

import numpy as np

from ..blocks import Block
from ..errors import IdentificationError, ParameterError
from ..models import simulate
from ..plot import PALETTE, figure, style_axes
from ..results import jsonable
from .time_model import quarter_time, sigma_coefficients, sigma_surface
from .timing import flatten_intervals


@dataclass
class FreeRockingFit:
    """Result of :func:`free_rocking` (rad, s, 1/s).

    ``peak_times``, ``peak_values`` (signed, offset removed) and ``impact_numbers`` describe
    the ``n`` half-cycles used; ``crossing_times`` (``n x 2``) holds the zero crossings
    before and after each (consecutive half-cycles share one). ``residuals`` (``n x 2``)
    are measured minus model rise (crossing to peak) and fall (peak to crossing) times.
    When ``release`` is True the first half-cycle is the release (cut by the start of the
    record): only its fall is timed, and ``crossing_times[0, 0]`` and ``residuals[0, 0]``
    are NaN. ``mu_n`` (Eq 12) has one value per half-cycle after the first, for
    ``n = impact_numbers[1:]`` impacts. ``alpha_std``, ``p_std`` are standard errors
    (``cov`` their covariance); ``mu_std`` is the spread (standard deviation) of ``mu_n``.
    ``offset`` (rad) was removed from the record, ``noise`` (rad) is its estimated noise
    std, ``t`` and ``theta`` keep the record (s; rad, offset removed) for the plots.
    ``weights`` (1/s) weight the rise and fall residuals of each half-cycle in Eq 13.
    :meth:`summary` (the main numbers) and :meth:`to_dict` (all fields) are JSON-ready.

    Examples
    --------
    The fit of a simulated free-rocking record of specimen 2 and the block it gives:

    >>> import rocking
    >>> from rocking.identify import free_rocking
    >>> block = rocking.specimen(2)
    >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
    >>> fit = free_rocking(r.t, r.theta)
    >>> fit.n_half_cycles, fit.release
    (12, True)
    >>> identified = fit.to_block()
    >>> round(identified.alpha, 3), round(identified.p, 2), round(identified.mu, 3)
    (0.168, 3.81, 0.958)
    """

    alpha: float
    p: float
    mu: float
    alpha_std: float
    p_std: float
    mu_std: float
    mu_n: np.ndarray
    peak_times: np.ndarray
    peak_values: np.ndarray
    crossing_times: np.ndarray
    offset: float
    residuals: np.ndarray
    impact_numbers: np.ndarray = field(repr=False, default=None)
    crossing_std: np.ndarray = field(repr=False, default=None)
    weights: np.ndarray = field(repr=False, default=None)
    cov: np.ndarray = field(repr=False, default=None)
    noise: float = 0.0
    sampling_rate: float = 0.0
    offset_method: str = ""
    min_amplitude: float = 0.0
    uncertainty: str = "jacobian"
    n_lobes_found: int = 0
    release: bool = False
    t: np.ndarray = field(repr=False, default=None)
    theta: np.ndarray = field(repr=False, default=None)

    def __repr__(self) -> str:
        return (f"FreeRockingFit(alpha={self.alpha:.5f} ± {self.alpha_std:.5f} rad, "
                f"p={self.p:.4f} ± {self.p_std:.4f} 1/s, mu={self.mu:.4f} ± "
                f"{self.mu_std:.4f}, {self.n_half_cycles} half-cycles"
                + (", release" if self.release else "") + ")")

    # ------------------------------------------------------------------ derived
    @property
    def amplitudes(self) -> np.ndarray:
        """Amplitudes ``|peak_values|`` (rad) of the half-cycles used."""
        return np.abs(self.peak_values)

    @property
    def n_half_cycles(self) -> int:
        return int(self.peak_times.size)

    @property
    def rise_times(self) -> np.ndarray:
        """Measured crossing-to-peak times (s)."""
        return self.peak_times - self.crossing_times[:, 0]

    @property
    def fall_times(self) -> np.ndarray:
        """Measured peak-to-crossing times (s)."""
        return self.crossing_times[:, 1] - self.peak_times

    @property
    def model_quarter_times(self) -> np.ndarray:
        """``T(r_k)`` with the fitted parameters (s)."""
        return quarter_time(self.amplitudes, self.alpha, self.p)

    @property
    def alpha_p_corr(self) -> float:
        """Correlation of the ``alpha`` and ``p`` estimates."""
        if self.cov is None:
            return float("nan")
        return float(self.cov[0, 1] / math.sqrt(self.cov[0, 0] * self.cov[1, 1]))

    def to_block(self, name: str = "identified", **geometry):
        """A :class:`~rocking.Block` with the identified ``alpha``, ``p``, ``mu``.

        Examples
        --------
        >>> import rocking
        >>> from rocking.identify import free_rocking
        >>> block = rocking.specimen(2)  # a simulated free-rocking record of it:
        >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
        >>> fit = free_rocking(r.t, r.theta)
        >>> identified = fit.to_block("specimen 2, identified")
        >>> identified.name, round(identified.alpha, 4), round(identified.p, 3)
        ('specimen 2, identified', 0.168, 3.81)
        >>> bool(np.allclose([identified.alpha, identified.p, identified.mu],
        ...                  [block.alpha, block.p, block.mu], rtol=1e-4))
        True
        """
        if not 0.0 < self.mu <= 1.0:
            raise IdentificationError(
                f"the identified mu = {self.mu:.4f} is outside (0, 1]: the amplitudes do not "
                "decay as in free rocking of a rigid block")
        return Block.from_params(self.alpha, self.p, self.mu, name=name, **geometry)

    def error_surface(self, alphas=None, ps=None, n: int = 121, span: float | None = None):
        """``(alphas, ps, Sigma)`` on a grid around the fit; ``Sigma[i, j]`` at
        ``(alphas[i], ps[j])`` (weighted Eq 13, dimensionless).

        Examples
        --------
        >>> import rocking
        >>> from rocking.identify import free_rocking
        >>> block = rocking.specimen(2)  # a simulated free-rocking record of it:
        >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
        >>> fit = free_rocking(r.t, r.theta)
        >>> alphas, ps, S = fit.error_surface(n=41)
        >>> S.shape
        (41, 41)
        >>> i, j = np.unravel_index(S.argmin(), S.shape)  # the grid's minimum is the fit
        >>> bool(np.isclose(alphas[i], fit.alpha)), bool(np.isclose(ps[j], fit.p))
        (True, True)
        """
        if span is None:
            rel_a = self.alpha_std / self.alpha if np.isfinite(self.alpha_std) else 0.0
            rel_p = self.p_std / self.p if np.isfinite(self.p_std) else 0.0
            span = float(np.clip(8.0 * max(rel_a, rel_p), 0.03, 0.5))
        r_max = float(self.amplitudes.max())
        if alphas is None:
            lo = max(self.alpha * (1.0 - span), r_max * (1.0 + 1e-6))
            hi = min(self.alpha * (1.0 + span), 0.5 * math.pi - 1e-9)
            alphas = np.linspace(lo, hi, n)
        if ps is None:
            ps = np.linspace(self.p * (1.0 - span), self.p * (1.0 + span), n)
        alphas, ps = np.asarray(alphas, float), np.asarray(ps, float)
        r, d, w, _ = self._intervals()
        S = sigma_surface(r, d, alphas[:, None], ps[None, :], weights=w)
        return alphas, ps, S

    def _intervals(self):
        """The measured intervals: (amplitude, duration, weight, half-cycle index)."""
        return flatten_intervals(self.amplitudes, self.rise_times, self.fall_times, self.weights)

    def summary(self) -> dict:
        """JSON-ready summary (SI units; NaN as None).

        Examples
        --------
        >>> import rocking
        >>> from rocking.identify import free_rocking
        >>> block = rocking.specimen(2)  # a simulated free-rocking record of it:
        >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
        >>> fit = free_rocking(r.t, r.theta)
        >>> s = fit.summary()
        >>> s["n_half_cycles"], s["release"], s["uncertainty"]
        (12, True, 'jacobian')
        >>> import math
        >>> round(s["alpha_deg"], 3) == round(math.degrees(block.alpha), 3)
        True
        """
        res = self.residuals
        return jsonable({
            "alpha": self.alpha, "alpha_std": self.alpha_std,
            "alpha_deg": math.degrees(self.alpha),
            "p": self.p, "p_std": self.p_std,
            "mu": self.mu, "mu_std": self.mu_std,
            "alpha_p_correlation": self.alpha_p_corr,
            "uncertainty": self.uncertainty,
            "mu_n": [float(x) for x in self.mu_n],
            "n_half_cycles": self.n_half_cycles,
            "n_half_cycles_found": self.n_lobes_found,
            "amplitude_max": float(self.amplitudes.max()),
            "amplitude_min": float(self.amplitudes.min()),
            "min_amplitude": self.min_amplitude,
            "offset": self.offset, "offset_method": self.offset_method,
            "noise_std": self.noise, "sampling_rate": self.sampling_rate,
            "rms_residual": float(np.sqrt(np.nanmean(res ** 2))),
            "peak_times": [float(x) for x in self.peak_times],
            "peak_values": [float(x) for x in self.peak_values],
            "crossing_times": [[float(x) for x in row] for row in self.crossing_times],
            "release": bool(self.release),
        })

    def to_dict(self) -> dict:
        """All fields, JSON-ready (arrays as nested lists; NaN and inf as None).

        Examples
        --------
        >>> import rocking
        >>> from rocking.identify import free_rocking
        >>> block = rocking.specimen(2)  # a simulated free-rocking record of it:
        >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
        >>> fit = free_rocking(r.t, r.theta)
        >>> import json
        >>> d = json.loads(json.dumps(fit.to_dict()))  # plain JSON
        >>> len(d["theta"]) == r.t.size, d["release"], d["crossing_times"][0][0]
        (True, True, None)
        """
        return jsonable({f.name: _plain(getattr(self, f.name)) for f in fields(self)})

    def compare(self, theoretical):
        """Table II-style ``pandas.DataFrame``: theoretical, identified, std and % per parameter.

        ``theoretical`` is a :class:`~rocking.Block` (or anything with ``alpha``, ``p``,
        ``mu``, or a mapping with those keys).

        Examples
        --------
        >>> import rocking
        >>> from rocking.identify import free_rocking
        >>> block = rocking.specimen(2)  # a simulated free-rocking record of it:
        >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
        >>> fit = free_rocking(r.t, r.theta)
        >>> table = fit.compare(block)  # the record's own block: differences ~ 0
        >>> table["parameter"].tolist(), table["T"].tolist()
        (['alpha', 'mu', 'p'], [0.168, 0.958, 3.81])
        >>> bool((table["diff_pct"].abs() < 0.01).all())
        True
        """
        import pandas as pd

        th = _params_of(theoretical)
        rows = []
        for k in ("alpha", "mu", "p"):
            v, s = getattr(self, k), getattr(self, f"{k}_std")
            rows.append({"parameter": k, "T": th[k], "identified": v, "std": s,
                         "diff_pct": (v - th[k]) / th[k] * 100.0})
        return pd.DataFrame(rows)

    def table(self):
        """Per-half-cycle ``pandas.DataFrame``: times, amplitude, model time, residuals, mu_n.

        Examples
        --------
        >>> import rocking
        >>> from rocking.identify import free_rocking
        >>> block = rocking.specimen(2)  # a simulated free-rocking record of it:
        >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
        >>> fit = free_rocking(r.t, r.theta)
        >>> tab = fit.table()
        >>> len(tab), tab["impact"].tolist()[:4]
        (12, [0, 1, 2, 3])
        >>> bool(np.allclose(tab["fall"], tab["T_model"], rtol=1e-4))  # Housner's T(r)
        True
        >>> tab["mu_n"].iloc[1:].round(3).unique().tolist()  # the block's restitution
        [0.958]
        """
        import pandas as pd

        mu_n = np.concatenate(([np.nan], self.mu_n))
        return pd.DataFrame({
            "impact": self.impact_numbers, "t_cross_before": self.crossing_times[:, 0],
            "t_peak": self.peak_times, "t_cross_after": self.crossing_times[:, 1],
            "amplitude": self.amplitudes, "rise": self.rise_times, "fall": self.fall_times,
            "T_model": self.model_quarter_times, "residual_rise": self.residuals[:, 0],
            "residual_fall": self.residuals[:, 1], "mu_n": mu_n,
        })

    # ------------------------------------------------------------------ plots
    def plot_error_surface(self, ax=None, theoretical=None, n: int = 121,
                           span: float | None = None):
        """Contours of ``log10(Sigma / Sigma_min)`` over ``(alpha, p)``, the minimum marked.

        ``theoretical`` (a Block or mapping) adds its point when it lies in the window (the
        window is widened to include it). Returns the Axes.

        Examples
        --------
        >>> import rocking
        >>> from rocking.identify import free_rocking
        >>> block = rocking.specimen(2)  # a simulated free-rocking record of it:
        >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
        >>> fit = free_rocking(r.t, r.theta)
        >>> ax = fit.plot_error_surface(theoretical=block, n=41)
        >>> ax.get_ylabel(), ax.get_title()
        ('$p$ (1/s)', 'Error surface Σ(α, p), Eq 13 (12 half-cycles)')
        >>> [t.get_text() for t in ax.get_legend().get_texts()][1:]  # the two points agree
        ['theoretical α=0.1680, p=3.810', 'identified α=0.1680, p=3.810']
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """
        if ax is None:
            _, ax = figure(figsize=(5.6, 4.4))
        if theoretical is not None and span is None:
            th = _params_of(theoretical)
            need = max(abs(th["alpha"] / self.alpha - 1), abs(th["p"] / self.p - 1))
            rel = max(self.alpha_std / self.alpha, self.p_std / self.p)
            span = float(np.clip(max(8.0 * rel, 1.25 * need), 0.03, 0.3))
        alphas, ps, S = self.error_surface(n=n, span=span)
        smin = float(np.min(S))
        L = np.log10(np.maximum(S / max(smin, 1e-300), 1.0))
        levels = np.linspace(0.0, max(float(L.max()), 1e-3), 21)
        cf = ax.contourf(alphas, ps, L.T, levels=levels, cmap="viridis_r")
        ax.contour(alphas, ps, L.T, levels=levels[::4], colors="white", linewidths=0.5,
                   alpha=0.7)
        cb = ax.figure.colorbar(cf, ax=ax)
        top = float(levels[-1])
        step = 0.5 if top <= 4 else 1.0 if top <= 8 else 2.0
        cb.set_ticks(np.arange(0.0, top + 1e-9, step))
        cb.set_label(r"$\log_{10}\,\Sigma/\Sigma_{\min}$")
        # valley: best p for each alpha
        r, d, w, _ = self._intervals()
        _, B, C = sigma_coefficients(r, d, w * w, alphas)
        pv = C / B
        ok = (pv >= ps[0]) & (pv <= ps[-1])
        ax.plot(alphas[ok], pv[ok], color="white", ls="--", lw=1.0,
                label=r"valley $p^*(\alpha)$")
        ax.errorbar([self.alpha], [self.p], xerr=[self.alpha_std], yerr=[self.p_std],
                    color="#D55E00", marker="*", ms=13, mec="k", mew=0.6, capsize=3,
                    lw=1.2, ls="none", zorder=5,
                    label=f"identified α={self.alpha:.4f}, p={self.p:.3f}")
        if theoretical is not None:
            th = _params_of(theoretical)
            inside = (alphas[0] <= th["alpha"] <= alphas[-1]) and (ps[0] <= th["p"] <= ps[-1])
            ax.plot([th["alpha"]] if inside else [], [th["p"]] if inside else [], marker="X",
                    ms=10, color="#E69F00", mec="k", mew=0.6, ls="none", zorder=5,
                    label=f"theoretical α={th['alpha']:.4f}, p={th['p']:.3f}"
                    + ("" if inside else " (outside)"))
        style_axes(ax, r"$\alpha$ (rad)", r"$p$ (1/s)")
        ax.grid(False)
        ax.set_title(f"Error surface Σ(α, p), Eq 13 ({self.n_half_cycles} half-cycles)",
                     fontsize=10)
        ax.legend(loc="upper right", fontsize=7.5, framealpha=0.85)
        return ax

    def plot_fit(self, ax=None, theoretical=None, deg: bool = True):
        """Measured record against the classical model (Fig. 4 a/b analogue).

        The model is released from the first used peak with the fitted parameters and, if
        ``theoretical`` (a Block or mapping) is given, with those too. With ``ax=None`` a
        new figure is made with two panels (theoretical, identified) or one; ``ax`` may be
        one Axes (all curves on it) or two. Returns the Axes (a list of two for panels).

        Examples
        --------
        >>> import rocking
        >>> from rocking.identify import free_rocking
        >>> block = rocking.specimen(2)  # a simulated free-rocking record of it:
        >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
        >>> fit = free_rocking(r.t, r.theta)
        >>> ax = fit.plot_fit()  # one panel: the record and the identified model
        >>> ax.get_xlabel(), [t.get_text() for t in ax.get_legend().get_texts()][1]
        ('time (s)', 'classical, identified: α=0.1680, p=3.810, μ=0.9580')
        >>> axs = fit.plot_fit(theoretical=block)  # two panels
        >>> [a.get_title(loc="left") for a in axs]
        ['(a) theoretical parameters', '(b) identified parameters']
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """
        panels = theoretical is not None
        if ax is None:
            if panels:
                from matplotlib.figure import Figure

                fig = Figure(figsize=(8.0, 5.6), layout="constrained")
                axs = list(fig.subplots(2, 1, sharex=True))
            else:
                _, a = figure(figsize=(8.0, 3.2))
                axs = [a]
        elif isinstance(ax, list | tuple | np.ndarray):
            axs = list(np.ravel(ax))
        else:
            axs = [ax]
        k = 180.0 / math.pi if deg else 1.0
        t_end = self._plot_end()
        sel = self.t <= t_end
        models = []
        if panels:
            models.append(("theoretical", _params_of(theoretical), PALETTE[3]))
        models.append(("identified", {"alpha": self.alpha, "p": self.p, "mu": self.mu},
                       PALETTE[0]))
        for i, (label, prm, col) in enumerate(models):
            a = axs[min(i, len(axs) - 1)]
            if i < len(axs) and (i == 0 or len(axs) > 1):
                a.plot(self.t[sel], k * self.theta[sel], color="0.55", lw=0.8,
                       label="measured (offset removed)")
            tm, thm = self._simulate(prm, t_end)
            a.plot(tm, k * thm, color=col, lw=1.1,
                   label=f"classical, {label}: α={prm['alpha']:.4f}, p={prm['p']:.3f}, "
                         f"μ={prm['mu']:.4f}")
        for a in axs:
            a.plot(self.peak_times, k * self.peak_values, ls="none", marker="o", ms=2.8,
                   mfc="none", mec="k", mew=0.6, label="peaks used")
            style_axes(a, None, r"$\theta$ (deg)" if deg else r"$\theta$ (rad)")
            a.legend(loc="upper right", fontsize=7.5, framealpha=0.85)
            a.set_xlim(self.t[0], t_end)
        axs[-1].set_xlabel("time (s)")
        if panels and len(axs) > 1:
            axs[0].set_title("(a) theoretical parameters", fontsize=10, loc="left")
            axs[1].set_title("(b) identified parameters", fontsize=10, loc="left")
        return axs if len(axs) > 1 else axs[0]

    def _plot_end(self) -> float:
        t_last = float(self.crossing_times[-1, 1])
        return float(min(self.t[-1], t_last + 0.15 * (t_last - self.t[0]) + 0.5))

    def _simulate(self, prm, t_end):
        b = Block.from_params(prm["alpha"], prm["p"], min(max(prm["mu"], 1e-6), 1.0))
        t0 = float(self.peak_times[0])
        dt = min(0.002, float(np.median(np.diff(self.t))))
        th0 = float(self.peak_values[0])
        if abs(th0) >= b.alpha:
            return np.array([t0]), np.array([th0])
        r = simulate(b, None, duration=max(t_end - t0, dt), theta0=th0, dt_out=dt)
        return r.t + t0, r.theta


def _plain(x):
    """Arrays as (nested) lists; anything else unchanged."""
    return x.tolist() if isinstance(x, np.ndarray) else x


def _params_of(x) -> dict:
    if isinstance(x, dict):
        try:
            return {k: float(x[k]) for k in ("alpha", "p", "mu")}
        except KeyError as e:
            raise ParameterError(f"theoretical parameters need alpha, p and mu; missing {e}")\
                from None
    try:
        return {k: float(getattr(x, k)) for k in ("alpha", "p", "mu")}
    except AttributeError:
        raise ParameterError("theoretical must be a rocking.Block or a mapping with alpha, p "
                             f"and mu, got {type(x).__name__}") from None

