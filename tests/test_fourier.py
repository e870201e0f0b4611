"""Fourier amplitude spectrum of theta(t) (issue 10, the analogue of Fig. 6b)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rocking
from rocking import ParameterError
from rocking.analysis.fourier import FourierSpectrum, fourier_spectrum
from rocking.motions import OneSine, Sine

A, F0 = 0.7, 3.3
T_END = 10.37  # not a whole number of periods of F0


def _resolution(fs):
    return 1.0 / fs.duration


@pytest.mark.parametrize("window", ["hann", "boxcar"])
def test_peak_of_a_sampled_sine_is_at_its_frequency_and_amplitude(window):
    t = np.arange(0.0, T_END, 0.002)
    fs = fourier_spectrum((t, A * np.sin(2 * np.pi * F0 * t + 0.3)), window=window)
    assert isinstance(fs, FourierSpectrum) and not fs.resampled
    assert fs.peak_freq == pytest.approx(F0, abs=0.02 * _resolution(fs))
    assert fs.peak_amplitude == pytest.approx(A, rel=0.005)
    df = fs.spectrum
    assert list(df.columns) == ["freq", "amplitude"]
    assert df["freq"].iloc[-1] == pytest.approx(250.0, rel=1e-3)  # Nyquist of 0.002 s


@pytest.mark.parametrize("seed", [0, 1])
def test_uneven_sampling(seed):
    rng = np.random.default_rng(seed)
    t = np.concatenate([[0.0], np.sort(rng.uniform(0.0, T_END, 7000))])
    fs = fourier_spectrum((t, A * np.sin(2 * np.pi * F0 * t)))
    assert fs.resampled
    assert fs.peak_freq == pytest.approx(F0, abs=0.02 * _resolution(fs))
    assert fs.peak_amplitude == pytest.approx(A, rel=0.005)


def test_two_sines_give_two_peaks_with_their_amplitudes():
    t = np.arange(0.0, 20.0, 0.005)
    t = t + 0.3 * 0.005 * np.sin(7.0 * t)  # gently uneven steps
    x = 0.4 * np.sin(2 * np.pi * 1.7 * t) + 0.15 * np.cos(2 * np.pi * 4.1 * t) + 0.05
    fs = fourier_spectrum((t, x))
    assert fs.resampled
    peaks = fs.peaks.sort_values("freq").reset_index(drop=True)
    assert len(peaks) == 2
    np.testing.assert_allclose(peaks["freq"], [1.7, 4.1], atol=0.02 / 20.0)
    np.testing.assert_allclose(peaks["amplitude"], [0.4, 0.15], rtol=0.01)
    assert fs.amplitude[0] < 1e-3  # the mean is removed by default


def test_response_input_and_the_extra_overturning_sample():
    block = rocking.specimen(1)
    r = rocking.simulate(block, Sine(freq=F0, amplitude=0.007, duration=12.0))
    assert not r.overturned
    fs = fourier_spectrum(r)
    # a steadily rocking block responds at the forcing frequency
    assert fs.peak_freq == pytest.approx(F0, abs=_resolution(fs))
    assert fs.dt == pytest.approx(r.t[1] - r.t[0])
    ro = rocking.simulate(block, OneSine(25.0, 0.5))
    assert ro.overturned and not np.isclose(np.diff(ro.t)[-1], np.diff(ro.t)[0])
    fo = fourier_spectrum(ro)
    assert fo.resampled and np.all(np.isfinite(fo.amplitude))


def test_summary_plot_and_fmax(tmp_path):
    t = np.arange(0.0, 8.0, 0.01)
    fs = fourier_spectrum((t, np.sin(2 * np.pi * 2.0 * t)), fmax=10.0)
    assert fs.freq[-1] <= 10.0
    d = fs.to_dict()
    assert d["peaks"][0]["freq"] == pytest.approx(2.0, abs=0.01)
    ax = fs.plot()
    ax.figure.savefig(tmp_path / "f.png")
    assert (tmp_path / "f.png").stat().st_size > 0


@pytest.mark.parametrize("data, kwargs, name", [
    ("abc", {}, "response_or_signal"),
    ((np.arange(5.0), np.arange(4.0)), {}, "response_or_signal"),
    ((np.array([0.0, 1.0, 0.5, 2.0, 3.0]), np.zeros(5)), {}, "increasing"),
    ((np.arange(5.0), np.array([0, 1, math.nan, 1, 0])), {}, "non-finite"),
    ((np.arange(50.0), np.zeros(50)), {"pad": 0}, "pad"),
    ((np.arange(50.0), np.zeros(50)), {"detrend": "quadratic"}, "detrend"),
    ((np.arange(50.0), np.zeros(50)), {"window": "nope"}, "window"),
    ((np.arange(50.0), np.zeros(50)), {"prominence": 2.0}, "prominence"),
])
def test_bad_input_names_the_parameter(data, kwargs, name):
    with pytest.raises(ParameterError, match=name):
        fourier_spectrum(data, **kwargs)
