"""Fragility by heading of a 3-D campaign's rows (issue 30): a fit per heading, the worst
heading, and the pooled fit's interval by a bootstrap that resamples records
(:func:`rocking.analysis.heading_fragility`, :func:`rocking.analysis.fragility` with
``bootstrap="cluster"``).

The rows are synthetic with a known truth: each record ``r`` has a capacity
``m(h) exp(beta z_r)`` at heading ``h`` and overturns at every IM level at or above it.
With ``z_r`` shared by the headings (the same shaking, turned) the runs of a record are
perfectly correlated, and the bootstrap by record must widen the pooled interval by about
``sqrt(number of headings)`` over a bootstrap of runs; with independent ``z`` per heading
it must not.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from rocking.analysis import fragility, fragility_ida, heading_fragility
from rocking.errors import ParameterError

HEADINGS = (0.0, 45.0, 90.0, 135.0)
LEVELS = np.geomspace(0.8, 6.0, 10)
BETA = 0.35


def truth(h_deg):
    """The median (m/s^2) at heading ``h_deg``: smallest at 90 deg, largest at 0."""
    return 2.0 * math.exp(0.3 * math.cos(2.0 * math.radians(h_deg)))


def rows(n_records, *, shared=True, flat=False, seed=3):
    """One row per (record, heading, level); ``shared``: one z per record for every
    heading (perfect correlation), else one per (record, heading); ``flat``: the same
    median at every heading."""
    rng = np.random.default_rng(seed)
    z = rng.standard_normal((n_records, 1 if shared else len(HEADINGS)))
    out = []
    for r in range(n_records):
        for j, h in enumerate(HEADINGS):
            cap = (2.0 if flat else truth(h)) * math.exp(BETA * z[r, 0 if shared else j])
            out += [(r, h, lv, bool(lv >= cap)) for lv in LEVELS]
    return pd.DataFrame(out, columns=["motion", "heading", "im", "overturned"])


def width(ci):
    return ci[1] - ci[0]


def test_each_heading_recovers_its_median_and_beta_and_the_worst():
    """300 records: each heading's fit is within 10 % (about 5 standard errors) of its
    median and 20 % of beta; the worst heading is 90 deg, where the truth is smallest;
    each heading's by-record interval holds its true median. The pooled median's interval
    by record is wider than that of a bootstrap of runs (the records' runs are perfectly
    correlated here)."""
    hf = heading_fragility(rows(300), n_boot=100, im_unit="m/s^2")
    t = hf.table.set_index("heading_deg")
    assert list(t.index) == list(HEADINGS) and (t["n_records"] == 300).all()
    for h in HEADINGS:
        assert t.loc[h, "median"] == pytest.approx(truth(h), rel=0.10), h
        assert t.loc[h, "beta"] == pytest.approx(BETA, rel=0.20), h
        assert t.loc[h, "median_ci_lower"] < truth(h) < t.loc[h, "median_ci_upper"], h
    assert hf.worst_heading == 90.0 and t["worst"].sum() == 1
    assert set(hf.fits) == set(HEADINGS)
    # the medians follow the truth's shape: largest at 0, smallest at 90
    assert t["median"].idxmax() == 0.0 and t["median"].idxmin() == 90.0
    assert width(hf.ci["median"]) > 1.5 * width(hf.naive_ci)


def test_bootstrap_by_record_widens_the_interval_of_correlated_runs():
    """The same capacity at every heading (perfect correlation of a record's runs): the
    pooled median's interval by record is about sqrt(4) = 2 times that of a bootstrap
    that (wrongly) takes each (record, heading) as independent (measured 2.06-2.24 over
    seeds). With independent capacities per heading, clustering by record changes nothing
    (the ratio near 1: measured 0.95-0.99)."""
    kw = {"n_boot": 150, "seed": 1}
    corr = rows(120, flat=True)
    x, y = corr["im"].to_numpy(), corr["overturned"].to_numpy()
    pair_label = corr["motion"] * 1000 + corr["heading"].astype(int)
    by_pair = fragility(x, y, bootstrap="cluster", clusters=pair_label, **kw)
    by_rec = fragility(x, y, bootstrap="cluster", clusters=corr["motion"], **kw)
    assert by_rec.median == by_pair.median == fragility(x, y, n_boot=0).median
    ratio = width(by_rec.ci()["median"]) / width(by_pair.ci()["median"])
    assert 1.5 < ratio < 2.7
    ind = rows(120, flat=True, shared=False)
    x, y = ind["im"].to_numpy(), ind["overturned"].to_numpy()
    pair_label = ind["motion"] * 1000 + ind["heading"].astype(int)
    r_ind = (width(fragility(x, y, bootstrap="cluster", clusters=ind["motion"], **kw)
                   .ci()["median"])
             / width(fragility(x, y, bootstrap="cluster", clusters=pair_label, **kw)
                     .ci()["median"]))
    assert 0.75 < r_ind < 1.33


def test_a_heading_without_a_fit_gets_bounds_and_can_be_the_worst():
    """A heading at which every run from level 3 overturns and none below (separated): no
    fit, the bounds of its median; its upper bound below the other headings' medians
    makes it the worst."""
    d = rows(60)
    d = d[d["heading"] != 45.0]
    sep = [(r, 45.0, lv, bool(lv >= 1.2)) for r in range(60) for lv in LEVELS]
    d = pd.concat([d, pd.DataFrame(sep, columns=d.columns)], ignore_index=True)
    hf = heading_fragility(d, n_boot=20)
    row = hf.table.set_index("heading_deg").loc[45.0]
    assert math.isnan(row["median"]) and "separated" in row["note"]
    assert row["median_lower_bound"] < 1.2 < row["median_upper_bound"]
    assert hf.worst_heading == 45.0


def test_bad_input_names_the_parameter():
    x = np.repeat([1.0, 2.0, 4.0], 4)
    y = np.tile([True, False, False, True], 3)
    with pytest.raises(ParameterError, match="clusters"):
        fragility(x, y, bootstrap="cluster", n_boot=5)
    with pytest.raises(ParameterError, match="clusters"):
        fragility(x, y, bootstrap="cluster", clusters=[0, 1], n_boot=5)
    with pytest.raises(ParameterError, match="clusters"):
        fragility(x, y, bootstrap="cluster", clusters=np.zeros(12), n_boot=5)
    with pytest.raises(ParameterError, match="clusters"):
        fragility(x, y, clusters=np.arange(12), n_boot=5)  # without bootstrap='cluster'
    with pytest.raises(ParameterError, match="bootstrap"):
        fragility_ida([1.0, 2.0, 3.0], bootstrap="cluster", n_boot=5)
    d = rows(5)
    with pytest.raises(ParameterError, match="heading"):
        heading_fragility(d.drop(columns="heading"))
    with pytest.raises(ParameterError, match="record"):
        heading_fragility(d.assign(motion=0))
