"""Batches of the 3-D rigid body (``simulate_many(..., model="rigid3d")``, issue 30): one
compiled parallel call, each row bit-identical to its single run (pairs, single motions
along ``direction``, and their mix), one call per distinct body otherwise."""

import numpy as np
import pytest

import rocking
from rocking.models.rigid3d import Rigid3d
from rocking.motions import HorizontalPair, Record
from rocking.shapes import Shape

DT = 0.005
T = np.arange(0.0, 0.6, DT)


def rec(amp, f):
    return Record(amp * np.sin(2 * np.pi * f * T), DT)


@pytest.fixture(scope="module")
def box():
    return Shape.box(0.4, 0.3, 1.2, density=2000.0)


@pytest.fixture
def calls(monkeypatch):
    """Count the calls of the model's batch kernel."""
    seen = []
    kernel = Rigid3d.batch_kernel

    def counted(*args):
        seen.append(args[2].kinds.size)
        return kernel(*args)

    monkeypatch.setattr(Rigid3d, "batch_kernel", counted)
    return seen


def test_batch_is_one_parallel_call_and_rows_equal_single_runs(box, calls):
    motions = [HorizontalPair(rec(4.0, 2.0), rec(3.0, 3.0)),
               HorizontalPair(rec(2.0, 2.5), rec(5.0, 1.5), vertical=rec(2.0, 4.0)),
               rec(5.0, 2.0), rec(1.0, 2.0)]
    opts = {"model": "rigid3d", "duration": 0.6, "step": 1e-3, "heading": 30.0,
            "direction": 20.0, "dt_out": 0.01}
    res = rocking.simulate_many(box, motions, return_histories=True, **opts)
    assert calls == [len(motions)]  # one compiled call for the whole batch
    assert len(res) == 4 and res.model == "rigid3d"
    assert np.isnan(res.uplift_time[3])  # 1 m/s^2, far below g tan(alpha): at rest
    assert res.outputs["max_tilt"][0] > 0.01
    for i, mo in enumerate(motions):
        r = rocking.simulate(box, mo, **opts)
        for name in ("max_tilt", "max_slide", "residual_slide", "max_twist",
                     "residual_twist", "n_impacts", "overturn_azimuth"):
            np.testing.assert_array_equal(getattr(res, name)[i], getattr(r, name))
        assert res.overturned[i] == r.overturned
        np.testing.assert_array_equal(res.states[i, :len(r.t)], r.states)
    df = res.to_dataframe()
    assert {"max_tilt", "overturn_azimuth", "max_slide", "max_twist"} <= set(df.columns)


def test_batch_kernel_is_compiled_parallel():
    assert Rigid3d.batch_kernel.targetoptions.get("parallel") is True


def test_one_body_per_row_runs_per_distinct_body(box, calls):
    other = Shape.box(0.3, 0.3, 0.9, density=2000.0)
    motions = [rec(4.0, 2.0), rec(4.0, 2.0), rec(4.0, 2.0)]
    res = rocking.simulate_many([box, other, box], motions, model="rigid3d", duration=0.6,
                                step=1e-3)
    assert sorted(calls) == [1, 2]
    for b, i in ((box, 0), (other, 1), (box, 2)):
        r = rocking.simulate(b, motions[i], model="rigid3d", duration=0.6, step=1e-3)
        assert res.outputs["max_tilt"][i] == r.max_tilt
