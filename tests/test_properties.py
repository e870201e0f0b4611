"""Property-based checks (hypothesis) of the classical and CCRR models over random blocks."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import rocking

blocks = st.builds(
    rocking.Block.from_params,
    alpha=st.floats(0.05, 0.45),
    p=st.floats(1.0, 8.0),
    mu=st.floats(0.7, 0.99),
)
fractions = st.floats(0.1, 0.9)


def _energy(alpha, r):
    return math.cos(alpha - r) - math.cos(alpha)


@settings(max_examples=25, deadline=None)
@given(block=blocks, frac=fractions)
def test_energy_ratio_is_mu_squared_per_impact(block, frac):
    """Eq 12: successive free-rocking amplitudes lose a factor mu^2 of energy per impact."""
    r = rocking.simulate(block, None, duration=8.0, theta0=frac * block.alpha, dt_out=1e-3,
                         rtol=1e-10)
    _, peaks = r.half_cycle_peaks()
    amps = np.abs(peaks[: min(4, r.n_impacts)])  # half-cycles closed by an impact
    amps = amps[amps > 1e-3 * block.alpha]
    for a0, a1 in zip(amps[:-1], amps[1:], strict=True):
        ratio = _energy(block.alpha, a1) / _energy(block.alpha, a0)
        assert math.isclose(ratio, block.mu ** 2, rel_tol=2e-4)


@settings(max_examples=25, deadline=None)
@given(block=blocks, frac=fractions, sign=st.sampled_from([-1.0, 1.0]))
def test_free_rocking_is_mirror_symmetric(block, frac, sign):
    r1 = rocking.simulate(block, None, duration=2.0, theta0=sign * frac * block.alpha)
    r2 = rocking.simulate(block, None, duration=2.0, theta0=-sign * frac * block.alpha)
    np.testing.assert_allclose(r1.theta, -r2.theta, atol=1e-12)
    np.testing.assert_allclose(r1.impact_times, r2.impact_times, rtol=1e-12)


@settings(max_examples=15, deadline=None)
@given(block=blocks, frac=st.floats(0.2, 0.9))
def test_ccrr_first_crossing_matches_classical(block, frac):
    """Before the first impact both models solve the same equation (Eq 1 = Eq 10 with
    l -> 0), so the first zero crossing agrees closely."""
    th0 = frac * block.alpha
    rh = rocking.simulate(block, None, duration=20.0 / block.p, theta0=th0)
    rc = rocking.simulate(block, None, model="ccrr", duration=20.0 / block.p, theta0=th0)
    assert math.isclose(rc.impact_times[0], rh.impact_times[0], rel_tol=1e-4)
