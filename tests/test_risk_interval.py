"""The risk's uncertainty (issue 31, item 4): the interval of the annual frequency and of
the service-life probability from the fragility fit's bootstrap and the hazard's fractile
curves (``rocking.analysis.risk``, ``risk_interval``).

Checked against independent computations: the quadrature of :func:`risk` draw by draw (a
brute-force propagation), Cornell's closed form on a power law, and the monotonicity of
the annual frequency in the hazard's fractile.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy.stats import norm

from rocking.analysis import HazardCurve, fragility, probability_in, risk
from rocking.analysis.hazard import lognormal_risks, risk_interval, risk_text


def planted(n_per_stripe: int, seed: int = 0, n_boot: int = 400):
    """A fit to stripes drawn from a lognormal curve of median 3 m/s^2, beta 0.4."""
    rng = np.random.default_rng(seed)
    im = np.repeat([1.0, 2.0, 3.0, 4.0, 6.0], n_per_stripe)
    failed = rng.random(im.size) < norm.cdf(np.log(im / 3.0) / 0.4)
    return fragility(im, failed, n_boot=n_boot, seed=seed, im_name="pga", im_unit="m/s^2")


def hazard():
    """A hazard curve that is not a power law (its log-log slope grows with the PGA)."""
    x = np.geomspace(0.02, 2.0, 25)  # g
    rate = 1e-2 * np.exp(-3.0 * np.log(x / 0.02) ** 1.3 / 4)
    return HazardCurve(x, rate, im_name="PGA", unit="g", label="curved")


@dataclass
class Lognormal:  # a fit of one bootstrap draw, for the brute-force propagation
    median: float
    beta: float
    im_name: str = "pga"
    im_unit: str = "m/s^2"

    def probability(self, im):
        return norm.cdf(np.log(np.asarray(im, dtype=float) / self.median) / self.beta)


def test_vectorised_integral_equals_the_quadrature_and_the_closed_form():
    curve = hazard()
    med, beta = np.array([1.5, 3.0, 6.0]), np.array([0.2, 0.4, 0.9])
    lam = lognormal_risks(med, beta, curve, factor=9.80665)
    quad = [risk(Lognormal(m, b), curve).annual_frequency for m, b in zip(med, beta, strict=True)]
    np.testing.assert_allclose(lam, quad, rtol=1e-5)
    code = HazardCurve.from_code_value(0.25)  # (1/475) (a / 0.25 g)^-3
    closed = (0.25 / med) ** 3 / 475 * np.exp(9 * beta**2 / 2)  # median in g
    np.testing.assert_allclose(lognormal_risks(med, beta, code), closed, rtol=1e-6)


def test_interval_matches_a_brute_force_propagation_and_contains_the_estimate():
    fit = planted(40, n_boot=60)
    curve = hazard()
    r = risk(fit, curve, level=0.9)
    b0, b1 = fit.boot_coef.T
    ok = b1 > 0
    brute = [risk(Lognormal(math.exp(-a / b), 1 / b), curve).annual_frequency
             for a, b in zip(b0[ok], b1[ok], strict=True)]
    lo, hi = np.quantile(brute, [0.05, 0.95])
    assert r.annual_frequency_interval == pytest.approx((lo, hi), rel=1e-4)
    assert lo < r.annual_frequency < hi
    assert r.probability_interval == pytest.approx(
        (probability_in(50, lo), probability_in(50, hi)), rel=1e-4)
    assert r.probability_interval[0] < r.probability_50 < r.probability_interval[1]
    assert r.interval_level == 0.9 and "bootstrap (60 draws)" in r.interval_source
    # a wider level gives a wider interval
    r2 = risk(fit, curve, level=0.98)
    assert r2.annual_frequency_interval[0] < lo and r2.annual_frequency_interval[1] > hi


def test_interval_narrows_with_more_records():
    curve = hazard()
    widths = []
    for n in (10, 40, 160):
        r = risk(planted(n, seed=3), curve)
        lo, hi = r.annual_frequency_interval
        assert lo < r.annual_frequency < hi
        widths.append(math.log(hi / lo))
    assert widths[0] > widths[1] > widths[2]
    # about 1/sqrt(n): 16 times the records, a quarter of the width (within a factor 2)
    assert 0.125 < widths[2] / widths[0] < 0.5


def test_hazard_fractiles_alone_give_the_fractile_curves_risk():
    curve = hazard()
    lo_c = HazardCurve(curve.im, curve.rate / 3, im_name="PGA", unit="g")
    hi_c = HazardCurve(curve.im, curve.rate * 2.5, im_name="PGA", unit="g")
    mid = HazardCurve(curve.im, curve.rate * 1.1, im_name="PGA", unit="g")
    c = curve.with_fractiles({0.05: lo_c, 0.5: mid, 0.95: hi_c})
    fit = planted(40, n_boot=0)
    r = risk(fit, c, level=0.9)
    exact = (risk(fit, lo_c).annual_frequency, risk(fit, hi_c).annual_frequency)
    assert r.annual_frequency_interval == pytest.approx(exact, rel=1e-5)
    assert r.interval_source.startswith("hazard fractiles")
    assert r.annual_frequency_interval[0] < r.annual_frequency < r.annual_frequency_interval[1]
    # in m/s^2 the same (the fractiles converted with the curve)
    r_si = risk(fit, c.to_unit("m/s^2"))
    assert r_si.annual_frequency_interval == pytest.approx(exact, rel=1e-5)


def test_both_sources_widen_the_interval():
    curve = hazard()
    fit = planted(40, n_boot=600)
    c = curve.with_fractiles({
        0.16: HazardCurve(curve.im, curve.rate / 2, im_name="PGA", unit="g"),
        0.84: HazardCurve(curve.im, curve.rate * 2, im_name="PGA", unit="g")})
    fit_only, both = risk(fit, curve), risk(fit, c)
    lo1, hi1 = fit_only.annual_frequency_interval
    lo2, hi2 = both.annual_frequency_interval
    assert lo2 < lo1 and hi2 > hi1
    # independent lognormal sources: the log-widths add in quadrature (sigma_H = ln 2)
    w1, w2 = math.log(hi1 / lo1), math.log(hi2 / lo2)
    wh = 2 * norm.ppf(0.95) * math.log(2.0)
    assert w2 == pytest.approx(math.hypot(w1, wh), rel=0.1)
    assert "and hazard fractiles" in both.interval_source


def test_no_bootstrap_no_fractiles_no_interval_and_bad_input_refused():
    r = risk(planted(20, n_boot=0), hazard())
    assert all(math.isnan(v) for v in r.annual_frequency_interval)
    assert r.interval_source == "" and "%:" not in risk_text(r)
    with pytest.raises(ValueError, match="level"):
        risk_interval(planted(20, n_boot=10), hazard(), level=90)
    with pytest.raises(ValueError, match="fractile q"):
        hazard().with_fractiles({5: hazard(), 95: hazard()})
    with pytest.raises(ValueError, match="at least two"):
        hazard().with_fractiles({0.5: hazard()})


def test_campaign_report_writes_the_interval(tmp_path):
    from test_campaign_hazard import GROUPS, manifest, synthetic

    from rocking.campaign.hazard import curve_of, record
    from rocking.campaign.report import report, risk_lines

    curve = hazard()
    c = curve.with_fractiles({
        0.05: HazardCurve(curve.im, curve.rate / 3, im_name="PGA", unit="g"),
        0.95: HazardCurve(curve.im, curve.rate * 3, im_name="PGA", unit="g")})
    rec = record(c, {}, 50.0)
    assert sorted(curve_of(rec).fractiles) == [0.05, 0.95]  # kept in the manifest
    res = report(synthetic(GROUPS[:2], n_per=15), manifest(rec), tmp_path / "r", n_boot=100)
    rk = pd.read_csv(tmp_path / "r" / "risk.csv")
    ov = rk[rk["fit"] == "overturning"]
    assert len(ov) == 2
    assert (ov["annual_frequency_low"] < ov["annual_frequency"]).all()
    assert (ov["annual_frequency"] < ov["annual_frequency_high"]).all()
    assert (ov["probability_low"] < ov["probability"]).all()
    assert (ov["probability"] < ov["probability_high"]).all()
    assert (ov["interval_level"] == 0.9).all()
    assert ov["interval_source"].str.contains("hazard fractiles").all()
    md = (tmp_path / "r" / "report.md").read_text()
    assert "interval (/yr)" in md and "90 % interval (the 5th and 95th percentiles)" in md
    assert (tmp_path / "r" / "risk.png").is_file() and "(risk.png)" in md  # the plot
    line = next(x for x in risk_lines(res) if "annual frequency of overturning" in x)
    assert "(90 % interval: " in line


def test_openquake_fractile_exports_are_read_with_the_mean(tmp_path):
    src = (Path(__file__).resolve().parents[1] / "examples"
           / "hazard_curve-mean-PGA_site.csv").read_text()
    paths = []
    for q, f in ((0.05, 0.4), (0.95, 2.5)):
        lines = src.splitlines()
        lines[0] = lines[0].replace("kind='mean'", f"kind='quantile-{q}'")
        head = lines[1].split(",")
        rows = [lines[0], lines[1]]
        for row in lines[2:]:
            v = row.split(",")
            v[3:] = [repr(min(float(x) * f, 0.999)) if float(x) > 0 else x for x in v[3:]]
            rows.append(",".join(v))
        assert len(head) == len(rows[2].split(","))
        p = tmp_path / f"hazard_curve-quantile-{q}-PGA_7.csv"
        p.write_text("\n".join(rows) + "\n")
        paths.append(p)
    mean = tmp_path / "hazard_curve-mean-PGA_7.csv"
    mean.write_text(src)
    c = HazardCurve.from_openquake(mean, fractiles=paths)
    assert sorted(c.fractiles) == [0.05, 0.95]
    r = risk(planted(20, n_boot=0), c)
    assert r.annual_frequency_interval[0] < r.annual_frequency < r.annual_frequency_interval[1]
    with pytest.raises(ValueError, match="not a quantile export"):
        HazardCurve.from_openquake(mean, fractiles=[mean])
