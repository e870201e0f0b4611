"""``rocking simulate --building ... --floor K`` runs the block on the floor motion of the
catalog's ground motion in the catalog's building; ``rocking buildings`` lists the kinds."""

from __future__ import annotations

import json

import numpy as np
import pytest
from cli_helpers import assert_one_line_error, run_main

from rocking import models
from rocking.buildings import FloorMotion
from rocking.buildings.catalog import KINDS, make_building
from rocking.motions import GroundMotion, catalog

PULSE = ["--specimen", "2", "--motion", "one_sine", "--amp", "0.2g", "--tp", "0.5"]
SHEAR = ["--building", "shear", "--storeys", "3", "--building-period", "0.4",
         "--building-damping", "5%"]


class Captured(Exception):
    """Raised by the stand-in of rocking.models.simulate once it has seen its inputs."""


def captured_motion(monkeypatch, capsys, *args):
    """The motion that ``rocking simulate ARGS`` hands to the model."""
    seen = {}

    def stand_in(block, motion, **kw):
        seen["motion"] = motion
        raise Captured

    monkeypatch.setattr(models, "simulate", stand_in)
    with pytest.raises(Captured):
        run_main(capsys, "simulate", *args)
    return seen["motion"]


def same_motion(a, b) -> bool:
    ka, pa, sa = a.spec()
    kb, pb, sb = b.spec()
    return ka == kb and np.array_equal(pa, pb) and np.array_equal(sa, sb)


PULSE_GROUND = {"amplitude": "0.2g", "period": 0.5}
SHEAR_KEYS = {"kind": "shear", "storeys": 3, "period": 0.4, "damping_ratio": 0.05}


@pytest.mark.parametrize("args, building, where", [
    (SHEAR + ["--floor", "3"], SHEAR_KEYS, {"floor": 3}),
    (SHEAR + ["--floor", "0"], SHEAR_KEYS, {"floor": 0}),
    (["--building", "sdof", "--building-period", "0.3s", "--floor", "1"],
     {"kind": "sdof", "period": 0.3}, {"floor": 1}),
    (["--building", "continuous", "--building-period", "0.6", "--building-param",
      "stiffness_ratio=5", "--building-param", "n_modes=3", "--height-ratio", "0.75"],
     {"kind": "continuous", "period": 0.6, "stiffness_ratio": 5.0, "n_modes": 3},
     {"height_ratio": 0.75}),
    (["--building", "shear", "--storeys", "3", "--building-period", "0.4",
      "--building-param", "masses=[2, 1, 1]", "--floor", "2"],
     {"kind": "shear", "storeys": 3, "period": 0.4, "masses": [2, 1, 1]}, {"floor": 2}),
])
def test_the_floor_motion_is_the_catalog_ground_in_the_catalog_building(
        monkeypatch, capsys, args, building, where):
    got = captured_motion(monkeypatch, capsys, *PULSE, *args)
    pulse = catalog.build("one_sine", **PULSE_GROUND)
    expected = FloorMotion(pulse, make_building(building), **where)
    assert same_motion(got, expected)


def test_a_record_with_its_vertical_component_stands_on_the_floor(monkeypatch, capsys):
    got = captured_motion(monkeypatch, capsys, "--specimen", "2", "--record", "Rinaldi228",
                          "--vertical", "RinaldiUP", *SHEAR, "--floor", "2")
    g = GroundMotion(catalog.build("builtin", name="Rinaldi228"),
                     catalog.build("builtin", name="RinaldiUP"))
    assert same_motion(got, FloorMotion(g, make_building(SHEAR_KEYS), floor=2))
    assert got.vertical is not None


def test_summary_and_the_motion_line_name_the_floor(capsys, tmp_path):
    code, out, err = run_main(capsys, "simulate", *PULSE, *SHEAR, "--floor", "3",
                              "--out", tmp_path)
    assert code == 0, err
    line = next(s for s in out.splitlines() if s.startswith("motion"))
    assert "on floor 3 of the 3-storey shear building" in line
    summary = json.loads((tmp_path / "summary.json").read_text())
    fm = FloorMotion(catalog.build("one_sine", **PULSE_GROUND), make_building(SHEAR_KEYS), floor=3)
    for d in (summary, summary["inputs"]):
        assert d["floor"] == 3
        assert d["building"]["kind"] == "shear" and d["building"]["storeys"] == 3
        assert d["building"]["damping_ratio"] == 0.05 and d["building"]["n_floors"] == 3
        assert d["floor_pga"] == pytest.approx(fm.pga, rel=1e-12)
    assert summary["inputs"]["motion"]["type"] == "one_sine"  # the ground motion


@pytest.mark.parametrize("args, name", [
    (["--floor", "2"], "floor"),
    (["--storeys", "3"], "storeys"),
    (["--building-param", "stiffness_ratio=5"], "building-param"),
    (["--height-ratio", "0.5"], "height-ratio"),
    (SHEAR, "floor"),  # where does the block stand?
    (SHEAR + ["--floor", "4"], "floor"),  # above the top
    (SHEAR + ["--floor", "-1"], "floor"),
    (SHEAR + ["--floor", "x"], "floor"),
    (SHEAR + ["--floor", "1", "--height-ratio", "0.5"], "height-ratio"),
    (["--building", "tower", "--floor", "1"], "building"),
    (["--building", "shear", "--storeys", "3", "--floor", "1"], "building-period"),
    (["--building", "shear", "--building-period", "0.4", "--floor", "1"], "storeys"),
    (["--building", "shear", "--storeys", "0", "--building-period", "0.4", "--floor", "1"],
     "storeys"),
    (SHEAR[:-2] + ["--building-damping", "150%", "--floor", "1"], "building-damping"),
    (SHEAR[:-2] + ["--building-damping", "0", "--floor", "1"], "building-damping"),
    (SHEAR + ["--building-param", "foo=1", "--floor", "1"], "foo"),
    (SHEAR + ["--building-param", "storeys=4", "--floor", "1"], "storeys"),
    (SHEAR + ["--building-param", "masses=[1,", "--floor", "1"], "masses"),
    (["--building", "continuous", "--building-period", "1", "--floor", "1"],
     "stiffness_ratio"),
    (["--building", "continuous", "--building-period", "1", "--building-param",
      "stiffness_ratio=5", "--floor", "1"], "height-ratio"),
    (["--building", "continuous", "--building-period", "1", "--building-param",
      "stiffness_ratio=5", "--height-ratio", "1.5"], "height-ratio"),
])
def test_bad_building_flags_give_one_error_line(capsys, args, name):
    code, _, err = run_main(capsys, "simulate", *PULSE, *args)
    assert_one_line_error(code, err, name)


def test_free_rocking_has_no_floor(capsys):
    code, _, err = run_main(capsys, "simulate", "--specimen", "2", "--motion", "free",
                            "--theta0", "0.05", *SHEAR, "--floor", "1")
    assert_one_line_error(code, err, "building")


def test_rocking_buildings_lists_every_kind_and_key(capsys):
    code, out, err = run_main(capsys, "buildings")
    assert code == 0, err
    for k in KINDS.values():
        assert f"{k.name}: " in out
        for d in k.describe():
            assert f"  {d['name']} " in out, d["name"]
    assert "--building-period" in out and "[building]" in out
    code, out, _ = run_main(capsys, "buildings", "continuous", "--json")
    (d,) = json.loads(out)
    assert d["name"] == "continuous"
    assert [k["name"] for k in d["keys"]] == list(KINDS["continuous"].Params.names())
    assert_one_line_error(*run_main(capsys, "buildings", "tower")[::2], "kind")
