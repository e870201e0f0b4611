"""The initial tilt theta0 drawn truncated to |theta0| < alpha (Monte Carlo and campaigns):
the draws follow the truncated distribution, are counted, leave the samples that needed no
redraw exactly as they were, and a distribution with more than 1 % of its mass beyond
alpha is refused."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

import rocking
from rocking import ParameterError, campaign
from rocking.analysis.distributions import MAX_COV, frozen, mass_beyond
from rocking.analysis.montecarlo import PARAMETERS, STREAM, draw_samples, monte_carlo
from rocking.campaign.report import report, summary_lines
from rocking.motions import Sine

BLOCK = rocking.specimen(2, "experimental")  # alpha = 0.163 rad
A = BLOCK.alpha
# theta0 ~ N(0.03, 0.055): 0.80 % of the mass beyond +-alpha (allowed: at most 1 %)
MEAN, STD = 0.03, 0.055
THETA0 = {"dist": "normal", "mean": MEAN, "std": STD}
BEYOND = stats.norm(MEAN, STD).sf(A) + stats.norm(MEAN, STD).cdf(-A)


def _old_draws(block, uncertain, i, seed):
    """The draws of sample ``i`` as made before the truncation (clamp at 0.999 alpha): the
    reference that untruncated samples must still equal."""
    rng = np.random.default_rng(np.random.SeedSequence(seed, spawn_key=(STREAM, i)))
    v = {}
    for k, (nominal, (lo, hi)) in PARAMETERS.items():
        if k not in uncertain:
            v[k] = nominal(block)
            continue
        d = frozen(k, uncertain[k], nominal(block))
        while True:
            x = float(d.rvs(random_state=rng))
            if lo < x < hi:
                break
        v[k] = x
    if abs(v["theta0"]) >= v["alpha"]:
        v["theta0"] = math.copysign(0.999 * v["alpha"], v["theta0"])
    return v


def test_theta0_follows_the_truncated_normal():
    n = 6000
    unc = {"theta0": THETA0}
    table, _, _ = draw_samples(BLOCK, [Sine(2.0, 0.001, 0.5)], unc, n, seed=3)
    th = table["theta0"].to_numpy()
    assert np.all(np.abs(th) < A)
    assert not np.any(np.isclose(np.abs(th), 0.999 * A))  # no clamped atom
    # the truncated normal's closed-form mean and variance
    tn = stats.truncnorm((-A - MEAN) / STD, (A - MEAN) / STD, loc=MEAN, scale=STD)
    se = tn.std() / math.sqrt(n)
    assert abs(th.mean() - tn.mean()) < 4 * se
    assert stats.kstest(th, tn.cdf).pvalue > 1e-3
    # the flagged fraction is the mass beyond alpha (binomial, 4 standard errors)
    k = int(table["theta0_truncated"].sum())
    assert abs(k / n - BEYOND) < 4 * math.sqrt(BEYOND * (1 - BEYOND) / n) and k > 0


def test_samples_not_truncated_keep_their_draws_exactly():
    """Every parameter of a sample whose theta0 needed no redraw is the value drawn before
    the truncation existed (same random stream); truncated samples are those whose first
    theta0 draw lay beyond alpha."""
    unc = {"alpha": {"dist": "normal", "cov": 0.03}, "p": {"dist": "lognormal", "beta": 0.05},
           "theta0": THETA0, "amplitude": {"dist": "normal", "mean": 1.0, "std": 0.03},
           "noise": {"dist": "uniform", "low": 0.0, "high": 0.05}}
    n, seed = 1500, 21
    table, _, _ = draw_samples(BLOCK, [Sine(2.0, 0.001, 0.5)], unc, n, seed)
    assert table["theta0_truncated"].sum() > 0
    for i in range(n):
        old = _old_draws(BLOCK, unc, i, seed)
        row = table.iloc[i]
        clamped = abs(old["theta0"]) == 0.999 * old["alpha"]
        assert bool(row["theta0_truncated"]) == clamped, i
        if not clamped:
            for k in PARAMETERS:
                assert row[k] == old[k], (i, k)
        else:
            assert abs(row["theta0"]) < row["alpha"] and row["theta0"] != old["theta0"]


def test_monte_carlo_counts_the_truncated_draws():
    m = Sine(2.0, 0.02, 1.0)
    res = monte_carlo(BLOCK, m, {"theta0": THETA0}, n=800, seed=4)
    k = int(res.samples["theta0_truncated"].sum())
    assert res.n_theta0_truncated == k > 0
    assert res.summary()["n_theta0_truncated"] == k
    assert (res.samples["theta0"].abs() < res.samples["alpha"]).all()
    # without an uncertain theta0 nothing is truncated
    plain = monte_carlo(BLOCK, m, {"amplitude": {"dist": "uniform", "low": 0.9, "high": 1.1}},
                        n=20, seed=4)
    assert plain.n_theta0_truncated == 0


def test_mass_beyond_alpha_closed_form_and_with_uncertain_alpha():
    d = frozen("theta0", {"dist": "normal", "mean": 0.0, "std": 0.05}, 0.0)
    assert mass_beyond(d, A) == pytest.approx(2 * stats.norm.sf(A / 0.05), rel=1e-12)
    # alpha uncertain: the probability averaged over alpha's distribution (numerically)
    a = frozen("alpha", {"dist": "normal", "cov": 0.2}, A)
    x = np.linspace(1e-6, math.pi / 2, 200001)
    w = a.pdf(x) / (a.cdf(math.pi / 2) - a.cdf(0.0))
    ref = np.trapezoid(w * 2 * stats.norm.sf(x / 0.05), x)
    assert mass_beyond(d, a, (0.0, math.pi / 2)) == pytest.approx(ref, rel=1e-6)
    assert ref > mass_beyond(d, A)  # a smaller alpha weighs more


def test_a_theta0_with_more_than_one_percent_beyond_alpha_is_refused():
    m = Sine(2.0, 0.02, 1.0)
    # 1.3 % beyond: refused, naming the key, before any run
    wide = {"dist": "normal", "mean": 0.0, "std": A / stats.norm.isf(0.0065)}
    with pytest.raises(ParameterError, match=r"uncertain\['theta0'\].*1\.3% .*alpha"):
        monte_carlo(BLOCK, m, {"theta0": wide}, n=5)
    # 0.9 % at the nominal alpha: accepted; with an uncertain alpha the average is above 1 %
    near = {"dist": "normal", "mean": 0.0, "std": A / stats.norm.isf(0.0045)}
    draw_samples(BLOCK, [m], {"theta0": near}, 2, seed=0)
    with pytest.raises(ParameterError, match=r"uncertain\['theta0'\]"):
        draw_samples(BLOCK, [m], {"theta0": near, "alpha": {"dist": "normal", "cov": 0.25}},
                     2, seed=0)
    # a fixed tilt beyond alpha, and a uniform reaching past it
    with pytest.raises(ParameterError, match=r"uncertain\['theta0'\]: 100%"):
        monte_carlo(BLOCK, m, {"theta0": {"dist": "fixed", "value": 0.2}}, n=5)
    with pytest.raises(ParameterError, match=r"uncertain\['theta0'\]"):
        monte_carlo(BLOCK, m, {"theta0": {"dist": "uniform", "low": -0.2, "high": 0.2}}, n=5)


def test_monte_carlo_refuses_distributions_outside_the_range():
    m = Sine(2.0, 0.02, 1.0)
    with pytest.raises(ParameterError, match=r"uncertain\['noise'\]: 100%.*\[0, inf\)"):
        monte_carlo(BLOCK, m, {"noise": {"dist": "fixed", "value": -0.1}}, n=5)
    with pytest.raises(ParameterError, match=r"uncertain\['alpha'\].*std/mean <= 0.43"):
        monte_carlo(BLOCK, m, {"alpha": {"dist": "normal", "cov": 0.5}}, n=5)
    with pytest.raises(ParameterError, match=r"uncertain\['alpha'\]\['cov'\].*bool"):
        monte_carlo(BLOCK, m, {"alpha": {"dist": "normal", "cov": True}}, n=5)
    with pytest.raises(ParameterError, match=r"uncertain\['alpha'\]\['dist'\]"):
        monte_carlo(BLOCK, m, {"alpha": {"dist": ["normal"], "cov": 0.1}}, n=5)
    # the bound on cov is exactly where 1 % of a normal falls below zero
    assert stats.norm(1.0, MAX_COV).cdf(0.0) == pytest.approx(0.01, rel=1e-9)
    draw_samples(BLOCK, [m], {"amplitude": {"dist": "normal", "cov": 0.99 * MAX_COV}}, 2, 0)
    with pytest.raises(ParameterError, match=r"uncertain\['amplitude'\]"):
        draw_samples(BLOCK, [m], {"amplitude": {"dist": "normal", "cov": 1.01 * MAX_COV}},
                     2, 0)


SPEC = """
[campaign]
name = "tilt"
seed = 5
model = "housner"
samples = 600

[[blocks]]
specimen = 2
params = "experimental"

[motions]
kind = "sine"
frequency = [2.0]
cycles = 2
amplitude = 0.5
load_factors = [1.0]

[uncertain]
theta0 = {dist = "normal", mean = 0.03, std = 0.055}

[run]
chunk_size = 300
"""


def test_campaign_rows_flag_truncated_tilts_and_the_report_counts_them(tmp_path):
    spec = campaign.parse_spec(SPEC)
    c = campaign.Campaign(spec)
    table = c.table()
    assert table["theta0_truncated"].dtype == bool
    assert (table["theta0"].abs() < table["alpha"]).all()
    k = int(table["theta0_truncated"].sum())
    assert k > 0
    # a flagged row is one whose first draw in its stream lay beyond alpha
    for r in table.itertuples():
        rng = np.random.default_rng(np.random.SeedSequence(5, spawn_key=(3, r.sim_id)))
        first = stats.norm(MEAN, STD).rvs(random_state=rng)
        assert (abs(first) >= A) == r.theta0_truncated
        if not r.theta0_truncated:
            assert r.theta0 == first
    campaign.run(spec, tmp_path / "store", progress=False)
    rows = campaign.load(tmp_path / "store")
    assert rows["theta0_truncated"].sum() == k
    res = report(rows, campaign.Store(tmp_path / "store").manifest, tmp_path / "report")
    line = f"initial tilt: {k} of {spec.n_sims} runs drew theta0 at or beyond +-alpha"
    assert res["n_theta0_truncated"] == k
    assert line in (tmp_path / "report" / "report.md").read_text()
    assert any(s.startswith(line) for s in summary_lines(res))


def test_campaign_spec_refuses_theta0_beyond_alpha_of_a_block():
    text = SPEC.replace("samples = 600", "samples = 2").replace(
        "[motions]", "[[blocks]]\nalpha = 0.08\np = 3.0\nmu = 0.9\n\n[motions]")
    with pytest.raises(rocking.errors.SpecError,
                       match=r"^spec: uncertain\.theta0: .* beyond \+-alpha \(alpha of "
                             r"blocks\[1\] = 0\.08 rad\)"):
        campaign.parse_spec(text)
