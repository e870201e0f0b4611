"""The report section "A real object" (issue 20), quick mode: its files, and the physics its
tables must obey whatever the numbers (the weakest direction is the table's minimum, the
planar parameters' closed forms and the phi + 180 deg swap, no uplift below g tan alpha,
the fragility medians in order, the sweep at phi = 0 equal to the planar run, the
projected PGA bounded by the largest horizontal acceleration vector)."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from conftest import report_section

import rocking
from rocking.motions import GroundMotion, HorizontalPair, load_builtin
from rocking.report.sections import real_object as S
from rocking.shapes import load_example
from rocking.units import G

CSVS = ("mass_properties", "directional", "fragility_runs", "fragility", "sweep", "worst")
PNGS = ("mesh", "directional", "fragility", "sweep")


@pytest.fixture(scope="module")
def section_out(request):
    """The section in quick mode (conftest.report_section: the session's quick report
    when it builds one, else the section alone)."""
    out, index, _ = report_section(request, "real_object")
    return out, index


def _csv(out, name):
    return pd.read_csv(out / f"real_object_{name}.csv", keep_default_na=False,
                       na_values=["", "nan", "NaN"])


def test_page_and_files(section_out):
    out, index = section_out
    text = index.read_text(encoding="utf-8")
    assert 'id="real_object"' in text and 'class="error"' not in text
    for words in ("standard engineering answer until a 3-D model exists",
                  "no coupling between", "no twisting", "no wobbling", "Limits"):
        assert words in text, words
    for name in PNGS:
        p = out / f"real_object_{name}.png"
        assert p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name
        assert f'src="real_object_{name}.png"' in text
    for name in CSVS:
        assert f'href="real_object_{name}.csv"' in text, name
    assert sorted(p.name for p in out.glob("real_object_*")) == sorted(
        [f"real_object_{n}.png" for n in PNGS] + [f"real_object_{n}.csv" for n in CSVS])


def test_mass_properties_are_the_meshs(section_out):
    m = _csv(section_out[0], "mass_properties").set_index("quantity").value
    shape = load_example(density=S.DENSITY)
    assert m["mass"] == pytest.approx(S.DENSITY * m["volume"], rel=1e-7)
    assert m["mass"] == pytest.approx(shape.mass, rel=1e-7)
    # principal moments of a body: each at most the sum of the other two
    i1, i2, i3 = (m[f"principal inertia I{k}"] for k in (1, 2, 3))
    assert 0 < i1 <= i2 <= i3 <= (i1 + i2) * (1 + 1e-7)


def test_directional_table_physics(section_out):
    t = _csv(section_out[0], "directional")
    np.testing.assert_allclose(np.tan(t.alpha_plus), t.b_plus / t.h, rtol=1e-6)
    np.testing.assert_allclose(np.tan(t.alpha_minus), t.b_minus / t.h, rtol=1e-6)
    np.testing.assert_allclose(t.uplift_plus, G * np.tan(t.alpha_plus), rtol=1e-6)
    np.testing.assert_allclose(t.p_plus ** 2, G * t.R_plus / (t.radius_of_gyration ** 2
                                                               + t.R_plus ** 2), rtol=1e-6)
    # phi + 180 deg swaps the sides
    n = len(t)
    half = n // 2
    np.testing.assert_allclose(t.alpha_plus.to_numpy()[:half], t.alpha_minus.to_numpy()[half:],
                               rtol=1e-6)


def test_weakest_and_strongest_directions_are_the_table_extremes(section_out):
    out = section_out[0]
    t = _csv(out, "directional")
    amin = np.minimum(t.alpha_plus, t.alpha_minus)
    f = _csv(out, "fragility").set_index("direction")
    for label, k in (("weakest", amin.idxmin()), ("strongest", amin.idxmax())):
        r = f.loc[label]
        # the extreme row or its mirror (phi + 180 deg), named by its weak side "+"
        assert (r.phi_deg - t.phi_deg[k]) % 180.0 == pytest.approx(0.0, abs=1e-6)
        assert r.alpha_plus == pytest.approx(amin[k], rel=1e-6)
    assert min(f.loc["weakest", ["alpha_plus", "alpha_minus"]]) == pytest.approx(amin.min(),
                                                                                 rel=1e-6)


def test_no_uplift_below_the_weaker_sides_uplift_acceleration(section_out):
    """A record scaled to a PGA below g tan(alpha) of the weaker side never lifts the
    block from rest (the classical model's uplift criterion, per side)."""
    runs = _csv(section_out[0], "fragility_runs")
    cap = np.tan(np.minimum(runs.alpha_plus, runs.alpha_minus))
    below = runs[runs.pga_g < cap * (1 - 1e-6)]
    assert len(below) > 0
    assert not below.uplifted.any() and not below.overturned.any()
    assert (below.max_abs_theta == 0.0).all()
    # both directions ran the same motions
    w, s = (runs[runs.direction == d][["record", "pga_g"]].to_numpy() for d in
            ("weakest", "strongest"))
    np.testing.assert_array_equal(w, s)


def test_fragility_in_the_weakest_direction_is_not_stronger(section_out):
    f = _csv(section_out[0], "fragility").set_index("direction")
    w, s = f.loc["weakest"], f.loc["strongest"]
    assert np.isfinite(w.median_g) and np.isfinite(s.median_g), f.note.to_dict()
    tol = 2.0 * math.hypot(w.median_se_g, s.median_se_g)
    assert w.median_g <= s.median_g + tol
    assert w.n_overturned >= s.n_overturned - 2 * math.sqrt(w.n)


def test_sweep_at_phi_zero_equals_the_planar_run(section_out):
    sw = _csv(section_out[0], "sweep")
    shape = load_example(density=S.DENSITY)
    pair = HorizontalPair.builtin(S.PAIR)
    blk = rocking.Block.from_shape(shape, 0.0)
    up = load_builtin("RinaldiUP")
    for s in S.SCALES[0]:
        for vertical in (False, True):
            row = sw[(sw.scale == s) & (sw.vertical == vertical) & (sw.phi == 0.0)].iloc[0]
            motion = (GroundMotion(pair.first, up).scaled(s) if vertical
                      else pair.first.scaled(s))
            r = rocking.simulate(blk, motion)
            assert row.max_abs_theta == r.max_abs_theta
            assert bool(row.overturned) == r.overturned
            assert row.n_impacts == r.n_impacts
            for k in ("overturn_time", "uplift_time"):
                a, b = row[k], getattr(r, k)
                assert a == b or (np.isnan(a) and np.isnan(b)), k
            assert row.pga == pytest.approx(s * pair.pga_components[0], rel=1e-12)


def test_sweep_pga_and_worst_direction(section_out):
    out = section_out[0]
    sw, worst = _csv(out, "sweep"), _csv(out, "worst")
    pair = HorizontalPair.builtin(S.PAIR)
    assert (sw.pga <= sw.scale * pair.peak_resultant * (1 + 1e-9)).all()
    # the response grows with the load factor: overturned directions never fewer
    h = worst[~worst.vertical.astype(bool)].sort_values("scale")
    assert np.all(np.diff(h.n_overturned.to_numpy()) >= -1)
    for r in worst.itertuples():
        t = sw[(sw.scale == r.scale) & (sw.vertical == r.vertical)]
        assert t.worst.sum() == 1
        w = t[t.worst.astype(bool)].iloc[0]
        assert w.phi_deg == pytest.approx(r.worst_phi_deg)
        if t.overturned.any():  # the worst overturns, first
            assert w.overturned and w.overturn_time == t.overturn_time.min()
        d = abs((r.worst_phi_deg - r.static_weakest_phi_deg + 90.0) % 180.0 - 90.0)
        assert r.angle_to_static_weakest_deg == pytest.approx(d)
