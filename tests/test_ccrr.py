"""The CCRR model (Eqs 5-10) against the classical model and against its own theory."""

from __future__ import annotations

import math
from functools import partial
from types import SimpleNamespace

import numpy as np
import pytest

import rocking
from rocking.models import ccrr as ccrr_module
from rocking.models import simulate, simulate_many
from rocking.motions import OneCosine, Record, Sine

# the two models under comparison, each through the one entry point
housner = SimpleNamespace(simulate=partial(simulate, model="housner"),
                          simulate_many=partial(simulate_many, model="housner"))
ccrr = SimpleNamespace(DEFAULT_L=ccrr_module.DEFAULT_L, simulate=partial(simulate, model="ccrr"),
                       simulate_many=partial(simulate_many, model="ccrr"))

G = rocking.G
BLOCKS = [  # (alpha, p, mu): a generic block, specimens 2 (E), 3 (T) and 4 (T)
    (0.20, 2.00, 0.90),
    (0.163, 4.05, 0.973),
    (0.119, 3.82, 0.978),
    (0.310, 5.16, 0.860),
]


def _amplitudes(r: rocking.Response) -> np.ndarray:
    """Successive rocking amplitudes |theta| at the extrema of a finely sampled history."""
    a = np.abs(r.theta)
    i = np.flatnonzero((a[1:-1] >= a[:-2]) & (a[1:-1] >= a[2:]) & (a[1:-1] > 0)) + 1
    return a[i]


def _free_pair(block, l, n=6, dt_out=2e-4):
    th0 = 0.5 * block.alpha
    rh = housner.simulate(block, None, duration=6.0, theta0=th0, dt_out=dt_out)
    rc = ccrr.simulate(block, None, duration=6.0, theta0=th0, l=l, dt_out=dt_out)
    amp = np.abs(_amplitudes(rc)[:n] / _amplitudes(rh)[:n] - 1).max()
    tim = np.abs(rc.impact_times[:n] / rh.impact_times[:n] - 1).max()
    return amp, tim


@pytest.mark.parametrize("params", BLOCKS)
@pytest.mark.parametrize("l", [ccrr.DEFAULT_L, ccrr.DEFAULT_L / 10])
def test_converges_to_classical_model_as_l_vanishes(params, l):
    amp, tim = _free_pair(rocking.Block.from_params(*params), l)
    assert amp < 5e-3, f"amplitudes differ by {amp:.2%}"
    assert tim < 5e-3, f"zero-crossing times differ by {tim:.2%}"


def test_default_l_is_needed():
    """The convergence study behind DEFAULT_L: 100x larger l breaks the 0.5% agreement for
    at least one block, so the default is not arbitrary, while the error shrinks with l."""
    errs = {l: max(max(_free_pair(rocking.Block.from_params(*b), l)) for b in BLOCKS)
            for l in (1e-4, 1e-5, ccrr.DEFAULT_L)}
    assert errs[1e-4] > 5e-3
    assert errs[ccrr.DEFAULT_L] < errs[1e-4]
    assert errs[ccrr.DEFAULT_L] < 5e-3


@pytest.mark.parametrize("params", BLOCKS)
def test_velocity_ratio_through_one_passage_is_mu(params):
    """Energy before/after the first passage (Eq 12 with n = 1) gives |omega_a/omega_b| = mu."""
    b = rocking.Block.from_params(*params)
    th0 = 0.6 * b.alpha
    r = ccrr.simulate(b, None, duration=6.0, theta0=th0, dt_out=1e-4)
    r1 = _amplitudes(r)[0]
    ratio = math.sqrt((math.cos(b.alpha - r1) - math.cos(b.alpha))
                      / (math.cos(b.alpha - th0) - math.cos(b.alpha)))
    assert ratio == pytest.approx(b.mu, rel=1e-3)


def test_eq9_coefficient_would_not_give_mu():
    """Sanity of the derivation: the passage multiplies energy by exp(c pi); Eq 9's
    c = ln(mu)/pi gives sqrt(mu) for the velocity, Eq 10's 2 ln(mu)/pi gives mu."""
    mu = 0.86
    assert math.exp(0.5 * (2 * math.log(mu) / math.pi) * math.pi) == pytest.approx(mu)
    assert math.exp(0.5 * (math.log(mu) / math.pi) * math.pi) == pytest.approx(math.sqrt(mu))


def test_harmonic_response_matches_classical():
    b = rocking.specimen(2, "experimental")
    m = Sine(5.0, 0.005, 6.0)
    rh = housner.simulate(b, m)
    rc = ccrr.simulate(b, m)
    assert rc.max_abs_theta == pytest.approx(rh.max_abs_theta, rel=0.02)
    assert rc.uplift_time == pytest.approx(rh.uplift_time, abs=1e-6)


def test_pulse_overturning_agrees_with_classical():
    """One-cosine pulse, p = 2, alpha = 15 deg, mu = 0.9, Tp = 2 s: both models give the
    same outcome over a grid of amplitudes (the boundary is not monotone: a narrow band
    near 0.33 g survives in both models, see the issue note)."""
    b = rocking.Block.from_params(math.radians(15), 2.0, 0.9)
    amps = np.round(np.arange(0.26, 0.45, 0.01), 2)
    ms = [OneCosine(a * G, 2.0, duration=30.0) for a in amps]
    oh = housner.simulate_many(b, ms).overturned
    oc = ccrr.simulate_many(b, ms).overturned
    np.testing.assert_array_equal(oc, oh)
    assert not oc[list(amps).index(0.30)]
    assert oc[list(amps).index(0.32)] and oc[list(amps).index(0.34)]


def test_constant_step_rkf_is_fourth_order():
    """On a smooth segment (free motion before the first impact) the constant-step RKF45
    error falls as dt^4."""
    b = rocking.Block.from_params(0.2, 2.0, 0.9)
    th0 = 0.8 * b.alpha
    T = 0.5  # s, well before the first zero crossing (~0.93 s)
    ref = ccrr.simulate(b, None, duration=T, theta0=th0, rtol=1e-13, dt_out=T).theta[-1]
    dts = np.array([0.1, 0.05, 0.025, 0.0125])
    errs = [abs(ccrr.simulate(b, None, duration=T, theta0=th0, dt=dt, dt_out=T).theta[-1] - ref)
            for dt in dts]
    order = np.polyfit(np.log(dts), np.log(errs), 1)[0]
    assert 3.6 < order < 4.4, f"observed order {order:.2f}"


def test_earthquake_statistics_converge_to_classical():
    """Under random excitation single trajectories are chaotic (a 1e-4 change of mu moves
    the maximum angle by ~2%), so compare the statistics of a set of records: overturning
    fraction and median maximum angle of the standing blocks."""
    from scipy.signal import butter, sosfiltfilt

    rng = np.random.default_rng(11)
    b = rocking.specimen(2, "experimental")
    t = np.arange(1501) * 0.01
    env = np.clip(t / 2, 0, 1) * np.clip((15 - t) / 4, 0, 1)
    sos = butter(4, (1.0, 10.0), btype="bandpass", fs=100.0, output="sos")
    recs = []
    for _ in range(200):
        x = sosfiltfilt(sos, rng.standard_normal(t.size)) * env
        recs.append(Record(rng.uniform(2.8, 4.0) * x / np.abs(x).max(), 0.01))
    h = rocking.simulate_many(b, recs)
    c = rocking.simulate_many(b, recs, model="ccrr")
    assert abs(c.overturned.mean() - h.overturned.mean()) <= 0.05
    med_h = np.median(h.max_abs_theta[~h.overturned])
    med_c = np.median(c.max_abs_theta[~c.overturned])
    assert med_c == pytest.approx(med_h, rel=0.05)


def test_batch_equals_single_runs():
    rng = np.random.default_rng(3)
    b = rocking.specimen(2, "experimental")
    recs = []
    for _ in range(4):
        x = np.convolve(rng.standard_normal(801), np.hanning(25), "same")
        recs.append(Record(2.5 * x / np.abs(x).max(), 0.01))
    batch = rocking.simulate_many(b, recs, model="ccrr")
    single = [rocking.simulate(b, m, model="ccrr").max_abs_theta for m in recs]
    np.testing.assert_allclose(batch.max_abs_theta, single, rtol=1e-9)


def test_symmetry_under_flipped_motion():
    b = rocking.specimen(2, "experimental")
    m = Sine(3.0, 0.006, 4.0)
    # psi and psi + pi are not bit-symmetric in floating point, so the mirror image holds
    # to the integration tolerance: check it at a tight one
    r1 = ccrr.simulate(b, m, rtol=1e-10)
    r2 = ccrr.simulate(b, -m, rtol=1e-10)
    np.testing.assert_allclose(r1.theta, -r2.theta, atol=1e-9)


def test_bad_options():
    b = rocking.specimen(2)
    with pytest.raises(rocking.ParameterError, match="l must be"):
        ccrr.simulate(b, None, duration=1.0, theta0=0.01, l=0.0)
    with pytest.raises(rocking.ParameterError, match="dt must be"):
        ccrr.simulate(b, None, duration=1.0, theta0=0.01, dt=-1.0)
    with pytest.raises(rocking.ParameterError, match="linear"):
        rocking.simulate(b, None, model="ccrr", duration=1.0, theta0=0.01, linear=True)
