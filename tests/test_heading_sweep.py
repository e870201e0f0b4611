"""The heading sweep of a 3-D body (``rocking.analysis.heading_sweep``, issue 30): the
rigid body under a pair at every heading in one batch; a box square in plan repeats
itself every 90 deg; each row is the run at that heading; the planar sweep refuses
``model="rigid3d"`` and names it."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rocking
from rocking.analysis import HeadingSweep, direction_sweep, heading_sweep
from rocking.motions import HorizontalPair, Record
from rocking.shapes import Shape

OUTPUTS = ("max_tilt", "max_slide", "max_twist")


@pytest.fixture(scope="module")
def pair():
    """Rinaldi (clockwise NGA pair, with its vertical), 1.5 to 4.5 s, at half scale."""
    rin = HorizontalPair.builtin("rinaldi")
    w = slice(150, 450)
    return HorizontalPair(Record(rin.a1[w], rin.dt), Record(rin.a2[w], rin.dt),
                          azimuths=rin.azimuths, vertical=Record(rin.vertical.values[w],
                                                                 rin.dt),
                          name="rinaldi 1.5-4.5 s").scaled(0.5)


@pytest.fixture(scope="module")
def square_sweep(pair):
    box = Shape.box(0.3, 0.3, 1.2, density=2000.0)
    return heading_sweep(box, pair, np.radians(np.arange(0.0, 360.0, 30.0)), duration=3.0,
                         step=1e-3)


def test_a_box_square_in_plan_repeats_every_90_degrees(square_sweep):
    """Turning a square box by 90 deg maps it onto itself: headings h, h + 90, h + 180,
    h + 270 give the same response (to the contact solver's tolerance), while headings
    30 deg apart differ."""
    t = square_sweep.table
    assert isinstance(square_sweep, HeadingSweep) and len(t) == 12
    assert t["max_tilt"].min() > 0.05  # it rocks at every heading
    for name in OUTPUTS:
        v = t[name].to_numpy().reshape(4, 3)  # rows: h + 90 k, columns: h = 0, 30, 60
        spread = np.ptp(v, axis=0)
        scale = np.abs(v).max(axis=0)
        assert np.all(spread <= 1e-3 * scale + 1e-7), (name, v)
    first = t["max_tilt"].to_numpy()[:3]
    assert np.ptp(first) > 0.1 * first.max()  # the heading matters within 90 deg
    assert t["overturned"].to_numpy().reshape(4, 3).std(axis=0).max() == 0.0


def test_rows_are_the_runs_at_their_heading(pair):
    """Row h is ``simulate(..., heading=h)`` (the pair turned by -h, heading 0): for a box
    that is not square, at +30 and -30 deg (which differ)."""
    box = Shape.box(0.3, 0.5, 1.2, density=2000.0)
    sw = heading_sweep(box, pair, np.radians([30.0, -30.0]), duration=3.0, step=1e-3)
    for i, h in enumerate((30.0, -30.0)):
        r = rocking.simulate(box, pair, model="rigid3d", heading=h, duration=3.0, step=1e-3)
        for name in OUTPUTS:
            assert sw.table[name].iloc[i] == pytest.approx(getattr(r, name), rel=1e-6,
                                                           abs=1e-9), (h, name)
    assert abs(sw.table["max_tilt"].iloc[0] - sw.table["max_tilt"].iloc[1]) > 1e-3


def test_worst_heading_and_plot(square_sweep):
    sw = square_sweep
    t = sw.table
    assert sw.worst["max_tilt"] == t["max_tilt"].max() or sw.worst["overturned"]
    assert t["worst"].sum() == 1 and sw.worst_heading == float(sw.worst["heading"])
    assert sw.alpha == pytest.approx(math.atan(0.3 / 1.2), rel=1e-9)
    np.testing.assert_allclose(t["max_tilt_over_alpha"], t["max_tilt"] / sw.alpha)
    fig = sw.plot()
    ax = fig.axes[0]
    assert ax.name == "polar" and "heading" in ax.get_title()
    assert any("worst" in text.get_text() for text in ax.get_legend().get_texts())


def test_planar_sweep_refuses_rigid3d_and_names_heading_sweep(pair):
    with pytest.raises(rocking.ParameterError, match="heading_sweep"):
        direction_sweep(Shape.box(0.3, 0.3, 1.2, density=2000.0), pair, 4, model="rigid3d")
    with pytest.raises(rocking.ParameterError, match="heading"):
        heading_sweep(Shape.box(0.3, 0.3, 1.2, density=2000.0), pair, 4, heading=10.0)
    with pytest.raises(rocking.ParameterError, match="pair"):
        heading_sweep(Shape.box(0.3, 0.3, 1.2, density=2000.0), pair.first, 4)
