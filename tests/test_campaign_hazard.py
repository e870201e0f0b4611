"""The site's hazard in campaigns (issue 21, ``[hazard]``): the report's annual frequency
against Cornell's closed form at its own fits, the probability over the service life, the
approximation label of a code value, the IM check at parse time, bounds (never a number)
for a group without a fit, the curve kept in the manifest (a changed file changes no
report), resuming with another ``[hazard]``, and the command line."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from cli_helpers import assert_one_line_error, run_main
from scipy.stats import norm

from rocking import campaign
from rocking.analysis import DEFAULT_THRESHOLDS, damage_state
from rocking.analysis.hazard import HazardCurve
from rocking.campaign.hazard import code_value, read_hazard, record
from rocking.campaign.report import report, summary_lines
from rocking.campaign.spec import keys_table, parse_spec
from rocking.campaign.store import manifest_for
from rocking.errors import ParameterError, SpecError
from rocking.units import G

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
K, K0 = 2.7, 2.0e-5  # power-law hazard lambda(a) = K0 a^-K, a in g


# --------------------------------------------------------------------------- helpers

def power_law_csv(path: Path, lo: float = 0.1, hi: float = 0.5, n: int = 6) -> Path:
    """A hazard CSV (PGA in g, annual rate) on the power law: its tails are the same law."""
    a = np.geomspace(lo, hi, n)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["PGA (g)", "annual rate"])
        w.writerows([[repr(float(x)), repr(float(K0 * x ** -K))] for x in a])
    return path


def cornell(median_g: float, beta: float, k: float = K, k0: float = K0) -> float:
    """Cornell et al. (2002): lambda_f = k0 m^-k exp(k^2 beta^2 / 2) on a power law."""
    return k0 * median_g ** -k * math.exp(0.5 * (k * beta) ** 2)


def synthetic(groups, n_per: int = 25, seed: int = 3) -> pd.DataFrame:
    """A store's table whose outcomes follow planted lognormal fragilities: ``groups`` is
    ``[(mitigation, model, block, theta m/s^2 or None: never overturns, beta)]``."""
    rng = np.random.default_rng(seed)
    levels = np.geomspace(0.5, 12.0, 9)
    parts, sid = [], 0
    for mit, model, block, theta, beta in groups:
        lv = np.repeat(np.arange(levels.size), n_per)
        im = levels[lv]
        p = np.zeros(im.size) if theta is None else norm.cdf(np.log(im / theta) / beta)
        ov = rng.random(im.size) < p
        alpha = 0.2
        th = np.where(ov, np.nan, alpha * np.minimum(0.95, 0.5 * im / levels[-1]
                                                    * np.exp(0.3 * rng.standard_normal(
                                                        im.size))))
        n = im.size
        parts.append(pd.DataFrame({
            "sim_id": sid + np.arange(n), "model": model, "mitigation": mit,
            "block": block, "block_name": f"block {block}", "alpha": alpha, "p": 3.0,
            "mu": 0.7, "motion": lv % 4, "motion_id": [f"m{i % 4}" for i in lv],
            "level": lv, "load_factor": im / 2.0, "sample": 0, "theta0": 0.0,
            "amplitude": 1.0, "noise": 0.0, "pga": im, "im": im, "max_abs_theta": th,
            "max_abs_theta_over_alpha": th / alpha, "overturned": ov,
            "overturn_time": np.where(ov, 5.0, np.nan), "uplift_time": 1.0, "n_impacts": 3,
            "damage_state": damage_state(th, alpha, ov), "status": 0}))
        sid += n
    return pd.concat(parts, ignore_index=True)


def manifest(hazard=None) -> dict:
    m = {"name": "site test", "thresholds": list(DEFAULT_THRESHOLDS), "models": ["housner"],
         "blocks": [], "im": {"name": "pga", "unit": "m/s^2"}, "version": "0",
         "spec_hash": "abc"}
    if hazard is not None:
        m["hazard"] = hazard
    return m


GROUPS = [("none", "housner", 0, 3.0, 0.4), ("none", "housner", 1, 5.0, 0.3),
          ("isolated-2.5s", "isolated", 0, 8.0, 0.5), ("isolated-2.5s", "isolated", 1, None, 0)]


@pytest.fixture(scope="module")
def table():
    return synthetic(GROUPS)


# ------------------------------------------------------------------ the risk of the report

def test_annual_frequency_is_cornells_closed_form_at_the_reports_own_fit(table, tmp_path):
    """Power-law hazard given on 0.1-0.5 g only: the report's integral over the whole IM
    range (tails included) is k0 m^-k exp(k^2 beta^2/2) at its own fitted median and beta,
    for the overturning fit and every damage-state curve; P(50 yr) = 1 - exp(-50 lambda)."""
    curve, src = read_hazard(power_law_csv(tmp_path / "h.csv"))
    res = report(table, manifest(record(curve, src, 50.0)), tmp_path / "r", n_boot=0)
    rk = res["risk"]
    fitted = rk[np.isfinite(rk["annual_frequency"])]
    assert (fitted["fit"] == "overturning").sum() == 3  # the three groups that overturn
    assert (fitted["fit"] == "damage_states").sum() >= 3
    for r in fitted.itertuples():
        assert r.im_unit == "m/s^2"
        lam = cornell(r.median / G, r.beta)  # the fit in m/s^2, the curve in g
        assert r.annual_frequency == pytest.approx(lam, rel=1e-6)
        assert r.probability == pytest.approx(-math.expm1(-50.0 * lam), rel=1e-9)
        assert 0.0 <= r.tail_share <= 1.0
    # the median of the fragile block (3 m/s^2 = 0.31 g, beta 0.4) against a curve ending
    # at 0.5 g: much of the integral is beyond the curve: counted, and said
    ov = fitted[fitted["fit"] == "overturning"].set_index(["mitigation", "block"])
    assert ov.loc[("none", 0), "tail_share"] > 0.1
    assert "extrapolation" in ov.loc[("none", 0), "note"]
    # the overturning row's median and beta are the fragility table's
    fr = res["fragility"]
    f0 = fr[(fr["fit"] == "overturning") & (fr["mitigation"] == "none") & (fr["block"] == 0)]
    assert ov.loc[("none", 0), "median"] == f0["median"].iloc[0]
    # risk.csv holds the same numbers (10 significant digits)
    csv_rk = pd.read_csv(tmp_path / "r" / "risk.csv")
    np.testing.assert_allclose(csv_rk["annual_frequency"], rk["annual_frequency"],
                               rtol=1e-9)


def test_every_mitigation_and_block_gets_a_row_and_a_line(table, tmp_path):
    curve, src = read_hazard(power_law_csv(tmp_path / "h.csv", 0.01, 3.0, 12))
    res = report(table, manifest(record(curve, src, 30.0)), tmp_path / "r", n_boot=0)
    ov = res["risk"][res["risk"]["fit"] == "overturning"]
    assert sorted(zip(ov["mitigation"], ov["block"], strict=True)) == \
        sorted((m, b) for m, _, b, _, _ in GROUPS)
    assert (ov["t_years"] == 30.0).all()
    lines = summary_lines(res)
    assert any("service life 30 years" in x for x in lines)
    for mit, model, b, theta, _ in GROUPS:
        line = next(x for x in lines if x.startswith(f"{mit} ({model}) / block {b}:")
                    and ("annual frequency" in x or "no overturning fit (" in x))
        if theta is not None:
            lam = ov[(ov["mitigation"] == mit) & (ov["block"] == b)]["annual_frequency"]
            assert f"annual frequency of overturning {lam.iloc[0]:.3g} per year" in line
            assert "30-year probability" in line
    md = (tmp_path / "r" / "report.md").read_text()
    assert "## Risk at the site" in md and "### isolated-2.5s (isolated): overturning" in md


def test_a_group_without_a_fit_gets_a_bound_never_a_number(table, tmp_path):
    """The block that never overturns: no annual frequency, no probability; the rate of
    the largest IM run (a step fragility there) as an upper bound, and a note."""
    curve, src = read_hazard(power_law_csv(tmp_path / "h.csv", 0.01, 3.0, 12))
    res = report(table, manifest(record(curve, src, 50.0)), tmp_path / "r", n_boot=0)
    rk = res["risk"]
    r = rk[(rk["mitigation"] == "isolated-2.5s") & (rk["block"] == 1)]
    r = r[r["fit"] == "overturning"].iloc[0]
    assert math.isnan(r["annual_frequency"]) and math.isnan(r["probability"])
    assert math.isnan(r["median"]) and math.isnan(r["annual_frequency_lower_bound"])
    top = table["im"].max() / G  # the largest IM run, in the curve's g
    assert r["annual_frequency_upper_bound"] == pytest.approx(K0 * top ** -K, rel=1e-9)
    assert "no overturning fit" in r["note"] and "step" in r["note"]
    line = next(x for x in summary_lines(res) if x.startswith("isolated-2.5s (isolated) / "
                                                             "block 1: no overturning fit ("))
    assert "annual frequency of overturning" not in line  # no number, the note


def test_code_value_hazard_is_labelled_approximate_everywhere(table, tmp_path):
    curve, src = code_value(0.25 * G, k=3.0)
    assert curve.rate_at(0.25) == pytest.approx(1 / 475, rel=1e-12)  # its anchor
    res = report(table, manifest(record(curve, src, 50.0)), tmp_path / "r", n_boot=0)
    md = (tmp_path / "r" / "report.md").read_text()
    assert "APPROXIMATION" in md and "(approximate hazard)" in md
    rk = pd.read_csv(tmp_path / "r" / "risk.csv")
    assert rk["approximate"].all() and rk["hazard"].str.contains("approximation").all()
    risk_lines = [x for x in summary_lines(res) if "annual frequency of overturning" in x
                  or "no overturning fit (" in x]
    assert risk_lines and all("[approximate hazard]" in x for x in risk_lines)
    # a pure power law: Cornell's closed form with k0 = (1/475) a_475^k
    fit = res["risk"].dropna(subset=["annual_frequency"]).iloc[0]
    assert fit["annual_frequency"] == pytest.approx(
        cornell(fit["median"] / G, fit["beta"], 3.0, 0.25 ** 3 / 475), rel=1e-6)


def test_a_hazard_of_another_im_is_refused_by_the_report(table, tmp_path):
    p = tmp_path / "pgv.csv"
    p.write_text("PGV (m/s),annual rate\n0.1,0.01\n0.5,0.0004\n")
    curve, src = read_hazard(p)
    with pytest.raises(ParameterError, match=r"PGV \(m/s\).*pga \(m/s\^2\)"):
        report(table, manifest(record(curve, src, 50.0)), tmp_path / "r", n_boot=0)


# ------------------------------------------------------------------ the spec

SPEC = """
[campaign]
name = "site-small"
seed = 4
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
{intensity}

[[mitigation]]
name = "none"

[[mitigation]]
name = "anchored"
model = "anchored"
anchor_strength = 0.15

[run]
chunk_size = 24
{hazard}"""
PGA_LEVELS = 'im = "pga"\nlevels = {start = 0.6, stop = 9.0, num = 6, spacing = "log"}'


def spec_text(hazard: str, intensity: str = PGA_LEVELS) -> str:
    return SPEC.format(hazard=hazard, intensity=intensity)


def oq_file(path: Path, sites=((13.4, 42.35, 1.0), (12.5, 41.9, 0.4))) -> Path:
    """An OpenQuake export written from the documented layout (engine manual, "Outputs
    from Classical PSHA"): poe in T = 50 years of a power law scaled per site."""
    levels = np.array([0.02, 0.05, 0.1, 0.2, 0.4, 0.8, 1.6])
    lines = ["#,,,,,\"generated_by='OpenQuake engine 3.18.0', start_date='2023-10-03T06:09:"
             "08', checksum=2107362341, kind='mean', investigation_time=50.0, imt='PGA'\"",
             "lon,lat,depth," + ",".join(f"poe-{x:.7f}" for x in levels)]
    for lon, lat, s in sites:
        poe = -np.expm1(-50.0 * s * K0 * levels ** -K)
        lines.append(f"{lon:.5f},{lat:.5f},-0.10000," + ",".join(f"{q:.6E}" for q in poe))
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.fixture
def oq(tmp_path):
    return oq_file(tmp_path / "hazard_curve-mean-PGA_7.csv")


def test_the_hazard_is_read_at_parse_time_and_kept_whole(oq, tmp_path):
    s = parse_spec(spec_text('[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"\nsite = '
                             '[12.6, 41.8]\nt_years = 100'), base_dir=tmp_path)
    h = s.hazard
    assert h["source"]["format"] == "openquake" and h["source"]["site_index"] == 1
    assert h["t_years"] == 100.0 and h["im_name"] == "PGA" and h["unit"] == "g"
    # rates from the file's poe by -ln(1 - poe) / T, computed here from the text
    rows = list(csv.reader(oq.read_text().splitlines()[1:]))
    levels = [float(c[4:]) for c in rows[0][3:]]
    rate = [-math.log1p(-float(q)) / 50.0 for q in rows[2][3:]]
    np.testing.assert_allclose(h["im"], levels, rtol=0)
    np.testing.assert_allclose(h["rate"], rate, rtol=1e-12)
    # the manifest keeps the points exactly (JSON keeps every digit)
    m = json.loads(json.dumps(manifest_for(s)))
    assert m["hazard"] == h
    # the hazard is not in the spec hash: it changes no run
    plain = parse_spec(spec_text(""), base_dir=tmp_path)
    assert plain.hash == s.hash and plain.hazard is None
    assert "hazard" not in manifest_for(plain)


def test_a_code_value_in_the_spec(tmp_path):
    s = parse_spec(spec_text('[hazard]\npga_475 = "2.45m/s^2"\npga_2475 = "0.45g"'),
                   base_dir=tmp_path)
    h = s.hazard
    assert h["approximate"] and "approximation" in h["label"]
    c = HazardCurve(h["im"], h["rate"], im_name=h["im_name"], unit=h["unit"])
    assert c.rate_at(2.45 / G) == pytest.approx(1 / 475, rel=1e-9)
    assert c.rate_at(0.45) == pytest.approx(1 / 2475, rel=1e-9)


def test_an_im_mismatch_is_refused_at_parse_time(tmp_path):
    """A PGA hazard for a campaign scaled to PGV: refused, naming both IMs."""
    text = spec_text('[hazard]\npga_475 = "0.25g"', 'im = "pgv"\nlevels = [0.1, 0.2]')
    with pytest.raises(SpecError) as e:
        parse_spec(text, base_dir=tmp_path)
    msg = str(e.value)
    assert msg.startswith("spec: hazard.pga_475:")
    assert "PGA (g)" in msg and "pgv (m/s)" in msg


def test_an_im_mismatch_of_a_file_and_the_cli_exit_code(oq, tmp_path, capsys):
    text = spec_text('[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"',
                     'im = "pgv"\nlevels = [0.1, 0.2]')
    with pytest.raises(SpecError, match=r"^spec: hazard\.file: .*PGA \(g\).*pgv \(m/s\)"):
        parse_spec(text, base_dir=tmp_path)
    (tmp_path / "s.toml").write_text(text)
    code, out, err = run_main(capsys, "campaign", "run", tmp_path / "s.toml", "--out",
                              tmp_path / "store", "--dry-run")
    assert_one_line_error(code, err, "hazard.file")
    # and a PGV curve for a campaign of PGA (the PGA of each run, no im)
    (tmp_path / "pgv.csv").write_text("PGV (m/s),annual rate\n0.1,0.01\n0.5,0.0004\n")
    with pytest.raises(SpecError, match=r"hazard\.file: .*PGV \(m/s\).*pga \(m/s\^2\)"):
        parse_spec(spec_text('[hazard]\nfile = "pgv.csv"', "load_factors = [1.0, 2.0]"),
                   base_dir=tmp_path)


@pytest.mark.parametrize("hazard, key", [
    ('file = "h.csv"\npga_475 = "0.25g"', "hazard.file"),
    ('t_years = 50', "hazard.file"),
    ('file = "missing.csv"', "hazard.file"),
    ('file = "h.csv"\nsite = 0', "hazard.site"),
    ('file = "h.csv"\nk = 3', "hazard.k"),
    ('file = "h.csv"\nformat = "xml"', "hazard.format"),
    ('file = "h.csv"\nt_years = 0', "hazard.t_years"),
    ('file = "h.csv"\ncolour = 1', "hazard.colour"),
    ('pga_475 = true', "hazard.pga_475"),  # a bare number is in g (issue 31); not a bool
    ('pga_475 = "0.25 parsec"', "hazard.pga_475"),
    ('pga_475 = -0.25', "hazard.pga_475"),
    ('pga_475 = "0.25g"\nk = -1', "hazard.k"),
    ('pga_475 = "0.25g"\nk = 3\npga_2475 = "0.4g"', "hazard.k"),
    ('pga_475 = "0.25g"\npga_2475 = "0.2g"', "hazard.pga_2475"),
    ('pga_475 = "0.25g"\nsite = 1', "hazard.site"),
])
def test_bad_hazard_keys_are_named(tmp_path, hazard, key):
    power_law_csv(tmp_path / "h.csv")
    with pytest.raises(SpecError) as e:
        parse_spec(spec_text(f"[hazard]\n{hazard}"), base_dir=tmp_path)
    assert str(e.value).startswith(f"spec: {key}:"), str(e.value)


def test_an_openquake_site_out_of_range_is_named(oq, tmp_path):
    with pytest.raises(SpecError, match=r"^spec: hazard\.site: .*0\.\.1"):
        parse_spec(spec_text('[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"\nsite = 5'),
                   base_dir=tmp_path)


def test_the_keys_table_lists_hazard():
    t = keys_table()
    assert "**`[hazard]`**" in t and "`pga_475`" in t and "`t_years`" in t


def test_the_shipped_example_parses_and_its_curve_is_the_files(tmp_path):
    s = campaign.read_spec(EXAMPLES / "site.toml")
    h = s.hazard
    assert h["source"]["file"] == "hazard_curve-mean-PGA_site.csv"
    assert not h["approximate"] and s.mitigations
    lines = (EXAMPLES / "hazard_curve-mean-PGA_site.csv").read_text().splitlines()
    assert "investigation_time=50.0" in lines[0] and "imt='PGA'" in lines[0]
    row = next(csv.reader(lines[2:3]))
    poe = np.array([float(q) for q in row[3:]])
    keep = (poe > 0) & (poe < 1)
    np.testing.assert_allclose(h["rate"], -np.log1p(-poe[keep]) / 50.0, rtol=1e-12)


# ------------------------------------------------------------------ store and command line

@pytest.fixture(scope="module")
def store(tmp_path_factory):
    d = tmp_path_factory.mktemp("site")
    oq_file(d / "hazard_curve-mean-PGA_7.csv")
    (d / "s.toml").write_text(spec_text('[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"'))
    campaign.run(d / "s.toml", d / "store", progress=False, log=lambda m: None)
    return d


def test_cli_report_prints_the_risk_and_ignores_a_changed_file(store, capsys, tmp_path):
    d = store
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--out",
                              tmp_path / "r1")
    assert code == 0, err
    assert "hazard: OpenQuake PGA at (13.40000, 42.35000)" in out
    assert "service life 50 years" in out
    rk = pd.read_csv(tmp_path / "r1" / "risk.csv")
    ov = rk[rk["fit"] == "overturning"]
    assert set(ov["mitigation"]) == {"none", "anchored"}
    for r in ov.itertuples():
        run = r.mitigation if r.mitigation == r.model else f"{r.mitigation} ({r.model})"
        head = f"{run} / {r.block_name}:"  # a mitigation named as its model: once
        line = next(x for x in out.splitlines() if x.startswith(head)
                    and ("annual frequency of overturning" in x or "no overturning fit (" in x))
        if math.isfinite(r.annual_frequency):
            assert (f"annual frequency of overturning {r.annual_frequency:.3g} per year, "
                    f"50-year probability {r.probability:.3g}") in line
    assert np.isfinite(ov["annual_frequency"]).any()
    # the file changes (another hazard): the store's report does not
    oq_file(d / "hazard_curve-mean-PGA_7.csv", sites=((13.4, 42.35, 9.0),))
    code, out2, err = run_main(capsys, "campaign", "report", d / "store", "--out",
                               tmp_path / "r2")
    assert code == 0, err
    pd.testing.assert_frame_equal(pd.read_csv(tmp_path / "r2" / "risk.csv"), rk)
    oq_file(d / "hazard_curve-mean-PGA_7.csv")  # as it was


def test_cli_report_hazard_given_at_report_time(store, capsys, tmp_path):
    d = store
    oq2 = oq_file(tmp_path / "other.csv", sites=((10.0, 40.0, 2.0), (11.0, 41.0, 0.5)))
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--out",
                              tmp_path / "r", "--hazard", oq2, "--site", "11.1,41.2",
                              "--t-years", "25")
    assert code == 0, err
    assert "service life 25 years" in out and "(11.00000, 41.00000)" in out
    md = (tmp_path / "r" / "report.md").read_text()
    assert "given at report time" in md
    rk = pd.read_csv(tmp_path / "r" / "risk.csv")
    ok = rk.dropna(subset=["annual_frequency"])
    assert len(ok) and (ok["t_years"] == 25).all()
    # site 1 of the other file is 0.5 x the power law of the store's site 0 (scale 1.0):
    # the same fits, half the annual frequency (the curve is a power law within 1e-6)
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--out",
                              tmp_path / "r0")
    base = pd.read_csv(tmp_path / "r0" / "risk.csv").dropna(subset=["annual_frequency"])
    np.testing.assert_allclose(ok["annual_frequency"].to_numpy(),
                               0.5 * base["annual_frequency"].to_numpy(), rtol=1e-4)


@pytest.mark.parametrize("args, name", [
    (["--site", "1"], "--site"),
    (["--t-years", "-3"], "--t-years"),
    (["--hazard", "nothing.csv"], "--hazard"),
])
def test_cli_report_bad_hazard_options(store, capsys, args, name):
    code, out, err = run_main(capsys, "campaign", "report", store / "store", *args)
    assert_one_line_error(code, err, name)


def test_cli_report_refuses_a_hazard_of_another_im(store, capsys, tmp_path):
    p = tmp_path / "pgv.csv"
    p.write_text("PGV (m/s),annual rate\n0.1,0.01\n0.5,0.0004\n")
    code, out, err = run_main(capsys, "campaign", "report", store / "store", "--out",
                              tmp_path / "r", "--hazard", p)
    assert_one_line_error(code, err, "hazard")
    assert "PGV (m/s)" in err and "pga (m/s^2)" in err


def test_resuming_with_another_hazard_keeps_the_runs(store, tmp_path):
    """The hazard changes no run: a store resumes with another [hazard], keeps its chunks
    (same records) and takes the new curve into its manifest."""
    d = store
    s = campaign.Store(d / "store")
    before = {p.name: p.read_bytes() for p in (d / "store" / "chunks").iterdir()}
    old = s.manifest["hazard"]
    (d / "s2.toml").write_text(spec_text('[hazard]\npga_475 = "0.3g"\nt_years = 75'))
    logs = []
    st = campaign.run(d / "s2.toml", d / "store", progress=False, log=logs.append)
    assert st["complete"]
    after = {p.name: p.read_bytes() for p in (d / "store" / "chunks").iterdir()}
    assert after == before
    assert any("[hazard] changed" in m for m in logs)
    new = campaign.Store(d / "store").manifest["hazard"]
    assert new != old and new["approximate"] and new["t_years"] == 75.0
    assert 'pga_475 = "0.3g"' in (d / "store" / "spec.toml").read_text()
    # back to the first hazard, for the other tests of the module
    campaign.run(d / "s.toml", d / "store", progress=False, log=lambda m: None)
    assert campaign.Store(d / "store").manifest["hazard"] == old


# ------------------------------------------------------------------ runs stopped at the moat

MOAT = """
[campaign]
name = "moat"
seed = 5
model = "housner"
duration = 5.0

[[blocks]]
alpha = 0.25
p = 2.2
mu = 0.95

[motions]
kind = "sine"
frequency = [0.7, 1.0, 1.5, 2.2]
amplitude = 1.0
cycles = 3
im = "pga"
levels = {start = 0.8, stop = 8.0, num = 6, spacing = "log"}

[[mitigation]]
name = "none"

[[mitigation]]
name = "iso"
model = "isolated"
isolation_period = "2.5s"
isolation_damping = "10%"
clearance = "0.2m"
"""


@pytest.fixture(scope="module")
def moat():
    """A tiny isolated campaign (48 sine runs) whose 0.2 m moat stops some runs."""
    import warnings

    from rocking.campaign.plan import Campaign
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the isolated model's restitution remark
        spec = parse_spec(MOAT)
        c = Campaign(spec)
        t = c.run_ids(np.arange(c.n_sims))
    return t, manifest_for(spec)


def test_runs_stopped_at_the_clearance_fail_in_a_risk_of_their_own(moat, tmp_path):
    """Runs stopped at the isolator's clearance are no known survivors: the report gives
    the risk of overturned-or-clearance-reached, which is risk() of a fit of that failure
    made here (and compare_mitigations' with failure='auto'); the overturning row keeps no
    "at most" bound and says how many runs it counted as survivors."""
    from rocking.analysis import fragility
    from rocking.analysis.hazard import risk
    from rocking.analysis.mitigation import compare_mitigations
    table, man = moat
    iso = table[table["mitigation"] == "iso"]
    stop = iso["clearance_exceeded"].to_numpy(bool) & ~iso["overturned"].to_numpy(bool)
    assert 0 < stop.sum() < len(iso)  # the moat stops some runs, not all: can fail
    assert not iso["overturned"].any()  # so the overturning-only risk has no fit
    curve, src = read_hazard(power_law_csv(tmp_path / "h.csv", 0.01, 3.0, 12))
    res = report(table, man, tmp_path / "r", n_boot=0, hazard=record(curve, src, 50.0))
    rk = pd.read_csv(tmp_path / "r" / "risk.csv")
    r_iso = rk[rk["mitigation"] == "iso"].set_index("fit")
    # (1) the combined failure, fitted independently
    failed = iso["overturned"].to_numpy(bool) | iso["clearance_exceeded"].to_numpy(bool)
    f = fragility(iso["im"].to_numpy(float), failed, n_boot=0, im_name="pga",
                  im_unit="m/s^2")
    want = risk(f, curve, t_years=50.0)
    c = r_iso.loc["overturned_or_clearance"]
    assert c["label"] == "overturned or clearance reached"
    assert c["annual_frequency"] == pytest.approx(want.annual_frequency, rel=1e-8)
    assert c["probability"] == pytest.approx(want.probability_in(50.0), rel=1e-8)
    assert c["annual_frequency"] == pytest.approx(cornell(f.median / G, f.beta), rel=1e-6)
    by_im = table.drop(columns="pga").rename(columns={"im": "pga"})  # the level's PGA
    cmp = compare_mitigations(by_im, im="pga", im_unit="m/s^2", hazard=curve, n_boot=0)
    assert cmp.failure == "overturned_or_clearance"
    row = cmp.table.set_index("mitigation").loc["iso"]
    assert c["annual_frequency"] == pytest.approx(row["annual_frequency"], rel=1e-6)
    fr = pd.read_csv(tmp_path / "r" / "fragility.csv")
    fc = fr[(fr["mitigation"] == "iso") & (fr["fit"] == "overturned_or_clearance")].iloc[0]
    assert fc["n_exceed"] == failed.sum() and fc["median"] == pytest.approx(f.median,
                                                                            rel=1e-5)
    # (2) the overturning-only row: no number, no bound, the warning
    o = r_iso.loc["overturning"]
    assert math.isnan(o["annual_frequency"]) and math.isnan(o["annual_frequency_upper_bound"])
    warn = f"{int(stop.sum())} of {len(iso)} runs stopped at the isolator's clearance"
    assert warn in o["note"] and "not conservative" in o["note"] and "at most" not in \
        o["note"]
    fo = fr[(fr["mitigation"] == "iso") & (fr["fit"] == "overturning")].iloc[0]
    assert warn in fo["note"]
    lines = summary_lines(res)
    iso_lines = [x for x in lines if x.startswith("iso (isolated) / ")]
    ov_line = next(x for x in iso_lines if "no overturning fit (" in x)
    assert warn in ov_line and "at most" not in ov_line
    assert any(f"annual frequency {c['annual_frequency']:.3g} per year, 50-year probability "
               f"{c['probability']:.3g}" in x and "overturned or clearance reached" in x
               for x in iso_lines)
    md = (tmp_path / "r" / "report.md").read_text()
    assert "### iso (isolated): overturned or clearance reached" in md
    # p_overturn.csv: the stopped runs per level
    po = pd.read_csv(tmp_path / "r" / "p_overturn.csv")
    got = po[po["mitigation"] == "iso"].set_index("level")["n_clearance_exceeded"]
    pd.testing.assert_series_equal(
        got.sort_index(), pd.Series(stop, index=iso["level"]).groupby(level=0).sum(),
        check_names=False, check_dtype=False)
    # a group without runs at a clearance is as in a report without the isolated runs
    alone = report(table[table["mitigation"] == "none"].reset_index(drop=True), man,
                   tmp_path / "r0", n_boot=0, hazard=record(curve, src, 50.0))
    assert "overturned_or_clearance" not in set(alone["risk"]["fit"])
    full = (tmp_path / "r" / "risk.csv").read_text().splitlines()
    lone = (tmp_path / "r0" / "risk.csv").read_text().splitlines()
    assert [x for x in full if x.startswith("housner,none,")] == lone[1:] and \
        full[0] == lone[0] and len(lone) > 1


def test_a_fitted_overturning_risk_with_stopped_runs_carries_the_warning(table, tmp_path):
    """An isolated group that overturns (a fit) and whose moat stopped some survivors: the
    overturning number stands, with the warning on its row and line; the combined risk is
    at least as large (more failures at every IM) and is risk() of its own fit."""
    from rocking.analysis import fragility
    from rocking.analysis.hazard import risk
    t = table.copy()
    grp = ((t["mitigation"] == "isolated-2.5s") & (t["block"] == 0)).to_numpy()
    rng = np.random.default_rng(7)
    stop = grp & ~t["overturned"].to_numpy(bool) & (t["im"].to_numpy() > 3.0) & (
        rng.random(len(t)) < 0.5)
    t["clearance_exceeded"] = stop
    assert stop.sum() > 5
    curve, src = read_hazard(power_law_csv(tmp_path / "h.csv", 0.01, 3.0, 12))
    res = report(t, manifest(record(curve, src, 50.0)), tmp_path / "r", n_boot=0)
    rk = res["risk"]
    g = rk[(rk["mitigation"] == "isolated-2.5s") & (rk["block"] == 0)].set_index("fit")
    o, c = g.loc["overturning"], g.loc["overturned_or_clearance"]
    assert np.isfinite(o["annual_frequency"])
    assert f"{int(stop.sum())} of " in o["note"] and "not conservative" in o["note"]
    assert c["annual_frequency"] > o["annual_frequency"]
    ds = rk[(rk["mitigation"] == "isolated-2.5s") & (rk["block"] == 0)
            & (rk["fit"] == "damage_states")]
    assert len(ds) and ds["note"].str.contains("survivors with the angle").all()
    x, y = t.loc[grp, "im"].to_numpy(), (t["overturned"].to_numpy(bool) | stop)[grp]
    f = fragility(x, y, n_boot=0, im_name="pga", im_unit="m/s^2")
    assert c["annual_frequency"] == pytest.approx(risk(f, curve).annual_frequency,
                                                  rel=1e-8)
    line = next(x for x in summary_lines(res) if x.startswith(
        "isolated-2.5s (isolated) / block 0: annual frequency of overturning"))
    assert "stopped at the isolator's clearance" in line
    # the groups without stopped runs: no combined row, no warning
    other = rk[~((rk["mitigation"] == "isolated-2.5s") & (rk["block"] == 0))]
    assert "overturned_or_clearance" not in set(other["fit"])
    assert not other["note"].fillna("").str.contains("clearance").any()


# ------------------------------------------ probability-of-exceedance CSV, far OpenQuake site

def poe_csv(path: Path, t: float = 50.0, lo: float = 0.1, hi: float = 0.5,
            n: int = 6) -> Path:
    """The power law of :func:`power_law_csv` as a probability of exceedance in ``t``
    years (Poisson): ``poe = 1 - exp(-lambda t)``."""
    a = np.geomspace(lo, hi, n)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["PGA (g)", f"poe in {t:g} years"])
        w.writerows([[repr(float(x)), repr(float(-math.expm1(-t * K0 * x ** -K)))]
                     for x in a])
    return path


def test_a_poe_csv_with_investigation_time_is_the_rate_csv(tmp_path):
    """-ln(1 - poe)/T inverts poe = 1 - exp(-lambda T): the same curve as the rate CSV."""
    power_law_csv(tmp_path / "rate.csv")
    poe_csv(tmp_path / "poe.csv", t=50.0)
    a = parse_spec(spec_text('[hazard]\nfile = "rate.csv"'), base_dir=tmp_path).hazard
    b = parse_spec(spec_text('[hazard]\nfile = "poe.csv"\ninvestigation_time = 50'),
                   base_dir=tmp_path).hazard
    np.testing.assert_allclose(b["im"], a["im"], rtol=0)
    np.testing.assert_allclose(b["rate"], a["rate"], rtol=1e-12)
    assert b["source"]["investigation_time"] == 50.0


@pytest.mark.parametrize("hazard, key", [
    ('file = "poe.csv"', "hazard.investigation_time"),            # poe without T: refused
    ('file = "poe.csv"\ninvestigation_time = 30', "hazard.investigation_time"),  # header 50
    ('file = "poe.csv"\ninvestigation_time = 0', "hazard.investigation_time"),
    ('file = "rate.csv"\ninvestigation_time = 50', "hazard.investigation_time"),  # a rate
    ('file = "hazard_curve-mean-PGA_7.csv"\ninvestigation_time = 50',
     "hazard.investigation_time"),                                # OpenQuake states it
    ('file = "rate.csv"\nmax_distance_km = 100', "hazard.max_distance_km"),
    ('file = "hazard_curve-mean-PGA_7.csv"\nsite = [13.4, 42.4]\nmax_distance_km = -1',
     "hazard.max_distance_km"),
    ('file = "hazard_curve-mean-PGA_7.csv"\nsite = 0\nmax_distance_km = 100',
     "hazard.max_distance_km"),                                   # an index is that site
    ('pga_475 = "0.25g"\ninvestigation_time = 50', "hazard.investigation_time"),
    ('pga_475 = "0.25g"\nmax_distance_km = 50', "hazard.max_distance_km"),
])
def test_bad_poe_and_distance_keys_are_named(oq, tmp_path, hazard, key):
    power_law_csv(tmp_path / "rate.csv")
    poe_csv(tmp_path / "poe.csv", t=50.0)
    with pytest.raises(SpecError) as e:
        parse_spec(spec_text(f"[hazard]\n{hazard}"), base_dir=tmp_path)
    assert str(e.value).startswith(f"spec: {key}:"), str(e.value)
    assert "\n" not in str(e.value)


def test_a_far_openquake_site_is_refused_and_accepted_with_a_larger_limit(oq, tmp_path):
    """One degree of latitude north of site 0 is pi R / 180 = 111.19 km from it (on a
    meridian), farther from site 1: refused at the default 50 km, accepted at 200 km with
    that distance in the manifest's source."""
    ask = '[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"\nsite = [13.4, 43.35]'
    with pytest.raises(SpecError, match=r"^spec: hazard\.site: .*max_distance_km"):
        parse_spec(spec_text(ask), base_dir=tmp_path)
    with pytest.raises(SpecError, match=r"^spec: hazard\.site: .*max_distance_km"):
        parse_spec(spec_text(ask + "\nmax_distance_km = 100"), base_dir=tmp_path)
    h = parse_spec(spec_text(ask + "\nmax_distance_km = 200"), base_dir=tmp_path).hazard
    src = h["source"]
    assert src["site_index"] == 0 and src["max_distance_km"] == 200.0
    assert src["site_distance_km"] == pytest.approx(math.pi * 6371.0 / 180.0, rel=1e-9)
    # the curve is site 0's, the same as asked by index
    by_index = parse_spec(spec_text('[hazard]\nfile = "hazard_curve-mean-PGA_7.csv"\n'
                                    'site = 0'), base_dir=tmp_path).hazard
    assert h["rate"] == by_index["rate"] and "site_distance_km" not in by_index["source"]


def test_cli_report_poe_csv_and_a_far_site(store, capsys, tmp_path):
    """--investigation-time: a poe CSV gives the rate CSV's risk; --max-distance-km: a far
    OpenQuake site is refused (exit 2) at the default and accepted with a larger limit."""
    d = store
    rate, poe = power_law_csv(tmp_path / "rate.csv"), poe_csv(tmp_path / "poe.csv", t=50.0)
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--out",
                              tmp_path / "ra", "--hazard", rate)
    assert code == 0, err
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--out",
                              tmp_path / "rb", "--hazard", poe, "--investigation-time", "50")
    assert code == 0, err
    ra, rb = (pd.read_csv(tmp_path / r / "risk.csv") for r in ("ra", "rb"))
    assert np.isfinite(ra["annual_frequency"]).any()
    for col in ("annual_frequency", "probability"):
        np.testing.assert_allclose(rb[col], ra[col], rtol=1e-9)
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--hazard", poe)
    assert_one_line_error(code, err, "--investigation-time")
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--hazard",
                              d / "hazard_curve-mean-PGA_7.csv", "--site", "13.4,43.35")
    assert_one_line_error(code, err, "--max-distance-km")
    assert "--site" in err and "111" in err
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--out",
                              tmp_path / "rc", "--hazard", d / "hazard_curve-mean-PGA_7.csv",
                              "--site", "13.4,43.35", "--max-distance-km", "200")
    assert code == 0, err
    code, out, err = run_main(capsys, "campaign", "report", d / "store", "--out",
                              tmp_path / "rd")  # the store's own: site 0 of that file
    assert code == 0, err
    rc, rd = (pd.read_csv(tmp_path / r / "risk.csv") for r in ("rc", "rd"))
    np.testing.assert_allclose(rc["annual_frequency"], rd["annual_frequency"], rtol=1e-12)


@pytest.mark.parametrize("args, name", [
    (["--investigation-time", "50"], "--investigation-time"),
    (["--max-distance-km", "100"], "--max-distance-km"),
])
def test_cli_report_poe_and_distance_options_need_hazard(store, capsys, args, name):
    code, out, err = run_main(capsys, "campaign", "report", store / "store", *args)
    assert_one_line_error(code, err, name)
