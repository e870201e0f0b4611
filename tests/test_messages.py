"""Labels, units and messages say what is true (issue 16, section 5).

Overturning modes numbered as in Zhang and Makris (2001); fragility fits that carry their
IM's name and unit (and an annual frequency that refuses a hazard curve in another unit);
CLI messages in the user's words; plots with units and legends that hide no data.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import click
import numpy as np
import pandas as pd
import pytest
from cli_helpers import run_main

import rocking
import rocking.analysis as A
from rocking.analysis.overturning import pulse_motion
from rocking.errors import ParameterError
from rocking.units import G


def one_error_line(err: str) -> str:
    lines = err.strip("\n").splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("error: "), err
    return lines[0]


# ----------------------------------------------------------------- overturning modes

def test_modes_follow_zhang_and_makris_on_a_physical_case():
    """Specimen 1 under a one-sine pulse at omega_p/p = 2: a pulse 1.4 times the uplift
    acceleration overturns the block after one impact (mode 1: the tongue), one 8 times
    it without any impact (mode 2), as in Zhang and Makris (2001)."""
    b = rocking.specimen(1, "experimental")
    after = rocking.simulate(b, pulse_motion(b, "one_sine", 2.0, 1.4))
    direct = rocking.simulate(b, pulse_motion(b, "one_sine", 2.0, 8.0))
    assert after.overturned and after.n_impacts == 1
    assert direct.overturned and direct.n_impacts == 0
    m = A.outcome_map(b, "one_sine", [2.0], [1.4, 8.0])
    assert m["n_impacts"].tolist() == [1, 0]
    assert m["mode"].tolist() == [1, 2]
    spec = A.overturning_spectrum(b, "one_sine", [2.0], tol=0.02)
    assert int(spec["n_impacts"].iloc[0]) >= 1 and int(spec["mode"].iloc[0]) == 1


def test_mode_labels_and_docstrings_say_the_same():
    from rocking.analysis import overturning as o

    assert o._MODE_LABELS[1] == "mode 1 (after an impact)"
    assert o._MODE_LABELS[2] == "mode 2 (no impact)"
    doc = o.overturning_spectrum.__doc__
    assert "1, overturning after one or more impacts" in doc
    assert "2, overturning without any impact" in doc
    readme = Path(__file__).resolve().parents[1] / "README.md"
    if readme.exists():
        assert "1 = overturns after an impact" in readme.read_text(encoding="utf-8")


# ----------------------------------------------------------------- fragility fits

def _stripes(seed=0):
    rng = np.random.default_rng(seed)
    im = np.repeat(np.geomspace(1.0, 8.0, 8), 40)
    failed = rng.random(im.size) < 0.5 * (1.0 + np.vectorize(math.erf)(
        np.log(im / 3.0) / (0.4 * math.sqrt(2.0))))
    return im, failed


def test_fit_carries_its_im_and_repr_is_short():
    im, failed = _stripes()
    fit = A.fragility(im, failed, im_name="pga", im_unit="m/s^2", label="overturning")
    assert (fit.im_name, fit.im_unit) == ("pga", "m/s^2")
    for k in ("median", "beta", "median_se", "beta_se", "loglike"):
        assert type(getattr(fit, k)) is float, k
    r = repr(fit)
    assert len(r) < 160 and "\n" not in r and "array" not in r and "[" not in r, r
    assert "pga" in r and "m/s^2" in r and f"{fit.median:.4g}" in r
    assert fit.summary()["im_unit"] == "m/s^2"
    assert fit.plot().get_xlabel() == "PGA (m/s$^2$)"
    cap = fit.median * np.exp(0.3 * np.random.default_rng(1).standard_normal(30))
    ida_fit = A.fragility_ida(cap, im_name="pga", im_unit="g")
    assert ida_fit.im_unit == "g" and type(ida_fit.beta) is float
    state = np.where(failed, 2, (im > 2.0).astype(int))
    curves = A.fragility_curves(im, state, im_name="pga", im_unit="m/s^2")
    assert {(f.im_name, f.im_unit) for f in curves.fits} == {("pga", "m/s^2")}
    assert len(repr(curves)) < 600


def test_annual_frequency_refuses_a_hazard_curve_in_other_units():
    """The case found: a hazard curve in g with a fit in m/s^2 gave 1.6e-9 silently."""
    im, failed = _stripes()
    fit = A.fragility(im, failed, im_name="pga", im_unit="m/s^2")
    h_g = np.geomspace(0.02, 3.0, 13)
    rate = 1e-3 * (h_g / 0.1) ** -2.5
    with pytest.raises(ParameterError, match=r"hazard_unit='g' differs .*m/s\^2"):
        A.annual_frequency(fit, h_g, rate, hazard_unit="g")
    with pytest.raises(ParameterError, match="hazard_unit is required"):
        A.annual_frequency(fit, h_g, rate)
    lam = A.annual_frequency(fit, h_g * G, rate, hazard_unit="m/s^2")
    assert A.annual_frequency(fit, h_g * G, rate, hazard_unit="mps2") == lam
    # the same curve fitted in g agrees with the hazard in g
    fit_g = A.fragility(im / G, failed, im_name="pga", im_unit="g")
    assert A.annual_frequency(fit_g, h_g, rate, hazard_unit="g") == pytest.approx(lam,
                                                                                   rel=1e-6)
    curves = A.fragility_curves(im, np.where(failed, 2, (im > 2.0).astype(int)),
                                im_name="pga", im_unit="m/s^2")
    with pytest.raises(ParameterError, match="differs"):
        A.annual_frequency(curves, h_g, rate, hazard_unit="g")


def test_pelicun_table_uses_the_fit_unit():
    im, failed = _stripes()
    fit_g = A.fragility(im / G, failed, im_name="pga", im_unit="g", n_boot=0)
    fit_si = A.fragility(im, failed, im_name="pga", im_unit="m/s^2", n_boot=0)
    t_g = float(fit_g.to_pelicun(demand_unit="g")["LS1-Theta_0"].iloc[0])
    t_si = float(fit_si.to_pelicun(demand_unit="g")["LS1-Theta_0"].iloc[0])
    assert t_g == pytest.approx(fit_g.median, rel=1e-12)
    assert t_si == pytest.approx(fit_si.median / G, rel=1e-12)
    with pytest.raises(ParameterError, match="contradicts"):
        fit_g.to_pelicun(demand_unit="g", im_unit="mps2")


# ----------------------------------------------------------------- plots

def test_damage_state_legend_covers_no_curve():
    im, failed = _stripes()
    curves = A.fragility_curves(im, np.where(failed, 2, (im > 2.0).astype(int)),
                                im_name="pga", im_unit="m/s^2")
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    ax = curves.plot()
    fig = ax.figure
    FigureCanvasAgg(fig).draw()
    leg = ax.get_legend()
    texts = [t.get_text() for t in leg.get_texts()]
    assert sum("band" in t for t in texts) == 1  # one entry for the bands, not one each
    assert len(texts) == len(curves) + 1
    renderer = fig.canvas.get_renderer()
    assert leg.get_window_extent(renderer).x0 >= ax.get_window_extent(renderer).x1
    assert ax.get_xlabel() == "PGA (m/s$^2$)"


def test_plot_ida_axis_has_the_im_and_its_unit():
    table = pd.DataFrame({"record": [0, 0, 1, 1], "im": [1.0, 2.0, 1.0, 2.0],
                          "max_abs_theta_over_alpha": [0.1, 0.5, 0.2, 0.3],
                          "overturned": [False, True, False, False]})
    table.attrs.update(im="pga", unit="m/s^2")
    assert A.plot_ida(table).get_xlabel() == "PGA (m/s$^2$)"
    table.attrs.update(im="pga_ratio", unit="-")
    assert A.plot_ida(table).get_xlabel().startswith("PGA / (")


def test_campaign_plot_units_names_and_title(tmp_path, monkeypatch):
    from rocking import campaign
    from rocking.campaign import report as crep

    spec = tmp_path / "spec.toml"
    spec.write_text("""
[campaign]
name = "labels"
seed = 1
model = "housner"

[[blocks]]
width = 0.2
height = 1.0

[[blocks]]
specimen = 2
params = "experimental"

[motions]
kind = "stochastic"
n = 6
im = "pga"
levels = {start = 1.0, stop = 8.0, num = 6, spacing = "log"}
""")
    campaign.run(spec, tmp_path / "st", progress=False, log=lambda m: None)
    figs = []
    real = crep.save_figure
    monkeypatch.setattr(crep, "save_figure", lambda fig, path, **kw: (figs.append(fig),
                                                                     real(fig, path, **kw))[1])
    crep.report(campaign.load(tmp_path / "st", lazy=False),
                campaign.Store(tmp_path / "st").manifest, tmp_path / "rep")
    (ax,) = figs[0].axes
    assert ax.get_xlabel() == "PGA (m/s$^2$)"
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert not any(lab.startswith("block 0") for lab in labels), labels
    assert any(lab.startswith("0.2 x 1 m block (blocks[0])") for lab in labels), labels
    md = (tmp_path / "rep" / "report.md").read_text()
    assert "block 0" not in md and "0.2 x 1 m block (blocks[0])" in md
    assert any(lab.startswith("specimen 2 (experimental)") for lab in labels), labels
    assert ax.title.get_fontsize() >= 10


def test_report_sections_13_16_17(tmp_path, monkeypatch):
    """Section 13 prints its distributions to 3 figures with units; section 16 gives its
    medians in g in the table and in the plots; section 17's legend is outside the
    panels."""
    from rocking.report import core, reproduce
    from rocking.report.sections.probability import describe

    assert describe("alpha", {"dist": "normal", "std": 0.0025000000000000022}) == \
        "normal, std 0.0025 rad"
    figs = {}
    real = core.Context.save_figure

    def capture(self, fig, name, caption, alt=""):
        figs[f"{self.section_id}_{name}"] = fig
        return real(self, fig, name, caption, alt)

    monkeypatch.setattr(core.Context, "save_figure", capture)
    index = reproduce(tmp_path, quick=True, progress=False, jobs=1,  # figures captured here
                      only=["probability", "fragility", "vertical"])
    html = index.read_text(encoding="utf-8")
    assert "0.0025000000000000022" not in html and "std 0.0025 rad" in html
    assert "median DS1 (g)" in html
    xlabels = {a.get_xlabel() for a in figs["fragility_curves"].axes} - {""}
    assert xlabels == {"PGA (g)"}
    fits = pd.read_csv(tmp_path / "fragility_fits.csv")
    pel = pd.read_csv(tmp_path / "fragility_pelicun.csv")
    assert pel["LS3-Theta_0"].iloc[0] == pytest.approx(
        fits[(fits.fit == "common_beta") & (fits.state == 3)].median_g.iloc[0], rel=1e-5)
    vfig = figs["vertical_vertical"]
    assert vfig.legends and all(a.get_legend() is None for a in vfig.axes)


# ----------------------------------------------------------------- CLI

def test_python_m_rocking():
    r = subprocess.run([sys.executable, "-m", "rocking", "--version"], capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "rocking, version" in r.stdout


def test_earthquake_title_and_vertical_pga_as_run(tmp_path, capsys):
    from rocking.cli.simulate import _motion_title, make_motion

    m, desc, _ = make_motion(None, None, None, None, None, None, None, None, "1.1",
                             earthquake="20")
    title = _motion_title(desc)
    assert "free rocking" not in title
    assert title == f"earthquake 20 (PGA {m.pga / G:.3g} g), load factor 1.1"
    code, out, err = run_main(capsys, "simulate", "--specimen", "2", "--record",
                              "Rinaldi228", "--vertical", "RinaldiUP", "--load-factor", "0.5",
                              "--duration", "1", "--out", tmp_path)
    assert code == 0, err
    rec = rocking.motions.load_builtin("Rinaldi228")
    motion = json.loads((tmp_path / "summary.json").read_text())["inputs"]["motion"]
    assert motion["pga"] == pytest.approx(0.5 * rec.pga, rel=1e-12)
    line = next(x for x in out.splitlines() if x.startswith("motion"))
    assert f"pga={0.5 * rec.pga:.3f} m/s^2, scale=0.5" in line, line
    _, desc, _ = make_motion(None, None, None, None, None, "Rinaldi228", None, None, "0.5",
                             vertical="RinaldiUP")
    assert f"(PGA {0.5 * rec.pga / G:.3g} g, " in _motion_title(desc)


def test_damping_percent_message(tmp_path, capsys):
    f = tmp_path / "a.csv"
    f.write_text("# dt = 0.01 s\n" + "\n".join(f"{math.sin(i / 5):.4f}" for i in range(200)))
    code, _, err = run_main(capsys, "motion", "spectrum", f, "--damping", "500%",
                            "--no-plot")
    line = one_error_line(err)
    assert code == 2 and "'500%'" in line and "5.0" not in line, line


def test_an_acceleration_unit(tmp_path, capsys):
    code, _, err = run_main(capsys, "motion", "synth", "--ag", "3", "--out", tmp_path)
    line = one_error_line(err)
    assert code == 2 and "needs an acceleration unit" in line, line


def test_record_units_message_without_units(tmp_path, capsys):
    f = tmp_path / "acc.csv"
    f.write_text("# units: m/s^2\n# dt = 0.01 s\n0.1\n0.2\n-0.1\n0.0\n")
    code, _, err = run_main(capsys, "simulate", "--specimen", "2", "--record", f)
    line = one_error_line(err)
    assert code == 2 and "units='g'" not in line and "--units was not given" in line, line
    assert "pass --units m/s^2" in line
    code, _, err = run_main(capsys, "simulate", "--specimen", "2", "--record", f,
                            "--units", "g")
    assert "--units g was given" in one_error_line(err)
    for cmd in (("motion", "spectrum"), ("motion", "show")):
        code, _, err = run_main(capsys, *cmd, f, "--no-plot")
        line = one_error_line(err)
        assert code == 2 and "units='g'" not in line and "--units was not given" in line


def test_spec_message_has_one_prefix():
    from rocking.campaign import parse_spec
    from rocking.errors import SpecError

    text = ("[campaign]\nname = 'x'\nseed = 1\nmodel = 'housner'\n[[blocks]]\nspecimen = 2\n"
            "[motions]\nkind = 'builtin'\nname = ['Rinaldi228']\n"
            "[uncertain]\nalpha = {dist = 'normal', cov = -1}\n")
    with pytest.raises(SpecError) as e:
        parse_spec(text)
    msg = str(e.value)
    assert msg.startswith("spec: uncertain.alpha"), msg
    assert "uncertain[" not in msg, msg


def test_identify_non_rocking_file_is_one_line(tmp_path):
    t = np.arange(0.0, 5.0, 0.01)
    theta = 30.0 * np.exp(-0.3 * t) * np.cos(2.0 * np.pi * t)  # degrees read as rad
    f = tmp_path / "r.csv"
    f.write_text("t,theta\n" + "\n".join(f"{a:.2f},{b:.6f}" for a, b in zip(t, theta, strict=True)))
    r = subprocess.run([sys.executable, "-m", "rocking", "identify", str(f), "--out",
                        str(tmp_path / "out")], capture_output=True, text=True, timeout=300)
    assert r.returncode == 2, r.stderr
    assert "Warning" not in r.stderr, r.stderr
    one_error_line(r.stderr)


@pytest.mark.parametrize("size", [("1e308", "1"), ("0.2", "1e308"), ("1e200", "1e200")])
def test_huge_block_names_width_not_p(capsys, size):
    code, _, err = run_main(capsys, "simulate", "--width", size[0], "--height", size[1],
                            "--motion", "one_sine", "--amp", "0.3g", "--tp", "0.5")
    errors = [x for x in err.splitlines() if x.startswith("error:")]  # (and a warning)
    assert len(errors) == 1, err
    line = errors[0]
    assert code == 2 and "--width" in line and "p must" not in line, line
    assert "vertices" not in line


def test_reproduce_out_that_cannot_be_created(tmp_path, capsys):
    (tmp_path / "afile").write_text("x")
    code, _, err = run_main(capsys, "reproduce", "--out", tmp_path / "afile" / "x", "--quick")
    line = one_error_line(err)
    assert code == 2 and "--out" in line and "Errno" not in line, line


def test_early_ctrl_c_is_an_interrupt_not_an_abort(tmp_path, capsys, monkeypatch):
    """Ctrl-C before the command's own handler (while click parses the arguments, or while
    the campaign is being set up): exit 130 and 'interrupted', not 'error: aborted' (1)."""
    def boom(*a, **k):
        raise KeyboardInterrupt

    with monkeypatch.context() as mp:
        mp.setattr(click.Command, "parse_args", boom)
        code, _, err = run_main(capsys, "campaign", "run", "spec.toml", "--out", tmp_path)
    assert code == 130 and "interrupted" in err and "error" not in err, err
    import rocking.campaign as C

    spec = Path(__file__).resolve().parents[1] / "examples" / "fragility.toml"
    monkeypatch.setattr(C, "run", boom)
    code, _, err = run_main(capsys, "campaign", "run", spec, "--out", tmp_path / "st")
    assert code == 130 and "interrupted" in err and "error" not in err, err
