"""``Response.half_cycle_peaks``: the amplitudes of free rocking follow Housner's impact
law, and a run cut short has no peak that its full run does not have (the value at the
end of a cut half-cycle is no amplitude)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rocking


def next_peak(a: float, alpha: float, mu: float) -> float:
    """Linearised Eq 1: ``(theta - alpha)^2 - (omega/p)^2`` is conserved between impacts,
    and an impact multiplies ``omega`` by ``mu``, so a peak ``a`` is followed by
    ``alpha - sqrt(alpha^2 (1 - mu^2) + mu^2 (alpha - a)^2)`` on the other side."""
    return alpha - math.sqrt(alpha**2 * (1 - mu**2) + mu**2 * (alpha - a) ** 2)


@pytest.fixture(scope="module")
def block():
    return rocking.specimen(2)


def test_peaks_follow_the_impact_law(block):
    r = rocking.simulate(block, theta0=0.8 * block.alpha, duration=6.0, linear=True)
    _, peaks = r.half_cycle_peaks()
    a = np.abs(peaks)
    assert a.size >= 8
    assert np.all(np.sign(peaks[1:]) == -np.sign(peaks[:-1]))  # one side, then the other
    for k in range(a.size - 1):
        assert a[k + 1] == pytest.approx(next_peak(a[k], block.alpha, block.mu),
                                         abs=1e-6 * block.alpha)


@pytest.mark.parametrize("frac", [0.3, 0.6, 0.9])
def test_a_cut_run_has_only_the_full_runs_peaks(block, frac):
    """Cut inside the second, third... half-cycle, while |theta| grows or falls: the cut
    run's peaks are the first peaks of the full run, never its last sample."""
    full = rocking.simulate(block, theta0=0.8 * block.alpha, duration=6.0)
    t_full, p_full = full.half_cycle_peaks()
    imp = full.impact_times
    for k in range(3):
        end = imp[k] + frac * (imp[k + 1] - imp[k])
        cut = rocking.simulate(block, theta0=0.8 * block.alpha, duration=end)
        t_cut, p_cut = cut.half_cycle_peaks()
        n = t_cut.size
        assert n in (k + 1, k + 2)   # the cut half-cycle counts if its peak was reached
        assert (n == k + 2) == (t_full[k + 1] <= end)
        np.testing.assert_allclose(p_cut, p_full[:n], rtol=0, atol=1e-9)


def test_an_overturning_run_ends_without_a_false_peak(block):
    """Overturning: |theta| grows to the end of the run; its last value is no peak."""
    from rocking.motions import OneSine

    r = rocking.simulate(block, OneSine(3.0 * 9.80665 * math.tan(block.alpha), 0.5),
                         duration=5.0)
    assert r.overturned
    _, peaks = r.half_cycle_peaks()
    assert np.all(np.abs(peaks) < block.alpha)  # none at or past the overturning angle


def test_a_peak_between_the_last_two_samples_counts(block):
    """The run's last output sample is the first after a peak: |theta| is still larger
    than at the sample before, but already falling. The peak was reached, and it is the
    full run's (refined between the last samples)."""
    full = rocking.simulate(block, theta0=0.8 * block.alpha, duration=6.0)
    t_full, p_full = full.half_cycle_peaks()
    dt = 0.002  # the default output interval
    for k in (1, 2, 3):
        for f in (0.2, 0.5, 0.8):
            end = (math.floor(t_full[k] / dt) + 1 + f) * dt
            cut = rocking.simulate(block, theta0=0.8 * block.alpha, duration=end)
            t_cut, p_cut = cut.half_cycle_peaks()
            assert t_cut.size == k + 1, (k, f)
            assert p_cut[-1] == pytest.approx(p_full[k], abs=1e-5 * block.alpha)


def test_a_run_starting_towards_rest_has_no_first_peak(block):
    """Released at alpha/2 moving towards theta = 0: the first half-cycle has no peak;
    the next one is the impact law's, from the energy at the start."""
    th0, om0 = 0.5 * block.alpha, -0.3
    r = rocking.simulate(block, theta0=th0, omega0=om0, duration=3.0, linear=True)
    _, peaks = r.half_cycle_peaks()
    # the peak the start's energy would have reached, (theta - alpha)^2 - (omega/p)^2
    a0 = block.alpha - math.sqrt((block.alpha - th0) ** 2 - (om0 / block.p) ** 2)
    assert abs(peaks[0]) == pytest.approx(next_peak(a0, block.alpha, block.mu),
                                          abs=1e-6 * block.alpha)


def test_no_peak_without_uplift():
    """A DEM block under a pulse below its uplift acceleration: its contact springs move
    it by micro-radians, but it never rocked."""
    from rocking.motions import OneSine

    block = rocking.specimen(2)
    r = rocking.simulate(block, OneSine(0.5 * 9.80665 * math.tan(block.alpha), 0.5),
                         model="dem", duration=2.0)
    assert math.isnan(r.uplift_time) and r.max_abs_theta > 0
    assert r.half_cycle_peaks()[0].size == 0
