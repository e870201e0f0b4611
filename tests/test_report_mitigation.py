"""The report section "what would make it safe" (issue 19): its files and rows, and the
physics its tables must obey whatever the numbers (uplift thresholds of the free and the
anchored block, the isolated system's linearity and its agreement with the elastic
response spectrum, the notes where no fragility fit exists, the annual frequency of a
power-law hazard, the quasi-static limit of the overturning spectrum)."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from conftest import report_section

from rocking.motions import response_spectrum
from rocking.report.sections import mitigation as M
from rocking.report.sections.fragility import HAZARD_A0, HAZARD_K, HAZARD_K0
from rocking.units import G

CSVS = ("runs", "comparison", "comparison_with_clearance", "displacement_per_g",
        "clearance_pga", "pulses")
PNGS = ("fragility", "displacement", "pulses")
BLOCKS = ["specimen 2", "specimen 3", "specimen 4", "statue"]


@pytest.fixture(scope="module")
def section_out(request):
    """The section in quick mode (conftest.report_section: the session's quick report
    when it builds one, else the section alone)."""
    out, index, _ = report_section(request, "mitigation")
    return out, index


@pytest.fixture(scope="module")
def blocks():
    return M.make_blocks()


def _csv(out, name):
    return pd.read_csv(out / f"mitigation_{name}.csv", keep_default_na=False,
                       na_values=["", "nan", "NaN"])


def test_page_and_files(section_out):
    out, index = section_out
    text = index.read_text(encoding="utf-8")
    assert 'id="mitigation"' in text and 'class="error"' not in text
    assert "what would make it safe" in text
    for word in ("ILLUSTRATIVE", "not the assessment of any", "Vassiliou and Makris",
                 "clearance", "Limits"):
        assert word in text, word
    for name in PNGS:
        p = out / f"mitigation_{name}.png"
        assert p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name
        assert f'src="mitigation_{name}.png"' in text
    for name in CSVS:
        assert f'href="mitigation_{name}.csv"' in text, name
    assert sorted(p.name for p in out.glob("mitigation_*")) == sorted(
        [f"mitigation_{n}.png" for n in PNGS] + [f"mitigation_{n}.csv" for n in CSVS])


@pytest.mark.parametrize("name", ["comparison", "comparison_with_clearance"])
def test_one_row_per_mitigation_block_and_floor(section_out, name):
    df = _csv(section_out[0], name)
    keys = set(zip(df.mitigation, df.block, df.floor, strict=True))
    assert len(df) == len(keys) == len(M.MITIGATIONS) * len(BLOCKS) * len(M.FLOORS)
    assert keys == {(m, b, f) for m in M.MITIGATIONS for b in BLOCKS for f in M.FLOORS}
    assert set(df.model) == {model for model, _ in M.MITIGATIONS.values()}


def test_every_configuration_runs_the_same_motions(section_out):
    runs = _csv(section_out[0], "runs")
    nrec, nlev = M.N_RECORDS[0], M.N_LEVELS[0]
    ref = None
    for _, d in runs.groupby(["mitigation", "block", "floor"]):
        pairs = sorted(zip(d.record, d.pga, strict=True))
        assert len(pairs) == nrec * nlev == len({p for _, p in pairs})  # distinct PGAs
        ref = pairs if ref is None else ref
        assert pairs == ref
    pga = np.sort(runs.pga.unique())
    assert pga[0] == pytest.approx(M.PGA_RANGE[0]) and pga[-1] == pytest.approx(M.PGA_RANGE[1])
    # the ground motion is the record scaled to the PGA: the floor's PGA is the ground's
    g = runs[runs.floor == "ground"]
    np.testing.assert_allclose(g.floor_pga_g, g.pga, rtol=1e-9)


def test_uplift_thresholds_free_and_anchored(section_out, blocks):
    """Closed forms: at rest the free block lifts off when the floor acceleration exceeds
    g tan(alpha), the anchored one when it exceeds (1 + 2q) g tan(alpha) (its anchor's
    ultimate moment added to gravity's; Makris and Zhang 2001)."""
    runs = _csv(section_out[0], "runs")
    tan = runs.block.map({k: math.tan(b.alpha) for k, b in blocks.items()})
    for mit, factor in (("none", 1.0), ("anchored", 1.0 + 2.0 * M.ANCHOR_STRENGTH)):
        d = runs.mitigation == mit
        ratio = runs.floor_pga_g / (factor * tan)
        below, above = d & (ratio < 0.99), d & (ratio > 1.01)
        assert below.any() and above.any(), mit  # both sides are tested
        assert not runs.uplifted[below].any(), mit
        assert (runs.max_theta_over_alpha[below] == 0.0).all(), mit
        assert runs.uplifted[above].all(), mit
    # hence, run by run: a run that leaves the free block at rest leaves the anchored one too
    key = ["block", "floor", "record", "pga"]
    free = runs[runs.mitigation == "none"].set_index(key)
    anch = runs[runs.mitigation == "anchored"].set_index(key).loc[free.index]
    assert not (anch.uplifted & ~free.uplifted).any()


def test_isolated_plate_is_a_linear_oscillator(section_out, blocks):
    """While the block stands, plate and block are one linear oscillator of period T_b and
    damping ratio zeta: max |u| and the plate's peak absolute acceleration are the
    relative-displacement and absolute-acceleration spectra of the floor motion at
    (T_b, zeta), computed independently by rocking.motions.response_spectrum; the block
    uplifts exactly when the plate's acceleration reaches g tan(alpha)."""
    out = section_out[0]
    runs = _csv(out, "runs")
    recs = M.records(True)
    iso = runs[runs.model == "isolated"]
    tan = iso.block.map({k: math.tan(b.alpha) for k, b in blocks.items()})
    still = ~iso.uplifted
    assert still.any() and (~still).any()
    assert (iso.max_plate_acceleration_g[still] <= tan[still] * (1 + 1e-3)).all()
    assert (iso.max_plate_acceleration_g[~still] >= tan[~still] * (1 - 1e-3)).all()
    checked = 0
    for mit, (_, opts) in M.MITIGATIONS.items():
        if not mit.startswith("isolated"):
            continue
        tb, zeta = opts["isolation_period"], opts["isolation_damping"]
        d = iso[(iso.mitigation == mit) & (iso.floor == "ground") & ~iso.uplifted]
        for r in d.itertuples():
            rec = recs[r.record - 1].scaled(r.pga * G / recs[r.record - 1].pga)
            sd = response_spectrum(rec, tb, damping=zeta, kind="sd")
            sa = response_spectrum(rec, tb, damping=zeta, kind="sa")
            assert r.max_base_displacement == pytest.approx(sd, rel=1e-2)
            assert r.max_plate_acceleration_g * G == pytest.approx(sa, rel=1e-2)
            checked += 1
        # a long isolation period filters the short-period records: the plate's peak
        # acceleration is well below the floor's
        if tb >= 3.0:
            e = iso[iso.mitigation == mit]
            assert (e.max_plate_acceleration_g < e.floor_pga_g).all()
    assert checked > 0
    # linear: max |u| = k PGA with k fixed by the record, whatever the block and the level
    disp = _csv(out, "displacement_per_g")
    assert (disp.relative_spread < 1e-6).all()


def test_no_invented_fragility(section_out):
    """A mitigation whose outcomes give no fit has a note and bounds, never a number."""
    for name in ("comparison", "comparison_with_clearance"):
        t = _csv(section_out[0], name)
        none = t[t.n_failed == 0]
        assert none["median"].isna().all() and none.beta.isna().all()
        assert (none.note.str.len() > 0).all()
        np.testing.assert_allclose(none.median_lower_bound, none.im_max, rtol=1e-5)
        unfitted = t[t["median"].isna()]
        assert len(unfitted) > 0  # few runs in quick mode: some outcomes are separated
        assert (unfitted.note.str.len() > 0).all()
        assert (unfitted.median_lower_bound.notna() | unfitted.median_upper_bound.notna()).all()
        fitted = t[t["median"].notna()]
        assert (fitted.beta > 0).all()


def test_annual_frequency_of_a_power_law_hazard(section_out):
    """Cornell et al. (2002): with lambda = k0 (im / a0)^-k and a lognormal fragility, the
    annual frequency is k0 (median / a0)^-k exp(k^2 beta^2 / 2); the section's hazard is
    that power law between 0.02 and 3 g, so fitted medians well inside it agree."""
    t = _csv(section_out[0], "comparison")
    free = t[t.mitigation == "none"]
    fitted = t[t["median"].between(0.1, 1.0) & (t.beta < 0.5)]
    assert len(fitted) > 0  # the staggered PGAs give fits even in quick mode
    for r in fitted.itertuples():
        exact = HAZARD_K0 * (r.median / HAZARD_A0) ** -HAZARD_K * math.exp(
            (HAZARD_K * r.beta) ** 2 / 2)
        assert r.annual_frequency == pytest.approx(exact, rel=1e-3)
    # without a fit, the bounds: the hazard's rate at the bounds of the median
    for r in t[t["median"].isna() & t.median_lower_bound.notna()].itertuples():
        assert r.annual_frequency_upper_bound == pytest.approx(
            HAZARD_K0 * (r.median_lower_bound / HAZARD_A0) ** -HAZARD_K, rel=1e-4)
    assert len(free) == len(BLOCKS) * len(M.FLOORS)


def test_pulse_study(section_out, blocks):
    """A free block cannot overturn without uplift (a_p > g tan alpha), and under a long
    pulse it overturns just above it (the quasi-static limit)."""
    pul = _csv(section_out[0], "pulses")
    assert set(pul.block) == set(M.PULSE_BLOCKS)
    assert set(pul.mitigation) == set(M.PULSE_MITIGATIONS)
    free = pul[pul.mitigation == "none"]
    assert (free.min_overturn_ratio > 1.0).all()
    longest = free[free.tp_s == free.tp_s.max()]
    assert (longest.min_overturn_ratio < 1.2).all()
    np.testing.assert_allclose(pul.min_overturn_pga_g, pul.min_overturn_ratio
                               * pul.block.map({k: math.tan(b.alpha)
                                                for k, b in blocks.items()}), rtol=1e-5)
    iso = pul[pul.mitigation != "none"]
    found = iso.min_overturn_ratio.notna()
    assert found.any()
    # the plate's displacement at the threshold is recorded exactly where one was found
    assert (iso.base_displacement_at_overturn_m.notna() == found).all()
    assert (iso.base_displacement_at_overturn_m[found] > 0).all()
    assert free.base_displacement_at_overturn_m.isna().all()
