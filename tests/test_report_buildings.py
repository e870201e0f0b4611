"""The report section "objects inside buildings": files, columns and the physics of its
tables (floor 0 is the ground, the roofs amplify, the codes' numbers, the cascade)."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from conftest import report_section

import rocking
from rocking.buildings import FloorMotion
from rocking.report.sections import buildings as B
from rocking.units import G

CSVS = {
    "modes": {"building", "storeys", "height_m", "mode", "period_s", "damping",
              "gamma_phi_roof", "effective_mass_fraction"},
    "pfa": {"building", "storeys", "floor", "z_over_H", "T1_s", "pfa_over_pga_median",
            "pfa_over_pga_p16", "pfa_over_pga_p84", "pfa_over_pga_min", "pfa_over_pga_max",
            f"pfa_over_pga_{B.RECORD}", "asce7_hf", "ec8_rigid", "n_records"},
    "p_overturn": {"building", "storeys", "floor", "z_over_H", "block", "pga_g", "n_records",
                   "n_overturned", "p_overturn", "ci_low", "ci_high", "p_uplift",
                   "median_max_theta_over_alpha", "n_not_settled"},
    "thresholds": {"building", "storeys", "floor", "z_over_H", "block", "pga_p50_g",
                   "pga_p50_bound", "pga_p50_bound_g", "max_pga_no_overturn_g"},
    "rinaldi": {"building", "storeys", "floor", "z_over_H", "block", "pga_g", "overturned",
                "max_theta_over_alpha", "uplifted", "settled"},
    "mass_ratio": {"block", "mass_kg", "building", "floor_mass_kg",
                   "smallest_effective_mass_kg", "at_floor", "mode", "mass_ratio", "limit"},
    "floor_spectra": {"period_s", "ground_psa_g", "roof_3_storey_psa_g", "ec8_roof_3_storey_g",
                      "asce7_pfa_roof_3_storey_g", "roof_8_storey_psa_g",
                      "ec8_roof_8_storey_g", "asce7_pfa_roof_8_storey_g"},
}
PNGS = ("pfa", "p_overturn", "theta", "floor_spectra")
BLOCKS = ["specimen 2", "specimen 3", "specimen 4", "statue"]


@pytest.fixture(scope="module")
def section_out(request):
    """The section in quick mode (conftest.report_section: the session's quick report
    when it builds one, else the section alone)."""
    out, index, _ = report_section(request, "buildings")
    return out, index


def _csv(out, name):
    return pd.read_csv(out / f"buildings_{name}.csv", keep_default_na=False,
                       na_values=["", "nan", "NaN"])


def test_page_and_files(section_out):
    out, index = section_out
    text = index.read_text(encoding="utf-8")
    assert 'id="buildings"' in text and 'class="error"' not in text
    assert "objects inside buildings" in text
    for word in ("Cascade assumption", "Limits", "linear elastic", "vertical building filter",
                 "ASCE 7-22", "EN 1998-1"):
        assert word in text, word
    for name in PNGS:
        p = out / f"buildings_{name}.png"
        assert p.is_file(), name
        assert p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert f'src="buildings_{name}.png"' in text
    for name in CSVS:
        assert f'href="buildings_{name}.csv"' in text, name
    assert sorted(p.name for p in out.glob("buildings_*")) == sorted(
        [f"buildings_{n}.png" for n in PNGS] + [f"buildings_{n}.csv" for n in CSVS])


@pytest.mark.parametrize("name", sorted(CSVS))
def test_csv_columns(section_out, name):
    out, _ = section_out
    df = _csv(out, name)
    assert set(df.columns) == CSVS[name]
    assert len(df) > 0


def test_every_block_floor_and_level(section_out):
    out, _ = section_out
    p = _csv(out, "p_overturn")
    levels = B.pga_levels(quick=True)
    assert sorted(p.block.unique()) == BLOCKS
    assert sorted(p.storeys.unique()) == list(B.STOREYS)
    for n in B.STOREYS:
        d = p[p.storeys == n]
        assert sorted(d.floor.unique()) == list(range(n + 1))  # the ground and every floor
        assert len(d) == (n + 1) * len(BLOCKS) * len(levels)
    np.testing.assert_allclose(sorted(p.pga_g.unique()), levels)
    assert (p.n_records == B.QUICK_RECORDS).all()
    assert ((p.ci_low <= p.p_overturn) & (p.p_overturn <= p.ci_high)).all()
    assert (p.p_overturn == p.n_overturned / p.n_records).all()
    # a block overturns only if it rocked
    assert (p.p_uplift >= p.p_overturn).all()


def test_floor_zero_is_the_ground(section_out):
    """P(overturn) and the median angle at floor 0 of each building equal a computation
    on the ground records themselves, without any building."""
    out, _ = section_out
    p = _csv(out, "p_overturn")
    recs = B.seed_records(quick=True)
    for label, blk in B.make_blocks().items():
        for lev in B.pga_levels(quick=True):
            r = rocking.simulate_many(blk, [rec.scaled(lev * G / rec.pga) for rec in recs],
                                      model="housner")
            theta = np.where(r.overturned, np.inf, r.max_abs_theta / blk.alpha)
            med = float(np.median(theta))
            rows = p[(p.block == label) & (p.floor == 0) & np.isclose(p.pga_g, lev)]
            assert len(rows) == len(B.STOREYS)
            for row in rows.itertuples():
                assert row.n_overturned == int(r.overturned.sum()), (label, lev)
                assert row.p_overturn == pytest.approx(float(r.overturned.mean()))
                if math.isinf(med):
                    assert math.isinf(row.median_max_theta_over_alpha)
                else:
                    assert row.median_max_theta_over_alpha == pytest.approx(med, rel=1e-5,
                                                                            abs=1e-12)


def test_peak_floor_acceleration_amplified_at_the_roof(section_out):
    out, _ = section_out
    pfa = _csv(out, "pfa")
    for n in B.STOREYS:
        d = pfa[pfa.storeys == n].set_index("floor")
        # the ground is the ground
        for col in ("pfa_over_pga_median", "pfa_over_pga_min", "pfa_over_pga_max",
                    f"pfa_over_pga_{B.RECORD}", "asce7_hf", "ec8_rigid"):
            assert d.loc[0, col] == pytest.approx(1.0), col
        roof = d.loc[n]
        # a low-rise/mid-rise building amplifies the peak acceleration at its roof
        assert roof.pfa_over_pga_min >= 1.0
        assert roof.pfa_over_pga_median > 1.2
        assert roof[f"pfa_over_pga_{B.RECORD}"] >= 1.0
        assert (roof.pfa_over_pga_min <= roof.pfa_over_pga_p16 <= roof.pfa_over_pga_median
                <= roof.pfa_over_pga_p84 <= roof.pfa_over_pga_max)
        # the codes' numbers by independent arithmetic
        T1 = 0.075 * (3.0 * n) ** 0.75  # EN 1998-1 Eq 4.6, storeys of 3 m
        assert d.T1_s.iloc[0] == pytest.approx(T1, rel=1e-5)
        z = d.z_over_H.to_numpy()
        np.testing.assert_allclose(z, np.arange(n + 1) / n, rtol=1e-5)
        hf = 1 + min(1 / T1, 2.5) * z + max(1 - (0.4 / T1) ** 2, 0.0) * z ** 10
        np.testing.assert_allclose(d.asce7_hf, hf, rtol=1e-5)
        np.testing.assert_allclose(d.ec8_rigid, 1 + 1.5 * z, rtol=1e-5)
    # the same ratio as FloorMotion gives for one record (linear: independent of the PGA)
    real = rocking.motions.load_builtin(B.RECORD)
    bld = B.make_buildings()[3]
    fm = FloorMotion(real.scaled(0.37), bld, floor=3)
    d = pfa[(pfa.storeys == 3) & (pfa.floor == 3)].iloc[0]
    assert d[f"pfa_over_pga_{B.RECORD}"] == pytest.approx(fm.pfa / (0.37 * real.pga),
                                                          rel=1e-5)


def test_upstairs_is_more_dangerous(section_out):
    """The slender specimens overturn more often at the roof than on the ground, summed
    over the levels (the roofs amplify the peak acceleration by more than 1.2)."""
    out, _ = section_out
    p = _csv(out, "p_overturn")
    for label in ("specimen 2", "specimen 3"):
        for n in B.STOREYS:
            d = p[(p.block == label) & (p.storeys == n)]
            assert d[d.floor == n].n_overturned.sum() > d[d.floor == 0].n_overturned.sum()
    thr = _csv(out, "thresholds")
    assert set(thr.pga_p50_bound.fillna("")) <= {"", "<", ">"}
    ok = thr[thr.pga_p50_bound.fillna("") == ""]
    levels = B.pga_levels(quick=True)
    assert ((ok.pga_p50_g > levels[0]) & (ok.pga_p50_g <= levels[-1])).all()


def test_rinaldi_runs(section_out):
    out, _ = section_out
    r = _csv(out, "rinaldi")
    n_loc = sum(n + 1 for n in B.STOREYS)
    assert len(r) == n_loc * len(BLOCKS) * len(B.pga_levels(quick=True))
    assert (r.uplifted | ~r.overturned).all()
    # floor 0 of both buildings: the same ground run
    g = r[r.floor == 0].pivot_table(index=["block", "pga_g"], columns="storeys",
                                    values="max_theta_over_alpha")
    np.testing.assert_array_equal(g[B.STOREYS[0]], g[B.STOREYS[1]])


def test_modes_and_cascade(section_out):
    out, _ = section_out
    m = _csv(out, "modes")
    for n in B.STOREYS:
        d = m[m.storeys == n]
        assert list(d["mode"]) == list(range(1, n + 1))  # every mode kept
        assert d.period_s.iloc[0] == pytest.approx(0.075 * (3.0 * n) ** 0.75, rel=1e-5)
        assert (np.diff(d.period_s) < 0).all()
        assert (d.damping == B.DAMPING).all()
        # all the modes of a discrete model: the effective masses add up to the total,
        # and sum_j Gamma_j phi_j = 1 at every floor (the roof here)
        assert d.effective_mass_fraction.sum() == pytest.approx(1.0, rel=1e-5)
        assert d.gamma_phi_roof.sum() == pytest.approx(1.0, rel=1e-5)
    mr = _csv(out, "mass_ratio")
    blocks = B.make_blocks()
    assert sorted(mr.block.unique()) == BLOCKS
    for row in mr.itertuples():
        assert row.mass_kg == pytest.approx(blocks[row.block].mass, rel=1e-5)
        assert row.mass_ratio == pytest.approx(row.mass_kg / row.smallest_effective_mass_kg,
                                               rel=1e-5)
        assert row.mass_ratio < row.limit == 0.01  # the FloorMotion docstring's limit
        assert row.smallest_effective_mass_kg >= row.floor_mass_kg  # at least one floor
    st = blocks["statue"]
    assert st.mass == pytest.approx(0.5 * 1.8 * 0.5 * 2700.0)
    assert st.alpha == pytest.approx(math.atan(0.25 / 0.9))


def test_floor_spectra(section_out):
    out, _ = section_out
    s = _csv(out, "floor_spectra")
    pfa = _csv(out, "pfa")
    real = rocking.motions.load_builtin(B.RECORD)
    T = s.period_s.to_numpy()
    for n in B.STOREYS:
        T1 = 0.075 * (3.0 * n) ** 0.75
        roof = s[f"roof_{n}_storey_psa_g"].to_numpy()
        # a stiff oscillator follows the floor: the spectrum at T -> 0 is the peak floor
        # acceleration (within the 2 % a 0.02 s, 5 %-damped oscillator still amplifies)
        ratio = pfa[(pfa.storeys == n) & (pfa.floor == n)][f"pfa_over_pga_{B.RECORD}"].iloc[0]
        assert roof[0] == pytest.approx(ratio * real.pga / G, rel=0.03)
        # resonance: the roof spectrum peaks near the building's first period
        assert T[np.argmax(roof)] == pytest.approx(T1, rel=0.1)
        assert roof.max() > 2.0 * s.ground_psa_g.max()
        # EN 1998-1 Eq 4.25 at the roof: 5.5 a_g S at Ta = T1, a_g S far above T1
        ec8 = s[f"ec8_roof_{n}_storey_g"].to_numpy()
        i1 = np.argmin(abs(T - T1))
        assert ec8.max() <= 5.5 * real.pga / G * (1 + 1e-6)
        assert ec8[i1] == pytest.approx(ec8.max(), rel=0.02)
        assert ec8[-1] == pytest.approx(real.pga / G, rel=1e-5)
        asce = s[f"asce7_pfa_roof_{n}_storey_g"]
        hf = pfa[(pfa.storeys == n) & (pfa.floor == n)].asce7_hf.iloc[0]
        np.testing.assert_allclose(asce, hf * real.pga / G, rtol=1e-5)


def test_helpers():
    lev = np.array([0.1, 0.2, 0.4])
    assert B.pga_at(lev, np.array([0.0, 0.5, 1.0])) == (pytest.approx(0.2), "")
    x, b = B.pga_at(lev, np.array([0.0, 0.25, 0.75]))
    assert b == "" and x == pytest.approx(math.exp(0.5 * (math.log(0.2) + math.log(0.4))))
    assert B.pga_at(lev, np.array([0.6, 0.8, 1.0]))[1] == "<"
    assert B.pga_at(lev, np.array([0.0, 0.1, 0.4]))[1] == ">"
    # the median counts the overturned runs as infinite
    th = np.array([0.1, 0.2, 0.3, 0.4])
    assert B.censored_median(th, np.array([False] * 4)) == pytest.approx(0.25)
    assert B.censored_median(th, np.array([False, False, True, True])) == math.inf
    assert B.censored_median(th, np.array([True, False, False, False])) == pytest.approx(0.35)
    assert B.building_period(8) == pytest.approx(0.075 * 24.0 ** 0.75)
