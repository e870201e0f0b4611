"""Hazard curves (OpenQuake export, CSV, EN 1998-1 code value) and risk (issue 21)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.stats import norm

from rocking.analysis import HazardCurve, plot_risk, probability_in, risk
from rocking.analysis.fragility import FragilityFit
from rocking.errors import ParameterError
from rocking.units import G


def lognormal_fit(median, beta, *, im_name="PGA", im_unit="g"):
    """A FragilityFit with a given median and beta (no data)."""
    b1 = 1.0 / beta
    coef = np.array([-math.log(median) * b1, b1])
    return FragilityFit(median, beta, 0.0, 0.0, np.zeros((2, 2)), coef, np.zeros((2, 2)),
                        "given", im_name=im_name, im_unit=im_unit)


def cornell(k0, k, median, beta):
    """Cornell et al. (2002): integral of a lognormal fragility against k0 a^-k."""
    return k0 * median ** -k * math.exp(k * k * beta * beta / 2)


def write_openquake(path, levels, sites, T=50.0, imt="PGA"):
    """An OpenQuake hazard-curve export in its documented layout."""
    meta = (f"#,,,,,\"generated_by='OpenQuake engine 3.16', start_date='2026-01-01', "
            f"checksum=1, kind='mean', investigation_time={T}, imt='{imt}'\"")
    lines = [meta, ",".join(["lon", "lat", "depth"] + [f"poe-{lv}" for lv in levels])]
    for lon, lat, poe in sites:
        lines.append(",".join([f"{lon}", f"{lat}", "0.0"] + [repr(float(p)) for p in poe]))
    path.write_text("\n".join(lines) + "\n")
    return path


# ------------------------------------------------------------------ the curve


def test_power_law_interpolation_and_return_period_inverse():
    k0, k = 1e-4, 2.7
    x = np.array([0.05, 0.1, 0.2, 0.4, 0.8])
    c = HazardCurve(x, k0 * x ** -k, im_name="PGA", unit="g")
    xs = np.array([0.01, 0.07, 0.3, 2.0])            # inside and beyond both ends
    assert np.allclose(c.rate_at(xs), k0 * xs ** -k, rtol=1e-12)
    assert np.allclose(c.return_periods, 1 / c.rate)
    for T in (10.0, 475.0, 2475.0, 1e6):
        a = c.im_at_return_period(T)
        assert c.rate_at(a) == pytest.approx(1 / T, rel=1e-10)


@pytest.mark.parametrize("kw, name", [
    ({"im": [0.1, 0.1], "rate": [1e-2, 1e-3]}, "im"),
    ({"im": [-0.1, 0.2], "rate": [1e-2, 1e-3]}, "im"),
    ({"im": [0.1, 0.2], "rate": [1e-3, 1e-2]}, "rate"),
    ({"im": [0.1, 0.2], "rate": [0.0, 0.0]}, "rate"),
    ({"im": [0.1, 0.2], "rate": [1e-2, 1e-3], "unit": "furlongs"}, "unit"),
])
def test_bad_curves_refused_naming_the_argument(kw, name):
    kw = {"im_name": "PGA", "unit": "g", **kw}
    with pytest.raises(ParameterError, match=name):
        HazardCurve(kw.pop("im"), kw.pop("rate"), **kw)


def test_code_value_passes_through_its_anchor_and_is_labelled():
    c = HazardCurve.from_code_value(0.25, k=3.0)
    assert c.rate_at(0.25) == pytest.approx(1 / 475, rel=1e-12)
    assert c.im_at_return_period(475) == pytest.approx(0.25, rel=1e-12)
    # slope k: doubling the PGA divides the rate by 2^k
    assert c.rate_at(0.5) / c.rate_at(0.25) == pytest.approx(2.0 ** -3, rel=1e-12)
    assert c.approximate and "approximation" in c.label and "approximate" in repr(c)
    two = HazardCurve.from_code_value(0.25, pga_2475=0.45)
    assert two.im_at_return_period(475) == pytest.approx(0.25, rel=1e-12)
    assert two.im_at_return_period(2475) == pytest.approx(0.45, rel=1e-12)


def test_csv_rate_or_return_period(tmp_path):
    x = np.array([0.05, 0.1, 0.2, 0.4])
    lam = 1e-4 * x ** -2.5
    (tmp_path / "a.csv").write_text("PGA (g),annual_rate\n" + "\n".join(
        f"{a},{float(r)!r}" for a, r in zip(x, lam, strict=True)))
    (tmp_path / "b.csv").write_text("# site\npga_g,return_period\n" + "\n".join(
        f"{a},{float(1 / r)!r}" for a, r in zip(x, lam, strict=True)))
    a = HazardCurve.from_csv(tmp_path / "a.csv")
    b = HazardCurve.from_csv(tmp_path / "b.csv")
    for c in (a, b):
        assert c.unit == "g" and c.im_name.lower() == "pga"
        assert np.allclose(c.rate, lam, rtol=1e-12)
    (tmp_path / "c.csv").write_text("PGA,rate\n0.1,1e-2\n0.2,1e-3\n")
    with pytest.raises(ParameterError, match="unit"):
        HazardCurve.from_csv(tmp_path / "c.csv")
    assert HazardCurve.from_csv(tmp_path / "c.csv", unit="g").unit == "g"


def test_openquake_rates_from_poe_and_site_choice(tmp_path):
    levels = [0.05, 0.1, 0.2, 0.4, 0.8]
    T = 50.0
    lam_a = 2e-4 * np.array(levels) ** -2.0
    lam_b = 5e-5 * np.array(levels) ** -3.0
    sites = [(13.40, 42.35, -np.expm1(-lam_a * T)), (14.25, 40.85, -np.expm1(-lam_b * T))]
    # a first level whose poe is 1 (saturated: infinite rate) is dropped, and recorded
    sat = [(lon, lat, np.r_[1.0, poe]) for lon, lat, poe in sites]
    f = write_openquake(tmp_path / "hazard_curve-mean-PGA_22.csv", [0.001] + levels, sat,
                        T=T)
    c0 = HazardCurve.from_openquake(f)
    assert c0.im_name == "PGA" and c0.unit == "g"
    assert c0.metadata["dropped_levels"] == [0.001]
    assert np.allclose(c0.im, levels) and np.allclose(c0.rate, lam_a, rtol=1e-8)
    c1 = HazardCurve.from_openquake(f, site=(14.3, 40.9))      # nearest is the second
    assert np.allclose(c1.rate, lam_b, rtol=1e-8)
    assert HazardCurve.from_openquake(f, site=1).metadata["lat"] == 40.85
    with pytest.raises(ParameterError, match="site"):
        HazardCurve.from_openquake(f, site=2)
    bad = tmp_path / "hazard_curve-mean-PGA_23.csv"
    bad.write_text(f.read_text().replace(",42.35,0.0,", ",north,0.0,"))
    with pytest.raises(ParameterError, match="numbers"):
        HazardCurve.from_openquake(bad)
    g = write_openquake(tmp_path / "hazard_curve-mean-SA(0.3)_22.csv", levels, sites[:1],
                        T=1.0, imt="SA(0.3)")
    s = HazardCurve.from_openquake(g)
    assert s.im_name == "SA(0.3)"
    assert np.allclose(s.rate, T * lam_a, rtol=1e-8)       # the same poe read with T = 1 yr


# ------------------------------------------------------------------ risk


@pytest.mark.parametrize("k, median, beta", [(3.0, 0.4, 0.5), (2.2, 0.15, 0.3)])
def test_risk_equals_cornell_closed_form_including_tails(k, median, beta):
    """A power law k0 a^-k given only on a short range: the tails carry most of the risk
    and the power-law extension restores the closed form."""
    k0 = 1e-4
    x = np.array([0.1, 0.15, 0.2])
    c = HazardCurve(x, k0 * x ** -k, im_name="PGA", unit="g")
    r = risk(lognormal_fit(median, beta), c)
    exact = cornell(k0, k, median, beta)
    assert r.annual_frequency == pytest.approx(exact, rel=1e-6)
    assert 0.0 < r.tail_share < 1.0
    assert r.probability_50 == pytest.approx(1 - math.exp(-50 * exact), rel=1e-6)


def test_each_damage_state_gets_its_closed_form():
    """Damage-state curves (anything with ``fits``): one Risk per state, each Cornell's."""
    k0, k = 1e-4, 2.5
    x = np.array([0.1, 0.2, 0.3])
    c = HazardCurve(x, k0 * x ** -k, im_name="pga", unit="g")
    states = type("States", (), {"fits": (lognormal_fit(0.2, 0.4), lognormal_fit(0.5, 0.3))})
    out = risk(states(), c)
    assert [r.annual_frequency for r in out] == pytest.approx(
        [cornell(k0, k, 0.2, 0.4), cornell(k0, k, 0.5, 0.3)], rel=1e-6)
    assert out[0].annual_frequency > out[1].annual_frequency     # rarer worse state


def test_units_converted_and_mismatches_refused():
    k0, k, median, beta = 1e-4, 3.0, 0.3, 0.4
    x = np.array([0.05, 0.1, 0.2, 0.4])
    c = HazardCurve(x, k0 * x ** -k, im_name="PGA", unit="g")
    in_si = risk(lognormal_fit(median * G, beta, im_unit="m/s^2"), c)
    assert in_si.annual_frequency == pytest.approx(cornell(k0, k, median, beta), rel=1e-6)
    with pytest.raises(ParameterError, match="IM"):
        risk(lognormal_fit(median, beta, im_name="PGV"), c)
    with pytest.raises(ParameterError, match="unit"):
        risk(lognormal_fit(median, beta, im_unit="m/s"), c)
    with pytest.raises(ParameterError, match="im_unit"):
        risk(lognormal_fit(median, beta, im_unit=None), c)


def test_general_curve_agrees_with_direct_quadrature():
    """A curved (non power-law) hazard: risk() equals an independent trapezoid sum of
    lambda(a) dP/da over a fine grid (the curve's own power-law tails included)."""
    x = np.array([0.02, 0.05, 0.1, 0.2, 0.4, 0.8, 1.5])
    lam = 1e-2 * np.exp(-2.0 * np.log(x / 0.02) - 0.3 * np.log(x / 0.02) ** 2)
    c = HazardCurve(x, lam, im_name="PGA", unit="g")
    fit = lognormal_fit(0.35, 0.45)
    a = np.logspace(-6, 3, 400001)
    # integration by parts: integral P |d lambda| = integral lambda dP (P(0)=0, lambda(inf)=0)
    f = c.rate_at(a) * norm.pdf(np.log(a / 0.35) / 0.45) / (0.45 * a)
    direct = np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(a))
    assert risk(fit, c).annual_frequency == pytest.approx(direct, rel=1e-5)


def test_a_wide_curve_agrees_with_the_existing_annual_frequency():
    """Where the curve spans the fragility, the tails carry nothing and risk() equals
    rocking.analysis.fragility.annual_frequency (an independent segment integral)."""
    from rocking.analysis import annual_frequency

    x = np.logspace(-3, 2, 40)
    lam = 1e-2 * np.exp(-1.5 * np.log(x / 1e-3) - 0.1 * np.log(x / 1e-3) ** 2)
    c = HazardCurve(x, lam, im_name="pga", unit="g")
    fit = lognormal_fit(0.3, 0.35)
    r = risk(fit, c)
    assert r.tail_share < 1e-7
    assert r.annual_frequency == pytest.approx(
        annual_frequency(fit, x, lam, hazard_unit="g", tail=False), rel=1e-6)


@pytest.mark.parametrize("head", ["Tr", "RP", "T (years)", "return period"])
def test_csv_return_period_headers(tmp_path, head):
    (tmp_path / "p.csv").write_text(f"PGA [g],{head}\n0.1,100\n0.3,1000\n")
    assert HazardCurve.from_csv(tmp_path / "p.csv").rate[0] == pytest.approx(0.01)


def test_probability_in_is_poisson():
    assert probability_in(50, 1 / 475) == pytest.approx(1 - math.exp(-50 / 475))
    assert probability_in(0, 1.0) == 0.0
    # small rates: lambda t
    assert probability_in(50, 1e-9) == pytest.approx(5e-8, rel=1e-6)
    with pytest.raises(ParameterError, match="t_years"):
        probability_in(-1, 1e-3)


def test_plot_risk_returns_a_figure():
    c = HazardCurve.from_code_value(0.25)
    fig = plot_risk(c, lognormal_fit(0.5, 0.4))
    assert len(fig.axes) == 2


# ------------------------------------------------------------------ CLI


def test_cli_hazard_show_openquake_and_csv(capsys, tmp_path):
    from cli_helpers import run_main

    k0, k = 2e-4, 2.5
    levels = [0.05, 0.1, 0.2, 0.4, 0.8]
    lam = k0 * np.array(levels) ** -k
    f = write_openquake(tmp_path / "hazard_curve-mean-PGA_1.csv", levels,
                        [(10.0, 45.0, -np.expm1(-lam * 50.0))])
    code, out, err = run_main(capsys, "hazard", "show", f)
    assert code == 0, err
    assert "PGA in g" in out
    for T in (475, 2475):                      # the power law inverted: (k0 T)^(1/k)
        line = next(s for s in out.splitlines() if s.startswith(f"{T} years"))
        assert float(line.split("=")[1].split()[0]) == pytest.approx((k0 * T) ** (1 / k),
                                                                       rel=1e-3)
    (tmp_path / "c.csv").write_text("PGA (g),return_period\n0.1,100\n0.3,1000\n0.6,5000\n")
    code, out, err = run_main(capsys, "hazard", "show", tmp_path / "c.csv", "--json")
    assert code == 0, err
    import json
    d = json.loads(out)
    assert d["unit"] == "g" and d["rate"][0] == pytest.approx(1 / 100)


@pytest.mark.parametrize("args, name", [
    (["missing.csv"], "FILE"),
    (["c.csv"], "unit"),
    (["oq.csv", "--site", "7"], "site"),
    (["oq.csv", "--site", "x,y,z"], "site"),
])
def test_cli_hazard_bad_input_is_one_line(capsys, tmp_path, monkeypatch, args, name):
    from cli_helpers import assert_one_line_error, run_main

    monkeypatch.chdir(tmp_path)
    (tmp_path / "c.csv").write_text("PGA,rate\n0.1,1e-2\n0.2,1e-3\n")
    write_openquake(tmp_path / "oq.csv", [0.1, 0.2], [(10.0, 45.0, [0.3, 0.1])])
    code, _, err = run_main(capsys, "hazard", "show", *args)
    assert_one_line_error(code, err, name)


# ------------------------------------------------------------------ review: CSV headers


def write_csv(path, head, x, y):
    path.write_text(f"PGA (g),{head}\n" + "\n".join(
        f"{float(a)!r},{float(b)!r}" for a, b in zip(x, y, strict=True)) + "\n")
    return path


X = np.array([0.05, 0.1, 0.2, 0.4])
LAM = 2e-4 * X ** -2.5                        # a power law, rates of exceedance


@pytest.mark.parametrize("head", ["rate", "annual_rate", "annual rate", "Rate",
                                  "annual rate (1/year)", "lambda", "AFE", "MAFE",
                                  "mean annual frequency of exceedance", "frequency",
                                  "1/yr", "rate per year", "exceedance rate [1/yr]"])
def test_csv_rate_headers_read_as_rates(tmp_path, head):
    c = HazardCurve.from_csv(write_csv(tmp_path / "r.csv", head, X, LAM))
    assert np.allclose(c.rate, LAM, rtol=1e-12)


@pytest.mark.parametrize("head", ["return period", "return_period", "return period (years)",
                                  "T_R", "Tr", "RP", "T", "T (years)", "years"])
def test_csv_return_period_headers_read_as_periods(tmp_path, head):
    c = HazardCurve.from_csv(write_csv(tmp_path / "t.csv", head, X, 1 / LAM))
    assert np.allclose(c.rate, LAM, rtol=1e-12)


@pytest.mark.parametrize("head", ["poe", "probability of exceedance", "poe_50yr", "prob",
                                  "PoE in 50 years"])
def test_csv_probability_of_exceedance_needs_its_time_and_is_poisson(tmp_path, head):
    """The reviewer's case: a poe column was read as rates. Refused without
    investigation_time; with it, the rate is the Poisson rate whose probability in T years
    is the poe (checked through probability_in, the other direction)."""
    T = 50.0
    poe = -np.expm1(-LAM * T)
    f = write_csv(tmp_path / "p.csv", head, X, poe)
    with pytest.raises(ParameterError, match=r"investigation_time.*-ln\(1 - poe\)"):
        HazardCurve.from_csv(f)
    c = HazardCurve.from_csv(f, investigation_time=T)
    assert np.allclose(c.rate, LAM, rtol=1e-10)
    assert np.allclose(probability_in(T, c.rate), poe, rtol=1e-12)


def test_csv_probability_checks(tmp_path):
    poe = -np.expm1(-LAM * 50.0)
    f = write_csv(tmp_path / "p.csv", "poe_50yr", X, poe)
    with pytest.raises(ParameterError, match="investigation_time=1 contradicts"):
        HazardCurve.from_csv(f, investigation_time=1.0)       # the header says 50 years
    with pytest.raises(ParameterError, match="investigation_time"):
        HazardCurve.from_csv(f, investigation_time=-5)
    sat = write_csv(tmp_path / "s.csv", "poe", X, np.r_[1.0, poe[1:]])
    with pytest.raises(ParameterError, match=r"\(0, 1\).*0\.05"):   # poe 1: infinite rate
        HazardCurve.from_csv(sat, investigation_time=50)
    r = write_csv(tmp_path / "r.csv", "rate", X, LAM)
    with pytest.raises(ParameterError, match="investigation_time applies"):
        HazardCurve.from_csv(r, investigation_time=50)


@pytest.mark.parametrize("head", ["value", "PGA exceedance", "hazard", "rate (years)"])
def test_csv_unknown_or_ambiguous_header_refused(tmp_path, head):
    f = write_csv(tmp_path / "u.csv", head, X, LAM)
    with pytest.raises(ParameterError, match=r"rate.*(return period|years)"):
        HazardCurve.from_csv(f)


# ------------------------------------------------------------------ review: OpenQuake site


def two_sites(tmp_path):
    levels = [0.05, 0.1, 0.2, 0.4]
    lam = 2e-4 * np.array(levels) ** -2.0
    sites = [(13.40, 42.35, -np.expm1(-lam * 50)), (14.25, 40.85, -np.expm1(-lam * 25))]
    return write_openquake(tmp_path / "hazard_curve-mean-PGA_9.csv", levels, sites)


def test_site_distance_is_the_great_circle_arc(tmp_path):
    """Along a meridian the haversine distance is R d(lat) (R = 6371.0 km); the distance
    is kept in the metadata and the label; an index choice has none."""
    f = two_sites(tmp_path)
    c = HazardCurve.from_openquake(f, site=(14.25, 40.85 + 0.2))
    assert c.metadata["site_index"] == 1
    assert c.metadata["site_distance_km"] == pytest.approx(6371.0 * math.radians(0.2),
                                                           rel=1e-9)
    assert "22.2 km" in c.label
    # on the equator the arc crosses the date line: 179.9 and -179.9 are 0.2 deg apart
    eq = tmp_path / "hazard_curve-mean-PGA_8.csv"
    write_openquake(eq, [0.1, 0.2], [(179.9, 0.0, [0.3, 0.1]), (0.0, 0.0, [0.3, 0.1])])
    e = HazardCurve.from_openquake(eq, site=(-179.9, 0.0))
    assert e.metadata["site_index"] == 0
    assert e.metadata["site_distance_km"] == pytest.approx(6371.0 * math.radians(0.2))
    assert HazardCurve.from_openquake(f, site=1).metadata["site_distance_km"] is None


@pytest.mark.parametrize("site, match", [
    ((float("nan"), float("nan")), "lon must be finite"),
    ((13.4, 95.0), r"lat must be finite, in \[-90, 90\]"),
    ((400.0, 42.0), r"lon must be finite, in \[-180, 360\)"),
    ((13.4, float("inf")), "lat"),
    (("east", 42.0), "site"),
    ((1.0, 2.0, 3.0), "site"),
])
def test_bad_site_coordinates_refused(tmp_path, site, match):
    with pytest.raises(ParameterError, match=match):
        HazardCurve.from_openquake(two_sites(tmp_path), site=site)


def test_far_site_refused_naming_the_nearest_and_the_override(tmp_path):
    f = two_sites(tmp_path)
    with pytest.raises(ParameterError, match=r"site 1 at \(14\.25, 40\.85\), \d{4} km "
                       r"away.*max_distance_km=50.*site 0: lon and lat swapped"):
        HazardCurve.from_openquake(f, site=(42.35, 13.40))        # lat, lon swapped
    with pytest.raises(ParameterError, match=r"site 1 .*site=1"):
        HazardCurve.from_openquake(f, site=(15.0, 40.85))        # ~63 km east of site 1
    d = 6371.0 * 2 * math.asin(math.cos(math.radians(40.85)) * math.sin(math.radians(0.375)))
    c = HazardCurve.from_openquake(f, site=(15.0, 40.85), max_distance_km=100)
    assert c.metadata["site_index"] == 1
    assert c.metadata["site_distance_km"] == pytest.approx(d, rel=1e-9)
    with pytest.raises(ParameterError, match="max_distance_km"):
        HazardCurve.from_openquake(f, site=(15.0, 40.85), max_distance_km=0)


def test_poe_rising_with_level_refused_naming_the_levels(tmp_path):
    """The reviewer's row 0.5, 0.0, 0.01 was read after dropping its zero."""
    f = write_openquake(tmp_path / "hazard_curve-mean-PGA_4.csv", [0.1, 0.2, 0.4],
                        [(1.0, 1.0, [0.5, 0.0, 0.01])])
    with pytest.raises(ParameterError, match=r"rises.*poe-0\.2.*poe-0\.4"):
        HazardCurve.from_openquake(f)
    # flat saturated (1, 1) and flat zero (0, 0) ends are not rises: dropped, recorded
    g = write_openquake(tmp_path / "hazard_curve-mean-PGA_5.csv", [0.05, 0.1, 0.2, 0.4, 0.8],
                        [(1.0, 1.0, [1.0, 1.0, 0.2, 0.01, 0.0])])
    c = HazardCurve.from_openquake(g)
    assert c.metadata["dropped_levels"] == [0.05, 0.1, 0.8]
    assert np.allclose(c.rate, -np.log1p(-np.array([0.2, 0.01])) / 50.0)


def test_tail_slopes_are_the_first_two_and_last_two_points():
    """The documented tail model: below the curve, the slope of its first two points; above
    it, that of its last two (here 2 and 4: the curve bends)."""
    x = np.array([0.1, 0.2, 0.4])
    lam = np.array([1e-2, 1e-2 * 2.0 ** -2, 1e-2 * 2.0 ** -2 * 2.0 ** -4])
    c = HazardCurve(x, lam, im_name="PGA", unit="g")
    assert c.tail_slopes == pytest.approx((2.0, 4.0), rel=1e-12)
    assert c.rate_at(0.05) == pytest.approx(lam[0] * 2.0 ** 2, rel=1e-12)
    assert c.rate_at(0.8) == pytest.approx(lam[-1] * 2.0 ** -4, rel=1e-12)


def test_cli_show_reports_site_distance_dropped_levels_and_poe(capsys, tmp_path):
    from cli_helpers import run_main

    f = write_openquake(tmp_path / "hazard_curve-mean-PGA_6.csv", [0.05, 0.1, 0.2, 0.4],
                        [(14.25, 40.85, [1.0, 0.3, 0.1, 0.01])])
    code, out, err = run_main(capsys, "hazard", "show", f, "--site", "14.25,41.05")
    assert code == 0, err
    km = 6371.0 * math.radians(0.2)
    line = next(s for s in out.splitlines() if s.startswith("site 0"))
    assert f"{km:.3g} km" in line
    assert "dropped levels" in out and "0.05 (poe 1)" in out
    code, _, err = run_main(capsys, "hazard", "show", f, "--site", "14.25,43",
                            "--max-distance-km", "300")
    assert code == 0, err
    T = 50.0
    poe = -np.expm1(-LAM * T)
    p = write_csv(tmp_path / "p.csv", "probability of exceedance", X, poe)
    code, out, err = run_main(capsys, "hazard", "show", p, "--investigation-time", "50yr",
                              "--json")
    assert code == 0, err
    import json
    assert np.allclose(json.loads(out)["rate"], LAM, rtol=1e-10)


@pytest.mark.parametrize("args, name", [
    (["oq.csv", "--site", "nan,nan"], "lon"),
    (["oq.csv", "--site", "10,95"], "lat"),
    (["oq.csv", "--site", "45,10"], "--max-distance-km"),        # swapped: 1000s of km
    (["oq.csv", "--investigation-time", "50"], "--investigation-time"),
    (["p.csv"], "--investigation-time"),
    (["p.csv", "--max-distance-km", "10"], "--max-distance-km"),
    (["v.csv"], "return period"),
])
def test_cli_hazard_review_refusals_are_one_line(capsys, tmp_path, monkeypatch, args, name):
    from cli_helpers import assert_one_line_error, run_main

    monkeypatch.chdir(tmp_path)
    write_openquake(tmp_path / "oq.csv", [0.1, 0.2], [(10.0, 45.0, [0.3, 0.1])])
    write_csv(tmp_path / "p.csv", "poe", X, -np.expm1(-LAM * 50))
    write_csv(tmp_path / "v.csv", "value", X, LAM)
    code, _, err = run_main(capsys, "hazard", "show", *args)
    assert_one_line_error(code, err, name)
