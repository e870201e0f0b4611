"""The `settled` flag in campaign rows, `ida` tables and Monte Carlo samples, the campaign
key `max_free_time`, and the report's count of unsettled runs.

The case (issue 16): a one-sine pulse sampled as a record that ends with the pulse. The
block overturns after the pulse (Zhang and Makris 2001), so a run that stops with the
record says "safe" and is still rocking; the default run goes on until it has settled."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rocking
from rocking import G, campaign
from rocking.analysis.ida import ida
from rocking.analysis.montecarlo import monte_carlo
from rocking.campaign.report import report, summary_lines
from rocking.motions import OneSine, sample

BLOCK = rocking.specimen(2, "experimental")
AMP = 3.0 * G * math.tan(BLOCK.alpha)  # 3 x the uplift acceleration
TP = 2.0 * math.pi / (2.0 * BLOCK.p)   # omega_p = 2 p
RECORD = sample(OneSine(AMP, TP), TP / 500, duration=TP)


def test_ida_table_has_settled_and_follows_max_free_time():
    pga = RECORD.pga
    full = ida(BLOCK, [RECORD], im="pga", levels=[pga], model="ccrr")
    cut = ida(BLOCK, [RECORD], im="pga", levels=[pga], model="ccrr", max_free_time=0.0)
    fixed = ida(BLOCK, [RECORD], im="pga", levels=[pga], model="ccrr",
                duration=RECORD.duration)
    assert full["settled"].dtype == bool
    assert bool(full["overturned"].iloc[0]) and bool(full["settled"].iloc[0])
    for t in (cut, fixed):  # stopped with the record: still rocking, not overturned
        assert not t["overturned"].iloc[0] and not t["settled"].iloc[0]
    # each row is the single run
    r = rocking.simulate(BLOCK, RECORD.scaled(full["scale"].iloc[0]), model="ccrr",
                         max_free_time=0.0)
    assert r.settled == cut["settled"].iloc[0]


def test_monte_carlo_samples_have_settled():
    unc = {"amplitude": {"dist": "uniform", "low": 0.99, "high": 1.01}}
    cut = monte_carlo(BLOCK, RECORD, unc, n=6, seed=1, model="ccrr", max_free_time=0.0)
    full = monte_carlo(BLOCK, RECORD, unc, n=6, seed=1, model="ccrr")
    assert cut.n_unsettled == 6 and not cut.samples["overturned"].any()
    assert full.n_unsettled == 0 and full.samples["overturned"].all()
    assert cut.summary()["n_unsettled"] == 6


SPEC = f"""
[campaign]
name = "tail"
seed = 1
model = ["housner", "ccrr"]
{{extra}}

[[blocks]]
specimen = 2
params = "experimental"

[motions]
kind = "one_sine"
period = [{TP!r}]
amplitude = {AMP!r}
duration = {TP!r}
load_factors = [1.0, 0.2]
"""


@pytest.mark.parametrize("free", [None, 0.0])
def test_campaign_rows_settled_and_the_report_counts_unsettled(tmp_path, free):
    extra = "" if free is None else f"max_free_time = {free}"
    spec = campaign.parse_spec(SPEC.format(extra=extra))
    assert spec.max_free_time == free
    campaign.run(spec, tmp_path / "store", progress=False)
    rows = campaign.load(tmp_path / "store").sort_values("sim_id")
    assert rows["settled"].dtype == bool
    big = rows[rows["load_factor"] == 1.0].set_index("model")
    small = rows[rows["load_factor"] == 0.2]
    assert small["settled"].all() and not small["overturned"].any()  # below uplift: at rest
    if free is None:  # the tail decides both models: overturned after the pulse
        assert big["overturned"].all() and big["settled"].all()
    else:  # stopped with the pulse: the CCRR run is still rocking, counted a survivor;
        # the classical model decides its outcome at the cap by energy (settled)
        assert not big.loc["ccrr", "overturned"] and not big.loc["ccrr", "settled"]
        assert big.loc["housner", "overturned"] and big.loc["housner", "settled"]
    # the rows are the direct runs with the same max_free_time
    for r in rows.itertuples():
        direct = rocking.simulate(BLOCK, OneSine(AMP * r.load_factor, TP, duration=TP),
                                  model=r.model, max_free_time=free)
        assert (direct.overturned, direct.settled) == (r.overturned, r.settled)
        assert direct.max_abs_theta == r.max_abs_theta
    k = int((~rows["settled"]).sum())
    res = report(rows, campaign.Store(tmp_path / "store").manifest, tmp_path / "rep")
    assert res["n_unsettled"] == k == (0 if free is None else 1)
    md = (tmp_path / "rep" / "report.md").read_text()
    assert f"unsettled: {k} of 4 runs were still rocking when they ended" in md
    assert "count as survivors" in md
    assert any(s.startswith("unsettled: 1 of 4") for s in summary_lines(res)) == (k == 1)
    po = res["p_overturn"]
    assert po["n_unsettled"].sum() == k
    ccrr_big = po[(po["model"] == "ccrr") & (po["level"] == 0)]
    assert int(ccrr_big["n_unsettled"].iloc[0]) == k
    assert float(ccrr_big["p_overturn"].iloc[0]) == (1.0 if free is None else 0.0)


def test_spec_hash_depends_on_max_free_time():
    a = campaign.parse_spec(SPEC.format(extra=""))
    b = campaign.parse_spec(SPEC.format(extra="max_free_time = 0.0"))
    assert a.hash != b.hash
    assert np.isclose(b.max_free_time, 0.0)
