"""The isolator's demand at the codes' return periods, the clearance counting, and the
verdict of every mitigation against "none" (issue 31, items 5 and 6).

Tables are drawn from planted laws: the base displacement ``d = a PGA^b e^(s Z)`` and
lognormal fragilities. Against a power-law hazard ``k0 PGA^-k`` the demand at return
period T is ``a PGA_T^b`` (median) and the annual frequency of reaching a clearance c is
Cornell's closed form of the lognormal fragility ``median (c / a)^(1/b)``, beta ``s / b``.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from scipy.stats import norm

from rocking import ParameterError
from rocking.analysis import HazardCurve, compare_mitigations
from rocking.analysis.mitigation import demand_columns

A, B, S = 0.02, 1.0, 0.4          # d = A pga^B e^(S Z), m with pga in m/s^2
K0, K = 0.02, 2.5                 # hazard lambda = K0 pga^-K, pga in m/s^2 (2.46 at 475 yr)


def curve():
    x = np.geomspace(0.05, 100.0, 40)
    return HazardCurve(x, K0 * x ** -K, im_name="PGA", unit="m/s^2", label="power law")


def runs(levels, *, n=300, seed=0, medians=None, moat=None, name="isolated"):
    """Rows of 'none' and an isolated mitigation on ``levels`` (m/s^2); the isolated
    block overturns on a lognormal of median ``medians[name]`` (beta 0.4), its base moves
    by the planted law; with ``moat`` (m) the model stops the runs that reach it."""
    medians = medians or {"none": 3.0, name: 9.0}
    rng = np.random.default_rng(seed)
    parts = []
    for mit, med in medians.items():
        pga = np.repeat(np.asarray(levels, float), n)
        ov = rng.random(pga.size) < norm.cdf(np.log(pga / med) / 0.4)
        t = pd.DataFrame({"mitigation": mit, "pga": pga, "overturned": ov, "status": 0})
        if mit != "none":
            d = A * pga ** B * np.exp(S * rng.standard_normal(pga.size))
            stop = (d >= moat) if moat else np.zeros(pga.size, bool)
            t["max_base_displacement"] = np.where(stop, moat or 0.0, d)
            t["clearance_exceeded"] = stop
            t.loc[stop, "overturned"] = False
        parts.append(t)
    return pd.concat(parts, ignore_index=True)


def test_no_moat_and_a_moat_are_told_apart_with_a_clearance():
    """With clearance="0.15m", an isolator without a moat and one with a 0.15 m moat used
    to come out identical: the clearance turned the no-moat runs that passed 0.15 m into
    failures (the same event as the moat's stops). "auto" now judges each by its own
    model: the moat by overturned-or-moat-reached, the free plate by overturning."""
    lv = np.geomspace(1.0, 16.0, 6)
    free = runs(lv, seed=4, name="no moat")
    moat = runs(lv, seed=4, name="0.15 m", moat=0.15)
    t = pd.concat([free, moat[moat["mitigation"] == "0.15 m"]], ignore_index=True)
    cmp = compare_mitigations(t, clearance="0.15m", n_boot=0)
    r = cmp.table.set_index("mitigation")
    nm, m = r.loc["no moat"], r.loc["0.15 m"]
    ov_free = free.loc[free["mitigation"] == "no moat", "overturned"].to_numpy()
    mm = moat[moat["mitigation"] == "0.15 m"]
    assert nm["failure"] == "overturned" and m["failure"] == "overturned_or_clearance"
    assert nm["n_failed"] == ov_free.sum()
    assert m["n_failed"] == (mm["overturned"] | mm["clearance_exceeded"]).sum()
    assert m["n_failed"] > nm["n_failed"]
    assert m["median"] < nm["median"]
    # the same demand: both reach 0.15 m in the same runs
    assert nm["p_clearance_exceeded"] == pytest.approx(m["p_clearance_exceeded"])
    # asked explicitly, the clearance fails the free plate's runs too (as documented)
    both = compare_mitigations(t, clearance="0.15m", failure="overturned_or_clearance",
                               n_boot=0).table.set_index("mitigation")
    assert both.loc["no moat", "n_failed"] == both.loc["0.15 m", "n_failed"]


def test_each_mitigation_its_own_clearance():
    """``clearance={mitigation: c}``: two moats of 0.1 m and 0.2 m, each counted against
    its own (the share of runs whose base reaches it, from the displacements), the
    column giving each row's, none for the unmitigated block; a name not in the table is
    refused."""
    lv = np.geomspace(1.0, 16.0, 6)
    a = runs(lv, seed=5, name="moat 0.1", moat=0.1)
    b = runs(lv, seed=5, name="moat 0.2", moat=0.2)
    t = pd.concat([a, b[b["mitigation"] == "moat 0.2"]], ignore_index=True)
    cmp = compare_mitigations(t, clearance={"moat 0.1": "10cm", "moat 0.2": 0.2}, n_boot=0)
    r = cmp.table.set_index("mitigation")
    assert r.loc["moat 0.1", "clearance"] == 0.1 and r.loc["moat 0.2", "clearance"] == 0.2
    assert math.isnan(r.loc["none", "clearance"])
    for name, c in (("moat 0.1", 0.1), ("moat 0.2", 0.2)):
        d = t.loc[t["mitigation"] == name, "max_base_displacement"].to_numpy()
        assert r.loc[name, "p_clearance_exceeded"] == pytest.approx((d >= c).mean())
    assert r.loc["moat 0.1", "p_clearance_exceeded"] > r.loc["moat 0.2", "p_clearance_exceeded"]
    assert cmp.clearance == {"moat 0.1": 0.1, "moat 0.2": 0.2}
    with pytest.raises(ParameterError, match=r"clearance: no mitigation named \['moat'\]"):
        compare_mitigations(t, clearance={"moat": 0.1}, n_boot=0)


@pytest.mark.parametrize("levels", [np.geomspace(0.5, 12.0, 8), np.geomspace(1.5, 24.0, 5),
                                    np.geomspace(3.0, 24.0, 5)])
def test_demand_at_the_return_periods_is_the_planted_law(levels):
    c = curve()
    cmp = compare_mitigations(runs(levels, seed=1), hazard=c, clearance=0.15, n_boot=0,
                              return_periods=[975])
    r = cmp.table.set_index("mitigation").loc["isolated"]
    assert cmp.return_periods == (475.0, 975.0, 2475.0)
    for T in (475, 975, 2475):
        c_im, c_med, c_p84, c_p = demand_columns(T)
        a = c.im_at_return_period(T)
        assert r[c_im] == pytest.approx(a)
        if not levels[0] <= a <= levels[-1]:
            assert math.isnan(r[c_med]) and f"no demand at {T:g} years" in r["note"]
            continue
        med = A * a ** B
        # the sample median of 300 runs per level: ~1.25 s / sqrt(300) = 3 % (log)
        assert r[c_med] == pytest.approx(med, rel=0.1)
        assert r[c_p84] == pytest.approx(med * math.exp(S), rel=0.12)
        assert r[c_p] == pytest.approx(norm.sf(math.log(0.15 / med) / S), abs=0.06)
    # the annual frequency of reaching 0.15 m: a lognormal of median (c / A)^(1/B), beta S/B
    m, beta = (0.15 / A) ** (1 / B), S / B
    cornell = K0 * m ** -K * math.exp(0.5 * (K * beta) ** 2)
    assert r["clearance_annual_frequency"] == pytest.approx(cornell, rel=0.25)
    assert r["clearance_probability"] == pytest.approx(
        1 - math.exp(-50 * r["clearance_annual_frequency"]))


def test_demand_does_not_depend_on_the_levels_chosen():
    """The old pooled median over all levels moved with the levels the user ran; the
    demand at 475 years does not."""
    c = curve()
    a, b = (runs(lv, seed=2) for lv in (np.geomspace(1.0, 6.0, 6), np.geomspace(1.5, 20, 6)))
    col = demand_columns(475)[1]
    da, db = (compare_mitigations(t, hazard=c, n_boot=0).table.set_index(
        "mitigation").loc["isolated", col] for t in (a, b))
    assert da == pytest.approx(db, rel=0.1)
    pooled = [np.nanmedian(t["max_base_displacement"]) for t in (a, b)]
    assert pooled[1] / pooled[0] > 1.5  # what the old figure did


def test_a_mitigation_that_makes_it_worse_is_flagged_with_its_reason():
    lv = np.geomspace(1.0, 16.0, 6)
    t = runs(lv, seed=5, medians={"none": 12.0, "isolated": 20.0}, moat=0.15)
    t["floor"] = 3
    cmp = compare_mitigations(t, hazard=curve(), n_boot=0, building_period=2.2,
                              isolation_periods={"isolated": "2.5s"})
    r = cmp.table.set_index("mitigation")
    iso = r.loc["isolated"]
    assert r.loc["none", "verdict"] == "reference" and r.loc["none", "reason"] == ""
    assert iso["annual_frequency_ratio"] == pytest.approx(
        iso["annual_frequency"] / r.loc["none", "annual_frequency"])
    assert iso["annual_frequency_ratio"] > 1 and iso["verdict"] == "worse"
    assert "stopped at the clearance (0.15 m)" in iso["reason"]
    assert "near the building's 2.2 s" in iso["reason"]
    # the same isolator with room enough and far from the building's period: better
    t2 = runs(lv, seed=5, medians={"none": 3.0, "isolated": 20.0})
    r2 = compare_mitigations(t2, hazard=curve(), n_boot=0).table.set_index("mitigation")
    assert r2.loc["isolated", "verdict"] == "better" and r2.loc["isolated", "reason"] == ""
    # without a hazard: the medians decide
    r3 = compare_mitigations(t, n_boot=0).table.set_index("mitigation")
    assert r3.loc["isolated", "verdict"] == ("worse" if r3.loc["isolated", "median_ratio"] < 1
                                             else "better")


def test_campaign_report_compares_the_mitigations(tmp_path):
    """The campaign report states every mitigation's ratio to none, flags the worse one
    with its reason, and gives the isolator's demand at 475 and 2475 years."""
    from test_campaign_hazard import manifest, synthetic

    from rocking.campaign.hazard import record
    from rocking.campaign.report import report, summary_lines

    t = synthetic([("none", "housner", 0, 6.0, 0.4), ("isolated", "isolated", 0, 3.0, 0.4)],
                  n_per=20)
    iso = (t["mitigation"] == "isolated").to_numpy()
    rng = np.random.default_rng(0)
    d = A * t["pga"].to_numpy() * np.exp(S * rng.standard_normal(len(t)))
    stop = iso & (d >= 0.15) & ~t["overturned"].to_numpy()
    t["max_base_displacement"] = np.where(iso, np.minimum(d, 0.15), np.nan)
    t["clearance_exceeded"] = stop
    man = manifest(record(curve(), {}, 50.0))
    man["mitigations"] = [{"name": "none", "model": "housner", "options": {}},
                          {"name": "isolated", "model": "isolated",
                           "options": {"isolation_period": 2.5, "clearance": 0.15}}]
    res = report(t, man, tmp_path / "r", n_boot=0)
    cmp = pd.read_csv(tmp_path / "r" / "mitigation.csv")
    r = cmp.set_index("mitigation")
    assert r.loc["none", "verdict"] == "reference"
    assert r.loc["isolated", "verdict"] == "worse"
    assert r.loc["isolated", "annual_frequency_ratio"] == pytest.approx(
        r.loc["isolated", "annual_frequency"] / r.loc["none", "annual_frequency"], rel=1e-5)
    assert np.isfinite(r.loc["isolated", "displacement_median_475yr"])
    # the isolator's clearance option, from the manifest (the 'none' block has none)
    assert r.loc["isolated", "clearance"] == 0.15 and np.isnan(r.loc["none", "clearance"])
    md = (tmp_path / "r" / "report.md").read_text()
    assert "## Mitigations compared with none" in md and "| WORSE |" in md
    assert "### The isolator's displacement demand" in md
    line = next(x for x in summary_lines(res)
                if x.startswith("isolated / ") and "than none" in x)
    assert "WORSE than none" in line and "× the annual frequency of none" in line


# --------------------------------------------------------------------------- plots

def _curves(ax):
    return [ln for ln in ax.get_lines() if len(ln.get_xdata()) > 20]


def test_comparison_plot_tells_the_curves_apart_and_keeps_the_legend_off_the_data():
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    lv = np.geomspace(1.0, 16.0, 6)
    t = runs(lv, seed=5, medians={"none": 12.0, "isolated": 20.0}, moat=0.15)
    t2 = runs(lv, seed=6, medians={"none": 12.0, "anchored": 16.0})
    t = pd.concat([t, t2[t2["mitigation"] == "anchored"]], ignore_index=True)
    fig = compare_mitigations(t, hazard=curve(), n_boot=0).plot()
    FigureCanvasAgg(fig).draw()
    ax = fig.axes[0]
    lines = _curves(ax)
    assert len(lines) == 3
    looks = {(ln.get_color(), str(ln.get_linestyle())) for ln in lines}
    assert len({c for c, _ in looks}) == 3 and len({s for _, s in looks}) == 3
    assert ax.get_xlabel() and ax.get_ylabel() == "P(failure)" and fig.get_suptitle()
    legend = ax.get_legend()
    texts = [x.get_text() for x in legend.get_texts()]
    assert any("WORSE than none" in x and "× the annual frequency of none" in x for x in texts)
    assert not legend.get_window_extent().overlaps(ax.get_window_extent())


def test_campaign_plot_shows_every_floor_and_names_the_combined_failure(tmp_path,
                                                                         monkeypatch):
    """Two floors of an isolated block that never overturns: their points at P = 0 used
    to lie on one another (the floor-0 points hidden), and the combined failure was
    drawn under a "P(overturn)" label."""
    from test_campaign_hazard import manifest, synthetic

    import rocking.campaign.report as rep

    t = synthetic([("isolated", "isolated", 0, None, 0)], n_per=12)
    t = pd.concat([t.assign(floor=0), t.assign(floor=3)], ignore_index=True)
    t["sim_id"] = np.arange(len(t))
    d = A * t["pga"].to_numpy()
    t["max_base_displacement"] = np.minimum(d, 0.15)
    t["clearance_exceeded"] = d >= 0.15
    figs = []
    monkeypatch.setattr(rep, "save_figure", lambda fig, path, dpi=None: figs.append(fig)
                        or path)
    rep.report(t, manifest(), tmp_path / "r", n_boot=0)
    ax = figs[0].axes[0]
    assert "clearance" in ax.get_ylabel() and "clearance" in ax.get_title()
    pts = [ln for ln in ax.get_lines() if ln.get_linestyle() in ("None", "")
           and ln.get_marker() not in ("_", "|")]  # the points, not the error bars' caps
    at_zero = {}
    for ln in pts:
        x, y = np.asarray(ln.get_xdata(), float), np.asarray(ln.get_ydata(), float)
        for xi in x[y == 0]:
            at_zero.setdefault((ln.get_color(), ln.get_marker()), []).append(xi)
    assert len({c for c, _ in at_zero}) == 2 and len({m for _, m in at_zero}) == 2
    xs = sorted({round(v, 9) for v in np.concatenate([np.asarray(v) for v in
                                                         at_zero.values()])})
    per = len(np.unique(t["pga"]))
    assert len(xs) > per  # not drawn on one another


def test_anchors_that_break_are_the_reason_seen():
    lv = np.geomspace(1.0, 16.0, 6)
    t = runs(lv, seed=7, medians={"none": 8.0, "anchored": 5.0})
    anc = (t["mitigation"] == "anchored").to_numpy()
    t["anchor_broken_plus"] = anc & t["overturned"].to_numpy()
    t["anchor_broken_minus"] = False
    r = compare_mitigations(t, hazard=curve(), n_boot=0).table.set_index("mitigation")
    assert r.loc["anchored", "verdict"] == "worse"
    assert "the anchors broke in" in r.loc["anchored", "reason"]
    # nothing to see: said so, not invented
    t2 = t.drop(columns=["anchor_broken_plus", "anchor_broken_minus"])
    r2 = compare_mitigations(t2, hazard=curve(), n_boot=0).table.set_index("mitigation")
    assert r2.loc["anchored", "reason"] == "no reason visible in the runs"


def test_verdict_from_bounds_when_a_fit_is_missing():
    """No fit for the reference (separated outcomes): its median lies between the bounds
    its runs give; a mitigation whose median lies below them all is worse, one whose runs
    never failed above them is better, an overlap is not known."""
    lv = np.array([1.0, 2.0, 3.0, 4.0, 6.0, 8.0])
    n = 20
    none = pd.DataFrame({"mitigation": "none", "pga": np.repeat(lv, n),
                         "overturned": np.repeat(lv >= 4.0, n)})  # median in [3, 4]
    never = pd.DataFrame({"mitigation": "never", "pga": np.repeat(lv, n),
                          "overturned": False})                   # median > 8
    rng = np.random.default_rng(2)
    weak = pd.DataFrame({"mitigation": "weak", "pga": np.repeat(lv, n)})
    weak["overturned"] = rng.random(len(weak)) < norm.cdf(np.log(weak["pga"] / 1.5) / 0.4)
    same = none.assign(mitigation="same")
    r = compare_mitigations(pd.concat([none, never, weak, same]), n_boot=0).table
    v = dict(zip(r["mitigation"], r["verdict"], strict=True))
    assert v == {"none": "reference", "never": "better", "weak": "worse",
                 "same": "not known"}
