"""Plots a reader can tell apart and read (issue 31, item 8): several fragility curves on
one axes get distinct colours and line styles and a legend outside the data; the
direction sweep's polar plot has labels and a title; DirectionFragility has a plot that
marks the direction of the smallest median; theta(t) of an asymmetric block draws each
side's own overturning angle."""

from __future__ import annotations

import math

import matplotlib
import numpy as np
import pytest
from scipy.stats import norm

matplotlib.use("Agg")

import rocking  # noqa: E402
from rocking.analysis import direction_fragility, direction_sweep, fragility  # noqa: E402
from rocking.motions import HorizontalPair, Record  # noqa: E402
from rocking.plot import figure, plot_response  # noqa: E402

DT = 0.005
PULSE = np.sin(2 * np.pi * np.arange(0.0, 1.0, DT))  # a 1 Hz one-sine, m/s^2
PAIR = HorizontalPair(Record(3.0 * PULSE, DT), Record(PULSE, DT))


def _fit(median, seed=0):
    im = np.repeat([0.5, 1.0, 2.0, 4.0, 8.0, 16.0], 20)
    j = np.tile(np.arange(20), 6)
    failed = j < np.round(20 * norm.cdf(np.log(im / median) / 0.5))
    return fragility(im, failed, n_boot=20, seed=seed, im_name="pga", im_unit="m/s^2",
                     label=f"median {median}")


def _bbox(artist, fig):
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    return artist.get_window_extent(canvas.get_renderer())


def test_fits_on_one_axes_have_distinct_colours_and_styles_and_the_legend_is_outside():
    fig, ax = figure()
    fits = [_fit(m) for m in (1.0, 2.0, 4.0, 8.0)]
    for f in fits:
        f.plot(ax=ax)
    curves = [ln for ln in ax.lines if ln.get_gid() == "rocking.fragility_curve"]
    assert len(curves) == 4
    styles = {(matplotlib.colors.to_hex(c.get_color()), str(c.get_linestyle()))
              for c in curves}
    assert len({s[0] for s in styles}) == 4 and len({s[1] for s in styles}) == 4
    # each curve is the fit it belongs to (the colour did not move to another curve)
    for c, f in zip(curves, fits, strict=True):
        x = np.asarray(c.get_xdata())
        assert np.allclose(c.get_ydata(), f.probability(x))
    # one grey entry for the bands, not one per curve; the legend beside, not on, the data
    texts = [t.get_text() for t in ax.get_legend().get_texts()]
    assert sum("band" in t for t in texts) == 1 and len(texts) == 5
    leg = _bbox(ax.get_legend(), fig)
    assert leg.x0 >= ax.get_window_extent().x1 - 1.0
    # an explicit colour and style are kept
    fig, ax = figure()
    fits[0].plot(ax=ax, color="k", ls=":")
    assert ax.lines[0].get_color() == "k" and ax.lines[0].get_linestyle() == ":"


def test_the_direction_sweep_plot_is_labelled_titled_and_marks_the_worst_direction():
    sw = direction_sweep(rocking.specimen(2), PAIR, 4, duration=5.0)
    ax = sw.plot().axes[0]
    assert PAIR.name in ax.get_title() and "max |θ| / α" in ax.get_title()
    assert "phi" in ax.get_xlabel() and "deg" in ax.get_xlabel()
    worst = [ln for ln in ax.lines if str(ln.get_label()).startswith("worst")]
    assert len(worst) == 1
    assert np.allclose(worst[0].get_xdata(), sw.worst_phi)
    assert f"{math.degrees(sw.worst_phi):.0f} deg" in worst[0].get_label()


def test_direction_fragility_plot_marks_the_smallest_median_and_draws_bounds():
    levels = [1.0, 2.0, 4.0, 8.0]
    df = direction_fragility(rocking.specimen(2), [PAIR], levels, 6, duration=5.0, n_boot=0)
    fig = df.plot()
    axp, axc = fig.axes
    assert axp.name == "polar" and axp.get_title() and fig.get_suptitle()
    # no direction has a fit here: a bar per direction (and its mirror) from bound to bound
    bars = [ln for ln in axp.lines if ln.get_linewidth() == 3]
    t = df.table
    has = t.median_lower_bound.notna() | t.median_upper_bound.notna()
    assert len(bars) == 2 * int(has.sum())  # a Block: mirrored (the same response)
    hi = t.median_upper_bound.to_numpy(float)
    w = int(np.nanargmin(hi))
    weak = [ln for ln in axp.lines if str(ln.get_label()).startswith("weakest")]
    assert np.allclose(weak[0].get_xdata(), t.phi.iloc[w])
    # with fits: the curves on the right are the fits, the weakest first
    levels = np.geomspace(1.0, 12.0, 8)
    pairs = [PAIR, HorizontalPair(Record(PULSE, DT), Record(2.0 * PULSE, DT)),
             HorizontalPair(Record(np.sin(2 * np.pi * 2 * np.arange(0, 1, DT)), DT),
                            Record(PULSE, DT))]
    df = direction_fragility(rocking.specimen(2), pairs, levels, 4, duration=5.0, n_boot=0)
    assert df.fits, df.table
    fig = df.plot(curves=2)
    axc = fig.axes[1]
    curves = [ln for ln in axc.lines if ln.get_gid() == "rocking.fragility_curve"]
    meds = sorted(f.median for f in df.fits.values())
    assert len(curves) == min(2, len(meds))
    x = np.asarray(curves[0].get_xdata())
    first = min(df.fits.values(), key=lambda f: f.median)
    assert np.allclose(curves[0].get_ydata(), first.probability(x))


def test_direction_fragility_plot_draws_directions_of_one_fit_once():
    """Directions with the same outcomes have the same fit: one curve, named by each (a
    second curve would hide under the first)."""
    import pandas as pd

    from rocking.analysis import DirectionFragility
    im = np.repeat([1.0, 2.0, 3.0, 4.0, 6.0], 40)
    failed = np.tile(np.arange(40), 5) < np.round(40 * norm.cdf(np.log(im / 3) / 0.4))
    same = fragility(im, failed, n_boot=0, im_name="pga", im_unit="m/s^2")
    other = fragility(im, np.tile(np.arange(40), 5) < np.round(
        40 * norm.cdf(np.log(im / 2) / 0.3)), n_boot=0, im_name="pga", im_unit="m/s^2")
    phi = np.radians([0.0, 45.0, 90.0])
    fits = {0: same, 1: other, 2: same}
    table = pd.DataFrame({"phi": phi, "phi_deg": np.degrees(phi),
                          "median": [f.median for f in fits.values()],
                          "beta": [f.beta for f in fits.values()],
                          "median_lower_bound": np.nan, "median_upper_bound": np.nan})
    fig = DirectionFragility(table, pd.DataFrame(), fits, "larger").plot()
    axc = fig.axes[1]
    curves = [ln for ln in axc.lines if ln.get_gid() == "rocking.fragility_curve"]
    labels = [t.get_text() for t in axc.get_legend().get_texts()]
    assert len(curves) == 2
    assert any(x.startswith("0 and 90 deg: ") for x in labels), labels
    assert any(x.startswith("45 deg: ") for x in labels), labels


@pytest.mark.parametrize("asym", [True, False])
def test_theta_plot_draws_each_sides_alpha(asym):
    block = (rocking.Block.from_geometry(h=0.8, b_plus=0.2, b_minus=0.25,
                                         radius_of_gyration=0.5) if asym
             else rocking.specimen(2))
    resp = rocking.simulate(block, rocking.motions.Sine(freq=2.0, amplitude=0.05, duration=2.0))
    fig, ax = figure()
    plot_response(resp, ax=ax, show_alpha=True)
    ys = sorted(float(ln.get_ydata()[0]) for ln in ax.lines if ln.get_linestyle() == "--")
    want = sorted([math.degrees(block.alpha_plus), -math.degrees(block.alpha_minus)])
    assert np.allclose(ys, want)
    if asym:
        assert abs(ys[0]) != abs(ys[1])


def test_simulate_reports_each_sides_peak_over_its_own_alpha(capsys, tmp_path):
    """``rocking simulate`` of an asymmetric block: the text gives each side's peak over
    that side's alpha (the response's own peaks), and theta.png is written."""
    import re

    from cli_helpers import run_main

    from rocking.shapes import example_mesh_path

    args = ["simulate", "--mesh", str(example_mesh_path()), "--density", "2600",
            "--direction", "200", "--motion", "ricker", "--amp", "0.6g", "--freq", "1.5"]
    code, out, err = run_main(capsys, *args, "--out", str(tmp_path))
    assert code == 0, err
    m = re.search(r"\(\S+ rad, (\S+) alpha\+ on side \+, (\S+) alpha- on side -\)", out)
    assert m, out
    block = rocking.Block.from_mesh(example_mesh_path(), density=2600.0, direction=200)
    assert not block.symmetric
    import pandas as pd

    th = pd.read_csv(tmp_path / "response.csv")["theta"].to_numpy(float)
    assert th.max() > 0.0 > th.min()  # it rocked on both sides
    assert float(m[1]) == pytest.approx(th.max() / block.alpha_plus, rel=2e-3)
    assert float(m[2]) == pytest.approx(-th.min() / block.alpha_minus, rel=2e-3)
    assert (tmp_path / "theta.png").stat().st_size > 0
