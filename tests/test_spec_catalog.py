"""Campaign specs speak the catalog's vocabulary: every motion kind
(rocking.motions.catalog) and block form (rocking.blocks.factory) can be written in a spec,
its rows are the direct rocking.simulate_many calls, the old spellings give the same rows
with a DeprecationWarning that says how to write them, and the README's table of spec keys
is generated from the catalog and the factory."""

from __future__ import annotations

import hashlib
import json
import math
import re
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rocking
from rocking import campaign
from rocking.blocks.factory import make_block
from rocking.campaign.spec import KEYS_END, KEYS_START, keys_table
from rocking.errors import SpecError
from rocking.motions import GroundMotion, Record, catalog
from rocking.motions.io import _builtin_dir

RESULTS = ("max_abs_theta", "overturned", "overturn_time", "n_impacts", "settled")
README = Path(__file__).resolve().parents[1] / "README.md"


def toml(v) -> str:
    """``v`` as a TOML value (test-side writer)."""
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k} = {toml(x)}" for k, x in v.items()) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(map(toml, v)) + "]"
    if isinstance(v, bool):
        return str(v).lower()
    return json.dumps(v) if isinstance(v, str) else repr(v)


def spec_text(motions: dict, blocks=({"specimen": 2, "params": "experimental"},),
              model="housner", campaign_keys="") -> str:
    out = [f'[campaign]\nname = "catalog"\nseed = 4\nmodel = "{model}"\n{campaign_keys}']
    out += ["[[blocks]]\n" + "\n".join(f"{k} = {toml(v)}" for k, v in b.items())
            for b in blocks]
    out.append("[motions]\n" + "\n".join(f"{k} = {toml(v)}" for k, v in motions.items()))
    return "\n\n".join(out) + "\n"


def write_spec(d: Path, text: str) -> Path:
    p = d / "spec.toml"
    p.write_text(text)
    return p


def assert_rows_are(rows: pd.DataFrame, res, columns=RESULTS) -> None:
    """The campaign's rows are the direct run's, column by column, bit for bit."""
    for c in columns:
        assert np.array_equal(rows[c].to_numpy(), np.asarray(getattr(res, c)),
                              equal_nan=rows[c].dtype.kind == "f"), c


def record_file(path: Path, freq: float, peak: float, seconds: float = 4.0) -> Path:
    """A decaying sine (m/s^2) as a time, acceleration CSV."""
    t = np.arange(0.0, seconds, 0.01)
    a = peak * np.sin(2 * math.pi * freq * t) * np.exp(-0.4 * t)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("t,acc\n" + "".join(f"{x:.2f},{y:.6f}\n" for x, y in zip(t, a,
                                                                               strict=True)))
    return path


# ------------------------------------------------------------------ three components
def test_three_component_motions_are_the_direct_runs(tmp_path):
    """set + horizontal (swept) and vertical_factor: rows equal simulate_many under the
    class's ground motions; lift_off_time and lifted_off agree."""
    levels = [0.5, 1.6]
    text = spec_text({"kind": "ground_motion", "set": "rinaldi", "horizontal": [1, 2],
                      "vertical_factor": 1.2, "load_factors": levels})
    campaign.run(write_spec(tmp_path, text), tmp_path / "store", progress=False)
    rows = campaign.load(tmp_path / "store")
    block = rocking.specimen(2, "experimental")
    motions = []
    for h in (1, 2):
        gm = GroundMotion.builtin("rinaldi", horizontal=h)
        gm = GroundMotion(gm.horizontal, gm.vertical.scaled(1.2))
        motions += [gm.scaled(lf) for lf in levels]
    res = rocking.simulate_many(block, motions)
    assert_rows_are(rows, res, RESULTS + ("lift_off_time", "lifted_off"))
    assert (rows["lifted_off"] == rows["lift_off_time"].notna()).all()
    # the columns sit after settled
    cols = list(rows.columns)
    assert cols[cols.index("settled") + 1:cols.index("settled") + 3] == ["lift_off_time",
                                                                          "lifted_off"]


def test_ground_motion_from_files_and_its_im_is_the_horizontal_one(tmp_path):
    h = record_file(tmp_path / "h.csv", 1.5, 4.0)
    v = record_file(tmp_path / "v.csv", 6.0, 5.0)
    text = spec_text({"kind": "ground_motion", "file": "h.csv", "vertical_file": "v.csv",
                      "units": "m/s^2", "vertical_factor": 2.0, "im": "pga",
                      "levels": [1.0, 3.0]})
    spec = campaign.read_spec(write_spec(tmp_path, text))
    rows = campaign.Campaign(spec).run_ids(np.arange(spec.n_sims))
    hr = Record.from_file(h, units="m/s^2")
    vr = Record.from_file(v, units="m/s^2").scaled(2.0)
    # scaled to the levels by the horizontal component's PGA
    np.testing.assert_allclose(rows["load_factor"], np.array([1.0, 3.0]) / hr.pga,
                               rtol=1e-12)
    np.testing.assert_allclose(rows["pga"], rows["im"], rtol=1e-12)
    res = rocking.simulate_many(rocking.specimen(2, "experimental"),
                                [GroundMotion(hr, vr).scaled(f) for f in rows["load_factor"]])
    assert_rows_are(rows, res, RESULTS + ("lift_off_time", "lifted_off"))


def test_only_vertical_kinds_add_the_lift_off_columns():
    spec = campaign.parse_spec(spec_text({"kind": "one_sine", "amplitude": 3.0,
                                          "period": 0.5}))
    rows = campaign.Campaign(spec).run_ids([0])
    assert "lift_off_time" not in rows and "lifted_off" not in rows


# ------------------------------------------------------------------ blocks
STACK = {"stack": [{"width": 0.2, "height": 0.4, "mass": 10.0},
                   {"width": 0.16, "height": 0.5, "mass": 8.0}]}
POLYGON = {"vertices": [[-0.1, 0.0], [0.1, 0.0], [0.06, 0.6], [-0.06, 0.6]], "mass": 20.0}


def test_dem_stack_and_polygon_are_the_direct_runs(tmp_path):
    """A stack and a polygon under a short pulse with the DEM: the rows are
    simulate_many's; a stack stands in the table for its top block."""
    text = spec_text({"kind": "one_sine", "amplitude": 4.0, "period": 0.3,
                      "duration": 0.6, "load_factors": [1.0]},
                     blocks=(STACK, POLYGON), model="dem")
    spec = campaign.parse_spec(text)
    rows = campaign.Campaign(spec).run_ids(np.arange(spec.n_sims))
    stack, polygon = make_block(STACK), make_block(POLYGON)
    res = rocking.simulate_many([stack, polygon],
                                [rocking.motions.OneSine(4.0, 0.3, duration=0.6)] * 2,
                                model="dem")
    assert_rows_are(rows, res)
    top = stack.top
    assert rows.loc[0, ["alpha", "p", "mu"]].tolist() == [top.alpha, top.p, top.mu]
    assert rows.loc[1, ["alpha", "p", "mu"]].tolist() == [polygon.alpha, polygon.p,
                                                           polygon.mu]
    # unnamed: the factory's name and the block's place, as stored in block_name
    assert rows["block_name"].tolist() == [f"{stack.name} (blocks[0])",
                                           f"{polygon.name} (blocks[1])"]


def test_a_stack_with_a_classical_model_names_the_block():
    with pytest.raises(SpecError, match=r"^spec: blocks\[1\]: not usable with model "
                                        r"'housner'.*dem"):
        campaign.parse_spec(spec_text({"kind": "one_sine", "amplitude": 1.0, "period": 0.5},
                                      blocks=({"specimen": 2}, STACK)))


def test_block_keys_are_named_in_errors():
    bad = {"stack": [{"width": 0.2, "height": 0.4}, {"width": 0.2, "height": -1.0}]}
    with pytest.raises(SpecError, match=r"^spec: blocks\[0\]\.stack\[1\]\.height: must be "
                                        r"in \(0, inf\)"):
        campaign.parse_spec(spec_text({"kind": "one_sine", "amplitude": 1.0, "period": 0.5},
                                      blocks=(bad,), model="dem"))


# ------------------------------------------------------------------ record globs
def test_record_glob_gives_one_motion_per_file(tmp_path):
    for name, f in (("rec_a.csv", 1.5), ("rec_b.csv", 2.5), ("rec_c.csv", 4.0)):
        record_file(tmp_path / "recs" / name, f, 3.0)
    record_file(tmp_path / "recs" / "other.csv", 1.0, 9.0)  # not matched
    block = {"alpha": 0.2, "p": 2.5, "mu": 0.9}
    levels = [0.8, 1.5]
    text = spec_text({"kind": "record", "file": "recs/rec_*.csv", "units": "m/s^2",
                      "load_factors": levels}, blocks=(block,))
    spec = campaign.read_spec(write_spec(tmp_path, text))
    campaign.run(spec, tmp_path / "store", progress=False)
    rows = campaign.load(tmp_path / "store")
    files = sorted((tmp_path / "recs").glob("rec_*.csv"))
    assert rows["motion_id"].unique().tolist() == [f"recs/{f.name}" for f in files]
    motions = [Record.from_file(f, units="m/s^2").scaled(lf) for f in files for lf in levels]
    res = rocking.simulate_many(rocking.Block.from_params(**block), motions)
    assert_rows_are(rows, res)
    # the spec hash covers the matched files: a new match is another campaign
    record_file(tmp_path / "recs" / "rec_d.csv", 3.0, 3.0)
    assert campaign.read_spec(tmp_path / "spec.toml").hash != spec.hash


# ------------------------------------------------------------------ old spellings
def _files_pair(d: Path):
    record_file(d / "r.csv", 2.0, 3.0)
    return ({"kind": "files", "paths": ["r.csv"], "units": "m/s^2"},
            {"kind": "record", "file": ["r.csv"], "units": "m/s^2"})


OLD = {  # old [motions] -> the same in the catalog's vocabulary
    "seed_earthquakes": ({"kind": "seed_earthquakes", "records": [3, 20]},
                         {"kind": "earthquake", "number": [3, 20]}),
    "files": _files_pair,
    "builtin": ({"kind": "builtin", "names": ["RSN126_GAZLI_GAZ000"]},
                {"kind": "builtin", "name": ["RSN126_GAZLI_GAZ000"]}),
    "sine_grid": ({"kind": "sine_grid", "frequencies": [1.0, 2.5]},
                  {"kind": "sine", "frequency": [1.0, 2.5], "amplitude": 1.0, "cycles": 10}),
    "sine_grid record_duration": (
        {"kind": "sine_grid", "frequencies": {"start": 1.0, "stop": 3.0, "num": 3},
         "amplitude": 2.0, "record_duration": 4.0},
        {"kind": "sine", "frequency": {"start": 1.0, "stop": 3.0, "num": 3},
         "amplitude": 2.0, "duration": 4.0}),
    "pulse_grid": ({"kind": "pulse_grid", "pulse": "one_cosine", "periods": [0.4, 0.8]},
                   {"kind": "one_cosine", "period": [0.4, 0.8], "amplitude": 1.0}),
    "pulse_grid ricker": ({"kind": "pulse_grid", "pulse": "ricker", "periods": [0.5],
                           "record_duration": 6.0},
                          {"kind": "ricker", "period": [0.5], "amplitude": 1.0,
                           "duration": 6.0}),
    "stochastic record_duration": ({"kind": "stochastic", "n": 2, "record_duration": 15.0},
                                   {"kind": "stochastic", "n": 2, "duration": 15.0}),
}


@pytest.mark.parametrize("case", sorted(OLD))
def test_old_kinds_give_the_rows_of_their_new_spelling(tmp_path, case):
    old, new = OLD[case](tmp_path) if callable(OLD[case]) else OLD[case]
    levels = {"load_factors": [1.5, 3.0]}
    with pytest.warns(DeprecationWarning, match="is deprecated.*write kind = ") as w:
        a = campaign.read_spec(write_spec(tmp_path, spec_text({**old, **levels})))
    b = campaign.read_spec(write_spec(tmp_path, spec_text({**new, **levels})))
    # the warning's spelling is the new one
    said = str(w[0].message).split("write ", 1)[1]
    assert tomllib.loads(f"m = {{{said}}}")["m"] == new
    pd.testing.assert_frame_equal(campaign.Campaign(a).run_ids(np.arange(a.n_sims)),
                                  campaign.Campaign(b).run_ids(np.arange(b.n_sims)))


def test_an_old_spelling_keeps_its_hash_and_names_its_keys(tmp_path):
    """The hash is of the raw TOML (and the record files' contents); errors name the key
    as written."""
    old, _ = _files_pair(tmp_path)
    text = spec_text(old)
    with pytest.warns(DeprecationWarning):
        s = campaign.read_spec(write_spec(tmp_path, text))
    digest = hashlib.sha256((tmp_path / "r.csv").read_bytes()).hexdigest()[:16]
    raw = tomllib.loads(text)
    raw["run"] = {}
    expect = hashlib.sha256(json.dumps({"raw": raw, "digests": [digest]}, sort_keys=True,
                                       default=str).encode()).hexdigest()
    assert s.hash == expect
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        with pytest.raises(SpecError, match=r"^spec: motions\.record_duration: must be in"):
            campaign.parse_spec(spec_text({"kind": "sine_grid", "frequencies": [2.0],
                                           "record_duration": 1e9}))
        with pytest.raises(SpecError, match=r"^spec: motions\.records\[1\]: must be in "
                                            r"\[1, 30\]"):
            campaign.parse_spec(spec_text({"kind": "seed_earthquakes", "records": [2, 31]}))
        with pytest.raises(SpecError, match=r"^spec: motions\.name: give name or names"):
            campaign.parse_spec(spec_text({"kind": "builtin", "names": ["Rinaldi228"],
                                           "name": "Rinaldi228"}))


# ------------------------------------------------------------------ every kind
EXAMPLES = {
    "sine": {"frequency": 2.0, "amplitude": 1.5, "cycles": 3},
    "hanning": {"frequency": 3.3, "displacement": 0.007, "duration": 2.0},
    "one_sine": {"amplitude": 2.0, "period": 0.5},
    "one_cosine": {"amplitude": 2.0, "period": 0.5, "t0": 0.2},
    "half_sine": {"amplitude": 2.0, "period": 0.4, "duration": 3.0},
    "rectangular": {"amplitude": 2.0, "period": 0.3},
    "ricker": {"amplitude": 2.0, "frequency": 2.0},
    "mavroeidis_papageorgiou": {"amplitude": 2.0, "frequency": 1.0, "gamma": 2.0,
                                "nu": 0.5},
    "record": {"file": str(_builtin_dir() / "RSN982_NORTHR_JEN292.AT2")},
    "builtin": {"name": "RSN126_GAZLI_GAZ000"},
    "earthquake": {"number": 7},
    "ec8_earthquake": {"number": 2, "ground": "C"},
    "ground_motion": {"set": "duzce", "horizontal": 2, "vertical_factor": 0.5},
    "stochastic": {"index": 3, "duration": 15.0, "Ia": 0.8},
}


def test_every_kind_has_an_example():
    assert set(EXAMPLES) == set(catalog.KINDS)


@pytest.mark.parametrize("name", sorted(catalog.KINDS))
def test_every_catalog_kind_can_be_written_in_a_spec(tmp_path, name):
    params = EXAMPLES[name]
    spec = campaign.read_spec(write_spec(tmp_path, spec_text({"kind": name, **params})))
    assert spec.n_motions == 1
    ms = campaign.Campaign(spec).motions
    got = ms.get(0).spec()
    want = catalog.build(name, catalog.Context(tmp_path, seed=4), **params).spec()
    assert got[0] == want[0]
    assert all(np.array_equal(a, b) for a, b in zip(got[1:], want[1:], strict=True))
    kind = catalog.KINDS[name]
    assert ms.id(0) == kind.label(kind.params(**params))


GAZLI = str(_builtin_dir() / "RSN126_GAZLI_GAZ000.AT2")
TWO = {"frequency": [2.0, 3.0], "period": [0.5, 0.7],
       "file": [EXAMPLES["record"]["file"], GAZLI],
       "name": ["RSN126_GAZLI_GAZ000", "RSN982_NORTHR_JEN292"], "number": [7, 9],
       "set": ["duzce", "rinaldi"], "index": [3, 5]}
"""Two values of each first sweep parameter of the catalog."""


@pytest.mark.parametrize("name", sorted(k for k in catalog.KINDS if catalog.KINDS[k].sweep))
def test_the_swept_parameter_sets_the_motion_axis(tmp_path, name):
    """A list of two values of the kind's first sweep parameter is two motions, each the
    catalog's motion of that value."""
    param = catalog.KINDS[name].sweep[0]
    drop = {param, "frequency"} if name == "ricker" else {param}  # ricker: one of the two
    base = {k: v for k, v in EXAMPLES[name].items() if k not in drop}
    spec = campaign.read_spec(write_spec(tmp_path, spec_text({"kind": name, **base,
                                                              param: TWO[param]})))
    assert spec.n_motions == 2
    ms = campaign.Campaign(spec).motions
    ctx = catalog.Context(tmp_path, seed=4)
    for j, v in enumerate(TWO[param]):
        want = catalog.build(name, ctx, **{**base, param: v}).spec()
        assert all(np.array_equal(a, b) for a, b in zip(ms.get(j).spec(), want, strict=True))


# ------------------------------------------------------------------ bad keys
BAD = {
    "unknown key": ({"kind": "sine", "frequency": 2.0, "amplitude": 1.0, "cycles": 3,
                     "amplitud": 2}, "motions.amplitud"),
    "out of range": ({"kind": "one_sine", "amplitude": -1.0, "period": 0.5},
                     "motions.amplitude"),
    "out of range in a list": ({"kind": "one_sine", "amplitude": 1.0, "period": [0.5, -1.0]},
                               "motions.period[1]"),
    "missing": ({"kind": "one_sine", "amplitude": 1.0}, "motions.period"),
    "a list of a fixed parameter": ({"kind": "one_sine", "amplitude": [1.0, 2.0],
                                     "period": 0.5}, "motions.amplitude"),
    "two swept parameters": ({"kind": "ground_motion", "set": ["rinaldi", "duzce"],
                              "horizontal": [1, 2]}, "motions.horizontal"),
    "a glob matching nothing": ({"kind": "record", "file": "none/*.AT2"}, "motions.file"),
    "unknown kind": ({"kind": "sinus"}, "motions.kind"),
    "unknown record name": ({"kind": "builtin", "name": ["RSN126_GAZLI_GAZ000", "nope"]},
                            "motions.name[1]"),
    "earthquake 31": ({"kind": "earthquake", "number": [1, 31]}, "motions.number[1]"),
    "a bool": ({"kind": "one_sine", "amplitude": True, "period": 0.5}, "motions.amplitude"),
    "n and index": ({"kind": "stochastic", "n": 2, "index": 1}, "motions.n"),
    "no n": ({"kind": "stochastic"}, "motions.n"),
    "repeated values": ({"kind": "earthquake", "number": [4, 4]}, "motions.number"),
    "empty list": ({"kind": "earthquake", "number": []}, "motions.number"),
    "noise with a vertical component": ({"kind": "ground_motion", "set": "rinaldi"},
                                        "uncertain.noise"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_motion_keys_name_the_key(tmp_path, case):
    motions, key = BAD[case]
    text = spec_text(motions)
    if key == "uncertain.noise":
        text += "[uncertain]\nnoise = {dist = 'uniform', low = 0.0, high = 0.1}\n"
    with pytest.raises(SpecError) as e:
        campaign.parse_spec(text, base_dir=tmp_path)
    msg = str(e.value)
    assert msg.startswith(f"spec: {key}: ") and "\n" not in msg, msg


# ------------------------------------------------------------------ the README
def test_the_readme_table_is_generated_from_the_catalog_and_the_factory():
    """Regenerate with ``python -c "from rocking.campaign.spec import write_keys_table;
    write_keys_table('README.md')"``."""
    text = README.read_text(encoding="utf-8")
    assert text.count(KEYS_START) == 1 and text.count(KEYS_END) == 1
    between = text.split(KEYS_START, 1)[1].split(KEYS_END, 1)[0]
    assert between == "\n" + keys_table()
    table = keys_table()
    for k in catalog.KINDS.values():  # every kind and parameter, every block key
        for d in k.describe():
            assert re.search(rf"\| `{k.name}` \| `{d['name']}` \|", table), (k.name, d)
    for row in rocking.blocks.factory.table():
        assert f"`{row['name']}`" in table
