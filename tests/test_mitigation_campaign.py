"""The mitigation axis of campaigns (issue 19, ``[[mitigation]]``): its place in ``sim_id``,
rows equal to the plain campaign and to direct batches of the mitigation models, common
random numbers across mitigations, the row outputs as columns, the spec's checks and the
store's guard."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rocking
from rocking import campaign
from rocking.campaign.plan import RESULT_COLUMNS, Campaign
from rocking.campaign.report import report
from rocking.campaign.spec import parse_spec
from rocking.errors import SpecError, StoreError
from rocking.models.registry import MODELS
from rocking.motions import Sine

HEAD = """
[campaign]
name = "mit"
seed = 5
model = "housner"
duration = 5.0
{samples}

[[blocks]]
specimen = 2
params = "experimental"

[[blocks]]
alpha = 0.25
p = 2.2
mu = 0.95

[motions]
kind = "sine"
frequency = [1.0, 2.5]
amplitude = 1.0
cycles = 3
load_factors = [0.8, 2.0, 4.0]
{uncertain}
[run]
chunk_size = {chunk}
"""

MITIGATIONS = """
[[mitigation]]
name = "none"

[[mitigation]]
name = "isolated-2.5s"
model = "isolated"
isolation_period = "2.5s"
isolation_damping = "10%"
clearance = "0.1m"

[[mitigation]]
name = "anchored"
model = "anchored"
anchor_strength = 0.3
"""

UNCERTAIN = """
[uncertain]
alpha = {dist = "normal", cov = 0.03}
theta0 = {dist = "uniform", low = -0.002, high = 0.002}
amplitude = {dist = "normal", mean = 1.0, std = 0.05}
"""

ISO = {"isolation_period": 2.5, "isolation_damping": 0.1, "clearance": 0.1}
ANCHOR = {"anchor_strength": 0.3}


def text(mitigations: str = MITIGATIONS, *, uncertain: str = "", samples: int = 1,
         chunk: int = 1000) -> str:
    return HEAD.format(samples=f"samples = {samples}" if samples > 1 else "",
                       uncertain=uncertain, chunk=chunk) + mitigations


def rows(spec_text: str) -> pd.DataFrame:
    c = Campaign(parse_spec(spec_text))
    return c.run_ids(np.arange(c.n_sims))


def motions() -> list:
    """The spec's motions in the order of its (motion, level) axes, built here."""
    return [Sine.from_acceleration(f, 1.0, 3 / f).scaled(a)
            for f in (1.0, 2.5) for a in (0.8, 2.0, 4.0)]


@pytest.fixture(scope="module")
def nominal_rows() -> pd.DataFrame:
    return rows(text())


# --------------------------------------------------------------------- axes and columns
def test_the_mitigation_axis_follows_the_model_axis(nominal_rows):
    spec = parse_spec(text())
    assert list(spec.axes) == ["model", "mitigation", "heading", "block", "floor", "motion",
                               "level", "sample"]
    assert tuple(spec.axes.values()) == (1, 3, 1, 2, 1, 2, 3, 1)
    n = 2 * 2 * 3
    assert spec.n_sims == 3 * n
    t = nominal_rows
    assert list(t["sim_id"]) == list(range(3 * n))
    # sim_id = k * n + (block, motion, level) index: the mitigation axis is the slowest here
    names = ["none", "isolated-2.5s", "anchored"]
    models = ["housner", "isolated", "anchored"]
    k = t["sim_id"].to_numpy() // n
    assert list(t["mitigation"]) == [names[i] for i in k]
    assert list(t["model"]) == [models[i] for i in k]
    flat = t["sim_id"].to_numpy() % n
    assert (t["block"].to_numpy() == flat // 6).all()
    assert (t["motion"].to_numpy() == flat // 3 % 2).all()
    assert (t["level"].to_numpy() == flat % 3).all()
    cols = list(t.columns)
    assert cols.index("mitigation") == cols.index("model") + 1
    # after the result columns: the row outputs of each model run, in order of appearance
    outs = [o.name for m in models for o in MODELS[m].row_outputs]
    assert cols[-len(outs):] == outs
    assert cols[-len(outs) - len(RESULT_COLUMNS):-len(outs)] == list(RESULT_COLUMNS)


def test_without_mitigation_there_is_no_mitigation_column_nor_row_outputs():
    t = rows(text(""))
    assert "mitigation" not in t.columns
    assert list(t.columns[-len(RESULT_COLUMNS):]) == list(RESULT_COLUMNS)
    assert parse_spec(text("")).axes["mitigation"] == 1


def test_a_plain_isolated_campaign_has_its_row_outputs():
    t = rows(text("").replace('model = "housner"', 'model = "isolated"'))
    names = [o.name for o in MODELS["isolated"].row_outputs]
    assert "mitigation" not in t.columns and list(t.columns[-len(names):]) == names
    assert (t["max_base_displacement"] > 0).all()


# ------------------------------------------------------------------------- the rows
def test_none_rows_are_the_campaign_without_mitigation():
    """With uncertain parameters: the "none" rows are the plain campaign's rows (same
    draws: common random numbers keyed without the mitigation axis), the other mitigations
    only add columns."""
    plain = rows(text("", uncertain=UNCERTAIN, samples=2))
    mit = rows(text(uncertain=UNCERTAIN, samples=2))
    none = mit[mit["mitigation"] == "none"].reset_index(drop=True)
    assert len(none) == len(plain)
    cols = [c for c in plain.columns if c != "sim_id"]
    pd.testing.assert_frame_equal(none[cols], plain[cols])
    # the row outputs of models the row did not run: NaN, or False for flags
    for m in ("isolated", "anchored"):
        for o in MODELS[m].row_outputs:
            assert (~none[o.name]).all() if o.flag else none[o.name].isna().all()


@pytest.mark.parametrize("name, model, options", [("isolated-2.5s", "isolated", ISO),
                                                  ("anchored", "anchored", ANCHOR)])
def test_mitigation_rows_are_the_direct_batches(nominal_rows, name, model, options):
    """Each mitigation's rows equal rocking.simulate_many of its model with its options
    (the units converted: 2.5 s, 10 % and 0.1 m), row outputs included."""
    t = nominal_rows[nominal_rows["mitigation"] == name]
    for b, block in enumerate((rocking.specimen(2, "experimental"),
                               rocking.Block.from_params(0.25, 2.2, 0.95))):
        got = t[t["block"] == b]
        res = rocking.simulate_many(block, motions(), model=model, duration=5.0, **options)
        np.testing.assert_array_equal(got["max_abs_theta"], res.max_abs_theta)
        np.testing.assert_array_equal(got["overturned"], res.overturned)
        for o in MODELS[model].row_outputs:
            np.testing.assert_array_equal(got[o.name], res.outputs[o.name])
    if model == "isolated":  # the moat is reached by some runs and not by others
        assert t["clearance_exceeded"].any() and not t["clearance_exceeded"].all()
        assert (t["max_base_displacement"] <= 0.1 + 1e-12).all()


def test_common_random_numbers_across_mitigations():
    """Every mitigation of a (block, motion, level, sample) draws the same alpha, theta0
    and amplitude: the mitigations are compared on the same realizations."""
    t = rows(text(MITIGATIONS.split("[[mitigation]]\nname = \"anchored\"")[0],
                  uncertain=UNCERTAIN, samples=3))
    assert set(t["mitigation"]) == {"none", "isolated-2.5s"}
    key = ["block", "motion", "level", "sample"]
    drawn = ["alpha", "p", "mu", "theta0", "amplitude", "noise", "pga"]
    a = t[t["mitigation"] == "none"].set_index(key)[drawn]
    b = t[t["mitigation"] == "isolated-2.5s"].set_index(key)[drawn]
    pd.testing.assert_frame_equal(a, b)
    # the draws do differ between samples (the test could fail)
    assert a.groupby(level=["block", "motion", "level"])["alpha"].nunique().min() == 3


def test_rows_do_not_depend_on_the_chunk_size(tmp_path):
    got = []
    for chunk in (3, 1000):
        spec = tmp_path / f"s{chunk}.toml"
        spec.write_text(text(uncertain=UNCERTAIN, chunk=chunk))
        campaign.run(spec, tmp_path / f"store{chunk}", progress=False)
        got.append(campaign.load(tmp_path / f"store{chunk}"))
    assert campaign.Store(tmp_path / "store3").manifest["n_chunks"] == 12
    pd.testing.assert_frame_equal(got[0], got[1])


# ----------------------------------------------------------------------- store, report
def test_the_store_records_the_axis_and_refuses_another_mitigation_list(tmp_path):
    spec = tmp_path / "a.toml"
    spec.write_text(text())
    campaign.run(spec, tmp_path / "s", progress=False)
    m = json.loads((tmp_path / "s" / "manifest.json").read_text())
    assert m["axes"] == ["model", "mitigation", "block", "motion", "level", "sample"]
    assert m["shape"] == [1, 3, 2, 2, 3, 1]
    assert [e["name"] for e in m["mitigations"]] == ["none", "isolated-2.5s", "anchored"]
    assert m["mitigations"][1] == {"name": "isolated-2.5s", "model": "isolated",
                                   "options": ISO}
    for changed in (text(MITIGATIONS.replace('"0.1m"', '"0.2m"')),
                    text(MITIGATIONS.split("[[mitigation]]\nname = \"anchored\"")[0])):
        other = tmp_path / "b.toml"
        other.write_text(changed)
        with pytest.raises(StoreError, match="different campaign.*mitigations"):
            campaign.run(other, tmp_path / "s", progress=False)
    campaign.run(spec, tmp_path / "s", progress=False)  # the same spec resumes
    assert campaign.status(tmp_path / "s")["complete"]


def test_the_report_counts_overturns_per_mitigation(tmp_path, nominal_rows):
    m = campaign.store.manifest_for(parse_spec(text()))
    res = report(nominal_rows, m, tmp_path / "rep", n_boot=0)
    po = res["p_overturn"]
    assert list(po.columns[:2]) == ["model", "mitigation"]
    want = nominal_rows.groupby(["mitigation", "block", "level"])["overturned"].sum()
    got = po.set_index(["mitigation", "block", "level"])["n_overturned"]
    pd.testing.assert_series_equal(got.sort_index(), want.sort_index(), check_dtype=False,
                                   check_names=False)
    # the flags among the row outputs are counted over the runs of the models that have them
    iso = nominal_rows[nominal_rows["model"] == "isolated"]
    assert res["n_clearance_exceeded"] == int(iso["clearance_exceeded"].sum()) > 0
    assert any(line.startswith(f"clearance_exceeded: {res['n_clearance_exceeded']} of "
                               f"{len(iso)} isolated runs") for line in res["run_alerts"])
    md = (tmp_path / "rep" / "report.md").read_text()
    assert "## P(overturn) by mitigation" in md
    assert "| level | IM (m/s^2) | none | isolated-2.5s | anchored |" in md


# ------------------------------------------------------------------------ bad specs
BAD = {
    "unknown option": ('anchor_strength = 0.3', 'anchor_strengh = 0.3',
                       r"mitigation\[2\]\.anchor_strengh: unknown key"),
    "bad value": ('anchor_strength = 0.3', 'anchor_strength = -1.0',
                  r"mitigation\[2\]\.anchor_strength: must be"),
    "bool": ('anchor_strength = 0.3', 'anchor_strength = true',
             r"mitigation\[2\]\.anchor_strength"),
    "wrong unit": ('"2.5s"', '"2.5m"', r"mitigation\[1\]\.isolation_period: unknown time unit"),
    "not a quantity": ('"2.5s"', '"fast"',
                       r"mitigation\[1\]\.isolation_period: .*number with a time unit"),
    "duplicate": ('name = "anchored"', 'name = "none"',
                  r"mitigation\[2\]\.name: 'none' is already the name of mitigation\[0\]"),
    "no name": ('name = "anchored"\n', '', r"mitigation\[2\]\.name: missing"),
    "unknown model": ('model = "anchored"', 'model = "bolted"',
                      r"mitigation\[2\]\.model: must be one of"),
    "model list": ('model = "housner"', 'model = ["housner", "ccrr"]',
                   r"campaign\.model: must be a single model with \[\[mitigation\]\]"),
    "option of another model": ('anchor_strength = 0.3', 'isolation_period = 2.0',
                                r"mitigation\[2\]\.isolation_period: unknown key"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_mitigations_name_the_key(case):
    old, new, match = BAD[case]
    t = text()
    assert old in t
    with pytest.raises(SpecError, match=match):
        parse_spec(t.replace(old, new, 1))


def test_a_single_mitigation_table_is_refused():
    with pytest.raises(SpecError, match=r"spec: mitigation: must be \[\[mitigation\]\] "
                                        r"tables.*not \[mitigation\]"):
        parse_spec(text('\n[mitigation]\nname = "none"\n'))


def test_a_stack_on_an_isolated_base_is_refused():
    t = text('\n[[mitigation]]\nname = "iso"\nmodel = "isolated"\n').replace(
        "alpha = 0.25\np = 2.2\nmu = 0.95",
        "stack = [{width = 0.2, height = 0.4, mass = 10}, {width = 0.2, height = 0.4, "
        "mass = 10}]")
    with pytest.raises(SpecError, match=r"mitigation\[0\]\.model: model 'isolated' cannot "
                                        r"take blocks\[1\]"):
        parse_spec(t)


def test_options_of_the_models_run_merge_under_the_entries():
    """``[options.isolated]`` applies to every isolated entry; an entry's own options win."""
    t = text(MITIGATIONS + '\n[[mitigation]]\nname = "iso-2"\nmodel = "isolated"\n') \
        + '\n[options.isolated]\nisolation_damping = "20%"\nmass_ratio = 0.5\n'
    spec = parse_spec(t)
    iso = {m.name: m.options for m in spec.mitigations if m.model == "isolated"}
    assert iso["isolated-2.5s"] == {**ISO, "isolation_damping": 0.1, "mass_ratio": 0.5}
    assert iso["iso-2"] == {"isolation_damping": 0.2, "mass_ratio": 0.5}
    with pytest.raises(SpecError, match=r"options\.ccrr: unknown key"):
        parse_spec(text() + "\n[options.ccrr]\nrtol = 1e-8\n")


def test_the_example_parses():
    spec = campaign.read_spec(Path(__file__).parents[1] / "examples" / "mitigation.toml")
    assert [m.model for m in spec.mitigations] == ["housner", "isolated", "anchored"]
    assert spec.mitigations[1].options == {"isolation_period": 2.5, "isolation_damping": 0.1,
                                           "clearance": 0.15}
