"""Fourier amplitude spectrum of a rocking response (the analogue of Fig. 6b of the paper).

Method. The signal is first put on a uniform time grid: its step is the median step of the
input, and when the input is not uniform (the response of an overturning run ends on an
extra sample at the overturning time; a measured record may be uneven) it is resampled
there by a cubic spline through the samples (:class:`scipy.interpolate.CubicSpline`; a
uniform input is used as it is). The spectrum is then the real FFT of the detrended,
windowed, zero-padded signal, normalised as a *one-sided amplitude* spectrum:
``amplitude = 2 |X(f)| / sum(window)`` (``|X(0)| / sum(window)`` at ``f = 0``), so that a
sampled sine ``A sin(2 pi f0 t)`` gives a peak of height ``A`` at ``f0``. The zero padding
(``pad`` times the length) samples the spectrum finely between the FFT bins, and each peak
found by :func:`scipy.signal.find_peaks` is refined by a parabola through its three
highest samples, which removes the scalloping loss of the bins.

The default window is Hann: its side lobes (-31 dB, falling fast) do not show up as
spurious peaks, at the price of a main lobe twice as wide as the rectangular window's
(``window="boxcar"``, resolution ``1/T``, side lobes at -13 dB that ``find_peaks`` would
report as peaks).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
from scipy import fft
from scipy.interpolate import CubicSpline
from scipy.signal import detrend as _detrend
from scipy.signal import find_peaks, get_window

from .._validate import in_range
from ..errors import ParameterError
from ..plot import PALETTE, new_axes, style_axes
from ..results import jsonable

_DETREND = ("constant", "linear", None)


def _as_signal(data) -> tuple[np.ndarray, np.ndarray, str]:
    """``(t, x, label)`` from a Response (``t``, ``theta``) or a ``(t, x)`` pair."""
    if hasattr(data, "t") and hasattr(data, "theta"):
        t, x, label = data.t, data.theta, r"rocking angle $\theta$ (rad)"
    else:
        try:
            t, x = data
        except (TypeError, ValueError):
            raise ParameterError("response_or_signal must be a rocking.Response or a (t, x) "
                                 "pair of 1-D arrays") from None
        label = "amplitude"
    try:
        t = np.asarray(t, dtype=np.float64)
        x = np.asarray(x, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError("response_or_signal: t and x must be 1-D arrays of "
                             "numbers") from None
    if t.ndim != 1 or x.ndim != 1 or t.size != x.size:
        raise ParameterError(f"response_or_signal: t and x must be 1-D arrays of the same "
                             f"length, got shapes {t.shape} and {x.shape}")
    if t.size < 4:
        raise ParameterError(f"response_or_signal must hold at least 4 samples, got {t.size}")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(x))):
        raise ParameterError("response_or_signal holds a non-finite value (NaN or inf)")
    dt = np.diff(t)
    if np.any(dt < 0.0):
        raise ParameterError("response_or_signal: the times t must be increasing")
    keep = np.concatenate([[True], dt > 0.0])  # drop repeated times
    return t[keep], x[keep], label


def _uniform(t: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, float, bool]:
    """``x`` on a uniform grid from ``t[0]`` with the median step; ``resampled`` flag."""
    steps = np.diff(t)
    dt = float(np.median(steps))
    if np.all(np.abs(steps - dt) <= 1e-9 * dt):
        return x, dt, False
    n = int(math.floor((t[-1] - t[0]) / dt + 1e-9)) + 1

    grid = t[0] + np.arange(n) * dt
    return CubicSpline(t, x)(grid), dt, True


@dataclass
class FourierSpectrum:
    """One-sided Fourier amplitude spectrum with its peaks (:func:`fourier_spectrum`).

    ``freq`` (Hz) and ``amplitude`` (units of the signal) are arrays; ``peaks`` is a
    DataFrame (``freq``, ``amplitude``, ``prominence``), largest peak first; ``dt`` (s) is
    the step of the uniform grid the FFT ran on and ``resampled`` says whether the input
    had to be interpolated onto it.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from rocking.analysis import fourier_spectrum
    >>> t = np.linspace(0.0, 10.0, 1001)  # s
    >>> x = np.sin(2 * np.pi * 1.5 * t) + 0.5 * np.sin(2 * np.pi * 4.0 * t)
    >>> fs = fourier_spectrum((t, x), fmax=10.0)
    >>> fs.peaks[["freq", "amplitude"]].round(3).values.tolist()
    [[1.5, 1.0], [4.0, 0.5]]
    >>> round(fs.dt, 6), fs.resampled, type(fs.plot()).__name__
    (0.01, False, 'Axes')
    """

    freq: np.ndarray
    amplitude: np.ndarray
    peaks: object
    dt: float
    duration: float
    resampled: bool
    window: str = "hann"
    label: str = "amplitude"
    info: dict = field(default_factory=dict)

    @property
    def spectrum(self):
        """The spectrum as a DataFrame with columns ``freq`` (Hz) and ``amplitude``
        (also the method ``to_dataframe()``).

        Examples
        --------
        >>> from rocking.analysis import fourier_spectrum
        >>> t = np.arange(1000) * 0.01  # s: 10 s at 100 Hz
        >>> fs = fourier_spectrum((t, 0.3 * np.sin(2 * np.pi * 2.0 * t)), fmax=10.0)
        >>> df = fs.to_dataframe()
        >>> df.columns.tolist(), df.equals(fs.spectrum)
        (['freq', 'amplitude'], True)
        >>> round(float(df.loc[df["amplitude"].idxmax(), "freq"]), 2)  # the sine's 2 Hz
        2.0
        """

        return pd.DataFrame({"freq": self.freq, "amplitude": self.amplitude})

    to_dataframe = spectrum.fget

    @property
    def peak_freq(self) -> float:
        """Frequency (Hz) of the largest peak (NaN if none)."""
        return float(self.peaks["freq"].iloc[0]) if len(self.peaks) else math.nan

    @property
    def peak_amplitude(self) -> float:
        """Height of the largest peak (NaN if none)."""
        return float(self.peaks["amplitude"].iloc[0]) if len(self.peaks) else math.nan

    def summary(self) -> dict:
        """JSON-ready: the grid, the resolution ``1/T`` and the peaks.

        Examples
        --------
        >>> from rocking.analysis import fourier_spectrum
        >>> t = np.arange(1000) * 0.01  # s: 10 s at 100 Hz
        >>> fs = fourier_spectrum((t, 0.3 * np.sin(2 * np.pi * 2.0 * t)), fmax=10.0)
        >>> s = fs.summary()
        >>> [round(s[k], 6) for k in ("dt", "duration", "resolution")]  # 1/T = 0.1 Hz
        [0.01, 10.0, 0.1]
        >>> s["window"], s["resampled"]
        ('hann', False)
        >>> [{k: round(v, 4) for k, v in pk.items()} for pk in s["peaks"]]
        [{'freq': 2.0, 'amplitude': 0.3}]
        """

        return jsonable({
            "dt": self.dt, "duration": self.duration, "resolution": 1.0 / self.duration,
            "resampled": self.resampled, "window": self.window,
            "peaks": [{"freq": float(f), "amplitude": float(a)}
                      for f, a in zip(self.peaks["freq"], self.peaks["amplitude"],
                                      strict=True)],
        })

    def to_dict(self) -> dict:
        """The summary plus the spectrum arrays, JSON-ready.

        Examples
        --------
        >>> from rocking.analysis import fourier_spectrum
        >>> t = np.arange(1000) * 0.01  # s: 10 s at 100 Hz
        >>> fs = fourier_spectrum((t, 0.3 * np.sin(2 * np.pi * 2.0 * t)), fmax=10.0)
        >>> import json
        >>> d = json.loads(json.dumps(fs.to_dict()))
        >>> len(d["freq"]) == len(d["amplitude"]) == fs.freq.size, d["freq"][0]
        (True, 0.0)
        >>> round(max(d["amplitude"]), 4)  # the sine's amplitude
        0.3
        """

        d = self.summary()
        d["freq"] = jsonable(self.freq)
        d["amplitude"] = jsonable(self.amplitude)
        return d

    def plot(self, ax=None, *, fmax: float | None = None, label: str | None = None,
             annotate: bool = True, **kw):
        """Plot the amplitude against frequency, the peaks marked. Returns the Axes.

        Examples
        --------
        >>> from rocking.analysis import fourier_spectrum
        >>> t = np.arange(1000) * 0.01  # s: 10 s at 100 Hz
        >>> fs = fourier_spectrum((t, 0.3 * np.sin(2 * np.pi * 2.0 * t)), fmax=10.0)
        >>> ax = fs.plot(fmax=5.0)
        >>> ax.get_xlabel(), [float(v) for v in ax.get_xlim()]
        ('frequency f (Hz)', [0.0, 5.0])
        >>> [a.get_text() for a in ax.texts]  # the peaks, annotated
        ['2 Hz']
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """

        if ax is None:
            _, ax = new_axes()
        kw.setdefault("color", PALETTE[0])
        kw.setdefault("linewidth", 1.0)
        ax.plot(self.freq, self.amplitude, label=label, **kw)
        if len(self.peaks) and annotate:
            ax.plot(self.peaks["freq"], self.peaks["amplitude"], linestyle="none", marker="v",
                    color="#C00000", markersize=5)
            for f, a in zip(self.peaks["freq"], self.peaks["amplitude"], strict=True):
                ax.annotate(f"{f:.3g} Hz", xy=(f, a), xytext=(4, 4),
                            textcoords="offset points", fontsize=8, color="#C00000")
        style_axes(ax, "frequency f (Hz)", f"Fourier amplitude, {self.label}")
        ax.set_xlim(0.0, float(fmax) if fmax else float(self.freq[-1]))
        ax.set_ylim(bottom=0.0)
        if label:
            ax.legend(frameon=False, fontsize=9)
        return ax


def fourier_spectrum(response_or_signal, *, detrend: str | None = "constant",
                     window: str = "hann", pad: int = 8, fmax: float | None = None,
                     prominence: float = 0.05, max_peaks: int | None = 10) -> FourierSpectrum:
    """The one-sided Fourier amplitude spectrum of ``theta(t)`` (or any signal) and its
    peaks: the analogue of the paper's Fig. 6b.

    Parameters
    ----------
    response_or_signal : Response or (t, x)
        A :class:`rocking.Response` (its ``t`` and ``theta``) or a pair of 1-D arrays,
        times in s (increasing; the steps may be uneven: see the module docstring).
    detrend : {"constant", "linear", None}
        Removed before the transform (:func:`scipy.signal.detrend`); default the mean.
    window : str
        A :func:`scipy.signal.get_window` name; default ``"hann"``. The
        amplitude is normalised by the window's sum, so a sine of amplitude ``A`` peaks at
        ``A`` with any window.
    pad : int
        Zero padding: the FFT length is at least ``pad`` times the number of samples
        (1 to 64).
    fmax : float, optional
        Keep frequencies up to ``fmax`` (Hz); default the Nyquist frequency.
    prominence : float
        Peaks must stand out by this fraction of the largest amplitude (0 to 1).
    max_peaks : int or None
        Keep at most this many peaks (the highest).

    Returns
    -------
    FourierSpectrum
        ``spectrum`` (DataFrame ``freq``, ``amplitude``), ``peaks`` (DataFrame ``freq``,
        ``amplitude``, ``prominence``, highest first; frequency and height refined by a
        parabola through the three samples around each maximum) and ``plot()``.

    Examples
    --------
    A sine of 2 Hz and amplitude 0.3 peaks at 2 Hz with height 0.3 (the amplitude is
    normalised by the window's sum):

    >>> from rocking.analysis import fourier_spectrum
    >>> t = np.linspace(0.0, 10.0, 1001)  # s
    >>> fs = fourier_spectrum((t, 0.3 * np.sin(2 * np.pi * 2.0 * t)))
    >>> round(fs.peak_freq, 4), round(fs.peak_amplitude, 4)
    (2.0, 0.3)

    Of a rocking response: ``fourier_spectrum(rocking.simulate(block, motion))``.
    """

    t, x, label = _as_signal(response_or_signal)
    if detrend not in _DETREND:
        raise ParameterError(f"detrend must be 'constant', 'linear' or None, got {detrend!r}")
    pad = int(in_range("pad", pad, 1, 64, lo_open=False, hi_open=False, shown="[1, 64]"))
    prominence = in_range("prominence", prominence, 0.0, 1.0, lo_open=False, hi_open=False,
                          shown="[0, 1]")
    if max_peaks is not None:
        max_peaks = int(in_range("max_peaks", max_peaks, 1, 1e9, lo_open=False,
                                 shown=">= 1"))
    y, dt, resampled = _uniform(t, x)
    n = y.size
    if detrend is not None:
        y = _detrend(y, type=detrend)
    try:
        w = get_window(window, n, fftbins=False)
    except (ValueError, TypeError) as exc:
        raise ParameterError(f"window must be a scipy.signal.get_window name, got {window!r} "
                             f"({exc})") from None
    nfft = fft.next_fast_len(pad * n, real=True)
    amp = np.abs(fft.rfft(y * w, nfft)) * (2.0 / np.sum(w))
    amp[0] *= 0.5
    if nfft % 2 == 0:
        amp[-1] *= 0.5
    freq = fft.rfftfreq(nfft, dt)
    if fmax is not None:
        fmax = in_range("fmax", fmax, 0.0, math.inf, shown="> 0")
        keep = freq <= fmax
        freq, amp = freq[keep], amp[keep]
    top = float(amp.max()) if amp.size else 0.0
    idx, props = find_peaks(amp, prominence=prominence * top if top > 0 else None)
    pf, pa = [], []
    for k in idx:
        y0, y1, y2 = amp[k - 1], amp[k], amp[k + 1]
        den = y0 - 2.0 * y1 + y2
        d = 0.5 * (y0 - y2) / den if den != 0.0 else 0.0
        pf.append(freq[k] + d * (freq[1] - freq[0]))
        pa.append(y1 - 0.25 * (y0 - y2) * d)
    peaks = pd.DataFrame({"freq": np.asarray(pf, dtype=float),
                          "amplitude": np.asarray(pa, dtype=float),
                          "prominence": np.asarray(props.get("prominences", []), dtype=float)})
    peaks = peaks.sort_values("amplitude", ascending=False, kind="stable")
    if max_peaks is not None:
        peaks = peaks.head(max_peaks)
    peaks = peaks.reset_index(drop=True)
    return FourierSpectrum(freq=freq, amplitude=amp, peaks=peaks, dt=dt,
                           duration=float(n * dt), resampled=resampled, window=str(window),
                           label=label, info={"nfft": int(nfft), "n": int(n)})
