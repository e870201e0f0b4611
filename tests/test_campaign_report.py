"""The campaign report: counts, Wilson intervals and fragility fits checked against the
table they come from (simulated stripes and synthetic lognormal outcomes)."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from scipy.stats import norm

import rocking
from rocking.analysis import DEFAULT_THRESHOLDS, damage_state
from rocking.campaign.report import report, summary_lines
from rocking.errors import ParameterError
from rocking.motions import builtin_records, load_builtin
from rocking.units import G

LEVELS = np.geomspace(0.6, 12.0, 8)  # PGA levels, m/s^2
AMPLITUDES = (0.9, 1.0, 1.1)  # table-motion perturbations (samples)


def _manifest(im=True, **kw):
    m = {"name": "test campaign", "n_sims": 0, "thresholds": list(DEFAULT_THRESHOLDS),
         "models": ["housner"], "blocks": [], "im": {"name": "pga", "unit": "m/s^2"}
         if im else None, "version": "0", "spec_hash": "abc123"}
    m.update(kw)
    return m


def _columns(model, block, name, alpha, p, mu, motion, level, lf, sample, pga, th,
             overturned, im=None, amplitude=1.0):
    """The store's columns from arrays of one batch."""
    n = len(th)
    ratio = np.asarray(th, float) / alpha
    d = {"sim_id": np.arange(n), "model": model, "block": block, "block_name": name,
         "alpha": alpha, "p": p, "mu": mu, "motion": motion,
         "motion_id": [f"m{int(i)}" for i in np.broadcast_to(motion, (n,))],
         "level": level, "load_factor": lf, "sample": sample, "theta0": 0.0,
         "amplitude": amplitude, "noise": 0.0, "pga": pga, "max_abs_theta": th,
         "max_abs_theta_over_alpha": ratio, "overturned": np.asarray(overturned, bool),
         "overturn_time": np.where(overturned, 5.0, np.nan), "uplift_time": 1.0,
         "n_impacts": 3, "damage_state": damage_state(th, alpha, overturned),
         "status": 0}
    if im is not None:
        d["im"] = im
    return pd.DataFrame(d)


@pytest.fixture(scope="module")
def simulated():
    """Specimen 2 under the built-in records scaled to PGA stripes (x 3 amplitudes)."""
    b = rocking.specimen(2, "experimental")
    recs = [load_builtin(n) for n in builtin_records()]
    rows = [(r, lv, s, lvl * a / rec.pga, lvl, a) for r, rec in enumerate(recs)
            for lv, lvl in enumerate(LEVELS) for s, a in enumerate(AMPLITUDES)]
    motions = [recs[r].scaled(lf) for r, _, _, lf, _, _ in rows]
    res = rocking.simulate_many(b, motions, duration=15.0, errors="nan")
    r, lv, s, lf, lvl, a = (np.array(c) for c in zip(*rows, strict=True))
    t = _columns("housner", 0, "specimen 2", b.alpha, b.p, b.mu, r, lv, lf, s,
                 [m.pga for m in motions], res.max_abs_theta, res.overturned,
                 im=LEVELS[lv], amplitude=a)
    t["status"] = res.status
    return t


def _synthetic(theta, beta, seed, model="housner", block=0, n_per=150, levels=None):
    """Outcomes drawn from a known lognormal fragility P = Phi(ln(im/theta)/beta)."""
    rng = np.random.default_rng(seed)
    levels = np.geomspace(theta / 4, theta * 4, 10) if levels is None else levels
    lv = np.repeat(np.arange(levels.size), n_per)
    im = levels[lv]
    ov = rng.random(im.size) < norm.cdf(np.log(im / theta) / beta)
    alpha = 0.2
    th = np.where(ov, np.nan, alpha * np.minimum(0.95, 0.6 * (im / theta)
                                                 * np.exp(0.3 * rng.standard_normal(im.size))))
    return _columns(model, block, f"block {block}", alpha, 3.0, 0.7, lv % 5, lv, im / 2.0,
                    np.arange(im.size) % n_per, im, th, ov, im=im)


# --------------------------------------------------------------------------- tests

def test_p_overturn_is_the_count_of_the_table_with_its_wilson_interval(simulated, tmp_path):
    res = report(simulated, _manifest(), tmp_path)
    po = pd.read_csv(tmp_path / "p_overturn.csv")
    ok = simulated[simulated["status"] == 0]
    assert len(po) == LEVELS.size
    for r in po.itertuples():
        d = ok[ok["level"] == r.level]
        assert r.n == len(d) and r.n_overturned == int(d["overturned"].sum())
        assert r.p_overturn == pytest.approx(d["overturned"].mean(), abs=1e-6)
        assert r.ci_lower <= r.p_overturn <= r.ci_upper
        assert 0.0 <= r.ci_lower and r.ci_upper <= 1.0
        assert r.im == pytest.approx(LEVELS[r.level], rel=1e-5)  # stripes: one IM a level
        surv = d.loc[~d["overturned"], "max_abs_theta"] / d["alpha"].iloc[0]
        if len(surv):
            assert r.median_ratio_survivors == pytest.approx(surv.median(), rel=1e-5)
        # exceedance probabilities decrease with the state; the last one is overturning
        pe = [getattr(r, f"p_ds_ge_{k}") for k in range(1, len(DEFAULT_THRESHOLDS) + 2)]
        assert all(a >= b - 1e-12 for a, b in zip(pe, pe[1:], strict=False))
        assert pe[-1] == pytest.approx(r.p_overturn, abs=1e-6)
    assert res["p_overturn"]["n"].sum() == len(ok)


def test_fitted_median_lies_between_the_last_safe_and_the_first_certain_stripe(simulated,
                                                                               tmp_path):
    res = report(simulated, _manifest(), tmp_path)
    ok = simulated[simulated["status"] == 0]
    p = ok.groupby("im")["overturned"].mean()
    none, every = p.index[p == 0.0], p.index[p == 1.0]
    assert len(none) and len(every), "the stripes must span from safe to certain"
    fr = res["fragility"]
    ovt = fr[fr["fit"] == "overturning"].iloc[0]
    assert none.max() < ovt["median"] < every.min()
    assert ovt["beta"] > 0 and ovt["median_se"] > 0
    # uplift needs PGA > g tan(alpha): no stripe below it can overturn the block
    b = rocking.specimen(2, "experimental")
    assert ovt["median"] > G * math.tan(b.alpha)


def test_synthetic_lognormal_fragility_is_recovered(tmp_path):
    true = {0: (3.0, 0.4), 1: (6.0, 0.25)}
    t = pd.concat([_synthetic(*true[k], seed=k, block=k) for k in true], ignore_index=True)
    res = report(t, _manifest(), tmp_path)
    fr = res["fragility"]
    for k, (theta, beta) in true.items():
        f = fr[(fr["fit"] == "overturning") & (fr["block"] == k)].iloc[0]
        assert abs(f["median"] - theta) < 4 * f["median_se"]
        assert abs(f["beta"] - beta) < 4 * f["beta_se"]
        assert f["median_se"] < 0.1 * theta  # 1500 runs: a tight estimate
    # the pelicun table gives the damage-state medians in g (converted from m/s^2)
    pel = pd.read_csv(tmp_path / "pelicun.csv", index_col=0)
    assert len(pel) == 2 and (pel["Demand-Unit"] == "g").all()
    for k in true:
        ds = fr[(fr["fit"] == "damage_states") & (fr["block"] == k)].sort_values("state")
        row = pel.iloc[k]
        for s, m in zip(ds["state"], ds["median"], strict=True):
            assert row[f"LS{s}-Theta_0"] * G == pytest.approx(m, rel=1e-4)
        assert ds["median"].is_monotonic_increasing  # heavier damage needs a stronger IM


def test_a_group_that_never_overturns_gets_a_note_and_the_others_are_fitted(tmp_path):
    fit = _synthetic(3.0, 0.4, seed=1, model="housner")
    safe = _synthetic(1e6, 0.4, seed=2, model="ccrr",  # a median far beyond the levels
                      levels=np.geomspace(0.75, 12.0, 10))
    assert not safe["overturned"].any()
    res = report(pd.concat([fit, safe], ignore_index=True), _manifest(), tmp_path)
    fr = res["fragility"].set_index(["model", "fit"])
    assert math.isnan(fr.loc[("ccrr", "overturning"), "median"])
    assert fr.loc[("ccrr", "overturning"), "note"]
    assert math.isfinite(fr.loc[("housner", "overturning"), "median"])
    assert any("ccrr" in n for n in res["notes"])
    lines = summary_lines(res)
    assert any(line.startswith("ccrr") and "no overturning fit" in line for line in lines)
    for model in ("housner", "ccrr"):  # one figure per model, linked from the summary
        png = tmp_path / f"p_overturn_{model}.png"
        assert png.stat().st_size > 0 and png.name in (tmp_path / "report.md").read_text()


def test_failed_runs_are_excluded_and_counted(tmp_path):
    t = _synthetic(3.0, 0.4, seed=3)
    bad = np.random.default_rng(4).random(len(t)) < 0.1
    broken = t.copy()
    broken.loc[bad, "status"] = 1
    broken.loc[bad, ["max_abs_theta", "max_abs_theta_over_alpha"]] = np.nan
    broken.loc[bad, "overturned"] = True  # whatever a failed run reports must not count
    a = report(broken, _manifest(), tmp_path / "a")
    b = report(t[~bad].reset_index(drop=True), _manifest(), tmp_path / "b")
    assert a["n_excluded"] == int(bad.sum()) > 0
    assert f"{int(bad.sum())} failed" in (tmp_path / "a" / "report.md").read_text()
    cols = ["level", "n", "n_overturned", "p_overturn", "ci_lower", "ci_upper"]
    pd.testing.assert_frame_equal(a["p_overturn"][cols], b["p_overturn"][cols])
    assert a["p_overturn"]["n_excluded"].sum() == bad.sum()
    fa, fb = (r["fragility"].iloc[0] for r in (a, b))
    assert fa["median"] == pytest.approx(fb["median"], rel=1e-12)


def test_planar_runs_that_left_the_ground_are_neither_survivors_nor_overturns(tmp_path):
    """A planar model stops a run where g + a_v <= 0 (lifted_off), which it cannot
    represent: counting such runs as survivors would make the fragility unsafe. They are
    left out of every count and fit, as failed runs are, and the note says why."""
    t = _synthetic(3.0, 0.4, seed=6)
    t["lifted_off"] = False
    strong = t["im"] > 6.0  # the strong levels, where a vertical component exceeds g
    lift = strong & (np.random.default_rng(7).random(len(t)) < 0.5)
    t.loc[lift, "lifted_off"] = True
    t.loc[lift, "overturned"] = False  # the stopped run neither overturned nor survived
    t.loc[lift, "damage_state"] = 0
    a = report(t, _manifest(), tmp_path / "a")
    b = report(t[~lift].reset_index(drop=True), _manifest(), tmp_path / "b")
    cols = ["level", "n", "n_overturned", "p_overturn"]
    pd.testing.assert_frame_equal(a["p_overturn"][cols], b["p_overturn"][cols])
    fa, fb = (r["fragility"].iloc[0] for r in (a, b))
    assert fa["median"] == pytest.approx(fb["median"], rel=1e-12)
    assert f"{int(lift.sum())} of {len(t)} runs of a planar model left the ground" in (
        tmp_path / "a" / "report.md").read_text()


def test_without_im_scaling_the_im_is_the_pga_of_each_run(tmp_path):
    t = _synthetic(3.0, 0.4, seed=5).drop(columns="im")
    t["pga"] = t["pga"] * np.exp(0.05 * np.random.default_rng(6).standard_normal(len(t)))
    res = report(t, _manifest(im=False), tmp_path)
    assert res["im"]["column"] == "pga"
    for r in res["p_overturn"].itertuples():
        assert r.im == pytest.approx(t.loc[t["level"] == r.level, "pga"].median())


@pytest.mark.parametrize("column", ["overturned", "damage_state", "pga"])
def test_missing_column_is_named(column, tmp_path):
    t = _synthetic(3.0, 0.4, seed=0, n_per=5).drop(columns=column)
    with pytest.raises(ParameterError, match=column):
        report(t, _manifest(im=False), tmp_path)


def test_empty_table_and_missing_im_column_are_refused(tmp_path):
    t = _synthetic(3.0, 0.4, seed=0, n_per=5)
    with pytest.raises(ParameterError, match="empty"):
        report(t.iloc[:0], _manifest(), tmp_path)
    with pytest.raises(ParameterError, match="im"):
        report(t.drop(columns="im"), _manifest(im=True), tmp_path)
