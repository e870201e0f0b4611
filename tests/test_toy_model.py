"""The model contract's executable proof (issue 29): a toy model in one file
(``tests/sliding_model.py``, a block sliding with Coulomb friction, state ``(x, v)``) plus
one registry line runs through simulate, simulate_many, a campaign and check_model,
and its physics holds against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest
from sliding_model import Sliding

import rocking
from rocking.models import register
from rocking.motions import Rectangular, Sine


@pytest.fixture(autouse=True, scope="module")
def registered():
    """Registered for this module's tests only (the other tests see the package's
    models)."""
    register(Sliding)  # the one registry line
    yield
    rocking.models.MODELS.pop("sliding")


MU = 0.5
BLOCK = rocking.specimen(3)


def test_free_sliding_stops_after_v0_squared_over_2_mu_g():
    v0 = 0.8
    r = rocking.simulate(BLOCK, None, model="sliding", state0=[0.0, v0], duration=1.0)
    d = v0 ** 2 / (2 * MU * rocking.G)
    assert r.state_names == ("x", "v") and r.states.shape == (r.t.size, 2)
    assert r.theta is None and r.max_abs_theta is None
    assert r.residual_slide == pytest.approx(d, rel=1e-9)
    assert r.max_slide == pytest.approx(d, rel=1e-9)
    stop = v0 / (MU * rocking.G)
    moving = r.t < stop - 1e-3
    np.testing.assert_allclose(r.state("v")[moving], v0 - MU * rocking.G * r.t[moving],
                               atol=1e-12)
    assert r.settled and not r.overturned
    assert set(r.to_dataframe().columns) == {"t", "x", "v"}


def test_a_constant_drag_above_friction_slides_at_a_minus_mu_g():
    a = 1.5 * MU * rocking.G
    pulse = Rectangular(a, 0.5, duration=0.5)
    r = rocking.simulate(BLOCK, pulse, model="sliding", duration=0.5)
    x = -(a - MU * rocking.G) * r.t ** 2 / 2
    np.testing.assert_allclose(r.state("x"), x, atol=1e-12)
    assert r.uplift_time == 0.0


def test_below_friction_it_sticks():
    weak = Sine.from_acceleration(3.0, 0.9 * MU * rocking.G, 2.0)
    r = rocking.simulate(BLOCK, weak, model="sliding")
    assert np.all(r.states == 0.0) and math.isnan(r.uplift_time) and r.settled


def test_batches_equal_single_runs_with_states():
    ms = [Sine.from_acceleration(f, 1.3 * MU * rocking.G, 1.0) for f in (1.0, 2.0, 4.0)]
    b = rocking.simulate_many(BLOCK, ms, model="sliding", return_histories=True,
                              state0=[[0.0, 0.0], [0.01, 0.2], [0.0, -0.1]])
    assert b.states.shape[0] == 3 and b.states.shape[2] == 2 and b.theta is None
    for i, (m, y0) in enumerate(zip(ms, [[0.0, 0.0], [0.01, 0.2], [0.0, -0.1]], strict=True)):
        r = rocking.simulate(BLOCK, m, model="sliding", state0=y0)
        assert b.max_slide[i] == r.max_slide and b.residual_slide[i] == r.residual_slide
        np.testing.assert_array_equal(b.states[i, : r.t.size], r.states)
    with pytest.raises(rocking.ParameterError, match="state0"):
        rocking.simulate(BLOCK, ms[0], model="sliding", theta0=0.1)


def test_a_campaign_runs_the_toy_model_with_its_columns_and_units():
    from rocking.campaign import Campaign, parse_spec
    from rocking.campaign.store import result_schema
    spec = parse_spec("""\
campaign = {name = "toy", seed = 1, model = "sliding"}
blocks = [{specimen = 3}]
[motions]
kind = "one_sine"
period = 0.5
amplitude = 1.0
load_factors = [2.0, 8.0]
""")
    rows = Campaign(spec).run_ids(range(spec.n_sims))
    assert rows["max_slide"].tolist()[0] == 0.0 and rows["max_slide"].tolist()[1] > 0.0
    one = rocking.simulate(BLOCK, Campaign(spec).inputs([1])[2][0], model="sliding")
    assert rows["residual_slide"].iloc[1] == one.residual_slide
    schema = result_schema(rows)
    assert schema.field("max_slide").metadata[b"unit"] == b"m"
    assert rows["damage_state"].tolist() == [-1, -1]  # no planar angle: no damage state


def test_check_model_passes_for_the_toy_model():
    rocking.testing.check_model(Sliding)


def test_a_model_outside_the_package_leaves_the_package_cache_usable(tmp_path):
    """A batch of the toy model, then the DEM's batches (which share `same_block`) in a
    fresh process without the toy's module: the package's numba cache must not have
    recorded the toy's parameter type (it did: ModuleNotFoundError: sliding_model)."""
    import subprocess
    import sys
    rocking.simulate_many(BLOCK, [Sine.from_acceleration(2.0, 1.3 * MU * rocking.G, 0.5)],
                          model="sliding")
    code = ("import rocking; from rocking.motions import OneSine; "
            "r = rocking.simulate_many(rocking.specimen(2), [OneSine(3.0, 0.5)], model='dem', "
            "duration=0.3); print(bool(r.max_abs_theta[0] > 0))")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       cwd=tmp_path, timeout=600)
    assert p.returncode == 0, p.stderr[-2000:]
    assert p.stdout.strip().splitlines()[-1] == "True"


def test_analyses_of_the_planar_angle_refuse_the_toy_model_by_name():
    from rocking.analysis import ida, monte_carlo
    from rocking.motions import sample
    recs = [sample(Sine.from_acceleration(2.0, 1.3 * MU * rocking.G, 1.0), 0.01)]
    with pytest.raises(rocking.ParameterError, match="'sliding' has no planar angle"):
        ida(BLOCK, recs, levels=[1.0, 2.0], model="sliding")
    with pytest.raises(rocking.ParameterError, match="'sliding' has no planar angle"):
        monte_carlo(BLOCK, recs, {"p": {"dist": "normal", "cov": 0.02}}, n=4, model="sliding")


def test_the_plot_of_a_model_without_a_planar_angle_draws_its_states():
    import matplotlib.pyplot as plt
    r = rocking.simulate(BLOCK, None, model="sliding", state0=[0.0, 0.8], duration=0.5)
    ax = r.plot()
    assert [ln.get_label() for ln in ax.lines] == ["x", "v"]
    np.testing.assert_array_equal(ax.lines[1].get_ydata(), r.state("v"))
    assert "n_impacts" not in r.summary() and "max_abs_theta" not in r.summary()
    plt.close("all")
