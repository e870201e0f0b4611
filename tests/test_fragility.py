"""Fragility fits (issue 10): statistics of the MLE, the bootstrap band, censoring,
the hazard integral, damage states and bad input. Synthetic data are drawn from known
lognormal fragilities with fixed seeds; expected values come from the true parameters or
closed forms, never from earlier outputs of this code."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.stats import norm

from rocking import ParameterError
from rocking.analysis.damage import damage_state, fragility_curves
from rocking.analysis.fragility import (
    PELICUN_COLUMNS,
    annual_frequency,
    fragility,
    fragility_ida,
)
from rocking.units import G

MEDIAN, BETA = 2.0, 0.4                       # m/s^2 (PGA), lognormal dispersion
LEVELS = MEDIAN * np.exp(np.linspace(-2.0, 2.0, 20) * BETA)   # 20 stripes


def stripes(rng, n=50, median=MEDIAN, beta=BETA):
    im = np.repeat(LEVELS, n)
    return im, rng.random(im.size) < norm.cdf(np.log(im / median) / beta)


def test_mle_recovers_median_and_beta():
    fit = fragility(*stripes(np.random.default_rng(10)), n_boot=0)
    assert abs(fit.median - MEDIAN) < 3 * fit.median_se
    assert abs(fit.beta - BETA) < 3 * fit.beta_se
    # the standard errors are those of 1000 records, not absurd
    assert 0.005 < fit.median_se / MEDIAN < 0.05 and 0.01 < fit.beta_se / BETA < 0.15
    assert fit.probability(fit.median) == pytest.approx(0.5)
    s = fit.summary()
    assert s["n"] == 1000 and s["n_stripes"] == 20
    json.dumps(fit.to_dict())


def test_stripe_form_equals_record_form():
    im, f = stripes(np.random.default_rng(3), n=10)
    per_stripe = [f[im == v] for v in LEVELS]
    a, b = fragility(im, f, n_boot=0), fragility(LEVELS, per_stripe, n_boot=0)
    assert a.median == pytest.approx(b.median, rel=1e-10)
    assert a.beta == pytest.approx(b.beta, rel=1e-10)


def test_band_covers_true_curve_and_standard_errors_are_calibrated():
    """200 replications of 20 stripes x 50 records: the pointwise 95% band (normal
    bootstrap of the GLM coefficients, 400 draws) covers the true curve at each of three
    IMs in >= 90% of them; the delta-method z-scores have mean ~0 and spread ~1."""
    rng = np.random.default_rng(2015)
    x = MEDIAN * np.exp(np.array([-1.0, 0.0, 1.0]) * BETA)
    p_true = norm.cdf(np.log(x / MEDIAN) / BETA)
    covered, z = [], []
    for i in range(200):
        fit = fragility(*stripes(rng), n_boot=400, seed=i)
        b = fit.band(x, level=0.95)
        assert np.all(b["lower"] <= b["probability"]) and np.all(b["probability"] <= b["upper"])
        covered.append((b["lower"].to_numpy() <= p_true) & (p_true <= b["upper"].to_numpy()))
        z.append([(fit.median - MEDIAN) / fit.median_se, (fit.beta - BETA) / fit.beta_se])
    rate = np.mean(covered, axis=0)
    print("coverage per IM", rate, "all three", np.mean(np.all(covered, axis=1)))
    assert np.all(rate >= 0.90), rate
    assert np.all(rate <= 0.995), rate                    # not a uselessly wide band
    z = np.array(z)
    print("z mean", z.mean(0), "z sd", z.std(0))
    assert np.all(np.abs(z.mean(0)) < 0.25)
    assert np.all((0.8 < z.std(0)) & (z.std(0) < 1.25))


def test_resample_bootstrap_agrees_with_normal():
    im, f = stripes(np.random.default_rng(5))
    a = fragility(im, f, n_boot=300, seed=1)
    b = fragility(im, f, n_boot=300, seed=1, bootstrap="resample")
    assert b.n_boot + b.n_boot_failed == 300
    wa = np.diff(a.ci()["median"])[0]
    wb = np.diff(b.ci()["median"])[0]
    assert wb == pytest.approx(wa, rel=0.3)
    # the interval is about +-1.96 standard errors
    assert wa == pytest.approx(2 * 1.96 * a.median_se, rel=0.2)
    # seeded: the same seed gives the same band
    c = fragility(im, f, n_boot=300, seed=1)
    np.testing.assert_array_equal(a.boot_coef, c.boot_coef)


def test_ida_censoring_recovers_median_and_naive_fit_is_biased():
    """Capacities above the top IM level (1.2 x median: ~32% of the records) are
    censored. The censored MLE recovers the median; dropping the censored records (the
    strongest ones) biases it low, by several standard errors."""
    rng = np.random.default_rng(7)
    top = 1.2 * MEDIAN
    errs, naive_errs = [], []
    for _ in range(30):
        cap = MEDIAN * np.exp(BETA * rng.standard_normal(200))
        cens = cap > top
        cap[cens] = top
        fit = fragility_ida(cap, cens, n_boot=0)
        naive = fragility_ida(cap[~cens], n_boot=0)
        errs.append((fit.median - MEDIAN) / fit.median_se)
        naive_errs.append(naive.median - MEDIAN)
        assert abs(fit.beta - BETA) < 4 * fit.beta_se
    errs, naive_errs = np.array(errs), np.array(naive_errs)
    print("censored z mean", errs.mean(), "naive bias", naive_errs.mean() / MEDIAN)
    assert abs(errs.mean()) < 0.5 and np.all(np.abs(errs) < 4)
    assert naive_errs.mean() < -0.1 * MEDIAN                     # >10% low on average
    assert np.all(naive_errs < 0)


def test_ida_without_censoring_is_the_lognormal_mle():
    cap = MEDIAN * np.exp(BETA * np.random.default_rng(1).standard_normal(100))
    fit = fragility_ida(cap, n_boot=0)
    logs = np.log(cap)
    assert fit.median == pytest.approx(math.exp(logs.mean()), rel=1e-4)
    assert fit.beta == pytest.approx(logs.std(), rel=1e-3)
    assert fit.median_se == pytest.approx(fit.median * logs.std() / 10, rel=0.02)


@pytest.mark.parametrize("k", [1.5, 2.5, 3.0])
def test_annual_frequency_closed_form(k):
    """Power-law hazard k0 im^-k and a lognormal fragility: Cornell et al. (2002)."""
    cap = MEDIAN * np.exp(BETA * np.random.default_rng(0).standard_normal(60))
    fit = fragility_ida(cap, n_boot=0)
    k0 = 1e-3
    im = np.geomspace(1e-3, 1e3, 40)
    exact = k0 * fit.median**-k * math.exp(k**2 * fit.beta**2 / 2)
    assert annual_frequency(fit, im, k0 * im**-k) == pytest.approx(exact, rel=1e-6)


def test_annual_frequency_bad_hazard():
    fit = fragility_ida([1.0, 2.0, 3.0, 1.5], n_boot=0)
    im = np.array([0.1, 1.0, 10.0])
    with pytest.raises(ParameterError, match="hazard_rate"):
        annual_frequency(fit, im, [1e-2, 1e-1, 1e-4])
    with pytest.raises(ParameterError, match="hazard_rate"):
        annual_frequency(fit, im, [1e-2, 0.0, 0.0])
    with pytest.raises(ParameterError, match="hazard_im"):
        annual_frequency(fit, im[::-1], [1e-2, 1e-3, 1e-4])
    with pytest.raises(ParameterError, match="hazard_im"):
        annual_frequency(fit, [-1.0, 1.0, 2.0], [1e-2, 1e-3, 1e-4])
    with pytest.raises(ParameterError, match="same length"):
        annual_frequency(fit, im, [1e-2, 1e-3])


def test_damage_state_thresholds():
    alpha = 0.2
    theta = alpha * np.array([0.0, 0.1, 0.25, 0.3, 0.5, 0.9, 0.4, np.nan])
    over = np.array([0, 0, 0, 0, 0, 0, 1, 1], bool)
    np.testing.assert_array_equal(damage_state(theta, alpha, over), [0, 0, 1, 1, 2, 2, 3, 3])
    np.testing.assert_array_equal(damage_state(theta[:3], alpha, over[:3], thresholds=[0.05]),
                                  [0, 1, 1])
    with pytest.raises(ParameterError, match="thresholds"):
        damage_state(theta, alpha, over, thresholds=(0.5, 0.25))
    with pytest.raises(ParameterError, match="max_abs_theta"):
        damage_state(theta, alpha, np.zeros(8, bool))


def _ordinal_data(rng, medians, betas, n=60):
    im = np.repeat(np.geomspace(0.3, 8.0, 15), n)
    u = rng.standard_normal(im.size)          # one latent capacity per record
    exceed = np.log(im)[:, None] - np.log(medians)[None, :] >= np.asarray(betas) * u[:, None]
    return im, np.cumprod(exceed, axis=1).sum(axis=1)


def test_damage_curves_common_beta_recover_and_do_not_cross():
    medians = np.array([0.8, 1.5, 2.5])
    im, state = _ordinal_data(np.random.default_rng(4), medians, [0.45] * 3)
    curves = fragility_curves(im, state, n_boot=200)
    for f, m in zip(curves.fits, medians, strict=True):
        assert abs(f.median - m) < 3 * f.median_se
        assert abs(f.beta - 0.45) < 3 * f.beta_se
    assert np.all(np.diff(curves.medians) > 0) and np.ptp(curves.betas) == 0
    x = np.geomspace(im.min(), im.max(), 300)
    p = curves.probability(x).drop(columns="im").to_numpy()
    assert np.all(np.diff(p, axis=1) <= 0)                          # P(DS>=k) decreasing in k
    for a, b in zip(curves.fits[:-1], curves.fits[1:], strict=True):  # every bootstrap draw
        pa = norm.cdf(a.boot_coef[:, :1] + a.boot_coef[:, 1:] * np.log(x))
        pb = norm.cdf(b.boot_coef[:, :1] + b.boot_coef[:, 1:] * np.log(x))
        assert np.all(pb <= pa)
    sp = curves.state_probability(x).drop(columns="im").to_numpy()
    np.testing.assert_allclose(sp.sum(axis=1), 1.0)
    assert np.all(sp >= 0)
    # the same curves from the ratio and the overturning flag
    ratio = np.array([0.1, 0.3, 0.7, np.nan])[state]
    again = fragility_curves(im, ratio=ratio, overturned=state == 3, n_boot=0)
    np.testing.assert_allclose(again.medians, curves.medians, rtol=1e-6)
    json.dumps(curves.to_dict())


def test_separate_fits_that_cross_are_refused():
    """Different true betas make the separate MLE curves cross inside the data range;
    the common-beta fit of the same data does not."""
    im, state = _ordinal_data(np.random.default_rng(8), [1.0, 1.3], [0.8, 0.2])
    with pytest.raises(ParameterError, match="cross"):
        fragility_curves(im, state, method="separate", n_boot=0)
    c = fragility_curves(im, state, n_boot=0)
    assert c.fits[0].median < c.fits[1].median


def test_missing_damage_state_is_refused():
    im, state = _ordinal_data(np.random.default_rng(4), [0.8, 1.5, 2.5], [0.45] * 3)
    with pytest.raises(ParameterError, match="damage state"):
        fragility_curves(im, np.where(state == 2, 3, state), n_boot=0)


def test_to_pelicun_columns_and_units():
    fit = fragility(*stripes(np.random.default_rng(1)), n_boot=0)
    row = fit.to_pelicun("block.overturning")
    assert row.index.name == "ID" and list(row.index) == ["block.overturning"]
    assert list(row.columns) == [*PELICUN_COLUMNS, "LS1-Family", "LS1-Theta_0", "LS1-Theta_1"]
    r = row.iloc[0]
    assert r["LS1-Family"] == "lognormal" and r["Demand-Unit"] == "g"
    assert r["LS1-Theta_0"] == pytest.approx(fit.median / G)      # m/s^2 -> g
    assert r["LS1-Theta_1"] == pytest.approx(fit.beta)
    si = fit.to_pelicun(demand_unit="mps2").iloc[0]
    assert si["LS1-Theta_0"] == pytest.approx(fit.median)
    with pytest.raises(ParameterError, match="demand_unit"):
        fit.to_pelicun(demand_unit="furlong")
    with pytest.raises(ParameterError, match="im_unit"):
        fit.to_pelicun(demand_unit="g", im_unit="mps")
    im, state = _ordinal_data(np.random.default_rng(4), [0.8, 1.5, 2.5], [0.45] * 3)
    table = fragility_curves(im, state, n_boot=0).to_pelicun(demand_unit="mps2")
    assert [f"LS{k}-Theta_0" for k in (1, 2, 3)] == [c for c in table.columns
                                                   if c.endswith("Theta_0")]


def test_plot_draws_curve_band_and_data():
    fit = fragility(*stripes(np.random.default_rng(1)), n_boot=100)
    ax = fit.plot()
    assert len(ax.lines) == 2 and len(ax.collections) == 1
    ida = fragility_ida(MEDIAN * np.exp(BETA * np.random.default_rng(2).standard_normal(40)),
                        n_boot=50)
    assert len(ida.plot().lines) == 2


@pytest.mark.parametrize("im, failed, match", [
    ([1.0, -2.0], [0, 1], "im must be > 0"),
    ([1.0, 0.0], [0, 1], "im must be > 0"),
    ([1.0, np.nan], [0, 1], "im must be finite"),
    ([1.0, 2.0], [0, 2], "failed must be boolean"),
    ([1.0, 2.0], ["no", "yes"], "failed must be boolean"),
    ([1.0, 2.0], [0.0, np.nan], "failed must be boolean"),
    ([1.0, 2.0, 3.0], [0, 1], "same length"),
    ([1.0, 2.0], [[0, 1], []], r"failed\[1\].*empty"),
    ([], [], "im must not be empty"),
])
def test_bad_input(im, failed, match):
    with pytest.raises(ParameterError, match=match):
        fragility(im, failed)


def test_degenerate_outcomes():
    im = np.repeat([1.0, 2.0, 3.0], 4)
    with pytest.raises(ParameterError, match="no record failed"):
        fragility(im, np.zeros(12, bool))
    with pytest.raises(ParameterError, match="every record failed"):
        fragility(im, np.ones(12, bool))
    with pytest.raises(ParameterError, match="separated"):
        fragility(im, im >= 2.0)
    with pytest.raises(ParameterError, match="capacity"):
        fragility_ida([1.0, 2.0, 3.0], [True, True, False])
    with pytest.raises(ParameterError, match="n_boot"):
        fragility(im, im >= 2.0, n_boot=-1)
    with pytest.raises(ParameterError, match="bootstrap"):
        fragility([1.0, 2.0, 1.0, 2.0], [0, 1, 1, 0], bootstrap="jackknife")


def test_fit_or_bounds_gives_the_bounds_the_outcomes_allow_and_refuses_bad_input():
    """No failure: the median is above the largest IM; all failed: below the smallest;
    separated: between the largest survival and the smallest failure; otherwise a fit
    equal to fragility()'s. A non-positive IM is still an error, never a 'no fit'."""
    from rocking.analysis.fragility import fit_or_bounds

    x = np.array([1.0, 2.0, 3.0, 4.0])
    fit, lo, hi, why = fit_or_bounds(x, [False] * 4)
    assert fit is None and (lo, why) == (4.0, "none failed") and np.isnan(hi)
    fit, lo, hi, why = fit_or_bounds(x, [True] * 4)
    assert fit is None and (hi, why) == (1.0, "all failed") and np.isnan(lo)
    fit, lo, hi, why = fit_or_bounds(x, [False, False, True, True])
    assert fit is None and (lo, hi, why) == (2.0, 3.0, "separated")
    xs = np.repeat(x, 4)
    ys = np.array([0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 1, 1, 1, 1], bool)
    fit, lo, hi, why = fit_or_bounds(xs, ys, n_boot=0)
    ref = fragility(xs, ys, n_boot=0)
    assert why == "" and fit.median == ref.median and fit.beta == ref.beta
    with pytest.raises(ParameterError):
        fit_or_bounds([0.0, 1.0], [False, True])
