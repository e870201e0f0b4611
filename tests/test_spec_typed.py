"""The checked campaign spec keeps typed, frozen objects (the motion axis, the uncertain
parameters, the building, the mitigations); their dict views are fresh copies that cannot
change the spec; a motion of the sweep is the template replaced, never mutated; record
files read by the spec's check are not read again by the campaign."""

from __future__ import annotations

import dataclasses
import pickle
import shutil

import numpy as np
import pytest

from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
from rocking.campaign.spec import (
    BuildingAxis,
    Distribution,
    Mitigation,
    MotionAxis,
    UncertainParameters,
)
from rocking.motions import catalog
from rocking.motions.io import _builtin_dir

UNCERTAIN = '[uncertain]\nmu = {dist = "normal", cov = 0.01}\ntheta0 = {dist = "uniform", ' \
            'low = -0.001, high = 0.001}\n'
BUILDING = '[building]\nkind = "shear"\nstoreys = 2\nperiod = 0.3\nfloors = [0, 2]\n'
MITIGATION = 'mitigation = [{name = "none"}, {name = "anchors", model = "anchored"}]\n'
RECORDS = ("RSN126_GAZLI_GAZ000.AT2", "RSN982_NORTHR_JEN292.AT2")


def test_the_checked_tables_are_typed_and_frozen():
    spec = parse_spec(MITIGATION + EXAMPLE_SPEC + BUILDING + UNCERTAIN)
    assert isinstance(spec.motion_axis, MotionAxis)
    assert isinstance(spec.uncertain_parameters, UncertainParameters)
    assert isinstance(spec.building_axis, BuildingAxis)
    assert all(isinstance(m, Mitigation) for m in spec.mitigations)
    assert all(isinstance(d, Distribution) for d in spec.uncertain_parameters.parameters)
    for obj, name in ((spec.motion_axis, "n"), (spec.uncertain_parameters, "parameters"),
                      (spec.building_axis, "values"), (spec.mitigations[0], "model")):
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(obj, name, None)
    assert spec.uncertain_parameters.names == ("mu", "theta0")
    assert spec.building_axis.values == (0, 2)
    assert spec.floors == [0, 2]


def test_the_dict_views_are_the_tables_and_fresh_copies():
    spec = parse_spec(EXAMPLE_SPEC + BUILDING + UNCERTAIN)
    assert spec.motions == spec.motion_axis.to_dict()
    assert spec.motions["load_factors"] == [1.0, 1.5, 2.0, 3.0]
    assert spec.motions["params"] == {"period": 0.5, "amplitude": 1.0}
    assert spec.uncertain == {"mu": {"dist": "normal", "cov": 0.01},
                              "theta0": {"dist": "uniform", "low": -0.001, "high": 0.001}}
    assert spec.building["values"] == [0, 2] and spec.building["axis"] == "floor"
    hash0 = spec.hash
    spec.motions["load_factors"].append(9.0)  # a copy: the spec does not change
    spec.uncertain["mu"]["cov"] = 0.5
    spec.building["values"].append(1)
    assert spec.levels.tolist() == [1.0, 1.5, 2.0, 3.0]
    assert spec.uncertain["mu"]["cov"] == 0.01 and spec.floors == [0, 2]
    assert spec.hash == hash0 and spec.n_sims == 4 * 2


def test_a_swept_motion_is_the_template_replaced_not_mutated():
    spec = parse_spec(EXAMPLE_SPEC.replace("period = 0.5", "period = [0.5, 0.7, 0.9]"))
    axis = spec.motion_axis
    assert axis.sweep == "period" and axis.values == (0.5, 0.7, 0.9)
    kind = catalog.KINDS["one_sine"]
    for j, v in enumerate(axis.values):
        assert axis.params(j) == kind.Params(period=v, amplitude=1.0)
    assert axis.template.period == 0.5  # motion 0's parameters, untouched
    ms = Campaign(spec).motions
    assert [ms.id(j) for j in range(3)] == [kind.label(axis.params(j)) for j in range(3)]


def _record_spec(folder) -> str:
    (folder / "recs").mkdir(parents=True)
    for name in RECORDS:
        shutil.copy(_builtin_dir() / name, folder / "recs" / name)
    files = ", ".join(f'"recs/{n}"' for n in RECORDS)
    return ('campaign = {name = "r", seed = 2, model = "housner", duration = 3.0}\n'
            'blocks = [{specimen = 2}]\n[motions]\nkind = "record"\n'
            f'file = [{files}]\nunits = "g"\nload_factors = [0.5, 1.0]\n')


def test_record_files_are_read_once_by_the_spec(tmp_path):
    """The campaign runs the motions that the spec's check made: with the files gone
    after parse_spec, the rows are those of a spec whose files are still there."""
    text = _record_spec(tmp_path)
    want = Campaign(parse_spec(text, base_dir=tmp_path)).run_ids(range(4))
    spec = parse_spec(text, base_dir=tmp_path)
    assert spec.motion_axis.records is not None and len(spec.motion_axis.records) == 2
    shutil.rmtree(tmp_path / "recs")
    got = Campaign(spec).run_ids(range(4))
    assert got.equals(want)
    assert np.all(got["pga"] > 0) and got["motion_id"].nunique() == 2
    # a pickled spec (a Dask worker's) carries no records: the worker reads its own files
    assert pickle.loads(pickle.dumps(spec)).motion_axis.records is None
    assert pickle.loads(pickle.dumps(spec)).motion_axis == spec.motion_axis
