"""Campaigns of the 3-D rigid body (``model = "rigid3d"``, issue 30): box, cylinder and
mesh bodies in ``[[blocks]]``, pairs of horizontal components (``kind = "pair"``), the
heading axis (``[options.rigid3d] heading = [...]``), and the fragility and risk of the
report on its rows, end to end (store, report, risk)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import rocking
from rocking import campaign
from rocking.campaign import Campaign, parse_spec
from rocking.campaign.report import report
from rocking.errors import SpecError
from rocking.motions import HorizontalPair
from rocking.shapes import Shape, example

SPEC = """
[campaign]
name = "r3d"
seed = 1
model = "rigid3d"
duration = {duration}

{blocks}

[motions]
kind = "pair"
set = ["rinaldi", "duzce"]
{levels}

[options.rigid3d]
step = 4e-3
heading = [0, 45]

[run]
chunk_size = 16
"""
BOX = "[[blocks]]\nbox = [0.2, 0.2, 1.0]\nmass = 100.0"
BLOCKS = f"""{BOX}
[[blocks]]
cylinder = [0.15, 1.0]
[[blocks]]
name = "statue"
mesh = "{example.example_mesh_path()}"
density = 2600
"""


def spec_text(blocks=BLOCKS, duration=4.0, levels="load_factors = [0.25, 1.0]", extra=""):
    return SPEC.format(blocks=blocks, duration=duration, levels=levels) + extra


def test_spec_takes_bodies_pairs_and_the_heading_axis():
    spec = parse_spec(spec_text())
    assert [type(b).__name__ for b in spec.blocks] == ["Shape"] * 3
    assert spec.blocks[0].mass == pytest.approx(100.0)
    assert spec.headings == (0.0, 45.0)
    assert spec.shape == (2, 3, 1, 2, 2, 1) and spec.n_sims == 24
    assert [o["heading"] for _, o in spec.runs] == [0.0, 45.0]
    table = Campaign(spec).table()
    assert table["heading"].tolist()[:2] == [0.0, 0.0]
    assert sorted(set(table["heading"])) == [0.0, 45.0]
    # a body's alpha is its weakest direction's: the box's is atan(b/h)
    box = table[table.block == 0]
    assert box["alpha"].iloc[0] == pytest.approx(math.atan(0.2 / 1.0), rel=1e-9)
    # a pair's PGA is its larger component's, times the load factor
    rin = HorizontalPair.builtin("rinaldi")
    first = table[(table.motion == 0) & (table.level == 1)]
    assert first["pga"].iloc[0] == pytest.approx(max(rin.pga_components), rel=1e-12)


def test_a_row_is_its_single_run():
    """Row ``i``: the body, the pair scaled to the level, at the row's heading."""
    spec = parse_spec(spec_text(blocks=BLOCKS, duration=3.0))
    c = Campaign(spec)
    ids = [int(np.ravel_multi_index((1, 2, 0, 0, 1, 0), spec.shape))]  # statue, 45 deg
    row = c.run_ids(ids).iloc[0]
    assert row["heading"] == 45.0 and row["block_name"] == "statue"
    r = rocking.simulate(spec.blocks[2], HorizontalPair.builtin("rinaldi"), model="rigid3d",
                         duration=3.0, step=4e-3, heading=45.0)
    assert row["max_tilt"] == r.max_tilt and row["max_abs_theta"] == r.max_tilt
    assert row["max_slide"] == r.max_slide and row["overturned"] == r.overturned


def test_end_to_end_store_fragility_and_risk(tmp_path):
    """A box under two pairs, four levels and two headings: the store, then the report's
    fragility and risk on its rows; overturning grows with the level."""
    hazard = '\n[hazard]\npga_475 = "0.3g"\nk = 3\nt_years = 50\n'
    text = spec_text(blocks=BOX, duration=6.0,
                     levels="load_factors = [0.25, 0.5, 1.0, 2.0]", extra=hazard)
    path = tmp_path / "spec.toml"
    path.write_text(text)
    campaign.run(path, tmp_path / "store", progress=False, log=lambda *a: None)
    rows = campaign.load(tmp_path / "store")
    assert len(rows) == 16 and set(rows["heading"]) == {0.0, 45.0}
    assert (rows["status"] == 0).all()
    ov = rows.groupby("level")["overturned"].mean().to_numpy()
    assert ov[0] == 0.0 and ov[-1] > 0.0 and np.all(np.diff(ov) >= 0)
    ok = rows["damage_state"].between(0, 3).all()
    assert ok
    manifest = campaign.Store(tmp_path / "store").manifest
    assert manifest["headings"] == [0.0, 45.0]
    res = report(rows, manifest, tmp_path / "report", n_boot=50)
    fit = res["fragility"]
    over = fit[fit["fit"] == "overturning"].iloc[0]
    assert np.isfinite(over["median"]) and over["median"] > 0
    risk = res["risk"]
    assert np.isfinite(risk[risk["fit"] == "overturning"]["annual_frequency"]).all()
    md = (tmp_path / "report" / "report.md").read_text()
    assert "pool the 2 headings" in md and "bootstrap by record" in md  # said, not hidden
    assert fit[fit["fit"] == "overturning"].shape[0] == 1
    # a fit (or the bounds of the median) per heading, the worst one, and all headings
    hd = res["headings"]
    assert (tmp_path / "report" / "headings.csv").exists()
    each = hd[hd["heading_deg"].notna()]
    assert sorted(each["heading_deg"]) == [0.0, 45.0] and each["worst"].any()
    est = each["median"].fillna(each["median_upper_bound"])  # the worst: the least median
    assert (est[each["worst"]] == est.min()).all()
    every = hd[hd["heading_deg"].isna()].iloc[0]
    assert every["n"] == 16 and every["median"] == over["median"]
    assert hd.loc[hd["heading_deg"].notna(), "n"].tolist() == [8, 8]
    assert "### By heading" in md and "(worst)" in md
    assert any(p.name.startswith("headings_rigid3d") for p in res["files"])


@pytest.mark.parametrize("extra, blocks, key", [
    ("", "[[blocks]]\nspecimen = 2\n[[blocks]]\nalpha = 0.2\np = 2.0\nmu = 0.9", "blocks[1]"),
    ("", "[[blocks]]\nbox = [0.2, -1, 1]", "blocks[0]"),
    ('\n[uncertain]\nalpha = {dist = "normal", cov = 0.02}\n', BOX, "uncertain"),
])
def test_bad_3d_specs_are_refused(extra, blocks, key):
    with pytest.raises(SpecError, match=key.replace("[", r"\[").replace("]", r"\]")):
        parse_spec(spec_text(blocks=blocks, extra=extra))


def test_pair_needs_a_3d_model_and_3d_runs_alone():
    text = spec_text(blocks="[[blocks]]\nspecimen = 2").replace('"rigid3d"', '"housner"')
    text = text.replace("[options.rigid3d]\nstep = 4e-3\nheading = [0, 45]\n", "")
    with pytest.raises(SpecError, match="motions.kind"):
        parse_spec(text)
    with pytest.raises(SpecError, match="campaign.model"):
        parse_spec(spec_text(blocks=BOX).replace('model = "rigid3d"',
                                                 'model = ["rigid3d", "housner"]'))
    with pytest.raises(SpecError, match="not usable with model 'housner'"):
        parse_spec(text.replace('kind = "pair"\nset = ["rinaldi", "duzce"]',
                                'kind = "builtin"\nname = "Rinaldi228"').replace(
            "specimen = 2", "box = [0.2, 0.2, 1.0]"))


def test_single_component_motions_act_along_direction():
    text = spec_text(blocks=BOX, duration=3.0).replace(
        'kind = "pair"\nset = ["rinaldi", "duzce"]', 'kind = "builtin"\nname = "Rinaldi228"')
    text = text.replace("heading = [0, 45]", "direction = 30")
    spec = parse_spec(text)
    rows = Campaign(spec).run_ids([1])
    r = rocking.simulate(Shape.box(0.2, 0.2, 1.0, mass=100.0), rocking.motions.load_builtin(
        "Rinaldi228"), model="rigid3d", duration=3.0, step=4e-3, direction=30.0)
    assert rows["max_tilt"].iloc[0] == r.max_tilt


def test_orientation_options_the_runs_would_ignore_are_refused():
    single = spec_text(blocks=BOX).replace('kind = "pair"\nset = ["rinaldi", "duzce"]',
                                           'kind = "builtin"\nname = "Rinaldi228"')
    with pytest.raises(SpecError, match=r"options\.rigid3d\.heading"):
        parse_spec(single)
    with pytest.raises(SpecError, match=r"options\.rigid3d\.direction"):
        parse_spec(spec_text(blocks=BOX).replace("heading = [0, 45]", "direction = 30"))
    parse_spec(spec_text(blocks=BOX).replace("heading = [0, 45]",
                                             "direction = 30\ntilt0 = 0.01"))


def test_pair_from_files(tmp_path):
    """``file``, ``second_file``, ``vertical_file``: one pair read (and hashed) by the
    spec, its azimuths from the NGA headers."""
    from rocking.campaign.plan import MotionSet

    rec = Path(rocking.__file__).parent / "motions" / "data" / "records" / "three_component"
    text = spec_text(blocks=BOX).replace(
        'set = ["rinaldi", "duzce"]',
        f'file = "{rec / "Rinaldi228.AT2"}"\nsecond_file = "{rec / "Rinaldi318.AT2"}"\n'
        f'vertical_file = "{rec / "RinaldiUP.AT2"}"')
    spec = parse_spec(text)
    assert spec.n_motions == 1 and len(spec.motion_axis.digests[0].split("+")) == 3
    pair = MotionSet(spec.motion_axis, 1).get(0)
    ref = HorizontalPair.builtin("rinaldi")
    assert pair.azimuths_deg == pytest.approx(ref.azimuths_deg)
    np.testing.assert_array_equal(pair.a1, ref.a1)
    np.testing.assert_array_equal(pair.vertical.values, ref.vertical.values)
