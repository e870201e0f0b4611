"""Campaigns with a ``[building]`` (issue 18): the blocks stand on floors, the table gets a
floor axis, each row is the direct run on the floor motion of its ground motion, floor 0
is the ground, and a spec without ``[building]`` keeps its ids and columns."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

import rocking.buildings
from rocking import campaign
from rocking.blocks.factory import make_block
from rocking.buildings import FloorMotion
from rocking.buildings.catalog import KINDS, make_building
from rocking.campaign.report import report
from rocking.campaign.spec import keys_table
from rocking.campaign.store import manifest_for
from rocking.errors import SpecError
from rocking.models import simulate_many
from rocking.motions import catalog

RESULTS = ("max_abs_theta", "overturned", "overturn_time", "n_impacts", "settled")
BLOCK = {"width": 0.2, "height": 1.0}
MOTION = {"kind": "one_sine", "amplitude": "0.15g"}
PERIODS = [0.3, 0.6]
LEVELS = [1.0, 1.5]
SHEAR = {"kind": "shear", "storeys": 3, "period": 0.4, "damping_ratio": "5%"}


def spec_text(building: dict | None = None, floors="all", extra: str = "") -> str:
    """A spec: one block, a one-sine pulse of two periods, two load factors, and
    ``building`` with ``floors`` (a TOML value as text, or None for none)."""
    text = f"""
[campaign]
name = "floors"
seed = 3
model = "housner"

[[blocks]]
width = {BLOCK['width']}
height = {BLOCK['height']}

[motions]
kind = "{MOTION['kind']}"
amplitude = "{MOTION['amplitude']}"
period = {PERIODS}
load_factors = {LEVELS}
{extra}
"""
    if building is not None:
        text += "\n[building]\n" + "".join(f"{k} = {json.dumps(v)}\n"
                                           for k, v in building.items())
        if floors is not None:
            text += f"floors = {json.dumps(floors)}\n"
    return text


def rows_of(text: str) -> pd.DataFrame:
    spec = campaign.parse_spec(text)
    return campaign.Campaign(spec).run_ids(np.arange(spec.n_sims))


def assert_same_results(rows: pd.DataFrame, res) -> None:
    for c in RESULTS:
        a, b = rows[c].to_numpy(), np.asarray(getattr(res, c))
        assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), c


def ground(period: float):
    return catalog.build("one_sine", amplitude=MOTION["amplitude"], period=period)


# ------------------------------------------------------------------ rows are direct runs
def test_every_floor_row_is_the_direct_run_on_its_floor_motion():
    """A 3-storey shear building, floors "all", two pulse periods and two levels: each row
    equals simulate_many on FloorMotion(ground, building, floor).scaled(level)."""
    spec = campaign.parse_spec(spec_text(SHEAR))
    assert spec.shape == (1, 1, 4, 2, 2, 1)
    rows = campaign.Campaign(spec).run_ids(np.arange(spec.n_sims))
    building = make_building(SHEAR)
    block = make_block(BLOCK)
    motions, pfa, pga = [], [], []
    for r in rows.itertuples():
        g = ground(PERIODS[r.motion])
        fm = FloorMotion(g, building, floor=r.floor).scaled(LEVELS[r.level])
        motions.append(fm)
        pfa.append(fm.pga)
        pga.append(g.scaled(LEVELS[r.level]).pga)
    assert rows["floor"].tolist() == [f for f in range(4) for _ in range(4)]
    res = simulate_many([block] * len(rows), motions, model="housner")
    assert_same_results(rows, res)
    # the levels scale the ground: the same ground PGA on every floor, the floor's own peak
    assert np.allclose(rows["pga"], pga, rtol=1e-12)
    assert np.allclose(rows["floor_pga"], pfa, rtol=1e-12)
    assert np.array_equal(rows.loc[rows["floor"] == 0, "floor_pga"],
                          rows.loc[rows["floor"] == 0, "pga"])
    assert rows["overturned"].any() and not rows["overturned"].all()  # a telling case


def test_floor_zero_rows_equal_the_spec_without_building():
    with_building = rows_of(spec_text(SHEAR))
    ground_only = rows_of(spec_text())
    on_ground = with_building[with_building["floor"] == 0].reset_index(drop=True)
    assert len(on_ground) == len(ground_only)
    for c in ground_only.columns:
        if c == "sim_id":
            continue
        a, b = on_ground[c].to_numpy(), ground_only[c].to_numpy()
        assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), c


def test_height_ratios_of_a_continuous_building_are_the_direct_runs():
    b = {"kind": "continuous", "period": 0.5, "stiffness_ratio": 5.0, "n_modes": 4}
    text = spec_text(b, floors=None) + "height_ratios = [0.0, 0.5, 1.0]\n"
    spec = campaign.parse_spec(text)
    rows = campaign.Campaign(spec).run_ids(np.arange(spec.n_sims))
    assert rows["height_ratio"].tolist() == [x for x in (0.0, 0.5, 1.0) for _ in range(4)]
    assert rows["floor"].tolist() == [k for k in range(3) for _ in range(4)]
    building = make_building(b)
    motions = [FloorMotion(ground(PERIODS[r.motion]), building, height_ratio=r.height_ratio)
               .scaled(LEVELS[r.level]) for r in rows.itertuples()]
    assert_same_results(rows, simulate_many([make_block(BLOCK)] * len(rows), motions))


def test_floor_motions_are_built_once_per_floor_and_ground_motion(monkeypatch):
    built = []

    class Counting(FloorMotion):
        def __post_init__(self):
            built.append((self.floor, self.ground.scale))
            super().__post_init__()

    monkeypatch.setattr(rocking.buildings, "FloorMotion", Counting)
    rows = rows_of(spec_text(SHEAR))
    assert len(rows) == 16
    assert len(built) == 4 * 2  # (floor, ground motion) pairs, never one per row
    assert {s for _, s in built} == {1.0}  # unscaled: the levels scale the copies


# ------------------------------------------------------------------ the axis, the store
def test_without_building_the_ids_are_those_of_the_five_axes():
    spec = campaign.parse_spec(spec_text())
    assert spec.building is None and spec.shape[2] == 1
    rows = campaign.Campaign(spec).run_ids(np.arange(spec.n_sims))
    assert "floor" not in rows and "floor_pga" not in rows
    five = (1, 1, 2, 2, 1)
    idx = np.unravel_index(rows["sim_id"].to_numpy(), five)
    for col, i in zip(("block", "motion", "level", "sample"), idx[1:], strict=True):
        assert np.array_equal(rows[col], i), col
    m = manifest_for(spec)
    assert m["axes"] == ["model", "block", "motion", "level", "sample"]
    assert m["shape"] == list(five) and "building" not in m and "floors" not in m


def test_manifest_and_hash_carry_the_building():
    spec = campaign.parse_spec(spec_text(SHEAR, floors=[0, 3]))
    m = manifest_for(spec)
    assert m["axes"] == ["model", "block", "floor", "motion", "level", "sample"]
    assert m["shape"] == [1, 1, 2, 2, 2, 1] and m["floors"] == [0, 3]
    b = m["building"]
    assert (b["kind"], b["storeys"], b["period"], b["damping_ratio"]) == ("shear", 3, 0.4,
                                                                          0.05)
    assert b["periods"][0] == pytest.approx(0.4) and b["n_floors"] == 3
    json.dumps(m)  # JSON as written
    hashes = {campaign.parse_spec(t).hash for t in (
        spec_text(), spec_text(SHEAR, floors=[0, 3]), spec_text(SHEAR, floors=[0, 2]),
        spec_text({**SHEAR, "period": 0.5}, floors=[0, 3]))}
    assert len(hashes) == 4


def test_the_store_and_the_report_group_by_floor(tmp_path):
    spec = campaign.parse_spec(spec_text(SHEAR))
    campaign.run(spec, tmp_path / "store", progress=False)
    table = campaign.load(tmp_path / "store")
    out = report(table, campaign.Store(tmp_path / "store").manifest, tmp_path / "rep",
                 n_boot=0)
    po = out["p_overturn"]
    assert sorted(po["floor"].unique()) == [0, 1, 2, 3]
    for (f, lv), g in table.groupby(["floor", "level"]):
        row = po[(po["floor"] == f) & (po["level"] == lv)]
        assert row["n_overturned"].item() == g["overturned"].sum()
    md = (tmp_path / "rep" / "report.md").read_text()
    assert "## P(overturn) by floor" in md
    assert "| level | IM (m/s^2) | floor 0 | floor 1 | floor 2 | floor 3 |" in md
    for f in range(4):
        assert f"floor {f}\n" in md  # a per-level table per floor


# ------------------------------------------------------------------ errors
@pytest.mark.parametrize("building, floors, key", [
    (SHEAR, [0, 4], "building.floors[1]"),
    (SHEAR, [0, -1], "building.floors[1]"),
    (SHEAR, [1, 1], "building.floors"),
    (SHEAR, "top", "building.floors"),
    (SHEAR, None, "building.floors"),
    ({**SHEAR, "height": 30}, "all", "building.height"),
    ({**SHEAR, "period": -1.0}, "all", "building.period"),
    ({**SHEAR, "damping_ratio": "150%"}, "all", "building.damping_ratio"),
    ({**SHEAR, "damping_ratio": 0.0}, "all", "building.damping_ratio"),
    ({**SHEAR, "storeys": 2.5}, "all", "building.storeys"),
    ({"storeys": 3, "period": 0.4}, "all", "building.kind"),
    ({**SHEAR, "kind": "tower"}, "all", "building.kind"),
    ({"kind": "continuous", "period": 0.5, "stiffness_ratio": 5.0}, [1],
     "building.floors"),
    ({"kind": "continuous", "period": 0.5}, "all", "building.stiffness_ratio"),
])
def test_bad_building_keys_are_named(building, floors, key):
    with pytest.raises(SpecError) as e:
        campaign.parse_spec(spec_text(building, floors))
    assert str(e.value).startswith(f"spec: {key}: "), str(e.value)
    assert "\n" not in str(e.value)


@pytest.mark.parametrize("building, ratios, key", [
    (SHEAR, "[0.5]", "building.height_ratios[0]"),  # not a floor of the 3 storeys
    ({"kind": "continuous", "period": 0.5, "stiffness_ratio": 5.0}, "[0.5, 1.5]",
     "building.height_ratios[1]"),
    ({"kind": "continuous", "period": 0.5, "stiffness_ratio": 5.0}, "[0.5, 0.5]",
     "building.height_ratios"),
])
def test_bad_height_ratios_are_named(building, ratios, key):
    with pytest.raises(SpecError) as e:
        campaign.parse_spec(spec_text(building, None) + f"height_ratios = {ratios}\n")
    assert str(e.value).startswith(f"spec: {key}: "), str(e.value)


def test_height_ratios_of_a_shear_building_are_its_floors():
    s = campaign.parse_spec(spec_text(SHEAR, None) + "height_ratios = [0.0, 1.0]\n")
    f = campaign.parse_spec(spec_text(SHEAR, [0, 3]))
    assert s.n_sims == f.n_sims
    a, b = campaign.Campaign(s).run_ids(range(s.n_sims)), campaign.Campaign(f).run_ids(
        range(f.n_sims))
    assert np.array_equal(a["max_abs_theta"], b["max_abs_theta"], equal_nan=True)


def test_floors_and_height_ratios_together_are_refused():
    b = {"kind": "continuous", "period": 0.5, "stiffness_ratio": 5.0, "storeys": 4}
    with pytest.raises(SpecError, match=r"^spec: building\.height_ratios: give floors or"):
        campaign.parse_spec(spec_text(b, [0, 4]) + "height_ratios = [0.5]\n")
    rows = rows_of(spec_text(b, [0, 4]))  # a continuous building with storeys has floors
    assert rows["floor"].unique().tolist() == [0, 4]


def test_the_keys_table_lists_every_building_key():
    table = keys_table()
    for k in KINDS.values():
        for d in k.describe():
            assert f"| `{k.name}` | `{d['name']}` |" in table, (k.name, d["name"])
    assert "`floors`" in table and "`height_ratios`" in table
