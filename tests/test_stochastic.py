"""The stochastic ground-motion model (Rezaeian & Der Kiureghian 2008) and the rocking
intensity measures.

Statistical checks use fixed seeds (the tests are deterministic) and tolerances of about
4.5 standard errors of the compared means (or standard deviations), estimated from the
samples themselves. The distribution of PGA and of the 5 %-damped spectrum is compared
with a reference written here directly from the paper's equations: the explicit matrix
``S[k, i] = h(t_k - t_i; omega_f(t_i)) / sigma_f(t_k)`` (no phasors, no truncation), the
gamma modulating function solved with ``scipy.stats.gamma``, and the high-pass discretised
with ``scipy.signal.cont2discrete(..., method="foh")`` (exact for a piecewise-linear
input) and applied with ``lfilter``; its records are ``U @ M.T`` for independent noise.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import optimize, signal, stats

from rocking import Block, ParameterError
from rocking.motions import Record, intensity_measures, response_spectrum, stochastic_records
from rocking.motions.processing import significant_duration_acc
from rocking.units import G

TWO_PI = 2.0 * math.pi
TOL_SE = 4.5


def _close(a, b, se, what):
    assert abs(a - b) <= TOL_SE * se, f"{what}: {a:.5g} vs {b:.5g} (se {se:.3g})"


# --------------------------------------------------------------------------- reference
def _reference_matrix(Ia, D5_95, t_mid, omega_mid, omega_prime, zeta_f, omega_c, dt, N):
    """``M`` (N x N): the final record is ``M @ u`` for the N unit pulses ``u``."""
    def ratio(k):
        ppf = stats.gamma(k).ppf
        return (ppf(0.95) - ppf(0.05)) / ppf(0.45)

    k = optimize.brentq(lambda k: ratio(k) - D5_95 / t_mid, 1.0 + 1e-6, 1e4, xtol=1e-13)
    scale = t_mid / stats.gamma(k).ppf(0.45)
    a2, a3 = (k + 1) / 2, 1 / (2 * scale)
    a1 = math.sqrt(Ia * 2 * G / math.pi * (2 * a3) ** k / math.gamma(k))
    t = np.arange(N) * dt
    q = a1 * t ** (a2 - 1) * np.exp(-a3 * t)
    wf = omega_mid + omega_prime * (t - t_mid)
    lag = t[:, None] - t[None, :]
    wd = wf[None, :] * math.sqrt(1 - zeta_f**2)
    h = np.where(lag >= 0, wf[None, :] / math.sqrt(1 - zeta_f**2)
                 * np.exp(-zeta_f * wf[None, :] * np.maximum(lag, 0)) * np.sin(wd * lag), 0.0)
    norm = np.sqrt((h**2).sum(axis=1))
    S = np.divide(h, norm[:, None], out=np.zeros_like(h), where=norm[:, None] > 0)
    M = q[:, None] * S
    num, den, _ = signal.cont2discrete(([1.0, 0.0, 0.0], [1.0, 2 * omega_c, omega_c**2]),
                                       dt, method="foh")
    return signal.lfilter(np.ravel(num), den, M, axis=0), t


def _expected_arias(M, dt):
    """Exact expected Arias intensity of the records ``M @ u`` (linear between samples)."""
    c0 = (M**2).sum(axis=1)
    c1 = (M[:-1] * M[1:]).sum(axis=1)
    return math.pi / (2 * G) * dt / 3 * float((c0[:-1] + c1 + c0[1:]).sum())


REF = {"Ia": 0.3, "D5_95": 5.0, "t_mid": 4.0, "omega_mid": TWO_PI * 4.0,
       "omega_prime": -TWO_PI * 0.1, "zeta_f": 0.25, "omega_c": TWO_PI * 0.2, "dt": 0.02}
PERIODS = np.array([0.05, 0.1, 0.2, 0.5, 1.0, 2.0])


@pytest.fixture(scope="module")
def reference():
    gen = stochastic_records(400, seed=2024, **REF)
    N = gen[0].acc.size
    M, t = _reference_matrix(**REF, N=N)
    factor = math.sqrt(REF["Ia"] / _expected_arias(M, REF["dt"]))
    U = np.random.default_rng(99).standard_normal((2000, N))
    ref = (U @ M.T) * factor
    return gen, ref, factor


def test_normalisation_matches_the_reference(reference):
    gen, _, factor = reference
    # the generator scales alpha_1 so that the exact expected Arias intensity of its final
    # records is Ia; the reference computes the same factor from its own matrix
    assert gen[0].meta["alpha1_factor"] == pytest.approx(factor, rel=1e-8)


def _log_stats(x):
    lx = np.log(x)
    return lx.mean(), lx.std(ddof=1), lx.size


def test_pga_and_spectrum_distribution_match_the_reference(reference):
    gen, ref, _ = reference
    dt = REF["dt"]
    pga_g = np.array([np.abs(r.acc).max() for r in gen])
    pga_r = np.abs(ref).max(axis=1)
    sa_g = np.array([response_spectrum(r, PERIODS) for r in gen])
    sa_r = np.array([response_spectrum(a, PERIODS, dt=dt) for a in ref])
    for name, xg, xr in [("PGA", pga_g, pga_r)] + [
            (f"PSA({T:g} s)", sa_g[:, j], sa_r[:, j]) for j, T in enumerate(PERIODS)]:
        mg, sg, ng = _log_stats(xg)
        mr, sr, nr = _log_stats(xr)
        _close(mg, mr, math.hypot(sg / math.sqrt(ng), sr / math.sqrt(nr)), f"mean ln {name}")
        _close(sg, sr, math.hypot(sg / math.sqrt(2 * ng), sr / math.sqrt(2 * nr)),
               f"std ln {name}")


def test_arias_duration_and_tmid_match_the_parameters():
    p = {"Ia": 0.5, "D5_95": 10.0, "t_mid": 6.0}
    recs = stochastic_records(100, seed=7, **p)
    ims = [intensity_measures(r) for r in recs]
    ia = np.array([m["arias"] for m in ims])
    d = np.array([m["d5_95"] for m in ims])
    tm = np.array([significant_duration_acc(r.acc, r.dt, 0.05, 0.45)[2] for r in recs])
    n = len(recs)
    _close(ia.mean(), p["Ia"], ia.std(ddof=1) / math.sqrt(n), "Arias intensity")
    _close(d.mean(), p["D5_95"], d.std(ddof=1) / math.sqrt(n), "D5-95")
    _close(tm.mean(), p["t_mid"], tm.std(ddof=1) / math.sqrt(n), "t_mid")


def test_predominant_frequency_and_its_drift():
    # zero crossings: a Gaussian process crosses zero at the rate sqrt(lambda2/lambda0)/pi,
    # and for the filter h (an oscillator's displacement times omega_f) under white noise
    # sqrt(lambda2/lambda0) = omega_f; q > 0 does not move the crossings
    wm, wp, tmid = TWO_PI * 5.0, -TWO_PI * 0.25, 6.0
    recs = stochastic_records(100, seed=5, omega_mid=wm, omega_prime=wp, t_mid=tmid,
                              dt=0.005, duration=16.0)
    A = np.array([r.acc for r in recs])
    t = recs[0].t[:-1]
    cross = np.signbit(A[:, 1:]) != np.signbit(A[:, :-1])
    centres = np.array([3.0, 6.0, 9.0, 12.0])
    est, se = [], []
    for c in centres:
        w = (t >= c - 1.5) & (t < c + 1.5)
        om = math.pi * cross[:, w].sum(axis=1) / 3.0
        est.append(om.mean())
        se.append(om.std(ddof=1) / math.sqrt(om.size))
    est, se = np.array(est), np.array(se)
    # + 2 % for what the sampling and the high-pass add to the crossing rate
    _close(est[1], wm, math.hypot(se[1], 0.02 * wm), "omega_f(t_mid)")
    slope = np.polyfit(centres, est, 1)[0]
    se_slope = math.sqrt((se**2).mean() / ((centres - centres.mean())**2).sum())
    _close(slope, wp, math.hypot(se_slope, 0.02 * abs(wp)), "omega_prime")


def test_velocity_and_displacement_return_to_zero():
    for r in stochastic_records(20, seed=3):
        m = r.intensity_measures()
        assert abs(m["v_end"]) < 1e-2 * m["pgv"]
        assert abs(m["d_end"]) < 2e-2 * m["pgd"]


def test_reproducible_and_chunk_independent():
    a = stochastic_records(20, seed=11)
    b = stochastic_records(10, seed=11) + stochastic_records(10, seed=11, start=10)
    c = stochastic_records(1, seed=11, start=13)
    for x, y in zip(a, b, strict=True):
        assert np.array_equal(x.acc, y.acc)
    assert np.array_equal(a[13].acc, c[0].acc)
    assert all(isinstance(r, Record) and r.number == i for i, r in enumerate(a))
    d = stochastic_records(2, seed=12)
    assert not np.allclose(a[0].acc, d[0].acc)
    assert not np.allclose(a[0].acc, a[1].acc)
    e = stochastic_records(1, seed=None)
    assert np.array_equal(e[0].acc, stochastic_records(1, seed=e[0].meta["seed"])[0].acc)


def test_rocking_intensity_measures_of_a_cosine():
    amp, f, dt = 1.5, 1.0, 1e-4
    w = TWO_PI * f
    t = np.arange(int(round(2.0 / dt)) + 1) * dt
    rec = Record(amp * np.cos(w * t), dt)  # velocity (amp / w) sin(w t): PGV = amp / w
    block = Block.from_params(alpha=0.2, p=2.5, mu=0.7)
    m = rec.intensity_measures(block=block)
    g_tan = G * math.tan(0.2)
    assert m["pga_ratio"] == pytest.approx(amp / g_tan, rel=1e-12)
    assert m["pgv_ratio"] == pytest.approx(amp / w * 2.5 / g_tan, rel=1e-6)
    plain = intensity_measures(rec)
    assert "pga_ratio" not in plain and "pgv_ratio" not in plain
    assert {k: m[k] for k in plain} == plain
    assert intensity_measures(rec, block=block) == m
    with pytest.raises(ParameterError, match="block"):
        intensity_measures(rec, block=object())


@pytest.mark.parametrize("kw, name", [
    ({"n": 0}, "n"),
    ({"Ia": -0.1}, "Ia"),
    ({"D5_95": 0.0}, "D5_95"),
    ({"D5_95": 40.0}, "D5_95"),
    ({"zeta_f": 0.0}, "zeta_f"),
    ({"zeta_f": 1.0}, "zeta_f"),
    ({"omega_prime": -TWO_PI * 2}, "omega_prime"),
    ({"dt": -0.01}, "dt"),
    ({"seed": -1}, "seed"),
])
def test_bad_input_names_the_parameter(kw, name):
    kw = {"n": 1, "seed": 0, **kw}
    with pytest.raises(ParameterError, match=name):
        stochastic_records(**kw)
