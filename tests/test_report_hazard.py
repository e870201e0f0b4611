"""The report's ILLUSTRATIVE hazard curve (issue 21): the shipped OpenQuake-format example
file, read through :meth:`HazardCurve.from_openquake`, is the power law it states, and the
fragility section's annual frequencies are Cornell's closed form on it."""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from conftest import report_section
from scipy.stats import norm

from rocking.analysis import fragility_curves
from rocking.analysis.hazard import HazardCurve
from rocking.report.sections import fragility as F


def cornell(median, beta, k0=F.HAZARD_K0, a0=F.HAZARD_A0, k=F.HAZARD_K):
    """Cornell et al. (2002): a lognormal fragility on lambda = k0 (im / a0)^-k over
    0 < im < inf gives k0 (median / a0)^-k exp(k^2 beta^2 / 2)."""
    return k0 * (median / a0) ** -k * math.exp((k * beta) ** 2 / 2)


def test_shipped_file_is_the_stated_power_law():
    lines = F.HAZARD_FILE.read_text().splitlines()
    assert "illustrative" in F.HAZARD_FILE.name.lower()
    assert "ILLUSTRATIVE" in lines[0] and "not the hazard of any site" in lines[0]
    # the engine's layout: metadata in the last field of a '#,,,' row as wide as the header
    header = lines[1].split(",")
    assert header[:3] == ["lon", "lat", "depth"]
    assert all(h.startswith("poe-") for h in header[3:])
    assert lines[0].startswith("#" + "," * (len(header) - 1) + '"')

    hz = F.hazard_curve()
    assert (hz.im_name, hz.unit) == ("PGA", "g")
    assert float(hz.metadata["investigation_time"]) == 50.0
    assert hz.metadata["kind"] == "mean" and hz.metadata["dropped_levels"] == []
    assert hz.metadata["site_index"] == 0
    assert (hz.metadata["lon"], hz.metadata["lat"]) == F.HAZARD_SITE
    assert 20 <= hz.im.size <= 30
    exact = F.HAZARD_K0 * (hz.im / F.HAZARD_A0) ** -F.HAZARD_K
    np.testing.assert_allclose(hz.rate, exact, rtol=1e-6)
    # log-log interpolation of a power law is the power law: anywhere inside the range,
    x = np.geomspace(hz.im[0], hz.im[-1], 97)
    np.testing.assert_allclose(hz.rate_at(x), F.HAZARD_K0 * (x / F.HAZARD_A0) ** -F.HAZARD_K,
                               rtol=1e-6)
    # and beyond it (the tail model: the end slopes, here the same k)
    np.testing.assert_allclose(hz.tail_slopes, (F.HAZARD_K, F.HAZARD_K), rtol=1e-6)

    # the site is chosen by (lon, lat): the nearest row; the other rows differ
    again = HazardCurve.from_openquake(F.HAZARD_FILE, site=0)
    np.testing.assert_array_equal(again.rate, hz.rate)
    other = HazardCurve.from_openquake(F.HAZARD_FILE, site=(0.09, 0.01))
    assert other.metadata["site_index"] == 1
    assert not np.allclose(other.rate, hz.rate, rtol=1e-3)


def test_the_documented_script_writes_the_shipped_file(tmp_path, monkeypatch):
    """The generator in :func:`hazard_curve`'s docstring reproduces the file byte for
    byte (the file's provenance is its docstring, not a copy that can drift)."""
    doc = F.hazard_curve.__doc__
    script = textwrap.dedent(doc[doc.index("::\n") + 3:])
    monkeypatch.chdir(tmp_path)
    exec(compile(script, "hazard_curve docstring", "exec"), {})  # noqa: S102
    written = Path(tmp_path) / F.HAZARD_FILE.name
    assert written.read_bytes() == F.HAZARD_FILE.read_bytes()


def _ladder(medians, beta, levels, n=40):
    """Damage states of ``n`` records per IM level whose capacities are the lognormal
    quantiles ``median_k exp(beta z_j)`` (one z per record, common to the states)."""
    z = norm.ppf((np.arange(n) + 0.5) / n)
    im = np.repeat(levels, n)
    cap = np.array(medians)[None, :] * np.exp(beta * np.tile(z, levels.size))[:, None]
    return im, (im[:, None] > cap).sum(axis=1)


def test_risk_table_is_cornell_closed_form_tails_included():
    """Fits whose medians lie near the top of the file (3 g), so that the tail beyond it
    carries a large share: the section's table equals the closed form over 0..inf."""
    hz = F.hazard_curve()
    res = {}
    for j, (meds, beta) in enumerate((((0.2, 0.3, 0.45), 0.3), ((1.5, 2.5, 4.0), 0.5))):
        levels = np.geomspace(meds[0] / 3, meds[-1] * 3, 10)
        im, state = _ladder(meds, beta, levels)
        curves = fragility_curves(im, state, n_boot=20, seed=0, im_name="pga", im_unit="g")
        res[("synthetic", j)] = (curves, None)
    tab = F.risk_table(res, hz)
    assert len(tab) == 6
    for (s, j), (curves, _) in res.items():
        d = tab[(tab.record_set == s) & (tab.specimen == j)].sort_values("state")
        exact = [cornell(f.median, f.beta) for f in curves.fits]
        np.testing.assert_allclose(d.annual_frequency, exact, rtol=1e-6)
        np.testing.assert_allclose(d.probability_50yr, -np.expm1(-50.0 * np.array(exact)),
                                   rtol=1e-6)
    # the high medians do reach beyond the file: without the tails this would fail
    assert tab.tail_share.max() > 0.3


@pytest.fixture(scope="module")
def section(request):
    """The fragility section in quick mode (conftest.report_section): its folder and the
    HTML it wrote into the page."""
    out, _, html = report_section(request, "fragility")
    return out, html


def test_section_annual_frequency_is_cornell_on_its_fits(section):
    """The section's written annual frequencies (and 50-year probabilities) are the closed
    form for its own fitted curves (common beta) on the file's power law."""
    out, html = section
    fits = pd.read_csv(out / "fragility_fits.csv")
    af = pd.read_csv(out / "fragility_annual_frequency_illustrative.csv")
    cb = fits[fits.fit == "common_beta"]
    m = af.merge(cb, on=["record_set", "specimen", "state"], validate="one_to_one")
    assert len(m) == len(af) == len(cb) == 18
    exact = np.array([cornell(r.median_g, r.beta) for r in m.itertuples()])
    # the CSVs carry 6 digits: the median's rounding moves lambda by ~k 5e-7
    np.testing.assert_allclose(m.annual_frequency, exact, rtol=2e-5)
    np.testing.assert_allclose(m.probability_50yr, -np.expm1(-50.0 * exact), rtol=2e-5)
    np.testing.assert_allclose(m.return_period_yr, 1.0 / exact, rtol=2e-5)
    assert ((m.tail_share >= 0) & (m.tail_share < 1)).all()
    # still labelled illustrative, and the file and site named
    assert html.count("ILLUSTRATIVE") >= 3
    assert F.HAZARD_FILE.name in html and "not the hazard of any site" in html
    for name in ("fragility_annual_frequency.png", "fragility_risk.png"):
        assert (out / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
