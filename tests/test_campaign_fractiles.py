"""The hazard model's fractile curves in a campaign (issue 31): named in ``[hazard]``
(``fractiles = [...]``) and on the command line (``rocking campaign report STORE --hazard
mean.csv --fractiles q05.csv --fractiles q95.csv``), kept in the manifest, and carried
into the risk's interval. The risk is linear in the hazard's rates, so fractile curves
that are the mean's rates times 0.5 and 2 give, with a fit without bootstrap, exactly the
interval (0.5, 2) x the annual frequency."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from cli_helpers import assert_one_line_error, run_main
from scipy.stats import norm

from rocking import campaign
from rocking.analysis import fragility, risk
from rocking.campaign.hazard import curve_of
from rocking.campaign.spec import parse_spec
from rocking.campaign.store import manifest_for
from rocking.errors import SpecError

K, K0 = 2.7, 2.0e-5  # power law lambda(a) = K0 a^-K, a in g
SPEC = """
[campaign]
name = "fractiles"
seed = 5
model = "housner"
duration = 4.0

[[blocks]]
alpha = 0.2
p = 2.0
mu = 0.9

[motions]
kind = "sine"
frequency = [1.0, 1.5, 2.0, 3.0]
amplitude = 1.0
cycles = 2
im = "pga"
levels = {{start = 0.6, stop = 9.0, num = 6, spacing = "log"}}

[run]
chunk_size = 24
{hazard}"""
FRACTILES = {"mean": 1.0, "quantile-0.05": 0.5, "quantile-0.95": 2.0}


def oq_file(path: Path, kind: str, scale: float) -> Path:
    """An OpenQuake export (engine manual, "Outputs from Classical PSHA") of ``kind``:
    poe in 50 years of ``scale`` x the power law at two sites."""
    levels = np.array([0.02, 0.05, 0.1, 0.2, 0.4, 0.8, 1.6])
    lines = [f"#,,,,,\"generated_by='OpenQuake engine 3.18.0', checksum=1, kind='{kind}', "
             "investigation_time=50.0, imt='PGA'\"",
             "lon,lat,depth," + ",".join(f"poe-{x:.7f}" for x in levels)]
    for lon, lat, s in ((13.4, 42.35, 1.0), (12.5, 41.9, 0.4)):
        poe = -np.expm1(-50.0 * scale * s * K0 * levels ** -K)
        lines.append(f"{lon:.5f},{lat:.5f},-0.10000," + ",".join(f"{q:.9E}" for q in poe))
    path.write_text("\n".join(lines) + "\n")
    return path


def files(d: Path) -> dict:
    return {k: oq_file(d / f"hazard_curve-{k}-PGA_7.csv", k, s) for k, s in FRACTILES.items()}


HAZARD = ('[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"\nsite = 1\nfractiles = '
          '["hazard_curve-quantile-0.05-PGA_7.csv", "hazard_curve-quantile-0.95-PGA_7.csv"]')


def test_spec_fractiles_reach_the_manifest_and_the_risk(tmp_path):
    f = files(tmp_path)
    s = parse_spec(SPEC.format(hazard=HAZARD), base_dir=tmp_path)
    h = s.hazard
    assert sorted(float(q) for q in h["fractiles"]) == [0.05, 0.95]
    assert [(x["file"], x["q"]) for x in h["source"]["fractiles"]] == [
        (f["quantile-0.05"].name, 0.05), (f["quantile-0.95"].name, 0.95)]
    assert json.loads(json.dumps(manifest_for(s)))["hazard"] == h   # kept exactly
    curve = curve_of(h)
    assert sorted(curve.fractiles) == [0.05, 0.95]
    # a fit without bootstrap: the interval is that of the fractiles alone, and the risk
    # is linear in the rates: (0.5, 2) x the annual frequency
    im = np.repeat([1.0, 2.0, 3.0, 4.0, 6.0], 100)
    failed = np.tile(np.arange(100), 5) < np.round(100 * norm.cdf(np.log(im / 3) / 0.4))
    fit = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
    r = risk(fit, curve)
    lo, hi = r.annual_frequency_interval
    assert lo == pytest.approx(0.5 * r.annual_frequency, rel=2e-3)
    assert hi == pytest.approx(2.0 * r.annual_frequency, rel=2e-3)
    assert "hazard fractiles" in r.interval_source
    # without fractiles: no interval at all
    plain = parse_spec(SPEC.format(hazard=HAZARD.split("\nfractiles")[0]), base_dir=tmp_path)
    assert math.isnan(risk(fit, curve_of(plain.hazard)).annual_frequency_interval[0])


@pytest.mark.parametrize("hazard", [
    '[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"\nfractiles = '
    '["hazard_curve-quantile-0.05-PGA_7.csv"]',                      # one fractile
    '[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"\nfractiles = '
    '["nothing.csv", "hazard_curve-quantile-0.95-PGA_7.csv"]',      # no such file
    '[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"\nfractiles = '
    '["hazard_curve-mean-PGA_7.csv", "hazard_curve-quantile-0.95-PGA_7.csv"]',  # no q
    '[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"\nfractiles = 3',
    '[hazard]\npga_475 = "0.25g"\nfractiles = '
    '["hazard_curve-quantile-0.05-PGA_7.csv", "hazard_curve-quantile-0.95-PGA_7.csv"]',
])
def test_bad_fractiles_are_named(tmp_path, hazard):
    files(tmp_path)
    with pytest.raises(SpecError, match=r"hazard\.fractiles"):
        parse_spec(SPEC.format(hazard=hazard), base_dir=tmp_path)


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    d = tmp_path_factory.mktemp("fractiles")
    files(d)
    (d / "s.toml").write_text(SPEC.format(hazard='[hazard]\nfile = '
                                                 '"hazard_curve-mean-PGA_7.csv"'))
    campaign.run(d / "s.toml", d / "store", progress=False, log=lambda m: None)
    return d


def test_cli_report_fractiles(store, capsys, tmp_path):
    d = store
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--out",
                              tmp_path / "b", "--hazard", d / "hazard_curve-mean-PGA_7.csv")
    assert code == 0, err
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--out",
                              tmp_path / "f", "--hazard", d / "hazard_curve-mean-PGA_7.csv",
                              "--fractiles", d / "hazard_curve-quantile-0.05-PGA_7.csv",
                              "--fractiles", d / "hazard_curve-quantile-0.95-PGA_7.csv")
    assert code == 0, err
    b, f = (pd.read_csv(tmp_path / x / "risk.csv").dropna(subset=["annual_frequency"])
            for x in ("b", "f"))
    assert len(f) and (f["interval_source"].str.contains("hazard fractiles")).all()
    assert not b["interval_source"].str.contains("hazard fractiles").any()
    # the same fits and mean curve: the same point estimates, each inside its interval
    # (the interval's width is a Monte Carlo of the bootstrap paired with the hazard's
    # score; its exact form without bootstrap is tested above)
    np.testing.assert_allclose(f["annual_frequency"], b["annual_frequency"], rtol=1e-12)
    assert (f["annual_frequency_low"] <= f["annual_frequency"]).all()
    assert (f["annual_frequency"] <= f["annual_frequency_high"]).all()
    assert "hazard fractiles (0.05, 0.95)" in (tmp_path / "f" / "report.md").read_text()


@pytest.mark.parametrize("args", [
    ["--fractiles", "q.csv"],                                          # without --hazard
    ["--hazard", "HAZ", "--fractiles", "Q05"],                         # only one
    ["--hazard", "HAZ", "--fractiles", "Q05", "--fractiles", "none.csv"],
])
def test_cli_bad_fractiles(store, capsys, args):
    d = store
    sub = {"HAZ": d / "hazard_curve-mean-PGA_7.csv",
           "Q05": d / "hazard_curve-quantile-0.05-PGA_7.csv"}
    code, out, err = run_main(capsys, "campaign", "report", d / "store",
                              *[sub.get(a, a) for a in args])
    assert_one_line_error(code, err, "--fractiles")
